/*
 * glBitmap, glDrawPixels and glCopyPixels [S: main/drawpix.c,
 * state_tracker/st_cb_bitmap.c, st_cb_drawpixels.c].
 *
 * The oracle draws each as a texture plus a screen-aligned quad whose
 * fragment shader samples it (the quad: tnl/t_pixels.c; its fragments:
 * raster/r_pixels.c).  This file validates, builds the texture exactly
 * as the state tracker fills it, and places the quad:
 *  - glBitmap: the bitmap is expanded into the state tracker's 512x32
 *    bitmap cache (0 where a bit is set, 0xff elsewhere), which is drawn
 *    later, as one quad, with the raster colour and depth of its first
 *    bitmap and the state validated last: when a bitmap does not fit or
 *    its colour or depth differs, and before every draw, clear, pixel
 *    read or copy, scissor change and flush (st_flush_bitmap_cache's
 *    callers).  State changes alone do not draw it.
 *  - glDrawPixels: colour images replace the fixed-function program's
 *    primary colour (scale/bias and colour maps in the shader), depth and
 *    stencil images write the fragment depth or the stencil value.
 *  - glCopyPixels: a blit when nothing per-fragment applies (no zoom, no
 *    overlap), otherwise the source copied into a texture and drawn.
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "main/dlist.h"
#include "main/pixelformat.h"
#include "main/groups.h"
#include "fgl_alloc.h"
#include "tnl/t_pipeline.h"

#define BITMAP_CACHE_WIDTH  512
#define BITMAP_CACHE_HEIGHT 32

/* ---- helpers ---- */

/* util_ifloor (u_math.h, not x86-32): floor through the bits of two
 * floats, exact for |f| < 2^22; beyond, and for NaN, the same
 * deterministic values as the oracle's (NaN gives 0) */
static int ifloor(float f)
{
   const float af = (float)((3 << 22) + 0.5 + (double)f);
   const float bf = (float)((3 << 22) + 0.5 - (double)f);
   uint32_t ai, bi;
   memcpy(&ai, &af, sizeof(ai));
   memcpy(&bi, &bf, sizeof(bi));
   return (int32_t)(ai - bi) >> 1;
}

/* a + b and a - b with the int wrap-around of the oracle's arithmetic */
static int add_wrap(int a, int b)
{
   return (int)((unsigned)a + (unsigned)b);
}

static int sub_wrap(int a, int b)
{
   return (int)((unsigned)a - (unsigned)b);
}

/* The window-buffer orientation: the oracle renders y-down; the quads
 * are placed in GL's y-up window coordinates and the viewport flips
 * them (t_pixels.c). */
static void quad_init(struct t_pixel_quad *q, const struct fgl_framebuffer *fb, float z,
                      const float color[4])
{
   memset(q, 0, sizeof(*q));
   q->fb_width = fb->Width;
   q->fb_height = fb->Height;
   q->z = z;
   memcpy(q->color, color, sizeof(q->color));
}

/* [S: feedback.c:_mesa_feedback_vertex] for the raster position */
static void feedback_raster(struct fgl_context *ctx, GLenum token)
{
   const struct fgl_current_attrib *cur = &ctx->Current;
   const unsigned mask = ctx->Feedback.Mask;
   fgl_feedback_token(ctx, (GLfloat)(GLint)token);
   fgl_feedback_token(ctx, cur->RasterPos[0]);
   fgl_feedback_token(ctx, cur->RasterPos[1]);
   if (mask & FGL_FB_3D)
      fgl_feedback_token(ctx, cur->RasterPos[2]);
   if (mask & FGL_FB_4D)
      fgl_feedback_token(ctx, cur->RasterPos[3]);
   if (mask & FGL_FB_COLOR)
      for (int c = 0; c < 4; c++)
         fgl_feedback_token(ctx, cur->RasterColor[c]);
   if (mask & FGL_FB_TEXTURE)
      for (int c = 0; c < 4; c++)
         fgl_feedback_token(ctx, cur->RasterTexCoords[0][c]);
}

/* ---- glBitmap ---- */

/* _mesa_image_offset for GL_BITMAP data */
static const uint8_t *bitmap_row(const struct fgl_pixelstore *p, const uint8_t *bitmap,
                                 int width, int row)
{
   const size_t ppr = (size_t)(p->RowLength > 0 ? p->RowLength : width);
   const size_t align = (size_t)p->Alignment;
   const size_t bytes_per_row = align * ((ppr + 8 * align - 1) / (8 * align));
   return bitmap + ((size_t)p->SkipRows + (size_t)row) * bytes_per_row +
          (size_t)p->SkipPixels / 8;
}

/* [S: main/pack.c:_mesa_expand_bitmap] with onValue 0: a set bit stores
 * 0 (drawn), a clear bit leaves the byte (0xff) */
static void expand_bitmap(const struct fgl_pixelstore *p, const uint8_t *bitmap, int width,
                          int height, uint8_t *dst, int dst_stride)
{
   for (int row = 0; row < height; row++) {
      const uint8_t *src = bitmap_row(p, bitmap, width, row);
      uint8_t *d = dst + (size_t)row * (size_t)dst_stride;
      if (p->LsbFirst) {
         unsigned mask = 1u << (p->SkipPixels & 7);
         for (int col = 0; col < width; col++) {
            if (*src & mask)
               d[col] = 0;
            if (mask == 128u) {
               src++;
               mask = 1u;
            } else {
               mask <<= 1;
            }
         }
      } else {
         unsigned mask = 128u >> (p->SkipPixels & 7);
         for (int col = 0; col < width; col++) {
            if (*src & mask)
               d[col] = 0;
            if (mask == 1u) {
               src++;
               mask = 128u;
            } else {
               mask >>= 1;
            }
         }
      }
   }
}

/* The fixed-function fragment program's gl_TexCoord[u] inputs at a pixel
 * rectangle: a unit whose coordinate may vary (the last draw's vertex
 * format had it, or texgen or the texture matrix produce it) reads the
 * varying, the others the current coordinate as a constant
 * [S: ff_fragment_shader.cpp:filter_fp_input_mask, load_texture]. */
static unsigned tex_varying(const struct fgl_context *ctx)
{
   return fgl_tex_varying_units(ctx);
}

/* What each unit sees (r_pixel_image.tex_quad, tex_const), for the
 * program whose varying coordinates are `varying`.  The passthrough
 * vertex shader writes only gl_TexCoord[0], the image's coordinate
 * [S: st_cb_drawpixels.c:st_make_passthrough_vertex_shader], and
 * llvmpipe feeds varyings no output writes zeros
 * [S: draw_vertex.h:draw_emit_vertex_attr, DRAW_ATTR_NONEXIST]:
 * - glBitmap (nir_lower_bitmap.c) reads the image through that same
 *   varying, so a varying unit 0 reads the quad's coordinate, the other
 *   varying units zeros, the rest the current coordinate;
 * - glDrawPixels and glCopyPixels (nir_lower_drawpixels.c:lower_texcoord)
 *   replace gl_TexCoord[0] by the current coordinate of unit 0
 *   (STATE_CURRENT_ATTRIB, VERT_ATTRIB_TEX0), and the other units read
 *   (0, 0, 0, 0) whether or not their coordinate varies (probed: a unit-1
 *   lookup with a current coordinate of its own, with no draw before, or
 *   with unit 1 outside the last batch's vertex format, is the lookup at
 *   q = 0 under NEAREST and LINEAR, never the current coordinate's). */
