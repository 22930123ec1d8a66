/*
 * Client images: addressing with the pixel store state and conversion
 * between client formats/types and fixgl's internal storage (Mesa's
 * main/image.c, pack.c, texstore.c, format_utils.c).  Shared by the
 * texture image calls, glDrawPixels, glReadPixels and glGetTexImage.
 */
#ifndef FGL_PIXELFORMAT_H
#define FGL_PIXELFORMAT_H

#include <stddef.h>
#include <stdint.h>

#include "context.h"

/* Components per pixel of a colour format (GL_RGBA 4, GL_RGB 3,
 * GL_LUMINANCE_ALPHA 2, GL_LUMINANCE/ALPHA/RED/... 1), 0 if unknown. */
int fgl_format_components(GLenum format);

/* Bytes per pixel of format/type, 0 if unknown (GL_BITMAP: 0). */
size_t fgl_pixel_bytes(GLenum format, GLenum type);

/* [S: image.c:_mesa_image_address2d, _mesa_image_row_stride] the address
 * of pixel (col, row) of a width-wide image at `pixels` under the store
 * state p. */
const uint8_t *fgl_image_address(const struct fgl_pixelstore *p, const void *pixels,
                                 int width, GLenum format, GLenum type, int row, int col);
size_t fgl_image_row_stride(const struct fgl_pixelstore *p, int width, GLenum format,
                            GLenum type);

/* Unpacks width x height pixels of the colour image at `pixels`
 * (format/type, the unpack state p) into RGBA8 texels of base format
 * `base` as struct fgl_texture_image stores them, with the conversions
 * Mesa's texstore uses for the oracle's 8-bit texture formats and the
 * pixel transfer operations the context has on.  Returns false, storing
 * nothing, for a format/type combination it does not convert (the caller
 * has validated the combination against GL's rules). */
bool fgl_unpack_texels_rgba8(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                             int width, int height, GLenum format, GLenum type,
                             const void *pixels, GLenum base, uint8_t *dst);

#endif
