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
 * With one thread (FIXGL_NUM_THREADS=1) nothing is binned (but in a scene
 * that may take llvmpipe's linear path: fgl_lin_binning, below): the
 * primitives are drawn at once on the calling thread, as the tiles would draw them
 * (the same code, the region not cut).  Binning, and replaying a
 * primitive's setup in every tile it touches, only pays when other
 * threads share the tiles: on one thread it cost 25-45% more CPU time a
 * frame (gears, sphere, lit200) than drawing directly.
 *
 * Lazy clears: a whole-buffer clear only marks the framebuffer's 64x64
 * tiles as holding its value (fb->Lazy); a tile's memory is written with
 * it just before something draws there (one thread: the tiles of a
 * triangle's box, by the raster core through r_state.lazy, all of them
 * for a line or a point; more threads: a
 * clear with nothing binned before it is lazy, and each tile with
 * commands writes it first, on the thread that then draws the tile),
 * and every other reader or writer of the buffers goes through
 * fgl_scene_flush, which writes all of them.  glFlush/glFinish copies a tile still
 * pending as the clear colour straight into the owner's buffer
 * (osmesa.c), so the pixels no primitive touched are written once a
 * frame instead of three times (clear, read, copy).  The bytes that
 * anyone can see are the same.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

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
   /* the tile of each item (r_scene_tile_order), or NULL: item order */
   const uint32_t *order;
   /* the framebuffer whose lazy clears (fb->Lazy) a tile with commands
    * writes first, or NULL */
   struct fgl_framebuffer *lazy;
};

static void lazy_resolve_tiles(struct fgl_framebuffer *fb, unsigned what, int tx0, int ty0,
                               int tx1, int ty1);

static void run_tile(void *arg, unsigned item, unsigned slot)
{
   struct tile_job *j = arg;
   if (j->order)
      item = j->order[item];
   if (j->scene) {
      /* a tile that is drawn holds its lazy clears first (each tile's
       * byte is this thread's alone during the job) */
      if (j->lazy && j->scene->bins[item].count) {
         const int tx = (int)(item % (unsigned)j->scene->tiles_x);
         const int ty = (int)(item / (unsigned)j->scene->tiles_x);
         lazy_resolve_tiles(j->lazy, FGL_LAZY_COLOR | FGL_LAZY_ZS, tx, ty, tx, ty);
      }
      /* the oracle's rasterizer threads run with denormals flushed
       * (lp_rast.c thread_function, util_fpstate_set_denorms_to_zero), as
       * the draw did (tnl/t_render.c): a worker's MXCSR is its own, and
       * the calling thread restored its own after the draw (fuzzer seed
       * 3000366: perspective planes of w = 1.5e35, ORACLE-NOTES.md
       * "Clamps and NaN") */
#if defined(__SSE__) || defined(__x86_64__)
      const unsigned mxcsr = _mm_getcsr();
      _mm_setcsr(mxcsr | 0x8040u);   /* FTZ (bit 15) | DAZ (bit 6) */
#endif
      r_scene_run_tile(j->scene, item, &j->stats[slot], slot);
#if defined(__SSE__) || defined(__x86_64__)
      _mm_setcsr(mxcsr);
#endif
   }
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
   /* the tile orders (r_scene_tile_order) of `scene` [1] and of the
    * context's scene when a flush runs it [0] */
   uint32_t *order[2];
   unsigned order_capacity[2];
};

/* Scene s's tiles in the order the threads of job take them (its lanes,
 * one a thread), in a's buffer `which`; NULL (index order, one lane) when
 * out of memory. */
static const uint32_t *tile_order(struct fgl_scene_async *a, int which, const struct r_scene *s,
                                  struct r_job *job)
{
   const unsigned n = r_scene_tiles(s);
   if (n > a->order_capacity[which]) {
      uint32_t *o = fgl_realloc(a->order[which], (size_t)n * sizeof(*o));
      if (!o)
         return NULL;
      a->order[which] = o;
      a->order_capacity[which] = n;
   }
   _Static_assert(R_SCENE_MAX_LANES <= R_POOL_MAX_LANES, "a lane per thread");
   job->lanes = job->threads < R_SCENE_MAX_LANES ? job->threads : R_SCENE_MAX_LANES;
   r_scene_tile_order(s, job->lanes, a->order[which], job->lane_end);
   return a->order[which];
}

