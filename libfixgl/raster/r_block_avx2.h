/*
 * r_block_avx2.h: what every AVX2 block kernel shares (r_kernel.h) -- the
 * 8-lane forms of the reference's operations (plane evaluation, unorm
 * conversions, depth compare, blending), the row loads and stores of a
 * 4x2 half, and the scalar finish of a block past the buffer's right edge.
 * Include it only from files compiled with -mavx2 -mfma.
 */
#ifndef FGL_R_BLOCK_AVX2_H
#define FGL_R_BLOCK_AVX2_H

#include "r_kernel.h"
#include "r_blend.h"
#include "math/m_shade_avx2.h"

#include <immintrin.h>
#include <string.h>

/* the depth/stencil buffer and tests: none, Z16 or Z24 (X8 or S8) depth
 * test, or on a Z24S8 buffer the stencil test with (ZF_24S) or without
 * (ZF_S) the depth test; ZF_24_LESS and ZF_24_LEQUAL are ZF_24 with the
 * usual depth functions compiled in (one compare instead of depth_pass) */
enum zfmt { ZF_NONE, ZF_16, ZF_24, ZF_24S, ZF_S, ZF_24_LESS, ZF_24_LEQUAL };
/* the colour operations after the depth test:
 *   BL_NONE   store
 *   BL_ALPHA  SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ADD, every channel written
 *   BL_BLEND  any blend factors and equation, any colour mask (gen_ops)
 *   BL_LOGIC  a logic op (COPY without GL_COLOR_LOGIC_OP), any colour mask
 *   BL_BLEND_AT, BL_LOGIC_AT  the same after an alpha test (of a stage
 *             that defines block_stage_alpha) */
enum blend { BL_NONE, BL_ALPHA, BL_BLEND, BL_LOGIC, BL_BLEND_AT, BL_LOGIC_AT };

#define ALWAYS_INLINE inline __attribute__((always_inline))

/* r_eval_plane in 8 lanes: fma(dady, y, fma(dadx, x, a0)) (ORACLE-NOTES.md
 * "Interpolation") */
/* r_eval_plane's inner term, fma(dadx, x, a0): the same for both halves
 * of a block (their lanes share the columns) */
static ALWAYS_INLINE __m256 eval8_x(const struct r_attr_plane *p, __m256 fx)
{
   return _mm256_fmadd_ps(_mm256_set1_ps(p->dadx), fx, _mm256_set1_ps(p->a0));
}

/* ... and the outer one: eval8(p, fx, fy) == eval8_y(p, eval8_x(p, fx), fy) */
static ALWAYS_INLINE __m256 eval8_y(const struct r_attr_plane *p, __m256 inner, __m256 fy)
{
   return _mm256_fmadd_ps(_mm256_set1_ps(p->dady), fy, inner);
}

static ALWAYS_INLINE __m256 eval8(const struct r_attr_plane *p, __m256 fx, __m256 fy)
{
   return _mm256_fmadd_ps(_mm256_set1_ps(p->dady), fy,
                          _mm256_fmadd_ps(_mm256_set1_ps(p->dadx), fx, _mm256_set1_ps(p->a0)));
}

/* A plane's coefficients broadcast once per primitive (a stage's or the
 * walk's constants), for the same two fmas as eval8_x and eval8_y without
 * a broadcast per block or half. */
struct vplane {
   __m256 dadx, a0, dady;
};

static ALWAYS_INLINE struct vplane vplane_of(const struct r_attr_plane *p)
{
   return (struct vplane){ _mm256_set1_ps(p->dadx), _mm256_set1_ps(p->a0), _mm256_set1_ps(p->dady) };
}

/* eval8_x and eval8_y of the broadcast plane: the same operations */
static ALWAYS_INLINE __m256 veval8_x(const struct vplane *p, __m256 fx)
{
   return _mm256_fmadd_ps(p->dadx, fx, p->a0);
}

static ALWAYS_INLINE __m256 veval8_y(const struct vplane *p, __m256 inner, __m256 fy)
{
   return _mm256_fmadd_ps(p->dady, fy, inner);
}

/* ---- coverage (r_kernel.h r_tri_cover) ----
 * Lane i of half h of a 4x4 block is pixel (x + (i & 3), y + 2h + (i >> 2)),
 * so its edge value is the block's top-left value plus the lane offset
 * (i & 3) * dx + ((i >> 2) + 2h) * dy. */
