/*
 * The block kernels of textured triangles, AVX2 + FMA (r_kernel.h): one
 * texture unit (unit 0) with a texture the 8-lane lookup samples itself
 * (r_tex8_fast: 1D or 2D, no `soa`, REPEAT or CLAMP_TO_EDGE, any image
 * and mip filter), an environment of the simple form (r_frag.c
 * r_tex_combine_simplify: REPLACE, MODULATE, and every combine made of one
 * argument or the product of two per channel) or GL_DECAL on an RGBA
 * texture, the colour smooth or flat,
 * through the triangle template (r_block_tri.h).
 *
 * Every lane does what the reference does for its pixel (r_tri.c
 * shade_pixel, fill_quad, shade_textured; r_frag.c texture_units,
 * simple_texenv, tex_color):
 *  - the inputs: fma(dady, y, fma(dadx, x, a0)) times 1/w (a true divide),
 *    or the provoking vertex's value for a flat input;
 *  - the projection: s, t times 1/q (a true divide);
 *  - the level of detail of each 2x2 quad (ORACLE-NOTES.md "Texture
 *    sampling: level of detail per quad") from its top-left, top-right and
 *    bottom-left pixels' projected coordinates (r_tex_lod.h, the code of
 *    fill_quad's r_tex_lod_aos), whether those pixels are covered or not:
 *    a 4x2 half holds two whole quads (x a multiple of 4, y even), and its
 *    lanes are evaluated at every pixel, as fill_quad evaluates the quad's
 *    corners; the quad of a pixel is the same in both paths (x & ~1, y & ~1)
 *    and its coordinates are the same float operations, so the cached
 *    quad of the reference and the lanes here agree;
 *  - the lookup: r_tex_avx2.h, r_tex_filter_aos's code on 8 lanes, bit for
 *    bit (tests/unit/test_tex8.c; ORACLE-NOTES.md "Texture sampling: the
 *    8-bit path"); texels to float as (float)b * (1/255);
 *  - the environment per channel: the argument, 1 - x, or a product, on
 *    floats, then r_float_to_unorm8 (unorm8).  A channel that is the
 *    texel itself is the texel's byte: unorm8((float)b * (float)(1/255))
 *    is b for every byte b (tests/unit/test_tex8.c checks it), so it skips the
 *    float round trip; t * p and p * t are the same float (an IEEE product
 *    commutes; a NaN, whichever it is, converts to 0).
 * The lanes are evaluated in the lookup's quad-major order (quad A =
 * pixels (x..x+1, y..y+1) in lanes 0..3, quad B in 4..7) and the packed
 * colours are put back in the template's row-major order at the end.
 */
#include "r_block_avx2.h"
#include "r_tex_avx2.h"

#include <math.h>

/* the environment's form: RGB channels then alpha, each the texel (T),
 * the primary colour (P) or their product (TP); ENV_ARGS: any simple
 * environment, by its arguments; ENV_DECAL: GL_DECAL on an RGBA texture
 * (r_frag.c emit_texenv: INTERPOLATE of T, PREVIOUS by T.a unsaturated,
 * so rgb = T.c * T.a + P.c * (1 - T.a); alpha REPLACE by P.a) */
enum env { ENV_ARGS, ENV_T_T, ENV_T_P, ENV_TP_TP, ENV_TP_P, ENV_DECAL };
/* the variant: an env, plus VAR_TRILINEAR for a texture of
 * tex8_is_trilinear_repeat or VAR_BILINEAR for one of
 * tex8_is_bilinear with REPEAT (its lookup's properties constants) */
#define VAR_ENV(v) ((v) & 15)
#define VAR_TRILINEAR 16
#define VAR_BILINEAR 32

/* what stage_front computes for a half */
struct stage_front {
   __m256 rw, s, t;
   struct r_tex_lod lod[2];
   struct tex8_trilod tl;   /* VAR_TRILINEAR's */
};

