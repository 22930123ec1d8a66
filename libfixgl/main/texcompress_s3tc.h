/*
 * S3TC (GL_EXT_texture_compression_s3tc) block formats, and the LATC ones
 * the oracle stores GL_COMPRESSED_LUMINANCE(_ALPHA) in: their sizes, the
 * oracle's encoders and the texels llvmpipe decodes (texcompress_s3tc.c).
 * Knows no context; used by main/texcompress.c.
 */
#ifndef FGL_TEXCOMPRESS_S3TC_H
#define FGL_TEXCOMPRESS_S3TC_H

#include <GL/gl.h>
#include <GL/glext.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Bytes of one 4x4 block of an S3TC internal format, 0 for any other
 * format; *base (when not NULL) its base format (GL_RGB for DXT1 RGB,
 * else GL_RGBA). */
unsigned fgl_s3tc_block_bytes(GLenum format, GLenum *base);

/* Bytes of one 4x4 block of the LATC formats the oracle stores
 * GL_COMPRESSED_LUMINANCE (LATC1) and GL_COMPRESSED_LUMINANCE_ALPHA
 * (LATC2) in, 0 for any other format.  Not formats an application may
 * name (GL_EXT_texture_compression_latc is not listed): only an image's
 * stored format. */
unsigned fgl_latc_block_bytes(GLenum format);

/* Decodes a LATC image as Mesa's CPU decoder does (exact sevenths and
 * fifths, truncated; not the sampler's approximation): what glGetTexImage
 * and GL_GENERATE_MIPMAP read of a LATC2 image (ORACLE-NOTES.md
 * "Compressed textures: LATC"). */
void fgl_latc_decode_exact(GLenum format, const uint8_t *blocks, int w, int h, uint8_t *rgba);

/* Decodes an image of `format` (S3TC or LATC) as Mesa's CPU decoders do
 * (exact thirds, halves, sevenths and fifths, truncated; not the
 * sampler's approximations): what glGetTexImage reads of a compressed
 * image outside its texture object's resource (main/teximage.c
 * "Storage"). Arguments as fgl_s3tc_decode_image's. */
void fgl_s3tc_decode_exact(GLenum format, const uint8_t *blocks, int w, int h, uint8_t *rgba);

/* Bytes of one block of a stored compressed format (S3TC or LATC). */
unsigned fgl_stored_block_bytes(GLenum format);

/* Decodes the w x h texels of an image of `format` (S3TC or LATC) stored as blocks (rows
 * of ceil(w / 4) blocks, ceil(h / 4) rows) into RGBA8 texels, row 0 first,
 * `rgba` w * h * 4 bytes. */
void fgl_s3tc_decode_image(GLenum format, const uint8_t *blocks, int w, int h,
                           uint8_t *rgba);

/* Compresses the w x h RGBA8 texels `rgba` (row 0 first) into blocks of
 * `format` (S3TC, or LATC from red and alpha) as the oracle's encoders do
 * (texcompress_s3tc.c "The encoder", "LATC"): block row k at blocks +
 * k * row_bytes.  For DXT5 and LATC, byte 1 of a channel block of one
 * value keeps what `blocks` held. */
void fgl_s3tc_encode_image(GLenum format, const uint8_t *rgba, int w, int h, uint8_t *blocks,
                           size_t row_bytes);

#endif
