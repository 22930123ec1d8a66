/*
 * Texture objects and their parameters (Mesa 22.3
 * main/texobj.c, main/texparam.c): glGenTextures, glBindTexture,
 * glDeleteTextures, glIsTexture, glAreTexturesResident,
 * glPrioritizeTextures, glTexParameter{f,i}[v], glGetTexParameter{f,i}v.
 *
 * Names come from the shared hash's free-key search
 * (hash.c:_mesa_HashFindFreeKeyBlock: one past the largest name ever
 * used; texture objects do not enable name reuse), a generated name is an
 * object without a target until it is first bound (glIsTexture false), and
 * binding a name never generated creates it (compatibility profile).
 */
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "main/conv.h"
#include "main/dlist.h"
#include "main/groups.h"
#include "fgl_alloc.h"

/* [S: texobj.c:_mesa_initialize_texture_object] */
static void init_object(struct fgl_texture_object *t, GLuint name, GLenum target)
{
   memset(t, 0, sizeof(*t));
   t->Name = name;
   t->Target = target;
   t->MinFilter = GL_NEAREST_MIPMAP_LINEAR;
   t->MagFilter = GL_LINEAR;
   t->WrapS = t->WrapT = t->WrapR = GL_REPEAT;
   t->Priority = 1.0f;
   t->MinLod = -1000.0f;
   t->MaxLod = 1000.0f;
   t->MaxLevel = 1000;
   t->DepthMode = GL_LUMINANCE;
   t->CompareMode = GL_NONE;
   t->CompareFunc = GL_LEQUAL;
}

static const GLenum index_target[FGL_TEX_TARGETS] = {
   [FGL_TEX_1D] = GL_TEXTURE_1D, [FGL_TEX_2D] = GL_TEXTURE_2D,
   [FGL_TEX_3D] = GL_TEXTURE_3D, [FGL_TEX_CUBE] = GL_TEXTURE_CUBE_MAP,
};

/* [S: shared.c:_mesa_alloc_shared_state] the object table and the
 * default objects of a new context; false when out of memory */
bool fgl_init_texobj(struct fgl_context *ctx)
{
   struct fgl_texture_objects *to = fgl_calloc_gl(ctx, 1, sizeof(*to));
   if (!to)
      return false;
   for (int i = 0; i < FGL_TEX_TARGETS; i++)
      init_object(&to->Default[i], 0, index_target[i]);
   to->Refs = 1;
   pthread_mutex_init(&to->Lock, NULL);
   atomic_init(&to->Stamp, 0u);
   ctx->TexObjects = to;
   memset(&ctx->TexLocal, 0, sizeof(ctx->TexLocal));
   init_object(&ctx->TexLocal.Proxy[0], 0, GL_PROXY_TEXTURE_1D);
   init_object(&ctx->TexLocal.Proxy[1], 0, GL_PROXY_TEXTURE_2D);
   init_object(&ctx->TexLocal.Proxy[2], 0, GL_PROXY_TEXTURE_3D);
   init_object(&ctx->TexLocal.Proxy[3], 0, GL_PROXY_TEXTURE_CUBE_MAP);
   return true;
}

/* [S: texobj.c:_mesa_reference_texobj_] one reference fewer; the last
 * frees the object and its images.  The caller holds the table's lock. */
static void unref_object_locked(struct fgl_texture_object *t)
{
   if (--t->RefCount != 0)
      return;
   fgl_free_tex_images(t);
   fgl_free(t);
}

/* [S: shared.c:free_shared_state] the last context drops the table's
 * references (the contexts' bindings are gone by then) */
static void unref_shared(struct fgl_texture_objects *to)
{
   pthread_mutex_lock(&to->Lock);
   const bool last = --to->Refs == 0;
   pthread_mutex_unlock(&to->Lock);
   if (!last)
      return;
   for (unsigned i = 0; i < to->Count; i++)
      unref_object_locked(to->Objs[i]);
   fgl_free(to->Objs);
   for (int i = 0; i < FGL_TEX_TARGETS; i++)
      fgl_free_tex_images(&to->Default[i]);
   pthread_mutex_destroy(&to->Lock);
   fgl_free(to);
}

/* [S: texstate.c:_mesa_free_texture_data] the context's bindings drop
 * their references before the shared table goes */
