/*
 * The block kernels of triangles, AVX2 + FMA (r_kernel.h).
 *
 * A triangle's box is walked in 4x4 blocks aligned to the buffer, as the
 * oracle's rasterizer walks it (lp_rast_tri_tmp.h): per block, the three
 * reduced edge functions of r_tri_cover give a 16-bit coverage mask, cut
 * to the box; each half of a covered block (4x2 pixels, lane i at
 * (x + (i & 3), y + (i >> 2))) is then shaded in 8 lanes.  Every lane does
 * the reference's operations (r_tri.c shade_pixel, r_frag.c
 * r_fragment_shader and r_fragment_ops) in the reference's order:
 *  - inputs: fma(dady, y, fma(dadx, x, a0)) (vfmadd), times 1/w, where w
 *    is the same plane evaluation and 1/w a true divide (vdivps);
 *  - colour to unorm8: max(c, 0), min(., 1), * 255, round to nearest even
 *    (vcvtps2dq under the default rounding mode, as r_round_even);
 *  - depth: z + offset (an fadd), clamped by minps/maxps (NaN -> 1, as
 *    r_clamp01), * (2^n - 1), RNE; compared as integers;
 *  - blending on unorm8 in 16-bit lanes with the oracle's normalized
 *    multiply (r_frag.c mul_u8) and a saturating add.
 * So the bytes written are the reference's.  Which state each kernel
 * covers is decided once, by r_block_choose_tri; the loops below test no
 * state: the kernel's variant is fixed at compile time (the constant
 * arguments of tri_blocks), the depth function is three masks.
 *
 * Memory: a row of a half is read and written only when one of its
 * pixels is covered (covered pixels lie inside the buffer), and a block
 * reaching past the right edge of the buffer takes the lanes one at a
 * time (finish_lanes), so no access leaves the buffer.
 */
#include "r_kernel.h"

#include <immintrin.h>
#include <string.h>

enum zfmt { ZF_NONE, ZF_16, ZF_24 };
enum blend { BL_NONE, BL_ALPHA };

#define ALWAYS_INLINE inline __attribute__((always_inline))

/* r_eval_plane in 8 lanes */
static ALWAYS_INLINE __m256 eval8(const struct r_attr_plane *p, __m256 fx, __m256 fy)
{
   return _mm256_fmadd_ps(_mm256_set1_ps(p->dady), fy,
                          _mm256_fmadd_ps(_mm256_set1_ps(p->dadx), fx, _mm256_set1_ps(p->a0)));
}

/* r_float_to_unorm8 in 8 lanes (maxps returns its second operand for NaN:
 * NaN -> 0, as !(c > 0)) */
static ALWAYS_INLINE __m256i unorm8(__m256 c)
{
   c = _mm256_max_ps(c, _mm256_setzero_ps());
   c = _mm256_min_ps(c, _mm256_set1_ps(1.0f));
   return _mm256_cvtps_epi32(_mm256_mul_ps(c, _mm256_set1_ps(255.0f)));
}

/* r_clamp01(z) * scale, RNE */
static ALWAYS_INLINE __m256i depth_unorm(__m256 z, float scale)
{
   const __m256 m = _mm256_min_ps(z, _mm256_set1_ps(1.0f));   /* NaN -> 1 */
   const __m256 c = _mm256_max_ps(m, _mm256_setzero_ps());
   return _mm256_cvtps_epi32(_mm256_mul_ps(c, _mm256_set1_ps(scale)));
}

/* lanes whose bit is set in m8 */
static ALWAYS_INLINE __m256i lane_mask(unsigned m8)
{
   const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
   return _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32((int)m8), bit), bit);
}

/* Two rows of four 32-bit pixels at p and p + stride, each read only when
 * its lanes in m8 are not all clear. */
static ALWAYS_INLINE __m256i load_rows32(const uint32_t *p, size_t stride, unsigned m8)
{
   const __m128i r0 = (m8 & 0x0f) ? _mm_loadu_si128((const __m128i *)p) : _mm_setzero_si128();
   const __m128i r1 = (m8 & 0xf0) ? _mm_loadu_si128((const __m128i *)(p + stride))
                                  : _mm_setzero_si128();
   return _mm256_set_m128i(r1, r0);
}

static ALWAYS_INLINE void store_rows32(uint32_t *p, size_t stride, unsigned m8, __m256i v)
{
   if (m8 & 0x0f)
      _mm_storeu_si128((__m128i *)p, _mm256_castsi256_si128(v));
   if (m8 & 0xf0)
      _mm_storeu_si128((__m128i *)(p + stride), _mm256_extracti128_si256(v, 1));
}

