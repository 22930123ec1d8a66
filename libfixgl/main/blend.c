/*
 * The fragment parts of GL_COLOR_BUFFER_BIT: glAlphaFunc, glBlendFunc,
 * glBlendEquation, glBlendColor, glLogicOp, glColorMask.  The enables
 * (GL_ALPHA_TEST, GL_BLEND, GL_COLOR_LOGIC_OP) are in main/enable.c; the
 * clear colour and dither in main/clear.c.  Validation follows Mesa's
 * main/blend.c.
 */
/* glBlendFuncSeparate and glBlendEquationSeparate are declared by
 * <GL/glext.h> only with GL_GLEXT_PROTOTYPES (which exports them: GLAPI) */
#define GL_GLEXT_PROTOTYPES 1
#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_blend(struct fgl_context *ctx)
{
   /* [S: main/blend.c:_mesa_init_color] */
   struct fgl_colorbuffer_attrib *c = &ctx->Color;
   c->AlphaEnabled = false;
   c->AlphaFunc = GL_ALWAYS;
   c->AlphaRef = 0.0f;
   c->BlendEnabled = false;
   c->BlendSrc = GL_ONE;
   c->BlendDst = GL_ZERO;
   c->BlendEquation = GL_FUNC_ADD;
   c->BlendSrcA = GL_ONE;
   c->BlendDstA = GL_ZERO;
   c->BlendEquationA = GL_FUNC_ADD;
   for (int i = 0; i < 4; i++)
      c->BlendColor[i] = 0.0f;
   c->LogicOpEnabled = false;
   c->LogicOp = GL_COPY;
   c->ColorMask = 0xfu;
}

void GLAPIENTRY glAlphaFunc(GLenum func, GLclampf ref)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, AlphaFunc, func, ref);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Color.AlphaFunc == func && ctx->Color.AlphaRef == ref)
      return; /* no change */
   if (func < GL_NEVER || func > GL_ALWAYS) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_COLOR);
   ctx->Color.AlphaFunc = func;
   ctx->Color.AlphaRef = ref;
}

/* [S: main/blend.c:legal_src_factor, legal_dst_factor]: desktop GL
 * accepts every factor as source and destination (NV_blend_square).  The
 * oracle's ARB_blend_func_extended SRC1 factors are not GL 1.5's:
 * GL_INVALID_ENUM (README "Version and honesty"). */
static bool legal_factor(GLenum factor)
{
   switch (factor) {
   case GL_ZERO:
   case GL_ONE:
   case GL_SRC_COLOR:
   case GL_ONE_MINUS_SRC_COLOR:
   case GL_DST_COLOR:
   case GL_ONE_MINUS_DST_COLOR:
   case GL_SRC_ALPHA:
   case GL_ONE_MINUS_SRC_ALPHA:
   case GL_DST_ALPHA:
   case GL_ONE_MINUS_DST_ALPHA:
   case GL_CONSTANT_COLOR:
   case GL_ONE_MINUS_CONSTANT_COLOR:
   case GL_CONSTANT_ALPHA:
   case GL_ONE_MINUS_CONSTANT_ALPHA:
      return true;
   case GL_SRC_ALPHA_SATURATE:
      return true;
   default:
      return false;
   }
}

/* blend_func_separate's store, after the checks [S: main/blend.c] */
static void blend_func(struct fgl_context *ctx, GLenum src, GLenum dst, GLenum src_a,
                       GLenum dst_a)
{
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_COLOR);
   ctx->Color.BlendSrc = src;
   ctx->Color.BlendDst = dst;
   ctx->Color.BlendSrcA = src_a;
   ctx->Color.BlendDstA = dst_a;
}

/* skip_blend_state_update [S: main/blend.c]: nothing, not even the
 * checks, when the four factors are the current ones */
static bool blend_func_same(const struct fgl_context *ctx, GLenum src, GLenum dst,
                            GLenum src_a, GLenum dst_a)
{
   const struct fgl_colorbuffer_attrib *c = &ctx->Color;
   return c->BlendSrc == src && c->BlendDst == dst && c->BlendSrcA == src_a &&
          c->BlendDstA == dst_a;
}

