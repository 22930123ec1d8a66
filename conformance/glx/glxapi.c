/*
 * glxapi - GLX 1.3/1.4 without GLUT: a window through glXChooseFBConfig,
 * glXGetVisualFromFBConfig, glXCreateNewContext, glXCreateWindow and
 * glXMakeContextCurrent with text from glXUseXFont's display lists; then
 * a single-buffered GLX pixmap (glXChooseVisual, glXCreateGLXPixmap,
 * glXMakeCurrent) drawn and finished with glFinish.  Both are read back
 * from the server into one PPM file (the window's image, then the
 * pixmap's).  The calls' results that both libraries must give are
 * checked on the way (exit 1 with a message when one is wrong).
 */
#include <GL/gl.h>

#include "glx_frames.h"

#define CHECK(cond)                                                           \
   do {                                                                       \
      if (!(cond)) {                                                          \
         fprintf(stderr, "glxapi: check failed: %s (line %d)\n", #cond, __LINE__); \
         exit(1);                                                             \
      }                                                                       \
   } while (0)

static void scene(int w, int h, GLuint font_base, int frames)
{
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, w, 0, h, -1, 1);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glClearColor(0.2f, 0.1f, 0.3f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT);
   glBegin(GL_TRIANGLES);
   glColor3f(1, 0, 0);
   glVertex2f(10, 10);
   glColor3f(0, 1, 0);
   glVertex2f((GLfloat)w - 20, 30);
   glColor3f(0, 0, 1);
   glVertex2f((GLfloat)w / 2, (GLfloat)h - 10);
   glEnd();
   if (font_base) {
      glColor3f(1, 1, 0.6f);
      glRasterPos2i(12, h - 24);
      glListBase(font_base);
      glCallLists(16, GL_UNSIGNED_BYTE, "GLX 1.4 glXUseXF");
      glRasterPos2i(12, h / 2);
      char line[32];
      snprintf(line, sizeof(line), "frames: %d ~{}", frames);
      glCallLists((GLsizei)strlen(line), GL_UNSIGNED_BYTE, line);
   }
}

