/*
 * Triangle rasterization, bit-exact with llvmpipe (ORACLE-NOTES.md
 * "Rasterization: snapping, fill rule, edge functions", "Interpolation").
 *
 * Precision note (after s_tritemp.h's): positions are snapped to 8 fractional
 * bits with round-half-even, (x - 0.5) * 256, exactly as llvmpipe's
 * calc_fixed_position does with cvtps2dq.  Orientation and the three edge
 * functions are evaluated on those integers in 64 bits, so coverage is exact
 * whatever the triangle size.  Attribute planes are computed in float from
 * the unsnapped window coordinates (lp_state_setup.c:calc_coef) and
 * evaluated per pixel as fma(dady, y, fma(dadx, x, a0)) at integer pixel
 * coordinates (lp_bld_interp.c).  Every float operation below is part of
 * the contract: the file is compiled with -ffp-contract=off and fmaf() is
 * called exactly where the oracle fuses.
 *
 * Fill rule (bottom_edge_rule = 1 for OSMesa's window buffers): in GL terms
 * pixel centres exactly on a left edge or a horizontal bottom edge are
 * inside; on a right or top edge they are outside.
 */
#include "r_kernel.h"
#include "r_scene.h"
#include "r_tri_cover.h"

#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* cvtps2dq: round half to even; NaN and out-of-range values give INT32_MIN. */
static inline int32_t cvt_rne_i32(float f)
{
   if (!(f >= -2147483648.0f && f < 2147483648.0f))
      return INT32_MIN;
   return (int32_t)lrintf(f);
}

/* 32-bit wrapping subtraction, as the SSE setup code does it. */
static inline int32_t sub_wrap(int32_t a, int32_t b)
{
   return (int32_t)((uint32_t)a - (uint32_t)b);
}

static inline int32_t min3(int32_t a, int32_t b, int32_t c)
{
   int32_t m = a < b ? a : b;
   return m < c ? m : c;
}

static inline int32_t max3(int32_t a, int32_t b, int32_t c)
{
   int32_t m = a > b ? a : b;
   return m > c ? m : c;
}

/* ---- coverage: llvmpipe's planes, bins and blocks ----------------------
 *
 * Coverage is decided exactly as llvmpipe decides it (lp_setup_tri.c,
 * lp_rast_tri.c, lp_rast_tri_tmp.h with RASTER_64 and the SSE mask
 * builders): edge planes with a 64-bit constant and 32-bit steps, extra
 * planes where the bounding box leaves the draw region, 64x64 tiles tested
 * at the corners (trivial reject / accept), then 16x16 and 4x4 blocks, then
 * pixels.  For every triangle with finite window coordinates this equals
 * testing each pixel centre against the three exact edge functions; it is
 * modelled step by step because NaN and infinite positions (w = 0) snap to
 * INT32_MIN and the 32-bit parts wrap, and then which pixels the oracle
 * draws depends on every one of those steps.  All 32-bit arithmetic below
 * wraps, as the SSE code does.  (ORACLE-NOTES.md "Coverage of non-finite
 * triangles"; "Rasterization: snapping, fill rule, edge functions" covers
 * the finite case only.) */

#define TILE_SIZE 64
#define MAX_PLANES R_MAX_PLANES

static inline int32_t neg32(int32_t a) { return (int32_t)(0u - (uint32_t)a); }
static inline int32_t mul32(int32_t a, int32_t b) { return (int32_t)((uint32_t)a * (uint32_t)b); }
static inline int32_t shl32(int32_t a, int n) { return (int32_t)((uint32_t)a << n); }
/* IMUL64 */
static inline int64_t imul64(int32_t a, int32_t b) { return (int64_t)a * (int64_t)b; }
/* 64-bit wrapping add/sub (garbage planes must not be UB) */
static inline int64_t add64(int64_t a, int64_t b) { return (int64_t)((uint64_t)a + (uint64_t)b); }
static inline int64_t sub64(int64_t a, int64_t b) { return (int64_t)((uint64_t)a - (uint64_t)b); }

/* floor_pot via bsr; 0 for 0 */
static inline uint32_t floor_pot(uint32_t n)
{
   if (n == 0)
      return 0;
   return 1u << (31 - __builtin_clz(n));
}

/* build_mask_linear_sse: sign bits of c + i*dcdx + j*dcdy, bit 4j+i. */
static inline unsigned mask_linear(int32_t c, int32_t dcdx, int32_t dcdy)
{
   unsigned mask = 0;
   int32_t row[4] = { c, r_add32(c, dcdx), r_add32(c, mul32(dcdx, 2)), r_add32(c, mul32(dcdx, 3)) };
   for (int j = 0; j < 4; j++) {
      for (int i = 0; i < 4; i++)
         mask |= (unsigned)(row[i] < 0) << (4 * j + i);
      for (int i = 0; i < 4; i++)
         row[i] = r_add32(row[i], dcdy);
   }
   return mask;
}

/* build_masks_sse: sign bits of the 16 sub-block corners (trivial
 * reject) and of the same plus cdiff (trivial accept). */
static inline void build_masks(int32_t c, int32_t cdiff, int32_t dcdx, int32_t dcdy,
                               unsigned *outmask, unsigned *partmask)
{
   *outmask |= mask_linear(c, dcdx, dcdy);
   *partmask |= mask_linear(r_add32(c, cdiff), dcdx, dcdy);
}

/* The per-block trivial reject/accept values of lp_rast_tri_tmp.h
 * (RASTER_64): c and the steps reduced by FIXED_ORDER to 32 bits, for
 * sub-blocks of size 1 << log2_sub pixels. */
static inline void block_masks(const struct r_plane *p, int64_t c, int log2_sub,
                               unsigned *outmask, unsigned *partmask)
{
   int32_t dcdx = neg32(p->dcdx) >> 8;
   int32_t dcdy = p->dcdy >> 8;
   const int32_t cox = (int32_t)(p->eo >> 8);
   const int32_t ei = shl32(r_add32(r_add32(dcdy, dcdx), neg32(cox)), log2_sub);
   const int32_t cox_s = shl32(cox, log2_sub);
   const int32_t co = r_add32((int32_t)(c >> 8), cox_s);
   const int32_t cdiff = r_add32(r_add32(ei, neg32(cox_s)),
                               (int32_t)((uint32_t)(int32_t)(sub64(c, 1) >> 8) -
                                         (uint32_t)(int32_t)(c >> 8)));
   dcdx = shl32(dcdx, log2_sub);
   dcdy = shl32(dcdy, log2_sub);
   build_masks(co, cdiff, dcdx, dcdy, outmask, partmask);
}

/* ---- attribute setup and shading ---------------------------------------- */

/* lp_state_setup.c:calc_coef with the triangle's shared factors. */
struct setup_factors {
   float x0c, y0c;
   float dx01o, dy01o, dx20o, dy20o;
};

static inline struct r_attr_plane make_plane(const struct setup_factors *f,
                                      float a0, float a1, float a2)
{
   struct r_attr_plane p;
   const float da01 = a0 - a1;
   const float da20 = a2 - a0;
   p.dadx = da01 * f->dy20o - da20 * f->dy01o;
   p.dady = da20 * f->dx01o - da01 * f->dx20o;
   p.a0 = a0 - (p.dadx * f->x0c + p.dady * f->y0c);
   return p;
}


#if defined(__SSE2__)
_Static_assert(sizeof(struct r_attr_plane) == 3 * sizeof(float), "planes are packed");
_Static_assert(offsetof(struct r_tri_setup, w) == offsetof(struct r_tri_setup, z) +
               sizeof(struct r_attr_plane), "w follows z");

/* make_plane's float operations on four attributes at once, lane c
 * those of a0[c], a1[c], a2[c], in the same order, each lane rounded as
 * the scalar one (mulps, subps, addps). */
