/*
 * frontback - glDrawBuffer(GL_FRONT_AND_BACK) and GL_LEFT on a
 * double-buffered GLX window (depth, stencil, accumulation buffer), on
 * Mesa's libGL and on fixgl's (run_glx.py compare).  The two buffers
 * first get different images, then every kind of colour write goes into
 * both: clears (whole and scissored), shaded triangles under a depth
 * test, blended and logic-op triangles (each buffer blends with its own
 * destination), a stencil-tested pair, wide lines and points,
 * glDrawPixels, glBitmap, glCopyPixels and glAccum(GL_RETURN); an
 * occlusion query counts the fragments once.  Both buffers are read back
 * (glReadPixels) and the window grabbed after glFlush and after the swap,
 * all into one PPM; the errors of GL_RIGHT, GL_FRONT_RIGHT and
 * GL_BACK_RIGHT (no right buffers: GL_INVALID_OPERATION) are printed.
 *
 *   frontback --out FILE.ppm
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "glx_frames.h"

#define W 64
#define H 48

static Display *dpy;
static Window win;
static XVisualInfo *vi;
static const char *out;
static int images;

static void grab_window(void)
{
   XSync(dpy, False);
   write_drawable_ppm(dpy, win, vi->visual, out, images++ > 0);
}

/* glReadPixels of buf, as a PPM, top row first */
static void grab_buffer(GLenum buf)
{
   GLint old = 0;
   glGetIntegerv(GL_READ_BUFFER, &old);
   glReadBuffer(buf);
   append_read_ppm(out, &images, W, H, 0);
   glReadBuffer((GLenum)old);
}

static void shaded_tri(float x0, float y0, float s, float z, float a)
{
   glBegin(GL_TRIANGLES);
   glColor4f(1, 0.8f, 0.1f, a);
   glVertex3f(x0, y0, z);
   glColor4f(0.1f, 0.9f, 0.7f, a);
   glVertex3f(x0 + s, y0 + s * 0.2f, z);
   glColor4f(0.6f, 0.2f, 1, a);
   glVertex3f(x0 + s * 0.4f, y0 + s, z);
   glEnd();
}

static void clear_rect(float r, float g, float b, int x, int y, int w, int h)
{
   glEnable(GL_SCISSOR_TEST);
   glScissor(x, y, w, h);
   glClearColor(r, g, b, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT);
   glDisable(GL_SCISSOR_TEST);
}

static void check_error(const char *what)
{
   GLenum e = glGetError();
   printf("= %s: error 0x%x\n", what, (unsigned)e);
}

