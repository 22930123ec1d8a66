/*
 * bench.c - frames per second of immediate-mode scenes through OSMesa.
 *
 * Built twice from this one source: against libfixgl (fixgl-bench-fixgl)
 * and against the system OSMesa (fixgl-bench-osmesa). run-bench.sh runs
 * both and prints the comparison table; `./fixgl bench` calls it.
 *
 * Every frame is glClear + all geometry re-submitted with glBegin/glEnd +
 * glFinish, at 1024x768 RGBA with a 24-bit depth buffer. After a warm-up,
 * frames are counted for a fixed wall-clock budget (CLOCK_MONOTONIC).
 *
 * Scenes:
 *   soup    10,000 random flat-coloured triangles, orthographic, depth test
 *   sphere  a smooth-coloured sphere of 20,000 triangles, perspective,
 *           depth test
 *   lit200  a smooth-shaded lit sphere of 200 triangles (glNormal3fv per
 *           vertex), one directional light with specular, perspective,
 *           depth test
 *   lit20k  the same sphere with 20,000 triangles
 *   gears   three gears as glxgears draws them (quad strips and quads, flat
 *           and smooth shading, glNormal3f), one directional light,
 *           GL_NORMALIZE, GL_CULL_FACE, depth test
 *   texfloor a 256x256 RGB texture with a full mipmap chain
 *           (GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT, GL_MODULATE) on a floor
 *           receding to the horizon plus a GL_LINEAR-textured wall, the
 *           whole screen textured, perspective, depth test
 *   phong   fixgl's per-fragment lighting (GL_PHONG_WIN, include/fixgl/
 *           shading.md): the 20,000-triangle sphere seen from close enough
 *           that its front half covers every pixel (back faces culled, so
 *           one lit fragment per pixel, 786,432 a frame), Blinn-Phong, a
 *           white directional light and a warm attenuated point light
 *   ctphong the same with GL_FIXGL_cook_torrance per fragment (a
 *           half-metallic material)
 *   ctsmooth the same Cook-Torrance per vertex (GL_SMOOTH)
 *   manydraws a legacy demo's frame: 240 small lit, textured cubes, each
 *           its own glBegin/glEnd after a glPushMatrix, glTranslatef,
 *           glRotatef, glScalef, glMaterialfv and glBindTexture (two
 *           textures: the texfloor one, mipmapped, and a 64x64 LINEAR one)
 *   lines   2,000 random smooth-coloured lines 3 pixels wide (up to ~300 px
 *           long, every orientation), orthographic, depth test
 *   points  10,000 random points of size 8, one colour each,
 *           orthographic, depth test
 *   lightmap the texfloor floor and wall with two texture units, as legacy
 *           demos light a level: unit 0 the texfloor texture
 *           (GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT, GL_MODULATE), unit 1 a
 *           64x64 RGB light map (GL_LINEAR, GL_CLAMP_TO_EDGE, GL_MODULATE)
 *           stretched over each quad, the whole screen textured
 *   stipple the lines scene's 2,000 lines stippled (glLineStipple(2,
 *           0x3f3f): dashes of 12 pixels, gaps of 4), 1 pixel wide as
 *           GL_LINE_STRIPs of 4 lines each (the stipple counter runs
 *           along a strip and restarts at each glBegin)
 * OSMesa has neither extension: for the last three scenes its build binds
 * the GLSL reference of the conformance suite (conformance/reference/
 * fcr_shading.c, through OSMesaGetProcAddress), which evaluates the same
 * equations on llvmpipe; the reference cases are bit-exact, so the frames
 * are the same.
 *
 * Usage: fixgl-bench-* [SECONDS_PER_SCENE [SCENE...]]   (default 2, every
 * scene)
 * FIXGL_BENCH_DUMP=DIR writes the check frame of each scene to DIR/NAME.ppm.
 * FIXGL_BENCH_FRAMES=N draws exactly N frames of each scene, without warm-up
 * or stats frames, then its check frames (a fixed amount of work for
 * callgrind or perf: N + CHECK_FRAMES frames a scene, the check frames in
 * a context of their own).
 * Output, one line per scene:  scene NAME fps X frames N checksum C
 * The checksum (FNV-1a of the scene's check frame) tells whether both
 * libraries drew the same image.  The check frame is not the last timed
 * frame: a frame of immediate-mode vertices depends on where the vbo's
 * 512 KiB vertex buffer wraps inside it (a line strip split there restarts
 * its stipple), i.e. on every vertex the context received before, so on
 * the frame counts of this and the earlier scenes, which the time budget
 * makes differ between the builds and between runs (the stipple scene's
 * last frame was another image in about one run of ten, on both
 * libraries alike).  So after the scene's timed frames a fresh context sharing
 * the textures draws CHECK_FRAMES frames of it (check_frame), the same
 * vertex stream in both builds whatever the clock did; the workers, the
 * textures and the user's buffer are the long run's.  The fixgl build
 * draws the middle one with its counters on, as the stats frames do.
 * The fixgl build adds a line per scene with fixgl's own
 * counters (fixglStats), from extra frames after the timed ones:
 *   stats NAME frames N frame_ns F fragments X setup_ns S raster_ns R
 *         vertex_ns V batch_ns B
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#ifdef BENCH_ORACLE
#include "fcr_shading.h"
#define BENCH_NAME "fixgl-bench-osmesa"
#else
#define BENCH_NAME "fixgl-bench-fixgl"
#include <fixgl/fixgl.h>
#endif

#include <fixgl/version.h>

#include <getopt.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define WIDTH 1024
#define HEIGHT 768
#define SOUP_TRIANGLES 10000
#define SPHERE_STACKS 100 /* 2 * STACKS * SLICES = 20,000 triangles */
#define SPHERE_SLICES 100
#define LIT_SMALL_STACKS 10 /* 200 triangles */
#define LIT_SMALL_SLICES 10
#define WARMUP_SECONDS 0.3

