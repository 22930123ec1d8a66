/* c_vertex.c - every glVertex{2,3,4}{s,i,f,d}[v] and glColor{3,4}{b,s,i,
 * f,d,ub,us,ui}[v] entry point, with extreme values; the current colour is
 * queried back after each glColor call. */
#include <math.h>
#include "cases.h"

#include <xmmintrin.h>

/* Cell k of an 8x8 grid of 8-pixel cells in a 64x64 window-ortho view. */
static void cell(int k, double *x, double *y)
{
    *x = 8.0 * (k % 8);
    *y = 8.0 * (k / 8);
}

/* Triangle corners of the current cell (x, y) in a[3][4] of type T. */
#define VTX_SET(T)                                                            \
    for (int i = 0; i < 3; i++) {                                             \
        a[i][0] = (T)(x + (i == 1 ? 7 : 1));                                  \
        a[i][1] = (T)(y + (i == 2 ? 7 : 1));                                  \
        a[i][2] = (T)0;                                                       \
        a[i][3] = (T)1;                                                       \
    }

/* One flat triangle in cell k drawn with vertex call CALL, then next cell. */
#define VTX_DRAW(T, CALL)                                                     \
    do {                                                                      \
        VTX_SET(T)                                                            \
        fcu_color(k);                                                         \
        glBegin(GL_TRIANGLES);                                                \
        for (int i = 0; i < 3; i++)                                           \
            CALL;                                                             \
        glEnd();                                                              \
        cell(++k, &x, &y);                                                    \
    } while (0)

