/*
 * Texture images (Mesa 22.3 main/teximage.c, texstore.c, texgetimage.c,
 * texparam.c, state_tracker/st_format.c, st_cb_texture.c):
 * glTexImage1D/2D/3D, glTexSubImage1D/2D/3D, glCopyTexImage1D/2D,
 * glCopyTexSubImage1D/2D/3D (and GL_EXT_texture3D's names), glGetTexImage,
 * glGetTexLevelParameter{fv,iv}.  A 3D image is Depth slices of
 * Width x Height texels, each unpacked and packed as a 2D image at the
 * offset of its slice (GL_*_IMAGE_HEIGHT, GL_*_SKIP_IMAGES).
 *
 * Images are stored as RGBA8 texels expanded from their base format
 * (struct fgl_texture_image).  The oracle stores each image in the pipe
 * format st_choose_format picks for the internal format (and, for unsized
 * internal formats, the client format/type); for a format of other than
 * 8 bits per channel fixgl keeps the stored values in their own precision
 * (img->Store, StoreBits) and their 8-bit expansion as llvmpipe's AoS
 * sampler and glGetTexImage's 8-bit conversions expand them (img->Data),
 * so that every value the oracle can read back is the one fixgl holds.
 */
/* GL_EXT_texture3D's names are declared by <GL/glext.h> only with
 * GL_GLEXT_PROTOTYPES */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "main/dlist.h"
#include "main/groups.h"
#include "main/pixelformat.h"
#include "main/texcompress_s3tc.h"
#include "fgl_alloc.h"
#include "math/m_gallivm.h"

/* An image and everything it owns (NULL: nothing).  Its texels are
 * reference-counted blocks (fgl_rc_alloc): a state object of a context
 * that samples them holds them (state.c update_tex_units), so a pending
 * scene of another context sharing the texture reads them until its
 * flush, whatever this context does to the image. */
static void free_image(struct fgl_texture_image *img)
{
   if (!img)
      return;
   fgl_rc_release(img->Data);
   fgl_rc_release(img->Store);
   fgl_rc_release(img->ZValues);
   fgl_free(img->Blocks);
   fgl_free(img);
}

void fgl_free_tex_images(struct fgl_texture_object *t)
{
   for (unsigned f = 0; f < 6; f++) {
      for (int l = 0; l < FGL_MAX_TEXTURE_LEVELS; l++) {
         struct fgl_texture_image **slot = fgl_tex_face_slot(t, f, l);
         free_image(*slot);
         *slot = NULL;
      }
   }
}

/* ------------------------------------------------------------------ */
/* Internal formats                                                   */
/* ------------------------------------------------------------------ */

/* The pipe formats llvmpipe gets for the legacy internal formats
 * [S: st_format.c:format_map, st_choose_format; the bits checked against
 * the oracle's GL_TEXTURE_*_SIZE]: bits of R, G, B, A, L, I and bytes
 * per texel (the size llvmpipe_can_create_resource weighs). */
struct fgl_tex_pipe_format {
   uint8_t r, g, b, a, l, i;
   uint8_t bytes;
   /* how glCopyTexImage stores the colour buffer's 8-bit channels
    * (enum fgl_copy_rule): as texstore rounds them, or as the blit's
    * conversion into the format as a render target does */
   uint8_t copy_rule;
};

/* [S: llvmpipe/lp_state_fs.c: convert_from_blend_type, scale_bits]
 * st_CopyTexSubImage blits into the formats llvmpipe renders to; the
 * blend stage's 8-bit channels go to n bits by a single shift
 * (x >> (8 - n); measured: every 8-bit value into B5G5R5X1, B5G5R5A1,
 * B5G6R5) or, for B2G3R3, by the rounded rescale
 * ((x >> n) * (2^n - 1) + 2^(7 - n)) >> (8 - n) (measured: every 8-bit
 * value; probe p_copy_tex); the 10-bit channels of 10-10-10-2 through
 * the 16-bit blend type, (unorm16 of x * (1/255)) >> 6 (measured: every
 * 8-bit value; its 2-bit alpha rounds as texstore does) */
enum fgl_copy_rule { COPY_TEXSTORE, COPY_TRUNCATE, COPY_RESCALE, COPY_WIDE };

static const struct fgl_tex_pipe_format PF_RGBA8 = { 8, 8, 8, 8, 0, 0, 4, false };
static const struct fgl_tex_pipe_format PF_RGBX8 = { 8, 8, 8, 0, 0, 0, 4, false };
static const struct fgl_tex_pipe_format PF_RGBA16 = { 16, 16, 16, 16, 0, 0, 8, false };
static const struct fgl_tex_pipe_format PF_RGBX16 = { 16, 16, 16, 0, 0, 0, 8, false };
static const struct fgl_tex_pipe_format PF_RGB10A2 = { 10, 10, 10, 2, 0, 0, 4, COPY_WIDE };
static const struct fgl_tex_pipe_format PF_RGB10X2 = { 10, 10, 10, 0, 0, 0, 4, COPY_WIDE };
static const struct fgl_tex_pipe_format PF_RGBA4 = { 4, 4, 4, 4, 0, 0, 2, false };
static const struct fgl_tex_pipe_format PF_RGBX4 = { 4, 4, 4, 0, 0, 0, 2, false };
static const struct fgl_tex_pipe_format PF_RGB5A1 = { 5, 5, 5, 1, 0, 0, 2, COPY_TRUNCATE };
static const struct fgl_tex_pipe_format PF_RGB5X1 = { 5, 5, 5, 0, 0, 0, 2, COPY_TRUNCATE };
static const struct fgl_tex_pipe_format PF_RGB565 = { 5, 6, 5, 0, 0, 0, 2, COPY_TRUNCATE };
static const struct fgl_tex_pipe_format PF_RGB332 = { 3, 3, 2, 0, 0, 0, 1, COPY_RESCALE };
static const struct fgl_tex_pipe_format PF_L8 = { 0, 0, 0, 0, 8, 0, 1, false };
static const struct fgl_tex_pipe_format PF_L16 = { 0, 0, 0, 0, 16, 0, 2, false };
static const struct fgl_tex_pipe_format PF_A8 = { 0, 0, 0, 8, 0, 0, 1, false };
static const struct fgl_tex_pipe_format PF_A16 = { 0, 0, 0, 16, 0, 0, 2, false };
static const struct fgl_tex_pipe_format PF_L8A8 = { 0, 0, 0, 8, 8, 0, 2, false };
static const struct fgl_tex_pipe_format PF_L4A4 = { 0, 0, 0, 4, 4, 0, 1, false };
static const struct fgl_tex_pipe_format PF_L16A16 = { 0, 0, 0, 16, 16, 0, 4, false };
static const struct fgl_tex_pipe_format PF_I8 = { 0, 0, 0, 0, 0, 8, 1, false };
static const struct fgl_tex_pipe_format PF_I16 = { 0, 0, 0, 0, 0, 16, 2, false };
/* the depth formats (no colour channel; main/texdepth.c): Z16_UNORM,
 * Z24X8_UNORM, Z32_UNORM */
static const struct fgl_tex_pipe_format PF_Z16 = { 0, 0, 0, 0, 0, 0, 2, false };
static const struct fgl_tex_pipe_format PF_Z24 = { 0, 0, 0, 0, 0, 0, 4, false };
static const struct fgl_tex_pipe_format PF_Z32 = { 0, 0, 0, 0, 0, 0, 4, false };
/* [S: formats.c: MESA_FORMAT_RGB_DXT1 .. RGBA_DXT5] the channel sizes the
 * oracle reports for the S3TC formats (4 bits; no alpha for DXT1 RGB);
 * their texels are 8-bit (Data, decoded from Blocks), nothing is stored
 * in other precisions */
static const struct fgl_tex_pipe_format PF_DXT_RGB = { 4, 4, 4, 0, 0, 0, 1, false };
static const struct fgl_tex_pipe_format PF_DXT_RGBA = { 4, 4, 4, 4, 0, 0, 1, false };
/* [S: formats.csv: MESA_FORMAT_L_LATC1_UNORM, MESA_FORMAT_LA_LATC2_UNORM]
 * the LATC formats GL_COMPRESSED_LUMINANCE(_ALPHA) are stored in */
static const struct fgl_tex_pipe_format PF_LATC1 = { 0, 0, 0, 0, 8, 0, 1, false };
static const struct fgl_tex_pipe_format PF_LATC2 = { 0, 0, 0, 8, 8, 0, 1, false };

struct tex_format {
   GLint internal;
   GLenum base;
   const struct fgl_tex_pipe_format *pf;
};

/* [S: glformats.c:_mesa_base_tex_format; st_format.c:format_map] */
static const struct tex_format tex_formats[] = {
   { 1, GL_LUMINANCE, &PF_L8 },
   { 2, GL_LUMINANCE_ALPHA, &PF_L8A8 },
   { 3, GL_RGB, &PF_RGBX8 },
   { 4, GL_RGBA, &PF_RGBA8 },
   { GL_ALPHA, GL_ALPHA, &PF_A8 },
   { GL_ALPHA4, GL_ALPHA, &PF_A8 },
   { GL_ALPHA8, GL_ALPHA, &PF_A8 },
   { GL_ALPHA12, GL_ALPHA, &PF_A16 },
   { GL_ALPHA16, GL_ALPHA, &PF_A16 },
   { GL_LUMINANCE, GL_LUMINANCE, &PF_L8 },
   { GL_LUMINANCE4, GL_LUMINANCE, &PF_L8 },
   { GL_LUMINANCE8, GL_LUMINANCE, &PF_L8 },
   { GL_LUMINANCE12, GL_LUMINANCE, &PF_L16 },
   { GL_LUMINANCE16, GL_LUMINANCE, &PF_L16 },
   { GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, &PF_L8A8 },
   { GL_LUMINANCE4_ALPHA4, GL_LUMINANCE_ALPHA, &PF_L4A4 },
   { GL_LUMINANCE6_ALPHA2, GL_LUMINANCE_ALPHA, &PF_L8A8 },
   { GL_LUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA, &PF_L8A8 },
   { GL_LUMINANCE12_ALPHA4, GL_LUMINANCE_ALPHA, &PF_L16A16 },
   { GL_LUMINANCE12_ALPHA12, GL_LUMINANCE_ALPHA, &PF_L16A16 },
   { GL_LUMINANCE16_ALPHA16, GL_LUMINANCE_ALPHA, &PF_L16A16 },
   { GL_INTENSITY, GL_INTENSITY, &PF_I8 },
   { GL_INTENSITY4, GL_INTENSITY, &PF_I8 },
   { GL_INTENSITY8, GL_INTENSITY, &PF_I8 },
   { GL_INTENSITY12, GL_INTENSITY, &PF_I16 },
   { GL_INTENSITY16, GL_INTENSITY, &PF_I16 },
   { GL_RGB, GL_RGB, &PF_RGBX8 },
   { GL_R3_G3_B2, GL_RGB, &PF_RGB332 },
   { GL_RGB4, GL_RGB, &PF_RGBX4 },
   { GL_RGB5, GL_RGB, &PF_RGB5X1 },
   { GL_RGB565, GL_RGB, &PF_RGB565 },
   { GL_RGB8, GL_RGB, &PF_RGBX8 },
   { GL_RGB10, GL_RGB, &PF_RGB10X2 },
   { GL_RGB12, GL_RGB, &PF_RGBX16 },
   { GL_RGB16, GL_RGB, &PF_RGBX16 },
   { GL_RGBA, GL_RGBA, &PF_RGBA8 },
   { GL_RGBA2, GL_RGBA, &PF_RGBA4 },
   { GL_RGBA4, GL_RGBA, &PF_RGBA4 },
   { GL_RGB5_A1, GL_RGBA, &PF_RGB5A1 },
   { GL_RGBA8, GL_RGBA, &PF_RGBA8 },
   { GL_RGB10_A2, GL_RGBA, &PF_RGB10A2 },
   { GL_RGBA12, GL_RGBA, &PF_RGBA16 },
   { GL_RGBA16, GL_RGBA, &PF_RGBA16 },
   /* [S: st_format.c:format_map, DEFAULT_DEPTH_FORMATS] */
   { GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, &PF_Z24 },
   { GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, &PF_Z16 },
   { GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, &PF_Z24 },
   { GL_DEPTH_COMPONENT32, GL_DEPTH_COMPONENT, &PF_Z32 },
   /* GL_EXT_texture_compression_s3tc: 2D and cube-map images only
    * (s3tc_format_of), compressed by the oracle's encoder */
   { GL_COMPRESSED_RGB_S3TC_DXT1_EXT, GL_RGB, &PF_DXT_RGB },
   { GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, GL_RGBA, &PF_DXT_RGBA },
   { GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, GL_RGBA, &PF_DXT_RGBA },
   { GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, GL_RGBA, &PF_DXT_RGBA },
   /* the generic compressed formats (GL 1.3): llvmpipe stores ALPHA and
    * INTENSITY uncompressed; RGB and RGBA images of 2D targets it
    * compresses as DXT1 RGB and DXT5 (s3tc_format_of; of 1D and 3D
    * targets they stay uncompressed here); LUMINANCE and LUMINANCE_ALPHA
    * it compresses as LATC1/LATC2, which fixgl does not model: it stores
    * them uncompressed, as GL 1.3 allows, so their texels are the
    * application's, not the oracle's lossy ones (README status, issue 19) */
   { GL_COMPRESSED_ALPHA, GL_ALPHA, &PF_A8 },
   { GL_COMPRESSED_INTENSITY, GL_INTENSITY, &PF_I8 },
   { GL_COMPRESSED_LUMINANCE, GL_LUMINANCE, &PF_L8 },
   { GL_COMPRESSED_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, &PF_L8A8 },
   { GL_COMPRESSED_RGB, GL_RGB, &PF_RGBX8 },
   { GL_COMPRESSED_RGBA, GL_RGBA, &PF_RGBA8 },
};

/* [S: util/format/u_format.c:util_format_fits_8unorm; llvmpipe's
 * lp_bld_sample_soa.c picks its AoS 8-bit path only for such formats]
 * whether no channel of the image's oracle format is wider than 8 bits:
 * the 12/16-bit and 10-10-10-2 formats are sampled on the float path
 * (texture/image_rendered_wide) */
