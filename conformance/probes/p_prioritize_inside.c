/* p_prioritize_inside.c - glPrioritizeTextures while compiling a list,
 * between glBegin and glEnd: the compiler's begin/end check comes before
 * any look at n, so a negative n is GL_INVALID_OPERATION there (under
 * GL_COMPILE_AND_EXECUTE, reported at the glEnd), as is a valid call;
 * outside glBegin/glEnd the negative n reaches the executed call,
 * GL_INVALID_VALUE (ORACLE-NOTES.md "Display lists"). */
#include "probe.h"

int main(void)
{
   static const GLuint names[2] = { 1, 2 };
   static const GLclampf prio[2] = { 0.5f, 0.25f };

   probe_init_ub(32, 32);
   glNewList(1, GL_COMPILE_AND_EXECUTE);
   glBegin(GL_TRIANGLE_FAN);
   glPrioritizeTextures(-1, names, prio);
   glEnd();
   probe_expect("n = -1 inside glBegin, compile and execute", glGetError(),
                GL_INVALID_OPERATION);
   glPrioritizeTextures(-1, names, prio);
   probe_expect("n = -1 outside glBegin, compile and execute", glGetError(), GL_INVALID_VALUE);
   glEndList();
   probe_expect("glEndList", glGetError(), GL_NO_ERROR);
   glCallList(1);
   probe_expect("replayed: the compiled GL_INVALID_OPERATION", glGetError(),
                GL_INVALID_OPERATION);
   glNewList(2, GL_COMPILE);
   glBegin(GL_POINTS);
   glPrioritizeTextures(-1, names, prio);
   glEnd();
   glEndList();
   probe_expect("n = -1 inside glBegin, compile only", glGetError(), GL_NO_ERROR);
   glCallList(2);
   probe_expect("replayed: GL_INVALID_OPERATION", glGetError(), GL_INVALID_OPERATION);
   return probe_result();
}