/* All six glVertex variants of one type, each in its own cell. */
#define VTX_CASE(suf, T)                                                      \
    do {                                                                      \
        T a[3][4];                                                            \
        VTX_DRAW(T, glVertex2##suf(a[i][0], a[i][1]));                        \
        VTX_DRAW(T, glVertex2##suf##v(a[i]));                                 \
        VTX_DRAW(T, glVertex3##suf(a[i][0], a[i][1], a[i][2]));               \
        VTX_DRAW(T, glVertex3##suf##v(a[i]));                                 \
        VTX_DRAW(T, glVertex4##suf(a[i][0], a[i][1], a[i][2], a[i][3]));      \
        VTX_DRAW(T, glVertex4##suf##v(a[i]));                                 \
    } while (0)

static void vertex_variants(fc_h *h)
{
    int k = 0;
    double x, y;
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    cell(k, &x, &y);
    VTX_CASE(s, GLshort);
    VTX_CASE(i, GLint);
    VTX_CASE(f, GLfloat);
    VTX_CASE(d, GLdouble);
    /* w != 1 in the free top rows: w = 2 (same points scaled), w = -1
     * everywhere (outside every clip plane) and mixed signs (clipped at w = 0). */
    glColor3f(1, 1, 1);
    glBegin(GL_TRIANGLES);
    glVertex4f(2.0f * 2.5f, 2.0f * 40.5f, 0, 2);
    glVertex4d(20.25 * 2, 42.0 * 2, 0, 2);
    glVertex4s(6, 60, 0, 1);
    glVertex4i(-30, -41, 0, -1);
    glVertex4f(-40.0f, -41.0f, 0, -1);
    glVertex4d(-35.0, -60.0, 0, -1);
    glVertex4f(40.5f, 40.5f, 0, 1);
    glVertex4d(-62.0, -41.0, 0, -1);
    glVertex4s(50, 62, 0, 1);
    glEnd();
    fc_capture(h);
    fc_error(h, "after vertex variants");
}

#define COLOR_TEST(suf, T, lo, hi)                                            \
    do {                                                                      \
        const T v4[4] = { (T)(lo), (T)(hi), (T)0, (T)((hi) / 2) };            \
        const T w4[4] = { (T)((hi) / 3), (T)((lo) / 2), (T)(hi), (T)(lo) };   \
        glColor3##suf(v4[0], v4[1], v4[2]); draw_cell(h, k++);                \
        glColor3##suf##v(w4); draw_cell(h, k++);                              \
        glColor4##suf(v4[0], v4[1], v4[2], v4[3]); draw_cell(h, k++);         \
        glColor4##suf##v(w4); draw_cell(h, k++);                              \
        glColor3##suf((T)((hi) / 4), (T)((hi) / 2 + 1), (T)((hi) - 1)); draw_cell(h, k++); \
    } while (0)

/* Records the current colour and draws one flat 8x8 cell with it. */
static void draw_cell(fc_h *h, int k)
{
    float x = 8.0f * (float)(k % 8), y = 8.0f * (float)(k / 8);
    fc_get_float(h, "GL_CURRENT_COLOR", GL_CURRENT_COLOR, 4);
    fc_get_integer(h, "GL_CURRENT_COLOR i", GL_CURRENT_COLOR, 4);
    fcu_rect(x, y, x + 8, y + 8, 0);
}

static void color_variants(fc_h *h)
{
    int k = 0;
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    COLOR_TEST(b, GLbyte, -128, 127);
    COLOR_TEST(s, GLshort, -32768, 32767);
    COLOR_TEST(i, GLint, -2147483647 - 1, 2147483647);
    COLOR_TEST(ub, GLubyte, 0, 255);
    COLOR_TEST(us, GLushort, 0, 65535);
    COLOR_TEST(ui, GLuint, 0, 4294967295u);
    COLOR_TEST(f, GLfloat, -0.5f, 1.0f);
    COLOR_TEST(d, GLdouble, -1.0, 2.0);
    fc_capture(h);
}

/* Smooth interpolation between extreme integer colours: the conversions
 * feed the rasterizer, not only the queries. */
static void color_integer_smooth(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_SMOOTH);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_QUADS);
    glColor3b(-128, 127, 63); glVertex2f(0, 0);
    glColor3us(65535, 1, 32768); glVertex2f(32, 0);
    glColor3ui(4294967295u, 2147483648u, 16777216u); glVertex2f(32, 32);
    glColor3s(-1, 16384, 32767); glVertex2f(0, 32);
    glEnd();
    fc_capture(h);
}

/* Mesa's vbo batching corner cases: an incomplete GL_TRIANGLES block is not
 * merged with the next one (its tail vertex is dropped, not shifted into
 * the next triangle); a colour first given in the middle of a primitive
 * upgrades the vertex format, and the vertices replayed into the new
 * buffer get the current colour cut to the new size (alpha 1 after
 * glColor3f); the current colour used outside glBegin/glEnd is a constant. */
static void batch_corners(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);                      /* 7 vertices: 2 triangles + 1 */
    glVertex2f(1, 1); glVertex2f(10, 1); glVertex2f(1, 10);
    glVertex2f(12, 1); glVertex2f(20, 1); glVertex2f(12, 10);
    glVertex2f(30, 30);
    glEnd();
    glBegin(GL_TRIANGLES);
    glVertex2f(1, 20); glVertex2f(10, 20); glVertex2f(1, 30);
    glEnd();
    fc_capture(h);

    glColor4f(0.4f, 0.9f, 0.2f, 0.6f);           /* current colour, 4 components */
    glBegin(GL_QUADS);
    glColor4d(0.4, 0.9, 0.13, 0.63);
    glEnd();
    glBegin(GL_POLYGON);                        /* colour added after vertex 0 */
    glVertex2f(2, 2);
    glColor3f(0.3f, 0.7f, 0.3f);
    glVertex2f(30, 4);
    glVertex2f(16, 30);
    glEnd();
    fc_capture(h);
}

/* The oracle draws with denormals flushed to zero (DAZ and FTZ in
 * draw_vbo and the rasterizer), but computes uniforms on the CPU without.
 * Frame 1: x coordinates that are denormal floats (1e-38) under a 4e37 x
 * scale count as 0, so that triangle is degenerate; the one with normal
 * floats (2e-38) is drawn.  Frame 2: a light diffuse of 1e38 times a
 * denormal material diffuse: a constant material makes the product a
 * uniform, computed before the draw (the left quad is lit); a per-vertex
 * material is multiplied in the vertex program, where it counts as 0. */
static void denormals_flushed(fc_h *h)
{
    static const GLfloat zero[4] = { 0, 0, 0, 1 };
    static const GLfloat big[4] = { 1e38f, 1e38f, 1e38f, 1 };
    static const GLfloat tiny[4] = { 5e-39f, 3e-39f, 1e-39f, 1 };
    glViewport(0, 0, 32, 32);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glScalef(4e37f, 1, 1);
    glColor3f(1, 0.5f, 0);
    glBegin(GL_TRIANGLES);
    glVertex2f(-1e-38f, 0.1f); glVertex2f(1e-38f, 0.1f); glVertex2f(1e-38f, 0.9f);
    glVertex2f(-2e-38f, -0.9f); glVertex2f(2e-38f, -0.9f); glVertex2f(2e-38f, -0.1f);
    glEnd();
    fc_capture(h);

    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    glLoadIdentity();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, big);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, tiny);
    glNormal3f(0, 0, 1);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1); glVertex2f(0, -1); glVertex2f(0, 1); glVertex2f(-1, 1);
    glEnd();
    glBegin(GL_QUADS);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, tiny);
    glVertex2f(0, -1); glVertex2f(1, -1); glVertex2f(1, 1); glVertex2f(0, 1);
    glEnd();
    fc_capture(h);
}

