/* c_varray.c - client-side vertex arrays: every type and size of the
 * vertex, normal and colour arrays (the oracle fetches them in draw's
 * vertex shader through gallivm, with its own normalization of integer
 * colours and normals), strides 0, padded and interleaved, glDrawArrays of
 * every mode from first > 0, glDrawElements and glDrawRangeElements with
 * each index type and repeated, out-of-order indices (llvmpipe's indexed
 * quad split), glArrayElement inside glBegin/glEnd mixed with glColor,
 * lit arrays and colour material, flat shading, edge-flag arrays, the
 * current values after an array draw, and the errors and queries of every
 * entry point. */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

/* A 4 x 4 grid of 16 x 16 cells in a 64 x 64 buffer: cell c's corner. */
static float cell_x(int c) { return 16.0f * (float)(c % 4); }
static float cell_y(int c) { return 16.0f * (float)(c / 4); }

/* ---- vertex array types and sizes ---- */

/* A triangle pair of cell c with vertex values of type T, size n. */
#define FILL_VERTS(T, arr, n, c)                                                      \
    do {                                                                              \
        static const float q[6][3] = { { 1, 1, -0.5f }, { 14, 2, 0.25f }, { 3, 15, 0.75f }, \
                                       { 14, 2, 0.25f }, { 15, 14, -0.9f }, { 3, 15, 0.75f } }; \
        for (int i = 0; i < 6; i++) {                                                 \
            arr[i * n + 0] = (T)(cell_x(c) + q[i][0]);                                \
            arr[i * n + 1] = (T)(cell_y(c) + q[i][1]);                                \
            if (n > 2) arr[i * n + 2] = (T)(q[i][2]);                                 \
            if (n > 3) arr[i * n + 3] = (T)1;                                         \
        }                                                                             \
    } while (0)

