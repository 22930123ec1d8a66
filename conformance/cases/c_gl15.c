/* c_gl15.c - GL 1.5 buffer objects (tags gl15 vbo) and occlusion queries
 * (tags gl15 query).
 *
 * Buffers: vertex arrays of every kind and glDrawElements indices sourced
 * from buffers at offsets, in each primitive mode and index type, in
 * immediate drawing and compiled into display lists (which keep the data
 * of the compile), glArrayElement, buffers mapped while drawing (no error
 * in the oracle: the store is drawn as it is), deleted while bound (the
 * arrays fall back to client pointers), every GL_*_BUFFER_BINDING,
 * glPushClientAttrib, sharing through OSMesaCreateContext's sharelist,
 * GL_EXT_vertex_array's names, and the errors of every entry point.
 *
 * Queries: the samples that pass (depth, stencil, alpha tests, scissor,
 * colour mask, stipple, smooth points and lines, pixel rectangles),
 * queries spanning clears and display lists, GL_QUERY_RESULT_AVAILABLE as
 * the oracle answers it (false right after glEndQuery until a flush: the
 * first question flushes), and the errors.  The enums of later versions
 * the oracle has (other buffer targets, GL_TIME_ELAPSED, ...) are not
 * used: fixgl raises GL_INVALID_ENUM for them on purpose. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

/* ---- shared data ---- */

/* An interleaved vertex: position (3 floats) and colour (4 ubytes), 16
 * bytes, for a 64 x 64 buffer. */
struct ivert {
    GLfloat x, y, z;
    GLubyte c[4];
};

/* The vertices of each mode's test shape, 12 of them, after 3 leading
 * dummies (the buffer offset skips them). */
static struct ivert g_verts[15];

static void fill_verts(int seed)
{
    static const float p[12][2] = {
        { 4, 4 }, { 30, 6 }, { 58, 3 }, { 6, 30 }, { 33, 29 }, { 60, 33 },
        { 3, 59 }, { 29, 57 }, { 61, 60 }, { 17, 44 }, { 45, 15 }, { 40, 50 },
    };
    memset(g_verts, 0, sizeof(g_verts));
    for (int i = 0; i < 3; i++) {
        g_verts[i].x = 1000.0f;   /* never drawn */
        g_verts[i].c[0] = 255;
    }
    for (int i = 0; i < 12; i++) {
        struct ivert *v = &g_verts[3 + i];
        v->x = p[i][0] + 0.25f * (float)((i + seed) % 3);
        v->y = p[i][1] + 0.125f * (float)((i * 5 + seed) % 4);
        v->z = -0.5f + 0.08f * (float)i;
        v->c[0] = (GLubyte)(37 * (i + seed));
        v->c[1] = (GLubyte)(255 - 23 * i);
        v->c[2] = (GLubyte)(90 + 13 * (i + 2 * seed));
        v->c[3] = 255;
    }
}

/* A buffer holding g_verts bound to GL_ARRAY_BUFFER, the vertex and colour
 * arrays pointing into it past the dummies. */
static GLuint vbo_arrays(void)
{
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, sizeof(g_verts), g_verts, GL_STATIC_DRAW);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(struct ivert), (const GLvoid *)(uintptr_t)(3 * sizeof(struct ivert)));
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct ivert),
                   (const GLvoid *)(uintptr_t)(3 * sizeof(struct ivert) + 12));
    return b;
}

static void setup_scene(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glPointSize(3.0f);
    glLineWidth(2.0f);
    fcu_clear(0.1f, 0.1f, 0.2f, 0, 1);
}

/* ---- glDrawArrays from a buffer, every mode ---- */


static void draw_arrays_mode(fc_h *h, GLenum mode)
{
    setup_scene(h);
    fill_verts((int)mode);
    vbo_arrays();
    glDrawArrays(mode, 0, 12);
    fc_error(h, "draw");
    fc_capture(h);
    /* the same again from first 2 */
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(mode, 2, 9);
    fc_capture(h);
    fc_error(h, "final");
}

#define MODE_CASE(name, mode) \
    static void arrays_##name(fc_h *h) { draw_arrays_mode(h, mode); }
MODE_CASE(points, GL_POINTS)
MODE_CASE(lines, GL_LINES)
MODE_CASE(line_loop, GL_LINE_LOOP)
MODE_CASE(line_strip, GL_LINE_STRIP)
MODE_CASE(triangles, GL_TRIANGLES)
MODE_CASE(triangle_strip, GL_TRIANGLE_STRIP)
MODE_CASE(triangle_fan, GL_TRIANGLE_FAN)
MODE_CASE(quads, GL_QUADS)
MODE_CASE(quad_strip, GL_QUAD_STRIP)
MODE_CASE(polygon, GL_POLYGON)

/* ---- glDrawElements / glDrawRangeElements with an element buffer ---- */

static const unsigned g_idx[16] = { 0, 1, 4, 3, 4, 5, 2, 1, 3, 4, 7, 6, 9, 10, 11, 8 };

/* The indices as `type`, after `lead` dummy indices, in a buffer bound to
 * GL_ELEMENT_ARRAY_BUFFER (or returned in client memory) */
static GLuint index_buffer(GLenum type, int lead, void *client)
{
    GLubyte ib[24];
    GLushort is[24];
    GLuint ii[24];
    for (int i = 0; i < 24; i++) {
        const unsigned v = i < lead ? 11u : i - lead < 16 ? g_idx[i - lead] : 0u;
        ib[i] = (GLubyte)v;
        is[i] = (GLushort)v;
        ii[i] = v;
    }
    const size_t size = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4;
    const void *src = type == GL_UNSIGNED_BYTE ? (const void *)ib
                      : type == GL_UNSIGNED_SHORT ? (const void *)is : (const void *)ii;
    if (client) {
        memcpy(client, src, 24 * size);
        return 0;
    }
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(24 * size), src, GL_STATIC_DRAW);
    return b;
}

enum elt_src { ELT_BOTH_BUFFERS, ELT_CLIENT_INDICES, ELT_CLIENT_ARRAYS };

static void elements_case(fc_h *h, GLenum type, enum elt_src src, bool range)
{
    setup_scene(h);
    fill_verts(5);
    static GLuint client_idx[24];
    const size_t size = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4;
    const int lead = 3;
    const void *indices;
    if (src == ELT_CLIENT_INDICES) {
        vbo_arrays();
        index_buffer(type, lead, client_idx);
        indices = (const GLubyte *)client_idx + lead * size;
    } else {
        index_buffer(type, lead, NULL);
        indices = (const GLvoid *)(uintptr_t)(lead * size);
        if (src == ELT_BOTH_BUFFERS) {
            vbo_arrays();
        } else {
            glEnableClientState(GL_VERTEX_ARRAY);
            glEnableClientState(GL_COLOR_ARRAY);
            glVertexPointer(3, GL_FLOAT, sizeof(struct ivert), &g_verts[3].x);
            glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct ivert), g_verts[3].c);
        }
    }
    static const struct { GLenum mode; int first, n; } d[] = {
        { GL_QUADS, 0, 12 }, { GL_TRIANGLE_STRIP, 4, 8 }, { GL_LINE_LOOP, 0, 16 },
        { GL_POINTS, 0, 16 }, { GL_TRIANGLES, 3, 12 },
    };
    for (unsigned k = 0; k < sizeof(d) / sizeof(d[0]); k++) {
        fcu_clear(0, 0, 0, 0, 1);
        const GLvoid *p = (const GLubyte *)indices + (size_t)d[k].first * size;
        if (range)
            glDrawRangeElements(d[k].mode, 0, 11, d[k].n, type, p);
        else
            glDrawElements(d[k].mode, d[k].n, type, p);
        fc_capture(h);
    }
    fc_error(h, "final");
}

#define ELT_CASE(name, type, src, range) \
    static void elements_##name(fc_h *h) { elements_case(h, type, src, range); }
ELT_CASE(ubyte_buffers, GL_UNSIGNED_BYTE, ELT_BOTH_BUFFERS, false)
ELT_CASE(ushort_buffers, GL_UNSIGNED_SHORT, ELT_BOTH_BUFFERS, false)
ELT_CASE(uint_buffers, GL_UNSIGNED_INT, ELT_BOTH_BUFFERS, false)
ELT_CASE(ubyte_client_indices, GL_UNSIGNED_BYTE, ELT_CLIENT_INDICES, false)
ELT_CASE(ushort_client_indices, GL_UNSIGNED_SHORT, ELT_CLIENT_INDICES, false)
ELT_CASE(uint_client_arrays, GL_UNSIGNED_INT, ELT_CLIENT_ARRAYS, false)
ELT_CASE(ushort_client_arrays, GL_UNSIGNED_SHORT, ELT_CLIENT_ARRAYS, false)
ELT_CASE(range_ubyte, GL_UNSIGNED_BYTE, ELT_BOTH_BUFFERS, true)
ELT_CASE(range_ushort, GL_UNSIGNED_SHORT, ELT_BOTH_BUFFERS, true)
ELT_CASE(range_uint, GL_UNSIGNED_INT, ELT_CLIENT_ARRAYS, true)

