/*
 * The fast level-of-detail selection of the AoS path (r_tex_lod_aos,
 * r_tex_rho; documented in r_state.h), inline for r_tex.c and the 8-lane
 * kernels (r_tex_avx2.c), so that both run the same code.
 */
#ifndef FGL_R_TEX_LOD_H
#define FGL_R_TEX_LOD_H

#include <math.h>
#include <string.h>

#include "r_state.h"

/* cvttps2dq: INT32_MIN outside int32 */
static inline int32_t r_lod_itrunc(float f)
{
   if (!(f >= -2147483648.0f && f < 2147483648.0f))
      return INT32_MIN;
   return (int32_t)f;
}

static inline int r_lod_clampi(int i, int lo, int hi)
{
   return i < lo ? lo : (i > hi ? hi : i);
}

/* biased exponent field of a float */
static inline int r_lod_float_exp(float x)
{
   return (int)((r_f2u(x) >> 23) & 255u);
}

/* rho of the quad [S: lp_bld_sample.c:lp_build_rho] from the base
 * level's size.  2D (no_rho_approx): the squared length,
 * max((dsdx*W)^2 + (dtdx*H)^2, (dsdy*W)^2 + (dtdy*H)^2); 3D adds
 * (drdx*D)^2 and (drdy*D)^2 to those sums (ORACLE-NOTES.md "3D
 * textures").  1D (the
 * approximation stays on for one dimension): max(|dsdx|, |dsdy|) * W, not
 * squared. */
static inline float r_tex_rho_inline(const struct r_texture *t, const float q[3][3])
{
   if (t->cube)
      return r_tex_cube_rho(t, q);
   const struct r_tex_level *l = &t->level[t->first_level];
   const float fw = (float)l->width;
   if (t->dims == 1) {
      const float dx = fabsf(q[R_QUAD_TR][0] - q[R_QUAD_TL][0]);
      const float dy = fabsf(q[R_QUAD_TL][0] - q[R_QUAD_BL][0]);
      const float m = dx > dy ? dx : dy;
      return m * fw;
   }
   const float fh = (float)l->height;
   float dsdx = (q[R_QUAD_TR][0] - q[R_QUAD_TL][0]) * fw;
   float dsdy = (q[R_QUAD_BL][0] - q[R_QUAD_TL][0]) * fw;
   float dtdx = (q[R_QUAD_TR][1] - q[R_QUAD_TL][1]) * fh;
   float dtdy = (q[R_QUAD_BL][1] - q[R_QUAD_TL][1]) * fh;
   dsdx = dsdx * dsdx;
   dsdy = dsdy * dsdy;
   dtdx = dtdx * dtdx;
   dtdy = dtdy * dtdy;
   float rx = dsdx + dtdx, ry = dsdy + dtdy;
   if (t->dims == 3) {
      /* lp_build_packed_ddx_ddy_onecoord's r derivatives (x: TR - TL,
       * y: TL - BL, the sign lost in the square) times the depth,
       * squared, added to the s + t sums */
      const float fd = (float)l->depth;
      float drdx = (q[R_QUAD_TR][2] - q[R_QUAD_TL][2]) * fd;
      float drdy = (q[R_QUAD_TL][2] - q[R_QUAD_BL][2]) * fd;
      drdx = drdx * drdx;
      drdy = drdy * drdy;
      rx = rx + drdx;
      ry = ry + drdy;
   }
   return rx > ry ? rx : ry;
}

static inline void r_tex_lod_aos_inline(const struct r_texture *t, const float quad[3][3],
                                        struct r_tex_lod *lod)
{
   const int first = t->first_level, last = t->last_level;
   if (t->mip == R_MIP_NONE && t->min_img == t->mag_img) {
      /* no level of detail at all */
      lod->minify = true;
      lod->level0 = lod->level1 = first;
      lod->weight = 0;
      return;
   }
   /* the fast LOD path of lp_build_lod_selector (no bias, no clamps) */
   const float rho = r_tex_rho_inline(t, quad);
   const bool squared = t->dims > 1;
   bool minify;
   int level0 = first, level1 = first, weight = 0;
   if (t->mip != R_MIP_LINEAR) {
      /* lp_build_ilog2_sqrt (2D: rho squared) or lp_build_ilog2 (1D:
       * log2(rho * sqrt(2)) rounded down), then
       * lp_build_nearest_mip_level's clamp to the level range */
      int ipart;
      if (squared)
         ipart = (r_lod_float_exp(rho) - 126) >> 1;
      else
         ipart = r_lod_float_exp(rho * (float)M_SQRT2) - 127;
      /* lp_build_cmp(GREATER): an unordered compare, NaN (a coordinate
       * divided by q = 0) minifies */
      minify = !(rho <= 1.0f);
      level0 = r_lod_clampi(first + ipart, first, last);
   } else {
      /* lp_build_fast_log2 of rho squared, halved
       * [S: lp_bld_sample.c:lp_build_lod_selector, ordinary path]; then
       * lp_build_linear_mip_levels */
      const float r2 = squared ? rho : rho * rho;
      const float l2 = (float)(r_lod_float_exp(r2) - 128) +
                       r_u2f((r_f2u(r2) & 0x7fffffu) | 0x3f800000u);
      const float lod = l2 * 0.5f;
      minify = !(lod <= 0.0f);   /* unordered, as above */
      const float fl = floorf(lod);
      float fpart = lod - fl;
      int l0 = first + r_lod_itrunc(fl);
      if (l0 < first) {
         l0 = first;
         fpart = 0.0f;
      }
      if (l0 >= last) {
         l0 = last;
         fpart = 0.0f;
      }
      level0 = l0;
      level1 = l0 + 1 <= last ? l0 + 1 : last;
      weight = r_lod_itrunc(fpart * 256.0f);
   }
   lod->minify = minify;
   lod->level0 = level0;
   lod->level1 = level1;
   lod->weight = weight;
}

#endif
