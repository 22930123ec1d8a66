/*
 * Client images (see pixelformat.h): Mesa's main/image.c (addressing),
 * glformats.c (format/type checks), format_utils.c (_mesa_format_convert
 * and _mesa_swizzle_and_convert), util/format (the packed formats),
 * pack.c (indices, stencil, depth, luminance), pixeltransfer.c and
 * texstore.c / readpix.c / texgetimage.c (which path each call takes).
 *
 * The value paths matter for bit-exactness: Mesa converts between two
 * "array" formats (one type per channel: the non-packed GL types and the
 * 8_8_8_8 ones) directly, channel by channel (e.g. GL_UNSIGNED_SHORT ->
 * 8 bits as (x*255 + 32767) / 65535), while a packed type goes through
 * util/format's unpack/pack (bit rescaling), and any pixel transfer
 * operation sends the image through float RGBA first.
 */
#include "main/pixelformat.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "main/groups.h"
#include "fgl_alloc.h"

/* ------------------------------------------------------------------ */
/* Mesa's scalar conversions [S: util/format/format_utils.h]           */
/* ------------------------------------------------------------------ */

static uint64_t uint_max(unsigned bits)
{
   return bits >= 64 ? ~0ull : (1ull << bits) - 1;
}

static int64_t int_max(unsigned bits)
{
   return (int64_t)((1ull << (bits - 1)) - 1);
}

/* _mesa_i64roundevenf / _mesa_lroundevenf: lrintf (round to nearest
 * even; NaN and out-of-range values give LONG_MIN on x86-64, as cvtss2si
 * does, where a cast of rintf's result was undefined behaviour: clang
 * UBSan, found by the libFuzzer run in CI) */
static int64_t round_even(float x)
{
   return (int64_t)lrintf(x);
}

static float unorm_to_float(uint32_t x, unsigned src_bits)
{
   return (float)x * (1.0f / (float)uint_max(src_bits));
}

static float snorm_to_float(int32_t x, unsigned src_bits)
{
   if (x <= -int_max(src_bits))
      return -1.0f;
   return (float)x * (1.0f / (float)int_max(src_bits));
}

static uint32_t float_to_unorm(float x, unsigned dst_bits)
{
   if (x < 0.0f)
      return 0;
   else if (x > 1.0f)
      return (uint32_t)uint_max(dst_bits);
   /* the float product; the 64-bit result is truncated to 32 bits (1.0
    * as a 32-bit unorm gives 0 in the oracle) */
   return (uint32_t)round_even(x * (float)uint_max(dst_bits));
}

static int32_t float_to_snorm(float x, unsigned dst_bits)
{
   if (x < -1.0f)
      return (int32_t)-int_max(dst_bits);
   else if (x > 1.0f)
      return (int32_t)int_max(dst_bits);
   return (int32_t)round_even(x * (float)int_max(dst_bits));
}

/* EXTEND_NORMALIZED_INT */
static uint32_t extend_normalized(uint32_t x, unsigned src_bits, unsigned dst_bits)
{
   const uint32_t mul = (uint32_t)(int)(uint_max(dst_bits) / uint_max(src_bits));
   return x * mul + ((dst_bits % src_bits) ? x >> (src_bits - dst_bits % src_bits) : 0);
}

static uint32_t unorm_to_unorm(uint32_t x, unsigned src_bits, unsigned dst_bits)
{
   if (src_bits < dst_bits)
      return extend_normalized(x, src_bits, dst_bits);
   if (src_bits > dst_bits) {
      const uint32_t src_half = (1u << (src_bits - 1)) - 1;
      if (src_bits + dst_bits > 32)
         return (uint32_t)(((uint64_t)x * uint_max(dst_bits) + src_half) /
                           uint_max(src_bits));
      return (uint32_t)(((uint64_t)x * uint_max(dst_bits) + src_half) / uint_max(src_bits));
   }
   return x;
}

static uint32_t snorm_to_unorm(int32_t x, unsigned src_bits, unsigned dst_bits)
{
   return x < 0 ? 0 : unorm_to_unorm((uint32_t)x, src_bits - 1, dst_bits);
}

static int32_t unorm_to_snorm(uint32_t x, unsigned src_bits, unsigned dst_bits)
{
   return (int32_t)unorm_to_unorm(x, src_bits, dst_bits - 1);
}

/* macros.h CLAMPED_FLOAT_TO_UBYTE (the IEEE form) for a value in [0, 1] */
static uint8_t clamped_float_to_ubyte(float f)
{
   union { float f; uint32_t u; } t;
   t.f = f * (255.0f / 256.0f) + 32768.0f;
   return (uint8_t)t.u;
}

static float clampf(float x, float lo, float hi)
{
   return x < lo ? lo : x > hi ? hi : x;   /* CLAMP: NaN stays NaN */
}

/* ------------------------------------------------------------------ */
/* Formats and types                                                   */
/* ------------------------------------------------------------------ */

int fgl_format_components(GLenum format)
{
   switch (format) {
   case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA:
   case GL_LUMINANCE: case GL_INTENSITY: case GL_COLOR_INDEX:
   case GL_STENCIL_INDEX: case GL_DEPTH_COMPONENT:
   case GL_RED_INTEGER: case GL_GREEN_INTEGER: case GL_BLUE_INTEGER:
   case GL_ALPHA_INTEGER: case GL_LUMINANCE_INTEGER_EXT:
      return 1;
   case GL_LUMINANCE_ALPHA: case GL_DEPTH_STENCIL: case GL_RG: case GL_RG_INTEGER:
   case GL_LUMINANCE_ALPHA_INTEGER_EXT:
      return 2;
   case GL_RGB: case GL_BGR: case GL_RGB_INTEGER: case GL_BGR_INTEGER:
      return 3;
   case GL_RGBA: case GL_BGRA: case GL_ABGR_EXT: case GL_RGBA_INTEGER:
   case GL_BGRA_INTEGER:
      return 4;
   default:
      return 0;
   }
}

/* [S: image.c:_mesa_sizeof_packed_type] bytes of one element: a
 * component, or a whole pixel of a packed type; 0 if unknown */
static size_t type_size(GLenum type)
{
   switch (type) {
   case GL_UNSIGNED_BYTE: case GL_BYTE:
   case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV:
      return 1;
   case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_HALF_FLOAT: case 0x8D61: /* _OES */
   case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV:
   case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
   case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV:
      return 2;
   case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT:
   case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
   case GL_UNSIGNED_INT_10_10_10_2: case GL_UNSIGNED_INT_2_10_10_10_REV:
   case GL_UNSIGNED_INT_24_8: case GL_UNSIGNED_INT_10F_11F_11F_REV:
   case GL_UNSIGNED_INT_5_9_9_9_REV:
      return 4;
   case GL_FLOAT_32_UNSIGNED_INT_24_8_REV:
      return 8;
   default:
      return 0;
   }
}

static bool is_packed_type(GLenum type)
{
   switch (type) {
   case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_SHORT: case GL_SHORT:
   case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: case GL_HALF_FLOAT:
   case 0x8D61: /* GL_HALF_FLOAT_OES */ case GL_BITMAP:
      return false;
   default:
      return true;
   }
}

/* [S: image.c:_mesa_bytes_per_pixel] */
size_t fgl_pixel_bytes(GLenum format, GLenum type)
{
   const size_t n = (size_t)fgl_format_components(format);
   if (type == GL_BITMAP || n == 0)
      return 0;
   if (is_packed_type(type))
      return type_size(type);
   return n * type_size(type);
}

/* [S: image.c:_mesa_image_row_stride] rows padded to the alignment;
 * the row length replaces the width when > 0 */
size_t fgl_image_row_stride(const struct fgl_pixelstore *p, int width, GLenum format,
                            GLenum type)
{
   const size_t len = p->RowLength > 0 ? (size_t)p->RowLength : (size_t)width;
   size_t stride = type == GL_BITMAP ? (len + 7) / 8
                                     : fgl_pixel_bytes(format, type) * len;
   const size_t rem = stride % (size_t)p->Alignment;
   if (rem)
      stride += (size_t)p->Alignment - rem;
   return stride;
}

/* [S: image.c:_mesa_image_offset] skip pixels and rows, then (row, col) */
const uint8_t *fgl_image_address(const struct fgl_pixelstore *p, const void *pixels,
                                 int width, GLenum format, GLenum type, int row, int col)
{
   const size_t stride = fgl_image_row_stride(p, width, format, type);
   const size_t rows = (size_t)p->SkipRows + (size_t)row;
   if (type == GL_BITMAP)
      return (const uint8_t *)pixels + rows * stride +
             ((size_t)p->SkipPixels + (size_t)col) / 8;
   return (const uint8_t *)pixels + rows * stride +
          ((size_t)p->SkipPixels + (size_t)col) * fgl_pixel_bytes(format, type);
}

/* ------------------------------------------------------------------ */
/* Pixel layouts                                                       */
/* ------------------------------------------------------------------ */

#define SWZ_ZERO 4
#define SWZ_ONE 5

/* A client format/type as _mesa_format_from_format_and_type sees it:
 * an array format (every channel one `type`, `swz` giving for each of
 * R, G, B, A the channel or SWZ_ZERO/ONE) or a packed one (one word of
 * `bytes`, the bit field of R, G, B, A; bits 0 = absent). */
struct layout {
   bool packed;
   GLenum type;               /* array: the channel type */
   int nchan;
   uint8_t swz[4];
   size_t bytes;              /* bytes per pixel */
   int shift[4], bits[4];     /* packed, per RGBA */
};

/* [S: glformats.c:get_swizzle_from_gl_format] */
static bool format_swizzle(GLenum format, uint8_t swz[4])
{
   static const struct { GLenum f; uint8_t s[4]; } tab[] = {
      {GL_RED, {0, SWZ_ZERO, SWZ_ZERO, SWZ_ONE}},
      {GL_GREEN, {SWZ_ZERO, 0, SWZ_ZERO, SWZ_ONE}},
      {GL_BLUE, {SWZ_ZERO, SWZ_ZERO, 0, SWZ_ONE}},
      {GL_ALPHA, {SWZ_ZERO, SWZ_ZERO, SWZ_ZERO, 0}},
      {GL_RGB, {0, 1, 2, SWZ_ONE}},
      {GL_BGR, {2, 1, 0, SWZ_ONE}},
      {GL_RGBA, {0, 1, 2, 3}},
      {GL_BGRA, {2, 1, 0, 3}},
      {GL_ABGR_EXT, {3, 2, 1, 0}},
      {GL_LUMINANCE, {0, 0, 0, SWZ_ONE}},
      {GL_LUMINANCE_ALPHA, {0, 0, 0, 1}},
      {GL_INTENSITY, {0, 0, 0, 0}},
   };
   for (size_t i = 0; i < sizeof(tab) / sizeof(tab[0]); i++) {
      if (tab[i].f == format) {
         memcpy(swz, tab[i].s, 4);
         return true;
      }
   }
   return false;
}

/* position of R, G, B, A among the components of a packed type's
 * format (-1: absent) */
