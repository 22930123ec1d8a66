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
 * The polygon clipper itself, t_clip_polygon, knows no GL: it takes what
 * it needs of the draw in a struct t_clipper (the user planes, the
 * viewport, the varyings to interpolate).  t_clip_triangle builds one
 * from the context and sends every resulting triangle on to
 * t_draw_pipe_tri (t_draw_pipe.c), the draw stages after clipping; the
 * pixel rectangles' quads (t_pixels.c) build their own.
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

/* draw_context.c:draw_create: the view-volume planes */
static const float clip_planes[6][4] = {
   { -1, 0, 0, 1 }, { 1, 0, 0, 1 }, { 0, -1, 0, 1 },
   { 0, 1, 0, 1 },  { 0, 0, 1, 1 }, { 0, 0, -1, 1 },
};

/* the guard band's planes: -0.5 x + w >= 0, ... (t_guard_mask) */
static const float guard_planes[4][4] = {
   { -0.5f, 0, 0, 1 }, { 0.5f, 0, 0, 1 }, { 0, -0.5f, 0, 1 }, { 0, 0.5f, 0, 1 },
};

static inline const float *clipper_plane(const struct t_clipper *c, unsigned plane_idx)
{
   if (c->guard && plane_idx < 4)
      return guard_planes[plane_idx];
   return plane_idx < 6 ? clip_planes[plane_idx] : c->user_planes[plane_idx - 6];
}

