/*
 * linrect - rectangles of one colour drawn on a GLX drawable without
 * depth and stencil buffers, on Mesa's libGL and on fixgl's (run_glx.py
 * compare).  llvmpipe draws some of them through its linear path, which
 * takes a constant colour to a byte as trunc(c * 256 - c) where the
 * fragment stage rounds c * 255 (ORACLE-NOTES.md "GLX linear
 * rectangles").  Every band holds 256 columns one pixel wide, each drawn
 * with its own colour (every channel ramped over k/255 and the points
 * between): glRecti with smooth and flat shading, GL_QUADS, GL_POLYGON,
 * a GL_TRIANGLE_FAN and two GL_TRIANGLES of the same rectangle, blending
 * on, the alpha test on, scissored, a colour mask, a quad whose corners
 * differ, wider rectangles, on windows with and without alpha, with a
 * depth buffer.  The bands are read back (glReadPixels, RGB then alpha)
 * into one PPM; a few pixels are printed.  Every tile (64 x 64) of these
 * scenes holds a whole-buffer clear or a triangle, so llvmpipe rounds
 * everywhere: fixgl (which always rounds) must match.
 *
 * With --scenes (the probe, not run by the suite: fixgl does not model
 * the linear path yet, README issue 20) it prints the colour of pixel
 * (10, 10) after scenes that each begin with glFinish: a rectangle of
 * one colour alone, after a whole-buffer clear, beside a triangle in its
 * tile or in another, a scissored clear followed by a triangle, ...
 *
 *   linrect --out FILE.ppm [--scenes]
 */
#include <GL/gl.h>
#include <stdbool.h>

#include "glx_frames.h"

#define W 256
#define H 96

static Display *dpy;
static const char *out;
static int images;

static void grab(int w, int h)
{
   append_read_ppm(out, &images, w, h, 1);
}

static void colour_of(int x, int salt, float c[4])
{
   const float q = (float)(salt & 3) * 0.25f;
   c[0] = ((float)x + q) / 255.0f;
   c[1] = ((float)(255 - x) + q * 0.5f) / 255.0f;
   c[2] = ((float)((x * 7 + salt * 13) & 255)) / 255.0f;
   c[3] = ((float)((x * 13 + 5) & 255) + 0.5f) / 255.0f;
   for (int i = 0; i < 4; i++)
      if (c[i] > 1.0f)
         c[i] = 1.0f;
}

enum prim { RECT, QUADS, POLYGON, FAN, TRIS, STRIP, CORNERS };

static void draw(enum prim p, int x0, int y0, int x1, int y1, const float c[4])
{
   glColor4fv(c);
   switch (p) {
   case RECT:
      glRecti(x0, y0, x1, y1);
      return;
   case QUADS:
   case POLYGON:
   case FAN:
      glBegin(p == QUADS ? GL_QUADS : p == POLYGON ? GL_POLYGON : GL_TRIANGLE_FAN);
      glVertex2i(x0, y0);
      glVertex2i(x1, y0);
      glVertex2i(x1, y1);
      glVertex2i(x0, y1);
      glEnd();
      return;
   case TRIS:
      glBegin(GL_TRIANGLES);
      glVertex2i(x0, y0);
      glVertex2i(x1, y0);
      glVertex2i(x1, y1);
      glVertex2i(x0, y0);
      glVertex2i(x1, y1);
      glVertex2i(x0, y1);
      glEnd();
      return;
   case STRIP:
      glBegin(GL_TRIANGLE_STRIP);
      glVertex2i(x0, y0);
      glVertex2i(x1, y0);
      glVertex2i(x0, y1);
      glVertex2i(x1, y1);
      glEnd();
      return;
   case CORNERS:
      glBegin(GL_QUADS);
      glVertex2i(x0, y0);
      glColor4f(c[1], c[2], c[3], c[0]);
      glVertex2i(x1, y0);
      glVertex2i(x1, y1);
      glColor4fv(c);
      glVertex2i(x0, y1);
      glEnd();
      return;
   }
}

/* rows y..y+h, one column per colour */
static void band(enum prim p, int y, int h, int salt)
{
   for (int x = 0; x < W; x++) {
      float c[4];
      colour_of(x, salt, c);
      draw(p, x, y, x + 1, y + h, c);
   }
}