static inline __attribute__((always_inline)) void plane_vectors(const struct setup_factors *f,
                                                               __m128 a0, __m128 a1, __m128 a2,
                                                               __m128 *c0_out, __m128 *dadx_out,
                                                               __m128 *dady_out)
{
   const __m128 da01 = _mm_sub_ps(a0, a1);
   const __m128 da20 = _mm_sub_ps(a2, a0);
   const __m128 dadx = _mm_sub_ps(_mm_mul_ps(da01, _mm_set1_ps(f->dy20o)),
                                  _mm_mul_ps(da20, _mm_set1_ps(f->dy01o)));
   const __m128 dady = _mm_sub_ps(_mm_mul_ps(da20, _mm_set1_ps(f->dx01o)),
                                  _mm_mul_ps(da01, _mm_set1_ps(f->dx20o)));
   *c0_out = _mm_sub_ps(a0, _mm_add_ps(_mm_mul_ps(dadx, _mm_set1_ps(f->x0c)),
                                       _mm_mul_ps(dady, _mm_set1_ps(f->y0c))));
   *dadx_out = dadx;
   *dady_out = dady;
}

/* The planes of lanes 2 and 3 only (z and w of four positions), written
 * to ts->z and ts->w. */
static inline void make_planes_zw(const struct setup_factors *f, __m128 a0, __m128 a1,
                                  __m128 a2, struct r_tri_setup *ts)
{
   __m128 c0, dadx, dady;
   plane_vectors(f, a0, a1, a2, &c0, &dadx, &dady);
   const __m128 hi = _mm_unpackhi_ps(c0, dadx);                               /* a0.2 dx.2 a0.3 dx.3 */
   const __m128 t2 = _mm_shuffle_ps(dady, c0, _MM_SHUFFLE(3, 3, 2, 2));       /* dy.2 dy.2 a0.3 a0.3 */
   const __m128 t3 = _mm_shuffle_ps(dadx, dady, _MM_SHUFFLE(3, 3, 3, 3));     /* dx.3 dx.3 dy.3 dy.3 */
   float *d = (float *)((char *)ts + offsetof(struct r_tri_setup, z));
   _mm_storeu_ps(d, _mm_shuffle_ps(hi, t2, _MM_SHUFFLE(2, 0, 1, 0)));         /* a0.2 dx.2 dy.2 a0.3 */
   _mm_storel_pi((__m64 *)(d + 4), _mm_shuffle_ps(t3, t3, _MM_SHUFFLE(2, 0, 2, 0)));  /* dx.3 dy.3 */
}

/* make_plane on four attributes at once, lane c the plane of a0[c],
 * a1[c], a2[c]: the same float operations in the same order, each lane
 * rounded as the scalar one (mulps, subps, addps), written to p[0..3]. */
static inline void make_planes4(const struct setup_factors *f, __m128 a0, __m128 a1,
                                __m128 a2, struct r_attr_plane p[4])
{
   __m128 c0, dadx, dady;
   plane_vectors(f, a0, a1, a2, &c0, &dadx, &dady);
   /* to { a0, dadx, dady } per lane: 12 floats in a row */
   const __m128 lo = _mm_unpacklo_ps(c0, dadx);                               /* a0.0 dx.0 a0.1 dx.1 */
   const __m128 hi = _mm_unpackhi_ps(c0, dadx);                               /* a0.2 dx.2 a0.3 dx.3 */
   const __m128 t0 = _mm_shuffle_ps(dady, c0, _MM_SHUFFLE(1, 1, 0, 0));       /* dy.0 dy.0 a0.1 a0.1 */
   const __m128 t1 = _mm_shuffle_ps(dadx, dady, _MM_SHUFFLE(1, 1, 1, 1));     /* dx.1 dx.1 dy.1 dy.1 */
   const __m128 t2 = _mm_shuffle_ps(dady, c0, _MM_SHUFFLE(3, 3, 2, 2));       /* dy.2 dy.2 a0.3 a0.3 */
   const __m128 t3 = _mm_shuffle_ps(dadx, dady, _MM_SHUFFLE(3, 3, 3, 3));     /* dx.3 dx.3 dy.3 dy.3 */
   float *d = (float *)p;
   _mm_storeu_ps(d, _mm_shuffle_ps(lo, t0, _MM_SHUFFLE(2, 0, 1, 0)));         /* a0.0 dx.0 dy.0 a0.1 */
   _mm_storeu_ps(d + 4, _mm_shuffle_ps(t1, hi, _MM_SHUFFLE(1, 0, 2, 0)));     /* dx.1 dy.1 a0.2 dx.2 */
   _mm_storeu_ps(d + 8, _mm_shuffle_ps(t2, t3, _MM_SHUFFLE(2, 0, 2, 0)));     /* dy.2 a0.3 dx.3 dy.3 */
}
#endif

/* Setup of the fragment inputs: the colour (and the secondary colour), from
 * the back-face slots for a back-facing two-sided triangle
 * (lp_state_setup.c:lp_twoside). */
static void setup_planes(const struct r_state *rs, const struct r_vertex *const v[3],
                         bool back, bool phong_back, struct r_tri_setup *ts)
{
   /* plain float arithmetic in llvmpipe's order */
   const float x0 = v[0]->pos[0], y0 = v[0]->pos[1];
   const float x1 = v[1]->pos[0], y1 = v[1]->pos[1];
   const float x2 = v[2]->pos[0], y2 = v[2]->pos[1];
   const float dx01 = x0 - x1, dy01 = y0 - y1;
   const float dx20 = x2 - x0, dy20 = y2 - y0;
   const float ooa = 1.0f / (dx01 * dy20 - dy01 * dx20);
   const struct setup_factors f = {
      .x0c = x0 - 0.5f, .y0c = y0 - 0.5f,
      .dx01o = dx01 * ooa, .dy01o = dy01 * ooa,
      .dx20o = dx20 * ooa, .dy20o = dy20 * ooa,
   };

#if defined(__SSE2__)
   /* z and w together, lanes 2 and 3 of the positions (ts->w follows
    * ts->z) */
   make_planes_zw(&f, _mm_loadu_ps(&v[0]->pos[0]), _mm_loadu_ps(&v[1]->pos[0]),
                  _mm_loadu_ps(&v[2]->pos[0]), ts);
#else
   ts->z = make_plane(&f, v[0]->pos[2], v[1]->pos[2], v[2]->pos[2]);
   ts->w = make_plane(&f, v[0]->pos[3], v[1]->pos[3], v[2]->pos[3]);
#endif
   /* [S: lp_state_setup.c:lp_do_offset_tri] (res1, res2) = cross(e, f).xy
    * of the setup-order edges; the larger slope is picked with an
    * unordered compare (NaN picks dzdx); offset = units + max * factor */
   ts->zoffset = 0.0f;
   if (rs->rast->offset_scale != 0.0f || rs->rast->offset_units != 0.0f) {
      const float dz01 = v[0]->pos[2] - v[1]->pos[2];
      const float dz20 = v[2]->pos[2] - v[0]->pos[2];
      const float res1 = dz20 * dy01 - dy20 * dz01;
      const float res2 = dx20 * dz01 - dz20 * dx01;
      const float dzdx = fabsf(res1 * ooa), dzdy = fabsf(res2 * ooa);
      const float max = !(dzdx <= dzdy) ? dzdx : dzdy;
      ts->zoffset = rs->rast->offset_units + max * rs->rast->offset_scale;
   }
   ts->quad_x = INT_MIN;   /* no quad cached */
   ts->quad_y = INT_MIN;
   ts->inputs = rs->fs->fs_inputs;
   ts->phong_back = phong_back;
   bool need_w = false;
   for (unsigned m = ts->inputs; m; m &= m - 1) {
      const int a = __builtin_ctz(m);
      const int slot = r_fs_slot(a, back);
      const bool flat = (rs->flat_mask & (1u << slot)) != 0;
      ts->flat_attr[a] = flat;
      need_w |= !flat;
      if (flat) {
         memcpy(ts->flat[a], v[2]->attr[slot], sizeof(ts->flat[a]));
         continue;
      }
#if defined(__SSE2__)
      make_planes4(&f, _mm_mul_ps(_mm_loadu_ps(v[0]->attr[slot]), _mm_set1_ps(v[0]->pos[3])),
                   _mm_mul_ps(_mm_loadu_ps(v[1]->attr[slot]), _mm_set1_ps(v[1]->pos[3])),
                   _mm_mul_ps(_mm_loadu_ps(v[2]->attr[slot]), _mm_set1_ps(v[2]->pos[3])),
                   ts->ap[a]);
#else
      for (int c = 0; c < 4; c++)
         ts->ap[a][c] = make_plane(&f, v[0]->attr[slot][c] * v[0]->pos[3],
                                       v[1]->attr[slot][c] * v[1]->pos[3],
                                       v[2]->attr[slot][c] * v[2]->pos[3]);
#endif
   }
   ts->need_w = need_w;
   if (__builtin_expect(rs->rast->sprite_coord_enable != 0, 0))
      r_zero_sprite_inputs(rs->rast, ts);
}

