/*
 * m_shade_avx2.h: the 8-lane lighting of math/m_shade_avx2.c as an inline
 * function on vectors, m_shade8_eval, for the kernels that keep their
 * lanes in registers (m_shade_point8_avx2 and the per-fragment block
 * kernel, raster/r_block_phong_avx2.c).  Include it only from files
 * compiled with -mavx2 -mfma; the rules of its operations are
 * m_shade_avx2.c's (every lane m_shade_point_prepared's bits).
 */
#ifndef FGL_M_SHADE_AVX2_H
#define FGL_M_SHADE_AVX2_H

#include "math/m_shade.h"

#include <immintrin.h>
#include <math.h>
#include <stdint.h>

#if !defined(__AVX2__) || !defined(__FMA__)
#error "m_shade_avx2.h must be compiled with -mavx2 -mfma"
#endif

#define M_SHADE_PI 3.14159265f

typedef __m256 v8;

#define vset _mm256_set1_ps
#define vadd _mm256_add_ps
#define vsub _mm256_sub_ps
#define vmul _mm256_mul_ps
#define vdiv _mm256_div_ps

/* mask ? b : a */
static inline __attribute__((always_inline)) v8 vsel(v8 a, v8 b, v8 mask)
{
   return _mm256_blendv_ps(a, b, mask);
}

/* whether any lane of a mask is set */
static inline __attribute__((always_inline)) bool any(v8 mask)
{
   return _mm256_movemask_ps(mask) != 0;
}

static inline __attribute__((always_inline)) v8 vneg(v8 x)
{
   return _mm256_xor_ps(x, vset(-0.0f));
}

/* ---- m_gallivm.h, lane-wise ---- */

/* m_gallivm_polynomial's chains, written out: even and odd coefficients
 * by Horner's rule in x^2 (fused) from the highest index down, then
 * odd * x + even (fused) */
static inline __attribute__((always_inline)) v8 poly6(v8 x, const float *c)   /* i = 5, 4, ..., 0 */
{
   const v8 x2 = vmul(x, x);
   v8 odd = vset(c[5]), even = vset(c[4]);
   odd = _mm256_fmadd_ps(x2, odd, vset(c[3]));
   even = _mm256_fmadd_ps(x2, even, vset(c[2]));
   odd = _mm256_fmadd_ps(x2, odd, vset(c[1]));
   even = _mm256_fmadd_ps(x2, even, vset(c[0]));
   return _mm256_fmadd_ps(odd, x, even);
}

static inline __attribute__((always_inline)) v8 poly5(v8 x, const float *c)   /* i = 4, 3, ..., 0 */
{
   const v8 x2 = vmul(x, x);
   v8 even = vset(c[4]), odd = vset(c[3]);
   even = _mm256_fmadd_ps(x2, even, vset(c[2]));
   odd = _mm256_fmadd_ps(x2, odd, vset(c[1]));
   even = _mm256_fmadd_ps(x2, even, vset(c[0]));
   return _mm256_fmadd_ps(odd, x, even);
}

