/*
 * A lit, animated legacy GLUT demo: a teapot, a torus and a sphere under
 * two lights, turned by a timer, the sphere bobbing by the elapsed time
 * in an idle callback; the view through gluPerspective and gluLookAt, which
 * classic <GL/glut.h> brings with <GL/glu.h>.  Plain GLUT 3.7 code: it
 * builds unchanged against any <GL/glut.h>.  Esc quits.
 */
#include <GL/glut.h>
#include <math.h>
#include <stdlib.h>

static float angle;
static float bob;

static void init(void)
{
   static const GLfloat light0_pos[] = { 2.0f, 3.0f, 4.0f, 1.0f };
   static const GLfloat light0_diffuse[] = { 1.0f, 0.95f, 0.85f, 1.0f };
   static const GLfloat light1_dir[] = { -1.0f, 0.5f, 0.5f, 0.0f };
   static const GLfloat light1_diffuse[] = { 0.2f, 0.3f, 0.6f, 1.0f };
   static const GLfloat specular[] = { 1.0f, 1.0f, 1.0f, 1.0f };
   static const GLfloat ambient[] = { 0.15f, 0.15f, 0.15f, 1.0f };

   glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
   glEnable(GL_DEPTH_TEST);
   glEnable(GL_LIGHTING);
   glEnable(GL_LIGHT0);
   glEnable(GL_LIGHT1);
   glLightfv(GL_LIGHT0, GL_POSITION, light0_pos);
   glLightfv(GL_LIGHT0, GL_DIFFUSE, light0_diffuse);
   glLightfv(GL_LIGHT0, GL_SPECULAR, specular);
   glLightfv(GL_LIGHT1, GL_POSITION, light1_dir);
   glLightfv(GL_LIGHT1, GL_DIFFUSE, light1_diffuse);
   glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
   glShadeModel(GL_SMOOTH);
}

static void material(float r, float g, float b, float shininess)
{
   const GLfloat diffuse[] = { r, g, b, 1.0f };
   const GLfloat specular[] = { 0.7f, 0.7f, 0.7f, 1.0f };
   glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diffuse);
   glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
   glMaterialf(GL_FRONT, GL_SHININESS, shininess);
}

static void display(void)
{
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   gluLookAt(0.0, 2.0, 5.6, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

   glPushMatrix();
   glRotatef(angle, 0.0f, 1.0f, 0.0f);
   material(0.8f, 0.6f, 0.2f, 60.0f);
   glutSolidTeapot(0.9);
   glPopMatrix();

   glPushMatrix();
   glTranslatef(-1.9f, -0.4f, 0.0f);
   glRotatef(2.0f * angle, 1.0f, 0.0f, 0.0f);
   material(0.2f, 0.7f, 0.3f, 30.0f);
   glutSolidTorus(0.2, 0.5, 16, 24);
   glPopMatrix();

   glPushMatrix();
   glTranslatef(1.9f, bob, 0.0f);
   material(0.7f, 0.2f, 0.2f, 90.0f);
   glutSolidSphere(0.5, 20, 14);
   glPopMatrix();

   glutSwapBuffers();
}

static void reshape(int w, int h)
{
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluPerspective(50.0, (double)w / (double)(h ? h : 1), 1.0, 20.0);
   glMatrixMode(GL_MODELVIEW);
}

static void timer(int value)
{
   angle += 7.5f;
   if (angle >= 360.0f)
      angle -= 360.0f;
   glutPostRedisplay();
   glutTimerFunc(50, timer, value + 1);
}

static void idle(void)
{
   float t = glutGet(GLUT_ELAPSED_TIME) / 1000.0f;
   float b = 0.5f * (float)sin(3.0 * t);
   if (b != bob) {
      bob = b;
      glutPostRedisplay();
   }
}

static void keyboard(unsigned char key, int x, int y)
{
   (void)x, (void)y;
   if (key == 27)
      exit(0);
}

int main(int argc, char **argv)
{
   glutInit(&argc, argv);
   glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
   glutInitWindowSize(320, 240);
   glutCreateWindow("fixgl: lit GLUT demo");
   init();
   glutDisplayFunc(display);
   glutReshapeFunc(reshape);
   glutKeyboardFunc(keyboard);
   glutIdleFunc(idle);
   glutTimerFunc(50, timer, 0);
   glutMainLoop();
   return 0;
}
