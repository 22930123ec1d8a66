/*
 * Points and lines between primitive assembly and the raster core, as the
 * oracle's draw module runs them (ORACLE-NOTES.md "Line and point
 * rasterization", "Points and lines"; [S: draw/
 * draw_pipe_validate.c:validate_pipeline]): clip, then (when line stipple
 * or smoothing is on) the flatshade and stipple stages, then the aapoint /
 * aaline stages (smooth points and lines become triangle quads with a
 * coverage input) or llvmpipe's point and line setup.  Lines and points
 * that need no stage go straight to llvmpipe; for them that is the same as
 * this pipeline with nothing to do, since each point and line is set up on
 * its own (unlike the quad split of triangles, only the line stipple
 * counter, which points in the pipeline restart, sees which path a batch
 * takes).
 *
 * Wide points and lines are never split by draw (llvmpipe sets the wide
 * thresholds to 10000, above the 255 limit), so they are only cut by the
 * draw region (the framebuffer intersected with the scissor box).
 */
#include "tnl/t_pipeline.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "context.h"
#include "fgl_alloc.h"

/* The raster state of the smooth point and line quads (validated with
 * the draw's, state.c update_aa_states: the draw module's "no cull"
 * rasterizer, the fragment shader with the coverage lowering), with what
 * the draw's r_state has of the batch (the quads are draw's pipeline's:
 * set up in the caller's MXCSR, pipeline_setup). */
static bool aa_state(struct fgl_context *ctx, struct r_state *aa, enum r_aa_mode mode)
{
   /* the quads of the first primitive after a change decide the region
    * with the "no cull" rasterizer: not cut */
   if (ctx->_VpCutDirty)
      fgl_vpcut_decide(ctx, true);
   const struct r_state *rs = &ctx->_Raster;
   *aa = ctx->_RasterAA[mode == R_AA_POINT ? 0 : 1];
   aa->flat_mask = rs->flat_mask;
   aa->shade_env = rs->shade_env;
   aa->stats = rs->stats;
   aa->samples = rs->samples;
   aa->setup_mxcsr = rs->setup_mxcsr;
   return aa->fs != NULL;   /* else out of memory at validation */
}

/* draw_pipe_aapoint.c:aapoint_point: a square of half size `radius` with
 * coordinates (+-1, +-1, k, 1), drawn as two triangles. */
static void aapoint_point(struct fgl_context *ctx, const struct r_vertex *v)
{
   const struct r_state *rs = &ctx->_Raster;
   struct r_state aa;
   if (!aa_state(ctx, &aa, R_AA_POINT))
      return;

   /* aapoint_first_point */
   /* aapoint_first_point: 1 for a size of 2 or less; a size per vertex:
    * half of it, always (aapoint_point's psize_slot) */
   const float radius = rs->rast->point_size_per_vertex ? 0.5f * v->attr[R_ATTR_PSIZE][0]
                      : rs->rast->point_size <= 2.0f ? 1.0f : 0.5f * rs->rast->point_size;
   float k = 1.0f / radius;
   k = 1.0f - 2.0f * k + k * k;

   static const float sx[4] = { -1, 1, 1, -1 }, sy[4] = { -1, -1, 1, 1 };
   struct r_vertex q[4];
   for (int i = 0; i < 4; i++) {
      q[i] = *v;
      if (sx[i] < 0)
         q[i].pos[0] -= radius;
      else
         q[i].pos[0] += radius;
      if (sy[i] < 0)
         q[i].pos[1] -= radius;
      else
         q[i].pos[1] += radius;
      q[i].attr[R_ATTR_AA][0] = sx[i];
      q[i].attr[R_ATTR_AA][1] = sy[i];
      q[i].attr[R_ATTR_AA][2] = k;
      q[i].attr[R_ATTR_AA][3] = 1.0f;
   }
   fgl_raster_triangle(ctx, &aa, &q[0], &q[1], &q[2]);
   fgl_raster_triangle(ctx, &aa, &q[0], &q[2], &q[3]);
}

