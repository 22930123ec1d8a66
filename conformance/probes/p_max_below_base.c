/* p_max_below_base.c - an oracle defect: GL_TEXTURE_MAX_LEVEL below
 * GL_TEXTURE_BASE_LEVEL with a non-mipmap filter.  The texture is complete
 * and GL samples its base level; llvmpipe gets a sampler view with no
 * level and reads stale offsets (zeros in a fresh context): the texel is
 * row 0 of level 0's storage, zeros when level 0 was never specified
 * (ORACLE-NOTES.md "Texture sampling: the float SoA path and the
 * general LOD").  fixgl samples the base level; this probe shows the
 * oracle's defect is still there. */
#include "probe.h"

static long texel_drawn(void)
{
   clear0();
   glBegin(GL_QUADS);
   glTexCoord2f(0, 0); glVertex2f(0, 0);
   glTexCoord2f(1, 0); glVertex2f(8, 0);
   glTexCoord2f(1, 1); glVertex2f(8, 8);
   glTexCoord2f(0, 1); glVertex2f(0, 8);
   glEnd();
   glFinish();
   unsigned char *p = px(4, 4);
   return (long)p[0] << 24 | p[1] << 16 | p[2] << 8 | p[3];
}

int main(void)
{
   probe_init_ub(8, 8);
   unsigned char level1[2 * 2 * 4];
   for (int i = 0; i < 4; i++) {
      level1[4 * i + 0] = 200;
      level1[4 * i + 1] = 100;
      level1[4 * i + 2] = 50;
      level1[4 * i + 3] = 255;
   }
   glEnable(GL_TEXTURE_2D);
   glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
   glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, level1);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
   probe_expect("MAX_LEVEL 0 below BASE_LEVEL 1, level 0 never given: texel (defect: 0)",
                texel_drawn(), 0);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
   probe_expect("MAX_LEVEL 1: the base level's texel", texel_drawn(),
                (long)200 << 24 | 100 << 16 | 50 << 8 | 255);
   return probe_result();
}
