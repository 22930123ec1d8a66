/*
 * depth32 - the depth buffer a program gets when it asks for "a depth
 * buffer" (GLX_DEPTH_SIZE 1 or 16), on Mesa's libGL and on fixgl's
 * (run_glx.py compare).  Mesa's llvmpipe on Xvfb lists Z32_UNORM configs
 * (32 depth bits, no stencil) for every visual, and its "larger depth
 * first" order makes them the first answers: fixgl mirrors them.
 *
 *   depth32 --depth N [--frames F] --out FILE.ppm
 *
 * Recorded, into the PPM file after the window's image (each as the bytes
 * of an "image" the runner compares bit for bit):
 *   - glXChooseVisual (GLX_RGBA, GLX_DEPTH_SIZE N, GLX_DOUBLEBUFFER) and
 *     the first answer of glXChooseFBConfig (RGBA 8-8-8, GLX_DEPTH_SIZE
 *     N, double-buffered): depth, stencil, accumulation, alpha, double
 *     buffering, buffer size; GL_DEPTH_BITS of the context;
 *   - the depth buffer after depth-close geometry: triangles whose depths
 *     differ by less than a 24-bit step (drawn with GL_LESS: a 24-bit
 *     buffer keeps the first), polygon offsets of a few units near 0 and
 *     0.5, clears to glClearDepth values between 24-bit steps; read with
 *     glReadPixels as GL_UNSIGNED_INT, GL_FLOAT and GL_UNSIGNED_SHORT;
 *   - glCopyPixels(GL_DEPTH) and glDrawPixels(GL_DEPTH_COMPONENT,
 *     GL_FLOAT) of that buffer, read back again;
 *   - glCopyTexImage2D of GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16, 24
 *     and 32 from it, read with glGetTexImage as GL_UNSIGNED_INT.
 */
#include <GL/gl.h>

#include "glx_frames.h"

#define CHECK(cond)                                                           \
   do {                                                                       \
      if (!(cond)) {                                                          \
         fprintf(stderr, "depth32: check failed: %s (line %d)\n", #cond, __LINE__); \
         exit(1);                                                             \
      }                                                                       \
   } while (0)

#define W 96
#define H 64

/* bytes as one more PPM image (width: the bytes / 3, padded with zeros) */
static void append_bytes(const char *path, const void *data, size_t n)
{
   FILE *f = fopen(path, "ab");
   CHECK(f);
   const size_t w = (n + 2) / 3;
   fprintf(f, "P6\n%zu 1\n255\n", w);
   fwrite(data, 1, n, f);
   for (size_t i = n; i < 3 * w; i++)
      fputc(0, f);
   CHECK(fclose(f) == 0);
}

static void append_ints(const char *path, const int *v, size_t n)
{
   append_bytes(path, v, n * sizeof(int));
}

static void read_depth_all(const char *path)
{
   static GLuint u[W * H];
   static GLfloat fl[W * H];
   static GLushort us[W * H];
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, u);
   glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, fl);
   glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, us);
   CHECK(glGetError() == GL_NO_ERROR);
   append_bytes(path, u, sizeof(u));
   append_bytes(path, fl, sizeof(fl));
   append_bytes(path, us, sizeof(us));
}

static void tri(float z0, float z1, float z2, float r, float g, float b)
{
   glColor3f(r, g, b);
   glBegin(GL_TRIANGLES);
   glVertex3f(-0.9f, -0.9f, z0);
   glVertex3f(0.9f, -0.8f, z1);
   glVertex3f(-0.1f, 0.9f, z2);
   glEnd();
}

/* Depth-close geometry: each step below a 24-bit depth step (2^-24 of
 * the range; the NDC z is twice the window z). */