bool fgl_tex_image_fits_unorm8(const struct fgl_texture_image *img)
{
   const struct fgl_tex_pipe_format *pf = img->Format;
   return !pf || (pf->r <= 8 && pf->g <= 8 && pf->b <= 8 && pf->a <= 8 && pf->l <= 8 &&
                  pf->i <= 8);
}

int fgl_tex_image_depth_bits(const struct fgl_texture_image *img)
{
   const struct fgl_tex_pipe_format *pf = img->Format;
   return pf == &PF_Z16 ? 16 : pf == &PF_Z24 ? 24 : pf == &PF_Z32 ? 32 : 0;
}

static const struct tex_format *find_format(GLint internal)
{
   for (size_t i = 0; i < sizeof(tex_formats) / sizeof(tex_formats[0]); i++)
      if (tex_formats[i].internal == internal)
         return &tex_formats[i];
   return NULL;
}

static bool is_depth_format(GLenum f)
{
   return f == GL_DEPTH_COMPONENT || f == GL_DEPTH_COMPONENT16 ||
          f == GL_DEPTH_COMPONENT24 || f == GL_DEPTH_COMPONENT32;
}

static bool is_depthstencil_format(GLenum f)
{
   return f == GL_DEPTH_STENCIL || f == GL_DEPTH24_STENCIL8;
}

/* [S: teximage.c:texture_formats_agree] */
static bool formats_agree(GLint internal, GLenum format)
{
   const bool int_depth = is_depth_format((GLenum)internal) ||
                          is_depthstencil_format((GLenum)internal);
   const bool fmt_depth = is_depth_format(format) || is_depthstencil_format(format);
   if (!int_depth && !fgl_is_color_format(format) && format != GL_COLOR_INDEX)
      return false;
   return int_depth == fmt_depth;
}

/* [S: st_format.c:st_choose_format] an unsized internal format with an
 * unsigned client type takes the pipe format matching the client data
 * when its base format is the internal format; GL_RGB/GL_RGBA with the
 * 5_5_5_1 or 2_10_10_10_REV types become RGB5/RGB5_A1 and RGB10/RGB10_A2. */
static const struct fgl_tex_pipe_format *choose_pipe_format(const struct tex_format *tf,
                                                 GLenum format, GLenum type)
{
   const GLint in = tf->internal;
   if (in == GL_RGBA) {
      if ((format == GL_RGBA && (type == GL_UNSIGNED_SHORT_4_4_4_4 ||
                                 type == GL_UNSIGNED_SHORT_4_4_4_4_REV)) ||
          (format == GL_BGRA && type == GL_UNSIGNED_SHORT_4_4_4_4_REV))
         return &PF_RGBA4;
      if ((format == GL_RGBA && type == GL_UNSIGNED_INT_10_10_10_2) ||
          type == GL_UNSIGNED_INT_2_10_10_10_REV)
         return &PF_RGB10A2;
      if (type == GL_UNSIGNED_SHORT_5_5_5_1 ||
          (format == GL_BGRA && type == GL_UNSIGNED_SHORT_1_5_5_5_REV))
         return &PF_RGB5A1;
      if (format == GL_RGBA && type == GL_UNSIGNED_SHORT)
         return &PF_RGBA16;
   } else if (in == GL_RGB) {
      if (format == GL_RGB && (type == GL_UNSIGNED_SHORT_5_6_5 ||
                               type == GL_UNSIGNED_SHORT_5_6_5_REV))
         return &PF_RGB565;
      if (format == GL_RGB && (type == GL_UNSIGNED_BYTE_3_3_2 ||
                               type == GL_UNSIGNED_BYTE_2_3_3_REV))
         return &PF_RGB332;
      if (type == GL_UNSIGNED_SHORT_5_5_5_1)
         return &PF_RGB5X1;
      if (type == GL_UNSIGNED_INT_2_10_10_10_REV)
         return &PF_RGB10X2;
   } else if (in == GL_DEPTH_COMPONENT) {
      /* st_choose_matching_format: Z_UNORM16, Z_UNORM32 (measured: every
       * type, GL_TEXTURE_DEPTH_SIZE and the values read back) */
      if (type == GL_UNSIGNED_SHORT)
         return &PF_Z16;
      if (type == GL_UNSIGNED_INT)
         return &PF_Z32;
   } else if (type == GL_UNSIGNED_SHORT && format == (GLenum)in) {
      if (in == GL_LUMINANCE)
         return &PF_L16;
      if (in == GL_ALPHA)
         return &PF_A16;
      if (in == GL_LUMINANCE_ALPHA)
         return &PF_L16A16;
   }
   return tf->pf;
}

/* ------------------------------------------------------------------ */
/* Quantization                                                       */
/* ------------------------------------------------------------------ */

/* [S: util/format/format_utils.h:EXTEND_NORMALIZED_INT] */
static unsigned extend_to_8(unsigned x, unsigned bits)
{
   const unsigned mul = 255u / ((1u << bits) - 1u);
   return x * mul + ((8u % bits) ? x >> (bits - 8u % bits) : 0u);
}

static unsigned max_bits(const struct fgl_tex_pipe_format *pf)
{
   unsigned m = pf->r;
   const uint8_t o[5] = { pf->g, pf->b, pf->a, pf->l, pf->i };
   for (int k = 0; k < 5; k++)
      if (o[k] > m)
         m = o[k];
   return m;
}

/* The bits of each RGBA channel of a texel of base format `base` stored
 * in pf (L in R, G and B; I in all four); 0 for a channel the format
 * does not store (a constant: alpha 1 of RGB and L, R, G, B 0 of A). */
static void channel_bits(const struct fgl_tex_pipe_format *pf, GLenum base, uint8_t bits[4])
{
   switch (base) {
   case GL_LUMINANCE: case GL_LUMINANCE_ALPHA:
      bits[0] = bits[1] = bits[2] = pf->l;
      bits[3] = base == GL_LUMINANCE ? 0 : pf->a;
      break;
   case GL_INTENSITY:
      bits[0] = bits[1] = bits[2] = bits[3] = pf->i;
      break;
   case GL_ALPHA:
      bits[0] = bits[1] = bits[2] = 0;
      bits[3] = pf->a;
      break;
   default:
      bits[0] = pf->r;
      bits[1] = pf->g;
      bits[2] = pf->b;
      bits[3] = base == GL_RGB ? 0 : pf->a;
      break;
   }
}

/* Whether images of pf keep their stored values (img->Store): a channel
 * of other than 8 bits. */
static bool needs_store(const struct fgl_tex_pipe_format *pf)
{
   if (pf == &PF_DXT_RGB || pf == &PF_DXT_RGBA)
      return false;
   const uint8_t b[6] = { pf->r, pf->g, pf->b, pf->a, pf->l, pf->i };
   for (int k = 0; k < 6; k++)
      if (b[k] != 0 && b[k] != 8)
         return true;
   return false;
}

/* [S: format_utils.h:_mesa_unorm_to_unorm(q, bits, 8)] a stored value as
 * the oracle's sampler and glGetTexImage expand it to 8 bits (an 8-bit
 * intermediate: util/format unpack_rgba_8unorm, _mesa_swizzle_and_convert) */
static uint8_t expand_to_8(unsigned q, unsigned bits)
{
   if (bits == 8)
      return (uint8_t)q;
   if (bits > 8)
      return (uint8_t)((q * 255u + (1u << (bits - 1)) - 1u) / ((1u << bits) - 1u));
   return (uint8_t)extend_to_8(q, bits);
}

/* One 8-bit channel value as a channel of `bits` bits stores it.
 * [S: format_utils.c:_mesa_format_convert] a 16-bit array format takes
 * the byte channel by _mesa_unorm_to_unorm(x, 8, 16) (x * 257); a packed
 * format of at most 8 bits per channel converts through an RGBA ubyte
 * intermediate (_mesa_unorm_to_unorm(x, 8, n): (x * max + 127) / 255), a
 * wider one (10-10-10-2) through float (x/255, then util_iround(f * max)).
 * `rule`: glCopyTexImage's (enum fgl_copy_rule), COPY_TEXSTORE otherwise. */
static unsigned store_from_8(uint8_t x, unsigned bits, bool via_float, unsigned rule)
{
   if (bits == 8)
      return x;
   if (bits == 16)
      return (unsigned)x * 257u;
   if (rule == COPY_TRUNCATE)
      return (unsigned)x >> (8u - bits);
   if (rule == COPY_RESCALE)
      return (((unsigned)x >> bits) * ((1u << bits) - 1u) + (1u << (7u - bits))) >> (8u - bits);
   if (rule == COPY_WIDE && bits > 8)
      return (unsigned)m_gallivm_float_to_unorm16((float)x * (1.0f / 255.0f)) >> (16u - bits);
   const unsigned max = (1u << bits) - 1u;
   if (via_float) {
      /* [S: u_format_pack.py: util_iround(x * max), (int)(f + 0.5f) off
       * x86-32: the float sum rounds, 794.49997 gives 795] */
      const float f = (float)x * (1.0f / 255.0f);
      return (unsigned)(int)(f * (float)max + 0.5f);
   }
   return ((unsigned)x * max + 127u) / 255u;
}

/* Stores n texels of stored values `q` (four per texel, img->StoreBits
 * wide; constants 0 or 1) at texel index `at` of img. */
static void put_stored(struct fgl_texture_image *img, size_t at, const uint16_t *q, size_t n)
{
   uint8_t *data = img->Data + 4 * at;
   memcpy(img->Store + 4 * at, q, 4 * n * sizeof(uint16_t));
   for (size_t i = 0; i < 4 * n; i++) {
      const unsigned bits = img->StoreBits[i & 3];
      data[i] = bits ? expand_to_8(q[i], bits) : (q[i] ? 255 : 0);
   }
}

/* Stores n RGBA8 texels `t` of img's base format (rebased: constants 0 or
 * 255 in the channels the format lacks) at texel index `at` of img, in
 * img's format (truncating: as glCopyTexImage stores into some formats). */
static void put_texels(struct fgl_texture_image *img, size_t at, const uint8_t *t, size_t n,
                       unsigned rule)
{
   uint8_t *data = img->Data + 4 * at;
   if (!img->Store) {
      memcpy(data, t, 4 * n);   /* 8 bits per channel */
      return;
   }
   uint16_t *store = img->Store + 4 * at;
   const bool via_float = max_bits(img->Format) > 8;
   for (size_t i = 0; i < 4 * n; i++) {
      const unsigned bits = img->StoreBits[i & 3];
      if (bits == 0) {
         store[i] = t[i] ? 1 : 0;
         data[i] = t[i];
         continue;
      }
      const unsigned q = store_from_8(t[i], bits, via_float, rule);
      store[i] = (uint16_t)q;
      data[i] = expand_to_8(q, bits);
   }
}

/* The texel an unwritten (zeroed) texel of the oracle's storage reads as. */
static void zero_texel(GLenum base, uint8_t *t)
{
   t[0] = t[1] = t[2] = 0;
   t[3] = base == GL_RGB || base == GL_LUMINANCE ? 255 : 0;
}

/* The RGBA8 texel of base format `base` from an RGBA colour (Mesa's
 * rebase: luminance and intensity take red). */
static void rebase_texel(GLenum base, const uint8_t c[4], uint8_t *t)
{
   switch (base) {
   case GL_LUMINANCE:       t[0] = t[1] = t[2] = c[0]; t[3] = 255; break;
   case GL_LUMINANCE_ALPHA: t[0] = t[1] = t[2] = c[0]; t[3] = c[3]; break;
   case GL_INTENSITY:       t[0] = t[1] = t[2] = t[3] = c[0]; break;
   case GL_ALPHA:           t[0] = t[1] = t[2] = 0; t[3] = c[3]; break;
   case GL_RGB:             t[0] = c[0]; t[1] = c[1]; t[2] = c[2]; t[3] = 255; break;
   default:                 memcpy(t, c, 4); break;
   }
}

/* ------------------------------------------------------------------ */
/* Targets, objects, sizes                                            */
/* ------------------------------------------------------------------ */

static bool is_proxy(GLenum target)
{
   return target == GL_PROXY_TEXTURE_1D || target == GL_PROXY_TEXTURE_2D ||
          target == GL_PROXY_TEXTURE_3D || target == GL_PROXY_TEXTURE_CUBE_MAP;
}

/* [S: teximage.h:_mesa_is_cube_face] */
static bool is_cube_face(GLenum target)
{
   return target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z;
}

/* A cube map's targets: the faces and the proxy, whose sizes must be
 * square (_mesa_legal_texture_dimensions) */
static bool is_cube_target(GLenum target)
{
   return is_cube_face(target) || target == GL_PROXY_TEXTURE_CUBE_MAP;
}

/* [S: teximage.h:_mesa_tex_target_to_face] the face index of a target
 * (0 for the targets without faces) */
static unsigned target_face(GLenum target)
{
   return is_cube_face(target) ? target - GL_TEXTURE_CUBE_MAP_POSITIVE_X : 0;
}

/* The image slot an image call on `target` (a face, or a target without
 * faces) at `level` of t changes. */
static struct fgl_texture_image **image_slot(struct fgl_texture_object *t, GLenum target,
                                             GLint level)
{
   return fgl_tex_face_slot(t, target_face(target), level);
}

/* The object an image call on `target` changes: the bound object, or the
 * context's proxy object. */
static struct fgl_texture_object *target_object(struct fgl_context *ctx, GLenum target)
{
   switch (target) {
   case GL_PROXY_TEXTURE_1D: return &ctx->TexLocal.Proxy[0];
   case GL_PROXY_TEXTURE_2D: return &ctx->TexLocal.Proxy[1];
   case GL_PROXY_TEXTURE_3D: return &ctx->TexLocal.Proxy[2];
   case GL_PROXY_TEXTURE_CUBE_MAP: return &ctx->TexLocal.Proxy[3];
   default:
      /* a face changes the bound cube map */
      return fgl_bound_texture(ctx, ctx->Texture.CurrentUnit,
                               is_cube_face(target) ? GL_TEXTURE_CUBE_MAP : target);
   }
}

/* [S: teximage.c:_mesa_legal_texture_dimensions] with NPOT textures; 3D
 * images are limited by 1 << (Max3DTextureLevels - 1), cube faces by
 * 1 << (MaxCubeTextureLevels - 1) and must be square */
