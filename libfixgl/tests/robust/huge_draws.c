/*
 * huge_draws.c - huge but legal draws on fixgl alone (issue 18 §4), suite
 * `robust`.  glDrawArrays, glDrawElements and glDrawRangeElements with a
 * count of 2^31 - 1 and no vertex position array enabled fetch nothing,
 * so the client owes no memory for them: each returns without an error
 * and draws nothing; then a small draw shows the state intact.  The
 * oracle is not compared here: Mesa 22.3's OSMesa spent more than a
 * minute and a gigabyte on these calls (a conformance case timed out on
 * its side).  The time bound is the test's timeout.
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

int main(void)
{
   enum { W = 32, H = 32 };
   static unsigned char buf[W * H * 4], before[W * H * 4];
   static const GLfloat v[3][2] = { { -0.9f, -0.9f }, { 0.9f, -0.8f }, { 0.0f, 0.9f } };
   static const GLubyte col[4] = { 10, 20, 30, 255 };
   static const GLuint idx[3] = { 0, 1, 2 };
   OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
   if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
      printf("FAIL: no context\n");
      return 1;
   }
   glClearColor(0.1f, 0.2f, 0.3f, 1);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glFinish();
   memcpy(before, buf, sizeof buf);
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
         expect_no_error("glDrawArrays(0, INT_MAX)");
         glDrawArrays(modes[m], INT_MAX, INT_MAX);
         expect_no_error("glDrawArrays(INT_MAX, INT_MAX)");
      }
      /* the indices are never read without a position array */
      glDrawElements(GL_TRIANGLES, INT_MAX, GL_UNSIGNED_INT, idx);
      expect_no_error("glDrawElements(INT_MAX)");
      glDrawRangeElements(GL_POINTS, 0, 2, INT_MAX, GL_UNSIGNED_INT, idx);
      expect_no_error("glDrawRangeElements(INT_MAX)");
   }
   glDisableClientState(GL_COLOR_ARRAY);
   glFinish();
   CHECK(memcmp(buf, before, sizeof buf) == 0, "a draw without a position array drew");
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
