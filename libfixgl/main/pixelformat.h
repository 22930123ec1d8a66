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

/* Bytes per pixel of format/type, 0 if unknown (GL_BITMAP: 0; the packed
 * types: their size). */
size_t fgl_pixel_bytes(GLenum format, GLenum type);

/* [S: image.c:_mesa_image_address2d, _mesa_image_row_stride] the address
 * of pixel (col, row) of a width-wide image at `pixels` under the store
 * state p (GL_BITMAP: the byte holding the pixel, its bit being
 * (SkipPixels + col) & 7 counted as LSB_FIRST says). */
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

/* The same into the values of a texture format of other than 8 bits per
 * channel as the oracle stores them (struct fgl_texture_image Store):
 * bits[c] per texel channel (0: a constant of the format), `array16`: the
 * oracle's format is a 16-bit array format (else a packed one).  dst gets
 * width * height texels of four uint16_t.  False as above. */
bool fgl_unpack_texels_stored(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                              int width, int height, GLenum format, GLenum type,
                              const void *pixels, GLenum base, const uint8_t bits[4],
                              bool array16, uint16_t *dst);

/* ------------------------------------------------------------------ */
/* Format/type validation                                              */
/* ------------------------------------------------------------------ */

/* [S: glformats.c:_mesa_error_check_format_and_type] GL_NO_ERROR, or the
 * error (GL_INVALID_ENUM / GL_INVALID_OPERATION) the oracle raises for a
 * client format/type pair in glReadPixels, glDrawPixels and
 * glTex[Sub]Image (desktop GL, the oracle's extensions). */
GLenum fgl_error_check_format_and_type(const struct fgl_context *ctx, GLenum format,
                                       GLenum type);

/* [S: glformats.c:_mesa_is_color_format].  The check above passes GL
 * 1.5's client formats only (no GL_RG, no integer formats: they raise
 * GL_INVALID_ENUM), so no later integer-format check is needed. */
bool fgl_is_color_format(GLenum format);


/* ------------------------------------------------------------------ */
/* Pixel transfer                                                      */
/* ------------------------------------------------------------------ */

/* Mesa's IMAGE_*_BIT transfer operation bits */
#define FGL_IMAGE_SCALE_BIAS_BIT    0x1
#define FGL_IMAGE_SHIFT_OFFSET_BIT  0x2
#define FGL_IMAGE_MAP_COLOR_BIT     0x4
#define FGL_IMAGE_CLAMP_BIT         0x800
/* fixgl's own unpack flag (no transfer operation): GL_INT channels
 * quantized to 16-bit snorm first, as glDrawPixels' image texture
 * stores them (fgl_unpack_rgba_float) */
#define FGL_UNPACK_INT_SNORM16      0x10000
/* likewise GL_UNSIGNED_INT channels quantized to 16-bit unorm, rounded */
#define FGL_UNPACK_UINT_UNORM16     0x20000

/* [S: pixel.c:_mesa_update_pixel] ctx->_ImageTransferState */
unsigned fgl_image_transfer_state(const struct fgl_context *ctx);

/* [S: pixeltransfer.c:_mesa_apply_rgba_transfer_ops] scale/bias, then
 * the colour maps, then the clamp, as `ops` selects */
void fgl_apply_rgba_transfer_ops(const struct fgl_context *ctx, unsigned ops, size_t n,
                                 float (*rgba)[4]);

/* [S: pixeltransfer.c:_mesa_apply_stencil_transfer_ops] shift/offset
 * and GL_MAP_STENCIL on 8-bit stencil values */
void fgl_apply_stencil_transfer_ops(const struct fgl_context *ctx, size_t n, uint8_t *s);

/* [S: pixeltransfer.c:_mesa_shift_and_offset_ci, _mesa_map_ci_to_rgba] */
void fgl_shift_and_offset_ci(const struct fgl_context *ctx, size_t n, GLuint *index);
void fgl_map_ci_to_rgba(const struct fgl_context *ctx, size_t n, const GLuint *index,
                        float (*rgba)[4]);

/* ------------------------------------------------------------------ */
/* Unpacking (client memory -> values)                                 */
/* ------------------------------------------------------------------ */

/* width x height colour pixels (any colour format of the check above
 * but the integer ones, or GL_COLOR_INDEX) to float RGBA, row-major,
 * rows in the order given: [S: format_utils.c:_mesa_format_convert] to
 * RGBA32_FLOAT with SWAP_BYTES handled first (texstore.c:texstore_rgba),
 * then fgl_apply_rgba_transfer_ops(ops).  GL_COLOR_INDEX: the indices
 * (shifted and offset when ops has FGL_IMAGE_SHIFT_OFFSET_BIT) through
 * the I_TO_R/G/B/A maps, then only the clamp of ops
 * ([S: pack.c:_mesa_unpack_color_index_to_rgba_float]; note that Mesa
 * reads the width*height indices as one contiguous span, ignoring the row
 * padding).  Returns false for a format/type it does not convert.
 * Note for callers emulating a texstore (glDrawPixels' image texture):
 * texstore_rgba then addresses a colour-index image a second time with
 * the unpack state, ignores the skips on its float (transfer) path and
 * applies the skips to its byte-swapped temporary; fgl_unpack_texels_rgba8
 * reproduces these, see ORACLE-NOTES.md "Client pixel formats". */
