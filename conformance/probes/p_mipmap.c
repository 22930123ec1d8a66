/* p_mipmap.c - mipmaps and the level of detail on the 8-bit path: one LOD
 * per 2x2 quad from its top-left pixel's differences, rho^2 without a
 * square root, the exponent for NEAREST mip filters, the piecewise-linear
 * log2 for LINEAR ones, the 8-bit lerp between levels (ORACLE-NOTES.md
 * "Texture sampling: level of detail per quad").  Float colour buffer. */
#include "probe.h"
#define W 48
#define H 48
static float buf[W*H*4];
static unsigned char tex[5][16*16*4];
static const int TS = 16, NL = 5;
static int lerp8(int w, int a, int b) { int d = b - a; return (a + ((w*d + 128) >> 8)) & 0xff; }
static unsigned f2u(float f){ unsigned u; memcpy(&u,&f,4); return u; }
static float u2f(unsigned u){ float f; memcpy(&f,&u,4); return f; }
static void sample_level(int L, int linear, float s, float t, int out[4]) {
  int n = TS >> L; if (n < 1) n = 1;
  const unsigned char *T = tex[L];
  if (!linear) { int i = (int)floorf(s * (float)n) & (n-1), j = (int)floorf(t * (float)n) & (n-1);
    for (int c = 0; c < 4; c++) out[c] = T[4*(j*n+i)+c];
    return; }
  int si = (int)nearbyintf(s * (float)(n << 8)) - 128, ti = (int)nearbyintf(t * (float)(n << 8)) - 128;
  int ws = si & 255, wt = ti & 255; int i0 = (si >> 8) & (n-1), j0 = (ti >> 8) & (n-1);
  int i1 = (i0 != n-1) ? i0+1 : 0, j1 = (j0 != n-1) ? j0+1 : 0;
  for (int c = 0; c < 4; c++) { int r0 = lerp8(ws, T[4*(j0*n+i0)+c], T[4*(j0*n+i1)+c]);
    int r1 = lerp8(ws, T[4*(j1*n+i0)+c], T[4*(j1*n+i1)+c]); out[c] = lerp8(wt, r0, r1); }
}
int main(void) {
  probe_init_float(buf, W, H); glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0,W,0,H,-1,1);
  glEnable(GL_TEXTURE_2D); glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  srand(1);
  for (int L = 0; L < NL; L++) { int n = TS >> L; for (int i = 0; i < n*n*4; i++) tex[L][i] = rand() & 255;
    glTexImage2D(GL_TEXTURE_2D, L, GL_RGBA8, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex[L]); }
  const GLenum mins[5] = { GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR };
  const GLenum mags[5] = { GL_NEAREST, GL_LINEAR, GL_NEAREST, GL_LINEAR, GL_NEAREST };
  const char *names[5] = { "NEAREST_MIPMAP_NEAREST", "LINEAR_MIPMAP_NEAREST", "NEAREST_MIPMAP_LINEAR", "LINEAR_MIPMAP_LINEAR", "LINEAR_MIPMAP_LINEAR+mag NEAREST" };
  const float invw = (float)(1.0/255.0);
  for (int m = 0; m < 5; m++) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mins[m]); glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mags[m]);
    int min_lin = (mins[m] == GL_LINEAR_MIPMAP_NEAREST || mins[m] == GL_LINEAR_MIPMAP_LINEAR);
    int mip_lin = (mins[m] == GL_NEAREST_MIPMAP_LINEAR || mins[m] == GL_LINEAR_MIPMAP_LINEAR);
    int mag_lin = mags[m] == GL_LINEAR;
    long tot = 0, bad = 0;
    for (int iter = 0; iter < 40; iter++) {
      float vx[3], vy[3], s[3], t[3]; float range = 0.5f + (rand() % 8000) / 1000.0f;
      for (int i = 0; i < 3; i++) { vx[i] = (rand() % (W*16)) / 16.0f; vy[i] = (rand() % (H*16)) / 16.0f;
        s[i] = ((rand() % 2000) / 1000.0f - 1.0f) * range; t[i] = ((rand() % 2000) / 1000.0f - 1.0f) * range; }
      glClearColor(-1,-1,-1,-1); glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_TRIANGLES); for (int i = 0; i < 3; i++) { glTexCoord2f(s[i], t[i]); glVertex2f(vx[i], vy[i]); } glEnd(); glFinish();
      float gx[3], gy[3]; for (int i = 0; i < 3; i++) win_from_ortho(vx[i], vy[i], W, H, &gx[i], &gy[i]);
      int o[3];
      if (setup_order(gx, gy, o) == 0) continue;
      const struct plane_setup ps = plane_init(gx, gy, o);
      float cs[3], ct[3];
      plane_coef(&ps, s[o[0]], s[o[1]], s[o[2]], cs);
      plane_coef(&ps, t[o[0]], t[o[1]], t[o[2]], ct);
#define EV(C,X,Y) fmaf(C[2], (float)(Y), fmaf(C[1], (float)(X), C[0]))
      for (int py = 0; py < H; py++) for (int px = 0; px < W; px++) {
        float *p = &buf[4*((H-1-py)*W + px)]; if (p[0] == -1.0f) continue;
        int qx = px & ~1, qy = py & ~1;
        float s00 = EV(cs,qx,qy), s10 = EV(cs,qx+1,qy), s01 = EV(cs,qx,qy+1);
        float t00 = EV(ct,qx,qy), t10 = EV(ct,qx+1,qy), t01 = EV(ct,qx,qy+1);
        float a = (s10 - s00) * (float)TS, b = (s01 - s00) * (float)TS, c = (t10 - t00) * (float)TS, d = (t01 - t00) * (float)TS;
        a = a*a; b = b*b; c = c*c; d = d*d;
        float rx = a + c, ry = b + d; float rho = rx > ry ? rx : ry; if (isinf(rho) || isnan(rho)) rho = 0;
        int L0, L1 = 0, wmip = 0, lod_pos;
        if (!mip_lin) { int ex = (int)((f2u(rho) >> 23) & 255) - 126; L0 = ex >> 1; lod_pos = rho > 1.0f;
          if (L0 < 0) L0 = 0;
          if (L0 > NL-1) L0 = NL-1; }
        else { int ex = (int)((f2u(rho) >> 23) & 255) - 128; float mant = u2f((f2u(rho) & 0x7fffff) | 0x3f800000);
          float lod = ((float)ex + mant) * 0.5f; lod_pos = lod > 0.0f;
          float fl = floorf(lod); float fp = lod - fl; L0 = (int)fl; L1 = L0 + 1;
          if (L0 < 0) { L0 = 0; L1 = 0; fp = 0; } if (L0 >= NL-1) { L0 = NL-1; L1 = NL-1; fp = 0; }
          wmip = (int)(fp * 256.0f); }
        float ss = EV(cs,px,py), tt = EV(ct,px,py);
        int res[4];
        if (!lod_pos && mags[m] != (min_lin ? GL_LINEAR : GL_NEAREST)) { sample_level(L0, mag_lin, ss, tt, res); }
        else { sample_level(L0, min_lin, ss, tt, res);
          if (mip_lin && wmip > 0) { int r1[4]; sample_level(L1, min_lin, ss, tt, r1); for (int k = 0; k < 4; k++) res[k] = lerp8(wmip, res[k], r1[k]); } }
        for (int k = 0; k < 4; k++) { tot++; if (p[k] != (float)res[k]*invw) bad++; }
      }
    }
    char what[96];
    snprintf(what, sizeof what, "%s: %ld channels, misses", names[m], tot);
    probe_expect(what, bad, 0);
  }
  return probe_result();
}