static bool legal_dimensions(GLenum target, GLuint dims, GLint level, GLint w, GLint h, GLint d,
                             GLint border)
{
   if (is_cube_target(target) && w != h)
      return false;
   const GLint max = (dims == 3 ? FGL_MAX_3D_TEXTURE_SIZE
                      : is_cube_target(target) ? FGL_MAX_CUBE_MAP_TEXTURE_SIZE
                                               : FGL_MAX_TEXTURE_SIZE) >> level;
   if (w < 2 * border || w > 2 * border + max)
      return false;
   if (dims >= 2 && (h < 2 * border || h > 2 * border + max))
      return false;
   if (dims == 3 && (d < 2 * border || d > 2 * border + max))
      return false;
   return true;
}

/* [S: teximage.c:_mesa_max_texture_levels] */
static int max_levels(GLenum target)
{
   switch (target) {
   case GL_TEXTURE_3D: case GL_PROXY_TEXTURE_3D:
      return FGL_MAX_3D_TEXTURE_LEVELS;
   case GL_TEXTURE_RECTANGLE: case GL_PROXY_TEXTURE_RECTANGLE:
      return 1;
   default:
      return FGL_MAX_TEXTURE_LEVELS;
   }
}

static unsigned logbase2(unsigned n)
{
   unsigned l = 0;
   while (n >>= 1)
      l++;
   return l;
}

/* [S: st_cb_texture.c:st_TestProxyTexImage, lp_texture.c:
 * llvmpipe_texture_layout, llvmpipe_can_create_resource] the oracle
 * sizes a full mipmap chain from (w, h, d) (the proxy object's filter is
 * the default mipmap one): rows of 4-aligned width padded to the 64-byte
 * cache line, 2D and 3D heights aligned to 4, a 3D level d such images,
 * levels aligned to 64 bytes; more than LP_MAX_TEXTURE_SIZE (2 GiB) does
 * not fit. */
static bool size_ok(GLuint dims, const struct fgl_tex_pipe_format *pf, GLint w, GLint h,
                    GLint d, unsigned layers)
{
   if (w == 0 || h == 0 || d == 0)
      return true;
   uint64_t total = 0;
   unsigned width = (unsigned)w, height = (unsigned)h, depth = (unsigned)d;
   unsigned larger = width > height ? width : height;
   larger = larger > depth ? larger : depth;
   const unsigned last = logbase2(larger);
   for (unsigned l = 0; l <= last; l++) {
      const uint64_t aw = (width + 3u) & ~3u;
      const uint64_t ah = dims == 1 ? height : ((height + 3u) & ~3u);
      const uint64_t stride = (aw * pf->bytes + 63u) & ~(uint64_t)63u;
      total += (stride * ah * depth * layers + 63u) & ~(uint64_t)63u;
      if (total > 2ull * 1024 * 1024 * 1024)
         return false;
      width = width > 1 ? width >> 1 : 1;
      height = height > 1 ? height >> 1 : 1;
      depth = depth > 1 ? depth >> 1 : 1;
   }
   return true;
}

static struct fgl_texture_image *new_image(int w, int h, int d, int border, GLint internal,
                                           GLenum base, const struct fgl_tex_pipe_format *pf)
{
   struct fgl_texture_image *img = fgl_calloc(1, sizeof(*img));
   if (!img)
      return NULL;
   img->Width = w;
   img->Height = h;
   img->Depth = d;
   img->Border = border;
   img->InternalFormat = (GLenum)internal;
   img->BaseFormat = base;
   img->Format = pf;
   return img;
}

/* ------------------------------------------------------------------ */
/* Storage                                                            */
/* ------------------------------------------------------------------ */

/*
 * Which of the oracle's resources an image lives in decides how
 * glGetTexImage reads a compressed image: one in the object's resource
 * goes through the sampler (a blit), one in a resource of its own through
 * Mesa's CPU decoders (ORACLE-NOTES.md "Compressed textures: LATC", cube
 * faces of mixed formats; probe p_cube_mixed_storage) [S: st_cb_texture.c:
 * st_GetTexSubImage, "stImage->pt != stObj->pt"].  fixgl keeps the
 * texels either way and records only where the oracle put them:
 *  - at each image's allocation [S: st_AllocTextureImageBuffer]: an image
 *    the object's resource fits (same pipe format, the level's size, the
 *    level within the resource) lives there; otherwise, when the object
 *    has no resource, or one of a single level, or the image is of level
 *    0, the object's resource is dropped and a new one guessed from the
 *    image (guess_and_alloc_texture: level 0's size from the base image
 *    when that agrees, else from this one; all levels or one,
 *    allocate_full_mipmap) and the image lives there if it fits; else
 *    the image gets a resource of its own;
 *  - when a complete texture is drawn [S: st_finalize_texture]: the base
 *    image's resource becomes the object's when it has as many levels; a
 *    resource of another format, size or too few levels is replaced; the
 *    images of the used levels that fit are moved into it.
 * Faces of different formats therefore leave the faces before the last
 * change of format in resources of their own.
 */

static GLint minify(GLint x, GLint level)
{
   return x >> level > 1 ? x >> level : 1;
}

/* [S: st_texture.c:st_texture_match_image] */
static bool storage_fits(const struct fgl_tex_storage *s, const struct fgl_texture_image *img,
                         GLint level)
{
   return s->Id != 0 && s->Format == img->Format && s->CompressedFormat == img->CompressedFormat &&
          level <= s->LastLevel && img->Width == minify(s->Width0, level) &&
          img->Height == minify(s->Height0, level) && img->Depth == minify(s->Depth0, level);
}

/* [S: st_cb_texture.c:guess_base_level_size] level 0's size from an image
 * of `level`; false when it cannot be told */
static bool guess_level0(GLenum target, const struct fgl_texture_image *img, GLint level,
                         GLint size[3])
{
   size[0] = img->Width;
   size[1] = img->Height;
   size[2] = img->Depth;
   if (level == 0)
      return true;
   if ((target == GL_TEXTURE_2D && (size[0] == 1 || size[1] == 1)) ||
       (target == GL_TEXTURE_3D && (size[0] == 1 || size[1] == 1 || size[2] == 1)))
      return false;
   size[0] <<= level;
   if (target != GL_TEXTURE_1D)
      size[1] <<= level;
   if (target == GL_TEXTURE_3D)
      size[2] <<= level;
   return true;
}

/* [S: st_cb_texture.c:allocate_full_mipmap] */
static bool full_mipmap(const struct fgl_texture_object *t, const struct fgl_texture_image *img,
                        GLint level)
{
   if (level > 0 || t->GenerateMipmap)
      return true;
   if (t->MaxLevel < FGL_MAX_TEXTURE_LEVELS && t->MaxLevel - t->BaseLevel > 0)
      return true;
   if (img->BaseFormat == GL_DEPTH_COMPONENT)
      return false;
   if (t->BaseLevel == 0 && t->MaxLevel == 0)
      return false;
   if (t->MinFilter == GL_NEAREST || t->MinFilter == GL_LINEAR ||
       t->MinFilter == GL_NEAREST_MIPMAP_LINEAR)
      return false;
   return t->Target != GL_TEXTURE_3D;
}

static struct fgl_tex_storage new_storage(struct fgl_texture_object *t,
                                          const struct fgl_texture_image *img,
                                          const GLint size[3], GLint last_level)
{
   const struct fgl_tex_storage s = { ++t->StorageIds, img->Format, img->CompressedFormat,
                                      size[0], size[1], size[2], last_level };
   return s;
}

/* [S: st_cb_texture.c:guess_and_alloc_texture] the object's new resource
 * for img at `level` (none when level 0's size cannot be guessed) */
static void guess_storage(struct fgl_texture_object *t, const struct fgl_texture_image *img,
                          GLint level)
{
   const struct fgl_texture_image *base =
      t->BaseLevel >= 0 && t->BaseLevel < FGL_MAX_TEXTURE_LEVELS ? t->Image[t->BaseLevel] : NULL;
   GLint size[3];
   bool guessed = false;
   if (base && base->Width > 0 && base->Height > 0 && base->Depth > 0 &&
       guess_level0(t->Target, base, t->BaseLevel, size))
      guessed = img->Width == minify(size[0], level) && img->Height == minify(size[1], level) &&
                img->Depth == minify(size[2], level);
   if (!guessed && !guess_level0(t->Target, img, level, size))
      return;
   GLint last = 0;
   if (full_mipmap(t, img, level)) {
      GLint m = size[0] > size[1] ? size[0] : size[1];
      if (t->Target == GL_TEXTURE_3D && size[2] > m)
         m = size[2];
      while (m > 1) {
         m >>= 1;
         last++;
      }
   }
   t->Storage = new_storage(t, img, size, last);
}

/* [S: st_cb_texture.c:st_AllocTextureImageBuffer] where img, the new
 * image of `level`, lives */
static void place_image(struct fgl_texture_object *t, struct fgl_texture_image *img, GLint level)
{
   if (img->Width <= 0 || img->Height <= 0 || img->Depth <= 0)
      return;
   if (t->Storage.Id == 0 || t->Storage.LastLevel == 0 || level == 0) {
      if (storage_fits(&t->Storage, img, level)) {
         img->Storage = t->Storage;
         return;
      }
      t->Storage.Id = 0;
      guess_storage(t, img, level);
   }
   if (storage_fits(&t->Storage, img, level)) {
      img->Storage = t->Storage;
   } else {
      const GLint size[3] = { img->Width, img->Height, img->Depth };
      img->Storage = new_storage(t, img, size, 0);
   }
}

void fgl_tex_finalize_storage(struct fgl_texture_object *t, int max_level)
{
   struct fgl_texture_image *first = t->Image[t->BaseLevel];
   const GLint last = t->MinFilter == GL_NEAREST || t->MinFilter == GL_LINEAR ? t->BaseLevel
                                                                               : max_level;
   if (first->Storage.Id != t->Storage.Id &&
       (t->Storage.Id == 0 || first->Storage.LastLevel >= t->Storage.LastLevel))
      t->Storage = first->Storage;
   GLint size[3];
   if (!guess_level0(t->Target, first, t->BaseLevel, size)) {
      size[0] = t->Storage.Width0;
      size[1] = t->Storage.Height0;
      size[2] = t->Storage.Depth0;
   }
   if (t->Storage.Id != 0 &&
       (t->Storage.Format != first->Format ||
        t->Storage.CompressedFormat != first->CompressedFormat || t->Storage.LastLevel < last ||
        t->Storage.Width0 != size[0] || t->Storage.Height0 != size[1] ||
        t->Storage.Depth0 != size[2]))
      t->Storage.Id = 0;
   if (t->Storage.Id == 0)
      t->Storage = new_storage(t, first, size, last);
   const unsigned faces = t->Target == GL_TEXTURE_CUBE_MAP ? 6 : 1;
   for (unsigned f = 0; f < faces; f++) {
      for (GLint l = t->BaseLevel; l <= last && l < FGL_MAX_TEXTURE_LEVELS; l++) {
         struct fgl_texture_image *img = *fgl_tex_face_slot(t, f, l);
         if (img && img->Storage.Id != t->Storage.Id &&
             (l == 0 || (img->Width == minify(size[0], l) && img->Height == minify(size[1], l) &&
                         img->Depth == minify(size[2], l))))
            img->Storage = t->Storage;
      }
   }
}

/* [S: st_atom_texture.c:update_textures, st_finalize_texture;
 * lp_setup.c:try_update_scene_state, lp_scene_add_resource_reference] a
 * draw (not a clear or a pixel rectangle, whose validation binds no
 * sampler views) finalizes the textures it samples, and their resources
 * join the scene's references until its flush */
void fgl_tex_note_scene_use(struct fgl_context *ctx)
{
   for (unsigned bits = ctx->_EnabledTexUnits; bits; bits &= bits - 1) {
      const unsigned u = (unsigned)__builtin_ctz(bits);
      fgl_tex_finalize_storage(ctx->_CurrentTex[u], ctx->_CurrentTexMaxLevel[u]);
   }
   if (ctx->_SceneTexEpoch != ctx->Query.FlushEpoch) {
      ctx->_SceneTexEpoch = ctx->Query.FlushEpoch;
      ctx->_SceneTexCount = 0;
      ctx->_SceneTexFull = false;
   }
   for (unsigned bits = ctx->_EnabledTexUnits; bits; bits &= bits - 1) {
      const struct fgl_texture_object *t = ctx->_CurrentTex[__builtin_ctz(bits)];
      unsigned i = 0;
      while (i < ctx->_SceneTexCount &&
             (ctx->_SceneTex[i].Obj != t || ctx->_SceneTex[i].Storage != t->Storage.Id))
         i++;
      if (i < ctx->_SceneTexCount)
         continue;
      if (i == sizeof(ctx->_SceneTex) / sizeof(ctx->_SceneTex[0])) {
         ctx->_SceneTexFull = true;
         continue;
      }
      ctx->_SceneTex[i].Obj = t;
      ctx->_SceneTex[i].Storage = t->Storage.Id;
      ctx->_SceneTexCount++;
   }
}

/* [S: llvmpipe/lp_texture.c:llvmpipe_transfer_map, lp_flush.c:
 * llvmpipe_flush_resource] Mesa maps the image's resource to write
 * texels; llvmpipe flushes the scene first when the scene samples that
 * resource (probe p_vpcut_state: glTexImage2D of the same size and
 * glTexSubImage2D of a texture the pending triangle samples; not another
 * texture's, not an image given new storage).  The flush marks
 * llvmpipe's setup state dirty and makes the ended queries available. */
void fgl_tex_written(struct fgl_context *ctx, const struct fgl_texture_object *t,
                     const struct fgl_texture_image *img)
{
   if (!img || img->Storage.Id == 0 || ctx->_SceneTexEpoch != ctx->Query.FlushEpoch)
      return;
   bool sampled = ctx->_SceneTexFull;
   for (unsigned i = 0; i < ctx->_SceneTexCount && !sampled; i++)
      sampled = ctx->_SceneTex[i].Obj == t && ctx->_SceneTex[i].Storage == img->Storage.Id;
   if (sampled) {
      fgl_query_flushed(ctx);
      fgl_vpcut_invalidate(ctx);
   }
}

/* Replaces the image of face `face` (0 without faces) at `level` of t. */
static void set_image(struct fgl_texture_object *t, unsigned face, GLint level,
                      struct fgl_texture_image *img)
{
   struct fgl_texture_image **slot = fgl_tex_face_slot(t, face, level);
   free_image(*slot);
   *slot = img;
   if (img)
      place_image(t, img, level);
}