void fgl_free_texobj(struct fgl_context *ctx)
{
   if (ctx->TexObjects) {
      pthread_mutex_lock(&ctx->TexObjects->Lock);
      for (int u = 0; u < FGL_MAX_COMBINED_TEXTURE_UNITS; u++)
         for (int x = 0; x < FGL_TEX_TARGETS; x++)
            if (ctx->TexLocal.Current[u][x])
               unref_object_locked(ctx->TexLocal.Current[u][x]);
      pthread_mutex_unlock(&ctx->TexObjects->Lock);
      memset(ctx->TexLocal.Current, 0, sizeof(ctx->TexLocal.Current));
      unref_shared(ctx->TexObjects);
   }
   ctx->TexObjects = NULL;
   fgl_free_tex_images(&ctx->TexLocal.Proxy[0]);
   fgl_free_tex_images(&ctx->TexLocal.Proxy[1]);
   fgl_free_tex_images(&ctx->TexLocal.Proxy[2]);
   fgl_free_tex_images(&ctx->TexLocal.Proxy[3]);
}

/* OSMesaCreateContext's sharelist: the new context (which has bound
 * nothing yet) takes share's objects and default objects
 * [S: context.c:_mesa_initialize_context, shared state] */
void fgl_share_texobjs(struct fgl_context *ctx, struct fgl_context *share)
{
   struct fgl_texture_objects *to = share->TexObjects;
   pthread_mutex_lock(&to->Lock);
   to->Refs++;
   pthread_mutex_unlock(&to->Lock);
   unref_shared(ctx->TexObjects);
   ctx->TexObjects = to;
}

/* [S: texobj.c:_mesa_tex_target_to_index] -1 for other targets.  GL
 * 1.5's targets only: the oracle's rectangle and array targets are not
 * enums of GL 1.5 without those extensions (README "Version and
 * honesty"), so no object ever has them. */
static int target_index(GLenum target)
{
   for (int i = 0; i < FGL_TEX_TARGETS; i++)
      if (index_target[i] == target)
         return i;
   return -1;
}

/* the object named `name`; the caller holds the table's lock */
static struct fgl_texture_object *lookup_locked(struct fgl_context *ctx, GLuint name)
{
   struct fgl_texture_objects *to = ctx->TexObjects;
   for (unsigned i = 0; i < to->Count; i++)
      if (to->Objs[i]->Name == name)
         return to->Objs[i];
   return NULL;
}

/* _mesa_lookup_texture: under the lock of the shared table */
static struct fgl_texture_object *lookup(struct fgl_context *ctx, GLuint name)
{
   pthread_mutex_lock(&ctx->TexObjects->Lock);
   struct fgl_texture_object *t = lookup_locked(ctx, name);
   pthread_mutex_unlock(&ctx->TexObjects->Lock);
   return t;
}

static struct fgl_texture_object *insert(struct fgl_context *ctx, GLuint name, GLenum target)
{
   struct fgl_texture_objects *to = ctx->TexObjects;
   if (to->Count == to->Alloc) {
      const unsigned alloc = to->Alloc ? to->Alloc * 2 : 16;
      struct fgl_texture_object **objs = fgl_realloc_gl(ctx, to->Objs, alloc * sizeof(*objs));
      if (!objs)
         return NULL;
      to->Objs = objs;
      to->Alloc = alloc;
   }
   struct fgl_texture_object *t = fgl_malloc_gl(ctx, sizeof(*t));
   if (!t)
      return NULL;
   init_object(t, name, target);
   t->RefCount = 1;   /* the table's */
   to->Objs[to->Count++] = t;
   if (name > to->MaxName)
      to->MaxName = name;
   return t;
}

/* The object bound to target's index on a unit: the one its binding
 * references, which outlives a glDeleteTextures of its name in another
 * context sharing the table (texture/image_sharing_delete_bound). */
static struct fgl_texture_object *unit_object(struct fgl_context *ctx, unsigned unit,
                                              int index)
{
   struct fgl_texture_object *t = ctx->TexLocal.Current[unit][index];
   return t ? t : &ctx->TexObjects->Default[index];
}

static struct fgl_texture_object *current_object(struct fgl_context *ctx, int index)
{
   return unit_object(ctx, ctx->Texture.CurrentUnit, index);
}

struct fgl_texture_object *fgl_bound_texture(struct fgl_context *ctx, unsigned unit,
                                             GLenum target)
{
   return unit_object(ctx, unit, target_index(target));
}

/* the names bound to a unit (units 8..191 keep them apart) */
static GLuint *unit_names(struct fgl_context *ctx, unsigned unit)
{
   return unit < FGL_MAX_TEXTURE_UNITS ? ctx->Texture.Unit[unit].Bound
                                       : ctx->Texture.ImageBound[unit - FGL_MAX_TEXTURE_UNITS];
}

/* [S: texobj.c:bind_texture_object, _mesa_reference_texobj] unit's
 * binding of index references t (NULL: the default object) and reports
 * its name; the caller holds the table's lock */
