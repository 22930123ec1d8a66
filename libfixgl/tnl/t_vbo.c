/*
 * Immediate-mode vertex store, reproducing Mesa 22.3's vbo_exec batching
 * (vbo_exec_api.c, vbo_exec_draw.c, vbo_minmax/vbo_merge_draws): see t_vbo.h
 * for why the batch boundaries are part of the oracle's output.
 */
#include "t_vbo.h"

#include <stdlib.h>
#include <string.h>

#include "context.h"
#include "main/groups.h"
#include "tnl/t_pipeline.h"
#include "fgl_alloc.h"

static const float attr_default[4] = { 0.0f, 0.0f, 0.0f, 1.0f };

/* The packed layout of the stored vertices for the current format: the
 * position in slot 0, then each attribute of the format in attribute
 * order.  Only changed with no vertex stored (after a flush or wrap). */
static void relayout(struct fgl_vbo *vbo)
{
   int k = 1;
   for (int a = 0; a < FGL_ATTR_COUNT; a++)
      vbo->slot[a] = a == FGL_ATTR_POS ? 0 : (vbo->format_mask >> a) & 1u ? (int8_t)k++ : -1;
   vbo->vstride = 4u * (unsigned)k;
}

/* the view of the stored vertices (t_render_batch) */
static struct fgl_vertex_view stored_view(const struct fgl_vbo *vbo)
{
   struct fgl_vertex_view v;
   v.base = vbo->verts;
   v.stride = vbo->vstride;
   memcpy(v.slot, vbo->slot, sizeof(v.slot));
   return v;
}

/* stored vertex i into the whole vertex d (its format's attributes) */
static void unpack_vertex(const struct fgl_vbo *vbo, unsigned i, struct fgl_vbo_vertex *d)
{
   const float *src = vbo->verts + (size_t)i * vbo->vstride;
   for (int a = 0; a < FGL_ATTR_COUNT; a++)
      if (vbo->slot[a] >= 0)
         memcpy(d->attr[a], src + 4 * vbo->slot[a], sizeof(d->attr[a]));
}

bool fgl_vbo_init(struct fgl_vbo *vbo)
{
   memset(vbo, 0, sizeof(*vbo));
   relayout(vbo);
   vbo->vert_alloc = 1024 * 8;
   vbo->verts = fgl_malloc(vbo->vert_alloc * sizeof(*vbo->verts));
   for (int a = 0; a < FGL_ATTR_COUNT; a++)
      memcpy(vbo->current[a], attr_default, sizeof(attr_default));
   return vbo->verts != NULL;
}

void fgl_vbo_fini(struct fgl_vbo *vbo)
{
   fgl_free(vbo->verts);
   vbo->verts = NULL;
   fgl_free(vbo->tv);
   vbo->tv = NULL;
   vbo->tv_alloc = 0;
   fgl_free(vbo->array_verts);
   vbo->array_verts = NULL;
   vbo->array_alloc = 0;
   fgl_free(vbo->array_elts);
   vbo->array_elts = NULL;
   vbo->array_elts_alloc = 0;
}

/* The elements a scratch array of *alloc grows to for n (doubling from
 * 256), 0 when that is more than FGL_VBO_SCRATCH_MAX_BYTES: a draw of
 * billions of vertices (glDrawArrays(mode, 0, INT_MAX)) asks for hundreds
 * of gigabytes at once, refused as out of memory rather than attempted
 * (the oracle draws it in segments; fixgl fetches a draw's vertices at
 * once) */
static size_t scratch_grown(unsigned alloc, unsigned n, size_t elem_size)
{
   size_t want = alloc ? alloc : 256;
   while (want < n)
      want *= 2;
   return want > FGL_VBO_SCRATCH_MAX_BYTES / elem_size ? 0 : want;
}

void *fgl_vbo_scratch(void *buf, unsigned *alloc, unsigned n, size_t elem_size)
{
   if (buf && n <= *alloc)
      return buf;
   const size_t want = scratch_grown(*alloc, n, elem_size);
   if (!want)
      return NULL;
   void *p = fgl_realloc(buf, want * elem_size);
   if (p)
      *alloc = (unsigned)want;
   return p;
}

