/*
 * Lighting state (GL_LIGHTING_BIT): glShadeModel, glLight, glLightModel,
 * glMaterial, glColorMaterial, and the derived state the vertex stage
 * lights with (fgl_update_lighting, and fgl_update_shade_env for fixgl's
 * shading extensions, include/fixgl/shading.md).
 * Entry points validate as Mesa's main/light.c does and store what it
 * stores: positions through the modelview and spot directions through its
 * 3x3 part at call time (TRANSFORM_POINT / TRANSFORM_DIRECTION, float, left
 * to right), cos of the cutoff from a double angle (ORACLE-NOTES.md
 * "Lighting order of operations", what glLight stores).
 */
#include <math.h>
#include <string.h>

#include <fixgl/fixgl.h>

#include "main/conv.h"
#include "main/groups.h"
#include "main/dlist.h"
#include "math/m_shade.h"

static unsigned material_pname_bits(GLenum pname);

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
   ctx->Light._ColorMaterialBitmask = material_pname_bits(GL_AMBIENT_AND_DIFFUSE);
   /* GL_FIXGL_cook_torrance defaults (shading.md) */
   for (int f = 0; f < 2; f++)
      ctx->Light.Reflectance[f] = (struct fgl_reflectance){
         .Model = GL_BLINN_PHONG_FIXGL, .Roughness = 0.5f, .Metalness = 0.0f, .F0 = 0.04f,
      };
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
      /* cosf of a double angle, clamped to >= 0 (ORACLE-NOTES.md
       * "Lighting order of operations") */
      l->CosCutoff = cosf((float)(l->SpotCutoff * M_PI / 180.0));
      if (l->CosCutoff < 0)
         l->CosCutoff = 0;
   }
}

/* The values of glLightfv's pname that save_Lightfv stores (0 for an
 * unknown pname: the error comes when the list executes). */
static unsigned light_param_count(GLenum pname)
{
   switch (pname) {
   case GL_AMBIENT:
   case GL_DIFFUSE:
   case GL_SPECULAR:
   case GL_POSITION:
      return 4;
   case GL_SPOT_DIRECTION:
      return 3;
   case GL_SPOT_EXPONENT:
   case GL_SPOT_CUTOFF:
   case GL_CONSTANT_ATTENUATION:
   case GL_LINEAR_ATTENUATION:
   case GL_QUADRATIC_ATTENUATION:
      return 1;
   default:
      return 0;
   }
}

void GLAPIENTRY glLightfv(GLenum light, GLenum pname, const GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, Lightfv, light, pname, params, params ? light_param_count(pname) : 0);
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
      /* Mesa analyses a dirty modelview here (light.c:_mesa_Lightfv), which
       * resets its geometry flags to what its values show; they outlive a
       * glLoadIdentity and choose the kind of inverse of later matrices
       * (ORACLE-NOTES.md "Matrices") */
      fgl_matrix_analyse(ctx->ModelviewStack.Top);
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
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, 0);
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
   FGL_SAVE(ctx, LightModelfv, pname, params,
            !params ? 0 : pname == GL_LIGHT_MODEL_AMBIENT ? 4 : 1);
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
   if (ctx->CompileFlag) {
      fgl_save_shade_model(ctx, mode);
      return;
   }
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Light.ShadeModel == mode)
      return;
   /* GL_WIN_phong_shading: GL_PHONG_WIN too (shading.md) */
   if (mode != GL_FLAT && mode != GL_SMOOTH && mode != GL_PHONG_WIN) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
   ctx->Light.ShadeModel = mode;
}

/* ---- glMaterial, glColorMaterial ---- */

/* The material attributes that pname names on both faces, or 0
 * (_mesa_material_bitmask before the face is applied). */
static unsigned material_pname_bits(GLenum pname)
{
   switch (pname) {
   case GL_EMISSION:
      return FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_EMISSION) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_EMISSION);
   case GL_AMBIENT:
      return FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_AMBIENT) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_AMBIENT);
   case GL_DIFFUSE:
      return FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_DIFFUSE) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_DIFFUSE);
   case GL_SPECULAR:
      return FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_SPECULAR) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_SPECULAR);
   case GL_SHININESS:
      return FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_SHININESS) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_SHININESS);
   case GL_AMBIENT_AND_DIFFUSE:
      return material_pname_bits(GL_AMBIENT) | material_pname_bits(GL_DIFFUSE);
   case GL_COLOR_INDEXES:
      return FGL_MAT_BIT(FGL_ATTR_MAT_FRONT_INDEXES) | FGL_MAT_BIT(FGL_ATTR_MAT_BACK_INDEXES);
   default:
      return 0;
   }
}

