/*
 * The OSMesa-compatible context API.
 *
 * Behaviour follows Mesa 22.3's gallium OSMesa frontend (osmesa.c): the
 * context renders into its own buffers, which glFlush/glFinish copy into
 * the application's buffer (bottom row first unless OSMESA_Y_UP is
 * false); OSMesaGetDepthBuffer returns a bottom-row-first copy of the depth
 * buffer taken at the first call and refreshed at every glFlush/glFinish.
 * Buffer formats are chosen as Mesa does: depth and stencil give Z24S8,
 * stencil alone S8, 24 or more depth bits Z24X8, 16..23 Z16; any accumBits
 * gives a 16-bit-per-channel accumulation buffer (main/accum.c).
 *
 * GL_UNSIGNED_SHORT and GL_FLOAT buffers of OSMESA_RGBA, BGRA, ARGB and
 * RGB are rendered as the oracle renders them, into a wide target
 * (R16G16B16A16_UNORM, R32G32B32A32_FLOAT: fb.Wide, r_fb_state.wide)
 * whose channels glFlush copies as they are, in RGBA (RGB) order whatever
 * the OSMesa format [S: gallium/frontends/osmesa/osmesa.c:
 * osmesa_choose_format, osmesa_read_buffer] (ORACLE-NOTES.md "OSMesa
 * contexts and buffers").
 *
 * Differences from the oracle, on purpose: OSMESA_BGR works with
 * GL_UNSIGNED_BYTE (Mesa has no gallium format for it and fails
 * OSMesaMakeCurrent); OSMESA_RGB_565 buffers are refused (OSMesaMakeCurrent
 * returns GL_FALSE); NULL arguments never crash.
 */
/* the GL 1.4 entry points fixgl exports (glWindowPos) are declared by
 * <GL/glext.h> only with GL_GLEXT_PROTOTYPES */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include "context.h"
#include "main/groups.h"
#include "fgl_alloc.h"
#include "raster/r_rows.h"

#define OSMESA_MAX_SIZE 16384

struct osmesa_context;

/* The OSMesa context current on this thread (its GL context is the one
 * fgl_get_current() returns). */
static _Thread_local struct osmesa_context *current_os;

struct osmesa_context {
   struct fgl_context *gl;
   GLenum format;
   enum r_zs_format zs_format;
   int depth_bits, stencil_bits;
   int accum_bits;            /* 16 when accumBits > 0, else 0 */

   /* the bound image and the internal buffers that render for it */
   struct fgl_framebuffer fb;
   bool has_buffer;
   void *user_buffer;
   GLenum type;
   GLint row_length;
   GLboolean y_up;

   /* OSMesaGetDepthBuffer's bottom-row-first snapshot */
   void *zs_copy;
   void *depth_mem;   /* the allocation fb.Depth lies in */
   void *color_mem;   /* the allocation fb.Color lies in */
   int zs_bpv;
};

static int channels(GLenum format)
{
   return (format == OSMESA_RGB || format == OSMESA_BGR) ? 3 : 4;
}

/* bytes of a pixel of the application's buffer */
static int bytes_per_pixel(GLenum format, GLenum type)
{
   const int size = type == GL_FLOAT ? 4 : type == GL_UNSIGNED_SHORT ? 2 : 1;
   return channels(format) * size;
}

/* The oracle's render target for format/type (osmesa_choose_format):
 * GL_UNSIGNED_SHORT and GL_FLOAT make a wide one for the RGBA family and
 * RGB; false for what it refuses. */
static bool choose_type(GLenum format, GLenum type, enum r_wide_format *wide)
{
   *wide = R_WIDE_NONE;
   switch (format) {
   case OSMESA_RGBA: case OSMESA_BGRA: case OSMESA_ARGB: case OSMESA_RGB:
      if (type == GL_UNSIGNED_SHORT)
         *wide = R_WIDE_UNORM16;
      else if (type == GL_FLOAT)
         *wide = R_WIDE_FLOAT;
      return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT || type == GL_FLOAT;
   case OSMESA_BGR:
      return type == GL_UNSIGNED_BYTE;
   default:
      return false;
   }
}

