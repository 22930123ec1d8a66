/*
 * S3TC texel decoding as the oracle samples it (ORACLE-NOTES.md
 * "Compressed textures"; probe p_s3tc).
 *
 * llvmpipe keeps an S3TC texture compressed and decodes each texel it
 * fetches [S: gallivm/lp_bld_format_s3tc.c: s3tc_dxt1_full_to_rgba_aos,
 * lp_build_lerp23, lp_build_pavgb, s3tc_dxt3_to_rgba_aos,
 * s3tc_dxt5_alpha_channel, lp_build_lerpdxta]; glGetTexImage of such a
 * texture goes through the same sampler (a blit), so both read the same
 * 8-bit texels.  Those texels are a pure function of the block, so fixgl
 * decodes each image once, at upload, into its RGBA8 texels and filters
 * them as any 8-bit texture (the AoS path: util_format_fits_8unorm holds
 * for S3TC).
 *
 * The decoder's arithmetic, all on 8-bit channels:
 *  - colours 565 to 8 bits by bit replication (r5 << 3 | r5 >> 2,
 *    g6 << 2 | g6 >> 4);
 *  - the thirds: d = c1 - c0 as a 16-bit signed product m = 85 * d taken
 *    unsigned (mod 2^16); colour 2 = c0 + (m >> 8), colour 3 =
 *    c0 + ((m >> 7) & 255), each sum mod 256 (not (2*c0 + c1) / 3);
 *  - DXT1 with c0 <= c1 (as 16-bit numbers): colour 2 the rounded-up
 *    average (c0 + c1 + 1) >> 1 (pavgb), colour 3 black with alpha 0 for
 *    DXT1 RGBA (1 for DXT1 RGB); DXT3 and DXT5 always take the four-colour
 *    mode;
 *  - DXT3 alpha: the texel's nibble a, a << 4 | a;
 *  - DXT5 alpha: codes 0 and 1 the two alphas; with a0 > a1 codes 2..7,
 *    with a0 <= a1 codes 2..5 interpolate: the weight
 *    ((W * (code - 1)) mod 2^16) >> 6 with W = 255*64/7 = 2331 or
 *    255*64/5 = 3264, then a0 + ((((a1 - a0) * weight) mod 2^16) >> 8),
 *    mod 256; with a0 <= a1 code 6 is 0 and code 7 is 255.
 */
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "main/texcompress_s3tc.h"

unsigned fgl_s3tc_block_bytes(GLenum format, GLenum *base)
{
   switch (format) {
   case GL_COMPRESSED_RGB_S3TC_DXT1_EXT:
      if (base)
         *base = GL_RGB;
      return 8;
   case GL_COMPRESSED_RGBA_S3TC_DXT1_EXT:
      if (base)
         *base = GL_RGBA;
      return 8;
   case GL_COMPRESSED_RGBA_S3TC_DXT3_EXT:
   case GL_COMPRESSED_RGBA_S3TC_DXT5_EXT:
      if (base)
         *base = GL_RGBA;
      return 16;
   default:
      return 0;
   }
}

/* c0 + 1/3 (k = 0) or 2/3 (k = 1) of c1 - c0, lp_build_lerp23's way */
static uint8_t lerp_third(int c0, int c1, int k)
{
   const unsigned m = (uint16_t)(85 * (c1 - c0));
   return (uint8_t)(c0 + (k ? ((m >> 7) & 255u) : (m >> 8)));
}

/* The four colours of a colour block (its first 4 bytes), RGBA8. */
static void colour_palette(const uint8_t *b, bool dxt1, bool dxt1_alpha, uint8_t pal[4][4])
{
   const unsigned c[2] = { (unsigned)b[0] | (unsigned)b[1] << 8,
                           (unsigned)b[2] | (unsigned)b[3] << 8 };
   for (int i = 0; i < 2; i++) {
      const unsigned r = c[i] >> 11, g = (c[i] >> 5) & 63u, bl = c[i] & 31u;
      pal[i][0] = (uint8_t)(r << 3 | r >> 2);
      pal[i][1] = (uint8_t)(g << 2 | g >> 4);
      pal[i][2] = (uint8_t)(bl << 3 | bl >> 2);
      pal[i][3] = 255;
   }
   if (!dxt1 || c[0] > c[1]) {
      for (int n = 0; n < 3; n++) {
         pal[2][n] = lerp_third(pal[0][n], pal[1][n], 0);
         pal[3][n] = lerp_third(pal[0][n], pal[1][n], 1);
      }
      pal[2][3] = pal[3][3] = 255;
   } else {
      for (int n = 0; n < 3; n++) {
         pal[2][n] = (uint8_t)((pal[0][n] + pal[1][n] + 1) >> 1);
         pal[3][n] = 0;
      }
      pal[2][3] = 255;
      pal[3][3] = dxt1_alpha ? 0 : 255;
   }
}