static void pixel_texcoords(struct fgl_context *ctx, struct r_pixel_image *img,
                            unsigned varying, bool bitmap)
{
   fgl_flush_current(ctx);
   img->tex_quad = 0;
   for (unsigned u = 0; u < R_MAX_TEX_UNITS && u < FGL_MAX_TEXTURE_UNITS; u++) {
      const float *cur = ctx->Current.Attrib[FGL_ATTR_TEX0 + u];
      const bool vary = (varying & (1u << u)) != 0;
      if (bitmap && u == 0 && vary)
         img->tex_quad = 1u;
      else if (bitmap ? !vary : u == 0)
         memcpy(img->tex_const[u], cur, sizeof(img->tex_const[u]));
      else
         memset(img->tex_const[u], 0, sizeof(img->tex_const[u]));
   }
}

/* t_pixel_rect into the draw buffer, and first into the other one when
 * both are drawn (main/buffers.c "Both buffers": a rectangle's two
 * triangles share no pixel, so the whole rectangle goes to one buffer,
 * then to the other) */
static void pixel_rect(struct fgl_context *ctx, const struct r_state *rs,
                       const struct r_pixel_image *img, const struct t_pixel_quad *q)
{
   if (ctx->DrawBuffer && ctx->DrawBuffer->DrawBoth)
      t_pixel_rect(fgl_both_begin(ctx, rs), img, q);
   t_pixel_rect(rs, img, q);
}

/* Draws a bitmap texture of w x h texels at GL window (x, y) with the
 * state rs [S: st_cb_bitmap.c:draw_bitmap_quad]: texture coordinates 0..1,
 * t = 1 at the top edge. */
static void draw_bitmap_quad(struct fgl_context *ctx, const struct r_state *rs,
                             unsigned varying, int fb_w, int fb_h, int x, int y,
                             float z, int w, int h, const uint8_t *texels, const float color[4])
{
   if (!rs->fb->color && !rs->fb->zs)
      return;
   fgl_scene_flush(ctx);   /* drawn now, after what the scene holds */
   /* the quad's viewport and rasterizer: the draw regions are computed
    * again after it (probe p_vpcut_state) */
   fgl_vpcut_invalidate(ctx);
   fgl_lin_draw(ctx);
   struct r_pixel_image img = {
      .kind = R_PIX_BITMAP, .width = w, .height = h, .mask = texels,
   };
   pixel_texcoords(ctx, &img, varying, true);
   struct t_pixel_quad q;
   memset(&q, 0, sizeof(q));
   q.fb_width = fb_w;
   q.fb_height = fb_h;
   q.z = z;
   memcpy(q.color, color, sizeof(q.color));
   q.x0 = (float)x;
   q.x1 = (float)add_wrap(x, w);
   q.y0 = (float)y;
   q.y1 = (float)add_wrap(y, h);
   q.s0 = 0.0f;
   q.s1 = 1.0f;
   /* st_draw_quad(..., sLeft, tBot = 1, sRight, tTop = 0): t0 = 1 goes to
    * the y1 corners */
   q.t_y1 = 1.0f;
   q.t_y0 = 0.0f;
   pixel_rect(ctx, rs, &img, &q);
}

void fgl_flush_bitmap_cache(struct fgl_context *ctx)
{
   struct fgl_bitmap_cache *c = &ctx->BitmapCache;
   if (!c->Pending)
      return;
   c->Pending = false;
   /* the cache is drawn into the framebuffer it was validated with; one
    * replaced since (a rebind to another size reallocates the buffers)
    * is gone, and so is the drawing */
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   if (!fb || fb->Color != c->Raster.fb->color || fb->Width != c->Raster.fb->width ||
       fb->Height != c->Raster.fb->height)
      return;
   /* [S: st_cb_bitmap.c:setup_render_state] the shader variant is the
    * last validated one, but its constants are uploaded now
    * (st_upload_constants): the fog parameters and colour are the
    * current ones */
   struct r_state rs = c->Raster;
   struct r_fs_state fs = *rs.fs;
   fgl_fog_uniforms(ctx, &fs);
   rs.fs = &fs;
   draw_bitmap_quad(ctx, &rs, c->TexVarying, c->FbWidth, c->FbHeight, c->XPos, c->YPos, c->ZPos,
                    BITMAP_CACHE_WIDTH, BITMAP_CACHE_HEIGHT, c->Buffer, c->Color);
}

/* TEST_EQ_4V: == per component (-0 equals 0, NaN never equal) */
static bool same_color(const float a[4], const float b[4])
{
   return a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && a[3] == b[3];
}

/* [S: st_cb_bitmap.c:accum_bitmap] false if the bitmap is too big to
 * cache, or has no data (no PBO: _mesa_map_pbo_source returns the NULL
 * pointer, after the cache took its position) */
static bool accum_bitmap(struct fgl_context *ctx, int x, int y, int width, int height,
                         const uint8_t *bitmap)
{
   struct fgl_bitmap_cache *c = &ctx->BitmapCache;
   const float z = ctx->Current.RasterPos[2];
   int px = 0, py = 0;

   if (width > BITMAP_CACHE_WIDTH || height > BITMAP_CACHE_HEIGHT)
      return false;
   if (c->Pending) {
      px = sub_wrap(x, c->XPos);
      py = sub_wrap(y, c->YPos);
      if (px < 0 || px > BITMAP_CACHE_WIDTH - width || py < 0 ||
          py > BITMAP_CACHE_HEIGHT - height || !same_color(ctx->Current.RasterColor, c->Color) ||
          fabsf(z - c->ZPos) > 1e-06)
         fgl_flush_bitmap_cache(ctx);
   }
   if (!c->Pending) {
      /* centre the bitmap vertically in the cache */
      px = 0;
      py = (BITMAP_CACHE_HEIGHT - height) / 2;
      c->XPos = x;
      c->YPos = sub_wrap(y, py);
      c->ZPos = z;
      c->Pending = true;
      memcpy(c->Color, ctx->Current.RasterColor, sizeof(c->Color));
      memset(c->Buffer, 0xff, sizeof(c->Buffer));
      c->FbWidth = ctx->DrawBuffer->Width;
      c->FbHeight = ctx->DrawBuffer->Height;
   }
   if (!bitmap)
      return false;
   expand_bitmap(&ctx->Unpack, bitmap, width, height,
                 c->Buffer + (size_t)py * BITMAP_CACHE_WIDTH + (size_t)px, BITMAP_CACHE_WIDTH);
   return true;
}

/* [S: drawpix.c:_mesa_bitmap, st_cb_bitmap.c:st_Bitmap]; `tex`: the
 * texels a display list made at compile time (st_make_bitmap_texture),
 * drawn at once after the cache */
static void bitmap(struct fgl_context *ctx, GLsizei width, GLsizei height, GLfloat xorig,
                   GLfloat yorig, GLfloat xmove, GLfloat ymove, const GLubyte *bits,
                   const uint8_t *tex)
{
   if (width < 0 || height < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!ctx->Current.RasterPosValid)
      return;   /* nothing, not even the move */
   fgl_update_state(ctx);

   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   if (ctx->RenderMode == GL_RENDER) {
      /* truncate, with an epsilon */
      if (width > 0 && height > 0 && fb) {
         const float eps = 0.0001f;
         const int x = ifloor(ctx->Current.RasterPos[0] + eps - xorig);
         const int y = ifloor(ctx->Current.RasterPos[1] + eps - yorig);
         if (ctx->Color.DrawBuffer != GL_NONE)
            fgl_mark_color_defined(fb);
         if (tex)
            fgl_flush_bitmap_cache(ctx);
         /* the cache is drawn with the state validated last: this call's */
         r_state_release(&ctx->BitmapCache.Raster);
         ctx->BitmapCache.Raster = ctx->_Raster;
         r_state_hold(&ctx->BitmapCache.Raster);
         ctx->BitmapCache.TexVarying = tex_varying(ctx);
         if (tex) {
            draw_bitmap_quad(ctx, &ctx->_Raster, tex_varying(ctx), fb->Width, fb->Height, x, y,
                             ctx->Current.RasterPos[2], width, height, tex,
                             ctx->Current.RasterColor);
         } else if (!accum_bitmap(ctx, x, y, width, height, bits) && bits) {
            /* too big: a texture of its own, drawn at once */
            uint8_t *t = fgl_malloc_gl(ctx, (size_t)width * (size_t)height);
            if (!t) {
               fgl_error(ctx, GL_OUT_OF_MEMORY);
               return;
            }
            memset(t, 0xff, (size_t)width * (size_t)height);
            expand_bitmap(&ctx->Unpack, bits, width, height, t, width);
            draw_bitmap_quad(ctx, &ctx->_Raster, tex_varying(ctx), fb->Width, fb->Height, x, y,
                             ctx->Current.RasterPos[2], width, height, t,
                             ctx->Current.RasterColor);
            fgl_free(t);
         }
      }
   } else if (ctx->RenderMode == GL_FEEDBACK) {
      fgl_flush_current(ctx);
      feedback_raster(ctx, GL_BITMAP_TOKEN);
   }
   /* GL_SELECT: nothing */

   ctx->Current.RasterPos[0] += xmove;
   ctx->Current.RasterPos[1] += ymove;
}

