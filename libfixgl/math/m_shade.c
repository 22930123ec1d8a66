/*
 * fixgl's lighting equations at one point: include/fixgl/shading.md "The
 * equations", transcribed operation by operation.  Every binary operation
 * is one rounded float operation (-ffp-contract=off, no fmaf), in the
 * order shading.md writes it (left to right where it writes a chain):
 *   dot(a, b)       = (a.x*b.x + a.y*b.y) + a.z*b.z
 *   normalize(v)    = v * (1/sqrt(dot(v, v)))
 *   kc + kl*d + kq*d*d = (kc + kl*d) + (kq*d)*d
 * and pow is gallivm's approximation (m_gallivm_pow), the one llvmpipe
 * runs for GLSL's pow() in the conformance reference
 * [S: gallivm/lp_bld_arit.c:lp_build_pow], behind spow's rules for 0.
 * This code is not the per-vertex Blinn-Phong of GL_SMOOTH/GL_FLAT (that
 * is tnl/t_light.c, the oracle's vertex program); it lights per vertex
 * for Cook-Torrance and per fragment for GL_PHONG_WIN.
 *
 * Speed without changing a bit: what does not depend on the point (the
 * directions of directional lights and their half vectors without local
 * viewer, p.xyz / p.w, the spot factor of directional lights, the
 * Cook-Torrance constants) is computed once per batch by m_shade_prepare
 * with the very operations shading.md writes per point; a value whose
 * result is unused (H where ndl <= 0) is not computed; max/min are written
 * inline with fmaxf/fminf's results (below); fmaf is inline in the FMA
 * clone.
 */
#include "math/m_shade.h"

#include <math.h>

#include "math/m_gallivm.h"

#define M_SHADE_PI 3.14159265f

/* The evaluation is compiled twice, with and without the FMA instruction
 * set, and the loader picks the clone the CPU runs (as raster/r_state.h
 * R_FMA_CLONES does for the raster loops): with FMA, m_gallivm_pow's
 * fmaf() is one vfmadd instead of a libm call (and floorf one vroundss).
 * fmaf is the fused operation either way: the same bits. */
/* (Not under ThreadSanitizer, which instruments the clones' resolver, run
 * by the loader before its runtime exists.) */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__) && \
    !defined(__SANITIZE_THREAD__)
/* flatten: m_gallivm_pow and the helpers are inlined into each clone and
 * compiled for its target (an outlined helper would be a default-target
 * function calling libm's fmaf) */
#define M_SHADE_FMA_CLONES __attribute__((target_clones("fma", "default"), flatten))
#else
#define M_SHADE_FMA_CLONES
#endif

