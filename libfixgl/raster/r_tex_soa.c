/*
 * llvmpipe's float (SoA) texture sampling path and its general level-of-
 * detail selection, bit-exact (ORACLE-NOTES.md "Texture sampling: the
 * float SoA path and the general LOD"; probe conformance/probes/
 * p_tex_float.c for the wraps and float lerps; cases texture/wrap_*,
 * texture/lod_*: every wrap mode x filter x size, mipmaps, LOD bias,
 * MIN_LOD/MAX_LOD, BASE/MAX_LEVEL, 1D, border colours of every base
 * format, projective coordinates).
 *
 * r_tex_sample (r_tex.c) hands a lookup here when state.c set `soa`:
 *  - float_path: the sampler is not one the fixed-point AoS path takes
 *    (a wrap mode other than REPEAT / CLAMP_TO_EDGE on a used axis)
 *    [S: gallivm/lp_bld_sample_soa.c:lp_build_sample_soa_code, use_aos];
 *    the texels are filtered as floats [S: lp_bld_sample_soa.c:
 *    lp_build_sample_general];
 *  - otherwise the AoS path samples (r_tex_filter_aos, r_tex.c) with the
 *    level of detail of the general path: LOD bias, MIN_LOD / MAX_LOD
 *    [S: gallivm/lp_bld_sample.c:lp_build_lod_selector].
 *
 * The fragment shader runs on 8 pixels at once, two 2x2 quads side by
 * side (the 4x2 halves of a 4x4 block [S: llvmpipe/lp_bld_interp.c,
 * quad_offset_x/y]); with min filter != mag filter the float path makes
 * one choice per 8 pixels (below), so a lookup also gets the coordinates
 * of the other quad of its 8 ("pair").
 */
#include "r_state.h"
#include "r_blend.h"

#include <math.h>
#include <string.h>

/* cvttps2dq (LLVMBuildFPToSI): INT32_MIN outside int32 and for NaN */
static inline int32_t itrunc(float f)
{
   if (!(f >= -2147483648.0f && f < 2147483648.0f))
      return INT32_MIN;
   return (int32_t)f;
}

/* minps / maxps, as lp_build_min / lp_build_max emit them: the second
 * operand when either is NaN */
static inline float fmin_ps(float a, float b)
{
   return a < b ? a : b;
}

static inline float fmax_ps(float a, float b)
{
   return a > b ? a : b;
}

/* lp_build_lerp on floats: lp_build_mad(w, v1 - v0, v0), an
 * llvm.fmuladd, fused on the FMA host [S: lp_bld_arit.c:
 * lp_build_lerp_simple, lp_build_fmuladd] (ORACLE-NOTES.md "The oracle
 * and its host") */
static inline float lerp_f(float w, float v0, float v1)
{
   return fmaf(w, v1 - v0, v0);
}

/* ---- level of detail [S: lp_bld_sample.c:lp_build_lod_selector] ------- */

/* A quad's level of detail: minified or not, the level(s) to sample
 * (absolute) and the float weight of the second one. */
struct lod {
   bool minify;
   int level0, level1;
   float fpart;
};

static inline int float_exp(float x)
{
   return (int)((r_f2u(x) >> 23) & 255u);
}

/* lp_build_fast_log2: (exponent - 128) + the mantissa as a float in [1,2) */
static inline float fast_log2(float x)
{
   return (float)(float_exp(x) - 128) + r_u2f((r_f2u(x) & 0x7fffffu) | 0x3f800000u);
}

/* lod_positive (minified) is lp_build_cmp(GREATER), an unordered compare
 * (LLVMRealUGT) [S: lp_bld_logic.c:lp_build_compare_ext, ordered FALSE]:
 * a NaN rho or lod (derivatives of infinite coordinates, q == 0) minifies. */
