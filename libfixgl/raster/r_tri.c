/*
 * Triangle rasterization, bit-exact with llvmpipe (llvmpipe-facts.md §1, §2).
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
#include "r_state.h"

#include <limits.h>
#include <math.h>
#include <stddef.h>

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

uint8_t r_float_to_unorm8(float c)
{
   /* RNE(min(c, 1) * 255) with a saturating pack: negative and NaN give 0. */
   if (!(c > 0.0f))
      return 0;
   if (c > 1.0f)
      c = 1.0f;
   return (uint8_t)lrintf(c * 255.0f);
}

/* Depth is clamped to [0,1] (NaN becomes 0) before the conversion. */
static inline float clamp_depth(float z)
{
   if (!(z > 0.0f))
      return 0.0f;
   return z < 1.0f ? z : 1.0f;
}

uint32_t r_depth_to_z24(float z)
{
   return (uint32_t)lrintf(clamp_depth(z) * 16777215.0f);
}

uint16_t r_depth_to_z16(float z)
{
   return (uint16_t)lrintf(clamp_depth(z) * 65535.0f);
}

static inline bool depth_compare(enum r_func func, uint32_t frag, uint32_t buf)
{
   switch (func) {
   case R_NEVER:    return false;
   case R_LESS:     return frag < buf;
   case R_EQUAL:    return frag == buf;
   case R_LEQUAL:   return frag <= buf;
   case R_GREATER:  return frag > buf;
   case R_NOTEQUAL: return frag != buf;
   case R_GEQUAL:   return frag >= buf;
   case R_ALWAYS:
   default:         return true;
   }
}

/* Plane equation a(x, y) = fma(dady, y, fma(dadx, x, a0)). */
struct plane {
   float a0, dadx, dady;
};

/* lp_state_setup.c:calc_coef with the triangle's shared factors. */
struct setup_factors {
   float x0c, y0c;
   float dx01o, dy01o, dx20o, dy20o;
};

static inline struct plane make_plane(const struct setup_factors *f,
                                      float a0, float a1, float a2)
{
   struct plane p;
   const float da01 = a0 - a1;
   const float da20 = a2 - a0;
   p.dadx = da01 * f->dy20o - da20 * f->dy01o;
   p.dady = da20 * f->dx01o - da01 * f->dx20o;
   p.a0 = a0 - (p.dadx * f->x0c + p.dady * f->y0c);
   return p;
}

static inline float eval_plane(const struct plane *p, float x, float y)
{
   return fmaf(p->dady, y, fmaf(p->dadx, x, p->a0));
}

/* An edge function in 8.8 fixed point: inside where c - dcdx*X + dcdy*Y > 0. */
struct edge {
   int64_t c, dcdx, dcdy;
};

static struct edge make_edge(int32_t xi, int32_t yi, int32_t xj, int32_t yj)
{
   struct edge e;
   const int32_t dcdx = sub_wrap(yi, yj);
   const int32_t dcdy = sub_wrap(xi, xj);
   e.c = (int64_t)((uint64_t)((int64_t)dcdx * xi) - (uint64_t)((int64_t)dcdy * yi));
   /* bottom-left fill convention (window buffers are y-down) */
   if (dcdx < 0 || (dcdx == 0 && dcdy < 0))
      e.c++;
   /* scaled in 32 bits as lp_setup_tri.c does (_mm_slli_epi32): only
    * garbage (NaN-derived, INT32_MIN) positions are large enough to wrap */
   e.dcdx = (int32_t)((uint32_t)dcdx << 8);
   e.dcdy = (int32_t)((uint32_t)dcdy << 8);
   return e;
}

static inline void write_fragment(const struct r_state *rs, int px, int py,
                                  const struct plane *z, float fx, float fy,
                                  const float color[4])
{
   const size_t idx = (size_t)py * (size_t)rs->width + (size_t)px;

   if (rs->depth_test) {
      const float zf = eval_plane(z, fx, fy);
      switch (rs->zs_format) {
      case R_ZS_Z16: {
         uint16_t *zb = (uint16_t *)rs->zs + idx;
         const uint16_t zv = r_depth_to_z16(zf);
         if (!depth_compare(rs->depth_func, zv, *zb))
            return;
         if (rs->depth_write)
            *zb = zv;
         break;
      }
      case R_ZS_Z24X8:
      case R_ZS_Z24S8: {
         uint32_t *zb = (uint32_t *)rs->zs + idx;
         const uint32_t zv = r_depth_to_z24(zf);
         if (!depth_compare(rs->depth_func, zv, *zb & 0xffffffu))
            return;
         if (rs->depth_write)
            *zb = (*zb & 0xff000000u) | zv;
         break;
      }
      default:
         break; /* no depth buffer: the test always passes */
      }
   }

   uint8_t *dst = rs->color + 4 * idx;
   dst[0] = r_float_to_unorm8(color[0]);
   dst[1] = r_float_to_unorm8(color[1]);
   dst[2] = r_float_to_unorm8(color[2]);
   dst[3] = r_float_to_unorm8(color[3]);
}

/* Rasterize a triangle whose snapped area is positive (lp_setup_tri.c:
 * do_triangle_ccw).  v[2] is the provoking vertex. */
