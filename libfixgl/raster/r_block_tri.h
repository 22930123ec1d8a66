#ifndef BLOCK_STAGE_KILLS
#define BLOCK_STAGE_KILLS 0
#endif
/* BLOCK_STAGE_EARLY_Z: the stage kills no fragment and has no other
 * effect than its colours, so the depth test (and its write) may come
 * first and the stage shade only the halves with a fragment that passes
 * it: the same bytes, since no fragment's colour depends on the depth
 * buffer nor its depth on the colour.  (Not for a block past the buffer's
 * right edge, which finish_lanes takes in the reference's order.) */
#ifndef BLOCK_STAGE_EARLY_Z
#define BLOCK_STAGE_EARLY_Z 0
#endif
/* BLOCK_STAGE_PREFETCH: the stage is slow enough for the buffers' lines
 * of the next block row to be asked for ahead (depth, and colour when
 * blending, or always with BLOCK_STAGE_PREFETCH_COLOR) */
#ifndef BLOCK_STAGE_PREFETCH
#define BLOCK_STAGE_PREFETCH 0
#endif
#ifndef BLOCK_STAGE_PREFETCH_COLOR
#define BLOCK_STAGE_PREFETCH_COLOR 0
#endif

/*
 * r_block_tri.h: the triangle block walk, a template.  The including file
 * defines, before including it:
 *   struct block_stage                 per-triangle constants of its stage
 *   block_stage_prepare(rs, ts, variant, &stage)
 *                                      fills them once per triangle
 *   block_stage_shade(rs, ts, &stage, variant, fx, fy, x, y, m8, &live)
 *                                      the fragment stage: returns the 8
 *                                      lanes' RGBA8 colours of the 4x2 half
 *                                      at (x, y) (lane coordinates fx, fy;
 *                                      m8 the covered lanes) and may clear
 *                                      lanes of live (a kill)
 * all ALWAYS_INLINE, then instantiates tri_blocks with constant arguments.
 * Fragments are counted as shaded before the stage (its kills included),
 * as the reference counts them.
 *
 * The kernel template: the constant arguments choose the variant.
 *   variant the stage's variant (block_stage_*)
 *   zf      the depth test's buffer (ZF_NONE: no depth test)
 *   zwrite  depth writes
 *   bl      the blend (BL_ALPHA: SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ADD) */
static ALWAYS_INLINE void tri_blocks(const struct r_state *rs, const struct r_tri_setup *ts,
                                     const struct r_tri_cover *cv, const int variant,
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

   struct block_stage stage;
   block_stage_prepare(rs, ts, variant, &stage);
   const struct depth_fn fn = depth_fn(rs->depth_func);
   const __m256i dst_or = _mm256_set1_epi32(rs->dst_alpha_one ? (int)0xff000000u : 0);
   uint64_t fragments = 0;

   const int32_t bx0 = cv->x0 & ~3, by0 = cv->y0 & ~3;
   int32_t rowc[3];
   for (int e = 0; e < 3; e++)
      rowc[e] = cv->c[e] + (bx0 - cv->ox) * cv->dx[e] + (by0 - cv->oy) * cv->dy[e];

   /* the buffers' lines of the box's rows [ya, yb] and columns [x0, x1]
    * are asked for ahead of their use (a triangle touches a few pixels of
    * many rows, each row of the buffers its own page): the first block
    * row's now, each next block row's while this one is shaded */
   const size_t zbytes = zf == ZF_16 ? 2 : 4;
#define TRI_PREFETCH_ROWS(ya, yb)                                                          \
   for (int32_t py_ = (ya); py_ <= (yb) && py_ <= cv->y1; py_++) {                         \
      const size_t row_ = (size_t)py_ * stride;                                            \
      for (int32_t px_ = cv->x0 & ~15; px_ <= cv->x1; px_ += 16) {                         \
         if (bl != BL_NONE || BLOCK_STAGE_PREFETCH_COLOR)                                  \
            _mm_prefetch((const char *)((const uint32_t *)rs->color + row_ + (size_t)px_), \
                         _MM_HINT_T0);                                                     \
         if (zf != ZF_NONE)                                                                \
            _mm_prefetch((const char *)rs->zs + (row_ + (size_t)px_) * zbytes, _MM_HINT_T0); \
      }                                                                                    \
   }
   if (BLOCK_STAGE_PREFETCH)
      TRI_PREFETCH_ROWS(cv->y0, by0 + 3)

   for (int32_t by = by0; by <= cv->y1; by += 4) {
      if (BLOCK_STAGE_PREFETCH)
         TRI_PREFETCH_ROWS(by + 4, by + 7)
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

            /* the fragment colour (after the depth test with an early one) */
            __m256i live = lane_mask(m8);
            const bool early = BLOCK_STAGE_EARLY_Z && !BLOCK_STAGE_KILLS && zf != ZF_NONE && !edge;
            __m256i src = _mm256_setzero_si256();
            if (!early)
               src = block_stage_shade(rs, ts, &stage, variant, fx, fy, bx, y, m8, &live);
            unsigned lm8 = m8;
            if (BLOCK_STAGE_KILLS) {
               lm8 = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(live));
               if (!lm8)
                  continue;
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
               finish_lanes(rs, bx, y, lm8, zl, sl, zf, zwrite, bl);
               continue;
            }

            const size_t idx = (size_t)y * stride + (size_t)bx;
            __m256i pass = live;
            if (zf == ZF_24) {
               uint32_t *zp = (uint32_t *)rs->zs + idx;
               const __m256i zb = load_rows32(zp, stride, lm8);
               pass = _mm256_and_si256(
                  pass, depth_pass(&fn, zv, _mm256_and_si256(zb, _mm256_set1_epi32(0xffffff))));
               if (zwrite) {
                  const __m256i nz = _mm256_or_si256(
                     _mm256_and_si256(zb, _mm256_set1_epi32((int)0xff000000u)), zv);
                  store_rows32(zp, stride, lm8, _mm256_blendv_epi8(zb, nz, pass));
               }
            } else if (zf == ZF_16) {
               uint16_t *zp = (uint16_t *)rs->zs + idx;
               const __m256i zb = load_rows16(zp, stride, lm8);
               pass = _mm256_and_si256(pass, depth_pass(&fn, zv, zb));
               if (zwrite)
                  store_rows16(zp, stride, lm8, _mm256_blendv_epi8(zb, zv, pass));
            }
            const unsigned pm = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(pass));
            if (!pm)
               continue;
            if (early)
               src = block_stage_shade(rs, ts, &stage, variant, fx, fy, bx, y, m8, &live);

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
#undef TRI_PREFETCH_ROWS
}

