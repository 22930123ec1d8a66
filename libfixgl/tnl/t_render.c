/*
 * Primitive assembly: immediate-mode primitives to triangles, in the vertex
 * orders the oracle uses (ORACLE-NOTES.md "Primitive decomposition and
 * the provoking vertex"; Mesa lp_setup_vbuf.c and draw_decompose_tmp.h),
 * with the
 * provoking vertex last in every triangle:
 *   TRIANGLES       (i, i+1, i+2)
 *   TRIANGLE_STRIP  (i, i+1, i+2) for even i, (i+1, i, i+2) for odd i
 *   TRIANGLE_FAN    (0, i+1, i+2)
 *   POLYGON         (i+1, i+2, 0)      provoking vertex = first vertex
 *   QUADS           (0,1,2)+(0,2,3) on llvmpipe's direct path,
 *                   (0,1,3)+(1,2,3) with a flat colour input or through
 *                   the draw pipeline
 *   QUAD_STRIP      direct:   (k,k+1,k+3) then (k+2,k,k+3)
 *                   pipeline: (k+2,k,k+3) then (k,k+1,k+3)
 *   POINTS, LINES   each vertex, each pair (i, i+1)
 *   LINE_STRIP/LOOP (i-1, i), closed by (n-1, 0)   provoking vertex = 2nd
 * A draw goes through the draw pipeline, segment by segment (Mesa's vsplit:
 * 4096 vertices, 4095 for GL_TRIANGLES, 1024-vertex fan segments for fans
 * and polygons longer than 4096), when any vertex of the segment needs
 * clipping; triangles also as a whole when the state needs the pipeline's
 * stages (draw_need_pipeline: ctx->_DrawPipeline.always).  Each triangle
 * carries the flags of draw's decomposition (draw_decompose_tmp.h): which of
 * its edges are polygon edges (for unfilled modes, with the per-vertex edge
 * flags) and whether it starts a primitive (line stipple restart).
 */
#include "tnl/t_pipeline.h"

#include <stdlib.h>
#include <string.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "context.h"
#include "main/groups.h"
#include "fgl_alloc.h"
#include "raster/r_kernel.h"

#define SEGMENT_SIZE 4096

/* A batch of triangles, strips, quads and quad strips of more than
 * 2 * LAZY_WINDOW vertices, not indexed, is transformed LAZY_WINDOW
 * vertices at a time as its primitives reach them (need_prim) rather
 * than all at once before drawing: the window's transformed vertices
 * (60 KiB) stay in the cache from the vertex stage to the triangle
 * setup, where the whole batch's (up to 65535 of 320 bytes) went to
 * memory and back.  The clip codes that choose each vsplit segment's
 * path come from a pass over the segment's positions first
 * (t_clip_masks_any, the same arithmetic).  A multiple of 3 and 4. */
#define LAZY_WINDOW 192

/* A draw whose vertices are fetched window by window (t_render_source):
 * vertices [first, first + n) of the draw are in[] and, transformed, tv[];
 * vertex 0 is v0 as well (the first vertex of fans, polygons and loops,
 * which every segment uses). */
struct render_window {
   const struct t_vertex_source *src;   /* NULL: a lazy batch (view) */
   const struct fgl_vertex_view *view;  /* a lazy batch's stored vertices */
   enum t_edge_source edges;
   unsigned count;               /* vertices of the draw */
   unsigned first, n;
   struct fgl_vbo_vertex *in;    /* SEGMENT_SIZE fetched vertices */
   struct t_vertex *tv;          /* SEGMENT_SIZE transformed vertices */
   struct t_vertex v0;
};

struct render {
   struct fgl_context *ctx;
   struct render_window *win;    /* NULL: every vertex is in v */
   const struct t_vertex *v;     /* transformed vertices of the draw */
   const struct fgl_vertex_view *in;   /* the stored vertices */
   /* an indexed draw's vertex cache: vertex i of the primitives is
    * v[elts[i]] (NULL: v[i]) */
   const unsigned *elts;
   /* GL_PHONG_WIN with materials in the batch's vertex format (glMaterial
    * between glBegin and glEnd): bit a - FGL_ATTR_MAT_FIRST for each */
   unsigned phong_mats;
   /* the scene may take llvmpipe's linear path and the setup has no
    * constant-interpolated input: pairs of triangles may be rectangles
    * (tri_pair) */
   bool lin;
};

/* Where vertex i of the draw's primitives is. */
static inline unsigned elt(const struct render *r, unsigned i)
{
   return r->elts ? r->elts[i] : i;
}

static inline const struct t_vertex *vtx(const struct render *r, unsigned i)
{
   if (__builtin_expect(r->win != NULL, 0)) {
      const struct render_window *w = r->win;
      /* need() made every vertex but vertex 0 resident (none of a
       * uniform draw's) */
      return i - w->first < w->n ? &w->tv[i - w->first] : &w->v0;
   }
   return &r->v[elt(r, i)];
}

/* Vertices [start, start + count) of a windowed draw fetched and
 * transformed (count <= SEGMENT_SIZE): the window moves to start, as many
 * vertices as it holds.  A vertex is transformed the same wherever its
 * window starts, so the bytes are those of a whole draw. */
static void need(const struct render *r, unsigned start, unsigned count)
{
   struct render_window *w = r->win;
   if (!w || w->view || w->src->uniform ||
       (start >= w->first && start - w->first + count <= w->n))
      return;
   const unsigned n = w->count - start < SEGMENT_SIZE ? w->count - start : SEGMENT_SIZE;
   w->src->fetch(w->src->ud, start, n, w->in);
   const struct fgl_vertex_view view = fgl_vertex_view_full(w->in);
   t_transform(r->ctx, &view, n, w->tv, w->edges);
   w->first = start;
   w->n = n;
}

/* A lazy batch (LAZY_WINDOW): vertices [start, start + count) of a
 * primitive ending at `end` transformed, the window moved to start when
 * they are not all in it. */
static inline void need_prim(const struct render *r, unsigned start, unsigned count,
                             unsigned end)
{
   struct render_window *w = r->win;
   if (!w || !w->view || (start >= w->first && start - w->first + count <= w->n))
      return;
   const unsigned n = end - start < LAZY_WINDOW ? end - start : LAZY_WINDOW;
   const struct fgl_vertex_view view = fgl_vv_from(w->view, start);
   t_transform(r->ctx, &view, n, w->tv, w->edges);
   w->first = start;
   w->n = n;
}

/* GL_PHONG_WIN (include/fixgl/shading.md): a primitive is lit with the
 * material current at its provoking vertex pv; the properties the batch
 * stores per vertex replace the shading environment's current ones
 * (t_phong.c and r_fragment_phong read no material per vertex).  (Points
 * and lines queued in the polygon stipple's vbuf batch, t_linepoint.c, are
 * drawn with the material of the primitive that flushes them.) */