/* One row of the wide target into the application's buffer: the
 * channels as they are (nc of each pixel's four), 2 or 4 bytes each. */
static void copy_row_wide(const struct fgl_framebuffer *fb, int nc, uint8_t *restrict dst,
                          size_t first, int w)
{
   const size_t size = fb->WideFormat == R_WIDE_FLOAT ? 4 : 2;
   const uint8_t *src = (const uint8_t *)fb->Wide + first * 4 * size;
   if (nc == 4) {
      memcpy(dst, src, (size_t)w * 4 * size);
      return;
   }
   for (int x = 0; x < w; x++)
      memcpy(dst + (size_t)x * 3 * size, src + (size_t)x * 4 * size, 3 * size);
}

static int zs_bytes_per_value(enum r_zs_format f)
{
   switch (f) {
   case R_ZS_Z16:   return 2;
   case R_ZS_Z24X8:
   case R_ZS_Z24S8:
   case R_ZS_Z32:   return 4;
   case R_ZS_S8:    return 1;
   default:         return 0;
   }
}

/* Copy the internal zs buffer, flipping it to bottom-row-first. */
static void snapshot_zs(struct osmesa_context *c)
{
   const size_t row = (size_t)c->fb.Width * (size_t)c->zs_bpv;
   const uint8_t *src = c->fb.Depth ? c->fb.Depth : (void *)c->fb.Stencil;
   for (int y = 0; y < c->fb.Height; y++)
      memcpy((uint8_t *)c->zs_copy + (size_t)(c->fb.Height - 1 - y) * row,
             src + (size_t)y * row, row);
}

/* One row of the internal RGBA8 image into the user's format, the format
 * chosen once per row. */
static void copy_row(GLenum format, uint8_t *restrict dst, const uint8_t *restrict src, int w)
{
   switch (format) {
   case OSMESA_RGBA:
      r_rows_copy(dst, src, (size_t)w * 4);
      return;
   case OSMESA_BGRA:
      for (int x = 0; x < w; x++) {
         dst[4 * x + 0] = src[4 * x + 2]; dst[4 * x + 1] = src[4 * x + 1];
         dst[4 * x + 2] = src[4 * x + 0]; dst[4 * x + 3] = src[4 * x + 3];
      }
      return;
   case OSMESA_ARGB:
      for (int x = 0; x < w; x++) {
         dst[4 * x + 0] = src[4 * x + 3]; dst[4 * x + 1] = src[4 * x + 0];
         dst[4 * x + 2] = src[4 * x + 1]; dst[4 * x + 3] = src[4 * x + 2];
      }
      return;
   case OSMESA_RGB:
      for (int x = 0; x < w; x++) {
         dst[3 * x + 0] = src[4 * x + 0];
         dst[3 * x + 1] = src[4 * x + 1];
         dst[3 * x + 2] = src[4 * x + 2];
      }
      return;
   default: /* BGR */
      for (int x = 0; x < w; x++) {
         dst[3 * x + 0] = src[4 * x + 2];
         dst[3 * x + 1] = src[4 * x + 1];
         dst[3 * x + 2] = src[4 * x + 0];
      }
      return;
   }
}

/* glFlush/glFinish: copy the image into the application's buffer and
 * refresh the depth snapshot, when the colour buffer was bound to a draw
 * or clear since the last time (st_manager_flush_frontbuffer's
 * rb->defined): after drawing only under glDrawBuffer(GL_NONE) neither
 * happens, as in the oracle (api/draw_buffer_render).  The copy is done by
 * rectangles (flush_front_rect), which the scene's tiles call each for
 * itself after drawing it (scene.c), then flush_front_end; flush_front does
 * all of it at once. */
static struct osmesa_context *osmesa_of(struct fgl_framebuffer *fb)
{
   return (struct osmesa_context *)((char *)fb - offsetof(struct osmesa_context, fb));
}

static void flush_front_lazy_rect(struct fgl_framebuffer *fb, int rx0, int ry0, int rx1, int ry1);

/* whether [x0,x1) x [y0,y1) lies inside one 64x64 tile (a scene's) */
static bool one_tile(int x0, int y0, int x1, int y1)
{
   return x0 < x1 && y0 < y1 && x0 / R_TILE_SIZE == (x1 - 1) / R_TILE_SIZE &&
          y0 / R_TILE_SIZE == (y1 - 1) / R_TILE_SIZE;
}

