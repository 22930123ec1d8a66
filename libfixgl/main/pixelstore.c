/*
 * Pixel storage modes (GL_CLIENT_PIXEL_STORE_BIT): glPixelStorei/f, and
 * the GL_BITMAP packing used by glPolygonStipple / glGetPolygonStipple.
 *
 * [S: main/pixelstore.c:pixel_storei] Negative lengths and skips are
 * INVALID_VALUE, an alignment other than 1, 2, 4, 8 too; the call flushes
 * nothing (it does not affect rendering).  glPixelStoref rounds with
 * lroundf into a long that becomes the GLint.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "main/conv.h"
#include "main/groups.h"

static void init_store(struct fgl_pixelstore *p)
{
   memset(p, 0, sizeof(*p));
   p->Alignment = 4;
}

void fgl_init_pixelstore(struct fgl_context *ctx)
{
   init_store(&ctx->Pack);
   init_store(&ctx->Unpack);
}

static void pixel_storei(GLenum pname, GLint param)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   struct fgl_pixelstore *p;
   switch (pname) {
   case GL_PACK_SWAP_BYTES: case GL_PACK_LSB_FIRST: case GL_PACK_ROW_LENGTH:
   case GL_PACK_IMAGE_HEIGHT: case GL_PACK_SKIP_PIXELS: case GL_PACK_SKIP_ROWS:
   case GL_PACK_SKIP_IMAGES: case GL_PACK_ALIGNMENT:
      p = &ctx->Pack;
      break;
   case GL_UNPACK_SWAP_BYTES: case GL_UNPACK_LSB_FIRST: case GL_UNPACK_ROW_LENGTH:
   case GL_UNPACK_IMAGE_HEIGHT: case GL_UNPACK_SKIP_PIXELS: case GL_UNPACK_SKIP_ROWS:
   case GL_UNPACK_SKIP_IMAGES: case GL_UNPACK_ALIGNMENT:
      p = &ctx->Unpack;
      break;
   default:
      /* (the compressed-block and GL_PACK_INVERT_MESA modes are not
       * implemented) */
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   switch (pname) {
   case GL_PACK_SWAP_BYTES:
   case GL_UNPACK_SWAP_BYTES:
      p->SwapBytes = param != 0;
      return;
   case GL_PACK_LSB_FIRST:
   case GL_UNPACK_LSB_FIRST:
      p->LsbFirst = param != 0;
      return;
   case GL_PACK_ALIGNMENT:
   case GL_UNPACK_ALIGNMENT:
      if (param != 1 && param != 2 && param != 4 && param != 8) {
         fgl_error(ctx, GL_INVALID_VALUE);
         return;
      }
      p->Alignment = param;
      return;
   default:
      break;
   }
   if (param < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   switch (pname) {
   case GL_PACK_ROW_LENGTH: case GL_UNPACK_ROW_LENGTH: p->RowLength = param; break;
   case GL_PACK_IMAGE_HEIGHT: case GL_UNPACK_IMAGE_HEIGHT: p->ImageHeight = param; break;
   case GL_PACK_SKIP_PIXELS: case GL_UNPACK_SKIP_PIXELS: p->SkipPixels = param; break;
   case GL_PACK_SKIP_ROWS: case GL_UNPACK_SKIP_ROWS: p->SkipRows = param; break;
   default: p->SkipImages = param; break;
   }
}

void GLAPIENTRY glPixelStorei(GLenum pname, GLint param)
{
   pixel_storei(pname, param);
}

void GLAPIENTRY glPixelStoref(GLenum pname, GLfloat param)
{
   /* _mesa_PixelStoref: lroundf, kept to 32 bits */
   pixel_storei(pname, fgl_lround_to_int(param));
}

/* _mesa_image_offset for GL_BITMAP data (2D): rows of
 * alignment * ceil(row_length / (8 * alignment)) bytes. */
