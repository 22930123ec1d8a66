/* p_query.c - "Occlusion queries" and "Buffer objects" (ORACLE-NOTES.md).
 *
 * Occlusion queries: the oracle counts a sample for every fragment that
 * passes the scissor, the primitive's own kills (glBitmap's zero bits)
 * and the alpha, stencil and depth tests, whatever the colour mask,
 * blending or logic op do with it; clears (whole, scissored, masked)
 * count nothing; glDrawPixels and glCopyPixels count their fragments.
 * GL_QUERY_RESULT_AVAILABLE is false when first asked after glEndQuery
 * (the question flushes the scene) and true when asked again (with the
 * rasterizer on the calling thread, LP_NUM_THREADS=0: with threads the
 * second answer races them), or after a glFlush, glFinish or
 * glReadPixels; clears and draws in between do not make it available.  The model: the pixel counts of axis-aligned
 * rectangles on pixel edges.
 *
 * Buffer objects: drawing from a mapped buffer raises no error and draws
 * the store; a glDrawElements offset that is not a multiple of the index
 * size draws nothing without an error; a display list keeps the data it
 * compiled; a deleted buffer is unbound from the targets and the arrays.
 * The model: the same drawing from client memory. */
#include "probe.h"

static GLuint result(GLuint q)
{
    GLuint r = 0xdeadbeefu;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &r);
    return r;
}

static GLuint available(GLuint q)
{
    GLuint a = 77;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &a);
    return a;
}

