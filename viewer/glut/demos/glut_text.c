/*
 * GLUT's fonts: every bitmap font (glRasterPos + glutBitmapCharacter, i.e.
 * glBitmap) and both stroke fonts, over the printable ASCII range.
 * Plain GLUT 3.7 code.
 */
#include <GL/glut.h>
#include <stdlib.h>

static const struct { void *font; const char *name; } fonts[] = {
   { GLUT_BITMAP_8_BY_13, "8x13" },
   { GLUT_BITMAP_9_BY_15, "9x15" },
   { GLUT_BITMAP_TIMES_ROMAN_10, "Times 10" },
   { GLUT_BITMAP_TIMES_ROMAN_24, "Times 24" },
   { GLUT_BITMAP_HELVETICA_10, "Helvetica 10" },
   { GLUT_BITMAP_HELVETICA_12, "Helvetica 12" },
   { GLUT_BITMAP_HELVETICA_18, "Helvetica 18" },
};

static void bitmap_text(int x, int y, void *font, const char *s)
{
   glRasterPos2i(x, y);
   for (; *s; s++)
      glutBitmapCharacter(font, *s);
}

static void display(void)
{
   int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
   glClear(GL_COLOR_BUFFER_BIT);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0.0, w, 0.0, h, -1.0, 1.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();

   int y = h - 20;
   for (unsigned i = 0; i < sizeof fonts / sizeof fonts[0]; i++) {
      glColor3f(1.0f, 1.0f, 1.0f);
      bitmap_text(6, y, fonts[i].font, fonts[i].name);
      int len = glutBitmapLength(fonts[i].font, (const unsigned char *)fonts[i].name);
      glColor3f(0.5f, 1.0f, 0.5f);
      bitmap_text(10 + len, y, fonts[i].font, ": AaBbQq 0123 !?@#&");
      y -= 30;
   }
   glColor3f(0.3f, 0.8f, 1.0f);
   glRasterPos2i(6, y);
   for (int c = 32; c < 127; c++) {
      if (c == 80) {
         y -= 18;
         glRasterPos2i(6, y);
      }
      glutBitmapCharacter(GLUT_BITMAP_9_BY_15, c);
   }

   glColor3f(1.0f, 0.8f, 0.3f);
   glPushMatrix();
   glTranslatef(6.0f, 30.0f, 0.0f);
   glScalef(0.15f, 0.15f, 0.15f);
   for (const char *p = "Stroke Roman {|}~"; *p; p++)
      glutStrokeCharacter(GLUT_STROKE_ROMAN, *p);
   glPopMatrix();
   glPushMatrix();
   glTranslatef(6.0f, 6.0f, 0.0f);
   glScalef(0.15f, 0.15f, 0.15f);
   for (const char *p = "Mono Roman $%^*()"; *p; p++)
      glutStrokeCharacter(GLUT_STROKE_MONO_ROMAN, *p);
   glPopMatrix();
   glutSwapBuffers();
}

int main(int argc, char **argv)
{
   glutInit(&argc, argv);
   glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA);
   glutInitWindowSize(400, 300);
   glutCreateWindow("fixgl: GLUT fonts");
   glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
   glutDisplayFunc(display);
   glutMainLoop();
   return 0;
}
