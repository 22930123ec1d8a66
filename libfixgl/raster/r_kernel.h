/*
 * Raster kernels: the code that shades a primitive's pixels, chosen once
 * per state at validation (r_choose_kernels), never per pixel.
 *
 * Two kernel sets exist:
 *  - the reference kernels (r_tri.c rasterize_direct and shade_pixel,
 *    r_frag.c): portable scalar code, one pixel at a time, which handles
 *    every state and is the specification of the others;
 *  - the block kernels (r_block_avx2.c untextured, r_block_tex_avx2.c
 *    with one texture unit, r_block_mtex_avx2.c with two to four,
 *    r_block_phong_avx2.c per-fragment lit; the
 *    walk r_block_tri.h and the shared operations r_block_avx2.h; AVX2 +
 *    FMA): a triangle's, a line's or a point's 4x4 blocks (r_tri.c,
 *    r_line.c, r_point.c; the proof that they cover the same pixels is
 *    above r_tri.c rasterize_direct), each shaded as two 4x2 halves of 8
 *    lanes (lane i is pixel
 *    (x + (i & 3), y + (i >> 2)), llvmpipe's 8-wide vector), specialised
 *    at compile time for the states real programs spend their time in.
 *    Every lane performs the reference's float operations in the
 *    reference's order (fmaf where it fuses, true divides, RNE
 *    conversions), so they produce the same bytes; the kernel-equivalence
 *    tests check this on random states against a context with
 *    FIXGL_KERNELS=reference (tests/unit/test_kernels.c over the whole
 *    state space, tests/api/lit_kernels.c for lit scenes,
 *    tests/api/tex_kernels.c for textured triangles, one to four units).
 * A state no block kernel covers draws with the reference kernels.
 * FIXGL_KERNELS=reference in the environment forces the reference kernels
 * for every context created afterwards (and the scalar per-vertex
 * Cook-Torrance lighting, tnl/t_light.c, instead of its eight-lane form).
 */
#ifndef FGL_R_KERNEL_H
#define FGL_R_KERNEL_H

#include "r_bin.h"

/* The interpolation setup of one triangle (the oracle's jit setup
 * function's job; r_tri.c setup_shade), read by the kernels. */
struct r_tri_setup {
   struct r_attr_plane z, w;
   float zoffset;           /* polygon offset, added to every fragment's z */
   /* Perspective-correct attributes are interpolated premultiplied by 1/w
    * (lp_state_setup.c:apply_perspective_corr); flat ones come from the
    * provoking vertex. */
   struct r_attr_plane ap[R_FS_NUM_INPUTS][4];
   float flat[R_FS_NUM_INPUTS][4];
   bool flat_attr[R_FS_NUM_INPUTS];
   bool need_w;             /* some input is interpolated */
   unsigned inputs;         /* R_FS_* inputs the fragment shader reads */
   /* the reference's per-quad texture cache (r_tri.c fill_quad): the
    * texture coordinates of the quad at (quad_x, quad_y), which the pixels
    * of a quad's row share, and the fast LOD of the quad for the units
    * without `soa` */
   int quad_x, quad_y;
   struct r_fs_quad quad;
   struct r_tex_lod lod[R_MAX_TEX_UNITS];
   /* GL_PHONG_WIN: the face the fragments are lit with */
   bool phong_back;
};

/* Coverage of a primitive for the block kernels: up to three edge
 * functions (n of them: 3 for a triangle, the two long sides of a line's
 * parallelogram, whose ends are sides of its box (r_line.c), none for a
 * point, whose square is its box), each the
 * primitive's exact 64-bit edge function reduced by FIXED_ORDER (as
 * lp_rast_tri_tmp.h's 4x4 level reduces them), relative to the origin
 * (ox, oy), a multiple of 4:
 *    v_e(x, y) = c[e] + (x - ox) * dx[e] + (y - oy) * dy[e]
 * is floor((C_e(x, y) - 1) / 256) for the exact 64-bit edge value C_e, so
 * pixel (x, y) of the box is covered exactly when every v_e >= 0.  The
 * edges past n are (0, 0, 0), always inside, so that the walk tests three
 * (r_block_cover).  r_cover_planes builds it only when every v_e over the
 * box fits in 32 bits. */
