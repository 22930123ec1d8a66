/*
 * test_shade8.c - m_shade_point8 (math/m_shade8.c, math/m_shade_avx2.c)
 * against m_shade_point_prepared, bit for bit: every lane's primary and
 * secondary colours must be the scalar function's on that lane's inputs
 * (memcmp of the floats: NaNs and zeros compared by their bits).
 *
 *   random   random environments, built as the library builds them
 *            (an m_shade_env filled field by field then m_shade_prepare,
 *            as test_shade.c does, and some from a context's GL state
 *            through fgl_update_shade_env): 0-8 lights, directional and
 *            positional, with and without a spot cone (exponent 0, 128,
 *            random; cutoffs 0-90 degrees), attenuation (zeros included),
 *            Blinn-Phong (shininess 0, 128, random) and Cook-Torrance
 *            (roughness 0, 1/32, 1, random; metalness 0, 1, random) faces,
 *            two-sided lighting and the back face, colour material (every
 *            bit combination), separate specular, local viewer; lanes with
 *            random normals and positions, zero, NaN, infinite, tiny and
 *            huge normals, axis-aligned normals (n.l exactly 0 with
 *            axis-aligned lights), points exactly at a positional light
 *            (L = 0), at the eye (V = normalize(0)), NaN or infinite
 *            positions, colours outside [0, 1] or NaN.  Each batch runs
 *            through m_shade_point8 (the dispatched kernel),
 *            m_shade_point8_portable and, when the CPU has AVX2 and FMA,
 *            m_shade_point8_avx2.
 *   bench    ns per fragment: m_shade_point_prepared, the portable and
 *            the AVX2 kernels, on a few typical environments (printed,
 *            not checked).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include <GL/osmesa.h>
#include <fixgl/fixgl.h>

#include "context.h"
#include "math/m_shade.h"

#include "check.h"

#define LANES M_SHADE_LANES

static uint64_t rng_state = 0x2545f4914f6cdd1dull;

static uint32_t rnd(void)
{
   rng_state ^= rng_state << 13;
   rng_state ^= rng_state >> 7;
   rng_state ^= rng_state << 17;
   return (uint32_t)(rng_state >> 32);
}

static float frand(float lo, float hi)
{
   return lo + (hi - lo) * (float)(rnd() >> 8) / 16777216.0f;
}

/* true with probability p */
static bool chance(float p)
{
   return frand(0.0f, 1.0f) < p;
}

