/*
 * Compressed texture images (GL 1.3, GL_ARB_texture_compression,
 * GL_EXT_texture_compression_s3tc) [S: Mesa 22.3 main/teximage.c:
 * teximage (compressed), compressed_texture_error_check,
 * compressed_tex_sub_image, compressed_subtexture_target_check,
 * compressed_subtexture_error_check, error_check_subtexture_dimensions;
 * texgetimage.c: _mesa_GetCompressedTexImage,
 * getcompressedteximage_error_check; dlist.c: save_CompressedTex*]:
 * glCompressedTexImage1D/2D/3D, glCompressedTexSubImage1D/2D/3D,
 * glGetCompressedTexImage and their ARB names.
 *
 * fixgl's compressed formats are the four S3TC ones.  An image keeps the
 * blocks as given (fgl_texture_image.Blocks: glGetCompressedTexImage
 * returns them) and, in Data, the RGBA8 texels the oracle's sampler
 * decodes from them (main/texcompress_s3tc.c), so the raster core samples
 * it as any 8-bit image.  S3TC images are 2D (GL_TEXTURE_2D and the
 * cube-map faces) only (the oracle refuses them on GL_TEXTURE_3D with
 * GL_INVALID_OPERATION and has no 1D compressed textures).  Uncompressed
 * data given to an S3TC image goes through the oracle's encoder
 * (main/teximage.c "S3TC images").  ORACLE-NOTES.md "Compressed
 * textures" and "Compressed textures: the encoder".
 */
#define GL_GLEXT_PROTOTYPES 1
#include <stdlib.h>
#include <string.h>

#include "main/dlist.h"
#include "main/groups.h"
#include "main/texcompress_s3tc.h"
#include "fgl_alloc.h"

/* [S: formats.c:_mesa_format_image_size] the bytes of a w x h x d image
 * of an S3TC (or stored LATC) format, in the oracle's unsigned arithmetic (a negative size
 * wraps as it does there) */
GLint fgl_compressed_image_size(GLenum format, GLsizei w, GLsizei h, GLsizei d)
{
   const unsigned bytes = fgl_stored_block_bytes(format);
   const unsigned wb = ((unsigned)w + 3u) / 4u, hb = ((unsigned)h + 3u) / 4u;
   return (GLint)(wb * hb * (unsigned)d * bytes);
}

/* [S: glformats.c:_mesa_generic_compressed_format_to_uncompressed_format] */
static bool is_generic_compressed(GLenum f)
{
   switch (f) {
   case GL_COMPRESSED_RED: case GL_COMPRESSED_RG: case GL_COMPRESSED_RGB:
   case GL_COMPRESSED_RGBA: case GL_COMPRESSED_ALPHA: case GL_COMPRESSED_LUMINANCE:
   case GL_COMPRESSED_LUMINANCE_ALPHA: case GL_COMPRESSED_INTENSITY:
   case GL_COMPRESSED_SRGB: case GL_COMPRESSED_SRGB_ALPHA:
   case GL_COMPRESSED_SLUMINANCE: case GL_COMPRESSED_SLUMINANCE_ALPHA:
      return true;
   default:
      return false;
   }
}

/* Decodes the whole of img's blocks into its texels. */
static void decode_image(struct fgl_texture_image *img)
{
   if (img->Width > 0 && img->Height > 0)
      fgl_s3tc_decode_image(img->CompressedFormat, img->Blocks, img->Width, img->Height,
                            img->Data);
}

/* ------------------------------------------------------------------ */
/* glCompressedTexImage                                               */
/* ------------------------------------------------------------------ */

/* [S: teximage.c:compressed_texture_error_check] true after an error */
static bool compressed_image_error(struct fgl_context *ctx, GLenum target,
                                   GLint level, GLenum internal, GLsizei w, GLsizei h,
                                   GLsizei d, GLint border, GLsizei image_size)
{
   /* _mesa_target_can_be_compressed: 2D targets and cube maps only
    * (measured: a 1D or 3D target raises GL_INVALID_ENUM) */
   if (!fgl_tex_is_2d_image_target(target, true)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return true;
   }
   if (!fgl_s3tc_block_bytes(internal, NULL)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return true;
   }
   /* measured: a bad level before the border (the API fuzzer's seed 54) */
   if (level < 0 || level >= fgl_tex_max_levels(target)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return true;
   }
   if (border != 0) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return true;
   }
   if (fgl_compressed_image_size(internal, w, h, d) != image_size) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return true;
   }
   return false;
}