/* The face's share of a material bitmask; false for an invalid face. */
static bool material_face_bits(GLenum face, unsigned *bits)
{
   switch (face) {
   case GL_FRONT: *bits &= FGL_MAT_BITS_FRONT; return true;
   case GL_BACK: *bits &= FGL_MAT_BITS_BACK; return true;
   case GL_FRONT_AND_BACK: return true;
   default: return false;
   }
}

void fgl_update_color_material(struct fgl_context *ctx, const float color[4])
{
   unsigned bits = ctx->Light._ColorMaterialBitmask;
   while (bits) {
      const int i = __builtin_ctz(bits);
      bits &= bits - 1;
      memcpy(ctx->Current.Attrib[FGL_ATTR_MAT_FIRST + i], color, 4 * sizeof(float));
   }
}

/* GL_FIXGL_cook_torrance's material pnames (shading.md) */
static bool is_reflectance_pname(GLenum pname)
{
   return pname == GL_REFLECTANCE_MODEL_FIXGL || pname == GL_ROUGHNESS_FIXGL ||
          pname == GL_METALNESS_FIXGL || pname == GL_DIELECTRIC_F0_FIXGL;
}

static float *reflectance_field(struct fgl_reflectance *r, GLenum pname)
{
   switch (pname) {
   case GL_ROUGHNESS_FIXGL: return &r->Roughness;
   case GL_METALNESS_FIXGL: return &r->Metalness;
   default: return &r->F0;
   }
}

/* glMaterial of a reflectance pname: lighting state, not a vertex
 * attribute, so refused between glBegin and glEnd like glLight
 * (GL_INVALID_OPERATION); the model must be one of the two enums
 * (GL_INVALID_ENUM), a parameter in [0, 1] (GL_INVALID_VALUE, NaN
 * included).  Nothing changes on an error. */
