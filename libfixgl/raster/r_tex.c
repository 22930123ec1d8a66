/*
 * Texture sampling, bit-exact with llvmpipe's fixed-point AoS path for
 * 8-bit unorm textures (ORACLE-NOTES.md "Texture sampling: the 8-bit
 * path", "Texture sampling: level of detail per quad"; probes p_tex,
 * p_mipmap) and its
 * fast level-of-detail selection [S: gallivm/lp_bld_sample_aos.c,
 * lp_bld_sample.c:lp_build_rho, lp_build_lod_selector, lp_bld_arit.c:
 * lp_build_fast_log2, lp_build_ilog2].
 *
 * Dispatch: r_tex_sample handles the samplers state.c marks as AoS with
 * the fast LOD (wraps REPEAT / CLAMP_TO_EDGE, no LOD bias, no min/max LOD
 * clamp); every other sampler (`soa` set: GL_CLAMP, CLAMP_TO_BORDER,
 * MIRRORED_REPEAT, LOD bias, MIN_LOD/MAX_LOD) goes whole to
 * r_tex_sample_soa (r_tex_soa.c), with the same arguments: the fragment's
 * projected coordinate and those of the top-left, top-right and
 * bottom-left pixels of its quad.
 */
#include "r_state.h"
#include "r_tex_lod.h"

#include <math.h>
#include <string.h>

/* cvtps2dq / cvttps2dq of values outside int32 give INT32_MIN */
static inline int32_t iround_even(float f)
{
   if (!(f >= -2147483648.0f && f < 2147483648.0f))
      return INT32_MIN;
   return r_round_even(f);
}

static inline int32_t itrunc(float f)
{
   if (!(f >= -2147483648.0f && f < 2147483648.0f))
      return INT32_MIN;
   return (int32_t)f;
}

static inline int32_t ifloor(float f)
{
   return itrunc(floorf(f));
}

/* [S: lp_bld_arit.c:lp_build_lerp_simple] on 8-bit channels with SSSE3 /
 * AVX2: pmulhrsw rounding, (w*(b-a) + 128) >> 8, then the low 8 bits. */
static inline int lerp8(int w, int a, int b)
{
   return (a + ((w * (b - a) + 128) >> 8)) & 0xff;
}

static inline int clampi(int i, int lo, int hi)
{
   return i < lo ? lo : (i > hi ? hi : i);
}

/* lp_build_fract_safe: s - floor(s), kept below 1 */
static inline float fract_safe(float s)
{
   const float f = s - floorf(s);
   return f < 0.99999994f ? f : 0.99999994f;
}

/* Texel index of NEAREST filtering along one axis of size n
 * [S: lp_bld_sample_aos.c:lp_build_sample_wrap_nearest_int]. */
static int wrap_nearest(float s, int n, bool pot, enum r_tex_wrap wrap)
{
   if (wrap == R_WRAP_REPEAT) {
      if (pot)
         return ifloor(s * (float)n) & (n - 1);
      return itrunc(fract_safe(s) * (float)n);
   }
   /* CLAMP_TO_EDGE */
   return clampi(ifloor(s * (float)n), 0, n - 1);
}

/* Texel indices and 8-bit weight of LINEAR filtering along one axis
 * [S: lp_bld_sample_aos.c:lp_build_sample_wrap_linear_int]: the
 * coordinate in 24.8 fixed point (RNE), minus half a texel. */
static void wrap_linear(float s, int n, bool pot, enum r_tex_wrap wrap,
                        int *i0, int *i1, int *w)
{
   if (wrap == R_WRAP_REPEAT && !pot) {
      const float v = (fract_safe(s) * (float)n) * 256.0f;
      int i = iround_even(v) - 128;
      *w = i & 255;
      i >>= 8;
      if (i < 0)
         i = n - 1;
      if (i > n - 1)
         i = n - 1;
      *i0 = i;
      *i1 = i != n - 1 ? i + 1 : 0;
      return;
   }
   const int u = (int)((uint32_t)iround_even(s * (float)(n << 8)) - 128u);
   *w = u & 255;
   const int i = u >> 8;
   if (wrap == R_WRAP_REPEAT) {
      *i0 = i & (n - 1);
      *i1 = (i + 1) & (n - 1);
   } else {
      *i0 = clampi(i, 0, n - 1);
      *i1 = (i < 0 || i >= n - 1) ? *i0 : i + 1;
   }
}

