/* p_vpcut_state.c - llvmpipe's viewport cut of the draw region under
 * point attenuation is state computed once, not per primitive
 * (ORACLE-NOTES.md "Point parameters"):
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
 *  - what marks the regions dirty (events after a triangle has cut them;
 *    then a smooth line, not cut iff they were): a flush (glFinish,
 *    glFlush, glReadPixels, glCopyPixels), another viewport (depth range
 *    included), the scissor test toggled, a pixel rectangle (glDrawPixels,
 *    glBitmap) and a quad clear (their own viewport); not: the same
 *    viewport again, a viewport changed and changed back between draws, a
 *    scissor box changed while the test is off, the test toggled on and
 *    off between draws, a plain clear, attenuation toggled;
 *  - occlusion queries begun or ended mark nothing, asking for a
 *    result that is not ready does (llvmpipe flushes to wait for it); a
 *    texel write into the resource the pending scene samples
 *    (glTexImage2D of the same size, glTexSubImage2D) flushes and marks,
 *    one into another texture, an image given new storage, a deletion or
 *    glGetTexImage does not;
 *  - a smooth point first (the aapoint stage binds the same "no cull"
 *    rasterizer) leaves them uncut, a polygon-mode line first cuts them,
 *    and a wide point after an uncut region is not cut either.
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

static void smooth_point(void)
{
   glEnable(GL_POINT_SMOOTH);
   glBegin(GL_POINTS);
   glColor3f(0, 1, 0);
   glVertex2f(30, 40);
   glEnd();
   glDisable(GL_POINT_SMOOTH);
}

static void wide_point(void)
{
   glPointSize(12);
   glBegin(GL_POINTS);
   glColor3f(0, 1, 0);
   glVertex2f(20, 8);
   glEnd();
   glPointSize(1);
}

/* A triangle (or what `ev` names) first, then the event, then the smooth
 * line (or a wide point); pixels below the viewport. */
