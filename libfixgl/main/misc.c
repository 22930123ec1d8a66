/*
 * glFlush, glFinish and fixgl's own version query.
 *
 * Rendering is synchronous, so both only draw what is batched and then
 * make the image visible: like OSMesa, fixgl renders into its own buffers
 * and copies them to the application's buffer here.
 */
#include <fixgl/fixgl.h>

#include "main/groups.h"

void fgl_flush_front(struct fgl_context *ctx)
{
   FGL_FLUSH_VERTICES(ctx, 0);
   /* [S: st_cb_flush.c:st_flush] glBitmap's cache is drawn first */
   fgl_flush_bitmap_cache(ctx);
   fgl_scene_flush_front(ctx);
   /* [S: lp_setup.c:lp_setup_reset] a flushed scene leaves all of
    * llvmpipe's setup state dirty (probe p_vpcut_state) */
   fgl_vpcut_invalidate(ctx);
   fgl_lin_flushed(ctx);   /* also by a swap or a change of binding */
}

void GLAPIENTRY glFlush(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_OWN(ctx);
   fgl_flush_front(ctx);
   fgl_query_flushed(ctx);   /* the ended queries are available */
}

void GLAPIENTRY glFinish(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_OWN(ctx);
   fgl_flush_front(ctx);
   fgl_query_flushed(ctx);   /* the ended queries are available */
}

FGLAPI const char *fixglGetVersion(void)
{
   return FIXGL_VERSION_STRING;
}