static void phong_material(const struct render *r, unsigned pv)
{
   struct fgl_context *ctx = r->ctx;
   struct m_shade_env *env = &ctx->_ShadeEnv;
   const unsigned vi = elt(r, pv);
   for (unsigned m = r->phong_mats; m; m &= m - 1) {
      const int a = FGL_ATTR_MAT_FIRST + __builtin_ctz(m);
      struct m_shade_material *mat = &env->material[(a - FGL_ATTR_MAT_FIRST) & 1];
      switch ((a - FGL_ATTR_MAT_FIRST) >> 1) {
      case 0: memcpy(mat->ambient, fgl_vv_attr(r->in, vi, a), sizeof(mat->ambient)); break;
      case 1: memcpy(mat->diffuse, fgl_vv_attr(r->in, vi, a), sizeof(mat->diffuse)); break;
      case 2: memcpy(mat->specular, fgl_vv_attr(r->in, vi, a), sizeof(mat->specular)); break;
      case 3: memcpy(mat->emission, fgl_vv_attr(r->in, vi, a), sizeof(mat->emission)); break;
      case 4: mat->shininess = fgl_vv_attr(r->in, vi, a)[0]; break;
      default: break;   /* colour indexes */
      }
   }
   fgl_set_shade_env(ctx);   /* out of memory: the last environment */
}

/* A triangle with provoking vertex pv; `pipeline`: its vsplit segment
 * takes draw's pipeline; flags: draw's decomposition flags (T_EDGE_*,
 * T_RESET_STIPPLE). */
static inline void tri_pv(const struct render *r, unsigned a, unsigned b, unsigned c,
                          unsigned pv, bool pipeline, unsigned flags)
{
   if (r->phong_mats)
      phong_material(r, pv);
   t_clip_triangle(r->ctx, vtx(r, a), vtx(r, b), vtx(r, c), pipeline, flags);
}

/* A triangle whose last vertex is the provoking vertex. */
static inline void tri(const struct render *r, unsigned a, unsigned b, unsigned c,
                       bool pipeline, unsigned flags)
{
   tri_pv(r, a, b, c, c, pipeline, flags);
}

/* ---- llvmpipe's rectangles (ORACLE-NOTES.md "GLX linear rectangles") ----
 * In a scene that may take the linear path, llvmpipe's setup takes two
 * triangles of its direct path (a quad's (0,1,2)+(0,2,3), a pair of
 * GL_TRIANGLES, a fan of four vertices) that form an axis-aligned
 * rectangle as one rectangle command [S: lp_setup_vbuf.c rect(),
 * lp_setup_rect.c setup_rect_both/_ccw/_cw, do_rect_ccw]: the two
 * windings equal and not zero; two corners shared (the six joinings of
 * do_rect_ccw, positions compared whole); the four corners pairwise on
 * one x and one y; one w; every input of the fragment program affine
 * over the corners (the differences along each side equal).  A 64 x 64
 * bin whose commands are all such rectangles (and clears) is drawn by
 * the linear path, which colours an untextured rectangle otherwise:
 * "GLX linear arithmetic". */

/* <0: counter-clockwise, >0: clockwise, 0: none, as lp_setup_rect.c's
 * winding() */
static int lin_winding(const struct r_vertex *v0, const struct r_vertex *v1,
                       const struct r_vertex *v2)
{
   const float ex = v0->pos[0] - v2->pos[0], ey = v0->pos[1] - v2->pos[1];
   const float fx = v1->pos[0] - v2->pos[0], fy = v1->pos[1] - v2->pos[1];
   const float det = ex * fy - ey * fx;
   return det < 0.0f ? -1 : det > 0.0f ? 1 : 0;
}

static bool same_pos(const struct r_vertex *a, const struct r_vertex *b)
{
   return a->pos[0] == b->pos[0] && a->pos[1] == b->pos[1] && a->pos[2] == b->pos[2] &&
          a->pos[3] == b->pos[3];
}

/* do_rect_ccw: the rectangle's corners rv[0..3] (counter-clockwise) of
 * two counter-clockwise triangles v[0..2], v[3..5], or false */
static bool lin_rect_corners(const struct r_vertex *const v[6], const struct r_vertex *rv[4])
{
#define RV(A, B, C, D) (rv[0] = v[A], rv[1] = v[B], rv[2] = v[C], rv[3] = v[D], true)
   if (same_pos(v[0], v[3]))
      return same_pos(v[2], v[4])   ? RV(5, 0, 1, 2)
             : same_pos(v[1], v[5]) ? RV(4, 1, 2, 0)
                                    : false;
   if (same_pos(v[0], v[5]))
      return same_pos(v[2], v[3])   ? RV(4, 0, 1, 2)
             : same_pos(v[1], v[4]) ? RV(3, 1, 2, 0)
                                    : false;
   if (same_pos(v[0], v[4]))
      return same_pos(v[2], v[5])   ? RV(3, 0, 1, 2)
             : same_pos(v[1], v[3]) ? RV(5, 1, 2, 0)
                                    : false;
   if (same_pos(v[2], v[3]))
      return same_pos(v[1], v[4]) ? RV(5, 2, 0, 1) : false;
   if (same_pos(v[2], v[5]))
      return same_pos(v[1], v[3]) ? RV(4, 2, 0, 1) : false;
   if (same_pos(v[2], v[4]))
      return same_pos(v[1], v[5]) ? RV(3, 2, 0, 1) : false;
   return false;
#undef RV
}

/* The classification of the triangles (a0,a1,a2), (b0,b1,b2) in a scene
 * that may take the linear path (enum r_lin), with ctx->_LinColor set
 * for R_LIN_COLOR; the rectangle's pixel box in box when it is opaque
 * (it then covers whole tiles: r_scene_cover), else box[0] = box[2]. */
