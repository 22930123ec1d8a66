/* p_s3tc_encode.c - the oracle's S3TC encoder (ORACLE-NOTES.md
 * "Compressed textures: the encoder"): uncompressed data given to an
 * S3TC (or generic RGB/RGBA) image goes through Mesa's texstore, which
 * converts it to RGB8/RGBA8 and compresses it with the libtxc_dxtn
 * algorithm.  The model is libfixgl's own encoder (main/texcompress_s3tc.c,
 * compiled in here), so this probe fails when the oracle and fixgl's
 * encoder part.  Checked, byte for byte through glGetCompressedTexImage:
 *  - glTexImage2D of random images, gradients, alpha edges and three-level
 *    alphas, all four formats, sizes 4x4 to 64x64 and NPOT (7x9, 13x6,
 *    33x17), DXT1 also 1x1, 2x2, 3x5, 5x3;
 *  - DXT3/DXT5 images narrower or shorter than a block: the texels only
 *    (the oracle's encoder reads uninitialised stack memory for the texels
 *    of its first block that lie outside the image: DXT3 alpha nibbles
 *    and DXT5 alpha codes there are garbage, and a garbage DXT5 code can
 *    spill into the next texel's code: DXT5 images under 4 texels wide
 *    and 2 or more high are left out);
 *  - a DXT5 block of one alpha leaves its second byte as the storage held
 *    it (zero for new storage, the previous image's for an image of the
 *    same size and format);
 *  - glTexSubImage2D at block boundaries and to the edge;
 *  - GL_GENERATE_MIPMAP: the base's decoded texels, box-filtered with
 *    truncation along an uncompressed chain, each level compressed;
 *  - GL_COMPRESSED_RGB / GL_COMPRESSED_RGBA stored as DXT1 RGB / DXT5;
 *  - glCopyTexImage2D: the colour buffer's bytes compressed;
 *  - a GL_FLOAT source compresses the bytes an RGBA8 image of the same
 *    data holds. */
#include "probe.h"

#include <stdbool.h>
#include <stdint.h>

#include "main/texcompress_s3tc.c"

#define MAXN 64
static const GLenum fmts[4] = { GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
   GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
   GL_COMPRESSED_RGBA_S3TC_DXT5_EXT };
static unsigned char src[MAXN * MAXN * 4], got[MAXN * MAXN * 2], want[MAXN * MAXN * 2];
static unsigned char tex_got[MAXN * MAXN * 4], tex_want[MAXN * MAXN * 4];

static unsigned rng_state = 1;
static int rnd(void)
{
   rng_state = rng_state * 1103515245u + 12345u;
   return (int)((rng_state >> 16) & 255);
}

/* kind 0 random, 1 gradients, 2 random colours with an alpha edge, 3
 * alpha in three levels over colour bands */
static void make_image(int kind, int w, int h)
{
   for (int y = 0; y < h; y++)
      for (int x = 0; x < w; x++)
         for (int c = 0; c < 4; c++) {
            int v;
            switch (kind) {
            case 0: v = rnd(); break;
            case 1:
               v = c == 3 ? y * 255 / (h > 1 ? h - 1 : 1)
                          : (x * 255 / (w > 1 ? w - 1 : 1) + c * 40 + y * 3) & 255;
               break;
            case 2: v = c == 3 ? (x < w / 2 ? 0 : 255) : rnd(); break;
            default: v = c == 3 ? (rnd() % 3) * 127 : (y * 30 + c * 50) & 255; break;
            }
            src[4 * (y * w + x) + c] = (unsigned char)v;
         }
}

static int block_bytes(int f) { return f < 2 ? 8 : 16; }
static int image_bytes(int f, int w, int h) { return ((w + 3) / 4) * ((h + 3) / 4) * block_bytes(f); }

/* the model's blocks of `rgba` into want (zeroed storage first unless
 * `keep`) */
static void model_blocks(int f, const unsigned char *rgba, int w, int h, bool keep)
{
   if (!keep)
      memset(want, 0, sizeof want);
   fgl_s3tc_encode_image(fmts[f], rgba, w, h, want, (size_t)((w + 3) / 4) * block_bytes(f));
}

static long blocks_off(int f, int w, int h)
{
   long bad = 0;
   for (int i = 0; i < image_bytes(f, w, h); i++)
      bad += got[i] != want[i];
   return bad;
}