/* ---- the vbuf batch under the polygon stipple ----
 * [S: draw_pipe_pstipple.c:pstip_first_tri, pstip_flush] the pstipple
 * stage binds its stipple fragment shader when the first filled triangle
 * of a draw reaches it (with flushing suspended) and restores the user's
 * shader only when the pipeline is flushed (llvmpipe_draw_vbo's draw_flush,
 * at the end of every llvmpipe draw); points and lines pass it untouched.
 * [S: draw_pipe_vbuf.c:vbuf_first_tri/line/point, vbuf_flush_vertices] the
 * vbuf stage hands llvmpipe its queued primitives only when the primitive
 * type changes or the pipeline is flushed, and llvmpipe sets them up with
 * the fragment shader bound then (lp_setup_vbuf.c:lp_setup_draw_elements,
 * lp_setup_update_state).  So within one draw the points and lines the
 * unfilled stage makes after the first filled triangle are polygon
 * stippled, and so is the batch of points or lines queued just before it
 * (flushed by that triangle after the bind); earlier batches are not.
 * (Not modelled: vbuf also flushes when its 4096-byte vertex buffer or
 * 1020 indices are full.)  Queued primitives of draw's pipeline are set up
 * in the caller's MXCSR only at draw_flush (`draw_end`); vbuf's flushes
 * within draw_vbo set them up under its FTZ|DAZ. */
static void vbuf_flush(struct fgl_context *ctx, bool draw_end)
{
   struct fgl_draw_vbuf *vb = &ctx->_DrawVbuf;
   struct r_state *rs = &ctx->_Raster;
   const unsigned csr = rs->setup_mxcsr;
   rs->stipple_points_lines = vb->pstipple_bound;
   rs->setup_mxcsr = draw_end ? vb->setup_mxcsr : 0;
   for (unsigned i = 0; i < vb->count; i++) {
      if (vb->prim == T_VBUF_POINTS)
         fgl_raster_point(ctx, rs, &vb->queue[i][0]);
      else
         fgl_raster_line(ctx, rs, &vb->queue[i][0], &vb->queue[i][1]);
   }
   rs->stipple_points_lines = false;
   rs->setup_mxcsr = csr;
   vb->count = 0;
   vb->prim = T_VBUF_NONE;
}

/* llvmpipe's point or line setup, through the vbuf batch when the polygon
 * stipple is on */
static void vbuf_add(struct fgl_context *ctx, enum t_vbuf_prim prim, const struct r_vertex *v0,
                     const struct r_vertex *v1)
{
   struct fgl_draw_vbuf *vb = &ctx->_DrawVbuf;
   t_lin_flush_tris(ctx);   /* vbuf_first_point / vbuf_first_line */
   if (!ctx->_Raster.rast->stipple) {
      if (prim == T_VBUF_POINTS)
         fgl_raster_point(ctx, &ctx->_Raster, v0);
      else
         fgl_raster_line(ctx, &ctx->_Raster, v0, v1);
      return;
   }
   if (vb->prim != prim)
      vbuf_flush(ctx, false);   /* vbuf_first_point / vbuf_first_line */
   else if (vb->setup_mxcsr != ctx->_Raster.setup_mxcsr)
      vbuf_flush(ctx, true);    /* (a direct segment after a pipeline one) */
   if (vb->count == vb->cap) {
      const unsigned cap = vb->cap ? 2 * vb->cap : 64;
      struct r_vertex (*q)[2] = fgl_realloc(vb->queue, cap * sizeof(*q));
      if (!q) {
         vbuf_flush(ctx, true);   /* out of memory: draw what is queued now */
         vb->prim = prim;
         ctx->_Raster.stipple_points_lines = vb->pstipple_bound;
         if (prim == T_VBUF_POINTS)
            fgl_raster_point(ctx, &ctx->_Raster, v0);
         else
            fgl_raster_line(ctx, &ctx->_Raster, v0, v1);
         ctx->_Raster.stipple_points_lines = false;
         return;
      }
      vb->queue = q;
      vb->cap = cap;
   }
   vb->prim = prim;
   vb->setup_mxcsr = ctx->_Raster.setup_mxcsr;
   vb->queue[vb->count][0] = *v0;
   if (v1)
      vb->queue[vb->count][1] = *v1;
   vb->count++;
}

