/*
 * lit_kernels.c - the kernels of lit scenes against the reference kernels,
 * byte for byte, through the API (fixgl only).
 *
 * Two sets of contexts draw the same random scenes: the first created as
 * usual (on an AVX2 + FMA CPU the block kernels, raster/r_block_*_avx2.c,
 * and the 8-lane lighting), the others after
 * setenv("FIXGL_KERNELS", "reference"), which a context reads when it is
 * created (context.c): the scalar reference kernels for everything; a
 * third set after setenv("FIXGL_KERNELS", "avx2"): the AVX2 build of the
 * kernels where the CPU runs their AVX-512 build (which the first set then
 * uses), the same kernels elsewhere.  The colour buffer and the depth buffer (16 and 24 bits) must be the same
 * bytes.
 *
 * The scenes: random lights (directional, point, spot, attenuated; one to
 * eight), light models (two-sided, local viewer, separate specular),
 * materials per face with both reflectance models (Blinn-Phong and
 * GL_FIXGL_cook_torrance), colour material of every mode and face,
 * glMaterial between vertices, GL_NORMALIZE, GL_RESCALE_NORMAL under a
 * scaled modelview, unnormalised and zero normals,
 * GL_PHONG_WIN mostly (the per-fragment block kernel) and GL_SMOOTH /
 * GL_FLAT (per-vertex lighting), culling, both windings, depth functions
 * and masks, alpha blending, and now and then fog of every mode, user
 * clip planes, the lighting off, and batches of up to 2,200 vertices
 * (triangles, strips, quads) that the vertex stage transforms window by
 * window (the eight-lane positions and clip codes, tnl/t_vertex_avx2.c,
 * against the scalar ones).
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <fixgl/fixgl.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define W 67   /* not a multiple of 4: blocks past the right edge */
#define H 50
#define SCENES 600

static uint32_t rng;

static uint32_t next(void)
{
  rng ^= rng << 13;
  rng ^= rng >> 17;
  rng ^= rng << 5;
  return rng;
}

static float frand(float lo, float hi)
{
  return lo + (hi - lo) * (float)(next() >> 8) / 16777216.0f;
}

static int chance(int percent)
{
  return (int)(next() % 100u) < percent;
}

static GLenum pick(const GLenum *v, int n)
{
  return v[next() % (uint32_t)n];
}

static void rand4(float *v, float lo, float hi)
{
  for (int i = 0; i < 4; i++)
    v[i] = frand(lo, hi);
}

static void material(GLenum face)
{
  float v[4];
  rand4(v, 0.0f, 1.0f);
  glMaterialfv(face, GL_AMBIENT, v);
  rand4(v, 0.0f, 1.0f);
  glMaterialfv(face, GL_DIFFUSE, v);
  rand4(v, 0.0f, 1.0f);
  glMaterialfv(face, GL_SPECULAR, v);
  rand4(v, 0.0f, chance(50) ? 0.0f : 0.4f);
  glMaterialfv(face, GL_EMISSION, v);
  glMaterialf(face, GL_SHININESS, chance(10) ? 0.0f : frand(0.0f, 128.0f));
  glMateriali(face, GL_REFLECTANCE_MODEL_FIXGL,
              chance(50) ? GL_COOK_TORRANCE_FIXGL : GL_BLINN_PHONG_FIXGL);
  glMaterialf(face, GL_ROUGHNESS_FIXGL, chance(10) ? 0.0f : frand(0.0f, 1.0f));
  glMaterialf(face, GL_METALNESS_FIXGL, frand(0.0f, 1.0f));
  glMaterialf(face, GL_DIELECTRIC_F0_FIXGL, frand(0.0f, 0.2f));
}

