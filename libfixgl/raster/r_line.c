/*
 * Non-antialiased lines, bit-exact with llvmpipe (ORACLE-NOTES.md "Line
 * and point rasterization"; [S: llvmpipe/lp_setup_line.c:try_setup_line]).
 *
 * A line is a parallelogram: its two ends are snapped with util_iround
 * (round half away from zero) after the "diamond exit" emulation moved them
 * by half a pixel along the major axis where the GL diamond rule and the
 * parallelogram disagree, then widened by the whole-pixel width
 * iround(max(1, width)) along the minor axis.  Coverage uses the four edge
 * functions with the triangles' bottom-left fill convention.
 *
 * Attributes use llvmpipe's "wide lines" plane: along the major axis only,
 * dadx = (a1 - a2) * (dx * (1 + (dy/dx)^2)) * (1 / (dx^2 + dy^2)) for an
 * x-major line (dady = 0), from the vertices in their original order, and
 * the same fma plane evaluation as triangles.
 *
 * In the exact case (below) a line is shaded by the state's block kernel
 * (r_state.line_kernel, r_kernel.h: its two long sides and its planes as a
 * r_tri_setup) unless the pstipple shader is bound; else, and for the
 * reference kernels, pixel by pixel here.
 *
 * A line with a non-finite end (a vertex at w = 0 on the clip volume
 * projects to NaN or infinity) is still set up: its corners snap to
 * INT32_MIN, the 32-bit corner, bounding box and step arithmetic wraps,
 * and its coverage then follows llvmpipe's binning and block code, shared
 * with the triangles (r_bin_planes; ORACLE-NOTES.md "Coverage of
 * non-finite triangles" and "Lines with a non-finite end").
 */
#include "r_kernel.h"
#include "r_scene.h"

#include <limits.h>
#include <math.h>

/* lp_setup_line.c sign(): x >= 0 */
static inline bool sign(float x)
{
   return x >= 0.0f;
}

/* lp_setup_line.c fracf() */
static inline float fracf(float f)
{
   return f - floorf(f);
}

struct line_info {
   float dx, dy, oneoverarea;
   const struct r_vertex *v1;   /* the original first vertex */
};

/* lp_setup_line.c:linear_coef (a1, a2 already premultiplied for
 * perspective_coef) */
static inline struct r_attr_plane line_coef(const struct line_info *info, float a1, float a2)
{
   struct r_attr_plane p;
   const float da21 = a1 - a2;
   p.dadx = da21 * info->dx * info->oneoverarea;
   p.dady = da21 * info->dy * info->oneoverarea;
   p.a0 = a1 - (p.dadx * (info->v1->pos[0] - 0.5f) + p.dady * (info->v1->pos[1] - 0.5f));
   return p;
}

/* A line's setup switches to the MXCSR rs->setup_mxcsr asks for (draw's
 * pipeline lines are set up in the application's, ORACLE-NOTES.md
 * "Interpolation", probe p_setup_fpstate_lines; as r_tri.c setup_shade's
 * triangles): the state to restore with setup_fpstate_leave, 0 when
 * nothing was switched. */
static inline unsigned setup_fpstate_enter(const struct r_state *rs)
{
#if defined(__SSE__) || defined(__x86_64__)
   if (__builtin_expect(rs->setup_mxcsr != 0, 0)) {
      const unsigned csr = _mm_getcsr();
      _mm_setcsr(rs->setup_mxcsr);
      return csr;
   }
#else
   (void)rs;
#endif
   return 0;
}

static inline void setup_fpstate_leave(unsigned csr)
{
#if defined(__SSE__) || defined(__x86_64__)
   if (__builtin_expect(csr != 0, 0))
      _mm_setcsr(csr);
#else
   (void)csr;
#endif
}

/* floor(a / b) for b > 0 */
static inline int64_t floor_div(int64_t a, int64_t b)
{
   return a >= 0 ? a / b : -((-a + b - 1) / b);
}

