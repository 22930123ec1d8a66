/*
 * t_vertex_avx2.c: the position part of t_transform (t_vertex.c
 * transform_positions) and t_clip_masks_any eight vertices at a time,
 * AVX2 + FMA, in the archive of such code (meson.build); called only on
 * a CPU that runs it and not under FIXGL_KERNELS=reference.
 *
 * Each lane does the scalar path's operations for its vertex, in its
 * order and with its operand order (so a NaN propagates as it does
 * there):
 *   clip = ((x*C0 + y*C1) + z*C2) + w*C3   t_mul_mad_chain, mul then add
 *   the view-volume outcodes               t_clip_mask, unordered compares
 *   oow = 1/clip.w                         a true divide
 *   win = fma(clip*oow, scale, translate)  fmaf
 * every operation rounded on its own (-ffp-contract=off); the flush of
 * denormals is the MXCSR's, the same for both.  The user planes' bits are
 * left to the caller.
 */
#include "tnl/t_pipeline.h"

#include <immintrin.h>

#include "tnl/t_soa8.h"

#define TV_STRIDE (sizeof(struct t_vertex) / sizeof(float))

/* the clip coordinates of eight positions (lanes) */
static inline void clip8(const float *m, const __m256 p[4], __m256 c[4])
{
   for (int r = 0; r < 4; r++) {
      __m256 acc = _mm256_mul_ps(p[0], _mm256_set1_ps(m[r]));
      acc = _mm256_add_ps(_mm256_mul_ps(p[1], _mm256_set1_ps(m[4 + r])), acc);
      acc = _mm256_add_ps(_mm256_mul_ps(p[2], _mm256_set1_ps(m[8 + r])), acc);
      c[r] = _mm256_add_ps(_mm256_mul_ps(p[3], _mm256_set1_ps(m[12 + r])), acc);
   }
}

/* t_clip_mask's six tests: lane masks, true = outside */
static inline void outside8(const __m256 c[4], __m256 out[6])
{
   const __m256 zero = _mm256_setzero_ps();
   out[0] = _mm256_cmp_ps(c[0], c[3], _CMP_NLE_UQ);                      /* !(x <= w) */
   out[1] = _mm256_cmp_ps(zero, _mm256_add_ps(c[0], c[3]), _CMP_NLE_UQ); /* !(0 <= x + w) */
   out[2] = _mm256_cmp_ps(c[1], c[3], _CMP_NLE_UQ);
   out[3] = _mm256_cmp_ps(zero, _mm256_add_ps(c[1], c[3]), _CMP_NLE_UQ);
   out[4] = _mm256_cmp_ps(zero, _mm256_add_ps(c[2], c[3]), _CMP_NLE_UQ);
   out[5] = _mm256_cmp_ps(c[2], c[3], _CMP_NLE_UQ);
}

void t_positions8_avx2(const float *m, const float *scale, const float *translate,
                       const float *pos, unsigned pstride, unsigned n, struct t_vertex *out)
{
   for (unsigned g = 0; g < n; g += 8) {
      const unsigned cnt = n - g < 8 ? n - g : 8;
      __m256 p[4], c[4], o[6], w[4];
      t_soa8_load4(pos + (size_t)g * pstride, pstride, cnt, p);
      clip8(m, p, c);
      outside8(c, o);
      __m256i mask = _mm256_setzero_si256();
      for (int b = 0; b < 6; b++)
         mask = _mm256_or_si256(mask, _mm256_and_si256(_mm256_castps_si256(o[b]),
                                                       _mm256_set1_epi32(1 << b)));
      const __m256 oow = _mm256_div_ps(_mm256_set1_ps(1.0f), c[3]);
      for (int k = 0; k < 3; k++)
         w[k] = _mm256_fmadd_ps(_mm256_mul_ps(c[k], oow), _mm256_set1_ps(scale[k]),
                                _mm256_set1_ps(translate[k]));
      w[3] = oow;
      struct t_vertex *v = out + g;
      t_soa8_store4(c, v->clip, TV_STRIDE, cnt);
      t_soa8_store4(w, v->r.pos, TV_STRIDE, cnt);
      unsigned bits[8];
      _mm256_storeu_si256((__m256i *)bits, mask);
      for (unsigned l = 0; l < cnt; l++)
         v[l].mask = bits[l];
   }
}

bool t_clip_any8_avx2(const float *m, const float *pos, unsigned pstride, unsigned n)
{
   for (unsigned g = 0; g < n; g += 8) {
      const unsigned cnt = n - g < 8 ? n - g : 8;
      __m256 p[4], c[4], o[6];
      t_soa8_load4(pos + (size_t)g * pstride, pstride, cnt, p);
      clip8(m, p, c);
      outside8(c, o);
      const __m256 any = _mm256_or_ps(_mm256_or_ps(_mm256_or_ps(o[0], o[1]), _mm256_or_ps(o[2], o[3])),
                                      _mm256_or_ps(o[4], o[5]));
      if (_mm256_movemask_ps(any))
         return true;
   }
   return false;
}