/* The floating-point state of triangle setup (ORACLE-NOTES.md
 * "Interpolation", probe p_setup_fpstate, fuzzer seed 3000366): a quad of
 * clip w near 1.5e35, whose colour planes' derivatives are denormal.  The
 * triangles of draw's pipeline (a vertex of the batch needs clipping) are
 * set up in the application's MXCSR (llvmpipe's draw_flush after draw_vbo
 * restored it), the direct ones under FTZ/DAZ, and the pixels are shaded
 * with DAZ.  Frames: the quad alone (direct), then with a clipped triangle
 * in the same glBegin/glEnd (pipeline), then a larger quad drawn with
 * glDrawArrays that is itself clipped; each with the default MXCSR and
 * with FTZ|DAZ set by the program around the draw. */
static const float fp_quad[4][7] = {
    { 64, 32, 1.53420652e+35f, 0.997522652f, 0.00247733132f, 0.0f, 0.0f },
    { 32, 32, 1.5380167e+35f, 1.0f, 0.0f, 0.0f, 0.0f },
    { 64, 64, 1.53041526e+35f, 0.995057583f, 0.00247120927f, 0.00247120927f, 0.0f },
    { 32, 64, 1.53420652e+35f, 0.997522652f, 0.0f, 0.00247733132f, 0.0f },
};

static void fp_vertex(int i, float shift)
{
    const float *q = fp_quad[i];
    const float w = q[2];
    glColor4f(q[3], q[4], q[5], q[6]);
    glVertex4f((2.0f * (q[0] - shift) / 64 - 1.0f) * w, (2.0f * q[1] / 64 - 1.0f) * w, 0.0f, w);
}

static void fp_draw(fc_h *h, int kind, unsigned csr)
{
    static const int tris[2][3] = { { 0, 1, 2 }, { 1, 3, 2 } };
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    const unsigned saved = _mm_getcsr();
    _mm_setcsr(csr);
    if (kind < 2) {
        glBegin(GL_TRIANGLES);
        for (int t = 0; t < 2; t++)
            for (int k = 0; k < 3; k++)
                fp_vertex(tris[t][k], 0.0f);
        if (kind == 1) {
            glColor4f(0, 1, 0, 1);
            glVertex4f(-3.0f, -1.0f, 0.0f, 1.0f);
            glVertex4f(-0.6f, -1.0f, 0.0f, 1.0f);
            glVertex4f(-0.9f, -0.6f, 0.0f, 1.0f);
        }
        glEnd();
    } else {
        /* the quad moved 48 pixels left: its left side is outside */
        GLfloat v[4][8];
        static const int order[4] = { 1, 0, 2, 3 };
        for (int i = 0; i < 4; i++) {
            const float *q = fp_quad[order[i]];
            const float w = q[2];
            v[i][0] = q[3]; v[i][1] = q[4]; v[i][2] = q[5]; v[i][3] = q[6];
            v[i][4] = (2.0f * (q[0] - 48.0f) / 64 - 1.0f) * w;
            v[i][5] = (2.0f * q[1] / 64 - 1.0f) * w;
            v[i][6] = 0.0f;
            v[i][7] = w;
        }
        glEnableClientState(GL_COLOR_ARRAY);
        glEnableClientState(GL_VERTEX_ARRAY);
        glColorPointer(4, GL_FLOAT, 8 * sizeof(GLfloat), &v[0][0]);
        glVertexPointer(4, GL_FLOAT, 8 * sizeof(GLfloat), &v[0][4]);
        glDrawArrays(GL_QUADS, 0, 4);
        glDisableClientState(GL_COLOR_ARRAY);
        glDisableClientState(GL_VERTEX_ARRAY);
    }
    glFinish();
    _mm_setcsr(saved);
    fc_capture(h);
}

