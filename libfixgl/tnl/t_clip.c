/*
 * Geometric clipping against the six view-volume planes, as the oracle's
 * draw module does it (llvmpipe-facts.md §1 "Clipping"; Mesa
 * draw_pipe_clip.c: do_clip_tri, interp, emit_poly):
 *  - planes in outcode-bit order, Sutherland-Hodgman, inside iff dp >= 0;
 *  - the new vertex is interpolated from whichever end is inside the plane
 *    by the larger margin, as out + t*(in - out) for the clip position and
 *    every attribute;
 *  - new vertices get window coordinates in plain C, without FMA;
 *  - a NaN or infinite plane distance discards the triangle;
 *  - the result is fanned as (P[i-1], P[i], P[0]) with the provoking
 *    vertex's flat attributes on P[0].
 * Lines are clipped parametrically (do_clip_line): each end that is outside
 * moves to the largest exit parameter over the planes, its attributes lerped
 * the same way; points are dropped unless the centre is inside every plane
 * (clip_point: llvmpipe has no guard band here).
 */
#include "tnl/t_pipeline.h"

#include <math.h>

#include "context.h"

#define MAX_CLIPPED_VERTICES (2 * (6 + 8) + 1)   /* as Mesa, with 8 user planes */

static const float clip_planes[6][4] = {
   { -1, 0, 0, 1 }, { 1, 0, 0, 1 }, { 0, -1, 0, 1 },
   { 0, 1, 0, 1 },  { 0, 0, 1, 1 }, { 0, 0, -1, 1 },
};

