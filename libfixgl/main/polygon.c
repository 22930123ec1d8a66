/*
 * Polygon state (GL_POLYGON_BIT, GL_POLYGON_STIPPLE_BIT): glFrontFace,
 * glCullFace, glPolygonMode, glPolygonOffset, glPolygonStipple and the
 * GL_CULL_FACE, GL_POLYGON_OFFSET_* and GL_POLYGON_STIPPLE enables
 * (main/enable.c).  Facing is decided where llvmpipe decides it, from the
 * sign of the snapped triangle area in the raster core (also for two-sided
 * lighting), or from draw's float determinant when the triangle goes
 * through the draw pipeline (tnl/t_clip.c).
 *
 * glPolygonMode's GL_LINE and GL_POINT are draw's unfilled stage
 * (tnl/t_clip.c pipeline_tri; state.c derives the modes the state tracker
 * hands to llvmpipe).
 */
#include <string.h>

#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_polygon(struct fgl_context *ctx)
{
   ctx->Polygon.FrontFace = GL_CCW;
   ctx->Polygon.CullFaceMode = GL_BACK;
   ctx->Polygon.CullFlag = false;
   ctx->Polygon.SmoothFlag = false;
   ctx->Polygon.FrontMode = GL_FILL;
   ctx->Polygon.BackMode = GL_FILL;
   ctx->Polygon.OffsetFactor = 0.0f;
   ctx->Polygon.OffsetUnits = 0.0f;
   ctx->Polygon.OffsetFill = false;
   ctx->Polygon.OffsetLine = false;
   ctx->Polygon.OffsetPoint = false;
   ctx->Polygon.StippleFlag = false;
   /* _mesa_init_polygon: the stipple starts all ones */
   memset(ctx->PolygonStipple, 0xff, sizeof(ctx->PolygonStipple));
   /* the rows the rasterizer stipples with before the state tracker first
    * hands it a pattern cover every pixel, while its copy to compare with
    * (_StipplePattern) starts all zero: a first glPolygonStipple of zeros
    * is no change to it and leaves the stipple covering everything
    * (case polygon/stipple_first_zeros) */
   memset(ctx->_StippleRows, 0xff, sizeof(ctx->_StippleRows));
}

void GLAPIENTRY glFrontFace(GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, FrontFace, mode);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Polygon.FrontFace == mode)
      return;
   if (mode != GL_CW && mode != GL_CCW) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_POLYGON);
   ctx->Polygon.FrontFace = mode;
}

void GLAPIENTRY glCullFace(GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, CullFace, mode);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Polygon.CullFaceMode == mode)
      return;
   if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_POLYGON);
   ctx->Polygon.CullFaceMode = mode;
}

/* [S: main/polygon.c:polygon_mode] the mode is checked first (llvmpipe has
 * no GL_FILL_RECTANGLE_NV), then the face; an unchanged value does not
 * flush. */
void GLAPIENTRY glPolygonMode(GLenum face, GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PolygonMode, face, mode);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   switch (face) {
   case GL_FRONT:
      if (ctx->Polygon.FrontMode == mode)
         return;
      FGL_FLUSH_VERTICES(ctx, FGL_NEW_POLYGON);
      ctx->Polygon.FrontMode = mode;
      break;
   case GL_FRONT_AND_BACK:
      if (ctx->Polygon.FrontMode == mode && ctx->Polygon.BackMode == mode)
         return;
      FGL_FLUSH_VERTICES(ctx, FGL_NEW_POLYGON);
      ctx->Polygon.FrontMode = mode;
      ctx->Polygon.BackMode = mode;
      break;
   case GL_BACK:
      if (ctx->Polygon.BackMode == mode)
         return;
      FGL_FLUSH_VERTICES(ctx, FGL_NEW_POLYGON);
      ctx->Polygon.BackMode = mode;
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
}

/* [S: main/polygon.c:_mesa_polygon_offset_clamp] no error case; equal
 * values (compared as floats: NaN never equal) do not flush. */
void GLAPIENTRY glPolygonOffset(GLfloat factor, GLfloat units)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PolygonOffset, factor, units);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Polygon.OffsetFactor == factor && ctx->Polygon.OffsetUnits == units)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_POLYGON);
   ctx->Polygon.OffsetFactor = factor;
   ctx->Polygon.OffsetUnits = units;
}

/* [S: main/polygon.c:_mesa_PolygonStipple, pack.c:_mesa_unpack_polygon_stipple]
 * The pattern is a 32x32 GL_BITMAP read with the unpack state (by default
 * rows of 4 bytes, bottom row first, most significant bit = leftmost
 * pixel); each row becomes a word with byte 0 in bits 24..31.  The flush
 * comes first, also for a NULL pattern, which is then ignored without an
 * error. */
void GLAPIENTRY glPolygonStipple(const GLubyte *mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag && mask) {
      /* save_PolygonStipple unpacks the pattern with the pixel-store state
       * of compile time; the replay unpacks the result again with the
       * state of its own time, as Mesa's does */
      static const struct fgl_pixelstore packed = { .Alignment = 1 };
      uint32_t rows[32];
      GLubyte bytes[128];
      fgl_unpack_stipple(&ctx->Unpack, mask, rows);
      fgl_pack_stipple(&packed, rows, bytes);
      if (!fgl_save_PolygonStipple(ctx, bytes, 128))
         return;
   }
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_POLYGON);
   if (!mask)
      return;
   fgl_unpack_stipple(&ctx->Unpack, mask, ctx->PolygonStipple);
}

/* [S: main/polygon.c:_mesa_GetnPolygonStippleARB, pack.c:_mesa_pack_polygon_stipple]
 * with the pack state; a NULL destination is ignored. */
void GLAPIENTRY glGetPolygonStipple(GLubyte *mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (!mask)
      return;
   fgl_pack_stipple(&ctx->Pack, ctx->PolygonStipple, mask);
}