static inline float dot3(const float *a, const float *b)
{
   return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void normalize3(float *v)
{
   const float r = 1.0f / sqrtf(dot3(v, v));
   v[0] = v[0] * r;
   v[1] = v[1] * r;
   v[2] = v[2] * r;
}

/* spow(x, e) = e == 0 ? 1 : (x <= 0 ? 0 : pow(x, e)); pow is the common
 * case (GCC would otherwise compile it as a cold path, with libm calls
 * for its floorf) */
static inline float spow(float x, float e)
{
   if (__builtin_expect(e == 0.0f, 0))
      return 1.0f;
   if (__builtin_expect(x <= 0.0f, 0))
      return 0.0f;
   return m_gallivm_pow(x, e);
}

/* max(x, 0) as shading.md's max (fmaxf(x, 0.0f)) returns it, inline:
 * NaN gives 0 and -0 gives +0 (glibc's fmaxf is maxss when neither operand
 * is NaN, x > 0 ? x : 0, and the other operand for a NaN one). */
static inline float max0(float x)
{
   return x > 0.0f ? x : 0.0f;
}

/* clamp to [0, 1] as fminf(fmaxf(x, 0), 1): NaN becomes 0 (max first);
 * fminf(m, 1) of a non-NaN m is minss, m < 1 ? m : 1 */
static inline float clamp01(float x)
{
   const float m = max0(x);
   return m < 1.0f ? m : 1.0f;
}

/* One light's point-independent values: the operations shading.md writes
 * per point, in its order. */
static void prepare_light(const struct m_shade_light *l, struct m_shade_light_prep *lp)
{
   if (l->position[3] != 0.0f) {
      /* p.xyz / p.w of L = p.xyz / p.w - P */
      for (int i = 0; i < 3; i++)
         lp->L[i] = l->position[i] / l->position[3];
      lp->spot = 1.0f;   /* unused: the spot factor varies with L */
   } else {
      /* L = normalize(p.xyz) */
      lp->L[0] = l->position[0];
      lp->L[1] = l->position[1];
      lp->L[2] = l->position[2];
      normalize3(lp->L);
      /* c = dot(-L, normalize(sd)); spot = c >= cos(sc) ? spow(c, se) : 0 */
      lp->spot = 1.0f;
      if (l->spot) {
         const float negL[3] = { -lp->L[0], -lp->L[1], -lp->L[2] };
         const float cs = dot3(negL, l->spot_direction);
         lp->spot = cs >= l->spot_cos_cutoff ? spow(cs, l->spot_exponent) : 0.0f;
      }
   }
   /* H = normalize(L + V) with V = (0, 0, 1) */
   lp->H[0] = lp->L[0] + 0.0f;
   lp->H[1] = lp->L[1] + 0.0f;
   lp->H[2] = lp->L[2] + 1.0f;
   normalize3(lp->H);
}

/* One face's Cook-Torrance constants. */
static void prepare_material(const struct m_shade_material *mat, struct m_shade_material_prep *mp)
{
   const float r = fmaxf(mat->roughness, 1.0f / 32.0f);
   const float alpha = r * r;
   mp->a2 = alpha * alpha;
   mp->a2_minus_1 = mp->a2 - 1.0f;
   mp->k = (r + 1.0f) * (r + 1.0f) / 8.0f;
   mp->one_minus_k = 1.0f - mp->k;
   mp->metal = mat->metalness;
   mp->one_minus_metal = 1.0f - mp->metal;
   mp->f0_dielectric = mat->f0 * mp->one_minus_metal;
}

static inline void prepare(const struct m_shade_env *env, struct m_shade_prep *prep)
{
   for (unsigned li = 0; li < env->num_lights; li++)
      prepare_light(&env->light[li], &prep->light[li]);
   for (int f = 0; f < 2; f++)
      prepare_material(&env->material[f], &prep->material[f]);
}

void m_shade_prepare(struct m_shade_env *env)
{
   prepare(env, &env->prep);
}

/* One face's material at this point: the tracked properties replaced by
 * the vertex colour. */
struct point_material {
   const float *ambient, *diffuse, *specular, *emission;
};

/* H = normalize(L + V): prepared for a directional light without local
 * viewer (fixed), else computed at the point. */
static inline void half_vector(const struct m_shade_light_prep *lp, bool fixed, const float L[3],
                               const float V[3], float H[3])
{
   if (fixed) {
      H[0] = lp->H[0], H[1] = lp->H[1], H[2] = lp->H[2];
      return;
   }
   H[0] = L[0] + V[0], H[1] = L[1] + V[1], H[2] = L[2] + V[2];
   normalize3(H);
}

/* The equations at one point, with the point-independent values of prep. */
static inline __attribute__((always_inline)) void
shade(const struct m_shade_env *env, const struct m_shade_prep *prep, const float n[3],
      const float p[3], bool back, const float color[4], float primary[4], float secondary[4])
{
   /* without two-sided lighting every face is lit as the front one */
   back = back && env->two_side;
   const struct m_shade_material *mat = &env->material[back ? 1 : 0];
   const struct m_shade_material_prep *mp = &prep->material[back ? 1 : 0];
   const unsigned cm = back ? env->color_material >> M_SHADE_CM_BACK_SHIFT
                            : env->color_material;
   const struct point_material m = {
      (cm & M_SHADE_CM_AMBIENT) ? color : mat->ambient,
      (cm & M_SHADE_CM_DIFFUSE) ? color : mat->diffuse,
      (cm & M_SHADE_CM_SPECULAR) ? color : mat->specular,
      (cm & M_SHADE_CM_EMISSION) ? color : mat->emission,
   };
   const bool cook_torrance = mat->model == M_SHADE_COOK_TORRANCE;
   const bool local_viewer = env->local_viewer;

   /* N = normalize(n), -N for the back face */
   float N[3] = { n[0], n[1], n[2] };
   normalize3(N);
   if (back) {
      N[0] = -N[0];
      N[1] = -N[1];
      N[2] = -N[2];
   }
   /* V = local_viewer ? normalize(-P) : (0, 0, 1) */
   float V[3] = { 0.0f, 0.0f, 1.0f };
   if (local_viewer) {
      V[0] = -p[0];
      V[1] = -p[1];
      V[2] = -p[2];
      normalize3(V);
   }

   /* F0 = f0 * (1 - m) + c * m, c the base colour */
   const float *c = m.diffuse;
   float F0[3] = { 0.0f, 0.0f, 0.0f };
   if (cook_torrance) {
      for (int i = 0; i < 3; i++)
         F0[i] = mp->f0_dielectric + c[i] * mp->metal;   /* mix(f0, c, m) */
   }

   /* primary = e_m + a_m * a_g + sum_i light_i */
   float sum[3], spec_sum[3] = { 0.0f, 0.0f, 0.0f };
   for (int i = 0; i < 3; i++)
      sum[i] = m.emission[i] + m.ambient[i] * env->global_ambient[i];

   for (unsigned li = 0; li < env->num_lights; li++) {
      const struct m_shade_light *l = &env->light[li];
      const struct m_shade_light_prep *lp = &prep->light[li];
      const bool positional = l->position[3] != 0.0f;
      float L[3], att, spot;
      if (positional) {
         /* L = p.xyz / p.w - P;  d = sqrt(dot(L, L));  L = L / d */
         for (int i = 0; i < 3; i++)
            L[i] = lp->L[i] - p[i];
         const float d = sqrtf(dot3(L, L));
         for (int i = 0; i < 3; i++)
            L[i] = L[i] / d;
         att = 1.0f / (l->kc + l->kl * d + l->kq * d * d);
         spot = 1.0f;
         if (l->spot) {
            const float negL[3] = { -L[0], -L[1], -L[2] };
            const float cs = dot3(negL, l->spot_direction);
            spot = cs >= l->spot_cos_cutoff ? spow(cs, l->spot_exponent) : 0.0f;
         }
      } else {
         L[0] = lp->L[0];
         L[1] = lp->L[1];
         L[2] = lp->L[2];
         att = 1.0f;
         spot = lp->spot;
      }
      const float ndl = dot3(N, L);
      /* H = normalize(L + V), where a term reads it */
      float H[3];
      const bool fixed_h = !positional && !local_viewer;

      float ambient[3], diffuse[3], specular[3];
      for (int i = 0; i < 3; i++)
         ambient[i] = l->ambient[i] * m.ambient[i];
      if (!cook_torrance) {
         const float fd = max0(ndl);
         float fs = 0.0f;
         if (ndl > 0.0f) {
            half_vector(lp, fixed_h, L, V, H);
            fs = spow(max0(dot3(N, H)), mat->shininess);
         }
         for (int i = 0; i < 3; i++) {
            diffuse[i] = fd * (l->diffuse[i] * m.diffuse[i]);
            specular[i] = ndl > 0.0f ? fs * (l->specular[i] * m.specular[i]) : 0.0f;
         }
      } else {
         const float ndv = dot3(N, V);
         for (int i = 0; i < 3; i++)
            diffuse[i] = ndl > 0.0f ? mp->one_minus_metal * ndl * (l->diffuse[i] * c[i]) : 0.0f;
         if (ndl > 0.0f && ndv > 0.0f) {
            half_vector(lp, fixed_h, L, V, H);
            const float ndh = max0(dot3(N, H));
            const float vdh = max0(dot3(V, H));
            const float a2 = mp->a2, k = mp->k, one_minus_k = mp->one_minus_k;
            const float t = ndh * ndh * mp->a2_minus_1 + 1.0f;
            const float D = a2 / (M_SHADE_PI * t * t);
            const float G = (ndl / (ndl * one_minus_k + k)) * (ndv / (ndv * one_minus_k + k));
            const float q = 1.0f - vdh;
            const float q5 = (q * q) * (q * q) * q;
            const float s = M_SHADE_PI * D * G / (4.0f * ndv);
            for (int i = 0; i < 3; i++) {
               const float F = F0[i] + (1.0f - F0[i]) * q5;
               specular[i] = F * s * l->specular[i];
            }
         } else {
            specular[0] = specular[1] = specular[2] = 0.0f;
         }
      }

      /* light_i = att * spot * (ambient + diffuse [+ specular]) */
      const float f = att * spot;
      if (env->separate_specular) {
         for (int i = 0; i < 3; i++) {
            sum[i] = sum[i] + f * (ambient[i] + diffuse[i]);
            spec_sum[i] = spec_sum[i] + f * specular[i];
         }
      } else {
         for (int i = 0; i < 3; i++)
            sum[i] = sum[i] + f * (ambient[i] + diffuse[i] + specular[i]);
      }
   }

   for (int i = 0; i < 3; i++)
      primary[i] = clamp01(sum[i]);
   primary[3] = clamp01(m.diffuse[3]);
   for (int i = 0; i < 3; i++)
      secondary[i] = env->separate_specular ? clamp01(spec_sum[i]) : 0.0f;
   secondary[3] = 1.0f;
}

/* Per vertex (and from any caller's environment): the point-independent
 * values computed here, as shading.md writes them per point. */
M_SHADE_FMA_CLONES
void m_shade_point(const struct m_shade_env *env, const float n[3], const float p[3],
                   bool back, const float color[4], float primary[4], float secondary[4])
{
   struct m_shade_prep prep;
   prepare(env, &prep);
   shade(env, &prep, n, p, back, color, primary, secondary);
}

/* Per fragment: env->prep, filled once per batch (fgl_update_shade_env). */
M_SHADE_FMA_CLONES
void m_shade_point_prepared(const struct m_shade_env *env, const float n[3], const float p[3],
                      bool back, const float color[4], float primary[4], float secondary[4])
{
   shade(env, &env->prep, n, p, back, color, primary, secondary);
}
