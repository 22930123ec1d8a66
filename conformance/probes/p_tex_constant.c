/* p_tex_constant.c - a texture coordinate that cannot vary is a constant
 * of the fixed-function fragment program: a unit whose coordinate is not
 * in the draw's vertex format, with no texgen and an identity texture
 * matrix, reads the current coordinate (ff_fragment_shader.cpp:
 * filter_fp_input_mask, load_texture) instead of interpolating it.  Where
 * interpolation is not exact this shows: a triangle with the clip-space
 * origin at w = 0 as a vertex interpolates NaN coordinates (a NEAREST
 * REPEAT lookup of NaN reads texel 0), while the constant reads its own
 * texel everywhere (ORACLE-NOTES.md "Texture coordinates and
 * multitexture"). */
#include "probe.h"

#define W 17
#define H 54

/* texel i of the 8x1 texture: (30i, 255 - 30i, 100, 255) */
static void counts(int *tex0, int *tex6, int *other)
{
   *tex0 = *tex6 = *other = 0;
   for (int y = 0; y < H; y++)
      for (int x = 0; x < W; x++) {
         const unsigned char *p = px(x, y);
         if (p[3] == 0)
            continue;                        /* the clear colour */
         if (p[0] == 0 && p[1] == 255)
            (*tex0)++;
         else if (p[0] == 180 && p[1] == 75)
            (*tex6)++;
         else
            (*other)++;
      }
}

/* Triangles with the origin at w = 0 as a vertex (the shapes of the
 * conformance case core/w_zero_vertex); the coordinate (0.826, 0.8) per
 * vertex or current. */
static void draw(int per_vertex)
{
   static const float tri[3][4] = {
      { -0.8f, -0.8f, 0.7f, -0.6f },
      { 0.9f, 0.9f, -0.9f, 0.95f },
      { -0.2f, 0.5f, 0.1f, -0.9f },
   };
   clear0();
   if (!per_vertex)
      glTexCoord2f(0.826f, 0.8f);
   for (int t = 0; t < 3; t++) {
      glBegin(GL_TRIANGLES);
      if (per_vertex)
         glTexCoord2f(0.826f, 0.8f);
      glVertex4f(tri[t][0], tri[t][1], 0.1f, 1.0f);
      glVertex4f(tri[t][2], tri[t][3], 0.1f, 1.0f);
      glVertex4f(0.0f, 0.0f, 0.0f, 0.0f);
      glEnd();
   }
   glFinish();
}

int main(void)
{
   probe_init_ub(W, H);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glMatrixMode(GL_MODELVIEW);
   unsigned char texels[8 * 4];
   for (int i = 0; i < 8; i++) {
      texels[4 * i + 0] = (unsigned char)(30 * i);
      texels[4 * i + 1] = (unsigned char)(255 - 30 * i);
      texels[4 * i + 2] = 100;
      texels[4 * i + 3] = 255;
   }
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
   glEnable(GL_TEXTURE_2D);
   int t0, t6, other;

   draw(0);
   counts(&t0, &t6, &other);
   probe_expect("current coordinate: pixels of texel 6 (the constant)", t6 > 0, 1);
   probe_expect("current coordinate: pixels of texel 0 (NaN)", t0, 0);
   probe_expect("current coordinate: other pixels", other, 0);
   const int covered = t6;

   draw(1);
   counts(&t0, &t6, &other);
   probe_expect("coordinate per vertex: pixels of texel 0 (NaN)", t0, covered);
   probe_expect("coordinate per vertex: pixels of texel 6", t6, 0);

   /* a texture matrix makes the vertex program compute the coordinate:
    * a varying again, though no vertex gives one */
   glMatrixMode(GL_TEXTURE);
   glTranslatef(0.0625f, 0.0f, 0.0f);
   glMatrixMode(GL_MODELVIEW);
   draw(0);
   counts(&t0, &t6, &other);
   probe_expect("texture matrix: pixels of texel 0 (NaN)", t0, covered);
   glMatrixMode(GL_TEXTURE);
   glLoadIdentity();
   glMatrixMode(GL_MODELVIEW);

   /* texgen on s: a varying too */
   glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
   glEnable(GL_TEXTURE_GEN_S);
   draw(0);
   counts(&t0, &t6, &other);
   probe_expect("texgen on s: pixels of texel 0 (NaN)", t0, covered);
   glDisable(GL_TEXTURE_GEN_S);

   /* back to the constant: the draw before had no coordinate either */
   draw(0);
   counts(&t0, &t6, &other);
   probe_expect("current coordinate again: pixels of texel 6", t6, covered);
   return probe_result();
}
