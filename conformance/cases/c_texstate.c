/* c_texstate.c - the first layer of texturing: the texture coordinate as a
 * vertex attribute (every glTexCoord variant, GL_CURRENT_TEXTURE_COORDS,
 * the texture coordinate array through glDrawArrays, glDrawElements,
 * glArrayElement and glInterleavedArrays, glPushAttrib(GL_CURRENT_BIT),
 * display lists), checked through queries and the GL_3D_COLOR_TEXTURE /
 * GL_4D_COLOR_TEXTURE feedback records (clipped vertices interpolate it;
 * the texture matrix applies only to a unit with a complete texture), and
 * rendering with GL_TEXTURE_1D/2D enabled while no texture can be complete
 * (the oracle leaves such a unit out of the fixed-function program). */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

#define FB_MARK (-12345.0f)

static GLfloat fbbuf[1024];

static void fb_begin(GLenum type)
{
    for (size_t i = 0; i < sizeof fbbuf / sizeof fbbuf[0]; i++)
        fbbuf[i] = FB_MARK;
    glFeedbackBuffer((GLsizei)(sizeof fbbuf / sizeof fbbuf[0]), type, fbbuf);
    glRenderMode(GL_FEEDBACK);
}

/* Back to GL_RENDER: the value count and the values written plus a few. */
static void fb_end(fc_h *h, const char *label)
{
    char l[96];
    const GLint n = glRenderMode(GL_RENDER);
    snprintf(l, sizeof l, "%s count", label);
    fc_value(h, l, n);
    int len = n < 0 ? 1024 : n + 4;
    if (len > 1024)
        len = 1024;
    snprintf(l, sizeof l, "%s buffer", label);
    fc_blob(h, l, fbbuf, (size_t)len * sizeof(GLfloat));
}

static void cur(fc_h *h, const char *label)
{
    fc_get_float(h, label, GL_CURRENT_TEXTURE_COORDS, 4);
}

/* Every glTexCoord variant, the current value after each. */
static void coord_variants(fc_h *h)
{
    static const GLshort sv[4] = { -3, 7, 32767, -32768 };
    static const GLint iv[4] = { 2147483647, -5, 9, 65536 };
    static const GLfloat fv[4] = { 0.25f, -1.5f, 1e20f, -0.0f };
    static const GLdouble dv[4] = { 1.0 / 3.0, 1e-40, -2.5e38, 7.125 };
    cur(h, "initial");
    glTexCoord1s(5); cur(h, "1s");
    glTexCoord2s(-2, 3); cur(h, "2s");
    glTexCoord3s(4, 5, 6); cur(h, "3s");
    glTexCoord4s(7, 8, 9, 10); cur(h, "4s");
    glTexCoord1sv(sv); cur(h, "1sv");
    glTexCoord2sv(sv); cur(h, "2sv");
    glTexCoord3sv(sv); cur(h, "3sv");
    glTexCoord4sv(sv); cur(h, "4sv");
    glTexCoord1i(-7); cur(h, "1i");
    glTexCoord2i(16777217, 3); cur(h, "2i");
    glTexCoord3i(1, 2, 3); cur(h, "3i");
    glTexCoord4i(4, 3, 2, 1); cur(h, "4i");
    glTexCoord1iv(iv); cur(h, "1iv");
    glTexCoord2iv(iv); cur(h, "2iv");
    glTexCoord3iv(iv); cur(h, "3iv");
    glTexCoord4iv(iv); cur(h, "4iv");
    glTexCoord1f(0.5f); cur(h, "1f");
    glTexCoord2f(0.5f, -0.75f); cur(h, "2f");
    glTexCoord3f(1.0f, 2.0f, NAN); cur(h, "3f");
    glTexCoord4f(1.0f, 2.0f, 3.0f, 0.0f); cur(h, "4f");
    glTexCoord1fv(fv); cur(h, "1fv");
    glTexCoord2fv(fv); cur(h, "2fv");
    glTexCoord3fv(fv); cur(h, "3fv");
    glTexCoord4fv(fv); cur(h, "4fv");
    glTexCoord1d(0.1); cur(h, "1d");
    glTexCoord2d(0.1, 1e300); cur(h, "2d");
    glTexCoord3d(-0.1, 0.2, 0.3); cur(h, "3d");
    glTexCoord4d(1, 2, 3, 4); cur(h, "4d");
    glTexCoord1dv(dv); cur(h, "1dv");
    glTexCoord2dv(dv); cur(h, "2dv");
    glTexCoord3dv(dv); cur(h, "3dv");
    glTexCoord4dv(dv); cur(h, "4dv");
    fc_get_double(h, "as double", GL_CURRENT_TEXTURE_COORDS, 4);
    fc_get_integer(h, "as integer", GL_CURRENT_TEXTURE_COORDS, 4);
    fc_get_boolean(h, "as boolean", GL_CURRENT_TEXTURE_COORDS, 4);
    /* inside glBegin/glEnd: the current value follows, queries are errors */
    glBegin(GL_POINTS);
    glTexCoord2f(9.0f, 8.0f);
    glVertex2f(0.0f, 0.0f);
    glTexCoord3f(1.0f, 1.0f, 1.0f);
    glEnd();
    cur(h, "after begin/end");
    glBegin(GL_TRIANGLES);
    cur(h, "query inside begin");
    glEnd();
    fc_error(h, "query inside begin");
}

/* A scene whose texture coordinates vary per vertex, in feedback: points,
 * lines and triangles, some clipped by the near plane and a side. */
static void coord_scene(void)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-0.5f, -0.5f, -2.0f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex3f(0.5f, -0.5f, -2.0f);
    glTexCoord4f(0.5f, 1.0f, 0.25f, 2.0f);
    glVertex3f(0.0f, 0.5f, -2.0f);
    /* crosses the near plane (z = -1) and the right side */
    glTexCoord3f(-1.0f, 2.0f, 3.0f);
    glVertex3f(-0.5f, 0.0f, -0.5f);
    glTexCoord1f(4.0f);
    glVertex3f(3.0f, -0.2f, -3.0f);
    glTexCoord4f(0.0f, 1.0f, 2.0f, 3.0f);
    glVertex3f(0.2f, 0.8f, -4.0f);
    glEnd();
    glBegin(GL_LINES);
    glTexCoord2f(0.125f, 0.5f);
    glVertex3f(-0.9f, 0.9f, -2.0f);
    glTexCoord2f(0.875f, -0.5f);
    glVertex3f(0.9f, -0.9f, -0.25f);   /* clipped by the near plane */
    glEnd();
    glBegin(GL_POINTS);
    glTexCoord3f(0.3f, 0.6f, 0.9f);
    glVertex3f(0.1f, 0.1f, -3.0f);
    glEnd();
}

static void persp(void)
{
    glViewport(0, 0, 32, 32);
    fcu_frustum(-1, 1, -1, 1, 1, 10);
}

