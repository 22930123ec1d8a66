/*
 * glReadPixels [S: main/readpix.c:read_pixels, _mesa_readpixels;
 * state_tracker/st_cb_readpixels.c:st_ReadPixels, which on llvmpipe (no
 * PIPE_CAP_TEXTURE_TRANSFER_MODES) always falls back to _mesa_readpixels].
 * Every colour format and type (the conversions are in pixelformat.c),
 * GL_DEPTH_COMPONENT and GL_STENCIL_INDEX in every type the oracle takes
 * (GL_DEPTH_STENCIL, GL_RG and the integer formats are not GL 1.5's:
 * GL_INVALID_ENUM), with the pack state and the pixel transfer
 * operations.  The rectangle is first clipped to the buffer
 * (image.c:_mesa_clip_readpixels, which moves SKIP_PIXELS/SKIP_ROWS and
 * sets ROW_LENGTH to the width when 0); pixels outside are not written.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "main/groups.h"
#include "main/pixelformat.h"
#include "fgl_alloc.h"

/* depth value at internal (y-down) pixel idx, as 32-, 24- or 16-bit integer */
static uint32_t depth_at(const struct fgl_framebuffer *fb, size_t idx)
{
   if (fb->ZSFormat == R_ZS_Z16)
      return ((const uint16_t *)fb->Depth)[idx];
   if (fb->ZSFormat == R_ZS_Z32)
      return ((const uint32_t *)fb->Depth)[idx];
   return ((const uint32_t *)fb->Depth)[idx] & 0xffffffu;
}

/* [S: util/format unpack_z_float] Z16: z * (1.0f / 0xffff); Z24 and Z32:
 * in double */
static float depth_float_at(const struct fgl_framebuffer *fb, size_t idx)
{
   const uint32_t z = depth_at(fb, idx);
   if (fb->ZSFormat == R_ZS_Z16)
      return (float)z * (1.0f / 65535.0f);
   if (fb->ZSFormat == R_ZS_Z32)
      return (float)((double)z * (1.0 / (double)0xffffffffu));
   return (float)((double)z * (1.0 / (double)0xffffff));
}

/* [S: util/format unpack_z_32unorm] the depth bits replicated to 32 */
static uint32_t depth_uint_at(const struct fgl_framebuffer *fb, size_t idx)
{
   const uint32_t z = depth_at(fb, idx);
   if (fb->ZSFormat == R_ZS_Z16)
      return (z << 16) | z;
   if (fb->ZSFormat == R_ZS_Z32)
      return z;
   return (z << 8) | (z >> 16);
}

static uint8_t stencil_at(const struct fgl_framebuffer *fb, size_t idx)
{
   if (fb->ZSFormat == R_ZS_S8)
      return fb->Stencil[idx];
   return (uint8_t)(((const uint32_t *)fb->Depth)[idx] >> 24);
}

/* [S: glformats.c:_mesa_is_depth_format, _mesa_is_depthstencil_format] */
static bool is_depth_or_ds_format(GLenum format)
{
   switch (format) {
   case GL_DEPTH_COMPONENT: case GL_DEPTH_COMPONENT16: case GL_DEPTH_COMPONENT24:
   case GL_DEPTH_COMPONENT32: case GL_DEPTH_COMPONENT32F:
   case GL_DEPTH_STENCIL: case GL_DEPTH24_STENCIL8: case GL_DEPTH32F_STENCIL8:
      return true;
   default:
      return false;
   }
}

/* [S: framebuffer.c:renderbuffer_exists] for reading */
static bool source_buffer_exists(const struct fgl_context *ctx,
                                 const struct fgl_framebuffer *fb, GLenum format)
{
   switch (format) {
   case GL_DEPTH_COMPONENT:
      return fb->DepthBits > 0;
   case GL_STENCIL_INDEX:
      return fb->StencilBits > 0;
   case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE:
   case GL_LUMINANCE_ALPHA: case GL_INTENSITY: case GL_RGB: case GL_BGR:
   case GL_RGBA: case GL_BGRA: case GL_ABGR_EXT:
      /* no colour buffer to read under glReadBuffer(GL_NONE) */
      return ctx->Pixel.ReadBuffer != GL_NONE;
   default:   /* GL_COLOR_INDEX: no index buffer */
      return false;
   }
}

/* the clipped rectangle, in GL (y-up) coordinates */
struct read_rect {
   GLint x, y;
   GLsizei width, height;
};

/* glReadPixels of a colour format from a wide colour buffer (OSMesa
 * GL_UNSIGNED_SHORT and GL_FLOAT buffers): the rectangle's values, alpha
 * 1 for a buffer without alpha, converted by fgl_pack_wide as the oracle
 * converts its R16G16B16A16_UNORM / R32G32B32A32_FLOAT render target.
 * Measured: probe p_osmesa_wide, cases osmesa/ushort_readpixels_formats and siblings. */