static void flush_front_rect(struct fgl_framebuffer *fb, int x0, int y0, int x1, int y1)
{
   struct osmesa_context *c = osmesa_of(fb);
   if (fb->Lazy.pending & FGL_LAZY_COLOR) {
      /* a rectangle inside one tile (a scene's tile, scene.c) that holds
       * no pending clear is copied as below, without looking for runs of
       * pending tiles row by row */
      const int tx = x0 / R_TILE_SIZE, ty = y0 / R_TILE_SIZE;
      if (!one_tile(x0, y0, x1, y1) ||
          (fb->Lazy.tiles[(size_t)ty * (size_t)fb->Lazy.tiles_x + (size_t)tx] & FGL_LAZY_COLOR)) {
         flush_front_lazy_rect(fb, x0, y0, x1, y1);
         return;
      }
   }
   const int bpp = bytes_per_pixel(c->format, c->type);
   const size_t stride = (size_t)bpp * (size_t)(c->row_length > 0 ? c->row_length : fb->Width);
   if (fb->Wide) {
      for (int y = y0; y < y1; y++) {
         const int dst_row = c->y_up ? fb->Height - 1 - y : y;
         copy_row_wide(fb, channels(c->format),
                       (uint8_t *)c->user_buffer + (size_t)dst_row * stride + (size_t)x0 * (size_t)bpp,
                       (size_t)y * (size_t)fb->Width + (size_t)x0, x1 - x0);
      }
      return;
   }
   for (int y = y0; y < y1; y++) {
      const uint8_t *src = fb->Color + ((size_t)y * (size_t)fb->Width + (size_t)x0) * 4;
      const int dst_row = c->y_up ? fb->Height - 1 - y : y;
      uint8_t *dst = (uint8_t *)c->user_buffer + (size_t)dst_row * stride + (size_t)x0 * (size_t)bpp;
      copy_row(c->format, dst, src, x1 - x0);
   }
}

static void flush_front_end(struct fgl_framebuffer *fb)
{
   struct osmesa_context *c = osmesa_of(fb);
   if (c->zs_copy) {
      fgl_lazy_resolve(fb, FGL_LAZY_ZS);
      snapshot_zs(c);
   }
}

/* flush_front_rect while some tiles still hold a lazy clear (scene.c):
 * those tiles' pixels are the clear colour, copied into the application's
 * buffer from a row of it, the context's buffer left as it is. */
