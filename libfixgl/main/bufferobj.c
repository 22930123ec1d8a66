/*
 * Buffer objects (GL 1.5, GL_ARB_vertex_buffer_object): glGenBuffers,
 * glBindBuffer, glBufferData, glBufferSubData, glGetBufferSubData,
 * glMapBuffer, glUnmapBuffer, glGetBufferParameteriv, glGetBufferPointerv,
 * glIsBuffer, glDeleteBuffers, with Mesa 22.3's validation and its order
 * of errors [S: main/bufferobj.c].  Vertex arrays and glDrawElements
 * indices read them through tnl/t_array.c; main/varray.c records the
 * GL_ARRAY_BUFFER binding with each pointer.
 *
 * The targets are GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER: the others
 * the oracle accepts (pixel buffers, GL 2.1, and the targets of GL 3 and
 * later) raise GL_INVALID_ENUM here, as the GL 1.5 specification requires
 * of an implementation without them; likewise the GL 3 and later pnames
 * of glGetBufferParameteriv.
 *
 * Names and objects live in a table shared by the contexts of a sharelist
 * (struct fgl_buffer_objects); bindings hold references, so an object
 * deleted in one context lives on while another still has it bound.
 * Drawing from a buffer the user has mapped is no error in the oracle
 * (Mesa 22.3 does not check it): it draws the store as it is
 * (ORACLE-NOTES.md "Buffer objects").
 */
/* the prototypes of <GL/glext.h> (GL 1.5 and the ARB names) check the
 * definitions and export them */
#define GL_GLEXT_PROTOTYPES 1
#include <string.h>

#include "fgl_alloc.h"
#include "main/groups.h"

/* ---- the shared table ---- */

bool fgl_init_bufobj(struct fgl_context *ctx)
{
   struct fgl_buffer_objects *bo = fgl_calloc_gl(ctx, 1, sizeof(*bo));
   if (!bo)
      return false;
   bo->Refs = 1;
   pthread_mutex_init(&bo->Lock, NULL);
   ctx->BufObjects = bo;
   return true;
}

/* One reference fewer; the last frees the object.  Under the lock. */
static void unref_locked(struct fgl_buffer_object *obj)
{
   if (!obj || --obj->RefCount != 0)
      return;
   fgl_free(obj->Data);
   fgl_free(obj);
}

void fgl_buffer_reference(struct fgl_context *ctx, struct fgl_buffer_object **slot,
                          struct fgl_buffer_object *obj)
{
   if (*slot == obj)
      return;
   pthread_mutex_lock(&ctx->BufObjects->Lock);
   if (obj)
      obj->RefCount++;
   unref_locked(*slot);
   pthread_mutex_unlock(&ctx->BufObjects->Lock);
   *slot = obj;
}

void fgl_buffer_hold_array(struct fgl_context *ctx, const struct fgl_array_attrib *a)
{
   pthread_mutex_lock(&ctx->BufObjects->Lock);
   for (int i = 0; i < FGL_ARRAY_COUNT; i++)
      if (a->Array[i].BufferObj)
         a->Array[i].BufferObj->RefCount++;
   if (a->ArrayBufferObj)
      a->ArrayBufferObj->RefCount++;
   if (a->ElementBufferObj)
      a->ElementBufferObj->RefCount++;
   pthread_mutex_unlock(&ctx->BufObjects->Lock);
}

void fgl_buffer_release_array(struct fgl_context *ctx, struct fgl_array_attrib *a)
{
   pthread_mutex_lock(&ctx->BufObjects->Lock);
   for (int i = 0; i < FGL_ARRAY_COUNT; i++) {
      unref_locked(a->Array[i].BufferObj);
      a->Array[i].BufferObj = NULL;
   }
   unref_locked(a->ArrayBufferObj);
   unref_locked(a->ElementBufferObj);
   a->ArrayBufferObj = a->ElementBufferObj = NULL;
   pthread_mutex_unlock(&ctx->BufObjects->Lock);
}

static void unref_table(struct fgl_buffer_objects *bo)
{
   pthread_mutex_lock(&bo->Lock);
   const bool last = --bo->Refs == 0;
   if (last) {
      for (unsigned i = 0; i < bo->Count; i++)
         unref_locked(bo->Entries[i].Obj);
   }
   pthread_mutex_unlock(&bo->Lock);
   if (!last)
      return;
   fgl_free(bo->Entries);
   pthread_mutex_destroy(&bo->Lock);
   fgl_free(bo);
}

