/*
 * The block kernels of multi-textured triangles, AVX2 + FMA (r_kernel.h):
 * units 0 .. n-1 (2 <= n <= MTEX_MAX_UNITS, the counts the
 * kernel-equivalence tests draw) all enabled, each with a
 * texture the 8-lane lookup samples itself (r_tex8_fast) and an
 * environment whose channels are each one of (r_frag.c emit_texenv,
 * emit_combine, simple_texenv, without a scale):
 *   ARG   a0                 (REPLACE)
 *   MUL   a0 * a1            (MODULATE)
 *   ADD   a0 + a1, saturated (GL_ADD; after a unit whose channel is an
 *         INTERP, NIR's reassociation (p0 + a) + p1, as emit_combine)
 *   SUB   a0 - a1, saturated
 *   INTERP a0 * a2 + a1 * (1 - a2) with no common factor (GL_DECAL,
 *         GL_BLEND, COMBINE's INTERPOLATE without 1 - x as a2)
 * over the arguments TEXTURE (the unit's own), PREVIOUS, PRIMARY_COLOR,
 * CONSTANT, ZERO, ONE, any component, optionally 1 - x.  That is every
 * GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND and GL_ADD environment on
 * every base format, and the COMBINEs of those modes (GL_SUBTRACT too);
 * other units' textures as sources, DOT3, ADD_SIGNED, the ATI/NV modes,
 * RGB_SCALE/ALPHA_SCALE other than 1 draw with the reference kernels.
 *
 * Each lane does what the reference does for its pixel (r_tri.c
 * shade_pixel and fill_quad, r_frag.c texture_units): per unit, the
 * coordinates (plane * 1/w, projected by a true divide by q), the level
 * of detail of each 2x2 quad from its corners (r_tex_lod.h, as the
 * one-unit kernel r_block_tex_avx2.c), the lookup of r_tex_avx2.h
 * (r_tex_filter_aos bit for bit), texels as (float)b * (1/255); then the
 * environments in unit order on floats (PREVIOUS starts as the primary
 * colour), and the result to unorm8.
 *
 * What is known at validation is not tested per pixel: each unit's
 * lookup (the trilinear REPEAT one, the bilinear REPEAT or CLAMP_TO_EDGE
 * one, or the general one) and environment
 * (the common forms MODULATE, REPLACE, their RGB-texture variants, or
 * the general program) are functions chosen once per triangle
 * (block_stage_prepare) from the unit's state; the fragment operations
 * are the template's constants (r_block_tri.h).  The common two-unit
 * state, MODULATE on both (a lightmapped surface: base texture times
 * light map), has its own kernels with both environments inline.
 */
#include "r_block_avx2.h"
#include "r_tex_avx2.h"

#include <math.h>

#define MTEX_MAX_UNITS 4

/* the variants: any units (each through its functions), or two units
 * both MODULATE on a texture with alpha (T * P on every channel), or both
 * MODULATE on a texture without alpha (RGB, LUMINANCE: rgb T * P, alpha
 * P) */
enum { V_ANY, V_MOD2, V_MOD2_RGB };

/* the channel operations */
enum { OP_ARG, OP_MUL, OP_ADD, OP_ADD_RE, OP_SUB, OP_INTERP };
/* the argument sources (arg = src * 8 + 4 for 1 - x + component) */
enum { A_TEX, A_PREV, A_PRIM, A_CONST, A_ZERO, A_ONE };

struct chan_prog {
   uint8_t op, sat;
   uint8_t arg[3];
   uint8_t o;          /* OP_ADD_RE: the argument that is not PREVIOUS */
};

/* one unit's program: its channels, and the channels whose result is an
 * unsaturated sum of two products (INTERP: what a following ADD
 * reassociates with) */
struct unit_prog {
   struct chan_prog ch[4];
   unsigned sum;
};

/* the per-half values a unit's lookup needs */
struct unit_front {
   __m256 s, t;
   struct r_tex_lod lod[2];
   struct tex8_trilod tl;   /* the trilinear lookup's */
};

struct unit_stage;
typedef __m256i (*lookup_fn)(const struct unit_stage *u, const struct unit_front *f);
/* env_fn: the unit's environment on prev (in place), tf the texels as
 * floats, pc the primary colour, p the previous unit's products (read
 * by OP_ADD_RE) and this unit's (written by OP_INTERP) */
