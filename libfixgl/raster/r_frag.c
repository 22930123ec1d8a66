/*
 * The fragment stage shared by triangles, lines and points: the
 * fixed-function fragment program (r_fragment_shader) and the per-fragment
 * operations in the specification's order (r_fragment_ops), with the
 * oracle's conversions (ORACLE-NOTES.md "Colour conversion", "Depth
 * conversion and polygon offset", "Blending, alpha test, dithering").
 *
 * Primitives hand every covered pixel here with its interpolated depth and
 * fragment-shader inputs; nothing in this file knows which primitive a
 * fragment came from.
 */
#include "r_state.h"
#include "r_blend.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "math/m_gallivm.h"

uint8_t r_float_to_unorm8(float c)
{
   /* RNE(min(c, 1) * 255) with a saturating pack: negative and NaN give 0. */
   if (!(c > 0.0f))
      return 0;
   if (c > 1.0f)
      c = 1.0f;
   return (uint8_t)r_round_even(c * 255.0f);
}

/* The fragment shader restricts depth to [0,1] (lp_build_depth_clamp),
 * then converts with RNE (ORACLE-NOTES.md "Depth conversion and polygon
 * offset"). */
uint32_t r_depth_to_z24(float z)
{
   return (uint32_t)r_round_even(r_clamp01(z) * 16777215.0f);
}

uint16_t r_depth_to_z16(float z)
{
   return (uint16_t)r_round_even(r_clamp01(z) * 65535.0f);
}

/* A 32-bit unorm has more bits than a float's mantissa
 * [S: gallivm/lp_bld_conv.c:lp_build_clamped_float_to_unsigned_norm, its
 * last case]: z * 2^31 (exact) truncated to an integer t, then
 * (t << 1) - (t >> 31), which maps 1.0 (t = 2^31) to 0xffffffff
 * (ORACLE-NOTES.md "Depth sizes"). */
uint32_t r_depth_to_z32(float z)
{
   const uint32_t t = (uint32_t)(r_clamp01(z) * 2147483648.0f);
   return (t << 1) - (t >> 31);
}

/* R_COMPARE, compare: r_blend.h */

static bool compare_float(enum r_func func, float a, float b)
{
   R_COMPARE(func, a, b)
}

/* The fog factor of the fixed-function fragment program from the
 * interpolated fog coordinate fc, with the CPU-precomputed
 * STATE_FOG_PARAMS_OPTIMIZED p (ff_fragment_shader.cpp
 * emit_fog_instructions, as NIR hands it to gallivm: llvmpipe lowers ffma
 * and fsat, so every op is rounded on its own):
 *   LINEAR  fc * p[0] + p[1]             (fmul, fadd)
 *   EXP     exp2(-(fc * p[2]))
 *   EXP2    t = fc * p[3]; exp2(-(t * t))
 * exp2 is gallivm's approximation (lp_build_exp2), then fsat lowered to
 * fmin(fmax(f, 0), 1), where gallivm's fmax returns the other operand for
 * NaN (lp_bld_nir.c: GALLIVM_NAN_RETURN_OTHER): a NaN factor is 0. */
static float fog_factor(const struct r_state *rs, float fc)
{
   const float *p = rs->fs->fog_params;
   float f;
   switch (rs->fs->fog_mode) {
   case R_FOG_LINEAR:
      f = fc * p[0] + p[1];
      break;
   case R_FOG_EXP:
      f = m_gallivm_exp2(-(fc * p[2]));
      break;
   case R_FOG_EXP2:
   default: {
      const float t = fc * p[3];
      f = m_gallivm_exp2(-(t * t));
      break;
   }
   }
   f = f > 0.0f ? f : 0.0f;   /* fmax(f, 0): NaN -> 0 */
   return f < 1.0f ? f : 1.0f;
}

/* stencil_op: r_blend.h */

/* mul_u8, blend_channel, logic_op: r_blend.h (the block kernels share them) */

/* nir fsat as llvmpipe lowers it, fmin(fmax(x, 0), 1) with gallivm's
 * NaN-returns-the-other-operand min/max: NaN gives 0 */
static inline float fsat(float x)
{
   x = x > 0.0f ? x : 0.0f;
   return x < 1.0f ? x : 1.0f;
}

/* The texture colours of the fragment program, looked up when a combiner
 * first reads them (ff_fragment_shader.cpp load_texture: a projective
 * lookup, coord * frcp(q); a GL_TEXTUREn source of a unit without a
 * texture reads 0). */
struct tex_cache {
   unsigned have;
   float c[R_MAX_TEX_UNITS][4];
   const struct r_tex_lod *lod;   /* the quad's LOD per unit, or NULL */
   /* NIR's reassociation across units: the channels (bit c) of the
    * previous unit's result that are an unsaturated sum of two products
    * p0 + p1 (a generic INTERPOLATE), with the products; cur_*: the same
    * of the unit being emitted (emit_combine's R_COMB_ADD reads prev_*) */
   unsigned prev_sum, cur_sum;
   float prev_p[4][2], cur_p[4][2];
};

