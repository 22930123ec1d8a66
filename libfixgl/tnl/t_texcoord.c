/*
 * Texture coordinates, as the oracle's fixed-function vertex program
 * computes them (Mesa 22.3 ffvertex_prog.c:build_texture_transform,
 * through prog_to_nir and gallivm; ORACLE-NOTES.md "The fixed-function
 * vertex program"): for each unit
 * the fragment program reads,
 *   - with coordinate generation, per component: OBJECT_LINEAR and
 *     EYE_LINEAR a DP4 of the object or eye position with the plane,
 *     SPHERE_MAP and REFLECTION_MAP from the eye normal and the normalised
 *     eye position, NORMAL_MAP the eye normal, others the vertex's
 *     coordinate;
 *   - then the texture matrix when it applies (ctx->_TexMatEnabled), the
 *     column MUL/MAD chain;
 *   - else a copy of the vertex's coordinate.
 * Every MAD is a multiply then an add; DP3/DP4 sum from the last
 * component; RSQ is 1/sqrt(|x|).
 */
#include "tnl/t_pipeline.h"

#include <math.h>
#include <stddef.h>

#include "context.h"

/* DP3 = (z*z' + y*y') + x*x'; DP4 = ((w*w' + z*z') + y*y') + x*x' */
static inline float dp3(const float *a, const float *b)
{
   return (a[2] * b[2] + a[1] * b[1]) + a[0] * b[0];
}

static inline float dp4(const float *a, const float *b)
{
   return ((a[3] * b[3] + a[2] * b[2]) + a[1] * b[1]) + a[0] * b[0];
}

/* translate_texgen: the mode of a component, 0 when it is not generated */
static unsigned component_mode(const struct fgl_texture_unit *t, int c)
{
   if (!(t->TexGenEnabled & (1u << c)))
      return 0;
   switch (t->GenMode[c]) {
   case GL_OBJECT_LINEAR: return FGL_TEXGEN_OBJ_LINEAR;
   case GL_EYE_LINEAR:    return FGL_TEXGEN_EYE_LINEAR;
   case GL_SPHERE_MAP:    return FGL_TEXGEN_SPHERE_MAP;
   case GL_REFLECTION_MAP: return FGL_TEXGEN_REFLECTION_MAP;
   case GL_NORMAL_MAP:    return FGL_TEXGEN_NORMAL_MAP;
   default:               return 0;
   }
}