/* setup_planes in the floating-point state rs asks for (rs->setup_mxcsr:
 * draw's pipeline triangles are set up in the application's, the pixels
 * shaded in the draw's FTZ|DAZ) */
static void setup_shade(const struct r_state *rs, const struct r_vertex *const v[3],
                        bool back, bool phong_back, struct r_tri_setup *ts)
{
#if defined(__SSE2__)
   if (rs->setup_mxcsr) {
      const unsigned csr = _mm_getcsr();
      _mm_setcsr(rs->setup_mxcsr);
      setup_planes(rs, v, back, phong_back, ts);
      _mm_setcsr(csr);
      return;
   }
#endif
   setup_planes(rs, v, back, phong_back, ts);
}

void r_zero_sprite_inputs(const struct r_rast_state *rast, struct r_tri_setup *ts)
{
   for (unsigned m = rast->sprite_coord_enable; m; m &= m - 1) {
      const int a = R_FS_TEX0 + __builtin_ctz(m);
      if (!(ts->inputs & (1u << a)))
         continue;
      for (int c = 0; c < 4; c++) {
         ts->flat[a][c] = 0.0f;
         ts->ap[a][c] = (struct r_attr_plane){ 0.0f, 0.0f, 0.0f };
      }
   }
}

/* The texture coordinates of the quad of pixel (px, py) for the units in
 * `units`: its top-left, top-right and bottom-left pixels (even y-down
 * coordinates), evaluated like every pixel's inputs whether or not they
 * are covered [S: lp_bld_interp.c, lp_bld_quad.c] (ORACLE-NOTES.md
 * "Texture sampling: level of detail per quad"), cached in ts->quad for the
 * pixels of a quad's row. */
static inline __attribute__((always_inline)) void fill_quad(const struct r_state *rs, const struct r_tri_setup *ts, int px, int py,
                      unsigned units)
{
   static const int dx[3] = { 0, 1, 0 }, dy[3] = { 0, 0, 1 };
   const int qx = px & ~1, qy = py & ~1;
   /* the setup object itself is not const (rasterize_ccw's local): the
    * cache is written through it */
   struct r_tri_setup *cache = (struct r_tri_setup *)ts;
   if (qx != ts->quad_x || qy != ts->quad_y) {
      struct r_fs_quad *q = &cache->quad;
      /* i >= 3: the pair quad (qx ^ 2) when a lookup needs it */
      for (int i = 0; i < (rs->fs->tex_pair ? 6 : 3); i++) {
         const float fx = (float)((i < 3 ? qx : qx ^ 2) + dx[i % 3]), fy = (float)(qy + dy[i % 3]);
         const float rw = 1.0f / r_eval_plane(&ts->w, fx, fy);
         for (unsigned m = units; m; m &= m - 1) {
            const int u = __builtin_ctz(m);
            const int a = R_FS_TEX0 + u;
            float *d = i < 3 ? q->tex[u][i] : q->pair[u][i - 3];
            for (int c = 0; c < 4; c++)
               d[c] = ts->flat_attr[a] ? ts->flat[a][c] : r_eval_plane(&ts->ap[a][c], fx, fy) * rw;
         }
      }
      /* a cube map's bottom-right pixels, of the quad and of the pair
       * quad (r_tex_sample_cube: a LOD per pixel) */
      for (int i = 0; rs->fs->tex_cube && i < (rs->fs->tex_pair ? 2 : 1); i++) {
         const float fx = (float)((i ? qx ^ 2 : qx) + 1), fy = (float)(qy + 1);
         const float rw = 1.0f / r_eval_plane(&ts->w, fx, fy);
         for (unsigned m = units; m; m &= m - 1) {
            const int u = __builtin_ctz(m);
            const int a = R_FS_TEX0 + u;
            float *d = i ? q->pair_br[u] : q->br[u];
            for (int c = 0; c < 4; c++)
               d[c] = ts->flat_attr[a] ? ts->flat[a][c] : r_eval_plane(&ts->ap[a][c], fx, fy) * rw;
         }
      }
      /* the LOD of the units that texture (a pixel rectangle's quad
       * coordinate is unit 0's, whether or not it textures) */
      for (unsigned m = units & rs->fs->tex_units; m; m &= m - 1) {
         const int u = __builtin_ctz(m);
         const struct r_texture *t = &rs->tex[u]->tex;
         if (t->soa)
            continue;
         float qc[3][3];
         for (int i = 0; i < 3; i++)
            r_tex_project(q->tex[u][i], qc[i]);
         r_tex_lod_aos(t, (const float (*)[3])qc, &cache->lod[u]);
      }
      cache->quad_x = qx;
      cache->quad_y = qy;
   }
}

/* The fragment program of a textured triangle, with the level of detail
 * chosen once per quad (fill_quad).  Out of line: the untextured pixel
 * loop keeps its size. */
R_FMA_CLONES
static __attribute__((noinline)) void shade_textured(const struct r_state *rs,
                                                     const struct r_tri_setup *ts,
                                                     const float in[][4], int px, int py,
                                                     float color[4])
{
   fill_quad(rs, ts, px, py, rs->fs->tex_units);
   ((struct r_tri_setup *)ts)->quad.pos = (unsigned)((px & 1) | (py & 1) << 1);
   r_fragment_shader_lod(rs, in, &ts->quad, ts->lod, color);
}

/* Shades pixel (px, py), which is inside the draw region. */
static inline __attribute__((always_inline)) void shade_pixel(const struct r_state *rs, const struct r_tri_setup *ts,
                               int px, int py)
{
   /* polygon stipple: the pstipple stage's kill, first */
   if (rs->rast->stipple && !r_stipple_pass(rs, px, py))
      return;
   if (__builtin_expect(rs->stats != NULL, 0))
      rs->stats->fragments++;
   const float fx = (float)px, fy = (float)py;
   float in[R_FS_NUM_INPUTS][4];
   const float rw = ts->need_w ? 1.0f / r_eval_plane(&ts->w, fx, fy) : 0.0f;
   for (unsigned m = ts->inputs; m; m &= m - 1) {
      const int a = __builtin_ctz(m);
      for (int c = 0; c < 4; c++)
         in[a][c] = ts->flat_attr[a] ? ts->flat[a][c] : r_eval_plane(&ts->ap[a][c], fx, fy) * rw;
   }
   if (rs->pix) {
      /* a pixel rectangle's quad: its own fragment stage (r_pixels.c);
       * a unit reading the quad's coordinate (R_FS_TEX0) needs its quad */
      const bool quad = rs->fs->tex_units && rs->pix->tex_quad;
      if (quad) {
         fill_quad(rs, ts, px, py, 1u);
         ((struct r_tri_setup *)ts)->quad.pos = (unsigned)((px & 1) | (py & 1) << 1);
      }
      r_pixel_fragment(rs, px, py, (const float (*)[4])in, r_eval_plane(&ts->z, fx, fy),
                       quad ? &ts->quad : NULL);
      return;
   }
   if (rs->fs->phong)
      r_fragment_phong(rs, in, ts->phong_back);
   float color[4];
   if (rs->fs->tex_units) {
      shade_textured(rs, ts, (const float (*)[4])in, px, py, color);
   } else {
      r_fragment_shader(rs, (const float (*)[4])in, NULL, color);
   }
   if (rs->fs->aa != R_AA_NONE && !r_fragment_aa(rs, (const float (*)[4])in, color))
      return;
   /* lp_bld_interp.c: z = interpolated z + polygon offset (an fadd) */
   r_fragment_ops(rs, px, py, r_eval_plane(&ts->z, fx, fy) + ts->zoffset, color);
}

/* Shades the pixels of the 4x4 block at (x, y) selected by mask (bit 4j+i
 * is pixel (x+i, y+j)).  The scissor box is only the extra planes (and the
 * tiles binned): where a non-finite primitive's edges reach beyond its
 * bounding box, a side of the box inside the draw region adds no plane
 * and the oracle writes the pixels outside the scissor box too, up to the
 * framebuffer ([S: lp_rast.c:lp_rast_shade_quads_mask] drops only blocks past
 * the framebuffer's edge; pixels past it in a block land in the texture
 * padding).  Finite primitives never cover pixels outside their box. */
