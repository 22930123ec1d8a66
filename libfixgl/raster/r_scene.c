/*
 * The scene (r_scene.h): binning on the submitting thread, the replay of
 * one tile on any thread.
 */
#include "r_scene.h"

#include "r_kernel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fgl_alloc.h"

/* vertex storage */
struct r_scene_chunk {
   struct r_scene_chunk *next;
   size_t size;
   _Alignas(16) unsigned char data[];
};

#define CHUNK_SIZE (256u << 10)

static void *scene_alloc(struct r_scene *s, size_t size)
{
   size = (size + 15u) & ~(size_t)15u;
   if (s->chunk && s->chunk_used + size <= s->chunk->size) {
      void *p = s->chunk->data + s->chunk_used;
      s->chunk_used += size;
      s->bytes += size;
      return p;
   }
   /* the next chunk of the list (kept from an earlier scene), or a new one */
   struct r_scene_chunk *next = s->chunk ? s->chunk->next : s->chunks;
   if (!next || next->size < size) {
      const size_t csize = size > CHUNK_SIZE ? size : CHUNK_SIZE;
      struct r_scene_chunk *c = fgl_malloc(sizeof(*c) + csize);
      if (!c)
         return NULL;
      c->size = csize;
      /* inserted after the current chunk (an oversized one in front of a
       * reusable one is fine: both stay on the list) */
      if (s->chunk) {
         c->next = s->chunk->next;
         s->chunk->next = c;
      } else {
         c->next = s->chunks;
         s->chunks = c;
      }
      next = c;
   }
   s->chunk = next;
   s->chunk_used = size;
   s->bytes += size;
   return next->data;
}

/* The vertex attribute slots r_triangle, r_line and r_point read for
 * state rs: those of the fragment-shader inputs, for both faces when
 * colours are two-sided, and the normal's (its w is the face) with
 * GL_PHONG_WIN. */
static int vertex_slots(const struct r_state *rs)
{
   int n = 0;
   for (unsigned m = rs->fs->fs_inputs; m; m &= m - 1) {
      const int a = __builtin_ctz(m);
      int slot = r_fs_slot(a, false) + 1;
      if (slot > n)
         n = slot;
      if (rs->rast->twoside) {
         slot = r_fs_slot(a, true) + 1;
         if (slot > n)
            n = slot;
      }
   }
   if (rs->fs->phong && n < R_ATTR_NORMAL + 1)
      n = R_ATTR_NORMAL + 1;
   if (rs->rast->point_size_per_vertex)
      n = R_ATTR_PSIZE + 1;
   return n;
}

static const struct r_vertex *copy_vertex(struct r_scene *s, const struct r_vertex *v, int slots)
{
   const size_t size = offsetof(struct r_vertex, attr) + (size_t)slots * sizeof(v->attr[0]);
   struct r_vertex *d = scene_alloc(s, size);
   if (d) {
      /* by rows of four floats: a memcpy of a variable size this small
       * (typically 32 to 96 bytes) compiles to `rep movs`, whose start-up
       * cost was most of the binning's time */
      memcpy(d->pos, v->pos, sizeof(d->pos));
      for (int i = 0; i < slots; i++)
         memcpy(d->attr[i], v->attr[i], sizeof(d->attr[i]));
   }
   return d;
}

static bool grow(void **p, uint32_t *capacity, uint32_t need, size_t elem)
{
   if (need <= *capacity)
      return true;
   uint32_t cap = *capacity ? *capacity : 16;
   while (cap < need)
      cap *= 2;
   void *n = fgl_realloc(*p, (size_t)cap * elem);
   if (!n)
      return false;
   *p = n;
   *capacity = cap;
   return true;
}

/* The scene's index of state rs: the last one when equal, else a new
 * copy that holds rs's objects.  UINT32_MAX when out of memory. */
static uint32_t state_index(struct r_scene *s, const struct r_state *rs)
{
   if (s->nstates && memcmp(&s->states[s->nstates - 1], rs, sizeof(*rs)) == 0)
      return s->nstates - 1;
   if (!grow((void **)&s->states, &s->states_capacity, s->nstates + 1, sizeof(*s->states)))
      return UINT32_MAX;
   /* a member-wise copy of rs would leave padding that never compares
    * equal: copy the bytes */
   memcpy(&s->states[s->nstates], rs, sizeof(*rs));
   r_state_hold(rs);
   s->stats |= rs->stats != NULL;
   s->bytes += sizeof(*rs);
   return s->nstates++;
}

/* Starts the scene on rs's framebuffer, or false when it has commands
 * for another. */
static bool begin(struct r_scene *s, const struct r_state *rs)
{
   if (s->fb == rs->fb)
      return true;
   if (!r_scene_empty(s))
      return false;
   const int tx = (rs->fb->width + R_TILE_SIZE - 1) >> R_TILE_LOG2;
   const int ty = (rs->fb->height + R_TILE_SIZE - 1) >> R_TILE_LOG2;
   const unsigned n = (unsigned)(tx * ty);
   if (n > s->bins_capacity) {
      struct r_bin *b = fgl_realloc(s->bins, n * sizeof(*b));
      if (!b)
         return false;
      memset(b + s->bins_capacity, 0, (n - s->bins_capacity) * sizeof(*b));
      s->bins = b;
      s->bins_capacity = n;
   }
   s->fb = rs->fb;
   s->tiles_x = tx;
   s->tiles_y = ty;
   return true;
}

