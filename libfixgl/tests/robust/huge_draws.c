/*
 * huge_draws.c - huge but legal draws on fixgl alone (issue 18 §4), suite
 * `robust`.  A glDrawArrays without a vertex position array reads no
 * client memory: every vertex is the current attribute values, as in the
 * oracle.  fixgl draws a non-indexed draw longer than 65536 vertices
 * window by window (tnl/t_array.c, t_render.c t_render_source), as the
 * oracle's draw module runs it in vsplit segments, so its memory does not
 * grow with the count: glDrawArrays(GL_QUADS, 0, 2^31 - 1) completes with
 * no error and the process grows by less than BOUND_KB; so do draws of
 * 20 million vertices in every mode (more than the 8 GiB scratch of a
 * draw fetched at once held: fixgl raised GL_OUT_OF_MEMORY for them).
 * The triangle-class draws among them return at once (all their
 * triangles have three equal positions: t_array.c t_draw_arrays, case
 * robust/drawarrays_no_position_faces); the points and lines are drawn,
 * 20 million each.  The oracle completes the same draws (glDrawArrays(GL_QUADS, 0,
 * 2^31 - 1) in minutes, no error; ORACLE-NOTES.md "Vertex arrays"); it is
 * not run here.  glDrawElements and glDrawRangeElements read only the
 * indices they are given.  Then a small draw shows the state intact.  The
 * time bound is the test's timeout.
 *
 * Usage: robust-huge-draws [COUNT]: the vertices of each draw in every
 * mode (default 20000000).  A sanitized build's test passes 2000000:
 * still 30 windows of the draw module's 65536 vertices and full tile
 * scenes, the path the sanitizers watch; the unsanitized build's test
 * draws the 20 million.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <limits.h>
#include <stdio.h>
#include <sys/resource.h>
#include <stdlib.h>
#include <string.h>

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { printf("FAIL: " __VA_ARGS__); printf("\n"); failures++; } } while (0)

static void expect_no_error(const char *what)
{
   GLenum e = glGetError();
   CHECK(e == GL_NO_ERROR, "%s: error 0x%04x", what, e);
}

/* the process's peak resident size, in KB */
static long peak_kb(void)
{
   struct rusage ru;
   getrusage(RUSAGE_SELF, &ru);
   return ru.ru_maxrss;
}

/* what the draws may add to the peak, whatever their count: two tile
 * scenes of R_SCENE_MAX_BYTES (48 MB; one is binned while the workers
 * draw the other: 20 million points fill them) and the windows of 4096
 * fetched and transformed vertices (a few MB) */
#define BOUND_KB (160 * 1024)

int main(int argc, char **argv)
{
   enum { W = 32, H = 32 };
   const long count = argc > 1 ? strtol(argv[1], NULL, 10) : 20000000;
   if (count < 65536 * 4 || count > 20000000) {
      printf("FAIL: COUNT %s: 262144 to 20000000\n", argv[1]);
      return 1;
   }
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
   /* the huge draws: no array enabled, every vertex the current values */
   const long before = peak_kb();
   glDrawArrays(GL_QUADS, 0, INT_MAX);
   expect_no_error("glDrawArrays(GL_QUADS, 0, INT_MAX)");
   for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
      glDrawArrays(modes[m], INT_MAX - (GLint)count, (GLsizei)count);
      expect_no_error("glDrawArrays(COUNT)");
   }
   glFinish();
   CHECK(peak_kb() - before < BOUND_KB, "the huge draws grew the process by %ld KB",
         peak_kb() - before);
   /* the small draws with a colour array of the three elements they fetch */
   glEnableClientState(GL_COLOR_ARRAY);
   glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);
   glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, idx);
   expect_no_error("glDrawElements(3)");
   glDrawRangeElements(GL_POINTS, 0, 2, 3, GL_UNSIGNED_INT, idx);
   expect_no_error("glDrawRangeElements(3)");
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
      printf("huge draws: ok (%ld vertices a mode)\n", count);
   return failures != 0;
}
