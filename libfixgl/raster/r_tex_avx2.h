/*
 * r_tex_avx2.h: the 8-lane texture lookup's AVX2 code, shared by the
 * r_tex_sample8 kernel (r_tex_avx2.c) and the textured block kernels
 * (r_block_tex_avx2.c), which sample lanes already in the quad-major order
 * below.  Include only from files compiled with -mavx2 -mfma.
 *
 * Texture lookups 8 fragments at a time with AVX2 (r_tex8.h): llvmpipe's
 * fixed-point AoS filtering of r_tex.c (sample_level, r_tex_filter_aos)
 * on the 8 lanes of a fragment vector at once, four 8-bit channels
 * together.  Compiled with -mavx2 -mfma (and -ffp-contract=off, like the
 * rest): r_tex8.c calls it only on a CPU with both.
 *
 * Every step is the scalar one on each lane: the same float products and
 * floors (floorf, cvttss2si / cvtss2si, which give INT32_MIN out of range
 * or for NaN as cvttps2dq / cvtps2dq do), fract_safe's compare the minps
 * of (f, 0.99999994), the integer wraps, and lerp8's
 * (a + ((w * (b - a) + 128) >> 8)) & 0xff, which pmulhrsw on 16-bit
 * lanes gives exactly (lerp16).  The level of detail is r_tex_lod_aos's code (r_tex_lod.h), once
 * per quad.
 *
 * Lanes run in a quad-major order inside: quad A (lanes 0, 1, 4, 5) in the
 * low 128 bits, quad B (2, 3, 6, 7) in the high ones (one permute of the
 * 64-bit pairs, its own inverse), so the per-quad values (level size,
 * mip weight, texel base address) are a broadcast per 128-bit half and two
 * levels are fetched with one 4-lane gather each.  LINEAR reads both texels
 * of a row with one 64-bit gather per lane when every lane's second texel
 * follows its first (no wrap or edge clamp in the vector), else four
 * 32-bit gathers.  (Gathers measured a little faster than scalar loads on
 * the reference machine, an AMD Zen 4; on Intel parts with the Downfall
 * microcode mitigation, scalar loads may be the better choice.)
 *
 * The quads choose their branch of r_tex_filter_aos separately: when one
 * is magnified and the other minified with different filters, both image
 * filters run on all lanes and each quad keeps its own; a quad without a
 * second mip level takes part in the other's second lookup with weight 0
 * (lerp8(0, a, b) = a, exactly).
 */
#ifndef FGL_R_TEX_AVX2_H
#define FGL_R_TEX_AVX2_H

#include <immintrin.h>
#include <math.h>
#include <stdint.h>

#include "r_tex8.h"
#include "r_tex_lod.h"

/* lanes (0 1 2 3 4 5 6 7) <-> (0 1 4 5 2 3 6 7) */
#define QUAD_ORDER 0xD8

static inline __m256 load_quads(const float *v)
{
   return _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(_mm256_loadu_ps(v)), QUAD_ORDER));
}

static inline void store_lanes(float *v, __m256 x)
{
   _mm256_storeu_ps(v, _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(x), QUAD_ORDER)));
}

/* a for the lanes of quad A, b for those of quad B */
static inline __attribute__((always_inline)) __m256i halves_i(int a, int b)
{
   return _mm256_setr_m128i(_mm_set1_epi32(a), _mm_set1_epi32(b));
}

static inline __attribute__((always_inline)) __m256 halves_f(float a, float b)
{
   return _mm256_setr_m128(_mm_set1_ps(a), _mm_set1_ps(b));
}

/* one axis of the lanes' levels */
struct axis {
   __m256 fn;        /* (float)n */
   __m256 fn256;     /* (float)(n << 8) */
   __m256i nm1;      /* n - 1 */
};

/* the level each lane samples (one per quad) */
struct lv8 {
   const int *base[2];   /* level data of quad A, quad B */
   __m256i width;
   struct axis s, t;
};

static inline void axis_init(struct axis *a, int na, int nb)
{
   a->fn = halves_f((float)na, (float)nb);
   a->fn256 = halves_f((float)(na << 8), (float)(nb << 8));
   a->nm1 = halves_i(na - 1, nb - 1);
}

static inline void lv8_init(const struct r_texture *t, int la, int lb, struct lv8 *v)
{
   const struct r_tex_level *A = &t->level[la], *B = &t->level[lb];
   v->base[0] = (const int *)(const void *)A->data;
   v->base[1] = (const int *)(const void *)B->data;
   v->width = halves_i(A->width, B->width);
   axis_init(&v->s, A->width, B->width);
   axis_init(&v->t, A->height, B->height);
}

/* A level's part of struct lv8, precomputed (a block kernel's table of a
 * texture's levels, filled once per triangle). */
