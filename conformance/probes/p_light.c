/* p_light.c - per-vertex lighting: order of operations, gallivm's pow,
 * shininess 0, two-sided lighting, object- versus eye-space lighting,
 * spot and attenuation, local viewer with GL_NORMALIZE
 * (ORACLE-NOTES.md "Lighting order of operations", "gallivm's pow, exp2
 * and log2").  Float colour buffer, flat shading: a pixel is the clamped
 * lit colour of the provoking (last) vertex. */
#include "probe.h"
#include "gallivm_math.h"

#define W 32
#define H 32
static float buf[W * H * 4];

static float rnd(void) { return (rand() % 10000) / 10000.0f; }
static float clamp01(float v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }
/* Mesa's NORMALIZE_3FV on the CPU */
static void norm3(float v[3])
{
   float l = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
   if (l) {
      l = 1.0f / sqrtf(l);
      v[0] *= l; v[1] *= l; v[2] *= l;
   }
}
/* the vertex program's DP3: reduction from the last component */
static float dp3(const float *a, const float *b) { return (a[2] * b[2] + a[1] * b[1]) + a[0] * b[0]; }
static float rsq(float x) { return 1.0f / sqrtf(fabsf(x)); }
static void vnorm(float v[3])
{
   float r = rsq(dp3(v, v));
   v[0] *= r; v[1] *= r; v[2] *= r;
}

/* One directional light, infinite viewer, identity modelview; back faces
 * (two-sided, clockwise triangle) when `back`.  pow_libm: model with
 * libm's powf instead of gallivm's (expected to miss some). */
static void directional(int back, int pow_libm, long *tot, long *bad)
{
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, W, 0, H, -1, 1);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, back);
   srand(1);
   for (int iter = 0; iter < 300; iter++) {
      float la[4] = { rnd(), rnd(), rnd(), 1 }, ld[4] = { rnd(), rnd(), rnd(), 1 }, ls[4] = { rnd(), rnd(), rnd(), 1 };
      float ma[4] = { rnd(), rnd(), rnd(), rnd() }, md[4] = { rnd(), rnd(), rnd(), rnd() };
      float ms[4] = { rnd(), rnd(), rnd(), 1 }, me[4] = { rnd() * 0.3f, rnd() * 0.3f, rnd() * 0.3f, 1 };
      float gm[4] = { rnd() * 0.5f, rnd() * 0.5f, rnd() * 0.5f, 1 };
      float shin = (iter % 5 == 0) ? 0.0f : rnd() * 128.0f;
      float lp[4] = { rnd() * 2 - 1, rnd() * 2 - 1, rnd() * 2 - 1 + 0.2f, 0 };
      float n[3] = { rnd() * 2 - 1, rnd() * 2 - 1, rnd() * 1.5f - 0.3f };
      GLenum face = back ? GL_BACK : GL_FRONT;
      if (back) { /* a different front material, to see the choice */
         glMaterialfv(GL_FRONT, GL_AMBIENT, ms);
         glMaterialfv(GL_FRONT, GL_DIFFUSE, ms);
         glMaterialfv(GL_FRONT, GL_SPECULAR, ma);
         glMaterialf(GL_FRONT, GL_SHININESS, 7.0f);
      }
      glLightfv(GL_LIGHT0, GL_AMBIENT, la);
      glLightfv(GL_LIGHT0, GL_DIFFUSE, ld);
      glLightfv(GL_LIGHT0, GL_SPECULAR, ls);
      glLightfv(GL_LIGHT0, GL_POSITION, lp);
      glLightModelfv(GL_LIGHT_MODEL_AMBIENT, gm);
      glMaterialfv(face, GL_AMBIENT, ma);
      glMaterialfv(face, GL_DIFFUSE, md);
      glMaterialfv(face, GL_SPECULAR, ms);
      glMaterialfv(face, GL_EMISSION, me);
      glMaterialf(face, GL_SHININESS, shin);
      glClearColor(-1, -1, -1, -1);
      glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_TRIANGLES);
      glNormal3fv(n);
      glVertex2f(2, 2);
      if (back) { glVertex2f(2, 30); glVertex2f(30, 2); }
      else { glVertex2f(30, 2); glVertex2f(2, 30); }
      glEnd();
      glFinish();
      /* model: VP and the half vector precomputed on the CPU */
      float P[3] = { lp[0], lp[1], lp[2] };
      norm3(P);
      float Hh[3] = { P[0] + 0.0f, P[1] + 0.0f, P[2] + 1.0f };
      norm3(Hh);
      float nd = dp3(n, P), nh = dp3(n, Hh);
      if (back) { nd = -nd; nh = -nh; }
      float ly = nd > 0 ? nd : 0, lz;
      /* no pow only when every side's shininess is 0 (the front one is 7
       * when the back faces are drawn) */
      if (shin == 0.0f && !back)
         lz = (0.0f < nd) ? 1.0f : 0.0f;
      else {
         float e = shin > 128 ? 128 : shin, b = nh > 0 ? nh : 0;
         float pw = pow_libm ? powf(b, e) : gv_pow(b, e);
         lz = (0.0f >= nd) ? 0.0f : pw;
      }
      const float *p = &buf[4 * (10 * W + 10)];
      for (int c = 0; c < 3; c++) {
         float scene = gm[c] * ma[c] + me[c];
         float amb = la[c] * ma[c], dif = ld[c] * md[c], spc = ls[c] * ms[c];
         float col = amb + scene;
         col = ly * dif + col;
         col = lz * spc + col;
         (*tot)++;
         if (p[c] != clamp01(col)) (*bad)++;
      }
      (*tot)++;
      if (p[3] != clamp01(md[3])) (*bad)++; /* alpha: the diffuse alpha */
   }
   glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
}

