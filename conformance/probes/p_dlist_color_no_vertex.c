/* p_dlist_color_no_vertex.c - an oracle defect: a display list whose
 * glBegin/glEnd holds a glColor and no vertex.  After glCallList the
 * oracle's GL_CURRENT_COLOR reads the compiler's vertex store past its
 * last vertex (uninitialised: it changes from run to run), not the list's
 * glColor3f(1, 0, 0) the GL gives; and the next primitive is drawn with a
 * colour that depends on the immediate-mode state before the list (seed
 * 3000589: the colour current before the list, while glGet reports the
 * store's value; printed here, not checked, as it follows that memory).
 * fixgl gives (0, 0, 0, 1) and draws with it (ORACLE-NOTES.md "OSMesa
 * defects kept visible"). */
#include "probe.h"

static void line(float y)
{
   glBegin(GL_LINES);
   glVertex2f(0, y);
   glVertex2f(32, y);
   glEnd();
}

static void drawn(const char *what, int row)
{
   GLfloat c[4];
   glFinish();
   glGetFloatv(GL_CURRENT_COLOR, c);
   const unsigned char *p = g_buf + 4 * (row * g_w + 16);
   printf("     %s: GL_CURRENT_COLOR reads %g %g %g %g, the line drawn %d %d %d %d\n", what,
          c[0], c[1], c[2], c[3], p[0], p[1], p[2], p[3]);
   probe_expect("GL_CURRENT_COLOR is not the list's (1, 0, 0, 1)",
                c[0] == 1 && c[1] == 0 && c[2] == 0 && c[3] == 1, 0);
}

int main(void)
{
   probe_init_ub(32, 32);
   for (int mode = 0; mode < 2; mode++) {
      glColor3f(1, 1, 1);
      glNewList(3, mode ? GL_COMPILE_AND_EXECUTE : GL_COMPILE);
      glBegin(GL_LINES);
      glColor3f(1, 0, 0);
      glEnd();
      glEndList();
      glClear(GL_COLOR_BUFFER_BIT);
      glCallList(3);
      line(4.5f);
      drawn("after glCallList", 4);
      glColor3f(0, 1, 0);
      glCallList(3);
      line(12.5f);
      drawn("after glColor3f(0, 1, 0) and glCallList", 12);
   }
   probe_expect("no error", glGetError(), GL_NO_ERROR);
   return probe_result();
}
