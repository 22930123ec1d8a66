/*
 * readdraw - a separate read drawable (glXMakeContextCurrent(dpy, draw,
 * read, ctx) with read != draw), on Mesa's libGL and on fixgl's
 * (run_glx.py compare).  Two double-buffered windows of one visual and
 * different sizes, A (64x48) and B (56x40), each drawn first on its own
 * (front and back of A differ); then with B drawn and A read:
 * glReadPixels of A's back and front (colour, clipped to A's size) and of
 * its depth, glCopyPixels and glCopyTexImage2D from A into B, glAccum
 * (an error); B's back read once B is the read drawable again, B's
 * window after the swap; A read after the context left it (its buffers
 * gone: black) and after a second context bound B while the first stayed
 * on A (kept); a glXCreateWindow window and a pbuffer read the same way
 * after their context left them (kept); all into one PPM.
 *
 *   readdraw --out FILE.ppm
 */
#include <GL/gl.h>

#include "glx_frames.h"

#define AW 64
#define AH 48
#define BW 56
#define BH 40

static Display *dpy;
static XVisualInfo *vi;
static const char *out;
static int images;

/* glReadPixels of (0, 0, w, h) from buf of the read drawable, as a PPM */
static void grab_buffer(GLenum buf, int w, int h)
{
   glReadBuffer(buf);
   append_read_ppm(out, &images, w, h, 0);
}

static void shaded_tri(float x0, float y0, float s, float z)
{
   glBegin(GL_TRIANGLES);
   glColor3f(1, 0.8f, 0.1f);
   glVertex3f(x0, y0, z);
   glColor3f(0.1f, 0.9f, 0.7f);
   glVertex3f(x0 + s, y0 + s * 0.2f, -z);
   glColor3f(0.6f, 0.2f, 1);
   glVertex3f(x0 + s * 0.4f, y0 + s, z * 0.5f);
   glEnd();
}

static void setup_view(int w, int h)
{
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, w, 0, h, -1, 1);
   glMatrixMode(GL_MODELVIEW);
}

