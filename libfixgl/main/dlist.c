/*
 * Display lists, after Mesa 22.3 [S: main/dlist.c, vbo/vbo_save_api.c,
 * vbo/vbo_save_draw.c, vbo/vbo_save_loopback.c].
 *
 * A list is an array of nodes: a header (opcode, size) and its arguments.
 * The plain commands come from one table (main/dlist_ops.h), which
 * generates their opcodes, save functions and replay cases here.  The
 * hand-written parts are the ones Mesa writes by hand:
 *
 *  - The vertex-list compiler (vbo_save_api.c).  glBegin/glEnd vertices
 *    are stored in a vertex format of their own, and consecutive
 *    primitives accumulate until a compiled state change, an attribute
 *    call outside glBegin/glEnd or glEndList flushes them into one
 *    "vertex list" node ([S: vbo/vbo_save_api.c:compile_vertex_list]):
 *    independent primitives of one mode merge, the last line loop becomes a strip, and the
 *    primitives become indexed draws (consecutive ones of one mode merged
 *    into one, strips joined by degenerate triangles, line strips next to
 *    lines turned into lines, short primitives padded by repeating their
 *    last vertex).  Replaying the node is one indexed llvmpipe draw per
 *    mode run, so quads take the 1-3 diagonal, and the list's last
 *    vertex's attributes become current (playback_copy_to_current).
 *  - GL_COMPILE_AND_EXECUTE executes a vertex list when it is compiled,
 *    by "loopback" through the immediate-mode calls, and lists whose
 *    vertex data depends on state outside them (a glBegin/glEnd open at
 *    glEndList or around a glCallList) are replayed that way too.
 *  - Attribute calls outside glBegin/glEnd are nodes of their own (and
 *    flush the vertex list); glShadeModel and glMaterial skip repeated
 *    values and execute before flushing; glCallList(s) nest up to
 *    MAX_LIST_NESTING (64) calls deep.
 *  - Errors the save functions find are compiled as ERROR nodes, raised
 *    when the list executes (and at once under GL_COMPILE_AND_EXECUTE);
 *    everything else is validated by the command when it executes.
 */
/* the replay calls GL 1.4 and 1.5 entry points (glBeginQuery, glEndQuery)
 * declared by <GL/glext.h> only with GL_GLEXT_PROTOTYPES */
#define GL_GLEXT_PROTOTYPES 1
#include "main/dlist.h"

#include <assert.h>
#include <limits.h>
#include <pthread.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <fixgl/fixgl.h>

#include "main/conv.h"
#include "main/groups.h"
#include "main/pixelformat.h"
#include "tnl/t_pipeline.h"
#include "fgl_alloc.h"

/* ------------------------------------------------------------------ */
/* Nodes and opcodes                                                   */
/* ------------------------------------------------------------------ */

union dl_node {
   struct {
      uint16_t op, size;    /* size: nodes, header included */
   } h;
   GLenum e;
   GLint i;
   GLsizei sz;
   GLuint u;
   GLfloat f;
   GLboolean b;
   GLbitfield bf;
   GLushort us;
};
_Static_assert(sizeof(union dl_node) == 4, "nodes are 4 bytes, as Mesa's");

enum dl_opcode {
#define DL_OP0(Name) DL_OP_##Name,
#define DL_OP1(Name, A) DL_OP_##Name,
#define DL_OP2(Name, A, B) DL_OP_##Name,
#define DL_OP3(Name, A, B, C) DL_OP_##Name,
#define DL_OP4(Name, A, B, C, D_) DL_OP_##Name,
#define DL_OP5(Name, A, B, C, D_, E_) DL_OP_##Name,
#define DL_OP6(Name, A, B, C, D_, E_, F_) DL_OP_##Name,
#define DL_OPV0(Name, VT, N) DL_OP_##Name,
#define DL_OPV1(Name, A, VT, N) DL_OP_##Name,
#define DL_OPV2(Name, A, B, VT, N) DL_OP_##Name,
#define DL_CUSTOM0 DL_OP0
#define DL_CUSTOM1 DL_OP1
#define DL_CUSTOMV2 DL_OPV2
#include "main/dlist_ops.h"
#include "main/dlist_ops_undef.h"
   DL_OP_ATTR,             /* OPCODE_ATTR_{1,2,3,4}F_NV: attr, size, 4 values */
   DL_OP_MAP1,             /* target, u1, u2, stride, order, count, points */
   DL_OP_MAP2,             /* target, u1, u2, v1, v2, ustride, vstride,
                            * uorder, vorder, count, points */
   DL_OP_EVAL_C1,          /* u */
   DL_OP_EVAL_C2,          /* u, v */
   DL_OP_EVAL_P1,          /* i */
   DL_OP_EVAL_P2,          /* i, j */
   DL_OP_CALL_LIST,        /* list */
   DL_OP_CALL_LISTS,       /* n, type, pointer to a copy of the names */
   DL_OP_BITMAP,           /* width, height, xorig, yorig, xmove, ymove,
                            * pointer to the bitmap texture */
   DL_OP_DRAW_PIXELS,      /* width, height, format, type, pointer to the
                            * image copy */
   DL_OP_ERROR,            /* a compiled error */
   DL_OP_TEX_IMAGE,        /* dims, target, level, internal, width, height,
                            * border, format, type, pointer to the image */
   DL_OP_TEX_SUB_IMAGE,    /* dims, target, level, xoffset, yoffset, width,
                            * height, format, type, pointer to the image */
   DL_OP_COPY_TEX_IMAGE,   /* dims, target, level, internal, x, y, width,
                            * height, border */
   DL_OP_COPY_TEX_SUB_IMAGE, /* dims, target, level, xoffset, yoffset, x, y,
                              * width, height */
   DL_OP_TEX_IMAGE_3D,     /* target, level, internal, width, height, depth,
                            * border, format, type, pointer to the image */
   DL_OP_TEX_SUB_IMAGE_3D, /* target, level, xoffset, yoffset, zoffset, width,
                            * height, depth, format, type, pointer to the
                            * image */
   DL_OP_COPY_TEX_SUB_IMAGE_3D, /* target, level, xoffset, yoffset, zoffset,
                                 * x, y, width, height */
   DL_OP_COMPRESSED_TEX,   /* dims | sub << 4, target, level, format, x, y, z,
                            * width, height, depth, border, imageSize,
                            * pointer to the copy of the data */
   DL_OP_VERTEX_LIST,      /* pointer to a struct vertex_list */
   DL_OP_END_OF_LIST,
};

#define PTR_NODES (sizeof(void *) / sizeof(union dl_node))

static void put_pointer(union dl_node *n, const void *p)
{
   memcpy(n, &p, sizeof(p));
}

static void *get_pointer(const union dl_node *n)
{
   void *p;
   memcpy(&p, n, sizeof(p));
   return p;
}

/* ------------------------------------------------------------------ */
/* Lists and the name table                                            */
/* ------------------------------------------------------------------ */

struct display_list {
   GLuint name;
   union dl_node *nodes;
   unsigned count, cap;
   unsigned walk;           /* replace_op_vertex_list_recursively's mark */
};

/* Mesa's current vertex primitive while compiling
 * (ctx->Driver.CurrentSavePrimitive): a GL mode inside glBegin/glEnd (GL
 * 1.5's ten: every compiled glBegin and draw refuses a mode above
 * GL_POLYGON before it gets here, so the adjacency modes and GL_PATCHES
 * of the oracle's vbo_save are not handled). */
#define PRIM_MAX              GL_POLYGON
#define PRIM_OUTSIDE_BEGIN_END (PRIM_MAX + 1)
#define PRIM_UNKNOWN          (PRIM_MAX + 2)

/* VBO_SAVE_BUFFER_SIZE: the compiler's vertex store wraps into a new
 * vertex list when it would grow beyond this */
#define SAVE_BUFFER_SIZE (1024 * 1024)

struct save_prim {
   GLenum mode;
   bool begin, end;
   unsigned start, count;
};

/* A vertex list node (vbo_save_vertex_list). */
enum vertex_list_kind {
   VL_DRAW,            /* OPCODE_VERTEX_LIST */
   VL_COPY_CURRENT,    /* OPCODE_VERTEX_LIST_COPY_CURRENT */
   VL_LOOPBACK,        /* OPCODE_VERTEX_LIST_LOOPBACK */
};

struct vertex_list {
   enum vertex_list_kind kind;
   unsigned attrsz[FGL_ATTR_COUNT];
   unsigned vertex_size;
   /* the vertices as compiled, for loopback */
   float *buffer;
   unsigned vertex_count;
   struct save_prim *prims;   /* after merge_prims */
   unsigned prim_count;
   unsigned wrap_count;       /* copied vertices at the start */
   float *current_data;       /* the last vertex's attributes but the
                               * position, or NULL */
   bool draw_begins;
   /* where the vertices were uploaded: loopback after compilation reads
    * vertex (start + start_offset + j) at bo + vao_offset */
   struct bo_image *bo;
   unsigned vao_offset, start_offset;
   /* the indexed draws, indices resolved to vertices */
   struct fgl_vbo_vertex *verts;
   unsigned nverts;
   struct fgl_vbo_prim *draws;
   unsigned ndraws;
};

/* The buffer object the compiler uploads each vertex list to, vertices
 * then indices, shared by the lists compiled after it until it is full
 * [S: vbo_save_api.c:compile_vertex_list, save->current_bo].  The draws
 * need none of it (they have their vertices), but a list replayed by
 * loopback after compilation reads its vertices back from here, at the
 * offsets Mesa computed for the indexed draw: where those are not the
 * compiled vertices (vertices merged as duplicates, a wrapped line loop's
 * closing vertex past the uploaded ones), Mesa reads other data, and so
 * does this. */
struct bo_image {
   unsigned refs;
   unsigned size;
   uint8_t *data;             /* zeroed when created, as llvmpipe's */
};

#define SAVE_BO_MIN_SIZE (1024 * 1024)   /* VBO_SAVE_BUFFER_SIZE */

static struct bo_image *bo_ref(struct bo_image *bo)
{
   if (bo)
      bo->refs++;
   return bo;
}

static void bo_unref(struct bo_image *bo)
{
   if (bo && --bo->refs == 0) {
      fgl_free(bo->data);
      fgl_free(bo);
   }
}

static void bo_write(struct bo_image *bo, unsigned offset, const void *src, size_t bytes)
{
   if (!bo || offset >= bo->size || bytes == 0)
      return;
   if (bytes > bo->size - offset)
      bytes = bo->size - offset;
   memcpy(bo->data + offset, src, bytes);
}

/* vbo_save_context: the vertex list being compiled */
struct save_context {
   float *buffer;             /* vertex_store->buffer_in_ram */
   unsigned used;             /* floats */
   unsigned buffer_size;      /* bytes: buffer_in_ram_size, kept from
                               * list to list as Mesa keeps its store */
   unsigned alloc;            /* floats actually allocated */
   struct save_prim *prims;
   unsigned prim_used, prim_size;
   unsigned attrsz[FGL_ATTR_COUNT];
   unsigned active_sz[FGL_ATTR_COUNT];
   unsigned vertex_size;
   unsigned attroff[FGL_ATTR_COUNT];
   float vertex[FGL_ATTR_COUNT * 4];
   float *copied;             /* copied.buffer */
   unsigned copied_nr;
   bool dangling_attr_ref;
   bool no_current_update;
   struct bo_image *bo;       /* current_bo */
   unsigned bo_used;          /* current_bo_bytes_used */
   unsigned vao_offset;       /* offset of save->VAO[0] (old_offset) */
};

/* The lists of the contexts that share them (OSMesaCreateContext's
 * sharelist; Mesa's ctx->Shared->DisplayList): name -> list, sorted by
 * name, under a lock as Mesa's hash table. */
struct dlist_shared {
   unsigned refs;
   pthread_mutex_t lock;
   struct {
      GLuint name;
      struct display_list *dl;
   } *table;
   unsigned table_count, table_cap;
   GLuint max_key;            /* highest name ever inserted (MaxKey) */
   unsigned walk;             /* replace_vertex_lists' mark */
};

struct fgl_dlist_state {
   struct dlist_shared *shared;

   struct display_list *current_list;   /* ListState.CurrentList */
   unsigned call_depth;            /* ListState.CallDepth */
   bool use_loopback;              /* ListState.Current.UseLoopback */
   /* after dlist_fallback inside glBegin/glEnd, the rest of the primitive
    * compiles into nodes: the attributes as save_Attr* nodes, glEnd as an
    * END node [S: vbo_save_api.c:dlist_fallback installs
    * _mesa_init_dispatch_save_begin_end's functions] */
   bool opcode_fallback;
   GLenum shade_model;             /* ListState.Current.ShadeModel */
   /* ListState.ActiveAttribSize/ActiveMaterialSize and
    * CurrentAttrib/CurrentMaterial: what the compiler knows of the
    * current values (save->currentsz, save->current) */
   unsigned active_size[FGL_ATTR_COUNT];
   float current[FGL_ATTR_COUNT][4];
   GLenum save_prim;               /* Driver.CurrentSavePrimitive */
   bool save_need_flush;           /* Driver.SaveNeedFlush */
   struct save_context save;
};

static const float attr_default[4] = { 0.0f, 0.0f, 0.0f, 1.0f };

static struct display_list *make_list(GLuint name)
{
   struct display_list *dl = fgl_calloc(1, sizeof(*dl));
   if (!dl)
      return NULL;
   dl->name = name;
   dl->cap = 8;
   dl->nodes = fgl_malloc(dl->cap * sizeof(*dl->nodes));
   if (!dl->nodes) {
      fgl_free(dl);
      return NULL;
   }
   dl->nodes[0].h.op = DL_OP_END_OF_LIST;
   dl->nodes[0].h.size = 1;
   dl->count = 1;
   return dl;
}

static void free_vertex_list(struct vertex_list *vl)
{
   bo_unref(vl->bo);
   fgl_free(vl->buffer);
   fgl_free(vl->prims);
   fgl_free(vl->current_data);
   fgl_free(vl->verts);
   fgl_free(vl->draws);
   fgl_free(vl);
}

static void delete_list(struct display_list *dl)
{
   if (!dl)
      return;
   for (unsigned i = 0; i < dl->count; i += dl->nodes[i].h.size) {
      const union dl_node *n = &dl->nodes[i];
      if (n->h.op == DL_OP_VERTEX_LIST)
         free_vertex_list(get_pointer(&n[1]));
      else if (n->h.op == DL_OP_CALL_LISTS)
         fgl_free(get_pointer(&n[3]));
      else if (n->h.op == DL_OP_BITMAP)
         fgl_free(get_pointer(&n[7]));
      else if (n->h.op == DL_OP_DRAW_PIXELS)
         fgl_free(get_pointer(&n[5]));
      else if (n->h.op == DL_OP_TEX_IMAGE || n->h.op == DL_OP_TEX_SUB_IMAGE ||
               n->h.op == DL_OP_TEX_IMAGE_3D)
         fgl_free(get_pointer(&n[10]));
      else if (n->h.op == DL_OP_TEX_SUB_IMAGE_3D)
         fgl_free(get_pointer(&n[11]));
      else if (n->h.op == DL_OP_COMPRESSED_TEX)
         fgl_free(get_pointer(&n[13]));
   }
   fgl_free(dl->nodes);
   fgl_free(dl);
}

/* index of the first entry with a name >= name */
static unsigned table_find(const struct dlist_shared *ls, GLuint name)
{
   unsigned lo = 0, hi = ls->table_count;
   while (lo < hi) {
      const unsigned mid = lo + (hi - lo) / 2;
      if (ls->table[mid].name < name)
         lo = mid + 1;
      else
         hi = mid;
   }
   return lo;
}

static struct display_list *lookup_list(const struct fgl_context *ctx, GLuint name)
{
   const struct dlist_shared *ls = ctx->ListState->shared;
   if (name == 0)
      return NULL;
   const unsigned i = table_find(ls, name);
   return i < ls->table_count && ls->table[i].name == name ? ls->table[i].dl : NULL;
}