static void vertex_types(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    fcu_clear(0, 0, 0, 0, 1);
    static GLshort vs[3][24];
    static GLint vi[3][24];
    static GLfloat vf[3][24];
    static GLdouble vd[3][24];
    glEnableClientState(GL_VERTEX_ARRAY);
    int c = 0;
    for (int n = 2; n <= 4; n++, c++) {
        FILL_VERTS(GLshort, vs[n - 2], n, c);
        fcu_color(c);
        glVertexPointer(n, GL_SHORT, 0, vs[n - 2]);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    for (int n = 2; n <= 4; n++, c++) {
        FILL_VERTS(GLint, vi[n - 2], n, c);
        fcu_color(c);
        glVertexPointer(n, GL_INT, 0, vi[n - 2]);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    for (int n = 2; n <= 4; n++, c++) {
        FILL_VERTS(GLfloat, vf[n - 2], n, c);
        for (int i = 0; i < 6; i++) {
            vf[n - 2][i * n] += 0.3f;
            vf[n - 2][i * n + 1] += 0.45f;
        }
        fcu_color(c);
        glVertexPointer(n, GL_FLOAT, 0, vf[n - 2]);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    for (int n = 2; n <= 4; n++, c++) {
        FILL_VERTS(GLdouble, vd[n - 2], n, c);
        for (int i = 0; i < 6; i++) {
            vd[n - 2][i * n] += 0.1234567891;
            vd[n - 2][i * n + 1] += 0.987654321;
            if (n == 4)
                vd[n - 2][i * n + 3] = 1.0000001;
        }
        fcu_color(c);
        glVertexPointer(n, GL_DOUBLE, 0, vd[n - 2]);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    fc_capture(h);
    fc_error(h, "final");
}

/* ---- colour arrays: every type, 3 and 4 components, extremes ---- */

/* 256 points on a 16 x 16 grid, each in its own colour from the array. */
static void color_points(fc_h *h, GLint size, GLenum type, const void *colors)
{
    static GLfloat pos[256][2];
    for (int i = 0; i < 256; i++) {
        pos[i][0] = 2.0f + 4.0f * (float)(i % 16);
        pos[i][1] = 2.0f + 4.0f * (float)(i / 16);
    }
    fcu_clear(0, 0, 0, 0, 1);
    glPointSize(3.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glColorPointer(size, type, 0, colors);
    glDrawArrays(GL_POINTS, 0, 256);
    fc_capture(h);
}

/* Component k of colour i: a sweep of the type's range with both ends. */
static double sweep(int i, int k, double lo, double hi)
{
    const int j = (i * 4 + k * 37) % 256;
    if (j == 0) return lo;
    if (j == 255) return hi;
    return lo + (hi - lo) * (double)j / 255.0;
}

static void color_types(fc_h *h, GLint size)
{
    fc_pixel_ortho(h);
    static GLbyte cb[256 * 4];
    static GLubyte cub[256 * 4];
    static GLshort cs[256 * 4];
    static GLushort cus[256 * 4];
    static GLint ci[256 * 4];
    static GLuint cui[256 * 4];
    static GLfloat cf[256 * 4];
    static GLdouble cd[256 * 4];
    for (int i = 0; i < 256; i++) {
        for (int k = 0; k < size; k++) {
            const int o = i * size + k;
            cb[o] = (GLbyte)(k == 0 ? i - 128 : sweep(i, k, -128, 127));
            cub[o] = (GLubyte)(k == 0 ? i : sweep(i, k, 0, 255));
            cs[o] = (GLshort)sweep(i, k, -32768, 32767);
            cus[o] = (GLushort)sweep(i, k, 0, 65535);
            ci[o] = (GLint)sweep(i, k, -2147483648.0, 2147483647.0);
            cui[o] = (GLuint)sweep(i, k, 0, 4294967295.0);
            cf[o] = (GLfloat)sweep(i, k, -0.25, 1.25);
            cd[o] = sweep(i, k, -0.1, 1.1) + 1e-9;
        }
    }
    color_points(h, size, GL_BYTE, cb);
    color_points(h, size, GL_UNSIGNED_BYTE, cub);
    color_points(h, size, GL_SHORT, cs);
    color_points(h, size, GL_UNSIGNED_SHORT, cus);
    color_points(h, size, GL_INT, ci);
    color_points(h, size, GL_UNSIGNED_INT, cui);
    color_points(h, size, GL_FLOAT, cf);
    color_points(h, size, GL_DOUBLE, cd);
    fc_error(h, "final");
}

static void color_types4(fc_h *h) { color_types(h, 4); }
static void color_types3(fc_h *h) { color_types(h, 3); }

/* Normalized colours under blending and smooth shading, where the exact
 * float matters more than its 8-bit rounding: GL_ONE, GL_ONE of 17
 * overlapping faint triangles. */
static void color_types_blend(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    static const GLfloat pos[3][2] = { { 1, 1 }, { 63, 5 }, { 9, 62 } };
    static const GLubyte cub[3][4] = { { 1, 3, 5, 7 }, { 127, 128, 129, 254 }, { 13, 77, 200, 255 } };
    static const GLushort cus[3][4] = { { 257, 1000, 40000, 65535 }, { 1, 2, 3, 4 }, { 32767, 32768, 65534, 0 } };
    static const GLbyte cb[3][4] = { { -128, -127, 0, 127 }, { 1, 2, 3, 4 }, { 63, 64, 65, 100 } };
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    for (int r = 0; r < 6; r++) {
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, cub);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glColorPointer(4, GL_UNSIGNED_SHORT, 0, cus);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glColorPointer(4, GL_BYTE, 0, cb);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    fc_capture(h);
    fc_error(h, "final");
}

/* glColorPointer(GL_BGRA, GL_UNSIGNED_BYTE): red and blue swapped. */
static void color_bgra(fc_h *h)
{
    fc_pixel_ortho(h);
    static GLubyte c[256][4];
    for (int i = 0; i < 256; i++) {
        c[i][0] = (GLubyte)i;
        c[i][1] = (GLubyte)(255 - i);
        c[i][2] = (GLubyte)(i * 7);
        c[i][3] = 255;
    }
    color_points(h, GL_BGRA, GL_UNSIGNED_BYTE, c);
    fc_get_integer(h, "GL_COLOR_ARRAY_SIZE", GL_COLOR_ARRAY_SIZE, 1);
    fc_error(h, "final");
}

/* ---- normals ---- */

/* A lit sphere-ish grid of points and triangles with normals of type T. */
static void lit_setup(void)
{
    static const GLfloat pos[4] = { 0.3f, 0.5f, 1.0f, 0.0f };
    static const GLfloat spec[4] = { 1, 1, 1, 1 };
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
}

static void normal_draw(fc_h *h, GLenum type, const void *normals)
{
    static GLfloat pos[64][2];
    for (int i = 0; i < 64; i++) {
        pos[i][0] = 4.0f + 8.0f * (float)(i % 8);
        pos[i][1] = 4.0f + 8.0f * (float)(i / 8);
    }
    fcu_clear(0, 0, 0, 0, 1);
    glPointSize(7.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glNormalPointer(type, 0, normals);
    glDrawArrays(GL_POINTS, 0, 64);
    /* smooth triangles over the points' rows 0..3 */
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 16);
    fc_capture(h);
}

static void normal_types(fc_h *h)
{
    fc_pixel_ortho(h);
    lit_setup();
    static GLbyte nb[64][3];
    static GLshort ns[64][3];
    static GLint ni[64][3];
    static GLfloat nf[64][3];
    static GLdouble nd[64][3];
    for (int i = 0; i < 64; i++) {
        const double v[3] = { sweep(i, 0, -1, 1), sweep(i, 1, -1, 1), 0.2 + 0.8 * sweep(i, 2, 0, 1) };
        for (int k = 0; k < 3; k++) {
            nb[i][k] = (GLbyte)(i == 0 ? -128 : v[k] * 127.0);
            ns[i][k] = (GLshort)(i == 0 ? -32768 : v[k] * 32767.0);
            ni[i][k] = (GLint)(i == 0 ? -2147483647.0 - 1.0 : v[k] * 2147483647.0);
            nf[i][k] = (GLfloat)v[k];
            nd[i][k] = v[k] * 1.7;
        }
    }
    normal_draw(h, GL_BYTE, nb);
    normal_draw(h, GL_SHORT, ns);
    normal_draw(h, GL_INT, ni);
    normal_draw(h, GL_FLOAT, nf);
    glEnable(GL_NORMALIZE);
    normal_draw(h, GL_DOUBLE, nd);
    fc_error(h, "final");
}

/* Lit arrays with colour material following a colour array, then the
 * current colour and material after the draw. */
static void lit_color_material(fc_h *h)
{
    fc_pixel_ortho(h);
    lit_setup();
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glColor4f(0.2f, 0.9f, 0.3f, 1.0f);
    static GLfloat v[16][3], n[16][3];
    static GLubyte c[16][4];
    for (int i = 0; i < 16; i++) {
        v[i][0] = 4.0f + 56.0f * (float)(i % 2) + (float)i;
        v[i][1] = 2.0f + 4.0f * (float)i;
        v[i][2] = 0.0f;
        n[i][0] = 0.1f * (float)(i % 5) - 0.2f;
        n[i][1] = 0.07f * (float)(i % 3);
        n[i][2] = 1.0f;
        c[i][0] = (GLubyte)(i * 16);
        c[i][1] = (GLubyte)(255 - i * 9);
        c[i][2] = (GLubyte)(i * 5 + 100);
        c[i][3] = 255;
    }
    fcu_clear(0, 0, 0, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glNormalPointer(GL_FLOAT, 0, n);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 16);
    fc_capture(h);
    fc_get_float(h, "current colour after", GL_CURRENT_COLOR, 4);
    fc_get_float(h, "current normal after", GL_CURRENT_NORMAL, 3);
    /* the tracked materials follow the current colour, not the array */
    GLfloat mat[2][4];
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, mat[0]);
    glGetMaterialfv(GL_BACK, GL_AMBIENT, mat[1]);
    fc_blob(h, "materials after", mat, sizeof mat);
    /* without the colour array: the current colour as the material */
    glDisableClientState(GL_COLOR_ARRAY);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 16);
    fc_capture(h);
    /* a pending glColor (not yet flushed) becomes current and tracked by
     * the draw's flush; the array's colours do not */
    glBegin(GL_POINTS);
    glColor3f(0.9f, 0.1f, 0.4f);
    glEnd();
    glColor3f(0.3f, 0.3f, 0.8f);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawArrays(GL_POINTS, 0, 1);
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, mat[0]);
    glGetMaterialfv(GL_BACK, GL_AMBIENT, mat[1]);
    fc_blob(h, "materials after a pending colour", mat, sizeof mat);
    fc_get_float(h, "current colour", GL_CURRENT_COLOR, 4);
    /* flat */
    glShadeModel(GL_FLAT);
    glEnableClientState(GL_COLOR_ARRAY);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 16);
    fc_capture(h);
    fc_error(h, "final");
}

/* ---- strides ---- */

struct ivert {
    GLfloat pos[3];
    GLubyte color[4];
    GLshort pad;
    GLfloat normal[3];
};

static void strides(fc_h *h)
{
    fc_pixel_ortho(h);
    static struct ivert iv[8];
    static const float xy[8][2] = { { 2, 2 }, { 30, 4 }, { 4, 30 }, { 32, 32 },
                                    { 6, 60 }, { 34, 62 }, { 62, 10 }, { 60, 58 } };
    for (int i = 0; i < 8; i++) {
        iv[i].pos[0] = xy[i][0];
        iv[i].pos[1] = xy[i][1];
        iv[i].pos[2] = 0.1f * (float)i - 0.4f;
        iv[i].color[0] = (GLubyte)(30 * i);
        iv[i].color[1] = (GLubyte)(200 - 20 * i);
        iv[i].color[2] = (GLubyte)(i & 1 ? 255 : 10);
        iv[i].color[3] = 255;
        iv[i].pad = 0x7777;
    }
    fcu_clear(0, 0, 0, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(struct ivert), iv[0].pos);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct ivert), iv[0].color);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 8);
    fc_capture(h);
    fc_get_integer(h, "vertex stride", GL_VERTEX_ARRAY_STRIDE, 1);
    fc_get_integer(h, "color stride", GL_COLOR_ARRAY_STRIDE, 1);
    /* padded: shorts with a stride of 10 bytes, colours as 3 floats in 16 */
    static GLshort sv[8 * 5];
    static GLfloat fc[8 * 4];
    for (int i = 0; i < 8; i++) {
        sv[i * 5 + 0] = (GLshort)xy[7 - i][0];
        sv[i * 5 + 1] = (GLshort)xy[7 - i][1];
        sv[i * 5 + 2] = -9999;
        fc[i * 4 + 0] = 0.1f * (float)i;
        fc[i * 4 + 1] = 0.9f - 0.1f * (float)i;
        fc[i * 4 + 2] = 0.5f;
        fc[i * 4 + 3] = -7.0f;
    }
    fcu_clear(0, 0, 0, 0, 1);
    glVertexPointer(2, GL_SHORT, 10, sv);
    glColorPointer(3, GL_FLOAT, 16, fc);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 8);
    fc_capture(h);
    fc_error(h, "final");
}

