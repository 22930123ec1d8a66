/* p_cubemap.c - cube maps (ORACLE-NOTES.md "Cube maps"): each pixel's
 * face is the major axis of its (s, t, r) (x when |s| > |t|, z when
 * |r| >= max(|s|, |t|): ties go to z, then y), the face coordinates the
 * GL table's minor coordinates times |0.5 * (1/ma)| plus 0.5 (without a
 * level of detail 0.5 / |ma|, and 0 for ma = 0), sampled as a 2D image
 * with CLAMP_TO_EDGE (whatever GL_TEXTURE_WRAP_* say) on the 8-bit path.
 * The level of detail: the pixel's own derivatives (its row's
 * right - left, its column's bottom - top) carried onto its face
 * (0.5 * (d sc - sc * d ma / ma) / ma) and the 2D squared rho, each pixel
 * its own LOD under a mipmap filter; with min != mag and no mipmap
 * filter, the quad's top-left pixel's for the quad; an infinite or NaN
 * rho (q = 0) is 0, level 0 magnified.  Float colour
 * buffer; 16x16 faces with five levels of random texels; random
 * triangles under six filters, and constant directions on ties. */
#include "probe.h"
#include <limits.h>
#define W 48
#define H 48
static float buf[W*H*4];
static unsigned char tex[6][5][16*16*4];
static const int TS = 16, NL = 5;
static int lerp8(int w, int a, int b) { int d = b - a; return (a + ((w*d + 128) >> 8)) & 0xff; }
static unsigned f2u(float f){ unsigned u; memcpy(&u,&f,4); return u; }
static float u2f(unsigned u){ float f; memcpy(&f,&u,4); return f; }
static int clampi(int i, int lo, int hi) { return i < lo ? lo : i > hi ? hi : i; }
static int major(const float c[3]) {
  float as = fabsf(c[0]), at = fabsf(c[1]), ar = fabsf(c[2]);
  int sgt = !(as <= at); float m = as > at ? as : at; int rge = !(ar < m);
  return rge ? 2 : sgt ? 0 : 1;
}
static void minor(int ax, unsigned sg, const float v[3], float *fs, float *ft) {
  const unsigned S = 0x80000000u;
  if (ax == 0) { *fs = u2f(f2u(v[2]) ^ S ^ sg); *ft = u2f(f2u(v[1]) ^ S); }
  else if (ax == 1) { *fs = v[0]; *ft = u2f(f2u(v[2]) ^ sg); }
  else { *fs = u2f(f2u(v[0]) ^ sg); *ft = u2f(f2u(v[1]) ^ S); }
}
/* face and face coordinates; without derivatives (deriv 0) the scale is
 * 0.5 / |ma|, 0 when ma is 0 */