/* A new command of state rs at index `at` (s->ncmds, or one past it for
 * a second command not yet counted), or UINT32_MAX. */
static uint32_t new_cmd_at(struct r_scene *s, const struct r_state *rs, enum r_cmd_kind kind,
                           uint32_t at)
{
   if (s->bytes > R_SCENE_MAX_BYTES)
      return UINT32_MAX;
   const uint32_t st = state_index(s, rs);
   if (st == UINT32_MAX)
      return UINT32_MAX;
   if (!grow((void **)&s->cmds, &s->cmds_capacity, at + 1, sizeof(*s->cmds)))
      return UINT32_MAX;
   s->bytes += sizeof(struct r_cmd);
   struct r_cmd *c = &s->cmds[at];
   memset(c, 0, sizeof(*c));
   c->kind = (uint8_t)kind;
   c->state = st;
   return at;
}

/* A new command of state rs (its index), or UINT32_MAX. */
static uint32_t new_cmd(struct r_scene *s, const struct r_state *rs, enum r_cmd_kind kind)
{
   return new_cmd_at(s, rs, kind, s->ncmds);
}

/* Appends command `ci` to the bins of the tiles that the pixel box
 * [x0,x1) x [y0,y1) touches (already inside the framebuffer), but those
 * that a triangle's `edges` (or NULL) exclude. */
static bool bin_box(struct r_scene *s, uint32_t ci, int x0, int y0, int x1, int y1,
                    const struct r_tri_edges *edges)
{
   const int tx0 = x0 >> R_TILE_LOG2, tx1 = (x1 - 1) >> R_TILE_LOG2;
   const int ty0 = y0 >> R_TILE_LOG2, ty1 = (y1 - 1) >> R_TILE_LOG2;
   if (tx0 == tx1 && ty0 == ty1) {
      /* a box of one tile (most small triangles): no test, no loop */
      struct r_bin *b = &s->bins[ty0 * s->tiles_x + tx0];
      if (__builtin_expect(b->count >= b->capacity, 0) &&
          !grow((void **)&b->cmd, &b->capacity, b->count + 1, sizeof(*b->cmd)))
         return false;
      b->cmd[b->count++] = ci;
      s->bytes += sizeof(*b->cmd);
      return true;
   }
   for (int ty = ty0; ty <= ty1; ty++) {
      for (int tx = tx0; tx <= tx1; tx++) {
         if (edges && r_tri_edges_miss_tile(edges, tx << R_TILE_LOG2, ty << R_TILE_LOG2))
            continue;
         struct r_bin *b = &s->bins[ty * s->tiles_x + tx];
         if (!grow((void **)&b->cmd, &b->capacity, b->count + 1, sizeof(*b->cmd)))
            return false;
         b->cmd[b->count++] = ci;
         s->bytes += sizeof(*b->cmd);
      }
   }
   return true;
}

/* Removes command `ci` from every bin again (out of memory while binning
 * it), so that the scene stays as it was. */
static void unbin(struct r_scene *s, uint32_t ci)
{
   for (unsigned t = 0; t < r_scene_tiles(s); t++) {
      struct r_bin *b = &s->bins[t];
      if (b->count && b->cmd[b->count - 1] == ci)
         b->count--;
   }
}

/* rs's draw region cut to its framebuffer: r = x0, y0, x1, y1 */
static inline void draw_region(const struct r_state *rs, int r[4])
{
   r[0] = rs->x0 < 0 ? 0 : rs->x0;
   r[1] = rs->y0 < 0 ? 0 : rs->y0;
   r[2] = rs->x1 > rs->fb->width ? rs->fb->width : rs->x1;
   r[3] = rs->y1 > rs->fb->height ? rs->fb->height : rs->y1;
}

/* The pixel box of a primitive whose window positions span
 * [minx, maxx] x [miny, maxy] widened by `pad` pixels, cut to the draw
 * region of rs; false when empty.  Non-finite positions take the whole
 * region (the rasterizers decide what, if anything, they cover). */
static bool prim_box(const struct r_state *rs, float minx, float miny, float maxx, float maxy,
                     float pad, int box[4])
{
   int r[4];
   draw_region(rs, r);
   int x0 = r[0], y0 = r[1], x1 = r[2], y1 = r[3];
   if (isfinite(minx) && isfinite(maxx) && isfinite(miny) && isfinite(maxy) && isfinite(pad)) {
      /* pixel centres x + 0.5 inside [minx - pad, maxx + pad], with a
       * pixel of slack for the snapping to 1/256 and the fill rules */
      const float fx0 = floorf(minx - pad) - 1.0f, fx1 = ceilf(maxx + pad) + 2.0f;
      const float fy0 = floorf(miny - pad) - 1.0f, fy1 = ceilf(maxy + pad) + 2.0f;
      if (fx0 > (float)x0) x0 = fx0 >= (float)x1 ? x1 : (int)fx0;
      if (fy0 > (float)y0) y0 = fy0 >= (float)y1 ? y1 : (int)fy0;
      if (fx1 < (float)x1) x1 = fx1 <= (float)x0 ? x0 : (int)fx1;
      if (fy1 < (float)y1) y1 = fy1 <= (float)y0 ? y0 : (int)fy1;
   }
   box[0] = x0;
   box[1] = y0;
   box[2] = x1;
   box[3] = y1;
   return x0 < x1 && y0 < y1;
}

static inline float min2(float a, float b) { return a < b ? a : b; }
static inline float max2(float a, float b) { return a > b ? a : b; }