static inline int32_t min4(int32_t a, int32_t b, int32_t c, int32_t d)
{
   const int32_t m = a < b ? a : b, n = c < d ? c : d;
   return m < n ? m : n;
}

static inline int32_t max4(int32_t a, int32_t b, int32_t c, int32_t d)
{
   const int32_t m = a > b ? a : b, n = c > d ? c : d;
   return m > n ? m : n;
}

static inline int32_t sub32(int32_t a, int32_t b) { return (int32_t)((uint32_t)a - (uint32_t)b); }

void r_setup_shade_pixel(const struct r_state *rs, const void *ctx, int px, int py)
{
   /* the line's or the sprite's setup (setup_line_coefficients,
    * r_point.c sprite) */
   const struct r_tri_setup *ls = ctx;
   if (rs->stipple_points_lines && !r_stipple_pass(rs, px, py))
      return;   /* the pstipple shader's kill (t_vbuf_flush) */
   if (__builtin_expect(rs->stats != NULL, 0))
      rs->stats->fragments++;
   const float fx = (float)px, fy = (float)py;
   float in[R_FS_NUM_INPUTS][4];
   const float rw = ls->need_w ? 1.0f / r_eval_plane(&ls->w, fx, fy) : 0.0f;
   for (int a = 0; a < R_FS_NUM_INPUTS; a++) {
      if (!(rs->fs->fs_inputs & (1u << a)))
         continue;
      for (int k = 0; k < 4; k++)
         in[a][k] = ls->flat_attr[a] ? ls->flat[a][k] : r_eval_plane(&ls->ap[a][k], fx, fy) * rw;
   }
   if (rs->fs->phong)
      r_fragment_phong(rs, in, ls->phong_back);
   float color[4];
   if (rs->fs->tex_units) {
      /* the quad's texture coordinates from the line's planes
       * (ORACLE-NOTES.md "Texture sampling: level of detail per quad") */
      static const int dx[3] = { 0, 1, 0 }, dy[3] = { 0, 0, 1 };
      struct r_fs_quad quad;
      const int qx = px & ~1, qy = py & ~1;
      /* i >= 3: the pair quad (qx ^ 2) when a lookup needs it */
      for (int i = 0; i < (rs->fs->tex_pair ? 6 : 3); i++) {
         const float qfx = (float)((i < 3 ? qx : qx ^ 2) + dx[i % 3]);
         const float qfy = (float)(qy + dy[i % 3]);
         const float qrw = 1.0f / r_eval_plane(&ls->w, qfx, qfy);
         for (int u = 0; u < R_MAX_TEX_UNITS; u++) {
            if (!(rs->fs->tex_units & (1u << u)))
               continue;
            const int a = R_FS_TEX0 + u;
            float *d = i < 3 ? quad.tex[u][i] : quad.pair[u][i - 3];
            for (int k = 0; k < 4; k++)
               d[k] = ls->flat_attr[a] ? ls->flat[a][k] : r_eval_plane(&ls->ap[a][k], qfx, qfy) * qrw;
         }
      }
      /* a cube map's bottom-right pixels and the fragment's place */
      for (int i = 0; rs->fs->tex_cube && i < (rs->fs->tex_pair ? 2 : 1); i++) {
         const float qfx = (float)((i ? qx ^ 2 : qx) + 1), qfy = (float)(qy + 1);
         const float qrw = 1.0f / r_eval_plane(&ls->w, qfx, qfy);
         for (int u = 0; u < R_MAX_TEX_UNITS; u++) {
            if (!(rs->fs->tex_units & (1u << u)))
               continue;
            const int a = R_FS_TEX0 + u;
            float *d = i ? quad.pair_br[u] : quad.br[u];
            for (int k = 0; k < 4; k++)
               d[k] = ls->flat_attr[a] ? ls->flat[a][k]
                                       : r_eval_plane(&ls->ap[a][k], qfx, qfy) * qrw;
         }
      }
      quad.pos = (unsigned)((px & 1) | (py & 1) << 1);
      r_fragment_shader(rs, (const float (*)[4])in, &quad, color);
   } else {
      r_fragment_shader(rs, (const float (*)[4])in, NULL, color);
   }
   r_fragment_ops(rs, px, py, r_eval_plane(&ls->z, fx, fy), color);
}