/* An element-buffer offset that is not a multiple of the index size: the
 * oracle draws nothing, without an error; indices read up to the last
 * whole one of the store */
static void elements_misaligned(fc_h *h)
{
    setup_scene(h);
    fill_verts(2);
    vbo_arrays();
    index_buffer(GL_UNSIGNED_SHORT, 2, NULL);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, (const GLvoid *)(uintptr_t)3);
    fc_error(h, "misaligned ushort");
    glDrawElements(GL_POINTS, 4, GL_UNSIGNED_SHORT, (const GLvoid *)(uintptr_t)4);
    fc_error(h, "aligned ushort");
    fc_capture(h);
    index_buffer(GL_UNSIGNED_INT, 1, NULL);
    glDrawElements(GL_QUADS, 8, GL_UNSIGNED_INT, (const GLvoid *)(uintptr_t)6);
    fc_error(h, "misaligned uint");
    glDrawElements(GL_QUADS, 8, GL_UNSIGNED_INT, (const GLvoid *)(uintptr_t)8);
    fc_capture(h);
    fc_error(h, "final");
}

/* ---- glArrayElement and display lists ---- */

static void array_element_immediate(fc_h *h)
{
    setup_scene(h);
    fill_verts(7);
    vbo_arrays();
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 9; i++)
        glArrayElement(i);
    glEnd();
    glBegin(GL_LINE_STRIP);
    glColor3f(1, 1, 1);
    glArrayElementEXT(9);
    glArrayElementEXT(10);
    glArrayElementEXT(11);
    glEnd();
    fc_error(h, "final");
    fc_capture(h);
    fc_get_float(h, "current color", GL_CURRENT_COLOR, 4);
}

/* Lists compile the arrays' data (glArrayElement, glDrawArrays,
 * glDrawElements read it at compile time): a change of the buffer after
 * does not reach them */
static void dlist_compiled_data(fc_h *h, GLenum list_mode)
{
    setup_scene(h);
    fill_verts(3);
    GLuint vb = vbo_arrays();
    index_buffer(GL_UNSIGNED_SHORT, 2, NULL);
    glNewList(1, list_mode);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDrawElements(GL_LINE_LOOP, 8, GL_UNSIGNED_SHORT, (const GLvoid *)(uintptr_t)4);
    glDrawRangeElements(GL_POINTS, 0, 11, 10, GL_UNSIGNED_SHORT, (const GLvoid *)(uintptr_t)10);
    glBegin(GL_QUADS);
    for (int i = 6; i < 10; i++)
        glArrayElement(i);
    glEnd();
    glEndList();
    fc_error(h, "compiled");
    fc_capture(h);
    /* the buffer changes, then is deleted: the list still draws its data */
    fill_verts(9);
    glBindBuffer(GL_ARRAY_BUFFER, vb);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(g_verts), g_verts);
    fcu_clear(0, 0, 0, 0, 1);
    glCallList(1);
    fc_capture(h);
    glDeleteBuffers(1, &vb);
    fcu_clear(0, 0, 0, 0, 1);
    glCallList(1);
    fc_capture(h);
    fc_error(h, "final");
}

static void dlist_compile(fc_h *h) { dlist_compiled_data(h, GL_COMPILE); }
static void dlist_compile_execute(fc_h *h) { dlist_compiled_data(h, GL_COMPILE_AND_EXECUTE); }

/* ---- mapped buffers ---- */

/* Drawing from a mapped buffer: no error in the oracle (Mesa 22.3 does
 * not check), the store drawn as it is, also compiled into a list */
static void mapped_draw(fc_h *h)
{
    setup_scene(h);
    fill_verts(4);
    vbo_arrays();
    void *p = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
    fc_value(h, "mapped", p != NULL);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    fc_error(h, "draw arrays mapped");
    glBegin(GL_POINTS);
    glArrayElement(7);
    glArrayElement(8);
    glEnd();
    fc_error(h, "array element mapped");
    glNewList(2, GL_COMPILE);
    glDrawArrays(GL_LINES, 6, 6);
    glEndList();
    fc_error(h, "compile mapped");
    glCallList(2);
    fc_capture(h);
    fc_value(h, "unmap", glUnmapBuffer(GL_ARRAY_BUFFER));
    fc_error(h, "final");
}

static void mapped_element_buffer(fc_h *h)
{
    setup_scene(h);
    fill_verts(6);
    vbo_arrays();
    index_buffer(GL_UNSIGNED_BYTE, 0, NULL);
    void *p = glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_WRITE_ONLY);
    fc_value(h, "mapped", p != NULL);
    glDrawElements(GL_QUADS, 12, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "draw elements mapped");
    glDrawRangeElements(GL_LINES, 0, 11, 6, GL_UNSIGNED_BYTE, (const GLvoid *)(uintptr_t)10);
    fc_error(h, "draw range elements mapped");
    fc_capture(h);
    fc_value(h, "unmap", glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER));
    fc_error(h, "final");
}

/* The vertices written through the mapping, read back through it */
static void map_write_read(fc_h *h)
{
    setup_scene(h);
    fill_verts(8);
    GLuint b = vbo_arrays();
    glBufferData(GL_ARRAY_BUFFER, sizeof(g_verts), NULL, GL_DYNAMIC_DRAW);
    struct ivert *w = glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    fc_value(h, "write map", w != NULL);
    if (w)
        memcpy(w, g_verts, sizeof(g_verts));
    GLvoid *q = (GLvoid *)1;
    glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &q);
    fc_value(h, "pointer is the map", q == (GLvoid *)w);
    fc_get_integer(h, "array binding", GL_ARRAY_BUFFER_BINDING, 1);
    fc_value(h, "unmap", glUnmapBuffer(GL_ARRAY_BUFFER));
    glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &q);
    fc_value(h, "pointer after unmap", q == NULL);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 8);
    fc_capture(h);
    const struct ivert *r = glMapBufferARB(GL_ARRAY_BUFFER, GL_READ_ONLY);
    fc_value(h, "read map", r != NULL);
    if (r)
        fc_blob(h, "read back", r, sizeof(g_verts));
    fc_value(h, "unmap arb", glUnmapBufferARB(GL_ARRAY_BUFFER));
    glDeleteBuffers(1, &b);
    fc_error(h, "final");
}

/* ---- buffer contents ---- */

static void subdata_contents(fc_h *h)
{
    GLubyte data[64], out[72];
    for (int i = 0; i < 64; i++)
        data[i] = (GLubyte)(i * 7 + 3);
    GLuint b = 0;
    glGenBuffersARB(1, &b);
    glBindBufferARB(GL_ARRAY_BUFFER, b);
    glBufferDataARB(GL_ARRAY_BUFFER, 64, data, GL_STREAM_DRAW);
    memset(out, 0xee, sizeof(out));
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, 64, out);
    fc_blob(h, "whole", out, sizeof(out));
    GLubyte patch[10] = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 };
    glBufferSubDataARB(GL_ARRAY_BUFFER, 50, 10, patch);
    glBufferSubData(GL_ARRAY_BUFFER, 64, 0, patch);   /* empty, at the end */
    fc_error(h, "subdata");
    memset(out, 0xee, sizeof(out));
    glGetBufferSubDataARB(GL_ARRAY_BUFFER, 40, 24, out);
    fc_blob(h, "patched", out, sizeof(out));
    /* the same size and usage again: rewritten */
    for (int i = 0; i < 64; i++)
        data[i] = (GLubyte)(200 - i);
    glBufferData(GL_ARRAY_BUFFER, 64, data, GL_STREAM_DRAW);
    memset(out, 0xee, sizeof(out));
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, 64, out);
    fc_blob(h, "respecified", out, sizeof(out));
    /* another size */
    glBufferData(GL_ARRAY_BUFFER, 8, data + 8, GL_DYNAMIC_COPY);
    GLint v = -1;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    fc_value(h, "size", v);
    glGetBufferParameterivARB(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &v);
    fc_value(h, "usage", v);
    memset(out, 0xee, sizeof(out));
    glGetBufferSubData(GL_ARRAY_BUFFER, 2, 6, out);
    fc_blob(h, "resized", out, sizeof(out));
    /* an empty store */
    glBufferData(GL_ARRAY_BUFFER, 0, NULL, GL_STATIC_READ);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    fc_value(h, "empty size", v);
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, 0, out);
    fc_error(h, "final");
    glDeleteBuffersARB(1, &b);
}