static uint8_t lin_classify(struct fgl_context *ctx, const struct r_vertex *a0,
                            const struct r_vertex *a1, const struct r_vertex *a2,
                            const struct r_vertex *b0, const struct r_vertex *b1,
                            const struct r_vertex *b2, int box[4])
{
   const struct r_state *rs = &ctx->_Raster;
   box[0] = box[2] = 0;
   const int w0 = lin_winding(a0, a1, a2), w1 = lin_winding(b0, b1, b2);
   if (w0 != w1 || w0 == 0)
      return R_LIN_NO;
   const struct r_vertex *v[6] = { a0, a1, a2, b0, b1, b2 };
   if (w0 > 0) {   /* clockwise: do_rect_ccw(v0, v2, v1, v3, v5, v4) */
      v[1] = a2;
      v[2] = a1;
      v[4] = b2;
      v[5] = b1;
   }
   const struct r_vertex *rv[4];
   if (!lin_rect_corners(v, rv))
      return R_LIN_NO;
   if (rv[0]->pos[1] == rv[1]->pos[1]) {
      const struct r_vertex *t = rv[0];
      rv[0] = rv[1];
      rv[1] = rv[2];
      rv[2] = rv[3];
      rv[3] = t;
   }
   if (!(rv[0]->pos[0] == rv[1]->pos[0] && rv[2]->pos[0] == rv[3]->pos[0] &&
         rv[0]->pos[1] == rv[3]->pos[1] && rv[1]->pos[1] == rv[2]->pos[1]))
      return R_LIN_NO;
   if (rv[1]->pos[3] != rv[0]->pos[3] || rv[2]->pos[3] != rv[0]->pos[3] ||
       rv[3]->pos[3] != rv[0]->pos[3])
      return R_LIN_NO;
   for (unsigned m = rs->fs->fs_inputs; m; m &= m - 1) {
      const int slot = r_fs_slot(__builtin_ctz(m), false);
      for (int c = 0; c < 4; c++) {
         const float dx1 = rv[0]->attr[slot][c] - rv[3]->attr[slot][c];
         const float dx2 = rv[1]->attr[slot][c] - rv[2]->attr[slot][c];
         const float dy1 = rv[0]->attr[slot][c] - rv[1]->attr[slot][c];
         const float dy2 = rv[3]->attr[slot][c] - rv[2]->attr[slot][c];
         if (dx1 != dx2 || dy1 != dy2)
            return R_LIN_NO;
      }
   }
   /* the rectangle's pixels, as try_rect_cw bounds them:
    * subpixel_snap(v - 0.5), x (s + 255) >> 8, y with the window buffers'
    * bottom_edge_rule (s + 256) >> 8 (r_point.c's adj) */
   int rbox[4] = { 0, 0, 0, 0 };
   {
      float x0 = rv[0]->pos[0], x1 = rv[2]->pos[0], y0 = rv[0]->pos[1], y1 = rv[1]->pos[1];
      if (x0 > x1) { const float t = x0; x0 = x1; x1 = t; }
      if (y0 > y1) { const float t = y0; y0 = y1; y1 = t; }
      const float lim = 0x1p20f;
      if (!(fabsf(x0) < lim && fabsf(x1) < lim && fabsf(y0) < lim && fabsf(y1) < lim))
         return R_LIN_NO;
      rbox[0] = (r_subpixel_snap(x0 - 0.5f) + 255) >> 8;
      rbox[2] = (r_subpixel_snap(x1 - 0.5f) + 255) >> 8;
      rbox[1] = (r_subpixel_snap(y0 - 0.5f) + 256) >> 8;
      rbox[3] = (r_subpixel_snap(y1 - 0.5f) + 256) >> 8;
   }
   /* a rectangle of rect(): set up from its corners as try_rect_cw does
    * (lp_rect_cw(rv0, rv2, rv1)), its planes shade both triangles
    * (lp_rast_rectangle, whichever path the tile takes) */
   if (!ctx->_LinRectSetup) {
      ctx->_LinRectSetup = fgl_malloc(sizeof(*ctx->_LinRectSetup));
      if (!ctx->_LinRectSetup)
         return R_LIN_NO;   /* (out of memory: as two triangles) */
   }
   struct r_tri_setup *ts = ctx->_LinRectSetup;
   r_tri_setup_as_given(rs, rv[0], rv[2], rv[1], ts);
   ctx->_LinRect = true;
   /* opaque (fgl_lin_opaque): it empties the tiles it covers */
   if (fgl_lin_opaque(ctx))
      memcpy(box, rbox, sizeof(rbox));
   if (!fgl_lin_permitted(ctx))
      return R_LIN_NO;   /* a scene that does not take the linear path */
   const uint8_t kind = fgl_lin_color_kind(ctx, rv, 4);
   if (kind == R_LIN_INTERP) {
      struct r_lin_interp *li = &ctx->_LinInterp;
      memcpy(li->c, ts->ap[R_FS_COLOR0], sizeof(li->c));
      li->w_a0 = ts->w.a0;
      memcpy(li->box, rbox, sizeof(rbox));
      if (++ctx->_LinInterpId == 0)
         ctx->_LinInterpId = 1;
      li->id = ctx->_LinInterpId;
   }
   return kind;
}

/* The classification of a pair (lin_classify) for the raster scene
 * (ctx->_LinTri, until the pair is drawn), an opaque rectangle first
 * dropping what the tiles it covers hold. */
static void lin_pair_begin(struct fgl_context *ctx, const struct r_vertex *a0,
                           const struct r_vertex *a1, const struct r_vertex *a2,
                           const struct r_vertex *b0, const struct r_vertex *b1,
                           const struct r_vertex *b2)
{
   int box[4];
   ctx->_LinRect = false;
   const uint8_t k = lin_classify(ctx, a0, a1, a2, b0, b1, b2, box);
   /* (not when a face is culled: a culled rectangle bins nothing) */
   const struct r_rast_state *rast = ctx->_Raster.rast;
   if (ctx->_LinRect && box[0] < box[2] && box[1] < box[3] && !rast->cull_front &&
       !rast->cull_back)
      r_scene_cover(&ctx->_Scene, &ctx->_Raster, box);
   ctx->_LinTri = k;
}

void t_lin_flush_tris(struct fgl_context *ctx)
{
   /* lp_setup_draw_elements: the vbuf's triangles, in pairs through rect()
    * when they are a whole number of pairs (nr % 6 == 0) */
   struct fgl_lin_queue *q = &ctx->_LinQueue;
   if (!q->count)
      return;
   const unsigned n = q->count;
   q->count = 0;   /* (fgl_raster_triangle may flush the scene: not this) */
   struct r_state *rs = &ctx->_Raster;
   const unsigned csr = rs->setup_mxcsr;
   rs->setup_mxcsr = q->setup_mxcsr;
   for (unsigned i = 0; i < n; i++) {
      const struct r_vertex *t = q->tri[i];
      if (n % 2 == 0 && i % 2 == 0)
         lin_pair_begin(ctx, &t[0], &t[1], &t[2], &t[3], &t[4], &t[5]);
      fgl_raster_triangle(ctx, rs, &t[0], &t[1], &t[2]);
      if (i % 2 == 1) {
         ctx->_LinTri = R_LIN_NO;
         ctx->_LinRect = false;
      }
   }
   ctx->_LinTri = R_LIN_NO;
   ctx->_LinRect = false;
   rs->setup_mxcsr = csr;
}

