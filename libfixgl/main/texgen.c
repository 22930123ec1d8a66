/*
 * Texture coordinate generation state (Mesa 22.3 main/texgen.c):
 * glTexGen{i,f,d}[v] and glGetTexGen{i,f,d}v for the active unit.  The eye
 * planes are transformed by the inverse modelview at specification time,
 * exactly as glClipPlane's (_mesa_transform_vector).  The vertex stage
 * generates the coordinates (tnl/t_texcoord.c).
 */
#include <string.h>

#include "main/conv.h"
#include "main/dlist.h"
#include "main/groups.h"

/* [S: texstate.c:init_texture_unit] EYE_LINEAR everywhere, the S and T
 * planes (1,0,0,0) and (0,1,0,0), R and Q zero */
void fgl_init_texgen(struct fgl_context *ctx)
{
   for (int u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      struct fgl_texture_unit *t = &ctx->Texture.Unit[u];
      memset(t->ObjectPlane, 0, sizeof(t->ObjectPlane));
      memset(t->EyePlane, 0, sizeof(t->EyePlane));
      for (int c = 0; c < 4; c++)
         t->GenMode[c] = GL_EYE_LINEAR;
      t->ObjectPlane[0][0] = t->EyePlane[0][0] = 1.0f;
      t->ObjectPlane[1][1] = t->EyePlane[1][1] = 1.0f;
   }
}

/* [S: texgen.c:get_texgen] GL_S..GL_Q, else -1 */
static int coord_index(GLenum coord)
{
   return coord >= GL_S && coord <= GL_Q ? (int)(coord - GL_S) : -1;
}

/* _mesa_transform_vector: u = v * m (row vector times matrix), each sum
 * left to right (as main/clip.c). */
static void transform_vector(float u[4], const float v[4], const float m[16])
{
   const float v0 = v[0], v1 = v[1], v2 = v[2], v3 = v[3];
   for (int c = 0; c < 4; c++)
      u[c] = v0 * m[4 * c + 0] + v1 * m[4 * c + 1] + v2 * m[4 * c + 2] + v3 * m[4 * c + 3];
}

static inline bool eq4(const float *a, const float *b)
{
   return a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && a[3] == b[3];   /* TEST_EQ_4V */
}

/* FLUSH_VERTICES(ctx, _NEW_TEXTURE_STATE, GL_TEXTURE_BIT) */
static void gen_flush(struct fgl_context *ctx)
{
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_TEXTURE);
   ctx->PopAttribState |= GL_TEXTURE_BIT;
}

/* [S: texgen.c:texgenfv] */
static void tex_genfv(struct fgl_context *ctx, GLenum coord, GLenum pname, const GLfloat *params)
{
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* [S: texgen.c:get_texgen] units past MaxTextureCoordUnits first */
   if (ctx->Texture.CurrentUnit >= FGL_MAX_TEXTURE_UNITS) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   const int i = coord_index(coord);
   if (i < 0) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   struct fgl_texture_unit *t = &ctx->Texture.Unit[ctx->Texture.CurrentUnit];
   switch (pname) {
   case GL_TEXTURE_GEN_MODE: {
      const GLenum mode = (GLenum)fgl_double_to_int_trunc(params[0]);   /* (GLint) on x86 */
      if (t->GenMode[i] == mode)
         return;
      bool legal;
      switch (mode) {
      case GL_OBJECT_LINEAR:
      case GL_EYE_LINEAR:
         legal = true;
         break;
      case GL_SPHERE_MAP:
         legal = coord == GL_S || coord == GL_T;
         break;
      case GL_REFLECTION_MAP:
      case GL_NORMAL_MAP:
         legal = coord != GL_Q;
         break;
      default:
         legal = false;
      }
      if (!legal) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      gen_flush(ctx);
      t->GenMode[i] = mode;
      return;
   }
   case GL_OBJECT_PLANE:
      if (eq4(t->ObjectPlane[i], params))
         return;
      gen_flush(ctx);
      memcpy(t->ObjectPlane[i], params, 4 * sizeof(float));
      return;
   case GL_EYE_PLANE: {
      float tmp[4];
      fgl_matrix_analyse(ctx->ModelviewStack.Top);
      transform_vector(tmp, params, ctx->ModelviewStack.Top->inv);
      if (eq4(t->EyePlane[i], tmp))
         return;
      gen_flush(ctx);
      memcpy(t->EyePlane[i], tmp, sizeof(tmp));
      return;
   }
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
}

/* While compiling, every variant is stored as glTexGenfv with four values
 * converted to float (dlist.c:save_TexGen*: the scalar forms pad with
 * zeros; a vector mode call stores what follows its value, read here as
 * zeros: only params[0] is used at replay) */
void GLAPIENTRY glTexGenfv(GLenum coord, GLenum pname, const GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx || !params)
      return;
   FGL_SAVE(ctx, TexGenfv, coord, pname, params, pname == GL_TEXTURE_GEN_MODE ? 1 : 4);
   float p[4] = { params[0], 0.0f, 0.0f, 0.0f };
   if (pname != GL_TEXTURE_GEN_MODE)
      memcpy(p, params, sizeof(p));
   tex_genfv(ctx, coord, pname, p);
}

