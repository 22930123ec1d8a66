/* c_select.c - selection and feedback (glRenderMode, glSelectBuffer, the
 * name stack, glFeedbackBuffer, glPassThrough): hit records and feedback
 * buffers compared value by value (whole buffers, pre-filled with a marker
 * so unwritten values compare too), glRenderMode's return values, errors,
 * queries and the overflow behaviour.  A picking demo with a hand-built
 * pick matrix, depths of clipped objects and of objects crossing the near
 * and far planes, every feedback type for every primitive, lit, two-sided
 * and flat colours, polygon modes with edge flags, culling, clipping,
 * polygon offset, and the state that survives mode switches. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

#define SEL_MARK 0xabababu
#define FB_MARK (-12345.0f)

static GLuint selbuf[512];
static GLfloat fbbuf[2048];

static void sel_begin(GLsizei size)
{
    for (size_t i = 0; i < sizeof selbuf / sizeof selbuf[0]; i++)
        selbuf[i] = SEL_MARK;
    glSelectBuffer(size, selbuf);
    glRenderMode(GL_SELECT);
}

/* Back to GL_RENDER: the hit count (or -1) and the buffer up to limit. */
static void sel_end(fc_h *h, const char *label, int limit)
{
    char l[96];
    const GLint hits = glRenderMode(GL_RENDER);
    snprintf(l, sizeof l, "%s hits", label);
    fc_value(h, l, hits);
    snprintf(l, sizeof l, "%s buffer", label);
    fc_blob(h, l, selbuf, (size_t)limit * sizeof(GLuint));
}

static void fb_begin(GLsizei size, GLenum type)
{
    for (size_t i = 0; i < sizeof fbbuf / sizeof fbbuf[0]; i++)
        fbbuf[i] = FB_MARK;
    glFeedbackBuffer(size, type, fbbuf);
    glRenderMode(GL_FEEDBACK);
}

/* Back to GL_RENDER: the value count (or -1) and the values written (plus
 * a few beyond, up to limit when the count is larger). */
static void fb_end(fc_h *h, const char *label, int limit)
{
    char l[96];
    const GLint n = glRenderMode(GL_RENDER);
    snprintf(l, sizeof l, "%s count", label);
    fc_value(h, l, n);
    int len = n < 0 ? limit : n + 4;
    if (len > limit)
        len = limit;
    snprintf(l, sizeof l, "%s buffer", label);
    fc_blob(h, l, fbbuf, (size_t)len * sizeof(GLfloat));
}

/* gluPickMatrix(x, y, w, h, viewport), multiplied onto the current matrix. */
static void pick_matrix(float x, float y, float w, float hgt, const GLint vp[4])
{
    glTranslatef(((float)vp[2] - 2.0f * (x - (float)vp[0])) / w,
                 ((float)vp[3] - 2.0f * (y - (float)vp[1])) / hgt, 0.0f);
    glScalef((float)vp[2] / w, (float)vp[3] / hgt, 1.0f);
}

static void cube(float s)
{
    static const float n[6][3] = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 },
                                   { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 } };
    static const int f[6][4] = { { 4, 5, 6, 7 }, { 1, 0, 3, 2 }, { 5, 1, 2, 6 },
                                 { 0, 4, 7, 3 }, { 7, 6, 2, 3 }, { 0, 1, 5, 4 } };
    float v[8][3];
    for (int i = 0; i < 8; i++) {
        v[i][0] = (i == 1 || i == 2 || i == 5 || i == 6) ? s : -s;
        v[i][1] = (i == 2 || i == 3 || i == 6 || i == 7) ? s : -s;
        v[i][2] = i >= 4 ? s : -s;
    }
    glBegin(GL_QUADS);
    for (int k = 0; k < 6; k++) {
        glNormal3fv(n[k]);
        for (int j = 0; j < 4; j++)
            glVertex3fv(v[f[k][j]]);
    }
    glEnd();
}

/* The picking demo's scene: named objects, nested names. */
static void pick_scene(void)
{
    glInitNames();
    glPushName(1);                       /* the "table" */
    glPushMatrix();
    glTranslatef(-1.0f, 0.0f, -6.0f);
    glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
    cube(0.7f);
    glPopMatrix();
    glPushName(10);                      /* a part of it */
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.5f, -0.5f, -4.0f);
    glVertex3f(0.8f, -0.3f, -5.5f);
    glVertex3f(0.1f, 0.9f, -7.0f);
    glEnd();
    glPopName();
    glLoadName(2);                       /* a "chair" */
    glPushMatrix();
    glTranslatef(1.2f, 0.3f, -5.0f);
    glRotatef(-20.0f, 0.0f, 1.0f, 0.3f);
    cube(0.5f);
    glPopMatrix();
    glLoadName(3);                       /* a lamp: lines and points */
    glBegin(GL_LINES);
    glVertex3f(0.0f, -1.0f, -3.0f);
    glVertex3f(0.3f, 1.0f, -9.0f);
    glEnd();
    glBegin(GL_POINTS);
    glVertex3f(0.05f, 0.05f, -5.0f);
    glVertex3f(0.9f, -0.9f, -4.5f);
    glEnd();
    glPopName();
    glPushName(4);                       /* behind the camera: no hit */
    glBegin(GL_TRIANGLES);
    glVertex3f(-1.0f, -1.0f, 2.0f);
    glVertex3f(1.0f, -1.0f, 2.0f);
    glVertex3f(0.0f, 1.0f, 2.0f);
    glEnd();
}

