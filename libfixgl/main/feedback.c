/*
 * Selection and feedback: glRenderMode, glSelectBuffer, the name stack
 * (glInitNames, glLoadName, glPushName, glPopName), glFeedbackBuffer and
 * glPassThrough, as Mesa's main/feedback.c does them on llvmpipe, which
 * has no hardware-accelerated GL_SELECT (u_screen.c
 * PIPE_CAP_HARDWARE_GL_SELECT needs PIPE_CAP_ACCELERATED, 0 on llvmpipe),
 * so the CPU path of update_hit_record applies.
 *
 * The primitives themselves reach the buffers through the draw pipeline
 * with a selection or feedback stage in place of rasterization
 * (tnl/t_feedback.c; state.c picks the stages of the state tracker's own
 * draw context while the render mode is not GL_RENDER).
 *
 * Mesa's quirks kept here:
 *  - glRenderMode processes the old mode (writing the pending hit,
 *    resetting the counts and the name stack) before it validates the new
 *    one: an invalid mode raises GL_INVALID_ENUM after that, returns 0 and
 *    keeps the old mode;
 *  - GL_SELECT or GL_FEEDBACK without a buffer raises GL_INVALID_OPERATION
 *    but still switches the mode;
 *  - glFeedbackBuffer(size > 0, NULL) raises GL_INVALID_VALUE and sets the
 *    buffer size to 0;
 *  - the name stack calls are ignored (no error) outside GL_SELECT;
 *  - a hit's depths are (GLuint)(4294967296.0f * z) as x86-64 compiles the
 *    conversion (cvttss2si to 64 bits, low 32 bits kept), so a depth of 1.0
 *    gives 0 and a slightly negative depth a value near 2^32.
 */
#include <stdint.h>

#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_feedback(struct fgl_context *ctx)
{
   /* [S: feedback.c:_mesa_init_feedback] */
   ctx->Feedback.Type = GL_2D;
   ctx->Feedback.Mask = 0;
   ctx->Feedback.Buffer = NULL;
   ctx->Feedback.BufferSize = 0;
   ctx->Feedback.Count = 0;
   ctx->Feedback.ResetStipple = false;
   ctx->Select.Buffer = NULL;
   ctx->Select.BufferSize = 0;
   ctx->Select.BufferCount = 0;
   ctx->Select.Hits = 0;
   ctx->Select.NameStackDepth = 0;
   /* gl_context is calloc'ed: HitFlag false, HitMinZ = HitMaxZ = 0 until
    * glSelectBuffer or a reset sets them */
   ctx->Select.HitFlag = false;
   ctx->Select.HitMinZ = 0.0f;
   ctx->Select.HitMaxZ = 0.0f;
   ctx->RenderMode = GL_RENDER;
}

bool fgl_get_feedback_value(struct fgl_context *ctx, GLenum pname, int *value)
{
   /* [S: get_hash_params.py] */
   switch (pname) {
   case GL_RENDER_MODE:           *value = (int)ctx->RenderMode; return true;
   case GL_NAME_STACK_DEPTH:      *value = (int)ctx->Select.NameStackDepth; return true;
   case GL_MAX_NAME_STACK_DEPTH:  *value = FGL_MAX_NAME_STACK_DEPTH; return true;
   case GL_SELECTION_BUFFER_SIZE: *value = (int)ctx->Select.BufferSize; return true;
   case GL_FEEDBACK_BUFFER_SIZE:  *value = (int)ctx->Feedback.BufferSize; return true;
   case GL_FEEDBACK_BUFFER_TYPE:  *value = (int)ctx->Feedback.Type; return true;
   default:                       return false;
   }
}

/* ---- feedback ---- */

void GLAPIENTRY glFeedbackBuffer(GLsizei size, GLenum type, GLfloat *buffer)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   /* [S: feedback.c:_mesa_FeedbackBuffer] */
   if (ctx->RenderMode == GL_FEEDBACK) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (size < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!buffer && size > 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      ctx->Feedback.BufferSize = 0;
      return;
   }
   unsigned mask;
   switch (type) {
   case GL_2D:               mask = 0; break;
   case GL_3D:               mask = FGL_FB_3D; break;
   case GL_3D_COLOR:         mask = FGL_FB_3D | FGL_FB_COLOR; break;
   case GL_3D_COLOR_TEXTURE: mask = FGL_FB_3D | FGL_FB_COLOR | FGL_FB_TEXTURE; break;
   case GL_4D_COLOR_TEXTURE: mask = FGL_FB_3D | FGL_FB_4D | FGL_FB_COLOR | FGL_FB_TEXTURE; break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   ctx->Feedback.Mask = mask;
   ctx->Feedback.Type = type;
   ctx->Feedback.BufferSize = (GLuint)size;
   ctx->Feedback.Buffer = buffer;
   ctx->Feedback.Count = 0;
}

void GLAPIENTRY glPassThrough(GLfloat token)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PassThrough, token);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* [S: feedback.c:_mesa_PassThrough] ignored outside GL_FEEDBACK */
   if (ctx->RenderMode == GL_FEEDBACK) {
      FGL_FLUSH_VERTICES(ctx, 0);
      fgl_feedback_token(ctx, (GLfloat)(GLint)GL_PASS_THROUGH_TOKEN);
      fgl_feedback_token(ctx, token);
   }
}

/* ---- selection ---- */

