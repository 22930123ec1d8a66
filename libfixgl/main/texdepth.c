/*
 * Depth texture images (GL 1.4, ARB_depth_texture; Mesa 22.3
 * main/texstore.c _mesa_texstore_z16, _mesa_texstore_x8_z24,
 * _mesa_texstore_z32, main/pack.c _mesa_unpack_depth_span,
 * main/texgetimage.c get_tex_depth, get_tex_memcpy,
 * state_tracker/st_cb_texture.c fallback_copy_texsubimage).
 *
 * A GL_DEPTH_COMPONENT image keeps the values the oracle stores
 * (img->ZValues) in the pipe format st_choose_format picks for it
 * (ORACLE-NOTES.md "Depth textures and shadow comparison"; teximage.c
 * maps the internal formats):
 *   GL_DEPTH_COMPONENT16               Z16_UNORM   (16 bits)
 *   GL_DEPTH_COMPONENT24               Z24X8_UNORM (24 bits)
 *   GL_DEPTH_COMPONENT32               Z32_UNORM   (32 bits)
 *   GL_DEPTH_COMPONENT with GL_UNSIGNED_SHORT data  Z16_UNORM
 *                      with GL_UNSIGNED_INT data    Z32_UNORM
 *                      with any other type          Z24X8_UNORM
 * The sampler reads them as floats (r_state.h r_tex_depth_value).
 */
#include <math.h>
#include <string.h>

#include "main/groups.h"
#include "main/pixelformat.h"
#include "fgl_alloc.h"
#include "math/m_gallivm.h"

/* [S: pack.c:_mesa_unpack_depth_span] n values of `type` at src to the
 * depth values of a format of `bits` bits (depthMax 2^bits - 1):
 *  - without scale and bias, GL_UNSIGNED_INT into 16 bits keeps the top
 *    16 bits and GL_UNSIGNED_SHORT into 32 bits replicates (no byte swap
 *    on these two paths); the type of the format itself is copied
 *    (_mesa_texstore_can_use_memcpy, without byte swapping);
 *  - otherwise each value goes to float (the conversions, scale, bias and
 *    clamp of fgl_unpack_depth_span_float; GL_UNSIGNED_INT in double,
 *    UINT_TO_FLOAT) and then to the integer (GLuint)(d * (float)depthMax)
 *    up to 24 bits, (GLuint)(d * (double)depthMax) for 32 (saturated). */
static void unpack_depth_row(struct fgl_context *ctx, const struct fgl_pixelstore *p, int n,
                             GLenum type, const uint8_t *src, int bits, float *tmp,
                             uint32_t *dst)
{
   const bool identity = ctx->Pixel.DepthScale == 1.0f && ctx->Pixel.DepthBias == 0.0f;
   if (identity) {
      if (type == GL_UNSIGNED_INT && bits == 16) {
         for (int i = 0; i < n; i++) {
            uint32_t v;
            memcpy(&v, src + 4 * (size_t)i, 4);
            dst[i] = v >> 16;
         }
         return;
      }
      if (type == GL_UNSIGNED_SHORT && bits == 32) {
         for (int i = 0; i < n; i++) {
            uint16_t v;
            memcpy(&v, src + 2 * (size_t)i, 2);
            dst[i] = (uint32_t)v | ((uint32_t)v << 16);
         }
         return;
      }
      if (!p->SwapBytes && type == GL_UNSIGNED_SHORT && bits == 16) {
         for (int i = 0; i < n; i++) {
            uint16_t v;
            memcpy(&v, src + 2 * (size_t)i, 2);
            dst[i] = v;
         }
         return;
      }
      if (!p->SwapBytes && type == GL_UNSIGNED_INT && bits == 32) {
         memcpy(dst, src, 4 * (size_t)n);
         return;
      }
   }
   fgl_unpack_depth_span_float(ctx, p, (size_t)n, type, src, tmp);
   if (type == GL_UNSIGNED_INT) {
      /* UINT_TO_FLOAT: (GLfloat)(u * (1.0F / 4294967295.0)), in double */
      for (int i = 0; i < n; i++) {
         uint32_t v;
         memcpy(&v, src + 4 * (size_t)i, 4);
         if (p->SwapBytes)
            v = __builtin_bswap32(v);
         float d = (float)((double)v * (1.0 / 4294967295.0));
         if (!identity) {
            d = d * ctx->Pixel.DepthScale + ctx->Pixel.DepthBias;
            d = d > 0.0f ? (d > 1.0f ? 1.0f : d) : 0.0f;
         }
         tmp[i] = d;
      }
   }
   if (bits == 32) {
      for (int i = 0; i < n; i++) {
         const double z = (double)tmp[i] * 4294967295.0;
         dst[i] = z >= 4294967295.0 ? 0xffffffffu : (uint32_t)z;
      }
      return;
   }
   const float max = bits == 16 ? 65535.0f : (float)0xffffff;
   for (int i = 0; i < n; i++)
      dst[i] = (uint32_t)(tmp[i] * max);
}