/* A picking demo: the whole view, then pick windows around a few points. */
static void picking(fc_h *h)
{
    const GLint vp[4] = { 0, 0, 64, 48 };
    glViewport(vp[0], vp[1], vp[2], vp[3]);
    static const float picks[][4] = {
        { 32, 24, 64, 48 }, { 32, 24, 5, 5 }, { 20, 26, 3, 3 }, { 44, 28, 4, 4 },
        { 33.5f, 25.5f, 1, 1 }, { 2, 2, 2, 2 }, { 50, 10, 8, 8 },
    };
    for (size_t i = 0; i < sizeof picks / sizeof picks[0]; i++) {
        char l[32];
        sel_begin(256);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        pick_matrix(picks[i][0], picks[i][1], picks[i][2], picks[i][3], vp);
        glFrustum(-1.0, 1.0, -0.75, 0.75, 2.0, 10.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        pick_scene();
        snprintf(l, sizeof l, "pick %zu", i);
        sel_end(h, l, 64);
    }
    fc_error(h, "after picking");
}

/* Depths of hits: objects crossing the near and far planes (the clipped
 * vertices count), partly outside the view, a point exactly on the far
 * plane (1.0 -> 0 by the oracle's conversion), a slightly negative depth
 * (a new vertex on the near plane: 0xffffff00), depth ranges, reversed
 * depth range. */
static void hit_depths(fc_h *h)
{
    sel_begin(256);
    fcu_frustum(-1, 1, -1, 1, 1, 5);
    glPushName(1);
    glBegin(GL_TRIANGLES);                  /* crosses the near plane */
    glVertex3f(-0.5f, -0.5f, -0.5f);
    glVertex3f(0.5f, -0.5f, -3.0f);
    glVertex3f(0.0f, 0.5f, -2.0f);
    glEnd();
    glLoadName(2);
    glBegin(GL_TRIANGLES);                  /* crosses the far plane */
    glVertex3f(-0.5f, -0.5f, -3.0f);
    glVertex3f(0.5f, -0.5f, -8.0f);
    glVertex3f(0.0f, 0.5f, -4.0f);
    glEnd();
    glLoadName(3);
    glBegin(GL_TRIANGLES);                  /* crosses both */
    glVertex3f(-0.2f, -0.2f, -0.2f);
    glVertex3f(0.3f, -0.3f, -9.0f);
    glVertex3f(0.0f, 0.4f, -3.0f);
    glEnd();
    glLoadName(4);
    glBegin(GL_QUADS);                      /* partly left of the view */
    glVertex3f(-6.0f, -1.0f, -3.0f);
    glVertex3f(0.5f, -1.0f, -2.5f);
    glVertex3f(0.5f, 1.0f, -3.5f);
    glVertex3f(-6.0f, 1.0f, -4.5f);
    glEnd();
    glLoadName(5);
    glBegin(GL_LINES);                      /* a line through the volume */
    glVertex3f(-3.0f, 0.1f, -0.3f);
    glVertex3f(2.0f, -0.1f, -7.0f);
    glEnd();
    glLoadName(7);
    glBegin(GL_TRIANGLES);                  /* a new vertex on the near plane
                                             * gets a window z below 0 */
    glVertex3f(-0x1.2e147ap-2f, 0x1.083126p-3f, -0x1.db22dp-3f);
    glVertex3f(0x1.70a3d8p-1f, 0x1.b126eap-2f, -0x1.1f5c28p+1f);
    glVertex3f(-0x1.fef9dcp-2f, -0x1.0d4fep-1f, -0x1.208312p+1f);
    glEnd();
    glLoadName(6);
    glBegin(GL_TRIANGLES);                  /* entirely outside */
    glVertex3f(3.0f, 3.0f, -2.0f);
    glVertex3f(4.0f, 3.0f, -2.0f);
    glVertex3f(3.0f, 4.0f, -2.0f);
    glEnd();
    sel_end(h, "frustum", 64);

    /* identity matrices: exact plane positions */
    sel_begin(256);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glPushName(7);
    glBegin(GL_POINTS);
    glVertex3f(0.0f, 0.0f, 1.0f);           /* far plane: 1.0 */
    glEnd();
    glLoadName(8);
    glBegin(GL_POINTS);
    glVertex3f(0.0f, 0.0f, -1.0f);          /* near plane: 0.0 */
    glEnd();
    glLoadName(9);
    glBegin(GL_POINTS);
    glVertex4f(0.3f, 0.0f, -3.0f, 3.0f);    /* z = -w: depth 0 */
    glEnd();
    glLoadName(10);                         /* the same after a hit reset */
    glBegin(GL_POINTS);
    glVertex4f(0.3f, 0.0f, -3.0f, 3.0f);
    glEnd();
    glInitNames();                          /* and after glInitNames */
    glPushName(11);
    glBegin(GL_POINTS);
    glVertex4f(0.3f, 0.0f, -3.0f, 3.0f);
    glEnd();
    glLoadName(12);
    glBegin(GL_POINTS);
    glVertex3f(0.0f, 0.0f, 0.5f);
    glVertex3f(0.1f, 0.0f, -0.25f);
    glVertex3f(0.2f, 0.0f, 0.999f);
    glVertex3f(0.3f, 0.0f, 1.0001f);        /* clipped */
    glEnd();
    sel_end(h, "planes", 64);

    static const double ranges[][2] = { { 0.2, 0.7 }, { 1.0, 0.0 }, { 0.5, 0.5 }, { 0.0, 1.0 } };
    for (int r = 0; r < 4; r++) {
        char l[32];
        glDepthRange(ranges[r][0], ranges[r][1]);
        sel_begin(256);
        glPushName((GLuint)r);
        glBegin(GL_TRIANGLE_STRIP);
        glVertex3f(-0.5f, -0.5f, -0.9f);
        glVertex3f(0.5f, -0.5f, 0.3f);
        glVertex3f(-0.5f, 0.5f, -0.1f);
        glVertex3f(0.5f, 0.5f, 0.95f);
        glEnd();
        glPushName(100);
        glBegin(GL_LINE_LOOP);
        glVertex3f(-0.9f, 0.0f, 0.1f);
        glVertex3f(0.0f, -0.9f, 0.2f);
        glVertex3f(0.9f, 0.9f, -0.7f);
        glEnd();
        snprintf(l, sizeof l, "range %d", r);
        sel_end(h, l, 32);
    }
}

/* When hits are written: by glLoadName, glPushName, glPopName,
 * glInitNames and glRenderMode, only after something was hit; hits with
 * an empty name stack; culled faces, unfilled modes and polygon offset. */
static void hit_flush(fc_h *h)
{
    fc_pixel_ortho(h);
    sel_begin(256);
    fcu_tri(1, 1, 10, 1, 1, 10);            /* empty stack hit */
    glPushName(1);                          /* writes it (0 names) */
    glPushName(2);                          /* nothing pending */
    fcu_rect(2, 2, 8, 8, 0.25f);
    glPopName();                            /* writes 1 2 */
    fcu_rect(2, 2, 8, 8, -0.5f);
    glLoadName(3);                          /* writes 1 */
    glLoadName(4);                          /* nothing */
    glPopName();
    glPopName();                            /* underflow, no write */
    fc_error(h, "underflow");
    glPushName(5);
    fcu_tri(1, 1, 10, 1, 1, 10);
    glInitNames();                          /* writes 5 */
    glPushName(6);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    fcu_tri(1, 1, 1, 10, 10, 1);            /* clockwise: culled */
    glLoadName(7);
    glFrontFace(GL_CW);
    fcu_tri(1, 1, 1, 10, 10, 1);            /* now front */
    glFrontFace(GL_CCW);
    glDisable(GL_CULL_FACE);
    glLoadName(8);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_FALSE);
    glVertex3f(1, 1, 0.5f);
    glEdgeFlag(GL_TRUE);
    glVertex3f(10, 1, -0.5f);
    glVertex3f(1, 10, 0.25f);
    glEnd();
    glLoadName(9);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_FALSE);
    glVertex3f(1, 1, 0.5f);
    glVertex3f(10, 1, -0.5f);
    glVertex3f(1, 10, 0.25f);
    glEnd();                                /* no edges: no hit */
    glEdgeFlag(GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glLoadName(10);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(4.0f, 1000.0f);
    glBegin(GL_TRIANGLES);
    glVertex3f(1, 1, 0.5f);
    glVertex3f(10, 1, -0.5f);
    glVertex3f(1, 10, 0.25f);
    glEnd();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glLoadName(11);
    fcu_tri(1, 1, 10, 1, 1, 10);            /* written by glRenderMode */
    sel_end(h, "flush", 80);
    fc_get_integer(h, "depth after", GL_NAME_STACK_DEPTH, 1);
}

/* Small selection buffers: values up to the size are written, the rest
 * counted; glRenderMode returns -1; a later selection starts over. */
static void select_overflow(fc_h *h)
{
    fc_pixel_ortho(h);
    static const int sizes[] = { 1, 3, 4, 5, 9, 10, 11, 30 };
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        char l[32];
        sel_begin(sizes[i]);
        glPushName(0x11111111u);
        fcu_tri(1, 1, 10, 1, 1, 10);
        glPushName(0x22222222u);
        fcu_rect(2, 2, 6, 6, 0.5f);
        glPopName();
        glLoadName(0x33333333u);
        fcu_rect(3, 3, 7, 7, -0.5f);
        snprintf(l, sizeof l, "size %d", sizes[i]);
        sel_end(h, l, 32);
    }
    /* overflow, then the same buffer again without glSelectBuffer */
    sel_begin(2);
    glPushName(1);
    fcu_tri(1, 1, 10, 1, 1, 10);
    sel_end(h, "overflow", 8);
    glRenderMode(GL_SELECT);
    glPushName(1);
    sel_end(h, "no hit", 8);
}

/* The name stack: its depth limit, overflow and underflow errors, calls
 * outside GL_SELECT ignored, glLoadName on an empty stack. */
static void name_stack(fc_h *h)
{
    fc_get_integer(h, "max depth", GL_MAX_NAME_STACK_DEPTH, 1);
    fc_get_integer(h, "depth", GL_NAME_STACK_DEPTH, 1);
    glPushName(1);
    glLoadName(2);
    glPopName();
    glPopName();
    glInitNames();
    fc_error(h, "outside select");
    fc_get_integer(h, "depth outside", GL_NAME_STACK_DEPTH, 1);

    fc_pixel_ortho(h);
    sel_begin(512);
    glLoadName(1);
    fc_error(h, "load empty");
    glPopName();
    fc_error(h, "pop empty");
    for (GLuint i = 0; i < 64; i++)
        glPushName(i + 100);
    fc_error(h, "64 pushes");
    fc_get_integer(h, "depth 64", GL_NAME_STACK_DEPTH, 1);
    fcu_tri(1, 1, 10, 1, 1, 10);
    glPushName(999);
    fc_error(h, "overflow");
    fc_get_integer(h, "depth after overflow", GL_NAME_STACK_DEPTH, 1);
    glLoadName(7);
    fcu_tri(1, 1, 10, 1, 1, 10);
    for (int i = 0; i < 63; i++)
        glPopName();
    fc_get_integer(h, "depth 1", GL_NAME_STACK_DEPTH, 1);
    fcu_tri(1, 1, 10, 1, 1, 10);
    glPopName();
    glPopName();
    fc_error(h, "underflow");
    glBegin(GL_TRIANGLES);
    glPushName(3);
    fc_error(h, "push in begin");
    glLoadName(3);
    glPopName();
    glInitNames();
    fc_error(h, "names in begin");
    glEnd();
    sel_end(h, "stack", 160);
    fc_get_integer(h, "depth after select", GL_NAME_STACK_DEPTH, 1);
}