static int lookup(const float c[3], int deriv, float *s, float *t) {
  int ax = major(c); float ma = c[ax]; unsigned sg = f2u(ma) & 0x80000000u;
  float fs, ft; minor(ax, sg, c, &fs, &ft);
  float k = deriv ? fabsf(0.5f * (1.0f / ma)) : fabsf(ma) > 0.0f ? 0.5f / fabsf(ma) : 0.0f;
  *s = fs * k + 0.5f; *t = ft * k + 0.5f;
  return 2 * ax + (int)(sg >> 31);
}
static float cube_rho_px(const float tl[3], const float dx[3], const float dy[3]);
static float cube_rho(const float tl[3], const float tr[3], const float bl[3]) {
  float dx[3], dy[3]; for (int k = 0; k < 3; k++) { dx[k] = tr[k] - tl[k]; dy[k] = bl[k] - tl[k]; }
  return cube_rho_px(tl, dx, dy);
}
static float cube_rho_px(const float tl[3], const float dx[3], const float dy[3]) {
  int ax = major(tl); float ma = tl[ax]; unsigned sg = f2u(ma) & 0x80000000u;
  float fs, ft, fsx, ftx, fsy, fty;
  minor(ax, sg, tl, &fs, &ft); minor(ax, sg, dx, &fsx, &ftx); minor(ax, sg, dy, &fsy, &fty);
  float ima = 1.0f / ma, imh = 0.5f * ima;
  float mx = dx[ax] * ima, my = dy[ax] * ima;
  float a = (float)TS * ((fsx - mx * fs) * imh), b = (float)TS * ((ftx - mx * ft) * imh);
  float c = (float)TS * ((fsy - my * fs) * imh), d = (float)TS * ((fty - my * ft) * imh);
  a = a*a; b = b*b; c = c*c; d = d*d;
  float rx = a + b, ry = c + d; float rho = rx > ry ? rx : ry;
  /* lp_build_rho, explicit derivatives: an infinite or NaN rho is 0 */
  return (f2u(rho) & 0x7f800000u) == 0x7f800000u ? 0.0f : rho;
}
static const unsigned char *texel(int f, int L, int n, int i, int j) { return tex[f][L] + 4 * (j * n + i); }
static void sample_level(int f, int L, int linear, float s, float t, int out[4]) {
  int n = TS >> L;
  if (!linear) { int i = clampi((int)floorf(s * (float)n), 0, n-1), j = clampi((int)floorf(t * (float)n), 0, n-1);
    for (int c = 0; c < 4; c++) out[c] = texel(f, L, n, i, j)[c];
    return; }
  int us = (int)nearbyintf(s * (float)(n << 8)) - 128, ut = (int)nearbyintf(t * (float)(n << 8)) - 128;
  int ws = us & 255, wt = ut & 255, i = us >> 8, j = ut >> 8;
  int i0 = clampi(i, 0, n-1), i1 = (i < 0 || i >= n-1) ? i0 : i + 1;
  int j0 = clampi(j, 0, n-1), j1 = (j < 0 || j >= n-1) ? j0 : j + 1;
  for (int c = 0; c < 4; c++)
    out[c] = lerp8(wt, lerp8(ws, texel(f,L,n,i0,j0)[c], texel(f,L,n,i1,j0)[c]),
                       lerp8(ws, texel(f,L,n,i0,j1)[c], texel(f,L,n,i1,j1)[c]));
}
static const GLenum mins[6] = { GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_NEAREST };
static const GLenum mags[6] = { GL_NEAREST, GL_LINEAR, GL_NEAREST, GL_LINEAR, GL_NEAREST, GL_LINEAR };
/* the model's colour of a pixel at c with quad TL, TR, BL under filter m */
static float g_dx[3], g_dy[3];   /* the pixel's own derivatives */
static void model(int m, const float c[3], const float q[3][3], int res[4]) {
  float s, t; int f = lookup(c, m >= 2, &s, &t);
  int mipmapped = m == 2 || m == 3, min_lin = m != 2 && m != 5, mip_lin = m == 3;
  if (m >= 4) { float rho = cube_rho(q[0], q[1], q[2]);
    sample_level(f, 0, !(rho <= 1.0f) ? min_lin : !min_lin, s, t, res); return; }
  if (!mipmapped) { sample_level(f, 0, m == 1, s, t, res); return; }
  float rho = cube_rho_px(c, g_dx, g_dy);
  int L0 = 0, L1 = 0, wmip = 0, lod_pos = 0;
  if (!mip_lin) { int ex = (int)((f2u(rho) >> 23) & 255) - 126; L0 = ex >> 1; lod_pos = !(rho <= 1.0f);
    L0 = clampi(L0, 0, NL-1); }
  else { int ex = (int)((f2u(rho) >> 23) & 255) - 128; float mant = u2f((f2u(rho) & 0x7fffff) | 0x3f800000);
    float lod = ((float)ex + mant) * 0.5f; lod_pos = !(lod <= 0.0f);
    float fl = floorf(lod); float fp = lod - fl; L0 = (int)fl; L1 = L0 + 1;
    if (L0 < 0) { L0 = 0; L1 = 0; fp = 0; } if (L0 >= NL-1) { L0 = NL-1; L1 = NL-1; fp = 0; }
    wmip = (int)(fp * 256.0f); }
  if (!lod_pos && mags[m] != (min_lin ? GL_LINEAR : GL_NEAREST)) { sample_level(f, L0, mags[m] == GL_LINEAR, s, t, res); return; }
  sample_level(f, L0, min_lin, s, t, res);
  if (mip_lin && wmip > 0) { int r1[4]; sample_level(f, L1, min_lin, s, t, r1); for (int k = 0; k < 4; k++) res[k] = lerp8(wmip, res[k], r1[k]); }
}
int main(void) {
  probe_init_float(buf, W, H); glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0,W,0,H,-1,1);
  glEnable(GL_TEXTURE_CUBE_MAP); glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  srand(5);
  for (int f = 0; f < 6; f++) for (int L = 0; L < NL; L++) { int n = TS >> L; for (int i = 0; i < n*n*4; i++) tex[f][L][i] = rand() & 255;
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, L, GL_RGBA8, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex[f][L]); }
  /* wraps that would differ from CLAMP_TO_EDGE: ignored */
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  const char *names[6] = { "NEAREST (faces, coordinates)", "LINEAR (clamped per face)",
                           "NEAREST_MIPMAP_NEAREST (each pixel's rho)", "LINEAR_MIPMAP_LINEAR (each pixel's rho, log2)",
                           "LINEAR / NEAREST (the quad's rho)", "NEAREST / LINEAR (the quad's rho)" };
  const float invw = (float)(1.0/255.0);
  for (int m = 0; m < 6; m++) {
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, mins[m]); glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, mags[m]);
    long tot = 0, bad = 0;
    for (int iter = 0; iter < 60; iter++) {
      float vx[3], vy[3], s[3], t[3], r[3];
      for (int i = 0; i < 3; i++) { vx[i] = (rand() % (W*16)) / 16.0f; vy[i] = (rand() % (H*16)) / 16.0f;
        s[i] = (rand() % 2001) / 1000.0f - 1.0f; t[i] = (rand() % 2001) / 1000.0f - 1.0f; r[i] = (rand() % 2001) / 1000.0f - 1.0f;
        if (m >= 2 && (iter & 1)) { s[i] *= 0.05f; t[i] *= 0.05f; r[i] = r[i] < 0 ? -1.0f : 1.0f; } }
      glClearColor(-1,-1,-1,-1); glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_TRIANGLES); for (int i = 0; i < 3; i++) { glTexCoord3f(s[i], t[i], r[i]); glVertex2f(vx[i], vy[i]); } glEnd(); glFinish();
      float gx[3], gy[3]; for (int i = 0; i < 3; i++) win_from_ortho(vx[i], vy[i], W, H, &gx[i], &gy[i]);
      int o[3];
      if (setup_order(gx, gy, o) == 0) continue;
      const struct plane_setup ps = plane_init(gx, gy, o);
      float cs[3], ct[3], cr[3];
      plane_coef(&ps, s[o[0]], s[o[1]], s[o[2]], cs);
      plane_coef(&ps, t[o[0]], t[o[1]], t[o[2]], ct);
      plane_coef(&ps, r[o[0]], r[o[1]], r[o[2]], cr);
