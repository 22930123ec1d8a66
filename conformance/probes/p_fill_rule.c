/* p_fill_rule.c - triangle snapping and the fill rule
 * (ORACLE-NOTES.md "Rasterization: snapping, fill rule, edge functions"). */
#include "probe.h"

static void tri(float x0, float y0, float x1, float y1, float x2, float y2)
{
   glBegin(GL_TRIANGLES);
   glVertex2f(x0, y0);
   glVertex2f(x1, y1);
   glVertex2f(x2, y2);
   glEnd();
}

/* Rectangle [xl, 8] x [1, 9]: is column 2 (centre x = 2.5) lit? */
static int col2_lit(double xl)
{
   clear0();
   glColor3f(1, 1, 1);
   glBegin(GL_TRIANGLES);
   glVertex2d(xl, 1); glVertex2d(8, 1); glVertex2d(8, 9);
   glVertex2d(xl, 1); glVertex2d(8, 9); glVertex2d(xl, 9);
   glEnd();
   glFinish();
   return px(2, 4)[0] != 0;
}

int main(void)
{
   probe_init_ub(16, 16);
   glDisable(GL_DITHER);

   /* A square whose four edges run through pixel centres 2.5 and 6.5:
    * the left and bottom edges' pixels are in, the right and top ones out. */
   clear0();
   glColor3f(1, 0, 0);
   glBegin(GL_QUADS);
   glVertex2f(2.5, 2.5); glVertex2f(6.5, 2.5); glVertex2f(6.5, 6.5); glVertex2f(2.5, 6.5);
   glEnd();
   glFinish();
   int minx = 99, maxx = -1, miny = 99, maxy = -1;
   for (int y = 0; y < 16; y++)
      for (int x = 0; x < 16; x++)
         if (px(x, y)[0]) {
            if (x < minx) minx = x;
            if (x > maxx) maxx = x;
            if (y < miny) miny = y;
            if (y > maxy) maxy = y;
         }
   probe_expect("square 2.5..6.5: first column", minx, 2);
   probe_expect("square 2.5..6.5: last column", maxx, 5);
   probe_expect("square 2.5..6.5: first row (GL, y up)", miny, 2);
   probe_expect("square 2.5..6.5: last row (GL, y up)", maxy, 5);

   /* Two triangles sharing a diagonal through pixel centres, added: no
    * pixel twice, none missed. */
   clear0();
   glEnable(GL_BLEND);
   glBlendFunc(GL_ONE, GL_ONE);
   glColor3f(0.5, 0, 0);
   tri(1.5, 1.5, 9.5, 1.5, 9.5, 9.5);
   tri(1.5, 1.5, 9.5, 9.5, 1.5, 9.5);
   glDisable(GL_BLEND);
   glFinish();
   int dbl = 0, gap = 0;
   for (int y = 2; y < 9; y++)
      for (int x = 2; x < 9; x++) {
         int r = px(x, y)[0];
         if (r > 200) dbl++;
         if (r == 0) gap++;
      }
   probe_expect("shared diagonal: pixels drawn twice", dbl, 0);
   probe_expect("shared diagonal: pixels missed", gap, 0);

   /* Snapping: a left edge at 2.5 + k/512 is (x - 0.5) * 256 = 512 + k/2
    * in fixed point; round half to even keeps 512.5 at 512 (column 2 in,
    * the edge on its centre) and takes 513 and up out. */
   int wrong = 0;
   for (int k = -4; k <= 6; k++) {
      int lit = col2_lit(2.5 + k / 512.0);
      if (lit != (k <= 1)) {
         printf("  k = %d: column 2 %s\n", k, lit ? "lit" : "off");
         wrong++;
      }
   }
   probe_expect("left edge at 2.5 + k/512: wrong columns", wrong, 0);
   probe_expect("left edge at 2.5 + 0.0019 (rounds to 512) lit", col2_lit(2.5 + 0.0019), 1);
   probe_expect("left edge at 2.5 + 0.0021 (rounds to 513) lit", col2_lit(2.5 + 0.0021), 0);
   return probe_result();
}
