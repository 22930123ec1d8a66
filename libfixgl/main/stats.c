/*
 * fixglStats, fixglResetStats, fixglGetStats: the benchmark's breakdown of
 * a frame (include/fixgl/fixgl.h).
 *
 * The counters live in the context (ctx->Stats).  While they are enabled
 * the raster core's r_state points to them (_Raster.stats; NULL
 * otherwise, so a disabled context pays one well-predicted branch per
 * vertex batch and per primitive), the raster core adds the fragments it
 * shades and its setup and raster time, and t_render_batch times each
 * vertex batch: the vertex stage is the batch's time minus the raster
 * core's time inside it.
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

void fgl_stats_batch_begin(const struct fgl_context *ctx, struct fgl_stats_mark *mark)
{
   mark->raster0 = ctx->Stats.raster.setup_ns + ctx->Stats.raster.raster_ns;
   mark->t0 = now_ns();
}

void fgl_stats_batch_end(struct fgl_context *ctx, const struct fgl_stats_mark *mark)
{
   const uint64_t t1 = now_ns();
   struct fgl_stats *st = &ctx->Stats;
   const uint64_t batch = t1 - mark->t0;
   const uint64_t raster = st->raster.setup_ns + st->raster.raster_ns - mark->raster0;
   st->batch_ns += batch;
   /* the raster core's timers are read inside the batch: its time cannot
    * exceed the batch's, but clamp rather than wrap */
   st->vertex_ns += batch > raster ? batch - raster : 0;
   st->batches++;
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
   const struct fgl_stats *st = &ctx->Stats;
   out->enabled = ctx->_Raster.stats != NULL;
   out->fragments = st->raster.fragments;
   out->setup_ns = st->raster.setup_ns;
   out->raster_ns = st->raster.raster_ns;
   out->vertex_ns = st->vertex_ns;
   out->batch_ns = st->batch_ns;
   out->batches = st->batches;
}
