/*
 * llvmpipe's binning and coverage of edge planes (lp_setup_bin_triangle,
 * lp_rast_tri.c, lp_rast_tri_tmp.h), shared by triangles (r_tri.c) and
 * lines (r_line.c).  Internal to the raster core.
 */
#ifndef FGL_R_BIN_H
#define FGL_R_BIN_H

#include "r_state.h"

/* Edge planes: 3 for a triangle, 4 for a line, plus up to 4 of the draw
 * region. */
#define R_MAX_PLANES 8

/* struct lp_rast_plane: a 64-bit constant, 32-bit steps scaled by 256 and
 * the one-pixel trivial reject offset. */
struct r_plane {
   int64_t c;
   int32_t dcdx, dcdy;
   uint32_t eo;
};

/* An attribute's plane equation, a(x, y) = fma(dady, y, fma(dadx, x, a0)),
 * as llvmpipe's interpolation evaluates it at pixel (x, y) for triangles
 * and lines alike (lp_bld_interp.c). */
struct r_attr_plane {
   float a0, dadx, dady;
};

static inline float r_eval_plane(const struct r_attr_plane *p, float x, float y)
{
   return fmaf(p->dady, y, fmaf(p->dadx, x, p->a0));
}

/* llvmpipe's wrapping 32-bit int addition */
static inline int32_t r_add32(int32_t a, int32_t b) { return (int32_t)((uint32_t)a + (uint32_t)b); }

/* Shades pixel (px, py), which is inside the draw region. */
struct r_shader {
   void (*pixel)(const struct r_state *rs, const void *ctx, int px, int py);
   const void *ctx;
};

/* lp_setup_bin_triangle and the rasterizer for the n edge planes p[] (room
 * for R_MAX_PLANES) and the bounding box bx0..bx1, by0..by1 (inclusive,
 * already clamped to >= 0 and known to meet the region): adds the planes
 * of the sides of region (x0, y0, x1, y1 exclusive: the draw region, or
 * r_state's point and line region) the box leaves, then bins 64x64 tiles
 * and descends through 16x16 and 4x4 blocks with llvmpipe's wrapping
 * 32-bit block arithmetic. */
void r_bin_planes(const struct r_state *rs, struct r_plane *p, int n,
                  int32_t bx0, int32_t by0, int32_t bx1, int32_t by1,
                  const int32_t region[4], const struct r_shader *sh);

#endif
