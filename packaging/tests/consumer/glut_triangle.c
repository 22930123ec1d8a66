/*
 * glut_triangle.c - the GLUT consumer of an installed fixgl (suite
 * packaging): run headless (FIXGLUT_HEADLESS=1) for one frame, it draws a
 * flat green triangle over a blue clear and prints two pixels of it.
 */
#include <GL/glut.h>

#include <stdio.h>

static void display(void)
{
  unsigned char c[4], k[4];
  int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0.0f, 1.0f, 0.0f);
  glBegin(GL_TRIANGLES);
  glVertex2f(-0.9f, -0.9f);
  glVertex2f(0.9f, -0.9f);
  glVertex2f(0.0f, 0.9f);
  glEnd();
  glReadPixels(w / 2, h / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, c);
  glReadPixels(0, h - 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, k);
  printf("window: %dx%d\n", w, h);
  printf("center: %d %d %d\n", c[0], c[1], c[2]);
  printf("corner: %d %d %d\n", k[0], k[1], k[2]);
  fflush(stdout);
  glutSwapBuffers();
}

int main(int argc, char **argv)
{
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE);
  glutInitWindowSize(80, 60);
  glutCreateWindow("fixgl consumer");
  glutDisplayFunc(display);
  glutMainLoop();
  return 0;
}
