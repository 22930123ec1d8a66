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
   V_RAWBOOL,   /* a GLboolean stored as given (TYPE_BOOLEAN of a raw byte):
                   booleans, integers and doubles get the byte, floats 0/1 */
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

/* [S: get.c:check_extra, EXTRA_VALID_TEXTURE_UNIT] the active unit's
 * matrix and coordinates exist for the fixed-function units only; past
 * them GL_INVALID_OPERATION (then no value) */
static bool valid_texture_unit(struct fgl_context *ctx)
{
   if (ctx->Texture.CurrentUnit < FGL_MAX_TEXTURE_UNITS)
      return true;
   fgl_error(ctx, GL_INVALID_OPERATION);
   return false;
}

/* the names bound to the active unit */
static const GLuint *bound_names(const struct fgl_context *ctx)
{
   const unsigned u = ctx->Texture.CurrentUnit;
   return u < FGL_MAX_TEXTURE_UNITS ? ctx->Texture.Unit[u].Bound
                                    : ctx->Texture.ImageBound[u - FGL_MAX_TEXTURE_UNITS];
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
   case GL_BLEND_SRC:
   case GL_BLEND_SRC_RGB:
      set_ints(val, V_INT, 1, (int)ctx->Color.BlendSrc, 0, 0, 0);
      return true;
   case GL_BLEND_SRC_ALPHA:
      set_ints(val, V_INT, 1, (int)ctx->Color.BlendSrcA, 0, 0, 0);
      return true;
   case GL_BLEND_DST:
   case GL_BLEND_DST_RGB:
      set_ints(val, V_INT, 1, (int)ctx->Color.BlendDst, 0, 0, 0);
      return true;
   case GL_BLEND_DST_ALPHA:
      set_ints(val, V_INT, 1, (int)ctx->Color.BlendDstA, 0, 0, 0);
      return true;
   case GL_BLEND_EQUATION:         /* = GL_BLEND_EQUATION_RGB */
      set_ints(val, V_INT, 1, (int)ctx->Color.BlendEquation, 0, 0, 0);
      return true;
   case GL_BLEND_EQUATION_ALPHA:
      set_ints(val, V_INT, 1, (int)ctx->Color.BlendEquationA, 0, 0, 0);
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
      set_ints(val, V_RAWBOOL, 1, ctx->Depth.Mask, 0, 0, 0);
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
      if (!valid_texture_unit(ctx))
         return false;
      set_floats(val, V_FLOATN, ctx->TextureStack[ctx->Texture.CurrentUnit].Top->m, 16);
      return true;
   case GL_MODELVIEW_STACK_DEPTH:
      set_ints(val, V_INT, 1, (int)ctx->ModelviewStack.Depth + 1, 0, 0, 0);
      return true;
   case GL_PROJECTION_STACK_DEPTH:
      set_ints(val, V_INT, 1, (int)ctx->ProjectionStack.Depth + 1, 0, 0, 0);
      return true;
   case GL_TEXTURE_STACK_DEPTH:
      if (!valid_texture_unit(ctx))
         return false;
      set_ints(val, V_INT, 1, (int)ctx->TextureStack[ctx->Texture.CurrentUnit].Depth + 1, 0, 0, 0);
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
      /* a wide OSMesa buffer: R16G16B16A16_UNORM or R32G32B32A32_FLOAT */
      set_ints(val, V_INT, 1, fb && fb->Wide ? (fb->WideFormat == R_WIDE_FLOAT ? 32 : 16) : 8,
               0, 0, 0);
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
   /* glPointParameter (main/points.c) */
   case GL_POINT_SIZE_MIN:
      set_floats(val, V_FLOAT, &ctx->Point.MinSize, 1);
      return true;
   case GL_POINT_SIZE_MAX:
      set_floats(val, V_FLOAT, &ctx->Point.MaxSize, 1);
      return true;
   case GL_POINT_FADE_THRESHOLD_SIZE:
      set_floats(val, V_FLOAT, &ctx->Point.Threshold, 1);
      return true;
   case GL_POINT_DISTANCE_ATTENUATION:
      set_floats(val, V_FLOAT, ctx->Point.Params, 3);
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
      set_ints(val, V_BOOL, 1, ctx->DrawBuffer && ctx->DrawBuffer->DoubleBuffer, 0, 0, 0);
      return true;
   case GL_STEREO:
   case GL_INDEX_MODE:
      set_ints(val, V_BOOL, 1, 0, 0, 0, 0);
      return true;
   case GL_RGBA_MODE:
      set_ints(val, V_BOOL, 1, 1, 0, 0, 0);
      return true;
   case GL_DRAW_BUFFER:
      set_ints(val, V_INT, 1, (int)ctx->Color.DrawBuffer, 0, 0, 0);
      return true;
   case GL_READ_BUFFER:
      set_ints(val, V_INT, 1, (int)ctx->Pixel.ReadBuffer, 0, 0, 0);
      return true;
   /* ---- GL 1.3 state of colour index mode, buffer bits and GL 1.4
    * current values, with the types of get_hash_params.py ---- */
   /* colour index (CONST / CONTEXT_INT / CONTEXT_FLOAT) */
   case GL_CURRENT_INDEX:
      /* extra_flush_current */
      fgl_flush_current(ctx);
      set_floats(val, V_FLOAT, ctx->Current.Attrib[FGL_ATTR_COLOR_INDEX], 1);
      return true;
   case GL_INDEX_CLEAR_VALUE:
      /* CONTEXT_INT(Color.ClearIndex): Mesa stores the GLuint */
      set_ints(val, V_INT, 1, (int)ctx->Color.ClearIndex, 0, 0, 0);
      return true;
   case GL_INDEX_WRITEMASK:
      set_ints(val, V_INT, 1, (int)ctx->Color.IndexMask, 0, 0, 0);
      return true;
   case GL_ACCUM_RED_BITS:      /* 16 with an accumulation buffer (main/accum.c) */
   case GL_ACCUM_GREEN_BITS:
   case GL_ACCUM_BLUE_BITS:
   case GL_ACCUM_ALPHA_BITS:
      set_ints(val, V_INT, 1, ctx->DrawBuffer ? ctx->DrawBuffer->AccumBits : 0, 0, 0, 0);
      return true;
   case GL_INDEX_BITS:
   case GL_AUX_BUFFERS:
   case GL_SAMPLE_BUFFERS:      /* nor multisample buffers */
   case GL_SAMPLES:
      set_ints(val, V_INT, 1, 0, 0, 0, 0);
      return true;
   /* GL 1.4 current values (extra_flush_current) */
   case GL_CURRENT_SECONDARY_COLOR:
      fgl_flush_current(ctx);
      set_floats(val, V_FLOATN, ctx->Current.Attrib[FGL_ATTR_COLOR1], 4);
      return true;
   case GL_CURRENT_FOG_COORD:
      fgl_flush_current(ctx);
      set_floats(val, V_FLOAT, ctx->Current.Attrib[FGL_ATTR_FOG], 1);
      return true;
   /* current texture coordinates and raster position */
   case GL_CURRENT_TEXTURE_COORDS:
      /* extra_flush_current_valid_texture_unit: the active unit's vbo
       * attribute */
      fgl_flush_current(ctx);
      if (!valid_texture_unit(ctx))
         return false;
      set_floats(val, V_FLOAT, ctx->Current.Attrib[FGL_ATTR_TEX0 + ctx->Texture.CurrentUnit], 4);
      return true;
   case GL_CURRENT_RASTER_POSITION:
      set_floats(val, V_FLOAT, ctx->Current.RasterPos, 4);
      return true;
   case GL_CURRENT_RASTER_DISTANCE:
      set_floats(val, V_FLOAT, &ctx->Current.RasterDistance, 1);
      return true;
   case GL_CURRENT_RASTER_COLOR:
      set_floats(val, V_FLOATN, ctx->Current.RasterColor, 4);
      return true;
   case GL_CURRENT_RASTER_INDEX:
      set_ints(val, V_INT, 1, 1, 0, 0, 0);     /* CONST(1) */
      return true;
   case GL_CURRENT_RASTER_TEXTURE_COORDS:
      if (!valid_texture_unit(ctx))
         return false;
      set_floats(val, V_FLOAT, ctx->Current.RasterTexCoords[ctx->Texture.CurrentUnit], 4);
      return true;
   case GL_CURRENT_RASTER_POSITION_VALID:
      set_ints(val, V_BOOL, 1, ctx->Current.RasterPosValid, 0, 0, 0);
      return true;
   /* GL_ACCUM_BUFFER_BIT */
   case GL_ACCUM_CLEAR_VALUE:
      set_floats(val, V_FLOATN, ctx->Accum.ClearColor, 4);
      return true;
   /* GL_PIXEL_MODE_BIT */
   case GL_MAP_COLOR: set_ints(val, V_BOOL, 1, ctx->Pixel.MapColorFlag, 0, 0, 0); return true;
   case GL_MAP_STENCIL: set_ints(val, V_BOOL, 1, ctx->Pixel.MapStencilFlag, 0, 0, 0); return true;
   case GL_INDEX_SHIFT: set_ints(val, V_INT, 1, ctx->Pixel.IndexShift, 0, 0, 0); return true;
   case GL_INDEX_OFFSET: set_ints(val, V_INT, 1, ctx->Pixel.IndexOffset, 0, 0, 0); return true;
   case GL_RED_SCALE: set_floats(val, V_FLOAT, &ctx->Pixel.RedScale, 1); return true;
   case GL_GREEN_SCALE: set_floats(val, V_FLOAT, &ctx->Pixel.GreenScale, 1); return true;
   case GL_BLUE_SCALE: set_floats(val, V_FLOAT, &ctx->Pixel.BlueScale, 1); return true;
   case GL_ALPHA_SCALE: set_floats(val, V_FLOAT, &ctx->Pixel.AlphaScale, 1); return true;
   case GL_DEPTH_SCALE: set_floats(val, V_FLOAT, &ctx->Pixel.DepthScale, 1); return true;
   case GL_RED_BIAS: set_floats(val, V_FLOAT, &ctx->Pixel.RedBias, 1); return true;
   case GL_GREEN_BIAS: set_floats(val, V_FLOAT, &ctx->Pixel.GreenBias, 1); return true;
   case GL_BLUE_BIAS: set_floats(val, V_FLOAT, &ctx->Pixel.BlueBias, 1); return true;
   case GL_ALPHA_BIAS: set_floats(val, V_FLOAT, &ctx->Pixel.AlphaBias, 1); return true;
   case GL_DEPTH_BIAS: set_floats(val, V_FLOAT, &ctx->Pixel.DepthBias, 1); return true;
   case GL_ZOOM_X: set_floats(val, V_FLOAT, &ctx->Pixel.ZoomX, 1); return true;
   case GL_ZOOM_Y: set_floats(val, V_FLOAT, &ctx->Pixel.ZoomY, 1); return true;
   case GL_PIXEL_MAP_I_TO_I_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.ItoI.Size, 0, 0, 0); return true;
   case GL_PIXEL_MAP_S_TO_S_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.StoS.Size, 0, 0, 0); return true;
   case GL_PIXEL_MAP_I_TO_R_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.ItoR.Size, 0, 0, 0); return true;
   case GL_PIXEL_MAP_I_TO_G_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.ItoG.Size, 0, 0, 0); return true;
   case GL_PIXEL_MAP_I_TO_B_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.ItoB.Size, 0, 0, 0); return true;
   case GL_PIXEL_MAP_I_TO_A_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.ItoA.Size, 0, 0, 0); return true;
   case GL_PIXEL_MAP_R_TO_R_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.RtoR.Size, 0, 0, 0); return true;
   case GL_PIXEL_MAP_G_TO_G_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.GtoG.Size, 0, 0, 0); return true;
   case GL_PIXEL_MAP_B_TO_B_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.BtoB.Size, 0, 0, 0); return true;
   case GL_PIXEL_MAP_A_TO_A_SIZE: set_ints(val, V_INT, 1, ctx->PixelMaps.AtoA.Size, 0, 0, 0); return true;
   case GL_MAX_PIXEL_MAP_TABLE:
      set_ints(val, V_INT, 1, FGL_MAX_PIXEL_MAP_TABLE, 0, 0, 0);
      return true;
   /* GL_EVAL_BIT */
   case GL_MAP1_GRID_DOMAIN:
      f[0] = ctx->Eval.MapGrid1u1;
      f[1] = ctx->Eval.MapGrid1u2;
      set_floats(val, V_FLOAT, f, 2);
      return true;
   case GL_MAP2_GRID_DOMAIN:
      f[0] = ctx->Eval.MapGrid2u1;
      f[1] = ctx->Eval.MapGrid2u2;
      f[2] = ctx->Eval.MapGrid2v1;
      f[3] = ctx->Eval.MapGrid2v2;
      set_floats(val, V_FLOAT, f, 4);
      return true;
   case GL_MAP1_GRID_SEGMENTS:
      set_ints(val, V_INT, 1, ctx->Eval.MapGrid1un, 0, 0, 0);
      return true;
   case GL_MAP2_GRID_SEGMENTS:
      set_ints(val, V_INT, 2, ctx->Eval.MapGrid2un, ctx->Eval.MapGrid2vn, 0, 0);
      return true;
   case GL_MAX_EVAL_ORDER:
      set_ints(val, V_INT, 1, FGL_MAX_EVAL_ORDER, 0, 0, 0);
      return true;
   /* GL_TEXTURE_BIT and texture limits */
   case GL_ACTIVE_TEXTURE:
      set_ints(val, V_INT, 1, GL_TEXTURE0 + (int)ctx->Texture.CurrentUnit, 0, 0, 0);
      return true;
   case GL_TEXTURE_BINDING_1D:
      set_ints(val, V_INT, 1, (int)bound_names(ctx)[FGL_TEX_1D], 0, 0, 0);
      return true;
   case GL_TEXTURE_BINDING_2D:
      set_ints(val, V_INT, 1, (int)bound_names(ctx)[FGL_TEX_2D], 0, 0, 0);
      return true;
   case GL_TEXTURE_BINDING_3D:
      set_ints(val, V_INT, 1, (int)bound_names(ctx)[FGL_TEX_3D], 0, 0, 0);
      return true;
   case GL_TEXTURE_BINDING_CUBE_MAP:
      set_ints(val, V_INT, 1, (int)bound_names(ctx)[FGL_TEX_CUBE], 0, 0, 0);
      return true;
   case GL_MAX_TEXTURE_UNITS:
      set_ints(val, V_INT, 1, FGL_MAX_TEXTURE_UNITS, 0, 0, 0);
      return true;
   case GL_MAX_TEXTURE_SIZE:
      set_ints(val, V_INT, 1, FGL_MAX_TEXTURE_SIZE, 0, 0, 0);
      return true;
   case GL_MAX_3D_TEXTURE_SIZE:
      set_ints(val, V_INT, 1, FGL_MAX_3D_TEXTURE_SIZE, 0, 0, 0);
      return true;
   case GL_MAX_CUBE_MAP_TEXTURE_SIZE:
      set_ints(val, V_INT, 1, FGL_MAX_CUBE_MAP_TEXTURE_SIZE, 0, 0, 0);
      return true;
   case GL_MAX_TEXTURE_LOD_BIAS:
      f[0] = FGL_MAX_TEXTURE_LOD_BIAS;
      set_floats(val, V_FLOAT, f, 1);
      return true;
   case GL_NUM_COMPRESSED_TEXTURE_FORMATS:
      /* [S: texcompress.c:_mesa_get_compressed_formats] the S3TC formats
       * fixgl has, as the oracle lists them (not DXT1 RGBA, whose 1-bit
       * alpha the list leaves out; the oracle's FXT1 and ETC2 fixgl lacks) */
      set_ints(val, V_INT, 1, 3, 0, 0, 0);
      return true;
   case GL_COMPRESSED_TEXTURE_FORMATS:
      set_ints(val, V_INT, 3, GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
               GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, 0);
      return true;
   case GL_TRANSPOSE_MODELVIEW_MATRIX:
   case GL_TRANSPOSE_PROJECTION_MATRIX:
   case GL_TRANSPOSE_TEXTURE_MATRIX: {
      /* CONTEXT_MATRIX_T: the top of the stack, transposed; for the
       * texture matrix the first stack of TextureMatrixStack, unit 0's
       * whatever the active unit (probe p_transpose_texmat) */
      const fgl_matrix *m = pname == GL_TRANSPOSE_MODELVIEW_MATRIX ? ctx->ModelviewStack.Top
                          : pname == GL_TRANSPOSE_PROJECTION_MATRIX ? ctx->ProjectionStack.Top
                          : ctx->TextureStack[0].Top;
      val->type = V_FLOATN;
      val->n = 16;
      for (int i = 0; i < 4; i++)
         for (int j = 0; j < 4; j++)
            val->v[i * 4 + j] = m->m[j * 4 + i];
      return true;
   }
   /* GL_MULTISAMPLE_BIT */
   case GL_SAMPLE_COVERAGE_VALUE:
      set_floats(val, V_FLOAT, &ctx->Multisample.SampleCoverageValue, 1);
      return true;
   case GL_SAMPLE_COVERAGE_INVERT:
      /* TYPE_BOOLEAN of the byte glSampleCoverage stored */
      set_ints(val, V_RAWBOOL, 1, ctx->Multisample.SampleCoverageInvert, 0, 0, 0);
      return true;
   case GL_MAX_ELEMENTS_VERTICES:
   case GL_MAX_ELEMENTS_INDICES:
      set_ints(val, V_INT, 1, FGL_MAX_ELEMENTS, 0, 0, 0);
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
      /* [S: get.c:find_value] a LOC_TEXUNIT value (the coordinate
       * generation enables) of a unit past the fixed-function ones:
       * GL_INVALID_VALUE (kept before the GL_INVALID_ENUM that follows) */
      if (pname >= GL_TEXTURE_GEN_S && pname <= GL_TEXTURE_GEN_Q &&
          ctx->Texture.CurrentUnit >= FGL_MAX_TEXTURE_UNITS) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return false;
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
      if (val.type == V_RAWBOOL)
         params[i] = (GLboolean)val.v[i];
      else if (val.type == V_BOOL || val.type == V_INT || val.type == V_UINT)
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
      case V_RAWBOOL:
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
      params[i] = val.type == V_RAWBOOL ? (val.v[i] != 0.0 ? 1.0f : 0.0f) : (GLfloat)val.v[i];
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
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, GL_NO_ERROR);
   const GLenum e = ctx->ErrorValue;
   ctx->ErrorValue = GL_NO_ERROR;
   return e;
}