typedef void (*env_fn)(const struct unit_stage *u, const __m256 tf[4], const __m256 pc[4],
                       __m256 prev[4], __m256 p[4][2]);

struct unit_stage {
   const struct r_texture *tex;
   bool flat_tex;
   bool trilinear;
   bool bilinear;       /* a lookup of tex8_is_bilinear: no level of detail */
   lookup_fn lookup;
   env_fn env;
   struct unit_prog prog;
   __m256 tc[4];        /* flat texture coordinates, broadcast */
   __m256 konst[4];     /* GL_TEXTURE_ENV_COLOR */
   struct vplane ptc[4];   /* the coordinates' planes (r unused), broadcast */
   __m256 fw, fh;          /* the base level's size (the trilinear lookup's LOD) */
   struct tex8_level levels[R_MAX_TEX_LEVELS];
};

struct block_stage {
   int n;
   bool flat_color;
   __m256 color[4];
   struct vplane pw, pcol[4];   /* w's and the colour's planes, broadcast */
   struct unit_stage u[MTEX_MAX_UNITS];
};

/* ---- the lookups ---- */

static __m256i lookup_general(const struct unit_stage *u, const struct unit_front *f)
{
   return tex8_filter_quads(u->tex, u->levels, f->lod, f->s, f->t);
}

static __m256i lookup_trilinear(const struct unit_stage *u, const struct unit_front *f)
{
   return tex8_filter_trilinear_lod(u->levels, u->tex->last_level, &f->tl, f->s, f->t);
}

static __m256i lookup_bilinear_repeat(const struct unit_stage *u, const struct unit_front *f)
{
   return tex8_filter_bilinear(u->levels, u->tex->first_level, R_WRAP_REPEAT, f->s, f->t);
}

static __m256i lookup_bilinear_clamp(const struct unit_stage *u, const struct unit_front *f)
{
   return tex8_filter_bilinear(u->levels, u->tex->first_level, R_WRAP_CLAMP_TO_EDGE, f->s, f->t);
}

/* u->lookup's lookup inline (the MODULATE x MODULATE kernels: no call,
 * so none of the caller's vector registers is saved around it) */
static ALWAYS_INLINE __m256i lookup_inline(const struct unit_stage *u, const struct unit_front *f)
{
   if (u->lookup == lookup_trilinear)
      return tex8_filter_trilinear_lod(u->levels, u->tex->last_level, &f->tl, f->s, f->t);
   if (u->lookup == lookup_bilinear_clamp)
      return tex8_filter_bilinear(u->levels, u->tex->first_level, R_WRAP_CLAMP_TO_EDGE, f->s, f->t);
   if (u->lookup == lookup_bilinear_repeat)
      return tex8_filter_bilinear(u->levels, u->tex->first_level, R_WRAP_REPEAT, f->s, f->t);
   return lookup_general(u, f);
}

/* ---- the environments ---- */

static ALWAYS_INLINE __m256 arg8(const struct unit_stage *u, unsigned a, const __m256 tf[4],
                                 const __m256 pc[4], const __m256 prev[4])
{
   __m256 v;
   switch (a >> 3) {
   case A_TEX:   v = tf[a & 3]; break;
   case A_PREV:  v = prev[a & 3]; break;
   case A_PRIM:  v = pc[a & 3]; break;
   case A_CONST: v = u->konst[a & 3]; break;
   case A_ZERO:  v = _mm256_setzero_ps(); break;
   default:      v = _mm256_set1_ps(1.0f); break;
   }
   if (a & 4)
      v = _mm256_sub_ps(_mm256_set1_ps(1.0f), v);
   return v;
}

/* fsat: max(x, 0) (NaN -> 0), then min(., 1) */
static ALWAYS_INLINE __m256 sat8(__m256 x)
{
   return _mm256_min_ps(_mm256_max_ps(x, _mm256_setzero_ps()), _mm256_set1_ps(1.0f));
}