/* Errors and state of selection: glSelectBuffer sizes and mode, glRenderMode
 * without a buffer (an error, yet the mode changes), bad modes, inside
 * glBegin/glEnd; the queries and buffer pointers. */
static void select_errors(fc_h *h)
{
    fc_get_integer(h, "render mode", GL_RENDER_MODE, 1);
    fc_get_integer(h, "sel size", GL_SELECTION_BUFFER_SIZE, 1);
    GLvoid *p = (GLvoid *)1;
    glGetPointerv(GL_SELECTION_BUFFER_POINTER, &p);
    fc_value(h, "initial pointer null", p == NULL);
    fc_value(h, "select without buffer", glRenderMode(GL_SELECT));
    fc_error(h, "select without buffer");
    fc_get_integer(h, "mode after", GL_RENDER_MODE, 1);
    fc_pixel_ortho(h);
    fcu_tri(1, 1, 10, 1, 1, 10);
    glPushName(4);
    fcu_tri(1, 1, 10, 1, 1, 10);
    fc_value(h, "back to render", glRenderMode(GL_RENDER));
    fc_error(h, "back to render");

    glSelectBuffer(-1, selbuf);
    fc_error(h, "negative size");
    glSelectBuffer(0, selbuf);
    fc_error(h, "size 0");
    fc_value(h, "select size 0", glRenderMode(GL_SELECT));
    fc_error(h, "select size 0");
    glSelectBuffer(16, selbuf);
    fc_error(h, "buffer while selecting");
    glSelectBuffer(-1, selbuf);
    fc_error(h, "negative while selecting");
    fc_value(h, "leave", glRenderMode(GL_RENDER));

    glSelectBuffer(40, selbuf);
    fc_get_integer(h, "sel size 40", GL_SELECTION_BUFFER_SIZE, 1);
    fc_get_float(h, "sel size float", GL_SELECTION_BUFFER_SIZE, 1);
    fc_get_boolean(h, "render mode bool", GL_RENDER_MODE, 1);
    fc_get_double(h, "max depth double", GL_MAX_NAME_STACK_DEPTH, 1);
    fc_get_float(h, "feedback type float", GL_FEEDBACK_BUFFER_TYPE, 1);
    glGetPointerv(GL_SELECTION_BUFFER_POINTER, &p);
    fc_value(h, "pointer", p == (GLvoid *)selbuf);
    fc_value(h, "bad mode", glRenderMode(GL_POINT));
    fc_error(h, "bad mode");
    fc_get_integer(h, "mode after bad", GL_RENDER_MODE, 1);

    /* a bad mode while selecting: the pending hit is written and the
     * selection state reset before the error */
    sel_begin(40);
    glPushName(9);
    fcu_tri(1, 1, 10, 1, 1, 10);
    fc_value(h, "bad mode in select", glRenderMode(GL_LINE));
    fc_error(h, "bad mode in select");
    fc_get_integer(h, "mode still select", GL_RENDER_MODE, 1);
    fc_get_integer(h, "depth reset", GL_NAME_STACK_DEPTH, 1);
    glPushName(10);
    fcu_tri(1, 1, 10, 1, 1, 10);
    sel_end(h, "after bad mode", 16);

    glBegin(GL_POINTS);
    fc_value(h, "render mode in begin", glRenderMode(GL_SELECT));
    fc_error(h, "render mode in begin");
    glSelectBuffer(8, selbuf);
    fc_error(h, "select buffer in begin");
    glVertex2f(1, 1);
    glEnd();
    glFinish();
    fc_get_integer(h, "mode end", GL_RENDER_MODE, 1);
    fc_get_integer(h, "sel size end", GL_SELECTION_BUFFER_SIZE, 1);
}

/* One triangle with a perspective projection in every feedback type. */
static void feedback_types(fc_h *h)
{
    static const GLenum types[] = { GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE,
                                    GL_4D_COLOR_TEXTURE };
    glViewport(3, 5, 50, 40);
    for (size_t i = 0; i < 5; i++) {
        char l[32];
        fb_begin(512, types[i]);
        fc_get_integer(h, "type", GL_FEEDBACK_BUFFER_TYPE, 1);
        fcu_frustum(-1, 1, -0.8, 0.8, 1.5, 20);
        glTranslatef(0.1f, -0.2f, -4.0f);
        glRotatef(25.0f, 0.3f, 1.0f, 0.2f);
        glBegin(GL_TRIANGLES);
        glColor3f(1.0f, 0.2f, 0.1f);
        glVertex3f(-1.0f, -1.0f, 0.5f);
        glColor4f(0.1f, 0.9f, 0.3f, 0.5f);
        glVertex3f(1.2f, -0.7f, -0.5f);
        glColor3ub(10, 20, 250);
        glVertex3f(0.1f, 1.1f, 0.0f);
        glEnd();
        glBegin(GL_POINTS);
        glVertex3f(0.3f, 0.3f, 0.3f);
        glEnd();
        glBegin(GL_LINES);
        glVertex3f(-0.3f, 0.3f, 1.3f);
        glColor3f(0.5f, 0.5f, 0.5f);
        glVertex3f(0.7f, -0.6f, -2.0f);
        glEnd();
        snprintf(l, sizeof l, "type %zu", i);
        fb_end(h, l, 512);
    }
}

static void color_i(int i)
{
    glColor4f(0.1f + 0.11f * (float)(i % 8), 1.0f - 0.13f * (float)(i % 7),
              0.3f + 0.17f * (float)(i % 4), 1.0f - 0.05f * (float)i);
}

static void prim(GLenum mode, const float (*v)[2], int n, float dx, float dy)
{
    glBegin(mode);
    for (int i = 0; i < n; i++) {
        color_i(i);
        glVertex3f(v[i][0] + dx, v[i][1] + dy, 0.1f * (float)i - 0.3f);
    }
    glEnd();
}

/* Points, lines, strips, loops (also stippled, wide and smooth: lines are
 * never reset tokens) in GL_3D_COLOR. */
static void feedback_points_lines(fc_h *h)
{
    fc_pixel_ortho(h);
    static const float pts[5][2] = { { 2.5f, 3.25f }, { 10, 20 }, { 30.75f, 5 }, { 17, 17 }, { 5, 28 } };
    fb_begin(2048, GL_3D_COLOR);
    prim(GL_POINTS, pts, 5, 0, 0);
    prim(GL_LINES, pts, 5, 0, 0);
    prim(GL_LINE_STRIP, pts, 5, 0, 0);
    prim(GL_LINE_LOOP, pts, 5, 0, 0);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x0f0f);
    prim(GL_LINES, pts, 4, 0.5f, 0);
    prim(GL_LINE_STRIP, pts, 5, 0.5f, 0);
    prim(GL_LINE_LOOP, pts, 3, 0.5f, 0);
    glDisable(GL_LINE_STIPPLE);
    glLineWidth(3.0f);
    glPointSize(4.0f);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    prim(GL_LINE_STRIP, pts, 3, 0, 0.5f);
    prim(GL_POINTS, pts, 3, 0, 0.5f);
    glShadeModel(GL_FLAT);
    prim(GL_LINE_LOOP, pts, 4, 0, 0.25f);
    fb_end(h, "points lines", 2048);
}

/* Every polygon primitive in GL_3D_COLOR and GL_2D: the triangles the
 * oracle decomposes them into. */
