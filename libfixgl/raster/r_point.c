/*
 * Non-antialiased points, bit-exact with llvmpipe's legacy (non-sprite)
 * point rasterization (ORACLE-NOTES.md "Line and point rasterization";
 * [S: llvmpipe/lp_setup_point.c:try_setup_point, legacy_points path]):
 *  - the window position is snapped with util_iround(x*256), y with one
 *    subtracted (bottom_edge_rule);
 *  - the size becomes a whole number of pixels, n = max(1, ((iround(size*256)
 *    + 127) & ~255) >> 8), so .5 rounds down;
 *  - the point is the n x n square starting at (x0>>8, y0>>8) - (n-1)/2 for
 *    odd n, ((x0+128)>>8, (y0+128)>>8) - n/2 for even n, cut to the draw
 *    region, and to the viewport under attenuation (r_state.px0..py1;
 *    lp_setup_bin_rectangle shades the whole box);
 *  - depth and every input come from the vertex: constant coefficients, or,
 *    for perspective-interpolated inputs, the vertex value premultiplied by
 *    its 1/w and divided by the (constant) interpolated 1/w again in the
 *    fragment shader ([S: lp_setup_point.c:point_persp_coeff]).
 * A point of three pixels or more is shaded by the state's block kernel
 * (r_state.line_kernel, r_kernel.h) unless the pstipple shader is bound;
 * else, and for the reference kernels, pixel by pixel here.
 *
 * Point sprites (r_rast_state.point_sprite, chosen at validation from
 * GL_POINT_SPRITE: the rasterizer object's point_quad_rasterization) are
 * llvmpipe's other point ([S: lp_setup_point.c:try_setup_point, the
 * !legacy_points path, texcoord_coef]; ORACLE-NOTES.md "Point sprites"):
 * a square of fw = max(256, iround(size*256)) sub-pixel units whose
 * corner is iround((x - 0.5)*256) - fw/2, y alike, with the triangles'
 * fill rule (left and bottom edges in), so exactly the pixels whose
 * centres lie in [x0, x0 + fw) x (y0, y0 + fw]; the replaced texture
 * coordinates are planes over it (sprite_planes), the other inputs the
 * vertex's as for legacy points.  Shaded by the same block kernel (the
 * square is its box; the planes are the kernel's interpolated inputs)
 * or, for the reference kernels and under the pstipple shader, by
 * r_setup_shade_pixel.
 */
#include "r_kernel.h"
#include "r_scene.h"

#include <limits.h>
#include <math.h>
#include <string.h>

static void point(const struct r_state *rs, const struct r_vertex *v);
static void sprite(const struct r_state *rs, const struct r_vertex *v);

/* under fixglStats a point is raster time (setup included) */
void r_point(const struct r_state *rs, const struct r_vertex *v)
{
   /* the rasterizer object says which point (once per point) */
   void (*const fn)(const struct r_state *, const struct r_vertex *) =
      rs->rast->point_sprite ? sprite : point;
   if (__builtin_expect(rs->stats != NULL, 0)) {
      const uint64_t t0 = r_stats_now();
      fn(rs, v);
      rs->stats->raster_ns += r_stats_now() - t0;
      return;
   }
   fn(rs, v);
}

/* setup_point_coefficients for both points: depth and 1/w constant, every
 * input the vertex's (constant, or premultiplied by the vertex 1/w and
 * divided by it again: point_persp_coeff), a flat input of the kernels;
 * a sprite then replaces the planes of its replaced coordinates. */
/* what a point's setup holds besides its inputs' values */
static void point_setup_head(struct r_tri_setup *ts, float z, float w, unsigned inputs,
                             bool phong_back)
{
   ts->z = (struct r_attr_plane){ z, 0.0f, 0.0f };
   ts->w = (struct r_attr_plane){ w, 0.0f, 0.0f };
   ts->zoffset = 0.0f;
   ts->need_w = false;
   ts->inputs = inputs;
   ts->quad_x = ts->quad_y = INT_MIN;   /* (r_tri.c's quad cache: not read here) */
   ts->phong_back = phong_back;
}

static void point_setup(const struct r_state *rs, const struct r_vertex *v,
                        struct r_tri_setup *ts)
{
   const float w = v->pos[3];
   /* GL_PHONG_WIN: a point is front facing, unless it is a vertex of an
    * unfilled back face, whose face the vertex carries (draw's
    * inject_front_face_info [S: draw_pipe_unfilled.c], read by
    * lp_setup_point.c) */
   point_setup_head(ts, v->pos[2], w, rs->fs->fs_inputs,
                    rs->fs->phong && rs->shade_env->two_side &&
                       v->attr[R_ATTR_NORMAL][3] == 0.0f);
   for (unsigned m = ts->inputs; m; m &= m - 1) {
      const int a = __builtin_ctz(m);
      const int slot = r_fs_slot(a, false);
      const bool flat = (rs->flat_mask & (1u << slot)) != 0;
      ts->flat_attr[a] = true;
      for (int c = 0; c < 4; c++)
         ts->flat[a][c] = flat ? v->attr[slot][c] : (v->attr[slot][c] * w) * (1.0f / w);
   }
}

