/*
 * The stages of Mesa's draw pipeline after clipping, for triangles
 * (draw_pipe_validate.c:validate_pipeline decides which run; state.c
 * derives that choice into ctx->_DrawPipeline): cull (float determinant),
 * twoside, offset (latched per draw), flatshade, unfilled (GL_LINE: edges
 * v2->v0, v0->v1, v1->v2; GL_POINT: v0, v1, v2, each where the edge is
 * flagged; they continue as points and lines, t_linepoint.c), the line
 * stipple stage's counter restart, then llvmpipe's setup (r_triangle).
 * Only triangles of a draw that takes the pipeline come here
 * (t_clip_triangle); the others go straight to r_triangle.
 */
#include "tnl/t_pipeline.h"

#include <math.h>
#include <string.h>

#include "context.h"

/* The draw stages after clipping, for one triangle in window coordinates
 * (v2 provoking; flags: its T_EDGE_* bits already cleared where the edge's
 * first vertex has no edge flag, and T_RESET_STIPPLE), in
 * draw_pipe_validate.c:validate_pipeline's order: cull, twoside, offset,
 * flatshade, unfilled, then the line stipple stage and llvmpipe's setup. */
void t_draw_pipe_tri(struct fgl_context *ctx, const struct r_vertex *v0,
                     const struct r_vertex *v1, const struct r_vertex *v2, unsigned flags)
{
   const struct r_state *rs = &ctx->_Raster;
   const struct fgl_draw_pipeline *dp = &ctx->_DrawPipeline;
   const struct r_vertex *v[3] = { v0, v1, v2 };
   struct r_vertex tmp[3];
   float det = 0.0f;

   if (dp->cull) {
      /* [S: draw_pipe_cull.c:cull_tri] e = v0 - v2, f = v1 - v2,
       * det = cross(e, f).z; det < 0 is counter-clockwise (y-down); a zero
       * determinant counts as a back face.  The culled faces include those
       * the state tracker culls for a false current edge flag. */
      const float ex = v0->pos[0] - v2->pos[0], ey = v0->pos[1] - v2->pos[1];
      const float fx = v1->pos[0] - v2->pos[0], fy = v1->pos[1] - v2->pos[1];
      det = ex * fy - ey * fx;
      bool back = true;
      if (det != 0.0f)
         back = (det < 0.0f) != dp->front_ccw;
      if (back ? dp->cull_back || dp->edge_cull_back : dp->cull_front || dp->edge_cull_front)
         return;
   }
   if (dp->twoside && det * (dp->front_ccw ? -1.0f : 1.0f) < 0.0f) {
      /* [S: draw_pipe_twoside.c:twoside_tri, copy_bfc] back colours into
       * the front slots */
      for (int i = 0; i < 3; i++) {
         tmp[i] = *v[i];
         memcpy(tmp[i].attr[R_ATTR_COLOR0], v[i]->attr[R_ATTR_BCOLOR0], sizeof(tmp[i].attr[0]));
         memcpy(tmp[i].attr[R_ATTR_COLOR1], v[i]->attr[R_ATTR_BCOLOR1], sizeof(tmp[i].attr[0]));
         v[i] = &tmp[i];
      }
   }

   /* the fill mode of this face [S: draw_pipe_unfilled.c:unfilled_first_tri,
    * unfilled_tri: mode[det >= 0], mode[0] = front_ccw ? front : back] */
   const bool cw = det >= 0.0f;
   const GLenum mode = cw == dp->front_ccw ? dp->fill_back : dp->fill_front;

   if (dp->offset) {
      struct fgl_draw_offset_latch *ol = &ctx->_DrawOffset;
      if (!ol->latched) {
         /* [S: draw_pipe_offset.c:offset_first_tri] the first triangle
          * after a flush decides for the whole draw, by its face's fill
          * mode (the back mode when the modes differ and it is back-facing:
          * the same face rule as unfilled's) */
         GLenum fill_mode = dp->fill_front;
         if (dp->fill_back != dp->fill_front && (det < 0.0f) != dp->front_ccw)
            fill_mode = dp->fill_back;
         const bool on = fill_mode == GL_FILL ? dp->offset_fill
                       : fill_mode == GL_LINE ? dp->offset_line : dp->offset_point;
         ol->latched = true;
         ol->units = on ? dp->offset_units : 0.0f;
         ol->scale = on ? dp->offset_scale : 0.0f;
      }
      /* [S: draw_pipe_offset.c:do_offset_tri] per vertex, then saturated
       * (even with a zero offset) with Mesa's SATURATE = CLAMP(x, 0, 1) =
       * x > 0 ? (x > 1 ? 1 : x) : 0 (util/macros.h), so a NaN z becomes 0:
       * a zero-area face (det 0, inv_det infinite) has a NaN slope, and
       * NaN * 0 keeps the offset NaN even when the offset is off */
      const float inv_det = 1.0f / det;
      const float ex = v[0]->pos[0] - v[2]->pos[0], ey = v[0]->pos[1] - v[2]->pos[1];
      const float ez = v[0]->pos[2] - v[2]->pos[2];
      const float fx = v[1]->pos[0] - v[2]->pos[0], fy = v[1]->pos[1] - v[2]->pos[1];
      const float fz = v[1]->pos[2] - v[2]->pos[2];
      const float a = ey * fz - ez * fy;
      const float b = ez * fx - ex * fz;
      const float dzdx = fabsf(a * inv_det), dzdy = fabsf(b * inv_det);
      const float mult = (dzdx > dzdy ? dzdx : dzdy) * ol->scale;   /* MAX2 */
      const float zoffset = ol->units + mult;
      for (int i = 0; i < 3; i++) {
         if (v[i] != &tmp[i]) {
            tmp[i] = *v[i];
            v[i] = &tmp[i];
         }
         const float z = tmp[i].pos[2] + zoffset;
         tmp[i].pos[2] = z > 0.0f ? (z > 1.0f ? 1.0f : z) : 0.0f;   /* SATURATE */
      }
   }

   if (dp->flatshade && rs->flat_mask) {
      /* [S: draw_pipe_flatshade.c:flatshade_tri_2] the provoking vertex's
       * flat attributes on v0 and v1 */
      for (int i = 0; i < 2; i++) {
         if (v[i] != &tmp[i]) {
            tmp[i] = *v[i];
            v[i] = &tmp[i];
         }
         t_copy_flat(rs, &tmp[i], v[2]);
      }
   }

   if (dp->unfilled && mode != GL_FILL && rs->fs->phong) {
      /* GL_PHONG_WIN: the lines and points of an unfilled face are lit
       * with its face, which the vertices carry in R_ATTR_NORMAL's w (the
       * front-face input that draw injects for them when the fragment
       * shader reads gl_FrontFacing [S: draw_pipe_unfilled.c:
       * inject_front_face_info]: front iff det < 0 with front_ccw, det > 0
       * without) */
      const bool front = dp->front_ccw ? det < 0.0f : det > 0.0f;
      for (int i = 0; i < 3; i++) {
         if (v[i] != &tmp[i]) {
            tmp[i] = *v[i];
            v[i] = &tmp[i];
         }
         tmp[i].attr[R_ATTR_NORMAL][3] = front ? 1.0f : 0.0f;
      }
   }

   if (dp->unfilled && mode == GL_LINE) {
      /* [S: draw_pipe_unfilled.c:lines] the stipple counter restarts at a
       * primitive's first triangle; edges v2->v0, v0->v1, v1->v2 */
      if (flags & T_RESET_STIPPLE) {
         if (ctx->RenderMode != GL_RENDER)
            t_feedback_reset_stipple(ctx);
         else if (dp->line_stipple)
            ctx->StippleCounter = 0;
      }
      if (flags & T_EDGE_2)
         t_unfilled_line(ctx, v[2], v[0]);
      if (flags & T_EDGE_0)
         t_unfilled_line(ctx, v[0], v[1]);
      if (flags & T_EDGE_1)
         t_unfilled_line(ctx, v[1], v[2]);
      return;
   }
   if (dp->unfilled && mode == GL_POINT) {
      /* [S: draw_pipe_unfilled.c:points] v0, v1, v2 */
      for (int i = 0; i < 3; i++)
         if (flags & (T_EDGE_0 << i))
            t_unfilled_point(ctx, v[i]);
      return;
   }

   /* GL_SELECT, GL_FEEDBACK: the selection or feedback stage instead of
    * rasterization (which has no stipple stages before it) */
   if (ctx->RenderMode != GL_RENDER) {
      t_feedback_tri(ctx, v[0], v[1], v[2]);
      return;
   }

   /* [S: draw_pipe_stipple.c:stipple_reset_tri] the line stipple stage
    * restarts its counter on every triangle that reaches it */
   if (dp->line_stipple)
      ctx->StippleCounter = 0;
   /* the pstipple stage's first filled triangle of the draw */
   t_vbuf_filled_tri(ctx);
   /* [S: lp_draw_arrays.c:llvmpipe_draw_vbo, draw_flush; draw_pipe_vbuf.c]
    * the vbuf stage queues the pipeline's triangles and llvmpipe sets them
    * up when draw is flushed after draw_vbo restored the caller's MXCSR:
    * denormal plane derivatives are kept in setup (ORACLE-NOTES.md
    * "Interpolation"; not modelled: the vbuf's mid-draw flushes, buffer
    * full or a line or point after the triangle, which set up under
    * FTZ/DAZ) */
   ctx->_Raster.setup_mxcsr = dp->caller_mxcsr;
   if (!(ctx->_LinPairs && fgl_lin_binning(ctx) && t_lin_queue_tri(ctx, v[0], v[1], v[2])))
      fgl_raster_triangle(ctx, rs, v[0], v[1], v[2]);
   ctx->_Raster.setup_mxcsr = 0;
}
