/*
 * Texture lookups 8 fragments at a time with AVX2 (r_tex8.h): the
 * r_tex_sample8 kernel on the shared code of r_tex_avx2.h.
 */
#include "r_tex_avx2.h"

void r_tex_sample8_avx2(const struct r_texture *t, const float c[3][8], float out[4][8]);

void r_tex_sample8_avx2(const struct r_texture *t, const float c[3][8], float out[4][8])
{
   if (!r_tex8_fast(t)) {
      r_tex_sample8_portable(t, c, out);
      return;
   }
   /* the level of detail of each quad (r_tri.c fill_quad) */
   const __m256 s = load_quads(c[0]), tc = load_quads(c[1]);
   struct r_tex_lod lod[2];
   tex8_lod_quads(t, s, tc, lod);
   const __m256i tex = tex8_filter_quads(t, NULL, lod, s, tc);
   /* unorm8 to float: (float)texel * (float)(1.0 / 255.0) */
   const __m256 scale = _mm256_set1_ps((float)(1.0 / 255.0));
   const __m256i m255 = _mm256_set1_epi32(255);
   store_lanes(out[0], _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_and_si256(tex, m255)), scale));
   store_lanes(out[1], _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_and_si256(_mm256_srli_epi32(tex, 8), m255)), scale));
   store_lanes(out[2], _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_and_si256(_mm256_srli_epi32(tex, 16), m255)), scale));
   store_lanes(out[3], _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_srli_epi32(tex, 24)), scale));
}