static void flush_front_lazy_rect(struct fgl_framebuffer *fb, int rx0, int ry0, int rx1, int ry1)
{
   struct osmesa_context *c = osmesa_of(fb);
   const struct r_lazy_clear *lz = &fb->Lazy;
   const int bpp = bytes_per_pixel(c->format, GL_UNSIGNED_BYTE);   /* never wide */
   const size_t stride = (size_t)bpp * (size_t)(c->row_length > 0 ? c->row_length : fb->Width);
   uint8_t fill[4 * R_TILE_SIZE];
   for (int i = 0; i < R_TILE_SIZE; i++)
      memcpy(fill + 4 * i, lz->rgba, 4);
   /* a 4-byte format: the clear colour's pixel in it, stored along the run */
   uint32_t px = 0;
   if (bpp == 4)
      copy_row(c->format, (uint8_t *)&px, fill, 1);
   /* a rectangle inside one pending tile (a scene's tile): its rows are
    * runs of the clear colour */
   if (bpp == 4 && one_tile(rx0, ry0, rx1, ry1) && (stride & 3u) == 0 &&
       ((uintptr_t)c->user_buffer & 3u) == 0 &&
       (lz->tiles[(size_t)(ry0 / R_TILE_SIZE) * (size_t)lz->tiles_x + (size_t)(rx0 / R_TILE_SIZE)] &
        FGL_LAZY_COLOR)) {
      for (int y = ry0; y < ry1; y++) {
         const int dst_row = c->y_up ? fb->Height - 1 - y : y;
         uint8_t *d = (uint8_t *)c->user_buffer + (size_t)dst_row * stride + (size_t)rx0 * 4u;
         r_rows_fill32(d, px, (size_t)(rx1 - rx0));
      }
      return;
   }
   const int tx0 = rx0 / R_TILE_SIZE, tx1 = (rx1 + R_TILE_SIZE - 1) / R_TILE_SIZE;
   for (int ty = ry0 / R_TILE_SIZE; ty * R_TILE_SIZE < ry1; ty++) {
      const uint8_t *tiles = lz->tiles + (size_t)ty * (size_t)lz->tiles_x;
      const int y0 = ty * R_TILE_SIZE > ry0 ? ty * R_TILE_SIZE : ry0;
      const int y1 = (ty + 1) * R_TILE_SIZE < ry1 ? (ty + 1) * R_TILE_SIZE : ry1;
      for (int y = y0; y < y1; y++) {
         const int dst_row = c->y_up ? fb->Height - 1 - y : y;
         uint8_t *dst = (uint8_t *)c->user_buffer + (size_t)dst_row * stride;
         /* runs of tiles of one kind */
         for (int tx = tx0; tx < tx1;) {
            const bool lazy = (tiles[tx] & FGL_LAZY_COLOR) != 0;
            int te = tx + 1;
            while (te < tx1 && ((tiles[te] & FGL_LAZY_COLOR) != 0) == lazy)
               te++;
            const int x0 = tx * R_TILE_SIZE > rx0 ? tx * R_TILE_SIZE : rx0;
            const int x1 = te * R_TILE_SIZE < rx1 ? te * R_TILE_SIZE : rx1;
            uint8_t *d = dst + (size_t)x0 * (size_t)bpp;
            if (lazy && bpp == 4 && ((uintptr_t)d & 3u) == 0) {
               r_rows_fill32(d, px, (size_t)(x1 - x0));
            } else if (lazy) {
               for (int x = x0; x < x1; x += R_TILE_SIZE)
                  copy_row(c->format, dst + (size_t)x * (size_t)bpp, fill,
                           x1 - x < R_TILE_SIZE ? x1 - x : R_TILE_SIZE);
            } else {
               copy_row(c->format, dst + (size_t)x0 * (size_t)bpp,
                        fb->Color + ((size_t)y * (size_t)fb->Width + (size_t)x0) * 4, x1 - x0);
            }
            tx = te;
         }
      }
   }
}

static void flush_front(struct fgl_framebuffer *fb)
{
   if (!fb->ColorDefined)
      return;
   fb->ColorDefined = false;
   flush_front_rect(fb, 0, 0, fb->Width, fb->Height);
   flush_front_end(fb);
}

GLAPI OSMesaContext GLAPIENTRY
OSMesaCreateContext(GLenum format, OSMesaContext sharelist)
{
   return OSMesaCreateContextExt(format, 24, 8, 0, sharelist);
}

GLAPI OSMesaContext GLAPIENTRY
OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits,
                       GLint accumBits, OSMesaContext sharelist)
{
   const int attribs[] = {
      OSMESA_FORMAT, (int)format,
      OSMESA_DEPTH_BITS, depthBits,
      OSMESA_STENCIL_BITS, stencilBits,
      OSMESA_ACCUM_BITS, accumBits,
      0,
   };
   return OSMesaCreateContextAttribs(attribs, sharelist);
}