/* [S: bufferobj.c:_mesa_free_buffer_objects] the context's bindings, then
 * its share of the table (after the client attribute stack, attrib.c) */
void fgl_free_bufobj(struct fgl_context *ctx)
{
   if (!ctx->BufObjects)
      return;
   fgl_buffer_release_array(ctx, &ctx->Array);
   unref_table(ctx->BufObjects);
   ctx->BufObjects = NULL;
}

/* OSMesaCreateContext's sharelist: the new context (which has bound
 * nothing yet) takes share's table */
void fgl_share_bufobjs(struct fgl_context *ctx, struct fgl_context *share)
{
   struct fgl_buffer_objects *bo = share->BufObjects;
   pthread_mutex_lock(&bo->Lock);
   bo->Refs++;
   pthread_mutex_unlock(&bo->Lock);
   unref_table(ctx->BufObjects);
   ctx->BufObjects = bo;
}

/* The entry of `name`, or where it would go (*found false).  Under the
 * lock. */
static unsigned find_locked(const struct fgl_buffer_objects *bo, GLuint name, bool *found)
{
   unsigned lo = 0, hi = bo->Count;
   while (lo < hi) {
      const unsigned mid = lo + (hi - lo) / 2;
      if (bo->Entries[mid].Name < name)
         lo = mid + 1;
      else
         hi = mid;
   }
   *found = lo < bo->Count && bo->Entries[lo].Name == name;
   return lo;
}

/* A new entry at position i (from find_locked); false when out of memory
 * (GL_OUT_OF_MEMORY raised).  Under the lock. */
static bool insert_locked(struct fgl_context *ctx, unsigned i, GLuint name,
                          struct fgl_buffer_object *obj)
{
   struct fgl_buffer_objects *bo = ctx->BufObjects;
   if (bo->Count == bo->Alloc) {
      const unsigned alloc = bo->Alloc ? 2 * bo->Alloc : 16;
      struct fgl_buffer_entry *e = fgl_realloc_gl(ctx, bo->Entries, alloc * sizeof(*e));
      if (!e)
         return false;
      bo->Entries = e;
      bo->Alloc = alloc;
   }
   memmove(&bo->Entries[i + 1], &bo->Entries[i], (bo->Count - i) * sizeof(bo->Entries[0]));
   bo->Entries[i] = (struct fgl_buffer_entry){ name, obj };
   bo->Count++;
   if (name > bo->MaxName)
      bo->MaxName = name;
   return true;
}

/* [S: bufferobj.c:_mesa_lookup_bufferobj] the object of `name`: NULL for
 * 0, an unknown name, or a name from glGenBuffers never bound */
static struct fgl_buffer_object *lookup(struct fgl_context *ctx, GLuint name, bool *exists)
{
   struct fgl_buffer_objects *bo = ctx->BufObjects;
   bool found = false;
   struct fgl_buffer_object *obj = NULL;
   if (name != 0) {
      pthread_mutex_lock(&bo->Lock);
      const unsigned i = find_locked(bo, name, &found);
      if (found)
         obj = bo->Entries[i].Obj;
      pthread_mutex_unlock(&bo->Lock);
   }
   if (exists)
      *exists = found;
   return obj;
}

/* The binding point of a target, or NULL for a target fixgl does not
 * have [S: bufferobj.c:get_buffer_target] */
static struct fgl_buffer_object **target_slot(struct fgl_context *ctx, GLenum target)
{
   switch (target) {
   case GL_ARRAY_BUFFER: return &ctx->Array.ArrayBufferObj;
   case GL_ELEMENT_ARRAY_BUFFER: return &ctx->Array.ElementBufferObj;
   default: return NULL;
   }
}

/* [S: bufferobj.c:get_buffer] the bound object, or NULL with
 * GL_INVALID_ENUM (target) or GL_INVALID_OPERATION (nothing bound) */
static struct fgl_buffer_object *get_buffer(struct fgl_context *ctx, GLenum target)
{
   struct fgl_buffer_object **slot = target_slot(ctx, target);
   if (!slot) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return NULL;
   }
   if (!*slot)
      fgl_error(ctx, GL_INVALID_OPERATION);
   return *slot;
}

/* [S: bufferobj.c:_mesa_buffer_unmap_all_mappings] */
static void unmap(struct fgl_buffer_object *obj)
{
   obj->MapPointer = NULL;
   obj->MapAccess = 0;
}

/* [S: bufferobj.c:bind_buffer_object, handle_bind_buffer_gen]: a name
 * without an object (new, or only generated) gets one now (the
 * compatibility profile takes any name) */