bool fgl_tex_store_depth(struct fgl_context *ctx, struct fgl_texture_image *img,
                         const struct fgl_pixelstore *unpack, int x, int y, int z, int w,
                         int h, GLenum type, const void *pixels)
{
   switch (type) {
   case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_SHORT: case GL_SHORT:
   case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT:
      break;
   default:
      return false;
   }
   float *tmp = fgl_malloc_gl(ctx, (size_t)w * sizeof(float));
   if (!tmp) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return true;
   }
   const int bits = fgl_tex_image_depth_bits(img);
   for (int j = 0; j < h; j++) {
      const uint8_t *src = fgl_image_address(unpack, pixels, w, GL_DEPTH_COMPONENT, type, j, 0);
      const size_t at = ((size_t)z * (size_t)img->Height + (size_t)(y + j)) * (size_t)img->Width +
                        (size_t)x;
      unpack_depth_row(ctx, unpack, w, type, src, bits, tmp, img->ZValues + at);
   }
   fgl_free(tmp);
   return true;
}

/* [S: format_unpack.c:_mesa_unpack_float_z_row] a stored value as
 * glGetTexImage converts it: Z16 z * (1.0F / 0xffff) in float, Z24 and
 * Z32 in double */
static float depth_to_float(uint32_t z, int bits)
{
   if (bits == 16)
      return (float)z * (1.0f / 65535.0f);
   if (bits == 24)
      return (float)((double)z * (1.0 / (double)0xffffff));
   return (float)((double)z * (1.0 / (double)0xffffffffu));
}

void fgl_tex_get_depth(struct fgl_context *ctx, const struct fgl_texture_image *img, int z,
                       GLenum type, void *dst)
{
   const int bits = fgl_tex_image_depth_bits(img);
   const int w = img->Width, h = img->Height;
   const struct fgl_pixelstore *p = &ctx->Pack;
   /* [S: texgetimage.c:get_tex_memcpy] the format's own type is copied
    * (_mesa_format_matches_format_and_type: no byte swapping; the depth
    * scale and bias are not applied) */
   const bool copy = !p->SwapBytes && ((bits == 16 && type == GL_UNSIGNED_SHORT) ||
                                       (bits == 32 && type == GL_UNSIGNED_INT));
   float *row = copy ? NULL : fgl_malloc_gl(ctx, (size_t)w * sizeof(float));
   if (!copy && !row) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   for (int j = 0; j < h; j++) {
      const uint32_t *src = img->ZValues + ((size_t)z * (size_t)h + (size_t)j) * (size_t)w;
      uint8_t *out = (uint8_t *)fgl_image_address(p, dst, w, GL_DEPTH_COMPONENT, type, j, 0);
      if (copy) {
         for (int i = 0; i < w; i++) {
            if (bits == 16) {
               const uint16_t v = (uint16_t)src[i];
               memcpy(out + 2 * (size_t)i, &v, 2);
            } else {
               memcpy(out + 4 * (size_t)i, &src[i], 4);
            }
         }
         continue;
      }
      for (int i = 0; i < w; i++)
         row[i] = depth_to_float(src[i], bits);
      fgl_pack_depth_span(ctx, p, (size_t)w, type, row, out);
   }
   fgl_free(row);
}

