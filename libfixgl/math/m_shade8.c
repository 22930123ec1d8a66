/*
 * m_shade_point8: the lighting of 8 points (structure of arrays), resolved
 * once when the library is loaded -- the AVX2 + FMA kernel
 * (m_shade_avx2.c) on a CPU that runs it, else the portable one below,
 * m_shade_point_prepared lane by lane.  Both give every lane the bits of
 * m_shade_point_prepared (tests/unit/test_shade8.c checks it).
 */
#include "math/m_shade.h"

#include <stddef.h>

void m_shade_point8_portable(const struct m_shade_env *env, const float n[3][M_SHADE_LANES],
                             const float p[3][M_SHADE_LANES], bool back,
                             const float color[4][M_SHADE_LANES],
                             float primary[4][M_SHADE_LANES],
                             float secondary[4][M_SHADE_LANES])
{
   for (int i = 0; i < M_SHADE_LANES; i++) {
      const float ni[3] = { n[0][i], n[1][i], n[2][i] };
      const float pi[3] = { p[0][i], p[1][i], p[2][i] };
      float ci[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
      if (color) {
         for (int k = 0; k < 4; k++)
            ci[k] = color[k][i];
      }
      float prim[4], sec[4];
      m_shade_point_prepared(env, ni, pi, back, color ? ci : NULL, prim, sec);
      for (int k = 0; k < 4; k++) {
         primary[k][i] = prim[k];
         secondary[k][i] = sec[k];
      }
   }
}

#if defined(M_SHADE_HAVE_AVX2)

/* Runs inside the ifunc resolver, at relocation time, before a sanitizer's
 * runtime is set up: not instrumented. */
__attribute__((no_sanitize("address", "undefined", "thread")))
bool m_shade_point8_avx2_supported(void)
{
   __builtin_cpu_init();
   return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

typedef void m_shade_point8_fn(const struct m_shade_env *, const float[3][M_SHADE_LANES],
                               const float[3][M_SHADE_LANES], bool,
                               const float[4][M_SHADE_LANES], float[4][M_SHADE_LANES],
                               float[4][M_SHADE_LANES]);

#if defined(__ELF__) && !defined(__clang__)
/* an ifunc: the dynamic loader runs the resolver once, at relocation */
__attribute__((no_sanitize("address", "undefined", "thread")))
static m_shade_point8_fn *resolve_point8(void)
{
   return m_shade_point8_avx2_supported() ? m_shade_point8_avx2 : m_shade_point8_portable;
}

void m_shade_point8(const struct m_shade_env *env, const float n[3][M_SHADE_LANES],
                    const float p[3][M_SHADE_LANES], bool back,
                    const float color[4][M_SHADE_LANES], float primary[4][M_SHADE_LANES],
                    float secondary[4][M_SHADE_LANES])
   __attribute__((ifunc("resolve_point8")));
#else
/* elsewhere: a pointer set by a constructor, before main and before any
 * library call */
static m_shade_point8_fn *point8 = m_shade_point8_portable;

__attribute__((constructor)) static void resolve_point8(void)
{
   if (m_shade_point8_avx2_supported())
      point8 = m_shade_point8_avx2;
}

void m_shade_point8(const struct m_shade_env *env, const float n[3][M_SHADE_LANES],
                    const float p[3][M_SHADE_LANES], bool back,
                    const float color[4][M_SHADE_LANES], float primary[4][M_SHADE_LANES],
                    float secondary[4][M_SHADE_LANES])
{
   point8(env, n, p, back, color, primary, secondary);
}
#endif

#else /* !M_SHADE_HAVE_AVX2 */

bool m_shade_point8_avx2_supported(void)
{
   return false;
}

void m_shade_point8(const struct m_shade_env *env, const float n[3][M_SHADE_LANES],
                    const float p[3][M_SHADE_LANES], bool back,
                    const float color[4][M_SHADE_LANES], float primary[4][M_SHADE_LANES],
                    float secondary[4][M_SHADE_LANES])
{
   m_shade_point8_portable(env, n, p, back, color, primary, secondary);
}

#endif
