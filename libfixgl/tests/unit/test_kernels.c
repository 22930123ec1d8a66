/*
 * test_kernels.c - the kernel-equivalence test (raster/r_kernel.h): every
 * fast kernel draws the same colour, depth and stencil bytes as the
 * reference kernels.
 *
 * Each batch creates two contexts of the same random configuration
 * (OSMESA_RGBA / BGRA / ARGB / RGB / BGR, depth 0 / 16 / 24, stencil 0 / 8,
 * a small buffer whose width is often not a multiple of 4): one as usual,
 * which chooses the fast kernels the CPU runs, and one created under
 * FIXGL_KERNELS=reference.  The same random GL call stream (the batch's
 * seed replayed) is drawn into both: four random textures, a clear, then
 * cases, each changing a random subset of the whole GL 1.x state and
 * drawing random primitives under it.  The state: depth function, mask
 * and range; stencil function, operations and masks; alpha test; blend
 * equation, factors and colour; logic op; colour mask; draw buffer;
 * scissor; viewport; shade model including GL_PHONG_WIN; lighting with
 * Blinn-Phong and Cook-Torrance materials, spots, attenuation, two-sided
 * lighting, local viewer, colour material and separate specular; fog
 * modes, coordinate source and distance mode; up to four texture units
 * with 1D/2D textures of every base format and several sized ones, every
 * filter, wrap (mirror and border ones included), LOD bias, min/max LOD
 * and base level, and every environment (combine, crossbar, dot3,
 * combine3, combine4), texgen and texture matrices; polygon modes,
 * culling, front face, offsets, stipple and a user clip plane; line width,
 * stipple and smoothing; point size and smoothing; projections (clip
 * coordinates with w near 0 and behind the eye, pixel ortho, frustum).
 * Each batch draws its groups of optional state (stencil, alpha test,
 * blending, logic op and masks, fog, texturing, lighting, polygon) as
 * off, as real programs set them, or anything, with none, one, a few or
 * all of them on, so that plain states, each feature alone and every mix
 * come up often.  The primitives: triangles, strips, fans, quads,
 * polygons, rectangles (tiny to huge, vertices on pixel corners and
 * centres and the subpixel grid, perspective, partly off-screen,
 * degenerate, redrawn at equal depths), lines, line strips and loops
 * (widths 1 to 8, whole and fractional; anywhere, or from pixel centre to
 * pixel centre in every orientation, axis-aligned and diagonal ones
 * included), points (sizes 1 to 16, whole and fractional; legacy, smooth
 * and sprites with GL_COORD_REPLACE on random units and either origin),
 * vertex arrays,
 * and a few glDrawPixels (colour, depth, stencil), glBitmap and
 * glCopyPixels; now and then, in the middle of a case, a clear of some of
 * the buffers (whole: lazy; or scissored or masked: a quad) or a
 * glReadPixels of colour, depth or stencil, whose bytes must be the same
 * in both contexts.  Each context draws with one thread (directly, a
 * triangle writing the lazy clears of its box's tiles first, scene.c) or
 * the default threads (binned into tiles), chosen per batch and per side.
 * The internal colour, depth and stencil
 * buffers of the two contexts are then compared byte for byte, and the
 * results of the occlusion queries that about half the cases draw inside
 * (the samples each kernel counts) number for number.
 *
 * Nothing here depends on which kernels exist: the comparison covers any
 * kernel r_choose_kernels picks.  The coverage count reads the kernels
 * the fast context chose (kernel_of below: r_state.tri_kernel and
 * line_kernel today; list new kernel fields there) after each case that
 * drew filled triangles, (non-smooth) lines, or (non-smooth) points
 * of three pixels or more, per kind of primitive, with a key of the raster state that matters to kernels
 * (make_key), and prints the distinct (kernel, state key) combinations a
 * fast kernel drew, the state keys that fell back to the reference
 * kernels, the primitives and the fragments drawn.  Where fast kernels
 * can run (the library built with them, a CPU with AVX2 and FMA) it fails
 * when none was exercised; elsewhere it says so and passes.
 *
 * On a mismatch it replays the batch with fresh contexts, draw call by
 * draw call, to the first call after which the buffers differ, and prints
 * the seed, batch, case, the GL calls of the batch up to that call, the
 * fast context's raster state and the first differing pixel, then fails.
 *
 * Before the run a self-check changes one byte of each buffer of a drawn
 * pair and requires the comparison to notice it.
 *
 *   --seed N      the run's seed (default 1)
 *   --count N     primitives to draw at least (default 200000)
 *   --batch N     replay batch N of the seed alone, with its GL calls
 *                 printed
 *   --perturb N   flip a byte of batch N's fast colour buffer (shows the
 *                 failure path)
 *   --same        both contexts with the usual kernels (a mismatch then
 *                 means drawing that is not deterministic)
 *   -v            one line per batch
 */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "GL/osmesa.h"
#include "fixgl/fixgl.h"
#include <GL/glext.h>

#include "context.h"
#include "raster/r_kernel.h"
#include "raster/r_state.h"

#include "check.h"

/* ---- random numbers ----------------------------------------------------- */

static uint64_t rng_state;

static uint64_t mix64(uint64_t z)
{
   z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
   z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
   return z ^ (z >> 31);
}

static uint64_t rnd64(void)
{
   return mix64(rng_state += 0x9e3779b97f4a7c15ull);
}

/* 0 .. n - 1 */
static int rnd(int n)
{
   return (int)(rnd64() % (uint64_t)n);
}

/* [0, 1) */
static float rndf(void)
{
   return (float)(rnd64() >> 40) * (1.0f / 16777216.0f);
}

static float rndr(float a, float b)
{
   return a + (b - a) * rndf();
}

/* true with probability p */
static bool chance(float p)
{
   return rndf() < p;
}

#define PICK(arr) ((arr)[rnd((int)(sizeof(arr) / sizeof((arr)[0])))])

/* ---- the log of a batch's calls (on a replay) --------------------------- */

static bool g_log, g_log_stopped;
static char *g_logbuf;
static size_t g_loglen, g_logcap;

static void L(const char *fmt, ...)
{
   if (!g_log || g_log_stopped)
      return;
   char line[512];
   va_list ap;
   va_start(ap, fmt);
   int n = vsnprintf(line, sizeof line, fmt, ap);
   va_end(ap);
   if (n < 0)
      return;
   if ((size_t)n >= sizeof line)
      n = sizeof line - 1;
   if (g_loglen + (size_t)n + 2 > g_logcap) {
      g_logcap = (g_logcap + (size_t)n + 2) * 2;
      g_logbuf = realloc(g_logbuf, g_logcap);
   }
   memcpy(g_logbuf + g_loglen, line, (size_t)n);
   g_loglen += (size_t)n;
   g_logbuf[g_loglen++] = '\n';
   g_logbuf[g_loglen] = 0;
}

/* ---- a batch's configuration -------------------------------------------- */

struct config {
   GLenum format;
   int depth, stencil;
   int w, h;
   /* FIXGL_NUM_THREADS of the fast and the reference context (1, or 0:
    * the default): one thread draws directly, each triangle writing the
    * lazy clears of its box first (scene.c "Lazy clears"); more bin into
    * tiles */
   int threads[2];
};

static const char *format_name(GLenum f)
{
   switch (f) {
   case OSMESA_RGBA: return "RGBA";
   case OSMESA_BGRA: return "BGRA";
   case OSMESA_ARGB: return "ARGB";
   case OSMESA_RGB:  return "RGB";
   case OSMESA_BGR:  return "BGR";
   default:          return "?";
   }
}

static struct config pick_config(uint64_t bseed)
{
   rng_state = bseed ^ 0x5bd1e995u;
   static const GLenum formats[] = { OSMESA_RGBA, OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB,
                                     OSMESA_RGB, OSMESA_BGR };
   static const int depths[] = { 0, 16, 24, 24 };
   static const int sizes[][2] = { { 64, 64 }, { 61, 37 }, { 96, 64 }, { 33, 50 }, { 64, 48 },
                                   { 7, 9 } };
   struct config c;
   c.format = PICK(formats);
   c.depth = PICK(depths);
   c.stencil = chance(0.5f) ? 8 : 0;
   const int s = rnd(16) < 14 ? rnd(5) : 5;
   c.w = sizes[s][0];
   c.h = sizes[s][1];
   /* (from the seed's bits, not its random stream) */
   c.threads[0] = (bseed >> 3) % 4 ? 1 : 0;
   c.threads[1] = (bseed >> 5) % 2 ? 1 : 0;
   return c;
}

struct side {
   OSMesaContext osm;
   uint8_t *buf;
   struct fgl_context *gl;
};

/* --same: both contexts choose their kernels as usual (a mismatch is
 * then no kernel's: the drawing is not deterministic) */
static bool g_same;

/* FIXGL_KERNELS for the fast side: NULL (the best build this CPU runs) or
 * "avx2" (the AVX2 build of the kernels on a CPU with AVX-512, which
 * otherwise runs their AVX-512 build: both are compared) */
static const char *g_fast_kernels;

static bool make_side(struct side *sd, const struct config *c, bool reference)
{
   if (g_same)
      reference = false;
   if (reference)
      setenv("FIXGL_KERNELS", "reference", 1);
   else if (g_fast_kernels)
      setenv("FIXGL_KERNELS", g_fast_kernels, 1);
   const char *nt = getenv("FIXGL_NUM_THREADS");
   char *saved = nt ? strdup(nt) : NULL;
   if (c->threads[reference])
      setenv("FIXGL_NUM_THREADS", "1", 1);
   sd->osm = OSMesaCreateContextExt(c->format, c->depth, c->stencil, 0, NULL);
   if (saved)
      setenv("FIXGL_NUM_THREADS", saved, 1);
   else
      unsetenv("FIXGL_NUM_THREADS");
   free(saved);
   if (reference || g_fast_kernels)
      unsetenv("FIXGL_KERNELS");
   if (!sd->osm)
      return false;
   sd->buf = calloc((size_t)c->w * (size_t)c->h, 4);
   if (!sd->buf || !OSMesaMakeCurrent(sd->osm, sd->buf, GL_UNSIGNED_BYTE, c->w, c->h))
      return false;
   sd->gl = fgl_get_current();
   return sd->gl && sd->gl->_Raster.reference_kernels == reference &&
          (reference || !g_fast_kernels || sd->gl->_Raster.kernel_isa != R_ISA_AVX512);
}

static void free_side(struct side *sd)
{
   if (sd->osm)
      OSMesaDestroyContext(sd->osm);
   free(sd->buf);
   memset(sd, 0, sizeof *sd);
}

/* ---- coverage ------------------------------------------------------------ */

/* The kernels rs chose, NULL for the reference: the one a filled triangle
 * with a flat or interpolated colour uses.  List new kernel fields of
 * r_state here. */
typedef void (*any_kernel)(void);
enum { KIND_TRI_SMOOTH, KIND_TRI_FLAT, KIND_LINE_SMOOTH, KIND_LINE_FLAT, KIND_POINT, KIND_COUNT };

static any_kernel kernel_of(const struct r_state *rs, int kind)
{
   switch (kind) {
   case KIND_TRI_SMOOTH:  return (any_kernel)rs->tri_kernel[0];
   case KIND_TRI_FLAT:    return (any_kernel)rs->tri_kernel[1];
   case KIND_LINE_SMOOTH: return (any_kernel)rs->line_kernel[0];
   case KIND_LINE_FLAT:   return (any_kernel)rs->line_kernel[1];
   /* a point's inputs are all flat (r_point.c) */
   case KIND_POINT:
      return (any_kernel)rs->line_kernel[(rs->fs->fs_inputs >> R_FS_COLOR0) & 1u];
   default:               return NULL;
   }
}

/* The raster state that decides kernels, with the fields that do not
 * apply zeroed. */