static void set_reflectance(struct fgl_context *ctx, GLenum face, GLenum pname,
                            const GLfloat *params)
{
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (!params)
      return;
   const float v = params[0];
   GLenum model = 0;
   if (pname == GL_REFLECTANCE_MODEL_FIXGL) {
      if (v == (GLfloat)GL_BLINN_PHONG_FIXGL)
         model = GL_BLINN_PHONG_FIXGL;
      else if (v == (GLfloat)GL_COOK_TORRANCE_FIXGL)
         model = GL_COOK_TORRANCE_FIXGL;
      else {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
   } else if (!(v >= 0.0f && v <= 1.0f)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   for (int f = 0; f < 2; f++) {
      if ((f == 0 && face == GL_BACK) || (f == 1 && face == GL_FRONT))
         continue;
      struct fgl_reflectance *r = &ctx->Light.Reflectance[f];
      if (pname == GL_REFLECTANCE_MODEL_FIXGL) {
         if (r->Model == model)
            continue;
         FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
         r->Model = model;
      } else {
         float *dst = reflectance_field(r, pname);
         if (*dst == v)
            continue;
         FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
         *dst = v;
      }
   }
}

/* glMaterial is a vertex attribute call (allowed inside glBegin/glEnd);
 * materials that track the colour through GL_COLOR_MATERIAL are skipped
 * (vbo_exec_api.c:_mesa_Materialfv). */
void GLAPIENTRY glMaterialfv(GLenum face, GLenum pname, const GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      if (params)
         fgl_save_material(ctx, face, pname, params);
      return;
   }
   unsigned update = ctx->Light.ColorMaterialEnabled ? ~ctx->Light._ColorMaterialBitmask
                                                     : FGL_MAT_BITS_ALL;
   if (!material_face_bits(face, &update)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (is_reflectance_pname(pname)) {
      set_reflectance(ctx, face, pname, params);
      return;
   }
   const unsigned bits = material_pname_bits(pname) & update;
   unsigned n = 4;
   switch (pname) {
   case GL_SHININESS:
      if (params && (params[0] < 0.0f || params[0] > 128.0f)) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return;
      }
      n = 1;
      break;
   case GL_COLOR_INDEXES:
      n = 3;
      break;
   case GL_EMISSION:
   case GL_AMBIENT:
   case GL_DIFFUSE:
   case GL_SPECULAR:
   case GL_AMBIENT_AND_DIFFUSE:
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (!params)
      return;
   /* attribute order: front before back, ambient before diffuse */
   static const enum fgl_vbo_attr order[] = {
      FGL_ATTR_MAT_FRONT_EMISSION, FGL_ATTR_MAT_BACK_EMISSION,
      FGL_ATTR_MAT_FRONT_AMBIENT, FGL_ATTR_MAT_BACK_AMBIENT,
      FGL_ATTR_MAT_FRONT_DIFFUSE, FGL_ATTR_MAT_BACK_DIFFUSE,
      FGL_ATTR_MAT_FRONT_SPECULAR, FGL_ATTR_MAT_BACK_SPECULAR,
      FGL_ATTR_MAT_FRONT_SHININESS, FGL_ATTR_MAT_BACK_SHININESS,
      FGL_ATTR_MAT_FRONT_INDEXES, FGL_ATTR_MAT_BACK_INDEXES,
   };
   static const enum fgl_vbo_attr amb_diff_order[] = {
      FGL_ATTR_MAT_FRONT_AMBIENT, FGL_ATTR_MAT_FRONT_DIFFUSE,
      FGL_ATTR_MAT_BACK_AMBIENT, FGL_ATTR_MAT_BACK_DIFFUSE,
   };
   const enum fgl_vbo_attr *list = order;
   unsigned count = sizeof(order) / sizeof(order[0]);
   if (pname == GL_AMBIENT_AND_DIFFUSE) {
      list = amb_diff_order;
      count = 4;
   }
   const float v[4] = { params[0], n > 1 ? params[1] : 0.0f, n > 2 ? params[2] : 0.0f,
                        n > 3 ? params[3] : 1.0f };
   for (unsigned i = 0; i < count; i++)
      if (bits & FGL_MAT_BIT(list[i]))
         fgl_vbo_attr(ctx, list[i], n, v[0], v[1], v[2], v[3]);
}

void GLAPIENTRY glMaterialf(GLenum face, GLenum pname, GLfloat param)
{
   const GLfloat p[4] = { param, 0, 0, 0 };
   glMaterialfv(face, pname, p);
}

void GLAPIENTRY glMateriali(GLenum face, GLenum pname, GLint param)
{
   const GLfloat p[4] = { (GLfloat)param, 0, 0, 0 };
   glMaterialfv(face, pname, p);
}

void GLAPIENTRY glMaterialiv(GLenum face, GLenum pname, const GLint *params)
{
   GLfloat f[4] = { 0, 0, 0, 0 };
   if (!params)
      return;
   switch (pname) {
   case GL_AMBIENT:
   case GL_DIFFUSE:
   case GL_SPECULAR:
   case GL_EMISSION:
   case GL_AMBIENT_AND_DIFFUSE:
      for (int i = 0; i < 4; i++)
         f[i] = INT_TO_FLOAT(params[i]);
      break;
   case GL_SHININESS:
   case GL_REFLECTANCE_MODEL_FIXGL:
   case GL_ROUGHNESS_FIXGL:
   case GL_METALNESS_FIXGL:
   case GL_DIELECTRIC_F0_FIXGL:
      f[0] = (GLfloat)params[0];
      break;
   case GL_COLOR_INDEXES:
      for (int i = 0; i < 3; i++)
         f[i] = (GLfloat)params[i];
      break;
   default:
      break;   /* the error comes from glMaterialfv */
   }
   glMaterialfv(face, pname, f);
}

/* The common part of glGetMaterial{f,i}v: flush (materials are vertex
 * attributes), then the face's values for pname (the attribute, or the
 * reflectance state of GL_FIXGL_cook_torrance) and their count, 0 after
 * raising the error Mesa raises. */
static int get_material_values(GLenum face, GLenum pname, float v[4])
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return 0;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, 0);
   fgl_flush_vertices(ctx);
   fgl_flush_current(ctx);
   if (face != GL_FRONT && face != GL_BACK) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return 0;
   }
   const int back = face == GL_BACK;
   enum fgl_vbo_attr attr;
   int n = 4;
   switch (pname) {
   case GL_AMBIENT: attr = FGL_ATTR_MAT_FRONT_AMBIENT; break;
   case GL_DIFFUSE: attr = FGL_ATTR_MAT_FRONT_DIFFUSE; break;
   case GL_SPECULAR: attr = FGL_ATTR_MAT_FRONT_SPECULAR; break;
   case GL_EMISSION: attr = FGL_ATTR_MAT_FRONT_EMISSION; break;
   case GL_SHININESS: attr = FGL_ATTR_MAT_FRONT_SHININESS; n = 1; break;
   case GL_COLOR_INDEXES: attr = FGL_ATTR_MAT_FRONT_INDEXES; n = 3; break;
   case GL_REFLECTANCE_MODEL_FIXGL:
      v[0] = (float)ctx->Light.Reflectance[back].Model;
      return 1;
   case GL_ROUGHNESS_FIXGL:
   case GL_METALNESS_FIXGL:
   case GL_DIELECTRIC_F0_FIXGL:
      v[0] = *reflectance_field(&ctx->Light.Reflectance[back], pname);
      return 1;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return 0;
   }
   memcpy(v, ctx->Current.Attrib[attr + back], (size_t)n * sizeof(float));
   return n;
}

