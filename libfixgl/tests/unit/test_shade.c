/*
 * test_shade.c - unit tests of math/m_shade.c (m_shade_point) against
 * include/fixgl/shading.md evaluated in double precision (../api/
 * shade_ref.h, libm's pow), and of fgl_update_shade_env (main/light.c):
 *
 *   random      many random lights (directional, point with attenuation,
 *               spot), materials (Blinn-Phong shininess 0..128,
 *               Cook-Torrance roughness 0.2..1, metalness, f0), local or
 *               infinite viewer, separate specular or not, both faces:
 *               |float - double| per channel within a bound that covers
 *               float rounding and gallivm's pow (points next to a
 *               discontinuity of the equations -- n.l, n.v or the spot
 *               cosine at its threshold -- are skipped)
 *   low rough.  roughness 0.05 and below the 1/32 clamp, relative bound
 *   rules      spow's 0 rules, the spot cone, two-sided faces, colour
 *               material bits, the secondary colour, the clamp, NaN
 *   env         fgl_update_shade_env from a context's state
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <GL/osmesa.h>
#include <fixgl/fixgl.h>

#include "context.h"
#include "math/m_shade.h"

#include "check.h"
#include "shade_ref.h"

static uint64_t rng_state = 0x9e3779b97f4a7c15ull;

static float frand(float lo, float hi)
{
   rng_state ^= rng_state << 13;
   rng_state ^= rng_state >> 7;
   rng_state ^= rng_state << 17;
   return lo + (hi - lo) * (float)((rng_state >> 40) & 0xffffff) / 16777216.0f;
}

static void rand_color(float c[4], float lo, float hi)
{
   for (int k = 0; k < 3; k++)
      c[k] = frand(lo, hi);
   c[3] = frand(0.0f, 1.0f);
}

static void rand_dir(float v[3])
{
   float l;
   do {
      for (int k = 0; k < 3; k++)
         v[k] = frand(-1.0f, 1.0f);
      l = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
   } while (l < 0.05f || l > 1.0f);
}

/* The double environment of a float one (the same float values). */
static void to_ref(const struct m_shade_env *e, struct shade_ref_env *r)
{
   memset(r, 0, sizeof(*r));
   r->num_lights = (int)e->num_lights;
   for (unsigned i = 0; i < e->num_lights; i++) {
      const struct m_shade_light *l = &e->light[i];
      struct shade_ref_light *rl = &r->light[i];
      for (int k = 0; k < 3; k++) {
         rl->ambient[k] = l->ambient[k];
         rl->diffuse[k] = l->diffuse[k];
         rl->specular[k] = l->specular[k];
         rl->spot_direction[k] = l->spot_direction[k];
      }
      for (int k = 0; k < 4; k++)
         rl->position[k] = l->position[k];
      rl->spot_exponent = l->spot_exponent;
      rl->spot_cutoff_cos = l->spot ? l->spot_cos_cutoff : -2.0;
      rl->kc = l->kc;
      rl->kl = l->kl;
      rl->kq = l->kq;
   }
   for (int k = 0; k < 3; k++)
      r->global_ambient[k] = e->global_ambient[k];
   r->local_viewer = e->local_viewer;
   r->separate_specular = e->separate_specular;
}

static void to_ref_material(const struct m_shade_material *m, const float *color,
                            unsigned cm, struct shade_ref_material *r)
{
   const float *amb = cm & M_SHADE_CM_AMBIENT ? color : m->ambient;
   const float *dif = cm & M_SHADE_CM_DIFFUSE ? color : m->diffuse;
   const float *spe = cm & M_SHADE_CM_SPECULAR ? color : m->specular;
   const float *emi = cm & M_SHADE_CM_EMISSION ? color : m->emission;
   r->cook_torrance = m->model == M_SHADE_COOK_TORRANCE;
   for (int k = 0; k < 3; k++) {
      r->ambient[k] = amb[k];
      r->diffuse[k] = dif[k];
      r->specular[k] = spe[k];
      r->emission[k] = emi[k];
   }
   r->diffuse[3] = dif[3];
   r->shininess = m->shininess;
   r->roughness = m->roughness;
   r->metalness = m->metalness;
   r->f0 = m->f0;
}