/* [S: lp_setup_point.c:texcoord_coef] the planes (a0, dadx, dady) of a
 * replaced texture coordinate, channel c, for the sprite of sub-pixel
 * width fw centred at the window position (x, y), premultiplied by the
 * vertex 1/w (the input is perspective): s = 0.5 + (x_pixel - (x - 0.5))
 * * 256/fw, t the same down the buffer (ARB_point_sprite's upper-left
 * origin; GL 2.0's lower-left one is no GL 1.5 state), r = 0, q = 1.  The
 * setup's C: float products and sum, the subtraction from 0.5 in double
 * (the literal), rounded to float. */
static struct r_attr_plane sprite_plane(int c, float x, float y, float w, int32_t fw)
{
   const float xo = x - 0.5f, yo = y - 0.5f;   /* minus pixel_offset */
   float dadx = 0.0f, dady = 0.0f, a0;
   switch (c) {
   case 0:
      dadx = 256.0f / (float)fw;
      a0 = (float)(0.5 - (double)(dadx * xo + dady * yo));
      break;
   case 1:
      dady = 256.0f / (float)fw;
      a0 = (float)(0.5 - (double)(dadx * xo + dady * yo));
      break;
   case 2:
      return (struct r_attr_plane){ 0.0f, 0.0f, 0.0f };
   default:
      return (struct r_attr_plane){ w, 0.0f, 0.0f };
   }
   return (struct r_attr_plane){ a0 * w, dadx * w, dady * w };
}

static void sprite(const struct r_state *rs, const struct r_vertex *v)
{
   /* LP_MAX_POINT_WIDTH */
   float size = r_point_size(rs->rast, v->attr[R_ATTR_PSIZE]);
   if (size > 255.0f)
      size = 255.0f;
   if (!isfinite(v->pos[0]) || !isfinite(v->pos[1]))
      return;   /* cannot pass the clip test (NaN positions: outside) */

   /* the square in sub-pixel units (a NaN size snaps to INT32_MIN: 256);
    * positions inside the clip volume keep these far from overflowing */
   int32_t fw = r_subpixel_snap(size);
   if (fw < 256)
      fw = 256;
   const int64_t x0 = (int64_t)r_subpixel_snap(v->pos[0] - 0.5f) - fw / 2;
   const int64_t y0 = (int64_t)r_subpixel_snap(v->pos[1] - 0.5f) - fw / 2;
   const int64_t x1 = x0 + fw, y1 = y0 + fw;
   /* The four planes of try_setup_point, C(px, py) > 0 with the left
    * plane's c incremented and the bottom one's (bottom_edge_rule):
    * 256 px >= x0, 256 px < x1, 256 py > y0, 256 py <= y1; the bounding
    * box and the draw region cut it further only where it is empty. */
   int64_t bx0 = (x0 + 255) >> 8, bx1 = ((x1 + 255) >> 8) - 1;
   int64_t by0 = (y0 >> 8) + 1, by1 = y1 >> 8;
   const int64_t own_by1 = by1;
   if (bx0 < rs->px0) bx0 = rs->px0;
   if (by0 < rs->py0) by0 = rs->py0;
   if (bx1 > rs->px1 - 1) bx1 = rs->px1 - 1;
   if (by1 > rs->py1 - 1) by1 = rs->py1 - 1;
   if (bx0 > bx1 || by0 > by1)
      return;
   /* The bottom plane's constant is the box's bottom + 1 row, plus the
    * fill rule's increment: a square the region cuts at its bottom also
    * covers the row below the region, shaded where the rasterizer walks,
    * in the bottom row of tiles binned and inside the framebuffer
    * (ORACLE-NOTES.md "Point sprites"; probe p_point_viewport) */
   if (own_by1 > by1 && by1 + 1 < rs->fb->height && (by1 + 1) % 64 != 0)
      by1++;

   /* setup_point_coefficients, with the planes of the replaced
    * coordinates (a constant-interpolated input never takes them) */
   struct r_tri_setup ts;
   point_setup(rs, v, &ts);
   for (int u = 0; u < R_MAX_TEX_UNITS; u++) {
      const int a = R_FS_TEX0 + u;
      if (!(ts.inputs & (1u << a)) || !((rs->rast->sprite_coord_enable >> u) & 1u) ||
          (rs->flat_mask & (1u << r_fs_slot(a, false))))
         continue;
      ts.flat_attr[a] = false;
      ts.need_w = true;
      for (int c = 0; c < 4; c++)
         ts.ap[a][c] = sprite_plane(c, v->pos[0], v->pos[1], v->pos[3], fw);
   }

   /* the square is the box: the block kernel of the state (a flat colour,
    * as every input but the planes), unless the pstipple shader kills */
   const r_tri_kernel kernel = rs->stipple_points_lines
                                  ? NULL
                                  : rs->line_kernel[(rs->fs->fs_inputs >> R_FS_COLOR0) & 1u];
   if (kernel) {
      struct r_tri_cover cv;
      r_cover_box((int32_t)bx0, (int32_t)by0, (int32_t)bx1, (int32_t)by1, &cv);
      kernel(rs, &ts, &cv);
      return;
   }
   for (int32_t py = (int32_t)by0; py <= (int32_t)by1; py++)
      for (int32_t px = (int32_t)bx0; px <= (int32_t)bx1; px++)
         r_setup_shade_pixel(rs, &ts, px, py);
}