static void quad_lod(const struct r_texture *t, const float q[3][3], struct lod *r)
{
   const int first = t->first_level, last = t->last_level;
   r->minify = false;
   r->level0 = r->level1 = first;
   r->fpart = 0.0f;
   /* lp_build_sample_common: no LOD at all without a mip filter and with
    * min filter == mag filter */
   if (t->mip == R_MIP_NONE && t->min_img == t->mag_img)
      return;
   float lod;
   if (t->min_max_lod_equal) {
      /* MIN_LOD == MAX_LOD: the LOD is min_lod, no rho, no bias */
      lod = t->min_lod;
   } else {
      /* lp_build_rho (r_tex.c) */
      float rho = r_tex_rho(t, q);
      const bool squared = t->dims > 1;
      if (!t->lod_bias_non_zero && !t->apply_min_lod && !t->apply_max_lod &&
          t->mip != R_MIP_LINEAR) {
         /* the special case without post-log2 adjustments: the integer
          * part only, lp_build_ilog2_sqrt (2D) / lp_build_ilog2 (1D), and
          * minified iff rho > 1 */
         int ipart;
         if (squared)
            ipart = (float_exp(rho) - 126) >> 1;
         else
            ipart = float_exp(rho * (float)M_SQRT2) - 127;
         /* lp_build_cmp(GREATER) is unordered: NaN minifies */
         r->minify = !(rho <= 1.0f);
         if (t->mip == R_MIP_NEAREST) {
            /* lp_build_nearest_mip_level: clamp (min, then max) */
            int l = first + ipart;
            l = l < last ? l : last;
            r->level0 = l > first ? l : first;
         }
         return;
      }
      /* rho squared (brilinear is off), fast_log2, halved */
      if (!squared)
         rho = rho * rho;
      lod = fast_log2(rho) * 0.5f;
      /* + the sampler's bias (object + unit, each quantized), then
       * max_lod, then min_lod */
      if (t->lod_bias_non_zero)
         lod = lod + t->lod_bias;
      if (t->apply_max_lod)
         lod = fmin_ps(lod, t->max_lod);
      if (t->apply_min_lod)
         lod = fmax_ps(lod, t->min_lod);
   }
   r->minify = !(lod <= 0.0f);   /* unordered: NaN minifies */
   if (t->mip == R_MIP_NEAREST) {
      /* lp_build_iround (cvtps2dq, half to even), then
       * lp_build_nearest_mip_level */
      int l = r_round_even(lod);
      l = l == INT32_MIN ? l : first + l;
      l = l < last ? l : last;
      r->level0 = l > first ? l : first;
   } else if (t->mip == R_MIP_LINEAR) {
      /* lp_build_ifloor_fract, then lp_build_linear_mip_levels */
      const float fl = floorf(lod);
      float fpart = lod - fl;
      int l0 = first + itrunc(fl), l1 = l0 + 1;
      if (l0 < first) {
         l0 = l1 = first;
         fpart = 0.0f;
      }
      if (l0 >= last) {
         l0 = l1 = last;
         fpart = 0.0f;
      }
      r->level0 = l0;
      r->level1 = l1;
      r->fpart = fpart;
   }
}

/* ---- the float path: wrap modes [S: lp_bld_sample_soa.c] ------------- */

/* lp_build_coord_mirror(posOnly): 2*(x/2 - round(x/2)) (round half to
 * even, roundps), its absolute value, NaN killed by a max with 0 */
static inline float coord_mirror(float c)
{
   c = c * 0.5f;
   const float f = c - nearbyintf(c);
   c = f + f;
   return fmax_ps(fabsf(c), 0.0f);
}

static bool wrap_uses_border(enum r_tex_wrap wrap, const struct r_texture *t)
{
   /* lp_bld_sample.c:lp_sampler_wrap_mode_uses_border_color */
   switch (wrap) {
   case R_WRAP_CLAMP:
   case R_WRAP_MIRROR_CLAMP:
      return t->min_img != R_TEX_NEAREST || t->mag_img != R_TEX_NEAREST;
   case R_WRAP_CLAMP_TO_BORDER:
   case R_WRAP_MIRROR_CLAMP_TO_BORDER:
      return true;
   default:
      return false;
   }
}

/* lp_build_sample_wrap_nearest: the texel index along one axis (outside
 * [0, n) selects the border colour) */