/* the general program, channel by channel */
static void env_program(const struct unit_stage *u, const __m256 tf[4], const __m256 pc[4],
                        __m256 prev[4], __m256 p[4][2])
{
   __m256 res[4], np[4][2];
   for (int c = 0; c < 4; c++) {
      const struct chan_prog *k = &u->prog.ch[c];
      const __m256 a0 = arg8(u, k->arg[0], tf, pc, prev);
      __m256 r;
      switch (k->op) {
      case OP_ARG:
         r = a0;
         break;
      case OP_MUL:
         r = _mm256_mul_ps(a0, arg8(u, k->arg[1], tf, pc, prev));
         break;
      case OP_ADD:
         r = _mm256_add_ps(a0, arg8(u, k->arg[1], tf, pc, prev));
         break;
      case OP_ADD_RE:
         /* (p0 + a) + p1 */
         r = _mm256_add_ps(_mm256_add_ps(p[c][0], arg8(u, k->arg[k->o], tf, pc, prev)), p[c][1]);
         break;
      case OP_SUB:
         r = _mm256_sub_ps(a0, arg8(u, k->arg[1], tf, pc, prev));
         break;
      default: {   /* OP_INTERP */
         const __m256 a2 = arg8(u, k->arg[2], tf, pc, prev);
         const __m256 b = _mm256_sub_ps(_mm256_set1_ps(1.0f), a2);
         np[c][0] = _mm256_mul_ps(a0, a2);
         np[c][1] = _mm256_mul_ps(arg8(u, k->arg[1], tf, pc, prev), b);
         r = _mm256_add_ps(np[c][0], np[c][1]);
         break;
      }
      }
      res[c] = k->sat ? sat8(r) : r;
   }
   for (int c = 0; c < 4; c++) {
      prev[c] = res[c];
      if (u->prog.sum & (1u << c)) {
         p[c][0] = np[c][0];
         p[c][1] = np[c][1];
      }
   }
}

/* MODULATE on a texture with alpha: T * PREVIOUS on every channel */
static ALWAYS_INLINE void env_mod_body(const __m256 tf[4], __m256 prev[4])
{
   for (int c = 0; c < 4; c++)
      prev[c] = _mm256_mul_ps(tf[c], prev[c]);
}

static void env_mod(const struct unit_stage *u, const __m256 tf[4], const __m256 pc[4],
                    __m256 prev[4], __m256 p[4][2])
{
   (void)u; (void)pc; (void)p;
   env_mod_body(tf, prev);
}

/* MODULATE on a texture without alpha: rgb T * PREVIOUS, alpha PREVIOUS */
static ALWAYS_INLINE void env_mod_rgb_body(const __m256 tf[4], __m256 prev[4])
{
   for (int c = 0; c < 3; c++)
      prev[c] = _mm256_mul_ps(tf[c], prev[c]);
}

static void env_mod_rgb(const struct unit_stage *u, const __m256 tf[4], const __m256 pc[4],
                        __m256 prev[4], __m256 p[4][2])
{
   (void)u; (void)pc; (void)p;
   env_mod_rgb_body(tf, prev);
}

/* REPLACE on a texture with alpha: T */
static void env_replace(const struct unit_stage *u, const __m256 tf[4], const __m256 pc[4],
                        __m256 prev[4], __m256 p[4][2])
{
   (void)u; (void)pc; (void)p;
   for (int c = 0; c < 4; c++)
      prev[c] = tf[c];
}

/* REPLACE on a texture without alpha: rgb T, alpha PREVIOUS */
static void env_replace_rgb(const struct unit_stage *u, const __m256 tf[4], const __m256 pc[4],
                            __m256 prev[4], __m256 p[4][2])
{
   (void)u; (void)pc; (void)p;
   for (int c = 0; c < 3; c++)
      prev[c] = tf[c];
}

/* ---- the program of a unit (at validation and per triangle) ---- */

static bool one_minus(int opr)
{
   return opr == R_OPR_ONE_MINUS_COLOR || opr == R_OPR_ONE_MINUS_ALPHA;
}

static bool is_alpha(int opr)
{
   return opr == R_OPR_ALPHA || opr == R_OPR_ONE_MINUS_ALPHA;
}