/* Allocates the texel storage of img (and its stored values when the
 * format is not 8 bits per channel), every texel as the oracle's zeroed
 * storage reads; false (nothing allocated) when out of memory. */
static bool alloc_texels(struct fgl_texture_image *img)
{
   const size_t n = (size_t)img->Width * (size_t)img->Height * (size_t)img->Depth;
   img->Data = fgl_rc_alloc(n ? n * 4 : 4, 0);
   if (needs_store(img->Format)) {
      channel_bits(img->Format, img->BaseFormat, img->StoreBits);
      img->Store = fgl_rc_alloc(n ? n * 4 * sizeof(uint16_t) : 4 * sizeof(uint16_t), 0);
   }
   if (img->BaseFormat == GL_DEPTH_COMPONENT)
      img->ZValues = fgl_rc_alloc((n ? n : 1) * sizeof(uint32_t), 1);   /* zeroed storage */
   if (!img->Data || (needs_store(img->Format) && !img->Store) ||
       (img->BaseFormat == GL_DEPTH_COMPONENT && !img->ZValues)) {
      fgl_rc_release(img->Data);
      fgl_rc_release(img->Store);
      fgl_rc_release(img->ZValues);
      img->Data = NULL;
      img->Store = NULL;
      img->ZValues = NULL;
      return false;
   }
   uint8_t t[4];
   zero_texel(img->BaseFormat, t);
   for (size_t i = 0; i < n; i++)
      put_texels(img, i, t, 1, false);
   return true;
}

/* Unpacks a w x h client image into texels (x, y) of slice z of img. */
static bool store_rect(struct fgl_context *ctx, struct fgl_texture_image *img,
                       const struct fgl_pixelstore *unpack, int x, int y, int z, int w, int h,
                       GLenum format, GLenum type, const void *pixels)
{
   if (!pixels || w == 0 || h == 0)
      return true;
   const size_t slice = (size_t)z * (size_t)img->Height;
   if (img->ZValues) {
      if (!fgl_tex_store_depth(ctx, img, unpack, x, y, z, w, h, type, pixels)) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return false;
      }
      return true;
   }
   if (img->Store) {
      /* the stored values straight from the client data: a float or
       * 16-bit source reaches a wide format without an 8-bit step */
      uint16_t *q = fgl_malloc_gl(ctx, (size_t)w * (size_t)h * 4 * sizeof(uint16_t));
      if (!q) {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return false;
      }
      if (!fgl_unpack_texels_stored(ctx, unpack, w, h, format, type, pixels, img->BaseFormat,
                                    img->StoreBits, max_bits(img->Format) == 16, q)) {
         fgl_free(q);
         fgl_error(ctx, GL_INVALID_ENUM);
         return false;
      }
      for (int j = 0; j < h; j++)
         put_stored(img, (slice + (size_t)(y + j)) * (size_t)img->Width + (size_t)x,
                    q + 4 * (size_t)j * (size_t)w, (size_t)w);
      fgl_free(q);
      return true;
   }
   uint8_t *tmp = fgl_malloc_gl(ctx, (size_t)w * (size_t)h * 4);
   if (!tmp) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return false;
   }
   if (!fgl_unpack_texels_rgba8(ctx, unpack, w, h, format, type, pixels,
                                img->BaseFormat, tmp)) {
      /* a legal format/type pair the unpacker does not convert yet */
      fgl_free(tmp);
      fgl_error(ctx, GL_INVALID_ENUM);
      return false;
   }
   for (int j = 0; j < h; j++)
      put_texels(img, (slice + (size_t)(y + j)) * (size_t)img->Width + (size_t)x,
                 tmp + 4 * (size_t)j * (size_t)w, (size_t)w, false);
   fgl_free(tmp);
   return true;
}

/* The client address of slice k of a w x h x d image [S: image.c:
 * _mesa_image_offset]: slices of ImageHeight rows (the image's height when
 * 0), SkipImages slices skipped; within it the 2D addressing applies. */
static const void *slice_address(const struct fgl_pixelstore *p, const void *pixels, int w,
                                 int h, GLenum format, GLenum type, int k)
{
   const size_t rows = (size_t)(p->ImageHeight > 0 ? p->ImageHeight : h);
   const size_t stride = fgl_image_row_stride(p, w, format, type);
   return (const uint8_t *)pixels + ((size_t)p->SkipImages + (size_t)k) * rows * stride;
}

/* Unpacks a w x h x d client image of a `dims`-dimensional call into
 * texels (x, y, z) of img (1D and 2D calls ignore the image modes). */
static bool store_texels(struct fgl_context *ctx, struct fgl_texture_image *img,
                         const struct fgl_pixelstore *unpack, GLuint dims, int x, int y, int z,
                         int w, int h, int d, GLenum format, GLenum type, const void *pixels)
{
   if (!pixels)
      return true;
   for (int k = 0; k < d; k++)
      if (!store_rect(ctx, img, unpack, x, y, z + k, w, h, format, type,
                      dims < 3 ? pixels : slice_address(unpack, pixels, w, h, format, type, k)))
         return false;
   return true;
}

/* ------------------------------------------------------------------ */
/* S3TC images                                                        */
/* ------------------------------------------------------------------ */

/* An image of an S3TC format keeps the oracle's blocks (Blocks) and, in
 * Data, the texels llvmpipe decodes from them.  Uncompressed data given
 * to it (glTexImage, glTexSubImage, glCopyTexImage, glCopyTexSubImage,
 * GL_GENERATE_MIPMAP) is first stored in Data as into an RGBA8 image of
 * the same base format (the oracle's texstore converts it to RGB8 or
 * RGBA8 first [S: texcompress_s3tc.c:_mesa_texstore_rgb_dxt1 and
 * siblings]), then compressed by the oracle's encoder
 * (main/texcompress_s3tc.c) and decoded back. */

/* [S: glformats.c:_mesa_target_can_be_compressed; st_format.c:
 * st_choose_format for GL_COMPRESSED_RGB/RGBA] the S3TC format an image
 * of `internal` on `target` is stored in, 0 for an uncompressed one */
static GLenum s3tc_format_of(GLint internal, GLenum target)
{
   /* a generic format is compressed on a 3D target too (measured: each
    * slice an image of its own to the encoder), an S3TC one is not
    * (refused there) */
   const bool is_3d = target == GL_TEXTURE_3D || target == GL_PROXY_TEXTURE_3D;
   if (target != GL_TEXTURE_2D && target != GL_PROXY_TEXTURE_2D && !is_cube_target(target) &&
       !is_3d)
      return 0;
   if (fgl_s3tc_block_bytes((GLenum)internal, NULL))
      return is_3d ? 0 : (GLenum)internal;
   if (internal == GL_COMPRESSED_RGB)
      return GL_COMPRESSED_RGB_S3TC_DXT1_EXT;
   if (internal == GL_COMPRESSED_RGBA)
      return GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
   /* LATC1 / LATC2 (ORACLE-NOTES.md "Compressed textures: LATC") */
   if (internal == GL_COMPRESSED_LUMINANCE)
      return GL_COMPRESSED_LUMINANCE_LATC1_EXT;
   if (internal == GL_COMPRESSED_LUMINANCE_ALPHA)
      return GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT;
   return 0;
}

static const struct fgl_tex_pipe_format *s3tc_pipe_format(GLenum cf)
{
   switch (cf) {
   case GL_COMPRESSED_RGB_S3TC_DXT1_EXT: return &PF_DXT_RGB;
   case GL_COMPRESSED_LUMINANCE_LATC1_EXT: return &PF_LATC1;
   case GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT: return &PF_LATC2;
   default: return &PF_DXT_RGBA;
   }
}

/* The bytes of one slice of a compressed image (a 3D image is its slices'
 * blocks, one slice after the other). */
static size_t slice_blocks_bytes(const struct fgl_texture_image *img)
{
   return (size_t)fgl_compressed_image_size(img->CompressedFormat, img->Width, img->Height, 1);
}

/* Decodes slices z .. z + d - 1 of img's blocks into its Data. */
static void decode_slices(struct fgl_texture_image *img, int z, int d)
{
   if (img->Width <= 0 || img->Height <= 0)
      return;
   const size_t texels = (size_t)img->Width * (size_t)img->Height;
   for (int k = z; k < z + d; k++)
      fgl_s3tc_decode_image(img->CompressedFormat, img->Blocks + (size_t)k * slice_blocks_bytes(img),
                            img->Width, img->Height, img->Data + 4 * texels * (size_t)k);
}

/* Gives img (texels allocated) zeroed blocks of `cf`, or, when `old` is an
 * image of the same format and size (the oracle then keeps the texture's
 * storage: st_texture_match_image), old's blocks, and decodes them into
 * Data; false when out of memory. */
static bool alloc_blocks(struct fgl_texture_image *img, GLenum cf,
                         const struct fgl_texture_image *old)
{
   img->CompressedFormat = cf;
   img->BlocksSize = (size_t)fgl_compressed_image_size(cf, img->Width, img->Height, img->Depth);
   img->Blocks = fgl_calloc(img->BlocksSize ? img->BlocksSize : 1, 1);
   if (!img->Blocks)
      return false;
   if (old && old->Blocks && old->CompressedFormat == cf && old->Width == img->Width &&
       old->Height == img->Height && old->Depth == img->Depth)
      memcpy(img->Blocks, old->Blocks, img->BlocksSize);
   decode_slices(img, 0, img->Depth);
   return true;
}

/* Compresses texels (x, y) .. (x + w - 1, y + h - 1) of img's Data (x and
 * y on the 4x4 grid) into its blocks as the oracle's texstore does (the
 * region is an image of its own to the encoder), then decodes them back
 * into Data. */
static void compress_region(struct fgl_context *ctx, struct fgl_texture_image *img, int x,
                            int y, int z, int w, int h, int d)
{
   if (w <= 0 || h <= 0 || d <= 0)
      return;
   const GLenum cf = img->CompressedFormat;
   const unsigned bytes = fgl_stored_block_bytes(cf);
   const size_t row = (size_t)((img->Width + 3) / 4) * bytes;
   const size_t texels = (size_t)img->Width * (size_t)img->Height;
   uint8_t *tmp = fgl_malloc_gl(ctx, (size_t)w * (size_t)h * 4);
   if (!tmp) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   /* each slice of a 3D region an image of its own */
   for (int k = z; k < z + d; k++) {
      const uint8_t *data = img->Data + 4 * texels * (size_t)k;
      for (int j = 0; j < h; j++)
         memcpy(tmp + 4 * (size_t)j * (size_t)w,
                data + 4 * ((size_t)(y + j) * (size_t)img->Width + (size_t)x), 4 * (size_t)w);
      fgl_s3tc_encode_image(cf, tmp, w, h,
                            img->Blocks + (size_t)k * slice_blocks_bytes(img) +
                               (size_t)(y / 4) * row + (size_t)(x / 4) * bytes,
                            row);
   }
   fgl_free(tmp);
   decode_slices(img, z, d);
}

/* [S: teximage.c:error_check_subtexture_dimensions] a region of an S3TC
 * image starts on the 4x4 grid and is whole blocks, but where it ends at
 * the image's edge; true (GL_INVALID_OPERATION raised) when not */
static bool block_alignment_error(struct fgl_context *ctx, const struct fgl_texture_image *img,
                                  GLint xoff, GLint yoff, GLsizei w, GLsizei h)
{
   if (!img->CompressedFormat)
      return false;
   if (xoff % 4 != 0 || yoff % 4 != 0 || (w % 4 != 0 && xoff + w != img->Width) ||
       (h % 4 != 0 && yoff + h != img->Height)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return true;
   }
   return false;
}

/* [S: st_cb_texture.c:st_GetTexSubImage] Whether glGetTexImage (and
 * GL_GENERATE_MIPMAP's read of the base) reads img, an image of t, through
 * Mesa's CPU decoders: a compressed image in a resource other than the
 * object's ("Storage" above), and LATC2 always (measured: exact sevenths
 * and fifths; ORACLE-NOTES.md "Compressed textures: LATC"). */
static bool reads_through_cpu(const struct fgl_texture_object *t,
                              const struct fgl_texture_image *img)
{
   return img->CompressedFormat &&
          (img->CompressedFormat == GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT ||
           img->Storage.Id != t->Storage.Id);
}

/* The RGBA8 texels glGetTexImage and GL_GENERATE_MIPMAP read of img, an
 * image of t: its Data (the sampler's texels), or Mesa's CPU decode of
 * its blocks (reads_through_cpu). */
static void readback_texels(const struct fgl_texture_object *t,
                            const struct fgl_texture_image *img, uint8_t *out)
{
   if (reads_through_cpu(t, img))
      for (int k = 0; k < img->Depth; k++)
         fgl_s3tc_decode_exact(img->CompressedFormat,
                               img->Blocks + (size_t)k * slice_blocks_bytes(img), img->Width,
                               img->Height,
                               out + 4 * (size_t)k * (size_t)img->Width * (size_t)img->Height);
   else
      memcpy(out, img->Data,
             (size_t)img->Width * (size_t)img->Height * (size_t)img->Depth * 4);
}

/* [S: mipmap.c:generate_mipmap_compressed, make_2d_mipmap, do_row] The
 * levels below `level` of a compressed image: the base's decoded texels,
 * each level the truncated mean of 2x2 texels of the one above (a 1-texel
 * side doubles its texel; an odd side drops its last texel; 3D below),
 * kept uncompressed along the chain, each compressed into its level. */
