/*
 * Client images (see pixelformat.h).
 */
#include "main/pixelformat.h"

#include <string.h>

int fgl_format_components(GLenum format)
{
   switch (format) {
   case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA:
   case GL_LUMINANCE: case GL_INTENSITY: case GL_COLOR_INDEX:
   case GL_STENCIL_INDEX: case GL_DEPTH_COMPONENT:
      return 1;
   case GL_LUMINANCE_ALPHA: case GL_DEPTH_STENCIL:
      return 2;
   case GL_RGB: case GL_BGR:
      return 3;
   case GL_RGBA: case GL_BGRA:
      return 4;
   default:
      return 0;
   }
}

size_t fgl_pixel_bytes(GLenum format, GLenum type)
{
   const int n = fgl_format_components(format);
   switch (type) {
   case GL_UNSIGNED_BYTE: case GL_BYTE:
      return (size_t)n;
   case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_HALF_FLOAT:
      return 2u * (size_t)n;
   case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT:
      return 4u * (size_t)n;
   default:
      return 0;
   }
}

/* [S: image.c:_mesa_image_row_stride] rows padded to the alignment;
 * GL_UNPACK_ROW_LENGTH replaces the width when > 0 */
size_t fgl_image_row_stride(const struct fgl_pixelstore *p, int width, GLenum format,
                            GLenum type)
{
   const size_t bpp = fgl_pixel_bytes(format, type);
   const size_t len = p->RowLength > 0 ? (size_t)p->RowLength : (size_t)width;
   size_t stride = bpp * len;
   const size_t rem = stride % (size_t)p->Alignment;
   if (rem)
      stride += (size_t)p->Alignment - rem;
   return stride;
}

/* [S: image.c:_mesa_image_address] skip pixels and rows, then (row, col) */
const uint8_t *fgl_image_address(const struct fgl_pixelstore *p, const void *pixels,
                                 int width, GLenum format, GLenum type, int row, int col)
{
   const size_t bpp = fgl_pixel_bytes(format, type);
   const size_t stride = fgl_image_row_stride(p, width, format, type);
   return (const uint8_t *)pixels + ((size_t)p->SkipRows + (size_t)row) * stride +
          ((size_t)p->SkipPixels + (size_t)col) * bpp;
}

/* The RGBA8 texel of base format `base` from an RGBA colour (Mesa's
 * rebase: a luminance or intensity texture takes red, and the oracle's
 * sampler swizzle expands the stored channels). */
static void store_texel(GLenum base, const uint8_t c[4], uint8_t *t)
{
   switch (base) {
   case GL_LUMINANCE:       t[0] = t[1] = t[2] = c[0]; t[3] = 255; break;
   case GL_LUMINANCE_ALPHA: t[0] = t[1] = t[2] = c[0]; t[3] = c[3]; break;
   case GL_INTENSITY:       t[0] = t[1] = t[2] = t[3] = c[0]; break;
   case GL_ALPHA:           t[0] = t[1] = t[2] = 0; t[3] = c[3]; break;
   case GL_RGB:             t[0] = c[0]; t[1] = c[1]; t[2] = c[2]; t[3] = 255; break;
   case GL_RGBA:
   default:                 memcpy(t, c, 4); break;
   }
}

bool fgl_unpack_texels_rgba8(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                             int width, int height, GLenum format, GLenum type,
                             const void *pixels, GLenum base, uint8_t *dst)
{
   (void)ctx;
   /* first step: GL_UNSIGNED_BYTE in the plain colour formats, no pixel
    * transfer */
   if (type != GL_UNSIGNED_BYTE)
      return false;
   if (format != GL_RGBA && format != GL_RGB && format != GL_LUMINANCE &&
       format != GL_LUMINANCE_ALPHA && format != GL_ALPHA)
      return false;
   for (int y = 0; y < height; y++) {
      const uint8_t *src = fgl_image_address(p, pixels, width, format, type, y, 0);
      for (int x = 0; x < width; x++) {
         uint8_t c[4] = {0, 0, 0, 255};
         switch (format) {
         case GL_RGBA:  memcpy(c, src, 4); src += 4; break;
         case GL_RGB:   memcpy(c, src, 3); src += 3; break;
         case GL_LUMINANCE: c[0] = c[1] = c[2] = *src++; break;
         case GL_LUMINANCE_ALPHA: c[0] = c[1] = c[2] = src[0]; c[3] = src[1]; src += 2; break;
         case GL_ALPHA: c[0] = c[1] = c[2] = 0; c[3] = *src++; break;
         default: break;
         }
         store_texel(base, c, dst + 4 * ((size_t)y * (size_t)width + (size_t)x));
      }
   }
   return true;
}
