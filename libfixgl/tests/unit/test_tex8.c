/*
 * test_tex8.c - r_tex_sample8 (raster/r_tex8.h), the texture lookup of an
 * 8-lane fragment vector (two 2x2 quads side by side), against the scalar
 * path lane by lane, bit for bit:
 *
 *   reference   a texture without `soa`: r_tex_lod_aos of the lane's quad
 *               (TL, TR, BL lanes: 0, 1, 4 for lanes 0, 1, 4, 5; 2, 3, 6
 *               for lanes 2, 3, 6, 7), then r_tex_filter_aos of the lane
 *               (r_tri.c fill_quad + r_frag.c tex_color); with `soa`:
 *               r_tex_sample with the quad (and the other quad when
 *               r_tex_need_pair)
 *   textures    random r_texture states as state.c builds them: 1D / 2D,
 *               power-of-two and other sizes, BaseLevel 0..2, full or
 *               partial mipmap chains, every min / mag / mip filter, REPEAT
 *               and CLAMP_TO_EDGE (the AVX2 kernel's own cases) and, for
 *               the portable fallback, the float-path wraps and the general
 *               LOD (bias, min/max LOD); random RGBA8 texels, each level its
 *               own allocation (small and large: far apart in memory)
 *   coordinates projected perspective planes over the 4x2 pixels with
 *               derivatives from deep magnification to heavy minification,
 *               and lanes replaced by NaN, +-inf, q = 0, huge and negative
 *               values, exact texel centres and edges of every level
 *   round trip  r_float_to_unorm8((float)b * (1/255)) == b for every byte
 *               (what the textured block kernels rely on)
 *   lerp        the kernels' pmulhrsw form of lerp8, every weight and pair
 *               of bytes
 *   implementations  r_tex_sample8_portable, the AVX2 kernel (when built
 *               and the CPU has it) and the dispatching r_tex_sample8
 *
 * FIXGL_TEX8_STATES=N (default 3000) and FIXGL_TEX8_SEED=S change the run.
 * With --bench (or FIXGL_TEX8_BENCH=1) it also times the texfloor scene's
 * lookup (256x256, full chain, LINEAR_MIPMAP_LINEAR, REPEAT): ns per lane
 * of the scalar path against the 8-lane kernels.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "raster/r_state.h"
#include "raster/r_tex8.h"

#include "check.h"

static uint64_t rng_state = 0x9e3779b97f4a7c15ull;

static uint64_t rnd64(void)
{
   uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
   z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
   z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
   return z ^ (z >> 31);
}

/* 0 .. n - 1 */
static int rnd(int n)
{
   return (int)(rnd64() % (uint64_t)n);
}

static float rndf(void)
{
   return (float)(rnd64() >> 40) * (1.0f / 16777216.0f);
}

static bool is_pot(int n)
{
   return n > 0 && (n & (n - 1)) == 0;
}

/* ---- random textures -------------------------------------------------- */

struct tex {
   struct r_texture t;
   uint8_t *mem[R_MAX_TEX_LEVELS];
};

static int rnd_size(int max_log2)
{
   if (rnd(2))
      return 1 << rnd(max_log2 + 1);
   return 1 + rnd((1 << max_log2) + 40);
}

/* update_texture_general's LOD flags */
static void lod_flags(struct r_texture *t)
{
   t->lod_bias_non_zero = t->lod_bias != 0.0f;
   t->min_max_lod_equal = t->apply_min_lod = t->apply_max_lod = false;
   if (t->mip != R_MIP_NONE || t->min_img != t->mag_img) {
      if (t->min_lod == t->max_lod) {
         t->min_max_lod_equal = true;
      } else {
         t->apply_min_lod = t->min_lod > 0.0f;
         t->apply_max_lod = t->max_lod < 15.0f;
      }
   }
}

/* kind 0: the AoS fast path; 1: general LOD (soa, AoS filtering);
 * 2: the float path (other wraps) */
