/*
 * Per-vertex lighting, as the oracle's fixed-function vertex program
 * computes it (Mesa 22.3 ffvertex_prog.c:build_lighting, compiled through
 * prog_to_nir and gallivm; ORACLE-NOTES.md "Lighting order of
 * operations"):
 *
 *   colour = emission + ambient_material * global_ambient
 *          + sum over enabled lights, in index order, of
 *            att * spot * (ambient + max(n.l, 0) * diffuse
 *                          + max(n.h, 0)^shininess * specular)
 *
 * with every product a separate float multiply and every sum a separate
 * add (no FMA), dot products summed from the last component, 1/sqrt(|x|)
 * for normalisation, and pow from gallivm's exp2/log2 approximations.  The
 * light vectors and the lighting space come from fgl_update_lighting.
 *
 * fixgl's shading extensions (include/fixgl/shading.md) leave that path
 * untouched: when either face's reflectance model is Cook-Torrance, every
 * vertex is lit by m_shade_point (math/m_shade.c) instead, and under
 * GL_PHONG_WIN the lighting moves to the fragments (t_vertex.c calls
 * t_phong.c instead of t_light; in GL_SELECT / GL_FEEDBACK the vertices
 * are lit here, as under GL_SMOOTH).
 */
#include "tnl/t_light.h"
#include "raster/r_kernel.h"

#include <math.h>
#include <stddef.h>
#include <string.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include <fixgl/fixgl.h>

#include "context.h"
#include "math/m_gallivm.h"
#include "math/m_shade.h"

/* DP3 = (z*z' + y*y') + x*x' (NIR's reduction from the last component) */
static inline float dp3(const float *a, const float *b)
{
   return (a[2] * b[2] + a[1] * b[1]) + a[0] * b[0];
}

/* RSQ: 1/sqrt(|x|) */
static inline float rsq(float x)
{
   return 1.0f / sqrtf(fabsf(x));
}

/* emit_normalize_vec3: v * rsq(v.v) */
static inline void normalize3(float *v)
{
   const float r = rsq(dp3(v, v));
   v[0] *= r;
   v[1] *= r;
   v[2] *= r;
}

/* max(x, 0): the same bits as libm's fmaxf(x, 0.0f) and fmaxf(0.0f, x)
 * (a NaN or either zero gives +0, with or without the flush of
 * denormals; checked against Debian 12's glibc), without the call. */
static inline float max0(float x)
{
   return x > 0.0f ? x : 0.0f;
}

/* MAD as the oracle runs it: a separate multiply and add */
static inline void mad3(float *acc, float s, const float *v)
{
   for (int k = 0; k < 3; k++)
      acc[k] = s * v[k] + acc[k];
}

/* The LIT result of one face: (att, diffuse factor, specular factor). */
struct lit {
   float ambient, diffuse, specular;
};

/* LIT's exponent: the shininess clamped to [-128, 128]. */
static inline float lit_exponent(float shininess)
{
   return fmaxf(fminf(shininess, 128.0f), -128.0f);
}

/* LIT of (nd, nh, -, shininess) (prog_to_nir.c:ptn_lit): y = max(nd, 0),
 * z = nd <= 0 ? 0 : pow(max(nh, 0), clamp(shininess, -128, 128)), the
 * exponent already clamped (lit_exponent). */
static inline struct lit lit_op(float nd, float nh, float exponent)
{
   struct lit l = { 1.0f, max0(nd), 0.0f };
   l.specular = 0.0f >= nd ? 0.0f : m_gallivm_pow(max0(nh), exponent);
   return l;
}

/* A face's material for one vertex (exponent: its shininess through
 * lit_exponent). */
struct material {
   const float *ambient, *diffuse, *specular, *emission;
   float exponent;
};



static void scene_colour(const struct fgl_context *ctx, const struct material *m, float c[3])
{
   for (int k = 0; k < 3; k++)
      c[k] = ctx->Light.Model.Ambient[k] * m->ambient[k] + m->emission[k];
}

static void light_product(const float *light, const float *material, float p[3])
{
   for (int k = 0; k < 3; k++)
      p[k] = light[k] * material[k];
}

/* One vertex: col[0] front colour, col[1] front secondary, col[2] back
 * colour, col[3] back secondary (R_ATTR_* slots), before the clamp. */