static void rand_color(float c[4], float lo, float hi)
{
   for (int k = 0; k < 4; k++)
      c[k] = frand(lo, hi);
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

/* an axis direction: one component +-1, the others +-0 */
static void axis_dir(float v[3])
{
   const int a = (int)(rnd() % 3);
   for (int k = 0; k < 3; k++)
      v[k] = chance(0.5f) ? -0.0f : 0.0f;
   v[a] = chance(0.5f) ? -1.0f : 1.0f;
}

/* ---- coverage ---- */

static struct {
   long envs, gl_envs, lanes, calls;
   long lights_dir, lights_dir_spot, lights_pos, lights_pos_spot;
   long faces_bp, faces_ct, shin0, shin128, back_calls, cm_calls, sep_calls, lv_calls;
   long lanes_nan_n, lanes_zero_n, lanes_inf_n, lanes_axis_n, lanes_at_light, lanes_at_eye;
   long lanes_special_p, lanes_special_color, lanes_spot_boundary, spot_boundary_envs;
   long lanes_ndl_zero;
} cov;

/* Whether n.l is exactly 0 at a lane for one of the lights (the operations
 * of m_shade.c), for the coverage report. */
static bool ndl_zero(const struct m_shade_env *e, const float n[3], const float p[3], bool back)
{
   float N[3] = { n[0], n[1], n[2] };
   const float r = 1.0f / sqrtf(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
   for (int k = 0; k < 3; k++)
      N[k] = back && e->two_side ? -(N[k] * r) : N[k] * r;
   for (unsigned li = 0; li < e->num_lights; li++) {
      float L[3];
      for (int k = 0; k < 3; k++)
         L[k] = e->light[li].position[3] != 0.0f ? e->prep.light[li].L[k] - p[k]
                                                 : e->prep.light[li].L[k];
      if (e->light[li].position[3] != 0.0f) {
         const float d = sqrtf(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
         for (int k = 0; k < 3; k++)
            L[k] = L[k] / d;
      }
      if (N[0] * L[0] + N[1] * L[1] + N[2] * L[2] == 0.0f)
         return true;
   }
   return false;
}

/* ---- environments ---- */

static void rand_light(struct m_shade_light *l)
{
   rand_color(l->ambient, 0.0f, chance(0.1f) ? 2.0f : 0.2f);
   rand_color(l->diffuse, 0.0f, chance(0.1f) ? 2.0f : 0.5f);
   rand_color(l->specular, 0.0f, chance(0.1f) ? 2.0f : 0.5f);
   const bool directional = chance(0.4f);
   if (directional) {
      if (chance(0.3f))
         axis_dir(l->position);
      else
         rand_dir(l->position);
      if (chance(0.1f))
         for (int k = 0; k < 3; k++)
            l->position[k] *= frand(0.01f, 100.0f);
      l->position[3] = 0.0f;
      l->kc = 1.0f;
      cov.lights_dir++;
   } else {
      const float w = chance(0.7f) ? 1.0f : frand(-2.0f, 2.0f);
      for (int k = 0; k < 3; k++)
         l->position[k] = (chance(0.1f) ? 0.0f : frand(-4.0f, 4.0f)) * w;
      l->position[3] = w == 0.0f ? 1.0f : w;
      const int att = (int)(rnd() % 4);   /* none, random, zeros, big */
      l->kc = att == 0 ? 1.0f : att == 2 ? 0.0f : frand(0.0f, 2.0f);
      l->kl = att == 0 ? 0.0f : att == 3 ? frand(0.0f, 10.0f) : frand(0.0f, 0.5f);
      l->kq = att == 0 ? 0.0f : att == 3 ? frand(0.0f, 10.0f) : frand(0.0f, 0.2f);
      cov.lights_pos++;
   }
   l->spot = chance(0.4f);
   if (l->spot) {
      float sd[3];
      if (chance(0.2f))
         axis_dir(sd);
      else
         rand_dir(sd);
      const float r = 1.0f / sqrtf(sd[0] * sd[0] + sd[1] * sd[1] + sd[2] * sd[2]);
      for (int k = 0; k < 3; k++)
         l->spot_direction[k] = sd[k] * r;
      const float u = frand(0.0f, 1.0f);
      l->spot_exponent = u < 0.2f ? 0.0f : u < 0.35f ? 128.0f : frand(0.0f, 128.0f);
      const float v = frand(0.0f, 1.0f);
      const float deg = v < 0.05f ? 0.0f : v < 0.1f ? 90.0f : frand(0.0f, 90.0f);
      l->spot_cos_cutoff = cosf(deg * 3.14159265f / 180.0f);
      if (directional)
         cov.lights_dir_spot++;
      else
         cov.lights_pos_spot++;
   } else {
      l->spot_direction[2] = -1.0f;
      l->spot_cos_cutoff = -1.0f;
   }
}

static void rand_material(struct m_shade_material *m)
{
   m->model = chance(0.5f) ? M_SHADE_BLINN_PHONG : M_SHADE_COOK_TORRANCE;
   rand_color(m->ambient, 0.0f, 1.0f);
   rand_color(m->diffuse, 0.0f, 1.0f);
   rand_color(m->specular, 0.0f, 1.0f);
   rand_color(m->emission, 0.0f, chance(0.2f) ? 1.0f : 0.1f);
   const float u = frand(0.0f, 1.0f);
   m->shininess = u < 0.15f ? 0.0f : u < 0.3f ? 128.0f : u < 0.4f ? frand(0.0f, 1.0f)
                                                                    : frand(0.0f, 128.0f);
   const float r = frand(0.0f, 1.0f);
   m->roughness = r < 0.1f ? 0.0f : r < 0.2f ? 1.0f / 32.0f : r < 0.3f ? 1.0f
                : r < 0.4f ? frand(0.0f, 0.06f) : frand(0.0f, 1.0f);
   const float mt = frand(0.0f, 1.0f);
   m->metalness = mt < 0.2f ? 0.0f : mt < 0.4f ? 1.0f : frand(0.0f, 1.0f);
   m->f0 = frand(0.0f, 1.0f);
}

/* A point exactly on the cone of a positional spot light (its cosine
 * equal to the cutoff, computed with m_shade.c's operations), for the
 * lanes that test c >= cos(sc) at equality. */
static bool have_boundary;
static float boundary_p[3];

static void set_spot_boundary(struct m_shade_env *e)
{
   have_boundary = false;
   if (!chance(0.5f))
      return;
   for (unsigned li = 0; li < e->num_lights; li++) {
      struct m_shade_light *l = &e->light[li];
      if (l->position[3] == 0.0f || !l->spot)
         continue;
      float P[3] = { frand(-2.0f, 2.0f), frand(-2.0f, 2.0f), frand(-6.0f, 0.5f) }, L[3];
      for (int k = 0; k < 3; k++)
         L[k] = e->prep.light[li].L[k] - P[k];
      const float d = sqrtf(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
      for (int k = 0; k < 3; k++)
         L[k] = L[k] / d;
      const float cs = -L[0] * l->spot_direction[0] + -L[1] * l->spot_direction[1] +
                       -L[2] * l->spot_direction[2];
      if (!(cs > -1.0f && cs < 1.0f))
         continue;
      l->spot_cos_cutoff = cs;   /* m_shade_prepare reads no cutoff of a positional light */
      memcpy(boundary_p, P, sizeof(P));
      have_boundary = true;
      cov.spot_boundary_envs++;
      return;
   }
}

static void rand_env(struct m_shade_env *e)
{
   memset(e, 0, sizeof(*e));
   const unsigned u = rnd() % 16;
   e->num_lights = u < 9 ? u : 1 + rnd() % 3;   /* 0..8, mostly 1..3 */
   for (unsigned i = 0; i < e->num_lights; i++)
      rand_light(&e->light[i]);
   rand_color(e->global_ambient, 0.0f, 0.3f);
   e->local_viewer = chance(0.5f);
   e->two_side = chance(0.5f);
   e->separate_specular = chance(0.5f);
   rand_material(&e->material[0]);
   rand_material(&e->material[1]);
   e->color_material = chance(0.4f) ? 0 : rnd() % 256;
   /* as fgl_update_shade_env does after filling the fields */
   m_shade_prepare(e);
   set_spot_boundary(e);
}

/* An environment from a context's GL state (fgl_update_shade_env). */
static void gl_env(struct fgl_context *ctx, struct m_shade_env *e)
{
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glTranslatef(frand(-1.0f, 1.0f), frand(-1.0f, 1.0f), frand(-1.0f, 1.0f));
   glRotatef(frand(0.0f, 360.0f), frand(-1.0f, 1.0f), frand(-1.0f, 1.0f), frand(-1.0f, 1.0f));
   for (int i = 0; i < 8; i++) {
      if (!chance(0.4f)) {
         glDisable(GL_LIGHT0 + i);
         continue;
      }
      glEnable(GL_LIGHT0 + i);
      struct m_shade_light l;
      memset(&l, 0, sizeof(l));
      rand_light(&l);
      glLightfv(GL_LIGHT0 + i, GL_AMBIENT, l.ambient);
      glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, l.diffuse);
      glLightfv(GL_LIGHT0 + i, GL_SPECULAR, l.specular);
      glLightfv(GL_LIGHT0 + i, GL_POSITION, l.position);
      float sd[3];
      rand_dir(sd);
      glLightfv(GL_LIGHT0 + i, GL_SPOT_DIRECTION, sd);
      glLightf(GL_LIGHT0 + i, GL_SPOT_CUTOFF, l.spot ? frand(0.0f, 90.0f) : 180.0f);
      glLightf(GL_LIGHT0 + i, GL_SPOT_EXPONENT, l.spot_exponent);
      glLightf(GL_LIGHT0 + i, GL_CONSTANT_ATTENUATION, l.kc);
      glLightf(GL_LIGHT0 + i, GL_LINEAR_ATTENUATION, l.kl);
      glLightf(GL_LIGHT0 + i, GL_QUADRATIC_ATTENUATION, l.kq);
   }
   float ga[4];
   rand_color(ga, 0.0f, 0.3f);
   glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ga);
   glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, chance(0.5f));
   glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, chance(0.5f));
   glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                 chance(0.5f) ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
   for (int f = 0; f < 2; f++) {
      const GLenum face = f ? GL_BACK : GL_FRONT;
      struct m_shade_material m;
      rand_material(&m);
      glMaterialfv(face, GL_AMBIENT, m.ambient);
      glMaterialfv(face, GL_DIFFUSE, m.diffuse);
      glMaterialfv(face, GL_SPECULAR, m.specular);
      glMaterialfv(face, GL_EMISSION, m.emission);
      glMaterialf(face, GL_SHININESS, m.shininess);
      glMateriali(face, GL_REFLECTANCE_MODEL_FIXGL,
                  m.model == M_SHADE_COOK_TORRANCE ? GL_COOK_TORRANCE_FIXGL
                                                   : GL_BLINN_PHONG_FIXGL);
      glMaterialf(face, GL_ROUGHNESS_FIXGL, m.roughness);
      glMaterialf(face, GL_METALNESS_FIXGL, m.metalness);
      glMaterialf(face, GL_DIELECTRIC_F0_FIXGL, m.f0);
   }
   if (chance(0.5f)) {
      static const GLenum faces[] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
      static const GLenum modes[] = { GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION,
                                      GL_AMBIENT_AND_DIFFUSE };
      glColorMaterial(faces[rnd() % 3], modes[rnd() % 5]);
      glEnable(GL_COLOR_MATERIAL);
   } else {
      glDisable(GL_COLOR_MATERIAL);
   }
   CHECK(glGetError() == GL_NO_ERROR, "GL state of a random environment");
   fgl_update_shade_env(ctx, e);
}