/* floorf(v) and ceilf(v) as ints, for |v| < 2^23 */
static inline int ifloor(float v)
{
   const int i = (int)v;
   return i - ((float)i > v);
}

static inline int iceil(float v)
{
   const int i = (int)v;
   return i + ((float)i < v);
}

/* The pixel box of n vertices' window positions widened by `pad` (see
 * prim_box); false when it is empty. */
static bool vertex_box(const struct r_state *rs, const struct r_vertex *const *v, int n,
                       float pad, int box[4])
{
   float minx = v[0]->pos[0], maxx = minx, miny = v[0]->pos[1], maxy = miny;
   /* every position and the pad under 2^22 (a NaN is not): prim_box's
    * box in ints, without its floorf, ceilf and float compares (the
    * sums are under 2^23, so exact integers, and so are the region's
    * bounds, cut to the buffer, once the region is not empty); the
    * stipple stage's dashes and small lines spent 210 instructions a
    * line in prim_box */
   const float lim = 0x1p22f;
   bool small = fabsf(pad) < lim;
   for (int i = 0; i < n; i++) {
      const float x = v[i]->pos[0], y = v[i]->pos[1];
      small &= fabsf(x) < lim;
      small &= fabsf(y) < lim;
      minx = min2(minx, x);
      maxx = max2(maxx, x);
      miny = min2(miny, y);
      maxy = max2(maxy, y);
   }
   if (small) {
      int r[4];
      draw_region(rs, r);
      int x0 = r[0], y0 = r[1], x1 = r[2], y1 = r[3];
      if (x0 < x1 && y0 < y1) {
         const int fx0 = ifloor(minx - pad) - 1, fx1 = iceil(maxx + pad) + 2;
         const int fy0 = ifloor(miny - pad) - 1, fy1 = iceil(maxy + pad) + 2;
         if (fx0 > x0) x0 = fx0 >= x1 ? x1 : fx0;
         if (fy0 > y0) y0 = fy0 >= y1 ? y1 : fy0;
         if (fx1 < x1) x1 = fx1 <= x0 ? x0 : fx1;
         if (fy1 < y1) y1 = fy1 <= y0 ? y0 : fy1;
      }
      box[0] = x0;
      box[1] = y0;
      box[2] = x1;
      box[3] = y1;
      return x0 < x1 && y0 < y1;
   }
   for (int i = 0; i < n; i++) {
      if (isnan(v[i]->pos[0]) || isnan(v[i]->pos[1]))
         minx = NAN;   /* the whole region */
   }
   return prim_box(rs, minx, miny, maxx, maxy, pad, box);
}

/* Where the scene's storage stood before a command was added: a command
 * that cannot be binned is dropped with what it allocated (its vertices or
 * setup, and the state it added). */
struct scene_mark {
   struct r_scene_chunk *chunk;
   size_t used, bytes;
   uint32_t states;
};

static struct scene_mark scene_mark(const struct r_scene *s)
{
   return (struct scene_mark){ s->chunk, s->chunk_used, s->bytes, s->nstates };
}

/* drops the storage allocated since `m` (the state too when `state`) */
static void scene_rollback(struct r_scene *s, const struct scene_mark *m, bool state)
{
   s->chunk = m->chunk;
   s->chunk_used = m->used;
   s->bytes = m->bytes;
   if (state && s->nstates > m->states) {
      s->nstates--;
      r_state_release(&s->states[s->nstates]);
   }
}

/* Appends command ci, made since `mark`, to the bins of the tiles of `box`
 * that `edges` (or NULL) does not exclude; when that fails (out of
 * memory), drops it with what it allocated (scene_rollback). */
static bool bin_cmd(struct r_scene *s, uint32_t ci, const int box[4],
                    const struct r_tri_edges *edges, const struct scene_mark *mark)
{
   if (bin_box(s, ci, box[0], box[1], box[2], box[3], edges)) {
      s->ncmds++;
      return true;
   }
   unbin(s, ci);
   scene_rollback(s, mark, true);
   return false;
}

/* Appends a primitive of n vertices whose pixels lie in `known_box`
 * inside `edges` (NULL: no edges) or, when it is NULL, in their vertex_box
 * widened by `pad`. */
static bool add_prim(struct r_scene *s, const struct r_state *rs, enum r_cmd_kind kind,
                     const struct r_vertex *const *v, int n, float pad, const int *known_box,
                     const struct r_tri_edges *edges)
{
   if (!begin(s, rs))
      return false;
   int box[4];
   if (known_box)
      memcpy(box, known_box, sizeof(box));
   else if (!vertex_box(rs, v, n, pad, box))
      return true;   /* no pixel of the region: nothing to draw */
   const struct scene_mark mark = scene_mark(s);
   const uint32_t ci = new_cmd(s, rs, kind);
   if (ci == UINT32_MAX)
      goto fail;
   const int slots = vertex_slots(rs);
   for (int i = 0; i < n; i++) {
      s->cmds[ci].v[i] = copy_vertex(s, v[i], slots);
      if (!s->cmds[ci].v[i])
         goto fail;
   }
   return bin_cmd(s, ci, box, edges, &mark);
fail:
   /* as it was: the vertices and a state this command added dropped */
   scene_rollback(s, &mark, true);
   return false;
}

/* Appends a command of `kind` set up when binned, its setup (an
 * r_tri_binned, r_line_binned or r_point_binned) allocated since `mark`,
 * into the tiles of `box` that `edges` (or NULL) does not exclude; `lin`
 * its enum r_lin, with lv (or NULL) its vertices on the linear way. */
