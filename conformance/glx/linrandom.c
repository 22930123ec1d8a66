/*
 * linrandom - seeded random scenes of rectangles, clear quads, triangles,
 * lines and points on a GLX window without depth and stencil buffers, on
 * Mesa's libGL and on fixgl's (run_glx.py compare).  llvmpipe decides per
 * 64 x 64 bin, when a scene is flushed, whether the bin goes through its
 * linear path (every command binned into it a rectangle) or the ordinary
 * one (ORACLE-NOTES.md "GLX linear rectangles", "GLX linear
 * arithmetic"); the two round colours differently.  Each scene is a few
 * commands in a 256 x 192 window (4 x 3 bins), read back with glReadPixels
 * (which ends the oracle's scene) into the PPM: every scene's whole image
 * is compared.
 *
 *   linrandom --out FILE.ppm [--seed S] [--scenes N] [--outside PX] [--blend] [--verbose]
 *   linrandom --probe
 *
 * --probe (run on Mesa's libGL alone: run_glx.py oracle) checks the
 * oracle's facts ORACLE-NOTES.md "GLX linear bins" relies on or records
 * as not modelled, each a pixel after a scene of its own: a legacy point
 * binned after a rectangle leaves its bin linear; a rectangle reaching
 * past the window's top is still a rectangle (the xy guard band); a
 * tile a triangle covers whole goes the linear way, unless the region's
 * bottom plane cuts it.
 *
 * The commands: glRecti/glRectf (integer, half and quarter pixel
 * corners) with the current colour; a GL_QUADS, GL_TRIANGLES pair or
 * glDrawArrays(GL_QUADS) rectangle with the colour as a vertex attribute
 * (given inside glBegin/glEnd, one colour or corners that differ); a
 * scissored or colour-masked glClear (a clear quad); a whole-buffer
 * clear; triangles of one colour and of three; lines of width 1 and 3;
 * glFlush between some.
 * Colours are near k/255 and the halves between, where rounding and
 * truncation part.  --outside PX lets half the boxes reach up to PX pixels
 * past the window (llvmpipe's xy guard band, twice the viewport, keeps
 * them from being clipped: ORACLE-NOTES.md "GLX guard band").
 */
#include <GL/gl.h>
#include <stdbool.h>
#include <stdint.h>

#include "glx_frames.h"

#define W 256
#define H 192

static uint64_t rng;

static uint32_t next(void)
{
   rng = rng * 6364136223846793005ull + 1442695040888963407ull;
   return (uint32_t)(rng >> 33);
}

static int range(int n)
{
   return (int)(next() % (uint32_t)n);
}

static float channel(void)
{
   const int k = range(256);
   switch (range(4)) {
   case 0: return (float)k / 255.0f;
   case 1: return ((float)k + 0.5f) / 255.0f > 1.0f ? 1.0f : ((float)k + 0.5f) / 255.0f;
   case 2: return ((float)k + 0.25f) / 255.0f > 1.0f ? 1.0f : ((float)k + 0.25f) / 255.0f;
   default: return (float)range(1000) / 999.0f;
   }
}

static void colour(float c[4])
{
   for (int i = 0; i < 4; i++)
      c[i] = channel();
}

/* a corner on the pixel grid, at a half or a quarter pixel */
static float coord(int max)
{
   const float f[4] = { 0.0f, 0.0f, 0.5f, 0.25f };
   const float v = (float)range(max + 1) + f[range(4)];
   return v > (float)max ? (float)max : v;
}

/* --outside: corners up to `outside` pixels beyond the window */
static int outside;
/* --blend: blending (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) around some commands;
 * --points: points among the commands */
static bool blend, points;

static void box(float b[4])
{
   float x0 = coord(W), x1 = coord(W), y0 = coord(H), y1 = coord(H);
   if (outside && range(2)) {
      x0 -= (float)range(outside + 1);
      y0 -= (float)range(outside + 1);
      x1 += (float)range(outside + 1);
      y1 += (float)range(outside + 1);
   }
   if (range(2)) {   /* small ones, inside a bin or across a border */
      x1 = x0 + (float)(1 + range(40));
      y1 = y0 + (float)(1 + range(40));
      /* inside the window unless --outside */
      if (x1 > (float)W && !outside)
         x1 = (float)W;
      if (y1 > (float)H && !outside)
         y1 = (float)H;
   }
   b[0] = x0 < x1 ? x0 : x1;
   b[1] = y0 < y1 ? y0 : y1;
   b[2] = x0 < x1 ? x1 : x0;
   b[3] = y0 < y1 ? y1 : y0;
}