static void make_texture(struct tex *x, int kind)
{
   struct r_texture *t = &x->t;
   memset(x, 0, sizeof *x);
   t->dims = rnd(3) ? 2 : 1;
   const int first = rnd(4) ? 0 : 1 + rnd(2);
   const int bw = rnd_size(t->dims == 1 ? 11 : 8);
   const int bh = t->dims == 1 ? 1 : rnd_size(8);
   const int w0 = bw << first, h0 = bh << first;
   t->first_level = first;
   t->min_img = (enum r_tex_filter)rnd(2);
   t->mag_img = (enum r_tex_filter)rnd(2);
   t->mip = (enum r_tex_mip)rnd(3);
   /* the levels as state.c sees a complete texture: each half the one
    * above (rounded down, at least 1) down to 1x1, or fewer */
   int n = 1;
   while ((bw >> (n - 1)) > 1 || (bh >> (n - 1)) > 1)
      n++;
   if (first + n > R_MAX_TEX_LEVELS)
      n = R_MAX_TEX_LEVELS - first;
   if (rnd(4) == 0)
      n = 1 + rnd(n);
   t->last_level = t->mip == R_MIP_NONE ? first : first + n - 1;
   const int pattern = rnd(3);   /* random bytes, only 0 / 255, few values */
   for (int l = first; l <= t->last_level; l++) {
      struct r_tex_level *lv = &t->level[l];
      lv->width = bw >> (l - first) ? bw >> (l - first) : 1;
      lv->height = t->dims == 1 ? 1 : (bh >> (l - first) ? bh >> (l - first) : 1);
      const size_t bytes = 4 * (size_t)lv->width * (size_t)lv->height;
      x->mem[l] = malloc(bytes);
      for (size_t i = 0; i < bytes; i++) {
         const unsigned r = (unsigned)rnd64();
         x->mem[l][i] = (uint8_t)(pattern == 0 ? r : pattern == 1 ? (r & 1 ? 255 : 0) : (r % 3) * 100);
      }
      lv->data = x->mem[l];
   }
   t->pot_s = is_pot(w0);
   t->pot_t = t->dims == 1 || is_pot(h0);
   if (rnd(20) == 0) {
      /* a resource whose level 0 is not the base level's size in
       * proportion (GL's incomplete-but-unused levels): the flags alone */
      t->pot_s = !t->pot_s;
      t->pot_t = t->dims == 1 || !t->pot_t;
   }
   t->wrap_s = (enum r_tex_wrap)rnd(2);
   t->wrap_t = (enum r_tex_wrap)rnd(t->dims == 1 ? 8 : 2);   /* ignored in 1D */
   t->max_lod = 1000.0f;
   for (int c = 0; c < 4; c++)
      t->border_color[c] = rndf();
   t->border_mask = 15;
   if (kind == 1) {
      t->lod_bias = (float)(rnd(33) - 16) * 0.25f;
      t->min_lod = rnd(2) ? 0.0f : (float)rnd(4) * 0.5f;
      t->max_lod = rnd(2) ? 1000.0f : (float)rnd(8) * 0.5f;
   } else if (kind == 2) {
      t->wrap_s = (enum r_tex_wrap)rnd(8);
      t->wrap_t = (enum r_tex_wrap)rnd(8);
      if (t->wrap_s <= R_WRAP_CLAMP_TO_EDGE && (t->dims == 1 || t->wrap_t <= R_WRAP_CLAMP_TO_EDGE))
         t->wrap_s = R_WRAP_CLAMP;
   }
   lod_flags(t);
   if (t->mip != R_MIP_NONE && t->last_level == 0 && t->max_lod > 0.0f)
      t->mip = R_MIP_NONE;
   t->float_path = kind == 2;
   t->soa = t->float_path || t->lod_bias_non_zero || t->min_max_lod_equal || t->apply_min_lod ||
            t->apply_max_lod;
}

static void free_texture(struct tex *x)
{
   for (int l = 0; l < R_MAX_TEX_LEVELS; l++)
      free(x->mem[l]);
}

/* ---- coordinates ------------------------------------------------------ */

static float special(const struct r_texture *t, int axis)
{
   const int l = t->first_level + rnd(t->last_level - t->first_level + 1);
   const int n = axis == 0 ? t->level[l].width : t->level[l].height;
   const int i = rnd(n + 2) - 1 + n * (rnd(9) - 4);
   switch (rnd(14)) {
   case 0: return NAN;
   case 1: return INFINITY;
   case 2: return -INFINITY;
   case 3: return (rnd(2) ? 1.0f : -1.0f) * ldexpf(1.0f + rndf(), 20 + rnd(100));
   case 4: return 2147483648.0f / (float)(n << 8);   /* s * (n << 8) = 2^31 */
   case 5: return -2147483648.0f / (float)(n << 8);
   case 6: return ((float)i + 0.5f) / (float)n;       /* texel centre */
   case 7: return (float)i / (float)n;                /* texel edge */
   case 8: return nextafterf((float)i / (float)n, rnd(2) ? INFINITY : -INFINITY);
   case 9: return ((float)i + 0.5f + (float)(rnd(3) - 1) / 512.0f) / (float)n;
   case 10: return rnd(2) ? -0.0f : 0.99999994f;
   case 11: return (float)(rnd(2001) - 1000);
   case 12: return -rndf() * 1e6f;
   default: return (rndf() - 0.5f) * 8.0f;
   }
}