static void shade_block(const struct r_state *rs, const struct r_shader *sh,
                        int x, int y, unsigned mask)
{
   for (int j = 0; j < 4; j++) {
      const int py = y + j;
      if (py < 0 || py >= rs->fb->height)
         continue;
      for (int i = 0; i < 4; i++) {
         const int px = x + i;
         if ((mask & (1u << (4 * j + i))) && px >= 0 && px < rs->fb->width)
            sh->pixel(rs, sh->ctx, px, py);
      }
   }
}

/* ---- the rasterizer levels ---------------------------------------------- */

/* Shades the whole w x h area at (x, y) (multiples of 4), block by block. */
static void shade_area(const struct r_state *rs, const struct r_shader *sh,
                       int x, int y, int w, int h)
{
   for (int iy = 0; iy < h; iy += 4)
      for (int ix = 0; ix < w; ix += 4)
         shade_block(rs, sh, x + ix, y + iy, 0xffff);
}

/* do_block_4: per-pixel masks of one 4x4 block. */
static void do_block_4(const struct r_state *rs, const struct r_shader *sh,
                       const struct r_plane *p, int n, int x, int y, const int64_t *c)
{
   unsigned mask = 0xffff;
   for (int j = 0; j < n; j++)
      mask &= ~mask_linear((int32_t)(sub64(c[j], 1) >> 8),
                           neg32(p[j].dcdx) >> 8, p[j].dcdy >> 8);
   if (mask)
      shade_block(rs, sh, x, y, mask);
}

/* One level of lp_rast_tri_tmp.h: the block at (x, y) is split into 4x4
 * sub-blocks of 1 << log2_sub pixels (16 in a 64x64 tile, 4 in a 16x16
 * block); each is rejected, shaded whole, or descended into.  Partial
 * sub-blocks come first, then the full ones, each in bit order. */
static void do_block(const struct r_state *rs, const struct r_shader *sh,
                     const struct r_plane *p, int n, int x, int y, const int64_t *c,
                     int log2_sub)
{
   const int sub = 1 << log2_sub;
   unsigned outmask = 0, partmask = 0;
   for (int j = 0; j < n; j++)
      block_masks(&p[j], c[j], log2_sub, &outmask, &partmask);
   if (outmask == 0xffff)
      return;
   unsigned inmask = ~partmask & 0xffff;
   unsigned partial = partmask & ~outmask;
   while (partial) {
      const int i = __builtin_ctz(partial);
      const int ix = (i & 3) * sub, iy = (i >> 2) * sub;
      int64_t cx[MAX_PLANES];
      partial &= ~(1u << i);
      for (int j = 0; j < n; j++)
         cx[j] = add64(sub64(c[j], imul64(p[j].dcdx, ix)), imul64(p[j].dcdy, iy));
      if (log2_sub == 2)
         do_block_4(rs, sh, p, n, x + ix, y + iy, cx);
      else
         do_block(rs, sh, p, n, x + ix, y + iy, cx, 2);
   }
   while (inmask) {
      const int i = __builtin_ctz(inmask);
      inmask &= ~(1u << i);
      shade_area(rs, sh, x + (i & 3) * sub, y + (i >> 2) * sub, sub, sub);
   }
}

/* lp_rast_triangle_N on the tile at (x, y) with the planes in plane_mask. */
static void rast_tile(const struct r_state *rs, const struct r_shader *sh,
                      const struct r_plane *tri_planes, unsigned plane_mask, int x, int y)
{
   struct r_plane p[MAX_PLANES];
   int64_t c[MAX_PLANES];
   int n = 0;
   while (plane_mask) {
      const int i = __builtin_ctz(plane_mask);
      plane_mask &= ~(1u << i);
      p[n] = tri_planes[i];
      c[n] = sub64(add64(p[n].c, imul64(p[n].dcdy, y)), imul64(p[n].dcdx, x));
      n++;
   }
   do_block(rs, sh, p, n, x, y, c, 4);
}

/* With finite snapped positions and edge steps below 2^22 (always the case
 * after clipping: window coordinates stay within the viewport), none of the
 * 32-bit arithmetic of the binned path wraps, and its tile and block tests
 * are exact, conservative versions of the per-pixel test: the covered
 * pixels are exactly those whose three edge values are positive.  This
 * evaluates that directly over the box cut to the draw region.
 *
 * The block kernels (r_kernel.h) take the same pixels: r_cover_planes
 * reduces each edge C (an integer) to v = floor((C - 1) / 256), and
 * v >= 0 exactly when C - 1 >= 0, i.e. C > 0; the steps of C are
 * multiples of 256, so v at any pixel is v at the origin plus the unscaled
 * steps times the offsets, exactly, and r_cover_planes makes sure all of
 * it fits in 32 bits.  The walk (r_block_tri.h) tests every pixel of the
 * box's blocks that way and keeps those inside the box.
 *
 * Lines and points go to the same kernels:
 *  - a line (r_line.c) in the exact case (finite corners whose
 *    differences stay below 2^22) covers the pixels of its box whose four
 *    parallelogram edge values, built with the conventions above (constant
 *    dcdx * x - dcdy * y, the same fill bias, steps times 256), are all
 *    positive -- r_line.c's reference solves that set row by row; its two
 *    ends are axis-aligned and their tests are the box's bounds (shown in
 *    r_line.c), so r_cover_planes of the two long sides over the box is the
 *    same set; its attribute planes
 *    (line_coef) fill r_tri_setup as a triangle's would, evaluated by the
 *    same fma(dady, y, fma(dadx, x, a0)), and its texture quads are those
 *    planes at the quad's pixels, as r_line.c evaluates them;
 *  - a point (r_point.c) covers its whole square, cut to the draw region
 *    (lp_setup_bin_rectangle): that box is the kernel's box, with no edge
 *    (r_cover_box), and every input is flat, the value the reference
 *    computes once for the whole point.
 * What a kernel cannot do stays with the reference: the pstipple kill of
 * points and lines (stipple_points_lines), lines and triangles that are
 * not exact, and points of one or two pixels (for speed). */
R_FMA_CLONES
static void rasterize_direct(const struct r_state *rs, const struct r_tri_setup *ts,
                             const struct r_plane *p, int32_t x0, int32_t y0,
                             int32_t x1, int32_t y1)
{
   for (int32_t py = y0; py <= y1; py++) {
      int64_t c0 = p[0].c - (int64_t)p[0].dcdx * x0 + (int64_t)p[0].dcdy * py;
      int64_t c1 = p[1].c - (int64_t)p[1].dcdx * x0 + (int64_t)p[1].dcdy * py;
      int64_t c2 = p[2].c - (int64_t)p[2].dcdx * x0 + (int64_t)p[2].dcdy * py;
      for (int32_t px = x0; px <= x1; px++, c0 -= p[0].dcdx, c1 -= p[1].dcdx, c2 -= p[2].dcdx) {
         if (c0 > 0 && c1 > 0 && c2 > 0)
            shade_pixel(rs, ts, px, py);
      }
   }
}

/* rasterize_direct for textured triangles: the same pixels, walked two
 * rows at a time, column by column, so that the four pixels of a 2x2
 * quad come one after the other and share shade_textured's per-quad
 * cache (each pixel is shaded once whatever the order, and the per-fragment
 * operations of one triangle's pixels are independent). */
R_FMA_CLONES
static void rasterize_direct_quads(const struct r_state *rs, const struct r_tri_setup *ts,
                                   const struct r_plane *p, int32_t x0, int32_t y0,
                                   int32_t x1, int32_t y1)
{
   for (int32_t qy = y0 & ~1; qy <= y1; qy += 2) {
      const int32_t ra = qy < y0 ? 1 : 0, rb = qy + 1 > y1 ? 0 : 1;   /* rows used */
      int64_t c[2][3];
      for (int32_t r = ra; r <= rb; r++)
         for (int i = 0; i < 3; i++)
            c[r][i] = p[i].c - (int64_t)p[i].dcdx * x0 + (int64_t)p[i].dcdy * (qy + r);
      for (int32_t px = x0; px <= x1; px++) {
         for (int32_t r = ra; r <= rb; r++) {
            if (c[r][0] > 0 && c[r][1] > 0 && c[r][2] > 0)
               shade_pixel(rs, ts, px, qy + r);
            for (int i = 0; i < 3; i++)
               c[r][i] -= p[i].dcdx;
         }
      }
   }
}