static void coord_feedback(fc_h *h)
{
    persp();
    fb_begin(GL_4D_COLOR_TEXTURE);
    coord_scene();
    fb_end(h, "4d");
    fb_begin(GL_3D_COLOR_TEXTURE);
    coord_scene();
    fb_end(h, "3d");
    /* smooth and flat, lit: the texture coordinate is never flat */
    glShadeModel(GL_FLAT);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    fb_begin(GL_4D_COLOR_TEXTURE);
    coord_scene();
    fb_end(h, "flat lit");
    glDisable(GL_LIGHTING);
    glShadeModel(GL_SMOOTH);
    /* unfilled polygons (the unfilled stage's lines and points) */
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    fb_begin(GL_3D_COLOR_TEXTURE);
    coord_scene();
    fb_end(h, "line mode");
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    fb_begin(GL_3D_COLOR_TEXTURE);
    coord_scene();
    fb_end(h, "point mode");
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    /* the other feedback types carry no texture coordinate; select mode */
    fb_begin(GL_3D_COLOR);
    coord_scene();
    fb_end(h, "3d color");
    cur(h, "current");
}

/* The texture matrix: not applied in feedback while no unit has a
 * complete texture, whether or not a texture target is enabled. */
static void coord_texmatrix(fc_h *h)
{
    persp();
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.5f, 0.25f, 0.0f);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    glScalef(2.0f, 3.0f, 4.0f);
    glMatrixMode(GL_MODELVIEW);
    fb_begin(GL_4D_COLOR_TEXTURE);
    coord_scene();
    fb_end(h, "disabled");
    glEnable(GL_TEXTURE_2D);
    fb_begin(GL_4D_COLOR_TEXTURE);
    coord_scene();
    fb_end(h, "2d enabled, incomplete");
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_1D);
    fb_begin(GL_4D_COLOR_TEXTURE);
    coord_scene();
    fb_end(h, "1d enabled, incomplete");
    cur(h, "current");
}

static const GLfloat arr_pos[4][3] = {
    { -0.6f, -0.6f, -2.0f }, { 0.6f, -0.6f, -2.0f },
    { 0.6f, 0.6f, -0.5f }, { -0.6f, 0.6f, -3.0f },
};

/* The texture coordinate array: every type and size through
 * glDrawArrays, glDrawElements, glArrayElement (which also sets the
 * current value), with and without a list being compiled. */
static void coord_array(fc_h *h)
{
    static const GLshort s[4][4] = { { 1, 2, 3, 4 }, { -5, 6, -7, 8 },
                                     { 9, -10, 11, -12 }, { 32767, -32768, 0, 1 } };
    static const GLint iv[4][4] = { { 1, 2, 3, 4 }, { -5, 6, -7, 8 },
                                    { 9, -10, 11, -12 }, { 100000, -3, 0, 2 } };
    static const GLfloat f[4][4] = { { 0.0f, 0.5f, 1.0f, 2.0f }, { 0.25f, -1.0f, 3.0f, 1.0f },
                                     { 1.0f, 1.0f, -2.0f, 0.5f }, { 0.75f, 0.125f, 8.0f, 4.0f } };
    static const GLdouble d[4][4] = { { 0.1, 0.2, 0.3, 0.4 }, { -0.5, 0.6, 0.7, 0.8 },
                                      { 1.5, 2.5, 3.5, 4.5 }, { 1e-3, 1e3, 1e6, 1.0 } };
    static const GLubyte idx[6] = { 0, 1, 2, 0, 2, 3 };
    const struct { GLenum type; const void *p; GLsizei stride; } t[4] = {
        { GL_SHORT, s, 8 }, { GL_INT, iv, 16 }, { GL_FLOAT, f, 16 }, { GL_DOUBLE, d, 32 },
    };
    persp();
    glVertexPointer(3, GL_FLOAT, 0, arr_pos);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    char l[64];
    for (int ti = 0; ti < 4; ti++) {
        for (int size = 1; size <= 4; size++) {
            glTexCoordPointer(size, t[ti].type, t[ti].stride, t[ti].p);
            fb_begin(GL_4D_COLOR_TEXTURE);
            glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
            glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);
            glBegin(GL_LINE_STRIP);
            glArrayElement(3);
            glArrayElement(1);
            glArrayElement(2);
            glEnd();
            snprintf(l, sizeof l, "type %x size %d", t[ti].type, size);
            fb_end(h, l);
            snprintf(l, sizeof l, "type %x size %d current", t[ti].type, size);
            cur(h, l);
        }
    }
    /* the array disabled: the current value for every vertex */
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoord2f(0.5f, 0.5f);
    fb_begin(GL_3D_COLOR_TEXTURE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fb_end(h, "disabled");
    /* glArrayElement compiled into a list */
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 16, f);
    const GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glArrayElement(0);
    glArrayElement(2);
    glArrayElement(3);
    glEnd();
    glEndList();
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoord1f(-1.0f);
    fb_begin(GL_3D_COLOR_TEXTURE);
    glCallList(list);
    fb_end(h, "list");
    cur(h, "after list");
}

/* glInterleavedArrays' formats with texture coordinates. */
static void coord_interleaved(fc_h *h)
{
    static const GLfloat t2v3[4][5] = {
        { 0.0f, 0.0f, -0.6f, -0.6f, -2.0f }, { 1.0f, 0.0f, 0.6f, -0.6f, -2.0f },
        { 1.0f, 1.0f, 0.6f, 0.6f, -0.5f }, { 0.0f, 1.0f, -0.6f, 0.6f, -3.0f },
    };
    static const GLfloat t4v4[4][8] = {
        { 0.1f, 0.2f, 0.3f, 0.4f, -0.6f, -0.6f, -2.0f, 1.0f },
        { 0.5f, 0.6f, 0.7f, 0.8f, 0.6f, -0.6f, -2.0f, 1.0f },
        { 0.9f, 1.0f, 1.1f, 1.2f, 1.2f, 1.2f, -1.0f, 2.0f },
        { 1.3f, 1.4f, 1.5f, 1.6f, -0.6f, 0.6f, -3.0f, 1.0f },
    };
    struct { GLfloat t[2]; GLubyte c[4]; GLfloat v[3]; } t2c4ub[4] = {
        { { 0.0f, 0.0f }, { 255, 0, 0, 255 }, { -0.6f, -0.6f, -2.0f } },
        { { 2.0f, 0.0f }, { 0, 255, 0, 128 }, { 0.6f, -0.6f, -2.0f } },
        { { 2.0f, 2.0f }, { 0, 0, 255, 0 }, { 0.6f, 0.6f, -0.5f } },
        { { 0.0f, 2.0f }, { 255, 255, 0, 255 }, { -0.6f, 0.6f, -3.0f } },
    };
    static const GLfloat t2c4n3v3[3][12] = {
        { 0.5f, 0.5f, 1, 0, 0, 1, 0, 0, 1, -0.5f, -0.5f, -2.0f },
        { 0.7f, 0.1f, 0, 1, 0, 1, 0, 1, 0, 0.5f, -0.5f, -2.0f },
        { 0.2f, 0.9f, 0, 0, 1, 1, 1, 0, 0, 0.0f, 0.5f, -2.0f },
    };
    persp();
    glInterleavedArrays(GL_T2F_V3F, 0, t2v3);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glDrawArrays(GL_QUADS, 0, 4);
    fb_end(h, "T2F_V3F");
    glInterleavedArrays(GL_T4F_V4F, 0, t4v4);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    fb_end(h, "T4F_V4F");
    glInterleavedArrays(GL_T2F_C4UB_V3F, sizeof t2c4ub[0], t2c4ub);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glDrawArrays(GL_POLYGON, 0, 4);
    fb_end(h, "T2F_C4UB_V3F");
    glInterleavedArrays(GL_T2F_C4F_N3F_V3F, 0, t2c4n3v3);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glBegin(GL_TRIANGLES);
    glArrayElement(2);
    glArrayElement(0);
    glArrayElement(1);
    glEnd();
    fb_end(h, "T2F_C4F_N3F_V3F");
    cur(h, "current");
    /* a format without texture coordinates disables the array */
    glInterleavedArrays(GL_V3F, 0, arr_pos);
    fc_is_enabled(h, "array after V3F", GL_TEXTURE_COORD_ARRAY);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fb_end(h, "V3F");
}