/* [S: teximage.c:teximage with compressed] */
static void compressed_tex_image(GLuint dims, GLenum target, GLint level, GLenum internal,
                                 GLsizei width, GLsizei height, GLsizei depth, GLint border,
                                 GLsizei image_size, const void *data)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag &&
       !fgl_save_compressed_tex(ctx, dims, false, target, level, internal, 0, 0, 0, width,
                                height, depth, border, image_size, data))
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_flush_vertices(ctx);
   fgl_scene_flush(ctx);   /* the scene may sample the images */
   /* legal_teximage_target (fixgl's targets, as glTexImage) */
   if (dims == 1   ? target != GL_TEXTURE_1D && target != GL_PROXY_TEXTURE_1D
       : dims == 2 ? !fgl_tex_is_2d_image_target(target, true)
                   : target != GL_TEXTURE_3D && target != GL_PROXY_TEXTURE_3D) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (compressed_image_error(ctx, target, level, internal, width, height, depth, border,
                              image_size))
      return;
   /* sizes beyond the limits: a proxy is cleared, without an error
    * (measured: a 32768-wide proxy with its right imageSize) */
   const bool dims_ok = fgl_tex_legal_dimensions(target, dims, level, width, height, depth, border);
   GLenum base;
   fgl_s3tc_block_bytes(internal, &base);
   struct fgl_texture_object *t = fgl_tex_target_object(ctx, target);
   struct fgl_texture_image *img =
      fgl_tex_new_compressed_image(width, height, depth, internal, base);
   if (!img) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   if (target == GL_PROXY_TEXTURE_2D || target == GL_PROXY_TEXTURE_CUBE_MAP) {
      if (!dims_ok) {
         fgl_free(img);
         img = NULL;
      }
      fgl_tex_set_image(t, target, level, img);
      return;
   }
   if (!dims_ok) {
      fgl_free(img);
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   const size_t n = (size_t)width * (size_t)height;
   img->BlocksSize = (size_t)image_size;
   img->Blocks = fgl_calloc(image_size ? (size_t)image_size : 1, 1);
   img->Data = fgl_rc_alloc(n ? n * 4 : 4, 0);   /* teximage.c free_image */
   if (!img->Blocks || !img->Data) {
      fgl_free(img->Blocks);
      fgl_rc_release(img->Data);
      fgl_free(img);
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   /* st_CompressedTexImage: nothing to store for an empty image or no
    * data (the storage reads as zero blocks) */
   if (width > 0 && height > 0 && depth > 0) {
      fgl_flush_bitmap_cache(ctx);
      if (data)
         memcpy(img->Blocks, data, (size_t)image_size);
      decode_image(img);
   }
   fgl_tex_set_image(t, target, level, img);
   if (data && width > 0 && height > 0 && depth > 0)
      fgl_tex_written(ctx, t, img);
   fgl_tex_object_changed(ctx);
   /* [S: teximage.c:teximage] then GL_GENERATE_MIPMAP */
   fgl_tex_image_changed(ctx, t, target, level);
}

void GLAPIENTRY glCompressedTexImage1D(GLenum target, GLint level, GLenum internalformat,
                                       GLsizei width, GLint border, GLsizei imageSize,
                                       const void *data)
{
   compressed_tex_image(1, target, level, internalformat, width, 1, 1, border, imageSize,
                        data);
}

void GLAPIENTRY glCompressedTexImage2D(GLenum target, GLint level, GLenum internalformat,
                                       GLsizei width, GLsizei height, GLint border,
                                       GLsizei imageSize, const void *data)
{
   compressed_tex_image(2, target, level, internalformat, width, height, 1, border,
                        imageSize, data);
}

void GLAPIENTRY glCompressedTexImage3D(GLenum target, GLint level, GLenum internalformat,
                                       GLsizei width, GLsizei height, GLsizei depth,
                                       GLint border, GLsizei imageSize, const void *data)
{
   compressed_tex_image(3, target, level, internalformat, width, height, depth, border,
                        imageSize, data);
}

void GLAPIENTRY glCompressedTexImage1DARB(GLenum target, GLint level, GLenum internalformat,
                                          GLsizei width, GLint border, GLsizei imageSize,
                                          const void *data)
{
   compressed_tex_image(1, target, level, internalformat, width, 1, 1, border, imageSize,
                        data);
}

void GLAPIENTRY glCompressedTexImage2DARB(GLenum target, GLint level, GLenum internalformat,
                                          GLsizei width, GLsizei height, GLint border,
                                          GLsizei imageSize, const void *data)
{
   compressed_tex_image(2, target, level, internalformat, width, height, 1, border,
                        imageSize, data);
}

void GLAPIENTRY glCompressedTexImage3DARB(GLenum target, GLint level, GLenum internalformat,
                                          GLsizei width, GLsizei height, GLsizei depth,
                                          GLint border, GLsizei imageSize, const void *data)
{
   compressed_tex_image(3, target, level, internalformat, width, height, depth, border,
                        imageSize, data);
}

/* ------------------------------------------------------------------ */
/* glCompressedTexSubImage                                            */
/* ------------------------------------------------------------------ */

/* [S: teximage.c:compressed_subtexture_target_check,
 * compressed_subtexture_error_check, error_check_subtexture_dimensions]
 * true after an error */
static bool compressed_sub_error(struct fgl_context *ctx, GLuint dims, GLenum target,
                                 GLint level, GLint x, GLint y, GLint z, GLsizei w,
                                 GLsizei h, GLsizei d, GLenum format, GLsizei image_size,
                                 struct fgl_texture_image **out)
{
   /* no 1D compressed textures; 2D on GL_TEXTURE_2D and the cube faces;
    * none of fixgl's formats on GL_TEXTURE_3D */
   if (dims == 3 && target == GL_TEXTURE_3D) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return true;
   }
   if (dims != 2 || !fgl_tex_is_2d_image_target(target, false)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return true;
   }
   /* measured: a generic compressed format raises GL_INVALID_ENUM, any
    * other that is not a compressed format GL_INVALID_OPERATION, both
    * before the level and imageSize checks */
   if (is_generic_compressed(format)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return true;
   }
   if (!fgl_s3tc_block_bytes(format, NULL)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return true;
   }
   if (level < 0 || level >= fgl_tex_max_levels(target)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return true;
   }
   if (fgl_compressed_image_size(format, w, h, d) != image_size) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return true;
   }
   struct fgl_texture_image *img =
      *fgl_tex_image_slot(fgl_tex_target_object(ctx, target), target, level);
   if (!img || img->InternalFormat != format) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return true;
   }
   if (w < 0 || h < 0 || d < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return true;
   }
   if (x < 0 || (int64_t)x + w > img->Width || y < 0 || (int64_t)y + h > img->Height ||
       z < 0 || (int64_t)z + d > img->Depth) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return true;
   }
   /* whole blocks only, but for a region that ends at the image's edge */
   if (x % 4 != 0 || y % 4 != 0 || (w % 4 != 0 && x + w != img->Width) ||
       (h % 4 != 0 && y + h != img->Height)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return true;
   }
   *out = img;
   return false;
}

