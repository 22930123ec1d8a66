/*
 * The immediate-mode vertex store (glBegin/glVertex/glEnd).
 *
 * Vertices are batched and drawn when state changes, as Mesa's vbo_exec
 * does, and the batching is reproduced exactly because it is observable:
 * llvmpipe splits a smooth quad along 0-2 or 1-3 depending on whether any
 * vertex in the same 4096-vertex segment of the same draw needs clipping
 * (ORACLE-NOTES.md "Primitive decomposition and the provoking vertex").
 * So the store tracks
 * what decides draw boundaries in Mesa 22.3's vbo_exec:
 *  - the vertex format (each attribute's component count) of the batch;
 *    a larger format "upgrades" the vertex and splits the batch;
 *  - the 512 KiB vertex buffer, whose remaining room (minus one vertex)
 *    caps the batch; a full buffer "wraps" it mid-primitive;
 *  - consecutive glBegin/glEnd of the same independent mode merging into
 *    one draw (vbo_merge_draws), at most FGL_VBO_MAX_PRIM draws per batch.
 */
#ifndef FGL_T_VBO_H
#define FGL_T_VBO_H

#include <GL/gl.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#if defined(__SSE2__) || defined(__x86_64__)
#include <emmintrin.h>
#define FGL_VBO_SSE2 1
#endif

#define FGL_VBO_BUFFER_BYTES (512 * 1024)
#define FGL_VBO_MAX_PRIM     64

/* vbo_merge_draws' test of the earlier draw [S: vbo/vbo_exec.c:
 * vbo_merge_draws], shared by immediate mode and the display-list
 * compiler: a draw of independent primitives with no partial tail can take
 * the next draw of its mode; strips, loops, fans and polygons never (line
 * strips and loops also because a begin restarts their stipple). */
static inline bool fgl_vbo_prim_mergeable(GLenum mode, unsigned count)
{
   switch (mode) {
   case GL_POINTS:
      return true;
   case GL_LINES:
      return count % 2 == 0;
   case GL_TRIANGLES:
      return count % 3 == 0;
   case GL_QUADS:
   case GL_LINES_ADJACENCY:
      return count % 4 == 0;
   case GL_TRIANGLES_ADJACENCY:
      return count % 6 == 0;
   default:
      return false;
   }
}

struct fgl_context;

/* What a flush has to do (Mesa's ctx->Driver.NeedFlush bits). */
#define FGL_VBO_FLUSH_STORED  0x1u   /* a primitive was stored */
#define FGL_VBO_FLUSH_CURRENT 0x2u   /* an attribute was set */

/* The attributes of Mesa's vbo that fixed-function GL 1.x programs set
 * through immediate mode.  Materials are attributes too: glMaterial goes
 * through the vbo inside and outside glBegin/glEnd, so it takes part in the
 * vertex format and its batching (Mesa's VBO_ATTRIB_MAT_*, MAT_ATTRIB_*
 * order). */
enum fgl_vbo_attr {
   FGL_ATTR_POS,
   FGL_ATTR_NORMAL,
   FGL_ATTR_COLOR0,
   FGL_ATTR_COLOR1,         /* glSecondaryColor (VBO_ATTRIB_COLOR1) */
   FGL_ATTR_FOG,            /* glFogCoord (VBO_ATTRIB_FOG) */
   FGL_ATTR_COLOR_INDEX,    /* glIndex: stored and queried; nothing reads it
                             * in RGBA, but it is part of the vertex format
                             * (VBO_ATTRIB_COLOR_INDEX) */
   FGL_ATTR_TEX0,           /* glTexCoord, glMultiTexCoord: texture unit
                             * u's coordinate is FGL_ATTR_TEX0 + u
                             * (VBO_ATTRIB_TEX0..TEX7, after COLOR_INDEX
                             * as in Mesa's vbo_attrib order) */
   FGL_ATTR_TEX1, FGL_ATTR_TEX2, FGL_ATTR_TEX3, FGL_ATTR_TEX4,
   FGL_ATTR_TEX5, FGL_ATTR_TEX6, FGL_ATTR_TEX7,
   FGL_ATTR_EDGEFLAG,       /* glEdgeFlag: 1.0 or 0.0 (VBO_ATTRIB_EDGEFLAG) */
   FGL_ATTR_MAT_FRONT_AMBIENT,
   FGL_ATTR_MAT_BACK_AMBIENT,
   FGL_ATTR_MAT_FRONT_DIFFUSE,
   FGL_ATTR_MAT_BACK_DIFFUSE,
   FGL_ATTR_MAT_FRONT_SPECULAR,
   FGL_ATTR_MAT_BACK_SPECULAR,
   FGL_ATTR_MAT_FRONT_EMISSION,
   FGL_ATTR_MAT_BACK_EMISSION,
   FGL_ATTR_MAT_FRONT_SHININESS,
   FGL_ATTR_MAT_BACK_SHININESS,
   FGL_ATTR_MAT_FRONT_INDEXES,
   FGL_ATTR_MAT_BACK_INDEXES,
   FGL_ATTR_COUNT,
};

