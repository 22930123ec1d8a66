/*
 * Matrix stacks and the matrix entry points (GL 1.x §2.10.2; Mesa
 * main/matrix.c for stack depths, errors and when vertices are flushed).
 */
/* the ARB transpose-matrix names are declared by <GL/glext.h> only with
 * GL_GLEXT_PROTOTYPES (which exports them: GLAPI) */
#define GL_GLEXT_PROTOTYPES 1
#include <stdlib.h>
#include <string.h>

#include "main/groups.h"
#include "main/dlist.h"
#include "fgl_alloc.h"

static bool init_stack(struct fgl_matrix_stack *stack, unsigned max_depth, unsigned dirty)
{
   stack->Stack = fgl_calloc(max_depth, sizeof(fgl_matrix));
   if (!stack->Stack)
      return false;
   stack->MaxDepth = max_depth;
   stack->Depth = 0;
   stack->Top = &stack->Stack[0];
   stack->DirtyFlag = dirty;
   fgl_matrix_identity(stack->Top);
   return true;
}

bool fgl_init_matrix(struct fgl_context *ctx)
{
   bool ok = init_stack(&ctx->ModelviewStack, FGL_MAX_MODELVIEW_STACK_DEPTH, FGL_NEW_MODELVIEW) &&
             init_stack(&ctx->ProjectionStack, FGL_MAX_PROJECTION_STACK_DEPTH, FGL_NEW_PROJECTION);
   for (int i = 0; ok && i <= FGL_MAX_TEXTURE_UNITS; i++)
      ok = init_stack(&ctx->TextureStack[i], FGL_MAX_TEXTURE_STACK_DEPTH,
                      FGL_NEW_TEXTURE_MATRIX);
   ctx->CurrentStack = &ctx->ModelviewStack;
   ctx->Transform.MatrixMode = GL_MODELVIEW;
   return ok;
}

void fgl_free_matrix(struct fgl_context *ctx)
{
   fgl_free(ctx->ModelviewStack.Stack);
   fgl_free(ctx->ProjectionStack.Stack);
   for (int i = 0; i <= FGL_MAX_TEXTURE_UNITS; i++)
      fgl_free(ctx->TextureStack[i].Stack);
}

/* The stack glMatrixMode(mode) selects, or NULL for an invalid mode.
 * (The oracle's ARB_vertex_program stacks GL_MATRIX0_ARB..7 are not GL
 * 1.5's: README "Version and honesty".) */
struct fgl_matrix_stack *fgl_matrix_stack_for_mode(struct fgl_context *ctx, GLenum mode)
{
   switch (mode) {
   case GL_MODELVIEW:
      return &ctx->ModelviewStack;
   case GL_PROJECTION:
      return &ctx->ProjectionStack;
   case GL_TEXTURE:
      /* the active unit's [S: matrix.c:get_named_matrix_stack]; past
       * unit 7 the oracle's index leaves its array, fixgl's scratch
       * stack takes the calls */
      return fgl_texture_stack(ctx);
   default:
      return NULL;
   }
}

void GLAPIENTRY glMatrixMode(GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, MatrixMode, mode);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Transform.MatrixMode == mode && mode != GL_TEXTURE)
      return;
   /* [S: matrix.c:_mesa_MatrixMode] GL_TEXTURE0 + i of a coordinate
    * unit (a name of EXT_direct_state_access's matrix calls) selects no
    * stack and raises no error: nothing changes */
   if (mode >= GL_TEXTURE0 && mode < GL_TEXTURE0 + FGL_MAX_TEXTURE_UNITS)
      return;
   struct fgl_matrix_stack *stack = fgl_matrix_stack_for_mode(ctx, mode);
   if (!stack) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   ctx->CurrentStack = stack;
   ctx->Transform.MatrixMode = mode;
   /* marked even when unchanged (GL_TEXTURE), for glPopAttrib */
   ctx->PopAttribState |= GL_TRANSFORM_BIT;
}

