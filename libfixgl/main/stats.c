/*
 * fixglStats, fixglResetStats, fixglGetStats: the benchmark's breakdown of
 * a frame (include/fixgl/fixgl.h).
 *
 * The counters live in the context (ctx->Stats).  While they are enabled
 * the raster core's r_state points to them (_Raster.stats; NULL
 * otherwise, so a disabled context pays one well-predicted branch per
 * vertex batch and per primitive), and the states the scene keeps point
 * to them too: the raster core adds the fragments it shades and its
 * setup and raster time (per thread while the scene is rasterized, then
 * summed, scene.c), t_render_batch times each vertex batch and
 * fgl_scene_flush each rasterization of the scene.  batch_ns is the wall
 * time of both, vertex_ns the batches' time minus the rasterization inside
 * them (with one thread, which rasterizes each primitive as it comes, the
 * raster core's own time); with one thread setup_ns + raster_ns fits in
 * batch_ns - vertex_ns.
 */
#include <fixgl/fixgl.h>

#include <string.h>
#include <time.h>

#include "context.h"

static uint64_t now_ns(void)
{
   struct timespec ts;
   clock_gettime(CLOCK_MONOTONIC, &ts);
   return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

void fgl_stats_batch_begin(struct fgl_context *ctx, struct fgl_stats_mark *mark)
{
   mark->flush0 = ctx->Stats.flush_ns;
   mark->raster0 = ctx->Stats.raster.setup_ns + ctx->Stats.raster.raster_ns;
   mark->t0 = now_ns();
   ctx->Stats.in_batch = true;
}

void fgl_stats_batch_end(struct fgl_context *ctx, const struct fgl_stats_mark *mark)
{
   const uint64_t t1 = now_ns();
   struct fgl_stats *st = &ctx->Stats;
   const uint64_t batch = t1 - mark->t0;
   uint64_t flush = st->flush_ns - mark->flush0;
   /* with one thread the primitives are rasterized as they come (scene.c):
    * the raster core's time inside the batch is not the vertex stage's */
   if (ctx->_NumThreads == 1)
      flush += st->raster.setup_ns + st->raster.raster_ns - mark->raster0;
   st->batch_ns += batch;
   /* the rasterization is timed inside the batch: it cannot exceed the
    * batch's time, but clamp rather than wrap */
   st->vertex_ns += batch > flush ? batch - flush : 0;
   st->batches++;
   st->in_batch = false;
}

void fgl_stats_flush(struct fgl_context *ctx, uint64_t ns)
{
   ctx->Stats.flush_ns += ns;
   if (!ctx->Stats.in_batch)
      ctx->Stats.batch_ns += ns;
}

FGLAPI void fixglStats(int enable)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   /* what is batched so far is drawn under the old setting */
   fgl_flush_vertices(ctx);
   ctx->_Raster.stats = enable ? &ctx->Stats.raster : NULL;
}

FGLAPI void fixglResetStats(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_flush_vertices(ctx);
   fgl_scene_flush(ctx);
   memset(&ctx->Stats, 0, sizeof(ctx->Stats));
}

FGLAPI void fixglGetStats(struct fixgl_stats *out)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!out)
      return;
   memset(out, 0, sizeof(*out));
   if (!ctx)
      return;
   /* the batched vertices are drawn first, as glFinish would */
   fgl_flush_vertices(ctx);
   fgl_scene_flush(ctx);
   const struct fgl_stats *st = &ctx->Stats;
   out->enabled = ctx->_Raster.stats != NULL;
   out->fragments = st->raster.fragments;
   out->setup_ns = st->raster.setup_ns;
   out->raster_ns = st->raster.raster_ns;
   out->vertex_ns = st->vertex_ns;
   out->batch_ns = st->batch_ns;
   out->batches = st->batches;
}