static void bind_buffer(struct fgl_context *ctx, struct fgl_buffer_object **slot, GLuint name)
{
   if (name == 0) {
      fgl_buffer_reference(ctx, slot, NULL);
      return;
   }
   const struct fgl_buffer_object *old = *slot;
   if (old && !old->DeletePending && old->Name == name)
      return;
   struct fgl_buffer_objects *bo = ctx->BufObjects;
   pthread_mutex_lock(&bo->Lock);
   bool found;
   const unsigned i = find_locked(bo, name, &found);
   struct fgl_buffer_object *obj = found ? bo->Entries[i].Obj : NULL;
   if (!obj) {
      obj = fgl_calloc_gl(ctx, 1, sizeof(*obj));
      if (!obj) {
         pthread_mutex_unlock(&bo->Lock);
         return;
      }
      obj->Name = name;
      obj->RefCount = 1;   /* the table's */
      obj->Usage = GL_STATIC_DRAW;
      if (found) {
         bo->Entries[i].Obj = obj;
      } else if (!insert_locked(ctx, i, name, obj)) {
         fgl_free(obj);
         pthread_mutex_unlock(&bo->Lock);
         return;
      }
   }
   pthread_mutex_unlock(&bo->Lock);
   fgl_buffer_reference(ctx, slot, obj);
}

void fgl_bind_buffer_name(struct fgl_context *ctx, GLenum target, GLuint name)
{
   bind_buffer(ctx, target_slot(ctx, target), name);
}

/* ---- entry points ---- */

void GLAPIENTRY glGenBuffers(GLsizei n, GLuint *buffers)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (n < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!buffers || n == 0)
      return;
   /* [S: hash.c:_mesa_HashFindFreeKeyBlock] past the largest name while
    * that stays below ~0 - 1, else the first block of free names from 1 */
   struct fgl_buffer_objects *bo = ctx->BufObjects;
   pthread_mutex_lock(&bo->Lock);
   GLuint first = 0;
   if (bo->MaxName < 0xFFFFFFFEu && (GLuint)n <= 0xFFFFFFFEu - bo->MaxName) {
      first = bo->MaxName + 1;
   } else {
      GLuint start = 1;
      for (unsigned i = 0; i <= bo->Count; i++) {
         const GLuint next = i < bo->Count ? bo->Entries[i].Name : 0xFFFFFFFEu;
         if (next >= start && next - start >= (GLuint)n) {
            first = start;
            break;
         }
         if (i == bo->Count)
            break;
         start = next + 1;
      }
   }
   if (first == 0) {
      pthread_mutex_unlock(&bo->Lock);
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   for (GLsizei k = 0; k < n; k++) {
      bool found;
      const unsigned i = find_locked(bo, first + (GLuint)k, &found);
      if (!insert_locked(ctx, i, first + (GLuint)k, NULL))
         break;
      buffers[k] = first + (GLuint)k;
   }
   pthread_mutex_unlock(&bo->Lock);
}

void GLAPIENTRY glBindBuffer(GLenum target, GLuint buffer)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   struct fgl_buffer_object **slot = target_slot(ctx, target);
   if (!slot) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   bind_buffer(ctx, slot, buffer);
}

/* [S: bufferobj.c:_mesa_IsBuffer] an object, not a generated name only */
GLboolean GLAPIENTRY glIsBuffer(GLuint buffer)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return GL_FALSE;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, GL_FALSE);
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, GL_FALSE);
   return lookup(ctx, buffer, NULL) != NULL;
}

/* [S: bufferobj.c:delete_buffers]: unmapped, unbound from this context's
 * vertex arrays (which keep their offsets, now client pointers) and
 * binding points, the name freed at once */