/* _mesa_HashInsertLocked: replace or add; MaxKey follows. */
static bool insert_list(struct fgl_context *ctx, struct display_list *dl)
{
   struct dlist_shared *ls = ctx->ListState->shared;
   const unsigned i = table_find(ls, dl->name);
   if (i < ls->table_count && ls->table[i].name == dl->name) {
      delete_list(ls->table[i].dl);
      ls->table[i].dl = dl;
      return true;
   }
   if (ls->table_count == ls->table_cap) {
      const unsigned cap = ls->table_cap ? ls->table_cap * 2 : 64;
      void *t = fgl_realloc_gl(ctx, ls->table, cap * sizeof(*ls->table));
      if (!t)
         return false;
      ls->table = t;
      ls->table_cap = cap;
   }
   memmove(&ls->table[i + 1], &ls->table[i], (ls->table_count - i) * sizeof(*ls->table));
   ls->table[i].name = dl->name;
   ls->table[i].dl = dl;
   ls->table_count++;
   if (dl->name > ls->max_key)
      ls->max_key = dl->name;
   return true;
}

/* destroy_list */
static void remove_list(struct fgl_context *ctx, GLuint name)
{
   struct dlist_shared *ls = ctx->ListState->shared;
   const unsigned i = table_find(ls, name);
   if (name == 0 || i >= ls->table_count || ls->table[i].name != name)
      return;
   delete_list(ls->table[i].dl);
   memmove(&ls->table[i], &ls->table[i + 1], (ls->table_count - i - 1) * sizeof(*ls->table));
   ls->table_count--;
}

/* alloc_instruction: a node of `args` argument cells at the end of the
 * list being compiled (before its END_OF_LIST, which moves). */
static union dl_node *alloc_node(struct fgl_context *ctx, enum dl_opcode op, unsigned args)
{
   struct display_list *dl = ctx->ListState->current_list;
   if (!dl)
      return NULL;
   const unsigned size = 1 + args;
   if (dl->count + size > dl->cap) {
      unsigned cap = dl->cap;
      while (cap < dl->count + size)
         cap *= 2;
      union dl_node *nodes = fgl_realloc_gl(ctx, dl->nodes, cap * sizeof(*nodes));
      if (!nodes) {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return NULL;
      }
      dl->nodes = nodes;
      dl->cap = cap;
   }
   /* the END_OF_LIST node is the last one; the new node takes its place */
   union dl_node *n = &dl->nodes[dl->count - 1];
   memset(n, 0, size * sizeof(*n));
   n->h.op = (uint16_t)op;
   n->h.size = (uint16_t)size;
   n[size].h.op = DL_OP_END_OF_LIST;
   n[size].h.size = 1;
   dl->count += size;
   return n;
}

bool fgl_init_dlist(struct fgl_context *ctx)
{
   ctx->ListState = fgl_calloc_gl(ctx, 1, sizeof(*ctx->ListState));
   if (!ctx->ListState)
      return false;
   ctx->ListState->shared = fgl_calloc_gl(ctx, 1, sizeof(*ctx->ListState->shared));
   if (!ctx->ListState->shared) {
      fgl_free(ctx->ListState);
      ctx->ListState = NULL;
      return false;
   }
   ctx->ListState->shared->refs = 1;
   pthread_mutex_init(&ctx->ListState->shared->lock, NULL);
   ctx->ExecuteFlag = true;
   ctx->CompileFlag = false;
   ctx->List.ListBase = 0;
   ctx->ListState->save_prim = PRIM_UNKNOWN;
   /* _mesa_init_display_list starts the depth at 1: a glCallList runs
    * MAX_LIST_NESTING lists deep, its own included */
   ctx->ListState->call_depth = 1;
   return true;
}

static void unref_shared(struct dlist_shared *sh)
{
   if (!sh || --sh->refs > 0)
      return;
   for (unsigned i = 0; i < sh->table_count; i++)
      delete_list(sh->table[i].dl);
   fgl_free(sh->table);
   pthread_mutex_destroy(&sh->lock);
   fgl_free(sh);
}

void fgl_share_dlists(struct fgl_context *ctx, struct fgl_context *share)
{
   struct dlist_shared *sh = share->ListState->shared;
   pthread_mutex_lock(&sh->lock);
   sh->refs++;
   pthread_mutex_unlock(&sh->lock);
   unref_shared(ctx->ListState->shared);
   ctx->ListState->shared = sh;
}

void fgl_free_dlist(struct fgl_context *ctx)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   if (!ls)
      return;
   pthread_mutex_lock(&ls->shared->lock);
   const bool last = ls->shared->refs == 1;
   if (!last)
      ls->shared->refs--;
   pthread_mutex_unlock(&ls->shared->lock);
   if (last)
      unref_shared(ls->shared);
   delete_list(ls->current_list);
   fgl_free(ls->save.buffer);
   fgl_free(ls->save.prims);
   fgl_free(ls->save.copied);
   bo_unref(ls->save.bo);
   fgl_free(ls);
   ctx->ListState = NULL;
}

/* ------------------------------------------------------------------ */
/* Compile-time helpers                                                */
/* ------------------------------------------------------------------ */

static inline bool inside_save_begin_end(const struct fgl_dlist_state *ls)
{
   return ls->save_prim <= PRIM_MAX;
}

/* _mesa_compile_error: an ERROR node, and the error at once under
 * GL_COMPILE_AND_EXECUTE. */
static void compile_error(struct fgl_context *ctx, GLenum error)
{
   if (ctx->CompileFlag) {
      union dl_node *n = alloc_node(ctx, DL_OP_ERROR, 1);
      if (n)
         n[1].e = error;
   }
   if (ctx->ExecuteFlag)
      fgl_error(ctx, error);
}

static void save_flush_vertices(struct fgl_context *ctx);

/* SAVE_FLUSH_VERTICES */
static inline void save_flush(struct fgl_context *ctx)
{
   if (ctx->ListState->save_need_flush)
      save_flush_vertices(ctx);
}

/* ASSERT_OUTSIDE_SAVE_BEGIN_END_AND_FLUSH: false after compiling the
 * error of a command inside glBegin/glEnd. */
static bool save_prologue(struct fgl_context *ctx)
{
   if (inside_save_begin_end(ctx->ListState)) {
      compile_error(ctx, GL_INVALID_OPERATION);
      return false;
   }
   save_flush(ctx);
   return true;
}

/* invalidate_saved_current_state: after glCallList(s) while compiling,
 * and at glNewList. */
static void invalidate_saved_current_state(struct fgl_context *ctx)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   memset(ls->active_size, 0, sizeof(ls->active_size));
   ls->shade_model = 0;
   ls->save_prim = PRIM_UNKNOWN;
}

/* ------------------------------------------------------------------ */
/* The table's save functions and node layouts                         */
/* ------------------------------------------------------------------ */

#define DL_PUT_E(c, v)  ((c).e = (v))
#define DL_PUT_I(c, v)  ((c).i = (v))
#define DL_PUT_SZ(c, v) ((c).sz = (v))
#define DL_PUT_U(c, v)  ((c).u = (v))
#define DL_PUT_F(c, v)  ((c).f = (v))
#define DL_PUT_B(c, v)  ((c).b = (v))
#define DL_PUT_BF(c, v) ((c).bf = (v))
#define DL_PUT_US(c, v) ((c).us = (v))
#define DL_PUT_D(c, v)  ((c).f = (GLfloat)(v))
#define DL_PUT_FU(c, v) ((c).f = (v))
#define DL_GET_E(c)  ((c).e)
#define DL_GET_I(c)  ((c).i)
#define DL_GET_SZ(c) ((c).sz)
#define DL_GET_U(c)  ((c).u)
#define DL_GET_F(c)  ((c).f)
#define DL_GET_B(c)  ((c).b)
#define DL_GET_BF(c) ((c).bf)
#define DL_GET_US(c) ((c).us)
#define DL_GET_D(c)  ((GLdouble)(c).f)
/* FU: stored as a float, replayed as the float of its bit pattern
 * ([S: main/dlist.c:execute_list OPCODE_CLEAR_INDEX]: save_ClearIndex
 * writes n[1].f, the replay calls ClearIndex((GLfloat) n[1].ui)) */
#define DL_GET_FU(c) ((GLfloat)(c).u)

/* vectors: cells used, store (the first cnt values, zeros after), read */
#define DL_VEC_NODES_F(N)  (N)
#define DL_VEC_NODES_D(N)  (N)
#define DL_VEC_NODES_UB(N) (((N) + 3) / 4)

static void put_vec_F(union dl_node *dst, const GLfloat *v, unsigned cnt, unsigned n)
{
   for (unsigned i = 0; i < n; i++)
      dst[i].f = i < cnt ? v[i] : 0.0f;
}

static void put_vec_D(union dl_node *dst, const GLdouble *v, unsigned cnt, unsigned n)
{
   for (unsigned i = 0; i < n; i++)
      dst[i].f = i < cnt ? (GLfloat)v[i] : 0.0f;
}

static void put_vec_UB(union dl_node *dst, const GLubyte *v, unsigned cnt, unsigned n)
{
   GLubyte *b = (GLubyte *)dst;
   for (unsigned i = 0; i < n; i++)
      b[i] = i < cnt ? v[i] : 0;
}

static const GLdouble *get_vec_D(const union dl_node *src, GLdouble *tmp, unsigned n)
{
   for (unsigned i = 0; i < n; i++)
      tmp[i] = (GLdouble)src[i].f;
   return tmp;
}

#define DL_GET_VEC_F(p, N)  (&(p)->f)
#define DL_GET_VEC_D(p, N)  get_vec_D((p), (GLdouble[N]){ 0 }, (N))
#define DL_GET_VEC_UB(p, N) ((const GLubyte *)(p))

#define DL_SAVE_BODY(Name, ...)                                                 \
   {                                                                            \
      if (!save_prologue(ctx))                                                  \
         return false;                                                          \
      fgl_dl_put_##Name(ctx, __VA_ARGS__);                                      \
      return ctx->ExecuteFlag;                                                  \
   }

#define DL_OP0(Name)                                                            \
   void fgl_dl_put_##Name(struct fgl_context *ctx)                              \
   {                                                                            \
      (void)alloc_node(ctx, DL_OP_##Name, 0);                                   \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx)                                \
   {                                                                            \
      if (!save_prologue(ctx))                                                  \
         return false;                                                          \
      fgl_dl_put_##Name(ctx);                                                   \
      return ctx->ExecuteFlag;                                                  \
   }
#define DL_OP1(Name, A)                                                         \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0)                \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 1);                      \
      if (n)                                                                    \
         DL_PUT_##A(n[1], a0);                                                  \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx, DL_CT_##A a0)                  \
   DL_SAVE_BODY(Name, a0)
#define DL_OP2(Name, A, B)                                                      \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1)  \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 2);                      \
      if (n) {                                                                  \
         DL_PUT_##A(n[1], a0);                                                  \
         DL_PUT_##B(n[2], a1);                                                  \
      }                                                                         \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1)    \
   DL_SAVE_BODY(Name, a0, a1)
#define DL_OP3(Name, A, B, C)                                                   \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,  \
                          DL_CT_##C a2)                                         \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 3);                      \
      if (n) {                                                                  \
         DL_PUT_##A(n[1], a0);                                                  \
         DL_PUT_##B(n[2], a1);                                                  \
         DL_PUT_##C(n[3], a2);                                                  \
      }                                                                         \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,    \
                        DL_CT_##C a2)                                           \
   DL_SAVE_BODY(Name, a0, a1, a2)
#define DL_OP4(Name, A, B, C, D_)                                               \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,  \
                          DL_CT_##C a2, DL_CT_##D_ a3)                          \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 4);                      \
      if (n) {                                                                  \
         DL_PUT_##A(n[1], a0);                                                  \
         DL_PUT_##B(n[2], a1);                                                  \
         DL_PUT_##C(n[3], a2);                                                  \
         DL_PUT_##D_(n[4], a3);                                                 \
      }                                                                         \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,    \
                        DL_CT_##C a2, DL_CT_##D_ a3)                            \
   DL_SAVE_BODY(Name, a0, a1, a2, a3)
#define DL_OP5(Name, A, B, C, D_, E_)                                           \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,  \
                          DL_CT_##C a2, DL_CT_##D_ a3, DL_CT_##E_ a4)           \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 5);                      \
      if (n) {                                                                  \
         DL_PUT_##A(n[1], a0);                                                  \
         DL_PUT_##B(n[2], a1);                                                  \
         DL_PUT_##C(n[3], a2);                                                  \
         DL_PUT_##D_(n[4], a3);                                                 \
         DL_PUT_##E_(n[5], a4);                                                 \
      }                                                                         \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,    \
                        DL_CT_##C a2, DL_CT_##D_ a3, DL_CT_##E_ a4)             \
   DL_SAVE_BODY(Name, a0, a1, a2, a3, a4)
#define DL_OP6(Name, A, B, C, D_, E_, F_)                                       \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,  \
                          DL_CT_##C a2, DL_CT_##D_ a3, DL_CT_##E_ a4,           \
                          DL_CT_##F_ a5)                                        \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 6);                      \
      if (n) {                                                                  \
         DL_PUT_##A(n[1], a0);                                                  \
         DL_PUT_##B(n[2], a1);                                                  \
         DL_PUT_##C(n[3], a2);                                                  \
         DL_PUT_##D_(n[4], a3);                                                 \
         DL_PUT_##E_(n[5], a4);                                                 \
         DL_PUT_##F_(n[6], a5);                                                 \
      }                                                                         \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,    \
                        DL_CT_##C a2, DL_CT_##D_ a3, DL_CT_##E_ a4,             \
                        DL_CT_##F_ a5)                                          \
   DL_SAVE_BODY(Name, a0, a1, a2, a3, a4, a5)
#define DL_OPV0(Name, VT, N)                                                    \
   void fgl_dl_put_##Name(struct fgl_context *ctx, const DL_CT_##VT *v,         \
                          unsigned cnt)                                         \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, DL_VEC_NODES_##VT(N));   \
      if (n)                                                                    \
         put_vec_##VT(&n[1], v, cnt, N);                                        \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx, const DL_CT_##VT *v,           \
                        unsigned cnt)                                           \
   DL_SAVE_BODY(Name, v, cnt)
#define DL_OPV1(Name, A, VT, N)                                                 \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0,                \
                          const DL_CT_##VT *v, unsigned cnt)                    \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 1 + DL_VEC_NODES_##VT(N)); \
      if (n) {                                                                  \
         DL_PUT_##A(n[1], a0);                                                  \
         put_vec_##VT(&n[2], v, cnt, N);                                        \
      }                                                                         \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx, DL_CT_##A a0,                  \
                        const DL_CT_##VT *v, unsigned cnt)                      \
   DL_SAVE_BODY(Name, a0, v, cnt)
#define DL_OPV2(Name, A, B, VT, N)                                              \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,  \
                          const DL_CT_##VT *v, unsigned cnt)                    \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 2 + DL_VEC_NODES_##VT(N)); \
      if (n) {                                                                  \
         DL_PUT_##A(n[1], a0);                                                  \
         DL_PUT_##B(n[2], a1);                                                  \
         put_vec_##VT(&n[3], v, cnt, N);                                        \
      }                                                                         \
   }                                                                            \
   bool fgl_save_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,    \
                        const DL_CT_##VT *v, unsigned cnt)                      \
   DL_SAVE_BODY(Name, a0, a1, v, cnt)
/* the DL_CUSTOM commands: only the node; their save function is below */
#define DL_CUSTOM0(Name)                                                        \
   void fgl_dl_put_##Name(struct fgl_context *ctx)                              \
   {                                                                            \
      (void)alloc_node(ctx, DL_OP_##Name, 0);                                   \
   }
#define DL_CUSTOM1(Name, A)                                                     \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0)                \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 1);                      \
      if (n)                                                                    \
         DL_PUT_##A(n[1], a0);                                                  \
   }
