/*
 * Array draws (glDrawArrays, glDrawElements) and glArrayElement.
 *
 * The oracle fetches client arrays in draw's LLVM vertex shader
 * [S: gallium/auxiliary/draw/draw_llvm.c:fetch_vector ->
 * gallivm/lp_bld_format_soa.c:lp_build_fetch_rgba_soa,
 * lp_build_extract_soa_chan], with the pipe format the state tracker picks
 * for each GL type [S: state_tracker/st_atom_array.c, main/glformats.c:
 * _mesa_get_vertex_format]: normalized integers (colours, normals) as
 *   unsigned n-bit:  (float)c * (float)(1.0 / (2^n - 1))       n <= 24
 *                    32 bits: ((bits(c >> 9 | 0x3f800000) - 1.0f)
 *                             * (float)(2^23 / (2^23 - 1)))
 *                    [S: gallivm/lp_bld_conv.c:lp_build_unsigned_norm_to_float]
 *   signed n-bit:    max((float)c * (float)(1.0 / (2^(n-1) - 1)), -1.0f)
 * which is not the immediate-mode conversion of main/conv.h (c / 255.0f,
 * (2c + 1) / 255): an array draw and glArrayElement of the same data can
 * differ.  Other integers convert with (float)c, doubles round to float.
 * Components the array does not have are (0, 0, 0, 1).
 *
 * The fetched vertices become one batch for t_render_batch, with the
 * enabled arrays as its vertex format: attributes without an enabled array
 * are the current values (stride 0, and a colour that is not a varying
 * of the fragment program), and the draw leaves the current values alone.
 */
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "context.h"
#include "main/conv.h"
#include "main/dlist.h"
#include "tnl/t_pipeline.h"
#include "fgl_alloc.h"

/* One component c of an array element, as gallivm fetches it.  The
 * array types are GL 1.5's: varray.c refuses GL_HALF_FLOAT, the packed
 * 2_10_10_10 types and a GL_BGRA size (README "Version and honesty"). */
static float fetch_comp(const GLubyte *p, GLenum type, bool normalized, int c)
{
   switch (type) {
   case GL_BYTE: {
      const GLbyte v = ((const GLbyte *)p)[c];
      return normalized ? fmaxf((float)v * (float)(1.0 / 127), -1.0f) : (float)v;
   }
   case GL_UNSIGNED_BYTE: {
      const GLubyte v = p[c];
      return normalized ? (float)v * (float)(1.0 / 255) : (float)v;
   }
   case GL_SHORT: {
      GLshort v;
      memcpy(&v, p + 2 * c, 2);
      return normalized ? fmaxf((float)v * (float)(1.0 / 32767), -1.0f) : (float)v;
   }
   case GL_UNSIGNED_SHORT: {
      GLushort v;
      memcpy(&v, p + 2 * c, 2);
      return normalized ? (float)v * (float)(1.0 / 65535) : (float)v;
   }
   case GL_INT: {
      GLint v;
      memcpy(&v, p + 4 * c, 4);
      return normalized ? fmaxf((float)v * (float)(1.0 / 2147483647.0), -1.0f) : (float)v;
   }
   case GL_UNSIGNED_INT: {
      GLuint v;
      memcpy(&v, p + 4 * c, 4);
      if (!normalized)
         return (float)v;
      /* more bits than a float's mantissa: the top 23 as a float in [1,2) */
      const uint32_t bits = (v >> 9) | 0x3f800000u;
      float f;
      memcpy(&f, &bits, 4);
      return (f - 1.0f) * (float)(8388608.0 / 8388607.0);
   }
   case GL_FLOAT: {
      float v;
      memcpy(&v, p + 4 * c, 4);
      return v;
   }
   case GL_DOUBLE: {
      double v;
      memcpy(&v, p + 8 * c, 8);
      return (float)v;
   }
   default:
      return 0.0f;
   }
}

/* Bytes of one element of an array. */
static uint64_t element_bytes(const struct fgl_client_array *a)
{
   switch (a->Type) {
   case GL_BYTE:
   case GL_UNSIGNED_BYTE:
      return (uint64_t)a->Size;
   case GL_SHORT:
   case GL_UNSIGNED_SHORT:
      return 2u * (uint64_t)a->Size;
   case GL_DOUBLE:
      return 8u * (uint64_t)a->Size;
   default:
      return 4u * (uint64_t)a->Size;
   }
}