/* m_gallivm_exp2 */
static inline __attribute__((always_inline)) v8 exp2v(v8 x)
{
   static const float c[6] = {
      1.000000000000000000000, 0.693153073200168932794, 0.240153617044375388211,
      0.0558263180532956664775, 0.00898934009049466391101, 0.00187757667519147912699,
   };
   const v8 nan = _mm256_cmp_ps(x, x, _CMP_UNORD_Q);
   /* x > 128 ? 128 : x, then x < -126.99999 ? -126.99999 : x */
   v8 xc = _mm256_min_ps(vset(128.0f), x);
   xc = _mm256_max_ps(vset(-126.99999f), xc);
   const v8 ipart = _mm256_round_ps(xc, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
   const v8 fpart = vsub(xc, ipart);
   const __m256i e = _mm256_add_epi32(_mm256_cvttps_epi32(ipart), _mm256_set1_epi32(127));
   const v8 scale = _mm256_castsi256_ps(_mm256_slli_epi32(e, 23));
   const v8 r = vmul(scale, poly6(fpart, c));
   return vsel(r, x, nan);   /* NaN: x itself */
}

/* m_gallivm_log2 */
static inline __attribute__((always_inline)) v8 log2v(v8 x)
{
   static const float c[5] = {
      2.88539009343309178325, 0.961791550404184197881, 0.577440339438736392009,
      0.403343858251329912514, 0.406718052498846252698,
   };
   const __m256i i = _mm256_castps_si256(x);
   const __m256i ebits = _mm256_srli_epi32(_mm256_and_si256(i, _mm256_set1_epi32(0x7f800000)), 23);
   const v8 exponent = _mm256_cvtepi32_ps(_mm256_sub_epi32(ebits, _mm256_set1_epi32(127)));
   const v8 mant = _mm256_castsi256_ps(_mm256_or_si256(_mm256_and_si256(i, _mm256_set1_epi32(0x007fffff)),
                                                       _mm256_set1_epi32(0x3f800000)));
   const v8 one = vset(1.0f);
   const v8 y = vdiv(vsub(mant, one), vadd(mant, one));
   v8 r = _mm256_fmadd_ps(y, poly5(vmul(y, y), c), exponent);
   r = vsel(r, vset(INFINITY), _mm256_cmp_ps(x, vset(INFINITY), _CMP_GE_OQ));
   r = vsel(r, vset(-INFINITY), _mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_EQ_OQ));
   const v8 bad = _mm256_or_ps(_mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_LT_OQ),
                               _mm256_cmp_ps(x, x, _CMP_UNORD_Q));
   return vsel(r, vset(NAN), bad);
}

/* m_gallivm_pow: 0 for x == 0, else exp2(log2(x) * y) */
static inline __attribute__((always_inline)) v8 powv(v8 x, float y)
{
   const v8 r = exp2v(vmul(log2v(x), vset(y)));
   return vsel(r, _mm256_setzero_ps(), _mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_EQ_OQ));
}

/* spow(x, e) = e == 0 ? 1 : (x <= 0 ? 0 : pow(x, e)); e is the
 * environment's */
static inline __attribute__((always_inline)) v8 spowv(v8 x, float e)
{
   if (e == 0.0f)
      return vset(1.0f);
   const v8 r = powv(x, e);
   return vsel(r, _mm256_setzero_ps(), _mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_LE_OQ));
}

/* ---- m_shade.c's helpers, lane-wise ---- */

static inline __attribute__((always_inline)) v8 dot3v(const v8 *a, const v8 *b)
{
   return vadd(vadd(vmul(a[0], b[0]), vmul(a[1], b[1])), vmul(a[2], b[2]));
}

static inline __attribute__((always_inline)) void normalize3v(v8 *v)
{
   const v8 r = vdiv(vset(1.0f), _mm256_sqrt_ps(dot3v(v, v)));
   v[0] = vmul(v[0], r);
   v[1] = vmul(v[1], r);
   v[2] = vmul(v[2], r);
}

/* x > 0 ? x : 0 */
static inline __attribute__((always_inline)) v8 max0v(v8 x)
{
   return _mm256_max_ps(x, _mm256_setzero_ps());
}

/* m = max0(x); m < 1 ? m : 1 */
static inline __attribute__((always_inline)) v8 clamp01v(v8 x)
{
   return _mm256_min_ps(max0v(x), vset(1.0f));
}

static inline __attribute__((always_inline)) void half_vector8(const struct m_shade_light_prep *lp, bool fixed, const v8 L[3],
                                const v8 V[3], v8 H[3])
{
   if (fixed) {
      H[0] = vset(lp->H[0]), H[1] = vset(lp->H[1]), H[2] = vset(lp->H[2]);
      return;
   }
   H[0] = vadd(L[0], V[0]), H[1] = vadd(L[1], V[1]), H[2] = vadd(L[2], V[2]);
   normalize3v(H);
}

/* One material property: the vertex colours when tracked, else the
 * material's (broadcast). */
static inline __attribute__((always_inline)) void property(v8 *dst, int count, bool tracked, const v8 *col, const float *mat)
{
   for (int i = 0; i < count; i++)
      dst[i] = tracked ? col[i] : vset(mat[i]);
}

/* The equations for 8 points: n, P the normals and eye positions, col
 * the vertex colours (read only where the face tracks a property), the
 * face the call's; primary and secondary as m_shade_point8's. */
