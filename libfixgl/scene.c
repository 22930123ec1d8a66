/*
 * The context's scene (raster/r_scene.h): the vertex stage bins its
 * primitives and glClear its whole-buffer clears; fgl_scene_flush
 * rasterizes them, tile by tile on FIXGL_NUM_THREADS threads (the calling
 * thread and workers of raster/r_pool.c), before anything reads or
 * replaces the framebuffer or the textures the scene samples:
 * glFlush/glFinish (and so OSMesaMakeCurrent's change of binding),
 * glReadPixels, glCopyPixels, glDrawPixels and glBitmap (drawn at once),
 * glAccum, glCopyTex(Sub)Image, any change of a texture image, scissored
 * or masked clears, OSMesaGetDepthBuffer, context destruction; or when the
 * scene is full (R_SCENE_MAX_BYTES).
 *
 * With one thread (FIXGL_NUM_THREADS=1) nothing is binned: the primitives
 * and clears are drawn at once on the calling thread, as the tiles would
 * draw them (the same code, the region not cut).  Binning, and replaying
 * a primitive's setup in every tile it touches, only pays when other
 * threads share the tiles: on one thread it cost 25-45% more CPU time a
 * frame (gears, sphere, lit200) than drawing directly.
 */
#include <stdlib.h>
#include <string.h>

#include "context.h"
#include "fgl_alloc.h"
#include "raster/r_pool.h"

/* FIXGL_NUM_THREADS: a positive number, else the online CPUs (at most
 * FGL_MAX_THREADS) */
unsigned fgl_num_threads(void)
{
   const char *e = getenv("FIXGL_NUM_THREADS");
   unsigned n = 0;
   if (e && *e) {
      char *end;
      const long v = strtol(e, &end, 10);
      if (*end == '\0' && v > 0)
         n = v > FGL_MAX_THREADS ? FGL_MAX_THREADS : (unsigned)v;
   }
   if (n == 0)
      n = r_pool_cpus();
   return n > FGL_MAX_THREADS ? FGL_MAX_THREADS : n;
}

struct tile_job {
   const struct r_scene *scene;   /* NULL: no commands */
   struct r_stats stats[FGL_MAX_THREADS];
   /* the copy of each tile to the owner's buffer after it is drawn, or
    * NULL: tiles_x columns of 64x64 tiles of the framebuffer */
   struct fgl_framebuffer *front;
   int tiles_x;
};

static void run_tile(void *arg, unsigned item, unsigned slot)
{
   struct tile_job *j = arg;
   if (j->scene)
      r_scene_run_tile(j->scene, item, &j->stats[slot]);
   if (j->front) {
      struct fgl_framebuffer *fb = j->front;
      const int x0 = (int)(item % (unsigned)j->tiles_x) * R_TILE_SIZE;
      const int y0 = (int)(item / (unsigned)j->tiles_x) * R_TILE_SIZE;
      const int x1 = x0 + R_TILE_SIZE < fb->Width ? x0 + R_TILE_SIZE : fb->Width;
      const int y1 = y0 + R_TILE_SIZE < fb->Height ? y0 + R_TILE_SIZE : fb->Height;
      fb->FlushFrontRect(fb, x0, y0, x1, y1);
   }
}

/* The scene rasterized by the workers while the context bins the next
 * one (ctx->_SceneAsync): the vertex stage and the binning of a frame's
 * later primitives overlap with the rasterization of its earlier ones.
 * A scene is handed over only when the previous one has finished, and
 * every flush waits for it first, so each tile still sees its commands
 * in submission order, whatever the threads. */
struct fgl_scene_async {
   struct r_scene scene;
   struct tile_job tiles;
   struct r_job job;
   bool busy;                     /* submitted, not yet waited for */
};

/* Past this many commands, a scene is handed to the workers when they
 * are idle: a job costs a wake-up and a pass over the tiles, which a few
 * hundred primitives pay for. */
#define ASYNC_MIN_CMDS 512u

static void add_stats(struct fgl_context *ctx, const struct tile_job *j, uint64_t ns)
{
   fgl_stats_flush(ctx, ns);
   for (unsigned t = 0; t < ctx->_NumThreads; t++) {
      ctx->Stats.raster.fragments += j->stats[t].fragments;
      ctx->Stats.raster.setup_ns += j->stats[t].setup_ns;
      ctx->Stats.raster.raster_ns += j->stats[t].raster_ns;
   }
}

/* Waits for the scene in the workers' hands, if any (the calling thread
 * takes the tiles they have not started), and empties it. */
static void wait_async(struct fgl_context *ctx)
{
   struct fgl_scene_async *a = ctx->_SceneAsync;
   if (!a || !a->busy)
      return;
   const bool stats = a->scene.stats;
   const uint64_t t0 = stats ? r_stats_now() : 0;
   r_pool_wait(&a->job);
   a->busy = false;
   if (stats)
      add_stats(ctx, &a->tiles, r_stats_now() - t0);
   r_scene_reset(&a->scene);
}

/* After a primitive was binned: hands the scene to the workers when it is
 * big enough and they have finished the previous one. */
static void maybe_hand_over(struct fgl_context *ctx)
{
   struct r_scene *s = &ctx->_Scene;
   if (s->ncmds < ASYNC_MIN_CMDS)
      return;
   struct fgl_scene_async *a = ctx->_SceneAsync;
   if (!a) {
      a = fgl_calloc(1, sizeof(*a));
      if (!a)
         return;   /* drawn at the next flush, as without it */
      ctx->_SceneAsync = a;
   }
   if (a->busy) {
      if (!r_pool_finished(&a->job))
         return;
      wait_async(ctx);
   }
   /* the binned scene goes to the workers, the emptied one takes its
    * place (each keeps its memory) */
   const struct r_scene t = a->scene;
   a->scene = *s;
   *s = t;
   a->tiles.scene = &a->scene;
   memset(a->tiles.stats, 0, sizeof(a->tiles.stats));
   a->tiles.front = NULL;
   a->tiles.tiles_x = a->scene.tiles_x;
   a->job = (struct r_job){
      .run = run_tile,
      .arg = &a->tiles,
      .count = r_scene_tiles(&a->scene),
      .threads = ctx->_NumThreads,
   };
   a->busy = true;
   r_pool_submit(&a->job);
}

