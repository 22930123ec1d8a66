/*
 * The accumulation buffer (GL_ACCUM_BUFFER_BIT): glClearAccum, glAccum and
 * the accumulation part of glClear.
 *
 * The oracle implements glAccum in software on mapped renderbuffers
 * [S: main/accum.c]; its OSMesa accumulation buffer, requested with any
 * accumBits > 0, is PIPE_FORMAT_R16G16B16A16_SNORM
 * [S: gallium/frontends/osmesa/osmesa.c:OSMesaCreateContextAttribs], so
 * GL_ACCUM_*_BITS are 16.  Values are stored as GLshort scaled by 32767 and
 * every operation is C arithmetic on them: float products truncated to
 * GLshort (x86-64: cvttss2si to 32 bits, then the low 16 bits, so values
 * out of range wrap and huge ones or NaN give 0) and GLshort sums that
 * wrap.  GL_RETURN packs through the colour mask but without dithering,
 * blending, logic op or any other fragment operation.  The scissored draw
 * bounds (_Xmin.._Ymax) limit every operation and the clear.
 *
 * The whole-buffer operations work on the framebuffer's Color (RGBA8,
 * y-down) and Accum (4 x int16 per pixel, same layout) directly, outside the
 * raster core.  GL_RETURN does not mark the colour buffer defined (no state
 * validation in the oracle), so glFlush/glFinish copy its result to the
 * application only after a draw or a clear since the last copy.
 *
 * The colour buffer is read and written through its format's unpack and
 * pack; the oracle's GLX drawables have sRGB formats (fb->Srgb), whose
 * red, green and blue go to linear light and back (main/srgb.h; alpha
 * stays linear), so a glAccum there works in linear light while drawing
 * does not (GL_FRAMEBUFFER_SRGB off; ORACLE-NOTES.md "GLX sRGB
 * buffers").  The conversion is chosen once per call (color_io).
 */
#include <stdint.h>

#include "main/groups.h"
#include "main/dlist.h"
#include "main/srgb.h"

/* (GLshort)f as the oracle's x86-64 build converts: cvttss2si to a 32-bit
 * integer (0x80000000 for NaN and out of range), then the low 16 bits */
static int16_t float_to_short_x86(float f)
{
   int32_t i = INT32_MIN;
   if (f >= -2147483648.0f && f < 2147483648.0f)
      i = (int32_t)f;
   const uint16_t lo = (uint16_t)(uint32_t)i;
   return (int16_t)(lo >= 0x8000u ? (int32_t)lo - 0x10000 : (int32_t)lo);
}

/* GLshort += GLshort: the int sum stored back wraps */
static int16_t add_short(int16_t a, int16_t b)
{
   const uint16_t lo = (uint16_t)((uint32_t)(int32_t)a + (uint32_t)(int32_t)b);
   return (int16_t)(lo >= 0x8000u ? (int32_t)lo - 0x10000 : (int32_t)lo);
}

/* [S: util/u_math.h:ubyte_to_float] (the unpack of the UNORM8 colour
 * buffer, util_format_*_unpack_rgba_float) */
static float ubyte_to_float(uint8_t ub)
{
   return (float)ub * (1.0f / 255.0f);
}

/* [S: util/u_math.h:float_to_ubyte] (the pack into the UNORM8 colour
 * buffer, util_format_*_pack_rgba_float) */
static uint8_t float_to_ubyte(float f)
{
   if (!(f > 0.0f))
      return 0;
   if (f >= 1.0f)
      return 255;
   union { float f; uint32_t i; } tmp;
   tmp.f = f * (255.0f / 256.0f) + 32768.0f;
   return (uint8_t)tmp.i;
}

/* FLOAT_TO_SHORT [S: main/macros.h] */
static int16_t clear_to_short(float x)
{
   return (int16_t)((((int32_t)(65535.0f * x)) - 1) / 2);
}

void fgl_init_accum(struct fgl_context *ctx)
{
   for (int i = 0; i < 4; i++)
      ctx->Accum.ClearColor[i] = 0.0f;
}

/* CLAMP [S: util/macros.h]: NaN gives the minimum */
static float clampf(float v, float lo, float hi)
{
   return v > lo ? (v > hi ? hi : v) : lo;
}