static inline const uint8_t *texel(const struct r_tex_level *l, int x, int y)
{
   return l->data + 4 * ((size_t)y * (size_t)l->width + (size_t)x);
}

static inline const uint8_t *texel3(const struct r_tex_level *l, int x, int y, int z)
{
   return texel(l, x, (int)((size_t)z * (size_t)l->height) + y);
}

/* sample_level of a 3D texture [S: lp_bld_sample_aos.c:
 * lp_build_sample_image_nearest, lp_build_sample_image_linear,
 * lp_build_reduce_filter_3d]: r wraps as s and t do (its own pot flag),
 * and LINEAR lerps the two slices' bilinear results along r by r's
 * 8-bit weight. */
static void sample_level_3d(const struct r_texture *t, const struct r_tex_level *l,
                            enum r_tex_filter filter, const float c[3], int out[4])
{
   if (filter == R_TEX_NEAREST) {
      const int i = wrap_nearest(c[0], l->width, t->pot_s, t->wrap_s);
      const int j = wrap_nearest(c[1], l->height, t->pot_t, t->wrap_t);
      const int k = wrap_nearest(c[2], l->depth, t->pot_r, t->wrap_r);
      const uint8_t *p = texel3(l, i, j, k);
      for (int n = 0; n < 4; n++)
         out[n] = p[n];
      return;
   }
   int i0, i1, ws, j0, j1, wt, k0, k1, wr;
   wrap_linear(c[0], l->width, t->pot_s, t->wrap_s, &i0, &i1, &ws);
   wrap_linear(c[1], l->height, t->pot_t, t->wrap_t, &j0, &j1, &wt);
   wrap_linear(c[2], l->depth, t->pot_r, t->wrap_r, &k0, &k1, &wr);
   const uint8_t *a0 = texel3(l, i0, j0, k0), *b0 = texel3(l, i1, j0, k0);
   const uint8_t *d0 = texel3(l, i0, j1, k0), *e0 = texel3(l, i1, j1, k0);
   const uint8_t *a1 = texel3(l, i0, j0, k1), *b1 = texel3(l, i1, j0, k1);
   const uint8_t *d1 = texel3(l, i0, j1, k1), *e1 = texel3(l, i1, j1, k1);
   for (int n = 0; n < 4; n++) {
      const int s0 = lerp8(wt, lerp8(ws, a0[n], b0[n]), lerp8(ws, d0[n], e0[n]));
      const int s1 = lerp8(wt, lerp8(ws, a1[n], b1[n]), lerp8(ws, d1[n], e1[n]));
      out[n] = lerp8(wr, s0, s1);
   }
}

/* sample_level's LINEAR filter for a 2D texture with REPEAT on both axes
 * and a power-of-two size, the commonest lookup, inlined: wrap_linear's
 * pot REPEAT branch on both axes, then the same lerps. */
static inline __attribute__((always_inline)) void
linear_2d_repeat_pot(const struct r_tex_level *l, const float c[3], int out[4])
{
   const int w = l->width, h = l->height;
   const int us = (int)((uint32_t)iround_even(c[0] * (float)(w << 8)) - 128u);
   const int ut = (int)((uint32_t)iround_even(c[1] * (float)(h << 8)) - 128u);
   const int ws = us & 255, wt = ut & 255;
   const int is = us >> 8, it = ut >> 8;
   const size_t x0 = (size_t)(is & (w - 1)), x1 = (size_t)((is + 1) & (w - 1));
   const size_t y0 = (size_t)(it & (h - 1)), y1 = (size_t)((it + 1) & (h - 1));
   const uint8_t *r0 = l->data + 4 * y0 * (size_t)w, *r1 = l->data + 4 * y1 * (size_t)w;
   const uint8_t *a = r0 + 4 * x0, *b = r0 + 4 * x1, *d = r1 + 4 * x0, *e = r1 + 4 * x1;
   for (int k = 0; k < 4; k++)
      out[k] = lerp8(wt, lerp8(ws, a[k], b[k]), lerp8(ws, d[k], e[k]));
}

/* One level, one image filter, to 8-bit channels
 * [S: lp_bld_sample_aos.c:lp_build_sample_image_nearest,
 * lp_build_sample_image_linear]: lerp along s on rows t0 and t1, then
 * along t (3D: sample_level_3d). */