static void gen_mip_compressed(struct fgl_context *ctx, struct fgl_texture_object *t,
                               unsigned face, GLint level, GLint last)
{
   const struct fgl_texture_image *base = fgl_tex_face_image(t, face, level);
   int W = base->Width, H = base->Height, D = base->Depth;
   uint8_t *src = fgl_malloc_gl(ctx, (size_t)W * (size_t)H * (size_t)D * 4);
   if (!src) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   readback_texels(t, base, src);
   for (GLint l = level + 1; l <= last; l++) {
      const int w = W > 1 ? W >> 1 : 1, h = H > 1 ? H >> 1 : 1, d = D > 1 ? D >> 1 : 1;
      struct fgl_texture_image *img = new_image(w, h, d, 0, (GLint)base->InternalFormat,
                                                base->BaseFormat, base->Format);
      if (!img || !alloc_texels(img) ||
          !alloc_blocks(img, base->CompressedFormat, fgl_tex_face_image(t, face, l))) {
         free_image(img);
         fgl_free(src);
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return;
      }
      /* [S: mipmap.c:make_2d_mipmap, make_3d_mipmap, do_row_3D] 2D: the
       * truncated mean of 2x2 texels; a 3D texture: the rounded mean
       * (sum + 4) >> 3 of 2x2x2 texels, a side that does not shrink
       * counting its texels twice */
      const bool is_3d = t->Target == GL_TEXTURE_3D;
      const int row_step = H > h ? 1 : 0, col_step = W > w ? 1 : 0, slice_step = D > d ? 1 : 0;
      const size_t slice = (size_t)W * (size_t)H;
      for (int k = 0; k < d; k++) {
         const uint8_t *sa = src + 4 * slice * (size_t)(k * (slice_step + 1));
         const uint8_t *sb = sa + 4 * slice * (size_t)slice_step;
         for (int j = 0; j < h; j++) {
            const size_t ya = (size_t)(j * (row_step + 1)) * (size_t)W,
                         yb = ya + (size_t)row_step * (size_t)W;
            for (int i = 0; i < w; i++) {
               const size_t x0 = (size_t)(i * (col_step + 1)), x1 = x0 + (size_t)col_step;
               uint8_t *o =
                  img->Data + 4 * (((size_t)k * (size_t)h + (size_t)j) * (size_t)w + (size_t)i);
               for (int n = 0; n < 4; n++) {
                  const unsigned q = sa[4 * (ya + x0) + n] + sa[4 * (ya + x1) + n] +
                                     sa[4 * (yb + x0) + n] + sa[4 * (yb + x1) + n];
                  if (!is_3d) {
                     o[n] = (uint8_t)(q / 4);
                     continue;
                  }
                  const unsigned r = sb[4 * (ya + x0) + n] + sb[4 * (ya + x1) + n] +
                                     sb[4 * (yb + x0) + n] + sb[4 * (yb + x1) + n];
                  o[n] = (uint8_t)((q + r + 4) >> 3);
               }
            }
         }
      }
      /* the chain goes on from the uncompressed level */
      memcpy(src, img->Data, (size_t)w * (size_t)h * (size_t)d * 4);
      compress_region(ctx, img, 0, 0, 0, w, h, d);
      set_image(t, face, l, img);
      W = w;
      H = h;
      D = d;
   }
   fgl_free(src);
   fgl_tex_object_changed(ctx);
}

/* [S: lp_bld_arit.c:lp_build_lerp_simple, AoS with pmulhrsw rounding] */
static uint8_t lerp8(int w, int a, int b)
{
   return (uint8_t)((a + ((w * (b - a) + 128) >> 8)) & 255);
}

/* [S: teximage.c:check_gen_mipmap, st_gen_mipmap.c:st_generate_mipmap,
 * util/u_gen_mipmap.c:util_gen_mipmap] with GL_GENERATE_MIPMAP, a change
 * of the base level (below MAX_LEVEL) regenerates the levels after it up
 * to the last of a full chain (_mesa_compute_num_levels, at most
 * MAX_LEVEL): _mesa_prepare_mipmap_levels makes each the base image's
 * format at half the size above it (at least 1), and llvmpipe, which has
 * no PIPE_CAP_GENERATE_MIPMAP, fills it by util_gen_mipmap's
 * PIPE_TEX_FILTER_LINEAR blit from the level above: a quad sampling that
 * level bilinearly at each pixel centre, s = (i + 0.5) / w, on the AoS
 * 8-bit path (CLAMP_TO_EDGE, weights (int)round(s * W * 256) - 128 in 8.8
 * fixed point, lerp8 along s on both rows, then along t), the 8-bit
 * result stored into a narrower format as the blit's render target
 * converts it (copy_rule, as glCopyTexImage).  A format wider than 8 bits
 * is sampled on the float path instead (gen_mip_float).  Checked for
 * every format, POT and NPOT sizes, 1D (texture/genmipmap_*; probe
 * p_copy_tex). */
/* The two texels and the 8.8 weight of texel i of n along an axis of the
 * level above (n_src texels), as check_gen_mipmap's blit samples it. */
static void gen_axis(int i, int n, int n_src, int *i0, int *i1, int *w)
{
   const long f = lrintf(((float)i + 0.5f) / (float)n * (float)n_src * 256.0f) - 128;
   int a = (int)(f >> 8), b = a + 1;
   *w = (int)(f & 255);
   *i0 = a < 0 ? 0 : a > n_src - 1 ? n_src - 1 : a;
   *i1 = b < 0 ? 0 : b > n_src - 1 ? n_src - 1 : b;
}

/* One texel (i, j) of the w x h level blitted from src, a format wider
 * than 8 bits, on llvmpipe's float path (use_aos is false for it): the
 * stored values as floats (r_tex_soa.c's texel), CLAMP_TO_EDGE's linear
 * wrap of the blit quad's (s, t) (fgl_blit_quad_coord), lp_build_lerp_2d
 * with fused lerps; the float result to unorm16
 * (lp_build_clamped_float_to_unsigned_norm: the low 16 mantissa bits of
 * v * (65535/65536) + 2^7), then to the channel's bits as scale_bits
 * does (blend16_to_bits: 10-10-10-2 renders through a 16-bit blend
 * type).  Measured: probes p_genmip_planes (random sizes) and p_copy_tex
 * (2x2 -> 1x1). */
static void wrap_edge_linear(float c, int n, int *x0, int *x1, float *w)
{
   c = fminf(c * (float)n, (float)n) - 0.5f;
   c = fmaxf(c, 0.0f);
   const float ip = floorf(c);
   *w = c - ip;
   *x0 = (int)ip;
   *x1 = *x0 + 1 < n - 1 ? *x0 + 1 : n - 1;
}

/* [S: llvmpipe/lp_state_fs.c:scale_bits] a 16-bit blend-type channel
 * to a channel of `bits` bits: a shift where the bits dropped are at
 * most `bits` (10, 12), else ((u >> bits) * (2^bits - 1) + 2^(d - 1)) >> d
 * with d = 16 - bits (the 2-bit alpha of 10-10-10-2; probe
 * p_genmip_planes) */
static unsigned blend16_to_bits(unsigned u, unsigned bits)
{
   const unsigned d = 16u - bits;
   if (d <= bits)
      return u >> d;
   return ((u >> bits) * ((1u << bits) - 1u) + (1u << (d - 1u))) >> d;
}

/* The setup of one triangle's planes (ORACLE-NOTES.md "Interpolation")
 * for vertices (gx, gy) in setup order */
struct tri_setup {
   float x0c, y0c, dx20o, dy20o, dx01o, dy01o;
};

static struct tri_setup tri_setup_init(const float gx[3], const float gy[3])
{
   struct tri_setup u;
   u.x0c = gx[0] - 0.5f;
   u.y0c = gy[0] - 0.5f;
   const float dx01 = gx[0] - gx[1], dy01 = gy[0] - gy[1];
   const float dx20 = gx[2] - gx[0], dy20 = gy[2] - gy[0];
   const float e = dx01 * dy20, f = dy01 * dx20;
   const float ooa = 1.0f / (e - f);
   u.dx20o = dx20 * ooa;
   u.dy20o = dy20 * ooa;
   u.dx01o = dx01 * ooa;
   u.dy01o = dy01 * ooa;
   return u;
}

/* (a0', dadx, dady) of an attribute with values a0, a1, a2 in setup order */
static void tri_plane(const struct tri_setup *u, float a0, float a1, float a2, float r[3])
{
   const float da01 = a0 - a1, da20 = a2 - a0;
   const float t1 = da01 * u->dy20o, t2 = da20 * u->dy01o;
   r[1] = t1 - t2;
   const float t3 = da20 * u->dx01o, t4 = da01 * u->dx20o;
   r[2] = t3 - t4;
   const float s1 = r[1] * u->x0c, s2 = r[2] * u->y0c;
   r[0] = a0 - (s1 + s2);
}

/* [S: util/u_blitter.c:blitter_set_rectangle, get_texcoords,
 * blitter_draw; llvmpipe/lp_setup_vbuf.c:lp_setup_draw_arrays,
 * lp_setup_tri.c:triangle_both, triangle_cw] util_gen_mipmap's blit
 * draws the level as a TRIANGLE_FAN of V0 (0, 0), V1 (w, 0), V2 (w, h),
 * V3 (0, h) (window coordinates, y down, exact), texture coordinates
 * (0, 0), (1, 0), (1, 1), (0, 1).  llvmpipe takes a fan of four as the
 * triangles (V0, V1, V2) and (V0, V2, V3) (its rectangle path needs a
 * B8G8R8A8/X8 target); both are clockwise there, so each is set up as
 * (v1, v0, v2): (V1, V0, V2) and (V2, V0, V3), and a texel's coordinate is
 * the plane of its triangle at its centre, fma(dady, j, fma(dadx, i, a0')).
 * A centre on the diagonal V0-V2 belongs to the first.  Neither s nor t
 * is exactly (i + 0.5) / w there: on the float path that moves a weight
 * next to 0.5 one step (probe p_genmip_planes: 0 of 140,824 RGBA16
 * channels off, against 4,484 with (i + 0.5) / w). */
void fgl_blit_quad_init(struct fgl_blit_quad *q, int w, int h)
{
   const float fw = (float)w, fh = (float)h;
   const float ax[3] = { fw, 0.0f, fw }, ay[3] = { 0.0f, 0.0f, fh };   /* V1, V0, V2 */
   const float bx[3] = { fw, 0.0f, 0.0f }, by[3] = { fh, 0.0f, fh };   /* V2, V0, V3 */
   const struct tri_setup a = tri_setup_init(ax, ay), b = tri_setup_init(bx, by);
   tri_plane(&a, 1.0f, 0.0f, 1.0f, q->s[0]);
   tri_plane(&a, 0.0f, 0.0f, 1.0f, q->t[0]);
   tri_plane(&b, 1.0f, 0.0f, 0.0f, q->s[1]);
   tri_plane(&b, 1.0f, 0.0f, 1.0f, q->t[1]);
   q->w = w;
   q->h = h;
}

void fgl_blit_quad_coord(const struct fgl_blit_quad *q, int i, int j, float *s, float *t)
{
   /* the centre (i + 0.5, j + 0.5) against the diagonal from (0, 0) to
    * (w, h), in integers */
   const long long lhs = (2LL * i + 1) * q->h, rhs = (2LL * j + 1) * q->w;
   const int k = lhs >= rhs ? 0 : 1;
   *s = fmaf(q->s[k][2], (float)j, fmaf(q->s[k][1], (float)i, q->s[k][0]));
   *t = fmaf(q->t[k][2], (float)j, fmaf(q->t[k][1], (float)i, q->t[k][0]));
}

static void gen_mip_float(const struct fgl_texture_image *src, const struct fgl_blit_quad *bq,
                          int i, int j, uint16_t q[4])
{
   const int W = src->Width, H = src->Height;
   int x0, x1, y0, y1;
   float ws, wt, s, t;
   fgl_blit_quad_coord(bq, i, j, &s, &t);
   wrap_edge_linear(s, W, &x0, &x1, &ws);
   wrap_edge_linear(t, H, &y0, &y1, &wt);
   const uint16_t *n[4] = {
      src->Store + 4 * ((size_t)y0 * (size_t)W + (size_t)x0),
      src->Store + 4 * ((size_t)y0 * (size_t)W + (size_t)x1),
      src->Store + 4 * ((size_t)y1 * (size_t)W + (size_t)x0),
      src->Store + 4 * ((size_t)y1 * (size_t)W + (size_t)x1),
   };
   for (int c = 0; c < 4; c++) {
      const unsigned bits = src->StoreBits[c];
      if (bits == 0) {
         q[c] = n[0][c];   /* the format's constant */
         continue;
      }
      const float scale = (float)(1.0 / (double)((1u << bits) - 1u));
      float v[4];
      for (int k = 0; k < 4; k++)
         v[k] = (float)n[k][c] * scale;
      const float a = fmaf(ws, v[1] - v[0], v[0]);
      const float b = fmaf(ws, v[3] - v[2], v[2]);
      q[c] = (uint16_t)blend16_to_bits(m_gallivm_float_to_unorm16(fmaf(wt, b - a, a)), bits);
   }
}

/* [S: mipmap.c:_mesa_prepare_mipmap_levels, prepare_mipmap_level] a
 * cube map's generation first gives every face the levels base+1..last
 * in the format and halved sizes of face +X's base image: a face whose
 * image there differs (or is missing) gets a new one, its texels the
 * zeroed storage's; false when +X has no base image (nothing is
 * generated) or out of memory. */
static bool prepare_cube_levels(struct fgl_context *ctx, struct fgl_texture_object *t,
                                GLint level, GLint last)
{
   const struct fgl_texture_image *tmpl = t->Image[level];
   if (!tmpl)
      return false;
   int w = tmpl->Width, h = tmpl->Height;
   for (GLint l = level + 1; l <= last; l++) {
      w = w > 1 ? w >> 1 : 1;
      h = h > 1 ? h >> 1 : 1;
      for (unsigned f = 0; f < 6; f++) {
         const struct fgl_texture_image *old = fgl_tex_face_image(t, f, l);
         if (old && old->Width == w && old->Height == h && old->Depth == 1 &&
             old->Border == 0 && old->InternalFormat == tmpl->InternalFormat &&
             old->Format == tmpl->Format)
            continue;
         struct fgl_texture_image *img = new_image(w, h, 1, 0, (GLint)tmpl->InternalFormat,
                                                   tmpl->BaseFormat, tmpl->Format);
         if (!img || !alloc_texels(img) ||
             (tmpl->CompressedFormat && !alloc_blocks(img, tmpl->CompressedFormat, old))) {
            free_image(img);
            fgl_error(ctx, GL_OUT_OF_MEMORY);
            return false;
         }
         set_image(t, f, l, img);
      }
   }
   return true;
}