static void rasterize_ccw(const struct r_state *rs, const struct r_vertex *const v[3],
                          const int32_t X[3], const int32_t Y[3])
{
   /* Bounding box in pixels: x inclusive/exclusive, y adjusted for the
    * bottom-left convention, then trimmed to the draw region. */
   int64_t bx0 = (int64_t)min3(X[0], X[1], X[2]) >> 8;
   int64_t bx1 = ((int64_t)max3(X[0], X[1], X[2]) - 1) >> 8;
   int64_t by0 = ((int64_t)min3(Y[0], Y[1], Y[2]) + 1) >> 8;
   int64_t by1 = (int64_t)max3(Y[0], Y[1], Y[2]) >> 8;
   if (bx0 < rs->x0) bx0 = rs->x0;
   if (by0 < rs->y0) by0 = rs->y0;
   if (bx1 > rs->x1 - 1) bx1 = rs->x1 - 1;
   if (by1 > rs->y1 - 1) by1 = rs->y1 - 1;
   if (bx0 > bx1 || by0 > by1)
      return;

   const struct edge e[3] = {
      make_edge(X[0], Y[0], X[1], Y[1]),
      make_edge(X[1], Y[1], X[2], Y[2]),
      make_edge(X[2], Y[2], X[0], Y[0]),
   };

   /* Interpolation setup, plain float arithmetic in llvmpipe's order. */
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

   const struct plane zp = make_plane(&f, v[0]->pos[2], v[1]->pos[2], v[2]->pos[2]);
   const struct plane wp = make_plane(&f, v[0]->pos[3], v[1]->pos[3], v[2]->pos[3]);

   /* Perspective-correct attributes are interpolated premultiplied by 1/w
    * (lp_state_setup.c:apply_perspective_corr); flat ones come from the
    * provoking vertex. */
   struct plane ap[R_MAX_ATTRIBS][4];
   float flat[R_MAX_ATTRIBS][4];
   for (int a = 0; a < rs->num_attribs; a++) {
      for (int c = 0; c < 4; c++) {
         if (rs->flat_mask & (1u << a)) {
            flat[a][c] = v[2]->attr[a][c];
         } else {
            ap[a][c] = make_plane(&f, v[0]->attr[a][c] * v[0]->pos[3],
                                      v[1]->attr[a][c] * v[1]->pos[3],
                                      v[2]->attr[a][c] * v[2]->pos[3]);
         }
      }
   }

   const bool color_flat = (rs->flat_mask & 1u) != 0;
   for (int64_t py = by0; py <= by1; py++) {
      int64_t c0 = (int64_t)((uint64_t)e[0].c - (uint64_t)e[0].dcdx * (uint64_t)bx0 + (uint64_t)e[0].dcdy * (uint64_t)py);
      int64_t c1 = (int64_t)((uint64_t)e[1].c - (uint64_t)e[1].dcdx * (uint64_t)bx0 + (uint64_t)e[1].dcdy * (uint64_t)py);
      int64_t c2 = (int64_t)((uint64_t)e[2].c - (uint64_t)e[2].dcdx * (uint64_t)bx0 + (uint64_t)e[2].dcdy * (uint64_t)py);
      const float fy = (float)py;
      /* wrapping steps: garbage (NaN-derived) edges must not be UB */
      for (int64_t px = bx0; px <= bx1; px++,
           c0 = (int64_t)((uint64_t)c0 - (uint64_t)e[0].dcdx),
           c1 = (int64_t)((uint64_t)c1 - (uint64_t)e[1].dcdx),
           c2 = (int64_t)((uint64_t)c2 - (uint64_t)e[2].dcdx)) {
         if (c0 <= 0 || c1 <= 0 || c2 <= 0)
            continue;
         const float fx = (float)px;
         float color[4];
         if (color_flat) {
            for (int c = 0; c < 4; c++)
               color[c] = flat[0][c];
         } else {
            const float rw = 1.0f / eval_plane(&wp, fx, fy);
            for (int c = 0; c < 4; c++)
               color[c] = eval_plane(&ap[0][c], fx, fy) * rw;
         }
         write_fragment(rs, (int)px, (int)py, &zp, fx, fy, color);
      }
   }
}

void r_triangle(const struct r_state *rs, const struct r_vertex *v0,
                const struct r_vertex *v1, const struct r_vertex *v2)
{
   const struct r_vertex *v[3] = { v0, v1, v2 };
   int32_t X[3], Y[3];
   for (int i = 0; i < 3; i++) {
      X[i] = cvt_rne_i32((v[i]->pos[0] - 0.5f) * 256.0f);
      Y[i] = cvt_rne_i32((v[i]->pos[1] - 0.5f) * 256.0f);
   }

   const int32_t dx01 = sub_wrap(X[0], X[1]), dy01 = sub_wrap(Y[0], Y[1]);
   const int32_t dx20 = sub_wrap(X[2], X[0]), dy20 = sub_wrap(Y[2], Y[0]);
   const int64_t area = (int64_t)((uint64_t)((int64_t)dx01 * dy20) -
                                  (uint64_t)((int64_t)dx20 * dy01));
   if (area == 0)
      return;
   if (area < 0) {
      /* clockwise: processed as (v1, v0, v2), keeping the provoking vertex */
      const struct r_vertex *t = v[0]; v[0] = v[1]; v[1] = t;
      int32_t ti = X[0]; X[0] = X[1]; X[1] = ti;
      ti = Y[0]; Y[0] = Y[1]; Y[1] = ti;
   }
   rasterize_ccw(rs, v, X, Y);
}