#define DL_CUSTOMV2(Name, A, B, VT, N)                                          \
   void fgl_dl_put_##Name(struct fgl_context *ctx, DL_CT_##A a0, DL_CT_##B a1,  \
                          const DL_CT_##VT *v, unsigned cnt)                    \
   {                                                                            \
      union dl_node *n = alloc_node(ctx, DL_OP_##Name, 2 + DL_VEC_NODES_##VT(N)); \
      if (n) {                                                                  \
         DL_PUT_##A(n[1], a0);                                                  \
         DL_PUT_##B(n[2], a1);                                                  \
         put_vec_##VT(&n[3], v, cnt, N);                                        \
      }                                                                         \
   }
#include "main/dlist_ops.h"
#include "main/dlist_ops_undef.h"

/* ------------------------------------------------------------------ */
/* The vertex-list compiler [S: vbo/vbo_save_api.c]                    */
/* ------------------------------------------------------------------ */

static unsigned get_vertex_count(const struct save_context *save)
{
   return save->vertex_size ? save->used / save->vertex_size : 0;
}

/* reset_counters */
static void reset_counters(struct fgl_context *ctx)
{
   struct save_context *save = &ctx->ListState->save;
   save->used = 0;
   save->prim_used = 0;
   save->dangling_attr_ref = false;
}

static bool ensure_alloc(struct save_context *save, unsigned floats)
{
   if (floats <= save->alloc)
      return true;
   unsigned alloc = save->alloc ? save->alloc : 1024;
   while (alloc < floats)
      alloc *= 2;
   float *b = fgl_realloc(save->buffer, alloc * sizeof(float));
   if (!b)
      return false;
   memset(b + save->alloc, 0, (alloc - save->alloc) * sizeof(float));
   save->buffer = b;
   save->alloc = alloc;
   return true;
}

/* vbo_copy_vertices (in_dlist): the tail of an open primitive that the
 * next vertex list repeats; a triangle strip keeps an even count. */
static unsigned copy_vertices_mode(GLenum mode, unsigned *pcount, unsigned vertex_size,
                                   float *dst, const float *src)
{
   const unsigned count = *pcount;
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
   case GL_TRIANGLE_FAN:
   case GL_POLYGON:
      if (count == 0)
         return 0;
      memcpy(dst, src, vertex_size * sizeof(float));
      if (count == 1)
         return 1;
      memcpy(dst + vertex_size, src + (count - 1) * vertex_size, vertex_size * sizeof(float));
      return 2;
   case GL_TRIANGLE_STRIP:
      *pcount -= count % 2;
      /* fallthrough */
   case GL_QUAD_STRIP:
      copy = count <= 1 ? count : 2 + (count % 2);
      break;
   default:
      return 0;
   }
   memcpy(dst, src + (count - copy) * vertex_size, copy * vertex_size * sizeof(float));
   return copy;
}

/* copy_vertices: for a primitive still open when its list is compiled */
static unsigned save_copy_vertices(struct save_context *save, struct save_prim *prims,
                                   unsigned prim_count)
{
   struct save_prim *prim = &prims[prim_count - 1];
   const unsigned sz = save->vertex_size;
   if (prim->end || !prim->count || !sz)
      return 0;
   /* a copy no later list consumed (glEndList or glCallList inside
    * glBegin/glEnd) is dropped */
   fgl_free(save->copied);
   save->copied = fgl_malloc(sizeof(float) * sz * prim->count);
   if (!save->copied)
      return 0;
   const unsigned r = copy_vertices_mode(prim->mode, &prim->count, sz, save->copied,
                                         save->buffer + prim->start * sz);
   if (!r) {
      fgl_free(save->copied);
      save->copied = NULL;
   }
   return r;
}

/* vbo_try_prim_conversion */
static void try_prim_conversion(GLenum *mode, unsigned count)
{
   if (*mode == GL_LINE_STRIP && count == 2)
      *mode = GL_LINES;
   else if ((*mode == GL_TRIANGLE_STRIP || *mode == GL_TRIANGLE_FAN) && count == 3)
      *mode = GL_TRIANGLES;
}

/* vbo_merge_draws (in_dlist) */
static bool merge_draws(struct save_prim *p0, const struct save_prim *p1)
{
   if (p0->mode != p1->mode || p0->start + p0->count != p1->start ||
       !fgl_vbo_prim_mergeable(p0->mode, p0->count))
      return false;
   p0->count += p1->count;
   p0->end = p1->end;
   return true;
}

/* merge_prims: the first primitive keeps its mode (the conversion loop
 * starts at the second one). */
static void merge_prims(struct save_prim *prims, unsigned *prim_count)
{
   struct save_prim *prev = prims;
   for (unsigned i = 1; i < *prim_count; i++) {
      struct save_prim *cur = &prims[i];
      try_prim_conversion(&cur->mode, cur->count);
      if (merge_draws(prev, cur))
         continue;
      prev++;
      if (prev != cur)
         *prev = *cur;
   }
   *prim_count = (unsigned)(prev - prims) + 1;
}

/* convert_line_loop_to_strip: the last primitive, when a line loop */
static void convert_line_loop_to_strip(struct save_context *save, struct vertex_list *vl,
                                       struct save_prim *prim)
{
   if (prim->end) {
      /* the loop's first vertex appended after its last one (the end of
       * the buffer) closes it */
      const unsigned sz = save->vertex_size;
      if (ensure_alloc(save, (prim->start + prim->count + 1) * sz)) {
         if (sz)   /* no attributes (no buffer yet): nothing to copy */
            memcpy(save->buffer + (prim->start + prim->count) * sz,
                   save->buffer + prim->start * sz, sz * sizeof(float));
         prim->count++;
         vl->vertex_count++;
         save->used += sz;
      }
   }
   if (!prim->begin) {
      /* a later section of a wrapped loop: its first vertex is the loop's
       * first, copied for the end */
      prim->start++;
      prim->count--;
   }
   prim->mode = GL_LINE_STRIP;
}

/* u_prim_vertex_count(mode)->min */
static unsigned prim_min_vertices(GLenum mode)
{
   switch (mode) {
   case GL_POINTS: return 1;
   case GL_LINES: case GL_LINE_LOOP: case GL_LINE_STRIP: return 2;
   case GL_TRIANGLES: case GL_TRIANGLE_STRIP: case GL_TRIANGLE_FAN: case GL_POLYGON: return 3;
   case GL_QUADS: case GL_QUAD_STRIP: return 4;
   default: return 1;
   }
}

/* A vertex of the compiled buffer as the draw fetches it: each attribute
 * of the format, missing components (0, 0, 0, 1). */
static void fetch_vertex(const struct vertex_list *vl, const float *src,
                         struct fgl_vbo_vertex *dst)
{
   for (int a = 0; a < FGL_ATTR_COUNT; a++) {
      const unsigned sz = vl->attrsz[a];
      if (!sz) {
         /* a list without positions (an empty GL_LINE_LOOP's closing
          * vertex, convert_line_loop_to_strip): the draw reads the current
          * value of attribute 0, (0, 0, 0, 1) */
         if (a == FGL_ATTR_POS)
            for (unsigned c = 0; c < 4; c++)
               dst->attr[a][c] = attr_default[c];
         continue;
      }
      for (unsigned c = 0; c < 4; c++)
         dst->attr[a][c] = c < sz ? src[c] : attr_default[c];
      src += sz;
   }
}

/* The index buffer of compile_vertex_list (all primitive types are
 * supported by llvmpipe, so none is converted), resolved to vertices. */
static unsigned *build_draws(struct vertex_list *vl, const float *buffer, unsigned *nidx)
{
   const struct save_prim *prims = vl->prims;
   const unsigned prim_count = vl->prim_count;
   unsigned total = 0;
   for (unsigned i = 0; i < prim_count; i++)
      total += prims[i].count;
   /* at most 2 indices per vertex for strips turned into lines, plus the
    * padding and the strip joins */
   unsigned max_idx = 2 * total + 8 * prim_count + 8;
   unsigned *indices = fgl_malloc(max_idx * sizeof(*indices));
   struct fgl_vbo_prim *merged = fgl_calloc(prim_count ? prim_count : 1, sizeof(*merged));
   if (!indices || !merged) {
      fgl_free(indices);
      fgl_free(merged);
      return NULL;
   }
   unsigned idx = 0;
   int last = -1;
   for (unsigned i = 0; i < prim_count; i++) {
      GLenum mode = prims[i].mode;
      const unsigned vertex_count = prims[i].count;
      if (!vertex_count)
         continue;
      /* line strips may become lines */
      if (mode == GL_LINE_STRIP)
         mode = GL_LINES;
      const bool merge = last >= 0 && mode == merged[last].mode &&
                         mode != GL_LINE_LOOP && mode != GL_TRIANGLE_FAN &&
                         mode != GL_QUAD_STRIP && mode != GL_POLYGON;
      /* consecutive triangle strips are joined by degenerate triangles,
       * with one more index when the first has an odd triangle count */
      if (merge && mode == GL_TRIANGLE_STRIP) {
         const unsigned tri_count = merged[last].count - 2;
         indices[idx] = indices[idx - 1];
         indices[idx + 1] = prims[i].start;
         idx += 2;
         merged[last].count += 2;
         if (tri_count % 2) {
            indices[idx++] = prims[i].start;
            merged[last].count++;
         }
      }
      const unsigned start = idx;
      /* a line strip merged into lines, or followed by a strip or lines,
       * is drawn as lines: inner vertices repeated */
      if (prims[i].mode == GL_LINE_STRIP &&
          (merge || (i < prim_count - 1 && (prims[i + 1].mode == GL_LINE_STRIP ||
                                            prims[i + 1].mode == GL_LINES)))) {
         for (unsigned j = 0; j < vertex_count; j++) {
            indices[idx++] = prims[i].start + j;
            if (j && j != vertex_count - 1)
               indices[idx++] = prims[i].start + j;
         }
      } else {
         mode = prims[i].mode;
         for (unsigned j = 0; j < vertex_count; j++)
            indices[idx++] = prims[i].start + j;
      }
      /* an incomplete primitive repeats its last vertex up to the mode's
       * minimum */
      for (unsigned j = vertex_count; j < prim_min_vertices(mode); j++)
         indices[idx++] = prims[i].start + vertex_count - 1;
      if (merge) {
         merged[last].count += idx - start;
      } else {
         last++;
         merged[last] = (struct fgl_vbo_prim){
            .mode = mode, .start = start, .count = idx - start,
            .begin = prims[i].begin, .end = prims[i].end, .indexed = true,
         };
      }
      merged[last].mode = mode;
   }

   vl->verts = fgl_malloc((idx ? idx : 1) * sizeof(*vl->verts));
   if (!vl->verts) {
      fgl_free(indices);
      fgl_free(merged);
      return NULL;
   }
   for (unsigned k = 0; k < idx; k++)
      fetch_vertex(vl, buffer + indices[k] * vl->vertex_size, &vl->verts[k]);
   vl->nverts = idx;
   vl->draws = merged;
   vl->ndraws = (unsigned)(last + 1);
   *nidx = idx;
   return indices;
}

static struct bo_image *bo_new(unsigned size)
{
   struct bo_image *bo = fgl_calloc(1, sizeof(*bo));
   if (!bo)
      return NULL;
   bo->data = fgl_calloc(size, 1);
   if (!bo->data) {
      fgl_free(bo);
      return NULL;
   }
   bo->size = size;
   bo->refs = 1;
   return bo;
}

/* compile_vertex_list's upload: the vertices (duplicates merged, unless
 * the list is replayed by loopback), then the indices, placed where Mesa
 * places them so that a later loopback reads what Mesa reads.  False when
 * Mesa's node gets no index buffer (node->cold->ib.obj NULL): nothing to
 * upload (no index: a loopback list whose only primitive, an open
 * GL_TRIANGLE_STRIP of one vertex, lost it to copy_vertices) before the
 * context's first vertex list made the save buffer (current_bo), which
 * Mesa then reuses while it is NULL; Mesa sets the node's vertex and
 * primitive counts to 0, so its replay has no glBegin (ORACLE-NOTES.md
 * "OSMesa defects kept visible", probe p_dlist_first_begin). */
static bool upload_vertex_list(struct fgl_context *ctx, struct vertex_list *vl,
                               unsigned *indices, unsigned idx, unsigned *buffer_offset_out)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   struct save_context *save = &ls->save;
   const unsigned vsize = save->vertex_size;
   const unsigned stride = vsize * (unsigned)sizeof(float);
   const bool dedup = !ls->use_loopback;

   /* add_vertex: vertices by first use, equal ones (bitwise) merged */
   float *temp = NULL;
   unsigned unique = 0;
   if (dedup) {
      unsigned hsize = 16;
      while (hsize < 2 * idx)
         hsize *= 2;
      temp = fgl_malloc_gl(ctx, (size_t)(idx ? idx : 1) * vsize * sizeof(float));
      unsigned *hash = fgl_calloc_gl(ctx, hsize, sizeof(*hash));   /* unique index + 1 */
      if (!temp || !hash) {
         fgl_free(temp);
         fgl_free(hash);
         return true;
      }
      for (unsigned k = 0; k < idx; k++) {
         const float *v = save->buffer + (size_t)indices[k] * vsize;
         uint32_t hv = 2166136261u;   /* FNV-1a of the vertex's bytes */
         const uint8_t *b = (const uint8_t *)v;
         for (size_t i = 0; i < vsize * sizeof(float); i++)
            hv = (hv ^ b[i]) * 16777619u;
         unsigned slot = hv & (hsize - 1);
         while (hash[slot] &&
                memcmp(temp + (size_t)(hash[slot] - 1) * vsize, v, vsize * sizeof(float)) != 0)
            slot = (slot + 1) & (hsize - 1);
         if (!hash[slot]) {
            memcpy(temp + (size_t)unique * vsize, v, vsize * sizeof(float));
            hash[slot] = ++unique;
         }
         indices[k] = hash[slot] - 1;
      }
      fgl_free(hash);
   }
   /* max_index starts at 0: with no index at all (primitives without
    * vertices) Mesa still uploads one vertex of its (uninitialized) merge
    * buffer; zeros here */
   if (dedup && unique == 0)
      memset(temp, 0, vsize * sizeof(float));
   const unsigned total_vert_count = dedup ? (unique ? unique : 1) : idx;
   const unsigned total_bytes = idx * 4u + total_vert_count * stride;

   /* the start is padded to a multiple of the stride from the previous
    * list's offset, so that both can share one vertex array */
   const unsigned old_offset = save->vao_offset;
   if (old_offset != save->bo_used && stride > 0 && save->bo) {
      while (save->bo_used > old_offset && save->bo_used < save->bo->size &&
             (save->bo_used - old_offset) % stride != 0)
         save->bo_used++;
   }
   unsigned buffer_offset = save->bo_used;
   unsigned start_offset = 0;
   const unsigned available = save->bo ? save->bo->size - save->bo_used : 0;
   if (total_bytes > available) {
      bo_unref(save->bo);
      save->bo = bo_new(total_bytes > SAVE_BO_MIN_SIZE ? total_bytes : SAVE_BO_MIN_SIZE);
      save->bo_used = 0;
      buffer_offset = 0;
   } else if (!save->bo) {
      fgl_free(temp);
      *buffer_offset_out = buffer_offset;
      return false;
   } else {
      if (buffer_offset > old_offset && stride > 0 && (buffer_offset - old_offset) % stride == 0) {
         start_offset = (buffer_offset - old_offset) / stride;
         buffer_offset = old_offset;
      }
      for (unsigned k = 0; k < idx; k++)
         indices[k] += start_offset;
   }
   /* the vertices: the merged ones, or the first idx of the store */
   if (!dedup)
      ensure_alloc(save, idx * vsize);
   const float *src = dedup ? temp : save->buffer;
   bo_write(save->bo, save->bo_used, src, (size_t)total_vert_count * stride);
   save->bo_used += total_vert_count * stride;
   if (dedup)
      save->bo_used = (save->bo_used + 3u) & ~3u;
   bo_write(save->bo, save->bo_used, indices, (size_t)idx * 4u);
   save->bo_used += idx * 4u;
   fgl_free(temp);
   vl->start_offset = start_offset;
   *buffer_offset_out = buffer_offset;
   return true;
}

static void loopback_vertex_list(struct fgl_context *ctx, const struct vertex_list *vl,
                                 const uint8_t *base, size_t size);

