/*
 * test_vertex.c - unit tests of the vertex stage's vectorised arithmetic
 * (tnl/t_light.c): the eight-lane LIT pow of light_simd (t_lit_pows) gives
 * m_gallivm_pow's bits for millions of random arguments -- any bit
 * patterns, [0, 1), denormals, the special values 0, -0, inf, NaN, and
 * exponents in and beyond [-128, 128] -- with and without the draw's flush
 * of denormals (FTZ/DAZ).  (On a CPU without AVX2 and FMA, t_lit_pows is
 * m_gallivm_pow itself and the test is trivially true.)
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "math/m_gallivm.h"
#include "tnl/t_light.h"

#include "check.h"

static uint64_t rng_state = 88172645463325252ull;

static uint32_t rnd(void)
{
   rng_state ^= rng_state << 13;
   rng_state ^= rng_state >> 7;
   rng_state ^= rng_state << 17;
   return (uint32_t)(rng_state >> 16);
}

static float from_bits(uint32_t u)
{
   float f;
   memcpy(&f, &u, 4);
   return f;
}

static uint32_t to_bits(float f)
{
   uint32_t u;
   memcpy(&u, &f, 4);
   return u;
}

static float random_base(void)
{
   static const float special[] = { 0.0f, -0.0f, 1.0f, INFINITY, -INFINITY, NAN, 1e-30f,
                                    0.5f, 2.0f };
   const uint32_t r = rnd();
   switch (rnd() % 6) {
   case 0: return from_bits(r);                               /* any bits */
   case 1: return (float)(r & 0xffffff) / 16777216.0f;        /* [0, 1) */
   case 2: return from_bits(r & 0x007fffff);                  /* denormal */
   case 3: return special[r % 9];
   default: return from_bits(0x3f000000u + (r & 0x00ffffff)); /* [0.5, 2) */
   }
}

static float random_exponent(void)
{
   const uint32_t q = rnd();
   switch (rnd() % 4) {
   case 0: return (float)(int)(q % 257) - 128.0f;
   case 1: return ((float)(q & 0xffffff) / 16777216.0f) * 256.0f - 128.0f;
   case 2: return (float)(q % 129);
   default: {
      const float y = from_bits(q);   /* any bits but NaN (LIT's exponent never is) */
      return isnan(y) ? 40.0f : y;
   }
   }
}

#define N 4096

int main(void)
{
   static float x[N], y[N], out[N];
   long differ = 0;
#if defined(__SSE__) || defined(__x86_64__)
   const unsigned mxcsr = _mm_getcsr();
#endif
   for (int flush = 0; flush < 2; flush++) {
#if defined(__SSE__) || defined(__x86_64__)
      _mm_setcsr(flush ? mxcsr | 0x8040u : mxcsr);   /* FTZ | DAZ */
#endif
      for (int round = 0; round < 500; round++) {
         for (int k = 0; k < N; k++) {
            x[k] = random_base();
            y[k] = random_exponent();
         }
         t_lit_pows(x, y, out, N);
         for (int k = 0; k < N; k++) {
            const float want = m_gallivm_pow(x[k], y[k]);
            if (to_bits(want) != to_bits(out[k]) && differ++ < 10)
               FAIL("flush %d: pow(%08x, %08x) = %08x, want %08x", flush, to_bits(x[k]),
                    to_bits(y[k]), to_bits(out[k]), to_bits(want));
         }
      }
   }
#if defined(__SSE__) || defined(__x86_64__)
   _mm_setcsr(mxcsr);
#endif
   CHECK(differ == 0, "%ld of %d pows differ", differ, 2 * 500 * N);
   return check_report("vertex");
}
