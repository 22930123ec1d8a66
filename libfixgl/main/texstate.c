/*
 * Which texture units texture fragments (Mesa 22.3 main/texstate.c,
 * texobj.c): a unit takes the highest-priority enabled target whose bound
 * object is complete for its minification filter; a unit without one is
 * left out of fixed-function texturing.
 */
#include "main/groups.h"
#include "main/dlist.h"

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

/* [S: texobj.c:_mesa_test_texobj_completeness] a cube map's base level:
 * the five other faces must have an image there of face +X's width
 * (faces are square), internal format and border (a face missing or
 * mismatched leaves the object incomplete whatever the filter). */
static bool fgl_cube_base_complete(const struct fgl_texture_object *t)
{
   const struct fgl_texture_image *bi = t->Image[t->BaseLevel];
   for (unsigned f = 1; f < 6; f++) {
      const struct fgl_texture_image *img = fgl_tex_face_image(t, f, t->BaseLevel);
      if (!img || img->Width - 2 * img->Border != bi->Width - 2 * bi->Border ||
          img->InternalFormat != bi->InternalFormat || img->Border != bi->Border)
         return false;
   }
   return true;
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
   const bool is3d = t->Target == GL_TEXTURE_3D;
   const bool cube = t->Target == GL_TEXTURE_CUBE_MAP;
   if (is3d && bi->Depth == 0)
      return false;
   if (cube && !fgl_cube_base_complete(t))
      return false;
   int w = bi->Width - 2 * bi->Border;
   int h = is1d ? 1 : bi->Height - 2 * bi->Border;
   int d = is3d ? bi->Depth - 2 * bi->Border : 1;
   int larger = w > h ? w : h;
   larger = larger > d ? larger : d;
   int maxl = base + num_levels(larger) - 1;
   if (t->MaxLevel < maxl)
      maxl = t->MaxLevel;
   const int max_levels = is3d ? FGL_MAX_3D_TEXTURE_LEVELS : FGL_MAX_TEXTURE_LEVELS;
   if (maxl > max_levels - 1)
      maxl = max_levels - 1;
   *max_level = maxl;
   if (!needs_mipmaps(t->MinFilter))
      return true;
   for (int i = base + 1; i < max_levels; i++) {
      if (w > 1)
         w /= 2;
      if (h > 1)
         h /= 2;
      if (d > 1)
         d /= 2;
      /* a cube map: each face's level (check_level_completeness per
       * face) */
      for (unsigned f = 0; i <= maxl && f < (cube ? 6u : 1u); f++) {
         const struct fgl_texture_image *img = fgl_tex_face_image(t, f, i);
         if (!img || img->InternalFormat != bi->InternalFormat ||
             img->Border != bi->Border || img->Width - 2 * img->Border != w ||
             (!is1d && img->Height - 2 * img->Border != h) ||
             (is3d && img->Depth - 2 * img->Border != d))
            return false;
      }
      if (w == 1 && h == 1 && d == 1)
         break;
   }
   return true;
}

/* Mesa's _ModeBit of a glTexGen mode [S: texgen.c:texgenfv] */
static unsigned gen_mode_bit(GLenum mode)
{
   switch (mode) {
   case GL_OBJECT_LINEAR: return FGL_TEXGEN_OBJ_LINEAR;
   case GL_EYE_LINEAR:    return FGL_TEXGEN_EYE_LINEAR;
   case GL_SPHERE_MAP:    return FGL_TEXGEN_SPHERE_MAP;
   case GL_REFLECTION_MAP: return FGL_TEXGEN_REFLECTION_MAP;
   case GL_NORMAL_MAP:    return FGL_TEXGEN_NORMAL_MAP;
   default:               return 0;
   }
}

/* [S: texstate.c:update_texgen] for the units that texture: the enabled
 * coordinate generation and its modes, and the texture matrix unless its
 * type is the identity (analysed: _mesa_update_texture_matrices ran first
 * for a changed matrix) */
