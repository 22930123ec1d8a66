/*
 * The texture environment (Mesa 22.3 main/texenv.c): glTexEnv{f,i}[v],
 * glGetTexEnv{f,i}v for GL_TEXTURE_ENV (mode, colour, the combiner state
 * of GL 1.3 with the ATI_texture_env_combine3, NV_texture_env_combine4 and
 * dot3 additions the oracle enables) and GL_TEXTURE_FILTER_CONTROL's LOD
 * bias, per texture unit (the active unit, glActiveTexture).  The
 * fragment stage applies the environment (raster/r_frag.c); state.c
 * translates this state for it.
 */
#include <string.h>

#include "main/conv.h"
#include "main/dlist.h"
#include "main/groups.h"

/* [S: texstate.c:init_texture_unit, default_combine_state] */
void fgl_init_texenv(struct fgl_context *ctx)
{
   for (int u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      struct fgl_texture_unit *t = &ctx->Texture.Unit[u];
      t->EnvMode = GL_MODULATE;
      memset(t->EnvColor, 0, sizeof(t->EnvColor));
      memset(t->EnvColorUnclamped, 0, sizeof(t->EnvColorUnclamped));
      t->CombineModeRGB = t->CombineModeA = GL_MODULATE;
      static const GLenum src[4] = { GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_CONSTANT };
      static const GLenum oprgb[4] = { GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA, GL_SRC_ALPHA };
      for (int i = 0; i < 4; i++) {
         t->SourceRGB[i] = t->SourceA[i] = src[i];
         t->OperandRGB[i] = oprgb[i];
         t->OperandA[i] = GL_SRC_ALPHA;
      }
      t->ScaleShiftRGB = t->ScaleShiftA = 0;
      t->LodBias = 0.0f;
   }
}

/* FLUSH_VERTICES(ctx, _NEW_TEXTURE_STATE, GL_TEXTURE_BIT) */
static void env_flush(struct fgl_context *ctx)
{
   fgl_flush_vertices(ctx);
   ctx->NewState |= FGL_NEW_TEXTURE;
   ctx->PopAttribState |= GL_TEXTURE_BIT;
}