static void draw_scene(uint32_t seed)
{
  rng = seed * 2654435761u + 1u;
  if (!rng)
    rng = 1;
  static const GLenum faces[] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
  static const GLenum cm_modes[] = { GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION,
                                     GL_AMBIENT_AND_DIFFUSE };
  static const GLenum zfuncs[] = { GL_LESS, GL_LEQUAL, GL_GREATER, GL_GEQUAL, GL_ALWAYS,
                                   GL_NOTEQUAL, GL_EQUAL };
  static const GLenum models[] = { GL_PHONG_WIN, GL_PHONG_WIN, GL_PHONG_WIN, GL_PHONG_WIN,
                                   GL_PHONG_WIN, GL_PHONG_WIN, GL_SMOOTH, GL_SMOOTH, GL_FLAT };

  glClearColor(frand(0, 1), frand(0, 1), frand(0, 1), frand(0, 1));
  glClearDepth(chance(70) ? 1.0 : 0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.4, 0.4, 1.0, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.5f);
  glRotatef(frand(0, 360), frand(-1, 1), frand(-1, 1), frand(0.1f, 1));
  if (chance(30)) {
    const float k = frand(0.5f, 1.5f);
    glScalef(k, k, k);
  }

  /* lights, in the rotated eye space */
  const int nlights = chance(60) ? 1 + (int)(next() % 3u) : 1 + (int)(next() % 8u);
  for (int i = 0; i < 8; i++)
    glDisable(GL_LIGHT0 + i);
  for (int i = 0; i < nlights; i++) {
    const GLenum l = GL_LIGHT0 + (GLenum)(next() % 8u);
    float v[4];
    glEnable(l);
    rand4(v, 0.0f, 0.4f);
    glLightfv(l, GL_AMBIENT, v);
    rand4(v, 0.0f, 1.2f);
    glLightfv(l, GL_DIFFUSE, v);
    rand4(v, 0.0f, 1.2f);
    glLightfv(l, GL_SPECULAR, v);
    v[0] = frand(-3, 3), v[1] = frand(-3, 3), v[2] = frand(-3, 3);
    v[3] = chance(50) ? 0.0f : chance(80) ? 1.0f : frand(0.2f, 2.0f);
    glLightfv(l, GL_POSITION, v);
    const int spot = chance(30);
    glLightf(l, GL_SPOT_CUTOFF, spot ? frand(5, 90) : 180.0f);
    glLightf(l, GL_SPOT_EXPONENT, spot ? frand(0, 128) : 0.0f);
    v[0] = frand(-1, 1), v[1] = frand(-1, 1), v[2] = frand(-1, 1);
    glLightfv(l, GL_SPOT_DIRECTION, v);
    glLightf(l, GL_CONSTANT_ATTENUATION, chance(50) ? 1.0f : frand(0.3f, 1.5f));
    glLightf(l, GL_LINEAR_ATTENUATION, chance(50) ? 0.0f : frand(0, 0.5f));
    glLightf(l, GL_QUADRATIC_ATTENUATION, chance(70) ? 0.0f : frand(0, 0.3f));
  }
  float ga[4];
  rand4(ga, 0.0f, 0.3f);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ga);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, chance(50));
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, chance(30));
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                chance(40) ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
  material(GL_FRONT);
  material(GL_BACK);
  const int color_material = chance(35);
  if (color_material) {
    glColorMaterial(pick(faces, 3), pick(cm_modes, 5));
    glEnable(GL_COLOR_MATERIAL);
  } else {
    glDisable(GL_COLOR_MATERIAL);
  }
  glEnable(GL_LIGHTING);
  glShadeModel(pick(models, 9));
  if (chance(50))
    glEnable(GL_NORMALIZE);
  else
    glDisable(GL_NORMALIZE);
  if (chance(40))
    glEnable(GL_RESCALE_NORMAL);
  else
    glDisable(GL_RESCALE_NORMAL);

  if (chance(30)) {
    glEnable(GL_CULL_FACE);
    glCullFace(pick(faces, 2));
  } else {
    glDisable(GL_CULL_FACE);
  }
  glFrontFace(chance(50) ? GL_CCW : GL_CW);
  if (chance(85)) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(pick(zfuncs, 7));
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glDepthMask(chance(80));
  if (chance(25)) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  } else {
    glDisable(GL_BLEND);
  }
  if (chance(15)) {
    static const GLenum fog_modes[] = { GL_LINEAR, GL_EXP, GL_EXP2 };
    float fc[4];
    rand4(fc, 0.0f, 1.0f);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, pick(fog_modes, 3));
    glFogf(GL_FOG_START, frand(0.0f, 3.0f));
    glFogf(GL_FOG_END, frand(3.5f, 7.0f));
    glFogf(GL_FOG_DENSITY, frand(0.0f, 0.6f));
    glFogfv(GL_FOG_COLOR, fc);
  } else {
    glDisable(GL_FOG);
  }

  /* now and then a batch long enough to be transformed window by window,
   * its segments' clip codes from the eight-lane pre-pass (tnl/t_render.c
   * LAZY_WINDOW), as triangles, a strip or quads; a user clip plane; the
   * lighting off (the unlit colours after the eight-lane positions) */
  const int long_batch = chance(20);
  static const GLenum modes[] = { GL_TRIANGLES, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_QUADS };
  const GLenum mode = long_batch ? pick(modes, 4) : GL_TRIANGLES;
  if (chance(10)) {
    const GLdouble plane[4] = { frand(-1, 1), frand(-1, 1), frand(-1, 1), frand(0, 1) };
    glClipPlane(GL_CLIP_PLANE0 + (GLenum)(next() % 2u), plane);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE1);
  } else {
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_CLIP_PLANE1);
  }
  if (chance(10))
    glDisable(GL_LIGHTING);
  const int ntris = long_batch ? 130 + (int)(next() % 600u) : 4 + (int)(next() % 40u);
  const int big = chance(30);
  const int vertex_color = chance(70);
  const int mat_per_vertex = chance(10);
  glBegin(mode);
  for (int t = 0; t < ntris; t++) {
    float c[3] = { frand(-1.2f, 1.2f), frand(-1.2f, 1.2f), frand(-1.2f, 1.2f) };
    const float s = big ? 2.0f : 0.8f;
    for (int k = 0; k < 3; k++) {
      if (vertex_color || k == 0)
        glColor4f(frand(0, 1), frand(0, 1), frand(0, 1), frand(0, 1));
      if (chance(3))
        glNormal3f(0.0f, 0.0f, 0.0f);
      else
        glNormal3f(frand(-2, 2), frand(-2, 2), frand(-2, 2));
      if (mat_per_vertex && chance(30)) {
        float v[4];
        rand4(v, 0.0f, 1.0f);
        glMaterialfv(pick(faces, 3), chance(50) ? GL_DIFFUSE : GL_SPECULAR, v);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, frand(1.0f, 100.0f));
      }
      glVertex3f(c[0] + frand(-s, s), c[1] + frand(-s, s), c[2] + frand(-s, s));
    }
  }
  glEnd();
  glFinish();
}

