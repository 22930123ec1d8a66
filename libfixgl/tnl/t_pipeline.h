/*
 * The vertex stage: transform to clip space, clip test, geometric clipping,
 * primitive assembly.  Its output is r_vertex triangles for the raster core.
 */
#ifndef FGL_T_PIPELINE_H
#define FGL_T_PIPELINE_H

#include <stdbool.h>
#include <string.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "raster/r_state.h"
#include "tnl/t_vbo.h"

struct fgl_context;

/* A vertex after the vertex "shader": clip-space position, outcode bits
 * (ORACLE-NOTES.md "Clipping"), its edge flag (vertex_header.edgeflag:
 * the glEdgeFlag value == 1.0, or 1 without per-vertex edge flags), window
 * position and varyings. */
struct t_vertex {
   float clip[4];
   unsigned mask;
   bool edge;
   struct r_vertex r;
   /* to 320 bytes, five cache lines: in the vertex stage's line-aligned
    * array (fgl_vbo_scratch_lines) a vertex's clip coordinates, mask,
    * window position and first colour share its first line, the only one
    * an untextured batch writes and the raster setup reads */
   float pad_to_lines[2];
};
_Static_assert(sizeof(struct t_vertex) % 64 == 0, "a transformed vertex is whole cache lines");

/* The prim_header flags of draw's primitive decomposition (draw_pipe.h,
 * draw_decompose_tmp.h): T_EDGE_i marks the edge from v[i] to v[(i+1)%3]
 * as a polygon edge (drawn by unfilled modes when that vertex's edge flag
 * is set too), T_RESET_STIPPLE the first triangle of a primitive. */
#define T_EDGE_0        0x1u
#define T_EDGE_1        0x2u
#define T_EDGE_2        0x4u
#define T_EDGE_ALL      0x7u
#define T_RESET_STIPPLE 0x8u

/* The per-vertex loops of the vertex stage are compiled twice, with and
 * without the FMA instruction set, and the loader picks the clone the CPU
 * runs (GCC's target_clones, an ifunc), as R_FMA_CLONES does for the
 * raster loops and math/m_shade.c for the shading: with FMA, the fmaf() of
 * the viewport transform, the user clip distances and m_gallivm_pow (LIT,
 * the spot exponent) is one vfmadd instruction instead of a libm call
 * through the PLT.  fmaf is the fused operation either way, and
 * -ffp-contract=off still forbids any other fusion: the same bits.
 * flatten: the helpers are inlined into each clone and compiled for its
 * target (an outlined helper would be a default-target function calling
 * libm's fmaf). */
/* (Not under ThreadSanitizer, which instruments the clones' resolver, run
 * by the loader before its runtime exists.) */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__) && \
    !defined(__SANITIZE_THREAD__)
#define T_FMA_CLONES __attribute__((target_clones("fma", "default"), flatten))
#else
#define T_FMA_CLONES
#endif

/* A column-major matrix m times a position p as the oracle's vertex
 * program does it (ORACLE-NOTES.md "Vertex transformation"; ffvertex_prog.c
 * MUL then MADs, the MADs unfused):
 * out = ((x*M0 + y*M1) + z*M2) + w*M3, every operation rounded.
 * The four rows are the four lanes of SSE operations, one per column:
 * each lane does the scalar chain's own multiplies and adds in its order,
 * so the bits are those of the scalar chain below. */
static inline void t_mul_mad_chain(float out[4], const float *m, const float *p)
{
#if defined(__SSE__) || defined(__x86_64__)
   __m128 acc = _mm_mul_ps(_mm_set1_ps(p[0]), _mm_loadu_ps(m));
   acc = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(p[1]), _mm_loadu_ps(m + 4)), acc);
   acc = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(p[2]), _mm_loadu_ps(m + 8)), acc);
   acc = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(p[3]), _mm_loadu_ps(m + 12)), acc);
   _mm_storeu_ps(out, acc);
#else
   for (int r = 0; r < 4; r++) {
      float acc = p[0] * m[r];
      acc = p[1] * m[4 + r] + acc;
      acc = p[2] * m[8 + r] + acc;
      acc = p[3] * m[12 + r] + acc;
      out[r] = acc;
   }