static bool add_set_up(struct r_scene *s, const struct r_state *rs, enum r_cmd_kind kind,
                       const struct scene_mark *mark, const void *setup, const int box[4],
                       const struct r_tri_edges *edges, uint8_t lin,
                       const struct r_vertex *const *lv)
{
   const uint32_t ci = new_cmd(s, rs, kind);
   if (ci == UINT32_MAX)
      goto fail;
   if (kind == R_CMD_TRIANGLE)
      s->cmds[ci].tri = setup;
   else if (kind == R_CMD_LINE)
      s->cmds[ci].line = setup;
   else
      s->cmds[ci].point = setup;
   s->cmds[ci].lin = lin;
   if (lv) {
      const int slots = vertex_slots(rs);
      for (int i = 0; i < (kind == R_CMD_POINT ? 1 : 3); i++) {
         s->cmds[ci].v[i] = copy_vertex(s, lv[i], slots);
         if (!s->cmds[ci].v[i])
            goto fail;
      }
      s->lin = true;
   }
   return bin_cmd(s, ci, box, edges, mark);
fail:
   /* as it was: the setup and a state this command added dropped */
   scene_rollback(s, mark, true);
   return false;
}

bool r_scene_triangle(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v0,
                      const struct r_vertex *v1, const struct r_vertex *v2)
{
   static const struct r_lin_tri no = { R_LIN_NO, R_LIN_NO, false, NULL, NULL, NULL };
   return r_scene_triangle_lin(s, rs, v0, v1, v2, &no);
}

/* A triangle of R_LIN_NO (command ci) whose whole tiles take command wi
 * (made since `mark`): bin_cmd with the tiles it covers whole apart,
 * their bins first emptied when `opaque` (ORACLE-NOTES.md "GLX linear
 * bins" (3), (4)). */
static bool bin_whole(struct r_scene *s, const struct r_state *rs, uint32_t ci, uint32_t wi,
                      const int box[4], const struct r_tri_edges *edges, bool opaque,
                      const struct scene_mark *mark)
{
   int r[4];
   draw_region(rs, r);
   const int tx0 = box[0] >> R_TILE_LOG2, tx1 = (box[2] - 1) >> R_TILE_LOG2;
   const int ty0 = box[1] >> R_TILE_LOG2, ty1 = (box[3] - 1) >> R_TILE_LOG2;
   for (int ty = ty0; ty <= ty1; ty++) {
      for (int tx = tx0; tx <= tx1; tx++) {
         const int x = tx << R_TILE_LOG2, y = ty << R_TILE_LOG2;
         if (r_tri_edges_miss_tile(edges, x, y))
            continue;
         /* whole: no edge cuts it, nor a plane of the draw region's right
          * or bottom side, which llvmpipe adds when the triangle's box
          * leaves the region there and which cuts the tile holding the
          * region's last column or row (lp_setup_tri.c, scissor planes;
          * rasterize_ccw's planes) */
         const bool whole =
            x >= r[0] && y >= r[1] && x + R_TILE_SIZE <= r[2] && y + R_TILE_SIZE <= r[3] &&
            (edges->bx1 <= r[2] - 1 || r[2] > x + R_TILE_SIZE) &&
            (edges->by1 <= r[3] - 1 || r[3] > y + R_TILE_SIZE) &&
            r_tri_edges_cover_tile(edges, x, y);
         struct r_bin *b = &s->bins[ty * s->tiles_x + tx];
         if (whole && opaque)
            b->count = 0;
         if (!grow((void **)&b->cmd, &b->capacity, b->count + 1, sizeof(*b->cmd))) {
            unbin(s, ci);
            unbin(s, wi);
            scene_rollback(s, mark, true);
            return false;
         }
         b->cmd[b->count++] = whole ? wi : ci;
         s->bytes += sizeof(*b->cmd);
      }
   }
   s->ncmds += 2;
   return true;
}