static void light_vertex(const struct fgl_context *ctx, const struct t_light_key *key,
                         const struct t_light_products *P, const float n[3], const float V[4],
                         const struct material mat[2], float col[4][4])
{
   const struct fgl_light_attrib *la = &ctx->Light;
   const struct fgl_lighting_derived *ld = &ctx->_Lighting;
   const int sides = key->twoside ? 2 : 1;

   /* scene colour: emission + ambient * global ambient, alpha = diffuse alpha */
   for (int s = 0; s < sides; s++) {
      float *c = col[2 * s];
      if (P->vary_scene[s])
         scene_colour(ctx, &mat[s], c);
      else
         for (int k = 0; k < 3; k++)
            c[k] = P->scene[s][k];
      c[3] = mat[s].diffuse[3];
      float *c1 = col[2 * s + 1];
      c1[0] = c1[1] = c1[2] = 0.0f;
      c1[3] = 1.0f;
   }

   float eye_hat[3];
   if (key->local_viewer && !key->shininess_is_zero) {
      for (int k = 0; k < 3; k++)
         eye_hat[k] = V[k];
      normalize3(eye_hat);
   }

   for (unsigned lights = ld->EnabledLights; lights; lights &= lights - 1) {
      const int i = __builtin_ctz(lights);   /* in index order */
      const struct fgl_light *l = &la->Light[i];
      const struct fgl_light_derived *d = &ld->Light[i];

      /* direction to the light, and the squared distance */
      float VP[3], dist2 = 0.0f, inv_dist = 0.0f;
      if (d->Positional) {
         for (int k = 0; k < 3; k++)
            VP[k] = d->Position[k] - V[k];
         dist2 = dp3(VP, VP);
         inv_dist = rsq(dist2);
         for (int k = 0; k < 3; k++)
            VP[k] *= inv_dist;
      } else {
         for (int k = 0; k < 3; k++)
            VP[k] = d->Position[k];
      }

      /* attenuation: spot cone and exponent, then distance
       * (calculate_light_attenuation) */
      bool attenuated = false;
      float att = 1.0f;
      if (d->Spot) {
         const float spot = (-VP[2] * d->SpotDirection[2] + -VP[1] * d->SpotDirection[1]) +
                            -VP[0] * d->SpotDirection[0];
         /* SLT times POW: the oracle selects, so outside the cone the
          * factor is 0 even where pow is NaN (a light exactly at the
          * vertex; ORACLE-NOTES.md "Lighting") */
         const bool inside = l->CosCutoff < spot;
         att = inside ? m_gallivm_pow(fabsf(spot), l->SpotExponent) : 0.0f;
         attenuated = true;
      }
      if (d->Attenuated && d->Positional) {
         const float dist = sqrtf(fabsf(dist2));   /* rcp(rsq(s)) */
         const float k = (l->QuadraticAttenuation * dist2 + l->LinearAttenuation * dist) +
                         l->ConstantAttenuation * (inv_dist * dist);
         att = attenuated ? (1.0f / k) * att : 1.0f / k;
         attenuated = true;
      }

      /* half vector */
      float H[3];
      if (!key->shininess_is_zero) {
         if (key->local_viewer) {
            for (int k = 0; k < 3; k++)
               H[k] = VP[k] - eye_hat[k];
            normalize3(H);
         } else if (!d->Positional) {
            for (int k = 0; k < 3; k++)
               H[k] = d->HalfVector[k];
         } else {
            H[0] = VP[0];
            H[1] = VP[1];
            H[2] = VP[2] + 1.0f;
            normalize3(H);
         }
      }

      const float nd = dp3(n, VP);
      const float nh = key->shininess_is_zero ? nd : dp3(n, H);

      for (int s = 0; s < sides; s++) {
         /* the back face sees the negated dot products */
         const float snd = s ? -nd : nd, snh = s ? -nh : nh;
         struct lit lt;
         if (attenuated) {
            /* with shininess 0 every component of dots is n.VP */
            lt = lit_op(snd, snh, key->shininess_is_zero ? lit_exponent(snd) : mat[s].exponent);
            lt.ambient = att;
            lt.diffuse *= att;
            lt.specular *= att;
         } else if (!key->shininess_is_zero) {
            lt = lit_op(snd, snh, mat[s].exponent);
         } else {
            /* emit_degenerate_lit */
            lt.ambient = 1.0f;
            lt.diffuse = max0(snd);   /* fmaxf(0.0f, snd) */
            lt.specular = 0.0f < snd ? 1.0f : 0.0f;
         }

         float varying[3][3];
         const float *ambient = P->ambient[i][s], *diffuse = P->diffuse[i][s],
                     *specular = P->specular[i][s];
         if (P->vary_ambient[s]) {
            light_product(l->Ambient, mat[s].ambient, varying[0]);
            ambient = varying[0];
         }
         if (P->vary_diffuse[s]) {
            light_product(l->Diffuse, mat[s].diffuse, varying[1]);
            diffuse = varying[1];
         }
         if (P->vary_specular[s]) {
            light_product(l->Specular, mat[s].specular, varying[2]);
            specular = varying[2];
         }
         float *c0 = col[2 * s];
         float *c1 = key->separate ? col[2 * s + 1] : c0;
         if (attenuated) {
            mad3(c0, lt.ambient, ambient);
         } else {
            for (int k = 0; k < 3; k++)
               c0[k] = ambient[k] + c0[k];
         }
         mad3(c0, lt.diffuse, diffuse);
         mad3(c1, lt.specular, specular);
      }
   }
}

/* get_transformed_normal */
static void transform_normal(const struct fgl_context *ctx, const struct t_light_key *key,
                             const float *in, float n[3])
{
   if (key->eye) {
      const float *inv = ctx->ModelviewStack.Top->inv;
      for (int r = 0; r < 3; r++)
         n[r] = dp3(in, inv + 4 * r);
   } else {
      for (int k = 0; k < 3; k++)
         n[k] = in[k];
   }
   if (key->normalize) {
      normalize3(n);
   } else if (key->rescale) {
      for (int k = 0; k < 3; k++)
         n[k] *= ctx->_Lighting.NormalScale;
   }
}

/* get_transformed_normal outside the lighting code (texgen, t_texcoord.c):
 * the same key fields (_NeedEyeCoords, GL_NORMALIZE, the rescale rule) */
void t_transformed_normal(const struct fgl_context *ctx, const float *in, float n[3])
{
   struct t_light_key key = {
      .eye = ctx->_Lighting.NeedEyeCoords,
      .normalize = ctx->Transform.Normalize,
   };
   key.rescale = !key.normalize && key.eye == ctx->Transform.RescaleNormals;
   transform_normal(ctx, &key, in, n);
}


/* GL_FIXGL_cook_torrance per vertex (GL_SMOOTH, GL_FLAT): m_shade_point
 * in eye space for both faces.  A face left at GL_BLINN_PHONG_FIXGL in
 * such a draw is lit by m_shade_point's Blinn-Phong too (the same
 * equations as the oracle's program, not its rounding); draws where
 * neither face is Cook-Torrance keep the oracle-exact path above.  The
 * material of each vertex comes from lb->src (the vertex colour where it
 * is tracked, per-vertex values where the format has them, else the
 * current ones), the reflectance parameters from the lighting state. */
static void light_shade(const struct fgl_context *ctx, struct t_light_batch *lb,
                        const struct fgl_vertex_view *in, unsigned first, unsigned n,
                        struct t_vertex *out)
{
   struct m_shade_env *env = &lb->env;
   const struct t_material_source *src = lb->src;
   const int sides = ctx->Light.Model.TwoSide ? 2 : 1;
   const fgl_matrix *mv = ctx->ModelviewStack.Top;