/* ---- modes ---- */

static const float mode_v[12][2] = {
    { 3, 4 }, { 13, 2 }, { 7, 13 }, { 14, 12 }, { 2, 10 }, { 11, 7 },
    { 5, 1 }, { 15, 5 }, { 9, 15 }, { 1, 14 }, { 12, 14 }, { 6, 6 },
};

static void draw_modes(fc_h *h, GLenum shade)
{
    fc_pixel_ortho(h);
    glShadeModel(shade);
    static GLfloat v[10][20][2];
    static GLubyte c[20][4];
    for (int i = 0; i < 20; i++) {
        c[i][0] = (GLubyte)(i * 13 + 40);
        c[i][1] = (GLubyte)(255 - i * 11);
        c[i][2] = (GLubyte)((i * 71) & 255);
        c[i][3] = 255;
    }
    fcu_clear(0, 0, 0, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    for (GLenum m = GL_POINTS; m <= GL_POLYGON; m++) {
        /* cell m; the draw starts at vertex 3 */
        for (int i = 0; i < 12; i++) {
            v[m][i + 3][0] = cell_x((int)m) + mode_v[i][0] * 1.0f + 0.25f;
            v[m][i + 3][1] = cell_y((int)m) + mode_v[i][1] * 1.0f + 0.5f;
        }
        if (m == GL_QUADS || m == GL_QUAD_STRIP || m == GL_POLYGON) {
            /* convex shapes for the polygon types */
            static const float cq[8][2] = { { 1, 1 }, { 14, 2 }, { 15, 9 }, { 2, 8 },
                                            { 2, 9 }, { 14, 10 }, { 13, 15 }, { 1, 14 } };
            static const float cs[8][2] = { { 1, 1 }, { 14, 2 }, { 1, 6 }, { 15, 7 },
                                            { 2, 11 }, { 14, 10 }, { 1, 15 }, { 13, 14 } };
            static const float cp[6][2] = { { 2, 1 }, { 12, 2 }, { 15, 8 }, { 11, 14 }, { 4, 15 }, { 1, 7 } };
            for (int i = 0; i < 8; i++) {
                const float *p = m == GL_QUADS ? cq[i] : m == GL_QUAD_STRIP ? cs[i] : cp[i < 6 ? i : 5];
                v[m][i + 3][0] = cell_x((int)m) + p[0] + 0.25f;
                v[m][i + 3][1] = cell_y((int)m) + p[1] + 0.5f;
            }
        }
        glVertexPointer(2, GL_FLOAT, 0, v[m]);
        const GLsizei count = m == GL_QUADS || m == GL_QUAD_STRIP ? 8 : m == GL_POLYGON ? 6 : 12;
        glDrawArrays(m, 3, count);
    }
    fc_capture(h);
    fc_error(h, "final");
}

static void modes_smooth(fc_h *h) { draw_modes(h, GL_SMOOTH); }
static void modes_flat(fc_h *h) { draw_modes(h, GL_FLAT); }

/* ---- glDrawElements ---- */

static const GLfloat elem_v[9][2] = {
    { 2, 2 }, { 30, 3 }, { 62, 2 }, { 3, 30 }, { 33, 33 }, { 61, 31 }, { 2, 62 }, { 31, 60 }, { 62, 61 },
};
static const GLubyte elem_c[9][4] = {
    { 255, 0, 0, 255 }, { 0, 255, 0, 255 }, { 0, 0, 255, 255 }, { 255, 255, 0, 255 },
    { 255, 0, 255, 255 }, { 0, 255, 255, 255 }, { 128, 64, 32, 255 }, { 32, 64, 128, 255 },
    { 200, 200, 200, 255 },
};

static void elements_draw(fc_h *h, GLenum type, bool range)
{
    /* repeated, out-of-order indices: a quad grid, a fan, strips */
    static const unsigned quads[] = { 0, 1, 4, 3, 4, 5, 2, 1, 3, 4, 7, 6, 5, 8, 7, 4 };
    static const unsigned tris[] = { 4, 0, 1, 4, 2, 5, 8, 4, 5, 6, 4, 7 };
    static const unsigned strip[] = { 6, 3, 7, 4, 8, 5 };
    const struct { GLenum mode; const unsigned *idx; int n; } d[] = {
        { GL_QUADS, quads, 16 }, { GL_TRIANGLES, tris, 12 }, { GL_TRIANGLE_STRIP, strip, 6 },
        { GL_LINE_LOOP, tris, 12 }, { GL_POINTS, quads, 16 }, { GL_QUAD_STRIP, strip, 6 },
        { GL_POLYGON, quads, 4 }, { GL_TRIANGLE_FAN, quads, 8 },
    };
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, elem_v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, elem_c);
    glPointSize(3.0f);
    for (unsigned k = 0; k < sizeof(d) / sizeof(d[0]); k++) {
        GLubyte ib[16];
        GLushort is[16];
        GLuint ii[16];
        for (int i = 0; i < d[k].n; i++) {
            ib[i] = (GLubyte)d[k].idx[i];
            is[i] = (GLushort)d[k].idx[i];
            ii[i] = d[k].idx[i];
        }
        const void *p = type == GL_UNSIGNED_BYTE ? (const void *)ib
                      : type == GL_UNSIGNED_SHORT ? (const void *)is : (const void *)ii;
        fcu_clear(0, 0, 0, 0, 1);
        if (range)
            glDrawRangeElements(d[k].mode, 0, 8, d[k].n, type, p);
        else
            glDrawElements(d[k].mode, d[k].n, type, p);
        fc_capture(h);
    }
}

static void elements_ubyte(fc_h *h) { fc_pixel_ortho(h); elements_draw(h, GL_UNSIGNED_BYTE, false); fc_error(h, "final"); }
static void elements_ushort(fc_h *h) { fc_pixel_ortho(h); glShadeModel(GL_FLAT); elements_draw(h, GL_UNSIGNED_SHORT, false); fc_error(h, "final"); }
static void elements_uint(fc_h *h) { fc_pixel_ortho(h); elements_draw(h, GL_UNSIGNED_INT, false); fc_error(h, "final"); }
static void range_elements(fc_h *h) { fc_pixel_ortho(h); elements_draw(h, GL_UNSIGNED_SHORT, true); fc_error(h, "final"); }

/* The quad diagonal: the same smooth quads through glBegin, glDrawArrays
 * and glDrawElements. */
