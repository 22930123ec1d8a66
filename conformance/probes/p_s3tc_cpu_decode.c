/* p_s3tc_cpu_decode.c - Mesa's CPU decoders, which the oracle's
 * glGetTexImage uses for a compressed image that is not in its texture
 * object's resource (ORACLE-NOTES.md "Compressed textures: LATC", cube
 * faces of mixed formats; libfixgl/main/teximage.c "Storage").  The model
 * is libfixgl's fgl_s3tc_decode_exact (main/texcompress_s3tc.c, compiled
 * in here): exact thirds and halves of the 8-bit colours, truncated, the
 * DXT3 nibble replicated, DXT5 alpha and LATC channels in exact sevenths
 * or fifths.
 * For each of DXT1 RGB, DXT1 RGBA, DXT3, DXT5, LATC1 and LATC2, random
 * 64x64 images (256 blocks each; colour blocks of both DXT1 modes, alpha
 * blocks of both orders) go on face +X of a cube map whose face -X then
 * gets another format, so +X keeps a resource of its own: its read-back
 * must equal the model channel for channel.  The same blocks on face -X
 * after the change (the object's resource) must read as the sampler
 * decodes them (fgl_s3tc_decode_image), and the probe counts the channels
 * where the two decoders differ. */
#include "probe.h"

#include <stdbool.h>
#include <stdint.h>

#include "main/texcompress_s3tc.c"

#define N 64
static unsigned char blocks[N * N], got[N * N * 4], want[N * N * 4];

static unsigned rs = 7;
static unsigned r8(void)
{
   rs = rs * 1103515245u + 12345u;
   return (rs >> 16) & 255u;
}

static const GLenum formats[] = { GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
                                  GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
                                  GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
                                  GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
                                  GL_COMPRESSED_LUMINANCE_LATC1_EXT,
                                  GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT };
static const char *const names[] = { "DXT1 RGB", "DXT1 RGBA", "DXT3", "DXT5", "LATC1", "LATC2" };

static long count_off(const unsigned char *a, const unsigned char *b, size_t n)
{
   long off = 0;
   for (size_t i = 0; i < n; i++)
      off += a[i] != b[i];
   return off;
}

int main(void)
{
   probe_init_ub(16, 16);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   long total = 0;
   for (size_t fi = 0; fi < sizeof formats / sizeof formats[0]; fi++) {
      const GLenum f = formats[fi];
      const unsigned bytes = fgl_stored_block_bytes(f);
      const int size = (int)(bytes * (N / 4) * (N / 4));
      long cpu_off = 0, sampler_off = 0, decoders_apart = 0;
      for (int round = 0; round < 4; round++) {
         for (int i = 0; i < size; i++)
            blocks[i] = (unsigned char)r8();
         GLuint t;
         glGenTextures(1, &t);
         glBindTexture(GL_TEXTURE_CUBE_MAP, t);
         glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, f, N, N, 0, size, blocks);
         /* another format on the next face: +X keeps its own resource */
         const GLenum other = f == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT
                                 ? GL_COMPRESSED_RGBA_S3TC_DXT3_EXT
                                 : GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
         static unsigned char zero[N * N];
         glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 0, other, N, N, 0, N * N, zero);
         glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, f, N, N, 0, size, blocks);
         memset(got, 0xcd, sizeof got);
         glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
         fgl_s3tc_decode_exact(f, blocks, N, N, want);
         /* glGetTexImage of a luminance image as GL_RGBA: (L, 0, 0, A) */
         if (fi >= 4)
            for (int i = 0; i < N * N; i++)
               want[4 * i + 1] = want[4 * i + 2] = 0;
         cpu_off += count_off(got, want, sizeof got);
         static unsigned char samp[N * N * 4];
         fgl_s3tc_decode_image(f, blocks, N, N, samp);
         if (fi >= 4)
            for (int i = 0; i < N * N; i++)
               samp[4 * i + 1] = samp[4 * i + 2] = 0;
         decoders_apart += count_off(samp, want, sizeof samp);
         /* +Y after the change: in the object's resource, the sampler's
          * decode (LATC2: the CPU's always) */
         memset(got, 0xcd, sizeof got);
         glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
         sampler_off += count_off(got, fi == 5 ? want : samp, sizeof got);
         glDeleteTextures(1, &t);
      }
      char what[128];
      snprintf(what, sizeof what, "%s: channels of 65536 off the CPU-decoder model", names[fi]);
      probe_expect(what, cpu_off, 0);
      snprintf(what, sizeof what, "%s: channels of 65536 off the sampler (object's resource)",
               names[fi]);
      probe_expect(what, sampler_off, 0);
      printf("     %s: the two decoders differ in %ld of 65536 channels\n", names[fi],
             decoders_apart);
      total += decoders_apart;
   }
   probe_expect("the decoders differ somewhere (the check can fail)", total > 0, 1);
   return probe_result();
}
