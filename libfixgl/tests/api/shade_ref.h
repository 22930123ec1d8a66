/*
 * shade_ref.h - include/fixgl/shading.md "The equations" in double
 * precision, written independently of libfixgl's math/m_shade.c (libm's
 * pow, no operation-order rules), for the tests that check fixgl's float
 * evaluation: unit/test_shade.c (m_shade_point) and api/shading.c (the
 * per-vertex Cook-Torrance of rendered primitives).
 */
#ifndef FIXGL_TESTS_SHADE_REF_H
#define FIXGL_TESTS_SHADE_REF_H

#include <math.h>
#include <stdbool.h>

#define SHADE_REF_MAX_LIGHTS 8

struct shade_ref_light {
   double ambient[3], diffuse[3], specular[3];
   double position[4];        /* eye space; w == 0: directional */
   double spot_direction[3];  /* eye space, any length */
   double spot_exponent, spot_cutoff_cos;   /* cutoff_cos < -1: no spot (180) */
   double kc, kl, kq;
};

struct shade_ref_material {
   bool cook_torrance;
   double ambient[3], diffuse[4], specular[3], emission[3];
   double shininess, roughness, metalness, f0;
};

struct shade_ref_env {
   int num_lights;
   struct shade_ref_light light[SHADE_REF_MAX_LIGHTS];
   double global_ambient[3];
   bool local_viewer, separate_specular;
};

static inline double shade_ref_dot(const double *a, const double *b)
{
   return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void shade_ref_normalize(double *v)
{
   const double l = sqrt(shade_ref_dot(v, v));
   v[0] /= l;
   v[1] /= l;
   v[2] /= l;
}

static inline double shade_ref_spow(double x, double e)
{
   return e == 0.0 ? 1.0 : (x <= 0.0 ? 0.0 : pow(x, e));
}

static inline double shade_ref_clamp01(double x)
{
   return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x);
}

/* One face (the caller passes the face's material and, for the back face,
 * the negated normal).  unclamped[]: primary rgb and secondary rgb before
 * the clamp, for error measurements. */
static void shade_ref_point(const struct shade_ref_env *env, const struct shade_ref_material *m,
                            const double n[3], const double P[3], double primary[4],
                            double secondary[3], double unclamped[6])
{
   double N[3] = { n[0], n[1], n[2] };
   shade_ref_normalize(N);
   double V[3] = { 0.0, 0.0, 1.0 };
   if (env->local_viewer) {
      V[0] = -P[0];
      V[1] = -P[1];
      V[2] = -P[2];
      shade_ref_normalize(V);
   }
   double sum[3], spec[3] = { 0.0, 0.0, 0.0 };
   for (int k = 0; k < 3; k++)
      sum[k] = m->emission[k] + m->ambient[k] * env->global_ambient[k];
   for (int i = 0; i < env->num_lights; i++) {
      const struct shade_ref_light *l = &env->light[i];
      double L[3], att = 1.0;
      if (l->position[3] != 0.0) {
         for (int k = 0; k < 3; k++)
            L[k] = l->position[k] / l->position[3] - P[k];
         const double d = sqrt(shade_ref_dot(L, L));
         for (int k = 0; k < 3; k++)
            L[k] /= d;
         att = 1.0 / (l->kc + l->kl * d + l->kq * d * d);
      } else {
         for (int k = 0; k < 3; k++)
            L[k] = l->position[k];
         shade_ref_normalize(L);
      }
      double spot = 1.0;
      if (l->spot_cutoff_cos >= -1.0) {
         double sd[3] = { l->spot_direction[0], l->spot_direction[1], l->spot_direction[2] };
         shade_ref_normalize(sd);
         const double c = -shade_ref_dot(L, sd);
         spot = c >= l->spot_cutoff_cos ? shade_ref_spow(c, l->spot_exponent) : 0.0;
      }
      const double ndl = shade_ref_dot(N, L);
      double H[3] = { L[0] + V[0], L[1] + V[1], L[2] + V[2] };
      shade_ref_normalize(H);
      double diffuse[3], specular[3] = { 0.0, 0.0, 0.0 };
      if (!m->cook_torrance) {
         const double s = ndl > 0.0 ? shade_ref_spow(fmax(shade_ref_dot(N, H), 0.0),
                                                      m->shininess) : 0.0;
         for (int k = 0; k < 3; k++) {
            diffuse[k] = fmax(ndl, 0.0) * l->diffuse[k] * m->diffuse[k];
            specular[k] = s * l->specular[k] * m->specular[k];
         }
      } else {
         const double r = fmax(m->roughness, 1.0 / 32.0), a2 = r * r * r * r;
         const double ndv = shade_ref_dot(N, V);
         const double ndh = fmax(shade_ref_dot(N, H), 0.0), vdh = fmax(shade_ref_dot(V, H), 0.0);
         for (int k = 0; k < 3; k++)
            diffuse[k] = ndl > 0.0 ? (1.0 - m->metalness) * ndl * l->diffuse[k] * m->diffuse[k]
                                   : 0.0;
         if (ndl > 0.0 && ndv > 0.0) {
            const double t = ndh * ndh * (a2 - 1.0) + 1.0;
            const double D = a2 / (M_PI * t * t);
            const double kk = (r + 1.0) * (r + 1.0) / 8.0;
            const double G = ndl / (ndl * (1.0 - kk) + kk) * ndv / (ndv * (1.0 - kk) + kk);
            const double q5 = pow(1.0 - vdh, 5.0);
            for (int k = 0; k < 3; k++) {
               const double F0 = m->f0 * (1.0 - m->metalness) + m->diffuse[k] * m->metalness;
               const double F = F0 + (1.0 - F0) * q5;
               specular[k] = F * M_PI * D * G / (4.0 * ndv) * l->specular[k];
            }
         }
      }
      for (int k = 0; k < 3; k++) {
         const double a = l->ambient[k] * m->ambient[k];
         if (env->separate_specular) {
            sum[k] += att * spot * (a + diffuse[k]);
            spec[k] += att * spot * specular[k];
         } else {
            sum[k] += att * spot * (a + diffuse[k] + specular[k]);
         }
      }
   }
   for (int k = 0; k < 3; k++) {
      unclamped[k] = sum[k];
      unclamped[3 + k] = spec[k];
      primary[k] = shade_ref_clamp01(sum[k]);
      secondary[k] = shade_ref_clamp01(spec[k]);
   }
   primary[3] = shade_ref_clamp01(m->diffuse[3]);
}

#endif /* FIXGL_TESTS_SHADE_REF_H */