/* ---- lanes ---- */

struct batch {
   float n[3][LANES], p[3][LANES], color[4][LANES];
};

static void rand_lane(const struct m_shade_env *e, struct batch *b, int i)
{
   float n[3], p[3], c[4];
   rand_dir(n);
   const float s = frand(0.0f, 1.0f) < 0.5f ? 1.0f : frand(0.1f, 3.0f);
   for (int k = 0; k < 3; k++)
      n[k] *= s;
   p[0] = frand(-2.0f, 2.0f);
   p[1] = frand(-2.0f, 2.0f);
   p[2] = frand(-6.0f, 0.5f);
   rand_color(c, 0.0f, 1.0f);

   const unsigned kind = rnd() % 64;
   switch (kind) {
   case 0: /* zero normal */
      n[0] = n[1] = n[2] = chance(0.5f) ? 0.0f : -0.0f;
      cov.lanes_zero_n++;
      break;
   case 1: /* NaN normal */
      n[rnd() % 3] = NAN;
      cov.lanes_nan_n++;
      break;
   case 2: /* infinite normal */
      n[rnd() % 3] = chance(0.5f) ? INFINITY : -INFINITY;
      cov.lanes_inf_n++;
      break;
   case 3: /* tiny (denormal squares) and huge (overflowing) normals */
      for (int k = 0; k < 3; k++)
         n[k] *= chance(0.5f) ? 1e-30f : 1e30f;
      break;
   case 4: case 5: case 6: case 7: /* axis normals: n.l exactly 0 with axis lights */
      axis_dir(n);
      cov.lanes_axis_n++;
      break;
   case 8: case 9: /* exactly at a positional light: L = 0 */
      for (unsigned li = 0; li < e->num_lights; li++) {
         if (e->light[li].position[3] != 0.0f) {
            for (int k = 0; k < 3; k++)
               p[k] = e->prep.light[li].L[k];
            cov.lanes_at_light++;
            break;
         }
      }
      break;
   case 10: /* at the eye: V = normalize(0) */
      p[0] = p[1] = p[2] = 0.0f;
      cov.lanes_at_eye++;
      break;
   case 11: /* NaN or infinite position */
      p[rnd() % 3] = chance(0.5f) ? NAN : INFINITY;
      cov.lanes_special_p++;
      break;
   case 12: /* colours outside [0, 1], or NaN */
      for (int k = 0; k < 4; k++)
         c[k] = frand(-0.5f, 1.5f);
      if (chance(0.3f))
         c[rnd() % 4] = NAN;
      cov.lanes_special_color++;
      break;
   case 13: /* normal along the view or a light: n.v, n.l at their extremes */
      if (e->num_lights && e->light[0].position[3] == 0.0f)
         for (int k = 0; k < 3; k++)
            n[k] = e->prep.light[0].L[k];
      else
         n[0] = n[1] = 0.0f, n[2] = 1.0f;
      break;
   case 14: case 15: case 16: /* exactly on a spot cone */
      if (have_boundary) {
         memcpy(p, boundary_p, sizeof(p));
         cov.lanes_spot_boundary++;
      }
      break;
   default:
      break;
   }
   for (int k = 0; k < 3; k++) {
      b->n[k][i] = n[k];
      b->p[k][i] = p[k];
   }
   for (int k = 0; k < 4; k++)
      b->color[k][i] = c[k];
}

