/*
 * State queries: glGetBooleanv/Integerv/Floatv/Doublev, glGetError,
 * glGetString.
 *
 * Every value is described once (fill_value) with its type; the four
 * getters convert like Mesa's get.c:
 *   float -> boolean   f != 0 (NaN is true)
 *   float -> integer   lroundf, or FLOAT_TO_INT for normalized values
 *                      (colours, depth values, and matrices, as Mesa does):
 *                      (GLint)(2147483647.0 * f)
 * Out-of-range float->int conversions give INT_MIN, as on x86 where the
 * oracle runs.
 */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "main/conv.h"
#include "main/dlist.h"
#include "main/groups.h"

enum value_type {
   V_BOOL,      /* GLboolean state */
   V_INT,       /* integers and enums */
   V_UINT,      /* unsigned integers: int queries saturate at INT_MAX */
   V_FLOAT,     /* floats converted with lroundf (low 32 bits kept) */
   V_FLOATN,    /* normalized floats converted with FLOAT_TO_INT */
};

struct value {
   enum value_type type;
   int n;
   double v[16];
};

static void set_floats(struct value *val, enum value_type type, const float *f, int n)
{
   val->type = type;
   val->n = n;
   for (int i = 0; i < n; i++)
      val->v[i] = f[i];
}

static void set_ints(struct value *val, enum value_type type, int n, int a, int b, int c, int d)
{
   const int x[4] = { a, b, c, d };
   val->type = type;
   val->n = n;
   for (int i = 0; i < n; i++)
      val->v[i] = x[i];
}

