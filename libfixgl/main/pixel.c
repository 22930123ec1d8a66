/*
 * Pixel transfer state (GL_PIXEL_MODE_BIT) and the pixel maps:
 * glPixelTransfer{f,i}, glPixelZoom, glPixelMap{fv,uiv,usv} and
 * glGetPixelMap{fv,uiv,usv} [S: mesa/main/pixel.c].  The state is read by
 * glGet (main/get.c), saved by glPushAttrib(GL_PIXEL_MODE_BIT)
 * (main/attrib.c; the maps are not part of the group, gl_pixel_attrib),
 * and used by glDrawPixels, glCopyPixels, glReadPixels and the texture
 * image paths (main/drawpix.c, main/readpix.c, main/pixelformat.c).
 *
 * Oracle rules:
 *  - glPixelMap checks the size first: outside [1, MAX_PIXEL_MAP_TABLE]
 *    is INVALID_VALUE, and so is a size that is not a power of two for the
 *    maps whose enum lies in [GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_A]
 *    (S_TO_S, I_TO_R/G/B/A; not I_TO_I, not the colour maps).  A bad map
 *    is INVALID_ENUM only after those tests.  A NULL pointer is ignored
 *    without an error (_mesa_map_pbo_source returns it, no PBO is bound).
 *  - store_pixelmap: S_TO_S entries are roundf'ed, I_TO_I ones kept as
 *    given, the colour maps clamped to [0, 1] (CLAMP: NaN becomes 0).
 *    The uiv/usv variants convert first: the index maps by a plain cast,
 *    the others with UINT_TO_FLOAT / USHORT_TO_FLOAT.
 *  - glGetPixelMapuiv copies the bits of the S_TO_S floats (memcpy) and
 *    converts every other map, I_TO_I included, with FLOAT_TO_UINT;
 *    glGetPixelMapusv casts the clamped index maps and rounds the colour
 *    maps half to even (CLAMPED_FLOAT_TO_USHORT).
 *  - glPixelTransferi goes through glPixelTransferf's float; the index
 *    shift and offset are C casts of that float to GLint.
 *  - Display lists: glPixelTransfer, glPixelZoom and glPixelMap are
 *    compiled (the uiv/usv maps converted to floats at compile time,
 *    save_PixelMapuiv/usv), glGetPixelMap executes at once.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "main/conv.h"
#include "main/dlist.h"
#include "main/groups.h"

/* [S: pixel.c:get_pixelmap] */
static struct fgl_pixelmap *get_pixelmap(struct fgl_context *ctx, GLenum map)
{
   switch (map) {
   case GL_PIXEL_MAP_I_TO_I: return &ctx->PixelMaps.ItoI;
   case GL_PIXEL_MAP_S_TO_S: return &ctx->PixelMaps.StoS;
   case GL_PIXEL_MAP_I_TO_R: return &ctx->PixelMaps.ItoR;
   case GL_PIXEL_MAP_I_TO_G: return &ctx->PixelMaps.ItoG;
   case GL_PIXEL_MAP_I_TO_B: return &ctx->PixelMaps.ItoB;
   case GL_PIXEL_MAP_I_TO_A: return &ctx->PixelMaps.ItoA;
   case GL_PIXEL_MAP_R_TO_R: return &ctx->PixelMaps.RtoR;
   case GL_PIXEL_MAP_G_TO_G: return &ctx->PixelMaps.GtoG;
   case GL_PIXEL_MAP_B_TO_B: return &ctx->PixelMaps.BtoB;
   case GL_PIXEL_MAP_A_TO_A: return &ctx->PixelMaps.AtoA;
   default: return NULL;
   }
}

/* ------------------------------------------------------------------ */
/* glPixelZoom, glPixelTransfer                                        */
/* ------------------------------------------------------------------ */

/* A change marks GL_PIXEL_MODE_BIT for glPopAttrib (Mesa passes it to
 * FLUSH_VERTICES), so a value changed and set back still makes the pop
 * restore the group, whose glReadBuffer flushes; glPixelMap passes 0. */

void GLAPIENTRY glPixelZoom(GLfloat xfactor, GLfloat yfactor)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PixelZoom, xfactor, yfactor);
   /* not in Mesa's begin/end dispatch table: INVALID_OPERATION there */
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* [S: pixel.c:_mesa_PixelZoom] */
   if (ctx->Pixel.ZoomX == xfactor && ctx->Pixel.ZoomY == yfactor)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_PIXEL);
   ctx->PopAttribState |= GL_PIXEL_MODE_BIT;   /* FLUSH_VERTICES(.., GL_PIXEL_MODE_BIT) */
   ctx->Pixel.ZoomX = xfactor;
   ctx->Pixel.ZoomY = yfactor;
}

static void set_float(struct fgl_context *ctx, float *dst, float param)
{
   if (*dst == param)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_PIXEL);
   ctx->PopAttribState |= GL_PIXEL_MODE_BIT;
   *dst = param;
}

