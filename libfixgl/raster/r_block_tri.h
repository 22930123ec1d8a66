#ifndef BLOCK_STAGE_KILLS
#define BLOCK_STAGE_KILLS 0
#endif
/* BLOCK_STAGE_PER_BLOCK: the stage defines
 *   block_stage_block(rs, ts, &stage, variant, fx)
 * which computes into the stage what both halves of the block at lane
 * columns fx share (the planes' x terms), before either is shaded */
#ifndef BLOCK_STAGE_PER_BLOCK
#define BLOCK_STAGE_PER_BLOCK 0
#endif
#ifndef BLOCK_STAGE_HAS_ALPHA
#define BLOCK_STAGE_HAS_ALPHA 0
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
 * r_block_tri.h: the block walk of triangles, lines and points (their
 * r_tri_cover: up to three edges over a box), a template.  The including file
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
 * and, with BLOCK_STAGE_HAS_ALPHA 1,
 *   block_stage_alpha(rs, ts, &stage, variant, fx, fy)
 *                                      the fragment alpha as a float (the
 *                                      alpha test's operand, NaN kept)
 * all ALWAYS_INLINE, then instantiates tri_blocks with constant arguments.
 * Fragments are counted as shaded before the stage (its kills included),
 * as the reference counts them.
 *
 * The kernel template: the constant arguments choose the variant.
 *   variant the stage's variant (block_stage_*)
 *   zf      the depth test's buffer (ZF_NONE: no depth test)
 *   bl      the colour operations (r_block_avx2.h enum blend)
 * Depth writes are the state's, read once a call: a branch per half that
 * always goes the same way, so that one kernel serves both (compiling
 * them apart was two of every five kernels). */
static ALWAYS_INLINE void tri_blocks(const struct r_state *rs, const struct r_tri_setup *ts,
                                     const struct r_tri_cover *cv, const int variant,
                                     const enum zfmt zf, const enum blend bl)
{
   const bool zwrite = zf != ZF_NONE && zf != ZF_S && rs->dsa->depth_write;
   const int width = rs->fb->width, height = rs->fb->height;
   const size_t stride = (size_t)width;
   /* the buffers, read once: the stores through them might alias rs */
   void *const zs_base = rs->fb->zs;
   uint32_t *const color_base = (uint32_t *)rs->fb->color;
   const __m256i lx = _mm256_setr_epi32(0, 1, 2, 3, 0, 1, 2, 3);
   const __m256i ly = _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1);
   const __m256 flx = _mm256_cvtepi32_ps(lx), fly = _mm256_cvtepi32_ps(ly);
   /* the depth plane and offset, broadcast once */
   const struct vplane zplane = vplane_of(&ts->z);
   const __m256 zoffset = _mm256_set1_ps(ts->zoffset);

   /* the edge functions' offsets of the lanes of the two halves */
   __m256i eoff[R_COVER_EDGES][2];
   block_cover_offsets(cv, eoff);

   struct block_stage stage;
   block_stage_prepare(rs, ts, variant, &stage);
   const struct depth_fn fn = depth_fn(rs->dsa->depth_func);
   const __m256i dst_or = _mm256_set1_epi32(rs->blend->dst_alpha_one ? (int)0xff000000u : 0);
   /* the general colour operations and the alpha test */
   const bool alpha_test = bl == BL_BLEND_AT || bl == BL_LOGIC_AT;
   const enum blend cop = bl == BL_BLEND_AT ? BL_BLEND : bl == BL_LOGIC_AT ? BL_LOGIC : bl;
   (void)alpha_test;   /* (read only for a stage with block_stage_alpha) */
   struct gen_ops gops;
   if (cop == BL_BLEND || cop == BL_LOGIC)
      gen_ops_init(&gops, rs);
   struct stencil_ops sops;
   if (zf == ZF_24S || zf == ZF_S)
      stencil_ops_init(&sops, rs);
   uint64_t fragments = 0;
   /* the samples that pass, for the active occlusion query (a branch on
    * a constant of the walk when there is none) */
   const bool count_samples = rs->samples != NULL;
   uint64_t samples = 0;

   const int32_t bx0 = cv->x0 & ~3, by0 = cv->y0 & ~3;
   int32_t rowc[R_COVER_EDGES];
   for (int e = 0; e < R_COVER_EDGES; e++)
      rowc[e] = cv->c[e] + (bx0 - cv->ox) * cv->dx[e] + (by0 - cv->oy) * cv->dy[e];
   /* the edges' steps from a block to the next one along the row */
   __m256i estep[R_COVER_EDGES];
   for (int e = 0; e < R_COVER_EDGES; e++)
      estep[e] = _mm256_set1_epi32(4 * cv->dx[e]);
   /* the box's columns in its first and last block columns (a block
    * column is cut only there: x0 - bx0 < 4, last <= x1) */
   const int32_t bxl = cv->x1 & ~3;
   const unsigned first_cols = (0xfu << (cv->x0 - bx0)) & 0xfu;
   const unsigned last_cols = 0xfu >> (3 - (cv->x1 - bxl));
   const unsigned first_mask = first_cols * 0x1111u, last_mask = last_cols * 0x1111u;
   /* fragments are counted only for fixgl's counters */
   const bool count_fragments = rs->stats != NULL;
   /* rows of five blocks or more are narrowed to the blocks the edges
    * allow (block_row_span) */
   const bool wide = cv->x1 - bx0 >= 16;
   const bool long_rows = cv->x1 - bx0 >= 32;

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
            _mm_prefetch((const char *)((const uint32_t *)rs->fb->color + row_ + (size_t)px_), \
                         _MM_HINT_T0);                                                     \
         if (zf != ZF_NONE)                                                                \
            _mm_prefetch((const char *)rs->fb->zs + (row_ + (size_t)px_) * zbytes, _MM_HINT_T0); \
      }                                                                                    \
   }
   if (BLOCK_STAGE_PREFETCH)
      TRI_PREFETCH_ROWS(cv->y0, by0 + 3)

   for (int32_t by = by0; by <= cv->y1; by += 4) {
      if (BLOCK_STAGE_PREFETCH)
         TRI_PREFETCH_ROWS(by + 4, by + 7)
      /* the box's rows in this block row, one nibble each (by <= y1,
       * by + 3 >= y0: only the first and the last block rows lose some) */
      unsigned rows = 0xffffu;
      if (by < cv->y0)
         rows &= 0xffffu << (4 * (cv->y0 - by));
      if (by + 3 > cv->y1)
         rows &= 0xffffu >> (4 * (by + 3 - cv->y1));
      /* the row's blocks that may hold a covered pixel */
      int32_t first = bx0, last = cv->x1;
      if (wide && !block_row_span(cv, rowc, bx0, &first, &last)) {
         for (int e = 0; e < R_COVER_EDGES; e++)
            rowc[e] += 4 * cv->dy[e];
         continue;
      }
      /* the row's blocks wholly inside the edges (block_row_inner), which
       * skip the edge test: none in a box of fewer than nine block
       * columns */
      int32_t ifirst = 1, ilast = 0;
      if (long_rows && !block_row_inner(cv, rowc, bx0, &ifirst, &ilast))
         ifirst = 1, ilast = 0;
      /* the edge values of the lanes of both halves of the block at bx
       * (r_block_cover's v = c + eoff), stepped along the row */
      __m256i ev[R_COVER_EDGES][2];
      for (int e = 0; e < R_COVER_EDGES; e++) {
         const __m256i c = _mm256_set1_epi32(rowc[e] + (first - bx0) * cv->dx[e]);
         ev[e][0] = _mm256_add_epi32(c, eoff[e][0]);
         ev[e][1] = _mm256_add_epi32(c, eoff[e][1]);
      }
      for (int32_t bx = first; bx <= last; bx += 4) {
         /* coverage: a lane is covered when no edge value is negative,
          * i.e. the sign bit of their OR is clear (r_block_cover) */
         unsigned mask = 0xffffu;
         if (!(bx >= ifirst && bx <= ilast)) {
            __m256i neg0 = ev[0][0], neg1 = ev[0][1];
            for (int e = 1; e < R_COVER_EDGES; e++) {
               neg0 = _mm256_or_si256(neg0, ev[e][0]);
               neg1 = _mm256_or_si256(neg1, ev[e][1]);
            }
            mask = ~((unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(neg0)) |
                     (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(neg1)) << 8) & 0xffffu;
         }
         for (int e = 0; e < R_COVER_EDGES; e++) {
            ev[e][0] = _mm256_add_epi32(ev[e][0], estep[e]);
            ev[e][1] = _mm256_add_epi32(ev[e][1], estep[e]);
         }
         /* cut to the box's rows and, in its first and last block
          * columns, its columns */
         mask &= rows;
         if (bx == bx0)
            mask &= first_mask;
         if (bx == bxl)
            mask &= last_mask;
         if (!mask)
            continue;
         if (count_fragments)
            fragments += (unsigned)__builtin_popcount(mask);
         const bool edge_x = bx + 4 > width;

         /* what both halves share: the lanes' columns and the planes'
          * x terms */
         const __m256 fx = _mm256_add_ps(_mm256_set1_ps((float)bx), flx);
         const __m256 zx = veval8_x(&zplane, fx);
#if BLOCK_STAGE_PER_BLOCK
         block_stage_block(rs, ts, &stage, variant, fx);
#endif
         for (int h = 0; h < 2; h++) {
            const unsigned m8 = (mask >> (8 * h)) & 0xffu;
            if (!m8)
               continue;
            const int y = by + 2 * h;
            const __m256 fy = _mm256_add_ps(_mm256_set1_ps((float)y), fly);
            /* a half reaching past the buffer's right edge or, in a buffer
             * of odd height, past its last row takes its lanes one at a
             * time (finish_lanes); every other half reads and writes both
             * of its rows whole */
            const bool edge = edge_x || y + 1 >= height;

            /* the fragment colour (after the depth test with an early one) */
            __m256i live = lane_mask(m8);
            const bool early = BLOCK_STAGE_EARLY_Z && !BLOCK_STAGE_KILLS && !alpha_test &&
                               zf != ZF_NONE && !edge;
            __m256i src = _mm256_setzero_si256();
            if (!early)
               src = block_stage_shade(rs, ts, &stage, variant, fx, fy, bx, y, m8, &live);
            unsigned lm8 = m8;
            if (BLOCK_STAGE_KILLS) {
               lm8 = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(live));
               if (!lm8)
                  continue;
            }
#if BLOCK_STAGE_HAS_ALPHA
            if (alpha_test) {
               /* r_fragment_ops: round_even(clamp01(a) * 255) (NaN -> 1,
                * as depth_unorm clamps) against the reference */
               const __m256 a = block_stage_alpha(rs, ts, &stage, variant, fx, fy);
               live = _mm256_and_si256(live, depth_pass(&gops.afn, depth_unorm(a, 255.0f), gops.aref));
               lm8 = (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(live));
               if (!lm8)
                  continue;
            }
#endif

            /* the depth value (lp_bld_interp.c: interpolated z + offset) */
            __m256i zv = _mm256_setzero_si256();
            if (zf != ZF_NONE && zf != ZF_S) {
               const __m256 z = _mm256_add_ps(veval8_y(&zplane, zx, fy), zoffset);
               zv = depth_unorm(z, zf == ZF_16 ? 65535.0f : 16777215.0f);
            }

            if (edge) {
               uint32_t zl[8], sl[8];
               _mm256_storeu_si256((__m256i *)zl, zv);
               _mm256_storeu_si256((__m256i *)sl, src);
               const unsigned passed = finish_lanes(rs, bx, y, lm8, zl, sl, zf, zwrite, cop);
               if (count_samples)
                  samples += passed;
               continue;
            }

            const size_t idx = (size_t)y * stride + (size_t)bx;
            __m256i pass = live;
            /* both rows of the half are read and written back whole
             * (uncovered and failing lanes with their old values), without
             * a branch on the masks */
            const unsigned rm = 0xffu;
            if (zf == ZF_24S || zf == ZF_S) {
               /* r_frag.c stencil_depth_test: the stencil test, then the
                * depth test of its passing lanes, the op of each outcome
                * under the write mask, the Z24S8 words of the live lanes
                * rewritten */
               uint32_t *zp = (uint32_t *)zs_base + idx;
               const __m256i zb = load_rows32(zp, stride, rm);
               const __m256i s8 = _mm256_srli_epi32(zb, 24);
               const __m256i spass = depth_pass(&sops.fn, sops.ref_vm, _mm256_and_si256(s8, sops.vm));
               __m256i zpass = spass;
               __m256i zword = _mm256_and_si256(zb, _mm256_set1_epi32(0xffffff));
               if (zf == ZF_24S) {
                  zpass = _mm256_and_si256(spass, depth_pass(&fn, zv, zword));
                  if (zwrite)
                     zword = _mm256_blendv_epi8(zword, zv, zpass);
               }
               /* fail: !spass; zfail: spass & !zpass; zpass */
               __m256i ns = _mm256_blendv_epi8(stencil_op8(&sops, 0, s8), stencil_op8(&sops, 1, s8), spass);
               ns = _mm256_blendv_epi8(ns, stencil_op8(&sops, 2, s8), zpass);
               ns = _mm256_or_si256(_mm256_and_si256(ns, sops.wm), _mm256_andnot_si256(sops.wm, s8));
               const __m256i nw = _mm256_or_si256(zword, _mm256_slli_epi32(ns, 24));
               store_rows32(zp, stride, rm, _mm256_blendv_epi8(zb, nw, pass));
               pass = _mm256_and_si256(pass, zpass);
            } else if (zf_z24(zf)) {
               uint32_t *zp = (uint32_t *)zs_base + idx;
               const __m256i zb = load_rows32(zp, stride, rm);
               pass = _mm256_and_si256(
                  pass, depth_test8(zf, &fn, zv, _mm256_and_si256(zb, _mm256_set1_epi32(0xffffff))));
               if (zwrite) {
                  const __m256i nz = _mm256_or_si256(
                     _mm256_and_si256(zb, _mm256_set1_epi32((int)0xff000000u)), zv);
                  store_rows32(zp, stride, rm, _mm256_blendv_epi8(zb, nz, pass));
               }
            } else if (zf == ZF_16) {
               uint16_t *zp = (uint16_t *)zs_base + idx;
               const __m256i zb = load_rows16(zp, stride, rm);
               pass = _mm256_and_si256(pass, depth_pass(&fn, zv, zb));
               if (zwrite)
                  store_rows16(zp, stride, rm, _mm256_blendv_epi8(zb, zv, pass));
            }
            if (count_samples)
               samples += (unsigned)__builtin_popcount(
                  (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(pass)));
            if (early) {
               /* shade only a half with a fragment that passed */
               if (!_mm256_movemask_ps(_mm256_castsi256_ps(pass)))
                  continue;
               src = block_stage_shade(rs, ts, &stage, variant, fx, fy, bx, y, m8, &live);
            }

            uint32_t *cp = color_base + idx;
            const __m256i dst = load_rows32(cp, stride, rm);
            __m256i out = src;
            if (cop == BL_ALPHA)
               out = blend_alpha(src, _mm256_or_si256(dst, dst_or));
            else if (cop == BL_BLEND || cop == BL_LOGIC)
               out = gen_color(&gops, cop, src, _mm256_or_si256(dst, dst_or), dst);
            store_rows32(cp, stride, rm, _mm256_blendv_epi8(dst, out, pass));
         }
      }
      for (int e = 0; e < R_COVER_EDGES; e++)
         rowc[e] += 4 * cv->dy[e];
   }
   if (rs->stats)
      rs->stats->fragments += fragments;
   if (count_samples)
      rs->samples->n += samples;
#undef TRI_PREFETCH_ROWS
}