struct block_stage {
   const struct r_texture *tex;
   bool flat_color, flat_tex;
   __m256 color[4];   /* flat colour, broadcast */
   __m256 tc[4];      /* flat texture coordinates, broadcast */
   __m256 konst[4];   /* the unit's constant colour */
   /* the planes of w, the coordinates and the colour, broadcast once
    * (those of the inputs read: not flat) */
   struct vplane pw, ptc[4], pcol[4];
   __m256 fw, fh;   /* the base level's size (VAR_TRILINEAR's level of detail) */
   uint8_t nargs[4], arg[4][2];   /* ENV_ARGS: r_tex_combine.simple_* */
   struct tex8_level levels[R_MAX_TEX_LEVELS];   /* first_level .. last_level */
   /* the front of the lower half of the last block (next_x, next_y) */
   int next_x, next_y;
   struct stage_front next;
};

static ALWAYS_INLINE void block_stage_prepare(const struct r_state *rs, const struct r_tri_setup *ts,
                                              int variant, struct block_stage *st)
{
   (void)variant;
   st->tex = &rs->tex[0]->tex;
   st->flat_color = ts->flat_attr[R_FS_COLOR0];
   st->flat_tex = ts->flat_attr[R_FS_TEX0];
   st->next_x = st->next_y = INT32_MIN;   /* (y is even) */
   for (int l = st->tex->first_level; l <= st->tex->last_level; l++)
      tex8_level_init(st->tex, l, &st->levels[l]);
   st->fw = _mm256_set1_ps((float)st->tex->level[st->tex->first_level].width);
   st->fh = _mm256_set1_ps((float)st->tex->level[st->tex->first_level].height);
   if (!st->flat_tex || !st->flat_color)
      st->pw = vplane_of(&ts->w);
   for (int c = 0; c < 4; c++) {
      if (!st->flat_tex && c != 2)
         st->ptc[c] = vplane_of(&ts->ap[R_FS_TEX0][c]);
      if (!st->flat_color)
         st->pcol[c] = vplane_of(&ts->ap[R_FS_COLOR0][c]);
   }
   const struct r_tex_combine *k = &rs->tex[0]->comb;
   for (int c = 0; c < 4; c++) {
      st->color[c] = _mm256_set1_ps(ts->flat[R_FS_COLOR0][c]);
      st->tc[c] = _mm256_set1_ps(ts->flat[R_FS_TEX0][c]);
      st->konst[c] = _mm256_set1_ps(rs->tex[0]->env_color[c]);
      st->nargs[c] = k->simple_nargs[c];
      st->arg[c][0] = k->simple_arg[c][0];
      st->arg[c][1] = k->simple_arg[c][1];
   }
}

/* the lanes' pixel offsets in quad-major order */
static ALWAYS_INLINE __m256 quad_lx(void) { return _mm256_setr_ps(0, 1, 0, 1, 2, 3, 2, 3); }
static ALWAYS_INLINE __m256 quad_ly(void) { return _mm256_setr_ps(0, 0, 1, 1, 0, 0, 1, 1); }

/* one simple_arg (r_frag.c simple_texenv) of channel c: its source's
 * component, or 1 - that */
static ALWAYS_INLINE __m256 env_arg(const struct block_stage *st, unsigned a, const __m256 tf[4],
                                    const __m256 pc[4])
{
   __m256 v;
   switch (a >> 3) {
   case R_SIMPLE_TEXTURE:  v = tf[a & 3]; break;
   case R_SIMPLE_PREVIOUS:               /* unit 0: the primary colour */
   case R_SIMPLE_PRIMARY:  v = pc[a & 3]; break;
   case R_SIMPLE_CONSTANT: v = st->konst[a & 3]; break;
   case R_SIMPLE_ZERO:     v = _mm256_setzero_ps(); break;
   default:                v = _mm256_set1_ps(1.0f); break;
   }
   if (a & 4)
      v = _mm256_sub_ps(_mm256_set1_ps(1.0f), v);
   return v;
}

/* The front of the stage for the half at (x, y): 1/w, the projected
 * coordinates and (but for VAR_TRILINEAR: stage_lod) the quads' level of
 * detail -- the chain of two divides the lookup waits for. */
static ALWAYS_INLINE void stage_front(const struct block_stage *st, int variant, int x, int y,
                                      struct stage_front *f)
{
   const __m256 fx = _mm256_add_ps(_mm256_set1_ps((float)x), quad_lx());
   const __m256 fy = _mm256_add_ps(_mm256_set1_ps((float)y), quad_ly());
   const bool need_color = VAR_ENV(variant) != ENV_T_T;
   __m256 rw = _mm256_setzero_ps();
   if (!st->flat_tex || (need_color && !st->flat_color))
      rw = _mm256_div_ps(_mm256_set1_ps(1.0f), veval8_y(&st->pw, veval8_x(&st->pw, fx), fy));

