/* p_latc.c - the oracle's LATC storage of GL_COMPRESSED_LUMINANCE and
 * GL_COMPRESSED_LUMINANCE_ALPHA (ORACLE-NOTES.md "Compressed textures:
 * LATC"): llvmpipe stores them as LATC1 / LATC2, Mesa's texstore stores
 * the data as into an L8 / L8A8 image and compresses each channel with
 * its RGTC encoder, and the sampler decodes each channel as a DXT5 alpha
 * block.  The model is libfixgl's own encoder and decoder
 * (main/texcompress_s3tc.c, compiled in here).  Checked, byte for byte
 * through glGetCompressedTexImage and texel for texel through
 * glGetTexImage (which samples):
 *  - the internal format reported (the LATC enums), GL_TEXTURE_COMPRESSED
 *    and GL_TEXTURE_COMPRESSED_IMAGE_SIZE;
 *  - glTexImage2D of random, ramp, flat-block and few-level images, sizes
 *    1x1 to 64x64 and NPOT; images narrower than 4 texels and 2 or more
 *    high are counted apart (the encoder's uninitialised code arrays);
 *  - a block of one value leaves its second byte as the storage held it;
 *  - glTexSubImage2D on block boundaries and to the edge;
 *  - GL_GENERATE_MIPMAP (decoded base, truncated box filter, each level
 *    compressed); glCopyTexImage2D (the buffer's red as luminance);
 *  - the decoder: glGetTexImage of random blocks given through
 *    glCompressedTexImage2D with the LATC enums (the oracle lists
 *    GL_EXT_texture_compression_latc; fixgl does not). */
#include "probe.h"

#include <stdbool.h>
#include <stdint.h>

#include "main/texcompress_s3tc.c"

#define MAXN 64
static const GLenum generic[2] = { GL_COMPRESSED_LUMINANCE, GL_COMPRESSED_LUMINANCE_ALPHA };
static const GLenum latc[2] = { GL_COMPRESSED_LUMINANCE_LATC1_EXT,
                                GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT };
static unsigned char src[MAXN * MAXN * 4], data[MAXN * MAXN * 4];
static unsigned char got[MAXN * MAXN * 2], want[MAXN * MAXN * 2];
static unsigned char tex_got[MAXN * MAXN * 4], tex_want[MAXN * MAXN * 4];

static unsigned rng_state = 1;
static int rnd(void)
{
   rng_state = rng_state * 1103515245u + 12345u;
   return (int)((rng_state >> 16) & 255);
}

/* kind 0 random, 1 ramps, 2 flat 2x2 patches (blocks of one value),
 * 3 three levels with 0 and 255, 4 values close together */
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
                          : (x * 255 / (w > 1 ? w - 1 : 1) + y * 3) & 255;
               break;
            case 2: v = c == 3 ? 200 : ((x / 4 + y / 4) & 1 ? 90 : 17); break;
            case 3: v = (rnd() % 3) * 127 + (rnd() & 1); break;
            default: v = 120 + rnd() % 7; break;
            }
            src[4 * (y * w + x) + c] = (unsigned char)v;
         }
}

static int bb(int f) { return f ? 16 : 8; }
static int image_bytes(int f, int w, int h) { return ((w + 3) / 4) * ((h + 3) / 4) * bb(f); }

/* the RGBA8 texels an L8 / L8A8 image of RGBA bytes holds */
static void as_luminance(int f, const unsigned char *rgba, int n, unsigned char *out)
{
   for (int i = 0; i < n; i++) {
      out[4 * i] = out[4 * i + 1] = out[4 * i + 2] = rgba[4 * i];
      out[4 * i + 3] = f ? rgba[4 * i + 3] : 255;
   }
}

static void model_blocks(int f, const unsigned char *rgba, int w, int h, bool keep)
{
   if (!keep)
      memset(want, 0, sizeof want);
   as_luminance(f, rgba, w * h, data);
   fgl_s3tc_encode_image(latc[f], data, w, h, want, (size_t)((w + 3) / 4) * (size_t)bb(f));
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
   fgl_s3tc_decode_image(latc[f], got, w, h, tex_got);
   fgl_s3tc_decode_image(latc[f], want, w, h, tex_want);
   long bad = 0;
   for (int i = 0; i < w * h * 4; i++)
      bad += tex_got[i] != tex_want[i];
   return bad;
}

