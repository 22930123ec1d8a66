/*
 * gears - glxgears' scene (Brian Paul's three gears: flat-shaded teeth,
 * smooth inner cylinders, one light, back faces culled, display lists) as
 * a GLUT program whose frames depend on the frame number only: glxgears
 * advances its angle by the wall clock (70 degrees per second), so its
 * frames cannot be compared; this one turns the gears by 7 degrees a
 * frame and the view by the frame number as well.
 */
#include <GL/glut.h>
#include <math.h>

#include "glx_frames.h"

static struct frames_opts opts;
static int frame;
static GLuint gear1, gear2, gear3;

/* A gear: inner radius, outer radius at the teeth's middle, width, number
 * of teeth, depth of a tooth. */
static void gear(GLfloat inner, GLfloat outer, GLfloat width, GLint teeth, GLfloat tooth_depth)
{
   const GLfloat r0 = inner, r1 = outer - tooth_depth / 2.0f, r2 = outer + tooth_depth / 2.0f;
   const GLfloat da = 2.0f * (GLfloat)M_PI / (GLfloat)teeth / 4.0f;
   GLfloat angle;
   GLint i;

   glShadeModel(GL_FLAT);
   glNormal3f(0.0f, 0.0f, 1.0f);

   /* front face */
   glBegin(GL_QUAD_STRIP);
   for (i = 0; i <= teeth; i++) {
      angle = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
      glVertex3f(r0 * cosf(angle), r0 * sinf(angle), width * 0.5f);
      glVertex3f(r1 * cosf(angle), r1 * sinf(angle), width * 0.5f);
      if (i < teeth) {
         glVertex3f(r0 * cosf(angle), r0 * sinf(angle), width * 0.5f);
         glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), width * 0.5f);
      }
   }
   glEnd();

   /* front sides of the teeth */
   glBegin(GL_QUADS);
   for (i = 0; i < teeth; i++) {
      angle = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
      glVertex3f(r1 * cosf(angle), r1 * sinf(angle), width * 0.5f);
      glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), width * 0.5f);
      glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), width * 0.5f);
      glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), width * 0.5f);
   }
   glEnd();

   glNormal3f(0.0f, 0.0f, -1.0f);

   /* back face */
   glBegin(GL_QUAD_STRIP);
   for (i = 0; i <= teeth; i++) {
      angle = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
      glVertex3f(r1 * cosf(angle), r1 * sinf(angle), -width * 0.5f);
      glVertex3f(r0 * cosf(angle), r0 * sinf(angle), -width * 0.5f);
      if (i < teeth) {
         glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), -width * 0.5f);
         glVertex3f(r0 * cosf(angle), r0 * sinf(angle), -width * 0.5f);
      }
   }
   glEnd();

   /* back sides of the teeth */
   glBegin(GL_QUADS);
   for (i = 0; i < teeth; i++) {
      angle = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
      glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), -width * 0.5f);
      glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), -width * 0.5f);
      glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), -width * 0.5f);
      glVertex3f(r1 * cosf(angle), r1 * sinf(angle), -width * 0.5f);
   }
   glEnd();

   /* outward faces of the teeth */
   glBegin(GL_QUAD_STRIP);
   for (i = 0; i < teeth; i++) {
      angle = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
      glVertex3f(r1 * cosf(angle), r1 * sinf(angle), width * 0.5f);
      glVertex3f(r1 * cosf(angle), r1 * sinf(angle), -width * 0.5f);
      GLfloat u = r2 * cosf(angle + da) - r1 * cosf(angle);
      GLfloat v = r2 * sinf(angle + da) - r1 * sinf(angle);
      const GLfloat len = sqrtf(u * u + v * v);
      u /= len;
      v /= len;
      glNormal3f(v, -u, 0.0f);
      glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), width * 0.5f);
      glVertex3f(r2 * cosf(angle + da), r2 * sinf(angle + da), -width * 0.5f);
      glNormal3f(cosf(angle), sinf(angle), 0.0f);
      glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), width * 0.5f);
      glVertex3f(r2 * cosf(angle + 2 * da), r2 * sinf(angle + 2 * da), -width * 0.5f);
      u = r1 * cosf(angle + 3 * da) - r2 * cosf(angle + 2 * da);
      v = r1 * sinf(angle + 3 * da) - r2 * sinf(angle + 2 * da);
      glNormal3f(v, -u, 0.0f);
      glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), width * 0.5f);
      glVertex3f(r1 * cosf(angle + 3 * da), r1 * sinf(angle + 3 * da), -width * 0.5f);
      glNormal3f(cosf(angle), sinf(angle), 0.0f);
   }
   glVertex3f(r1 * cosf(0), r1 * sinf(0), width * 0.5f);
   glVertex3f(r1 * cosf(0), r1 * sinf(0), -width * 0.5f);
   glEnd();

   glShadeModel(GL_SMOOTH);

   /* inside radius cylinder */
   glBegin(GL_QUAD_STRIP);
   for (i = 0; i <= teeth; i++) {
      angle = (GLfloat)i * 2.0f * (GLfloat)M_PI / (GLfloat)teeth;
      glNormal3f(-cosf(angle), -sinf(angle), 0.0f);
      glVertex3f(r0 * cosf(angle), r0 * sinf(angle), -width * 0.5f);
      glVertex3f(r0 * cosf(angle), r0 * sinf(angle), width * 0.5f);
   }
   glEnd();
}