   /* the projected coordinates (tex_color: coord * (1 / q)) */
   __m256 s, t, q;
   if (st->flat_tex) {
      s = st->tc[0];
      t = st->tc[1];
      q = st->tc[3];
   } else {
      s = _mm256_mul_ps(veval8_y(&st->ptc[0], veval8_x(&st->ptc[0], fx), fy), rw);
      t = _mm256_mul_ps(veval8_y(&st->ptc[1], veval8_x(&st->ptc[1], fx), fy), rw);
      q = _mm256_mul_ps(veval8_y(&st->ptc[3], veval8_x(&st->ptc[3], fx), fy), rw);
   }
   const __m256 rq = _mm256_div_ps(_mm256_set1_ps(1.0f), q);
   f->rw = rw;
   f->s = _mm256_mul_ps(s, rq);
   f->t = _mm256_mul_ps(t, rq);

   /* the level of detail of quads A and B (fill_quad) */
   if (variant & VAR_TRILINEAR)
      return;
   if (!(variant & VAR_BILINEAR))   /* (its lookup needs none) */
      tex8_lod_quads(st->tex, f->s, f->t, f->lod);
}

static ALWAYS_INLINE __m256i block_stage_shade(const struct r_state *rs, const struct r_tri_setup *ts,
                                               const struct block_stage *st, int variant,
                                               __m256 fx_rows, __m256 fy_rows, int x, int y,
                                               unsigned m8, __m256i *live)
{
   (void)rs; (void)ts; (void)fx_rows; (void)fy_rows; (void)m8; (void)live;
   const __m256 fx = _mm256_add_ps(_mm256_set1_ps((float)x), quad_lx());
   const __m256 fy = _mm256_add_ps(_mm256_set1_ps((float)y), quad_ly());
   const int env = VAR_ENV(variant);
   /* The front of both halves of a block at its top half, the lower
    * half's kept for it (the two divide chains overlap); the stage is the
    * walk's local object (tri_blocks), written through its pointer as
    * r_tri.c fill_quad writes its cache. */
   struct block_stage *mst = (struct block_stage *)st;
   struct stage_front f;
   if ((y & 3) == 0) {
      stage_front(st, variant, x, y, &f);
      stage_front(st, variant, x, y + 2, &mst->next);
      mst->next_x = x;
      mst->next_y = y + 2;
      /* the trilinear level of detail of both halves' quads at once */
      if (variant & VAR_TRILINEAR)
         tex8_trilinear_lod2(st->tex->first_level, st->tex->last_level, st->fw, st->fh, f.s, f.t,
                             mst->next.s, mst->next.t, &f.tl, &mst->next.tl);
   } else if (st->next_x == x && st->next_y == y) {
      f = st->next;
   } else {
      stage_front(st, variant, x, y, &f);
      if (variant & VAR_TRILINEAR) {
         struct tex8_trilod unused;
         tex8_trilinear_lod2(st->tex->first_level, st->tex->last_level, st->fw, st->fh, f.s,
                             f.t, f.s, f.t, &f.tl, &unused);
      }
   }
   const __m256 rw = f.rw;
   const struct r_texture *tex = st->tex;
   __m256i texel;
   if (variant & VAR_TRILINEAR)
      texel = tex8_filter_trilinear_lod(st->levels, tex->last_level, &f.tl, f.s, f.t);
   else if (variant & VAR_BILINEAR)
      texel = tex8_filter_bilinear(st->levels, tex->first_level, R_WRAP_REPEAT, f.s, f.t);
   else
      texel = tex8_filter_quads(tex, st->levels, f.lod, f.s, f.t);

   __m256i out;
   if (env == ENV_T_T) {
      out = texel;
   } else {
      __m256 pc[4];
      if (st->flat_color) {
         for (int c = 0; c < 4; c++)
            pc[c] = st->color[c];
      } else {
         for (int c = 0; c < 4; c++)
            pc[c] = _mm256_mul_ps(veval8_y(&st->pcol[c], veval8_x(&st->pcol[c], fx), fy), rw);
      }
      const __m256 scale = _mm256_set1_ps((float)(1.0 / 255.0));
      const __m256i m255 = _mm256_set1_epi32(255);
      __m256 tf[4];
      for (int c = 0; c < 4; c++)
         tf[c] = _mm256_mul_ps(
            _mm256_cvtepi32_ps(_mm256_and_si256(_mm256_srli_epi32(texel, 8 * c), m255)), scale);
      if (env == ENV_DECAL) {
         const __m256 b = _mm256_sub_ps(_mm256_set1_ps(1.0f), tf[3]);
         __m256 res[3];
         for (int c = 0; c < 3; c++)
            res[c] = _mm256_add_ps(_mm256_mul_ps(tf[c], tf[3]), _mm256_mul_ps(pc[c], b));
         out = pack_rgba8(res[0], res[1], res[2], pc[3]);
      } else if (env == ENV_ARGS) {
         __m256 res[4];
         for (int c = 0; c < 4; c++) {
            const __m256 v0 = env_arg(st, st->arg[c][0], tf, pc);
            res[c] = st->nargs[c] == 1 ? v0 : _mm256_mul_ps(v0, env_arg(st, st->arg[c][1], tf, pc));
         }
         out = pack_rgba8(res[0], res[1], res[2], res[3]);
      } else {
         /* the RGB channels (T or TP), then alpha (P or TP); T_T was the
          * texel itself */
         const bool rgb_t = env == ENV_T_P;
         const bool a_p = env == ENV_T_P || env == ENV_TP_P;
         __m256i rgb, a;
         if (rgb_t)
            rgb = _mm256_and_si256(texel, _mm256_set1_epi32(0xffffff));
         else
            rgb = _mm256_or_si256(
               _mm256_or_si256(unorm8(_mm256_mul_ps(tf[0], pc[0])),
                               _mm256_slli_epi32(unorm8(_mm256_mul_ps(tf[1], pc[1])), 8)),
               _mm256_slli_epi32(unorm8(_mm256_mul_ps(tf[2], pc[2])), 16));
         if (a_p)
            a = _mm256_slli_epi32(unorm8(pc[3]), 24);
         else
            a = _mm256_slli_epi32(unorm8(_mm256_mul_ps(tf[3], pc[3])), 24);
         out = _mm256_or_si256(rgb, a);
      }
   }
   /* quad-major back to row-major (the swap of the middle 64-bit pairs is
    * its own inverse) */
   return _mm256_permute4x64_epi64(out, QUAD_ORDER);
}