/* The 8 lanes' projected coordinates: s, t, r, q planes over the 4x2
 * pixels (perspective), projected as r_tex_project does, then some lanes
 * or coordinates replaced by special values. */
static void make_coords(const struct r_texture *t, float c[3][8])
{
   const struct r_tex_level *base = &t->level[t->first_level];
   float plane[4][3];
   /* derivative scale: 2^-12 .. 2^8 texels per pixel */
   const float scale = ldexpf(1.0f, rnd(21) - 12);
   for (int k = 0; k < 3; k++) {
      const float n = (float)(k == 0 ? base->width : k == 1 ? base->height : 1);
      plane[k][0] = (rndf() - 0.5f) * 20.0f;
      plane[k][1] = (rndf() - 0.5f) * 2.0f * scale / n;
      plane[k][2] = (rndf() - 0.5f) * 2.0f * scale / n;
      if (rnd(8) == 0)
         plane[k][1] = 0.0f;
      if (rnd(8) == 0)
         plane[k][2] = 0.0f;
   }
   const int persp = rnd(3);
   plane[3][0] = persp == 0 ? 1.0f : 0.25f + 4.0f * rndf();
   plane[3][1] = persp == 2 ? (rndf() - 0.5f) * 0.2f : 0.0f;
   plane[3][2] = persp == 2 ? (rndf() - 0.5f) * 0.2f : 0.0f;
   for (int i = 0; i < 8; i++) {
      const float x = (float)(i & 3), y = (float)(i >> 2);
      float v[4], p[3];
      for (int k = 0; k < 4; k++)
         v[k] = plane[k][0] + plane[k][1] * x + plane[k][2] * y;
      if (persp && rnd(200) == 0)
         v[3] = rnd(2) ? 0.0f : -0.0f;   /* q = 0: inf or NaN */
      r_tex_project(v, p);
      for (int k = 0; k < 3; k++)
         c[k][i] = p[k];
   }
   const int mode = rnd(6);
   if (mode == 0) {
      /* a few lanes' coordinates replaced */
      for (int m = rnd(4); m >= 0; m--)
         c[rnd(2)][rnd(8)] = special(t, rnd(2));
   } else if (mode == 1) {
      /* every coordinate special */
      for (int k = 0; k < 3; k++)
         for (int i = 0; i < 8; i++)
            c[k][i] = special(t, k & 1);
   } else if (mode == 2) {
      /* one value over the block (no derivatives: magnified) */
      const float s = special(t, 0), tt = special(t, 1);
      for (int i = 0; i < 8; i++) {
         c[0][i] = s;
         c[1][i] = tt;
      }
   }
}

/* ---- reference -------------------------------------------------------- */

static void reference(const struct r_texture *t, const float c[3][8], float out[4][8])
{
   for (int i = 0; i < 8; i++) {
      const int q = (i >> 1) & 1;   /* quad A or B */
      float quad[2][3][3];
      for (int p = 0; p < 2; p++) {
         const int tl = 2 * p, lanes[3] = { tl, tl + 1, tl + 4 };
         for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
               quad[p][j][k] = c[k][lanes[j]];
      }
      const float ci[3] = { c[0][i], c[1][i], c[2][i] };
      float o[4];
      if (!t->soa) {
         struct r_tex_lod lod;
         r_tex_lod_aos(t, (const float (*)[3])quad[q], &lod);
         r_tex_filter_aos(t, ci, lod.minify, lod.level0, lod.level1, lod.weight, o);
      } else {
         r_tex_sample(t, ci, (const float (*)[3])quad[q],
                      r_tex_need_pair(t) ? (const float (*)[3])quad[q ^ 1] : NULL, o);
      }
      for (int k = 0; k < 4; k++)
         out[k][i] = o[k];
   }
}

static long lanes_checked[3], lanes_fast, states_fast, states[3];
/* fast-path calls by what the two quads' LOD asks (r_tex_filter_aos's
 * branches): the quads at different levels, one magnified and one
 * minified with different filters, a second level blended in; lanes with
 * a non-finite coordinate */