/* Vertex with colour, as the scenes submit it. */
struct vertex {
  float pos[3];
  float color[3];
};

static struct vertex soup[SOUP_TRIANGLES * 3];
#define LINES 2000
#define POINTS 10000
static struct vertex lines[LINES * 2];
static struct vertex points[POINTS];
static struct vertex sphere[SPHERE_STACKS * SPHERE_SLICES * 6];

/* Vertex with normal, for the lit scenes. */
struct lit_vertex {
  float pos[3];
  float normal[3];
};

static struct lit_vertex lit_small[LIT_SMALL_STACKS * LIT_SMALL_SLICES * 6];
static struct lit_vertex lit_large[SPHERE_STACKS * SPHERE_SLICES * 6];

/* Deterministic generator (xorshift32), so both builds draw the same soup. */
static uint32_t rng_state = 0x12345678u;
static float rand01(void)
{
  rng_state ^= rng_state << 13;
  rng_state ^= rng_state >> 17;
  rng_state ^= rng_state << 5;
  return (float)(rng_state >> 8) / 16777216.0f;
}

/* Small random triangles (up to ~50 px across) scattered over the screen, in
 * window coordinates, one flat colour each (the last vertex provokes). */
static void build_soup(void)
{
  for (int t = 0; t < SOUP_TRIANGLES; t++) {
    float cx = rand01() * WIDTH, cy = rand01() * HEIGHT;
    float r = rand01(), g = rand01(), b = rand01();
    for (int v = 0; v < 3; v++) {
      struct vertex *p = &soup[3 * t + v];
      p->pos[0] = cx + (rand01() - 0.5f) * 50.0f;
      p->pos[1] = cy + (rand01() - 0.5f) * 50.0f;
      p->pos[2] = rand01() * 2.0f - 1.0f;
      p->color[0] = r;
      p->color[1] = g;
      p->color[2] = b;
    }
  }
}

/* Lines of every orientation and length up to ~300 px, a colour per end,
 * and points, a colour each, scattered over the screen in window
 * coordinates. */
static void build_lines_points(void)
{
  for (int l = 0; l < LINES; l++) {
    const float cx = rand01() * WIDTH, cy = rand01() * HEIGHT;
    const float a = rand01() * 6.2831853f, len = 4.0f + rand01() * 300.0f;
    for (int v = 0; v < 2; v++) {
      struct vertex *p = &lines[2 * l + v];
      const float s = v ? 0.5f : -0.5f;
      p->pos[0] = cx + s * len * cosf(a);
      p->pos[1] = cy + s * len * sinf(a);
      p->pos[2] = rand01() * 2.0f - 1.0f;
      p->color[0] = rand01();
      p->color[1] = rand01();
      p->color[2] = rand01();
    }
  }
  for (int i = 0; i < POINTS; i++) {
    struct vertex *p = &points[i];
    p->pos[0] = rand01() * WIDTH;
    p->pos[1] = rand01() * HEIGHT;
    p->pos[2] = rand01() * 2.0f - 1.0f;
    p->color[0] = rand01();
    p->color[1] = rand01();
    p->color[2] = rand01();
  }
}

/* Unit sphere as a latitude/longitude grid, two triangles per cell, coloured
 * by the normal so that smooth shading varies everywhere. */
static void sphere_point(int stack, int slice, struct vertex *out)
{
  const float pi = 3.14159265f;
  float theta = pi * (float)stack / SPHERE_STACKS;
  float phi = 2.0f * pi * (float)slice / SPHERE_SLICES;
  float x = sinf(theta) * cosf(phi), y = cosf(theta), z = sinf(theta) * sinf(phi);
  out->pos[0] = x;
  out->pos[1] = y;
  out->pos[2] = z;
  out->color[0] = 0.5f + 0.5f * x;
  out->color[1] = 0.5f + 0.5f * y;
  out->color[2] = 0.5f + 0.5f * z;
}

static void build_sphere(void)
{
  struct vertex *v = sphere;
  for (int i = 0; i < SPHERE_STACKS; i++) {
    for (int j = 0; j < SPHERE_SLICES; j++) {
      struct vertex a, b, c, d;
      sphere_point(i, j, &a);
      sphere_point(i + 1, j, &b);
      sphere_point(i + 1, j + 1, &c);
      sphere_point(i, j + 1, &d);
      *v++ = a, *v++ = b, *v++ = c;
      *v++ = a, *v++ = c, *v++ = d;
    }
  }
}

/* Unit sphere with its normals, stacks x slices cells of two triangles. */
static void build_lit_sphere(struct lit_vertex *out, int stacks, int slices)
{
  const float pi = 3.14159265f;
  struct lit_vertex *v = out;
  for (int i = 0; i < stacks; i++) {
    for (int j = 0; j < slices; j++) {
      struct lit_vertex c[4];
      static const int di[4] = { 0, 1, 1, 0 }, dj[4] = { 0, 0, 1, 1 };
      for (int k = 0; k < 4; k++) {
        float theta = pi * (float)(i + di[k]) / (float)stacks;
        float phi = 2.0f * pi * (float)(j + dj[k]) / (float)slices;
        c[k].pos[0] = c[k].normal[0] = sinf(theta) * cosf(phi);
        c[k].pos[1] = c[k].normal[1] = cosf(theta);
        c[k].pos[2] = c[k].normal[2] = sinf(theta) * sinf(phi);
      }
      *v++ = c[0], *v++ = c[1], *v++ = c[2];
      *v++ = c[0], *v++ = c[2], *v++ = c[3];
    }
  }
}

/* glxgears' gear, recorded once and replayed with glBegin/glEnd every
 * frame (glxgears compiles it into a display list). */