bool t_lin_queue_tri(struct fgl_context *ctx, const struct r_vertex *v0,
                     const struct r_vertex *v1, const struct r_vertex *v2)
{
   struct fgl_lin_queue *q = &ctx->_LinQueue;
   /* draw_pipe_vbuf.c: 1020 indices, 340 triangles, a flush */
   if (q->count == 340 || (q->count && q->setup_mxcsr != ctx->_Raster.setup_mxcsr))
      t_lin_flush_tris(ctx);
   if (q->count == q->cap) {
      const unsigned cap = q->cap ? 2 * q->cap : 32;
      struct r_vertex *t = fgl_realloc(q->tri, cap * sizeof(q->tri[0]));
      if (!t)
         return false;   /* drawn now, unpaired */
      q->tri = (void *)t;
      q->cap = cap;
   }
   q->setup_mxcsr = ctx->_Raster.setup_mxcsr;
   q->tri[q->count][0] = *v0;
   q->tri[q->count][1] = *v1;
   q->tri[q->count][2] = *v2;
   q->count++;
   return true;
}

/* Two triangles that llvmpipe's direct path hands to rect() (the first
 * with provoking vertex pva): in a scene that may take the linear path,
 * marked for the raster scene as a rectangle's or not (lin_pair_begin). */
static void tri_pair(const struct render *r, unsigned a0, unsigned a1, unsigned a2,
                     unsigned pva, unsigned b0, unsigned b1, unsigned b2, bool pipeline,
                     unsigned fa, unsigned fb)
{
   if (r->lin && !pipeline) {
      struct fgl_context *ctx = r->ctx;
      lin_pair_begin(ctx, &vtx(r, a0)->r, &vtx(r, a1)->r, &vtx(r, a2)->r, &vtx(r, b0)->r,
                     &vtx(r, b1)->r, &vtx(r, b2)->r);
      tri_pv(r, a0, a1, a2, pva, pipeline, fa);
      tri(r, b0, b1, b2, pipeline, fb);
      ctx->_LinTri = R_LIN_NO;
      ctx->_LinRect = false;
      return;
   }
   tri_pv(r, a0, a1, a2, pva, pipeline, fa);
   tri(r, b0, b1, b2, pipeline, fb);
}

/* [S: draw_decompose_tmp.h] with the last vertex provoking: every
 * triangle of GL_TRIANGLES, strips and fans is a primitive of its own with
 * all three edges */
#define TRI_FLAGS (T_RESET_STIPPLE | T_EDGE_ALL)

/* Vertices [start, start+count) of a segment need the draw pipeline. */
static bool segment_clipped(const struct render *r, unsigned start, unsigned count)
{
   if (r->win && r->win->view)
      return t_clip_masks_any(r->ctx, r->win->view, start, count);
   unsigned m = 0;
   for (unsigned i = start; i < start + count; i++)
      m |= vtx(r, i)->mask;
   return m != 0;
}

/* Whether a segment of triangles takes draw's pipeline: the state needs it
 * (polygon stipple, unfilled, offset or two-sided lighting left to draw),
 * or some vertex needs clipping. */
static bool segment_pipeline(const struct render *r, unsigned start, unsigned count)
{
   return r->ctx->_DrawPipeline.always || segment_clipped(r, start, count);
}

/* the longest GL_TRIANGLES draw whose pairs are tried as rectangles:
 * llvmpipe's vertex buffer holds 4096 bytes (LP_MAX_VBUF_SIZE), at least
 * 96 vertices of the formats a linear scene draws; a longer draw is cut
 * into buffers whose vertex counts are not modelled */
#define LIN_PAIRS_MAX 96

/* GL_TRIANGLES: vsplit segments of 4095 vertices (the 4096 trimmed to
 * whole triangles). */
static void render_triangles(const struct render *r, unsigned s, unsigned n)
{
   n -= n % 3;
   for (unsigned seg = 0; seg < n; seg += SEGMENT_SIZE - 1) {
      const unsigned cnt = n - seg < SEGMENT_SIZE - 1 ? n - seg : SEGMENT_SIZE - 1;
      need(r, s + seg, cnt);
      const bool pipeline = segment_pipeline(r, s + seg, cnt);
      /* pairs of triangles may be rectangles when the draw is a whole
       * number of pairs (lp_setup_draw_arrays: nr % 6 == 0; only small
       * draws, whose vertex buffer is the whole draw) */
      if (r->lin && !pipeline && n % 6 == 0 && n <= LIN_PAIRS_MAX) {
         for (unsigned i = seg; i < seg + cnt; i += 6) {
            need_prim(r, s + i, 6, s + n);
            tri_pair(r, s + i, s + i + 1, s + i + 2, s + i + 2, s + i + 3, s + i + 4, s + i + 5,
                     pipeline, TRI_FLAGS, TRI_FLAGS);
         }
         continue;
      }
      for (unsigned i = seg; i < seg + cnt; i += 3) {
         need_prim(r, s + i, 3, s + n);
         tri(r, s + i, s + i + 1, s + i + 2, pipeline, TRI_FLAGS);
      }
   }
}

/* GL_TRIANGLE_STRIP: segments of 4096 vertices overlapping by two (an even
 * step, so the winding parity is kept). */
static void render_triangle_strip(const struct render *r, unsigned s, unsigned n)
{
   for (unsigned seg = 0; seg + 2 < n; seg += SEGMENT_SIZE - 2) {
      const unsigned cnt = n - seg < SEGMENT_SIZE ? n - seg : SEGMENT_SIZE;
      need(r, s + seg, cnt);
      const bool pipeline = segment_pipeline(r, s + seg, cnt);
      for (unsigned i = seg; i + 2 < seg + cnt; i++) {
         need_prim(r, s + i, 3, s + n);
         if (i & 1)
            tri(r, s + i + 1, s + i, s + i + 2, pipeline, TRI_FLAGS);
         else
            tri(r, s + i, s + i + 1, s + i + 2, pipeline, TRI_FLAGS);
      }
      if (seg + cnt >= n)
         break;
   }
}

/* GL_TRIANGLE_FAN and GL_POLYGON: one segment up to SEGMENT_SIZE vertices;
 * longer ones are cut into vsplit's fan segments of FAN_SEGMENT_SIZE
 * vertices (its 1024-entry segment_size), each after the first made of
 * vertex 0 and the next vertices from the previous segment's last pair
 * on (draw_split_tmp.h). */
#define FAN_SEGMENT_SIZE 1024