bool fgl_unpack_rgba_float(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                           int width, int height, GLenum format, GLenum type,
                           const void *pixels, unsigned ops, float *rgba);

/* n indices of one row at `src` (already addressed, e.g. by
 * fgl_image_address) of type `type` (GL_BITMAP: bits from SkipPixels & 7
 * on, honouring LSB_FIRST) [S: pack.c:extract_uint_indexes] */
void fgl_extract_uint_indexes(const struct fgl_pixelstore *p, size_t n, GLenum type,
                              const void *src, GLuint *index);

/* n stencil indices of one row [S: pack.c:_mesa_unpack_stencil_span]
 * with shift/offset (when `ops` has FGL_IMAGE_SHIFT_OFFSET_BIT) and
 * GL_MAP_STENCIL (when on), as GLuint. */
void fgl_unpack_stencil_span(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                             size_t n, GLenum type, const void *src, unsigned ops,
                             GLuint *dst);

/* n depth values of one row as floats [S: pack.c:_mesa_unpack_depth_span]
 * (GL_DEPTH_SCALE/BIAS applied, clamped as Mesa clamps). */
void fgl_unpack_depth_span_float(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                                 size_t n, GLenum type, const void *src, float *dst);

/* ------------------------------------------------------------------ */
/* Packing (values -> client memory)                                   */
/* ------------------------------------------------------------------ */

/* Where the RGBA8 values to pack come from: their base format decides
 * Mesa's rebase and its luminance rule. */
enum fgl_pack_source {
   FGL_PACK_READPIXELS,   /* colour buffer: L = R+G+B clamped (readpix.c) */
   FGL_PACK_TEXIMAGE,     /* texture image: L = R (texgetimage.c) */
};
/* Or'ed into the source when the oracle stores the values in an 8-bit
 * layout other than R8G8B8A8_UNORM (B8G8R8A8, A8R8G8B8, R8G8B8, L8...):
 * _mesa_format_convert then packs fields wider than 8 bits through float
 * rather than pack_rgba_8unorm, which rounds differently
 * (GL_UNSIGNED_INT_10_10_10_2 and _REV). */
#define FGL_PACK_NOT_R8G8B8A8 0x100
/* Or'ed into FGL_PACK_TEXIMAGE when the texels come from Mesa's CPU
 * decoders (texcompress.c:_mesa_decompress_image): they reach the
 * destination through float, each channel UBYTE_TO_FLOAT's x / 255.0f
 * (not x * (1.0f / 255)), then as the float path packs. */
#define FGL_PACK_CPU_DECODED 0x200

/* Packs width x height RGBA8 values (row-major; rows in the order they
 * go to memory) of base format `base` (GL_RGBA, GL_RGB for a buffer or
 * texture without alpha, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_INTENSITY,
 * GL_ALPHA) into `pixels` as format/type under the pack state p, with the
 * pixel transfer operations the context has on, SWAP_BYTES last
 * [S: readpix.c:read_rgba_pixels, texgetimage.c:get_tex_rgba_uncompressed].
 * Returns false for a format/type it does not convert. */
bool fgl_pack_rgba8(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                    unsigned source, int width, int height, GLenum base,
                    const uint8_t *rgba8, GLenum format, GLenum type, void *pixels);

/* glGetTexImage of an image that keeps its stored values (struct
 * fgl_texture_image Store/StoreBits, base format `base`): packs the
 * width x height texels from their own precision as the oracle converts
 * its texture format [S: texgetimage.c:get_tex_rgba_uncompressed];
 * `array16`: the oracle's format is a 16-bit array format (RGBA16, RGBX16,
 * L16, A16, L16A16, I16), else a packed one.  Returns false for a
 * format/type it does not convert. */
bool fgl_pack_tex_stored(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                         int width, int height, GLenum base, const uint16_t *store,
                         const uint8_t bits[4], bool array16, GLenum format, GLenum type,
                         void *pixels);

/* glReadPixels of a colour format from a wide OSMesa buffer: packs the
 * width x height RGBA values of its R16G16B16A16_UNORM (u16) or
 * R32G32B32A32_FLOAT (f32; the other NULL) render target, rows in memory
 * order, as the oracle converts them [S: readpix.c:read_rgba_pixels],
 * with the pixel transfer operations, SWAP_BYTES last.  Returns false for
 * a format/type it does not convert. */
bool fgl_pack_wide(struct fgl_context *ctx, const struct fgl_pixelstore *p, int width,
                   int height, const uint16_t *u16, const float *f32, GLenum format,
                   GLenum type, void *pixels);

/* One row of n depth values [S: pack.c:_mesa_pack_depth_span] (depth
 * scale/bias applied, SWAP_BYTES) at `dst` (already addressed). */
void fgl_pack_depth_span(struct fgl_context *ctx, const struct fgl_pixelstore *p, size_t n,
                         GLenum type, const float *depth, void *dst);

/* One row of n stencil values [S: pack.c:_mesa_pack_stencil_span]
 * (shift/offset and MAP_STENCIL applied, SWAP_BYTES, GL_BITMAP bits) at
 * `dst` (already addressed). */
void fgl_pack_stencil_span(struct fgl_context *ctx, const struct fgl_pixelstore *p, size_t n,
                           GLenum type, const uint8_t *stencil, void *dst);

#endif
