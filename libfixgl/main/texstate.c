/*
 * Which texture units texture fragments (Mesa 22.3 main/texstate.c,
 * texobj.c): a unit takes the highest-priority enabled target whose bound
 * object is complete for its minification filter; a unit without one is
 * left out of fixed-function texturing.
 */
#include "main/groups.h"

/* floor(log2(n)) + 1: the number of levels of a base image whose larger
 * side is n (gl_texture_image MaxNumLevels) */
static int num_levels(int n)
{
   int l = 1;
   while (n > 1) {
      n >>= 1;
      l++;
   }
   return l;
}

static bool needs_mipmaps(GLenum min_filter)
{
   return min_filter != GL_NEAREST && min_filter != GL_LINEAR;
}

/* [S: texobj.c:_mesa_test_texobj_completeness, texobj.h:
 * _mesa_is_texture_complete] the base image must exist and be non-empty;
 * with a mipmap filter every level from the base to _MaxLevel =
 * min(MaxLevel, base + levels - 1, 14) must exist with the halved size,
 * the base's internal format and border.  *max_level gets _MaxLevel.
 * MAX_LEVEL < BASE_LEVEL makes the object mipmap-incomplete only
 * (incomplete(t, MIPMAP)): without a mipmap filter it stays complete
 * (texture/image_completeness), with _MaxLevel below the base. */
bool fgl_texture_complete(const struct fgl_texture_object *t, int *max_level)
{
   const int base = t->BaseLevel;
   if (base < 0 || base >= FGL_MAX_TEXTURE_LEVELS)
      return false;
   if (t->MaxLevel < base && needs_mipmaps(t->MinFilter))
      return false;
   const struct fgl_texture_image *bi = t->Image[base];
   if (!bi || bi->Width == 0 || bi->Height == 0)
      return false;
   const bool is1d = t->Target == GL_TEXTURE_1D;
   int w = bi->Width - 2 * bi->Border;
   int h = is1d ? 1 : bi->Height - 2 * bi->Border;
   int maxl = base + num_levels(w > h ? w : h) - 1;
   if (t->MaxLevel < maxl)
      maxl = t->MaxLevel;
   if (maxl > FGL_MAX_TEXTURE_LEVELS - 1)
      maxl = FGL_MAX_TEXTURE_LEVELS - 1;
   *max_level = maxl;
   if (!needs_mipmaps(t->MinFilter))
      return true;
   for (int i = base + 1; i < FGL_MAX_TEXTURE_LEVELS; i++) {
      if (w > 1)
         w /= 2;
      if (h > 1)
         h /= 2;
      if (i <= maxl) {
         const struct fgl_texture_image *img = t->Image[i];
         if (!img || img->InternalFormat != bi->InternalFormat ||
             img->Border != bi->Border || img->Width - 2 * img->Border != w ||
             (!is1d && img->Height - 2 * img->Border != h))
            return false;
      }
      if (w == 1 && h == 1)
         break;
   }
   return true;
}

/* [S: texstate.c:update_ff_texture_state] targets in priority order,
 * cube map, 3D, rectangle, 2D, 1D; the first complete one wins.  Only 1D
 * and 2D textures can have images in fixgl, so only they can texture. */
void fgl_update_texture_state(struct fgl_context *ctx)
{
   static const GLenum targets[] = { GL_TEXTURE_2D, GL_TEXTURE_1D };
   ctx->_EnabledTexUnits = 0;
   for (unsigned u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      ctx->_CurrentTex[u] = NULL;
      ctx->_CurrentTexTarget[u] = 0;
      for (unsigned k = 0; k < sizeof(targets) / sizeof(targets[0]); k++) {
         if (!fgl_texture_target_enabled(ctx, u, targets[k]))
            continue;
         struct fgl_texture_object *t = fgl_bound_texture(ctx, u, targets[k]);
         int max_level;
         if (!fgl_texture_complete(t, &max_level))
            continue;
         ctx->_EnabledTexUnits |= 1u << u;
         ctx->_CurrentTex[u] = t;
         ctx->_CurrentTexTarget[u] = targets[k];
         break;
      }
   }
}
