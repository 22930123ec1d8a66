/*
 * Non-antialiased lines, bit-exact with llvmpipe (llvmpipe-facts.md §3
 * "Lines"; [S: llvmpipe/lp_setup_line.c:try_setup_line]).
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
 */
#include "r_state.h"

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

struct plane {
   float a0, dadx, dady;
};

struct line_info {
   float dx, dy, oneoverarea;
   const struct r_vertex *v1;   /* the original first vertex */
};

/* lp_setup_line.c:linear_coef (a1, a2 already premultiplied for
 * perspective_coef) */
static inline struct plane line_coef(const struct line_info *info, float a1, float a2)
{
   struct plane p;
   const float da21 = a1 - a2;
   p.dadx = da21 * info->dx * info->oneoverarea;
   p.dady = da21 * info->dy * info->oneoverarea;
   p.a0 = a1 - (p.dadx * (info->v1->pos[0] - 0.5f) + p.dady * (info->v1->pos[1] - 0.5f));
   return p;
}

static inline float eval_plane(const struct plane *p, float x, float y)
{
   return fmaf(p->dady, y, fmaf(p->dadx, x, p->a0));
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

void r_line(const struct r_state *rs, const struct r_vertex *v1, const struct r_vertex *v2)
{
   /* v2 (the second vertex) is the provoking vertex */
   const struct r_vertex *const pv = v2;
   /* MAX2(1.0, line_width) */
   const float width = 1.0f > rs->line_width ? 1.0f : rs->line_width;

   for (int i = 0; i < 2; i++)
      if (!isfinite(v1->pos[i]) || !isfinite(v2->pos[i]))
         return;   /* only reachable with w = 0 exactly on the clip volume */

   float dx = v1->pos[0] - v2->pos[0];
   float dy = v1->pos[1] - v2->pos[1];
   const float area = dx * dx + dy * dy;
   if (area == 0.0f)
      return;

   struct line_info info = {
      .dx = dx, .dy = dy, .oneoverarea = 1.0f / area, .v1 = v1,
   };

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
   int32_t x[4], y[4];

   if (fabsf(dx) >= fabsf(dy)) {
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
      y[0] = r_subpixel_snap(a->pos[1] + y_offset - 0.5f) - fixed_width / 2;
      y[1] = r_subpixel_snap(b->pos[1] + y_offset_end - 0.5f) - fixed_width / 2;
      y[2] = r_subpixel_snap(b->pos[1] + y_offset_end - 0.5f) + fixed_width / 2;
      y[3] = r_subpixel_snap(a->pos[1] + y_offset - 0.5f) + fixed_width / 2;
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
      x[0] = r_subpixel_snap(a->pos[0] + x_offset - 0.5f) - fixed_width / 2;
      x[1] = r_subpixel_snap(b->pos[0] + x_offset_end - 0.5f) - fixed_width / 2;
      x[2] = r_subpixel_snap(b->pos[0] + x_offset_end - 0.5f) + fixed_width / 2;
      x[3] = r_subpixel_snap(a->pos[0] + x_offset - 0.5f) + fixed_width / 2;
      y[0] = r_subpixel_snap(a->pos[1] + y_offset - 0.5f);
      y[1] = r_subpixel_snap(b->pos[1] + y_offset_end - 0.5f);
      y[2] = r_subpixel_snap(b->pos[1] + y_offset_end - 0.5f);
      y[3] = r_subpixel_snap(a->pos[1] + y_offset - 0.5f);
   }

   /* bounding box in pixels (inclusive), adjusted for the bottom-left
    * convention, cut to the draw region */
   const int adj = 1;
   int32_t bx0 = (min4(x[0], x[1], x[2], x[3]) + 255) >> 8;
   int32_t bx1 = ((max4(x[0], x[1], x[2], x[3]) + 255) >> 8) - 1;
   int32_t by0 = (min4(y[0], y[1], y[2], y[3]) + 255 + adj) >> 8;
   int32_t by1 = ((max4(y[0], y[1], y[2], y[3]) + 255 + adj) >> 8) - 1;
   if (bx0 < rs->x0) bx0 = rs->x0;
   if (by0 < rs->y0) by0 = rs->y0;
   if (bx1 > rs->x1 - 1) bx1 = rs->x1 - 1;
   if (by1 > rs->y1 - 1) by1 = rs->y1 - 1;
   if (bx0 > bx1 || by0 > by1)
      return;

   /* the four edges, as the triangles' (lp_setup_tri.c conventions) */
   int64_t c[4], dcdx[4], dcdy[4];
   for (int i = 0; i < 4; i++) {
      const int j = (i + 1) & 3;
      dcdy[i] = (int64_t)x[i] - x[j];
      dcdx[i] = (int64_t)y[i] - y[j];
      c[i] = dcdx[i] * x[i] - dcdy[i] * y[i];
      if (dcdx[i] < 0 || (dcdx[i] == 0 && dcdy[i] < 0))
         c[i]++;
      dcdx[i] *= 256;
      dcdy[i] *= 256;
   }

   /* setup_line_coefficients: depth and 1/w are linear, the inputs
    * perspective (premultiplied by 1/w) or constant from the provoking
    * vertex */
   const struct plane zp = line_coef(&info, v1->pos[2], v2->pos[2]);
   const struct plane wp = line_coef(&info, v1->pos[3], v2->pos[3]);
   struct plane ap[R_FS_NUM_INPUTS][4];
   float flat[R_FS_NUM_INPUTS][4];
   bool flat_attr[R_FS_NUM_INPUTS];
   bool need_w = false;
   for (int a = 0; a < R_FS_NUM_INPUTS; a++) {
      if (!(rs->fs_inputs & (1u << a)))
         continue;
      const int slot = r_fs_slot(a, false);
      flat_attr[a] = (rs->flat_mask & (1u << slot)) != 0;
      need_w |= !flat_attr[a];
      for (int k = 0; k < 4; k++) {
         if (flat_attr[a])
            flat[a][k] = pv->attr[slot][k];
         else
            ap[a][k] = line_coef(&info, v1->attr[slot][k] * v1->pos[3],
                                 v2->attr[slot][k] * v2->pos[3]);
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
      for (int32_t px = (int32_t)x0; px <= x1; px++) {
         const float fx = (float)px, fy = (float)py;
         float in[R_FS_NUM_INPUTS][4];
         const float rw = need_w ? 1.0f / eval_plane(&wp, fx, fy) : 0.0f;
         for (int a = 0; a < R_FS_NUM_INPUTS; a++) {
            if (!(rs->fs_inputs & (1u << a)))
               continue;
            for (int k = 0; k < 4; k++)
               in[a][k] = flat_attr[a] ? flat[a][k] : eval_plane(&ap[a][k], fx, fy) * rw;
         }
         float color[4];
         r_fragment_shader(rs, (const float (*)[4])in, color);
         r_fragment_ops(rs, px, py, eval_plane(&zp, fx, fy), color);
      }
   }
}
