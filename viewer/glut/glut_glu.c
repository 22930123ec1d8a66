/*
 * The three GLU matrix helpers legacy GLUT demos use most (classic
 * <GL/glut.h> includes <GL/glu.h>, so they call them without including
 * it): gluPerspective, gluLookAt, gluOrtho2D.  Same arithmetic as SGI's
 * libGLU (libutil/project.c), expressed through glMultMatrix as there, so
 * that a program linking the system libGLU as well gets the same matrices
 * from either (test glut-glu).
 */
#include <math.h>
#include <string.h>

#include "glut_internal.h"

GLUT_EXPORT void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top)
{
   glOrtho(left, right, bottom, top, -1.0, 1.0);
}

GLUT_EXPORT void gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble z_near, GLdouble z_far)
{
   GLdouble m[4][4];
   double radians = fovy / 2.0 * 3.14159265358979323846 / 180.0;
   double delta_z = z_far - z_near;
   double sine = sin(radians);
   if (delta_z == 0.0 || sine == 0.0 || aspect == 0.0)
      return;
   double cotangent = cos(radians) / sine;
   memset(m, 0, sizeof m);
   m[0][0] = cotangent / aspect;
   m[1][1] = cotangent;
   m[2][2] = -(z_far + z_near) / delta_z;
   m[2][3] = -1.0;
   m[3][2] = -2.0 * z_near * z_far / delta_z;
   m[3][3] = 0.0;
   glMultMatrixd(&m[0][0]);
}

static void normalize(float v[3])
{
   float r = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
   if (r == 0.0f)
      return;
   v[0] /= r, v[1] /= r, v[2] /= r;
}

static void cross(const float a[3], const float b[3], float r[3])
{
   r[0] = a[1] * b[2] - a[2] * b[1];
   r[1] = a[2] * b[0] - a[0] * b[2];
   r[2] = a[0] * b[1] - a[1] * b[0];
}

GLUT_EXPORT void gluLookAt(GLdouble eye_x, GLdouble eye_y, GLdouble eye_z,
                           GLdouble center_x, GLdouble center_y, GLdouble center_z,
                           GLdouble up_x, GLdouble up_y, GLdouble up_z)
{
   float forward[3] = { (float)(center_x - eye_x), (float)(center_y - eye_y),
                        (float)(center_z - eye_z) };
   float up[3] = { (float)up_x, (float)up_y, (float)up_z }, side[3];
   GLfloat m[4][4];
   normalize(forward);
   cross(forward, up, side);
   normalize(side);
   cross(side, forward, up);
   memset(m, 0, sizeof m);
   m[0][0] = side[0], m[1][0] = side[1], m[2][0] = side[2];
   m[0][1] = up[0], m[1][1] = up[1], m[2][1] = up[2];
   m[0][2] = -forward[0], m[1][2] = -forward[1], m[2][2] = -forward[2];
   m[3][3] = 1.0f;
   glMultMatrixf(&m[0][0]);
   glTranslated(-eye_x, -eye_y, -eye_z);
}