   for (unsigned i = first; i < first + n; i++) {
      /* the eye-space normal n as GL_PHONG_WIN's vertices have it
       * (t_phong.c t_eye_normal: the inverse-transpose of the modelview,
       * then GL_NORMALIZE or GL_RESCALE_NORMAL, whose rounding shows even
       * though m_shade_point_prepared normalises again; shading.md).  P: the
       * modelview times the vertex, xyz (its w is ignored, as GL's
       * lighting ignores it). */
      float nrm[3], P[4];
      t_eye_normal(&lb->en, lb->normal + (size_t)i * lb->nstride, nrm);
      t_mul_mad_chain(P, mv->m, fgl_vv_attr(in, i, FGL_ATTR_POS));

      for (int s = 0; s < sides; s++) {
         struct m_shade_material *m = &env->material[s];
         /* the face's attribute a + s (front/back attributes alternate) */
#define MAT(a) (src[(a) + s].ptr + (size_t)i * src[(a) + s].stride)
         memcpy(m->ambient, MAT(FGL_ATTR_MAT_FRONT_AMBIENT), sizeof(m->ambient));
         memcpy(m->diffuse, MAT(FGL_ATTR_MAT_FRONT_DIFFUSE), sizeof(m->diffuse));
         memcpy(m->specular, MAT(FGL_ATTR_MAT_FRONT_SPECULAR), sizeof(m->specular));
         memcpy(m->emission, MAT(FGL_ATTR_MAT_FRONT_EMISSION), sizeof(m->emission));
         m->shininess = MAT(FGL_ATTR_MAT_FRONT_SHININESS)[0];
#undef MAT
      }
      float (*col)[4] = out[i].r.attr;
      /* env's point-independent values were prepared once per batch
       * (fgl_update_shade_env in t_light_prepare); the per-vertex material
       * colours and shininess are not among them */
      for (int s = 0; s < sides; s++)
         m_shade_point_prepared(env, nrm, P, s == 1, NULL, col[2 * s], col[2 * s + 1]);
   }
}

/* Whether light_shade8 lights this Cook-Torrance batch, and its
 * environment then (t_light_prepare): the shininess of the lit faces does
 * not vary per vertex, and every other property either does not vary (set
 * in env once, the value light_shade copies per vertex) or is the vertex
 * colour (a color_material bit: m_shade_point8 reads the colour of the
 * lane, light_shade copies the same floats); not under
 * FIXGL_KERNELS=reference (the scalar path alone, which the tests compare
 * with), and on a CPU with AVX2 and FMA. */
static bool shade8_prepare(const struct fgl_context *ctx, const struct fgl_vertex_view *in,
                           struct t_light_batch *lb)
{
   if (ctx->_Raster.reference_kernels || !m_shade_point8_avx2_supported())
      return false;
   const struct t_material_source *src = lb->src;
   lb->color = fgl_vbo_attr_ptr(ctx, in, FGL_ATTR_COLOR0, &lb->cstride);
   struct m_shade_env *env = &lb->env;
   unsigned cm = 0;
   for (int s = 0; s < (ctx->Light.Model.TwoSide ? 2 : 1); s++) {
      if (src[FGL_ATTR_MAT_FRONT_SHININESS + s].stride != 0)
         return false;
      for (int k = 0; k < 4; k++) {
         /* ambient, diffuse, specular, emission: front/back alternate */
         const struct t_material_source *ms = &src[FGL_ATTR_MAT_FRONT_AMBIENT + 2 * k + s];
         if (ms->stride != 0 && (ms->ptr != lb->color || ms->stride != lb->cstride))
            return false;
         if (ms->stride != 0)
            cm |= (M_SHADE_CM_AMBIENT << k) << (s ? M_SHADE_CM_BACK_SHIFT : 0);
      }
   }
   for (int s = 0; s < (ctx->Light.Model.TwoSide ? 2 : 1); s++) {
      struct m_shade_material *m = &env->material[s];
#define MAT(a) (src[(a) + s].ptr)
      memcpy(m->ambient, MAT(FGL_ATTR_MAT_FRONT_AMBIENT), sizeof(m->ambient));
      memcpy(m->diffuse, MAT(FGL_ATTR_MAT_FRONT_DIFFUSE), sizeof(m->diffuse));
      memcpy(m->specular, MAT(FGL_ATTR_MAT_FRONT_SPECULAR), sizeof(m->specular));
      memcpy(m->emission, MAT(FGL_ATTR_MAT_FRONT_EMISSION), sizeof(m->emission));
      m->shininess = MAT(FGL_ATTR_MAT_FRONT_SHININESS)[0];
#undef MAT
   }
   env->color_material = cm;
   return true;
}

/* light_shade eight vertices at a time (shade8_prepare): the normals and
 * eye positions as light_shade computes them, lit by m_shade_point8 per
 * face (each lane m_shade_point_prepared's bits); a last group of fewer
 * than eight fills its other lanes with its first vertex.  Where the
 * AVX2 archive is built, t_light_avx2.c does it all in registers. */
static void light_shade8(const struct fgl_context *ctx, struct t_light_batch *lb,
                         const struct fgl_vertex_view *in, unsigned first, unsigned n,
                         struct t_vertex *out)
{
#ifdef FGL_HAVE_BLOCK_KERNELS
   /* the same in registers: gathered inputs, the lighting inline */
#ifdef FGL_HAVE_AVX512_KERNELS
   if (ctx->_Raster.kernel_isa == R_ISA_AVX512) {
      t_light_shade8_avx512(ctx, lb, in, first, n, out);
      return;
   }
#endif
   t_light_shade8_avx2(ctx, lb, in, first, n, out);
#else
   const struct m_shade_env *env = &lb->env;
   const int sides = ctx->Light.Model.TwoSide ? 2 : 1;
   const fgl_matrix *mv = ctx->ModelviewStack.Top;
   const bool colour = env->color_material != 0;