/* GL_BUFFER_SIZE, USAGE, ACCESS, MAPPED through every mapping */
static void buffer_params(fc_h *h)
{
    static const GLenum pnames[] = { GL_BUFFER_SIZE, GL_BUFFER_USAGE, GL_BUFFER_ACCESS,
                                     GL_BUFFER_MAPPED };
    static const GLenum access[] = { GL_READ_ONLY, GL_WRITE_ONLY, GL_READ_WRITE };
    GLuint b[2] = { 0, 0 };
    glGenBuffers(2, b);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
    char label[64];
    for (int k = 0; k < 4; k++) {
        GLint v = -7;
        glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, pnames[k], &v);
        snprintf(label, sizeof(label), "new 0x%x", pnames[k]);
        fc_value(h, label, v);
    }
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, 40, NULL, GL_DYNAMIC_READ);
    for (int a = 0; a < 3; a++) {
        void *p = glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, access[a]);
        fc_value(h, "mapped", p != NULL);
        for (int k = 0; k < 4; k++) {
            GLint v = -7;
            glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, pnames[k], &v);
            snprintf(label, sizeof(label), "access 0x%x 0x%x", access[a], pnames[k]);
            fc_value(h, label, v);
        }
        fc_value(h, "unmapped", glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER));
    }
    GLint v = -7;
    glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, GL_BUFFER_ACCESS, &v);
    fc_value(h, "access after", v);
    fc_get_integer(h, "element binding", GL_ELEMENT_ARRAY_BUFFER_BINDING, 1);
    fc_error(h, "final");
}

/* ---- names, bindings, deletion ---- */

static void names_isbuffer(fc_h *h)
{
    GLuint b[4] = { 0, 0, 0, 0 };
    glGenBuffers(3, b);
    fc_value(h, "names", (long long)b[0] * 10000 + b[1] * 100 + b[2]);
    fc_value(h, "generated is no buffer", glIsBuffer(b[0]));
    glBindBuffer(GL_ARRAY_BUFFER, b[0]);
    fc_value(h, "bound is a buffer", glIsBuffer(b[0]));
    fc_value(h, "zero", glIsBuffer(0));
    /* any name binds in the compatibility profile */
    glBindBuffer(GL_ARRAY_BUFFER, 77);
    fc_value(h, "77", glIsBufferARB(77));
    fc_get_integer(h, "binding 77", GL_ARRAY_BUFFER_BINDING, 1);
    glDeleteBuffers(2, b);
    fc_value(h, "deleted", glIsBuffer(b[0]));
    glGenBuffers(1, &b[3]);
    fc_value(h, "next name", b[3]);
    /* deleting 0, unknown names and a generated name only */
    GLuint odd[3] = { 0, 12345, b[2] };
    glDeleteBuffers(3, odd);
    fc_value(h, "generated deleted", glIsBuffer(b[2]));
    fc_get_integer(h, "binding", GL_ARRAY_BUFFER_BINDING, 1);
    fc_error(h, "final");
}

/* Every GL_*_ARRAY_BUFFER_BINDING: the buffer bound when the pointer was
 * set, per texture unit for the coordinates */
static void array_bindings(fc_h *h)
{
    GLuint b[8];
    glGenBuffers(8, b);
    for (int i = 0; i < 8; i++) {
        glBindBuffer(GL_ARRAY_BUFFER, b[i]);
        glBufferData(GL_ARRAY_BUFFER, 64, NULL, GL_STATIC_DRAW);
    }
    glBindBuffer(GL_ARRAY_BUFFER, b[0]);
    glVertexPointer(3, GL_FLOAT, 0, (const GLvoid *)(uintptr_t)4);
    glBindBuffer(GL_ARRAY_BUFFER, b[1]);
    glNormalPointer(GL_SHORT, 8, (const GLvoid *)(uintptr_t)2);
    glBindBuffer(GL_ARRAY_BUFFER, b[2]);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, NULL);
    glBindBuffer(GL_ARRAY_BUFFER, b[3]);
    glIndexPointer(GL_INT, 0, NULL);
    glBindBuffer(GL_ARRAY_BUFFER, b[4]);
    glTexCoordPointer(2, GL_FLOAT, 0, NULL);
    glClientActiveTexture(GL_TEXTURE1);
    glBindBuffer(GL_ARRAY_BUFFER, b[5]);
    glTexCoordPointer(4, GL_SHORT, 0, NULL);
    glBindBuffer(GL_ARRAY_BUFFER, b[6]);
    glEdgeFlagPointer(0, NULL);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    static const GLenum q[] = { GL_VERTEX_ARRAY_BUFFER_BINDING, GL_NORMAL_ARRAY_BUFFER_BINDING,
                                GL_COLOR_ARRAY_BUFFER_BINDING, GL_INDEX_ARRAY_BUFFER_BINDING,
                                GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
                                GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, GL_ARRAY_BUFFER_BINDING,
                                GL_ELEMENT_ARRAY_BUFFER_BINDING };
    char label[48];
    for (unsigned i = 0; i < sizeof(q) / sizeof(q[0]); i++) {
        snprintf(label, sizeof(label), "unit1 0x%x", q[i]);
        fc_get_integer(h, label, q[i], 1);
    }
    glClientActiveTexture(GL_TEXTURE0);
    fc_get_integer(h, "unit0 texcoord", GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 1);
    fc_get_float(h, "float", GL_VERTEX_ARRAY_BUFFER_BINDING, 1);
    fc_get_boolean(h, "boolean", GL_NORMAL_ARRAY_BUFFER_BINDING, 1);
    GLvoid *p = (GLvoid *)1;
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
    fc_value(h, "vertex pointer is the offset", (long long)(uintptr_t)p);
    glGetPointervEXT(GL_NORMAL_ARRAY_POINTER, &p);
    fc_value(h, "normal pointer", (long long)(uintptr_t)p);
    fc_error(h, "final");
}

/* A buffer deleted while bound: the targets read 0, the arrays lose it
 * (their pointers keep the offsets), other arrays keep theirs */
static void delete_bound(fc_h *h)
{
    setup_scene(h);
    fill_verts(1);
    GLuint b = vbo_arrays();
    GLuint other = 0;
    glGenBuffers(1, &other);
    glBindBuffer(GL_ARRAY_BUFFER, other);
    glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_STATIC_DRAW);
    glTexCoordPointer(2, GL_FLOAT, 0, NULL);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b);
    glDeleteBuffers(1, &b);
    fc_get_integer(h, "array", GL_ARRAY_BUFFER_BINDING, 1);
    fc_get_integer(h, "element", GL_ELEMENT_ARRAY_BUFFER_BINDING, 1);
    fc_get_integer(h, "vertex", GL_VERTEX_ARRAY_BUFFER_BINDING, 1);
    fc_get_integer(h, "color", GL_COLOR_ARRAY_BUFFER_BINDING, 1);
    fc_get_integer(h, "texcoord", GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 1);
    GLvoid *p = NULL;
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
    fc_value(h, "vertex offset kept", (long long)(uintptr_t)p);
    fc_value(h, "is buffer", glIsBuffer(b));
    /* client pointers again: drawing works */
    glVertexPointer(3, GL_FLOAT, sizeof(struct ivert), &g_verts[3].x);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct ivert), g_verts[3].c);
    glDrawArrays(GL_TRIANGLES, 0, 9);
    fc_capture(h);
    /* the name binds anew: an empty buffer */
    glBindBuffer(GL_ARRAY_BUFFER, b);
    GLint v = -1;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    fc_value(h, "rebound size", v);
    fc_error(h, "final");
}

/* glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT) saves the arrays with
 * their buffers and both bindings; the pop binds the saved names again */
static void push_client_attrib(fc_h *h)
{
    setup_scene(h);
    fill_verts(11);
    GLuint b = vbo_arrays();
    index_buffer(GL_UNSIGNED_BYTE, 0, NULL);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    GLuint c = 0;
    glGenBuffers(1, &c);
    glBindBuffer(GL_ARRAY_BUFFER, c);
    glBufferData(GL_ARRAY_BUFFER, 32, NULL, GL_STATIC_DRAW);
    glVertexPointer(2, GL_SHORT, 4, NULL);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glDisableClientState(GL_COLOR_ARRAY);
    fc_get_integer(h, "pushed vertex", GL_VERTEX_ARRAY_BUFFER_BINDING, 1);
    glPopClientAttrib();
    fc_get_integer(h, "array", GL_ARRAY_BUFFER_BINDING, 1);
    fc_get_integer(h, "element", GL_ELEMENT_ARRAY_BUFFER_BINDING, 1);
    fc_get_integer(h, "vertex", GL_VERTEX_ARRAY_BUFFER_BINDING, 1);
    fc_get_integer(h, "vertex size", GL_VERTEX_ARRAY_SIZE, 1);
    glDrawElements(GL_QUADS, 12, GL_UNSIGNED_BYTE, NULL);
    fc_capture(h);
    fc_value(h, "b", b);
    fc_error(h, "final");
}

/* The saved GL_ARRAY_BUFFER deleted before the pop: its name is bound
 * again, which makes a new, empty buffer; the arrays keep the deleted
 * buffer they had */