void GLAPIENTRY glBlendFunc(GLenum sfactor, GLenum dfactor)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, BlendFunc, sfactor, dfactor);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (blend_func_same(ctx, sfactor, dfactor, sfactor, dfactor))
      return;
   if (!legal_factor(sfactor) || !legal_factor(dfactor)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   blend_func(ctx, sfactor, dfactor, sfactor, dfactor);
}

/* glBlendFuncSeparate (GL 1.4) and its EXT alias [S: main/blend.c:
 * _mesa_BlendFuncSeparate, validate_blend_factors] */
void GLAPIENTRY glBlendFuncSeparate(GLenum src, GLenum dst, GLenum src_a, GLenum dst_a)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, BlendFuncSeparate, src, dst, src_a, dst_a);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (blend_func_same(ctx, src, dst, src_a, dst_a))
      return;
   if (!legal_factor(src) || !legal_factor(dst) || !legal_factor(src_a) ||
       !legal_factor(dst_a)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   blend_func(ctx, src, dst, src_a, dst_a);
}

void GLAPIENTRY glBlendFuncSeparateEXT(GLenum src, GLenum dst, GLenum src_a, GLenum dst_a)
{
   glBlendFuncSeparate(src, dst, src_a, dst_a);
}

/* legal_simple_blend_equation [S: main/blend.c] */
static bool legal_equation(GLenum mode)
{
   switch (mode) {
   case GL_FUNC_ADD:
   case GL_FUNC_SUBTRACT:
   case GL_FUNC_REVERSE_SUBTRACT:
   case GL_MIN:
   case GL_MAX:
      return true;
   default:
      return false;
   }
}

void GLAPIENTRY glBlendEquation(GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, BlendEquation, mode);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Color.BlendEquation == mode && ctx->Color.BlendEquationA == mode)
      return;
   if (!legal_equation(mode)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_COLOR);
   ctx->Color.BlendEquation = mode;
   ctx->Color.BlendEquationA = mode;
}

/* glBlendEquationSeparate (GL 2.0, and GL_EXT_blend_equation_separate's
 * name) [S: main/blend.c:_mesa_BlendEquationSeparate]: the rgb mode is
 * checked first */
void GLAPIENTRY glBlendEquationSeparate(GLenum mode_rgb, GLenum mode_a)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, BlendEquationSeparate, mode_rgb, mode_a);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Color.BlendEquation == mode_rgb && ctx->Color.BlendEquationA == mode_a)
      return;
   if (!legal_equation(mode_rgb) || !legal_equation(mode_a)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_COLOR);
   ctx->Color.BlendEquation = mode_rgb;
   ctx->Color.BlendEquationA = mode_a;
}

void GLAPIENTRY glBlendEquationSeparateEXT(GLenum mode_rgb, GLenum mode_a)
{
   glBlendEquationSeparate(mode_rgb, mode_a);
}

void GLAPIENTRY glBlendColor(GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, BlendColor, red, green, blue, alpha);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const float c[4] = { red, green, blue, alpha };
   float *bc = ctx->Color.BlendColor;
   if (bc[0] == c[0] && bc[1] == c[1] && bc[2] == c[2] && bc[3] == c[3])
      return; /* TEST_EQ_4V */
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_COLOR);
   for (int i = 0; i < 4; i++)
      bc[i] = c[i];
}

void GLAPIENTRY glLogicOp(GLenum opcode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, LogicOp, opcode);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Color.LogicOp == opcode)
      return;
   if (opcode < GL_CLEAR || opcode > GL_SET) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_COLOR);
   ctx->Color.LogicOp = opcode;
}

void GLAPIENTRY glColorMask(GLboolean red, GLboolean green, GLboolean blue, GLboolean alpha)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ColorMask, red, green, blue, alpha);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const unsigned mask = (red ? 1u : 0u) | (green ? 2u : 0u) | (blue ? 4u : 0u) |
                         (alpha ? 8u : 0u);
   if (ctx->Color.ColorMask == mask)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_COLOR);
   ctx->Color.ColorMask = mask;
}