static ALWAYS_INLINE void block_cover_offsets(const struct r_tri_cover *cv,
                                              __m256i eoff[R_COVER_EDGES][2])
{
   const __m256i lx = _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3);
   const __m256i ly = _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1);
   for (int e = 0; e < R_COVER_EDGES; e++) {
      eoff[e][0] = _mm256_add_epi32(_mm256_mullo_epi32(lx, _mm256_set1_epi32(cv->dx[e])),
                                    _mm256_mullo_epi32(ly, _mm256_set1_epi32(cv->dy[e])));
      eoff[e][1] = _mm256_add_epi32(eoff[e][0], _mm256_set1_epi32(2 * cv->dy[e]));
   }
}

/* The coverage mask of a 4x4 block, shared by triangles, lines and points:
 * bit 4j + i set when pixel (x + i, y + j) has every edge value >= 0, c[e]
 * the edge values at (x, y) (the edges past r_tri_cover.n are 0 with zero
 * steps: always inside). */
static ALWAYS_INLINE unsigned r_block_cover(const int32_t c[R_COVER_EDGES],
                                            __m256i eoff[R_COVER_EDGES][2])
{
   const __m256i minus1 = _mm256_set1_epi32(-1);
   unsigned mask = 0;
   for (int h = 0; h < 2; h++) {
      __m256i in = minus1;
      for (int e = 0; e < R_COVER_EDGES; e++) {
         const __m256i v = _mm256_add_epi32(_mm256_set1_epi32(c[e]), eoff[e][h]);
         in = _mm256_and_si256(in, _mm256_cmpgt_epi32(v, minus1));
      }
      mask |= (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(in)) << (8 * h);
   }
   return mask;
}