static void fetch(const struct fgl_client_array *a, bool normalized, GLuint elt, float out[4])
{
   out[0] = 0.0f, out[1] = 0.0f, out[2] = 0.0f, out[3] = 1.0f;
   /* an enabled array without a pointer: llvmpipe maps no buffer for it
    * (lp_draw_arrays.c: a NULL user buffer is skipped) and draw's fetch
    * of an empty buffer gives zeros in the format's channels
    * (draw_llvm.c:fetch_vector, out-of-bound elements): a default 4-component
    * colour array is (0, 0, 0, 0).  The element's offset there is
    * stride * index in 32 bits (wrapping), and a user array's size is
    * ~0u: an element that ends past 2^32 - 1 bytes is out of bounds too
    * (glDrawArrays with first -1 fetches index 2^32 - 1), one whose
    * offset wraps is read there (first INT_MIN draws from element 0).
    * The 32-bit offset is a signed GEP index added to the buffer's
    * pointer (lp_build_gather): an element of a negative first below the
    * 4 GB bound is read before the array's pointer (first -2 of a 16-byte
    * stride: offset 0xffffffe0, 32 bytes before Ptr), not 4 GB after it. */
   const uint32_t offset = (uint32_t)((uint64_t)elt * (uint64_t)a->EffStride);
   const GLubyte *p;
   const struct fgl_buffer_object *bo = a->BufferObj;
   if (bo) {
      /* from a buffer object: the pointer is an offset, 32 bits in
       * gallium's pipe_vertex_buffer, and the element must end inside
       * the store (draw_llvm.c: buffer_size_adj), else it reads zeros */
      const uint64_t base = (uint32_t)(uintptr_t)a->Ptr, esize = element_bytes(a);
      const uint64_t size = bo->Data ? (uint64_t)bo->Size : 0;
      if (base + esize > size || offset > size - esize - base) {
         if (a->Size == 4)
            out[3] = 0.0f;
         return;
      }
      p = bo->Data + base + offset;
   } else {
      if (!a->Ptr || (uint64_t)offset + element_bytes(a) > UINT32_MAX) {
         if (a->Size == 4)
            out[3] = 0.0f;
         return;
      }
      p = (const GLubyte *)a->Ptr + (ptrdiff_t)(int32_t)offset;
   }
   for (int c = 0; c < a->Size; c++)
      out[c] = fetch_comp(p, a->Type, normalized, c);
}

/* The vertices of mode's first primitive and of each next one
 * (u_prim.h u_prim_vertex_count), count trimmed to whole primitives. */
static GLsizei trim_count(GLenum mode, GLsizei count)
{
   static const GLsizei first[] = { 1, 2, 2, 2, 3, 3, 3, 4, 4, 3 };
   static const GLsizei incr[] = { 1, 2, 1, 1, 3, 1, 1, 4, 2, 1 };
   if (count < first[mode])
      return 0;
   return count - (count - first[mode]) % incr[mode];
}

/* the batch's vertex format of an array draw: the enabled arrays (the
 * state tracker's vertex elements; _mesa_set_varying_vp_inputs) */
static const struct { enum fgl_array_index array; enum fgl_vbo_attr attr; bool norm; }
array_map[] = {
   { FGL_ARRAY_VERTEX, FGL_ATTR_POS, false },
   { FGL_ARRAY_NORMAL, FGL_ATTR_NORMAL, true },
   { FGL_ARRAY_COLOR, FGL_ATTR_COLOR0, true },
   { FGL_ARRAY_COLOR1, FGL_ATTR_COLOR1, true },
   { FGL_ARRAY_FOGCOORD, FGL_ATTR_FOG, false },
   { FGL_ARRAY_TEXCOORD, FGL_ATTR_TEX0, false },
   { FGL_ARRAY_TEXCOORD1 + 0, FGL_ATTR_TEX1, false },
   { FGL_ARRAY_TEXCOORD1 + 1, FGL_ATTR_TEX2, false },
   { FGL_ARRAY_TEXCOORD1 + 2, FGL_ATTR_TEX3, false },
   { FGL_ARRAY_TEXCOORD1 + 3, FGL_ATTR_TEX4, false },
   { FGL_ARRAY_TEXCOORD1 + 4, FGL_ATTR_TEX5, false },
   { FGL_ARRAY_TEXCOORD1 + 5, FGL_ATTR_TEX6, false },
   { FGL_ARRAY_TEXCOORD1 + 6, FGL_ATTR_TEX7, false },
   { FGL_ARRAY_EDGEFLAG, FGL_ATTR_EDGEFLAG, false },
};

