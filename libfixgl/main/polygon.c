/*
 * Polygon state (GL_POLYGON_BIT) so far: glFrontFace, glCullFace and
 * GL_CULL_FACE (main/enable.c).  Facing is decided where llvmpipe decides
 * it, from the sign of the snapped triangle area in the raster core (also
 * for two-sided lighting).
 */
#include "main/groups.h"

void fgl_init_polygon(struct fgl_context *ctx)
{
   ctx->Polygon.FrontFace = GL_CCW;
   ctx->Polygon.CullFaceMode = GL_BACK;
   ctx->Polygon.CullFlag = false;
}

void GLAPIENTRY glFrontFace(GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
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