static int wrap_nearest(float c, int n, bool pot, enum r_tex_wrap wrap)
{
   const float nf = (float)n;
   int i;
   switch (wrap) {
   case R_WRAP_REPEAT:
      if (pot)
         return itrunc(floorf(c * nf)) & (n - 1);
      /* lp_build_fract_safe, unnormalize, itrunc */
      c = fmin_ps(c - floorf(c), 0x1.fffffep-1f);
      return itrunc(c * nf);
   case R_WRAP_CLAMP:
   case R_WRAP_CLAMP_TO_EDGE:
   default:
      /* itrunc, then lp_build_clamp (min, then max) */
      i = itrunc(c * nf);
      i = i < n - 1 ? i : n - 1;
      return i > 0 ? i : 0;
   case R_WRAP_CLAMP_TO_BORDER:
      return itrunc(floorf(c * nf));
   case R_WRAP_MIRRORED_REPEAT:
      i = itrunc(coord_mirror(c) * nf);
      return i < n - 1 ? i : n - 1;
   case R_WRAP_MIRROR_CLAMP:
   case R_WRAP_MIRROR_CLAMP_TO_EDGE:
      /* unsigned min with n - 1 */
      i = itrunc(fabsf(c * nf));
      return (uint32_t)i < (uint32_t)(n - 1) ? i : n - 1;
   case R_WRAP_MIRROR_CLAMP_TO_BORDER:
      return itrunc(fabsf(c * nf));
   }
}

/* lp_build_ifloor_fract (roundps floor, then fptosi and a fsub) */
static inline void floor_fract(float c, int *i, float *f)
{
   const float ip = floorf(c);
   *f = c - ip;
   *i = itrunc(ip);
}

/* lp_build_sample_wrap_linear: the two texel indices and the weight of
 * the second along one axis */
static void wrap_linear(float c, int n, bool pot, enum r_tex_wrap wrap,
                        int *x0, int *x1, float *w)
{
   const float nf = (float)n;
   switch (wrap) {
   case R_WRAP_REPEAT:
      if (pot) {
         floor_fract(c * nf - 0.5f, x0, w);
         *x1 = (*x0 + 1) & (n - 1);
         *x0 &= n - 1;
      } else {
         /* lp_build_coord_repeat_npot_linear: fract (not the safe one),
          * scale, -0.5; an unordered c < 0 selects n - 1 */
         c = c - floorf(c);
         c = c * nf - 0.5f;
         const bool neg = !(c >= 0.0f);
         floor_fract(c, x0, w);
         if (neg)
            *x0 = n - 1;
         *x1 = *x0 != n - 1 ? *x0 + 1 : 0;
      }
      return;
   case R_WRAP_CLAMP:
      /* clamp to [0, n] (min, then max), -0.5 */
      c = fmax_ps(fmin_ps(c * nf, nf), 0.0f);
      floor_fract(c - 0.5f, x0, w);
      *x1 = *x0 + 1;
      return;
   case R_WRAP_CLAMP_TO_EDGE:
   default:
      c = fmin_ps(c * nf, nf) - 0.5f;
      floor_fract(fmax_ps(c, 0.0f), x0, w);
      *x1 = *x0 + 1 < n - 1 ? *x0 + 1 : n - 1;
      return;
   case R_WRAP_CLAMP_TO_BORDER:
      floor_fract(c * nf - 0.5f, x0, w);
      *x1 = *x0 + 1;
      return;
   case R_WRAP_MIRRORED_REPEAT:
      floor_fract(coord_mirror(c) * nf - 0.5f, x0, w);
      *x1 = *x0 + 1 < n - 1 ? *x0 + 1 : n - 1;
      *x0 = *x0 > 0 ? *x0 : 0;
      return;
   case R_WRAP_MIRROR_CLAMP:
      c = fmin_ps(fabsf(c * nf), nf);
      floor_fract(c - 0.5f, x0, w);
      *x1 = *x0 + 1;
      return;
   case R_WRAP_MIRROR_CLAMP_TO_EDGE:
      c = fmin_ps(fabsf(c * nf), nf) - 0.5f;
      floor_fract(fmax_ps(c, 0.0f), x0, w);
      *x1 = *x0 + 1 < n - 1 ? *x0 + 1 : n - 1;
      return;
   case R_WRAP_MIRROR_CLAMP_TO_BORDER:
      floor_fract(fabsf(c * nf) - 0.5f, x0, w);
      *x1 = *x0 + 1;
      return;
   }
}