/* The coverage of the block kernels (r_kernel.h r_tri_cover) for the n
 * exact edges p of a triangle or a line (rasterize_direct's conditions)
 * and its box x0..x1, y0..y1 cut to the draw region: each 64-bit edge
 * value C at pixel (x, y) is C(ox, oy) - dcdx * (x - ox) + dcdy * (y - oy)
 * with steps that are multiples of 256 (FIXED_ORDER), so
 * floor((C - 1) / 256), whose sign is that of C - 1 >= 0, i.e. C > 0, is
 * the reduced value at the origin plus the unscaled steps.  False when
 * some reduced value over the box (and the blocks it touches) might not
 * fit in 32 bits. */
bool r_cover_planes(const struct r_plane *p, int n, int32_t x0, int32_t y0, int32_t x1,
                    int32_t y1, struct r_tri_cover *cv)
{
   r_cover_box(x0, y0, x1, y1, cv);
   cv->n = n;
   const int64_t w = (int64_t)x1 - cv->ox + 4, h = (int64_t)y1 - cv->oy + 4;
   for (int e = 0; e < n; e++) {
      const int64_t c = p[e].c - (int64_t)p[e].dcdx * cv->ox + (int64_t)p[e].dcdy * cv->oy;
      const int64_t cr = (c - 1) >> 8;
      const int32_t dx = -(p[e].dcdx >> 8), dy = p[e].dcdy >> 8;
      const int64_t bound = (cr < 0 ? -cr : cr) + (int64_t)(dx < 0 ? -dx : dx) * w +
                            (int64_t)(dy < 0 ? -dy : dy) * h;
      if (bound >= (INT64_C(1) << 30))
         return false;
      cv->c[e] = (int32_t)cr;
      cv->dx[e] = dx;
      cv->dy[e] = dy;
   }
   return true;
}

/* r_cover_planes for the three exact edges p (edge_planes true) of a
 * triangle whose snapped box b (snapped_box: bx0, bx1, by0, by1) spans at
 * most R_COVER_SMALL pixels each way, over a box x0..x1, y0..y1 inside b
 * with x0, y0 >= 0: the same values, without the 64-bit bound test, which
 * such a triangle always passes.  Why: the snapped positions differ by at
 * most 256 (S + 2) (S = R_COVER_SMALL), which bounds the unscaled steps
 * |dx|, |dy|; the origin (ox, oy) lies within S + 4 pixels of each vertex
 * and w, h (r_cover_planes) are at most S + 7, so the bound
 * |cr| + |dx| w + |dy| h is below 1024 (S + 2) (S + 7) + 2 (S + 2) + 2,
 * 273.2M for S = 512, under the 2^30 the test asks.  And the reduced value
 * at the origin is floor((c - 1) / 256) plus the unscaled steps times the
 * origin, exactly (the scaled steps are multiples of 256), which fits in
 * 32 bits, so wrapping 32-bit arithmetic gives it. */
#define R_COVER_SMALL 512
static inline __attribute__((always_inline)) bool tri_cover_small(const int32_t b[4])
{
   return (uint32_t)sub_wrap(b[1], b[0]) <= R_COVER_SMALL &&
          (uint32_t)sub_wrap(b[3], b[2]) <= R_COVER_SMALL;
}

static inline __attribute__((always_inline)) void cover_small(const struct r_plane *p, int32_t x0,
                                                              int32_t y0, int32_t x1, int32_t y1,
                                                              struct r_tri_cover *cv)
{
   const int32_t ox = x0 & ~3, oy = y0 & ~3;
   cv->ox = ox;
   cv->oy = oy;
   cv->n = 3;
#pragma GCC unroll 3
   for (int e = 0; e < 3; e++) {
      const int32_t dx = -(p[e].dcdx >> 8), dy = p[e].dcdy >> 8;
      const uint32_t c0 = (uint32_t)(uint64_t)(sub64(p[e].c, 1) >> 8);
      cv->c[e] = (int32_t)(c0 + (uint32_t)dx * (uint32_t)ox + (uint32_t)dy * (uint32_t)oy);
      cv->dx[e] = dx;
      cv->dy[e] = dy;
   }
   cv->x0 = x0;
   cv->y0 = y0;
   cv->x1 = x1;
   cv->y1 = y1;
}

/* r_cover_planes(p, 3, ...) of such a triangle, b its snapped box and
 * x0..x1, y0..y1 that box clamped to x, y >= 0 and cut to the draw region
 * (rasterize_ccw, r_triangle_binned): through cover_small when the box is
 * small and the cut not empty (then x0 and y0 lie in b). */
static inline __attribute__((always_inline)) bool cover_tri(const struct r_plane *p,
                                                            const int32_t b[4], int32_t x0,
                                                            int32_t y0, int32_t x1, int32_t y1,
                                                            struct r_tri_cover *cv)
{
   if (tri_cover_small(b) && x0 <= x1 && y0 <= y1) {
      cover_small(p, x0, y0, x1, y1, cv);
      return true;
   }
   return r_cover_planes(p, 3, x0, y0, x1, y1, cv);
}

bool r_cover_tri(const struct r_plane *p, const int32_t b[4], int32_t x0, int32_t y0,
                 int32_t x1, int32_t y1, struct r_tri_cover *cv)
{
   return cover_tri(p, b, x0, y0, x1, y1, cv);
}

static void tri_shade_pixel(const struct r_state *rs, const void *ctx, int px, int py);

/* The bounding box in pixels of snapped positions X, Y: x inclusive /
 * exclusive, y adjusted for the bottom-left convention
 * (lp_setup_tri.c do_triangle_ccw); b = x0, x1, y0, y1, inclusive. */
static inline void snapped_box(const int32_t X[3], const int32_t Y[3], int32_t b[4])
{
   b[0] = min3(X[0], X[1], X[2]) >> 8;
   b[1] = sub_wrap(max3(X[0], X[1], X[2]), 1) >> 8;
   b[2] = r_add32(min3(Y[0], Y[1], Y[2]), 1) >> 8;
   b[3] = max3(Y[0], Y[1], Y[2]) >> 8;
}

/* Edge i of a counter-clockwise triangle, from vertex i (Xi, Yi) to vertex
 * i + 1 (Xk, Yk) (lp_setup_tri.c SSE path); true when nothing in it wraps
 * (see rasterize_direct). */
static inline __attribute__((always_inline)) bool edge_plane(int32_t Xi, int32_t Yi, int32_t Xk,
                                                             int32_t Yk, struct r_plane *p)
{
   const int32_t dcdx = sub_wrap(Yi, Yk);
   const int32_t dcdy = sub_wrap(Xi, Xk);
   /* -(1 << 22) < dcdx, dcdy < 1 << 22 */
   const bool exact = Xi != INT32_MIN && Yi != INT32_MIN &&
                      (uint32_t)dcdx + ((1u << 22) - 1u) < (1u << 23) - 1u &&
                      (uint32_t)dcdy + ((1u << 22) - 1u) < (1u << 23) - 1u;
   int64_t c = (int64_t)((uint64_t)imul64(dcdx, Xi) - (uint64_t)imul64(dcdy, Yi));
   /* bottom-left fill convention (window buffers are y-down) */
   if (dcdx < 0 || (dcdx == 0 && dcdy < 0))
      c = add64(c, 1);
   p->c = c;
   p->dcdx = shl32(dcdx, 8);
   p->dcdy = shl32(dcdy, 8);
   /* trivial reject offset, 32 bits: the signs come from the unscaled
    * steps, the values from the scaled ones */
   p->eo = (uint32_t)(dcdy >= 0 ? p->dcdy : 0) - (uint32_t)(dcdx < 0 ? p->dcdx : 0);
   return exact;
}

/* The three edges of a counter-clockwise triangle; true when nothing in
 * them wraps. */
static inline __attribute__((always_inline)) bool edge_planes(const int32_t X[3], const int32_t Y[3],
                                                              struct r_plane p[3])
{
   const bool e0 = edge_plane(X[0], Y[0], X[1], Y[1], &p[0]);
   const bool e1 = edge_plane(X[1], Y[1], X[2], Y[2], &p[1]);
   const bool e2 = edge_plane(X[2], Y[2], X[0], Y[0], &p[2]);
   return e0 & e1 & e2;
}