static void quad_diagonal(fc_h *h)
{
    fc_pixel_ortho(h);
    static const GLfloat v[4][2] = { { 2, 3 }, { 61, 1 }, { 63, 62 }, { 1, 58 } };
    static const GLubyte c[4][4] = { { 255, 0, 0, 255 }, { 0, 255, 0, 255 },
                                     { 0, 0, 255, 255 }, { 255, 255, 255, 255 } };
    static const GLubyte idx[4] = { 0, 1, 2, 3 };
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    for (int f = 0; f < 2; f++) {
        glShadeModel(f ? GL_FLAT : GL_SMOOTH);
        fcu_clear(0, 0, 0, 0, 1);
        glDrawArrays(GL_QUADS, 0, 4);
        fc_capture(h);
        fcu_clear(0, 0, 0, 0, 1);
        glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, idx);
        fc_capture(h);
        fcu_clear(0, 0, 0, 0, 1);
        glBegin(GL_QUADS);
        for (int i = 0; i < 4; i++)
            glArrayElement(i);
        glEnd();
        fc_capture(h);
    }
    fc_error(h, "final");
}

/* ---- glArrayElement ---- */

static void array_element(fc_h *h)
{
    fc_pixel_ortho(h);
    static GLfloat v[12][2];
    static GLubyte c[12][3];
    for (int i = 0; i < 12; i++) {
        v[i][0] = 2.0f + 5.0f * (float)i;
        v[i][1] = i & 1 ? 60.0f : 3.0f;
        c[i][0] = (GLubyte)(i * 20 + 3);
        c[i][1] = (GLubyte)(250 - i * 19);
        c[i][2] = (GLubyte)(i * 111);
    }
    fcu_clear(0, 0, 0, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, c);
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 12; i++) {
        if (i % 3 == 2) {
            /* a glColor call overridden by the array's colour, then a
             * vertex of its own in the glColor colour */
            glColor4f(0.1f, 0.2f, 0.9f, 0.5f);
        }
        glArrayElement(i);
    }
    glEnd();
    fc_capture(h);
    fc_get_float(h, "current colour", GL_CURRENT_COLOR, 4);
    /* only the position array: glColor colours */
    glDisableClientState(GL_COLOR_ARRAY);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 9; i++) {
        glColor3ub((GLubyte)(i * 28), 255, (GLubyte)(255 - i * 28));
        glArrayElement(i);
    }
    glEnd();
    fc_capture(h);
    /* outside glBegin/glEnd: the array's colour becomes current */
    glEnableClientState(GL_COLOR_ARRAY);
    glArrayElement(5);
    fc_error(h, "outside");
    fc_get_float(h, "current colour from element 5", GL_CURRENT_COLOR, 4);
    /* the same data as glDrawArrays (gallivm conversions) */
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 12);
    fc_capture(h);
    fc_get_float(h, "current colour after draw", GL_CURRENT_COLOR, 4);
    fc_error(h, "final");
}