enum { OP_BEGIN, OP_END, OP_NORMAL, OP_VERTEX, OP_SHADE };
struct op {
  int op;
  GLenum mode;
  float v[3];
};
#define GEAR_OPS 4096
static struct op gears_ops[3][GEAR_OPS];
static int gears_nops[3];
static struct op *rec;
static int *rec_n;

static void rec_op(int op, GLenum mode, double x, double y, double z)
{
  if (*rec_n >= GEAR_OPS) {
    fprintf(stderr, "bench: gear too large\n");
    exit(1);
  }
  struct op *o = &rec[(*rec_n)++];
  o->op = op;
  o->mode = mode;
  o->v[0] = (float)x, o->v[1] = (float)y, o->v[2] = (float)z;
}

#define G_BEGIN(m) rec_op(OP_BEGIN, m, 0, 0, 0)
#define G_END() rec_op(OP_END, 0, 0, 0, 0)
#define G_NORMAL(x, y, z) rec_op(OP_NORMAL, 0, x, y, z)
#define G_VERTEX(x, y, z) rec_op(OP_VERTEX, 0, x, y, z)
#define G_SHADE(m) rec_op(OP_SHADE, m, 0, 0, 0)

static void build_gear(int which, double inner_radius, double outer_radius, double width,
                       int teeth, double tooth_depth)
{
  const double pi = 3.14159265358979323846;
  double r0 = inner_radius, r1 = outer_radius - tooth_depth / 2.0;
  double r2 = outer_radius + tooth_depth / 2.0, da = 2.0 * pi / teeth / 4.0;
  double angle, u, v, len;
  rec = gears_ops[which];
  rec_n = &gears_nops[which];

  G_SHADE(GL_FLAT);
  G_NORMAL(0.0, 0.0, 1.0);
  G_BEGIN(GL_QUAD_STRIP);                        /* front face */
  for (int i = 0; i <= teeth; i++) {
    angle = i * 2.0 * pi / teeth;
    G_VERTEX(r0 * cos(angle), r0 * sin(angle), width * 0.5);
    G_VERTEX(r1 * cos(angle), r1 * sin(angle), width * 0.5);
    if (i < teeth) {
      G_VERTEX(r0 * cos(angle), r0 * sin(angle), width * 0.5);
      G_VERTEX(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), width * 0.5);
    }
  }
  G_END();
  G_BEGIN(GL_QUADS);                             /* front sides of teeth */
  for (int i = 0; i < teeth; i++) {
    angle = i * 2.0 * pi / teeth;
    G_VERTEX(r1 * cos(angle), r1 * sin(angle), width * 0.5);
    G_VERTEX(r2 * cos(angle + da), r2 * sin(angle + da), width * 0.5);
    G_VERTEX(r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), width * 0.5);
    G_VERTEX(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), width * 0.5);
  }
  G_END();
  G_NORMAL(0.0, 0.0, -1.0);
  G_BEGIN(GL_QUAD_STRIP);                        /* back face */
  for (int i = 0; i <= teeth; i++) {
    angle = i * 2.0 * pi / teeth;
    G_VERTEX(r1 * cos(angle), r1 * sin(angle), -width * 0.5);
    G_VERTEX(r0 * cos(angle), r0 * sin(angle), -width * 0.5);
    if (i < teeth) {
      G_VERTEX(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), -width * 0.5);
      G_VERTEX(r0 * cos(angle), r0 * sin(angle), -width * 0.5);
    }
  }
  G_END();
  G_BEGIN(GL_QUADS);                             /* back sides of teeth */
  for (int i = 0; i < teeth; i++) {
    angle = i * 2.0 * pi / teeth;
    G_VERTEX(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), -width * 0.5);
    G_VERTEX(r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), -width * 0.5);
    G_VERTEX(r2 * cos(angle + da), r2 * sin(angle + da), -width * 0.5);
    G_VERTEX(r1 * cos(angle), r1 * sin(angle), -width * 0.5);
  }
  G_END();
  G_BEGIN(GL_QUAD_STRIP);                        /* outward faces of teeth */
  for (int i = 0; i < teeth; i++) {
    angle = i * 2.0 * pi / teeth;
    G_VERTEX(r1 * cos(angle), r1 * sin(angle), width * 0.5);
    G_VERTEX(r1 * cos(angle), r1 * sin(angle), -width * 0.5);
    u = r2 * cos(angle + da) - r1 * cos(angle);
    v = r2 * sin(angle + da) - r1 * sin(angle);
    len = sqrt(u * u + v * v);
    u /= len;
    v /= len;
    G_NORMAL(v, -u, 0.0);
    G_VERTEX(r2 * cos(angle + da), r2 * sin(angle + da), width * 0.5);
    G_VERTEX(r2 * cos(angle + da), r2 * sin(angle + da), -width * 0.5);
    G_NORMAL(cos(angle), sin(angle), 0.0);
    G_VERTEX(r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), width * 0.5);
    G_VERTEX(r2 * cos(angle + 2 * da), r2 * sin(angle + 2 * da), -width * 0.5);
    u = r1 * cos(angle + 3 * da) - r2 * cos(angle + 2 * da);
    v = r1 * sin(angle + 3 * da) - r2 * sin(angle + 2 * da);
    G_NORMAL(v, -u, 0.0);                        /* not unit: GL_NORMALIZE */
    G_VERTEX(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), width * 0.5);
    G_VERTEX(r1 * cos(angle + 3 * da), r1 * sin(angle + 3 * da), -width * 0.5);
    G_NORMAL(cos(angle), sin(angle), 0.0);
  }
  G_VERTEX(r1 * cos(0.0), r1 * sin(0.0), width * 0.5);
  G_VERTEX(r1 * cos(0.0), r1 * sin(0.0), -width * 0.5);
  G_END();
  G_SHADE(GL_SMOOTH);
  G_BEGIN(GL_QUAD_STRIP);                        /* inside radius cylinder */
  for (int i = 0; i <= teeth; i++) {
    angle = i * 2.0 * pi / teeth;
    G_NORMAL(-cos(angle), -sin(angle), 0.0);
    G_VERTEX(r0 * cos(angle), r0 * sin(angle), -width * 0.5);
    G_VERTEX(r0 * cos(angle), r0 * sin(angle), width * 0.5);
  }
  G_END();
}