static void push_client_attrib_deleted(fc_h *h)
{
    setup_scene(h);
    fill_verts(12);
    GLuint b = vbo_arrays();
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glDeleteBuffers(1, &b);
    fc_get_integer(h, "deleted binding", GL_ARRAY_BUFFER_BINDING, 1);
    glPopClientAttrib();
    fc_get_integer(h, "array", GL_ARRAY_BUFFER_BINDING, 1);
    fc_get_integer(h, "vertex", GL_VERTEX_ARRAY_BUFFER_BINDING, 1);
    fc_value(h, "is buffer", glIsBuffer(b));
    GLint v = -1;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    fc_value(h, "size", v);
    /* the arrays still draw from the deleted store */
    glDrawArrays(GL_QUADS, 0, 8);
    fc_capture(h);
    fc_error(h, "final");
}

/* Buffers shared through the sharelist: names and stores; a buffer
 * deleted in one context lives on where the other has it bound */
static void shared_contexts(fc_h *h)
{
    setup_scene(h);
    fill_verts(13);
    GLuint b = vbo_arrays();
    static GLubyte buf2[64 * 64 * 4];
    OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, fc_context(h));
    fc_value(h, "context", shared != NULL);
    if (!shared)
        return;
    OSMesaMakeCurrent(shared, buf2, GL_UNSIGNED_BYTE, 64, 64);
    fc_value(h, "shared is buffer", glIsBuffer(b));
    fc_get_integer(h, "shared binding", GL_ARRAY_BUFFER_BINDING, 1);
    GLuint names[2] = { 0, 0 };
    glGenBuffers(2, names);
    fc_value(h, "shared names", names[0] * 100 + names[1]);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    GLint v = -1;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    fc_value(h, "shared size", v);
    glDeleteBuffers(1, &b);
    fc_value(h, "deleted there", glIsBuffer(b));
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 64, 64);
    fc_value(h, "deleted here", glIsBuffer(b));
    fc_get_integer(h, "still bound", GL_ARRAY_BUFFER_BINDING, 1);
    fc_get_integer(h, "vertex", GL_VERTEX_ARRAY_BUFFER_BINDING, 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    fc_capture(h);
    OSMesaDestroyContext(shared);
    fc_error(h, "final");
}

/* Every array kind from buffers: normals with lighting, texture
 * coordinates with a texture, edge flags with GL_LINE polygons, packed
 * and double types, a zero stride */
static void all_arrays(fc_h *h)
{
    setup_scene(h);
    static const GLfloat pos[6][2] = { { 4, 4 }, { 60, 8 }, { 30, 40 }, { 8, 60 }, { 40, 58 }, { 62, 30 } };
    static const GLshort nrm[6][3] = { { 0, 0, 32767 }, { 16000, 0, 28000 }, { 0, -16000, 28000 },
                                       { -9000, 9000, 30000 }, { 3000, 20000, 20000 }, { 0, 0, 32767 } };
    static const GLdouble tc[6][2] = { { 0, 0 }, { 1.5, 0 }, { 0.7, 1.2 }, { 0, 2 }, { 1, 1 }, { 2, 0.5 } };
    static const GLboolean ef[6] = { 1, 0, 1, 1, 1, 0 };
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, 512, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(pos), pos);
    glBufferSubData(GL_ARRAY_BUFFER, 64, sizeof(nrm), nrm);
    glBufferSubData(GL_ARRAY_BUFFER, 128, sizeof(tc), tc);
    glBufferSubData(GL_ARRAY_BUFFER, 256, sizeof(ef), ef);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, NULL);
    glNormalPointer(GL_SHORT, 0, (const GLvoid *)(uintptr_t)64);
    glTexCoordPointer(2, GL_DOUBLE, 0, (const GLvoid *)(uintptr_t)128);
    glEdgeFlagPointer(0, (const GLvoid *)(uintptr_t)256);
    /* a 4x4 checker texture */
    GLubyte tex[4 * 4 * 4];
    for (int i = 0; i < 16; i++) {
        const bool on = ((i & 1) ^ ((i >> 2) & 1)) != 0;
        tex[4 * i + 0] = on ? 250 : 20;
        tex[4 * i + 1] = on ? 200 : 60;
        tex[4 * i + 2] = on ? 40 : 180;
        tex[4 * i + 3] = 255;
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    fc_capture(h);
    /* unfilled, with edge flags */
    fcu_clear(0, 0, 0, 0, 1);
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glColor3f(1, 1, 0);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    fc_capture(h);
    fc_error(h, "final");
}

/* glInterleavedArrays with a buffer bound: its pointer is an offset */
static void interleaved(fc_h *h)
{
    setup_scene(h);
    static GLfloat c3v3[8][6];
    for (int i = 0; i < 8; i++) {
        c3v3[i][0] = (float)(i & 1);
        c3v3[i][1] = (float)((i >> 1) & 1);
        c3v3[i][2] = 0.25f * (float)(i & 3);
        c3v3[i][3] = 4.0f + 7.5f * (float)i;
        c3v3[i][4] = (i & 1) ? 60.0f : 6.0f;
        c3v3[i][5] = 0.1f * (float)i - 0.3f;
    }
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, 24 + sizeof(c3v3), NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 24, sizeof(c3v3), c3v3);
    glInterleavedArrays(GL_C3F_V3F, 0, (const GLvoid *)(uintptr_t)24);
    fc_get_integer(h, "color binding", GL_COLOR_ARRAY_BUFFER_BINDING, 1);
    glDrawArrays(GL_QUAD_STRIP, 0, 8);
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_EXT_vertex_array's names (the count is ignored) */
static void ext_vertex_array(fc_h *h)
{
    setup_scene(h);
    fill_verts(14);
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, sizeof(g_verts), g_verts, GL_STATIC_DRAW);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointerEXT(3, GL_FLOAT, sizeof(struct ivert), 3, (const GLvoid *)(uintptr_t)48);
    glColorPointerEXT(4, GL_UNSIGNED_BYTE, sizeof(struct ivert), -5, (const GLvoid *)(uintptr_t)60);
    glNormalPointerEXT(GL_FLOAT, 0, 0, NULL);
    glTexCoordPointerEXT(3, GL_FLOAT, 0, 0, NULL);
    glIndexPointerEXT(GL_FLOAT, 0, 0, NULL);
    glEdgeFlagPointerEXT(0, 0, NULL);
    fc_error(h, "pointers");
    glVertexPointerEXT(5, GL_FLOAT, 0, 0, NULL);
    fc_error(h, "bad size");
    glDrawArraysEXT(GL_TRIANGLE_FAN, 0, 12);
    glBegin(GL_POINTS);
    glArrayElementEXT(11);
    glEnd();
    fc_capture(h);
    GLvoid *p = NULL;
    glGetPointervEXT(GL_COLOR_ARRAY_POINTER, &p);
    fc_value(h, "color pointer", (long long)(uintptr_t)p);
    fc_get_integer(h, "color binding", GL_COLOR_ARRAY_BUFFER_BINDING, 1);
    fc_error(h, "final");
}

/* ---- errors ---- */

static void errors_no_buffer(fc_h *h)
{
    GLubyte data[16] = { 0 };
    GLint v = -3;
    GLvoid *p = (GLvoid *)2;
    glBufferData(GL_ARRAY_BUFFER, 16, data, GL_STATIC_DRAW);
    fc_error(h, "data no buffer");
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, 4, data);
    fc_error(h, "subdata no buffer");
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, data);
    fc_error(h, "getsubdata no buffer");
    fc_value(h, "map no buffer", glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY) != NULL);
    fc_error(h, "map no buffer");
    fc_value(h, "unmap no buffer", glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER));
    fc_error(h, "unmap no buffer");
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    fc_error(h, "param no buffer");
    fc_value(h, "param untouched", v);
    glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &p);
    fc_error(h, "pointer no buffer");
    fc_value(h, "pointer untouched", (long long)(uintptr_t)p);
    fc_error(h, "final");
}

static void errors_enums(fc_h *h)
{
    GLuint b = 0;
    GLubyte data[16] = { 0 };
    GLint v = -3;
    GLvoid *p = (GLvoid *)2;
    glGenBuffers(1, &b);
    glBindBuffer(GL_TEXTURE_2D, b);
    fc_error(h, "bind target");
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, 16, data, GL_STATIC_DRAW + 3);
    fc_error(h, "usage");
    glBufferData(GL_ARRAY_BUFFER, 16, data, GL_RGBA);
    fc_error(h, "usage rgba");
    glBufferData(GL_ARRAY_BUFFER, -1, data, GL_RGBA);
    fc_error(h, "size first");
    glBufferData(GL_VERTEX_ARRAY, 16, data, GL_STATIC_DRAW);
    fc_error(h, "data target");
    glBufferData(GL_ARRAY_BUFFER, 16, data, GL_STATIC_DRAW);
    fc_value(h, "map access", glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE + 1) != NULL);
    fc_error(h, "map access");
    fc_value(h, "map access before target", glMapBuffer(GL_BLEND, GL_BLEND) != NULL);
    fc_error(h, "map access before target");
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &v);
    fc_error(h, "param pname");
    glGetBufferParameteriv(GL_COLOR, GL_BUFFER_SIZE, &v);
    fc_error(h, "param target");
    glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &p);
    fc_error(h, "pointer pname");
    glGetBufferPointerv(GL_COLOR, GL_BUFFER_SIZE, &p);
    fc_error(h, "pointer pname before target");
    fc_value(h, "unmap target", glUnmapBuffer(GL_FLOAT));
    fc_error(h, "unmap target");
    fc_value(h, "values untouched", (long long)v * 1000 + (long long)(uintptr_t)p);
    fc_error(h, "final");
}

