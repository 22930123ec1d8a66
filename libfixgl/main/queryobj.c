/*
 * Occlusion queries (GL 1.5, GL_ARB_occlusion_query): glGenQueries,
 * glDeleteQueries, glIsQuery, glBeginQuery, glEndQuery, glGetQueryiv,
 * glGetQueryObjectiv, glGetQueryObjectuiv, with Mesa 22.3's validation
 * [S: main/queryobj.c] and the oracle's answers (ORACLE-NOTES.md
 * "Occlusion queries", conformance/probes/p_query.c).
 *
 * GL_SAMPLES_PASSED is the only target: the oracle's others (GL 3 and
 * later: GL_ANY_SAMPLES_PASSED, GL_TIME_ELAPSED, ...) raise
 * GL_INVALID_ENUM here, as the GL 1.5 specification requires of an
 * implementation without them.
 *
 * Counting: while a query is active, ctx->_Raster.samples points to its
 * counters (decided here, not per pixel: no draw without a query pays
 * for it); the raster core adds every sample that passes the fragment
 * tests, one counter per rasterizing thread (raster/r_state.h
 * r_sample_counter), and the result is their sum once the scene that
 * holds the query's draws is rasterized.  Clears count nothing; pixel
 * rectangles count as triangles.
 *
 * Availability: llvmpipe's query has the fence of the scene it ended in;
 * asking whether it is available flushes that scene and answers false
 * unless a flush has already come since (llvmpipe_get_query_result with
 * wait false), and its flush waits for the rasterizer, so the next
 * question answers true.  ctx->Query.FlushEpoch counts those flushes.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <string.h>

#include "fgl_alloc.h"
#include "main/dlist.h"
#include "main/groups.h"

static struct fgl_query_object *lookup(const struct fgl_context *ctx, GLuint id)
{
   if (id == 0)
      return NULL;
   for (unsigned i = 0; i < ctx->Query.Count; i++)
      if (ctx->Query.Objs[i]->Id == id)
         return ctx->Query.Objs[i];
   return NULL;
}

/* A new query object named id in the table, or NULL (GL_OUT_OF_MEMORY) */
static struct fgl_query_object *insert(struct fgl_context *ctx, GLuint id)
{
   struct fgl_query_state *qs = &ctx->Query;
   if (qs->Count == qs->Alloc) {
      const unsigned alloc = qs->Alloc ? 2 * qs->Alloc : 16;
      struct fgl_query_object **objs = fgl_realloc_gl(ctx, qs->Objs, alloc * sizeof(*objs));
      if (!objs)
         return NULL;
      qs->Objs = objs;
      qs->Alloc = alloc;
   }
   struct fgl_query_object *q = fgl_calloc_gl(ctx, 1, sizeof(*q));
   if (!q)
      return NULL;
   q->Id = id;
   qs->Objs[qs->Count++] = q;
   if (id > qs->MaxName)
      qs->MaxName = id;
   return q;
}

static void free_query(struct fgl_query_object *q)
{
   fgl_free(q->Counters);
   fgl_free(q);
}

void fgl_free_queries(struct fgl_context *ctx)
{
   for (unsigned i = 0; i < ctx->Query.Count; i++)
      free_query(ctx->Query.Objs[i]);
   fgl_free(ctx->Query.Objs);
   memset(&ctx->Query, 0, sizeof(ctx->Query));
   ctx->_Raster.samples = NULL;
}

/* The end of the active query (glEndQuery, or glDeleteQueries of it):
 * what is batched and glBitmap's cache are drawn while it counts
 * [S: st_cb_queryobj.c:st_EndQuery flushes the bitmap cache], then the
 * raster state stops counting. */
static void end_query(struct fgl_context *ctx, struct fgl_query_object *q)
{
   fgl_flush_vertices(ctx);
   fgl_flush_bitmap_cache(ctx);
   ctx->_Raster.samples = NULL;
   ctx->Query.CurrentOcclusion = NULL;
   q->Active = false;
   q->EndEpoch = ctx->Query.FlushEpoch;
}