/* floor(a / b), b > 0 */
static ALWAYS_INLINE int64_t block_floor_div(int64_t a, int64_t b)
{
   return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/* The range kmin .. kmax of the blocks k blocks along one block row
 * (from bx0, the row's first) where every edge's extreme value over the
 * block is >= 0: its largest (`inner` false: the block may hold a covered
 * pixel) or its smallest (`inner` true: every pixel of the block is
 * covered).  rowc[e]: the edge values at the row's first block.  An edge's
 * values are linear over the block and fit in 32 bits (r_cover_planes):
 * over the block k blocks along they reach rowc + 4k dx + {max, min}(0,
 * 3 dx) + {max, min}(0, 3 dy).  False when no block qualifies. */
static ALWAYS_INLINE bool block_row_range(const struct r_tri_cover *cv,
                                          const int32_t rowc[R_COVER_EDGES], int32_t bx0,
                                          bool inner, int64_t *kmin_out, int64_t *kmax_out)
{
   int64_t kmax = (cv->x1 - bx0) >> 2;
   int64_t kmin = 0;
   for (int e = 0; e < R_COVER_EDGES; e++) {
      const int64_t dx = cv->dx[e], dy = cv->dy[e];
      const int64_t m = (int64_t)rowc[e] + ((inner ? dx < 0 : dx > 0) ? 3 * dx : 0) +
                        ((inner ? dy < 0 : dy > 0) ? 3 * dy : 0);
      if (dx > 0) {
         /* m + 4k dx >= 0: k >= ceil(-m / 4dx) */
         const int64_t k = -block_floor_div(m, 4 * dx);
         kmin = k > kmin ? k : kmin;
      } else if (dx < 0) {
         /* k <= floor(m / -4dx) */
         const int64_t k = block_floor_div(m, -4 * dx);
         kmax = k < kmax ? k : kmax;
      } else if (m < 0) {
         return false;
      }
   }
   if (kmin > kmax)
      return false;
   *kmin_out = kmin;
   *kmax_out = kmax;
   return true;
}

/* The blocks of one block row that may hold a covered pixel: those at
 * *first .. *last (block x, multiples of 4 from bx0), narrowed from the
 * whole row (of five blocks or more), false when there is none.  A block
 * where some edge's largest value is negative covers no pixel and
 * r_block_cover would give it an empty mask: skipping it changes nothing
 * but the time (a line's or a thin triangle's box is mostly empty).  Only
 * worth its divides on a row of many blocks. */
static ALWAYS_INLINE bool block_row_span(const struct r_tri_cover *cv,
                                         const int32_t rowc[R_COVER_EDGES], int32_t bx0,
                                         int32_t *first, int32_t *last)
{
   int64_t kmin, kmax;
   if (!block_row_range(cv, rowc, bx0, false, &kmin, &kmax))
      return false;
   *first = bx0 + 4 * (int32_t)kmin;
   *last = bx0 + 4 * (int32_t)kmax + 3 < cv->x1 ? bx0 + 4 * (int32_t)kmax + 3 : cv->x1;
   return true;
}

/* The blocks of one block row that lie wholly inside every edge: those
 * at *ifirst .. *ilast (block x, multiples of 4 from bx0), false when
 * there is none: every pixel of such a block is covered and
 * r_block_cover would give 0xffff, so the walk takes that mask without
 * evaluating the edges.  Worth its divides on long rows only. */
static ALWAYS_INLINE bool block_row_inner(const struct r_tri_cover *cv,
                                          const int32_t rowc[R_COVER_EDGES], int32_t bx0,
                                          int32_t *ifirst, int32_t *ilast)
{
   int64_t kmin, kmax;
   if (!block_row_range(cv, rowc, bx0, true, &kmin, &kmax))
      return false;
   *ifirst = bx0 + 4 * (int32_t)kmin;
   *ilast = bx0 + 4 * (int32_t)kmax;
   return true;
}

/* r_float_to_unorm8 in 8 lanes (ORACLE-NOTES.md "Colour conversion"; maxps returns its second operand for NaN:
 * NaN -> 0, as !(c > 0)) */
static ALWAYS_INLINE __m256i unorm8(__m256 c)
{
   c = _mm256_max_ps(c, _mm256_setzero_ps());
   c = _mm256_min_ps(c, _mm256_set1_ps(1.0f));
   return _mm256_cvtps_epi32(_mm256_mul_ps(c, _mm256_set1_ps(255.0f)));
}

/* r_clamp01(z) * scale, RNE (ORACLE-NOTES.md "Depth conversion and polygon
 * offset") */
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

/* compare(func, zv, zb) of r_blend.h; both operands below 2^24 */
static ALWAYS_INLINE __m256i depth_pass(const struct depth_fn *fn, __m256i zv, __m256i zb)
{
   const __m256i lt = _mm256_cmpgt_epi32(zb, zv), gt = _mm256_cmpgt_epi32(zv, zb);
   const __m256i eq = _mm256_cmpeq_epi32(zv, zb);
   return _mm256_or_si256(_mm256_or_si256(_mm256_and_si256(lt, fn->lt), _mm256_and_si256(eq, fn->eq)),
                          _mm256_and_si256(gt, fn->gt));
}

static ALWAYS_INLINE bool zf_z24(enum zfmt zf)
{
   return zf == ZF_24 || zf == ZF_24_LESS || zf == ZF_24_LEQUAL;
}

/* the depth test of the lanes: compare(func, zv, zb) */
static ALWAYS_INLINE __m256i depth_test8(enum zfmt zf, const struct depth_fn *fn, __m256i zv,
                                         __m256i zb)
{
   if (zf == ZF_24_LESS)
      return _mm256_cmpgt_epi32(zb, zv);
   if (zf == ZF_24_LEQUAL)
      return _mm256_xor_si256(_mm256_cmpgt_epi32(zv, zb), _mm256_set1_epi32(-1));
   return depth_pass(fn, zv, zb);
}

/* r_blend.h mul_u8 on 16-bit lanes: t = a*b, (t + (t >> 8) + 128) >> 8
 * (t <= 65025, the sum below 2^16) */
static ALWAYS_INLINE __m256i mul_u8x16(__m256i a, __m256i b)
{
   const __m256i t = _mm256_mullo_epi16(a, b);
   return _mm256_srli_epi16(
      _mm256_add_epi16(_mm256_add_epi16(t, _mm256_srli_epi16(t, 8)), _mm256_set1_epi16(0x80)), 8);
}

/* SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ADD on 8 RGBA8 pixels (ORACLE-NOTES.md
 * "Blending, alpha test, dithering"; r_blend.h
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

/* The stencil test and ops in 8 lanes (r_frag.c stencil_depth_test), the
 * state as constants built once per triangle.  A stencil op is
 *    t = (s & keep) ^ flip;  r = ((min(t + inc, 255) - dec, at least 0) + add) & 0xff
 * KEEP: keep 0xff; ZERO: keep 0; REPLACE: keep 0, add ref; INCR: inc 1;
 * DECR: dec 1; INCR_WRAP: add 1; DECR_WRAP: add 0xff; INVERT: keep and
 * flip 0xff (stencil_op, r_blend.h). */
struct stencil_ops {
   struct depth_fn fn;
   __m256i ref_vm, vm, wm;
   __m256i keep[3], flip[3], inc[3], dec[3], add[3];   /* [fail, zfail, zpass] */
};

static inline void stencil_ops_init(struct stencil_ops *st, const struct r_state *rs)
{
   st->fn = depth_fn(rs->dsa->stencil_func);
   st->ref_vm = _mm256_set1_epi32(rs->dsa->stencil_ref & rs->dsa->stencil_valuemask);
   st->vm = _mm256_set1_epi32(rs->dsa->stencil_valuemask);
   st->wm = _mm256_set1_epi32(rs->dsa->stencil_writemask);
   const enum r_stencil_op ops[3] = { rs->dsa->stencil_fail, rs->dsa->stencil_zfail, rs->dsa->stencil_zpass };
   for (int k = 0; k < 3; k++) {
      int keep = 0xff, flip = 0, inc = 0, dec = 0, add = 0;
      switch (ops[k]) {
      case R_STENCIL_ZERO:      keep = 0; break;
      case R_STENCIL_REPLACE:   keep = 0; add = rs->dsa->stencil_ref; break;
      case R_STENCIL_INCR:      inc = 1; break;
      case R_STENCIL_DECR:      dec = 1; break;
      case R_STENCIL_INCR_WRAP: add = 1; break;
      case R_STENCIL_DECR_WRAP: add = 0xff; break;
      case R_STENCIL_INVERT:    flip = 0xff; break;
      case R_STENCIL_KEEP:
      default:                  break;
      }
      st->keep[k] = _mm256_set1_epi32(keep);
      st->flip[k] = _mm256_set1_epi32(flip);
      st->inc[k] = _mm256_set1_epi32(inc);
      st->dec[k] = _mm256_set1_epi32(dec);
      st->add[k] = _mm256_set1_epi32(add);
   }
}

static ALWAYS_INLINE __m256i stencil_op8(const struct stencil_ops *st, int k, __m256i s)
{
   const __m256i t = _mm256_xor_si256(_mm256_and_si256(s, st->keep[k]), st->flip[k]);
   const __m256i u = _mm256_max_epi32(
      _mm256_sub_epi32(_mm256_min_epi32(_mm256_add_epi32(t, st->inc[k]), _mm256_set1_epi32(0xff)),
                       st->dec[k]),
      _mm256_setzero_si256());
   return _mm256_and_si256(_mm256_add_epi32(u, st->add[k]), _mm256_set1_epi32(0xff));
}

/* The lanes of a half one at a time (a half reaching past the buffer's
 * right edge or last row): the reference's own compares, stencil ops and
 * colour operations (r_blend.h) on the lanes' depth and colour values.
 * m8: the lanes covered and passing the alpha test.  Returns how many
 * passed the tests (the occlusion query's samples). */
static unsigned finish_lanes(const struct r_state *rs, int x, int y, unsigned m8,
                             const uint32_t zv[8], const uint32_t src[8], enum zfmt zf,
                             bool zwrite, enum blend bl)
{
   unsigned passed = 0;
   for (unsigned m = m8; m; m &= m - 1) {
      const int i = __builtin_ctz(m);
      const size_t idx = (size_t)(y + (i >> 2)) * (size_t)rs->fb->width + (size_t)(x + (i & 3));
      if (zf == ZF_24S || zf == ZF_S) {
         /* r_frag.c stencil_depth_test on the Z24S8 word */
         uint32_t *zb = (uint32_t *)rs->fb->zs + idx;
         const uint8_t s = (uint8_t)(*zb >> 24), vm = rs->dsa->stencil_valuemask;
         enum r_stencil_op op;
         bool pass = compare(rs->dsa->stencil_func, rs->dsa->stencil_ref & vm, s & vm);
         if (!pass) {
            op = rs->dsa->stencil_fail;
         } else if (zf == ZF_24S) {
            pass = compare(rs->dsa->depth_func, zv[i], *zb & 0xffffffu);
            op = pass ? rs->dsa->stencil_zpass : rs->dsa->stencil_zfail;
            if (pass && zwrite)
               *zb = (*zb & 0xff000000u) | zv[i];
         } else {
            op = rs->dsa->stencil_zpass;
         }
         const uint8_t wm = rs->dsa->stencil_writemask;
         const uint8_t ns = (uint8_t)((stencil_op(rs, op, s) & wm) | (s & (uint8_t)~wm));
         *zb = (*zb & 0xffffffu) | (uint32_t)ns << 24;
         if (!pass)
            continue;
      } else if (zf_z24(zf)) {
         uint32_t *zb = (uint32_t *)rs->fb->zs + idx;
         if (!compare(rs->dsa->depth_func, zv[i], *zb & 0xffffffu))
            continue;
         if (zwrite)
            *zb = (*zb & 0xff000000u) | zv[i];
      } else if (zf == ZF_16) {
         uint16_t *zb = (uint16_t *)rs->fb->zs + idx;
         if (!compare(rs->dsa->depth_func, zv[i], *zb))
            continue;
         if (zwrite)
            *zb = (uint16_t)zv[i];
      }
      uint8_t *dst = rs->fb->color + 4 * idx;
      passed++;
      uint8_t s[4];
      memcpy(s, &src[i], 4);
      if (bl == BL_NONE) {
         memcpy(dst, s, 4);
         continue;
      }
      const uint8_t d[4] = { dst[0], dst[1], dst[2], rs->blend->dst_alpha_one ? 255 : dst[3] };
      uint8_t out[4];
      for (int c = 0; c < 4; c++) {
         if (bl == BL_ALPHA || bl == BL_BLEND) {
            out[c] = blend_channel(rs, c, s, d);
         } else {
            out[c] = rs->blend->logic_op ? logic_op(rs->blend->logic_op_mode, s[c], d[c]) : s[c];
         }
      }
      for (int c = 0; c < 4; c++)
         if (rs->blend->color_mask & (1u << c))
            dst[c] = out[c];
   }
   return passed;
}

/* The general colour operations in 8 lanes (ORACLE-NOTES.md "Blending,
 * alpha test, dithering"), their state as masks built
 * once per triangle (gen_ops_init), so no lane loop tests the state:
 *  - a blend factor is the OR of the candidate vectors (src, src alpha,
 *    dst, dst alpha, constant, constant alpha, alpha saturate) each ANDed
 *    with an all-ones or all-zeros mask, XOR 0xff for the ONE_MINUS_
 *    factors (255 - x == x ^ 255 on bytes); ZERO is no candidate, ONE is
 *    ZERO inverted (r_blend.h blend_factor);
 *  - the equation is the OR of the five results ANDed with masks;
 *  - a logic op is its truth table: (s & d & t1) | (s & ~d & t2) |
 *    (~s & d & t4) | (~s & ~d & t8), each t all ones or zeros;
 *  - the colour mask is a byte mask between the result and the buffer;
 *  - the alpha test compares like the depth test (three masks). */
struct gen_ops {
   __m256i fsel[2][7], finv[2];   /* [src, dst factor][candidate] */
   __m256i konst, konst_a;        /* the blend colour, 16-bit lanes */
   __m256i eq[5];
   __m256i lop[4];
   __m256i cmask;                 /* bytes written */
   struct depth_fn afn;
   __m256i aref;
};

static inline __m256i all_if(bool b)
{
   return _mm256_set1_epi32(b ? -1 : 0);
}

/* a mask of the 16-bit channel lanes of gen_blend16 (r, g, b, a per
 * pixel): the rgb lanes set when rgb, the alpha lanes when a */
static inline __m256i lanes_if(bool rgb, bool a)
{
   const short r = rgb ? -1 : 0, x = a ? -1 : 0;
   return _mm256_setr_epi16(r, r, r, x, r, r, r, x, r, r, r, x, r, r, r, x);
}

/* blend_channel's factor selection for factor x (r_blend.h blend_factor):
 * the candidate of gen_blend16 it takes, and whether it is inverted */
static inline bool factor_is(enum r_blend_factor x, int j)
{
   switch (j) {
   case 0: return x == R_BF_SRC_COLOR || x == R_BF_INV_SRC_COLOR;
   case 1: return x == R_BF_SRC_ALPHA || x == R_BF_INV_SRC_ALPHA;
   case 2: return x == R_BF_DST_COLOR || x == R_BF_INV_DST_COLOR;
   case 3: return x == R_BF_DST_ALPHA || x == R_BF_INV_DST_ALPHA;
   case 4: return x == R_BF_CONST_COLOR || x == R_BF_INV_CONST_COLOR;
   case 5: return x == R_BF_CONST_ALPHA || x == R_BF_INV_CONST_ALPHA;
   default: return x == R_BF_SRC_ALPHA_SATURATE;
   }
}

static inline bool factor_inv(enum r_blend_factor x)
{
   return x == R_BF_ONE || x == R_BF_INV_SRC_COLOR || x == R_BF_INV_SRC_ALPHA ||
          x == R_BF_INV_DST_COLOR || x == R_BF_INV_DST_ALPHA ||
          x == R_BF_INV_CONST_COLOR || x == R_BF_INV_CONST_ALPHA;
}

static inline void gen_ops_init(struct gen_ops *g, const struct r_state *rs)
{
   /* the rgb lanes take the rgb equation and factors, the alpha lanes the
    * alpha ones (the same unless separate_alpha), decided here once */
   const struct r_blend_state *b = rs->blend;
   const bool sep = b->separate_alpha;
   const enum r_blend_factor f[2] = { b->blend_src, b->blend_dst };
   const enum r_blend_factor fa[2] = { sep ? b->blend_src_a : b->blend_src,
                                       sep ? b->blend_dst_a : b->blend_dst };
   for (int k = 0; k < 2; k++) {
      for (int j = 0; j < 7; j++)
         g->fsel[k][j] = lanes_if(factor_is(f[k], j), factor_is(fa[k], j));
      g->finv[k] = _mm256_and_si256(lanes_if(factor_inv(f[k]), factor_inv(fa[k])),
                                    _mm256_set1_epi16(0xff));
   }
   const uint8_t *bc = b->blend_color;
   g->konst = _mm256_setr_epi16(bc[0], bc[1], bc[2], bc[3], bc[0], bc[1], bc[2], bc[3],
                                bc[0], bc[1], bc[2], bc[3], bc[0], bc[1], bc[2], bc[3]);
   g->konst_a = _mm256_set1_epi16(bc[3]);
   /* R_BLEND_ADD .. R_BLEND_MAX in enum order; an unknown one adds, as
    * blend_channel's default */
   unsigned eq = (unsigned)b->blend_eq, eq_a = sep ? (unsigned)b->blend_eq_a : eq;
   if (eq > R_BLEND_MAX)
      eq = R_BLEND_ADD;
   if (eq_a > R_BLEND_MAX)
      eq_a = R_BLEND_ADD;
   for (unsigned e = 0; e < 5; e++)
      g->eq[e] = lanes_if(eq == e, eq_a == e);
   const unsigned mode = rs->blend->logic_op ? rs->blend->logic_op_mode : 0x3u;   /* COPY */
   for (int t = 0; t < 4; t++)
      g->lop[t] = all_if(mode & (1u << t));
   uint32_t cm = 0;
   for (int c = 0; c < 4; c++)
      if (rs->blend->color_mask & (1u << c))
         cm |= 0xffu << (8 * c);
   g->cmask = _mm256_set1_epi32((int)cm);
   g->afn = depth_fn(rs->dsa->alpha_func);
   g->aref = _mm256_set1_epi32(rs->dsa->alpha_ref);
}

/* blend_channel on the 4 pixels of one unpacked half (16-bit lanes) */
static ALWAYS_INLINE __m256i gen_blend16(const struct gen_ops *g, __m256i s, __m256i d)
{
   const __m256i amask = _mm256_setr_epi8(6, 7, 6, 7, 6, 7, 6, 7, 14, 15, 14, 15, 14, 15, 14, 15,
                                          6, 7, 6, 7, 6, 7, 6, 7, 14, 15, 14, 15, 14, 15, 14, 15);
   const __m256i c255 = _mm256_set1_epi16(0xff);
   const __m256i alpha_lanes = _mm256_setr_epi16(0, 0, 0, 0xff, 0, 0, 0, 0xff,
                                                 0, 0, 0, 0xff, 0, 0, 0, 0xff);
   const __m256i sa = _mm256_shuffle_epi8(s, amask), da = _mm256_shuffle_epi8(d, amask);
   const __m256i sat = _mm256_or_si256(_mm256_min_epu16(sa, _mm256_xor_si256(da, c255)), alpha_lanes);
   const __m256i cand[7] = { s, sa, d, da, g->konst, g->konst_a, sat };
   __m256i f[2];
   for (int k = 0; k < 2; k++) {
      __m256i v = _mm256_setzero_si256();
      for (int j = 0; j < 7; j++)
         v = _mm256_or_si256(v, _mm256_and_si256(cand[j], g->fsel[k][j]));
      f[k] = _mm256_xor_si256(v, g->finv[k]);
   }
   const __m256i sm = mul_u8x16(s, f[0]), dm = mul_u8x16(d, f[1]);
   const __m256i r[5] = {
      _mm256_adds_epu16(sm, dm),   /* at most 510: packus saturates it */
      _mm256_subs_epu16(sm, dm),
      _mm256_subs_epu16(dm, sm),
      _mm256_min_epu16(sm, dm),
      _mm256_max_epu16(sm, dm),
   };
   __m256i out = _mm256_setzero_si256();
   for (int e = 0; e < 5; e++)
      out = _mm256_or_si256(out, _mm256_and_si256(r[e], g->eq[e]));
   return out;
}

/* the colour written over dst (the buffer's bytes) by BL_BLEND or
 * BL_LOGIC, the colour mask applied; d is dst with dst_alpha_one */
static ALWAYS_INLINE __m256i gen_color(const struct gen_ops *g, enum blend bl, __m256i src,
                                       __m256i d, __m256i dst)
{
   __m256i out;
   if (bl == BL_BLEND) {
      const __m256i zero = _mm256_setzero_si256();
      const __m256i lo = gen_blend16(g, _mm256_unpacklo_epi8(src, zero), _mm256_unpacklo_epi8(d, zero));
      const __m256i hi = gen_blend16(g, _mm256_unpackhi_epi8(src, zero), _mm256_unpackhi_epi8(d, zero));
      out = _mm256_packus_epi16(lo, hi);
   } else {
      out = _mm256_or_si256(
         _mm256_or_si256(_mm256_and_si256(_mm256_and_si256(src, d), g->lop[0]),
                         _mm256_and_si256(_mm256_andnot_si256(d, src), g->lop[1])),
         _mm256_or_si256(_mm256_and_si256(_mm256_andnot_si256(src, d), g->lop[2]),
                         _mm256_andnot_si256(_mm256_or_si256(src, d), g->lop[3])));
   }
   return _mm256_or_si256(_mm256_and_si256(out, g->cmask), _mm256_andnot_si256(g->cmask, dst));
}

/* four channel vectors (floats) to packed RGBA8 lanes, as r_float_to_unorm8
 * per channel */
static ALWAYS_INLINE __m256i pack_rgba8(__m256 r, __m256 g, __m256 b, __m256 a)
{
   /* the values are 0..255, so the saturating packs keep them: per
    * 128-bit lane, bytes r0..r3 g0..g3 b0..b3 a0..a3, then interleaved */
   const __m256i rg = _mm256_packus_epi32(unorm8(r), unorm8(g));
   const __m256i ba = _mm256_packus_epi32(unorm8(b), unorm8(a));
   const __m256i planar = _mm256_packus_epi16(rg, ba);
   const __m256i idx = _mm256_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15,
                                        0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15);
   return _mm256_shuffle_epi8(planar, idx);
}

