/*
 * glxwindow - glXCreateWindow's GLXWindow is an XID of its own (the
 * oracle's CreateDrawable: XAllocID, X_GLXCreateWindow), so the X window
 * made current beside it has buffers of its own; glXDestroyWindow and
 * the X errors of bad windows, configs of another visual and unknown or
 * twice destroyed GLXWindows, on Mesa's libGL and on fixgl's (run_glx.py
 * compare).  The errors are printed relative to the GLX error base.
 *
 *   glxwindow --out FILE.ppm
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include "glx_frames.h"

#define W 40
#define H 30

static Display *dpy;
static int glx_error_base, glx_event_base;

static int on_error(Display *d, XErrorEvent *ev)
{
   (void)d;
   const int code = ev->error_code;
   if (code >= glx_error_base && code < glx_error_base + 20)
      printf("= error GLX+%d request %d.%d\n", code - glx_error_base, ev->request_code == 0 ? 0 : 1,
             ev->minor_code);
   else
      printf("= error %d request %d.%d\n", code, ev->request_code >= 128 ? 128 : ev->request_code,
             ev->minor_code);
   return 0;
}

static void settle(const char *what)
{
   XSync(dpy, False);
   printf("= -- %s\n", what);
}

static void print_pixel(const char *what)
{
   unsigned char p[4], q[4];
   glReadPixels(W / 2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
   glReadPixels(W / 2, H - 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, q);
   printf("= %s: %d %d %d, %d %d %d\n", what, p[0], p[1], p[2], q[0], q[1], q[2]);
}

static void clear(float r, float g, float b)
{
   glClearColor(r, g, b, 1);
   glClear(GL_COLOR_BUFFER_BIT);
}

static void shaded_tri(float s)
{
   glBegin(GL_TRIANGLES);
   glColor3f(1, 0.8f, 0.2f);
   glVertex2f(-s, -s);
   glColor3f(0.2f, 1, 0.6f);
   glVertex2f(s, -s * 0.5f);
   glColor3f(0.6f, 0.2f, 1);
   glVertex2f(0, s);
   glEnd();
}

static Window make_window(XVisualInfo *vi)
{
   XSetWindowAttributes swa;
   swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
   swa.background_pixel = 0;
   swa.border_pixel = 0;
   Window w = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, W, H, 0, vi->depth, InputOutput,
                            vi->visual, CWColormap | CWBackPixel | CWBorderPixel, &swa);
   XMapWindow(dpy, w);
   XSync(dpy, False);
   return w;
}

static GLXFBConfig choose(int alpha)
{
   int attrs[] = { GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, alpha,
                   GLX_DOUBLEBUFFER, False, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, None };
   int n = 0;
   GLXFBConfig *cs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attrs, &n);
   if (!cs || n < 1) {
      fprintf(stderr, "glxwindow: no config\n");
      exit(1);
   }
   GLXFBConfig c = cs[0];
   XFree(cs);
   return c;
}

int main(int argc, char **argv)
{
   if (argc != 3 || strcmp(argv[1], "--out") != 0) {
      fprintf(stderr, "usage: %s --out FILE.ppm\n", argv[0]);
      return 2;
   }
   const char *out = argv[2];
   dpy = XOpenDisplay(NULL);
   if (!dpy || !glXQueryExtension(dpy, &glx_error_base, &glx_event_base)) {
      fprintf(stderr, "glxwindow: no display or no GLX\n");
      return 1;
   }
   XSetErrorHandler(on_error);
   /* single-buffered: glFinish shows what was drawn */
   GLXFBConfig cfg = choose(0), cfg32 = choose(8);
   XVisualInfo *vi = glXGetVisualFromFBConfig(dpy, cfg);
   XVisualInfo *vi32 = glXGetVisualFromFBConfig(dpy, cfg32);
   if (!vi || !vi32) {
      fprintf(stderr, "glxwindow: no visual\n");
      return 1;
   }
   printf("= visual depths %d %d\n", vi->depth, vi32->depth);
   Window win = make_window(vi);
   GLXContext ctx = glXCreateNewContext(dpy, cfg, GLX_RGBA_TYPE, NULL, True);
   if (!ctx) {
      fprintf(stderr, "glxwindow: no context\n");
      return 1;
   }

   /* the X window first, then a GLXWindow of it: two drawables */
   glXMakeCurrent(dpy, win, ctx);
   print_renderer();
   glViewport(0, 0, W, H);
   clear(0, 0.5f, 0);
   glFinish();
   print_pixel("x window cleared green");
   GLXWindow gwin = glXCreateWindow(dpy, cfg, win, NULL);
   printf("= glxwindow %s, %s the window\n", gwin != None ? "made" : "none",
          gwin == win ? "same as" : "not");
   settle("created");
   if (!glXMakeContextCurrent(dpy, gwin, gwin, ctx)) {
      fprintf(stderr, "glxwindow: cannot bind the GLXWindow\n");
      return 1;
   }
   printf("= current drawable is %s\n", glXGetCurrentDrawable() == gwin ? "the glxwindow"
                                        : glXGetCurrentDrawable() == win ? "the window" : "other");
   unsigned wv = 0, hv = 0;
   glXQueryDrawable(dpy, gwin, GLX_WIDTH, &wv);
   glXQueryDrawable(dpy, gwin, GLX_HEIGHT, &hv);
   printf("= glxwindow size %u x %u\n", wv, hv);
   print_pixel("glxwindow first");
   glEnable(GL_SCISSOR_TEST);
   glScissor(0, 0, W, H / 2);
   clear(0.8f, 0.2f, 0.4f);
   glDisable(GL_SCISSOR_TEST);
   shaded_tri(0.7f);
   glFinish();
   print_pixel("glxwindow half cleared");
   write_drawable_ppm(dpy, win, vi->visual, out, 0);
   glXMakeCurrent(dpy, win, ctx);
   print_pixel("x window again");
   glEnable(GL_SCISSOR_TEST);
   glScissor(0, H / 2, W, H - H / 2);
   clear(0.2f, 0.4f, 0.8f);
   glDisable(GL_SCISSOR_TEST);
   shaded_tri(-0.5f);
   glFinish();
   write_drawable_ppm(dpy, win, vi->visual, out, 1);
   glXMakeContextCurrent(dpy, gwin, gwin, ctx);
   print_pixel("glxwindow again");
   glXMakeCurrent(dpy, None, NULL);
   settle("drawn");

   /* a second GLXWindow of the same window */
   GLXWindow gwin2 = glXCreateWindow(dpy, cfg, win, NULL);
   printf("= second glxwindow %s\n", gwin2 == None ? "none" : gwin2 == gwin ? "same" : "another");
   settle("second");
   /* no config: None, no request */
   GLXWindow g0 = glXCreateWindow(dpy, NULL, win, NULL);
   printf("= no config: %s\n", g0 == None ? "none" : "made");
   settle("no config");
   /* a config of another visual (depth 32 on a depth-24 window) */
   GLXWindow gm = glXCreateWindow(dpy, cfg32, win, NULL);
   printf("= other visual: %s\n", gm == None ? "none" : "made");
   settle("other visual");
   /* not a window */
   GLXWindow gb = glXCreateWindow(dpy, cfg, (Window)0x3fffff0, NULL);
   printf("= bad window: %s\n", gb == None ? "none" : "made");
   settle("bad window");
   /* destroy: the GLXWindow, again, the X window's own ID, an unknown ID */
   glXDestroyWindow(dpy, gwin);
   settle("destroyed");
   glXDestroyWindow(dpy, gwin);
   settle("destroyed twice");
   glXDestroyWindow(dpy, win);
   settle("destroy x window");
   glXDestroyWindow(dpy, (GLXWindow)0x3fffff1);
   settle("destroy unknown");
   if (gwin2 != None && gwin2 != gwin)
      glXDestroyWindow(dpy, gwin2);
   settle("destroy second");
   /* the X window still draws */
   glXMakeCurrent(dpy, win, ctx);
   print_pixel("x window at the end");
   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   settle("end");
   XFree(vi);
   XFree(vi32);
   XCloseDisplay(dpy);
   return 0;
}