   for (unsigned i = first; i < first + n; i += M_SHADE_LANES) {
      const unsigned cnt = first + n - i < M_SHADE_LANES ? first + n - i : M_SHADE_LANES;
      float N[3][M_SHADE_LANES], P[3][M_SHADE_LANES], C[4][M_SHADE_LANES];
      float prim[4][M_SHADE_LANES], sec[4][M_SHADE_LANES];
      for (unsigned l = 0; l < M_SHADE_LANES; l++) {
         const unsigned v = i + (l < cnt ? l : 0);
         float nrm[3], p[4];
         t_eye_normal(&lb->en, lb->normal + (size_t)v * lb->nstride, nrm);
         t_mul_mad_chain(p, mv->m, fgl_vv_attr(in, v, FGL_ATTR_POS));
         for (int k = 0; k < 3; k++) {
            N[k][l] = nrm[k];
            P[k][l] = p[k];
         }
         if (colour) {
            const float *c = lb->color + (size_t)v * lb->cstride;
            for (int k = 0; k < 4; k++)
               C[k][l] = c[k];
         }
      }
      for (int s = 0; s < sides; s++) {
         m_shade_point8(env, (const float (*)[M_SHADE_LANES])N, (const float (*)[M_SHADE_LANES])P,
                        s == 1, colour ? (const float (*)[M_SHADE_LANES])C : NULL, prim, sec);
         for (unsigned l = 0; l < cnt; l++) {
            float (*col)[4] = out[i + l].r.attr;
            for (int k = 0; k < 4; k++) {
               col[2 * s][k] = prim[k][l];
               col[2 * s + 1][k] = sec[k][l];
            }
         }
      }
   }
#endif
}

/* ---- Eight vertices at a time ----
 * The common case -- directional and positional lights without spot, a
 * shininess that does not vary per vertex -- is lit in
 * structure-of-arrays form with AVX2: the eight lanes
 * of each operation are eight vertices, each lane doing light_vertex's
 * operations for its vertex in light_vertex's order (separate multiplies
 * and adds, DP3 from the last component, RSQ as 1/sqrt(|x|), LIT's pow as
 * m_gallivm_pow: pow8 below), so the bits are those of the scalar path,
 * which lights every other batch (and all of them on a CPU without AVX2
 * and FMA).  light_simd_eligible decides per batch. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
#define T_LIGHT_SIMD 1
#include <immintrin.h>

#define T_AVX2 __attribute__((target("avx2,fma")))

#include "tnl/t_soa8.h"

T_AVX2 static inline __m256 sel8(__m256 mask, __m256 if_true, __m256 if_false)
{
   return _mm256_blendv_ps(if_false, if_true, mask);
}

/* m_gallivm_pow(x, y) lane by lane: lp_build_pow, lp_build_log2_approx
 * and lp_build_exp2 with their polynomials (math/m_gallivm.h, whose
 * coefficients, double constants converted to float, are repeated here):
 * the same operations in the same order, vfmadd for its fmaf, vroundps to
 * -inf for its floorf, its special cases as selects. */
T_AVX2 static inline __m256 pow8(__m256 x, __m256 y)
{
   const __m256 one = _mm256_set1_ps(1.0f), zero = _mm256_setzero_ps();
   const __m256 inf = _mm256_set1_ps(INFINITY);

   /* m_gallivm_log2(x) */
   const __m256i i = _mm256_castps_si256(x);
   const __m256 exponent = _mm256_cvtepi32_ps(_mm256_sub_epi32(
      _mm256_srli_epi32(_mm256_and_si256(i, _mm256_set1_epi32(0x7f800000)), 23),
      _mm256_set1_epi32(127)));
   const __m256 mant = _mm256_castsi256_ps(_mm256_or_si256(
      _mm256_and_si256(i, _mm256_set1_epi32(0x007fffff)), _mm256_set1_epi32(0x3f800000)));
   const __m256 ly = _mm256_div_ps(_mm256_sub_ps(mant, one), _mm256_add_ps(mant, one));
   /* m_gallivm_polynomial(ly * ly, c, 5) */
   const __m256 lz = _mm256_mul_ps(ly, ly);
   const __m256 lz2 = _mm256_mul_ps(lz, lz);
   __m256 leven = _mm256_fmadd_ps(lz2, _mm256_set1_ps((float)0.406718052498846252698),
                                  _mm256_set1_ps((float)0.577440339438736392009));
   const __m256 lodd = _mm256_fmadd_ps(lz2, _mm256_set1_ps((float)0.403343858251329912514),
                                       _mm256_set1_ps((float)0.961791550404184197881));
   leven = _mm256_fmadd_ps(lz2, leven, _mm256_set1_ps((float)2.88539009343309178325));
   __m256 lg = _mm256_fmadd_ps(ly, _mm256_fmadd_ps(lodd, lz, leven), exponent);
   lg = sel8(_mm256_cmp_ps(x, inf, _CMP_GE_OQ), inf, lg);
   lg = sel8(_mm256_cmp_ps(x, zero, _CMP_EQ_OQ), _mm256_set1_ps(-INFINITY), lg);
   lg = sel8(_mm256_or_ps(_mm256_cmp_ps(x, zero, _CMP_LT_OQ), _mm256_cmp_ps(x, x, _CMP_UNORD_Q)),
             _mm256_set1_ps(NAN), lg);

   /* m_gallivm_exp2(log2(x) * y) */
   const __m256 t = _mm256_mul_ps(lg, y);
   __m256 tc = sel8(_mm256_cmp_ps(t, _mm256_set1_ps(128.0f), _CMP_GT_OQ),
                    _mm256_set1_ps(128.0f), t);
   tc = sel8(_mm256_cmp_ps(tc, _mm256_set1_ps(-126.99999f), _CMP_LT_OQ),
             _mm256_set1_ps(-126.99999f), tc);
   const __m256 ipart = _mm256_round_ps(tc, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
   const __m256 fpart = _mm256_sub_ps(tc, ipart);
   const __m256 scale = _mm256_castsi256_ps(_mm256_slli_epi32(
      _mm256_add_epi32(_mm256_cvttps_epi32(ipart), _mm256_set1_epi32(127)), 23));
   /* m_gallivm_polynomial(fpart, c, 6) */
   const __m256 f2 = _mm256_mul_ps(fpart, fpart);
   __m256 eodd = _mm256_fmadd_ps(f2, _mm256_set1_ps((float)0.00187757667519147912699),
                                 _mm256_set1_ps((float)0.0558263180532956664775));
   __m256 eeven = _mm256_fmadd_ps(f2, _mm256_set1_ps((float)0.00898934009049466391101),
                                  _mm256_set1_ps((float)0.240153617044375388211));
   eodd = _mm256_fmadd_ps(f2, eodd, _mm256_set1_ps((float)0.693153073200168932794));
   eeven = _mm256_fmadd_ps(f2, eeven, _mm256_set1_ps((float)1.000000000000000000000));
   __m256 r = _mm256_mul_ps(scale, _mm256_fmadd_ps(eodd, fpart, eeven));
   r = sel8(_mm256_cmp_ps(t, t, _CMP_UNORD_Q), t, r);   /* NaN passes */
   /* lp_build_pow: 0 for x == 0 */
   return sel8(_mm256_cmp_ps(x, zero, _CMP_EQ_OQ), zero, r);
}

T_AVX2 static void t_lit_pows8(const float *x, const float *y, float *out)
{
   _mm256_storeu_ps(out, pow8(_mm256_loadu_ps(x), _mm256_loadu_ps(y)));
}

/* DP3 = (z*z' + y*y') + x*x' of three lanes-of-eight against a constant */
T_AVX2 static inline __m256 dp3_8(const __m256 v[3], const float *c)
{
   return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(v[2], _mm256_set1_ps(c[2])),
                                      _mm256_mul_ps(v[1], _mm256_set1_ps(c[1]))),
                        _mm256_mul_ps(v[0], _mm256_set1_ps(c[0])));
}