/* Rotated modelview.  cfg 0: directional light (lighting in object space
 * unless force_eye); 1: positional light with spot and attenuation; 2:
 * positional light, local viewer, GL_NORMALIZE (both eye space). */
static void rotated(int cfg, int force_eye, long *tot, long *bad)
{
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(-1, 1, -1, 1, -10, 10);
   glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, cfg == 2);
   if (cfg == 2) glEnable(GL_NORMALIZE); else glDisable(GL_NORMALIZE);
   glLightModelfv(GL_LIGHT_MODEL_AMBIENT, (const float[4]){ 0.2f, 0.2f, 0.2f, 1 });
   glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
   glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0);
   glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1);
   glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0);
   glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0);
   srand(100 + cfg);
   for (int iter = 0; iter < 200; iter++) {
      float ang = rnd() * 360.0f, ax[3] = { rnd() - 0.5f, rnd() - 0.5f, rnd() - 0.5f };
      glMatrixMode(GL_MODELVIEW);
      glLoadIdentity();
      glRotatef(ang, ax[0], ax[1], ax[2]);
      GLfloat M[16];
      glGetFloatv(GL_MODELVIEW_MATRIX, M);
      float la[4] = { rnd(), rnd(), rnd(), 1 }, ld[4] = { rnd(), rnd(), rnd(), 1 }, ls[4] = { rnd(), rnd(), rnd(), 1 };
      float ma[4] = { rnd(), rnd(), rnd(), 1 }, md[4] = { rnd(), rnd(), rnd(), rnd() };
      float ms[4] = { rnd(), rnd(), rnd(), 1 }, me[4] = { rnd() * 0.2f, rnd() * 0.2f, rnd() * 0.2f, 1 };
      float shin = 1.0f + rnd() * 100.0f;
      float lp[4], sd[3] = { rnd() - 0.5f, rnd() - 0.5f, rnd() - 0.5f };
      float sexp = rnd() * 20, scut = 30 + rnd() * 60;
      float k0 = 0.5f + rnd(), k1 = rnd(), k2 = rnd() * 0.5f;
      if (cfg == 0) { lp[0] = rnd() * 2 - 1; lp[1] = rnd() * 2 - 1; lp[2] = rnd() * 2 - 1; lp[3] = 0; }
      else { lp[0] = rnd() * 4 - 2; lp[1] = rnd() * 4 - 2; lp[2] = rnd() * 4 - 2; lp[3] = 1; }
      glLightfv(GL_LIGHT0, GL_AMBIENT, la);
      glLightfv(GL_LIGHT0, GL_DIFFUSE, ld);
      glLightfv(GL_LIGHT0, GL_SPECULAR, ls);
      glLightfv(GL_LIGHT0, GL_POSITION, lp);
      if (cfg == 1) {
         glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, sd);
         glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, sexp);
         glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, scut);
         glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, k0);
         glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, k1);
         glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, k2);
      }
      glMaterialfv(GL_FRONT, GL_AMBIENT, ma);
      glMaterialfv(GL_FRONT, GL_DIFFUSE, md);
      glMaterialfv(GL_FRONT, GL_SPECULAR, ms);
      glMaterialfv(GL_FRONT, GL_EMISSION, me);
      glMaterialf(GL_FRONT, GL_SHININESS, shin);
      float n[3] = { rnd() * 2 - 1, rnd() * 2 - 1, rnd() * 2 - 1 };
      float vtx[3] = { rnd() * 0.2f - 0.1f, rnd() * 0.2f - 0.1f, rnd() * 0.2f - 0.1f };
      /* two vertices placed in eye space (through the transposed
       * rotation), the provoking one near the centre */
      float e1[3] = { -2, -2, 0 }, e2[3] = { 2, -2, 0 }, o1[3], o2[3];
      for (int i = 0; i < 3; i++) {
         o1[i] = M[i * 4 + 0] * e1[0] + M[i * 4 + 1] * e1[1] + M[i * 4 + 2] * e1[2];
         o2[i] = M[i * 4 + 0] * e2[0] + M[i * 4 + 1] * e2[1] + M[i * 4 + 2] * e2[2];
      }
      glClearColor(-1, -1, -1, -1);
      glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_TRIANGLES);
      glNormal3fv(n);
      glVertex3fv(o1);
      glVertex3fv(o2);
      glVertex3fv(vtx);
      glEnd();
      glFinish();
      const float *p = &buf[4 * (16 * W + 16)];
      if (p[0] == -1.0f) continue;
      /* ---- model ---- */
      float EP[4]; /* glLight(GL_POSITION): MV * p, sums left to right */
      for (int i = 0; i < 4; i++) EP[i] = M[i] * lp[0] + M[4 + i] * lp[1] + M[8 + i] * lp[2] + M[12 + i] * lp[3];
      float INV[16] = { 0 }; /* a rotation's inverse: its transpose */
      for (int r = 0; r < 3; r++)
         for (int c = 0; c < 3; c++) INV[c * 4 + r] = M[r * 4 + c];
      INV[15] = 1;
      int eye = cfg != 0 || force_eye;
      float Pos[4], EyeZ[3];
      if (eye) {
         for (int i = 0; i < 4; i++) Pos[i] = EP[i];
         EyeZ[0] = 0; EyeZ[1] = 0; EyeZ[2] = 1;
      } else {
         for (int i = 0; i < 4; i++) Pos[i] = INV[i] * EP[0] + INV[4 + i] * EP[1] + INV[8 + i] * EP[2] + INV[12 + i] * EP[3];
         EyeZ[0] = 0 * M[0] + 0 * M[1] + 1 * M[2];
         EyeZ[1] = 0 * M[4] + 0 * M[5] + 1 * M[6];
         EyeZ[2] = 0 * M[8] + 0 * M[9] + 1 * M[10];
      }
      if (lp[3] != 0) {
         float wi = 1.0f / Pos[3];
         Pos[0] *= wi; Pos[1] *= wi; Pos[2] *= wi;
      }
      float N[3];
      if (eye) { N[0] = dp3(n, &INV[0]); N[1] = dp3(n, &INV[4]); N[2] = dp3(n, &INV[8]); }
      else { N[0] = n[0] * 1.0f; N[1] = n[1] * 1.0f; N[2] = n[2] * 1.0f; }
      if (cfg == 2) vnorm(N);
      float VP[3], half[3], att = 1, V[4];
      int have_att = 0;
      for (int i = 0; i < 4; i++) V[i] = ((vtx[0] * M[i] + vtx[1] * M[4 + i]) + vtx[2] * M[8 + i]) + 1.0f * M[12 + i];
      if (lp[3] == 0) {
         VP[0] = Pos[0]; VP[1] = Pos[1]; VP[2] = Pos[2];
         norm3(VP);
         half[0] = VP[0] + EyeZ[0]; half[1] = VP[1] + EyeZ[1]; half[2] = VP[2] + EyeZ[2];
         norm3(half);
      } else {
         for (int i = 0; i < 3; i++) VP[i] = Pos[i] - V[i];
         float s2 = dp3(VP, VP), r = rsq(s2);
         for (int i = 0; i < 3; i++) VP[i] *= r;
         if (cfg == 1) {
            float SD[3];
            for (int i = 0; i < 3; i++) SD[i] = sd[0] * M[i] + sd[1] * M[4 + i] + sd[2] * M[8 + i];
            norm3(SD); /* normalized twice */
            norm3(SD);
            float cosc = cosf(scut * M_PI / 180.0);
            if (cosc < 0) cosc = 0;
            float nvp[3] = { -VP[0], -VP[1], -VP[2] };
            float spot = dp3(nvp, SD);
            float slt = (cosc < spot) ? 1.0f : 0.0f;
            att = slt * gv_pow(fabsf(spot), sexp);
            /* NIR: rcp(rsq(s)) -> sqrt(s), sqrt(s)*sqrt(s) -> s */
            float d1 = sqrtf(s2);
            float K[3] = { k0, k1, k2 }, D[3] = { r * d1, d1, s2 };
            att = (1.0f / dp3(K, D)) * att;
            have_att = 1;
         }
         if (cfg == 2) {
            float eh[3] = { V[0], V[1], V[2] };
            vnorm(eh);
            for (int i = 0; i < 3; i++) half[i] = VP[i] - eh[i];
         } else {
            half[0] = VP[0] + 0.0f; half[1] = VP[1] + 0.0f; half[2] = VP[2] + 1.0f;
         }
         vnorm(half);
      }
      float nd = dp3(N, VP), nh = dp3(N, half);
      float lit[3] = { 1, nd > 0 ? nd : 0, 0 };
      float e = shin > 128 ? 128 : shin, b = nh > 0 ? nh : 0;
      lit[2] = (0.0f >= nd) ? 0.0f : gv_pow(b, e);
      if (have_att) for (int i = 0; i < 3; i++) lit[i] *= att;
      for (int c = 0; c < 3; c++) {
         float scene = 0.2f * ma[c] + me[c];
         float amb = la[c] * ma[c], dif = ld[c] * md[c], spc = ls[c] * ms[c];
         float col = have_att ? (lit[0] * amb + scene) : (amb + scene);
         col = lit[1] * dif + col;
         col = lit[2] * spc + col;
         (*tot)++;
         if (p[c] != clamp01(col)) (*bad)++;
      }
   }
}