static void update_texgen(struct fgl_context *ctx)
{
   ctx->_TexGenEnabled = 0;
   ctx->_TexMatEnabled = 0;
   ctx->_GenFlags = 0;
   for (unsigned u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      if (!(ctx->_EnabledTexUnits & (1u << u)))
         continue;
      const struct fgl_texture_unit *t = &ctx->Texture.Unit[u];
      if (t->TexGenEnabled) {
         for (int c = 0; c < 4; c++)
            if (t->TexGenEnabled & (1u << c))
               ctx->_GenFlags |= gen_mode_bit(t->GenMode[c]);
         ctx->_TexGenEnabled |= 1u << u;
      }
      fgl_matrix_analyse(ctx->TextureStack[u].Top);
      if (!ctx->TextureStack[u].Top->type_identity)
         ctx->_TexMatEnabled |= 1u << u;
   }
}

/* [S: texstate.c:_mesa_update_texture_matrices] on a texture matrix change
 * alone (_NEW_TEXTURE_MATRIX): the mask is rebuilt from the matrices
 * changed since the last validation only, for the units that had a texture
 * then; an unchanged non-identity matrix of another unit drops out until
 * the texture state is validated again (texture/matrix_other_unit). */
void fgl_update_texture_matrices(struct fgl_context *ctx)
{
   ctx->_TexMatEnabled = 0;
   for (unsigned u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      fgl_matrix *m = ctx->TextureStack[u].Top;
      if (!(m->flags & MAT_DIRTY))
         continue;
      fgl_matrix_analyse(m);
      if (ctx->_CurrentTex[u] && !m->type_identity)
         ctx->_TexMatEnabled |= 1u << u;
   }
}

/* [S: texstate.c:update_ff_texture_state] targets in priority order,
 * cube map, 3D, rectangle, 2D, 1D; the first complete one wins.  fixgl
 * has no rectangle target (GL_INVALID_ENUM: not GL 1.5's). */
void fgl_update_texture_state(struct fgl_context *ctx)
{
   static const GLenum targets[] = { GL_TEXTURE_CUBE_MAP, GL_TEXTURE_3D, GL_TEXTURE_2D,
                                     GL_TEXTURE_1D };
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
         ctx->_CurrentTexMaxLevel[u] = max_level;
         ctx->_CurrentTex[u] = t;
         ctx->_CurrentTexTarget[u] = targets[k];
         break;
      }
   }   update_texgen(ctx);
}

/* ---- the active units (GL 1.3 multitexture) ---- */

/* [S: texstate.c:active_texture] units beyond the combined image unit
 * count (192) are GL_INVALID_ENUM; a change flushes and, in GL_TEXTURE
 * matrix mode, points the matrix calls at the unit's stack (units 8..191
 * have none: ORACLE-NOTES.md "Units 8..191"). */
static void active_texture(GLenum texture)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ActiveTexture, texture);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const GLuint unit = texture - GL_TEXTURE0;
   if (ctx->Texture.CurrentUnit == unit)
      return;
   if (unit >= FGL_MAX_COMBINED_TEXTURE_UNITS) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_TEXTURE);
   ctx->Texture.CurrentUnit = unit;
   if (ctx->Transform.MatrixMode == GL_TEXTURE)
      ctx->CurrentStack = fgl_texture_stack(ctx);
}

void GLAPIENTRY glActiveTexture(GLenum texture)
{
   active_texture(texture);
}

void GLAPIENTRY glActiveTextureARB(GLenum texture)
{
   active_texture(texture);
}

/* [S: texstate.c:_mesa_ClientActiveTexture] client state: no flush, not
 * compiled into lists; units beyond MaxTextureCoordUnits (8) are
 * GL_INVALID_ENUM. */
static void client_active_texture(GLenum texture)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   const GLuint unit = texture - GL_TEXTURE0;
   if (ctx->Array.ActiveTexture == unit)
      return;
   if (unit >= FGL_MAX_TEXTURE_UNITS) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   ctx->Array.ActiveTexture = unit;
}

void GLAPIENTRY glClientActiveTexture(GLenum texture)
{
   client_active_texture(texture);
}

void GLAPIENTRY glClientActiveTextureARB(GLenum texture)
{
   client_active_texture(texture);
}