void GLAPIENTRY glClearAccum(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ClearAccum, red, green, blue, alpha);
   /* no check of its own: only the BeginEnd dispatch's */
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* [S: main/accum.c:_mesa_ClearAccum]: CLAMP to [-1, 1] (NaN gives -1),
    * no flush, and an unchanged value is not marked for
    * glPopAttrib */
   float tmp[4] = {
      clampf(red, -1.0f, 1.0f), clampf(green, -1.0f, 1.0f),
      clampf(blue, -1.0f, 1.0f), clampf(alpha, -1.0f, 1.0f),
   };
   if (tmp[0] == ctx->Accum.ClearColor[0] && tmp[1] == ctx->Accum.ClearColor[1] &&
       tmp[2] == ctx->Accum.ClearColor[2] && tmp[3] == ctx->Accum.ClearColor[3])
      return;
   ctx->PopAttribState |= GL_ACCUM_BUFFER_BIT;
   for (int i = 0; i < 4; i++)
      ctx->Accum.ClearColor[i] = tmp[i];
}

/* The scissored draw bounds as storage rows/columns: x0..x1, rows
 * r0..r1 (y-down, exclusive ends) */
static void accum_region(const struct fgl_context *ctx, int *x0, int *x1, int *r0, int *r1)
{
   int bbox[4];
   fgl_scissor_bounds(ctx, bbox);
   const int h = ctx->DrawBuffer->Height;
   *x0 = bbox[0];
   *x1 = bbox[1];
   *r0 = h - bbox[3];
   *r1 = h - bbox[2];
}

/* [S: main/accum.c:_mesa_clear_accum_buffer], called by glClear */
void fgl_clear_accum_buffer(struct fgl_context *ctx)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   if (!fb || !fb->Accum)
      return;
   int x0, x1, r0, r1;
   accum_region(ctx, &x0, &x1, &r0, &r1);
   int16_t clear[4];
   for (int c = 0; c < 4; c++)
      clear[c] = clear_to_short(ctx->Accum.ClearColor[c]);
   for (int r = r0; r < r1; r++) {
      int16_t *acc = fb->Accum + ((size_t)r * (size_t)fb->Width + (size_t)x0) * 4;
      for (int x = x0; x < x1; x++, acc += 4)
         for (int c = 0; c < 4; c++)
            acc[c] = clear[c];
   }
}

/* [S: util/format/u_format_pack.py] unorm16 to float: x * (1 / 65535) */
static float ushort_to_float(uint16_t us)
{
   return (float)us * (1.0f / 65535.0f);
}

/* [S: util/format/u_format_pack.py] float to unorm16: clamped to [0, 1]
 * (NaN gives 0), then util_iround(f * 65535), (int)(f + 0.5f): halves
 * round up (case osmesa/ushort_accum: six channels on a half) */
static uint16_t float_to_ushort(float f)
{
   const float c = f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f;
   return (uint16_t)(int)(c * 65535.0f + 0.5f);
}

/* the colour buffer's unpacked RGBA at pixel `idx` (alpha 1 without alpha
 * bits: the RGB formats unpack it as one): the wide target of an OSMesa
 * GL_UNSIGNED_SHORT or GL_FLOAT buffer where there is one
 * (R16G16B16A16_UNORM, R32G32B32A32_FLOAT), else the RGBA8 image `color`
 * (fb->Color, or the read buffer of a separate front: fgl_read_color) */
static void unpack_plain(const struct fgl_framebuffer *fb, const uint8_t *color, size_t idx,
                         float rgba[4])
{
   if (fb->WideFormat == R_WIDE_UNORM16) {
      const uint16_t *src = (const uint16_t *)fb->Wide + 4 * idx;
      for (int c = 0; c < 4; c++)
         rgba[c] = ushort_to_float(src[c]);
   } else if (fb->WideFormat == R_WIDE_FLOAT) {
      const float *src = (const float *)fb->Wide + 4 * idx;
      for (int c = 0; c < 4; c++)
         rgba[c] = src[c];
   } else {
      const uint8_t *src = color + 4 * idx;
      for (int c = 0; c < 4; c++)
         rgba[c] = ubyte_to_float(src[c]);
   }
   if (fb->AlphaBits == 0)
      rgba[3] = 1.0f;
}

/* rgba packed into the colour buffer at pixel `idx` (nch channels: 3 for
 * the RGB formats), into the wide target and its RGBA8 image where there
 * is one */
