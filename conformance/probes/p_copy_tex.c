/* p_copy_tex.c - glCopyTexImage into R3_G3_B2 and GL_GENERATE_MIPMAP into
 * the formats of other than 8 bits per channel (ORACLE-NOTES.md "Copies
 * into textures and generated mipmaps"):
 *  - every 8-bit value of the colour buffer copied into GL_R3_G3_B2
 *    becomes ((x >> n) * (2^n - 1) + 2^(7 - n)) >> (8 - n) (n = 3, 3, 2);
 *  - a copy into GL_RGB reads alpha 1 whatever the buffer's alpha;
 *  - a generated level of RGBA16 or RGB10_A2 is the fused float lerp of
 *    the level above's stored values, converted to unorm16 by the magic
 *    of lp_build_clamped_float_to_unsigned_norm, then to the channel's
 *    bits by llvmpipe's scale_bits (a shift for 10 bits, a rescale with
 *    a rounding term for the 2-bit alpha). */
#include "probe.h"

#include <stdint.h>

static unsigned rnd = 7;
static unsigned r32(void)
{
   rnd = rnd * 1103515245u + 12345u;
   return rnd >> 8;   /* the LCG's low bits have short periods */
}

/* float in [0, 1] to an unorm of `bits` bits: the low mantissa bits of
 * v * (2^bits - 1) / 2^bits + 2^(23 - bits) */
static unsigned to_unorm(float v, int bits)
{
   const float x = v * ((float)((1u << bits) - 1u) / (float)(1u << bits)) +
                   (float)(1u << (23 - bits));
   uint32_t u;
   memcpy(&u, &x, sizeof(u));
   return u & ((1u << bits) - 1u);
}

static unsigned lerp2(const unsigned t[4], int bits)
{
   const float sc = (float)(1.0 / (double)((1u << bits) - 1u));
   float v[4];
   for (int k = 0; k < 4; k++)
      v[k] = (float)t[k] * sc;
   const float a = fmaf(0.5f, v[1] - v[0], v[0]);
   const float b = fmaf(0.5f, v[3] - v[2], v[2]);
   const unsigned u = to_unorm(fmaf(0.5f, b - a, a), 16), d = 16u - (unsigned)bits;
   return d <= (unsigned)bits ? u >> d
                              : ((u >> bits) * ((1u << bits) - 1u) + (1u << (d - 1u))) >> d;
}

int main(void)
{
   probe_init_ub(16, 16);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glPixelStorei(GL_PACK_ALIGNMENT, 1);

   /* every 8-bit value in each channel */
   unsigned char ramp[256 * 4];
   for (int i = 0; i < 256; i++) {
      ramp[4 * i + 0] = (unsigned char)i;
      ramp[4 * i + 1] = (unsigned char)(255 - i);
      ramp[4 * i + 2] = (unsigned char)((i * 7) & 255);
      ramp[4 * i + 3] = (unsigned char)(i ^ 0x5a);
   }
   glWindowPos2i(0, 0);
   glDrawPixels(16, 16, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
   glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_R3_G3_B2, 0, 0, 16, 16, 0);
   unsigned char t332[256];
   glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, t332);
   long bad = 0;
   for (int i = 0; i < 256; i++) {
      const int bits[3] = { 3, 3, 2 }, shift[3] = { 5, 2, 0 };
      for (int c = 0; c < 3; c++) {
         const unsigned x = ramp[4 * i + c], n = (unsigned)bits[c];
         const unsigned want = ((x >> n) * ((1u << n) - 1u) + (1u << (7u - n))) >> (8u - n);
         bad += ((t332[i] >> shift[c]) & ((1u << n) - 1u)) != want;
      }
   }
   probe_expect("R3_G3_B2 copy: channels off the rescale rule (of 768)", bad, 0);

   glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 16, 16, 0);
   unsigned char rgba[256 * 4];
   glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
   bad = 0;
   for (int i = 0; i < 256; i++)
      bad += rgba[4 * i + 3] != 255 || memcmp(rgba + 4 * i, ramp + 4 * i, 3) != 0;
   probe_expect("GL_RGB copy: texels not (r, g, b, 1) (of 256)", bad, 0);

   /* generated mipmaps on the float path: 2x2 -> 1x1, random values */
   glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
   long bad16 = 0, bad1010102 = 0;
   for (int it = 0; it < 1000; it++) {
      unsigned short s[16];
      for (int i = 0; i < 16; i++)
         s[i] = (unsigned short)r32();
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16, 2, 2, 0, GL_RGBA, GL_UNSIGNED_SHORT, s);
      unsigned short o[4];
      glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_SHORT, o);
      for (int c = 0; c < 4; c++) {
         const unsigned t[4] = { s[c], s[4 + c], s[8 + c], s[12 + c] };
         bad16 += o[c] != lerp2(t, 16);
      }
      unsigned p[4];
      for (int i = 0; i < 4; i++)
         p[i] = r32() ^ (r32() << 16);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB10_A2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, p);
      unsigned q;
      glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, &q);
      for (int c = 0; c < 4; c++) {
         const int bits = c == 3 ? 2 : 10, sh = c == 3 ? 0 : 22 - 10 * c;
         const unsigned m = (1u << bits) - 1u;
         const unsigned t[4] = { p[0] >> sh & m, p[1] >> sh & m, p[2] >> sh & m, p[3] >> sh & m };
         bad1010102 += (q >> sh & m) != lerp2(t, bits);
      }
   }
   probe_expect("RGBA16 generated level: channels off the model (of 4000)", bad16, 0);
   probe_expect("RGB10_A2 generated level: channels off the model (of 4000)", bad1010102, 0);
   return probe_result();
}
