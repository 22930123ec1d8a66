/*
 * Point state (GL_POINT_BIT): glPointSize, glPointParameter (GL 1.4),
 * GL_POINT_SMOOTH and GL_POINT_SPRITE (main/enable.c), GL_COORD_REPLACE
 * (main/texenv.c).  [S: mesa/main/points.c:point_size, _mesa_init_point,
 * _mesa_PointParameterfv]
 *
 * The size is stored as given; the state tracker clamps it to
 * [Point.MinSize, Point.MaxSize] when drawing (st_atom_rasterizer.c),
 * which state.c derives into r_state.  With a distance attenuation other
 * than (1, 0, 0) the vertex program computes each vertex's size instead
 * (tnl/t_vertex.c t_point_size).
 */
#define GL_GLEXT_PROTOTYPES 1
#include "main/groups.h"
#include "main/dlist.h"

void fgl_init_point(struct fgl_context *ctx)
{
   ctx->Point.Size = 1.0f;
   ctx->Point.SmoothFlag = false;
   ctx->Point.MinSize = 0.0f;
   ctx->Point.MaxSize = FGL_MAX_POINT_SIZE;
   ctx->Point.Threshold = 1.0f;
   ctx->Point.Params[0] = 1.0f;
   ctx->Point.Params[1] = 0.0f;
   ctx->Point.Params[2] = 0.0f;
   ctx->Point.PointSprite = false;
   ctx->Point.CoordReplace = 0;
}

void GLAPIENTRY glPointSize(GLfloat size)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PointSize, size);
   /* not in Mesa's begin/end dispatch table: INVALID_OPERATION there */
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* an unchanged size cannot be an error */
   if (ctx->Point.Size == size)
      return;
   if (size <= 0.0f) {        /* NaN passes, as in Mesa */
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_POINT);
   ctx->Point.Size = size;
}

/* A size parameter: negative values are GL_INVALID_VALUE (NaN passes),
 * an unchanged one does nothing */
static void point_size_param(struct fgl_context *ctx, float *dst, float v)
{
   if (v < 0.0f) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (*dst == v)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_POINT);
   *dst = v;
}

/* The internal setter of every glPointParameter [S: main/points.c:
 * _mesa_PointParameterfv]: params[0..2] as floats. */
static void fgl_point_parameter(struct fgl_context *ctx, GLenum pname, const GLfloat *params)
{
   struct fgl_point_attrib *pt = &ctx->Point;
   switch (pname) {
   case GL_POINT_DISTANCE_ATTENUATION:
      if (pt->Params[0] == params[0] && pt->Params[1] == params[1] &&
          pt->Params[2] == params[2])
         return;
      FGL_FLUSH_VERTICES(ctx, FGL_NEW_POINT);
      for (int i = 0; i < 3; i++)
         pt->Params[i] = params[i];
      return;
   case GL_POINT_SIZE_MIN:
      point_size_param(ctx, &pt->MinSize, params[0]);
      return;
   case GL_POINT_SIZE_MAX:
      point_size_param(ctx, &pt->MaxSize, params[0]);
      return;
   case GL_POINT_FADE_THRESHOLD_SIZE:
      point_size_param(ctx, &pt->Threshold, params[0]);
      return;
   /* GL_POINT_SPRITE_COORD_ORIGIN is GL 2.0's (the oracle's 4.5 context
    * takes it): ARB_point_sprite's origin is the upper left, always
    * (README "Version and honesty") */
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
}

/* glPointParameterfv and the other forms [S: main/points.c]: f is
 * (param, 0, 0); i and iv convert to float, iv reading three values only
 * for the attenuation; compiled as glPointParameterfv's three floats
 * (dlist.c:save_PointParameterfvEXT) */
static void point_parameter(GLenum pname, const GLfloat *p)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PointParameterfv, pname, p, 3);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_point_parameter(ctx, pname, p);
}

void GLAPIENTRY glPointParameterfv(GLenum pname, const GLfloat *params)
{
   if (!params)
      return;
   /* Mesa reads three values only for the attenuation */
   const GLfloat p[3] = { params[0], pname == GL_POINT_DISTANCE_ATTENUATION ? params[1] : 0.0f,
                          pname == GL_POINT_DISTANCE_ATTENUATION ? params[2] : 0.0f };
   point_parameter(pname, p);
}

void GLAPIENTRY glPointParameterf(GLenum pname, GLfloat param)
{
   const GLfloat p[3] = { param, 0.0f, 0.0f };
   point_parameter(pname, p);
}

void GLAPIENTRY glPointParameteri(GLenum pname, GLint param)
{
   const GLfloat p[3] = { (GLfloat)param, 0.0f, 0.0f };
   point_parameter(pname, p);
}

void GLAPIENTRY glPointParameteriv(GLenum pname, const GLint *params)
{
   if (!params)
      return;
   const bool atten = pname == GL_POINT_DISTANCE_ATTENUATION;
   const GLfloat p[3] = { (GLfloat)params[0], atten ? (GLfloat)params[1] : 0.0f,
                          atten ? (GLfloat)params[2] : 0.0f };
   point_parameter(pname, p);
}

void GLAPIENTRY glPointParameterfARB(GLenum pname, GLfloat param)
{
   glPointParameterf(pname, param);
}
void GLAPIENTRY glPointParameterfEXT(GLenum pname, GLfloat param)
{
   glPointParameterf(pname, param);
}
void GLAPIENTRY glPointParameterfvARB(GLenum pname, const GLfloat *params)
{
   glPointParameterfv(pname, params);
}
void GLAPIENTRY glPointParameterfvEXT(GLenum pname, const GLfloat *params)
{
   glPointParameterfv(pname, params);
}