static long calls_fast, calls_split_level, calls_mixed_filter, calls_two_levels, lanes_nonfinite;

static void classify(const struct r_texture *t, const float c[3][8])
{
   struct r_tex_lod lod[2];
   for (int q = 0; q < 2; q++) {
      const float qc[3][3] = { { c[0][2 * q], c[1][2 * q], c[2][2 * q] },
                               { c[0][2 * q + 1], c[1][2 * q + 1], c[2][2 * q + 1] },
                               { c[0][2 * q + 4], c[1][2 * q + 4], c[2][2 * q + 4] } };
      r_tex_lod_aos(t, qc, &lod[q]);
   }
   calls_fast++;
   const bool mag[2] = { !lod[0].minify && t->mag_img != t->min_img,
                         !lod[1].minify && t->mag_img != t->min_img };
   calls_split_level += lod[0].level0 != lod[1].level0;
   calls_mixed_filter += mag[0] != mag[1];
   calls_two_levels += t->mip == R_MIP_LINEAR &&
                       ((!mag[0] && lod[0].weight > 0) || (!mag[1] && lod[1].weight > 0));
   for (int i = 0; i < 8; i++)
      lanes_nonfinite += !isfinite(c[0][i]) || (t->dims > 1 && !isfinite(c[1][i]));
}
static long combos[2][2][3][2][2][2];   /* dims, pot_s, mip, min, mag, wrap_s (fast states) */

static void compare(const char *name, const struct r_texture *t, const float c[3][8],
                    const float ref[4][8], const float got[4][8], int *reported)
{
   for (int i = 0; i < 8; i++) {
      bool same = true;
      for (int k = 0; k < 4; k++)
         same &= memcmp(&ref[k][i], &got[k][i], sizeof(float)) == 0;
      if (!same && (*reported)++ < 10) {
         FAIL("%s lane %d: dims %d %dx%d levels %d..%d pot %d%d min %d mag %d mip %d "
              "wrap %d %d soa %d: s %a t %a: got %a %a %a %a, expected %a %a %a %a",
              name, i, t->dims, t->level[t->first_level].width, t->level[t->first_level].height,
              t->first_level, t->last_level, t->pot_s, t->pot_t, t->min_img, t->mag_img, t->mip,
              t->wrap_s, t->wrap_t, t->soa, (double)c[0][i], (double)c[1][i],
              (double)got[0][i], (double)got[1][i], (double)got[2][i], (double)got[3][i],
              (double)ref[0][i], (double)ref[1][i], (double)ref[2][i], (double)ref[3][i]);
      }
   }
}

static void test_random(int nstates, int blocks)
{
   r_tex_sample8_fn avx2 = r_tex_sample8_avx2_fn();
   const r_tex_sample8_fn impl[3] = { r_tex_sample8_portable, avx2, r_tex_sample8 };
   const char *names[3] = { "portable", "avx2", "r_tex_sample8" };
   int reported = 0;
   for (int s = 0; s < nstates; s++) {
      struct tex x;
      const int kind = rnd(8) == 0 ? 1 + rnd(2) : 0;
      make_texture(&x, kind);
      const struct r_texture *t = &x.t;
      const bool fast = r_tex8_fast(t);
      states[kind]++;
      if (fast) {
         states_fast++;
         combos[t->dims - 1][t->pot_s][t->mip][t->min_img][t->mag_img][t->wrap_s]++;
      }
      const int nb = kind ? blocks / 8 : blocks;
      for (int b = 0; b < nb; b++) {
         float c[3][8], ref[4][8];
         make_coords(t, c);
         reference(t, (const float (*)[8])c, ref);
         for (int m = 0; m < 3; m++) {
            if (!impl[m])
               continue;
            float got[4][8];
            memset(got, 0x5a, sizeof got);
            impl[m](t, (const float (*)[8])c, got);
            compare(names[m], t, (const float (*)[8])c, (const float (*)[8])ref,
                    (const float (*)[8])got, &reported);
            lanes_checked[m] += 8;
         }
         if (fast && avx2)
            lanes_fast += 8;
         if (fast)
            classify(t, (const float (*)[8])c);
      }
      free_texture(&x);
   }
   int covered = 0, total = 0;
   for (int d = 0; d < 2; d++)
      for (int p = 0; p < 2; p++)
         for (int m = 0; m < 3; m++)
            for (int mi = 0; mi < 2; mi++)
               for (int ma = 0; ma < 2; ma++)
                  for (int w = 0; w < 2; w++) {
                     total++;
                     covered += combos[d][p][m][mi][ma][w] > 0;
                  }
   printf("tex8: %ld texture states (%ld AoS fast-LOD, %ld general LOD, %ld float path); "
          "%d of %d (dims, pot, mip, min, mag, wrap_s) fast-path combinations\n",
          states[0] + states[1] + states[2], states[0], states[1], states[2], covered, total);
   printf("tex8: lanes compared bit for bit: portable %ld, avx2 %ld (%ld on its own kernel), "
          "dispatch %ld; AVX2 kernel %s\n",
          lanes_checked[0], lanes_checked[1], lanes_fast, lanes_checked[2],
          avx2 ? "available" : "not available (not built or no AVX2+FMA CPU)");
   printf("tex8: fast-path calls %ld: quads on different levels %ld, a magnified quad next to a "
          "minified one (min != mag) %ld, a second mip level blended %ld; lanes with a "
          "non-finite coordinate %ld\n",
          calls_fast, calls_split_level, calls_mixed_filter, calls_two_levels, lanes_nonfinite);
   /* the default run is large enough to meet every combination */
   CHECK(!avx2 || nstates < 3000 || covered == total, "every fast-path combination covered (%d of %d)", covered,
         total);
}