static void set_binding_locked(struct fgl_context *ctx, unsigned unit, int index,
                               struct fgl_texture_object *t)
{
   struct fgl_texture_object **cur = &ctx->TexLocal.Current[unit][index];
   if (t)
      t->RefCount++;
   if (*cur)
      unref_object_locked(*cur);
   *cur = t;
   unit_names(ctx, unit)[index] = t ? t->Name : 0;
}

/* FLUSH_VERTICES(ctx, _NEW_TEXTURE_OBJECT, GL_TEXTURE_BIT): the change
 * also marks the group for glPopAttrib.  `object`: an object's own state
 * changed (a parameter), which the contexts sharing it are told of
 * (fgl_tex_object_changed); a binding, deletion or priority is this
 * context's alone. */
static void tex_flush(struct fgl_context *ctx, bool object)
{
   fgl_flush_vertices(ctx);
   if (object)
      fgl_tex_object_changed(ctx);
   else
      ctx->NewState |= FGL_NEW_TEXTURE;
   ctx->PopAttribState |= GL_TEXTURE_BIT;
}

/* ---- objects ---- */

/* [S: texobj.c:create_textures] */
static int cmp_name(const void *a, const void *b)
{
   const GLuint x = *(const GLuint *)a, y = *(const GLuint *)b;
   return x < y ? -1 : x > y;
}

/* The slow search of _mesa_HashFindFreeKeyBlock: the first n consecutive
 * unused names from 1, below ~0 - 1; 0 if there are none (or no memory
 * to look). */
static GLuint find_free_block(const struct fgl_texture_objects *to, GLuint n)
{
   GLuint *names = fgl_malloc((to->Count ? to->Count : 1) * sizeof(*names));
   if (!names)
      return 0;
   for (unsigned i = 0; i < to->Count; i++)
      names[i] = to->Objs[i]->Name;
   qsort(names, to->Count, sizeof(*names), cmp_name);
   const GLuint max_key = 0xFFFFFFFEu;
   GLuint start = 1, found = 0;
   for (unsigned i = 0; i <= to->Count; i++) {
      const GLuint next = i < to->Count && names[i] < max_key ? names[i] : max_key;
      if (next >= start && next - start >= n) {
         found = start;
         break;
      }
      if (next == max_key)
         break;
      if (next >= start)
         start = next + 1;
   }
   fgl_free(names);
   return found;
}

void GLAPIENTRY glGenTextures(GLsizei n, GLuint *textures)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   /* not allowed between glBegin and glEnd (the oracle's begin/end
    * dispatch), before anything else; while a list is compiled the save
    * dispatch calls _mesa_GenTextures itself, which has no such check */
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (n < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!textures || n == 0)
      return;
   /* [S: hash.c:_mesa_HashFindFreeKeyBlock] past the largest key while
    * that stays below ~0 - 1, else the first block of free names from 1 */
   struct fgl_texture_objects *to = ctx->TexObjects;
   pthread_mutex_lock(&to->Lock);
   const GLuint first = to->MaxName < 0xFFFFFFFEu && (GLuint)n <= 0xFFFFFFFEu - to->MaxName
                        ? to->MaxName + 1 : find_free_block(to, (GLuint)n);
   if (first == 0) {
      pthread_mutex_unlock(&to->Lock);
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   for (GLsizei i = 0; i < n; i++) {
      if (!insert(ctx, first + (GLuint)i, 0)) {
         pthread_mutex_unlock(&to->Lock);
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return;
      }
      textures[i] = first + (GLuint)i;
   }
   pthread_mutex_unlock(&to->Lock);
}

/* [S: texobj.c:_mesa_BindTexture, _mesa_lookup_or_create_texture,
 * bind_texture] */
void GLAPIENTRY glBindTexture(GLenum target, GLuint texture)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, BindTexture, target, texture);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const int index = target_index(target);
   if (index < 0) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   struct fgl_texture_object *t = NULL;
   pthread_mutex_lock(&ctx->TexObjects->Lock);
   if (texture != 0) {
      t = lookup_locked(ctx, texture);
      if (t) {
         if (t->Target != 0 && t->Target != target) {
            pthread_mutex_unlock(&ctx->TexObjects->Lock);
            fgl_error(ctx, GL_INVALID_OPERATION);
            return;
         }
         if (t->Target == 0) {
            /* [S: texobj.c:finish_texture_init] the target (the
             * rectangle's clamped wraps and linear filters do not arise);
             * other parameters (a priority set before the first bind) stay */
            t->Target = target;
         }
      } else if (!(t = insert(ctx, texture, target))) {
         pthread_mutex_unlock(&ctx->TexObjects->Lock);
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return;
      }
   }
   /* bind_texture: nothing when the object is already bound (no flush);
    * an object deleted in another context keeps its name on the unit, and
    * binding the name again binds the new object of that name */
   if (ctx->TexLocal.Current[ctx->Texture.CurrentUnit][index] == t) {
      pthread_mutex_unlock(&ctx->TexObjects->Lock);
      return;
   }
   tex_flush(ctx, false);
   set_binding_locked(ctx, ctx->Texture.CurrentUnit, index, t);
   pthread_mutex_unlock(&ctx->TexObjects->Lock);
   if (ctx->TexLocal.NumCurrentTexUsed < ctx->Texture.CurrentUnit + 1)
      ctx->TexLocal.NumCurrentTexUsed = ctx->Texture.CurrentUnit + 1;
}