/* compile_vertex_list: the stored primitives become a vertex list node. */
static void compile_vertex_list(struct fgl_context *ctx)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   struct save_context *save = &ls->save;
   /* a list without attributes (glEvalCoord alone between glBegin and
    * glEnd) has vertices of no size and, so far, no buffer: give it one,
    * so that its offsets and copies of zero bytes have a base */
   if (!save->buffer)
      ensure_alloc(save, 1);

   struct vertex_list *vl = fgl_calloc_gl(ctx, 1, sizeof(*vl));
   union dl_node *n = vl ? alloc_node(ctx, DL_OP_VERTEX_LIST, PTR_NODES) : NULL;
   if (!n) {
      fgl_free(vl);
      reset_counters(ctx);
      return;
   }
   put_pointer(&n[1], vl);
   vl->kind = !save->dangling_attr_ref && !save->no_current_update ? VL_COPY_CURRENT : VL_DRAW;
   memcpy(vl->attrsz, save->attrsz, sizeof(vl->attrsz));
   vl->vertex_size = save->vertex_size;
   vl->vertex_count = get_vertex_count(save);
   vl->wrap_count = save->copied_nr;
   vl->prim_count = save->prim_used;
   vl->prims = fgl_malloc_gl(ctx, (save->prim_used ? save->prim_used : 1) * sizeof(*vl->prims));
   if (vl->prims)
      memcpy(vl->prims, save->prims, save->prim_used * sizeof(*vl->prims));
   else
      vl->prim_count = 0;

   /* the current values after the list: the attributes (but the position)
    * of the last vertex stored */
   if (!save->no_current_update) {
      const unsigned current_size = save->vertex_size - save->attrsz[FGL_ATTR_POS];
      if (current_size) {
         vl->current_data = fgl_malloc_gl(ctx, current_size * sizeof(float));
         const unsigned vertex_offset =
            vl->vertex_count ? (vl->vertex_count - 1) * save->vertex_size : 0;
         if (vl->current_data && ensure_alloc(save, vertex_offset + save->vertex_size))
            memcpy(vl->current_data, save->buffer + vertex_offset + save->attrsz[FGL_ATTR_POS],
                   current_size * sizeof(float));
      }
   }

   if (save->dangling_attr_ref)
      ls->use_loopback = true;

   if (vl->prim_count) {
      save->copied_nr = save_copy_vertices(save, vl->prims, vl->prim_count);
      if (vl->prims[vl->prim_count - 1].mode == GL_LINE_LOOP)
         convert_line_loop_to_strip(save, vl, &vl->prims[vl->prim_count - 1]);
      merge_prims(vl->prims, &vl->prim_count);
   } else {
      save->copied_nr = 0;
   }

   const size_t bytes = (size_t)vl->vertex_count * vl->vertex_size * sizeof(float);
   vl->buffer = fgl_malloc_gl(ctx, bytes ? bytes : 1);
   if (vl->buffer && bytes)
      memcpy(vl->buffer, save->buffer, bytes);

   unsigned buffer_offset = 0;
   if (vl->vertex_count && vl->prim_count && vl->buffer) {
      unsigned nidx = 0;
      unsigned *indices = build_draws(vl, vl->buffer, &nidx);
      if (indices) {
         if (!upload_vertex_list(ctx, vl, indices, nidx, &buffer_offset))
            vl->vertex_count = vl->prim_count = 0;
         fgl_free(indices);
      } else {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
      }
   }
   vl->draw_begins = vl->prim_count ? vl->prims[0].begin : save->prim_used && save->prims[0].begin;
   if (!save->bo && !(save->bo = bo_new(SAVE_BO_MIN_SIZE)))
      fgl_error(ctx, GL_OUT_OF_MEMORY);
   /* update_vao: the next list's old_offset */
   save->vao_offset = buffer_offset;
   vl->bo = bo_ref(save->bo);
   vl->vao_offset = buffer_offset;

   /* GL_COMPILE_AND_EXECUTE: through the immediate-mode calls (not when
    * the copy could not be made: out of memory, raised above) */
   if (ctx->ExecuteFlag && vl->buffer)
      loopback_vertex_list(ctx, vl, (const uint8_t *)vl->buffer,
                           (size_t)vl->vertex_count * vl->vertex_size * sizeof(float));

   reset_counters(ctx);
}

/* wrap_buffers: the open primitive continues in a new vertex list */
static void wrap_buffers(struct fgl_context *ctx)
{
   struct save_context *save = &ctx->ListState->save;
   if (save->prim_used == 0) {   /* no open primitive (Mesa asserts) */
      compile_vertex_list(ctx);
      return;
   }
   const unsigned i = save->prim_used - 1;
   save->prims[i].count = get_vertex_count(save) - save->prims[i].start;
   const GLenum mode = save->prims[i].mode;
   compile_vertex_list(ctx);
   save->prims[0] = (struct save_prim){ .mode = mode };
   save->prim_used = 1;
}

/* wrap_filled_vertex */
static void wrap_filled_vertex(struct fgl_context *ctx)
{
   struct save_context *save = &ctx->ListState->save;
   wrap_buffers(ctx);
   const unsigned num = save->copied_nr * save->vertex_size;
   if (num && save->copied && ensure_alloc(save, num))
      memcpy(save->buffer, save->copied, num * sizeof(float));
   fgl_free(save->copied);
   save->copied = NULL;
   save->used = num;
}

/* grow_vertex_storage: room for vertex_count more vertices; beyond
 * VBO_SAVE_BUFFER_SIZE the list wraps */
static void grow_vertex_storage(struct fgl_context *ctx, unsigned vertex_count)
{
   struct save_context *save = &ctx->ListState->save;
   unsigned new_size = (save->used + vertex_count * save->vertex_size) * (unsigned)sizeof(float);
   if (save->prim_used > 0 && vertex_count > 0 && new_size > SAVE_BUFFER_SIZE) {
      wrap_filled_vertex(ctx);
      new_size = SAVE_BUFFER_SIZE;
   }
   if (new_size > save->buffer_size)
      save->buffer_size = new_size;
   ensure_alloc(save, save->buffer_size / (unsigned)sizeof(float) + 1);
}

/* copy_to_current: the compiler's vertex values become what it knows as
 * current (COPY_CLEAN_4V) */
static void save_copy_to_current(struct fgl_context *ctx)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   struct save_context *save = &ls->save;
   for (int a = FGL_ATTR_POS + 1; a < FGL_ATTR_COUNT; a++) {
      const unsigned sz = save->attrsz[a];
      if (!sz)
         continue;
      for (unsigned c = 0; c < 4; c++)
         ls->current[a][c] = c < sz ? save->vertex[save->attroff[a] + c] : attr_default[c];
   }
}

static void save_copy_from_current(struct fgl_context *ctx)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   struct save_context *save = &ls->save;
   for (int a = FGL_ATTR_POS + 1; a < FGL_ATTR_COUNT; a++)
      for (unsigned c = 0; c < save->attrsz[a]; c++)
         save->vertex[save->attroff[a] + c] = ls->current[a][c];
}

/* upgrade_vertex: a new or larger attribute */
static void upgrade_vertex(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned newsz)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   struct save_context *save = &ls->save;

   if (save->used)
      wrap_buffers(ctx);
   save_copy_to_current(ctx);

   const unsigned oldsz = save->attrsz[attr];
   save->attrsz[attr] = newsz;
   save->vertex_size += newsz - oldsz;
   unsigned off = 0;
   for (int a = 0; a < FGL_ATTR_COUNT; a++) {
      save->attroff[a] = off;
      off += save->attrsz[a];
   }
   save_copy_from_current(ctx);

   /* the copied vertices in the new format; a new attribute takes the
    * value the compiler knows, and without one the list depends on the
    * state it is called in (loopback) */
   if (save->copied_nr && save->copied) {
      const float *data = save->copied;
      grow_vertex_storage(ctx, save->copied_nr);
      if (!ensure_alloc(save, save->used + save->copied_nr * save->vertex_size))
         return;
      float *dest = save->buffer + save->used;
      if (attr != FGL_ATTR_POS && ls->active_size[attr] == 0)
         save->dangling_attr_ref = true;
      for (unsigned i = 0; i < save->copied_nr; i++) {
         for (int j = 0; j < FGL_ATTR_COUNT; j++) {
            if (!save->attrsz[j])
               continue;
            if (j == (int)attr) {
               const float *src = oldsz ? data : ls->current[attr];
               const unsigned copy = oldsz ? oldsz : newsz;
               unsigned k;
               for (k = 0; k < copy; k++)
                  dest[k] = src[k];
               for (; k < newsz; k++)
                  dest[k] = k == 3 ? 1.0f : 0.0f;
               dest += newsz;
               data += oldsz;
            } else {
               const unsigned sz = save->attrsz[j];
               memcpy(dest, data, sz * sizeof(float));
               data += sz;
               dest += sz;
            }
         }
      }
      save->used += save->vertex_size * save->copied_nr;
      fgl_free(save->copied);
      save->copied = NULL;
   }
}

/* fixup_vertex */
static void fixup_vertex(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned sz)
{
   struct save_context *save = &ctx->ListState->save;
   if (sz > save->attrsz[attr]) {
      upgrade_vertex(ctx, attr, sz);
   } else if (sz < save->active_sz[attr]) {
      for (unsigned i = sz; i <= save->attrsz[attr]; i++)
         save->vertex[save->attroff[attr] + i - 1] = attr_default[i - 1];
   }
   save->active_sz[attr] = sz;
   grow_vertex_storage(ctx, 1);
}

/* reset_vertex */
static void reset_vertex(struct fgl_context *ctx)
{
   struct save_context *save = &ctx->ListState->save;
   memset(save->attrsz, 0, sizeof(save->attrsz));
   memset(save->active_sz, 0, sizeof(save->active_sz));
   save->vertex_size = 0;
}

/* ATTR_UNION of vbo_save_api.c: an attribute inside glBegin/glEnd; the
 * position stores the vertex. */
static void save_attr_vertex(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned n,
                             const float v[4])
{
   struct save_context *save = &ctx->ListState->save;
   if (save->active_sz[attr] != n)
      fixup_vertex(ctx, attr, n);
   float *dest = save->vertex + save->attroff[attr];
   for (unsigned i = 0; i < n; i++)
      dest[i] = v[i];
   if (attr == FGL_ATTR_POS) {
      if (!ensure_alloc(save, save->used + save->vertex_size))
         return;
      memcpy(save->buffer + save->used, save->vertex, save->vertex_size * sizeof(float));
      save->used += save->vertex_size;
      const unsigned used_next = (save->used + save->vertex_size) * (unsigned)sizeof(float);
      if (used_next > save->buffer_size)
         grow_vertex_storage(ctx, get_vertex_count(save));
   }
}

/* vbo_save_NotifyBegin */
static void notify_begin(struct fgl_context *ctx, GLenum mode, bool no_current_update)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   struct save_context *save = &ls->save;
   if (save->prim_used >= save->prim_size) {
      const unsigned size = save->prim_size ? save->prim_size * 2 : 8;
      struct save_prim *p = fgl_realloc_gl(ctx, save->prims, size * sizeof(*p));
      if (!p)
         return;
      save->prims = p;
      save->prim_size = size;
   }
   const unsigned i = save->prim_used++;
   ls->save_prim = mode;
   ls->opcode_fallback = false;
   save->prims[i] = (struct save_prim){
      .mode = mode, .begin = true, .start = get_vertex_count(save),
   };
   save->no_current_update = no_current_update;
   ls->save_need_flush = true;
}

/* _save_End */
static void save_end_vertex(struct fgl_context *ctx)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   struct save_context *save = &ls->save;
   const unsigned i = save->prim_used - 1;
   ls->save_prim = PRIM_OUTSIDE_BEGIN_END;
   save->prims[i].end = true;
   save->prims[i].count = get_vertex_count(save) - save->prims[i].start;
}

/* vbo_save_SaveFlushVertices */
static void save_flush_vertices(struct fgl_context *ctx)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   if (inside_save_begin_end(ls))
      return;
   if (ls->save.used || ls->save.prim_used)
      compile_vertex_list(ctx);
   save_copy_to_current(ctx);
   reset_vertex(ctx);
   ls->save_need_flush = false;
}

/* dlist_fallback: glCallList(s) inside glBegin/glEnd while compiling */
static void dlist_fallback(struct fgl_context *ctx)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   struct save_context *save = &ls->save;
   if (inside_save_begin_end(ls))
      ls->opcode_fallback = true;
   if (save->used || save->prim_used) {
      if (save->prim_used > 0 && save->used > 0) {
         const unsigned i = save->prim_used - 1;
         save->prims[i].count = get_vertex_count(save) - save->prims[i].start;
      }
      save->dangling_attr_ref = true;
      compile_vertex_list(ctx);
   }
   save_copy_to_current(ctx);
   reset_vertex(ctx);
   ls->save_need_flush = false;
}

/* ------------------------------------------------------------------ */
/* Save functions of the entry points                                  */
/* ------------------------------------------------------------------ */

void fgl_save_attr(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned n,
                   float x, float y, float z, float w)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   const float v[4] = { x, y, z, w };
   if (inside_save_begin_end(ls) && !ls->opcode_fallback) {
      save_attr_vertex(ctx, attr, n, v);
      return;
   }
   /* save_Attr32bit: a node of its own, which flushes the vertex list */
   save_flush(ctx);
   union dl_node *node = alloc_node(ctx, DL_OP_ATTR, 6);
   if (node) {
      node[1].u = attr;
      node[2].u = n;
      for (int i = 0; i < 4; i++)
         node[3 + i].f = v[i];
   }
   ls->active_size[attr] = n;
   memcpy(ls->current[attr], v, sizeof(v));
   if (ctx->ExecuteFlag)
      fgl_vbo_attr(ctx, attr, n, x, y, z, w);
}

/* save_Begin (outside glBegin/glEnd) and _save_Begin (inside) */
void fgl_save_begin(struct fgl_context *ctx, GLenum mode)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   if (inside_save_begin_end(ls)) {
      compile_error(ctx, GL_INVALID_OPERATION);   /* "Recursive glBegin" */
      return;
   }
   /* _mesa_is_valid_prim_mode: GL 1.5's ten modes (the oracle's 4.5
    * context takes everything up to GL_PATCHES) */
   if (mode > GL_POLYGON) {
      compile_error(ctx, GL_INVALID_ENUM);
      return;
   }
   notify_begin(ctx, mode, false);
}

/* _save_End inside glBegin/glEnd; save_End for a glEnd whose glBegin is
 * not in the list: a node that ends the caller's primitive */
void fgl_save_end(struct fgl_context *ctx)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   if (inside_save_begin_end(ls) && !ls->opcode_fallback) {
      save_end_vertex(ctx);
      return;
   }
   save_flush(ctx);
   fgl_dl_put_End(ctx);
   ls->save_prim = PRIM_OUTSIDE_BEGIN_END;
   ls->opcode_fallback = false;
   if (ctx->ExecuteFlag)
      fgl_exec_end(ctx);
}

/* save_Rectf [S: vbo_save_api.c]: a GL_QUADS primitive, whatever the
 * state of the compiler */
void fgl_save_rect(struct fgl_context *ctx, float x1, float y1, float x2, float y2)
{
   notify_begin(ctx, GL_QUADS, false);
   fgl_save_attr(ctx, FGL_ATTR_POS, 2, x1, y1, 0.0f, 1.0f);
   fgl_save_attr(ctx, FGL_ATTR_POS, 2, x2, y1, 0.0f, 1.0f);
   fgl_save_attr(ctx, FGL_ATTR_POS, 2, x2, y2, 0.0f, 1.0f);
   fgl_save_attr(ctx, FGL_ATTR_POS, 2, x1, y2, 0.0f, 1.0f);
   fgl_save_end(ctx);
}

/* _mesa_material_bitmask for a valid face and pname: bit i is
 * FGL_ATTR_MAT_FIRST + i */
static unsigned material_bitmask(GLenum face, GLenum pname)
{
   unsigned bits = 0;
   switch (pname) {
   case GL_EMISSION:
      bits = FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_EMISSION) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_EMISSION);
      break;
   case GL_AMBIENT:
      bits = FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_AMBIENT) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_AMBIENT);
      break;
   case GL_DIFFUSE:
      bits = FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_DIFFUSE) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_DIFFUSE);
      break;
   case GL_SPECULAR:
      bits = FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_SPECULAR) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_SPECULAR);
      break;
   case GL_SHININESS:
      bits = FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_SHININESS) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_SHININESS);
      break;
   case GL_AMBIENT_AND_DIFFUSE:
      bits = material_bitmask(GL_FRONT_AND_BACK, GL_AMBIENT) |
             material_bitmask(GL_FRONT_AND_BACK, GL_DIFFUSE);
      break;
   case GL_COLOR_INDEXES:
      bits = FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_INDEXES) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_INDEXES);
      break;
   default:
      return 0;
   }
   if (face == GL_FRONT)
      bits &= FGL_MAT_BITS_FRONT;
   else if (face == GL_BACK)
      bits &= FGL_MAT_BITS_BACK;
   return bits;
}

/* glMaterialfv while compiling: inside glBegin/glEnd the material
 * attributes of the vertex [S: vbo_save_api.c:_save_Materialfv], outside
 * (or after dlist_fallback) a MATERIAL node [S: dlist.c:save_Materialfv], which executes first and
 * is left out when it sets what the compiler knows to be set. */