/* input a's component c at the lanes, as shade_pixel reads it */
static ALWAYS_INLINE __m256 input8(const struct r_tri_setup *ts, int a, int c, __m256 fx, __m256 fy,
                                   __m256 rw)
{
   if (ts->flat_attr[a])
      return _mm256_set1_ps(ts->flat[a][c]);
   return _mm256_mul_ps(eval8(&ts->ap[a][c], fx, fy), rw);
}

/* r_frag.c fog_factor in 8 lanes (ORACLE-NOTES.md "Fog: coordinate and
 * factor", "gallivm's pow, exp2 and log2"): LINEAR fc * p0 + p1, EXP
 * exp2(-(fc * p2)), EXP2 exp2(-(t * t)) with t = fc * p3 (exp2v is
 * m_gallivm_exp2 lane-wise), then max(f, 0) (NaN -> 0) and min(., 1) */
static ALWAYS_INLINE __m256 fog_factor8(const struct r_state *rs, __m256 fc)
{
   const float *p = rs->fs->fog_params;
   __m256 f;
   switch (rs->fs->fog_mode) {
   case R_FOG_LINEAR:
      f = _mm256_add_ps(_mm256_mul_ps(fc, _mm256_set1_ps(p[0])), _mm256_set1_ps(p[1]));
      break;
   case R_FOG_EXP:
      f = exp2v(vneg(_mm256_mul_ps(fc, _mm256_set1_ps(p[2]))));
      break;
   case R_FOG_EXP2:
   default: {
      const __m256 t = _mm256_mul_ps(fc, _mm256_set1_ps(p[3]));
      f = exp2v(vneg(_mm256_mul_ps(t, t)));
      break;
   }
   }
   f = _mm256_max_ps(f, _mm256_setzero_ps());
   return _mm256_min_ps(f, _mm256_set1_ps(1.0f));
}