void GLAPIENTRY glDeleteBuffers(GLsizei n, const GLuint *buffers)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (n < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   if (!buffers)
      return;
   struct fgl_buffer_objects *bo = ctx->BufObjects;
   for (GLsizei k = 0; k < n; k++) {
      if (buffers[k] == 0)
         continue;
      pthread_mutex_lock(&bo->Lock);
      bool found;
      const unsigned i = find_locked(bo, buffers[k], &found);
      if (!found) {
         pthread_mutex_unlock(&bo->Lock);
         continue;
      }
      struct fgl_buffer_object *obj = bo->Entries[i].Obj;
      memmove(&bo->Entries[i], &bo->Entries[i + 1], (bo->Count - i - 1) * sizeof(bo->Entries[0]));
      bo->Count--;
      pthread_mutex_unlock(&bo->Lock);
      if (!obj)
         continue;   /* a generated name only */
      unmap(obj);
      struct fgl_array_attrib *a = &ctx->Array;
      for (int j = 0; j < FGL_ARRAY_COUNT; j++)
         if (a->Array[j].BufferObj == obj)
            fgl_buffer_reference(ctx, &a->Array[j].BufferObj, NULL);
      if (a->ArrayBufferObj == obj)
         fgl_buffer_reference(ctx, &a->ArrayBufferObj, NULL);
      if (a->ElementBufferObj == obj)
         fgl_buffer_reference(ctx, &a->ElementBufferObj, NULL);
      obj->DeletePending = true;
      pthread_mutex_lock(&bo->Lock);
      unref_locked(obj);   /* the name's reference */
      pthread_mutex_unlock(&bo->Lock);
   }
}

/* [S: bufferobj.c:buffer_data, bufferobj_data]: size, then usage; the
 * mapping is dropped (no error) and the store replaced.  A store of more
 * than 4 GB or one that cannot be allocated leaves the buffer empty with
 * GL_OUT_OF_MEMORY.  Without data the new store is zeros (the oracle's is
 * whatever its allocator returns). */
void GLAPIENTRY glBufferData(GLenum target, GLsizeiptr size, const GLvoid *data, GLenum usage)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   struct fgl_buffer_object *obj = get_buffer(ctx, target);
   if (!obj)
      return;
   if (size < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   switch (usage) {
   case GL_STREAM_DRAW: case GL_STREAM_READ: case GL_STREAM_COPY:
   case GL_STATIC_DRAW: case GL_STATIC_READ: case GL_STATIC_COPY:
   case GL_DYNAMIC_DRAW: case GL_DYNAMIC_READ: case GL_DYNAMIC_COPY:
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   unmap(obj);
   FGL_FLUSH_VERTICES(ctx, 0);
   const GLbitfield storage = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_DYNAMIC_STORAGE_BIT;
   if (size > 0 && obj->Data && obj->Size == size && obj->Usage == usage &&
       obj->StorageFlags == storage) {
      /* the same store again: rewritten in place */
      if (data)
         memcpy(obj->Data, data, (size_t)size);
      return;
   }
   if ((uint64_t)size > UINT32_MAX) {
      obj->Size = 0;
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   obj->Usage = usage;
   obj->StorageFlags = storage;
   fgl_free(obj->Data);
   obj->Data = NULL;
   obj->Size = 0;
   if (size == 0)
      return;
   uint8_t *store = data ? fgl_malloc_gl(ctx, (size_t)size) : fgl_calloc_gl(ctx, 1, (size_t)size);
   if (!store)
      return;
   if (data)
      memcpy(store, data, (size_t)size);
   obj->Data = store;
   obj->Size = size;
}

/* [S: bufferobj.c:buffer_object_subdata_range_good]: size, offset, the
 * range, then a mapping (of the range, or of the buffer at all) */
static bool range_good(struct fgl_context *ctx, const struct fgl_buffer_object *obj,
                       GLintptr offset, GLsizeiptr size)
{
   if (size < 0 || offset < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return false;
   }
   if ((uint64_t)offset + (uint64_t)size > (uint64_t)obj->Size) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return false;
   }
   /* the user's mapping is always the whole store: a range overlaps it
    * unless it ends at 0 or starts at its end (bufferobj_range_mapped) */
   if (obj->MapPointer && (uint64_t)offset + (uint64_t)size > 0 && offset < obj->Size) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return false;
   }
   return true;
}

void GLAPIENTRY glBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size,
                                const GLvoid *data)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   struct fgl_buffer_object *obj = get_buffer(ctx, target);
   if (!obj || !range_good(ctx, obj, offset, size))
      return;
   if (size == 0 || !data || !obj->Data)
      return;
   memcpy(obj->Data + offset, data, (size_t)size);
}

void GLAPIENTRY glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size,
                                   GLvoid *data)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   struct fgl_buffer_object *obj = get_buffer(ctx, target);
   if (!obj)
      return;
   if (size < 0 || offset < 0 || (uint64_t)offset + (uint64_t)size > (uint64_t)obj->Size) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   /* here any mapping is an error [S: buffer_object_subdata_range_good
    * with mappedRange false] */
   if (obj->MapPointer) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (size == 0 || !data || !obj->Data)
      return;
   memcpy(data, obj->Data + offset, (size_t)size);
}