static bool packed_order(GLenum format, int pos[4])
{
   switch (format) {
   case GL_RGB: pos[0] = 0; pos[1] = 1; pos[2] = 2; pos[3] = -1; return true;
   case GL_RGBA: pos[0] = 0; pos[1] = 1; pos[2] = 2; pos[3] = 3; return true;
   case GL_BGRA: pos[0] = 2; pos[1] = 1; pos[2] = 0; pos[3] = 3; return true;
   case GL_ABGR_EXT: pos[0] = 3; pos[1] = 2; pos[2] = 1; pos[3] = 0; return true;
   default: return false;
   }
}

/* The layout of format/type; false if fixgl does not convert it
 * (GL_BITMAP, depth/stencil).  The callers convert GL 1.5's colour formats
 * and types only: GL_RG, the integer formats, GL_HALF_FLOAT and the packed
 * float types are GL_INVALID_ENUM in fgl_error_check_format_and_type. */
static bool get_layout(GLenum format, GLenum type, struct layout *l)
{
   memset(l, 0, sizeof(*l));
   l->type = type;
   switch (type) {
   case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_SHORT: case GL_SHORT:
   case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT:
      if (!format_swizzle(format, l->swz))
         return false;
      l->nchan = fgl_format_components(format);
      l->bytes = (size_t)l->nchan * type_size(type);
      return true;
   case GL_UNSIGNED_INT_8_8_8_8:
   case GL_UNSIGNED_INT_8_8_8_8_REV: {
      /* an array format of bytes [S: format_parser.py:is_array]: the
       * first component in the high byte, or (_REV) the low one */
      int pos[4];
      if (!packed_order(format, pos) || pos[3] < 0)
         return false;
      l->type = GL_UNSIGNED_BYTE;
      l->nchan = 4;
      l->bytes = 4;
      for (int c = 0; c < 4; c++)
         l->swz[c] = (uint8_t)(type == GL_UNSIGNED_INT_8_8_8_8 ? 3 - pos[c] : pos[c]);
      return true;
   }
   default:
      break;
   }
   static const struct { GLenum type; int n, bytes; int bits[4]; bool rev; } packed[] = {
      {GL_UNSIGNED_BYTE_3_3_2, 3, 1, {3, 3, 2}, false},
      {GL_UNSIGNED_BYTE_2_3_3_REV, 3, 1, {3, 3, 2}, true},
      {GL_UNSIGNED_SHORT_5_6_5, 3, 2, {5, 6, 5}, false},
      {GL_UNSIGNED_SHORT_5_6_5_REV, 3, 2, {5, 6, 5}, true},
      {GL_UNSIGNED_SHORT_4_4_4_4, 4, 2, {4, 4, 4, 4}, false},
      {GL_UNSIGNED_SHORT_4_4_4_4_REV, 4, 2, {4, 4, 4, 4}, true},
      {GL_UNSIGNED_SHORT_5_5_5_1, 4, 2, {5, 5, 5, 1}, false},
      {GL_UNSIGNED_SHORT_1_5_5_5_REV, 4, 2, {5, 5, 5, 1}, true},
      {GL_UNSIGNED_INT_10_10_10_2, 4, 4, {10, 10, 10, 2}, false},
      {GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4, {10, 10, 10, 2}, true},
   };
   for (size_t i = 0; i < sizeof(packed) / sizeof(packed[0]); i++) {
      if (packed[i].type != type)
         continue;
      int pos[4];
      if (!packed_order(format, pos) || (packed[i].n == 4) != (pos[3] >= 0))
         return false;
      /* component k's shift: the GL layout puts the first component in
       * the high bits, or (_REV) in the low ones */
      int shift[4], s = 0;
      for (int k = 0; k < packed[i].n; k++) {
         const int kk = packed[i].rev ? k : packed[i].n - 1 - k;
         shift[kk] = s;
         s += packed[i].bits[kk];
      }
      l->packed = true;
      l->bytes = (size_t)packed[i].bytes;
      for (int c = 0; c < 4; c++) {
         if (pos[c] < 0)
            continue;
         l->shift[c] = shift[pos[c]];
         l->bits[c] = packed[i].bits[pos[c]];
      }
      return true;
   }
   return false;
}

static uint32_t load_word(const uint8_t *src, size_t bytes)
{
   if (bytes == 1)
      return src[0];
   if (bytes == 2) {
      uint16_t v;
      memcpy(&v, src, 2);
      return v;
   }
   uint32_t v;
   memcpy(&v, src, 4);
   return v;
}

static void store_word(uint8_t *dst, size_t bytes, uint32_t v)
{
   if (bytes == 1) {
      dst[0] = (uint8_t)v;
   } else if (bytes == 2) {
      const uint16_t s = (uint16_t)v;
      memcpy(dst, &s, 2);
   } else {
      memcpy(dst, &v, 4);
   }
}

/* [S: image.c:_mesa_swap_bytes_2d_image] one row of n pixels in place */
static void swap_row(const struct layout *l, GLenum type, uint8_t *row, size_t n)
{
   const size_t sz = type_size(type);
   if (sz != 2 && sz != 4)
      return;
   const size_t elems = n * l->bytes / sz;
   for (size_t i = 0; i < elems; i++) {
      uint8_t *e = row + i * sz;
      for (size_t b = 0; b < sz / 2; b++) {
         const uint8_t t = e[b];
         e[b] = e[sz - 1 - b];
         e[sz - 1 - b] = t;
      }
   }
}

/* channel c of an array pixel as its raw value */
static void load_channel(GLenum type, const uint8_t *px, int c, int64_t *iv, float *fv)
{
   switch (type) {
   case GL_UNSIGNED_BYTE: *iv = px[c]; break;
   case GL_BYTE: *iv = (int8_t)px[c]; break;
   case GL_UNSIGNED_SHORT: { uint16_t v; memcpy(&v, px + 2 * c, 2); *iv = v; break; }
   case GL_SHORT: { int16_t v; memcpy(&v, px + 2 * c, 2); *iv = v; break; }
   case GL_UNSIGNED_INT: { uint32_t v; memcpy(&v, px + 4 * c, 4); *iv = v; break; }
   case GL_INT: { int32_t v; memcpy(&v, px + 4 * c, 4); *iv = v; break; }
   case GL_FLOAT: memcpy(fv, px + 4 * c, 4); break;
   default: break;
   }
}

/* [S: format_utils.c:convert_ubyte] a normalized channel to 8 bits */
static uint8_t channel_to_ubyte(GLenum type, const uint8_t *px, int c)
{
   int64_t i = 0;
   float f = 0.0f;
   load_channel(type, px, c, &i, &f);
   switch (type) {
   case GL_UNSIGNED_BYTE: return (uint8_t)i;
   case GL_BYTE: return (uint8_t)snorm_to_unorm((int32_t)i, 8, 8);
   case GL_UNSIGNED_SHORT: return (uint8_t)unorm_to_unorm((uint32_t)i, 16, 8);
   case GL_SHORT: return (uint8_t)snorm_to_unorm((int32_t)i, 16, 8);
   case GL_UNSIGNED_INT: return (uint8_t)unorm_to_unorm((uint32_t)i, 32, 8);
   case GL_INT: return (uint8_t)snorm_to_unorm((int32_t)i, 32, 8);
   default: return (uint8_t)float_to_unorm(f, 8);   /* GL_FLOAT */
   }
}

/* [S: format_utils.c:convert_float] a normalized channel to float */
static float channel_to_float(GLenum type, const uint8_t *px, int c)
{
   int64_t i = 0;
   float f = 0.0f;
   load_channel(type, px, c, &i, &f);
   switch (type) {
   case GL_UNSIGNED_BYTE: return unorm_to_float((uint32_t)i, 8);
   case GL_BYTE: return snorm_to_float((int32_t)i, 8);
   case GL_UNSIGNED_SHORT: return unorm_to_float((uint32_t)i, 16);
   case GL_SHORT: return snorm_to_float((int32_t)i, 16);
   case GL_UNSIGNED_INT: return unorm_to_float((uint32_t)i, 32);
   case GL_INT: return snorm_to_float((int32_t)i, 32);
   default: return f;
   }
}

/* Unpacks n pixels of layout l to RGBA 8-bit [S: format_utils.c:
 * _mesa_swizzle_and_convert for an array format (ONE is 255),
 * util/format unpack_rgba_8unorm for a packed one: _mesa_unorm_to_unorm
 * of each field, 255 for an absent alpha]. */
static void unpack_row_ubyte(const struct layout *l, const uint8_t *src, size_t n,
                             uint8_t (*out)[4])
{
   for (size_t i = 0; i < n; i++, src += l->bytes) {
      if (l->packed) {
         const uint32_t w = load_word(src, l->bytes);
         for (int c = 0; c < 4; c++) {
            if (!l->bits[c]) {
               out[i][c] = c == 3 ? 255 : 0;
               continue;
            }
            const uint32_t v = (w >> l->shift[c]) & (uint32_t)uint_max((unsigned)l->bits[c]);
            out[i][c] = (uint8_t)unorm_to_unorm(v, (unsigned)l->bits[c], 8);
         }
         continue;
      }
      for (int c = 0; c < 4; c++) {
         const int s = l->swz[c];
         out[i][c] = s == SWZ_ZERO ? 0 : s == SWZ_ONE ? 255 : channel_to_ubyte(l->type, src, s);
      }
   }
}

/* The same to float RGBA [S: convert_float; util/format unpack_rgba_float:
 * field * (1.0f / max)] */
static void unpack_row_float(const struct layout *l, const uint8_t *src, size_t n,
                             float (*out)[4], bool int_snorm16, bool uint_unorm16)
{
   for (size_t i = 0; i < n; i++, src += l->bytes) {
      if (l->packed) {
         const uint32_t w = load_word(src, l->bytes);
         for (int c = 0; c < 4; c++) {
            if (!l->bits[c]) {
               out[i][c] = c == 3 ? 1.0f : 0.0f;
               continue;
            }
            const uint32_t v = (w >> l->shift[c]) & (uint32_t)uint_max((unsigned)l->bits[c]);
            out[i][c] = unorm_to_float(v, (unsigned)l->bits[c]);
         }
         continue;
      }
      for (int c = 0; c < 4; c++) {
         const int s = l->swz[c];
         if (int_snorm16 && s != SWZ_ZERO && s != SWZ_ONE) {
            /* a GL_INT channel through a 16-bit snorm texel:
             * _mesa_snorm_to_snorm(x, 32, 16) is x >> 16 */
            int32_t v;
            memcpy(&v, src + 4 * s, 4);
            out[i][c] = snorm_to_float(v >> 16, 16);
            continue;
         }
         if (uint_unorm16 && s != SWZ_ZERO && s != SWZ_ONE) {
            /* a GL_UNSIGNED_INT channel through a 16-bit unorm texel:
             * _mesa_unorm_to_unorm(x, 32, 16) rounds */
            uint32_t v;
            memcpy(&v, src + 4 * s, 4);
            out[i][c] = unorm_to_float(unorm_to_unorm(v, 32, 16), 16);
            continue;
         }
         out[i][c] = s == SWZ_ZERO ? 0.0f : s == SWZ_ONE ? 1.0f
                                          : channel_to_float(l->type, src, s);
      }
   }
}

