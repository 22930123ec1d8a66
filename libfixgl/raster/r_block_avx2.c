/*
 * The block kernels of untextured triangles, AVX2 + FMA (r_kernel.h): the
 * colour input alone, smooth or flat, through the triangle template
 * (r_block_tri.h) and the shared operations (r_block_avx2.h).
 *
 * The walk: a triangle's box in 4x4 blocks aligned to the buffer, as the
 * oracle's rasterizer walks it (lp_rast_tri_tmp.h; ORACLE-NOTES.md
 * "Rasterization: snapping, fill rule, edge functions"): per block, the three
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
 *    multiply (r_blend.h mul_u8) and a saturating add.
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

/* FLAT, SMOOTH: the colour input alone; EXTRA: with the colour sum or fog
 * (either flat or smooth inputs, one out-of-line stage per half) */
enum { FLAT = 0, SMOOTH = 1, EXTRA = 2 };

/* The colour, the colour sum and fog of 8 lanes (shade_pixel's inputs,
 * r_frag.c fragment_shader), packed.  Out of line: the kernels of every
 * fragment-operation variant share it; the state it reads is per
 * triangle. */
static __attribute__((noinline)) __m256i extra_half(const struct r_state *rs,
                                                    const struct r_tri_setup *ts, __m256 fx,
                                                    __m256 fy)
{
   const __m256 rw = ts->need_w ? _mm256_div_ps(_mm256_set1_ps(1.0f), eval8(&ts->w, fx, fy))
                                : _mm256_setzero_ps();
   __m256 out[4];
   for (int c = 0; c < 4; c++)
      out[c] = input8(ts, R_FS_COLOR0, c, fx, fy, rw);
   color_sum_fog8(rs, ts, fx, fy, rw, out);
   return pack_rgba8(out[0], out[1], out[2], out[3]);
}

struct block_stage {
   uint32_t flat_rgba;   /* a flat colour is the same bytes at every pixel */
   __m256 wx, cx[4];     /* SMOOTH: the block's x terms of w and the colour */
   struct vplane w, c[4];   /* SMOOTH: the planes of w and the colour, broadcast */
};

static ALWAYS_INLINE void block_stage_prepare(const struct r_state *rs, const struct r_tri_setup *ts,
                                              int variant, struct block_stage *st)
{
   (void)rs;
   st->flat_rgba = 0;
   if (variant == SMOOTH) {
      st->w = vplane_of(&ts->w);
      for (int c = 0; c < 4; c++)
         st->c[c] = vplane_of(&ts->ap[R_FS_COLOR0][c]);
   }
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
   if (variant == EXTRA)
      return extra_half(rs, ts, fx, fy);
   const __m256 rw = _mm256_div_ps(_mm256_set1_ps(1.0f), veval8_y(&st->w, st->wx, fy));
   return pack_rgba8(_mm256_mul_ps(veval8_y(&st->c[0], st->cx[0], fy), rw),
                     _mm256_mul_ps(veval8_y(&st->c[1], st->cx[1], fy), rw),
                     _mm256_mul_ps(veval8_y(&st->c[2], st->cx[2], fy), rw),
                     _mm256_mul_ps(veval8_y(&st->c[3], st->cx[3], fy), rw));
}

/* SMOOTH: the x terms both halves of the block share */
static ALWAYS_INLINE void block_stage_block(const struct r_state *rs, const struct r_tri_setup *ts,
                                            struct block_stage *st, int variant, __m256 fx)
{
   (void)rs; (void)ts;
   if (variant != SMOOTH)
      return;
   st->wx = veval8_x(&st->w, fx);
   for (int c = 0; c < 4; c++)
      st->cx[c] = veval8_x(&st->c[c], fx);
}

/* the alpha test's operand: the alpha the colour above converts */
static ALWAYS_INLINE __m256 block_stage_alpha(const struct r_state *rs, const struct r_tri_setup *ts,
                                              const struct block_stage *st, int variant,
                                              __m256 fx, __m256 fy)
{
   (void)rs; (void)st;
   if (variant == FLAT)
      return _mm256_set1_ps(ts->flat[R_FS_COLOR0][3]);
   if (variant == EXTRA) {
      /* the colour sum and fog leave alpha alone */
      const __m256 rw = ts->need_w ? _mm256_div_ps(_mm256_set1_ps(1.0f), eval8(&ts->w, fx, fy))
                                   : _mm256_setzero_ps();
      return input8(ts, R_FS_COLOR0, 3, fx, fy, rw);
   }
   const __m256 rw = _mm256_div_ps(_mm256_set1_ps(1.0f), eval8(&ts->w, fx, fy));
   return _mm256_mul_ps(eval8(&ts->ap[R_FS_COLOR0][3], fx, fy), rw);
}

#define BLOCK_STAGE_HAS_ALPHA 1
#define BLOCK_STAGE_PER_BLOCK 1
#define BLOCK_STAGE_EARLY_Z 1
#include "r_block_tri.h"

#define TRI_KERNEL(name, smooth, zf, bl)                                                   \
   static void name(const struct r_state *rs, const struct r_tri_setup *ts,               \
                    const struct r_tri_cover *cv)                                          \
   {                                                                                       \
      tri_blocks(rs, ts, cv, smooth, zf, bl);                                              \
   }

