/*
 * Lighting state (GL_LIGHTING_BIT).  So far: glShadeModel.
 */
#include "main/groups.h"

void fgl_init_light(struct fgl_context *ctx)
{
   ctx->Light.ShadeModel = GL_SMOOTH;
}

void GLAPIENTRY glShadeModel(GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Light.ShadeModel == mode)
      return;
   if (mode != GL_FLAT && mode != GL_SMOOTH) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
   ctx->Light.ShadeModel = mode;
}