/* the draws of one round, into whatever glDrawBuffer selects */
static void draw_round(int round)
{
   const float o = (float)round * 3.0f;
   /* a scissored clear (a quad) */
   clear_rect(0.1f, 0.2f, 0.9f, 2, 30, 20, 14);

   /* the depth test: the near triangle first, the far one fails where
    * they overlap, in both buffers */
   glClear(GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_LESS);
   shaded_tri(4 + o, 4, 26, -0.5f, 1);
   shaded_tri(12 + o, 8, 26, 0.5f, 1);
   glDisable(GL_DEPTH_TEST);

   /* blending: each buffer with its own destination */
   glEnable(GL_BLEND);
   glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
   shaded_tri(30 + o, 2, 30, 0, 0.45f);
   glDisable(GL_BLEND);

   /* a logic op */
   glEnable(GL_COLOR_LOGIC_OP);
   glLogicOp(GL_XOR);
   shaded_tri(36, 20 + o, 24, 0, 1);
   glDisable(GL_COLOR_LOGIC_OP);

   /* the stencil test: the second triangle only where the first was not */
   glClear(GL_STENCIL_BUFFER_BIT);
   glEnable(GL_STENCIL_TEST);
   glStencilFunc(GL_EQUAL, 0, 0xff);
   glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
   glColor3f(0.9f, 0.1f, 0.3f);
   glRectf(40, 30, 56, 44);
   glColor3f(0.2f, 0.9f, 0.2f);
   glRectf(46, 34, 62 - o, 47);
   glDisable(GL_STENCIL_TEST);

   /* wide lines and points, a smooth line */
   glLineWidth(3);
   glBegin(GL_LINES);
   glColor3f(1, 1, 1);
   glVertex2f(2, 46 - o);
   glColor3f(0, 0.5f, 1);
   glVertex2f(60, 26);
   glEnd();
   glLineWidth(1);
   glEnable(GL_LINE_SMOOTH);
   glEnable(GL_BLEND);
   glBegin(GL_LINES);
   glVertex2f(3, 2);
   glVertex2f(61, 20 + o);
   glEnd();
   glDisable(GL_BLEND);
   glDisable(GL_LINE_SMOOTH);
   glPointSize(4);
   glBegin(GL_POINTS);
   glColor3f(1, 0.5f, 0);
   glVertex2f(8.5f + o, 22.5f);
   glVertex2f(20.5f, 40.5f);
   glEnd();
   glPointSize(1);

   /* glDrawPixels, glBitmap, glCopyPixels */
   static unsigned char img[8 * 6 * 4];
   for (int i = 0; i < 8 * 6; i++) {
      img[4 * i + 0] = (unsigned char)(i * 5);
      img[4 * i + 1] = (unsigned char)(255 - i * 3);
      img[4 * i + 2] = (unsigned char)(i * 11 + round * 40);
      img[4 * i + 3] = 255;
   }
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glRasterPos2f(24, 36);
   glDrawPixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, img);
   static const GLubyte bits[8] = { 0x81, 0x42, 0x24, 0x18, 0x18, 0x24, 0x42, 0xff };
   glColor3f(1, 1, 0.2f);
   glRasterPos2f(50, 4);
   glBitmap(8, 8, 0, 0, 9, 0, bits);
   glBitmap(8, 8, 0, 0, 0, 0, bits);
   glRasterPos2f(52, 14);
   glCopyPixels(0, 0, 10, 8, GL_COLOR);
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
      fprintf(stderr, "frontback: no display\n");
      return 1;
   }
   int attrs[] = { GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8,
                   GLX_DEPTH_SIZE, 1, GLX_STENCIL_SIZE, 1, GLX_ACCUM_RED_SIZE, 1,
                   GLX_ACCUM_GREEN_SIZE, 1, GLX_ACCUM_BLUE_SIZE, 1, None };
   vi = glXChooseVisual(dpy, DefaultScreen(dpy), attrs);
   if (!vi) {
      fprintf(stderr, "frontback: no visual\n");
      return 1;
   }
   XSetWindowAttributes swa;
   swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
   swa.background_pixel = 0;
   swa.border_pixel = 0;
   win = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, W, H, 0, vi->depth, InputOutput,
                       vi->visual, CWColormap | CWBackPixel | CWBorderPixel, &swa);
   XMapWindow(dpy, win);
   XSync(dpy, False);
   GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
   if (!ctx || !glXMakeCurrent(dpy, win, ctx)) {
      fprintf(stderr, "frontback: no context\n");
      return 1;
   }
   print_renderer();
   GLint bits[4] = { 0 };
   glGetIntegerv(GL_DEPTH_BITS, &bits[0]);
   glGetIntegerv(GL_STENCIL_BITS, &bits[1]);
   glGetIntegerv(GL_ACCUM_RED_BITS, &bits[2]);
   glGetIntegerv(GL_DOUBLEBUFFER, &bits[3]);
   printf("= depth %d stencil %d accum %d doublebuffer %d\n", bits[0], bits[1], bits[2], bits[3]);
   glViewport(0, 0, W, H);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, W, 0, H, -1, 1);
   glMatrixMode(GL_MODELVIEW);

   /* 1: different images in the two buffers */
   glDrawBuffer(GL_BACK);
   glClearColor(0.5f, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   shaded_tri(0, 0, 40, 0, 1);
   glDrawBuffer(GL_FRONT);
   glClearColor(0, 0.3f, 0.1f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   shaded_tri(20, 6, 44, 0, 1);
   glFlush();
   grab_window();
   grab_buffer(GL_FRONT);
   grab_buffer(GL_BACK);

   /* 2: GL_FRONT_AND_BACK over them; an occlusion query counts once */
   glDrawBuffer(GL_FRONT_AND_BACK);
   check_error("glDrawBuffer(GL_FRONT_AND_BACK)");
   GLint v = 0;
   glGetIntegerv(GL_DRAW_BUFFER, &v);
   printf("= draw buffer 0x%x\n", (unsigned)v);
   GLuint q = 0;
   glGenQueries(1, &q);
   glBeginQuery(GL_SAMPLES_PASSED, q);
   draw_round(0);
   glEndQuery(GL_SAMPLES_PASSED);
   GLuint samples = 0;
   glGetQueryObjectuiv(q, GL_QUERY_RESULT, &samples);
   printf("= samples passed %u\n", samples);
   /* the accumulation buffer from the front (the read buffer of
    * GL_FRONT_AND_BACK names the front), returned into both */
   /* (values of 1 only: the oracle's window buffers are sRGB formats,
    * which its accumulation unpacks and packs (ORACLE-NOTES.md "Both
    * buffers"); 1 gives the 8-bit values back) */
   glReadBuffer(GL_FRONT);
   glAccum(GL_LOAD, 1.0f);
   /* (the back takes the accumulation rows one region's height above:
    * the oracle's loop; 4 + 2 * 18 rows stay inside the buffer) */
   glEnable(GL_SCISSOR_TEST);
   glScissor(8, 4, 40, 18);
   glAccum(GL_RETURN, 1.0f);
   glDisable(GL_SCISSOR_TEST);
   glFlush();
   grab_window();
   grab_buffer(GL_FRONT);
   grab_buffer(GL_BACK);

   /* 3: a whole clear and the same draws under GL_LEFT */
   glDrawBuffer(GL_LEFT);
   check_error("glDrawBuffer(GL_LEFT)");
   glClearColor(0.2f, 0.2f, 0.25f, 1);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glDrawBuffer(GL_BACK);
   shaded_tri(0, 20, 30, 0, 1);   /* the back differs again */
   glDrawBuffer(GL_LEFT);
   draw_round(1);
   glFinish();
   grab_window();
   grab_buffer(GL_FRONT);
   grab_buffer(GL_BACK);

   /* 4: right buffers do not exist; the draw buffer stays GL_LEFT */
   glDrawBuffer(GL_RIGHT);
   check_error("glDrawBuffer(GL_RIGHT)");
   glDrawBuffer(GL_FRONT_RIGHT);
   check_error("glDrawBuffer(GL_FRONT_RIGHT)");
   glDrawBuffer(GL_BACK_RIGHT);
   check_error("glDrawBuffer(GL_BACK_RIGHT)");
   glGetIntegerv(GL_DRAW_BUFFER, &v);
   printf("= draw buffer 0x%x\n", (unsigned)v);

   /* 5: the swap shows the back; back to GL_BACK only */
   glXSwapBuffers(dpy, win);
   glFinish();
   grab_window();
   glDrawBuffer(GL_BACK);
   shaded_tri(10, 10, 20, 0, 1);
   grab_buffer(GL_FRONT);
   grab_buffer(GL_BACK);

   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   XDestroyWindow(dpy, win);
   XCloseDisplay(dpy);
   printf("%d images\n", images);
   return 0;
}
