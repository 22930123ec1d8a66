/*
 * glutSolidTeapot / glutWireTeapot: the Utah teapot's 32 Bezier patches
 * drawn with evaluators, as classic GLUT draws it: GL_MAP2_VERTEX_3 and
 * GL_MAP2_TEXTURE_COORD_2 per patch, GL_AUTO_NORMAL and GL_NORMALIZE, a
 * 14x14 mesh (solid, GL_FILL) or 10x10 (wire, GL_LINE), rotated so that
 * the lid points up +y, scaled by size / 2 and lowered by 1.5 units.
 */
#include "glut_internal.h"
#include "glut_teapot_data.h"

static void teapot(GLint grid, GLdouble scale, GLenum type)
{
   static const GLfloat tex[2][2][2] = { { { 0, 0 }, { 1, 0 } }, { { 0, 1 }, { 1, 1 } } };
   GLfloat p[4][4][3];

   glPushAttrib(GL_ENABLE_BIT | GL_EVAL_BIT);
   glEnable(GL_AUTO_NORMAL);
   glEnable(GL_NORMALIZE);
   glEnable(GL_MAP2_VERTEX_3);
   glEnable(GL_MAP2_TEXTURE_COORD_2);
   glPushMatrix();
   glRotatef(270.0f, 1.0f, 0.0f, 0.0f);
   glScalef(0.5f * (GLfloat)scale, 0.5f * (GLfloat)scale, 0.5f * (GLfloat)scale);
   glTranslatef(0.0f, 0.0f, -1.5f);
   for (int i = 0; i < 32; i++) {
      for (int j = 0; j < 4; j++)
         for (int k = 0; k < 4; k++)
            for (int l = 0; l < 3; l++)
               p[j][k][l] = teapot_points[teapot_patches[i][j * 4 + k]][l];
      glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &p[0][0][0]);
      glMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 2, 0.0f, 1.0f, 4, 2, &tex[0][0][0]);
      glMapGrid2f(grid, 0.0f, 1.0f, grid, 0.0f, 1.0f);
      glEvalMesh2(type, 0, grid, 0, grid);
   }
   glPopMatrix();
   glPopAttrib();
}

GLUT_EXPORT void glutSolidTeapot(GLdouble size)
{
   teapot(14, size, GL_FILL);
}

GLUT_EXPORT void glutWireTeapot(GLdouble size)
{
   teapot(10, size, GL_LINE);
}