GLAPI OSMesaContext GLAPIENTRY
OSMesaCreateContextAttribs(const int *attribList, OSMesaContext sharelist)
{
   GLenum format = GL_RGBA;
   int depth = 0, stencil = 0, accum = 0;
   int profile = OSMESA_COMPAT_PROFILE, major = 1, minor = 0;

   for (int i = 0; attribList && attribList[i]; i += 2) {
      const int value = attribList[i + 1];
      switch (attribList[i]) {
      case OSMESA_FORMAT:
         switch (value) {
         case OSMESA_COLOR_INDEX: case OSMESA_RGBA: case OSMESA_BGRA:
         case OSMESA_ARGB: case OSMESA_RGB: case OSMESA_BGR: case OSMESA_RGB_565:
            format = (GLenum)value;
            break;
         default:
            return NULL;
         }
         break;
      case OSMESA_DEPTH_BITS:
         if (value < 0)
            return NULL;
         depth = value;
         break;
      case OSMESA_STENCIL_BITS:
         if (value < 0)
            return NULL;
         stencil = value;
         break;
      case OSMESA_ACCUM_BITS:
         if (value < 0)
            return NULL;
         accum = value;
         break;
      case OSMESA_PROFILE:
         if (value != OSMESA_CORE_PROFILE && value != OSMESA_COMPAT_PROFILE)
            return NULL;
         profile = value;
         break;
      case OSMESA_CONTEXT_MAJOR_VERSION:
         if (value < 1)
            return NULL;
         major = value;
         break;
      case OSMESA_CONTEXT_MINOR_VERSION:
         if (value < 0)
            return NULL;
         minor = value;
         break;
      default:
         fprintf(stderr, "Bad attribute in OSMesaCreateContextAttribs()\n");
         return NULL;
      }
   }
   /* What the context cannot provide gives NULL, as in Mesa, whose
    * st_api_create_context compares major * 10 + minor (the last value
    * of each attribute) with the version it implements: fixgl has no
    * core profile and implements at most GL 1.5 (ORACLE-NOTES.md "OSMesa
    * contexts and buffers") */
   if (profile == OSMESA_CORE_PROFILE || (long long)major * 10 + minor > 15)
      return NULL;

   struct osmesa_context *c = fgl_calloc(1, sizeof(*c));
   if (!c)
      return NULL;
   /* display lists, texture and buffer objects are shared with
    * sharelist's context */
   c->gl = fgl_context_create(sharelist ? sharelist->gl : NULL);
   if (!c->gl) {
      fgl_free(c);
      return NULL;
   }
   c->format = format;
   c->y_up = GL_TRUE;
   if (depth > 0 && stencil > 0) {
      c->zs_format = R_ZS_Z24S8; c->depth_bits = 24; c->stencil_bits = 8;
   } else if (stencil > 0) {
      c->zs_format = R_ZS_S8; c->stencil_bits = 8;
   } else if (depth >= 24) {
      c->zs_format = R_ZS_Z24X8; c->depth_bits = 24;
   } else if (depth >= 16) {
      c->zs_format = R_ZS_Z16; c->depth_bits = 16;
   }
   c->zs_bpv = zs_bytes_per_value(c->zs_format);
   /* any accumBits > 0 gives PIPE_FORMAT_R16G16B16A16_SNORM
    * [S: gallium/frontends/osmesa/osmesa.c:OSMesaCreateContextAttribs] */
   c->accum_bits = accum > 0 ? 16 : 0;
   return c;
}

static void free_buffers(struct osmesa_context *c)
{
   fgl_lazy_fini(&c->fb);
   fgl_free(c->color_mem);
   c->color_mem = NULL;
   fgl_free(c->fb.Wide);
   c->fb.Wide = NULL;
   fgl_free(c->depth_mem);
   c->depth_mem = NULL;
   fgl_free(c->fb.Stencil);
   fgl_free(c->fb.Accum);
   fgl_free(c->zs_copy);
   c->fb.Accum = NULL;
   c->fb.Color = NULL;
   c->fb.Depth = NULL;
   c->fb.Stencil = NULL;
   c->zs_copy = NULL;
   c->has_buffer = false;
}

GLAPI void GLAPIENTRY
OSMesaDestroyContext(OSMesaContext c)
{
   if (!c)
      return;
   if (fgl_get_current() == c->gl) {
      fgl_set_current(NULL);
      current_os = NULL;
   }
   fgl_context_destroy(c->gl);
   free_buffers(c);
   fgl_free(c);
}

/* A zeroed buffer of `size` bytes for the context's colour or depth, in
 * an allocation returned in *mem (NULL when out of memory): 64-byte
 * aligned, so that the rows of two 64-pixel tiles, which different
 * threads draw, share no cache line; from 2 MB up, 2 MB aligned and in
 * 2 MB pages where the kernel grants them (transparent huge pages in
 * madvise mode), whose few TLB entries cover what a frame touches: with
 * 4 KB pages the tiles' clears and copies, whose rows are 64 pages apart,
 * missed the TLB row by row (gears: 16% of a frame on one thread, 9% on
 * two).  The allocation is calloc's, so untouched pages cost nothing. */