void GLAPIENTRY glBitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig,
                         GLfloat xmove, GLfloat ymove, const GLubyte *bits)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag && !fgl_save_bitmap(ctx, width, height, xorig, yorig, xmove, ymove,
                                            bits))
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   bitmap(ctx, width, height, xorig, yorig, xmove, ymove, bits, NULL);
}

/* [S: st_cb_bitmap.c:st_make_bitmap_texture] the texels a compiled
 * glBitmap keeps: 0 where a bit is set, 0xff elsewhere; NULL without
 * data (the list then gets no node and GL_OUT_OF_MEMORY) */
uint8_t *fgl_make_bitmap_texture(const struct fgl_context *ctx, GLsizei width,
                                 GLsizei height, const GLubyte *bits)
{
   if (!bits || width < 0 || height < 0)
      return NULL;
   const size_t n = (size_t)width * (size_t)height;
   uint8_t *t = fgl_malloc_gl(ctx, n ? n : 1);
   if (!t)
      return NULL;
   memset(t, 0xff, n ? n : 1);
   expand_bitmap(&ctx->Unpack, bits, width, height, t, width);
   return t;
}

/* OPCODE_BITMAP: _mesa_bitmap with the compiled texture (glBitmap inside
 * glBegin/glEnd is GL_INVALID_OPERATION there) */
void fgl_exec_list_bitmap(struct fgl_context *ctx, GLsizei width, GLsizei height,
                          GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
                          const uint8_t *tex)
{
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   bitmap(ctx, width, height, xorig, yorig, xmove, ymove, NULL, tex);
}

/* ---- format and type checks ---- */

/* [S: framebuffer.c:_mesa_dest_buffer_exists] for depth and stencil */
static bool zs_buffer_exists(const struct fgl_framebuffer *fb, GLenum format)
{
   if (!fb)
      return false;
   switch (format) {
   case GL_DEPTH_COMPONENT: return fb->DepthBits > 0;
   case GL_STENCIL_INDEX:   return fb->StencilBits > 0;
   default:                 return true;
   }
}

/* ---- glDrawPixels ---- */

/* The float RGBA a colour sample of the oracle's texture returns for one
 * component value of the client image: the texture format matches the
 * client format and type (st_choose_matching_format), so normalized
 * integers come back as value * (float)(1 / (2^n - 1))
 * [S: gallivm/lp_bld_conv.c:lp_build_unsigned_norm_to_float] and floats
 * unchanged. */
static bool color_component(GLenum type, const uint8_t *src, int i, float *out)
{
   switch (type) {
   case GL_UNSIGNED_BYTE:
      *out = (float)src[i] * (float)(1.0 / 255.0);
      return true;
   case GL_UNSIGNED_SHORT: {
      uint16_t v;
      memcpy(&v, src + 2 * i, 2);
      *out = (float)v * (float)(1.0 / 65535.0);
      return true;
   }
   case GL_FLOAT:
      memcpy(out, src + 4 * i, 4);
      return true;
   default:
      return false;
   }
}

/* The client colour image as the RGBA texels the oracle samples
 * (missing channels 0, alpha 1; luminance in r, g, b), rows bottom-up.
 * False for the formats and types it leaves to unpack_other_texels. */
static bool unpack_color_texels(const struct fgl_pixelstore *p, const void *pixels,
                                int width, int height, GLenum format, GLenum type,
                                float *dst)
{
   if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_FLOAT)
      return false;
   if (p->SwapBytes && type != GL_UNSIGNED_BYTE)
      return false;
   for (int y = 0; y < height; y++) {
      const uint8_t *src = fgl_image_address(p, pixels, width, format, type, y, 0);
      const size_t bpp = fgl_pixel_bytes(format, type);
      for (int x = 0; x < width; x++, src += bpp) {
         float c[4] = { 0.0f, 0.0f, 0.0f, 1.0f }, v0, v1, v2, v3;
         switch (format) {
         case GL_RGBA:
            color_component(type, src, 0, &c[0]);
            color_component(type, src, 1, &c[1]);
            color_component(type, src, 2, &c[2]);
            color_component(type, src, 3, &c[3]);
            break;
         case GL_BGRA:
            color_component(type, src, 2, &c[0]);
            color_component(type, src, 1, &c[1]);
            color_component(type, src, 0, &c[2]);
            color_component(type, src, 3, &c[3]);
            break;
         case GL_RGB:
            color_component(type, src, 0, &c[0]);
            color_component(type, src, 1, &c[1]);
            color_component(type, src, 2, &c[2]);
            break;
         case GL_BGR:
            color_component(type, src, 2, &c[0]);
            color_component(type, src, 1, &c[1]);
            color_component(type, src, 0, &c[2]);
            break;
         case GL_RED:   color_component(type, src, 0, &c[0]); break;
         case GL_GREEN: color_component(type, src, 0, &c[1]); break;
         case GL_BLUE:  color_component(type, src, 0, &c[2]); break;
         case GL_ALPHA: color_component(type, src, 0, &c[3]); break;
         case GL_LUMINANCE:
            color_component(type, src, 0, &v0);
            c[0] = c[1] = c[2] = v0;
            break;
         case GL_LUMINANCE_ALPHA:
            color_component(type, src, 0, &v0);
            color_component(type, src, 1, &v1);
            c[0] = c[1] = c[2] = v0;
            c[3] = v1;
            break;
         default:
            (void)v2;
            (void)v3;
            return false;
         }
         memcpy(dst + 4 * ((size_t)y * (size_t)width + (size_t)x), c, sizeof(c));
      }
   }
   return true;
}

/* The depth texels of a GL_DEPTH_COMPONENT image, as texstore fills the
 * matching depth texture and the sampler reads it back
 * [S: pack.c:_mesa_unpack_depth_span; texstore.c:texstore_z32f,
 * texstore_z16, texstore_z32; lp_bld_conv.c:lp_build_unsigned_norm_to_float]:
 *   GL_FLOAT        Z32F: clamp01(d * scale + bias)
 *   GL_UNSIGNED_SHORT Z16: (ushort)(d * 65535.0f), read as z * (1/65535)
 *   GL_UNSIGNED_INT Z32: (uint)(d * 4294967295.0), read through its top 23
 *                   bits
 * where d is the value converted to float (USHORT_TO_FLOAT, UINT_TO_FLOAT),
 * scaled and biased and clamped when the transfer is not the identity. */