#endif
}

/* The provoking vertex pv's flat attributes (rs->flat_mask) onto dst, as
 * draw's clip (copy_flat), flatshade (flatshade_tri_2, flatshade_line_1)
 * stages copy them. */
static inline void t_copy_flat(const struct r_state *rs, struct r_vertex *dst,
                               const struct r_vertex *pv)
{
   for (int a = 0; a < rs->fs->num_attribs; a++)
      if (rs->flat_mask & (1u << a))
         for (int c = 0; c < 4; c++)
            dst->attr[a][c] = pv->attr[a][c];
}

/* Where the transformed vertices' edge flags (t_vertex.edge) come from:
 * every vertex has one, each is its glEdgeFlag value == 1.0, or none has
 * one. */
enum t_edge_source { T_EDGES_SET, T_EDGES_FROM_DATA, T_EDGES_CLEAR };

/* The vertex stage of n stored vertices into out[]: positions, clip codes,
 * texture coordinates, lighting or the vertex colour, fog and edge
 * flags. */
void t_transform(const struct fgl_context *ctx, const struct fgl_vertex_view *in,
                 unsigned n, struct t_vertex *out, enum t_edge_source edges);
/* Whether some vertex of in[first, first + n) is outside the view volume
 * or a user plane: the clip codes t_transform gives them, or'ed, from the
 * same arithmetic (the raster path's choice for a segment of a batch
 * that is transformed window by window later). */
bool t_clip_masks_any(const struct fgl_context *ctx, const struct fgl_vertex_view *in,
                      unsigned first, unsigned n);

#ifdef FGL_HAVE_BLOCK_KERNELS
/* Eight vertices at a time, AVX2 + FMA (t_vertex_avx2.c; only on a CPU
 * with both, t_vertex_simd): t_transform's clip coordinates, view-volume
 * outcodes (no user plane bits) and window positions of the n positions
 * at pos, pstride floats apart, into out[0..n-1], the scalar path's bits;
 * and t_clip_masks_any's answer for them without user planes. */
void t_positions8_avx2(const float *m, const float *scale, const float *translate,
                       const float *pos, unsigned pstride, unsigned n, struct t_vertex *out);
bool t_clip_any8_avx2(const float *m, const float *pos, unsigned pstride, unsigned n);
/* the same built with AVX-512 VL/BW/DQ as well (r_kernel_isa R_ISA_AVX512) */
void t_positions8_avx512(const float *m, const float *scale, const float *translate,
                         const float *pos, unsigned pstride, unsigned n, struct t_vertex *out);
bool t_clip_any8_avx512(const float *m, const float *pos, unsigned pstride, unsigned n);
#endif
/* Lighting (t_light.c): see tnl/t_light.h. */

/* The eye-space normal of shading.md (t_phong.c): GL_PHONG_WIN's vertex
 * normal, and the n of per-vertex Cook-Torrance (t_light.c): the
 * inverse-transpose modelview times the normal, then GL_NORMALIZE or
 * GL_RESCALE_NORMAL, in the GLSL reference's arithmetic.  t_eye_normal_init
 * reads the state once per batch. */
struct t_eye_normal {
   const float *inv;          /* the modelview's inverse */
   bool normalize, rescale;
   float scale;               /* the eye-space normal scale */
};
void t_eye_normal_init(const struct fgl_context *ctx, struct t_eye_normal *en);
void t_eye_normal(const struct t_eye_normal *en, const float *in, float n[3]);

/* GL_PHONG_WIN with lighting (t_phong.c): instead of t_light_run, the vertex
 * colour (R_ATTR_COLOR0), the
 * eye-space normal (R_ATTR_NORMAL, w = 1: front) and the eye position
 * (R_ATTR_EYEPOS) of n stored vertices, for r_fragment_phong. */
void t_phong(const struct fgl_context *ctx, const struct fgl_vertex_view *in, unsigned n,
             struct t_vertex *out);

/* The oracle's transformed normal (get_transformed_normal) of one vertex's
 * normal `in` (t_light.c). */