/* The result: every draw of the query rasterized, the threads' counts
 * summed */
static void resolve(struct fgl_context *ctx, struct fgl_query_object *q)
{
   fgl_scene_flush(ctx);
   uint64_t sum = 0;
   if (q->Counters)
      for (unsigned i = 0; i < R_SAMPLE_SLOTS; i++)
         sum += q->Counters[i].n;
   q->Result = sum;
   q->Ready = true;
}

void GLAPIENTRY glGenQueries(GLsizei n, GLuint *ids)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (n < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!ids || n == 0)
      return;
   /* [S: hash.c:_mesa_HashFindFreeKeyBlock] past the largest name; the
    * table of a context never holds 2^32 - 2 names in practice, and
    * running out is GL_OUT_OF_MEMORY */
   struct fgl_query_state *qs = &ctx->Query;
   if (qs->MaxName >= 0xFFFFFFFEu || (GLuint)n > 0xFFFFFFFEu - qs->MaxName) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   const GLuint first = qs->MaxName + 1;
   for (GLsizei i = 0; i < n; i++) {
      if (!insert(ctx, first + (GLuint)i))
         return;
      ids[i] = first + (GLuint)i;
   }
}

void GLAPIENTRY glDeleteQueries(GLsizei n, const GLuint *ids)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   if (n < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!ids)
      return;
   struct fgl_query_state *qs = &ctx->Query;
   for (GLsizei k = 0; k < n; k++) {
      struct fgl_query_object *q = lookup(ctx, ids[k]);
      if (!q)
         continue;
      /* an active query ends first (no error) */
      if (q->Active)
         end_query(ctx, q);
      /* the scene may still count into it */
      if (q->Counters)
         fgl_scene_flush(ctx);
      for (unsigned i = 0; i < qs->Count; i++) {
         if (qs->Objs[i] == q) {
            qs->Objs[i] = qs->Objs[--qs->Count];
            break;
         }
      }
      free_query(q);
   }
}

/* [S: queryobj.c:_mesa_IsQuery] a name glBeginQuery has used */
GLboolean GLAPIENTRY glIsQuery(GLuint id)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return GL_FALSE;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, GL_FALSE);
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, GL_FALSE);
   const struct fgl_query_object *q = lookup(ctx, id);
   return q && q->EverBound;
}

/* [S: queryobj.c:_mesa_BeginQueryIndexed]: the target, id 0, a query
 * already active on it, then the object: a name never generated gets one
 * (the compatibility profile), an active one is an error */
void GLAPIENTRY glBeginQuery(GLenum target, GLuint id)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, BeginQuery, target, id);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   if (target != GL_SAMPLES_PASSED) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (id == 0 || ctx->Query.CurrentOcclusion) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   struct fgl_query_object *q = lookup(ctx, id);
   if (!q) {
      q = insert(ctx, id);
      if (!q)
         return;
   } else if (q->Active) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (!q->Counters) {
      q->Counters = fgl_calloc_gl(ctx, R_SAMPLE_SLOTS, sizeof(*q->Counters));
      if (!q->Counters)
         return;
   } else {
      /* the draws of its last use may still be binned */
      fgl_scene_flush(ctx);
      memset(q->Counters, 0, R_SAMPLE_SLOTS * sizeof(*q->Counters));
   }
   /* glBitmap's cache is drawn before the query counts
    * [S: st_cb_queryobj.c:st_BeginQuery] */
   fgl_flush_bitmap_cache(ctx);
   q->Active = true;
   q->EverBound = true;
   q->Ready = false;
   q->Result = 0;
   ctx->Query.CurrentOcclusion = q;
   ctx->_Raster.samples = q->Counters;
}