static void set_int(struct fgl_context *ctx, GLint *dst, float param)
{
   /* (GLint) param: cvttss2si, INT_MIN out of range */
   const GLint v = fgl_double_to_int_trunc((double)param);
   if (*dst == v)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_PIXEL);
   ctx->PopAttribState |= GL_PIXEL_MODE_BIT;
   *dst = v;
}

static void set_flag(struct fgl_context *ctx, bool *dst, float param)
{
   const bool v = param ? true : false;     /* NaN is true */
   if (*dst == v)
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_PIXEL);
   ctx->PopAttribState |= GL_PIXEL_MODE_BIT;
   *dst = v;
}

void GLAPIENTRY glPixelTransferf(GLenum pname, GLfloat param)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PixelTransferf, pname, param);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   struct fgl_pixel_attrib *px = &ctx->Pixel;
   /* [S: pixel.c:_mesa_PixelTransferf] */
   switch (pname) {
   case GL_MAP_COLOR: set_flag(ctx, &px->MapColorFlag, param); break;
   case GL_MAP_STENCIL: set_flag(ctx, &px->MapStencilFlag, param); break;
   case GL_INDEX_SHIFT: set_int(ctx, &px->IndexShift, param); break;
   case GL_INDEX_OFFSET: set_int(ctx, &px->IndexOffset, param); break;
   case GL_RED_SCALE: set_float(ctx, &px->RedScale, param); break;
   case GL_RED_BIAS: set_float(ctx, &px->RedBias, param); break;
   case GL_GREEN_SCALE: set_float(ctx, &px->GreenScale, param); break;
   case GL_GREEN_BIAS: set_float(ctx, &px->GreenBias, param); break;
   case GL_BLUE_SCALE: set_float(ctx, &px->BlueScale, param); break;
   case GL_BLUE_BIAS: set_float(ctx, &px->BlueBias, param); break;
   case GL_ALPHA_SCALE: set_float(ctx, &px->AlphaScale, param); break;
   case GL_ALPHA_BIAS: set_float(ctx, &px->AlphaBias, param); break;
   case GL_DEPTH_SCALE: set_float(ctx, &px->DepthScale, param); break;
   case GL_DEPTH_BIAS: set_float(ctx, &px->DepthBias, param); break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      break;
   }
}

void GLAPIENTRY glPixelTransferi(GLenum pname, GLint param)
{
   /* [S: pixel.c:_mesa_PixelTransferi, dlist.c:save_PixelTransferi] */
   glPixelTransferf(pname, (GLfloat)param);
}

/* ------------------------------------------------------------------ */
/* glPixelMap                                                          */
/* ------------------------------------------------------------------ */

/* The size tests of _mesa_PixelMap{fv,uiv,usv}: false after the error. */
static bool check_map_size(struct fgl_context *ctx, GLenum map, GLsizei mapsize)
{
   if (mapsize < 1 || mapsize > FGL_MAX_PIXEL_MAP_TABLE) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return false;
   }
   /* the enum range test: I_TO_I (below) and the colour maps (above) may
    * have any size */
   if (map >= GL_PIXEL_MAP_S_TO_S && map <= GL_PIXEL_MAP_I_TO_A &&
       (mapsize & (mapsize - 1)) != 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return false;
   }
   return true;
}

/* [S: pixel.c:store_pixelmap] */
static void store_pixelmap(struct fgl_context *ctx, GLenum map, GLsizei mapsize,
                           const GLfloat *values)
{
   struct fgl_pixelmap *pm = get_pixelmap(ctx, map);
   if (!pm) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   pm->Size = mapsize;
   for (GLsizei i = 0; i < mapsize; i++) {
      if (map == GL_PIXEL_MAP_S_TO_S)
         pm->Map[i] = roundf(values[i]);
      else if (map == GL_PIXEL_MAP_I_TO_I)
         pm->Map[i] = values[i];
      else
         pm->Map[i] = fgl_clamp01(values[i]);
   }
}

/* The executed part of _mesa_PixelMapfv (and of uiv/usv after their
 * conversion, which gives the same errors). */
static void pixel_map(struct fgl_context *ctx, GLenum map, GLsizei mapsize,
                      const GLfloat *values)
{
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (!check_map_size(ctx, map, mapsize))
      return;
   FGL_FLUSH_VERTICES(ctx, FGL_NEW_PIXEL);
   if (!values)          /* no PBO: a NULL pointer is ignored */
      return;
   store_pixelmap(ctx, map, mapsize, values);
}

/* The values a compiled map stores: save_PixelMapfv memdups mapsize
 * floats; the node holds at most the table's size (a larger map is an
 * error at replay, whatever its values). */
static unsigned saved_count(GLsizei mapsize, const void *values)
{
   if (!values || mapsize <= 0)
      return 0;
   return mapsize > FGL_MAX_PIXEL_MAP_TABLE ? FGL_MAX_PIXEL_MAP_TABLE : (unsigned)mapsize;
}

void GLAPIENTRY glPixelMapfv(GLenum map, GLsizei mapsize, const GLfloat *values)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, PixelMapfv, map, mapsize, values, saved_count(mapsize, values));
   pixel_map(ctx, map, mapsize, values);
}

