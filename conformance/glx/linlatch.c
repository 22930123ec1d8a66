/*
 * linlatch - when the oracle's scene permits llvmpipe's linear path
 * (ORACLE-NOTES.md "GLX linear rectangles"): a scissored glClear on a
 * GLX window without depth and stencil is truncated, trunc(c * 256 - c),
 * in a scene that permits it, and rounded in a scene begun by a
 * whole-buffer clear before the context's first draw.  Each case runs in
 * a context of its own (the latch is the context's) on one window, with
 * eight clear colours, and prints pixel (10, 10) of the scissored clear
 * ("= " lines, compared by run_glx.py); the pixels also go to the PPM as
 * 8 x 8 blocks (a row a case, a column a colour).
 *
 * Probed on Mesa's libGL: a scissored clear as the context's first
 * command, or after a flush (glFinish, glFlush, glReadPixels,
 * glXSwapBuffers, glCopyPixels, glCopyTexImage2D), or in a scene begun
 * by a triangle, or begun by a whole clear after a triangle and a
 * glFinish: truncated; after a whole clear that began the context's
 * first scene, with glAccum (no accumulation buffer: an error),
 * glDrawPixels, glBitmap or a change of draw buffer between: rounded.
 * On a window with an accumulation buffer (and still no depth or
 * stencil), glAccum(GL_LOAD) or glAccum(GL_RETURN) between: truncated
 * (the oracle maps the colour buffer: a flush).
 *
 *   linlatch --out FILE.ppm
 */
#include <GL/gl.h>
#include <stdbool.h>

#include "glx_frames.h"

#define W 256
#define H 96
#define NCOLOURS 8

static const float colours[NCOLOURS][4] = {
   { 0.1f, 0.5f, 0.9f, 0.45f },   { 0.3f, 0.7f, 0.2f, 0.6f },
   { 0.45f, 0.05f, 0.65f, 0.95f }, { 0.9f, 0.1f, 0.5f, 0.2f },
   { 0.2f, 0.4f, 0.6f, 0.8f },    { 0.7f, 0.3f, 0.15f, 0.35f },
   { 0.55f, 0.85f, 0.25f, 0.5f }, { 0.05f, 0.95f, 0.35f, 0.65f },
};

static const float *C;

static void scissored_clear(void)
{
   scissored_clear_of(C);
}

/* a triangle in another tile than the scissored clear's */
static void tri(void)
{
   glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
   glBegin(GL_TRIANGLES);
   glVertex2i(200, 80);
   glVertex2i(210, 80);
   glVertex2i(200, 90);
   glEnd();
}

static const char *const names[] = {
   "scissored clear first", "clear, scissored clear", "clear, finish, scissored clear",
   "clear, flush, scissored clear", "clear, read pixels, scissored clear",
   "clear, swap, scissored clear", "triangle, clear, scissored clear",
   "triangle, finish, clear, scissored clear", "clear, copy pixels, scissored clear",
   "clear, copy tex image, scissored clear", "clear, accum error, scissored clear",
   "clear, draw pixels, scissored clear", "clear, bitmap, scissored clear",
   "clear, draw buffer front and back, scissored clear",
   "scissored clear, clear, scissored clear", "clear, clear, scissored clear",
   "accum window: clear, accum load, scissored clear",
   "accum window: clear, accum return, scissored clear",
};
#define FIRST_ACCUM_CASE 16

/* a double-buffered B8G8R8A8 config without depth and stencil, with an
 * accumulation buffer or without */
static GLXFBConfig config_of(Display *dpy, int accum)
{
   int attrs[] = { GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, 8,
                   GLX_DEPTH_SIZE, 0, GLX_ACCUM_RED_SIZE, accum ? 16 : 0, GLX_DOUBLEBUFFER, True,
                   GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, None };
   int n = 0;
   GLXFBConfig *cs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attrs, &n);
   GLXFBConfig c = NULL;
   for (int i = 0; cs && i < n && !c; i++) {
      int r = 0, a = 0, d = -1, s = -1, ac = -1;
      glXGetFBConfigAttrib(dpy, cs[i], GLX_RED_SIZE, &r);
      glXGetFBConfigAttrib(dpy, cs[i], GLX_ALPHA_SIZE, &a);
      glXGetFBConfigAttrib(dpy, cs[i], GLX_DEPTH_SIZE, &d);
      glXGetFBConfigAttrib(dpy, cs[i], GLX_STENCIL_SIZE, &s);
      glXGetFBConfigAttrib(dpy, cs[i], GLX_ACCUM_RED_SIZE, &ac);
      if (r == 8 && a == 8 && d == 0 && s == 0 && (ac > 0) == (accum != 0))
         c = cs[i];
   }
   if (cs)
      XFree(cs);
   if (!c) {
      fprintf(stderr, "linlatch: no config without depth and stencil (accum %d)\n", accum);
      exit(1);
   }
   return c;
}