/* The eight alphas of a DXT5 alpha block (its first 2 bytes). */
static void alpha_palette(const uint8_t *b, uint8_t pal[8])
{
   const int a0 = b[0], a1 = b[1];
   const bool seven = a0 > a1;
   pal[0] = (uint8_t)a0;
   pal[1] = (uint8_t)a1;
   for (int code = 2; code < 8; code++) {
      const unsigned w = (uint16_t)((seven ? 2331 : 3264) * (code - 1)) >> 6;
      const unsigned m = (uint16_t)((a1 - a0) * (int)w);
      pal[code] = (uint8_t)(a0 + (int)(m >> 8));
   }
   if (!seven) {
      pal[6] = 0;
      pal[7] = 255;
   }
}

static void latc_decode_image(GLenum format, const uint8_t *blocks, int w, int h,
                              uint8_t *rgba);

void fgl_s3tc_decode_image(GLenum format, const uint8_t *blocks, int w, int h,
                           uint8_t *rgba)
{
   if (fgl_latc_block_bytes(format)) {
      latc_decode_image(format, blocks, w, h, rgba);
      return;
   }
   const unsigned bytes = fgl_s3tc_block_bytes(format, NULL);
   const bool dxt1 = bytes == 8;
   const bool dxt1_alpha = format == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
   const int bw = (w + 3) / 4, bh = (h + 3) / 4;
   for (int by = 0; by < bh; by++) {
      for (int bx = 0; bx < bw; bx++) {
         const uint8_t *b = blocks + ((size_t)by * (size_t)bw + (size_t)bx) * bytes;
         const uint8_t *cb = dxt1 ? b : b + 8;
         uint8_t pal[4][4], apal[8];
         colour_palette(cb, dxt1, dxt1_alpha, pal);
         if (format == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT)
            alpha_palette(b, apal);
         const uint32_t codes = (uint32_t)cb[4] | (uint32_t)cb[5] << 8 |
                                (uint32_t)cb[6] << 16 | (uint32_t)cb[7] << 24;
         uint64_t acodes = 0;
         for (int k = 0; k < 6; k++)
            acodes |= (uint64_t)b[2 + k] << (8 * k);
         for (int j = 0; j < 4 && by * 4 + j < h; j++) {
            for (int i = 0; i < 4 && bx * 4 + i < w; i++) {
               const int t = j * 4 + i;
               uint8_t *o = rgba + 4 * ((size_t)(by * 4 + j) * (size_t)w + (size_t)(bx * 4 + i));
               const uint8_t *c = pal[(codes >> (2 * t)) & 3u];
               o[0] = c[0];
               o[1] = c[1];
               o[2] = c[2];
               o[3] = c[3];
               if (format == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT) {
                  const unsigned a = (b[t >> 1] >> (4 * (t & 1))) & 15u;
                  o[3] = (uint8_t)(a << 4 | a);
               } else if (format == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT) {
                  o[3] = apal[(acodes >> (3 * t)) & 7u];
               }
            }
         }
      }
   }
}

/* ------------------------------------------------------------------ */
/* The encoder                                                        */
/* ------------------------------------------------------------------ */

/*
 * The oracle compresses uncompressed data into an S3TC format with Mesa's
 * own encoder, the libtxc_dxtn algorithm (ORACLE-NOTES.md "Compressed
 * textures: the encoder"; probe p_s3tc_encode) [S: Mesa 22.3
 * main/texcompress_s3tc.c: _mesa_texstore_rgb_dxt1 and siblings;
 * util/format/texcompress_s3tc_tmp.h: tx_compress_dxtn].  It is a
 * heuristic, not an optimum, so fixgl repeats its every step: the same
 * 8-bit integer arithmetic, the same ties, the same slips.
 *
 * Colour block (all four formats):
 *  1. the two start colours are the texels of least and greatest
 *     weighted length r^2*4 + g^2*16 + b^2 (texel (0,0) when none is
 *     smaller / greater; for DXT1 RGBA texels of alpha <= 127 are left
 *     out and mark the block as having alpha);
 *  2. one refinement (refine_ends): each texel picks the nearest of the
 *     four colours of the ordered pair (by the same weighted distance,
 *     the first of equals), its signed error is spread 3:0, 2:1, 1:2 or
 *     0:3 over the two ends, each end moves by its summed error divided
 *     (truncating) by its weight; two ends that came within a 565 step
 *     are pushed apart;
 *  3. the ends are cut to 565, the texels coded against the four-colour
 *     palette (floor((2a + b) / 3), floor((a + 2b) / 3)) and, for DXT1,
 *     against the three-colour one (floor((a + b) / 2); alpha <= 127 code
 *     3 in DXT1 RGBA); DXT1 keeps the three-colour coding when its error
 *     is smaller or the block has alpha.
 * Texels outside a partial block take no part.
 *
 * DXT3 alpha: the top four bits of each of the 16 texels of the block's
 * scratch: a partial block's missing texels keep what the block before it
 * in the same call left there (the oracle's uninitialised local array).
 *
 * DXT5 alpha (encode_alpha_channel): a block whose alphas are all 0 or all
 * 255 is written as that alpha with all codes 0, its second byte left as
 * it was; otherwise the best of up to three codings: 8 alphas between the
 * extremes found (0 and 255 taking part), 6 alphas between the inner
 * extremes plus 0 and 255 (tried when the first errs by 32 or more), and
 * that with adjusted ends (tried when both err by more than 96).
 */