const GLubyte *GLAPIENTRY glGetString(GLenum name)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return NULL;
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, NULL);
   switch (name) {
   case GL_VENDOR:
      return (const GLubyte *)"fixgl";
   case GL_RENDERER:
      return (const GLubyte *)"fixgl CPU rasterizer (OpenGL 1.x fixed function)";
   case GL_VERSION:
      /* GL 1.5: every entry point of GL 1.2-1.5 (api/glext_exports), and
       * no enum of a later version (api/enum_honesty) */
      return (const GLubyte *)"1.5 fixgl " FIXGL_VERSION_STRING;
   case GL_EXTENSIONS:
      /* Exactly the extensions fixgl implements, each with its enums and
       * entry points (the suffixed ones through OSMesaGetProcAddress);
       * api/query_extensions checks the oracle advertises each too:
       *   ARB_multitexture       glActiveTextureARB, glClientActiveTextureARB,
       *                          glMultiTexCoord*ARB, GL_TEXTUREn_ARB
       *   ARB_texture_border_clamp GL_CLAMP_TO_BORDER
       *   ARB/EXT_texture_env_add GL_ADD
       *   ARB/EXT_texture_env_combine GL_COMBINE and its functions,
       *                          sources, operands and scales
       *   ARB_texture_env_crossbar GL_TEXTUREn as a combiner source
       *   ARB/EXT_texture_env_dot3 GL_DOT3_RGB(A)(_EXT)
       *   ARB_texture_mirrored_repeat, IBM_texture_mirrored_repeat
       *                          GL_MIRRORED_REPEAT
       *   ARB_texture_non_power_of_two any texture size
       *   ATI_texture_env_combine3 GL_MODULATE_ADD/SIGNED_ADD/SUBTRACT_ATI
       *   ATI_texture_mirror_once, EXT_texture_mirror_clamp the
       *                          GL_MIRROR_CLAMP* wraps
       *   EXT_abgr, EXT_bgra, EXT_packed_pixels client formats and types
       *   EXT_blend_color        glBlendColor, GL_CONSTANT_* factors
       *   EXT_blend_minmax       glBlendEquation, GL_MIN, GL_MAX
       *   EXT_blend_subtract     GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT
       *   EXT_draw_range_elements glDrawRangeElements
       *   EXT_rescale_normal     GL_RESCALE_NORMAL
       *   EXT_separate_specular_color GL_LIGHT_MODEL_COLOR_CONTROL
       *   EXT_stencil_wrap       GL_INCR_WRAP, GL_DECR_WRAP
       *   ARB_multisample        glSampleCoverage and its state (no samples)
       *   ARB/EXT_point_parameters glPointParameter
       *   ARB_point_sprite       GL_POINT_SPRITE, GL_COORD_REPLACE
       *   ARB_depth_texture, ARB_shadow GL_DEPTH_COMPONENT16/24/32 images,
       *                          GL_DEPTH_TEXTURE_MODE, GL_TEXTURE_COMPARE_*
       *   ARB_texture_compression glCompressedTex*ARB, the generic formats
       *   EXT_texture_compression_s3tc DXT1/DXT3/DXT5 images, compressed by
       *                          the oracle's encoder (main/texcompress_s3tc.c)
       *   ARB_texture_cube_map   GL_TEXTURE_CUBE_MAP, GL_REFLECTION_MAP,
       *                          GL_NORMAL_MAP
       *   EXT_texture3D          glTexImage3DEXT, glTexSubImage3DEXT,
       *                          glCopyTexSubImage3DEXT (GL 1.2's 3D textures)
       *   ARB_transpose_matrix   glLoad/MultTransposeMatrix
       *   EXT_blend_equation_separate, EXT_blend_func_separate
       *   EXT_fog_coord, EXT_secondary_color, EXT_multi_draw_arrays
       *   EXT/SGIS_texture_edge_clamp GL_CLAMP_TO_EDGE
       *   EXT_texture_lod_bias   GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS
       *   EXT_vertex_array       gl*PointerEXT, glArrayElementEXT,
       *                          glDrawArraysEXT, glGetPointervEXT
       *   ARB_vertex_buffer_object, ARB_occlusion_query the GL 1.5
       *                          buffer and query calls' *ARB names
       *   SGIS_generate_mipmap   GL_GENERATE_MIPMAP, GL_GENERATE_MIPMAP_HINT
       *   SGIS_texture_lod       GL_TEXTURE_MIN/MAX_LOD, BASE/MAX_LEVEL
       *   NV_blend_square        GL_SRC_COLOR as source, GL_DST_COLOR as
       *                          destination factor
       *   NV_fog_distance        GL_FOG_DISTANCE_MODE_NV
       *   NV_texture_env_combine4 GL_COMBINE4_NV
       * and fixgl's own (include/fixgl/shading.md; the oracle has neither):
       *   WIN_phong_shading      GL_PHONG_WIN, GL_PHONG_HINT_WIN
       *   FIXGL_cook_torrance    glMaterial's GL_REFLECTANCE_MODEL_FIXGL,
       *                          GL_ROUGHNESS/METALNESS/DIELECTRIC_F0_FIXGL */
      return (const GLubyte *)"GL_ARB_multitexture GL_ARB_occlusion_query "
                              "GL_ARB_vertex_buffer_object "
                              "GL_ARB_texture_border_clamp "
                              "GL_ARB_texture_env_add GL_ARB_texture_env_combine "
                              "GL_ARB_texture_env_crossbar GL_ARB_texture_env_dot3 "
                              "GL_ARB_texture_mirrored_repeat GL_ARB_texture_non_power_of_two "
                              "GL_ATI_texture_env_combine3 GL_ATI_texture_mirror_once "
                              "GL_ARB_depth_texture GL_ARB_multisample GL_ARB_point_parameters GL_ARB_point_sprite "
                              "GL_ARB_shadow GL_ARB_texture_compression GL_ARB_texture_cube_map "
                              "GL_ARB_transpose_matrix "
                              "GL_EXT_blend_equation_separate GL_EXT_blend_func_separate "
                              "GL_EXT_fog_coord GL_EXT_multi_draw_arrays GL_EXT_point_parameters "
                              "GL_EXT_secondary_color "
                              "GL_FIXGL_cook_torrance "
                              "GL_EXT_abgr GL_EXT_bgra "
                              "GL_EXT_blend_color GL_EXT_blend_minmax GL_EXT_blend_subtract "
                              "GL_EXT_draw_range_elements GL_EXT_packed_pixels "
                              "GL_EXT_rescale_normal GL_EXT_separate_specular_color "
                              "GL_EXT_stencil_wrap GL_EXT_texture_edge_clamp "
                              "GL_EXT_texture_env_add GL_EXT_texture_env_combine "
                              "GL_EXT_texture_compression_s3tc "
                              "GL_EXT_texture_env_dot3 GL_EXT_texture_lod_bias "
                              "GL_EXT_texture3D GL_EXT_texture_mirror_clamp GL_EXT_vertex_array "
                              "GL_IBM_texture_mirrored_repeat "
                              "GL_NV_blend_square GL_NV_fog_distance "
                              "GL_NV_texture_env_combine4 GL_SGIS_generate_mipmap GL_SGIS_texture_edge_clamp "
                              "GL_SGIS_texture_lod GL_WIN_phong_shading";
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return NULL;
   }
}