static void line(const struct r_state *rs, const struct r_vertex *v1, const struct r_vertex *v2);

/* under fixglStats a line is raster time (setup included) */
void r_line(const struct r_state *rs, const struct r_vertex *v1, const struct r_vertex *v2)
{
   if (__builtin_expect(rs->stats != NULL, 0)) {
      const uint64_t t0 = r_stats_now();
      line(rs, v1, v2);
      rs->stats->raster_ns += r_stats_now() - t0;
      return;
   }
   line(rs, v1, v2);
}

/* What a line's pixels depend on besides its attributes, from its
 * vertices and the state alone (never the draw region): the snapped
 * corners and their bounding box in pixels (inclusive, before the cut to
 * the draw region). */
struct line_geom {
   int32_t x[4], y[4];
   int32_t bx0, bx1, by0, by1;
   bool x_major;
};

/* The corners of the line v1 v2 (false: a zero-length line, no pixel)
 * and, in info, what its attribute planes need. */
static bool line_geom(const struct r_state *rs, const struct r_vertex *v1,
                      const struct r_vertex *v2, struct line_geom *g, struct line_info *pinfo)
{
   /* MAX2(1.0, line_width) */
   const float width = 1.0f > rs->rast->line_width ? 1.0f : rs->rast->line_width;

   float dx = v1->pos[0] - v2->pos[0];
   float dy = v1->pos[1] - v2->pos[1];
   const float area = dx * dx + dy * dy;
   if (area == 0.0f)
      return false;

   struct line_info info = {
      .dx = dx, .dy = dy, .oneoverarea = 1.0f / area, .v1 = v1,
   };
   int32_t *const x = g->x, *const y = g->y;

   float x_offset = 0, y_offset = 0;
   float x_offset_end = 0, y_offset_end = 0;
   float x1diff = v1->pos[0] - floorf(v1->pos[0]) - 0.5f;
   float y1diff = v1->pos[1] - floorf(v1->pos[1]) - 0.5f;
   float x2diff = v2->pos[0] - floorf(v2->pos[0]) - 0.5f;
   float y2diff = v2->pos[1] - floorf(v2->pos[1]) - 0.5f;
   /* the width as a whole number of pixels (width is finite here: the
    * state tracker's CLAMP turns NaN into 1) */
   const int32_t fixed_width = r_iround(width) * 256;
   bool draw_start, draw_end;

   const bool x_major = fabsf(dx) >= fabsf(dy);
   g->x_major = x_major;
   if (x_major) {
      /* x-major */
      const float dydx = dy / dx;
      if (y2diff == -0.5f && dy < 0)
         y2diff = 0.5f;

      /* diamond exit rule for the start point */
      if (fabsf(x1diff) + fabsf(y1diff) < 0.5f)
         draw_start = true;
      else if (sign(x1diff) == sign(-dx))
         draw_start = false;
      else if (sign(-y1diff) != sign(dy))
         draw_start = true;
      else {
         const float yintersect = fracf(v1->pos[1]) + x1diff * dydx;
         draw_start = yintersect < 1.0f && yintersect > 0.0f;
      }
      /* and for the end point */
      if (fabsf(x2diff) + fabsf(y2diff) < 0.5f)
         draw_end = false;
      else if (sign(x2diff) != sign(-dx))
         draw_end = false;
      else if (sign(-y2diff) == sign(dy))
         draw_end = true;
      else {
         const float yintersect = fracf(v2->pos[1]) + x2diff * dydx;
         draw_end = yintersect < 1.0f && yintersect > 0.0f;
      }
      /* what the parallelogram already draws */
      const bool will_draw_start = sign(-x1diff) != sign(dx);
      const bool will_draw_end = sign(x2diff) == sign(-dx) || x2diff == 0;

      /* the "preferred wide-lines formula" for the attributes */
      info.dx *= 1 + dydx * dydx;
      info.dy = 0;

      const struct r_vertex *a = v1, *b = v2;
      if (dx < 0) {
         /* v2 is to the right of v1: swap */
         a = v2;
         b = v1;
         dx = -dx;
         dy = -dy;
         if (will_draw_start != draw_start) {
            x_offset_end = -x1diff - 0.5f;
            y_offset_end = x_offset_end * dydx;
         }
         if (will_draw_end != draw_end) {
            x_offset = -x2diff - 0.5f;
            y_offset = x_offset * dydx;
         }
      } else {
         if (will_draw_start != draw_start) {
            x_offset = -x1diff + 0.5f;
            y_offset = x_offset * dydx;
         }
         if (will_draw_end != draw_end) {
            x_offset_end = -x2diff + 0.5f;
            y_offset_end = x_offset_end * dydx;
         }
      }
      x[0] = r_subpixel_snap(a->pos[0] + x_offset - 0.5f);
      x[1] = r_subpixel_snap(b->pos[0] + x_offset_end - 0.5f);
      x[2] = r_subpixel_snap(b->pos[0] + x_offset_end - 0.5f);
      x[3] = r_subpixel_snap(a->pos[0] + x_offset - 0.5f);
      y[0] = sub32(r_subpixel_snap(a->pos[1] + y_offset - 0.5f), fixed_width / 2);
      y[1] = sub32(r_subpixel_snap(b->pos[1] + y_offset_end - 0.5f), fixed_width / 2);
      y[2] = r_add32(r_subpixel_snap(b->pos[1] + y_offset_end - 0.5f), fixed_width / 2);
      y[3] = r_add32(r_subpixel_snap(a->pos[1] + y_offset - 0.5f), fixed_width / 2);
   } else {
      /* y-major */
      const float dxdy = dx / dy;
      if (x2diff == -0.5f && dx < 0)
         x2diff = 0.5f;

      if (fabsf(x1diff) + fabsf(y1diff) < 0.5f)
         draw_start = true;
      else if (sign(-y1diff) == sign(dy))
         draw_start = false;
      else if (sign(x1diff) != sign(-dx))
         draw_start = true;
      else {
         const float xintersect = fracf(v1->pos[0]) + y1diff * dxdy;
         draw_start = xintersect < 1.0f && xintersect > 0.0f;
      }
      if (fabsf(x2diff) + fabsf(y2diff) < 0.5f)
         draw_end = false;
      else if (sign(-y2diff) != sign(dy))
         draw_end = false;
      else if (sign(x2diff) == sign(-dx))
         draw_end = true;
      else {
         const float xintersect = fracf(v2->pos[0]) + y2diff * dxdy;
         /* (>= 0 here, > 0 everywhere else: as in the oracle) */
         draw_end = xintersect < 1.0f && xintersect >= 0.0f;
      }
      const bool will_draw_start = sign(y1diff) == sign(dy);
      const bool will_draw_end = sign(-y2diff) == sign(dy) || y2diff == 0;

      info.dx = 0;
      info.dy *= 1 + dxdy * dxdy;

      const struct r_vertex *a = v1, *b = v2;
      if (dy > 0) {
         /* v2 is above v1: swap */
         a = v2;
         b = v1;
         dx = -dx;
         dy = -dy;
         if (will_draw_start != draw_start) {
            y_offset_end = -y1diff + 0.5f;
            x_offset_end = y_offset_end * dxdy;
         }
         if (will_draw_end != draw_end) {
            y_offset = -y2diff + 0.5f;
            x_offset = y_offset * dxdy;
         }
      } else {
         if (will_draw_start != draw_start) {
            y_offset = -y1diff - 0.5f;
            x_offset = y_offset * dxdy;
         }
         if (will_draw_end != draw_end) {
            y_offset_end = -y2diff - 0.5f;
            x_offset_end = y_offset_end * dxdy;
         }
      }
      x[0] = sub32(r_subpixel_snap(a->pos[0] + x_offset - 0.5f), fixed_width / 2);
      x[1] = sub32(r_subpixel_snap(b->pos[0] + x_offset_end - 0.5f), fixed_width / 2);
      x[2] = r_add32(r_subpixel_snap(b->pos[0] + x_offset_end - 0.5f), fixed_width / 2);
      x[3] = r_add32(r_subpixel_snap(a->pos[0] + x_offset - 0.5f), fixed_width / 2);
      y[0] = r_subpixel_snap(a->pos[1] + y_offset - 0.5f);
      y[1] = r_subpixel_snap(b->pos[1] + y_offset_end - 0.5f);
      y[2] = r_subpixel_snap(b->pos[1] + y_offset_end - 0.5f);
      y[3] = r_subpixel_snap(a->pos[1] + y_offset - 0.5f);
   }

   /* bounding box in pixels (inclusive), adjusted for the bottom-left
    * convention (32-bit int arithmetic, wrapping for non-finite ends) */
   const int adj = 1;
   const int32_t xmin = min4(x[0], x[1], x[2], x[3]), xmax = max4(x[0], x[1], x[2], x[3]);
   const int32_t ymin = min4(y[0], y[1], y[2], y[3]), ymax = max4(y[0], y[1], y[2], y[3]);
   g->bx0 = r_add32(xmin, 255) >> 8;
   g->bx1 = (r_add32(xmax, 255) >> 8) - 1;
   g->by0 = r_add32(ymin, 255 + adj) >> 8;
   g->by1 = (r_add32(ymax, 255 + adj) >> 8) - 1;
   *pinfo = info;
   return true;
}