static void compressed_tex_sub_image(GLuint dims, GLenum target, GLint level, GLint x,
                                     GLint y, GLint z, GLsizei width, GLsizei height,
                                     GLsizei depth, GLenum format, GLsizei image_size,
                                     const void *data)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag &&
       !fgl_save_compressed_tex(ctx, dims, true, target, level, format, x, y, z, width,
                                height, depth, 0, image_size, data))
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   struct fgl_texture_image *img;
   if (compressed_sub_error(ctx, dims, target, level, x, y, z, width, height, depth, format,
                            image_size, &img))
      return;
   fgl_flush_vertices(ctx);
   fgl_scene_flush(ctx);   /* the scene may sample the image */
   if (width == 0 || height == 0 || depth == 0 || !data)
      return;
   fgl_flush_bitmap_cache(ctx);
   /* the region's rows of blocks into the image's */
   const unsigned bytes = fgl_s3tc_block_bytes(format, NULL);
   const size_t row = (size_t)((width + 3) / 4) * bytes;
   const size_t img_row = (size_t)((img->Width + 3) / 4) * bytes;
   const int rows = (height + 3) / 4;
   for (int j = 0; j < rows; j++)
      memcpy(img->Blocks + (size_t)(y / 4 + j) * img_row + (size_t)(x / 4) * bytes,
             (const uint8_t *)data + (size_t)j * row, row);
   decode_image(img);
   fgl_tex_written(ctx, fgl_tex_target_object(ctx, target), img);
   fgl_tex_object_changed(ctx);
   /* [S: teximage.c:compressed_tex_sub_image] then GL_GENERATE_MIPMAP */
   fgl_tex_image_changed(ctx, fgl_tex_target_object(ctx, target), target, level);
}

void GLAPIENTRY glCompressedTexSubImage1D(GLenum target, GLint level, GLint xoffset,
                                          GLsizei width, GLenum format, GLsizei imageSize,
                                          const void *data)
{
   compressed_tex_sub_image(1, target, level, xoffset, 0, 0, width, 1, 1, format, imageSize,
                            data);
}

