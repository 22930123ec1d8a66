/*
 * tex_kernels.c - the textured block kernels (raster/r_block_tex_avx2.c)
 * against the reference kernels, through the GL API (fixgl only).
 *
 * Two contexts of each depth format (16, 24, 24 + 8 stencil bits): one
 * created normally, one created after setenv("FIXGL_KERNELS",
 * "reference") (context.c reads it at creation), and one created after
 * setenv("FIXGL_KERNELS", "avx2") (the AVX2 build of the kernels where the
 * CPU runs their AVX-512 build, which the first one then uses; the same
 * kernels elsewhere), on buffers of an odd
 * size (blocks past the right edge).  Each case draws, in both, the same
 * random textured triangles on the same random state -- texture (1D or
 * 2D, power of two or not, RGB, RGBA, LUMINANCE, LUMINANCE_ALPHA, ALPHA,
 * INTENSITY, a full or partial mipmap chain, BASE/MAX_LEVEL, LOD clamps
 * and bias), filters, wraps, environment (MODULATE, REPLACE, DECAL, ADD,
 * BLEND, simple and other COMBINEs, a constant colour), flat or smooth
 * colour, depth test, function and mask, alpha blending (or another
 * blend), perspective (clip w) and projective (q) coordinates, tiny and
 * huge triangles, vertices on pixel centres, scales that magnify and
 * minify, a projective texture matrix, scissor box, polygon offset -- and compares the colour and depth buffers byte for byte.
 * A third of the cases enable two to four units (r_block_mtex_avx2.c), each
 * with its own random texture, environment and coordinates (COMBINE
 * sources then include the other units' textures, GL_SUBTRACT and
 * GL_INTERPOLATE after GL_ADD, DECAL or BLEND units followed by an ADD
 * one: NIR's reassociation, r_frag.c emit_combine).
 * A state the block kernels don't cover draws with the reference kernels
 * in both contexts, so every case must match.
 *
 * Usage: api-tex-kernels [cases] [seed]
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define W 83
#define H 61

/* xorshift64*, seeded per case: both contexts get the same stream */
static uint64_t rng_state;
static uint32_t rnd(void)
{
  rng_state ^= rng_state >> 12;
  rng_state ^= rng_state << 25;
  rng_state ^= rng_state >> 27;
  return (uint32_t)((rng_state * 2685821657736338717ull) >> 32);
}
static int irand(int n) { return (int)(rnd() % (uint32_t)n); }
static float frand(float lo, float hi) { return lo + (hi - lo) * (float)(rnd() >> 8) / 16777216.0f; }

static const GLenum formats[] = { GL_RGB, GL_RGBA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA,
                                  GL_INTENSITY };
static int format_channels(GLenum f)
{
  switch (f) {
  case GL_RGB:             return 3;
  case GL_RGBA:            return 4;
  case GL_LUMINANCE_ALPHA: return 2;
  default:                 return 1;
  }
}

static void random_texture(GLenum target)
{
  const GLenum fmt = formats[irand(6)];
  const int nc = format_channels(fmt);
  const bool npot = irand(4) == 0;
  int w = npot ? 1 + irand(40) : 1 << irand(8);
  int h = target == GL_TEXTURE_1D ? 1 : (npot ? 1 + irand(40) : 1 << irand(8));
  const int style = irand(3);
  const bool mip = irand(4) != 0;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  unsigned char *img = malloc((size_t)w * (size_t)h * (size_t)nc);
  for (int l = 0;; l++) {
    for (int y = 0; y < h; y++)
      for (int x = 0; x < w; x++)
        for (int c = 0; c < nc; c++) {
          unsigned char v;
          if (style == 0)
            v = (unsigned char)rnd();
          else if (style == 1)
            v = (unsigned char)((((x >> 2) ^ (y >> 2)) & 1) ? 230 - 40 * c : 20 + 60 * c + l * 10);
          else
            v = (unsigned char)(x * 7 + y * 3 + c * 50 + l * 30);
          img[((size_t)y * (size_t)w + (size_t)x) * (size_t)nc + (size_t)c] = v;
        }
    if (target == GL_TEXTURE_1D)
      glTexImage1D(GL_TEXTURE_1D, l, (GLint)fmt, w, 0, fmt, GL_UNSIGNED_BYTE, img);
    else
      glTexImage2D(GL_TEXTURE_2D, l, (GLint)fmt, w, h, 0, fmt, GL_UNSIGNED_BYTE, img);
    if (!mip || (w == 1 && h == 1))
      break;
    w = w > 1 ? w / 2 : 1;
    h = h > 1 ? h / 2 : 1;
  }
  free(img);
  static const GLenum mins[] = { GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
                                 GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                                 GL_LINEAR_MIPMAP_LINEAR };
  const GLenum min = irand(3) == 0 ? GL_LINEAR_MIPMAP_LINEAR : mins[irand(mip ? 6 : 2)];
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)min);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, irand(3) ? GL_LINEAR : GL_NEAREST);
  /* mostly the wraps the block kernels cover */
  static const GLenum wraps[] = { GL_REPEAT, GL_REPEAT, GL_REPEAT, GL_REPEAT, GL_REPEAT,
                                  GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE,
                                  GL_CLAMP, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT };
  glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)wraps[irand(irand(4) ? 8 : 11)]);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)wraps[irand(irand(4) ? 8 : 11)]);
  if (irand(8) == 0)
    glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, irand(3));
  if (irand(8) == 0)
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, irand(6));
  if (irand(30) == 0)
    glTexParameterf(target, GL_TEXTURE_MIN_LOD, frand(-2.0f, 3.0f));
  if (irand(30) == 0)
    glTexParameterf(target, GL_TEXTURE_MAX_LOD, frand(0.0f, 6.0f));
  if (irand(30) == 0)
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, frand(-2.0f, 2.0f));
}