/* glPushAttrib(GL_CURRENT_BIT) keeps the texture coordinate, also one
 * set inside an unfinished batch; other groups do not. */
static void coord_pushpop(fc_h *h)
{
    glTexCoord4f(1.0f, 2.0f, 3.0f, 4.0f);
    glPushAttrib(GL_CURRENT_BIT);
    glTexCoord2f(5.0f, 6.0f);
    cur(h, "changed");
    glPopAttrib();
    cur(h, "popped");
    glPushAttrib(GL_ALL_ATTRIB_BITS & ~GL_CURRENT_BIT);
    glTexCoord3f(7.0f, 8.0f, 9.0f);
    glPopAttrib();
    cur(h, "other groups");
    /* set between vertices of a pending batch, then pushed */
    persp();
    glBegin(GL_POINTS);
    glTexCoord1f(0.5f);
    glVertex3f(0.0f, 0.0f, -2.0f);
    glEnd();
    glPushAttrib(GL_CURRENT_BIT);
    glBegin(GL_POINTS);
    glTexCoord2f(0.25f, 0.75f);
    glVertex3f(0.1f, 0.0f, -2.0f);
    glEnd();
    glPopAttrib();
    cur(h, "popped after batch");
    fb_begin(GL_3D_COLOR_TEXTURE);
    glBegin(GL_POINTS);
    glVertex3f(0.0f, 0.0f, -2.0f);
    glEnd();
    fb_end(h, "point after pop");
}

/* Display lists: texture coordinates compiled into vertex lists, in and
 * outside glBegin/glEnd, a list that only sets the current value, and
 * GL_COMPILE_AND_EXECUTE. */
static void coord_dlist(fc_h *h)
{
    persp();
    const GLuint base = glGenLists(4);
    glNewList(base, GL_COMPILE);
    coord_scene();
    glEndList();
    glNewList(base + 1, GL_COMPILE);
    glTexCoord3f(0.5f, 0.25f, 0.125f);
    glEndList();
    glNewList(base + 2, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex3f(-0.5f, -0.5f, -2.0f);   /* before any texcoord: the current one */
    glTexCoord2s(1, 2);
    glVertex3f(0.5f, -0.5f, -2.0f);
    glVertex3f(-0.5f, 0.5f, -2.0f);
    glTexCoord4d(0.5, 0.5, 0.5, 0.5);
    glVertex3f(0.5f, 0.5f, -2.0f);
    glEnd();
    glEndList();
    cur(h, "after compile and execute");
    glTexCoord1i(3);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glCallList(base);
    glCallList(base + 2);
    fb_end(h, "lists");
    cur(h, "after lists");
    glCallList(base + 1);
    cur(h, "texcoord list");
    glTexCoord1i(3);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glCallList(base + 2);
    fb_end(h, "strip again");
    glDeleteLists(base, 4);
}

/* The vertex format grows mid-primitive when a texture coordinate first
 * appears (the batch splits like any attribute's upgrade); rendered, and
 * in feedback. */
static void coord_upgrade(fc_h *h)
{
    persp();
    fcu_clear(0, 0, 0, 1, 1);
    for (int pass = 0; pass < 2; pass++) {
        if (pass)
            fb_begin(GL_4D_COLOR_TEXTURE);
        glBegin(GL_QUADS);
        for (int i = 0; i < 8; i++) {
            const float x = -0.9f + 0.23f * (float)i;
            if (i == 5)
                glTexCoord2f(0.5f, 0.5f);
            if (i == 6)
                glTexCoord4f(0.5f, 0.5f, 1.0f, 2.0f);
            fcu_color(i);
            glVertex3f(x, (i & 1) ? 0.8f : -0.8f, (i & 2) ? -0.5f : -3.0f);
        }
        glEnd();
        if (pass)
            fb_end(h, "feedback");
        else
            fc_capture(h);
    }
}

/* Drawing with GL_TEXTURE_1D/2D enabled and the default texture objects,
 * which have no image: the oracle leaves the unit out of the fixed-function
 * fragment program (texstate.c:update_ff_texture_state skips a unit with
 * an incomplete texture), so nothing changes. */
static void incomplete_scene(fc_h *h, bool lit, bool fog)
{
    persp();
    glEnable(GL_DEPTH_TEST);
    fcu_clear(0.2f, 0.3f, 0.4f, 0.5f, 1);
    if (lit) {
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
        static const GLfloat spec[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 10.0f);
    }
    if (fog) {
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_START, 1.0f);
        glFogf(GL_FOG_END, 5.0f);
    }
    static const GLenum targets[3] = { GL_TEXTURE_2D, GL_TEXTURE_1D, 0 };
    for (int t = 0; t < 3; t++) {
        glDisable(GL_TEXTURE_1D);
        glDisable(GL_TEXTURE_2D);
        if (targets[t])
            glEnable(targets[t]);
        glPushMatrix();
        glTranslatef(0.0f, 0.0f, -0.3f * (float)t);
        glBegin(GL_TRIANGLES);
        glNormal3f(0.0f, 0.3f, 1.0f);
        glColor4f(1.0f, 0.2f, 0.1f, 0.7f);
        glTexCoord2f(0.0f, 0.0f);
        glVertex3f(-0.8f, -0.8f, -2.0f);
        glColor4f(0.1f, 1.0f, 0.2f, 0.3f);
        glTexCoord2f(1.0f, 0.0f);
        glVertex3f(0.8f, -0.7f, -4.0f);
        glColor4f(0.2f, 0.1f, 1.0f, 1.0f);
        glTexCoord2f(0.5f, 1.0f);
        glVertex3f(0.0f, 0.8f, -1.5f);
        glEnd();
        glBegin(GL_LINES);
        glVertex3f(-0.9f, 0.9f, -2.0f);
        glVertex3f(0.9f, -0.5f, -3.0f);
        glEnd();
        glPopMatrix();
        fc_capture(h);
    }
    fc_is_enabled(h, "1d", GL_TEXTURE_1D);
    fc_is_enabled(h, "2d", GL_TEXTURE_2D);
}

static void incomplete_unlit(fc_h *h) { incomplete_scene(h, false, false); }
static void incomplete_lit(fc_h *h) { incomplete_scene(h, true, false); }
static void incomplete_fog(fc_h *h) { incomplete_scene(h, false, true); }
static void incomplete_lit_fog(fc_h *h) { incomplete_scene(h, true, true); }