void t_transformed_normal(const struct fgl_context *ctx, const float *in, float n[3]);

/* The texture coordinates of n stored vertices (t_texcoord.c) into the
 * R_ATTR_TEX0 + u slots of out[], for the units in `units`. */
void t_texcoord(const struct fgl_context *ctx, const struct fgl_vertex_view *in, unsigned n,
                unsigned units, struct t_vertex *out);

/* The fog coordinate of n stored vertices (t_fog.c) into the R_ATTR_FOG
 * slot of out[]; eye_position_from_lighting is t_light_batch.eye_position. */
void t_fog(const struct fgl_context *ctx, const struct fgl_vertex_view *in, unsigned n,
           bool eye_position_from_lighting, struct t_vertex *out);

/* Clip planes in the oracle's order (outcode bit order): 0-5 the view
 * volume (x > w, x < -w, y > w, y < -w, z < -w, z > w), 6 + i the enabled
 * user plane i in clip space.  t_clip_dist is the clip stage's distance
 * (a C dot product, left to right; inside iff >= 0). */
float t_clip_dist(const struct fgl_context *ctx, const float clip[4], unsigned plane_idx);

/* The view-volume outcodes of a clip-space position: bit 0 x > w, 1
 * x + w < 0, 2 y > w, 3 y + w < 0, 4 z + w < 0, 5 z > w.  A point on a
 * boundary is inside.  The comparisons are unordered
 * [S: draw_llvm.c:generate_clipmask, lp_build_compare: LLVMRealUGT], so a
 * NaN coordinate sets the bits of the planes it enters (a point there is
 * dropped, a line or triangle discarded by the clip stage's NaN test).
 * User planes add bits 6 + i (t_vertex.c). */
static inline unsigned t_clip_mask(const float p[4])
{
   unsigned m = 0;
   if (!(p[0] <= p[3]))        m |= 1u << 0;
   if (!(0.0f <= p[0] + p[3])) m |= 1u << 1;
   if (!(p[1] <= p[3]))        m |= 1u << 2;
   if (!(0.0f <= p[1] + p[3])) m |= 1u << 3;
   if (!(0.0f <= p[2] + p[3])) m |= 1u << 4;
   if (!(p[2] <= p[3]))        m |= 1u << 5;
   return m;
}

/* The x and y bits of t_clip_mask with draw's guard band
 * (draw_cliptest_tmp.h DO_CLIP_XY_GUARD_BAND: outside when
 * -0.5 x + w < 0, ...): llvmpipe turns it on with its linear path, for
 * one B8G8R8A8/X8 colour buffer without depth or stencil
 * [S: lp_state_derived.c check_linear_rasterizer, draw_set_driver_clipping
 * guard_band_xy] (fgl_lin_capable; ORACLE-NOTES.md "GLX guard band"): a
 * vertex within twice the viewport needs no clipping there, and one
 * beyond it is clipped at the viewport's planes. */
static inline unsigned t_guard_mask(const float p[4])
{
   unsigned m = 0;
   if (!(-0.5f * p[0] + p[3] >= 0.0f)) m |= 1u << 0;
   if (!(0.5f * p[0] + p[3] >= 0.0f))  m |= 1u << 1;
   if (!(-0.5f * p[1] + p[3] >= 0.0f)) m |= 1u << 2;
   if (!(0.5f * p[1] + p[3] >= 0.0f))  m |= 1u << 3;
   return m;
}

/* The polygon clipper of draw's clip stage (t_clip.c; draw_pipe_clip.c
 * do_clip_tri, interp), free of GL: what it needs of the draw is here.
 * Triangles of the vertex stage and the quads of pixel rectangles
 * (t_pixels.c) go through it. */
struct t_clipper {
   /* planes 6 + i: user plane i in clip space (read only for the outcode
    * bits 6 + i the vertices carry) */
   const float (*user_planes)[4];
   /* the viewport of a new vertex's window position */
   const float *scale, *translate;
   /* bit a: varying slot a is interpolated into a new vertex */
   uint32_t attrs;
   /* planes 0-3 are draw's xy guard band, at twice the viewport
    * (t_guard_mask; the outcode bits then the guard band's) */
   bool guard;
   /* called with each new vertex and its index in t_clip_poly.tmp, or
    * NULL */
   void (*new_vertex)(void *data, struct t_vertex *v, unsigned slot);
   void *data;
};