static bool unpack_depth_texels(const struct fgl_context *ctx, const struct fgl_pixelstore *p,
                                const void *pixels, int width, int height, GLenum type,
                                float *dst)
{
   if (type != GL_FLOAT && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT)
      return false;
   if (p->SwapBytes)
      return false;
   const float scale = ctx->Pixel.DepthScale, bias = ctx->Pixel.DepthBias;
   const bool identity = scale == 1.0f && bias == 0.0f;
   for (int y = 0; y < height; y++) {
      const uint8_t *src = fgl_image_address(p, pixels, width, GL_DEPTH_COMPONENT, type, y, 0);
      for (int x = 0; x < width; x++) {
         float d, t;
         bool clamp = false;
         if (type == GL_FLOAT) {
            memcpy(&d, src + 4 * x, 4);
            clamp = true;
         } else if (type == GL_UNSIGNED_SHORT) {
            uint16_t v;
            memcpy(&v, src + 2 * x, 2);
            d = (float)v * (1.0f / 65535.0f);
         } else {
            uint32_t v;
            memcpy(&v, src + 4 * x, 4);
            d = (float)((double)v * (double)(1.0f / 4294967295.0));
         }
         if (!identity) {
            d = d * scale + bias;
            clamp = true;
         }
         if (clamp)
            d = d > 0.0f ? (d > 1.0f ? 1.0f : d) : 0.0f;   /* Mesa's CLAMP */
         if (identity) {
            /* _mesa_texstore_can_use_memcpy: the texture is the client
             * data as is (a float unclamped, an integer not rounded
             * through float) */
            if (type == GL_FLOAT) {
               memcpy(&t, src + 4 * x, 4);
            } else if (type == GL_UNSIGNED_SHORT) {
               uint16_t v;
               memcpy(&v, src + 2 * x, 2);
               t = (float)v * (float)(1.0 / 65535.0);
            } else {
               uint32_t v;
               memcpy(&v, src + 4 * x, 4);
               const uint32_t bits = (v >> 9) | 0x3f800000u;
               float f;
               memcpy(&f, &bits, 4);
               t = (f - 1.0f) * (float)(8388608.0 / 8388607.0);
            }
         } else if (type == GL_FLOAT) {
            t = d;
         } else if (type == GL_UNSIGNED_SHORT) {
            const uint16_t z = (uint16_t)(d * 65535.0f);
            t = (float)z * (float)(1.0 / 65535.0);
         } else {
            const double zd = (double)d * 4294967295.0;
            const uint32_t z = zd >= 4294967295.0 ? 0xffffffffu : (uint32_t)zd;
            const uint32_t bits = (z >> 9) | 0x3f800000u;
            float f;
            memcpy(&f, &bits, 4);
            t = (f - 1.0f) * (float)(8388608.0 / 8388607.0);
         }
         dst[(size_t)y * (size_t)width + (size_t)x] = t;
      }
   }
   return true;
}

/* The depth texels of the other types: the GL_DEPTH_COMPONENT texture is
 * Z24X8 (st_format.c DEFAULT_DEPTH_FORMATS), filled by _mesa_unpack_depth_span
 * (conversion, scale and bias, clamp) and (GLuint)(d * (float)0xffffff),
 * sampled as z * (float)(1 / 0xffffff). */
static bool unpack_depth_texels_z24(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                                    const void *pixels, int width, int height, GLenum type,
                                    float *dst)
{
   for (int y = 0; y < height; y++) {
      const uint8_t *src = fgl_image_address(p, pixels, width, GL_DEPTH_COMPONENT, type, y, 0);
      float *row = dst + (size_t)y * (size_t)width;
      fgl_unpack_depth_span_float(ctx, p, (size_t)width, type, src, row);
      for (int x = 0; x < width; x++) {
         const uint32_t z = (uint32_t)(row[x] * (float)0xffffff);
         row[x] = (float)z * (float)(1.0 / 16777215.0);
      }
   }
   return true;
}

/* The colour texels of the formats and types unpack_color_texels leaves:
 * through main/pixelformat.c without transfer operations (make_texture
 * clears _ImageTransferState).  The matching texture formats (snorm,
 * the packed unorm formats) sample as those floats, up to the last bit of
 * the unorm conversions, which no output rounding sees; GL_INT data is
 * narrowed to 16-bit snorm first and GL_UNSIGNED_INT data to 16-bit
 * unorm, whose last bit an output rounding does see
 * (FGL_UNPACK_INT_SNORM16, FGL_UNPACK_UINT_UNORM16).
 * GL_COLOR_INDEX goes through the I_TO_R/G/B/A maps into an RGBA8
 * texture (_mesa_unpack_color_index_to_rgba_ubyte, CLAMPED_FLOAT_TO_UBYTE:
 * the index shift and offset are off as well). */
/* The channel widths (r, g, b, a; 0: none) of the types whose matching
 * texture formats fit in 8-bit unorm: llvmpipe samples them on its AoS
 * path, which widens each channel to 8 bits by repeating its bits
 * (util_format's unpack_rgba_8unorm: (c << 3) | (c >> 2) for 5 bits)
 * before the conversion to float, t * (float)(1/255). */
static bool unorm8_widths(GLenum type, int w[4])
{
   static const int w332[4] = { 3, 3, 2, 0 }, w565[4] = { 5, 6, 5, 0 },
                    w4444[4] = { 4, 4, 4, 4 }, w5551[4] = { 5, 5, 5, 1 },
                    w8888[4] = { 8, 8, 8, 8 };
   const int *src;
   switch (type) {
   case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV:   src = w332; break;
   case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV: src = w565; break;
   case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV: src = w4444; break;
   case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV: src = w5551; break;
   case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
   case GL_UNSIGNED_BYTE:
      src = w8888;
      break;
   default:
      return false;
   }
   memcpy(w, src, 4 * sizeof(int));
   return true;
}

/* n-bit c widened to 8 bits by repeating its bits */
static unsigned replicate_bits(unsigned c, int n)
{
   unsigned v = 0;
   for (int shift = 8 - n; shift > -n; shift -= n)
      v |= shift >= 0 ? c << shift : c >> -shift;
   return v & 0xffu;
}

static bool unpack_other_texels(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                                const void *pixels, int width, int height, GLenum format,
                                GLenum type, float *dst)
{
   /* GL_INT: the oracle's image texture is 16-bit snorm, so each channel
    * keeps its top 16 bits; GL_UNSIGNED_INT: 16-bit unorm, each channel
    * rounded to 16 bits (ORACLE-NOTES.md "Bitmaps and pixel rectangles",
    * probe p_drawpixels_int) */
   const unsigned narrow = type == GL_INT ? FGL_UNPACK_INT_SNORM16
                         : type == GL_UNSIGNED_INT ? FGL_UNPACK_UINT_UNORM16 : 0;
   if (!fgl_unpack_rgba_float(ctx, p, width, height, format, type, pixels, narrow, dst))
      return false;
   int w[4];
   if (format != GL_COLOR_INDEX && unorm8_widths(type, w)) {
      const size_t n = (size_t)width * (size_t)height;
      for (size_t i = 0; i < n; i++)
         for (int c = 0; c < 4; c++) {
            if (w[c] == 0)
               continue;   /* a channel the format lacks keeps its default */
            float *v = &dst[4 * i + (size_t)c];
            const unsigned max = (1u << w[c]) - 1u;
            const unsigned q = (unsigned)lrintf(*v * (float)max);
            *v = (float)replicate_bits(q, w[c]) * (float)(1.0 / 255.0);
         }
   }
   if (format == GL_COLOR_INDEX) {
      const size_t n = 4 * (size_t)width * (size_t)height;
      for (size_t i = 0; i < n; i++) {
         const float v = dst[i] > 0.0f ? (dst[i] > 1.0f ? 1.0f : dst[i]) : 0.0f;
         dst[i] = (float)r_round_even(v * 255.0f) * (float)(1.0 / 255.0);
      }
   }
   return true;
}

/* The stencil texels of a GL_STENCIL_INDEX image [S: texstore.c:
 * _mesa_texstore_s8, pack.c:_mesa_unpack_stencil_span with the transfer
 * operations off (make_texture clears _ImageTransferState): no index shift
 * or offset, but GL_MAP_STENCIL, which the function reads from the
 * context, except for unsigned bytes, which are copied], the low 8 bits. */
