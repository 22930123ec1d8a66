/*
 * clearquad - glClear of part of a GLX drawable, on Mesa's libGL and on
 * fixgl's (run_glx.py compare).  The oracle clears a scissored or
 * colour-masked buffer with a quad (st_Cb_clear clear_with_quad); on a
 * B8G8R8A8 / B8G8R8X8 buffer without depth and stencil llvmpipe draws
 * that quad through its linear path, which truncates the clear colour
 * where a whole-buffer clear rounds it (ORACLE-NOTES.md "GLX partial
 * clears").  Every band holds 256 columns, each cleared on its own with
 * another colour (every channel ramped over k/255 and the points between,
 * channels in different orders): scissored, colour-masked, whole-buffer
 * rounding for comparison, into both buffers (GL_FRONT_AND_BACK), clear
 * colours outside [0, 1] (the quad then rounds), on windows with and
 * without alpha, with a depth buffer (rounds) and on a pbuffer (without
 * alpha: the oracle's drisw fails to show one with alpha on Xvfb,
 * BadMatch of X_ShmPutImage).  Into both buffers the oracle's quad
 * rounds (two colour buffers bound: no linear path).  Every
 * band is read back (glReadPixels, RGB then alpha) into one PPM; a few
 * pixels are printed.
 *
 *   clearquad --out FILE.ppm
 */
#include <GL/gl.h>
#include <stdbool.h>

#include "glx_frames.h"

#define W 256
#define H 64

static Display *dpy;
static const char *out;
static int images;

static void grab(int w, int h)
{
   append_read_ppm(out, &images, w, h, 1);
}

/* column x of band `salt`: k/255 plus a quarter step per salt, the
 * channels in other orders */
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

/* rows y..y+h of every column cleared with its own colour; out of range
 * colours when `wild` (one channel of each column below 0 or above 1) */
static void clear_band(int y, int h, int salt, bool wild)
{
   glEnable(GL_SCISSOR_TEST);
   for (int x = 0; x < W; x++) {
      float c[4];
      colour_of(x, salt, c);
      if (wild)
         c[x & 3] = (x & 4) ? 1.0f + (float)x / 512.0f : -(float)x / 512.0f;
      glScissor(x, y, 1, h);
      glClearColor(c[0], c[1], c[2], c[3]);
      glClear(GL_COLOR_BUFFER_BIT);
   }
   glDisable(GL_SCISSOR_TEST);
}

/* the bands: scissored (4 quarter steps), masked whole-buffer clears
 * (each leaves the channels it masks), a whole-buffer clear, out of range
 * colours */
static void bands(void)
{
   /* a whole-buffer clear (rounds), then a whole-buffer clear of green
    * alone (the quad over everything): rows 40..47 and 56..63 keep both */
   glDisable(GL_SCISSOR_TEST);
   glClearColor(0.5f, 0.1f, 0.45f, 0.9f);
   glClear(GL_COLOR_BUFFER_BIT);
   print_read_pixel("whole", 3, 60);
   glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE);
   glClearColor(0.3f, 0.9f, 0.7f, 0.1f);
   glClear(GL_COLOR_BUFFER_BIT);
   glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
   print_read_pixel("whole then masked", 3, 60);
   for (int s = 0; s < 4; s++)
      clear_band(8 * s, 8, s, false);
   print_read_pixel("scissored 0.5", 127, 0);
   print_read_pixel("scissored 0.1", 25, 17);
   /* scissored and masked */
   static const GLboolean masks[4][4] = {
      { GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE },
      { GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE },
      { GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE },
      { GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE },
   };
   for (int m = 0; m < 4; m++) {
      glColorMask(masks[m][0], masks[m][1], masks[m][2], masks[m][3]);
      clear_band(32 + 2 * m, 2, m + 1, false);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
   }
   print_read_pixel("masked", 100, 33);
   clear_band(48, 8, 1, true);
   print_read_pixel("out of range", 4, 50);
}

static void setup_view(int w, int h)
{
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, w, 0, h, -1, 1);
   glMatrixMode(GL_MODELVIEW);
}

static GLXFBConfig config_of(int alpha, int depth, int db, int drawable_type)
{
   int attrs[] = { GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, alpha,
                   GLX_DEPTH_SIZE, depth, GLX_DOUBLEBUFFER, db,
                   GLX_DRAWABLE_TYPE, drawable_type, None };
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
      fprintf(stderr, "clearquad: no config (alpha %d depth %d db %d)\n", alpha, depth, db);
      exit(1);
   }
   int id = 0, d = -1, s = -1;
   glXGetFBConfigAttrib(dpy, c, GLX_FBCONFIG_ID, &id);
   glXGetFBConfigAttrib(dpy, c, GLX_DEPTH_SIZE, &d);
   glXGetFBConfigAttrib(dpy, c, GLX_STENCIL_SIZE, &s);
   printf("= config 0x%x alpha %d depth %d stencil %d\n", id, alpha, d, s);
   return c;
}

static void window_case(int alpha, int depth)
{
   GLXFBConfig c = config_of(alpha, depth, True, GLX_WINDOW_BIT);
   XVisualInfo *vi;
   GLXContext ctx;
   Window win = config_window_current(dpy, c, W, H, &vi, &ctx);
   print_renderer();
   setup_view(W, H);
   glDrawBuffer(GL_BACK);
   glReadBuffer(GL_BACK);
   bands();
   grab(W, H);
   /* both buffers: the front cleared to another colour first, then
    * scissored clears into GL_FRONT_AND_BACK over rows 0..15 */
   glDrawBuffer(GL_FRONT);
   glClearColor(0.7f, 0.3f, 0.1f, 0.6f);
   glClear(GL_COLOR_BUFFER_BIT);
   glDrawBuffer(GL_FRONT_AND_BACK);
   clear_band(0, 8, 2, false);
   glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
   clear_band(8, 8, 3, false);
   glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
   glReadBuffer(GL_FRONT);
   print_read_pixel("both: front", 127, 3);
   grab(W, H);
   glReadBuffer(GL_BACK);
   print_read_pixel("both: back", 127, 3);
   grab(W, H);
   glFinish();
   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   XDestroyWindow(dpy, win);
   XFree(vi);
}

static void pbuffer_case(int alpha)
{
   GLXFBConfig c = config_of(alpha, 0, False, GLX_PBUFFER_BIT);
   const int pattrs[] = { GLX_PBUFFER_WIDTH, W, GLX_PBUFFER_HEIGHT, H, None };
   GLXPbuffer pb = glXCreatePbuffer(dpy, c, pattrs);
   GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
   if (!pb || !ctx || !glXMakeContextCurrent(dpy, pb, pb, ctx)) {
      fprintf(stderr, "clearquad: no pbuffer\n");
      exit(1);
   }
   setup_view(W, H);
   bands();
   grab(W, H);
   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   glXDestroyPbuffer(dpy, pb);
}

int main(int argc, char **argv)
{
   if (argc != 3 || strcmp(argv[1], "--out") != 0) {
      fprintf(stderr, "usage: %s --out FILE.ppm\n", argv[0]);
      return 2;
   }
   out = argv[2];
   dpy = XOpenDisplay(NULL);
   if (!dpy) {
      fprintf(stderr, "clearquad: no display\n");
      return 1;
   }
   window_case(8, 0);
   window_case(0, 0);
   window_case(8, 24);
   pbuffer_case(0);
   XCloseDisplay(dpy);
   return 0;
}