/* [S: bufferobj.c:_mesa_MapBuffer, validate_map_buffer_range,
 * map_buffer_range]: the access, the target, then the whole store's
 * checks (an empty store is a zero length: GL_INVALID_OPERATION) */
void *GLAPIENTRY glMapBuffer(GLenum target, GLenum access)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return NULL;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, NULL);
   GLbitfield flags;
   switch (access) {
   case GL_READ_ONLY: flags = GL_MAP_READ_BIT; break;
   case GL_WRITE_ONLY: flags = GL_MAP_WRITE_BIT; break;
   case GL_READ_WRITE: flags = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT; break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return NULL;
   }
   struct fgl_buffer_object *obj = get_buffer(ctx, target);
   if (!obj)
      return NULL;
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, NULL);
   if (obj->Size == 0 || (flags & ~obj->StorageFlags) || obj->MapPointer) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return NULL;
   }
   obj->MapPointer = obj->Data;
   obj->MapAccess = flags;
   return obj->MapPointer;
}

GLboolean GLAPIENTRY glUnmapBuffer(GLenum target)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return GL_FALSE;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, GL_FALSE);
   struct fgl_buffer_object *obj = get_buffer(ctx, target);
   if (!obj)
      return GL_FALSE;
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, GL_FALSE);
   if (!obj->MapPointer) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return GL_FALSE;
   }
   unmap(obj);
   return GL_TRUE;
}

/* [S: bufferobj.c:get_buffer_parameter] the GL 1.5 values */
void GLAPIENTRY glGetBufferParameteriv(GLenum target, GLenum pname, GLint *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   const struct fgl_buffer_object *obj = get_buffer(ctx, target);
   if (!obj)
      return;
   GLint v;
   switch (pname) {
   case GL_BUFFER_SIZE: v = (GLint)obj->Size; break;
   case GL_BUFFER_USAGE: v = (GLint)obj->Usage; break;
   case GL_BUFFER_ACCESS:
      /* simplified_access_mode: unmapped reads GL_READ_WRITE */
      v = obj->MapAccess == GL_MAP_READ_BIT    ? GL_READ_ONLY
          : obj->MapAccess == GL_MAP_WRITE_BIT ? GL_WRITE_ONLY
                                               : GL_READ_WRITE;
      break;
   case GL_BUFFER_MAPPED: v = obj->MapPointer != NULL; break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (params)
      *params = v;
}

void GLAPIENTRY glGetBufferPointerv(GLenum target, GLenum pname, GLvoid **params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (pname != GL_BUFFER_MAP_POINTER) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   const struct fgl_buffer_object *obj = get_buffer(ctx, target);
   if (obj && params)
      *params = obj->MapPointer;
}

/* ---- the ARB names (GL_ARB_vertex_buffer_object) ---- */

void GLAPIENTRY glGenBuffersARB(GLsizei n, GLuint *buffers)
{
   glGenBuffers(n, buffers);
}

void GLAPIENTRY glBindBufferARB(GLenum target, GLuint buffer)
{
   glBindBuffer(target, buffer);
}

void GLAPIENTRY glDeleteBuffersARB(GLsizei n, const GLuint *buffers)
{
   glDeleteBuffers(n, buffers);
}

GLboolean GLAPIENTRY glIsBufferARB(GLuint buffer)
{
   return glIsBuffer(buffer);
}

void GLAPIENTRY glBufferDataARB(GLenum target, GLsizeiptrARB size, const GLvoid *data,
                                GLenum usage)
{
   glBufferData(target, size, data, usage);
}

void GLAPIENTRY glBufferSubDataARB(GLenum target, GLintptrARB offset, GLsizeiptrARB size,
                                   const GLvoid *data)
{
   glBufferSubData(target, offset, size, data);
}

void GLAPIENTRY glGetBufferSubDataARB(GLenum target, GLintptrARB offset, GLsizeiptrARB size,
                                      GLvoid *data)
{
   glGetBufferSubData(target, offset, size, data);
}

void *GLAPIENTRY glMapBufferARB(GLenum target, GLenum access)
{
   return glMapBuffer(target, access);
}

GLboolean GLAPIENTRY glUnmapBufferARB(GLenum target)
{
   return glUnmapBuffer(target);
}

void GLAPIENTRY glGetBufferParameterivARB(GLenum target, GLenum pname, GLint *params)
{
   glGetBufferParameteriv(target, pname, params);
}

void GLAPIENTRY glGetBufferPointervARB(GLenum target, GLenum pname, GLvoid **params)
{
   glGetBufferPointerv(target, pname, params);
}
