/*
 * quadrics - GLU's quadrics and freeglut's shapes and fonts, lit: a
 * textured gluSphere, a gluCylinder and gluDisk/gluPartialDisk (fill,
 * line and silhouette styles, smooth and flat normals), glutSolidTeapot,
 * glutWireTorus, two lights (one a spotlight), GL_COLOR_MATERIAL, a
 * display list per object, and text in glutBitmapCharacter's bitmaps and
 * glutStrokeCharacter's lines.
 */
#include <GL/glut.h>
#include <GL/glu.h>

#include "glx_frames.h"

static struct frames_opts opts;
static int frame;
static GLuint lists;
static GLuint stripes;

static void init(void)
{
   static GLubyte img[16][16][3];
   for (int y = 0; y < 16; y++)
      for (int x = 0; x < 16; x++) {
         img[y][x][0] = (GLubyte)((y & 4) ? 250 : 40);
         img[y][x][1] = (GLubyte)(120 + x * 8);
         img[y][x][2] = (GLubyte)((x & 2) ? 200 : 20);
      }
   glGenTextures(1, &stripes);
   glBindTexture(GL_TEXTURE_2D, stripes);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, img);

   GLUquadric *q = gluNewQuadric();
   lists = glGenLists(4);

   glNewList(lists, GL_COMPILE);
   gluQuadricTexture(q, GL_TRUE);
   gluQuadricNormals(q, GLU_SMOOTH);
   gluQuadricDrawStyle(q, GLU_FILL);
   glEnable(GL_TEXTURE_2D);
   glColor3f(0.9f, 0.9f, 0.9f);
   gluSphere(q, 0.8, 24, 16);
   glDisable(GL_TEXTURE_2D);
   glEndList();

   glNewList(lists + 1, GL_COMPILE);
   gluQuadricTexture(q, GL_FALSE);
   gluQuadricNormals(q, GLU_FLAT);
   glColor3f(0.2f, 0.7f, 0.9f);
   gluCylinder(q, 0.5, 0.2, 1.2, 12, 3);
   gluQuadricDrawStyle(q, GLU_LINE);
   glColor3f(1.0f, 1.0f, 0.2f);
   gluDisk(q, 0.1, 0.5, 10, 2);
   glEndList();

   glNewList(lists + 2, GL_COMPILE);
   gluQuadricDrawStyle(q, GLU_FILL);
   gluQuadricNormals(q, GLU_SMOOTH);
   glColor3f(0.9f, 0.3f, 0.6f);
   gluPartialDisk(q, 0.2, 0.7, 16, 3, 30.0, 250.0);
   gluQuadricDrawStyle(q, GLU_SILHOUETTE);
   glColor3f(0.3f, 1.0f, 0.3f);
   gluDisk(q, 0.0, 0.9, 20, 1);
   glEndList();

   glNewList(lists + 3, GL_COMPILE);
   glColor3f(0.8f, 0.6f, 0.2f);
   glutSolidTeapot(0.6);
   glColor3f(0.5f, 0.5f, 1.0f);
   glutWireTorus(0.12, 0.8, 8, 20);
   glEndList();
   gluDeleteQuadric(q);

   static const GLfloat pos0[4] = { 3.0f, 4.0f, 5.0f, 1.0f };
   static const GLfloat pos1[4] = { -2.0f, 3.0f, 2.0f, 1.0f };
   static const GLfloat dir1[3] = { 0.6f, -0.8f, -0.5f };
   static const GLfloat spec[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
   static const GLfloat dim[4] = { 0.5f, 0.4f, 0.3f, 1.0f };
   glLightfv(GL_LIGHT0, GL_POSITION, pos0);
   glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
   glLightfv(GL_LIGHT1, GL_POSITION, pos1);
   glLightfv(GL_LIGHT1, GL_DIFFUSE, dim);
   glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, dir1);
   glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 35.0f);
   glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 8.0f);
   glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.1f);
   glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
   glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
   glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
   glEnable(GL_COLOR_MATERIAL);
   glEnable(GL_LIGHT0);
   glEnable(GL_LIGHT1);
   glEnable(GL_DEPTH_TEST);
   glEnable(GL_NORMALIZE);
   glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
}

static void text(void)
{
   static const char msg[] = "fixgl GLX";
   glDisable(GL_LIGHTING);
   glDisable(GL_DEPTH_TEST);
   glColor3f(1.0f, 1.0f, 1.0f);
   glRasterPos3f(-2.6f, -2.1f, 0.0f);
   for (const char *c = msg; *c; c++)
      glutBitmapCharacter(GLUT_BITMAP_HELVETICA_18, *c);
   glColor3f(0.4f, 1.0f, 0.8f);
   glRasterPos3f(0.6f, -2.1f, 0.0f);
   for (const char *c = "frame"; *c; c++)
      glutBitmapCharacter(GLUT_BITMAP_8_BY_13, *c);
   glPushMatrix();
   glTranslatef(-2.5f, 1.8f, 0.0f);
   glScalef(0.0035f, 0.0035f, 0.0035f);
   glLineWidth(2.0f);
   for (const char *c = "GLUT"; *c; c++)
      glutStrokeCharacter(GLUT_STROKE_ROMAN, *c);
   glPopMatrix();
   glLineWidth(1.0f);
   glEnable(GL_DEPTH_TEST);
}

static void draw(void)
{
   const GLfloat t = (GLfloat)frame;
   glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   gluLookAt(0.0, 0.5, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

   text();
   glEnable(GL_LIGHTING);

   glPushMatrix();
   glTranslatef(-1.3f, 0.8f, 0.0f);
   glRotatef(9.0f * t, 0.0f, 1.0f, 0.0f);
   glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
   glCallList(lists);
   glPopMatrix();

   glPushMatrix();
   glTranslatef(1.3f, 0.8f, 0.0f);
   glRotatef(-60.0f + 6.0f * t, 1.0f, 0.3f, 0.0f);
   glCallList(lists + 1);
   glPopMatrix();

   glPushMatrix();
   glTranslatef(-1.3f, -1.0f, 0.5f);
   glRotatef(20.0f + 4.0f * t, 1.0f, 1.0f, 0.0f);
   glCallList(lists + 2);
   glPopMatrix();

   glPushMatrix();
   glTranslatef(1.4f, -0.9f, 0.0f);
   glRotatef(15.0f * t, 0.0f, 1.0f, 0.2f);
   glCallList(lists + 3);
   glPopMatrix();

   glutSwapBuffers();
   if (++frame == opts.frames) {
      glFinish();
      write_current_window_ppm(opts.out);
      exit(0);
   }
   glutPostRedisplay();
}

static void reshape(int w, int h)
{
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluPerspective(45.0, (double)w / (double)h, 2.0, 30.0);
   glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
   glutInit(&argc, argv);
   frames_parse(argc, argv, &opts, 8);
   glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
   glutInitWindowPosition(0, 0);
   glutInitWindowSize(360, 300);
   glutCreateWindow("quadrics");
   init();
   glutDisplayFunc(draw);
   glutReshapeFunc(reshape);
   glutMainLoop();
   return 0;
}