void *fgl_vbo_scratch_lines(void *buf, unsigned *alloc, unsigned n, size_t elem_size)
{
   if (buf && n <= *alloc)
      return buf;
   const size_t want = scratch_grown(*alloc, n, elem_size);
   if (!want)
      return NULL;
   void *p = fgl_aligned_alloc(64, want * elem_size);
   if (!p)
      return NULL;
   fgl_free(buf);
   *alloc = (unsigned)want;
   return p;
}

/* vbo_compute_max_verts: room left in the buffer, less one vertex kept for
 * the GL_LINE_LOOP -> GL_LINE_STRIP conversion. */
static unsigned compute_max_verts(const struct fgl_vbo *vbo)
{
   if (vbo->vertex_size == 0)
      return 0;
   const unsigned n = (FGL_VBO_BUFFER_BYTES - vbo->buffer_used) /
                      (vbo->vertex_size * (unsigned)sizeof(float));
   return n ? n - 1 : 0;
}

/* vbo_copy_vertices: how many trailing vertices of the open primitive
 * (of GL mode `mode`, ctx->Driver.CurrentExecPrimitive) continue in the next
 * buffer; may shorten the draw (odd strips). */
static unsigned copy_vertices(struct fgl_vbo *vbo, GLenum mode, struct fgl_vbo_vertex *dst)
{
   struct fgl_vbo_prim *last = &vbo->prims[vbo->prim_count - 1];
   unsigned src = last->start;   /* stored vertex index */
   const unsigned count = last->count;
   unsigned copy;

   switch (mode) {
   case GL_POINTS:
      return 0;
   case GL_LINES:
      copy = count % 2;
      break;
   case GL_TRIANGLES:
      copy = count % 3;
      break;
   case GL_QUADS:
      copy = count % 4;
      break;
   case GL_LINE_STRIP:
      copy = count < 1 ? count : 1;
      break;
   case GL_LINE_LOOP:
      /* a later section of a wrapped loop was drawn from start + 1
       * (wrap_buffers); step back to its copied vertex 0.  The count stays
       * the shortened one, so the second copy is the section's
       * second-to-last vertex, not its last: the oracle's next section
       * starts there and the loop skips one vertex per such wrap. */
      if (!last->begin)
         src--;
      /* fallthrough */
   case GL_TRIANGLE_FAN:
   case GL_POLYGON:
      if (count == 0)
         return 0;
      unpack_vertex(vbo, src, &dst[0]);
      if (count == 1)
         return 1;
      unpack_vertex(vbo, src + count - 1, &dst[1]);
      return 2;
   case GL_TRIANGLE_STRIP:
      /* keep an even number of triangles in each draw so that windings
       * do not flip: an odd strip leaves its last triangle for the next */
      if (count & 1)
         last->count--;
      /* fallthrough */
   case GL_QUAD_STRIP:
      copy = count <= 1 ? count : 2 + (count & 1);
      break;
   default:
      return 0;
   }
   for (unsigned k = 0; k < copy; k++)
      unpack_vertex(vbo, src + count - copy + k, &dst[k]);
   return copy;
}

/* vbo_exec_vtx_flush: draw the stored primitives, keeping the vertices an
 * open primitive needs (returned in copied[], count in *ncopied). */
static void vtx_flush(struct fgl_context *ctx, struct fgl_vbo_vertex *copied,
                      unsigned *ncopied)
{
   struct fgl_vbo *vbo = &ctx->Vbo;
   struct fgl_vbo_vertex scratch[3];
   unsigned nc = 0;

   if (!copied)
      copied = scratch;
   if (vbo->prim_count && vbo->vert_count) {
      if (fgl_inside_begin_end(ctx))
         nc = copy_vertices(vbo, ctx->BeginMode, copied);
      if (nc != vbo->vert_count) {
         const struct fgl_vertex_view view = stored_view(vbo);
         t_render_batch(ctx, &view, vbo->vert_count, vbo->prims, vbo->prim_count);
      }
   }
   /* the emulated buffer advances; with 1 KiB or less left a new one is used */
   vbo->buffer_used += vbo->vert_count * vbo->vertex_size * (unsigned)sizeof(float);
   if (!(FGL_VBO_BUFFER_BYTES > vbo->buffer_used + 1024))
      vbo->buffer_used = 0;
   vbo->prim_count = 0;
   vbo->vert_count = 0;
   vbo->max_vert = compute_max_verts(vbo);
   if (ncopied)
      *ncopied = nc;
}

