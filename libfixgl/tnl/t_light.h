/*
 * Per-vertex lighting (t_light.c): what a batch's lighting needs that does
 * not change from vertex to vertex, prepared once per batch by
 * t_light_prepare, then t_light_run over the batch's vertices, chunk by
 * chunk (t_vertex.c).
 */
#ifndef FGL_T_LIGHT_H
#define FGL_T_LIGHT_H

#include <stdbool.h>

#include "context.h"
#include "math/m_shade.h"
#include "tnl/t_pipeline.h"

/* What the vertex program was generated for (ffvertex_prog.c state_key). */
struct t_light_key {
   bool eye;                 /* lighting in eye space: the normal goes
                              * through the inverse modelview */
   bool normalize;           /* GL_NORMALIZE */
   bool rescale;             /* normal times STATE_NORMAL_SCALE */
   bool local_viewer, twoside, separate;
   bool shininess_is_zero;   /* no specular pow: the degenerate LIT */
};

/* The scene colour and the light*material products of a face.  Where the
 * material does not vary per vertex they are uniforms of the oracle's
 * vertex program (STATE_LIGHTMODEL_SCENECOLOR, STATE_LIGHTPROD), which Mesa
 * computes on the CPU before the draw, so without the draw's flush of
 * denormals (t_render.c); t_light_prepare computes them once per batch
 * with the flush off.  A varying material's products are computed per
 * vertex, in the vertex program (build_lighting: get_scenecolor,
 * get_lightprod). */
struct t_light_products {
   bool vary_scene[2], vary_ambient[2], vary_diffuse[2], vary_specular[2];
   float scene[2][3];
   float ambient[FGL_MAX_LIGHTS][2][3];
   float diffuse[FGL_MAX_LIGHTS][2][3];
   float specular[FGL_MAX_LIGHTS][2][3];
};

/* The material source of each property of each face for this batch: the
 * vertex colour when it tracks the colour and the colour varies
 * (get_material's order), else the vbo attribute (per vertex when it is in
 * the vertex format, the current value otherwise). */
struct t_material_source {
   const float *ptr;
   unsigned stride;
};

/* A batch's lighting, prepared from the state and the batch's vertex
 * format; the pointers index the batch's stored vertices from its first. */
struct t_light_batch {
   struct t_light_key key;
   struct t_material_source src[FGL_ATTR_COUNT];
   const float *normal;       /* the normals, nstride floats apart */
   unsigned nstride;
   /* whether the oracle's lighting code computes the eye position (which
    * the fog coordinate then reuses) */
   bool eye_position;
   /* GL_FIXGL_cook_torrance (either face): m_shade_point with the
    * environment env, its lights prepared once, and the eye-space normal
    * en; else the oracle's program with the products P */
   bool shade;
   struct t_light_products P;
   float exponent[2];         /* the faces' LIT exponents, where the
                               * shininess does not vary per vertex */
   bool simd;                 /* lit eight vertices at a time (t_light.c
                               * light_simd) */
   unsigned clamped;          /* the colour slots 0..clamped-1 that
                               * t_light_run leaves already clamped to
                               * [0, 1] as t_transform clamps them
                               * (light_simd's outputs; the clamp is
                               * idempotent) */
   struct m_shade_env env;
   struct t_eye_normal en;
   /* Cook-Torrance batches lit eight vertices at a time (m_shade_point8,
    * t_light.c light_shade8): every material property of the lit faces is
    * the batch's constant (in env) or the vertex colour (env's
    * color_material bits, read from color, cstride floats apart) */
   bool shade8;
   const float *color;
   unsigned cstride;
};

/* Prepare the lighting of the batch of stored vertices starting at in. */
void t_light_prepare(const struct fgl_context *ctx, const struct fgl_vertex_view *in,
                     struct t_light_batch *lb);

/* Light the batch's vertices first..first+n-1 (in and out index the
 * whole batch): the R_ATTR_* colour slots of out[], before the clamp
 * (but for the lb->clamped first ones). */
void t_light_run(const struct fgl_context *ctx, struct t_light_batch *lb,
                 const struct fgl_vertex_view *in, unsigned first, unsigned n,
                 struct t_vertex *out);

#ifdef FGL_HAVE_BLOCK_KERNELS
/* t_light_run of a batch with lb->shade8, AVX2 + FMA (t_light_avx2.c):
 * only where m_shade_point8_avx2_supported(). */
void t_light_shade8_avx2(const struct fgl_context *ctx, const struct t_light_batch *lb,
                         const struct fgl_vertex_view *in, unsigned first, unsigned n,
                         struct t_vertex *out);
/* the same built with AVX-512 VL/BW/DQ as well (r_kernel_isa R_ISA_AVX512) */
void t_light_shade8_avx512(const struct fgl_context *ctx, const struct t_light_batch *lb,
                           const struct fgl_vertex_view *in, unsigned first, unsigned n,
                           struct t_vertex *out);
#endif

/* LIT's pow of n argument pairs, out[k] = m_gallivm_pow(x[k], y[k]),
 * through light_simd's eight-lane pow where the CPU has AVX2 and FMA (for
 * the unit test that checks they are the same bits). */
void t_lit_pows(const float *x, const float *y, float *out, unsigned n);

#endif