/* As Mesa's clipper, with 8 user planes. */
#define T_MAX_CLIPPED_VERTICES (2 * (6 + 8) + 1)

/* A polygon being clipped: its n vertices (v[0..n-1], the first three
 * set by the caller), the polygon edges that start at each (edge[k]: the
 * edge v[k] -> v[k+1], the prim_header's flags), and the storage of the
 * vertices the clipper makes (tmp[0..ntmp-1]; the caller may append). */
struct t_clip_poly {
   unsigned n;
   const struct t_vertex *v[T_MAX_CLIPPED_VERTICES + 1];
   bool edge[T_MAX_CLIPPED_VERTICES + 1];
   unsigned ntmp;
   struct t_vertex tmp[T_MAX_CLIPPED_VERTICES + 2];
};

/* Clips the triangle p->v[0..2] (p->n = 3, p->edge set) against every
 * plane some vertex's outcode (t_vertex.mask) names, in bit order
 * (Sutherland-Hodgman, inside iff the distance is >= 0): a new vertex is
 * interpolated from whichever end is inside the plane by the larger
 * margin, as out + t * (in - out) for the clip position and the `attrs`
 * slots, gets its window position in plain C without FMA and outcode 0;
 * a new edge along a view-volume plane is hidden, along a user plane
 * drawn.  Afterwards p->v[0..p->n-1] is the polygon, to be fanned as
 * (P[i-1], P[i], P[0]); p->n < 3 when nothing is left: every vertex
 * outside one plane, a NaN or infinite plane distance, or too many
 * vertices.  A triangle inside every plane comes back as it went in. */
void t_clip_polygon(const struct t_clipper *c, struct t_clip_poly *p);

/* The draw stages after clipping for one triangle in window coordinates
 * (t_draw_pipe.c): cull, twoside, offset, flatshade, unfilled, the line
 * stipple restart, then llvmpipe's setup; v2 is the provoking vertex,
 * flags its T_EDGE_* (already cleared where the edge's first vertex has no
 * edge flag) and T_RESET_STIPPLE bits. */
void t_draw_pipe_tri(struct fgl_context *ctx, const struct r_vertex *v0,
                     const struct r_vertex *v1, const struct r_vertex *v2, unsigned flags);

/* A triangle of a vsplit segment that takes draw's pipeline (`pipeline`:
 * some vertex of its segment needs clipping, or the state requires it,
 * ctx->_DrawPipeline.always) or goes straight to llvmpipe: clipped against
 * the view volume and the user planes, passed through draw's cull, twoside,
 * offset, flatshade, unfilled and stipple stages, then rasterized; v2 is
 * the provoking vertex; flags are its T_EDGE_* / T_RESET_STIPPLE bits. */
void t_clip_triangle(struct fgl_context *ctx, const struct t_vertex *v0,
                     const struct t_vertex *v1, const struct t_vertex *v2, bool pipeline,
                     unsigned flags);

/* Clip a line against the view volume and the user planes
 * (draw_pipe_clip.c:clip_line, do_clip_line); v1 is the provoking vertex.
 * Returns false if nothing is left, else the clipped ends in out[]. */
bool t_clip_line(const struct fgl_context *ctx, const struct t_vertex *v0,
                 const struct t_vertex *v1, struct t_vertex out[2]);

/* Points and lines after assembly (t_linepoint.c): clipping, then the draw
 * module's stipple stage, then the raster core.  `first` marks the first
 * line of a primitive (DRAW_PIPE_RESET_STIPPLE); `pipeline` that the
 * primitive's vsplit segment takes draw's pipeline because some vertex
 * needs clipping. */
void t_point(struct fgl_context *ctx, const struct t_vertex *v, bool pipeline);
void t_line(struct fgl_context *ctx, const struct t_vertex *v0, const struct t_vertex *v1,
            bool first, bool pipeline);

