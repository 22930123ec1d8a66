/*
 * linrules - the arithmetic of llvmpipe's linear path on a GLX drawable,
 * checked on Mesa's libGL (the oracle) alone: run_glx.py oracle.  Each
 * section draws 256 one-colour rectangles into bins that hold nothing
 * else (so the oracle takes its linear path for them, ORACLE-NOTES.md
 * "GLX linear rectangles"), reads them back and compares every channel
 * with the rule written here (ORACLE-NOTES.md "GLX linear arithmetic"):
 *
 *   constant    each glRecti flushed on its own (a state change between
 *               them: the colour is the current value, not a vertex
 *               attribute): trunc(c * 256 - c)
 *   interp      the colour given inside glBegin/glEnd (a vertex
 *               attribute, the same at every corner): the 1.15 fixed
 *               point interpolant (int)(c * 32767) >> 7
 *   batched     glColor then glRecti, 256 times without a flush: the
 *               first rectangle's colour is the current value, the vbo
 *               makes the colour a vertex attribute from the second on
 *               (vbo_exec_wrap_upgrade_vertex): constant, then interp
 *   blend       SRC_ALPHA, ONE_MINUS_SRC_ALPHA over a whole-buffer clear,
 *               constant and interp sources: per channel
 *               mul(s, a) + mul(d, 255 - a), mul(x, y) = (x * y +
 *               (x * y >> 8) + 128) >> 8, s and a the source bytes of the
 *               rules above, d the destination's
 *   textured    textured rectangles (nearest and linear filters, 1:1 and
 *               scaled, GL_MODULATE, GL_REPLACE, GL_DECAL, GL_RGBA and
 *               GL_BGRA images): the same bytes as the same rectangle in
 *               a bin that also holds a triangle (the ordinary path)
 *
 * Ten colours a channel a section and column, near k/255 (exact, one
 * ulp either side, quarter steps) and near k * 128 / 32767; the clear
 * colour (the blend's destination) changes with the pass.  Prints one
 * line a section and exits 1 when a channel differs from its rule.  On
 * fixgl's libGL it is not run: fixgl does not model the linear path yet
 * (README issue 20, "Open").
 *
 *   linrules
 */
#include <GL/gl.h>
#include <math.h>
#include <stdbool.h>

#include "glx_frames.h"

#define W 256
#define H 128
#define PASSES 10

/* the linear path's bytes (ORACLE-NOTES.md "GLX linear arithmetic") */
static int lin_const(float c)
{
   const float t = c * 256.0f - c;
   return (int)t;
}

static int lin_interp(float c)
{
   int v = (int)(unsigned)(c * 32767.0f);
   if (v > 32767)
      v = 32767;
   return v >> 7;
}

static int mul8(int x, int y)
{
   const int ab = x * y;
   return (ab + (ab >> 8) + 128) >> 8;
}

static int lin_blend(int s, int d, int a)
{
   const int r = mul8(s, a) + mul8(d, 255 - a);
   return r > 255 ? 255 : r;
}

/* channel ch of column k's colour in pass `pass`, in [0, 1] */
static float colour(int pass, int k, int ch)
{
   const int j = (k + ch * 67) & 255;
   float c;
   switch (pass) {
   case 0: c = j / 255.0f; break;
   case 1: c = nextafterf(j / 255.0f, 2.0f); break;
   case 2: c = nextafterf(j / 255.0f, -1.0f); break;
   case 3: c = (j + 0.25f) / 255.0f; break;
   case 4: c = (j + 0.5f) / 255.0f; break;
   case 5: c = (j + 0.75f) / 255.0f; break;
   default: c = (j * 128.0f + (float)((pass * 37 + ch * 11) % 128)) / 32767.0f; break;
   }
   if (ch == 1)
      c = nextafterf(c, 2.0f);
   if (ch == 2)
      c = nextafterf(c, -1.0f);
   return c < 0.0f ? 0.0f : c > 1.0f ? 1.0f : c;
}

enum section { S_CONSTANT, S_INTERP, S_BATCHED, S_BLEND_CONSTANT, S_BLEND_INTERP, S_COUNT };