static void render_fan(const struct render *r, unsigned s, unsigned n, bool polygon)
{
   const unsigned seg_max = n <= SEGMENT_SIZE ? SEGMENT_SIZE : FAN_SEGMENT_SIZE;
   for (unsigned seg = 0; seg + 2 < n; seg += seg_max - 2) {
      const unsigned cnt = n - seg < seg_max ? n - seg : seg_max;
      /* vertex 0 and the segment's others (vertex 0 stays in v0) */
      if (seg == 0)
         need(r, s, cnt);
      else
         need(r, s + seg + 1, cnt - 1);
      const bool pipeline = seg == 0 ? segment_pipeline(r, s, cnt)
                                     : segment_pipeline(r, s, 1) ||
                                       segment_clipped(r, s + seg + 1, cnt - 1);
      /* a polygon's edges [S: draw_decompose_tmp.h PIPE_PRIM_POLYGON with
       * vsplit's DRAW_SPLIT_BEFORE/AFTER]: the first triangle of each
       * segment restarts the stipple, with the edge 0->1 only in the first
       * segment; each triangle (i+1, i+2, 0) has its outer edge i+1 -> i+2
       * (edge 0); the last triangle of the last segment also n-1 -> 0
       * (edge 1) */
      const bool split_before = seg != 0, split_after = seg + cnt < n;
      unsigned pflags = T_RESET_STIPPLE | T_EDGE_0 | (split_before ? 0u : T_EDGE_2);
      if (!polygon && n == 4 && r->lin && !pipeline && !r->elts) {
         /* lp_setup_draw_arrays: a fan of four is rect(0,1,2, 0,2,3) */
         tri_pair(r, s, s + 1, s + 2, s + 2, s, s + 2, s + 3, pipeline, TRI_FLAGS, TRI_FLAGS);
         break;
      }
      for (unsigned i = seg; i + 2 < seg + cnt; i++, pflags = T_EDGE_0) {
         if (polygon) {
            if (i + 3 == seg + cnt && !split_after)
               pflags |= T_EDGE_1;
            tri(r, s + i + 1, s + i + 2, s, pipeline, pflags);
         } else {
            tri(r, s, s + i + 1, s + i + 2, pipeline, TRI_FLAGS);
         }
      }
      if (seg + cnt >= n)
         break;
   }
}

static void render_quads(const struct render *r, unsigned start, unsigned count,
                         bool constant_interp, bool indexed)
{
   count &= ~3u;
   for (unsigned seg = 0; seg < count; seg += SEGMENT_SIZE) {
      const unsigned n = count - seg < SEGMENT_SIZE ? count - seg : SEGMENT_SIZE;
      need(r, start + seg, n);
      const bool pipeline = segment_pipeline(r, start + seg, n);
      /* llvmpipe's lp_setup_draw_elements always emits (i-3,i-2,i) +
       * (i-2,i-1,i) (lp_setup_vbuf.c), and draw emits an indexed draw's
       * vertices through it (draw_pt_emit.c) */
      const bool split13 = constant_interp || pipeline || indexed;
      for (unsigned i = start + seg; i < start + seg + n; i += 4) {
         need_prim(r, i, 4, start + count);
         /* [S: draw_decompose_tmp.h PIPE_PRIM_QUADS, last vertex
          * provoking] edges 0->1, 3->0, then 1->2, 2->3 */
         if (split13) {
            tri(r, i, i + 1, i + 3, pipeline, T_RESET_STIPPLE | T_EDGE_0 | T_EDGE_2);
            tri(r, i + 1, i + 2, i + 3, pipeline, T_EDGE_0 | T_EDGE_1);
         } else {
            /* llvmpipe's rect() */
            tri_pair(r, i, i + 1, i + 2, i + 3, i, i + 2, i + 3, pipeline, 0, 0);
         }
      }
   }
}

static void render_quad_strip(const struct render *r, unsigned start, unsigned count)
{
   count &= ~1u;
   if (count < 4)
      return;
   /* vsplit: segments of SEGMENT_SIZE vertices overlapping by one pair */
   for (unsigned seg = 0; seg + 2 < count; seg += SEGMENT_SIZE - 2) {
      const unsigned n = count - seg < SEGMENT_SIZE ? count - seg : SEGMENT_SIZE;
      need(r, start + seg, n);
      const bool pipeline = segment_pipeline(r, start + seg, n);
      for (unsigned k = start + seg; k + 3 < start + seg + n; k += 2) {
         need_prim(r, k, 4, start + count);
         /* [S: draw_decompose_tmp.h PIPE_PRIM_QUAD_STRIP, last vertex
          * provoking] edges k+2->k, k+3->k+2, then k->k+1, k+1->k+3 */
         if (pipeline) {
            tri(r, k + 2, k, k + 3, pipeline, T_RESET_STIPPLE | T_EDGE_0 | T_EDGE_2);
            tri(r, k, k + 1, k + 3, pipeline, T_EDGE_0 | T_EDGE_1);
         } else {
            tri(r, k, k + 1, k + 3, pipeline, 0);
            tri(r, k + 2, k, k + 3, pipeline, 0);
         }
      }
      if (seg + n >= count)
         break;
   }
}

