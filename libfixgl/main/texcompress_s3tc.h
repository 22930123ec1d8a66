/*
 * S3TC (GL_EXT_texture_compression_s3tc) block formats: their sizes and
 * the texels llvmpipe's sampler decodes from them (texcompress_s3tc.c).
 * Knows no context; used by main/texcompress.c.
 */
#ifndef FGL_TEXCOMPRESS_S3TC_H
#define FGL_TEXCOMPRESS_S3TC_H

#include <GL/gl.h>
#include <GL/glext.h>
#include <stdbool.h>
#include <stdint.h>

/* Bytes of one 4x4 block of an S3TC internal format, 0 for any other
 * format; *base (when not NULL) its base format (GL_RGB for DXT1 RGB,
 * else GL_RGBA). */
unsigned fgl_s3tc_block_bytes(GLenum format, GLenum *base);

/* Decodes the w x h texels of an image of `format` stored as blocks (rows
 * of ceil(w / 4) blocks, ceil(h / 4) rows) into RGBA8 texels, row 0 first,
 * `rgba` w * h * 4 bytes. */
void fgl_s3tc_decode_image(GLenum format, const uint8_t *blocks, int w, int h,
                           uint8_t *rgba);

#endif