struct tex8_level {
   __m128 fs, fs256, ft, ft256;   /* (float)n, (float)(n << 8) per axis */
   __m128i nm1s, nm1t, width;
   const int *base;
};

static inline void tex8_level_init(const struct r_texture *t, int l, struct tex8_level *o)
{
   const struct r_tex_level *L = &t->level[l];
   o->fs = _mm_set1_ps((float)L->width);
   o->fs256 = _mm_set1_ps((float)(L->width << 8));
   o->ft = _mm_set1_ps((float)L->height);
   o->ft256 = _mm_set1_ps((float)(L->height << 8));
   o->nm1s = _mm_set1_epi32(L->width - 1);
   o->nm1t = _mm_set1_epi32(L->height - 1);
   o->width = _mm_set1_epi32(L->width);
   o->base = (const int *)(const void *)L->data;
}

/* lv8_init from the table: the same values */
static inline __attribute__((always_inline)) void lv8_from(const struct tex8_level *A,
                                                           const struct tex8_level *B,
                                                           struct lv8 *v)
{
   v->base[0] = A->base;
   v->base[1] = B->base;
   if (A == B) {
      /* (both quads on one level: one broadcast load a value) */
      v->width = _mm256_broadcastsi128_si256(A->width);
      v->s.fn = _mm256_broadcast_ps(&A->fs);
      v->s.fn256 = _mm256_broadcast_ps(&A->fs256);
      v->s.nm1 = _mm256_broadcastsi128_si256(A->nm1s);
      v->t.fn = _mm256_broadcast_ps(&A->ft);
      v->t.fn256 = _mm256_broadcast_ps(&A->ft256);
      v->t.nm1 = _mm256_broadcastsi128_si256(A->nm1t);
      return;
   }
   v->width = _mm256_setr_m128i(A->width, B->width);
   v->s.fn = _mm256_setr_m128(A->fs, B->fs);
   v->s.fn256 = _mm256_setr_m128(A->fs256, B->fs256);
   v->s.nm1 = _mm256_setr_m128i(A->nm1s, B->nm1s);
   v->t.fn = _mm256_setr_m128(A->ft, B->ft);
   v->t.fn256 = _mm256_setr_m128(A->ft256, B->ft256);
   v->t.nm1 = _mm256_setr_m128i(A->nm1t, B->nm1t);
}

/* the RGBA8 texels at texel index idx of each lane's level */
static inline __attribute__((always_inline)) __m256i fetch(const struct lv8 *v, __m256i idx)
{
   if (v->base[0] == v->base[1])
      return _mm256_i32gather_epi32(v->base[0], idx, 4);
   const __m128i lo = _mm_i32gather_epi32(v->base[0], _mm256_castsi256_si128(idx), 4);
   const __m128i hi = _mm_i32gather_epi32(v->base[1], _mm256_extracti128_si256(idx, 1), 4);
   return _mm256_setr_m128i(lo, hi);
}

/* the texel pairs at idx and idx + 1 of each lane's level, one 64-bit
 * load per lane: the first texels in *a, the second ones in *b */
static inline __attribute__((always_inline)) void fetch_pairs(const struct lv8 *v, __m256i idx, __m256i *a, __m256i *b)
{
   const long long *ba = (const long long *)(const void *)v->base[0];
   const long long *bb = (const long long *)(const void *)v->base[1];
   /* lanes 0..3: a0 b0 a1 b1 | a2 b2 a3 b3; lanes 4..7 likewise */
   const __m256 lo = _mm256_castsi256_ps(_mm256_i32gather_epi64(ba, _mm256_castsi256_si128(idx), 4));
   const __m256 hi = _mm256_castsi256_ps(_mm256_i32gather_epi64(bb, _mm256_extracti128_si256(idx, 1), 4));
   /* a0 a1 a4 a5 | a2 a3 a6 a7, then the 64-bit pairs in order */
   const __m256 ea = _mm256_shuffle_ps(lo, hi, _MM_SHUFFLE(2, 0, 2, 0));
   const __m256 eb = _mm256_shuffle_ps(lo, hi, _MM_SHUFFLE(3, 1, 3, 1));
   *a = _mm256_permute4x64_epi64(_mm256_castps_si256(ea), 0xD8);
   *b = _mm256_permute4x64_epi64(_mm256_castps_si256(eb), 0xD8);
}

/* lp_build_fract_safe: s - floor(s), then min(f, 0.99999994) with minps
 * (f < k ? f : k, so NaN gives k, as the scalar compare) */
static inline __attribute__((always_inline)) __m256 fract_safe(__m256 s)
{
   const __m256 f = _mm256_sub_ps(s, _mm256_floor_ps(s));
   return _mm256_min_ps(f, _mm256_set1_ps(0.99999994f));
}

