/* p_genmip_planes.c - where GL_GENERATE_MIPMAP's blit samples the level
 * above on llvmpipe's float path (formats wider than 8 bits a channel;
 * ORACLE-NOTES.md "Copies into textures and generated mipmaps"):
 *  - the blit draws the level as a fan V0 (0, 0), V1 (w, 0), V2 (w, h),
 *    V3 (0, h) with texture coordinates (0, 0), (1, 0), (1, 1), (0, 1);
 *    llvmpipe sets up the triangles (V1, V0, V2) and (V2, V0, V3) (both
 *    clockwise, so v0 and v1 swapped), each with the planes of
 *    "Interpolation" (probe.h plane_init / plane_coef / plane_eval); a
 *    pixel centre on the diagonal V0-V2 belongs to the first;
 *  - the texel is the fused bilinear lerp at that (s, t) with
 *    CLAMP_TO_EDGE, converted to unorm16 by
 *    lp_build_clamped_float_to_unsigned_norm, then to the channel's bits
 *    by scale_bits: a shift for 10 bits, ((u >> 2) * 3 + 2^13) >> 14 for
 *    the 2-bit alpha of RGB10_A2.
 * Random sizes up to 40x40 (a quarter square), RGBA16 and RGB10_A2; the
 * plain s = (i + 0.5) / w misses some thousands of channels. */
#include "probe.h"

#include <stdint.h>

static unsigned rnd = 11;
static unsigned r32(void)
{
   rnd = rnd * 1103515245u + 12345u;
   return rnd >> 8;   /* the LCG's low bits have short periods */
}

static unsigned to_unorm16(float v)
{
   if (!(v > 0.0f))
      v = 0.0f;
   if (v > 1.0f)
      v = 1.0f;
   const float x = v * (65535.0f / 65536.0f) + 128.0f;
   uint32_t u;
   memcpy(&u, &x, sizeof(u));
   return u & 0xffffu;
}

static unsigned scale_bits16(unsigned u, unsigned bits)
{
   const unsigned d = 16u - bits;
   if (d <= bits)
      return u >> d;
   return ((u >> bits) * ((1u << bits) - 1u) + (1u << (d - 1u))) >> d;
}

static void wrap_linear(float c, int n, int *x0, int *x1, float *w)
{
   c = fminf(c * (float)n, (float)n) - 0.5f;
   c = fmaxf(c, 0.0f);
   const float ip = floorf(c);
   *w = c - ip;
   *x0 = (int)ip;
   *x1 = *x0 + 1 < n - 1 ? *x0 + 1 : n - 1;
}

/* (s, t) of texel (i, j) of a w x h level: the quad model, or the plain
 * centres */
static void coord(int w, int h, int i, int j, int quad, float *s, float *t)
{
   if (!quad) {
      *s = ((float)i + 0.5f) / (float)w;
      *t = ((float)j + 0.5f) / (float)h;
      return;
   }
   const float fw = (float)w, fh = (float)h;
   const float gx[4] = { 0.0f, fw, fw, 0.0f }, gy[4] = { 0.0f, 0.0f, fh, fh };
   const float vs[4] = { 0, 1, 1, 0 }, vt[4] = { 0, 0, 1, 1 };
   const long long lhs = (2LL * i + 1) * h, rhs = (2LL * j + 1) * w;
   static const int tri[2][3] = { { 1, 0, 2 }, { 2, 0, 3 } };
   const int *v = tri[lhs >= rhs ? 0 : 1];
   const float x[3] = { gx[v[0]], gx[v[1]], gx[v[2]] }, y[3] = { gy[v[0]], gy[v[1]], gy[v[2]] };
   const int o[3] = { 0, 1, 2 };
   const struct plane_setup ps = plane_init(x, y, o);
   float rs[3], rt[3];
   plane_coef(&ps, vs[v[0]], vs[v[1]], vs[v[2]], rs);
   plane_coef(&ps, vt[v[0]], vt[v[1]], vt[v[2]], rt);
   *s = plane_eval(rs, i, j);
   *t = plane_eval(rt, i, j);
}

int main(void)
{
   probe_init_ub(16, 16);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   static uint16_t s16[40 * 40 * 4], l16[20 * 20 * 4];
   static uint32_t s10[40 * 40], l10[20 * 20];
   long channels = 0, off[2][2] = { { 0, 0 }, { 0, 0 } };   /* [format][model] */
   for (int it = 0; it < 200; it++) {
      const int W = 2 + (int)(r32() % 39), H = (it & 3) == 0 ? W : 2 + (int)(r32() % 39);
      const int w = W / 2, h = H / 2;
      for (int k = 0; k < W * H * 4; k++)
         s16[k] = (uint16_t)r32();
      for (int k = 0; k < W * H; k++)
         s10[k] = r32() ^ (r32() << 16);
      GLuint tex[2];
      glGenTextures(2, tex);
      for (int f = 0; f < 2; f++) {
         glBindTexture(GL_TEXTURE_2D, tex[f]);
         glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
         if (f == 0) {
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16, W, H, 0, GL_RGBA, GL_UNSIGNED_SHORT, s16);
            glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_SHORT, l16);
         } else {
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB10_A2, W, H, 0, GL_RGBA,
                         GL_UNSIGNED_INT_2_10_10_10_REV, s10);
            glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, l10);
         }
      }
      glDeleteTextures(2, tex);
      for (int j = 0; j < h; j++)
         for (int i = 0; i < w; i++) {
            channels += 4;
            for (int m = 0; m < 2; m++) {
               float s, t, ws, wt;
               int x0, x1, y0, y1;
               coord(w, h, i, j, m, &s, &t);
               wrap_linear(s, W, &x0, &x1, &ws);
               wrap_linear(t, H, &y0, &y1, &wt);
               const int at[4] = { y0 * W + x0, y0 * W + x1, y1 * W + x0, y1 * W + x1 };
               for (int c = 0; c < 4; c++)
                  for (int f = 0; f < 2; f++) {
                     const unsigned bits = f == 0 ? 16u : c == 3 ? 2u : 10u;
                     const unsigned mask = (1u << bits) - 1u;
                     const float sc = (float)(1.0 / (double)mask);
                     float v[4];
                     for (int k = 0; k < 4; k++)
                        v[k] = (float)(f == 0 ? s16[4 * at[k] + c]
                                              : (s10[at[k]] >> (10 * c)) & mask) * sc;
                     const float a = fmaf(ws, v[1] - v[0], v[0]);
                     const float b = fmaf(ws, v[3] - v[2], v[2]);
                     const unsigned q = scale_bits16(to_unorm16(fmaf(wt, b - a, a)), bits);
                     const unsigned o = f == 0 ? l16[4 * (j * w + i) + c]
                                               : (l10[j * w + i] >> (10 * c)) & mask;
                     off[f][m] += q != o;
                  }
            }
         }
   }
   printf("channels per format: %ld\n", channels);
   probe_expect("RGBA16: channels off the quad-plane model", off[0][1], 0);
   probe_expect("RGB10_A2: channels off the quad-plane model", off[1][1], 0);
   /* the plain centres are not the oracle's coordinates */
   probe_expect("RGBA16: plain centres (i + 0.5) / w miss channels", off[0][0] > 0, 1);
   return probe_result();
}
