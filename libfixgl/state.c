/*
 * Derived state: one ordered validation pass before drawing.
 *
 * Order: matrices (analysis, then the MVP product), the lighting space
 * and light vectors (which need the analysed modelview), viewport
 * transform, then the raster core's state, which reads the framebuffer and
 * the per-fragment state.
 */
#include <math.h>
#include <string.h>

#include "context.h"
#include "main/groups.h"

/* The fog blend's uniforms (prog_statevars.c: STATE_FOG_PARAMS_OPTIMIZED,
 * computed on the CPU in this order; STATE_FOG_COLOR, clamped for a
 * fixed-point colour buffer) and the fog coordinate as an input of the
 * fragment program (ff_fragment_shader.cpp: key->fog_mode from
 * _PackedEnabledMode). */
void fgl_fog_uniforms(const struct fgl_context *ctx, struct r_state *rs)
{
   const struct fgl_fog_attrib *fog = &ctx->Fog;
   /* start == end gives val = 1, so f = c - end */
   const float val = fog->End == fog->Start ? 1.0f : -1.0f / (fog->End - fog->Start);
   rs->fog_params[0] = val;
   rs->fog_params[1] = fog->End * -val;
   /* density times double constants (M_LOG2E, 1/sqrt(ln 2)), then float */
   rs->fog_params[2] = (float)(fog->Density * 1.4426950408889634074);
   rs->fog_params[3] = (float)(fog->Density * 1.201122408786449815);
   for (int c = 0; c < 3; c++)
      rs->fog_color[c] = fog->Color[c];
}

static void update_fog(const struct fgl_context *ctx, struct r_state *rs)
{
   const struct fgl_fog_attrib *fog = &ctx->Fog;
   if (!fog->Enabled) {
      rs->fog_mode = R_FOG_NONE;
      return;
   }
   rs->fog_mode = fog->Mode == GL_LINEAR ? R_FOG_LINEAR
                : fog->Mode == GL_EXP    ? R_FOG_EXP : R_FOG_EXP2;
   fgl_fog_uniforms(ctx, rs);
   rs->fs_inputs |= 1u << R_FS_FOG;
   rs->num_attribs = R_ATTR_FOG + 1;
}

/* GL comparison, stencil op, blend factor and equation enums to the raster
 * core's (st_atom_depth.c, st_atom_blend.c translate them the same way). */
static enum r_stencil_op stencil_op(GLenum op)
{
   switch (op) {
   case GL_ZERO:      return R_STENCIL_ZERO;
   case GL_REPLACE:   return R_STENCIL_REPLACE;
   case GL_INCR:      return R_STENCIL_INCR;
   case GL_DECR:      return R_STENCIL_DECR;
   case GL_INCR_WRAP: return R_STENCIL_INCR_WRAP;
   case GL_DECR_WRAP: return R_STENCIL_DECR_WRAP;
   case GL_INVERT:    return R_STENCIL_INVERT;
   case GL_KEEP:
   default:           return R_STENCIL_KEEP;
   }
}

static enum r_blend_factor blend_factor(GLenum f)
{
   switch (f) {
   case GL_ZERO:                     return R_BF_ZERO;
   case GL_SRC_COLOR:                return R_BF_SRC_COLOR;
   case GL_ONE_MINUS_SRC_COLOR:      return R_BF_INV_SRC_COLOR;
   case GL_SRC_ALPHA:                return R_BF_SRC_ALPHA;
   case GL_ONE_MINUS_SRC_ALPHA:      return R_BF_INV_SRC_ALPHA;
   case GL_DST_COLOR:                return R_BF_DST_COLOR;
   case GL_ONE_MINUS_DST_COLOR:      return R_BF_INV_DST_COLOR;
   case GL_DST_ALPHA:                return R_BF_DST_ALPHA;
   case GL_ONE_MINUS_DST_ALPHA:      return R_BF_INV_DST_ALPHA;
   case GL_SRC_ALPHA_SATURATE:       return R_BF_SRC_ALPHA_SATURATE;
   case GL_CONSTANT_COLOR:           return R_BF_CONST_COLOR;
   case GL_ONE_MINUS_CONSTANT_COLOR: return R_BF_INV_CONST_COLOR;
   case GL_CONSTANT_ALPHA:           return R_BF_CONST_ALPHA;
   case GL_ONE_MINUS_CONSTANT_ALPHA: return R_BF_INV_CONST_ALPHA;
   /* The fixed-function fragment program writes no second colour: the
    * oracle blends with an unwritten output (different garbage per run and
    * thread count, ORACLE-NOTES.md), fixgl with a second colour of 0. */
   case GL_SRC1_COLOR:
   case GL_SRC1_ALPHA:               return R_BF_ZERO;
   case GL_ONE_MINUS_SRC1_COLOR:
   case GL_ONE_MINUS_SRC1_ALPHA:     return R_BF_ONE;
   case GL_ONE:
   default:                          return R_BF_ONE;
   }
}

