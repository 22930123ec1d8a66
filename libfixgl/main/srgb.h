/*
 * 8-bit sRGB <-> linear light as the oracle converts them (its
 * util_format_srgb_8unorm_to_linear_float and
 * util_format_linear_float_to_srgb_8unorm; tables from gen_srgb.py).
 * Used where the oracle's colour buffer is an sRGB format: glAccum on
 * GLX drawables (main/accum.c, ORACLE-NOTES.md "GLX sRGB buffers").
 */
#ifndef FGL_SRGB_H
#define FGL_SRGB_H

#include <stdint.h>
#include <string.h>

extern const float fgl_srgb8_to_linear_table[256];
extern const uint32_t fgl_linear_to_srgb8_table[104];

static inline float fgl_srgb8_to_linear(uint8_t s)
{
   return fgl_srgb8_to_linear_table[s];
}

/* clamped to [2^-13, 1 - 2^-24] (NaN to the minimum, which gives 0); the
 * bucket's bias and scale, interpolated by the next 8 mantissa bits */
static inline uint8_t fgl_linear_to_srgb8(float x)
{
   const uint32_t min_bits = (127u - 13u) << 23, one_less = 0x3f7fffffu;
   float lo, hi;
   memcpy(&lo, &min_bits, 4);
   memcpy(&hi, &one_less, 4);
   if (!(x > lo))
      x = lo;
   if (x > hi)
      x = hi;
   uint32_t bits;
   memcpy(&bits, &x, 4);
   const uint32_t tab = fgl_linear_to_srgb8_table[(bits - min_bits) >> 20];
   const uint32_t bias = (tab >> 16) << 9, scale = tab & 0xffffu;
   const uint32_t t = (bits >> 12) & 0xffu;
   return (uint8_t)((bias + scale * t) >> 16);
}

#endif