struct state_key {
   uint8_t kind, zs_format, depth_func, depth_write, stencil_func, sfail, szfail, szpass;
   uint8_t alpha_func, blend_eq, blend_src, blend_dst, logic_op, color_mask, dst_alpha_one;
   uint8_t flags, fog_mode, aa, phong, model[2], tex_nr, pix;
   uint32_t fs_inputs, tex_units;
   struct {
      uint8_t dims, min, mag, mip, ws, wt, soa, float_path;
      uint8_t mode_rgb, mode_a, simple, fn_rgb, fn_a;
   } tex[4];
};

static uint64_t key_hash(const struct state_key *k)
{
   const uint8_t *p = (const uint8_t *)k;
   uint64_t h = 1469598103934665603ull;
   for (size_t i = 0; i < sizeof *k; i++)
      h = (h ^ p[i]) * 1099511628211ull;
   return mix64(h) | 1;   /* never 0: 0 marks a free slot */
}

static void make_key(const struct r_state *rs, int kind, struct state_key *k)
{
   memset(k, 0, sizeof *k);
   k->kind = (uint8_t)kind;
   k->zs_format = (uint8_t)rs->fb->zs_format;
   if (rs->dsa->depth_test) {
      k->depth_func = (uint8_t)(rs->dsa->depth_func + 1);
      k->depth_write = rs->dsa->depth_write;
   }
   if (rs->full_ops) {
      if (rs->dsa->stencil_test) {
         k->stencil_func = (uint8_t)(rs->dsa->stencil_func + 1);
         k->sfail = (uint8_t)rs->dsa->stencil_fail;
         k->szfail = (uint8_t)rs->dsa->stencil_zfail;
         k->szpass = (uint8_t)rs->dsa->stencil_zpass;
      }
      if (rs->dsa->alpha_test)
         k->alpha_func = (uint8_t)(rs->dsa->alpha_func + 1);
      if (rs->blend->enable) {
         k->blend_eq = (uint8_t)(rs->blend->blend_eq + 1);
         k->blend_src = (uint8_t)rs->blend->blend_src;
         k->blend_dst = (uint8_t)rs->blend->blend_dst;
      }
      if (rs->blend->logic_op)
         k->logic_op = (uint8_t)(rs->blend->logic_op_mode + 1);
      k->color_mask = (uint8_t)rs->blend->color_mask;
      k->dst_alpha_one = rs->blend->dst_alpha_one;
   }
   k->flags = (uint8_t)(rs->full_ops | rs->fs->color_sum << 1 | rs->rast->twoside << 2 | rs->rast->stipple << 3 |
                        rs->dsa->alpha_test_float << 4 |
                        (kind == KIND_POINT && rs->rast->point_sprite) << 5);
   k->fog_mode = (uint8_t)rs->fs->fog_mode;
   k->aa = (uint8_t)rs->fs->aa;
   k->phong = rs->fs->phong;
   if (rs->fs->phong) {
      k->model[0] = (uint8_t)(rs->shade_env->material[0].model + 1);
      k->model[1] = (uint8_t)(rs->shade_env->material[1].model + 1);
   }
   k->pix = rs->pix ? (uint8_t)(rs->pix->kind + 1) : 0;
   k->fs_inputs = rs->fs->fs_inputs;
   k->tex_units = rs->fs->tex_units;
   k->tex_nr = (uint8_t)rs->fs->tex_nr;
   for (int u = 0; u < 4 && u < rs->fs->tex_nr; u++) {
      if (!(rs->fs->tex_units & (1u << u)))
         continue;
      const struct r_tex_unit *tu = rs->tex[u];
      k->tex[u].dims = (uint8_t)tu->tex.dims;
      k->tex[u].min = (uint8_t)tu->tex.min_img;
      k->tex[u].mag = (uint8_t)tu->tex.mag_img;
      k->tex[u].mip = (uint8_t)tu->tex.mip;
      k->tex[u].ws = (uint8_t)tu->tex.wrap_s;
      k->tex[u].wt = (uint8_t)tu->tex.wrap_t;
      k->tex[u].soa = tu->tex.soa;
      k->tex[u].float_path = tu->tex.float_path;
      k->tex[u].mode_rgb = tu->comb.mode_rgb;
      k->tex[u].mode_a = tu->comb.mode_a;
      k->tex[u].simple = tu->comb.simple;
      k->tex[u].fn_rgb = tu->comb.simple_fn_rgb;
      k->tex[u].fn_a = tu->comb.simple_fn_a;
   }
}

/* a set of 64-bit values (0 is not one) */
struct set {
   uint64_t *v;
   size_t cap, n;
};

static bool set_add(struct set *s, uint64_t x)
{
   if (2 * (s->n + 1) > s->cap) {
      struct set t = { calloc(s->cap ? 2 * s->cap : 1024, sizeof(uint64_t)),
                       s->cap ? 2 * s->cap : 1024, 0 };
      for (size_t i = 0; i < s->cap; i++)
         if (s->v[i])
            set_add(&t, s->v[i]);
      free(s->v);
      *s = t;
   }
   size_t i = (size_t)(x % s->cap);
   while (s->v[i]) {
      if (s->v[i] == x)
         return false;
      i = (i + 1) % s->cap;
   }
   s->v[i] = x;
   s->n++;
   return true;
}

static struct set g_combos;      /* (kernel, state key) drawn by a fast kernel */
static struct set g_fallback;    /* state keys the reference drew */
static struct set g_keys;        /* every state key */
static any_kernel g_kernels[256];
/* the combinations of g_combos per kind of primitive (the kind is part
 * of the state key) */
static unsigned long g_kind_combos[KIND_COUNT];
static int g_nkernels;

static int kernel_index(any_kernel k)
{
   for (int i = 0; i < g_nkernels; i++)
      if (g_kernels[i] == k)
         return i;
   if (g_nkernels < 256)
      g_kernels[g_nkernels++] = k;
   return g_nkernels - 1;
}

/* ---- the generator ------------------------------------------------------- */

/* the draw calls of the batch so far, and the call the replay stops
 * before (no draws from then on) */
static long g_calls, g_limit;
static bool g_record;
static struct {
   uint64_t tris, lines, points, pixels, cases, batches, fragments, stats_batches, gl_errors;
   uint64_t queries, samples;
} g_count;
static bool g_count_on;

enum { GROUP_STENCIL, GROUP_ALPHA, GROUP_BLEND, GROUP_MASK, GROUP_FOG, GROUP_TEX, GROUP_LIGHT,
       GROUP_POLY, GROUP_COUNT };
enum { MODE_OFF, MODE_USUAL, MODE_ANY };

/* state of the generator during a batch */
static struct gen {
   struct config cfg;
   int proj;              /* 0 clip coordinates, 1 pixels (ortho), 2 frustum */
   int nunits;            /* texture units whose coordinates are sent */
   bool filled;           /* both polygon modes GL_FILL */
   bool case_tris;        /* this case drew filled triangles */
   bool case_lines;       /* ... non-smooth lines */
   bool case_points;      /* ... non-smooth points of 3 pixels or more */
   bool line_smooth, point_smooth, point_sprite;
   float point_size;
   int case_index;
   bool tex_2d[4];        /* texture i + 1 is 2D (else 1D) */
   /* the batch's mode of each group of optional state (stencil, alpha
    * test, blending, logic op and colour mask, fog, texturing, lighting
    * and GL_PHONG_WIN, polygon modes, offsets and stipple): off, the usual
    * settings of real programs, or anything, so that the states every
    * kernel covers come up often and alone as well as mixed */
   int mode[GROUP_COUNT];
   float last[2][4];      /* the last two vertices sent (degenerate ones) */
   /* the last polygon draw's vertices, drawn again by draw_repeat (equal
    * depths: multi-pass, GL_EQUAL, decals) */
   GLenum rep_prim;
   int rep_n, rep_tris;
   float rep_v[16][4];
   bool flat_z;           /* this shape's vertices share one z */
   float flat_zv;
} G;

static int g_limit_case;   /* the case of the last draw call allowed */

static bool draw_allowed(void)
{
   if (g_calls >= g_limit) {
      g_log_stopped = true;
      return false;
   }
   g_calls++;
   g_limit_case = G.case_index;
   return true;
}

static float rnd_color_comp(void)
{
   switch (rnd(11)) {
   case 0:  return rndr(-0.3f, 1.3f);
   case 1:  return (float)rnd(2);
   case 2:  return (float)rnd(256) / 255.0f;
   case 3:  return ((float)rnd(255) + 0.5f) / 255.0f;   /* rounding ties */
   default: return rndf();
   }
}

static void rnd_color4(float c[4])
{
   for (int i = 0; i < 4; i++)
      c[i] = rnd_color_comp();
}

static const GLenum funcs[] = { GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS };

/* -- per-fragment operations -- */

static void set_depth(void)
{
   const bool on = chance(0.75f);
   const GLenum f = chance(0.3f) ? GL_LESS : PICK(funcs);
   const bool mask = chance(0.7f);
   L("depth test %d func 0x%x mask %d", on, f, mask);
   if (on)
      glEnable(GL_DEPTH_TEST);
   else
      glDisable(GL_DEPTH_TEST);
   glDepthFunc(f);
   glDepthMask(mask);
   if (chance(0.2f)) {
      const double n = chance(0.5f) ? 0.0 : rndf(), fa = chance(0.5f) ? 1.0 : rndf();
      L("depth range %g %g", n, fa);
      glDepthRange(n, fa);
   }
}

static const GLenum sops[] = { GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR,
                               GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP };

static void set_stencil(void)
{
   const int mode = G.mode[GROUP_STENCIL];
   const bool on = mode != MODE_OFF && chance(mode == MODE_ANY ? 0.6f : 0.8f);
   GLenum f = PICK(funcs), a = PICK(sops), b = PICK(sops), c = PICK(sops);
   const int ref = chance(0.8f) ? rnd(256) : rnd(600) - 100;
   unsigned vm = chance(0.6f) ? 0xffu : (unsigned)rnd(256);
   unsigned wm = chance(0.6f) ? 0xffu : (unsigned)rnd(256);
   if (mode == MODE_USUAL) {
      /* mark, then draw where marked (or not) */
      static const GLenum usual_funcs[] = { GL_ALWAYS, GL_EQUAL, GL_NOTEQUAL, GL_LESS };
      static const GLenum usual_ops[] = { GL_KEEP, GL_KEEP, GL_REPLACE, GL_INCR, GL_ZERO };
      f = PICK(usual_funcs);
      a = GL_KEEP;
      b = chance(0.7f) ? GL_KEEP : PICK(usual_ops);
      c = PICK(usual_ops);
      vm = wm = 0xffu;
   }
   L("stencil test %d func 0x%x ref %d vmask 0x%x ops 0x%x 0x%x 0x%x wmask 0x%x", on, f, ref, vm,
     a, b, c, wm);
   if (on)
      glEnable(GL_STENCIL_TEST);
   else
      glDisable(GL_STENCIL_TEST);
   glStencilFunc(f, ref, vm);
   glStencilOp(a, b, c);
   glStencilMask(wm);
}

static void set_alpha(void)
{
   const int mode = G.mode[GROUP_ALPHA];
   const bool on = mode != MODE_OFF && chance(0.8f);
   static const GLenum usual_funcs[] = { GL_GREATER, GL_GEQUAL, GL_NOTEQUAL, GL_LESS };
   const GLenum f = mode == MODE_USUAL ? PICK(usual_funcs) : PICK(funcs);
   const float ref = mode == MODE_USUAL ? (chance(0.5f) ? 0.0f : rndf())
                   : chance(0.8f) ? rndf() : rndr(-0.5f, 1.5f);
   L("alpha test %d func 0x%x ref %.9g", on, f, ref);
   if (on)
      glEnable(GL_ALPHA_TEST);
   else
      glDisable(GL_ALPHA_TEST);
   glAlphaFunc(f, ref);
}

static const GLenum bfactors[] = {
   GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA,
   GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA,
   GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA,
   GL_ONE_MINUS_CONSTANT_ALPHA,
};

