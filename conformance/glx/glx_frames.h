/*
 * glx_frames.h - shared by the programs of the glx suite (compiled against
 * the system's freeglut, GLU and libGL: nothing of fixgl at build time).
 *
 * A program draws a fixed number of frames, each a function of its frame
 * number alone (no clock), then reads its window back from the X server
 * (XGetImage after glFinish and the last swap) and writes it as a binary
 * PPM of the visual's red, green and blue bits, and prints the renderer
 * ("renderer: ..."): run_glx.py runs it once on Mesa's libGL and once on
 * fixgl's, checks the renderers and compares the two files.
 *
 *   PROGRAM [--frames N] --out FILE.ppm
 */
#ifndef GLX_FRAMES_H
#define GLX_FRAMES_H

#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct frames_opts {
   int frames;          /* frames drawn before the read-back */
   const char *out;     /* the PPM written */
};

static inline void frames_parse(int argc, char **argv, struct frames_opts *o, int default_frames)
{
   o->frames = default_frames;
   o->out = NULL;
   for (int i = 1; i < argc; i++) {
      if (strcmp(argv[i], "--frames") == 0 && i + 1 < argc)
         o->frames = atoi(argv[++i]);
      else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc)
         o->out = argv[++i];
      else {
         fprintf(stderr, "usage: %s [--frames N] --out FILE.ppm\n", argv[0]);
         exit(2);
      }
   }
   if (!o->out || o->frames < 1) {
      fprintf(stderr, "usage: %s [--frames N] --out FILE.ppm\n", argv[0]);
      exit(2);
   }
}

static inline int mask_shift(unsigned long m)
{
   int s = 0;
   while (m && !(m & 1ul)) {
      m >>= 1;
      s++;
   }
   return s;
}

/* The drawable's pixels as the X server holds them, as a PPM (append:
 * another image after the first in the same file); exits on failure. */
static inline void write_drawable_ppm(Display *dpy, Drawable d, Visual *visual, const char *path,
                                      int append)
{
   Window root;
   int x, y;
   unsigned w, h, bw, depth;
   if (!XGetGeometry(dpy, d, &root, &x, &y, &w, &h, &bw, &depth)) {
      fprintf(stderr, "XGetGeometry failed\n");
      exit(1);
   }
   XImage *img = XGetImage(dpy, d, 0, 0, w, h, AllPlanes, ZPixmap);
   if (!img) {
      fprintf(stderr, "XGetImage failed\n");
      exit(1);
   }
   FILE *f = fopen(path, append ? "ab" : "wb");
   if (!f) {
      perror(path);
      exit(1);
   }
   const int rs = mask_shift(visual->red_mask), gs = mask_shift(visual->green_mask),
             bs = mask_shift(visual->blue_mask);
   fprintf(f, "P6\n%u %u\n255\n", w, h);
   for (unsigned row = 0; row < h; row++)
      for (unsigned col = 0; col < w; col++) {
         const unsigned long p = XGetPixel(img, (int)col, (int)row);
         const unsigned char rgb[3] = {
            (unsigned char)((p & visual->red_mask) >> rs),
            (unsigned char)((p & visual->green_mask) >> gs),
            (unsigned char)((p & visual->blue_mask) >> bs),
         };
         fwrite(rgb, 1, 3, f);
      }
   if (fclose(f) != 0) {
      perror(path);
      exit(1);
   }
   XDestroyImage(img);
}

/* The renderer that drew, for the runner to check which library ran. */
static inline void print_renderer(void)
{
   printf("renderer: %s\n", (const char *)glGetString(GL_RENDERER));
   fflush(stdout);
}

/* The current GLX window (a GLUT program's) to path. */
static inline void write_current_window_ppm(const char *path)
{
   print_renderer();
   Display *dpy = glXGetCurrentDisplay();
   const GLXDrawable win = glXGetCurrentDrawable();
   if (!dpy || !win) {
      fprintf(stderr, "no current GLX drawable\n");
      exit(1);
   }
   XWindowAttributes wa;
   XGetWindowAttributes(dpy, win, &wa);
   write_drawable_ppm(dpy, win, wa.visual, path, 0);
}

/* Appends the current read buffer's w x h pixels (RGBA, unsigned bytes)
 * to the PPM file `path` as one binary PPM of their colour and, when
 * `alpha`, a second of their alpha as grey (pixels a read clipped to a
 * smaller drawable does not write are 0x55); the first call (*images 0)
 * creates the file, every call counts itself in *images. */
