/*
 * m_shade_point8_avx2: math/m_shade.c's equations for 8 points at once,
 * with AVX2 + FMA (this file alone is compiled with -mavx2 -mfma; the
 * loader calls it only on a CPU that has both, math/m_shade8.c).
 *
 * Each lane computes exactly what m_shade_point_prepared computes for its
 * point: the same IEEE operations on the same operands in the same order
 * (-ffp-contract=off applies to the intrinsics too: a mul then an add stay
 * two roundings), _mm256_fmadd_ps exactly where the scalar code calls
 * fmaf, _mm256_div_ps / _mm256_sqrt_ps where it divides / calls sqrtf,
 * _mm256_round_ps(floor) for floorf.  The scalar code's ternaries are
 * vmaxps / vminps with the same operand order (x > 0 ? x : 0 is
 * _mm256_max_ps(x, 0): the second operand for a NaN or a zero pair), and
 * its per-point branches are lane masks: both sides are computed for every
 * lane and the mask selects, per lane, the value the scalar branch would
 * have produced (a value the scalar code does not compute for a lane, e.g.
 * H where n.l <= 0, is computed here and thrown away).
 *
 * Everything the environment decides (number of lights, directional or
 * positional, spot or not, the model, colour material, local viewer,
 * separate specular, the face) is a branch on the environment, taken once
 * per 8 lanes.
 *
 * NaN payloads: the scalar code's NaNs may carry other payloads than the
 * lanes' (the compiler may swap the operands of a commutative operation),
 * but every output goes through clamp01 (max(x, 0) turns NaN into 0) or is
 * a constant, so only whether a value is NaN can reach the outputs, and
 * that does not depend on the payloads.
 */
#include "math/m_shade_avx2.h"

void m_shade_point8_avx2(const struct m_shade_env *env, const float n[3][M_SHADE_LANES],
                         const float p[3][M_SHADE_LANES], bool back,
                         const float color[4][M_SHADE_LANES], float primary[4][M_SHADE_LANES],
                         float secondary[4][M_SHADE_LANES])
{
   const v8 zero = _mm256_setzero_ps();
   back = back && env->two_side;
   const unsigned cm = back ? env->color_material >> M_SHADE_CM_BACK_SHIFT
                            : env->color_material;
   v8 col[4] = { zero, zero, zero, zero };
   if (cm & (M_SHADE_CM_AMBIENT | M_SHADE_CM_DIFFUSE | M_SHADE_CM_SPECULAR | M_SHADE_CM_EMISSION)) {
      for (int i = 0; i < 4; i++)
         col[i] = _mm256_loadu_ps(color[i]);
   }
   const v8 N[3] = { _mm256_loadu_ps(n[0]), _mm256_loadu_ps(n[1]), _mm256_loadu_ps(n[2]) };
   const v8 P[3] = { _mm256_loadu_ps(p[0]), _mm256_loadu_ps(p[1]), _mm256_loadu_ps(p[2]) };
   v8 prim[4], sec[4];
   m_shade8_eval(env, N, P, back, col, prim, sec);
   for (int i = 0; i < 4; i++) {
      _mm256_storeu_ps(primary[i], prim[i]);
      _mm256_storeu_ps(secondary[i], sec[i]);
   }
}