static const float *tex_color(const struct r_state *rs, const float in[][4],
                              const struct r_fs_quad *quad, struct tex_cache *tc, int u)
{
   if (tc->have & (1u << u))
      return tc->c[u];
   tc->have |= 1u << u;
   if (!(rs->fs->tex_units & (1u << u))) {
      tc->c[u][0] = tc->c[u][1] = tc->c[u][2] = tc->c[u][3] = 0.0f;   /* dummy_tex */
      return tc->c[u];
   }
   const struct r_texture *t = &rs->tex[u]->tex;
   const float *tcin = in[R_FS_TEX0 + u];
   /* vec2 coord * frcp(q): the reciprocal is a true divide in gallivm */
   const float rq = 1.0f / tcin[3];
   const float c[3] = { tcin[0] * rq, tcin[1] * rq, tcin[2] * rq };
   if (tc->lod && !t->soa) {
      /* the quad's LOD, selected once for the quad (r_tex_lod_aos) */
      const struct r_tex_lod *l = &tc->lod[u];
      r_tex_filter_aos(t, c, l->minify, l->level0, l->level1, l->weight, tc->c[u]);
      return tc->c[u];
   }
   float qc[3][3];
   for (int i = 0; i < 3; i++) {
      const float *v = quad->tex[u][i];
      const float r = 1.0f / v[3];
      qc[i][0] = v[0] * r;
      qc[i][1] = v[1] * r;
      qc[i][2] = v[2] * r;
   }
   float pc[3][3];
   const bool pair = r_tex_need_pair(t);
   for (int i = 0; pair && i < 3; i++) {
      const float *v = quad->pair[u][i];
      const float r = 1.0f / v[3];
      pc[i][0] = v[0] * r;
      pc[i][1] = v[1] * r;
      pc[i][2] = v[2] * r;
   }
   if (t->cube) {
      /* a cube map: the whole quad (a LOD per pixel), and the pair's */
      float q4[4][3], p4[4][3];
      memcpy(q4, qc, sizeof(qc));
      r_tex_project(quad->br[u], q4[3]);
      if (pair) {
         memcpy(p4, pc, sizeof(pc));
         r_tex_project(quad->pair_br[u], p4[3]);
      }
      r_tex_sample_cube(t, c, (const float (*)[3])q4, quad->pos,
                        pair ? (const float (*)[3])p4 : NULL, tc->c[u]);
      return tc->c[u];
   }
   r_tex_sample(t, c, (const float (*)[3])qc, pair ? (const float (*)[3])pc : NULL, tc->c[u]);
   return tc->c[u];
}

/* One combiner argument, all four channels
 * [S: ff_fragment_shader.cpp:get_source, emit_combine_source]: 1 - x is
 * an fadd of 1 and -x, which equals the float subtraction. */
static void comb_arg(const struct r_state *rs, const float in[][4], const struct r_fs_quad *quad,
                     struct tex_cache *tc, int unit, const float prev[4],
                     int src, int opr, float v[4], float raw[4])
{
   const float *s;
   float konst[4];
   switch (src) {
   case R_SRC_TEXTURE:        s = tex_color(rs, in, quad, tc, unit); break;
   case R_SRC_PREVIOUS:       s = prev; break;
   case R_SRC_PRIMARY_COLOR:  s = in[R_FS_COLOR0]; break;
   case R_SRC_CONSTANT:       s = rs->tex[unit]->env_color; break;
   case R_SRC_ZERO:
   case R_SRC_ONE:
      konst[0] = konst[1] = konst[2] = konst[3] = src == R_SRC_ONE ? 1.0f : 0.0f;
      s = konst;
      break;
   default:                   s = tex_color(rs, in, quad, tc, src - R_SRC_TEXTURE0); break;
   }
   for (int c = 0; c < 4; c++) {
      raw[c] = opr == R_OPR_COLOR || opr == R_OPR_ONE_MINUS_COLOR ? s[c] : s[3];
      switch (opr) {
      case R_OPR_COLOR:           v[c] = s[c]; break;
      case R_OPR_ONE_MINUS_COLOR: v[c] = 1.0f - s[c]; break;
      case R_OPR_ALPHA:           v[c] = s[3]; break;
      case R_OPR_ONE_MINUS_ALPHA:
      default:                    v[c] = 1.0f - s[3]; break;
      }
   }
}

static bool comb_need_saturate(int mode)
{
   return !(mode == R_COMB_REPLACE || mode == R_COMB_MODULATE || mode == R_COMB_INTERPOLATE);
}

static bool is_one_minus(int opr)
{
   return opr == R_OPR_ONE_MINUS_COLOR || opr == R_OPR_ONE_MINUS_ALPHA;
}

/* Which value an argument's channel c is in the compiled shader (NIR's CSE
 * merges equal expressions, and nir_opt_algebraic then factors
 * a*b + a*c into a*(b + c)): its source (the unit's own texture is its
 * GL_TEXTUREn; the first unit's PREVIOUS is the primary colour, the same
 * gl_Color load), whether it is 1 - x and the component read.  GL_ZERO and
 * GL_ONE fold away first: -1, never equal. */
static int arg_key(int src, bool one_minus, bool alpha, int c, int unit, bool prev_is_primary)
{
   if (src == R_SRC_ZERO || src == R_SRC_ONE)
      return -1;
   if (src == R_SRC_TEXTURE)
      src = R_SRC_TEXTURE0 + unit;
   if (src == R_SRC_PREVIOUS && prev_is_primary)
      src = R_SRC_PRIMARY_COLOR;
   return src * 16 + (one_minus ? 8 : 0) + (alpha ? 3 : c);
}

static inline bool same_key(int a, int b)
{
   return a >= 0 && a == b;
}

/* emit_combine for channels [c0, c1) [S: ff_fragment_shader.cpp:
 * emit_combine], as NIR optimizes it before llvmpipe compiles it (every op
 * rounded on its own: llvmpipe lowers ffma; ST_DEBUG=nir shows the
 * reassociations nir_opt_algebraic makes, noted below). */