/* glArrayElement with every colour type (immediate-mode conversions). */
static void array_element_types(fc_h *h)
{
    fc_pixel_ortho(h);
    static GLfloat pos[64][2];
    static GLbyte cb[64][4];
    static GLushort cus[64][4];
    static GLint ci[64][4];
    static GLuint cui[64][4];
    static GLshort cs[64][4];
    for (int i = 0; i < 64; i++) {
        pos[i][0] = 4.0f + 8.0f * (float)(i % 8);
        pos[i][1] = 4.0f + 8.0f * (float)(i / 8);
        for (int k = 0; k < 4; k++) {
            cb[i][k] = (GLbyte)sweep(i, k, -128, 127);
            cus[i][k] = (GLushort)sweep(i, k, 0, 65535);
            ci[i][k] = (GLint)sweep(i, k, -2147483648.0, 2147483647.0);
            cui[i][k] = (GLuint)sweep(i, k, 0, 4294967295.0);
            cs[i][k] = (GLshort)sweep(i, k, -32768, 32767);
        }
    }
    const struct { GLenum type; const void *p; } t[] = {
        { GL_BYTE, cb }, { GL_UNSIGNED_SHORT, cus }, { GL_INT, ci }, { GL_UNSIGNED_INT, cui }, { GL_SHORT, cs },
    };
    glPointSize(6.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    for (int k = 0; k < 5; k++) {
        glColorPointer(4, t[k].type, 0, t[k].p);
        fcu_clear(0, 0, 0, 0, 1);
        glBegin(GL_POINTS);
        for (int i = 0; i < 64; i++)
            glArrayElement(i);
        glEnd();
        fc_capture(h);
    }
    fc_error(h, "final");
}

/* ---- current values, flushing, disabled arrays ---- */

static void current_values(fc_h *h)
{
    fc_pixel_ortho(h);
    static const GLfloat v[3][2] = { { 2, 2 }, { 60, 10 }, { 20, 60 } };
    static const GLfloat c[3][4] = { { 1, 0, 0, 1 }, { 0, 1, 0, 1 }, { 0, 0, 1, 1 } };
    static const GLfloat n[3][3] = { { 0, 1, 0 }, { 1, 0, 0 }, { 0, 0, -1 } };
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    glNormal3f(0.5f, 0.5f, 0.5f);
    fcu_clear(0, 0, 0, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(4, GL_FLOAT, 0, c);
    glNormalPointer(GL_FLOAT, 0, n);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fc_get_float(h, "colour after draw", GL_CURRENT_COLOR, 4);
    fc_get_float(h, "normal after draw", GL_CURRENT_NORMAL, 3);
    /* colour array off: the current colour, as a constant */
    glDisableClientState(GL_COLOR_ARRAY);
    glTranslatef(3.0f, 1.0f, 0.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fc_capture(h);
    /* an immediate-mode batch is drawn before the array draw: depth
     * GL_ALWAYS makes the order visible */
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 0);
    glVertex2f(0, 0); glVertex2f(64, 0); glVertex2f(0, 64);
    glEnd();
    glColor3f(0, 1, 1);   /* pending current value */
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fc_capture(h);
    /* no vertex array: nothing is drawn, no error */
    glDisableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fc_error(h, "no vertex array");
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_VERTEX_ARRAY);   /* glEnable works for client state too */
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDrawArrays(GL_TRIANGLES, 0, 0);
    fc_capture(h);
    fc_error(h, "final");
}

/* Edge-flag arrays under glPolygonMode(GL_LINE). */
static void edge_flags(fc_h *h)
{
    fc_pixel_ortho(h);
    static const GLfloat v[8][2] = { { 4, 4 }, { 30, 5 }, { 29, 30 }, { 5, 28 },
                                     { 34, 34 }, { 60, 35 }, { 59, 60 }, { 35, 58 } };
    static const GLboolean e[8] = { 1, 0, 1, 1, 0, 1, 2, 1 };
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    fcu_clear(0, 0, 0, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEdgeFlagPointer(0, e);
    glDrawArrays(GL_QUADS, 0, 8);
    glDrawArrays(GL_TRIANGLES, 1, 6);
    fc_capture(h);
    fc_get_boolean(h, "current edge flag", GL_EDGE_FLAG, 1);
    fc_error(h, "final");
}

/* Vertices outside the view: clipping (draw's pipeline) on array draws. */
static void clipped(fc_h *h)
{
    fc_pixel_ortho(h);
    static const GLfloat v[8][3] = { { -20, 4, 0 }, { 70, 8, 0.5f }, { 30, 90, -0.5f }, { 60, 60, 3 },
                                     { 2, 30, 0 }, { 50, -10, 0 }, { 90, 50, 0 }, { 20, 62, -2 } };
    static const GLubyte c[8][4] = { { 255, 0, 0, 255 }, { 0, 255, 0, 255 }, { 0, 0, 255, 255 },
                                     { 255, 255, 0, 255 }, { 0, 255, 255, 255 }, { 255, 0, 255, 255 },
                                     { 90, 90, 90, 255 }, { 200, 100, 0, 255 } };
    static const GLushort idx[8] = { 0, 1, 3, 2, 4, 5, 6, 7 };
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_QUADS, 0, 8);
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawElements(GL_QUADS, 8, GL_UNSIGNED_SHORT, idx);
    fc_capture(h);
    fc_error(h, "final");
}

/* ---- half floats and packed 2_10_10_10 types ---- */

/* binary16 of a float that a half holds exactly (or nearly) */
static GLushort to_half(float f)
{
    union { float f; uint32_t u; } x = { f };
    const uint32_t sign = (x.u >> 16) & 0x8000u;
    const int e = (int)((x.u >> 23) & 0xff) - 127 + 15;
    if (f == 0.0f)
        return (GLushort)sign;
    if (e <= 0)
        return (GLushort)(sign | ((x.u & 0x7fffffu) | 0x800000u) >> (14 - e));
    return (GLushort)(sign | (uint32_t)e << 10 | ((x.u >> 13) & 0x3ffu));
}

static GLuint pack2101010(int r, int g, int b, int a)
{
    return ((GLuint)r & 0x3ffu) | ((GLuint)g & 0x3ffu) << 10 | ((GLuint)b & 0x3ffu) << 20 |
           ((GLuint)a & 3u) << 30;
}

static void half_packed(fc_h *h)
{
    fc_pixel_ortho(h);
    static GLushort hv[64][4], hc[64][4];
    static GLuint uc[64], ic[64], in[64], iv[64];
    static GLfloat pos[64][2];
    for (int i = 0; i < 64; i++) {
        pos[i][0] = 4.0f + 8.0f * (float)(i % 8);
        pos[i][1] = 4.0f + 8.0f * (float)(i / 8);
        hv[i][0] = to_half(pos[i][0] + 0.375f);
        hv[i][1] = to_half(pos[i][1] - 0.125f);
        hv[i][2] = to_half(0.5f - (float)i / 64.0f);
        hv[i][3] = to_half(1.0f);
        for (int k = 0; k < 4; k++)
            hc[i][k] = to_half((float)sweep(i, k, -0.5, 1.5));
        uc[i] = pack2101010((int)sweep(i, 0, 0, 1023), (int)sweep(i, 1, 0, 1023),
                            (int)sweep(i, 2, 0, 1023), i & 3);
        ic[i] = pack2101010((int)sweep(i, 0, -512, 511), (int)sweep(i, 1, -512, 511),
                            (int)sweep(i, 2, -512, 511), (i & 3) - 2);
        in[i] = pack2101010((int)sweep(i, 0, -512, 511), (int)sweep(i, 1, -512, 511),
                            200 + i * 4, 1);
        iv[i] = pack2101010((int)pos[i][0], (int)pos[i][1], i - 32, 1);
    }
    glPointSize(5.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    /* half positions and colours */
    glVertexPointer(4, GL_HALF_FLOAT, 0, hv);
    glColorPointer(4, GL_HALF_FLOAT, 0, hc);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_POINTS, 0, 64);
    fc_capture(h);
    /* packed colours, RGBA and BGRA order */
    glVertexPointer(2, GL_FLOAT, 0, pos);
    const struct { GLint size; GLenum type; const GLuint *p; } t[4] = {
        { 4, GL_UNSIGNED_INT_2_10_10_10_REV, uc }, { 4, GL_INT_2_10_10_10_REV, ic },
        { GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, uc }, { GL_BGRA, GL_INT_2_10_10_10_REV, ic },
    };
    for (int k = 0; k < 4; k++) {
        glColorPointer(t[k].size, t[k].type, 0, t[k].p);
        fcu_clear(0, 0, 0, 0, 1);
        glDrawArrays(GL_POINTS, 0, 64);
        fc_capture(h);
    }
    /* packed positions (not normalized), lit; glNormalPointer refuses the
     * packed types (its size 3 is not 4) and keeps the float array */
    static GLfloat nf[64][3];
    for (int i = 0; i < 64; i++) {
        nf[i][0] = (float)sweep(i, 0, -1, 1);
        nf[i][1] = (float)sweep(i, 1, -1, 1);
        nf[i][2] = 1.0f;
    }
    glDisableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    lit_setup();
    glVertexPointer(4, GL_INT_2_10_10_10_REV, 0, iv);
    glNormalPointer(GL_FLOAT, 0, nf);
    glNormalPointer(GL_INT_2_10_10_10_REV, 0, in);
    fc_error(h, "packed normals");
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_POINTS, 0, 64);
    fc_capture(h);
    fc_error(h, "final");
}

/* glArrayElement of the types the immediate path reads its own way:
 * half floats (TYPE_IDX), GL_BGRA colours (honesty: GL 3.0 and 3.2). */
static void array_element_quirks(fc_h *h)
{
    fc_pixel_ortho(h);
    static GLfloat pos[64][2];
    static GLushort hc[64][4];
    static GLubyte bc[64][4];
    for (int i = 0; i < 64; i++) {
        pos[i][0] = 4.0f + 8.0f * (float)(i % 8);
        pos[i][1] = 4.0f + 8.0f * (float)(i / 8);
        for (int k = 0; k < 4; k++) {
            hc[i][k] = to_half((float)sweep(i, k, 0.0, 1.0));
            bc[i][k] = (GLubyte)sweep(i, k, 0, 255);
        }
    }
    glPointSize(6.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    /* a GL 1.5 array first: fixgl (GL 1.5) refuses the next two and
     * glArrayElement reads this one (an enabled array without a pointer
     * would crash it, as it does the oracle) */
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, bc);
    glColorPointer(GL_BGRA, GL_UNSIGNED_BYTE, 0, bc);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_POINTS);
    for (int i = 0; i < 64; i++)
        glArrayElement(i);
    glEnd();
    fc_capture(h);
    glColorPointer(4, GL_HALF_FLOAT, 0, hc);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_POINTS);
    for (int i = 0; i < 64; i++)
        glArrayElement(i);
    glEnd();
    fc_capture(h);
    fc_error(h, "final");
}

/* Long draws: vsplit's segments of glDrawArrays and glDrawElements, with
 * one vertex in the middle that needs clipping (smooth quads change their
 * diagonal in the segment that takes draw's pipeline). */
static void long_draws(fc_h *h)
{
    fc_pixel_ortho(h);
    enum { N = 9000 };
    static GLfloat v[N][2];
    static GLubyte c[N][4];
    static GLuint idx[N];
    for (int i = 0; i < N; i++) {
        const int q = i / 4, k = i % 4;
        const float x = (float)(q % 30) * 2.0f + 2.0f, y = (float)((q / 30) % 30) * 2.0f + 2.0f;
        v[i][0] = x + (k == 1 || k == 2 ? 1.8f : 0.1f);
        v[i][1] = y + (k >= 2 ? 1.7f : 0.2f);
        c[i][0] = (GLubyte)(i * 7);
        c[i][1] = (GLubyte)(i * 13 + 50);
        c[i][2] = (GLubyte)(k * 80);
        c[i][3] = 255;
        idx[i] = (GLuint)i;
    }
    v[5001][0] = -30.0f;   /* clipped: the segment 4096..8191 takes the pipeline */
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_QUADS, 0, N);
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawElements(GL_QUADS, N, GL_UNSIGNED_INT, idx);
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 2, N - 2);
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawElements(GL_TRIANGLES, N, GL_UNSIGNED_INT, idx);
    fc_capture(h);
    fc_error(h, "final");
}