void t_vbuf_filled_tri(struct fgl_context *ctx)
{
   if (!ctx->_Raster.rast->stipple)
      return;
   /* pstip_first_tri binds the stipple shader, then vbuf_first_tri flushes
    * the queued points or lines */
   ctx->_DrawVbuf.pstipple_bound = true;
   vbuf_flush(ctx, false);
}

void t_vbuf_end_draw(struct fgl_context *ctx)
{
   t_lin_flush_tris(ctx);   /* the draw's pipeline triangles first */
   /* pstip_flush: the vbuf is flushed first, then the shader restored */
   vbuf_flush(ctx, true);
   ctx->_DrawVbuf.pstipple_bound = false;
}

/* [S: lp_draw_arrays.c:llvmpipe_draw_vbo, draw_flush; draw_pipe_vbuf.c]
 * llvmpipe sets up the points, lines and smooth quads of draw's pipeline
 * when draw is flushed after draw_vbo restored the caller's MXCSR, those
 * of the direct path inside draw_vbo, under FTZ|DAZ (ORACLE-NOTES.md
 * "Interpolation", probe p_setup_fpstate_lines): the r_state.setup_mxcsr
 * of what `pipeline` hands over until pipeline_setup(ctx, false). */
static inline void pipeline_setup(struct fgl_context *ctx, bool pipeline)
{
   ctx->_Raster.setup_mxcsr = pipeline ? ctx->_DrawPipeline.caller_mxcsr : 0;
}

/* The stage after stipple: the aapoint quad or llvmpipe's point. */
static void point_raster(struct fgl_context *ctx, const struct r_vertex *v)
{
   if (fgl_point_smooth(ctx)) {
      t_lin_flush_tris(ctx);
      vbuf_flush(ctx, false);   /* vbuf_first_tri: the aapoint quad is triangles */
      aapoint_point(ctx, v);
   } else
      vbuf_add(ctx, T_VBUF_POINTS, v, NULL);
}

void t_point(struct fgl_context *ctx, const struct t_vertex *v, bool pipeline)
{
   /* draw_pipe_clip.c:clip_point; with draw's xy guard band
    * (t_guard_mask) a point whose centre is inside the band is kept */
   if (v->mask && ((v->mask & ~0xfu) || !fgl_lin_capable(ctx) || t_guard_mask(v->clip)))
      return;
   if (ctx->RenderMode != GL_RENDER) {
      t_feedback_point(ctx, &v->r);
      return;
   }
   /* a point in draw's pipeline (smooth, or in a segment that needs
    * clipping) passes the stipple stage, which restarts the line stipple
    * counter (stipple_reset_point) */
   const bool in_pipeline = pipeline || fgl_point_smooth(ctx);
   if (in_pipeline && ctx->_DrawPipeline.line_stipple)
      ctx->StippleCounter = 0;
   pipeline_setup(ctx, in_pipeline);
   point_raster(ctx, &v->r);
   pipeline_setup(ctx, false);
}

void t_unfilled_point(struct fgl_context *ctx, const struct r_vertex *v)
{
   if (ctx->RenderMode != GL_RENDER) {
      t_feedback_point(ctx, v);
      return;
   }
   /* the stipple stage's stipple_reset_point, then aapoint or llvmpipe */
   if (ctx->_DrawPipeline.line_stipple)
      ctx->StippleCounter = 0;
   pipeline_setup(ctx, true);
   point_raster(ctx, v);
   pipeline_setup(ctx, false);
}

/* draw_pipe_aaline.c:aaline_line: the line as a quad lengthened by half a
 * pixel at each end and widened to the half width, with coordinates
 * (u, half width, v, half length), drawn as two triangles. */