static void emit_combine(const struct r_state *rs, const float in[][4],
                         const struct r_fs_quad *quad, struct tex_cache *tc, int unit,
                         const float prev[4], bool prev_is_primary, int nargs, int mode,
                         const uint8_t *src, const uint8_t *opr, int c0, int c1, float res[4])
{
   /* a: the arguments; x: their sources before a 1 - x operand */
   float a[4][4], x4[4][4];
   for (int i = 0; i < nargs; i++)
      comb_arg(rs, in, quad, tc, unit, prev, src[i], opr[i], a[i], x4[i]);
   switch (mode) {
   case R_COMB_DOT3_RGB:
   case R_COMB_DOT3_RGBA:
   case R_COMB_DOT3_RGB_EXT:
   case R_COMB_DOT3_RGBA_EXT: {
      /* (a*2 + -1) . (b*2 + -1) over xyz, smeared; fdot3 is reduced
       * from the last component: (z*z' + y*y') + x*x' */
      float x[3], y[3];
      for (int k = 0; k < 3; k++) {
         x[k] = a[0][k] * 2.0f + -1.0f;
         y[k] = a[1][k] * 2.0f + -1.0f;
      }
      const float d = (x[2] * y[2] + x[1] * y[1]) + x[0] * y[0];
      for (int c = c0; c < c1; c++)
         res[c] = d;
      return;
   }
   default:
      break;
   }
   for (int c = c0; c < c1; c++) {
      float r;
      int key[4] = { -1, -1, -1, -1 };
      if (mode == R_COMB_INTERPOLATE || mode == R_COMB_ADD_PRODUCTS_NV ||
          mode == R_COMB_ADD_PRODUCTS_SIGNED_NV) {
         for (int i = 0; i < nargs; i++)
            key[i] = arg_key(src[i], is_one_minus(opr[i]),
                             opr[i] == R_OPR_ALPHA || opr[i] == R_OPR_ONE_MINUS_ALPHA, c,
                             unit, prev_is_primary);
      }
      switch (mode) {
      case R_COMB_REPLACE:
         r = a[0][c];
         break;
      case R_COMB_MODULATE:
         r = a[0][c] * a[1][c];
         break;
      case R_COMB_ADD: {
         /* the previous unit's unsaturated p0 + p1 plus an argument that
          * is no product (a texel, a colour, the constant) becomes
          * (p0 + a) + p1 (nir_opt_algebraic moves the product out of the
          * inner fadd: ST_DEBUG=nir of GL_DECAL then GL_ADD) */
         const int pi = src[0] == R_SRC_PREVIOUS && opr[0] == R_OPR_COLOR ? 0
                      : src[1] == R_SRC_PREVIOUS && opr[1] == R_OPR_COLOR ? 1 : -1;
         const int o = 1 - pi;
         if (pi >= 0 && ((tc->prev_sum >> c) & 1u) && src[o] != R_SRC_PREVIOUS &&
             src[o] != R_SRC_ZERO && src[o] != R_SRC_ONE &&
             (opr[o] == R_OPR_COLOR || opr[o] == R_OPR_ALPHA))
            r = (tc->prev_p[c][0] + a[o][c]) + tc->prev_p[c][1];
         else
            r = a[0][c] + a[1][c];
         break;
      }
      case R_COMB_ADD_SIGNED:
         /* (a0 + a1) + -0.5 becomes (a0 + -0.5) + a1 (nir_opt_algebraic
          * "Prefer moving out a multiplication": (a + b) + #c ->
          * (a + c) + b); with a0 = 1 - x the constants fold,
          * -0.5 + (1 + -x) -> 0.5 + -x; a1 = 1 - x stays unfolded (both
          * checked against the oracle's float output; GL_ZERO/GL_ONE
          * arguments fold to the same values) */
         if (is_one_minus(opr[0]) && src[0] != R_SRC_ZERO && src[0] != R_SRC_ONE)
            r = (0.5f + -x4[0][c]) + a[1][c];
         else
            r = (a[0][c] + -0.5f) + a[1][c];
         break;
      case R_COMB_INTERPOLATE: {
         /* a0*a2 + a1*b, b = 1 - a2; with a2 = 1 - x, b = 1 - (1 - x)
          * folds to x (nir_opt_algebraic: a + -(a + b) -> -b); a common
          * factor of the two products is taken out, a*b + a*c ->
          * a*(b + c) (all checked against the oracle's float output) */
         const float b = is_one_minus(opr[2]) && key[2] >= 0 ? x4[2][c] : 1.0f - a[2][c];
         const int kb = key[2] >= 0 ? (key[2] ^ 8) : -1;
         if (same_key(key[0], key[1]))
            r = a[0][c] * (a[2][c] + b);
         else if (same_key(key[0], kb))
            r = a[0][c] * (a[2][c] + a[1][c]);
         else if (same_key(key[2], key[1]))
            r = a[2][c] * (a[0][c] + b);
         else {
            tc->cur_p[c][0] = a[0][c] * a[2][c];
            tc->cur_p[c][1] = a[1][c] * b;
            tc->cur_sum |= 1u << c;
            r = tc->cur_p[c][0] + tc->cur_p[c][1];
         }
         break;
      }
      case R_COMB_SUBTRACT:
         r = a[0][c] - a[1][c];
         break;
      case R_COMB_MODULATE_ADD_ATI:
         r = a[0][c] * a[2][c] + a[1][c];
         break;
      case R_COMB_MODULATE_SIGNED_ADD_ATI:
         /* (a0*a2 + a1) + -0.5 -> (a1 + -0.5) + a0*a2, with a1 = 1 - x
          * folded to (0.5 + -x) + a0*a2 as for ADD_SIGNED */
         if (is_one_minus(opr[1]) && src[1] != R_SRC_ZERO && src[1] != R_SRC_ONE)
            r = (0.5f + -x4[1][c]) + a[0][c] * a[2][c];
         else
            r = (a[1][c] + -0.5f) + a[0][c] * a[2][c];
         break;
      case R_COMB_MODULATE_SUBTRACT_ATI:
         r = a[0][c] * a[2][c] - a[1][c];
         break;
      case R_COMB_ADD_PRODUCTS_NV:
      case R_COMB_ADD_PRODUCTS_SIGNED_NV:
      default: {
         /* a0*a1 + a2*a3, a common factor taken out first; the signed
          * form adds -0.5 to the first product, (p0 + -0.5) + p1, unless
          * factored */
         const float *f = NULL;
         float u = 0.0f, v = 0.0f;
         if (same_key(key[0], key[2])) { f = a[0]; u = a[1][c]; v = a[3][c]; }
         else if (same_key(key[0], key[3])) { f = a[0]; u = a[1][c]; v = a[2][c]; }
         else if (same_key(key[1], key[2])) { f = a[1]; u = a[0][c]; v = a[3][c]; }
         else if (same_key(key[1], key[3])) { f = a[1]; u = a[0][c]; v = a[2][c]; }
         if (f) {
            r = f[c] * (u + v);
            if (mode == R_COMB_ADD_PRODUCTS_SIGNED_NV)
               r = r + -0.5f;
         } else if (mode == R_COMB_ADD_PRODUCTS_SIGNED_NV) {
            r = (a[0][c] * a[1][c] + -0.5f) + a[2][c] * a[3][c];
         } else {
            r = a[0][c] * a[1][c] + a[2][c] * a[3][c];
         }
         break;
      }
      }
      res[c] = r;
   }
}

