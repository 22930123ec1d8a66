/*
 * gallivm's transcendental approximations, which the oracle's shaders use
 * for POW (LIT's specular term, the spot exponent) and EX2 (the fog
 * factor): not libm
 * (ORACLE-NOTES.md "gallivm's pow, exp2 and log2"; Mesa 22.3
 * gallivm/lp_bld_arit.c: lp_build_pow, lp_build_exp2, lp_build_log2_approx,
 * lp_build_polynomial).  llvm.fmuladd is fused on the oracle's x86 hosts:
 * fmaf() below.
 */
#ifndef FGL_M_GALLIVM_H
#define FGL_M_GALLIVM_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

static inline float m_gallivm_bits_to_float(uint32_t u)
{
   float f;
   memcpy(&f, &u, sizeof(f));
   return f;
}

static inline uint32_t m_gallivm_float_to_bits(float f)
{
   uint32_t u;
   memcpy(&u, &f, sizeof(u));
   return u;
}

/* lp_build_clamped_float_to_unsigned_norm to 16 bits: v in [0, 1] (the
 * caller clamps) to unorm16 as the low 16 mantissa bits of
 * v * (65535/65536) + 2^7 (ORACLE-NOTES.md "OSMesa contexts and buffers":
 * 16-bit render targets; "Copies into textures and generated mipmaps":
 * the float path of wide formats) */
static inline uint16_t m_gallivm_float_to_unorm16(float v)
{
   return (uint16_t)(m_gallivm_float_to_bits(v * (65535.0f / 65536.0f) + 128.0f) & 0xffffu);
}

/* (The coefficient tables are written as double constants converted to
 * float, as gallivm converts its double tables.) */

/* lp_build_polynomial: even and odd coefficients accumulated separately by
 * Horner's rule in x^2 (fused), from the highest index down, then
 * odd * x + even (fused). */
static inline float m_gallivm_polynomial(float x, const float *coeffs, int n)
{
   const float x2 = x * x;
   float even = 0.0f, odd = 0.0f;
   bool have_even = false, have_odd = false;
   for (int i = n - 1; i >= 0; i--) {
      if ((i & 1) == 0) {
         even = have_even ? fmaf(x2, even, coeffs[i]) : coeffs[i];
         have_even = true;
      } else {
         odd = have_odd ? fmaf(x2, odd, coeffs[i]) : coeffs[i];
         have_odd = true;
      }
   }
   return have_odd ? fmaf(odd, x, even) : even;
}

/* lp_build_exp2: x clamped to [-126.99999, 128] (NaN passes), 2^floor(x)
 * times a degree-5 polynomial of the fraction. */
static inline float m_gallivm_exp2(float x)
{
   static const float c[6] = {
      1.000000000000000000000, 0.693153073200168932794, 0.240153617044375388211,
      0.0558263180532956664775, 0.00898934009049466391101, 0.00187757667519147912699,
   };
   if (isnan(x))
      return x;   /* NaN through the polynomial */
   if (x > 128.0f)
      x = 128.0f;
   if (x < -126.99999f)
      x = -126.99999f;
   const float ipart = floorf(x);
   const float fpart = x - ipart;
   const float scale = m_gallivm_bits_to_float((uint32_t)((int32_t)ipart + 127) << 23);
   return scale * m_gallivm_polynomial(fpart, c, 6);
}

/* lp_build_log2_approx (the "safe" variant): exponent plus
 * y * P(y^2) with y = (m - 1)/(m + 1); exact results for 0, inf, NaN and
 * negative inputs. */
static inline float m_gallivm_log2(float x)
{
   static const float c[5] = {
      2.88539009343309178325, 0.961791550404184197881, 0.577440339438736392009,
      0.403343858251329912514, 0.406718052498846252698,
   };
   const uint32_t i = m_gallivm_float_to_bits(x);
   const float exponent = (float)((int32_t)((i & 0x7f800000u) >> 23) - 127);
   const float mant = m_gallivm_bits_to_float((i & 0x007fffffu) | 0x3f800000u);
   const float y = (mant - 1.0f) / (mant + 1.0f);
   float r = fmaf(y, m_gallivm_polynomial(y * y, c, 5), exponent);
   if (x >= INFINITY)
      r = INFINITY;
   if (x == 0.0f)
      r = -INFINITY;
   if (x < 0.0f || isnan(x))
      r = NAN;
   return r;
}

/* lp_build_pow: 0 for x == 0, else exp2(log2(x) * y) */
static inline float m_gallivm_pow(float x, float y)
{
   if (x == 0.0f)
      return 0.0f;
   return m_gallivm_exp2(m_gallivm_log2(x) * y);
}

#endif