bool r_scene_triangle_lin(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v0,
                          const struct r_vertex *v1, const struct r_vertex *v2,
                          const struct r_lin_tri *lt)
{
   const uint8_t lin = lt->lin;
   const struct r_vertex *const *lv = lt->lv;
   /* binned into the tiles of the box r_triangle draws in, or not at all
    * when it draws nothing (culled, empty); an exact triangle (kind 1) is
    * set up now, once, instead of in each tile it is drawn in */
   if (s->fb != rs->fb && !begin(s, rs))
      return false;
   const struct scene_mark mark = scene_mark(s);
   struct r_tri_binned *bin = scene_alloc(s, r_tri_binned_size(rs));
   if (!bin)
      return false;
   int box[4];
   struct r_tri_edges edges;
   const int known = r_triangle_box_setup(rs, v0, v1, v2, box, &edges, bin);
   if (known != 1) {
      scene_rollback(s, &mark, false);
      if (known == 0)
         return true;
      const struct r_vertex *v[3] = { v0, v1, v2 };
      const uint32_t n = s->ncmds;
      if (!add_prim(s, rs, R_CMD_TRIANGLE, v, 3, 0.0f, NULL, NULL))
         return false;
      /* (not exact: drawn from its vertices on both ways) */
      if (s->ncmds > n && lin != R_LIN_NO)
         s->cmds[n].lin = R_LIN_SAME;
      return true;
   }
   if (lt->rect)
      r_tri_binned_pack(lt->rect, bin);   /* the rectangle's planes */
   const bool multi = (box[0] ^ (box[2] - 1)) >> R_TILE_LOG2 != 0 ||
                      (box[1] ^ (box[3] - 1)) >> R_TILE_LOG2 != 0;
   if (lin == R_LIN_NO && multi && (lt->whole != R_LIN_NO || lt->opaque)) {
      /* two commands of one setup: the triangle, and in the tiles it
       * covers whole, its tile shading */
      const uint32_t ci = new_cmd_at(s, rs, R_CMD_TRIANGLE, s->ncmds);
      const uint32_t wi =
         ci == UINT32_MAX ? UINT32_MAX : new_cmd_at(s, rs, R_CMD_TRIANGLE, s->ncmds + 1);
      if (wi == UINT32_MAX) {
         scene_rollback(s, &mark, true);
         return false;
      }
      s->cmds[ci].tri = bin;
      s->cmds[wi].tri = bin;
      s->cmds[wi].lin = lt->whole;
      if (lt->whole == R_LIN_INTERP) {
         /* the triangle's own planes over each whole tile */
         struct r_lin_interp *li = scene_alloc(s, sizeof(*li));
         if (!li) {
            scene_rollback(s, &mark, true);
            return false;
         }
         struct r_tri_setup ts;
         r_tri_binned_unpack(bin, &ts);
         if (ts.flat_attr[R_FS_COLOR0]) {
            /* a constant input: its value, not divided by w */
            for (int c = 0; c < 4; c++)
               li->c[c] = (struct r_attr_plane){ ts.flat[R_FS_COLOR0][c], 0.0f, 0.0f };
            li->w_a0 = 1.0f;
         } else {
            memcpy(li->c, ts.ap[R_FS_COLOR0], sizeof(li->c));
            li->w_a0 = ts.w.a0;
         }
         li->box[0] = li->box[1] = INT32_MIN;
         li->box[2] = li->box[3] = INT32_MAX;
         li->id = 0;   /* (each whole tile is its own) */
         s->cmds[wi].li = li;
         s->lin = true;
      }
      if (lt->whole == R_LIN_COLOR) {
         const int slots = vertex_slots(rs);
         for (int i = 0; i < 3; i++) {
            s->cmds[wi].v[i] = copy_vertex(s, lv[i], slots);
            if (!s->cmds[wi].v[i]) {
               scene_rollback(s, &mark, true);
               return false;
            }
         }
         s->lin = true;
      }
      return bin_whole(s, rs, ci, wi, box, &edges, lt->opaque, &mark);
   }
   if (lin == R_LIN_INTERP) {
      struct r_lin_interp *li = scene_alloc(s, sizeof(*li));
      if (!li) {
         scene_rollback(s, &mark, false);
         return false;
      }
      *li = *lt->li;
      const uint32_t n = s->ncmds;
      if (!add_set_up(s, rs, R_CMD_TRIANGLE, &mark, bin, box, &edges, lin, NULL))
         return false;
      s->cmds[n].li = li;
      s->lin = true;
      return true;
   }
   return add_set_up(s, rs, R_CMD_TRIANGLE, &mark, bin, box, &edges, lin,
                     lin == R_LIN_COLOR ? lv : NULL);
}

bool r_scene_line(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v0,
                  const struct r_vertex *v1)
{
   /* A line covers at most half its width (at most 255/2) beside its
    * ends and the segment between them, plus its diamond-exit pixels.  A
    * line whose box reaches one or two tiles is binned with its vertices
    * and set up in each (a short line's vertices cost less to hand to
    * another thread than its setup: stipple's dashes); a longer one is
    * set up now, once, as a triangle, and binned into the tiles its long
    * sides reach, unless it is not exact (kind 2). */
   if (!begin(s, rs))
      return false;
   const struct r_vertex *v[2] = { v0, v1 };
   int box[4];
   if (!vertex_box(rs, v, 2, 0.5f * rs->rast->line_width + 1.0f, box))
      return true;   /* no pixel of the region: nothing to draw */
   const int tiles = (((box[2] - 1) >> R_TILE_LOG2) - (box[0] >> R_TILE_LOG2) + 1) *
                     (((box[3] - 1) >> R_TILE_LOG2) - (box[1] >> R_TILE_LOG2) + 1);
   if (tiles > 2 || s->exact) {
      const struct scene_mark mark = scene_mark(s);
      struct r_line_binned *bin = scene_alloc(s, r_line_binned_size(rs));
      if (!bin)
         return false;
      int sbox[4];
      struct r_tri_edges edges;
      const int known = r_line_box_setup(rs, v0, v1, sbox, &edges, bin);
      if (known == 1)
         return add_set_up(s, rs, R_CMD_LINE, &mark, bin, sbox, &edges, R_LIN_NO, NULL);
      scene_rollback(s, &mark, false);
      if (known == 0)
         return true;
   }
   return add_prim(s, rs, R_CMD_LINE, v, 2, 0.0f, box, NULL);
}

bool r_scene_point(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v)
{
   return r_scene_point_lin(s, rs, v, R_LIN_NO, NULL);
}