/* Whether the RGB and alpha arguments match [S: ff_fragment_shader.cpp:
 * args_match]. */
static bool args_match(const struct r_tex_combine *k)
{
   for (int i = 0; i < k->nargs_rgb; i++) {
      if (k->src_a[i] != k->src_rgb[i])
         return false;
      switch (k->opr_a[i]) {
      case R_OPR_ALPHA:
         if (k->opr_rgb[i] != R_OPR_COLOR && k->opr_rgb[i] != R_OPR_ALPHA)
            return false;
         break;
      case R_OPR_ONE_MINUS_ALPHA:
         if (k->opr_rgb[i] != R_OPR_ONE_MINUS_COLOR && k->opr_rgb[i] != R_OPR_ONE_MINUS_ALPHA)
            return false;
         break;
      default:
         return false;
      }
   }
   return true;
}

/* One unit's environment [S: ff_fragment_shader.cpp:emit_texenv]. */
static void emit_texenv(const struct r_state *rs, const float in[][4],
                        const struct r_fs_quad *quad, struct tex_cache *tc, int unit,
                        const float prev[4], bool first, float res[4])
{
   const struct r_tex_combine *k = &rs->tex[unit]->comb;
   unsigned rgb_shift = k->shift_rgb, alpha_shift = k->shift_a;
   if (k->mode_rgb == R_COMB_DOT3_RGB_EXT) {
      rgb_shift = 0;
   } else if (k->mode_rgb == R_COMB_DOT3_RGBA_EXT) {
      rgb_shift = 0;
      alpha_shift = 0;
   }
   const bool rgb_sat = !rgb_shift && comb_need_saturate(k->mode_rgb);
   const bool alpha_sat = !alpha_shift && comb_need_saturate(k->mode_a);

   if (k->mode_rgb == k->mode_a && args_match(k)) {
      emit_combine(rs, in, quad, tc, unit, prev, first, k->nargs_rgb, k->mode_rgb,
                   k->src_rgb, k->opr_rgb, 0, 4, res);
      if (rgb_sat)
         for (int c = 0; c < 4; c++)
            res[c] = fsat(res[c]);
   } else if (k->mode_rgb == R_COMB_DOT3_RGBA || k->mode_rgb == R_COMB_DOT3_RGBA_EXT) {
      emit_combine(rs, in, quad, tc, unit, prev, first, k->nargs_rgb, k->mode_rgb,
                   k->src_rgb, k->opr_rgb, 0, 4, res);
      if (rgb_sat)
         for (int c = 0; c < 4; c++)
            res[c] = fsat(res[c]);
   } else {
      emit_combine(rs, in, quad, tc, unit, prev, first, k->nargs_rgb, k->mode_rgb,
                   k->src_rgb, k->opr_rgb, 0, 3, res);
      if (rgb_sat)
         for (int c = 0; c < 3; c++)
            res[c] = fsat(res[c]);
      emit_combine(rs, in, quad, tc, unit, prev, first, k->nargs_a, k->mode_a,
                   k->src_a, k->opr_a, 3, 4, res);
      if (alpha_sat)
         res[3] = fsat(res[3]);
   }
   /* the final shift: saturate(val * (2^rgb_shift, ..., 2^alpha_shift)),
    * on every channel once either shift is set (a factor 1 is dropped) */
   if (rgb_shift || alpha_shift) {
      tc->cur_sum = 0;   /* scaled and saturated: no sum left */
      for (int c = 0; c < 4; c++) {
         const unsigned sh = c < 3 ? rgb_shift : alpha_shift;
         res[c] = fsat(sh ? res[c] * (float)(1u << sh) : res[c]);
      }
   }
}