/* vbo_exec_wrap_buffers: draw what is stored and restart the open
 * primitive at the beginning of the buffer. */
static unsigned wrap_buffers(struct fgl_context *ctx, struct fgl_vbo_vertex *copied)
{
   struct fgl_vbo *vbo = &ctx->Vbo;
   unsigned ncopied = 0;

   if (vbo->prim_count == 0) {
      vbo->vert_count = 0;
      return 0;
   }

   struct fgl_vbo_prim *last = &vbo->prims[vbo->prim_count - 1];
   const bool last_begin = last->begin;
   unsigned last_count = 0;
   if (fgl_inside_begin_end(ctx)) {
      last->count = vbo->vert_count - last->start;
      last_count = last->count;
      last->end = false;
   }

   /* a wrapped GL_LINE_LOOP is drawn section by section as line strips;
    * later sections skip their vertex 0 (the loop's first vertex, kept for
    * closing the loop at glEnd) */
   if (last->mode == GL_LINE_LOOP && last_count > 0 && !last->end) {
      last->mode = GL_LINE_STRIP;
      if (!last_begin) {
         last->start++;
         last->count--;
      }
   }

   if (vbo->vert_count) {
      vtx_flush(ctx, copied, &ncopied);
   } else {
      vbo->prim_count = 0;
   }

   if (fgl_inside_begin_end(ctx)) {
      vbo->prims[0] = (struct fgl_vbo_prim){
         .mode = ctx->BeginMode, .start = 0,
         .begin = ncopied == last_count ? last_begin : false,
      };
      vbo->prim_count = 1;
   }
   return ncopied;
}

/* room for n stored vertices of the current layout */
static bool ensure_room(struct fgl_context *ctx, struct fgl_vbo *vbo, unsigned n)
{
   const size_t want = (size_t)n * vbo->vstride;
   if (want <= vbo->vert_alloc)
      return true;
   size_t alloc = vbo->vert_alloc;
   while (alloc < want)
      alloc *= 2;
   if (alloc > UINT32_MAX)
      return false;
   float *v = fgl_realloc(vbo->verts, alloc * sizeof(*v));
   if (!v) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return false;
   }
   vbo->verts = v;
   vbo->vert_alloc = (unsigned)alloc;
   return true;
}

/* the copied vertices stored again, in the current layout */
static void put_back(struct fgl_context *ctx, struct fgl_vbo *vbo, const struct fgl_vbo_vertex *copied, unsigned n)
{
   if (n && ensure_room(ctx, vbo, vbo->vert_count + n)) {
      for (unsigned k = 0; k < n; k++) {
         float *dst = vbo->verts + (size_t)(vbo->vert_count + k) * vbo->vstride;
         for (int a = 0; a < FGL_ATTR_COUNT; a++)
            if (vbo->slot[a] >= 0)
               memcpy(dst + 4 * vbo->slot[a], copied[k].attr[a], sizeof(copied[k].attr[a]));
      }
      vbo->vert_count += n;
   }
}

/* vbo_exec_vtx_wrap: the buffer is full in the middle of a primitive. */
static void vtx_wrap(struct fgl_context *ctx)
{
   struct fgl_vbo_vertex copied[3];
   const unsigned n = wrap_buffers(ctx, copied);
   put_back(ctx, &ctx->Vbo, copied, n);
}

/* vbo_exec_wrap_upgrade_vertex: a larger vertex format splits the batch. */
static void copy_to_current(struct fgl_context *ctx);

/* the format's attribute values into their slots of the vertex memory,
 * before the layout changes */
static void sync_vtx_mem(struct fgl_vbo *vbo)
{
   for (int a = FGL_ATTR_POS + 1; a < FGL_ATTR_COUNT; a++)
      if (vbo->attr_size[a])
         memcpy(&vbo->vtx_mem[vbo->mem_offset[a]], vbo->current[a],
                vbo->attr_size[a] * sizeof(float));
}