/* u_rect_test_intersection of the line's box with the draw region */
static inline bool line_outside(const struct r_state *rs, const struct line_geom *g)
{
   return rs->px0 >= rs->px1 || rs->py0 >= rs->py1 || g->bx1 < rs->px0 ||
          g->bx0 > rs->px1 - 1 || g->by1 < rs->py0 || g->by0 > rs->py1 - 1;
}

/* setup_line_coefficients: depth and 1/w are linear, the inputs
 * perspective (premultiplied by 1/w) or constant from the provoking
 * vertex v2 */
static void line_attrs(const struct r_state *rs, const struct r_vertex *v1,
                       const struct r_vertex *v2, const struct line_info *pinfo,
                       struct r_tri_setup *pls)
{
   const struct line_info info = *pinfo;
   const struct r_vertex *const pv = v2;
   struct r_tri_setup *const ls = pls;
   ls->z = line_coef(&info, v1->pos[2], v2->pos[2]);
   ls->w = line_coef(&info, v1->pos[3], v2->pos[3]);
   ls->zoffset = 0.0f;
   ls->quad_x = ls->quad_y = INT_MIN;   /* (r_tri.c's quad cache: not read for lines) */
   ls->inputs = rs->fs->fs_inputs;
   ls->need_w = false;
   /* GL_PHONG_WIN: a line is front facing, unless it is the edge of an
    * unfilled back face, whose face the vertices carry (draw's
    * inject_front_face_info [S: draw_pipe_unfilled.c], read by
    * lp_setup_line.c from the provoking vertex) */
   ls->phong_back = rs->fs->phong && rs->shade_env->two_side && pv->attr[R_ATTR_NORMAL][3] == 0.0f;
   /* (the inputs' bits in turn: a loop over every input cost more than
    * the planes) */
   for (unsigned m = rs->fs->fs_inputs; m; m &= m - 1) {
      const int a = __builtin_ctz(m);
      const int slot = r_fs_slot(a, false);
      ls->flat_attr[a] = (rs->flat_mask & (1u << slot)) != 0;
      ls->need_w |= !ls->flat_attr[a];
      for (int k = 0; k < 4; k++) {
         if (ls->flat_attr[a])
            ls->flat[a][k] = pv->attr[slot][k];
         else
            ls->ap[a][k] = line_coef(&info, v1->attr[slot][k] * v1->pos[3],
                                    v2->attr[slot][k] * v2->pos[3]);
      }
   }
   if (__builtin_expect(rs->rast->sprite_coord_enable != 0, 0))
      r_zero_sprite_inputs(rs->rast, ls);
}

