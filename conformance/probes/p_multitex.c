/* p_multitex.c - the texture units' chain (ORACLE-NOTES.md "Texture
 * sampling and environment"): each unit's environment reads the previous
 * unit's result as the float the combiner computed, never rounded to the
 * colour buffer's 8 bits between units; REPLACE, MODULATE and INTERPOLATE
 * are not saturated, ADD and SUBTRACT are (max(x, 0), then min(., 1)).
 * Two and three units on 1x1 RGBA8 textures (texel bytes b read as
 * (float)b * (float)(1/255)), a flat colour of exact floats, a float
 * colour buffer, exact compare of every channel's bits. */
#include "probe.h"

#include <stdint.h>

#define W 4
#define H 4
static float buf[W * H * 4];

static uint32_t bits(float f)
{
   uint32_t u;
   memcpy(&u, &f, 4);
   return u;
}

static float texel(int b)
{
   return (float)b * (float)(1.0 / 255.0);
}

static void unit_texture(int unit, const unsigned char rgba[4], GLenum env)
{
   glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
   glBindTexture(GL_TEXTURE_2D, (GLuint)(unit + 1));
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env);
   glEnable(GL_TEXTURE_2D);
}

static void draw(const float color[4])
{
   glClear(GL_COLOR_BUFFER_BIT);
   glColor4fv(color);
   glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
   glFinish();
}

static void expect_pixel(const char *what, const float want[4])
{
   const float *p = &buf[((H / 2) * W + W / 2) * 4];
   char name[128];
   for (int c = 0; c < 4; c++) {
      snprintf(name, sizeof name, "%s, channel %d (float bits)", what, c);
      probe_expect(name, (long)bits(p[c]), (long)bits(want[c]));
   }
}

int main(void)
{
   probe_init_float(buf, W, H);
   glShadeModel(GL_FLAT);
   const float color[4] = { 0.75f, 0.5f, 0.625f, 0.875f };
   static const unsigned char t0[4] = { 201, 77, 250, 130 };
   static const unsigned char t1[4] = { 99, 254, 13, 180 };
   static const unsigned char t2[4] = { 240, 3, 128, 255 };
   float want[4];

   /* MODULATE, MODULATE: (T0 * C) * T1, no rounding to 8 bits between */
   unit_texture(0, t0, GL_MODULATE);
   unit_texture(1, t1, GL_MODULATE);
   draw(color);
   for (int c = 0; c < 4; c++)
      want[c] = (texel(t0[c]) * color[c]) * texel(t1[c]);
   expect_pixel("MODULATE then MODULATE", want);

   /* MODULATE, ADD: rgb sat((T0 * C) + T1), alpha (T0.a * C.a) * T1.a */
   unit_texture(1, t1, GL_ADD);
   draw(color);
   for (int c = 0; c < 4; c++) {
      const float p = texel(t0[c]) * color[c];
      if (c < 3) {
         float s = p + texel(t1[c]);
         s = s > 0.0f ? s : 0.0f;
         want[c] = s < 1.0f ? s : 1.0f;
      } else {
         want[c] = p * texel(t1[c]);
      }
   }
   expect_pixel("MODULATE then ADD (saturated)", want);

   /* three units: MODULATE, REPLACE of rgb by the texel's, then COMBINE
    * SUBTRACT (PREVIOUS - TEXTURE, saturated) on every channel */
   unit_texture(1, t1, GL_MODULATE);
   unit_texture(2, t2, GL_COMBINE);
   glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_SUBTRACT);
   glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_SUBTRACT);
   glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS);
   glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE);
   glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS);
   glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_TEXTURE);
   draw(color);
   for (int c = 0; c < 4; c++) {
      float s = (texel(t0[c]) * color[c]) * texel(t1[c]) - texel(t2[c]);
      s = s > 0.0f ? s : 0.0f;
      want[c] = s < 1.0f ? s : 1.0f;
   }
   expect_pixel("MODULATE, MODULATE, SUBTRACT (saturated)", want);
   return probe_result();
}