/* glInterleavedArrays: every format drawn (untextured: the texture
 * coordinates are fetched but not used), the arrays it enables and the
 * strides it stores; errors. */
static void interleaved(fc_h *h)
{
    fc_pixel_ortho(h);
    lit_setup();
    glDisable(GL_LIGHTING);
    static const GLenum formats[14] = {
        GL_V2F, GL_V3F, GL_C4UB_V2F, GL_C4UB_V3F, GL_C3F_V3F, GL_N3F_V3F, GL_C4F_N3F_V3F,
        GL_T2F_V3F, GL_T4F_V4F, GL_T2F_C4UB_V3F, GL_T2F_C3F_V3F, GL_T2F_N3F_V3F,
        GL_T2F_C4F_N3F_V3F, GL_T4F_C4F_N3F_V4F,
    };
    /* per format: t, c (ubyte?), n, v components, as the layouts */
    static const struct { int t, c, cub, n, v; } lay[14] = {
        { 0, 0, 0, 0, 2 }, { 0, 0, 0, 0, 3 }, { 0, 4, 1, 0, 2 }, { 0, 4, 1, 0, 3 },
        { 0, 3, 0, 0, 3 }, { 0, 0, 0, 3, 3 }, { 0, 4, 0, 3, 3 }, { 2, 0, 0, 0, 3 },
        { 4, 0, 0, 0, 4 }, { 2, 4, 1, 0, 3 }, { 2, 3, 0, 0, 3 }, { 2, 0, 0, 3, 3 },
        { 2, 4, 0, 3, 3 }, { 4, 4, 0, 3, 4 },
    };
    static GLfloat buf[14][4 * 20];
    fcu_clear(0, 0, 0, 0, 1);
    glColor3f(0.6f, 0.6f, 0.6f);
    for (int k = 0; k < 14; k++) {
        /* 4 vertices of a quad in cell k, with a padded stride of 20 floats
         * for odd k and the default one for even k */
        const int words = lay[k].t + (lay[k].cub ? 1 : lay[k].c) + lay[k].n + lay[k].v;
        const int stride = k & 1 ? 20 : words;
        static const float q[4][2] = { { 1, 1 }, { 14, 2 }, { 15, 14 }, { 2, 15 } };
        for (int i = 0; i < 4; i++) {
            GLfloat *w = &buf[k][i * stride];
            int o = 0;
            for (int j = 0; j < lay[k].t; j++)
                w[o++] = 0.5f;
            if (lay[k].cub) {
                const GLubyte cb[4] = { (GLubyte)(60 * i), (GLubyte)(255 - 60 * i), (GLubyte)(k * 18), 255 };
                memcpy(&w[o++], cb, 4);
            } else {
                for (int j = 0; j < lay[k].c; j++)
                    w[o++] = (float)((i + j + k) % 4) / 3.0f;
            }
            for (int j = 0; j < lay[k].n; j++)
                w[o++] = j == 2 ? 1.0f : 0.1f * (float)i;
            w[o++] = cell_x(k % 16) + q[i][0] + 0.25f;
            w[o++] = cell_y(k % 16) + q[i][1] + 0.5f;
            if (lay[k].v > 2) w[o++] = 0.1f * (float)i;
            if (lay[k].v > 3) w[o++] = 1.0f;
        }
        if (lay[k].n)
            glEnable(GL_LIGHTING);
        glInterleavedArrays(formats[k], k & 1 ? 20 * (GLsizei)sizeof(GLfloat) : 0, buf[k]);
        glDrawArrays(GL_QUADS, 0, 4);
        glDisable(GL_LIGHTING);
        if (k == 13 || k == 4 || k == 9) {
            char label[48];
            static const GLenum caps[6] = { GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY,
                                            GL_INDEX_ARRAY, GL_TEXTURE_COORD_ARRAY,
                                            GL_EDGE_FLAG_ARRAY };
            for (int i = 0; i < 6; i++) {
                snprintf(label, sizeof(label), "format %d enabled %d", k, i);
                fc_is_enabled(h, label, caps[i]);
            }
            snprintf(label, sizeof(label), "format %d strides", k);
            fc_get_integer(h, label, GL_VERTEX_ARRAY_STRIDE, 1);
            fc_get_integer(h, label, GL_COLOR_ARRAY_STRIDE, 1);
            fc_get_integer(h, label, GL_TEXTURE_COORD_ARRAY_STRIDE, 1);
            fc_get_integer(h, label, GL_TEXTURE_COORD_ARRAY_SIZE, 1);
            fc_get_integer(h, label, GL_COLOR_ARRAY_TYPE, 1);
            void *p = NULL;
            glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
            fc_value(h, label, (long long)((const char *)p - (const char *)buf[k]));
        }
    }
    fc_capture(h);
    glInterleavedArrays(GL_V2F, -1, buf); fc_error(h, "negative stride");
    glInterleavedArrays(GL_RGBA, 0, buf); fc_error(h, "bad format");
    glInterleavedArrays(GL_RGBA, -1, buf); fc_error(h, "bad format and stride");
    glBegin(GL_POINTS);
    glInterleavedArrays(GL_V2F, 0, buf);
    glEnd();
    fc_error(h, "inside glBegin/glEnd");
    fc_get_integer(h, "vertex size unchanged", GL_VERTEX_ARRAY_SIZE, 1);
    fc_error(h, "final");
}

/* glPushClientAttrib/glPopClientAttrib of the vertex arrays and the pixel
 * store: restored arrays draw, masks apart, overflow and underflow. */