/* [S: texenv.c:set_env_mode] */
static void set_env_mode(struct fgl_context *ctx, struct fgl_texture_unit *t, GLenum mode)
{
   if (t->EnvMode == mode)
      return;
   switch (mode) {
   case GL_MODULATE:
   case GL_BLEND:
   case GL_DECAL:
   case GL_REPLACE:
   case GL_ADD:
   case GL_COMBINE:
   case GL_COMBINE4_NV:
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   env_flush(ctx);
   t->EnvMode = mode;
}

/* [S: texenv.c:set_combiner_mode] */
static void set_combiner_mode(struct fgl_context *ctx, struct fgl_texture_unit *t,
                              GLenum pname, GLenum mode)
{
   bool legal;
   switch (mode) {
   case GL_REPLACE:
   case GL_MODULATE:
   case GL_ADD:
   case GL_ADD_SIGNED:
   case GL_INTERPOLATE:
   case GL_SUBTRACT:
   case GL_MODULATE_ADD_ATI:
   case GL_MODULATE_SIGNED_ADD_ATI:
   case GL_MODULATE_SUBTRACT_ATI:
      legal = true;
      break;
   case GL_DOT3_RGB_EXT:
   case GL_DOT3_RGBA_EXT:
   case GL_DOT3_RGB:
   case GL_DOT3_RGBA:
      legal = pname == GL_COMBINE_RGB;
      break;
   default:
      legal = false;
   }
   if (!legal) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   GLenum *dst = pname == GL_COMBINE_RGB ? &t->CombineModeRGB : &t->CombineModeA;
   if (*dst == mode)
      return;
   env_flush(ctx);
   *dst = mode;
}

/* [S: texenv.c:set_combiner_source] four terms (NV_texture_env_combine4),
 * GL_ZERO and GL_ONE (ATI_texture_env_combine3); set even when unchanged */
static void set_combiner_source(struct fgl_context *ctx, struct fgl_texture_unit *t,
                                GLenum pname, GLenum param)
{
   const bool alpha = pname >= GL_SOURCE0_ALPHA && pname <= GL_SOURCE3_ALPHA_NV;
   const unsigned term = alpha ? pname - GL_SOURCE0_ALPHA : pname - GL_SOURCE0_RGB;
   bool legal;
   switch (param) {
   case GL_TEXTURE:
   case GL_CONSTANT:
   case GL_PRIMARY_COLOR:
   case GL_PREVIOUS:
   case GL_ZERO:
   case GL_ONE:
      legal = true;
      break;
   default:
      /* GL_TEXTUREi of a unit below MaxTextureUnits */
      legal = param >= GL_TEXTURE0 && param < GL_TEXTURE0 + FGL_MAX_TEXTURE_UNITS;
   }
   if (!legal) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   env_flush(ctx);
   if (alpha)
      t->SourceA[term] = param;
   else
      t->SourceRGB[term] = param;
}

/* [S: texenv.c:set_combiner_operand] */
static void set_combiner_operand(struct fgl_context *ctx, struct fgl_texture_unit *t,
                                 GLenum pname, GLenum param)
{
   const bool alpha = pname >= GL_OPERAND0_ALPHA && pname <= GL_OPERAND3_ALPHA_NV;
   const unsigned term = alpha ? pname - GL_OPERAND0_ALPHA : pname - GL_OPERAND0_RGB;
   bool legal;
   switch (param) {
   case GL_SRC_COLOR:
   case GL_ONE_MINUS_SRC_COLOR:
      legal = !alpha;
      break;
   case GL_ONE_MINUS_SRC_ALPHA:
   case GL_SRC_ALPHA:
      legal = true;
      break;
   default:
      legal = false;
   }
   if (!legal) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   env_flush(ctx);
   if (alpha)
      t->OperandA[term] = param;
   else
      t->OperandRGB[term] = param;
}

/* [S: texenv.c:set_combiner_scale] */
static void set_combiner_scale(struct fgl_context *ctx, struct fgl_texture_unit *t,
                               GLenum pname, GLfloat scale)
{
   unsigned shift;
   if (scale == 1.0f)
      shift = 0;
   else if (scale == 2.0f)
      shift = 1;
   else if (scale == 4.0f)
      shift = 2;
   else {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   unsigned *dst = pname == GL_RGB_SCALE ? &t->ScaleShiftRGB : &t->ScaleShiftA;
   if (*dst == shift)
      return;
   env_flush(ctx);
   *dst = shift;
}

/* [S: texenv.c:_mesa_texenvfv_indexed] */
static void tex_envfv(struct fgl_context *ctx, GLenum target, GLenum pname, const GLfloat *param)
{
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const unsigned unit = ctx->Texture.CurrentUnit;
   /* units 8..191: GL_COORD_REPLACE is GL_INVALID_OPERATION (its limit is
    * MaxTextureCoordUnits), GL_TEXTURE_ENV returns before any check (no
    * fixed-function unit), the LOD bias is the unit's */
   if (unit >= FGL_MAX_TEXTURE_UNITS && target == GL_POINT_SPRITE &&
       pname == GL_COORD_REPLACE) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   struct fgl_texture_unit *t = unit < FGL_MAX_TEXTURE_UNITS ? &ctx->Texture.Unit[unit] : NULL;
   float *lod_bias = t ? &t->LodBias : &ctx->TexLocal.ImageLodBias[unit - FGL_MAX_TEXTURE_UNITS];
   const GLint iparam0 = fgl_double_to_int_trunc(param[0]);   /* (GLint) on x86 */
   if (target == GL_TEXTURE_ENV) {
      if (!t)
         return;
      switch (pname) {
      case GL_TEXTURE_ENV_MODE:
         set_env_mode(ctx, t, (GLenum)iparam0);
         return;
      case GL_TEXTURE_ENV_COLOR:
         /* [S: texenv.c:set_env_color] */
         if (param[0] == t->EnvColorUnclamped[0] && param[1] == t->EnvColorUnclamped[1] &&
             param[2] == t->EnvColorUnclamped[2] && param[3] == t->EnvColorUnclamped[3])
            return;   /* TEST_EQ_4V */
         env_flush(ctx);
         for (int c = 0; c < 4; c++) {
            t->EnvColorUnclamped[c] = param[c];
            t->EnvColor[c] = fgl_clamp01(param[c]);
         }
         return;
      case GL_COMBINE_RGB:
      case GL_COMBINE_ALPHA:
         set_combiner_mode(ctx, t, pname, (GLenum)iparam0);
         return;
      case GL_SOURCE0_RGB:
      case GL_SOURCE1_RGB:
      case GL_SOURCE2_RGB:
      case GL_SOURCE3_RGB_NV:
      case GL_SOURCE0_ALPHA:
      case GL_SOURCE1_ALPHA:
      case GL_SOURCE2_ALPHA:
      case GL_SOURCE3_ALPHA_NV:
         set_combiner_source(ctx, t, pname, (GLenum)iparam0);
         return;
      case GL_OPERAND0_RGB:
      case GL_OPERAND1_RGB:
      case GL_OPERAND2_RGB:
      case GL_OPERAND3_RGB_NV:
      case GL_OPERAND0_ALPHA:
      case GL_OPERAND1_ALPHA:
      case GL_OPERAND2_ALPHA:
      case GL_OPERAND3_ALPHA_NV:
         set_combiner_operand(ctx, t, pname, (GLenum)iparam0);
         return;
      case GL_RGB_SCALE:
      case GL_ALPHA_SCALE:
         set_combiner_scale(ctx, t, pname, param[0]);
         return;
      default:
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
   } else if (target == GL_TEXTURE_FILTER_CONTROL) {
      if (pname != GL_TEXTURE_LOD_BIAS) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      if (*lod_bias == param[0])
         return;
      env_flush(ctx);
      *lod_bias = param[0];
   } else if (target == GL_POINT_SPRITE) {
      /* GL_COORD_REPLACE of the active unit: point state (GL_POINT_BIT)
       * set through glTexEnv [S: texenv.c:_mesa_TexEnvfv] */
      if (pname != GL_COORD_REPLACE) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      const unsigned bit = 1u << unit;
      if (iparam0 != GL_TRUE && iparam0 != GL_FALSE) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return;
      }
      const unsigned now = iparam0 == GL_TRUE ? ctx->Point.CoordReplace | bit
                                              : ctx->Point.CoordReplace & ~bit;
      if (now == ctx->Point.CoordReplace)
         return;
      FGL_FLUSH_VERTICES(ctx, FGL_NEW_POINT);
      ctx->Point.CoordReplace = now;
   } else {
      fgl_error(ctx, GL_INVALID_ENUM);
   }
}

/* While compiling, every variant is stored as glTexEnvfv: the colour's
 * four values (integers normalized), else params[0] and zeros
 * (dlist.c:save_TexEnvfv, save_TexEnvi, save_TexEnviv) */
void GLAPIENTRY glTexEnvfv(GLenum target, GLenum pname, const GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx || !params)
      return;
   FGL_SAVE(ctx, TexEnvfv, target, pname, params, pname == GL_TEXTURE_ENV_COLOR ? 4 : 1);
   tex_envfv(ctx, target, pname, params);
}

void GLAPIENTRY glTexEnvf(GLenum target, GLenum pname, GLfloat param)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const GLfloat p[4] = { param, 0.0f, 0.0f, 0.0f };
   FGL_SAVE(ctx, TexEnvfv, target, pname, p, 4);
   tex_envfv(ctx, target, pname, p);
}