static void setup_caller_fpstate(fc_h *h)
{
    const unsigned def = _mm_getcsr() & ~0x8040u, ftz = def | 0x8040u;   /* FTZ | DAZ */
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    for (int kind = 0; kind < 3; kind++) {
        fp_draw(h, kind, def);
        fp_draw(h, kind, ftz);
    }
}

/* ---- large immediate-mode batches ----
 * Batches of thousands of vertices (the vertex stage transforms those of
 * triangles and quads window by window as the primitives reach them,
 * t_render.c LAZY_WINDOW; vsplit's 4096-vertex segments choose the
 * clipped path): a wavy grid that crosses the near plane and the view
 * volume's sides, lit per vertex with a material inside glBegin/glEnd in
 * some, in each mode and in several fill and shade states. */

/* The grid point (i, j) of an n x n grid over [-1.3, 1.3]^2, z waving
 * through the near plane at z = -1 (eye space, frustum near 1). */
static void big_grid_vertex(int i, int j, int n, int lit)
{
    const float x = -1.3f + 2.6f * (float)i / (float)(n - 1);
    const float y = -1.3f + 2.6f * (float)j / (float)(n - 1);
    const float z = -1.6f + 0.75f * sinf(3.1f * x) * cosf(2.3f * y);
    if (lit)
        glNormal3f(-0.5f * cosf(3.1f * x), 0.4f * sinf(2.3f * y), 1.0f);
    else
        glColor3f(0.5f + 0.5f * sinf(7.0f * x), 0.5f + 0.5f * cosf(5.0f * y),
                  (float)((i * 7 + j * 3) % 11) / 10.0f);
    glVertex3f(x, y, z);
}

static void big_setup(int lit)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.8, 0.8, -0.8, 0.8, 1.0, 4.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    if (lit) {
        static const GLfloat pos[4] = { 0.4f, 0.6f, 1.0f, 0.0f };
        static const GLfloat spec[4] = { 1, 1, 1, 1 };
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glLightfv(GL_LIGHT0, GL_POSITION, pos);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    }
}

/* One batch of the grid in `mode`: GL_TRIANGLES and GL_QUADS as one
 * glBegin/glEnd, strips one per grid row (many primitives of one mode in
 * the batch), or one long strip when `one_strip`. */
static void big_grid(GLenum mode, int n, int lit, int materials)
{
    static const GLfloat mat_a[4] = { 0.9f, 0.3f, 0.2f, 1 }, mat_b[4] = { 0.2f, 0.5f, 0.9f, 1 };
    if (mode == GL_TRIANGLES || mode == GL_QUADS) {
        glBegin(mode);
        for (int j = 0; j + 1 < n; j++)
            for (int i = 0; i + 1 < n; i++) {
                if (materials && i % 5 == 0)
                    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (i + j) & 1 ? mat_a : mat_b);
                if (mode == GL_QUADS) {
                    big_grid_vertex(i, j, n, lit);
                    big_grid_vertex(i + 1, j, n, lit);
                    big_grid_vertex(i + 1, j + 1, n, lit);
                    big_grid_vertex(i, j + 1, n, lit);
                } else {
                    big_grid_vertex(i, j, n, lit);
                    big_grid_vertex(i + 1, j, n, lit);
                    big_grid_vertex(i + 1, j + 1, n, lit);
                    big_grid_vertex(i, j, n, lit);
                    big_grid_vertex(i + 1, j + 1, n, lit);
                    big_grid_vertex(i, j + 1, n, lit);
                }
            }
        glEnd();
        return;
    }
    for (int j = 0; j + 1 < n; j++) {
        glBegin(mode);
        for (int i = 0; i < n; i++) {
            if (materials && i % 7 == 0)
                glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (i + j) & 1 ? mat_a : mat_b);
            big_grid_vertex(i, j + (mode == GL_TRIANGLE_STRIP ? 0 : 0), n, lit);
            big_grid_vertex(i, j + 1, n, lit);
        }
        glEnd();
    }
}

/* One long triangle strip of 2 * n * rows vertices (past vsplit's 4096),
 * zig-zagging over the grid's rows. */