static void pack_plain(struct fgl_framebuffer *fb, uint8_t *color, size_t idx, const float rgba[4],
                       int nch)
{
   if (fb->WideFormat == R_WIDE_UNORM16) {
      uint16_t *dst = (uint16_t *)fb->Wide + 4 * idx;
      for (int c = 0; c < nch; c++)
         dst[c] = float_to_ushort(rgba[c]);
   } else if (fb->WideFormat == R_WIDE_FLOAT) {
      float *dst = (float *)fb->Wide + 4 * idx;
      for (int c = 0; c < nch; c++)
         dst[c] = rgba[c];
   }
   uint8_t *col = color + 4 * idx;
   for (int c = 0; c < nch; c++)
      col[c] = float_to_ubyte(rgba[c]);
}

/* the 8-bit sRGB formats (B8G8R8A8_SRGB, B8G8R8X8_SRGB): red, green and
 * blue through the oracle's table to linear light, alpha as UNORM8 (one
 * without alpha bits) */
static void unpack_srgb8(const struct fgl_framebuffer *fb, const uint8_t *color, size_t idx,
                         float rgba[4])
{
   const uint8_t *src = color + 4 * idx;
   for (int c = 0; c < 3; c++)
      rgba[c] = fgl_srgb8_to_linear(src[c]);
   rgba[3] = fb->AlphaBits == 0 ? 1.0f : ubyte_to_float(src[3]);
}

static void pack_srgb8(struct fgl_framebuffer *fb, uint8_t *color, size_t idx, const float rgba[4],
                       int nch)
{
   (void)fb;
   uint8_t *col = color + 4 * idx;
   for (int c = 0; c < 3; c++)
      col[c] = fgl_linear_to_srgb8(rgba[c]);
   if (nch == 4)
      col[3] = float_to_ubyte(rgba[3]);
}

/* the colour buffer's unpack and pack, by its format */
struct color_io {
   void (*unpack)(const struct fgl_framebuffer *fb, const uint8_t *color, size_t idx,
                  float rgba[4]);
   void (*pack)(struct fgl_framebuffer *fb, uint8_t *color, size_t idx, const float rgba[4],
                int nch);
};

static struct color_io color_io(const struct fgl_framebuffer *fb)
{
   if (fb->Srgb)
      return (struct color_io){ unpack_srgb8, pack_srgb8 };
   return (struct color_io){ unpack_plain, pack_plain };
}

/* [S: main/accum.c:accum_scale_or_bias] */
static void accum_scale_or_bias(struct fgl_context *ctx, float value, bool bias)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   int x0, x1, r0, r1;
   accum_region(ctx, &x0, &x1, &r0, &r1);
   const int16_t incr = float_to_short_x86(value * 32767.0f);
   for (int r = r0; r < r1; r++) {
      int16_t *acc = fb->Accum + ((size_t)r * (size_t)fb->Width + (size_t)x0) * 4;
      for (int i = 0; i < 4 * (x1 - x0); i++) {
         if (bias)
            acc[i] = add_short(acc[i], incr);
         else
            acc[i] = float_to_short_x86((float)acc[i] * value);
      }
   }
}

/* [S: main/accum.c:accum_or_load]: the read buffer's colours times
 * value * 32767 (one float product), truncated; no read buffer (glReadBuffer
 * GL_NONE) does nothing */
static void accum_or_load(struct fgl_context *ctx, float value, bool load)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   if (ctx->Pixel.ReadBuffer == GL_NONE)
      return;
   int x0, x1, r0, r1;
   accum_region(ctx, &x0, &x1, &r0, &r1);
   const float scale = value * 32767.0f;
   const uint8_t *read_color = fgl_read_color(ctx);
   const struct color_io io = color_io(fb);
   for (int r = r0; r < r1; r++) {
      const size_t first = (size_t)r * (size_t)fb->Width + (size_t)x0;
      int16_t *acc = fb->Accum + first * 4;
      for (int x = x0; x < x1; x++, acc += 4) {
         float rgba[4];
         io.unpack(fb, read_color, first + (size_t)(x - x0), rgba);
         for (int c = 0; c < 4; c++) {
            const int16_t v = float_to_short_x86(rgba[c] * scale);
            acc[c] = load ? v : add_short(acc[c], v);
         }
      }
   }
}

