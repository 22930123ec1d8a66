/* p_vpcut_state.c - llvmpipe's viewport cut of the draw region under
 * point attenuation is state computed once, not per primitive
 * (ORACLE-NOTES.md "Point parameters"; open in fixgl, known differences
 * random-raster/s1-i211 and others):
 *  - llvmpipe recomputes its draw regions (framebuffer, scissor box and,
 *    with per-vertex point sizes, the viewport rectangle) only when they
 *    are marked dirty (a viewport or scissor change, the scissor test
 *    toggled, a framebuffer bound) and then at the next primitive it
 *    bins, with the rasterizer state bound at that moment;
 *  - a smooth line is drawn by the draw module's aaline stage, which
 *    binds its own rasterizer (no per-vertex size): when the first
 *    primitive after the change is a smooth line the region is not cut
 *    and stays uncut; when it is anything else (a triangle, a plain line)
 *    the region is cut and the smooth lines after it are cut too, pixel
 *    by pixel.
 * Each case: a fresh context, a viewport starting at row 7 of a 64x64
 * buffer, attenuation on, then draws; counted: pixels below row 7. */
#include "probe.h"

static const float att[3] = { 1.0f, 0.5f, 0.25f };

static void smooth_line(void)
{
   glEnable(GL_LINE_SMOOTH);
   glLineWidth(6);
   glBegin(GL_LINES);
   glColor3f(1, 0, 0);
   glVertex2f(2, 8);
   glVertex2f(60, 9);
   glEnd();
   glDisable(GL_LINE_SMOOTH);
}

static void tiny_tri(void)
{
   glBegin(GL_TRIANGLES);
   glColor3f(0, 0, 1);
   glVertex2f(40, 40);
   glVertex2f(41, 40);
   glVertex2f(40, 41);
   glEnd();
}

static int below_viewport(void)
{
   int n = 0;
   for (int y = 0; y < 7; y++)
      for (int x = 0; x < g_w; x++)
         n += px(x, y)[0] != 0 || px(x, y)[1] != 0 || px(x, y)[2] != 0;
   return n;
}

/* first: 0 the smooth line first, 1 a triangle first, 2 a triangle drawn
 * before attenuation is turned on */
static int run(int first)
{
   probe_init_ub(64, 64);
   glViewport(0, 7, 64, 57);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, 64, 7, 64, -1, 1);
   glMatrixMode(GL_MODELVIEW);
   glClearColor(0, 0, 0, 0);
   glClear(GL_COLOR_BUFFER_BIT);
   if (first == 2)
      tiny_tri();
   glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
   if (first == 1)
      tiny_tri();
   smooth_line();
   glFinish();
   const int n = below_viewport();
   OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
   OSMesaDestroyContext(g_ctx);
   free(g_buf);
   return n;
}

int main(void)
{
   const int first_smooth = run(0), after_tri = run(1), tri_before_att = run(2);
   printf("pixels below the viewport: smooth line first %d, after a triangle %d, "
          "triangle before attenuation %d\n", first_smooth, after_tri, tri_before_att);
   probe_expect("a smooth line drawn first is not cut (pixels below the viewport > 0)",
                first_smooth > 0, 1);
   probe_expect("after a triangle under attenuation the smooth line is cut", after_tri, 0);
   probe_expect("a region computed before attenuation stays uncut (same as drawn first)",
                tri_before_att, first_smooth);
   return probe_result();
}