/* comb_arg's argument as an arg8 code; false for another unit's texture */
static bool prog_arg(int src, int opr, int unit, int c, uint8_t *arg)
{
   int s;
   switch (src) {
   case R_SRC_TEXTURE:       s = A_TEX; break;
   case R_SRC_PREVIOUS:      s = A_PREV; break;
   case R_SRC_PRIMARY_COLOR: s = A_PRIM; break;
   case R_SRC_CONSTANT:      s = A_CONST; break;
   case R_SRC_ZERO:          s = A_ZERO; break;
   case R_SRC_ONE:           s = A_ONE; break;
   default:
      if (src != R_SRC_TEXTURE0 + unit)
         return false;
      s = A_TEX;
      break;
   }
   *arg = (uint8_t)(s * 8 + (one_minus(opr) ? 4 : 0) + (is_alpha(opr) ? 3 : c));
   return true;
}

/* r_frag.c arg_key: the value an argument's channel is in the compiled
 * shader (for NIR's factoring of INTERPOLATE) */
static int prog_key(int src, int opr, int c, int unit, bool prev_is_primary)
{
   if (src == R_SRC_ZERO || src == R_SRC_ONE)
      return -1;
   if (src == R_SRC_TEXTURE)
      src = R_SRC_TEXTURE0 + unit;
   if (src == R_SRC_PREVIOUS && prev_is_primary)
      src = R_SRC_PRIMARY_COLOR;
   return src * 16 + (one_minus(opr) ? 8 : 0) + (is_alpha(opr) ? 3 : c);
}

/* The program of unit `unit` (the n-th enabled, first when it reads the
 * primary colour as PREVIOUS) after a unit whose INTERP channels are
 * prev_sum: false when some channel is of a form not covered. */
static bool unit_program(const struct r_tex_combine *k, int unit, bool first, unsigned prev_sum,
                         struct unit_prog *pr)
{
   if (k->shift_rgb || k->shift_a)
      return false;
   pr->sum = 0;
   for (int c = 0; c < 4; c++) {
      const int mode = c < 3 ? k->mode_rgb : k->mode_a;
      const int nargs = c < 3 ? k->nargs_rgb : k->nargs_a;
      const uint8_t *src = c < 3 ? k->src_rgb : k->src_a;
      const uint8_t *opr = c < 3 ? k->opr_rgb : k->opr_a;
      struct chan_prog *ch = &pr->ch[c];
      int need;
      switch (mode) {
      case R_COMB_REPLACE:     ch->op = OP_ARG; need = 1; break;
      case R_COMB_MODULATE:    ch->op = OP_MUL; need = 2; break;
      case R_COMB_ADD:         ch->op = OP_ADD; need = 2; break;
      case R_COMB_SUBTRACT:    ch->op = OP_SUB; need = 2; break;
      case R_COMB_INTERPOLATE: ch->op = OP_INTERP; need = 3; break;
      default:                 return false;
      }
      if (nargs < need)
         return false;
      ch->sat = mode == R_COMB_ADD || mode == R_COMB_SUBTRACT;
      ch->o = 0;
      for (int i = 0; i < need; i++)
         if (!prog_arg(src[i], opr[i], unit, c, &ch->arg[i]))
            return false;
      if (ch->op == OP_INTERP) {
         /* only the form without a common factor and b = 1 - a2 */
         if (one_minus(opr[2]))
            return false;
         const int k0 = prog_key(src[0], opr[0], c, unit, first);
         const int k1 = prog_key(src[1], opr[1], c, unit, first);
         const int k2 = prog_key(src[2], opr[2], c, unit, first);
         const int kb = k2 >= 0 ? (k2 ^ 8) : -1;
         if ((k0 >= 0 && (k0 == k1 || k0 == kb)) || (k2 >= 0 && k2 == k1))
            return false;
         pr->sum |= 1u << c;
      } else if (ch->op == OP_ADD) {
         const int pi = src[0] == R_SRC_PREVIOUS && opr[0] == R_OPR_COLOR ? 0
                      : src[1] == R_SRC_PREVIOUS && opr[1] == R_OPR_COLOR ? 1 : -1;
         const int o = 1 - pi;
         if (pi >= 0 && ((prev_sum >> c) & 1u) && src[o] != R_SRC_PREVIOUS &&
             src[o] != R_SRC_ZERO && src[o] != R_SRC_ONE &&
             (opr[o] == R_OPR_COLOR || opr[o] == R_OPR_ALPHA)) {
            ch->op = OP_ADD_RE;
            ch->o = (uint8_t)o;
         }
      }
   }
   return true;
}