void GLAPIENTRY glPushMatrix(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE0(ctx, PushMatrix);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   struct fgl_matrix_stack *stack = ctx->CurrentStack;
   if (stack->Depth + 1 >= stack->MaxDepth) {
      fgl_error(ctx, GL_STACK_OVERFLOW);
      return;
   }
   /* _math_matrix_push_copy: a dirty matrix is analysed first, so both
    * copies carry its analysed flags (ORACLE-NOTES.md "Matrices") */
   fgl_matrix_analyse(stack->Top);
   stack->Stack[stack->Depth + 1] = stack->Stack[stack->Depth];
   stack->Depth++;
   stack->Top = &stack->Stack[stack->Depth];
}

void GLAPIENTRY glPopMatrix(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE0(ctx, PopMatrix);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   struct fgl_matrix_stack *stack = ctx->CurrentStack;
   if (stack->Depth == 0) {
      fgl_error(ctx, GL_STACK_UNDERFLOW);
      return;
   }
   /* popping back to an identical matrix changes nothing */
   if (memcmp(stack->Top, &stack->Stack[stack->Depth - 1], sizeof(fgl_matrix)) != 0)
      FGL_FLUSH_VERTICES(ctx, stack->DirtyFlag);
   stack->Depth--;
   stack->Top = &stack->Stack[stack->Depth];
}

/* Prologue of the matrix-changing calls. */
#define MATRIX_OP_BEGIN(ctx, save_hook)             \
   GET_CURRENT_CONTEXT(ctx);                        \
   if (!ctx)                                        \
      return;                                       \
   save_hook;                                       \
   ASSERT_OUTSIDE_BEGIN_END(ctx);                   \
   FGL_FLUSH_VERTICES(ctx, ctx->CurrentStack->DirtyFlag)

void GLAPIENTRY glLoadIdentity(void)
{
   MATRIX_OP_BEGIN(ctx, FGL_SAVE0(ctx, LoadIdentity));
   fgl_matrix_identity(ctx->CurrentStack->Top);
}

void GLAPIENTRY glLoadMatrixf(const GLfloat *m)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx || !m)
      return;
   FGL_SAVE(ctx, LoadMatrixf, m, 16);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* loading the matrix already on top changes nothing */
   if (memcmp(m, ctx->CurrentStack->Top->m, 16 * sizeof(float)) == 0)
      return;
   FGL_FLUSH_VERTICES(ctx, ctx->CurrentStack->DirtyFlag);
   fgl_matrix_loadf(ctx->CurrentStack->Top, m);
}

/* The double variants convert to float first, as Mesa does. */
static const GLfloat *to_floats(const GLdouble *m, GLfloat f[16])
{
   if (!m)
      return NULL;
   for (int i = 0; i < 16; i++)
      f[i] = (GLfloat)m[i];
   return f;
}

void GLAPIENTRY glLoadMatrixd(const GLdouble *m)
{
   GLfloat f[16];
   glLoadMatrixf(to_floats(m, f));
}

void GLAPIENTRY glMultMatrixf(const GLfloat *m)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx || !m)
      return;
   FGL_SAVE(ctx, MultMatrixf, m, 16);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* Mesa's matrix_mult skips the identity, compared with memcmp: a -0.0
    * entry makes it a real multiplication, which leaves the flags "general"
    * and dirty, so the next analysis starts from scratch (ORACLE-NOTES.md
    * "Matrices") */
   static const float identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
   if (memcmp(m, identity, sizeof(identity)) == 0)
      return;
   FGL_FLUSH_VERTICES(ctx, ctx->CurrentStack->DirtyFlag);
   fgl_matrix_mul_floats(ctx->CurrentStack->Top, m);
}

void GLAPIENTRY glMultMatrixd(const GLdouble *m)
{
   GLfloat f[16];
   glMultMatrixf(to_floats(m, f));
}

/* glLoadTransposeMatrix{f,d} and glMultTransposeMatrix{f,d} (GL 1.3)
 * and their ARB aliases: the transpose, as floats, through glLoadMatrixf
 * and glMultMatrixf, compiled as those too [S: main/matrix.c:
 * _mesa_LoadTransposeMatrixf, _math_transposefd; main/dlist.c:
 * save_LoadTransposeMatrixf] */
