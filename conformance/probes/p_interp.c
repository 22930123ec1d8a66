/* p_interp.c - attribute interpolation: the setup's plane equations, the
 * fused per-pixel evaluation, perspective correction, window coordinates
 * (ORACLE-NOTES.md "Interpolation", "Window coordinates and the y-down
 * buffer").  Float colour buffer: the interpolated value itself. */
#include "probe.h"

#define W 64
#define H 64
static float buf[W * H * 4];

/* Affine: glOrtho, random triangles and colours; counts the channels the
 * fused model misses and those a model without FMA misses. */
static void affine(int seed, long *tot, long *bad, long *bad_nofma)
{
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, W, 0, H, -1, 1);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   srand(seed);
   for (int iter = 0; iter < 100; iter++) {
      float vx[3], vy[3], col[3][4], gx[3], gy[3];
      for (int i = 0; i < 3; i++) {
         vx[i] = (rand() % (W * 64)) / 64.0f;
         vy[i] = (rand() % (H * 64)) / 64.0f;
         for (int c = 0; c < 4; c++) col[i][c] = (rand() % 100000) / 100000.0f;
         win_from_ortho(vx[i], vy[i], W, H, &gx[i], &gy[i]);
      }
      glClearColor(-1, -1, -1, -1);
      glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_TRIANGLES);
      for (int i = 0; i < 3; i++) { glColor4fv(col[i]); glVertex2f(vx[i], vy[i]); }
      glEnd();
      glFinish();
      int o[3];
      if (setup_order(gx, gy, o) == 0) continue;
      struct plane_setup s = plane_init(gx, gy, o);
      float r[4][3];
      for (int c = 0; c < 4; c++) plane_coef(&s, col[o[0]][c], col[o[1]][c], col[o[2]][c], r[c]);
      for (int py = 0; py < H; py++)
         for (int x = 0; x < W; x++) {
            const float *p = &buf[4 * ((H - 1 - py) * W + x)];
            if (p[0] == -1.0f) continue;
            for (int c = 0; c < 4; c++) {
               float m = plane_eval(r[c], x, py);
               float q = r[c][2] * (float)py + (r[c][1] * (float)x + r[c][0]);
               if (m > 1) m = 1;   /* no clamp but the vertex colours' */
               if (q > 1) q = 1;
               (*tot)++;
               if (p[c] != m) (*bad)++;
               if (p[c] != q) (*bad_nofma)++;
            }
         }
   }
}

/* Perspective: clip coordinates with w != 1 (identity matrices), a
 * viewport of size vp; interp(a*oow) * (1/interp(oow)). */
static void perspective(int seed, int vp, long *tot, long *bad)
{
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glViewport(0, 0, vp, vp);
   float half = 0.5f * (float)vp;
   srand(seed);
   for (int iter = 0; iter < 100; iter++) {
      float cx[3], cy[3], cw[3], col[3][4], gx[3], gy[3], oow[3];
      for (int i = 0; i < 3; i++) {
         float nx = (rand() % 2000) / 1000.0f - 1.0f, ny = (rand() % 2000) / 1000.0f - 1.0f;
         cw[i] = 0.5f + (rand() % 4000) / 1000.0f;
         cx[i] = nx * cw[i];
         cy[i] = ny * cw[i];
         for (int c = 0; c < 4; c++) col[i][c] = (rand() % 100000) / 100000.0f;
         oow[i] = 1.0f / cw[i];
         gx[i] = fmaf(cx[i] * oow[i], half, half);
         gy[i] = fmaf(cy[i] * oow[i], -half, (float)H - half); /* y-down */
      }
      glClearColor(-1, -1, -1, -1);
      glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_TRIANGLES);
      for (int i = 0; i < 3; i++) { glColor4fv(col[i]); glVertex4f(cx[i], cy[i], 0.0f, cw[i]); }
      glEnd();
      glFinish();
      int o[3];
      if (setup_order(gx, gy, o) == 0) continue;
      struct plane_setup s = plane_init(gx, gy, o);
      float rw[3], r[4][3];
      plane_coef(&s, oow[o[0]], oow[o[1]], oow[o[2]], rw);
      for (int c = 0; c < 4; c++)
         plane_coef(&s, col[o[0]][c] * oow[o[0]], col[o[1]][c] * oow[o[1]],
                    col[o[2]][c] * oow[o[2]], r[c]);
      for (int py = 0; py < H; py++)
         for (int x = 0; x < W; x++) {
            const float *p = &buf[4 * ((H - 1 - py) * W + x)];
            if (p[0] == -1.0f) continue;
            float inv = 1.0f / plane_eval(rw, x, py);
            for (int c = 0; c < 4; c++) {
               (*tot)++;
               if (p[c] != plane_eval(r[c], x, py) * inv) (*bad)++;
            }
         }
   }
   glViewport(0, 0, W, H);
}

/* Texture coordinates through an ARB fragment program that writes them
 * out: same planes, perspective division by an interpolated 1 (exact). */
static void texcoords(long *tot, long *bad)
{
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, W, 0, H, -1, 1);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   const char *fp = "!!ARBfp1.0\nMOV result.color, fragment.texcoord[0];\nEND\n";
   GLuint id;
   glGenProgramsARB(1, &id);
   glBindProgramARB(GL_FRAGMENT_PROGRAM_ARB, id);
   glProgramStringARB(GL_FRAGMENT_PROGRAM_ARB, GL_PROGRAM_FORMAT_ASCII_ARB, (GLsizei)strlen(fp), fp);
   glEnable(GL_FRAGMENT_PROGRAM_ARB);
   srand(1);
   for (int iter = 0; iter < 60; iter++) {
      float st[2][3], gx[3], gy[3];
      draw_random_tex_tri(W, H, -9.0f, gx, gy, st);
      int o[3];
      if (setup_order(gx, gy, o) == 0) continue;
      struct plane_setup s = plane_init(gx, gy, o);
      float r[2][3];
      for (int c = 0; c < 2; c++) plane_coef(&s, st[c][o[0]], st[c][o[1]], st[c][o[2]], r[c]);
      for (int py = 0; py < H; py++)
         for (int x = 0; x < W; x++) {
            const float *p = &buf[4 * ((H - 1 - py) * W + x)];
            if (p[0] == -9.0f) continue;
            for (int c = 0; c < 2; c++) {
               (*tot)++;
               if (p[c] != plane_eval(r[c], x, py)) (*bad)++;
            }
         }
   }
   glDisable(GL_FRAGMENT_PROGRAM_ARB);
}

int main(void)
{
   probe_init_float(buf, W, H);
   glShadeModel(GL_SMOOTH);
   long tot = 0, bad = 0, nofma = 0;
   affine(1, &tot, &bad, &nofma);
   affine(7, &tot, &bad, &nofma);
   printf("     affine colours: %ld channels\n", tot);
   probe_expect("affine colours: channels the fused model misses", bad, 0);
   probe_expect("affine colours: a model without FMA misses some", nofma > 0, 1);

   tot = bad = 0;
   perspective(3, 64, &tot, &bad);
   perspective(3, 60, &tot, &bad);
   printf("     perspective colours: %ld channels\n", tot);
   probe_expect("perspective colours (viewports 64 and 60): misses", bad, 0);

   tot = bad = 0;
   texcoords(&tot, &bad);
   printf("     texture coordinates: %ld values\n", tot);
   probe_expect("texture coordinates: misses", bad, 0);
   return probe_result();
}