/* Blending with the incomplete texture enabled (alpha untouched). */
static void incomplete_blend(fc_h *h)
{
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.4f);
    incomplete_scene(h, false, false);
}


/* ---- texture objects and parameters ---- */

static void tex_params(fc_h *h, const char *label, GLenum target)
{
    static const GLenum pnames[] = {
        GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S,
        GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R, GL_TEXTURE_BORDER_COLOR,
        GL_TEXTURE_PRIORITY, GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD,
        GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL, GL_GENERATE_MIPMAP,
        GL_TEXTURE_RESIDENT, GL_TEXTURE_LOD_BIAS,
    };
    char l[96];
    for (size_t i = 0; i < sizeof pnames / sizeof pnames[0]; i++) {
        GLfloat f[4] = { -7, -7, -7, -7 };
        GLint iv[4] = { -7, -7, -7, -7 };
        glGetTexParameterfv(target, pnames[i], f);
        glGetTexParameteriv(target, pnames[i], iv);
        snprintf(l, sizeof l, "%s %x fv", label, pnames[i]);
        fc_blob(h, l, f, sizeof f);
        snprintf(l, sizeof l, "%s %x iv", label, pnames[i]);
        fc_blob(h, l, iv, sizeof iv);
    }
    snprintf(l, sizeof l, "%s errors", label);
    fc_error(h, l);
}

static void bindings(fc_h *h, const char *label)
{
    char l[96];
    snprintf(l, sizeof l, "%s 1d", label);
    fc_get_integer(h, l, GL_TEXTURE_BINDING_1D, 1);
    snprintf(l, sizeof l, "%s 2d", label);
    fc_get_integer(h, l, GL_TEXTURE_BINDING_2D, 1);
    snprintf(l, sizeof l, "%s 3d", label);
    fc_get_integer(h, l, GL_TEXTURE_BINDING_3D, 1);
}

/* glGenTextures, glBindTexture, glDeleteTextures, glIsTexture,
 * glAreTexturesResident, glPrioritizeTextures: names, targets, errors. */
static void objects(fc_h *h)
{
    GLuint t[6] = { 0 };
    glGenTextures(3, t);
    fc_blob(h, "gen 3", t, sizeof t);
    fc_value(h, "is before bind", glIsTexture(t[0]));
    fc_value(h, "is 0", glIsTexture(0));
    fc_value(h, "is unknown", glIsTexture(999));
    glBindTexture(GL_TEXTURE_2D, t[0]);
    fc_value(h, "is after bind", glIsTexture(t[0]));
    bindings(h, "bound t0");
    glBindTexture(GL_TEXTURE_1D, t[0]);
    fc_error(h, "t0 to 1d");
    bindings(h, "after mismatch");
    glBindTexture(GL_TEXTURE_1D, t[1]);
    glBindTexture(GL_TEXTURE_3D, t[2]);
    glBindTexture(GL_PROXY_TEXTURE_2D, t[2]);
    fc_error(h, "proxy target");
    glBindTexture(GL_TEXTURE_2D + 1, 0);
    fc_error(h, "bad target");
    /* (GL_TEXTURE_RECTANGLE, foreign to GL 1.5, in honesty/texture_targets) */
    glBindTexture(GL_TEXTURE_3D, 77);
    fc_error(h, "3d, new name");
    fc_value(h, "is 77", glIsTexture(77));
    glBindTexture(GL_TEXTURE_2D, 50);  /* not generated: created */
    fc_value(h, "is 50", glIsTexture(50));
    bindings(h, "bound 50");
    glGenTextures(2, t + 3);
    fc_blob(h, "gen after 77", t, sizeof t);
    /* a generated name's parameters before its first bind: a priority
     * stays (a rectangle's own wraps and filters: honesty/texture_targets) */
    const GLclampf half = 0.5f;
    glPrioritizeTextures(1, &t[4], &half);
    glBindTexture(GL_TEXTURE_3D, t[4]);
    tex_params(h, "3d first bound", GL_TEXTURE_3D);
    glBindTexture(GL_TEXTURE_3D, 0);
    glGenTextures(0, t);
    glGenTextures(-1, t);
    fc_error(h, "gen -1");
    glGenTextures(1, NULL);
    fc_error(h, "gen null");
    /* residency */
    GLboolean res[4] = { 9, 9, 9, 9 };
    GLuint names[3] = { t[0], t[1], 50 };
    fc_value(h, "resident", glAreTexturesResident(3, names, res));
    fc_blob(h, "residences", res, sizeof res);
    names[1] = 0;
    fc_value(h, "resident 0", glAreTexturesResident(3, names, res));
    fc_error(h, "resident 0");
    names[1] = 12345;
    fc_value(h, "resident unknown", glAreTexturesResident(3, names, res));
    fc_error(h, "resident unknown");
    names[1] = t[3];   /* generated, never bound */
    fc_value(h, "resident unbound", glAreTexturesResident(3, names, res));
    fc_error(h, "resident unbound");
    fc_value(h, "resident -1", glAreTexturesResident(-1, names, res));
    fc_error(h, "resident -1");
    fc_blob(h, "residences after", res, sizeof res);
    /* priorities, clamped; names without objects skipped */
    const GLuint pn[4] = { t[0], 0, 4321, t[1] };
    const GLclampf pr[4] = { 0.25f, 0.5f, 0.75f, 7.0f };
    glPrioritizeTextures(4, pn, pr);
    fc_error(h, "prioritize");
    tex_params(h, "2d t0", GL_TEXTURE_2D);
    tex_params(h, "1d t1", GL_TEXTURE_1D);
    glPrioritizeTextures(-2, pn, pr);
    fc_error(h, "prioritize -2");
    const GLclampf neg = -3.0f;
    glPrioritizeTextures(1, pn, &neg);
    tex_params(h, "2d negative priority", GL_TEXTURE_2D);
    /* deleting unbinds; names are not reused */
    GLuint del[4] = { t[0], 0, 9999, t[1] };
    glDeleteTextures(4, del);
    fc_error(h, "delete");
    bindings(h, "after delete");
    fc_value(h, "is deleted", glIsTexture(t[0]));
    glGenTextures(2, t);
    fc_blob(h, "gen after delete", t, sizeof t);
    glDeleteTextures(-1, del);
    fc_error(h, "delete -1");
    glBindTexture(GL_TEXTURE_1D, del[0]);   /* a deleted name: created again */
    fc_value(h, "rebound deleted", glIsTexture(del[0]));
    bindings(h, "rebound");
    /* inside glBegin/glEnd */
    glBegin(GL_POINTS);
    glBindTexture(GL_TEXTURE_2D, 0);
    glEnd();
    fc_error(h, "bind in begin");
    glBegin(GL_POINTS);
    fc_value(h, "is in begin", glIsTexture(50));
    glEnd();
    fc_error(h, "is in begin");
    glBegin(GL_POINTS);
    glDeleteTextures(1, t);
    glEnd();
    fc_error(h, "delete in begin");
}

