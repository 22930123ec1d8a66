/*
 * test_vertex.c - unit tests of the vertex stage's vectorised arithmetic
 * (tnl/t_light.c): the eight-lane LIT pow of light_simd (t_lit_pows) gives
 * m_gallivm_pow's bits for millions of random arguments -- any bit
 * patterns, [0, 1), denormals, the special values 0, -0, inf, NaN, and
 * exponents in and beyond [-128, 128] -- with and without the draw's flush
 * of denormals (FTZ/DAZ).  (On a CPU without AVX2 and FMA, t_lit_pows is
 * m_gallivm_pow itself and the test is trivially true.)
 *
 * And the clipper shared by the vertex stage and the pixel rectangles
 * (tnl/t_clip.c, t_pipeline.h): t_clip_mask's outcodes (points on the
 * planes inside, w at and near 0, NaN and infinities unordered) and
 * t_clip_polygon's polygons (all inside: untouched; all outside one
 * plane: nothing; a plane crossed: the new vertices, exact where the
 * arithmetic is, their window positions, varyings and edge flags; a
 * vertex on a plane; w near 0; a NaN distance).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "math/m_gallivm.h"
#include "tnl/t_light.h"
#include "tnl/t_pipeline.h"

#include "check.h"

static uint64_t rng_state = 88172645463325252ull;

static uint32_t rnd(void)
{
   rng_state ^= rng_state << 13;
   rng_state ^= rng_state >> 7;
   rng_state ^= rng_state << 17;
   return (uint32_t)(rng_state >> 16);
}

static float from_bits(uint32_t u)
{
   float f;
   memcpy(&f, &u, 4);
   return f;
}

static uint32_t to_bits(float f)
{
   uint32_t u;
   memcpy(&u, &f, 4);
   return u;
}

static float random_base(void)
{
   static const float special[] = { 0.0f, -0.0f, 1.0f, INFINITY, -INFINITY, NAN, 1e-30f,
                                    0.5f, 2.0f };
   const uint32_t r = rnd();
   switch (rnd() % 6) {
   case 0: return from_bits(r);                               /* any bits */
   case 1: return (float)(r & 0xffffff) / 16777216.0f;        /* [0, 1) */
   case 2: return from_bits(r & 0x007fffff);                  /* denormal */
   case 3: return special[r % 9];
   default: return from_bits(0x3f000000u + (r & 0x00ffffff)); /* [0.5, 2) */
   }
}

static float random_exponent(void)
{
   const uint32_t q = rnd();
   switch (rnd() % 4) {
   case 0: return (float)(int)(q % 257) - 128.0f;
   case 1: return ((float)(q & 0xffffff) / 16777216.0f) * 256.0f - 128.0f;
   case 2: return (float)(q % 129);
   default: {
      const float y = from_bits(q);   /* any bits but NaN (LIT's exponent never is) */
      return isnan(y) ? 40.0f : y;
   }
   }
}

/* ---- the clipper ---- */

