/*
 * Derived state: one ordered validation pass before drawing.
 *
 * Order: matrices (analysis, then the MVP product), the lighting space
 * and light vectors (which need the analysed modelview), viewport
 * transform, then the raster core's state, which reads the framebuffer and
 * the per-fragment state.
 */
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
      rs->twoside = lit && ctx->Light.Model.TwoSide;
      rs->color_sum = lit && ctx->Light.Model.ColorControl == GL_SEPARATE_SPECULAR_COLOR;
      rs->num_attribs = rs->twoside ? 4 : rs->color_sum ? 2 : 1;
      rs->fs_inputs = 1u << R_FS_COLOR0 | (rs->color_sum ? 1u << R_FS_COLOR1 : 0u);
      /* GL's counter-clockwise is a positive snapped area in the y-down
       * window buffer (the state tracker's front_ccw for OSMesa) */
      rs->ccw_is_front = ctx->Polygon.FrontFace == GL_CCW;
      const GLenum cull = ctx->Polygon.CullFlag ? ctx->Polygon.CullFaceMode : GL_NONE;
      rs->cull_front = cull == GL_FRONT || cull == GL_FRONT_AND_BACK;
      rs->cull_back = cull == GL_BACK || cull == GL_FRONT_AND_BACK;
      /* flat_mask is set per batch by t_render_batch */
   }

   if (dirty & (FGL_NEW_POINT | FGL_NEW_LINE | FGL_NEW_LIGHT)) {
      /* lp_state_rasterizer.c: line stipple or smooth points/lines put
       * llvmpipe's two-sided lighting into draw (context.h) */
      const bool stipple = ctx->Line.StippleFlag && ctx->Line.StipplePattern != 0xffff;
      ctx->_DrawTwosideTris = (stipple || ctx->Point.SmoothFlag || ctx->Line.SmoothFlag) &&
                              ctx->Light.Enabled && ctx->Light.Model.TwoSide;
   }

   if (dirty & (FGL_NEW_POINT | FGL_NEW_LINE)) {
      /* st_atom_rasterizer.c: the size clamped to [Point.MinSize,
       * Point.MaxSize] = [0, 255], the width to [MinLineWidth(AA),
       * MaxLineWidth(AA)] = [1, 255], with Mesa's CLAMP(X, MIN, MAX) =
       * X > MIN ? (X > MAX ? MAX : X) : MIN, so NaN becomes MIN */
      struct r_state *rs = &ctx->_Raster;
      const float size = ctx->Point.Size, width = ctx->Line.Width;
      rs->point_size = size > 0.0f ? (size > FGL_MAX_POINT_SIZE ? FGL_MAX_POINT_SIZE : size) : 0.0f;
      rs->line_width = width > FGL_MIN_LINE_WIDTH
                     ? (width > FGL_MAX_LINE_WIDTH ? FGL_MAX_LINE_WIDTH : width)
                     : FGL_MIN_LINE_WIDTH;
   }

   ctx->NewState = 0;
}