/* ---- texfloor micro-benchmark ----------------------------------------- */

static double now_ns(void)
{
   struct timespec ts;
   clock_gettime(CLOCK_MONOTONIC, &ts);
   return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static volatile float sink;

static void bench(void)
{
   /* the texfloor texture: 256x256, full chain, LINEAR_MIPMAP_LINEAR, LINEAR
    * mag, REPEAT */
   struct tex x;
   memset(&x, 0, sizeof x);
   struct r_texture *t = &x.t;
   t->dims = 2;
   t->first_level = 0;
   t->last_level = 8;
   for (int l = 0; l <= 8; l++) {
      const int n = 256 >> l;
      x.mem[l] = malloc(4 * (size_t)n * (size_t)n);
      for (int i = 0; i < 4 * n * n; i++)
         x.mem[l][i] = (uint8_t)rnd64();
      t->level[l].width = t->level[l].height = n;
      t->level[l].data = x.mem[l];
   }
   t->pot_s = t->pot_t = true;
   t->min_img = t->mag_img = R_TEX_LINEAR;
   t->mip = R_MIP_LINEAR;
   t->wrap_s = t->wrap_t = R_WRAP_REPEAT;
   t->max_lod = 1000.0f;
   /* the floor of the scene (glFrustum(-0.4, 0.4, -0.3, 0.3, 0.5, 200), the
    * eye 1 above the floor, s = (x + 40) / 4, t = (-0.5 - z) * 40 / 99.5):
    * the 1024x384 pixels below the horizon, q = 1 / depth */
   enum { BW = 256, BH = 192, NB = BW * BH };
   float (*cs)[3][8] = malloc(sizeof(float[3][8]) * NB);
   for (int by = 0; by < BH; by++)
      for (int bx = 0; bx < BW; bx++)
         for (int i = 0; i < 8; i++) {
            const float px = (float)(bx * 4 + (i & 3)) + 0.5f;
            const float py = (float)(by * 2 + (i >> 2)) + 0.5f;
            const float xn = (px - 512.0f) / 512.0f;
            const float q = py / 384.0f * 0.6f;
            const float v[4] = { (xn * 0.8f + 40.0f * q) / 4.0f,
                                 (1.0f - 0.5f * q) * 40.0f / 99.5f, 0.0f, q };
            float p[3];
            r_tex_project(v, p);
            for (int k = 0; k < 3; k++)
               cs[by * BW + bx][k][i] = p[k];
         }
   const r_tex_sample8_fn avx2 = r_tex_sample8_avx2_fn();
   double best[3] = { 1e30, 1e30, 1e30 };
   float acc = 0.0f;
   for (int rep = 0; rep < 15; rep++) {
      /* scalar: one r_tex_lod_aos per quad (fill_quad), r_tex_filter_aos
       * per pixel (tex_color) */
      double t0 = now_ns();
      for (int b = 0; b < NB; b++) {
         const float (*c)[8] = (const float (*)[8])cs[b];
         for (int q = 0; q < 2; q++) {
            const float qc[3][3] = { { c[0][2 * q], c[1][2 * q], c[2][2 * q] },
                                     { c[0][2 * q + 1], c[1][2 * q + 1], c[2][2 * q + 1] },
                                     { c[0][2 * q + 4], c[1][2 * q + 4], c[2][2 * q + 4] } };
            struct r_tex_lod lod;
            r_tex_lod_aos(t, qc, &lod);
            for (int j = 0; j < 4; j++) {
               const int i = 2 * q + (j & 1) + 4 * (j >> 1);
               const float ci[3] = { c[0][i], c[1][i], c[2][i] };
               float o[4];
               r_tex_filter_aos(t, ci, lod.minify, lod.level0, lod.level1, lod.weight, o);
               acc += o[0];
            }
         }
      }
      double t1 = now_ns();
      if (t1 - t0 < best[0])
         best[0] = t1 - t0;
      for (int m = 1; m < 3; m++) {
         const r_tex_sample8_fn f = m == 1 ? r_tex_sample8_portable : avx2;
         if (!f)
            continue;
         t0 = now_ns();
         for (int b = 0; b < NB; b++) {
            float o[4][8];
            f(t, (const float (*)[8])cs[b], o);
            acc += o[0][0];
         }
         t1 = now_ns();
         if (t1 - t0 < best[m])
            best[m] = t1 - t0;
      }
   }
   sink = acc;
   const double lanes = (double)NB * 8.0;
   printf("tex8 bench (texfloor lookup, %d lanes, best of 15): scalar %.2f ns/lane, "
          "portable 8-lane %.2f ns/lane",
          NB * 8, best[0] / lanes, best[1] / lanes);
   if (avx2)
      printf(", AVX2 %.2f ns/lane (%.2fx scalar)", best[2] / lanes, best[0] / best[2]);
   printf("\n");
   free(cs);
   free_texture(&x);
}

/* The textured block kernels (r_block_tex_avx2.c) store a channel that is
 * the texel itself as the texel's byte: r_float_to_unorm8 of the lookup's
 * float, (float)b * (float)(1.0 / 255.0), must give b back. */
static void test_unorm8_round_trip(void)
{
   for (unsigned b = 0; b < 256; b++) {
      const float f = (float)b * (float)(1.0 / 255.0);
      CHECK(r_float_to_unorm8(f) == b, "texel byte %u round trip gives %u", b,
            (unsigned)r_float_to_unorm8(f));
   }
}

/* The 8-lane lerp (r_tex_avx2.h lerp16) is pmulhrsw(b - a, w * 128)
 * added to a, without a mask: for every weight 0..255 and bytes a, b that
 * is r_tex.c's lerp8, (a + ((w * (b - a) + 128) >> 8)) & 0xff.  pmulhrsw
 * per 16-bit lane: (x * y + 0x4000) >> 15 of the 32-bit product,
 * arithmetic, the low 16 bits kept; paddw keeps the low 16 bits. */
static void test_lerp_pmulhrsw(void)
{
   unsigned bad = 0;
   for (int w = 0; w < 256; w++)
      for (int a = 0; a < 256; a++)
         for (int b = 0; b < 256; b++) {
            const int ref = (a + ((w * (b - a) + 128) >> 8)) & 0xff;
            const int32_t prod = (int32_t)(int16_t)(b - a) * (int32_t)(int16_t)(w * 128);
            const uint16_t hrs = (uint16_t)((prod + 0x4000) >> 15);
            const uint16_t sum = (uint16_t)((unsigned)a + hrs);
            if (sum != ref && bad++ < 5)
               CHECK(false, "lerp w %d a %d b %d: pmulhrsw form %u, lerp8 %d", w, a, b, sum, ref);
         }
   CHECK(bad == 0, "pmulhrsw lerp differs from lerp8 for %u (w, a, b)", bad);
}

int main(int argc, char **argv)
{
   test_unorm8_round_trip();
   test_lerp_pmulhrsw();
   int nstates = 3000, blocks = 200;
   const char *e = getenv("FIXGL_TEX8_STATES");
   if (e)
      nstates = atoi(e);
   const char *seed = getenv("FIXGL_TEX8_SEED");
   if (seed)
      rng_state ^= strtoull(seed, NULL, 0) * 0x2545f4914f6cdd1dull;
   test_random(nstates, blocks);
   const char *b = getenv("FIXGL_TEX8_BENCH");
   if ((argc > 1 && strcmp(argv[1], "--bench") == 0) || (b && *b == '1'))
      bench();
   return check_report("unit-tex8");
}