static void bands(void)
{
   glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
   glClear(GL_COLOR_BUFFER_BIT);
   band(RECT, 0, 4, 0);
   print_read_pixel("rect 0.5", 127, 1);
   glShadeModel(GL_FLAT);
   band(RECT, 4, 4, 1);
   glShadeModel(GL_SMOOTH);
   band(QUADS, 8, 4, 2);
   band(POLYGON, 12, 4, 3);
   band(FAN, 16, 4, 0);
   band(TRIS, 20, 4, 1);
   band(STRIP, 24, 4, 2);
   band(CORNERS, 28, 4, 3);
   glEnable(GL_BLEND);
   glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
   band(RECT, 32, 4, 0);
   glDisable(GL_BLEND);
   glEnable(GL_ALPHA_TEST);
   glAlphaFunc(GL_GREATER, 0.25f);
   band(RECT, 36, 4, 1);
   glDisable(GL_ALPHA_TEST);
   glEnable(GL_SCISSOR_TEST);
   glScissor(0, 41, W, 2);
   band(RECT, 40, 4, 2);
   glDisable(GL_SCISSOR_TEST);
   glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
   band(RECT, 44, 4, 3);
   glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
   glEnable(GL_DITHER);
   glDisable(GL_DITHER);
   band(RECT, 48, 4, 0);
   glEnable(GL_DITHER);
   /* wider rectangles: 64 of 4 columns, then 16 of 16 */
   for (int x = 0; x < W; x += 4) {
      float c[4];
      colour_of(x, 1, c);
      draw(RECT, x, 52, x + 4, 60, c);
   }
   for (int x = 0; x < W; x += 16) {
      float c[4];
      colour_of(x + 3, 2, c);
      draw(RECT, x, 60, x + 16, 76, c);
   }
   /* a rectangle at half-pixel corners, float coordinates */
   for (int x = 0; x < W; x++) {
      float c[4];
      colour_of(x, 3, c);
      glColor4fv(c);
      glRectf((float)x + 0.25f, 76.5f, (float)x + 1.25f, 80.5f);
   }
   /* lines and points of one colour */
   glBegin(GL_LINES);
   for (int x = 0; x < W; x++) {
      float c[4];
      colour_of(x, 0, c);
      glColor4fv(c);
      glVertex2f((float)x + 0.5f, 80.0f);
      glVertex2f((float)x + 0.5f, 84.0f);
   }
   glEnd();
   glBegin(GL_POINTS);
   for (int x = 0; x < W; x++) {
      float c[4];
      colour_of(x, 1, c);
      glColor4fv(c);
      glVertex2f((float)x + 0.5f, 84.5f);
   }
   glEnd();
   /* out of range colours */
   for (int x = 0; x < W; x++) {
      float c[4];
      colour_of(x, 2, c);
      c[x & 3] = (x & 4) ? 1.0f + (float)x / 512.0f : -(float)x / 512.0f;
      draw(RECT, x, 88, x + 1, 92, c);
   }
   /* a rectangle over the whole drawable's width at once */
   glColor4f(0.1f, 0.5f, 0.9f, 0.45f);
   glRecti(0, 92, W, H);
   print_read_pixel("wide", 10, 93);
}

static const float C[4] = { 0.1f, 0.5f, 0.9f, 0.45f };

static void tri_at(int x, int y)
{
   glColor4f(0.7f, 0.7f, 0.7f, 0.7f);
   glBegin(GL_TRIANGLES);
   glVertex2i(x, y);
   glVertex2i(x + 30, y);
   glVertex2i(x, y + 30);
   glEnd();
}

static void scissored_clear(void)
{
   scissored_clear_of(C);
}

static void rect(void)
{
   glColor4fv(C);
   glRecti(0, 0, 40, 40);
}

/* the probe: each scene begins with glFinish (llvmpipe's scene is
 * rasterized, bin by bin, when it is flushed) */
