/*
 * Scissor state (GL_SCISSOR_BIT): glScissor.  GL_SCISSOR_TEST itself is in
 * main/enable.c.  The box limits the draw region of every primitive
 * (state.c) and of quad clears (main/clear.c).
 */
#include "main/groups.h"

void fgl_init_scissor(struct fgl_context *ctx)
{
   /* the box starts as 0,0,0,0; Mesa sets it to the window size when a
    * framebuffer is first bound (fgl_context_bind_framebuffer) */
   ctx->Scissor.Enabled = false;
   ctx->Scissor.X = 0;
   ctx->Scissor.Y = 0;
   ctx->Scissor.Width = 0;
   ctx->Scissor.Height = 0;
}

void fgl_set_scissor(struct fgl_context *ctx, int x, int y, int width, int height)
{
   /* [S: main/scissor.c:set_scissor_no_notify] */
   if (x == ctx->Scissor.X && y == ctx->Scissor.Y &&
       width == ctx->Scissor.Width && height == ctx->Scissor.Height)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_SCISSOR);
   ctx->Scissor.X = x;
   ctx->Scissor.Y = y;
   ctx->Scissor.Width = width;
   ctx->Scissor.Height = height;
}

void GLAPIENTRY glScissor(GLint x, GLint y, GLsizei width, GLsizei height)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (width < 0 || height < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   fgl_set_scissor(ctx, x, y, width, height);
}

void fgl_scissor_bounds(const struct fgl_context *ctx, int bbox[4])
{
   /* [S: main/framebuffer.c:scissor_bounding_box,
    * _mesa_intersect_scissor_bounding_box]: xmin, xmax, ymin, ymax in GL's
    * y-up window coordinates, an empty box collapsed onto its max edge */
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   bbox[0] = 0;
   bbox[1] = fb ? fb->Width : 0;
   bbox[2] = 0;
   bbox[3] = fb ? fb->Height : 0;
   if (ctx->Scissor.Enabled) {
      const struct fgl_scissor_attrib *s = &ctx->Scissor;
      if (s->X > bbox[0])
         bbox[0] = s->X;
      if (s->Y > bbox[2])
         bbox[2] = s->Y;
      if (s->X + s->Width < bbox[1])
         bbox[1] = s->X + s->Width;
      if (s->Y + s->Height < bbox[3])
         bbox[3] = s->Y + s->Height;
      if (bbox[0] > bbox[1])
         bbox[0] = bbox[1];
      if (bbox[2] > bbox[3])
         bbox[2] = bbox[3];
   }
}