/* r_tex.c wrap_nearest */
static inline __m256i nearest_axis(__m256 s, const struct axis *a, bool pot, enum r_tex_wrap wrap)
{
   if (wrap == R_WRAP_REPEAT) {
      if (pot)
         return _mm256_and_si256(_mm256_cvttps_epi32(_mm256_floor_ps(_mm256_mul_ps(s, a->fn))),
                                 a->nm1);
      return _mm256_cvttps_epi32(_mm256_mul_ps(fract_safe(s), a->fn));
   }
   /* CLAMP_TO_EDGE */
   const __m256i i = _mm256_cvttps_epi32(_mm256_floor_ps(_mm256_mul_ps(s, a->fn)));
   return _mm256_max_epi32(_mm256_min_epi32(i, a->nm1), _mm256_setzero_si256());
}

/* r_tex.c wrap_linear */
static inline __attribute__((always_inline)) void linear_axis(__m256 s, const struct axis *a, bool pot, enum r_tex_wrap wrap,
                               __m256i *i0, __m256i *i1, __m256i *w)
{
   const __m256i zero = _mm256_setzero_si256(), one = _mm256_set1_epi32(1);
   const __m256i m255 = _mm256_set1_epi32(255), k128 = _mm256_set1_epi32(128);
   if (wrap == R_WRAP_REPEAT && !pot) {
      const __m256 v = _mm256_mul_ps(_mm256_mul_ps(fract_safe(s), a->fn), _mm256_set1_ps(256.0f));
      __m256i i = _mm256_sub_epi32(_mm256_cvtps_epi32(v), k128);
      *w = _mm256_and_si256(i, m255);
      i = _mm256_srai_epi32(i, 8);
      const __m256i out = _mm256_or_si256(_mm256_cmpgt_epi32(zero, i), _mm256_cmpgt_epi32(i, a->nm1));
      i = _mm256_blendv_epi8(i, a->nm1, out);
      *i0 = i;
      *i1 = _mm256_andnot_si256(_mm256_cmpeq_epi32(i, a->nm1), _mm256_add_epi32(i, one));
      return;
   }
   const __m256i u = _mm256_sub_epi32(_mm256_cvtps_epi32(_mm256_mul_ps(s, a->fn256)), k128);
   *w = _mm256_and_si256(u, m255);
   const __m256i i = _mm256_srai_epi32(u, 8);
   if (wrap == R_WRAP_REPEAT) {
      *i0 = _mm256_and_si256(i, a->nm1);
      *i1 = _mm256_and_si256(_mm256_add_epi32(i, one), a->nm1);
   } else {
      *i0 = _mm256_max_epi32(_mm256_min_epi32(i, a->nm1), zero);
      /* i + 1 when 0 <= i < n - 1, else i0 */
      const __m256i inner = _mm256_andnot_si256(_mm256_cmpgt_epi32(zero, i),
                                                _mm256_cmpgt_epi32(a->nm1, i));
      *i1 = _mm256_blendv_epi8(*i0, _mm256_add_epi32(i, one), inner);
   }
}

/* lerp8 on 16-bit channels, w7 the weight times 128 (weights16):
 * pmulhrsw(b - a, w * 128) is ((b - a) * w * 128 + 0x4000) >> 15 (the
 * 32-bit product, arithmetic shift), which is ((b - a) * w + 128) >> 8,
 * lerp8's term; a plus that lies between a and b (w <= 255), in 0..255,
 * so lerp8's & 0xff changes nothing.  (llvmpipe's own SSSE3 / AVX2 lerp.) */
static inline __attribute__((always_inline)) __m256i lerp16(__m256i w7, __m256i a, __m256i b)
{
   return _mm256_add_epi16(a, _mm256_mulhrs_epi16(_mm256_sub_epi16(b, a), w7));
}

/* the lanes' 32-bit weights (0..255) times 128 as 16-bit channel weights
 * of the low (unpacklo: lanes 0, 1 of each half) and high (lanes 2, 3)
 * texels, for lerp16 */
static inline __attribute__((always_inline)) void weights16(__m256i w32, __m256i *lo, __m256i *hi)
{
   const __m256i w7 = _mm256_slli_epi32(w32, 7);
   const __m256i w16 = _mm256_blend_epi16(w7, _mm256_slli_epi32(w7, 16), 0xaa);
   *lo = _mm256_unpacklo_epi32(w16, w16);
   *hi = _mm256_unpackhi_epi32(w16, w16);
}

