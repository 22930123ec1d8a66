/* p_huge_draw.c - the oracle draws an array draw of any count: no
 * GL_OUT_OF_MEMORY, whatever the vertices would take fetched at once
 * (ORACLE-NOTES.md "Client vertex arrays": draw's vsplit runs it in
 * segments).  Without a position array every vertex is the current values,
 * (0, 0, 0, 1): 20 million points (more than fixgl's former 8 GiB scratch
 * held: 464 bytes a vertex) draw the one pixel at the origin in the
 * current colour, 20 million triangles or quads of identical vertices
 * nothing, and glDrawArrays(GL_QUADS, 0, 2^31 - 1) took 16 s (77 MB) alone
 * and raised no error either (not run here: too long for the suite). */
#include "probe.h"

#include <limits.h>

int main(void)
{
   probe_init_ub(8, 8);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(-4, 4, -4, 4, -1, 1);
   static const GLenum modes[] = { GL_TRIANGLES, GL_QUADS, GL_TRIANGLE_FAN, GL_POINTS };
   for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
      clear0();
      glColor4ub(200, 100, 50, 255);
      glDrawArrays(modes[m], INT_MAX - 20000000, 20000000);
      probe_expect("glDrawArrays of 20 million vertices: no error", glGetError(), GL_NO_ERROR);
      glFinish();
      /* the origin is the corner of pixels (3, 3) to (4, 4): the point
       * covers pixel (4, 4) (y up), the triangles nothing */
      probe_expect("the pixel at the origin", px(4, 4)[0], modes[m] == GL_POINTS ? 200 : 0);
      probe_expect("a pixel away from it", px(1, 6)[0], 0);
   }
   return probe_result();
}