bool r_scene_point_lin(struct r_scene *s, const struct r_state *rs, const struct r_vertex *v,
                       uint8_t lin, const struct r_vertex *lv)
{
   /* a legacy point set up now, binned into the tiles of its square */
   if (!begin(s, rs))
      return false;
   const struct scene_mark mark = scene_mark(s);
   struct r_point_binned *bin = scene_alloc(s, r_point_binned_size(rs));
   if (!bin)
      return false;
   int box[4];
   const int known = r_point_box_setup(rs, v, box, bin);
   if (known == 1)
      return add_set_up(s, rs, R_CMD_POINT, &mark, bin, box, NULL, lin,
                        lin == R_LIN_COLOR ? &lv : NULL);
   scene_rollback(s, &mark, false);
   if (known == 0)
      return true;
   /* a sprite: a square of at most the size rounded up, around the
    * snapped centre */
   const struct r_vertex *vv[1] = { v };
   float size = r_point_size(rs->rast, v->attr[R_ATTR_PSIZE]);
   if (!(size <= 255.0f))
      size = 255.0f;   /* LP_MAX_POINT_WIDTH (and a NaN: one pixel) */
   return add_prim(s, rs, R_CMD_POINT, vv, 1, 0.5f * size + 1.0f, NULL, NULL);
}

bool r_scene_clear(struct r_scene *s, const struct r_state *rs, bool color,
                   const uint8_t rgba[4], bool depth, uint32_t zvalue, bool stencil,
                   uint8_t svalue)
{
   if (!begin(s, rs))
      return false;
   const uint32_t mark_states = s->nstates;
   const uint32_t ci = new_cmd(s, rs, R_CMD_CLEAR);
   if (ci == UINT32_MAX)
      goto fail;
   struct r_cmd *c = &s->cmds[ci];
   c->clear_color = color;
   if (color)
      memcpy(c->rgba, rgba, 4);
   c->clear_depth = depth;
   c->zvalue = zvalue;
   c->clear_stencil = stencil;
   c->svalue = svalue;
   c->lin = R_LIN_SAME;   /* a clear command of a linear bin */
   if (!bin_box(s, ci, 0, 0, rs->fb->width, rs->fb->height, NULL)) {
      unbin(s, ci);
      goto fail;
   }
   s->ncmds++;
   return true;
fail:
   if (s->nstates > mark_states) {
      s->nstates--;
      r_state_release(&s->states[s->nstates]);
   }
   return false;
}

bool r_scene_quad(struct r_scene *s, const struct r_state *rs, float z, const float color[4],
                  uint8_t lin, const float lcolor[4])
{
   int box[4];
   draw_region(rs, box);
   if (box[0] >= box[2] || box[1] >= box[3])
      return true;   /* no pixel */
   if (!begin(s, rs))
      return false;
   const struct scene_mark mark = scene_mark(s);
   struct r_quad_binned *q = scene_alloc(s, sizeof(*q));
   if (!q)
      return false;
   q->z = z;
   memcpy(q->color, color, sizeof(q->color));
   memcpy(q->lcolor, lin == R_LIN_COLOR ? lcolor : color, sizeof(q->lcolor));
   const uint32_t ci = new_cmd(s, rs, R_CMD_QUAD);
   if (ci == UINT32_MAX) {
      scene_rollback(s, &mark, true);
      return false;
   }
   s->cmds[ci].quad = q;
   s->cmds[ci].lin = lin;
   s->lin |= lin == R_LIN_COLOR;
   return bin_cmd(s, ci, box, NULL, &mark);
}

void r_scene_cover(struct r_scene *s, const struct r_state *rs, const int box[4])
{
   if (s->fb != rs->fb || r_scene_empty(s))
      return;
   int r[4];
   draw_region(rs, r);
   const int x0 = box[0] > r[0] ? box[0] : r[0], y0 = box[1] > r[1] ? box[1] : r[1];
   const int x1 = box[2] < r[2] ? box[2] : r[2], y1 = box[3] < r[3] ? box[3] : r[3];
   /* the tiles wholly inside [x0, x1) x [y0, y1): the box cut to the
    * region covers all 64 x 64 pixels (ORACLE-NOTES.md "GLX linear bins"
    * (3)) */
   for (int ty = (y0 + R_TILE_SIZE - 1) >> R_TILE_LOG2;
        ty < s->tiles_y && ((ty + 1) << R_TILE_LOG2) <= y1; ty++)
      for (int tx = (x0 + R_TILE_SIZE - 1) >> R_TILE_LOG2;
           tx < s->tiles_x && ((tx + 1) << R_TILE_LOG2) <= x1; tx++)
         s->bins[ty * s->tiles_x + tx].count = 0;
}

/* lp_linear_init_interp's signed 1.15 fixed point */
static inline int16_t sfixed_1_15(float f)
{
   const int i = (int)(f * 32767.0f);
   return (int16_t)(i < -32767 ? -32767 : i > 32767 ? 32767 : i);
}

