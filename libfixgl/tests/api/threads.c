/*
 * threads.c - two contexts rendering on two threads at the same time.
 *
 * First every frame of two different scenes is rendered alone on the main
 * thread (the references).  Then two threads each create their own context
 * and render one of the scenes, frame after frame, at the same time; every
 * frame must equal its reference byte for byte.  Shared state between
 * contexts (a global matrix stack, colour, current context, ...) shows up
 * as a mismatch.  The test also checks that OSMesaGetCurrentContext answers
 * per thread: NULL in a new thread, each thread's own context after binding
 * it, and the main thread's context unchanged by the other threads.
 *
 * Built against libfixgl (test `threads`) and against the system OSMesa
 * (test `threads (oracle)`), which proves the test itself right.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define W 96
#define H 80
#define VARIANTS 12 /* frames differ: frame f draws variant f % VARIANTS */
#define FRAMES 1500 /* frames per thread */
#define BUF_SIZE (W * H * 4)

/* Scene 0: a smooth-shaded fan turning with the variant, no depth buffer use. */
static void draw_fan(int variant)
{
  glDisable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);
  glClearColor(0.2f, 0.4f, 0.6f, 1.0f); /* exact in bytes: 51 102 153 */
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(30.0f * (float)variant, 0.0f, 0.0f, 1.0f);
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1.0f, 1.0f, 1.0f);
  glVertex2f(0.0f, 0.0f);
  glColor3f(1.0f, 0.0f, 0.0f);
  glVertex2f(0.9f, 0.0f);
  glColor3f(0.0f, 1.0f, 0.0f);
  glVertex2f(0.3f, 0.8f);
  glColor3f(0.0f, 0.0f, 1.0f);
  glVertex2f(-0.6f, 0.5f);
  glColor3f(1.0f, 1.0f, 0.0f);
  glVertex2f(-0.7f, -0.4f);
  glEnd();
}

/* Scene 1: flat quads interpenetrating in depth, in perspective. */
static void draw_quads(int variant)
{
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glShadeModel(GL_FLAT);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -0.8, 0.8, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.05f * (float)(variant - VARIANTS / 2), 0.0f, -2.0f);
  for (int i = 0; i < 3; i++) {
    glPushMatrix();
    glRotatef(40.0f * (float)i + 5.0f * (float)variant, 0.0f, 1.0f, 0.2f);
    glBegin(GL_QUADS);
    glColor3f(i == 0 ? 1.0f : 0.2f, i == 1 ? 1.0f : 0.2f, i == 2 ? 1.0f : 0.2f);
    glVertex3f(-1.2f, -0.9f, 0.0f);
    glVertex3f(1.2f, -0.9f, 0.0f);
    glVertex3f(1.2f, 0.9f, 0.0f);
    glVertex3f(-1.2f, 0.9f, 0.0f);
    glEnd();
    glPopMatrix();
  }
}

static void (*const scenes[2])(int) = { draw_fan, draw_quads };
static const unsigned char clear_bytes[2][4] = { { 51, 102, 153, 255 }, { 0, 0, 0, 0 } };

static unsigned char references[2][VARIANTS][BUF_SIZE];
static pthread_barrier_t start_line;
static OSMesaContext main_ctx;

static OSMesaContext new_context(void)
{
  return OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
}

/* Renders one frame into the bound buffer and waits for it. */
static void render(int scene, int variant)
{
  glViewport(0, 0, W, H);
  scenes[scene](variant);
  glFinish();
}

/* Counts the pixels not of the clear colour: a reference must show a real
 * drawing, or the comparison below would prove nothing. */
static int drawn_pixels(const unsigned char *buf, const unsigned char *clear)
{
  int n = 0;
  for (int i = 0; i < W * H; i++)
    n += memcmp(buf + 4 * i, clear, 4) != 0;
  return n;
}

/* Thread body: bind a fresh context and render FRAMES frames of one scene. */
static void *render_thread(void *arg)
{
  const int scene = *(const int *)arg;
  unsigned char *buf = calloc(1, BUF_SIZE);
  OSMesaContext ctx = new_context();
  CHECK(buf && ctx, "scene %d: no buffer or context", scene);
  CHECK(OSMesaGetCurrentContext() == NULL,
        "scene %d: a new thread sees the main thread's context", scene);

  pthread_barrier_wait(&start_line);
  if (buf && ctx && OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
    int bad_frames = 0, lost_context = 0;
    for (int f = 0; f < FRAMES; f++) {
      render(scene, f % VARIANTS);
      if (memcmp(buf, references[scene][f % VARIANTS], BUF_SIZE) != 0 && bad_frames++ < 3)
        FAIL("scene %d frame %d differs from the same frame rendered alone", scene, f);
      if (OSMesaGetCurrentContext() != ctx && lost_context++ < 3)
        FAIL("scene %d frame %d: the thread's current context changed", scene, f);
    }
    CHECK(bad_frames == 0, "scene %d: %d bad frames out of %d", scene, bad_frames, FRAMES);
    CHECK(lost_context == 0, "scene %d: current context wrong in %d frames", scene,
          lost_context);
    CHECK(glGetError() == GL_NO_ERROR, "scene %d: GL error", scene);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  } else {
    FAIL("scene %d: cannot bind the thread's context", scene);
  }
  if (ctx)
    OSMesaDestroyContext(ctx);
  free(buf);
  return NULL;
}

int main(void)
{
  /* References: each frame of each scene, alone, on the main thread, each
   * scene in its own context. */
  unsigned char *main_buf = calloc(1, BUF_SIZE);
  for (int scene = 0; scene < 2; scene++) {
    OSMesaContext ctx = new_context();
    if (!ctx || !main_buf || !OSMesaMakeCurrent(ctx, main_buf, GL_UNSIGNED_BYTE, W, H)) {
      FAIL("cannot create and bind a context on the main thread");
      return check_report("threads");
    }
    for (int v = 0; v < VARIANTS; v++) {
      render(scene, v);
      memcpy(references[scene][v], main_buf, BUF_SIZE);
      CHECK(drawn_pixels(main_buf, clear_bytes[scene]) > W * H / 10, "scene %d variant %d draws almost nothing",
            scene, v);
    }
    CHECK(memcmp(references[scene][0], references[scene][1], BUF_SIZE) != 0,
          "scene %d: variants 0 and 1 render the same image", scene);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
  }

  /* The main thread keeps a context of its own bound while the threads run. */
  main_ctx = new_context();
  CHECK(main_ctx && OSMesaMakeCurrent(main_ctx, main_buf, GL_UNSIGNED_BYTE, W, H),
        "cannot bind the main thread's context");

  static const int scene_ids[2] = { 0, 1 };
  pthread_t threads[2];
  pthread_barrier_init(&start_line, NULL, 2);
  for (int i = 0; i < 2; i++)
    CHECK(pthread_create(&threads[i], NULL, render_thread, (void *)&scene_ids[i]) == 0,
          "pthread_create failed");
  for (int i = 0; i < 2; i++)
    pthread_join(threads[i], NULL);
  pthread_barrier_destroy(&start_line);

  CHECK(OSMesaGetCurrentContext() == main_ctx,
        "the main thread's current context changed while other threads rendered");
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(main_ctx);
  free(main_buf);
  return check_report("threads");
}