/* The conversion of _mesa_PixelMapuiv/usv and save_PixelMapuiv/usv: a
 * plain cast for the index maps, normalised for the colour maps; then
 * what glPixelMapfv does with the floats (the same errors, in the same
 * order: the size tests come before the pointer is looked at). */
static void pixel_map_converted(struct fgl_context *ctx, GLenum map, GLsizei mapsize,
                                const void *values, bool is_uint)
{
   GLfloat fvalues[FGL_MAX_PIXEL_MAP_TABLE];
   const bool index = map == GL_PIXEL_MAP_I_TO_I || map == GL_PIXEL_MAP_S_TO_S;
   if (!ctx->CompileFlag) {
      /* executed: the values are read only after the size tests */
      ASSERT_OUTSIDE_BEGIN_END(ctx);
      if (!check_map_size(ctx, map, mapsize))
         return;
   }
   const unsigned n = saved_count(mapsize, values);
   for (unsigned i = 0; i < n; i++) {
      /* (the application's array need not be aligned: memcpy) */
      if (is_uint) {
         GLuint u;
         memcpy(&u, (const GLubyte *)values + 4 * (size_t)i, sizeof(u));
         fvalues[i] = index ? (GLfloat)u : UINT_TO_FLOAT(u);
      } else {
         GLushort us;
         memcpy(&us, (const GLubyte *)values + 2 * (size_t)i, sizeof(us));
         fvalues[i] = index ? (GLfloat)us : USHORT_TO_FLOAT(us);
      }
   }
   /* save_PixelMapuiv/usv: converted, then save_PixelMapfv, which
    * executes glPixelMapfv of the converted values */
   FGL_SAVE(ctx, PixelMapfv, map, mapsize, fvalues, n);
   pixel_map(ctx, map, mapsize, values ? fvalues : NULL);
}

void GLAPIENTRY glPixelMapuiv(GLenum map, GLsizei mapsize, const GLuint *values)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   pixel_map_converted(ctx, map, mapsize, values, true);
}

void GLAPIENTRY glPixelMapusv(GLenum map, GLsizei mapsize, const GLushort *values)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   pixel_map_converted(ctx, map, mapsize, values, false);
}

/* ------------------------------------------------------------------ */
/* glGetPixelMap                                                       */
/* ------------------------------------------------------------------ */

/* FLOAT_TO_UINT: (GLuint) (x * 4294967295.0) as x86-64 gcc casts a double
 * to a 32-bit unsigned (cvttsd2si into 64 bits, low half kept; out of the
 * int64 range or NaN the indefinite 0x8000000000000000, low half 0). */
static GLuint float_to_uint(float x)
{
   const double d = x * 4294967295.0;
   if (!(d >= -9223372036854775808.0 && d < 9223372036854775808.0))
      return 0;
   return (GLuint)(uint64_t)(int64_t)d;
}

/* The lookup of _mesa_GetnPixelMap*: NULL after the error */
static const struct fgl_pixelmap *get_map_for_query(struct fgl_context *ctx, GLenum map)
{
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, NULL);
   const struct fgl_pixelmap *pm = get_pixelmap(ctx, map);
   if (!pm)
      fgl_error(ctx, GL_INVALID_ENUM);
   return pm;
}

void GLAPIENTRY glGetPixelMapfv(GLenum map, GLfloat *values)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const struct fgl_pixelmap *pm = get_map_for_query(ctx, map);
   if (!pm || !values)
      return;
   /* [S: pixel.c:_mesa_GetnPixelMapfvARB] (S_TO_S: a float cast of the
    * floats, the same values) */
   memcpy(values, pm->Map, (size_t)pm->Size * sizeof(GLfloat));
}

void GLAPIENTRY glGetPixelMapuiv(GLenum map, GLuint *values)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const struct fgl_pixelmap *pm = get_map_for_query(ctx, map);
   if (!pm || !values)
      return;
   /* [S: pixel.c:_mesa_GetnPixelMapuivARB] */
   if (map == GL_PIXEL_MAP_S_TO_S) {
      /* memcpy of the floats: their bit patterns */
      memcpy(values, pm->Map, (size_t)pm->Size * sizeof(GLuint));
      return;
   }
   for (GLint i = 0; i < pm->Size; i++)
      values[i] = float_to_uint(pm->Map[i]);
}

void GLAPIENTRY glGetPixelMapusv(GLenum map, GLushort *values)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const struct fgl_pixelmap *pm = get_map_for_query(ctx, map);
   if (!pm || !values)
      return;
   /* [S: pixel.c:_mesa_GetnPixelMapusvARB] */
   for (GLint i = 0; i < pm->Size; i++) {
      const float v = pm->Map[i];
      if (map == GL_PIXEL_MAP_I_TO_I || map == GL_PIXEL_MAP_S_TO_S) {
         /* (GLushort) CLAMP(v, 0, 65535): truncation, NaN is 0 */
         values[i] = (GLushort)(v > 0.0f ? (v > 65535.0f ? 65535.0f : v) : 0.0f);
      } else {
         /* CLAMPED_FLOAT_TO_USHORT: _mesa_lroundevenf (lrintf) */
         values[i] = (GLushort)lrintf(v * 65535.0f);
      }
   }
}