static void feedback_polygons(fc_h *h)
{
    fc_pixel_ortho(h);
    fb_begin(2048, GL_3D_COLOR);
    prim(GL_TRIANGLES, fcu_tri_v, 6, 0, 0);
    prim(GL_TRIANGLE_STRIP, fcu_strip_v, 8, 0, 0);
    prim(GL_TRIANGLE_FAN, fcu_fan_v, 7, 0, 0);
    prim(GL_QUADS, fcu_quads_v, 8, 0, 0);
    prim(GL_QUAD_STRIP, fcu_qstrip_v, 8, 0, 0);
    prim(GL_POLYGON, fcu_poly_v, 6, 0, 0);
    fb_end(h, "3d color", 2048);
    fb_begin(2048, GL_2D);
    prim(GL_QUADS, fcu_quads_v, 7, 0.5f, 0.5f);      /* a trailing vertex */
    prim(GL_TRIANGLES, fcu_tri_v, 5, 0.5f, 0.5f);
    prim(GL_POLYGON, fcu_poly_v, 2, 0, 0);            /* too few */
    prim(GL_QUAD_STRIP, fcu_qstrip_v, 7, 0, 0);
    glRectf(2.0f, 3.0f, 9.5f, 12.25f);
    fb_end(h, "2d", 2048);
}

static void light_setup(void)
{
    static const GLfloat pos[4] = { 0.3f, 0.5f, 1.0f, 0.0f };
    static const GLfloat amb[4] = { 0.1f, 0.05f, 0.2f, 1.0f };
    static const GLfloat dif[4] = { 0.8f, 0.7f, 0.3f, 0.6f };
    static const GLfloat spec[4] = { 0.7f, 0.7f, 0.7f, 1.0f };
    static const GLfloat back[4] = { 0.2f, 0.3f, 0.9f, 0.8f };
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
    glMaterialfv(GL_BACK, GL_DIFFUSE, back);
}

/* Lit colours, two-sided (back faces get the back colours), separate
 * specular (only the primary colour is fed back), lines and points. */
static void feedback_lit(fc_h *h)
{
    glViewport(0, 0, 48, 48);
    fcu_frustum(-1, 1, -1, 1, 2, 10);
    glTranslatef(0.0f, 0.0f, -5.0f);
    glRotatef(40.0f, 1.0f, 0.5f, 0.0f);
    light_setup();
    fb_begin(2048, GL_3D_COLOR);
    cube(1.0f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    cube(0.9f);
    glBegin(GL_LINES);
    glNormal3f(0.0f, 0.0f, -1.0f);
    glVertex3f(-0.5f, 0.0f, 0.0f);
    glNormal3f(0.0f, 0.6f, 0.8f);
    glVertex3f(0.5f, 0.2f, 0.3f);
    glEnd();
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    cube(0.8f);
    glBegin(GL_POINTS);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex3f(0.1f, 0.1f, 0.1f);
    glEnd();
    fb_end(h, "lit", 2048);
}

/* Flat shading: filled triangles keep their per-vertex colours (draw has no
 * flatshade stage then), clipped ones get the provoking colour on P[0] and
 * on the new vertices the colour their temporary vertex slot last held;
 * unfilled ones and, with them, lines are flat-shaded by draw. */
static void feedback_flat(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fb_begin(2048, GL_3D_COLOR);
    prim(GL_TRIANGLE_STRIP, fcu_strip_v, 6, 0, 0);
    prim(GL_QUADS, fcu_quads_v, 4, 0, 0);
    prim(GL_POLYGON, fcu_poly_v, 5, 0, 0);
    prim(GL_LINE_STRIP, fcu_poly_v, 4, 0, 0);
    /* the clipper's temporary vertices start uninitialised (malloc): a
     * smooth clipped triangle fills the slots the flat one then reads */
    glShadeModel(GL_SMOOTH);
    prim(GL_TRIANGLES, fcu_tri_v, 3, -8.5f, 0.5f);
    glShadeModel(GL_FLAT);
    prim(GL_TRIANGLES, fcu_tri_v, 3, -8.0f, 0);       /* clipped at x = 0 */
    prim(GL_QUADS, fcu_quads_v, 4, -6.0f, -1.0f);     /* slots written by flat clips */
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    prim(GL_TRIANGLE_FAN, fcu_fan_v, 5, 0, 0);
    prim(GL_LINES, fcu_poly_v, 4, 0, 0);
    glPolygonMode(GL_FRONT, GL_POINT);
    prim(GL_LINE_LOOP, fcu_poly_v, 3, 0, 0);
    prim(GL_QUAD_STRIP, fcu_qstrip_v, 6, 0, 0);
    fb_end(h, "flat", 2048);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    light_setup();
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    fb_begin(2048, GL_3D_COLOR);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 6; i++) {
        glNormal3f(0.2f * (float)i - 0.5f, 0.3f, 0.8f);
        glVertex3f(fcu_tri_v[i][0], fcu_tri_v[i][1], 0.0f);
    }
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 6; i++) {
        glNormal3f(0.2f * (float)i - 0.5f, 0.3f, 0.8f);
        glVertex3f(fcu_tri_v[5 - i][0], fcu_tri_v[5 - i][1], 0.0f);
    }
    glEnd();
    fb_end(h, "flat lit", 2048);
}

/* Polygon modes: lines (the first of each primitive a reset token) and
 * points of the edges whose edge flags are set; different front and back
 * modes; the reset flag kept by the stage until the next line. */
static void feedback_polygon_mode(fc_h *h)
{
    fc_pixel_ortho(h);
    fb_begin(2048, GL_2D);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    prim(GL_TRIANGLES, fcu_tri_v, 6, 0, 0);
    prim(GL_QUADS, fcu_quads_v, 8, 0, 0);
    prim(GL_QUAD_STRIP, fcu_qstrip_v, 6, 0, 0);
    prim(GL_POLYGON, fcu_poly_v, 6, 0, 0);
    prim(GL_TRIANGLE_STRIP, fcu_strip_v, 5, 0, 0);
    glBegin(GL_POLYGON);
    glEdgeFlag(GL_FALSE);
    glVertex2f(2, 2);
    glEdgeFlag(GL_TRUE);
    glVertex2f(20, 2);
    glEdgeFlag(GL_FALSE);
    glVertex2f(25, 15);
    glVertex2f(12, 25);
    glEdgeFlag(GL_TRUE);
    glVertex2f(3, 14);
    glEnd();
    fb_end(h, "line", 2048);

    fb_begin(2048, GL_3D);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    prim(GL_QUADS, fcu_quads_v, 4, 0, 0);
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_FALSE);
    glVertex2f(2, 2);
    glEdgeFlag(GL_TRUE);
    glVertex2f(20, 2);
    glVertex2f(12, 25);
    glEnd();
    glPolygonMode(GL_FRONT, GL_FILL);
    glPolygonMode(GL_BACK, GL_LINE);
    fcu_tri(2, 2, 20, 2, 12, 25);             /* front: filled */
    fcu_tri(2, 2, 12, 25, 20, 2);             /* back: lines */
    glPolygonMode(GL_FRONT, GL_POINT);
    fcu_tri(2, 2, 20, 2, 12, 25);
    fb_end(h, "point", 2048);

    /* a polygon whose edges are all hidden sets the reset flag without a
     * line; the next line, even of GL_LINES, is the reset token */
    fb_begin(2048, GL_2D);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_FALSE);
    glVertex2f(2, 2);
    glVertex2f(20, 2);
    glVertex2f(12, 25);
    glEnd();
    glEdgeFlag(GL_TRUE);
    glBegin(GL_LINES);
    glVertex2f(1, 1);
    glVertex2f(9, 9);
    glVertex2f(1, 9);
    glVertex2f(9, 1);
    glEnd();
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_FALSE);
    glVertex2f(2, 2);
    glVertex2f(20, 2);
    glVertex2f(12, 25);
    glEnd();
    glEdgeFlag(GL_TRUE);
    fb_end(h, "hidden", 64);
    /* the flag survives glRenderMode */
    fb_begin(2048, GL_2D);
    glBegin(GL_LINES);
    glVertex2f(1, 1);
    glVertex2f(9, 9);
    glEnd();
    fb_end(h, "after switch", 64);
}

/* Culling in feedback and selection, with unfilled modes and the current
 * edge flag (false culls the unfilled faces). */