/* The context's fgl_scene_async, made on first use; NULL when out of
 * memory. */
static struct fgl_scene_async *scene_async(struct fgl_context *ctx)
{
   if (!ctx->_SceneAsync)
      ctx->_SceneAsync = fgl_calloc(1, sizeof(*ctx->_SceneAsync));
   return ctx->_SceneAsync;
}

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

/* The framebuffer whose pending lazy clears the tiles of scene s write
 * before drawing (tile_job.lazy): the context's, when s draws into it;
 * when s draws elsewhere, they are all written now. */
static struct fgl_framebuffer *scene_lazy_fb(struct fgl_context *ctx, const struct r_scene *s)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   if (!fb || !fb->Lazy.pending)
      return NULL;
   if (!r_scene_empty(s) &&
       (s->fb->color != fb->Color || s->fb->width != fb->Width || s->fb->height != fb->Height)) {
      fgl_lazy_resolve(fb, FGL_LAZY_COLOR | FGL_LAZY_ZS);
      return NULL;
   }
   return fb;
}

/* After a primitive was binned: hands the scene to the workers when it is
 * big enough and they have finished the previous one. */
static void maybe_hand_over(struct fgl_context *ctx)
{
   struct r_scene *s = &ctx->_Scene;
   /* (a scene that may take the linear path is held whole until the
    * oracle's flush: its tiles decide then) */
   if (s->ncmds < ASYNC_MIN_CMDS || fgl_lin_binning(ctx))
      return;
   struct fgl_scene_async *a = scene_async(ctx);
   if (!a)
      return;   /* drawn at the next flush, as without it */
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
   a->tiles.lazy = scene_lazy_fb(ctx, &a->scene);
   a->job = (struct r_job){
      .run = run_tile,
      .arg = &a->tiles,
      .count = r_scene_tiles(&a->scene),
      .threads = ctx->_NumThreads,
   };
   a->tiles.order = tile_order(a, 1, &a->scene, &a->job);
   a->busy = true;
   r_pool_submit(&a->job);
}

