/*
 * User clip planes (GL_TRANSFORM_BIT): glClipPlane, glGetClipPlane; the
 * GL_CLIP_PLANEi enables are in main/enable.c.
 *
 * [S: main/clip.c:_mesa_ClipPlane, _mesa_update_clip_plane] The equation
 * is converted to float and transformed at call time by the inverse of the
 * current modelview into eye space (EyeUserPlane, what glGetClipPlane
 * returns).  At draw time the oracle clips in clip space with
 * _ClipUserPlane = EyeUserPlane * inverse(projection), recomputed whenever
 * the plane is enabled or set, or the projection changes
 * (main/matrix.c:update_projection), so it always uses the current
 * projection: fgl_update_clip_planes derives it in state.c.
 */
#include "main/groups.h"
#include "main/dlist.h"

/* _mesa_transform_vector: u = v * m (row vector times matrix), each sum
 * left to right. */
static void transform_vector(float u[4], const float v[4], const float m[16])
{
   const float v0 = v[0], v1 = v[1], v2 = v[2], v3 = v[3];
   for (int c = 0; c < 4; c++)
      u[c] = v0 * m[4 * c + 0] + v1 * m[4 * c + 1] + v2 * m[4 * c + 2] + v3 * m[4 * c + 3];
}

void GLAPIENTRY glClipPlane(GLenum plane, const GLdouble *equation)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ClipPlane, plane, equation, equation ? 4 : 0);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const int p = (int)plane - (int)GL_CLIP_PLANE0;
   if (p < 0 || p >= FGL_MAX_CLIP_PLANES) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (!equation)
      return;
   float eq[4] = { (GLfloat)equation[0], (GLfloat)equation[1], (GLfloat)equation[2],
                   (GLfloat)equation[3] };
   fgl_matrix_analyse(ctx->ModelviewStack.Top);
   transform_vector(eq, eq, ctx->ModelviewStack.Top->inv);
   float *dst = ctx->Transform.EyeUserPlane[p];
   if (dst[0] == eq[0] && dst[1] == eq[1] && dst[2] == eq[2] && dst[3] == eq[3])
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_CLIP);
   for (int i = 0; i < 4; i++)
      dst[i] = eq[i];
}

void GLAPIENTRY glGetClipPlane(GLenum plane, GLdouble *equation)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   const int p = (int)plane - (int)GL_CLIP_PLANE0;
   if (p < 0 || p >= FGL_MAX_CLIP_PLANES) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (!equation)
      return;
   for (int i = 0; i < 4; i++)
      equation[i] = (GLdouble)ctx->Transform.EyeUserPlane[p][i];
}

void fgl_update_clip_planes(struct fgl_context *ctx)
{
   unsigned mask = ctx->Transform.ClipPlanesEnabled;
   if (!mask)
      return;
   fgl_matrix_analyse(ctx->ProjectionStack.Top);
   while (mask) {
      const int p = __builtin_ctz(mask);
      mask &= mask - 1;
      transform_vector(ctx->_ClipUserPlane[p], ctx->Transform.EyeUserPlane[p],
                       ctx->ProjectionStack.Top->inv);
   }
}
