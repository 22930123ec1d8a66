/* p_setup_fpstate.c - triangles that go through the draw module's pipeline
 * (a vertex of their vsplit segment needs clipping) are set up when
 * llvmpipe_draw_vbo flushes draw after draw_vbo returned, that is in the
 * application's floating-point state, not under draw_vbo's FTZ/DAZ; the
 * fragment shaders run with DAZ (the rasterizer's threads).  With w about
 * 1.5e35 the colour planes' derivatives are denormal: the oracle keeps
 * them in setup (they move a0 by a normal amount) and its shader reads
 * them as zero, so each triangle is one colour; with the caller's MXCSR
 * set to FTZ|DAZ the same draw gives other colours, those of the direct
 * path (seed 3000366 of the differential fuzzer, ORACLE-NOTES.md
 * "Interpolation"). */
#include "probe.h"

#include <xmmintrin.h>

#define W 64

/* the clipped quad of seed 3000366: window (x, y), clip w, colour */
static const float quad[4][7] = {
   { 64, 32, 1.53420652e+35f, 0.997522652f, 0.00247733132f, 0.0f, 0.0f },
   { 32, 32, 1.5380167e+35f, 1.0f, 0.0f, 0.0f, 0.0f },
   { 64, 64, 1.53041526e+35f, 0.995057583f, 0.00247120927f, 0.00247120927f, 0.0f },
   { 32, 64, 1.53420652e+35f, 0.997522652f, 0.0f, 0.00247733132f, 0.0f },
};
static const int tris[2][3] = { { 0, 1, 2 }, { 1, 3, 2 } };

static void vtx(int i)
{
   const float *q = quad[i];
   const float w = q[2];
   glColor4f(q[3], q[4], q[5], q[6]);
   glVertex4f((2.0f * q[0] / W - 1.0f) * w, (2.0f * q[1] / W - 1.0f) * w, 0.0f, w);
}

/* Draws the quad (and, `clipped`, a small triangle with a vertex outside
 * the left plane in the same glBegin/glEnd, so the segment takes the
 * pipeline) with the caller's MXCSR `csr`; copies the quad's pixels. */
static void draw(int clipped, unsigned csr, unsigned char out[32 * 32 * 4])
{
   clear0();
   const unsigned saved = _mm_getcsr();
   _mm_setcsr(csr);
   glBegin(GL_TRIANGLES);
   for (int t = 0; t < 2; t++)
      for (int k = 0; k < 3; k++)
         vtx(tris[t][k]);
   if (clipped) {
      glColor4f(0, 1, 0, 1);
      glVertex4f(-3.0f, -1.0f, 0.0f, 1.0f);
      glVertex4f(-0.6f, -1.0f, 0.0f, 1.0f);
      glVertex4f(-0.9f, -0.6f, 0.0f, 1.0f);
   }
   glEnd();
   glFinish();
   _mm_setcsr(saved);
   for (int y = 0; y < 32; y++)
      memcpy(out + 4 * 32 * y, px(32, 32 + y), 4 * 32);
}

static long count_rgba(const unsigned char *img, unsigned r, unsigned g, unsigned b, unsigned a)
{
   long n = 0;
   for (int i = 0; i < 32 * 32; i++)
      n += img[4 * i] == r && img[4 * i + 1] == g && img[4 * i + 2] == b && img[4 * i + 3] == a;
   return n;
}

int main(void)
{
   static unsigned char u_def[4096], u_ftz[4096], p_def[4096], p_ftz[4096];
   const unsigned csr = _mm_getcsr() & ~0x8040u, ftz = csr | 0x8040u;
   probe_init_ub(W, W);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glShadeModel(GL_SMOOTH);
   draw(0, csr, u_def);
   draw(0, ftz, u_ftz);
   draw(1, csr, p_def);
   draw(1, ftz, p_ftz);
   probe_expect("direct path: the caller's FTZ/DAZ changes nothing", memcmp(u_def, u_ftz, 4096), 0);
   probe_expect("pipeline, caller with FTZ/DAZ: the direct path's pixels",
                memcmp(p_ftz, u_def, 4096), 0);
   probe_expect("pipeline, caller without: other pixels", memcmp(p_def, p_ftz, 4096) != 0, 1);
   /* setup without FTZ: a0' = a*oow - (dadx*x0c + dady*y0c) with denormal
    * dadx, dady; the shader (DAZ) reads them as 0, so the colour is
    * a0'/w0' on every pixel: red 1.0, blue 0.00245 (1/255 after rounding) */
   probe_expect("pipeline, caller without: (255, 0, 1, 0) on all 1024 pixels",
                count_rgba(p_def, 255, 0, 1, 0), 1024);
   /* with FTZ the planes are a vertex's a*oow and oow: one colour per
    * triangle */
   probe_expect("pipeline, caller with FTZ/DAZ: (254, 0, 1, 0) + (255, 0, 0, 0)",
                count_rgba(p_ftz, 254, 0, 1, 0) + count_rgba(p_ftz, 255, 0, 0, 0), 1024);
   return probe_result();
}
