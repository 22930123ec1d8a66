/*
 * triangle.c - the OSMesa consumer of an installed fixgl (suite packaging):
 * draws one flat red triangle over a blue clear into a 64x64 buffer and
 * prints the library's strings and two pixels, which the test checks.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <fixgl/version.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIZE 64

int main(void)
{
  static unsigned char rgba[SIZE * SIZE * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, rgba, GL_UNSIGNED_BYTE, SIZE, SIZE)) {
    fprintf(stderr, "triangle: no OSMesa context\n");
    return 1;
  }
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(1.0f, 0.0f, 0.0f);
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.9f, -0.9f);
  glVertex2f(0.9f, -0.9f);
  glVertex2f(0.0f, 0.9f);
  glEnd();
  glFinish();

  const unsigned char *c = rgba + 4 * (SIZE / 2 * SIZE + SIZE / 2);
  const unsigned char *k = rgba + 4 * ((SIZE - 1) * SIZE);
  printf("renderer: %s\n", (const char *)glGetString(GL_RENDERER));
  printf("version: %s (header %s)\n", (const char *)glGetString(GL_VERSION), FIXGL_VERSION);
  printf("center: %d %d %d\n", c[0], c[1], c[2]);
  printf("corner: %d %d %d\n", k[0], k[1], k[2]);
  int ok = strstr((const char *)glGetString(GL_VERSION), FIXGL_VERSION) != NULL;
  OSMesaDestroyContext(ctx);
  return ok ? 0 : 1;
}