/* lerp8 of packed RGBA8 texels, one weight per lane */
static inline __attribute__((always_inline)) __m256i lerp_packed(__m256i w32, __m256i a, __m256i b)
{
   const __m256i z = _mm256_setzero_si256();
   __m256i wl, wh;
   weights16(w32, &wl, &wh);
   const __m256i rl = lerp16(wl, _mm256_unpacklo_epi8(a, z), _mm256_unpacklo_epi8(b, z));
   const __m256i rh = lerp16(wh, _mm256_unpackhi_epi8(a, z), _mm256_unpackhi_epi8(b, z));
   return _mm256_packus_epi16(rl, rh);
}

/* sample_level's NEAREST */
static inline __m256i sample_nearest(const struct r_texture *t, const struct lv8 *v, __m256 s,
                                     __m256 tc)
{
   const __m256i x = nearest_axis(s, &v->s, t->pot_s, t->wrap_s);
   if (t->dims == 1)
      return fetch(v, x);
   const __m256i y = nearest_axis(tc, &v->t, t->pot_t, t->wrap_t);
   return fetch(v, _mm256_add_epi32(_mm256_mullo_epi32(y, v->width), x));
}

/* sample_level's LINEAR: along s on rows t0 and t1, then along t */
static inline __attribute__((always_inline)) void
sample_linear_k16(int dims, bool pot_s, enum r_tex_wrap wrap_s, bool pot_t, enum r_tex_wrap wrap_t,
                  const struct lv8 *v, __m256 s, __m256 tc, __m256i *lo16, __m256i *hi16)
{
   __m256i x0, x1, ws;
   linear_axis(s, &v->s, pot_s, wrap_s, &x0, &x1, &ws);
   /* every lane's second texel next to its first one in the row (no
    * wrap, no clamp at the edge): both in one 64-bit fetch */
   const bool pairs = _mm256_movemask_ps(_mm256_castsi256_ps(
                         _mm256_cmpeq_epi32(x1, _mm256_add_epi32(x0, _mm256_set1_epi32(1))))) == 0xff;
   __m256i a, b, d, e;
   if (dims == 1) {
      if (pairs)
         fetch_pairs(v, x0, &a, &b);
      else {
         a = fetch(v, x0);
         b = fetch(v, x1);
      }
      const __m256i z = _mm256_setzero_si256();
      __m256i wl, wh;
      weights16(ws, &wl, &wh);
      *lo16 = lerp16(wl, _mm256_unpacklo_epi8(a, z), _mm256_unpacklo_epi8(b, z));
      *hi16 = lerp16(wh, _mm256_unpackhi_epi8(a, z), _mm256_unpackhi_epi8(b, z));
      return;
   }
   __m256i y0, y1, wt;
   linear_axis(tc, &v->t, pot_t, wrap_t, &y0, &y1, &wt);
   const __m256i r0 = _mm256_mullo_epi32(y0, v->width), r1 = _mm256_mullo_epi32(y1, v->width);
   if (pairs) {
      fetch_pairs(v, _mm256_add_epi32(r0, x0), &a, &b);
      fetch_pairs(v, _mm256_add_epi32(r1, x0), &d, &e);
   } else {
      a = fetch(v, _mm256_add_epi32(r0, x0));
      b = fetch(v, _mm256_add_epi32(r0, x1));
      d = fetch(v, _mm256_add_epi32(r1, x0));
      e = fetch(v, _mm256_add_epi32(r1, x1));
   }
   const __m256i z = _mm256_setzero_si256();
   __m256i wsl, wsh, wtl, wth;
   weights16(ws, &wsl, &wsh);
   weights16(wt, &wtl, &wth);
   *lo16 = lerp16(wtl, lerp16(wsl, _mm256_unpacklo_epi8(a, z), _mm256_unpacklo_epi8(b, z)),
                  lerp16(wsl, _mm256_unpacklo_epi8(d, z), _mm256_unpacklo_epi8(e, z)));
   *hi16 = lerp16(wth, lerp16(wsh, _mm256_unpackhi_epi8(a, z), _mm256_unpackhi_epi8(b, z)),
                  lerp16(wsh, _mm256_unpackhi_epi8(d, z), _mm256_unpackhi_epi8(e, z)));
}

/* the same, packed: RGBA8 per lane (the 16-bit channels are below 256:
 * packus keeps them, and unpacking gives them back) */
static inline __attribute__((always_inline)) __m256i
sample_linear_k(int dims, bool pot_s, enum r_tex_wrap wrap_s, bool pot_t, enum r_tex_wrap wrap_t,
                const struct lv8 *v, __m256 s, __m256 tc)
{
   __m256i lo, hi;
   sample_linear_k16(dims, pot_s, wrap_s, pot_t, wrap_t, v, s, tc, &lo, &hi);
   return _mm256_packus_epi16(lo, hi);
}