void fgl_save_material(struct fgl_context *ctx, GLenum face, GLenum pname,
                       const GLfloat *params)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) {
      compile_error(ctx, GL_INVALID_ENUM);
      return;
   }
   /* GL_FIXGL_cook_torrance's pnames are lighting state, not vertex
    * attributes (include/fixgl/shading.md): refused between glBegin and
    * glEnd like glShadeModel, else a MATERIAL node that executes first;
    * their value errors come when the node executes */
   if (pname == GL_REFLECTANCE_MODEL_FIXGL || pname == GL_ROUGHNESS_FIXGL ||
       pname == GL_METALNESS_FIXGL || pname == GL_DIELECTRIC_F0_FIXGL) {
      if (inside_save_begin_end(ls)) {
         compile_error(ctx, GL_INVALID_OPERATION);
         return;
      }
      if (ctx->ExecuteFlag) {
         ctx->CompileFlag = false;
         glMaterialfv(face, pname, params);
         ctx->CompileFlag = true;
      }
      save_flush(ctx);
      fgl_dl_put_Materialfv(ctx, face, pname, params, 1);
      return;
   }
   /* after a glEvalCoord or glCallList ended the vertex list
    * (opcode_fallback), the vertex format is gone: a MATERIAL node */
   if (inside_save_begin_end(ls) && !ls->opcode_fallback) {
      /* MAT(): front, then back, each with its size */
      static const struct { GLenum pname; enum fgl_vbo_attr front; unsigned n; } mats[] = {
         { GL_EMISSION, FGL_ATTR_MAT_FRONT_EMISSION, 4 },
         { GL_AMBIENT, FGL_ATTR_MAT_FRONT_AMBIENT, 4 },
         { GL_DIFFUSE, FGL_ATTR_MAT_FRONT_DIFFUSE, 4 },
         { GL_SPECULAR, FGL_ATTR_MAT_FRONT_SPECULAR, 4 },
         { GL_SHININESS, FGL_ATTR_MAT_FRONT_SHININESS, 1 },
         { GL_COLOR_INDEXES, FGL_ATTR_MAT_FRONT_INDEXES, 3 },
         { GL_AMBIENT_AND_DIFFUSE, FGL_ATTR_MAT_FRONT_AMBIENT, 4 },
         { GL_AMBIENT_AND_DIFFUSE, FGL_ATTR_MAT_FRONT_DIFFUSE, 4 },
      };
      bool known = false;
      if (pname == GL_SHININESS && (params[0] < 0.0f || params[0] > 128.0f)) {
         compile_error(ctx, GL_INVALID_VALUE);
         return;
      }
      for (unsigned i = 0; i < sizeof(mats) / sizeof(mats[0]); i++) {
         if (mats[i].pname != pname)
            continue;
         known = true;
         float v[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
         for (unsigned c = 0; c < mats[i].n; c++)
            v[c] = params[c];
         if (face != GL_BACK)
            save_attr_vertex(ctx, mats[i].front, mats[i].n, v);
         if (face != GL_FRONT)
            save_attr_vertex(ctx, (enum fgl_vbo_attr)(mats[i].front + 1), mats[i].n, v);
      }
      if (!known)
         compile_error(ctx, GL_INVALID_ENUM);
      return;
   }

   unsigned args;
   switch (pname) {
   case GL_EMISSION:
   case GL_AMBIENT:
   case GL_DIFFUSE:
   case GL_SPECULAR:
   case GL_AMBIENT_AND_DIFFUSE:
      args = 4;
      break;
   case GL_SHININESS:
      args = 1;
      break;
   case GL_COLOR_INDEXES:
      args = 3;
      break;
   default:
      compile_error(ctx, GL_INVALID_ENUM);
      return;
   }
   /* CALL_Materialfv(ctx->Exec): the entry point without its hook */
   if (ctx->ExecuteFlag) {
      ctx->CompileFlag = false;
      glMaterialfv(face, pname, params);
      ctx->CompileFlag = true;
   }
   unsigned bitmask = material_bitmask(face, pname);
   for (int i = 0; i < FGL_ATTR_COUNT - FGL_ATTR_MAT_FIRST; i++) {
      if (!(bitmask & (1u << i)))
         continue;
      const int a = FGL_ATTR_MAT_FIRST + i;
      if (ls->active_size[a] == args &&
          memcmp(ls->current[a], params, args * sizeof(float)) == 0) {
         bitmask &= ~(1u << i);
      } else {
         ls->active_size[a] = args;
         memcpy(ls->current[a], params, args * sizeof(float));   /* COPY_SZ_4V */
      }
   }
   if (bitmask == 0)
      return;
   save_flush(ctx);
   fgl_dl_put_Materialfv(ctx, face, pname, params, args);
}

/* save_ShadeModel: executes first; a repeated mode is not compiled */
void fgl_save_shade_model(struct fgl_context *ctx, GLenum mode)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   if (inside_save_begin_end(ls)) {
      compile_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (ctx->ExecuteFlag) {
      ctx->CompileFlag = false;
      glShadeModel(mode);
      ctx->CompileFlag = true;
   }
   if (ls->shade_model == mode)
      return;
   save_flush(ctx);
   ls->shade_model = mode;
   fgl_dl_put_ShadeModel(ctx, mode);
}

/* save_DrawArrays: the arrays are read now, through glArrayElement, into
 * a primitive of the vertex list that does not update the current values */
void fgl_save_draw_arrays(struct fgl_context *ctx, GLenum mode, GLint first, GLsizei count)
{
   if (mode > GL_POLYGON) {
      compile_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (count < 0) {
      compile_error(ctx, GL_INVALID_VALUE);
      return;
   }
   grow_vertex_storage(ctx, (unsigned)count);
   notify_begin(ctx, mode, true);
   for (GLsizei i = 0; i < count; i++)   /* start + i, wrapping */
      t_array_element(ctx, (GLint)((GLuint)first + (GLuint)i));
   fgl_save_end(ctx);
}

/* The sum of a multi-draw's counts as Mesa's int accumulates it (wrapping),
 * and the vertex storage grown for it when it is not negative
 * [S: vbo/vbo_save_api.c:_save_OBE_MultiDrawArrays, grow_vertex_storage's
 * int arithmetic] */
static void grow_for_counts(struct fgl_context *ctx, const GLsizei *count, GLsizei n)
{
   uint32_t sum = 0;
   for (GLsizei i = 0; i < n; i++)
      sum += (uint32_t)count[i];
   if ((int32_t)sum >= 0)
      grow_vertex_storage(ctx, sum);
}

/* glMultiDrawArrays while compiling [S: vbo/vbo_save_api.c:
 * _save_OBE_MultiDrawArrays]: the storage for every count, then the mode,
 * the draw count and each count checked, then a glDrawArrays of each
 * non-empty draw */
void fgl_save_multi_draw_arrays(struct fgl_context *ctx, GLenum mode, const GLint *first,
                                const GLsizei *count, GLsizei n)
{
   if (n > 0)
      grow_for_counts(ctx, count, n);
   if (mode > GL_POLYGON) {
      compile_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (n < 0) {
      compile_error(ctx, GL_INVALID_VALUE);
      return;
   }
   for (GLsizei i = 0; i < n; i++) {
      if (count[i] < 0) {
         compile_error(ctx, GL_INVALID_VALUE);
         return;
      }
   }
   for (GLsizei i = 0; i < n; i++)
      if (count[i] > 0)
         fgl_save_draw_arrays(ctx, mode, first[i], count[i]);
}

/* glMultiDrawElements while compiling [S: vbo/vbo_save_api.c:
 * _save_OBE_MultiDrawElements]: no checks of its own, a compiled
 * glDrawElements of each non-empty draw */
void fgl_save_multi_draw_elements(struct fgl_context *ctx, GLenum mode, const GLsizei *count,
                                  GLenum type, const GLvoid *const *indices, GLsizei n)
{
   if (n <= 0)
      return;
   grow_for_counts(ctx, count, n);
   for (GLsizei i = 0; i < n; i++)
      if (count[i] > 0)
         fgl_save_draw_elements(ctx, mode, count[i], type, indices[i]);
}

void fgl_save_draw_elements(struct fgl_context *ctx, GLenum mode, GLsizei count,
                            GLenum type, const GLvoid *indices)
{
   if (mode > GL_POLYGON) {
      compile_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (count < 0) {
      compile_error(ctx, GL_INVALID_VALUE);
      return;
   }
   /* save_DrawElementsBaseVertex raises GL_INVALID_VALUE for a bad type
    * (its message says count < 0) */
   if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) {
      compile_error(ctx, GL_INVALID_VALUE);
      return;
   }
   grow_vertex_storage(ctx, (unsigned)count);
   notify_begin(ctx, mode, true);
   const struct fgl_buffer_object *ebo = ctx->Array.ElementBufferObj;
   if (ebo) {
      /* the element buffer's store from the offset (mapped by the oracle,
       * _mesa_vao_map, any alignment); an index outside it reads 0 here */
      const uint64_t isize = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4;
      for (GLsizei i = 0; i < count; i++) {
         const uint64_t at = (uint64_t)(uintptr_t)indices + (uint64_t)i * isize;
         const bool in = ebo->Data && at + isize <= (uint64_t)ebo->Size;
         t_array_element(ctx, in ? (GLint)t_index_at(type, ebo->Data + at, 0) : 0);
      }
   } else {
      for (GLsizei i = 0; i < count && indices; i++)
         t_array_element(ctx, (GLint)t_index_at(type, indices, i));
   }
   fgl_save_end(ctx);
}

void fgl_save_draw_range_elements(struct fgl_context *ctx, GLenum mode, GLuint start,
                                  GLuint end, GLsizei count, GLenum type,
                                  const GLvoid *indices)
{
   if (mode > GL_POLYGON) {
      compile_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (count < 0) {
      compile_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) {
      compile_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (end < start) {
      compile_error(ctx, GL_INVALID_VALUE);
      return;
   }
   fgl_save_draw_elements(ctx, mode, count, type, indices);
}

static void exec_call_lists(struct fgl_context *ctx, GLsizei n, GLenum type, const GLvoid *lists);
static void locked_call_list(struct fgl_context *ctx, GLuint list);
static void locked_call_lists(struct fgl_context *ctx, GLsizei n, GLenum type,
                              const GLvoid *lists);

/* save_CallList (after _save_CallList's fallback inside glBegin/glEnd) */
void fgl_save_call_list(struct fgl_context *ctx, GLuint list)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   if (inside_save_begin_end(ls))
      dlist_fallback(ctx);
   save_flush(ctx);
   union dl_node *n = alloc_node(ctx, DL_OP_CALL_LIST, 1);
   if (n)
      n[1].u = list;
   invalidate_saved_current_state(ctx);
   if (ctx->ExecuteFlag)
      locked_call_list(ctx, list);
}

static unsigned call_lists_type_size(GLenum type)
{
   switch (type) {
   case GL_BYTE:
   case GL_UNSIGNED_BYTE:
      return 1;
   case GL_SHORT:
   case GL_UNSIGNED_SHORT:
   case GL_2_BYTES:
      return 2;
   case GL_3_BYTES:
      return 3;
   case GL_INT:
   case GL_UNSIGNED_INT:
   case GL_FLOAT:
   case GL_4_BYTES:
      return 4;
   default:
      return 0;
   }
}

/* save_Map1f, save_Map1d [S: main/dlist.c]: the points as
 * _mesa_copy_map_points1{f,d} copies them (packed floats; none for a bad
 * target or no points), replayed with the packed stride; the arguments
 * are validated when the list executes.  fixgl keeps the points in the
 * node itself; an order out of range stores none (the replay fails on the
 * order before it looks at the points). */
bool fgl_save_map1(struct fgl_context *ctx, GLenum target, GLfloat u1, GLfloat u2,
                   GLint stride, GLint order, const GLfloat *pf, const GLdouble *pd)
{
   if (!save_prologue(ctx))
      return false;
   const int k = (int)fgl_eval_components(target);
   const unsigned cnt = (pf || pd) && k && order >= 1 && order <= FGL_MAX_EVAL_ORDER ?
                        (unsigned)(order * k) : 0;
   union dl_node *n = alloc_node(ctx, DL_OP_MAP1, 6 + cnt);
   if (n) {
      n[1].e = target;
      n[2].f = u1;
      n[3].f = u2;
      n[4].i = k;            /* stride */
      n[5].i = order;
      n[6].u = cnt;
      /* a negative stride (an error when the call executes, but the
       * node has its own stride) would read before the caller's points,
       * as the oracle does: zeros instead */
      float *p = &n[7].f;
      for (int i = 0; cnt && i < order; i++)
         for (int c = 0; c < k; c++)
            *p++ = stride < 0 ? 0.0f
                   : pf ? pf[(size_t)i * (size_t)stride + (size_t)c]
                        : (float)pd[(size_t)i * (size_t)stride + (size_t)c];
   }
   return ctx->ExecuteFlag;
}

/* save_Map2f, save_Map2d: ustride = components * vorder, vstride =
 * components */
bool fgl_save_map2(struct fgl_context *ctx, GLenum target, GLfloat u1, GLfloat u2,
                   GLint ustride, GLint uorder, GLfloat v1, GLfloat v2, GLint vstride,
                   GLint vorder, const GLfloat *pf, const GLdouble *pd)
{
   if (!save_prologue(ctx))
      return false;
   const int k = (int)fgl_eval_components(target);
   const bool ok = (pf || pd) && k && uorder >= 1 && uorder <= FGL_MAX_EVAL_ORDER &&
                   vorder >= 1 && vorder <= FGL_MAX_EVAL_ORDER;
   const unsigned cnt = ok ? (unsigned)(uorder * vorder * k) : 0;
   union dl_node *n = alloc_node(ctx, DL_OP_MAP2, 10 + cnt);
   if (n) {
      n[1].e = target;
      n[2].f = u1;
      n[3].f = u2;
      n[4].f = v1;
      n[5].f = v2;
      /* ustride; k * vorder wraps as Mesa's int product does on x86 for
       * an order the replay rejects again */
      n[6].i = (GLint)((unsigned)k * (unsigned)vorder);
      n[7].i = k;            /* vstride */
      n[8].i = uorder;
      n[9].i = vorder;
      n[10].u = cnt;
      /* negative strides: zeros, as in fgl_save_map1 */
      const bool before = ustride < 0 || vstride < 0;
      float *p = &n[11].f;
      for (int i = 0; cnt && i < uorder; i++)
         for (int j = 0; j < vorder; j++) {
            const size_t o = before ? 0 : (size_t)i * (size_t)ustride + (size_t)j * (size_t)vstride;
            for (int c = 0; c < k; c++)
               *p++ = before ? 0.0f : pf ? pf[o + (size_t)c] : (float)pd[o + (size_t)c];
         }
   }
   return ctx->ExecuteFlag;
}

/* glEvalCoord and glEvalPoint: inside glBegin/glEnd _save_EvalCoord1f
 * etc. [S: vbo/vbo_save_api.c] end the vertex list being compiled
 * (dlist_fallback), then save_EvalCoord1f etc. [S: main/dlist.c] store a
 * node of their own */
static bool save_eval(struct fgl_context *ctx, enum dl_opcode op, union dl_node a,
                      union dl_node b, unsigned args)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   if (inside_save_begin_end(ls))
      dlist_fallback(ctx);
   save_flush(ctx);
   union dl_node *n = alloc_node(ctx, op, args);
   if (n) {
      n[1] = a;
      if (args > 1)
         n[2] = b;
   }
   return ctx->ExecuteFlag;
}

/* [S: dlist.c:save_PrioritizeTextures] the begin/end check comes first,
 * once, whatever n is (a negative n inside glBegin/glEnd is
 * GL_INVALID_OPERATION, not GL_INVALID_VALUE; probe p_prioritize_inside);
 * then a node per name, replayed as a call with n = 1 */
bool fgl_save_prioritize_textures(struct fgl_context *ctx, GLsizei n, const GLuint *textures,
                                  const GLclampf *priorities)
{
   if (!save_prologue(ctx))
      return false;
   for (GLsizei i = 0; i < n && textures && priorities; i++)
      fgl_dl_put_PrioritizeTexture1(ctx, textures[i], priorities[i]);
   return ctx->ExecuteFlag;
}

bool fgl_save_eval_coord1(struct fgl_context *ctx, GLfloat u)
{
   return save_eval(ctx, DL_OP_EVAL_C1, (union dl_node){ .f = u }, (union dl_node){ .u = 0 }, 1);
}

bool fgl_save_eval_coord2(struct fgl_context *ctx, GLfloat u, GLfloat v)
{
   return save_eval(ctx, DL_OP_EVAL_C2, (union dl_node){ .f = u }, (union dl_node){ .f = v }, 2);
}

bool fgl_save_eval_point1(struct fgl_context *ctx, GLint i)
{
   return save_eval(ctx, DL_OP_EVAL_P1, (union dl_node){ .i = i }, (union dl_node){ .u = 0 }, 1);
}

bool fgl_save_eval_point2(struct fgl_context *ctx, GLint i, GLint j)
{
   return save_eval(ctx, DL_OP_EVAL_P2, (union dl_node){ .i = i }, (union dl_node){ .i = j }, 2);
}

/* save_CallLists: the names are copied, validated when executed */
void fgl_save_call_lists(struct fgl_context *ctx, GLsizei num, GLenum type, const GLvoid *lists)
{
   struct fgl_dlist_state *ls = ctx->ListState;
   if (inside_save_begin_end(ls))
      dlist_fallback(ctx);
   save_flush(ctx);
   const unsigned type_size = call_lists_type_size(type);
   void *copy = NULL;
   if (num > 0 && type_size > 0 && lists) {
      copy = fgl_malloc_gl(ctx, (size_t)num * type_size);
      if (copy)
         memcpy(copy, lists, (size_t)num * type_size);
   }
   union dl_node *n = alloc_node(ctx, DL_OP_CALL_LISTS, 2 + PTR_NODES);
   if (n) {
      n[1].i = num;
      n[2].e = type;
      put_pointer(&n[3], copy);
   } else {
      fgl_free(copy);
   }
   invalidate_saved_current_state(ctx);
   if (ctx->ExecuteFlag)
      locked_call_lists(ctx, num, type, lists);
}

/* ------------------------------------------------------------------ */
/* Texture images                                                      */
/* ------------------------------------------------------------------ */

/* bytes of one component of `type` (packed types: the whole pixel) */
static size_t image_comp_bytes(GLenum type)
{
   switch (type) {
   case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_BYTE_3_3_2:
   case GL_UNSIGNED_BYTE_2_3_3_REV:
      return 1;
   case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_HALF_FLOAT:
   case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV:
   case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
   case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV:
      return 2;
   default:
      return 4;
   }
}

/* [S: dlist.c:unpack_image, pack.c:_mesa_unpack_image] a copy of the
 * client image in Mesa's default packing (tight rows, alignment 1, bytes
 * swapped as the unpack state asks); NULL for NULL data, an empty image
 * or a format/type without a pixel size */
static void *copy_client_image(struct fgl_context *ctx, GLsizei width, GLsizei height,
                               GLenum format, GLenum type, const void *pixels)
{
   if (!pixels || width <= 0 || height <= 0)
      return NULL;
   if (type == GL_BITMAP) {
      /* [S: pack.c:_mesa_unpack_bitmap] rows of whole bytes, most
       * significant bit first, skips and bit order applied */
      const size_t row_bytes = ((size_t)width + 7) / 8;
      uint8_t *image = fgl_calloc_gl(ctx, row_bytes * (size_t)height, 1);
      if (!image) {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return NULL;
      }
      const unsigned skip = (unsigned)ctx->Unpack.SkipPixels & 7u;
      for (GLsizei row = 0; row < height; row++) {
         const uint8_t *src = fgl_image_address(&ctx->Unpack, pixels, width, format, type,
                                                row, 0);
         uint8_t *dst = image + (size_t)row * row_bytes;
         for (GLsizei col = 0; col < width; col++) {
            const size_t bit = skip + (size_t)col;
            const unsigned b = ctx->Unpack.LsbFirst ? (src[bit / 8] >> (bit % 8)) & 1u
                                                    : (src[bit / 8] >> (7 - bit % 8)) & 1u;
            if (b)
               dst[col / 8] |= (uint8_t)(0x80u >> (col % 8));
         }
      }
      return image;
   }
   const size_t bpp = fgl_pixel_bytes(format, type);
   if (bpp == 0)
      return NULL;
   const size_t row_bytes = bpp * (size_t)width;
   uint8_t *image = fgl_malloc_gl(ctx, row_bytes * (size_t)height);
   if (!image) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return NULL;
   }
   const size_t cb = image_comp_bytes(type);
   const bool swap = ctx->Unpack.SwapBytes && (cb == 2 || cb == 4);
   for (GLsizei row = 0; row < height; row++) {
      const uint8_t *src = fgl_image_address(&ctx->Unpack, pixels, width, format, type,
                                             row, 0);
      uint8_t *dst = image + (size_t)row * row_bytes;
      memcpy(dst, src, row_bytes);
      if (swap)
         for (size_t k = 0; k + cb <= row_bytes; k += cb)
            for (size_t a = 0, b = cb - 1; a < b; a++, b--) {
               const uint8_t t = dst[k + a];
               dst[k + a] = dst[k + b];
               dst[k + b] = t;
            }
   }
   return image;
}

/* save_TexImage1D/2D: a proxy target executes at once (no node);
 * otherwise the image is copied into the node */
bool fgl_save_tex_image(struct fgl_context *ctx, GLuint dims, GLenum target, GLint level,
                        GLint internal, GLsizei width, GLsizei height, GLint border,
                        GLenum format, GLenum type, const void *pixels)
{
   if (target == (dims == 1 ? GL_PROXY_TEXTURE_1D : GL_PROXY_TEXTURE_2D))
      return true;
   if (!save_prologue(ctx))
      return false;
   union dl_node *n = alloc_node(ctx, DL_OP_TEX_IMAGE, 9 + PTR_NODES);
   if (n) {
      n[1].u = dims;
      n[2].e = target;
      n[3].i = level;
      n[4].i = internal;
      n[5].i = width;
      n[6].i = height;
      n[7].i = border;
      n[8].e = format;
      n[9].e = type;
      put_pointer(&n[10], copy_client_image(ctx, width, height, format, type, pixels));
   }
   return ctx->ExecuteFlag;
}

/* save_TexSubImage1D/2D */
bool fgl_save_tex_sub_image(struct fgl_context *ctx, GLuint dims, GLenum target, GLint level,
                            GLint xoffset, GLint yoffset, GLsizei width, GLsizei height,
                            GLenum format, GLenum type, const void *pixels)
{
   if (!save_prologue(ctx))
      return false;
   union dl_node *n = alloc_node(ctx, DL_OP_TEX_SUB_IMAGE, 9 + PTR_NODES);
   if (n) {
      n[1].u = dims;
      n[2].e = target;
      n[3].i = level;
      n[4].i = xoffset;
      n[5].i = yoffset;
      n[6].i = width;
      n[7].i = height;
      n[8].e = format;
      n[9].e = type;
      put_pointer(&n[10], copy_client_image(ctx, width, height, format, type, pixels));
   }
   return ctx->ExecuteFlag;
}

/* save_CopyTexImage1D/2D (height 1 and no slot for 1D) */
bool fgl_save_copy_tex_image(struct fgl_context *ctx, GLuint dims, GLenum target,
                             GLint level, GLenum internal, GLint x, GLint y, GLsizei width,
                             GLsizei height, GLint border)
{
   if (!save_prologue(ctx))
      return false;
   union dl_node *n = alloc_node(ctx, DL_OP_COPY_TEX_IMAGE, 9);
   if (n) {
      n[1].u = dims;
      n[2].e = target;
      n[3].i = level;
      n[4].e = internal;
      n[5].i = x;
      n[6].i = y;
      n[7].i = width;
      n[8].i = height;
      n[9].i = border;
   }
   return ctx->ExecuteFlag;
}

/* save_CopyTexSubImage1D/2D */
bool fgl_save_copy_tex_sub_image(struct fgl_context *ctx, GLuint dims, GLenum target,
                                 GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y,
                                 GLsizei width, GLsizei height)
{
   if (!save_prologue(ctx))
      return false;
   union dl_node *n = alloc_node(ctx, DL_OP_COPY_TEX_SUB_IMAGE, 9);
   if (n) {
      n[1].u = dims;
      n[2].e = target;
      n[3].i = level;
      n[4].i = xoffset;
      n[5].i = yoffset;
      n[6].i = x;
      n[7].i = y;
      n[8].i = width;
      n[9].i = height;
   }
   return ctx->ExecuteFlag;
}

/* [S: dlist.c:unpack_image with three dimensions] a w x h x d client
 * image in the default packing, slice after slice; NULL as
 * copy_client_image.  unpack_image checks the width and height only, and
 * _mesa_unpack_image returns NULL for a depth <= 0, which its caller
 * takes for a failed allocation: GL_OUT_OF_MEMORY when the data pointer
 * is not NULL (ORACLE-NOTES.md "Display lists", fuzzer seed 1000447) */
static void *copy_client_image_3d(struct fgl_context *ctx, GLsizei width, GLsizei height,
                                  GLsizei depth, GLenum format, GLenum type,
                                  const void *pixels)
{
   if (!pixels || width <= 0 || height <= 0 || type == GL_BITMAP)
      return NULL;
   const size_t bpp = fgl_pixel_bytes(format, type);
   if (bpp == 0)
      return NULL;
   if (depth <= 0) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return NULL;
   }
   const size_t slice_bytes = bpp * (size_t)width * (size_t)height;
   uint8_t *image = fgl_malloc_gl(ctx, slice_bytes * (size_t)depth);
   if (!image) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return NULL;
   }
   /* each slice is a 2D image at its slice's address (image.c:
    * _mesa_image_offset), copied by copy_client_image */
   const struct fgl_pixelstore save = ctx->Unpack;
   const size_t rows = (size_t)(save.ImageHeight > 0 ? save.ImageHeight : height);
   const size_t stride = fgl_image_row_stride(&save, width, format, type);
   bool ok = true;
   for (GLsizei k = 0; k < depth && ok; k++) {
      const uint8_t *src =
         (const uint8_t *)pixels + ((size_t)save.SkipImages + (size_t)k) * rows * stride;
      uint8_t *slice = copy_client_image(ctx, width, height, format, type, src);
      if (slice) {
         memcpy(image + (size_t)k * slice_bytes, slice, slice_bytes);
         fgl_free(slice);
      } else {
         ok = false;
      }
   }
   if (!ok) {
      fgl_free(image);
      return NULL;
   }
   return image;
}

