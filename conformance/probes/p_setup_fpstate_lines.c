/* p_setup_fpstate_lines.c - lines and points of the draw module's pipeline
 * are set up, as its triangles (p_setup_fpstate), when llvmpipe_draw_vbo
 * flushes draw after draw_vbo returned: in the application's
 * floating-point state.  Lines at clip w 1.5e35 whose colour changes by
 * 0.003 over 2 pixels have denormal plane derivatives: setup without FTZ
 * keeps them, they move a0 by a normal amount, and the shader (DAZ) reads
 * them as 0, so each line is one colour other than its first vertex's.
 * The direct path (no vertex of the batch clipped, no stage) sets up under
 * draw_vbo's FTZ|DAZ; stippled and smooth lines always take the pipeline.
 * Points (plain and sprites) come out the same either way: their setup
 * keeps no derivative that the shader does not read as 0 anyway
 * (ORACLE-NOTES.md "Interpolation"). */
#include "probe.h"

#include <xmmintrin.h>

#define W 64

enum kind { LINES, POINTS, SPRITES, SMOOTH_LINES, STIPPLED_LINES, SMOOTH_POINTS, KINDS };
static const char *const names[KINDS] = {
   "lines", "points", "sprites", "smooth lines", "stippled lines", "smooth points",
};

static void vtx(float x, float y, float w, float c)
{
   glColor4f(c, c, 0.0f, 1.0f);
   glVertex4f((2.0f * x / W - 1.0f) * w, (2.0f * y / W - 1.0f) * w, 0.0f, w);
}

/* The primitives of `kind` at w 1.5e35 (and, `clipped`, one with a vertex
 * outside the left plane in the same glBegin/glEnd, at y < 8) with the
 * caller's MXCSR `csr`; out: rows 8..63. */
static void draw(enum kind kind, int clipped, unsigned csr, unsigned char *out)
{
   const float w = 1.5e35f;
   clear0();
   const unsigned saved = _mm_getcsr();
   _mm_setcsr(csr);
   if (kind == LINES || kind == SMOOTH_LINES || kind == STIPPLED_LINES) {
      glBegin(GL_LINES);
      for (int i = 0; i < 6; i++) {
         const float a = i & 1 ? 0.5f : 0.503f, b = i & 1 ? 0.503f : 0.5f;
         vtx(40 + 3 * i, 10 + 8 * i, w, a);
         vtx(42 + 3 * i, 10.5f + 8 * i, w, b);
      }
      vtx(8, 60, w, 0.99f);
      vtx(12, 20, w, 1.0f);
      if (clipped) {
         glColor4f(0, 1, 0, 1);
         glVertex4f(-3.0f, -0.9f, 0.0f, 1.0f);
         glVertex4f(-0.8f, -0.9f, 0.0f, 1.0f);
      }
      glEnd();
   } else {
      glBegin(GL_POINTS);
      for (int i = 0; i < 8; i++)
         vtx(6 + 7 * i, 10 + 6 * i, w, 0.3f + 0.05f * i);
      if (clipped) {
         glColor4f(0, 1, 0, 1);
         glVertex4f(-3.0f, -0.9f, 0.0f, 1.0f);
      }
      glEnd();
   }
   glFinish();
   _mm_setcsr(saved);
   memcpy(out, px(0, 8), 4 * W * (W - 8));
}

static long ndiff(const unsigned char *a, const unsigned char *b)
{
   long n = 0;
   for (int i = 0; i < W * (W - 8); i++)
      n += memcmp(a + 4 * i, b + 4 * i, 4) != 0;
   return n;
}

int main(void)
{
   static unsigned char u_def[4 * W * W], u_ftz[4 * W * W], p_def[4 * W * W], p_ftz[4 * W * W];
   static unsigned char tex[16][16][4];
   const unsigned csr = _mm_getcsr() & ~0x8040u, ftz = csr | 0x8040u;   /* FTZ | DAZ */
   probe_init_ub(W, W);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glShadeModel(GL_SMOOTH);
   for (int y = 0; y < 16; y++)
      for (int x = 0; x < 16; x++) {
         tex[y][x][0] = (unsigned char)(16 * x);
         tex[y][x][1] = (unsigned char)(16 * y);
         tex[y][x][2] = tex[y][x][3] = 255;
      }
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
   glLineStipple(1, 0xf0f3);
   for (int k = 0; k < KINDS; k++) {
      glPointSize(k == SPRITES ? 7.0f : 3.0f);
      if (k == SPRITES) {
         glEnable(GL_POINT_SPRITE);
         glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
         glEnable(GL_TEXTURE_2D);
      }
      if (k == SMOOTH_LINES || k == SMOOTH_POINTS) {
         glEnable(k == SMOOTH_LINES ? GL_LINE_SMOOTH : GL_POINT_SMOOTH);
         glEnable(GL_BLEND);
      }
      if (k == STIPPLED_LINES)
         glEnable(GL_LINE_STIPPLE);
      draw(k, 0, csr, u_def);
      draw(k, 0, ftz, u_ftz);
      draw(k, 1, csr, p_def);
      draw(k, 1, ftz, p_ftz);
      char what[160];
      if (k == LINES) {
         probe_expect("lines, direct path: the caller's FTZ/DAZ changes nothing",
                      ndiff(u_def, u_ftz), 0);
         probe_expect("lines, pipeline, caller with FTZ/DAZ: the direct path's pixels",
                      ndiff(p_ftz, u_def), 0);
         /* the six short lines (12 pixels) one colour each, 0.5 +- 0.06
          * instead of 0.5 or 0.503 */
         probe_expect("lines, pipeline, caller without: the 12 pixels of the short lines differ",
                      ndiff(p_def, p_ftz), 12);
         long off = 0;
         for (int i = 0; i < 6; i++) {
            const unsigned char *a = p_def + 4 * ((8 * i + 2) * W + 40 + 3 * i);
            const unsigned char *b = p_def + 4 * ((8 * i + 2) * W + 41 + 3 * i);
            off += a[0] == b[0] && (a[0] > 128 + 12 || a[0] < 128 - 12);
         }
         probe_expect("lines, pipeline, caller without: each short line one colour, off by more than 12",
                      off, 6);
      } else if (k == POINTS || k == SPRITES || k == SMOOTH_POINTS) {
         snprintf(what, sizeof(what), "%s: the caller's FTZ/DAZ changes nothing (direct)", names[k]);
         probe_expect(what, ndiff(u_def, u_ftz), 0);
         snprintf(what, sizeof(what), "%s: the caller's FTZ/DAZ changes nothing (pipeline)", names[k]);
         probe_expect(what, ndiff(p_def, p_ftz), 0);
      } else {
         snprintf(what, sizeof(what), "%s (always draw's pipeline): the caller's FTZ/DAZ matters",
                  names[k]);
         probe_expect(what, ndiff(u_def, u_ftz) > 0 && ndiff(p_def, p_ftz) > 0, 1);
      }
      glDisable(GL_POINT_SPRITE);
      glDisable(GL_TEXTURE_2D);
      glDisable(GL_LINE_SMOOTH);
      glDisable(GL_POINT_SMOOTH);
      glDisable(GL_BLEND);
      glDisable(GL_LINE_STIPPLE);
   }
   return probe_result();
}
