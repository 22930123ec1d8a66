/* p_dlist_compile_rules.c - which glNewList starts a list, and what
 * glEndList inside glBegin/glEnd does (ORACLE-NOTES.md "Display lists",
 * "Which glNewList starts a list"): a bad mode, name 0 or an executed
 * glBegin make glNewList start nothing; glEndList inside glBegin/glEnd
 * ends the list, and the glEnd after it is GL_INVALID_OPERATION, in
 * GL_COMPILE and GL_COMPILE_AND_EXECUTE alike.  The API fuzzer's
 * generator check (conformance/fuzz/fz_gen_check.c) replays these rules. */
#include "probe.h"

static GLint list_index(void)
{
   GLint i = -1;
   glGetIntegerv(GL_LIST_INDEX, &i);
   return i;
}

/* glNewList(name, mode): its error and whether a list is then open */
static void newlist(const char *what, GLuint name, GLenum mode, GLenum err, GLint index)
{
   char buf[160];
   glNewList(name, mode);
   snprintf(buf, sizeof buf, "%s: error", what);
   probe_expect(buf, (long)glGetError(), (long)err);
   snprintf(buf, sizeof buf, "%s: GL_LIST_INDEX", what);
   probe_expect(buf, list_index(), index);
   if (list_index())
      glEndList();
   while (glGetError())
      ;
}

int main(void)
{
   probe_init_ub(8, 8);
   newlist("glNewList(7, bad mode)", 7, 0x1234, GL_INVALID_ENUM, 0);
   newlist("glNewList(0, GL_COMPILE)", 0, GL_COMPILE, GL_INVALID_VALUE, 0);
   newlist("glNewList(4, GL_COMPILE)", 4, GL_COMPILE, GL_NO_ERROR, 4);

   /* inside an executed glBegin/glEnd: no list (the error is not
    * readable there; GL_LIST_INDEX after the glEnd) */
   glBegin(GL_TRIANGLES);
   glNewList(5, GL_COMPILE);
   glEnd();
   probe_expect("glNewList inside an executed glBegin: GL_LIST_INDEX after glEnd", list_index(),
                0);
   if (list_index())
      glEndList();
   while (glGetError())
      ;

   static const GLenum modes[2] = { GL_COMPILE, GL_COMPILE_AND_EXECUTE };
   for (int m = 0; m < 2; m++) {
      char buf[160];
      glNewList(6, modes[m]);
      glBegin(GL_TRIANGLES);
      glEndList();
      glEnd();
      snprintf(buf, sizeof buf, "mode 0x%x: glEnd after glEndList inside glBegin", modes[m]);
      probe_expect(buf, (long)glGetError(), GL_INVALID_OPERATION);
      snprintf(buf, sizeof buf, "mode 0x%x: GL_LIST_INDEX after glEndList inside glBegin",
               modes[m]);
      probe_expect(buf, list_index(), 0);
      if (list_index())
         glEndList();
      while (glGetError())
         ;
   }
   return probe_result();
}