/* The same for 16-bit depth: the values widened to 32-bit lanes. */
static ALWAYS_INLINE __m256i load_rows16(const uint16_t *p, size_t stride, unsigned m8)
{
   const __m128i r0 = (m8 & 0x0f) ? _mm_loadl_epi64((const __m128i *)p) : _mm_setzero_si128();
   const __m128i r1 = (m8 & 0xf0) ? _mm_loadl_epi64((const __m128i *)(p + stride))
                                  : _mm_setzero_si128();
   return _mm256_cvtepu16_epi32(_mm_unpacklo_epi64(r0, r1));
}

static ALWAYS_INLINE void store_rows16(uint16_t *p, size_t stride, unsigned m8, __m256i v)
{
   /* values < 2^16: packus keeps them; each 128-bit half holds its row */
   const __m256i packed = _mm256_packus_epi32(v, v);
   if (m8 & 0x0f)
      _mm_storel_epi64((__m128i *)p, _mm256_castsi256_si128(packed));
   if (m8 & 0xf0)
      _mm_storel_epi64((__m128i *)(p + stride), _mm256_extracti128_si256(packed, 1));
}

/* The depth function as three lane masks: GL's functions are NEVER + a
 * set of {less, equal, greater} (bit 0 less, bit 1 equal, bit 2 greater),
 * the pass mask is the union of the chosen relations. */
struct depth_fn {
   __m256i lt, eq, gt;
};

static ALWAYS_INLINE struct depth_fn depth_fn(enum r_func f)
{
   return (struct depth_fn){ _mm256_set1_epi32(f & 1 ? -1 : 0), _mm256_set1_epi32(f & 2 ? -1 : 0),
                             _mm256_set1_epi32(f & 4 ? -1 : 0) };
}

/* compare(func, zv, zb) of r_frag.c; both operands below 2^24 */
static ALWAYS_INLINE __m256i depth_pass(const struct depth_fn *fn, __m256i zv, __m256i zb)
{
   const __m256i lt = _mm256_cmpgt_epi32(zb, zv), gt = _mm256_cmpgt_epi32(zv, zb);
   const __m256i eq = _mm256_cmpeq_epi32(zv, zb);
   return _mm256_or_si256(_mm256_or_si256(_mm256_and_si256(lt, fn->lt), _mm256_and_si256(eq, fn->eq)),
                          _mm256_and_si256(gt, fn->gt));
}

/* r_frag.c mul_u8 on 16-bit lanes: t = a*b, (t + (t >> 8) + 128) >> 8
 * (t <= 65025, the sum below 2^16) */
static ALWAYS_INLINE __m256i mul_u8x16(__m256i a, __m256i b)
{
   const __m256i t = _mm256_mullo_epi16(a, b);
   return _mm256_srli_epi16(
      _mm256_add_epi16(_mm256_add_epi16(t, _mm256_srli_epi16(t, 8)), _mm256_set1_epi16(0x80)), 8);
}

/* SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ADD on 8 RGBA8 pixels (r_frag.c
 * blend_channel): s*a + d*(255 - a), each a normalized multiply, summed
 * with saturation. */
static ALWAYS_INLINE __m256i blend_alpha(__m256i src, __m256i dst)
{
   const __m256i zero = _mm256_setzero_si256();
   const __m256i amask = _mm256_setr_epi8(6, 7, 6, 7, 6, 7, 6, 7, 14, 15, 14, 15, 14, 15, 14, 15,
                                          6, 7, 6, 7, 6, 7, 6, 7, 14, 15, 14, 15, 14, 15, 14, 15);
   const __m256i c255 = _mm256_set1_epi16(255);
   __m256i out[2];
   for (int h = 0; h < 2; h++) {
      const __m256i s = h ? _mm256_unpackhi_epi8(src, zero) : _mm256_unpacklo_epi8(src, zero);
      const __m256i d = h ? _mm256_unpackhi_epi8(dst, zero) : _mm256_unpacklo_epi8(dst, zero);
      const __m256i a = _mm256_shuffle_epi8(s, amask);
      out[h] = _mm256_adds_epu16(mul_u8x16(s, a), mul_u8x16(d, _mm256_sub_epi16(c255, a)));
   }
   return _mm256_packus_epi16(out[0], out[1]);   /* sums up to 510: saturated */
}

static inline unsigned mul_u8(unsigned a, unsigned b)
{
   const unsigned t = a * b;
   return (t + (t >> 8) + 0x80u) >> 8;
}