/* the channel of an array layout's pixel channel ch: Mesa's invert_swizzle
 * (the first of R, G, B, A mapped to it) */
static int rgba_of_channel(const struct layout *l, int ch)
{
   for (int c = 0; c < 4; c++)
      if (l->swz[c] == ch)
         return c;
   return -1;
}

static void store_channel_int(GLenum type, uint8_t *px, int ch, int64_t v)
{
   switch (type) {
   case GL_UNSIGNED_BYTE: case GL_BYTE: px[ch] = (uint8_t)v; break;
   case GL_UNSIGNED_SHORT: case GL_SHORT: {
      const uint16_t s = (uint16_t)v;
      memcpy(px + 2 * ch, &s, 2);
      break;
   }
   default: {
      const uint32_t u = (uint32_t)v;
      memcpy(px + 4 * ch, &u, 4);
      break;
   }
   }
}

/* Packs n RGBA 8-bit pixels into layout l [S: format_utils.c convert_*
 * from UBYTE (normalized); util/format pack_rgba_8unorm:
 * _mesa_unorm_to_unorm(x, 8, bits)] */
static void pack_row_ubyte(const struct layout *l, const uint8_t (*in)[4], size_t n,
                           uint8_t *dst)
{
   for (size_t i = 0; i < n; i++, dst += l->bytes) {
      if (l->packed) {
         uint32_t w = 0;
         for (int c = 0; c < 4; c++)
            if (l->bits[c])
               w |= unorm_to_unorm(in[i][c], 8, (unsigned)l->bits[c]) << l->shift[c];
         store_word(dst, l->bytes, w);
         continue;
      }
      for (int ch = 0; ch < l->nchan; ch++) {
         const int c = rgba_of_channel(l, ch);
         const uint32_t x = c < 0 ? 0 : in[i][c];
         switch (l->type) {
         case GL_UNSIGNED_BYTE: dst[ch] = (uint8_t)x; break;
         case GL_BYTE: dst[ch] = (uint8_t)unorm_to_snorm(x, 8, 8); break;
         case GL_UNSIGNED_SHORT: store_channel_int(l->type, dst, ch, unorm_to_unorm(x, 8, 16)); break;
         case GL_SHORT: store_channel_int(l->type, dst, ch, unorm_to_snorm(x, 8, 16)); break;
         case GL_UNSIGNED_INT: store_channel_int(l->type, dst, ch, unorm_to_unorm(x, 8, 32)); break;
         case GL_INT: store_channel_int(l->type, dst, ch, unorm_to_snorm(x, 8, 32)); break;
         case GL_FLOAT: {
            const float f = unorm_to_float(x, 8);
            memcpy(dst + 4 * ch, &f, 4);
            break;
         }
         default: break;
         }
      }
   }
}

/* Packs n float RGBA pixels into layout l [S: format_utils.c convert_*
 * from FLOAT (normalized); util/format pack_rgba_float: CLAMP to [0, 1],
 * util_iround(x * max)] */
static void pack_row_float(const struct layout *l, const float (*in)[4], size_t n,
                           uint8_t *dst)
{
   for (size_t i = 0; i < n; i++, dst += l->bytes) {
      if (l->packed) {
         uint32_t w = 0;
         for (int c = 0; c < 4; c++) {
            if (!l->bits[c])
               continue;
            const float x = clampf(in[i][c], 0.0f, 1.0f);
            /* util_iround off x86-32: (int)(f + 0.5f) for f >= 0 */
            const float f = x * (float)uint_max((unsigned)l->bits[c]);
            w |= ((uint32_t)(int)(f + 0.5f) & (uint32_t)uint_max((unsigned)l->bits[c]))
                 << l->shift[c];
         }
         store_word(dst, l->bytes, w);
         continue;
      }
      for (int ch = 0; ch < l->nchan; ch++) {
         const int c = rgba_of_channel(l, ch);
         const float x = c < 0 ? 0.0f : in[i][c];
         switch (l->type) {
         case GL_UNSIGNED_BYTE: dst[ch] = (uint8_t)float_to_unorm(x, 8); break;
         case GL_BYTE: dst[ch] = (uint8_t)float_to_snorm(x, 8); break;
         case GL_UNSIGNED_SHORT: store_channel_int(l->type, dst, ch, float_to_unorm(x, 16)); break;
         case GL_SHORT: store_channel_int(l->type, dst, ch, float_to_snorm(x, 16)); break;
         case GL_UNSIGNED_INT: store_channel_int(l->type, dst, ch, float_to_unorm(x, 32)); break;
         case GL_INT: store_channel_int(l->type, dst, ch, float_to_snorm(x, 32)); break;
         case GL_FLOAT: memcpy(dst + 4 * ch, &x, 4); break;
         default: break;
         }
      }
   }
}

/* ------------------------------------------------------------------ */
/* Pixel transfer [S: pixeltransfer.c, pixel.c:_mesa_update_pixel]     */
/* ------------------------------------------------------------------ */

unsigned fgl_image_transfer_state(const struct fgl_context *ctx)
{
   const struct fgl_pixel_attrib *px = &ctx->Pixel;
   unsigned mask = 0;
   if (px->RedScale != 1.0f || px->RedBias != 0.0f || px->GreenScale != 1.0f ||
       px->GreenBias != 0.0f || px->BlueScale != 1.0f || px->BlueBias != 0.0f ||
       px->AlphaScale != 1.0f || px->AlphaBias != 0.0f)
      mask |= FGL_IMAGE_SCALE_BIAS_BIT;
   if (px->IndexShift || px->IndexOffset)
      mask |= FGL_IMAGE_SHIFT_OFFSET_BIT;
   if (px->MapColorFlag)
      mask |= FGL_IMAGE_MAP_COLOR_BIT;
   return mask;
}

void fgl_apply_rgba_transfer_ops(const struct fgl_context *ctx, unsigned ops, size_t n,
                                 float (*rgba)[4])
{
   const struct fgl_pixel_attrib *px = &ctx->Pixel;
   if (ops & FGL_IMAGE_SCALE_BIAS_BIT) {
      /* [S: pixeltransfer.c:_mesa_scale_and_bias_rgba] per channel, only
       * the channels whose scale or bias is not the identity */
      const float scale[4] = {px->RedScale, px->GreenScale, px->BlueScale, px->AlphaScale};
      const float bias[4] = {px->RedBias, px->GreenBias, px->BlueBias, px->AlphaBias};
      for (int c = 0; c < 4; c++) {
         if (scale[c] == 1.0f && bias[c] == 0.0f)
            continue;
         for (size_t i = 0; i < n; i++)
            rgba[i][c] = rgba[i][c] * scale[c] + bias[c];
      }
   }
   if (ops & FGL_IMAGE_MAP_COLOR_BIT) {
      /* [S: pixeltransfer.c:_mesa_map_rgba] clamp, scale by size - 1,
       * round half to even */
      const struct fgl_pixelmap *maps[4] = {&ctx->PixelMaps.RtoR, &ctx->PixelMaps.GtoG,
                                            &ctx->PixelMaps.BtoB, &ctx->PixelMaps.AtoA};
      for (size_t i = 0; i < n; i++) {
         for (int c = 0; c < 4; c++) {
            const float v = clampf(rgba[i][c], 0.0f, 1.0f);
            const float scale = (float)(maps[c]->Size - 1);
            rgba[i][c] = maps[c]->Map[(int)round_even(v * scale)];
         }
      }
   }
   if (ops & FGL_IMAGE_CLAMP_BIT) {
      for (size_t i = 0; i < n; i++)
         for (int c = 0; c < 4; c++)
            rgba[i][c] = clampf(rgba[i][c], 0.0f, 1.0f);
   }
}

void fgl_shift_and_offset_ci(const struct fgl_context *ctx, size_t n, GLuint *index)
{
   /* The oracle's C shifts by the GL_INDEX_SHIFT value (and by its
    * negation) as x86's scalar shifts do: the count taken modulo 32.  Done
    * here without C's undefined behaviour for counts outside [0, 31] and
    * for -INT_MIN (found by the long libFuzzer campaign). */
   const GLint shift = ctx->Pixel.IndexShift;
   const GLuint offset = (GLuint)ctx->Pixel.IndexOffset;
   const unsigned left = (unsigned)shift & 31u, right = (0u - (unsigned)shift) & 31u;
   for (size_t i = 0; i < n; i++) {
      if (shift > 0)
         index[i] = (index[i] << left) + offset;
      else if (shift < 0)
         index[i] = (index[i] >> right) + offset;
      else
         index[i] = index[i] + offset;
   }
}

void fgl_map_ci_to_rgba(const struct fgl_context *ctx, size_t n, const GLuint *index,
                        float (*rgba)[4])
{
   const struct fgl_pixelmaps *m = &ctx->PixelMaps;
   for (size_t i = 0; i < n; i++) {
      rgba[i][0] = m->ItoR.Map[index[i] & (GLuint)(m->ItoR.Size - 1)];
      rgba[i][1] = m->ItoG.Map[index[i] & (GLuint)(m->ItoG.Size - 1)];
      rgba[i][2] = m->ItoB.Map[index[i] & (GLuint)(m->ItoB.Size - 1)];
      rgba[i][3] = m->ItoA.Map[index[i] & (GLuint)(m->ItoA.Size - 1)];
   }
}

/* ------------------------------------------------------------------ */
/* Indices, stencil, depth [S: pack.c]                                 */
/* ------------------------------------------------------------------ */

static uint16_t swap16(uint16_t v)
{
   return (uint16_t)((v >> 8) | (v << 8));
}

