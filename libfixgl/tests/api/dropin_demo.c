/*
 * dropin_demo.c - a small, typical OSMesa program.
 *
 * It knows nothing about fixgl: the same file is built once with -lOSMesa
 * and once with -lfixgl (see README.md, "OSMesa drop-in"), and test `dropin`
 * requires the two images to be identical byte for byte.
 *
 * Usage: dropin_demo [OUTPUT.ppm]    (default: dropin.ppm)
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <stdio.h>
#include <stdlib.h>

#define WIDTH 320
#define HEIGHT 240

/* Three smooth-shaded triangles that cut through each other in depth. */
static void draw_scene(void)
{
  glViewport(0, 0, WIDTH, HEIGHT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.0, 1.0, -0.75, 0.75, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
  glRotatef(-25.0f, 1.0f, 0.0f, 0.0f);

  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);
  glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  for (int i = 0; i < 3; i++) {
    glPushMatrix();
    glRotatef(120.0f * (float)i + 10.0f, 0.0f, 1.0f, 0.0f);
    glRotatef(35.0f, 0.0f, 0.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.2f, 0.2f);
    glVertex3f(-1.6f, -0.8f, 0.3f);
    glColor3f(0.2f, 1.0f, 0.2f);
    glVertex3f(1.6f, -0.6f, -0.3f);
    glColor3f(0.2f, 0.3f, 1.0f);
    glVertex3f(0.1f, 1.4f, 0.0f);
    glEnd();
    glPopMatrix();
  }
  glFinish();
}

/* Writes the RGBA buffer (bottom row first) as a binary PPM, top row first. */
static int write_ppm(const char *path, const unsigned char *rgba)
{
  FILE *f = fopen(path, "wb");
  if (!f)
    return 0;
  fprintf(f, "P6\n%d %d\n255\n", WIDTH, HEIGHT);
  for (int y = HEIGHT - 1; y >= 0; y--)
    for (int x = 0; x < WIDTH; x++)
      fwrite(rgba + 4 * (y * WIDTH + x), 1, 3, f);
  return fclose(f) == 0;
}

int main(int argc, char **argv)
{
  const char *out = argc > 1 ? argv[1] : "dropin.ppm";

  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  if (!ctx) {
    fprintf(stderr, "OSMesaCreateContextExt failed\n");
    return 1;
  }
  unsigned char *buffer = malloc(WIDTH * HEIGHT * 4);
  if (!buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
    fprintf(stderr, "OSMesaMakeCurrent failed\n");
    return 1;
  }

  draw_scene();

  int ok = write_ppm(out, buffer);
  if (!ok)
    fprintf(stderr, "cannot write %s\n", out);
  OSMesaDestroyContext(ctx);
  free(buffer);
  return ok ? 0 : 1;
}