static bool verbose;
static const float *say_c, *say_b;

static void say(const char *what)
{
   if (verbose && say_c)
      printf("  %s (%g %g %g %g) colour %.9g %.9g %.9g %.9g\n", what, say_b[0], say_b[1],
             say_b[2], say_b[3], say_c[0], say_c[1], say_c[2], say_c[3]);
   else if (verbose)
      printf("  %s\n", what);
}

static void command(void)
{
   float c[4], b[4];
   colour(c);
   box(b);
   say_c = c;
   say_b = b;
   switch (range(12)) {
   case 0:
   case 1:
      say("glRectf");
      glColor4fv(c);
      glRectf(b[0], b[1], b[2], b[3]);
      break;
   case 2:
      say("glRecti");
      glColor4fv(c);
      glRecti((int)b[0], (int)b[1], (int)b[2] + ((int)b[2] < W), (int)b[3] + ((int)b[3] < H));
      break;
   case 3: {
      const bool differ = range(3) == 0;
      say(differ ? "quad, corners differ" : "quad, colour inside");
      glBegin(GL_QUADS);
      glColor4fv(c);
      glVertex2f(b[0], b[1]);
      glVertex2f(b[2], b[1]);
      if (differ)
         glColor4f(c[1], c[2], c[3], c[0]);
      glVertex2f(b[2], b[3]);
      glVertex2f(b[0], b[3]);
      glEnd();
      break;
   }
   case 4:
      say("two triangles");
      glColor4fv(c);
      glBegin(GL_TRIANGLES);
      glVertex2f(b[0], b[1]);
      glVertex2f(b[2], b[1]);
      glVertex2f(b[2], b[3]);
      glVertex2f(b[0], b[1]);
      glVertex2f(b[2], b[3]);
      glVertex2f(b[0], b[3]);
      glEnd();
      break;
   case 5: {
      say("arrays quad");
      const GLfloat v[] = { b[0], b[1], b[2], b[1], b[2], b[3], b[0], b[3] };
      glColor4fv(c);
      glEnableClientState(GL_VERTEX_ARRAY);
      glVertexPointer(2, GL_FLOAT, 0, v);
      glDrawArrays(GL_QUADS, 0, 4);
      glDisableClientState(GL_VERTEX_ARRAY);
      break;
   }
   case 6: {
      const bool mask = range(3) == 0;
      say(mask ? "masked clear" : "scissored clear");
      glClearColor(c[0], c[1], c[2], c[3]);
      if (mask) {
         glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
      } else {
         glEnable(GL_SCISSOR_TEST);
         glScissor((int)b[0], (int)b[1], (int)(b[2] - b[0]) + 1, (int)(b[3] - b[1]) + 1);
      }
      glClear(GL_COLOR_BUFFER_BIT);
      glDisable(GL_SCISSOR_TEST);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      break;
   }
   case 7:
      say("whole clear");
      glClearColor(c[0], c[1], c[2], c[3]);
      glClear(GL_COLOR_BUFFER_BIT);
      break;
   case 8:
   case 9:
      say("triangle");
      glColor4fv(c);
      glBegin(GL_TRIANGLES);
      glVertex2f(b[0], b[1]);
      glVertex2f(b[2], b[1]);
      glVertex2f(b[0], b[3]);
      glEnd();
      break;
   case 10:
      say("line");
      glColor4fv(c);
      glLineWidth(range(2) ? 1.0f : 3.0f);
      glBegin(GL_LINES);
      glVertex2f(b[0], b[1]);
      glVertex2f(b[2], b[3]);
      glEnd();
      break;
   case 11:
      if (points) {
         say("point");
         glColor4fv(c);
         glPointSize(range(2) ? 1.0f : 4.0f);
         glBegin(GL_POINTS);
         glVertex2f(b[0], b[1]);
         glEnd();
         break;
      }
      /* fall through */
   default:
      /* (points only with --points: llvmpipe colours a point of a linear
       * bin by rules not settled, README issue 20) */
      say("triangle, smooth colours");
      glBegin(GL_TRIANGLES);
      glColor4fv(c);
      glVertex2f(b[2], b[3]);
      glColor4f(c[1], c[2], c[3], c[0]);
      glVertex2f(b[0], b[3]);
      glColor4f(c[2], c[3], c[0], c[1]);
      glVertex2f(b[2], b[1]);
      glEnd();
      break;
   }
}