static inline __attribute__((always_inline)) void
m_shade8_eval(const struct m_shade_env *env, const v8 n[3], const v8 P[3], bool back,
              const v8 col[4], v8 primary[4], v8 secondary[4])
{
   const struct m_shade_prep *prep = &env->prep;
   const v8 zero = _mm256_setzero_ps(), one = vset(1.0f);

   back = back && env->two_side;
   const struct m_shade_material *mat = &env->material[back ? 1 : 0];
   const struct m_shade_material_prep *mp = &prep->material[back ? 1 : 0];
   const unsigned cm = back ? env->color_material >> M_SHADE_CM_BACK_SHIFT
                            : env->color_material;
   v8 m_ambient[3], m_diffuse[4], m_specular[3], m_emission[3];
   property(m_ambient, 3, cm & M_SHADE_CM_AMBIENT, col, mat->ambient);
   property(m_diffuse, 4, cm & M_SHADE_CM_DIFFUSE, col, mat->diffuse);
   property(m_specular, 3, cm & M_SHADE_CM_SPECULAR, col, mat->specular);
   property(m_emission, 3, cm & M_SHADE_CM_EMISSION, col, mat->emission);
   const bool cook_torrance = mat->model == M_SHADE_COOK_TORRANCE;
   const bool local_viewer = env->local_viewer;

   /* N = normalize(n), -N for the back face */
   v8 N[3] = { n[0], n[1], n[2] };
   normalize3v(N);
   if (back) {
      N[0] = vneg(N[0]);
      N[1] = vneg(N[1]);
      N[2] = vneg(N[2]);
   }
   /* V = local_viewer ? normalize(-P) : (0, 0, 1) */
   v8 V[3] = { zero, zero, one };
   if (local_viewer) {
      V[0] = vneg(P[0]);
      V[1] = vneg(P[1]);
      V[2] = vneg(P[2]);
      normalize3v(V);
   }

   /* F0 = f0 * (1 - m) + c * m, c the base colour */
   const v8 *c = m_diffuse;
   v8 F0[3] = { zero, zero, zero };
   if (cook_torrance) {
      for (int i = 0; i < 3; i++)
         F0[i] = vadd(vset(mp->f0_dielectric), vmul(c[i], vset(mp->metal)));
   }

   v8 sum[3], spec_sum[3] = { zero, zero, zero };
   for (int i = 0; i < 3; i++)
      sum[i] = vadd(m_emission[i], vmul(m_ambient[i], vset(env->global_ambient[i])));

   for (unsigned li = 0; li < env->num_lights; li++) {
      const struct m_shade_light *l = &env->light[li];
      const struct m_shade_light_prep *lp = &prep->light[li];
      const bool positional = l->position[3] != 0.0f;
      v8 L[3], att, spot;
      if (positional) {
         /* L = p.xyz / p.w - P;  d = sqrt(dot(L, L));  L = L / d */
         for (int i = 0; i < 3; i++)
            L[i] = vsub(vset(lp->L[i]), P[i]);
         const v8 d = _mm256_sqrt_ps(dot3v(L, L));
         for (int i = 0; i < 3; i++)
            L[i] = vdiv(L[i], d);
         /* 1 / ((kc + kl*d) + (kq*d)*d) */
         att = vdiv(one, vadd(vadd(vset(l->kc), vmul(vset(l->kl), d)),
                              vmul(vmul(vset(l->kq), d), d)));
         spot = one;
         if (l->spot) {
            const v8 negL[3] = { vneg(L[0]), vneg(L[1]), vneg(L[2]) };
            const v8 sd[3] = { vset(l->spot_direction[0]), vset(l->spot_direction[1]),
                               vset(l->spot_direction[2]) };
            const v8 cs = dot3v(negL, sd);
            const v8 inside = _mm256_cmp_ps(cs, vset(l->spot_cos_cutoff), _CMP_GE_OQ);
            /* (no lane inside the cone: every lane's spot is 0, the
             * power is not needed) */
            spot = any(inside) ? vsel(zero, spowv(cs, l->spot_exponent), inside) : zero;
         }
      } else {
         L[0] = vset(lp->L[0]);
         L[1] = vset(lp->L[1]);
         L[2] = vset(lp->L[2]);
         att = one;
         spot = vset(lp->spot);
      }
      const v8 ndl = dot3v(N, L);
      const v8 ndl_pos = _mm256_cmp_ps(ndl, zero, _CMP_GT_OQ);   /* ndl > 0 */
      v8 H[3];
      const bool fixed_h = !positional && !local_viewer;

      v8 ambient[3], diffuse[3], specular[3];
      for (int i = 0; i < 3; i++)
         ambient[i] = vmul(vset(l->ambient[i]), m_ambient[i]);
      if (!cook_torrance) {
         const v8 fd = max0v(ndl);
         for (int i = 0; i < 3; i++) {
            diffuse[i] = vmul(fd, vmul(vset(l->diffuse[i]), m_diffuse[i]));
            specular[i] = zero;
         }
         /* fs where ndl > 0 (the other lanes' value is not used; no lane
          * with ndl > 0: every lane's specular is 0) */
         if (any(ndl_pos)) {
            half_vector8(lp, fixed_h, L, V, H);
            const v8 fs = spowv(max0v(dot3v(N, H)), mat->shininess);
            for (int i = 0; i < 3; i++)
               specular[i] = vsel(zero, vmul(fs, vmul(vset(l->specular[i]), m_specular[i])),
                                  ndl_pos);
         }
      } else {
         const v8 ndv = dot3v(N, V);
         const v8 one_minus_metal = vset(mp->one_minus_metal);
         for (int i = 0; i < 3; i++)
            diffuse[i] = vsel(zero, vmul(vmul(one_minus_metal, ndl),
                                         vmul(vset(l->diffuse[i]), c[i])), ndl_pos);
         const v8 lobe = _mm256_and_ps(ndl_pos, _mm256_cmp_ps(ndv, zero, _CMP_GT_OQ));
         specular[0] = specular[1] = specular[2] = zero;
         if (any(lobe)) {   /* else every lane's specular is 0 */
            half_vector8(lp, fixed_h, L, V, H);
            const v8 ndh = max0v(dot3v(N, H));
            const v8 vdh = max0v(dot3v(V, H));
            const v8 a2 = vset(mp->a2), k = vset(mp->k), one_minus_k = vset(mp->one_minus_k);
            const v8 pi = vset(M_SHADE_PI);
            /* t = ndh*ndh*(a2 - 1) + 1;  D = a2 / (PI * t * t) */
            const v8 t = vadd(vmul(vmul(ndh, ndh), vset(mp->a2_minus_1)), one);
            const v8 D = vdiv(a2, vmul(vmul(pi, t), t));
            /* G = (ndl / (ndl*(1 - k) + k)) * (ndv / (ndv*(1 - k) + k)) */
            const v8 G = vmul(vdiv(ndl, vadd(vmul(ndl, one_minus_k), k)),
                              vdiv(ndv, vadd(vmul(ndv, one_minus_k), k)));
            const v8 q = vsub(one, vdh);
            const v8 qq = vmul(q, q);
            const v8 q5 = vmul(vmul(qq, qq), q);
            /* s = PI * D * G / (4 * ndv) */
            const v8 s = vdiv(vmul(vmul(pi, D), G), vmul(vset(4.0f), ndv));
            for (int i = 0; i < 3; i++) {
               const v8 F = vadd(F0[i], vmul(vsub(one, F0[i]), q5));
               specular[i] = vsel(zero, vmul(vmul(F, s), vset(l->specular[i])), lobe);
            }
         }
      }

      /* light_i = att * spot * (ambient + diffuse [+ specular]) */
      const v8 f = vmul(att, spot);
      if (env->separate_specular) {
         for (int i = 0; i < 3; i++) {
            sum[i] = vadd(sum[i], vmul(f, vadd(ambient[i], diffuse[i])));
            spec_sum[i] = vadd(spec_sum[i], vmul(f, specular[i]));
         }
      } else {
         for (int i = 0; i < 3; i++)
            sum[i] = vadd(sum[i], vmul(f, vadd(vadd(ambient[i], diffuse[i]), specular[i])));
      }
   }

   for (int i = 0; i < 3; i++)
      primary[i] = clamp01v(sum[i]);
   primary[3] = clamp01v(m_diffuse[3]);
   for (int i = 0; i < 3; i++)
      secondary[i] = env->separate_specular ? clamp01v(spec_sum[i]) : zero;
   secondary[3] = one;
}

#endif
