/* p_quad_split.c - the provoking vertex of each primitive and the diagonal
 * along which GL_QUADS are split (ORACLE-NOTES.md "Primitive
 * decomposition and the provoking vertex"). */
#include "probe.h"

static const float V[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };

/* Colours red, green, blue, white at vertices 0..3; at (0.2, 0.6) of the
 * quad green is about 0.8 in triangle (0,1,3) of the v1-v3 diagonal
 * (triangles (0,1,3)+(1,2,3)): 1; about 0.4 in triangle (0,2,3) of the
 * v0-v2 diagonal ((0,1,2)+(0,2,3)): 0. */
static int diag13(int x, int y)
{
   glFinish();
   int g = px(x, y)[1];
   return g > 150 ? 1 : g > 50 ? 0 : -1;
}

static long rgb(int x, int y)
{
   unsigned char *p = px(x, y);
   return (long)p[0] << 16 | p[1] << 8 | p[2];
}

static void quad_small(void)
{
   static const float C[4][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
   for (int i = 0; i < 4; i++) {
      glColor3fv(C[i]);
      glVertex2f(V[i][0] * 0.5f, V[i][1] * 0.5f);
   }
}

/* a second quad at the right, partly outside the window if off > 0 */
static void quad_right(float off)
{
   glColor3f(1, 1, 1);
   glVertex2f(0.6f, 0.6f);
   glVertex2f(0.9f + off, 0.6f);
   glVertex2f(0.9f + off, 0.9f);
   glVertex2f(0.6f, 0.9f);
}

int main(void)
{
   probe_init_ub(32, 32);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, 1, 0, 1, -1, 1);
   const float C[4][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
   const GLenum modes[3] = { GL_QUADS, GL_POLYGON, GL_TRIANGLE_FAN };
   const char *names[3] = { "smooth GL_QUADS: v1-v3 diagonal", "smooth GL_POLYGON: v1-v3 diagonal",
                            "smooth GL_TRIANGLE_FAN: v1-v3 diagonal" };
   for (int m = 0; m < 3; m++) {
      clear0();
      glBegin(modes[m]);
      for (int i = 0; i < 4; i++) { glColor3fv(C[i]); glVertex2fv(V[i]); }
      glEnd();
      probe_expect(names[m], diag13(6, 19), 0);
   }

   /* flat shading: the provoking vertex */
   glShadeModel(GL_FLAT);
   const float D[4][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0 } };
   clear0();
   glBegin(GL_QUADS);
   for (int i = 0; i < 4; i++) { glColor3fv(D[i]); glVertex2fv(V[i]); }
   glEnd();
   glFinish();
   probe_expect("flat GL_QUADS: both halves vertex 3 (yellow)", rgb(6, 19) == 0xffff00 && rgb(25, 9) == 0xffff00, 1);
   clear0();
   glBegin(GL_POLYGON);
   for (int i = 0; i < 4; i++) { glColor3fv(D[i]); glVertex2fv(V[i]); }
   glEnd();
   glFinish();
   probe_expect("flat GL_POLYGON: both halves vertex 0 (red)", rgb(6, 19) == 0xff0000 && rgb(25, 9) == 0xff0000, 1);
   clear0();
   glBegin(GL_TRIANGLE_STRIP);
   for (int i = 0; i < 4; i++) { static const int k[4] = { 0, 1, 3, 2 }; glColor3fv(D[i]); glVertex2fv(V[k[i]]); }
   glEnd();
   glFinish();
   probe_expect("flat GL_TRIANGLE_STRIP: vertex 2 (blue) then 3 (yellow)", rgb(6, 9) == 0x0000ff && rgb(25, 22) == 0xffff00, 1);
   clear0();
   glBegin(GL_QUAD_STRIP);
   for (int i = 0; i < 4; i++) { static const int k[4] = { 0, 3, 1, 2 }; glColor3fv(D[i]); glVertex2fv(V[k[i]]); }
   glEnd();
   glFinish();
   probe_expect("flat GL_QUAD_STRIP: vertex 3 (yellow)", rgb(6, 19) == 0xffff00 && rgb(25, 9) == 0xffff00, 1);
   clear0();
   glBegin(GL_LINES);
   glColor3f(1, 0, 0); glVertex2f(0.1f, 0.52f);
   glColor3f(0, 0, 1); glVertex2f(0.9f, 0.52f);
   glEnd();
   glFinish();
   probe_expect("flat GL_LINES: vertex 1 (blue)", rgb(5, 16) == 0x0000ff, 1);
   glShadeModel(GL_SMOOTH);

   /* the quad diagonal follows the path of the draw */
   clear0(); glBegin(GL_QUADS); quad_small(); glEnd();
   probe_expect("quad alone: v1-v3 diagonal", diag13(3, 9), 0);
   clear0(); glBegin(GL_QUADS); quad_small(); quad_right(0); glEnd();
   probe_expect("with a second quad inside, same glBegin: v1-v3 diagonal", diag13(3, 9), 0);
   clear0(); glBegin(GL_QUADS); quad_small(); quad_right(0.5f); glEnd();
   probe_expect("with a second quad clipped, same glBegin: v1-v3 diagonal", diag13(3, 9), 1);
   clear0(); glBegin(GL_QUADS); quad_small(); glEnd(); glBegin(GL_QUADS); quad_right(0.5f); glEnd();
   probe_expect("clipped quad in the next glBegin/glEnd of the batch: v1-v3 diagonal", diag13(3, 9), 1);
   glEnable(GL_POLYGON_OFFSET_FILL);
   glPolygonOffset(1, 1);
   clear0(); glBegin(GL_QUADS); quad_small(); glEnd();
   probe_expect("polygon offset: v1-v3 diagonal", diag13(3, 9), 0);
   glDisable(GL_POLYGON_OFFSET_FILL);
   GLuint idx[4] = { 0, 1, 2, 3 };
   float va[8], ca[12];
   for (int i = 0; i < 4; i++) {
      va[2 * i] = V[i][0] * 0.5f;
      va[2 * i + 1] = V[i][1] * 0.5f;
      for (int c = 0; c < 3; c++) ca[3 * i + c] = C[i][c];
   }
   glEnableClientState(GL_VERTEX_ARRAY);
   glEnableClientState(GL_COLOR_ARRAY);
   glVertexPointer(2, GL_FLOAT, 0, va);
   glColorPointer(3, GL_FLOAT, 0, ca);
   clear0(); glDrawArrays(GL_QUADS, 0, 4);
   probe_expect("glDrawArrays(GL_QUADS): v1-v3 diagonal", diag13(3, 9), 0);
   clear0(); glDrawElements(GL_QUADS, 4, GL_UNSIGNED_INT, idx);
   probe_expect("glDrawElements(GL_QUADS): v1-v3 diagonal", diag13(3, 9), 1);
   return probe_result();
}