static int run_event(int ev)
{
   probe_init_ub(64, 64);
   glViewport(0, 7, 64, 57);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, 64, 7, 64, -1, 1);
   glMatrixMode(GL_MODELVIEW);
   glClearColor(0, 0, 0, 0);
   glClear(GL_COLOR_BUFFER_BIT);
   glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
   static const float one[3] = { 1, 0, 0 };
   unsigned char b[4] = { 0, 0, 0, 0 };
   static const GLubyte bm[8] = { 0xff };
   if (ev == 24) {
      GLuint q;
      glGenQueries(1, &q);
      glBeginQuery(GL_SAMPLES_PASSED, q);
   }
   if (ev == 12)
      smooth_point();
   else if (ev == 13) {
      glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
      tiny_tri();
      glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
   } else if (ev == 18 || ev == 21)
      smooth_line();
   else if (ev >= 25 && ev <= 30) {
      /* a textured triangle pending; textures t[0] (used) and t[1] */
      static const unsigned char texels[4 * 4 * 4] = { 255, 255, 255, 255 };
      GLuint t[2];
      glGenTextures(2, t);
      for (int i = 1; i >= 0; i--) {
         glBindTexture(GL_TEXTURE_2D, t[i]);
         glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
         glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      }
      glEnable(GL_TEXTURE_2D);
      tiny_tri();
      glDisable(GL_TEXTURE_2D);
      switch (ev) {
      case 25:   /* the used texture's image again, same size and format */
         glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
         break;
      case 26:   /* the used texture, a sub-image */
         glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels);
         break;
      case 27:   /* the other texture's sub-image */
         glBindTexture(GL_TEXTURE_2D, t[1]);
         glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels);
         break;
      case 28:   /* the used texture, another size (new storage) */
         glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
         break;
      case 29:   /* the used texture deleted */
         glDeleteTextures(1, &t[0]);
         break;
      case 30:   /* glGetTexImage of the used texture */
         {
            static unsigned char out[4 * 4 * 4];
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
         }
         break;
      default: break;
      }
   } else
      tiny_tri();
   switch (ev) {
   case 1: glFinish(); break;
   case 2: glViewport(0, 7, 64, 57); break;
   case 3: glViewport(0, 7, 64, 56); break;
   case 4: glScissor(0, 0, 64, 64); break;
   case 5: glEnable(GL_SCISSOR_TEST); break;
   case 6: glScissor(0, 0, 60, 64); break;
   case 7: glDepthRange(0.1, 1); break;
   case 8: glRasterPos2f(50, 50); glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b); break;
   case 9: glClear(GL_COLOR_BUFFER_BIT); break;
   case 10:
      glColorMask(1, 0, 1, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glColorMask(1, 1, 1, 1);
      break;
   case 11: glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b); break;
   case 14: glRasterPos2f(50, 50); glBitmap(8, 1, 0, 0, 0, 0, bm); break;
   case 15: glFlush(); break;
   case 16:
      glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, one);
      tiny_tri();
      glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
      break;
   case 17: glViewport(0, 7, 64, 56); glViewport(0, 7, 64, 57); break;
   case 18: tiny_tri(); break;
   case 19: glRasterPos2f(50, 50); glCopyPixels(0, 0, 1, 1, GL_COLOR); break;
   case 20: glScissor(0, 0, 60, 64); glEnable(GL_SCISSOR_TEST); glDisable(GL_SCISSOR_TEST); break;
   case 22: {   /* an occlusion query begun (active at the next draw) */
      GLuint q;
      glGenQueries(1, &q);
      glBeginQuery(GL_SAMPLES_PASSED, q);
      break;
   }
   case 23: {   /* an occlusion query begun and ended */
      GLuint q;
      glGenQueries(1, &q);
      glBeginQuery(GL_SAMPLES_PASSED, q);
      glEndQuery(GL_SAMPLES_PASSED);
      break;
   }
   case 24: {   /* an occlusion query ended (begun before the triangle) */
      glEndQuery(GL_SAMPLES_PASSED);
      break;
   }
   case 31: {   /* a query's result asked for */
      GLuint q, r;
      glGenQueries(1, &q);
      glBeginQuery(GL_SAMPLES_PASSED, q);
      glEndQuery(GL_SAMPLES_PASSED);
      glGetQueryObjectuiv(q, GL_QUERY_RESULT, &r);
      break;
   }
   default: break;
   }
   if (ev == 21) {
      glClear(GL_COLOR_BUFFER_BIT);
      wide_point();
   } else
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
   /* 1: re-dirtied (the smooth line then decides: not cut), 0: not */
   static const struct { int ev; int dirty; const char *what; } evs[] = {
      { 0, 0, "nothing" },          { 1, 1, "glFinish" },
      { 2, 0, "the same viewport" }, { 3, 1, "another viewport" },
      { 4, 0, "glScissor, test off" }, { 5, 1, "the scissor test on" },
      { 6, 0, "another box, test off" }, { 7, 1, "glDepthRange" },
      { 8, 1, "glDrawPixels" },     { 9, 0, "a plain glClear" },
      { 10, 1, "a quad glClear" },  { 11, 1, "glReadPixels" },
      { 12, 1, "a smooth point first" }, { 13, 0, "a polygon-mode line first" },
      { 14, 1, "glBitmap" },        { 15, 1, "glFlush" },
      { 16, 0, "attenuation off and on around a triangle" },
      { 17, 0, "a viewport changed and back between draws" },
      { 18, 1, "a smooth line first, then a triangle" },
      { 19, 1, "glCopyPixels" },
      { 20, 0, "the scissor test on and off between draws" },
      { 21, 1, "a wide point after a smooth line first" },
      { 22, 0, "glBeginQuery" },    { 23, 0, "glBeginQuery, glEndQuery" },
      { 24, 0, "glEndQuery" },      { 25, 1, "glTexImage2D of the used texture" },
      { 26, 1, "glTexSubImage2D of the used texture" },
      { 27, 0, "glTexSubImage2D of another texture" },
      { 28, 0, "glTexImage2D of the used texture, another size" },
      { 29, 0, "the used texture deleted" },
      { 30, 0, "glGetTexImage of the used texture" },
      { 31, 1, "glGetQueryObjectuiv(GL_QUERY_RESULT)" },
   };
   for (unsigned i = 0; i < sizeof(evs) / sizeof(evs[0]); i++) {
      const int n = run_event(evs[i].ev);
      printf("  %-44s %d pixels below\n", evs[i].what, n);
      probe_expect(evs[i].what, n > 0, evs[i].dirty);
   }
   return probe_result();
}