static void render_prim(const struct render *r, const struct fgl_vbo_prim *p,
                        bool constant_interp)
{
   const unsigned s = p->start, n = p->count;
   switch (p->mode) {
   case GL_TRIANGLES:
      render_triangles(r, s, n);
      break;
   case GL_TRIANGLE_STRIP:
      render_triangle_strip(r, s, n);
      break;
   case GL_TRIANGLE_FAN:
   case GL_POLYGON:
      render_fan(r, s, n, p->mode == GL_POLYGON);
      break;
   case GL_QUADS:
      render_quads(r, s, n, constant_interp, p->indexed);
      break;
   case GL_QUAD_STRIP:
      render_quad_strip(r, s, n);
      break;
   case GL_POINTS:
      /* vsplit segments: a segment with a clipped vertex takes draw's
       * pipeline (which matters to the line stipple counter only) */
      for (unsigned seg = 0; seg < n; seg += SEGMENT_SIZE) {
         const unsigned cnt = n - seg < SEGMENT_SIZE ? n - seg : SEGMENT_SIZE;
         need(r, s + seg, cnt);
         const bool pipeline = segment_clipped(r, s + seg, cnt);
         /* a legacy point is a rectangle of llvmpipe's setup
          * (lp_setup_point.c: lp_setup_bin_rectangle): classified for a
          * scene that may take the linear path (ctx->_LinPoint) */
         const bool lin = r->lin && fgl_lin_permitted(r->ctx) && !fgl_point_smooth(r->ctx) &&
                          !r->ctx->_Raster.rast->point_sprite;
         for (unsigned i = seg; i < seg + cnt; i++) {
            if (r->phong_mats)
               phong_material(r, s + i);
            if (lin) {
               const struct r_vertex *pv = &vtx(r, s + i)->r;
               r->ctx->_LinPoint = fgl_lin_color_kind(r->ctx, &pv, 1);
            }
            t_point(r->ctx, vtx(r, s + i), pipeline);
         }
         r->ctx->_LinPoint = R_LIN_NO;
      }
      break;
   case GL_LINES:
      /* every line is a primitive of its own (DRAW_PIPE_RESET_STIPPLE);
       * vsplit segments of SEGMENT_SIZE vertices (even) */
      for (unsigned seg = 0; seg + 1 < n; seg += SEGMENT_SIZE) {
         const unsigned cnt = n - seg < SEGMENT_SIZE ? n - seg : SEGMENT_SIZE;
         need(r, s + seg, cnt);
         const bool pipeline = segment_clipped(r, s + seg, cnt);
         for (unsigned i = seg; i + 1 < seg + cnt; i += 2) {
            if (r->phong_mats)
               phong_material(r, s + i + 1);
            t_line(r->ctx, vtx(r, s + i), vtx(r, s + i + 1), true, pipeline);
         }
      }
      break;
   case GL_LINE_STRIP:
   case GL_LINE_LOOP:
      /* draw_decompose_tmp.h: (i-1, i), the stipple counter reset by the
       * first line only; a loop is closed by (n-1, 0).  vsplit's segments
       * (DRAW_SPLIT_BEFORE/AFTER) and Mesa's vbo wrapping of a loop into
       * strips keep this order and the counter, so they need no model. */
      if (n < 2)
         break;
      {
         /* vsplit segments of SEGMENT_SIZE vertices sharing one; a loop's
          * closing line is in its last segment, with vertex 0 */
         bool pipeline = false;
         for (unsigned seg = 0; seg + 1 < n; seg += SEGMENT_SIZE - 1) {
            const unsigned cnt = n - seg < SEGMENT_SIZE ? n - seg : SEGMENT_SIZE;
            need(r, s + seg, cnt);
            pipeline = segment_clipped(r, s + seg, cnt);
            for (unsigned i = seg + 1; i < seg + cnt; i++) {
               if (r->phong_mats)
                  phong_material(r, s + i);
               t_line(r->ctx, vtx(r, s + i - 1), vtx(r, s + i), i == 1, pipeline);
            }
         }
         if (p->mode == GL_LINE_LOOP) {
            need(r, s + n - 1, 1);
            if (r->phong_mats)
               phong_material(r, s);
            t_line(r->ctx, vtx(r, s + n - 1), vtx(r, s), false,
                   pipeline || segment_clipped(r, s, 1));
         }
      }
      break;
   default:
      break;
   }
}

/* Whether the fragment program reads the primary colour after the
 * compiler drops dead code: the final colour, traced back through the
 * enabled units' combiners channel by channel (PREVIOUS of the first unit
 * is the primary colour; a DOT3_RGBA result is every channel).  A flat
 * colour that no live instruction reads is no input of the shader, so it
 * makes no constant-interpolated input of llvmpipe's setup
 * [S: ff_fragment_shader.cpp emit_texenv, emit_combine; the NIR
 * optimisations of the state tracker] (ORACLE-NOTES.md "Primitive
 * decomposition and the provoking vertex"; random-tex witness, s2-i107: a
 * GL_REPLACE unit of an RGBA texture after the colour). */
static bool t_fs_reads_primary(const struct r_state *rs)
{
   bool need_rgb = true, need_a = true, reads = false;
   for (int u = rs->fs->tex_nr - 1; u >= 0; u--) {
      if (!(rs->fs->tex_units & (1u << u)) || !rs->tex[u])
         continue;
      const struct r_tex_combine *k = &rs->tex[u]->comb;
      const bool dot3_rgba = k->mode_rgb == R_COMB_DOT3_RGBA ||
                             k->mode_rgb == R_COMB_DOT3_RGBA_EXT;
      bool prev_rgb = false, prev_a = false;
      if (need_rgb || (dot3_rgba && need_a)) {
         for (int i = 0; i < k->nargs_rgb; i++) {
            const bool alpha = k->opr_rgb[i] == R_OPR_ALPHA ||
                               k->opr_rgb[i] == R_OPR_ONE_MINUS_ALPHA;
            if (k->src_rgb[i] == R_SRC_PRIMARY_COLOR)
               reads = true;
            else if (k->src_rgb[i] == R_SRC_PREVIOUS)
               *(alpha ? &prev_a : &prev_rgb) = true;
         }
      }
      if (need_a && !dot3_rgba) {
         for (int i = 0; i < k->nargs_a; i++) {
            if (k->src_a[i] == R_SRC_PRIMARY_COLOR)
               reads = true;
            else if (k->src_a[i] == R_SRC_PREVIOUS)
               prev_a = true;
         }
      }
      need_rgb = prev_rgb;
      need_a = prev_a;
   }
   return reads || need_rgb || need_a;
}

/* src: the vertices come window by window from src (one primitive,
 * nverts its count, verts and elts unused), else all are in verts. */