/* [S: main/accum.c:accum_return]: accum * (value / 32767) packed into the
 * draw buffer `color` (each of them: both under fb->DrawBoth); a channel
 * the colour mask disables keeps the buffer's colour (unpacked and packed
 * again).  Row r takes the accumulation row r - skip (y-down): see
 * accum_return for the second buffer; rows whose source would lie above
 * the buffer are left as they are (the oracle reads outside its buffer
 * there) */
static void accum_return_into(struct fgl_context *ctx, uint8_t *color, float value, int skip)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   int x0, x1, r0, r1;
   accum_region(ctx, &x0, &x1, &r0, &r1);
   const float scale = value / 32767.0f;
   const unsigned mask = ctx->Color.ColorMask & 0xfu;
   const int nch = fb->AlphaBits > 0 ? 4 : 3;
   const struct color_io io = color_io(fb);
   for (int r = r0; r < r1; r++) {
      if (r - skip < 0)
         continue;
      const size_t first = (size_t)r * (size_t)fb->Width + (size_t)x0;
      const int16_t *acc = fb->Accum + ((size_t)(r - skip) * (size_t)fb->Width + (size_t)x0) * 4;
      for (int x = x0; x < x1; x++, acc += 4) {
         const size_t idx = first + (size_t)(x - x0);
         float rgba[4];
         for (int c = 0; c < 4; c++)
            rgba[c] = (float)acc[c] * scale;
         if (mask != 0xfu) {
            float dest[4];
            io.unpack(fb, color, idx, dest);
            for (int c = 0; c < 4; c++)
               if (!(mask & (1u << c)))
                  rgba[c] = dest[c];
         }
         io.pack(fb, color, idx, rgba, nch);
      }
   }
}

/* glDrawBuffer(GL_NONE) writes nothing.  Into both buffers (fb->DrawBoth)
 * the oracle's loop over the draw buffers writes the front (FRONT_LEFT,
 * Other) first, then the back, without going back to the start of the
 * region in the accumulation buffer it walks row by row: the back's row
 * y (GL's, up) gets the accumulation row y + height of the region
 * (ORACLE-NOTES.md "Both buffers") */
static void accum_return(struct fgl_context *ctx, float value)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   if (ctx->Color.DrawBuffer == GL_NONE)
      return;
   if (!fb->DrawBoth) {
      accum_return_into(ctx, fb->Color, value, 0);
      return;
   }
   int x0, x1, r0, r1;
   accum_region(ctx, &x0, &x1, &r0, &r1);
   accum_return_into(ctx, fb->Other, value, 0);
   accum_return_into(ctx, fb->Color, value, r1 - r0);
}

void GLAPIENTRY glAccum(GLenum op, GLfloat value)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, Accum, op, value);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* [S: main/accum.c:_mesa_Accum] */
   FGL_FLUSH_VERTICES(ctx, 0);
   switch (op) {
   case GL_ADD:
   case GL_MULT:
   case GL_ACCUM:
   case GL_LOAD:
   case GL_RETURN:
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   if (!fb || fb->AccumBits == 0) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   /* a separate read drawable (glXMakeContextCurrent): "different
    * read/draw buffers" (ORACLE-NOTES.md "GLX read drawables") */
   if (ctx->ReadFb) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (ctx->RenderMode != GL_RENDER || !fb->Accum)
      return;
   fgl_scene_flush(ctx);   /* reads or writes the colour buffer */
   fgl_vpcut_invalidate(ctx);   /* the oracle's map: a flush */
   fgl_lin_flushed(ctx);

   /* [S: main/accum.c:accum]: ADD of 0, MULT by 1 and ACCUM of 0 do
    * nothing (a MULT by 1 would otherwise be exact anyway) */
   switch (op) {
   case GL_ADD:
      if (value != 0.0f)
         accum_scale_or_bias(ctx, value, true);
      break;
   case GL_MULT:
      if (value != 1.0f)
         accum_scale_or_bias(ctx, value, false);
      break;
   case GL_ACCUM:
      if (value != 0.0f)
         accum_or_load(ctx, value, false);
      break;
   case GL_LOAD:
      accum_or_load(ctx, value, true);
      break;
   default: /* GL_RETURN */
      accum_return(ctx, value);
      break;
   }
}