static const char *const section_names[S_COUNT] = {
   "constant", "interp", "batched", "blend constant", "blend interp",
};

static void column(enum section s, int k, const float v[4])
{
   switch (s) {
   case S_CONSTANT:
   case S_BLEND_CONSTANT:
      glLineWidth(1.0f + (float)(k & 1));   /* a state change: the vbo flushes */
      glColor4fv(v);
      glRecti(k, 0, k + 1, 8);
      break;
   case S_BATCHED:
      glColor4fv(v);
      glRecti(k, 0, k + 1, 8);
      break;
   default:
      glBegin(GL_QUADS);
      glColor4fv(v);
      glVertex2i(k, 0);
      glVertex2i(k + 1, 0);
      glVertex2i(k + 1, 8);
      glVertex2i(k, 8);
      glEnd();
      break;
   }
}

/* one section: the number of channels that differ from the rule */
static int run_section(enum section s, int *total)
{
   const bool blend = s == S_BLEND_CONSTANT || s == S_BLEND_INTERP;
   int bad = 0;
   for (int pass = 0; pass < PASSES; pass++) {
      glClearColor((float)(pass % 5) * 0.2f + 0.1f, 0.3f + 0.01f * (float)pass,
                   0.7f - 0.013f * (float)pass, 0.5f);
      glClear(GL_COLOR_BUFFER_BIT);
      if (blend) {
         glEnable(GL_BLEND);
         glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      }
      for (int k = 0; k < 256; k++) {
         float v[4];
         for (int ch = 0; ch < 4; ch++)
            v[ch] = colour(pass, k, ch);
         column(s, k, v);
      }
      glDisable(GL_BLEND);
      glLineWidth(1.0f);
      unsigned char p[W * 4], d[4];
      glReadPixels(0, 4, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
      glClear(GL_COLOR_BUFFER_BIT);   /* the destination the blend saw */
      glReadPixels(0, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, d);
      for (int k = 0; k < 256; k++) {
         int src[4];
         for (int ch = 0; ch < 4; ch++) {
            const float c = colour(pass, k, ch);
            const bool constant = s == S_CONSTANT || s == S_BLEND_CONSTANT ||
                                  (s == S_BATCHED && k == 0);
            src[ch] = constant ? lin_const(c) : lin_interp(c);
         }
         for (int ch = 0; ch < 4; ch++) {
            const int want = blend ? lin_blend(src[ch], d[ch], src[3]) : src[ch];
            (*total)++;
            if (p[4 * k + ch] != want) {
               if (bad < 8)
                  printf("  %s pass %d column %d channel %d: %d, the rule gives %d\n",
                         section_names[s], pass, k, ch, p[4 * k + ch], want);
               bad++;
            }
         }
      }
   }
   return bad;
}

/* textured rectangles: row 0 (bins alone) against row 1 (bins with a
 * triangle); the number of pixels that differ */
static int run_textured(int *total)
{
   unsigned char rgba[256 * 4], bgra[256 * 4];
   for (int k = 0; k < 256; k++) {
      rgba[4 * k] = (unsigned char)k;
      rgba[4 * k + 1] = (unsigned char)(255 - k);
      rgba[4 * k + 2] = (unsigned char)((k * 7) & 255);
      rgba[4 * k + 3] = (unsigned char)((k * 13 + 5) & 255);
      bgra[4 * k] = rgba[4 * k + 2];
      bgra[4 * k + 1] = rgba[4 * k + 1];
      bgra[4 * k + 2] = rgba[4 * k];
      bgra[4 * k + 3] = rgba[4 * k + 3];
   }
   static const float C[][4] = {
      { 0.1f, 0.5f, 0.9f, 0.45f }, { 0.3f, 0.7f, 0.2f, 0.8f }, { 0.55f, 0.25f, 0.75f, 0.6f },
   };
   static const GLenum envs[] = { GL_MODULATE, GL_REPLACE, GL_DECAL };
   GLuint t;
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
   int bad = 0;
   for (int bgr = 0; bgr < 2; bgr++) {
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 256, 1, 0, bgr ? GL_BGRA : GL_RGBA,
                   GL_UNSIGNED_BYTE, bgr ? bgra : rgba);
      for (int filt = 0; filt < 2; filt++) {
         const GLint f = filt ? GL_LINEAR : GL_NEAREST;
         const float s0 = filt ? 0.1f : 0.0f, s1 = filt ? 0.73f : 1.0f;
         glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
         glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
         for (int e = 0; e < 3; e++) {
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)envs[e]);
            for (int c = 0; c < 3; c++) {
               glClearColor(0.2f, 0.4f, 0.6f, 0.5f);
               glClear(GL_COLOR_BUFFER_BIT);
               glColor4fv(C[c]);
               glEnable(GL_TEXTURE_2D);
               for (int row = 0; row < 2; row++) {
                  const int y = row * 64;
                  glBegin(GL_QUADS);
                  glTexCoord2f(s0, 0.0f);
                  glVertex2i(0, y);
                  glTexCoord2f(s1, 0.0f);
                  glVertex2i(256, y);
                  glTexCoord2f(s1, 1.0f);
                  glVertex2i(256, y + 8);
                  glTexCoord2f(s0, 1.0f);
                  glVertex2i(0, y + 8);
                  glEnd();
               }
               glDisable(GL_TEXTURE_2D);
               glBegin(GL_TRIANGLES);
               for (int b = 0; b < 4; b++) {
                  glVertex2i(b * 64 + 10, 110);
                  glVertex2i(b * 64 + 20, 110);
                  glVertex2i(b * 64 + 10, 120);
               }
               glEnd();
               unsigned char p0[W * 4], p1[W * 4];
               glReadPixels(0, 4, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, p0);
               glReadPixels(0, 68, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, p1);
               for (int k = 0; k < W; k++) {
                  (*total)++;
                  if (memcmp(p0 + 4 * k, p1 + 4 * k, 4) != 0) {
                     if (bad < 8)
                        printf("  textured %s filter %d env %d colour %d column %d: "
                               "%d %d %d %d alone, %d %d %d %d beside a triangle\n",
                               bgr ? "BGRA" : "RGBA", filt, e, c, k, p0[4 * k], p0[4 * k + 1],
                               p0[4 * k + 2], p0[4 * k + 3], p1[4 * k], p1[4 * k + 1],
                               p1[4 * k + 2], p1[4 * k + 3]);
                     bad++;
                  }
               }
            }
         }
      }
   }
   glDeleteTextures(1, &t);
   return bad;
}