static void check_gen_mipmap(struct fgl_context *ctx, struct fgl_texture_object *t,
                             unsigned face, GLint level)
{
   if (!t->GenerateMipmap || level != t->BaseLevel || level >= t->MaxLevel)
      return;
   const struct fgl_texture_image *base = fgl_tex_face_image(t, face, level);
   if (!base || base->Width == 0 || base->Height == 0 || base->Depth == 0)
      return;
   unsigned larger = (unsigned)(base->Width > base->Height ? base->Width : base->Height);
   larger = larger > (unsigned)base->Depth ? larger : (unsigned)base->Depth;
   GLint last = level + (GLint)logbase2(larger);
   if (last > t->MaxLevel)
      last = t->MaxLevel;
   const GLint max_level = (base->Depth > 1 || t->Target == GL_TEXTURE_3D)
                              ? FGL_MAX_3D_TEXTURE_LEVELS - 1
                              : FGL_MAX_TEXTURE_LEVELS - 1;
   if (last > max_level)
      last = max_level;
   /* a cube map generates the levels of the face given, after giving
    * every face its levels (st_gen_mipmap.c:st_generate_mipmap: the one
    * layer of the face) */
   if (t->Target == GL_TEXTURE_CUBE_MAP && !prepare_cube_levels(ctx, t, level, last))
      return;
   if (base->CompressedFormat) {
      gen_mip_compressed(ctx, t, face, level, last);
      return;
   }
   for (GLint l = level + 1; l <= last; l++) {
      const struct fgl_texture_image *src = fgl_tex_face_image(t, face, l - 1);
      const int W = src->Width, H = src->Height, D = src->Depth;
      const int w = W > 1 ? W >> 1 : 1, h = H > 1 ? H >> 1 : 1, d = D > 1 ? D >> 1 : 1;
      struct fgl_texture_image *img = new_image(w, h, d, 0, (GLint)base->InternalFormat,
                                                base->BaseFormat, base->Format);
      if (!img || !alloc_texels(img)) {
         fgl_free(img);
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return;
      }
      if (img->ZValues) {
         fgl_tex_gen_mip_depth(src, img);   /* a depth texture: main/texdepth.c */
         set_image(t, face, l, img);
         continue;
      }
      if (!fgl_tex_image_fits_unorm8(base) && D == 1) {
         struct fgl_blit_quad bq;
         fgl_blit_quad_init(&bq, w, h);
         for (int j = 0; j < h; j++)
            for (int i = 0; i < w; i++) {
               uint16_t q[4];
               gen_mip_float(src, &bq, i, j, q);
               put_stored(img, (size_t)j * (size_t)w + (size_t)i, q, 1);
            }
         set_image(t, face, l, img);
         continue;
      }
      for (int k = 0; k < d; k++) {
         int z0, z1, wr;
         gen_axis(k, d, D, &z0, &z1, &wr);
         for (int j = 0; j < h; j++) {
            int y0, y1, wt;
            gen_axis(j, h, H, &y0, &y1, &wt);
            for (int i = 0; i < w; i++) {
               int x0, x1, ws;
               gen_axis(i, w, W, &x0, &x1, &ws);
               uint8_t texel[2][4];
               for (int z = 0; z < 2; z++) {
                  const size_t row0 = ((size_t)(z ? z1 : z0) * (size_t)H + (size_t)y0) * (size_t)W;
                  const size_t row1 = ((size_t)(z ? z1 : z0) * (size_t)H + (size_t)y1) * (size_t)W;
                  const uint8_t *a = src->Data + 4 * (row0 + (size_t)x0);
                  const uint8_t *b = src->Data + 4 * (row0 + (size_t)x1);
                  const uint8_t *c = src->Data + 4 * (row1 + (size_t)x0);
                  const uint8_t *e = src->Data + 4 * (row1 + (size_t)x1);
                  for (int n = 0; n < 4; n++)
                     texel[z][n] = lerp8(wt, lerp8(ws, a[n], b[n]), lerp8(ws, c[n], e[n]));
               }
               /* 3D: the two slices' bilinear values along r */
               if (D > 1)
                  for (int n = 0; n < 4; n++)
                     texel[0][n] = lerp8(wr, texel[0][n], texel[1][n]);
               put_texels(img, ((size_t)k * (size_t)h + (size_t)j) * (size_t)w + (size_t)i,
                          texel[0], 1, img->Format->copy_rule);
            }
         }
      }
      set_image(t, face, l, img);
   }
   fgl_tex_object_changed(ctx);
}

/* ------------------------------------------------------------------ */
/* glTexImage                                                         */
/* ------------------------------------------------------------------ */

/* [S: teximage.c:teximage, texture_error_check] */
static void tex_image(GLuint dims, GLenum target, GLint level, GLint internal,
                      GLsizei width, GLsizei height, GLsizei depth, GLint border,
                      GLenum format, GLenum type, const void *pixels)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag &&
       !(dims == 3 ? fgl_save_tex_image_3d(ctx, target, level, internal, width, height, depth,
                                           border, format, type, pixels)
                   : fgl_save_tex_image(ctx, dims, target, level, internal, width, height,
                                        border, format, type, pixels)))
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_flush_vertices(ctx);
   fgl_scene_flush(ctx);   /* the scene may sample the images */
   /* legal_teximage_target (rectangle and 1D array targets are not
    * modelled) */
   if (dims == 1   ? target != GL_TEXTURE_1D && target != GL_PROXY_TEXTURE_1D
       : dims == 2 ? target != GL_TEXTURE_2D && target != GL_PROXY_TEXTURE_2D &&
                        !is_cube_target(target)
                   : target != GL_TEXTURE_3D && target != GL_PROXY_TEXTURE_3D) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (level < 0 || level >= max_levels(target)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   /* border 1 is legal in the compatibility profile */
   if (border < 0 || border > 1) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (width < 0 || height < 0 || depth < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   const GLenum err = fgl_error_check_format_and_type(ctx, format, type);
   if (err != GL_NO_ERROR) {
      fgl_error(ctx, err);
      return;
   }
   const struct tex_format *tf = find_format(internal);
   if (!tf) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!formats_agree(internal, format)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   /* [S: teximage.c:texture_error_check, "additional checks for
    * compressed textures"] an S3TC format on a target that cannot be
    * compressed, or with a border */
   if (fgl_s3tc_block_bytes((GLenum)internal, NULL)) {
      if (!s3tc_format_of(internal, target)) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      if (border != 0) {
         fgl_error(ctx, GL_INVALID_OPERATION);
         return;
      }
   }
   /* [S: teximage.c:_mesa_legal_texture_base_format_for_target] no 3D
    * depth textures (proxies included) */
   if (dims == 3 && tf->base == GL_DEPTH_COMPONENT) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   const GLenum cf = s3tc_format_of(internal, target);
   const struct fgl_tex_pipe_format *pf =
      cf ? s3tc_pipe_format(cf) : choose_pipe_format(tf, format, type);
   const bool dims_ok = legal_dimensions(target, dims, level, width, height, depth, border);
   const bool sz_ok = size_ok(dims, pf, width, height, depth, is_cube_target(target) ? 6 : 1);

   struct fgl_texture_object *t = target_object(ctx, target);
   if (is_proxy(target)) {
      /* [S: teximage.c:teximage] a proxy keeps the fields as given (border
       * included) or is cleared, without an error */
      struct fgl_texture_image *img = NULL;
      if (dims_ok && sz_ok) {
         img = new_image(width, height, depth, border, internal, tf->base, pf);
         if (!img) {
            fgl_error(ctx, GL_OUT_OF_MEMORY);
            return;
         }
         img->CompressedFormat = cf;
      }
      set_image(t, 0, level, img);
      return;
   }
   if (!dims_ok) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!sz_ok) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   /* [S: teximage.c:strip_texture_border] the oracle drops the border:
    * the image is the inner width - 2 (height - 2 when at least 3) texels */
   struct fgl_pixelstore unpack = ctx->Unpack;
   if (border) {
      if (unpack.RowLength == 0)
         unpack.RowLength = width;
      if (unpack.ImageHeight == 0)
         unpack.ImageHeight = height;
      unpack.SkipPixels++;
      width -= 2;
      if (dims >= 2 && height >= 3) {
         unpack.SkipRows++;
         height -= 2;
      }
      if (depth >= 3) {
         unpack.SkipImages++;
         depth -= 2;
      }
   }
   struct fgl_texture_image *img = new_image(width, height, depth, 0, internal, tf->base, pf);
   if (!img || !alloc_texels(img) ||
       (cf && !alloc_blocks(img, cf, *image_slot(t, target, level)))) {
      free_image(img);
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   /* [S: st_cb_texture.c:st_TexImage, st_TexSubImage] a non-empty image
    * draws glBitmap's cache first */
   if (width && height && depth)
      fgl_flush_bitmap_cache(ctx);
   if (!store_texels(ctx, img, &unpack, dims, 0, 0, 0, width, height, depth, format, type,
                     pixels)) {
      free_image(img);
      return;
   }
   /* no data: the storage is left as it was */
   if (cf && pixels)
      compress_region(ctx, img, 0, 0, 0, width, height, depth);
   set_image(t, target_face(target), level, img);
   if (pixels)
      fgl_tex_written(ctx, t, img);
   fgl_tex_object_changed(ctx);
   check_gen_mipmap(ctx, t, target_face(target), level);
}

void GLAPIENTRY glTexImage1D(GLenum target, GLint level, GLint internalFormat,
                             GLsizei width, GLint border, GLenum format, GLenum type,
                             const GLvoid *pixels)
{
   tex_image(1, target, level, internalFormat, width, 1, 1, border, format, type, pixels);
}

void GLAPIENTRY glTexImage2D(GLenum target, GLint level, GLint internalFormat,
                             GLsizei width, GLsizei height, GLint border, GLenum format,
                             GLenum type, const GLvoid *pixels)
{
   tex_image(2, target, level, internalFormat, width, height, 1, border, format, type,
             pixels);
}

void GLAPIENTRY glTexImage3D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                             GLsizei height, GLsizei depth, GLint border, GLenum format,
                             GLenum type, const GLvoid *pixels)
{
   tex_image(3, target, level, internalFormat, width, height, depth, border, format, type,
             pixels);
}

/* GL_EXT_texture3D's name (Mesa's alias of glTexImage3D) */
void GLAPIENTRY glTexImage3DEXT(GLenum target, GLint level, GLenum internalFormat,
                                GLsizei width, GLsizei height, GLsizei depth, GLint border,
                                GLenum format, GLenum type, const GLvoid *pixels)
{
   tex_image(3, target, level, (GLint)internalFormat, width, height, depth, border, format,
             type, pixels);
}

/* ------------------------------------------------------------------ */
/* glTexSubImage                                                      */
/* ------------------------------------------------------------------ */

/* [S: teximage.c:error_check_subtexture_dimensions] (borders are
 * stripped, so the image's border is 0) */
static bool sub_dimensions_error(struct fgl_context *ctx, GLuint dims,
                                 const struct fgl_texture_image *img, GLint xoff,
                                 GLint yoff, GLint zoff, GLsizei w, GLsizei h, GLsizei d)
{
   if (xoff < -img->Border || (int64_t)xoff + w > img->Width) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return true;
   }
   if (dims > 1 && (yoff < -img->Border || (int64_t)yoff + h > img->Height)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return true;
   }
   if (dims > 2 && (zoff < -img->Border || (int64_t)zoff + d > img->Depth)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return true;
   }
   return false;
}

/* [S: teximage.c:texsubimage_err, texsubimage_error_check,
 * legal_texsubimage_target] */
static void tex_sub_image(GLuint dims, GLenum target, GLint level, GLint xoff, GLint yoff,
                          GLint zoff, GLsizei width, GLsizei height, GLsizei depth,
                          GLenum format, GLenum type, const void *pixels)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag &&
       !(dims == 3 ? fgl_save_tex_sub_image_3d(ctx, target, level, xoff, yoff, zoff, width,
                                               height, depth, format, type, pixels)
                   : fgl_save_tex_sub_image(ctx, dims, target, level, xoff, yoff, width,
                                            height, format, type, pixels)))
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (target != (dims == 1 ? GL_TEXTURE_1D : dims == 2 ? GL_TEXTURE_2D : GL_TEXTURE_3D) &&
       !(dims == 2 && is_cube_face(target))) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (level < 0 || level >= max_levels(target)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   /* error_check_subtexture_negative_dimensions */
   if (width < 0 || (dims > 1 && height < 0) || (dims > 2 && depth < 0)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   struct fgl_texture_object *t = target_object(ctx, target);
   struct fgl_texture_image *img = *image_slot(t, target, level);
   if (!img) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   const GLenum err = fgl_error_check_format_and_type(ctx, format, type);
   if (err != GL_NO_ERROR) {
      fgl_error(ctx, err);
      return;
   }
   if (!formats_agree((GLint)img->InternalFormat, format)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (sub_dimensions_error(ctx, dims, img, xoff, yoff, zoff, width, height, depth) ||
       block_alignment_error(ctx, img, xoff, yoff, width, height))
      return;
   /* [S: teximage.c:texture_sub_image] FLUSH_VERTICES after every check
    * (an erroneous call leaves the vertex format alone: a glTexCoord4f,
    * glTexCoord3f after it keeps q), then nothing to store for an empty
    * region; offsets are biased by the (stripped, 0) border */
   fgl_flush_vertices(ctx);
   fgl_scene_flush(ctx);   /* the scene may sample the images */
   if (width == 0 || height == 0 || depth == 0)
      return;
   /* [S: st_cb_texture.c:st_TexSubImage] glBitmap's cache is drawn first */
   fgl_flush_bitmap_cache(ctx);
   if (store_texels(ctx, img, &ctx->Unpack, dims, xoff, yoff, zoff, width, height, depth,
                    format, type, pixels)) {
      if (pixels)
         fgl_tex_written(ctx, t, img);
      if (img->CompressedFormat && pixels)
         compress_region(ctx, img, xoff, yoff, zoff, width, height, depth);
      fgl_tex_object_changed(ctx);
      check_gen_mipmap(ctx, t, target_face(target), level);
   }
}

void GLAPIENTRY glTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width,
                                GLenum format, GLenum type, const GLvoid *pixels)
{
   tex_sub_image(1, target, level, xoffset, 0, 0, width, 1, 1, format, type, pixels);
}

void GLAPIENTRY glTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                GLsizei width, GLsizei height, GLenum format, GLenum type,
                                const GLvoid *pixels)
{
   tex_sub_image(2, target, level, xoffset, yoffset, 0, width, height, 1, format, type,
                 pixels);
}

