/*
 * Stencil state (GL_STENCIL_BUFFER_BIT): glStencilFunc, glStencilOp,
 * glStencilMask, glClearStencil.  GL_STENCIL_TEST itself is in
 * main/enable.c.  GL 1.x has one state for both faces (Mesa's front and
 * back copies are always equal here, so it draws single-sided).
 */
#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_stencil(struct fgl_context *ctx)
{
   /* [S: main/stencil.c:_mesa_init_stencil] */
   struct fgl_stencil_attrib *s = &ctx->Stencil;
   s->Enabled = false;
   s->Func = GL_ALWAYS;
   s->Ref = 0;
   s->ValueMask = 0xffu;   /* 2^8 - 1, Mesa's deepest stencil buffer */
   s->WriteMask = 0xffu;
   s->FailFunc = GL_KEEP;
   s->ZFailFunc = GL_KEEP;
   s->ZPassFunc = GL_KEEP;
   s->Clear = 0;
}

int fgl_stencil_ref(const struct fgl_context *ctx)
{
   /* [S: main/stencil.h:_mesa_get_stencil_ref] */
   const int bits = ctx->DrawBuffer ? ctx->DrawBuffer->StencilBits : 0;
   const int max = (1 << bits) - 1;
   const int ref = ctx->Stencil.Ref;
   return ref < 0 ? 0 : (ref > max ? max : ref);
}

void GLAPIENTRY glClearStencil(GLint s)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ClearStencil, s);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* marked for glPopAttrib even when unchanged [S: main/stencil.c] */
   ctx->PopAttribState |= GL_STENCIL_BUFFER_BIT;
   ctx->Stencil.Clear = (GLuint)s;
}

static bool valid_func(GLenum func)
{
   return func >= GL_NEVER && func <= GL_ALWAYS;
}

/* [S: main/stencil.c:validate_stencil_op] EXT_stencil_wrap is always
 * supported */
static bool valid_op(GLenum op)
{
   switch (op) {
   case GL_KEEP:
   case GL_ZERO:
   case GL_REPLACE:
   case GL_INCR:
   case GL_DECR:
   case GL_INVERT:
   case GL_INCR_WRAP:
   case GL_DECR_WRAP:
      return true;
   default:
      return false;
   }
}

void GLAPIENTRY glStencilFunc(GLenum func, GLint ref, GLuint mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, StencilFunc, func, ref, mask);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (!valid_func(func)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   struct fgl_stencil_attrib *s = &ctx->Stencil;
   if (s->Func == func && s->Ref == ref && s->ValueMask == mask)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_STENCIL);
   s->Func = func;
   s->Ref = ref;
   s->ValueMask = mask;
}

void GLAPIENTRY glStencilOp(GLenum fail, GLenum zfail, GLenum zpass)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, StencilOp, fail, zfail, zpass);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* checked in this order: sfail, zfail, zpass */
   if (!valid_op(fail) || !valid_op(zfail) || !valid_op(zpass)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   struct fgl_stencil_attrib *s = &ctx->Stencil;
   if (s->FailFunc == fail && s->ZFailFunc == zfail && s->ZPassFunc == zpass)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_STENCIL);
   s->FailFunc = fail;
   s->ZFailFunc = zfail;
   s->ZPassFunc = zpass;
}

void GLAPIENTRY glStencilMask(GLuint mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, StencilMask, mask);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Stencil.WriteMask == mask)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_STENCIL);
   ctx->Stencil.WriteMask = mask;
}
