/* p_tex_float.c - texture sampling on llvmpipe's float (SoA) path: the
 * wrap modes the 8-bit path does not take (GL_CLAMP, CLAMP_TO_BORDER,
 * MIRRORED_REPEAT, also mixed with REPEAT on the other axis), NEAREST and
 * LINEAR, the border colour, texels t * (float)(1/255) lerped with fused
 * multiply-adds (ORACLE-NOTES.md "Texture sampling: the float SoA path
 * and the general LOD").  RGBA8 textures, no mipmaps, GL_REPLACE, float
 * colour buffer, exact compare. */
#include "probe.h"

#define W 48
#define H 48
static float buf[W * H * 4];
static unsigned char tex[8 * 8 * 4];
static int TW, TH;
static float border[4];

/* cvttps2dq: INT32_MIN outside int32 and for NaN */
static int itrunc(float f)
{
   if (!(f >= -2147483648.0f && f < 2147483648.0f))
      return INT32_MIN;
   return (int)f;
}

/* minps / maxps: the second operand when either is NaN */
static float fmin_ps(float a, float b) { return a < b ? a : b; }
static float fmax_ps(float a, float b) { return a > b ? a : b; }

/* 2 * (x/2 - roundeven(x/2)), its absolute value */
static float mirror(float c)
{
   c = c * 0.5f;
   float f = c - nearbyintf(c);
   c = f + f;
   return fmax_ps(fabsf(c), 0.0f);
}

static int pot(int n) { return (n & (n - 1)) == 0; }

static int wrap_nearest(float c, int n, GLenum wrap)
{
   float nf = (float)n;
   int i;
   switch (wrap) {
   case GL_REPEAT:
      if (pot(n))
         return itrunc(floorf(c * nf)) & (n - 1);
      c = fmin_ps(c - floorf(c), 0x1.fffffep-1f);
      return itrunc(c * nf);
   case GL_CLAMP:
      i = itrunc(c * nf);
      i = i < n - 1 ? i : n - 1;
      return i > 0 ? i : 0;
   case GL_CLAMP_TO_BORDER:
      return itrunc(floorf(c * nf));
   default: /* GL_MIRRORED_REPEAT */
      i = itrunc(mirror(c) * nf);
      return i < n - 1 ? i : n - 1;
   }
}

static void floor_fract(float c, int *i, float *f)
{
   float ip = floorf(c);
   *f = c - ip;
   *i = itrunc(ip);
}

static void wrap_linear(float c, int n, GLenum wrap, int *x0, int *x1, float *w)
{
   float nf = (float)n;
   switch (wrap) {
   case GL_REPEAT:
      if (pot(n)) {
         floor_fract(c * nf - 0.5f, x0, w);
         *x1 = (*x0 + 1) & (n - 1);
         *x0 &= n - 1;
      } else {
         c = c - floorf(c);
         c = c * nf - 0.5f;
         int neg = !(c >= 0.0f);
         floor_fract(c, x0, w);
         if (neg) *x0 = n - 1;
         *x1 = *x0 != n - 1 ? *x0 + 1 : 0;
      }
      return;
   case GL_CLAMP:
      c = fmax_ps(fmin_ps(c * nf, nf), 0.0f);
      floor_fract(c - 0.5f, x0, w);
      *x1 = *x0 + 1;
      return;
   case GL_CLAMP_TO_BORDER:
      floor_fract(c * nf - 0.5f, x0, w);
      *x1 = *x0 + 1;
      return;
   default: /* GL_MIRRORED_REPEAT */
      floor_fract(mirror(c) * nf - 0.5f, x0, w);
      *x1 = *x0 + 1 < n - 1 ? *x0 + 1 : n - 1;
      *x0 = *x0 > 0 ? *x0 : 0;
      return;
   }
}

/* GL_CLAMP reaches the border colour only with a LINEAR filter */
static int uses_border(GLenum wrap, int linear)
{
   return wrap == GL_CLAMP_TO_BORDER || (wrap == GL_CLAMP && linear);
}