/* [S: texobj.c:delete_textures, unbind_texobj_from_texunits] */
void GLAPIENTRY glDeleteTextures(GLsizei n, const GLuint *textures)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_flush_vertices(ctx);
   fgl_scene_flush(ctx);   /* the scene may sample the images */
   if (n < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!textures)
      return;
   struct fgl_texture_objects *to = ctx->TexObjects;
   pthread_mutex_lock(&to->Lock);
   for (GLsizei i = 0; i < n; i++) {
      if (textures[i] == 0)
         continue;
      for (unsigned k = 0; k < to->Count; k++) {
         struct fgl_texture_object *t = to->Objs[k];
         if (t->Name != textures[i])
            continue;
         /* every unit of this context bound to it goes back to the
          * default object (FLUSH_VERTICES(_NEW_TEXTURE_OBJECT)); other
          * contexts keep their references */
         for (unsigned u = 0; u < FGL_MAX_COMBINED_TEXTURE_UNITS; u++)
            for (int x = 0; x < FGL_TEX_TARGETS; x++)
               if (ctx->TexLocal.Current[u][x] == t) {
                  tex_flush(ctx, false);
                  set_binding_locked(ctx, u, x, NULL);
               }
         /* the name goes from the table with the table's reference */
         to->Objs[k] = to->Objs[--to->Count];
         unref_object_locked(t);
         break;
      }
   }
   pthread_mutex_unlock(&to->Lock);
}

/* [S: texobj.c:_mesa_IsTexture] only an object bound once has a target */
GLboolean GLAPIENTRY glIsTexture(GLuint texture)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return GL_FALSE;
   if (fgl_inside_begin_end(ctx)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return GL_FALSE;
   }
   if (!texture)
      return GL_FALSE;
   const struct fgl_texture_object *t = lookup(ctx, texture);
   return t && t->Target ? GL_TRUE : GL_FALSE;
}

/* [S: texobj.c:_mesa_AreTexturesResident] every object is resident;
 * residences is never written */
GLboolean GLAPIENTRY glAreTexturesResident(GLsizei n, const GLuint *textures,
                                           GLboolean *residences)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return GL_FALSE;
   if (fgl_inside_begin_end(ctx)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return GL_FALSE;
   }
   if (n < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return GL_FALSE;
   }
   if (!textures || !residences)
      return GL_FALSE;
   for (GLsizei i = 0; i < n; i++) {
      if (textures[i] == 0 || !lookup(ctx, textures[i])) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return GL_FALSE;
      }
   }
   return GL_TRUE;
}

/* [S: texobj.c:_mesa_PrioritizeTextures] names without an object are
 * skipped silently */
void GLAPIENTRY glPrioritizeTextures(GLsizei n, const GLuint *textures,
                                     const GLclampf *priorities)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      /* [S: dlist.c:save_PrioritizeTextures] the begin/end check, a node
       * per name (none for n <= 0), then the call itself under
       * GL_COMPILE_AND_EXECUTE */
      if (!fgl_save_prioritize_textures(ctx, n, textures, priorities))
         return;
   }
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (n < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!priorities)
      return;
   tex_flush(ctx, false);
   for (GLsizei i = 0; i < n; i++) {
      if (textures[i] == 0)
         continue;
      struct fgl_texture_object *t = lookup(ctx, textures[i]);
      if (t)
         t->Priority = fminf(fmaxf(priorities[i], 0.0f), 1.0f);   /* CLAMP */
   }
}

/* ---- parameters ---- */

/* [S: texparam.c:get_texobj_by_target] the targets glTexParameter takes
 * (proxy targets and the others are INVALID_ENUM) */
static struct fgl_texture_object *param_object(struct fgl_context *ctx, GLenum target)
{
   const int index = target_index(target);
   if (index < 0) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return NULL;
   }
   return current_object(ctx, index);
}

