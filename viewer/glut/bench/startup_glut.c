/*
 * The start-up bench's GLUT program: one small headless frame (a lit
 * sphere), no image written; prints the time to its first display
 * callback and its peak resident size (startup_common.h).
 */
#include <GL/glut.h>

#include "startup_common.h"

static void display(void)
{
   startup_mark();
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);
   glEnable(GL_LIGHTING);
   glEnable(GL_LIGHT0);
   glutSolidSphere(0.8, 16, 12);
   glutSwapBuffers();
}

int main(int argc, char **argv)
{
   atexit(startup_report);
   glutInit(&argc, argv);
   glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH);
   glutInitWindowSize(64, 64);
   glutCreateWindow("startup");
   glutDisplayFunc(display);
   glutMainLoop();
   return 0;
}