static void big_long_strip(int n, int lit)
{
    glBegin(GL_TRIANGLE_STRIP);
    for (int j = 0; j + 1 < n; j++)
        for (int k = 0; k < n; k++) {
            const int i = j & 1 ? n - 1 - k : k;
            big_grid_vertex(i, j, n, lit);
            big_grid_vertex(i, j + 1, n, lit);
        }
    glEnd();
}

static void big_batches(fc_h *h)
{
    static const GLenum modes[4] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_QUADS, GL_QUAD_STRIP };
    big_setup(0);
    for (int m = 0; m < 4; m++) {
        fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
        big_grid(modes[m], 48, 0, 0);
        fc_capture(h);
    }
    glShadeModel(GL_FLAT);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    big_grid(GL_QUAD_STRIP, 48, 0, 0);
    fc_capture(h);
    glShadeModel(GL_SMOOTH);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    big_long_strip(48, 0);
    fc_capture(h);
    fc_error(h, "final");
}

static void big_batches_lit(fc_h *h)
{
    static const GLenum modes[4] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_QUADS, GL_QUAD_STRIP };
    big_setup(1);
    for (int m = 0; m < 4; m++) {
        fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
        big_grid(modes[m], 40, 1, m & 1);
        fc_capture(h);
    }
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    big_long_strip(40, 1);
    fc_capture(h);
    fc_error(h, "final");
}

/* The same batches under a user clip plane, unfilled with edge flags,
 * polygon offset and stipple: draw's pipeline for the segments that
 * need it. */
static void big_batches_pipeline(fc_h *h)
{
    static const GLdouble plane[4] = { 1.0, 0.3, 0.0, 0.2 };
    big_setup(0);
    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    big_grid(GL_TRIANGLES, 40, 0, 0);
    fc_capture(h);
    glDisable(GL_CLIP_PLANE0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    glBegin(GL_QUADS);
    for (int j = 0; j + 1 < 36; j++)
        for (int i = 0; i + 1 < 36; i++) {
            glEdgeFlag((i + j) % 3 != 0);
            big_grid_vertex(i, j, 36, 0);
            big_grid_vertex(i + 1, j, 36, 0);
            big_grid_vertex(i + 1, j + 1, 36, 0);
            big_grid_vertex(i, j + 1, 36, 0);
        }
    glEnd();
    glEdgeFlag(GL_TRUE);
    fc_capture(h);
    glPolygonMode(GL_FRONT, GL_FILL);
    glPolygonMode(GL_BACK, GL_POINT);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 2.0f);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    big_grid(GL_TRIANGLE_STRIP, 40, 0, 0);
    fc_capture(h);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_POLYGON_OFFSET_FILL);
    static GLubyte stipple[128];
    for (int i = 0; i < 128; i++)
        stipple[i] = (GLubyte)(i & 4 ? 0xaa : 0x5c);
    glPolygonStipple(stipple);
    glEnable(GL_POLYGON_STIPPLE);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    big_grid(GL_QUAD_STRIP, 40, 0, 0);
    fc_capture(h);
    glDisable(GL_POLYGON_STIPPLE);
    fc_error(h, "final");
}

const fc_case fc_cases_vertex[] = {
    FC_CASE_RGBA("core/vertex_entry_points", 64, 64, 1, "core vertex", vertex_variants),
    FC_CASE_RGBA("core/color_entry_points", 64, 64, 1, "core vertex query", color_variants),
    FC_CASE_RGBA("core/color_integer_smooth", 32, 32, 1, "core vertex shade", color_integer_smooth),
    FC_CASE_RGBA("core/vbo_batch_corners", 32, 32, 2, "core vertex", batch_corners),
    FC_CASE_RGBA("core/denormals_flushed", 32, 32, 2, "core vertex", denormals_flushed),
    FC_CASE_RGBA("core/setup_caller_fpstate", 64, 64, 6, "core vertex clip", setup_caller_fpstate),
    FC_CASE_RGBA("core/large_batches", 96, 96, 6, "core vertex", big_batches),
    FC_CASE_RGBA("core/large_batches_lit", 96, 96, 5, "core vertex lighting", big_batches_lit),
    FC_CASE_RGBA("core/large_batches_pipeline", 96, 96, 4, "core vertex polygon", big_batches_pipeline),
    { 0 }
};