#define FGL_ATTR_MAT_FIRST FGL_ATTR_MAT_FRONT_AMBIENT
_Static_assert(FGL_ATTR_COUNT <= 32, "fgl_vbo.format_mask holds a bit per attribute");

/* A stored vertex: the position and the attributes of the batch's vertex
 * format, each as float[4] (slots of attributes outside the format are not
 * written: read them through fgl_vbo_attr_ptr). */
struct fgl_vbo_vertex {
   float attr[FGL_ATTR_COUNT][4];
};

/* A batch's vertices as the vertex stage reads them: vertex i's attribute
 * a is the float[4] at base + i * stride + 4 * slot[a] (slot -1: not
 * stored).  Immediate mode stores the position and the format's
 * attributes only, packed (t_vbo.c); display lists and vertex arrays
 * store whole struct fgl_vbo_vertex (fgl_vertex_view_full). */
struct fgl_vertex_view {
   const float *base;
   unsigned stride;                     /* floats */
   int8_t slot[FGL_ATTR_COUNT];
};

static inline const float *fgl_vv_attr(const struct fgl_vertex_view *v, unsigned i, int a)
{
   return v->base + (size_t)i * v->stride + 4u * (unsigned)v->slot[a];
}

/* the view of v from vertex `first` on */
static inline struct fgl_vertex_view fgl_vv_from(const struct fgl_vertex_view *v, unsigned first)
{
   struct fgl_vertex_view r = *v;
   r.base += (size_t)first * v->stride;
   return r;
}

/* the view of whole stored vertices */
static inline struct fgl_vertex_view fgl_vertex_view_full(const struct fgl_vbo_vertex *verts)
{
   struct fgl_vertex_view v;
   v.base = verts->attr[0];
   v.stride = sizeof(struct fgl_vbo_vertex) / sizeof(float);
   for (int a = 0; a < FGL_ATTR_COUNT; a++)
      v.slot[a] = (int8_t)a;
   return v;
}

struct fgl_vbo_prim {
   GLenum mode;
   unsigned start, count;
   bool begin, end;          /* the prim starts/ends a glBegin/glEnd pair */
   bool indexed;             /* a glDrawElements draw (t_array.c) */
};

