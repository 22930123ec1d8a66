/*
 * t_soa8.h: eight vertices' float[4] rows to four lane vectors and back
 * (array of structures <-> structure of arrays), for the vertex stage's
 * eight-lane loops (t_vertex_avx2.c, t_light.c light_simd).  Loads and
 * stores move bits only: no arithmetic, so a lane holds exactly its
 * vertex's floats.  The functions carry the AVX2 target themselves, so
 * that a file built for the baseline can call them from its own AVX2
 * functions; call them only on a CPU with AVX2.
 */
#ifndef FGL_T_SOA8_H
#define FGL_T_SOA8_H

#include <immintrin.h>
#include <stddef.h>

#define T_SOA8 __attribute__((target("avx2,fma"), always_inline)) static inline

/* v[k] lane l = row l's component k, row l at base + l * stride floats
 * (l < cnt; the lanes past cnt repeat row cnt - 1, read nowhere else);
 * cnt in 1..8 */
T_SOA8 void t_soa8_load4(const float *base, size_t stride, unsigned cnt, __m256 v[4])
{
   const float *r[8];
   for (unsigned l = 0; l < 8; l++)
      r[l] = base + (l < cnt ? l : cnt - 1) * stride;
   /* a[j]: rows j (low half) and j + 4 (high half) */
   const __m256 a0 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(r[0])),
                                          _mm_loadu_ps(r[4]), 1);
   const __m256 a1 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(r[1])),
                                          _mm_loadu_ps(r[5]), 1);
   const __m256 a2 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(r[2])),
                                          _mm_loadu_ps(r[6]), 1);
   const __m256 a3 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(r[3])),
                                          _mm_loadu_ps(r[7]), 1);
   const __m256 t0 = _mm256_unpacklo_ps(a0, a1), t1 = _mm256_unpackhi_ps(a0, a1);
   const __m256 t2 = _mm256_unpacklo_ps(a2, a3), t3 = _mm256_unpackhi_ps(a2, a3);
   v[0] = _mm256_shuffle_ps(t0, t2, 0x44);
   v[1] = _mm256_shuffle_ps(t0, t2, 0xee);
   v[2] = _mm256_shuffle_ps(t1, t3, 0x44);
   v[3] = _mm256_shuffle_ps(t1, t3, 0xee);
}

/* row l (l < cnt) at base + l * stride floats = lane l of v[0..3] */
T_SOA8 void t_soa8_store4(const __m256 v[4], float *base, size_t stride, unsigned cnt)
{
   const __m256 t0 = _mm256_unpacklo_ps(v[0], v[1]), t1 = _mm256_unpackhi_ps(v[0], v[1]);
   const __m256 t2 = _mm256_unpacklo_ps(v[2], v[3]), t3 = _mm256_unpackhi_ps(v[2], v[3]);
   /* q[j]: rows j (low half) and j + 4 (high half) */
   const __m256 q[4] = { _mm256_shuffle_ps(t0, t2, 0x44), _mm256_shuffle_ps(t0, t2, 0xee),
                         _mm256_shuffle_ps(t1, t3, 0x44), _mm256_shuffle_ps(t1, t3, 0xee) };
   if (cnt == 8) {
      for (unsigned l = 0; l < 4; l++) {
         _mm_storeu_ps(base + l * stride, _mm256_castps256_ps128(q[l]));
         _mm_storeu_ps(base + (l + 4) * stride, _mm256_extractf128_ps(q[l], 1));
      }
      return;
   }
   for (unsigned l = 0; l < cnt; l++) {
      const __m128 r = l < 4 ? _mm256_castps256_ps128(q[l]) : _mm256_extractf128_ps(q[l - 4], 1);
      _mm_storeu_ps(base + l * stride, r);
   }
}

#endif
