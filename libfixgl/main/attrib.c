/*
 * The client attribute stack: glPushClientAttrib, glPopClientAttrib
 * [S: main/attrib.c:_mesa_PushClientAttrib, _mesa_PopClientAttrib] for
 * GL_CLIENT_PIXEL_STORE_BIT (ctx->Pack, ctx->Unpack) and
 * GL_CLIENT_VERTEX_ARRAY_BIT (ctx->Array).  Other mask bits are kept in
 * the node and ignored, as Mesa does.  The server attribute stack
 * (glPushAttrib) comes later.
 */
#include "main/groups.h"

void GLAPIENTRY glPushClientAttrib(GLbitfield mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   /* not in the oracle's glBegin/glEnd dispatch table (generic_nop) */
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->ClientAttribStackDepth >= FGL_MAX_CLIENT_ATTRIB_STACK_DEPTH) {
      fgl_error(ctx, GL_STACK_OVERFLOW);
      return;
   }
   struct fgl_client_attrib_node *head = &ctx->ClientAttribStack[ctx->ClientAttribStackDepth];
   head->Mask = mask;
   if (mask & GL_CLIENT_PIXEL_STORE_BIT) {
      head->Pack = ctx->Pack;
      head->Unpack = ctx->Unpack;
   }
   if (mask & GL_CLIENT_VERTEX_ARRAY_BIT)
      head->Array = ctx->Array;
   ctx->ClientAttribStackDepth++;
}

void GLAPIENTRY glPopClientAttrib(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->ClientAttribStackDepth == 0) {
      fgl_error(ctx, GL_STACK_UNDERFLOW);
      return;
   }
   ctx->ClientAttribStackDepth--;
   const struct fgl_client_attrib_node *head =
      &ctx->ClientAttribStack[ctx->ClientAttribStackDepth];
   /* pixel store and arrays are read when used: no flush */
   if (head->Mask & GL_CLIENT_PIXEL_STORE_BIT) {
      ctx->Pack = head->Pack;
      ctx->Unpack = head->Unpack;
   }
   if (head->Mask & GL_CLIENT_VERTEX_ARRAY_BIT)
      ctx->Array = head->Array;
}