static void set_and_check(fc_h *h, const char *label, GLenum target, GLenum pname, GLint v)
{
    glTexParameteri(target, pname, v);
    char l[96];
    snprintf(l, sizeof l, "%s error", label);
    fc_error(h, l);
    GLint got = -7;
    glGetTexParameteriv(target, pname, &got);
    snprintf(l, sizeof l, "%s value", label);
    fc_value(h, l, got);
}

/* Every GL 1.3 parameter with each setter and its errors, on the default
 * 2D object and a named 1D object. */
static void parameters(fc_h *h)
{
    tex_params(h, "default 2d", GL_TEXTURE_2D);
    tex_params(h, "default 1d", GL_TEXTURE_1D);
    tex_params(h, "default 3d", GL_TEXTURE_3D);
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_1D, t);
    static const GLenum targets[2] = { GL_TEXTURE_2D, GL_TEXTURE_1D };
    static const GLint minf[] = { GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
                                  GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                                  GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT, 0 };
    static const GLint wraps[] = { GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER,
                                   GL_MIRRORED_REPEAT, GL_REPEAT, GL_LINEAR, GL_MIRROR_CLAMP_EXT };
    char l[96];
    for (int ti = 0; ti < 2; ti++) {
        const GLenum tg = targets[ti];
        for (size_t i = 0; i < sizeof minf / sizeof minf[0]; i++) {
            snprintf(l, sizeof l, "%x min %x", tg, minf[i]);
            set_and_check(h, l, tg, GL_TEXTURE_MIN_FILTER, minf[i]);
            snprintf(l, sizeof l, "%x mag %x", tg, minf[i]);
            set_and_check(h, l, tg, GL_TEXTURE_MAG_FILTER, minf[i]);
        }
        for (size_t i = 0; i < sizeof wraps / sizeof wraps[0]; i++) {
            snprintf(l, sizeof l, "%x wrap s %x", tg, wraps[i]);
            set_and_check(h, l, tg, GL_TEXTURE_WRAP_S, wraps[i]);
            snprintf(l, sizeof l, "%x wrap t %x", tg, wraps[i]);
            set_and_check(h, l, tg, GL_TEXTURE_WRAP_T, wraps[i]);
            snprintf(l, sizeof l, "%x wrap r %x", tg, wraps[i]);
            set_and_check(h, l, tg, GL_TEXTURE_WRAP_R, wraps[i]);
        }
        static const GLint levels[] = { 3, 0, -1, 1000, 2000000000 };
        for (size_t i = 0; i < sizeof levels / sizeof levels[0]; i++) {
            snprintf(l, sizeof l, "%x base %d", tg, levels[i]);
            set_and_check(h, l, tg, GL_TEXTURE_BASE_LEVEL, levels[i]);
            snprintf(l, sizeof l, "%x max %d", tg, levels[i]);
            set_and_check(h, l, tg, GL_TEXTURE_MAX_LEVEL, levels[i]);
        }
        set_and_check(h, "genmip 5", tg, GL_GENERATE_MIPMAP, 5);
        set_and_check(h, "genmip 0", tg, GL_GENERATE_MIPMAP, 0);
        set_and_check(h, "resident", tg, GL_TEXTURE_RESIDENT, 1);
        set_and_check(h, "bad pname", tg, GL_TEXTURE_WIDTH, 1);
        /* floats, scalar and vector; the integer getters round them */
        static const GLfloat lods[] = { -1.5f, 2.5f, 0.5f, -0.5f, 1e10f, -1e10f, 3.49f };
        for (size_t i = 0; i < sizeof lods / sizeof lods[0]; i++) {
            glTexParameterf(tg, GL_TEXTURE_MIN_LOD, lods[i]);
            glTexParameterfv(tg, GL_TEXTURE_MAX_LOD, &lods[i]);
            glTexParameterf(tg, GL_TEXTURE_LOD_BIAS, lods[i]);
            glTexParameterf(tg, GL_TEXTURE_PRIORITY, lods[i] * 0.25f);
            snprintf(l, sizeof l, "%x lod %g", tg, lods[i]);
            tex_params(h, l, tg);
        }
        glTexParameteri(tg, GL_TEXTURE_MIN_LOD, -3);
        glTexParameteri(tg, GL_TEXTURE_PRIORITY, 1);
        tex_params(h, "int lod", tg);
        /* float calls on integer pnames: rounded (scalar) or cast (vector) */
        glTexParameterf(tg, GL_TEXTURE_BASE_LEVEL, 2.5f);
        glTexParameterf(tg, GL_TEXTURE_MAX_LEVEL, -0.4f);
        tex_params(h, "float levels", tg);
        const GLfloat fl[4] = { 4.9f, 0, 0, 0 };
        glTexParameterfv(tg, GL_TEXTURE_BASE_LEVEL, fl);
        glTexParameterf(tg, GL_TEXTURE_MIN_FILTER, (GLfloat)GL_LINEAR);
        tex_params(h, "float levels v", tg);
        /* border colours: floats unclamped when set, ints normalized */
        const GLfloat bc[4] = { -0.5f, 0.25f, 2.0f, 1.0f };
        glTexParameterfv(tg, GL_TEXTURE_BORDER_COLOR, bc);
        tex_params(h, "border f", tg);
        const GLint bi[4] = { 2147483647, -2147483647 - 1, 1073741824, 0 };
        glTexParameteriv(tg, GL_TEXTURE_BORDER_COLOR, bi);
        tex_params(h, "border i", tg);
        glTexParameterf(tg, GL_TEXTURE_BORDER_COLOR, 0.5f);
        fc_error(h, "border scalar f");
        glTexParameteri(tg, GL_TEXTURE_BORDER_COLOR, 1);
        fc_error(h, "border scalar i");
        glTexParameterf(tg, GL_TEXTURE_WIDTH, 1.0f);
        fc_error(h, "bad pname f");
    }
    /* (the rectangle rules: honesty/texture_targets) */
    /* targets */
    glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    fc_error(h, "proxy");
    glTexParameteri(0, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    fc_error(h, "target 0");
    GLfloat f = -7;
    glGetTexParameterfv(GL_PROXY_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, &f);
    fc_error(h, "get proxy");
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, &f);
    fc_error(h, "get bad pname");
    glBegin(GL_POINTS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnd();
    fc_error(h, "in begin");
    tex_params(h, "final 2d", GL_TEXTURE_2D);
    tex_params(h, "final 1d", GL_TEXTURE_1D);
}

/* glPushAttrib(GL_TEXTURE_BIT): bindings and the bound named objects'
 * parameters come back; the default objects keep theirs. */