enum { RED_W = 4, GREEN_W = 16, BLUE_W = 1, ALPHA_CUT = 127 };

/* the block's texels, [row][column][channel] */
typedef uint8_t s3tc_texels[4][4][4];

static unsigned weighted_length(const uint8_t *c)
{
   return (unsigned)(c[0] * c[0] * RED_W + c[1] * c[1] * GREEN_W + c[2] * c[2] * BLUE_W);
}

/* weighted squared distance of texel c from palette colour p, and the
 * signed channel differences */
static unsigned colour_error(const uint8_t *c, const uint8_t *p, int diff[3])
{
   const int dr = c[0] - p[0], dg = c[1] - p[1], db = c[2] - p[2];
   if (diff) {
      diff[0] = dr;
      diff[1] = dg;
      diff[2] = db;
   }
   return (unsigned)(dr * dr * RED_W) + (unsigned)(dg * dg * GREEN_W) +
          (unsigned)(db * db * BLUE_W);
}

/* the colour's 565 value, as the encoder compares them */
static unsigned pack565(const uint8_t *c)
{
   return (unsigned)(c[0] & 0xf8) << 8 | (unsigned)(c[1] & 0xfc) << 3 | (unsigned)c[2] >> 3;
}

static void four_palette(uint8_t e[2][3], uint8_t pal[4][3])
{
   for (int n = 0; n < 3; n++) {
      pal[0][n] = e[0][n];
      pal[1][n] = e[1][n];
      pal[2][n] = (uint8_t)((e[0][n] * 2 + e[1][n]) / 3);
      pal[3][n] = (uint8_t)((e[0][n] + e[1][n] * 2) / 3);
   }
}

static uint8_t clamp_u8(int v)
{
   return (uint8_t)(v <= 0 ? 0 : v >= 255 ? 255 : v);
}

static uint8_t add_sat(uint8_t v, int add)
{
   return (uint8_t)(v + add <= 255 ? v + add : 255);
}

/* Step 2: moves the two ends toward the texels' mean errors. */
static void refine_ends(s3tc_texels px, int nx, int ny, uint8_t ends[2][3])
{
   uint8_t e[2][3], pal[4][3];
   const bool keep = pack565(ends[0]) < pack565(ends[1]);
   memcpy(e[0], ends[keep ? 0 : 1], 3);
   memcpy(e[1], ends[keep ? 1 : 0], 3);
   four_palette(e, pal);
   /* the share of each end in each palette entry, out of 3 */
   static const int share[4][2] = { { 3, 0 }, { 0, 3 }, { 2, 1 }, { 1, 2 } };
   int err[2][3] = { { 0 } };
   int weight[2] = { 0, 0 };
   for (int j = 0; j < ny; j++) {
      for (int i = 0; i < nx; i++) {
         unsigned best = 0xffffffffu;
         int code = 0, best_diff[3] = { 0, 0, 0 };
         for (int k = 0; k < 4; k++) {
            int diff[3];
            const unsigned d = colour_error(px[j][i], pal[k], diff);
            if (d < best) {
               best = d;
               code = k;
               memcpy(best_diff, diff, sizeof(best_diff));
            }
         }
         for (int s = 0; s < 2; s++) {
            for (int n = 0; n < 3; n++)
               err[s][n] += share[code][s] * best_diff[n];
            weight[s] += share[code][s];
         }
      }
   }
   for (int s = 0; s < 2; s++) {
      if (weight[s] == 0)
         weight[s] = 1;
      for (int n = 0; n < 3; n++)
         e[s][n] = clamp_u8(e[s][n] + err[s][n] / weight[s]);
   }
   /* ends that may meet in 565: pushed apart along green, and along red
    * and blue on the side the oracle picks (its red test compares with
    * the other end's green, as it does) */
   const int dr = abs(e[0][0] - e[1][0]), dg = abs(e[0][1] - e[1][1]),
             db = abs(e[0][2] - e[1][2]);
   if (dr < 8 && dg < 4 && db < 8) {
      const int red = dr, green = 2 * dg, blue = db;
      int most = red > green ? red : green;
      most = most > blue ? most : blue;
      if (most > 0) {
         const int f = most > 4 ? 2 : most > 2 ? 3 : 4;
         const int hi = e[1][1] >= e[0][1] ? 1 : 0, lo = 1 - hi;
         e[hi][1] = add_sat(e[hi][1], f * green);
         if (e[hi][0] - e[lo][1] > 0)
            e[hi][0] = add_sat(e[hi][0], f * red);
         else
            e[lo][0] = add_sat(e[lo][0], f * red);
         if (e[hi][2] - e[lo][2] > 0)
            e[hi][2] = add_sat(e[hi][2], f * blue);
         else
            e[lo][2] = add_sat(e[lo][2], f * blue);
      }
   }
   /* the oracle's order test shifts the whole of the second 565 value
    * right by 3 (a misplaced parenthesis) */
   const unsigned second = ((unsigned)(e[1][0] & 0xf8) << 8 | (unsigned)(e[1][1] & 0xfc) << 3 |
                            e[1][2]) >> 3;
   const bool in_order = pack565(e[0]) < second;
   memcpy(ends[0], e[in_order ? 0 : 1], 3);
   memcpy(ends[1], e[in_order ? 1 : 0], 3);
}