/* ctx->Vbo.attr_size for an array draw.  No position array: the
 * compatibility profile draws all the same, every vertex at the position
 * attribute's current value, which no glVertex changes: (0, 0, 0, 1)
 * (st_atom_array.c feeds a disabled attribute from the current values;
 * vbo_exec_copy_to_current skips the position). */
static void set_array_format(struct fgl_context *ctx)
{
   const struct fgl_client_array *A = ctx->Array.Array;
   struct fgl_vbo *vbo = &ctx->Vbo;
   memset(vbo->attr_size, 0, sizeof(vbo->attr_size));
   if (!A[FGL_ARRAY_VERTEX].Enabled)
      vbo->attr_size[FGL_ATTR_POS] = 4;
   for (unsigned m = 0; m < sizeof(array_map) / sizeof(array_map[0]); m++)
      if (A[array_map[m].array].Enabled)
         vbo->attr_size[array_map[m].attr] = (unsigned)A[array_map[m].array].Size;
}

void t_set_draw_inputs(struct fgl_context *ctx)
{
   const struct fgl_client_array *A = ctx->Array.Array;
   ctx->_VaryingTexUnits = 0;
   for (unsigned u = 0; u < FGL_MAX_TEXTURE_UNITS; u++)
      if (A[FGL_ARRAY_TEX(u)].Enabled)
         ctx->_VaryingTexUnits |= 1u << u;
}

/* n vertices of the enabled arrays into verts: elements fetch_elt[i], or
 * first + i without an element list */
static void fetch_vertices(const struct fgl_context *ctx, const GLuint *fetch_elt, GLuint first,
                           unsigned n, struct fgl_vbo_vertex *verts)
{
   const struct fgl_client_array *A = ctx->Array.Array;
   if (!A[FGL_ARRAY_VERTEX].Enabled) {
      for (unsigned i = 0; i < n; i++) {
         float *p = verts[i].attr[FGL_ATTR_POS];
         p[0] = 0.0f, p[1] = 0.0f, p[2] = 0.0f, p[3] = 1.0f;
      }
   }
   for (unsigned m = 0; m < sizeof(array_map) / sizeof(array_map[0]); m++) {
      const struct fgl_client_array *a = &A[array_map[m].array];
      if (!a->Enabled)
         continue;
      for (unsigned i = 0; i < n; i++) {
         const GLuint elt = fetch_elt ? fetch_elt[i] : first + i;
         fetch(a, array_map[m].norm, elt, verts[i].attr[array_map[m].attr]);
      }
   }
}

/* Non-indexed draws longer than this are drawn window by window
 * (t_render_source): their memory does not grow with the count, so a
 * draw of 2^31 - 1 vertices completes as the oracle's does (draw's vsplit
 * runs it in segments too); shorter ones fetch every vertex at once. */
#define ARRAY_WINDOW_MIN FGL_VBO_SCRATCH_KEEP

struct window_fetch {
   const struct fgl_context *ctx;
   GLuint first;                /* the draw's first element */
};

static void fetch_window(void *ud, unsigned first, unsigned n, struct fgl_vbo_vertex *out)
{
   const struct window_fetch *wf = ud;
   fetch_vertices(wf->ctx, NULL, wf->first + first, n, out);
}