static uint8_t *alloc_buffer(void **mem, size_t size)
{
   const size_t huge = (size_t)2 << 20;
   const size_t align = size >= huge ? huge : 64;
   /* a large buffer is rounded up to whole 2 MB pages: its last part,
    * short of a page, was in 4 KB pages before, and its tiles' rows
    * missed the TLB again (1024x768: the bottom 256 rows of both the
    * colour and the depth buffer); the cost, at most 2 MB a buffer of
    * memory that the huge page holds past the buffer's end */
   const size_t span = align == huge ? (size + huge - 1) & ~(huge - 1) : size;
   *mem = fgl_calloc(span + align, 1);
   if (!*mem)
      return NULL;
   uint8_t *p = (uint8_t *)(((uintptr_t)*mem + align - 1) & ~(uintptr_t)(align - 1));
#ifdef MADV_HUGEPAGE
   if (align == huge)
      (void)madvise(p, span, MADV_HUGEPAGE);
#endif
   return p;
}

/* (Re)allocate the internal buffers for a width x height image, a wide
 * colour target for `wide`. */
static bool alloc_buffers(struct osmesa_context *c, int width, int height,
                          enum r_wide_format wide)
{
   const size_t n = (size_t)width * (size_t)height;
   free_buffers(c);
   struct fgl_framebuffer *fb = &c->fb;
   fb->Width = width;
   fb->Height = height;
   fb->DepthBits = c->depth_bits;
   fb->StencilBits = c->stencil_bits;
   fb->AlphaBits = channels(c->format) == 4 ? (wide == R_WIDE_UNORM16 ? 16 : wide ? 32 : 8) : 0;
   fb->ColorR8G8B8A8 = c->format == OSMESA_RGBA;
   fb->ZSFormat = c->zs_format;
   fb->FlushFront = flush_front;
   fb->FlushFrontRect = flush_front_rect;
   fb->FlushFrontEnd = flush_front_end;
   fb->AccumBits = c->accum_bits;
   fb->Color = alloc_buffer(&c->color_mem, n * 4);
   fb->WideFormat = wide;
   if (wide)
      fb->Wide = fgl_calloc(n, wide == R_WIDE_FLOAT ? 4 * sizeof(float) : 4 * sizeof(uint16_t));
   if (c->zs_format == R_ZS_S8)
      fb->Stencil = fgl_calloc(n, 1);
   else if (c->zs_format != R_ZS_NONE) {
      /* the depth buffer starts 2112 bytes past a page boundary, so that
       * a pixel's depth and colour never share their address bits 11:0:
       * the block kernels load one while storing the other, which the CPU
       * would otherwise check against each other as if they aliased
       * (4K aliasing; 3-4% of lit200's frame) */
      uint8_t *d = alloc_buffer(&c->depth_mem, n * (size_t)c->zs_bpv + 4096);
      fb->Depth = d ? d + 2048 + 64 : NULL;
   }
   if (c->accum_bits > 0)
      fb->Accum = fgl_calloc(n, 4 * sizeof(int16_t));
   if (!fb->Color || (wide && !fb->Wide) || (c->zs_format != R_ZS_NONE && !fb->Depth && !fb->Stencil) ||
       (c->accum_bits > 0 && !fb->Accum)) {
      free_buffers(c);
      return false;
   }
   c->has_buffer = true;
   return true;
}