static bool unpack_stencil_texels(const struct fgl_context *ctx,
                                  const struct fgl_pixelstore *p, const void *pixels,
                                  int width, int height, GLenum type, uint8_t *dst)
{
   /* unsigned bytes match S8: _mesa_texstore_can_use_memcpy (stencil
    * needs no transfer operations, it says), so no map either */
   const bool map = ctx->Pixel.MapStencilFlag && type != GL_UNSIGNED_BYTE;
   GLuint *idx = fgl_malloc_gl(ctx, (size_t)width * sizeof(GLuint));
   if (!idx)
      return false;
   for (int y = 0; y < height; y++) {
      const uint8_t *src = fgl_image_address(p, pixels, width, GL_STENCIL_INDEX, type, y, 0);
      fgl_extract_uint_indexes(p, (size_t)width, type, src, idx);
      for (int x = 0; x < width; x++) {
         GLuint v = idx[x];
         if (map) {
            const GLuint mask = (GLuint)ctx->PixelMaps.StoS.Size - 1;
            v = (GLuint)ctx->PixelMaps.StoS.Map[v & mask];
         }
         dst[(size_t)y * (size_t)width + (size_t)x] = (uint8_t)(v & 0xffu);
      }
   }
   fgl_free(idx);
   return true;
}

/* The state of the stencil-writing quad [S: st_cb_drawpixels.c:
 * draw_textured_quad with write_stencil]: stencil ALWAYS, zpass REPLACE
 * with the exported value under the stencil write mask, depth off (the
 * oracle's depth+stencil draw, ALWAYS under the depth mask, is
 * GL_DEPTH_STENCIL's, not GL 1.5's); no colour, alpha test or blending. */
struct stencil_quad_objects {
   struct r_dsa_state dsa;
   struct r_blend_state blend;
};

static void stencil_quad_state(const struct fgl_context *ctx, struct r_state *rs,
                               struct stencil_quad_objects *o)
{
   o->dsa = *rs->dsa;
   o->blend = *rs->blend;
   o->dsa.stencil_test = true;
   o->dsa.stencil_func = R_ALWAYS;
   o->dsa.stencil_valuemask = 0;
   o->dsa.stencil_writemask = (uint8_t)(ctx->Stencil.WriteMask & 0xffu);
   o->dsa.stencil_fail = o->dsa.stencil_zfail = R_STENCIL_KEEP;
   o->dsa.stencil_zpass = R_STENCIL_REPLACE;
   o->dsa.depth_test = false;
   o->dsa.depth_func = R_ALWAYS;
   o->dsa.depth_write = ctx->Depth.Mask;
   o->dsa.alpha_test = false;
   o->blend.enable = false;
   o->blend.logic_op = false;
   o->blend.color_mask = 0;
   rs->dsa = &o->dsa;
   rs->blend = &o->blend;
   rs->full_ops = true;
}

/* [S: pixel.c:_mesa_update_pixel] the scale/bias uniforms of the shader */
static bool scale_bias_on(const struct fgl_pixel_attrib *px)
{
   return px->RedBias != 0.0f || px->RedScale != 1.0f || px->GreenBias != 0.0f ||
          px->GreenScale != 1.0f || px->BlueBias != 0.0f || px->BlueScale != 1.0f ||
          px->AlphaBias != 0.0f || px->AlphaScale != 1.0f;
}

static void color_transfer(const struct fgl_context *ctx, struct r_pixel_image *img)
{
   const struct fgl_pixel_attrib *px = &ctx->Pixel;
   img->scale_bias = scale_bias_on(px);
   img->scale[0] = px->RedScale;
   img->scale[1] = px->GreenScale;
   img->scale[2] = px->BlueScale;
   img->scale[3] = px->AlphaScale;
   img->bias[0] = px->RedBias;
   img->bias[1] = px->GreenBias;
   img->bias[2] = px->BlueBias;
   img->bias[3] = px->AlphaBias;
   img->map_color = px->MapColorFlag;
   const struct fgl_pixelmap *maps[4] = {
      &ctx->PixelMaps.RtoR, &ctx->PixelMaps.GtoG, &ctx->PixelMaps.BtoB, &ctx->PixelMaps.AtoA,
   };
   for (int i = 0; i < 4; i++) {
      img->maps[i] = maps[i]->Map;
      img->map_size[i] = maps[i]->Size;
   }
}

/* One axis of a clip: [*pos, *pos + *size) against [lo, hi), the cut
 * start added to *skip (wrapping, as the oracle's int); false if nothing
 * is left.  64-bit arithmetic, so no position or size overflows. */
static bool clip_span(int *pos, int *size, int lo, int hi, int *skip)
{
   long long p = *pos, n = *size;
   long long cut = 0;
   if (p < lo) {
      cut = lo - p;
      n -= cut;
      p = lo;
   }
   if (p + n > hi)
      n = hi - p;
   if (n <= 0)
      return false;
   *skip = (int)((unsigned)*skip + (unsigned)cut);
   *pos = (int)p;
   *size = (int)n;
   return true;
}

/* [S: image.c:_mesa_clip_drawpixels] with zoom (1, 1): the destination
 * against the scissored draw bounds, skipping what is left out */
static bool clip_drawpixels(const struct fgl_context *ctx, int *x, int *y, int *w, int *h,
                            struct fgl_pixelstore *unpack)
{
   int b[4];
   fgl_scissor_bounds(ctx, b);   /* xmin, xmax, ymin, ymax */
   if (unpack->RowLength == 0)
      unpack->RowLength = *w;
   /* in 64 bits: a position or size near the int limits clips as it
    * should instead of overflowing */
   if (!clip_span(x, w, b[0], b[1], &unpack->SkipPixels))
      return false;
   return clip_span(y, h, b[2], b[3], &unpack->SkipRows);
}

/* The quad of a glDrawPixels or glCopyPixels texture [S: st_cb_drawpixels.c:
 * draw_textured_quad]: x1 = x + width * zoomX, y1 = y + height * zoomY
 * (float), texture coordinates 0..1; `invert` (glCopyPixels, whose
 * texture is y-down): t = 0 at the y1 edge. */
static void textured_quad(const struct fgl_context *ctx, struct t_pixel_quad *q, int x, int y,
                          int width, int height, bool invert)
{
   q->x0 = (float)x;
   q->x1 = (float)x + (float)width * ctx->Pixel.ZoomX;
   q->y0 = (float)y;
   q->y1 = (float)y + (float)height * ctx->Pixel.ZoomY;
   q->s0 = 0.0f;
   q->s1 = 1.0f;
   /* st_draw_quad(..., sLeft, tBot, sRight, tTop): tBot at the y1 edge */
   q->t_y1 = invert ? 0.0f : 1.0f;
   q->t_y0 = invert ? 1.0f : 0.0f;
}

/* [S: st_cb_drawpixels.c:search_drawpixels_cache] the texture made from
 * the same client pointer, size, format and type with the same bytes
 * (compared over width * height * bytes per pixel, whatever the row
 * padding) is reused as it was made: with the depth scale and bias or
 * the stencil map of that time.  Only images without skips or a row
 * length of their own take part. */
static struct fgl_drawpix_cache_entry *search_cache(struct fgl_context *ctx, int width,
                                                    int height, GLenum format, GLenum type,
                                                    const struct fgl_pixelstore *unpack,
                                                    const void *pixels)
{
   struct fgl_drawpix_cache *c = &ctx->DrawpixCache;
   const size_t bpp = fgl_pixel_bytes(format, type);
   if ((unpack->RowLength != 0 && unpack->RowLength != width) || unpack->SkipPixels != 0 ||
       unpack->SkipRows != 0 || unpack->SwapBytes)
      return NULL;
   for (int i = 0; i < 4; i++) {
      struct fgl_drawpix_cache_entry *e = &c->Entries[i];
      if (width == e->Width && height == e->Height && format == e->Format &&
          type == e->Type && pixels == e->UserPointer && e->Image &&
          memcmp(pixels, e->Image, (size_t)width * (size_t)height * bpp) == 0) {
         e->Age = ++c->Age;
         return e;
      }
   }
   return NULL;
}