#define EV(C,X,Y) fmaf(C[2], (float)(Y), fmaf(C[1], (float)(X), C[0]))
      for (int py = 0; py < H; py++) for (int px = 0; px < W; px++) {
        float *p = &buf[4*((H-1-py)*W + px)]; if (p[0] == -1.0f) continue;
        int qx = px & ~1, qy = py & ~1;
        float q[3][3] = { { EV(cs,qx,qy), EV(ct,qx,qy), EV(cr,qx,qy) },
                          { EV(cs,qx+1,qy), EV(ct,qx+1,qy), EV(cr,qx+1,qy) },
                          { EV(cs,qx,qy+1), EV(ct,qx,qy+1), EV(cr,qx,qy+1) } };
        float c[3] = { EV(cs,px,py), EV(ct,px,py), EV(cr,px,py) };
        { /* lp_build_ddx / ddy per pixel: its row's right - left, its
           * column's bottom - top */
          float br[3] = { EV(cs,qx+1,qy+1), EV(ct,qx+1,qy+1), EV(cr,qx+1,qy+1) };
          int bottom = py & 1, right = px & 1;
          const float *tl = q[0], *tr = q[1], *bl = q[2];
          for (int k = 0; k < 3; k++) {
            g_dx[k] = bottom ? br[k] - bl[k] : tr[k] - tl[k];
            g_dy[k] = right ? br[k] - tr[k] : bl[k] - tl[k]; } }
        int res[4]; model(m, c, (const float (*)[3])q, res);
        for (int k = 0; k < 4; k++) { tot++; if (p[k] != (float)res[k]*invw) bad++; }
      }
    }
    char what[96];
    snprintf(what, sizeof what, "%s: %ld channels, misses", names[m], tot);
    probe_expect(what, bad, 0);
  }
  /* constant directions: exact axes, ties of two and three axes, both
   * signs, the face edges (|minor| == |major|), and (0, 0, 0) */
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  static const float dirs[][3] = {
    { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 },
    { 1, 1, 0 }, { -1, 1, 0 }, { 1, -1, 0 }, { 0, 1, 1 }, { 0, -1, -1 }, { 1, 0, 1 }, { -1, 0, -1 },
    { 1, 1, 1 }, { -1, -1, -1 }, { 1, -1, 1 }, { -1, 1, -1 }, { 0.5f, 0.5f, -0.5f },
    { 1, 0.999f, 0.2f }, { 0.3f, -1, 1 }, { -0.0f, -0.0f, 1 }, { 0, 0, -0.0f }, };
  long bad = 0;
  for (size_t d = 0; d < sizeof dirs / sizeof dirs[0]; d++) {
    glClearColor(-1,-1,-1,-1); glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS); glTexCoord3fv(dirs[d]);
    glVertex2f(0, 0); glVertex2f(4, 0); glVertex2f(4, 4); glVertex2f(0, 4); glEnd(); glFinish();
    float *p = buf;
    int res[4]; float q[3][3] = { { 0 } }; model(0, dirs[d], (const float (*)[3])q, res);
    for (int k = 0; k < 4; k++) if (p[k] != (float)res[k]*invw) { bad++;
      printf("  dir %g %g %g: oracle %g model %g\n", dirs[d][0], dirs[d][1], dirs[d][2], p[k]*255.0, (double)res[k]); break; }
  }
  probe_expect("constant directions on ties, axes and edges: misses", bad, 0);
  /* q = 0: the coordinates times 1/q are infinite (NaN for 0 * inf), their
   * derivatives NaN, so rho is NaN and becomes 0 (magnified, level 0)
   * under every filter; the face coordinates are NaN (inf * 0), whose
   * floor converts to INT32_MIN: texel (0, 0) under NEAREST.  (A NaN rho
   * kept would select the last level.) */
  static const GLenum qmin[4] = { GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
                                  GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR };
  static const float qdirs[][3] = { { -1, 5, 380 }, { 3, -0.5f, 0.25f }, { 0.5f, -2, 1 }, { 0, 0, 0 } };
  volatile float vzero = 0.0f;
  const float inf = 1.0f / vzero;
  bad = 0;
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  for (int m = 0; m < 4; m++) {
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, qmin[m]);
    for (size_t d = 0; d < sizeof qdirs / sizeof qdirs[0]; d++) {
      glClearColor(-1,-1,-1,-1); glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_QUADS); glTexCoord4f(qdirs[d][0], qdirs[d][1], qdirs[d][2], 0.0f);
      glVertex2f(0, 0); glVertex2f(4, 0); glVertex2f(4, 4); glVertex2f(0, 4); glEnd(); glFinish();
      float c[3], dd[3];
      for (int k = 0; k < 3; k++) { c[k] = qdirs[d][k] * inf; dd[k] = c[k] - c[k]; }
      const float rho = cube_rho_px(c, dd, dd);
      float s, t; const int f = lookup(c, 1, &s, &t);
      const float fsn = floorf(s * (float)TS), ftn = floorf(t * (float)TS);
      const int i = clampi(fsn >= -2147483648.0f && fsn < 2147483648.0f ? (int)fsn : INT_MIN, 0, TS-1);
      const int j = clampi(ftn >= -2147483648.0f && ftn < 2147483648.0f ? (int)ftn : INT_MIN, 0, TS-1);
      const unsigned char *e = texel(f, 0, TS, i, j);
      for (int k = 0; k < 4; k++) if (rho != 0.0f || buf[k] != (float)e[k]*invw) { bad++;
        printf("  q = 0, min filter %d, dir %g %g %g: oracle %g model %d\n", m,
               qdirs[d][0], qdirs[d][1], qdirs[d][2], buf[k]*255.0, e[k]); break; }
    }
  }
  probe_expect("q = 0: infinite or NaN rho is 0 (level 0, magnified): misses", bad, 0);
  return probe_result();
}