void GLAPIENTRY glSelectBuffer(GLsizei size, GLuint *buffer)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   /* [S: feedback.c:_mesa_SelectBuffer] the size is checked first */
   if (size < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (ctx->RenderMode == GL_SELECT) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   struct fgl_selection *s = &ctx->Select;
   s->Buffer = buffer;
   s->BufferSize = (GLuint)size;
   s->BufferCount = 0;
   s->HitFlag = false;
   s->HitMinZ = 1.0f;
   s->HitMaxZ = 0.0f;
}

/* [S: feedback.c:write_record] values past the buffer are counted only */
static inline void write_record(struct fgl_selection *s, GLuint value)
{
   if (s->BufferCount < s->BufferSize)
      s->Buffer[s->BufferCount] = value;
   s->BufferCount++;
}

/* [S: feedback.c:update_hit_record] (GLuint)((GLfloat)0xffffffffu * z):
 * the float scale rounds to 2^32, and the oracle's x86-64 build converts
 * with cvttss2si to a 64-bit integer and keeps the low 32 bits (NaN and
 * values beyond +-2^63 give INT64_MIN, whose low bits are 0). */
static GLuint depth_to_uint(float z)
{
   const float f = (GLfloat)0xffffffffu * z;
   if (!(f > -9223372036854775808.0f && f < 9223372036854775808.0f))
      return 0;
   return (GLuint)(uint64_t)(int64_t)f;
}

/* [S: feedback.c:update_hit_record, the !HardwareAcceleratedSelect path]
 * the pending hit: name count, min and max depth, the names; then the
 * depths restart at 1 and -1 (not 0, as glSelectBuffer and
 * reset_name_stack_to_empty set them) */
static void update_hit_record(struct fgl_context *ctx)
{
   struct fgl_selection *s = &ctx->Select;
   if (!s->HitFlag)
      return;
   const GLuint zmin = depth_to_uint(s->HitMinZ);
   const GLuint zmax = depth_to_uint(s->HitMaxZ);
   write_record(s, s->NameStackDepth);
   write_record(s, zmin);
   write_record(s, zmax);
   for (GLuint i = 0; i < s->NameStackDepth; i++)
      write_record(s, s->NameStack[i]);
   s->HitFlag = false;
   s->HitMinZ = 1.0f;
   s->HitMaxZ = -1.0f;
   s->Hits++;
}

/* [S: feedback.c:reset_name_stack_to_empty] */
static void reset_name_stack_to_empty(struct fgl_context *ctx)
{
   struct fgl_selection *s = &ctx->Select;
   s->NameStackDepth = 0;
   s->HitFlag = false;
   s->HitMinZ = 1.0f;
   s->HitMaxZ = 0.0f;
}

void GLAPIENTRY glInitNames(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE0(ctx, InitNames);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* [S: feedback.c:_mesa_InitNames] ignored outside GL_SELECT */
   if (ctx->RenderMode != GL_SELECT)
      return;
   FGL_FLUSH_VERTICES(ctx, 0);
   update_hit_record(ctx);
   reset_name_stack_to_empty(ctx);
}

void GLAPIENTRY glLoadName(GLuint name)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, LoadName, name);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* [S: feedback.c:_mesa_LoadName] */
   if (ctx->RenderMode != GL_SELECT)
      return;
   if (ctx->Select.NameStackDepth == 0) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   update_hit_record(ctx);
   ctx->Select.NameStack[ctx->Select.NameStackDepth - 1] = name;
}

void GLAPIENTRY glPushName(GLuint name)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PushName, name);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* [S: feedback.c:_mesa_PushName] */
   if (ctx->RenderMode != GL_SELECT)
      return;
   if (ctx->Select.NameStackDepth >= FGL_MAX_NAME_STACK_DEPTH) {
      fgl_error(ctx, GL_STACK_OVERFLOW);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   update_hit_record(ctx);
   ctx->Select.NameStack[ctx->Select.NameStackDepth++] = name;
}

void GLAPIENTRY glPopName(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE0(ctx, PopName);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* [S: feedback.c:_mesa_PopName] */
   if (ctx->RenderMode != GL_SELECT)
      return;
   if (ctx->Select.NameStackDepth == 0) {
      fgl_error(ctx, GL_STACK_UNDERFLOW);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   update_hit_record(ctx);
   ctx->Select.NameStackDepth--;
}

/* ---- render mode ---- */

GLint GLAPIENTRY glRenderMode(GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return 0;
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, 0);
   /* [S: feedback.c:_mesa_RenderMode] the batched vertices are drawn in
    * the old mode; the draw pipeline's stages change with the mode */
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_RENDERMODE);

   GLint result = 0;
   switch (ctx->RenderMode) {
   case GL_SELECT:
      update_hit_record(ctx);
      /* a count past the buffer is an overflow */
      result = ctx->Select.BufferCount > ctx->Select.BufferSize ? -1 : (GLint)ctx->Select.Hits;
      ctx->Select.BufferCount = 0;
      ctx->Select.Hits = 0;
      reset_name_stack_to_empty(ctx);
      break;
   case GL_FEEDBACK:
      result = ctx->Feedback.Count > ctx->Feedback.BufferSize ? -1 : (GLint)ctx->Feedback.Count;
      ctx->Feedback.Count = 0;
      break;
   default:
      result = 0;
      break;
   }

   switch (mode) {
   case GL_RENDER:
      break;
   case GL_SELECT:
      /* no glSelectBuffer yet: an error, but the mode still changes */
      if (ctx->Select.BufferSize == 0)
         fgl_error(ctx, GL_INVALID_OPERATION);
      break;
   case GL_FEEDBACK:
      if (ctx->Feedback.BufferSize == 0)
         fgl_error(ctx, GL_INVALID_OPERATION);
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return 0;
   }
   ctx->RenderMode = mode;
   return result;
}