static void client_attrib(fc_h *h)
{
    fc_pixel_ortho(h);
    static const GLfloat v[4][2] = { { 2, 2 }, { 60, 4 }, { 62, 60 }, { 3, 58 } };
    static const GLubyte c[4][4] = { { 255, 0, 0, 255 }, { 0, 255, 0, 255 },
                                     { 0, 0, 255, 255 }, { 255, 255, 0, 255 } };
    static const GLshort sv[4][3] = { { 10, 10, 0 }, { 50, 12, 0 }, { 30, 50, 0 }, { 0, 0, 0 } };
    fc_get_integer(h, "max depth", GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glPixelStorei(GL_PACK_ROW_LENGTH, 7);
    glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    fc_get_integer(h, "depth 1", GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
    glDisableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_SHORT, 0, sv);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glPopClientAttrib();
    fc_get_integer(h, "unpack alignment 8", GL_UNPACK_ALIGNMENT, 1);
    fc_is_enabled(h, "edge flag array kept", GL_EDGE_FLAG_ARRAY);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);
    fcu_clear(0, 0, 0, 0, 1);
    glColor3f(0.5f, 0.5f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fc_capture(h);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glPopClientAttrib();
    glPopClientAttrib();
    fc_get_integer(h, "depth 0", GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
    fc_get_integer(h, "unpack alignment 2", GL_UNPACK_ALIGNMENT, 1);
    fc_get_integer(h, "pack row length 7", GL_PACK_ROW_LENGTH, 1);
    fc_is_enabled(h, "colour array back", GL_COLOR_ARRAY);
    fc_get_integer(h, "vertex size 2", GL_VERTEX_ARRAY_SIZE, 1);
    void *p = NULL;
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
    fc_value(h, "vertex pointer back", p == (const void *)v);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_QUADS, 0, 4);
    fc_capture(h);
    glPopClientAttrib();
    fc_error(h, "underflow");
    for (int i = 0; i < 17; i++)
        glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    fc_error(h, "overflow");
    fc_get_integer(h, "depth 16", GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
    glBegin(GL_POINTS);
    glPopClientAttrib();
    glEnd();
    fc_error(h, "pop inside glBegin/glEnd");
    glBegin(GL_POINTS);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glEnd();
    fc_error(h, "push inside glBegin/glEnd");
    fc_get_integer(h, "still 16", GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
    for (int i = 0; i < 16; i++)
        glPopClientAttrib();
    glPushClientAttrib(0x10);   /* no client bit */
    glPopClientAttrib();
    fc_error(h, "final");
}

/* An enabled colour or normal array whose pointer was never set (NULL):
 * the oracle reads no buffer (zeros), fixgl must not crash. */
static void null_pointer(fc_h *h)
{
    fc_pixel_ortho(h);
    static const GLfloat v[3][2] = { { 2, 2 }, { 60, 10 }, { 20, 60 } };
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColor3f(0.5f, 0.75f, 1.0f);
    glEnableClientState(GL_COLOR_ARRAY);
    fcu_clear(0.2f, 0.2f, 0.2f, 0.2f, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fc_capture(h);
    glDisableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    lit_setup();
    fcu_clear(0.2f, 0.2f, 0.2f, 0.2f, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fc_capture(h);
    fc_error(h, "final");
}

/* ---- errors and queries ---- */

static void pointer_errors(fc_h *h)
{
    static GLfloat data[64];
    glVertexPointer(1, GL_FLOAT, 0, data); fc_error(h, "vertex size 1");
    glVertexPointer(5, GL_FLOAT, 0, data); fc_error(h, "vertex size 5");
    glVertexPointer(3, GL_UNSIGNED_BYTE, 0, data); fc_error(h, "vertex ubyte");
    glVertexPointer(3, GL_BYTE, 0, data); fc_error(h, "vertex byte");
    glVertexPointer(5, GL_BYTE, 0, data); fc_error(h, "vertex bad type and size");
    glVertexPointer(3, GL_FLOAT, -4, data); fc_error(h, "vertex negative stride");
    fc_get_integer(h, "vertex stride after negative", GL_VERTEX_ARRAY_STRIDE, 1);
    glVertexPointer(3, GL_FLOAT, -4, data + 1); fc_error(h, "vertex negative stride again");
    glVertexPointer(GL_BGRA, GL_UNSIGNED_BYTE, 0, data); fc_error(h, "vertex bgra");
    glNormalPointer(GL_UNSIGNED_BYTE, 0, data); fc_error(h, "normal ubyte");
    glNormalPointer(GL_UNSIGNED_SHORT, 0, data); fc_error(h, "normal ushort");
    glNormalPointer(GL_FLOAT, -1, data); fc_error(h, "normal negative stride");
    glNormalPointer(GL_BYTE, -1, data); fc_error(h, "normal negative stride, byte");
    glColorPointer(2, GL_FLOAT, 0, data); fc_error(h, "colour size 2");
    glColorPointer(5, GL_FLOAT, 0, data); fc_error(h, "colour size 5");
    glColorPointer(4, GL_BOOL, 0, data); fc_error(h, "colour bool");
    glTexCoordPointer(0, GL_FLOAT, 0, data); fc_error(h, "texcoord size 0");
    glTexCoordPointer(2, GL_UNSIGNED_BYTE, 0, data); fc_error(h, "texcoord ubyte");
    glIndexPointer(GL_BYTE, 0, data); fc_error(h, "index byte");
    glIndexPointer(GL_UNSIGNED_BYTE, -3, data); fc_error(h, "index negative stride");
    glEdgeFlagPointer(-1, data); fc_error(h, "edge flag negative stride");
    glEnableClientState(GL_LIGHTING); fc_error(h, "enable client lighting");
    glDisableClientState(0x1234); fc_error(h, "disable client bad");
    glBegin(GL_TRIANGLES);
    glVertexPointer(2, GL_FLOAT, 0, data);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnd();
    fc_error(h, "pointer and client state inside glBegin/glEnd");
    fc_is_enabled(h, "colour array", GL_COLOR_ARRAY);
    fc_get_integer(h, "vertex size", GL_VERTEX_ARRAY_SIZE, 1);
    void *p = (void *)1;
    glGetPointerv(0x1234, &p); fc_error(h, "getpointerv bad");
    fc_value(h, "getpointerv bad leaves value", p == (void *)1);
    fc_error(h, "final");
}

static void draw_errors(fc_h *h)
{
    fc_pixel_ortho(h);
    static const GLfloat v[3][2] = { { 2, 2 }, { 60, 10 }, { 20, 60 } };
    static const GLubyte idx[3] = { 0, 1, 2 };
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_TRIANGLES, 0, -1); fc_error(h, "arrays count -1");
    glDrawArrays(0x20, 0, 3); fc_error(h, "arrays mode 0x20");
    glDrawArrays(0x20, 0, -1); fc_error(h, "arrays bad mode and count");
    glDrawElements(GL_TRIANGLES, -1, GL_UNSIGNED_BYTE, idx); fc_error(h, "elements count -1");
    glDrawElements(0x20, 3, GL_UNSIGNED_BYTE, idx); fc_error(h, "elements bad mode");
    glDrawElements(GL_TRIANGLES, 3, GL_BYTE, idx); fc_error(h, "elements byte");
    glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, idx); fc_error(h, "elements float");
    glDrawElements(0x20, 3, GL_FLOAT, idx); fc_error(h, "elements bad mode and type");
    glDrawElements(GL_TRIANGLES, -1, GL_FLOAT, idx); fc_error(h, "elements bad count and type");
    glDrawRangeElements(GL_TRIANGLES, 2, 1, 3, GL_UNSIGNED_BYTE, idx); fc_error(h, "range end < start");
    glDrawRangeElements(0x20, 2, 1, 3, GL_FLOAT, idx); fc_error(h, "range end < start, bad mode");
    glDrawRangeElements(GL_TRIANGLES, 0, 2, -1, GL_UNSIGNED_BYTE, idx); fc_error(h, "range count -1");
    glDrawRangeElements(GL_TRIANGLES, 0, 2, 3, GL_SHORT, idx); fc_error(h, "range short");
    glDrawRangeElements(0x20, 0, 2, 3, GL_UNSIGNED_BYTE, idx); fc_error(h, "range bad mode");
    glBegin(GL_POINTS);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnd();
    fc_error(h, "arrays inside glBegin/glEnd");
    glBegin(GL_POINTS);
    glDrawArrays(0x20, 0, 3);
    glEnd();
    fc_error(h, "arrays bad mode inside glBegin/glEnd");
    glBegin(GL_POINTS);
    glDrawArrays(GL_TRIANGLES, 0, -3);
    glEnd();
    fc_error(h, "arrays count -3 inside glBegin/glEnd");
    glBegin(GL_POINTS);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, idx);
    glEnd();
    fc_error(h, "elements inside glBegin/glEnd");
    glBegin(GL_POINTS);
    glDrawRangeElements(GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_BYTE, idx);
    glEnd();
    fc_error(h, "range inside glBegin/glEnd");
    glBegin(GL_POINTS);
    glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, idx);
    glEnd();
    fc_error(h, "elements float inside glBegin/glEnd");
    /* nothing was drawn */
    fc_capture(h);
    fc_error(h, "final");
}

static void queries(fc_h *h)
{
    static const GLenum caps[6] = { GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY,
                                    GL_INDEX_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY };
    static const GLenum pnames[] = {
        GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE,
        GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE,
        GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE,
        GL_INDEX_ARRAY_TYPE, GL_INDEX_ARRAY_STRIDE,
        GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY_STRIDE,
        GL_EDGE_FLAG_ARRAY_STRIDE,
    };
    static const GLenum ptrs[6] = { GL_VERTEX_ARRAY_POINTER, GL_NORMAL_ARRAY_POINTER,
                                    GL_COLOR_ARRAY_POINTER, GL_INDEX_ARRAY_POINTER,
                                    GL_TEXTURE_COORD_ARRAY_POINTER, GL_EDGE_FLAG_ARRAY_POINTER };
    static GLdouble data[64];
    for (int pass = 0; pass < 3; pass++) {
        char label[64];
        for (int i = 0; i < 6; i++) {
            snprintf(label, sizeof(label), "pass %d enabled %d", pass, i);
            fc_is_enabled(h, label, caps[i]);
            fc_get_boolean(h, label, caps[i], 1);
            void *p = (void *)1;
            glGetPointerv(ptrs[i], &p);
            snprintf(label, sizeof(label), "pass %d pointer %d", pass, i);
            fc_value(h, label, p == NULL ? 0 : (long long)((const char *)p - (const char *)data) + 1000);
        }
        for (unsigned i = 0; i < sizeof(pnames) / sizeof(pnames[0]); i++) {
            snprintf(label, sizeof(label), "pass %d pname %u", pass, i);
            fc_get_integer(h, label, pnames[i], 1);
            fc_get_float(h, label, pnames[i], 1);
        }
        if (pass == 0) {
            for (int i = 0; i < 6; i++)
                glEnableClientState(caps[i]);
            glVertexPointer(2, GL_SHORT, 6, data);
            glNormalPointer(GL_BYTE, 3, (const char *)data + 1);
            glColorPointer(3, GL_UNSIGNED_SHORT, 0, data + 2);
            glIndexPointer(GL_UNSIGNED_BYTE, 7, data + 3);
            glTexCoordPointer(1, GL_DOUBLE, 100, data + 4);
            glEdgeFlagPointer(9, data + 5);
        } else if (pass == 1) {
            for (int i = 0; i < 6; i += 2)
                glDisable(caps[i]);
            glVertexPointer(4, GL_DOUBLE, 0, data + 6);
            glNormalPointer(GL_INT, 0, data);
            glColorPointer(4, GL_UNSIGNED_INT, 12, data);
            glTexCoordPointer(3, GL_SHORT, 0, data + 7);
        }
    }
    void *p = (void *)1;
    glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &p);
    fc_value(h, "feedback pointer", p == NULL);
    p = (void *)1;
    glGetPointerv(GL_SELECTION_BUFFER_POINTER, &p);
    fc_value(h, "selection pointer", p == NULL);
    glBegin(GL_POINTS);
    p = (void *)1;
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
    glEnd();
    fc_error(h, "getpointerv inside glBegin/glEnd");
    fc_value(h, "getpointerv inside glBegin/glEnd value", p == (void *)(data + 6));
    fc_error(h, "final");
}