bool r_tri_snapped_edges(const int32_t X[3], const int32_t Y[3], struct r_plane *p,
                         int32_t b[4])
{
   snapped_box(X, Y, b);
   return edge_planes(X, Y, p);
}

/* Whether the colour input of setup ts is flat (it chooses the kernel). */
static inline bool tri_flat0(const struct r_tri_setup *ts)
{
   /* (flat_attr is set for the inputs only) */
   return (ts->inputs & (1u << R_FS_COLOR0)) && ts->flat_attr[R_FS_COLOR0];
}

/* Draws an exact triangle (edge_planes true) of setup ts, edges p and
 * snapped box b over its box trimmed to the draw region, tx0..tx1,
 * ty0..ty1 (inclusive); t0: the time its setup started, when rs counts. */
static inline void draw_exact(const struct r_state *rs, const struct r_tri_setup *ts, bool flat0,
                              const struct r_plane *p, const int32_t b[4], int32_t tx0,
                              int32_t ty0, int32_t tx1, int32_t ty1, uint64_t t0)
{
   const r_tri_kernel kernel = rs->tri_kernel[flat0];
   struct r_tri_cover cv;
   const bool blocks = kernel && cover_tri(p, b, tx0, ty0, tx1, ty1, &cv);
   const uint64_t t1 = rs->stats ? r_stats_now() : 0;
   if (blocks)
      kernel(rs, ts, &cv);
   else if (rs->fs->tex_units)
      rasterize_direct_quads(rs, ts, p, tx0, ty0, tx1, ty1);
   else
      rasterize_direct(rs, ts, p, tx0, ty0, tx1, ty1);
   if (rs->stats) {
      rs->stats->setup_ns += t1 - t0;
      rs->stats->raster_ns += r_stats_now() - t1;
   }
}

/* Triangle setup and binning of a triangle whose snapped area is positive
 * (lp_setup_tri.c: do_triangle_ccw, lp_setup_bin_triangle).  v[2] is the
 * provoking vertex. */
static void rasterize_ccw(const struct r_state *rs, const struct r_vertex *const v[3],
                          const int32_t X[3], const int32_t Y[3], bool back, bool phong_back)
{
   /* draw region, inclusive: the points' region (px0..py1), which is the
    * draw region cut to the viewport where llvmpipe cuts it (under
    * attenuation, ORACLE-NOTES.md "Point parameters": it cuts every
    * primitive; a triangle the clipper left whole, a vertex at w = 0,
    * shows it) and the draw region elsewhere */
   const int32_t rx0 = rs->px0, ry0 = rs->py0, rx1 = rs->px1 - 1, ry1 = rs->py1 - 1;
   if (rx0 > rx1 || ry0 > ry1)
      return;

   /* bounding box in pixels */
   int32_t b[4];
   snapped_box(X, Y, b);
   int32_t bx0 = b[0], bx1 = b[1], by0 = b[2], by1 = b[3];
   if (bx0 > rx1 || bx1 < rx0 || by0 > ry1 || by1 < ry0)
      return;

   /* (llvmpipe picks 32-bit rasterizers for boxes up to 128 pixels; their
    * coverage is the same, exact, so they need no model here) */
   if (bx0 < 0) bx0 = 0;
   if (by0 < 0) by0 = 0;
   /* trimmed box: the box intersected with the draw region */
   const int32_t tx0 = bx0 > rx0 ? bx0 : rx0, ty0 = by0 > ry0 ? by0 : ry0;
   const int32_t tx1 = bx1 < rx1 ? bx1 : rx1, ty1 = by1 < ry1 ? by1 : ry1;
   r_lazy_touch(rs, tx0, ty0, tx1, ty1);

   const uint64_t t0 = rs->stats ? r_stats_now() : 0;
   struct r_plane p[MAX_PLANES];
   const bool exact = edge_planes(X, Y, p);
   if (exact) {
      struct r_tri_setup ts;
      setup_shade(rs, v, back, phong_back, &ts);
      draw_exact(rs, &ts, tri_flat0(&ts), p, b, tx0, ty0, tx1, ty1, t0);
      return;
   }

   struct r_tri_setup ts;
   setup_shade(rs, v, back, phong_back, &ts);
   const struct r_shader sh = { tri_shade_pixel, &ts };
   const uint64_t t1 = rs->stats ? r_stats_now() : 0;
   const int32_t region[4] = { rs->px0, rs->py0, rs->px1, rs->py1 };
   r_bin_planes(rs, p, 3, bx0, by0, bx1, by1, region, &sh);
   if (rs->stats) {
      rs->stats->setup_ns += t1 - t0;
      rs->stats->raster_ns += r_stats_now() - t1;
   }
}

static void tri_shade_pixel(const struct r_state *rs, const void *ctx, int px, int py)
{
   shade_pixel(rs, ctx, px, py);
}

/* [S: lp_setup_tri.c:lp_setup_bin_triangle] */
void r_bin_planes(const struct r_state *rs, struct r_plane *p, int n,
                  int32_t bx0, int32_t by0, int32_t bx1, int32_t by1,
                  const int32_t region[4], const struct r_shader *sh)
{
   /* draw region, inclusive */
   const int32_t rx0 = region[0], ry0 = region[1], rx1 = region[2] - 1, ry1 = region[3] - 1;
   /* trimmed box: the box intersected with the draw region */
   const int32_t tx0 = bx0 > rx0 ? bx0 : rx0, ty0 = by0 > ry0 ? by0 : ry0;
   const int32_t tx1 = bx1 < rx1 ? bx1 : rx1, ty1 = by1 < ry1 ? by1 : ry1;

   /* planes for the sides of the draw region the box leaves
    * [S: lp_setup_context.h:scissor_planes_needed,
    * lp_setup.c:lp_setup_add_scissor_planes] */
   if (bx0 < rx0)
      p[n++] = (struct r_plane){ .c = -(int64_t)(shl32(rx0 - 1, 8)), .dcdx = shl32(-1, 8),
                                 .dcdy = 0, .eo = 1u << 8 };
   if (bx1 > rx1)
      p[n++] = (struct r_plane){ .c = (int64_t)shl32(rx1, 8) + 127, .dcdx = 1 << 8,
                                 .dcdy = 0, .eo = 0 };
   if (by0 < ry0)
      p[n++] = (struct r_plane){ .c = -(int64_t)(shl32(ry0 - 1, 8)), .dcdx = 0,
                                 .dcdy = 1 << 8, .eo = 1u << 8 };
   if (by1 > ry1)
      p[n++] = (struct r_plane){ .c = (int64_t)shl32(ry1, 8) + 127, .dcdx = 0,
                                 .dcdy = shl32(-1, 8), .eo = 0 };

   /* binning */
   const uint32_t dx = floor_pot((uint32_t)(bx0 ^ bx1) | (uint32_t)(by0 ^ by1));
   if (dx < TILE_SIZE) {
      /* one tile: lp_rast_triangle_3_4/_3_16/_4_16 and the one-tile case
       * all rasterize the tile with every plane */
      rast_tile(rs, sh, p, (1u << n) - 1, bx0 / TILE_SIZE * TILE_SIZE,
                by0 / TILE_SIZE * TILE_SIZE);
      return;
   }
   const int ix0 = tx0 / TILE_SIZE, iy0 = ty0 / TILE_SIZE;
   const int ix1 = tx1 / TILE_SIZE, iy1 = ty1 / TILE_SIZE;
   int64_t c[MAX_PLANES], ei[MAX_PLANES], eo[MAX_PLANES], xstep[MAX_PLANES], ystep[MAX_PLANES];
   for (int i = 0; i < n; i++) {
      c[i] = sub64(add64(p[i].c, imul64(p[i].dcdy, iy0) * TILE_SIZE),
                   imul64(p[i].dcdx, ix0) * TILE_SIZE);
      ei[i] = (int64_t)((uint64_t)((int64_t)sub_wrap(p[i].dcdy, p[i].dcdx) - (int64_t)p[i].eo) << 6);
      eo[i] = (int64_t)p[i].eo * TILE_SIZE;
      xstep[i] = -((int64_t)p[i].dcdx * TILE_SIZE);
      ystep[i] = (int64_t)p[i].dcdy * TILE_SIZE;
   }
   for (int y = iy0; y <= iy1; y++) {
      bool in = false;
      int64_t cx[MAX_PLANES];
      for (int i = 0; i < n; i++)
         cx[i] = c[i];
      for (int x = ix0; x <= ix1; x++) {
         bool out = false;
         unsigned partial = 0;
         for (int i = 0; i < n; i++) {
            out |= add64(cx[i], eo[i]) < 0;
            if (sub64(add64(cx[i], ei[i]), 1) < 0)
               partial |= 1u << i;
         }
         if (out) {
            if (in)
               break;   /* leaving the triangle: done with this row */
         } else if (partial) {
            in = true;
            rast_tile(rs, sh, p, partial, x * TILE_SIZE, y * TILE_SIZE);
         } else {
            in = true;
            /* lp_rast_shade_tile: the whole tile, cut to the framebuffer */
            const int tx = x * TILE_SIZE, ty = y * TILE_SIZE;
            shade_area(rs, sh, tx, ty, rs->fb->width - tx < TILE_SIZE ? rs->fb->width - tx : TILE_SIZE,
                       rs->fb->height - ty < TILE_SIZE ? rs->fb->height - ty : TILE_SIZE);
         }
         for (int i = 0; i < n; i++)
            cx[i] = add64(cx[i], xstep[i]);
      }
      for (int i = 0; i < n; i++)
         c[i] = add64(c[i], ystep[i]);
   }
}

