/*
 * The fog coordinate per vertex, as the oracle's fixed-function vertex
 * program computes it (Mesa 22.3 ffvertex_prog.c build_fog, compiled
 * through prog_to_nir and gallivm; ORACLE-NOTES.md "Fog: coordinate and
 * factor"):
 *
 *   source GL_FRAGMENT_DEPTH, by GL_FOG_DISTANCE_MODE_NV:
 *     GL_EYE_PLANE_ABSOLUTE_NV (default)  |z_eye|
 *     GL_EYE_PLANE                        z_eye
 *     GL_EYE_RADIAL_NV                    sqrt(dot3(eye, eye))
 *   source GL_FOG_COORDINATE              |current fog coordinate|
 *
 * z_eye is the DP4 of the position with the modelview's third row, summed
 * from the last component (get_eye_position_z), unless the lighting code
 * already computed the whole eye position with the modelview's column
 * MUL/MAD chain (get_eye_position), whose z is then used; the radial
 * distance always uses that chain.  No FMA: llvmpipe lowers ffma.
 * The result is written as (fc, 0, 0, 1) and interpolated with perspective
 * like the colours, but never flat-shaded (the fragment program's
 * gl_FogFragCoord is not a colour input).
 */
#include "tnl/t_pipeline.h"

#include <math.h>

#include "context.h"

void t_fog(const struct fgl_context *ctx, const struct fgl_vertex_view *in, unsigned n,
           bool eye_position_from_lighting, struct t_vertex *out)
{
   const struct fgl_fog_attrib *fog = &ctx->Fog;
   const float *mv = ctx->ModelviewStack.Top->m;
   const bool from_array = fog->CoordinateSource == GL_FOG_COORDINATE;
   const bool radial = fog->DistanceMode == GL_EYE_RADIAL_NV;
   const bool chain = radial || eye_position_from_lighting;
   /* the fog coordinate of each vertex (glFogCoord, arrays), or the current
    * one for all (stride 0) */
   unsigned fstride = 0;
   const float *fcoord = from_array ? fgl_vbo_attr_ptr(ctx, in, FGL_ATTR_FOG, &fstride) : NULL;

   for (unsigned i = 0; i < n; i++) {
      const float *p = fgl_vv_attr(in, i, FGL_ATTR_POS);
      float fc;
      if (from_array) {
         fc = fabsf(fcoord[(size_t)i * fstride]);
      } else {
         float eye[4];
         if (chain) {
            /* get_eye_position: the column MUL/MAD chain */
            t_mul_mad_chain(eye, mv, p);
         } else {
            /* get_eye_position_z: DP4 with row 2, from the last component */
            eye[2] = ((p[3] * mv[14] + p[2] * mv[10]) + p[1] * mv[6]) + p[0] * mv[2];
         }
         if (radial) {
            /* DP3, RSQ of |d|, RCP: NIR folds rcp(rsq(a)) into sqrt(a)
             * (nir_opt_algebraic.py: ~frcp(frsq(a)) -> fsqrt(a), llvmpipe
             * has no lower_fsqrt) and drops the fabs of a sum of squares,
             * so gallivm's IEEE sqrt of the DP3 */
            const float d = (eye[2] * eye[2] + eye[1] * eye[1]) + eye[0] * eye[0];
            fc = sqrtf(d);
         } else if (fog->DistanceMode == GL_EYE_PLANE) {
            fc = eye[2];
         } else {
            fc = fabsf(eye[2]);
         }
      }
      float *f = out[i].r.attr[R_ATTR_FOG];
      f[0] = fc;
      f[1] = 0.0f;
      f[2] = 0.0f;
      f[3] = 1.0f;
   }
}
