/*
 * accum - glAccum on GLX drawables, on Mesa's libGL and on fixgl's
 * (run_glx.py compare).  The oracle's window, pbuffer and pixmap colour
 * buffers are sRGB formats (GL_FRAMEBUFFER_SRGB off: drawing, reading and
 * copying are plain), and glAccum unpacks and packs through them: every
 * operation with values other than 1, a masked GL_RETURN, GL_RETURN into
 * both buffers, on a visual with alpha and one without, and a pbuffer
 * (not a pixmap: the oracle's drisw fails to show one on Xvfb, BadMatch
 * of X_ShmPutImage).  Every band is read back (glReadPixels, RGB then
 * alpha) into one PPM; a few pixels and the configs'
 * GLX_FRAMEBUFFER_SRGB_CAPABLE are printed.
 *
 *   accum --out FILE.ppm
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "glx_frames.h"

#ifndef GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB
#define GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB 0x20B2
#endif

#define W 256
#define H 48

static Display *dpy;
static const char *out;
static int images;

/* glReadPixels of the current read buffer: RGB, then alpha as grey */
static void grab(int w, int h)
{
   append_read_ppm(out, &images, w, h, 1);
}

/* every 8-bit value in every channel: rows of ramps, each row another
 * permutation */
static void ramps(int w, int h, int salt)
{
   static unsigned char img[W * H * 4];
   for (int y = 0; y < h; y++)
      for (int x = 0; x < w; x++) {
         unsigned char *p = &img[4 * (y * w + x)];
         p[0] = (unsigned char)(x + 37 * y + salt);
         p[1] = (unsigned char)(255 - x + 11 * y);
         p[2] = (unsigned char)(x * 7 + 3 * y + salt);
         p[3] = (unsigned char)(x * 13 + 5 * y);
      }
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glWindowPos2i(0, 0);
   glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, img);
}

static void band(int y, int h)
{
   glEnable(GL_SCISSOR_TEST);
   glScissor(0, y, W, h);
}

/* the accumulation operations, each in its own band of rows */
static void accum_bands(int w)
{
   (void)w;
   /* 20, 30, 105 at (0,0) first: the values of the issue */
   band(0, 1);
   glClearColor(20 / 255.0f, 30 / 255.0f, 105 / 255.0f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   print_read_pixel("cleared", 0, 0);
   band(0, 8);
   glAccum(GL_LOAD, 1.0f);
   glAccum(GL_RETURN, 0.6f);
   print_read_pixel("load 1 return 0.6", 0, 0);
   band(8, 8);
   glAccum(GL_LOAD, 0.5f);
   glAccum(GL_ACCUM, 0.3f);
   glAccum(GL_MULT, 1.7f);
   glAccum(GL_ADD, 0.05f);
   glAccum(GL_RETURN, 1.2f);
   print_read_pixel("load accum mult add return", 9, 8);
   band(16, 8);
   glAccum(GL_LOAD, 1.0f);
   glAccum(GL_RETURN, 1.0f);
   band(24, 8);
   glAccum(GL_LOAD, 0.9f);
   glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
   glAccum(GL_RETURN, 1.1f);
   glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
   print_read_pixel("masked return", 40, 24);
   band(32, 8);
   glAccum(GL_LOAD, 0.25f);
   glColor4f(0.8f, 0.2f, 0.4f, 0.6f);
   glRecti(0, 32, W, 40);
   glAccum(GL_ACCUM, 0.75f);
   glAccum(GL_RETURN, 1.0f);
   print_read_pixel("load clear accum return", 3, 33);
   band(40, 8);
   glAccum(GL_LOAD, -0.5f);
   glAccum(GL_ADD, 0.9f);
   glAccum(GL_MULT, 0.8f);
   glAccum(GL_RETURN, 2.0f);
   glDisable(GL_SCISSOR_TEST);
}

static void setup_view(int w, int h)
{
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, w, 0, h, -1, 1);
   glMatrixMode(GL_MODELVIEW);
}