/* the stage kills nothing and reads no buffer (a half's front kept for
 * the next half is a function of its position alone): the depth test may
 * come first and a half none of whose fragments passes it is not
 * textured (r_block_tri.h) */
#define BLOCK_STAGE_EARLY_Z 1
#include "r_block_tri.h"

#define TEX_KERNEL(name, env, zf, bl)                                                      \
   static void name(const struct r_state *rs, const struct r_tri_setup *ts,               \
                    const struct r_tri_cover *cv)                                          \
   {                                                                                       \
      tri_blocks(rs, ts, cv, env, zf, bl);                                                 \
   }

/* (depth writes or not: the same kernel, r_block_tri.h) */
#define TEX_KERNELS_ENV(p, env, bl)                                                        \
   TEX_KERNEL(p##_nz, env, ZF_NONE, bl)                                                   \
   TEX_KERNEL(p##_z16, env, ZF_16, bl)                                                    \
   TEX_KERNEL(p##_z24, env, ZF_24, bl)

#define TEX_KERNELS_BLEND(p, bl)                                                           \
   TEX_KERNELS_ENV(p##_args, ENV_ARGS, bl)                                                \
   TEX_KERNELS_ENV(p##_t_t, ENV_T_T, bl)                                                  \
   TEX_KERNELS_ENV(p##_t_p, ENV_T_P, bl)                                                  \
   TEX_KERNELS_ENV(p##_tp_tp, ENV_TP_TP, bl)                                              \
   TEX_KERNELS_ENV(p##_tp_p, ENV_TP_P, bl)                                                \
   TEX_KERNELS_ENV(p##_decal, ENV_DECAL, bl)

/* the trilinear REPEAT lookup with the texture environments of REPLACE
 * and MODULATE on RGB and RGBA textures */
#define TEX_KERNELS_BLEND_TRI(p, bl)                                                       \
   TEX_KERNELS_ENV(p##_tri_t_t, ENV_T_T | VAR_TRILINEAR, bl)                              \
   TEX_KERNELS_ENV(p##_tri_t_p, ENV_T_P | VAR_TRILINEAR, bl)                              \
   TEX_KERNELS_ENV(p##_tri_tp_tp, ENV_TP_TP | VAR_TRILINEAR, bl)                          \
   TEX_KERNELS_ENV(p##_tri_tp_p, ENV_TP_P | VAR_TRILINEAR, bl)

/* the same with the bilinear REPEAT lookup */
#define TEX_KERNELS_BLEND_BI(p, bl)                                                        \
   TEX_KERNELS_ENV(p##_bi_t_t, ENV_T_T | VAR_BILINEAR, bl)                                \
   TEX_KERNELS_ENV(p##_bi_t_p, ENV_T_P | VAR_BILINEAR, bl)                                \
   TEX_KERNELS_ENV(p##_bi_tp_tp, ENV_TP_TP | VAR_BILINEAR, bl)                            \
   TEX_KERNELS_ENV(p##_bi_tp_p, ENV_TP_P | VAR_BILINEAR, bl)

/* The kernels are compiled in three translation units, so that a build
 * spreads their compile time over its jobs (one unit held about half of
 * the library's kernel compile time): this file with R_BLOCK_TEX_PART 0
 * (the default) the general lookup's and the choice, and the wrappers
 * r_block_tex_tri_avx2.c (1) and r_block_tex_bi_avx2.c (2) the trilinear
 * and bilinear REPEAT lookups' four environments, each exported as a
 * table [blend][env - ENV_T_T][zfmt][zwrite] (hidden in the library;
 * the AVX-512 build renames them, libfixgl/meson.build). */
#ifndef R_BLOCK_TEX_PART
#define R_BLOCK_TEX_PART 0
#endif

#define ROW(p)                                                                             \
   { { p##_nz, p##_nz }, { p##_z16, p##_z16 }, { p##_z24, p##_z24 } }

typedef r_tri_kernel tex_env_table[2][4][3][2];
extern const tex_env_table r_block_tex_tables_tri, r_block_tex_tables_bi;

#if R_BLOCK_TEX_PART == 1
TEX_KERNELS_BLEND_TRI(opaque, BL_NONE)
TEX_KERNELS_BLEND_TRI(alpha, BL_ALPHA)
const tex_env_table r_block_tex_tables_tri = {
   { ROW(opaque_tri_t_t), ROW(opaque_tri_t_p), ROW(opaque_tri_tp_tp), ROW(opaque_tri_tp_p) },
   { ROW(alpha_tri_t_t), ROW(alpha_tri_t_p), ROW(alpha_tri_tp_tp), ROW(alpha_tri_tp_p) },
};
#elif R_BLOCK_TEX_PART == 2
TEX_KERNELS_BLEND_BI(opaque, BL_NONE)
TEX_KERNELS_BLEND_BI(alpha, BL_ALPHA)
const tex_env_table r_block_tex_tables_bi = {
   { ROW(opaque_bi_t_t), ROW(opaque_bi_t_p), ROW(opaque_bi_tp_tp), ROW(opaque_bi_tp_p) },
   { ROW(alpha_bi_t_t), ROW(alpha_bi_t_p), ROW(alpha_bi_tp_tp), ROW(alpha_bi_tp_p) },
};
#else
TEX_KERNELS_BLEND(opaque, BL_NONE)
TEX_KERNELS_BLEND(alpha, BL_ALPHA)

/* the general lookup's [blend][env][zfmt][zwrite]; the trilinear and
 * bilinear REPEAT lookups use theirs for ENV_T_T .. ENV_TP_P and these
 * for ENV_ARGS and ENV_DECAL */
static const r_tri_kernel tex_table[2][6][3][2] = {
   { ROW(opaque_args), ROW(opaque_t_t), ROW(opaque_t_p), ROW(opaque_tp_tp), ROW(opaque_tp_p),
     ROW(opaque_decal) },
   { ROW(alpha_args), ROW(alpha_t_t), ROW(alpha_t_p), ROW(alpha_tp_tp), ROW(alpha_tp_p),
     ROW(alpha_decal) },
};

/* the form of a group of channels (r_tex_combine.simple_fn_*): 0 T,
 * 1 P, 2 TP (or PT), -1 other */
static int env_form(int fn)
{
   switch (fn) {
   case R_SIMPLE_FN_T:  return 0;
   case R_SIMPLE_FN_P:  return 1;
   case R_SIMPLE_FN_TP:
   case R_SIMPLE_FN_PT: return 2;
   default:             return -1;
   }
}

/* GL_DECAL's combiner on an RGBA texture (state.c update_combine) */
static bool is_decal_rgba(const struct r_tex_combine *k)
{
   return k->mode_rgb == R_COMB_INTERPOLATE && k->mode_a == R_COMB_REPLACE && k->shift_rgb == 0 &&
          k->shift_a == 0 && k->nargs_rgb == 3 && k->src_rgb[0] == R_SRC_TEXTURE &&
          k->opr_rgb[0] == R_OPR_COLOR && k->src_rgb[1] == R_SRC_PREVIOUS &&
          k->opr_rgb[1] == R_OPR_COLOR && k->src_rgb[2] == R_SRC_TEXTURE &&
          k->opr_rgb[2] == R_OPR_ALPHA && k->nargs_a == 1 && k->src_a[0] == R_SRC_PREVIOUS &&
          k->opr_a[0] == R_OPR_ALPHA;
}

r_tri_kernel r_block_choose_tri_tex(const struct r_state *rs, bool flat_color)
{
   (void)flat_color;   /* read per triangle */
   if (rs->fs->tex_nr >= 2)
      return r_block_choose_tri_mtex(rs, flat_color);   /* r_block_mtex_avx2.c */
   /* the fragment program: the colour and unit 0's coordinates, unit 0
    * alone, its lookup in r_tex_avx2.h, a simple environment; no colour
    * sum, fog, GL_PHONG_WIN, pixel rectangle, coverage lowering or
    * stipple */
   if (rs->fs->fs_inputs != (1u << R_FS_COLOR0 | 1u << R_FS_TEX0) || rs->fs->tex_units != 1u ||
       rs->fs->tex_nr != 1 || rs->fs->color_sum || rs->fs->fog_mode != R_FOG_NONE || rs->fs->phong || rs->pix ||
       rs->fs->aa != R_AA_NONE || rs->rast->stipple || !rs->fb->color)
      return NULL;
   const struct r_texture *t = &rs->tex[0]->tex;
   const struct r_tex_combine *k = &rs->tex[0]->comb;
   if (!r_tex8_fast(t) || !(k->simple || is_decal_rgba(k)))
      return NULL;
   enum blend bl;
   enum zfmt zf;
   if (!block_simple_ops(rs, &bl, &zf))
      return NULL;
   /* the forms with a kernel of their own, else by the arguments */
   static const int8_t forms[3][3] = {
      /* rgb T */  { ENV_T_T, ENV_T_P, -1 },
      /* rgb P */  { -1, -1, -1 },   /* (ALPHA textures: by the arguments) */
      /* rgb TP */ { -1, ENV_TP_P, ENV_TP_TP },
   };
   const int fr = env_form(k->simple_fn_rgb), fa = env_form(k->simple_fn_a);
   int env = ENV_ARGS;
   if (!k->simple)
      env = ENV_DECAL;
   else if (fr >= 0 && fa >= 0 && forms[fr][fa] >= 0)
      env = forms[fr][fa];
   const int lookup = tex8_is_trilinear_repeat(t) ? 1 : tex8_is_bilinear(t, R_WRAP_REPEAT) ? 2 : 0;
   const int zw = rs->dsa->depth_write;
   if (lookup != 0 && env >= ENV_T_T && env <= ENV_TP_P)
      return (lookup == 1 ? r_block_tex_tables_tri
                          : r_block_tex_tables_bi)[bl][env - ENV_T_T][zf][zw];
   return tex_table[bl][env][zf][zw];
}
#endif
