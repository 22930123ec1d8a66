/*
 * The block coverage of a triangle (r_kernel.h r_tri_cover) as r_tri.c
 * draw_exact gives it to the block kernels, for the unit tests
 * (unit/raster compares it with r_cover_planes).  Internal to the raster
 * core.
 */
#ifndef FGL_R_TRI_COVER_H
#define FGL_R_TRI_COVER_H

#include "r_kernel.h"

/* r_cover_planes(p, 3, x0, y0, x1, y1, cv) for the three exact edges p of
 * a counter-clockwise triangle of snapped box b (r_tri.c snapped_box: x0,
 * x1, y0, y1, inclusive), x0..x1, y0..y1 being that box clamped to
 * x, y >= 0 and cut to a draw region: a box of at most 512 pixels each way
 * skips the 64-bit bound test, which it always passes (r_tri.c
 * cover_small). */
bool r_cover_tri(const struct r_plane *p, const int32_t b[4], int32_t x0, int32_t y0,
                 int32_t x1, int32_t y1, struct r_tri_cover *cv);

/* The snapped box b and the edges p of the counter-clockwise triangle of
 * snapped positions X, Y (r_tri.c snapped_box, edge_planes); true when
 * the edges are exact (nothing wraps). */
bool r_tri_snapped_edges(const int32_t X[3], const int32_t Y[3], struct r_plane *p,
                         int32_t b[4]);

#endif
