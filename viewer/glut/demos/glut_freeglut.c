/*
 * glut_freeglut - a legacy demo written for freeglut: its own event loop
 * on glutMainLoopEvent, glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE,
 * GLUT_ACTION_CONTINUE_EXECUTION) and a close callback that ends that
 * loop, freeglut's cylinders (solid, wire) beside the classic shapes, text
 * through glutBitmapString/glutStrokeString centred with glutBitmapLength
 * and glutStrokeLength, a glClearColor reached through glutGetProcAddress,
 * and glutFullScreenToggle (a state only, headless).
 *
 * Headless (FIXGLUT_FRAMES=N) the run ends as a closed window would: the
 * close callback stops the loop and main returns 0.
 */
#include <GL/freeglut.h>
#include <stdio.h>
#include <string.h>

static int running = 1;
static int frame;
static float spin;

static void close_window(void)
{
   running = 0;
}

static void reshape(int w, int h)
{
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluPerspective(40.0, (double)w / (double)h, 1.0, 30.0);
   glMatrixMode(GL_MODELVIEW);
}

static void text(void)
{
   static const unsigned char bitmap_line[] = "freeglut: glutBitmapString";
   static const unsigned char stroke_line[] = "Cylinders";
   int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
   glDisable(GL_LIGHTING);
   glDisable(GL_DEPTH_TEST);
   glMatrixMode(GL_PROJECTION);
   glPushMatrix();
   glLoadIdentity();
   gluOrtho2D(0.0, w, 0.0, h);
   glMatrixMode(GL_MODELVIEW);
   glPushMatrix();
   glLoadIdentity();
   glColor3f(1.0f, 1.0f, 0.4f);
   int len = glutBitmapLength(GLUT_BITMAP_HELVETICA_12, bitmap_line);
   glRasterPos2i((w - len) / 2, h - 4 - glutBitmapHeight(GLUT_BITMAP_HELVETICA_12));
   glutBitmapString(GLUT_BITMAP_HELVETICA_12, bitmap_line);
   glTranslatef(8.0f, 8.0f, 0.0f);
   float scale = 20.0f / glutStrokeHeight(GLUT_STROKE_ROMAN);
   glScalef(scale, scale, 1.0f);
   glColor3f(0.5f, 1.0f, 0.8f);
   glutStrokeString(GLUT_STROKE_ROMAN, stroke_line);
   glTranslatef(40.0f, 0.0f, 0.0f);
   glutStrokeString(GLUT_STROKE_MONO_ROMAN, (const unsigned char *)(glutGet(GLUT_FULL_SCREEN) ? "F" : "W"));
   glPopMatrix();
   glMatrixMode(GL_PROJECTION);
   glPopMatrix();
   glMatrixMode(GL_MODELVIEW);
   (void)glutStrokeLength(GLUT_STROKE_ROMAN, stroke_line);
}

static void display(void)
{
   void (*clear_color)(GLclampf, GLclampf, GLclampf, GLclampf) =
      (void (*)(GLclampf, GLclampf, GLclampf, GLclampf))glutGetProcAddress("glClearColor");
   clear_color(0.08f, 0.1f + 0.01f * (float)(frame % 8), 0.16f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);
   glEnable(GL_LIGHTING);
   glEnable(GL_LIGHT0);
   glEnable(GL_COLOR_MATERIAL);
   glEnable(GL_NORMALIZE);
   glLoadIdentity();
   gluLookAt(0.0, 1.5, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

   glPushMatrix();
   glTranslatef(-1.6f, 0.0f, 0.0f);
   glRotatef(spin, 1.0f, 0.3f, 0.0f);
   glColor3f(0.9f, 0.5f, 0.2f);
   glutSolidCylinder(0.7, 1.6, 14, 3);
   glPopMatrix();

   glPushMatrix();
   glTranslatef(0.4f, 0.3f, 0.0f);
   glRotatef(-spin, 0.2f, 1.0f, 0.0f);
   glColor3f(0.3f, 0.8f, 1.0f);
   glutWireCylinder(0.6, 1.4, 10, 4);
   glPopMatrix();

   glPushMatrix();
   glTranslatef(2.0f, -0.3f, 0.0f);
   glRotatef(spin * 0.5f, 0.0f, 1.0f, 0.0f);
   glColor3f(0.6f, 0.9f, 0.4f);
   glutSolidTorus(0.2, 0.6, 10, 16);
   glPopMatrix();

   text();
   glutSwapBuffers();
}

int main(int argc, char **argv)
{
   glutInit(&argc, argv);
   glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_CONTINUE_EXECUTION);
   glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH);
   glutInitWindowSize(200, 160);
   glutInitContextVersion(1, 5);
   glutCreateWindow("freeglut extensions");
   glutDisplayFunc(display);
   glutReshapeFunc(reshape);
   glutCloseFunc(close_window);

   while (running) {
      glutMainLoopEvent();
      if (!running)
         break;
      frame++;
      spin += 9.0f;
      if (frame == 3)
         glutFullScreenToggle();
      glutPostRedisplay();
   }
   printf("glut_freeglut: %d frames, the loop left by the close callback\n", frame);
   return 0;
}