#define R_COVER_EDGES 3
struct r_tri_cover {
   int32_t ox, oy;
   int n;                   /* edges of the primitive, 0..R_COVER_EDGES */
   int32_t c[R_COVER_EDGES], dx[R_COVER_EDGES], dy[R_COVER_EDGES];
   int32_t x0, y0, x1, y1;  /* the box cut to the draw region, inclusive */
};

/* The block coverage of the n (<= R_COVER_EDGES) exact edge planes p
 * (r_bin.h: C(x, y) = c - dcdx * x + dcdy * y, steps multiples of 256;
 * r_tri.c rasterize_direct's conditions) over the box x0..x1, y0..y1
 * already cut to the draw region (r_tri.c); false when some reduced value
 * over the box might not fit in 32 bits. */
bool r_cover_planes(const struct r_plane *p, int n, int32_t x0, int32_t y0, int32_t x1,
                    int32_t y1, struct r_tri_cover *cv);

/* The coverage of a box, every pixel of it (a point's square): no edge. */
static inline void r_cover_box(int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                               struct r_tri_cover *cv)
{
   cv->ox = x0 & ~3;
   cv->oy = y0 & ~3;
   cv->n = 0;
   for (int e = 0; e < R_COVER_EDGES; e++)
      cv->c[e] = cv->dx[e] = cv->dy[e] = 0;
   cv->x0 = x0;
   cv->y0 = y0;
   cv->x1 = x1;
   cv->y1 = y1;
}

/* Shades pixel (px, py) of the draw region with the planes of the
 * r_tri_setup ctx (flat inputs or planes times 1/w, the texture quads from
 * the planes, the pstipple kill when rs->stipple_points_lines): the
 * reference kernel of lines and point sprites (r_line.c; an r_shader's
 * pixel function). */
void r_setup_shade_pixel(const struct r_state *rs, const void *ctx, int px, int py);

/* The block kernel for the state rs and a triangle whose colour is flat
 * or interpolated, or NULL when no block kernel covers the state
 * (r_block_avx2.c; built where the compiler targets x86-64 AVX2:
 * FGL_HAVE_BLOCK_KERNELS, and called only on a CPU that runs AVX2 and
 * FMA). */
r_tri_kernel r_block_choose_tri(const struct r_state *rs, bool flat_color);

/* The same for per-fragment-lit triangles (rs->fs->phong; r_block_phong_avx2.c):
 * NULL for a state it does not cover. */
r_tri_kernel r_block_choose_tri_phong(const struct r_state *rs, bool flat_color);

/* The same for the textured states (r_block_tex_avx2.c), which
 * r_block_choose_tri asks first when a texture unit is on. */
r_tri_kernel r_block_choose_tri_tex(const struct r_state *rs, bool flat_color);

/* The same for two texture units or more (r_block_mtex_avx2.c), which
 * r_block_choose_tri_tex asks when units past the first are walked. */
r_tri_kernel r_block_choose_tri_mtex(const struct r_state *rs, bool flat_color);

/* The same four built again with AVX-512 VL/BW/DQ enabled as well
 * (libfixgl/meson.build: FGL_HAVE_AVX512_KERNELS): the same sources and
 * intrinsics on 256-bit vectors, so the same bytes; called only where
 * r_kernel_isa says R_ISA_AVX512. */
r_tri_kernel r_block_choose_tri_avx512(const struct r_state *rs, bool flat_color);
r_tri_kernel r_block_choose_tri_phong_avx512(const struct r_state *rs, bool flat_color);
r_tri_kernel r_block_choose_tri_tex_avx512(const struct r_state *rs, bool flat_color);
r_tri_kernel r_block_choose_tri_mtex_avx512(const struct r_state *rs, bool flat_color);

/* The fast kernels a context uses (r_state.kernel_isa), from the CPU, the
 * OS (XCR0's AVX, opmask and ZMM state bits) and FIXGL_KERNELS (kernels:
 * its value or NULL): "reference" the reference kernels, "avx2" the AVX2
 * build even on an AVX-512 CPU, otherwise the best this CPU runs. */
enum r_isa { R_ISA_NONE, R_ISA_AVX2, R_ISA_AVX512 };
enum r_isa r_kernel_isa(const char *kernels);

#endif