static void replay_gear(int which)
{
  const struct op *o = gears_ops[which];
  for (int i = 0; i < gears_nops[which]; i++, o++) {
    switch (o->op) {
    case OP_BEGIN: glBegin(o->mode); break;
    case OP_END: glEnd(); break;
    case OP_NORMAL: glNormal3f(o->v[0], o->v[1], o->v[2]); break;
    case OP_VERTEX: glVertex3f(o->v[0], o->v[1], o->v[2]); break;
    default: glShadeModel(o->mode); break;
    }
  }
}

static void build_gears(void)
{
  build_gear(0, 1.0, 4.0, 1.0, 20, 0.7);
  build_gear(1, 0.5, 2.0, 2.0, 10, 0.7);
  build_gear(2, 1.3, 2.0, 0.5, 10, 0.7);
}

static void submit(const struct vertex *v, int count)
{
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < count; i++) {
    glColor3fv(v[i].color);
    glVertex3fv(v[i].pos);
  }
  glEnd();
}

/* A cleared frame with window-sized orthographic coordinates. */
static void begin_ortho_frame(GLenum shade_model)
{
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(shade_model);
}

static void draw_soup(void)
{
  begin_ortho_frame(GL_FLAT);
  submit(soup, SOUP_TRIANGLES * 3);
  glFinish();
}

static void submit_prims(GLenum mode, const struct vertex *v, int count)
{
  glBegin(mode);
  for (int i = 0; i < count; i++) {
    glColor3fv(v[i].color);
    glVertex3fv(v[i].pos);
  }
  glEnd();
}

static void draw_lines_points(GLenum mode)
{
  begin_ortho_frame(GL_SMOOTH);
  if (mode == GL_LINES) {
    glLineWidth(3.0f);
    submit_prims(GL_LINES, lines, LINES * 2);
    glLineWidth(1.0f);
  } else {
    glPointSize(8.0f);
    submit_prims(GL_POINTS, points, POINTS);
    glPointSize(1.0f);
  }
  glFinish();
}

static void draw_lines(void)
{
  draw_lines_points(GL_LINES);
}

static void draw_points(void)
{
  draw_lines_points(GL_POINTS);
}

static void draw_stipple(void)
{
  begin_ortho_frame(GL_SMOOTH);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x3f3f);
  for (int i = 0; i < LINES; i += 4) {
    glBegin(GL_LINE_STRIP);
    for (int k = 0; k < 5; k++) {
      glColor3fv(lines[2 * i + k].color);
      glVertex3fv(lines[2 * i + k].pos);
    }
    glEnd();
  }
  glDisable(GL_LINE_STIPPLE);
  glFinish();
}

static void draw_sphere(void)
{
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.48, 0.48, -0.36, 0.36, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.0f);
  glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
  glShadeModel(GL_SMOOTH);
  submit(sphere, SPHERE_STACKS * SPHERE_SLICES * 6);
  glFinish();
}

static void submit_lit(const struct lit_vertex *v, int count)
{
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < count; i++) {
    glNormal3fv(v[i].normal);
    glVertex3fv(v[i].pos);
  }
  glEnd();
}

/* One directional light with specular on a shiny orange material; the
 * modelview is a translation and a rotation (llvmpipe lights such a scene
 * in object space). Lighting is switched off again for the other scenes. */