static void texture_pushpop(fc_h *h)
{
    GLuint t[2];
    glGenTextures(2, t);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    glPushAttrib(GL_TEXTURE_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 0.5f);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
    glBindTexture(GL_TEXTURE_1D, t[1]);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    bindings(h, "changed");
    glPopAttrib();
    bindings(h, "popped");
    tex_params(h, "popped 2d", GL_TEXTURE_2D);
    tex_params(h, "popped 1d", GL_TEXTURE_1D);
    glBindTexture(GL_TEXTURE_1D, t[1]);
    tex_params(h, "t1 after pop", GL_TEXTURE_1D);
    /* only GL_GENERATE_MIPMAP changed: the group is not marked */
    glBindTexture(GL_TEXTURE_1D, 0);
    glPushAttrib(GL_TEXTURE_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    glPopAttrib();
    tex_params(h, "genmip only", GL_TEXTURE_2D);
    /* the bound object deleted between push and pop */
    glPushAttrib(GL_TEXTURE_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glDeleteTextures(1, t);
    bindings(h, "deleted");
    glPopAttrib();
    bindings(h, "popped after delete");
    fc_value(h, "is deleted after pop", glIsTexture(t[0]));
    tex_params(h, "recreated", GL_TEXTURE_2D);
    /* GL_ALL_ATTRIB_BITS */
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glBindTexture(GL_TEXTURE_2D, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 4);
    glPopAttrib();
    bindings(h, "all bits");
    tex_params(h, "all bits 2d", GL_TEXTURE_2D);
}

/* Display lists: glBindTexture and glTexParameter are compiled (every
 * variant as glTexParameterfv of params[0]), glGenTextures, glIsTexture,
 * glDeleteTextures, glAreTexturesResident and the getters run at once. */
static void texture_dlist(fc_h *h)
{
    GLuint t[2];
    const GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glGenTextures(2, t);
    fc_blob(h, "gen in list", t, sizeof t);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    fc_value(h, "is in list", glIsTexture(t[0]));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 2.5f);
    const GLint bi[4] = { 2147483647, 1073741824, 0, 2147483647 };
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, bi);
    const GLfloat bf[4] = { 0.5f, 0.25f, 0.125f, 2.0f };
    glTexParameterfv(GL_TEXTURE_1D, GL_TEXTURE_BORDER_COLOR, bf);
    const GLuint pn[3] = { t[0], 0, t[1] };
    const GLclampf pr[3] = { 0.125f, 0.5f, -1.0f };
    glPrioritizeTextures(3, pn, pr);
    glPrioritizeTextures(-1, pn, pr);   /* nothing compiled, no error */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR);  /* error at replay */
    glBindTexture(GL_TEXTURE_1D, t[0]);                             /* error at replay */
    glBindTexture(GL_TEXTURE_1D, t[1]);
    glEndList();
    fc_error(h, "compile");
    bindings(h, "after compile");
    tex_params(h, "after compile 2d", GL_TEXTURE_2D);
    glCallList(list);
    fc_error(h, "replay");
    bindings(h, "after replay");
    tex_params(h, "after replay 2d", GL_TEXTURE_2D);
    tex_params(h, "after replay 1d", GL_TEXTURE_1D);
    /* compile and execute */
    glNewList(list, GL_COMPILE_AND_EXECUTE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEndList();
    bindings(h, "compile and execute");
    tex_params(h, "compile and execute 2d", GL_TEXTURE_2D);
    glDeleteLists(list, 1);
}


/* ---- texture environment ---- */

static void env_state(fc_h *h, const char *label)
{
    static const GLenum pnames[] = {
        GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR, GL_COMBINE_RGB, GL_COMBINE_ALPHA,
        GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_SOURCE2_RGB, GL_SOURCE3_RGB_NV,
        GL_SOURCE0_ALPHA, GL_SOURCE1_ALPHA, GL_SOURCE2_ALPHA, GL_SOURCE3_ALPHA_NV,
        GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB, GL_OPERAND3_RGB_NV,
        GL_OPERAND0_ALPHA, GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA, GL_OPERAND3_ALPHA_NV,
        GL_RGB_SCALE, GL_ALPHA_SCALE,
    };
    char l[96];
    for (size_t i = 0; i < sizeof pnames / sizeof pnames[0]; i++) {
        GLfloat f[4] = { -7, -7, -7, -7 };
        GLint iv[4] = { -7, -7, -7, -7 };
        glGetTexEnvfv(GL_TEXTURE_ENV, pnames[i], f);
        glGetTexEnviv(GL_TEXTURE_ENV, pnames[i], iv);
        snprintf(l, sizeof l, "%s %x fv", label, pnames[i]);
        fc_blob(h, l, f, sizeof f);
        snprintf(l, sizeof l, "%s %x iv", label, pnames[i]);
        fc_blob(h, l, iv, sizeof iv);
    }
    GLfloat b = -7;
    GLint bi = -7;
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &b);
    glGetTexEnviv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &bi);
    snprintf(l, sizeof l, "%s lod bias", label);
    fc_blob(h, l, &b, sizeof b);
    fc_value(h, l, bi);
    snprintf(l, sizeof l, "%s errors", label);
    fc_error(h, l);
}

static void env_set(fc_h *h, const char *label, GLenum pname, GLint v)
{
    glTexEnvi(GL_TEXTURE_ENV, pname, v);
    fc_error(h, label);
}

/* glTexEnv: every mode, the colour, every combiner parameter and value,
 * their errors, the LOD bias, push/pop and lists. */
