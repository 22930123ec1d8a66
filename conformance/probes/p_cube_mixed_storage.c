/* p_cube_mixed_storage.c - how the oracle reads back cube-map faces of
 * mixed compressed formats (modelled by libfixgl/main/teximage.c
 * "Storage", the decoders pinned by p_s3tc_cpu_decode; ORACLE-NOTES.md
 * "Compressed textures: LATC", which images glGetTexImage reads through
 * Mesa's CPU decoders):
 *  - a face specified in another format than the face before it gets new
 *    storage for the texture object, which the faces specified after it
 *    in that format share; the faces specified before the last such change
 *    keep storage of their own;
 *  - glGetTexImage reads a face of the object's current storage as a
 *    face of a one-format cube map is read (the sampler's decode), and a
 *    face of an older storage through Mesa's CPU decoders, which round
 *    some DXT1 texels one step apart.
 * For each pattern of six faces (D: DXT1 RGBA blocks, X: DXT1 RGB blocks,
 * L: GL_COMPRESSED_LUMINANCE (LATC1) from RGBA data), every face is read
 * back and compared with the same data read back from a cube map whose
 * six faces all have that face's format; the faces that differ are
 * exactly those before the last format change. */
#include "probe.h"

#include <stdint.h>

static unsigned rs = 1;
static unsigned r8(void)
{
   rs = rs * 1103515245u + 12345u;
   return (rs >> 16) & 255u;
}

static unsigned char blocks[6][32], images[6][8 * 8 * 4];

static void specify(GLenum target, char kind, int f)
{
   if (kind == 'L')
      glTexImage2D(target, 0, GL_COMPRESSED_LUMINANCE, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   images[f]);
   else
      glCompressedTexImage2D(target, 0,
                             kind == 'X' ? GL_COMPRESSED_RGB_S3TC_DXT1_EXT
                                         : GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
                             8, 8, 0, 32, blocks[f]);
}

/* bit f set: face f reads back other than in a one-format cube */
static unsigned run(const char *pat)
{
   static unsigned char got[8 * 8 * 4], ref[8 * 8 * 4];
   GLuint t[2];
   glGenTextures(2, t);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   glBindTexture(GL_TEXTURE_CUBE_MAP, t[0]);
   for (int f = 0; f < 6; f++)
      specify(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, pat[f], f);
   unsigned mask = 0;
   for (int f = 0; f < 6; f++) {
      glBindTexture(GL_TEXTURE_CUBE_MAP, t[0]);
      glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
      glBindTexture(GL_TEXTURE_CUBE_MAP, t[1]);
      for (int g = 0; g < 6; g++)
         specify(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)g, pat[f], f);
      glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA, GL_UNSIGNED_BYTE, ref);
      if (memcmp(got, ref, sizeof got) != 0)
         mask |= 1u << f;
   }
   glDeleteTextures(2, t);
   return mask;
}

/* the faces before the last format change */
static unsigned model(const char *pat)
{
   int last = 0;
   for (int f = 1; f < 6; f++)
      if (pat[f] != pat[f - 1])
         last = f;
   return (1u << last) - 1u;
}

int main(void)
{
   probe_init_ub(16, 16);
   for (int f = 0; f < 6; f++) {
      for (int i = 0; i < 32; i++)
         blocks[f][i] = (unsigned char)r8();
      for (int i = 0; i < 8 * 8 * 4; i++)
         images[f][i] = (unsigned char)r8();
   }
   static const char *const pats[] = { "DDDDDD", "DLDDDD", "LDDDDD", "DDDDDL", "DDLDDD",
                                       "DXDDDD", "DLLDDD", "DDDLDX" };
   int off = 0;
   for (size_t p = 0; p < sizeof pats / sizeof pats[0]; p++) {
      const unsigned got = run(pats[p]), want = model(pats[p]);
      printf("%s: faces read another way 0x%02x, model 0x%02x\n", pats[p], got, want);
      /* a face whose CPU and sampler decodes happen to agree reads the
       * same either way: only faces the model keeps may differ */
      off += (got & ~want) != 0;
   }
   probe_expect("patterns with a face of the current storage read another way", off, 0);
   probe_expect("pattern DLDDDD: faces 0 and 1 read through the CPU decoders", run("DLDDDD"), 3);
   return probe_result();
}