void fgl_scene_fini(struct fgl_context *ctx)
{
   wait_async(ctx);
   r_scene_fini(&ctx->_Scene);
   if (ctx->_SceneAsync) {
      r_scene_fini(&ctx->_SceneAsync->scene);
      fgl_free(ctx->_SceneAsync->order[0]);
      fgl_free(ctx->_SceneAsync->order[1]);
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
   j.lazy = draw ? scene_lazy_fb(ctx, s) : NULL;
   struct r_job job = {
      .run = run_tile,
      .arg = &j,
      .threads = ctx->_NumThreads,
   };
   j.order = NULL;
   if (draw) {
      j.tiles_x = s->tiles_x;
      job.count = r_scene_tiles(s);
      struct fgl_scene_async *a = ctx->_NumThreads > 1 ? scene_async(ctx) : NULL;
      if (a)
         j.order = tile_order(a, 0, s, &job);
   } else {
      j.tiles_x = (front->Width + R_TILE_SIZE - 1) / R_TILE_SIZE;
      job.count = (unsigned)(j.tiles_x * ((front->Height + R_TILE_SIZE - 1) / R_TILE_SIZE));
   }
   const uint64_t t0 = s->stats ? r_stats_now() : 0;
   r_pool_run(&job);
   if (s->stats)
      add_stats(ctx, &j, r_stats_now() - t0);
   r_scene_reset(s);
}

/* ---- Lazy clears ---- */

/* writes `what` of the tiles tx0..tx1, ty0..ty1 (inclusive, in range) */
static void lazy_resolve_tiles(struct fgl_framebuffer *fb, unsigned what, int tx0, int ty0,
                               int tx1, int ty1)
{
   const struct r_fb_state fbs = fgl_fb_raster_state(fb);
   r_lazy_resolve_tiles(&fb->Lazy, &fbs, what, tx0, ty0, tx1, ty1);
}

void fgl_lazy_resolve(struct fgl_framebuffer *fb, unsigned what)
{
   if (!fb || !(fb->Lazy.pending & what))
      return;
   lazy_resolve_tiles(fb, what, 0, 0, fb->Lazy.tiles_x - 1, fb->Lazy.tiles_y - 1);
   fb->Lazy.pending &= ~what;
}

void fgl_lazy_fini(struct fgl_framebuffer *fb)
{
   fgl_free(fb->Lazy.tiles);
   memset(&fb->Lazy, 0, sizeof(fb->Lazy));
}

/* Records a whole-buffer clear of fb; false when it must be done now
 * (no memory for the tiles) */
static bool lazy_clear(struct fgl_framebuffer *fb, bool color, const uint8_t rgba[4], bool depth,
                       uint32_t zvalue, bool stencil, uint8_t svalue)
{
   struct r_lazy_clear *lz = &fb->Lazy;
   const int tx = (fb->Width + R_TILE_SIZE - 1) / R_TILE_SIZE;
   const int ty = (fb->Height + R_TILE_SIZE - 1) / R_TILE_SIZE;
   if (!lz->tiles || lz->tiles_x != tx || lz->tiles_y != ty) {
      fgl_lazy_resolve(fb, FGL_LAZY_COLOR | FGL_LAZY_ZS);
      fgl_free(lz->tiles);
      lz->tiles = fgl_calloc((size_t)tx * (size_t)ty, 1);
      lz->pending = 0;
      if (!lz->tiles)
         return false;
      lz->tiles_x = tx;
      lz->tiles_y = ty;
   }
   /* a depth/stencil clear of other buffers than the pending one (depth
    * alone, then stencil alone) writes the pending one first */
   if ((depth || stencil) && (lz->pending & FGL_LAZY_ZS) &&
       (lz->depth != depth || lz->stencil != stencil))
      fgl_lazy_resolve(fb, FGL_LAZY_ZS);
   unsigned bits = 0;
   if (color) {
      memcpy(lz->rgba, rgba, 4);
      bits |= FGL_LAZY_COLOR;
   }
   if (depth || stencil) {
      lz->depth = depth;
      lz->stencil = stencil;
      lz->zvalue = zvalue;
      lz->svalue = svalue;
      bits |= FGL_LAZY_ZS;
   }
   const size_t n = (size_t)tx * (size_t)ty;
   for (size_t i = 0; i < n; i++)
      lz->tiles[i] |= (uint8_t)bits;
   lz->pending |= bits;
   return true;
}

void fgl_scene_flush(struct fgl_context *ctx)
{
   run_scene(ctx, NULL);
   fgl_lazy_resolve(ctx->DrawBuffer, FGL_LAZY_COLOR | FGL_LAZY_ZS);
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
   /* (pending clears stay pending: FlushFront copies them) */
   run_scene(ctx, NULL);
   if (fb && fb->FlushFront)
      fb->FlushFront(fb);
}

/* What the linear path makes of a rectangle (a legacy point: n = 1; a
 * triangle's whole tile: 3) of the current state whose corners are
 * v[0..n-1] (enum r_lin), with
 * ctx->_LinColor set for R_LIN_COLOR: an untextured rectangle of one
 * colour, without fog or secondary colour, blended not at all or by
 * SRC_ALPHA, ONE_MINUS_SRC_ALPHA ("GLX linear arithmetic" rules 1, 2 and
 * 4) is coloured otherwise; other rectangles are drawn alike on both
 * ways (rule 5) or are not probed (other blend functions, logic ops,
 * colour masks, a colour that varies over the rectangle). */
uint8_t fgl_lin_color_kind(struct fgl_context *ctx, const struct r_vertex *const *v, int n)
{
   const struct r_state *rs = &ctx->_Raster;
   const struct r_blend_state *bl = rs->blend;
   const struct r_fs_state *fs = rs->fs;
   const unsigned surf = fgl_fb_channel_mask(ctx->DrawBuffer);
   if ((fs->fs_inputs & ~(1u << R_FS_COLOR0)) != 0 || fs->tex_units != 0 || fs->color_sum ||
       fs->phong || bl->logic_op || (bl->color_mask & surf) != surf)
      return R_LIN_SAME;
   if (bl->enable &&
       (bl->separate_alpha || bl->blend_eq != R_BLEND_ADD || bl->blend_src != R_BF_SRC_ALPHA ||
        bl->blend_dst != R_BF_INV_SRC_ALPHA))
      return R_LIN_SAME;
   if (ctx->_LinColorConst)   /* rule 1: the constant, as set */
      return fgl_lin_const_color(ctx->Current.Attrib[FGL_ATTR_COLOR0], ctx->_LinColor)
                ? R_LIN_COLOR
                : R_LIN_SAME;
   /* a vertex colour: interpolated in 1.15 fixed point over the part of
    * the tile drawn (R_LIN_INTERP, ORACLE-NOTES.md "GLX linear bins" (5);
    * the raster scene takes the planes); a point's, one value: rule 2 */
   if (n > 1)
      return R_LIN_INTERP;
   const float *c = v[0]->attr[R_ATTR_COLOR0];
   for (int i = 0; i < 4; i++) {
      if (!(c[i] >= 0.0f && c[i] <= 1.0f))
         return R_LIN_SAME;
      ctx->_LinColor[i] = (float)(r_lin_ufixed_1_15(c[i]) >> 7) / 255.0f;
   }
   return R_LIN_COLOR;
}

/* ---- The linear path's scenes (fgl_lin_binning) ----
 * Every command is binned, also on one thread, and nothing goes to the
 * workers before the oracle's flush: each tile then decides from all of
 * its commands (r_scene_run_tile).  Triangles carry the vertex stage's
 * classification (_LinTri: a rectangle's or not) and, when the linear
 * path colours them otherwise, vertices with that colour. */
bool fgl_lin_opaque(const struct fgl_context *ctx)
{
   /* lp_state_fs.c variant->opaque: no blending, logic op or alpha test,
    * every channel of the buffer written (no depth or stencil buffer
    * here) */
   const struct r_state *rs = &ctx->_Raster;
   const unsigned surf = fgl_fb_channel_mask(ctx->DrawBuffer);
   return !rs->blend->enable && !rs->blend->logic_op && (rs->blend->color_mask & surf) == surf &&
          !rs->dsa->alpha_test && !rs->samples;
}

static void lin_triangle(struct fgl_context *ctx, const struct r_state *rs,
                         const struct r_vertex *v0, const struct r_vertex *v1,
                         const struct r_vertex *v2)
{
   const struct r_vertex *v[3] = { v0, v1, v2 };
   struct r_lin_tri lt = { ctx->_LinTri, R_LIN_NO, false, NULL, NULL,
                           ctx->_LinRect ? ctx->_LinRectSetup : NULL };
   /* a tile the triangle covers whole is shaded by a tile command
    * (lp_setup_whole_tile), which the linear path takes as it takes a
    * rectangle, an opaque one emptying the tile's bin first */
   if (lt.lin == R_LIN_NO && fgl_lin_permitted(ctx)) {
      lt.whole = fgl_lin_color_kind(ctx, v, 3);
      lt.opaque = fgl_lin_opaque(ctx);
   }
   if (lt.lin == R_LIN_INTERP)
      lt.li = &ctx->_LinInterp;   /* the rectangle's (tnl/t_render.c) */
   struct r_vertex lv[3];
   const struct r_vertex *lp[3] = { &lv[0], &lv[1], &lv[2] };
   if (lt.lin == R_LIN_COLOR || lt.whole == R_LIN_COLOR) {
      for (int i = 0; i < 3; i++) {
         lv[i] = *v[i];
         memcpy(lv[i].attr[R_ATTR_COLOR0], ctx->_LinColor, sizeof(ctx->_LinColor));
      }
      lt.lv = lp;
   }
   struct r_scene *s = &ctx->_Scene;
   if (r_scene_triangle_lin(s, rs, v0, v1, v2, &lt))
      return;
   fgl_scene_flush(ctx);
   if (!r_scene_triangle_lin(s, rs, v0, v1, v2, &lt))
      r_triangle(rs, v0, v1, v2);   /* out of memory: drawn now, in order */
}

void fgl_raster_quad(struct fgl_context *ctx, const struct r_state *rs, float z,
                     const float color[4], const float *lin_color)
{
   const uint8_t lin = !fgl_lin_permitted(ctx) ? R_LIN_NO
                       : lin_color                ? R_LIN_COLOR
                                                  : R_LIN_SAME;
   if (r_scene_quad(&ctx->_Scene, rs, z, color, lin, lin_color))
      return;
   fgl_scene_flush(ctx);
   if (!r_scene_quad(&ctx->_Scene, rs, z, color, lin, lin_color))
      r_clear_quad(rs, z, color);
}

void fgl_raster_triangle(struct fgl_context *ctx, const struct r_state *rs,
                         const struct r_vertex *v0, const struct r_vertex *v1,
                         const struct r_vertex *v2)
{
   if (ctx->_VpCutDirty)
      fgl_vpcut_decide(ctx, false);
   if (ctx->DrawBuffer && ctx->DrawBuffer->DrawBoth) {
      /* into both buffers, directly (main/buffers.c "Both buffers") */
      r_triangle(fgl_both_begin(ctx, rs), v0, v1, v2);
      r_triangle(rs, v0, v1, v2);
      return;
   }
   if (fgl_lin_binning(ctx)) {
      lin_triangle(ctx, rs, v0, v1, v2);
      return;
   }
   if (ctx->_NumThreads == 1) {
      /* (its box's lazy clears are written by rasterize_ccw: rs->lazy) */
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
   if (ctx->_VpCutDirty)
      fgl_vpcut_decide(ctx, false);
   if (ctx->DrawBuffer && ctx->DrawBuffer->DrawBoth) {
      /* into both buffers, directly (main/buffers.c "Both buffers") */
      r_line(fgl_both_begin(ctx, rs), v0, v1);
      r_line(rs, v0, v1);
      return;
   }
   if (fgl_lin_binning(ctx))
      ctx->_Scene.exact = true;   /* its tiles decide */
   else if (ctx->_NumThreads == 1) {
      fgl_lazy_resolve(ctx->DrawBuffer, FGL_LAZY_COLOR | FGL_LAZY_ZS);
      r_line(rs, v0, v1);
      return;
   }
   if (r_scene_line(&ctx->_Scene, rs, v0, v1)) {
      maybe_hand_over(ctx);
      return;
   }
   fgl_scene_flush(ctx);
   ctx->_Scene.exact = fgl_lin_binning(ctx);
   if (!r_scene_line(&ctx->_Scene, rs, v0, v1))
      r_line(rs, v0, v1);
}

void fgl_raster_point(struct fgl_context *ctx, const struct r_state *rs,
                      const struct r_vertex *v)
{
   if (ctx->_VpCutDirty)
      fgl_vpcut_decide(ctx, false);
   if (ctx->DrawBuffer && ctx->DrawBuffer->DrawBoth) {
      /* into both buffers, directly (main/buffers.c "Both buffers") */
      r_point(fgl_both_begin(ctx, rs), v);
      r_point(rs, v);
      return;
   }
   if (fgl_lin_binning(ctx)) {
      const uint8_t lin = ctx->_LinPoint;
      struct r_vertex lv;
      if (lin == R_LIN_COLOR) {
         lv = *v;
         memcpy(lv.attr[R_ATTR_COLOR0], ctx->_LinColor, sizeof(ctx->_LinColor));
      }
      if (r_scene_point_lin(&ctx->_Scene, rs, v, lin, &lv))
         return;
      fgl_scene_flush(ctx);
      if (!r_scene_point_lin(&ctx->_Scene, rs, v, lin, &lv))
         r_point(rs, v);
      return;
   }
   if (ctx->_NumThreads == 1) {
      fgl_lazy_resolve(ctx->DrawBuffer, FGL_LAZY_COLOR | FGL_LAZY_ZS);
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
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   const bool fb_match = fb && rs->fb->color == fb->Color && rs->fb->width == fb->Width &&
                         rs->fb->height == fb->Height;
   if (color && fb && fb->DrawBoth)   /* the other buffer now (main/buffers.c) */
      r_clear_color(fgl_both_begin(ctx, rs), rgba);
   if (ctx->_NumThreads > 1 || fgl_lin_binning(ctx)) {
      /* a clear with nothing binned before it (a frame's first) is lazy
       * too: the tiles that the scene then draws write it first
       * (run_tile), the others are copied as its colour */
      if (fb_match && r_scene_empty(&ctx->_Scene)) {
         wait_async(ctx);   /* no worker reads the tiles' bytes now */
         if (lazy_clear(fb, color, rgba, depth, zvalue, stencil, svalue))
            return;
      }
      if (r_scene_clear(&ctx->_Scene, rs, color, rgba, depth, zvalue, stencil, svalue))
         return;
      fgl_scene_flush(ctx);
      if (r_scene_clear(&ctx->_Scene, rs, color, rgba, depth, zvalue, stencil, svalue))
         return;
   }
   if (ctx->_NumThreads == 1 && fb_match && r_scene_empty(&ctx->_Scene) &&
       lazy_clear(fb, color, rgba, depth, zvalue, stencil, svalue))
      return;
   if (color)
      r_clear_color(rs, rgba);
   if (depth || stencil)
      r_clear_depth_stencil(rs, depth, zvalue, stencil, svalue);
}
