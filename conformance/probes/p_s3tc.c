/* p_s3tc.c - S3TC texels as the oracle samples them (ORACLE-NOTES.md
 * "Compressed textures"): llvmpipe decodes each fetched texel from its
 * block (lp_bld_format_s3tc.c), glGetTexImage reads the same texels;
 *  - 565 colours expand by bit replication;
 *  - the thirds are c0 + (m >> 8) and c0 + ((m >> 7) & 255) with
 *    m = (85 * (c1 - c0)) mod 2^16, sums mod 256 (not (2*c0 + c1) / 3);
 *  - DXT1 with c0 <= c1: (c0 + c1 + 1) >> 1 and black (alpha 0 in
 *    DXT1 RGBA); DXT3 and DXT5 always four colours;
 *  - DXT3 alpha a << 4 | a; DXT5 alpha a0 + ((((a1 - a0) * w) mod 2^16)
 *    >> 8) with w = ((W * (code - 1)) mod 2^16) >> 6, W = 2331 (a0 > a1)
 *    or 3264 (a0 <= a1: codes 6 and 7 are 0 and 255);
 *  - glCompressedTexImage of a generic format: GL_COMPRESSED_ALPHA and
 *    GL_COMPRESSED_INTENSITY stay uncompressed (GL_ALPHA, GL_INTENSITY),
 *    GL_COMPRESSED_RGB becomes DXT1 RGB (the encoder: p_s3tc_encode).
 * 64x64 textures of random blocks of each format, drawn with NEAREST
 * and read back, against the C model. */
#include "probe.h"

#include <stdbool.h>

#define N 64
static unsigned char tex[N * N * 4];

static int e5(unsigned c) { return (int)(((c >> 8) & 0xf8) | ((c >> 13) & 7)); }
static int e6(unsigned c) { return (int)(((c >> 3) & 0xfc) | ((c >> 9) & 3)); }
static int e5b(unsigned c) { return (int)(((c << 3) & 0xf8) | ((c >> 2) & 7)); }
static int third(int v0, int v1, int k)
{
   unsigned m = (unsigned short)(85 * (v1 - v0));
   return (v0 + (int)(k ? ((m >> 7) & 255) : (m >> 8))) & 255;
}
static int alpha_lerp(int a0, int a1, int code, int W)
{
   unsigned w = ((unsigned short)(W * (code - 1))) >> 6;
   unsigned m = (unsigned short)((a1 - a0) * (int)w);
   return (a0 + (int)(m >> 8)) & 255;
}
/* type 0 DXT1 RGB, 1 DXT1 RGBA, 2 DXT3, 3 DXT5 */
static void model(const unsigned char *b, int i, int j, int type, int o[4])
{
   const unsigned char *cb = type >= 2 ? b + 8 : b;
   unsigned c0 = cb[0] | cb[1] << 8, c1 = cb[2] | cb[3] << 8;
   unsigned bits = cb[4] | cb[5] << 8 | cb[6] << 16 | (unsigned)cb[7] << 24;
   int code = (bits >> (2 * (j * 4 + i))) & 3;
   int p0[3] = { e5(c0), e6(c0), e5b(c0) }, p1[3] = { e5(c1), e6(c1), e5b(c1) };
   bool four = type > 1 || c0 > c1;
   o[3] = 255;
   for (int n = 0; n < 3; n++)
      o[n] = code == 0 ? p0[n] : code == 1 ? p1[n]
           : four ? third(p0[n], p1[n], code - 2)
           : code == 2 ? (p0[n] + p1[n] + 1) >> 1 : 0;
   if (!four && code == 3 && type == 1)
      o[3] = 0;
   if (type == 2) {
      int a = (b[(j * 4 + i) / 2] >> (4 * ((j * 4 + i) & 1))) & 15;
      o[3] = a | a << 4;
   }
   if (type == 3) {
      int a0 = b[0], a1 = b[1];
      unsigned long long ab = 0;
      for (int k = 0; k < 6; k++)
         ab |= (unsigned long long)b[2 + k] << (8 * k);
      int ac = (int)((ab >> (3 * (j * 4 + i))) & 7);
      o[3] = ac == 0 ? a0 : ac == 1 ? a1
           : a0 > a1 ? alpha_lerp(a0, a1, ac, 2331)
           : ac < 6 ? alpha_lerp(a0, a1, ac, 3264) : ac == 6 ? 0 : 255;
   }
}

int main(void)
{
   probe_init_ub(N, N);
   static const GLenum fmt[4] = { GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
      GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
      GL_COMPRESSED_RGBA_S3TC_DXT5_EXT };
   static const char *names[4] = { "DXT1 RGB", "DXT1 RGBA", "DXT3", "DXT5" };
   srand(5);
   glEnable(GL_TEXTURE_2D);
   glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   for (int t = 0; t < 4; t++) {
      const int bs = t < 2 ? 8 : 16, nb = (N / 4) * (N / 4);
      unsigned char *data = malloc((size_t)nb * bs);
      for (int i = 0; i < nb * bs; i++)
         data[i] = (unsigned char)rand();
      glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmt[t], N, N, 0, nb * bs, data);
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
      glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_QUADS);
      glTexCoord2f(0, 0); glVertex2f(0, 0);
      glTexCoord2f(1, 0); glVertex2f(N, 0);
      glTexCoord2f(1, 1); glVertex2f(N, N);
      glTexCoord2f(0, 1); glVertex2f(0, N);
      glEnd();
      glFinish();
      long bad_get = 0, bad_draw = 0;
      for (int y = 0; y < N; y++)
         for (int x = 0; x < N; x++) {
            int o[4];
            model(data + ((y / 4) * (N / 4) + x / 4) * bs, x & 3, y & 3, t, o);
            for (int c = 0; c < 4; c++) {
               bad_get += tex[4 * (y * N + x) + c] != o[c];
               bad_draw += g_buf[4 * (y * N + x) + c] != o[c];
            }
         }
      char what[96];
      snprintf(what, sizeof what, "%s: glGetTexImage channels off the model", names[t]);
      probe_expect(what, bad_get, 0);
      snprintf(what, sizeof what, "%s: sampled channels off the model", names[t]);
      probe_expect(what, bad_draw, 0);
      free(data);
   }
   static const GLenum gen[3] = { GL_COMPRESSED_ALPHA, GL_COMPRESSED_INTENSITY, GL_COMPRESSED_RGB };
   static const GLint want[3][2] = { { 0, GL_ALPHA }, { 0, GL_INTENSITY },
                                     { 1, GL_COMPRESSED_RGB_S3TC_DXT1_EXT } };
   for (int g = 0; g < 3; g++) {
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)gen[g], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
      GLint cmp = -1, ifmt = -1;
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &cmp);
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &ifmt);
      char what[96];
      snprintf(what, sizeof what, "generic 0x%x: GL_TEXTURE_COMPRESSED", gen[g]);
      probe_expect(what, cmp, want[g][0]);
      snprintf(what, sizeof what, "generic 0x%x: GL_TEXTURE_INTERNAL_FORMAT", gen[g]);
      probe_expect(what, ifmt, want[g][1]);
   }
   return probe_result();
}