static void put_colour_block(uint8_t *out, unsigned c0, unsigned c1, uint32_t codes)
{
   out[0] = (uint8_t)c0;
   out[1] = (uint8_t)(c0 >> 8);
   out[2] = (uint8_t)c1;
   out[3] = (uint8_t)(c1 >> 8);
   for (int k = 0; k < 4; k++)
      out[4 + k] = (uint8_t)(codes >> (8 * k));
}

/* Step 3: codes the texels against the 565 ends and writes the block. */
static void code_colour_block(uint8_t *out, s3tc_texels px, int nx, int ny,
                              uint8_t ends[2][3], GLenum format, bool has_alpha)
{
   for (int s = 0; s < 2; s++) {
      ends[s][0] &= 0xf8;
      ends[s][1] &= 0xfc;
      ends[s][2] &= 0xf8;
   }
   unsigned c0 = pack565(ends[0]), c1 = pack565(ends[1]);
   uint8_t e[2][3];
   const bool swap = c0 < c1;
   memcpy(e[0], ends[swap ? 1 : 0], 3);
   memcpy(e[1], ends[swap ? 0 : 1], 3);
   if (swap) {
      const unsigned t = c0;
      c0 = c1;
      c1 = t;
   }
   uint8_t pal[4][3];
   four_palette(e, pal);
   unsigned err4 = 0, err3 = 0xffffffffu;
   uint32_t codes4 = 0, codes3 = 0;
   for (int j = 0; j < ny; j++) {
      for (int i = 0; i < nx; i++) {
         unsigned best = 0xffffffffu;
         unsigned code = 0;
         for (unsigned k = 0; k < 4; k++) {
            const unsigned d = colour_error(px[j][i], pal[k], NULL);
            if (d < best) {
               best = d;
               code = k;
            }
         }
         err4 += best;
         codes4 |= code << (2 * (j * 4 + i));
      }
   }
   if (format == GL_COMPRESSED_RGB_S3TC_DXT1_EXT ||
       format == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT) {
      /* the three-colour palette, written with the ends exchanged (c1
       * first), so entries 0 and 1 swap codes */
      for (int n = 0; n < 3; n++) {
         pal[2][n] = (uint8_t)((e[0][n] + e[1][n]) / 2);
         pal[3][n] = 0;
      }
      err3 = 0;
      for (int j = 0; j < ny; j++) {
         for (int i = 0; i < nx; i++) {
            unsigned best = 0xffffffffu;
            unsigned code = 0;
            if (format == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT && px[j][i][3] <= ALPHA_CUT) {
               code = 3;
               best = 0;
            } else {
               for (unsigned k = 0; k < 3; k++) {
                  const unsigned d = colour_error(px[j][i], pal[k], NULL);
                  if (d < best) {
                     best = d;
                     code = k > 1 ? k : k ^ 1u;
                  }
               }
            }
            err3 += best;
            codes3 |= code << (2 * (j * 4 + i));
         }
      }
   }
   if (err4 > err3 || has_alpha)
      put_colour_block(out, c1, c0, codes3);
   else
      put_colour_block(out, c0, c1, codes4);
}

static void encode_colour_block(uint8_t *out, s3tc_texels px, int nx, int ny,
                                GLenum format)
{
   const uint8_t *lo = px[0][0], *hi = px[0][0];
   unsigned lo_len = weighted_length(px[0][0]), hi_len = lo_len;
   bool has_alpha = false;
   for (int j = 0; j < ny; j++) {
      for (int i = 0; i < nx; i++) {
         if (format == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT && px[j][i][3] <= ALPHA_CUT) {
            has_alpha = true;
            continue;
         }
         const unsigned len = weighted_length(px[j][i]);
         if (len > hi_len) {
            hi_len = len;
            hi = px[j][i];
         } else if (len < lo_len) {
            lo_len = len;
            lo = px[j][i];
         }
      }
   }
   uint8_t ends[2][3];
   memcpy(ends[0], lo, 3);
   memcpy(ends[1], hi, 3);
   refine_ends(px, nx, ny, ends);
   code_colour_block(out, px, nx, ny, ends, format, has_alpha);
}

static void put_alpha_block(uint8_t *out, uint8_t a0, uint8_t a1, const uint8_t codes[16])
{
   out[0] = a0;
   out[1] = a1;
   uint64_t bits = 0;
   for (int t = 0; t < 16; t++)
      bits |= (uint64_t)codes[t] << (3 * t);
   for (int k = 0; k < 6; k++)
      out[2 + k] = (uint8_t)(bits >> (8 * k));
}