static uint32_t swap32(uint32_t v)
{
   return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

void fgl_extract_uint_indexes(const struct fgl_pixelstore *p, size_t n, GLenum type,
                              const void *src, GLuint *index)
{
   const uint8_t *s = src;
   switch (type) {
   case GL_BITMAP: {
      /* [S: pack.c:extract_uint_indexes] the first bit is SkipPixels & 7 */
      if (p->LsbFirst) {
         unsigned mask = 1u << (p->SkipPixels & 7);
         for (size_t i = 0; i < n; i++) {
            index[i] = (*s & mask) ? 1 : 0;
            if (mask == 128) {
               mask = 1;
               s++;
            } else {
               mask <<= 1;
            }
         }
      } else {
         unsigned mask = 128u >> (p->SkipPixels & 7);
         for (size_t i = 0; i < n; i++) {
            index[i] = (*s & mask) ? 1 : 0;
            if (mask == 1) {
               mask = 128;
               s++;
            } else {
               mask >>= 1;
            }
         }
      }
      break;
   }
   case GL_UNSIGNED_BYTE:
      for (size_t i = 0; i < n; i++)
         index[i] = s[i];
      break;
   case GL_BYTE:
      for (size_t i = 0; i < n; i++)
         index[i] = (GLuint)(int8_t)s[i];
      break;
   case GL_UNSIGNED_SHORT:
   case GL_SHORT:
      for (size_t i = 0; i < n; i++) {
         uint16_t v;
         memcpy(&v, s + 2 * i, 2);
         if (p->SwapBytes)
            v = swap16(v);
         if (type == GL_UNSIGNED_SHORT)
            index[i] = v;
         else
            index[i] = (GLuint)(int16_t)v;
      }
      break;
   case GL_UNSIGNED_INT:
   case GL_INT:
   case GL_FLOAT:
      for (size_t i = 0; i < n; i++) {
         uint32_t v;
         memcpy(&v, s + 4 * i, 4);
         if (p->SwapBytes)
            v = swap32(v);
         if (type == GL_FLOAT) {
            float f;
            memcpy(&f, &v, 4);
            /* (GLuint) of a float on x86-64: cvttss2si to 64 bits,
             * INT64_MIN past the range or NaN, then the low 32 bits */
            index[i] = f >= -9223372036854775808.0f && f < 9223372036854775808.0f
                          ? (GLuint)(int64_t)f : 0u;
         } else {
            index[i] = v;
         }
      }
      break;
   default:
      memset(index, 0, n * sizeof(*index));
      break;
   }
}

void fgl_unpack_stencil_span(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                             size_t n, GLenum type, const void *src, unsigned ops,
                             GLuint *dst)
{
   fgl_extract_uint_indexes(p, n, type, src, dst);
   if (ops & FGL_IMAGE_SHIFT_OFFSET_BIT)
      fgl_shift_and_offset_ci(ctx, n, dst);
   if (ctx->Pixel.MapStencilFlag) {
      const GLuint mask = (GLuint)(ctx->PixelMaps.StoS.Size - 1);
      for (size_t i = 0; i < n; i++)
         dst[i] = (GLuint)(int64_t)ctx->PixelMaps.StoS.Map[dst[i] & mask];
   }
}

void fgl_unpack_depth_span_float(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                                 size_t n, GLenum type, const void *src, float *dst)
{
   const uint8_t *s = src;
   bool clamp = false;
   for (size_t i = 0; i < n; i++) {
      float d = 0.0f;
      switch (type) {
      case GL_BYTE: {       /* BYTE_TO_FLOATZ */
         const int8_t b = (int8_t)s[i];
         d = b == 0 ? 0.0f : (2.0f * b + 1.0f) * (1.0f / 255.0f);
         clamp = true;
         break;
      }
      case GL_UNSIGNED_BYTE:   /* _mesa_ubyte_to_float_color_tab */
         d = (float)s[i] / 255.0f;
         break;
      case GL_SHORT:
      case GL_UNSIGNED_SHORT: {
         uint16_t v;
         memcpy(&v, s + 2 * i, 2);
         if (p->SwapBytes)
            v = swap16(v);
         if (type == GL_SHORT) {   /* SHORT_TO_FLOATZ */
            const int16_t sv = (int16_t)v;
            d = sv == 0 ? 0.0f : (2.0f * sv + 1.0f) * (1.0f / 65535.0f);
            clamp = true;
         } else {   /* USHORT_TO_FLOAT */
            d = (float)v * (1.0f / 65535.0f);
         }
         break;
      }
      default: {
         uint32_t v;
         memcpy(&v, s + 4 * i, 4);
         if (p->SwapBytes)
            v = swap32(v);
         if (type == GL_INT) {          /* INT_TO_FLOAT */
            d = (float)((2.0f * (float)(int32_t)v + 1.0f) * (1.0f / 4294967294.0));
            clamp = true;
         } else if (type == GL_UNSIGNED_INT) {   /* UINT_TO_FLOAT */
            d = (float)((float)v * (1.0f / 4294967295.0));
         } else {      /* GL_FLOAT */
            memcpy(&d, &v, 4);
            clamp = true;
         }
         break;
      }
      }
      dst[i] = d;
   }
   const float scale = ctx->Pixel.DepthScale, bias = ctx->Pixel.DepthBias;
   if (scale != 1.0f || bias != 0.0f) {
      for (size_t i = 0; i < n; i++)
         dst[i] = dst[i] * scale + bias;
      clamp = true;
   }
   if (clamp)
      for (size_t i = 0; i < n; i++)
         dst[i] = clampf(dst[i], 0.0f, 1.0f);
}

void fgl_pack_depth_span(struct fgl_context *ctx, const struct fgl_pixelstore *p, size_t n,
                         GLenum type, const float *depth, void *dstv)
{
   uint8_t *dst = dstv;
   const float scale = ctx->Pixel.DepthScale, bias = ctx->Pixel.DepthBias;
   const bool sb = scale != 1.0f || bias != 0.0f;
   for (size_t i = 0; i < n; i++) {
      float d = depth[i];
      if (sb)   /* [S: pixeltransfer.c:_mesa_scale_and_bias_depth] */
         d = clampf(d * scale + bias, 0.0f, 1.0f);
      switch (type) {
      case GL_UNSIGNED_BYTE:   /* FLOAT_TO_UBYTE: truncated */
         dst[i] = (uint8_t)(int32_t)(d * 255.0f);
         break;
      case GL_BYTE:            /* FLOAT_TO_BYTE */
         dst[i] = (uint8_t)(int8_t)((((int32_t)(255.0f * d)) - 1) / 2);
         break;
      case GL_UNSIGNED_SHORT: {   /* CLAMPED_FLOAT_TO_USHORT */
         uint16_t v = (uint16_t)round_even(d * 65535.0f);
         if (p->SwapBytes)
            v = swap16(v);
         memcpy(dst + 2 * i, &v, 2);
         break;
      }
      case GL_SHORT: {            /* FLOAT_TO_SHORT */
         uint16_t v = (uint16_t)(int16_t)((((int32_t)(65535.0f * d)) - 1) / 2);
         if (p->SwapBytes)
            v = swap16(v);
         memcpy(dst + 2 * i, &v, 2);
         break;
      }
      case GL_UNSIGNED_INT: {     /* FLOAT_TO_UINT: (GLuint)(X * 4294967295.0) */
         uint32_t v = (uint32_t)(int64_t)((double)d * 4294967295.0);
         if (p->SwapBytes)
            v = swap32(v);
         memcpy(dst + 4 * i, &v, 4);
         break;
      }
      case GL_INT: {              /* FLOAT_TO_INT: (GLint)(2147483647.0 * X) */
         uint32_t v = (uint32_t)(int32_t)(2147483647.0 * (double)d);
         if (p->SwapBytes)
            v = swap32(v);
         memcpy(dst + 4 * i, &v, 4);
         break;
      }
      default: {                  /* GL_FLOAT */
         uint32_t v;
         memcpy(&v, &d, 4);
         if (p->SwapBytes)
            v = swap32(v);
         memcpy(dst + 4 * i, &v, 4);
         break;
      }
      }
   }
}

void fgl_apply_stencil_transfer_ops(const struct fgl_context *ctx, size_t n, uint8_t *s)
{
   /* [S: pixeltransfer.c:_mesa_apply_stencil_transfer_ops] in 8 bits */
   if (ctx->Pixel.IndexShift != 0 || ctx->Pixel.IndexOffset != 0) {
      /* (counts modulo 32 as x86's shifts, in unsigned arithmetic: the
       * same low 8 bits without C's undefined behaviour; see
       * fgl_shift_and_offset_ci) */
      const unsigned offset = (unsigned)ctx->Pixel.IndexOffset;
      const GLint shift = ctx->Pixel.IndexShift;
      const unsigned left = (unsigned)shift & 31u, right = (0u - (unsigned)shift) & 31u;
      for (size_t i = 0; i < n; i++) {
         if (shift > 0)
            s[i] = (uint8_t)(((unsigned)s[i] << left) + offset);
         else if (shift < 0)
            s[i] = (uint8_t)(((unsigned)s[i] >> right) + offset);
         else
            s[i] = (uint8_t)(s[i] + offset);
      }
   }
   if (ctx->Pixel.MapStencilFlag) {
      const GLuint mask = (GLuint)(ctx->PixelMaps.StoS.Size - 1);
      for (size_t i = 0; i < n; i++)
         s[i] = (uint8_t)(int32_t)ctx->PixelMaps.StoS.Map[s[i] & mask];
   }
}

void fgl_pack_stencil_span(struct fgl_context *ctx, const struct fgl_pixelstore *p, size_t n,
                           GLenum type, const uint8_t *stencil, void *dstv)
{
   uint8_t *dst = dstv;
   uint8_t *s = fgl_malloc_gl(ctx, n ? n : 1);
   if (!s)
      return;
   memcpy(s, stencil, n);
   fgl_apply_stencil_transfer_ops(ctx, n, s);
   for (size_t i = 0; i < n; i++) {
      switch (type) {
      case GL_UNSIGNED_BYTE: dst[i] = s[i]; break;
      case GL_BYTE: dst[i] = (uint8_t)(s[i] & 0x7f); break;
      case GL_UNSIGNED_SHORT: case GL_SHORT: {
         uint16_t v = s[i];
         if (p->SwapBytes)
            v = swap16(v);
         memcpy(dst + 2 * i, &v, 2);
         break;
      }
      case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: {
         uint32_t v = s[i];
         if (type == GL_FLOAT) {
            const float f = (float)s[i];
            memcpy(&v, &f, 4);
         }
         if (p->SwapBytes)
            v = swap32(v);
         memcpy(dst + 4 * i, &v, 4);
         break;
      }
      default:
         break;
      }
   }
   if (type == GL_BITMAP) {
      /* [S: pack.c:_mesa_pack_stencil_span] bits from the start of the
       * byte (the pack state's SkipPixels is not used), a started byte
       * cleared first */
      int shift = p->LsbFirst ? 0 : 7;
      for (size_t i = 0; i < n; i++) {
         if (p->LsbFirst) {
            if (shift == 0)
               *dst = 0;
            *dst |= (uint8_t)((s[i] != 0) << shift);
            if (++shift == 8) {
               shift = 0;
               dst++;
            }
         } else {
            if (shift == 7)
               *dst = 0;
            *dst |= (uint8_t)((s[i] != 0) << shift);
            if (--shift < 0) {
               shift = 7;
               dst++;
            }
         }
      }
   }
   fgl_free(s);
}

/* ------------------------------------------------------------------ */
/* Unpacking colour images                                             */
/* ------------------------------------------------------------------ */

/* Row y of a colour image with its bytes swapped as SWAP_BYTES asks, in
 * `tmp` (texstore.c:texstore_rgba swaps the whole image first). */
static const uint8_t *image_row(const struct fgl_pixelstore *p, const struct layout *l,
                                int width, GLenum format, GLenum type, const void *pixels,
                                int y, uint8_t *tmp)
{
   const uint8_t *src = fgl_image_address(p, pixels, width, format, type, y, 0);
   if (!p->SwapBytes)
      return src;
   memcpy(tmp, src, (size_t)width * l->bytes);
   swap_row(l, type, tmp, (size_t)width);
   return tmp;
}

/* [S: pack.c:_mesa_unpack_color_index_to_rgba_float] the width*height
 * indices from the image's first pixel on, as one span */
static void unpack_ci_float(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                            int width, int height, GLenum type, const void *pixels,
                            unsigned ops, float (*rgba)[4], GLuint *index)
{
   const size_t count = (size_t)width * (size_t)height;
   const void *src = fgl_image_address(p, pixels, width, GL_COLOR_INDEX, type, 0, 0);
   fgl_extract_uint_indexes(p, count, type, src, index);
   if (ops & FGL_IMAGE_SHIFT_OFFSET_BIT)
      fgl_shift_and_offset_ci(ctx, count, index);
   fgl_map_ci_to_rgba(ctx, count, index, rgba);
   /* no RGBA scale/bias or map for colour indices */
   fgl_apply_rgba_transfer_ops(ctx, ops & ~(FGL_IMAGE_SCALE_BIAS_BIT | FGL_IMAGE_MAP_COLOR_BIT),
                               count, rgba);
}

bool fgl_unpack_rgba_float(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                           int width, int height, GLenum format, GLenum type,
                           const void *pixels, unsigned ops, float *rgba)
{
   if (width <= 0 || height <= 0)
      return true;
   const size_t count = (size_t)width * (size_t)height;
   if (format == GL_COLOR_INDEX) {
      GLuint *index = fgl_malloc_gl(ctx, count * sizeof(*index));
      if (!index)
         return false;
      unpack_ci_float(ctx, p, width, height, type, pixels, ops, (float (*)[4])rgba, index);
      fgl_free(index);
      return true;
   }
   struct layout l;
   if (!get_layout(format, type, &l))
      return false;
   uint8_t *tmp = p->SwapBytes ? fgl_malloc_gl(ctx, (size_t)width * l.bytes) : NULL;
   if (p->SwapBytes && !tmp)
      return false;
   for (int y = 0; y < height; y++) {
      const uint8_t *src = image_row(p, &l, width, format, type, pixels, y, tmp);
      unpack_row_float(&l, src, (size_t)width, (float (*)[4])(rgba + 4 * (size_t)y * width),
                       (ops & FGL_UNPACK_INT_SNORM16) && type == GL_INT && !l.packed,
                       (ops & FGL_UNPACK_UINT_UNORM16) && type == GL_UNSIGNED_INT && !l.packed);
   }
   fgl_free(tmp);
   ops &= ~(unsigned)(FGL_UNPACK_INT_SNORM16 | FGL_UNPACK_UINT_UNORM16);
   if (ops)
      fgl_apply_rgba_transfer_ops(ctx, ops, count, (float (*)[4])rgba);
   return true;
}

/* The RGBA8 texel of base format `base` from an RGBA colour (Mesa's
 * rebase: a luminance or intensity texture takes red, and the oracle's
 * sampler swizzle expands the stored channels). */
static void store_texel(GLenum base, const uint8_t c[4], uint8_t *t)
{
   switch (base) {
   case GL_LUMINANCE:       t[0] = t[1] = t[2] = c[0]; t[3] = 255; break;
   case GL_LUMINANCE_ALPHA: t[0] = t[1] = t[2] = c[0]; t[3] = c[3]; break;
   case GL_INTENSITY:       t[0] = t[1] = t[2] = t[3] = c[0]; break;
   case GL_ALPHA:           t[0] = t[1] = t[2] = 0; t[3] = c[3]; break;
   case GL_RGB:             t[0] = c[0]; t[1] = c[1]; t[2] = c[2]; t[3] = 255; break;
   case GL_RGBA:
   default:                 memcpy(t, c, 4); break;
   }
}

/*
 * [S: texstore.c:texstore_rgba] into the oracle's 8-bit texture formats:
 *  - GL_COLOR_INDEX: indices -> I_TO_RGBA maps (shift/offset when on),
 *    clamped, CLAMPED_FLOAT_TO_UBYTE (pack.c:
 *    _mesa_unpack_color_index_to_rgba_ubyte), that image addressed with
 *    the unpack state again;
 *  - any pixel transfer state (_ImageTransferState, the index shift/offset
 *    included): to float RGBA without the skips, the operations, then
 *    _mesa_float_to_unorm;
 *  - otherwise straight to 8 bits (_mesa_format_convert: array formats
 *    channel by channel, packed ones through unpack_rgba_8unorm).
 */
bool fgl_unpack_texels_rgba8(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                             int width, int height, GLenum format, GLenum type,
                             const void *pixels, GLenum base, uint8_t *dst)
{
   if (width <= 0 || height <= 0)
      return true;
   const size_t count = (size_t)width * (size_t)height;
   const unsigned ops = fgl_image_transfer_state(ctx);
   if (format == GL_COLOR_INDEX) {
      float (*rgba)[4] = fgl_malloc_gl(ctx, count * sizeof(*rgba));
      GLuint *index = fgl_malloc_gl(ctx, count * sizeof(*index));
      uint8_t (*temp)[4] = fgl_malloc_gl(ctx, count * sizeof(*temp));
      if (!rgba || !index || !temp) {
         fgl_free(rgba);
         fgl_free(index);
         fgl_free(temp);
         return false;
      }
      unpack_ci_float(ctx, p, width, height, type, pixels, ops | FGL_IMAGE_CLAMP_BIT, rgba,
                      index);
      for (size_t i = 0; i < count; i++)
         for (int k = 0; k < 4; k++)
            temp[i][k] = clamped_float_to_ubyte(rgba[i][k]);
      /* texstore_rgba then reads that tight RGBA ubyte image with the
       * caller's unpack state still in place: the skips, row length and
       * alignment apply to it a second time.  A texel beyond the
       * width*height pixels reads past the oracle's buffer (undefined);
       * fixgl stores 0 there. */
      const size_t stride = fgl_image_row_stride(p, width, GL_RGBA, GL_UNSIGNED_BYTE);
      const size_t total = count * 4;
      for (int y = 0; y < height; y++) {
         for (int x = 0; x < width; x++) {
            const size_t off = ((size_t)p->SkipRows + (size_t)y) * stride +
                               ((size_t)p->SkipPixels + (size_t)x) * 4;
            uint8_t c[4] = {0, 0, 0, 0};
            if (off + 4 <= total)
               memcpy(c, (const uint8_t *)temp + off, 4);
            store_texel(base, c, dst + 4 * ((size_t)y * (size_t)width + (size_t)x));
         }
      }
      fgl_free(rgba);
      fgl_free(index);
      fgl_free(temp);
      return true;
   }
   struct layout l;
   if (!get_layout(format, type, &l))
      return false;
   if (ops) {
      /* texstore_rgba converts to float from the image's base address at
       * its row stride: SKIP_PIXELS and SKIP_ROWS are not applied on this
       * path */
      struct fgl_pixelstore noskip = *p;
      noskip.SkipPixels = 0;
      noskip.SkipRows = 0;
      float (*rgba)[4] = fgl_malloc_gl(ctx, count * sizeof(*rgba));
      if (!rgba)
         return false;
      if (!fgl_unpack_rgba_float(ctx, &noskip, width, height, format, type, pixels, ops,
                                 (float *)rgba)) {
         fgl_free(rgba);
         return false;
      }
      for (size_t i = 0; i < count; i++) {
         uint8_t c[4];
         for (int k = 0; k < 4; k++)
            c[k] = (uint8_t)float_to_unorm(rgba[i][k], 8);
         store_texel(base, c, dst + 4 * i);
      }
      fgl_free(rgba);
      return true;
   }
   uint8_t *tmp = p->SwapBytes ? fgl_malloc_gl(ctx, (size_t)width * l.bytes) : NULL;
   uint8_t (*row)[4] = fgl_malloc_gl(ctx, (size_t)width * sizeof(*row));
   if ((p->SwapBytes && !tmp) || !row) {
      fgl_free(tmp);
      fgl_free(row);
      return false;
   }
   for (int y = 0; y < height; y++) {
      const uint8_t *src = image_row(p, &l, width, format, type, pixels, y, tmp);
      unpack_row_ubyte(&l, src, (size_t)width, row);
      for (int x = 0; x < width; x++)
         store_texel(base, row[x], dst + 4 * ((size_t)y * (size_t)width + (size_t)x));
   }
   fgl_free(tmp);
   fgl_free(row);
   return true;
}

/* [S: format_utils.c:convert_ushort, normalized] a plain-type channel
 * straight to unorm16 (_mesa_swizzle_and_convert between array formats) */
static uint32_t channel_to_unorm16(GLenum type, const uint8_t *px, int c)
{
   int64_t i = 0;
   float f = 0.0f;
   load_channel(type, px, c, &i, &f);
   switch (type) {
   case GL_UNSIGNED_BYTE: return unorm_to_unorm((uint32_t)i, 8, 16);
   case GL_BYTE: return snorm_to_unorm((int32_t)i, 8, 16);
   case GL_UNSIGNED_SHORT: return (uint32_t)i;
   case GL_SHORT: return snorm_to_unorm((int32_t)i, 16, 16);
   case GL_UNSIGNED_INT: return unorm_to_unorm((uint32_t)i, 32, 16);
   case GL_INT: return snorm_to_unorm((int32_t)i, 32, 16);
   default: return float_to_unorm(f, 16);   /* GL_FLOAT */
   }
}

/*
 * [S: texstore.c:texstore_rgba, format_utils.c:_mesa_format_convert into
 * the texture's own format] Mesa's paths to the stored values:
 *  - GL_COLOR_INDEX: the RGBA ubyte image fgl_unpack_texels_rgba8 makes,
 *    packed by _mesa_pack_ubyte_rgba_row (_mesa_unorm_to_unorm(x, 8, n))
 *    or, into a 16-bit array format, x * 257;
 *  - a transfer state or GL_RGBA/GL_FLOAT data: RGBA32_FLOAT, which goes
 *    to a packed format by _mesa_pack_float_rgba_row (util_iround of
 *    CLAMP(f) * max) and to a 16-bit array by _mesa_float_to_unorm;
 *  - plain-type data into a 16-bit array format: channel by channel;
 *  - RGBA8 data (GL_RGBA with GL_UNSIGNED_BYTE or _8_8_8_8_REV) into a
 *    packed format: _mesa_pack_ubyte_rgba_row (the 10-bit fields too);
 *  - anything else through an intermediate: ubyte for a packed format of
 *    at most 8 bits per field, float otherwise.
 */
bool fgl_unpack_texels_stored(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                              int width, int height, GLenum format, GLenum type,
                              const void *pixels, GLenum base, const uint8_t bits[4],
                              bool array16, uint16_t *dst)
{
   if (width <= 0 || height <= 0)
      return true;
   const size_t count = (size_t)width * (size_t)height;
   const unsigned ops = fgl_image_transfer_state(ctx);
   int maxbits = 0;
   for (int c = 0; c < 4; c++)
      if (bits[c] > maxbits)
         maxbits = bits[c];
   /* the source channel of each texel channel (store_texel), -1 / -2: the
    * constant 0 / 1 */
   int map[4] = { 0, 1, 2, 3 };
   switch (base) {
   case GL_LUMINANCE: map[1] = map[2] = 0; map[3] = -2; break;
   case GL_LUMINANCE_ALPHA: map[1] = map[2] = 0; break;
   case GL_INTENSITY: map[1] = map[2] = map[3] = 0; break;
   case GL_ALPHA: map[0] = map[1] = map[2] = -1; break;
   case GL_RGB: map[3] = -2; break;
   default: break;
   }
   struct layout l;
   const bool have_layout = format != GL_COLOR_INDEX && get_layout(format, type, &l);
   if (format != GL_COLOR_INDEX && !have_layout)
      return false;
   const bool rgba8 = format == GL_RGBA && (type == GL_UNSIGNED_BYTE ||
                                            type == GL_UNSIGNED_INT_8_8_8_8_REV);
   const bool rgba_float = format == GL_RGBA && type == GL_FLOAT;
   enum { VIA_UBYTE, VIA_FLOAT, DIRECT16 } path;
   if (format == GL_COLOR_INDEX)
      path = VIA_UBYTE;
   else if (ops || rgba_float)
      path = VIA_FLOAT;
   else if (array16 && !l.packed)
      path = DIRECT16;
   else if (!array16 && (rgba8 || maxbits <= 8))
      path = VIA_UBYTE;
   else
      path = VIA_FLOAT;

   if (path == VIA_UBYTE) {
      uint8_t *t = fgl_malloc_gl(ctx, count * 4);
      if (!t)
         return false;
      if (!fgl_unpack_texels_rgba8(ctx, p, width, height, format, type, pixels, base, t)) {
         fgl_free(t);
         return false;
      }
      for (size_t i = 0; i < 4 * count; i++) {
         const unsigned b = bits[i & 3];
         dst[i] = (uint16_t)(b == 0 ? (t[i] ? 1 : 0) : unorm_to_unorm(t[i], 8, b));
      }
      fgl_free(t);
      return true;
   }
   if (path == DIRECT16) {
      uint8_t *tmp = p->SwapBytes ? fgl_malloc_gl(ctx, (size_t)width * l.bytes) : NULL;
      if (p->SwapBytes && !tmp)
         return false;
      for (int y = 0; y < height; y++) {
         const uint8_t *src = image_row(p, &l, width, format, type, pixels, y, tmp);
         for (int x = 0; x < width; x++, src += l.bytes) {
            uint32_t c[4];
            for (int k = 0; k < 4; k++) {
               const int sw = l.swz[k];
               c[k] = sw == SWZ_ZERO ? 0 : sw == SWZ_ONE ? 0xffff
                                                        : channel_to_unorm16(l.type, src, sw);
            }
            uint16_t *o = dst + 4 * ((size_t)y * (size_t)width + (size_t)x);
            for (int k = 0; k < 4; k++)
               o[k] = (uint16_t)(map[k] < 0 ? (map[k] == -2) : bits[k] ? c[map[k]] : 0);
         }
      }
      fgl_free(tmp);
      return true;
   }
   /* VIA_FLOAT; a transfer state converts from the base address (the
    * skips are not applied, as fgl_unpack_texels_rgba8 notes) */
   struct fgl_pixelstore noskip = *p;
   if (ops) {
      noskip.SkipPixels = 0;
      noskip.SkipRows = 0;
   }
   float (*rgba)[4] = fgl_malloc_gl(ctx, count * sizeof(*rgba));
   if (!rgba)
      return false;
   if (!fgl_unpack_rgba_float(ctx, &noskip, width, height, format, type, pixels, ops,
                              (float *)rgba)) {
      fgl_free(rgba);
      return false;
   }
   for (size_t i = 0; i < count; i++) {
      for (int k = 0; k < 4; k++) {
         uint32_t v;
         if (map[k] < 0) {
            v = map[k] == -2;
         } else if (!bits[k]) {
            v = 0;
         } else if (array16) {
            v = float_to_unorm(rgba[i][map[k]], 16);
         } else {
            /* util_iround off x86-32: (int)(f + 0.5f) */
            const float x = clampf(rgba[i][map[k]], 0.0f, 1.0f);
            v = (uint32_t)(int)(x * (float)uint_max(bits[k]) + 0.5f);
         }
         dst[4 * i + (size_t)k] = (uint16_t)v;
      }
   }
   fgl_free(rgba);
   return true;
}

/* ------------------------------------------------------------------ */
/* Packing colour images                                               */
/* ------------------------------------------------------------------ */

/*
 * [S: readpix.c:read_rgba_pixels, texgetimage.c:get_tex_rgba_uncompressed]
 * The source is 8-bit RGBA of base `base`.  Mesa's paths:
 *  - transfer operations or (glReadPixels) a luminance destination: to
 *    float RGBA (the rebase applied), the operations, then float to the
 *    destination (luminance = clamped R+G+B for glReadPixels);
 *  - otherwise the 8-bit values go to the destination directly: array
 *    formats channel by channel, packed ones by pack_rgba_8unorm when the
 *    source is exactly R8G8B8A8 without a rebase, else through the 8-bit
 *    intermediate (destination fields <= 8 bits) or float (> 8 bits).
 */
bool fgl_pack_rgba8(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                    unsigned source, int width, int height, GLenum base,
                    const uint8_t *rgba8, GLenum format, GLenum type, void *pixels)
{
   struct layout l;
   if (!get_layout(format, type, &l))
      return false;
   if (width <= 0 || height <= 0)
      return true;
   const size_t count = (size_t)width * (size_t)height;
   const bool lum = format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA;
   unsigned ops;
   bool rgb_to_lum = false;
   const bool exact_rgba8 = base == GL_RGBA && !(source & FGL_PACK_NOT_R8G8B8A8);
   const bool cpu_decoded = (source & FGL_PACK_CPU_DECODED) != 0;
   source &= ~(unsigned)(FGL_PACK_NOT_R8G8B8A8 | FGL_PACK_CPU_DECODED);
   if (source == FGL_PACK_READPIXELS) {
      /* [S: readpix.c:_mesa_get_readpixels_transfer_ops] the clamp stays
       * only for the R+G+B luminance of an unsigned normalized buffer */
      ops = fgl_image_transfer_state(ctx);
      rgb_to_lum = lum && (base == GL_RGB || base == GL_RGBA);
      if (rgb_to_lum)
         ops |= FGL_IMAGE_CLAMP_BIT;
   } else {
      /* [S: texgetimage.c:get_tex_rgba] only a clamp, for a luminance
       * destination of a type that cannot hold negative values */
      ops = 0;
      const bool signed_type = type == GL_BYTE || type == GL_SHORT || type == GL_INT ||
                               type == GL_FLOAT;
      if (!signed_type && lum)
         ops |= FGL_IMAGE_CLAMP_BIT;
   }

   /* the source with Mesa's rebase (readpix.c / texgetimage.c:
    * teximage_needs_rebase: L and I read as (L, 0, 0, 1), LA as
    * (L, 0, 0, A); RGB has alpha 1) */
   uint8_t (*src)[4] = fgl_malloc_gl(ctx, count * sizeof(*src));
   if (!src)
      return false;
   for (size_t i = 0; i < count; i++) {
      const uint8_t *t = rgba8 + 4 * i;
      switch (base) {
      case GL_LUMINANCE: case GL_INTENSITY:
         src[i][0] = t[0]; src[i][1] = src[i][2] = 0; src[i][3] = 255; break;
      case GL_LUMINANCE_ALPHA:
         src[i][0] = t[0]; src[i][1] = src[i][2] = 0; src[i][3] = t[3]; break;
      case GL_ALPHA:
         src[i][0] = src[i][1] = src[i][2] = 0; src[i][3] = t[3]; break;
      case GL_RGB:
         memcpy(src[i], t, 3); src[i][3] = 255; break;
      default:
         memcpy(src[i], t, 4); break;
      }
   }
   const size_t stride = fgl_image_row_stride(p, width, format, type);
   uint8_t *dst0 = (uint8_t *)fgl_image_address(p, pixels, width, format, type, 0, 0);

   if (ops || rgb_to_lum || cpu_decoded) {
      float (*f)[4] = fgl_malloc_gl(ctx, count * sizeof(*f));
      if (!f) {
         fgl_free(src);
         return false;
      }
      for (size_t i = 0; i < count; i++)
         for (int c = 0; c < 4; c++)
            f[i][c] = cpu_decoded ? (float)src[i][c] / 255.0f : unorm_to_float(src[i][c], 8);
      fgl_apply_rgba_transfer_ops(ctx, ops, count, f);
      if (rgb_to_lum) {
         /* [S: pack.c:_mesa_pack_luminance_from_rgba_float] */
         for (size_t i = 0; i < count; i++) {
            const float sum = f[i][0] + f[i][1] + f[i][2];
            f[i][0] = (ops & FGL_IMAGE_CLAMP_BIT) ? clampf(sum, 0.0f, 1.0f) : sum;
         }
      }
      for (int y = 0; y < height; y++)
         pack_row_float(&l, (const float (*)[4])(f + (size_t)y * width), (size_t)width,
                        dst0 + (size_t)y * stride);
      fgl_free(f);
   } else if (l.packed && !exact_rgba8) {
      int maxbits = 0;
      for (int c = 0; c < 4; c++)
         if (l.bits[c] > maxbits)
            maxbits = l.bits[c];
      if (maxbits > 8) {
         float (*f)[4] = fgl_malloc_gl(ctx, (size_t)width * sizeof(*f));
         if (!f) {
            fgl_free(src);
            return false;
         }
         for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++)
               for (int c = 0; c < 4; c++)
                  f[x][c] = unorm_to_float(src[(size_t)y * width + x][c], 8);
            pack_row_float(&l, (const float (*)[4])f, (size_t)width, dst0 + (size_t)y * stride);
         }
         fgl_free(f);
      } else {
         for (int y = 0; y < height; y++)
            pack_row_ubyte(&l, (const uint8_t (*)[4])(src + (size_t)y * width), (size_t)width,
                           dst0 + (size_t)y * stride);
      }
   } else {
      for (int y = 0; y < height; y++)
         pack_row_ubyte(&l, (const uint8_t (*)[4])(src + (size_t)y * width), (size_t)width,
                        dst0 + (size_t)y * stride);
   }
   if (p->SwapBytes)
      for (int y = 0; y < height; y++)
         swap_row(&l, type, dst0 + (size_t)y * stride, (size_t)width);
   fgl_free(src);
   return true;
}