static bool fill_value(struct fgl_context *ctx, GLenum pname, struct value *val)
{
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   float f[4];

   switch (pname) {
   /* GL_CURRENT_BIT */
   /* extra_flush_current: the vertex format's values become current (a
    * colour change then updates the colour-tracking materials) */
   case GL_CURRENT_COLOR:
      fgl_flush_current(ctx);
      set_floats(val, V_FLOATN, ctx->Current.Attrib[FGL_ATTR_COLOR0], 4);
      return true;
   case GL_CURRENT_NORMAL:
      fgl_flush_current(ctx);
      set_floats(val, V_FLOATN, ctx->Current.Attrib[FGL_ATTR_NORMAL], 3);   /* TYPE_FLOATN_3 */
      return true;
   case GL_EDGE_FLAG:
      /* get.c: LOC_CUSTOM, Current.Attrib[VERT_ATTRIB_EDGEFLAG][0] == 1.0F */
      fgl_flush_current(ctx);
      set_ints(val, V_BOOL, 1, ctx->Current.Attrib[FGL_ATTR_EDGEFLAG][0] == 1.0f, 0, 0, 0);
      return true;
   /* GL_COLOR_BUFFER_BIT */
   case GL_COLOR_CLEAR_VALUE:
      for (int i = 0; i < 4; i++)
         f[i] = fgl_clamp01(ctx->Color.ClearColor[i]);
      set_floats(val, V_FLOATN, f, 4);
      return true;
   case GL_ALPHA_TEST_FUNC:
      set_ints(val, V_INT, 1, (int)ctx->Color.AlphaFunc, 0, 0, 0);
      return true;
   case GL_ALPHA_TEST_REF:
      /* _mesa_get_clamp_fragment_color is true for fixed-point buffers */
      f[0] = fgl_clamp01(ctx->Color.AlphaRef);
      set_floats(val, V_FLOATN, f, 1);
      return true;
   case GL_BLEND_SRC:              /* = GL_BLEND_SRC_RGB */
   case GL_BLEND_SRC_ALPHA:
      set_ints(val, V_INT, 1, (int)ctx->Color.BlendSrc, 0, 0, 0);
      return true;
   case GL_BLEND_DST:              /* = GL_BLEND_DST_RGB */
   case GL_BLEND_DST_ALPHA:
      set_ints(val, V_INT, 1, (int)ctx->Color.BlendDst, 0, 0, 0);
      return true;
   case GL_BLEND_EQUATION:         /* = GL_BLEND_EQUATION_RGB */
   case GL_BLEND_EQUATION_ALPHA:
      set_ints(val, V_INT, 1, (int)ctx->Color.BlendEquation, 0, 0, 0);
      return true;
   case GL_BLEND_COLOR:
      for (int i = 0; i < 4; i++)
         f[i] = fgl_clamp01(ctx->Color.BlendColor[i]);
      set_floats(val, V_FLOATN, f, 4);
      return true;
   case GL_LOGIC_OP_MODE:
      set_ints(val, V_INT, 1, (int)ctx->Color.LogicOp, 0, 0, 0);
      return true;
   case GL_COLOR_WRITEMASK: {
      const unsigned m = ctx->Color.ColorMask;
      set_ints(val, V_INT, 4, (m & 1u) != 0, (m & 2u) != 0, (m & 4u) != 0, (m & 8u) != 0);
      return true;
   }
   /* GL_SCISSOR_BIT */
   case GL_SCISSOR_BOX:
      set_ints(val, V_INT, 4, ctx->Scissor.X, ctx->Scissor.Y,
               ctx->Scissor.Width, ctx->Scissor.Height);
      return true;
   /* GL_STENCIL_BUFFER_BIT */
   case GL_STENCIL_FUNC:
      set_ints(val, V_INT, 1, (int)ctx->Stencil.Func, 0, 0, 0);
      return true;
   case GL_STENCIL_FAIL:
      set_ints(val, V_INT, 1, (int)ctx->Stencil.FailFunc, 0, 0, 0);
      return true;
   case GL_STENCIL_PASS_DEPTH_FAIL:
      set_ints(val, V_INT, 1, (int)ctx->Stencil.ZFailFunc, 0, 0, 0);
      return true;
   case GL_STENCIL_PASS_DEPTH_PASS:
      set_ints(val, V_INT, 1, (int)ctx->Stencil.ZPassFunc, 0, 0, 0);
      return true;
   case GL_STENCIL_REF:
      set_ints(val, V_UINT, 1, fgl_stencil_ref(ctx), 0, 0, 0);
      return true;
   case GL_STENCIL_VALUE_MASK:
      val->type = V_UINT;
      val->n = 1;
      val->v[0] = ctx->Stencil.ValueMask;
      return true;
   case GL_STENCIL_WRITEMASK:
      val->type = V_UINT;
      val->n = 1;
      val->v[0] = ctx->Stencil.WriteMask;
      return true;
   case GL_STENCIL_CLEAR_VALUE:
      /* CONTEXT_INT of the GLuint */
      set_ints(val, V_INT, 1, (int)ctx->Stencil.Clear, 0, 0, 0);
      return true;
   /* GL_DEPTH_BUFFER_BIT */
   case GL_DEPTH_CLEAR_VALUE:
      val->type = V_FLOATN;
      val->n = 1;
      val->v[0] = ctx->Depth.Clear;
      return true;
   /* GL_FOG_BIT (Mesa reports the clamped colour: the fixed-point colour
    * buffer makes _mesa_get_clamp_fragment_color true) */
   case GL_FOG_COLOR:
      set_floats(val, V_FLOATN, ctx->Fog.Color, 4);
      return true;
   case GL_FOG_DENSITY:
      set_floats(val, V_FLOAT, &ctx->Fog.Density, 1);
      return true;
   case GL_FOG_START:
      set_floats(val, V_FLOAT, &ctx->Fog.Start, 1);
      return true;
   case GL_FOG_END:
      set_floats(val, V_FLOAT, &ctx->Fog.End, 1);
      return true;
   case GL_FOG_INDEX:
      set_floats(val, V_FLOAT, &ctx->Fog.Index, 1);
      return true;
   case GL_FOG_MODE:
      set_ints(val, V_INT, 1, (int)ctx->Fog.Mode, 0, 0, 0);
      return true;
   case GL_FOG_COORDINATE_SOURCE:
      set_ints(val, V_INT, 1, (int)ctx->Fog.CoordinateSource, 0, 0, 0);
      return true;
   case GL_FOG_DISTANCE_MODE_NV:
      set_ints(val, V_INT, 1, (int)ctx->Fog.DistanceMode, 0, 0, 0);
      return true;
   /* GL_POLYGON_BIT */
   case GL_FRONT_FACE:
      set_ints(val, V_INT, 1, (int)ctx->Polygon.FrontFace, 0, 0, 0);
      return true;
   case GL_CULL_FACE_MODE:
      set_ints(val, V_INT, 1, (int)ctx->Polygon.CullFaceMode, 0, 0, 0);
      return true;
   case GL_POLYGON_MODE:
      set_ints(val, V_INT, 2, (int)ctx->Polygon.FrontMode, (int)ctx->Polygon.BackMode, 0, 0);
      return true;
   case GL_POLYGON_OFFSET_FACTOR:
      set_floats(val, V_FLOAT, &ctx->Polygon.OffsetFactor, 1);
      return true;
   case GL_POLYGON_OFFSET_UNITS:
      set_floats(val, V_FLOAT, &ctx->Polygon.OffsetUnits, 1);
      return true;
   case GL_DEPTH_FUNC:
      set_ints(val, V_INT, 1, (int)ctx->Depth.Func, 0, 0, 0);
      return true;
   case GL_DEPTH_WRITEMASK:
      set_ints(val, V_BOOL, 1, ctx->Depth.Mask, 0, 0, 0);
      return true;
   /* GL_LIGHTING_BIT */
   case GL_SHADE_MODEL:
      set_ints(val, V_INT, 1, (int)ctx->Light.ShadeModel, 0, 0, 0);
      return true;
   case GL_LIGHT_MODEL_AMBIENT:
      set_floats(val, V_FLOATN, ctx->Light.Model.Ambient, 4);
      return true;
   case GL_LIGHT_MODEL_LOCAL_VIEWER:
      set_ints(val, V_BOOL, 1, ctx->Light.Model.LocalViewer, 0, 0, 0);
      return true;
   case GL_LIGHT_MODEL_TWO_SIDE:
      set_ints(val, V_BOOL, 1, ctx->Light.Model.TwoSide, 0, 0, 0);
      return true;
   case GL_LIGHT_MODEL_COLOR_CONTROL:
      set_ints(val, V_INT, 1, (int)ctx->Light.Model.ColorControl, 0, 0, 0);
      return true;
   case GL_COLOR_MATERIAL_FACE:
      set_ints(val, V_INT, 1, (int)ctx->Light.ColorMaterialFace, 0, 0, 0);
      return true;
   case GL_COLOR_MATERIAL_PARAMETER:
      set_ints(val, V_INT, 1, (int)ctx->Light.ColorMaterialMode, 0, 0, 0);
      return true;
   case GL_MAX_LIGHTS:
      set_ints(val, V_INT, 1, FGL_MAX_LIGHTS, 0, 0, 0);
      return true;
   /* GL_TRANSFORM_BIT and matrices */
   case GL_MATRIX_MODE:
      set_ints(val, V_INT, 1, (int)ctx->Transform.MatrixMode, 0, 0, 0);
      return true;
   case GL_MODELVIEW_MATRIX:
      set_floats(val, V_FLOATN, ctx->ModelviewStack.Top->m, 16);
      return true;
   case GL_PROJECTION_MATRIX:
      set_floats(val, V_FLOATN, ctx->ProjectionStack.Top->m, 16);
      return true;
   case GL_TEXTURE_MATRIX:
      set_floats(val, V_FLOATN, ctx->TextureStack[0].Top->m, 16);
      return true;
   case GL_MODELVIEW_STACK_DEPTH:
      set_ints(val, V_INT, 1, (int)ctx->ModelviewStack.Depth + 1, 0, 0, 0);
      return true;
   case GL_PROJECTION_STACK_DEPTH:
      set_ints(val, V_INT, 1, (int)ctx->ProjectionStack.Depth + 1, 0, 0, 0);
      return true;
   case GL_TEXTURE_STACK_DEPTH:
      set_ints(val, V_INT, 1, (int)ctx->TextureStack[0].Depth + 1, 0, 0, 0);
      return true;
   case GL_MAX_CLIP_PLANES:
      set_ints(val, V_INT, 1, FGL_MAX_CLIP_PLANES, 0, 0, 0);
      return true;
   case GL_ATTRIB_STACK_DEPTH:
      set_ints(val, V_INT, 1, (int)ctx->AttribStackDepth, 0, 0, 0);
      return true;
   case GL_MAX_ATTRIB_STACK_DEPTH:
      set_ints(val, V_INT, 1, FGL_MAX_ATTRIB_STACK_DEPTH, 0, 0, 0);
      return true;
   case GL_CLIENT_ATTRIB_STACK_DEPTH:
      set_ints(val, V_INT, 1, (int)ctx->ClientAttribStackDepth, 0, 0, 0);
      return true;
   case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH:
      set_ints(val, V_INT, 1, FGL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 0, 0, 0);
      return true;
   case GL_MAX_MODELVIEW_STACK_DEPTH:
      set_ints(val, V_INT, 1, FGL_MAX_MODELVIEW_STACK_DEPTH, 0, 0, 0);
      return true;
   case GL_MAX_PROJECTION_STACK_DEPTH:
      set_ints(val, V_INT, 1, FGL_MAX_PROJECTION_STACK_DEPTH, 0, 0, 0);
      return true;
   case GL_MAX_TEXTURE_STACK_DEPTH:
      set_ints(val, V_INT, 1, FGL_MAX_TEXTURE_STACK_DEPTH, 0, 0, 0);
      return true;
   /* GL_VIEWPORT_BIT */
   case GL_VIEWPORT:
      set_ints(val, V_INT, 4, ctx->Viewport.X, ctx->Viewport.Y,
               ctx->Viewport.Width, ctx->Viewport.Height);
      return true;
   case GL_DEPTH_RANGE:
      f[0] = ctx->Viewport.Near;
      f[1] = ctx->Viewport.Far;
      set_floats(val, V_FLOATN, f, 2);
      return true;
   case GL_MAX_VIEWPORT_DIMS:
      set_ints(val, V_INT, 2, FGL_MAX_VIEWPORT_SIZE, FGL_MAX_VIEWPORT_SIZE, 0, 0);
      return true;
   case GL_VIEWPORT_BOUNDS_RANGE:
      f[0] = FGL_VIEWPORT_BOUNDS_MIN;
      f[1] = FGL_VIEWPORT_BOUNDS_MAX;
      set_floats(val, V_FLOAT, f, 2);
      return true;
   /* GL_CLIENT_PIXEL_STORE_BIT */
   case GL_PACK_SWAP_BYTES: set_ints(val, V_BOOL, 1, ctx->Pack.SwapBytes, 0, 0, 0); return true;
   case GL_PACK_LSB_FIRST: set_ints(val, V_BOOL, 1, ctx->Pack.LsbFirst, 0, 0, 0); return true;
   case GL_PACK_ROW_LENGTH: set_ints(val, V_INT, 1, ctx->Pack.RowLength, 0, 0, 0); return true;
   case GL_PACK_IMAGE_HEIGHT: set_ints(val, V_INT, 1, ctx->Pack.ImageHeight, 0, 0, 0); return true;
   case GL_PACK_SKIP_PIXELS: set_ints(val, V_INT, 1, ctx->Pack.SkipPixels, 0, 0, 0); return true;
   case GL_PACK_SKIP_ROWS: set_ints(val, V_INT, 1, ctx->Pack.SkipRows, 0, 0, 0); return true;
   case GL_PACK_SKIP_IMAGES: set_ints(val, V_INT, 1, ctx->Pack.SkipImages, 0, 0, 0); return true;
   case GL_PACK_ALIGNMENT: set_ints(val, V_INT, 1, ctx->Pack.Alignment, 0, 0, 0); return true;
   case GL_UNPACK_SWAP_BYTES: set_ints(val, V_BOOL, 1, ctx->Unpack.SwapBytes, 0, 0, 0); return true;
   case GL_UNPACK_LSB_FIRST: set_ints(val, V_BOOL, 1, ctx->Unpack.LsbFirst, 0, 0, 0); return true;
   case GL_UNPACK_ROW_LENGTH: set_ints(val, V_INT, 1, ctx->Unpack.RowLength, 0, 0, 0); return true;
   case GL_UNPACK_IMAGE_HEIGHT: set_ints(val, V_INT, 1, ctx->Unpack.ImageHeight, 0, 0, 0); return true;
   case GL_UNPACK_SKIP_PIXELS: set_ints(val, V_INT, 1, ctx->Unpack.SkipPixels, 0, 0, 0); return true;
   case GL_UNPACK_SKIP_ROWS: set_ints(val, V_INT, 1, ctx->Unpack.SkipRows, 0, 0, 0); return true;
   case GL_UNPACK_SKIP_IMAGES: set_ints(val, V_INT, 1, ctx->Unpack.SkipImages, 0, 0, 0); return true;
   case GL_UNPACK_ALIGNMENT: set_ints(val, V_INT, 1, ctx->Unpack.Alignment, 0, 0, 0); return true;
   /* framebuffer and implementation */
   case GL_RED_BITS:
   case GL_GREEN_BITS:
   case GL_BLUE_BITS:
      set_ints(val, V_INT, 1, 8, 0, 0, 0);
      return true;
   case GL_ALPHA_BITS:
      set_ints(val, V_INT, 1, fb ? fb->AlphaBits : 8, 0, 0, 0);
      return true;
   case GL_DEPTH_BITS:
      set_ints(val, V_INT, 1, fb ? fb->DepthBits : 0, 0, 0, 0);
      return true;
   case GL_STENCIL_BITS:
      set_ints(val, V_INT, 1, fb ? fb->StencilBits : 0, 0, 0, 0);
      return true;
   /* GL_POINT_BIT, GL_LINE_BIT and their limits (Mesa's Const values from
    * llvmpipe's caps: st_extensions.c, lp_screen.c) */
   case GL_POINT_SIZE:
      set_floats(val, V_FLOAT, &ctx->Point.Size, 1);
      return true;
   case GL_POINT_SIZE_RANGE:        /* = GL_SMOOTH_POINT_SIZE_RANGE */
   case GL_ALIASED_POINT_SIZE_RANGE:
      f[0] = FGL_MIN_POINT_SIZE;
      f[1] = FGL_MAX_POINT_SIZE;
      set_floats(val, V_FLOAT, f, 2);
      return true;
   case GL_POINT_SIZE_GRANULARITY:  /* = GL_SMOOTH_POINT_SIZE_GRANULARITY */
   case GL_LINE_WIDTH_GRANULARITY:  /* = GL_SMOOTH_LINE_WIDTH_GRANULARITY */
      f[0] = FGL_POINT_LINE_GRANULARITY;
      set_floats(val, V_FLOAT, f, 1);
      return true;
   case GL_LINE_WIDTH:
      set_floats(val, V_FLOAT, &ctx->Line.Width, 1);
      return true;
   case GL_LINE_WIDTH_RANGE:        /* = GL_SMOOTH_LINE_WIDTH_RANGE */
   case GL_ALIASED_LINE_WIDTH_RANGE:
      f[0] = FGL_MIN_LINE_WIDTH;
      f[1] = FGL_MAX_LINE_WIDTH;
      set_floats(val, V_FLOAT, f, 2);
      return true;
   case GL_LINE_STIPPLE_PATTERN:
      set_ints(val, V_INT, 1, ctx->Line.StipplePattern, 0, 0, 0);
      return true;
   case GL_LINE_STIPPLE_REPEAT:
      set_ints(val, V_INT, 1, ctx->Line.StippleFactor, 0, 0, 0);
      return true;
   case GL_SUBPIXEL_BITS:
      set_ints(val, V_INT, 1, FGL_SUBPIXEL_BITS, 0, 0, 0);
      return true;
   case GL_DOUBLEBUFFER:
   case GL_STEREO:
   case GL_INDEX_MODE:
      set_ints(val, V_BOOL, 1, 0, 0, 0, 0);
      return true;
   case GL_RGBA_MODE:
      set_ints(val, V_BOOL, 1, 1, 0, 0, 0);
      return true;
   case GL_DRAW_BUFFER:
   case GL_READ_BUFFER:
      set_ints(val, V_INT, 1, GL_FRONT, 0, 0, 0);
      return true;
   default: {
      /* GL_HINT_BIT: every glHint target */
      GLenum hint;
      if (fgl_get_hint(ctx, pname, &hint)) {
         set_ints(val, V_INT, 1, (int)hint, 0, 0, 0);
         return true;
      }
      int array_value;
      if (fgl_get_array_value(ctx, pname, &array_value)) {
         set_ints(val, V_INT, 1, array_value, 0, 0, 0);
         return true;
      }
      /* display lists: GL_LIST_BASE, GL_LIST_INDEX, GL_LIST_MODE,
       * GL_MAX_LIST_NESTING (main/dlist.c) */
      int list_value;
      if (fgl_get_list_value(ctx, pname, &list_value)) {
         set_ints(val, V_INT, 1, list_value, 0, 0, 0);
         return true;
      }
      /* selection and feedback (main/feedback.c): GL_RENDER_MODE, the
       * name stack depths, the buffer sizes and GL_FEEDBACK_BUFFER_TYPE */
      int feedback_value;
      if (fgl_get_feedback_value(ctx, pname, &feedback_value)) {
         set_ints(val, V_INT, 1, feedback_value, 0, 0, 0);
         return true;
      }
      /* every capability is also a boolean state value */
      if (fgl_is_cap(ctx, pname, &val->v[0])) {
         val->type = V_BOOL;
         val->n = 1;
         return true;
      }
      return false;
   }
   }
}