void GLAPIENTRY glTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                                GLenum format, GLenum type, const GLvoid *pixels)
{
   tex_sub_image(3, target, level, xoffset, yoffset, zoffset, width, height, depth, format,
                 type, pixels);
}

void GLAPIENTRY glTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                   GLint zoffset, GLsizei width, GLsizei height,
                                   GLsizei depth, GLenum format, GLenum type,
                                   const GLvoid *pixels)
{
   tex_sub_image(3, target, level, xoffset, yoffset, zoffset, width, height, depth, format,
                 type, pixels);
}

/* ------------------------------------------------------------------ */
/* glCopyTexImage, glCopyTexSubImage                                  */
/* ------------------------------------------------------------------ */

/* n texels of img from `at`, a format wider than 8 bits a channel, copied
 * from pixels idx.. of the wide target of an OSMesa GL_UNSIGNED_SHORT or
 * GL_FLOAT buffer (st_CopyTexSubImage's blit; case osmesa/ushort_copytex,
 * ORACLE-NOTES.md "OSMesa contexts and buffers"): the source as unorm16
 * (an R16G16B16A16_UNORM buffer's values as they are; a float buffer's
 * clamped and converted by the blit's shader,
 * m_gallivm_float_to_unorm16), rebased, each channel of n > 8 bits its
 * top n bits, one of fewer bits util_iround(f * (2^n - 1)) of its float.
 * The buffer's format and the rebase are chosen once per call. */
static void put_texels_wide(struct fgl_texture_image *img, size_t at,
                            const struct fgl_framebuffer *fb, size_t idx, size_t n)
{
   /* rebase_texel as source channels: >= 0 a channel, -1 the constant 1,
    * -2 the constant 0 */
   static const int pick[6][4] = {
      { 0, 0, 0, -1 }, { 0, 0, 0, 3 }, { 0, 0, 0, 0 }, { -2, -2, -2, 3 }, { 0, 1, 2, -1 },
      { 0, 1, 2, 3 },
   };
   const int *p = img->BaseFormat == GL_LUMINANCE         ? pick[0]
                  : img->BaseFormat == GL_LUMINANCE_ALPHA ? pick[1]
                  : img->BaseFormat == GL_INTENSITY       ? pick[2]
                  : img->BaseFormat == GL_ALPHA           ? pick[3]
                  : img->BaseFormat == GL_RGB             ? pick[4]
                                                          : pick[5];
   const bool unorm16 = fb->WideFormat == R_WIDE_UNORM16;
   const int nch = fb->AlphaBits == 0 ? 3 : 4;   /* alpha 1 without alpha bits */
   for (size_t k = 0; k < n; k++) {
      float f[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
      uint16_t q[4] = { 65535, 65535, 65535, 65535 };
      if (unorm16) {
         const uint16_t *src = (const uint16_t *)fb->Wide + 4 * (idx + k);
         for (int c = 0; c < nch; c++) {
            q[c] = src[c];
            f[c] = (float)q[c] * (1.0f / 65535.0f);
         }
      } else {
         const float *src = (const float *)fb->Wide + 4 * (idx + k);
         for (int c = 0; c < nch; c++) {
            f[c] = src[c] > 0.0f ? (src[c] < 1.0f ? src[c] : 1.0f) : 0.0f;
            q[c] = m_gallivm_float_to_unorm16(f[c]);
         }
      }
      uint16_t *store = img->Store + 4 * (at + k);
      uint8_t *data = img->Data + 4 * (at + k);
      for (int c = 0; c < 4; c++) {
         const uint16_t tq = p[c] >= 0 ? q[p[c]] : p[c] == -1 ? 65535 : 0;
         const float tf = p[c] >= 0 ? f[p[c]] : p[c] == -1 ? 1.0f : 0.0f;
         const unsigned bits = img->StoreBits[c];
         unsigned v;
         if (bits == 0) {
            v = tq ? 1 : 0;
            store[c] = (uint16_t)v;
            data[c] = v ? 255 : 0;
            continue;
         }
         v = bits > 8 ? (unsigned)tq >> (16u - bits)
                      : (unsigned)(int)(tf * (float)((1u << bits) - 1u) + 0.5f);
         store[c] = (uint16_t)v;
         data[c] = expand_to_8(v, bits);
      }
   }
}

/* [S: teximage.c:copy_texture_sub_image, image.c:_mesa_clip_copytexsubimage]
 * copies the framebuffer rectangle (x, y, w, h) (GL window coordinates,
 * y up) to texels (xoff, yoff) of img, clipped to the framebuffer; the
 * texels whose source is outside keep their values.  The colour goes
 * through the texture's format as glTexImage stores RGBA ubyte data,
 * except for the formats whose copy differs (copy_rule; the
 * oracle's st_CopyTexSubImage blits into them). */
static void copy_texels(struct fgl_context *ctx, struct fgl_texture_image *img, GLint xoff,
                        GLint yoff, GLint zoff, GLint x, GLint y, GLsizei w, GLsizei h)
{
   const struct fgl_framebuffer *fb = fgl_read_fb(ctx);
   if (!fb || !fb->Color)
      return;
   fgl_vpcut_invalidate(ctx);   /* the oracle reads its buffer: a flush */
   fgl_lin_flushed(ctx);
   const uint8_t *color = fgl_read_color(ctx);
   /* _mesa_clip_to_region */
   if (x < 0) {
      w -= -x;
      xoff += -x;
      x = 0;
   }
   if ((int64_t)x + w > fb->Width)
      w = fb->Width - x;
   if (w <= 0)
      return;
   if (y < 0) {
      h -= -y;
      yoff += -y;
      y = 0;
   }
   if ((int64_t)y + h > fb->Height)
      h = fb->Height - y;
   if (h <= 0)
      return;
   /* [S: st_cb_texture.c:st_CopyTexSubImage] called for a non-empty
    * clipped region only (teximage.c:copy_texture_sub_image): glBitmap's
    * cache is drawn first, and may be copied */
   fgl_flush_bitmap_cache(ctx);
   if (img->ZValues) {
      fgl_tex_copy_depth(ctx, img, xoff, yoff, zoff, x, y, w, h);   /* the depth buffer */
      return;
   }
   const bool wide = fb->Wide && img->Store && max_bits(img->Format) > 8 &&
                     !img->CompressedFormat;
   for (GLint j = 0; j < h; j++) {
      const size_t row = (size_t)(fb->Height - 1 - (y + j));   /* y-down buffer row */
      const size_t at =
         ((size_t)zoff * (size_t)img->Height + (size_t)(yoff + j)) * (size_t)img->Width +
         (size_t)xoff;
      if (wide) {
         put_texels_wide(img, at, fb, row * (size_t)fb->Width + (size_t)x, (size_t)w);
         continue;
      }
      for (GLint i = 0; i < w; i++) {
         uint8_t c[4], t[4];
         memcpy(c, color + 4 * (row * (size_t)fb->Width + (size_t)(x + i)), 4);
         if (fb->AlphaBits == 0)
            c[3] = 255;
         rebase_texel(img->BaseFormat, c, t);
         put_texels(img, at + (size_t)i, t, 1, img->Format->copy_rule);
      }
   }
   /* [S: st_cb_texture.c:fallback_copy_texsubimage] an S3TC image: the
    * copied region through texstore (the encoder); a region the clipping
    * moved off the 4x4 grid is taken from the grid line before it */
   if (img->CompressedFormat)
      compress_region(ctx, img, xoff & ~3, yoff & ~3, zoff, w + (xoff & 3), h + (yoff & 3), 1);
   fgl_tex_object_changed(ctx);
}

/* [S: teximage.c:copyteximage, copytexture_error_check] */
static void copy_tex_image(GLuint dims, GLenum target, GLint level, GLenum internal, GLint x,
                           GLint y, GLsizei width, GLsizei height, GLint border)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag && !fgl_save_copy_tex_image(ctx, dims, target, level, internal, x, y,
                                                    width, height, border))
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_flush_vertices(ctx);
   fgl_scene_flush(ctx);   /* the scene may sample the images */
   /* legal_texsubimage_target: no proxies */
   if (target != (dims == 1 ? GL_TEXTURE_1D : GL_TEXTURE_2D) &&
       !(dims == 2 && is_cube_face(target))) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (level < 0 || level >= FGL_MAX_TEXTURE_LEVELS) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (border < 0 || border > 1) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   /* the unsized component counts 1..4 are not taken */
   if (internal >= 1 && internal <= 4) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   const struct tex_format *tf = find_format((GLint)internal);
   if (!tf) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   /* [S: teximage.c:copytexture_error_check] S3TC: a border is
    * GL_INVALID_OPERATION */
   const GLenum cf = s3tc_format_of((GLint)internal, target);
   if (fgl_s3tc_block_bytes(internal, NULL)) {
      if (!cf) {
         fgl_error(ctx, GL_INVALID_ENUM);
         return;
      }
      if (border != 0) {
         fgl_error(ctx, GL_INVALID_OPERATION);
         return;
      }
   }
   /* _mesa_get_read_renderbuffer_for_format: no colour read buffer under
    * glReadBuffer(GL_NONE); a depth format reads the depth buffer */
   if (tf->base == GL_DEPTH_COMPONENT ? !fgl_read_fb(ctx) || !fgl_read_fb(ctx)->Depth
                                      : ctx->Pixel.ReadBuffer == GL_NONE) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (!legal_dimensions(target, dims, level, width, height, 1, border)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   const struct fgl_tex_pipe_format *pf = cf ? s3tc_pipe_format(cf) : tf->pf;
   struct fgl_texture_object *t = target_object(ctx, target);
   const unsigned face = target_face(target);
   struct fgl_texture_image *old = *image_slot(t, target, level);
   /* can_avoid_reallocation: the same format and size keeps the storage,
    * and the texels outside the framebuffer keep their values */
   if (old && old->InternalFormat == internal && old->Format == pf && border == 0 &&
       old->Depth == 1 &&
       old->Border == 0 && old->Width == width && old->Height == height) {
      copy_texels(ctx, old, 0, 0, 0, x, y, width, height);
      check_gen_mipmap(ctx, t, face, level);
      return;
   }
   if (!size_ok(dims, pf, width, height, 1, is_cube_target(target) ? 6 : 1)) {
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   if (border) {
      x += 1;
      width -= 2;
      if (dims == 2) {
         y += 1;
         height -= 2;
      }
   }
   struct fgl_texture_image *img =
      new_image(width, height, 1, 0, (GLint)internal, tf->base, pf);
   if (!img || !alloc_texels(img) || (cf && !alloc_blocks(img, cf, old))) {
      free_image(img);
      fgl_error(ctx, GL_OUT_OF_MEMORY);
      return;
   }
   set_image(t, face, level, img);
   fgl_tex_object_changed(ctx);
   if (width && height)
      copy_texels(ctx, img, 0, 0, 0, x, y, width, height);
   check_gen_mipmap(ctx, t, face, level);
}

void GLAPIENTRY glCopyTexImage1D(GLenum target, GLint level, GLenum internalformat, GLint x,
                                 GLint y, GLsizei width, GLint border)
{
   copy_tex_image(1, target, level, internalformat, x, y, width, 1, border);
}

void GLAPIENTRY glCopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x,
                                 GLint y, GLsizei width, GLsizei height, GLint border)
{
   copy_tex_image(2, target, level, internalformat, x, y, width, height, border);
}

/* [S: teximage.c:copy_texture_sub_image_err, copytexsubimage_error_check] */
static void copy_tex_sub_image(GLuint dims, GLenum target, GLint level, GLint xoff,
                               GLint yoff, GLint zoff, GLint x, GLint y, GLsizei width,
                               GLsizei height)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag &&
       !(dims == 3 ? fgl_save_copy_tex_sub_image_3d(ctx, target, level, xoff, yoff, zoff, x, y,
                                                    width, height)
                   : fgl_save_copy_tex_sub_image(ctx, dims, target, level, xoff, yoff, x, y,
                                                 width, height)))
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* _mesa_CopyTexSubImage{1,2}D check the target (no proxies) before
    * copy_texture_sub_image_err's FLUSH_VERTICES: a bad target raises
    * GL_INVALID_ENUM with the vertex format untouched (a glTexCoord4f,
    * glTexCoord3f after it keeps q; the API fuzzer's seed 150) */
   if (target != (dims == 1 ? GL_TEXTURE_1D : dims == 2 ? GL_TEXTURE_2D : GL_TEXTURE_3D) &&
       !(dims == 2 && is_cube_face(target))) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   fgl_flush_vertices(ctx);
   fgl_scene_flush(ctx);   /* the scene may sample the images */
   if (level < 0 || level >= max_levels(target)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   struct fgl_texture_object *t = target_object(ctx, target);
   struct fgl_texture_image *img = *image_slot(t, target, level);
   if (!img) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (width < 0 || (dims > 1 && height < 0)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (sub_dimensions_error(ctx, dims, img, xoff, yoff, zoff, width, height, 1) ||
       block_alignment_error(ctx, img, xoff, yoff, width, height))
      return;
   /* _mesa_source_buffer_exists */
   if (img->BaseFormat == GL_DEPTH_COMPONENT ? !fgl_read_fb(ctx) || !fgl_read_fb(ctx)->Depth
                                             : ctx->Pixel.ReadBuffer == GL_NONE) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (width == 0 || height == 0)
      return;
   copy_texels(ctx, img, xoff, yoff, zoff, x, y, width, height);
   check_gen_mipmap(ctx, t, target_face(target), level);
}

void GLAPIENTRY glCopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x,
                                    GLint y, GLsizei width)
{
   copy_tex_sub_image(1, target, level, xoffset, 0, 0, x, y, width, 1);
}

void GLAPIENTRY glCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset,
                                    GLint yoffset, GLint x, GLint y, GLsizei width,
                                    GLsizei height)
{
   copy_tex_sub_image(2, target, level, xoffset, yoffset, 0, x, y, width, height);
}

void GLAPIENTRY glCopyTexSubImage3D(GLenum target, GLint level, GLint xoffset,
                                    GLint yoffset, GLint zoffset, GLint x, GLint y,
                                    GLsizei width, GLsizei height)
{
   copy_tex_sub_image(3, target, level, xoffset, yoffset, zoffset, x, y, width, height);
}