static bool prog_is(const struct unit_prog *pr, int c0, int c1, int op, bool tex_first)
{
   for (int c = c0; c < c1; c++) {
      const struct chan_prog *k = &pr->ch[c];
      const uint8_t t = (uint8_t)(A_TEX * 8 + c), p = (uint8_t)(A_PREV * 8 + c);
      if (k->op != op || k->sat)
         return false;
      if (op == OP_ARG && k->arg[0] != (tex_first ? t : p))
         return false;
      if (op == OP_MUL && !((k->arg[0] == t && k->arg[1] == p) || (k->arg[0] == p && k->arg[1] == t)))
         return false;
   }
   return true;
}

/* the function of a program: a common form, else the general one
 * (T * P and P * T are the same float) */
static env_fn program_fn(const struct unit_prog *pr)
{
   if (prog_is(pr, 0, 4, OP_MUL, true))
      return env_mod;
   if (prog_is(pr, 0, 3, OP_MUL, true) && prog_is(pr, 3, 4, OP_ARG, false))
      return env_mod_rgb;
   if (prog_is(pr, 0, 4, OP_ARG, true))
      return env_replace;
   if (prog_is(pr, 0, 3, OP_ARG, true) && prog_is(pr, 3, 4, OP_ARG, false))
      return env_replace_rgb;
   return env_program;
}

/* ---- the stage ---- */

static ALWAYS_INLINE void block_stage_prepare(const struct r_state *rs, const struct r_tri_setup *ts,
                                              int variant, struct block_stage *st)
{
   st->n = variant == V_ANY ? rs->fs->tex_nr : 2;
   st->flat_color = ts->flat_attr[R_FS_COLOR0];
   for (int c = 0; c < 4; c++) {
      st->color[c] = _mm256_set1_ps(ts->flat[R_FS_COLOR0][c]);
      if (!st->flat_color)
         st->pcol[c] = vplane_of(&ts->ap[R_FS_COLOR0][c]);
   }
   if (ts->need_w)
      st->pw = vplane_of(&ts->w);
   unsigned prev_sum = 0;
   for (int i = 0; i < st->n; i++) {
      struct unit_stage *u = &st->u[i];
      const struct r_tex_unit *tu = rs->tex[i];
      u->tex = &tu->tex;
      u->flat_tex = ts->flat_attr[R_FS_TEX0 + i];
      if (!u->flat_tex)
         for (int c = 0; c < 4; c++)
            if (c != 2)
               u->ptc[c] = vplane_of(&ts->ap[R_FS_TEX0 + i][c]);
      u->trilinear = tex8_is_trilinear_repeat(u->tex);
      u->fw = _mm256_set1_ps((float)u->tex->level[u->tex->first_level].width);
      u->fh = _mm256_set1_ps((float)u->tex->level[u->tex->first_level].height);
      u->bilinear = false;
      u->lookup = lookup_general;
      if (u->trilinear) {
         u->lookup = lookup_trilinear;
      } else if (tex8_is_bilinear(u->tex, R_WRAP_REPEAT)) {
         u->bilinear = true;
         u->lookup = lookup_bilinear_repeat;
      } else if (tex8_is_bilinear(u->tex, R_WRAP_CLAMP_TO_EDGE)) {
         u->bilinear = true;
         u->lookup = lookup_bilinear_clamp;
      }
      for (int c = 0; c < 4; c++) {
         u->tc[c] = _mm256_set1_ps(ts->flat[R_FS_TEX0 + i][c]);
         u->konst[c] = _mm256_set1_ps(tu->env_color[c]);
      }
      for (int l = u->tex->first_level; l <= u->tex->last_level; l++)
         tex8_level_init(u->tex, l, &u->levels[l]);
      if (variant == V_ANY) {
         /* (validated by r_block_choose_tri_mtex) */
         unit_program(&tu->comb, i, i == 0, prev_sum, &u->prog);
         prev_sum = u->prog.sum;
         u->env = program_fn(&u->prog);
      }
   }
}

