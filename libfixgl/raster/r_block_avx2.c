/*
 * The block kernels of untextured triangles, AVX2 + FMA (r_kernel.h): the
 * colour input alone, smooth or flat, through the triangle template
 * (r_block_tri.h) and the shared operations (r_block_avx2.h).
 *
 * The walk: a triangle's box in 4x4 blocks aligned to the buffer, as the
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
 * covers is decided once, by r_block_choose_tri; the loops test no state:
 * the kernel's variant is fixed at compile time (the constant arguments
 * of tri_blocks), the depth function is three masks.
 *
 * Memory: a row of a half is read and written only when one of its
 * pixels is covered (covered pixels lie inside the buffer), and a block
 * reaching past the right edge of the buffer takes the lanes one at a
 * time (finish_lanes), so no access leaves the buffer.
 */
#include "r_block_avx2.h"

enum { FLAT = 0, SMOOTH = 1 };

struct block_stage {
   uint32_t flat_rgba;   /* a flat colour is the same bytes at every pixel */
};

static ALWAYS_INLINE void block_stage_prepare(const struct r_state *rs, const struct r_tri_setup *ts,
                                              int variant, struct block_stage *st)
{
   (void)rs;
   st->flat_rgba = 0;
   if (variant == FLAT) {
      const float *c = ts->flat[R_FS_COLOR0];
      st->flat_rgba = (uint32_t)r_float_to_unorm8(c[0]) | (uint32_t)r_float_to_unorm8(c[1]) << 8 |
                      (uint32_t)r_float_to_unorm8(c[2]) << 16 |
                      (uint32_t)r_float_to_unorm8(c[3]) << 24;
   }
}

static ALWAYS_INLINE __m256i block_stage_shade(const struct r_state *rs, const struct r_tri_setup *ts,
                                               const struct block_stage *st, int variant,
                                               __m256 fx, __m256 fy, int x, int y, unsigned m8,
                                               __m256i *live)
{
   (void)rs; (void)x; (void)y; (void)m8; (void)live;
   if (variant == FLAT)
      return _mm256_set1_epi32((int)st->flat_rgba);
   const __m256 rw = _mm256_div_ps(_mm256_set1_ps(1.0f), eval8(&ts->w, fx, fy));
   const struct r_attr_plane *ap = ts->ap[R_FS_COLOR0];
   return pack_rgba8(_mm256_mul_ps(eval8(&ap[0], fx, fy), rw),
                     _mm256_mul_ps(eval8(&ap[1], fx, fy), rw),
                     _mm256_mul_ps(eval8(&ap[2], fx, fy), rw),
                     _mm256_mul_ps(eval8(&ap[3], fx, fy), rw));
}

#include "r_block_tri.h"

#define TRI_KERNEL(name, smooth, zf, zwrite, bl)                                           \
   static void name(const struct r_state *rs, const struct r_tri_setup *ts,               \
                    const struct r_tri_cover *cv)                                          \
   {                                                                                       \
      tri_blocks(rs, ts, cv, smooth, zf, zwrite, bl);                                      \
   }

#define TRI_KERNELS_BLEND(prefix, bl)                                                      \
   TRI_KERNEL(prefix##_flat_nz, FLAT, ZF_NONE, false, bl)                                 \
   TRI_KERNEL(prefix##_flat_z16, FLAT, ZF_16, false, bl)                                  \
   TRI_KERNEL(prefix##_flat_z16w, FLAT, ZF_16, true, bl)                                  \
   TRI_KERNEL(prefix##_flat_z24, FLAT, ZF_24, false, bl)                                  \
   TRI_KERNEL(prefix##_flat_z24w, FLAT, ZF_24, true, bl)                                  \
   TRI_KERNEL(prefix##_smooth_nz, SMOOTH, ZF_NONE, false, bl)                                \
   TRI_KERNEL(prefix##_smooth_z16, SMOOTH, ZF_16, false, bl)                                 \
   TRI_KERNEL(prefix##_smooth_z16w, SMOOTH, ZF_16, true, bl)                                 \
   TRI_KERNEL(prefix##_smooth_z24, SMOOTH, ZF_24, false, bl)                                 \
   TRI_KERNEL(prefix##_smooth_z24w, SMOOTH, ZF_24, true, bl)                                 \
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
   if (rs->tex_units)
      return r_block_choose_tri_tex(rs, flat_color);
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