/* lp_build_sample_texel_soa: one texel as floats, t * (float)(1/255)
 * [S: lp_bld_conv.c:lp_build_unsigned_norm_to_float]; outside the level
 * on an axis whose wrap uses it, the border colour replaces the channels
 * the format has (border_mask) and the others keep the format's constant
 * (those of texel (0, 0), where the fetch is redirected). */
static void texel(const struct r_texture *t, int lvl, int x, int y, int z, float out[4])
{
   const struct r_tex_level *l = &t->level[lvl];
   bool border = false;
   if (wrap_uses_border(t->wrap_s, t) && (x < 0 || x >= l->width))
      border = true;
   if (t->dims > 1 && wrap_uses_border(t->wrap_t, t) && (y < 0 || y >= l->height))
      border = true;
   if (t->dims > 2 && wrap_uses_border(t->wrap_r, t) && (z < 0 || z >= l->depth))
      border = true;
   if (border)
      x = y = z = 0;
   const size_t at =
      4 * (((size_t)z * (size_t)l->height + (size_t)y) * (size_t)l->width + (size_t)x);
   if (l->zvalues) {
      /* a depth texture: the value in every channel (the swizzle comes
       * after the filter, r_tex_sample_soa); the border colour replaces
       * the format's one channel, X */
      const float d = border ? t->border_color[0]
                             : r_tex_depth_value(l->zvalues[at / 4], t->depth_bits);
      out[0] = out[1] = out[2] = out[3] = d;
      return;
   }
   if (l->store) {
      /* a format wider (or narrower) than 8 bits per channel: the stored
       * n-bit value times (float)(1 / (2^n - 1)) [S: lp_bld_conv.c:
       * lp_build_unsigned_norm_to_float], a constant channel as is */
      const uint16_t *q = l->store + at;
      for (int c = 0; c < 4; c++) {
         float v = l->store_bits[c] ? (float)q[c] * l->store_scale[c] : (float)q[c];
         out[c] = border && (t->border_mask >> c & 1) ? t->border_color[c] : v;
      }
      return;
   }
   const uint8_t *p = l->data + at;
   const float scale = (float)(1.0 / 255.0);
   for (int c = 0; c < 4; c++)
      out[c] = border && (t->border_mask >> c & 1) ? t->border_color[c] : (float)p[c] * scale;
}

/* ---- the shadow comparison [S: lp_bld_sample_soa.c:
 * lp_build_sample_comparefunc, lp_build_masklerp, lp_build_masklerp2d] --- */

/* The reference value: the coordinate after the texture's own (t of a 1D
 * texture, r of a 2D one: ff_fragment_shader.cpp load_texture's
 * shadow_comparator, divided by q with the others), clamped to [0, 1]
 * as the format is unorm (lp_build_sample_common: lp_build_clamp, min then
 * max; a NaN becomes 1). */
static inline float shadow_ref(const struct r_texture *t, const float c[3])
{
   return fmax_ps(fmin_ps(c[t->dims == 1 ? 1 : 2], 1.0f), 0.0f);
}

/* p FUNC texel: ordered comparisons, NOTEQUAL unordered (C's) */
static inline bool shadow_pass(const struct r_texture *t, float p, float texel_value)
{
   R_COMPARE((enum r_func)t->compare_func, p, texel_value)
}

/* lp_build_masklerp: the weight where the second texel passes plus
 * 1 - weight where the first does */
static inline float masklerp(float w, bool m0, bool m1)
{
   const float a = m1 ? w : 0.0f, b = m0 ? 1.0f - w : 0.0f;
   return a + b;
}

/* lp_build_sample_image_nearest */
static void image_nearest(const struct r_texture *t, int lvl, const float c[3], float out[4])
{
   const struct r_tex_level *l = &t->level[lvl];
   const int x = wrap_nearest(c[0], l->width, t->pot_s, t->wrap_s);
   const int y = t->dims > 1 ? wrap_nearest(c[1], l->height, t->pot_t, t->wrap_t) : 0;
   const int z = t->dims > 2 ? wrap_nearest(c[2], l->depth, t->pot_r, t->wrap_r) : 0;
   texel(t, lvl, x, y, z, out);
   if (t->compare) {
      const float v = shadow_pass(t, shadow_ref(t, c), out[0]) ? 1.0f : 0.0f;
      out[0] = out[1] = out[2] = out[3] = v;
   }
}

