/*
 * glDrawBuffer, glReadBuffer on the OSMesa framebuffer: one single-buffered
 * mono colour buffer, which the oracle's GL_FRONT_LEFT stands for.
 *
 * [S: main/buffers.c:draw_buffer, read_buffer] The given enum is stored
 * as is (GL_DRAW_BUFFER/GL_READ_BUFFER report it); on a single-buffered
 * framebuffer GL_BACK* names the front buffer
 * (_mesa_back_to_front_if_single_buffered), so every value that names a
 * left buffer draws into and reads from the one buffer.  Right buffers,
 * GL_AUXi and colour attachments do not exist: INVALID_OPERATION; any
 * other enum: INVALID_ENUM.  GL_NONE is legal: no colour is drawn
 * (state.c, clear.c) and glReadPixels of a colour format raises
 * INVALID_OPERATION (readpix.c).
 *
 * A context of a double-buffered GLX config (libfixgl/libgl/) starts with GL_BACK
 * for both.  A double-buffered GLX window has a separate front buffer
 * (fb->Other): GL_FRONT and GL_FRONT_LEFT draw into it, the other draw
 * buffers into the back (fgl_select_color_buffer, at glDrawBuffer, at
 * glPopAttrib and when a framebuffer is bound); GL_FRONT, GL_FRONT_LEFT,
 * GL_LEFT and GL_FRONT_AND_BACK read from the front, GL_BACK and
 * GL_BACK_LEFT from the back (fgl_read_color).
 *
 * Both buffers.  GL_FRONT_AND_BACK and GL_LEFT name FRONT_LEFT and
 * BACK_LEFT (draw_buffer_enum_to_bitmask): with a separate front the
 * oracle binds two colour buffers, and llvmpipe's fragment shader tests
 * depth and stencil once per fragment, then blends (logic op, colour mask)
 * into each buffer with that buffer's own destination; glClear clears
 * both, glAccum(GL_RETURN) writes both (accum_return loops over the draw
 * buffers), and glCopyPixels takes no blit (_NumColorDrawBuffers is 2).
 * Here Color is the back and Other the front (fb->DrawBoth), and each
 * primitive is rasterized twice, directly (scene.c, not binned): first
 * into Other with a raster state whose depth and stencil are tested but
 * not written (fgl_both_begin), then into Color with the draw's own
 * state.  The depth and stencil buffers are the same for both passes of a
 * primitive and the fragments' colours do not depend on the destination,
 * so every fragment passes or fails alike in both, as in the oracle's one
 * pass; an occlusion query counts the second pass only.  Probe: the glx
 * test frontback.c (conformance/glx/), images equal to Mesa's.
 */
#include "main/groups.h"
#include "main/dlist.h"

enum buffer_class { BUF_BAD_ENUM, BUF_MISSING, BUF_OK };

/* draw_buffer_enum_to_bitmask / read_buffer_enum_to_index, with the
 * supported buffer mask of a single-buffered mono window framebuffer
 * (BUFFER_BIT_FRONT_LEFT).  The read side maps GL_RIGHT to FRONT_RIGHT and
 * GL_FRONT_AND_BACK to FRONT_LEFT, which gives the same classes. */
static enum buffer_class classify(GLenum buffer)
{
   switch (buffer) {
   case GL_NONE:
   case GL_FRONT:
   case GL_BACK:
   case GL_LEFT:
   case GL_FRONT_LEFT:
   case GL_BACK_LEFT:
   case GL_FRONT_AND_BACK:
      return BUF_OK;
   case GL_RIGHT:
   case GL_FRONT_RIGHT:
   case GL_BACK_RIGHT:
   case GL_AUX0:
   case GL_AUX1:
   case GL_AUX2:
   case GL_AUX3:
      return BUF_MISSING;
   default:
      if (buffer >= GL_COLOR_ATTACHMENT0 && buffer <= GL_COLOR_ATTACHMENT31)
         return BUF_MISSING;
      return BUF_BAD_ENUM;
   }
}

static bool check_buffer(struct fgl_context *ctx, GLenum buffer)
{
   switch (classify(buffer)) {
   case BUF_BAD_ENUM:
      fgl_error(ctx, GL_INVALID_ENUM);
      return false;
   case BUF_MISSING:
      fgl_error(ctx, GL_INVALID_OPERATION);
      return false;
   default:
      return true;
   }
}

void GLAPIENTRY glDrawBuffer(GLenum buffer)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, DrawBuffer, buffer);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* FLUSH_VERTICES(ctx, 0, GL_COLOR_BUFFER_BIT) before validation, as
    * draw_buffer does: even a refused call marks the group for glPopAttrib */
   FGL_FLUSH_VERTICES(ctx, 0);
   ctx->PopAttribState |= GL_COLOR_BUFFER_BIT;
   if (!check_buffer(ctx, buffer))
      return;
   ctx->NewState |= FGL_NEW_COLOR;
   ctx->Color.DrawBuffer = buffer;
   fgl_select_color_buffer(ctx);
}

