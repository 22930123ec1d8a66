/*
 * Context lifetime, the thread-local current context and GL errors.
 */
#include "context.h"
#include "raster/r_kernel.h"
#include "raster/r_pool.h"

#include <stdlib.h>
#include <string.h>

#include "main/dlist.h"
#include "main/groups.h"
#include "fgl_alloc.h"

/* initial-exec (FGL_TLS_INITIAL_EXEC, context.h): read at a fixed offset
 * from the thread pointer, without a __tls_get_addr call in every GL entry
 * point (the general model of a shared library's TLS); the library's few
 * bytes come from the static TLS block, or its reserve when it is
 * dlopen()ed, as Mesa's current context and dispatch do. */
_Thread_local struct fgl_context *fgl_current_context FGL_TLS_INITIAL_EXEC;

struct fgl_context *fgl_get_current(void)
{
   return fgl_current_context;
}

void fgl_set_current(struct fgl_context *ctx)
{
   fgl_current_context = ctx;
}

void fgl_error(struct fgl_context *ctx, GLenum error)
{
   if (ctx->ErrorValue == GL_NO_ERROR)
      ctx->ErrorValue = error;
}

void *fgl_malloc_gl(const struct fgl_context *ctx, size_t size)
{
   void *p = fgl_malloc(size);
   if (!p)
      fgl_error((struct fgl_context *)ctx, GL_OUT_OF_MEMORY);
   return p;
}

void *fgl_realloc_gl(const struct fgl_context *ctx, void *p, size_t size)
{
   void *q = fgl_realloc(p, size);
   if (!q && size)
      fgl_error((struct fgl_context *)ctx, GL_OUT_OF_MEMORY);
   return q;
}

void *fgl_calloc_gl(const struct fgl_context *ctx, size_t n, size_t size)
{
   void *p = fgl_calloc(n, size);
   if (!p)
      fgl_error((struct fgl_context *)ctx, GL_OUT_OF_MEMORY);
   return p;
}

/* Initial values (GL 1.3 state tables 6.5-6.31) of the state no init
 * function of its own sets: the raster position, the current secondary
 * colour and fog coordinate (GL 1.4 values without a setter in fixgl's
 * API, queried only), pixel transfer, zoom and map sizes, the evaluator
 * grids, multisample and colour-index state, the draw and read buffers
 * [S: main/context.c, main/pixel.c:init_pixelmap, main/eval.c:
 * _mesa_init_eval, main/accum.c:_mesa_init_accum, main/multisample.c:
 * _mesa_init_multisample] */
static void init_other_state(struct fgl_context *ctx)
{
   struct fgl_current_attrib *cur = &ctx->Current;
   for (int u = 0; u < FGL_MAX_TEXTURE_UNITS; u++)
      cur->RasterTexCoords[u][3] = 1.0f;
   cur->RasterPos[3] = 1.0f;
   for (int i = 0; i < 4; i++)
      cur->RasterColor[i] = 1.0f;
   cur->RasterSecondaryColor[3] = 1.0f;
   cur->RasterPosValid = true;

   struct fgl_pixel_attrib *px = &ctx->Pixel;
   px->ReadBuffer = GL_FRONT;     /* single-buffered OSMesa framebuffer */
   px->RedScale = px->GreenScale = px->BlueScale = px->AlphaScale = 1.0f;
   px->DepthScale = 1.0f;
   px->ZoomX = px->ZoomY = 1.0f;
   struct fgl_pixelmap *maps[] = {
      &ctx->PixelMaps.RtoR, &ctx->PixelMaps.GtoG, &ctx->PixelMaps.BtoB,
      &ctx->PixelMaps.AtoA, &ctx->PixelMaps.ItoR, &ctx->PixelMaps.ItoG,
      &ctx->PixelMaps.ItoB, &ctx->PixelMaps.ItoA, &ctx->PixelMaps.ItoI,
      &ctx->PixelMaps.StoS,
   };
   for (size_t i = 0; i < sizeof(maps) / sizeof(maps[0]); i++)
      maps[i]->Size = 1;          /* one entry, 0 */

   struct fgl_eval_attrib *ev = &ctx->Eval;
   ev->MapGrid1un = 1;
   ev->MapGrid1u1 = 0.0f;
   ev->MapGrid1u2 = 1.0f;
   ev->MapGrid2un = ev->MapGrid2vn = 1;
   ev->MapGrid2u1 = ev->MapGrid2v1 = 0.0f;
   ev->MapGrid2u2 = ev->MapGrid2v2 = 1.0f;

   ctx->Multisample.Enabled = true;
   ctx->Multisample.SampleCoverageValue = 1.0f;

   ctx->Color.IndexMask = ~0u;
   ctx->Color.DrawBuffer = GL_FRONT;
}