/* vbo_reset_all_attr: the memory keeps its contents */
static void reset_all_attr(struct fgl_vbo *vbo)
{
   sync_vtx_mem(vbo);
   memset(vbo->attr_size, 0, sizeof(vbo->attr_size));
   vbo->format_mask = 0;
   memset(vbo->active_size, 0, sizeof(vbo->active_size));
   vbo->vertex_size = 0;
   vbo->size_no_pos = 0;
   relayout(vbo);
}

/* the slot layout of vbo_exec_wrap_upgrade_vertex: a new attribute is
 * appended (the position is always last, outside the memory); a grown
 * one moves the attributes after it right.  The components the attribute
 * gains read what the memory held there. */
static void upgrade_layout(struct fgl_vbo *vbo, enum fgl_vbo_attr attr, unsigned size)
{
   const unsigned old = vbo->attr_size[attr];
   sync_vtx_mem(vbo);
   if (old) {
      const unsigned off = vbo->mem_offset[attr];
      if (off + old < vbo->size_no_pos) {
         memmove(&vbo->vtx_mem[off + size], &vbo->vtx_mem[off + old],
                 (vbo->size_no_pos - off - old) * sizeof(float));
         for (int a = FGL_ATTR_POS + 1; a < FGL_ATTR_COUNT; a++)
            if (a != (int)attr && vbo->attr_size[a] && vbo->mem_offset[a] > off)
               vbo->mem_offset[a] += size - old;
      }
   } else {
      vbo->mem_offset[attr] = vbo->size_no_pos;
   }
   vbo->size_no_pos += size - old;
   for (unsigned i = old; i < size; i++)
      vbo->current[attr][i] = vbo->vtx_mem[vbo->mem_offset[attr] + i];
}

static void upgrade_vertex(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned size)
{
   struct fgl_vbo *vbo = &ctx->Vbo;
   struct fgl_vbo_vertex copied[3];
   const unsigned lastcount = vbo->vert_count;
   const unsigned n = wrap_buffers(ctx, copied);

   /* "Heuristic: attempt to isolate attributes received outside
    * begin/end": a new attribute outside glBegin/glEnd after more than 8
    * stored vertices empties the vertex format first, so the next glBegin
    * flushes the batch [S: vbo/vbo_exec_api.c:vbo_exec_wrap_upgrade_vertex]
    * (dlist/empty_after_points). */
   if (!fgl_inside_begin_end(ctx) && !vbo->attr_size[attr] && lastcount > 8 &&
       vbo->vertex_size) {
      copy_to_current(ctx);
      reset_all_attr(vbo);
   }

   /* Replayed vertices get a newly added attribute as its current value cut
    * to the new size (COPY_SZ_4V), so the missing components read back as
    * defaults; a grown attribute keeps its clean old value
    * (ORACLE-NOTES.md "Vertex batching"). */
   if (!vbo->attr_size[attr] && attr != FGL_ATTR_POS) {
      for (unsigned k = 0; k < n; k++)
         for (unsigned i = 0; i < 4; i++)
            copied[k].attr[attr][i] = i < size ? ctx->Current.Attrib[attr][i] : attr_default[i];
   }

   if (attr != FGL_ATTR_POS)
      upgrade_layout(vbo, attr, size);
   vbo->vertex_size += size - vbo->attr_size[attr];
   vbo->attr_size[attr] = size;
   if (attr != FGL_ATTR_POS) {
      vbo->format_mask |= 1u << attr;
      /* the components past the format's size read as the defaults
       * (COPY_CLEAN): keep them so in current[], which a glVertex then
       * stores as it is (fgl_vbo_attr); a value left there by an earlier,
       * larger format is never read */
      for (unsigned i = size; i < 4; i++)
         vbo->current[attr][i] = attr_default[i];
   }
   vbo->active_size[attr] = size;
   vbo->max_vert = compute_max_verts(vbo);
   vbo->vert_count = 0;
   relayout(vbo);
   put_back(ctx, vbo, copied, n);
}

/* COPY_CLEAN: the attribute's stored components, then defaults. */
static void clean_value(const struct fgl_vbo *vbo, enum fgl_vbo_attr attr, float out[4])
{
   for (unsigned i = 0; i < 4; i++)
      out[i] = i < vbo->attr_size[attr] ? vbo->current[attr][i] : attr_default[i];
}