/* The six-alpha coding between lo and hi (0 and 255 as codes 6 and 7
 * when `extremes`, else by the cuts at lo/2 and (255 + hi)/2); returns
 * its squared error. */
static unsigned six_alpha_coding(s3tc_texels px, int ch, int nx, int ny, int lo, int hi,
                                 bool exact_extremes, uint8_t codes[16])
{
   uint8_t cut[5];
   for (int k = 0; k < 5; k++)
      cut[k] = (uint8_t)((lo * (10 - (2 * k + 1)) + hi * (2 * k + 1)) / 10);
   unsigned err = 0;
   for (int j = 0; j < ny; j++) {
      for (int i = 0; i < nx; i++) {
         const int a = px[j][i][ch];
         int code, dist;
         if (exact_extremes ? a == 0 : a <= lo / 2) {
            code = 6;
            dist = a;
         } else if (exact_extremes ? a == 255 : a > (255 + hi) / 2) {
            code = 7;
            dist = 255 - a;
         } else if (a <= cut[0]) {
            code = 0;
            dist = a - lo;
         } else if (a <= cut[4]) {
            int k = 1;
            while (a > cut[k])
               k++;
            /* codes 2..5: (lo * (5 - k) + hi * k) / 5 */
            code = k + 1;
            dist = a - (lo * (5 - k) + hi * k) / 5;
         } else {
            code = 1;
            dist = a - hi;
         }
         if (exact_extremes && (code == 6 || code == 7))
            dist = 0;
         dist = (int16_t)dist;
         err += (unsigned)(dist * dist);
         codes[4 * j + i] = (uint8_t)code;
      }
   }
   return err;
}

/* What an image's blocks share (the oracle's stack arrays, whose entries
 * for the texels outside a partial block keep the last block's values):
 * the texels and the three alpha codings. */
struct s3tc_scratch {
   s3tc_texels px;
   uint8_t codes1[16], codes2[16], codes3[16];
};

/* The DXT5 alpha coding of channel `ch` of the block's texels; `rgtc`:
 * the RGTC/LATC encoder's variant [S: util/format/texcompress_rgtc_tmp.h:
 * encode_rgtc_ubyte], which also writes a block of one value other than 0
 * and 255 as that value with all codes 0 (its second byte unwritten). */
static void encode_alpha_channel(uint8_t *out, struct s3tc_scratch *s, int ch, bool rgtc,
                                 int nx, int ny)
{
   uint8_t(*const px)[4][4] = s->px;
   uint8_t *const codes1 = s->codes1, *const codes2 = s->codes2, *const codes3 = s->codes3;
   int lo = 255, hi = 0;
   bool has0 = false, has255 = false;
   for (int j = 0; j < ny; j++) {
      for (int i = 0; i < nx; i++) {
         const int a = px[j][i][ch];
         if (a == 0)
            has0 = true;
         else if (a == 255)
            has255 = true;
         else {
            hi = a > hi ? a : hi;
            lo = a < lo ? a : lo;
         }
      }
   }
   if ((lo > hi && !(has0 && has255)) || (rgtc && lo == hi && !has0 && !has255)) {
      /* all 0 or all 255 (or, for RGTC, all one value): codes 0; byte 1
       * is not written */
      out[0] = px[0][0][ch];
      memset(out + 2, 0, 6);
      return;
   }
   /* coding 1: eight alphas from `use_hi` (alpha 0) down to `use_lo` */
   const int use_lo = has0 ? 0 : lo, use_hi = has255 ? 255 : hi;
   uint8_t cut[7];
   for (int k = 0; k < 7; k++)
      cut[k] = (uint8_t)((use_lo * (2 * k + 1) + use_hi * (14 - (2 * k + 1))) / 14);
   unsigned err1 = 0, err2 = 0xffffffffu, err3 = 0xffffffffu;
   for (int j = 0; j < ny; j++) {
      for (int i = 0; i < nx; i++) {
         const int a = px[j][i][ch];
         int code, dist;
         if (a > cut[0]) {
            code = 0;
            dist = a - use_hi;
         } else if (a > cut[6]) {
            int k = 1;
            while (a <= cut[k])
               k++;
            /* codes 2..7: (use_hi * (7 - k) + use_lo * k) / 7 */
            code = k + 1;
            dist = a - (use_hi * (7 - k) + use_lo * k) / 7;
         } else {
            code = 1;
            dist = a - use_lo;
         }
         dist = (int16_t)dist;
         err1 += (unsigned)(dist * dist);
         codes1[4 * j + i] = (uint8_t)code;
      }
   }
   int t_lo = 0, t_hi = 0;
   if (err1 >= 32) {
      err2 = six_alpha_coding(px, ch, nx, ny, lo, hi, true, codes2);
      if (err2 > 96 && err1 > 96) {
         /* coding 3: inner ends away from 0 and 255, moved by the mean
          * error of the alphas between them */
         t_lo = 0xff;
         t_hi = 0;
         const int margin = (hi - lo) / 28;
         for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
               const int a = px[j][i][ch];
               if (a > t_hi && a < 255 - margin)
                  t_hi = a;
               if (a < t_lo && a > margin)
                  t_lo = a;
            }
         }
         if (t_hi <= t_lo) {
            t_lo = 1;
            t_hi = 254;
         }
         uint8_t c[5];
         for (int k = 0; k < 5; k++)
            c[k] = (uint8_t)((t_lo * (10 - (2 * k + 1)) + t_hi * (2 * k + 1)) / 10);
         int16_t sum_lo = 0, sum_hi = 0;
         int n_lo = 0, n_hi = 0;
         for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
               const int a = px[j][i][ch];
               if (a <= t_lo / 2 || a > (255 + t_hi) / 2)
                  continue;
               if (a <= c[0]) {
                  sum_lo = (int16_t)(sum_lo + (a - t_lo));
                  n_lo++;
               } else if (a <= c[4]) {
                  int k = 1;
                  while (a > c[k])
                     k++;
                  const int d = a - (t_lo * (5 - k) + t_hi * k) / 5;
                  sum_lo = (int16_t)(sum_lo + d);
                  sum_hi = (int16_t)(sum_hi + d);
                  n_lo++;
                  n_hi++;
               } else {
                  sum_hi = (int16_t)(sum_hi + (a - t_hi));
                  n_hi++;
               }
            }
         }
         n_lo = (uint8_t)n_lo ? (uint8_t)n_lo : 1;
         n_hi = (uint8_t)n_hi ? (uint8_t)n_hi : 1;
         t_lo = (int16_t)(t_lo + sum_lo / n_lo);
         if (t_lo < 0)
            t_lo = 0;
         t_hi = (int16_t)(t_hi + sum_hi / n_hi);
         if (t_hi > 255)
            t_hi = 255;
         err3 = six_alpha_coding(px, ch, nx, ny, t_lo, t_hi, false, codes3);
      }
   }
   if (err1 <= err2 && err1 <= err3)
      put_alpha_block(out, (uint8_t)use_hi, (uint8_t)use_lo, codes1);
   else if (err2 <= err3)
      put_alpha_block(out, (uint8_t)lo, (uint8_t)hi, codes2);
   else
      put_alpha_block(out, (uint8_t)t_lo, (uint8_t)t_hi, codes3);
}