static void feedback_cull(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_CULL_FACE);
    fb_begin(2048, GL_2D);
    for (int c = 0; c < 3; c++) {
        static const GLenum faces[3] = { GL_BACK, GL_FRONT, GL_FRONT_AND_BACK };
        glCullFace(faces[c]);
        fcu_tri(2, 2, 20, 2, 12, 25);
        fcu_tri(2, 2, 12, 25, 20, 2);
        glPassThrough((GLfloat)c);
    }
    glCullFace(GL_BACK);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    fcu_tri(2, 2, 20, 2, 12, 25);
    fcu_tri(2, 2, 12, 25, 20, 2);
    glPassThrough(10.0f);
    glEdgeFlag(GL_FALSE);
    glDisable(GL_CULL_FACE);
    fcu_tri(2, 2, 20, 2, 12, 25);
    glPassThrough(11.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    fcu_tri(2, 2, 20, 2, 12, 25);
    glEdgeFlag(GL_TRUE);
    fb_end(h, "cull", 2048);
}

/* Clipping: new vertices of triangles, quads and lines clipped by the
 * view volume (with perspective: near and far) and user planes; points
 * outside dropped. */
static void feedback_clip(fc_h *h)
{
    glViewport(0, 0, 40, 30);
    fcu_frustum(-1, 1, -0.75, 0.75, 1, 6);
    fb_begin(2048, GL_4D_COLOR_TEXTURE);
    glBegin(GL_TRIANGLES);
    color_i(0);
    glVertex3f(-0.5f, -0.5f, -0.5f);
    color_i(1);
    glVertex3f(2.5f, -0.5f, -3.0f);
    color_i(2);
    glVertex3f(0.0f, 0.5f, -8.0f);
    glEnd();
    glBegin(GL_QUADS);
    color_i(3);
    glVertex3f(-3.0f, -3.0f, -2.0f);
    color_i(4);
    glVertex3f(3.0f, -3.0f, -2.0f);
    color_i(5);
    glVertex3f(3.0f, 3.0f, -2.0f);
    color_i(6);
    glVertex3f(-3.0f, 3.0f, -2.0f);
    glEnd();
    glBegin(GL_LINES);
    color_i(7);
    glVertex3f(-2.0f, 0.1f, -0.5f);
    color_i(8);
    glVertex3f(1.0f, -0.2f, -9.0f);
    glEnd();
    glBegin(GL_POINTS);
    glVertex3f(0.0f, 0.0f, -0.5f);
    glVertex3f(0.2f, 0.1f, -2.0f);
    glVertex3f(9.0f, 0.1f, -2.0f);
    glEnd();
    fb_end(h, "frustum", 2048);

    static const GLdouble plane0[4] = { 1.0, 0.5, 0.0, 0.2 };
    static const GLdouble plane1[4] = { -0.3, 1.0, 0.1, 0.4 };
    glClipPlane(GL_CLIP_PLANE0, plane0);
    glClipPlane(GL_CLIP_PLANE1, plane1);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE1);
    glTranslatef(0.0f, 0.0f, -3.0f);
    fb_begin(2048, GL_3D_COLOR);
    static const float poly[6][2] = { { -1, -1 }, { 1, -1.2f }, { 1.3f, 0.4f },
                                      { 0, 1 }, { -1.1f, 0.5f }, { -1.2f, 0 } };
    static const float tri[3][2] = { { -1, -1 }, { 1, -1 }, { 0, 1 } };
    prim(GL_POLYGON, poly, 6, 0, 0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    prim(GL_TRIANGLES, tri, 3, 0, 0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glShadeModel(GL_FLAT);
    prim(GL_LINE_LOOP, tri, 3, 0, 0);
    prim(GL_TRIANGLES, tri, 3, 0, 0);
    fb_end(h, "user planes", 2048);
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_CLIP_PLANE1);
}

/* glPassThrough: tokens among primitives, ignored outside GL_FEEDBACK;
 * glInitNames and friends ignored in feedback. */
static void feedback_passthrough(fc_h *h)
{
    fc_pixel_ortho(h);
    glPassThrough(1.0f);
    fc_error(h, "outside");
    fb_begin(64, GL_2D);
    glPassThrough(2.5f);
    fcu_tri(2, 2, 20, 2, 12, 25);
    glPassThrough(-7.0f);
    glInitNames();
    glPushName(3);
    glLoadName(4);
    glPopName();
    glPopName();
    fc_error(h, "names in feedback");
    glBegin(GL_POINTS);
    glVertex2f(3, 3);
    glPassThrough(9.0f);
    fc_error(h, "in begin");
    glVertex2f(4, 4);
    glEnd();
    glPassThrough(1e30f);
    fb_end(h, "pass", 64);
    sel_begin(16);
    glPassThrough(5.0f);
    fc_error(h, "in select");
    sel_end(h, "select", 8);
}

/* Small feedback buffers: values up to the size written, -1 returned. */
static void feedback_overflow(fc_h *h)
{
    fc_pixel_ortho(h);
    static const int sizes[] = { 1, 2, 7, 8, 9, 16, 17, 24 };
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        char l[32];
        fb_begin(sizes[i], GL_3D);
        fcu_tri(2, 2, 20, 2, 12, 25);
        glPassThrough(3.0f);
        glBegin(GL_POINTS);
        glVertex2f(5, 5);
        glEnd();
        snprintf(l, sizeof l, "size %d", sizes[i]);
        fb_end(h, l, 32);
    }
    fb_begin(4, GL_2D);
    glPassThrough(1.0f);
    glPassThrough(2.0f);
    fb_end(h, "exact", 8);
    fb_begin(4, GL_2D);
    glPassThrough(1.0f);
    glPassThrough(2.0f);
    glPassThrough(3.0f);
    fb_end(h, "one over", 8);
}

/* Errors and state of feedback. */
static void feedback_errors(fc_h *h)
{
    fc_get_integer(h, "size", GL_FEEDBACK_BUFFER_SIZE, 1);
    fc_get_integer(h, "type", GL_FEEDBACK_BUFFER_TYPE, 1);
    GLvoid *p = (GLvoid *)1;
    glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &p);
    fc_value(h, "initial pointer null", p == NULL);
    fc_value(h, "feedback without buffer", glRenderMode(GL_FEEDBACK));
    fc_error(h, "feedback without buffer");
    fc_get_integer(h, "mode", GL_RENDER_MODE, 1);
    glFeedbackBuffer(8, GL_2D, fbbuf);
    fc_error(h, "buffer in feedback");
    fc_pixel_ortho(h);
    fcu_tri(2, 2, 20, 2, 12, 25);
    glPassThrough(1.0f);
    fc_value(h, "leave", glRenderMode(GL_RENDER));

    glFeedbackBuffer(-1, GL_2D, fbbuf);
    fc_error(h, "negative");
    glFeedbackBuffer(8, GL_4D_COLOR_TEXTURE, fbbuf);
    glFeedbackBuffer(8, GL_RGBA, fbbuf);
    fc_error(h, "bad type");
    fc_get_integer(h, "type after bad", GL_FEEDBACK_BUFFER_TYPE, 1);
    fc_get_integer(h, "size 8", GL_FEEDBACK_BUFFER_SIZE, 1);
    glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &p);
    fc_value(h, "pointer", p == (GLvoid *)fbbuf);
    glFeedbackBuffer(5, GL_3D, NULL);
    fc_error(h, "null buffer");
    fc_get_integer(h, "size after null", GL_FEEDBACK_BUFFER_SIZE, 1);
    fc_get_integer(h, "type after null", GL_FEEDBACK_BUFFER_TYPE, 1);
    fc_value(h, "feedback size 0", glRenderMode(GL_FEEDBACK));
    fc_error(h, "feedback size 0");
    fcu_tri(2, 2, 20, 2, 12, 25);
    fc_value(h, "leave size 0", glRenderMode(GL_RENDER));
    glFeedbackBuffer(0, GL_3D, NULL);
    fc_error(h, "size 0 null");
    glFeedbackBuffer(16, GL_3D_COLOR, fbbuf);
    glBegin(GL_TRIANGLES);
    glFeedbackBuffer(16, GL_3D, fbbuf);
    fc_error(h, "in begin");
    glEnd();
    fc_get_integer(h, "type end", GL_FEEDBACK_BUFFER_TYPE, 1);
    fc_value(h, "bad mode from render", glRenderMode(GL_FEEDBACK + 1));
    fc_error(h, "bad mode");
    fb_begin(16, GL_2D);
    glPassThrough(4.0f);
    fc_value(h, "bad mode in feedback", glRenderMode(0));
    fc_error(h, "bad mode in feedback");
    fc_get_integer(h, "mode kept", GL_RENDER_MODE, 1);
    glPassThrough(5.0f);
    fb_end(h, "after bad", 8);
}

