/* probe.h - the small harness shared by the oracle probes.
 *
 * Each probe renders with the system OSMesa (Mesa 22.3.6, llvmpipe: the
 * oracle), computes what a rule of libfixgl/ORACLE-NOTES.md predicts with
 * a plain C model, and compares bit for bit.  A probe prints one line per
 * check and exits 1 when any check fails, so `meson test --suite probes`
 * fails when the oracle (or the host's CPU: llvmpipe's results depend on
 * FMA) no longer behaves as the notes say.
 *
 * Built with -ffp-contract=off like libfixgl: every fmaf() in a model is
 * written where the oracle fuses, and nowhere else.
 */
#ifndef PROBE_H
#define PROBE_H

#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int probe_failures;

/* One named check: `got` must equal `want`. */
static void probe_expect(const char *what, long got, long want)
{
   int ok = got == want;
   printf("%s %s: %ld (expected %ld)\n", ok ? "ok  " : "FAIL", what, got, want);
   if (!ok)
      probe_failures++;
}

static int probe_result(void)
{
   if (probe_failures)
      printf("%d check(s) failed\n", probe_failures);
   return probe_failures ? 1 : 0;
}

/* RGBA8 colour buffer (depth 24, stencil 8) bound to the oracle, GL y-up
 * rows (OSMESA_Y_UP default), glOrtho(0, w, 0, h, -1, 1). */
static unsigned char *g_buf;
static int g_w, g_h;
static OSMesaContext g_ctx;

static void probe_init_ub(int w, int h)
{
   g_w = w;
   g_h = h;
   g_ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
   g_buf = calloc((size_t)w * h, 4);
   if (!g_ctx || !g_buf || !OSMesaMakeCurrent(g_ctx, g_buf, GL_UNSIGNED_BYTE, w, h)) {
      fprintf(stderr, "cannot create an OSMesa context\n");
      exit(2);
   }
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, w, 0, h, -1, 1);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
}

/* Float RGBA colour buffer (no clamping or conversion on output: the
 * fragment's value as the shader computed it), depth 24, no stencil. */
static void probe_init_float(float *buf, int w, int h)
{
   g_w = w;
   g_h = h;
   g_ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
   if (!g_ctx || !OSMesaMakeCurrent(g_ctx, buf, GL_FLOAT, w, h)) {
      fprintf(stderr, "cannot create an OSMesa context\n");
      exit(2);
   }
   glViewport(0, 0, w, h);
}

/* Pixel (x, y) of the RGBA8 buffer, y = 0 the bottom row (GL order). */
static unsigned char *px(int x, int y) { return g_buf + 4 * (y * g_w + x); }

