/*
 * Depth buffer state (GL_DEPTH_BUFFER_BIT): glDepthFunc, glDepthMask,
 * glClearDepth.  GL_DEPTH_TEST itself is in main/enable.c.
 */
#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_depth(struct fgl_context *ctx)
{
   ctx->Depth.Func = GL_LESS;
   ctx->Depth.Clear = 1.0;
   ctx->Depth.Test = false;
   ctx->Depth.Mask = true;
}

void GLAPIENTRY glDepthFunc(GLenum func)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, DepthFunc, func);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Depth.Func == func)
      return;
   if (func < GL_NEVER || func > GL_ALWAYS) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_DEPTH);
   ctx->Depth.Func = func;
}

void GLAPIENTRY glDepthMask(GLboolean flag)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, DepthMask, flag);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* the byte itself, not normalized [S: main/depth.c:_mesa_DepthMask]:
    * glGetIntegerv, glGetBooleanv and glGetDoublev return it as given */
   if (ctx->Depth.Mask == flag)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_DEPTH);
   ctx->Depth.Mask = flag;
}

void GLAPIENTRY glClearDepth(GLclampd depth)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ClearDepth, depth);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* marked for glPopAttrib even when unchanged; CLAMP(depth, 0.0, 1.0)
    * [S: main/depth.c:_mesa_ClearDepth]: NaN -> 0 */
   ctx->PopAttribState |= GL_DEPTH_BUFFER_BIT;
   ctx->Depth.Clear = depth > 0.0 ? (depth > 1.0 ? 1.0 : depth) : 0.0;
}