void GLAPIENTRY glGetMaterialfv(GLenum face, GLenum pname, GLfloat *params)
{
   float v[4];
   const int n = get_material_values(face, pname, v);
   if (n && params)
      memcpy(params, v, (size_t)n * sizeof(float));
}

void GLAPIENTRY glGetMaterialiv(GLenum face, GLenum pname, GLint *params)
{
   float v[4];
   const int n = get_material_values(face, pname, v);
   if (!n || !params)
      return;
   /* colours with FLOAT_TO_INT, shininess, indexes and the reflectance
    * values with lroundf (the model is an enum, exact in a float) */
   for (int i = 0; i < n; i++)
      params[i] = n == 4 ? fgl_float_to_int_norm(v[i]) : fgl_lround_to_int(v[i]);
}

void GLAPIENTRY glColorMaterial(GLenum face, GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ColorMaterial, face, mode);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const unsigned legal = FGL_MAT_BITS_ALL &
      ~(material_pname_bits(GL_SHININESS) | material_pname_bits(GL_COLOR_INDEXES));
   unsigned bits = material_pname_bits(mode);
   if (!bits || !material_face_bits(face, &bits) || (bits & ~legal)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   struct fgl_light_attrib *l = &ctx->Light;
   if (l->_ColorMaterialBitmask == bits && l->ColorMaterialFace == face &&
       l->ColorMaterialMode == mode)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
   l->_ColorMaterialBitmask = bits;
   l->ColorMaterialFace = face;
   l->ColorMaterialMode = mode;
   if (l->ColorMaterialEnabled) {
      fgl_flush_current(ctx);
      fgl_update_color_material(ctx, ctx->Current.Attrib[FGL_ATTR_COLOR0]);
   }
}

void fgl_set_color_material_enabled(struct fgl_context *ctx, bool state)
{
   /* enable.c: FLUSH_VERTICES, FLUSH_CURRENT, then the current colour */
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_LIGHT);
   fgl_flush_current(ctx);
   ctx->Light.ColorMaterialEnabled = state;
   if (state)
      fgl_update_color_material(ctx, ctx->Current.Attrib[FGL_ATTR_COLOR0]);
}

/* ---- derived state ---- */

/* The lighting space and the light vectors in it (Mesa's
 * _mesa_update_lighting, _mesa_update_tnl_spaces, update_modelview_scale,
 * compute_light_positions and the STATE_LIGHT_* uniforms of
 * prog_statevars.c).  Lighting runs in object space when every enabled
 * light is directional and not a spot, the viewer is infinite, there is no
 * separate specular colour and the modelview preserves lengths
 * (ORACLE-NOTES.md "Lighting order of operations"); the modelview must
 * have been analysed. */