static void run_case(Display *dpy, Window win, int k)
{
   unsigned char q[4];
   switch (k) {
   case 0: scissored_clear(); break;
   case 1: whole_clear(); scissored_clear(); break;
   case 2: whole_clear(); glFinish(); scissored_clear(); break;
   case 3: whole_clear(); glFlush(); scissored_clear(); break;
   case 4:
      whole_clear();
      glReadPixels(100, 50, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, q);
      scissored_clear();
      break;
   case 5: whole_clear(); glXSwapBuffers(dpy, win); scissored_clear(); break;
   case 6: tri(); whole_clear(); scissored_clear(); break;
   case 7: tri(); glFinish(); whole_clear(); scissored_clear(); break;
   case 8: whole_clear(); glCopyPixels(100, 50, 4, 4, GL_COLOR); scissored_clear(); break;
   case 9: {
      whole_clear();
      GLuint t;
      glGenTextures(1, &t);
      glBindTexture(GL_TEXTURE_2D, t);
      glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 100, 50, 4, 4, 0);
      scissored_clear();
      glDeleteTextures(1, &t);
      break;
   }
   case 10: whole_clear(); glAccum(GL_LOAD, 1.0f); scissored_clear(); break;
   case 11: {
      static const unsigned char px[16 * 4];
      whole_clear();
      glRasterPos2i(150, 50);
      glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
      scissored_clear();
      break;
   }
   case 12: {
      static const unsigned char bm[8] = { 0xff };
      whole_clear();
      glRasterPos2i(150, 50);
      glBitmap(8, 8, 0, 0, 0, 0, bm);
      scissored_clear();
      break;
   }
   case 13:
      whole_clear();
      glDrawBuffer(GL_FRONT);
      glDrawBuffer(GL_BACK);
      scissored_clear();
      break;
   case 14: scissored_clear(); whole_clear(); scissored_clear(); break;
   case 15: whole_clear(); whole_clear(); scissored_clear(); break;
   case 16: whole_clear(); glAccum(GL_LOAD, 1.0f); scissored_clear(); break;
   default: whole_clear(); glAccum(GL_RETURN, 1.0f); scissored_clear(); break;
   }
}

int main(int argc, char **argv)
{
   struct frames_opts o;
   frames_parse(argc, argv, &o, 1);
   Display *dpy = XOpenDisplay(NULL);
   if (!dpy) {
      fprintf(stderr, "linlatch: no display\n");
      return 1;
   }
   /* double-buffered B8G8R8A8 windows without depth and stencil, the
    * second with an accumulation buffer */
   GLXFBConfig c = config_of(dpy, 0), c_accum = config_of(dpy, 1);
   XVisualInfo *vi, *vi_accum;
   GLXContext first;
   Window win = config_window_current(dpy, c, W, H, &vi, &first);
   print_renderer();
   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, first);
   Window win_accum = config_window_current(dpy, c_accum, W, H, &vi_accum, &first);
   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, first);

   enum { NCASES = (int)(sizeof names / sizeof names[0]) };
   static unsigned char img[NCASES * 8][NCOLOURS * 8][3];
   for (int k = 0; k < NCASES; k++) {
      for (int ci = 0; ci < NCOLOURS; ci++) {
         /* a context of its own: no draw validated before the case */
         const bool accum = k >= FIRST_ACCUM_CASE;
         const Window w = accum ? win_accum : win;
         GLXContext ctx = glXCreateNewContext(dpy, accum ? c_accum : c, GLX_RGBA_TYPE, NULL, True);
         if (!ctx || !glXMakeCurrent(dpy, w, ctx)) {
            fprintf(stderr, "linlatch: no context\n");
            return 1;
         }
         pixel_view(W, H);
         C = colours[ci];
         run_case(dpy, w, k);
         unsigned char p[4];
         glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
         printf("= %s, colour %d: %d %d %d %d\n", names[k], ci, p[0], p[1], p[2], p[3]);
         for (int y = 0; y < 8; y++)
            for (int x = 0; x < 8; x++)
               memcpy(img[k * 8 + y][ci * 8 + x], p, 3);
         glXMakeCurrent(dpy, None, NULL);
         glXDestroyContext(dpy, ctx);
      }
   }
   FILE *f = fopen(o.out, "wb");
   if (!f) {
      fprintf(stderr, "linlatch: cannot write %s\n", o.out);
      return 1;
   }
   fprintf(f, "P6\n%d %d\n255\n", NCOLOURS * 8, NCASES * 8);
   fwrite(img, 1, sizeof img, f);
   fclose(f);
   XDestroyWindow(dpy, win);
   XDestroyWindow(dpy, win_accum);
   XFree(vi);
   XFree(vi_accum);
   XCloseDisplay(dpy);
   return 0;
}