typedef void point8_fn(const struct m_shade_env *, const float[3][LANES], const float[3][LANES],
                       bool, const float[4][LANES], float[4][LANES], float[4][LANES]);

static int reported;

static void dump_lane(const char *what, const struct m_shade_env *e, const struct batch *b,
                      int i, bool back, const float *ref_p, const float *ref_s,
                      float got_p[4][LANES], float got_s[4][LANES])
{
   if (reported++ >= 10)
      return;
   fprintf(stderr,
           "%s lane %d: lights %u lv %d two_side %d sep %d cm %#x back %d models %d/%d\n"
           "  n %a %a %a  p %a %a %a  color %a %a %a %a\n",
           what, i, e->num_lights, e->local_viewer, e->two_side, e->separate_specular,
           e->color_material, back, e->material[0].model, e->material[1].model, b->n[0][i],
           b->n[1][i], b->n[2][i], b->p[0][i], b->p[1][i], b->p[2][i], b->color[0][i],
           b->color[1][i], b->color[2][i], b->color[3][i]);
   for (int k = 0; k < 4; k++)
      fprintf(stderr, "  [%d] primary %a vs %a   secondary %a vs %a\n", k, got_p[k][i],
              ref_p[k], got_s[k][i], ref_s[k]);
}

/* Runs one batch through `fn` and compares every lane with the scalar
 * results ref_p/ref_s; returns the number of differing lanes. */