void GLAPIENTRY glReadBuffer(GLenum buffer)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ReadBuffer, buffer);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* FLUSH_VERTICES(ctx, 0, GL_PIXEL_MODE_BIT) before validation */
   FGL_FLUSH_VERTICES(ctx, 0);
   ctx->PopAttribState |= GL_PIXEL_MODE_BIT;
   if (!check_buffer(ctx, buffer))
      return;
   ctx->Pixel.ReadBuffer = buffer;
}

/* A new window framebuffer's ColorReadBuffer: GL_FRONT (single-buffered) */
void fgl_new_window_framebuffer(struct fgl_context *ctx)
{
   ctx->Pixel.ReadBuffer = GL_FRONT;
}

void fgl_init_double_buffered(struct fgl_context *ctx)
{
   ctx->Color.DrawBuffer = GL_BACK;
   ctx->Pixel.ReadBuffer = GL_BACK;
}

/* The draw buffer into Color (see the top): the drawing so far is
 * finished into the buffer it was for, then Color and Other trade places,
 * with their ColorDefined. */
void fgl_select_color_buffer(struct fgl_context *ctx)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   const GLenum b = ctx->Color.DrawBuffer;
   if (!fb)
      return;
   fb->DrawBoth = fb->Other && (b == GL_FRONT_AND_BACK || b == GL_LEFT);
   if (!fb->Other || b == GL_NONE)
      return;
   const bool front = b == GL_FRONT || b == GL_FRONT_LEFT;
   if (front == fb->FrontIsColor)
      return;
   fgl_scene_flush(ctx);
   fgl_lazy_resolve(fb, FGL_LAZY_COLOR);
   uint8_t *const color = fb->Color;
   fb->Color = fb->Other;
   fb->Other = color;
   const bool defined = fb->ColorDefined;
   fb->ColorDefined = fb->OtherDefined;
   fb->OtherDefined = defined;
   fb->FrontIsColor = front;
   ctx->NewState |= FGL_NEW_BUFFERS;
   fgl_vpcut_invalidate(ctx);   /* another colour surface bound */
}

/* A separate read framebuffer (glXMakeContextCurrent with a read
 * drawable other than the draw one): the oracle's ctx->ReadBuffer, which
 * glReadPixels, glCopyPixels, glCopyTexImage and glAccum(GL_LOAD,
 * GL_ACCUM) read (colour, depth and stencil, clipped to its size), its
 * front or back by glReadBuffer; this context's drawing into it was
 * flushed when it stopped being the draw drawable (glx.c), what was left
 * of it are lazy clears, written here. */
struct fgl_framebuffer *fgl_read_fb(const struct fgl_context *ctx)
{
   struct fgl_framebuffer *fb = ctx->ReadFb;
   if (!fb)
      return ctx->DrawBuffer;
   fgl_lazy_resolve(fb, FGL_LAZY_COLOR | FGL_LAZY_ZS);
   return fb;
}

/* The colour buffer glReadPixels, glCopyPixels, glCopyTexImage and
 * glAccum read from: Color of the read framebuffer, or Other when the
 * read buffer names the other one (a separate front buffer only). */
const uint8_t *fgl_read_color(const struct fgl_context *ctx)
{
   const struct fgl_framebuffer *fb = fgl_read_fb(ctx);
   if (!fb || !fb->Other)
      return fb ? fb->Color : NULL;
   const GLenum b = ctx->Pixel.ReadBuffer;
   const bool front = b == GL_FRONT || b == GL_FRONT_LEFT || b == GL_LEFT || b == GL_FRONT_AND_BACK;
   return front == fb->FrontIsColor ? fb->Color : fb->Other;
}

/* The raster state of fb->Other for a primitive of state rs (see "Both
 * buffers" at the top): rs with the colour buffer Other, depth and
 * stencil tested but not written (stencil ops KEEP, write mask 0), no lazy
 * clears (all written by now), no occlusion or benchmark counting; its
 * kernels chosen again.  Made for every primitive: rs may be a caller's
 * copy whose objects live on its stack (clear.c, drawpix.c), so nothing
 * of it can be kept. */
static const struct r_state *other_state(struct fgl_context *ctx, const struct r_state *rs)
{
   struct fgl_both_target *b = &ctx->_Both;
   b->fb = *rs->fb;
   b->fb.color = ctx->DrawBuffer->Other;
   b->dsa = *rs->dsa;
   b->dsa.depth_write = false;
   b->dsa.stencil_fail = b->dsa.stencil_zfail = b->dsa.stencil_zpass = R_STENCIL_KEEP;
   b->dsa.stencil_writemask = 0;
   b->rs = *rs;
   b->rs.fb = &b->fb;
   b->rs.dsa = &b->dsa;
   b->rs.lazy = NULL;
   b->rs.samples = NULL;
   b->rs.stats = NULL;
   r_choose_kernels(&b->rs);
   b->rs.full_ops |= rs->full_ops;   /* (a clear quad's rs sets it) */
   return &b->rs;
}

const struct r_state *fgl_both_begin(struct fgl_context *ctx, const struct r_state *rs)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   fgl_scene_flush(ctx);
   fb->OtherDefined = true;
   return other_state(ctx, rs);
}