/* Whether the point is within eps of a discontinuity of the equations for
 * one of the lights (n.l = 0, n.v = 0, the spot cosine at its cutoff). */
static bool near_discontinuity(const struct shade_ref_env *r, const double n[3],
                               const double P[3], double eps)
{
   double N[3] = { n[0], n[1], n[2] }, V[3] = { 0, 0, 1 };
   shade_ref_normalize(N);
   if (r->local_viewer) {
      V[0] = -P[0];
      V[1] = -P[1];
      V[2] = -P[2];
      shade_ref_normalize(V);
   }
   if (fabs(shade_ref_dot(N, V)) < eps)
      return true;
   for (int i = 0; i < r->num_lights; i++) {
      const struct shade_ref_light *l = &r->light[i];
      double L[3];
      for (int k = 0; k < 3; k++)
         L[k] = l->position[3] != 0.0 ? l->position[k] / l->position[3] - P[k] : l->position[k];
      shade_ref_normalize(L);
      if (fabs(shade_ref_dot(N, L)) < eps)
         return true;
      if (l->spot_cutoff_cos >= -1.0) {
         double sd[3] = { l->spot_direction[0], l->spot_direction[1], l->spot_direction[2] };
         shade_ref_normalize(sd);
         if (fabs(-shade_ref_dot(L, sd) - l->spot_cutoff_cos) < eps)
            return true;
      }
   }
   return false;
}

/* A random environment: 1-4 lights of every kind, dim enough that most
 * sums stay below the clamp. */
static void rand_env(struct m_shade_env *e, float rough_lo, float rough_hi)
{
   memset(e, 0, sizeof(*e));
   e->num_lights = 1 + (unsigned)frand(0.0f, 3.999f);
   for (unsigned i = 0; i < e->num_lights; i++) {
      struct m_shade_light *l = &e->light[i];
      rand_color(l->ambient, 0.0f, 0.1f);
      rand_color(l->diffuse, 0.0f, 0.4f);
      rand_color(l->specular, 0.0f, 0.4f);
      const int kind = (int)frand(0.0f, 2.999f);   /* directional, point, spot */
      if (kind == 0) {
         rand_dir(l->position);
         l->position[3] = 0.0f;
      } else {
         const float w = frand(0.5f, 2.0f);
         for (int k = 0; k < 3; k++)
            l->position[k] = frand(-4.0f, 4.0f) * w;
         l->position[3] = w;
         l->kc = frand(0.5f, 1.5f);
         l->kl = frand(0.0f, 0.3f);
         l->kq = frand(0.0f, 0.1f);
      }
      if (kind == 0 || kind == 1) {
         l->kc = kind == 0 ? 1.0f : l->kc;
      }
      if (kind == 2) {
         float sd[3];
         rand_dir(sd);
         const float r = 1.0f / sqrtf(sd[0] * sd[0] + sd[1] * sd[1] + sd[2] * sd[2]);
         for (int k = 0; k < 3; k++)
            l->spot_direction[k] = sd[k] * r;
         l->spot = true;
         l->spot_exponent = frand(0.0f, 1.0f) < 0.2f ? 0.0f : frand(0.0f, 128.0f);
         l->spot_cos_cutoff = cosf(frand(10.0f, 90.0f) * 3.14159265f / 180.0f);
      }
   }
   rand_color(e->global_ambient, 0.0f, 0.2f);
   e->local_viewer = frand(0.0f, 1.0f) < 0.5f;
   e->two_side = true;
   e->separate_specular = frand(0.0f, 1.0f) < 0.5f;
   for (int f = 0; f < 2; f++) {
      struct m_shade_material *m = &e->material[f];
      m->model = frand(0.0f, 1.0f) < 0.5f ? M_SHADE_BLINN_PHONG : M_SHADE_COOK_TORRANCE;
      rand_color(m->ambient, 0.0f, 0.5f);
      rand_color(m->diffuse, 0.0f, 1.0f);
      rand_color(m->specular, 0.0f, 1.0f);
      rand_color(m->emission, 0.0f, 0.1f);
      const float u = frand(0.0f, 1.0f);
      m->shininess = u < 0.1f ? 0.0f : u < 0.2f ? 128.0f : frand(0.0f, 128.0f);
      m->roughness = frand(rough_lo, rough_hi);
      m->metalness = frand(0.0f, 1.0f) < 0.3f ? 1.0f : frand(0.0f, 1.0f);
      m->f0 = frand(0.0f, 0.2f);
   }
   e->color_material = (unsigned)frand(0.0f, 255.999f);
}