static inline void append_read_ppm(const char *path, int *images, int w, int h, int alpha)
{
   unsigned char *px = malloc((size_t)w * (size_t)h * 4);
   FILE *f = px ? fopen(path, (*images)++ > 0 ? "ab" : "wb") : NULL;
   if (!f) {
      perror(path);
      exit(1);
   }
   memset(px, 0x55, (size_t)w * (size_t)h * 4);   /* what a clipped read leaves */
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
   for (int pass = 0; pass < (alpha ? 2 : 1); pass++) {
      fprintf(f, "P6\n%d %d\n255\n", w, h);
      for (int y = h - 1; y >= 0; y--)
         for (int x = 0; x < w; x++) {
            const unsigned char *p = &px[4 * (y * w + x)];
            const unsigned char a[3] = { p[3], p[3], p[3] };
            fwrite(pass == 0 ? p : a, 1, 3, f);
         }
   }
   fclose(f);
   free(px);
}

/* One pixel of the current read buffer, as a "= " line run_glx.py
 * compares. */
static inline void print_read_pixel(const char *what, int x, int y)
{
   unsigned char p[4];
   glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
   printf("= %s (%d,%d): %d %d %d %d\n", what, x, y, p[0], p[1], p[2], p[3]);
}

/* A mapped w x h window of config c, made current with a new context of
 * that config (the program exits when there is none); the caller frees
 * *vip, the window and *ctxp. */
/* A projection of window coordinates, one unit a pixel, origin lower
 * left, over the whole w x h drawable. */
static inline void pixel_view(int w, int h)
{
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, w, 0, h, -1, 1);
   glMatrixMode(GL_MODELVIEW);
}

/* The probes of llvmpipe's linear path (linrect.c, linlatch.c): a
 * whole-buffer clear to 0.3, and a clear of colour c scissored to
 * (0, 0, 40, 40) (a clear quad, in the tile of pixel (10, 10)). */
static inline void whole_clear(void)
{
   glClearColor(0.3f, 0.3f, 0.3f, 0.3f);
   glClear(GL_COLOR_BUFFER_BIT);
}

static inline void scissored_clear_of(const float c[4])
{
   glEnable(GL_SCISSOR_TEST);
   glScissor(0, 0, 40, 40);
   glClearColor(c[0], c[1], c[2], c[3]);
   glClear(GL_COLOR_BUFFER_BIT);
   glDisable(GL_SCISSOR_TEST);
}

static inline Window config_window_current(Display *dpy, GLXFBConfig c, int w, int h,
                                           XVisualInfo **vip, GLXContext *ctxp)
{
   XVisualInfo *vi = glXGetVisualFromFBConfig(dpy, c);
   if (!vi) {
      fprintf(stderr, "no visual for the config\n");
      exit(1);
   }
   XSetWindowAttributes swa;
   swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
   swa.background_pixel = 0;
   swa.border_pixel = 0;
   Window win = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, (unsigned)w, (unsigned)h,
                              0, vi->depth, InputOutput, vi->visual,
                              CWColormap | CWBackPixel | CWBorderPixel, &swa);
   XMapWindow(dpy, win);
   XSync(dpy, False);
   GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
   if (!ctx || !glXMakeCurrent(dpy, win, ctx)) {
      fprintf(stderr, "no context for the config\n");
      exit(1);
   }
   *vip = vi;
   *ctxp = ctx;
   return win;
}

/* The oracle's drawables that permit llvmpipe's linear path (linrules.c,
 * linrandom.c): a double-buffered B8G8R8A8 window of w x h without depth
 * and stencil, current with a new context, the renderer printed, a
 * pixel projection, drawing and reading the back buffer; `prog` names
 * the program in its messages (it exits when there is no such config). */
static inline Window linear_window_current(Display *dpy, int w, int h, XVisualInfo **vip,
                                           GLXContext *ctxp, const char *prog)
{
   int attrs[] = { GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, 8,
                   GLX_DEPTH_SIZE, 0, GLX_STENCIL_SIZE, 0, GLX_DOUBLEBUFFER, True,
                   GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, None };
   int n = 0;
   GLXFBConfig *cs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attrs, &n);
   GLXFBConfig c = NULL;
   for (int i = 0; cs && i < n && !c; i++) {
      int r = 0, a = 0, d = -1, s = -1;
      glXGetFBConfigAttrib(dpy, cs[i], GLX_RED_SIZE, &r);
      glXGetFBConfigAttrib(dpy, cs[i], GLX_ALPHA_SIZE, &a);
      glXGetFBConfigAttrib(dpy, cs[i], GLX_DEPTH_SIZE, &d);
      glXGetFBConfigAttrib(dpy, cs[i], GLX_STENCIL_SIZE, &s);
      if (r == 8 && a == 8 && d == 0 && s == 0)
         c = cs[i];
   }
   if (cs)
      XFree(cs);
   if (!c) {
      fprintf(stderr, "%s: no config without depth and stencil\n", prog);
      exit(1);
   }
   Window win = config_window_current(dpy, c, w, h, vip, ctxp);
   print_renderer();
   pixel_view(w, h);
   glDrawBuffer(GL_BACK);
   glReadBuffer(GL_BACK);
   return win;
}

#endif
