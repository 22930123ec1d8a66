/*
 * Scissor state (GL_SCISSOR_BIT): glScissor.  GL_SCISSOR_TEST itself is in
 * main/enable.c.  The box limits the draw region of every primitive
 * (state.c) and of quad clears (main/clear.c).
 */
#include "main/groups.h"
#include "main/dlist.h"

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
   /* a new box with the test on draws glBitmap's cache first */
   if (ctx->Scissor.Enabled)
      fgl_flush_bitmap_cache(ctx);
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
   FGL_SAVE(ctx, Scissor, x, y, width, height);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (width < 0 || height < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   fgl_set_scissor(ctx, x, y, width, height);
}

/* x + w with the wrap-around of the oracle's int arithmetic (no UB here) */
static int add_wrap(int a, int b)
{
   return (int)((unsigned)a + (unsigned)b);
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
      if (add_wrap(s->X, s->Width) < bbox[1])
         bbox[1] = add_wrap(s->X, s->Width);
      if (add_wrap(s->Y, s->Height) < bbox[3])
         bbox[3] = add_wrap(s->Y, s->Height);
      if (bbox[0] > bbox[1])
         bbox[0] = bbox[1];
      if (bbox[2] > bbox[3])
         bbox[2] = bbox[3];
   }
}

void fgl_scissor_draw_region(const struct fgl_context *ctx, int region[4])
{
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   const int w = fb ? fb->Width : 0, h = fb ? fb->Height : 0;
   region[0] = 0;
   region[1] = 0;
   region[2] = w;
   region[3] = h;
   if (!ctx->Scissor.Enabled)
      return;
   /* [S: state_tracker/st_atom_scissor.c:st_update_scissor] into
    * pipe_scissor_state, whose fields are 16-bit bitfields: a box origin
    * of 65536 + x starts at x. */
   const struct fgl_scissor_attrib *s = &ctx->Scissor;
   unsigned minx = 0, miny = 0, maxx = (unsigned)w & 0xffffu, maxy = (unsigned)h & 0xffffu;
   int xmax = add_wrap(s->X, s->Width);
   int ymax = add_wrap(s->Y, s->Height);
   if (xmax < 0)
      xmax = 0;
   if (ymax < 0)
      ymax = 0;
   if (s->X > (int)minx)
      minx = (unsigned)s->X & 0xffffu;
   if (s->Y > (int)miny)
      miny = (unsigned)s->Y & 0xffffu;
   if (xmax < (int)maxx)
      maxx = (unsigned)xmax & 0xffffu;
   if (ymax < (int)maxy)
      maxy = (unsigned)ymax & 0xffffu;
   if (minx >= maxx || miny >= maxy)
      minx = miny = maxx = maxy = 0;
   /* y-down, then llvmpipe's draw region: the intersection with the
    * framebuffer (lp_setup.c try_update_scene_state) */
   const int y0 = h - (int)maxy, y1 = h - (int)miny;
   region[0] = (int)minx < w ? (int)minx : w;
   region[1] = y0 > 0 ? y0 : 0;
   region[2] = (int)maxx < w ? (int)maxx : w;
   region[3] = y1 < h ? y1 : h;
   if (region[0] >= region[2] || region[1] >= region[3])
      region[0] = region[1] = region[2] = region[3] = 0;
}