/* Polygon offset in feedback: draw's own context has no depth format, so
 * only the factor moves z (and z is saturated). */
static void feedback_offset(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 50.0f);
    fb_begin(2048, GL_3D);
    glBegin(GL_TRIANGLES);
    glVertex3f(2, 2, 0.5f);
    glVertex3f(20, 2, -0.5f);
    glVertex3f(12, 25, 0.9f);
    glVertex3f(2, 2, 0.0f);
    glVertex3f(20, 2, 0.0f);
    glVertex3f(12, 25, 0.0f);
    glEnd();
    glPolygonOffset(-100.0f, -3.0f);
    fcu_tri(2, 2, 20, 2, 12, 25);
    glBegin(GL_TRIANGLES);
    glVertex3f(2, 2, 0.99f);
    glVertex3f(20, 2, -0.5f);
    glVertex3f(12, 25, -0.99f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    fcu_tri(2, 2, 20, 2, 12, 25);              /* offset line is off */
    glEnable(GL_POLYGON_OFFSET_LINE);
    glBegin(GL_TRIANGLES);
    glVertex3f(2, 2, 0.5f);
    glVertex3f(20, 2, -0.5f);
    glVertex3f(12, 25, 0.9f);
    glEnd();
    fb_end(h, "offset", 2048);
}

/* Switching modes back and forth with drawing in between, glRenderMode's
 * return values, and the picture drawn in GL_RENDER unaffected. */
static void mode_switch(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.1f, 0.1f, 1.0f, 1.0);
    glSelectBuffer(64, selbuf);
    glFeedbackBuffer(256, GL_3D_COLOR, fbbuf);
    fc_value(h, "render->render", glRenderMode(GL_RENDER));
    fc_value(h, "render->select", glRenderMode(GL_SELECT));
    glPushName(1);
    fcu_color(1);
    fcu_rect(2, 2, 14, 14, 0.0f);
    fc_value(h, "select->feedback", glRenderMode(GL_FEEDBACK));
    fcu_color(2);
    fcu_tri(2, 2, 20, 2, 12, 25);
    fc_value(h, "feedback->select", glRenderMode(GL_SELECT));
    fc_get_integer(h, "depth", GL_NAME_STACK_DEPTH, 1);
    glPushName(2);
    fcu_rect(4, 4, 8, 8, 0.5f);
    glEnable(GL_DEPTH_TEST);
    fc_value(h, "select->render", glRenderMode(GL_RENDER));
    fcu_color(3);
    fcu_rect(1, 1, 30, 30, 0.2f);
    fc_value(h, "render->feedback", glRenderMode(GL_FEEDBACK));
    fcu_color(4);
    fcu_rect(5, 5, 25, 25, -0.2f);
    fc_value(h, "feedback->feedback", glRenderMode(GL_FEEDBACK));
    fc_value(h, "feedback->render", glRenderMode(GL_RENDER));
    /* the other mode's buffer may change while in a mode; select->select
     * finishes the old selection */
    fc_value(h, "render->select 2", glRenderMode(GL_SELECT));
    glFeedbackBuffer(128, GL_2D, fbbuf + 128);
    fc_error(h, "feedback buffer in select");
    glPushName(5);
    fcu_rect(4, 4, 8, 8, -0.25f);
    fc_value(h, "select->select", glRenderMode(GL_SELECT));
    fc_get_integer(h, "depth after select->select", GL_NAME_STACK_DEPTH, 1);
    glPushName(6);
    fcu_rect(4, 4, 8, 8, 0.75f);
    fc_value(h, "select->feedback 2", glRenderMode(GL_FEEDBACK));
    glSelectBuffer(32, selbuf + 32);
    fc_error(h, "select buffer in feedback");
    fcu_rect(4, 4, 8, 8, 0.75f);
    fc_value(h, "feedback->select 2", glRenderMode(GL_SELECT));
    glPushName(7);
    fcu_rect(4, 4, 8, 8, 0.5f);
    fc_value(h, "select->render 2", glRenderMode(GL_RENDER));
    fc_blob(h, "select buffer 2", selbuf + 32, 16 * sizeof(GLuint));
    fc_blob(h, "feedback buffer 2", fbbuf + 128, 32 * sizeof(GLfloat));
    fcu_color(5);
    fcu_tri(2, 2, 30, 2, 16, 30);
    fc_blob(h, "select buffer", selbuf, 16 * sizeof(GLuint));
    fc_blob(h, "feedback buffer", fbbuf, 64 * sizeof(GLfloat));
    fc_capture(h);
}

/* Vertex arrays in feedback: glDrawArrays quads and glDrawElements. */
static void feedback_arrays(fc_h *h)
{
    fc_pixel_ortho(h);
    static const GLfloat v[8][3] = { { 2, 2, 0 }, { 12, 3, 0.2f }, { 13, 14, 0.4f }, { 1, 12, -0.1f },
                                     { 16, 2, 0 }, { 28, 4, 0.3f }, { 27, 20, 0.5f }, { 15, 18, -0.2f } };
    static const GLubyte c[8][4] = { { 255, 0, 0, 255 }, { 0, 255, 0, 255 }, { 0, 0, 255, 255 },
                                     { 255, 255, 0, 128 }, { 0, 255, 255, 255 }, { 255, 0, 255, 255 },
                                     { 128, 128, 128, 255 }, { 10, 20, 30, 40 } };
    static const GLushort idx[6] = { 0, 1, 2, 4, 5, 6 };
    glVertexPointer(3, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    fb_begin(2048, GL_3D_COLOR);
    glDrawArrays(GL_QUADS, 0, 8);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, idx);
    glDrawArrays(GL_LINE_LOOP, 2, 5);
    fb_end(h, "arrays", 2048);
    sel_begin(64);
    glPushName(1);
    glDrawArrays(GL_QUADS, 0, 4);
    glLoadName(2);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, idx + 3);
    sel_end(h, "arrays select", 32);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
}

/* Long primitives: a polygon and a triangle fan of 5000 vertices are cut
 * into the draw module's fan segments, whose first triangles restart the
 * stipple (reset tokens in GL_LINE mode); a 5000-vertex line strip. */
static GLfloat bigbuf[60000];