static enum r_blend_eq blend_eq(GLenum mode)
{
   switch (mode) {
   case GL_FUNC_SUBTRACT:         return R_BLEND_SUBTRACT;
   case GL_FUNC_REVERSE_SUBTRACT: return R_BLEND_REVERSE_SUBTRACT;
   case GL_MIN:                   return R_BLEND_MIN;
   case GL_MAX:                   return R_BLEND_MAX;
   case GL_FUNC_ADD:
   default:                       return R_BLEND_ADD;
   }
}

/* The per-fragment operations of the raster state: scissor (the draw
 * region), alpha test, stencil, depth, blending, logic op, colour mask. */
static void update_fragment_ops(struct fgl_context *ctx, struct r_state *rs)
{
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;

   /* scissor: the draw region [S: st_atom_scissor.c:st_update_scissor;
    * lp_setup.c try_update_scene_state draw_regions] */
   int region[4];
   fgl_scissor_draw_region(ctx, region);
   rs->x0 = region[0];
   rs->y0 = region[1];
   rs->x1 = region[2];
   rs->y1 = region[3];

   /* depth and stencil only with their buffers [S: st_atom_depth.c] */
   const bool has_depth = fb && fb->DepthBits > 0;
   const bool has_stencil = fb && fb->StencilBits > 0;
   rs->depth_test = ctx->Depth.Test && has_depth;
   rs->depth_func = (enum r_func)(ctx->Depth.Func - GL_NEVER);
   rs->depth_write = ctx->Depth.Mask;

   const struct fgl_stencil_attrib *st = &ctx->Stencil;
   rs->stencil_test = st->Enabled && has_stencil;
   rs->stencil_func = (enum r_func)(st->Func - GL_NEVER);
   rs->stencil_ref = (uint8_t)fgl_stencil_ref(ctx);
   rs->stencil_valuemask = (uint8_t)(st->ValueMask & 0xffu);
   rs->stencil_writemask = (uint8_t)(st->WriteMask & 0xffu);
   rs->stencil_fail = stencil_op(st->FailFunc);
   rs->stencil_zfail = stencil_op(st->ZFailFunc);
   rs->stencil_zpass = stencil_op(st->ZPassFunc);

   /* alpha test: the reference clamped (lp_build_clamp: NaN -> 1) and
    * converted to unorm8 [S: lp_bld_alpha.c:lp_build_alpha_test] */
   const struct fgl_colorbuffer_attrib *c = &ctx->Color;
   rs->alpha_test = c->AlphaEnabled;
   rs->alpha_func = (enum r_func)(c->AlphaFunc - GL_NEVER);
   rs->alpha_ref = (uint8_t)lrintf(r_clamp01(c->AlphaRef) * 255.0f);
   /* OSMESA_RGB buffers are R8G8B8, not an rgba8 variant: float compare */
   rs->alpha_test_float = fb && fb->AlphaBits == 0;
   rs->alpha_ref_float = c->AlphaRef;

   /* blending [S: st_atom_blend.c:st_update_blend]: the logic op wins;
    * MIN and MAX use factors ONE; blend colour by float_to_ubyte
    * (lp_setup.c:try_update_scene_state) */
   rs->logic_op = c->LogicOpEnabled;
   rs->logic_op_mode = c->LogicOp - GL_CLEAR;
   /* glDrawBuffer(GL_NONE): no colour buffer is bound (Mesa's
    * _NumColorDrawBuffers 0, [S: main/buffers.c:_mesa_drawbuffers],
    * st_atom_framebuffer.c:st_update_framebuffer_state binds no cbuf), the
    * fragments still reach depth and stencil (ORACLE-NOTES.md "Queries,
    * strings, buffers") */
   rs->color_mask = c->DrawBuffer == GL_NONE ? 0u : c->ColorMask & 0xfu;
   rs->blend = !c->LogicOpEnabled && c->BlendEnabled && rs->color_mask != 0;
   rs->blend_eq = blend_eq(c->BlendEquation);
   const bool minmax = rs->blend_eq == R_BLEND_MIN || rs->blend_eq == R_BLEND_MAX;
   rs->blend_src = minmax ? R_BF_ONE : blend_factor(c->BlendSrc);
   rs->blend_dst = minmax ? R_BF_ONE : blend_factor(c->BlendDst);
   for (int i = 0; i < 4; i++)
      rs->blend_color[i] = r_float_to_unorm8(c->BlendColor[i]);
   rs->dst_alpha_one = fb && fb->AlphaBits == 0;

   rs->full_ops = rs->alpha_test || rs->stencil_test || rs->blend ||
                  rs->logic_op || rs->color_mask != 0xfu;
}

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

   if (dirty & FGL_NEW_TEXTURE)
      fgl_update_texture_state(ctx);

   if (dirty & (FGL_NEW_CLIP | FGL_NEW_PROJECTION))
      fgl_update_clip_planes(ctx);

   if (dirty & (FGL_NEW_BUFFERS | FGL_NEW_DEPTH | FGL_NEW_LIGHT | FGL_NEW_POLYGON |
                FGL_NEW_FOG | FGL_NEW_SCISSOR | FGL_NEW_STENCIL | FGL_NEW_COLOR |
                FGL_NEW_POINT | FGL_NEW_LINE | FGL_NEW_RENDERMODE | FGL_NEW_TEXTURE)) {
      struct r_state *rs = &ctx->_Raster;
      const struct fgl_framebuffer *fb = ctx->DrawBuffer;
      if (fb) {
         rs->color = fb->Color;
         rs->zs = fb->Depth ? fb->Depth : (void *)fb->Stencil;
         rs->zs_format = fb->ZSFormat;
         rs->width = fb->Width;
         rs->height = fb->Height;
      }
      update_fragment_ops(ctx, rs);
      /* colours: the lit front (and back, and secondary) colours, or the
       * vertex colour */
      const bool lit = ctx->Light.Enabled;
      const bool twoside = lit && ctx->Light.Model.TwoSide;
      rs->twoside = twoside;
      rs->color_sum = lit && ctx->Light.Model.ColorControl == GL_SEPARATE_SPECULAR_COLOR;
      rs->num_attribs = twoside ? 4 : rs->color_sum ? 2 : 1;
      rs->fs_inputs = 1u << R_FS_COLOR0 | (rs->color_sum ? 1u << R_FS_COLOR1 : 0u);
      /* fog: the fragment program reads the fog coordinate, which the
       * vertex stage writes to its own slot after the colours */
      update_fog(ctx, rs);
      /* texture coordinates: a slot per unit up to the last enabled one
       * (ffvertex_prog.c writes the coordinate of every enabled unit) */
      for (unsigned u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
         if (ctx->_EnabledTexUnits & (1u << u)) {
            rs->fs_inputs |= 1u << (R_FS_TEX0 + u);
            rs->num_attribs = R_ATTR_TEX0 + (int)u + 1;
         }
      }
      /* GL's counter-clockwise is a positive snapped area in the y-down
       * window buffer (the state tracker's front_ccw for OSMesa) */
      rs->ccw_is_front = ctx->Polygon.FrontFace == GL_CCW;
      const GLenum cull = ctx->Polygon.CullFlag ? ctx->Polygon.CullFaceMode : GL_NONE;
      rs->cull_front = cull == GL_FRONT || cull == GL_FRONT_AND_BACK;
      rs->cull_back = cull == GL_BACK || cull == GL_FRONT_AND_BACK;
      /* flat_mask is set per batch by t_render_batch */

      /* [S: lp_state_rasterizer.c:llvmpipe_create_rasterizer_state] with
       * unfilled polygons, smooth points or lines, line stipple or the
       * polygon stipple (need_pipeline) the draw module does two-sided
       * colours and polygon offset (clear_flags on llvmpipe's copy), else
       * llvmpipe's setup does them; facing and culling are decided by both
       * (draw's cull stage, then the setup's area sign).  The state
       * tracker turns an all-ones line stipple pattern off
       * (st_atom_rasterizer.c). */
      const struct fgl_polygon_attrib *pg = &ctx->Polygon;
      /* [S: st_atom_rasterizer.c] the fill modes, simplified when culling
       * is on: a culled front face takes the back mode and a culled back
       * face the front mode (both the back mode with GL_FRONT_AND_BACK) */
      GLenum fill_front = pg->FrontMode, fill_back = pg->BackMode;
      if (rs->cull_front)
         fill_front = fill_back;
      if (rs->cull_back)
         fill_back = fill_front;
      const bool unfilled = fill_front != GL_FILL || fill_back != GL_FILL;
      const bool line_stipple = ctx->Line.StippleFlag && ctx->Line.StipplePattern != 0xffff;
      const bool need_pipeline = unfilled || pg->StippleFlag || ctx->Point.SmoothFlag ||
                                 ctx->Line.SmoothFlag || line_stipple;
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
      /* draw_pipe_offset.c:offset_first_tri: the enable of the fill mode
       * of the first triangle's face (t_clip.c) */
      dp->offset = need_pipeline && any_offset;
      dp->offset_fill = pg->OffsetFill;
      dp->offset_line = pg->OffsetLine;
      dp->offset_point = pg->OffsetPoint;
      dp->offset_units = units;
      dp->offset_scale = pg->OffsetFactor;
      /* draw_pipe_validate.c: precalc_flat (wide lines never: llvmpipe's
       * threshold is 10000) */
      dp->flatshade = unfilled || line_stipple || ctx->Line.SmoothFlag;
      dp->unfilled = unfilled;
      dp->fill_front = fill_front;
      dp->fill_back = fill_back;
      dp->front_ccw = rs->ccw_is_front;
      dp->cull_front = rs->cull_front;
      dp->cull_back = rs->cull_back;
      /* draw_pipe_validate.c: the cull stage runs when a stage needs the
       * determinant or culling is on */
      dp->cull = dp->cull_front || dp->cull_back || unfilled ||
                 (need_pipeline && (any_offset || twoside));
      /* the line stipple stage: triangles and points that reach it restart
       * the counter (draw_pipe_stipple.c) */
      dp->line_stipple = line_stipple;

      if (ctx->RenderMode != GL_RENDER) {
         /* GL_SELECT and GL_FEEDBACK draw with the state tracker's own
          * draw context (st_draw_feedback.c, st_draw.c:st_get_draw_context),
          * given the full rasterizer state: it has no vbuf backend, so
          * every primitive takes the pipeline (draw_pt.c: PT_PIPELINE when
          * !draw->render); draw_pipe_validate.c:validate_pipeline then
          * inserts twoside and offset whenever enabled, flatshade only for
          * unfilled polygons (line stipple, aaline and wide lines are
          * disabled or not installed there), the cull stage for unfilled,
          * offset, two-sided or culling.  Its mrd is never set
          * (draw_set_zs_format is llvmpipe's), so the offset units are 0:
          * units * 0.0 * 2 in double (draw_pipe_offset.c:offset_first_tri) */
         dp->always = true;
         dp->twoside = twoside;
         dp->offset = any_offset;
         dp->offset_units = (float)((double)pg->OffsetUnits * 0.0 * 2.0);
         dp->flatshade = unfilled;
         dp->cull = dp->cull_front || dp->cull_back || unfilled || any_offset || twoside;
         dp->line_stipple = false;
      }
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