/* The positions snapped to 8 sub-pixel bits and the fixed-point area
 * (twice the signed area, positive for a clockwise triangle in y-down
 * window coordinates). */
static inline int64_t snap_area(const struct r_vertex *const v[3], int32_t X[3], int32_t Y[3])
{
#if defined(__SSE2__)
   /* cvt_rne_i32 of the three x (then y) at once: cvtps2dq rounds to
    * nearest even and gives INT32_MIN for NaN and every value out of
    * range, as cvt_rne_i32 does */
   const __m128 half = _mm_set1_ps(0.5f), scale = _mm_set1_ps(256.0f);
   const __m128 xs = _mm_setr_ps(v[0]->pos[0], v[1]->pos[0], v[2]->pos[0], 0.0f);
   const __m128 ys = _mm_setr_ps(v[0]->pos[1], v[1]->pos[1], v[2]->pos[1], 0.0f);
   int32_t xi[4], yi[4];
   _mm_storeu_si128((__m128i *)xi, _mm_cvtps_epi32(_mm_mul_ps(_mm_sub_ps(xs, half), scale)));
   _mm_storeu_si128((__m128i *)yi, _mm_cvtps_epi32(_mm_mul_ps(_mm_sub_ps(ys, half), scale)));
   for (int i = 0; i < 3; i++) {
      X[i] = xi[i];
      Y[i] = yi[i];
   }
#else
   for (int i = 0; i < 3; i++) {
      X[i] = cvt_rne_i32((v[i]->pos[0] - 0.5f) * 256.0f);
      Y[i] = cvt_rne_i32((v[i]->pos[1] - 0.5f) * 256.0f);
   }
#endif
   const int32_t dx01 = sub_wrap(X[0], X[1]), dy01 = sub_wrap(Y[0], Y[1]);
   const int32_t dx20 = sub_wrap(X[2], X[0]), dy20 = sub_wrap(Y[2], Y[0]);
   return (int64_t)((uint64_t)((int64_t)dx01 * dy20) - (uint64_t)((int64_t)dx20 * dy01));
}

/* lp_setup_tri.c triangle_both/_ccw/_cw: facing from the area sign and
 * culling: whether the triangle of snapped area `area` is discarded. */
static inline bool area_culled(const struct r_state *rs, int64_t area)
{
   if (area == 0)
      return true;
   const bool is_back = (area > 0) != rs->rast->ccw_is_front;
   return is_back ? rs->rast->cull_back : rs->rast->cull_front;
}

/* A triangle of the scene (r_scene.c), set up once when it is binned:
 * what rasterize_ccw computes from the vertices, which depends on the
 * vertices and the state alone, never on the draw region (the tile): the
 * exact edges, the snapped box, and setup_shade's result, of which only
 * the inputs' planes or flat values are kept, in data[]: for each input a
 * of `inputs` in increasing order, 4 floats (flat, bit a of `flat`) or
 * 4 planes of 3 (r_attr_plane).  Each tile's replay (r_triangle_binned)
 * rebuilds the r_tri_setup from it, bit for bit what setup_shade gave. */
struct r_tri_binned {
   struct r_plane p[3];
   int32_t b[4];              /* snapped_box: bx0, bx1, by0, by1 */
   struct r_attr_plane z, w;
   float zoffset;
   uint32_t inputs, flat;
   bool need_w, phong_back, flat0;
   float data[];
};

size_t r_tri_binned_size(const struct r_state *rs)
{
   /* (counted bit by bit: without -mpopcnt __builtin_popcount is a call
    * into libgcc, on every binned triangle) */
   size_t inputs = 0;
   for (unsigned m = rs->fs->fs_inputs; m; m &= m - 1)
      inputs++;
   return offsetof(struct r_tri_binned, data) + inputs * 12 * sizeof(float);
}

void r_tri_binned_pack(const struct r_tri_setup *ts, struct r_tri_binned *t)
{
   t->z = ts->z;
   t->w = ts->w;
   t->zoffset = ts->zoffset;
   t->inputs = ts->inputs;
   t->need_w = ts->need_w;
   t->phong_back = ts->phong_back;
   t->flat0 = tri_flat0(ts);
   t->flat = 0;
   float *d = t->data;
   for (unsigned m = ts->inputs; m; m &= m - 1) {
      const int a = __builtin_ctz(m);
      if (ts->flat_attr[a]) {
         t->flat |= 1u << a;
         memcpy(d, ts->flat[a], 4 * sizeof(float));
         d += 4;
      } else {
         memcpy(d, ts->ap[a], 12 * sizeof(float));
         d += 12;
      }
   }
}

void r_tri_binned_unpack(const struct r_tri_binned *t, struct r_tri_setup *ts)
{
   ts->z = t->z;
   ts->w = t->w;
   ts->zoffset = t->zoffset;
   ts->inputs = t->inputs;
   ts->need_w = t->need_w;
   ts->phong_back = t->phong_back;
   ts->quad_x = INT_MIN;   /* no quad cached */
   ts->quad_y = INT_MIN;
   const float *d = t->data;
   for (unsigned m = t->inputs; m; m &= m - 1) {
      const int a = __builtin_ctz(m);
      const bool flat = (t->flat >> a) & 1u;
      ts->flat_attr[a] = flat;
      if (flat) {
         memcpy(ts->flat[a], d, 4 * sizeof(float));
         d += 4;
      } else {
         memcpy(ts->ap[a], d, 12 * sizeof(float));
         d += 12;
      }
   }
}

int r_triangle_box_setup(const struct r_state *rs, const struct r_vertex *v0,
                         const struct r_vertex *v1, const struct r_vertex *v2, int box[4],
                         struct r_tri_edges *edges, struct r_tri_binned *bin)
{
   const struct r_vertex *v[3] = { v0, v1, v2 };
   int32_t X[3], Y[3];
   const int64_t area = snap_area(v, X, Y);
   if (area_culled(rs, area))
      return 0;
   if (area < 0) {
      /* r_triangle's order */
      const struct r_vertex *t = v[0]; v[0] = v[1]; v[1] = t;
      int32_t ti = X[0]; X[0] = X[1]; X[1] = ti;
      ti = Y[0]; Y[0] = Y[1]; Y[1] = ti;
   }
   struct r_plane p[3];
   if (!edge_planes(X, Y, p))
      return 2;   /* the planes may wrap */
   /* rasterize_ccw's box, cut to the draw region: no pixel outside it is
    * covered */
   int32_t b[4];
   snapped_box(X, Y, b);
   if (!r_scene_box(rs->fb, rs->px0, rs->py0, rs->px1, rs->py1, b[0], b[2], b[1], b[3], box))
      return 0;
   /* the edges only for a box of more than one tile (one tile needs no
    * test) */
   if ((box[0] ^ (box[2] - 1)) / TILE_SIZE != 0 || (box[1] ^ (box[3] - 1)) / TILE_SIZE != 0) {
      for (int i = 0; i < 3; i++) {
         edges->c[i] = p[i].c;
         edges->dcdx[i] = p[i].dcdx;
         edges->dcdy[i] = p[i].dcdy;
         edges->eo[i] = (int64_t)p[i].eo * TILE_SIZE;
      }
      edges->bx1 = b[1];
      edges->by1 = b[3];
   }
   if (bin) {
      /* r_triangle's facing and rasterize_ccw's setup */
      const bool is_back = (area > 0) != rs->rast->ccw_is_front;
      const bool back = rs->rast->twoside && is_back;
      const bool phong_back = rs->fs->phong && rs->shade_env->two_side && is_back;
      memcpy(bin->p, p, sizeof(p));
      memcpy(bin->b, b, sizeof(b));
      struct r_tri_setup ts;
      setup_shade(rs, v, back, phong_back, &ts);
      r_tri_binned_pack(&ts, bin);
   }
   return 1;
}