static void clear0(void)
{
   glClearColor(0, 0, 0, 0);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/* ---- models shared by several probes ---------------------------------- */

/* Triangle snapping: round half to even of v * 256 (cvtps2dq). */
static int snap_rne(float a) { return (int)nearbyintf(a * 256.0f); }

/* Line and point snapping: util_iround, half away from zero. */
static int snap_iround(float a)
{
   float f = 256.0f * a;
   return f >= 0.0f ? (int)(f + 0.5f) : (int)(f - 0.5f);
}

/* Window position of (x, y) under glOrtho(0, W, 0, H, -1, 1) and an
 * identity modelview, in the oracle's y-down window coordinates: Mesa's
 * float ortho matrix, the vertex program's column MUL/MAD chain, 1/w and
 * the fused viewport transform with the flipped y scale. */
static void win_from_ortho(float x, float y, int Wd, int Hd, float *gx, float *gy)
{
   float m0 = 2.0f / (float)Wd, m12 = -((float)Wd + 0.0f) / ((float)Wd - 0.0f);
   float m5 = 2.0f / (float)Hd, m13 = -((float)Hd + 0.0f) / ((float)Hd - 0.0f);
   float cx = ((x * m0 + y * 0.0f) + 0.0f * 0.0f) + 1.0f * m12;
   float cy = ((x * 0.0f + y * m5) + 0.0f * 0.0f) + 1.0f * m13;
   float oow = 1.0f / 1.0f;
   float sx = 0.5f * (float)Wd, tx = 0.5f * (float)Wd + 0.0f;
   float sy = -(0.5f * (float)Hd), ty = (float)Hd - (0.5f * (float)Hd + 0.0f);
   *gx = fmaf(cx * oow, sx, tx);
   *gy = fmaf(cy * oow, sy, ty);
}

/* The triangle setup's plane equations (llvmpipe lp_state_setup.c): for
 * vertices in setup order, plain float operations, no FMA. */
struct plane_setup {
   float x0c, y0c, dx20o, dy20o, dx01o, dy01o;
};

/* Orientation from the snapped coordinates; 0: dropped.  When negative
 * the setup order is (v1, v0, v2), written to order[]. */
static long long setup_order(const float gx[3], const float gy[3], int order[3])
{
   int X[3], Y[3];
   for (int i = 0; i < 3; i++) {
      X[i] = snap_rne(gx[i] - 0.5f);
      Y[i] = snap_rne(gy[i] - 0.5f);
   }
   long long area = (long long)(X[0] - X[1]) * (Y[2] - Y[0]) -
                    (long long)(X[2] - X[0]) * (Y[0] - Y[1]);
   order[0] = area < 0 ? 1 : 0;
   order[1] = area < 0 ? 0 : 1;
   order[2] = 2;
   return area;
}

static struct plane_setup plane_init(const float gx[3], const float gy[3], const int o[3])
{
   struct plane_setup s;
   s.x0c = gx[o[0]] - 0.5f;
   s.y0c = gy[o[0]] - 0.5f;
   float dx01 = gx[o[0]] - gx[o[1]], dy01 = gy[o[0]] - gy[o[1]];
   float dx20 = gx[o[2]] - gx[o[0]], dy20 = gy[o[2]] - gy[o[0]];
   float e = dx01 * dy20, f = dy01 * dx20;
   float ooa = 1.0f / (e - f);
   s.dx20o = dx20 * ooa;
   s.dy20o = dy20 * ooa;
   s.dx01o = dx01 * ooa;
   s.dy01o = dy01 * ooa;
   return s;
}

/* Coefficients (a0', dadx, dady) of one attribute, values in setup order. */
static void plane_coef(const struct plane_setup *s, float a0, float a1, float a2, float r[3])
{
   float da01 = a0 - a1, da20 = a2 - a0;
   float t1 = da01 * s->dy20o, t2 = da20 * s->dy01o;
   r[1] = t1 - t2;
   float t3 = da20 * s->dx01o, t4 = da01 * s->dx20o;
   r[2] = t3 - t4;
   float s1 = r[1] * s->x0c, s2 = r[2] * s->y0c;
   float sum = s1 + s2;
   r[0] = a0 - sum;
}

/* Per-pixel evaluation at integer y-down pixel (px, py): two fused ops. */
static float plane_eval(const float r[3], int x, int y)
{
   return fmaf(r[2], (float)y, fmaf(r[1], (float)x, r[0]));
}

/* A random triangle with texture coordinates in [-1.5, 2.5) drawn on a
 * buffer cleared to `clear` (vertices on the 1/16-pixel grid of a W x H
 * orthographic view): its window positions in gx, gy, its coordinates in
 * st (rand() must be seeded by the caller). */
static void draw_random_tex_tri(int Wd, int Hd, float clear, float gx[3], float gy[3],
                                float st[2][3])
{
   float vx[3], vy[3];
   for (int i = 0; i < 3; i++) {
      vx[i] = (rand() % (Wd * 16)) / 16.0f;
      vy[i] = (rand() % (Hd * 16)) / 16.0f;
      st[0][i] = (rand() % 4000) / 1000.0f - 1.5f;
      st[1][i] = (rand() % 4000) / 1000.0f - 1.5f;
      win_from_ortho(vx[i], vy[i], Wd, Hd, &gx[i], &gy[i]);
   }
   glClearColor(clear, clear, clear, clear);
   glClear(GL_COLOR_BUFFER_BIT);
   glBegin(GL_TRIANGLES);
   for (int i = 0; i < 3; i++) {
      glTexCoord2f(st[0][i], st[1][i]);
      glVertex2f(vx[i], vy[i]);
   }
   glEnd();
   glFinish();
}

#endif