static long texels_off(int f, int w, int h)
{
   fgl_s3tc_decode_image(fmts[f], got, w, h, tex_got);
   fgl_s3tc_decode_image(fmts[f], want, w, h, tex_want);
   long bad = 0;
   for (int i = 0; i < w * h * 4; i++)
      bad += tex_got[i] != tex_want[i];
   return bad;
}

static GLuint fresh_texture(void)
{
   static GLuint t;
   if (t)
      glDeleteTextures(1, &t);
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   return t;
}

static void read_blocks(int level)
{
   memset(got, 0xcc, sizeof got);
   glGetCompressedTexImage(GL_TEXTURE_2D, level, got);
}

int main(void)
{
   probe_init_ub(32, 32);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   char what[160];

   /* glTexImage2D */
   static const int sizes[][2] = { { 1, 1 }, { 2, 2 }, { 3, 5 }, { 5, 3 }, { 4, 4 }, { 7, 9 },
                                   { 8, 8 }, { 13, 6 }, { 16, 16 }, { 33, 17 }, { 64, 64 } };
   for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
      const int w = sizes[s][0], h = sizes[s][1];
      long bytes_bad[4] = { 0 }, tex_bad[4] = { 0 };
      int bytes_n[4] = { 0 }, tex_n[4] = { 0 };
      for (int f = 0; f < 4; f++) {
         const bool first_full = w >= 4 && h >= 4;
         if (f == 3 && w < 4 && h >= 2)
            continue;   /* garbage alpha codes may spill into texels */
         for (int kind = 0; kind < 4; kind++) {
            make_image(kind, w, h);
            fresh_texture();
            glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                         src);
            read_blocks(0);
            model_blocks(f, src, w, h, false);
            if (f < 2 || first_full) {
               bytes_bad[f] += blocks_off(f, w, h);
               bytes_n[f]++;
            }
            tex_bad[f] += texels_off(f, w, h);
            tex_n[f]++;
         }
      }
      for (int f = 0; f < 4; f++) {
         if (bytes_n[f]) {
            snprintf(what, sizeof what, "glTexImage2D %dx%d format %d: bytes off (%d images)", w,
                     h, f, bytes_n[f]);
            probe_expect(what, bytes_bad[f], 0);
         }
         if (tex_n[f]) {
            snprintf(what, sizeof what, "glTexImage2D %dx%d format %d: decoded texels off", w, h,
                     f);
            probe_expect(what, tex_bad[f], 0);
         }
      }
   }

   /* the storage kept: DXT5 8x8 twice, the second of one-alpha blocks */
   fresh_texture();
   make_image(1, 8, 8);
   glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[3], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
   model_blocks(3, src, 8, 8, false);
   make_image(2, 8, 8);
   glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[3], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
   model_blocks(3, src, 8, 8, true);
   read_blocks(0);
   probe_expect("DXT5 image over one of the same size: bytes off", blocks_off(3, 8, 8), 0);
   probe_expect("DXT5 one-alpha block keeps byte 1 (non-zero here)", got[1] != 0, 1);

   /* glTexSubImage2D on block boundaries and to the edge */
   for (int f = 0; f < 4; f++) {
      fresh_texture();
      make_image(0, 13, 10);
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], 13, 10, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
      model_blocks(f, src, 13, 10, false);
      static unsigned char sub[9 * 6 * 4];
      for (size_t i = 0; i < sizeof sub; i++)
         sub[i] = (unsigned char)rnd();
      /* 8x4 at (4, 4), then 5x6 at (8, 4) to both edges */
      glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, sub);
      const size_t row = (size_t)4 * (size_t)block_bytes(f);
      fgl_s3tc_encode_image(fmts[f], sub, 8, 4, want + row + (size_t)block_bytes(f), row);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 4, 5, 6, GL_RGBA, GL_UNSIGNED_BYTE, sub + 16);
      fgl_s3tc_encode_image(fmts[f], sub + 16, 5, 6, want + row + 2 * (size_t)block_bytes(f),
                            row);
      read_blocks(0);
      snprintf(what, sizeof what, "glTexSubImage2D format %d: bytes off", f);
      probe_expect(what, blocks_off(f, 13, 10), 0);
   }

   /* GL_GENERATE_MIPMAP */
   for (int f = 0; f < 4; f++) {
      static unsigned char chain[2][MAXN * MAXN * 4];
      fresh_texture();
      make_image(f & 1 ? 1 : 0, 24, 16);
      glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], 24, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
      /* the base's texels as the sampler decodes them */
      model_blocks(f, src, 24, 16, false);
      fgl_s3tc_decode_image(fmts[f], want, 24, 16, chain[0]);
      int W = 24, H = 16;
      for (int l = 1; W > 1 || H > 1; l++) {
         const int w = W > 1 ? W / 2 : 1, h = H > 1 ? H / 2 : 1;
         const int cs = W > w, rs = H > h;
         unsigned char *d = chain[l & 1];
         const unsigned char *s = chain[(l - 1) & 1];
         for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
               for (int c = 0; c < 4; c++) {
                  const int x0 = x * (cs + 1), x1 = x0 + cs, y0 = y * (rs + 1), y1 = y0 + rs;
                  d[4 * (y * w + x) + c] =
                     (unsigned char)((s[4 * (y0 * W + x0) + c] + s[4 * (y0 * W + x1) + c] +
                                      s[4 * (y1 * W + x0) + c] + s[4 * (y1 * W + x1) + c]) /
                                     4);
               }
         model_blocks(f, d, w, h, false);
         read_blocks(l);
         if (f < 2 || (w >= 4 && h >= 4)) {
            snprintf(what, sizeof what, "GL_GENERATE_MIPMAP format %d level %d (%dx%d): bytes off",
                     f, l, w, h);
            probe_expect(what, blocks_off(f, w, h), 0);
         } else if (f == 2 || w >= 4 || h < 2) {
            snprintf(what, sizeof what,
                     "GL_GENERATE_MIPMAP format %d level %d (%dx%d): texels off", f, l, w, h);
            probe_expect(what, texels_off(f, w, h), 0);
         }
         W = w;
         H = h;
      }
   }

   /* the generic formats */
   static const GLenum generic[2] = { GL_COMPRESSED_RGB, GL_COMPRESSED_RGBA };
   static const int generic_f[2] = { 0, 3 };
   for (int g = 0; g < 2; g++) {
      fresh_texture();
      make_image(2, 16, 12);
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[g], 16, 12, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   src);
      GLint ifmt = 0;
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &ifmt);
      snprintf(what, sizeof what, "generic 0x%x: internal format", generic[g]);
      probe_expect(what, ifmt, (long)fmts[generic_f[g]]);
      model_blocks(generic_f[g], src, 16, 12, false);
      read_blocks(0);
      snprintf(what, sizeof what, "generic 0x%x: bytes off", generic[g]);
      probe_expect(what, blocks_off(generic_f[g], 16, 12), 0);
   }

   /* glCopyTexImage2D from the colour buffer */
   glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
   glClear(GL_COLOR_BUFFER_BIT);
   glBegin(GL_TRIANGLES);
   glColor4f(1, 0, 0, 0.1f); glVertex2f(1, 1);
   glColor4f(0, 1, 0, 0.5f); glVertex2f(30, 4);
   glColor4f(0, 0, 1, 1); glVertex2f(12, 29);
   glEnd();
   glFinish();
   static unsigned char fb[32 * 32 * 4];
   glReadPixels(2, 3, 20, 18, GL_RGBA, GL_UNSIGNED_BYTE, fb);
   for (int f = 0; f < 4; f++) {
      fresh_texture();
      glCopyTexImage2D(GL_TEXTURE_2D, 0, fmts[f], 2, 3, 20, 18, 0);
      model_blocks(f, fb, 20, 18, false);
      read_blocks(0);
      snprintf(what, sizeof what, "glCopyTexImage2D format %d: bytes off", f);
      probe_expect(what, blocks_off(f, 20, 18), 0);
   }

   /* a float source: the bytes of an RGBA8 image of the same data */
   static float fsrc[16 * 8 * 4];
   for (int i = 0; i < 16 * 8 * 4; i++)
      fsrc[i] = (float)rnd() / 255.0f + (float)(rnd() - 128) / 70000.0f;
   fresh_texture();
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 8, 0, GL_RGBA, GL_FLOAT, fsrc);
   glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
   for (int f = 0; f < 4; f++) {
      fresh_texture();
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], 16, 8, 0, GL_RGBA, GL_FLOAT, fsrc);
      model_blocks(f, src, 16, 8, false);
      read_blocks(0);
      snprintf(what, sizeof what, "float source format %d: bytes off", f);
      probe_expect(what, blocks_off(f, 16, 8), 0);
   }
   probe_expect("GL errors", (long)glGetError(), 0);
   return probe_result();
}