/* DP3 of two lane vectors */
T_AVX2 static inline __m256 dp3_8v(const __m256 a[3], const __m256 b[3])
{
   return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a[2], b[2]), _mm256_mul_ps(a[1], b[1])),
                        _mm256_mul_ps(a[0], b[0]));
}

/* max(x, 0) as max0: x > 0 ? x : +0 */
T_AVX2 static inline __m256 max0_8(__m256 x)
{
   const __m256 zero = _mm256_setzero_ps();
   return sel8(_mm256_cmp_ps(x, zero, _CMP_GT_OQ), x, zero);
}

/* light_vertex for the batch's vertices first..first+n-1, eight at a time
 * (a last group of fewer repeats its last vertex in the unused lanes). */
/* normalize3 of three lanes-of-eight: v * rsq(dp3(v, v)), rsq = 1/sqrt(|x|) */
T_AVX2 static inline void normalize3_8(__m256 v[3])
{
   const __m256 d = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(v[2], v[2]),
                                                _mm256_mul_ps(v[1], v[1])),
                                  _mm256_mul_ps(v[0], v[0]));
   const __m256 r = _mm256_div_ps(_mm256_set1_ps(1.0f),
                                  _mm256_sqrt_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), d)));
   for (int k = 0; k < 3; k++)
      v[k] = _mm256_mul_ps(v[k], r);
}

/* sides: 1, or 2 with two-sided lighting, a constant of each
 * instance (light_simd), so that the faces' loops unroll and their lane
 * vectors stay in registers */
T_AVX2 static inline __attribute__((always_inline)) void
light_simd_sides(const struct fgl_context *ctx, const struct t_light_batch *lb,
                 const struct fgl_vertex_view *in, unsigned first, unsigned n,
                 struct t_vertex *out, const int sides)
{
   const struct t_light_key *key = &lb->key;
   const struct t_light_products *P = &lb->P;
   const struct fgl_lighting_derived *ld = &ctx->_Lighting;
   const struct t_material_source *src = lb->src;
   const float *inv = ctx->ModelviewStack.Top->inv;
   const float *mv = ctx->ModelviewStack.Top->m;
   const __m256 sign = _mm256_set1_ps(-0.0f);

