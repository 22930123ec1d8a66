/*
 * glReadPixels for the formats of the first slice: GL_RGBA and GL_RGB as
 * GL_UNSIGNED_BYTE or GL_FLOAT, and GL_DEPTH_COMPONENT as GL_FLOAT,
 * GL_UNSIGNED_INT or GL_UNSIGNED_SHORT.  Pixels are placed with the pack
 * state (main/image.c:_mesa_image_offset: GL_PACK_ALIGNMENT, ROW_LENGTH,
 * SKIP_PIXELS, SKIP_ROWS; GL_PACK_SWAP_BYTES swaps 2- and 4-byte
 * components); pixels outside the framebuffer are not written.
 * Conversions follow Mesa's unpack functions (format_utils.h, format_unpack.c).
 */
#include <math.h>
#include <string.h>

#include "main/groups.h"

/* _mesa_swap2 / _mesa_swap4 of one component */
static void swap_component(uint8_t *p, size_t bytes)
{
   for (size_t i = 0; i < bytes / 2; i++) {
      const uint8_t t = p[i];
      p[i] = p[bytes - 1 - i];
      p[bytes - 1 - i] = t;
   }
}

/* The pixel types GL knows; another type is an invalid enum, while a
 * known type with a format it does not combine with (or one fixgl does
 * not read yet) is an invalid operation, as in the oracle. */
static bool known_type(GLenum type)
{
   switch (type) {
   case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_SHORT: case GL_SHORT:
   case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: case GL_HALF_FLOAT:
   case GL_BITMAP: case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV:
   case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV:
   case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
   case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV:
   case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
   case GL_UNSIGNED_INT_10_10_10_2: case GL_UNSIGNED_INT_2_10_10_10_REV:
   case GL_UNSIGNED_INT_24_8: case GL_UNSIGNED_INT_10F_11F_11F_REV:
   case GL_UNSIGNED_INT_5_9_9_9_REV: case GL_FLOAT_32_UNSIGNED_INT_24_8_REV:
      return true;
   default:
      return false;
   }
}

static bool color_type_ok(GLenum type)
{
   return type == GL_UNSIGNED_BYTE || type == GL_FLOAT;
}

static bool depth_type_ok(GLenum type)
{
   return type == GL_FLOAT || type == GL_UNSIGNED_INT || type == GL_UNSIGNED_SHORT;
}

/* depth value at internal (y-down) pixel idx, as 24- or 16-bit integer */
static uint32_t depth_at(const struct fgl_framebuffer *fb, size_t idx)
{
   if (fb->ZSFormat == R_ZS_Z16)
      return ((const uint16_t *)fb->Depth)[idx];
   return ((const uint32_t *)fb->Depth)[idx] & 0xffffffu;
}

/* swap: GL_PACK_SWAP_BYTES, which makes GL_UNSIGNED_INT leave the integer
 * fast path (readpix.c:read_uint_depth_pixels) for the float one:
 * _mesa_pack_depth_span's FLOAT_TO_UINT, (GLuint)(z * 4294967295.0). */
static void read_depth_pixel(const struct fgl_framebuffer *fb, size_t idx, GLenum type,
                             bool swap, void *dst)
{
   const uint32_t z = depth_at(fb, idx);
   const bool z16 = fb->ZSFormat == R_ZS_Z16;
   const float f = z16 ? (float)z * (1.0f / 65535.0f)
                       : (float)((double)z * (1.0 / (double)0xffffff));
   switch (type) {
   case GL_FLOAT:
      memcpy(dst, &f, 4);
      break;
   case GL_UNSIGNED_INT: {
      const uint32_t u = swap ? (uint32_t)((double)f * 4294967295.0)
                              : z16 ? (z << 16) | z : (z << 8) | (z >> 16);
      memcpy(dst, &u, 4);
      break;
   }
   default: { /* GL_UNSIGNED_SHORT: through float, rounded (pack.c) */
      const uint16_t u = z16 ? (uint16_t)z : (uint16_t)lrintf(f * 65535.0f);
      memcpy(dst, &u, 2);
      break;
   }
   }
}