void fgl_scene_fini(struct fgl_context *ctx)
{
   wait_async(ctx);
   r_scene_fini(&ctx->_Scene);
   if (ctx->_SceneAsync) {
      r_scene_fini(&ctx->_SceneAsync->scene);
      fgl_free(ctx->_SceneAsync);
      ctx->_SceneAsync = NULL;
   }
}

/* Runs the scene's tiles (when it has commands) and the copy of the tiles
 * of `front` (when not NULL), then empties the scene. */
static void run_scene(struct fgl_context *ctx, struct fgl_framebuffer *front)
{
   wait_async(ctx);
   struct r_scene *s = &ctx->_Scene;
   const bool draw = !r_scene_empty(s);
   if (!draw && !front) {
      r_scene_reset(s);
      return;
   }
   struct tile_job j;
   j.scene = draw ? s : NULL;
   memset(j.stats, 0, sizeof(j.stats));
   j.front = front;
   unsigned count;
   if (draw) {
      j.tiles_x = s->tiles_x;
      count = r_scene_tiles(s);
   } else {
      j.tiles_x = (front->Width + R_TILE_SIZE - 1) / R_TILE_SIZE;
      count = (unsigned)(j.tiles_x * ((front->Height + R_TILE_SIZE - 1) / R_TILE_SIZE));
   }
   struct r_job job = {
      .run = run_tile,
      .arg = &j,
      .count = count,
      .threads = ctx->_NumThreads,
   };
   const uint64_t t0 = s->stats ? r_stats_now() : 0;
   r_pool_run(&job);
   if (s->stats)
      add_stats(ctx, &j, r_stats_now() - t0);
   r_scene_reset(s);
}

void fgl_scene_flush(struct fgl_context *ctx)
{
   run_scene(ctx, NULL);
}

void fgl_scene_flush_front(struct fgl_context *ctx)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   struct r_scene *s = &ctx->_Scene;
   wait_async(ctx);
   /* by tiles when the scene's tiles are the framebuffer's (a scene for
    * other buffers, if any, is drawn first); with one thread the
    * buffer was drawn directly, and the copy row by row of the whole
    * buffer (FlushFront) streams better than by tiles */
   if (ctx->_NumThreads > 1 && fb && fb->FlushFrontRect && fb->ColorDefined &&
       (r_scene_empty(s) || (s->fb->color == fb->Color && s->fb->width == fb->Width &&
                             s->fb->height == fb->Height))) {
      fb->ColorDefined = false;
      run_scene(ctx, fb);
      if (fb->FlushFrontEnd)
         fb->FlushFrontEnd(fb);
      return;
   }
   fgl_scene_flush(ctx);
   if (fb && fb->FlushFront)
      fb->FlushFront(fb);
}

void fgl_raster_triangle(struct fgl_context *ctx, const struct r_state *rs,
                         const struct r_vertex *v0, const struct r_vertex *v1,
                         const struct r_vertex *v2)
{
   if (ctx->_NumThreads == 1) {
      r_triangle(rs, v0, v1, v2);
      return;
   }
   if (r_scene_triangle(&ctx->_Scene, rs, v0, v1, v2)) {
      maybe_hand_over(ctx);
      return;
   }
   fgl_scene_flush(ctx);
   if (!r_scene_triangle(&ctx->_Scene, rs, v0, v1, v2))
      r_triangle(rs, v0, v1, v2);   /* out of memory: drawn now, in order */
}

void fgl_raster_line(struct fgl_context *ctx, const struct r_state *rs,
                     const struct r_vertex *v0, const struct r_vertex *v1)
{
   if (ctx->_NumThreads == 1) {
      r_line(rs, v0, v1);
      return;
   }
   if (r_scene_line(&ctx->_Scene, rs, v0, v1)) {
      maybe_hand_over(ctx);
      return;
   }
   fgl_scene_flush(ctx);
   if (!r_scene_line(&ctx->_Scene, rs, v0, v1))
      r_line(rs, v0, v1);
}

void fgl_raster_point(struct fgl_context *ctx, const struct r_state *rs,
                      const struct r_vertex *v)
{
   if (ctx->_NumThreads == 1) {
      r_point(rs, v);
      return;
   }
   if (r_scene_point(&ctx->_Scene, rs, v)) {
      maybe_hand_over(ctx);
      return;
   }
   fgl_scene_flush(ctx);
   if (!r_scene_point(&ctx->_Scene, rs, v))
      r_point(rs, v);
}

void fgl_raster_clear(struct fgl_context *ctx, bool color, const uint8_t rgba[4], bool depth,
                      uint32_t zvalue, bool stencil, uint8_t svalue)
{
   const struct r_state *rs = &ctx->_Raster;
   if (ctx->_NumThreads > 1) {
      if (r_scene_clear(&ctx->_Scene, rs, color, rgba, depth, zvalue, stencil, svalue))
         return;
      fgl_scene_flush(ctx);
      if (r_scene_clear(&ctx->_Scene, rs, color, rgba, depth, zvalue, stencil, svalue))
         return;
   }
   if (color)
      r_clear_color(rs, rgba);
   if (depth || stencil)
      r_clear_depth_stencil(rs, depth, zvalue, stencil, svalue);
}