/* The vbuf batch of points and lines under the polygon stipple
 * (t_linepoint.c): a filled triangle reaching the pstipple stage, and the
 * end of an llvmpipe draw. */
void t_vbuf_filled_tri(struct fgl_context *ctx);
/* The pipeline's triangles in a scene that may take llvmpipe's linear path
 * (ctx->_LinPairs, fgl_lin_binning): queued as its vbuf queues them
 * (false: not, out of memory), and handed to the raster scene in pairs
 * that may be rectangles when the vbuf is flushed (t_render.c) */
bool t_lin_queue_tri(struct fgl_context *ctx, const struct r_vertex *v0,
                     const struct r_vertex *v1, const struct r_vertex *v2);
void t_lin_flush_tris(struct fgl_context *ctx);
void t_vbuf_end_draw(struct fgl_context *ctx);

/* The points and lines the unfilled stage makes of a triangle, through the
 * stages after it (stipple, aapoint/aaline) to llvmpipe; they are already
 * clipped and flat-shaded. */
void t_unfilled_point(struct fgl_context *ctx, const struct r_vertex *v);
void t_unfilled_line(struct fgl_context *ctx, const struct r_vertex *v0,
                     const struct r_vertex *v1);

/* The selection and feedback stages (t_feedback.c), the last stage of the
 * draw pipeline while the render mode is GL_SELECT or GL_FEEDBACK: they
 * take the primitives rasterization would get, in window coordinates;
 * t_feedback_reset_stipple is the stage's reset_stipple_counter. */
void t_feedback_tri(struct fgl_context *ctx, const struct r_vertex *v0,
                    const struct r_vertex *v1, const struct r_vertex *v2);
void t_feedback_line(struct fgl_context *ctx, const struct r_vertex *v0,
                     const struct r_vertex *v1);
void t_feedback_point(struct fgl_context *ctx, const struct r_vertex *v);
/* [S: feedback.c:_mesa_update_hitflag] (also glRasterPos's) */
void t_update_hitflag(struct fgl_context *ctx, float z);
void t_feedback_reset_stipple(struct fgl_context *ctx);
/* t_clip.c: in GL_SELECT and GL_FEEDBACK, the clip stage's temporary
 * vertex `slot` now holds v (its flat colours first taken from what the
 * slot held, when stale_flat: a vertex made by interpolation). */
void t_feedback_clip_slot(struct fgl_context *ctx, struct t_vertex *v, unsigned slot,
                          bool stale_flat);

/* A pixel rectangle (glBitmap, glDrawPixels, glCopyPixels) as the state
 * tracker's textured quad (st_draw_quad through the passthrough vertex
 * shader): corners x0..x1, y0..y1 in GL window coordinates (y up) of a
 * fb_width x fb_height buffer, window depth z, a constant colour,
 * texture coordinates s0..s1 and t at y0 (t_y0) and y1 (t_y1). */
struct t_pixel_quad {
   float x0, y0, x1, y1, z;
   int fb_width, fb_height;
   float color[4];
   float s0, s1, t_y0, t_y1;
};

/* Draws the quad q with `pix` sampled per fragment (t_pixels.c): its
 * corners in clip space, clipped by t_clip_polygon when one is outside
 * the view volume, the triangles to r_triangle under the quad's own
 * rasterizer state (rs's scissor, framebuffer and fragment operations),
 * each fragment shaded by r_pixel_fragment.  Draws directly: the caller
 * flushes the tile scene first. */
void t_pixel_rect(const struct r_state *rs, const struct r_pixel_image *pix,
                  const struct t_pixel_quad *q);

/* Draw a batch of immediate-mode primitives. */
void t_render_batch(struct fgl_context *ctx, const struct fgl_vertex_view *verts,
                    unsigned nverts, const struct fgl_vbo_prim *prims, unsigned nprims);
/* The same with the primitives' vertices through an element list: vertex
 * i of the primitives is verts[elts[i]] (an indexed draw's post-transform
 * vertex cache, t_array.c: each of the nverts vertices is transformed and
 * lit once however often the primitives use it). */