static void set_blend(void)
{
   static const GLenum eqs[] = { GL_FUNC_ADD, GL_FUNC_ADD, GL_FUNC_ADD, GL_FUNC_SUBTRACT,
                                 GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX };
   static const GLenum usual[][2] = {
      { GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA }, { GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA },
      { GL_ONE, GL_ONE }, { GL_SRC_ALPHA, GL_ONE }, { GL_ONE, GL_ONE_MINUS_SRC_ALPHA },
      { GL_DST_COLOR, GL_ZERO }, { GL_ZERO, GL_SRC_COLOR }, { GL_ONE, GL_ZERO },
   };
   const int mode = G.mode[GROUP_BLEND];
   /* "off": no blending or the standard alpha blend */
   const bool on = mode != MODE_OFF ? chance(0.8f) : chance(0.4f);
   GLenum src = PICK(bfactors), dst = PICK(bfactors);
   if (mode == MODE_OFF) {
      src = GL_SRC_ALPHA;
      dst = GL_ONE_MINUS_SRC_ALPHA;
   } else if (mode == MODE_USUAL) {
      const int u = rnd((int)(sizeof usual / sizeof usual[0]));
      src = usual[u][0];
      dst = usual[u][1];
   }
   const GLenum eq = mode == MODE_ANY ? PICK(eqs) : GL_FUNC_ADD;
   float bc[4];
   rnd_color4(bc);
   L("blend %d eq 0x%x src 0x%x dst 0x%x color %.9g %.9g %.9g %.9g", on, eq, src, dst, bc[0],
     bc[1], bc[2], bc[3]);
   if (on)
      glEnable(GL_BLEND);
   else
      glDisable(GL_BLEND);
   glBlendFunc(src, dst);
   glBlendEquation(eq);
   /* glBlendFuncSeparate / glBlendEquationSeparate: the alpha channel's
    * own factors and equation (the generic kernel's per-lane selection) */
   if (mode == MODE_ANY && chance(0.3f)) {
      const GLenum src_a = PICK(bfactors), dst_a = PICK(bfactors), eq_a = PICK(eqs);
      L("blend separate alpha eq 0x%x src 0x%x dst 0x%x", eq_a, src_a, dst_a);
      glBlendFuncSeparate(src, dst, src_a, dst_a);
      glBlendEquationSeparate(eq, eq_a);
   }
   glBlendColor(bc[0], bc[1], bc[2], bc[3]);
}

static void set_logic_mask(void)
{
   const int mode = G.mode[GROUP_MASK];
   const bool lo = mode == MODE_ANY && chance(0.4f);
   static const GLenum usual_ops[] = { GL_XOR, GL_INVERT, GL_COPY };
   const GLenum op = mode == MODE_USUAL ? PICK(usual_ops) : GL_CLEAR + (GLenum)rnd(16);
   static const unsigned usual_masks[] = { 0xf, 0x7, 0x8, 0x0 };
   const unsigned cm = mode == MODE_OFF ? 0xfu : mode == MODE_USUAL ? PICK(usual_masks)
                     : (unsigned)rnd(16);
   L("logic op %d 0x%x colour mask 0x%x", lo, op, cm);
   if (lo)
      glEnable(GL_COLOR_LOGIC_OP);
   else
      glDisable(GL_COLOR_LOGIC_OP);
   glLogicOp(op);
   glColorMask(cm & 1, (cm >> 1) & 1, (cm >> 2) & 1, (cm >> 3) & 1);
   if (mode == MODE_ANY && chance(0.1f)) {
      static const GLenum bufs[] = { GL_NONE, GL_FRONT, GL_FRONT_AND_BACK };
      const GLenum db = PICK(bufs);
      L("draw buffer 0x%x", db);
      glDrawBuffer(db);
   }
   if (chance(0.2f)) {
      const bool di = chance(0.5f);
      L("dither %d", di);
      if (di)
         glEnable(GL_DITHER);
      else
         glDisable(GL_DITHER);
   }
}

static void set_scissor(void)
{
   const bool on = chance(0.25f);
   const int x = rnd(G.cfg.w) - 4, y = rnd(G.cfg.h) - 4;
   const int w = rnd(G.cfg.w + 8), h = rnd(G.cfg.h + 8);
   L("scissor %d %d %d %d %d", on, x, y, w, h);
   if (on)
      glEnable(GL_SCISSOR_TEST);
   else
      glDisable(GL_SCISSOR_TEST);
   glScissor(x, y, w, h);
}

/* -- shading and lighting -- */

static void set_shade_model(void)
{
   static const GLenum models[] = { GL_SMOOTH, GL_SMOOTH, GL_FLAT, GL_PHONG_WIN, GL_PHONG_WIN };
   const GLenum m = models[rnd(G.mode[GROUP_LIGHT] != MODE_OFF ? 5 : 3)];
   L("shade model 0x%x", m);
   glShadeModel(m);
}

static void rnd_vec4(float v[4], float lo, float hi)
{
   for (int i = 0; i < 4; i++)
      v[i] = rndr(lo, hi);
}

static void set_lighting(void)
{
   const int mode = G.mode[GROUP_LIGHT];
   const bool on = mode != MODE_OFF && chance(0.85f);
   L("lighting %d", on);
   if (on)
      glEnable(GL_LIGHTING);
   else
      glDisable(GL_LIGHTING);
   if (!on && chance(0.5f))
      return;
   for (int i = 0; i < 3; i++) {
      const GLenum li = GL_LIGHT0 + (GLenum)i;
      const bool en = i == 0 ? chance(0.9f) : chance(0.4f);
      if (!en) {
         glDisable(li);
         continue;
      }
      glEnable(li);
      float pos[4], amb[4], dif[4], spe[4], dir[4];
      rnd_vec4(pos, -3.0f, 3.0f);
      pos[3] = chance(0.5f) ? 0.0f : rndr(0.5f, 2.0f);
      rnd_vec4(amb, 0.0f, 0.5f);
      rnd_vec4(dif, 0.0f, 1.0f);
      rnd_vec4(spe, 0.0f, 1.0f);
      rnd_vec4(dir, -1.0f, 1.0f);
      const float cutoff = chance(0.7f) ? 180.0f : rndr(5.0f, 90.0f);
      const float expo = rndr(0.0f, 20.0f);
      const float kc = rndr(0.5f, 1.5f), kl = chance(0.5f) ? 0.0f : rndr(0.0f, 0.5f),
                  kq = chance(0.5f) ? 0.0f : rndr(0.0f, 0.2f);
      L("light %d pos %.9g %.9g %.9g %.9g cutoff %.9g exp %.9g att %.9g %.9g %.9g", i, pos[0], pos[1],
        pos[2], pos[3], cutoff, expo, kc, kl, kq);
      glLightfv(li, GL_POSITION, pos);
      glLightfv(li, GL_AMBIENT, amb);
      glLightfv(li, GL_DIFFUSE, dif);
      glLightfv(li, GL_SPECULAR, spe);
      glLightfv(li, GL_SPOT_DIRECTION, dir);
      glLightf(li, GL_SPOT_CUTOFF, cutoff);
      glLightf(li, GL_SPOT_EXPONENT, expo);
      glLightf(li, GL_CONSTANT_ATTENUATION, kc);
      glLightf(li, GL_LINEAR_ATTENUATION, kl);
      glLightf(li, GL_QUADRATIC_ATTENUATION, kq);
   }
   const bool two = chance(0.4f), local = chance(0.3f);
   const bool sep = chance(mode == MODE_USUAL ? 0.15f : 0.4f);
   float ga[4];
   rnd_vec4(ga, 0.0f, 0.4f);
   L("light model two-side %d local viewer %d separate specular %d", two, local, sep);
   glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, two);
   glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local);
   glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, sep ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
   glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ga);
   for (int f = 0; f < 2; f++) {
      const GLenum face = f ? GL_BACK : GL_FRONT;
      float a[4], d[4], s[4], e[4];
      rnd_vec4(a, 0.0f, 1.0f);
      rnd_vec4(d, 0.0f, 1.0f);
      rnd_vec4(s, 0.0f, 1.0f);
      rnd_vec4(e, 0.0f, 0.3f);
      d[3] = rndf();
      const float shin = chance(0.2f) ? 0.0f : rndr(0.0f, 128.0f);
      const bool ct = chance(0.4f);
      const float rough = rndf(), metal = rndf(), f0 = rndf();
      L("material %s shininess %.9g model %s roughness %.9g metalness %.9g f0 %.9g",
        f ? "back" : "front", shin, ct ? "cook-torrance" : "blinn-phong", rough, metal, f0);
      glMaterialfv(face, GL_AMBIENT, a);
      glMaterialfv(face, GL_DIFFUSE, d);
      glMaterialfv(face, GL_SPECULAR, s);
      glMaterialfv(face, GL_EMISSION, e);
      glMaterialf(face, GL_SHININESS, shin);
      glMateriali(face, GL_REFLECTANCE_MODEL_FIXGL, ct ? GL_COOK_TORRANCE_FIXGL : GL_BLINN_PHONG_FIXGL);
      glMaterialf(face, GL_ROUGHNESS_FIXGL, rough);
      glMaterialf(face, GL_METALNESS_FIXGL, metal);
      glMaterialf(face, GL_DIELECTRIC_F0_FIXGL, f0);
   }
   const bool cm = chance(0.3f);
   static const GLenum cm_modes[] = { GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_AMBIENT,
                                      GL_SPECULAR, GL_EMISSION };
   static const GLenum cm_faces[] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
   const GLenum cmm = PICK(cm_modes), cmf = PICK(cm_faces);
   L("color material %d 0x%x 0x%x", cm, cmf, cmm);
   glColorMaterial(cmf, cmm);
   if (cm)
      glEnable(GL_COLOR_MATERIAL);
   else
      glDisable(GL_COLOR_MATERIAL);
   const bool nz = chance(0.5f);
   if (nz)
      glEnable(GL_NORMALIZE);
   else
      glDisable(GL_NORMALIZE);
}

static void set_fog(void)
{
   static const GLenum modes[] = { GL_LINEAR, GL_EXP, GL_EXP2 };
   static const GLenum dmodes[] = { GL_EYE_PLANE_ABSOLUTE_NV, GL_EYE_PLANE, GL_EYE_RADIAL_NV };
   const int mode = G.mode[GROUP_FOG];
   const bool on = mode != MODE_OFF && chance(0.8f);
   const GLenum m = PICK(modes);
   const GLenum dm = mode == MODE_USUAL ? GL_EYE_PLANE_ABSOLUTE_NV : PICK(dmodes);
   const float dens = rndr(0.0f, 3.0f), st = rndr(-1.0f, 1.0f), en = rndr(-0.5f, 3.0f);
   const bool src_depth = mode == MODE_USUAL || chance(0.8f);
   float c[4];
   rnd_color4(c);
   L("fog %d mode 0x%x density %.9g start %.9g end %.9g distance 0x%x src %s", on, m, dens, st,
     en, dm, src_depth ? "depth" : "coordinate");
   if (on)
      glEnable(GL_FOG);
   else
      glDisable(GL_FOG);
   glFogi(GL_FOG_MODE, (GLint)m);
   glFogf(GL_FOG_DENSITY, dens);
   glFogf(GL_FOG_START, st);
   glFogf(GL_FOG_END, en);
   glFogfv(GL_FOG_COLOR, c);
   glFogi(GL_FOG_DISTANCE_MODE_NV, (GLint)dm);
   glFogi(GL_FOG_COORDINATE_SOURCE, src_depth ? GL_FRAGMENT_DEPTH : GL_FOG_COORDINATE);
}

/* -- textures -- */

#define NTEX 4

