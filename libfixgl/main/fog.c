/*
 * Fog state (GL_FOG_BIT): glFog{f,i}[v].  GL_FOG itself is in
 * main/enable.c.  Validation, defaults and the no-op-when-unchanged tests
 * follow Mesa's main/fog.c (_mesa_Fogfv, _mesa_init_fog) in a
 * compatibility context, where GL_FOG_INDEX, GL_FOG_COORDINATE_SOURCE and
 * GL_NV_fog_distance's GL_FOG_DISTANCE_MODE_NV are accepted.  What the
 * vertex stage and the fragment program make of it: tnl/t_fog.c,
 * raster/r_frag.c and state.c.
 */

#include "main/conv.h"
#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_fog(struct fgl_context *ctx)
{
   struct fgl_fog_attrib *fog = &ctx->Fog;
   fog->Enabled = false;
   fog->Mode = GL_EXP;
   for (int i = 0; i < 4; i++)
      fog->Color[i] = fog->ColorUnclamped[i] = 0.0f;
   fog->Index = 0.0f;
   fog->Density = 1.0f;
   fog->Start = 0.0f;
   fog->End = 1.0f;
   fog->CoordinateSource = GL_FRAGMENT_DEPTH;
   fog->DistanceMode = GL_EYE_PLANE_ABSOLUTE_NV;
}

/* A scalar float parameter: flush and store unless it is unchanged
 * (compared with ==, so NaN always stores). */
static void set_float(struct fgl_context *ctx, float *dst, float v)
{
   if (*dst == v)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_FOG);
   *dst = v;
}

static void set_enum(struct fgl_context *ctx, GLenum *dst, GLenum v)
{
   if (*dst == v)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_FOG);
   *dst = v;
}

void GLAPIENTRY glFogfv(GLenum pname, const GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, Fogfv, pname, params, !params ? 0 : pname == GL_FOG_COLOR ? 4 : 1);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (!params)
      return;
   struct fgl_fog_attrib *fog = &ctx->Fog;
   /* enum parameters: (GLenum)(GLint)*params, an x86 float -> int cast */
   const GLenum e = (GLenum)fgl_double_to_int_trunc(params[0]);

   switch (pname) {
   case GL_FOG_MODE:
      if (e != GL_LINEAR && e != GL_EXP && e != GL_EXP2) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      set_enum(ctx, &fog->Mode, e);
      break;
   case GL_FOG_DENSITY:
      if (params[0] < 0.0f) {   /* NaN is accepted */
         fgl_error(ctx, GL_INVALID_VALUE);
         return;
      }
      set_float(ctx, &fog->Density, params[0]);
      break;
   case GL_FOG_START:
      set_float(ctx, &fog->Start, params[0]);
      break;
   case GL_FOG_END:
      set_float(ctx, &fog->End, params[0]);
      break;
   case GL_FOG_INDEX:
      set_float(ctx, &fog->Index, params[0]);
      break;
   case GL_FOG_COLOR:
      /* TEST_EQ_4V against the clamped colour */
      if (fog->Color[0] == params[0] && fog->Color[1] == params[1] &&
          fog->Color[2] == params[2] && fog->Color[3] == params[3])
         return;
      FGL_FLUSH_VERTICES(ctx, FGL_NEW_FOG);
      for (int i = 0; i < 4; i++) {
         fog->ColorUnclamped[i] = params[i];
         fog->Color[i] = fgl_clamp01(params[i]);
      }
      break;
   case GL_FOG_COORDINATE_SOURCE:
      if (e != GL_FOG_COORDINATE && e != GL_FRAGMENT_DEPTH) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      set_enum(ctx, &fog->CoordinateSource, e);
      break;
   case GL_FOG_DISTANCE_MODE_NV:
      if (e != GL_EYE_RADIAL_NV && e != GL_EYE_PLANE && e != GL_EYE_PLANE_ABSOLUTE_NV) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      set_enum(ctx, &fog->DistanceMode, e);
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
}

/* The scalar forms take any pname: the value becomes the first component,
 * the others 0 (so glFogf(GL_FOG_COLOR, x) sets the colour to (x,0,0,0)). */
void GLAPIENTRY glFogf(GLenum pname, GLfloat param)
{
   const GLfloat p[4] = { param, 0.0f, 0.0f, 0.0f };
   glFogfv(pname, p);
}

/* While compiling, save_Fogiv (which glFogi goes through) converts only
 * the pnames it knows: GL_FOG_DISTANCE_MODE_NV is compiled as 0, an error
 * when the list executes [S: main/dlist.c:save_Fogiv]. */
static bool fogiv_compiled_as_zero(GLenum pname)
{
   GET_CURRENT_CONTEXT(ctx);
   return ctx && ctx->CompileFlag && pname == GL_FOG_DISTANCE_MODE_NV;
}

void GLAPIENTRY glFogi(GLenum pname, GLint param)
{
   const GLfloat p[4] = { fogiv_compiled_as_zero(pname) ? 0.0f : (GLfloat)param,
                          0.0f, 0.0f, 0.0f };
   glFogfv(pname, p);
}

/* Integer vectors: the colour is normalized (INT_TO_FLOAT), the scalars
 * are converted; an invalid pname reaches glFogfv's error with zeros. */
void GLAPIENTRY glFogiv(GLenum pname, const GLint *params)
{
   GLfloat p[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
   if (!params)
      return;
   switch (pname) {
   case GL_FOG_MODE:
   case GL_FOG_DENSITY:
   case GL_FOG_START:
   case GL_FOG_END:
   case GL_FOG_INDEX:
   case GL_FOG_COORDINATE_SOURCE:
   case GL_FOG_DISTANCE_MODE_NV:
      if (!fogiv_compiled_as_zero(pname))
         p[0] = (GLfloat)params[0];
      break;
   case GL_FOG_COLOR:
      for (int i = 0; i < 4; i++)
         p[i] = INT_TO_FLOAT(params[i]);
      break;
   default:
      break;
   }
   glFogfv(pname, p);
}
