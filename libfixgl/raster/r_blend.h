/*
 * r_blend.h: the compares and the colour and stencil operations of the
 * fragment stage on unorm8 values,
 * shared by the reference (r_frag.c r_fragment_ops) and the lanes the
 * block kernels finish one at a time (r_block_avx2.h), so both are the
 * same code.
 */
#ifndef FGL_R_BLEND_H
#define FGL_R_BLEND_H

#include "r_state.h"

/* lp_build_cmp(func, a, b): on unsigned integers (depth, stencil, the
 * unorm8 alpha test) and on floats (the alpha test of formats that are not
 * rgba8 variants; C's ordered comparisons, the caller adds lp_build_cmp's
 * unordered treatment of a NaN reference). */
#define R_COMPARE(func, a, b)                      \
   switch (func) {                                 \
   case R_NEVER:    return false;                  \
   case R_LESS:     return (a) < (b);              \
   case R_EQUAL:    return (a) == (b);             \
   case R_LEQUAL:   return (a) <= (b);             \
   case R_GREATER:  return (a) > (b);              \
   case R_NOTEQUAL: return (a) != (b);             \
   case R_GEQUAL:   return (a) >= (b);             \
   case R_ALWAYS:                                  \
   default:         return true;                   \
   }

static inline bool compare(enum r_func func, uint32_t a, uint32_t b)
{
   R_COMPARE(func, a, b)
}

/* gallivm's lp_build_mul for unorm8 [S: gallivm/lp_bld_arit.c:lp_build_mul_norm]:
 * t = a*b, (t + (t >> 8) + 128) >> 8.  This is round(a*b/255) except for
 * 24 of the 65536 pairs, where it is one less (152 * 229 gives 136, not
 * 137; fragment/blend_mul_exhaustive). */
static inline unsigned mul_u8(unsigned a, unsigned b)
{
   const unsigned t = a * b;
   return (t + (t >> 8) + 0x80u) >> 8;
}

/* The blend factor for channel c [S: llvmpipe/lp_bld_blend_aos.c:
 * lp_build_blend_factor_unswizzled, lp_build_blend_factor_swizzle]: the
 * *_ALPHA factors broadcast alpha; for the alpha channel, SRC_ALPHA_SATURATE
 * is ONE; for rgb it is min(src.a, 1 - dst.a). */
static inline unsigned blend_factor(const struct r_state *rs, enum r_blend_factor f, int c,
                             const uint8_t src[4], const uint8_t dst[4])
{
   switch (f) {
   case R_BF_ZERO:            return 0;
   case R_BF_ONE:             return 255;
   case R_BF_SRC_COLOR:       return src[c];
   case R_BF_INV_SRC_COLOR:   return 255u - src[c];
   case R_BF_SRC_ALPHA:       return src[3];
   case R_BF_INV_SRC_ALPHA:   return 255u - src[3];
   case R_BF_DST_COLOR:       return dst[c];
   case R_BF_INV_DST_COLOR:   return 255u - dst[c];
   case R_BF_DST_ALPHA:       return dst[3];
   case R_BF_INV_DST_ALPHA:   return 255u - dst[3];
   case R_BF_SRC_ALPHA_SATURATE: {
      if (c == 3)
         return 255;
      const unsigned inv_da = 255u - dst[3];
      return src[3] < inv_da ? src[3] : inv_da;
   }
   case R_BF_CONST_COLOR:     return rs->blend->blend_color[c];
   case R_BF_INV_CONST_COLOR: return 255u - rs->blend->blend_color[c];
   case R_BF_CONST_ALPHA:     return rs->blend->blend_color[3];
   case R_BF_INV_CONST_ALPHA: return 255u - rs->blend->blend_color[3];
   default:                   return 0;
   }
}

/* [S: llvmpipe/lp_bld_blend.c:lp_build_blend, lp_build_blend_func] on
 * unorm8: each term is a normalized multiply, then a saturating add or
 * subtract, or an unsigned min/max (whose factors the state tracker sets
 * to ONE, st_atom_blend.c).  The lerp shortcut needs equal rgb and alpha
 * factor pairs with complementary src/dst factors, which GL 1.x cannot
 * produce (src == dst then). */