static void make_texture(int i)
{
   /* the unsized formats (and RGBA8) first: the usual ones */
   static const GLint ifmts[] = { GL_RGBA, GL_RGBA, GL_RGB, GL_RGB, GL_LUMINANCE, GL_ALPHA,
                                  GL_INTENSITY, GL_LUMINANCE_ALPHA, GL_RGBA8, GL_RGB8,
                                  GL_RGBA4, GL_RGB5_A1, GL_R3_G3_B2, GL_RGB10_A2,
                                  GL_LUMINANCE16, GL_ALPHA4, GL_RGB16, GL_INTENSITY8 };
   const bool usual = G.mode[GROUP_TEX] != MODE_ANY;
   const bool two_d = chance(usual ? 0.95f : 0.7f);
   const GLenum target = two_d ? GL_TEXTURE_2D : GL_TEXTURE_1D;
   const float pot = usual ? 0.85f : 0.5f;
   int w = chance(pot) ? 1 << rnd(6) : 1 + rnd(40);
   int h = two_d ? (chance(pot) ? 1 << rnd(6) : 1 + rnd(40)) : 1;
   const GLint ifmt = ifmts[rnd(usual ? 9 : (int)(sizeof ifmts / sizeof ifmts[0]))];
   const bool mip = chance(0.6f);
   const bool incomplete = !usual && chance(0.1f);
   G.tex_2d[i] = two_d;
   L("texture %d %dD %dx%d ifmt 0x%x mipmaps %d", i + 1, two_d ? 2 : 1, w, h, ifmt, mip);
   glBindTexture(target, (GLuint)(i + 1));
   uint8_t *data = malloc((size_t)w * (size_t)h * 4);
   for (int level = 0;; level++) {
      const int n = w * h * 4;
      const int style = rnd(3);
      for (int k = 0; k < n; k++)
         data[k] = style == 0 ? (uint8_t)rnd(256) : style == 1 ? (uint8_t)(rnd(2) * 255)
                                                              : (uint8_t)((k * 37 + level * 91) & 255);
      if (two_d)
         glTexImage2D(target, level, ifmt, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
      else
         glTexImage1D(target, level, ifmt, w, 0, GL_RGBA, GL_UNSIGNED_BYTE, data);
      if (!mip || (w == 1 && h == 1) || (incomplete && level == 1))
         break;
      w = w > 1 ? w / 2 : 1;
      h = h > 1 ? h / 2 : 1;
   }
   free(data);
}

static void set_tex_params(GLenum target)
{
   static const GLenum mins[] = { GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
                                  GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                                  GL_LINEAR_MIPMAP_LINEAR };
   static const GLenum mags[] = { GL_NEAREST, GL_LINEAR };
   static const GLenum wraps[] = { GL_REPEAT, GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE,
                                   GL_CLAMP, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT,
                                   GL_MIRROR_CLAMP_EXT, GL_MIRROR_CLAMP_TO_EDGE_EXT,
                                   GL_MIRROR_CLAMP_TO_BORDER_EXT };
   const bool usual = G.mode[GROUP_TEX] != MODE_ANY;
   GLenum mi = PICK(mins), ma = PICK(mags);
   GLenum ws = wraps[rnd(usual ? 4 : 10)], wt = wraps[rnd(usual ? 4 : 10)];
   if (usual && chance(0.2f)) {
      /* the block kernels' bilinear lookups (r_tex_avx2.h
       * tex8_is_bilinear): LINEAR, no mipmap, one wrap on both axes */
      mi = ma = GL_LINEAR;
      wt = ws;
   }
   float bc[4];
   rnd_color4(bc);
   L("  params min 0x%x mag 0x%x wrap 0x%x 0x%x", mi, ma, ws, wt);
   glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)mi);
   glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)ma);
   glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)ws);
   glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)wt);
   glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, bc);
   if (!usual && chance(0.3f)) {
      const float bias = rndr(-3.0f, 3.0f), mn = rndr(-2.0f, 3.0f), mx = rndr(0.0f, 8.0f);
      const int base = rnd(3);
      L("  params lod bias %.9g min lod %.9g max lod %.9g base level %d", bias, mn, mx, base);
      glTexParameterf(target, GL_TEXTURE_LOD_BIAS, bias);
      glTexParameterf(target, GL_TEXTURE_MIN_LOD, mn);
      glTexParameterf(target, GL_TEXTURE_MAX_LOD, mx);
      glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, base);
   } else {
      glTexParameterf(target, GL_TEXTURE_LOD_BIAS, 0.0f);
      glTexParameterf(target, GL_TEXTURE_MIN_LOD, -1000.0f);
      glTexParameterf(target, GL_TEXTURE_MAX_LOD, 1000.0f);
      glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, 0);
   }
}

static GLenum rnd_source(void)
{
   static const GLenum srcs[] = { GL_TEXTURE, GL_TEXTURE, GL_PREVIOUS, GL_PREVIOUS,
                                  GL_PRIMARY_COLOR, GL_CONSTANT, GL_TEXTURE0, GL_TEXTURE1,
                                  GL_TEXTURE2, GL_ZERO, GL_ONE, GL_TEXTURE3 };
   return PICK(srcs);
}

static void set_combine(bool nv4)
{
   static const GLenum rgb_modes[] = { GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED,
                                       GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA,
                                       GL_DOT3_RGB_EXT, GL_DOT3_RGBA_EXT, GL_MODULATE_ADD_ATI,
                                       GL_MODULATE_SIGNED_ADD_ATI, GL_MODULATE_SUBTRACT_ATI };
   static const GLenum a_modes[] = { GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED,
                                     GL_INTERPOLATE, GL_SUBTRACT, GL_MODULATE_ADD_ATI,
                                     GL_MODULATE_SIGNED_ADD_ATI, GL_MODULATE_SUBTRACT_ATI };
   static const GLenum nv_modes[] = { GL_ADD, GL_ADD_SIGNED };
   static const GLenum rgb_ops[] = { GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                     GL_ONE_MINUS_SRC_ALPHA };
   static const GLenum a_ops[] = { GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA };
   const GLenum mr = nv4 ? PICK(nv_modes) : PICK(rgb_modes);
   const GLenum ma = nv4 ? PICK(nv_modes) : PICK(a_modes);
   const int sr = rnd(3), sa = rnd(3);
   L("  combine%s rgb 0x%x alpha 0x%x scale %d %d", nv4 ? "4" : "", mr, ma, 1 << sr, 1 << sa);
   glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)mr);
   glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)ma);
   glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, (float)(1 << sr));
   glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, (float)(1 << sa));
   for (int i = 0; i < (nv4 ? 4 : 3); i++) {
      const GLenum s = rnd_source(), sa2 = rnd_source(), o = PICK(rgb_ops), oa = PICK(a_ops);
      L("  arg %d rgb 0x%x 0x%x alpha 0x%x 0x%x", i, s, o, sa2, oa);
      const GLenum srgb = i < 3 ? GL_SOURCE0_RGB + (GLenum)i : GL_SOURCE3_RGB_NV;
      const GLenum salpha = i < 3 ? GL_SOURCE0_ALPHA + (GLenum)i : GL_SOURCE3_ALPHA_NV;
      const GLenum orgb = i < 3 ? GL_OPERAND0_RGB + (GLenum)i : GL_OPERAND3_RGB_NV;
      const GLenum oalpha = i < 3 ? GL_OPERAND0_ALPHA + (GLenum)i : GL_OPERAND3_ALPHA_NV;
      glTexEnvi(GL_TEXTURE_ENV, srgb, (GLint)s);
      glTexEnvi(GL_TEXTURE_ENV, salpha, (GLint)sa2);
      glTexEnvi(GL_TEXTURE_ENV, orgb, (GLint)o);
      glTexEnvi(GL_TEXTURE_ENV, oalpha, (GLint)oa);
   }
}

static void set_texturing(void)
{
   static const GLenum envs[] = { GL_MODULATE, GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND,
                                  GL_ADD, GL_COMBINE, GL_COMBINE, GL_COMBINE4_NV };
   const int mode = G.mode[GROUP_TEX];
   const int n = mode == MODE_OFF || chance(0.1f) ? 0 : mode == MODE_USUAL ? (chance(0.8f) ? 1 : 2)
               : chance(0.5f) ? 1 : 1 + rnd(4);
   G.nunits = n;
   L("texture units %d", n);
   for (int u = 0; u < 4; u++) {
      glActiveTexture(GL_TEXTURE0 + (GLenum)u);
      glDisable(GL_TEXTURE_1D);
      glDisable(GL_TEXTURE_2D);
      glDisable(GL_TEXTURE_GEN_S);
      glDisable(GL_TEXTURE_GEN_T);
      if (u >= n)
         continue;
      const int t = rnd(NTEX);
      const GLenum target = G.tex_2d[t] ? GL_TEXTURE_2D : GL_TEXTURE_1D;
      glBindTexture(GL_TEXTURE_1D, 0);
      glBindTexture(GL_TEXTURE_2D, 0);
      glBindTexture(target, (GLuint)(t + 1));
      glEnable(target);
      static const GLenum usual_envs[] = { GL_MODULATE, GL_MODULATE, GL_REPLACE, GL_DECAL };
      const GLenum env = mode == MODE_USUAL ? PICK(usual_envs) : PICK(envs);
      float ec[4];
      rnd_color4(ec);
      L(" unit %d texture %d env 0x%x colour %.9g %.9g %.9g %.9g", u, t + 1, env, ec[0], ec[1],
        ec[2], ec[3]);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env);
      glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
      if (env == GL_COMBINE || env == GL_COMBINE4_NV)
         set_combine(env == GL_COMBINE4_NV);
      if (chance(0.7f))
         set_tex_params(target);
      if (mode == MODE_ANY && chance(0.1f)) {
         const float p[4] = { rndr(-0.2f, 0.2f), rndr(-0.2f, 0.2f), 0.0f, rndf() };
         L(" unit %d texgen object linear %.9g %.9g 0 %.9g", u, p[0], p[1], p[3]);
         glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
         glTexGenfv(GL_S, GL_OBJECT_PLANE, p);
         glEnable(GL_TEXTURE_GEN_S);
      }
      glMatrixMode(GL_TEXTURE);
      glLoadIdentity();
      if (mode == MODE_ANY && chance(0.15f)) {
         const float s = rndr(0.25f, 4.0f);
         L(" unit %d texture matrix scale %.9g", u, s);
         glScalef(s, s, 1.0f);
      }
      glMatrixMode(GL_MODELVIEW);
   }
   glActiveTexture(GL_TEXTURE0);
}

/* -- rasterization -- */

static void set_polygon(void)
{
   static const GLenum modes[] = { GL_FILL, GL_FILL, GL_FILL, GL_FILL, GL_LINE, GL_POINT };
   static const GLenum cull[] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
   const int mode = G.mode[GROUP_POLY];
   const GLenum mf = mode == MODE_ANY ? PICK(modes) : GL_FILL;
   const GLenum mb = chance(0.8f) ? mf : PICK(modes);
   const bool cu = chance(0.2f);
   const GLenum cf = PICK(cull), ff = chance(0.5f) ? GL_CCW : GL_CW;
   const bool of = mode != MODE_OFF && chance(0.3f);
   const bool ol = mode == MODE_ANY && chance(0.1f), op = mode == MODE_ANY && chance(0.1f);
   const float factor = rndr(-2.0f, 4.0f), units = rndr(-4.0f, 8.0f);
   const bool st = mode == MODE_ANY && chance(0.3f);
   L("polygon mode 0x%x 0x%x cull %d 0x%x front 0x%x offset %d %d %d %.9g %.9g stipple %d", mf, mb,
     cu, cf, ff, of, ol, op, factor, units, st);
   glPolygonMode(GL_FRONT, mf);
   glPolygonMode(GL_BACK, mb);
   G.filled = mf == GL_FILL && mb == GL_FILL;
   if (cu)
      glEnable(GL_CULL_FACE);
   else
      glDisable(GL_CULL_FACE);
   glCullFace(cf);
   glFrontFace(ff);
   if (of) glEnable(GL_POLYGON_OFFSET_FILL); else glDisable(GL_POLYGON_OFFSET_FILL);
   if (ol) glEnable(GL_POLYGON_OFFSET_LINE); else glDisable(GL_POLYGON_OFFSET_LINE);
   if (op) glEnable(GL_POLYGON_OFFSET_POINT); else glDisable(GL_POLYGON_OFFSET_POINT);
   glPolygonOffset(factor, units);
   const bool clip = mode == MODE_ANY && chance(0.2f);
   if (clip) {
      const double eq[4] = { rndr(-1.0f, 1.0f), rndr(-1.0f, 1.0f), rndr(-0.2f, 0.2f), rndr(-0.5f, 0.5f) };
      L("clip plane 0: %.17g %.17g %.17g %.17g", eq[0], eq[1], eq[2], eq[3]);
      glClipPlane(GL_CLIP_PLANE0, eq);
      glEnable(GL_CLIP_PLANE0);
   } else {
      glDisable(GL_CLIP_PLANE0);
   }
   if (st) {
      GLubyte pat[128];
      for (int i = 0; i < 128; i++)
         pat[i] = (GLubyte)rnd(256);
      glPolygonStipple(pat);
      glEnable(GL_POLYGON_STIPPLE);
   } else {
      glDisable(GL_POLYGON_STIPPLE);
   }
}