/* lp_build_sample_image_linear; `nearest` (a pixel lp_build_sample_mipmap_
 * both filters with the nearest filter): each weight becomes 1 if it was
 * > 0.5, else 0 */
static void image_linear(const struct r_texture *t, int lvl, bool nearest, const float c[3],
                         float out[4])
{
   const struct r_tex_level *l = &t->level[lvl];
   int x0, x1, y0 = 0, y1 = 0, z0 = 0, z1 = 0;
   float ws, wt = 0.0f, wr = 0.0f;
   wrap_linear(c[0], l->width, t->pot_s, t->wrap_s, &x0, &x1, &ws);
   if (t->dims > 1)
      wrap_linear(c[1], l->height, t->pot_t, t->wrap_t, &y0, &y1, &wt);
   if (t->dims > 2)
      wrap_linear(c[2], l->depth, t->pot_r, t->wrap_r, &z0, &z1, &wr);
   if (nearest) {
      ws = ws > 0.5f ? 1.0f : 0.0f;
      wt = wt > 0.5f ? 1.0f : 0.0f;
      wr = wr > 0.5f ? 1.0f : 0.0f;
   }
   float n00[4], n01[4];
   texel(t, lvl, x0, y0, z0, n00);
   texel(t, lvl, x1, y0, z0, n01);
   if (t->compare) {
      /* the four (two) comparisons filtered by the weights (PCF); depth
       * textures are 1D or 2D */
      const float p = shadow_ref(t, c);
      float v = masklerp(ws, shadow_pass(t, p, n00[0]), shadow_pass(t, p, n01[0]));
      if (t->dims > 1) {
         float n10[4], n11[4];
         texel(t, lvl, x0, y1, z0, n10);
         texel(t, lvl, x1, y1, z0, n11);
         const float v1 = masklerp(ws, shadow_pass(t, p, n10[0]), shadow_pass(t, p, n11[0]));
         v = lerp_f(wt, v, v1);
      }
      out[0] = out[1] = out[2] = out[3] = v;
      return;
   }
   if (t->dims == 1) {
      for (int k = 0; k < 4; k++)
         out[k] = lerp_f(ws, n00[k], n01[k]);
      return;
   }
   float n10[4], n11[4];
   texel(t, lvl, x0, y1, z0, n10);
   texel(t, lvl, x1, y1, z0, n11);
   /* lp_build_lerp_2d: along s on rows y0 and y1, then along t */
   for (int k = 0; k < 4; k++)
      out[k] = lerp_f(wt, lerp_f(ws, n00[k], n01[k]), lerp_f(ws, n10[k], n11[k]));
   if (t->dims == 2)
      return;
   /* 3D: the same on slice z1, then along r between the slices */
   float m00[4], m01[4], m10[4], m11[4];
   texel(t, lvl, x0, y0, z1, m00);
   texel(t, lvl, x1, y0, z1, m01);
   texel(t, lvl, x0, y1, z1, m10);
   texel(t, lvl, x1, y1, z1, m11);
   for (int k = 0; k < 4; k++) {
      const float s1 = lerp_f(wt, lerp_f(ws, m00[k], m01[k]), lerp_f(ws, m10[k], m11[k]));
      out[k] = lerp_f(wr, out[k], s1);
   }
}

static void image(const struct r_texture *t, int lvl, enum r_tex_filter f, const float c[3],
                  float out[4])
{
   if (f == R_TEX_NEAREST)
      image_nearest(t, lvl, c, out);
   else
      image_linear(t, lvl, false, c, out);
}

/* lp_build_sample_mipmap: level0, then (mip LINEAR) the lerp with level1
 * by the weight.  The oracle lerps all 8 pixels when any has a weight
 * > 0; a lerp by 0 returns level0's value unchanged, so the per-quad test
 * here gives the same result. */
static void sample_mipmap(const struct r_texture *t, enum r_tex_filter f, enum r_tex_mip mip,
                          const struct lod *q, const float c[3], float out[4])
{
   image(t, q->level0, f, c, out);
   if (mip == R_MIP_LINEAR && q->fpart > 0.0f) {
      float c1[4];
      image(t, q->level1, f, c, c1);
      for (int k = 0; k < 4; k++)
         out[k] = lerp_f(q->fpart, out[k], c1[k]);
   }
}