static void aaline_line(struct fgl_context *ctx, const struct r_vertex *v0,
                        const struct r_vertex *v1)
{
   const struct r_state *rs = &ctx->_Raster;
   struct r_state aa;
   if (!aa_state(ctx, &aa, R_AA_LINE))
      return;

   /* aaline_first_line */
   const float half_width = rs->rast->line_width <= 1.0f ? 1.0f : 0.5f * rs->rast->line_width + 0.5f;

   const float dx = v1->pos[0] - v0->pos[0];
   const float dy = v1->pos[1] - v0->pos[1];
   const float a = atan2f(dy, dx);
   const float c_a = cosf(a), s_a = sinf(a);
   float half_length = 0.5f * sqrtf(dx * dx + dy * dy);
   if (half_length < 0.5f)
      half_length = 2.0f * half_length;   /* very short segments fade out */
   else
      half_length = half_length + 0.5f;
   const float t_w = half_width, t_l = 0.5f;

   /*  1 +---------------+ 3
    *    | *v0       v1* |
    *  0 +---------------+ 2   */
   struct r_vertex q[4] = { *v0, *v0, *v1, *v1 };
   q[0].pos[0] += (-t_l * c_a - t_w * s_a);
   q[0].pos[1] += (-t_l * s_a + t_w * c_a);
   q[1].pos[0] += (-t_l * c_a - -t_w * s_a);
   q[1].pos[1] += (-t_l * s_a + -t_w * c_a);
   q[2].pos[0] += (t_l * c_a - t_w * s_a);
   q[2].pos[1] += (t_l * s_a + t_w * c_a);
   q[3].pos[0] += (t_l * c_a - -t_w * s_a);
   q[3].pos[1] += (t_l * s_a + -t_w * c_a);
   static const float su[4] = { -1, 1, -1, 1 }, sv[4] = { -1, -1, 1, 1 };
   for (int i = 0; i < 4; i++) {
      q[i].attr[R_ATTR_AA][0] = su[i] < 0 ? -half_width : half_width;
      q[i].attr[R_ATTR_AA][1] = half_width;
      q[i].attr[R_ATTR_AA][2] = sv[i] < 0 ? -half_length : half_length;
      q[i].attr[R_ATTR_AA][3] = half_length;
   }
   fgl_raster_triangle(ctx, &aa, &q[2], &q[1], &q[0]);
   fgl_raster_triangle(ctx, &aa, &q[3], &q[1], &q[2]);
}

/* The stage after stipple: the aaline quad or llvmpipe's line. */
static void line_raster(struct fgl_context *ctx, const struct r_vertex *v0,
                        const struct r_vertex *v1)
{
   if (ctx->Line.SmoothFlag) {
      t_lin_flush_tris(ctx);
      vbuf_flush(ctx, false);   /* vbuf_first_tri: the aaline quad is triangles */
      aaline_line(ctx, v0, v1);
   } else
      vbuf_add(ctx, T_VBUF_LINES, v0, v1);
}

/* draw_pipe_stipple.c:screen_interp: every output, position (window
 * coordinates and 1/w) included, lerped linearly */
static void screen_interp(const struct r_state *rs, struct r_vertex *dst, float t,
                          const struct r_vertex *v0, const struct r_vertex *v1)
{
   for (int i = 0; i < 4; i++)
      dst->pos[i] = v0->pos[i] + t * (v1->pos[i] - v0->pos[i]);
   for (int a = 0; a < rs->fs->num_attribs; a++)
      for (int c = 0; c < 4; c++)
         dst->attr[a][c] = v0->attr[a][c] + t * (v1->attr[a][c] - v0->attr[a][c]);
}