static unsigned char color[3][W * H * 4];

/* draws scene `seed` in ctx and copies its colour and depth */
static void render(OSMesaContext ctx, unsigned char *buf, uint32_t seed, unsigned char *out,
                   unsigned char *depth, size_t *depth_bytes)
{
  if (!OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
    FAIL("OSMesaMakeCurrent");
    return;
  }
  draw_scene(seed);
  memcpy(out, buf, W * H * 4);
  GLint w = 0, h = 0, bpv = 0;
  void *z = NULL;
  if (!OSMesaGetDepthBuffer(ctx, &w, &h, &bpv, &z) || !z) {
    FAIL("OSMesaGetDepthBuffer");
    *depth_bytes = 0;
    return;
  }
  *depth_bytes = (size_t)w * (size_t)h * (size_t)bpv;
  memcpy(depth, z, *depth_bytes);
}

static unsigned char fb[3][2][W * H * 4];
static unsigned char depth[3][W * H * 4];

int main(int argc, char **argv)
{
  /* argv[1]: the number of scenes (default SCENES) */
  const uint32_t scenes = argc > 1 ? (uint32_t)strtoul(argv[1], NULL, 10) : SCENES;
  /* [kernels: default, reference, avx2][depth 16, 24] */
  OSMesaContext ctx[3][2];
  for (int k = 0; k < 3; k++) {
    if (k > 0)
      setenv("FIXGL_KERNELS", k == 1 ? "reference" : "avx2", 1);
    for (int z = 0; z < 2; z++) {
      ctx[k][z] = OSMesaCreateContextExt(OSMESA_RGBA, z ? 24 : 16, 0, 0, NULL);
      CHECK(ctx[k][z] != NULL, "context %d/%d", k, z);
    }
  }
  unsetenv("FIXGL_KERNELS");
  if (check_failures)
    return check_report("lit_kernels");

  int bad = 0;
  for (uint32_t s = 0; s < scenes && bad < 10; s++) {
    const int z = (int)(s & 1);
    size_t nb[3];
    for (int k = 0; k < 3; k++)
      render(ctx[k][z], fb[k][z], s, color[k], depth[k], &nb[k]);
    /* the default kernels, then FIXGL_KERNELS=avx2's, against the reference */
    for (int k = 0; k < 3; k += 2) {
      if (memcmp(color[k], color[1], sizeof color[k]) != 0) {
        for (int i = 0; i < W * H; i++) {
          if (memcmp(&color[k][4 * i], &color[1][4 * i], 4) != 0) {
            const unsigned char *a = &color[k][4 * i], *b = &color[1][4 * i];
            FAIL("scene %u (z%d, %s kernels): colour differs at (%d, %d): %u %u %u %u, reference "
                 "%u %u %u %u",
                 s, z ? 24 : 16, k ? "avx2" : "default", i % W, i / W, a[0], a[1], a[2], a[3],
                 b[0], b[1], b[2], b[3]);
            break;
          }
        }
        bad++;
      }
      CHECK(nb[k] == nb[1] && memcmp(depth[k], depth[1], nb[k]) == 0,
            "scene %u (%s kernels): depth differs", s, k ? "avx2" : "default");
    }
  }
  for (int k = 0; k < 3; k++)
    for (int z = 0; z < 2; z++)
      OSMesaDestroyContext(ctx[k][z]);
  return check_report("lit_kernels");
}
