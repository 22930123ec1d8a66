/*
 * glViewport and glDepthRange (GL_VIEWPORT_BIT).  Values are clamped like
 * Mesa's: size to GL_MAX_VIEWPORT_DIMS, origin to GL_VIEWPORT_BOUNDS_RANGE,
 * depth range to [0,1].
 */
#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_viewport(struct fgl_context *ctx)
{
   ctx->Viewport.X = 0;
   ctx->Viewport.Y = 0;
   ctx->Viewport.Width = 0;
   ctx->Viewport.Height = 0;
   ctx->Viewport.Near = 0.0f;
   ctx->Viewport.Far = 1.0f;
}

static int clampi(int v, int lo, int hi)
{
   return v < lo ? lo : (v > hi ? hi : v);
}

void fgl_set_viewport(struct fgl_context *ctx, int x, int y, int width, int height)
{
   width = width < FGL_MAX_VIEWPORT_SIZE ? width : FGL_MAX_VIEWPORT_SIZE;
   height = height < FGL_MAX_VIEWPORT_SIZE ? height : FGL_MAX_VIEWPORT_SIZE;
   x = clampi(x, FGL_VIEWPORT_BOUNDS_MIN, FGL_VIEWPORT_BOUNDS_MAX);
   y = clampi(y, FGL_VIEWPORT_BOUNDS_MIN, FGL_VIEWPORT_BOUNDS_MAX);
   struct fgl_viewport_attrib *vp = &ctx->Viewport;
   if (vp->X == x && vp->Y == y && vp->Width == width && vp->Height == height)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_VIEWPORT);
   vp->X = x;
   vp->Y = y;
   vp->Width = width;
   vp->Height = height;
}

void GLAPIENTRY glViewport(GLint x, GLint y, GLsizei width, GLsizei height)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, Viewport, x, y, width, height);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (width < 0 || height < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   fgl_set_viewport(ctx, x, y, width, height);
}

/* SATURATE = Mesa's CLAMP(x, 0, 1) (util/macros.h): NaN becomes 0 */
static double clampd(double v)
{
   return v > 0.0 ? (v > 1.0 ? 1.0 : v) : 0.0;
}

void GLAPIENTRY glDepthRange(GLclampd nearval, GLclampd farval)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, DepthRange, nearval, farval);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* set_depth_range_no_notify [S: main/viewport.c] compares the stored
    * floats with the unclamped double arguments: only values a float
    * holds exactly and inside [0,1] count as unchanged (0.2 flushes every
    * time) */
   if (ctx->Viewport.Near == nearval && ctx->Viewport.Far == farval)
      return;
   const float n = (float)clampd(nearval), f = (float)clampd(farval);
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_VIEWPORT);
   ctx->Viewport.Near = n;
   ctx->Viewport.Far = f;
}