static void rect(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

static GLuint count_rect(GLuint q, float x0, float y0, float x1, float y1, float z)
{
    glBeginQuery(GL_SAMPLES_PASSED, q);
    rect(x0, y0, x1, y1, z);
    glEndQuery(GL_SAMPLES_PASSED);
    return result(q);
}

static void queries(void)
{
    GLuint q = 0;
    glGenQueries(1, &q);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    probe_expect("rect 10x6", count_rect(q, 2, 3, 12, 9, 0), 60);
    glEnable(GL_SCISSOR_TEST);
    glScissor(5, 0, 4, 64);
    probe_expect("scissored rect", count_rect(q, 2, 3, 12, 9, 0), 4 * 6);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    probe_expect("colour mask off counts", count_rect(q, 0, 0, 8, 8, 0), 64);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glColor4f(1, 1, 1, 0.25f);
    probe_expect("alpha test fails", count_rect(q, 0, 0, 8, 8, 0), 0);
    glDisable(GL_ALPHA_TEST);
    glColor4f(1, 1, 1, 1);

    /* depth: a full-window rect at window z 0.5, then one behind, one in
     * front */
    glEnable(GL_DEPTH_TEST);
    rect(0, 0, 64, 64, 0);
    probe_expect("depth fails", count_rect(q, 0, 0, 16, 16, -0.5f), 0);
    probe_expect("depth passes", count_rect(q, 0, 0, 16, 16, 0.5f), 256);
    glDisable(GL_DEPTH_TEST);

    /* stencil: half the window marked */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    rect(0, 0, 32, 64, 0);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    probe_expect("stencil", count_rect(q, 16, 0, 48, 10, 0), 16 * 10);
    glDisable(GL_STENCIL_TEST);

    /* clears count nothing, also scissored or masked ones (which the
     * oracle may draw as a quad) */
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 1, 20, 20);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEndQuery(GL_SAMPLES_PASSED);
    probe_expect("clears", result(q), 0);

    /* pixel rectangles */
    static GLubyte img[5 * 3 * 4];
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2i(10, 10);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glDrawPixels(5, 3, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glEndQuery(GL_SAMPLES_PASSED);
    probe_expect("drawpixels", result(q), 15);
    static const GLubyte bm[4] = { 0xf0, 0x81, 0x00, 0xff };   /* 4 + 2 + 0 + 8 bits */
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glBitmap(8, 4, 0, 0, 0, 0, bm);
    glEndQuery(GL_SAMPLES_PASSED);
    probe_expect("bitmap", result(q), 14);
    glRasterPos2i(30, 30);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glCopyPixels(0, 0, 6, 7, GL_COLOR);
    glEndQuery(GL_SAMPLES_PASSED);
    probe_expect("copypixels", result(q), 42);

    /* availability */
    glBeginQuery(GL_SAMPLES_PASSED, q);
    rect(0, 0, 4, 4, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    probe_expect("available first", available(q), 0);
    probe_expect("available second", available(q), 1);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEndQuery(GL_SAMPLES_PASSED);
    glClear(GL_COLOR_BUFFER_BIT);
    rect(0, 0, 4, 4, 0);
    probe_expect("available after clear and draw", available(q), 0);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEndQuery(GL_SAMPLES_PASSED);
    glFlush();
    probe_expect("available after glFlush", available(q), 1);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEndQuery(GL_SAMPLES_PASSED);
    GLubyte px[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    probe_expect("available after glReadPixels", available(q), 1);
    GLint bits = 0;
    glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &bits);
    probe_expect("counter bits", bits, 64);
    glDeleteQueries(1, &q);
}

/* the colour buffer's bytes after drawing `draw` on a cleared buffer */
static void frame(void (*draw)(void), unsigned char *out)
{
    glClear(GL_COLOR_BUFFER_BIT);
    draw();
    glFinish();
    memcpy(out, g_buf, (size_t)g_w * g_h * 4);
}

static const GLfloat verts[6][2] = { { 2, 2 }, { 60, 5 }, { 30, 58 }, { 40, 3 }, { 63, 40 }, { 10, 40 } };
static GLuint g_vbo;

static void draw_client(void)
{
    glVertexPointer(2, GL_FLOAT, 0, verts);
    glDrawArrays(GL_TRIANGLES, 0, 6);
}

static void draw_mapped(void)
{
    glBindBuffer(GL_ARRAY_BUFFER, g_vbo);
    glVertexPointer(2, GL_FLOAT, 0, NULL);
    glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    probe_expect("draw from a mapped buffer: error", (long)glGetError(), 0);
    glUnmapBuffer(GL_ARRAY_BUFFER);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

static void draw_list(void)
{
    glCallList(1);
}

static void buffers(void)
{
    static unsigned char want[64 * 64 * 4], got[64 * 64 * 4];
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor3f(1, 0.5f, 0.25f);
    glGenBuffers(1, &g_vbo);
    glBindBuffer(GL_ARRAY_BUFFER, g_vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof(verts), verts, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    frame(draw_client, want);
    frame(draw_mapped, got);
    probe_expect("mapped buffer draws its store", memcmp(want, got, sizeof(want)) == 0, 1);

    /* a list keeps the compiled data */
    glBindBuffer(GL_ARRAY_BUFFER, g_vbo);
    glVertexPointer(2, GL_FLOAT, 0, NULL);
    glNewList(1, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glEndList();
    static const GLfloat other[6][2] = { { 0 } };
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(other), other);
    frame(draw_list, got);
    probe_expect("list keeps the compiled data", memcmp(want, got, sizeof(want)) == 0, 1);

    /* a misaligned index offset draws nothing, without an error */
    static const GLushort idx[4] = { 0, 1, 2, 0 };
    GLuint ebo = 0;
    glGenBuffers(1, &ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(idx), idx, GL_STATIC_DRAW);
    glBufferData(GL_ARRAY_BUFFER, sizeof(verts), verts, GL_STATIC_DRAW);
    GLuint q = 0;
    glGenQueries(1, &q);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, (const GLvoid *)1);
    glEndQuery(GL_SAMPLES_PASSED);
    probe_expect("misaligned offset: error", (long)glGetError(), 0);
    probe_expect("misaligned offset: samples", result(q), 0);

    /* deleting unbinds the targets and the arrays */
    glDeleteBuffers(1, &g_vbo);
    GLint v = -1;
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &v);
    probe_expect("deleted: array binding", v, 0);
    glGetIntegerv(GL_VERTEX_ARRAY_BUFFER_BINDING, &v);
    probe_expect("deleted: vertex array binding", v, 0);
    probe_expect("deleted: is buffer", glIsBuffer(g_vbo), 0);
}

int main(void)
{
    /* llvmpipe rasterizing on the calling thread: the answer to a second
     * GL_QUERY_RESULT_AVAILABLE right after a first (which flushed the
     * scene) is then always true; with rasterizer threads it depends on
     * whether they have finished (ORACLE-NOTES.md "Occlusion queries") */
    setenv("LP_NUM_THREADS", "0", 1);
    probe_init_ub(64, 64);
    queries();
    buffers();
    return probe_result();
}