/* (depth writes or not: the same kernel, r_block_tri.h) */
#define TRI_KERNELS_SHADE(prefix, var, bl)                                                 \
   TRI_KERNEL(prefix##_nz, var, ZF_NONE, bl)                                               \
   TRI_KERNEL(prefix##_z16, var, ZF_16, bl)                                                \
   TRI_KERNEL(prefix##_z24, var, ZF_24, bl)                                                \
   TRI_KERNEL(prefix##_z24s, var, ZF_24S, bl)                                              \
   TRI_KERNEL(prefix##_s, var, ZF_S, bl)                                                   \
   TRI_KERNEL(prefix##_z24l, var, ZF_24_LESS, bl)                                          \
   TRI_KERNEL(prefix##_z24le, var, ZF_24_LEQUAL, bl)

#define TRI_KERNELS_ROW(prefix)                                                            \
   { { prefix##_nz, prefix##_nz }, { prefix##_z16, prefix##_z16 },                          \
     { prefix##_z24, prefix##_z24 }, { prefix##_z24s, prefix##_z24s },                      \
     { prefix##_s, prefix##_s }, { prefix##_z24l, prefix##_z24l },                          \
     { prefix##_z24le, prefix##_z24le } }

/* [FLAT, SMOOTH, EXTRA][zfmt][zwrite] */
#define TRI_KERNELS_BLEND(prefix, bl)                                                      \
   TRI_KERNELS_SHADE(prefix##_flat, FLAT, bl)                                              \
   TRI_KERNELS_SHADE(prefix##_smooth, SMOOTH, bl)                                          \
   TRI_KERNELS_SHADE(prefix##_extra, EXTRA, bl)                                            \
   static const r_tri_kernel prefix##_table[3][7][2] = {                                   \
      TRI_KERNELS_ROW(prefix##_flat), TRI_KERNELS_ROW(prefix##_smooth),                    \
      TRI_KERNELS_ROW(prefix##_extra),                                                     \
   };

TRI_KERNELS_BLEND(opaque, BL_NONE)
TRI_KERNELS_BLEND(alpha, BL_ALPHA)
TRI_KERNELS_BLEND(blend, BL_BLEND)
TRI_KERNELS_BLEND(logic, BL_LOGIC)
TRI_KERNELS_BLEND(blend_at, BL_BLEND_AT)
TRI_KERNELS_BLEND(logic_at, BL_LOGIC_AT)

/* [enum blend] */
static const r_tri_kernel(*const tables[])[7][2] = {
   opaque_table, alpha_table, blend_table, logic_table, blend_at_table, logic_at_table,
};

r_tri_kernel r_block_choose_tri(const struct r_state *rs, bool flat_color)
{
   if (rs->fs->tex_units)
      return r_block_choose_tri_tex(rs, flat_color);
   /* the fragment program: the colour input, with the secondary colour
    * under the colour sum and the fog coordinate under fog, and nothing
    * else: no texture, GL_PHONG_WIN, pixel rectangle, coverage lowering
    * or stipple */
   const bool extra = rs->fs->color_sum || rs->fs->fog_mode != R_FOG_NONE;
   const unsigned inputs = 1u << R_FS_COLOR0 | (rs->fs->color_sum ? 1u << R_FS_COLOR1 : 0u) |
                           (rs->fs->fog_mode != R_FOG_NONE ? 1u << R_FS_FOG : 0u);
   if (rs->fs->fs_inputs != inputs || rs->fs->tex_units || rs->fs->phong || rs->pix ||
       rs->fs->aa != R_AA_NONE || rs->rast->stipple || !rs->fb->color)
      return NULL;
   /* the fragment operations (r_fragment_ops): the alpha test on the
    * colour's precision, no stencil test; then the depth test and store,
    * or blending, a logic op and the colour mask in their general form,
    * or SRC_ALPHA / ONE_MINUS_SRC_ALPHA / ADD on every channel (the common
    * case, its own kernels) */
   enum blend bl = BL_NONE;
   if (rs->full_ops) {
      if ((rs->dsa->stencil_test && rs->fb->zs_format != R_ZS_Z24S8) ||
          (rs->dsa->alpha_test && rs->dsa->alpha_test_float))
         return NULL;
      if (rs->blend->logic_op)
         bl = BL_LOGIC;
      else if (!rs->blend->enable)
         bl = rs->blend->color_mask == 0xfu ? BL_NONE : BL_LOGIC;   /* COPY (under the colour mask) */
      else if (!rs->dsa->alpha_test && rs->blend->color_mask == 0xfu && rs->blend->blend_eq == R_BLEND_ADD &&
               rs->blend->blend_src == R_BF_SRC_ALPHA &&
               rs->blend->blend_dst == R_BF_INV_SRC_ALPHA && !rs->blend->separate_alpha)
         bl = BL_ALPHA;
      else
         bl = BL_BLEND;
      if (rs->dsa->alpha_test)
         bl = bl == BL_BLEND ? BL_BLEND_AT : BL_LOGIC_AT;   /* (NONE: as LOGIC's COPY) */
   }
   enum zfmt zf = ZF_NONE;
   if (rs->full_ops && rs->dsa->stencil_test) {
      zf = rs->dsa->depth_test ? ZF_24S : ZF_S;
   } else if (rs->dsa->depth_test) {
      switch (rs->fb->zs_format) {
      case R_ZS_Z16:   zf = ZF_16; break;
      case R_ZS_Z24X8:
      case R_ZS_Z24S8: zf = ZF_24; break;
      default:         return NULL;
      }
      if (zf == ZF_24 && rs->dsa->depth_func == R_LESS)
         zf = ZF_24_LESS;
      else if (zf == ZF_24 && rs->dsa->depth_func == R_LEQUAL)
         zf = ZF_24_LEQUAL;
   }
   return tables[bl][extra ? EXTRA : flat_color ? FLAT : SMOOTH][zf][rs->dsa->depth_write];
}
