/* p_element_buffer_no_store.c - glDrawElements from a bound
 * GL_ELEMENT_ARRAY_BUFFER that has no data store (bound but never given
 * data, or glBufferData of size 0) draws nothing: in feedback and
 * selection mode nothing is returned (st_draw.c prepare_indexed_draw
 * returns when the buffer has no backing storage).  Rendering such a draw
 * crashes the oracle (it looks for the index bounds in the missing store),
 * so only feedback and selection are probed.  A store of 2 bytes draws
 * its two indices (indices past the end of a store are not probed here:
 * the feedback path maps the store with no bound, st_draw_feedback.c
 * draw_set_indexes(..., ~0)) (ORACLE-NOTES.md "Buffer objects"). */
#include "probe.h"

/* the first vertex (the one every index of a missing store would read)
 * with w != 1: fixgl's old model (indices read as 0) fed back the
 * degenerate triangles of such a vertex (fuzzer seed 440) */
static const float v[4][4] = { { 1.13666f, -0.265503f, -1.24915f, 1.72406f },
                               { 0.5f, -0.5f, 0, 1 }, { 0.5f, 0.5f, 0, 1 }, { -0.5f, 0.5f, 0, 1 } };

static GLint feedback(int store)
{
   static GLfloat fb[400];
   glFeedbackBuffer(400, GL_2D, fb);
   glRenderMode(GL_FEEDBACK);
   if (store) {
      glDrawElements(GL_LINES, 2, GL_UNSIGNED_BYTE, (void *)0);
   } else {
      glDrawElements(GL_QUAD_STRIP, 6, GL_UNSIGNED_BYTE, (void *)0);
      glDrawElements(GL_QUAD_STRIP, 6, GL_UNSIGNED_BYTE, (void *)0x40);
   }
   return glRenderMode(GL_RENDER);
}

static GLint selection(void)
{
   static GLuint sb[64];
   glSelectBuffer(64, sb);
   glRenderMode(GL_SELECT);
   glInitNames();
   glPushName(7);
   glDrawElements(GL_POINTS, 2, GL_UNSIGNED_BYTE, (void *)0x40);
   return glRenderMode(GL_RENDER);
}

int main(void)
{
   static const GLubyte two[2] = { 1, 2 };
   probe_init_ub(32, 32);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glEnableClientState(GL_VERTEX_ARRAY);
   glVertexPointer(4, GL_FLOAT, 0, v);
   glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 5);
   probe_expect("no store: feedback values", feedback(0), 0);
   probe_expect("no store: selection hits", selection(), 0);
   glBufferData(GL_ELEMENT_ARRAY_BUFFER, 0, NULL, GL_STATIC_DRAW);
   probe_expect("store of size 0: feedback values", feedback(0), 0);
   probe_expect("store of size 0: selection hits", selection(), 0);
   glBufferData(GL_ELEMENT_ARRAY_BUFFER, 2, two, GL_STATIC_DRAW);
   probe_expect("store of 2 bytes: feedback values (a line, 1 + 2 * 2)", feedback(1), 5);
   probe_expect("no error", glGetError(), GL_NO_ERROR);
   return probe_result();
}