static void feedback_long(fc_h *h)
{
    fc_pixel_ortho(h);
    const int n = 5000;
    for (int pass = 0; pass < 3; pass++) {
        char l[32];
        for (size_t i = 0; i < sizeof bigbuf / sizeof bigbuf[0]; i++)
            bigbuf[i] = FB_MARK;
        glFeedbackBuffer((GLsizei)(sizeof bigbuf / sizeof bigbuf[0]), GL_2D, bigbuf);
        glRenderMode(GL_FEEDBACK);
        glPolygonMode(GL_FRONT_AND_BACK, pass == 2 ? GL_FILL : GL_LINE);
        glBegin(pass == 0 ? GL_POLYGON : pass == 1 ? GL_TRIANGLE_FAN : GL_LINE_STRIP);
        for (int i = 0; i < n; i++) {
            const float a = 6.2831853f * (float)i / (float)n;
            glVertex2f(16.0f + 14.0f * cosf(a), 16.0f + 14.0f * sinf(a));
        }
        glEnd();
        const GLint cnt = glRenderMode(GL_RENDER);
        snprintf(l, sizeof l, "long %d count", pass);
        fc_value(h, l, cnt);
        snprintf(l, sizeof l, "long %d buffer", pass);
        fc_blob(h, l, bigbuf, sizeof bigbuf);
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    sel_begin(64);
    glPushName(1);
    glBegin(GL_POLYGON);
    for (int i = 0; i < n; i++) {
        const float a = 6.2831853f * (float)i / (float)n;
        glVertex3f(16.0f + 14.0f * cosf(a), 16.0f + 14.0f * sinf(a), 0.9f * sinf(3.0f * a));
    }
    glEnd();
    sel_end(h, "long select", 16);
}

/* Vertices at infinity and NaN: no crash, the oracle's values. */
static void feedback_nonfinite(fc_h *h)
{
    fc_pixel_ortho(h);
    const float inf = 1.0f / 0.0f, nan = 0.0f / 0.0f;
    fb_begin(512, GL_4D_COLOR_TEXTURE);
    glBegin(GL_POINTS);
    glVertex3f(5.0f, 5.0f, nan);
    glVertex3f(inf, 5.0f, 0.0f);
    glVertex4f(5.0f, 5.0f, 0.0f, 0.0f);
    glEnd();
    glBegin(GL_LINES);
    glVertex3f(2.0f, 2.0f, 0.0f);
    glVertex3f(nan, 20.0f, 0.0f);
    glEnd();
    glBegin(GL_TRIANGLES);
    glVertex3f(2.0f, 2.0f, 0.0f);
    glVertex3f(20.0f, 2.0f, inf);
    glVertex3f(12.0f, 25.0f, 0.0f);
    glVertex3f(2.0f, 2.0f, 0.0f);
    glVertex3f(20.0f, 2.0f, nan);
    glVertex3f(12.0f, 25.0f, 0.0f);
    glEnd();
    fb_end(h, "nonfinite", 512);
    sel_begin(64);
    glPushName(1);
    glBegin(GL_POINTS);
    glVertex3f(5.0f, 5.0f, nan);
    glEnd();
    glLoadName(2);
    glBegin(GL_TRIANGLES);
    glVertex3f(2.0f, 2.0f, 0.0f);
    glVertex3f(20.0f, 2.0f, nan);
    glVertex3f(12.0f, 25.0f, 0.5f);
    glEnd();
    sel_end(h, "nonfinite select", 16);

    /* the same in GL_RENDER: a NaN clip coordinate is outside (unordered
     * clip test), so the point is dropped and the triangle discarded */
    fcu_clear(0.0f, 0.0f, 0.0f, 1.0f, 1.0);
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex3f(5.0f, 5.0f, nan);
    glVertex3f(nan, 25.0f, 0.0f);
    glVertex3f(25.0f, 25.0f, 0.0f);
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor3f(0.0f, 1.0f, 1.0f);
    glVertex3f(2.0f, 2.0f, 0.0f);
    glVertex3f(20.0f, 2.0f, nan);
    glVertex3f(12.0f, 25.0f, 0.0f);
    glEnd();
    glBegin(GL_LINES);
    glVertex3f(2.0f, 30.0f, 0.0f);
    glVertex3f(30.0f, nan, 0.0f);
    glEnd();
    fc_capture(h);
}

/* Rasterization-only state in feedback: polygon stipple, smooth polygons,
 * depth test, scissor, blending do not change what is fed back; two-sided
 * lighting with unfilled faces gives the back colours to the edges. */
static void feedback_raster_state(fc_h *h)
{
    fc_pixel_ortho(h);
    static GLubyte stip[128];
    for (int i = 0; i < 128; i++)
        stip[i] = (GLubyte)(i * 37 + 5);
    glPolygonStipple(stip);
    glEnable(GL_POLYGON_STIPPLE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST);
    glScissor(4, 4, 3, 3);
    glEnable(GL_BLEND);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_NEVER, 0.0f);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, -1.0f);
    glFogf(GL_FOG_END, 0.5f);
    fb_begin(2048, GL_3D_COLOR);
    prim(GL_TRIANGLES, fcu_tri_v, 6, 0, 0);
    prim(GL_QUADS, fcu_quads_v, 4, 0, 0);
    glDisable(GL_POLYGON_STIPPLE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_ALPHA_TEST);
    light_setup();
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glBegin(GL_QUADS);
    glNormal3f(0.1f, 0.2f, 1.0f);
    glVertex2f(2, 2);
    glVertex2f(14, 3);
    glVertex2f(13, 15);
    glVertex2f(3, 12);
    glNormal3f(-0.3f, 0.2f, 0.9f);
    glVertex2f(16, 16);
    glVertex2f(17, 29);
    glVertex2f(29, 28);
    glVertex2f(28, 17);
    glEnd();
    fb_end(h, "raster state", 2048);
}

/* A deterministic mix of states and primitives (splitmix-style generator
 * local to the case), fed back and selected scene by scene: shade model,
 * polygon modes, culling, front face, offset, user planes, per-vertex edge
 * flags, depth range, line/point/stipple state that only rasterization
 * uses, a perspective view that the primitives cross at the near and far
 * planes.  Lighting
 * (lit) stays fixed within a case: the clipper's stale flat slots follow
 * the vertex program's output layout (ORACLE-NOTES.md). */
static uint64_t rng_state;

static uint32_t rnd(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return (uint32_t)((z ^ (z >> 31)) >> 32);
}

static float rndf(float lo, float hi)
{
    return lo + (hi - lo) * (float)(rnd() & 0xffffff) / 16777216.0f;
}

/* Fill the clipper's temporary slots (uninitialised at first) with a big
 * smooth polygon clipped by every plane. */
static void prime_clip_slots(void)
{
    glShadeModel(GL_SMOOTH);
    glBegin(GL_POLYGON);
    for (int i = 0; i < 12; i++) {
        const float a = 6.2831853f * (float)i / 12.0f;
        color_i(i);
        glNormal3f(cosf(a), sinf(a), 1.0f);
        glVertex3f(9.0f * cosf(a), 9.0f * sinf(a), -3.0f + 8.0f * sinf(2.0f * a));
    }
    glEnd();
}

