/*
 * Hints (GL_HINT_BIT): glHint.  Mesa's main/hint.c in a compatibility
 * context: the mode is checked first, then the target; an unchanged hint
 * is a no-op.  The values are only stored and reported: llvmpipe's
 * rendering depends on none of them (GL_FOG_HINT included; the fog cases
 * draw under each value).
 */

#include <stddef.h>

#include <fixgl/fixgl.h>

#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_hint(struct fgl_context *ctx)
{
   struct fgl_hint_attrib *h = &ctx->Hint;
   h->PerspectiveCorrection = GL_DONT_CARE;
   h->PointSmooth = GL_DONT_CARE;
   h->LineSmooth = GL_DONT_CARE;
   h->PolygonSmooth = GL_DONT_CARE;
   h->Fog = GL_DONT_CARE;
   h->TextureCompression = GL_DONT_CARE;
   h->GenerateMipmap = GL_DONT_CARE;
   h->PhongWin = GL_DONT_CARE;
}

/* The stored value of a hint target, NULL for an invalid target. */
static GLenum *hint_field(struct fgl_context *ctx, GLenum target)
{
   struct fgl_hint_attrib *h = &ctx->Hint;
   switch (target) {
   case GL_FOG_HINT:                         return &h->Fog;
   case GL_LINE_SMOOTH_HINT:                 return &h->LineSmooth;
   case GL_PERSPECTIVE_CORRECTION_HINT:      return &h->PerspectiveCorrection;
   case GL_POINT_SMOOTH_HINT:                return &h->PointSmooth;
   case GL_POLYGON_SMOOTH_HINT:              return &h->PolygonSmooth;
   case GL_TEXTURE_COMPRESSION_HINT:         return &h->TextureCompression;
   case GL_GENERATE_MIPMAP_HINT:             return &h->GenerateMipmap;
   /* GL_WIN_phong_shading: stored and ignored (fixgl always shades every
    * fragment; include/fixgl/shading.md) */
   case GL_PHONG_HINT_WIN:                   return &h->PhongWin;
   default:                                  return NULL;
   }
}

void GLAPIENTRY glHint(GLenum target, GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, Hint, target, mode);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (mode != GL_NICEST && mode != GL_FASTEST && mode != GL_DONT_CARE) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   GLenum *field = hint_field(ctx, target);
   if (!field) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (*field == mode)
      return;
   FGL_FLUSH_VERTICES(ctx, 0);
   *field = mode;
}

bool fgl_get_hint(struct fgl_context *ctx, GLenum target, GLenum *value)
{
   const GLenum *field = hint_field(ctx, target);
   if (!field)
      return false;
   *value = *field;
   return true;
}