static void sample_level(const struct r_texture *t, int lvl, enum r_tex_filter filter,
                         const float c[3], int out[4])
{
   const struct r_tex_level *l = &t->level[lvl];
   if (t->dims == 3) {
      sample_level_3d(t, l, filter, c, out);
      return;
   }
   if (filter == R_TEX_NEAREST) {
      const int i = wrap_nearest(c[0], l->width, t->pot_s, t->wrap_s);
      const int j = t->dims > 1 ? wrap_nearest(c[1], l->height, t->pot_t, t->wrap_t) : 0;
      const uint8_t *p = texel(l, i, j);
      for (int k = 0; k < 4; k++)
         out[k] = p[k];
      return;
   }
   if (t->dims == 2 && t->wrap_s == R_WRAP_REPEAT && t->wrap_t == R_WRAP_REPEAT &&
       t->pot_s && t->pot_t) {
      linear_2d_repeat_pot(l, c, out);
      return;
   }
   int i0, i1, ws;
   wrap_linear(c[0], l->width, t->pot_s, t->wrap_s, &i0, &i1, &ws);
   if (t->dims == 1) {
      const uint8_t *a = texel(l, i0, 0), *b = texel(l, i1, 0);
      for (int k = 0; k < 4; k++)
         out[k] = lerp8(ws, a[k], b[k]);
      return;
   }
   int j0, j1, wt;
   wrap_linear(c[1], l->height, t->pot_t, t->wrap_t, &j0, &j1, &wt);
   const uint8_t *a = texel(l, i0, j0), *b = texel(l, i1, j0);
   const uint8_t *d = texel(l, i0, j1), *e = texel(l, i1, j1);
   for (int k = 0; k < 4; k++)
      out[k] = lerp8(wt, lerp8(ws, a[k], b[k]), lerp8(ws, d[k], e[k]));
}

void r_tex_sample(const struct r_texture *t, const float c[3], const float quad[3][3],
                  const float (*pair)[3], float out[4])
{
   if (t->cube == R_CUBE_MAP) {
      /* (r_frag.c calls r_tex_sample_cube itself with the whole quad;
       * here the top-left pixel's derivatives stand for every pixel's) */
      const float q4[4][3] = {
         { quad[0][0], quad[0][1], quad[0][2] }, { quad[1][0], quad[1][1], quad[1][2] },
         { quad[2][0], quad[2][1], quad[2][2] }, { quad[2][0], quad[2][1], quad[2][2] },
      };
      (void)pair;
      r_tex_sample_cube(t, c, q4, 0, NULL, out);
   } else if (t->soa)
      r_tex_sample_soa(t, c, quad, pair, out);
   else
      r_tex_sample_aos(t, c, quad, out);
}

void r_tex_filter_aos(const struct r_texture *t, const float c[3], bool minify,
                      int level0, int level1, int weight, float out[4])
{
   int texel8[4];
   if (!minify && t->mag_img != t->min_img) {
      /* the magnification branch: one level, no mip filter
       * [S: lp_bld_sample_aos.c:lp_build_sample_aos] */
      sample_level(t, level0, t->mag_img, c, texel8);
   } else if (t->mip == R_MIP_NONE) {
      sample_level(t, t->first_level, minify ? t->min_img : t->mag_img, c, texel8);
   } else {
      /* [S: lp_bld_sample_aos.c:lp_build_sample_mipmap] */
      sample_level(t, level0, t->min_img, c, texel8);
      if (t->mip == R_MIP_LINEAR && weight > 0) {
         int t1[4];
         sample_level(t, level1, t->min_img, c, t1);
         for (int k = 0; k < 4; k++)
            texel8[k] = lerp8(weight, texel8[k], t1[k]);
      }
   }
   /* unorm8 to float: a multiply by (float)(1.0/255.0)
    * [S: lp_bld_conv.c:lp_build_unsigned_norm_to_float] */
   const float scale = (float)(1.0 / 255.0);
   for (int k = 0; k < 4; k++)
      out[k] = (float)texel8[k] * scale;
}

void r_tex_lod_aos(const struct r_texture *t, const float quad[3][3], struct r_tex_lod *lod)
{
   r_tex_lod_aos_inline(t, quad, lod);
}

float r_tex_rho(const struct r_texture *t, const float q[3][3])
{
   return r_tex_rho_inline(t, q);
}

void r_tex_sample_aos(const struct r_texture *t, const float c[3], const float quad[3][3],
                      float out[4])
{
   struct r_tex_lod lod;
   r_tex_lod_aos(t, quad, &lod);
   r_tex_filter_aos(t, c, lod.minify, lod.level0, lod.level1, lod.weight, out);
}