/* [S: texparam.c:validate_texture_wrap_mode] */
static bool valid_wrap(GLint wrap)
{
   if (wrap == GL_CLAMP || wrap == GL_CLAMP_TO_EDGE || wrap == GL_CLAMP_TO_BORDER)
      return true;
   return wrap == GL_REPEAT || wrap == GL_MIRRORED_REPEAT ||
          wrap == GL_MIRROR_CLAMP_EXT || wrap == GL_MIRROR_CLAMP_TO_EDGE ||
          wrap == GL_MIRROR_CLAMP_TO_BORDER_EXT;
}

/* [S: texparam.c:set_tex_parameteri] the integer pnames (GL 1.3 and
 * GL_GENERATE_MIPMAP); a value equal to the current one changes nothing */
static void set_parameteri(struct fgl_context *ctx, struct fgl_texture_object *t,
                           GLenum pname, GLint v)
{
   GLenum *wrap = NULL;
   switch (pname) {
   case GL_TEXTURE_MIN_FILTER:
      if ((GLint)t->MinFilter == v)
         return;
      switch (v) {
      case GL_NEAREST_MIPMAP_NEAREST:
      case GL_LINEAR_MIPMAP_NEAREST:
      case GL_NEAREST_MIPMAP_LINEAR:
      case GL_LINEAR_MIPMAP_LINEAR:
      case GL_NEAREST:
      case GL_LINEAR:
         tex_flush(ctx, true);
         t->MinFilter = (GLenum)v;
         return;
      }
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   case GL_TEXTURE_MAG_FILTER:
      if ((GLint)t->MagFilter == v)
         return;
      if (v != GL_NEAREST && v != GL_LINEAR) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      tex_flush(ctx, true);
      t->MagFilter = (GLenum)v;
      return;
   case GL_TEXTURE_WRAP_S: wrap = &t->WrapS; break;
   case GL_TEXTURE_WRAP_T: wrap = &t->WrapT; break;
   case GL_TEXTURE_WRAP_R: wrap = &t->WrapR; break;
   case GL_TEXTURE_BASE_LEVEL:
      if (t->BaseLevel == v)
         return;
      if (v < 0) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return;
      }
      tex_flush(ctx, true);
      t->BaseLevel = v;
      return;
   case GL_TEXTURE_MAX_LEVEL:
      if (t->MaxLevel == v)
         return;
      if (v < 0) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return;
      }
      tex_flush(ctx, true);
      t->MaxLevel = v;
      return;
   case GL_GENERATE_MIPMAP:
      t->GenerateMipmap = v != 0;   /* no flush */
      return;
   case GL_TEXTURE_COMPARE_MODE:
      /* ARB_shadow; GL_COMPARE_R_TO_TEXTURE is GL_COMPARE_REF_TO_TEXTURE */
      if ((GLint)t->CompareMode == v)
         return;
      if (v != GL_NONE && v != GL_COMPARE_R_TO_TEXTURE) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      tex_flush(ctx, true);
      t->CompareMode = (GLenum)v;
      return;
   case GL_TEXTURE_COMPARE_FUNC:
      /* the eight functions (GL 1.5, EXT_shadow_funcs) */
      if ((GLint)t->CompareFunc == v)
         return;
      if (v < GL_NEVER || v > GL_ALWAYS) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      tex_flush(ctx, true);
      t->CompareFunc = (GLenum)v;
      return;
   case GL_DEPTH_TEXTURE_MODE:
      /* ARB_depth_texture's three; GL_RED is ARB_texture_rg's (GL 3.0),
       * which fixgl does not list: GL_INVALID_ENUM (the oracle accepts
       * it; honesty/depth_texture_mode_red) */
      if ((GLint)t->DepthMode == v)
         return;
      if (v != GL_LUMINANCE && v != GL_INTENSITY && v != GL_ALPHA) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      tex_flush(ctx, true);
      t->DepthMode = (GLenum)v;
      return;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if ((GLint)*wrap == v)
      return;
   if (!valid_wrap(v)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   tex_flush(ctx, true);
   *wrap = (GLenum)v;
}

/* [S: texparam.c:set_tex_parameterf] the float pnames; the border colour
 * is clamped to [0,1] (llvmpipe's compatibility context has no
 * ARB_texture_float) */