static void draw_lit_sphere(const struct lit_vertex *v, int count)
{
  static const GLfloat light_pos[4] = { 1.0f, 1.0f, 2.0f, 0.0f };
  static const GLfloat white[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
  static const GLfloat diffuse[4] = { 0.9f, 0.5f, 0.2f, 1.0f };
  static const GLfloat ambient[4] = { 0.3f, 0.15f, 0.05f, 1.0f };
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.48, 0.48, -0.36, 0.36, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glTranslatef(0.0f, 0.0f, -3.0f);
  glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
  glShadeModel(GL_SMOOTH);
  submit_lit(v, count);
  glDisable(GL_LIGHTING);
  glFinish();
}

static void draw_lit200(void)
{
  draw_lit_sphere(lit_small, LIT_SMALL_STACKS * LIT_SMALL_SLICES * 6);
}

static void draw_lit20k(void)
{
  draw_lit_sphere(lit_large, SPHERE_STACKS * SPHERE_SLICES * 6);
}

/* glxgears' frame, at a fixed gear angle (the last frame is compared). */
static void draw_gears(void)
{
  static const GLfloat pos[4] = { 5.0f, 5.0f, 10.0f, 0.0f };
  static const GLfloat red[4] = { 0.8f, 0.1f, 0.0f, 1.0f };
  static const GLfloat green[4] = { 0.0f, 0.8f, 0.2f, 1.0f };
  static const GLfloat blue[4] = { 0.2f, 0.2f, 1.0f, 1.0f };
  const GLfloat angle = 12.0f;
  const double h = (double)HEIGHT / (double)WIDTH;

  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -h, h, 5.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glEnable(GL_CULL_FACE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glTranslatef(0.0f, 0.0f, -40.0f);
  glPushMatrix();
  glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
  glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
  glRotatef(0.0f, 0.0f, 0.0f, 1.0f);

  glPushMatrix();
  glTranslatef(-3.0f, -2.0f, 0.0f);
  glRotatef(angle, 0.0f, 0.0f, 1.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  replay_gear(0);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(3.1f, -2.0f, 0.0f);
  glRotatef(-2.0f * angle - 9.0f, 0.0f, 0.0f, 1.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
  replay_gear(1);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-3.1f, 4.2f, 0.0f);
  glRotatef(-2.0f * angle - 25.0f, 0.0f, 0.0f, 1.0f);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
  replay_gear(2);
  glPopMatrix();

  glPopMatrix();
  glDisable(GL_NORMALIZE);
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glShadeModel(GL_SMOOTH);
  glFinish();
}

/* The texfloor scene's texture: a checker with a colour ramp, every level
 * built by hand as the 2x2 box average of the one above. */
#define TEX_SIZE 256
static GLuint tex_name;
static void build_texture(void)
{
  static unsigned char level[2][TEX_SIZE * TEX_SIZE * 3];
  int w = TEX_SIZE, cur = 0;
  for (int y = 0; y < TEX_SIZE; y++)
    for (int x = 0; x < TEX_SIZE; x++) {
      unsigned char *t = &level[0][(y * TEX_SIZE + x) * 3];
      const int on = ((x / 16) ^ (y / 16)) & 1;
      t[0] = (unsigned char)(on ? 230 : x);
      t[1] = (unsigned char)(on ? 200 : y);
      t[2] = (unsigned char)(on ? 120 : 255 - x);
    }
  glGenTextures(1, &tex_name);
  glBindTexture(GL_TEXTURE_2D, tex_name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int l = 0;; l++) {
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGB, w, w, 0, GL_RGB, GL_UNSIGNED_BYTE, level[cur]);
    if (w == 1)
      break;
    const int n = w / 2;
    for (int y = 0; y < n; y++)
      for (int x = 0; x < n; x++)
        for (int c = 0; c < 3; c++) {
          const unsigned char *a = level[cur];
          level[1 - cur][(y * n + x) * 3 + c] =
              (unsigned char)((a[((2 * y) * w + 2 * x) * 3 + c] + a[((2 * y) * w + 2 * x + 1) * 3 + c] +
                               a[((2 * y + 1) * w + 2 * x) * 3 + c] +
                               a[((2 * y + 1) * w + 2 * x + 1) * 3 + c]) / 4);
        }
    cur = 1 - cur;
    w = n;
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, 0);
}

static void draw_texfloor(void)
{
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.4, 0.4, -0.3, 0.3, 0.5, 200.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -1.0f, 0.0f);
  glBindTexture(GL_TEXTURE_2D, tex_name);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_QUADS);
  glColor3f(1.0f, 0.9f, 0.8f);
  glTexCoord2f(0.0f, 0.0f);   glVertex3f(-40.0f, 0.0f, -0.5f);
  glTexCoord2f(20.0f, 0.0f);  glVertex3f(40.0f, 0.0f, -0.5f);
  glTexCoord2f(20.0f, 40.0f); glVertex3f(40.0f, 0.0f, -100.0f);
  glTexCoord2f(0.0f, 40.0f);  glVertex3f(-40.0f, 0.0f, -100.0f);
  glColor3f(0.8f, 0.9f, 1.0f);
  glTexCoord2f(0.0f, 0.0f);   glVertex3f(-40.0f, 0.0f, -100.0f);
  glTexCoord2f(20.0f, 0.0f);  glVertex3f(40.0f, 0.0f, -100.0f);
  glTexCoord2f(20.0f, 10.0f); glVertex3f(40.0f, 60.0f, -100.0f);
  glTexCoord2f(0.0f, 10.0f);  glVertex3f(-40.0f, 60.0f, -100.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glFinish();
}

/* The lightmap scene's light map: a dark ambient with a few soft
 * round lights, RGB. */
#define LIGHTMAP_SIZE 64
static GLuint tex_lightmap;
static void build_lightmap(void)
{
  static unsigned char t[LIGHTMAP_SIZE * LIGHTMAP_SIZE * 3];
  static const float lights[4][5] = {
    /* x, y, radius, warm, cool */
    { 16, 20, 14, 1.0f, 0.7f }, { 44, 12, 10, 0.6f, 1.0f },
    { 36, 44, 18, 1.0f, 0.9f }, { 8, 54, 8, 0.9f, 0.5f },
  };
  for (int y = 0; y < LIGHTMAP_SIZE; y++)
    for (int x = 0; x < LIGHTMAP_SIZE; x++) {
      float c[3] = { 0.15f, 0.15f, 0.2f };
      for (int l = 0; l < 4; l++) {
        const float dx = (float)x - lights[l][0], dy = (float)y - lights[l][1];
        float f = 1.0f - sqrtf(dx * dx + dy * dy) / lights[l][2];
        if (f > 0.0f) {
          c[0] += f * lights[l][3];
          c[1] += f * 0.5f * (lights[l][3] + lights[l][4]);
          c[2] += f * lights[l][4];
        }
      }
      for (int k = 0; k < 3; k++)
        t[(y * LIGHTMAP_SIZE + x) * 3 + k] = (unsigned char)(c[k] > 1.0f ? 255 : c[k] * 255.0f);
    }
  glGenTextures(1, &tex_lightmap);
  glBindTexture(GL_TEXTURE_2D, tex_lightmap);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, LIGHTMAP_SIZE, LIGHTMAP_SIZE, 0, GL_RGB,
               GL_UNSIGNED_BYTE, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
}

static void lightmap_vertex(float s, float t, float u, float v, float x, float y, float z)
{
  glMultiTexCoord2f(GL_TEXTURE0, s, t);
  glMultiTexCoord2f(GL_TEXTURE1, u, v);
  glVertex3f(x, y, z);
}

static void draw_lightmap(void)
{
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.4, 0.4, -0.3, 0.3, 0.5, 200.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, -1.0f, 0.0f);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex_name);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, tex_lightmap);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBegin(GL_QUADS);
  glColor3f(1.0f, 0.95f, 0.9f);
  lightmap_vertex(0.0f, 0.0f, 0.0f, 0.0f, -40.0f, 0.0f, -0.5f);
  lightmap_vertex(20.0f, 0.0f, 1.0f, 0.0f, 40.0f, 0.0f, -0.5f);
  lightmap_vertex(20.0f, 40.0f, 1.0f, 1.0f, 40.0f, 0.0f, -100.0f);
  lightmap_vertex(0.0f, 40.0f, 0.0f, 1.0f, -40.0f, 0.0f, -100.0f);
  lightmap_vertex(0.0f, 0.0f, 0.0f, 0.0f, -40.0f, 0.0f, -100.0f);
  lightmap_vertex(20.0f, 0.0f, 1.0f, 0.0f, 40.0f, 0.0f, -100.0f);
  lightmap_vertex(20.0f, 10.0f, 1.0f, 1.0f, 40.0f, 60.0f, -100.0f);
  lightmap_vertex(0.0f, 10.0f, 0.0f, 1.0f, -40.0f, 60.0f, -100.0f);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_2D);
  glFinish();
}