bool r_lin_interp_fill(const struct r_state *rs, const struct r_lin_interp *li, int x0, int y0,
                       int x1, int y1)
{
   const int w = x1 - x0, h = y1 - y0;
   if (w <= 0 || h <= 0)
      return true;
   /* ORACLE-NOTES.md "GLX linear bins" (5): oow = 1 / a0 of w; the
    * colour (perspective) divided back when it is not 1 */
   const float oow = 1.0f / li->w_a0;
   int16_t s0[4], dx[4], dy[4];
   for (int j = 0; j < 4; j++) {
      float a0 = li->c[j].a0, dsdx = li->c[j].dadx, dsdy = li->c[j].dady;
      if (oow != 1.0f) {
         a0 = a0 * oow;
         dsdx = dsdx * oow;
         dsdy = dsdy * oow;
      }
      const float sx = (float)x0 * dsdx, sy = (float)y0 * dsdy;
      const float v0 = a0 + (sx + sy);
      /* the values at the part's corners in [0, 1], else the path fails */
      const float vb = v0 + (float)(w - 1) * dsdx;
      const float vc = v0 + (float)(h - 1) * dsdy;
      const float vd = v0 + (float)(h - 1) * dsdy + (float)(w - 1) * dsdx;
      if (!(v0 >= 0.0f && vb >= 0.0f && vc >= 0.0f && vd >= 0.0f) ||
          !(v0 <= 1.0f && vb <= 1.0f && vc <= 1.0f && vd <= 1.0f))
         return false;
      dx[j] = sfixed_1_15(dsdx);
      dy[j] = sfixed_1_15(dsdy);
      s0[j] = r_lin_ufixed_1_15(v0);
   }
   /* each pixel: the 16-bit sums (wrapping), >> 7, saturated to a byte;
    * stored straight into the RGBA8 buffer when the fragment operations
    * would store it unchanged (no blending, logic op, alpha test, query;
    * every channel written), else through them */
   const struct r_blend_state *bl = rs->blend;
   if (!rs->fb->wide && rs->fb->color && !bl->enable && !bl->logic_op &&
       bl->color_mask == 0xfu && !bl->dst_alpha_one && !rs->dsa->alpha_test &&
       !rs->dsa->depth_test && !rs->dsa->stencil_test && !rs->samples) {
      for (int y = y0; y < y1; y++) {
         uint8_t *row = rs->fb->color + ((size_t)y * (size_t)rs->fb->width + (size_t)x0) * 4;
         for (int j = 0; j < 4; j++) {
            uint16_t v = (uint16_t)((unsigned)(uint16_t)s0[j] +
                                    (unsigned)(y - y0) * (uint16_t)dy[j]);
            for (int i = 0; i < w; i++, v = (uint16_t)(v + (uint16_t)dx[j])) {
               const int b = (int16_t)v >> 7;
               row[4 * i + j] = (uint8_t)(b < 0 ? 0 : b > 255 ? 255 : b);
            }
         }
      }
      return true;
   }
   for (int y = y0; y < y1; y++) {
      for (int x = x0; x < x1; x++) {
         float color[4];
         for (int j = 0; j < 4; j++) {
            const int16_t v = (int16_t)(uint16_t)((unsigned)(uint16_t)s0[j] +
                                                  (unsigned)(y - y0) * (uint16_t)dy[j] +
                                                  (unsigned)(x - x0) * (uint16_t)dx[j]);
            int b = v >> 7;
            b = b < 0 ? 0 : b > 255 ? 255 : b;
            color[j] = (float)b / 255.0f;
         }
         r_fragment_ops(rs, x, y, 0.0f, color);
      }
   }
   return true;
}

/* buckets of r_scene_tile_order: tiles with this many commands or more
 * share the last */
#define ORDER_BUCKETS 64u

void r_scene_tile_order(const struct r_scene *s, unsigned lanes, uint32_t *order,
                        unsigned *lane_end)
{
   /* a counting sort by lane, then by the number of commands, most
    * first, then by index */
   enum { KEYS = R_SCENE_MAX_LANES * ORDER_BUCKETS };
   unsigned start[KEYS + 1] = { 0 };
   for (int ty = 0; ty < s->tiles_y; ty++) {
      for (int tx = 0; tx < s->tiles_x; tx++) {
         const uint32_t c = s->bins[ty * s->tiles_x + tx].count;
         const unsigned key = (unsigned)ty % lanes * ORDER_BUCKETS + ORDER_BUCKETS - 1 -
                              (c < ORDER_BUCKETS - 1 ? c : ORDER_BUCKETS - 1);
         start[key + 1]++;
      }
   }
   for (unsigned k = 1; k <= KEYS; k++)
      start[k] += start[k - 1];
   for (unsigned l = 0; l < lanes; l++)
      lane_end[l] = start[(l + 1) * ORDER_BUCKETS];
   for (int ty = 0; ty < s->tiles_y; ty++) {
      for (int tx = 0; tx < s->tiles_x; tx++) {
         const uint32_t t = (uint32_t)(ty * s->tiles_x + tx);
         const uint32_t c = s->bins[t].count;
         const unsigned key = (unsigned)ty % lanes * ORDER_BUCKETS + ORDER_BUCKETS - 1 -
                              (c < ORDER_BUCKETS - 1 ? c : ORDER_BUCKETS - 1);
         order[start[key]++] = t;
      }
   }
}

/* how far r_scene_run_tile fetches ahead, in commands of the tile */
#define RUN_AHEAD_CMD 8u
#define RUN_AHEAD_SETUP 4u