static void set_parameterf(struct fgl_context *ctx, struct fgl_texture_object *t,
                           GLenum pname, const float *v)
{
   switch (pname) {
   case GL_TEXTURE_MIN_LOD:
      if (t->MinLod == v[0])
         return;
      tex_flush(ctx, true);
      t->MinLod = v[0];
      return;
   case GL_TEXTURE_MAX_LOD:
      if (t->MaxLod == v[0])
         return;
      tex_flush(ctx, true);
      t->MaxLod = v[0];
      return;
   case GL_TEXTURE_PRIORITY:
      tex_flush(ctx, true);
      t->Priority = fgl_clamp01(v[0]);
      return;
   case GL_TEXTURE_LOD_BIAS:
      if (t->LodBias == v[0])
         return;
      tex_flush(ctx, true);
      t->LodBias = v[0];
      return;
   case GL_TEXTURE_BORDER_COLOR:
      tex_flush(ctx, true);
      for (int c = 0; c < 4; c++)
         t->BorderColor[c] = fgl_clamp01(v[c]);
      return;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
}

static bool int_pname(GLenum pname)
{
   switch (pname) {
   case GL_TEXTURE_MIN_FILTER:
   case GL_TEXTURE_MAG_FILTER:
   case GL_TEXTURE_WRAP_S:
   case GL_TEXTURE_WRAP_T:
   case GL_TEXTURE_WRAP_R:
   case GL_TEXTURE_BASE_LEVEL:
   case GL_TEXTURE_MAX_LEVEL:
   case GL_GENERATE_MIPMAP:
   case GL_TEXTURE_COMPARE_MODE:
   case GL_TEXTURE_COMPARE_FUNC:
   case GL_DEPTH_TEXTURE_MODE:
      return true;
   default:
      return false;
   }
}

/* [S: texparam.c:_mesa_texture_parameterfv] integer pnames take the value
 * cast to GLint; the scalar glTexParameterf rounds instead and refuses the
 * border colour */
static void tex_parameterfv(struct fgl_context *ctx, GLenum target, GLenum pname,
                            const GLfloat *params, bool scalar)
{
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   struct fgl_texture_object *t = param_object(ctx, target);
   if (!t)
      return;
   if (int_pname(pname)) {
      GLint v;
      const float p = params[0];
      if (scalar) {
         /* [S: texparam.c:_mesa_texture_parameterf] (param > 0) ?
          * floor(param + 0.5) : ceil(param - 0.5), clamped to the int
          * range by float compares with INT_MAX and INT_MIN, which are
          * 2^31 and -2^31 as floats: so 2^31 itself is not clamped and
          * converts as x86 converts it, to INT_MIN, as does a NaN */
         v = isnan(p) ? INT_MIN
             : p > 0 ? (p > 2147483648.0f ? INT_MAX
                        : p == 2147483648.0f ? INT_MIN : (GLint)floor(p + 0.5))
                     : (p < -2147483648.0f ? INT_MIN : (GLint)ceil(p - 0.5));
      } else {
         /* (GLint)params[0]: the x86 conversion, INT_MIN when out of
          * range or NaN */
         v = p > -2147483649.0f && p < 2147483648.0f ? (GLint)p : INT_MIN;
      }
      set_parameteri(ctx, t, pname, v);
      return;
   }
   if (scalar && pname == GL_TEXTURE_BORDER_COLOR) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   float p[4] = { params[0], 0.0f, 0.0f, 0.0f };
   if (pname == GL_TEXTURE_BORDER_COLOR)
      memcpy(p, params, sizeof(p));
   set_parameterf(ctx, t, pname, p);
}

/* [S: texparam.c:_mesa_texture_parameteriv] float pnames take the value
 * converted to float, the border colour normalized (INT_TO_FLOAT) */
static void tex_parameteriv(struct fgl_context *ctx, GLenum target, GLenum pname,
                            const GLint *params, bool scalar)
{
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   struct fgl_texture_object *t = param_object(ctx, target);
   if (!t)
      return;
   if (int_pname(pname)) {
      set_parameteri(ctx, t, pname, params[0]);
      return;
   }
   if (pname == GL_TEXTURE_BORDER_COLOR) {
      if (scalar) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      const float c[4] = { INT_TO_FLOAT(params[0]), INT_TO_FLOAT(params[1]),
                           INT_TO_FLOAT(params[2]), INT_TO_FLOAT(params[3]) };
      set_parameterf(ctx, t, pname, c);
      return;
   }
   const float p[4] = { (GLfloat)params[0], 0.0f, 0.0f, 0.0f };
   set_parameterf(ctx, t, pname, p);
}

/* While compiling, every variant is stored as glTexParameterfv with
 * params[0] converted to float and the rest 0 (dlist.c:save_TexParameteri,
 * save_TexParameteriv: an integer border colour loses three components);
 * glTexParameterfv keeps four values.  Under GL_COMPILE_AND_EXECUTE
 * that glTexParameterfv is what executes (save_TexParameterfv), so the
 * scalar calls take a border colour there. */
void GLAPIENTRY glTexParameterf(GLenum target, GLenum pname, GLfloat param)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const GLfloat p[4] = { param, 0.0f, 0.0f, 0.0f };
   FGL_SAVE(ctx, TexParameterfv, target, pname, p, 4);
   tex_parameterfv(ctx, target, pname, p, !ctx->CompileFlag);
}