int main(void)
{
   probe_init_float(buf, W, H);
   glShadeModel(GL_FLAT);
   glEnable(GL_LIGHTING);
   glEnable(GL_LIGHT0);
   long tot = 0, bad = 0;
   directional(0, 0, &tot, &bad);
   printf("     directional light: %ld channels\n", tot);
   probe_expect("directional light, gallivm pow: misses", bad, 0);
   tot = bad = 0;
   directional(0, 1, &tot, &bad);
   probe_expect("directional light, libm powf: misses some", bad > 0, 1);
   tot = bad = 0;
   directional(1, 0, &tot, &bad);
   probe_expect("two-sided lighting, back faces: misses", bad, 0);

   tot = bad = 0;
   rotated(0, 0, &tot, &bad);
   printf("     rotated modelview, directional light: %ld channels\n", tot);
   probe_expect("rotated modelview, directional light, object space: misses", bad, 0);
   tot = bad = 0;
   rotated(0, 1, &tot, &bad);
   probe_expect("same, lit in eye space: misses some", bad > 0, 1);
   tot = bad = 0;
   rotated(1, 0, &tot, &bad);
   printf("     positional light: %ld channels\n", tot);
   probe_expect("positional light, spot, attenuation: misses", bad, 0);
   tot = bad = 0;
   rotated(2, 0, &tot, &bad);
   printf("     local viewer: %ld channels\n", tot);
   probe_expect("local viewer, GL_NORMALIZE: misses", bad, 0);
   return probe_result();
}