static void read_color_wide(struct fgl_context *ctx, const struct fgl_framebuffer *fb,
                            const struct read_rect *r, const struct fgl_pixelstore *pack,
                            GLenum format, GLenum type, void *pixels)
{
   const bool u16 = fb->WideFormat == R_WIDE_UNORM16;
   const size_t n = (size_t)r->width * (size_t)r->height;
   void *src = fgl_malloc_gl(ctx, n * 4 * (u16 ? sizeof(uint16_t) : sizeof(float)));
   if (!src) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   /* rows bottom-up as GL reads them; the buffer is stored y-down */
   for (GLsizei j = 0; j < r->height; j++) {
      const size_t row = (size_t)(fb->Height - 1 - (r->y + j));
      const size_t at = 4 * (row * (size_t)fb->Width + (size_t)r->x);
      const size_t to = 4 * (size_t)j * (size_t)r->width;
      if (u16) {
         uint16_t *d = (uint16_t *)src + to;
         memcpy(d, (const uint16_t *)fb->Wide + at, 8 * (size_t)r->width);
         if (fb->AlphaBits == 0)
            for (GLsizei i = 0; i < r->width; i++)
               d[4 * i + 3] = 65535u;
      } else {
         float *d = (float *)src + to;
         memcpy(d, (const float *)fb->Wide + at, 16 * (size_t)r->width);
         if (fb->AlphaBits == 0)
            for (GLsizei i = 0; i < r->width; i++)
               d[4 * i + 3] = 1.0f;
      }
   }
   if (!fgl_pack_wide(ctx, pack, r->width, r->height, u16 ? src : NULL, u16 ? NULL : src,
                      format, type, pixels))
      fgl_error(ctx, GL_INVALID_OPERATION);   /* not reached: validated */
   fgl_free(src);
}

static void read_color(struct fgl_context *ctx, const struct fgl_framebuffer *fb,
                       const struct read_rect *r, const struct fgl_pixelstore *pack,
                       GLenum format, GLenum type, void *pixels)
{
   if (fb->Wide) {
      read_color_wide(ctx, fb, r, pack, format, type, pixels);
      return;
   }
   const size_t n = (size_t)r->width * (size_t)r->height;
   uint8_t *rgba = fgl_malloc_gl(ctx, n * 4);
   if (!rgba) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   /* rows bottom-up as GL reads them; the buffer is stored y-down */
   const uint8_t *color = fgl_read_color(ctx);
   for (GLsizei j = 0; j < r->height; j++) {
      const size_t row = (size_t)(fb->Height - 1 - (r->y + j));
      memcpy(rgba + 4 * (size_t)j * (size_t)r->width,
             color + 4 * (row * (size_t)fb->Width + (size_t)r->x), 4 * (size_t)r->width);
   }
   /* the oracle's buffer without alpha is an RGB format: alpha reads 1 */
   const GLenum base = fb->AlphaBits == 0 ? GL_RGB : GL_RGBA;
   const unsigned source =
      FGL_PACK_READPIXELS | (fb->ColorR8G8B8A8 ? 0 : FGL_PACK_NOT_R8G8B8A8);
   if (!fgl_pack_rgba8(ctx, pack, source, r->width, r->height, base, rgba, format, type,
                       pixels))
      fgl_error(ctx, GL_INVALID_OPERATION);   /* not reached: validated */
   fgl_free(rgba);
}

static void read_depth(struct fgl_context *ctx, const struct fgl_framebuffer *fb,
                       const struct read_rect *r, const struct fgl_pixelstore *pack,
                       GLenum type, void *pixels)
{
   float *z = fgl_malloc_gl(ctx, (size_t)r->width * sizeof(float));
   if (!z) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   /* [S: readpix.c:read_uint_depth_pixels] GL_UNSIGNED_INT without
    * scale/bias or byte swapping copies the replicated integer */
   const bool uint_fast = type == GL_UNSIGNED_INT && ctx->Pixel.DepthScale == 1.0f &&
                          ctx->Pixel.DepthBias == 0.0f && !pack->SwapBytes;
   for (GLsizei j = 0; j < r->height; j++) {
      const size_t row = (size_t)(fb->Height - 1 - (r->y + j));
      const size_t idx0 = row * (size_t)fb->Width + (size_t)r->x;
      uint8_t *dst = (uint8_t *)fgl_image_address(pack, pixels, r->width, GL_DEPTH_COMPONENT,
                                                  type, j, 0);
      if (uint_fast) {
         for (GLsizei i = 0; i < r->width; i++) {
            const uint32_t u = depth_uint_at(fb, idx0 + (size_t)i);
            memcpy(dst + 4 * (size_t)i, &u, 4);
         }
         continue;
      }
      /* [S: readpix.c:read_depth_pixels] float, then _mesa_pack_depth_span */
      for (GLsizei i = 0; i < r->width; i++)
         z[i] = depth_float_at(fb, idx0 + (size_t)i);
      fgl_pack_depth_span(ctx, pack, (size_t)r->width, type, z, dst);
   }
   fgl_free(z);
}

