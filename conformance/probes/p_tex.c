/* p_tex.c - texture sampling on llvmpipe's 8-bit fixed-point path
 * (RGBA8, REPEAT / CLAMP_TO_EDGE, NEAREST / LINEAR, power-of-two and other
 * sizes, no mipmaps), GL_REPLACE (ORACLE-NOTES.md "Texture sampling: the
 * 8-bit path").  Float colour buffer, exact compare. */
#include "probe.h"
#define W 48
#define H 48
static float buf[W*H*4];
static unsigned char tex[64*64*4];
static int TW, TH;
static int wrapn(int i, int n, int wrap, float sn) {
  if (wrap == GL_CLAMP_TO_EDGE) return i < 0 ? 0 : (i > n-1 ? n-1 : i);
  if ((n & (n-1)) == 0) return i & (n-1);
  float fr = sn - floorf(sn); if (fr > 0.99999994f) fr = 0.99999994f;  /* fract_safe */
  return (int)(fr * (float)n);                                           /* itrunc */
}
static int lerp8(int w, int a, int b) { int d = b - a; return (a + ((w*d + 128) >> 8)) & 0xff; } /* pmulhrsw form */
static void lin_coord(float sn, int n, int wrap, int *c0, int *c1, int *fw) {
  if (wrap == GL_REPEAT && (n & (n-1))) {           /* npot repeat */
    float fr = sn - floorf(sn); float v = fr * (float)n; v = v * 256.0f;
    int i = (int)nearbyintf(v) - 128; *fw = i & 255; i >>= 8;
    if (i < 0) i = n - 1;
    if (i > n - 1) i = n - 1;
    *c0 = i; *c1 = (i != n - 1) ? i + 1 : 0; return;
  }
  float v = sn * (float)(n << 8);
  int i = (int)nearbyintf(v) - 128; *fw = i & 255; i >>= 8;
  if (wrap == GL_REPEAT) { *c0 = i & (n-1); *c1 = (*c0 != n-1) ? *c0 + 1 : 0; }
  else { int a = i, b = i + 1; *c0 = a < 0 ? 0 : (a > n-1 ? n-1 : a); *c1 = b < 0 ? 0 : (b > n-1 ? n-1 : b);
         if (i < 0 || i >= n-1) *c1 = *c0; }
}
static const unsigned char *T(int x, int y) { return &tex[4*(y*TW + x)]; }
int main(void) {
  probe_init_float(buf, W, H); glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0,W,0,H,-1,1);
  glEnable(GL_TEXTURE_2D); glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  srand(1);
  const int sizes[4][2] = { {4,4}, {8,2}, {5,3}, {7,6} };
  const int filt[2] = { GL_NEAREST, GL_LINEAR }, wraps[2] = { GL_REPEAT, GL_CLAMP_TO_EDGE };
  const float invw = (float)(1.0/255.0);
  for (int sz = 0; sz < 4; sz++) for (int fi = 0; fi < 2; fi++) for (int wi = 0; wi < 2; wi++) {
    long tot = 0, bad = 0;
    TW = sizes[sz][0]; TH = sizes[sz][1];
    for (int i = 0; i < TW*TH*4; i++) tex[i] = rand() & 255;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filt[fi]); glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filt[fi]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[wi]); glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[wi]);
    for (int iter = 0; iter < 10; iter++) {
      float st[2][3], gx[3], gy[3];
      draw_random_tex_tri(W, H, -1.0f, gx, gy, st);
      const float *s = st[0], *t = st[1];
      int o[3];
      if (setup_order(gx, gy, o) == 0) continue;
      const struct plane_setup ps = plane_init(gx, gy, o);
      float cs[3], ct[3];
      plane_coef(&ps, s[o[0]], s[o[1]], s[o[2]], cs);
      plane_coef(&ps, t[o[0]], t[o[1]], t[o[2]], ct);
      for (int py = 0; py < H; py++) for (int px = 0; px < W; px++) {
        float *p = &buf[4*((H-1-py)*W + px)]; if (p[0] == -1.0f) continue;
        float ss = fmaf(cs[2], (float)py, fmaf(cs[1], (float)px, cs[0])) * 1.0f;
        float tt = fmaf(ct[2], (float)py, fmaf(ct[1], (float)px, ct[0])) * 1.0f;
        int texel[4];
        if (fi == 0) {
          int i = (int)floorf(ss * (float)TW), j = (int)floorf(tt * (float)TH);
          i = wrapn(i, TW, wraps[wi], ss); j = wrapn(j, TH, wraps[wi], tt);
          for (int c = 0; c < 4; c++) texel[c] = T(i, j)[c];
        } else {
          int i0, i1, j0, j1, ws, wt;
          lin_coord(ss, TW, wraps[wi], &i0, &i1, &ws); lin_coord(tt, TH, wraps[wi], &j0, &j1, &wt);
          for (int c = 0; c < 4; c++) { int r0 = lerp8(ws, T(i0,j0)[c], T(i1,j0)[c]); int r1 = lerp8(ws, T(i0,j1)[c], T(i1,j1)[c]);
            texel[c] = lerp8(wt, r0, r1); }
        }
        for (int c = 0; c < 4; c++) { float m = (float)texel[c] * invw; tot++; if (p[c] != m) { bad++; } }
      }
    }
    char what[96];
    snprintf(what, sizeof what, "texture %dx%d %s %s: %ld channels, misses", TW, TH, fi ? "LINEAR" : "NEAREST", wi ? "CLAMP_TO_EDGE" : "REPEAT", tot);
    probe_expect(what, bad, 0);
  }
  return probe_result();
}