/* Common prologue: context, begin/end check, value lookup. */
static bool get_value(GLenum pname, const void *params, struct value *val)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return false;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, false);
   if (!fill_value(ctx, pname, val)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return false;
   }
   return params != NULL;
}

void GLAPIENTRY glGetBooleanv(GLenum pname, GLboolean *params)
{
   struct value val;
   if (!get_value(pname, params, &val))
      return;
   for (int i = 0; i < val.n; i++) {
      if (val.type == V_BOOL || val.type == V_INT || val.type == V_UINT)
         params[i] = val.v[i] != 0.0 ? GL_TRUE : GL_FALSE;
      else
         params[i] = (float)val.v[i] != 0.0f ? GL_TRUE : GL_FALSE; /* NaN is true */
   }
}

void GLAPIENTRY glGetIntegerv(GLenum pname, GLint *params)
{
   struct value val;
   if (!get_value(pname, params, &val))
      return;
   for (int i = 0; i < val.n; i++) {
      switch (val.type) {
      case V_BOOL:
      case V_INT:
         params[i] = (GLint)val.v[i];
         break;
      case V_UINT:
         params[i] = val.v[i] > (double)INT_MAX ? INT_MAX : (GLint)val.v[i];
         break;
      case V_FLOAT:
         params[i] = fgl_lround_to_int((float)val.v[i]);
         break;
      case V_FLOATN:
         params[i] = fgl_float_to_int_norm(val.v[i]);
         break;
      }
   }
}