static void test_clip_mask(void)
{
   static const struct {
      float p[4];
      unsigned mask;
   } cases[] = {
      { { 0, 0, 0, 1 }, 0 },
      /* on the planes: inside */
      { { 1, -1, 1, 1 }, 0 },
      { { -1, 1, -1, 1 }, 0 },
      { { 2, 2, 2, 2 }, 0 },
      /* one plane each, in bit order */
      { { 1.5f, 0, 0, 1 }, 1u << 0 },
      { { -1.5f, 0, 0, 1 }, 1u << 1 },
      { { 0, 1.5f, 0, 1 }, 1u << 2 },
      { { 0, -1.5f, 0, 1 }, 1u << 3 },
      { { 0, 0, -1.5f, 1 }, 1u << 4 },
      { { 0, 0, 1.5f, 1 }, 1u << 5 },
      { { 3, -3, 3, 1 }, 1u << 0 | 1u << 3 | 1u << 5 },
      /* the smallest step past a plane */
      { { 0x1.000002p0f, 0, 0, 1 }, 1u << 0 },
      { { -0x1.000002p0f, 0, 0, 1 }, 1u << 1 },
      /* w = 0 and near it */
      { { 0, 0, 0, 0 }, 0 },
      { { 0, 0, 0, -0.0f }, 0 },
      { { 1e-30f, 0, 0, 0 }, 1u << 0 },
      { { 0, -1e-45f, 0, 0 }, 1u << 3 },
      { { 0, 0, 0, 1e-45f }, 0 },
      { { 0, 0, 0, -1e-45f }, 0x3fu },
      { { 1e-38f, 1e-38f, 1e-38f, -1e-38f }, 1u << 0 | 1u << 2 | 1u << 5 },
      /* everything behind the eye */
      { { 0.5f, 0.5f, 0.5f, -1 }, 0x3fu },
      /* unordered: NaN is outside both planes of its axis, all six for w */
      { { NAN, 0, 0, 1 }, 1u << 0 | 1u << 1 },
      { { 0, 0, NAN, 1 }, 1u << 4 | 1u << 5 },
      { { 0, 0, 0, NAN }, 0x3fu },
      /* x + w, not -w <= x: -inf + inf is NaN, outside */
      { { INFINITY, 0, 0, 1 }, 1u << 0 },
      { { -INFINITY, 0, 0, INFINITY }, 1u << 1 },
      { { INFINITY, 0, 0, INFINITY }, 0 },
   };
   for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
      const unsigned m = t_clip_mask(cases[i].p);
      CHECK(m == cases[i].mask, "t_clip_mask(%g, %g, %g, %g) = 0x%x, want 0x%x",
            (double)cases[i].p[0], (double)cases[i].p[1], (double)cases[i].p[2],
            (double)cases[i].p[3], m, cases[i].mask);
   }
}

/* a 100 x 100 y-down viewport */
static const float vp_scale[3] = { 50.0f, -50.0f, 0.5f };
static const float vp_translate[3] = { 50.0f, 50.0f, 0.5f };
/* user plane 0: x <= 0.5 w; plane 1: y >= 0 */
static const float user_planes[2][4] = { { -2, 0, 0, 1 }, { 0, 1, 0, 0 } };

static const unsigned clip_attrs = 1u << R_ATTR_COLOR0 | 1u << R_ATTR_TEX0;
#define SENTINEL 0x7f7f7f7fu

static struct t_clipper make_clipper(void)
{
   const struct t_clipper c = {
      .user_planes = user_planes,
      .scale = vp_scale,
      .translate = vp_translate,
      .attrs = clip_attrs,
   };
   return c;
}

/* a vertex at clip position p with outcode mask | t_clip_mask(p), colour
 * (g, g, g, 1) and texture coordinate (g, 1 - g, 0, 1) */
static void make_vertex(struct t_vertex *v, float x, float y, float z, float w, unsigned mask,
                        float g)
{
   memset(v, 0, sizeof(*v));
   v->clip[0] = x;
   v->clip[1] = y;
   v->clip[2] = z;
   v->clip[3] = w;
   v->mask = t_clip_mask(v->clip) | mask;
   v->edge = true;
   for (int c = 0; c < 3; c++)
      v->r.attr[R_ATTR_COLOR0][c] = g;
   v->r.attr[R_ATTR_COLOR0][3] = 1.0f;
   v->r.attr[R_ATTR_TEX0][0] = g;
   v->r.attr[R_ATTR_TEX0][1] = 1.0f - g;
   v->r.attr[R_ATTR_TEX0][3] = 1.0f;
   const float oow = 1.0f / w;
   for (int c = 0; c < 3; c++)
      v->r.pos[c] = fmaf(v->clip[c] * oow, vp_scale[c], vp_translate[c]);
   v->r.pos[3] = oow;
}

static void poly_init(struct t_clip_poly *p, const struct t_vertex *v0,
                      const struct t_vertex *v1, const struct t_vertex *v2)
{
   memset(p->tmp, 0x7f, sizeof(p->tmp));   /* SENTINEL in every float */
   p->n = 3;
   p->v[0] = v0;
   p->v[1] = v1;
   p->v[2] = v2;
   p->edge[0] = p->edge[1] = p->edge[2] = true;
   p->ntmp = 0;
}