/* Whether the corners are finite and their differences below 2^22 */
static bool line_exact(const struct line_geom *g)
{
   const int32_t *const x = g->x, *const y = g->y;
   /* With finite corners whose differences stay below 2^22 nothing wraps,
    * and the binned coverage is exactly the pixels whose four edge
    * functions are positive (as for triangles: r_tri.c rasterize_direct);
    * line_raster solves that per row.  Otherwise it follows llvmpipe's
    * arithmetic step by step. */
   bool exact = true;
   for (int i = 0; i < 4; i++) {
      const int j = (i + 1) & 3;
      const int64_t ddx = (int64_t)x[i] - x[j], ddy = (int64_t)y[i] - y[j];
      if (x[i] <= INT32_MIN + (1 << 16) || x[i] >= INT32_MAX - (1 << 16) ||
          y[i] <= INT32_MIN + (1 << 16) || y[i] >= INT32_MAX - (1 << 16) ||
          ddx <= -(1 << 22) || ddx >= (1 << 22) || ddy <= -(1 << 22) || ddy >= (1 << 22))
         exact = false;
   }
   return exact;
}

/* The four edges of an exact line, as the triangles' (lp_setup_tri.c
 * conventions): c, dcdx, dcdy in 64 bits and as r_planes */
static void line_planes(const struct line_geom *g, int64_t c[4], int64_t dcdx[4],
                        int64_t dcdy[4], struct r_plane p[4])
{
   const int32_t *const x = g->x, *const y = g->y;
   for (int i = 0; i < 4; i++) {
      const int j = (i + 1) & 3;
      dcdy[i] = (int64_t)x[i] - x[j];
      dcdx[i] = (int64_t)y[i] - y[j];
      c[i] = dcdx[i] * x[i] - dcdy[i] * y[i];
      if (dcdx[i] < 0 || (dcdx[i] == 0 && dcdy[i] < 0))
         c[i]++;
      dcdx[i] *= 256;
      dcdy[i] *= 256;
      /* (below 2^30: the corners' differences are below 2^22) */
      p[i] = (struct r_plane){ .c = c[i], .dcdx = (int32_t)dcdx[i], .dcdy = (int32_t)dcdy[i] };
   }
}