int main(int argc, char **argv)
{
   (void)argv;
   if (argc != 1) {
      fprintf(stderr, "usage: linrules (run on Mesa's libGL under X)\n");
      return 2;
   }
   Display *dpy = XOpenDisplay(NULL);
   if (!dpy) {
      fprintf(stderr, "linrules: no display\n");
      return 1;
   }
   XVisualInfo *vi;
   GLXContext ctx;
   Window win = linear_window_current(dpy, W, H, &vi, &ctx, "linrules");
   /* a first draw and flush: the scenes that follow may take the linear
    * path (a scene begun by the context's first clear does not) */
   glBegin(GL_TRIANGLES);
   glVertex2i(0, 0);
   glVertex2i(1, 0);
   glVertex2i(0, 1);
   glEnd();
   glFinish();

   int failed = 0;
   for (int s = 0; s < S_COUNT; s++) {
      int total = 0;
      const int bad = run_section((enum section)s, &total);
      printf("%s: %d of %d channels as the rule\n", section_names[s], total - bad, total);
      failed |= bad != 0;
   }
   int total = 0;
   const int bad = run_textured(&total);
   printf("textured: %d of %d pixels as beside a triangle\n", total - bad, total);
   failed |= bad != 0;

   glXMakeCurrent(dpy, None, NULL);
   glXDestroyContext(dpy, ctx);
   XDestroyWindow(dpy, win);
   XFree(vi);
   XCloseDisplay(dpy);
   return failed;
}