static inline bool compare_u32(enum r_func f, uint32_t a, uint32_t b)
{
   return ((f & 1) && a < b) || ((f & 2) && a == b) || ((f & 4) && a > b);
}

/* The lanes of a half one at a time (a block reaching past the buffer's
 * right edge): the same integer operations as the vector path. */
static void finish_lanes(const struct r_state *rs, int x, int y, unsigned m8, const uint32_t zv[8],
                         const uint32_t src[8], enum zfmt zf, bool zwrite, enum blend bl)
{
   for (unsigned m = m8; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      const size_t idx = (size_t)(y + (i >> 2)) * (size_t)rs->width + (size_t)(x + (i & 3));
      if (zf == ZF_24) {
         uint32_t *zb = (uint32_t *)rs->zs + idx;
         if (!compare_u32(rs->depth_func, zv[i], *zb & 0xffffffu))
            continue;
         if (zwrite)
            *zb = (*zb & 0xff000000u) | zv[i];
      } else if (zf == ZF_16) {
         uint16_t *zb = (uint16_t *)rs->zs + idx;
         if (!compare_u32(rs->depth_func, zv[i], *zb))
            continue;
         if (zwrite)
            *zb = (uint16_t)zv[i];
      }
      uint8_t *dst = rs->color + 4 * idx;
      uint8_t s[4];
      memcpy(s, &src[i], 4);
      if (bl == BL_ALPHA) {
         const unsigned a = s[3];
         uint8_t d[4] = { dst[0], dst[1], dst[2], rs->dst_alpha_one ? 255 : dst[3] };
         for (int c = 0; c < 4; c++) {
            const unsigned v = mul_u8(s[c], a) + mul_u8(d[c], 255u - a);
            dst[c] = (uint8_t)(v > 255u ? 255u : v);
         }
      } else {
         memcpy(dst, s, 4);
      }
   }
}

/* The kernel template: the constant arguments choose the variant.
 *   smooth  the colour is interpolated (else the provoking vertex's)
 *   zf      the depth test's buffer (ZF_NONE: no depth test)
 *   zwrite  depth writes
 *   bl      the blend (BL_ALPHA: SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ADD) */