   for (unsigned g = first; g < first + n; g += 8) {
      const unsigned cnt = first + n - g < 8 ? first + n - g : 8;
      /* the normals, structure of arrays (each a float[4] slot, or the
       * current normal for every vertex: stride 0) */
      __m256 nv[3], iv[4];
      t_soa8_load4(lb->normal + (size_t)g * lb->nstride, lb->nstride, cnt, iv);
      /* transform_normal */
      if (key->eye) {
         for (int r = 0; r < 3; r++)
            nv[r] = dp3_8(iv, inv + 4 * r);
      } else {
         for (int k = 0; k < 3; k++)
            nv[k] = iv[k];
      }
      if (key->normalize) {
         /* normalize3: n * rsq(dp3(n, n)), rsq = 1/sqrt(|x|) */
         const __m256 d = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(nv[2], nv[2]),
                                                      _mm256_mul_ps(nv[1], nv[1])),
                                        _mm256_mul_ps(nv[0], nv[0]));
         const __m256 r = _mm256_div_ps(_mm256_set1_ps(1.0f),
                                        _mm256_sqrt_ps(_mm256_andnot_ps(sign, d)));
         for (int k = 0; k < 3; k++)
            nv[k] = _mm256_mul_ps(nv[k], r);
      } else if (key->rescale) {
         const __m256 s = _mm256_set1_ps(ld->NormalScale);
         for (int k = 0; k < 3; k++)
            nv[k] = _mm256_mul_ps(nv[k], s);
      }

      /* the eye position V (t_mul_mad_chain, xyz), in eye space only
       * (else 0), and the local viewer's normalised eye vector */
      __m256 V[3] = { _mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps() };
      if (key->eye) {
         __m256 p[4];
         t_soa8_load4(fgl_vv_attr(in, g, FGL_ATTR_POS), in->stride, cnt, p);
         const __m256 px = p[0], py = p[1], pz = p[2], pw = p[3];
         for (int r = 0; r < 3; r++) {
            __m256 acc = _mm256_mul_ps(px, _mm256_set1_ps(mv[r]));
            acc = _mm256_add_ps(_mm256_mul_ps(py, _mm256_set1_ps(mv[4 + r])), acc);
            acc = _mm256_add_ps(_mm256_mul_ps(pz, _mm256_set1_ps(mv[8 + r])), acc);
            acc = _mm256_add_ps(_mm256_mul_ps(pw, _mm256_set1_ps(mv[12 + r])), acc);
            V[r] = acc;
         }
      }
      __m256 eye_hat[3];
      if (key->local_viewer && !key->shininess_is_zero) {
         for (int k = 0; k < 3; k++)
            eye_hat[k] = V[k];
         normalize3_8(eye_hat);
      }

      /* the faces' materials where they vary per vertex (the colour
       * tracked by glColorMaterial): m[face][property][component], the
       * properties ambient, diffuse, specular, emission */
      __m256 m[2][4][4];
      for (int s = 0; s < sides; s++) {
         if (!(P->vary_scene[s] || P->vary_diffuse[s] || P->vary_specular[s]))
            continue;
         for (int prop = 0; prop < 4; prop++) {
            const struct t_material_source *ms = &src[FGL_ATTR_MAT_FRONT_AMBIENT + 2 * prop + s];
            t_soa8_load4(ms->ptr + (size_t)g * ms->stride, ms->stride, cnt, m[s][prop]);
         }
      }

      /* the colours: c[face][0 primary, 1 secondary][component]; the
       * scene colour emission + ambient * global ambient (scene_colour) */
      __m256 c[2][2][3];
      for (int s = 0; s < sides; s++)
         for (int k = 0; k < 3; k++) {
            c[s][0][k] = P->vary_scene[s]
                            ? _mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(ctx->Light.Model.Ambient[k]),
                                                          m[s][0][k]),
                                            m[s][3][k])
                            : _mm256_set1_ps(P->scene[s][k]);
            c[s][1][k] = _mm256_setzero_ps();
         }
      for (unsigned lights = ld->EnabledLights; lights; lights &= lights - 1) {
         const int i = __builtin_ctz(lights);   /* in index order */
         const struct fgl_light_derived *d = &ld->Light[i];
         const struct fgl_light *lt = &ctx->Light.Light[i];

         /* the direction to the light VP (normalised, from the vertex for a
          * positional light), its squared distance and the distance
          * attenuation (no spot lights here) */
         __m256 VP[3], dist2 = _mm256_setzero_ps(), inv_dist = _mm256_setzero_ps();
         if (d->Positional) {
            for (int k = 0; k < 3; k++)
               VP[k] = _mm256_sub_ps(_mm256_set1_ps(d->Position[k]), V[k]);
            dist2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(VP[2], VP[2]),
                                                _mm256_mul_ps(VP[1], VP[1])),
                                  _mm256_mul_ps(VP[0], VP[0]));
            inv_dist = _mm256_div_ps(_mm256_set1_ps(1.0f),
                                     _mm256_sqrt_ps(_mm256_andnot_ps(sign, dist2)));
            for (int k = 0; k < 3; k++)
               VP[k] = _mm256_mul_ps(VP[k], inv_dist);
         } else {
            for (int k = 0; k < 3; k++)
               VP[k] = _mm256_set1_ps(d->Position[k]);
         }
         const bool attenuated = d->Attenuated && d->Positional;
         __m256 att = _mm256_set1_ps(1.0f);
         if (attenuated) {
            const __m256 dist = _mm256_sqrt_ps(_mm256_andnot_ps(sign, dist2));
            const __m256 k = _mm256_add_ps(
               _mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(lt->QuadraticAttenuation), dist2),
                             _mm256_mul_ps(_mm256_set1_ps(lt->LinearAttenuation), dist)),
               _mm256_mul_ps(_mm256_set1_ps(lt->ConstantAttenuation),
                             _mm256_mul_ps(inv_dist, dist)));
            att = _mm256_div_ps(_mm256_set1_ps(1.0f), k);
         }

         /* the half vector */
         __m256 H[3];
         if (!key->shininess_is_zero) {
            if (key->local_viewer) {
               for (int k = 0; k < 3; k++)
                  H[k] = _mm256_sub_ps(VP[k], eye_hat[k]);
               normalize3_8(H);
            } else if (!d->Positional) {
               for (int k = 0; k < 3; k++)
                  H[k] = _mm256_set1_ps(d->HalfVector[k]);
            } else {
               H[0] = VP[0];
               H[1] = VP[1];
               H[2] = _mm256_add_ps(VP[2], _mm256_set1_ps(1.0f));
               normalize3_8(H);
            }
         }

         const __m256 nd = dp3_8v(nv, VP);
         const __m256 nh = key->shininess_is_zero ? nd : dp3_8v(nv, H);
         for (int s = 0; s < sides; s++) {
            const __m256 snd = s ? _mm256_xor_ps(nd, sign) : nd;
            __m256 diffuse = max0_8(snd);
            __m256 specular;
            if (!key->shininess_is_zero) {
               /* LIT: z = nd <= 0 ? 0 : pow(max(nh, 0), exponent) */
               const __m256 snh = s ? _mm256_xor_ps(nh, sign) : nh;
               const __m256 pw = pow8(max0_8(snh), _mm256_set1_ps(lb->exponent[s]));
               specular = sel8(_mm256_cmp_ps(_mm256_setzero_ps(), snd, _CMP_GE_OQ),
                               _mm256_setzero_ps(), pw);
            } else {
               /* emit_degenerate_lit: 0 < nd ? 1 : 0 (never attenuated
                * here: light_simd_eligible) */
               specular = sel8(_mm256_cmp_ps(_mm256_setzero_ps(), snd, _CMP_LT_OQ),
                               _mm256_set1_ps(1.0f), _mm256_setzero_ps());
            }
            if (attenuated) {
               /* lt.ambient = att; lt.diffuse *= att; lt.specular *= att */
               diffuse = _mm256_mul_ps(diffuse, att);
               specular = _mm256_mul_ps(specular, att);
            }
            /* the light products, uniform or per vertex (light_product:
             * light * material) */
            __m256 amb[3], dif[3], spe[3];
            for (int k = 0; k < 3; k++) {
               amb[k] = P->vary_ambient[s]
                           ? _mm256_mul_ps(_mm256_set1_ps(lt->Ambient[k]), m[s][0][k])
                           : _mm256_set1_ps(P->ambient[i][s][k]);
               dif[k] = P->vary_diffuse[s]
                           ? _mm256_mul_ps(_mm256_set1_ps(lt->Diffuse[k]), m[s][1][k])
                           : _mm256_set1_ps(P->diffuse[i][s][k]);
               spe[k] = P->vary_specular[s]
                           ? _mm256_mul_ps(_mm256_set1_ps(lt->Specular[k]), m[s][2][k])
                           : _mm256_set1_ps(P->specular[i][s][k]);
            }
            __m256 *c0 = c[s][0], *c1 = key->separate ? c[s][1] : c[s][0];
            for (int k = 0; k < 3; k++)
               c0[k] = attenuated ? _mm256_add_ps(_mm256_mul_ps(att, amb[k]), c0[k])
                                  : _mm256_add_ps(amb[k], c0[k]);
            for (int k = 0; k < 3; k++)
               c0[k] = _mm256_add_ps(_mm256_mul_ps(diffuse, dif[k]), c0[k]);
            for (int k = 0; k < 3; k++)
               c1[k] = _mm256_add_ps(_mm256_mul_ps(specular, spe[k]), c1[k]);
         }
      }

      /* back into the vertices: alpha the diffuse alpha, the secondary's 1 */
      for (int s = 0; s < sides; s++) {
         const struct t_material_source *dsrc = &src[FGL_ATTR_MAT_FRONT_DIFFUSE + s];
         __m256 alpha;
         if (dsrc->stride) {
            float a[8];
            for (unsigned l = 0; l < 8; l++)
               a[l] = dsrc->ptr[(size_t)(g + (l < cnt ? l : cnt - 1)) * dsrc->stride + 3];
            alpha = _mm256_loadu_ps(a);
         } else {
            alpha = _mm256_set1_ps(dsrc->ptr[3]);
         }
         /* clamped as t_transform's clamp01x4 does it, lane by lane:
          * minps(x, 1) (NaN -> 1), then maxps(., 0) */
         const __m256 one = _mm256_set1_ps(1.0f), zero = _mm256_setzero_ps();
         __m256 prim[4] = { c[s][0][0], c[s][0][1], c[s][0][2], alpha };
         __m256 sec[4] = { c[s][1][0], c[s][1][1], c[s][1][2], one };
         for (int k = 0; k < 4; k++) {
            prim[k] = _mm256_max_ps(_mm256_min_ps(prim[k], one), zero);
            sec[k] = _mm256_max_ps(_mm256_min_ps(sec[k], one), zero);
         }
         float *base = out[g].r.attr[2 * s];
         t_soa8_store4(prim, base, sizeof(out[0]) / sizeof(float), cnt);
         t_soa8_store4(sec, base + 4, sizeof(out[0]) / sizeof(float), cnt);
      }
   }
}