struct fgl_context *fgl_context_create(struct fgl_context *share)
{
   struct fgl_context *ctx = fgl_calloc(1, sizeof(*ctx));
   if (!ctx)
      return NULL;
   if (!fgl_vbo_init(&ctx->Vbo) || !fgl_init_matrix(ctx) || !fgl_init_dlist(ctx) ||
       !fgl_init_texobj(ctx) || !fgl_init_bufobj(ctx)) {
      fgl_context_destroy(ctx);
      return NULL;
   }
   ctx->BeginMode = FGL_OUTSIDE_BEGIN_END;
   ctx->ErrorValue = GL_NO_ERROR;
   fgl_init_current(ctx);
   fgl_init_texenv(ctx);
   fgl_init_texgen(ctx);
   fgl_init_array(ctx);
   fgl_init_color(ctx);
   fgl_init_accum(ctx);
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
   init_other_state(ctx);
   fgl_init_eval(ctx);
   /* FIXGL_KERNELS=reference: the reference kernels draw everything
    * (raster/r_kernel.h) */
   const char *kernels = getenv("FIXGL_KERNELS");
   ctx->_Raster.reference_kernels = kernels && strcmp(kernels, "reference") == 0;
   ctx->_Raster.kernel_isa = r_kernel_isa(kernels);
   ctx->_NumThreads = fgl_num_threads();
   r_pool_ref();
   /* the state objects of the initial state, so that every r_state
    * field points to one from now on */
   ctx->NewState = FGL_NEW_ALL;
   fgl_update_state(ctx);
   if (ctx->NewState != 0) {
      fgl_context_destroy(ctx);
      return NULL;
   }
   /* no framebuffer is bound yet: this framebuffer object is the empty
    * one, kept for an out-of-memory validation (state.c update_raster) */
   ctx->_NullFb = ctx->_Raster.fb;
   r_cso_hold(ctx->_NullFb);
   ctx->ErrorValue = GL_NO_ERROR;
   ctx->NewState = FGL_NEW_ALL;
   if (share) {
      fgl_share_dlists(ctx, share);
      fgl_share_texobjs(ctx, share);
      fgl_share_bufobjs(ctx, share);
   }
   return ctx;
}

void fgl_context_destroy(struct fgl_context *ctx)
{
   if (!ctx)
      return;
   /* what is binned reaches the buffers, which the caller may still read
    * (OSMesa's internal ones are freed after) */
   fgl_scene_flush(ctx);
   fgl_scene_fini(ctx);
   if (ctx->_NumThreads)
      r_pool_unref();
   fgl_free_matrix(ctx);
   fgl_free_dlist(ctx);
   fgl_free_drawpix_cache(ctx);
   fgl_free_texobj(ctx);
   /* the client attribute stack's references to buffers, then the
    * context's own */
   if (ctx->BufObjects)
      for (unsigned i = 0; i < ctx->ClientAttribStackDepth; i++)
         if (ctx->ClientAttribStack[i].Mask & GL_CLIENT_VERTEX_ARRAY_BIT)
            fgl_buffer_release_array(ctx, &ctx->ClientAttribStack[i].Array);
   fgl_free_bufobj(ctx);
   fgl_free_queries(ctx);
   fgl_vbo_fini(&ctx->Vbo);
   fgl_free(ctx->_DrawVbuf.queue);
   fgl_free(ctx->_LinQueue.tri);
   fgl_free(ctx->_LinRectSetup);
   if (ctx->_NullFb)
      r_cso_release(ctx->_NullFb);
   r_cso_cache_fini(&ctx->_StateCache);
   fgl_free(ctx);
}

void fgl_context_bind_framebuffer(struct fgl_context *ctx, struct fgl_framebuffer *fb)
{
   /* [S: lp_setup.c:lp_setup_bind_framebuffer] another framebuffer: the
    * draw regions are recomputed at the next primitive */
   if (ctx->DrawBuffer != fb)
      fgl_vpcut_invalidate(ctx);
   ctx->DrawBuffer = fb;
   if (!fb || fb == ctx->ReadFb)
      ctx->ReadFb = NULL;
   ctx->NewState |= FGL_NEW_BUFFERS;
   fgl_select_color_buffer(ctx);   /* a separate front buffer: the one drawn */
   /* Like _mesa_make_current (_mesa_check_init_viewport): the first
    * binding sizes viewport and scissor box to the buffer. */
   if (fb && !ctx->ViewportInitialized) {
      ctx->ViewportInitialized = true;
      fgl_set_viewport(ctx, 0, 0, fb->Width, fb->Height);
      fgl_set_scissor(ctx, 0, 0, fb->Width, fb->Height);
   }
}

void fgl_context_bind_read_framebuffer(struct fgl_context *ctx, struct fgl_framebuffer *fb)
{
   ctx->ReadFb = fb == ctx->DrawBuffer ? NULL : fb;
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

void fgl_flush_for_draw(struct fgl_context *ctx)
{
   if (!ctx->Vbo.need_flush || fgl_inside_begin_end(ctx))
      return;
   if (ctx->Vbo.need_flush & FGL_VBO_FLUSH_STORED)
      fgl_vbo_flush_vertices(ctx);
   else
      fgl_vbo_flush_current(ctx);
}