static const GLfloat *transposef(const GLfloat *m, GLfloat t[16])
{
   for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++)
         t[4 * i + j] = m[4 * j + i];
   return t;
}

static const GLfloat *transposed(const GLdouble *m, GLfloat t[16])
{
   for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++)
         t[4 * i + j] = (GLfloat)m[4 * j + i];
   return t;
}

void GLAPIENTRY glLoadTransposeMatrixf(const GLfloat m[16])
{
   GLfloat t[16];
   if (m)
      glLoadMatrixf(transposef(m, t));
}

void GLAPIENTRY glLoadTransposeMatrixd(const GLdouble m[16])
{
   GLfloat t[16];
   if (m)
      glLoadMatrixf(transposed(m, t));
}

void GLAPIENTRY glMultTransposeMatrixf(const GLfloat m[16])
{
   GLfloat t[16];
   if (m)
      glMultMatrixf(transposef(m, t));
}

void GLAPIENTRY glMultTransposeMatrixd(const GLdouble m[16])
{
   GLfloat t[16];
   if (m)
      glMultMatrixf(transposed(m, t));
}

void GLAPIENTRY glLoadTransposeMatrixfARB(const GLfloat *m) { glLoadTransposeMatrixf(m); }
void GLAPIENTRY glLoadTransposeMatrixdARB(const GLdouble *m) { glLoadTransposeMatrixd(m); }
void GLAPIENTRY glMultTransposeMatrixfARB(const GLfloat *m) { glMultTransposeMatrixf(m); }
void GLAPIENTRY glMultTransposeMatrixdARB(const GLdouble *m) { glMultTransposeMatrixd(m); }

void GLAPIENTRY glOrtho(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top,
                        GLdouble nearval, GLdouble farval)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, Ortho, left, right, bottom, top, nearval, farval);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const float l = (float)left, r = (float)right, b = (float)bottom, t = (float)top;
   const float n = (float)nearval, f = (float)farval;
   if (l == r || b == t || n == f) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, ctx->CurrentStack->DirtyFlag);
   fgl_matrix_ortho(ctx->CurrentStack->Top, l, r, b, t, n, f);
}

void GLAPIENTRY glFrustum(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top,
                          GLdouble nearval, GLdouble farval)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, Frustum, left, right, bottom, top, nearval, farval);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const float l = (float)left, r = (float)right, b = (float)bottom, t = (float)top;
   const float n = (float)nearval, f = (float)farval;
   if (n <= 0.0f || f <= 0.0f || n == f || l == r || t == b) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, ctx->CurrentStack->DirtyFlag);
   fgl_matrix_frustum(ctx->CurrentStack->Top, l, r, b, t, n, f);
}

void GLAPIENTRY glTranslatef(GLfloat x, GLfloat y, GLfloat z)
{
   MATRIX_OP_BEGIN(ctx, FGL_SAVE(ctx, Translatef, x, y, z));
   fgl_matrix_translate(ctx->CurrentStack->Top, x, y, z);
}

void GLAPIENTRY glTranslated(GLdouble x, GLdouble y, GLdouble z)
{
   glTranslatef((GLfloat)x, (GLfloat)y, (GLfloat)z);
}

void GLAPIENTRY glScalef(GLfloat x, GLfloat y, GLfloat z)
{
   MATRIX_OP_BEGIN(ctx, FGL_SAVE(ctx, Scalef, x, y, z));
   fgl_matrix_scale(ctx->CurrentStack->Top, x, y, z);
}

void GLAPIENTRY glScaled(GLdouble x, GLdouble y, GLdouble z)
{
   glScalef((GLfloat)x, (GLfloat)y, (GLfloat)z);
}

void GLAPIENTRY glRotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, Rotatef, angle, x, y, z);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (angle == 0.0f)
      return; /* Mesa: a zero rotation changes nothing */
   FGL_FLUSH_VERTICES(ctx, ctx->CurrentStack->DirtyFlag);
   fgl_matrix_rotate(ctx->CurrentStack->Top, angle, x, y, z);
}

void GLAPIENTRY glRotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z)
{
   glRotatef((GLfloat)angle, (GLfloat)x, (GLfloat)y, (GLfloat)z);
}