/* A unit's environment as r_tex_combine_simplify records it: emit_texenv
 * without saturation, scale or NIR's rewrites (REPLACE and MODULATE have
 * none), each channel one argument or a product of two, the argument
 * read as comb_arg reads it: s[c] (COLOR) or s[3] (ALPHA), or 1 - that.
 * Channel 3 is the alpha combiner's: with mode_rgb == mode_a and
 * args_match emit_texenv computes it with the RGB arguments, which then
 * read the same values. */
static bool simple_arg(int src, int opr, int unit, int c, uint8_t *arg)
{
   int s;
   switch (src) {
   case R_SRC_TEXTURE:       s = R_SIMPLE_TEXTURE; break;
   case R_SRC_PREVIOUS:      s = R_SIMPLE_PREVIOUS; break;
   case R_SRC_PRIMARY_COLOR: s = R_SIMPLE_PRIMARY; break;
   case R_SRC_CONSTANT:      s = R_SIMPLE_CONSTANT; break;
   case R_SRC_ZERO:          s = R_SIMPLE_ZERO; break;
   case R_SRC_ONE:           s = R_SIMPLE_ONE; break;
   default:
      if (src != R_SRC_TEXTURE0 + unit)
         return false;   /* another unit's texture */
      s = R_SIMPLE_TEXTURE;
      break;
   }
   const bool alpha = opr == R_OPR_ALPHA || opr == R_OPR_ONE_MINUS_ALPHA;
   *arg = (uint8_t)(s * 8 + (is_one_minus(opr) ? 4 : 0) + (alpha ? 3 : c));
   return true;
}

void r_tex_combine_simplify(struct r_tex_combine *k, int unit)
{
   k->simple = false;
   if (k->shift_rgb || k->shift_a)
      return;
   for (int c = 0; c < 4; c++) {
      const int mode = c < 3 ? k->mode_rgb : k->mode_a;
      const uint8_t *src = c < 3 ? k->src_rgb : k->src_a;
      const uint8_t *opr = c < 3 ? k->opr_rgb : k->opr_a;
      if (mode != R_COMB_REPLACE && mode != R_COMB_MODULATE)
         return;
      k->simple_nargs[c] = mode == R_COMB_REPLACE ? 1 : 2;
      for (int i = 0; i < k->simple_nargs[c]; i++)
         if (!simple_arg(src[i], opr[i], unit, c, &k->simple_arg[c][i]))
            return;
   }
   k->simple = true;
   /* the common forms */
   for (int g = 0; g < 2; g++) {
      const int c0 = g ? 3 : 0, c1 = g ? 4 : 3;
      int fn = -1;
      for (int c = c0; c < c1; c++) {
         const uint8_t *a = k->simple_arg[c];
         const int t = R_SIMPLE_TEXTURE * 8 + c, p = R_SIMPLE_PREVIOUS * 8 + c;
         int f = R_SIMPLE_FN_ARGS;
         if (k->simple_nargs[c] == 1)
            f = a[0] == t ? R_SIMPLE_FN_T : a[0] == p ? R_SIMPLE_FN_P : R_SIMPLE_FN_ARGS;
         else if (a[0] == t && a[1] == p)
            f = R_SIMPLE_FN_TP;
         else if (a[0] == p && a[1] == t)
            f = R_SIMPLE_FN_PT;
         fn = fn < 0 || fn == f ? f : R_SIMPLE_FN_ARGS;
      }
      if (g)
         k->simple_fn_a = (uint8_t)fn;
      else
         k->simple_fn_rgb = (uint8_t)fn;
   }
}

static inline __attribute__((always_inline)) void
simple_fn(int fn, const float t[4], const float p[4], int c0, int c1, float res[4])
{
   for (int c = c0; c < c1; c++) {
      switch (fn) {
      case R_SIMPLE_FN_T:  res[c] = t[c]; break;
      case R_SIMPLE_FN_P:  res[c] = p[c]; break;
      case R_SIMPLE_FN_TP: res[c] = t[c] * p[c]; break;
      case R_SIMPLE_FN_PT:
      default:             res[c] = p[c] * t[c]; break;
      }
   }
}