/* sample_linear_k on the texture's own properties (the constant ones of
 * a specialised kernel give its code alone) */
static inline __m256i sample_linear(const struct r_texture *t, const struct lv8 *v, __m256 s,
                                    __m256 tc)
{
   return sample_linear_k(t->dims, t->pot_s, t->wrap_s, t->pot_t, t->wrap_t, v, s, tc);
}

/* one level per quad with image filter f[q] for quad q */
static inline __m256i sample_levels(const struct r_texture *t, const enum r_tex_filter f[2],
                                    const struct lv8 *v, __m256 s, __m256 tc)
{
   if (f[0] == f[1]) {
      return f[0] == R_TEX_LINEAR ? sample_linear(t, v, s, tc) : sample_nearest(t, v, s, tc);
   }
   /* a quad magnified next to a minified one: both filters, each quad
    * keeps its own */
   const __m256i n = sample_nearest(t, v, s, tc), l = sample_linear(t, v, s, tc);
   return f[0] == R_TEX_NEAREST ? _mm256_blend_epi32(n, l, 0xf0) : _mm256_blend_epi32(l, n, 0xf0);
}

/* r_tex_lod_aos_inline's LINEAR_MIPMAP_LINEAR levels from rho squared
 * (r2) in every lane: lp_build_fast_log2 halved (*lodf), its floor as the
 * first level, clamped to first..last with the weight 0 when clamped,
 * else the fraction times 256 truncated (*weight) */
static inline __attribute__((always_inline)) void
mip_linear_levels(__m256 r2, __m256i vfirst, __m256i vlast, __m256 *lodf, __m256i *level0,
                  __m256i *weight)
{
   const __m256i bits = _mm256_castps_si256(r2);
   const __m256i e = _mm256_and_si256(_mm256_srli_epi32(bits, 23), _mm256_set1_epi32(255));
   const __m256 mant = _mm256_castsi256_ps(_mm256_or_si256(
      _mm256_and_si256(bits, _mm256_set1_epi32(0x7fffff)), _mm256_set1_epi32(0x3f800000)));
   const __m256 l2 =
      _mm256_add_ps(_mm256_cvtepi32_ps(_mm256_sub_epi32(e, _mm256_set1_epi32(128))), mant);
   const __m256 lod = _mm256_mul_ps(l2, _mm256_set1_ps(0.5f));
   const __m256 fl = _mm256_floor_ps(lod);
   __m256 fpart = _mm256_sub_ps(lod, fl);
   __m256i l0 = _mm256_add_epi32(vfirst, _mm256_cvttps_epi32(fl));
   /* l0 < first or l0 >= last: clamped, fpart 0 */
   const __m256i below = _mm256_cmpgt_epi32(vfirst, l0);
   const __m256i above = _mm256_cmpgt_epi32(l0, _mm256_sub_epi32(vlast, _mm256_set1_epi32(1)));
   l0 = _mm256_blendv_epi8(l0, vfirst, below);
   l0 = _mm256_blendv_epi8(l0, vlast, above);
   fpart = _mm256_andnot_ps(_mm256_castsi256_ps(_mm256_or_si256(below, above)), fpart);
   *lodf = lod;
   *level0 = l0;
   *weight = _mm256_cvttps_epi32(_mm256_mul_ps(fpart, _mm256_set1_ps(256.0f)));
}

/* r_tex_lod_aos_inline (r_tex_lod.h) of quads A and B at once, from their
 * lanes in quad-major order (TL, TR, BL = lanes 0, 1, 2 of each 128-bit
 * half): the same float operations on every lane of a half (the half's
 * TL, TR, BL broadcast), the float compares as minps/maxps/cmpps with the
 * scalar code's operand order, the exponent and mantissa as integer bit
 * operations, floorf as roundps, the truncations as cvttps2dq (INT32_MIN
 * for NaN, as r_lod_itrunc). */