static long compare(const char *what, point8_fn *fn, const struct m_shade_env *e,
                    const struct batch *b, bool back, bool with_color,
                    float ref_p[LANES][4], float ref_s[LANES][4])
{
   float got_p[4][LANES], got_s[4][LANES];
   memset(got_p, 0xa5, sizeof(got_p));
   memset(got_s, 0xa5, sizeof(got_s));
   fn(e, (const float(*)[LANES])b->n, (const float(*)[LANES])b->p, back,
      with_color ? (const float(*)[LANES])b->color : NULL, got_p, got_s);
   long bad = 0;
   for (int i = 0; i < LANES; i++) {
      bool same = true;
      for (int k = 0; k < 4; k++) {
         same = same && memcmp(&got_p[k][i], &ref_p[i][k], sizeof(float)) == 0;
         same = same && memcmp(&got_s[k][i], &ref_s[i][k], sizeof(float)) == 0;
      }
      if (!same) {
         bad++;
         dump_lane(what, e, b, i, back, ref_p[i], ref_s[i], got_p, got_s);
      }
   }
   return bad;
}

static void run_env(const struct m_shade_env *e, int batches, bool have_avx2, long *bad)
{
   cov.envs++;
   for (unsigned li = 0; li < 2; li++) {
      const struct m_shade_material *m = &e->material[li];
      if (m->model == M_SHADE_COOK_TORRANCE)
         cov.faces_ct++;
      else
         cov.faces_bp++;
      cov.shin0 += m->shininess == 0.0f;
      cov.shin128 += m->shininess == 128.0f;
   }
   for (int bi = 0; bi < batches; bi++) {
      struct batch b;
      for (int i = 0; i < LANES; i++)
         rand_lane(e, &b, i);
      const bool back = chance(0.5f);
      const unsigned cm = back && e->two_side ? e->color_material >> M_SHADE_CM_BACK_SHIFT
                                              : e->color_material;
      /* colour may be NULL when the face tracks nothing */
      const bool with_color = (cm & 15u) != 0 || chance(0.5f);
      float ref_p[LANES][4], ref_s[LANES][4];
      for (int i = 0; i < LANES; i++) {
         const float n[3] = { b.n[0][i], b.n[1][i], b.n[2][i] };
         const float p[3] = { b.p[0][i], b.p[1][i], b.p[2][i] };
         const float c[4] = { b.color[0][i], b.color[1][i], b.color[2][i], b.color[3][i] };
         m_shade_point_prepared(e, n, p, back, with_color ? c : NULL, ref_p[i], ref_s[i]);
         cov.lanes_ndl_zero += ndl_zero(e, n, p, back);
      }
      cov.lanes += LANES;
      cov.calls++;
      cov.back_calls += back && e->two_side;
      cov.cm_calls += (cm & 15u) != 0;
      cov.sep_calls += e->separate_specular;
      cov.lv_calls += e->local_viewer;
      bad[0] += compare("m_shade_point8", m_shade_point8, e, &b, back, with_color, ref_p, ref_s);
      bad[1] += compare("portable", m_shade_point8_portable, e, &b, back, with_color, ref_p,
                        ref_s);
#if defined(M_SHADE_HAVE_AVX2)
      if (have_avx2)
         bad[2] += compare("avx2", m_shade_point8_avx2, e, &b, back, with_color, ref_p, ref_s);
#else
      (void)have_avx2;
#endif
   }
}