T_AVX2 static void light_simd(const struct fgl_context *ctx, const struct t_light_batch *lb,
                              const struct fgl_vertex_view *in, unsigned first, unsigned n,
                              struct t_vertex *out)
{
   if (lb->key.twoside)
      light_simd_sides(ctx, lb, in, first, n, out, 2);
   else
      light_simd_sides(ctx, lb, in, first, n, out, 1);
}
#endif

void t_lit_pows(const float *x, const float *y, float *out, unsigned n)
{
   unsigned k = 0;
#ifdef T_LIGHT_SIMD
   __builtin_cpu_init();
   if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
      for (; k + 8 <= n; k += 8)
         t_lit_pows8(x + k, y + k, out + k);
#endif
   for (; k < n; k++)
      out[k] = m_gallivm_pow(x[k], y[k]);
}

/* Whether light_simd lights this batch (t_light_prepare, after the
 * products): no spot light, a shininess that does not vary per vertex
 * (and is not 0 with an attenuated light), and a CPU with AVX2 and FMA. */
static bool light_simd_eligible(const struct fgl_context *ctx, const struct t_light_batch *lb)
{
#ifdef T_LIGHT_SIMD
   const struct fgl_lighting_derived *ld = &ctx->_Lighting;
   /* FIXGL_KERNELS=reference: light_vertex alone, which api/lit_kernels
    * compares this path with */
   if (!ld->EnabledLights || ctx->_Raster.reference_kernels)
      return false;
   for (int s = 0; s < (lb->key.twoside ? 2 : 1); s++)
      if (lb->src[FGL_ATTR_MAT_FRONT_SHININESS + s].stride != 0)
         return false;
   for (unsigned lights = ld->EnabledLights; lights; lights &= lights - 1) {
      const struct fgl_light_derived *d = &ld->Light[__builtin_ctz(lights)];
      /* no spot light; no attenuated light with the degenerate shininess
       * (whose LIT exponent is the clamped n.VP of each vertex) */
      if (d->Spot || (d->Attenuated && d->Positional && lb->key.shininess_is_zero))
         return false;
   }
   __builtin_cpu_init();
   return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
   (void)ctx;
   (void)lb;
   return false;
#endif
}

void t_light_prepare(const struct fgl_context *ctx, const struct fgl_vertex_view *in,
                     struct t_light_batch *lb)
{
   const struct fgl_lighting_derived *ld = &ctx->_Lighting;
   const struct fgl_vbo *vbo = &ctx->Vbo;
   struct t_light_key key = {
      .eye = ld->NeedEyeCoords,
      .normalize = ctx->Transform.Normalize,
      .local_viewer = ctx->Light.Model.LocalViewer,
      .twoside = ctx->Light.Model.TwoSide,
      .separate = ctx->Light.Model.ColorControl == GL_SEPARATE_SPECULAR_COLOR,
   };
   const bool rescale_match = key.eye == ctx->Transform.RescaleNormals;
   key.rescale = !key.normalize && rescale_match;

   const bool color_varying = vbo->attr_size[FGL_ATTR_COLOR0] != 0;
   const unsigned color_mats = ctx->Light.ColorMaterialEnabled && color_varying
                                  ? ctx->Light._ColorMaterialBitmask : 0;

   struct t_material_source *src = lb->src;
   for (int a = FGL_ATTR_MAT_FIRST; a < FGL_ATTR_COUNT; a++) {
      if (color_mats & FGL_MAT_BIT(a))
         src[a].ptr = fgl_vbo_attr_ptr(ctx, in, FGL_ATTR_COLOR0, &src[a].stride);
      else
         src[a].ptr = fgl_vbo_attr_ptr(ctx, in, (enum fgl_vbo_attr)a, &src[a].stride);
   }
   lb->normal = fgl_vbo_attr_ptr(ctx, in, FGL_ATTR_NORMAL, &lb->nstride);
   lb->simd = false;
   lb->shade8 = false;
   lb->clamped = 0;

   /* GL_FIXGL_cook_torrance: m_shade_point for both faces, with the
    * batch's lights prepared here once; the fog coordinate is |P.z| of the
    * eye position it lit with (shading.md) */
   lb->shade = ctx->Light.Reflectance[0].Model == GL_COOK_TORRANCE_FIXGL ||
               ctx->Light.Reflectance[1].Model == GL_COOK_TORRANCE_FIXGL;
   if (lb->shade) {
      fgl_update_shade_env(ctx, &lb->env);
      lb->env.color_material = 0;   /* src already reads the tracked colours */
      t_eye_normal_init(ctx, &lb->en);
      lb->key = key;
      lb->eye_position = true;
      lb->shade8 = shade8_prepare(ctx, in, lb);
      return;
   }

