/*
 * shared_textures.c - texture objects shared by two contexts on two
 * threads, changed in one while the other draws with them.
 *
 * Built against the oracle and against libfixgl (test
 * shared_textures_threads_N, compare_runs.sh), run with
 * FIXGL_NUM_THREADS=1 and 3.  Thread A draws into context A, thread B
 * changes the texture A samples through context B (OSMesaCreateContextExt
 * sharelist); barriers order the steps, so every run is the same.  The
 * transcript prints A's pixels at each step and the GL errors.  Steps:
 *  1. A draws a textured quad and does not flush; B gives the texture a
 *     level 0 of another size, then another, then deletes it; A finishes.
 *     A's vertices wait in its vertex buffer until the flush, so they are
 *     drawn with the state of then, the last image B gave (the object
 *     lives on while A's unit holds it).
 *  2. The same, with A's draw sent on to the rasterizer by a state change
 *     before B's changes (glEnable(GL_BLEND) after glEnd, with the blend
 *     function GL_ONE, GL_ZERO: the same pixels): the quad is drawn with
 *     the image it was set up with, which B's glTexImage2D and
 *     glDeleteTextures must not free under it.
 *  3. A draws and finishes; B replaces level 0 (another size) and
 *     finishes; A draws again without binding anything: the oracle keeps
 *     sampling what A validated, the old image (its resource lives on:
 *     a context revalidates its textures only for a change of its own),
 *     which fixgl must not have freed either; after A binds texture 0
 *     and the texture again, the new image.
 *  4. The same with glTexSubImage2D of texels A samples and a texture
 *     parameter (GL_NEAREST to GL_LINEAR magnification) in B: A's next
 *     draw shows the new texels (written into the storage both sample)
 *     with the old filter; after binding again, the new filter.
 * fixgl keeps a texture's texels in reference-counted blocks that the
 * state objects sampling them hold (fgl_rc_alloc; main/teximage.c
 * free_image, state.c tex_unit_hold), so neither a pending scene (step
 * 2) nor a context's validated state (step 3) reads freed memory.
 * (GL leaves undefined what a context sees of another's change until it
 * binds the object again: appendix D of the specification.  The steps
 * keep to what the oracle does deterministically; an image replaced by
 * one of the same size is not among them, since the oracle may then
 * write into storage the other context's pending scene still reads.)
 * Under AddressSanitizer (CI's sanitized step) a read of freed texels
 * fails the test, as it did before step 2's storage was held.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 64, H = 64 };

static OSMesaContext ctx_a, ctx_b;
static unsigned char buf_a[W * H * 4], buf_b[W * H * 4];
static pthread_barrier_t barrier;
static GLuint tex;
static int failures;

static void sync_step(void) { pthread_barrier_wait(&barrier); }

/* a size x size RGBA image: texel (x, y) of colour (x * k, y * k, 40 * k, 255) */
static unsigned char *image(int size, int k)
{
  unsigned char *p = malloc((size_t)size * (size_t)size * 4);
  if (!p) {
    printf("out of memory\n");
    exit(1);
  }
  for (int y = 0; y < size; y++)
    for (int x = 0; x < size; x++) {
      unsigned char *t = p + 4 * ((size_t)y * (size_t)size + (size_t)x);
      t[0] = (unsigned char)(x * k * 9);
      t[1] = (unsigned char)(y * k * 13);
      t[2] = (unsigned char)(40 * k);
      t[3] = 255;
    }
  return p;
}

static void give_image(int size, int k)
{
  unsigned char *p = image(size, k);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
  free(p);
}

static void new_texture(void)
{
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  give_image(8, 1);
}

static void quad(void)
{
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(-1, -1);
  glTexCoord2f(1, 0); glVertex2f(1, -1);
  glTexCoord2f(1, 1); glVertex2f(1, 1);
  glTexCoord2f(0, 1); glVertex2f(-1, 1);
  glEnd();
}

static void report(const char *what)
{
  /* texels (0, 0), (5, 1), (3, 3) in B's glTexSubImage2D, (7, 7) of the
   * 8 x 8 image */
  static const int at[4][2] = { { 1, 1 }, { 40, 9 }, { 28, 28 }, { 63, 63 } };
  printf("%-34s", what);
  for (int i = 0; i < 4; i++) {
    const unsigned char *p = buf_a + 4 * (at[i][1] * W + at[i][0]);
    printf(" %3u,%3u,%3u", p[0], p[1], p[2]);
  }
  printf("  error %04x\n", (unsigned)glGetError());
}

static void *thread_a(void *arg)
{
  (void)arg;
  if (!OSMesaMakeCurrent(ctx_a, buf_a, GL_UNSIGNED_BYTE, W, H)) {
    printf("A: make current failed\n");
    failures++;
  }
  glEnable(GL_TEXTURE_2D);
  for (int step = 1; step <= 4; step++) {
    new_texture();
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    sync_step();   /* (a) the texture exists: B binds it */
    sync_step();   /* (b) B bound it */
    quad();
    if (step == 2)
      glEnable(GL_BLEND);   /* the quad goes on to the rasterizer */
    if (step >= 3) {
      glFinish();
      report("A drew");
    }
    sync_step();   /* (c) A drew: B changes the texture */
    sync_step();   /* (d) B changed it */
    if (step >= 3) {
      glClear(GL_COLOR_BUFFER_BIT);
      quad();
    }
    glFinish();
    char what[64];
    snprintf(what, sizeof what, "step %d: A after B's change", step);
    report(what);
    if (step >= 3) {
      glBindTexture(GL_TEXTURE_2D, 0);
      glBindTexture(GL_TEXTURE_2D, tex);
      glClear(GL_COLOR_BUFFER_BIT);
      quad();
      glFinish();
      snprintf(what, sizeof what, "step %d: A after binding again", step);
      report(what);
    }
    glDisable(GL_BLEND);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteTextures(1, &tex);
    sync_step();   /* (e) the step is over */
  }
  return NULL;
}

static void *thread_b(void *arg)
{
  (void)arg;
  if (!OSMesaMakeCurrent(ctx_b, buf_b, GL_UNSIGNED_BYTE, W, H)) {
    printf("B: make current failed\n");
    failures++;
  }
  for (int step = 1; step <= 4; step++) {
    sync_step();   /* (a) */
    glBindTexture(GL_TEXTURE_2D, tex);
    sync_step();   /* (b) */
    sync_step();   /* (c) */
    if (step <= 3) {
      give_image(32, 2);
      if (step <= 2) {
        give_image(4, 3);
        glDeleteTextures(1, &tex);
      }
    } else {
      unsigned char *p = image(4, 5);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, p);
      free(p);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    glFinish();
    printf("B step %d: error %04x\n", step, (unsigned)glGetError());
    sync_step();   /* (d) */
    sync_step();   /* (e) */
  }
  return NULL;
}

int main(int argc, char **argv)
{
  (void)argc;
  (void)argv;
  ctx_a = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  ctx_b = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, ctx_a);
  if (!ctx_a || !ctx_b) {
    printf("context creation failed\n");
    return 1;
  }
  pthread_barrier_init(&barrier, NULL, 2);
  pthread_t a, b;
  pthread_create(&a, NULL, thread_a, NULL);
  pthread_create(&b, NULL, thread_b, NULL);
  pthread_join(a, NULL);
  pthread_join(b, NULL);
  OSMesaDestroyContext(ctx_b);
  OSMesaDestroyContext(ctx_a);
  return failures != 0;
}