static void render_batch(struct fgl_context *ctx, const struct fgl_vertex_view *verts,
                         unsigned nverts, const unsigned *elts,
                         const struct fgl_vbo_prim *prims, unsigned nprims,
                         const struct t_vertex_source *src)
{
   /* [S: st_draw.c:prepare_draw] glBitmap's cache is drawn first, with
    * the state validated before this draw's */
   fgl_flush_bitmap_cache(ctx);
   /* [S: draw.c:_mesa_set_varying_vp_inputs] the batch's texture
    * coordinates are the fragment program's varyings from now on */
   ctx->_VaryingTexUnits = 0;
   for (unsigned u = 0; u < FGL_MAX_TEXTURE_UNITS; u++)
      if (ctx->Vbo.attr_size[FGL_ATTR_TEX0 + u] != 0)
         ctx->_VaryingTexUnits |= 1u << u;
   /* [S: st_draw.c:prepare_draw] the oracle derives its sampler views
    * here, from the objects as they are now: texture state derived
    * earlier for this draw (at its glBegin) again when another context
    * changed an object since (fgl_texture_local.DerivedPending;
    * ORACLE-NOTES.md "Another context's change of a shared texture") */
   if (ctx->TexLocal.DerivedPending &&
       atomic_load_explicit(&ctx->TexObjects->Stamp, memory_order_acquire) !=
          ctx->TexLocal.DerivedStamp)
      ctx->NewState |= FGL_NEW_TEXTURE;
   fgl_update_state(ctx);
   ctx->TexLocal.DerivedPending = false;
   if (!ctx->DrawBuffer)
      return;
   fgl_lin_draw(ctx);
   fgl_vpcut_validate(ctx, true);
   fgl_tex_note_scene_use(ctx);
   if (ctx->Color.DrawBuffer != GL_NONE)
      fgl_mark_color_defined(ctx->DrawBuffer);
   fgl_update_stipple(ctx);

   /* LAZY_WINDOW: a batch of triangles and quads, in strips or not,
    * transformed window by window */
   bool lazy = !src && !elts && nverts > 2 * LAZY_WINDOW;
   for (unsigned i = 0; lazy && i < nprims; i++)
      lazy = prims[i].mode == GL_TRIANGLES || prims[i].mode == GL_TRIANGLE_STRIP ||
             prims[i].mode == GL_QUADS || prims[i].mode == GL_QUAD_STRIP;

   /* the transformed vertices: the context's scratch array, no
    * allocation per batch */
   struct t_vertex *tv = fgl_vbo_scratch_lines(ctx->Vbo.tv, &ctx->Vbo.tv_alloc,
                                               src ? SEGMENT_SIZE : lazy ? LAZY_WINDOW : nverts,
                                               sizeof(*tv));
   if (!tv) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   ctx->Vbo.tv = tv;
   /* a windowed draw's fetched vertices: the array draws' scratch */
   struct render_window win = { .src = src, .view = lazy ? verts : NULL, .count = nverts,
                                .tv = tv };
   if (src) {
      win.in = fgl_vbo_scratch(ctx->Vbo.array_verts, &ctx->Vbo.array_alloc, SEGMENT_SIZE,
                               sizeof(*win.in));
      if (!win.in) {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return;
      }
      ctx->Vbo.array_verts = win.in;
   }

   /* The oracle draws with denormals flushed: draw_vbo sets DAZ and FTZ
    * around the vertex shader, clipping and triangle setup, and the
    * rasterizer runs with them too (draw_pt.c:draw_vbo and
    * lp_rast.c:lp_rast_queue_scene, util_fpstate_set_denorms_to_zero), while
    * the state (matrix products, light vectors) was derived before, without
    * them.  So from here on a denormal operand counts as zero and a
    * denormal result becomes zero (ORACLE-NOTES.md "Clamps and NaN"). */
#if defined(__SSE__) || defined(__x86_64__)
   const unsigned mxcsr = _mm_getcsr();
   _mm_setcsr(mxcsr | 0x8040u);   /* FTZ (bit 15) | DAZ (bit 6) */
   /* the pipeline's triangles are set up in the caller's (t_draw_pipe.c);
    * 0 (the draw's own) when the caller already flushes denormals, so
    * their setup switches nothing */
   ctx->_DrawPipeline.caller_mxcsr = (mxcsr | 0x8040u) != mxcsr ? mxcsr : 0;
#endif

   /* [S: st_atom.c:st_update_edgeflags] with a fill mode other than
    * GL_FILL, glEdgeFlag values in the batch's vertex format are per-vertex
    * edge flags (draw_llvm.c: edgeflag = (value == 1.0)); without them
    * every vertex has one, and a false current edge flag culls the faces
    * that are not filled (st_atom_rasterizer.c: edgeflag_culls_prims) */
   struct fgl_draw_pipeline *dp = &ctx->_DrawPipeline;
   const bool edgeflags_enabled = ctx->Polygon.FrontMode != GL_FILL ||
                                  ctx->Polygon.BackMode != GL_FILL;
   const bool vertdata_edgeflags = edgeflags_enabled &&
                                   ctx->Vbo.attr_size[FGL_ATTR_EDGEFLAG] != 0;
   /* In GL_SELECT and GL_FEEDBACK the per-vertex edge flags all read as
    * false (observed, ORACLE-NOTES.md "Selection and feedback": the draw
    * shader variant's passthrough edge-flag input, added by
    * nir_lower_passthrough_edgeflags, is not among the vp->num_inputs
    * vertex elements st_draw_feedback.c gives the draw module), so unfilled
    * polygons of such a batch give no lines or points. */
   const bool feedback = ctx->RenderMode != GL_RENDER;
   const enum t_edge_source edges = !vertdata_edgeflags ? T_EDGES_SET
                                    : feedback          ? T_EDGES_CLEAR
                                                        : T_EDGES_FROM_DATA;
   if (src) {
      /* vertex 0, kept for the whole draw; the segments load the rest */
      win.edges = edges;
      src->fetch(src->ud, 0, 1, win.in);
      const struct fgl_vertex_view view0 = fgl_vertex_view_full(win.in);
      t_transform(ctx, &view0, 1, &win.v0, edges);
   } else if (lazy) {
      win.edges = edges;   /* need_prim transforms the windows */
   } else {
      t_transform(ctx, verts, nverts, tv, edges);
   }
   const bool edgeflag_culls = edgeflags_enabled && !vertdata_edgeflags &&
                               ctx->Current.Attrib[FGL_ATTR_EDGEFLAG][0] == 0.0f;
   dp->edge_cull_front = edgeflag_culls && dp->fill_front != GL_FILL;
   dp->edge_cull_back = edgeflag_culls && dp->fill_back != GL_FILL;

   /* GL_PHONG_WIN: the shading environment of the batch, with the current
    * material (the materials in the vertex format, per primitive) */
   unsigned phong_mats = 0;
   if (ctx->_Raster.fs->phong) {
      memset(&ctx->_ShadeEnv, 0, sizeof(ctx->_ShadeEnv));
      fgl_update_shade_env(ctx, &ctx->_ShadeEnv);
      if (!fgl_set_shade_env(ctx)) {
#if defined(__SSE__) || defined(__x86_64__)
         ctx->_DrawPipeline.caller_mxcsr = 0;
         _mm_setcsr(mxcsr);   /* the caller's state back */
#endif
         return;
      }
      for (int a = FGL_ATTR_MAT_FIRST; a < FGL_ATTR_COUNT; a++)
         if (ctx->Vbo.attr_size[a] != 0)
            phong_mats |= 1u << (a - FGL_ATTR_MAT_FIRST);
   }
   struct render r = { ctx, src || lazy ? &win : NULL, tv, verts, elts, phong_mats, false };
   const bool flat = ctx->Light.ShadeModel == GL_FLAT;
   /* A colour that is not part of the batch's vertex format is the current
    * colour for every vertex, and Mesa's fixed-function fragment program
    * then reads it as a constant instead of interpolating it
    * (ff_fragment_shader.cpp: get_gl_Color without VARYING_BIT_COL0), so it
    * is exact even where interpolation is not (w = 0, NaN positions;
    * ORACLE-NOTES.md "Vertex batching"). */
   const bool color_varying = ctx->Vbo.attr_size[FGL_ATTR_COLOR0] != 0;
   /* the same for the secondary colour of GL_COLOR_SUM, unlit
    * (filter_fp_input_mask: VERT_BIT_COLOR1 among the varying inputs) */
   const bool color1_varying = ctx->_Raster.fs->color_sum &&
                               ctx->Vbo.attr_size[FGL_ATTR_COLOR1] != 0;
   if (feedback)
      /* [S: draw_pipe_clip.c:clip_init_state] the feedback draw context
       * has no fragment shader bound: the colours are flat exactly with
       * GL_FLAT */
      ctx->_Raster.flat_mask = flat ? (ctx->Light.Enabled ? 0xfu : 1u) : 0u;
   else if (ctx->Light.Enabled)
      /* lit colours are always varyings of the vertex program
       * (ff_fragment_shader.cpp: COL0/COL1 are possible inputs whenever
       * lighting is on), so only flat shading makes them constant */
      ctx->_Raster.flat_mask = flat ? 0xfu : 0u;
   else
      ctx->_Raster.flat_mask = (flat || !color_varying ? 1u : 0u) |
                               (ctx->_Raster.fs->color_sum && (flat || !color1_varying)
                                   ? 2u : 0u);
   /* Likewise a texture coordinate that cannot vary (not in the batch's
    * vertex format, no texgen, no texture matrix) is read by the fragment
    * program as the current coordinate, a constant (filter_fp_input_mask,
    * load_texture: gl_CurrentAttribFragMESA), never interpolated: every
    * vertex carries that value (t_texcoord), so the provoking vertex's is
    * it, also where interpolation is not exact (w = 0; ORACLE-NOTES.md
    * "Texture coordinates and multitexture"). */
   if (!feedback)
      ctx->_Raster.flat_mask |= (fgl_tex_constant_units(ctx) & ctx->_Raster.fs->tex_units)
                                << R_ATTR_TEX0;
   /* llvmpipe's direct path draws a quad as (0,1,2)+(0,2,3) unless its
    * setup variant has a constant-interpolated input
    * (lp_setup_vbuf.c:lp_setup_draw_arrays, rect() when
    * !uses_constant_interp).  Only a colour input can be one, and only with
    * flat shading (lp_state_setup.c:lp_make_setup_variant_key,
    * LP_INTERP_COLOR becomes LP_INTERP_CONSTANT): a flat-shaded batch whose
    * colour is not a fragment-shader input (unlit, colour outside the
    * vertex format) still gets the (0,2) diagonal (ORACLE-NOTES.md
    * "Vertex batching"). */
   const bool constant_interp = flat && (((ctx->Light.Enabled || color_varying) &&
                                          t_fs_reads_primary(&ctx->_Raster)) ||
                                         (ctx->Light.Enabled && ctx->_Raster.fs->color_sum) ||
                                         color1_varying);
   r.lin = fgl_lin_binning(ctx) && !constant_interp && !feedback;
   ctx->_LinPairs = r.lin;   /* the pipeline's triangles too (t_lin_queue_tri) */
   ctx->_LinColorConst = !ctx->Light.Enabled && !color_varying;
   bool skip_draw = false;
   for (unsigned i = 0; i < nprims; i++) {
      /* consecutive primitives of one mode are one llvmpipe draw
       * (st_draw.c:st_draw_gallium_multimode), and draw is flushed after
       * each (lp_draw_arrays.c: draw_flush): the offset stage's latch.  In
       * GL_SELECT and GL_FEEDBACK every primitive is a draw of its own,
       * ending with a flush (st_draw_feedback.c:
       * st_feedback_draw_vbo_multi_mode, draw_bind_vertex_shader(NULL)).
       * llvmpipe_draw_vbo returns at once when the first of its draws is
       * empty (`!draws[0].count`), skipping the others: an empty
       * glBegin/glEnd hides the primitives of its mode batched after it
       * (ORACLE-NOTES.md "Vertex batching", dlist/fuzz). */
      /* (a later draw of glMultiDrawArrays/Elements continues the same
       * llvmpipe draw: ctx->_MultiDrawCont) */
      if ((i == 0 && !ctx->_MultiDrawCont) || (i > 0 && prims[i].mode != prims[i - 1].mode) ||
          feedback) {
         t_vbuf_end_draw(ctx);
         ctx->_DrawOffset.latched = false;
         skip_draw = prims[i].count == 0;
      }
      if (!skip_draw)
         render_prim(&r, &prims[i], constant_interp);
   }
   if (!ctx->_MultiDrawMore || feedback)
      t_vbuf_end_draw(ctx);
#if defined(__SSE__) || defined(__x86_64__)
   ctx->_DrawPipeline.caller_mxcsr = 0;
   _mm_setcsr(mxcsr);
#endif
   if (ctx->Vbo.tv_alloc > FGL_VBO_SCRATCH_KEEP) {
      fgl_free(ctx->Vbo.tv);
      ctx->Vbo.tv = NULL;
      ctx->Vbo.tv_alloc = 0;
   }
}