const float *fgl_vbo_attr_ptr(const struct fgl_context *ctx, const struct fgl_vertex_view *verts,
                              enum fgl_vbo_attr attr, unsigned *stride)
{
   if (ctx->Vbo.attr_size[attr] && verts->slot[attr] >= 0) {
      *stride = verts->stride;
      return verts->base + 4 * verts->slot[attr];
   }
   *stride = 0;
   return ctx->Current.Attrib[attr];
}

/* vbo_exec_copy_to_current: the format's attributes become current; a
 * changed colour then updates the materials that track it (after all
 * attributes, so it wins over a glMaterial of the same batch). */
static void copy_to_current(struct fgl_context *ctx)
{
   struct fgl_vbo *vbo = &ctx->Vbo;
   bool color0_changed = false;
   for (int a = FGL_ATTR_POS + 1; a < FGL_ATTR_COUNT; a++) {
      if (!vbo->attr_size[a])
         continue;
      float v[4];
      clean_value(vbo, (enum fgl_vbo_attr)a, v);
      if (memcmp(ctx->Current.Attrib[a], v, sizeof(v)) == 0)
         continue;
      memcpy(ctx->Current.Attrib[a], v, sizeof(v));
      if (a == FGL_ATTR_COLOR0)
         color0_changed = true;
      /* changed groups for glPopAttrib; the materials that the colour
       * material sets below are not marked */
      ctx->PopAttribState |= a >= FGL_ATTR_MAT_FIRST ? GL_LIGHTING_BIT : GL_CURRENT_BIT;
   }
   if (color0_changed && ctx->Light.ColorMaterialEnabled)
      fgl_update_color_material(ctx, ctx->Current.Attrib[FGL_ATTR_COLOR0]);
}

void fgl_vbo_flush_vertices(struct fgl_context *ctx)
{
   struct fgl_vbo *vbo = &ctx->Vbo;
   if (vbo->vert_count)
      vtx_flush(ctx, NULL, NULL);
   if (vbo->vertex_size) {
      copy_to_current(ctx);
      reset_all_attr(vbo);
   }
   vbo->need_flush = 0;
}

void fgl_vbo_flush_current(struct fgl_context *ctx)
{
   copy_to_current(ctx);
   /* NeedFlush = ~FLUSH_UPDATE_CURRENT: the next FLUSH_VERTICES flushes */
   ctx->Vbo.need_flush = FGL_VBO_FLUSH_STORED;
}

/* vbo_exec_fixup_vertex: grow the format, or fill defaults when the call
 * has fewer components than the last one; active_size only changes on
 * those two paths (so glColor4f then glColor3fv after a shrink keeps the
 * old alpha, as in the oracle). */
void fgl_vbo_fixup(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned n)
{
   struct fgl_vbo *vbo = &ctx->Vbo;
   float *cur = vbo->current[attr];

   if (vbo->active_size[attr] != n) {
      if (n > vbo->attr_size[attr]) {
         upgrade_vertex(ctx, attr, n);
      } else if (n < vbo->active_size[attr]) {
         for (unsigned i = n - 1; i < vbo->attr_size[attr]; i++)
            cur[i] = attr_default[i];
         vbo->active_size[attr] = n;
      }
   }
}

void fgl_vbo_attr(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned n,
                  float x, float y, float z, float w)
{
   struct fgl_vbo *vbo = &ctx->Vbo;
   const float v[4] = { x, y, z, w };
   float *cur = vbo->current[attr];

   if (attr != FGL_ATTR_POS) {
      fgl_vbo_fixup(ctx, attr, n);
      for (unsigned i = 0; i < n; i++)
         cur[i] = v[i];
      vbo->need_flush |= FGL_VBO_FLUSH_CURRENT;
      return;
   }

   if (vbo->attr_size[attr] < n)
      upgrade_vertex(ctx, attr, n);
   for (unsigned i = 0; i < 4; i++)
      cur[i] = v[i];

   /* glVertex: store a vertex (outside glBegin/glEnd it takes buffer room
    * but belongs to no primitive, as in Mesa) */
   if (!ensure_room(ctx, vbo, vbo->vert_count + 1))
      return;
   float *dst = vbo->verts + (size_t)vbo->vert_count * vbo->vstride;
   memcpy(dst, cur, 4 * sizeof(float));
   /* only the format's attributes are stored, packed; the others are
    * constant for the batch and read from ctx->Current.Attrib
    * (fgl_vbo_attr_ptr) */
   for (unsigned m = vbo->format_mask; m; m &= m - 1) {
      const int a = __builtin_ctz(m);
      /* clean_value: current[a] holds the defaults past attr_size[a]
       * (upgrade_vertex; calls write only the format's components) */
      memcpy(dst + 4 * vbo->slot[a], vbo->current[a], 4 * sizeof(float));
   }
   if (++vbo->vert_count >= vbo->max_vert)
      vtx_wrap(ctx);
}

