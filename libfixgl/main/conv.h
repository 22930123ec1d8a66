/*
 * Number conversions of Mesa's main/macros.h that the entry points share:
 * integer arguments normalized to float (confirmed exhaustively against the
 * oracle for colours, ORACLE-NOTES.md "Colour conversion") and x86
 * float -> int casts.
 */
#ifndef FGL_MAIN_CONV_H
#define FGL_MAIN_CONV_H

#include <GL/gl.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>

/* Signed types map (2c+1)/(2^n-1); unsigned bytes use i/255.0f, the other
 * unsigned types multiply by the reciprocal; INT/UINT go through double. */
#define BYTE_TO_FLOAT(b)   ((2.0F * (b) + 1.0F) * (1.0F / 255.0F))
#define UBYTE_TO_FLOAT(u)  ((float)(u) / 255.0F)
#define SHORT_TO_FLOAT(s)  ((2.0F * (s) + 1.0F) * (1.0F / 65535.0F))
#define USHORT_TO_FLOAT(s) ((GLfloat)(s) * (1.0F / 65535.0F))
#define INT_TO_FLOAT(i)    ((GLfloat)((2.0F * (i) + 1.0F) * (1.0F / 4294967294.0)))
#define UINT_TO_FLOAT(u)   ((GLfloat)((u) * (1.0F / 4294967295.0)))

/* A C cast to GLint as x86 does it (cvttsd2si): truncation, INT_MIN when
 * out of range or NaN. */
static inline GLint fgl_double_to_int_trunc(double d)
{
   if (!(d >= -2147483648.0 && d < 2147483648.0))
      return INT_MIN;
   return (GLint)d;
}

/* FLOAT_TO_INT: normalized float state read as an integer. */
static inline GLint fgl_float_to_int_norm(double f)
{
   return fgl_double_to_int_trunc(2147483647.0 * f);
}

/* Mesa's IROUND-like lroundf of a float into a GLint (_mesa_GetIntegerv
 * TYPE_FLOAT, _mesa_PixelStoref, _mesa_GetMaterialiv): a long (64 bits)
 * rounded half away from zero, then its low 32 bits; out of the long range
 * or NaN, glibc's x86-64 lroundf gives LONG_MIN, whose low 32 bits are 0
 * (1e30 reads back as 0). */
static inline GLint fgl_lround_to_int(float f)
{
   int64_t l = INT64_MIN;
   if (f >= -9223372036854775808.0f && f < 9223372036854775808.0f)
      l = (int64_t)lroundf(f);
   return (GLint)(uint32_t)(uint64_t)l;
}

/* Mesa's CLAMP(x, 0, 1) (util/macros.h: x > min ? (x > max ? max : x) : min):
 * NaN becomes 0 (unlike gallivm's clamp, raster/r_state.h r_clamp01). */
static inline float fgl_clamp01(float x)
{
   return x > 0.0f ? (x > 1.0f ? 1.0f : x) : 0.0f;
}

#endif