void GLAPIENTRY glCopyTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset,
                                       GLint yoffset, GLint zoffset, GLint x, GLint y,
                                       GLsizei width, GLsizei height)
{
   copy_tex_sub_image(3, target, level, xoffset, yoffset, zoffset, x, y, width, height);
}

/* ------------------------------------------------------------------ */
/* glGetTexImage                                                      */
/* ------------------------------------------------------------------ */

/* [S: texgetimage.c:legal_getteximage_target] the targets the oracle
 * takes; fixgl has images on 1D and 2D only, the others have none */
static bool legal_get_target(GLenum target)
{
   switch (target) {
   case GL_TEXTURE_1D: case GL_TEXTURE_2D: case GL_TEXTURE_3D:
   case GL_TEXTURE_CUBE_MAP_POSITIVE_X: case GL_TEXTURE_CUBE_MAP_NEGATIVE_X:
   case GL_TEXTURE_CUBE_MAP_POSITIVE_Y: case GL_TEXTURE_CUBE_MAP_NEGATIVE_Y:
   case GL_TEXTURE_CUBE_MAP_POSITIVE_Z: case GL_TEXTURE_CUBE_MAP_NEGATIVE_Z:
   case GL_TEXTURE_RECTANGLE: case GL_TEXTURE_1D_ARRAY: case GL_TEXTURE_2D_ARRAY:
   case GL_TEXTURE_CUBE_MAP_ARRAY:
      return true;
   default:
      return false;
   }
}

void GLAPIENTRY glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type,
                              GLvoid *pixels)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   fgl_flush_vertices(ctx);
   if (!legal_get_target(target)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (level < 0 || level >= max_levels(target)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   const GLenum err = fgl_error_check_format_and_type(ctx, format, type);
   if (err != GL_NO_ERROR) {
      fgl_error(ctx, err);
      return;
   }
   if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D && target != GL_TEXTURE_3D &&
       !is_cube_face(target))
      return;   /* no image: nothing to do */
   const struct fgl_texture_object *tobj = target_object(ctx, target);
   const struct fgl_texture_image *img = *image_slot(target_object(ctx, target), target, level);
   if (!img || img->Width == 0 || img->Height == 0 || img->Depth == 0)
      return;
   /* teximage_error_check: a colour image reads back as colours only, a
    * depth image as GL_DEPTH_COMPONENT only */
   const bool depth_image = img->BaseFormat == GL_DEPTH_COMPONENT;
   if (depth_image ? !is_depth_format(format)
                   : is_depth_format(format) || is_depthstencil_format(format) ||
                        format == GL_STENCIL_INDEX) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (!pixels)
      return;
   if (depth_image) {
      fgl_flush_bitmap_cache(ctx);
      for (int k = 0; k < img->Depth; k++)
         fgl_tex_get_depth(ctx, img, k, type, pixels);
      return;
   }
   /* [S: st_cb_texture.c:st_GetTexSubImage] glBitmap's cache is drawn
    * first */
   fgl_flush_bitmap_cache(ctx);
   /* [S: texgetimage.c:get_tex_rgba_uncompressed] the texels through
    * pixelformat's packer (the rebase of L/LA/I/A/RGB images, L = R) */
   /* a 3D image slice by slice, each at its slice's address
    * (GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES) */
   const size_t slice = (size_t)img->Width * (size_t)img->Height;
   uint8_t *cpu = NULL;
   if (reads_through_cpu(tobj, img)) {
      cpu = fgl_malloc_gl(ctx, slice * (size_t)img->Depth * 4);
      if (!cpu) {
         fgl_error(ctx, GL_OUT_OF_MEMORY);
         return;
      }
      readback_texels(tobj, img, cpu);
   }
   for (int k = 0; k < img->Depth; k++) {
      void *dst = target == GL_TEXTURE_3D
                     ? (void *)(uintptr_t)slice_address(&ctx->Pack, pixels, img->Width,
                                                        img->Height, format, type, k)
                     : pixels;
      if (img->Store)
         fgl_pack_tex_stored(ctx, &ctx->Pack, img->Width, img->Height, img->BaseFormat,
                             img->Store + 4 * slice * (size_t)k, img->StoreBits,
                             max_bits(img->Format) == 16, format, type, dst);
      else
         fgl_pack_rgba8(ctx, &ctx->Pack,
                        FGL_PACK_TEXIMAGE | (cpu ? FGL_PACK_CPU_DECODED : 0u), img->Width,
                        img->Height,
                        img->BaseFormat, (cpu ? cpu : img->Data) + 4 * slice * (size_t)k,
                        format, type, dst);
   }
   fgl_free(cpu);
}

/* ------------------------------------------------------------------ */
/* glGetTexLevelParameter                                             */
/* ------------------------------------------------------------------ */

/* [S: glformats.c:_mesa_legal_get_tex_level_parameter_target] */
static bool legal_level_param_target(GLenum target)
{
   switch (target) {
   case GL_TEXTURE_1D: case GL_PROXY_TEXTURE_1D:
   case GL_TEXTURE_2D: case GL_PROXY_TEXTURE_2D:
   case GL_TEXTURE_3D: case GL_PROXY_TEXTURE_3D:
   case GL_TEXTURE_CUBE_MAP_POSITIVE_X: case GL_TEXTURE_CUBE_MAP_NEGATIVE_X:
   case GL_TEXTURE_CUBE_MAP_POSITIVE_Y: case GL_TEXTURE_CUBE_MAP_NEGATIVE_Y:
   case GL_TEXTURE_CUBE_MAP_POSITIVE_Z: case GL_TEXTURE_CUBE_MAP_NEGATIVE_Z:
   case GL_PROXY_TEXTURE_CUBE_MAP:
   case GL_TEXTURE_RECTANGLE: case GL_PROXY_TEXTURE_RECTANGLE:
   case GL_TEXTURE_1D_ARRAY: case GL_PROXY_TEXTURE_1D_ARRAY:
   case GL_TEXTURE_2D_ARRAY: case GL_PROXY_TEXTURE_2D_ARRAY:
   case GL_TEXTURE_CUBE_MAP_ARRAY: case GL_PROXY_TEXTURE_CUBE_MAP_ARRAY:
   case GL_TEXTURE_2D_MULTISAMPLE: case GL_PROXY_TEXTURE_2D_MULTISAMPLE:
   case GL_TEXTURE_2D_MULTISAMPLE_ARRAY: case GL_PROXY_TEXTURE_2D_MULTISAMPLE_ARRAY:
      return true;
   default:
      return false;
   }
}

static int level_param_max_levels(GLenum target)
{
   switch (target) {
   case GL_TEXTURE_2D_MULTISAMPLE: case GL_PROXY_TEXTURE_2D_MULTISAMPLE:
   case GL_TEXTURE_2D_MULTISAMPLE_ARRAY: case GL_PROXY_TEXTURE_2D_MULTISAMPLE_ARRAY:
      return 1;
   default:
      return max_levels(target);
   }
}

/* [S: glformats.c:_mesa_base_format_has_channel] */
static bool has_channel(GLenum base, GLenum pname)
{
   switch (pname) {
   case GL_TEXTURE_RED_SIZE:
      return base == GL_RGB || base == GL_RGBA;
   case GL_TEXTURE_GREEN_SIZE:
      return base == GL_RGB || base == GL_RGBA;
   case GL_TEXTURE_BLUE_SIZE:
      return base == GL_RGB || base == GL_RGBA;
   case GL_TEXTURE_ALPHA_SIZE:
      return base == GL_ALPHA || base == GL_LUMINANCE_ALPHA || base == GL_RGBA;
   case GL_TEXTURE_LUMINANCE_SIZE:
      return base == GL_LUMINANCE || base == GL_LUMINANCE_ALPHA;
   case GL_TEXTURE_INTENSITY_SIZE:
      return base == GL_INTENSITY;
   default:
      return false;
   }
}

/* [S: texparam.c:get_tex_level_parameteriv, get_tex_level_parameter_image]
 * false after an error */
static bool tex_level_parameter(struct fgl_context *ctx, GLenum target, GLint level,
                                GLenum pname, GLint *v)
{
   if (!legal_level_param_target(target)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return false;
   }
   if (level < 0 || level >= level_param_max_levels(target)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return false;
   }
   const struct fgl_texture_image *img = NULL;
   if (target == GL_TEXTURE_1D || target == GL_TEXTURE_2D || target == GL_TEXTURE_3D ||
       is_cube_face(target) || is_proxy(target))
      img = *image_slot(target_object(ctx, target), target, level);
   /* an undefined image reads as Mesa's dummy image: sizes 0, internal
    * format GL_RGBA, no format */
   const GLenum base = img ? img->BaseFormat : GL_NONE;
   const struct fgl_tex_pipe_format *pf = img ? img->Format : NULL;
   switch (pname) {
   case GL_TEXTURE_WIDTH:
      *v = img ? img->Width : 0;
      return true;
   case GL_TEXTURE_HEIGHT:
      *v = img ? img->Height : 0;
      return true;
   case GL_TEXTURE_DEPTH:
      *v = img ? img->Depth : 0;
      return true;
   case GL_TEXTURE_INTERNAL_FORMAT:
      /* [S: texparam.c: _mesa_generic_compressed_format_to_uncompressed_format]
       * a generic compressed format stored uncompressed reads as its base */
      *v = img ? (GLint)fgl_tex_reported_internal_format(img) : GL_RGBA;
      return true;
   case GL_TEXTURE_BORDER:
      *v = img ? img->Border : 0;
      return true;
   case GL_TEXTURE_RED_SIZE:
      *v = has_channel(base, pname) ? pf->r : 0;
      return true;
   case GL_TEXTURE_GREEN_SIZE:
      *v = has_channel(base, pname) ? pf->g : 0;
      return true;
   case GL_TEXTURE_BLUE_SIZE:
      *v = has_channel(base, pname) ? pf->b : 0;
      return true;
   case GL_TEXTURE_ALPHA_SIZE:
      *v = has_channel(base, pname) ? pf->a : 0;
      return true;
   case GL_TEXTURE_LUMINANCE_SIZE:
      *v = has_channel(base, pname) ? pf->l : 0;
      return true;
   case GL_TEXTURE_INTENSITY_SIZE:
      *v = has_channel(base, pname) ? pf->i : 0;
      return true;
   case GL_TEXTURE_DEPTH_SIZE:
      *v = img ? fgl_tex_image_depth_bits(img) : 0;
      return true;
   case GL_TEXTURE_COMPRESSED:
      *v = img && img->CompressedFormat;
      return true;
   case GL_TEXTURE_COMPRESSED_IMAGE_SIZE:
      /* an uncompressed image (or none) has no compressed size */
      if (!img || !img->CompressedFormat || is_proxy(target)) {
         fgl_error(ctx, GL_INVALID_OPERATION);
         return false;
      }
      *v = fgl_compressed_image_size(img->CompressedFormat, img->Width, img->Height,
                                     img->Depth);
      return true;
   /* the oracle's GL 3.0 queries (the *_TYPE, STENCIL, SHARED and
    * sample and buffer values) are not GL 1.5's (README "Version and
    * honesty") */
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return false;
   }
}

void GLAPIENTRY glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname,
                                         GLint *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   GLint v;
   if (tex_level_parameter(ctx, target, level, pname, &v))
      *params = v;
}

void GLAPIENTRY glGetTexLevelParameterfv(GLenum target, GLint level, GLenum pname,
                                         GLfloat *params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   GLint v;
   if (tex_level_parameter(ctx, target, level, pname, &v))
      *params = (GLfloat)v;
}

/* ------------------------------------------------------------------ */
/* For main/texcompress.c                                             */
/* ------------------------------------------------------------------ */

GLenum fgl_tex_reported_internal_format(const struct fgl_texture_image *img)
{
   /* [S: texparam.c:get_tex_level_parameter_image] a compressed image
    * reports its actual compressed format */
   if (img->CompressedFormat)
      return img->CompressedFormat;
   switch (img->InternalFormat) {
   case GL_COMPRESSED_ALPHA: return GL_ALPHA;
   case GL_COMPRESSED_INTENSITY: return GL_INTENSITY;
   case GL_COMPRESSED_LUMINANCE: return GL_LUMINANCE;
   case GL_COMPRESSED_LUMINANCE_ALPHA: return GL_LUMINANCE_ALPHA;
   /* GL_COMPRESSED_RGB/RGBA of a 1D image (measured: stored
    * uncompressed, reported as the base format) */
   case GL_COMPRESSED_RGB: return GL_RGB;
   case GL_COMPRESSED_RGBA: return GL_RGBA;
   default: return img->InternalFormat;
   }
}

struct fgl_texture_object *fgl_tex_target_object(struct fgl_context *ctx, GLenum target)
{
   return target_object(ctx, target);
}

int fgl_tex_max_levels(GLenum target)
{
   return max_levels(target);
}

bool fgl_tex_legal_dimensions(GLenum target, GLuint dims, GLint level, GLint w, GLint h,
                              GLint d, GLint border)
{
   return legal_dimensions(target, dims, level, w, h, d, border);
}

struct fgl_texture_image *fgl_tex_new_compressed_image(int w, int h, int d, GLenum internal,
                                                       GLenum base)
{
   struct fgl_texture_image *img = new_image(w, h, d, 0, (GLint)internal, base,
                                             base == GL_RGB ? &PF_DXT_RGB : &PF_DXT_RGBA);
   if (img)
      img->CompressedFormat = internal;
   return img;
}

void fgl_tex_set_image(struct fgl_texture_object *t, GLenum target, GLint level,
                       struct fgl_texture_image *img)
{
   set_image(t, target_face(target), level, img);
}

void fgl_tex_image_changed(struct fgl_context *ctx, struct fgl_texture_object *t,
                           GLenum target, GLint level)
{
   check_gen_mipmap(ctx, t, target_face(target), level);
}

struct fgl_texture_image **fgl_tex_image_slot(struct fgl_texture_object *t, GLenum target,
                                              GLint level)
{
   return image_slot(t, target, level);
}

bool fgl_tex_is_2d_image_target(GLenum target, bool proxies)
{
   return target == GL_TEXTURE_2D || is_cube_face(target) ||
          (proxies && (target == GL_PROXY_TEXTURE_2D || target == GL_PROXY_TEXTURE_CUBE_MAP));
}
