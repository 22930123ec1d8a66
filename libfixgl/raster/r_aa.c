/*
 * The coverage lowering the draw module appends to the fragment shader for
 * its smooth point and line quads (ORACLE-NOTES.md "Line and point
 * rasterization"; [S: gallium/auxiliary/nir/nir_draw_helpers.c:
 * nir_lower_aapoint_impl, nir_lower_aaline_block]).  It runs on the
 * shader's final colour, so after everything the fixed-function program
 * computes and before the per-fragment operations (alpha test included).
 */
#include "r_state.h"

#include <math.h>

/* nir fsat on llvmpipe: NaN gives 0 */
static inline float fsat(float x)
{
   return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f;
}

bool r_fragment_aa(const struct r_state *rs, const float in[][4], float color[4])
{
   const float *aa = in[R_FS_AA];
   switch (rs->fs->aa) {
   case R_AA_POINT: {
      /* aa = (x, y, k, 1) across the quad: discard outside the unit disc;
       * the coverage (1 - d) / (1 - k) is selected where k >= d, i.e. in
       * the inner disc, and the outer ring keeps its alpha (the oracle's
       * selection is inverted relative to its comment) */
      const float dist = aa[0] * aa[0] + aa[1] * aa[1];
      const float k = aa[2], one = aa[3];
      if (one < dist)
         return false;
      const float rcp = 1.0f / (one + -k);
      const float coverage = rcp * (one + -dist);
      const float sel = k >= dist ? coverage : one;
      color[3] = color[3] * sel;
      return true;
   }
   case R_AA_LINE: {
      /* aa = (u, half width, v, half length):
       * alpha *= sat(hw - |u|) * sat(hl - |v|) */
      const float t0 = fsat(aa[1] + -fabsf(aa[0]));
      const float t1 = fsat(aa[3] + -fabsf(aa[2]));
      color[3] = color[3] * (t0 * t1);
      return true;
   }
   case R_AA_NONE:
   default:
      return true;
   }
}