static void sample_float_others(const struct r_texture *t, const float c[3],
                                const float quad[3][3], const float (*const *others)[3],
                                int n_others, float out[4]);

/* lp_build_sample_general (no anisotropy, no shadow compare) */
static void sample_float(const struct r_texture *t, const float c[3], const float quad[3][3],
                         const float (*pair)[3], float out[4])
{
   const float (*other)[3] = pair ? pair : quad;
   sample_float_others(t, c, quad, &other, 1, out);
}

void r_tex_sample_float_lods(const struct r_texture *t, const float c[3],
                             const float quad[3][3], const float (*const *others)[3],
                             int n_others, float out[4])
{
   sample_float_others(t, c, quad, others, n_others, out);
}

/* sample_float with the LODs of the other quads (or pixels) of the
 * 8-pixel vector given by their coordinates */
static void sample_float_others(const struct r_texture *t, const float c[3],
                                const float quad[3][3], const float (*const *others)[3],
                                int n_others, float out[4])
{
   struct lod q;
   quad_lod(t, quad, &q);
   if (t->min_img == t->mag_img) {
      sample_mipmap(t, t->min_img, t->mip, &q, c, out);
      return;
   }
   /* min != mag: one LOD per quad, 8 pixels per vector.  linear_mask
    * (per quad): minified with a LINEAR min filter, else magnified.  If
    * either quad of the 8 wants LINEAR, every pixel is filtered linearly
    * (lp_build_sample_mipmap_both) and the others' weights are rounded to
    * 0 or 1 (this differs from true NEAREST at weights of exactly 0.5 and
    * reaches the border colour under GL_CLAMP); else all use NEAREST with
    * the mip filter of the nearest side. */
   const bool min_linear = t->min_img == R_TEX_LINEAR;
   const bool lin_q = min_linear ? q.minify : !q.minify;
   bool lin_p = false, min_p = false;
   for (int i = 0; i < n_others; i++) {
      struct lod p;
      quad_lod(t, others[i], &p);
      lin_p |= min_linear ? p.minify : !p.minify;
      min_p |= p.minify;
   }
   if (lin_q || lin_p) {
      image_linear(t, q.level0, !lin_q, c, out);
      if (t->mip == R_MIP_LINEAR && (q.minify || min_p)) {
         /* lerp by max(fpart, 0), for all 8 pixels */
         float c1[4];
         image_linear(t, q.level1, !lin_q, c, c1);
         const float w = fmax_ps(q.fpart, 0.0f);
         for (int k = 0; k < 4; k++)
            out[k] = lerp_f(w, out[k], c1[k]);
      }
   } else {
      sample_mipmap(t, R_TEX_NEAREST, min_linear ? R_MIP_NONE : t->mip, &q, c, out);
   }
}

/* The AoS path with the general LOD [S: lp_bld_sample_aos.c:
 * lp_build_sample_aos, lp_build_sample_mipmap] (r_tex_filter_aos):
 * min != mag decided per quad (the AoS path splits 8-wide vectors into
 * quads then), the level weight is (int)(fpart * 256). */
static void sample_aos_lod(const struct r_texture *t, const float c[3], const float quad[3][3],
                           float out[4])
{
   struct lod q;
   quad_lod(t, quad, &q);
   r_tex_filter_aos(t, c, q.minify, q.level0, q.level1, itrunc(q.fpart * 256.0f), out);
}

void r_tex_sample_soa(const struct r_texture *t, const float c[3], const float quad[3][3],
                      const float (*pair)[3], float out[4])
{
   if (t->float_path)
      sample_float(t, c, quad, pair, out);
   else
      sample_aos_lod(t, c, quad, out);
   if (t->depth_bits) {
      /* the sampler view's swizzle of GL_DEPTH_TEXTURE_MODE
       * [S: st_sampler_view.c:compute_texture_format_swizzle] */
      const float v = out[0];
      for (int k = 0; k < 4; k++)
         out[k] = t->depth_swizzle[k] == R_SWZ_X ? v : t->depth_swizzle[k] == R_SWZ_1 ? 1.0f
                                                                                      : 0.0f;
   }
}