void GLAPIENTRY glReadPixels(GLint x, GLint y, GLsizei width, GLsizei height,
                             GLenum format, GLenum type, GLvoid *pixels)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   if (width < 0 || height < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   size_t comps, bytes;
   if (!known_type(type)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   switch (format) {
   case GL_RGBA:
   case GL_RGB:
      if (!color_type_ok(type)) {
         fgl_error(ctx, GL_INVALID_OPERATION);
         return;
      }
      /* _mesa_source_buffer_exists: under glReadBuffer(GL_NONE) there is
       * no colour buffer to read, INVALID_OPERATION after the format and
       * type checks [S: main/readpix.c:read_pixels].  (Mesa's earlier
       * rb == NULL test reads Attachment[BUFFER_NONE = -1], outside the
       * array, and does not fire.)  The formats fixgl does not read yet
       * raise the same error below. */
      if (ctx->Pixel.ReadBuffer == GL_NONE) {
         fgl_error(ctx, GL_INVALID_OPERATION);
         return;
      }
      comps = format == GL_RGBA ? 4 : 3;
      bytes = type == GL_FLOAT ? 4 : 1;
      break;
   case GL_DEPTH_COMPONENT:
      if (!depth_type_ok(type)) {
         fgl_error(ctx, GL_INVALID_OPERATION);
         return;
      }
      if (!fb || fb->DepthBits == 0) {
         fgl_error(ctx, GL_INVALID_OPERATION);
         return;
      }
      comps = 1;
      bytes = type == GL_UNSIGNED_SHORT ? 2 : 4;
      break;
   default:
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (!fb || !pixels)
      return;
   /* [S: st_cb_readpixels.c:st_ReadPixels] glBitmap's cache is drawn
    * before reading */
   fgl_flush_bitmap_cache(ctx);

   const struct fgl_pixelstore *pack = &ctx->Pack;
   const size_t pixel_bytes = comps * bytes;
   const size_t ppr = (size_t)(pack->RowLength > 0 ? pack->RowLength : width);
   size_t row_stride = ppr * pixel_bytes;
   if (row_stride % (size_t)pack->Alignment)
      row_stride += (size_t)pack->Alignment - row_stride % (size_t)pack->Alignment;
   pixels = (uint8_t *)pixels + (size_t)pack->SkipRows * row_stride +
            (size_t)pack->SkipPixels * pixel_bytes;
   const bool swap = pack->SwapBytes && bytes > 1;
   for (GLint j = 0; j < height; j++) {
      const int64_t gy = (int64_t)y + j;          /* GL row, y-up */
      if (gy < 0 || gy >= fb->Height)
         continue;
      const size_t row = (size_t)(fb->Height - 1 - gy);   /* internal y-down row */
      uint8_t *dst_row = (uint8_t *)pixels + (size_t)j * row_stride;
      for (GLint i = 0; i < width; i++) {
         const int64_t gx = (int64_t)x + i;
         if (gx < 0 || gx >= fb->Width)
            continue;
         const size_t idx = row * (size_t)fb->Width + (size_t)gx;
         uint8_t *dst = dst_row + (size_t)i * comps * bytes;
         if (format == GL_DEPTH_COMPONENT) {
            read_depth_pixel(fb, idx, type, swap, dst);
            if (swap)
               swap_component(dst, bytes);
            continue;
         }
         uint8_t src[4];
         memcpy(src, fb->Color + 4 * idx, 4);
         if (fb->AlphaBits == 0)
            src[3] = 255;
         for (size_t c = 0; c < comps; c++) {
            if (type == GL_FLOAT) {
               const float f = (float)src[c] * (1.0f / 255.0f);
               memcpy(dst + 4 * c, &f, 4);
               if (swap)
                  swap_component(dst + 4 * c, 4);
            } else {
               dst[c] = src[c];
            }
         }
      }
   }
}