/* The square of a legacy point before the cut to the draw region
 * (b = bx0, by0, bx1, by1, inclusive); false when its position is not
 * finite (it cannot pass the clip test: no pixel). */
static bool point_square(const struct r_state *rs, const struct r_vertex *v, int32_t b[4])
{
   /* LP_MAX_POINT_WIDTH */
   float size = r_point_size(rs->rast, v->attr[R_ATTR_PSIZE]);
   if (size > 255.0f)
      size = 255.0f;
   if (!isfinite(v->pos[0]) || !isfinite(v->pos[1]))
      return false;   /* cannot pass the clip test (NaN positions: outside) */

   const int adj = 1;   /* bottom_edge_rule of the y-down window buffer */
   const int32_t x0 = r_subpixel_snap(v->pos[0]);
   /* lp_setup_point.c: C int arithmetic that wraps on the oracle's
    * build; a position beyond the int range snaps to INT_MIN */
   const int32_t y0 = (int32_t)((uint32_t)r_subpixel_snap(v->pos[1]) - (uint32_t)adj);
   int32_t fixed_width = (r_subpixel_snap(size) + 256 / 2 - 1) & ~(256 - 1);
   if (fixed_width < 256)
      fixed_width = 256;
   const int32_t n = fixed_width >> 8;

   int32_t bx0, by0;
   if (n == 1) {
      bx0 = x0 >> 8;
      by0 = y0 >> 8;
   } else if (n & 1) {
      bx0 = (x0 >> 8) - (n - 1) / 2;
      by0 = (y0 >> 8) - (n - 1) / 2;
   } else {
      bx0 = ((x0 + 256 / 2) >> 8) - n / 2;
      by0 = ((y0 + 256 / 2) >> 8) - n / 2;
   }
   b[0] = bx0;
   b[1] = by0;
   b[2] = bx0 + n - 1;
   b[3] = by0 + n - 1;
   return true;
}

/* u_rect_find_intersection of square b with the draw region (the point
 * region) into c; false when empty */
static inline bool point_cut(const struct r_state *rs, const int32_t b[4], int32_t c[4])
{
   c[0] = b[0] < rs->px0 ? rs->px0 : b[0];
   c[1] = b[1] < rs->py0 ? rs->py0 : b[1];
   c[2] = b[2] > rs->px1 - 1 ? rs->px1 - 1 : b[2];
   c[3] = b[3] > rs->py1 - 1 ? rs->py1 - 1 : b[3];
   return c[0] <= c[2] && c[1] <= c[3];
}

/* The pixels c (the square b cut to the draw region) of the point of
 * setup ts */