static void random_env(int nunits)
{
  static const GLenum modes[] = { GL_MODULATE, GL_MODULATE, GL_REPLACE, GL_REPLACE, GL_DECAL,
                                  GL_ADD, GL_BLEND, GL_COMBINE, GL_COMBINE };
  const GLenum mode = modes[irand(9)];
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)mode);
  const GLfloat ec[4] = { frand(0, 1), frand(0, 1), frand(0, 1), frand(0, 1) };
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
  if (mode != GL_COMBINE)
    return;
  static const GLenum cmodes[] = { GL_REPLACE, GL_MODULATE, GL_REPLACE, GL_MODULATE, GL_ADD,
                                   GL_INTERPOLATE, GL_SUBTRACT };
  static const GLenum srcs[] = { GL_TEXTURE, GL_PRIMARY_COLOR, GL_PREVIOUS, GL_CONSTANT,
                                 GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE2, GL_TEXTURE3 };
  /* another unit's texture as a source only now and then (those draw
   * with the reference kernels) */
  const int nsrcs = nunits > 1 && irand(4) == 0 ? 4 + nunits : 4;
  static const GLenum oprs_rgb[] = { GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                     GL_ONE_MINUS_SRC_ALPHA };
  static const GLenum oprs_a[] = { GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA };
  const int ncm = nunits > 1 ? 7 : 6;
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)cmodes[irand(ncm)]);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)cmodes[irand(ncm)]);
  static const GLenum src_rgb[] = { GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_SOURCE2_RGB };
  static const GLenum src_a[] = { GL_SOURCE0_ALPHA, GL_SOURCE1_ALPHA, GL_SOURCE2_ALPHA };
  static const GLenum op_rgb[] = { GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB };
  static const GLenum op_a[] = { GL_OPERAND0_ALPHA, GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA };
  for (int i = 0; i < 3; i++) {
    glTexEnvi(GL_TEXTURE_ENV, src_rgb[i], (GLint)srcs[irand(nsrcs)]);
    glTexEnvi(GL_TEXTURE_ENV, src_a[i], (GLint)srcs[irand(nsrcs)]);
    glTexEnvi(GL_TEXTURE_ENV, op_rgb[i], (GLint)oprs_rgb[irand(4)]);
    glTexEnvi(GL_TEXTURE_ENV, op_a[i], (GLint)oprs_a[irand(2)]);
  }
  if (irand(6) == 0)
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
}

/* one vertex: window-ish position in clip space with weight w, a colour
 * and a texture coordinate with q */
#define MAX_UNITS 4
struct vert {
  float x, y, z, w;
  float c[4];
  float s[MAX_UNITS], t[MAX_UNITS], q[MAX_UNITS];
};

static int case_units;   /* the units of the case */

static void emit(const struct vert *v, bool proj)
{
  glColor4fv(v->c);
  for (int u = 0; u < case_units; u++) {
    if (proj)
      glMultiTexCoord4f(GL_TEXTURE0 + (GLenum)u, v->s[u] * v->q[u], v->t[u] * v->q[u], 0.0f,
                        v->q[u]);
    else
      glMultiTexCoord2f(GL_TEXTURE0 + (GLenum)u, v->s[u], v->t[u]);
  }
  glVertex4f(v->x * v->w, v->y * v->w, v->z * v->w, v->w);
}