/* fixglStats (main/stats.c): with the counters on, the batch is timed */
void t_render_batch_elts(struct fgl_context *ctx, const struct fgl_vertex_view *verts,
                         unsigned nverts, const unsigned *elts,
                         const struct fgl_vbo_prim *prims, unsigned nprims)
{
   if (__builtin_expect(ctx->_Raster.stats != NULL, 0)) {
      struct fgl_stats_mark mark;
      fgl_stats_batch_begin(ctx, &mark);
      render_batch(ctx, verts, nverts, elts, prims, nprims, NULL);
      fgl_stats_batch_end(ctx, &mark);
      return;
   }
   render_batch(ctx, verts, nverts, elts, prims, nprims, NULL);
}

void t_render_source(struct fgl_context *ctx, const struct t_vertex_source *src,
                     const struct fgl_vbo_prim *prim)
{
   if (__builtin_expect(ctx->_Raster.stats != NULL, 0)) {
      struct fgl_stats_mark mark;
      fgl_stats_batch_begin(ctx, &mark);
      render_batch(ctx, NULL, prim->count, NULL, prim, 1, src);
      fgl_stats_batch_end(ctx, &mark);
      return;
   }
   render_batch(ctx, NULL, prim->count, NULL, prim, 1, src);
}

void t_render_batch(struct fgl_context *ctx, const struct fgl_vertex_view *verts,
                    unsigned nverts, const struct fgl_vbo_prim *prims, unsigned nprims)
{
   t_render_batch_elts(ctx, verts, nverts, NULL, prims, nprims);
}