void fgl_vbo_wrap(struct fgl_context *ctx)
{
   vtx_wrap(ctx);
}

void fgl_vbo_begin(struct fgl_context *ctx, GLenum mode)
{
   struct fgl_vbo *vbo = &ctx->Vbo;

   /* attributes set outside glBegin/glEnd do not stay in the vertex format */
   if (vbo->vertex_size && !vbo->attr_size[FGL_ATTR_POS])
      fgl_vbo_flush_vertices(ctx);

   vbo->prims[vbo->prim_count++] = (struct fgl_vbo_prim){
      .mode = mode, .start = vbo->vert_count, .begin = true,
   };
}

/* vbo_merge_draws: consecutive independent primitives of one mode become
 * one draw, unless the first one has an incomplete tail
 * (ORACLE-NOTES.md "Vertex batching"). */
static bool merge_draws(struct fgl_vbo_prim *prev, const struct fgl_vbo_prim *cur)
{
   if (prev->mode != cur->mode || prev->start + prev->count != cur->start ||
       !fgl_vbo_prim_mergeable(prev->mode, prev->count))
      return false;
   prev->count += cur->count;
   prev->end = cur->end;
   return true;
}

void fgl_vbo_end(struct fgl_context *ctx)
{
   struct fgl_vbo *vbo = &ctx->Vbo;
   /* vbo_exec_End leaves glBegin/glEnd whether or not it has a primitive
    * to close: a display list's vertex list that ends mid-primitive puts
    * the context inside glBegin/glEnd without one (playback_copy_to_current),
    * and the next glEnd ends it (ORACLE-NOTES.md "Display lists";
    * `robust/end_after_list_mid_primitive`) */
   if (vbo->prim_count == 0) {
      ctx->BeginMode = FGL_OUTSIDE_BEGIN_END;
      return;
   }
   struct fgl_vbo_prim *last = &vbo->prims[vbo->prim_count - 1];

   last->count = vbo->vert_count - last->start;
   last->end = true;
   if (last->count)
      vbo->need_flush |= FGL_VBO_FLUSH_STORED;

   /* the last section of a wrapped GL_LINE_LOOP: its vertex 0 (the loop's
    * first vertex) is appended and the section drawn as a strip from its
    * second vertex, which closes the loop (the count stays the same) */
   if (last->mode == GL_LINE_LOOP && !last->begin &&
       ensure_room(ctx, vbo, vbo->vert_count + 1)) {
      memcpy(vbo->verts + (size_t)vbo->vert_count * vbo->vstride,
             vbo->verts + (size_t)last->start * vbo->vstride, vbo->vstride * sizeof(float));
      last->start++;
      last->mode = GL_LINE_STRIP;
      vbo->vert_count++;
   }

   /* vbo_try_prim_conversion */
   if (last->mode == GL_LINE_STRIP && last->count == 2)
      last->mode = GL_LINES;
   else if ((last->mode == GL_TRIANGLE_STRIP || last->mode == GL_TRIANGLE_FAN) &&
            last->count == 3)
      last->mode = GL_TRIANGLES;

   if (vbo->prim_count >= 2 && merge_draws(&vbo->prims[vbo->prim_count - 2], last))
      vbo->prim_count--;

   ctx->BeginMode = FGL_OUTSIDE_BEGIN_END;
   if (vbo->prim_count == FGL_VBO_MAX_PRIM)
      vtx_flush(ctx, NULL, NULL);
}
