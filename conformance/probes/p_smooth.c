/* p_smooth.c - GL_POINT_SMOOTH and GL_LINE_SMOOTH through draw's aapoint
 * and aaline stages: the alpha they write without blending, rows from the
 * top (ORACLE-NOTES.md "Line and point rasterization").  The point's
 * outer ring keeps the colour's alpha (0.5 -> 128) and its inner disc
 * gets more (the stage's inverted selection); the line's alpha is the
 * product of its two coverage ramps. */
#include "probe.h"

static const unsigned char point_alpha[13][13] = {
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 128, 128, 128, 128, 128, 128, 0, 0, 0, 0 },
   { 0, 0, 128, 128, 187, 219, 219, 187, 128, 128, 0, 0, 0 },
   { 0, 0, 128, 187, 251, 255, 255, 251, 187, 128, 0, 0, 0 },
   { 0, 0, 128, 219, 255, 255, 255, 255, 219, 128, 0, 0, 0 },
   { 0, 0, 128, 219, 255, 255, 255, 255, 219, 128, 0, 0, 0 },
   { 0, 0, 128, 187, 251, 255, 255, 251, 187, 128, 0, 0, 0 },
   { 0, 0, 128, 128, 187, 219, 219, 187, 128, 128, 0, 0, 0 },
   { 0, 0, 0, 128, 128, 128, 128, 128, 128, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
};

static const unsigned char line_alpha[14][22] = {
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 68, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 33, 130, 227, 186, 20, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 75, 172, 241, 144, 47, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 19, 116, 213, 200, 102, 5, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 61, 158, 255, 158, 61, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 5, 102, 200, 213, 116, 19, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 47, 144, 241, 172, 75, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 20, 186, 227, 130, 33, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 68, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
   { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 },
};

int main(void)
{
   probe_init_ub(24, 24);
   glDisable(GL_DITHER);
   clear0();
   glEnable(GL_POINT_SMOOTH);
   glPointSize(9.0f);
   glColor4f(1, 1, 1, 0.5f);
   glBegin(GL_POINTS);
   glVertex2f(12, 12);
   glEnd();
   glFinish();
   long bad = 0;
   for (int y = 18; y >= 6; y--)
      for (int x = 6; x < 19; x++)
         bad += px(x, y)[3] != point_alpha[18 - y][x - 6];
   probe_expect("smooth point, size 9, alpha 0.5: alphas differing", bad, 0);
   glDisable(GL_POINT_SMOOTH);

   clear0();
   glEnable(GL_LINE_SMOOTH);
   glLineWidth(1.0f);
   glColor4f(1, 1, 1, 1.0f);
   glBegin(GL_LINES);
   glVertex2f(3, 4);
   glVertex2f(20, 11);
   glEnd();
   glFinish();
   bad = 0;
   for (int y = 14; y >= 1; y--)
      for (int x = 1; x < 23; x++)
         bad += px(x, y)[3] != line_alpha[14 - y][x - 1];
   probe_expect("smooth line, width 1: alphas differing", bad, 0);
   return probe_result();
}