static void test_random(void)
{
   const bool have_avx2 = m_shade_point8_avx2_supported();
   long bad[3] = { 0, 0, 0 };
   for (int it = 0; it < 12000; it++) {
      struct m_shade_env e;
      rand_env(&e);
      run_env(&e, 12, have_avx2, bad);
   }

   OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
   static unsigned char buf[4 * 4 * 4];
   CHECK(c && OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 4, 4), "context");
   struct fgl_context *ctx = fgl_get_current();
   for (int it = 0; it < 1000; it++) {
      struct m_shade_env e;
      gl_env(ctx, &e);
      have_boundary = false;
      cov.gl_envs++;
      run_env(&e, 12, have_avx2, bad);
   }
   OSMesaDestroyContext(c);

   printf("random: %ld environments (%ld from GL state), %ld calls, %ld lanes per kernel\n",
          cov.envs, cov.gl_envs, cov.calls, cov.lanes);
   printf("  lights: %ld directional (%ld spot), %ld positional (%ld spot)\n", cov.lights_dir,
          cov.lights_dir_spot, cov.lights_pos, cov.lights_pos_spot);
   printf("  faces: %ld Blinn-Phong (%ld shininess 0, %ld shininess 128 of all), "
          "%ld Cook-Torrance\n", cov.faces_bp, cov.shin0, cov.shin128, cov.faces_ct);
   printf("  calls: %ld back face (two-sided), %ld colour material, %ld separate specular, "
          "%ld local viewer\n", cov.back_calls, cov.cm_calls, cov.sep_calls, cov.lv_calls);
   printf("  lanes: %ld zero n, %ld NaN n, %ld inf n, %ld axis n, %ld at a light, %ld at the "
          "eye, %ld NaN/inf P, %ld odd colours, %ld on a spot cone (%ld environments)\n",
          cov.lanes_zero_n, cov.lanes_nan_n, cov.lanes_inf_n, cov.lanes_axis_n,
          cov.lanes_at_light, cov.lanes_at_eye, cov.lanes_special_p, cov.lanes_special_color,
          cov.lanes_spot_boundary, cov.spot_boundary_envs);
   printf("  lanes with n.l exactly 0 for a light: %ld\n", cov.lanes_ndl_zero);
   printf("  m_shade_point8 is the %s kernel; differing lanes: dispatched %ld, portable %ld, "
          "avx2 %ld%s\n", have_avx2 ? "AVX2" : "portable", bad[0], bad[1], bad[2],
          have_avx2 ? "" : " (not run: no AVX2/FMA)");
   CHECK(cov.lanes >= 100000, "only %ld lanes", cov.lanes);
   CHECK(bad[0] == 0 && bad[1] == 0 && bad[2] == 0, "lanes differ: %ld %ld %ld", bad[0],
         bad[1], bad[2]);
}

