/* p_tex3d.c - 3D textures on the 8-bit path (ORACLE-NOTES.md "3D
 * textures"): LINEAR lerps along s on both rows of each of the two
 * slices, then along t, then along r between the slices, each lerp on
 * 8 bits with r's weight from the same 8.8 fixed point as s and t; the
 * level of detail's rho adds (dr/dx * D)^2 and (dr/dy * D)^2 to the 2D
 * sums before the max; levels minify all three sizes.  Float colour
 * buffer; a 16x16x16 texture with five levels of random texels, random
 * triangles with random s, t, r under three filters. */
#include "probe.h"
#define W 48
#define H 48
static float buf[W*H*4];
static unsigned char tex[5][16*16*16*4];
static const int TS = 16, NL = 5;
static int lerp8(int w, int a, int b) { int d = b - a; return (a + ((w*d + 128) >> 8)) & 0xff; }
static unsigned f2u(float f){ unsigned u; memcpy(&u,&f,4); return u; }
static float u2f(unsigned u){ float f; memcpy(&f,&u,4); return f; }
static const unsigned char *texel(int L, int n, int i, int j, int k) {
  return tex[L] + 4 * (((size_t)k * (size_t)n + (size_t)j) * (size_t)n + (size_t)i);
}
static void axis(float c, int n, int *i0, int *i1, int *w) {
  int u = (int)nearbyintf(c * (float)(n << 8)) - 128;
  *w = u & 255; *i0 = (u >> 8) & (n-1); *i1 = (*i0 + 1) & (n-1);
}
static void sample_level(int L, int linear, float s, float t, float r, int out[4]) {
  int n = TS >> L; if (n < 1) n = 1;
  if (!linear) {
    int i = (int)floorf(s * (float)n) & (n-1), j = (int)floorf(t * (float)n) & (n-1);
    int k = (int)floorf(r * (float)n) & (n-1);
    for (int c = 0; c < 4; c++) out[c] = texel(L, n, i, j, k)[c];
    return; }
  int i0, i1, ws, j0, j1, wt, k0, k1, wr;
  axis(s, n, &i0, &i1, &ws); axis(t, n, &j0, &j1, &wt); axis(r, n, &k0, &k1, &wr);
  for (int c = 0; c < 4; c++) {
    int sl[2];
    for (int z = 0; z < 2; z++) { int k = z ? k1 : k0;
      int r0 = lerp8(ws, texel(L, n, i0, j0, k)[c], texel(L, n, i1, j0, k)[c]);
      int r1 = lerp8(ws, texel(L, n, i0, j1, k)[c], texel(L, n, i1, j1, k)[c]);
      sl[z] = lerp8(wt, r0, r1); }
    out[c] = lerp8(wr, sl[0], sl[1]); }
}
int main(void) {
  probe_init_float(buf, W, H); glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0,W,0,H,-1,1);
  glEnable(GL_TEXTURE_3D); glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  srand(3);
  for (int L = 0; L < NL; L++) { int n = TS >> L; for (int i = 0; i < n*n*n*4; i++) tex[L][i] = rand() & 255;
    glTexImage3D(GL_TEXTURE_3D, L, GL_RGBA8, n, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex[L]); }
  const GLenum mins[3] = { GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR };
  const GLenum mags[3] = { GL_LINEAR, GL_NEAREST, GL_LINEAR };
  const char *names[3] = { "LINEAR (trilinear lerp order)", "NEAREST_MIPMAP_NEAREST (3D rho)",
                           "LINEAR_MIPMAP_LINEAR (3D rho, log2)" };
  const float invw = (float)(1.0/255.0);
  for (int m = 0; m < 3; m++) {
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, mins[m]); glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, mags[m]);
    int mipmapped = m > 0, min_lin = m != 1, mip_lin = m == 2;
    long tot = 0, bad = 0;
    for (int iter = 0; iter < 40; iter++) {
      float vx[3], vy[3], s[3], t[3], r[3];
      float range = m == 0 ? 0.3f : 0.5f + (rand() % 8000) / 1000.0f;
      for (int i = 0; i < 3; i++) { vx[i] = (rand() % (W*16)) / 16.0f; vy[i] = (rand() % (H*16)) / 16.0f;
        s[i] = ((rand() % 2000) / 1000.0f - 1.0f) * range; t[i] = ((rand() % 2000) / 1000.0f - 1.0f) * range;
        /* r varies most in half of the triangles */
        r[i] = ((rand() % 2000) / 1000.0f - 1.0f) * range * ((iter & 1) ? 3.0f : 0.5f); }
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
        float s00 = EV(cs,qx,qy), s10 = EV(cs,qx+1,qy), s01 = EV(cs,qx,qy+1);
        float t00 = EV(ct,qx,qy), t10 = EV(ct,qx+1,qy), t01 = EV(ct,qx,qy+1);
        float r00 = EV(cr,qx,qy), r10 = EV(cr,qx+1,qy), r01 = EV(cr,qx,qy+1);
        float a = (s10 - s00) * (float)TS, b = (s01 - s00) * (float)TS, c = (t10 - t00) * (float)TS, d = (t01 - t00) * (float)TS;
        float e = (r10 - r00) * (float)TS, f = (r00 - r01) * (float)TS;
        a = a*a; b = b*b; c = c*c; d = d*d; e = e*e; f = f*f;
        float rx = (a + c) + e, ry = (b + d) + f; float rho = rx > ry ? rx : ry;
        int L0 = 0, L1 = 0, wmip = 0, lod_pos = 0;
        if (mipmapped && !mip_lin) { int ex = (int)((f2u(rho) >> 23) & 255) - 126; L0 = ex >> 1; lod_pos = rho > 1.0f;
          if (L0 < 0) L0 = 0;
          if (L0 > NL-1) L0 = NL-1; }
        else if (mip_lin) { int ex = (int)((f2u(rho) >> 23) & 255) - 128; float mant = u2f((f2u(rho) & 0x7fffff) | 0x3f800000);
          float lod = ((float)ex + mant) * 0.5f; lod_pos = lod > 0.0f;
          float fl = floorf(lod); float fp = lod - fl; L0 = (int)fl; L1 = L0 + 1;
          if (L0 < 0) { L0 = 0; L1 = 0; fp = 0; } if (L0 >= NL-1) { L0 = NL-1; L1 = NL-1; fp = 0; }
          wmip = (int)(fp * 256.0f); }
        float ss = EV(cs,px,py), tt = EV(ct,px,py), rr = EV(cr,px,py);
        int res[4];
        if (!mipmapped) { sample_level(0, 1, ss, tt, rr, res); }
        else if (!lod_pos && mags[m] != (min_lin ? GL_LINEAR : GL_NEAREST)) { sample_level(L0, mags[m] == GL_LINEAR, ss, tt, rr, res); }
        else { sample_level(L0, min_lin, ss, tt, rr, res);
          if (mip_lin && wmip > 0) { int r1[4]; sample_level(L1, min_lin, ss, tt, rr, r1); for (int k = 0; k < 4; k++) res[k] = lerp8(wmip, res[k], r1[k]); } }
        for (int k = 0; k < 4; k++) { tot++; if (p[k] != (float)res[k]*invw) bad++; }
      }
    }
    char what[96];
    snprintf(what, sizeof what, "%s: %ld channels, misses", names[m], tot);
    probe_expect(what, bad, 0);
  }
  return probe_result();
}
