/*
 * Geometric clipping against the six view-volume planes, as the oracle's
 * draw module does it (ORACLE-NOTES.md "Clipping"; Mesa
 * draw_pipe_clip.c: do_clip_tri, interp, emit_poly):
 *  - planes in outcode-bit order, Sutherland-Hodgman, inside iff dp >= 0;
 *  - the new vertex is interpolated from whichever end is inside the plane
 *    by the larger margin, as out + t*(in - out) for the clip position and
 *    every attribute;
 *  - new vertices get window coordinates in plain C, without FMA;
 *  - a NaN or infinite plane distance discards the triangle;
 *  - the result is fanned as (P[i-1], P[i], P[0]) with the provoking
 *    vertex's flat attributes on P[0].
 * User clip planes (GL_CLIP_PLANEi) are planes 6 + i, clipped after the
 * frustum planes in index order, with the clip-space plane
 * (ctx->_ClipUserPlane) and the same C dot product (draw_pipe_clip.c
 * getclipdist: legacy user planes dot the clip position).
 *
 * The clipper also carries the triangle's edge flags (do_clip_tri,
 * emit_poly): new edges along a frustum plane are hidden, along a user
 * plane drawn.
 *
 * Then every triangle goes on to t_draw_pipe_tri (t_draw_pipe.c), the
 * draw stages after clipping.
 *
 * Lines are clipped parametrically (do_clip_line): each end that is outside
 * moves to the largest exit parameter over the planes (user planes
 * included, through the same distance), its attributes lerped the
 * same way; points are dropped unless the centre is inside every plane
 * (clip_point: llvmpipe has no guard band here).
 */
#include "tnl/t_pipeline.h"

#include <math.h>
#include <string.h>

#include "context.h"

#define MAX_CLIPPED_VERTICES (2 * (6 + 8) + 1)   /* as Mesa, with 8 user planes */

/* draw_context.c:draw_create: the view-volume planes */
static const float clip_planes[6][4] = {
   { -1, 0, 0, 1 }, { 1, 0, 0, 1 }, { 0, -1, 0, 1 },
   { 0, 1, 0, 1 },  { 0, 0, 1, 1 }, { 0, 0, -1, 1 },
};

const float *t_clip_plane(const struct fgl_context *ctx, unsigned plane_idx)
{
   return plane_idx < 6 ? clip_planes[plane_idx] : ctx->_ClipUserPlane[plane_idx - 6];
}