void GLAPIENTRY glTexParameterfv(GLenum target, GLenum pname, const GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx || !params)
      return;
   FGL_SAVE(ctx, TexParameterfv, target, pname, params,
            pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1);
   tex_parameterfv(ctx, target, pname, params, false);
}

void GLAPIENTRY glTexParameteri(GLenum target, GLenum pname, GLint param)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const GLfloat f[4] = { (GLfloat)param, 0.0f, 0.0f, 0.0f };
   FGL_SAVE(ctx, TexParameterfv, target, pname, f, 4);
   if (ctx->CompileFlag)
      tex_parameterfv(ctx, target, pname, f, false);
   else
      tex_parameteriv(ctx, target, pname, &param, true);
}

void GLAPIENTRY glTexParameteriv(GLenum target, GLenum pname, const GLint *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx || !params)
      return;
   const GLfloat f[4] = { (GLfloat)params[0], 0.0f, 0.0f, 0.0f };
   FGL_SAVE(ctx, TexParameterfv, target, pname, f, 4);
   if (ctx->CompileFlag)
      tex_parameterfv(ctx, target, pname, f, false);
   else
      tex_parameteriv(ctx, target, pname, params, false);
}

/* [S: texparam.c:get_tex_parameterfv, get_tex_parameteriv] the GL 1.3
 * pnames; GL_TEXTURE_RESIDENT is always true */
static bool get_parameter(struct fgl_context *ctx, GLenum target, GLenum pname,
                          float f[4], GLint i[4], bool *is_float, int *count)
{
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, false);
   struct fgl_texture_object *t = param_object(ctx, target);
   if (!t)
      return false;
   *count = 1;
   *is_float = false;
   switch (pname) {
   case GL_TEXTURE_MIN_FILTER: i[0] = (GLint)t->MinFilter; break;
   case GL_TEXTURE_MAG_FILTER: i[0] = (GLint)t->MagFilter; break;
   case GL_TEXTURE_WRAP_S: i[0] = (GLint)t->WrapS; break;
   case GL_TEXTURE_WRAP_T: i[0] = (GLint)t->WrapT; break;
   case GL_TEXTURE_WRAP_R: i[0] = (GLint)t->WrapR; break;
   case GL_TEXTURE_BASE_LEVEL: i[0] = t->BaseLevel; break;
   case GL_TEXTURE_MAX_LEVEL: i[0] = t->MaxLevel; break;
   case GL_GENERATE_MIPMAP: i[0] = t->GenerateMipmap; break;
   case GL_TEXTURE_COMPARE_MODE: i[0] = (GLint)t->CompareMode; break;
   case GL_TEXTURE_COMPARE_FUNC: i[0] = (GLint)t->CompareFunc; break;
   case GL_DEPTH_TEXTURE_MODE: i[0] = (GLint)t->DepthMode; break;
   case GL_TEXTURE_RESIDENT: i[0] = GL_TRUE; break;
   case GL_TEXTURE_BORDER_COLOR:
      memcpy(f, t->BorderColor, 4 * sizeof(float));
      *count = 4;
      *is_float = true;
      break;
   case GL_TEXTURE_PRIORITY: f[0] = t->Priority; *is_float = true; break;
   case GL_TEXTURE_MIN_LOD: f[0] = t->MinLod; *is_float = true; break;
   case GL_TEXTURE_MAX_LOD: f[0] = t->MaxLod; *is_float = true; break;
   case GL_TEXTURE_LOD_BIAS: f[0] = t->LodBias; *is_float = true; break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return false;
   }
   return true;
}

void GLAPIENTRY glGetTexParameterfv(GLenum target, GLenum pname, GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   float f[4];
   GLint i[4];
   bool is_float;
   int count;
   if (!get_parameter(ctx, target, pname, f, i, &is_float, &count) || !params)
      return;
   for (int c = 0; c < count; c++)
      params[c] = is_float ? f[c] : (GLfloat)i[c];
}

/* integer queries of float values: rounded, the border colour through
 * CLAMP then FLOAT_TO_INT, the priority FLOAT_TO_INT
 * [S: texparam.c:get_tex_parameteriv] */