static inline float dot4(const float *a, const float *b)
{
   return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

static inline float lerp(float t, float out, float in)
{
   return out + t * (in - out);
}

static void interp(const struct fgl_context *ctx, struct t_vertex *dst, float t,
                   const struct t_vertex *out, const struct t_vertex *in, int nattr)
{
   for (int i = 0; i < 4; i++)
      dst->clip[i] = lerp(t, out->clip[i], in->clip[i]);
   dst->mask = 0;

   const float *s = ctx->_ViewportScale, *tr = ctx->_ViewportTranslate;
   const float oow = 1.0f / dst->clip[3];
   for (int i = 0; i < 3; i++)
      dst->r.pos[i] = dst->clip[i] * oow * s[i] + tr[i];
   dst->r.pos[3] = oow;

   for (int a = 0; a < nattr; a++)
      for (int c = 0; c < 4; c++)
         dst->r.attr[a][c] = lerp(t, out->r.attr[a][c], in->r.attr[a][c]);
}

/* A triangle through the stages after clipping (draw_pipe_validate.c
 * order): cull, when culling is on or draw does two-sided lighting, on the
 * float determinant of the window positions (zero area counts as back);
 * two-sided colours on its sign when draw does them (ctx->_DrawTwosideTris;
 * zero is front); the stipple stage, which restarts the line stipple
 * counter; then llvmpipe's setup, which culls again on the snapped area and
 * does two-sided colours itself only when draw does not.
 * [S: draw_pipe_cull.c:cull_tri, draw_pipe_twoside.c:twoside_tri,
 * draw_pipe_stipple.c:stipple_reset_tri] */
static void pipeline_tri(struct fgl_context *ctx, const struct r_vertex *v0,
                         const struct r_vertex *v1, const struct r_vertex *v2)
{
   const struct r_state *rs = &ctx->_Raster;
   const float ex = v0->pos[0] - v2->pos[0];
   const float ey = v0->pos[1] - v2->pos[1];
   const float fx = v1->pos[0] - v2->pos[0];
   const float fy = v1->pos[1] - v2->pos[1];
   const float det = ex * fy - ey * fx;

   if (rs->cull_front || rs->cull_back || ctx->_DrawTwosideTris) {
      /* det < 0 is counter-clockwise */
      if (det != 0) {
         const bool front = (det < 0) == rs->ccw_is_front;
         if (front ? rs->cull_front : rs->cull_back)
            return;
      } else if (rs->cull_back) {
         return;
      }
   }

   if (ctx->Line.StippleFlag && ctx->Line.StipplePattern != 0xffff)
      ctx->StippleCounter = 0;

   if (!ctx->_DrawTwosideTris) {
      r_triangle(rs, v0, v1, v2);
      return;
   }
   struct r_state nots = *rs;
   nots.twoside = false;
   /* back-facing if det * sign < 0, sign = front_ccw ? -1 : 1 */
   if (det * (rs->ccw_is_front ? -1.0f : 1.0f) < 0.0f) {
      struct r_vertex b[3] = { *v0, *v1, *v2 };
      for (int i = 0; i < 3; i++)
         for (int c = 0; c < 4; c++) {
            b[i].attr[R_ATTR_COLOR0][c] = b[i].attr[R_ATTR_BCOLOR0][c];
            b[i].attr[R_ATTR_COLOR1][c] = b[i].attr[R_ATTR_BCOLOR1][c];
         }
      r_triangle(&nots, &b[0], &b[1], &b[2]);
   } else {
      r_triangle(&nots, v0, v1, v2);
   }
}

void t_clip_triangle(struct fgl_context *ctx, const struct t_vertex *v0,
                     const struct t_vertex *v1, const struct t_vertex *v2, bool pipeline)
{
   const struct r_state *rs = &ctx->_Raster;
   unsigned clipmask = v0->mask | v1->mask | v2->mask;

   if (!pipeline) {
      /* straight to llvmpipe (nothing in the segment needs clipping) */
      r_triangle(rs, &v0->r, &v1->r, &v2->r);
      return;
   }
   if (clipmask == 0) {
      pipeline_tri(ctx, &v0->r, &v1->r, &v2->r);
      return;
   }
   if (v0->mask & v1->mask & v2->mask)
      return; /* entirely outside one plane */

   struct t_vertex tmp[MAX_CLIPPED_VERTICES + 2];
   unsigned tmpnr = 0;
   const struct t_vertex *a[MAX_CLIPPED_VERTICES + 1], *b[MAX_CLIPPED_VERTICES + 1];
   const struct t_vertex **inlist = a, **outlist = b;
   unsigned n = 3;
   inlist[0] = v0;
   inlist[1] = v1;
   inlist[2] = v2;

   while (clipmask && n >= 3) {
      const int plane_idx = __builtin_ctz(clipmask);
      const float *plane = clip_planes[plane_idx];
      const struct t_vertex *vert_prev = inlist[0];
      float dp_prev = dot4(vert_prev->clip, plane);
      unsigned outcount = 0;

      clipmask &= ~(1u << plane_idx);
      if (!isfinite(dp_prev) || n >= MAX_CLIPPED_VERTICES)
         return;
      inlist[n] = inlist[0];

      for (unsigned i = 1; i <= n; i++) {
         const struct t_vertex *vert = inlist[i];
         const float dp = dot4(vert->clip, plane);
         bool different_sign;

         if (!isfinite(dp))
            return;
         if (dp_prev >= 0.0f) {
            if (outcount >= MAX_CLIPPED_VERTICES)
               return;
            outlist[outcount++] = vert_prev;
            different_sign = dp < 0.0f;
         } else {
            different_sign = !(dp < 0.0f);
         }

         if (different_sign) {
            if (tmpnr >= MAX_CLIPPED_VERTICES + 1 || outcount >= MAX_CLIPPED_VERTICES)
               return;
            struct t_vertex *nv = &tmp[tmpnr++];
            outlist[outcount++] = nv;
            const float denom = dp - dp_prev;
            if (dp < 0.0f) {
               /* going out */
               if (-dp < dp_prev)
                  interp(ctx, nv, dp / denom, vert, vert_prev, rs->num_attribs);
               else
                  interp(ctx, nv, -dp_prev / denom, vert_prev, vert, rs->num_attribs);
            } else {
               /* coming back in */
               if (-dp_prev < dp)
                  interp(ctx, nv, -dp_prev / denom, vert_prev, vert, rs->num_attribs);
               else
                  interp(ctx, nv, dp / denom, vert, vert_prev, rs->num_attribs);
            }
         }
         vert_prev = vert;
         dp_prev = dp;
      }

      const struct t_vertex **t = inlist;
      inlist = outlist;
      outlist = t;
      n = outcount;
   }

   if (n < 3)
      return;

   /* flat attributes of the provoking vertex go to P[0] */
   if (rs->flat_mask && inlist[0] != v2) {
      struct t_vertex *p0 = &tmp[tmpnr++];
      *p0 = *inlist[0];
      for (int a = 0; a < rs->num_attribs; a++)
         if (rs->flat_mask & (1u << a))
            for (int c = 0; c < 4; c++)
               p0->r.attr[a][c] = v2->r.attr[a][c];
      inlist[0] = p0;
   }

   for (unsigned i = 2; i < n; i++)
      pipeline_tri(ctx, &inlist[i - 1]->r, &inlist[i]->r, &inlist[0]->r);
}

/* draw_pipe_clip.c copy_flat: the provoking vertex's flat attributes */
static void copy_flat(const struct r_state *rs, struct t_vertex *dst, const struct t_vertex *pv)
{
   for (int a = 0; a < rs->num_attribs; a++)
      if (rs->flat_mask & (1u << a))
         for (int c = 0; c < 4; c++)
            dst->r.attr[a][c] = pv->r.attr[a][c];
}

bool t_clip_line(const struct fgl_context *ctx, const struct t_vertex *v0,
                 const struct t_vertex *v1, struct t_vertex out[2])
{
   const struct r_state *rs = &ctx->_Raster;
   unsigned clipmask = v0->mask | v1->mask;

   out[0] = *v0;
   out[1] = *v1;
   if (clipmask == 0)
      return true;
   if (v0->mask & v1->mask)
      return false;   /* entirely outside one plane */

   /* do_clip_line: the parameters at which each end leaves the volume,
    * plane by plane in outcode-bit order */
   float t0 = 0.0f, t1 = 0.0f;
   while (clipmask) {
      const int plane_idx = __builtin_ctz(clipmask);
      const float dp0 = dot4(v0->clip, clip_planes[plane_idx]);
      const float dp1 = dot4(v1->clip, clip_planes[plane_idx]);
      if (!isfinite(dp0) || !isfinite(dp1))
         return false;   /* discard NaN */
      if (dp1 < 0.0f) {
         const float t = dp1 / (dp1 - dp0);
         t1 = t1 > t ? t1 : t;   /* MAX2 */
      }
      if (dp0 < 0.0f) {
         const float t = dp0 / (dp0 - dp1);
         t0 = t0 > t ? t0 : t;
      }
      if (t0 + t1 >= 1.0f)
         return false;
      clipmask &= ~(1u << plane_idx);
   }

   /* new ends interpolated from the end they replace towards the other,
    * with the provoking (second) vertex's flat attributes */
   if (v0->mask) {
      interp(ctx, &out[0], t0, v0, v1, rs->num_attribs);
      copy_flat(rs, &out[0], v1);
   }
   if (v1->mask) {
      interp(ctx, &out[1], t1, v1, v0, rs->num_attribs);
      copy_flat(rs, &out[1], v1);
   }
   return true;
}