/* A stored texel channel (value v of `bits` bits, or bits 0: the
 * constant v, 0 or 1) as float [S: util/format unpack_rgba_float:
 * field * (1.0f / max); format_utils.h:_mesa_unorm_to_float] */
static float stored_to_float(uint32_t v, unsigned bits)
{
   return bits ? unorm_to_float(v, bits) : (float)v;
}

static uint8_t stored_to_ubyte(uint32_t v, unsigned bits)
{
   return bits ? (uint8_t)unorm_to_unorm(v, bits, 8) : (uint8_t)(v ? 255 : 0);
}

/*
 * [S: texgetimage.c:get_tex_rgba_uncompressed, format_utils.c:
 * _mesa_format_convert from the texture's own format]
 *  - a luminance destination of an unsigned type (the clamp): to float
 *    RGBA, clamped, then float to the destination;
 *  - a 16-bit array format to a plain GL type: channel by channel from
 *    unorm16 (_mesa_swizzle_and_convert: _mesa_unorm_to_unorm/_snorm,
 *    _mesa_unorm_to_float);
 *  - otherwise (a packed texture format or a packed type) through an
 *    RGBA intermediate: float when the destination is signed, float or
 *    wider than 8 bits (its type size for a plain type, its widest field
 *    for a packed one), else ubyte (_mesa_unpack_ubyte_rgba_row /
 *    _mesa_pack_ubyte_rgba_row).
 * Constant channels (the rebase's 0 and 1, a format's missing channel)
 * are the exact 0 and 1 of the path's type.
 */