/* The pixels of the line g of setup ls in the draw region of rs
 * (exact: line_exact(g)) */
static void line_raster(const struct r_state *rs, const struct r_tri_setup *pls,
                        const struct line_geom *g, bool exact)
{
   const struct r_tri_setup *const ls = pls;
   const int32_t *const x = g->x, *const y = g->y;
   const bool x_major = g->x_major;
   int32_t bx0 = g->bx0, bx1 = g->bx1, by0 = g->by0, by1 = g->by1;
   if (!exact) {
      /* [S: lp_setup_line.c:try_setup_line] the four edges: int32 steps
       * (wrapping), a 64-bit constant from the unscaled ones, the fill
       * convention, steps scaled by FIXED_ONE, and the trivial reject
       * offset from the scaled steps */
      struct r_plane p[R_MAX_PLANES];
      for (int i = 0; i < 4; i++) {
         const int j = (i + 1) & 3;
         const int32_t dcdy = sub32(x[i], x[j]);
         const int32_t dcdx = sub32(y[i], y[j]);
         int64_t c = (int64_t)((uint64_t)((int64_t)dcdx * x[i]) -
                               (uint64_t)((int64_t)dcdy * y[i]));
         if (dcdx < 0 || (dcdx == 0 && dcdy < 0))
            c = (int64_t)((uint64_t)c + 1);
         p[i].c = c;
         p[i].dcdx = (int32_t)((uint32_t)dcdx * 256u);
         p[i].dcdy = (int32_t)((uint32_t)dcdy * 256u);
         p[i].eo = 0;
         if (p[i].dcdx < 0)
            p[i].eo -= (uint32_t)p[i].dcdx;
         if (p[i].dcdy > 0)
            p[i].eo += (uint32_t)p[i].dcdy;
      }
      /* bboxpos: negative regions discarded */
      const struct r_shader sh = { r_setup_shade_pixel, ls };
      const int32_t region[4] = { rs->px0, rs->py0, rs->px1, rs->py1 };
      r_bin_planes(rs, p, 4, bx0 > 0 ? bx0 : 0, by0 > 0 ? by0 : 0, bx1, by1, region, &sh);
      return;
   }

   if (bx0 < rs->px0) bx0 = rs->px0;
   if (by0 < rs->py0) by0 = rs->py0;
   if (bx1 > rs->px1 - 1) bx1 = rs->px1 - 1;
   if (by1 > rs->py1 - 1) by1 = rs->py1 - 1;

   int64_t c[4], dcdx[4], dcdy[4];
   struct r_plane p[4];
   line_planes(g, c, dcdx, dcdy, p);

   /* The block kernel of the state, unless the pstipple shader is bound
    * (it kills per pixel), with the two long sides (edges 0 and 2) for
    * edges: the ends (edges 1 and 3) are sides of the box.  With F the
    * width times 256 and X_a = x[0] = x[3], X_b = x[1] = x[2] of an
    * x-major line, edge 3 is F * (X_a - 256 px) > 0, i.e.
    * px < X_a / 256, and edge 1, -F * X_b + 1 + 256 F px > 0 (F >= 256),
    * px >= X_b / 256; the box is ceil(xmin / 256) <= px <=
    * ceil(xmax / 256) - 1, the same when X_b < X_a, and when X_b >= X_a
    * the ends leave no pixel.  Of a y-major line (Y_a = y[0] = y[3],
    * Y_b = y[1] = y[2]) edge 3 is py > Y_a / 256, edge 1 (its bias for a
    * negative dcdy) py <= Y_b / 256, the box floor(ymin / 256) + 1 <= py
    * <= floor(ymax / 256), the same when Y_a < Y_b.  So the pixels of the
    * box with the two long sides positive are the line's (r_tri.c, above
    * rasterize_direct). */
   const bool flat0 = (ls->inputs & (1u << R_FS_COLOR0)) && ls->flat_attr[R_FS_COLOR0];
   const r_tri_kernel kernel = rs->stipple_points_lines ? NULL : rs->line_kernel[flat0];
   if (kernel) {
      if (x_major ? x[1] >= x[0] : y[0] >= y[1])
         return;   /* the ends cross: no pixel */
      const struct r_plane sides[2] = { p[0], p[2] };
      struct r_tri_cover cv;
      if (r_cover_planes(sides, 2, bx0, by0, bx1, by1, &cv)) {
         kernel(rs, ls, &cv);
         return;
      }
   }

   for (int32_t py = by0; py <= by1; py++) {
      /* the pixels of the row where all four edge functions
       * e(px) = c - dcdx*px + dcdy*py are positive, solved per edge in
       * integers (the same set as testing every pixel) */
      int64_t x0 = bx0, x1 = bx1;
      for (int i = 0; i < 4; i++) {
         const int64_t v = c[i] + dcdy[i] * py;
         if (dcdx[i] > 0) {
            /* px < v / dcdx */
            const int64_t m = floor_div(v - 1, dcdx[i]);
            x1 = m < x1 ? m : x1;
         } else if (dcdx[i] < 0) {
            /* px > -v / -dcdx */
            const int64_t m = floor_div(-v, -dcdx[i]) + 1;
            x0 = m > x0 ? m : x0;
         } else if (v <= 0) {
            x1 = x0 - 1;
         }
      }
      for (int32_t px = (int32_t)x0; px <= x1; px++)
         r_setup_shade_pixel(rs, ls, px, py);
   }
}