/* [S: st_cb_texture.c:st_CopyTexSubImage, util/u_blitter.c
 * util_blitter_blit (the depth blit's fragment shader),
 * gallivm/lp_bld_conv.c lp_build_clamped_float_to_unsigned_norm] the copy
 * is a blit: each depth buffer value is sampled as a float (Z16:
 * z * (float)(1/65535), Z24: z * (float)(1/16777215)) and written as the
 * fragment's depth into the texture's format: 16 bits through gallivm's
 * magic-number rounding, 24 bits RNE(d * 16777215), 32 bits
 * (uint)(d * 2^31) shifted left by one minus its top bit (measured:
 * copies from 16- and 24-bit buffers into every depth format, texture
 * shadow/copy_from_depth*). */
static uint32_t blit_depth(float d, int bits)
{
   if (bits == 16)
      return m_gallivm_float_to_unorm16(d);
   if (bits == 24)
      return (uint32_t)r_round_even(d * 16777215.0f);
   const float f = d * 2147483648.0f;
   const uint32_t u = f >= 2147483648.0f ? 0x80000000u : (uint32_t)(int32_t)f;
   return (u << 1) - (u >> 31);
}

void fgl_tex_copy_depth(struct fgl_context *ctx, struct fgl_texture_image *img, GLint xoff,
                        GLint yoff, GLint zoff, GLint x, GLint y, GLsizei w, GLsizei h)
{
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   if (!fb || !fb->Depth)
      return;
   const int bits = fgl_tex_image_depth_bits(img);
   /* [S: st_cb_texture.c:fallback_copy_texsubimage, util/u_tile.c
    * pipe_get_tile_z, pipe_put_tile_z, pixeltransfer.c
    * _mesa_scale_and_bias_depth_uint] with a colour transfer operation on
    * (_ImageTransferState) or a depth scale or bias the copy is done on the
    * CPU: each value widened to 32 bits (Z16: z * 0x10001, Z24:
    * (z << 8) | (z >> 16)), scaled and biased in double (z * scale +
    * bias * 0xffffffff, clamped, truncated), narrowed by a shift */
   const double scale = ctx->Pixel.DepthScale, bias = ctx->Pixel.DepthBias;
   const bool sb = scale != 1.0 || bias != 0.0;
   const bool cpu = sb || fgl_image_transfer_state(ctx) != 0;
   for (GLint j = 0; j < h; j++) {
      const size_t row = (size_t)(fb->Height - 1 - (y + j));   /* y-down buffer row */
      uint32_t *dst = img->ZValues +
                      ((size_t)zoff * (size_t)img->Height + (size_t)(yoff + j)) *
                         (size_t)img->Width + (size_t)xoff;
      for (GLint i = 0; i < w; i++) {
         const size_t idx = row * (size_t)fb->Width + (size_t)(x + i);
         if (cpu) {
            uint32_t z32;
            if (fb->ZSFormat == R_ZS_Z16) {
               z32 = (uint32_t)((const uint16_t *)fb->Depth)[idx] * 0x10001u;
            } else if (fb->ZSFormat == R_ZS_Z32) {
               z32 = ((const uint32_t *)fb->Depth)[idx];
            } else {
               const uint32_t z = ((const uint32_t *)fb->Depth)[idx] & 0xffffffu;
               z32 = (z << 8) | (z >> 16);
            }
            if (sb) {
               double d = (double)z32 * scale + bias * 4294967295.0;
               d = d < 0.0 ? 0.0 : d > 4294967295.0 ? 4294967295.0 : d;
               z32 = (uint32_t)d;
            }
            dst[i] = bits == 32 ? z32 : z32 >> (32 - bits);
            continue;
         }
         if (fb->ZSFormat == R_ZS_Z32) {
            /* a Z32_UNORM buffer: into a Z32_UNORM texture the blit is a
             * plain copy (llvmpipe's lp_blit takes
             * util_try_blit_via_copy_region for equal formats), into the
             * others the value is sampled through its top 23 bits */
            const uint32_t z = ((const uint32_t *)fb->Depth)[idx];
            dst[i] = bits == 32 ? z : blit_depth(r_tex_depth_value(z, 32), bits);
            continue;
         }
         const float d =
            fb->ZSFormat == R_ZS_Z16
               ? (float)((const uint16_t *)fb->Depth)[idx] * (float)(1.0 / 65535.0)
               : (float)(((const uint32_t *)fb->Depth)[idx] & 0xffffffu) *
                    (float)(1.0 / 16777215.0);
         dst[i] = blit_depth(d, bits);
      }
   }
   fgl_tex_object_changed(ctx);
}

