/*
 * Lighting state (GL_LIGHTING_BIT): glShadeModel, glLight, glLightModel.
 * Entry points validate as Mesa's main/light.c does and store what it
 * stores: positions through the modelview and spot directions through its
 * 3x3 part at call time (TRANSFORM_POINT / TRANSFORM_DIRECTION, float, left
 * to right), cos of the cutoff from a double angle (llvmpipe-facts.md §4
 * "State captured at glLight time").
 */
#include <math.h>
#include <string.h>

#include "main/conv.h"
#include "main/groups.h"

static void init_light(struct fgl_light *l, int n)
{
   static const float zero1[4] = { 0, 0, 0, 1 }, one[4] = { 1, 1, 1, 1 };
   memset(l, 0, sizeof(*l));
   memcpy(l->Ambient, zero1, sizeof(zero1));
   memcpy(l->Diffuse, n == 0 ? one : zero1, sizeof(one));
   memcpy(l->Specular, n == 0 ? one : zero1, sizeof(one));
   l->EyePosition[2] = 1.0f;
   l->SpotDirection[2] = -1.0f;
   l->SpotCutoff = 180.0f;
   l->ConstantAttenuation = 1.0f;
}

void fgl_init_light(struct fgl_context *ctx)
{
   ctx->Light.ShadeModel = GL_SMOOTH;
   for (int i = 0; i < FGL_MAX_LIGHTS; i++)
      init_light(&ctx->Light.Light[i], i);
   static const float amb[4] = { 0.2f, 0.2f, 0.2f, 1.0f };
   memcpy(ctx->Light.Model.Ambient, amb, sizeof(amb));
   ctx->Light.Model.ColorControl = GL_SINGLE_COLOR;
   ctx->Light.ColorMaterialFace = GL_FRONT_AND_BACK;
   ctx->Light.ColorMaterialMode = GL_AMBIENT_AND_DIFFUSE;
}

/* ---- glLight ---- */

/* The light's values for pname and their count; 0 for an invalid pname. */
static int light_field(struct fgl_light *l, GLenum pname, float **v)
{
   switch (pname) {
   case GL_AMBIENT: *v = l->Ambient; return 4;
   case GL_DIFFUSE: *v = l->Diffuse; return 4;
   case GL_SPECULAR: *v = l->Specular; return 4;
   case GL_POSITION: *v = l->EyePosition; return 4;
   case GL_SPOT_DIRECTION: *v = l->SpotDirection; return 3;
   case GL_SPOT_EXPONENT: *v = &l->SpotExponent; return 1;
   case GL_SPOT_CUTOFF: *v = &l->SpotCutoff; return 1;
   case GL_CONSTANT_ATTENUATION: *v = &l->ConstantAttenuation; return 1;
   case GL_LINEAR_ATTENUATION: *v = &l->LinearAttenuation; return 1;
   case GL_QUADRATIC_ATTENUATION: *v = &l->QuadraticAttenuation; return 1;
   default: return 0;
   }
}

/* do_light: params already validated and transformed; no-op when unchanged
 * (compared with ==, so NaN always stores). */
static void set_light(struct fgl_context *ctx, struct fgl_light *l, GLenum pname,
                      const float *p)
{
   float *dst;
   const int n = light_field(l, pname, &dst);
   bool same = true;
   for (int i = 0; i < n; i++)
      same &= dst[i] == p[i];
   if (same)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
   memcpy(dst, p, (size_t)n * sizeof(float));
   if (pname == GL_SPOT_CUTOFF) {
      /* cosf of a double angle, clamped to >= 0 (llvmpipe-facts.md §4) */
      l->CosCutoff = cosf((float)(l->SpotCutoff * M_PI / 180.0));
      if (l->CosCutoff < 0)
         l->CosCutoff = 0;
   }
}

void GLAPIENTRY glLightfv(GLenum light, GLenum pname, const GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const GLint i = (GLint)(light - GL_LIGHT0);
   float temp[4];
   if (i < 0 || i >= FGL_MAX_LIGHTS) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (!params)
      return;
   const float *m = ctx->ModelviewStack.Top->m;
   switch (pname) {
   case GL_AMBIENT:
   case GL_DIFFUSE:
   case GL_SPECULAR:
      break;
   case GL_POSITION:
      for (int r = 0; r < 4; r++)
         temp[r] = m[r] * params[0] + m[4 + r] * params[1] + m[8 + r] * params[2] +
                   m[12 + r] * params[3];
      params = temp;
      break;
   case GL_SPOT_DIRECTION:
      for (int r = 0; r < 3; r++)
         temp[r] = params[0] * m[r] + params[1] * m[4 + r] + params[2] * m[8 + r];
      params = temp;
      break;
   case GL_SPOT_EXPONENT:
      if (params[0] < 0.0f || params[0] > 128.0f) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return;
      }
      break;
   case GL_SPOT_CUTOFF:
      if ((params[0] < 0.0f || params[0] > 90.0f) && params[0] != 180.0f) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return;
      }
      break;
   case GL_CONSTANT_ATTENUATION:
   case GL_LINEAR_ATTENUATION:
   case GL_QUADRATIC_ATTENUATION:
      if (params[0] < 0.0f) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return;
      }
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   set_light(ctx, &ctx->Light.Light[i], pname, params);
}

void GLAPIENTRY glLightf(GLenum light, GLenum pname, GLfloat param)
{
   const GLfloat p[4] = { param, 0, 0, 0 };
   glLightfv(light, pname, p);
}