static void latc_encode_image(GLenum format, const uint8_t *rgba, int w, int h,
                              uint8_t *blocks, size_t row_bytes);

void fgl_s3tc_encode_image(GLenum format, const uint8_t *rgba, int w, int h, uint8_t *blocks,
                           size_t row_bytes)
{
   if (fgl_latc_block_bytes(format)) {
      latc_encode_image(format, rgba, w, h, blocks, row_bytes);
      return;
   }
   const unsigned bytes = fgl_s3tc_block_bytes(format, NULL);
   /* the scratch lives for the whole image (see DXT3 above) */
   struct s3tc_scratch s;
   memset(&s, 0, sizeof(s));
   for (int y = 0; y < h; y += 4) {
      const int ny = h - y < 4 ? h - y : 4;
      uint8_t *out = blocks + (size_t)(y / 4) * row_bytes;
      for (int x = 0; x < w; x += 4, out += bytes) {
         const int nx = w - x < 4 ? w - x : 4;
         for (int j = 0; j < ny; j++)
            memcpy(s.px[j], rgba + 4 * ((size_t)(y + j) * (size_t)w + (size_t)x),
                   4 * (size_t)nx);
         if (format == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT) {
            for (int j = 0; j < 4; j++)
               for (int i = 0; i < 4; i += 2)
                  out[j * 2 + i / 2] =
                     (uint8_t)(s.px[j][i][3] >> 4 | (s.px[j][i + 1][3] & 0xf0));
         } else if (format == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT) {
            encode_alpha_channel(out, &s, 3, false, nx, ny);
         }
         encode_colour_block(bytes == 16 ? out + 8 : out, s.px, nx, ny, format);
      }
   }
}

/* ------------------------------------------------------------------ */
/* LATC: GL_COMPRESSED_LUMINANCE and GL_COMPRESSED_LUMINANCE_ALPHA     */
/* ------------------------------------------------------------------ */