static void set_lines_points(void)
{
   /* widths 1 to 8 and sizes 1 to 16, whole or fractional (and a few
    * below 1) */
   const int lr = rnd(10), pr = rnd(10);
   const float lw = lr < 3 ? 1.0f : lr < 6 ? (float)(1 + rnd(8)) : lr < 9 ? rndr(1.0f, 8.0f)
                                                                            : rndr(0.5f, 1.0f);
   /* line stipple: the draw stipple stage's sub-lines go to the line
    * kernels (factors up to 256 now and then: long dashes) */
   const bool ls = chance(0.15f), lst = chance(0.2f);
   const int factor = chance(0.2f) ? 1 + rnd(256) : 1 + rnd(3);
   const unsigned pattern = (unsigned)rnd(65536);
   const float ps = pr < 2 ? 1.0f : pr < 5 ? (float)(1 + rnd(16)) : pr < 9 ? rndr(1.0f, 16.0f)
                                                                        : rndr(0.2f, 1.0f);
   const bool psm = chance(0.15f);
   G.line_smooth = ls;
   G.point_smooth = psm;
   G.point_size = ps;
   L("line width %.9g smooth %d stipple %d %d 0x%x point size %.9g smooth %d", lw, ls, lst, factor,
     pattern, ps, psm);
   glLineWidth(lw);
   if (ls) glEnable(GL_LINE_SMOOTH); else glDisable(GL_LINE_SMOOTH);
   if (lst) glEnable(GL_LINE_STIPPLE); else glDisable(GL_LINE_STIPPLE);
   glLineStipple(factor, (GLushort)pattern);
   glPointSize(ps);
   if (psm) glEnable(GL_POINT_SMOOTH); else glDisable(GL_POINT_SMOOTH);
   /* point sprites (r_point.c sprite: every size through the kernels,
    * smoothing ignored), the coordinates of random units replaced, either
    * origin */
   const bool spr = chance(0.3f), lower = chance(0.5f);
   const int repl = rnd(8);
   G.point_sprite = spr;
   L("point sprite %d replace 0x%x lower left %d", spr, repl, lower);
   if (spr) glEnable(GL_POINT_SPRITE); else glDisable(GL_POINT_SPRITE);
   glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, lower ? GL_LOWER_LEFT : GL_UPPER_LEFT);
   GLint active = GL_TEXTURE0;
   glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
   for (int u = 0; u < 3; u++) {
      glActiveTexture(GL_TEXTURE0 + (GLenum)u);
      glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, (repl >> u) & 1 ? GL_TRUE : GL_FALSE);
   }
   glActiveTexture((GLenum)active);
}

/* this case's points go to a kernel: non-smooth ones of 3 pixels or more
 * (r_point.c), or sprites of any size (smoothing is off for them) */
static bool points_to_kernel(void)
{
   return G.point_sprite || (!G.point_smooth && G.point_size >= 3.0f);
}

static void set_projection(void)
{
   G.proj = rnd(3);
   L("projection %s", G.proj == 0 ? "clip coordinates" : G.proj == 1 ? "pixels" : "frustum");
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   if (G.proj == 1)
      glOrtho(0.0, G.cfg.w, 0.0, G.cfg.h, -1.0, 1.0);
   else if (G.proj == 2)
      glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   int vx = 0, vy = 0, vw = G.cfg.w, vh = G.cfg.h;
   if (chance(0.15f)) {
      vx = rnd(G.cfg.w) - G.cfg.w / 2;
      vy = rnd(G.cfg.h) - G.cfg.h / 2;
      vw = 1 + rnd(2 * G.cfg.w);
      vh = 1 + rnd(2 * G.cfg.h);
   }
   L("viewport %d %d %d %d", vx, vy, vw, vh);
   glViewport(vx, vy, vw, vh);
}

/* -- primitives -- */

/* a primitive's centre and size, in the projection's units */
struct shape {
   float cx, cy, cz, r;
};

static float pix_snap(float v)
{
   switch (rnd(5)) {
   case 0:  return floorf(v);                     /* pixel corner */
   case 1:  return floorf(v) + 0.5f;              /* pixel centre */
   case 2:  return floorf(v * 256.0f) / 256.0f;   /* the subpixel grid */
   default: return v;
   }
}

static struct shape rnd_shape(void)
{
   struct shape s;
   const int size = rnd(100);
   /* radius in pixels: tiny, small, medium, big, huge (past the block
    * kernels' 32-bit coverage and the exact edge functions) */
   float rp = size < 25 ? rndr(0.2f, 2.5f) : size < 60 ? rndr(2.0f, 10.0f)
            : size < 88 ? rndr(8.0f, 40.0f) : size < 98 ? rndr(40.0f, 200.0f)
            : chance(0.5f) ? rndr(1000.0f, 8000.0f) : rndr(8000.0f, 60000.0f);
   const float wp = (float)G.cfg.w, hp = (float)G.cfg.h;
   float px = rndr(-0.15f * wp, 1.15f * wp), py = rndr(-0.15f * hp, 1.15f * hp);
   if (G.proj == 1) {
      s.cx = px;
      s.cy = py;
      s.cz = rndr(-1.0f, 1.0f);
      s.r = rp;
   } else {
      s.cx = 2.0f * px / wp - 1.0f;
      s.cy = 2.0f * py / hp - 1.0f;
      s.cz = rndr(-1.0f, 1.0f);
      s.r = 2.0f * rp / (wp < hp ? wp : hp);
   }
   return s;
}

static void send_vertex_attribs(void)
{
   float c[4];
   rnd_color4(c);
   glColor4fv(c);
   if (chance(0.9f)) {
      float n[3] = { rndr(-1.0f, 1.0f), rndr(-1.0f, 1.0f), rndr(-1.0f, 1.0f) };
      glNormal3fv(n);
   }
   for (int u = 0; u < G.nunits; u++) {
      const float sc = chance(0.3f) ? 8.0f : 1.5f;
      float q = chance(G.mode[GROUP_TEX] == MODE_ANY ? 0.7f : 0.95f) ? 1.0f : rndr(0.2f, 2.0f);
      if (G.mode[GROUP_TEX] == MODE_ANY && chance(0.03f))
         q = chance(0.5f) ? 0.0f : -rndr(0.1f, 1.0f);
      glMultiTexCoord4f(GL_TEXTURE0 + (GLenum)u, rndr(-sc, sc), rndr(-sc, sc), rndr(-1.0f, 1.0f), q);
   }
}

static void place_vertex(float v[4], float x, float y, float z, bool snap);

/* a vertex near the shape, or (degenerate) the last one again or the
 * midpoint of the last two; logged */
static void emit_vertex(const struct shape *s, int degenerate)
{
   send_vertex_attribs();
   float v[4];
   if (degenerate == 1) {
      memcpy(v, G.last[1], sizeof v);
   } else if (degenerate == 2) {
      for (int i = 0; i < 4; i++)
         v[i] = 0.5f * (G.last[0][i] + G.last[1][i]);
   } else {
      float x = s->cx + rndr(-s->r, s->r), y = s->cy + rndr(-s->r, s->r);
      const float z = s->cz + rndr(-0.3f, 0.3f);
      place_vertex(v, x, y, z, true);
   }
   memcpy(G.last[0], G.last[1], sizeof v);
   memcpy(G.last[1], v, sizeof v);
   L("    vertex %.9g %.9g %.9g %.9g", v[0], v[1], v[2], v[3]);
   glVertex4fv(v);
}

/* the vertex at (x, y) (the projection's units) and depth z: snapped to
 * the pixel grid in some way (pix_snap) under the pixel projection when
 * `snap`, at a random eye depth under the frustum (the same NDC
 * position), and with a random w (a few near 0) in clip coordinates */
static void place_vertex(float v[4], float x, float y, float z, bool snap)
{
   if (G.proj == 1) {
      v[0] = snap ? pix_snap(x) : x;
      v[1] = snap ? pix_snap(y) : y;
      v[2] = G.flat_z ? G.flat_zv : z;
      v[3] = 1.0f;
   } else if (G.proj == 2) {
      /* eye space: depth 0.5 .. 12 (the near plane at 1), the NDC
       * position kept */
      const float d = chance(0.1f) ? rndr(0.5f, 1.2f) : rndr(1.0f, 12.0f);
      v[0] = x * d;
      v[1] = y * d;
      v[2] = -d;
      v[3] = 1.0f;
   } else {
      float w = chance(0.7f) ? 1.0f : rndr(0.2f, 3.0f);
      if (chance(0.03f))
         w = rndr(-0.01f, 0.01f);   /* near 0 (and behind) */
      v[0] = x * w;
      v[1] = y * w;
      v[2] = z * w;
      v[3] = w;
   }
}

static void draw_points(void);

static void draw_polys(void)
{
   static const GLenum prims[] = { GL_TRIANGLES, GL_TRIANGLES, GL_TRIANGLES, GL_TRIANGLE_STRIP,
                                   GL_TRIANGLE_FAN, GL_QUADS, GL_POLYGON };
   const GLenum prim = PICK(prims);
   int nv = 0, ntri = 0;
   switch (prim) {
   case GL_TRIANGLES: ntri = 1 + rnd(4); nv = 3 * ntri; break;
   case GL_QUADS:     ntri = 2 * (1 + rnd(2)); nv = 2 * ntri; break;
   default:           nv = 3 + rnd(4); ntri = nv - 2; break;
   }
   const struct shape s = rnd_shape();
   const bool degenerate = chance(0.05f);
   static const float flat_zs[] = { -1.0f, 0.0f, 0.5f, 1.0f, 0.25f };
   G.flat_z = chance(0.2f);
   G.flat_zv = PICK(flat_zs);
   L("  draw 0x%x %d vertices%s (call %ld)", prim, nv, degenerate ? " degenerate" : "", g_calls);
   glBegin(prim);
   for (int i = 0; i < nv; i++) {
      emit_vertex(&s, degenerate && i % 3 == 2 ? 1 + rnd(2) : 0);
      memcpy(G.rep_v[i], G.last[1], sizeof G.rep_v[i]);
   }
   glEnd();
   G.flat_z = false;
   G.rep_prim = prim;
   G.rep_n = nv;
   G.rep_tris = ntri;
   if (g_count_on)
      g_count.tris += (uint64_t)ntri;
   if (G.filled)
      G.case_tris = true;
}

/* the last polygon draw again, new colours and coordinates */
static void draw_repeat(void)
{
   if (!G.rep_n) {
      draw_points();
      return;
   }
   L("  draw 0x%x %d vertices again (call %ld)", G.rep_prim, G.rep_n, g_calls);
   glBegin(G.rep_prim);
   for (int i = 0; i < G.rep_n; i++) {
      send_vertex_attribs();
      L("    vertex %.9g %.9g %.9g %.9g", G.rep_v[i][0], G.rep_v[i][1], G.rep_v[i][2], G.rep_v[i][3]);
      glVertex4fv(G.rep_v[i]);
   }
   glEnd();
   if (g_count_on)
      g_count.tris += (uint64_t)G.rep_tris;
   if (G.filled)
      G.case_tris = true;
}

