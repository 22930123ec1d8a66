/*
 * r_block_avx2.h: what every AVX2 block kernel shares (r_kernel.h) -- the
 * 8-lane forms of the reference's operations (plane evaluation, unorm
 * conversions, depth compare, blending), the row loads and stores of a
 * 4x2 half, and the scalar finish of a block past the buffer's right edge.
 * Include it only from files compiled with -mavx2 -mfma.
 */
#ifndef FGL_R_BLOCK_AVX2_H
#define FGL_R_BLOCK_AVX2_H

#include "r_kernel.h"

#include <immintrin.h>
#include <string.h>

enum zfmt { ZF_NONE, ZF_16, ZF_24 };
enum blend { BL_NONE, BL_ALPHA };

#define ALWAYS_INLINE inline __attribute__((always_inline))

/* r_eval_plane in 8 lanes */
static ALWAYS_INLINE __m256 eval8(const struct r_attr_plane *p, __m256 fx, __m256 fy)
{
   return _mm256_fmadd_ps(_mm256_set1_ps(p->dady), fy,
                          _mm256_fmadd_ps(_mm256_set1_ps(p->dadx), fx, _mm256_set1_ps(p->a0)));
}

/* r_float_to_unorm8 in 8 lanes (maxps returns its second operand for NaN:
 * NaN -> 0, as !(c > 0)) */
static ALWAYS_INLINE __m256i unorm8(__m256 c)
{
   c = _mm256_max_ps(c, _mm256_setzero_ps());
   c = _mm256_min_ps(c, _mm256_set1_ps(1.0f));
   return _mm256_cvtps_epi32(_mm256_mul_ps(c, _mm256_set1_ps(255.0f)));
}

/* r_clamp01(z) * scale, RNE */
static ALWAYS_INLINE __m256i depth_unorm(__m256 z, float scale)
{
   const __m256 m = _mm256_min_ps(z, _mm256_set1_ps(1.0f));   /* NaN -> 1 */
   const __m256 c = _mm256_max_ps(m, _mm256_setzero_ps());
   return _mm256_cvtps_epi32(_mm256_mul_ps(c, _mm256_set1_ps(scale)));
}

/* lanes whose bit is set in m8 */
static ALWAYS_INLINE __m256i lane_mask(unsigned m8)
{
   const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
   return _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32((int)m8), bit), bit);
}

/* Two rows of four 32-bit pixels at p and p + stride, each read only when
 * its lanes in m8 are not all clear. */
static ALWAYS_INLINE __m256i load_rows32(const uint32_t *p, size_t stride, unsigned m8)
{
   const __m128i r0 = (m8 & 0x0f) ? _mm_loadu_si128((const __m128i *)p) : _mm_setzero_si128();
   const __m128i r1 = (m8 & 0xf0) ? _mm_loadu_si128((const __m128i *)(p + stride))
                                  : _mm_setzero_si128();
   return _mm256_set_m128i(r1, r0);
}

static ALWAYS_INLINE void store_rows32(uint32_t *p, size_t stride, unsigned m8, __m256i v)
{
   if (m8 & 0x0f)
      _mm_storeu_si128((__m128i *)p, _mm256_castsi256_si128(v));
   if (m8 & 0xf0)
      _mm_storeu_si128((__m128i *)(p + stride), _mm256_extracti128_si256(v, 1));
}

/* The same for 16-bit depth: the values widened to 32-bit lanes. */
static ALWAYS_INLINE __m256i load_rows16(const uint16_t *p, size_t stride, unsigned m8)
{
   const __m128i r0 = (m8 & 0x0f) ? _mm_loadl_epi64((const __m128i *)p) : _mm_setzero_si128();
   const __m128i r1 = (m8 & 0xf0) ? _mm_loadl_epi64((const __m128i *)(p + stride))
                                  : _mm_setzero_si128();
   return _mm256_cvtepu16_epi32(_mm_unpacklo_epi64(r0, r1));
}

static ALWAYS_INLINE void store_rows16(uint16_t *p, size_t stride, unsigned m8, __m256i v)
{
   /* values < 2^16: packus keeps them; each 128-bit half holds its row */
   const __m256i packed = _mm256_packus_epi32(v, v);
   if (m8 & 0x0f)
      _mm_storel_epi64((__m128i *)p, _mm256_castsi256_si128(packed));
   if (m8 & 0xf0)
      _mm_storel_epi64((__m128i *)(p + stride), _mm256_extracti128_si256(packed, 1));
}

/* The depth function as three lane masks: GL's functions are NEVER + a
 * set of {less, equal, greater} (bit 0 less, bit 1 equal, bit 2 greater),
 * the pass mask is the union of the chosen relations. */
struct depth_fn {
   __m256i lt, eq, gt;
};

static ALWAYS_INLINE struct depth_fn depth_fn(enum r_func f)
{
   return (struct depth_fn){ _mm256_set1_epi32(f & 1 ? -1 : 0), _mm256_set1_epi32(f & 2 ? -1 : 0),
                             _mm256_set1_epi32(f & 4 ? -1 : 0) };
}

