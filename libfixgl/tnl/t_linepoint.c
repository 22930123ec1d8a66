/*
 * Points and lines between primitive assembly and the raster core, as the
 * oracle's draw module runs them (llvmpipe-facts.md §3; [S: draw/
 * draw_pipe_validate.c:validate_pipeline]): clip, then (when line stipple
 * is on) the flatshade and stipple stages, then llvmpipe's point and line
 * setup.  Lines and points that need no stage go straight to llvmpipe;
 * for them that is the same as this pipeline with nothing to do, since
 * each point and line is set up on its own (unlike the quad split of
 * triangles, nothing depends on which path a batch takes).
 *
 * Wide points and lines are never split by draw (llvmpipe sets the wide
 * thresholds to 10000, above the 255 limit), so they are only cut by the
 * draw region (framebuffer, later the scissor).
 */
#include "tnl/t_pipeline.h"

#include <math.h>

#include "context.h"

void t_point(struct fgl_context *ctx, const struct t_vertex *v)
{
   /* draw_pipe_clip.c:clip_point */
   if (v->mask)
      return;
   r_point(&ctx->_Raster, &v->r);
}

/* draw_pipe_stipple.c:screen_interp: every output, position (window
 * coordinates and 1/w) included, lerped linearly */
static void screen_interp(const struct r_state *rs, struct r_vertex *dst, float t,
                          const struct r_vertex *v0, const struct r_vertex *v1)
{
   for (int i = 0; i < 4; i++)
      dst->pos[i] = v0->pos[i] + t * (v1->pos[i] - v0->pos[i]);
   for (int a = 0; a < rs->num_attribs; a++)
      for (int c = 0; c < 4; c++)
         dst->attr[a][c] = v0->attr[a][c] + t * (v1->attr[a][c] - v0->attr[a][c]);
}

/* draw_pipe_stipple.c:emit_segment */
static void emit_segment(const struct r_state *rs, const struct r_vertex *v0,
                         const struct r_vertex *v1, float t0, float t1)
{
   struct r_vertex n0, n1;
   const struct r_vertex *a = v0, *b = v1;
   if (t0 > 0.0f) {
      screen_interp(rs, &n0, t0, v0, v1);
      a = &n0;
   }
   if (t1 < 1.0f) {
      screen_interp(rs, &n1, t1, v0, v1);
      b = &n1;
   }
   r_line(rs, a, b);
}

/* draw_pipe_stipple.c:stipple_test */
static inline bool stipple_test(unsigned counter, unsigned pattern, unsigned factor)
{
   const unsigned b = (counter / factor) & 0xf;
   return ((1u << b) & pattern) != 0;
}

/* draw_pipe_stipple.c:stipple_line: the line is walked one pixel of its
 * major axis at a time and each run of "on" bits becomes a sub-line. */
static void stipple_line(struct fgl_context *ctx, const struct r_vertex *v0,
                         const struct r_vertex *v1, bool first)
{
   const struct r_state *rs = &ctx->_Raster;
   const unsigned pattern = ctx->Line.StipplePattern;
   const unsigned factor = (unsigned)ctx->Line.StippleFactor;
   const float x0 = v0->pos[0], x1 = v1->pos[0];
   const float y0 = v0->pos[1], y1 = v1->pos[1];
   float length;
   int intlength;

   if (first)
      ctx->StippleCounter = 0;

   if (ctx->Line.SmoothFlag) {
      /* rectangular (smooth) lines: the Euclidean length */
      const float dx = x1 - x0, dy = y1 - y0;
      length = sqrtf(dx * dx + dy * dy);
   } else {
      const float dx = x0 > x1 ? x0 - x1 : x1 - x0;
      const float dy = y0 > y1 ? y0 - y1 : y1 - y0;
      length = dx > dy ? dx : dy;   /* MAX2 */
   }
   intlength = isfinite(length) ? (int)ceilf(length) : 0;

   float start = 0;
   bool state = false;
   for (int i = 0; i < intlength; i++) {
      const bool result = stipple_test(ctx->StippleCounter + (unsigned)i, pattern, factor);
      if (result != state) {
         if (state)
            emit_segment(rs, v0, v1, start / length, (float)i / length);
         else
            start = (float)i;
         state = result;
      }
   }
   if (state && start < length)
      emit_segment(rs, v0, v1, start / length, 1.0f);

   ctx->StippleCounter += (unsigned)intlength;
}

void t_line(struct fgl_context *ctx, const struct t_vertex *v0, const struct t_vertex *v1,
            bool first)
{
   const struct r_state *rs = &ctx->_Raster;
   struct t_vertex c[2];
   if (!t_clip_line(ctx, v0, v1, c))
      return;   /* the stipple stage does not see it: no counter reset */

   /* st_atom_rasterizer.c: an all-ones pattern disables stippling */
   if (ctx->Line.StippleFlag && ctx->Line.StipplePattern != 0xffff) {
      /* the flatshade stage runs first (precalc_flat): both ends get the
       * provoking vertex's flat attributes, so the stipple lerp keeps them */
      for (int a = 0; a < rs->num_attribs; a++)
         if (rs->flat_mask & (1u << a))
            for (int k = 0; k < 4; k++)
               c[0].r.attr[a][k] = c[1].r.attr[a][k];
      stipple_line(ctx, &c[0].r, &c[1].r, first);
      return;
   }
   r_line(rs, &c[0].r, &c[1].r);
}