static void scene(int frame)
{
   glViewport(0, 0, W, H);
   glDisable(GL_POLYGON_OFFSET_FILL);
   glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
   glClearDepth(0.7 + 1.0 / 33554432.0 * (frame + 1));   /* between 24-bit steps */
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_LESS);
   const float e = 1.0f / 16777216.0f;   /* a 24-bit step in window z, half in NDC */
   /* near 0.5 in window z (NDC 0): sloped, the second lower by 1/4 step */
   glEnable(GL_SCISSOR_TEST);
   glScissor(0, 0, W / 2, H / 2);
   tri(0.0f, 0.01f, -0.01f, 1.0f, 0.0f, 0.0f);
   tri(0.0f - e * 0.5f, 0.01f - e * 0.5f, -0.01f - e * 0.5f, 0.0f, 1.0f, 0.0f);
   /* near 0 in window z (NDC -1): finer floats, offsets of a few units */
   glScissor(W / 2, 0, W / 2, H / 2);
   tri(-0.999f, -0.9985f, -0.9995f, 1.0f, 1.0f, 0.0f);
   glEnable(GL_POLYGON_OFFSET_FILL);
   glPolygonOffset(0.0f, -3.0f);
   tri(-0.999f, -0.9985f, -0.9995f, 0.0f, 1.0f, 1.0f);
   glPolygonOffset(0.0f, -200.0f);
   glScissor(W / 2 + W / 4, 0, W / 4, H / 2);
   tri(-0.999f, -0.9985f, -0.9995f, 1.0f, 0.0f, 1.0f);
   glDisable(GL_POLYGON_OFFSET_FILL);
   /* GL_LEQUAL and GL_EQUAL against the stored values */
   glScissor(0, H / 2, W / 2, H / 2);
   tri(0.3f, 0.31f, 0.29f, 0.5f, 0.5f, 1.0f);
   glDepthFunc(GL_EQUAL);
   tri(0.3f, 0.31f, 0.29f, 1.0f, 0.5f, 0.0f);
   glDepthFunc(GL_LESS);
   tri(0.3f - e, 0.31f - e, 0.29f - e, 0.0f, 0.5f, 0.0f);
   /* glPolygonOffset with a factor, near the clear value */
   glScissor(W / 2, H / 2, W / 2, H / 2);
   glEnable(GL_POLYGON_OFFSET_FILL);
   glPolygonOffset(1.0f, 1.0f);
   tri(0.4f, 0.5f, 0.35f, 0.8f, 0.8f, 0.8f);
   glPolygonOffset(0.0f, 0.0f);
   tri(0.4f, 0.5f, 0.35f, 0.2f, 0.6f, 0.9f);
   glDisable(GL_POLYGON_OFFSET_FILL);
   glDisable(GL_SCISSOR_TEST);
   /* a white mark, no depth test (nor depth write) */
   glDisable(GL_DEPTH_TEST);
   glColor3f(1.0f, 1.0f, 1.0f);
   glBegin(GL_TRIANGLES);
   glVertex2f(-1.0f, -1.0f);
   glVertex2f(-0.8f, -1.0f);
   glVertex2f(-1.0f, -0.7f);
   glEnd();
}