static void environment(fc_h *h)
{
    env_state(h, "initial");
    static const GLint modes[] = { GL_BLEND, GL_DECAL, GL_REPLACE, GL_ADD, GL_COMBINE,
                                   GL_COMBINE4_NV, GL_MODULATE, GL_LINEAR, 0 };
    char l[96];
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        snprintf(l, sizeof l, "mode %x", modes[i]);
        env_set(h, l, GL_TEXTURE_ENV_MODE, modes[i]);
        GLint m = -7;
        glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &m);
        fc_value(h, l, m);
    }
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLfloat)GL_DECAL + 0.7f);
    fc_error(h, "mode float");
    const GLfloat col[4] = { -0.5f, 0.25f, 1.5f, 0.75f };
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, col);
    env_state(h, "colour f");
    const GLint coli[4] = { 2147483647, -2147483647 - 1, 1073741824, 0 };
    glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, coli);
    env_state(h, "colour i");
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 0.5f);
    env_state(h, "colour scalar");
    static const GLint cmodes[] = { GL_REPLACE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE,
                                    GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA, GL_DOT3_RGB_EXT,
                                    GL_MODULATE_ADD_ATI, GL_MODULATE_SIGNED_ADD_ATI,
                                    GL_MODULATE_SUBTRACT_ATI, GL_BLEND, GL_MODULATE };
    for (size_t i = 0; i < sizeof cmodes / sizeof cmodes[0]; i++) {
        snprintf(l, sizeof l, "combine rgb %x", cmodes[i]);
        env_set(h, l, GL_COMBINE_RGB, cmodes[i]);
        snprintf(l, sizeof l, "combine alpha %x", cmodes[i]);
        env_set(h, l, GL_COMBINE_ALPHA, cmodes[i]);
        env_state(h, l);
    }
    static const GLint sources[] = { GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS,
                                     GL_TEXTURE0, GL_TEXTURE7, GL_TEXTURE8, GL_TEXTURE31,
                                     GL_ZERO, GL_ONE, GL_SRC_COLOR };
    static const GLenum spn[] = { GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_SOURCE2_RGB, GL_SOURCE3_RGB_NV,
                                  GL_SOURCE0_ALPHA, GL_SOURCE1_ALPHA, GL_SOURCE2_ALPHA,
                                  GL_SOURCE3_ALPHA_NV };
    for (size_t p = 0; p < sizeof spn / sizeof spn[0]; p++)
        for (size_t i = 0; i < sizeof sources / sizeof sources[0]; i++) {
            snprintf(l, sizeof l, "source %x %x", spn[p], sources[i]);
            env_set(h, l, spn[p], sources[i]);
        }
    env_state(h, "sources");
    static const GLint operands[] = { GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                      GL_ONE_MINUS_SRC_ALPHA, GL_ZERO };
    static const GLenum opn[] = { GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB,
                                  GL_OPERAND3_RGB_NV, GL_OPERAND0_ALPHA, GL_OPERAND1_ALPHA,
                                  GL_OPERAND2_ALPHA, GL_OPERAND3_ALPHA_NV };
    for (size_t p = 0; p < sizeof opn / sizeof opn[0]; p++)
        for (size_t i = 0; i < sizeof operands / sizeof operands[0]; i++) {
            snprintf(l, sizeof l, "operand %x %x", opn[p], operands[i]);
            env_set(h, l, opn[p], operands[i]);
        }
    env_state(h, "operands");
    static const GLfloat scales[] = { 2.0f, 4.0f, 3.0f, 0.0f, 1.0f, 4.0f };
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, scales[i]);
        glTexEnvfv(GL_TEXTURE_ENV, GL_ALPHA_SCALE, &scales[i]);
        snprintf(l, sizeof l, "scale %g", scales[i]);
        env_state(h, l);
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 2);
    env_state(h, "scale int");
    /* LOD bias, bad targets and pnames */
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 2.75f);
    env_state(h, "lod bias");
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, 1.0f);
    fc_error(h, "filter control bad pname");
    glTexEnvi(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    fc_error(h, "bad target");
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    fc_error(h, "bad pname");
    GLfloat f = -7;
    glGetTexEnvfv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, &f);
    fc_error(h, "get bad target");
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_MIN_FILTER, &f);
    fc_error(h, "get bad pname");
    glBegin(GL_POINTS);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glEnd();
    fc_error(h, "in begin");
    /* push/pop */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    glPushAttrib(GL_TEXTURE_BIT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, col);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PRIMARY_COLOR);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.0f);
    glPopAttrib();
    env_state(h, "popped");
    /* lists */
    const GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, coli);
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 4.0f);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 3.0f);   /* error at replay */
    glEndList();
    env_state(h, "after compile");
    glCallList(list);
    env_state(h, "after replay");
    glDeleteLists(list, 1);
}


/* Every environment mode with an incomplete texture enabled, lit with fog
 * and unlit: the unit is left out, so the mode changes nothing. */
static void incomplete_env_modes(fc_h *h)
{
    static const GLenum modes[6] = { GL_MODULATE, GL_DECAL, GL_REPLACE, GL_BLEND, GL_ADD,
                                     GL_COMBINE };
    static const GLfloat envcol[4] = { 0.9f, 0.1f, 0.5f, 0.3f };
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envcol);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_CONSTANT);
    for (int m = 0; m < 6; m++) {
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)modes[m]);
        glPushAttrib(GL_ALL_ATTRIB_BITS);
        incomplete_scene(h, (m & 1) != 0, m >= 2);
        glPopAttrib();
    }
}


/* GL_TEXTURE_BIT before any glBindTexture: the oracle saves the objects
 * and LOD bias only of units that have had a texture bound, so the default
 * objects' parameters are not restored; a unit first bound after the push
 * goes back to the default objects, the node's stale LOD bias comes back. */
static void texture_pushpop_unused(fc_h *h)
{
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.5f);
    glBindTexture(GL_TEXTURE_2D, 0);   /* already bound: does not count */
    glPushAttrib(GL_TEXTURE_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_T, GL_CLAMP);
    glPopAttrib();
    tex_params(h, "unused 2d", GL_TEXTURE_2D);
    tex_params(h, "unused 1d", GL_TEXTURE_1D);
    env_state(h, "unused env");
    /* bound after the push */
    glPushAttrib(GL_TEXTURE_BIT);
    glBindTexture(GL_TEXTURE_2D, 5);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -2.0f);
    glPopAttrib();
    bindings(h, "bound after push");
    tex_params(h, "bound after push 2d", GL_TEXTURE_2D);
    env_state(h, "bound after push env");
    /* now saved: a second level of nesting */
    glPushAttrib(GL_TEXTURE_BIT);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 3.0f);
    glPushAttrib(GL_TEXTURE_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 4.0f);
    glPopAttrib();
    env_state(h, "inner pop");
    tex_params(h, "inner pop 2d", GL_TEXTURE_2D);
    glPopAttrib();
    env_state(h, "outer pop");
}


/* ---- coordinate generation state ---- */

static void gen_state(fc_h *h, const char *label)
{
    static const GLenum coords[4] = { GL_S, GL_T, GL_R, GL_Q };
    static const GLenum pn[3] = { GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE };
    char l[96];
    for (int c = 0; c < 4; c++)
        for (int p = 0; p < 3; p++) {
            GLfloat f[4] = { -7, -7, -7, -7 };
            GLint iv[4] = { -7, -7, -7, -7 };
            GLdouble d[4] = { -7, -7, -7, -7 };
            glGetTexGenfv(coords[c], pn[p], f);
            glGetTexGeniv(coords[c], pn[p], iv);
            glGetTexGendv(coords[c], pn[p], d);
            snprintf(l, sizeof l, "%s %x %x", label, coords[c], pn[p]);
            fc_blob(h, l, f, sizeof f);
            fc_blob(h, l, iv, sizeof iv);
            fc_blob(h, l, d, sizeof d);
        }
    snprintf(l, sizeof l, "%s errors", label);
    fc_error(h, l);
}

/* glTexGen: modes per coordinate and their errors, object planes, eye
 * planes through several modelviews (inverse applied at specification),
 * every variant, push/pop and lists. */