/* Runs `count` random points; returns the largest error seen and the
 * number of points compared. */
static double run_random(int count, float rough_lo, float rough_hi, bool relative,
                         int *compared)
{
   double worst = 0.0;
   *compared = 0;
   for (int it = 0; it < count; it++) {
      struct m_shade_env e;
      rand_env(&e, rough_lo, rough_hi);
      struct shade_ref_env r;
      to_ref(&e, &r);
      float n[3], p[3], color[4];
      rand_dir(n);
      const float scale = frand(0.1f, 3.0f);
      for (int k = 0; k < 3; k++)
         n[k] *= scale;
      p[0] = frand(-2.0f, 2.0f);
      p[1] = frand(-2.0f, 2.0f);
      p[2] = frand(-6.0f, -0.5f);
      rand_color(color, 0.0f, 1.0f);
      const double dn[3] = { n[0], n[1], n[2] }, dp[3] = { p[0], p[1], p[2] };
      if (near_discontinuity(&r, dn, dp, 1e-3))
         continue;
      (*compared)++;
      for (int back = 0; back < 2; back++) {
         float prim[4], sec[4];
         m_shade_point(&e, n, p, back, color, prim, sec);
         struct shade_ref_material rm;
         const unsigned cm = back ? e.color_material >> M_SHADE_CM_BACK_SHIFT : e.color_material;
         to_ref_material(&e.material[back], color, cm, &rm);
         const double bn[3] = { back ? -dn[0] : dn[0], back ? -dn[1] : dn[1],
                                back ? -dn[2] : dn[2] };
         double rp[4], rs[3], un[6];
         shade_ref_point(&r, &rm, bn, dp, rp, rs, un);
         for (int k = 0; k < 4; k++) {
            const double err = fabs(prim[k] - rp[k]);
            const double scaled = relative && k < 3 ? err / fmax(fabs(un[k]), 1.0) : err;
            if (scaled > worst)
               worst = scaled;
         }
         for (int k = 0; k < 3; k++) {
            const double ref = e.separate_specular ? rs[k] : 0.0;
            const double err = fabs(sec[k] - ref);
            const double scaled = relative ? err / fmax(fabs(un[3 + k]), 1.0) : err;
            if (scaled > worst)
               worst = scaled;
         }
         CHECK(sec[3] == 1.0f, "secondary alpha %g", sec[3]);
      }
   }
   return worst;
}

static void test_random(void)
{
   int compared;
   /* float rounding (a few ulps in n.h and the spot cosine, multiplied
    * by exponents up to 128) and gallivm's pow (relative error up to
    * 1.6e-5 at exponent 128): measured ~1e-4 at worst; the bound, 2.5e-4,
    * is 1/16 of an 8-bit LSB */
   const double worst = run_random(200000, 0.2f, 1.0f, false, &compared);
   printf("random: %d points, largest |float - double| %.3g\n", compared, worst);
   CHECK(compared > 150000, "compared only %d points", compared);
   CHECK(worst < 2.5e-4, "largest error %.3g", worst);
}

static void test_low_roughness(void)
{
   /* GGX with r = 0.05 (a2 = 6.25e-6) and below the 1/32 clamp: near the
    * peak t = n.h^2 (a2 - 1) + 1 cancels to about a2, so the float error
    * of n.h (~6e-8) becomes a relative error of D of a few percent; the
    * sums are compared relative to their size (lights are dim, so the
    * peak mostly stays under the clamp) */
   int compared;
   const double worst = run_random(100000, 0.0f, 0.06f, true, &compared);
   printf("low roughness: %d points, largest relative error %.3g\n", compared, worst);
   CHECK(compared > 70000, "compared only %d points", compared);
   CHECK(worst < 0.1, "largest relative error %.3g", worst);
}