static inline __attribute__((always_inline)) void
tex8_lod_quads_k(const struct r_texture *t, int dims, enum r_tex_mip mip, bool no_lod, __m256 s,
                 __m256 tc, struct r_tex_lod lod[2])
{
   const int first = t->first_level, last = t->last_level;
   if (no_lod) {
      for (int q = 0; q < 2; q++) {
         lod[q].minify = true;
         lod[q].level0 = lod[q].level1 = first;
         lod[q].weight = 0;
      }
      return;
   }
   const struct r_tex_level *l = &t->level[first];
   const __m256 fw = _mm256_set1_ps((float)l->width);
   const __m256 s_tl = _mm256_permute_ps(s, 0x00), s_tr = _mm256_permute_ps(s, 0x55);
   const __m256 s_bl = _mm256_permute_ps(s, 0xaa);
   __m256 rho;
   if (dims == 1) {
      const __m256 abs = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
      const __m256 dx = _mm256_and_ps(_mm256_sub_ps(s_tr, s_tl), abs);
      const __m256 dy = _mm256_and_ps(_mm256_sub_ps(s_tl, s_bl), abs);
      /* dx > dy ? dx : dy */
      rho = _mm256_mul_ps(_mm256_max_ps(dx, dy), fw);
   } else {
      const __m256 fh = _mm256_set1_ps((float)l->height);
      const __m256 t_tl = _mm256_permute_ps(tc, 0x00), t_tr = _mm256_permute_ps(tc, 0x55);
      const __m256 t_bl = _mm256_permute_ps(tc, 0xaa);
      __m256 dsdx = _mm256_mul_ps(_mm256_sub_ps(s_tr, s_tl), fw);
      __m256 dsdy = _mm256_mul_ps(_mm256_sub_ps(s_bl, s_tl), fw);
      __m256 dtdx = _mm256_mul_ps(_mm256_sub_ps(t_tr, t_tl), fh);
      __m256 dtdy = _mm256_mul_ps(_mm256_sub_ps(t_bl, t_tl), fh);
      dsdx = _mm256_mul_ps(dsdx, dsdx);
      dsdy = _mm256_mul_ps(dsdy, dsdy);
      dtdx = _mm256_mul_ps(dtdx, dtdx);
      dtdy = _mm256_mul_ps(dtdy, dtdy);
      /* rx > ry ? rx : ry */
      rho = _mm256_max_ps(_mm256_add_ps(dsdx, dtdx), _mm256_add_ps(dsdy, dtdy));
   }
   const __m256i vfirst = _mm256_set1_epi32(first), vlast = _mm256_set1_epi32(last);
   const __m256i m255 = _mm256_set1_epi32(255);
   __m256i minify, level0, level1 = vfirst, weight = _mm256_setzero_si256();
   if (mip != R_MIP_LINEAR) {
      __m256i ipart;
      if (dims > 1) {
         const __m256i e = _mm256_and_si256(_mm256_srli_epi32(_mm256_castps_si256(rho), 23), m255);
         ipart = _mm256_srai_epi32(_mm256_sub_epi32(e, _mm256_set1_epi32(126)), 1);
      } else {
         const __m256 r2 = _mm256_mul_ps(rho, _mm256_set1_ps((float)M_SQRT2));
         const __m256i e = _mm256_and_si256(_mm256_srli_epi32(_mm256_castps_si256(r2), 23), m255);
         ipart = _mm256_sub_epi32(e, _mm256_set1_epi32(127));
      }
      /* !(rho <= 1) */
      minify = _mm256_castps_si256(_mm256_cmp_ps(rho, _mm256_set1_ps(1.0f), _CMP_NLE_UQ));
      level0 = _mm256_min_epi32(_mm256_max_epi32(_mm256_add_epi32(vfirst, ipart), vfirst), vlast);
      level1 = level0;
   } else {
      const __m256 r2 = dims > 1 ? rho : _mm256_mul_ps(rho, rho);
      __m256 lodf;
      mip_linear_levels(r2, vfirst, vlast, &lodf, &level0, &weight);
      /* !(lod <= 0) */
      minify = _mm256_castps_si256(_mm256_cmp_ps(lodf, _mm256_setzero_ps(), _CMP_NLE_UQ));
      level1 = _mm256_min_epi32(_mm256_add_epi32(level0, _mm256_set1_epi32(1)), vlast);
   }
   const __m128i mlo = _mm256_castsi256_si128(minify), mhi = _mm256_extracti128_si256(minify, 1);
   const __m128i l0lo = _mm256_castsi256_si128(level0), l0hi = _mm256_extracti128_si256(level0, 1);
   const __m128i l1lo = _mm256_castsi256_si128(level1), l1hi = _mm256_extracti128_si256(level1, 1);
   const __m128i wlo = _mm256_castsi256_si128(weight), whi = _mm256_extracti128_si256(weight, 1);
   lod[0].minify = _mm_cvtsi128_si32(mlo) != 0;
   lod[1].minify = _mm_cvtsi128_si32(mhi) != 0;
   lod[0].level0 = _mm_cvtsi128_si32(l0lo);
   lod[1].level0 = _mm_cvtsi128_si32(l0hi);
   lod[0].level1 = _mm_cvtsi128_si32(l1lo);
   lod[1].level1 = _mm_cvtsi128_si32(l1hi);
   lod[0].weight = _mm_cvtsi128_si32(wlo);
   lod[1].weight = _mm_cvtsi128_si32(whi);
}