static ALWAYS_INLINE void tri_blocks(const struct r_state *rs, const struct r_tri_setup *ts,
                                     const struct r_tri_cover *cv, const bool smooth,
                                     const enum zfmt zf, const bool zwrite, const enum blend bl)
{
   const int width = rs->width;
   const size_t stride = (size_t)width;
   const __m256i lx = _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3);
   const __m256i ly = _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1);
   const __m256 flx = _mm256_cvtepi32_ps(lx), fly = _mm256_cvtepi32_ps(ly);
   const __m256i minus1 = _mm256_set1_epi32(-1);

   /* the edge functions' offsets of the lanes of the two halves */
   __m256i eoff[3][2];
   for (int e = 0; e < 3; e++) {
      eoff[e][0] = _mm256_add_epi32(_mm256_mullo_epi32(lx, _mm256_set1_epi32(cv->dx[e])),
                                    _mm256_mullo_epi32(ly, _mm256_set1_epi32(cv->dy[e])));
      eoff[e][1] = _mm256_add_epi32(eoff[e][0], _mm256_set1_epi32(2 * cv->dy[e]));
   }

   /* a flat colour is the same bytes at every pixel */
   uint32_t flat_rgba = 0;
   if (!smooth) {
      const float *c = ts->flat[R_FS_COLOR0];
      flat_rgba = (uint32_t)r_float_to_unorm8(c[0]) | (uint32_t)r_float_to_unorm8(c[1]) << 8 |
                  (uint32_t)r_float_to_unorm8(c[2]) << 16 | (uint32_t)r_float_to_unorm8(c[3]) << 24;
   }
   const struct depth_fn fn = depth_fn(rs->depth_func);
   const __m256i dst_or = _mm256_set1_epi32(rs->dst_alpha_one ? (int)0xff000000u : 0);
   uint64_t fragments = 0;

   const int32_t bx0 = cv->x0 & ~3, by0 = cv->y0 & ~3;
   int32_t rowc[3];
   for (int e = 0; e < 3; e++)
      rowc[e] = cv->c[e] + (bx0 - cv->ox) * cv->dx[e] + (by0 - cv->oy) * cv->dy[e];

   for (int32_t by = by0; by <= cv->y1; by += 4) {
      /* the box's rows in this block row, one nibble each */
      unsigned rows = 0;
      for (int j = 0; j < 4; j++)
         if (by + j >= cv->y0 && by + j <= cv->y1)
            rows |= 0xfu << (4 * j);
      int32_t c[3] = { rowc[0], rowc[1], rowc[2] };
      for (int32_t bx = bx0; bx <= cv->x1; bx += 4) {
         /* coverage */
         unsigned mask = 0;
         for (int h = 0; h < 2; h++) {
            __m256i in = minus1;
            for (int e = 0; e < 3; e++) {
               const __m256i v = _mm256_add_epi32(_mm256_set1_epi32(c[e]), eoff[e][h]);
               in = _mm256_and_si256(in, _mm256_cmpgt_epi32(v, minus1));
            }
            mask |= (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(in)) << (8 * h);
         }
         for (int e = 0; e < 3; e++)
            c[e] += 4 * cv->dx[e];
         /* cut to the box's columns and rows */
         const int lo = cv->x0 - bx > 0 ? cv->x0 - bx : 0;
         const int hi = cv->x1 - bx + 1 < 4 ? cv->x1 - bx + 1 : 4;
         const unsigned cols = (0xfu >> (4 - hi)) & (0xfu << lo) & 0xfu;
         mask &= rows & (cols * 0x1111u);
         if (!mask)
            continue;
         fragments += (unsigned)__builtin_popcount(mask);
         const bool edge = bx + 4 > width;

         for (int h = 0; h < 2; h++) {
            const unsigned m8 = (mask >> (8 * h)) & 0xffu;
            if (!m8)
               continue;
            const int y = by + 2 * h;
            const __m256 fx = _mm256_add_ps(_mm256_set1_ps((float)bx), flx);
            const __m256 fy = _mm256_add_ps(_mm256_set1_ps((float)y), fly);

            /* the fragment colour */
            __m256i src;
            if (smooth) {
               const __m256 rw = _mm256_div_ps(_mm256_set1_ps(1.0f), eval8(&ts->w, fx, fy));
               const struct r_attr_plane *ap = ts->ap[R_FS_COLOR0];
               const __m256i r = unorm8(_mm256_mul_ps(eval8(&ap[0], fx, fy), rw));
               const __m256i g = unorm8(_mm256_mul_ps(eval8(&ap[1], fx, fy), rw));
               const __m256i b = unorm8(_mm256_mul_ps(eval8(&ap[2], fx, fy), rw));
               const __m256i a = unorm8(_mm256_mul_ps(eval8(&ap[3], fx, fy), rw));
               src = _mm256_or_si256(_mm256_or_si256(r, _mm256_slli_epi32(g, 8)),
                                     _mm256_or_si256(_mm256_slli_epi32(b, 16),
                                                     _mm256_slli_epi32(a, 24)));
            } else {
               src = _mm256_set1_epi32((int)flat_rgba);
            }

            /* the depth value (lp_bld_interp.c: interpolated z + offset) */
            __m256i zv = _mm256_setzero_si256();
            if (zf != ZF_NONE) {
               const __m256 z = _mm256_add_ps(eval8(&ts->z, fx, fy), _mm256_set1_ps(ts->zoffset));
               zv = depth_unorm(z, zf == ZF_24 ? 16777215.0f : 65535.0f);
            }

            if (edge) {
               uint32_t zl[8], sl[8];
               _mm256_storeu_si256((__m256i *)zl, zv);
               _mm256_storeu_si256((__m256i *)sl, src);
               finish_lanes(rs, bx, y, m8, zl, sl, zf, zwrite, bl);
               continue;
            }

            const size_t idx = (size_t)y * stride + (size_t)bx;
            __m256i pass = lane_mask(m8);
            if (zf == ZF_24) {
               uint32_t *zp = (uint32_t *)rs->zs + idx;
               const __m256i zb = load_rows32(zp, stride, m8);
               pass = _mm256_and_si256(
                  pass, depth_pass(&fn, zv, _mm256_and_si256(zb, _mm256_set1_epi32(0xffffff))));
               if (zwrite) {
                  const __m256i nz = _mm256_or_si256(
                     _mm256_and_si256(zb, _mm256_set1_epi32((int)0xff000000u)), zv);
                  store_rows32(zp, stride, m8, _mm256_blendv_epi8(zb, nz, pass));
               }
            } else if (zf == ZF_16) {
               uint16_t *zp = (uint16_t *)rs->zs + idx;
               const __m256i zb = load_rows16(zp, stride, m8);
               pass = _mm256_and_si256(pass, depth_pass(&fn, zv, zb));
               if (zwrite)
                  store_rows16(zp, stride, m8, _mm256_blendv_epi8(zb, zv, pass));
            }
            const unsigned pm = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(pass));
            if (!pm)
               continue;

            uint32_t *cp = (uint32_t *)rs->color + idx;
            if (bl == BL_NONE && pm == 0xffu) {
               store_rows32(cp, stride, pm, src);
               continue;
            }
            const __m256i dst = load_rows32(cp, stride, pm);
            __m256i out = src;
            if (bl == BL_ALPHA)
               out = blend_alpha(src, _mm256_or_si256(dst, dst_or));
            store_rows32(cp, stride, pm, _mm256_blendv_epi8(dst, out, pass));
         }
      }
      for (int e = 0; e < 3; e++)
         rowc[e] += 4 * cv->dy[e];
   }
   if (rs->stats)
      rs->stats->fragments += fragments;
}