static void random_triangles(void)
{
  const int kind = irand(5);
  const bool proj = irand(3) == 0;
  const bool persp = irand(2) == 0;
  /* texture scale: magnify (small) to minify (large) */
  float ts[MAX_UNITS], s0[MAX_UNITS], t0[MAX_UNITS];
  for (int u = 0; u < case_units; u++) {
    ts[u] = powf(2.0f, frand(-5.0f, 6.0f));
    s0[u] = frand(-4.0f, 4.0f);
    t0[u] = frand(-4.0f, 4.0f);
  }
  const int n = kind == 0 ? 40 : 1 + irand(6);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < n; i++) {
    struct vert v[3];
    const float cx = frand(-1.2f, 1.2f), cy = frand(-1.2f, 1.2f);
    for (int k = 0; k < 3; k++) {
      float x, y;
      switch (kind) {
      case 0:   /* tiny */
        x = cx + frand(-0.06f, 0.06f);
        y = cy + frand(-0.06f, 0.06f);
        break;
      case 1:   /* huge: reaches past the window */
        x = frand(-6.0f, 6.0f);
        y = frand(-6.0f, 6.0f);
        break;
      case 2:   /* on pixel centres: window x = k + 0.5 (viewport 64 x 64) */
        x = (float)(irand(64) * 2 + 1) / 64.0f - 1.0f;
        y = (float)(irand(64) * 2 + 1) / 64.0f - 1.0f;
        break;
      default:
        x = frand(-1.1f, 1.1f);
        y = frand(-1.1f, 1.1f);
        break;
      }
      v[k].x = x;
      v[k].y = y;
      v[k].z = frand(-1.0f, 1.0f);
      v[k].w = persp && kind != 2 ? frand(0.2f, 4.0f) : 1.0f;
      for (int c = 0; c < 4; c++)
        v[k].c[c] = frand(0.0f, 1.0f);
      for (int u = 0; u < case_units; u++) {
        v[k].s[u] = s0[u] + x * ts[u] * frand(0.5f, 1.5f);
        v[k].t[u] = t0[u] + y * ts[u] * frand(0.5f, 1.5f);
        v[k].q[u] = proj ? frand(0.25f, 3.0f) : 1.0f;
      }
    }
    for (int k = 0; k < 3; k++)
      emit(&v[k], proj);
  }
  glEnd();
}

/* the whole case, from its seed */
static void draw_case(uint64_t seed)
{
  rng_state = seed * 0x9E3779B97F4A7C15ull + 1;
  glViewport(0, 0, irand(2) ? W : 64, irand(2) ? H : 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(frand(0, 1), frand(0, 1), frand(0, 1), frand(0, 1));
  glClearDepth(frand(0.3f, 1.0f));
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  const GLuint names[MAX_UNITS] = { 1, 2, 3, 4 };
  case_units = irand(3) == 0 ? 2 + irand(MAX_UNITS - 1) : 1;
  for (int u = 0; u < MAX_UNITS; u++) {
    glActiveTexture(GL_TEXTURE0 + (GLenum)u);
    glDisable(GL_TEXTURE_1D);
    glDisable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
  }
  glDeleteTextures(MAX_UNITS, names);
  for (int u = case_units - 1; u >= 0; u--) {
    glActiveTexture(GL_TEXTURE0 + (GLenum)u);
    const GLenum target = irand(8) == 0 ? GL_TEXTURE_1D : GL_TEXTURE_2D;
    glBindTexture(target, names[u]);
    random_texture(target);
    random_env(case_units);
    glEnable(target);
  }

  glShadeModel(irand(3) == 0 ? GL_FLAT : GL_SMOOTH);
  static const GLenum funcs[] = { GL_LESS, GL_LEQUAL, GL_GREATER, GL_GEQUAL, GL_EQUAL,
                                  GL_NOTEQUAL, GL_ALWAYS, GL_NEVER };
  if (irand(4)) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(irand(2) ? GL_LESS : funcs[irand(8)]);
    glDepthMask(irand(4) ? GL_TRUE : GL_FALSE);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  const int blend = irand(4);
  if (blend == 0) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  } else if (blend == 1 && irand(3) == 0) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
  } else {
    glDisable(GL_BLEND);
  }
  if (irand(10) == 0) {
    glEnable(GL_CULL_FACE);
    glCullFace(irand(2) ? GL_BACK : GL_FRONT);
  } else {
    glDisable(GL_CULL_FACE);
  }
  if (irand(4) == 0) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(irand(W) - 5, irand(H) - 5, irand(W), irand(H));
  } else {
    glDisable(GL_SCISSOR_TEST);
  }
  if (irand(5) == 0) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(frand(-2.0f, 2.0f), frand(-4.0f, 4.0f));
  } else {
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  if (irand(6) == 0) {
    /* (on unit 0, the active one) */
    /* a projective texture matrix: q varies across the triangle */
    const GLfloat m[16] = { frand(-2, 2), frand(-1, 1), 0, frand(-0.5f, 0.5f),
                            frand(-1, 1), frand(-2, 2), 0, frand(-0.5f, 0.5f),
                            0, 0, 1, 0,
                            frand(-1, 1), frand(-1, 1), 0, frand(0.8f, 2.0f) };
    glLoadMatrixf(m);
  }
  glMatrixMode(GL_MODELVIEW);
  const int batches = 1 + irand(3);
  for (int b = 0; b < batches; b++)
    random_triangles();
  glFinish();
}