static void point_draw(const struct r_state *rs, struct r_tri_setup *ts, const int32_t b[4],
                       const int32_t c[4])
{
   const int32_t n = b[2] - b[0] + 1;
   const int32_t bx0 = c[0], by0 = c[1], bx1 = c[2], by1 = c[3];
   /* A point of three pixels or more goes to the block kernel of the state
    * (unless the pstipple shader is bound: it kills per pixel) as a
    * triangle whose inputs are all flat, each the value ts.flat holds, and
    * whose coverage is its box (r_cover_box): the kernel shades every
    * pixel of the square with the same inputs, so with the same colour
    * (texture coordinates equal at every pixel of a quad give zero
    * derivatives, as `quad` below, so the same level of detail; lighting
    * the same inputs gives the same colour in every lane), and its depth
    * fma(0, y, fma(0, x, z)) + 0 is z but for the sign of a zero, which
    * the depth conversion does not see.  (Points of one or two pixels stay
    * here: for them the kernel's setup costs as much as it saves.) */
   const r_tri_kernel kernel = n < 3 || rs->stipple_points_lines
                                  ? NULL
                                  : rs->line_kernel[(rs->fs->fs_inputs >> R_FS_COLOR0) & 1u];
   if (kernel) {
      struct r_tri_cover cv;
      r_cover_box(bx0, by0, bx1, by1, &cv);
      kernel(rs, ts, &cv);
      return;
   }

   /* GL_PHONG_WIN: lit once, as every pixel's inputs are the vertex's
    * (point_setup: the face) */
   float (*const in)[4] = ts->flat;
   if (rs->fs->phong)
      r_fragment_phong(rs, in, ts->phong_back);
   /* the quad's texture coordinates are the vertex's too: zero
    * derivatives, so the texture is magnified */
   struct r_fs_quad quad;
   for (int u = 0; u < R_MAX_TEX_UNITS; u++) {
      if (!(rs->fs->tex_units & (1u << u)))
         continue;
      for (int i = 0; i < 3; i++)
         for (int c = 0; c < 4; c++)
            quad.tex[u][i][c] = quad.pair[u][i][c] = in[R_FS_TEX0 + u][c];
      for (int c = 0; c < 4; c++)
         quad.br[u][c] = quad.pair_br[u][c] = in[R_FS_TEX0 + u][c];
   }
   quad.pos = 0;
   float color[4];
   r_fragment_shader(rs, (const float (*)[4])in, rs->fs->tex_units ? &quad : NULL, color);
   for (int32_t py = by0; py <= by1; py++) {
      for (int32_t px = bx0; px <= bx1; px++) {
         if (rs->stipple_points_lines && !r_stipple_pass(rs, px, py))
            continue;   /* the pstipple shader's kill (t_vbuf_flush) */
         if (__builtin_expect(rs->stats != NULL, 0))
            rs->stats->fragments++;
         r_fragment_ops(rs, px, py, ts->z.a0, color);   /* the vertex z */
      }
   }
}

static void point(const struct r_state *rs, const struct r_vertex *v)
{
   int32_t b[4], c[4];
   if (!point_square(rs, v, b) || !point_cut(rs, b, c))
      return;
   /* the inputs, and so the shaded colour, are the same at every pixel */
   struct r_tri_setup ts;
   point_setup(rs, v, &ts);
   point_draw(rs, &ts, b, c);
}

/* A legacy point of the scene (r_scene.c), set up once when it is
 * binned: its square and point_setup's result, which is all flat: z,
 * 1/w, the face and each input's four values, in data[] in increasing
 * input order.  (Kept small: a tile's replay of many small points waits
 * mostly for its commands' first cache lines.) */
struct r_point_binned {
   int32_t b[4];
   float z, w;
   uint32_t inputs;
   bool phong_back;
   float data[];
};

size_t r_point_binned_size(const struct r_state *rs)
{
   /* (counted bit by bit, as r_tri_binned_size: without -mpopcnt
    * __builtin_popcount is a libgcc call, 21 instructions a point) */
   size_t inputs = 0;
   for (unsigned m = rs->fs->fs_inputs; m; m &= m - 1)
      inputs++;
   return sizeof(struct r_point_binned) + inputs * 4 * sizeof(float);
}

int r_point_box_setup(const struct r_state *rs, const struct r_vertex *v, int box[4],
                      struct r_point_binned *bin)
{
   if (rs->rast->point_sprite)
      return 2;
   /* the square cut to the draw region (point_cut) and the buffer */
   const int32_t *const b = bin->b;
   if (!point_square(rs, v, bin->b) ||
       !r_scene_box(rs->fb, rs->px0, rs->py0, rs->px1, rs->py1, b[0], b[1], b[2], b[3], box))
      return 0;
   struct r_tri_setup ts;
   point_setup(rs, v, &ts);
   bin->z = ts.z.a0;
   bin->w = ts.w.a0;
   bin->inputs = ts.inputs;
   bin->phong_back = ts.phong_back;
   float *d = bin->data;
   for (unsigned m = ts.inputs; m; m &= m - 1, d += 4)
      memcpy(d, ts.flat[__builtin_ctz(m)], 4 * sizeof(float));
   return 1;
}

void r_point_binned(const struct r_state *rs, const struct r_point_binned *bin)
{
   int32_t c[4];
   if (!point_cut(rs, bin->b, c))
      return;
   const uint64_t t0 = __builtin_expect(rs->stats != NULL, 0) ? r_stats_now() : 0;
   /* point_setup's r_tri_setup again */
   struct r_tri_setup ts;
   point_setup_head(&ts, bin->z, bin->w, bin->inputs, bin->phong_back);
   const float *d = bin->data;
   for (unsigned m = bin->inputs; m; m &= m - 1, d += 4) {
      const int a = __builtin_ctz(m);
      ts.flat_attr[a] = true;
      memcpy(ts.flat[a], d, 4 * sizeof(float));
   }
   point_draw(rs, &ts, bin->b, c);
   if (__builtin_expect(rs->stats != NULL, 0))
      rs->stats->raster_ns += r_stats_now() - t0;
}