int main(int argc, char **argv)
{
   struct frames_opts opts;
   frames_parse(argc, argv, &opts, 3);
   Display *dpy = XOpenDisplay(NULL);
   CHECK(dpy);
   const int screen = DefaultScreen(dpy);
   int major = 0, minor = 0;
   CHECK(glXQueryExtension(dpy, NULL, NULL));
   CHECK(glXQueryVersion(dpy, &major, &minor));
   CHECK(major == 1 && minor >= 3);
   CHECK(strstr(glXQueryExtensionsString(dpy, screen), "GLX_ARB_get_proc_address"));
   CHECK(glXGetProcAddressARB((const GLubyte *)"glBindTexture") != NULL);

   /* the window, the GLX 1.3 way */
   static const int fb_attribs[] = {
      GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_RENDER_TYPE, GLX_RGBA_BIT,
      GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8,
      GLX_DOUBLEBUFFER, True, None,
   };
   int n = 0;
   GLXFBConfig *configs = glXChooseFBConfig(dpy, screen, fb_attribs, &n);
   CHECK(configs && n > 0);
   int db = 0, red = 0;
   CHECK(glXGetFBConfigAttrib(dpy, configs[0], GLX_DOUBLEBUFFER, &db) == Success && db);
   CHECK(glXGetFBConfigAttrib(dpy, configs[0], GLX_RED_SIZE, &red) == Success && red == 8);
   XVisualInfo *vi = glXGetVisualFromFBConfig(dpy, configs[0]);
   CHECK(vi);
   XSetWindowAttributes swa = {
      .colormap = XCreateColormap(dpy, RootWindow(dpy, screen), vi->visual, AllocNone),
      .border_pixel = 0,
      .event_mask = StructureNotifyMask | ExposureMask,
   };
   const int w = 240, h = 120;
   Window win = XCreateWindow(dpy, RootWindow(dpy, screen), 0, 0, (unsigned)w, (unsigned)h, 0,
                              vi->depth, InputOutput, vi->visual,
                              CWColormap | CWBorderPixel | CWEventMask, &swa);
   XMapWindow(dpy, win);
   for (XEvent ev;;) {
      XNextEvent(dpy, &ev);
      if (ev.type == MapNotify)
         break;
   }
   GLXContext ctx = glXCreateNewContext(dpy, configs[0], GLX_RGBA_TYPE, NULL, True);
   CHECK(ctx);
   GLXWindow gwin = glXCreateWindow(dpy, configs[0], win, NULL);
   CHECK(gwin);
   CHECK(glXMakeContextCurrent(dpy, gwin, gwin, ctx));
   CHECK(glXGetCurrentContext() == ctx);
   CHECK(glXGetCurrentDrawable() == gwin);
   CHECK(glXGetCurrentReadDrawable() == gwin);
   CHECK(glXGetCurrentDisplay() == dpy);
   CHECK(glXIsDirect(dpy, ctx));
   GLint ival = -1;
   glGetIntegerv(GL_DOUBLEBUFFER, &ival);
   CHECK(ival == GL_TRUE);
   glGetIntegerv(GL_DRAW_BUFFER, &ival);
   CHECK(ival == GL_BACK);
   glGetIntegerv(GL_READ_BUFFER, &ival);
   CHECK(ival == GL_BACK);

   Font font = XLoadFont(dpy, "fixed");
   const GLuint base = glGenLists(128);
   glXUseXFont(font, 0, 128, (int)base);
   for (int f = 0; f < opts.frames; f++) {
      scene(w, h, base, f);
      glXSwapBuffers(dpy, gwin);
   }
   glFinish();
   print_renderer();
   write_drawable_ppm(dpy, win, vi->visual, opts.out, 0);

   /* a GLX pixmap, single-buffered, the GLX 1.2 way */
   int vattribs[] = { GLX_RGBA, GLX_RED_SIZE, 1, GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1, None };
   XVisualInfo *pvi = glXChooseVisual(dpy, screen, vattribs);
   CHECK(pvi);
   int value = -1;
   CHECK(glXGetConfig(dpy, pvi, GLX_USE_GL, &value) == 0 && value);
   CHECK(glXGetConfig(dpy, pvi, GLX_DOUBLEBUFFER, &value) == 0 && !value);
   CHECK(glXGetConfig(dpy, pvi, GLX_RGBA, &value) == 0 && value);
   Pixmap pm = XCreatePixmap(dpy, RootWindow(dpy, screen), 100, 80, (unsigned)pvi->depth);
   GLXPixmap gpm = glXCreateGLXPixmap(dpy, pvi, pm);
   CHECK(gpm);
   GLXContext pctx = glXCreateContext(dpy, pvi, ctx, True);
   CHECK(pctx);
   CHECK(glXMakeCurrent(dpy, gpm, pctx));
   CHECK(glXGetCurrentContext() == pctx);
   CHECK(glIsList(base));   /* shared with ctx */
   glGetIntegerv(GL_DOUBLEBUFFER, &ival);
   CHECK(ival == GL_FALSE);
   glGetIntegerv(GL_DRAW_BUFFER, &ival);
   CHECK(ival == GL_FRONT);
   scene(100, 80, base, opts.frames);
   glFinish();
   write_drawable_ppm(dpy, pm, pvi->visual, opts.out, 1);

   CHECK(glXMakeCurrent(dpy, None, NULL));
   CHECK(glXGetCurrentContext() == NULL);
   glXDestroyGLXPixmap(dpy, gpm);
   glXDestroyContext(dpy, pctx);
   glXDestroyWindow(dpy, gwin);
   glXDestroyContext(dpy, ctx);
   XFreePixmap(dpy, pm);
   XFree(pvi);
   XFree(vi);
   XFree(configs);
   XUnloadFont(dpy, font);
   XDestroyWindow(dpy, win);
   XCloseDisplay(dpy);
   return 0;
}