static void errors_values(fc_h *h)
{
    GLuint b = 0;
    GLubyte data[32] = { 0 };
    glGenBuffers(-1, &b);
    fc_error(h, "gen negative");
    glDeleteBuffers(-2, &b);
    fc_error(h, "delete negative");
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, -16, data, GL_STATIC_DRAW);
    fc_error(h, "data negative");
    glBufferData(GL_ARRAY_BUFFER, 16, data, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, -1, 4, data);
    fc_error(h, "subdata offset");
    glBufferSubData(GL_ARRAY_BUFFER, 0, -4, data);
    fc_error(h, "subdata size");
    glBufferSubData(GL_ARRAY_BUFFER, 12, 5, data);
    fc_error(h, "subdata past end");
    glBufferSubData(GL_ARRAY_BUFFER, 17, 0, data);
    fc_error(h, "subdata empty past end");
    glGetBufferSubData(GL_ARRAY_BUFFER, 16, 1, data);
    fc_error(h, "getsubdata past end");
    glGetBufferSubData(GL_ARRAY_BUFFER, -4, -1, data);
    fc_error(h, "getsubdata negative");
    /* an empty buffer cannot be mapped (a zero length) */
    glBufferData(GL_ARRAY_BUFFER, 0, NULL, GL_STATIC_DRAW);
    fc_value(h, "map empty", glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY) != NULL);
    fc_error(h, "map empty");
    fc_error(h, "final");
}

static void errors_mapped(fc_h *h)
{
    GLuint b = 0;
    GLubyte data[32], out[32];
    for (int i = 0; i < 32; i++)
        data[i] = (GLubyte)i;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, 32, data, GL_STATIC_DRAW);
    GLubyte *m = glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_READ_ONLY);
    fc_value(h, "mapped", m != NULL);
    if (m)
        fc_blob(h, "mapped bytes", m, 32);
    fc_value(h, "map twice", glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_READ_ONLY) != NULL);
    fc_error(h, "map twice");
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 4, 4, data);
    fc_error(h, "subdata mapped");
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, 0, data);
    fc_error(h, "empty subdata at 0 mapped");
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 5, 0, data);
    fc_error(h, "empty subdata inside mapped");
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 32, 0, data);
    fc_error(h, "empty subdata at end mapped");
    glGetBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, 0, out);
    fc_error(h, "empty getsubdata mapped");
    glGetBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, 8, out);
    fc_error(h, "getsubdata mapped");
    /* glBufferData replaces the store and drops the mapping, no error */
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, 32, data, GL_STATIC_DRAW);
    fc_error(h, "data mapped");
    GLint v = -1;
    glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, GL_BUFFER_MAPPED, &v);
    fc_value(h, "mapped after data", v);
    fc_value(h, "unmap unmapped", glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER));
    fc_error(h, "unmap unmapped");
    /* a delete drops the mapping too */
    m = glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_READ_WRITE);
    glDeleteBuffers(1, &b);
    fc_error(h, "delete mapped");
    fc_error(h, "final");
}

/* Inside glBegin/glEnd every buffer call is GL_INVALID_OPERATION, without
 * effect */
static void errors_begin_end(fc_h *h)
{
    GLuint b = 0, c = 0;
    GLubyte data[8] = { 1, 2, 3, 4, 5, 6, 7, 8 };
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, 8, data, GL_STATIC_DRAW);
    glBegin(GL_POINTS);
    glGenBuffers(1, &c);
    glEnd();
    fc_error(h, "gen");
    fc_value(h, "gen untouched", c);
    glBegin(GL_POINTS);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glEnd();
    fc_error(h, "bind");
    fc_get_integer(h, "binding", GL_ARRAY_BUFFER_BINDING, 1);
    glBegin(GL_POINTS);
    glBufferData(GL_ARRAY_BUFFER, 4, data, GL_STATIC_DRAW);
    glEnd();
    fc_error(h, "data");
    glBegin(GL_POINTS);
    glBufferSubData(GL_ARRAY_BUFFER, 0, 4, data + 4);
    glEnd();
    fc_error(h, "subdata");
    glBegin(GL_POINTS);
    fc_value(h, "isbuffer", glIsBuffer(b));
    glEnd();
    fc_error(h, "isbuffer");
    glBegin(GL_POINTS);
    fc_value(h, "map", glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY) != NULL);
    glEnd();
    fc_error(h, "map");
    glBegin(GL_POINTS);
    glDeleteBuffers(1, &b);
    glEnd();
    fc_error(h, "delete");
    GLint v = -1;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    fc_value(h, "size", v);
    GLubyte out[8];
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, 8, out);
    fc_blob(h, "contents", out, 8);
    fc_error(h, "final");
}

/* Buffer calls while a list is compiled run at once (not compiled) */
static void dlist_not_compiled(fc_h *h)
{
    GLuint b = 0;
    GLubyte data[8] = { 9, 8, 7, 6, 5, 4, 3, 2 };
    glNewList(5, GL_COMPILE);
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, 8, data, GL_STATIC_DRAW);
    glEndList();
    fc_get_integer(h, "binding after compile", GL_ARRAY_BUFFER_BINDING, 1);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glCallList(5);
    fc_get_integer(h, "binding after call", GL_ARRAY_BUFFER_BINDING, 1);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    GLint v = -1;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    fc_value(h, "size", v);
    fc_error(h, "final");
}

/* ---- occlusion queries ---- */

static void q_result(fc_h *h, const char *label, GLuint q)
{
    GLuint r = 0xdeadbeefu;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &r);
    fc_value(h, label, r);
}

static void q_avail(fc_h *h, const char *label, GLuint q)
{
    GLuint a = 77;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &a);
    fc_value(h, label, a);
}

static GLuint q_gen(void)
{
    GLuint q = 0;
    glGenQueries(1, &q);
    return q;
}

/* One query around `draw`, its result recorded under label */
#define Q_AROUND(h, label, q, draw)            \
    do {                                       \
        glBeginQuery(GL_SAMPLES_PASSED, q);    \
        draw;                                  \
        glEndQuery(GL_SAMPLES_PASSED);         \
        q_result(h, label, q);                 \
    } while (0)

static void query_basic(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint q = q_gen();
    fc_value(h, "is query before", glIsQuery(q));
    Q_AROUND(h, "rect", q, fcu_rect(3, 5, 40, 22, 0));
    fc_value(h, "is query after", glIsQuery(q));
    Q_AROUND(h, "tri", q, fcu_tri(1.5f, 2.25f, 61.75f, 9.5f, 20.125f, 58.5f));
    Q_AROUND(h, "nothing", q, (void)0);
    GLint iv = -1;
    glGetQueryObjectiv(q, GL_QUERY_RESULT, &iv);
    fc_value(h, "iv", iv);
    glGetQueryObjectivARB(q, GL_QUERY_RESULT_AVAILABLE, &iv);
    fc_value(h, "iv available", iv);
    GLint bits = -1;
    glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &bits);
    fc_value(h, "bits", bits);
    fc_capture(h);
    fc_error(h, "final");
}

/* Depth test: passing and failing fragments, depth writes off, 16-bit
 * depth */
static void query_depth_common(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    fcu_color(1);
    fcu_rect(0, 0, 64, 32, 0);
    GLuint q = q_gen();
    fcu_color(2);
    Q_AROUND(h, "behind", q, fcu_rect(8, 8, 40, 40, 0.5f));
    Q_AROUND(h, "in front", q, fcu_rect(8, 8, 40, 40, -0.5f));
    glDepthFunc(GL_EQUAL);
    Q_AROUND(h, "equal", q, fcu_rect(0, 0, 64, 60, 0.0f));
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    fcu_color(3);
    Q_AROUND(h, "no writes", q, fcu_tri(2, 2, 62, 30, 30, 62));
    Q_AROUND(h, "no writes again", q, fcu_tri(2, 2, 62, 30, 30, 62));
    glDepthFunc(GL_NEVER);
    Q_AROUND(h, "never", q, fcu_rect(0, 0, 50, 50, 0.0f));
    fc_capture(h);
    fc_error(h, "final");
}