/* the fragment program's fog (r_frag.c fragment_shader): on rgb,
 * fogcolor * (1 + -f) + rgb * f */
static ALWAYS_INLINE void fog8(const struct r_state *rs, const struct r_tri_setup *ts, __m256 fx,
                               __m256 fy, __m256 rw, __m256 out[4])
{
   if (rs->fs->fog_mode != R_FOG_NONE) {
      const __m256 f = fog_factor8(rs, input8(ts, R_FS_FOG, 0, fx, fy, rw));
      const __m256 g = _mm256_add_ps(_mm256_set1_ps(1.0f), vneg(f));
      for (int c = 0; c < 3; c++)
         out[c] = _mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(rs->fs->fog_color[c]), g),
                                _mm256_mul_ps(out[c], f));
   }
}

/* the colour sum (rgb += the secondary colour input's rgb), then fog */
static ALWAYS_INLINE void color_sum_fog8(const struct r_state *rs, const struct r_tri_setup *ts,
                                         __m256 fx, __m256 fy, __m256 rw, __m256 out[4])
{
   if (rs->fs->color_sum) {
      for (int c = 0; c < 3; c++)
         out[c] = _mm256_add_ps(out[c], input8(ts, R_FS_COLOR1, c, fx, fy, rw));
   }
   fog8(rs, ts, fx, fy, rw, out);
}