static inline uint8_t blend_channel(const struct r_state *rs, int c,
                             const uint8_t src[4], const uint8_t dst[4])
{
   /* separate alpha: lp_build_blend_aos blends rgb and alpha apart with
    * the same per-channel arithmetic (no lerp: not_alpha_dependent is
    * false) */
   const struct r_blend_state *b = rs->blend;
   const bool a = c == 3 && b->separate_alpha;
   const enum r_blend_factor fs = a ? b->blend_src_a : b->blend_src;
   const enum r_blend_factor fd = a ? b->blend_dst_a : b->blend_dst;
   const unsigned s = mul_u8(src[c], blend_factor(rs, fs, c, src, dst));
   const unsigned d = mul_u8(dst[c], blend_factor(rs, fd, c, src, dst));
   switch (a ? b->blend_eq_a : b->blend_eq) {
   case R_BLEND_SUBTRACT:         return (uint8_t)(s > d ? s - d : 0);
   case R_BLEND_REVERSE_SUBTRACT: return (uint8_t)(d > s ? d - s : 0);
   case R_BLEND_MIN:              return (uint8_t)(s < d ? s : d);
   case R_BLEND_MAX:              return (uint8_t)(s > d ? s : d);
   case R_BLEND_ADD:
   default:                       return (uint8_t)(s + d > 255u ? 255u : s + d);
   }
}

/* [S: gallivm/lp_bld_logicop.c:lp_build_logicop], indexed by the GL op
 * minus GL_CLEAR, on whole words: a channel of n bits is the low n bits
 * of the result (logic_op for 8-bit channels, the wide targets' 16-bit
 * ones in r_frag.c). */
static inline unsigned r_logic_op_bits(unsigned mode, unsigned s, unsigned d)
{
   switch (mode) {
   case 0x0: return 0;          /* CLEAR */
   case 0x1: return s & d;      /* AND */
   case 0x2: return s & ~d;     /* AND_REVERSE */
   case 0x3: return s;          /* COPY */
   case 0x4: return ~s & d;     /* AND_INVERTED */
   case 0x5: return d;          /* NOOP */
   case 0x6: return s ^ d;      /* XOR */
   case 0x7: return s | d;      /* OR */
   case 0x8: return ~(s | d);   /* NOR */
   case 0x9: return ~(s ^ d);   /* EQUIV */
   case 0xa: return ~d;         /* INVERT */
   case 0xb: return s | ~d;     /* OR_REVERSE */
   case 0xc: return ~s;         /* COPY_INVERTED */
   case 0xd: return ~s | d;     /* OR_INVERTED */
   case 0xe: return ~(s & d);   /* NAND */
   case 0xf:
   default:  return ~0u;        /* SET */
   }
}

static inline uint8_t logic_op(unsigned mode, uint8_t s, uint8_t d)
{
   return (uint8_t)r_logic_op_bits(mode, s, d);
}

/* [S: llvmpipe/lp_bld_depth.c:lp_build_stencil_op_single] INCR/DECR
 * saturate at 0xff/0, the WRAP variants and INVERT keep the low 8 bits;
 * REPLACE writes the (clamped, unmasked) reference. */
static inline uint8_t stencil_op(const struct r_state *rs, enum r_stencil_op op, uint8_t s)
{
   switch (op) {
   case R_STENCIL_ZERO:      return 0;
   case R_STENCIL_REPLACE:   return rs->dsa->stencil_ref;
   case R_STENCIL_INCR:      return s == 0xff ? 0xff : (uint8_t)(s + 1);
   case R_STENCIL_DECR:      return s == 0 ? 0 : (uint8_t)(s - 1);
   case R_STENCIL_INCR_WRAP: return (uint8_t)(s + 1);
   case R_STENCIL_DECR_WRAP: return (uint8_t)(s - 1);
   case R_STENCIL_INVERT:    return (uint8_t)~s;
   case R_STENCIL_KEEP:
   default:                  return s;
   }
}

#endif