static GLXFBConfig config_of(int alpha, int db, int drawable_type)
{
   int attrs[] = { GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, alpha,
                   GLX_ACCUM_RED_SIZE, 1, GLX_ACCUM_GREEN_SIZE, 1, GLX_ACCUM_BLUE_SIZE, 1,
                   GLX_ACCUM_ALPHA_SIZE, alpha ? 1 : 0, GLX_DOUBLEBUFFER, db,
                   GLX_DRAWABLE_TYPE, drawable_type, None };
   int n = 0;
   GLXFBConfig *cs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attrs, &n);
   if (!cs || n < 1) {
      fprintf(stderr, "accum: no config (alpha %d db %d type %d)\n", alpha, db, drawable_type);
      exit(1);
   }
   /* the first of exactly 8 bits a channel (not 10-10-10-2) */
   GLXFBConfig c = NULL;
   for (int i = 0; i < n && !c; i++) {
      int r = 0, a8 = 0;
      glXGetFBConfigAttrib(dpy, cs[i], GLX_RED_SIZE, &r);
      glXGetFBConfigAttrib(dpy, cs[i], GLX_ALPHA_SIZE, &a8);
      if (r == 8 && a8 == alpha)
         c = cs[i];
   }
   XFree(cs);
   if (!c) {
      fprintf(stderr, "accum: no 8-bit config\n");
      exit(1);
   }
   int id = 0, srgb = -1, a = 0, acc = 0;
   glXGetFBConfigAttrib(dpy, c, GLX_FBCONFIG_ID, &id);
   glXGetFBConfigAttrib(dpy, c, GLX_ALPHA_SIZE, &a);
   glXGetFBConfigAttrib(dpy, c, GLX_ACCUM_RED_SIZE, &acc);
   const int err = glXGetFBConfigAttrib(dpy, c, GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB, &srgb);
   printf("= config 0x%x alpha %d accum %d srgb capable %d (%d)\n", id, a, acc, srgb, err);
   return c;
}

/* a double-buffered window of config c: the bands in the back, then
 * GL_RETURN into both buffers */
static void window_case(int alpha)
{
   GLXFBConfig c = config_of(alpha, True, GLX_WINDOW_BIT);
   XVisualInfo *vi;
   GLXContext ctx;
   Window win = config_window_current(dpy, c, W, H, &vi, &ctx);
   print_renderer();
   setup_view(W, H);
   glDrawBuffer(GL_BACK);
   glReadBuffer(GL_BACK);
   ramps(W, H, 0);
   print_read_pixel("ramp", 9, 8);
   accum_bands(W);
   grab(W, H);
   /* both buffers: the front another image; rows 0..19 of the back get
    * the accumulation rows 20..39 (ORACLE-NOTES.md "Both buffers") */
   glDrawBuffer(GL_FRONT);
   ramps(W, H, 101);
   glDrawBuffer(GL_BACK);
   band(0, 20);
   glAccum(GL_LOAD, 0.7f);
   glDrawBuffer(GL_FRONT_AND_BACK);
   glAccum(GL_RETURN, 0.85f);
   glDisable(GL_SCISSOR_TEST);
   glReadBuffer(GL_FRONT);
   print_read_pixel("both: front", 5, 5);
   grab(W, H);
   glReadBuffer(GL_BACK);
   print_read_pixel("both: back", 5, 5);
   grab(W, H);
   glFinish();
   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   XDestroyWindow(dpy, win);
   XFree(vi);
}

static void pbuffer_case(void)
{
   GLXFBConfig c = config_of(0, False, GLX_PBUFFER_BIT);
   const int pattrs[] = { GLX_PBUFFER_WIDTH, W, GLX_PBUFFER_HEIGHT, H, None };
   GLXPbuffer pb = glXCreatePbuffer(dpy, c, pattrs);
   GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
   if (!pb || !ctx || !glXMakeContextCurrent(dpy, pb, pb, ctx)) {
      fprintf(stderr, "accum: no pbuffer\n");
      exit(1);
   }
   setup_view(W, H);
   ramps(W, H, 55);
   accum_bands(W);
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
      fprintf(stderr, "accum: no display\n");
      return 1;
   }
   window_case(0);
   window_case(8);
   pbuffer_case();
   XCloseDisplay(dpy);
   return 0;
}