void fgl_update_lighting(struct fgl_context *ctx)
{
   const struct fgl_light_attrib *la = &ctx->Light;
   struct fgl_lighting_derived *d = &ctx->_Lighting;
   const fgl_matrix *mv = ctx->ModelviewStack.Top;

   d->EnabledLights = 0;
   bool need_vertices = la->Model.LocalViewer ||
                        la->Model.ColorControl == GL_SEPARATE_SPECULAR_COLOR;
   for (int i = 0; i < FGL_MAX_LIGHTS; i++) {
      const struct fgl_light *l = &la->Light[i];
      if (!l->Enabled)
         continue;
      d->EnabledLights |= 1u << i;
      d->Light[i].Positional = l->EyePosition[3] != 0.0f;
      d->Light[i].Spot = l->SpotCutoff != 180.0f;
      d->Light[i].Attenuated = l->ConstantAttenuation != 1.0f ||
                               l->LinearAttenuation != 0.0f ||
                               l->QuadraticAttenuation != 0.0f;
      need_vertices |= d->Light[i].Positional || d->Light[i].Spot;
   }
   /* _mesa_update_tnl_spaces: eye-space coordinate generation needs eye
    * coordinates too (for its normals, whether or not lighting is on) */
   d->NeedEyeCoords = (la->Enabled &&
                       (need_vertices || !fgl_matrix_is_length_preserving(mv->flags))) ||
                      (ctx->_GenFlags & FGL_TEXGEN_NEED_EYE_COORD) != 0;

   /* update_modelview_scale */
   d->NormalScale = 1.0f;
   if (!fgl_matrix_is_length_preserving(mv->flags)) {
      const float *inv = mv->inv;
      float f = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
      if (f < 1e-12f)
         f = 1.0f;
      d->NormalScale = d->NeedEyeCoords ? 1.0f / sqrtf(f) : sqrtf(f);
   }

   /* compute_light_positions and the uniforms derived from them */
   static const float eye_z[3] = { 0, 0, 1 };
   float eye_z_dir[3];
   if (d->NeedEyeCoords)
      memcpy(eye_z_dir, eye_z, sizeof(eye_z));
   else
      fgl_transform_normal(eye_z_dir, eye_z, mv->m);
   for (int i = 0; i < FGL_MAX_LIGHTS; i++) {
      if (!(d->EnabledLights & (1u << i)))
         continue;
      const struct fgl_light *l = &la->Light[i];
      struct fgl_light_derived *ld = &d->Light[i];
      float *p = ld->Position;
      if (d->NeedEyeCoords) {
         memcpy(p, l->EyePosition, 4 * sizeof(float));
      } else {
         /* TRANSFORM_POINT with the inverse, left to right */
         const float *m = mv->inv, *e = l->EyePosition;
         for (int r = 0; r < 4; r++)
            p[r] = m[r] * e[0] + m[4 + r] * e[1] + m[8 + r] * e[2] + m[12 + r] * e[3];
      }
      if (ld->Positional) {
         const float w_inv = 1.0f / p[3];
         p[0] *= w_inv;
         p[1] *= w_inv;
         p[2] *= w_inv;
      } else {
         /* STATE_LIGHT_POSITION_NORMALIZED and STATE_LIGHT_HALF_VECTOR */
         fgl_normalize3(p);
         for (int k = 0; k < 3; k++)
            ld->HalfVector[k] = p[k] + eye_z_dir[k];
         fgl_normalize3(ld->HalfVector);
      }
      if (ld->Spot) {
         float *s = ld->SpotDirection;
         if (d->NeedEyeCoords) {
            memcpy(s, l->SpotDirection, 3 * sizeof(float));
            fgl_normalize3(s);
         } else {
            float dir[3];
            memcpy(dir, l->SpotDirection, sizeof(dir));
            fgl_normalize3(dir);
            fgl_transform_normal(s, dir, mv->m);
         }
         fgl_normalize3(s);
      }
   }
}

/* ---- fixgl's shading extensions ---- */

static void copy4(float *dst, const float *src)
{
   memcpy(dst, src, 4 * sizeof(float));
}

