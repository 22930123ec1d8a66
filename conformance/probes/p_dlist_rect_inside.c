/* p_dlist_rect_inside.c - an oracle defect: a display list holding a glRect
 * and then a glBegin/glEnd, called between glBegin and glEnd, leaves the
 * oracle inside Begin/End for good: the outer glEnd, later glEnds, glGet and
 * glGetError are refused (ORACLE-NOTES.md "OSMesa defects kept visible"; the
 * API fuzzer's seed 112).  A list holding only the glRect or only the
 * glBegin/glEnd raises GL_INVALID_OPERATION and the outer glEnd ends the
 * primitive, as in fixgl, which does not model the defect.  The probe uses
 * a fresh list per case and the stuck case last (it cannot be undone). */
#include "probe.h"

/* 1 when the context is outside Begin/End: glGetIntegerv writes. */
static int outside(void)
{
   GLint v = -7;
   glGetIntegerv(GL_LIST_INDEX, &v);
   return v != -7;
}

static GLuint make_list(int rect, int prim)
{
   GLuint l = glGenLists(1);
   glNewList(l, GL_COMPILE);
   if (rect)
      glRectf(1, 1, 5, 5);
   if (prim) {
      glBegin(GL_TRIANGLES);
      glTexCoord1f(-0.5f);
      glEnd();
   }
   glEndList();
   return l;
}

/* glBegin, the list, glEnd; 1 when the context is outside Begin/End after
 * it, *err the error then. */
static int call_inside(GLuint l, GLenum *err)
{
   glBegin(GL_TRIANGLES);
   glCallList(l);
   glEnd();
   const int out = outside();
   *err = glGetError();
   while (glGetError() != GL_NO_ERROR)
      ;
   return out;
}

int main(void)
{
   probe_init_ub(16, 16);
   GLenum err;
   GLuint rect = make_list(1, 0), prim = make_list(0, 1), both = make_list(1, 1);
   glCallList(both);
   probe_expect("rect + primitive list called outside Begin/End: outside after", outside(), 1);
   probe_expect("... error", glGetError(), GL_NO_ERROR);
   probe_expect("rect list inside Begin/End: outside after", call_inside(rect, &err), 1);
   probe_expect("... error", err, GL_INVALID_OPERATION);
   probe_expect("primitive list inside Begin/End: outside after", call_inside(prim, &err), 1);
   probe_expect("... error", err, GL_INVALID_OPERATION);
   probe_expect("rect + primitive list inside Begin/End: outside after (defect: 0)",
                call_inside(both, &err), 0);
   glEnd();
   probe_expect("... and after one more glEnd (defect: 0)", outside(), 0);
   return probe_result();
}
