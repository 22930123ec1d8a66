/*
 * frontbuf - glDrawBuffer(GL_FRONT) / glReadBuffer(GL_FRONT) on a
 * double-buffered GLX window, on Mesa's libGL and on fixgl's (run_glx.py
 * compare): a fixed sequence of draws into the back and the front
 * buffer, the window (XGetImage) after each step, and glReadPixels of
 * the front and the back buffer at the end of some, all into one PPM.
 * On the oracle (Mesa's drisw): the front buffer is black at first (not
 * the window's image), glFlush/glFinish show it in the window when it
 * was drawn into, glXSwapBuffers shows the back buffer and leaves the
 * front as it was, and the back keeps its image after the swap.
 * (GL_FRONT_AND_BACK and GL_LEFT, which draw into both: frontback.c.)
 *
 *   frontbuf --out FILE.ppm
 */
#include <GL/gl.h>

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

/* glReadPixels of buf (GL_FRONT or GL_BACK), as a PPM, top row first */
static void grab_buffer(GLenum buf)
{
   glReadBuffer(buf);
   append_read_ppm(out, &images, W, H, 0);
}

static void tri(float r, float g, float b, float x0, float y0, float s)
{
   glColor3f(r, g, b);
   glBegin(GL_TRIANGLES);
   glVertex2f(x0, y0);
   glVertex2f(x0 + s, y0);
   glVertex2f(x0 + s * 0.3f, y0 + s);
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

int main(int argc, char **argv)
{
   if (argc != 3 || strcmp(argv[1], "--out") != 0) {
      fprintf(stderr, "usage: %s --out FILE.ppm\n", argv[0]);
      return 2;
   }
   out = argv[2];
   dpy = XOpenDisplay(NULL);
   if (!dpy) {
      fprintf(stderr, "frontbuf: no display\n");
      return 1;
   }
   int attrs[] = { GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8,
                   None };
   vi = glXChooseVisual(dpy, DefaultScreen(dpy), attrs);
   if (!vi) {
      fprintf(stderr, "frontbuf: no visual\n");
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
      fprintf(stderr, "frontbuf: no context\n");
      return 1;
   }
   print_renderer();
   glViewport(0, 0, W, H);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, W, 0, H, -1, 1);
   glMatrixMode(GL_MODELVIEW);

   GLint v = 0;
   glGetIntegerv(GL_DRAW_BUFFER, &v);
   printf("draw buffer 0x%x\n", (unsigned)v);

   /* 1: the back buffer red, swapped: the window red */
   glClearColor(1, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   tri(1, 1, 1, 4, 4, 20);
   glBegin(GL_TRIANGLES);   /* a shaded one: the image has many colours */
   glColor3f(1, 1, 0);
   glVertex2f(30, 30);
   glColor3f(0, 1, 1);
   glVertex2f(62, 34);
   glColor3f(0.2f, 0.1f, 0.9f);
   glVertex2f(40, 46);
   glEnd();
   glXSwapBuffers(dpy, win);
   glFinish();
   grab_window();

   /* 2: into the front: a green rectangle and a blue triangle, glFlush */
   glDrawBuffer(GL_FRONT);
   clear_rect(0, 1, 0, 30, 10, 20, 20);
   tri(0, 0, 1, 36, 14, 16);
   glFlush();
   grab_window();
   grab_buffer(GL_FRONT);
   grab_buffer(GL_BACK);

   /* 3: into the back: the window does not change until the swap */
   glDrawBuffer(GL_BACK);
   glClearColor(0, 0, 0.5f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   tri(1, 1, 0, 10, 20, 24);
   glFlush();
   grab_window();
   grab_buffer(GL_FRONT);

   /* 4: the swap: the window shows the back buffer; the front is it */
   glXSwapBuffers(dpy, win);
   glFinish();
   grab_window();
   grab_buffer(GL_FRONT);
   grab_buffer(GL_BACK);

   /* 5: front again, with glFinish, over the swapped image */
   glDrawBuffer(GL_FRONT);
   tri(0, 1, 1, 2, 2, 30);
   glFinish();
   grab_window();
   grab_buffer(GL_FRONT);

   /* 6: back again, swapped: the window shows the back buffer */
   glDrawBuffer(GL_BACK);
   tri(1, 0, 1, 40, 2, 20);
   glXSwapBuffers(dpy, win);
   glFinish();
   grab_window();
   grab_buffer(GL_FRONT);

   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   XDestroyWindow(dpy, win);
   XCloseDisplay(dpy);
   printf("%d images\n", images);
   return 0;
}
