/*
 * stats.c - fixgl's counters for the benchmark (fixglStats, fixglResetStats,
 * fixglGetStats in include/fixgl/fixgl.h; fixgl only).
 *
 *   off          a new context counts nothing, and nothing is counted
 *                while the counters are off
 *   triangle     one triangle, (0,0) (32.5,0) (0,32.5) in window
 *                coordinates: no pixel centre is on an edge, so it covers
 *                exactly the 528 pixels with x + y <= 31 (checked on the
 *                image too); fragments is 528, one vertex batch, the
 *                times add up (with one thread, setup + raster <= batch -
 *                vertex: the raster core's time within the
 *                rasterization's), setup and raster times are counted
 *   scissor      the same triangle with the scissor box x < 16: 392
 *                fragments (only the pixels inside the draw region)
 *   accumulate   two frames count twice; fixglResetStats zeroes; the
 *                batched vertices are drawn by fixglGetStats itself
 *
 * The fragment count and the setup and raster times come from the raster
 * core's hooks (raster/r_state.h struct r_stats); this test fails until
 * the raster core adds to them.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <fixgl/fixgl.h>

#include <stdlib.h>
#include <string.h>

#include "check.h"

#define W 64
#define H 64
#define TRIANGLE_PIXELS 528   /* sum over s = 0..31 of (s + 1) */
#define SCISSOR_PIXELS 392    /* x < 16: sum over x = 0..15 of (32 - x) */

static unsigned char buf[W * H * 4];

static void draw_triangle(void)
{
  glBegin(GL_TRIANGLES);
  glVertex2f(0.0f, 0.0f);
  glVertex2f(32.5f, 0.0f);
  glVertex2f(0.0f, 32.5f);
  glEnd();
}

static void frame(void)
{
  glClear(GL_COLOR_BUFFER_BIT);
  draw_triangle();
  glFinish();
}

static int lit_pixels(void)
{
  int n = 0;
  for (int i = 0; i < W * H; i++)
    n += buf[4 * i] != 0;
  return n;
}

static struct fixgl_stats get(void)
{
  struct fixgl_stats s;
  memset(&s, 0xa5, sizeof s);
  fixglGetStats(&s);
  return s;
}

static void check_zero(const struct fixgl_stats *s, const char *what)
{
  CHECK(s->fragments == 0 && s->setup_ns == 0 && s->raster_ns == 0 && s->vertex_ns == 0 &&
            s->batch_ns == 0 && s->batches == 0,
        "%s: counters zero (fragments %llu, setup %llu ns, raster %llu ns, vertex %llu ns, "
        "batch %llu ns, %llu batches)",
        what, s->fragments, s->setup_ns, s->raster_ns, s->vertex_ns, s->batch_ns, s->batches);
}

/* The times of one set of counters are consistent. */
static void check_times(const struct fixgl_stats *s, const char *what)
{
  CHECK(s->batch_ns > 0, "%s: batch time counted", what);
  /* one rasterizing thread (FIXGL_NUM_THREADS=1, main): the raster
   * core's time fits in the rasterization's, the batch time less the
   * vertex stage's */
  CHECK(s->vertex_ns < s->batch_ns && s->setup_ns + s->raster_ns <= s->batch_ns - s->vertex_ns,
        "%s: vertex %llu, setup %llu + raster %llu ns, batch %llu ns", what, s->vertex_ns,
        s->setup_ns, s->raster_ns, s->batch_ns);
  CHECK(s->setup_ns > 0, "%s: setup time counted (raster core hook)", what);
  CHECK(s->raster_ns > 0, "%s: raster time counted (raster core hook)", what);
}

static void test_off(void)
{
  struct fixgl_stats s = get();
  check_zero(&s, "new context");
  CHECK(s.enabled == 0, "off by default");
  frame();
  s = get();
  check_zero(&s, "drawn with the counters off");
  CHECK(lit_pixels() == TRIANGLE_PIXELS, "the triangle covers %d pixels, expected %d",
        lit_pixels(), TRIANGLE_PIXELS);
}

static void test_triangle(void)
{
  fixglStats(1);
  fixglResetStats();
  CHECK(get().enabled == 1, "enabled");
  frame();
  struct fixgl_stats s = get();
  CHECK(lit_pixels() == TRIANGLE_PIXELS, "the triangle covers %d pixels, expected %d",
        lit_pixels(), TRIANGLE_PIXELS);
  CHECK(s.fragments == TRIANGLE_PIXELS, "fragments %llu, expected %d (raster core hook)",
        s.fragments, TRIANGLE_PIXELS);
  CHECK(s.batches == 1, "%llu batches, expected 1", s.batches);
  check_times(&s, "triangle");

  /* off again: nothing more is counted, the values stay */
  fixglStats(0);
  CHECK(get().enabled == 0, "disabled");
  frame();
  struct fixgl_stats t = get();
  CHECK(t.fragments == s.fragments && t.batches == s.batches && t.batch_ns == s.batch_ns &&
            t.vertex_ns == s.vertex_ns && t.setup_ns == s.setup_ns && t.raster_ns == s.raster_ns,
        "nothing counted while off");
}

static void test_scissor(void)
{
  fixglStats(1);
  fixglResetStats();
  glScissor(0, 0, 16, H);
  glClear(GL_COLOR_BUFFER_BIT);   /* the whole buffer: no scissor test yet */
  glEnable(GL_SCISSOR_TEST);
  draw_triangle();
  glFinish();
  glDisable(GL_SCISSOR_TEST);
  struct fixgl_stats s = get();
  CHECK(lit_pixels() == SCISSOR_PIXELS, "the scissored triangle covers %d pixels, expected %d",
        lit_pixels(), SCISSOR_PIXELS);
  CHECK(s.fragments == SCISSOR_PIXELS, "scissor: fragments %llu, expected %d (raster core hook)",
        s.fragments, SCISSOR_PIXELS);
  CHECK(s.batches == 1, "scissor: %llu batches, expected 1", s.batches);
  fixglStats(0);
}

static void test_accumulate(void)
{
  fixglStats(1);
  fixglResetStats();
  frame();
  frame();
  struct fixgl_stats s = get();
  CHECK(s.fragments == 2 * TRIANGLE_PIXELS, "two frames: fragments %llu, expected %d",
        s.fragments, 2 * TRIANGLE_PIXELS);
  CHECK(s.batches == 2, "two frames: %llu batches, expected 2", s.batches);
  check_times(&s, "two frames");

  fixglResetStats();
  s = get();
  check_zero(&s, "after fixglResetStats");
  CHECK(s.enabled == 1, "still enabled after fixglResetStats");

  /* no glFinish: fixglGetStats draws the batched triangle itself */
  draw_triangle();
  s = get();
  CHECK(s.batches == 1, "batched vertices: %llu batches, expected 1", s.batches);
  CHECK(s.fragments == TRIANGLE_PIXELS, "batched vertices: fragments %llu, expected %d",
        s.fragments, TRIANGLE_PIXELS);
  fixglStats(0);
}

int main(void)
{
  /* one rasterizing thread: the raster core's time is the rasterization's */
  setenv("FIXGL_NUM_THREADS", "1", 1);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
    FAIL("cannot create and bind a %dx%d context", W, H);
    return check_report("stats");
  }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, W, 0.0, H, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(1.0f, 1.0f, 1.0f);

  test_off();
  test_triangle();
  test_scissor();
  test_accumulate();
  CHECK(glGetError() == GL_NO_ERROR, "no GL error");

  OSMesaDestroyContext(ctx);
  return check_report("stats");
}