/* the lanes' pixel offsets in quad-major order */
static ALWAYS_INLINE __m256 quad_lx(void) { return _mm256_setr_ps(0, 1, 0, 1, 2, 3, 2, 3); }
static ALWAYS_INLINE __m256 quad_ly(void) { return _mm256_setr_ps(0, 0, 1, 1, 0, 0, 1, 1); }

/* a unit's projected coordinates and the quads' level of detail */
static ALWAYS_INLINE void unit_front(const struct unit_stage *u, __m256 rw, __m256 fx, __m256 fy,
                                     struct unit_front *f)
{
   __m256 s, t, q;
   if (u->flat_tex) {
      s = u->tc[0];
      t = u->tc[1];
      q = u->tc[3];
   } else {
      s = _mm256_mul_ps(veval8_y(&u->ptc[0], veval8_x(&u->ptc[0], fx), fy), rw);
      t = _mm256_mul_ps(veval8_y(&u->ptc[1], veval8_x(&u->ptc[1], fx), fy), rw);
      q = _mm256_mul_ps(veval8_y(&u->ptc[3], veval8_x(&u->ptc[3], fx), fy), rw);
   }
   const __m256 rq = _mm256_div_ps(_mm256_set1_ps(1.0f), q);
   f->s = _mm256_mul_ps(s, rq);
   f->t = _mm256_mul_ps(t, rq);
   if (u->trilinear) {
      /* (the half's two quads: the second half's lanes repeat them) */
      struct tex8_trilod unused;
      tex8_trilinear_lod2(u->tex->first_level, u->tex->last_level, u->fw, u->fh, f->s, f->t, f->s,
                          f->t, &f->tl, &unused);
   } else if (!u->bilinear)   /* (its lookup needs none) */
      tex8_lod_quads(u->tex, f->s, f->t, f->lod);
}

/* packed RGBA8 texels to floats, (float)b * (1/255) */
static ALWAYS_INLINE void texel_floats(__m256i texel, __m256 tf[4])
{
   const __m256 scale = _mm256_set1_ps((float)(1.0 / 255.0));
   const __m256i m255 = _mm256_set1_epi32(255);
   for (int c = 0; c < 4; c++)
      tf[c] = _mm256_mul_ps(
         _mm256_cvtepi32_ps(_mm256_and_si256(_mm256_srli_epi32(texel, 8 * c), m255)), scale);
}

static ALWAYS_INLINE __m256i block_stage_shade(const struct r_state *rs, const struct r_tri_setup *ts,
                                               const struct block_stage *st, int variant,
                                               __m256 fx_rows, __m256 fy_rows, int x, int y,
                                               unsigned m8, __m256i *live)
{
   (void)rs; (void)fx_rows; (void)fy_rows; (void)m8; (void)live;
   const __m256 fx = _mm256_add_ps(_mm256_set1_ps((float)x), quad_lx());
   const __m256 fy = _mm256_add_ps(_mm256_set1_ps((float)y), quad_ly());
   /* 1/w (not read when every input is flat) */
   const __m256 rw =
      ts->need_w
         ? _mm256_div_ps(_mm256_set1_ps(1.0f), veval8_y(&st->pw, veval8_x(&st->pw, fx), fy))
         : _mm256_setzero_ps();
   __m256 pc[4], prev[4];
   if (st->flat_color) {
      for (int c = 0; c < 4; c++)
         pc[c] = st->color[c];
   } else {
      for (int c = 0; c < 4; c++)
         pc[c] = _mm256_mul_ps(veval8_y(&st->pcol[c], veval8_x(&st->pcol[c], fx), fy), rw);
   }
   for (int c = 0; c < 4; c++)
      prev[c] = pc[c];
   __m256 p[4][2];
   for (int c = 0; c < 4; c++)
      p[c][0] = p[c][1] = _mm256_setzero_ps();
   const int n = variant == V_ANY ? st->n : 2;
   for (int i = 0; i < n; i++) {
      const struct unit_stage *u = &st->u[i];
      struct unit_front f;
      unit_front(u, rw, fx, fy, &f);
      __m256 tf[4];
      texel_floats(variant == V_ANY ? u->lookup(u, &f) : lookup_inline(u, &f), tf);
      if (variant == V_MOD2)
         env_mod_body(tf, prev);
      else if (variant == V_MOD2_RGB)
         env_mod_rgb_body(tf, prev);
      else
         u->env(u, tf, pc, prev, p);
   }
   const __m256i out = pack_rgba8(prev[0], prev[1], prev[2], prev[3]);
   /* quad-major back to row-major */
   return _mm256_permute4x64_epi64(out, QUAD_ORDER);
}

