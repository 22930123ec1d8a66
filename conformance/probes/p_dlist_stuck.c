/* p_dlist_stuck.c - an oracle defect: a display list whose vertex list
 * grows the colour to four components after the last vertex of a
 * glBegin/glEnd, followed by a glDrawElements, leaves the oracle "inside
 * glBegin/glEnd" after glCallList, so the next glBegin raises
 * GL_INVALID_OPERATION and draws nothing (ORACLE-NOTES.md "OSMesa defects
 * kept visible").  fixgl does not model it; this probe shows the defect is
 * still there, and that the same list without the glColor4f is fine. */
#include "probe.h"

static const float va[3][2] = { { 1, 1 }, { 15, 1 }, { 1, 15 } };
static const GLuint idx[3] = { 0, 1, 2 };

static GLuint make_list(int grow)
{
   GLuint l = glGenLists(1);
   glNewList(l, GL_COMPILE);
   glBegin(GL_TRIANGLES);
   glColor3f(1, 0, 0); glVertex2f(20, 20);
   glColor3f(1, 0, 0); glVertex2f(30, 20);
   glColor3f(1, 0, 0); glVertex2f(20, 30);
   if (grow)
      glColor4f(1, 0, 0, 1); /* after the last vertex: the colour grows */
   glEnd();
   glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, idx);
   glEndList();
   return l;
}

/* Calls the list, then draws a green triangle at (33..47, 1..15) with
 * glBegin/glEnd; returns 1 if the green triangle was drawn and stores
 * the first error after the glBegin. */
static int after_list(GLuint l, GLenum *err)
{
   clear0();
   while (glGetError() != GL_NO_ERROR)
      ;
   glCallList(l);
   glBegin(GL_TRIANGLES);
   glColor3f(0, 1, 0); glVertex2f(33, 1);
   glColor3f(0, 1, 0); glVertex2f(47, 1);
   glColor3f(0, 1, 0); glVertex2f(33, 15);
   glEnd();
   glFinish();
   *err = glGetError();
   return px(36, 4)[1] == 255;
}

int main(void)
{
   probe_init_ub(48, 48);
   glEnableClientState(GL_VERTEX_ARRAY);
   glVertexPointer(2, GL_FLOAT, 0, va);
   GLenum err;
   GLuint good = make_list(0), bad = make_list(1);
   probe_expect("list without the glColor4f: next triangle drawn", after_list(good, &err), 1);
   probe_expect("list without the glColor4f: error", err, GL_NO_ERROR);
   probe_expect("list with the glColor4f: next triangle drawn (defect: 0)", after_list(bad, &err), 0);
   probe_expect("list with the glColor4f: error (defect: GL_INVALID_OPERATION)", err, GL_INVALID_OPERATION);
   return probe_result();
}