void GLAPIENTRY glTexEnvi(GLenum target, GLenum pname, GLint param)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const GLfloat p[4] = { (GLfloat)param, 0.0f, 0.0f, 0.0f };
   FGL_SAVE(ctx, TexEnvfv, target, pname, p, 4);
   tex_envfv(ctx, target, pname, p);
}

void GLAPIENTRY glTexEnviv(GLenum target, GLenum pname, const GLint *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx || !params)
      return;
   GLfloat p[4] = { (GLfloat)params[0], 0.0f, 0.0f, 0.0f };
   if (pname == GL_TEXTURE_ENV_COLOR)
      for (int c = 0; c < 4; c++)
         p[c] = INT_TO_FLOAT(params[c]);
   FGL_SAVE(ctx, TexEnvfv, target, pname, p, 4);
   tex_envfv(ctx, target, pname, p);
}

/* [S: texenv.c:get_texenvi] -1 after an error */
static GLint get_texenvi(struct fgl_context *ctx, const struct fgl_texture_unit *t, GLenum pname)
{
   switch (pname) {
   case GL_TEXTURE_ENV_MODE: return (GLint)t->EnvMode;
   case GL_COMBINE_RGB: return (GLint)t->CombineModeRGB;
   case GL_COMBINE_ALPHA: return (GLint)t->CombineModeA;
   case GL_SOURCE0_RGB:
   case GL_SOURCE1_RGB:
   case GL_SOURCE2_RGB:
   case GL_SOURCE3_RGB_NV:
      return (GLint)t->SourceRGB[pname - GL_SOURCE0_RGB];
   case GL_SOURCE0_ALPHA:
   case GL_SOURCE1_ALPHA:
   case GL_SOURCE2_ALPHA:
   case GL_SOURCE3_ALPHA_NV:
      return (GLint)t->SourceA[pname - GL_SOURCE0_ALPHA];
   case GL_OPERAND0_RGB:
   case GL_OPERAND1_RGB:
   case GL_OPERAND2_RGB:
   case GL_OPERAND3_RGB_NV:
      return (GLint)t->OperandRGB[pname - GL_OPERAND0_RGB];
   case GL_OPERAND0_ALPHA:
   case GL_OPERAND1_ALPHA:
   case GL_OPERAND2_ALPHA:
   case GL_OPERAND3_ALPHA_NV:
      return (GLint)t->OperandA[pname - GL_OPERAND0_ALPHA];
   case GL_RGB_SCALE: return 1 << t->ScaleShiftRGB;
   case GL_ALPHA_SCALE: return 1 << t->ScaleShiftA;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return -1;
   }
}