int main(int argc, char **argv)
{
   int depth_size = -1;
   char *rest[8];
   int nrest = 0;
   rest[nrest++] = argv[0];
   for (int i = 1; i < argc; i++) {
      if (strcmp(argv[i], "--depth") == 0 && i + 1 < argc)
         depth_size = atoi(argv[++i]);
      else if (nrest < 7)
         rest[nrest++] = argv[i];
   }
   rest[nrest] = NULL;
   CHECK(depth_size >= 0);
   struct frames_opts opts;
   frames_parse(nrest, rest, &opts, 2);
   Display *dpy = XOpenDisplay(NULL);
   CHECK(dpy);
   const int screen = DefaultScreen(dpy);

   int answers[256];
   size_t na = 0;
   int vis_attribs[] = { GLX_RGBA, GLX_DEPTH_SIZE, depth_size, GLX_DOUBLEBUFFER, None };
   XVisualInfo *vi = glXChooseVisual(dpy, screen, vis_attribs);
   CHECK(vi);
   static const int cfg_queries[] = { GLX_DEPTH_SIZE, GLX_STENCIL_SIZE, GLX_ACCUM_RED_SIZE,
                                      GLX_ALPHA_SIZE, GLX_DOUBLEBUFFER, GLX_BUFFER_SIZE };
   for (size_t q = 0; q < sizeof(cfg_queries) / sizeof(cfg_queries[0]); q++) {
      int v = -1;
      CHECK(glXGetConfig(dpy, vi, cfg_queries[q], &v) == 0);
      answers[na++] = v;
   }
   printf("glXChooseVisual: depth %d bits\n", answers[0]);
   CHECK(answers[0] == 32);   /* Mesa's choice on Xvfb, and fixgl's */
   const int fb_attribs[] = {
      GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8,
      GLX_DEPTH_SIZE, depth_size, GLX_DOUBLEBUFFER, True, None,
   };
   int n = 0;
   GLXFBConfig *configs = glXChooseFBConfig(dpy, screen, fb_attribs, &n);
   CHECK(configs && n > 0);
   /* the first answer (Mesa's Z32 one): fixgl has a subset of Mesa's
    * visuals (the default one and one with alpha), so the visual ids and
    * the answers after the first (Mesa's Z32 configs of its other
    * visuals) differ */
   for (size_t q = 0; q < sizeof(cfg_queries) / sizeof(cfg_queries[0]); q++) {
      int v = -1;
      CHECK(glXGetFBConfigAttrib(dpy, configs[0], cfg_queries[q], &v) == Success);
      answers[na++] = v;
   }
   printf("glXChooseFBConfig 0: depth %d stencil %d accum %d alpha %d db %d\n", answers[na - 6],
          answers[na - 5], answers[na - 4], answers[na - 3], answers[na - 2]);
   XFree(configs);

   XSetWindowAttributes swa = {
      .colormap = XCreateColormap(dpy, RootWindow(dpy, screen), vi->visual, AllocNone),
      .border_pixel = 0,
      .event_mask = StructureNotifyMask,
   };
   Window win = XCreateWindow(dpy, RootWindow(dpy, screen), 0, 0, W, H, 0, vi->depth,
                              InputOutput, vi->visual, CWColormap | CWBorderPixel | CWEventMask,
                              &swa);
   XMapWindow(dpy, win);
   for (XEvent ev;;) {
      XNextEvent(dpy, &ev);
      if (ev.type == MapNotify)
         break;
   }
   GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
   CHECK(ctx);
   CHECK(glXMakeCurrent(dpy, win, ctx));
   GLint bits = -1;
   glGetIntegerv(GL_DEPTH_BITS, &bits);
   answers[na++] = bits;
   printf("GL_DEPTH_BITS %d\n", bits);

   for (int f = 0; f < opts.frames; f++) {
      scene(f);
      if (f + 1 < opts.frames)
         glXSwapBuffers(dpy, win);
   }
   glFinish();
   /* the depth buffer of the last frame, before the swap */
   static GLuint u[W * H];
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, u);
   size_t distinct = 0;
   for (int i = 1; i < W * H; i++)
      distinct += u[i] != u[i - 1];
   printf("depth transitions along the rows: %zu\n", distinct);
   glXSwapBuffers(dpy, win);
   glFinish();
   print_renderer();
   write_drawable_ppm(dpy, win, vi->visual, opts.out, 0);
   append_ints(opts.out, answers, na);
   read_depth_all(opts.out);

   /* glCopyPixels of depth: the lower left quarter onto the upper right */
   glDepthFunc(GL_ALWAYS);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, W, 0, H, -1, 1);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glRasterPos2i(W / 2, H / 2);
   glCopyPixels(0, 0, W / 2, H / 2, GL_DEPTH);
   CHECK(glGetError() == GL_NO_ERROR);
   /* glDrawPixels of float depths between 24-bit steps */
   static GLfloat zf[16 * 16];
   for (int i = 0; i < 16 * 16; i++)
      zf[i] = 0.25f + (float)i * (1.0f / 67108864.0f);
   glRasterPos2i(4, H / 2 + 4);
   glDrawPixels(16, 16, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
   CHECK(glGetError() == GL_NO_ERROR);
   glFinish();
   read_depth_all(opts.out);

   /* glCopyTexImage2D of the depth buffer into depth textures */
   static const GLenum formats[] = { GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16,
                                     GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32 };
   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D, tex);
   for (size_t i = 0; i < sizeof(formats) / sizeof(formats[0]); i++) {
      static GLuint t[64 * 32];
      glCopyTexImage2D(GL_TEXTURE_2D, 0, formats[i], 8, 4, 64, 32, 0);
      CHECK(glGetError() == GL_NO_ERROR);
      glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, t);
      CHECK(glGetError() == GL_NO_ERROR);
      append_bytes(opts.out, t, sizeof(t));
   }
   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   XDestroyWindow(dpy, win);
   XCloseDisplay(dpy);
   return 0;
}