/*
 * The oracle stores the generic GL_COMPRESSED_LUMINANCE as LATC1 and
 * GL_COMPRESSED_LUMINANCE_ALPHA as LATC2 (ORACLE-NOTES.md "Compressed
 * textures: LATC"; probe p_latc) [S: st_format.c:format_map;
 * texcompress_rgtc.c:_mesa_texstore_red_rgtc1, _mesa_texstore_rg_rgtc2].
 * A LATC1 block is one 8-byte DXT5-style alpha block of the luminance, a
 * LATC2 block one of the luminance then one of the alpha.
 *  - Encoder: the data first stored as into an L8 / L8A8 image, then each
 *    block's channel coded by the RGTC encoder, the DXT5 alpha coder of
 *    libtxc with one more shortcut (encode_alpha_channel, `rgtc`).  The
 *    encoder's code arrays are uninitialised locals of one stack frame
 *    that every call of an image (both channels of LATC2 included)
 *    reuses: the texels outside a partial block keep the codes the call
 *    before left (fixgl: one scratch per image, zero at its start).
 *  - Decoder: llvmpipe samples each channel with the DXT5 alpha decoder
 *    [S: gallivm/lp_bld_format_s3tc.c: latc1_to_rgba_aos,
 *    latc2_to_rgba_aos, s3tc_dxt5_alpha_channel]: (L, L, L, 1) and
 *    (L, L, L, A).
 */

unsigned fgl_latc_block_bytes(GLenum format)
{
   switch (format) {
   case GL_COMPRESSED_LUMINANCE_LATC1_EXT: return 8;
   case GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT: return 16;
   default: return 0;
   }
}

unsigned fgl_stored_block_bytes(GLenum format)
{
   const unsigned b = fgl_s3tc_block_bytes(format, NULL);
   return b ? b : fgl_latc_block_bytes(format);
}

static void latc_decode_image(GLenum format, const uint8_t *blocks, int w, int h,
                              uint8_t *rgba)
{
   const bool two = format == GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT;
   const unsigned bytes = two ? 16 : 8;
   const int bw = (w + 3) / 4, bh = (h + 3) / 4;
   for (int by = 0; by < bh; by++) {
      for (int bx = 0; bx < bw; bx++) {
         const uint8_t *b = blocks + ((size_t)by * (size_t)bw + (size_t)bx) * bytes;
         uint8_t lpal[8], apal[8];
         uint64_t lcodes = 0, acodes = 0;
         alpha_palette(b, lpal);
         for (int k = 0; k < 6; k++)
            lcodes |= (uint64_t)b[2 + k] << (8 * k);
         if (two) {
            alpha_palette(b + 8, apal);
            for (int k = 0; k < 6; k++)
               acodes |= (uint64_t)b[10 + k] << (8 * k);
         }
         for (int j = 0; j < 4 && by * 4 + j < h; j++) {
            for (int i = 0; i < 4 && bx * 4 + i < w; i++) {
               const int t = j * 4 + i;
               uint8_t *o = rgba + 4 * ((size_t)(by * 4 + j) * (size_t)w + (size_t)(bx * 4 + i));
               o[0] = o[1] = o[2] = lpal[(lcodes >> (3 * t)) & 7u];
               o[3] = two ? apal[(acodes >> (3 * t)) & 7u] : 255;
            }
         }
      }
   }
}

static void latc_encode_image(GLenum format, const uint8_t *rgba, int w, int h,
                              uint8_t *blocks, size_t row_bytes)
{
   const bool two = format == GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT;
   struct s3tc_scratch s;
   memset(&s, 0, sizeof(s));
   for (int y = 0; y < h; y += 4) {
      const int ny = h - y < 4 ? h - y : 4;
      uint8_t *out = blocks + (size_t)(y / 4) * row_bytes;
      for (int x = 0; x < w; x += 4, out += two ? 16 : 8) {
         const int nx = w - x < 4 ? w - x : 4;
         for (int j = 0; j < ny; j++)
            memcpy(s.px[j], rgba + 4 * ((size_t)(y + j) * (size_t)w + (size_t)x),
                   4 * (size_t)nx);
         encode_alpha_channel(out, &s, 0, true, nx, ny);
         if (two)
            encode_alpha_channel(out + 8, &s, 3, true, nx, ny);
      }
   }
}

/* [S: util/format/texcompress_rgtc_tmp.h: fetch_texel_rgtc] a channel's
 * value for code `code` of the block's end values a0, a1 in the exact
 * arithmetic of Mesa's CPU decoder: sevenths or fifths, truncated */
static uint8_t rgtc_exact(int a0, int a1, unsigned code)
{
   if (code == 0)
      return (uint8_t)a0;
   if (code == 1)
      return (uint8_t)a1;
   if (a0 > a1)
      return (uint8_t)((a0 * (8 - (int)code) + a1 * ((int)code - 1)) / 7);
   if (code < 6)
      return (uint8_t)((a0 * (6 - (int)code) + a1 * ((int)code - 1)) / 5);
   return code == 6 ? 0 : 255;
}

