/*
 * The vertex stage of GL_PHONG_WIN with lighting (include/fixgl/shading.md):
 * instead of lit colours, each vertex carries its colour (unlit: the
 * material property GL_COLOR_MATERIAL tracks), its eye-space normal and its
 * eye position, which the raster core interpolates perspective-correctly,
 * like texture coordinates, and lights per fragment (r_frag.c
 * r_fragment_phong, with m_shade_point).
 *
 * Lighting is always evaluated in eye space, whatever the oracle's
 * fixed-function vertex program would choose (_NeedEyeCoords): the normal
 * goes through the modelview's inverse transposed (GLSL's gl_NormalMatrix *
 * gl_Normal: the columns of the inverse transposed times x, y, z, summed
 * in that order), then GL_NORMALIZE (GLSL's normalize() on llvmpipe,
 * v * 1/sqrt(dot(v, v)) with the dot from the last component) or
 * GL_RESCALE_NORMAL (times the eye-space normal scale, Mesa's
 * _ModelViewInvScaleEyespace [S: main/light.c:update_modelview_scale],
 * which is GLSL's gl_NormalScale); the eye position is the modelview's
 * column MUL/MAD chain (gl_ModelViewMatrix * gl_Vertex, get_eye_position).
 * These are not the oracle's fixed-function arithmetic (t_light.c) but
 * the GLSL reference's vertex stage (conformance/reference/fcr_shading.c)
 * as llvmpipe runs it; it lowers ffma, so each product and sum is rounded
 * on its own.
 */
#include "tnl/t_pipeline.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "context.h"

/* GLSL's mat3 * vec3 on llvmpipe: column 0 times x, plus column 1 times
 * y, plus column 2 times z (glsl_to_nir's fmul/ffma chain, ffma lowered):
 * row r of the product is (m0*x + m1*y) + m2*z */
static inline float mat_row3(const float *m, const float *v)
{
   return (m[0] * v[0] + m[1] * v[1]) + m[2] * v[2];
}

/* dot(a, b) on llvmpipe: fdot3 scalarised from the last component,
 * (z*z' + y*y') + x*x' (nir_lower_alu_to_scalar's reduction; the
 * ORACLE-NOTES.md finding for the fixed-function DP3, and what the GLSL
 * reference computes) */
static inline float dot3(const float *a, const float *b)
{
   return (a[2] * b[2] + a[1] * b[1]) + a[0] * b[0];
}

/* [S: main/light.c:update_modelview_scale] _ModelViewInvScaleEyespace:
 * 1 for a length-preserving modelview, else 1/sqrt of the squared length
 * of the inverse's third column (1 when it is below 1e-12). */
static float eye_normal_scale(const fgl_matrix *mv)
{
   if (fgl_matrix_is_length_preserving(mv->flags))
      return 1.0f;
   const float *inv = mv->inv;
   float f = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
   if (f < 1e-12f)
      f = 1.0f;
   return 1.0f / sqrtf(f);
}

void t_eye_normal_init(const struct fgl_context *ctx, struct t_eye_normal *en)
{
   const fgl_matrix *mv = ctx->ModelviewStack.Top;
   en->inv = mv->inv;
   en->normalize = ctx->Transform.Normalize;
   en->rescale = !en->normalize && ctx->Transform.RescaleNormals;
   en->scale = en->rescale ? eye_normal_scale(mv) : 1.0f;
}

void t_eye_normal(const struct t_eye_normal *en, const float *in, float n[3])
{
   /* row r of the transposed inverse is column r of the inverse */
   for (int r = 0; r < 3; r++)
      n[r] = mat_row3(en->inv + 4 * r, in);
   if (en->normalize) {
      /* normalize(v) = v * (1/sqrt(dot(v, v))) */
      const float k = 1.0f / sqrtf(dot3(n, n));
      for (int r = 0; r < 3; r++)
         n[r] *= k;
   } else if (en->rescale) {
      for (int r = 0; r < 3; r++)
         n[r] *= en->scale;
   }
}

void t_phong(const struct fgl_context *ctx, const struct fgl_vertex_view *in, unsigned n,
             struct t_vertex *out)
{
   const fgl_matrix *mv = ctx->ModelviewStack.Top;
   struct t_eye_normal en;
   t_eye_normal_init(ctx, &en);
   unsigned cstride, nstride;
   const float *color = fgl_vbo_attr_ptr(ctx, in, FGL_ATTR_COLOR0, &cstride);
   const float *normal = fgl_vbo_attr_ptr(ctx, in, FGL_ATTR_NORMAL, &nstride);
   static const float no_secondary[4] = { 0.0f, 0.0f, 0.0f, 1.0f };

   for (unsigned i = 0; i < n; i++) {
      float (*attr)[4] = out[i].r.attr;
      /* the vertex colour, for both faces (state.c: no two-sided
       * colours under Phong); the secondary colour is replaced per
       * fragment */
      const float *c = color + (size_t)i * cstride;
      memcpy(attr[R_ATTR_COLOR0], c, sizeof(attr[0]));
      memcpy(attr[R_ATTR_COLOR1], no_secondary, sizeof(attr[0]));

      float *nrm = attr[R_ATTR_NORMAL];
      t_eye_normal(&en, normal + (size_t)i * nstride, nrm);
      /* the face: front (the unfilled stage marks a back face's lines and
       * points, t_draw_pipe.c) */
      nrm[3] = 1.0f;

      t_mul_mad_chain(attr[R_ATTR_EYEPOS], mv->m, fgl_vv_attr(in, i, FGL_ATTR_POS));
   }
}