int r_triangle_box(const struct r_state *rs, const struct r_vertex *v0,
                   const struct r_vertex *v1, const struct r_vertex *v2, int box[4],
                   struct r_tri_edges *edges)
{
   return r_triangle_box_setup(rs, v0, v1, v2, box, edges, NULL);
}

void r_triangle_binned(const struct r_state *rs, const struct r_tri_binned *t)
{
   /* rasterize_ccw from its box on: the same tests, the same trimmed box,
    * the setup it made */
   const int32_t rx0 = rs->px0, ry0 = rs->py0, rx1 = rs->px1 - 1, ry1 = rs->py1 - 1;
   if (rx0 > rx1 || ry0 > ry1)
      return;
   int32_t bx0 = t->b[0], by0 = t->b[2];
   const int32_t bx1 = t->b[1], by1 = t->b[3];
   if (bx0 > rx1 || bx1 < rx0 || by0 > ry1 || by1 < ry0)
      return;
   if (bx0 < 0) bx0 = 0;
   if (by0 < 0) by0 = 0;
   const int32_t tx0 = bx0 > rx0 ? bx0 : rx0, ty0 = by0 > ry0 ? by0 : ry0;
   const int32_t tx1 = bx1 < rx1 ? bx1 : rx1, ty1 = by1 < ry1 ? by1 : ry1;
   r_lazy_touch(rs, tx0, ty0, tx1, ty1);
   const uint64_t t0 = rs->stats ? r_stats_now() : 0;
   struct r_tri_setup ts;
   r_tri_binned_unpack(t, &ts);
   draw_exact(rs, &ts, t->flat0, t->p, t->b, tx0, ty0, tx1, ty1, t0);
}

bool r_tri_edges_miss_tile(const struct r_tri_edges *e, int x, int y)
{
   /* r_bin_planes' trivial reject of the 64x64 tile at (x, y) */
   for (int i = 0; i < 3; i++) {
      const int64_t c = sub64(add64(e->c[i], imul64(e->dcdy[i], y)), imul64(e->dcdx[i], x));
      if (add64(c, e->eo[i]) < 0)
         return true;
   }
   return false;
}

void r_tri_setup_as_given(const struct r_state *rs, const struct r_vertex *v0,
                          const struct r_vertex *v1, const struct r_vertex *v2,
                          struct r_tri_setup *ts)
{
   const struct r_vertex *v[3] = { v0, v1, v2 };
   setup_shade(rs, v, false, false, ts);
}

bool r_tri_edges_cover_tile(const struct r_tri_edges *e, int x, int y)
{
   /* rasterize_ccw's whole-tile test (no plane partial) of the 64x64
    * tile at (x, y) */
   for (int i = 0; i < 3; i++) {
      const int64_t c = sub64(add64(e->c[i], imul64(e->dcdy[i], y)), imul64(e->dcdx[i], x));
      const int64_t ei = (int64_t)((uint64_t)((int64_t)sub_wrap((int32_t)e->dcdy[i],
                                                                 (int32_t)e->dcdx[i]) -
                                              e->eo[i] / TILE_SIZE)
                                   << 6);
      if (sub64(add64(c, ei), 1) < 0)
         return false;
   }
   return true;
}

void r_triangle(const struct r_state *rs, const struct r_vertex *v0,
                const struct r_vertex *v1, const struct r_vertex *v2)
{
   const struct r_vertex *v[3] = { v0, v1, v2 };
   int32_t X[3], Y[3];
   const int64_t area = snap_area(v, X, Y);
   /* facing and culling; the facing also chooses two-sided colours
    * (ORACLE-NOTES.md "Lighting order of operations", its two-sided
    * lighting) */
   if (area_culled(rs, area))
      return;
   const bool is_back = (area > 0) != rs->rast->ccw_is_front;
   const bool back = rs->rast->twoside && is_back;
   /* GL_PHONG_WIN lights a two-sided back face with the back material, by
    * this facing (gl_FrontFacing's [S: lp_setup_tri.c: the area sign]),
    * smooth point and line quads included */
   const bool phong_back = rs->fs->phong && rs->shade_env->two_side && is_back;
   if (area < 0) {
      /* clockwise: processed as (v1, v0, v2), keeping the provoking vertex */
      const struct r_vertex *t = v[0]; v[0] = v[1]; v[1] = t;
      int32_t ti = X[0]; X[0] = X[1]; X[1] = ti;
      ti = Y[0]; Y[0] = Y[1]; Y[1] = ti;
   }
   rasterize_ccw(rs, v, X, Y, back, phong_back);
}

#ifdef FGL_HAVE_BLOCK_KERNELS
/* the block kernel of rs->kernel_isa's build (not R_ISA_NONE) */
static r_tri_kernel choose_block_kernel(const struct r_state *rs, bool flat)
{
#ifdef FGL_HAVE_AVX512_KERNELS
   if (rs->kernel_isa == R_ISA_AVX512)
      return rs->fs->phong ? r_block_choose_tri_phong_avx512(rs, flat)
                           : r_block_choose_tri_avx512(rs, flat);
#endif
   return rs->fs->phong ? r_block_choose_tri_phong(rs, flat) : r_block_choose_tri(rs, flat);
}
#endif

enum r_isa r_kernel_isa(const char *kernels)
{
   enum r_isa isa = R_ISA_NONE;
#ifdef FGL_HAVE_BLOCK_KERNELS
   if (kernels && strcmp(kernels, "reference") == 0)
      return R_ISA_NONE;
   __builtin_cpu_init();
   if (!(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")))
      return R_ISA_NONE;
   isa = R_ISA_AVX2;
#ifdef FGL_HAVE_AVX512_KERNELS
   if (kernels && strcmp(kernels, "avx2") == 0)
      return isa;
   if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
       __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq")) {
      /* XCR0 (the AVX2 check above implies OSXSAVE): SSE, AVX, opmask,
       * ZMM0-15 upper halves and ZMM16-31 state enabled by the OS */
      uint32_t lo, hi;
      __asm__("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
      if ((lo & 0xe6u) == 0xe6u)
         isa = R_ISA_AVX512;
   }
#endif
#else
   (void)kernels;
#endif
   return isa;
}

void r_choose_kernels(struct r_state *rs)
{
   rs->full_ops = rs->dsa->alpha_test || rs->dsa->stencil_test || rs->blend->enable ||
                  rs->blend->logic_op || rs->blend->color_mask != 0xfu;
   rs->tri_kernel[0] = rs->tri_kernel[1] = NULL;
   rs->line_kernel[0] = rs->line_kernel[1] = NULL;
#ifdef FGL_HAVE_BLOCK_KERNELS
   /* a wide target: the reference kernels (r_fragment_ops) only */
   if (rs->kernel_isa == R_ISA_NONE || rs->fb->wide)
      return;
   for (int flat = 0; flat < 2; flat++)
      rs->tri_kernel[flat] = choose_block_kernel(rs, flat);
   /* lines and points: the same choice without the polygon stipple (a
    * kernel reads the state it is called with, never the stipple) */
   if (!rs->rast->stipple) {
      rs->line_kernel[0] = rs->tri_kernel[0];
      rs->line_kernel[1] = rs->tri_kernel[1];
      return;
   }
   struct r_rast_state rast = *rs->rast;
   rast.stipple = false;
   struct r_state ls = *rs;
   ls.rast = &rast;
   for (int flat = 0; flat < 2; flat++)
      rs->line_kernel[flat] = choose_block_kernel(&ls, flat);
#endif
}