void t_texcoord(const struct fgl_context *ctx, const struct fgl_vertex_view *in, unsigned n,
                unsigned units, struct t_vertex *out)
{
   /* whether the program computes a reflection map's R anywhere (the
    * eye normal and position are shared by every unit) */
   bool reflect_r = false;
   for (unsigned m = units & ctx->_TexGenEnabled; m; m &= m - 1) {
      const unsigned u = (unsigned)__builtin_ctz(m);
      reflect_r |= component_mode(&ctx->Texture.Unit[u], 2) == FGL_TEXGEN_REFLECTION_MAP;
   }

   const float *mv = ctx->ModelviewStack.Top->m;
   unsigned nstride;
   const float *normal = fgl_vbo_attr_ptr(ctx, in, FGL_ATTR_NORMAL, &nstride);

   while (units) {
      const unsigned u = (unsigned)__builtin_ctz(units);
      units &= units - 1;
      const struct fgl_texture_unit *t = &ctx->Texture.Unit[u];
      const int slot = R_ATTR_TEX0 + (int)u;
      unsigned tstride;
      const float *tex = fgl_vbo_attr_ptr(ctx, in, (enum fgl_vbo_attr)(FGL_ATTR_TEX0 + u),
                                          &tstride);
      const bool texgen = (ctx->_TexGenEnabled >> u) & 1u;
      const bool texmat = (ctx->_TexMatEnabled >> u) & 1u;

      unsigned modes[4] = { 0, 0, 0, 0 }, used = 0;
      if (texgen) {
         for (int c = 0; c < 4; c++) {
            modes[c] = component_mode(t, c);
            used |= modes[c];
         }
      }
      const bool need_eye = used & (FGL_TEXGEN_EYE_LINEAR | FGL_TEXGEN_SPHERE_MAP |
                                    FGL_TEXGEN_REFLECTION_MAP);
      const bool need_normal = used & (FGL_TEXGEN_SPHERE_MAP | FGL_TEXGEN_REFLECTION_MAP |
                                       FGL_TEXGEN_NORMAL_MAP);
      const bool reflect = used & (FGL_TEXGEN_SPHERE_MAP | FGL_TEXGEN_REFLECTION_MAP);

      for (unsigned i = 0; i < n; i++) {
         const float *tc = tex + (size_t)i * tstride;
         float *o = out[i].r.attr[slot];
         if (!texgen && !texmat) {
            /* emit_passthrough */
            for (int k = 0; k < 4; k++)
               o[k] = tc[k];
            continue;
         }
         float g[4] = { tc[0], tc[1], tc[2], tc[3] };
         if (texgen) {
            const float *obj = fgl_vv_attr(in, i, FGL_ATTR_POS);
            float eye[4] = { 0 }, nrm[3] = { 0 }, eye_hat[3] = { 0 }, r[3] = { 0 };
            float neg_nu_n[3] = { 0 };
            if (need_eye)
               t_mul_mad_chain(eye, mv, obj);      /* get_eye_position */
            if (need_normal)
               t_transformed_normal(ctx, normal + (size_t)i * nstride, nrm);
            if (reflect) {
               /* get_eye_position_normalized: eye * rsq(DP3(eye, eye)) */
               const float l = 1.0f / sqrtf(fabsf(dp3(eye, eye)));
               for (int k = 0; k < 3; k++)
                  eye_hat[k] = eye[k] * l;
               /* n.u, 2n.u, then (-2n.u)n + u */
               float nu = dp3(nrm, eye_hat);
               nu = nu + nu;
               for (int k = 0; k < 3; k++) {
                  neg_nu_n[k] = -nu * nrm[k];
                  r[k] = neg_nu_n[k] + eye_hat[k];
               }
            }
            float sphere[3] = { 0 };
            if (used & FGL_TEXGEN_SPHERE_MAP) {
               /* build_sphere_texgen: m = rsq(|r + (0,0,1)|^2), then
                * r * (m * 0.5) + 0.5.  NIR folds the x and y additions of
                * 0 and, when r.z has no other use, reassociates the z one
                * to (-2(n.u) n.z + 1) + u.z (nir_opt_algebraic's constant
                * reassociation; ST_DEBUG=nir dump); a reflection map on R
                * computes the same r.z, which CSE shares, and keeps
                * (r.z + 1) */
               const float vz = reflect_r ? r[2] + 1.0f : (neg_nu_n[2] + 1.0f) + eye_hat[2];
               const float v[3] = { r[0], r[1], vz };
               const float inv_m = (1.0f / sqrtf(fabsf(dp3(v, v)))) * 0.5f;
               for (int k = 0; k < 3; k++)
                  sphere[k] = r[k] * inv_m + 0.5f;
            }
            for (int c = 0; c < 4; c++) {
               switch (modes[c]) {
               case FGL_TEXGEN_OBJ_LINEAR:
                  g[c] = dp4(obj, t->ObjectPlane[c]);
                  break;
               case FGL_TEXGEN_EYE_LINEAR:
                  g[c] = dp4(eye, t->EyePlane[c]);
                  break;
               case FGL_TEXGEN_SPHERE_MAP:
                  g[c] = sphere[c];
                  break;
               case FGL_TEXGEN_REFLECTION_MAP:
                  g[c] = r[c];
                  break;
               case FGL_TEXGEN_NORMAL_MAP:
                  g[c] = nrm[c];
                  break;
               default:
                  break;   /* the vertex's coordinate */
               }
            }
         }
         if (texmat)
            t_mul_mad_chain(o, ctx->TextureStack[u].Top->m, g);
         else
            for (int k = 0; k < 4; k++)
               o[k] = g[k];
      }
   }
}