static Window make_window(int w, int h)
{
   XSetWindowAttributes swa;
   swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
   swa.background_pixel = 0;
   swa.border_pixel = 0;
   Window win = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, (unsigned)w, (unsigned)h, 0,
                              vi->depth, InputOutput, vi->visual,
                              CWColormap | CWBackPixel | CWBorderPixel, &swa);
   XMapWindow(dpy, win);
   return win;
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
      fprintf(stderr, "readdraw: no display\n");
      return 1;
   }
   int attrs[] = { GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8,
                   GLX_DEPTH_SIZE, 1, GLX_ACCUM_RED_SIZE, 1, GLX_ACCUM_GREEN_SIZE, 1,
                   GLX_ACCUM_BLUE_SIZE, 1, None };
   vi = glXChooseVisual(dpy, DefaultScreen(dpy), attrs);
   if (!vi) {
      fprintf(stderr, "readdraw: no visual\n");
      return 1;
   }
   Window a = make_window(AW, AH), b = make_window(BW, BH);
   XSync(dpy, False);
   GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
   if (!ctx || !glXMakeCurrent(dpy, a, ctx)) {
      fprintf(stderr, "readdraw: no context\n");
      return 1;
   }
   print_renderer();

   /* A: a back and a front of their own, a depth image */
   setup_view(AW, AH);
   glClearColor(0.4f, 0.1f, 0.1f, 1);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);
   shaded_tri(2, 2, 50, -0.6f);
   glDisable(GL_DEPTH_TEST);
   glDrawBuffer(GL_FRONT);
   glClearColor(0.1f, 0.3f, 0.5f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   shaded_tri(20, 10, 40, 0);
   glDrawBuffer(GL_BACK);
   glFinish();

   /* B drawn, A read (straight from A: A stays bound, its buffers too) */
   if (!glXMakeContextCurrent(dpy, b, a, ctx)) {
      fprintf(stderr, "readdraw: glXMakeContextCurrent failed\n");
      return 1;
   }
   setup_view(BW, BH);
   glClearColor(0.05f, 0.05f, 0.2f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   shaded_tri(30, 2, 24, 0);
   printf("= read drawable is A: %d, draw drawable is B: %d\n",
          glXGetCurrentReadDrawable() == a, glXGetCurrentDrawable() == b);
   GLint v = 0;
   glGetIntegerv(GL_READ_BUFFER, &v);
   printf("= read buffer 0x%x\n", (unsigned)v);
   grab_buffer(GL_BACK, AW, AH);    /* A's back, all of it */
   grab_buffer(GL_FRONT, AW, AH);   /* A's front */
   static unsigned char depth[AW * AH];
   glReadPixels(0, 0, AW, AH, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, depth);
   unsigned long sum = 0;
   for (int i = 0; i < AW * AH; i++)
      sum = sum * 31 + depth[i];
   printf("= A's depth: hash %lu, corner %u, middle %u\n", sum, depth[0],
          depth[(AH / 2) * AW + AW / 3]);
   printf("= error 0x%x\n", (unsigned)glGetError());

   /* glCopyPixels from A's back and front into B's back (the source
    * clipped to A, the destination to B) */
   glReadBuffer(GL_BACK);
   glRasterPos2i(2, 2);
   glCopyPixels(30, 20, 30, 26, GL_COLOR);
   glReadBuffer(GL_FRONT);
   glRasterPos2i(36, 26);
   glCopyPixels(40, 20, 20, 12, GL_COLOR);
   /* glCopyTexImage2D from A's back, drawn on B */
   glReadBuffer(GL_BACK);
   GLuint tex = 0;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D, tex);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 8, 32, 32, 0);
   glEnable(GL_TEXTURE_2D);
   glColor3f(1, 1, 1);
   glBegin(GL_QUADS);
   glTexCoord2f(0, 0);
   glVertex2f(34, 4);
   glTexCoord2f(1, 0);
   glVertex2f(54, 4);
   glTexCoord2f(1, 1);
   glVertex2f(54, 22);
   glTexCoord2f(0, 1);
   glVertex2f(34, 22);
   glEnd();
   glDisable(GL_TEXTURE_2D);
   printf("= error 0x%x\n", (unsigned)glGetError());
   /* glAccum with another read drawable: GL_INVALID_OPERATION, nothing
    * loaded or returned */
   glReadBuffer(GL_FRONT);
   glAccum(GL_LOAD, 1.0f);
   printf("= glAccum(GL_LOAD): error 0x%x\n", (unsigned)glGetError());
   glAccum(GL_RETURN, 0.7f);
   printf("= glAccum(GL_RETURN): error 0x%x\n", (unsigned)glGetError());
   glFinish();

   /* B read again: its back, then its window after the swap */
   if (!glXMakeCurrent(dpy, b, ctx)) {
      fprintf(stderr, "readdraw: cannot bind B again\n");
      return 1;
   }
   grab_buffer(GL_BACK, BW, BH);
   glXSwapBuffers(dpy, b);
   glFinish();
   XSync(dpy, False);
   write_drawable_ppm(dpy, b, vi->visual, out, images++ > 0);

   /* the context left A (bound to B alone): A, a plain X window no
    * context is bound to, lost its buffers; bound again they are black */
   if (!glXMakeContextCurrent(dpy, b, a, ctx)) {
      fprintf(stderr, "readdraw: cannot read A again\n");
      return 1;
   }
   grab_buffer(GL_BACK, AW, AH);
   grab_buffer(GL_FRONT, AW, AH);
   glReadPixels(0, 0, AW, AH, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, depth);
   printf("= A's depth again: corner %u, middle %u\n", depth[0], depth[(AH / 2) * AW + AW / 3]);

   /* A drawn, then a second context binds B while ctx stays bound to A:
    * A keeps its buffers */
   glXMakeCurrent(dpy, a, ctx);
   setup_view(AW, AH);
   glClearColor(0.3f, 0.6f, 0.2f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   shaded_tri(4, 4, 30, 0);
   GLXContext ctx2 = glXCreateContext(dpy, vi, NULL, True);
   if (!ctx2 || !glXMakeCurrent(dpy, b, ctx2)) {
      fprintf(stderr, "readdraw: no second context\n");
      return 1;
   }
   glClear(GL_COLOR_BUFFER_BIT);
   glXMakeCurrent(dpy, a, ctx);
   grab_buffer(GL_BACK, AW, AH);

   /* GLX 1.3 drawables keep their buffers: a pbuffer and a glXCreateWindow
    * window drawn, left for B, then read through (B, drawable) */
   int fbattrs[] = { GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DRAWABLE_TYPE,
                     GLX_WINDOW_BIT | GLX_PBUFFER_BIT, GLX_DOUBLEBUFFER, True, GLX_RED_SIZE, 8,
                     GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_X_VISUAL_TYPE, GLX_TRUE_COLOR, None };
   int n = 0;
   GLXFBConfig *cf = glXChooseFBConfig(dpy, DefaultScreen(dpy), fbattrs, &n);
   if (!cf || n < 1) {
      fprintf(stderr, "readdraw: no FBConfig\n");
      return 1;
   }
   XVisualInfo *cvi = glXGetVisualFromFBConfig(dpy, cf[0]);
   XSetWindowAttributes swa;
   swa.colormap = XCreateColormap(dpy, RootWindow(dpy, cvi->screen), cvi->visual, AllocNone);
   swa.border_pixel = 0;
   Window xc = XCreateWindow(dpy, RootWindow(dpy, cvi->screen), 0, 0, AW, AH, 0, cvi->depth,
                             InputOutput, cvi->visual, CWColormap | CWBorderPixel, &swa);
   Window xd = XCreateWindow(dpy, RootWindow(dpy, cvi->screen), 0, 0, BW, BH, 0, cvi->depth,
                             InputOutput, cvi->visual, CWColormap | CWBorderPixel, &swa);
   XMapWindow(dpy, xc);
   XMapWindow(dpy, xd);
   XSync(dpy, False);
   GLXWindow gw = glXCreateWindow(dpy, cf[0], xc, NULL);
   int pbattrs[] = { GLX_PBUFFER_WIDTH, AW, GLX_PBUFFER_HEIGHT, AH, None };
   GLXPbuffer pb = glXCreatePbuffer(dpy, cf[0], pbattrs);
   GLXContext nc = glXCreateNewContext(dpy, cf[0], GLX_RGBA_TYPE, NULL, True);
   if (!gw || !pb || !nc || !glXMakeContextCurrent(dpy, gw, gw, nc)) {
      fprintf(stderr, "readdraw: no GLX 1.3 drawables\n");
      return 1;
   }
   setup_view(AW, AH);
   glClearColor(0.7f, 0.2f, 0.5f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   shaded_tri(10, 6, 36, 0);
   glXMakeContextCurrent(dpy, pb, pb, nc);
   setup_view(AW, AH);
   glClearColor(0.1f, 0.5f, 0.5f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   shaded_tri(2, 12, 30, 0);
   glXMakeContextCurrent(dpy, xd, xd, nc);
   glClear(GL_COLOR_BUFFER_BIT);
   glXMakeContextCurrent(dpy, xd, gw, nc);
   grab_buffer(GL_BACK, AW, AH);
   glXMakeContextCurrent(dpy, xd, pb, nc);
   grab_buffer(GL_BACK, AW, AH);

   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, nc);
   glXDestroyPbuffer(dpy, pb);
   glXDestroyWindow(dpy, gw);
   XFree(cf);
   glXDestroyContext(dpy, ctx2);
   glXDestroyContext(dpy, ctx);
   XDestroyWindow(dpy, a);
   XDestroyWindow(dpy, b);
   XCloseDisplay(dpy);
   printf("%d images\n", images);
   return 0;
}