void GLAPIENTRY glGetTexParameteriv(GLenum target, GLenum pname, GLint *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   float f[4];
   GLint i[4];
   bool is_float;
   int count;
   if (!get_parameter(ctx, target, pname, f, i, &is_float, &count) || !params)
      return;
   for (int c = 0; c < count; c++) {
      if (!is_float)
         params[c] = i[c];
      else if (pname == GL_TEXTURE_BORDER_COLOR || pname == GL_TEXTURE_PRIORITY)
         params[c] = fgl_float_to_int_norm(fgl_clamp01(f[c]));   /* FLOAT_TO_INT */
      else   /* LCLAMPF: the nearest integer, clamped to GLint's range */
         params[c] = f[c] >= 2147483647.0f ? 2147483647
                   : f[c] <= -2147483648.0f ? (GLint)-2147483647 - 1
                   : (GLint)(f[c] >= 0.0f ? f[c] + 0.5f : f[c] - 0.5f);
   }
}

/* ---- GL_TEXTURE_BIT ---- */

/* [S: attrib.c:_mesa_PushAttrib] the default objects always; once a
 * texture has been bound (NumCurrentTexUsed > 0) unit 0's LOD bias and a
 * copy of each object bound to unit 0 (fixgl keeps unit 0's only; the
 * other units' bindings are restored by the group's copy).
 * Otherwise the node keeps what an earlier push at the same depth left
 * (the node is allocated zeroed once). */
void fgl_save_texobjs(struct fgl_context *ctx, struct fgl_attrib_node *node)
{
   memcpy(node->TexDefault, ctx->TexObjects->Default, sizeof(node->TexDefault));
   node->TexSaved = ctx->TexLocal.NumCurrentTexUsed > 0;
   if (!node->TexSaved)
      return;
   node->TexLodBias = ctx->Texture.Unit[0].LodBias;
   for (int x = 0; x < FGL_TEX_TARGETS; x++)
      node->TexObj[x] = *current_object(ctx, x);
}

/* t's parameters from a glPushAttrib copy, keeping what is not state of
 * GL_TEXTURE_BIT: the images (every face's) and the oracle's storage
 * (main/teximage.c "Storage") */
static void restore_params(struct fgl_texture_object *t, const struct fgl_texture_object *saved)
{
   struct fgl_texture_object keep = *t;
   *t = *saved;
   memcpy(t->Image, keep.Image, sizeof(t->Image));
   memcpy(t->FaceImage, keep.FaceImage, sizeof(t->FaceImage));
   t->Storage = keep.Storage;
   t->StorageIds = keep.StorageIds;
}

/* [S: attrib.c:pop_texture_group] after the bindings are restored (a
 * unit not saved had nothing but default objects bound at the push): the
 * LOD bias from the node, saved or not; for a saved unit each bound named
 * object gets the saved parameters back (a deleted one is created again
 * by the rebind); then the default objects get theirs back */
void fgl_restore_texobjs(struct fgl_context *ctx, const struct fgl_attrib_node *node)
{
   /* the group's copy restored the bound names: a unit whose object has
    * another name binds the name again (_mesa_BindTexture_no_error: the
    * object of that name, or a new one when it was deleted); one that
    * still has the name keeps its object, deleted elsewhere or not */
   pthread_mutex_lock(&ctx->TexObjects->Lock);
   for (unsigned u = 0; u < FGL_MAX_COMBINED_TEXTURE_UNITS; u++)
      for (int x = 0; x < FGL_TEX_TARGETS; x++) {
         const GLuint name = unit_names(ctx, u)[x];
         struct fgl_texture_object *cur = ctx->TexLocal.Current[u][x];
         if ((cur ? cur->Name : 0) == name)
            continue;
         struct fgl_texture_object *t = NULL;
         if (name != 0 && !(t = lookup_locked(ctx, name)))
            t = insert(ctx, name, index_target[x]);
         set_binding_locked(ctx, u, x, t);
      }
   pthread_mutex_unlock(&ctx->TexObjects->Lock);
   ctx->Texture.Unit[0].LodBias = node->TexLodBias;
   if (node->TexSaved) {
      const struct fgl_texture_object *saved = node->TexObj;
      for (int x = 0; x < FGL_TEX_TARGETS; x++) {
         struct fgl_texture_object *t = ctx->TexLocal.Current[0][x];
         if (t && saved[x].Name == t->Name) {
            const unsigned refs = t->RefCount;
            restore_params(t, &saved[x]);
            t->RefCount = refs;
         }
      }
   }
   for (int x = 0; x < FGL_TEX_TARGETS; x++) {
      restore_params(&ctx->TexObjects->Default[x], &node->TexDefault[x]);
   }
}