struct pair {
  int depth, stencil;
  OSMesaContext ctx[3];   /* [0] block kernels, [1] reference, [2] FIXGL_KERNELS=avx2 */
  unsigned char buf[3][W * H * 4];
};

int main(int argc, char **argv)
{
  const int cases = argc > 1 ? atoi(argv[1]) : 3000;
  const uint64_t seed0 = argc > 2 ? strtoull(argv[2], NULL, 0) : 1;
  static struct pair pairs[3];
  for (int p = 0; p < 3; p++) {
    pairs[p].depth = p ? 24 : 16;
    pairs[p].stencil = p == 2 ? 8 : 0;
    unsetenv("FIXGL_KERNELS");
    pairs[p].ctx[0] = OSMesaCreateContextExt(OSMESA_RGBA, pairs[p].depth, pairs[p].stencil, 0, NULL);
    setenv("FIXGL_KERNELS", "reference", 1);
    pairs[p].ctx[1] = OSMesaCreateContextExt(OSMESA_RGBA, pairs[p].depth, pairs[p].stencil, 0, NULL);
    setenv("FIXGL_KERNELS", "avx2", 1);
    pairs[p].ctx[2] = OSMesaCreateContextExt(OSMESA_RGBA, pairs[p].depth, pairs[p].stencil, 0, NULL);
    CHECK(pairs[p].ctx[0] && pairs[p].ctx[1] && pairs[p].ctx[2], "context creation");
  }
  unsetenv("FIXGL_KERNELS");
  int bad_cases = 0, multi = 0;
  long drawn = 0;
  for (int i = 0; i < cases; i++) {
    struct pair *pr = &pairs[i % 3];
    const uint64_t seed = seed0 + (uint64_t)i;
    void *depth[3];
    GLint bpv[3];
    for (int k = 0; k < 3; k++) {
      CHECK(OSMesaMakeCurrent(pr->ctx[k], pr->buf[k], GL_UNSIGNED_BYTE, W, H), "make current");
      draw_case(seed);
      multi += k == 0 && case_units > 1;
      GLint w, h;
      OSMesaGetDepthBuffer(pr->ctx[k], &w, &h, &bpv[k], &depth[k]);
    }
    /* the default kernels, then FIXGL_KERNELS=avx2's, against the reference */
    bool case_bad = false;
    for (int k = 0; k < 3; k += 2) {
      size_t diff = 0, first = SIZE_MAX;
      for (size_t j = 0; j < sizeof pr->buf[0]; j++)
        if (pr->buf[k][j] != pr->buf[1][j]) {
          diff++;
          if (first == SIZE_MAX)
            first = j;
        }
      const size_t zbytes = (size_t)W * H * (size_t)bpv[k];
      const bool zsame = bpv[k] == bpv[1] && memcmp(depth[k], depth[1], zbytes) == 0;
      if (diff || !zsame) {
        if (bad_cases + case_bad < 10)
          FAIL("case %d (seed %llu, depth %d/%d, %s kernels): %zu colour bytes differ (first at "
               "pixel %zu,%zu: %u vs %u), depth %s",
               i, (unsigned long long)seed, pr->depth, pr->stencil, k ? "avx2" : "default", diff,
               first == SIZE_MAX ? 0 : first / 4 % W, first == SIZE_MAX ? 0 : first / 4 / W,
               first == SIZE_MAX ? 0 : pr->buf[k][first],
               first == SIZE_MAX ? 0 : pr->buf[1][first], zsame ? "same" : "differs");
        case_bad = true;
      }
    }
    bad_cases += case_bad;
    /* something was drawn (the clear colour is rarely everywhere) */
    for (size_t j = 0; j < sizeof pr->buf[0]; j += 4)
      if (memcmp(&pr->buf[0][j], &pr->buf[0][0], 4) != 0) {
        drawn++;
        break;
      }
  }
  CHECK(drawn > cases / 2, "too few cases drew anything (%ld of %d)", drawn, cases);
  CHECK(cases < 30 || multi > cases / 5, "too few multi-texture cases (%d of %d)", multi, cases);
  fprintf(stderr, "tex_kernels: %d cases (%d with 2 to 4 units), %d differ\n", cases, multi,
          bad_cases);
  for (int p = 0; p < 3; p++) {
    OSMesaDestroyContext(pairs[p].ctx[0]);
    OSMesaDestroyContext(pairs[p].ctx[1]);
    OSMesaDestroyContext(pairs[p].ctx[2]);
  }
  return check_report("tex_kernels");
}