/* [S: st_cb_drawpixels.c:cache_drawpixels_image] into the oldest entry;
 * takes ownership of texels and mask (false: the caller keeps them) */
static bool cache_image(struct fgl_context *ctx, int width, int height, GLenum format,
                        GLenum type, const struct fgl_pixelstore *unpack, const void *pixels,
                        float *texels, uint8_t *mask)
{
   struct fgl_drawpix_cache *c = &ctx->DrawpixCache;
   if (!((unpack->RowLength == 0 || unpack->RowLength == width) && unpack->SkipPixels == 0 &&
         unpack->SkipRows == 0))
      return false;
   const size_t bytes = (size_t)width * (size_t)height * fgl_pixel_bytes(format, type);
   struct fgl_drawpix_cache_entry *e = &c->Entries[0];
   for (int i = 1; i < 4; i++)
      if (c->Entries[i].Age < e->Age)
         e = &c->Entries[i];
   fgl_free(e->Image);
   fgl_free(e->Texels);
   fgl_free(e->Mask);
   memset(e, 0, sizeof(*e));
   e->Image = fgl_malloc_gl(ctx, bytes ? bytes : 1);
   if (!e->Image)
      return false;
   memcpy(e->Image, pixels, bytes);
   e->Width = width;
   e->Height = height;
   e->Format = format;
   e->Type = type;
   e->UserPointer = pixels;
   e->Texels = texels;
   e->Mask = mask;
   e->Age = ++c->Age;
   return true;
}

void fgl_free_drawpix_cache(struct fgl_context *ctx)
{
   for (int i = 0; i < 4; i++) {
      struct fgl_drawpix_cache_entry *e = &ctx->DrawpixCache.Entries[i];
      fgl_free(e->Image);
      fgl_free(e->Texels);
      fgl_free(e->Mask);
      memset(e, 0, sizeof(*e));
   }
}

/* [S: st_cb_drawpixels.c:make_texture] the texels of the image: stencil
 * values in *mask, depth or RGBA floats in *texels; false if fixgl does
 * not convert this format and type */
static bool make_texture(struct fgl_context *ctx, const struct fgl_pixelstore *unpack,
                         int width, int height, GLenum format, GLenum type,
                         const void *pixels, float **texels, uint8_t **mask)
{
   const size_t n = (size_t)width * (size_t)height;
   *texels = NULL;
   *mask = NULL;
   if (format == GL_STENCIL_INDEX) {
      *mask = fgl_malloc_gl(ctx, n);
      if (*mask && unpack_stencil_texels(ctx, unpack, pixels, width, height, type, *mask))
         return true;
   } else if (format == GL_DEPTH_COMPONENT) {
      *texels = fgl_malloc_gl(ctx, n * sizeof(float));
      if (*texels && (unpack_depth_texels(ctx, unpack, pixels, width, height, type, *texels) ||
                      unpack_depth_texels_z24(ctx, unpack, pixels, width, height, type,
                                              *texels)))
         return true;
   } else {
      *texels = fgl_malloc_gl(ctx, 4 * n * sizeof(float));
      if (*texels && (unpack_color_texels(unpack, pixels, width, height, format, type,
                                          *texels) ||
                      unpack_other_texels(ctx, unpack, pixels, width, height, format, type,
                                          *texels)))
         return true;
   }
   fgl_free(*texels);
   fgl_free(*mask);
   *texels = NULL;
   *mask = NULL;
   return false;
}

/* [S: st_cb_drawpixels.c:st_DrawPixels] */
static void draw_pixels(struct fgl_context *ctx, int x, int y, int width, int height,
                        GLenum format, GLenum type, const void *pixels)
{
   fgl_scene_flush(ctx);   /* drawn now, after what the scene holds */
   fgl_vpcut_invalidate(ctx);   /* the quad's viewport (probe p_vpcut_state) */
   fgl_lin_draw(ctx);
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   struct fgl_pixelstore unpack = ctx->Unpack;

   fgl_flush_bitmap_cache(ctx);
   if (ctx->Pixel.ZoomX == 1.0f && ctx->Pixel.ZoomY == 1.0f &&
       !clip_drawpixels(ctx, &x, &y, &width, &height, &unpack))
      return;

   float *texels;
   uint8_t *mask;
   bool owned = true;
   const struct fgl_drawpix_cache_entry *hit =
      pixels ? search_cache(ctx, width, height, format, type, &unpack, pixels) : NULL;
   if (hit) {
      texels = hit->Texels;
      mask = hit->Mask;
      owned = false;
   } else {
      /* make_texture: no image (no PBO) is GL_OUT_OF_MEMORY */
      if (!pixels) {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return;
      }
      if (!make_texture(ctx, &unpack, width, height, format, type, pixels, &texels, &mask))
         return;
      if (cache_image(ctx, width, height, format, type, &unpack, pixels, texels, mask))
         owned = false;
   }
   if (ctx->Color.DrawBuffer != GL_NONE)
      fgl_mark_color_defined(fb);

   struct r_pixel_image img = { .width = width, .height = height, .texels = texels,
                                .mask = mask };
   struct t_pixel_quad q;
   quad_init(&q, fb, ctx->Current.RasterPos[2], ctx->Current.RasterColor);
   textured_quad(ctx, &q, x, y, width, height, false);
   struct r_state rs = ctx->_Raster;
   struct stencil_quad_objects qo;
   if (format == GL_STENCIL_INDEX) {
      img.kind = R_PIX_STENCIL;
      stencil_quad_state(ctx, &rs, &qo);
   } else if (format == GL_DEPTH_COMPONENT) {
      img.kind = R_PIX_DEPTH;
   } else {
      img.kind = R_PIX_COLOR;
      color_transfer(ctx, &img);
   }
   pixel_texcoords(ctx, &img, tex_varying(ctx), false);
   pixel_rect(ctx, &rs, &img, &q);
   if (owned) {
      fgl_free(texels);
      fgl_free(mask);
   }
}

static void drawpixels(struct fgl_context *ctx, GLsizei width, GLsizei height, GLenum format,
                       GLenum type, const GLvoid *pixels)
{
   FGL_FLUSH_VERTICES(ctx, 0);
   if (width < 0 || height < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   fgl_update_state(ctx);
   const GLenum err = fgl_error_check_format_and_type(ctx, format, type);
   if (err != GL_NO_ERROR) {
      fgl_error(ctx, err);
      return;
   }
   if (!zs_buffer_exists(ctx->DrawBuffer, format)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (!ctx->Current.RasterPosValid || !ctx->DrawBuffer)
      return;
   if (ctx->RenderMode == GL_RENDER) {
      if (width > 0 && height > 0) {
         /* round half away from zero (lroundf) */
         const int x = (int)lroundf(ctx->Current.RasterPos[0]);
         const int y = (int)lroundf(ctx->Current.RasterPos[1]);
         draw_pixels(ctx, x, y, width, height, format, type, pixels);
      }
   } else if (ctx->RenderMode == GL_FEEDBACK) {
      fgl_flush_current(ctx);
      feedback_raster(ctx, GL_DRAW_PIXEL_TOKEN);
   }
}

void GLAPIENTRY glDrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type,
                             const GLvoid *pixels)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag && !fgl_save_drawpixels(ctx, width, height, format, type, pixels))
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   drawpixels(ctx, width, height, format, type, pixels);
}