/* save_TexImage3D: as fgl_save_tex_image */
bool fgl_save_tex_image_3d(struct fgl_context *ctx, GLenum target, GLint level,
                           GLint internal, GLsizei width, GLsizei height, GLsizei depth,
                           GLint border, GLenum format, GLenum type, const void *pixels)
{
   if (target == GL_PROXY_TEXTURE_3D)
      return true;
   if (!save_prologue(ctx))
      return false;
   union dl_node *n = alloc_node(ctx, DL_OP_TEX_IMAGE_3D, 9 + PTR_NODES);
   if (n) {
      n[1].e = target;
      n[2].i = level;
      n[3].i = internal;
      n[4].i = width;
      n[5].i = height;
      n[6].i = depth;
      n[7].i = border;
      n[8].e = format;
      n[9].e = type;
      put_pointer(&n[10],
                  copy_client_image_3d(ctx, width, height, depth, format, type, pixels));
   }
   return ctx->ExecuteFlag;
}

/* save_TexSubImage3D */
bool fgl_save_tex_sub_image_3d(struct fgl_context *ctx, GLenum target, GLint level,
                               GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width,
                               GLsizei height, GLsizei depth, GLenum format, GLenum type,
                               const void *pixels)
{
   if (!save_prologue(ctx))
      return false;
   union dl_node *n = alloc_node(ctx, DL_OP_TEX_SUB_IMAGE_3D, 10 + PTR_NODES);
   if (n) {
      n[1].e = target;
      n[2].i = level;
      n[3].i = xoffset;
      n[4].i = yoffset;
      n[5].i = zoffset;
      n[6].i = width;
      n[7].i = height;
      n[8].i = depth;
      n[9].e = format;
      n[10].e = type;
      put_pointer(&n[11],
                  copy_client_image_3d(ctx, width, height, depth, format, type, pixels));
   }
   return ctx->ExecuteFlag;
}

/* save_CopyTexSubImage3D */
bool fgl_save_copy_tex_sub_image_3d(struct fgl_context *ctx, GLenum target, GLint level,
                                    GLint xoffset, GLint yoffset, GLint zoffset, GLint x,
                                    GLint y, GLsizei width, GLsizei height)
{
   if (!save_prologue(ctx))
      return false;
   union dl_node *n = alloc_node(ctx, DL_OP_COPY_TEX_SUB_IMAGE_3D, 9);
   if (n) {
      n[1].e = target;
      n[2].i = level;
      n[3].i = xoffset;
      n[4].i = yoffset;
      n[5].i = zoffset;
      n[6].i = x;
      n[7].i = y;
      n[8].i = width;
      n[9].i = height;
   }
   return ctx->ExecuteFlag;
}

/* [S: dlist.c:save_CompressedTexImage1D/2D/3DARB,
 * save_CompressedTexSubImage*DARB, copy_data] an image on the command's
 * proxy target is not compiled (executed at once); every other call is, with a copy of
 * imageSize bytes of the data made before any check (a negative size is
 * the malloc that fails: GL_OUT_OF_MEMORY, no copy) */
bool fgl_save_compressed_tex(struct fgl_context *ctx, GLuint dims, bool sub, GLenum target,
                             GLint level, GLenum format, GLint x, GLint y, GLint z, GLsizei w,
                             GLsizei h, GLsizei d, GLint border, GLsizei image_size,
                             const void *data)
{
   /* each command's own proxy only (a 3D call on GL_PROXY_TEXTURE_2D is
    * compiled; fuzzer seeds 46 and 127) */
   if (!sub && target == (dims == 1   ? GL_PROXY_TEXTURE_1D
                          : dims == 2 ? GL_PROXY_TEXTURE_2D
                                      : GL_PROXY_TEXTURE_3D))
      return true;
   if (!save_prologue(ctx))
      return false;
   union dl_node *n = alloc_node(ctx, DL_OP_COMPRESSED_TEX, 12 + PTR_NODES);
   if (n) {
      n[1].u = dims | (sub ? 16u : 0u);
      n[2].e = target;
      n[3].i = level;
      n[4].e = format;
      n[5].i = x;
      n[6].i = y;
      n[7].i = z;
      n[8].i = w;
      n[9].i = h;
      n[10].i = d;
      n[11].i = border;
      n[12].i = image_size;
      void *copy = NULL;
      if (data) {
         copy = image_size >= 0 ? fgl_malloc_gl(ctx, image_size ? (size_t)image_size : 1)
                                : NULL;
         if (copy)
            memcpy(copy, data, (size_t)image_size);
         else
            fgl_error(ctx, GL_OUT_OF_MEMORY);
      }
      put_pointer(&n[13], copy);
   }
   return ctx->ExecuteFlag;
}

static void exec_compressed_tex_node(const union dl_node *n)
{
   const GLuint dims = n[1].u & 15u;
   const void *data = get_pointer(&n[13]);
   if (n[1].u & 16u) {
      if (dims == 1)
         glCompressedTexSubImage1D(n[2].e, n[3].i, n[5].i, n[8].i, n[4].e, n[12].i, data);
      else if (dims == 2)
         glCompressedTexSubImage2D(n[2].e, n[3].i, n[5].i, n[6].i, n[8].i, n[9].i, n[4].e,
                                   n[12].i, data);
      else
         glCompressedTexSubImage3D(n[2].e, n[3].i, n[5].i, n[6].i, n[7].i, n[8].i, n[9].i,
                                   n[10].i, n[4].e, n[12].i, data);
   } else if (dims == 1) {
      glCompressedTexImage1D(n[2].e, n[3].i, n[4].e, n[8].i, n[11].i, n[12].i, data);
   } else if (dims == 2) {
      glCompressedTexImage2D(n[2].e, n[3].i, n[4].e, n[8].i, n[9].i, n[11].i, n[12].i, data);
   } else {
      glCompressedTexImage3D(n[2].e, n[3].i, n[4].e, n[8].i, n[9].i, n[10].i, n[11].i,
                             n[12].i, data);
   }
}

/* OPCODE_TEX_IMAGE3D / OPCODE_TEX_SUB_IMAGE3D: the stored image under
 * ctx->DefaultPacking */