bool t_index_source(const struct fgl_context *ctx, GLenum type, const GLvoid *indices,
                    struct t_index_source *src)
{
   const struct fgl_buffer_object *bo = ctx->Array.ElementBufferObj;
   src->type = type;
   if (!bo) {
      /* skip_validated_draw [S: main/draw.c]: no indices, no draw */
      src->base = indices;
      src->start = 0;
      src->limit = UINT64_MAX;
      return indices != NULL;
   }
   /* an element buffer without a store (never given data, or of size 0)
    * draws nothing ([S: st_draw.c:prepare_indexed_draw] "doesn't have any
    * backing storage"; the oracle's feedback and selection draw nothing,
    * its rendering crashes: probe p_element_buffer_no_store) */
   if (!bo->Data || bo->Size == 0)
      return false;
   /* [S: draw.c:_mesa_validated_drawrangeelements] an offset that is not
    * a multiple of the index size draws nothing; draw_pt.c DRAW_GET_IDX:
    * an index past the store (elt_buffer_size / index size) reads 0 */
   const uint64_t size = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4;
   const uint64_t offset = (uintptr_t)indices;
   if (offset % size != 0)
      return false;
   src->base = bo->Data;
   src->start = offset / size;
   src->limit = (uint64_t)bo->Size / size;
   return true;
}

void t_draw_arrays(struct fgl_context *ctx, GLenum mode, GLint first, GLsizei count,
                   GLenum index_type, const GLvoid *indices)
{
   /* skip_validated_draw [S: main/draw.c]: nothing to draw without
    * vertices or a position array */
   if (count == 0)
      return;
   /* mode: one of GL 1.5's ten (every caller, varray.c's draws, raised
    * GL_INVALID_ENUM above GL_POLYGON) */
   /* the indices: the client's (none: nothing drawn) or the element
    * buffer's */
   struct t_index_source isrc = { 0 };
   if (index_type && !t_index_source(ctx, index_type, indices, &isrc))
      return;
   /* draw_pt_trim_count [S: gallium/auxiliary/draw/draw_pt.c]: the draw
    * module runs whole primitives only and fetches no vertex of a partial
    * one (GL_TRIANGLES of 4 vertices fetches 3, a one-vertex line strip
    * none): the elements past the last whole primitive are never read */
   count = trim_count(mode, count);
   if (count == 0)
      return;
   /* ORACLE-NOTES.md "Client vertex arrays", "Without a position array
    * every triangle is empty": every vertex is at the same position (see
    * set_array_format), so every triangle, quad and polygon of the draw
    * has three equal window positions: a snapped area of 0, which the
    * rasterizer discards whatever the other attributes (r_tri.c
    * area_culled), and outside the volume all three vertices are out of
    * the same plane (t_clip_triangle).  Filled
    * on both faces and rendered (no selection hit, no feedback token, no
    * unfilled edges or points), such a draw changes nothing: it returns
    * here in O(1), where the oracle walks every vertex (robust/huge-draws:
    * 2^31 - 1 vertices of GL_QUADS).  Its lines and points are drawn. */
   if (!ctx->Array.Array[FGL_ARRAY_VERTEX].Enabled && mode >= GL_TRIANGLES &&
       ctx->RenderMode == GL_RENDER && ctx->Polygon.FrontMode == GL_FILL &&
       ctx->Polygon.BackMode == GL_FILL)
      return;

   /* glDrawElements: a small post-transform vertex cache.  An element that
    * the primitives use again while it is still in the direct-mapped
    * cache (slot: its low bits) is fetched, transformed and lit once, and
    * the primitives read their vertices through elts[].  The vertex stage
    * is a function of the element's data and of the draw's state only, so
    * sharing its result gives the same bits; the primitives, their vsplit
    * segments and their order are still those of the index list. */
   struct fgl_vbo *vbo = &ctx->Vbo;
   unsigned nverts = (unsigned)count;
   unsigned *elts = NULL;       /* the primitives' vertex i is verts[elts[i]] */
   GLuint *fetch_elt = NULL;    /* the element each stored vertex is */
   if (index_type) {
      unsigned *e = fgl_vbo_scratch(vbo->array_elts, &vbo->array_elts_alloc,
                                    2 * (unsigned)count, sizeof(*e));
      if (!e) {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return;
      }
      vbo->array_elts = e;
      elts = e;
      fetch_elt = e + count;
      enum { CACHE_SIZE = 256 };
      GLuint tag[CACHE_SIZE];
      unsigned slot[CACHE_SIZE];
      for (unsigned c = 0; c < CACHE_SIZE; c++)
         slot[c] = UINT_MAX;
      nverts = 0;
      for (GLsizei i = 0; i < count; i++) {
         const GLuint el = t_index_src_at(&isrc, i);
         const unsigned c = el % CACHE_SIZE;
         if (slot[c] == UINT_MAX || tag[c] != el) {
            tag[c] = el;
            slot[c] = nverts;
            fetch_elt[nverts++] = el;
         }
         elts[i] = slot[c];
      }
   }

   /* The immediate-mode format stays as FLUSH_FOR_DRAW left it (with only
    * attributes set it is not reset: fgl_flush_for_draw); the batch's
    * format, the enabled arrays, replaces it while the draw runs. */
   unsigned imm_size[FGL_ATTR_COUNT];
   memcpy(imm_size, vbo->attr_size, sizeof(imm_size));
   set_array_format(ctx);
   const struct fgl_vbo_prim prim = {
      .mode = mode, .start = 0, .count = (unsigned)count,
      .begin = true, .end = true, .indexed = index_type != 0,
   };
   if (!index_type && (unsigned)count > ARRAY_WINDOW_MIN) {
      /* a long draw: fetched window by window, in bounded memory */
      struct window_fetch wf = { ctx, (GLuint)first };
      /* with no array enabled every vertex is the current values */
      bool uniform = true;
      for (unsigned a = 0; a < FGL_ATTR_COUNT; a++)
         uniform &= a == FGL_ATTR_POS || vbo->attr_size[a] == 0;
      uniform &= !ctx->Array.Array[FGL_ARRAY_VERTEX].Enabled;
      const struct t_vertex_source src = { fetch_window, &wf, uniform };
      t_render_source(ctx, &src, &prim);
   } else {
      /* the fetched vertices: the context's scratch array, no allocation
       * per draw */
      struct fgl_vbo_vertex *verts = fgl_vbo_scratch(vbo->array_verts, &vbo->array_alloc,
                                                     nverts, sizeof(*verts));
      if (verts) {
         vbo->array_verts = verts;
         fetch_vertices(ctx, fetch_elt, (GLuint)first, nverts, verts);
         const struct fgl_vertex_view view = fgl_vertex_view_full(verts);
         t_render_batch_elts(ctx, &view, nverts, elts, &prim, 1);
      } else {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
      }
   }
   memcpy(vbo->attr_size, imm_size, sizeof(imm_size));
   if (vbo->array_alloc > FGL_VBO_SCRATCH_KEEP) {
      fgl_free(vbo->array_verts);
      vbo->array_verts = NULL;
      vbo->array_alloc = 0;
   }
   if (vbo->array_elts_alloc > 2 * FGL_VBO_SCRATCH_KEEP) {
      fgl_free(vbo->array_elts);
      vbo->array_elts = NULL;
      vbo->array_elts_alloc = 0;
   }
}

