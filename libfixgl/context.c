/*
 * Context lifetime, the thread-local current context and GL errors.
 */
#include "context.h"

#include <stdlib.h>
#include <string.h>

#include "main/dlist.h"
#include "main/groups.h"

static _Thread_local struct fgl_context *current_context;

struct fgl_context *fgl_get_current(void)
{
   return current_context;
}

void fgl_set_current(struct fgl_context *ctx)
{
   current_context = ctx;
}

void fgl_error(struct fgl_context *ctx, GLenum error)
{
   if (ctx->ErrorValue == GL_NO_ERROR)
      ctx->ErrorValue = error;
}

struct fgl_context *fgl_context_create(void)
{
   struct fgl_context *ctx = calloc(1, sizeof(*ctx));
   if (!ctx)
      return NULL;
   if (!fgl_vbo_init(&ctx->Vbo) || !fgl_init_matrix(ctx) || !fgl_init_dlist(ctx)) {
      fgl_context_destroy(ctx);
      return NULL;
   }
   ctx->BeginMode = FGL_OUTSIDE_BEGIN_END;
   ctx->ErrorValue = GL_NO_ERROR;
   fgl_init_current(ctx);
   fgl_init_array(ctx);
   fgl_init_color(ctx);
   fgl_init_depth(ctx);
   fgl_init_fog(ctx);
   fgl_init_hint(ctx);
   fgl_init_light(ctx);
   fgl_init_polygon(ctx);
   fgl_init_scissor(ctx);
   fgl_init_stencil(ctx);
   fgl_init_blend(ctx);
   fgl_init_pixelstore(ctx);
   fgl_init_point(ctx);
   fgl_init_line(ctx);
   fgl_init_viewport(ctx);
   fgl_init_feedback(ctx);
   ctx->NewState = FGL_NEW_ALL;
   return ctx;
}

void fgl_context_destroy(struct fgl_context *ctx)
{
   if (!ctx)
      return;
   fgl_free_matrix(ctx);
   fgl_free_dlist(ctx);
   fgl_vbo_fini(&ctx->Vbo);
   free(ctx->_DrawVbuf.queue);
   free(ctx);
}

void fgl_context_bind_framebuffer(struct fgl_context *ctx, struct fgl_framebuffer *fb)
{
   ctx->DrawBuffer = fb;
   ctx->NewState |= FGL_NEW_BUFFERS;
   /* Like _mesa_make_current (_mesa_check_init_viewport): the first
    * binding sizes viewport and scissor box to the buffer. */
   if (fb && !ctx->ViewportInitialized) {
      ctx->ViewportInitialized = true;
      fgl_set_viewport(ctx, 0, 0, fb->Width, fb->Height);
      fgl_set_scissor(ctx, 0, 0, fb->Width, fb->Height);
   }
}

void fgl_flush_vertices(struct fgl_context *ctx)
{
   /* inside glBegin/glEnd Mesa's flush returns at once */
   if ((ctx->Vbo.need_flush & FGL_VBO_FLUSH_STORED) && !fgl_inside_begin_end(ctx))
      fgl_vbo_flush_vertices(ctx);
}

void fgl_flush_current(struct fgl_context *ctx)
{
   if ((ctx->Vbo.need_flush & FGL_VBO_FLUSH_CURRENT) && !fgl_inside_begin_end(ctx))
      fgl_vbo_flush_current(ctx);
}