/* A new vertex at clip (x, y, 0, 1) with grey g: its exact clip position,
 * outcode 0, window position in plain C, the interpolated varyings, and
 * the slots outside clip_attrs untouched. */
static void check_new_vertex(const struct t_vertex *v, float x, float y, float g,
                             const char *what)
{
   CHECK(v->clip[0] == x && v->clip[1] == y && v->clip[2] == 0.0f && v->clip[3] == 1.0f,
         "%s: clip (%g, %g, %g, %g), want (%g, %g, 0, 1)", what, (double)v->clip[0],
         (double)v->clip[1], (double)v->clip[2], (double)v->clip[3], (double)x, (double)y);
   CHECK(v->mask == 0, "%s: mask 0x%x", what, v->mask);
   CHECK(v->r.pos[0] == x * 50.0f + 50.0f && v->r.pos[1] == y * -50.0f + 50.0f &&
            v->r.pos[2] == 0.5f && v->r.pos[3] == 1.0f,
         "%s: window (%g, %g, %g, %g)", what, (double)v->r.pos[0], (double)v->r.pos[1],
         (double)v->r.pos[2], (double)v->r.pos[3]);
   CHECK(v->r.attr[R_ATTR_COLOR0][0] == g && v->r.attr[R_ATTR_COLOR0][3] == 1.0f,
         "%s: colour %g, %g, want %g, 1", what, (double)v->r.attr[R_ATTR_COLOR0][0],
         (double)v->r.attr[R_ATTR_COLOR0][3], (double)g);
   CHECK(v->r.attr[R_ATTR_TEX0][0] == g && v->r.attr[R_ATTR_TEX0][1] == 1.0f - g,
         "%s: texcoord %g, %g", what, (double)v->r.attr[R_ATTR_TEX0][0],
         (double)v->r.attr[R_ATTR_TEX0][1]);
   CHECK(to_bits(v->r.attr[R_ATTR_COLOR1][0]) == SENTINEL &&
            to_bits(v->r.attr[R_ATTR_FOG][0]) == SENTINEL,
         "%s: a slot outside attrs was written", what);
}

static unsigned new_vertex_calls[T_MAX_CLIPPED_VERTICES + 2];

static void count_new_vertex(void *data, struct t_vertex *v, unsigned slot)
{
   struct t_clip_poly *p = data;
   CHECK(v == &p->tmp[slot], "new_vertex: slot %u is not the vertex", slot);
   CHECK(v->mask == 0, "new_vertex: called before the vertex was made");
   new_vertex_calls[slot]++;
}