/* Immediate-mode conversions of the NV attribute functions
 * [S: main/api_arrayelt.c:AttribFuncsNV]: normalized integers with Mesa's
 * macros (main/conv.h), others cast, indexed by TYPE_IDX(t) = t & 7
 * (GL_DOUBLE apart); only GL 1.5's types reach here (varray.c). */
static float immediate_comp(const GLubyte *p, GLenum type, bool normalized, int c)
{
   if (type != GL_DOUBLE)
      type = 0x1400 | (type & 7);
   switch (type) {
   case GL_BYTE: {
      const GLbyte v = ((const GLbyte *)p)[c];
      return normalized ? BYTE_TO_FLOAT(v) : (float)v;
   }
   case GL_UNSIGNED_BYTE: {
      const GLubyte v = p[c];
      return normalized ? UBYTE_TO_FLOAT(v) : (float)v;
   }
   case GL_SHORT: {
      GLshort v;
      memcpy(&v, p + 2 * c, 2);
      return normalized ? SHORT_TO_FLOAT(v) : (float)v;
   }
   case GL_UNSIGNED_SHORT: {
      GLushort v;
      memcpy(&v, p + 2 * c, 2);
      return normalized ? USHORT_TO_FLOAT(v) : (float)v;
   }
   case GL_INT: {
      GLint v;
      memcpy(&v, p + 4 * c, 4);
      return normalized ? INT_TO_FLOAT(v) : (float)v;
   }
   case GL_UNSIGNED_INT: {
      GLuint v;
      memcpy(&v, p + 4 * c, 4);
      return normalized ? UINT_TO_FLOAT(v) : (float)v;
   }
   case GL_FLOAT: {
      float v;
      memcpy(&v, p + 4 * c, 4);
      return v;
   }
   case GL_DOUBLE: {
      double v;
      memcpy(&v, p + 8 * c, 8);
      return (float)v;
   }
   default:
      return 0.0f;
   }
}