/* tex8_lod_quads_k on the texture's own properties */
static inline __attribute__((always_inline)) void
tex8_lod_quads(const struct r_texture *t, __m256 s, __m256 tc, struct r_tex_lod lod[2])
{
   tex8_lod_quads_k(t, t->dims, t->mip, t->mip == R_MIP_NONE && t->min_img == t->mag_img, s, tc,
                    lod);
}

/* r_tex_filter_aos on the lanes, in quad-major order (s, tc: the
 * projected coordinates; lod: the level of detail of quad A and of quad
 * B; tab: the texture's levels by tex8_level_init, or NULL): the texels
 * as packed RGBA8, in the same order. */
static inline __attribute__((always_inline)) __m256i
tex8_filter_quads(const struct r_texture *t, const struct tex8_level *tab,
                  const struct r_tex_lod lod[2], __m256 s, __m256 tc)
{
   /* r_tex_filter_aos's choice per quad: the image filter and level of
    * the first lookup, and the second level's when it is blended in (a
    * weight of 0 leaves the first lookup as it is: lerp8(0, a, b) = a) */
   enum r_tex_filter f0[2];
   int l0[2], l1[2], w1[2];
   bool two = false;
   for (int q = 0; q < 2; q++) {
      const struct r_tex_lod *l = &lod[q];
      l1[q] = l0[q] = l->level0;
      w1[q] = 0;
      if (!l->minify && t->mag_img != t->min_img) {
         f0[q] = t->mag_img;
      } else if (t->mip == R_MIP_NONE) {
         f0[q] = l->minify ? t->min_img : t->mag_img;
         l1[q] = l0[q] = t->first_level;
      } else {
         f0[q] = t->min_img;
         if (t->mip == R_MIP_LINEAR && l->weight > 0) {
            l1[q] = l->level1;
            w1[q] = l->weight;
            two = true;
         }
      }
   }
   struct lv8 v;
   if (tab)
      lv8_from(&tab[l0[0]], &tab[l0[1]], &v);
   else
      lv8_init(t, l0[0], l0[1], &v);
   __m256i tex = sample_levels(t, f0, &v, s, tc);
   if (two) {
      const enum r_tex_filter fm[2] = { t->min_img, t->min_img };
      if (tab)
         lv8_from(&tab[l1[0]], &tab[l1[1]], &v);
      else
         lv8_init(t, l1[0], l1[1], &v);
      const __m256i tex1 = sample_levels(t, fm, &v, s, tc);
      tex = lerp_packed(halves_i(w1[0], w1[1]), tex, tex1);
   }
   return tex;
}

/* Whether tex8_filter_trilinear_lod samples t: 2D, power-of-two sizes,
 * REPEAT on both axes, LINEAR_MIPMAP_LINEAR and LINEAR (with
 * r_tex8_fast). */
static inline bool tex8_is_trilinear_repeat(const struct r_texture *t)
{
   return t->dims == 2 && t->pot_s && t->pot_t && t->wrap_s == R_WRAP_REPEAT &&
          t->wrap_t == R_WRAP_REPEAT && t->min_img == R_TEX_LINEAR &&
          t->mag_img == R_TEX_LINEAR && t->mip == R_MIP_LINEAR;
}

/* The level of detail of tex8_filter_trilinear_lod: the first level of
 * quad A and quad B, and each lane's mip weight (its quad's, 0..255; 0
 * where the quad samples one level). */
struct tex8_trilod {
   int level0[2];
   __m256i weight;
};

/* tex8_lod_quads_k's LINEAR_MIPMAP_LINEAR branch of a 2D texture
 * (levels first..last, base level size fw x fh as floats) for the quads
 * of two halves at once (s0, t0 and s1, t1 in quad-major order; the same
 * half twice for one): the TL, TR, BL lanes of the four quads shuffled
 * into one vector, [TR - TL, BL - TL] of a quad of half 0 and one of
 * half 1 in each 128-bit half, so that rho, the log and the level of the
 * four quads are one vector's operations (the same float operations per
 * quad as tex8_lod_quads_k: (d * W)^2 + (d * H)^2 per direction, maxps
 * (rx, ry)); the quads' values in lanes 0, 4 (half 0's A, B) and 2, 6
 * (half 1's). */
