/*
 * glEnable, glDisable, glIsEnabled.  Each capability belongs to the group
 * that owns its state; this file only dispatches.  Capabilities of features
 * not implemented yet raise GL_INVALID_ENUM rather than being silently
 * accepted.
 */
#include <stddef.h>

#include "main/groups.h"

/* Returns a pointer to the flag for cap and its dirty bit, or NULL. */
static bool *cap_flag(struct fgl_context *ctx, GLenum cap, unsigned *dirty)
{
   switch (cap) {
   case GL_DEPTH_TEST:
      *dirty = FGL_NEW_DEPTH;
      return &ctx->Depth.Test;
   case GL_DITHER:
      *dirty = 0;
      return &ctx->Color.Dither;
   default:
      return NULL;
   }
}

static void set_enable(GLenum cap, bool state)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   unsigned dirty = 0;
   bool *flag = cap_flag(ctx, cap, &dirty);
   if (!flag) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (*flag == state)
      return;
   FGL_FLUSH_VERTICES(ctx, dirty);
   *flag = state;
}

void GLAPIENTRY glEnable(GLenum cap)
{
   set_enable(cap, true);
}

void GLAPIENTRY glDisable(GLenum cap)
{
   set_enable(cap, false);
}

GLboolean GLAPIENTRY glIsEnabled(GLenum cap)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return GL_FALSE;
   ASSERT_OUTSIDE_BEGIN_END_RET(ctx, GL_FALSE);
   unsigned dirty;
   const bool *flag = cap_flag(ctx, cap, &dirty);
   if (!flag) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return GL_FALSE;
   }
   return *flag ? GL_TRUE : GL_FALSE;
}