void GLAPIENTRY glGetFloatv(GLenum pname, GLfloat *params)
{
   struct value val;
   if (!get_value(pname, params, &val))
      return;
   for (int i = 0; i < val.n; i++)
      params[i] = (GLfloat)val.v[i];
}

void GLAPIENTRY glGetDoublev(GLenum pname, GLdouble *params)
{
   struct value val;
   if (!get_value(pname, params, &val))
      return;
   for (int i = 0; i < val.n; i++)
      params[i] = val.v[i];
}

GLenum GLAPIENTRY glGetError(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return GL_NO_ERROR;
   /* inside glBegin/glEnd the call itself is an error and reports nothing */
   ASSERT_OUTSIDE_BEGIN_END_RET(ctx, GL_NO_ERROR);
   const GLenum e = ctx->ErrorValue;
   ctx->ErrorValue = GL_NO_ERROR;
   return e;
}

const GLubyte *GLAPIENTRY glGetString(GLenum name)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return NULL;
   ASSERT_OUTSIDE_BEGIN_END_RET(ctx, NULL);
   switch (name) {
   case GL_VENDOR:
      return (const GLubyte *)"fixgl";
   case GL_RENDERER:
      return (const GLubyte *)"fixgl CPU rasterizer (OpenGL 1.x fixed function)";
   case GL_VERSION:
      /* the GL 1.0 core subset implemented so far */
      return (const GLubyte *)"1.0 fixgl " FIXGL_VERSION_STRING;
   case GL_EXTENSIONS:
      return (const GLubyte *)"";
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return NULL;
   }
}