/* the stage kills nothing and reads no buffer: the depth test may come
 * first (r_block_tri.h) */
#define BLOCK_STAGE_EARLY_Z 1
#include "r_block_tri.h"

#define MTEX_KERNEL(name, var, zf, bl)                                                     \
   static void name(const struct r_state *rs, const struct r_tri_setup *ts,               \
                    const struct r_tri_cover *cv)                                          \
   {                                                                                       \
      tri_blocks(rs, ts, cv, var, zf, bl);                                                 \
   }

/* (depth writes or not: the same kernel, r_block_tri.h) */
#define MTEX_KERNELS_VAR(p, var, bl)                                                       \
   MTEX_KERNEL(p##_nz, var, ZF_NONE, bl)                                                  \
   MTEX_KERNEL(p##_z16, var, ZF_16, bl)                                                   \
   MTEX_KERNEL(p##_z24, var, ZF_24, bl)

MTEX_KERNELS_VAR(opaque_any, V_ANY, BL_NONE)
MTEX_KERNELS_VAR(opaque_mod2, V_MOD2, BL_NONE)
MTEX_KERNELS_VAR(opaque_mod2rgb, V_MOD2_RGB, BL_NONE)
MTEX_KERNELS_VAR(alpha_any, V_ANY, BL_ALPHA)
MTEX_KERNELS_VAR(alpha_mod2, V_MOD2, BL_ALPHA)
MTEX_KERNELS_VAR(alpha_mod2rgb, V_MOD2_RGB, BL_ALPHA)

#define ROW(p)                                                                             \
   { { p##_nz, p##_nz }, { p##_z16, p##_z16 }, { p##_z24, p##_z24 } }
/* [blend][variant][zfmt][zwrite] */
static const r_tri_kernel mtex_table[2][3][3][2] = {
   { ROW(opaque_any), ROW(opaque_mod2), ROW(opaque_mod2rgb) },
   { ROW(alpha_any), ROW(alpha_mod2), ROW(alpha_mod2rgb) },
};

r_tri_kernel r_block_choose_tri_mtex(const struct r_state *rs, bool flat_color)
{
   (void)flat_color;   /* read per triangle */
   const int n = rs->fs->tex_nr;
   if (n < 2 || n > MTEX_MAX_UNITS || rs->fs->tex_units != (1u << n) - 1u)
      return NULL;
   unsigned inputs = 1u << R_FS_COLOR0;
   for (int i = 0; i < n; i++)
      inputs |= 1u << (R_FS_TEX0 + i);
   if (rs->fs->fs_inputs != inputs || rs->fs->color_sum || rs->fs->fog_mode != R_FOG_NONE ||
       rs->fs->phong || rs->pix || rs->fs->aa != R_AA_NONE || rs->rast->stipple || !rs->fb->color)
      return NULL;
   /* both units of one MODULATE form: V_MOD2 or V_MOD2_RGB */
   env_fn fns[MTEX_MAX_UNITS];
   unsigned prev_sum = 0;
   for (int i = 0; i < n; i++) {
      if (!r_tex8_fast(&rs->tex[i]->tex))
         return NULL;
      struct unit_prog pr;
      if (!unit_program(&rs->tex[i]->comb, i, i == 0, prev_sum, &pr))
         return NULL;
      prev_sum = pr.sum;
      fns[i] = program_fn(&pr);
   }
   int var = V_ANY;
   if (n == 2 && fns[0] == fns[1])
      var = fns[0] == env_mod ? V_MOD2 : fns[0] == env_mod_rgb ? V_MOD2_RGB : V_ANY;
   enum blend bl;
   enum zfmt zf;
   if (!block_simple_ops(rs, &bl, &zf))
      return NULL;
   return mtex_table[bl][var][zf][rs->dsa->depth_write];
}