/* [S: st_atom_sampler.c:st_convert_sampler, st_sampler_view.c:
 * compute_texture_format_swizzle; ff_fragment_shader.cpp make_state_key]
 * the sampler of a depth texture: llvmpipe samples its formats (none fits
 * 8-bit unorm) on the float path; GL_COMPARE_R_TO_TEXTURE makes a shadow
 * sampler; GL_DEPTH_TEXTURE_MODE is the view's swizzle (LUMINANCE: XXX1,
 * INTENSITY: XXXX, ALPHA: 000X as fixed function is no GLSL 1.30); the
 * border colour replaces the format's only channel (R). */
void fgl_update_texture_depth(const struct fgl_texture_object *t, struct r_texture *rt)
{
   rt->depth_bits = (uint8_t)fgl_tex_image_depth_bits(t->Image[rt->first_level]);
   rt->float_path = true;
   rt->soa = true;
   rt->border_mask = 1;
   rt->compare = t->CompareMode == GL_COMPARE_R_TO_TEXTURE;
   rt->compare_func = (uint8_t)(rt->compare ? t->CompareFunc - GL_NEVER : 0);
   static const uint8_t swz[3][4] = {
      { R_SWZ_X, R_SWZ_X, R_SWZ_X, R_SWZ_1 },   /* GL_LUMINANCE */
      { R_SWZ_X, R_SWZ_X, R_SWZ_X, R_SWZ_X },   /* GL_INTENSITY */
      { R_SWZ_0, R_SWZ_0, R_SWZ_0, R_SWZ_X },   /* GL_ALPHA */
   };
   const int m = t->DepthMode == GL_INTENSITY ? 1 : t->DepthMode == GL_ALPHA ? 2 : 0;
   memcpy(rt->depth_swizzle, swz[m], 4);
}

/* [S: st_gen_mipmap.c:st_generate_mipmap, util/u_gen_mipmap.c
 * util_gen_mipmap (blit.mask PIPE_MASK_Z, PIPE_TEX_FILTER_LINEAR)] a
 * GL_GENERATE_MIPMAP level of a depth texture: the level above sampled
 * bilinearly at each texel centre (CLAMP_TO_EDGE) on the float path, the
 * depth values as the sampler reads them, lerped fused along s on both
 * rows then along t, written as the blit's fragment depth (blit_depth). */
static void edge_linear(float c, int n, int *x0, int *x1, float *w)
{
   c = fminf(c * (float)n, (float)n) - 0.5f;
   c = fmaxf(c, 0.0f);
   const float ip = floorf(c);
   *w = c - ip;
   *x0 = (int)ip;
   *x1 = *x0 + 1 < n - 1 ? *x0 + 1 : n - 1;
}

void fgl_tex_gen_mip_depth(const struct fgl_texture_image *src, struct fgl_texture_image *dst)
{
   const int bits = fgl_tex_image_depth_bits(src);
   const int W = src->Width, H = src->Height, w = dst->Width, h = dst->Height;
   struct fgl_blit_quad bq;
   fgl_blit_quad_init(&bq, w, h);   /* the blit quad's coordinates */
   for (int j = 0; j < h; j++) {
      for (int i = 0; i < w; i++) {
         int x0, x1, y0, y1;
         float ws, wt, s, t;
         fgl_blit_quad_coord(&bq, i, j, &s, &t);
         edge_linear(s, W, &x0, &x1, &ws);
         edge_linear(t, H, &y0, &y1, &wt);
         const uint32_t *r0 = src->ZValues + (size_t)y0 * (size_t)W;
         const uint32_t *r1 = src->ZValues + (size_t)y1 * (size_t)W;
         const float v00 = r_tex_depth_value(r0[x0], bits), v01 = r_tex_depth_value(r0[x1], bits);
         const float v10 = r_tex_depth_value(r1[x0], bits), v11 = r_tex_depth_value(r1[x1], bits);
         const float a = fmaf(ws, v01 - v00, v00), b = fmaf(ws, v11 - v10, v10);
         dst->ZValues[(size_t)j * (size_t)w + (size_t)i] = blit_depth(fmaf(wt, b - a, a), bits);
      }
   }
}