static void query_depth(fc_h *h) { query_depth_common(h); }
static void query_depth16(fc_h *h) { query_depth_common(h); }
static void query_no_depth_buffer(fc_h *h) { query_depth_common(h); }

static void query_stencil(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    GLuint q = q_gen();
    fcu_color(4);
    Q_AROUND(h, "write", q, fcu_tri(0, 0, 64, 0, 0, 64));
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    fcu_color(5);
    Q_AROUND(h, "equal", q, fcu_rect(10, 10, 60, 60, 0));
    glStencilFunc(GL_NOTEQUAL, 1, 0xff);
    glEnable(GL_DEPTH_TEST);
    fcu_color(6);
    Q_AROUND(h, "notequal", q, fcu_rect(10, 10, 60, 60, 0.2f));
    Q_AROUND(h, "notequal depth fail", q, fcu_rect(10, 10, 60, 60, 0.4f));
    fc_capture(h);
    fc_error(h, "final");
}

static void query_alpha_test(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    GLuint q = q_gen();
    glShadeModel(GL_SMOOTH);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glBegin(GL_QUADS);
    glColor4f(1, 0, 0, 0.0f);
    glVertex2f(0, 0);
    glColor4f(0, 1, 0, 1.0f);
    glVertex2f(64, 0);
    glColor4f(0, 0, 1, 1.0f);
    glVertex2f(64, 64);
    glColor4f(1, 1, 0, 0.0f);
    glVertex2f(0, 64);
    glEnd();
    glEndQuery(GL_SAMPLES_PASSED);
    q_result(h, "gradient", q);
    glAlphaFunc(GL_LEQUAL, 0.25f);
    glColor4f(1, 1, 1, 0.5f);
    Q_AROUND(h, "all fail", q, fcu_rect(0, 0, 30, 30, 0));
    fc_capture(h);
    fc_error(h, "final");
}

/* Scissor, colour mask, blending and the logic op: only the scissor cuts */
static void query_scissor_mask(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint q = q_gen();
    glEnable(GL_SCISSOR_TEST);
    glScissor(5, 7, 20, 13);
    fcu_color(7);
    Q_AROUND(h, "scissored", q, fcu_rect(0, 0, 64, 64, 0));
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    Q_AROUND(h, "colour mask off", q, fcu_rect(30, 30, 50, 50, 0));
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_ONE);
    Q_AROUND(h, "blend keeps the buffer", q, fcu_tri(0, 0, 50, 10, 10, 50));
    glDisable(GL_BLEND);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_NOOP);
    Q_AROUND(h, "logic noop", q, fcu_rect(40, 0, 64, 20, 0));
    glDisable(GL_COLOR_LOGIC_OP);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    fc_capture(h);
    fc_error(h, "final");
}

/* A query spanning clears: a clear (whole, scissored, masked) counts no
 * sample; the draws before and after it do */
static void query_spanning_clear(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    GLuint q = q_gen();
    glBeginQuery(GL_SAMPLES_PASSED, q);
    fcu_color(8);
    fcu_rect(0, 0, 20, 20, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fcu_rect(10, 10, 30, 30, 0);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 32, 32);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    fcu_rect(5, 5, 15, 45, 0.5f);
    glEndQuery(GL_SAMPLES_PASSED);
    q_result(h, "spanning", q);
    Q_AROUND(h, "clear only", q, glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
    fcu_rect(30, 12, 50, 60, 0.25f);
    fc_capture(h);
    fc_error(h, "final");
}

static void query_pixels(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint q = q_gen();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);   /* the bitmaps' rows are bytes */
    GLubyte img[7 * 5 * 4];
    for (int i = 0; i < 7 * 5 * 4; i++)
        img[i] = (GLubyte)(i * 11);
    glRasterPos2i(3, 4);
    Q_AROUND(h, "drawpixels", q, glDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, img));
    glPixelZoom(2.0f, -1.5f);
    glRasterPos2i(20, 40);
    Q_AROUND(h, "drawpixels zoomed", q, glDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, img));
    glPixelZoom(1.0f, 1.0f);
    static const GLubyte bm[8] = { 0xff, 0x81, 0x42, 0x24, 0x18, 0x00, 0xf0, 0x0f };
    glRasterPos2i(40, 10);
    glColor3f(1, 1, 0);
    Q_AROUND(h, "bitmap", q, glBitmap(8, 8, 0, 0, 9, 0, bm));
    /* bitmaps cached before the query are drawn before it counts */
    glBitmap(8, 8, 0, 0, 9, 0, bm);
    Q_AROUND(h, "bitmap cached before", q, glBitmap(8, 8, 0, 0, 9, 0, bm));
    glRasterPos2i(30, 28);
    Q_AROUND(h, "copypixels", q, glCopyPixels(0, 0, 12, 9, GL_COLOR));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glRasterPos3f(50, 50, 0.5f);
    Q_AROUND(h, "drawpixels depth", q, glDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, img));
    Q_AROUND(h, "drawpixels depth again", q, glDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, img));
    fc_capture(h);
    fc_error(h, "final");
}

/* Points, lines, smooth ones (the coverage kills), stipples */
static void query_points_lines(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint q = q_gen();
    glPointSize(5.0f);
    Q_AROUND(h, "points", q, {
        glBegin(GL_POINTS);
        glVertex2f(10.5f, 10.5f);
        glVertex2f(20.3f, 40.7f);
        glVertex2f(63.5f, 0.5f);
        glEnd();
    });
    glEnable(GL_POINT_SMOOTH);
    glPointSize(6.5f);
    Q_AROUND(h, "smooth points", q, {
        glBegin(GL_POINTS);
        glVertex2f(30.25f, 30.75f);
        glVertex2f(50.5f, 12.5f);
        glEnd();
    });
    glDisable(GL_POINT_SMOOTH);
    glLineWidth(3.0f);
    Q_AROUND(h, "wide lines", q, {
        glBegin(GL_LINES);
        glVertex2f(2, 60);
        glVertex2f(60, 50);
        glVertex2f(5, 3);
        glVertex2f(9, 55);
        glEnd();
    });
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x3c3c);
    glLineWidth(1.0f);
    Q_AROUND(h, "stippled line", q, {
        glBegin(GL_LINE_STRIP);
        glVertex2f(1, 20);
        glVertex2f(63, 25);
        glVertex2f(40, 63);
        glEnd();
    });
    glDisable(GL_LINE_STIPPLE);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glLineWidth(2.5f);
    Q_AROUND(h, "smooth line", q, {
        glBegin(GL_LINES);
        glVertex2f(3, 33);
        glVertex2f(61, 47);
        glEnd();
    });
    fc_capture(h);
    fc_error(h, "final");
}

static void query_polygon_state(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint q = q_gen();
    GLubyte stipple[128];
    for (int i = 0; i < 128; i++)
        stipple[i] = (GLubyte)((i & 4) ? 0xcc : 0x5a);
    glPolygonStipple(stipple);
    glEnable(GL_POLYGON_STIPPLE);
    Q_AROUND(h, "stippled", q, fcu_rect(0, 0, 64, 64, 0));
    glDisable(GL_POLYGON_STIPPLE);
    glEnable(GL_CULL_FACE);
    Q_AROUND(h, "culled", q, fcu_tri(0, 0, 0, 60, 60, 0));
    Q_AROUND(h, "front", q, fcu_tri(0, 0, 60, 0, 0, 60));
    glDisable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    Q_AROUND(h, "outline", q, fcu_rect(10, 10, 50, 40, 0));
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(2.0f);
    Q_AROUND(h, "vertices", q, fcu_rect(10, 10, 50, 40, 0));
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    fc_capture(h);
    fc_error(h, "final");
}

/* A textured, alpha-tested triangle and a lit one (the block kernels'
 * stages) */
static void query_textured_lit(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLubyte tex[8 * 8 * 4];
    for (int i = 0; i < 64; i++) {
        tex[4 * i + 0] = (GLubyte)(i * 4);
        tex[4 * i + 1] = (GLubyte)(255 - i * 3);
        tex[4 * i + 2] = 128;
        tex[4 * i + 3] = (GLubyte)(((i ^ (i >> 3)) & 1) ? 255 : 30);
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GEQUAL, 0.5f);
    GLuint q = q_gen();
    Q_AROUND(h, "textured", q, {
        glBegin(GL_TRIANGLES);
        glTexCoord2f(0, 0);
        glVertex2f(1, 1);
        glTexCoord2f(1, 0);
        glVertex2f(63, 4);
        glTexCoord2f(0.5f, 1);
        glVertex2f(30, 62);
        glEnd();
    });
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    Q_AROUND(h, "lit", q, {
        glBegin(GL_TRIANGLES);
        glNormal3f(0, 0, 1);
        glVertex3f(5, 50, -0.5f);
        glNormal3f(0.6f, 0, 0.8f);
        glVertex3f(60, 60, 0.5f);
        glNormal3f(0, 0.6f, 0.8f);
        glVertex3f(40, 2, 0.1f);
        glEnd();
    });
    fc_capture(h);
    fc_error(h, "final");
}