/* The manydraws scene: a legacy demo's frame of many small objects, each
 * its own glBegin/glEnd with the matrix, the material and the texture
 * changed before it.  MANY_X * MANY_Y textured, lit cubes. */
#define MANY_X 20
#define MANY_Y 12
static GLuint tex_small;
static void build_small_texture(void)
{
  static unsigned char t[64 * 64 * 4];
  for (int y = 0; y < 64; y++)
    for (int x = 0; x < 64; x++) {
      unsigned char *p = &t[(y * 64 + x) * 4];
      const int on = ((x / 8) ^ (y / 8)) & 1;
      p[0] = (unsigned char)(on ? 255 : 4 * x);
      p[1] = (unsigned char)(on ? 240 : 60);
      p[2] = (unsigned char)(on ? 200 : 4 * y);
      p[3] = 255;
    }
  glGenTextures(1, &tex_small);
  glBindTexture(GL_TEXTURE_2D, tex_small);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, 0);
}

static void draw_manydraws(void)
{
  static const GLfloat pos[4] = { -2.0f, 3.0f, 4.0f, 0.0f };
  static const GLfloat palette[4][4] = {
    { 0.9f, 0.3f, 0.2f, 1.0f }, { 0.3f, 0.8f, 0.3f, 1.0f },
    { 0.3f, 0.4f, 0.9f, 1.0f }, { 0.9f, 0.8f, 0.3f, 1.0f },
  };
  static const GLfloat spec[4] = { 0.6f, 0.6f, 0.6f, 1.0f };
  /* the faces of a unit cube: normal, then 4 corners */
  static const float face[6][5][3] = {
    { { 0, 0, 1 }, { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } },
    { { 0, 0, -1 }, { 1, -1, -1 }, { -1, -1, -1 }, { -1, 1, -1 }, { 1, 1, -1 } },
    { { 1, 0, 0 }, { 1, -1, 1 }, { 1, -1, -1 }, { 1, 1, -1 }, { 1, 1, 1 } },
    { { -1, 0, 0 }, { -1, -1, -1 }, { -1, -1, 1 }, { -1, 1, 1 }, { -1, 1, -1 } },
    { { 0, 1, 0 }, { -1, 1, 1 }, { 1, 1, 1 }, { 1, 1, -1 }, { -1, 1, -1 } },
    { { 0, -1, 0 }, { -1, -1, -1 }, { 1, -1, -1 }, { 1, -1, 1 }, { -1, -1, 1 } },
  };
  static const float st[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };

  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 100.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 24.0f);
  glTranslatef(0.0f, 0.0f, -24.0f);
  for (int j = 0; j < MANY_Y; j++)
    for (int i = 0; i < MANY_X; i++) {
      const int n = j * MANY_X + i;
      glPushMatrix();
      glTranslatef(-19.0f + 2.0f * (float)i, -11.0f + 2.0f * (float)j, 0.0f);
      glRotatef(17.0f * (float)n, 0.4f, 1.0f, 0.2f);
      glScalef(0.7f, 0.7f, 0.7f);
      glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, palette[n & 3]);
      glBindTexture(GL_TEXTURE_2D, (n % 3) ? tex_small : tex_name);
      glBegin(GL_QUADS);
      for (int f = 0; f < 6; f++) {
        glNormal3fv(face[f][0]);
        for (int k = 0; k < 4; k++) {
          glTexCoord2fv(st[k]);
          glVertex3fv(face[f][1 + k]);
        }
      }
      glEnd();
      glPopMatrix();
    }
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_LIGHTING);
  glFinish();
}

/* The shading scenes (phong, ctphong, ctsmooth): lit_large from 1.9 units
 * with a 0.48 x 0.36 window at 0.5, so that the silhouette (half-angle
 * tangent 0.619) encloses the screen's corners (0.6); back faces culled. */
enum shading { SHADE_PHONG, SHADE_CT_PHONG, SHADE_CT_SMOOTH };

#ifdef BENCH_ORACLE
static struct fcr *reference;
#endif