/* compare(func, zv, zb) of r_frag.c; both operands below 2^24 */
static ALWAYS_INLINE __m256i depth_pass(const struct depth_fn *fn, __m256i zv, __m256i zb)
{
   const __m256i lt = _mm256_cmpgt_epi32(zb, zv), gt = _mm256_cmpgt_epi32(zv, zb);
   const __m256i eq = _mm256_cmpeq_epi32(zv, zb);
   return _mm256_or_si256(_mm256_or_si256(_mm256_and_si256(lt, fn->lt), _mm256_and_si256(eq, fn->eq)),
                          _mm256_and_si256(gt, fn->gt));
}

/* r_frag.c mul_u8 on 16-bit lanes: t = a*b, (t + (t >> 8) + 128) >> 8
 * (t <= 65025, the sum below 2^16) */
static ALWAYS_INLINE __m256i mul_u8x16(__m256i a, __m256i b)
{
   const __m256i t = _mm256_mullo_epi16(a, b);
   return _mm256_srli_epi16(
      _mm256_add_epi16(_mm256_add_epi16(t, _mm256_srli_epi16(t, 8)), _mm256_set1_epi16(0x80)), 8);
}

/* SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ADD on 8 RGBA8 pixels (r_frag.c
 * blend_channel): s*a + d*(255 - a), each a normalized multiply, summed
 * with saturation. */
static ALWAYS_INLINE __m256i blend_alpha(__m256i src, __m256i dst)
{
   const __m256i zero = _mm256_setzero_si256();
   const __m256i amask = _mm256_setr_epi8(6, 7, 6, 7, 6, 7, 6, 7, 14, 15, 14, 15, 14, 15, 14, 15,
                                          6, 7, 6, 7, 6, 7, 6, 7, 14, 15, 14, 15, 14, 15, 14, 15);
   const __m256i c255 = _mm256_set1_epi16(255);
   __m256i out[2];
   for (int h = 0; h < 2; h++) {
      const __m256i s = h ? _mm256_unpackhi_epi8(src, zero) : _mm256_unpacklo_epi8(src, zero);
      const __m256i d = h ? _mm256_unpackhi_epi8(dst, zero) : _mm256_unpacklo_epi8(dst, zero);
      const __m256i a = _mm256_shuffle_epi8(s, amask);
      out[h] = _mm256_adds_epu16(mul_u8x16(s, a), mul_u8x16(d, _mm256_sub_epi16(c255, a)));
   }
   return _mm256_packus_epi16(out[0], out[1]);   /* sums up to 510: saturated */
}

static inline unsigned r_block_mul_u8(unsigned a, unsigned b)
{
   const unsigned t = a * b;
   return (t + (t >> 8) + 0x80u) >> 8;
}

static inline bool compare_u32(enum r_func f, uint32_t a, uint32_t b)
{
   return ((f & 1) && a < b) || ((f & 2) && a == b) || ((f & 4) && a > b);
}

/* The lanes of a half one at a time (a block reaching past the buffer's
 * right edge): the same integer operations as the vector path. */
static void finish_lanes(const struct r_state *rs, int x, int y, unsigned m8, const uint32_t zv[8],
                         const uint32_t src[8], enum zfmt zf, bool zwrite, enum blend bl)
{
   for (unsigned m = m8; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      const size_t idx = (size_t)(y + (i >> 2)) * (size_t)rs->width + (size_t)(x + (i & 3));
      if (zf == ZF_24) {
         uint32_t *zb = (uint32_t *)rs->zs + idx;
         if (!compare_u32(rs->depth_func, zv[i], *zb & 0xffffffu))
            continue;
         if (zwrite)
            *zb = (*zb & 0xff000000u) | zv[i];
      } else if (zf == ZF_16) {
         uint16_t *zb = (uint16_t *)rs->zs + idx;
         if (!compare_u32(rs->depth_func, zv[i], *zb))
            continue;
         if (zwrite)
            *zb = (uint16_t)zv[i];
      }
      uint8_t *dst = rs->color + 4 * idx;
      uint8_t s[4];
      memcpy(s, &src[i], 4);
      if (bl == BL_ALPHA) {
         const unsigned a = s[3];
         uint8_t d[4] = { dst[0], dst[1], dst[2], rs->dst_alpha_one ? 255 : dst[3] };
         for (int c = 0; c < 4; c++) {
            const unsigned v = r_block_mul_u8(s[c], a) + r_block_mul_u8(d[c], 255u - a);
            dst[c] = (uint8_t)(v > 255u ? 255u : v);
         }
      } else {
         memcpy(dst, s, 4);
      }
   }
}


/* four channel vectors (floats) to packed RGBA8 lanes, as r_float_to_unorm8
 * per channel */
static ALWAYS_INLINE __m256i pack_rgba8(__m256 r, __m256 g, __m256 b, __m256 a)
{
   return _mm256_or_si256(_mm256_or_si256(unorm8(r), _mm256_slli_epi32(unorm8(g), 8)),
                          _mm256_or_si256(_mm256_slli_epi32(unorm8(b), 16),
                                          _mm256_slli_epi32(unorm8(a), 24)));
}

#endif