static void exec_tex_image_3d_node(struct fgl_context *ctx, const union dl_node *n)
{
   const struct fgl_pixelstore save = ctx->Unpack;
   ctx->Unpack = (struct fgl_pixelstore){ .Alignment = 1 };
   if (n->h.op == DL_OP_TEX_IMAGE_3D)
      glTexImage3D(n[1].e, n[2].i, n[3].i, n[4].i, n[5].i, n[6].i, n[7].i, n[8].e, n[9].e,
                   get_pointer(&n[10]));
   else
      glTexSubImage3D(n[1].e, n[2].i, n[3].i, n[4].i, n[5].i, n[6].i, n[7].i, n[8].i,
                      n[9].e, n[10].e, get_pointer(&n[11]));
   ctx->Unpack = save;
}

/* OPCODE_TEX_IMAGE*D / OPCODE_TEX_SUB_IMAGE*D: the stored image under
 * ctx->DefaultPacking */
static void exec_tex_image_node(struct fgl_context *ctx, const union dl_node *n)
{
   const struct fgl_pixelstore save = ctx->Unpack;
   ctx->Unpack = (struct fgl_pixelstore){ .Alignment = 1 };
   const void *image = get_pointer(&n[10]);
   if (n->h.op == DL_OP_TEX_IMAGE) {
      if (n[1].u == 1)
         glTexImage1D(n[2].e, n[3].i, n[4].i, n[5].i, n[7].i, n[8].e, n[9].e, image);
      else
         glTexImage2D(n[2].e, n[3].i, n[4].i, n[5].i, n[6].i, n[7].i, n[8].e, n[9].e, image);
   } else {
      if (n[1].u == 1)
         glTexSubImage1D(n[2].e, n[3].i, n[4].i, n[6].i, n[8].e, n[9].e, image);
      else
         glTexSubImage2D(n[2].e, n[3].i, n[4].i, n[5].i, n[6].i, n[7].i, n[8].e, n[9].e,
                         image);
   }
   ctx->Unpack = save;
}

/* ------------------------------------------------------------------ */
/* Execution                                                           */
/* ------------------------------------------------------------------ */

/* _vbo_loopback_vertex_list: the primitives as immediate-mode calls, the
 * materials first, then the other attributes, the position last; a
 * continued primitive skips its copied vertices.  base: vertex 0 of the
 * primitives' starts (size bytes readable; Mesa reads past it, the
 * vertices past it are zeros here). */
static void loopback_vertex_list(struct fgl_context *ctx, const struct vertex_list *vl,
                                 const uint8_t *base, size_t size)
{
   unsigned order[FGL_ATTR_COUNT], offset[FGL_ATTR_COUNT], nr = 0;
   unsigned off[FGL_ATTR_COUNT], o = 0;
   for (int a = 0; a < FGL_ATTR_COUNT; a++) {
      off[a] = o;
      o += vl->attrsz[a];
   }
   for (int a = FGL_ATTR_MAT_FIRST; a < FGL_ATTR_COUNT; a++)
      if (vl->attrsz[a])
         order[nr] = (unsigned)a, offset[nr++] = off[a];
   for (int a = FGL_ATTR_POS + 1; a < FGL_ATTR_MAT_FIRST; a++)
      if (vl->attrsz[a])
         order[nr] = (unsigned)a, offset[nr++] = off[a];
   if (vl->attrsz[FGL_ATTR_POS])
      order[nr] = FGL_ATTR_POS, offset[nr++] = off[FGL_ATTR_POS];

   const size_t stride = (size_t)vl->vertex_size * sizeof(float);
   float *data = fgl_malloc_gl(ctx, stride ? stride : 1);
   if (!data)
      return;
   for (unsigned p = 0; p < vl->prim_count; p++) {
      const struct save_prim *prim = &vl->prims[p];
      unsigned start = prim->start;
      const unsigned end = start + prim->count;
      if (prim->begin)
         fgl_exec_begin(ctx, prim->mode);
      else
         start += vl->wrap_count;
      for (unsigned j = start; j < end; j++) {
         const size_t at = (size_t)j * stride;
         memset(data, 0, stride);
         if (at < size)
            memcpy(data, base + at, size - at < stride ? size - at : stride);
         for (unsigned k = 0; k < nr; k++) {
            const enum fgl_vbo_attr a = (enum fgl_vbo_attr)order[k];
            const unsigned sz = vl->attrsz[a];
            const float *v = data + offset[k];
            fgl_vbo_attr(ctx, a, sz, v[0], sz > 1 ? v[1] : 0.0f, sz > 2 ? v[2] : 0.0f,
                         sz > 3 ? v[3] : 1.0f);
         }
      }
      if (prim->end)
         fgl_exec_end(ctx);
   }
   fgl_free(data);
}

/* playback_copy_to_current */
static void playback_copy_to_current(struct fgl_context *ctx, const struct vertex_list *vl)
{
   if (!vl->current_data)
      return;
   const float *data = vl->current_data;
   bool color0_changed = false;
   for (int a = FGL_ATTR_POS + 1; a < FGL_ATTR_COUNT; a++) {
      const unsigned sz = vl->attrsz[a];
      if (!sz)
         continue;
      float tmp[4];
      for (unsigned c = 0; c < 4; c++)
         tmp[c] = c < sz ? data[c] : attr_default[c];
      if (memcmp(ctx->Current.Attrib[a], tmp, sizeof(tmp)) != 0) {
         memcpy(ctx->Current.Attrib[a], tmp, sizeof(tmp));
         if (a == FGL_ATTR_COLOR0)
            color0_changed = true;
         ctx->PopAttribState |= a >= FGL_ATTR_MAT_FIRST ? GL_LIGHTING_BIT : GL_CURRENT_BIT;
      }
      data += sz;
   }
   if (color0_changed && ctx->Light.ColorMaterialEnabled)
      fgl_update_color_material(ctx, ctx->Current.Attrib[FGL_ATTR_COLOR0]);
   /* CurrentExecPrimitive: a node whose last primitive continues in the
    * next node (a vertex list wrapped mid-primitive) leaves Mesa "inside
    * glBegin/glEnd" until that node is drawn, so the next node's
    * FLUSH_FOR_DRAW does nothing (`dlist/fuzz`) */
   if (vl->prim_count) {
      const struct save_prim *last = &vl->prims[vl->prim_count - 1];
      ctx->BeginMode = last->end ? FGL_OUTSIDE_BEGIN_END : last->mode;
   }
}

/* vbo_save_playback_vertex_list(_loopback) */
static void playback_vertex_list(struct fgl_context *ctx, const struct vertex_list *vl)
{
   /* FLUSH_FOR_DRAW: attributes set outside glBegin/glEnd since the last
    * flush (a list's glColor, replayed through the immediate-mode
    * functions) are copied to the current values and stay in the vertex
    * format, so the next full flush copies them again over what the
    * list's last vertex made current (`dlist/current_values`) */
   fgl_flush_for_draw(ctx);
   if (fgl_inside_begin_end(ctx) && vl->draw_begins) {
      /* "draw operation inside glBegin/End" */
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (vl->kind == VL_LOOPBACK) {
      /* from the buffer object, where the draw would read */
      const size_t at = vl->vao_offset + (size_t)vl->start_offset * vl->vertex_size * sizeof(float);
      if (vl->bo && at < vl->bo->size)
         loopback_vertex_list(ctx, vl, vl->bo->data + at, vl->bo->size - at);
      else
         loopback_vertex_list(ctx, vl, NULL, 0);
      return;
   }
   if (vl->ndraws) {
      /* one indexed draw per run of a mode, the list's vertex format as
       * the draw's arrays (attributes outside it are the current values) */
      unsigned exec_attr_size[FGL_ATTR_COUNT];
      memcpy(exec_attr_size, ctx->Vbo.attr_size, sizeof(exec_attr_size));
      memcpy(ctx->Vbo.attr_size, vl->attrsz, sizeof(vl->attrsz));
      const struct fgl_vertex_view view = fgl_vertex_view_full(vl->verts);
      t_render_batch(ctx, &view, vl->nverts, vl->draws, vl->ndraws);
      memcpy(ctx->Vbo.attr_size, exec_attr_size, sizeof(exec_attr_size));
   }
   if (vl->kind == VL_COPY_CURRENT)
      playback_copy_to_current(ctx, vl);
}

static void execute_list(struct fgl_context *ctx, GLuint list);

/* OPCODE_POLYGON_STIPPLE: the list's own 32x32 copy, unpacked with the
 * default pixel-store state whatever the current one [S: dlist.c:
 * execute_list] */
static void list_polygon_stipple(struct fgl_context *ctx, const GLubyte *pattern)
{
   const struct fgl_pixelstore save = ctx->Unpack;
   ctx->Unpack = (struct fgl_pixelstore){ .Alignment = 4 };
   glPolygonStipple(pattern);
   ctx->Unpack = save;
}

/* commands whose replay is not an exported gl* function */
#define glWindowPos4fMESA fgl_window_pos4f
#define glPolygonStipple(pattern) list_polygon_stipple(ctx, pattern)

static void execute_nodes(struct fgl_context *ctx, const struct display_list *dl)
{
   for (unsigned pos = 0; pos < dl->count;) {
      const union dl_node *n = &dl->nodes[pos];
      switch (n->h.op) {
#define DL_OP0(Name)                                                            \
      case DL_OP_##Name:                                                        \
         gl##Name();                                                            \
         break;
#define DL_OP1(Name, A)                                                         \
      case DL_OP_##Name:                                                        \
         gl##Name(DL_GET_##A(n[1]));                                            \
         break;
#define DL_OP2(Name, A, B)                                                      \
      case DL_OP_##Name:                                                        \
         gl##Name(DL_GET_##A(n[1]), DL_GET_##B(n[2]));                          \
         break;
#define DL_OP3(Name, A, B, C)                                                   \
      case DL_OP_##Name:                                                        \
         gl##Name(DL_GET_##A(n[1]), DL_GET_##B(n[2]), DL_GET_##C(n[3]));        \
         break;
#define DL_OP4(Name, A, B, C, D_)                                               \
      case DL_OP_##Name:                                                        \
         gl##Name(DL_GET_##A(n[1]), DL_GET_##B(n[2]), DL_GET_##C(n[3]),         \
                  DL_GET_##D_(n[4]));                                           \
         break;
#define DL_OP5(Name, A, B, C, D_, E_)                                           \
      case DL_OP_##Name:                                                        \
         gl##Name(DL_GET_##A(n[1]), DL_GET_##B(n[2]), DL_GET_##C(n[3]),         \
                  DL_GET_##D_(n[4]), DL_GET_##E_(n[5]));                        \
         break;
#define DL_OP6(Name, A, B, C, D_, E_, F_)                                       \
      case DL_OP_##Name:                                                        \
         gl##Name(DL_GET_##A(n[1]), DL_GET_##B(n[2]), DL_GET_##C(n[3]),         \
                  DL_GET_##D_(n[4]), DL_GET_##E_(n[5]), DL_GET_##F_(n[6]));     \
         break;
#define DL_OPV0(Name, VT, N)                                                    \
      case DL_OP_##Name:                                                        \
         gl##Name(DL_GET_VEC_##VT(&n[1], N));                                   \
         break;
#define DL_OPV1(Name, A, VT, N)                                                 \
      case DL_OP_##Name:                                                        \
         gl##Name(DL_GET_##A(n[1]), DL_GET_VEC_##VT(&n[2], N));                 \
         break;
#define DL_OPV2(Name, A, B, VT, N)                                              \
      case DL_OP_##Name:                                                        \
         gl##Name(DL_GET_##A(n[1]), DL_GET_##B(n[2]), DL_GET_VEC_##VT(&n[3], N)); \
         break;
#define DL_CUSTOM0 DL_OP0
#define DL_CUSTOM1 DL_OP1
#define DL_CUSTOMV2 DL_OPV2
#include "main/dlist_ops.h"
#include "main/dlist_ops_undef.h"
      case DL_OP_ATTR: {
         /* glVertexAttrib{1,2,3,4}fvNV of the stored values */
         const unsigned sz = n[2].u;
         fgl_vbo_attr(ctx, (enum fgl_vbo_attr)n[1].u, sz, n[3].f, sz > 1 ? n[4].f : 0.0f,
                      sz > 2 ? n[5].f : 0.0f, sz > 3 ? n[6].f : 1.0f);
         break;
      }
      case DL_OP_MAP1:
         glMap1f(n[1].e, n[2].f, n[3].f, n[4].i, n[5].i, n[6].u ? &n[7].f : NULL);
         break;
      case DL_OP_MAP2:
         glMap2f(n[1].e, n[2].f, n[3].f, n[6].i, n[8].i, n[4].f, n[5].f, n[7].i, n[9].i,
                 n[10].u ? &n[11].f : NULL);
         break;
      case DL_OP_EVAL_C1:
         glEvalCoord1f(n[1].f);
         break;
      case DL_OP_EVAL_C2:
         glEvalCoord2f(n[1].f, n[2].f);
         break;
      case DL_OP_EVAL_P1:
         glEvalPoint1(n[1].i);
         break;
      case DL_OP_EVAL_P2:
         glEvalPoint2(n[1].i, n[2].i);
         break;
      case DL_OP_CALL_LIST:
         /* the nested call is skipped beyond MAX_LIST_NESTING */
         if (ctx->ListState->call_depth < FGL_MAX_LIST_NESTING) {
            ctx->ListState->call_depth++;
            execute_list(ctx, n[1].u);
            ctx->ListState->call_depth--;
         }
         break;
      case DL_OP_CALL_LISTS:
         if (ctx->ListState->call_depth < FGL_MAX_LIST_NESTING) {
            ctx->ListState->call_depth++;
            exec_call_lists(ctx, n[1].i, n[2].e, get_pointer(&n[3]));
            ctx->ListState->call_depth--;
         }
         break;
      case DL_OP_BITMAP:
         fgl_exec_list_bitmap(ctx, n[1].i, n[2].i, n[3].f, n[4].f, n[5].f, n[6].f,
                              get_pointer(&n[7]));
         break;
      case DL_OP_DRAW_PIXELS:
         fgl_exec_list_drawpixels(ctx, n[1].i, n[2].i, n[3].e, n[4].e, get_pointer(&n[5]));
         break;
      case DL_OP_ERROR:
         fgl_error(ctx, n[1].e);
         break;
      case DL_OP_TEX_IMAGE:
      case DL_OP_TEX_SUB_IMAGE:
         exec_tex_image_node(ctx, n);
         break;
      case DL_OP_COPY_TEX_IMAGE:
         if (n[1].u == 1)
            glCopyTexImage1D(n[2].e, n[3].i, n[4].e, n[5].i, n[6].i, n[7].i, n[9].i);
         else
            glCopyTexImage2D(n[2].e, n[3].i, n[4].e, n[5].i, n[6].i, n[7].i, n[8].i, n[9].i);
         break;
      case DL_OP_TEX_IMAGE_3D:
      case DL_OP_TEX_SUB_IMAGE_3D:
         exec_tex_image_3d_node(ctx, n);
         break;
      case DL_OP_COMPRESSED_TEX:
         exec_compressed_tex_node(n);
         break;
      case DL_OP_COPY_TEX_SUB_IMAGE_3D:
         glCopyTexSubImage3D(n[1].e, n[2].i, n[3].i, n[4].i, n[5].i, n[6].i, n[7].i, n[8].i,
                             n[9].i);
         break;
      case DL_OP_COPY_TEX_SUB_IMAGE:
         if (n[1].u == 1)
            glCopyTexSubImage1D(n[2].e, n[3].i, n[4].i, n[6].i, n[7].i, n[8].i);
         else
            glCopyTexSubImage2D(n[2].e, n[3].i, n[4].i, n[5].i, n[6].i, n[7].i, n[8].i,
                                n[9].i);
         break;
      case DL_OP_VERTEX_LIST:
         playback_vertex_list(ctx, get_pointer(&n[1]));
         break;
      case DL_OP_END_OF_LIST:
         return;
      default:
         break;
      }
      pos += n->h.size;
   }
}

/* execute_list: list 0 and unknown names do nothing */
static void execute_list(struct fgl_context *ctx, GLuint list)
{
   const struct display_list *dl = lookup_list(ctx, list);
   if (dl)
      execute_nodes(ctx, dl);
}

/* _mesa_CallList */
static void exec_call_list(struct fgl_context *ctx, GLuint list)
{
   fgl_flush_current(ctx);
   if (list == 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   const bool save_compile_flag = ctx->CompileFlag;
   ctx->CompileFlag = false;
   execute_list(ctx, list);
   ctx->CompileFlag = save_compile_flag;
}

/* _mesa_CallLists: each name plus the list base (integer arithmetic, a
 * float name truncated) */
static void exec_call_lists(struct fgl_context *ctx, GLsizei n, GLenum type, const GLvoid *lists)
{
   if (type < GL_BYTE || type > GL_4_BYTES) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (n < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (n == 0 || !lists)
      return;
   const bool save_compile_flag = ctx->CompileFlag;
   ctx->CompileFlag = false;
   const GLuint base = ctx->List.ListBase;
   const GLubyte *ub = lists;
   for (GLsizei i = 0; i < n; i++) {
      int id;
      switch (type) {
      case GL_BYTE:
         id = ((const GLbyte *)lists)[i];
         break;
      case GL_UNSIGNED_BYTE:
         id = ub[i];
         break;
      /* (the application's array need not be aligned: memcpy) */
      case GL_SHORT: {
         GLshort v;
         memcpy(&v, ub + 2 * (size_t)i, sizeof(v));
         id = v;
         break;
      }
      case GL_UNSIGNED_SHORT: {
         GLushort v;
         memcpy(&v, ub + 2 * (size_t)i, sizeof(v));
         id = v;
         break;
      }
      case GL_INT: {
         GLint v;
         memcpy(&v, ub + 4 * (size_t)i, sizeof(v));
         id = v;
         break;
      }
      case GL_UNSIGNED_INT: {
         GLuint v;
         memcpy(&v, ub + 4 * (size_t)i, sizeof(v));
         id = (int)v;
         break;
      }
      case GL_FLOAT: {   /* (GLint) cast as x86 does it: INT_MIN past the range */
         GLfloat v;
         memcpy(&v, ub + 4 * (size_t)i, sizeof(v));
         id = fgl_double_to_int_trunc(v);
         break;
      }
      case GL_2_BYTES:
         id = ub[2 * i] * 256 + ub[2 * i + 1];
         break;
      case GL_3_BYTES:
         id = ub[3 * i] * 65536 + ub[3 * i + 1] * 256 + ub[3 * i + 2];
         break;
      default: /* GL_4_BYTES */
         id = (int)((GLuint)ub[4 * i] * 16777216u + ub[4 * i + 1] * 65536u +
                    ub[4 * i + 2] * 256u + ub[4 * i + 3]);
         break;
      }
      execute_list(ctx, base + (GLuint)id);
   }
   ctx->CompileFlag = save_compile_flag;
}

/* A call from the application: the shared lists are locked while they
 * execute (the lists they call run under the same lock). */
static void locked_call_list(struct fgl_context *ctx, GLuint list)
{
   pthread_mutex_lock(&ctx->ListState->shared->lock);
   exec_call_list(ctx, list);
   pthread_mutex_unlock(&ctx->ListState->shared->lock);
}

static void locked_call_lists(struct fgl_context *ctx, GLsizei n, GLenum type,
                              const GLvoid *lists)
{
   pthread_mutex_lock(&ctx->ListState->shared->lock);
   exec_call_lists(ctx, n, type, lists);
   pthread_mutex_unlock(&ctx->ListState->shared->lock);
}

/* ------------------------------------------------------------------ */
/* Entry points                                                        */
/* ------------------------------------------------------------------ */

void GLAPIENTRY glNewList(GLuint name, GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   struct fgl_dlist_state *ls = ctx->ListState;
   if (ctx->CompileFlag) {
      /* save_NewList */
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   fgl_flush_current(ctx);
   ASSERT_OUTSIDE_BEGIN_END_OWN(ctx);
   if (name == 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (ls->current_list) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   struct display_list *dl = make_list(name);
   if (!dl) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   ctx->CompileFlag = true;
   ctx->ExecuteFlag = mode == GL_COMPILE_AND_EXECUTE;
   invalidate_saved_current_state(ctx);
   ls->current_list = dl;
   ls->use_loopback = false;
   /* vbo_save_NewList */
   reset_vertex(ctx);
   ls->save_need_flush = false;
}

/* replace_op_vertex_list_recursively: the vertex lists of a list that
 * depends on the state it is called in, and of the lists it calls, are
 * replayed by loopback (the lists it calls by name, without the list
 * base) */
static void replace_vertex_lists(struct fgl_context *ctx, struct display_list *dl)
{
   if (!dl || dl->walk == ctx->ListState->shared->walk)
      return;
   dl->walk = ctx->ListState->shared->walk;
   for (unsigned pos = 0; pos < dl->count; pos += dl->nodes[pos].h.size) {
      union dl_node *n = &dl->nodes[pos];
      if (n->h.op == DL_OP_VERTEX_LIST) {
         struct vertex_list *vl = get_pointer(&n[1]);
         vl->kind = VL_LOOPBACK;
      } else if (n->h.op == DL_OP_CALL_LIST) {
         replace_vertex_lists(ctx, lookup_list(ctx, n[1].u));
      } else if (n->h.op == DL_OP_CALL_LISTS) {
         const GLubyte *ub = get_pointer(&n[3]);
         const GLenum type = n[2].e;
         if (!ub)
            continue;
         for (GLint i = 0; i < n[1].i; i++) {
            GLuint id;
            switch (type) {
            case GL_BYTE: id = (GLuint)(int)((const GLbyte *)ub)[i]; break;
            case GL_UNSIGNED_BYTE: id = ub[i]; break;
            case GL_SHORT: id = (GLuint)(int)((const GLshort *)ub)[i]; break;
            case GL_UNSIGNED_SHORT: id = ((const GLushort *)ub)[i]; break;
            case GL_INT: id = (GLuint)((const GLint *)ub)[i]; break;
            case GL_UNSIGNED_INT: id = ((const GLuint *)ub)[i]; break;
            case GL_FLOAT: id = (GLuint)fgl_double_to_int_trunc(((const GLfloat *)ub)[i]); break;
            case GL_2_BYTES: id = ub[2 * i] * 256u + ub[2 * i + 1]; break;
            case GL_3_BYTES: id = ub[3 * i] * 65536u + ub[3 * i + 1] * 256u + ub[3 * i + 2]; break;
            case GL_4_BYTES:
               id = ub[4 * i] * 16777216u + ub[4 * i + 1] * 65536u + ub[4 * i + 2] * 256u +
                    ub[4 * i + 3];
               break;
            default: id = 0; break;
            }
            replace_vertex_lists(ctx, lookup_list(ctx, id));
         }
      }
   }
}

void GLAPIENTRY glEndList(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   struct fgl_dlist_state *ls = ctx->ListState;
   save_flush(ctx);
   fgl_flush_vertices(ctx);
   if (ctx->ExecuteFlag && inside_save_begin_end(ls))
      fgl_error(ctx, GL_INVALID_OPERATION);
   if (!ls->current_list) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   /* vbo_save_EndList: a primitive still open is ended here, and the list
    * is replayed by loopback */
   if (inside_save_begin_end(ls)) {
      struct save_context *save = &ls->save;
      if (save->prim_used > 0) {
         const unsigned i = save->prim_used - 1;
         ls->save_prim = PRIM_OUTSIDE_BEGIN_END;
         save->prims[i].end = false;
         save->prims[i].count = get_vertex_count(save) - save->prims[i].start;
      }
      save->dangling_attr_ref = true;
      save_flush_vertices(ctx);
   }
   ls->opcode_fallback = false;
   pthread_mutex_lock(&ls->shared->lock);
   if (ls->use_loopback) {
      ls->shared->walk++;
      replace_vertex_lists(ctx, ls->current_list);
   }
   struct display_list *dl = ls->current_list;
   ls->current_list = NULL;
   remove_list(ctx, dl->name);
   if (!insert_list(ctx, dl)) {
      delete_list(dl);
      fgl_error(ctx, GL_OUT_OF_MEMORY);
   }
   pthread_mutex_unlock(&ls->shared->lock);
   ctx->ExecuteFlag = true;
   ctx->CompileFlag = false;
}

void GLAPIENTRY glCallList(GLuint list)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      fgl_save_call_list(ctx, list);
      return;
   }
   locked_call_list(ctx, list);
}

void GLAPIENTRY glCallLists(GLsizei n, GLenum type, const GLvoid *lists)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      fgl_save_call_lists(ctx, n, type, lists);
      return;
   }
   locked_call_lists(ctx, n, type, lists);
}

void GLAPIENTRY glListBase(GLuint base)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ListBase, base);
   fgl_flush_vertices(ctx);
   ASSERT_OUTSIDE_BEGIN_END_OWN(ctx);
   ctx->List.ListBase = base;
}