   /* check_active_shininess: a shininess that varies, or is not 0 (the
    * colour never tracks shininess: glColorMaterial refuses it) */
   bool shininess_active = false;
   for (int s = 0; s < (key.twoside ? 2 : 1); s++) {
      const int a = FGL_ATTR_MAT_FRONT_SHININESS + s;
      shininess_active |= src[a].stride != 0 || ctx->Current.Attrib[a][0] != 0.0f;
   }
   key.shininess_is_zero = !shininess_active;
   lb->key = key;

   /* the uniform scene colours and products, with the caller's
    * floating-point environment (no flush of denormals) */
   struct t_light_products *P = &lb->P;
#if defined(__SSE__) || defined(__x86_64__)
   const unsigned mxcsr = _mm_getcsr();
   _mm_setcsr(mxcsr & ~0x8040u);
#endif
   for (int s = 0; s < (key.twoside ? 2 : 1); s++) {
      const int amb = FGL_ATTR_MAT_FRONT_AMBIENT + s, dif = FGL_ATTR_MAT_FRONT_DIFFUSE + s,
                spe = FGL_ATTR_MAT_FRONT_SPECULAR + s, emi = FGL_ATTR_MAT_FRONT_EMISSION + s;
      P->vary_ambient[s] = src[amb].stride != 0;
      P->vary_diffuse[s] = src[dif].stride != 0;
      P->vary_specular[s] = src[spe].stride != 0;
      P->vary_scene[s] = P->vary_ambient[s] || src[emi].stride != 0;
      const struct material m = { src[amb].ptr, src[dif].ptr, src[spe].ptr, src[emi].ptr, 0 };
      if (!P->vary_scene[s])
         scene_colour(ctx, &m, P->scene[s]);
      for (unsigned lights = ld->EnabledLights; lights; lights &= lights - 1) {
         const int i = __builtin_ctz(lights);
         const struct fgl_light *l = &ctx->Light.Light[i];
         if (!P->vary_ambient[s])
            light_product(l->Ambient, m.ambient, P->ambient[i][s]);
         if (!P->vary_diffuse[s])
            light_product(l->Diffuse, m.diffuse, P->diffuse[i][s]);
         if (!P->vary_specular[s])
            light_product(l->Specular, m.specular, P->specular[i][s]);
      }
   }
#if defined(__SSE__) || defined(__x86_64__)
   _mm_setcsr(mxcsr);
#endif

   /* the faces' LIT exponents, when the shininess does not vary per
    * vertex (in the draw's floating-point environment, as per vertex) */
   for (int s = 0; s < 2; s++) {
      const struct t_material_source *sh = &src[FGL_ATTR_MAT_FRONT_SHININESS + s];
      lb->exponent[s] = sh->stride ? 0.0f : lit_exponent(sh->ptr[0]);
   }
   lb->simd = light_simd_eligible(ctx, lb);
   lb->clamped = lb->simd ? 2u * (key.twoside ? 2u : 1u) : 0u;

   /* build_lighting asks for the eye position (get_eye_position) for a
    * positional light, or for the local viewer's eye vector when there is a
    * specular term; both only happen in eye space */
   bool eye_position = false;
   for (unsigned lights = ld->EnabledLights; lights; lights &= lights - 1) {
      const int i = __builtin_ctz(lights);
      eye_position |= ld->Light[i].Positional || (key.local_viewer && !key.shininess_is_zero);
   }
   lb->eye_position = eye_position;
}

T_FMA_CLONES
void t_light_run(const struct fgl_context *ctx, struct t_light_batch *lb,
                 const struct fgl_vertex_view *in, unsigned first, unsigned n,
                 struct t_vertex *out)
{
   if (lb->shade) {
      if (lb->shade8)
         light_shade8(ctx, lb, in, first, n, out);
      else
         light_shade(ctx, lb, in, first, n, out);
      return;
   }
   const struct t_light_key *key = &lb->key;
   const struct t_material_source *src = lb->src;
   const float *mv = ctx->ModelviewStack.Top->m;
#ifdef T_LIGHT_SIMD
   if (lb->simd) {
      light_simd(ctx, lb, in, first, n, out);
      return;
   }
#endif
   /* the faces' LIT exponents: from the batch when the shininess does not
    * vary per vertex */
#define EXPONENT(s)                                                             \
   (src[FGL_ATTR_MAT_FRONT_SHININESS + (s)].stride                              \
       ? lit_exponent(MAT(FGL_ATTR_MAT_FRONT_SHININESS + (s))[0]) : lb->exponent[s])

   for (unsigned i = first; i < first + n; i++) {
      float nrm[3], V[4] = { 0, 0, 0, 1 };
      transform_normal(ctx, key, lb->normal + (size_t)i * lb->nstride, nrm);
      if (key->eye) {
         /* eye position: the modelview's column MUL/MAD chain */
         t_mul_mad_chain(V, mv, fgl_vv_attr(in, i, FGL_ATTR_POS));
      }
#define MAT(a) (src[a].ptr + (size_t)i * src[a].stride)
      const struct material mat[2] = {
         { MAT(FGL_ATTR_MAT_FRONT_AMBIENT), MAT(FGL_ATTR_MAT_FRONT_DIFFUSE),
           MAT(FGL_ATTR_MAT_FRONT_SPECULAR), MAT(FGL_ATTR_MAT_FRONT_EMISSION),
           EXPONENT(0) },
         { MAT(FGL_ATTR_MAT_BACK_AMBIENT), MAT(FGL_ATTR_MAT_BACK_DIFFUSE),
           MAT(FGL_ATTR_MAT_BACK_SPECULAR), MAT(FGL_ATTR_MAT_BACK_EMISSION),
           EXPONENT(1) },
      };
      light_vertex(ctx, key, &lb->P, nrm, V, mat, out[i].r.attr);
   }
#undef MAT
#undef EXPONENT
}