static void read_stencil(struct fgl_context *ctx, const struct fgl_framebuffer *fb,
                         const struct read_rect *r, const struct fgl_pixelstore *pack,
                         GLenum type, void *pixels)
{
   uint8_t *s = fgl_malloc_gl(ctx, (size_t)r->width);
   if (!s) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   /* [S: readpix.c:read_stencil_pixels, pack.c:_mesa_pack_stencil_span] */
   for (GLsizei j = 0; j < r->height; j++) {
      const size_t row = (size_t)(fb->Height - 1 - (r->y + j));
      const size_t idx0 = row * (size_t)fb->Width + (size_t)r->x;
      for (GLsizei i = 0; i < r->width; i++)
         s[i] = stencil_at(fb, idx0 + (size_t)i);
      void *dst = (void *)fgl_image_address(pack, pixels, r->width, GL_STENCIL_INDEX, type, j, 0);
      fgl_pack_stencil_span(ctx, pack, (size_t)r->width, type, s, dst);
   }
   fgl_free(s);
}

void GLAPIENTRY glReadPixels(GLint x, GLint y, GLsizei width, GLsizei height,
                             GLenum format, GLenum type, GLvoid *pixels)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   fgl_scene_flush(ctx);
   if (width < 0 || height < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   fgl_query_flushed(ctx);   /* the oracle maps its buffer: a flush */
   const struct fgl_framebuffer *fb = fgl_read_fb(ctx);
   if (!fb)
      return;
   /* [S: readpix.c:read_pixels] the renderbuffer the format reads
    * (_mesa_get_read_renderbuffer_for_format) must exist: the colour
    * buffer for a colour format (Mesa's NULL test does not fire under
    * glReadBuffer(GL_NONE), it reads Attachment[-1]), the depth buffer for
    * a depth format, the stencil buffer for anything else (GL_COLOR_INDEX
    * and unknown enums included) */
   if (!fgl_is_color_format(format)) {
      if (is_depth_or_ds_format(format) ? fb->DepthBits == 0 : fb->StencilBits == 0) {
         fgl_error(ctx, GL_INVALID_OPERATION);
         return;
      }
   }
   const GLenum err = fgl_error_check_format_and_type(ctx, format, type);
   if (err != GL_NO_ERROR) {
      fgl_error(ctx, err);
      return;
   }
   if (!source_buffer_exists(ctx, fb, format)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   /* the oracle maps its colour buffer: a flush (probe p_vpcut_state) */
   fgl_vpcut_invalidate(ctx);

   /* [S: image.c:_mesa_clip_readpixels] */
   struct fgl_pixelstore pack = ctx->Pack;
   struct read_rect r = {x, y, width, height};
   if (pack.RowLength == 0)
      pack.RowLength = r.width;
   /* _mesa_clip_readpixels in int arithmetic, which wraps on x86 (x or y
    * INT_MIN: the size becomes negative and nothing is read) */
   if (r.x < 0) {
      pack.SkipPixels = (GLint)((unsigned)pack.SkipPixels - (unsigned)r.x);
      r.width += r.x;
      r.x = 0;
   }
   if ((int64_t)r.x + r.width > fb->Width)
      r.width -= (GLsizei)((int64_t)r.x + r.width - fb->Width);
   if (r.width <= 0)
      return;
   if (r.y < 0) {
      pack.SkipRows = (GLint)((unsigned)pack.SkipRows - (unsigned)r.y);
      r.height += r.y;
      r.y = 0;
   }
   if ((int64_t)r.y + r.height > fb->Height)
      r.height -= (GLsizei)((int64_t)r.y + r.height - fb->Height);
   if (r.height <= 0)
      return;
   /* [S: st_cb_readpixels.c:st_ReadPixels] runs from here: it draws
    * glBitmap's cache first, NULL pixels included */
   fgl_flush_bitmap_cache(ctx);
   if (!pixels)
      return;

   switch (format) {
   case GL_DEPTH_COMPONENT:
      read_depth(ctx, fb, &r, &pack, type, pixels);
      break;
   case GL_STENCIL_INDEX:
      read_stencil(ctx, fb, &r, &pack, type, pixels);
      break;
   default:
      read_color(ctx, fb, &r, &pack, format, type, pixels);
      break;
   }
}