static void stress(fc_h *h, bool lit)
{
    static const GLenum modes[] = { GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP,
                                    GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                    GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    static const GLenum fills[] = { GL_FILL, GL_LINE, GL_POINT };
    rng_state = lit ? 77 : 11;
    glViewport(0, 0, 48, 40);
    fcu_frustum(-1, 1, -0.8, 0.8, 1, 6);
    if (lit) {
        light_setup();
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        glEnable(GL_COLOR_MATERIAL);
    }
    for (int scene = 0; scene < 40; scene++) {
        char l[32];
        const bool select = scene & 1;
        if (select)
            sel_begin(512);
        else
            fb_begin(2048, GL_4D_COLOR_TEXTURE);
        prime_clip_slots();
        glShadeModel(rnd() % 2 ? GL_FLAT : GL_SMOOTH);
        glPolygonMode(GL_FRONT, fills[rnd() % 3]);
        glPolygonMode(GL_BACK, fills[rnd() % 3]);
        glFrontFace(rnd() % 2 ? GL_CW : GL_CCW);
        if (rnd() % 3 == 0) {
            glEnable(GL_CULL_FACE);
            glCullFace(rnd() % 2 ? GL_FRONT : GL_BACK);
        } else {
            glDisable(GL_CULL_FACE);
        }
        if (rnd() % 3 == 0) {
            glEnable(GL_POLYGON_OFFSET_FILL);
            glEnable(GL_POLYGON_OFFSET_LINE);
            glPolygonOffset(rndf(-3.0f, 3.0f), rndf(-50.0f, 50.0f));
        } else {
            glDisable(GL_POLYGON_OFFSET_FILL);
            glDisable(GL_POLYGON_OFFSET_LINE);
        }
        if (rnd() % 3 == 0) {
            const GLdouble plane[4] = { rndf(-1, 1), rndf(-1, 1), rndf(-0.3f, 0.3f), rndf(0, 2) };
            glClipPlane(GL_CLIP_PLANE0, plane);
            glEnable(GL_CLIP_PLANE0);
        } else {
            glDisable(GL_CLIP_PLANE0);
        }
        /* rasterization-only state, and the depth range */
        if (rnd() % 2)
            glEnable(GL_LINE_STIPPLE);
        else
            glDisable(GL_LINE_STIPPLE);
        glLineStipple((GLint)(1 + rnd() % 3), (GLushort)rnd());
        glDepthRange(rndf(0, 1), rndf(0, 1));
        glLineWidth(rndf(0.5f, 4.0f));
        glPointSize(rndf(0.5f, 4.0f));
        if (rnd() % 2)
            glEnable(GL_LINE_SMOOTH);
        else
            glDisable(GL_LINE_SMOOTH);
        if (rnd() % 3 == 0)
            glEnable(GL_POLYGON_STIPPLE);
        else
            glDisable(GL_POLYGON_STIPPLE);
        if (rnd() % 3 == 0)
            glEnable(GL_POLYGON_OFFSET_POINT);
        else
            glDisable(GL_POLYGON_OFFSET_POINT);
        glPushMatrix();
        glTranslatef(rndf(-0.5f, 0.5f), rndf(-0.5f, 0.5f), rndf(-4.0f, -1.5f));
        glRotatef(rndf(0.0f, 360.0f), rndf(-1, 1), rndf(-1, 1), 1.0f);
        glPushName(100);
        for (int p = 0; p < 4; p++) {
            const GLenum mode = modes[rnd() % 10];
            const int n = 1 + (int)(rnd() % 9);
            glLoadName((GLuint)(scene * 10 + p));
            glBegin(mode);
            for (int i = 0; i < n; i++) {
                glColor4f(rndf(0, 1), rndf(0, 1), rndf(0, 1), rndf(0, 1));
                if (scene % 4 == 2)
                    glEdgeFlag(rnd() % 2 ? GL_TRUE : GL_FALSE);
                glNormal3f(rndf(-1, 1), rndf(-1, 1), rndf(-1, 1));
                glVertex3f(rndf(-2.0f, 2.0f), rndf(-2.0f, 2.0f), rndf(-3.5f, 3.0f));
            }
            glEnd();
        }
        glPopMatrix();
        snprintf(l, sizeof l, "scene %d", scene);
        if (select)
            sel_end(h, l, 512);
        else
            fb_end(h, l, 2048);
    }
}

/* The clipper's stale flat slots across a change of the vertex program's
 * outputs: lit two-sided and then unlit smooth clips fill them (the unlit
 * vertex, position, colour and texture coordinate, leaves the back colour
 * behind it as it was), then lit two-sided flat clips of back faces read
 * them (the back colour becomes the fed-back colour), then unlit ones. */
static void stale_layout(fc_h *h)
{
    static const GLfloat behind[4] = { 0.3f, 0.5f, -1.0f, 0.0f };
    glViewport(0, 0, 32, 32);
    fcu_frustum(-1, 1, -1, 1, 1, 6);
    glTranslatef(0.0f, 0.0f, -2.0f);
    fb_begin(2048, GL_3D_COLOR);
    light_setup();
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glFrontFace(GL_CW);
    glLightfv(GL_LIGHT0, GL_POSITION, behind);   /* varied back colours */
    prime_clip_slots();                   /* back colours into the slots */
    glFrontFace(GL_CCW);
    glDisable(GL_LIGHTING);
    prime_clip_slots();                   /* the unlit outputs over them */
    glEnable(GL_LIGHTING);
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLES);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex3f(-3.0f, -0.5f, 0.0f);
    glVertex3f(0.0f, 2.5f, 0.0f);
    glVertex3f(3.0f, -0.5f, 0.0f);
    glEnd();
    glDisable(GL_LIGHTING);
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.4f, 0.6f);
    glVertex3f(-3.0f, -0.5f, 0.0f);
    glVertex3f(3.0f, -0.5f, 0.0f);
    glVertex3f(0.0f, 2.5f, 0.0f);
    glEnd();
    fb_end(h, "stale", 2048);

    /* lit two-sided clips in GL_SELECT (whose vertex has no texture
     * coordinate, so its back colour sits where feedback's texture
     * coordinate does) leave feedback's back colours in place */
    glEnable(GL_LIGHTING);
    fb_begin(2048, GL_3D_COLOR);
    glFrontFace(GL_CW);
    prime_clip_slots();
    fb_end(h, "lit prime", 4);
    sel_begin(64);
    glFrontFace(GL_CCW);
    glLightfv(GL_LIGHT0, GL_POSITION, behind);
    glPushName(1);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    prime_clip_slots();
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLES);
    glNormal3f(0.0f, 0.3f, 1.0f);
    glVertex3f(-3.0f, -0.5f, 0.0f);
    glVertex3f(0.0f, 2.5f, 0.0f);
    glVertex3f(3.0f, -0.5f, 0.0f);
    glEnd();
    sel_end(h, "lit select", 8);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -2.0f);
    fb_begin(2048, GL_3D_COLOR);
    glBegin(GL_TRIANGLES);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex3f(-3.0f, -0.5f, 0.0f);
    glVertex3f(0.0f, 2.5f, 0.0f);
    glVertex3f(3.0f, -0.5f, 0.0f);
    glEnd();
    fb_end(h, "after select", 2048);
}

static void stress_unlit(fc_h *h) { stress(h, false); }
static void stress_lit(fc_h *h) { stress(h, true); }

/* An empty GL_LINE_LOOP in a display list: Mesa's list compiler closes the
 * loop with a copy of its first vertex, of which there is none, so the
 * replay draws a one-vertex line strip whose position is the current
 * value of attribute 0, (0, 0, 0, 1): a hit at the middle of the depth
 * range, under GL_SELECT and GL_FEEDBACK (fuzzer seed 76). */
static void dlist_empty_line_loop(fc_h *h)
{
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_LINE_LOOP);
    glNormal3b(1, 2, 3);
    glEnd();
    glEndList();
    glDepthRange(0.2, 0.9);
    sel_begin(64);
    glCallList(list);
    sel_end(h, "select", 8);
    glDepthRange(0.0, 1.0);
    sel_begin(64);
    glCallList(list);
    sel_end(h, "select_full_range", 8);
    fb_begin(64, GL_3D_COLOR);
    glCallList(list);
    fb_end(h, "feedback", 16);
    fc_error(h, "empty_line_loop");
    glDeleteLists(list, 1);
}

const fc_case fc_cases_select[] = {
    FC_CASE_RGBA("select/picking", 64, 48, 0, "api select", picking),
    FC_CASE_RGBA("select/hit_depths", 32, 32, 0, "api select clip", hit_depths),
    FC_CASE_RGBA("select/hit_flush", 32, 32, 0, "api select", hit_flush),
    FC_CASE_RGBA("select/overflow", 32, 32, 0, "api select", select_overflow),
    FC_CASE_RGBA("select/name_stack", 32, 32, 0, "api select errors query", name_stack),
    FC_CASE_RGBA("select/errors", 32, 32, 0, "api select errors query", select_errors),
    FC_CASE_RGBA("feedback/types", 56, 48, 0, "api feedback", feedback_types),
    FC_CASE_RGBA("feedback/points_lines", 32, 32, 0, "api feedback", feedback_points_lines),
    FC_CASE_RGBA("feedback/polygons", 32, 32, 0, "api feedback", feedback_polygons),
    FC_CASE_RGBA("feedback/lit", 48, 48, 0, "api feedback lighting", feedback_lit),
    FC_CASE_RGBA("feedback/flat", 32, 32, 0, "api feedback", feedback_flat),
    FC_CASE_RGBA("feedback/polygon_mode", 32, 32, 0, "api feedback polygon", feedback_polygon_mode),
    FC_CASE_RGBA("feedback/cull", 32, 32, 0, "api feedback polygon", feedback_cull),
    FC_CASE_RGBA("feedback/clip", 40, 30, 0, "api feedback clip", feedback_clip),
    FC_CASE_RGBA("feedback/passthrough", 32, 32, 0, "api feedback", feedback_passthrough),
    FC_CASE_RGBA("feedback/overflow", 32, 32, 0, "api feedback", feedback_overflow),
    FC_CASE_RGBA("feedback/errors", 32, 32, 0, "api feedback errors query", feedback_errors),
    FC_CASE_RGBA("feedback/offset", 32, 32, 0, "api feedback polygon", feedback_offset),
    FC_CASE_RGBA("select/mode_switch", 32, 32, 1, "api select feedback", mode_switch),
    FC_CASE_RGBA("feedback/arrays", 32, 32, 0, "api feedback varray", feedback_arrays),
    FC_CASE_RGBA("feedback/long_primitives", 32, 32, 0, "api feedback select", feedback_long),
    FC_CASE_RGBA("feedback/nonfinite", 32, 32, 1, "api feedback select", feedback_nonfinite),
    FC_CASE_RGBA("feedback/raster_state", 32, 32, 0, "api feedback lighting", feedback_raster_state),
    FC_CASE_RGBA("feedback/stale_layout", 32, 32, 0, "api feedback clip lighting", stale_layout),
    FC_CASE_RGBA("feedback/stress_unlit", 48, 40, 0, "api feedback select clip polygon", stress_unlit),
    FC_CASE_RGBA("feedback/stress_lit", 48, 40, 0, "api feedback select clip polygon lighting", stress_lit),
    FC_CASE_RGBA("select/dlist_empty_line_loop", 16, 16, 0, "api select feedback dlist", dlist_empty_line_loop),
    { 0 }
};