void GLAPIENTRY glLightiv(GLenum light, GLenum pname, const GLint *params)
{
   GLfloat f[4] = { 0, 0, 0, 0 };
   if (!params)
      return;
   switch (pname) {
   case GL_AMBIENT:
   case GL_DIFFUSE:
   case GL_SPECULAR:
      for (int i = 0; i < 4; i++)
         f[i] = INT_TO_FLOAT(params[i]);
      break;
   case GL_POSITION:
      for (int i = 0; i < 4; i++)
         f[i] = (GLfloat)params[i];
      break;
   case GL_SPOT_DIRECTION:
      for (int i = 0; i < 3; i++)
         f[i] = (GLfloat)params[i];
      break;
   case GL_SPOT_EXPONENT:
   case GL_SPOT_CUTOFF:
   case GL_CONSTANT_ATTENUATION:
   case GL_LINEAR_ATTENUATION:
   case GL_QUADRATIC_ATTENUATION:
      f[0] = (GLfloat)params[0];
      break;
   default:
      break;   /* the error comes from glLightfv */
   }
   glLightfv(light, pname, f);
}

void GLAPIENTRY glLighti(GLenum light, GLenum pname, GLint param)
{
   const GLint p[4] = { param, 0, 0, 0 };
   glLightiv(light, pname, p);
}

/* The common part of glGetLight{f,i}v: the values and their count, 0 after
 * raising the error Mesa raises. */
static int get_light_values(GLenum light, GLenum pname, float **v)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return 0;
   ASSERT_OUTSIDE_BEGIN_END_RET(ctx, 0);
   const GLint i = (GLint)(light - GL_LIGHT0);
   const int n = i >= 0 && i < FGL_MAX_LIGHTS ? light_field(&ctx->Light.Light[i], pname, v) : 0;
   if (!n)
      fgl_error(ctx, GL_INVALID_ENUM);
   return n;
}

void GLAPIENTRY glGetLightfv(GLenum light, GLenum pname, GLfloat *params)
{
   float *v;
   const int n = get_light_values(light, pname, &v);
   if (n && params)
      memcpy(params, v, (size_t)n * sizeof(float));
}

void GLAPIENTRY glGetLightiv(GLenum light, GLenum pname, GLint *params)
{
   float *v;
   const int n = get_light_values(light, pname, &v);
   if (!n || !params)
      return;
   /* colours with FLOAT_TO_INT, the rest with a plain (GLint) cast */
   const bool color = pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR;
   for (int i = 0; i < n; i++)
      params[i] = color ? fgl_float_to_int_norm(v[i]) : fgl_double_to_int_trunc(v[i]);
}

/* ---- glLightModel ---- */

void GLAPIENTRY glLightModelfv(GLenum pname, const GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (!params)
      return;
   struct fgl_light_model *lm = &ctx->Light.Model;
   bool b;
   switch (pname) {
   case GL_LIGHT_MODEL_AMBIENT:
      if (lm->Ambient[0] == params[0] && lm->Ambient[1] == params[1] &&
          lm->Ambient[2] == params[2] && lm->Ambient[3] == params[3])
         return;
      FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
      memcpy(lm->Ambient, params, sizeof(lm->Ambient));
      return;
   case GL_LIGHT_MODEL_LOCAL_VIEWER:
   case GL_LIGHT_MODEL_TWO_SIDE:
      b = params[0] != 0.0f;
      {
         bool *dst = pname == GL_LIGHT_MODEL_TWO_SIDE ? &lm->TwoSide : &lm->LocalViewer;
         if (*dst == b)
            return;
         FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
         *dst = b;
      }
      return;
   case GL_LIGHT_MODEL_COLOR_CONTROL: {
      GLenum e;
      if (params[0] == (GLfloat)GL_SINGLE_COLOR)
         e = GL_SINGLE_COLOR;
      else if (params[0] == (GLfloat)GL_SEPARATE_SPECULAR_COLOR)
         e = GL_SEPARATE_SPECULAR_COLOR;
      else {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      if (lm->ColorControl == e)
         return;
      FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
      lm->ColorControl = e;
      return;
   }
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
}

void GLAPIENTRY glLightModelf(GLenum pname, GLfloat param)
{
   const GLfloat p[4] = { param, 0, 0, 0 };
   glLightModelfv(pname, p);
}

void GLAPIENTRY glLightModeliv(GLenum pname, const GLint *params)
{
   GLfloat f[4] = { 0, 0, 0, 0 };
   if (!params)
      return;
   switch (pname) {
   case GL_LIGHT_MODEL_AMBIENT:
      for (int i = 0; i < 4; i++)
         f[i] = INT_TO_FLOAT(params[i]);
      break;
   case GL_LIGHT_MODEL_LOCAL_VIEWER:
   case GL_LIGHT_MODEL_TWO_SIDE:
   case GL_LIGHT_MODEL_COLOR_CONTROL:
      f[0] = (GLfloat)params[0];
      break;
   default:
      break;   /* the error comes from glLightModelfv */
   }
   glLightModelfv(pname, f);
}

void GLAPIENTRY glLightModeli(GLenum pname, GLint param)
{
   const GLint p[4] = { param, 0, 0, 0 };
   glLightModeliv(pname, p);
}

void GLAPIENTRY glShadeModel(GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Light.ShadeModel == mode)
      return;
   if (mode != GL_FLAT && mode != GL_SMOOTH) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
   ctx->Light.ShadeModel = mode;
}