void t_render_batch_elts(struct fgl_context *ctx, const struct fgl_vertex_view *verts,
                         unsigned nverts, const unsigned *elts,
                         const struct fgl_vbo_prim *prims, unsigned nprims);

/* The vertices of a long array draw, fetched window by window so that its
 * memory does not grow with its count (t_array.c): fetch writes vertices
 * first..first+n-1 of the draw (whole struct fgl_vbo_vertex, the format
 * in ctx->Vbo.attr_size) to out. */
struct t_vertex_source {
   void (*fetch)(void *ud, unsigned first, unsigned n, struct fgl_vbo_vertex *out);
   void *ud;
   bool uniform;     /* every vertex is vertex 0 (no array enabled: all
                      * are the current values), transformed once */
};
/* Draw the one primitive prim (start 0, count vertices from src) as
 * t_render_batch would with all its vertices at once: the same vsplit
 * segments, strip, fan and loop continuity, the same bytes; each segment's
 * vertices are fetched and transformed when it is drawn, a window of
 * SEGMENT_SIZE (4096) at a time, and vertex 0 is kept for fans, polygons
 * and loops. */
void t_render_source(struct fgl_context *ctx, const struct t_vertex_source *src,
                     const struct fgl_vbo_prim *prim);

/* t_array.c: glDrawArrays (indices == NULL: vertices first..first+count-1)
 * and glDrawElements (count indices of index_type) of the enabled client
 * arrays, validated by the caller. */
void t_draw_arrays(struct fgl_context *ctx, GLenum mode, GLint first, GLsizei count,
                   GLenum index_type, const GLvoid *indices);
/* Every array draw call, before its validation (an invalid or empty draw
 * too): the enabled coordinate arrays become the units whose coordinates
 * the fixed-function fragment program reads as varyings
 * (ctx->_VaryingTexUnits; ORACLE-NOTES.md "Bitmaps and pixel
 * rectangles") [S: main/draw.c: each draw entry point calls
 * _mesa_set_draw_vao, hence _mesa_set_varying_vp_inputs, first]. */
void t_set_draw_inputs(struct fgl_context *ctx);
/* glArrayElement: the enabled arrays' element elt through the immediate-mode
 * attribute calls. */
void t_array_element(struct fgl_context *ctx, GLint elt);
/* index i of an index array of type GL_UNSIGNED_BYTE/SHORT/INT; the
 * application's pointer need not be aligned to the index size (the
 * oracle reads such arrays too): read by memcpy, one load on x86 */
static inline GLuint t_index_at(GLenum type, const GLvoid *indices, GLsizei i)
{
   switch (type) {
   case GL_UNSIGNED_BYTE:
      return ((const GLubyte *)indices)[i];
   case GL_UNSIGNED_SHORT: {
      GLushort v;
      memcpy(&v, (const GLubyte *)indices + (size_t)i * sizeof(v), sizeof(v));
      return v;
   }
   default: {
      GLuint v;
      memcpy(&v, (const GLubyte *)indices + (size_t)i * sizeof(v), sizeof(v));
      return v;
   }
   }
}

/* Where a glDrawElements reads its indices: the client's array, or the
 * GL_ELEMENT_ARRAY_BUFFER's store from the offset `indices` (t_array.c
 * t_index_source). */
struct t_index_source {
   GLenum type;
   const void *base;      /* the client's indices, or the buffer's store */
   uint64_t start;        /* the first index's position in base */
   uint64_t limit;        /* positions at and past it read as 0 */
};
/* false when nothing is drawn: a buffer offset that is not a multiple of
 * the index size (the oracle skips such a draw without an error) */
bool t_index_source(const struct fgl_context *ctx, GLenum type, const GLvoid *indices,
                    struct t_index_source *src);
static inline GLuint t_index_src_at(const struct t_index_source *src, GLsizei i)
{
   const uint64_t pos = src->start + (uint64_t)i;
   if (pos >= src->limit)
      return 0;
   const unsigned size = src->type == GL_UNSIGNED_BYTE ? 1u : src->type == GL_UNSIGNED_SHORT ? 2u : 4u;
   return t_index_at(src->type, (const uint8_t *)src->base + pos * size, 0);
}

#endif
