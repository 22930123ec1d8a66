/*
 * S3TC texel decoding as the oracle samples it (ORACLE-NOTES.md
 * "Compressed textures"; probe p_s3tc).
 *
 * llvmpipe keeps an S3TC texture compressed and decodes each texel it
 * fetches [S: gallivm/lp_bld_format_s3tc.c: s3tc_dxt1_full_to_rgba_aos,
 * lp_build_lerp23, lp_build_pavgb, s3tc_dxt3_to_rgba_aos,
 * s3tc_dxt5_alpha_channel, lp_build_lerpdxta]; glGetTexImage of such a
 * texture goes through the same sampler (a blit), so both read the same
 * 8-bit texels.  Those texels are a pure function of the block, so fixgl
 * decodes each image once, at upload, into its RGBA8 texels and filters
 * them as any 8-bit texture (the AoS path: util_format_fits_8unorm holds
 * for S3TC).
 *
 * The decoder's arithmetic, all on 8-bit channels:
 *  - colours 565 to 8 bits by bit replication (r5 << 3 | r5 >> 2,
 *    g6 << 2 | g6 >> 4);
 *  - the thirds: d = c1 - c0 as a 16-bit signed product m = 85 * d taken
 *    unsigned (mod 2^16); colour 2 = c0 + (m >> 8), colour 3 =
 *    c0 + ((m >> 7) & 255), each sum mod 256 (not (2*c0 + c1) / 3);
 *  - DXT1 with c0 <= c1 (as 16-bit numbers): colour 2 the rounded-up
 *    average (c0 + c1 + 1) >> 1 (pavgb), colour 3 black with alpha 0 for
 *    DXT1 RGBA (1 for DXT1 RGB); DXT3 and DXT5 always take the four-colour
 *    mode;
 *  - DXT3 alpha: the texel's nibble a, a << 4 | a;
 *  - DXT5 alpha: codes 0 and 1 the two alphas; with a0 > a1 codes 2..7,
 *    with a0 <= a1 codes 2..5 interpolate: the weight
 *    ((W * (code - 1)) mod 2^16) >> 6 with W = 255*64/7 = 2331 or
 *    255*64/5 = 3264, then a0 + ((((a1 - a0) * weight) mod 2^16) >> 8),
 *    mod 256; with a0 <= a1 code 6 is 0 and code 7 is 255.
 */
#include <stddef.h>

#include "main/texcompress_s3tc.h"

unsigned fgl_s3tc_block_bytes(GLenum format, GLenum *base)
{
   switch (format) {
   case GL_COMPRESSED_RGB_S3TC_DXT1_EXT:
      if (base)
         *base = GL_RGB;
      return 8;
   case GL_COMPRESSED_RGBA_S3TC_DXT1_EXT:
      if (base)
         *base = GL_RGBA;
      return 8;
   case GL_COMPRESSED_RGBA_S3TC_DXT3_EXT:
   case GL_COMPRESSED_RGBA_S3TC_DXT5_EXT:
      if (base)
         *base = GL_RGBA;
      return 16;
   default:
      return 0;
   }
}

/* c0 + 1/3 (k = 0) or 2/3 (k = 1) of c1 - c0, lp_build_lerp23's way */
static uint8_t lerp_third(int c0, int c1, int k)
{
   const unsigned m = (uint16_t)(85 * (c1 - c0));
   return (uint8_t)(c0 + (k ? ((m >> 7) & 255u) : (m >> 8)));
}

/* The four colours of a colour block (its first 4 bytes), RGBA8. */
static void colour_palette(const uint8_t *b, bool dxt1, bool dxt1_alpha, uint8_t pal[4][4])
{
   const unsigned c[2] = { (unsigned)b[0] | (unsigned)b[1] << 8,
                           (unsigned)b[2] | (unsigned)b[3] << 8 };
   for (int i = 0; i < 2; i++) {
      const unsigned r = c[i] >> 11, g = (c[i] >> 5) & 63u, bl = c[i] & 31u;
      pal[i][0] = (uint8_t)(r << 3 | r >> 2);
      pal[i][1] = (uint8_t)(g << 2 | g >> 4);
      pal[i][2] = (uint8_t)(bl << 3 | bl >> 2);
      pal[i][3] = 255;
   }
   if (!dxt1 || c[0] > c[1]) {
      for (int n = 0; n < 3; n++) {
         pal[2][n] = lerp_third(pal[0][n], pal[1][n], 0);
         pal[3][n] = lerp_third(pal[0][n], pal[1][n], 1);
      }
      pal[2][3] = pal[3][3] = 255;
   } else {
      for (int n = 0; n < 3; n++) {
         pal[2][n] = (uint8_t)((pal[0][n] + pal[1][n] + 1) >> 1);
         pal[3][n] = 0;
      }
      pal[2][3] = 255;
      pal[3][3] = dxt1_alpha ? 0 : 255;
   }
}

/* The eight alphas of a DXT5 alpha block (its first 2 bytes). */
static void alpha_palette(const uint8_t *b, uint8_t pal[8])
{
   const int a0 = b[0], a1 = b[1];
   const bool seven = a0 > a1;
   pal[0] = (uint8_t)a0;
   pal[1] = (uint8_t)a1;
   for (int code = 2; code < 8; code++) {
      const unsigned w = (uint16_t)((seven ? 2331 : 3264) * (code - 1)) >> 6;
      const unsigned m = (uint16_t)((a1 - a0) * (int)w);
      pal[code] = (uint8_t)(a0 + (int)(m >> 8));
   }
   if (!seven) {
      pal[6] = 0;
      pal[7] = 255;
   }
}

void fgl_s3tc_decode_image(GLenum format, const uint8_t *blocks, int w, int h,
                           uint8_t *rgba)
{
   const unsigned bytes = fgl_s3tc_block_bytes(format, NULL);
   const bool dxt1 = bytes == 8;
   const bool dxt1_alpha = format == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
   const int bw = (w + 3) / 4, bh = (h + 3) / 4;
   for (int by = 0; by < bh; by++) {
      for (int bx = 0; bx < bw; bx++) {
         const uint8_t *b = blocks + ((size_t)by * (size_t)bw + (size_t)bx) * bytes;
         const uint8_t *cb = dxt1 ? b : b + 8;
         uint8_t pal[4][4], apal[8];
         colour_palette(cb, dxt1, dxt1_alpha, pal);
         if (format == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT)
            alpha_palette(b, apal);
         const uint32_t codes = (uint32_t)cb[4] | (uint32_t)cb[5] << 8 |
                                (uint32_t)cb[6] << 16 | (uint32_t)cb[7] << 24;
         uint64_t acodes = 0;
         for (int k = 0; k < 6; k++)
            acodes |= (uint64_t)b[2 + k] << (8 * k);
         for (int j = 0; j < 4 && by * 4 + j < h; j++) {
            for (int i = 0; i < 4 && bx * 4 + i < w; i++) {
               const int t = j * 4 + i;
               uint8_t *o = rgba + 4 * ((size_t)(by * 4 + j) * (size_t)w + (size_t)(bx * 4 + i));
               const uint8_t *c = pal[(codes >> (2 * t)) & 3u];
               o[0] = c[0];
               o[1] = c[1];
               o[2] = c[2];
               o[3] = c[3];
               if (format == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT) {
                  const unsigned a = (b[t >> 1] >> (4 * (t & 1))) & 15u;
                  o[3] = (uint8_t)(a << 4 | a);
               } else if (format == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT) {
                  o[3] = apal[(acodes >> (3 * t)) & 7u];
               }
            }
         }
      }
   }
}