/* One white directional light along +z (or `l`), a white material. */
static void simple_env(struct m_shade_env *e, const float l[3])
{
   memset(e, 0, sizeof(*e));
   e->num_lights = 1;
   struct m_shade_light *li = &e->light[0];
   for (int k = 0; k < 4; k++) {
      li->diffuse[k] = 0.5f;
      li->specular[k] = 0.25f;
   }
   for (int k = 0; k < 3; k++)
      li->position[k] = l[k];
   li->kc = 1.0f;
   for (int f = 0; f < 2; f++) {
      struct m_shade_material *m = &e->material[f];
      for (int k = 0; k < 4; k++) {
         m->diffuse[k] = 1.0f;
         m->specular[k] = 1.0f;
      }
      m->diffuse[3] = 0.75f;
      m->roughness = 0.5f;
      m->f0 = 0.04f;
   }
}

static void test_rules(void)
{
   const float z[3] = { 0.0f, 0.0f, 1.0f }, origin[3] = { 0.0f, 0.0f, 0.0f };
   struct m_shade_env e;
   float prim[4], sec[4];

   /* N = L = V = z, Blinn-Phong: diffuse 0.5 + specular 0.25 */
   simple_env(&e, z);
   e.material[0].shininess = 10.0f;
   m_shade_point(&e, z, origin, false, NULL, prim, sec);
   CHECK(prim[0] == 0.75f && prim[1] == 0.75f && prim[2] == 0.75f, "%g %g %g", prim[0],
         prim[1], prim[2]);
   CHECK(prim[3] == 0.75f, "alpha is the diffuse alpha: %g", prim[3]);
   CHECK(sec[0] == 0.0f && sec[3] == 1.0f, "no separate specular: (0,0,0,1)");

   /* spow: n.h <= 0 with n.l > 0 (viewer behind the surface) gives
    * pow(0, shin) = 0, except shininess 0: 1 */
   const float L[3] = { 0.9f, 0.0f, 0.436f }, P[3] = { 0.5f, 0.0f, 0.866f };
   simple_env(&e, L);
   e.local_viewer = true;
   e.material[0].shininess = 5.0f;
   m_shade_point(&e, z, P, false, NULL, prim, sec);
   const float diffuse_only = prim[0];
   e.material[0].shininess = 0.0f;
   m_shade_point(&e, z, P, false, NULL, prim, sec);
   CHECK(fabsf(prim[0] - (diffuse_only + 0.25f)) < 1e-6f, "spow(x <= 0, 0) = 1: %g vs %g",
         prim[0], diffuse_only);
   CHECK(diffuse_only > 0.0f, "the light is above the surface");
   /* and n.l <= 0 never has a specular term, shininess 0 included */
   const float below[3] = { 1.0f, 0.0f, -0.1f };
   simple_env(&e, below);
   m_shade_point(&e, z, origin, false, NULL, prim, sec);
   CHECK(prim[0] == 0.0f && prim[1] == 0.0f, "n.l < 0: black, got %g", prim[0]);

   /* the spot cone: inside with exponent 0 is exactly 1, outside 0 */
   const float pl[4] = { 0.0f, 0.0f, 2.0f, 1.0f };
   simple_env(&e, z);
   memcpy(e.light[0].position, pl, sizeof(pl));
   e.light[0].spot = true;
   e.light[0].spot_direction[2] = -1.0f;
   e.light[0].spot_cos_cutoff = cosf(30.0f * 3.14159265f / 180.0f);
   float unspot[4];
   e.light[0].spot = false;
   m_shade_point(&e, z, origin, false, NULL, unspot, sec);
   e.light[0].spot = true;
   m_shade_point(&e, z, origin, false, NULL, prim, sec);
   CHECK(memcmp(prim, unspot, sizeof(prim)) == 0, "spot exponent 0 inside the cone");
   const float aside[3] = { 3.0f, 0.0f, 0.0f };
   m_shade_point(&e, z, aside, false, NULL, prim, sec);
   CHECK(prim[0] == 0.0f, "outside the cone: %g", prim[0]);

   /* two-sided: the back face uses -N and material[1]; without two-sided
    * lighting the back face is lit as the front one */
   simple_env(&e, z);
   e.material[1].diffuse[0] = 0.0f;
   float front[4];
   m_shade_point(&e, z, origin, false, NULL, front, sec);
   m_shade_point(&e, z, origin, true, NULL, prim, sec);
   CHECK(memcmp(prim, front, sizeof(prim)) == 0, "two_side off: back = front");
   e.two_side = true;
   m_shade_point(&e, z, origin, true, NULL, prim, sec);
   CHECK(prim[0] == 0.0f && prim[1] == 0.0f, "two_side: back faces away: %g", prim[1]);
   const float minus_z[3] = { 0.0f, 0.0f, -1.0f };
   m_shade_point(&e, minus_z, origin, true, NULL, prim, sec);
   CHECK(prim[0] == 0.25f && prim[1] == 0.75f, "two_side: back material %g %g", prim[0],
         prim[1]);

   /* colour material: the tracked property of the given face only */
   simple_env(&e, z);
   e.two_side = true;
   const float color[4] = { 0.5f, 0.25f, 0.0f, 0.5f };
   e.color_material = M_SHADE_CM_DIFFUSE << M_SHADE_CM_BACK_SHIFT;
   m_shade_point(&e, z, origin, false, color, prim, sec);
   CHECK(prim[1] == 0.75f && prim[3] == 0.75f, "front not tracked");
   m_shade_point(&e, minus_z, origin, true, color, prim, sec);
   CHECK(prim[0] == 0.5f && prim[1] == 0.375f && prim[2] == 0.25f && prim[3] == 0.5f,
         "back diffuse tracked: %g %g %g %g", prim[0], prim[1], prim[2], prim[3]);
   e.color_material = M_SHADE_CM_EMISSION;
   m_shade_point(&e, z, origin, false, color, prim, sec);
   CHECK(prim[0] == 1.0f && prim[1] == 1.0f && prim[2] == 0.75f, "emission tracked, clamped");

   /* separate specular */
   simple_env(&e, z);
   e.material[0].shininess = 10.0f;
   e.separate_specular = true;
   m_shade_point(&e, z, origin, false, NULL, prim, sec);
   CHECK(prim[0] == 0.5f && sec[0] == 0.25f && sec[3] == 1.0f, "separate: %g %g", prim[0],
         sec[0]);

   /* Cook-Torrance, N = L = V: D = 1/(PI a2) up to t's rounding, G = 1,
    * F = F0, diffuse (1 - m) * d_l * c */
   simple_env(&e, z);
   e.material[0].model = M_SHADE_COOK_TORRANCE;
   e.separate_specular = true;
   m_shade_point(&e, z, origin, false, NULL, prim, sec);
   CHECK(prim[0] == 0.5f, "CT diffuse of a dielectric is GL's: %g", prim[0]);
   const double a2 = 0.0625;   /* r = 0.5, alpha = r^2, a2 = alpha^2 */
   const double spec = 0.04 * M_PI * (1.0 / (M_PI * a2)) / 4.0 * 0.25;
   CHECK(fabs(sec[0] - fmin(spec, 1.0)) < 1e-6, "CT peak %g vs %g", sec[0], spec);
   e.material[0].metalness = 1.0f;
   e.light[0].specular[0] = e.light[0].specular[1] = e.light[0].specular[2] = 0.001f;
   m_shade_point(&e, z, origin, false, NULL, prim, sec);
   CHECK(prim[0] == 0.0f, "a metal has no diffuse term: %g", prim[0]);
   CHECK(fabs(sec[0] - 1.0 / (4.0 * a2) * 0.001) < 1e-4, "metal peak F0 = c: %g", sec[0]);
   /* n.v <= 0: no specular lobe */
   e.local_viewer = true;
   const float behind[3] = { 0.0f, 0.0f, 1.0f };   /* V = -z */
   m_shade_point(&e, z, behind, false, NULL, prim, sec);
   CHECK(sec[0] == 0.0f, "n.v < 0: %g", sec[0]);

   /* a positional light exactly at the point: NaN in, clamped to [0, 1] */
   simple_env(&e, z);
   const float at[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
   memcpy(e.light[0].position, at, sizeof(at));
   m_shade_point(&e, z, origin, false, NULL, prim, sec);
   for (int k = 0; k < 4; k++)
      CHECK(prim[k] >= 0.0f && prim[k] <= 1.0f, "light at the point: %g", prim[k]);
}

static void test_env(void)
{
   OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
   static unsigned char buf[4 * 4 * 4];
   CHECK(c && OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 4, 4), "context");
   struct fgl_context *ctx = fgl_get_current();

   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glTranslatef(1.0f, 2.0f, 3.0f);
   const float pos[4] = { 1.0f, 0.0f, 0.0f, 1.0f }, dir[3] = { 0.0f, 0.0f, -2.0f };
   glLightfv(GL_LIGHT5, GL_POSITION, pos);
   glLightfv(GL_LIGHT5, GL_SPOT_DIRECTION, dir);
   glLightf(GL_LIGHT5, GL_SPOT_CUTOFF, 60.0f);
   glLightf(GL_LIGHT5, GL_SPOT_EXPONENT, 7.0f);
   glLightf(GL_LIGHT5, GL_QUADRATIC_ATTENUATION, 0.5f);
   glEnable(GL_LIGHT5);
   glEnable(GL_LIGHT2);
   glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
   glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
   glMateriali(GL_BACK, GL_REFLECTANCE_MODEL_FIXGL, GL_COOK_TORRANCE_FIXGL);
   glMaterialf(GL_BACK, GL_ROUGHNESS_FIXGL, 0.25f);
   glMaterialf(GL_FRONT, GL_METALNESS_FIXGL, 0.75f);
   const float red[4] = { 1.0f, 0.0f, 0.0f, 0.5f };
   glMaterialfv(GL_FRONT, GL_EMISSION, red);
   glColorMaterial(GL_BACK, GL_SPECULAR);
   glEnable(GL_COLOR_MATERIAL);

   struct m_shade_env e;
   fgl_update_shade_env(ctx, &e);
   CHECK(e.num_lights == 2, "two lights: %u", e.num_lights);
   CHECK(e.light[0].diffuse[0] == 0.0f && e.light[1].position[3] == 1.0f,
         "index order: LIGHT2 then LIGHT5");
   CHECK(e.light[1].position[0] == 2.0f && e.light[1].position[1] == 2.0f &&
         e.light[1].position[2] == 3.0f, "eye-space position");
   CHECK(e.light[1].spot && e.light[1].spot_direction[2] == -1.0f,
         "spot direction normalised: %g", e.light[1].spot_direction[2]);
   CHECK(fabsf(e.light[1].spot_cos_cutoff - 0.5f) < 1e-6f && e.light[1].spot_exponent == 7.0f,
         "spot cone");
   CHECK(!e.light[0].spot && e.light[1].kq == 0.5f && e.light[1].kc == 1.0f, "attenuation");
   CHECK(e.local_viewer && e.separate_specular && !e.two_side, "light model");
   CHECK(e.global_ambient[0] == 0.2f, "global ambient");
   CHECK(e.material[0].model == M_SHADE_BLINN_PHONG &&
         e.material[1].model == M_SHADE_COOK_TORRANCE, "models");
   CHECK(e.material[1].roughness == 0.25f && e.material[0].roughness == 0.5f, "roughness");
   CHECK(e.material[0].metalness == 0.75f && e.material[1].metalness == 0.0f, "metalness");
   CHECK(e.material[0].f0 == 0.04f, "f0");
   CHECK(e.material[0].emission[0] == 1.0f && e.material[0].emission[3] == 0.5f &&
         e.material[1].emission[0] == 0.0f, "current materials");
   CHECK(e.material[0].diffuse[0] == 0.8f && e.material[0].shininess == 0.0f, "defaults");
   CHECK(e.color_material == M_SHADE_CM_SPECULAR << M_SHADE_CM_BACK_SHIFT, "cm bits %#x",
         e.color_material);
   glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
   fgl_update_shade_env(ctx, &e);
   CHECK(e.color_material == 0x33, "cm bits %#x", e.color_material);
   glDisable(GL_COLOR_MATERIAL);
   fgl_update_shade_env(ctx, &e);
   CHECK(e.color_material == 0, "cm off: %#x", e.color_material);
   OSMesaDestroyContext(c);
}

int main(void)
{
   test_rules();
   test_random();
   test_low_roughness();
   test_env();
   return check_report("unit-shade");
}