static void texel(int x, int y, GLenum ws, GLenum wt, int linear, float out[4])
{
   int b = (uses_border(ws, linear) && (x < 0 || x >= TW)) ||
           (uses_border(wt, linear) && (y < 0 || y >= TH));
   const float scale = (float)(1.0 / 255.0);
   for (int c = 0; c < 4; c++)
      out[c] = b ? border[c] : (float)tex[4 * (y * TW + x) + c] * scale;
}

static float lerp_f(float w, float a, float b) { return fmaf(w, b - a, a); }

static void sample(float s, float t, GLenum ws, GLenum wt, int linear, float out[4])
{
   if (!linear) {
      texel(wrap_nearest(s, TW, ws), wrap_nearest(t, TH, wt), ws, wt, 0, out);
      return;
   }
   int x0, x1, y0, y1;
   float fs, ft, a[4], b[4], c[4], d[4];
   wrap_linear(s, TW, ws, &x0, &x1, &fs);
   wrap_linear(t, TH, wt, &y0, &y1, &ft);
   texel(x0, y0, ws, wt, 1, a);
   texel(x1, y0, ws, wt, 1, b);
   texel(x0, y1, ws, wt, 1, c);
   texel(x1, y1, ws, wt, 1, d);
   for (int k = 0; k < 4; k++)
      out[k] = lerp_f(ft, lerp_f(fs, a[k], b[k]), lerp_f(fs, c[k], d[k]));
}

int main(void)
{
   probe_init_float(buf, W, H);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, W, 0, H, -1, 1);
   glEnable(GL_TEXTURE_2D);
   glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   srand(30);
   const int sizes[3][2] = { { 4, 4 }, { 5, 3 }, { 8, 2 } };
   const GLenum wraps[4][2] = { { GL_CLAMP, GL_CLAMP }, { GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER },
                                { GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT }, { GL_REPEAT, GL_CLAMP } };
   const char *wnames[4] = { "GL_CLAMP", "CLAMP_TO_BORDER", "MIRRORED_REPEAT", "REPEAT/GL_CLAMP" };
   for (int sz = 0; sz < 3; sz++)
      for (int fi = 0; fi < 2; fi++)
         for (int wi = 0; wi < 4; wi++) {
            long tot = 0, bad = 0;
            TW = sizes[sz][0];
            TH = sizes[sz][1];
            for (int i = 0; i < TW * TH * 4; i++) tex[i] = rand() & 255;
            for (int c = 0; c < 4; c++) border[c] = (rand() % 1000) / 999.0f;
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
            GLenum f = fi ? GL_LINEAR : GL_NEAREST;
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[wi][0]);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[wi][1]);
            glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
            for (int iter = 0; iter < 8; iter++) {
               float st[2][3], gx[3], gy[3];
               draw_random_tex_tri(W, H, -1.0f, gx, gy, st);
               int o[3];
               if (setup_order(gx, gy, o) == 0) continue;
               struct plane_setup ps = plane_init(gx, gy, o);
               float rs[3], rt[3];
               plane_coef(&ps, st[0][o[0]], st[0][o[1]], st[0][o[2]], rs);
               plane_coef(&ps, st[1][o[0]], st[1][o[1]], st[1][o[2]], rt);
               for (int py = 0; py < H; py++)
                  for (int x = 0; x < W; x++) {
                     const float *p = &buf[4 * ((H - 1 - py) * W + x)];
                     if (p[0] == -1.0f) continue;
                     /* the projective division by an interpolated q = 1 */
                     float s = plane_eval(rs, x, py) * (1.0f / 1.0f);
                     float t = plane_eval(rt, x, py) * (1.0f / 1.0f);
                     float m[4];
                     sample(s, t, wraps[wi][0], wraps[wi][1], fi, m);
                     for (int k = 0; k < 4; k++) {
                        tot++;
                        if (p[k] != m[k]) bad++;
                     }
                  }
            }
            char what[96];
            snprintf(what, sizeof what, "texture %dx%d %s %s: %ld channels, misses", TW, TH,
                     fi ? "LINEAR" : "NEAREST", wnames[wi], tot);
            probe_expect(what, bad, 0);
         }
   return probe_result();
}