static void texgen(fc_h *h)
{
    gen_state(h, "initial");
    static const GLenum coords[4] = { GL_S, GL_T, GL_R, GL_Q };
    static const GLint modes[] = { GL_OBJECT_LINEAR, GL_SPHERE_MAP, GL_REFLECTION_MAP,
                                   GL_NORMAL_MAP, GL_EYE_LINEAR, GL_LINEAR };
    char l[96];
    for (int c = 0; c < 4; c++)
        for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
            glTexGeni(coords[c], GL_TEXTURE_GEN_MODE, modes[m]);
            snprintf(l, sizeof l, "mode %x %x", coords[c], modes[m]);
            fc_error(h, l);
            GLint got = -7;
            glGetTexGeniv(coords[c], GL_TEXTURE_GEN_MODE, &got);
            fc_value(h, l, got);
        }
    const GLfloat op[4] = { 0.5f, -1.25f, 3.0f, 7.9f };
    glTexGenfv(GL_S, GL_OBJECT_PLANE, op);
    const GLdouble opd[4] = { 1.0 / 3.0, 2.0, -3.5, 1e-3 };
    glTexGendv(GL_T, GL_OBJECT_PLANE, opd);
    const GLint opi[4] = { 1, -2, 3, 100000 };
    glTexGeniv(GL_R, GL_OBJECT_PLANE, opi);
    glTexGenf(GL_Q, GL_OBJECT_PLANE, 2.0f);
    gen_state(h, "object planes");
    glTexGend(GL_S, GL_TEXTURE_GEN_MODE, (GLdouble)GL_SPHERE_MAP);
    glTexGenf(GL_R, GL_TEXTURE_GEN_MODE, (GLfloat)GL_SPHERE_MAP);
    fc_error(h, "sphere on r");
    gen_state(h, "modes");
    /* eye planes under moving modelviews */
    const GLfloat ep[4] = { 1.0f, 0.5f, -0.25f, 2.0f };
    glTexGenfv(GL_S, GL_EYE_PLANE, ep);
    glTranslatef(1.0f, -2.0f, 3.0f);
    glTexGenfv(GL_T, GL_EYE_PLANE, ep);
    glRotatef(33.0f, 0.3f, 0.4f, 0.5f);
    glScalef(2.0f, 0.5f, 3.0f);
    glTexGenfv(GL_R, GL_EYE_PLANE, ep);
    const GLfloat m[16] = { 1, 2, 0, 0.5f, 0, 1, 3, 0, 0.25f, 0, 1, 0, 4, 5, 6, 1 };
    glLoadMatrixf(m);
    const GLdouble epd[4] = { 0.1, 0.2, 0.3, 0.4 };
    glTexGendv(GL_Q, GL_EYE_PLANE, epd);
    gen_state(h, "eye planes");
    glScalef(0.0f, 1.0f, 1.0f);   /* singular */
    glTexGenfv(GL_S, GL_EYE_PLANE, ep);
    gen_state(h, "singular");
    glLoadIdentity();
    /* errors */
    glTexGeni(GL_S + 4, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    fc_error(h, "bad coord");
    glTexGeni(GL_S, GL_TEXTURE_ENV_MODE, GL_EYE_LINEAR);
    fc_error(h, "bad pname");
    GLfloat f[4];
    glGetTexGenfv(GL_S + 4, GL_TEXTURE_GEN_MODE, f);
    fc_error(h, "get bad coord");
    glGetTexGenfv(GL_S, GL_TEXTURE_ENV_MODE, f);
    fc_error(h, "get bad pname");
    glBegin(GL_POINTS);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glEnd();
    fc_error(h, "in begin");
    /* push/pop, with the enables */
    glEnable(GL_TEXTURE_GEN_S);
    glPushAttrib(GL_TEXTURE_BIT);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_T, GL_OBJECT_PLANE, ep);
    glTexGenfv(GL_R, GL_EYE_PLANE, op);
    glDisable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_Q);
    glPopAttrib();
    gen_state(h, "popped");
    fc_is_enabled(h, "gen s", GL_TEXTURE_GEN_S);
    fc_is_enabled(h, "gen q", GL_TEXTURE_GEN_Q);
    /* lists: compiled, the eye plane transformed at replay */
    const GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
    glTexGeniv(GL_S, GL_EYE_PLANE, opi);
    glTexGend(GL_Q, GL_TEXTURE_GEN_MODE, (GLdouble)GL_REFLECTION_MAP);   /* error */
    glEndList();
    gen_state(h, "after compile");
    glTranslatef(0.5f, 0.25f, -1.0f);
    glCallList(list);
    gen_state(h, "after replay");
    glDeleteLists(list, 1);
}

/* Mesa's CLAMP(x, 0, 1) of the priority, border colour and environment
 * colour (texparam.c:set_tex_parameterf, texenv.c:set_env_color): NaN and
 * -0 are stored as +0, read back through every query type. */
static void clamp_nan(fc_h *h)
{
    const float nan = NAN;
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR,
                     (const GLfloat[]){ nan, -0.0f, 2.0f, -1.0f });
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, nan);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR,
               (const GLfloat[]){ -0.0f, nan, 0.5f, 3.0f });
    fc_error(h, "set");
    GLfloat f[4];
    GLint iv[4];
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, f);
    fc_blob(h, "border colour fv", f, sizeof f);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, iv);
    fc_blob(h, "border colour iv", iv, sizeof iv);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, f);
    fc_blob(h, "priority fv", f, sizeof(GLfloat));
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
    fc_blob(h, "env colour fv", f, sizeof f);
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, iv);
    fc_blob(h, "env colour iv", iv, sizeof iv);
    fc_error(h, "get");
}

const fc_case fc_cases_texstate[] = {
    FC_CASE_RGBA("texstate/coord_variants", 16, 16, 0, "texture api", coord_variants),
    FC_CASE_RGBA("texstate/coord_feedback", 32, 32, 0, "texture api feedback", coord_feedback),
    FC_CASE_RGBA("texstate/coord_texmatrix", 32, 32, 0, "texture api feedback", coord_texmatrix),
    FC_CASE_RGBA("texstate/coord_array", 32, 32, 0, "texture api varray", coord_array),
    FC_CASE_RGBA("texstate/coord_interleaved", 32, 32, 0, "texture api varray", coord_interleaved),
    FC_CASE_RGBA("texstate/coord_pushpop", 32, 32, 0, "texture api attrib", coord_pushpop),
    FC_CASE_RGBA("texstate/coord_dlist", 32, 32, 0, "texture api dlist", coord_dlist),
    FC_CASE_RGBA("texstate/coord_upgrade", 32, 32, 1, "texture api", coord_upgrade),
    FC_CASE_RGBA("texstate/incomplete_unlit", 48, 48, 3, "texture api", incomplete_unlit),
    FC_CASE_RGBA("texstate/incomplete_lit", 48, 48, 3, "texture api lighting", incomplete_lit),
    FC_CASE_RGBA("texstate/incomplete_fog", 48, 48, 3, "texture api fog", incomplete_fog),
    FC_CASE_RGBA("texstate/incomplete_lit_fog", 48, 48, 3, "texture api lighting fog",
                 incomplete_lit_fog),
    FC_CASE_RGBA("texstate/incomplete_blend", 48, 48, 3, "texture api fragment", incomplete_blend),
    FC_CASE_RGBA("texstate/objects", 16, 16, 0, "texture api", objects),
    FC_CASE_RGBA("texstate/parameters", 16, 16, 0, "texture api", parameters),
    FC_CASE_RGBA("texstate/texture_pushpop", 16, 16, 0, "texture api attrib", texture_pushpop),
    FC_CASE_RGBA("texstate/texture_dlist", 16, 16, 0, "texture api dlist", texture_dlist),
    FC_CASE_RGBA("texstate/incomplete_env_modes", 48, 48, 18, "texture api lighting fog",
                 incomplete_env_modes),
    FC_CASE_RGBA("texstate/texture_pushpop_unused", 16, 16, 0, "texture api attrib",
                 texture_pushpop_unused),
    FC_CASE_RGBA("texstate/environment", 16, 16, 0, "texture api", environment),
    FC_CASE_RGBA("texstate/texgen", 16, 16, 0, "texture api", texgen),
    FC_CASE_RGBA("texstate/clamp_nan", 8, 8, 0, "texture api query", clamp_nan),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