static size_t bitmap_offset(const struct fgl_pixelstore *p, int width, int row)
{
   const size_t ppr = (size_t)(p->RowLength > 0 ? p->RowLength : width);
   const size_t align = (size_t)p->Alignment;
   const size_t bytes_per_row = align * ((ppr + 8 * align - 1) / (8 * align));
   return ((size_t)p->SkipRows + (size_t)row) * bytes_per_row + (size_t)p->SkipPixels / 8;
}

/* pack.c:flip_bytes: reverse the bits of each byte */
static void flip_bytes(uint8_t *b, size_t n)
{
   for (size_t i = 0; i < n; i++) {
      unsigned v = b[i], r = 0;
      for (int k = 0; k < 8; k++)
         r |= ((v >> k) & 1u) << (7 - k);
      b[i] = (uint8_t)r;
   }
}

/* Bits of one row from src (starting at bit `skip` of its first byte, in
 * `lsb`-first order when set) to dst, MSB first, as pack.c's loops do it:
 * each destination byte is cleared when reached, including the one after
 * the last complete byte. */
static void copy_bits(uint8_t *dst, const uint8_t *src, int width, unsigned src_mask,
                      bool src_lsb, unsigned dst_mask, bool dst_lsb)
{
   const uint8_t *s = src;
   uint8_t *d = dst;
   *d = 0;
   for (int i = 0; i < width; i++) {
      if (*s & src_mask)
         *d |= (uint8_t)dst_mask;
      if (src_mask == (src_lsb ? 128u : 1u)) {
         src_mask = src_lsb ? 1u : 128u;
         s++;
      } else {
         src_mask = src_lsb ? src_mask << 1 : src_mask >> 1;
      }
      if (dst_mask == (dst_lsb ? 128u : 1u)) {
         dst_mask = dst_lsb ? 1u : 128u;
         d++;
         *d = 0;
      } else {
         dst_mask = dst_lsb ? dst_mask << 1 : dst_mask >> 1;
      }
   }
}

/* _mesa_unpack_image(2, 32, 32, 1, GL_COLOR_INDEX, GL_BITMAP, ...) followed
 * by _mesa_unpack_polygon_stipple's byte order. */
void fgl_unpack_stipple(const struct fgl_pixelstore *p, const uint8_t *pattern,
                        uint32_t dest[32])
{
   uint8_t buf[32 * 4 + 1];   /* + the byte the skip loop clears past the end */
   for (int row = 0; row < 32; row++) {
      const uint8_t *src = pattern + bitmap_offset(p, 32, row);
      uint8_t *dst = buf + 4 * row;
      if (p->SkipPixels & 7) {
         const unsigned skip = (unsigned)p->SkipPixels & 7;
         if (p->LsbFirst)
            copy_bits(dst, src, 32, 1u << skip, true, 128u, false);
         else
            copy_bits(dst, src, 32, 128u >> skip, false, 128u, false);
      } else {
         memcpy(dst, src, 4);
         if (p->LsbFirst)
            flip_bytes(dst, 4);
      }
   }
   for (int i = 0; i < 32; i++) {
      const uint8_t *b = buf + 4 * i;
      dest[i] = (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3];
   }
}

/* _mesa_pack_polygon_stipple: the words as bytes, then _mesa_pack_bitmap. */
void fgl_pack_stipple(const struct fgl_pixelstore *p, const uint32_t pattern[32],
                      uint8_t *dest)
{
   for (int row = 0; row < 32; row++) {
      uint8_t src[4] = { (uint8_t)(pattern[row] >> 24), (uint8_t)(pattern[row] >> 16),
                         (uint8_t)(pattern[row] >> 8), (uint8_t)pattern[row] };
      uint8_t *dst = dest + bitmap_offset(p, 32, row);
      if ((p->SkipPixels & 7) == 0) {
         memcpy(dst, src, 4);
         if (p->LsbFirst)
            flip_bytes(dst, 4);
      } else {
         const unsigned skip = (unsigned)p->SkipPixels & 7;
         if (p->LsbFirst)
            copy_bits(dst, src, 32, 128u, false, 1u << skip, true);
         else
            copy_bits(dst, src, 32, 128u, false, 128u >> skip, false);
      }
   }
}
