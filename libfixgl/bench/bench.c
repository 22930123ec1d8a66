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
 *
 * Usage: fixgl-bench-* [SECONDS_PER_SCENE]   (default 2)
 * Output, one line per scene:  scene NAME fps X frames N checksum C
 * The checksum (FNV-1a of the last frame) tells whether both libraries drew
 * the same image.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define WIDTH 1024
#define HEIGHT 768
#define SOUP_TRIANGLES 10000
#define SPHERE_STACKS 100 /* 2 * STACKS * SLICES = 20,000 triangles */
#define SPHERE_SLICES 100
#define WARMUP_SECONDS 0.3

/* Vertex with colour, as the scenes submit it. */
struct vertex {
  float pos[3];
  float color[3];
};

static struct vertex soup[SOUP_TRIANGLES * 3];
static struct vertex sphere[SPHERE_STACKS * SPHERE_SLICES * 6];

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

static void submit(const struct vertex *v, int count)
{
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < count; i++) {
    glColor3fv(v[i].color);
    glVertex3fv(v[i].pos);
  }
  glEnd();
}

static void draw_soup(void)
{
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, WIDTH, 0.0, HEIGHT, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_FLAT);
  submit(soup, SOUP_TRIANGLES * 3);
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

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* FNV-1a over the colour buffer. */
static uint32_t checksum(const unsigned char *buf)
{
  uint32_t h = 2166136261u;
  for (size_t i = 0; i < (size_t)WIDTH * HEIGHT * 4; i++)
    h = (h ^ buf[i]) * 16777619u;
  return h;
}

/* Warms up, then counts whole frames until `seconds` have passed. */
static void run_scene(const char *name, void (*frame)(void), double seconds,
                      const unsigned char *buf)
{
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
         frames, (unsigned)checksum(buf));
  fflush(stdout);
}

int main(int argc, char **argv)
{
  double seconds = argc > 1 ? atof(argv[1]) : 2.0;
  if (!(seconds > 0.0)) {
    fprintf(stderr, "usage: %s [SECONDS_PER_SCENE]\n", argv[0]);
    return 2;
  }

  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  unsigned char *buf = malloc((size_t)WIDTH * HEIGHT * 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
    fprintf(stderr, "cannot create and bind a %dx%d OSMesa context\n", WIDTH, HEIGHT);
    return 1;
  }
  glViewport(0, 0, WIDTH, HEIGHT);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);

  build_soup();
  build_sphere();
  run_scene("soup", draw_soup, seconds, buf);
  run_scene("sphere", draw_sphere, seconds, buf);

  GLenum err = glGetError();
  OSMesaDestroyContext(ctx);
  free(buf);
  if (err != GL_NO_ERROR) {
    fprintf(stderr, "GL error 0x%x\n", err);
    return 1;
  }
  return 0;
}
