/*
 * Derived state: one ordered validation pass before drawing.
 *
 * Order: matrices (analysis, then the MVP product), the lighting space
 * and light vectors (which need the analysed modelview), viewport
 * transform, then the raster core's state, which reads the framebuffer and
 * the per-fragment state.
 */
#include <string.h>

#include "context.h"
#include "main/groups.h"

void fgl_update_state(struct fgl_context *ctx)
{
   const unsigned dirty = ctx->NewState;
   if (!dirty)
      return;

   if (dirty & (FGL_NEW_MODELVIEW | FGL_NEW_PROJECTION)) {
      /* update_modelview_project: analyse both, then P * MV */
      fgl_matrix_analyse(ctx->ModelviewStack.Top);
      fgl_matrix_analyse(ctx->ProjectionStack.Top);
      fgl_matrix_mul_matrix(&ctx->_ModelProjectMatrix, ctx->ProjectionStack.Top,
                            ctx->ModelviewStack.Top);
   }

   if (dirty & (FGL_NEW_MODELVIEW | FGL_NEW_LIGHT))
      fgl_update_lighting(ctx);

   if (dirty & (FGL_NEW_VIEWPORT | FGL_NEW_BUFFERS)) {
      /* _mesa_get_viewport_xform, then the state tracker's flip to the
       * y-down window buffer (llvmpipe-facts.md §0) */
      const struct fgl_viewport_attrib *vp = &ctx->Viewport;
      const float half_w = 0.5f * (float)vp->Width;
      const float half_h = 0.5f * (float)vp->Height;
      const float fb_h = ctx->DrawBuffer ? (float)ctx->DrawBuffer->Height : 0.0f;
      ctx->_ViewportScale[0] = half_w;
      ctx->_ViewportTranslate[0] = half_w + (float)vp->X;
      ctx->_ViewportScale[1] = -half_h;
      ctx->_ViewportTranslate[1] = fb_h - (half_h + (float)vp->Y);
      const double n = vp->Near, f = vp->Far;   /* computed in double */
      ctx->_ViewportScale[2] = (float)(0.5 * (f - n));
      ctx->_ViewportTranslate[2] = (float)(0.5 * (n + f));
   }

   if (dirty & (FGL_NEW_CLIP | FGL_NEW_PROJECTION))
      fgl_update_clip_planes(ctx);

   if (dirty & (FGL_NEW_BUFFERS | FGL_NEW_DEPTH | FGL_NEW_LIGHT | FGL_NEW_POLYGON)) {
      struct r_state *rs = &ctx->_Raster;
      const struct fgl_framebuffer *fb = ctx->DrawBuffer;
      if (fb) {
         rs->color = fb->Color;
         rs->zs = fb->Depth ? fb->Depth : (void *)fb->Stencil;
         rs->zs_format = fb->ZSFormat;
         rs->width = fb->Width;
         rs->height = fb->Height;
         rs->x0 = 0;
         rs->y0 = 0;
         rs->x1 = fb->Width;
         rs->y1 = fb->Height;
      }
      const bool has_depth = fb && fb->DepthBits > 0;
      rs->depth_test = ctx->Depth.Test && has_depth;
      rs->depth_func = (enum r_func)(ctx->Depth.Func - GL_NEVER);
      rs->depth_write = ctx->Depth.Mask;
      /* colours: the lit front (and back, and secondary) colours, or the
       * vertex colour */
      const bool lit = ctx->Light.Enabled;
      const bool twoside = lit && ctx->Light.Model.TwoSide;
      rs->twoside = twoside;
      rs->color_sum = lit && ctx->Light.Model.ColorControl == GL_SEPARATE_SPECULAR_COLOR;
      rs->num_attribs = twoside ? 4 : rs->color_sum ? 2 : 1;
      rs->fs_inputs = 1u << R_FS_COLOR0 | (rs->color_sum ? 1u << R_FS_COLOR1 : 0u);
      /* GL's counter-clockwise is a positive snapped area in the y-down
       * window buffer (the state tracker's front_ccw for OSMesa) */
      rs->ccw_is_front = ctx->Polygon.FrontFace == GL_CCW;
      const GLenum cull = ctx->Polygon.CullFlag ? ctx->Polygon.CullFaceMode : GL_NONE;
      rs->cull_front = cull == GL_FRONT || cull == GL_FRONT_AND_BACK;
      rs->cull_back = cull == GL_BACK || cull == GL_FRONT_AND_BACK;
      /* flat_mask is set per batch by t_render_batch */

      /* llvmpipe_create_rasterizer_state: with unfilled polygons, the
       * polygon stipple, smooth points or smooth lines (or stippled lines:
       * not yet modelled) the draw module does two-sided colours and
       * polygon offset, else llvmpipe's setup does them; facing and
       * culling are decided by both (draw's cull stage, then the setup's
       * area sign).  Smooth points and lines are read through their
       * capability flags. */
      const struct fgl_polygon_attrib *pg = &ctx->Polygon;
      const bool unfilled = pg->FrontMode != GL_FILL || pg->BackMode != GL_FILL;
      double point_smooth = 0.0, line_smooth = 0.0;
      fgl_is_cap(ctx, GL_POINT_SMOOTH, &point_smooth);
      fgl_is_cap(ctx, GL_LINE_SMOOTH, &line_smooth);
      const bool need_pipeline = unfilled || pg->StippleFlag || point_smooth != 0.0 ||
                                 line_smooth != 0.0;
      const bool any_offset = pg->OffsetFill || pg->OffsetLine || pg->OffsetPoint;
      /* util_get_depth_format_mrd: 1/(2^bits - 1), D24 without a unorm
       * depth buffer; units scaled in double, then stored as float */
      const double mrd = fb && fb->DepthBits == 16 ? 1.0 / 65535.0 : 1.0 / 16777215.0;
      const float units = (float)((double)pg->OffsetUnits * mrd * 2.0);
      const bool lp_offset = any_offset && !need_pipeline;
      rs->offset_units = lp_offset ? units : 0.0f;
      rs->offset_scale = lp_offset ? pg->OffsetFactor : 0.0f;
      rs->twoside = twoside && !need_pipeline;

      /* the rows themselves: fgl_update_stipple, at draw time */
      rs->stipple = pg->StippleFlag;

      struct fgl_draw_pipeline *dp = &ctx->_DrawPipeline;
      /* draw_pipe_validate.c:draw_need_pipeline for triangles: stipple,
       * unfilled, or an offset enable or two-sided lighting left to draw */
      dp->always = unfilled || pg->StippleFlag || (need_pipeline && (any_offset || twoside));
      dp->twoside = twoside && need_pipeline;
      /* draw_pipe_offset.c:offset_first_tri: filled triangles are offset
       * only with GL_POLYGON_OFFSET_FILL */
      dp->offset = need_pipeline && pg->OffsetFill;
      dp->offset_units = units;
      dp->offset_scale = pg->OffsetFactor;
      dp->front_ccw = rs->ccw_is_front;
      dp->cull_front = rs->cull_front;
      dp->cull_back = rs->cull_back;
      /* draw_pipe_validate.c: the cull stage runs when a stage needs the
       * determinant or culling is on */
      dp->cull = dp->cull_front || dp->cull_back || unfilled ||
                 (need_pipeline && (any_offset || twoside));
   }

   ctx->NewState = 0;
}

/* [S: st_atom_stipple.c:st_update_polygon_stipple] At each draw, when the
 * pattern differs from the one last handed to the driver, it is inverted
 * for the y-down window buffer with the current window height:
 * dest[i] = src[(height - 1 - i) & 31].  A later change of the window
 * height alone (re-binding the context to a buffer of another height)
 * keeps the old inversion, despite the function's comment. */
void fgl_update_stipple(struct fgl_context *ctx)
{
   if (memcmp(ctx->_StipplePattern, ctx->PolygonStipple, sizeof(ctx->_StipplePattern)) == 0)
      return;
   memcpy(ctx->_StipplePattern, ctx->PolygonStipple, sizeof(ctx->_StipplePattern));
   const unsigned h = ctx->DrawBuffer ? (unsigned)ctx->DrawBuffer->Height : 0u;
   for (unsigned i = 0; i < 32; i++)
      ctx->_Raster.stipple_rows[i] = ctx->PolygonStipple[(h - 1 - i) & 0x1f];
}