/* The fragment operations the simple stages' kernels cover (the
 * textured and per-fragment-lit ones): the depth test (any function,
 * 16 or 24 bits, written or not) and a store, or SRC_ALPHA /
 * ONE_MINUS_SRC_ALPHA / ADD on every channel; false for anything else
 * (alpha or stencil test, logic op, colour mask, other blends). */
static inline bool block_simple_ops(const struct r_state *rs, enum blend *bl, enum zfmt *zf)
{
   *bl = BL_NONE;
   if (rs->full_ops) {
      if (rs->dsa->alpha_test || rs->dsa->stencil_test || rs->blend->logic_op || rs->blend->color_mask != 0xfu ||
          !rs->blend->enable || rs->blend->blend_eq != R_BLEND_ADD || rs->blend->blend_src != R_BF_SRC_ALPHA ||
          rs->blend->blend_dst != R_BF_INV_SRC_ALPHA || rs->blend->separate_alpha)
         return false;
      *bl = BL_ALPHA;
   }
   *zf = ZF_NONE;
   if (rs->dsa->depth_test) {
      switch (rs->fb->zs_format) {
      case R_ZS_Z16:   *zf = ZF_16; break;
      case R_ZS_Z24X8:
      case R_ZS_Z24S8: *zf = ZF_24; break;
      default:         return false;
      }
   }
   return true;
}

#endif