void fgl_latc_decode_exact(GLenum format, const uint8_t *blocks, int w, int h, uint8_t *rgba)
{
   const bool two = format == GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT;
   const unsigned bytes = two ? 16 : 8;
   const int bw = (w + 3) / 4;
   for (int y = 0; y < h; y++) {
      for (int x = 0; x < w; x++) {
         const uint8_t *b = blocks + ((size_t)(y / 4) * (size_t)bw + (size_t)(x / 4)) * bytes;
         const int t = (y & 3) * 4 + (x & 3);
         uint8_t *o = rgba + 4 * ((size_t)y * (size_t)w + (size_t)x);
         uint64_t codes = 0;
         for (int k = 0; k < 6; k++)
            codes |= (uint64_t)b[2 + k] << (8 * k);
         o[0] = o[1] = o[2] = rgtc_exact(b[0], b[1], (unsigned)(codes >> (3 * t)) & 7u);
         o[3] = 255;
         if (two) {
            codes = 0;
            for (int k = 0; k < 6; k++)
               codes |= (uint64_t)b[10 + k] << (8 * k);
            o[3] = rgtc_exact(b[8], b[9], (unsigned)(codes >> (3 * t)) & 7u);
         }
      }
   }
}

/* ------------------------------------------------------------------ */
/* Mesa's CPU decoders                                                */
/* ------------------------------------------------------------------ */

/*
 * What glGetTexImage reads of an image outside the texture object's
 * resource (main/teximage.c "Storage"; ORACLE-NOTES.md "Compressed
 * textures: LATC", cube faces of mixed formats; probe p_s3tc_cpu_decode)
 * [S: util/format/texcompress_s3tc_tmp.h: dxt135_decode_imageblock,
 * fetch_2d_texel_rgba_dxt3, fetch_2d_texel_rgba_dxt5;
 * texcompress_rgtc_tmp.h: fetch_texel_rgtc]: exact integer thirds and
 * halves of the 8-bit colours, truncated (not the sampler's lerp23 and
 * rounded-up average), the DXT3 nibble replicated, DXT5 and LATC channels
 * in exact sevenths or fifths (rgtc_exact).
 */

/* The RGBA8 colour of code `code` of a colour block (its first 8 bytes);
 * dxt1_mode: DXT1 (three colours when c0 <= c1), dxt1_alpha: DXT1 RGBA. */
static void cpu_colour(const uint8_t *b, unsigned code, bool dxt1_mode, bool dxt1_alpha,
                       uint8_t *o)
{
   const unsigned c[2] = { (unsigned)b[0] | (unsigned)b[1] << 8,
                           (unsigned)b[2] | (unsigned)b[3] << 8 };
   int e[2][3];
   for (int i = 0; i < 2; i++) {
      const unsigned r = c[i] >> 11, g = (c[i] >> 5) & 63u, bl = c[i] & 31u;
      e[i][0] = (int)(r << 3 | r >> 2);
      e[i][1] = (int)(g << 2 | g >> 4);
      e[i][2] = (int)(bl << 3 | bl >> 2);
   }
   const bool four = !dxt1_mode || c[0] > c[1];
   o[3] = 255;
   for (int n = 0; n < 3; n++) {
      int v;
      switch (code) {
      case 0: v = e[0][n]; break;
      case 1: v = e[1][n]; break;
      case 2: v = four ? (e[0][n] * 2 + e[1][n]) / 3 : (e[0][n] + e[1][n]) / 2; break;
      default: v = four ? (e[0][n] + e[1][n] * 2) / 3 : 0; break;
      }
      o[n] = (uint8_t)v;
   }
   if (code == 3 && !four && dxt1_alpha)
      o[3] = 0;
}

static uint64_t codes48(const uint8_t *b)
{
   uint64_t codes = 0;
   for (int k = 0; k < 6; k++)
      codes |= (uint64_t)b[k] << (8 * k);
   return codes;
}

void fgl_s3tc_decode_exact(GLenum format, const uint8_t *blocks, int w, int h, uint8_t *rgba)
{
   if (fgl_latc_block_bytes(format)) {
      fgl_latc_decode_exact(format, blocks, w, h, rgba);
      return;
   }
   const unsigned bytes = fgl_s3tc_block_bytes(format, NULL);
   const bool dxt1 = bytes == 8;
   const bool dxt1_alpha = format == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
   const int bw = (w + 3) / 4;
   for (int y = 0; y < h; y++) {
      for (int x = 0; x < w; x++) {
         const uint8_t *b = blocks + ((size_t)(y / 4) * (size_t)bw + (size_t)(x / 4)) * bytes;
         const uint8_t *cb = dxt1 ? b : b + 8;
         const unsigned t = (unsigned)((y & 3) * 4 + (x & 3));
         const uint32_t codes = (uint32_t)cb[4] | (uint32_t)cb[5] << 8 |
                                (uint32_t)cb[6] << 16 | (uint32_t)cb[7] << 24;
         uint8_t *o = rgba + 4 * ((size_t)y * (size_t)w + (size_t)x);
         cpu_colour(cb, (codes >> (2 * t)) & 3u, dxt1, dxt1_alpha, o);
         if (format == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT) {
            const unsigned a = (b[t >> 1] >> (4 * (t & 1))) & 15u;
            o[3] = (uint8_t)(a << 4 | a);
         } else if (format == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT) {
            o[3] = rgtc_exact(b[0], b[1], (unsigned)(codes48(b + 2) >> (3 * t)) & 7u);
         }
      }
   }
}