static inline float dot4(const float *a, const float *b)
{
   return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

float t_clip_dist(const struct fgl_context *ctx, const float clip[4], unsigned plane_idx)
{
   const float *plane =
      plane_idx < 6 ? clip_planes[plane_idx] : ctx->_ClipUserPlane[plane_idx - 6];
   return dot4(clip, plane);
}

/* the same against the guard band's planes where it applies */
static float clip_dist(const struct fgl_context *ctx, bool guard, const float clip[4],
                       unsigned plane_idx)
{
   return guard && plane_idx < 4 ? dot4(clip, guard_planes[plane_idx])
                                  : t_clip_dist(ctx, clip, plane_idx);
}

/* a vertex's outcodes with draw's xy guard band (t_guard_mask) */
static inline unsigned guard_outcodes(const struct t_vertex *v)
{
   return (v->mask & ~0xfu) | t_guard_mask(v->clip);
}

static inline float lerp(float t, float out, float in)
{
   return out + t * (in - out);
}

static void interp(const struct t_clipper *c, struct t_vertex *dst, float t,
                   const struct t_vertex *out, const struct t_vertex *in)
{
   for (int i = 0; i < 4; i++)
      dst->clip[i] = lerp(t, out->clip[i], in->clip[i]);
   dst->mask = 0;

   const float *s = c->scale, *tr = c->translate;
   const float oow = 1.0f / dst->clip[3];
   for (int i = 0; i < 3; i++)
      dst->r.pos[i] = dst->clip[i] * oow * s[i] + tr[i];
   dst->r.pos[3] = oow;

   for (uint32_t attrs = c->attrs; attrs; attrs &= attrs - 1) {
      const int a = __builtin_ctz(attrs);
      for (int k = 0; k < 4; k++)
         dst->r.attr[a][k] = lerp(t, out->r.attr[a][k], in->r.attr[a][k]);
   }
}

void t_clip_polygon(const struct t_clipper *c, struct t_clip_poly *p)
{
   const struct t_vertex *v0 = p->v[0], *v1 = p->v[1], *v2 = p->v[2];
   unsigned clipmask = v0->mask | v1->mask | v2->mask;

   if (v0->mask & v1->mask & v2->mask) {
      p->n = 0;   /* entirely outside one plane */
      return;
   }

   const struct t_vertex *other[T_MAX_CLIPPED_VERTICES + 1];
   const struct t_vertex **inlist = p->v, **outlist = other;
   /* [S: draw_pipe_clip.c:do_clip_tri] the header's edge bits follow the
    * polygon as it is clipped: edge k starts at vertex k */
   bool other_edges[T_MAX_CLIPPED_VERTICES + 1];
   bool *in_edges = p->edge, *out_edges = other_edges;
   unsigned n = 3;

   while (clipmask && n >= 3) {
      const int plane_idx = __builtin_ctz(clipmask);
      const bool user_plane = plane_idx >= 6;
      const float *plane = clipper_plane(c, (unsigned)plane_idx);
      const struct t_vertex *vert_prev = inlist[0];
      bool edge_prev = in_edges[0];
      float dp_prev = dot4(vert_prev->clip, plane);
      unsigned outcount = 0;

      clipmask &= ~(1u << plane_idx);
      if (!isfinite(dp_prev) || n >= T_MAX_CLIPPED_VERTICES) {
         p->n = 0;
         return;
      }
      inlist[n] = inlist[0];
      in_edges[n] = in_edges[0];

      for (unsigned i = 1; i <= n; i++) {
         const struct t_vertex *vert = inlist[i];
         const bool edge = in_edges[i];
         const float dp = dot4(vert->clip, plane);
         bool different_sign;

         if (!isfinite(dp)) {
            p->n = 0;
            return;
         }
         if (dp_prev >= 0.0f) {
            if (outcount >= T_MAX_CLIPPED_VERTICES) {
               p->n = 0;
               return;
            }
            out_edges[outcount] = edge_prev;
            outlist[outcount++] = vert_prev;
            different_sign = dp < 0.0f;
         } else {
            different_sign = !(dp < 0.0f);
         }

         if (different_sign) {
            if (p->ntmp >= T_MAX_CLIPPED_VERTICES + 1 || outcount >= T_MAX_CLIPPED_VERTICES) {
               p->n = 0;
               return;
            }
            struct t_vertex *nv = &p->tmp[p->ntmp++];
            bool *new_edge = &out_edges[outcount];
            outlist[outcount++] = nv;
            const float denom = dp - dp_prev;
            if (dp < 0.0f) {
               /* going out */
               if (-dp < dp_prev)
                  interp(c, nv, dp / denom, vert, vert_prev);
               else
                  interp(c, nv, -dp_prev / denom, vert_prev, vert);
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
                  interp(c, nv, -dp_prev / denom, vert_prev, vert);
               else
                  interp(c, nv, dp / denom, vert, vert_prev);
               nv->edge = vert_prev->edge;
               *new_edge = edge_prev;
            }
            if (c->new_vertex)
               c->new_vertex(c->data, nv, p->ntmp - 1);
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

   if (inlist != p->v) {
      memcpy(p->v, inlist, n * sizeof(p->v[0]));
      memcpy(p->edge, in_edges, n * sizeof(p->edge[0]));
   }
   p->n = n;
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

static void feedback_new_vertex(void *data, struct t_vertex *v, unsigned slot)
{
   t_feedback_clip_slot(data, v, slot, true);
}

/* The vertex stage's clipper: the context's user planes and viewport and
 * the draw's varyings, with the feedback vertex's texture coordinate
 * (t_vertex.c), a perspective attribute like the colours. */
static void clipper_init(const struct fgl_context *ctx, struct t_clipper *c)
{
   const int nattr = ctx->_Raster.fs->num_attribs;
   c->user_planes = (const float (*)[4])ctx->_ClipUserPlane;
   c->scale = ctx->_ViewportScale;
   c->translate = ctx->_ViewportTranslate;
   c->attrs = (1u << nattr) - 1u;
   /* [S: draw_pipe_clip.c:interp] every vertex output is interpolated,
    * the point size too: a polygon-mode point at a new vertex takes the
    * lerped size (random-raster/s1-i1293; case gl14/points_atten_unfilled_clip) */
   if (ctx->_Raster.rast && ctx->_Raster.rast->point_size_per_vertex)
      c->attrs |= 1u << R_ATTR_PSIZE;
   if (ctx->RenderMode == GL_FEEDBACK)
      c->attrs |= 1u << R_ATTR_TEX0;
   c->guard = false;
   c->new_vertex = NULL;
   c->data = NULL;
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

   if (!pipeline) {
      /* straight to llvmpipe (nothing in the segment needs clipping) */
      fgl_raster_triangle(ctx, rs, &v0->r, &v1->r, &v2->r);
      return;
   }
   if ((v0->mask | v1->mask | v2->mask) == 0) {
      t_draw_pipe_tri(ctx, &v0->r, &v1->r, &v2->r, edge_flags(flags, v0, v1, v2));
      return;
   }
   if (v0->mask & v1->mask & v2->mask)
      return; /* entirely outside one plane: not worth a clipper */
   /* draw's xy guard band (t_guard_mask): a triangle outside the
    * viewport goes the pipeline's way, as the viewport's outcodes said,
    * into do_clip_tri, which clips it at the band's planes */
   struct t_vertex g[3];
   const bool guard = fgl_lin_capable(ctx);
   if (guard) {
      /* (inside the band, nothing is clipped, but the clip stage still
       * emits the triangle as a polygon: (v1, v2, v0), emit_poly's fan) */
      const unsigned m0 = guard_outcodes(v0), m1 = guard_outcodes(v1), m2 = guard_outcodes(v2);
      g[0] = *v0;
      g[1] = *v1;
      g[2] = *v2;
      g[0].mask = m0;
      g[1].mask = m1;
      g[2].mask = m2;
      v0 = &g[0];
      v1 = &g[1];
      v2 = &g[2];
   }

   struct t_clipper c;
   clipper_init(ctx, &c);
   c.guard = guard;
   if (ctx->RenderMode != GL_RENDER) {
      c.new_vertex = feedback_new_vertex;
      c.data = ctx;
   }
   struct t_clip_poly p;
   p.n = 3;
   p.v[0] = v0;
   p.v[1] = v1;
   p.v[2] = v2;
   p.edge[0] = (flags & T_EDGE_0) != 0;
   p.edge[1] = (flags & T_EDGE_1) != 0;
   p.edge[2] = (flags & T_EDGE_2) != 0;
   p.ntmp = 0;
   t_clip_polygon(&c, &p);
   const unsigned n = p.n;
   if (n < 3)
      return;

   /* flat attributes of the provoking vertex go to P[0] */
   if (rs->flat_mask && p.v[0] != v2) {
      struct t_vertex *p0 = &p.tmp[p.ntmp++];
      *p0 = *p.v[0];
      t_copy_flat(rs, &p0->r, &v2->r);
      p.v[0] = p0;
      if (ctx->RenderMode != GL_RENDER)
         t_feedback_clip_slot(ctx, p0, p.ntmp - 1, false);   /* dup_vert */
   }

   /* [S: draw_pipe_clip.c:emit_poly] the fan (P[i-1], P[i], P[0]): the
    * first triangle restarts the stipple and carries the edge P[0]->P[1]
    * (its edge 2), each the edge P[i-1]->P[i] (edge 0), the last also
    * P[n-1]->P[0] (edge 1) */
   const unsigned edge_first = p.edge[0] ? T_EDGE_2 : 0u;
   unsigned tri_flags = T_RESET_STIPPLE | edge_first | T_EDGE_0;
   for (unsigned i = 2; i < n; i++, tri_flags = T_EDGE_0) {
      if (!p.edge[i - 1])
         tri_flags &= ~T_EDGE_0;
      if (i == n - 1 && p.edge[i])
         tri_flags |= T_EDGE_1;
      t_draw_pipe_tri(ctx, &p.v[i - 1]->r, &p.v[i]->r, &p.v[0]->r,
                      edge_flags(tri_flags, p.v[i - 1], p.v[i], p.v[0]));
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
   /* draw's xy guard band for points and lines (t_guard_mask): clipped at
    * its planes, unclipped inside it */
   const bool guard = fgl_lin_capable(ctx);
   unsigned m0 = v0->mask, m1 = v1->mask;
   if (guard) {
      m0 = guard_outcodes(v0);
      m1 = guard_outcodes(v1);
      clipmask = m0 | m1;
      if (clipmask == 0)
         return true;
   }

   /* do_clip_line: the parameters at which each end leaves the volume,
    * plane by plane in outcode-bit order */
   float t0 = 0.0f, t1 = 0.0f;
   while (clipmask) {
      const int plane_idx = __builtin_ctz(clipmask);
      const float dp0 = clip_dist(ctx, guard, v0->clip, plane_idx);
      const float dp1 = clip_dist(ctx, guard, v1->clip, plane_idx);
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
   struct t_clipper c;
   clipper_init(ctx, &c);
   if (m0) {
      interp(&c, &out[0], t0, v0, v1);
      t_copy_flat(rs, &out[0].r, &v1->r);
   }
   if (m1) {
      interp(&c, &out[1], t1, v1, v0);
      t_copy_flat(rs, &out[1].r, &v1->r);
   }
   return true;
}