/* OPCODE_DRAW_PIXELS: the compile-time copy with the default packing */
void fgl_exec_list_drawpixels(struct fgl_context *ctx, GLsizei width, GLsizei height,
                              GLenum format, GLenum type, const GLvoid *pixels)
{
   /* glDrawPixels is not allowed between glBegin and glEnd there either
    * (a list called inside them) */
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   const struct fgl_pixelstore saved = ctx->Unpack;
   ctx->Unpack = (struct fgl_pixelstore){ .Alignment = 1 };
   drawpixels(ctx, width, height, format, type, pixels);
   ctx->Unpack = saved;
}

/* [S: dlist.c:unpack_image] the image copied with the unpack state into
 * rows packed with alignment 1 (NULL for a size or format it cannot
 * address) */
GLvoid *fgl_pack_list_image(const struct fgl_context *ctx, GLsizei width, GLsizei height,
                            GLenum format, GLenum type, const GLvoid *pixels)
{
   const size_t bpp = fgl_pixel_bytes(format, type);
   if (!pixels || width <= 0 || height <= 0 || bpp == 0)
      return NULL;
   uint8_t *out = fgl_malloc_gl(ctx, bpp * (size_t)width * (size_t)height);
   if (!out)
      return NULL;
   for (int y = 0; y < height; y++)
      memcpy(out + (size_t)y * bpp * (size_t)width,
             fgl_image_address(&ctx->Unpack, pixels, width, format, type, y, 0),
             bpp * (size_t)width);
   return out;
}

/* ---- glCopyPixels ---- */

/* [S: image.c:_mesa_clip_readpixels] against the framebuffer */
static bool clip_readpixels(const struct fgl_framebuffer *fb, int *x, int *y, int *w, int *h,
                            int *skip_pixels, int *skip_rows)
{
   return clip_span(x, w, 0, fb->Width, skip_pixels) &&
          clip_span(y, h, 0, fb->Height, skip_rows);
}

/* The _ImageTransferState of the colour path (_mesa_update_pixel):
 * scale/bias, index shift/offset, colour maps */
static bool transfer_ops(const struct fgl_context *ctx)
{
   return scale_bias_on(&ctx->Pixel) || ctx->Pixel.IndexShift != 0 ||
          ctx->Pixel.IndexOffset != 0 || ctx->Pixel.MapColorFlag;
}

/* pipe->blit of a w x h colour rectangle between two y-down positions:
 * whole pixels (PIPE_MASK_RGBA), of the wide target too (the same format
 * at both ends: its values copied as they are; case osmesa/float_copypixels);
 * the RGBA8 pixels from src (the read buffer: fb->Color, or a separate
 * front or back buffer, fgl_read_color) */
static void blit_rect(struct fgl_framebuffer *fb, const uint8_t *src, int sx, int sy, int dx, int dy,
                      int w, int h)
{
   const size_t wide_bpp = fb->WideFormat == R_WIDE_FLOAT     ? 16
                           : fb->WideFormat == R_WIDE_UNORM16 ? 8
                                                              : 0;
   for (int j = 0; j < h; j++) {
      const size_t s = (size_t)(sy + j) * (size_t)fb->Width + (size_t)sx;
      const size_t d = (size_t)(dy + j) * (size_t)fb->Width + (size_t)dx;
      memmove(fb->Color + 4 * d, src + 4 * s, 4 * (size_t)w);
      if (wide_bpp)
         memmove((uint8_t *)fb->Wide + wide_bpp * d, (const uint8_t *)fb->Wide + wide_bpp * s,
                 wide_bpp * (size_t)w);
   }
}

/* [S: st_cb_drawpixels.c:blit_copy_pixels] true if done by pipe->blit:
 * colour, zoom 1, and no per-fragment work the blit would skip
 * (blending, alpha test, a logic op but COPY, a depth test that could
 * fail or write, fog, stencil ops, pixel transfer, no colour buffer); the
 * colour mask, the stencil function and texturing are not looked at (an
 * enabled texture does not stop the blit: pixel/copypixels_textured_1d).  The regions
 * are clipped like glReadPixels and glDrawPixels; overlapping source and
 * destination take the texture path. */
static bool blit_copy_pixels(struct fgl_context *ctx, int srcx, int srcy, int width,
                             int height, int dstx, int dsty, GLenum type)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   /* the blit needs formats the screen can sample and render to: depth
    * and stencil buffers are no render targets of llvmpipe, so only
    * colour copies take it */
   if (type != GL_COLOR || ctx->Pixel.ZoomX != 1.0f || ctx->Pixel.ZoomY != 1.0f)
      return false;
   if (type == GL_COLOR &&
       (transfer_ops(ctx) || ctx->Color.BlendEnabled || ctx->Color.AlphaEnabled ||
        (ctx->Color.LogicOpEnabled && ctx->Color.LogicOp != GL_COPY) ||
        (ctx->Depth.Test && !(ctx->Depth.Func == GL_ALWAYS && !ctx->Depth.Mask)) ||
        ctx->Fog.Enabled ||
        (ctx->Stencil.Enabled &&
         (ctx->Stencil.FailFunc != GL_KEEP || ctx->Stencil.ZPassFunc != GL_KEEP ||
          ctx->Stencil.ZFailFunc != GL_KEEP)) ||
        ctx->Color.DrawBuffer == GL_NONE ||
        (fb && fb->DrawBoth) ||         /* _NumColorDrawBuffers 2 */
        ctx->ReadFb ||                  /* another read framebuffer: the quad */
        ctx->Query.CurrentOcclusion))   /* the quad counts its samples */
      return false;

   int rx = srcx, ry = srcy, rw = width, rh = height, skip_px = 0, skip_rows = 0;
   if (!clip_readpixels(fb, &rx, &ry, &rw, &rh, &skip_px, &skip_rows))
      return true;
   /* a destination past the int range is nowhere in the window */
   const long long drx64 = (long long)dstx + skip_px, dry64 = (long long)dsty + skip_rows;
   if (drx64 > INT_MAX || dry64 > INT_MAX)
      return true;
   int drx = (int)drx64, dry = (int)dry64;
   struct fgl_pixelstore unpack = { .Alignment = 1, .RowLength = width,
                                    .SkipPixels = skip_px, .SkipRows = skip_rows };
   if (!clip_drawpixels(ctx, &drx, &dry, &rw, &rh, &unpack))
      return true;
   rx = rx - skip_px + unpack.SkipPixels;
   ry = ry - skip_rows + unpack.SkipRows;
   /* y-down */
   const int H = fb->Height;
   const int ry_down = H - ry - rh, dy_down = H - dry - rh;
   /* _mesa_regions_overlap */
   const bool overlap = !((rx > drx ? rx : drx) >= (rx + rw < drx + rw ? rx + rw : drx + rw)) &&
                        !((ry_down > dy_down ? ry_down : dy_down) >=
                          (ry_down + rh < dy_down + rh ? ry_down + rh : dy_down + rh));
   if (overlap)
      return false;
   fgl_mark_color_defined(fb);
   blit_rect(fb, fgl_read_color(ctx), rx, ry_down, drx, dy_down, rw, rh);
   return true;
}

/* n pixels of glCopyPixels' source from index src, as the texture of
 * the read buffer's format samples them (each format chosen once per
 * row): the colour buffer's RGBA8 value * (float)(1 / 255), a wide
 * target's unorm16 * (float)(1 / 65535) or its floats (case
 * osmesa/ushort_copypixels; ORACLE-NOTES.md "OSMesa contexts and
 * buffers") */
