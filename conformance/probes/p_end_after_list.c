/* p_end_after_list.c - a display list whose glBegin/glEnd is split across
 * two vertex lists (a new attribute after the first vertex wraps the
 * compiler's store), the second also holding a compiled glDrawElements,
 * leaves the oracle "inside glBegin/glEnd" after glCallList with no
 * primitive open in its immediate-mode store: glGetError reports nothing,
 * and the next glEnd leaves that state (vbo_exec_End resets
 * CurrentExecPrimitive whether or not it had a primitive to close), after
 * which the error of the list's compiled glBindTexture shows
 * (ORACLE-NOTES.md "Display lists"). */
#include "probe.h"

static const float va[4][2] = { { 4, 4 }, { 28, 4 }, { 28, 28 }, { 4, 28 } };
static const GLubyte idx[2] = { 0, 1 };

int main(void)
{
   probe_init_ub(32, 32);
   glEnableClientState(GL_VERTEX_ARRAY);
   glVertexPointer(2, GL_FLOAT, 0, va);
   glNewList(1, GL_COMPILE);
   glBindTexture(GL_PROXY_TEXTURE_3D, 4);
   glBegin(GL_POINTS);
   glSecondaryColor3ui(5, 243, 0xffff0000u);
   glVertex2d(10, 10);
   glColor3ui(7, 6, 6);
   glColor3f(0.25f, 0.5f, 0.75f);
   glEnd();
   glDrawElements(GL_QUADS, 2, GL_UNSIGNED_BYTE, idx);
   glEndList();
   probe_expect("compiled", glGetError(), GL_NO_ERROR);
   glCallList(1);
   probe_expect("after glCallList: inside, nothing reported", glGetError(), GL_NO_ERROR);
   glLineWidth(-1.0f);
   probe_expect("glLineWidth(-1) inside: nothing reported", glGetError(), GL_NO_ERROR);
   glEnd();
   probe_expect("glEnd: outside, the list's glBindTexture error", glGetError(), GL_INVALID_ENUM);
   glLineWidth(-1.0f);
   probe_expect("glLineWidth(-1) after glEnd", glGetError(), GL_INVALID_VALUE);
   glEnd();
   probe_expect("a second glEnd", glGetError(), GL_INVALID_OPERATION);
   return probe_result();
}