bool fgl_pack_tex_stored(struct fgl_context *ctx, const struct fgl_pixelstore *p,
                         int width, int height, GLenum base, const uint16_t *store,
                         const uint8_t bits[4], bool array16, GLenum format, GLenum type,
                         void *pixels)
{
   (void)ctx;
   struct layout l;
   if (!get_layout(format, type, &l))
      return false;
   if (width <= 0 || height <= 0)
      return true;
   const size_t count = (size_t)width * (size_t)height;
   const bool lum = format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA;
   const bool signed_type = type == GL_BYTE || type == GL_SHORT || type == GL_INT ||
                            type == GL_FLOAT;
   const bool clamp = lum && !signed_type;

   /* the rebase (teximage_needs_rebase): L and I read as (L, 0, 0, 1), LA
    * as (L, 0, 0, A), A as (0, 0, 0, A), RGB with alpha 1 */
   uint32_t (*v)[4] = fgl_malloc_gl(ctx, count * sizeof(*v));
   uint8_t (*b)[4] = fgl_malloc_gl(ctx, count * sizeof(*b));
   if (!v || !b) {
      fgl_free(v);
      fgl_free(b);
      return false;
   }
   for (size_t i = 0; i < count; i++) {
      const uint16_t *t = store + 4 * i;
      static const int zero = -1, one = -2;
      int src[4] = { 0, 1, 2, 3 };
      switch (base) {
      case GL_LUMINANCE: case GL_INTENSITY:
         src[1] = src[2] = zero; src[3] = one; break;
      case GL_LUMINANCE_ALPHA:
         src[1] = src[2] = zero; break;
      case GL_ALPHA:
         src[0] = src[1] = src[2] = zero; break;
      case GL_RGB:
         src[3] = one; break;
      default:
         break;
      }
      for (int c = 0; c < 4; c++) {
         if (src[c] < 0) {
            v[i][c] = src[c] == one ? 1 : 0;
            b[i][c] = 0;
         } else {
            v[i][c] = t[src[c]];
            b[i][c] = bits[src[c]];
         }
      }
   }
   const size_t stride = fgl_image_row_stride(p, width, format, type);
   uint8_t *dst0 = (uint8_t *)fgl_image_address(p, pixels, width, format, type, 0, 0);
   const bool dst_array = !l.packed;
   bool via_float;
   if (dst_array) {
      via_float = signed_type || type_size(l.type) > 1;
   } else {
      int maxbits = 0;
      for (int c = 0; c < 4; c++)
         if (l.bits[c] > maxbits)
            maxbits = l.bits[c];
      via_float = maxbits > 8;
   }
   bool ok = true;
   if (!clamp && array16 && dst_array) {
      for (int y = 0; y < height; y++) {
         uint8_t *dst = dst0 + (size_t)y * stride;
         for (int x = 0; x < width; x++, dst += l.bytes) {
            const size_t i = (size_t)y * (size_t)width + (size_t)x;
            for (int ch = 0; ch < l.nchan; ch++) {
               const int c = rgba_of_channel(&l, ch);
               /* a constant 1 converts as unorm16 0xffff does, but for
                * float: exactly 1.0 */
               const bool konst = c < 0 || b[i][c] == 0;
               const uint32_t x16 = c < 0 ? 0 : konst ? (v[i][c] ? 0xffffu : 0u) : v[i][c];
               switch (l.type) {
               case GL_UNSIGNED_BYTE: dst[ch] = (uint8_t)unorm_to_unorm(x16, 16, 8); break;
               case GL_BYTE: dst[ch] = (uint8_t)unorm_to_snorm(x16, 16, 8); break;
               case GL_UNSIGNED_SHORT: store_channel_int(l.type, dst, ch, x16); break;
               case GL_SHORT: store_channel_int(l.type, dst, ch, unorm_to_snorm(x16, 16, 16)); break;
               case GL_UNSIGNED_INT: store_channel_int(l.type, dst, ch, unorm_to_unorm(x16, 16, 32)); break;
               case GL_INT: store_channel_int(l.type, dst, ch, unorm_to_snorm(x16, 16, 32)); break;
               case GL_FLOAT: {
                  const float f = konst ? (x16 ? 1.0f : 0.0f) : unorm_to_float(x16, 16);
                  memcpy(dst + 4 * ch, &f, 4);
                  break;
               }
               default: break;
               }
            }
         }
      }
   } else if (clamp || via_float) {
      float (*f)[4] = fgl_malloc_gl(ctx, (size_t)width * sizeof(*f));
      if (!f) {
         ok = false;
      } else {
         for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
               const size_t i = (size_t)y * (size_t)width + (size_t)x;
               for (int c = 0; c < 4; c++) {
                  f[x][c] = stored_to_float(v[i][c], b[i][c]);
                  if (clamp)
                     f[x][c] = clampf(f[x][c], 0.0f, 1.0f);
               }
            }
            pack_row_float(&l, (const float (*)[4])f, (size_t)width, dst0 + (size_t)y * stride);
         }
         fgl_free(f);
      }
   } else {
      uint8_t (*u)[4] = fgl_malloc_gl(ctx, (size_t)width * sizeof(*u));
      if (!u) {
         ok = false;
      } else {
         for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
               const size_t i = (size_t)y * (size_t)width + (size_t)x;
               for (int c = 0; c < 4; c++)
                  u[x][c] = stored_to_ubyte(v[i][c], b[i][c]);
            }
            pack_row_ubyte(&l, (const uint8_t (*)[4])u, (size_t)width, dst0 + (size_t)y * stride);
         }
         fgl_free(u);
      }
   }
   if (ok && p->SwapBytes)
      for (int y = 0; y < height; y++)
         swap_row(&l, type, dst0 + (size_t)y * stride, (size_t)width);
   fgl_free(v);
   fgl_free(b);
   return ok;
}

