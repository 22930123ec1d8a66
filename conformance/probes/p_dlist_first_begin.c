/* p_dlist_first_begin.c - fuzzer seed 279: in a context that has not yet
 * compiled a glBegin into any display list, a list holding glBegin
 * (GL_TRIANGLE_STRIP), one vertex, then glEvalCoord or glEvalPoint (no map
 * enabled) and glEnd raises GL_INVALID_OPERATION at its glEnd: under
 * GL_COMPILE_AND_EXECUTE when compiled, and at every glCallList of it
 * (also of a GL_COMPILE list), as if the replay left the oracle outside
 * glBegin/glEnd before the glEnd.  Any glBegin compiled before, in any
 * list (also an empty glBegin/glEnd, or a glRect), prevents it; a vertex
 * compiled outside glBegin/glEnd, a glColor, an empty list or an
 * immediate-mode glBegin/glEnd before do not: the open strip's one
 * vertex leaves its node no index, and before the context's first vertex
 * list made vbo_save's buffer the node reuses a NULL one and loses its
 * counts (ORACLE-NOTES.md "OSMesa defects kept visible"; modelled in
 * main/dlist.c upload_vertex_list). */
#include "probe.h"

static unsigned char buf2[64 * 64 * 4];

/* What compiles before the list in a fresh context. */
enum pre { PRE_NONE, PRE_IMMEDIATE, PRE_COLOR_LIST, PRE_POINT_LIST, PRE_VERTEX_LIST,
           PRE_EMPTY_BEGIN_LIST, PRE_RECT_LIST, PRE_EMPTY_LIST };

static void run(const char *name, enum pre pre, int eval_point, GLenum mode, GLenum want_end,
                GLenum want_call)
{
   OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
   if (!c || !OSMesaMakeCurrent(c, buf2, GL_UNSIGNED_BYTE, 64, 64)) {
      fprintf(stderr, "cannot create an OSMesa context\n");
      exit(2);
   }
   switch (pre) {
   case PRE_NONE:
      break;
   case PRE_IMMEDIATE:
      glBegin(GL_TRIANGLES);
      glVertex2f(0, 0);
      glVertex2f(1, 0);
      glVertex2f(0, 1);
      glEnd();
      break;
   case PRE_COLOR_LIST:
      glNewList(5, GL_COMPILE);
      glColor3f(1, 0, 0);
      glEndList();
      break;
   case PRE_POINT_LIST:
      glNewList(5, GL_COMPILE);
      glBegin(GL_POINTS);
      glVertex2f(0, 0);
      glEnd();
      glEndList();
      break;
   case PRE_VERTEX_LIST:
      glNewList(5, GL_COMPILE);
      glVertex2f(0, 0);
      glEndList();
      break;
   case PRE_EMPTY_BEGIN_LIST:
      glNewList(5, GL_COMPILE);
      glBegin(GL_POINTS);
      glEnd();
      glEndList();
      break;
   case PRE_RECT_LIST:
      glNewList(5, GL_COMPILE);
      glRectf(0, 0, 1, 1);
      glEndList();
      break;
   case PRE_EMPTY_LIST:
      glNewList(5, GL_COMPILE);
      glEndList();
      break;
   }
   while (glGetError())
      ;
   glNewList(2, mode);
   glBegin(GL_TRIANGLE_STRIP);
   glVertex3i(1, 2, 3);
   if (eval_point)
      glEvalPoint1(3);
   else
      glEvalCoord2d(0.5, 0.5);
   glEnd();
   const GLenum e_end = glGetError();
   glEndList();
   const GLenum e_endlist = glGetError();
   glCallList(2);
   const GLenum e_call1 = glGetError();
   glCallList(2);
   const GLenum e_call2 = glGetError();
   char what[160];
   snprintf(what, sizeof what, "%s: error at the compiled glEnd", name);
   probe_expect(what, (long)e_end, (long)want_end);
   snprintf(what, sizeof what, "%s: glEndList", name);
   probe_expect(what, (long)e_endlist, GL_NO_ERROR);
   snprintf(what, sizeof what, "%s: first glCallList", name);
   probe_expect(what, (long)e_call1, (long)want_call);
   snprintf(what, sizeof what, "%s: second glCallList", name);
   probe_expect(what, (long)e_call2, (long)want_call);
   OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
   OSMesaDestroyContext(c);
}

int main(void)
{
   const GLenum IO = GL_INVALID_OPERATION, NO = GL_NO_ERROR;
   run("first list, glEvalCoord2d, C&E", PRE_NONE, 0, GL_COMPILE_AND_EXECUTE, IO, IO);
   run("first list, glEvalPoint1, C&E", PRE_NONE, 1, GL_COMPILE_AND_EXECUTE, IO, IO);
   run("first list, GL_COMPILE", PRE_NONE, 0, GL_COMPILE, NO, IO);
   run("after immediate glBegin/glEnd", PRE_IMMEDIATE, 0, GL_COMPILE_AND_EXECUTE, IO, IO);
   run("after a list of glColor", PRE_COLOR_LIST, 0, GL_COMPILE_AND_EXECUTE, IO, IO);
   run("after a list of a vertex outside glBegin", PRE_VERTEX_LIST, 0, GL_COMPILE_AND_EXECUTE,
       IO, IO);
   run("after an empty list", PRE_EMPTY_LIST, 0, GL_COMPILE_AND_EXECUTE, IO, IO);
   run("after a list of a point", PRE_POINT_LIST, 0, GL_COMPILE_AND_EXECUTE, NO, NO);
   run("after a list of an empty glBegin/glEnd", PRE_EMPTY_BEGIN_LIST, 1, GL_COMPILE_AND_EXECUTE,
       NO, NO);
   run("after a list of a glRect", PRE_RECT_LIST, 0, GL_COMPILE_AND_EXECUTE, NO, NO);
   return probe_result();
}