static void test_clip_polygon(void)
{
   struct t_clipper c = make_clipper();
   struct t_clip_poly p;
   struct t_vertex a, b, d;

   /* all inside (vertices on the planes included): as it went in */
   make_vertex(&a, -1, -1, -1, 1, 0, 0.0f);
   make_vertex(&b, 1, -1, 1, 1, 0, 0.5f);
   make_vertex(&d, 0, 1, 0, 1, 0, 1.0f);
   poly_init(&p, &a, &b, &d);
   p.edge[1] = false;
   t_clip_polygon(&c, &p);
   CHECK(p.n == 3 && p.v[0] == &a && p.v[1] == &b && p.v[2] == &d && p.ntmp == 0,
         "all inside: n %u, ntmp %u", p.n, p.ntmp);
   CHECK(p.edge[0] && !p.edge[1] && p.edge[2], "all inside: edge flags changed");

   /* all outside x > w: nothing, no vertex made */
   make_vertex(&a, 2, 0, 0, 1, 0, 0.0f);
   make_vertex(&b, 3, 1, 0, 1, 0, 0.5f);
   make_vertex(&d, 1.5f, -5, 0, 1, 0, 1.0f);
   poly_init(&p, &a, &b, &d);
   t_clip_polygon(&c, &p);
   CHECK(p.n == 0 && p.ntmp == 0, "all outside x > w: n %u, ntmp %u", p.n, p.ntmp);
   /* all outside a user plane (bit 7) though inside the view volume */
   make_vertex(&a, 0, -0.5f, 0, 1, 1u << 7, 0.0f);
   make_vertex(&b, 0.5f, -0.25f, 0, 1, 1u << 7, 0.5f);
   make_vertex(&d, -0.5f, -1, 0, 1, 1u << 7, 1.0f);
   poly_init(&p, &a, &b, &d);
   t_clip_polygon(&c, &p);
   CHECK(p.n == 0 && p.ntmp == 0, "all outside plane 7: n %u", p.n);
   /* all behind the eye (w < 0) */
   make_vertex(&a, 0, 0, 0, -1, 0, 0.0f);
   make_vertex(&b, 0.5f, 0, 0, -1, 0, 0.5f);
   make_vertex(&d, 0, 0.5f, 0, -2, 0, 1.0f);
   poly_init(&p, &a, &b, &d);
   t_clip_polygon(&c, &p);
   CHECK(a.mask == 0x3fu && p.n == 0, "all behind the eye: mask 0x%x, n %u", a.mask, p.n);

   /* x > w crossed by one vertex: distances 1, -3, 1, so t = 0.25 both
    * ways and every new value is exact; the new vertices follow their
    * edges, from the inside end (out + t * (in - out)) */
   make_vertex(&a, 0, -0.5f, 0, 1, 0, 0.0f);
   make_vertex(&b, 4, 0, 0, 1, 0, 1.0f);
   make_vertex(&d, 0, 0.5f, 0, 1, 0, 0.5f);
   CHECK(b.mask == 1u, "b.mask 0x%x", b.mask);
   poly_init(&p, &a, &b, &d);
   c.new_vertex = count_new_vertex;
   c.data = &p;
   memset(new_vertex_calls, 0, sizeof(new_vertex_calls));
   t_clip_polygon(&c, &p);
   c.new_vertex = NULL;
   c.data = NULL;
   CHECK(p.n == 4 && p.ntmp == 2, "x > w: n %u, ntmp %u", p.n, p.ntmp);
   if (p.n == 4 && p.ntmp == 2) {
      CHECK(p.v[0] == &a && p.v[1] == &p.tmp[0] && p.v[2] == &p.tmp[1] && p.v[3] == &d,
            "x > w: polygon order");
      check_new_vertex(&p.tmp[0], 1.0f, -0.375f, 0.25f, "x > w, leaving");
      check_new_vertex(&p.tmp[1], 1.0f, 0.375f, 0.625f, "x > w, entering");
      /* the edge along a view-volume plane is hidden: its vertex's flag
       * is off; the entering vertex has the outside vertex's */
      CHECK(!p.tmp[0].edge && p.tmp[1].edge, "x > w: vertex edge flags %d %d",
            p.tmp[0].edge, p.tmp[1].edge);
      CHECK(p.edge[0] && p.edge[1] && p.edge[2] && p.edge[3], "x > w: edge flags");
      CHECK(new_vertex_calls[0] == 1 && new_vertex_calls[1] == 1 && new_vertex_calls[2] == 0,
            "x > w: new_vertex calls %u %u %u", new_vertex_calls[0], new_vertex_calls[1],
            new_vertex_calls[2]);
   }

   /* the same plane as user plane 0 scaled (x <= 0.5 w, outcode bit 6):
    * distances 1, -7, 1, t = 0.125; an edge along a user plane is drawn */
   make_vertex(&a, 0, -0.5f, 0, 1, 0, 0.0f);
   make_vertex(&b, 4, 0, 0, 1, 1u << 6, 1.0f);
   make_vertex(&d, 0, 0.5f, 0, 1, 0, 0.5f);
   b.mask = 1u << 6;   /* the user plane only: x > w is not clipped here */
   poly_init(&p, &a, &b, &d);
   p.edge[0] = false;
   t_clip_polygon(&c, &p);
   CHECK(p.n == 4 && p.ntmp == 2, "user plane: n %u, ntmp %u", p.n, p.ntmp);
   if (p.n == 4 && p.ntmp == 2) {
      check_new_vertex(&p.tmp[0], 0.5f, -0.4375f, 0.125f, "user plane, leaving");
      check_new_vertex(&p.tmp[1], 0.5f, 0.4375f, 0.5625f, "user plane, entering");
      CHECK(p.tmp[0].edge && p.tmp[1].edge, "user plane: vertex edge flags");
      /* edge 0 (a -> new) keeps a's flag, the new edge along the plane is
       * drawn */
      CHECK(!p.edge[0] && p.edge[1] && p.edge[2] && p.edge[3], "user plane: edges %d %d %d %d",
            p.edge[0], p.edge[1], p.edge[2], p.edge[3]);
   }

   /* a vertex on the plane counts as inside: followed by an inside vertex
    * nothing is made, followed by an outside one a copy of it (t = 0) */
   make_vertex(&a, 1, 0, 0, 1, 0, 0.0f);
   make_vertex(&b, 2, 1, 0, 1, 0, 1.0f);
   make_vertex(&d, 0, 1, 0, 1, 0, 0.5f);
   CHECK(a.mask == 0 && b.mask == 1u, "on the plane: masks 0x%x 0x%x", a.mask, b.mask);
   poly_init(&p, &a, &b, &d);
   t_clip_polygon(&c, &p);
   CHECK(p.n == 4 && p.ntmp == 2, "on the plane: n %u, ntmp %u", p.n, p.ntmp);
   if (p.n == 4 && p.ntmp == 2) {
      CHECK(p.v[0] == &a && p.v[1] == &p.tmp[0] && p.v[3] == &d, "on the plane: order");
      check_new_vertex(&p.tmp[0], 1.0f, 0.0f, 0.0f, "on the plane, copy");
      check_new_vertex(&p.tmp[1], 1.0f, 1.0f, 0.75f, "on the plane, entering");
   }

   /* two planes (x > w, then y > w) crossed by one corner: a pentagon,
    * the first plane's new vertex clipped again by the second */
   make_vertex(&a, 0, 0, 0, 1, 0, 0.0f);
   make_vertex(&b, 3, 0, 0, 1, 0, 1.0f);
   make_vertex(&d, 0, 3, 0, 1, 0, 0.5f);
   poly_init(&p, &a, &b, &d);
   t_clip_polygon(&c, &p);
   CHECK(p.n == 4 && p.ntmp == 4, "x and y: n %u, ntmp %u", p.n, p.ntmp);
   if (p.n == 4) {
      /* x <= 1 gives a, (1, 0), (1, 2), d; y <= 1 then a, (1, 0), (1, 1),
       * (0, 1) */
      static const float want[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
      for (unsigned i = 0; i < 4; i++)
         CHECK(fabsf(p.v[i]->clip[0] - want[i][0]) <= 1e-6f &&
                  fabsf(p.v[i]->clip[1] - want[i][1]) <= 1e-6f && p.v[i]->mask == 0,
               "x and y: vertex %u at (%g, %g)", i, (double)p.v[i]->clip[0],
               (double)p.v[i]->clip[1]);
   }
   /* the new vertices' window positions are plain C, not fused (an odd
    * triangle and viewport: at least one of them differs in the last bit
    * from the fused form) */
   static const float odd_scale[3] = { 333.3f, -217.7f, 0.3f };
   static const float odd_translate[3] = { 333.3f, 217.7f, 0.6f };
   struct t_clipper odd = c;
   odd.scale = odd_scale;
   odd.translate = odd_translate;
   make_vertex(&a, 0.1f, 0.2f, 0.3f, 1, 0, 0.0f);
   make_vertex(&b, 2.7f, 0.35f, -0.4f, 1.3f, 0, 1.0f);
   make_vertex(&d, -0.3f, 2.9f, 0.2f, 1.1f, 0, 0.5f);
   poly_init(&p, &a, &b, &d);
   t_clip_polygon(&odd, &p);
   CHECK(p.n >= 3 && p.ntmp >= 2, "odd: n %u, ntmp %u", p.n, p.ntmp);
   bool fused_differs = false;
   for (unsigned i = 0; i < p.ntmp; i++) {
      const struct t_vertex *v = &p.tmp[i];
      const float oow = 1.0f / v->clip[3];
      for (int k = 0; k < 3; k++) {
         const float plain = v->clip[k] * oow * odd_scale[k] + odd_translate[k];
         CHECK(to_bits(v->r.pos[k]) == to_bits(plain), "odd: tmp %u window %d: %a, want %a",
               i, k, (double)v->r.pos[k], (double)plain);
         if (to_bits(plain) != to_bits(fmaf(v->clip[k] * oow, odd_scale[k], odd_translate[k])))
            fused_differs = true;
      }
   }
   CHECK(fused_differs, "odd: no new vertex tells plain from fused");

   /* w near 0: one vertex barely behind the eye (outside all six planes)
    * against two inside; every vertex left lies in the view volume with
    * w > 0 and a finite window position */
   make_vertex(&a, -0.5f, -0.5f, 0.5f, 1, 0, 0.0f);
   make_vertex(&b, 1e-8f, 2e-8f, 0, -1e-7f, 0, 1.0f);
   make_vertex(&d, 0.5f, -0.5f, -0.5f, 1, 0, 0.5f);
   CHECK(b.mask == 0x3fu, "w near 0: mask 0x%x", b.mask);
   poly_init(&p, &a, &b, &d);
   t_clip_polygon(&c, &p);
   CHECK(p.n >= 3 && p.n <= 9, "w near 0: n %u", p.n);
   CHECK(p.v[0] == &a, "w near 0: first vertex");
   for (unsigned i = 0; i < p.n; i++) {
      const struct t_vertex *v = p.v[i];
      const float eps = 1e-6f * v->clip[3];
      CHECK(v->clip[3] > 0.0f && fabsf(v->clip[0]) <= v->clip[3] + eps &&
               fabsf(v->clip[1]) <= v->clip[3] + eps && fabsf(v->clip[2]) <= v->clip[3] + eps,
            "w near 0: vertex %u at (%g, %g, %g, %g)", i, (double)v->clip[0],
            (double)v->clip[1], (double)v->clip[2], (double)v->clip[3]);
      CHECK(isfinite(v->r.pos[0]) && isfinite(v->r.pos[1]) && isfinite(v->r.pos[2]),
            "w near 0: vertex %u window (%g, %g)", i, (double)v->r.pos[0],
            (double)v->r.pos[1]);
   }
   /* w = 0 exactly on every plane: inside, untouched */
   make_vertex(&b, 0, 0, 0, 0, 0, 1.0f);
   CHECK(b.mask == 0, "w = 0: mask 0x%x", b.mask);

   /* a NaN distance discards the triangle */
   make_vertex(&a, 0, 0, 0, 1, 0, 0.0f);
   make_vertex(&b, NAN, 0, 0, 1, 0, 1.0f);
   make_vertex(&d, 0, 0.5f, 0, 1, 0, 0.5f);
   CHECK(b.mask == 3u, "NaN: mask 0x%x", b.mask);
   poly_init(&p, &a, &b, &d);
   t_clip_polygon(&c, &p);
   CHECK(p.n < 3, "NaN: n %u", p.n);
}

#define N 4096

int main(void)
{
   test_clip_mask();
   test_clip_polygon();

   static float x[N], y[N], out[N];
   long differ = 0;
#if defined(__SSE__) || defined(__x86_64__)
   const unsigned mxcsr = _mm_getcsr();
#endif
   for (int flush = 0; flush < 2; flush++) {
#if defined(__SSE__) || defined(__x86_64__)
      _mm_setcsr(flush ? mxcsr | 0x8040u : mxcsr);   /* FTZ | DAZ */
#endif
      for (int round = 0; round < 500; round++) {
         for (int k = 0; k < N; k++) {
            x[k] = random_base();
            y[k] = random_exponent();
         }
         t_lit_pows(x, y, out, N);
         for (int k = 0; k < N; k++) {
            const float want = m_gallivm_pow(x[k], y[k]);
            if (to_bits(want) != to_bits(out[k]) && differ++ < 10)
               FAIL("flush %d: pow(%08x, %08x) = %08x, want %08x", flush, to_bits(x[k]),
                    to_bits(y[k]), to_bits(out[k]), to_bits(want));
         }
      }
   }
#if defined(__SSE__) || defined(__x86_64__)
   _mm_setcsr(mxcsr);
#endif
   CHECK(differ == 0, "%ld of %d pows differ", differ, 2 * 500 * N);
   return check_report("vertex");
}