GLAPI GLboolean GLAPIENTRY
OSMesaMakeCurrent(OSMesaContext c, void *buffer, GLenum type,
                  GLsizei width, GLsizei height)
{
   struct fgl_context *cur = fgl_get_current();

   if (!c && !buffer) {
      if (cur)
         fgl_flush_front(cur);
      fgl_set_current(NULL);
      current_os = NULL;
      return GL_TRUE;
   }
   if (!c || !buffer || width < 1 || height < 1 ||
       width > OSMESA_MAX_SIZE || height > OSMESA_MAX_SIZE)
      return GL_FALSE;
   enum r_wide_format wide;
   if (!choose_type(c->format, type, &wide)) {
      fprintf(stderr, "OSMesaMakeCurrent(unsupported format/type)\n");
      return GL_FALSE;
   }

   /* like _mesa_make_current, finish the work of the previous binding */
   if (cur && (cur != c->gl || c->user_buffer != buffer))
      fgl_flush_front(cur);

   if (!c->has_buffer || c->fb.Width != width || c->fb.Height != height ||
       c->fb.WideFormat != wide) {
      /* what c's scene holds is drawn before its buffers go */
      fgl_scene_flush(c->gl);
      if (!alloc_buffers(c, width, height, wide))
         return GL_FALSE;
      /* Mesa destroys the osmesa_buffer of another size or colour format
       * and makes a new
       * window framebuffer: the read buffer, which lives there, is GL_FRONT
       * again; the draw buffer is context state and carries over
       * [S: gallium/frontends/osmesa/osmesa.c:OSMesaMakeCurrent;
       * main/framebuffer.c:_mesa_initialize_window_framebuffer;
       * main/context.c:_mesa_make_current, _mesa_update_draw_buffers] */
      fgl_new_window_framebuffer(c->gl);
   }
   c->user_buffer = buffer;
   c->type = type;
   fgl_context_bind_framebuffer(c->gl, &c->fb);
   fgl_set_current(c->gl);
   current_os = c;
   return GL_TRUE;
}

static struct osmesa_context *current_osmesa(void)
{
   if (current_os && fgl_get_current() != current_os->gl)
      current_os = NULL;
   return current_os;
}

GLAPI OSMesaContext GLAPIENTRY
OSMesaGetCurrentContext(void)
{
   return current_osmesa();
}

GLAPI void GLAPIENTRY
OSMesaPixelStore(GLint pname, GLint value)
{
   struct osmesa_context *c = current_osmesa();
   if (!c)
      return;
   switch (pname) {
   case OSMESA_ROW_LENGTH:
      c->row_length = value;
      break;
   case OSMESA_Y_UP:
      c->y_up = value ? GL_TRUE : GL_FALSE;
      break;
   default:
      fprintf(stderr, "Invalid pname in OSMesaPixelStore()\n");
      break;
   }
}

GLAPI void GLAPIENTRY
OSMesaGetIntegerv(GLint pname, GLint *value)
{
   struct osmesa_context *c = current_osmesa();
   if (!value)
      return;
   switch (pname) {
   case OSMESA_WIDTH:
      *value = c && c->has_buffer ? c->fb.Width : 0;
      return;
   case OSMESA_HEIGHT:
      *value = c && c->has_buffer ? c->fb.Height : 0;
      return;
   case OSMESA_FORMAT:
      if (c)
         *value = (GLint)c->format;
      return;
   case OSMESA_TYPE:
      if (c)
         *value = (GLint)c->type;
      return;
   case OSMESA_ROW_LENGTH:
      if (c)
         *value = c->row_length;
      return;
   case OSMESA_Y_UP:
      if (c)
         *value = c->y_up;
      return;
   case OSMESA_MAX_WIDTH:
   case OSMESA_MAX_HEIGHT:
      *value = OSMESA_MAX_SIZE;
      return;
   default:
      fprintf(stderr, "Invalid pname in OSMesaGetIntegerv()\n");
      return;
   }
}

GLAPI GLboolean GLAPIENTRY
OSMesaGetDepthBuffer(OSMesaContext c, GLint *width, GLint *height,
                     GLint *bytesPerValue, void **buffer)
{
   GLint w = 0, h = 0, bpv = 0;
   void *buf = NULL;
   GLboolean ok = GL_FALSE;

   if (c && c->has_buffer && c->zs_format != R_ZS_NONE && c->zs_format != R_ZS_S8) {
      w = c->fb.Width;
      h = c->fb.Height;
      bpv = c->zs_bpv;
      if (!c->zs_copy) {
         c->zs_copy = fgl_calloc((size_t)w * (size_t)h, (size_t)bpv);
         if (c->zs_copy) {
            fgl_scene_flush(c->gl);   /* the depth drawn so far */
            snapshot_zs(c);
         }
      }
      buf = c->zs_copy;
      ok = buf ? GL_TRUE : GL_FALSE;
   }
   if (width) *width = ok ? w : 0;
   if (height) *height = ok ? h : 0;
   if (bytesPerValue) *bytesPerValue = ok ? bpv : 0;
   if (buffer) *buffer = buf;
   return ok;
}