static void scene(int k)
{
   const int n = 1 + range(6);
   if (verbose)
      printf("scene %d\n", k);
   for (int i = 0; i < n; i++) {
      const int r = range(16);
      say_c = NULL;
      /* (blending in linear bins is not modelled: the oracle's result
       * depends on what was drawn before, README issue 20; --blend draws
       * it, the known difference the suite keeps visible) */
      if (blend && r == 0) {
         say("blend on");
         glEnable(GL_BLEND);
         glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      } else if (blend && r == 1) {
         say("blend off");
         glDisable(GL_BLEND);
      } else if (r == 2) {
         say("flush");
         glFlush();
      }
      command();
   }
   glDisable(GL_BLEND);
   say_c = NULL;
}


/* ---- --probe ---- */
static int probe_fails;

static void probe_pixel(const char *what, int x, int y, const int want[4])
{
   unsigned char p[4];
   glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
   const bool ok = p[0] == want[0] && p[1] == want[1] && p[2] == want[2] && p[3] == want[3];
   printf("%s %-28s %3d %3d %3d %3d (oracle fact: %d %d %d %d)\n", ok ? "ok  " : "FAIL", what,
          p[0], p[1], p[2], p[3], want[0], want[1], want[2], want[3]);
   probe_fails += !ok;
}

static void pair(float x0, float y0, float x1, float y1)
{
   glBegin(GL_TRIANGLES);
   glVertex2f(x0, y0);
   glVertex2f(x1, y0);
   glVertex2f(x1, y1);
   glVertex2f(x0, y0);
   glVertex2f(x1, y1);
   glVertex2f(x0, y1);
   glEnd();
}

static void grey(void)
{
   glDisable(GL_BLEND);
   glFinish();
   glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
   glRecti(0, 0, W, H);
   glFinish();
}