/* the same for the image's first row alone (tex_got, tex_want as
 * texels_off left them): the garbage codes outside an image narrower than
 * 4 spill only into later texels' codes */
static long first_row_off(int w)
{
   long bad = 0;
   for (int i = 0; i < w * 4; i++)
      bad += tex_got[i] != tex_want[i];
   return bad;
}

/* what glGetTexImage reads of an image: LATC1 the sampler's texels, LATC2
 * Mesa's CPU decoder's (exact sevenths and fifths) */
static void readback_decode(int f, const unsigned char *blocks, int w, int h, unsigned char *out)
{
   if (f)
      fgl_latc_decode_exact(latc[f], blocks, w, h, out);
   else
      fgl_s3tc_decode_image(latc[f], blocks, w, h, out);
}

/* glGetTexImage (the sampler's texels) against the model's decoding of
 * the blocks glGetCompressedTexImage returns */
static long sampled_off(int f, int level, int w, int h)
{
   static unsigned char img[MAXN * MAXN * 2];
   glGetTexImage(GL_TEXTURE_2D, level, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, img);
   readback_decode(f, got, w, h, tex_got);
   long bad = 0;
   for (int i = 0; i < w * h; i++) {
      bad += img[2 * i] != tex_got[4 * i];
      bad += img[2 * i + 1] != tex_got[4 * i + 3];
   }
   return bad;
}

