/*
 * Point state (GL_POINT_BIT): glPointSize and GL_POINT_SMOOTH
 * (main/enable.c).  [S: mesa/main/points.c:point_size, _mesa_init_point]
 *
 * The size is stored as given; the state tracker clamps it to
 * [Point.MinSize, Point.MaxSize] = [0, 255] when drawing
 * (st_atom_rasterizer.c), which state.c derives into r_state.
 */
#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_point(struct fgl_context *ctx)
{
   ctx->Point.Size = 1.0f;
   ctx->Point.SmoothFlag = false;
}

void GLAPIENTRY glPointSize(GLfloat size)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PointSize, size);
   /* not in Mesa's begin/end dispatch table: INVALID_OPERATION there */
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* an unchanged size cannot be an error */
   if (ctx->Point.Size == size)
      return;
   if (size <= 0.0f) {        /* NaN passes, as in Mesa */
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_POINT);
   ctx->Point.Size = size;
}
