/*
 * Texture lookups 8 fragments at a time (r_tex8.h): the portable version,
 * the scalar functions lane by lane, and the dispatch to the AVX2 kernel
 * (r_tex_avx2.c, built when the compiler targets x86-64: FGL_TEX8_AVX2).
 */
#include "r_tex8.h"

/* the quad of lane i: A (lanes 0, 1, 4, 5) or B (2, 3, 6, 7) */
static inline int quad_of(int i)
{
   return (i >> 1) & 1;
}

/* The TL, TR, BL coordinates of quad q (0: A, 1: B). */
static void quad_coords(const float c[3][8], int q, float out[3][3])
{
   static const int lane[3] = { 0, 1, 4 };   /* R_QUAD_TL, TR, BL of quad A */
   for (int i = 0; i < 3; i++)
      for (int k = 0; k < 3; k++)
         out[i][k] = c[k][lane[i] + 2 * q];
}

bool r_tex8_fast(const struct r_texture *t)
{
   if (t->soa || (t->dims != 1 && t->dims != 2))
      return false;
   if (t->wrap_s != R_WRAP_REPEAT && t->wrap_s != R_WRAP_CLAMP_TO_EDGE)
      return false;
   if (t->dims == 2 && t->wrap_t != R_WRAP_REPEAT && t->wrap_t != R_WRAP_CLAMP_TO_EDGE)
      return false;
   return true;
}

void r_tex_sample8_portable(const struct r_texture *t, const float c[3][8], float out[4][8])
{
   float qc[2][3][3];
   quad_coords(c, 0, qc[0]);
   quad_coords(c, 1, qc[1]);
   if (!t->soa) {
      /* one level of detail per quad (r_tri.c fill_quad), then each
       * lane's filter (r_frag.c tex_color) */
      struct r_tex_lod lod[2];
      r_tex_lod_aos(t, (const float (*)[3])qc[0], &lod[0]);
      r_tex_lod_aos(t, (const float (*)[3])qc[1], &lod[1]);
      for (int i = 0; i < 8; i++) {
         const struct r_tex_lod *l = &lod[quad_of(i)];
         const float ci[3] = { c[0][i], c[1][i], c[2][i] };
         float o[4];
         r_tex_filter_aos(t, ci, l->minify, l->level0, l->level1, l->weight, o);
         for (int k = 0; k < 4; k++)
            out[k][i] = o[k];
      }
      return;
   }
   const bool pair = r_tex_need_pair(t);
   for (int i = 0; i < 8; i++) {
      const int q = quad_of(i);
      const float ci[3] = { c[0][i], c[1][i], c[2][i] };
      float o[4];
      r_tex_sample(t, ci, (const float (*)[3])qc[q], pair ? (const float (*)[3])qc[q ^ 1] : NULL,
                   o);
      for (int k = 0; k < 4; k++)
         out[k][i] = o[k];
   }
}

#ifdef FGL_TEX8_AVX2
/* r_tex_avx2.c, compiled with -mavx2 -mfma: call only when the CPU has both */
void r_tex_sample8_avx2(const struct r_texture *t, const float c[3][8], float out[4][8]);
#endif

r_tex_sample8_fn r_tex_sample8_avx2_fn(void)
{
#ifdef FGL_TEX8_AVX2
   if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
      return r_tex_sample8_avx2;
#endif
   return NULL;
}

/* the implementation, chosen at the first call (every thread stores the
 * same value) */
static r_tex_sample8_fn sample8_impl;

void r_tex_sample8(const struct r_texture *t, const float c[3][8], float out[4][8])
{
   r_tex_sample8_fn f = __atomic_load_n(&sample8_impl, __ATOMIC_RELAXED);
   if (!f) {
      f = r_tex_sample8_avx2_fn();
      if (!f)
         f = r_tex_sample8_portable;
      __atomic_store_n(&sample8_impl, f, __ATOMIC_RELAXED);
   }
   f(t, c, out);
}
