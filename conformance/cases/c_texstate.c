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
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0 },
};