/* draw_pipe_stipple.c:emit_segment */
static void emit_segment(struct fgl_context *ctx, const struct r_vertex *v0,
                         const struct r_vertex *v1, float t0, float t1)
{
   const struct r_state *rs = &ctx->_Raster;
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
   line_raster(ctx, a, b);
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
   /* the oracle's int conversion of ceilf(length): INT32_MIN for a finite
    * length past INT32_MAX (ORACLE-NOTES.md "A stippled line's length in
    * pixels"); in C that conversion is undefined, hence the range check */
   if (!isfinite(length))
      intlength = 0;
   else {
      const float c = ceilf(length);
      intlength = c < 2147483648.0f ? (int)c : INT32_MIN;
   }

   float start = 0;
   bool state = false;
   /* stipple_test(counter + i) for i = 0 .. intlength - 1, taken a run of
    * equal bits at a time: the bit changes only where (counter + i) /
    * factor does (and where counter + i wraps), so only there can a
    * segment start or end */
   for (int i = 0; i < intlength;) {
      const unsigned ci = ctx->StippleCounter + (unsigned)i;
      const bool result = stipple_test(ci, pattern, factor);
      if (result != state) {
         if (state)
            emit_segment(ctx, v0, v1, start / length, (float)i / length);
         else
            start = (float)i;
         state = result;
      }
      /* the next i whose bit may differ: past this quotient's values and
       * those of the next quotients with the same bit, never past a wrap
       * of counter + i */
      const unsigned q = ci / factor;
      unsigned k = 1;
      while (k < 16 && (((pattern >> ((q + k) & 0xfu)) & 1u) != 0) == result)
         k++;
      uint64_t step = (uint64_t)k * factor - ci % factor;
      if (step > (uint64_t)UINT32_MAX - ci + 1)
         step = (uint64_t)UINT32_MAX - ci + 1;
      if (step > (uint64_t)(intlength - i))
         step = (uint64_t)(intlength - i);
      i += (int)step;
   }
   if (state && start < length)
      emit_segment(ctx, v0, v1, start / length, 1.0f);

   ctx->StippleCounter += (unsigned)intlength;
}

void t_line(struct fgl_context *ctx, const struct t_vertex *v0, const struct t_vertex *v1,
            bool first, bool pipeline)
{
   const struct r_state *rs = &ctx->_Raster;
   struct t_vertex c[2];
   if (!t_clip_line(ctx, v0, v1, c))
      return;   /* the stipple stage does not see it: no counter reset */
   if (ctx->RenderMode != GL_RENDER) {
      /* the feedback draw context's flatshade stage runs only with
       * unfilled polygons (dp->flatshade there) */
      /* [S: draw_pipe_clip.c:do_clip_line] a new end is the clip stage's
       * temporary vertex 0 or 1, with the provoking vertex's flat values */
      if (v0->mask)
         t_feedback_clip_slot(ctx, &c[0], 0, false);
      if (v1->mask)
         t_feedback_clip_slot(ctx, &c[1], 1, false);
      if (ctx->_DrawPipeline.flatshade)
         t_copy_flat(rs, &c[0].r, &c[1].r);
      t_feedback_line(ctx, &c[0].r, &c[1].r);
      return;
   }

   /* st_atom_rasterizer.c: an all-ones pattern disables stippling */
   const bool stipple = ctx->_DrawPipeline.line_stipple;
   if (stipple || ctx->Line.SmoothFlag) {
      /* the flatshade stage runs first (precalc_flat): both ends get the
       * provoking vertex's flat attributes, so the stipple lerp keeps them
       * and the aaline quad's provoking vertices have them */
      t_copy_flat(rs, &c[0].r, &c[1].r);
   }
   /* (stipple and smooth lines need draw's pipeline) */
   pipeline_setup(ctx, pipeline || stipple || ctx->Line.SmoothFlag);
   if (stipple)
      stipple_line(ctx, &c[0].r, &c[1].r, first);
   else
      line_raster(ctx, &c[0].r, &c[1].r);
   pipeline_setup(ctx, false);
}

void t_unfilled_line(struct fgl_context *ctx, const struct r_vertex *v0,
                     const struct r_vertex *v1)
{
   /* unfilled's lines carry no DRAW_PIPE_RESET_STIPPLE (the triangle's
    * reset went through reset_stipple_counter) */
   if (ctx->RenderMode != GL_RENDER) {
      t_feedback_line(ctx, v0, v1);
      return;
   }
   pipeline_setup(ctx, true);
   if (ctx->_DrawPipeline.line_stipple)
      stipple_line(ctx, v0, v1, false);
   else
      line_raster(ctx, v0, v1);
   pipeline_setup(ctx, false);
}
