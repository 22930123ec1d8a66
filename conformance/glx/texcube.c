/*
 * texcube - textures through GLU and GLUT: a mipmapped checkerboard
 * (gluBuild2DMipmaps) on a turning cube modulated by per-face colours,
 * exponential fog, a blended translucent quad, wide lines and points, a
 * second texture of gluScaleImage's making on a quad in GL_DECAL, and a
 * resize of the window half way (glutReshapeWindow): the frames after it
 * are drawn at the window's new size.
 */
#include <GL/glut.h>
#include <GL/glu.h>

#include "glx_frames.h"

static struct frames_opts opts;
static int frame;
static GLuint tex[2];

static void make_textures(void)
{
   static GLubyte check[64][64][4];
   static GLubyte small[10][14][3];
   static GLubyte scaled[32][32][3];
   for (int y = 0; y < 64; y++)
      for (int x = 0; x < 64; x++) {
         const int on = ((x / 8) ^ (y / 8)) & 1;
         check[y][x][0] = on ? 255 : (GLubyte)(x * 4);
         check[y][x][1] = on ? 240 : 30;
         check[y][x][2] = on ? (GLubyte)(y * 4) : 60;
         check[y][x][3] = 255;
      }
   for (int y = 0; y < 10; y++)
      for (int x = 0; x < 14; x++) {
         small[y][x][0] = (GLubyte)(x * 18);
         small[y][x][1] = (GLubyte)(y * 25);
         small[y][x][2] = (GLubyte)((x * y * 7) & 255);
      }
   glGenTextures(2, tex);
   glBindTexture(GL_TEXTURE_2D, tex[0]);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
   gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, check);

   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   gluScaleImage(GL_RGB, 14, 10, GL_UNSIGNED_BYTE, small, 32, 32, GL_UNSIGNED_BYTE, scaled);
   glBindTexture(GL_TEXTURE_2D, tex[1]);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 32, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, scaled);
}

static void cube(void)
{
   static const GLfloat v[8][3] = {
      { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
      { -1, -1, 1 },  { 1, -1, 1 },  { 1, 1, 1 },  { -1, 1, 1 },
   };
   static const int faces[6][4] = {
      { 4, 5, 6, 7 }, { 1, 0, 3, 2 }, { 5, 1, 2, 6 }, { 0, 4, 7, 3 }, { 7, 6, 2, 3 }, { 0, 1, 5, 4 },
   };
   static const GLfloat colors[6][3] = {
      { 1, 1, 1 }, { 1, 0.5f, 0.5f }, { 0.5f, 1, 0.5f }, { 0.5f, 0.5f, 1 }, { 1, 1, 0.3f }, { 0.3f, 1, 1 },
   };
   glBegin(GL_QUADS);
   for (int f = 0; f < 6; f++) {
      glColor3fv(colors[f]);
      glTexCoord2f(0, 0); glVertex3fv(v[faces[f][0]]);
      glTexCoord2f(2, 0); glVertex3fv(v[faces[f][1]]);
      glTexCoord2f(2, 2); glVertex3fv(v[faces[f][2]]);
      glTexCoord2f(0, 2); glVertex3fv(v[faces[f][3]]);
   }
   glEnd();
}

static void draw(void)
{
   int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluPerspective(40.0, (double)w / (double)h, 1.0, 20.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   gluLookAt(0.0, 1.5, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

   glClearColor(0.1f, 0.15f, 0.2f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

   glEnable(GL_DEPTH_TEST);
   glEnable(GL_FOG);
   glFogi(GL_FOG_MODE, GL_EXP);
   glFogf(GL_FOG_DENSITY, 0.12f);
   static const GLfloat fogc[4] = { 0.1f, 0.15f, 0.2f, 1.0f };
   glFogfv(GL_FOG_COLOR, fogc);

   glEnable(GL_TEXTURE_2D);
   glBindTexture(GL_TEXTURE_2D, tex[0]);
   glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
   glPushMatrix();
   glRotatef(11.0f * (GLfloat)frame + 15.0f, 0.3f, 1.0f, 0.1f);
   glRotatef(5.0f * (GLfloat)frame, 1.0f, 0.0f, 0.0f);
   cube();
   glPopMatrix();

   glBindTexture(GL_TEXTURE_2D, tex[1]);
   glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
   glBegin(GL_QUADS);
   glTexCoord2f(0, 0); glVertex3f(-2.8f, -1.8f, -1.5f);
   glTexCoord2f(1, 0); glVertex3f(-1.4f, -1.8f, -1.5f);
   glTexCoord2f(1, 1); glVertex3f(-1.4f, -0.4f, -1.5f);
   glTexCoord2f(0, 1); glVertex3f(-2.8f, -0.4f, -1.5f);
   glEnd();
   glDisable(GL_TEXTURE_2D);
   glDisable(GL_FOG);

   glEnable(GL_BLEND);
   glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
   glDepthMask(GL_FALSE);
   glColor4f(1.0f, 0.3f, 0.1f, 0.45f);
   glBegin(GL_TRIANGLES);
   glVertex3f(-0.5f + 0.1f * (GLfloat)frame, -1.5f, 1.6f);
   glVertex3f(2.5f, -0.5f, 1.0f);
   glVertex3f(0.5f, 1.8f, 1.2f);
   glEnd();
   glDepthMask(GL_TRUE);
   glDisable(GL_BLEND);

   glLineWidth(3.0f);
   glBegin(GL_LINE_LOOP);
   glColor3f(1, 1, 0);
   glVertex3f(-2.5f, 1.5f, 0.0f);
   glColor3f(0, 1, 1);
   glVertex3f(2.5f, 1.7f, -0.5f);
   glColor3f(1, 0, 1);
   glVertex3f(2.0f, -2.0f, 0.5f);
   glEnd();
   glPointSize(5.0f);
   glBegin(GL_POINTS);
   for (int i = 0; i < 8; i++) {
      glColor3f((GLfloat)i / 8.0f, 1.0f - (GLfloat)i / 8.0f, 0.5f);
      glVertex3f(-2.0f + 0.5f * (GLfloat)i, 2.0f, 0.0f);
   }
   glEnd();

   glutSwapBuffers();
   ++frame;
   if (frame == opts.frames) {
      glFinish();
      write_current_window_ppm(opts.out);
      exit(0);
   }
   if (frame == opts.frames / 2)
      glutReshapeWindow(280, 200);
   glutPostRedisplay();
}

static void reshape(int w, int h)
{
   (void)w;
   (void)h;
   glutPostRedisplay();
}

int main(int argc, char **argv)
{
   glutInit(&argc, argv);
   frames_parse(argc, argv, &opts, 10);
   glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
   glutInitWindowPosition(0, 0);
   glutInitWindowSize(320, 240);
   glutCreateWindow("texcube");
   make_textures();
   glutDisplayFunc(draw);
   glutReshapeFunc(reshape);
   glutMainLoop();
   return 0;
}
