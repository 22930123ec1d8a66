/*
 * huge_draws.c - huge but legal draws on fixgl alone (issue 18 §4), suite
 * `robust`.  glDrawArrays with a count of 2^31 - 1 and no vertex position
 * array enabled reads no client memory: every vertex is the current
 * attribute values, as in the oracle (draws without a position array
 * draw, conformance/fuzz); it must end in bounded time and memory, drawn
 * or with GL_OUT_OF_MEMORY (expect_done_or_oom); glDrawElements and glDrawRangeElements read
 * only the indices they are given.  Then a small draw shows the state
 * intact.  The oracle is not compared here: Mesa 22.3's OSMesa spent more
 * than a minute and a gigabyte on these calls (a conformance case timed
 * out on its side).  The time bound is the test's timeout.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { printf("FAIL: " __VA_ARGS__); printf("\n"); failures++; } } while (0)

static void expect_no_error(const char *what)
{
   GLenum e = glGetError();
   CHECK(e == GL_NO_ERROR, "%s: error 0x%04x", what, e);
}

/* A draw of 2^31 - 1 vertices: the oracle completes it (in minutes);
 * fixgl fetches a draw's vertices at once, cannot allocate them and
 * raises GL_OUT_OF_MEMORY with the state unchanged (open in issue 18 §4:
 * drawing it in segments, as the draw module's vsplit does, would
 * complete it). Either, in bounded time, and nothing else. */
static void expect_done_or_oom(const char *what)
{
   GLenum e = glGetError();
   CHECK(e == GL_NO_ERROR || e == GL_OUT_OF_MEMORY, "%s: error 0x%04x", what, e);
   CHECK(glGetError() == GL_NO_ERROR, "%s: a second error", what);
}

int main(void)
{
   enum { W = 32, H = 32 };
   static unsigned char buf[W * H * 4];
   static const GLfloat v[3][2] = { { -0.9f, -0.9f }, { 0.9f, -0.8f }, { 0.0f, 0.9f } };
   /* one colour for each of the three elements the small element draws
    * fetch (a draw without a position array still fetches its colours) */
   static const GLubyte col[3][4] = { { 10, 20, 30, 255 }, { 10, 20, 30, 255 },
                                      { 10, 20, 30, 255 } };
   static const GLuint idx[3] = { 0, 1, 2 };
   OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
   if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
      printf("FAIL: no context\n");
      return 1;
   }
   glClearColor(0.1f, 0.2f, 0.3f, 1);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glFinish();
   static const GLenum modes[] = { GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_LINE_STRIP, GL_TRIANGLES,
                                   GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP,
                                   GL_POLYGON };
   for (int colour = 0; colour < 2; colour++) {
      if (colour) {
         glEnableClientState(GL_COLOR_ARRAY);
         glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);
      }
      for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
         glDrawArrays(modes[m], 0, INT_MAX);
         expect_done_or_oom("glDrawArrays(0, INT_MAX)");
         glDrawArrays(modes[m], INT_MAX, INT_MAX);
         expect_done_or_oom("glDrawArrays(INT_MAX, INT_MAX)");
      }
      glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, idx);
      expect_no_error("glDrawElements(3)");
      glDrawRangeElements(GL_POINTS, 0, 2, 3, GL_UNSIGNED_INT, idx);
      expect_no_error("glDrawRangeElements(3)");
   }
   glDisableClientState(GL_COLOR_ARRAY);
   glFinish();
   /* the frame is cleared again: the state, not the picture, is checked */
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   /* the state is intact: a small draw shows */
   glEnableClientState(GL_VERTEX_ARRAY);
   glVertexPointer(2, GL_FLOAT, 0, v);
   glColor3f(1, 0.5f, 0);
   glDrawArrays(GL_TRIANGLES, 0, 3);
   expect_no_error("small glDrawArrays");
   glFinish();
   const unsigned char *centre = buf + 4 * (W * (H / 2) + W / 2);
   CHECK(centre[0] == 255 && centre[1] == 128 && centre[2] == 0, "the small triangle: %u %u %u",
         centre[0], centre[1], centre[2]);
   OSMesaDestroyContext(ctx);
   if (!failures)
      printf("huge draws: ok\n");
   return failures != 0;
}