static int probes(void)
{
   static const float A[4] = { 0.918627441f, 0.545545518f, 0.416666657f, 0.954954982f };
   static const float B[4] = { 0.251960784f, 0.305305302f, 0.138235301f, 0.733333349f };
   static const int linear_a[4] = { 234, 139, 106, 243 }, round_a[4] = { 234, 139, 106, 244 };
   static const int vertex_a[4] = { 235, 139, 106, 244 };
   grey();
   glColor4fv(A);
   pair(108.5f, 36, 196.5f, 154.5f);
   probe_pixel("pair alone", 110, 150, linear_a);
   glColor4fv(A);
   glBegin(GL_TRIANGLES);
   glVertex2f(108.5f, 36);
   glVertex2f(196.5f, 36);
   glVertex2f(196.5f, 154.5f);
   glEnd();
   probe_pixel("one triangle", 190, 100, round_a);
   glColor4fv(A);
   pair(108.5f, 36, 196.5f, 154.5f);
   glColor4f(0.1f, 0.1f, 0.1f, 0.1f);
   glBegin(GL_POINTS);
   glVertex2f(101, 145);
   glEnd();
   probe_pixel("pair, point in its bin", 110, 150, linear_a);
   /* the point's glColor with vertices pending: the pair's colour is a
    * vertex attribute (rule 2) */
   glColor4f(0.1f, 0.1f, 0.1f, 0.1f);
   glBegin(GL_POINTS);
   glVertex2f(101, 145);
   glEnd();
   glColor4fv(A);
   pair(108.5f, 36, 196.5f, 154.5f);
   probe_pixel("point, pair", 110, 150, vertex_a);
   static const int b_linear[4] = { 64, 77, 35, 187 };
   glColor4fv(B);
   glRecti(108, 150, 134, 160);
   probe_pixel("recti inside", 110, 155, b_linear);
   glColor4fv(B);
   glRecti(108, 190, 134, 200);
   probe_pixel("recti past the top", 110, 191, b_linear);
   glDisable(GL_BLEND);
   /* a triangle's whole tile is a tile command of the linear path; the
    * region's bottom plane (GL's bottom rows) cuts the tile it ends in */
   static const float T[4] = { 0.501960814f, 0.701960802f, 0.684684694f, 0.382352948f };
   static const int t_linear[4] = { 128, 179, 174, 97 }, t_round[4] = { 128, 179, 175, 98 };
   static const float tops[2] = { 192.0f, 191.0f };
   for (int i = 0; i < 2; i++) {
      glColor4fv(T);
      glBegin(GL_TRIANGLES);
      glVertex2f(250, tops[i]);
      glVertex2f(55, tops[i]);
      glVertex2f(250, 10);
      glEnd();
      probe_pixel(i == 0 ? "triangle, whole top tile" : "triangle, top tile cut", 150, 150,
                  i == 0 ? t_linear : t_round);
   }
   static const float U[4] = { 0.33431372f, 0.590196073f, 0.800000012f, 0.0650650635f };
   static const int u_round[4] = { 85, 150, 204, 17 };
   glColor4fv(U);
   glBegin(GL_TRIANGLES);
   glVertex2f(-20, -20);
   glVertex2f(150, -20);
   glVertex2f(-20, 150);
   glEnd();
   probe_pixel("triangle past the bottom", 5, 63, u_round);
   printf("%d of the probes differ from the oracle's facts\n", probe_fails);
   return probe_fails ? 1 : 0;
}

int main(int argc, char **argv)
{
   const char *out = NULL;
   unsigned seed = 1;
   int nscenes = 60;
   bool probe = false;
   for (int i = 1; i < argc; i++) {
      if (strcmp(argv[i], "--probe") == 0)
         probe = true;
      else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc)
         out = argv[++i];
      else if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc)
         seed = (unsigned)strtoul(argv[++i], NULL, 10);
      else if (strcmp(argv[i], "--scenes") == 0 && i + 1 < argc)
         nscenes = atoi(argv[++i]);
      else if (strcmp(argv[i], "--blend") == 0)
         blend = true;
      else if (strcmp(argv[i], "--points") == 0)
         points = true;
      else if (strcmp(argv[i], "--outside") == 0 && i + 1 < argc)
         outside = atoi(argv[++i]);
      else if (strcmp(argv[i], "--verbose") == 0)
         verbose = true;
      else
         out = NULL, i = argc;
   }
   if ((!out && !probe) || nscenes < 1) {
      fprintf(stderr, "usage: %s --out FILE.ppm [--seed S] [--scenes N] [--outside PX] [--blend] [--verbose] | --probe\n",
              argv[0]);
      return 2;
   }
   rng = seed * 0x9e3779b97f4a7c15ull + 1;
   Display *dpy = XOpenDisplay(NULL);
   if (!dpy) {
      fprintf(stderr, "linrandom: no display\n");
      return 1;
   }
   XVisualInfo *vi;
   GLXContext ctx;
   Window win = linear_window_current(dpy, W, H, &vi, &ctx, "linrandom");
   /* a draw and a flush first, so that the scenes may take the linear
    * path (a scene begun by a clear before any draw does not) */
   glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
   glRecti(0, 0, W, H);
   glFinish();
   if (probe) {
      const int rc = probes();
      glXMakeCurrent(dpy, None, NULL);
      glXDestroyContext(dpy, ctx);
      XDestroyWindow(dpy, win);
      XFree(vi);
      XCloseDisplay(dpy);
      return rc;
   }
   int images = 0;
   for (int k = 0; k < nscenes; k++) {
      scene(k);
      append_read_ppm(out, &images, W, H, 1);
   }
   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   XDestroyWindow(dpy, win);
   XFree(vi);
   XCloseDisplay(dpy);
   return 0;
}