void GLAPIENTRY glCompressedTexSubImage2D(GLenum target, GLint level, GLint xoffset,
                                          GLint yoffset, GLsizei width, GLsizei height,
                                          GLenum format, GLsizei imageSize, const void *data)
{
   compressed_tex_sub_image(2, target, level, xoffset, yoffset, 0, width, height, 1, format,
                            imageSize, data);
}

void GLAPIENTRY glCompressedTexSubImage3D(GLenum target, GLint level, GLint xoffset,
                                          GLint yoffset, GLint zoffset, GLsizei width,
                                          GLsizei height, GLsizei depth, GLenum format,
                                          GLsizei imageSize, const void *data)
{
   compressed_tex_sub_image(3, target, level, xoffset, yoffset, zoffset, width, height,
                            depth, format, imageSize, data);
}

void GLAPIENTRY glCompressedTexSubImage1DARB(GLenum target, GLint level, GLint xoffset,
                                             GLsizei width, GLenum format, GLsizei imageSize,
                                             const void *data)
{
   compressed_tex_sub_image(1, target, level, xoffset, 0, 0, width, 1, 1, format, imageSize,
                            data);
}

void GLAPIENTRY glCompressedTexSubImage2DARB(GLenum target, GLint level, GLint xoffset,
                                             GLint yoffset, GLsizei width, GLsizei height,
                                             GLenum format, GLsizei imageSize,
                                             const void *data)
{
   compressed_tex_sub_image(2, target, level, xoffset, yoffset, 0, width, height, 1, format,
                            imageSize, data);
}

void GLAPIENTRY glCompressedTexSubImage3DARB(GLenum target, GLint level, GLint xoffset,
                                             GLint yoffset, GLint zoffset, GLsizei width,
                                             GLsizei height, GLsizei depth, GLenum format,
                                             GLsizei imageSize, const void *data)
{
   compressed_tex_sub_image(3, target, level, xoffset, yoffset, zoffset, width, height,
                            depth, format, imageSize, data);
}

/* ------------------------------------------------------------------ */
/* glGetCompressedTexImage                                            */
/* ------------------------------------------------------------------ */

/* [S: texgetimage.c:_mesa_GetCompressedTexImage, legal_getteximage_target,
 * getcompressedteximage_error_check, dimensions_error_check] */
static void get_compressed_tex_image(GLenum target, GLint level, void *img_out)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   fgl_flush_vertices(ctx);
   switch (target) {
   case GL_TEXTURE_1D: case GL_TEXTURE_2D: case GL_TEXTURE_3D:
   case GL_TEXTURE_CUBE_MAP_POSITIVE_X: case GL_TEXTURE_CUBE_MAP_NEGATIVE_X:
   case GL_TEXTURE_CUBE_MAP_POSITIVE_Y: case GL_TEXTURE_CUBE_MAP_NEGATIVE_Y:
   case GL_TEXTURE_CUBE_MAP_POSITIVE_Z: case GL_TEXTURE_CUBE_MAP_NEGATIVE_Z:
      break;
   case GL_TEXTURE_RECTANGLE: case GL_TEXTURE_1D_ARRAY:
      /* targets the oracle takes whose images fixgl does not have: a
       * missing image of a 1D or 2D target is GL_INVALID_VALUE */
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   case GL_TEXTURE_2D_ARRAY: case GL_TEXTURE_CUBE_MAP_ARRAY:
      /* of a layered target, none */
      if (level < 0 || level >= fgl_tex_max_levels(target))
         fgl_error(ctx, GL_INVALID_VALUE);
      return;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (level < 0 || level >= fgl_tex_max_levels(target)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   const struct fgl_texture_image *img =
      *fgl_tex_image_slot(fgl_tex_target_object(ctx, target), target, level);
   /* measured: a missing image of a 1D or 2D texture is GL_INVALID_VALUE,
    * of a 3D one or a cube face no error; an empty image nothing to do */
   if (!img) {
      if (target == GL_TEXTURE_1D || target == GL_TEXTURE_2D)
         fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (img->Width == 0 || img->Height == 0 || img->Depth == 0)
      return;
   if (!img->Blocks) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (img_out)
      memcpy(img_out, img->Blocks, img->BlocksSize);
}

void GLAPIENTRY glGetCompressedTexImage(GLenum target, GLint level, void *img)
{
   get_compressed_tex_image(target, level, img);
}

void GLAPIENTRY glGetCompressedTexImageARB(GLenum target, GLint level, void *img)
{
   get_compressed_tex_image(target, level, img);
}