static void draw_rect(void)
{
   const struct shape s = rnd_shape();
   send_vertex_attribs();
   const float x0 = s.cx - s.r * rndf(), y0 = s.cy - s.r * rndf();
   const float x1 = s.cx + s.r * rndf(), y1 = s.cy + s.r * rndf();
   L("  rect %.9g %.9g %.9g %.9g (call %ld)", x0, y0, x1, y1, g_calls);
   glRectf(x0, y0, x1, y1);
   if (g_count_on)
      g_count.tris += 2;
   if (G.filled)
      G.case_tris = true;
}

/* a vertex at the centre of pixel (i, j) of the buffer (in the
 * projection's units: exactly under the pixel projection with the whole
 * buffer's viewport), the shape's depth; logged */
static void emit_pixel_centre(const struct shape *s, int i, int j)
{
   send_vertex_attribs();
   const float px = (float)i + 0.5f, py = (float)j + 0.5f;
   float x = px, y = py;
   if (G.proj != 1) {
      x = 2.0f * px / (float)G.cfg.w - 1.0f;
      y = 2.0f * py / (float)G.cfg.h - 1.0f;
   }
   float v[4];
   place_vertex(v, x, y, s->cz + rndr(-0.3f, 0.3f), false);
   memcpy(G.last[0], G.last[1], sizeof v);
   memcpy(G.last[1], v, sizeof v);
   L("    vertex %.9g %.9g %.9g %.9g (pixel centre %d %d)", v[0], v[1], v[2], v[3], i, j);
   glVertex4fv(v);
}

static void draw_lines(void)
{
   static const GLenum prims[] = { GL_LINES, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP };
   const GLenum prim = PICK(prims);
   const int nv = prim == GL_LINES ? 2 * (1 + rnd(4)) : 2 + rnd(4);
   const int nl = prim == GL_LINES ? nv / 2 : prim == GL_LINE_STRIP ? nv - 1 : nv;
   const struct shape s = rnd_shape();
   /* half of them from pixel centre to pixel centre: horizontal,
    * vertical, diagonal, or any direction, short to long */
   const bool centres = chance(0.5f);
   L("  draw 0x%x %d vertices%s (call %ld)", prim, nv, centres ? " on pixel centres" : "",
     g_calls);
   glBegin(prim);
   int i = rnd(G.cfg.w + 8) - 4, j = rnd(G.cfg.h + 8) - 4;
   for (int k = 0; k < nv; k++) {
      if (!centres) {
         emit_vertex(&s, 0);
         continue;
      }
      if (prim != GL_LINES || k % 2 == 1) {
         const int len = chance(0.8f) ? 1 + rnd(24) : 1 + rnd(120);
         const int sx = chance(0.5f) ? 1 : -1, sy = chance(0.5f) ? 1 : -1;
         switch (rnd(5)) {
         case 0:  i += sx * len; break;
         case 1:  j += sy * len; break;
         case 2:  i += sx * len; j += sy * len; break;
         default: i += sx * rnd(len + 1); j += sy * rnd(len + 1); break;
         }
      } else {
         i = rnd(G.cfg.w + 8) - 4;
         j = rnd(G.cfg.h + 8) - 4;
      }
      emit_pixel_centre(&s, i, j);
   }
   glEnd();
   if (g_count_on)
      g_count.lines += (uint64_t)nl;
   if (!G.line_smooth)
      G.case_lines = true;
}

static void draw_points(void)
{
   const int nv = 1 + rnd(8);
   L("  draw points %d (call %ld)", nv, g_calls);
   glBegin(GL_POINTS);
   for (int i = 0; i < nv; i++) {
      const struct shape s = rnd_shape();
      emit_vertex(&s, 0);
   }
   glEnd();
   if (g_count_on)
      g_count.points += (uint64_t)nv;
   if (points_to_kernel())
      G.case_points = true;
}

static void draw_arrays(void)
{
   /* the same kinds through vertex arrays */
   static const GLenum prims[] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_LINES, GL_POINTS };
   const GLenum prim = PICK(prims);
   const int nv = prim == GL_TRIANGLES ? 3 * (1 + rnd(4)) : prim == GL_LINES ? 2 * (1 + rnd(4))
                                                                            : 3 + rnd(6);
   float pos[24][4], col[24][4];
   const struct shape s = rnd_shape();
   for (int i = 0; i < nv; i++) {
      const float w = G.proj == 0 && chance(0.3f) ? rndr(0.3f, 2.0f) : 1.0f;
      pos[i][0] = (s.cx + rndr(-s.r, s.r)) * w;
      pos[i][1] = (s.cy + rndr(-s.r, s.r)) * w;
      pos[i][2] = G.proj == 2 ? -rndr(1.0f, 9.0f) : rndr(-1.0f, 1.0f) * w;
      pos[i][3] = w;
      if (G.proj == 2) {
         pos[i][0] *= -pos[i][2];
         pos[i][1] *= -pos[i][2];
      }
      rnd_color4(col[i]);
   }
   L("  draw arrays 0x%x %d vertices (call %ld)", prim, nv, g_calls);
   for (int i = 0; i < nv; i++)
      L("    vertex %.9g %.9g %.9g %.9g", pos[i][0], pos[i][1], pos[i][2], pos[i][3]);
   glEnableClientState(GL_VERTEX_ARRAY);
   glEnableClientState(GL_COLOR_ARRAY);
   glVertexPointer(4, GL_FLOAT, 0, pos);
   glColorPointer(4, GL_FLOAT, 0, col);
   glDrawArrays(prim, 0, nv);
   glDisableClientState(GL_VERTEX_ARRAY);
   glDisableClientState(GL_COLOR_ARRAY);
   if (g_count_on) {
      if (prim == GL_TRIANGLES)
         g_count.tris += (uint64_t)nv / 3;
      else if (prim == GL_TRIANGLE_STRIP)
         g_count.tris += (uint64_t)nv - 2;
      else if (prim == GL_LINES)
         g_count.lines += (uint64_t)nv / 2;
      else
         g_count.points += (uint64_t)nv;
   }
   if (G.filled && (prim == GL_TRIANGLES || prim == GL_TRIANGLE_STRIP))
      G.case_tris = true;
   if (prim == GL_LINES && !G.line_smooth)
      G.case_lines = true;
   if (prim == GL_POINTS && points_to_kernel())
      G.case_points = true;
}

static void draw_pixels(void)
{
   const int x = rnd(G.cfg.w + 8) - 6, y = rnd(G.cfg.h + 8) - 6;
   const int w = 1 + rnd(9), h = 1 + rnd(9);
   float c[4];
   rnd_color4(c);
   glColor4fv(c);
   glWindowPos2i(x, y);
   const float zoom = chance(0.8f) ? 1.0f : 2.0f;
   glPixelZoom(zoom, zoom);
   int kind = rnd(5);
   if (kind == 2 && !G.cfg.depth)
      kind = 0;
   if (kind == 3 && !G.cfg.stencil)
      kind = 1;
   static const GLenum formats[] = { GL_RGBA, GL_RGBA, GL_BGRA, GL_ABGR_EXT, GL_RGB, GL_LUMINANCE,
                                     GL_LUMINANCE_ALPHA };
   const GLenum format = PICK(formats);
   L("  pixels kind %d at %d %d size %dx%d zoom %g format 0x%x (call %ld)", kind, x, y, w, h, zoom,
     format, g_calls);
   if (kind == 0) {
      GLubyte img[9 * 9 * 4];
      for (int i = 0; i < w * h * 4; i++)
         img[i] = (GLubyte)rnd(256);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glDrawPixels(w, h, format, GL_UNSIGNED_BYTE, img);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
   } else if (kind == 4) {
      const int sx = rnd(G.cfg.w), sy = rnd(G.cfg.h);
      L("  copy pixels from %d %d", sx, sy);
      glCopyPixels(sx, sy, w, h, GL_COLOR);
   } else if (kind == 1) {
      GLubyte bm[9 * 2];
      for (int i = 0; i < 18; i++)
         bm[i] = (GLubyte)rnd(256);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glBitmap(w, h, 0.0f, 0.0f, (float)rnd(5), 0.0f, bm);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
   } else if (kind == 2) {
      float d[81];
      for (int i = 0; i < w * h; i++)
         d[i] = rndr(-0.1f, 1.1f);
      glDrawPixels(w, h, GL_DEPTH_COMPONENT, GL_FLOAT, d);
   } else {
      GLubyte st[81];
      for (int i = 0; i < w * h; i++)
         st[i] = (GLubyte)rnd(256);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);   /* rows of w bytes */
      glDrawPixels(w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
   }
   glPixelZoom(1.0f, 1.0f);
   if (g_count_on)
      g_count.pixels++;
}

/* -- a batch -- */

static void record_kind(const struct r_state *rs, int kind)
{
   struct state_key k;
   make_key(rs, kind, &k);
   const uint64_t h = key_hash(&k);
   set_add(&g_keys, h);
   const any_kernel kern = kernel_of(rs, kind);
   if (!kern) {
      set_add(&g_fallback, h);
      return;
   }
   const int ki = kernel_index(kern);
   if (set_add(&g_combos, mix64(h ^ ((uint64_t)(ki + 1) << 32)) | 1))
      g_kind_combos[kind]++;
}

static void record_case(void)
{
   const struct r_state *rs = &fgl_get_current()->_Raster;
   const bool flat = (rs->flat_mask >> R_ATTR_COLOR0) & 1;
   if (G.case_tris)
      record_kind(rs, flat ? KIND_TRI_FLAT : KIND_TRI_SMOOTH);
   if (G.case_lines)
      record_kind(rs, flat ? KIND_LINE_FLAT : KIND_LINE_SMOOTH);
   if (G.case_points)
      record_kind(rs, KIND_POINT);
}

/* the occlusion queries' results of a batch, [fast] */
static GLuint g_queries[2][16];
static int g_nqueries[2];
/* what glReadPixels read in the middle of the batch (FNV-1a), per side */
static uint64_t g_reads[2];

static void hash_bytes(uint64_t *h, const void *p, size_t n)
{
   const uint8_t *b = p;
   for (size_t i = 0; i < n; i++)
      *h = (*h ^ b[i]) * 0x100000001b3ull;
}

/* In the middle of a frame, where blocks still hold lazy clears and
 * others were drawn: a clear of some of the buffers (whole or under the
 * scissor and masks: lazy, or drawn as a quad), or a glReadPixels of a
 * random rectangle of colour, depth or stencil. */
static void mid_frame(bool fast)
{
   if (chance(0.5f)) {
      static const GLbitfield masks[] = {
         GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT, GL_STENCIL_BUFFER_BIT,
         GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
         GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
         GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
      };
      const GLbitfield m = PICK(masks);
      float cc[4];
      rnd_color4(cc);
      const double cd = rndf();
      const int cs = rnd(256);
      L("  mid-frame clear 0x%x colour %.9g %.9g %.9g %.9g depth %.17g stencil %d (call %ld)", m,
        cc[0], cc[1], cc[2], cc[3], cd, cs, g_calls);
      glClearColor(cc[0], cc[1], cc[2], cc[3]);
      glClearDepth(cd);
      glClearStencil(cs);
      glClear(m);
      return;
   }
   const int x = rnd(G.cfg.w), y = rnd(G.cfg.h);
   const int w = 1 + rnd(G.cfg.w - x), h = 1 + rnd(G.cfg.h - y);
   static const GLenum kinds[] = { GL_RGBA, GL_RGBA, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX };
   GLenum kind = PICK(kinds);
   if ((kind == GL_DEPTH_COMPONENT && !G.cfg.depth) || (kind == GL_STENCIL_INDEX && !G.cfg.stencil))
      kind = GL_RGBA;
   L("  mid-frame glReadPixels 0x%x %d %d %dx%d (call %ld)", kind, x, y, w, h, g_calls);
   static uint32_t px[96 * 64];
   memset(px, 0, sizeof px);
   glPixelStorei(GL_PACK_ALIGNMENT, 4);
   glReadPixels(x, y, w, h, kind, kind == GL_RGBA ? GL_UNSIGNED_BYTE : GL_UNSIGNED_INT, px);
   hash_bytes(&g_reads[fast], px, (size_t)w * (size_t)h * 4);
}