#define TRI_KERNEL(name, smooth, zf, zwrite, bl)                                           \
   static void name(const struct r_state *rs, const struct r_tri_setup *ts,               \
                    const struct r_tri_cover *cv)                                          \
   {                                                                                       \
      tri_blocks(rs, ts, cv, smooth, zf, zwrite, bl);                                      \
   }

#define TRI_KERNELS_BLEND(prefix, bl)                                                      \
   TRI_KERNEL(prefix##_flat_nz, false, ZF_NONE, false, bl)                                 \
   TRI_KERNEL(prefix##_flat_z16, false, ZF_16, false, bl)                                  \
   TRI_KERNEL(prefix##_flat_z16w, false, ZF_16, true, bl)                                  \
   TRI_KERNEL(prefix##_flat_z24, false, ZF_24, false, bl)                                  \
   TRI_KERNEL(prefix##_flat_z24w, false, ZF_24, true, bl)                                  \
   TRI_KERNEL(prefix##_smooth_nz, true, ZF_NONE, false, bl)                                \
   TRI_KERNEL(prefix##_smooth_z16, true, ZF_16, false, bl)                                 \
   TRI_KERNEL(prefix##_smooth_z16w, true, ZF_16, true, bl)                                 \
   TRI_KERNEL(prefix##_smooth_z24, true, ZF_24, false, bl)                                 \
   TRI_KERNEL(prefix##_smooth_z24w, true, ZF_24, true, bl)                                 \
   /* [smooth][zfmt][zwrite] */                                                            \
   static const r_tri_kernel prefix##_table[2][3][2] = {                                   \
      { { prefix##_flat_nz, prefix##_flat_nz },                                            \
        { prefix##_flat_z16, prefix##_flat_z16w },                                         \
        { prefix##_flat_z24, prefix##_flat_z24w } },                                       \
      { { prefix##_smooth_nz, prefix##_smooth_nz },                                        \
        { prefix##_smooth_z16, prefix##_smooth_z16w },                                     \
        { prefix##_smooth_z24, prefix##_smooth_z24w } },                                   \
   };

TRI_KERNELS_BLEND(opaque, BL_NONE)
TRI_KERNELS_BLEND(alpha, BL_ALPHA)

r_tri_kernel r_block_choose_tri(const struct r_state *rs, bool flat_color)
{
   /* the fragment program: the colour input alone, no texture, colour
    * sum, fog, GL_PHONG_WIN, pixel rectangle, coverage lowering or
    * stipple */
   if (rs->fs_inputs != 1u << R_FS_COLOR0 || rs->tex_units || rs->color_sum ||
       rs->fog_mode != R_FOG_NONE || rs->phong || rs->pix || rs->aa != R_AA_NONE ||
       rs->stipple || !rs->color)
      return NULL;
   /* the fragment operations: depth test and store, or with blending
    * SRC_ALPHA / ONE_MINUS_SRC_ALPHA (r_fragment_ops' order: no alpha
    * test, stencil test, logic op; every channel written) */
   enum blend bl = BL_NONE;
   if (rs->full_ops) {
      if (rs->alpha_test || rs->stencil_test || rs->logic_op || rs->color_mask != 0xfu ||
          !rs->blend || rs->blend_eq != R_BLEND_ADD || rs->blend_src != R_BF_SRC_ALPHA ||
          rs->blend_dst != R_BF_INV_SRC_ALPHA)
         return NULL;
      bl = BL_ALPHA;
   }
   enum zfmt zf = ZF_NONE;
   if (rs->depth_test) {
      switch (rs->zs_format) {
      case R_ZS_Z16:   zf = ZF_16; break;
      case R_ZS_Z24X8:
      case R_ZS_Z24S8: zf = ZF_24; break;
      default:         return NULL;
      }
   }
   const r_tri_kernel(*t)[3][2] = bl == BL_ALPHA ? alpha_table : opaque_table;
   return t[!flat_color][zf][rs->depth_write];
}