static void draw_shading(enum shading mode)
{
  static const GLfloat sun_pos[4] = { 1.0f, 1.0f, 2.0f, 0.0f };
  static const GLfloat lamp_pos[4] = { -1.5f, 0.8f, -0.5f, 1.0f };
  static const GLfloat white[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
  static const GLfloat black[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
  static const GLfloat warm[4] = { 1.0f, 0.7f, 0.4f, 1.0f };
  static const GLfloat diffuse[4] = { 0.9f, 0.5f, 0.2f, 1.0f };
  static const GLfloat ambient[4] = { 0.3f, 0.15f, 0.05f, 1.0f };
  const int cook_torrance = mode != SHADE_PHONG;
  const int per_fragment = mode != SHADE_CT_SMOOTH;
#ifdef BENCH_ORACLE
  const struct fcr_face face = { cook_torrance, 0.35f, 0.5f, 0.04f };
#endif

  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.24, 0.24, -0.18, 0.18, 0.5, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, sun_pos);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glLightfv(GL_LIGHT1, GL_POSITION, lamp_pos);
  glLightfv(GL_LIGHT1, GL_AMBIENT, black);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
  glLightfv(GL_LIGHT1, GL_SPECULAR, warm);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.25f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_CULL_FACE);
  glFrontFace(GL_CW);   /* build_lit_sphere winds clockwise seen from outside */
  glShadeModel(GL_SMOOTH);
#ifdef BENCH_ORACLE
  if (!reference && !(reference = fcr_create((fcr_getproc)OSMesaGetProcAddress))) {
    fprintf(stderr, "bench: the GLSL reference is not available\n");
    exit(1);
  }
  if (!fcr_bind(reference, per_fragment, &face, &face)) {
    fprintf(stderr, "bench: the GLSL reference does not bind\n");
    exit(1);
  }
#else
  glMateriali(GL_FRONT_AND_BACK, GL_REFLECTANCE_MODEL_FIXGL,
              cook_torrance ? GL_COOK_TORRANCE_FIXGL : GL_BLINN_PHONG_FIXGL);
  glMaterialf(GL_FRONT_AND_BACK, GL_ROUGHNESS_FIXGL, 0.35f);
  glMaterialf(GL_FRONT_AND_BACK, GL_METALNESS_FIXGL, 0.5f);
  glMaterialf(GL_FRONT_AND_BACK, GL_DIELECTRIC_F0_FIXGL, 0.04f);
  if (per_fragment)
    glShadeModel(GL_PHONG_WIN);
#endif
  glTranslatef(0.0f, 0.0f, -1.9f);
  glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
  submit_lit(lit_large, SPHERE_STACKS * SPHERE_SLICES * 6);
#ifdef BENCH_ORACLE
  fcr_unbind(reference);
#else
  glMateriali(GL_FRONT_AND_BACK, GL_REFLECTANCE_MODEL_FIXGL, GL_BLINN_PHONG_FIXGL);
#endif
  glShadeModel(GL_SMOOTH);
  glFrontFace(GL_CCW);
  glDisable(GL_CULL_FACE);
  glDisable(GL_LIGHT1);
  glDisable(GL_LIGHTING);
  glFinish();
}

static void draw_phong(void)
{
  draw_shading(SHADE_PHONG);
}

static void draw_ctphong(void)
{
  draw_shading(SHADE_CT_PHONG);
}

static void draw_ctsmooth(void)
{
  draw_shading(SHADE_CT_SMOOTH);
}

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The state every scene starts from (the bench's context and the check
 * contexts). */
static void init_state(void)
{
  glViewport(0, 0, WIDTH, HEIGHT);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
}

/* FNV-1a over the colour buffer. */
static uint32_t checksum(const unsigned char *buf)
{
  uint32_t h = 2166136261u;
  for (size_t i = 0; i < (size_t)WIDTH * HEIGHT * 4; i++)
    h = (h ^ buf[i]) * 16777619u;
  return h;
}

/* FIXGL_BENCH_DUMP=DIR: the frame as DIR/NAME.ppm, top row first. */
static void dump(const char *name, const unsigned char *buf)
{
  const char *dir = getenv("FIXGL_BENCH_DUMP");
  char path[1024];
  FILE *f;
  if (!dir)
    return;
  snprintf(path, sizeof path, "%s/%s.ppm", dir, name);
  if (!(f = fopen(path, "wb"))) {
    perror(path);
    return;
  }
  fprintf(f, "P6\n%d %d\n255\n", WIDTH, HEIGHT);
  for (int y = HEIGHT - 1; y >= 0; y--)
    for (int x = 0; x < WIDTH; x++)
      fwrite(buf + 4 * ((size_t)y * WIDTH + (size_t)x), 1, 3, f);
  fclose(f);
}

#ifndef BENCH_ORACLE
/* fixgl only: the breakdown of a frame, from more frames drawn with
 * fixgl's counters on (fixglStats; the timed frames ran with them off, so
 * the fps are those of the library as applications use it).  At least
 * STATS_MIN_FRAMES frames, and a quarter of the timed budget.  Prints
 *   stats NAME frames N frame_ns F fragments X setup_ns S raster_ns R
 *         vertex_ns V batch_ns B
 * with totals over the N frames; F is their wall-clock time. */
#define STATS_MIN_FRAMES 3
static void stats_frames(const char *name, void (*frame)(void), double seconds)
{
  struct fixgl_stats st;
  long frames = 0;
  fixglStats(1);
  fixglResetStats();
  const double start = now();
  double elapsed;
  do {
    frame();
    frames++;
    elapsed = now() - start;
  } while (frames < STATS_MIN_FRAMES || elapsed < 0.25 * seconds);
  fixglGetStats(&st);
  fixglStats(0);
  printf("stats %s frames %ld frame_ns %.0f fragments %llu setup_ns %llu raster_ns %llu "
         "vertex_ns %llu batch_ns %llu\n",
         name, frames, elapsed * 1e9, st.fragments, st.setup_ns, st.raster_ns, st.vertex_ns,
         st.batch_ns);
  fflush(stdout);
}
#endif

/* The scene's check frame (the file's head comment): CHECK_FRAMES frames
 * of it in a new context that shares the objects of the current one (the
 * textures), with the state main() gives the bench's context; its
 * checksum, and DIR/NAME.ppm under FIXGL_BENCH_DUMP.  The current context
 * is bound again after. */