/* A 200 x 150 buffer: triangles over many tiles (the threads' counts
 * summed), half of them behind */
static void query_many_tiles(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    GLuint q = q_gen();
    glBeginQuery(GL_SAMPLES_PASSED, q);
    for (int i = 0; i < 40; i++) {
        fcu_color(i);
        const float x = (float)((i * 37) % 180), y = (float)((i * 53) % 130);
        glBegin(GL_TRIANGLES);
        glVertex3f(x, y, 0.9f - 0.04f * (float)i);
        glVertex3f(x + 70.5f, y + 10.25f, 0.3f);
        glVertex3f(x + 20.75f, y + 60.5f, -0.8f + 0.03f * (float)i);
        glEnd();
    }
    fcu_rect(0, 0, 200, 150, 0.0f);
    glEndQuery(GL_SAMPLES_PASSED);
    q_result(h, "many", q);
    fc_capture(h);
    fc_error(h, "final");
}

/* Queries spanning display lists: glBeginQuery and glEndQuery are
 * compiled (executed when the list runs), and a list drawn inside a
 * query counts */
static void query_display_lists(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint q = q_gen(), q2 = q_gen();
    glNewList(1, GL_COMPILE);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    fcu_rect(0, 0, 10, 10, 0);
    glEndList();
    fc_error(h, "compiled begin");
    GLint cur = -1;
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
    fc_value(h, "not begun by compile", cur);
    glNewList(2, GL_COMPILE);
    fcu_rect(20, 20, 26, 31, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    glEndList();
    fc_error(h, "compiled end");
    glCallList(1);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
    fc_value(h, "begun by the list", cur);
    fcu_rect(40, 40, 45, 45, 0);
    glCallList(2);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
    fc_value(h, "ended by the list", cur);
    q_result(h, "spanning lists", q);
    /* a list inside a query, and compile-and-execute */
    glNewList(3, GL_COMPILE_AND_EXECUTE);
    glBeginQuery(GL_SAMPLES_PASSED, q2);
    fcu_tri(0, 0, 30, 5, 5, 30);
    glEndQuery(GL_SAMPLES_PASSED);
    glEndList();
    q_result(h, "compile and execute", q2);
    Q_AROUND(h, "list in query", q, glCallList(3));
    fc_error(h, "nested begin from the list");
    /* a begin inside glBegin/glEnd of a list being compiled */
    glNewList(4, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEnd();
    glEndList();
    fc_error(h, "begin inside a compiled glBegin");
    glCallList(4);
    fc_error(h, "called");
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_QUERY_RESULT_AVAILABLE as the oracle answers it: not right after
 * glEndQuery (the question flushes); a flush, finish, read-back or result
 * wait makes it available; clears and draws do not */
static void query_available(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint q = q_gen(), q2 = q_gen();
    glBeginQuery(GL_SAMPLES_PASSED, q);
    fcu_rect(0, 0, 8, 8, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    q_avail(h, "first", q);
    /* (asked again at once, the oracle's answer depends on whether its
     * rasterizer threads have finished the scene the first question
     * flushed: not compared) */
    q_result(h, "result", q);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    fcu_rect(0, 0, 9, 9, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    glClear(GL_COLOR_BUFFER_BIT);
    fcu_rect(20, 20, 30, 30, 0);
    q_avail(h, "after clear and draw", q);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEndQuery(GL_SAMPLES_PASSED);
    glFlush();
    q_avail(h, "after flush", q);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEndQuery(GL_SAMPLES_PASSED);
    glFinish();
    q_avail(h, "after finish", q);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    fcu_rect(0, 0, 3, 3, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    GLubyte px[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    q_avail(h, "after readpixels", q);
    /* two queries ended in the same scene */
    glBeginQuery(GL_SAMPLES_PASSED, q);
    fcu_rect(0, 0, 4, 4, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    glBeginQuery(GL_SAMPLES_PASSED, q2);
    fcu_rect(0, 0, 5, 5, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    q_avail(h, "q2 first", q2);
    glFinish();
    q_avail(h, "q after a finish", q);
    /* the result of one waits: the other is then available */
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEndQuery(GL_SAMPLES_PASSED);
    glBeginQuery(GL_SAMPLES_PASSED, q2);
    glEndQuery(GL_SAMPLES_PASSED);
    q_result(h, "q2 result", q2);
    q_avail(h, "q after a result", q);
    /* glCopyPixels reads the buffer */
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEndQuery(GL_SAMPLES_PASSED);
    glCopyPixels(0, 0, 2, 2, GL_COLOR);
    q_avail(h, "after copypixels", q);
    /* glBitmap and glDrawPixels draw into the scene */
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEndQuery(GL_SAMPLES_PASSED);
    static const GLubyte bm[2] = { 0xc0, 0x40 };
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2i(50, 50);
    glBitmap(2, 2, 0, 0, 0, 0, bm);
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    q_avail(h, "after bitmap and drawpixels", q);
    fc_capture(h);
    fc_error(h, "final");
}

static void query_errors(fc_h *h)
{
    GLuint q = q_gen(), q2 = q_gen();
    GLuint r = 0xabcdu;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &r);
    fc_error(h, "result never begun");
    glGetQueryObjectuiv(0, GL_QUERY_RESULT, &r);
    fc_error(h, "result of 0");
    glGetQueryObjectuiv(4321, GL_QUERY_RESULT_AVAILABLE, &r);
    fc_error(h, "result of an unknown name");
    glBeginQuery(GL_SAMPLES_PASSED, 0);
    fc_error(h, "begin 0");
    glBeginQuery(GL_DEPTH_TEST, q);
    fc_error(h, "begin target");
    glEndQuery(GL_SAMPLES_PASSED);
    fc_error(h, "end without begin");
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glBeginQuery(GL_SAMPLES_PASSED, q2);
    fc_error(h, "nested begin");
    glBeginQuery(GL_SAMPLES_PASSED, q);
    fc_error(h, "begin again");
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &r);
    fc_error(h, "result while active");
    glGetQueryObjectiv(q, GL_QUERY_RESULT_AVAILABLE, (GLint *)&r);
    fc_error(h, "available while active");
    glEndQuery(GL_FLOAT);
    fc_error(h, "end target");
    GLint cur = -1;
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
    fc_value(h, "still active", cur);
    glEndQuery(GL_SAMPLES_PASSED);
    glGetQueryObjectuiv(q, GL_QUERY_COUNTER_BITS, &r);
    fc_error(h, "object pname");
    glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_RESULT, &cur);
    fc_error(h, "query pname");
    glGetQueryiv(GL_BLEND, GL_CURRENT_QUERY, &cur);
    fc_error(h, "query target");
    glGenQueries(-1, &q2);
    fc_error(h, "gen negative");
    glDeleteQueries(-1, &q2);
    fc_error(h, "delete negative");
    glGetIntegerv(GL_CURRENT_QUERY, &cur);
    fc_error(h, "glGet of the current query");
    fc_value(h, "untouched", r);
    fc_error(h, "final");
}

static void query_begin_end_errors(fc_h *h)
{
    GLuint q = q_gen(), q2 = 0;
    glBegin(GL_TRIANGLES);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glEnd();
    fc_error(h, "begin in glBegin");
    GLint cur = -1;
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
    fc_value(h, "not begun", cur);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glBegin(GL_POINTS);
    glEndQuery(GL_SAMPLES_PASSED);
    glEnd();
    fc_error(h, "end in glBegin");
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
    fc_value(h, "not ended", cur);
    glBegin(GL_POINTS);
    glGenQueries(1, &q2);
    glEnd();
    fc_error(h, "gen in glBegin");
    glBegin(GL_POINTS);
    fc_value(h, "isquery in glBegin", glIsQuery(q));
    glEnd();
    fc_error(h, "isquery in glBegin");
    glBegin(GL_POINTS);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
    glEnd();
    fc_error(h, "getquery in glBegin");
    glEndQuery(GL_SAMPLES_PASSED);
    fc_value(h, "q2", q2);
    fc_error(h, "final");
}

/* Names: glIsQuery once begun; deleting the active query ends it;
 * reusing a query restarts its count; a name never generated */
static void query_names(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint ids[3] = { 0, 0, 0 };
    glGenQueriesARB(3, ids);
    fc_value(h, "names", ids[0] * 10000 + ids[1] * 100 + ids[2]);
    fc_value(h, "generated", glIsQueryARB(ids[0]));
    glBeginQueryARB(GL_SAMPLES_PASSED, ids[1]);
    fcu_rect(0, 0, 5, 5, 0);
    GLint cur = -1;
    glGetQueryivARB(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
    fc_value(h, "current", cur);
    glDeleteQueriesARB(1, &ids[1]);
    fc_error(h, "delete active");
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &cur);
    fc_value(h, "current after delete", cur);
    glEndQueryARB(GL_SAMPLES_PASSED);
    fc_error(h, "end after delete");
    fc_value(h, "deleted", glIsQuery(ids[1]));
    /* a name never generated begins (the compatibility profile) */
    glBeginQuery(GL_SAMPLES_PASSED, 900);
    fcu_rect(0, 0, 6, 2, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    fc_error(h, "ungenerated");
    q_result(h, "ungenerated result", 900);
    fc_value(h, "is 900", glIsQuery(900));
    GLuint more = 0;
    glGenQueries(1, &more);
    fc_value(h, "next name", more);
    /* reuse: the count restarts */
    Q_AROUND(h, "first use", ids[2], fcu_rect(0, 0, 10, 10, 0));
    Q_AROUND(h, "reused", ids[2], fcu_rect(0, 0, 3, 10, 0));
    GLuint r = 0;
    glGetQueryObjectuivARB(ids[2], GL_QUERY_RESULT, &r);
    fc_value(h, "arb result", r);
    GLuint zero[2] = { 0, 5555 };
    glDeleteQueries(2, zero);
    fc_error(h, "final");
}

/* glBitmap's cache across a query's end, glPushAttrib around a query,
 * and a query around an array draw from buffers */
static void query_vbo_draw(fc_h *h)
{
    setup_scene(h);
    fill_verts(15);
    vbo_arrays();
    index_buffer(GL_UNSIGNED_INT, 2, NULL);
    GLuint q = q_gen();
    Q_AROUND(h, "arrays", q, glDrawArrays(GL_TRIANGLES, 0, 12));
    Q_AROUND(h, "elements", q, glDrawElements(GL_QUADS, 12, GL_UNSIGNED_INT, (const GLvoid *)(uintptr_t)8));
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glDisable(GL_DEPTH_TEST);
    glDrawArrays(GL_TRIANGLE_FAN, 2, 8);
    glPopAttrib();
    glDrawArrays(GL_TRIANGLE_FAN, 2, 8);
    glEndQuery(GL_SAMPLES_PASSED);
    q_result(h, "around a pop", q);
    fc_capture(h);
    fc_error(h, "final");
}

#define VBO(name, fn) FC_CASE_RGBA("gl15/vbo_" name, 64, 64, 2, "api gl15 vbo", fn)
#define VBO_N(name, frames, fn) FC_CASE_RGBA("gl15/vbo_" name, 64, 64, frames, "api gl15 vbo", fn)
#define QRY(name, frames, fn) FC_CASE("gl15/query_" name, 64, 64, OSMESA_RGBA, 24, 8, frames, "api gl15 query", fn)

/* glMultiDrawElements with an element buffer: an index pointer of 0 is
 * the buffer's offset 0, not the NULL that cancels a call of client
 * indices (found by the random families' buffer objects); then the same
 * pointers without the buffer (cancelled), and offsets mixed. */
static void multidraw_elements_offset0(fc_h *h)
{
    static const GLfloat v[8][2] = { { 4, 4 }, { 28, 4 }, { 4, 28 }, { 28, 28 },
                                     { 34, 6 }, { 60, 10 }, { 36, 40 }, { 58, 44 } };
    static const GLubyte c[8][4] = { { 255, 0, 0, 255 }, { 0, 255, 0, 255 }, { 0, 0, 255, 255 },
                                     { 255, 255, 0, 255 }, { 0, 255, 255, 255 }, { 255, 0, 255, 255 },
                                     { 128, 128, 128, 255 }, { 255, 128, 0, 255 } };
    static const GLushort idx[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    GLuint ibo;
    glGenBuffers(1, &ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
    const GLsizei count[2] = { 4, 4 };
    const GLvoid *at[2] = { (const GLvoid *)0, (const GLvoid *)(4 * sizeof(GLushort)) };
    glMultiDrawElements(GL_QUAD_STRIP, count, GL_UNSIGNED_SHORT, at, 1);
    fc_error(h, "offset 0");
    fc_capture(h);
    glMultiDrawElements(GL_TRIANGLE_STRIP, count, GL_UNSIGNED_SHORT, at, 2);
    fc_error(h, "offsets 0 and 8");
    fc_capture(h);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    fcu_clear(0, 0, 0, 1, 1);
    const GLvoid *client[2] = { NULL, idx + 4 };
    glMultiDrawElements(GL_TRIANGLE_STRIP, count, GL_UNSIGNED_SHORT, client, 2);
    fc_error(h, "client NULL");
    fc_capture(h);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDeleteBuffers(1, &ibo);
}

const fc_case fc_cases_gl15[] = {
    FC_CASE_RGBA("gl15/multidraw_elements_offset0", 64, 48, 3, "gl14 gl15 vbo varray",
                 multidraw_elements_offset0),
    VBO("arrays_points", arrays_points),
    VBO("arrays_lines", arrays_lines),
    VBO("arrays_line_loop", arrays_line_loop),
    VBO("arrays_line_strip", arrays_line_strip),
    VBO("arrays_triangles", arrays_triangles),
    VBO("arrays_triangle_strip", arrays_triangle_strip),
    VBO("arrays_triangle_fan", arrays_triangle_fan),
    VBO("arrays_quads", arrays_quads),
    VBO("arrays_quad_strip", arrays_quad_strip),
    VBO("arrays_polygon", arrays_polygon),
    VBO_N("elements_ubyte_buffers", 5, elements_ubyte_buffers),
    VBO_N("elements_ushort_buffers", 5, elements_ushort_buffers),
    VBO_N("elements_uint_buffers", 5, elements_uint_buffers),
    VBO_N("elements_ubyte_client_indices", 5, elements_ubyte_client_indices),
    VBO_N("elements_ushort_client_indices", 5, elements_ushort_client_indices),
    VBO_N("elements_uint_client_arrays", 5, elements_uint_client_arrays),
    VBO_N("elements_ushort_client_arrays", 5, elements_ushort_client_arrays),
    VBO_N("range_elements_ubyte", 5, elements_range_ubyte),
    VBO_N("range_elements_ushort", 5, elements_range_ushort),
    VBO_N("range_elements_uint", 5, elements_range_uint),
    VBO_N("elements_misaligned", 2, elements_misaligned),
    VBO_N("array_element", 1, array_element_immediate),
    VBO_N("dlist_compile", 3, dlist_compile),
    VBO_N("dlist_compile_and_execute", 3, dlist_compile_execute),
    VBO_N("mapped_draw", 1, mapped_draw),
    VBO_N("mapped_element_buffer", 1, mapped_element_buffer),
    VBO_N("map_write_read", 1, map_write_read),
    VBO_N("subdata_contents", 0, subdata_contents),
    VBO_N("buffer_params", 0, buffer_params),
    VBO_N("names_isbuffer", 0, names_isbuffer),
    VBO_N("array_bindings", 0, array_bindings),
    VBO_N("delete_bound", 1, delete_bound),
    VBO_N("push_client_attrib", 1, push_client_attrib),
    VBO_N("push_client_attrib_deleted", 1, push_client_attrib_deleted),
    VBO_N("shared_contexts", 1, shared_contexts),
    VBO_N("all_arrays", 2, all_arrays),
    VBO_N("interleaved", 1, interleaved),
    VBO_N("ext_vertex_array", 1, ext_vertex_array),
    VBO_N("errors_no_buffer", 0, errors_no_buffer),
    VBO_N("errors_enums", 0, errors_enums),
    VBO_N("errors_values", 0, errors_values),
    VBO_N("errors_mapped", 0, errors_mapped),
    VBO_N("errors_begin_end", 0, errors_begin_end),
    VBO_N("dlist_not_compiled", 0, dlist_not_compiled),
    QRY("basic", 1, query_basic),
    QRY("depth", 1, query_depth),
    FC_CASE("gl15/query_depth16", 64, 64, OSMESA_RGBA, 16, 0, 1, "api gl15 query", query_depth16),
    FC_CASE("gl15/query_no_depth_buffer", 64, 64, OSMESA_RGBA, 0, 0, 1, "api gl15 query",
            query_no_depth_buffer),
    QRY("stencil", 1, query_stencil),
    QRY("alpha_test", 1, query_alpha_test),
    QRY("scissor_mask", 1, query_scissor_mask),
    QRY("spanning_clear", 1, query_spanning_clear),
    QRY("pixels", 1, query_pixels),
    QRY("points_lines", 1, query_points_lines),
    QRY("polygon_state", 1, query_polygon_state),
    QRY("textured_lit", 1, query_textured_lit),
    FC_CASE("gl15/query_many_tiles", 200, 150, OSMESA_RGBA, 24, 0, 1, "api gl15 query",
            query_many_tiles),
    QRY("display_lists", 1, query_display_lists),
    QRY("available", 1, query_available),
    QRY("errors", 0, query_errors),
    QRY("begin_end_errors", 0, query_begin_end_errors),
    QRY("names", 0, query_names),
    QRY("vbo_draw", 1, query_vbo_draw),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