void GLAPIENTRY glTexGenf(GLenum coord, GLenum pname, GLfloat param)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const GLfloat p[4] = { param, 0.0f, 0.0f, 0.0f };
   FGL_SAVE(ctx, TexGenfv, coord, pname, p, 4);
   tex_genfv(ctx, coord, pname, p);
}

void GLAPIENTRY glTexGeni(GLenum coord, GLenum pname, GLint param)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const GLfloat p[4] = { (GLfloat)param, 0.0f, 0.0f, 0.0f };
   FGL_SAVE(ctx, TexGenfv, coord, pname, p, 4);
   tex_genfv(ctx, coord, pname, p);
}

void GLAPIENTRY glTexGend(GLenum coord, GLenum pname, GLdouble param)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const GLfloat p[4] = { (GLfloat)param, 0.0f, 0.0f, 0.0f };
   FGL_SAVE(ctx, TexGenfv, coord, pname, p, 4);
   tex_genfv(ctx, coord, pname, p);
}

/* [S: texgen.c:_mesa_TexGeniv, _mesa_TexGendv] a mode takes params[0]
 * only, planes four values cast to float */
void GLAPIENTRY glTexGeniv(GLenum coord, GLenum pname, const GLint *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx || !params)
      return;
   const bool mode = pname == GL_TEXTURE_GEN_MODE;
   const GLfloat p[4] = { (GLfloat)params[0], mode ? 0.0f : (GLfloat)params[1],
                          mode ? 0.0f : (GLfloat)params[2], mode ? 0.0f : (GLfloat)params[3] };
   FGL_SAVE(ctx, TexGenfv, coord, pname, p, 4);
   tex_genfv(ctx, coord, pname, p);
}

void GLAPIENTRY glTexGendv(GLenum coord, GLenum pname, const GLdouble *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx || !params)
      return;
   const bool mode = pname == GL_TEXTURE_GEN_MODE;
   const GLfloat p[4] = { (GLfloat)params[0], mode ? 0.0f : (GLfloat)params[1],
                          mode ? 0.0f : (GLfloat)params[2], mode ? 0.0f : (GLfloat)params[3] };
   FGL_SAVE(ctx, TexGenfv, coord, pname, p, 4);
   tex_genfv(ctx, coord, pname, p);
}

/* (GLint) of a float as x86-64 converts it: out of range (and NaN) gives
 * INT_MIN */
static GLint float_to_int_x86(float f)
{
   if (f >= -2147483648.0f && f < 2147483648.0f)
      return (GLint)f;
   return (GLint)0x80000000u;
}

/* [S: texgen.c:gettexgenfv, gettexgeniv, gettexgendv]: the mode, or a
 * plane (integers truncate) */
static void get_tex_gen(GLenum coord, GLenum pname, GLfloat *fv, GLint *iv, GLdouble *dv)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   /* [S: texgen.c:get_texgen] units past MaxTextureCoordUnits first */
   if (ctx->Texture.CurrentUnit >= FGL_MAX_TEXTURE_UNITS) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   const int i = coord_index(coord);
   if (i < 0) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   const struct fgl_texture_unit *t = &ctx->Texture.Unit[ctx->Texture.CurrentUnit];
   const float *plane;
   switch (pname) {
   case GL_TEXTURE_GEN_MODE:
      if (fv)
         fv[0] = (GLfloat)(GLint)t->GenMode[i];   /* ENUM_TO_FLOAT */
      else if (iv)
         iv[0] = (GLint)t->GenMode[i];
      else
         dv[0] = (GLdouble)(GLint)t->GenMode[i];  /* ENUM_TO_DOUBLE */
      return;
   case GL_OBJECT_PLANE:
      plane = t->ObjectPlane[i];
      break;
   case GL_EYE_PLANE:
      plane = t->EyePlane[i];
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   for (int c = 0; c < 4; c++) {
      if (fv)
         fv[c] = plane[c];
      else if (iv)
         iv[c] = float_to_int_x86(plane[c]);
      else
         dv[c] = plane[c];
   }
}

void GLAPIENTRY glGetTexGenfv(GLenum coord, GLenum pname, GLfloat *params)
{
   if (params)
      get_tex_gen(coord, pname, params, NULL, NULL);
}

void GLAPIENTRY glGetTexGeniv(GLenum coord, GLenum pname, GLint *params)
{
   if (params)
      get_tex_gen(coord, pname, NULL, params, NULL);
}

void GLAPIENTRY glGetTexGendv(GLenum coord, GLenum pname, GLdouble *params)
{
   if (params)
      get_tex_gen(coord, pname, NULL, NULL, params);
}