static void emit(struct fgl_context *ctx, const struct fgl_client_array *a,
                 enum fgl_vbo_attr attr, bool normalized, GLint elt)
{
   /* elt * stride in int arithmetic, then added to the pointer
    * (_mesa_array_element: _mesa_vertex_attrib_address(...) +
    * elt * binding->Stride): the product wraps in 32 bits, glArrayElement
    * (INT_MIN) of a 16-byte stride reads element 0 */
   const uint32_t off = (uint32_t)elt * (uint32_t)a->EffStride;
   const ptrdiff_t delta = off > INT32_MAX ? (ptrdiff_t)off - ((ptrdiff_t)1 << 32) : (ptrdiff_t)off;
   float v[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
   const struct fgl_buffer_object *bo = a->BufferObj;
   if (bo) {
      /* from a buffer object: its store (mapped by the oracle for the
       * call, _mesa_vao_map_arrays) at the offset the pointer holds; an
       * element outside the store (which the oracle reads from wherever
       * it points) is zeros here */
      const int64_t at = (int64_t)(uintptr_t)a->Ptr + (int64_t)delta;
      const int64_t esize = (int64_t)element_bytes(a);
      if (!bo->Data || at < 0 || at + esize > (int64_t)bo->Size) {
         for (int c = 0; c < a->Size; c++)
            v[c] = 0.0f;
      } else {
         for (int c = 0; c < a->Size; c++)
            v[c] = immediate_comp(bo->Data + at, a->Type, normalized, c);
      }
   } else {
      const GLubyte *p = (const GLubyte *)a->Ptr + delta;
      for (int c = 0; c < a->Size; c++)
         v[c] = immediate_comp(p, a->Type, normalized, c);
   }
   /* through the compiler while a list is compiled (_mesa_ArrayElement
    * calls the current dispatch) */
   fgl_attr(ctx, attr, (unsigned)a->Size, v[0], v[1], v[2], v[3]);
}

void t_array_element(struct fgl_context *ctx, GLint elt)
{
   /* _mesa_array_element: the enabled non-position arrays in attribute
    * order (normal, colour, secondary colour, fog coordinate, colour
    * index, the units' texture coordinates,
    * edge flag),
    * then the position; texture coordinates are not normalized
    * [S: main/api_arrayelt.c:_mesa_array_element] */
   const struct fgl_client_array *A = ctx->Array.Array;
   if (A[FGL_ARRAY_NORMAL].Enabled)
      emit(ctx, &A[FGL_ARRAY_NORMAL], FGL_ATTR_NORMAL, true, elt);
   if (A[FGL_ARRAY_COLOR].Enabled)
      emit(ctx, &A[FGL_ARRAY_COLOR], FGL_ATTR_COLOR0, true, elt);
   if (A[FGL_ARRAY_COLOR1].Enabled)
      emit(ctx, &A[FGL_ARRAY_COLOR1], FGL_ATTR_COLOR1, true, elt);
   if (A[FGL_ARRAY_FOGCOORD].Enabled)
      emit(ctx, &A[FGL_ARRAY_FOGCOORD], FGL_ATTR_FOG, false, elt);
   if (A[FGL_ARRAY_INDEX].Enabled)
      emit(ctx, &A[FGL_ARRAY_INDEX], FGL_ATTR_COLOR_INDEX, false, elt);
   for (unsigned u = 0; u < FGL_MAX_TEXTURE_UNITS; u++)
      if (A[FGL_ARRAY_TEX(u)].Enabled)
         emit(ctx, &A[FGL_ARRAY_TEX(u)], (enum fgl_vbo_attr)(FGL_ATTR_TEX0 + u), false, elt);
   if (A[FGL_ARRAY_EDGEFLAG].Enabled)
      emit(ctx, &A[FGL_ARRAY_EDGEFLAG], FGL_ATTR_EDGEFLAG, false, elt);
   if (A[FGL_ARRAY_VERTEX].Enabled)
      emit(ctx, &A[FGL_ARRAY_VERTEX], FGL_ATTR_POS, false, elt);
}
