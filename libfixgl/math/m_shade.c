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
 */
#include "math/m_shade.h"

#include <math.h>

#include "math/m_gallivm.h"

#define M_SHADE_PI 3.14159265f

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

/* spow(x, e) = e == 0 ? 1 : (x <= 0 ? 0 : pow(x, e)) */
static inline float spow(float x, float e)
{
   if (e == 0.0f)
      return 1.0f;
   if (x <= 0.0f)
      return 0.0f;
   return m_gallivm_pow(x, e);
}

/* clamp to [0, 1]; NaN becomes 0 (max first) */
static inline float clamp01(float x)
{
   return fminf(fmaxf(x, 0.0f), 1.0f);
}

/* One face's material at this point: the tracked properties replaced by
 * the vertex colour. */
struct point_material {
   const float *ambient, *diffuse, *specular, *emission;
};

void m_shade_point(const struct m_shade_env *env, const float n[3], const float p[3],
                   bool back, const float color[4], float primary[4], float secondary[4])
{
   /* without two-sided lighting every face is lit as the front one */
   back = back && env->two_side;
   const struct m_shade_material *mat = &env->material[back ? 1 : 0];
   const unsigned cm = back ? env->color_material >> M_SHADE_CM_BACK_SHIFT
                            : env->color_material;
   const struct point_material m = {
      (cm & M_SHADE_CM_AMBIENT) ? color : mat->ambient,
      (cm & M_SHADE_CM_DIFFUSE) ? color : mat->diffuse,
      (cm & M_SHADE_CM_SPECULAR) ? color : mat->specular,
      (cm & M_SHADE_CM_EMISSION) ? color : mat->emission,
   };
   const bool cook_torrance = mat->model == M_SHADE_COOK_TORRANCE;

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
   if (env->local_viewer) {
      V[0] = -p[0];
      V[1] = -p[1];
      V[2] = -p[2];
      normalize3(V);
   }

   /* the Cook-Torrance constants of the face */
   float r = 0.0f, a2 = 0.0f, k = 0.0f, metal = 0.0f, F0[3] = { 0.0f, 0.0f, 0.0f };
   const float *c = m.diffuse;   /* the base colour */
   if (cook_torrance) {
      r = fmaxf(mat->roughness, 1.0f / 32.0f);
      const float alpha = r * r;
      a2 = alpha * alpha;
      k = (r + 1.0f) * (r + 1.0f) / 8.0f;
      metal = mat->metalness;
      for (int i = 0; i < 3; i++)
         F0[i] = mat->f0 * (1.0f - metal) + c[i] * metal;   /* mix(f0, c, m) */
   }

   /* primary = e_m + a_m * a_g + sum_i light_i */
   float sum[3], spec_sum[3] = { 0.0f, 0.0f, 0.0f };
   for (int i = 0; i < 3; i++)
      sum[i] = m.emission[i] + m.ambient[i] * env->global_ambient[i];

   for (unsigned li = 0; li < env->num_lights; li++) {
      const struct m_shade_light *l = &env->light[li];
      float L[3], att;
      if (l->position[3] != 0.0f) {
         /* L = p.xyz / p.w - P;  d = sqrt(dot(L, L));  L = L / d */
         for (int i = 0; i < 3; i++)
            L[i] = l->position[i] / l->position[3] - p[i];
         const float d = sqrtf(dot3(L, L));
         for (int i = 0; i < 3; i++)
            L[i] = L[i] / d;
         att = 1.0f / (l->kc + l->kl * d + l->kq * d * d);
      } else {
         L[0] = l->position[0];
         L[1] = l->position[1];
         L[2] = l->position[2];
         normalize3(L);
         att = 1.0f;
      }
      float spot = 1.0f;
      if (l->spot) {
         const float negL[3] = { -L[0], -L[1], -L[2] };
         const float cs = dot3(negL, l->spot_direction);
         spot = cs >= l->spot_cos_cutoff ? spow(cs, l->spot_exponent) : 0.0f;
      }
      const float ndl = dot3(N, L);
      float H[3] = { L[0] + V[0], L[1] + V[1], L[2] + V[2] };
      normalize3(H);

      float ambient[3], diffuse[3], specular[3];
      for (int i = 0; i < 3; i++)
         ambient[i] = l->ambient[i] * m.ambient[i];
      if (!cook_torrance) {
         const float fd = fmaxf(ndl, 0.0f);
         const float fs = ndl > 0.0f ? spow(fmaxf(dot3(N, H), 0.0f), mat->shininess) : 0.0f;
         for (int i = 0; i < 3; i++) {
            diffuse[i] = fd * (l->diffuse[i] * m.diffuse[i]);
            specular[i] = ndl > 0.0f ? fs * (l->specular[i] * m.specular[i]) : 0.0f;
         }
      } else {
         const float ndv = dot3(N, V);
         const float ndh = fmaxf(dot3(N, H), 0.0f);
         const float vdh = fmaxf(dot3(V, H), 0.0f);
         for (int i = 0; i < 3; i++)
            diffuse[i] = ndl > 0.0f ? (1.0f - metal) * ndl * (l->diffuse[i] * c[i]) : 0.0f;
         if (ndl > 0.0f && ndv > 0.0f) {
            const float t = ndh * ndh * (a2 - 1.0f) + 1.0f;
            const float D = a2 / (M_SHADE_PI * t * t);
            const float G = (ndl / (ndl * (1.0f - k) + k)) * (ndv / (ndv * (1.0f - k) + k));
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
      for (int i = 0; i < 3; i++) {
         if (env->separate_specular) {
            sum[i] = sum[i] + f * (ambient[i] + diffuse[i]);
            spec_sum[i] = spec_sum[i] + f * specular[i];
         } else {
            sum[i] = sum[i] + f * (ambient[i] + diffuse[i] + specular[i]);
         }
      }
   }

   for (int i = 0; i < 3; i++)
      primary[i] = clamp01(sum[i]);
   primary[3] = clamp01(m.diffuse[3]);
   for (int i = 0; i < 3; i++)
      secondary[i] = env->separate_specular ? clamp01(spec_sum[i]) : 0.0f;
   secondary[3] = 1.0f;
}