const fc_case fc_cases_varray[] = {
    FC_CASE_RGBA("varray/vertex_types", 64, 64, 1, "api varray", vertex_types),
    FC_CASE_RGBA("varray/color_types4", 64, 64, 8, "api varray", color_types4),
    FC_CASE_RGBA("varray/color_types3", 64, 64, 8, "api varray", color_types3),
    FC_CASE_RGBA("varray/color_types_blend", 64, 64, 1, "api varray blend", color_types_blend),
    FC_CASE_RGBA("honesty/varray_color_bgra", 64, 64, 1, "honesty api varray", color_bgra),
    FC_CASE_RGBA("varray/normal_types", 64, 64, 5, "api varray lighting", normal_types),
    FC_CASE_RGBA("varray/lit_color_material", 64, 64, 3, "api varray lighting", lit_color_material),
    FC_CASE_RGBA("varray/strides", 64, 64, 2, "api varray", strides),
    FC_CASE_RGBA("varray/modes_smooth", 64, 64, 1, "api varray", modes_smooth),
    FC_CASE_RGBA("varray/modes_flat", 64, 64, 1, "api varray", modes_flat),
    FC_CASE_RGBA("varray/elements_ubyte", 64, 64, 8, "api varray", elements_ubyte),
    FC_CASE_RGBA("varray/elements_ushort_flat", 64, 64, 8, "api varray", elements_ushort),
    FC_CASE_RGBA("varray/elements_uint", 64, 64, 8, "api varray", elements_uint),
    FC_CASE_RGBA("varray/range_elements", 64, 64, 8, "api varray", range_elements),
    FC_CASE_RGBA("varray/quad_diagonal", 64, 64, 6, "api varray", quad_diagonal),
    FC_CASE_RGBA("varray/array_element", 64, 64, 3, "api varray", array_element),
    FC_CASE_RGBA("varray/array_element_types", 64, 64, 5, "api varray", array_element_types),
    FC_CASE_RGBA("varray/current_values", 64, 64, 3, "api varray", current_values),
    FC_CASE_RGBA("varray/edge_flags", 64, 64, 1, "api varray polygon_mode", edge_flags),
    FC_CASE_RGBA("varray/clipped", 64, 64, 2, "api varray clip", clipped),
    FC_CASE_RGBA("honesty/varray_half_packed", 64, 64, 6, "honesty api varray lighting", half_packed),
    FC_CASE_RGBA("honesty/varray_array_element_quirks", 64, 64, 2, "honesty api varray", array_element_quirks),
    FC_CASE_RGBA("varray/long_draws", 64, 64, 4, "api varray clip", long_draws),
    FC_CASE_RGBA("varray/interleaved", 64, 64, 1, "api varray errors query", interleaved),
    FC_CASE_RGBA("varray/client_attrib", 64, 64, 2, "api varray errors query", client_attrib),
    FC_CASE_RGBA("varray/null_pointer", 64, 64, 2, "api varray", null_pointer),
    FC_CASE_RGBA("varray/pointer_errors", 32, 32, 0, "api varray errors query", pointer_errors),
    /* every draw is an error: nothing may show (draws_nothing) */
    FC_CASE_NODRAW("varray/draw_errors", 64, 64, OSMESA_RGBA, 24, 0, 1, "api varray errors", draw_errors),
    FC_CASE_RGBA("varray/queries", 32, 32, 0, "api varray query", queries),
    { 0 }
};
