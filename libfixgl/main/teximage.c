/*
 * Texture images (Mesa 22.3 main/teximage.c, texstore.c): glTexImage1D and
 * glTexImage2D.  Images are stored as RGBA8 texels expanded from their
 * base format (struct fgl_texture_image).
 */
#include <stdlib.h>
#include <string.h>

#include "main/groups.h"
#include "main/pixelformat.h"

void fgl_free_tex_images(struct fgl_texture_object *t)
{
   for (int l = 0; l < FGL_MAX_TEXTURE_LEVELS; l++) {
      if (t->Image[l]) {
         free(t->Image[l]->Data);
         free(t->Image[l]);
         t->Image[l] = NULL;
      }
   }
}

/* [S: glformats.c:_mesa_base_tex_format] the base format of the internal
 * formats fixgl stores, 0 for others */
static GLenum base_format(GLint internal)
{
   switch (internal) {
   case 1: case GL_LUMINANCE: case GL_LUMINANCE8:
      return GL_LUMINANCE;
   case 2: case GL_LUMINANCE_ALPHA: case GL_LUMINANCE8_ALPHA8:
      return GL_LUMINANCE_ALPHA;
   case 3: case GL_RGB: case GL_RGB8:
      return GL_RGB;
   case 4: case GL_RGBA: case GL_RGBA8:
      return GL_RGBA;
   case GL_ALPHA: case GL_ALPHA8:
      return GL_ALPHA;
   case GL_INTENSITY: case GL_INTENSITY8:
      return GL_INTENSITY;
   default:
      return 0;
   }
}

/* Replaces level `level` of t with a width x height image from `pixels`
 * (NULL: texels undefined, zero here). */
static void store_image(struct fgl_context *ctx, struct fgl_texture_object *t, GLint level,
                        GLint internal, GLenum base, int width, int height,
                        GLenum format, GLenum type, const void *pixels)
{
   const size_t n = (size_t)width * (size_t)height;
   uint8_t *data = calloc(n ? n : 1, 4);
   struct fgl_texture_image *img = calloc(1, sizeof(*img));
   if (!data || !img) {
      free(data);
      free(img);
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   if (pixels && n &&
       !fgl_unpack_texels_rgba8(ctx, &ctx->Unpack, width, height, format, type, pixels,
                                base, data)) {
      free(data);
      free(img);
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   img->Width = width;
   img->Height = height;
   img->Border = 0;
   img->InternalFormat = (GLenum)internal;
   img->BaseFormat = base;
   img->Data = data;
   if (t->Image[level]) {
      free(t->Image[level]->Data);
      free(t->Image[level]);
   }
   t->Image[level] = img;
   ctx->NewState |= FGL_NEW_TEXTURE;
}

static void tex_image(GLuint dims, GLenum target, GLint level, GLint internal,
                      GLsizei width, GLsizei height, GLint border, GLenum format,
                      GLenum type, const void *pixels)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (fgl_inside_begin_end(ctx)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   fgl_flush_vertices(ctx);
   if (target != (dims == 1 ? GL_TEXTURE_1D : GL_TEXTURE_2D)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   const GLenum base = base_format(internal);
   if (level < 0 || level >= FGL_MAX_TEXTURE_LEVELS || width < 0 || height < 0 ||
       width > FGL_MAX_TEXTURE_SIZE || height > FGL_MAX_TEXTURE_SIZE || border != 0 ||
       !base) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   struct fgl_texture_object *t =
      fgl_bound_texture(ctx, ctx->Texture.CurrentUnit, target);
   store_image(ctx, t, level, internal, base, width, height, format, type, pixels);
}

void GLAPIENTRY glTexImage1D(GLenum target, GLint level, GLint internalFormat,
                             GLsizei width, GLint border, GLenum format, GLenum type,
                             const GLvoid *pixels)
{
   tex_image(1, target, level, internalFormat, width, 1, border, format, type, pixels);
}

void GLAPIENTRY glTexImage2D(GLenum target, GLint level, GLint internalFormat,
                             GLsizei width, GLsizei height, GLint border, GLenum format,
                             GLenum type, const GLvoid *pixels)
{
   tex_image(2, target, level, internalFormat, width, height, border, format, type, pixels);
}