#define CHECK_FRAMES 3
static uint32_t check_frame(const char *name, void (*frame)(void), unsigned char *buf)
{
  OSMesaContext ctx = OSMesaGetCurrentContext();
  OSMesaContext check = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, ctx);
  if (!check || !OSMesaMakeCurrent(check, buf, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
    fprintf(stderr, "bench: cannot create and bind the check context\n");
    exit(1);
  }
  init_state();
#ifdef BENCH_ORACLE
  /* the GLSL reference's objects are the bench context's: a new one here */
  struct fcr *const saved = reference;
  reference = NULL;
#endif
  for (int i = 0; i < CHECK_FRAMES; i++) {
#ifndef BENCH_ORACLE
    fixglStats(i == CHECK_FRAMES / 2);
#endif
    frame();
  }
  const uint32_t sum = checksum(buf);
  dump(name, buf);
  const GLenum err = glGetError();
#ifdef BENCH_ORACLE
  if (reference)
    fcr_destroy(reference);
  reference = saved;
#endif
  if (err != GL_NO_ERROR) {
    fprintf(stderr, "bench: GL error 0x%x in the check frames of %s\n", err, name);
    exit(1);
  }
  if (!OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
    fprintf(stderr, "bench: cannot bind the bench context again\n");
    exit(1);
  }
  OSMesaDestroyContext(check);
  return sum;
}

/* Warms up, then counts whole frames until `seconds` have passed. */
static void run_scene(const char *name, void (*frame)(void), double seconds,
                      unsigned char *buf)
{
  /* FIXGL_BENCH_FRAMES=N: exactly N frames, no warm-up and no stats
   * frames (for instruction counts under callgrind, or perf on a fixed
   * amount of work) */
  const char *fixed = getenv("FIXGL_BENCH_FRAMES");
  if (fixed && atol(fixed) > 0) {
    const long n = atol(fixed);
    const double t0 = now();
    for (long i = 0; i < n; i++)
      frame();
    const double el = now() - t0;
    printf("scene %s fps %.2f frames %ld checksum %08x\n", name, (double)n / el, n,
           (unsigned)check_frame(name, frame, buf));
    fflush(stdout);
    return;
  }
  double start = now();
  do
    frame();
  while (now() - start < WARMUP_SECONDS);

  long frames = 0;
  start = now();
  double elapsed;
  do {
    frame();
    frames++;
    elapsed = now() - start;
  } while (elapsed < seconds);
  printf("scene %s fps %.2f frames %ld checksum %08x\n", name, (double)frames / elapsed,
         frames, (unsigned)check_frame(name, frame, buf));
  fflush(stdout);
#ifndef BENCH_ORACLE
  stats_frames(name, frame, seconds);
#endif
}

int main(int argc, char **argv)
{
  /* [--seconds S] [SECONDS] [SCENE...]: the seconds per scene as an option
   * or, as run-bench.sh gives it, the first operand when it is a number */
  static const struct option longopts[] = {
    { "seconds", required_argument, NULL, 's' },
    { "version", no_argument, NULL, 'V' },
    { "help", no_argument, NULL, 'h' },
    { NULL, 0, NULL, 0 },
  };
  double seconds = 2.0;
  int ch, bad = 0;
#define BENCH_USAGE "usage: %s [--seconds S | SECONDS] [SCENE...]   (S seconds per scene, default 2;\n" \
                    "       --opt=value as well) | --version\n"
  char *end;
  while ((ch = getopt_long(argc, argv, "h", longopts, NULL)) != -1) {
    switch (ch) {
    case 's': seconds = strtod(optarg, &end); bad |= *end != 0; break;
    case 'V': puts(FIXGL_VERSION_BANNER(BENCH_NAME)); return 0;
    case 'h': printf(BENCH_USAGE, argv[0]); return 0;
    default: bad = 1; break;
    }
  }
  if (optind < argc && strtod(argv[optind], &end) > 0.0 && *end == 0)
    seconds = strtod(argv[optind++], NULL);
  if (bad || !(seconds > 0.0)) {
    fprintf(stderr, BENCH_USAGE, argv[0]);
    return 2;
  }
  const int first_scene = optind;   /* the scenes asked for: the operands left */

  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  unsigned char *buf = malloc((size_t)WIDTH * HEIGHT * 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
    fprintf(stderr, "cannot create and bind a %dx%d OSMesa context\n", WIDTH, HEIGHT);
    return 1;
  }
  init_state();

  build_soup();
  build_sphere();
  build_lit_sphere(lit_small, LIT_SMALL_STACKS, LIT_SMALL_SLICES);
  build_lit_sphere(lit_large, SPHERE_STACKS, SPHERE_SLICES);
  build_gears();
  build_texture();
  build_small_texture();
  build_lines_points();
  build_lightmap();
  static const struct {
    const char *name;
    void (*frame)(void);
  } scenes[] = {
    { "soup", draw_soup },       { "sphere", draw_sphere },     { "lit200", draw_lit200 },
    { "lit20k", draw_lit20k },   { "gears", draw_gears },       { "texfloor", draw_texfloor },
    { "phong", draw_phong },     { "ctphong", draw_ctphong },   { "ctsmooth", draw_ctsmooth },
    { "manydraws", draw_manydraws }, { "lines", draw_lines },   { "points", draw_points },
    { "lightmap", draw_lightmap }, { "stipple", draw_stipple },
  };
  for (size_t i = 0; i < sizeof(scenes) / sizeof(scenes[0]); i++) {
    int wanted = first_scene >= argc;
    for (int a = first_scene; a < argc; a++)
      wanted |= strcmp(argv[a], scenes[i].name) == 0;
    if (wanted)
      run_scene(scenes[i].name, scenes[i].frame, seconds, buf);
  }

  GLenum err = glGetError();
#ifdef BENCH_ORACLE
  fcr_destroy(reference);
#endif
  OSMesaDestroyContext(ctx);
  free(buf);
  if (err != GL_NO_ERROR) {
    fprintf(stderr, "GL error 0x%x\n", err);
    return 1;
  }
  return 0;
}