static void line(const struct r_state *rs, const struct r_vertex *v1, const struct r_vertex *v2)
{
   struct line_geom g;
   struct line_info info;
   struct r_tri_setup ls;
   /* the setup (not the pixels) in rs->setup_mxcsr's state */
   const unsigned csr = setup_fpstate_enter(rs);
   const bool drawn = line_geom(rs, v1, v2, &g, &info) && !line_outside(rs, &g);
   if (drawn)
      line_attrs(rs, v1, v2, &info, &ls);
   setup_fpstate_leave(csr);
   if (drawn)
      line_raster(rs, &ls, &g, line_exact(&g));
}

/* A line of the scene (r_scene.c), set up once when it is binned: its
 * corners and box, then its attribute setup as a triangle's
 * (r_tri_binned_pack), 16 bytes aligned after them. */
struct r_line_binned {
   struct line_geom g;
   _Alignas(16) unsigned char setup[];
};

size_t r_line_binned_size(const struct r_state *rs)
{
   return sizeof(struct r_line_binned) + r_tri_binned_size(rs);
}

static int line_box_setup(const struct r_state *rs, const struct r_vertex *v0,
                          const struct r_vertex *v1, int box[4], struct r_tri_edges *edges,
                          struct r_line_binned *bin)
{
   struct line_geom g;
   struct line_info info;
   if (!line_geom(rs, v0, v1, &g, &info) || line_outside(rs, &g))
      return 0;
   if (!line_exact(&g))
      return 2;
   /* the box cut to the draw region (line_raster's) and the buffer */
   if (!r_scene_box(rs->fb, rs->px0, rs->py0, rs->px1, rs->py1, g.bx0, g.by0, g.bx1, g.by1, box))
      return 0;
   /* every pixel of the line is inside its two long sides (edges 0 and
    * 2, C > 0): a tile where either is negative everywhere has none
    * (r_tri_edges_miss_tile with r_tri.c edge_plane's trivial reject
    * offset); the third edge is 0, never negative */
   int64_t c[4], dcdx[4], dcdy[4];
   struct r_plane p[4];
   line_planes(&g, c, dcdx, dcdy, p);
   for (int e = 0; e < 2; e++) {
      const int i = 2 * e;
      edges->c[e] = c[i];
      edges->dcdx[e] = dcdx[i];
      edges->dcdy[e] = dcdy[i];
      edges->eo[e] = ((dcdy[i] > 0 ? dcdy[i] : 0) - (dcdx[i] < 0 ? dcdx[i] : 0)) * R_TILE_SIZE;
   }
   edges->c[2] = edges->dcdx[2] = edges->dcdy[2] = edges->eo[2] = 0;
   struct r_tri_setup ls;
   bin->g = g;
   line_attrs(rs, v0, v1, &info, &ls);
   r_tri_binned_pack(&ls, (struct r_tri_binned *)(void *)bin->setup);
   return 1;
}

/* (the setup in rs->setup_mxcsr's state, as line()'s) */
int r_line_box_setup(const struct r_state *rs, const struct r_vertex *v0,
                     const struct r_vertex *v1, int box[4], struct r_tri_edges *edges,
                     struct r_line_binned *bin)
{
   const unsigned csr = setup_fpstate_enter(rs);
   const int known = line_box_setup(rs, v0, v1, box, edges, bin);
   setup_fpstate_leave(csr);
   return known;
}

void r_line_binned(const struct r_state *rs, const struct r_line_binned *bin)
{
   if (line_outside(rs, &bin->g))
      return;
   const uint64_t t0 = __builtin_expect(rs->stats != NULL, 0) ? r_stats_now() : 0;
   struct r_tri_setup ls;
   r_tri_binned_unpack((const struct r_tri_binned *)(const void *)bin->setup, &ls);
   line_raster(rs, &ls, &bin->g, true);   /* (only exact lines are binned so) */
   if (__builtin_expect(rs->stats != NULL, 0))
      rs->stats->raster_ns += r_stats_now() - t0;
}