/*
 * [S: readpix.c:read_rgba_pixels, get_readpixels_transfer_ops;
 * format_utils.c:_mesa_format_convert] glReadPixels from a wide colour
 * buffer (ORACLE-NOTES.md "OSMesa contexts and buffers"; probe
 * p_osmesa_wide):
 *  - R16G16B16A16_UNORM without transfer operations or a luminance
 *    destination: the values converted straight to the destination, as
 *    glGetTexImage converts a 16-bit array texture (fgl_pack_tex_stored:
 *    plain types channel by channel, packed types through an 8-bit
 *    intermediate, or float for fields wider than 8 bits);
 *  - otherwise, and always from R32G32B32A32_FLOAT (GL_FIXED_ONLY's read
 *    clamp is a transfer operation there): RGBA float (u * (1 / 65535) or
 *    the stored float), the operations (the clamp last), L = R+G+B for a
 *    luminance destination (clamped when the clamp is on), then float to
 *    the destination.
 * `u16` or `f32`: width * height RGBA source values, rows in memory order.
 */
bool fgl_pack_wide(struct fgl_context *ctx, const struct fgl_pixelstore *p, int width,
                   int height, const uint16_t *u16, const float *f32, GLenum format,
                   GLenum type, void *pixels)
{
   struct layout l;
   if (!get_layout(format, type, &l))
      return false;
   if (width <= 0 || height <= 0)
      return true;
   const size_t count = (size_t)width * (size_t)height;
   const bool lum = format == GL_LUMINANCE || format == GL_LUMINANCE_ALPHA;
   unsigned ops = fgl_image_transfer_state(ctx);
   if (f32 || lum)
      ops |= FGL_IMAGE_CLAMP_BIT;
   if (u16 && !lum && !(ops & ~(unsigned)FGL_IMAGE_CLAMP_BIT)) {
      static const uint8_t bits16[4] = { 16, 16, 16, 16 };
      return fgl_pack_tex_stored(ctx, p, width, height, GL_RGBA, u16, bits16, true, format,
                                 type, pixels);
   }
   float (*f)[4] = fgl_malloc_gl(ctx, count * sizeof(*f));
   if (!f)
      return false;
   for (size_t i = 0; i < count; i++)
      for (int c = 0; c < 4; c++)
         f[i][c] = u16 ? unorm_to_float(u16[4 * i + (size_t)c], 16) : f32[4 * i + (size_t)c];
   fgl_apply_rgba_transfer_ops(ctx, ops, count, f);
   if (lum) {
      /* [S: pack.c:_mesa_pack_luminance_from_rgba_float] */
      for (size_t i = 0; i < count; i++) {
         const float sum = f[i][0] + f[i][1] + f[i][2];
         f[i][0] = (ops & FGL_IMAGE_CLAMP_BIT) ? clampf(sum, 0.0f, 1.0f) : sum;
      }
   }
   const size_t stride = fgl_image_row_stride(p, width, format, type);
   uint8_t *dst0 = (uint8_t *)fgl_image_address(p, pixels, width, format, type, 0, 0);
   for (int y = 0; y < height; y++)
      pack_row_float(&l, (const float (*)[4])(f + (size_t)y * (size_t)width), (size_t)width,
                     dst0 + (size_t)y * stride);
   if (p->SwapBytes)
      for (int y = 0; y < height; y++)
         swap_row(&l, type, dst0 + (size_t)y * stride, (size_t)width);
   fgl_free(f);
   return true;
}

/* ------------------------------------------------------------------ */
/* Validation [S: glformats.c]                                         */
/* ------------------------------------------------------------------ */