/* ---- speed ---- */

static double now(void)
{
   struct timespec ts;
   clock_gettime(CLOCK_MONOTONIC, &ts);
   return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#define BENCH_BATCHES 64

static volatile float sink;

static double bench_scalar(const struct m_shade_env *e, const struct batch *bs, int reps)
{
   float acc = 0.0f;
   const double t0 = now();
   for (int r = 0; r < reps; r++) {
      for (int bi = 0; bi < BENCH_BATCHES; bi++) {
         const struct batch *b = &bs[bi];
         for (int i = 0; i < LANES; i++) {
            const float n[3] = { b->n[0][i], b->n[1][i], b->n[2][i] };
            const float p[3] = { b->p[0][i], b->p[1][i], b->p[2][i] };
            const float c[4] = { b->color[0][i], b->color[1][i], b->color[2][i],
                                 b->color[3][i] };
            float prim[4], sec[4];
            m_shade_point_prepared(e, n, p, false, c, prim, sec);
            acc += prim[0] + sec[0];
         }
      }
   }
   const double t = now() - t0;
   sink = acc;
   return t * 1e9 / ((double)reps * BENCH_BATCHES * LANES);
}

static double bench8(point8_fn *fn, const struct m_shade_env *e, const struct batch *bs,
                     int reps)
{
   float acc = 0.0f;
   const double t0 = now();
   for (int r = 0; r < reps; r++) {
      for (int bi = 0; bi < BENCH_BATCHES; bi++) {
         const struct batch *b = &bs[bi];
         float prim[4][LANES], sec[4][LANES];
         fn(e, (const float(*)[LANES])b->n, (const float(*)[LANES])b->p, false,
            (const float(*)[LANES])b->color, prim, sec);
         acc += prim[0][0] + sec[0][7];
      }
   }
   const double t = now() - t0;
   sink = acc;
   return t * 1e9 / ((double)reps * BENCH_BATCHES * LANES);
}

static void bench_env(struct m_shade_env *e, int config)
{
   memset(e, 0, sizeof(*e));
   const float white[4] = { 0.6f, 0.6f, 0.6f, 1.0f }, amb[4] = { 0.05f, 0.05f, 0.05f, 1.0f };
   e->num_lights = config == 0 ? 1 : 3;
   for (unsigned i = 0; i < e->num_lights; i++) {
      struct m_shade_light *l = &e->light[i];
      memcpy(l->ambient, amb, sizeof(amb));
      memcpy(l->diffuse, white, sizeof(white));
      memcpy(l->specular, white, sizeof(white));
      l->kc = 1.0f;
      l->spot_direction[2] = -1.0f;
      if (i == 0) {
         const float d[4] = { 0.3f, 0.5f, 0.8f, 0.0f };
         memcpy(l->position, d, sizeof(d));
      } else {
         const float pos[4] = { -1.0f + 2.0f * (float)i, 1.0f, 1.0f, 1.0f };
         memcpy(l->position, pos, sizeof(pos));
         l->kl = 0.1f;
         l->kq = 0.02f;
         if (i == 2) {
            l->spot = true;
            l->spot_exponent = 8.0f;
            l->spot_cos_cutoff = cosf(40.0f * 3.14159265f / 180.0f);
         }
      }
   }
   memcpy(e->global_ambient, amb, sizeof(amb));
   e->local_viewer = config != 0;
   for (int f = 0; f < 2; f++) {
      struct m_shade_material *m = &e->material[f];
      m->model = config == 2 ? M_SHADE_COOK_TORRANCE : M_SHADE_BLINN_PHONG;
      const float a[4] = { 0.2f, 0.2f, 0.2f, 1.0f }, d[4] = { 0.8f, 0.5f, 0.3f, 1.0f };
      memcpy(m->ambient, a, sizeof(a));
      memcpy(m->diffuse, d, sizeof(d));
      memcpy(m->specular, white, sizeof(white));
      m->shininess = 32.0f;
      m->roughness = 0.4f;
      m->metalness = 0.3f;
      m->f0 = 0.04f;
   }
   m_shade_prepare(e);
}

static void bench(void)
{
   static const char *const names[] = {
      "1 directional light, Blinn-Phong, infinite viewer",
      "3 lights (directional, point, spot), Blinn-Phong, local viewer",
      "3 lights (directional, point, spot), Cook-Torrance, local viewer",
   };
   static struct batch bs[BENCH_BATCHES];
   const bool have_avx2 = m_shade_point8_avx2_supported();
   for (int config = 0; config < 3; config++) {
      struct m_shade_env e;
      bench_env(&e, config);
      for (int bi = 0; bi < BENCH_BATCHES; bi++) {
         for (int i = 0; i < LANES; i++) {
            float n[3];
            rand_dir(n);
            n[2] = fabsf(n[2]);
            for (int k = 0; k < 3; k++) {
               bs[bi].n[k][i] = n[k];
               bs[bi].color[k][i] = frand(0.0f, 1.0f);
            }
            bs[bi].color[3][i] = 1.0f;
            bs[bi].p[0][i] = frand(-1.0f, 1.0f);
            bs[bi].p[1][i] = frand(-1.0f, 1.0f);
            bs[bi].p[2][i] = frand(-5.0f, -2.0f);
         }
      }
      const int reps = 400;
      double best_s = 1e9, best_p = 1e9, best_a = 1e9;
      for (int t = 0; t < 5; t++) {
         best_s = fmin(best_s, bench_scalar(&e, bs, reps));
         best_p = fmin(best_p, bench8(m_shade_point8_portable, &e, bs, reps));
#if defined(M_SHADE_HAVE_AVX2)
         if (have_avx2)
            best_a = fmin(best_a, bench8(m_shade_point8_avx2, &e, bs, reps));
#endif
      }
      printf("bench %s: m_shade_point_prepared %.1f ns/fragment, portable 8-lane %.1f", names[config],
             best_s, best_p);
      if (have_avx2)
         printf(", AVX2 8-lane %.2f (x%.1f)", best_a, best_s / best_a);
      printf("\n");
   }
}

int main(int argc, char **argv)
{
   test_random();
   if (argc < 2 || strcmp(argv[1], "--no-bench") != 0)
      bench();
   return check_report("unit-shade8");
}
