/*
 * test_convert.c - unit tests of the raster core's float -> unorm
 * conversions (raster/r_tri.c; ORACLE-NOTES.md "Depth conversion and
 * polygon offset", "Colour conversion").
 *
 *   colour: RNE(min(c, 1) * 255.0f), negative and NaN give 0
 *   depth:  clamp to [0, 1] (NaN -> 0), then RNE(z * 16777215.0f) for Z24
 *           or RNE(z * 65535.0f) for Z16
 *
 * The multiplications are single precision: several cases below are exact
 * ties only because the float product rounds onto .5 (the double product
 * would round the other way), which pins both the float multiply and the
 * round-half-to-even.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "raster/r_state.h"

#include "check.h"

#define CHECK_U8(in, want)                                                    \
   do {                                                                       \
      const float in_ = (in);                                                 \
      const unsigned got_ = r_float_to_unorm8(in_);                           \
      CHECK(got_ == (unsigned)(want), "r_float_to_unorm8(%a = %.9g) = %u, expected %u", \
            (double)in_, (double)in_, got_, (unsigned)(want));                \
   } while (0)

#define CHECK_Z24(in, want)                                                   \
   do {                                                                       \
      const float in_ = (in);                                                 \
      const unsigned long got_ = r_depth_to_z24(in_);                         \
      CHECK(got_ == (unsigned long)(want), "r_depth_to_z24(%a = %.9g) = %lu, expected %lu", \
            (double)in_, (double)in_, got_, (unsigned long)(want));           \
   } while (0)

#define CHECK_Z16(in, want)                                                   \
   do {                                                                       \
      const float in_ = (in);                                                 \
      const unsigned got_ = r_depth_to_z16(in_);                              \
      CHECK(got_ == (unsigned)(want), "r_depth_to_z16(%a = %.9g) = %u, expected %u", \
            (double)in_, (double)in_, got_, (unsigned)(want));                \
   } while (0)

static void test_unorm8(void)
{
   /* end points and clamping */
   CHECK_U8(0.0f, 0);
   CHECK_U8(-0.0f, 0);
   CHECK_U8(-1.0f, 0);
   CHECK_U8(-INFINITY, 0);
   CHECK_U8(NAN, 0);
   CHECK_U8(0x1p-140f, 0);          /* denormal */
   CHECK_U8(1.0f, 255);
   CHECK_U8(1.5f, 255);
   CHECK_U8(INFINITY, 255);
   CHECK_U8(0x1.fffffep-1f, 255);   /* 254.99998 */

   /* ties: the float products are exactly n + 0.5 */
   CHECK_U8(0.5f, 128);                  /* 127.5 */
   CHECK_U8(2.5f / 255.0f, 2);           /* 2.5 */
   CHECK_U8(1.5f / 255.0f, 2);           /* 1.5 */
   CHECK_U8(0.5f / 255.0f, 0);           /* 0.5 */
   CHECK_U8(128.5f / 255.0f, 128);       /* 128.5 */
   CHECK_U8(254.5f / 255.0f, 254);       /* 254.5 */

   /* exact levels */
   CHECK_U8(1.0f / 255.0f, 1);
   CHECK_U8(0.25f, 64);                  /* 63.75 */
   CHECK_U8(0.75f, 191);                 /* 191.25 */

   /* all 256 levels i/255 come back as i */
   for (int i = 0; i < 256; i++)
      CHECK_U8((float)i / 255.0f, i);
}

static void test_z24(void)
{
   CHECK_Z24(0.0f, 0);
   CHECK_Z24(-0.0f, 0);
   CHECK_Z24(-0.25f, 0);
   CHECK_Z24(-INFINITY, 0);
   /* lp_build_clamp(z, 0, 1) = max(min(z, 1), 0) with minps: NaN -> 1
    * (core/w_zero_vertex shows it against the oracle) */
   CHECK_Z24(NAN, 16777215);
   CHECK_Z24(1.0f, 16777215);
   CHECK_Z24(1.0001f, 16777215);
   CHECK_Z24(INFINITY, 16777215);

   CHECK_Z24(0.5f, 8388608);             /* 8388607.5, tie to even */
   CHECK_Z24(0.25f, 4194304);            /* 4194303.75 */
   CHECK_Z24(0.75f, 12582911);           /* 12582911.25 rounds to 12582911 in float */
   /* 0.3f * 16777215 = 5033164.5000... in double (5033165) but exactly
    * 5033164.5 in float, a tie that goes to even */
   CHECK_Z24(0.3f, 5033164);
   CHECK_Z24(0.1f, 1677722);             /* float product 1677721.5 */
   CHECK_Z24(1.0f / 16777215.0f, 1);
   CHECK_Z24(0.5f / 16777215.0f, 0);     /* product 0.5 */
   CHECK_Z24(1.5f / 16777215.0f, 2);     /* product 1.5 */
}

static void test_z16(void)
{
   CHECK_Z16(0.0f, 0);
   CHECK_Z16(-3.0f, 0);
   CHECK_Z16(NAN, 65535);
   CHECK_Z16(1.0f, 65535);
   CHECK_Z16(7.0f, 65535);
   CHECK_Z16(INFINITY, 65535);
   CHECK_Z16(0.5f, 32768);               /* 32767.5 */
   /* 0.3f * 65535: 19660.5008 in double, 19660.5 in float */
   CHECK_Z16(0.3f, 19660);
   CHECK_Z16(0.7f, 45874);               /* 45874.5 in float */
   CHECK_Z16(1.0f / 65535.0f, 1);
}

int main(void)
{
   test_unorm8();
   test_z24();
   test_z16();
   return check_report("unit-convert");
}