void GLAPIENTRY glEndQuery(GLenum target)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, EndQuery, target);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   if (target != GL_SAMPLES_PASSED) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   struct fgl_query_object *q = ctx->Query.CurrentOcclusion;
   if (!q) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   end_query(ctx, q);
}

/* [S: queryobj.c:_mesa_GetQueryIndexediv] */
void GLAPIENTRY glGetQueryiv(GLenum target, GLenum pname, GLint *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (target != GL_SAMPLES_PASSED) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   GLint v;
   switch (pname) {
   case GL_QUERY_COUNTER_BITS:
      v = 64;   /* llvmpipe's PIPE_QUERY_OCCLUSION_COUNTER */
      break;
   case GL_CURRENT_QUERY:
      v = ctx->Query.CurrentOcclusion ? (GLint)ctx->Query.CurrentOcclusion->Id : 0;
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (params)
      *params = v;
}

/* [S: queryobj.c:get_query_object] the value of pname, false after an
 * error */
static bool query_object_value(struct fgl_context *ctx, GLuint id, GLenum pname,
                               uint64_t *value)
{
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, false);
   struct fgl_query_object *q = lookup(ctx, id);
   if (!q || q->Active || !q->EverBound) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return false;
   }
   switch (pname) {
   case GL_QUERY_RESULT:
      if (!q->Ready) {
         /* the oracle waits for the scene's fence, flushing it first
          * unless a flush came since the query ended */
         if (ctx->Query.FlushEpoch == q->EndEpoch) {
            fgl_query_flushed(ctx);
            fgl_vpcut_invalidate(ctx);   /* lp_setup_reset (p_vpcut_state) */
         }
         resolve(ctx, q);
      }
      *value = q->Result;
      return true;
   case GL_QUERY_RESULT_AVAILABLE:
      if (!q->Ready) {
         if (ctx->Query.FlushEpoch != q->EndEpoch)
            resolve(ctx, q);
         else {
            fgl_query_flushed(ctx);   /* asked in vain: the scene flushes */
            fgl_vpcut_invalidate(ctx);
         }
      }
      *value = q->Ready;
      return true;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return false;
   }
}

void GLAPIENTRY glGetQueryObjectiv(GLuint id, GLenum pname, GLint *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   uint64_t v;
   if (query_object_value(ctx, id, pname, &v) && params)
      *params = v > 0x7fffffffu ? 0x7fffffff : (GLint)v;
}

void GLAPIENTRY glGetQueryObjectuiv(GLuint id, GLenum pname, GLuint *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   uint64_t v;
   if (query_object_value(ctx, id, pname, &v) && params)
      *params = v > 0xffffffffu ? 0xffffffffu : (GLuint)v;
}

/* ---- the ARB names (GL_ARB_occlusion_query) ---- */

void GLAPIENTRY glGenQueriesARB(GLsizei n, GLuint *ids)
{
   glGenQueries(n, ids);
}

void GLAPIENTRY glDeleteQueriesARB(GLsizei n, const GLuint *ids)
{
   glDeleteQueries(n, ids);
}

GLboolean GLAPIENTRY glIsQueryARB(GLuint id)
{
   return glIsQuery(id);
}

void GLAPIENTRY glBeginQueryARB(GLenum target, GLuint id)
{
   glBeginQuery(target, id);
}

void GLAPIENTRY glEndQueryARB(GLenum target)
{
   glEndQuery(target);
}

void GLAPIENTRY glGetQueryivARB(GLenum target, GLenum pname, GLint *params)
{
   glGetQueryiv(target, pname, params);
}

void GLAPIENTRY glGetQueryObjectivARB(GLuint id, GLenum pname, GLint *params)
{
   glGetQueryObjectiv(id, pname, params);
}

void GLAPIENTRY glGetQueryObjectuivARB(GLuint id, GLenum pname, GLuint *params)
{
   glGetQueryObjectuiv(id, pname, params);
}