static inline __attribute__((always_inline)) void
tex8_trilinear_lod2(int first, int last, __m256 fw, __m256 fh, __m256 s0, __m256 t0, __m256 s1,
                    __m256 t1, struct tex8_trilod *h0, struct tex8_trilod *h1)
{
   /* [TL, TL, TL', TL'] and [TR, BL, TR', BL'] per 128-bit half */
   const __m256 s_tl = _mm256_shuffle_ps(s0, s1, _MM_SHUFFLE(0, 0, 0, 0));
   const __m256 s_o = _mm256_shuffle_ps(s0, s1, _MM_SHUFFLE(2, 1, 2, 1));
   const __m256 t_tl = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(0, 0, 0, 0));
   const __m256 t_o = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(2, 1, 2, 1));
   __m256 ds = _mm256_mul_ps(_mm256_sub_ps(s_o, s_tl), fw);   /* dsdx, dsdy */
   __m256 dt = _mm256_mul_ps(_mm256_sub_ps(t_o, t_tl), fh);   /* dtdx, dtdy */
   ds = _mm256_mul_ps(ds, ds);
   dt = _mm256_mul_ps(dt, dt);
   const __m256 r = _mm256_add_ps(ds, dt);   /* rx, ry */
   /* rx > ry ? rx : ry, in lanes 0, 2, 4, 6 */
   const __m256 rho = _mm256_max_ps(r, _mm256_permute_ps(r, _MM_SHUFFLE(2, 3, 0, 1)));
   __m256 lodf;
   __m256i l0, w;
   mip_linear_levels(rho, _mm256_set1_epi32(first), _mm256_set1_epi32(last), &lodf, &l0, &w);
   h0->weight = _mm256_shuffle_epi32(w, 0x00);
   h1->weight = _mm256_shuffle_epi32(w, 0xaa);
   const __m128i llo = _mm256_castsi256_si128(l0), lhi = _mm256_extracti128_si256(l0, 1);
   h0->level0[0] = _mm_cvtsi128_si32(llo);
   h0->level0[1] = _mm_cvtsi128_si32(lhi);
   h1->level0[0] = _mm_extract_epi32(llo, 2);
   h1->level0[1] = _mm_extract_epi32(lhi, 2);
}

/* tex8_filter_quads for such a texture, with its table and the level of
 * detail of tex8_trilinear_lod2: the branches of r_tex_filter_aos it
 * takes (min_img == mag_img, a mip filter: the minified branch, LINEAR on
 * level0, blended with level1 by a positive weight), with every property
 * a constant; the second level (min(level0 + 1, last)) is sampled when a
 * quad has a positive weight, and blended in by every lane's weight (0
 * for a quad without one: lerp8(0, a, b) = a). */
static inline __attribute__((always_inline)) __m256i
tex8_filter_trilinear_lod(const struct tex8_level *tab, int last, const struct tex8_trilod *l,
                          __m256 s, __m256 tc)
{
   const int a = l->level0[0], b = l->level0[1];
   struct lv8 v;
   lv8_from(&tab[a], &tab[b], &v);
   __m256i lo, hi;
   sample_linear_k16(2, true, R_WRAP_REPEAT, true, R_WRAP_REPEAT, &v, s, tc, &lo, &hi);
   if (!_mm256_testz_si256(l->weight, l->weight)) {
      lv8_from(&tab[a < last ? a + 1 : last], &tab[b < last ? b + 1 : last], &v);
      __m256i lo1, hi1;
      sample_linear_k16(2, true, R_WRAP_REPEAT, true, R_WRAP_REPEAT, &v, s, tc, &lo1, &hi1);
      __m256i wl, wh;
      weights16(l->weight, &wl, &wh);
      lo = lerp16(wl, lo, lo1);
      hi = lerp16(wh, hi, hi1);
   }
   return _mm256_packus_epi16(lo, hi);
}

/* Whether tex8_filter_bilinear samples t: 2D, LINEAR for both image
 * filters, no mip filter, and REPEAT on both axes with power-of-two sizes
 * or CLAMP_TO_EDGE on both (with r_tex8_fast). */
static inline bool tex8_is_bilinear(const struct r_texture *t, enum r_tex_wrap wrap)
{
   return t->dims == 2 && t->wrap_s == wrap && t->wrap_t == wrap &&
          (wrap == R_WRAP_CLAMP_TO_EDGE || (wrap == R_WRAP_REPEAT && t->pot_s && t->pot_t)) &&
          t->min_img == R_TEX_LINEAR && t->mag_img == R_TEX_LINEAR && t->mip == R_MIP_NONE;
}

/* tex8_filter_quads for such a texture, with its table: tex8_lod_quads
 * gives no level of detail (no mip filter, min_img == mag_img), and
 * r_tex_filter_aos's branch of R_MIP_NONE is LINEAR on first_level for
 * both quads, with every property a constant (linear_axis reads pot only
 * with REPEAT). */
static inline __attribute__((always_inline)) __m256i
tex8_filter_bilinear(const struct tex8_level *tab, int first_level, enum r_tex_wrap wrap, __m256 s,
                     __m256 tc)
{
   struct lv8 v;
   lv8_from(&tab[first_level], &tab[first_level], &v);
   return sample_linear_k(2, true, wrap, true, wrap, &v, s, tc);
}

#endif
