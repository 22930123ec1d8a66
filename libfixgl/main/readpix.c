/*
 * glReadPixels for the formats of the first slice: GL_RGBA and GL_RGB as
 * GL_UNSIGNED_BYTE or GL_FLOAT, and GL_DEPTH_COMPONENT as GL_FLOAT,
 * GL_UNSIGNED_INT or GL_UNSIGNED_SHORT.  Rows are packed with the default
 * GL_PACK_ALIGNMENT of 4; pixels outside the framebuffer are not written.
 * Conversions follow Mesa's unpack functions (format_utils.h, format_unpack.c).
 */
#include <math.h>
#include <string.h>

#include "main/groups.h"

static size_t align4(size_t n)
{
   return (n + 3) & ~(size_t)3;
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

static void read_depth_pixel(const struct fgl_framebuffer *fb, size_t idx, GLenum type, void *dst)
{
   const uint32_t z = depth_at(fb, idx);
   const bool z16 = fb->ZSFormat == R_ZS_Z16;
   switch (type) {
   case GL_FLOAT: {
      const float f = z16 ? (float)z * (1.0f / 65535.0f)
                          : (float)((double)z * (1.0 / (double)0xffffff));
      memcpy(dst, &f, 4);
      break;
   }
   case GL_UNSIGNED_INT: {
      const uint32_t u = z16 ? (z << 16) | z : (z << 8) | (z >> 16);
      memcpy(dst, &u, 4);
      break;
   }
   default: { /* GL_UNSIGNED_SHORT: through float, rounded (pack.c) */
      const float f = (float)((double)z * (1.0 / (double)0xffffff));
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
   ASSERT_OUTSIDE_BEGIN_END(ctx);
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

   const size_t row_stride = align4((size_t)width * comps * bytes);
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
            read_depth_pixel(fb, idx, type, dst);
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
            } else {
               dst[c] = src[c];
            }
         }
      }
   }
}