static void draw(void)
{
   const GLfloat angle = 7.0f * (GLfloat)frame;
   const GLfloat view_rotx = 20.0f + 3.0f * (GLfloat)frame, view_roty = 30.0f - 2.0f * (GLfloat)frame;

   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glPushMatrix();
   glRotatef(view_rotx, 1.0f, 0.0f, 0.0f);
   glRotatef(view_roty, 0.0f, 1.0f, 0.0f);

   glPushMatrix();
   glTranslatef(-3.0f, -2.0f, 0.0f);
   glRotatef(angle, 0.0f, 0.0f, 1.0f);
   glCallList(gear1);
   glPopMatrix();

   glPushMatrix();
   glTranslatef(3.1f, -2.0f, 0.0f);
   glRotatef(-2.0f * angle - 9.0f, 0.0f, 0.0f, 1.0f);
   glCallList(gear2);
   glPopMatrix();

   glPushMatrix();
   glTranslatef(-3.1f, 4.2f, 0.0f);
   glRotatef(-2.0f * angle - 25.0f, 0.0f, 0.0f, 1.0f);
   glCallList(gear3);
   glPopMatrix();

   glPopMatrix();
   glutSwapBuffers();

   if (++frame == opts.frames) {
      glFinish();
      write_current_window_ppm(opts.out);
      exit(0);
   }
   glutPostRedisplay();
}

static void reshape(int width, int height)
{
   const GLfloat h = (GLfloat)height / (GLfloat)width;
   glViewport(0, 0, (GLint)width, (GLint)height);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glFrustum(-1.0, 1.0, -h, h, 5.0, 60.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glTranslatef(0.0f, 0.0f, -40.0f);
}

static void init(void)
{
   static const GLfloat pos[4] = { 5.0f, 5.0f, 10.0f, 0.0f };
   static const GLfloat red[4] = { 0.8f, 0.1f, 0.0f, 1.0f };
   static const GLfloat green[4] = { 0.0f, 0.8f, 0.2f, 1.0f };
   static const GLfloat blue[4] = { 0.2f, 0.2f, 1.0f, 1.0f };

   glLightfv(GL_LIGHT0, GL_POSITION, pos);
   glEnable(GL_CULL_FACE);
   glEnable(GL_LIGHTING);
   glEnable(GL_LIGHT0);
   glEnable(GL_DEPTH_TEST);

   gear1 = glGenLists(1);
   glNewList(gear1, GL_COMPILE);
   glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
   gear(1.0f, 4.0f, 1.0f, 20, 0.7f);
   glEndList();

   gear2 = glGenLists(1);
   glNewList(gear2, GL_COMPILE);
   glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
   gear(0.5f, 2.0f, 2.0f, 10, 0.7f);
   glEndList();

   gear3 = glGenLists(1);
   glNewList(gear3, GL_COMPILE);
   glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
   gear(1.3f, 2.0f, 0.5f, 10, 0.7f);
   glEndList();

   glEnable(GL_NORMALIZE);
}

int main(int argc, char **argv)
{
   glutInit(&argc, argv);
   frames_parse(argc, argv, &opts, 12);
   glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
   glutInitWindowPosition(0, 0);
   glutInitWindowSize(300, 300);
   glutCreateWindow("gears");
   init();
   glutDisplayFunc(draw);
   glutReshapeFunc(reshape);
   glutMainLoop();
   return 0;
}