GLAPI GLboolean GLAPIENTRY
OSMesaGetColorBuffer(OSMesaContext c, GLint *width, GLint *height,
                     GLint *format, void **buffer)
{
   const bool ok = c && c->has_buffer;
   if (width) *width = ok ? c->fb.Width : 0;
   if (height) *height = ok ? c->fb.Height : 0;
   if (format) *format = ok ? (GLint)c->format : 0;
   if (buffer) *buffer = ok ? c->user_buffer : NULL;
   return ok ? GL_TRUE : GL_FALSE;
}

GLAPI void GLAPIENTRY
OSMesaColorClamp(GLboolean enable)
{
   /* Colours are always clamped for the 8-bit buffers fixgl supports. */
   (void)enable;
}

GLAPI void GLAPIENTRY
OSMesaPostprocess(OSMesaContext osmesa, const char *filter, unsigned enable_value)
{
   (void)osmesa;
   (void)enable_value;
   fprintf(stderr, "OSMesaPostprocess(%s): no post-processing filters in fixgl\n",
           filter ? filter : "(null)");
}

struct proc_entry {
   const char *name;
   OSMESAproc proc;
};

static const struct proc_entry procs[] = {
/* casting through void (*)(void), the generic function pointer type */
#define PROC(f) ((OSMESAproc)(void (*)(void))(f))
#define FGL_API(f) { #f, PROC(f) },
#include "main/api_list.h"
#undef FGL_API
   { "OSMesaColorClamp", PROC(OSMesaColorClamp) },
   { "OSMesaCreateContext", PROC(OSMesaCreateContext) },
   { "OSMesaCreateContextAttribs", PROC(OSMesaCreateContextAttribs) },
   { "OSMesaCreateContextExt", PROC(OSMesaCreateContextExt) },
   { "OSMesaDestroyContext", PROC(OSMesaDestroyContext) },
   { "OSMesaGetColorBuffer", PROC(OSMesaGetColorBuffer) },
   { "OSMesaGetCurrentContext", PROC(OSMesaGetCurrentContext) },
   { "OSMesaGetDepthBuffer", PROC(OSMesaGetDepthBuffer) },
   { "OSMesaGetIntegerv", PROC(OSMesaGetIntegerv) },
   { "OSMesaGetProcAddress", PROC(OSMesaGetProcAddress) },
   { "OSMesaMakeCurrent", PROC(OSMesaMakeCurrent) },
   { "OSMesaPixelStore", PROC(OSMesaPixelStore) },
   { "OSMesaPostprocess", PROC(OSMesaPostprocess) },
};

/* Entry points of the extensions fixgl advertises (glGetString,
 * main/get.c) under their extension names: the same functions, as Mesa's
 * glapi aliases them. */
static const struct proc_entry aliases[] = {
   { "glBlendColorEXT", PROC(glBlendColor) },
   { "glBlendEquationEXT", PROC(glBlendEquation) },
   { "glDrawRangeElementsEXT", PROC(glDrawRangeElements) },
};

/* A name fixgl does not implement gives NULL.  On purpose, this differs
 * from the oracle: Mesa's glapi hands out a new dispatch stub for any
 * unknown name starting with "gl" (_glapi_get_proc_address), which does
 * nothing when called; fixgl never hands out a function that silently
 * does nothing, so a program can test for what is really there
 * (api/getprocaddress records it as a documented difference). */
GLAPI OSMESAproc GLAPIENTRY
OSMesaGetProcAddress(const char *funcName)
{
   if (!funcName)
      return NULL;
   for (size_t i = 0; i < sizeof(procs) / sizeof(procs[0]); i++)
      if (strcmp(procs[i].name, funcName) == 0)
         return procs[i].proc;
   for (size_t i = 0; i < sizeof(aliases) / sizeof(aliases[0]); i++)
      if (strcmp(aliases[i].name, funcName) == 0)
         return aliases[i].proc;
   return NULL;
}