void fgl_update_shade_env(const struct fgl_context *ctx, struct m_shade_env *env)
{
   const struct fgl_light_attrib *la = &ctx->Light;
   env->num_lights = 0;
   for (int i = 0; i < FGL_MAX_LIGHTS; i++) {
      const struct fgl_light *l = &la->Light[i];
      if (!l->Enabled)
         continue;
      struct m_shade_light *sl = &env->light[env->num_lights++];
      copy4(sl->ambient, l->Ambient);
      copy4(sl->diffuse, l->Diffuse);
      copy4(sl->specular, l->Specular);
      copy4(sl->position, l->EyePosition);
      /* normalize(sd) as shading.md writes it: v * (1/sqrt(dot(v, v))),
       * the dot left to right */
      const float *sd = l->SpotDirection;
      const float r = 1.0f / sqrtf(sd[0] * sd[0] + sd[1] * sd[1] + sd[2] * sd[2]);
      for (int k = 0; k < 3; k++)
         sl->spot_direction[k] = sd[k] * r;
      sl->spot = l->SpotCutoff != 180.0f;
      sl->spot_exponent = l->SpotExponent;
      /* cos(sc) as GL stores it (gl_LightSource[i].spotCosCutoff of the
       * GLSL reference): cosf of a double angle, clamped to >= 0 */
      sl->spot_cos_cutoff = l->CosCutoff;
      sl->kc = l->ConstantAttenuation;
      sl->kl = l->LinearAttenuation;
      sl->kq = l->QuadraticAttenuation;
   }
   copy4(env->global_ambient, la->Model.Ambient);
   env->local_viewer = la->Model.LocalViewer;
   env->two_side = la->Model.TwoSide;
   env->separate_specular = la->Model.ColorControl == GL_SEPARATE_SPECULAR_COLOR;

   /* both faces: the current material values, the reflectance state */
   for (int f = 0; f < 2; f++) {
      struct m_shade_material *m = &env->material[f];
      const struct fgl_reflectance *r = &la->Reflectance[f];
      copy4(m->ambient, ctx->Current.Attrib[FGL_ATTR_MAT_FRONT_AMBIENT + f]);
      copy4(m->diffuse, ctx->Current.Attrib[FGL_ATTR_MAT_FRONT_DIFFUSE + f]);
      copy4(m->specular, ctx->Current.Attrib[FGL_ATTR_MAT_FRONT_SPECULAR + f]);
      copy4(m->emission, ctx->Current.Attrib[FGL_ATTR_MAT_FRONT_EMISSION + f]);
      m->shininess = ctx->Current.Attrib[FGL_ATTR_MAT_FRONT_SHININESS + f][0];
      m->model = r->Model == GL_COOK_TORRANCE_FIXGL ? M_SHADE_COOK_TORRANCE
                                                    : M_SHADE_BLINN_PHONG;
      m->roughness = r->Roughness;
      m->metalness = r->Metalness;
      m->f0 = r->F0;
   }

   /* the properties that track the vertex colour */
   env->color_material = 0;
   if (la->ColorMaterialEnabled) {
      static const struct { enum fgl_vbo_attr attr; unsigned bit; } cm[] = {
         { FGL_ATTR_MAT_FRONT_AMBIENT, M_SHADE_CM_AMBIENT },
         { FGL_ATTR_MAT_FRONT_DIFFUSE, M_SHADE_CM_DIFFUSE },
         { FGL_ATTR_MAT_FRONT_SPECULAR, M_SHADE_CM_SPECULAR },
         { FGL_ATTR_MAT_FRONT_EMISSION, M_SHADE_CM_EMISSION },
      };
      for (unsigned i = 0; i < sizeof(cm) / sizeof(cm[0]); i++) {
         if (la->_ColorMaterialBitmask & FGL_MAT_BIT(cm[i].attr))
            env->color_material |= cm[i].bit;
         if (la->_ColorMaterialBitmask & FGL_MAT_BIT(cm[i].attr + 1))
            env->color_material |= cm[i].bit << M_SHADE_CM_BACK_SHIFT;
      }
   }

   /* the values that are the same at every point, for m_shade_point_prepared
    * (t_render.c's per-primitive materials change no input of them) */
   m_shade_prepare(env);
}