static void fresh_texture(void)
{
   static GLuint t;
   if (t)
      glDeleteTextures(1, &t);
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
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

   /* what the generic formats become */
   for (int f = 0; f < 2; f++) {
      fresh_texture();
      make_image(0, 6, 10);
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[f], 6, 10, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
      GLint v = 0;
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v);
      snprintf(what, sizeof what, "0x%x: internal format", generic[f]);
      probe_expect(what, v, (long)latc[f]);
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &v);
      snprintf(what, sizeof what, "0x%x: GL_TEXTURE_COMPRESSED", generic[f]);
      probe_expect(what, v, 1);
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v);
      snprintf(what, sizeof what, "0x%x: image size", generic[f]);
      probe_expect(what, v, image_bytes(f, 6, 10));
   }

   /* glTexImage2D */
   static const int sizes[][2] = { { 1, 1 }, { 4, 1 }, { 4, 3 }, { 5, 3 }, { 4, 4 }, { 7, 9 },
                                   { 8, 8 }, { 13, 6 }, { 16, 16 }, { 33, 17 }, { 64, 64 },
                                   { 2, 2 }, { 3, 5 }, { 2, 3 }, { 3, 2 }, { 1, 3 } };
   for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
      const int w = sizes[s][0], h = sizes[s][1];
      const bool spill = w < 4 && h >= 2;
      for (int f = 0; f < 2; f++) {
         long bytes_bad = 0, tex_bad = 0, samp_bad = 0, row_bad = 0;
         for (int kind = 0; kind < 5; kind++) {
            make_image(kind, w, h);
            fresh_texture();
            glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[f], w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                         src);
            read_blocks(0);
            model_blocks(f, src, w, h, false);
            if (w >= 4 && h >= 4)
               bytes_bad += blocks_off(f, w, h);
            tex_bad += texels_off(f, w, h);
            row_bad += first_row_off(w);
            samp_bad += sampled_off(f, 0, w, h);
         }
         if (w >= 4 && h >= 4) {
            snprintf(what, sizeof what, "glTexImage2D %dx%d format %d: bytes off", w, h, f);
            probe_expect(what, bytes_bad, 0);
         }
         snprintf(what, sizeof what, "glTexImage2D %dx%d format %d: texels off%s", w, h, f,
                  spill ? " (first block partial in x: not checked)" : "");
         if (spill)
            printf("info %s: %ld\n", what, tex_bad);
         else
            probe_expect(what, tex_bad, 0);
         snprintf(what, sizeof what, "glTexImage2D %dx%d format %d: first-row texels off", w, h, f);
         probe_expect(what, row_bad, 0);
         snprintf(what, sizeof what, "glTexImage2D %dx%d format %d: sampled texels off", w, h, f);
         probe_expect(what, samp_bad, 0);
      }
   }

   /* narrow images of one value a block: written without codes, defined */
   static const int narrow[][2] = { { 1, 3 }, { 2, 2 }, { 3, 5 }, { 2, 9 } };
   for (size_t s = 0; s < sizeof narrow / sizeof narrow[0]; s++) {
      const int w = narrow[s][0], h = narrow[s][1];
      for (int f = 0; f < 2; f++) {
         make_image(2, w, h);
         fresh_texture();
         glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[f], w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                      src);
         read_blocks(0);
         model_blocks(f, src, w, h, false);
         snprintf(what, sizeof what, "%dx%d of one value a block, format %d: bytes off", w, h, f);
         probe_expect(what, blocks_off(f, w, h), 0);
         snprintf(what, sizeof what, "%dx%d of one value a block, format %d: sampled texels off",
                  w, h, f);
         probe_expect(what, sampled_off(f, 0, w, h), 0);
      }
   }

   /* the storage kept: a block of one value leaves byte 1 as it was */
   for (int f = 0; f < 2; f++) {
      fresh_texture();
      make_image(0, 8, 8);
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[f], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
      model_blocks(f, src, 8, 8, false);
      make_image(2, 8, 8);
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[f], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
      model_blocks(f, src, 8, 8, true);
      read_blocks(0);
      snprintf(what, sizeof what, "format %d over the same size: bytes off", f);
      probe_expect(what, blocks_off(f, 8, 8), 0);
      snprintf(what, sizeof what, "format %d one-value block keeps byte 1 (non-zero here)", f);
      probe_expect(what, got[1] != 0, 1);
   }

   /* glTexSubImage2D on block boundaries and to the edge */
   for (int f = 0; f < 2; f++) {
      fresh_texture();
      make_image(1, 13, 10);
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[f], 13, 10, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   src);
      model_blocks(f, src, 13, 10, false);
      static unsigned char sub[9 * 6 * 4], subl[9 * 6 * 4];
      for (size_t i = 0; i < sizeof sub; i++)
         sub[i] = (unsigned char)rnd();
      glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, sub);
      const size_t row = (size_t)4 * (size_t)bb(f);
      as_luminance(f, sub, 8 * 4, subl);
      fgl_s3tc_encode_image(latc[f], subl, 8, 4, want + row + (size_t)bb(f), row);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 4, 5, 6, GL_RGBA, GL_UNSIGNED_BYTE, sub + 16);
      as_luminance(f, sub + 16, 5 * 6, subl);
      fgl_s3tc_encode_image(latc[f], subl, 5, 6, want + row + 2 * (size_t)bb(f), row);
      read_blocks(0);
      snprintf(what, sizeof what, "glTexSubImage2D format %d: bytes off", f);
      probe_expect(what, blocks_off(f, 13, 10), 0);
   }

   /* GL_GENERATE_MIPMAP: the base as glGetTexImage reads it */
   for (int m = 0; m < 4; m++) {
      static unsigned char chain[2][MAXN * MAXN * 4];
      fresh_texture();
      const int kind = m < 2 ? 0 : 1, f = m & 1;
      make_image(kind, 24, 16);
      glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
      glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[f], 24, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   src);
      model_blocks(f, src, 24, 16, false);
      readback_decode(f, want, 24, 16, chain[0]);
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
         memset(want, 0, sizeof want);
         fgl_s3tc_encode_image(latc[f], d, w, h, want, (size_t)((w + 3) / 4) * (size_t)bb(f));
         read_blocks(l);
         if (w >= 4 && h >= 4) {
            snprintf(what, sizeof what, "GL_GENERATE_MIPMAP format %d kind %d level %d (%dx%d): bytes off",
                     f, kind, l, w, h);
            probe_expect(what, blocks_off(f, w, h), 0);
         } else if (w >= 4 || h < 2) {
            snprintf(what, sizeof what,
                     "GL_GENERATE_MIPMAP format %d kind %d level %d (%dx%d): texels off", f, kind, l, w, h);
            probe_expect(what, texels_off(f, w, h), 0);
         }
         W = w;
         H = h;
      }
   }

   /* glCopyTexImage2D from the colour buffer */
   glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
   glClear(GL_COLOR_BUFFER_BIT);
   glBegin(GL_TRIANGLES);
   glColor4f(1, 0, 0, 0.1f); glVertex2f(1, 1);
   glColor4f(0, 1, 0, 0.5f); glVertex2f(30, 4);
   glColor4f(0.5f, 0, 1, 1); glVertex2f(12, 29);
   glEnd();
   glFinish();
   static unsigned char fb[32 * 32 * 4];
   glReadPixels(2, 3, 20, 18, GL_RGBA, GL_UNSIGNED_BYTE, fb);
   for (int f = 0; f < 2; f++) {
      fresh_texture();
      glCopyTexImage2D(GL_TEXTURE_2D, 0, generic[f], 2, 3, 20, 18, 0);
      model_blocks(f, fb, 20, 18, false);
      read_blocks(0);
      snprintf(what, sizeof what, "glCopyTexImage2D format %d: bytes off", f);
      probe_expect(what, blocks_off(f, 20, 18), 0);
   }

   /* glGetTexImage's decoder: random blocks through the LATC enums */
   for (int f = 0; f < 2; f++) {
      fresh_texture();
      const int n = image_bytes(f, 16, 16);
      for (int i = 0; i < n; i++)
         got[i] = (unsigned char)rnd();
      /* both orders of the end values */
      for (int b = 0; b < n; b += 8)
         if ((b / 8) % 3 == 0) {
            const unsigned char t = got[b];
            got[b] = got[b + 1] > t ? got[b + 1] : t;
            got[b + 1] = got[b + 1] > t ? t : got[b + 1];
         }
      glCompressedTexImage2D(GL_TEXTURE_2D, 0, latc[f], 16, 16, 0, n, got);
      snprintf(what, sizeof what, "random LATC%d blocks: sampled texels off", f + 1);
      probe_expect(what, sampled_off(f, 0, 16, 16), 0);
   }
   /* the sampler: a 16x16 image of random blocks drawn 1:1 with NEAREST */
   for (int f = 0; f < 2; f++) {
      fresh_texture();
      const int n = image_bytes(f, 16, 16);
      for (int i = 0; i < n; i++)
         got[i] = (unsigned char)rnd();
      for (int b = 0; b < n; b += 8)
         if ((b / 8) % 3 == 0) {
            const unsigned char t = got[b];
            got[b] = got[b + 1] > t ? got[b + 1] : t;
            got[b + 1] = got[b + 1] > t ? t : got[b + 1];
         }
      glCompressedTexImage2D(GL_TEXTURE_2D, 0, latc[f], 16, 16, 0, n, got);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
      glEnable(GL_TEXTURE_2D);
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_QUADS);
      glTexCoord2f(0, 0); glVertex2f(0, 0);
      glTexCoord2f(1, 0); glVertex2f(16, 0);
      glTexCoord2f(1, 1); glVertex2f(16, 16);
      glTexCoord2f(0, 1); glVertex2f(0, 16);
      glEnd();
      glDisable(GL_TEXTURE_2D);
      static unsigned char px[16 * 16 * 4];
      glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, px);
      fgl_s3tc_decode_image(latc[f], got, 16, 16, tex_got);
      long bad = 0;
      for (int i = 0; i < 16 * 16 * 4; i++)
         bad += px[i] != tex_got[i];
      snprintf(what, sizeof what, "random LATC%d blocks drawn with NEAREST: texels off", f + 1);
      probe_expect(what, bad, 0);
   }
   probe_expect("GL errors", (long)glGetError(), 0);
   return probe_result();
}