static inline float dot4(const float *a, const float *b)
{
   return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

float t_clip_dist(const struct fgl_context *ctx, const float clip[4], unsigned plane_idx)
{
   return dot4(clip, t_clip_plane(ctx, plane_idx));
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
   /* the feedback vertex's texture coordinate (t_vertex.c), a perspective
    * attribute like the colours */
   if (ctx->RenderMode == GL_FEEDBACK)
      for (int c = 0; c < 4; c++)
         dst->r.attr[R_ATTR_TEX0][c] = lerp(t, out->r.attr[R_ATTR_TEX0][c],
                                            in->r.attr[R_ATTR_TEX0][c]);
}

/* GL_SELECT, GL_FEEDBACK: the feedback draw context's clip stage
 * interpolates only the perspective and linear attributes of a new vertex
 * (draw_pipe_clip.c:interp), so its flat ones (the colours with GL_FLAT)
 * keep what temporary vertex `slot` last held (stale_flat); whatever the
 * slot now holds is what a later vertex in it starts from.  Not visible in
 * GL_RENDER, where llvmpipe takes flat colours from the provoking vertex.
 * Modelled per colour attribute: the oracle's slots hold vertex program
 * outputs by position (the primary colour always first after the position,
 * the back colours after the unlit outputs); a change that moves them
 * between clips (separate specular toggled) is not modelled, and the
 * slots start as uninitialised memory (zero here; ORACLE-NOTES.md). */
void t_feedback_clip_slot(struct fgl_context *ctx, struct t_vertex *v, unsigned slot,
                          bool stale_flat)
{
   float (*held)[4] = ctx->Feedback.ClipTmp[slot];
   const int nattr = ctx->_Raster.fs->num_attribs;
   for (int a = 0; a < R_ATTR_FOG && a < nattr; a++) {
      if (stale_flat && (ctx->_Raster.flat_mask & (1u << a)))
         memcpy(v->r.attr[a], held[a], sizeof(held[a]));
      /* GL_SELECT's vertex has no texture coordinate, so its back colours
       * land where GL_FEEDBACK's texture coordinate and back colours are:
       * they do not become feedback's back colours */
      if (ctx->RenderMode == GL_SELECT && (a == R_ATTR_BCOLOR0 || a == R_ATTR_BCOLOR1))
         continue;
      memcpy(held[a], v->r.attr[a], sizeof(held[a]));
   }
}

/* The unclipped triangle's flags with the edges of vertices whose edge
 * flag is off removed (unfilled draws an edge when both are set). */
static inline unsigned edge_flags(unsigned flags, const struct t_vertex *v0,
                                  const struct t_vertex *v1, const struct t_vertex *v2)
{
   return (flags & T_RESET_STIPPLE) | (v0->edge ? flags & T_EDGE_0 : 0u) |
          (v1->edge ? flags & T_EDGE_1 : 0u) | (v2->edge ? flags & T_EDGE_2 : 0u);
}

void t_clip_triangle(struct fgl_context *ctx, const struct t_vertex *v0,
                     const struct t_vertex *v1, const struct t_vertex *v2, bool pipeline,
                     unsigned flags)
{
   const struct r_state *rs = &ctx->_Raster;
   unsigned clipmask = v0->mask | v1->mask | v2->mask;

   if (!pipeline) {
      /* straight to llvmpipe (nothing in the segment needs clipping) */
      fgl_raster_triangle(ctx, rs, &v0->r, &v1->r, &v2->r);
      return;
   }
   if (clipmask == 0) {
      t_draw_pipe_tri(ctx, &v0->r, &v1->r, &v2->r, edge_flags(flags, v0, v1, v2));
      return;
   }
   if (v0->mask & v1->mask & v2->mask)
      return; /* entirely outside one plane */

   struct t_vertex tmp[MAX_CLIPPED_VERTICES + 2];
   unsigned tmpnr = 0;
   const struct t_vertex *a[MAX_CLIPPED_VERTICES + 1], *b[MAX_CLIPPED_VERTICES + 1];
   const struct t_vertex **inlist = a, **outlist = b;
   /* [S: draw_pipe_clip.c:do_clip_tri] the header's edge bits follow the
    * polygon as it is clipped: edge k starts at vertex k */
   bool ea[MAX_CLIPPED_VERTICES + 1], eb[MAX_CLIPPED_VERTICES + 1];
   bool *in_edges = ea, *out_edges = eb;
   unsigned n = 3;
   inlist[0] = v0;
   inlist[1] = v1;
   inlist[2] = v2;
   in_edges[0] = (flags & T_EDGE_0) != 0;
   in_edges[1] = (flags & T_EDGE_1) != 0;
   in_edges[2] = (flags & T_EDGE_2) != 0;

   while (clipmask && n >= 3) {
      const int plane_idx = __builtin_ctz(clipmask);
      const bool user_plane = plane_idx >= 6;
      const float *plane = t_clip_plane(ctx, plane_idx);
      const struct t_vertex *vert_prev = inlist[0];
      bool edge_prev = in_edges[0];
      float dp_prev = dot4(vert_prev->clip, plane);
      unsigned outcount = 0;

      clipmask &= ~(1u << plane_idx);
      if (!isfinite(dp_prev) || n >= MAX_CLIPPED_VERTICES)
         return;
      inlist[n] = inlist[0];
      in_edges[n] = in_edges[0];

      for (unsigned i = 1; i <= n; i++) {
         const struct t_vertex *vert = inlist[i];
         const bool edge = in_edges[i];
         const float dp = dot4(vert->clip, plane);
         bool different_sign;

         if (!isfinite(dp))
            return;
         if (dp_prev >= 0.0f) {
            if (outcount >= MAX_CLIPPED_VERTICES)
               return;
            out_edges[outcount] = edge_prev;
            outlist[outcount++] = vert_prev;
            different_sign = dp < 0.0f;
         } else {
            different_sign = !(dp < 0.0f);
         }

         if (different_sign) {
            if (tmpnr >= MAX_CLIPPED_VERTICES + 1 || outcount >= MAX_CLIPPED_VERTICES)
               return;
            struct t_vertex *nv = &tmp[tmpnr++];
            bool *new_edge = &out_edges[outcount];
            outlist[outcount++] = nv;
            const float denom = dp - dp_prev;
            if (dp < 0.0f) {
               /* going out */
               if (-dp < dp_prev)
                  interp(ctx, nv, dp / denom, vert, vert_prev, rs->fs->num_attribs);
               else
                  interp(ctx, nv, -dp_prev / denom, vert_prev, vert, rs->fs->num_attribs);
               /* an edge along a user plane is drawn, one along a frustum
                * plane is not (NVIDIA's behaviour, says Mesa) */
               if (user_plane) {
                  *new_edge = true;
                  nv->edge = true;
               } else {
                  *new_edge = edge_prev;
                  nv->edge = false;
               }
            } else {
               /* coming back in: the starting vertex's edge flag */
               if (-dp_prev < dp)
                  interp(ctx, nv, -dp_prev / denom, vert_prev, vert, rs->fs->num_attribs);
               else
                  interp(ctx, nv, dp / denom, vert, vert_prev, rs->fs->num_attribs);
               nv->edge = vert_prev->edge;
               *new_edge = edge_prev;
            }
            if (ctx->RenderMode != GL_RENDER)
               t_feedback_clip_slot(ctx, nv, tmpnr - 1, true);
         }
         vert_prev = vert;
         edge_prev = edge;
         dp_prev = dp;
      }

      const struct t_vertex **t = inlist;
      inlist = outlist;
      outlist = t;
      bool *te = in_edges;
      in_edges = out_edges;
      out_edges = te;
      n = outcount;
   }

   if (n < 3)
      return;

   /* flat attributes of the provoking vertex go to P[0] */
   if (rs->flat_mask && inlist[0] != v2) {
      struct t_vertex *p0 = &tmp[tmpnr++];
      *p0 = *inlist[0];
      t_copy_flat(rs, &p0->r, &v2->r);
      inlist[0] = p0;
      if (ctx->RenderMode != GL_RENDER)
         t_feedback_clip_slot(ctx, p0, tmpnr - 1, false);   /* dup_vert */
   }

   /* [S: draw_pipe_clip.c:emit_poly] the fan (P[i-1], P[i], P[0]): the
    * first triangle restarts the stipple and carries the edge P[0]->P[1]
    * (its edge 2), each the edge P[i-1]->P[i] (edge 0), the last also
    * P[n-1]->P[0] (edge 1) */
   const unsigned edge_first = in_edges[0] ? T_EDGE_2 : 0u;
   unsigned tri_flags = T_RESET_STIPPLE | edge_first | T_EDGE_0;
   for (unsigned i = 2; i < n; i++, tri_flags = T_EDGE_0) {
      if (!in_edges[i - 1])
         tri_flags &= ~T_EDGE_0;
      if (i == n - 1 && in_edges[i])
         tri_flags |= T_EDGE_1;
      t_draw_pipe_tri(ctx, &inlist[i - 1]->r, &inlist[i]->r, &inlist[0]->r,
                   edge_flags(tri_flags, inlist[i - 1], inlist[i], inlist[0]));
   }
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
      const float dp0 = t_clip_dist(ctx, v0->clip, plane_idx);
      const float dp1 = t_clip_dist(ctx, v1->clip, plane_idx);
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
      interp(ctx, &out[0], t0, v0, v1, rs->fs->num_attribs);
      t_copy_flat(rs, &out[0].r, &v1->r);
   }
   if (v1->mask) {
      interp(ctx, &out[1], t1, v1, v0, rs->fs->num_attribs);
      t_copy_flat(rs, &out[1].r, &v1->r);
   }
   return true;
}