/* _mesa_HashFindFreeKeyBlock: after the highest name ever used, or else
 * the first gap of range free names from 1 */
static GLuint find_free_block(const struct dlist_shared *ls, GLuint range)
{
   const GLuint max_key = ~(GLuint)0 - 1;
   if (max_key - range > ls->max_key)
      return ls->max_key + 1;
   GLuint free_start = 1;
   for (unsigned i = 0; i < ls->table_count; i++) {
      const GLuint name = ls->table[i].name;
      if (name >= free_start && name - free_start >= range)
         return free_start;
      if (name >= free_start)
         free_start = name + 1;
   }
   return max_key - free_start >= range ? free_start : 0;
}

/* The names base .. base + n - 1, all free, reserved by empty lists,
 * inserted into the table at once (one move of the names after them). */
static bool insert_empty_lists(struct dlist_shared *sh, GLuint base, unsigned n)
{
   if (n > UINT_MAX - sh->table_count)
      return false;
   const unsigned count = sh->table_count + n;
   if (count > sh->table_cap) {
      unsigned cap = sh->table_cap ? sh->table_cap : 64;
      while (cap < count)
         cap = cap > UINT_MAX / 2 ? count : cap * 2;
      void *t = fgl_realloc(sh->table, (size_t)cap * sizeof(*sh->table));
      if (!t)
         return false;
      sh->table = t;
      sh->table_cap = cap;
   }
   const unsigned at = table_find(sh, base);
   memmove(&sh->table[at + n], &sh->table[at], (sh->table_count - at) * sizeof(*sh->table));
   for (unsigned k = 0; k < n; k++) {
      struct display_list *dl = make_list(base + k);
      if (!dl) {   /* undo: the names after them move back */
         for (unsigned j = 0; j < k; j++)
            delete_list(sh->table[at + j].dl);
         memmove(&sh->table[at], &sh->table[at + n],
                 (sh->table_count - at) * sizeof(*sh->table));
         return false;
      }
      sh->table[at + k].name = base + k;
      sh->table[at + k].dl = dl;
   }
   sh->table_count = count;
   if (base + (n - 1) > sh->max_key)
      sh->max_key = base + (n - 1);
   return true;
}

GLuint GLAPIENTRY glGenLists(GLsizei range)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return 0;
   fgl_flush_vertices(ctx);
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, 0);
   if (range < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return 0;
   }
   if (range == 0)
      return 0;
   struct dlist_shared *sh = ctx->ListState->shared;
   pthread_mutex_lock(&sh->lock);
   GLuint base = find_free_block(sh, (GLuint)range);
   if (base && !insert_empty_lists(sh, base, (unsigned)range)) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      base = 0;
   }
   pthread_mutex_unlock(&sh->lock);
   return base;
}

void GLAPIENTRY glDeleteLists(GLuint list, GLsizei range)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_flush_vertices(ctx);
   ASSERT_OUTSIDE_BEGIN_END_OWN(ctx);
   if (range < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   /* for (i = list; i < list + range; i++) destroy_list(i), with the
    * unsigned wrap of list + range */
   const GLuint end = list + (GLuint)range;
   struct dlist_shared *sh = ctx->ListState->shared;
   pthread_mutex_lock(&sh->lock);
   const unsigned first = table_find(sh, list);
   unsigned last = first;
   for (; last < sh->table_count && sh->table[last].name < end; last++)
      delete_list(sh->table[last].dl);
   /* the names after them move once (nothing to move, and maybe no
    * table yet, when none was deleted) */
   if (last > first) {
      memmove(&sh->table[first], &sh->table[last],
              (sh->table_count - last) * sizeof(*sh->table));
      sh->table_count -= last - first;
   }
   pthread_mutex_unlock(&sh->lock);
}

GLboolean GLAPIENTRY glIsList(GLuint list)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return GL_FALSE;
   fgl_flush_vertices(ctx);
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, GL_FALSE);
   pthread_mutex_lock(&ctx->ListState->shared->lock);
   const bool found = lookup_list(ctx, list) != NULL;
   pthread_mutex_unlock(&ctx->ListState->shared->lock);
   return found ? GL_TRUE : GL_FALSE;
}

bool fgl_get_list_value(const struct fgl_context *ctx, GLenum pname, int *value)
{
   switch (pname) {
   case GL_LIST_BASE:
      *value = (int)ctx->List.ListBase;
      return true;
   case GL_LIST_INDEX:
      *value = ctx->ListState->current_list ? (int)ctx->ListState->current_list->name : 0;
      return true;
   case GL_LIST_MODE:
      /* [S: main/get.c:find_custom_value] */
      if (!ctx->CompileFlag)
         *value = 0;
      else
         *value = ctx->ExecuteFlag ? GL_COMPILE_AND_EXECUTE : GL_COMPILE;
      return true;
   case GL_MAX_LIST_NESTING:
      *value = FGL_MAX_LIST_NESTING;
      return true;
   default:
      return false;
   }
}

/* [S: dlist.c:save_Bitmap] the bitmap becomes a texture at compile time
 * (st_make_bitmap_texture; without data: GL_OUT_OF_MEMORY and no node);
 * GL_COMPILE_AND_EXECUTE draws that texture at once */
bool fgl_save_bitmap(struct fgl_context *ctx, GLsizei width, GLsizei height, GLfloat xorig,
                     GLfloat yorig, GLfloat xmove, GLfloat ymove, const GLubyte *bits)
{
   if (!save_prologue(ctx))
      return false;
   /* no pixels (a NULL pointer, whatever the size; glXUseXFont's blank
    * glyphs): st_make_bitmap_texture has no texture to give, so the call
    * raises GL_OUT_OF_MEMORY and is neither compiled nor executed, its
    * move lost (probe p_bitmap_compile_null) */
   if (!bits) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return false;
   }
   /* [S: dlist.c:save_Bitmap, st_cb_bitmap.c:st_make_bitmap_texture,
    * lp_texture.c:llvmpipe_texture_layout] a negative size is compiled as
    * it is (GL_INVALID_VALUE when the node executes), but the oracle
    * first makes its texture from the sizes as unsigned, the height cut
    * to pipe_resource's 16 bits: a row of the width aligned to 4 and to
    * 64 bytes in 32-bit arithmetic (widths -63 to -1 wrap to 0), times
    * the height aligned to 4, over LP_MAX_TEXTURE_SIZE (2 GiB) raises
    * GL_OUT_OF_MEMORY, neither compiled nor executed (oracle defect,
    * probe p_bitmap_compile_negative) */
   if (width < 0 || height < 0) {
      const uint32_t row = ((((uint32_t)width + 3u) & ~3u) + 63u) & ~63u;
      const uint64_t rows = (((uint32_t)height & 0xffffu) + 3u) & ~3u;
      if ((uint64_t)row * rows > 2ull * 1024 * 1024 * 1024) {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return false;
      }
   }
   uint8_t *tex = NULL;
   if (width > 0 && height > 0) {
      tex = fgl_make_bitmap_texture(ctx, width, height, bits);
      if (!tex) {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return false;
      }
   }
   union dl_node *n = alloc_node(ctx, DL_OP_BITMAP, 6 + PTR_NODES);
   if (!n) {
      fgl_free(tex);
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return false;
   }
   n[1].i = width;
   n[2].i = height;
   n[3].f = xorig;
   n[4].f = yorig;
   n[5].f = xmove;
   n[6].f = ymove;
   put_pointer(&n[7], tex);
   if (ctx->ExecuteFlag)
      fgl_exec_list_bitmap(ctx, width, height, xorig, yorig, xmove, ymove, tex);
   return false;
}

/* [S: dlist.c:save_DrawPixels] the image copied with the unpack state
 * (unpack_image), replayed with the default packing */
bool fgl_save_drawpixels(struct fgl_context *ctx, GLsizei width, GLsizei height,
                         GLenum format, GLenum type, const GLvoid *pixels)
{
   if (!save_prologue(ctx))
      return false;
   union dl_node *n = alloc_node(ctx, DL_OP_DRAW_PIXELS, 4 + PTR_NODES);
   if (n) {
      n[1].i = width;
      n[2].i = height;
      n[3].e = format;
      n[4].e = type;
      put_pointer(&n[5], fgl_pack_list_image(ctx, width, height, format, type, pixels));
   }
   return ctx->ExecuteFlag;
}
