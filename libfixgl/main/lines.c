/*
 * Line state (GL_LINE_BIT): glLineWidth, glLineStipple, GL_LINE_SMOOTH and
 * GL_LINE_STIPPLE (main/enable.c).
 * [S: mesa/main/lines.c:line_width, _mesa_LineStipple, _mesa_init_line]
 *
 * The width is stored as given; the state tracker clamps it to
 * [1, 255] when drawing (st_atom_rasterizer.c), which state.c derives into
 * r_state.
 */
#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_line(struct fgl_context *ctx)
{
   ctx->Line.Width = 1.0f;
   ctx->Line.SmoothFlag = false;
   ctx->Line.StippleFlag = false;
   ctx->Line.StipplePattern = 0xffff;
   ctx->Line.StippleFactor = 1;
}

void GLAPIENTRY glLineWidth(GLfloat width)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, LineWidth, width);
   /* not in Mesa's begin/end dispatch table: INVALID_OPERATION there */
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* an unchanged width cannot be an error */
   if (ctx->Line.Width == width)
      return;
   if (width <= 0.0f) {       /* NaN passes, as in Mesa */
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_LINE);
   ctx->Line.Width = width;
}

void GLAPIENTRY glLineStipple(GLint factor, GLushort pattern)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, LineStipple, factor, pattern);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   factor = factor < 1 ? 1 : factor > 256 ? 256 : factor;
   if (ctx->Line.StippleFactor == factor && ctx->Line.StipplePattern == pattern)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_LINE);
   ctx->Line.StippleFactor = factor;
   ctx->Line.StipplePattern = pattern;
}
