/*
 * The block kernels of per-fragment-lit triangles (GL_PHONG_WIN, both
 * reflectance models), AVX2 + FMA (r_kernel.h): the triangle template
 * (r_block_tri.h) with a fragment stage that does, in 8 lanes, what the
 * reference does per pixel (r_tri.c shade_pixel, r_frag.c
 * r_fragment_phong and r_fragment_shader), in its order:
 *  - the inputs the lighting reads, R_FS_NORMAL and R_FS_EYEPOS (xyz) and,
 *    under colour material, R_FS_COLOR0: a flat input is the provoking
 *    vertex's value, an interpolated one fma(dady, y, fma(dadx, x, a0))
 *    times 1/w, 1/w a true divide of the w plane's value (shade_pixel);
 *  - the lighting: m_shade8_eval (math/m_shade_avx2.h), every lane
 *    m_shade_point_prepared's bits, with the triangle's face
 *    (ts->phong_back) and the environment of the batch (rs->shade_env,
 *    read per triangle: the material may change between primitives);
 *  - the fragment program without texture: the primary colour, plus the
 *    secondary colour's rgb under the colour sum (an fadd), then fog
 *    (r_frag.c fog_factor and the blend with the fog colour, the
 *    exponential factors by m_gallivm_exp2 lane-wise);
 *  - the colour to unorm8, the depth test and the store or the blend of
 *    the template (r_block_avx2.h).
 * Lanes of a half that no pixel covers are lit too and thrown away (their
 * values may be anything; nothing of them is stored).  The depth test
 * comes before the lighting (BLOCK_STAGE_EARLY_Z): a half none of whose
 * fragments passes is not lit.
 */
#include "r_block_avx2.h"

#include "math/m_shade_avx2.h"

struct block_stage {
   int unused;
};

static ALWAYS_INLINE void block_stage_prepare(const struct r_state *rs, const struct r_tri_setup *ts,
                                              int variant, struct block_stage *st)
{
   (void)rs; (void)ts; (void)variant;
   st->unused = 0;
}

/* input8, fog_factor8: r_block_avx2.h */

/* The lit fragment colour of 8 lanes, packed.  One copy, out of line,
 * shared by the depth and blend kernels: the state it reads (the vertex
 * colour input, the colour sum, fog) are branches per half, next to
 * nothing beside the lighting. */
static __attribute__((noinline)) __m256i phong_half(const struct r_state *rs,
                                                    const struct r_tri_setup *ts, __m256 fx,
                                                    __m256 fy)
{
   const __m256 rw = ts->need_w ? _mm256_div_ps(_mm256_set1_ps(1.0f), eval8(&ts->w, fx, fy))
                                : _mm256_setzero_ps();
   __m256 n[3], p[3], col[4];
   for (int c = 0; c < 3; c++) {
      n[c] = input8(ts, R_FS_NORMAL, c, fx, fy, rw);
      p[c] = input8(ts, R_FS_EYEPOS, c, fx, fy, rw);
   }
   if (ts->inputs & (1u << R_FS_COLOR0)) {
      for (int c = 0; c < 4; c++)
         col[c] = input8(ts, R_FS_COLOR0, c, fx, fy, rw);
   } else {
      /* (read only under colour material, which makes it an input) */
      col[0] = col[1] = col[2] = col[3] = _mm256_setzero_ps();
   }
   __m256 out[4], sec[4];
   m_shade8_eval(rs->shade_env, n, p, ts->phong_back, col, out, sec);
   /* the fragment program: rgb += secondary rgb under the colour sum, then
    * fog on rgb, fogcolor * (1 + -f) + rgb * f */
   if (rs->fs->color_sum) {
      for (int c = 0; c < 3; c++)
         out[c] = _mm256_add_ps(out[c], sec[c]);
   }
   fog8(rs, ts, fx, fy, rw, out);
   return pack_rgba8(out[0], out[1], out[2], out[3]);
}

static ALWAYS_INLINE __m256i block_stage_shade(const struct r_state *rs, const struct r_tri_setup *ts,
                                               const struct block_stage *st, int variant,
                                               __m256 fx, __m256 fy, int x, int y, unsigned m8,
                                               __m256i *live)
{
   (void)st; (void)variant; (void)x; (void)y; (void)m8; (void)live;
   return phong_half(rs, ts, fx, fy);
}

/* a half's lighting takes long enough to hide the next block row's
 * buffer lines coming in */
#define BLOCK_STAGE_PREFETCH 1
#define BLOCK_STAGE_PREFETCH_COLOR 1
/* the lighting has no effect but the colours: a half whose fragments all
 * fail the depth test is not lit */
#define BLOCK_STAGE_EARLY_Z 1
#include "r_block_tri.h"

#define TRI_KERNEL(name, zf, bl)                                                           \
   static void name(const struct r_state *rs, const struct r_tri_setup *ts,               \
                    const struct r_tri_cover *cv)                                          \
   {                                                                                       \
      tri_blocks(rs, ts, cv, 0, zf, bl);                                                   \
   }

/* (depth writes or not: the same kernel, r_block_tri.h) */
#define TRI_KERNELS_BLEND(prefix, bl)                                                      \
   TRI_KERNEL(prefix##_nz, ZF_NONE, bl)                                                   \
   TRI_KERNEL(prefix##_z16, ZF_16, bl)                                                    \
   TRI_KERNEL(prefix##_z24, ZF_24, bl)                                                    \
   /* [zfmt][zwrite] */                                                                    \
   static const r_tri_kernel prefix##_table[3][2] = {                                      \
      { prefix##_nz, prefix##_nz },                                                        \
      { prefix##_z16, prefix##_z16 },                                                      \
      { prefix##_z24, prefix##_z24 },                                                      \
   };

TRI_KERNELS_BLEND(opaque, BL_NONE)
TRI_KERNELS_BLEND(alpha, BL_ALPHA)

r_tri_kernel r_block_choose_tri_phong(const struct r_state *rs, bool flat_color)
{
   (void)flat_color;   /* each input's flatness is read per triangle */
   const unsigned lit = 1u << R_FS_NORMAL | 1u << R_FS_EYEPOS;
   /* the fragment program: the lighting inputs (and the vertex colour, and
    * the fog coordinate), no texture, pixel rectangle, coverage lowering
    * or stipple */
   if (!rs->fs->phong || (rs->fs->fs_inputs & ~(lit | 1u << R_FS_COLOR0 | 1u << R_FS_FOG)) ||
       (rs->fs->fs_inputs & lit) != lit || rs->fs->tex_units || rs->pix || rs->fs->aa != R_AA_NONE ||
       rs->rast->stipple || !rs->fb->color)
      return NULL;
   if (rs->fs->fog_mode != R_FOG_NONE && !(rs->fs->fs_inputs & (1u << R_FS_FOG)))
      return NULL;
   /* the fragment operations */
   enum blend bl;
   enum zfmt zf;
   if (!block_simple_ops(rs, &bl, &zf))
      return NULL;
   return (bl == BL_ALPHA ? alpha_table : opaque_table)[zf][rs->dsa->depth_write];
}