bool fgl_is_color_format(GLenum format)
{
   /* [S: glformats.c:_mesa_is_color_format] (the formats a desktop GL 1.x-4.x
    * client can name; compressed and sRGB ones included) */
   switch (format) {
   case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA:
   case GL_ALPHA4: case GL_ALPHA8: case GL_ALPHA12: case GL_ALPHA16:
   case 1: case GL_LUMINANCE: case GL_LUMINANCE4: case GL_LUMINANCE8:
   case GL_LUMINANCE12: case GL_LUMINANCE16:
   case 2: case GL_LUMINANCE_ALPHA: case GL_LUMINANCE4_ALPHA4: case GL_LUMINANCE6_ALPHA2:
   case GL_LUMINANCE8_ALPHA8: case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12:
   case GL_LUMINANCE16_ALPHA16:
   case GL_INTENSITY: case GL_INTENSITY4: case GL_INTENSITY8: case GL_INTENSITY12:
   case GL_INTENSITY16:
   case GL_R8: case GL_R16: case GL_RG: case GL_RG8: case GL_RG16:
   case 3: case GL_RGB: case GL_BGR: case GL_R3_G3_B2: case GL_RGB4: case GL_RGB5:
   case GL_RGB565: case GL_RGB8: case GL_RGB10: case GL_RGB12: case GL_RGB16:
   case 4: case GL_ABGR_EXT: case GL_RGBA: case GL_BGRA: case GL_RGBA2: case GL_RGBA4:
   case GL_RGB5_A1: case GL_RGBA8: case GL_RGB10_A2: case GL_RGBA12: case GL_RGBA16:
   case GL_ALPHA16F_ARB: case GL_ALPHA32F_ARB: case GL_LUMINANCE16F_ARB:
   case GL_LUMINANCE32F_ARB: case GL_LUMINANCE_ALPHA16F_ARB: case GL_LUMINANCE_ALPHA32F_ARB:
   case GL_INTENSITY16F_ARB: case GL_INTENSITY32F_ARB:
   case GL_R16F: case GL_R32F: case GL_RG16F: case GL_RG32F:
   case GL_RGB16F: case GL_RGB32F: case GL_RGBA16F: case GL_RGBA32F:
   case GL_COMPRESSED_ALPHA: case GL_COMPRESSED_LUMINANCE:
   case GL_COMPRESSED_LUMINANCE_ALPHA: case GL_COMPRESSED_INTENSITY:
   case GL_COMPRESSED_RED: case GL_COMPRESSED_RG: case GL_COMPRESSED_RGB:
   case GL_COMPRESSED_RGBA:
   case GL_RGB_S3TC: case GL_RGB4_S3TC: case GL_RGBA_S3TC: case GL_RGBA4_S3TC:
   case GL_COMPRESSED_RGB_S3TC_DXT1_EXT: case GL_COMPRESSED_RGBA_S3TC_DXT1_EXT:
   case GL_COMPRESSED_RGBA_S3TC_DXT3_EXT: case GL_COMPRESSED_RGBA_S3TC_DXT5_EXT:
   case GL_COMPRESSED_RGB_FXT1_3DFX: case GL_COMPRESSED_RGBA_FXT1_3DFX:
   case GL_SRGB: case GL_SRGB8: case GL_SRGB_ALPHA: case GL_SRGB8_ALPHA8:
   case GL_SLUMINANCE_ALPHA: case GL_SLUMINANCE8_ALPHA8: case GL_SLUMINANCE:
   case GL_SLUMINANCE8: case GL_COMPRESSED_SRGB: case GL_COMPRESSED_SRGB_ALPHA:
   case GL_COMPRESSED_SLUMINANCE: case GL_COMPRESSED_SLUMINANCE_ALPHA:
   case GL_COMPRESSED_SRGB_S3TC_DXT1_EXT: case GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT:
   case GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT: case GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT:
   case GL_COMPRESSED_RED_RGTC1: case GL_COMPRESSED_SIGNED_RED_RGTC1:
   case GL_COMPRESSED_RG_RGTC2: case GL_COMPRESSED_SIGNED_RG_RGTC2:
   case GL_COMPRESSED_LUMINANCE_LATC1_EXT: case GL_COMPRESSED_SIGNED_LUMINANCE_LATC1_EXT:
   case GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT:
   case GL_COMPRESSED_SIGNED_LUMINANCE_ALPHA_LATC2_EXT:
   case 0x8837: /* GL_COMPRESSED_LUMINANCE_ALPHA_3DC_ATI */
   case 0x8D64: /* GL_ETC1_RGB8_OES */ case GL_COMPRESSED_RGB8_ETC2: case GL_COMPRESSED_SRGB8_ETC2:
   case GL_COMPRESSED_RGBA8_ETC2_EAC: case GL_COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:
   case GL_COMPRESSED_R11_EAC: case GL_COMPRESSED_RG11_EAC:
   case GL_COMPRESSED_SIGNED_R11_EAC: case GL_COMPRESSED_SIGNED_RG11_EAC:
   case GL_COMPRESSED_RGB8_PUNCHTHROUGH_ALPHA1_ETC2:
   case GL_COMPRESSED_SRGB8_PUNCHTHROUGH_ALPHA1_ETC2:
   case GL_COMPRESSED_RGBA_BPTC_UNORM: case GL_COMPRESSED_SRGB_ALPHA_BPTC_UNORM:
   case GL_COMPRESSED_RGB_BPTC_SIGNED_FLOAT: case GL_COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT:
   case GL_R11F_G11F_B10F: case GL_RGB9_E5:
   case GL_RED_SNORM: case GL_R8_SNORM: case GL_R16_SNORM: case GL_RG_SNORM:
   case GL_RG8_SNORM: case GL_RG16_SNORM: case GL_RGB_SNORM: case GL_RGB8_SNORM:
   case GL_RGB16_SNORM: case GL_RGBA_SNORM: case GL_RGBA8_SNORM: case GL_RGBA16_SNORM:
   case GL_ALPHA_SNORM: case GL_ALPHA8_SNORM: case GL_ALPHA16_SNORM:
   case GL_LUMINANCE_SNORM: case GL_LUMINANCE8_SNORM: case GL_LUMINANCE16_SNORM:
   case GL_LUMINANCE_ALPHA_SNORM: case GL_LUMINANCE8_ALPHA8_SNORM:
   case GL_LUMINANCE16_ALPHA16_SNORM: case GL_INTENSITY_SNORM: case GL_INTENSITY8_SNORM:
   case GL_INTENSITY16_SNORM:
   case GL_RED_INTEGER: case GL_GREEN_INTEGER: case GL_BLUE_INTEGER:
   case GL_ALPHA_INTEGER: case GL_RGB_INTEGER: case GL_RGBA_INTEGER: case GL_BGR_INTEGER:
   case GL_BGRA_INTEGER: case GL_RG_INTEGER: case GL_LUMINANCE_INTEGER_EXT:
   case GL_LUMINANCE_ALPHA_INTEGER_EXT:
   case GL_RGBA32UI: case GL_RGB32UI: case GL_RG32UI: case GL_R32UI:
   case GL_RGBA16UI: case GL_RGB16UI: case GL_RG16UI: case GL_R16UI:
   case GL_RGBA8UI: case GL_RGB8UI: case GL_RG8UI: case GL_R8UI:
   case GL_RGBA32I: case GL_RGB32I: case GL_RG32I: case GL_R32I:
   case GL_RGBA16I: case GL_RGB16I: case GL_RG16I: case GL_R16I:
   case GL_RGBA8I: case GL_RGB8I: case GL_RG8I: case GL_R8I:
   case GL_RGB10_A2UI:
      return true;
   default:
      return false;
   }
}

static bool is_basic_type(GLenum type)
{
   switch (type) {
   case GL_BYTE: case GL_UNSIGNED_BYTE: case GL_SHORT: case GL_UNSIGNED_SHORT:
   case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT:
      return true;
   default:
      return false;
   }
}

/* The client formats and types the oracle's GL 4.5 context knows beyond
 * GL 1.5 with the listed EXT_abgr, EXT_bgra and EXT_packed_pixels (get.c
 * GL_EXTENSIONS): GL_RG, the *_INTEGER formats, GL_DEPTH_STENCIL,
 * GL_HALF_FLOAT(_OES), GL_UNSIGNED_INT_24_8, the packed float types.  Not
 * enums of a GL 1.5 implementation without those extensions:
 * GL_INVALID_ENUM (README "Version and honesty"; api/enum_honesty).  Any
 * other value, a GL 1.5 enum or none at all, takes the oracle's checks in
 * their order (a packed type with a format it does not fit is
 * GL_INVALID_OPERATION before an unknown format is GL_INVALID_ENUM). */
static bool foreign_format(GLenum format)
{
   switch (format) {
   case GL_RG: case GL_DEPTH_STENCIL:
   case GL_RED_INTEGER: case GL_GREEN_INTEGER: case GL_BLUE_INTEGER: case GL_ALPHA_INTEGER:
   case GL_RG_INTEGER: case GL_RGB_INTEGER: case GL_BGR_INTEGER: case GL_RGBA_INTEGER:
   case GL_BGRA_INTEGER: case GL_LUMINANCE_INTEGER_EXT: case GL_LUMINANCE_ALPHA_INTEGER_EXT:
      return true;
   default:
      return false;
   }
}

static bool foreign_type(GLenum type)
{
   switch (type) {
   case GL_HALF_FLOAT: case 0x8D61: /* GL_HALF_FLOAT_OES */
   case GL_UNSIGNED_INT_24_8: case GL_FLOAT_32_UNSIGNED_INT_24_8_REV:
   case GL_UNSIGNED_INT_10F_11F_11F_REV: case GL_UNSIGNED_INT_5_9_9_9_REV:
      return true;
   default:
      return false;
   }
}

/* [S: glformats.c:_mesa_error_check_format_and_type] for the oracle's
 * desktop context (every extension the checks ask for is on except
 * GL_MESA_ycbcr_texture), after the GL 1.5 gate above */
GLenum fgl_error_check_format_and_type(const struct fgl_context *ctx, GLenum format,
                                       GLenum type)
{
   (void)ctx;
   if (foreign_format(format) || foreign_type(type))
      return GL_INVALID_ENUM;

   /* special type-based checks (the foreign formats and types gone) */
   switch (type) {
   case GL_BITMAP:
      if (format != GL_COLOR_INDEX && format != GL_STENCIL_INDEX)
         return GL_INVALID_ENUM;
      break;
   case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV:
   case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV:
      if (format == GL_RGB)
         break;
      return GL_INVALID_OPERATION;
   case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
   case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
      if (format == GL_RGBA || format == GL_BGRA || format == GL_ABGR_EXT)
         break;
      return GL_INVALID_OPERATION;
   case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV:
   case GL_UNSIGNED_INT_10_10_10_2: case GL_UNSIGNED_INT_2_10_10_10_REV:
      if (format == GL_RGBA || format == GL_BGRA)
         break;
      return GL_INVALID_OPERATION;
   default:
      break;
   }

   switch (format) {
   case GL_COLOR_INDEX: case GL_STENCIL_INDEX:
      return is_basic_type(type) || type == GL_BITMAP ? GL_NO_ERROR : GL_INVALID_ENUM;
   case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE:
   case GL_LUMINANCE_ALPHA: case GL_DEPTH_COMPONENT: case GL_BGR:
      return is_basic_type(type) ? GL_NO_ERROR : GL_INVALID_ENUM;
   case GL_RGB:
      switch (type) {
      case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV:
      case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV:
         return GL_NO_ERROR;
      default:
         return is_basic_type(type) ? GL_NO_ERROR : GL_INVALID_ENUM;
      }
   case GL_RGBA: case GL_BGRA:
      switch (type) {
      case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
      case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV:
      case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
      case GL_UNSIGNED_INT_10_10_10_2: case GL_UNSIGNED_INT_2_10_10_10_REV:
         return GL_NO_ERROR;
      default:
         return is_basic_type(type) ? GL_NO_ERROR : GL_INVALID_ENUM;
      }
   case GL_ABGR_EXT:
      switch (type) {
      case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
      case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
         return GL_NO_ERROR;
      default:
         return is_basic_type(type) ? GL_NO_ERROR : GL_INVALID_ENUM;
      }
   default:
      return GL_INVALID_ENUM;
   }
}