static void gen_batch(uint64_t bseed, bool fast)
{
   memset(&G, 0, sizeof G);
   G.cfg = pick_config(bseed);
   G.filled = true;
   rng_state = bseed;
   /* how many groups are on: none (the plainest states), one alone, a
    * few, each independently, or all of them anything */
   static const int active[] = { 0, 0, 1, 1, 2, 3, -1, -2 };
   const int k = PICK(active);
   for (int g = 0; g < GROUP_COUNT; g++) {
      const int r = rnd(20);
      G.mode[g] = k == -2 ? MODE_ANY : k >= 0 ? MODE_OFF
                : r < 8 ? MODE_OFF : r < 15 ? MODE_USUAL : MODE_ANY;
   }
   for (int i = 0; i < k; i++)
      G.mode[rnd(GROUP_COUNT)] = chance(0.6f) ? MODE_USUAL : MODE_ANY;
   L("groups (0 off, 1 usual, 2 any): stencil %d alpha %d blend %d mask %d fog %d tex %d light %d "
     "poly %d", G.mode[0], G.mode[1], G.mode[2], G.mode[3], G.mode[4], G.mode[5], G.mode[6],
     G.mode[7]);
   g_calls = 0;
   g_limit_case = -1;
   g_log_stopped = false;
   g_count_on = fast;

   /* textures */
   for (int i = 0; i < NTEX; i++) {
      make_texture(i);
      set_tex_params(G.tex_2d[i] ? GL_TEXTURE_2D : GL_TEXTURE_1D);
   }
   glBindTexture(GL_TEXTURE_1D, 0);
   glBindTexture(GL_TEXTURE_2D, 0);

   /* the clear */
   float cc[4];
   rnd_color4(cc);
   const double cd = chance(0.6f) ? 1.0 : rndf();
   const int cs = rnd(256);
   L("clear colour %.9g %.9g %.9g %.9g depth %.17g stencil %d", cc[0], cc[1], cc[2], cc[3], cd, cs);
   glClearColor(cc[0], cc[1], cc[2], cc[3]);
   glClearDepth(cd);
   glClearStencil(cs);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

   const int ncases = 4 + rnd(6);
   g_nqueries[fast] = 0;
   g_reads[fast] = 0xcbf29ce484222325ull;
   for (int c = 0; c < ncases; c++) {
      G.case_index = c;
      G.case_tris = G.case_lines = G.case_points = false;
      L("case %d:", c);
      /* a random subset of the state, the first case all of it */
      const float p = c == 0 ? 1.0f : 0.35f;
      if (chance(p)) set_depth();
      if (chance(p)) set_stencil();
      if (chance(p)) set_alpha();
      if (chance(p)) set_blend();
      if (chance(p)) set_logic_mask();
      if (chance(p * 0.5f)) set_scissor();
      if (chance(p)) set_shade_model();
      if (chance(p)) set_lighting();
      if (chance(p)) set_fog();
      if (chance(p)) set_texturing();
      if (chance(p)) set_polygon();
      if (chance(p)) set_lines_points();
      if (chance(p)) set_projection();
      if (chance(0.03f) && draw_allowed()) {
         L("  clear depth and stencil (call %ld)", g_calls - 1);
         glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
      }
      /* about half the cases draw inside an occlusion query: the samples
       * that pass, counted by the kernels (r_state.samples), must be the
       * same in both contexts */
      const bool query = ((bseed >> (c % 48)) ^ (uint64_t)c) & 1;   /* (not from the
                                                                   * batch's random stream) */
      if (query) {
         L("  glBeginQuery(GL_SAMPLES_PASSED, %d)", c + 1);
         glBeginQuery(GL_SAMPLES_PASSED, (GLuint)c + 1);
      }
      const int nprims = 2 + rnd(14);
      for (int i = 0; i < nprims; i++) {
         if (chance(0.04f) && draw_allowed())
            mid_frame(fast);
         const int what = rnd(100);
         if (!draw_allowed())
            break;
         if (what < 45)
            draw_polys();
         else if (what < 55)
            draw_repeat();
         else if (what < 60)
            draw_rect();
         else if (what < 75)
            draw_lines();
         else if (what < 88)
            draw_points();
         else if (what < 98)
            draw_arrays();
         else
            draw_pixels();
      }
      if (query) {
         glEndQuery(GL_SAMPLES_PASSED);
         GLuint n = 0;
         glGetQueryObjectuiv((GLuint)c + 1, GL_QUERY_RESULT, &n);
         g_queries[fast][g_nqueries[fast]++] = n;
         if (g_count_on) {
            g_count.queries++;
            g_count.samples += n;
         }
      }
      fgl_flush_vertices(fgl_get_current());
      if (fast && g_record)
         record_case();
      const GLenum err = glGetError();
      if (g_count_on) {
         g_count.cases++;
         if (err != GL_NO_ERROR) {
            g_count.gl_errors++;
            L("  (GL error 0x%x)", err);
         }
      }
   }
   glFinish();
}

/* ---- comparison ---------------------------------------------------------- */

struct diff {
   const char *buffer;
   int x, y;           /* GL window coordinates (y up) */
   uint32_t expected, got;
};

static bool compare_buffers(const struct config *c, const struct side *fast,
                            const struct side *ref, struct diff *d)
{
   /* the buffers' memory: a tile that still holds a lazy clear (scene.c)
    * has it written first, as any reader inside the library has */
   fgl_lazy_resolve(fast->gl->DrawBuffer, FGL_LAZY_COLOR | FGL_LAZY_ZS);
   fgl_lazy_resolve(ref->gl->DrawBuffer, FGL_LAZY_COLOR | FGL_LAZY_ZS);
   const struct fgl_framebuffer *fa = fast->gl->DrawBuffer, *fb = ref->gl->DrawBuffer;
   const size_t n = (size_t)c->w * (size_t)c->h;
   const int zbytes = c->depth == 16 ? 2 : c->depth == 24 ? 4 : 0;
   const struct {
      const char *name;
      const uint8_t *a, *b;
      int bpp;
   } bufs[] = {
      { "colour", fa->Color, fb->Color, 4 },
      { c->stencil ? "depth/stencil" : "depth", fa->Depth, fb->Depth, zbytes },
      { "stencil", fa->Stencil, fb->Stencil, 1 },
   };
   for (int i = 0; i < 3; i++) {
      if (!bufs[i].a || !bufs[i].b || !bufs[i].bpp)
         continue;
      if (!memcmp(bufs[i].a, bufs[i].b, n * (size_t)bufs[i].bpp))
         continue;
      for (size_t p = 0; p < n; p++) {
         const int bpp = bufs[i].bpp;
         if (!memcmp(bufs[i].a + p * (size_t)bpp, bufs[i].b + p * (size_t)bpp, (size_t)bpp))
            continue;
         d->buffer = bufs[i].name;
         d->x = (int)(p % (size_t)c->w);
         d->y = c->h - 1 - (int)(p / (size_t)c->w);
         d->expected = d->got = 0;
         memcpy(&d->expected, bufs[i].b + p * (size_t)bpp, (size_t)bpp);
         memcpy(&d->got, bufs[i].a + p * (size_t)bpp, (size_t)bpp);
         return false;
      }
   }
   return true;
}

static long g_perturb = -1;

/* A copy of a context's raster state with its objects, which outlives
 * the context (for the failure report). */
struct rs_snapshot {
   struct r_state rs;
   struct r_fb_state fb;
   struct r_rast_state rast;
   struct r_dsa_state dsa;
   struct r_blend_state blend;
   struct r_fs_state fs;
   struct r_tex_unit tex[R_MAX_TEX_UNITS];
   struct m_shade_env shade_env;
};

static void snapshot(struct rs_snapshot *s, const struct r_state *rs)
{
   s->rs = *rs;
   s->fb = *rs->fb;
   s->rast = *rs->rast;
   s->dsa = *rs->dsa;
   s->blend = *rs->blend;
   s->fs = *rs->fs;
   s->rs.fb = &s->fb;
   s->rs.rast = &s->rast;
   s->rs.dsa = &s->dsa;
   s->rs.blend = &s->blend;
   s->rs.fs = &s->fs;
   for (int u = 0; u < R_MAX_TEX_UNITS; u++) {
      if (rs->tex[u]) {
         s->tex[u] = *rs->tex[u];
         s->rs.tex[u] = &s->tex[u];
      }
   }
   if (rs->shade_env) {
      s->shade_env = *rs->shade_env;
      s->rs.shade_env = &s->shade_env;
   }
}

/* Draws batch `b` (its seed bseed) into a fresh pair of contexts, the
 * draw calls up to `limit`; false with *d filled when they differ. */
static bool run_pair(long b, uint64_t bseed, long limit, bool record, struct diff *d,
                     struct rs_snapshot *fast_rs)
{
   const struct config c = pick_config(bseed);
   struct side fast = { 0 }, ref = { 0 };
   if (!make_side(&fast, &c, false) || !make_side(&ref, &c, true)) {
      FAIL("batch %ld: cannot create the contexts (%s depth %d stencil %d %dx%d)", b,
           format_name(c.format), c.depth, c.stencil, c.w, c.h);
      free_side(&fast);
      free_side(&ref);
      return true;
   }
   OSMesaMakeCurrent(fast.osm, fast.buf, GL_UNSIGNED_BYTE, c.w, c.h);
   g_limit = limit;
   g_record = record;
   /* the counters in every other batch (the kernels' paths with and
    * without them) */
   const bool stats = bseed & 2;
   fixglStats(stats);
   gen_batch(bseed, true);
   struct fixgl_stats st;
   fixglGetStats(&st);
   if (stats && g_count_on) {
      g_count.fragments += st.fragments;
      g_count.stats_batches++;
   }
   if (fast_rs)
      snapshot(fast_rs, &fast.gl->_Raster);
   const bool log = g_log;
   g_log = false;
   OSMesaMakeCurrent(ref.osm, ref.buf, GL_UNSIGNED_BYTE, c.w, c.h);
   g_record = false;
   gen_batch(bseed, false);
   g_log = log;
   if (b == g_perturb && fast.gl->DrawBuffer->Color) {
      fgl_lazy_resolve(fast.gl->DrawBuffer, FGL_LAZY_COLOR | FGL_LAZY_ZS);
      fast.gl->DrawBuffer->Color[4 * (size_t)(c.w * (c.h / 2) + c.w / 2)] ^= 0x10;
   }
   bool same = compare_buffers(&c, &fast, &ref, d);
   /* then the occlusion queries' counts */
   if (same && g_reads[0] != g_reads[1]) {
      *d = (struct diff){ "glReadPixels in the middle of the batch", 0, 0, (uint32_t)g_reads[0],
                          (uint32_t)g_reads[1] };
      same = false;
   }
   for (int i = 0; same && i < g_nqueries[0] && i < g_nqueries[1]; i++) {
      if (g_queries[1][i] != g_queries[0][i]) {
         *d = (struct diff){ "occlusion query", i, 0, g_queries[0][i], g_queries[1][i] };
         same = false;
      }
   }
   OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
   free_side(&fast);
   free_side(&ref);
   return same;
}

static uint64_t batch_seed(uint64_t seed, long b)
{
   return mix64(seed * 0x9e3779b97f4a7c15ull + (uint64_t)b + 1);
}