struct fgl_vbo {
   /* the stored vertices, packed: the position, then the format's
    * attributes in attribute order, float[4] each (the view's slots) */
   float *verts;
   unsigned vert_count, max_vert, vert_alloc;   /* vert_alloc: floats */
   unsigned vstride;                    /* floats per stored vertex */
   int8_t slot[FGL_ATTR_COUNT];
   struct fgl_vbo_prim prims[FGL_VBO_MAX_PRIM];
   unsigned prim_count;
   unsigned attr_size[FGL_ATTR_COUNT];  /* components in the vertex format, 0 = absent */
   unsigned active_size[FGL_ATTR_COUNT];/* components of the last call, as Mesa tracks it */
   unsigned vertex_size;                /* sum of attr_size, in floats */
   unsigned format_mask;                /* bit a: attribute a (not the
                                         * position) is in the format,
                                         * attr_size[a] != 0; what a
                                         * glVertex stores besides the
                                         * position */
   unsigned buffer_used;                /* bytes of the emulated buffer consumed */
   unsigned need_flush;                 /* FGL_VBO_FLUSH_* (Mesa's NeedFlush) */
   float current[FGL_ATTR_COUNT][4];    /* latest value of each attribute in
                                         * the format (ctx->Current.Attrib
                                         * holds the others); its
                                         * components past attr_size are
                                         * the defaults */
   /* Mesa's exec->vtx.vertex memory behind the non-position attributes:
    * each attribute's slot (offset, attr_size floats, in the order the
    * attributes joined the format), and what the slots last held when the
    * layout changed.  A slot keeps its old contents when the format is
    * reset or rearranged, so an attribute that joins the format starts
    * with whatever an earlier format left there; only glEvalCoord
    * (main/eval.c), which restores the vertex after evaluating, lets such
    * a value survive [S: vbo_exec_api.c:vbo_exec_wrap_upgrade_vertex,
    * _mesa_EvalCoord1f]. */
   float vtx_mem[FGL_ATTR_COUNT * 4];
   unsigned mem_offset[FGL_ATTR_COUNT];
   unsigned size_no_pos;                /* vertex_size_no_pos */

   /* Scratch memory of the vertex stage, kept from draw to draw and only
    * grown (fgl_vbo_scratch), so that a batch allocates nothing: the
    * transformed vertices of t_render_batch (struct t_vertex, t_pipeline.h)
    * and the fetched vertices of an array draw with its element lists
    * (t_array.c). */
   struct t_vertex *tv;
   unsigned tv_alloc;
   struct fgl_vbo_vertex *array_verts;
   unsigned array_alloc;
   unsigned *array_elts;        /* an indexed draw's vertex cache lists */
   unsigned array_elts_alloc;
};

bool fgl_vbo_init(struct fgl_vbo *vbo);
/* A scratch array buf of *alloc elements of elem_size bytes, grown to at
 * least n (*alloc updated): the array to use from now on, or NULL when out
 * of memory (buf is then still the caller's). */
void *fgl_vbo_scratch(void *buf, unsigned *alloc, unsigned n, size_t elem_size);
/* The same for an array whose elements start on cache lines (elem_size a
 * multiple of 64, the array 64-byte aligned): the transformed vertices,
 * so that the hot fields of one vertex share one line.  The contents are
 * not kept when it grows (buf is then freed). */
void *fgl_vbo_scratch_lines(void *buf, unsigned *alloc, unsigned n, size_t elem_size);
/* The most elements a scratch array keeps after a draw: enough for any
 * immediate-mode batch (the 512 KiB buffer holds at most 65535 vertices);
 * a larger one (a long array draw or display list) is freed after its
 * draw rather than kept for the context's lifetime. */
#define FGL_VBO_SCRATCH_KEEP 65536u
/* The largest scratch array fgl_vbo_scratch allocates (8 GiB): a larger
 * request fails, and the draw raises GL_OUT_OF_MEMORY. */
#define FGL_VBO_SCRATCH_MAX_BYTES ((size_t)8 << 30)
void fgl_vbo_fini(struct fgl_vbo *vbo);

/* An attribute call (glColor*, glVertex*) with n components. */
void fgl_vbo_attr(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned n,
                  float x, float y, float z, float w);
/* The common cases of fgl_vbo_attr, inline in the entry points (as
 * Mesa's vbo_attrib_tmp.h ATTR macros): an attribute whose last call had
 * as many components (fgl_vbo_fixup would change nothing), and a glVertex
 * whose format holds its components and whose vertex fits the buffer
 * (neither upgrade_vertex nor ensure_room would act); the vertex stored
 * exactly as fgl_vbo_attr stores it.  Returns false, having done nothing,
 * in every other case: the caller then calls fgl_vbo_attr. */