static void scenes(void)
{
   static const char *const names[] = {
      "rect alone",  "clear, rect",   "clear, finish, rect",   "arrays quad",
      "colour in begin/end", "rect, tri in another tile", "rect, tri in its tile",
      "scissored clear, tri in its tile", "scissored clear, flush, tri in its tile",
      "clear, scissored clear", "scissored clear alone", "clear, finish, rect blended",
      "rect alpha test", "rect at quarter pixels", "flat quad, corners differ",
      "rect of 1.5 alpha", "triangles of a rect",
   };
   for (int k = 0; k < (int)(sizeof names / sizeof names[0]); k++) {
      glFinish();
      switch (k) {
      case 0: rect(); break;
      case 1: whole_clear(); rect(); break;
      case 2: whole_clear(); glFinish(); rect(); break;
      case 3: {
         static const GLfloat v[] = { 0, 0, 40, 0, 40, 40, 0, 40 };
         glColor4fv(C);
         glEnableClientState(GL_VERTEX_ARRAY);
         glVertexPointer(2, GL_FLOAT, 0, v);
         glDrawArrays(GL_QUADS, 0, 4);
         glDisableClientState(GL_VERTEX_ARRAY);
         break;
      }
      case 4:
         glBegin(GL_QUADS);
         glColor4fv(C);
         glVertex2i(0, 0);
         glVertex2i(40, 0);
         glVertex2i(40, 40);
         glVertex2i(0, 40);
         glEnd();
         break;
      case 5: rect(); tri_at(150, 20); break;
      case 6: rect(); tri_at(20, 20); break;
      case 7: scissored_clear(); tri_at(20, 20); break;
      case 8: scissored_clear(); glFlush(); tri_at(20, 20); break;
      case 9: whole_clear(); scissored_clear(); break;
      case 10: scissored_clear(); break;
      case 11:
         whole_clear();
         glFinish();
         glEnable(GL_BLEND);
         glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
         rect();
         glDisable(GL_BLEND);
         break;
      case 12:
         glEnable(GL_ALPHA_TEST);
         glAlphaFunc(GL_GREATER, 0.25f);
         rect();
         glDisable(GL_ALPHA_TEST);
         break;
      case 13:
         glColor4fv(C);
         glRectf(0.25f, 0.25f, 40.25f, 40.25f);
         break;
      case 14:
         glShadeModel(GL_FLAT);
         glBegin(GL_QUADS);
         glColor4f(0.9f, 0.9f, 0.9f, 0.9f);
         glVertex2i(0, 0);
         glVertex2i(40, 0);
         glVertex2i(40, 40);
         glColor4fv(C);
         glVertex2i(0, 40);
         glEnd();
         glShadeModel(GL_SMOOTH);
         break;
      case 15:
         glColor4f(C[0], C[1], C[2], 1.5f);
         glRecti(0, 0, 40, 40);
         break;
      case 16:
         glColor4fv(C);
         glBegin(GL_TRIANGLES);
         glVertex2i(0, 0);
         glVertex2i(40, 0);
         glVertex2i(40, 40);
         glVertex2i(0, 0);
         glVertex2i(40, 40);
         glVertex2i(0, 40);
         glEnd();
         break;
      }
      unsigned char p[4];
      glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
      printf("scene %s: %d %d %d %d\n", names[k], p[0], p[1], p[2], p[3]);
   }
}

static bool probe;

static GLXFBConfig config_of(int alpha, int depth, int db)
{
   int attrs[] = { GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, alpha,
                   GLX_DEPTH_SIZE, depth, GLX_DOUBLEBUFFER, db,
                   GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, None };
   int n = 0;
   GLXFBConfig *cs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attrs, &n);
   GLXFBConfig c = NULL;
   for (int i = 0; cs && i < n && !c; i++) {
      int r = 0, a8 = 0;
      glXGetFBConfigAttrib(dpy, cs[i], GLX_RED_SIZE, &r);
      glXGetFBConfigAttrib(dpy, cs[i], GLX_ALPHA_SIZE, &a8);
      if (r == 8 && a8 == alpha)
         c = cs[i];
   }
   if (cs)
      XFree(cs);
   if (!c) {
      fprintf(stderr, "linrect: no config (alpha %d depth %d db %d)\n", alpha, depth, db);
      exit(1);
   }
   int id = 0, d = -1;
   glXGetFBConfigAttrib(dpy, c, GLX_FBCONFIG_ID, &id);
   glXGetFBConfigAttrib(dpy, c, GLX_DEPTH_SIZE, &d);
   printf("= config 0x%x alpha %d depth %d\n", id, alpha, d);
   return c;
}

static void window_case(int alpha, int depth)
{
   GLXFBConfig c = config_of(alpha, depth, True);
   XVisualInfo *vi;
   GLXContext ctx;
   Window win = config_window_current(dpy, c, W, H, &vi, &ctx);
   print_renderer();
   pixel_view(W, H);
   glDrawBuffer(GL_BACK);
   glReadBuffer(GL_BACK);
   bands();
   grab(W, H);
   if (probe && alpha == 8 && depth == 0)
      scenes();
   glFinish();
   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   XDestroyWindow(dpy, win);
   XFree(vi);
}

int main(int argc, char **argv)
{
   probe = argc == 4 && strcmp(argv[3], "--scenes") == 0;
   if ((argc != 3 && !probe) || strcmp(argv[1], "--out") != 0) {
      fprintf(stderr, "usage: %s --out FILE.ppm [--scenes]\n", argv[0]);
      return 2;
   }
   out = argv[2];
   dpy = XOpenDisplay(NULL);
   if (!dpy) {
      fprintf(stderr, "linrect: no display\n");
      return 1;
   }
   window_case(8, 0);
   window_case(0, 0);
   window_case(8, 24);
   XCloseDisplay(dpy);
   return 0;
}