void r_scene_run_tile(const struct r_scene *s, unsigned tile, struct r_stats *stats,
                      unsigned slot)
{
   const struct r_bin *b = &s->bins[tile];
   const int tx0 = (int)(tile % (unsigned)s->tiles_x) << R_TILE_LOG2;
   const int ty0 = (int)(tile / (unsigned)s->tiles_x) << R_TILE_LOG2;
   const int tx1 = tx0 + R_TILE_SIZE, ty1 = ty0 + R_TILE_SIZE;
   uint32_t cur = UINT32_MAX;
   struct r_state rs;
   const uint32_t n = b->count;
   /* llvmpipe's linear path (enum r_lin; ORACLE-NOTES.md "GLX linear
    * bins" (5)): the tile's commands all rectangles, points, tile
    * commands or clears; decided once per tile */
   bool linear = false;
   if (s->lin) {
      linear = true;
      for (uint32_t i = 0; i < n && linear; i++)
         linear = s->cmds[b->cmd[i]].lin != R_LIN_NO;
   }
   uint32_t last_interp = 0;   /* the rectangle filled last (r_lin_interp.id) */
   for (uint32_t i = 0; i < n; i++) {
      /* A command is three dependent loads away (the bin's index, the
       * 56-byte command, its setup), each a miss when the other core
       * binned it; small points and lines spend less time drawing than
       * waiting for them: fetch the commands RUN_AHEAD_CMD ahead and the
       * setups (or first vertex) of those RUN_AHEAD_SETUP ahead, whose
       * commands are by then in the cache.  (A prefetch never faults: a
       * clear's NULL is harmless.) */
      if (i + RUN_AHEAD_CMD < n) {
         const char *pc = (const char *)&s->cmds[b->cmd[i + RUN_AHEAD_CMD]];
         __builtin_prefetch(pc);
         __builtin_prefetch(pc + sizeof(struct r_cmd) - 1);
      }
      if (i + RUN_AHEAD_SETUP < n) {
         const struct r_cmd *pc = &s->cmds[b->cmd[i + RUN_AHEAD_SETUP]];
         __builtin_prefetch(pc->tri ? (const void *)pc->tri : (const void *)pc->v[0]);
      }
      const struct r_cmd *c = &s->cmds[b->cmd[i]];
      if (c->kind == R_CMD_CLEAR) {
         const struct r_fb_state *fb = s->states[c->state].fb;
         const int x1 = tx1 < fb->width ? tx1 : fb->width;
         const int y1 = ty1 < fb->height ? ty1 : fb->height;
         if (c->clear_color)
            r_clear_color_rect(fb, tx0, ty0, x1, y1, c->rgba);
         if (c->clear_depth || c->clear_stencil)
            r_clear_depth_stencil_rect(fb, tx0, ty0, x1, y1, c->clear_depth, c->zvalue,
                                       c->clear_stencil, c->svalue);
         continue;
      }
      if (c->state != cur) {
         /* the state with its draw region cut to the tile */
         cur = c->state;
         rs = s->states[cur];
         if (rs.x0 < tx0) rs.x0 = tx0;
         if (rs.y0 < ty0) rs.y0 = ty0;
         if (rs.x1 > tx1) rs.x1 = tx1;
         if (rs.y1 > ty1) rs.y1 = ty1;
         if (rs.px0 < tx0) rs.px0 = tx0;
         if (rs.py0 < ty0) rs.py0 = ty0;
         if (rs.px1 > tx1) rs.px1 = tx1;
         if (rs.py1 > ty1) rs.py1 = ty1;
         if (rs.stats)
            rs.stats = stats;
         if (rs.samples)
            rs.samples += slot;
      }
      switch (c->kind) {
      case R_CMD_TRIANGLE:
         if (linear && c->lin == R_LIN_INTERP) {
            const struct r_lin_interp *li = c->li;
            if (li->id && li->id == last_interp)
               break;   /* the rectangle's other triangle: filled */
            const int x0 = li->box[0] > rs.x0 ? li->box[0] : rs.x0;
            const int y0 = li->box[1] > rs.y0 ? li->box[1] : rs.y0;
            const int x1 = li->box[2] < rs.x1 ? li->box[2] : rs.x1;
            const int y1 = li->box[3] < rs.y1 ? li->box[3] : rs.y1;
            if (r_lin_interp_fill(&rs, li, x0, y0, x1, y1)) {
               last_interp = li->id;
               break;
            }
            last_interp = 0;   /* refused: each triangle the ordinary way */
         }
         if (linear && c->lin == R_LIN_COLOR)
            r_triangle(&rs, c->v[0], c->v[1], c->v[2]);
         else if (c->tri)
            r_triangle_binned(&rs, c->tri);
         else
            r_triangle(&rs, c->v[0], c->v[1], c->v[2]);
         break;
      case R_CMD_LINE:
         if (c->line)
            r_line_binned(&rs, c->line);
         else
            r_line(&rs, c->v[0], c->v[1]);
         break;
      case R_CMD_QUAD:
         r_clear_quad(&rs, c->quad->z, linear ? c->quad->lcolor : c->quad->color);
         break;
      case R_CMD_POINT:
      default:
         if (linear && c->lin == R_LIN_COLOR)
            r_point(&rs, c->v[0]);
         else if (c->point)
            r_point_binned(&rs, c->point);
         else
            r_point(&rs, c->v[0]);
         break;
      }
   }
}

void r_scene_reset(struct r_scene *s)
{
   for (uint32_t i = 0; i < s->nstates; i++)
      r_state_release(&s->states[i]);
   s->nstates = 0;
   s->ncmds = 0;
   for (unsigned t = 0; t < s->bins_capacity; t++)
      s->bins[t].count = 0;
   s->fb = NULL;
   s->chunk = NULL;
   s->chunk_used = 0;
   s->stats = false;
   s->lin = false;
   s->exact = false;
   /* what stays allocated counts toward the bound again as it is used */
   s->bytes = 0;
}

void r_scene_fini(struct r_scene *s)
{
   r_scene_reset(s);
   for (unsigned t = 0; t < s->bins_capacity; t++)
      fgl_free(s->bins[t].cmd);
   fgl_free(s->bins);
   fgl_free(s->cmds);
   fgl_free(s->states);
   for (struct r_scene_chunk *c = s->chunks, *n; c; c = n) {
      n = c->next;
      fgl_free(c);
   }
   memset(s, 0, sizeof(*s));
}