static void print_rs(const struct r_state *rs)
{
   fprintf(stderr,
           "  raster state: zs_format %d depth test %d func %d write %d | full_ops %d alpha %d "
           "func %d ref %u | stencil %d func %d ref %u masks 0x%x 0x%x ops %d %d %d | blend %d eq %d "
           "%d %d colour %u %u %u %u | logic %d %u | colour mask 0x%x dst_alpha_one %d\n"
           "  fs_inputs 0x%x flat_mask 0x%x colour sum %d twoside %d fog %d aa %d stipple %d "
           "phong %d (models %d %d) tex_units 0x%x tex_nr %d pix %d | offset %.9g %.9g | "
           "tri kernels %p %p line kernels %p %p\n",
           rs->fb->zs_format, rs->dsa->depth_test, rs->dsa->depth_func, rs->dsa->depth_write, rs->full_ops,
           rs->dsa->alpha_test, rs->dsa->alpha_func, rs->dsa->alpha_ref, rs->dsa->stencil_test, rs->dsa->stencil_func,
           rs->dsa->stencil_ref, rs->dsa->stencil_valuemask, rs->dsa->stencil_writemask, rs->dsa->stencil_fail,
           rs->dsa->stencil_zfail, rs->dsa->stencil_zpass, rs->blend->enable, rs->blend->blend_eq, rs->blend->blend_src,
           rs->blend->blend_dst, rs->blend->blend_color[0], rs->blend->blend_color[1], rs->blend->blend_color[2],
           rs->blend->blend_color[3], rs->blend->logic_op, rs->blend->logic_op_mode, rs->blend->color_mask, rs->blend->dst_alpha_one,
           rs->fs->fs_inputs, rs->flat_mask, rs->fs->color_sum, rs->rast->twoside, rs->fs->fog_mode, rs->fs->aa,
           rs->rast->stipple, rs->fs->phong, rs->shade_env ? (int)rs->shade_env->material[0].model : -1,
           rs->shade_env ? (int)rs->shade_env->material[1].model : -1,
           rs->fs->tex_units, rs->fs->tex_nr, rs->pix != NULL, rs->rast->offset_units, rs->rast->offset_scale,
           (void *)(uintptr_t)rs->tri_kernel[0], (void *)(uintptr_t)rs->tri_kernel[1],
           (void *)(uintptr_t)rs->line_kernel[0], (void *)(uintptr_t)rs->line_kernel[1]);
   for (int u = 0; u < rs->fs->tex_nr; u++)
      if (rs->fs->tex_units & (1u << u))
         fprintf(stderr,
                 "  unit %d: %dD min %d mag %d mip %d wrap %d %d soa %d float %d comb %d %d "
                 "simple %d fn %d %d\n",
                 u, rs->tex[u]->tex.dims, rs->tex[u]->tex.min_img, rs->tex[u]->tex.mag_img,
                 rs->tex[u]->tex.mip, rs->tex[u]->tex.wrap_s, rs->tex[u]->tex.wrap_t,
                 rs->tex[u]->tex.soa, rs->tex[u]->tex.float_path, rs->tex[u]->comb.mode_rgb,
                 rs->tex[u]->comb.mode_a, rs->tex[u]->comb.simple, rs->tex[u]->comb.simple_fn_rgb,
                 rs->tex[u]->comb.simple_fn_a);
}

/* A batch whose buffers differ: the first draw call after which they do,
 * with its calls and state. */
static void report_mismatch(uint64_t seed, long b, const struct diff *whole)
{
   const uint64_t bseed = batch_seed(seed, b);
   const struct config c = pick_config(bseed);
   fprintf(stderr,
           "MISMATCH: seed %llu batch %ld (replay: --seed %llu --batch %ld): %s %dx%d depth %d "
           "stencil %d: %s at (%d, %d) reference 0x%08x fast 0x%08x\n",
           (unsigned long long)seed, b, (unsigned long long)seed, b, format_name(c.format), c.w,
           c.h, c.depth, c.stencil, whole->buffer, whole->x, whole->y, whole->expected, whole->got);
   long first = -1;
   struct diff d;
   for (long lim = 0; lim < 100000; lim++) {
      if (!run_pair(b, bseed, lim, false, &d, NULL)) {
         first = lim;
         break;
      }
      if (lim > g_calls)
         break;
   }
   if (first < 0) {
      fprintf(stderr, "  (no prefix of the draw calls differs: only the whole batch)\n");
      return;
   }
   static struct rs_snapshot rs;
   g_log = true;
   g_loglen = 0;
   run_pair(b, bseed, first, false, &d, &rs);
   g_log = false;
   if (first == 0)
      fprintf(stderr, "  differing before any draw call: ");
   else
      fprintf(stderr, "  first differing after draw call %ld (case %d): ", first, g_limit_case);
   fprintf(stderr,
           "%s at (%d, %d) (GL window coordinates) reference 0x%08x fast 0x%08x\n", d.buffer, d.x, d.y, d.expected, d.got);
   fprintf(stderr, "  GL calls of the batch up to it:\n%s", g_logbuf ? g_logbuf : "");
   print_rs(&rs.rs);
}

/* ---- main ---------------------------------------------------------------- */

static bool self_check(void)
{
   /* a batch drawn twice into equal contexts compares equal; one byte of
    * each buffer changed does not */
   const struct config c = { OSMESA_RGBA, 24, 8, 61, 37, { 1, 0 } };
   struct side a = { 0 }, r = { 0 };
   if (!make_side(&a, &c, false) || !make_side(&r, &c, true))
      return false;
   bool ok = true;
   for (int i = 0; i < 2; i++) {
      OSMesaMakeCurrent(i ? r.osm : a.osm, i ? r.buf : a.buf, GL_UNSIGNED_BYTE, c.w, c.h);
      glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
      glClearStencil(3);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
      glFinish();
   }
   struct diff d;
   ok &= compare_buffers(&c, &a, &r, &d);
   uint8_t *bytes[3] = { a.gl->DrawBuffer->Color, (uint8_t *)a.gl->DrawBuffer->Depth,
                         (uint8_t *)a.gl->DrawBuffer->Depth + 3 };
   for (int i = 0; i < 3; i++) {
      const size_t at = 4 * (size_t)(c.w * 17 + 59);
      bytes[i][at] ^= 1;
      ok &= !compare_buffers(&c, &a, &r, &d) && d.x == 59 && d.y == c.h - 1 - 17;
      bytes[i][at] ^= 1;
   }
   ok &= compare_buffers(&c, &a, &r, &d);
   OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
   free_side(&a);
   free_side(&r);
   return ok;
}

int main(int argc, char **argv)
{
   uint64_t seed = 1;
   long count = 200000, only = -1;
   bool verbose = false;
   for (int i = 1; i < argc; i++) {
      if (!strcmp(argv[i], "--seed") && i + 1 < argc)
         seed = strtoull(argv[++i], NULL, 0);
      else if (!strcmp(argv[i], "--count") && i + 1 < argc)
         count = strtol(argv[++i], NULL, 0);
      else if (!strcmp(argv[i], "--batch") && i + 1 < argc)
         only = strtol(argv[++i], NULL, 0);
      else if (!strcmp(argv[i], "--perturb") && i + 1 < argc)
         g_perturb = strtol(argv[++i], NULL, 0);
      else if (!strcmp(argv[i], "--same"))
         g_same = true;
      else if (!strcmp(argv[i], "-v"))
         verbose = true;
      else {
         fprintf(stderr, "usage: %s [--seed N] [--count N] [--batch N] [--perturb N] [--same] [-v]\n",
                 argv[0]);
         return 2;
      }
   }
   if (getenv("FIXGL_KERNELS")) {
      fprintf(stderr, "note: FIXGL_KERNELS=%s ignored (this test sets it itself)\n",
              getenv("FIXGL_KERNELS"));
      unsetenv("FIXGL_KERNELS");
   }
#if defined(FGL_HAVE_BLOCK_KERNELS) && (defined(__x86_64__) || defined(__i386__))
   const bool have_fast = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
   /* each batch is drawn by both builds of the fast kernels */
   const bool have_avx512 = r_kernel_isa(NULL) == R_ISA_AVX512;
#else
   const bool have_fast = false;   /* the library has no fast kernels */
   const bool have_avx512 = false;
#endif

   CHECK(self_check(), "the comparison does not notice a changed byte");

   struct timespec ts0;
   clock_gettime(CLOCK_MONOTONIC, &ts0);
   long b = only >= 0 ? only : 0;
   int mismatches = 0;
   for (;; b++) {
      if (only >= 0 ? b > only : (long)(g_count.tris + g_count.lines + g_count.points +
                                        g_count.pixels) >= count)
         break;
      const uint64_t bseed = batch_seed(seed, b);
      if (only >= 0) {
         g_log = true;
         g_loglen = 0;
      }
      struct diff d;
      bool same = run_pair(b, bseed, 1L << 30, true, &d, NULL);
      if (same && have_avx512) {
         /* the same batch drawn by the AVX2 build (counted once) */
         const __typeof__(g_count) counted = g_count;
         g_fast_kernels = "avx2";
         same = run_pair(b, bseed, 1L << 30, true, &d, NULL);
         if (!same)
            fprintf(stderr, "(the AVX2 build of the kernels, FIXGL_KERNELS=avx2)\n");
         g_fast_kernels = NULL;
         g_count = counted;
      }
      g_count.batches++;
      if (only >= 0) {
         fprintf(stderr, "%s", g_logbuf ? g_logbuf : "");
         g_log = false;
      }
      if (verbose) {
         const struct config c = pick_config(bseed);
         fprintf(stderr, "batch %ld: %s %dx%d depth %d stencil %d: %s\n", b,
                 format_name(c.format), c.w, c.h, c.depth, c.stencil, same ? "same" : "DIFFERENT");
      }
      if (!same) {
         FAIL("seed %llu batch %ld: the fast kernels' buffers differ from the reference's",
              (unsigned long long)seed, b);
         report_mismatch(seed, b, &d);
         if (++mismatches >= 3)
            break;
      }
   }
   struct timespec ts1;
   clock_gettime(CLOCK_MONOTONIC, &ts1);
   const double secs = (double)(ts1.tv_sec - ts0.tv_sec) + 1e-9 * (double)(ts1.tv_nsec - ts0.tv_nsec);

   const uint64_t prims = g_count.tris + g_count.lines + g_count.points + g_count.pixels;
   printf("kernels: seed %llu, %llu batches, %llu cases, %llu primitives (%llu triangles, %llu "
          "lines, %llu points, %llu pixel rectangles) in %.2f s\n",
          (unsigned long long)seed, (unsigned long long)g_count.batches,
          (unsigned long long)g_count.cases, (unsigned long long)prims,
          (unsigned long long)g_count.tris, (unsigned long long)g_count.lines,
          (unsigned long long)g_count.points, (unsigned long long)g_count.pixels, secs);
   printf("kernels: %llu fragments shaded in the fast contexts of the %llu batches that counted "
          "them (fixglStats); %llu cases raised a GL error\n",
          (unsigned long long)g_count.fragments, (unsigned long long)g_count.stats_batches,
          (unsigned long long)g_count.gl_errors);
   printf("kernels: %llu occlusion queries counted %llu samples, equal in both contexts\n",
          (unsigned long long)g_count.queries, (unsigned long long)g_count.samples);
   printf("kernels: %zu kernel/state combinations drawn by %d fast kernels; %zu of %zu state keys "
          "fell back to the reference kernels\n",
          g_combos.n, g_nkernels, g_fallback.n, g_keys.n);
   printf("kernels: combinations by primitive: %lu triangles, %lu lines, %lu points\n",
          g_kind_combos[KIND_TRI_SMOOTH] + g_kind_combos[KIND_TRI_FLAT],
          g_kind_combos[KIND_LINE_SMOOTH] + g_kind_combos[KIND_LINE_FLAT],
          g_kind_combos[KIND_POINT]);
   if (have_avx512)
      printf("kernels: every batch drawn by the AVX-512 and the AVX2 builds of the fast kernels\n");
   if (!have_fast) {
      printf("kernels: NOTE: no fast kernel can run here (the CPU lacks AVX2+FMA, or the library "
             "was built without its AVX2 kernels): both contexts drew with the reference "
             "kernels, so the comparison is trivially equal\n");
   } else if (only < 0 && g_combos.n == 0) {
      FAIL("no fast kernel was exercised on a CPU with AVX2 and FMA: the test tests nothing");
   }
   if (only < 0 && g_count.samples == 0)
      FAIL("no occlusion query counted a sample: the counting is not tested");
   fflush(stdout);
   return check_report("kernels");
}