/* emit_texenv of a unit with comb.simple set. */
static void simple_texenv(const struct r_state *rs, const float in[][4],
                          const struct r_fs_quad *quad, struct tex_cache *tc, int unit,
                          const float prev[4], float res[4])
{
   static const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
   static const float one[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
   const struct r_tex_combine *k = &rs->tex[unit]->comb;
   if (k->simple_fn_rgb != R_SIMPLE_FN_ARGS && k->simple_fn_a != R_SIMPLE_FN_ARGS) {
      const float *t = tex_color(rs, in, quad, tc, unit);
      simple_fn(k->simple_fn_rgb, t, prev, 0, 3, res);
      simple_fn(k->simple_fn_a, t, prev, 3, 4, res);
      return;
   }
   const float *srcs[6] = { NULL, prev, in[R_FS_COLOR0], rs->tex[unit]->env_color, zero, one };
   for (int c = 0; c < 4; c++) {
      float v[2];
      for (int i = 0; i < k->simple_nargs[c]; i++) {
         const int a = k->simple_arg[c][i];
         if (!srcs[a >> 3])
            srcs[R_SIMPLE_TEXTURE] = tex_color(rs, in, quad, tc, unit);
         v[i] = srcs[a >> 3][a & 3];
         if (a & 4)
            v[i] = 1.0f - v[i];
      }
      res[c] = k->simple_nargs[c] == 1 ? v[0] : v[0] * v[1];
   }
}

/* The texture environments of the enabled units in order, each on the
 * previous one's result, the first on the fragment colour
 * (ff_fragment_shader.cpp emit_instructions); kept out of line so the
 * untextured fragment program stays small. */
static __attribute__((noinline)) void texture_units(const struct r_state *rs, const float in[][4],
                                                    const struct r_fs_quad *quad,
                                                    const struct r_tex_lod *lod, float out[4])
{
   struct tex_cache tc;
   tc.have = 0;
   tc.lod = lod;
   tc.cur_sum = 0;
   float prev[4], res[4];
   bool first = true;   /* PREVIOUS is still the primary colour */
   for (int c = 0; c < 4; c++)
      prev[c] = in[R_FS_COLOR0][c];
   for (int u = 0; u < rs->fs->tex_nr; u++) {
      if (!(rs->fs->tex_units & (1u << u)))
         continue;
      tc.prev_sum = tc.cur_sum;
      if (tc.cur_sum)
         memcpy(tc.prev_p, tc.cur_p, sizeof(tc.prev_p));
      tc.cur_sum = 0;
      if (rs->tex[u]->comb.simple)
         simple_texenv(rs, in, quad, &tc, u, prev, res);
      else
         emit_texenv(rs, in, quad, &tc, u, prev, first, res);
      first = false;
      for (int c = 0; c < 4; c++)
         prev[c] = res[c];
   }
   for (int c = 0; c < 4; c++)
      out[c] = prev[c];
}

static inline __attribute__((always_inline)) void
fragment_shader(const struct r_state *rs, const float in[][4], const struct r_fs_quad *quad,
                const struct r_tex_lod *lod, float out[4])
{
   if (rs->fs->tex_units) {
      texture_units(rs, in, quad, lod, out);
   } else {
      for (int c = 0; c < 4; c++)
         out[c] = in[R_FS_COLOR0][c];
   }
   /* the secondary colour's rgb with separate specular
    * (ff_fragment_shader.cpp emit_instructions: rgb += spec.rgb) */
   if (rs->fs->color_sum) {
      for (int c = 0; c < 3; c++)
         out[c] = out[c] + in[R_FS_COLOR1][c];
   }
   /* then fog on rgb (emit_fog_instructions): fogcolor * (1 - f) + rgb * f,
    * two fmuls and an fadd (lower_flrp keeps NIR from forming a lerp);
    * alpha passes */
   if (rs->fs->fog_mode != R_FOG_NONE) {
      const float f = fog_factor(rs, in[R_FS_FOG][0]);
      const float g = 1.0f + -f;
      for (int c = 0; c < 3; c++)
         out[c] = rs->fs->fog_color[c] * g + out[c] * f;
   }
}

/* GL_PHONG_WIN (include/fixgl/shading.md): the lighting equation at the
 * fragment, from its perspective-correctly interpolated normal and eye
 * position; the vertex colour (interpolated like them) is read only for
 * colour material.  The lit colours take the place of the interpolated
 * colour inputs, so texturing, the colour sum and fog follow unchanged.
 * The environment's point-independent values were prepared with it, once
 * per batch (fgl_update_shade_env). */
void r_fragment_phong(const struct r_state *rs, float in[][4], bool back)
{
   float primary[4], secondary[4];
   m_shade_point_prepared(rs->shade_env, in[R_FS_NORMAL], in[R_FS_EYEPOS], back, in[R_FS_COLOR0],
                    primary, secondary);
   for (int c = 0; c < 4; c++) {
      in[R_FS_COLOR0][c] = primary[c];
      in[R_FS_COLOR1][c] = secondary[c];
   }
}

void r_fragment_shader(const struct r_state *rs, const float in[][4],
                       const struct r_fs_quad *quad, float out[4])
{
   fragment_shader(rs, in, quad, NULL, out);
}

void r_fragment_shader_lod(const struct r_state *rs, const float in[][4],
                           const struct r_fs_quad *quad, const struct r_tex_lod *lod,
                           float out[4])
{
   fragment_shader(rs, in, quad, lod, out);
}

/* The depth test alone, with its write: the common path. */
static bool depth_test_write(const struct r_state *rs, size_t idx, float z)
{
   switch (rs->fb->zs_format) {
   case R_ZS_Z16: {
      uint16_t *zb = (uint16_t *)rs->fb->zs + idx;
      const uint16_t zv = r_depth_to_z16(z);
      if (!compare(rs->dsa->depth_func, zv, *zb))
         return false;
      if (rs->dsa->depth_write)
         *zb = zv;
      return true;
   }
   case R_ZS_Z24X8:
   case R_ZS_Z24S8: {
      uint32_t *zb = (uint32_t *)rs->fb->zs + idx;
      const uint32_t zv = r_depth_to_z24(z);
      if (!compare(rs->dsa->depth_func, zv, *zb & 0xffffffu))
         return false;
      if (rs->dsa->depth_write)
         *zb = (*zb & 0xff000000u) | zv;
      return true;
   }
   case R_ZS_Z32: {
      uint32_t *zb = (uint32_t *)rs->fb->zs + idx;
      const uint32_t zv = r_depth_to_z32(z);
      if (!compare(rs->dsa->depth_func, zv, *zb))
         return false;
      if (rs->dsa->depth_write)
         *zb = zv;
      return true;
   }
   default:
      return true; /* no depth buffer: the test always passes */
   }
}

/* Stencil test, depth test and their writes
 * [S: llvmpipe/lp_bld_depth.c:lp_build_depth_stencil_test]: the stencil
 * test compares (ref & valuemask) with (stencil & valuemask); a failing
 * fragment gets the fail op, a passing one zfail or zpass after the depth
 * test (zpass when the depth test is off); the new stencil value is merged
 * under the write mask. */
static bool stencil_depth_test(const struct r_state *rs, size_t idx, float z)
{
   uint8_t s;
   uint32_t *zs32 = NULL;
   if (rs->fb->zs_format == R_ZS_S8) {
      s = ((uint8_t *)rs->fb->zs)[idx];
   } else {
      zs32 = (uint32_t *)rs->fb->zs + idx;
      s = (uint8_t)(*zs32 >> 24);
   }

   const uint8_t vm = rs->dsa->stencil_valuemask;
   enum r_stencil_op op;
   bool pass = compare(rs->dsa->stencil_func, rs->dsa->stencil_ref & vm, s & vm);
   if (!pass) {
      op = rs->dsa->stencil_fail;
   } else if (rs->dsa->depth_test) {
      /* the depth buffer is this Z24S8 word */
      const uint32_t zv = r_depth_to_z24(z);
      pass = compare(rs->dsa->depth_func, zv, *zs32 & 0xffffffu);
      op = pass ? rs->dsa->stencil_zpass : rs->dsa->stencil_zfail;
      if (pass && rs->dsa->depth_write)
         *zs32 = (*zs32 & 0xff000000u) | zv;
   } else {
      op = rs->dsa->stencil_zpass;
   }

   const uint8_t wm = rs->dsa->stencil_writemask;
   const uint8_t ns = (uint8_t)((stencil_op(rs, op, s) & wm) | (s & (uint8_t)~wm));
   if (zs32)
      *zs32 = (*zs32 & 0xffffffu) | (uint32_t)ns << 24;
   else
      ((uint8_t *)rs->fb->zs)[idx] = ns;
   return pass;
}

/* ---- wide targets (r_fb_state.wide) ---------------------------------
 *
 * [S: llvmpipe/lp_state_fs.c:generate_unswizzled_blend,
 * lp_blend_type_from_format_desc; gallivm/lp_bld_blend.c:lp_build_blend]
 * the colour of a fragment that passed the tests, into an
 * R16G16B16A16_UNORM target: clamped (the shader's colour clamp), to
 * unorm16 by lp_build_clamped_float_to_unsigned_norm, blended in 16-bit
 * lanes (lp_build_mul_norm: t = a*b, (t + (t >> 16) + 0x8000) >> 16;
 * saturating add and subtract); into R32G32B32A32_FLOAT: unclamped (no
 * fragment colour clamp for a float buffer), blended on floats
 * (s * sf + d * df, unfused).  ORACLE-NOTES.md "OSMesa contexts and
 * buffers" (probe p_osmesa_wide). */
static inline unsigned mul_u16(unsigned a, unsigned b)
{
   const uint32_t t = a * b;
   return (t + (t >> 16) + 0x8000u) >> 16;
}

/* blend_factor of a wide target on floats, `one` its 1 (65535 for
 * unorm16: the channels are whole numbers up to 65535 there, exact in a
 * float, and so are one - x and the minimum) */
static float wide_factor(enum r_blend_factor f, int c, const float src[4], const float dst[4],
                         const float k[4], float one)
{
   switch (f) {
   case R_BF_ZERO:               return 0;
   case R_BF_ONE:                return one;
   case R_BF_SRC_COLOR:          return src[c];
   case R_BF_INV_SRC_COLOR:      return one - src[c];
   case R_BF_SRC_ALPHA:          return src[3];
   case R_BF_INV_SRC_ALPHA:      return one - src[3];
   case R_BF_DST_COLOR:          return dst[c];
   case R_BF_INV_DST_COLOR:      return one - dst[c];
   case R_BF_DST_ALPHA:          return dst[3];
   case R_BF_INV_DST_ALPHA:      return one - dst[3];
   case R_BF_SRC_ALPHA_SATURATE: return c == 3 ? one : src[3] < one - dst[3] ? src[3] : one - dst[3];
   case R_BF_CONST_COLOR:        return k[c];
   case R_BF_INV_CONST_COLOR:    return one - k[c];
   case R_BF_CONST_ALPHA:        return k[3];
   case R_BF_INV_CONST_ALPHA:    return one - k[3];
   default:                      return 0;
   }
}

static void wide_ops(const struct r_state *rs, size_t idx, const float color[4])
{
   const struct r_blend_state *b = rs->blend;
   if (rs->fb->wide_format == R_WIDE_UNORM16) {
      uint16_t *dst = (uint16_t *)rs->fb->wide + 4 * idx;
      unsigned s[4], d[4], out[4];
      float sf[4], df[4];   /* the same values for wide_factor */
      for (int c = 0; c < 4; c++) {
         s[c] = m_gallivm_float_to_unorm16(r_clamp01(color[c]));
         d[c] = dst[c];
      }
      if (b->dst_alpha_one)
         d[3] = 65535u;
      for (int c = 0; c < 4; c++) {
         sf[c] = (float)s[c];
         df[c] = (float)d[c];
      }
      for (int c = 0; c < 4; c++) {
         if (b->logic_op) {
            out[c] = r_logic_op_bits(b->logic_op_mode, s[c], d[c]) & 0xffffu;
            continue;
         }
         if (!b->enable) {
            out[c] = s[c];
            continue;
         }
         const bool a = c == 3 && b->separate_alpha;
         const float *k = b->blend_color_u16;
         const enum r_blend_factor fs = a ? b->blend_src_a : b->blend_src;
         const enum r_blend_factor fd = a ? b->blend_dst_a : b->blend_dst;
         const unsigned ts = mul_u16(s[c], (unsigned)wide_factor(fs, c, sf, df, k, 65535.0f));
         const unsigned td = mul_u16(d[c], (unsigned)wide_factor(fd, c, sf, df, k, 65535.0f));
         switch (a ? b->blend_eq_a : b->blend_eq) {
         case R_BLEND_SUBTRACT:         out[c] = ts > td ? ts - td : 0; break;
         case R_BLEND_REVERSE_SUBTRACT: out[c] = td > ts ? td - ts : 0; break;
         case R_BLEND_MIN:              out[c] = ts < td ? ts : td; break;
         case R_BLEND_MAX:              out[c] = ts > td ? ts : td; break;
         default:                       out[c] = ts + td > 65535u ? 65535u : ts + td; break;
         }
      }
      for (int c = 0; c < 4; c++)
         if (b->color_mask & (1u << c))
            dst[c] = (uint16_t)out[c];
      return;
   }
   float *dst = (float *)rs->fb->wide + 4 * idx;
   float d[4] = { dst[0], dst[1], dst[2], b->dst_alpha_one ? 1.0f : dst[3] };
   float out[4];
   for (int c = 0; c < 4; c++) {
      if (!b->enable || b->logic_op) {
         out[c] = color[c];   /* no logic op on a float target */
         continue;
      }
      const bool a = c == 3 && b->separate_alpha;
      const float ts = color[c] * wide_factor(a ? b->blend_src_a : b->blend_src, c, color, d,
                                              b->blend_color_f, 1.0f);
      const float td = d[c] * wide_factor(a ? b->blend_dst_a : b->blend_dst, c, color, d,
                                          b->blend_color_f, 1.0f);
      switch (a ? b->blend_eq_a : b->blend_eq) {
      case R_BLEND_SUBTRACT:         out[c] = ts - td; break;
      case R_BLEND_REVERSE_SUBTRACT: out[c] = td - ts; break;
      case R_BLEND_MIN:              out[c] = fminf(ts, td); break;
      case R_BLEND_MAX:              out[c] = fmaxf(ts, td); break;
      default:                       out[c] = ts + td; break;
      }
   }
   for (int c = 0; c < 4; c++)
      if (b->color_mask & (1u << c))
         dst[c] = out[c];
}

void r_fragment_ops(const struct r_state *rs, int px, int py, float z, const float color[4])
{
   const size_t idx = (size_t)py * (size_t)rs->fb->width + (size_t)px;
   uint8_t *dst = rs->fb->color + 4 * idx;

   if (!rs->full_ops) {
      if (rs->dsa->depth_test && !depth_test_write(rs, idx, z))
         return;
      if (rs->samples)
         rs->samples->n++;
      if (rs->fb->wide)
         wide_ops(rs, idx, color);
      dst[0] = r_float_to_unorm8(color[0]);
      dst[1] = r_float_to_unorm8(color[1]);
      dst[2] = r_float_to_unorm8(color[2]);
      dst[3] = r_float_to_unorm8(color[3]);
      return;
   }

   /* alpha test [S: llvmpipe/lp_bld_alpha.c:lp_build_alpha_test]: for
    * rgba8 buffers in their precision, alpha clamped (lp_build_clamp:
    * NaN -> 1) and converted like the colour, the reference likewise
    * (state.c); otherwise on floats, the alpha clamped by the shader's
    * colour clamp (st_program.c nir_lower_clamp_color_outputs) and the
    * reference as given, with lp_build_cmp's unordered compares (NaN
    * passes every function but NEVER) */
   if (rs->dsa->alpha_test) {
      if (rs->dsa->alpha_test_float) {
         const float a = r_clamp01(color[3]), ref = rs->dsa->alpha_ref_float;
         if (rs->dsa->alpha_func == R_NEVER ||
             (!isnan(ref) && !compare_float(rs->dsa->alpha_func, a, ref)))
            return;
      } else {
         const uint8_t a = (uint8_t)r_round_even(r_clamp01(color[3]) * 255.0f);
         if (!compare(rs->dsa->alpha_func, a, rs->dsa->alpha_ref))
            return;
      }
   }

   if (rs->dsa->stencil_test) {
      if (!stencil_depth_test(rs, idx, z))
         return;
   } else if (rs->dsa->depth_test && !depth_test_write(rs, idx, z)) {
      return;
   }
   /* a sample passed: the occlusion query counts it (llvmpipe's
    * lp_build_occlusion_count on the mask after the tests; the colour
    * mask, blending and the logic op do not matter) */
   if (rs->samples)
      rs->samples->n++;
   if (rs->fb->wide)
      wide_ops(rs, idx, color);

   /* blending or logic op on the colour converted to unorm8
    * [S: llvmpipe/lp_state_fs.c:generate_unswizzled_blend,
    * lp_bld_blend_aos.c:lp_build_blend_aos] */
   uint8_t src[4], out[4], d[4];
   for (int c = 0; c < 4; c++)
      src[c] = r_float_to_unorm8(color[c]);
   d[0] = dst[0];
   d[1] = dst[1];
   d[2] = dst[2];
   /* without alpha bits the destination alpha reads as one
    * (lp_state_fs.c make_variant_key: force_dst_alpha_one) */
   d[3] = rs->blend->dst_alpha_one ? 255 : dst[3];
   if (rs->blend->logic_op) {
      for (int c = 0; c < 4; c++)
         out[c] = logic_op(rs->blend->logic_op_mode, src[c], d[c]);
   } else if (rs->blend->enable) {
      for (int c = 0; c < 4; c++)
         out[c] = blend_channel(rs, c, src, d);
   } else {
      for (int c = 0; c < 4; c++)
         out[c] = src[c];
   }
   /* colour mask: a select between the result and the buffer */
   for (int c = 0; c < 4; c++) {
      if (rs->blend->color_mask & (1u << c))
         dst[c] = out[c];
   }
}