static void copy_source_color_row(const struct fgl_framebuffer *fb, const uint8_t *read_color,
                                  size_t src, float *t, int n)
{
   const size_t k = 4 * (size_t)n;
   switch (fb->WideFormat) {
   case R_WIDE_FLOAT:
      memcpy(t, (const float *)fb->Wide + 4 * src, k * sizeof(float));
      break;
   case R_WIDE_UNORM16: {
      const uint16_t *w = (const uint16_t *)fb->Wide + 4 * src;
      for (size_t i = 0; i < k; i++)
         t[i] = (float)w[i] * (float)(1.0 / 65535.0);
      break;
   }
   default: {
      const uint8_t *c = read_color + 4 * src;
      for (size_t i = 0; i < k; i++)
         t[i] = (float)c[i] * (float)(1.0 / 255.0);
      break;
   }
   }
}

/* the depth texture (the buffer's format) sampled: unorm to float,
 * value * (float)(1 / (2^n - 1)); a Z32_UNORM one through its top 23 bits
 * (r_tex_depth_value) */
static void copy_source_depth_row(const struct fgl_framebuffer *fb, size_t src, float *t, int n)
{
   switch (fb->ZSFormat) {
   case R_ZS_Z16:
      for (int i = 0; i < n; i++)
         t[i] = (float)((const uint16_t *)fb->Depth)[src + (size_t)i] * (float)(1.0 / 65535.0);
      break;
   case R_ZS_Z32:
      for (int i = 0; i < n; i++)
         t[i] = r_tex_depth_value(((const uint32_t *)fb->Depth)[src + (size_t)i], 32);
      break;
   default:
      for (int i = 0; i < n; i++)
         t[i] = (float)(((const uint32_t *)fb->Depth)[src + (size_t)i] & 0xffffffu) *
                (float)(1.0 / 16777215.0);
      break;
   }
}

static void copy_source_stencil_row(const struct fgl_framebuffer *fb, size_t src, uint8_t *s,
                                    int n)
{
   if (fb->ZSFormat == R_ZS_S8)
      memcpy(s, fb->Stencil + src, (size_t)n);
   else
      for (int i = 0; i < n; i++)
         s[i] = (uint8_t)(((const uint32_t *)fb->Depth)[src + (size_t)i] >> 24);
}

/* [S: st_cb_drawpixels.c:st_CopyPixels] */
static void copy_pixels(struct fgl_context *ctx, int srcx, int srcy, int width, int height,
                        int dstx, int dsty, GLenum type)
{
   struct fgl_framebuffer *fb = ctx->DrawBuffer;
   fgl_flush_bitmap_cache(ctx);
   fgl_scene_flush(ctx);   /* reads and draws the framebuffer now */
   fgl_vpcut_invalidate(ctx);   /* a flush, then a quad (probe p_vpcut_state) */
   fgl_query_flushed(ctx);  /* the oracle's copy reads its buffer: a flush */
   if (blit_copy_pixels(ctx, srcx, srcy, width, height, dstx, dsty, type))
      return;
   /* the source: the read framebuffer (a separate read drawable's) */
   const struct fgl_framebuffer *rfb = fgl_read_fb(ctx);

   /* the source, y-down, into a width x height texture whose row 0 is
    * the top row; the part outside the framebuffer stays uninitialised
    * in the oracle (zero here).  A source wholly outside draws nothing. */
   const long long ry64 = (long long)rfb->Height - srcy - height;
   if (ry64 < INT_MIN || ry64 > INT_MAX)
      return;
   int rx = srcx, ry = (int)ry64, rw = width, rh = height;
   int skip_px = 0, skip_rows = 0;
   if (!clip_readpixels(rfb, &rx, &ry, &rw, &rh, &skip_px, &skip_rows))
      return;
   if (width > FGL_MAX_TEXTURE_SIZE || height > FGL_MAX_TEXTURE_SIZE) {
      /* larger than any texture: only the part of the source inside the
       * window is defined, and only that is copied (to where it goes),
       * without a texture of the whole source */
      const long long cx = (long long)srcx < 0 ? 0 : srcx;
      const long long cy = (long long)srcy < 0 ? 0 : srcy;
      const long long dx = (long long)dstx + (cx - srcx), dy = (long long)dsty + (cy - srcy);
      if (dx <= INT_MAX && dy <= INT_MAX)
         copy_pixels(ctx, (int)cx, (int)cy, rw, rh, (int)dx, (int)dy, type);
      return;
   }
   const size_t n = (size_t)width * (size_t)height;
   float *t = NULL;
   uint8_t *s = NULL;
   /* glCopyPixels passes GL 1.5's three types only (GL_DEPTH_STENCIL and
    * the NV copy_depth_to_color types raise GL_INVALID_ENUM there) */
   const bool color = type == GL_COLOR;
   const bool depth = type == GL_DEPTH;
   const bool stencil = type == GL_STENCIL;
   const uint8_t *read_color = fgl_read_color(ctx);
   if (color || depth)
      t = fgl_calloc_gl(ctx, color ? 4 * n : n, sizeof(float));
   if (stencil)
      s = fgl_calloc_gl(ctx, n, 1);
   if ((!t && (color || depth)) || (!s && stencil)) {
      fgl_free(t);
      fgl_free(s);
      return;
   }
   for (int j = 0; j < rh; j++) {
      const size_t src = (size_t)(ry + j) * (size_t)rfb->Width + (size_t)rx;
      const size_t dst = (size_t)(skip_rows + j) * (size_t)width + (size_t)skip_px;
      if (color)
         copy_source_color_row(rfb, read_color, src, t + 4 * dst, rw);
      else if (depth)
         copy_source_depth_row(rfb, src, t + dst, rw);
      else
         copy_source_stencil_row(rfb, src, s + dst, rw);
   }

   struct r_pixel_image img = { .width = width, .height = height, .texels = t, .mask = s };
   struct t_pixel_quad q;
   /* the quad's colour is the current colour, which the depth and
    * stencil shaders pass on */
   fgl_flush_current(ctx);
   quad_init(&q, fb, ctx->Current.RasterPos[2], ctx->Current.Attrib[FGL_ATTR_COLOR0]);
   textured_quad(ctx, &q, dstx, dsty, width, height, true);
   struct r_state rs = ctx->_Raster;
   struct stencil_quad_objects qo;
   if (color) {
      img.kind = R_PIX_COLOR;
      color_transfer(ctx, &img);
      if (ctx->Color.DrawBuffer != GL_NONE)
         fgl_mark_color_defined(fb);
   } else if (stencil) {
      img.kind = R_PIX_STENCIL;
      stencil_quad_state(ctx, &rs, &qo);
   } else {
      img.kind = R_PIX_DEPTH;
      if (ctx->Color.DrawBuffer != GL_NONE)
         fgl_mark_color_defined(fb);
   }
   pixel_texcoords(ctx, &img, tex_varying(ctx), false);
   pixel_rect(ctx, &rs, &img, &q);
   fgl_free(t);
   fgl_free(s);
}

void GLAPIENTRY glCopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, CopyPixels, x, y, width, height, type);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   if (width < 0 || height < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   /* GL 1.5's three types (the oracle's GL_DEPTH_STENCIL and NV
    * copy_depth_to_color types are not GL 1.5's: README "Version and
    * honesty") */
   if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   fgl_update_state(ctx);
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   /* _mesa_source_buffer_exists, _mesa_dest_buffer_exists */
   const bool exists = fb && (type == GL_COLOR ? ctx->Pixel.ReadBuffer != GL_NONE
                              : type == GL_DEPTH ? fb->DepthBits > 0
                              : fb->StencilBits > 0);
   if (!exists) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (!ctx->Current.RasterPosValid || width == 0 || height == 0)
      return;
   if (ctx->RenderMode == GL_RENDER) {
      const int dx = (int)lroundf(ctx->Current.RasterPos[0]);
      const int dy = (int)lroundf(ctx->Current.RasterPos[1]);
      copy_pixels(ctx, x, y, width, height, dx, dy, type);
   } else if (ctx->RenderMode == GL_FEEDBACK) {
      fgl_flush_current(ctx);
      feedback_raster(ctx, GL_COPY_PIXEL_TOKEN);
   }
}