static inline bool fgl_vbo_attr_fast(struct fgl_vbo *vbo, enum fgl_vbo_attr attr, unsigned n,
                                     float x, float y, float z, float w, bool *wrap)
{
   float *cur = vbo->current[attr];
   /* Each attribute's float[4] is written whole, with one 16-byte store
    * (the components past n keep their bits), so that the glVertex that
    * copies it into the vertex reads it back from the store buffer:
    * stored as two or three pieces, that 16-byte load would wait for
    * them to reach the cache (a failed store-to-load forward, per
    * attribute and vertex). */
#ifdef FGL_VBO_SSE2
   const __m128 v = _mm_setr_ps(x, y, z, w);
#endif
   if (attr != FGL_ATTR_POS) {
      if (__builtin_expect(vbo->active_size[attr] != n, 0))
         return false;
#ifdef FGL_VBO_SSE2
      if (n >= 4) {
         _mm_storeu_ps(cur, v);
      } else {
         /* lanes 0..n-1 from v, the others from cur: bitwise selects */
         const __m128 keep =
            _mm_castsi128_ps(_mm_setr_epi32(0, n > 1 ? 0 : -1, n > 2 ? 0 : -1, -1));
         const __m128 old = _mm_loadu_ps(cur);
         _mm_storeu_ps(cur, _mm_or_ps(_mm_and_ps(keep, old), _mm_andnot_ps(keep, v)));
      }
#else
      cur[0] = x;
      if (n > 1)
         cur[1] = y;
      if (n > 2)
         cur[2] = z;
      if (n > 3)
         cur[3] = w;
#endif
      vbo->need_flush |= FGL_VBO_FLUSH_CURRENT;
      return true;
   }
   if (__builtin_expect(vbo->attr_size[FGL_ATTR_POS] < n ||
                        (size_t)(vbo->vert_count + 1) * vbo->vstride > vbo->vert_alloc, 0))
      return false;
   float *dst = vbo->verts + (size_t)vbo->vert_count * vbo->vstride;
#ifdef FGL_VBO_SSE2
   _mm_storeu_ps(cur, v);
   _mm_storeu_ps(dst, v);
#else
   cur[0] = x;
   cur[1] = y;
   cur[2] = z;
   cur[3] = w;
   memcpy(dst, cur, 4 * sizeof(float));
#endif
   for (unsigned m = vbo->format_mask; m; m &= m - 1) {
      const int a = __builtin_ctz(m);
      memcpy(dst + 4 * vbo->slot[a], vbo->current[a], 4 * sizeof(float));
   }
   *wrap = ++vbo->vert_count >= vbo->max_vert;
   return true;
}
/* vbo_exec_vtx_wrap: the buffer is full in the middle of a primitive
 * (after fgl_vbo_attr_fast set *wrap) */
void fgl_vbo_wrap(struct fgl_context *ctx);
/* vbo_exec_fixup_vertex: make attr's vertex-format size fit n components */
void fgl_vbo_fixup(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned n);
void fgl_vbo_begin(struct fgl_context *ctx, GLenum mode);
void fgl_vbo_end(struct fgl_context *ctx);

/* While a batch is drawn: where attribute attr of vertex verts[i] is, as
 * ptr + i * stride floats.  Attributes outside the batch's format are the
 * same for every vertex (Mesa's stride-0 current values): stride 0. */
const float *fgl_vbo_attr_ptr(const struct fgl_context *ctx, const struct fgl_vertex_view *verts,
                              enum fgl_vbo_attr attr, unsigned *stride);

/* vbo_exec_FlushVertices(FLUSH_STORED_VERTICES): draw what is stored,
 * copy the format's attributes to ctx->Current.Attrib and reset the vertex
 * format. */
void fgl_vbo_flush_vertices(struct fgl_context *ctx);

/* vbo_exec_FlushVertices(FLUSH_UPDATE_CURRENT): copy the format's
 * attributes to ctx->Current.Attrib, keeping the format. */
void fgl_vbo_flush_current(struct fgl_context *ctx);


#endif