/* [S: texenv.c:_mesa_gettexenvfv_indexed, _mesa_gettexenviv_indexed]; the
 * float colour query returns the clamped colour (fragment colour clamping
 * is on for the oracle's fixed-point buffers) */
static void get_tex_env(GLenum target, GLenum pname, GLfloat *fv, GLint *iv)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   /* [S: texenv.c:_mesa_gettexenvfv_indexed] units 8..191 as glTexEnv */
   const unsigned unit = ctx->Texture.CurrentUnit;
   if (unit >= FGL_MAX_TEXTURE_UNITS && target == GL_POINT_SPRITE &&
       pname == GL_COORD_REPLACE) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   const struct fgl_texture_unit *t =
      unit < FGL_MAX_TEXTURE_UNITS ? &ctx->Texture.Unit[unit] : NULL;
   const float lod_bias = t ? t->LodBias : ctx->TexLocal.ImageLodBias[unit - FGL_MAX_TEXTURE_UNITS];
   if (target == GL_TEXTURE_ENV) {
      if (!t)
         return;
      if (pname == GL_TEXTURE_ENV_COLOR) {
         for (int c = 0; c < 4; c++) {
            if (fv)
               fv[c] = t->EnvColor[c];
            else
               iv[c] = fgl_float_to_int_norm(t->EnvColor[c]);   /* FLOAT_TO_INT */
         }
         return;
      }
      const GLint v = get_texenvi(ctx, t, pname);
      if (v >= 0) {
         if (fv)
            *fv = (GLfloat)v;
         else
            *iv = v;
      }
   } else if (target == GL_TEXTURE_FILTER_CONTROL) {
      if (pname != GL_TEXTURE_LOD_BIAS) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      if (fv)
         *fv = lod_bias;
      else
         *iv = (GLint)lod_bias;
   } else if (target == GL_POINT_SPRITE) {
      if (pname != GL_COORD_REPLACE) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      const GLint v = (ctx->Point.CoordReplace >> unit) & 1u;
      if (fv)
         *fv = (GLfloat)v;
      else
         *iv = v;
   } else {
      fgl_error(ctx, GL_INVALID_ENUM);
   }
}

void GLAPIENTRY glGetTexEnvfv(GLenum target, GLenum pname, GLfloat *params)
{
   if (params)
      get_tex_env(target, pname, params, NULL);
}

void GLAPIENTRY glGetTexEnviv(GLenum target, GLenum pname, GLint *params)
{
   if (params)
      get_tex_env(target, pname, NULL, params);
}
