/* c_dlist.c - display lists: GL_COMPILE and GL_COMPILE_AND_EXECUTE,
 * nested calls (and nesting beyond Mesa's 64 levels), lists holding
 * matrix, light, material, colour-material and shade-model changes, lists
 * deleted and redefined, glCallLists with every type and glListBase,
 * glGenLists ranges and glIsList, every primitive type compiled into a list
 * (Mesa's vertex-list compiler merges primitives, turns them into indexed
 * draws and splits quads 1-3), arrays read at compile time, commands
 * executed at once during compilation, the current values a list leaves,
 * errors at compile and at execution time, and the list queries. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

static void smooth_quad(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0);
    glVertex2f(x0, y0);
    glColor3f(0, 1, 0);
    glVertex2f(x1, y0);
    glColor3f(0, 0, 1);
    glVertex2f(x1, y1);
    glColor3f(1, 1, 1);
    glVertex2f(x0, y1);
    glEnd();
}

/* ---- basic compile and call ---- */

static void basic(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint l = glGenLists(1);
    fc_value(h, "genlists", l);
    glNewList(l, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex2f(2, 2);
    glColor3f(0, 1, 0);
    glVertex2f(30, 4);
    glColor3f(0, 0, 1);
    glVertex2f(10, 29);
    glEnd();
    glEndList();
    fc_error(h, "compile");
    fc_capture(h);   /* nothing drawn by GL_COMPILE */
    glCallList(l);
    fc_capture(h);
    glTranslatef(24, 20, 0);
    glCallList(l);
    fc_capture(h);
    fc_get_float(h, "current color after list", GL_CURRENT_COLOR, 4);
}

/* a smooth quad compiled is an indexed draw: llvmpipe splits it 1-3, where
 * immediate mode splits it 0-2 */
static void quad_diagonal(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    smooth_quad(2, 2, 30, 30);
    glEndList();
    smooth_quad(34, 2, 62, 30);
    glCallList(1);
    fc_capture(h);
    /* compile and execute draws through immediate mode */
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glTranslatef(0, 32, 0);
    smooth_quad(2, 2, 30, 30);
    glEndList();
    glCallList(2);   /* one more translate, then the quad indexed */
    fc_capture(h);
}

static void compile_and_execute(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(5, GL_COMPILE_AND_EXECUTE);
    glColor3f(1, 0.5f, 0.25f);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(2, 2);
    glVertex2f(20, 3);
    glVertex2f(4, 20);
    glColor3f(0.1f, 0.9f, 0.3f);
    glVertex2f(22, 24);
    glEnd();
    fc_get_integer(h, "list index inside", GL_LIST_INDEX, 1);
    fc_get_integer(h, "list mode inside", GL_LIST_MODE, 1);
    glEndList();
    fc_get_integer(h, "list index after", GL_LIST_INDEX, 1);
    fc_get_integer(h, "list mode after", GL_LIST_MODE, 1);
    fc_get_float(h, "current color", GL_CURRENT_COLOR, 4);
    fc_capture(h);
    glColor3f(0, 0, 1);
    glTranslatef(30, 30, 0);
    glCallList(5);
    fc_get_float(h, "current color after call", GL_CURRENT_COLOR, 4);
    fc_capture(h);
}

/* ---- every primitive type in a list ---- */

static void prim_list(GLenum mode, const float (*v)[2], int n, float dx, float dy)
{
    glBegin(mode);
    for (int i = 0; i < n; i++) {
        glColor3f((float)(i % 3 == 0), (float)(i % 3 == 1), (float)(i % 3 == 2) + 0.25f * (float)(i / 3));
        glVertex2f(v[i][0] + dx, v[i][1] + dy);
    }
    glEnd();
}

static void primitives(fc_h *h)
{
    static const float pts[6][2] = { { 3, 3 }, { 10, 4 }, { 20, 6 }, { 28, 12 }, { 6, 26 }, { 25, 27 } };
    fc_pixel_ortho(h);
    for (int shade = 0; shade < 2; shade++) {
        glShadeModel(shade ? GL_FLAT : GL_SMOOTH);
        fcu_clear(0, 0, 0, 0, 1);
        glNewList(7, GL_COMPILE);
        prim_list(GL_TRIANGLES, fcu_tri_v, 6, 0, 0);
        prim_list(GL_TRIANGLE_STRIP, fcu_strip_v, 8, 32, 0);
        prim_list(GL_TRIANGLE_FAN, fcu_fan_v, 7, 64, 0);
        prim_list(GL_QUADS, fcu_quads_v, 8, 96, 0);
        prim_list(GL_QUAD_STRIP, fcu_qstrip_v, 8, 0, 32);
        prim_list(GL_POLYGON, fcu_poly_v, 6, 32, 32);
        prim_list(GL_POINTS, pts, 6, 64, 32);
        prim_list(GL_LINES, pts, 6, 96, 32);
        prim_list(GL_LINE_STRIP, pts, 6, 0, 64);
        prim_list(GL_LINE_LOOP, pts, 6, 32, 64);
        prim_list(GL_LINE_LOOP, pts, 5, 64, 64);
        prim_list(GL_LINE_STRIP, pts, 4, 96, 64);
        glEndList();
        glCallList(7);
        fc_capture(h);
    }
}

/* consecutive primitives of one mode merge into one indexed draw; strips
 * are joined by degenerate triangles, line strips next to lines become
 * lines, incomplete primitives are padded */
static void merged_prims(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(3, GL_COMPILE);
    for (int i = 0; i < 3; i++) {
        glBegin(GL_TRIANGLES);
        glColor3f(1, 0.3f * (float)i, 0);
        glVertex2f(2 + 10.0f * (float)i, 2);
        glVertex2f(10 + 10.0f * (float)i, 3);
        glColor3f(0, 0.5f, 1);
        glVertex2f(5 + 10.0f * (float)i, 14);
        glEnd();
    }
    for (int i = 0; i < 3; i++) {
        glBegin(GL_TRIANGLE_STRIP);
        glColor3f(0.2f * (float)i, 1, 0);
        glVertex2f(34 + 10.0f * (float)i, 2);
        glVertex2f(42 + 10.0f * (float)i, 3);
        glVertex2f(35 + 10.0f * (float)i, 14);
        if (i != 1)
            glVertex2f(43 + 10.0f * (float)i, 15);
        glEnd();
    }
    for (int i = 0; i < 3; i++) {
        glBegin(i == 1 ? GL_LINES : GL_LINE_STRIP);
        glColor3f(1, 1, 0.3f * (float)i);
        glVertex2f(2 + 10.0f * (float)i, 20);
        glVertex2f(9 + 10.0f * (float)i, 28);
        glVertex2f(4 + 10.0f * (float)i, 30);
        glVertex2f(11 + 10.0f * (float)i, 24);
        glEnd();
    }
    /* a quad with a fifth vertex followed by a quad: merged indices */
    glBegin(GL_QUADS);
    glColor3f(1, 0, 1);
    glVertex2f(34, 18);
    glVertex2f(44, 18);
    glVertex2f(44, 28);
    glVertex2f(34, 28);
    glVertex2f(50, 20);
    glEnd();
    glBegin(GL_QUADS);
    glColor3f(0, 1, 1);
    glVertex2f(46, 18);
    glVertex2f(56, 18);
    glVertex2f(56, 28);
    glVertex2f(46, 28);
    glEnd();
    /* a two-vertex triangle: padded */
    glBegin(GL_TRIANGLES);
    glVertex2f(58, 20);
    glVertex2f(62, 30);
    glEnd();
    glEndList();
    glCallList(3);
    fc_capture(h);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    fcu_clear(0, 0, 0, 0, 1);
    glCallList(3);
    fc_capture(h);
}

/* ---- state in lists ---- */

static void matrices(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(10, GL_COMPILE);
    glPushMatrix();
    glTranslated(16.25, 16.5, 0);
    glRotatef(30, 0, 0, 1);
    glScalef(1.5f, 0.75f, 1);
    glColor3f(1, 0, 0);
    glRectf(-8, -8, 8, 8);
    glPopMatrix();
    glEndList();
    glNewList(11, GL_COMPILE);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(-0.5, 63.5, -0.5, 63.5, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    static const GLdouble m[16] = { 1, 0, 0, 0, 0.25, 1, 0, 0, 0, 0, 1, 0, 30.1, 30.3, 0, 1 };
    glMultMatrixd(m);
    glCallList(10);
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glEndList();
    glCallList(10);
    glCallList(11);
    fc_get_integer(h, "matrix mode", GL_MATRIX_MODE, 1);
    fc_get_float(h, "modelview", GL_MODELVIEW_MATRIX, 16);
    fc_capture(h);
    /* frustum and a loaded matrix */
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(12, GL_COMPILE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.1, 1.05, -1.02, 1.03, 1.3, 10.7);
    glMatrixMode(GL_MODELVIEW);
    static const GLfloat lm[16] = { 0.9f, 0.1f, 0, 0, -0.1f, 0.9f, 0, 0, 0, 0, 1, 0, 0.1f, -0.2f, -3.1f, 1 };
    glLoadMatrixf(lm);
    smooth_quad(-1, -1, 1, 1);
    glEndList();
    glCallList(12);
    fc_get_float(h, "projection", GL_PROJECTION_MATRIX, 16);
    fc_capture(h);
}

static void lighting(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    static const GLfloat pos[4] = { 10, 40, 60, 1 }, dif[4] = { 0.9f, 0.7f, 0.5f, 1 };
    static const GLfloat amb[4] = { 0.1f, 0.2f, 0.1f, 1 }, spec[4] = { 1, 1, 1, 1 };
    static const GLfloat mdif[4] = { 0.3f, 0.8f, 0.6f, 1 }, mspec[4] = { 0.7f, 0.7f, 0.7f, 1 };
    glNewList(20, GL_COMPILE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.01f);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, mdif);
    glMaterialfv(GL_FRONT, GL_SPECULAR, mspec);
    glMaterialf(GL_FRONT, GL_SHININESS, 20);
    glEndList();
    glNewList(21, GL_COMPILE);
    glBegin(GL_TRIANGLE_FAN);
    glNormal3f(0, 0, 1);
    glVertex2f(32, 32);
    for (int i = 0; i <= 12; i++) {
        const float a = 6.2831853f * (float)i / 12.0f;
        glNormal3f(0.3f * (float)i / 12.0f, -0.2f, 0.93f);
        glVertex2f(32 + 28 * cosf(a), 32 + 28 * sinf(a));
    }
    glEnd();
    glEndList();
    glCallList(20);
    glCallList(21);
    fc_get_float(h, "current normal", GL_CURRENT_NORMAL, 3);
    fc_get_float(h, "material diffuse", GL_CURRENT_COLOR, 4);
    fc_capture(h);
    /* glMaterial inside glBegin/glEnd in a list, and colour material */
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(22, GL_COMPILE);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    glColor3f(1, 0, 0);
    glVertex2f(2, 2);
    glVertex2f(30, 2);
    glColor3f(0, 1, 0);
    glVertex2f(30, 30);
    glVertex2f(2, 30);
    glEnd();
    glShadeModel(GL_SMOOTH);
    glDisable(GL_COLOR_MATERIAL);
    glBegin(GL_TRIANGLES);
    glMaterialfv(GL_FRONT, GL_EMISSION, amb);
    glVertex2f(34, 2);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
    glVertex2f(62, 4);
    glVertex2f(40, 30);
    glEnd();
    glEndList();
    glCallList(22);
    fc_capture(h);
    GLfloat got[4];
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, got);
    fc_blob(h, "material diffuse after", got, sizeof(got));
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, got);
    fc_blob(h, "material ambient after", got, sizeof(got));
    glGetMaterialfv(GL_FRONT, GL_EMISSION, got);
    fc_blob(h, "material emission after", got, sizeof(got));
    fc_get_integer(h, "shade model", GL_SHADE_MODEL, 1);
}

/* ---- nesting, deletion, redefinition ---- */

static void nesting(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    fc_get_integer(h, "max nesting", GL_MAX_LIST_NESTING, 1);
    /* list 100 + k translates by one pixel and calls 100 + k + 1: the
     * call chain is cut at 64 nested calls */
    for (int k = 0; k < 70; k++) {
        glNewList(100 + k, GL_COMPILE);
        glTranslatef(0.5f, 0.25f, 0);
        glCallList(101 + k);
        glEndList();
    }
    glNewList(170, GL_COMPILE);
    glEndList();
    glColor3f(1, 1, 0);
    glCallList(100);
    fc_get_float(h, "modelview after chain", GL_MODELVIEW_MATRIX, 16);
    glRectf(0, 0, 4, 4);
    fc_capture(h);
}

static void delete_redefine(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint base = glGenLists(4);
    fc_value(h, "base", base);
    for (int i = 0; i < 4; i++)
        fc_value(h, "islist after gen", glIsList(base + (GLuint)i));
    glNewList(base, GL_COMPILE);
    glColor3f(1, 0, 0);
    glRectf(2, 2, 14, 14);
    glEndList();
    glNewList(base + 1, GL_COMPILE);
    glCallList(base);
    glTranslatef(16, 0, 0);
    glEndList();
    glCallList(base + 1);
    /* redefined: list base + 1 calls the new one */
    glNewList(base, GL_COMPILE);
    glColor3f(0, 1, 0);
    glRectf(2, 18, 14, 30);
    glEndList();
    glCallList(base + 1);
    glDeleteLists(base, 1);
    fc_value(h, "islist deleted", glIsList(base));
    glCallList(base + 1);   /* the deleted list does nothing */
    fc_get_float(h, "modelview", GL_MODELVIEW_MATRIX, 16);
    fc_capture(h);
    glDeleteLists(base, 4);
    for (int i = 0; i < 4; i++)
        fc_value(h, "islist after delete", glIsList(base + (GLuint)i));
    fc_value(h, "islist 0", glIsList(0));
    fc_value(h, "gen after delete", glGenLists(3));
    fc_value(h, "gen 0", glGenLists(0));
    fc_error(h, "final");
}

/* ---- glCallLists with every type ---- */

static void call_lists_types(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    /* lists 1..16 draw cell i; 257 and 65537 + 1 too */
    for (int i = 1; i <= 16; i++) {
        glNewList((GLuint)i, GL_COMPILE);
        fcu_color(i);
        glRectf(4.0f * (float)((i - 1) % 4) * 4, 16.0f * (float)((i - 1) / 4), 4.0f * (float)((i - 1) % 4) * 4 + 15,
                16.0f * (float)((i - 1) / 4) + 3);
        glTranslatef(0, 3, 0);
        glEndList();
    }
    glNewList(258, GL_COMPILE);
    glTranslatef(1, 0, 0);
    glEndList();
    glNewList(65538, GL_COMPILE);
    glTranslatef(0, 0.5f, 0);
    glEndList();
    const GLbyte b[3] = { 1, 2, -1 };
    const GLubyte ub[2] = { 3, 4 };
    const GLshort s[2] = { 5, 6 };
    const GLushort us[2] = { 7, 8 };
    const GLint in[2] = { 9, 10 };
    const GLuint ui[2] = { 11, 12 };
    const GLfloat f[2] = { 13.7f, 14.2f };
    const GLubyte b2[4] = { 0, 15, 1, 1 };
    const GLubyte b3[6] = { 0, 0, 16, 0, 1, 1 };
    const GLubyte b4[8] = { 0, 0, 0, 1, 0, 1, 0, 1 };
    glCallLists(3, GL_BYTE, b);
    glCallLists(2, GL_UNSIGNED_BYTE, ub);
    glCallLists(2, GL_SHORT, s);
    glCallLists(2, GL_UNSIGNED_SHORT, us);
    glCallLists(2, GL_INT, in);
    glCallLists(2, GL_UNSIGNED_INT, ui);
    glCallLists(2, GL_FLOAT, f);
    glCallLists(2, GL_2_BYTES, b2);
    glCallLists(2, GL_3_BYTES, b3);
    glCallLists(2, GL_4_BYTES, b4);
    fc_error(h, "calllists");
    fc_get_float(h, "modelview", GL_MODELVIEW_MATRIX, 16);
    fc_capture(h);
    /* list base, and glCallLists compiled */
    fcu_clear(0, 0, 0, 0, 1);
    glLoadIdentity();
    glListBase(4);
    fc_get_integer(h, "list base", GL_LIST_BASE, 1);
    glNewList(300, GL_COMPILE);
    glCallLists(2, GL_UNSIGNED_BYTE, ub);   /* base added when executed */
    glListBase(8);
    glCallLists(1, GL_SHORT, s);
    glEndList();
    fc_get_integer(h, "list base after compile", GL_LIST_BASE, 1);
    glListBase(0);
    glCallList(300);
    fc_get_integer(h, "list base after call", GL_LIST_BASE, 1);
    fc_capture(h);
    glPushAttrib(GL_LIST_BIT);
    glListBase(77);
    glPopAttrib();
    fc_get_integer(h, "list base after pop", GL_LIST_BASE, 1);
    glListBase(0xfffffff0u);
    fc_get_integer(h, "list base large", GL_LIST_BASE, 1);
    fc_get_float(h, "list base large float", GL_LIST_BASE, 1);
    glListBase(0xfffffff0u);
    const GLint wrap[1] = { 0x11 };
    glCallLists(1, GL_INT, wrap);   /* base + 17 wraps to list 1 */
    fc_capture(h);
}

/* ---- errors ---- */

static void errors(fc_h *h)
{
    fc_pixel_ortho(h);
    glNewList(0, GL_COMPILE);
    fc_error(h, "newlist 0");
    glNewList(1, GL_RENDER);
    fc_error(h, "newlist bad mode");
    glEndList();
    fc_error(h, "endlist without newlist");
    glNewList(1, GL_COMPILE);
    glNewList(2, GL_COMPILE);
    fc_error(h, "nested newlist");
    fc_get_integer(h, "list index nested", GL_LIST_INDEX, 1);
    glEnable(0x1234);             /* compiled: raised when executed */
    glBegin(0x77);                /* compile error */
    glBegin(GL_TRIANGLES);
    glBegin(GL_POINTS);           /* recursive: compile error */
    glEnable(GL_BLEND);           /* inside glBegin/glEnd: compile error */
    glVertex2f(1, 1);
    glVertex2f(10, 1);
    glVertex2f(1, 10);
    glEnd();
    glMaterialf(GL_FRONT, GL_SHININESS, 300);  /* validated when executed */
    glMaterialf(0x99, GL_SHININESS, 3);        /* compile error */
    glCallLists(1, 0x1500, NULL);
    glCallLists(-1, GL_UNSIGNED_BYTE, NULL);
    glCallList(0);
    glDrawArrays(0x55, 0, 3);
    glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, NULL);
    fc_error(h, "during compile");
    glEndList();
    fc_error(h, "endlist");
    glCallList(1);
    fc_error(h, "call 1");
    glCallList(1);
    fc_error(h, "call 2");
    glGetError();
    glGetError();
    glGetError();
    glCallList(0);
    fc_error(h, "calllist 0");
    glCallLists(1, GL_DOUBLE, NULL);
    fc_error(h, "calllists bad type");
    glCallLists(-1, GL_BYTE, NULL);
    fc_error(h, "calllists negative");
    glCallLists(0, 0x9999, NULL);
    fc_error(h, "calllists 0 bad type");
    glGenLists(-1);
    fc_error(h, "genlists negative");
    glDeleteLists(1, -1);
    fc_error(h, "deletelists negative");
    /* inside glBegin/glEnd */
    glBegin(GL_POINTS);
    glNewList(5, GL_COMPILE);
    fc_error(h, "newlist inside begin");
    glGenLists(1);
    fc_error(h, "genlists inside begin");
    glIsList(1);
    fc_error(h, "islist inside begin");
    glDeleteLists(1, 1);
    fc_error(h, "deletelists inside begin");
    glListBase(3);
    fc_error(h, "listbase inside begin");
    glCallList(1);
    fc_error(h, "calllist with begin inside begin");
    glEnd();
    fc_get_integer(h, "list base", GL_LIST_BASE, 1);
    fc_error(h, "final");
}

/* COMPILE_AND_EXECUTE raises compile errors at once */
static void errors_execute(fc_h *h)
{
    fc_pixel_ortho(h);
    glNewList(3, GL_COMPILE_AND_EXECUTE);
    glEnable(0x1234);
    fc_error(h, "bad enable");
    glBegin(GL_TRIANGLES);
    glEnable(GL_BLEND);
    fc_error(h, "enable inside begin");
    glEnd();
    glCallList(0);
    fc_error(h, "calllist 0");
    glNewList(4, GL_COMPILE);
    fc_error(h, "nested newlist");
    glEndList();
    fc_error(h, "endlist");
    glCallList(3);
    fc_error(h, "call");
    fc_error(h, "final");
}


/* ---- arrays in lists ---- */

static void arrays(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    static GLfloat v[8][2] = { { 2, 2 }, { 14, 3 }, { 13, 14 }, { 3, 13 },
                               { 18, 2 }, { 30, 4 }, { 29, 15 }, { 17, 12 } };
    static GLubyte c[8][4] = { { 255, 0, 0, 255 }, { 0, 255, 0, 255 }, { 0, 0, 255, 255 },
                               { 255, 255, 0, 255 }, { 0, 255, 255, 255 }, { 255, 0, 255, 255 },
                               { 128, 64, 32, 255 }, { 32, 64, 128, 255 } };
    static const GLushort idx[6] = { 4, 5, 6, 4, 6, 7 };
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    glNewList(1, GL_COMPILE);
    glDrawArrays(GL_QUADS, 0, 4);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, idx);
    glTranslatef(0, 16, 0);
    glBegin(GL_TRIANGLE_FAN);
    for (int i = 0; i < 4; i++)
        glArrayElement(i);
    glEnd();
    glDrawRangeElements(GL_LINE_LOOP, 4, 7, 4, GL_UNSIGNED_SHORT, idx);
    glEndList();
    /* the arrays change after compilation: the list keeps what it read */
    for (int i = 0; i < 8; i++) {
        v[i][0] += 32;
        c[i][0] = (GLubyte)(255 - c[i][0]);
    }
    glDisableClientState(GL_COLOR_ARRAY);
    glColor3f(0.5f, 0.5f, 0.5f);
    glCallList(1);
    fc_get_float(h, "current color after list", GL_CURRENT_COLOR, 4);
    fc_capture(h);
    /* compile and execute: drawn through immediate mode */
    fcu_clear(0, 0, 0, 0, 1);
    glLoadIdentity();
    glEnableClientState(GL_COLOR_ARRAY);
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glDrawArrays(GL_QUADS, 0, 8);
    glEndList();
    fc_get_float(h, "current color c&e", GL_CURRENT_COLOR, 4);
    fc_capture(h);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
}

/* ---- commands executed at once while compiling ---- */

static void immediate_commands(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    static const GLfloat v[3][2] = { { 2, 2 }, { 30, 2 }, { 2, 30 } };
    glNewList(1, GL_COMPILE);
    glEnableClientState(GL_VERTEX_ARRAY);    /* executed, not compiled */
    glVertexPointer(2, GL_FLOAT, 0, v);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    fc_is_enabled(h, "vertex array in list", GL_VERTEX_ARRAY);
    GLuint gen = glGenLists(2);
    fc_value(h, "genlists in list", gen);
    fc_value(h, "islist in list", glIsList(1));
    glDeleteLists(gen, 1);
    fc_value(h, "deleted in list", glIsList(gen));
    glColor3f(0, 1, 0);
    glRectf(4, 4, 28, 28);
    fc_get_float(h, "current color in list", GL_CURRENT_COLOR, 4);
    glFlush();
    glFinish();
    GLubyte px[4] = { 1, 2, 3, 4 };
    glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    fc_blob(h, "readpixels in list", px, sizeof(px));
    glDisableClientState(GL_VERTEX_ARRAY);
    glEndList();
    fc_error(h, "compile");
    fc_get_integer(h, "pack alignment", GL_PACK_ALIGNMENT, 1);
    fc_capture(h);
    glCallList(1);
    fc_is_enabled(h, "vertex array after call", GL_VERTEX_ARRAY);
    fc_capture(h);
    /* compile and execute: vertex data is executed when the vertex list
     * is compiled, so a glReadPixels right after it does not see it */
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glColor3f(1, 0, 0);
    glRectf(4, 4, 28, 28);
    glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    fc_blob(h, "readpixels c&e before flush", px, sizeof(px));
    glColor3f(0, 0, 1);           /* flushes the vertex list */
    glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    fc_blob(h, "readpixels c&e after flush", px, sizeof(px));
    glEndList();
    fc_capture(h);
}

/* glShadeModel and glMaterial execute before the pending vertex list is
 * flushed under GL_COMPILE_AND_EXECUTE; repeated values are not compiled */
static void execute_order(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE_AND_EXECUTE);
    smooth_quad(2, 2, 30, 30);
    glShadeModel(GL_FLAT);
    smooth_quad(34, 2, 62, 30);
    glShadeModel(GL_FLAT);
    glShadeModel(GL_SMOOTH);
    glEndList();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glCallList(1);
    fc_capture(h);
    /* lit: a material after a primitive */
    fcu_clear(0, 0, 0, 0, 1);
    static const GLfloat red[4] = { 1, 0, 0, 1 }, blue[4] = { 0, 0, 1, 1 };
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red);
    glNormal3f(0, 0, 1);
    glRectf(2, 34, 30, 62);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue);
    glRectf(34, 34, 62, 62);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue);   /* left out */
    glEndList();
    fc_capture(h);
    glDisable(GL_LIGHTING);
}

/* ---- primitives across lists ---- */

/* a glBegin in one list and its glEnd in another: the lists are replayed
 * through immediate mode (loopback) */
static void dangling(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0);
    glVertex2f(2, 2);
    glColor3f(0, 1, 0);
    glVertex2f(30, 2);
    glEndList();
    glNewList(2, GL_COMPILE);
    glColor3f(0, 0, 1);
    glVertex2f(30, 30);
    glColor3f(1, 1, 1);
    glVertex2f(2, 30);
    glEnd();
    glEndList();
    fc_error(h, "compile");
    glCallList(1);
    glCallList(2);
    fc_error(h, "call");
    /* a list of vertices only, called inside glBegin/glEnd */
    glNewList(3, GL_COMPILE);
    glColor3f(1, 0, 1);
    glVertex2f(34, 2);
    glVertex2f(62, 2);
    glColor3f(0, 1, 1);
    glVertex2f(62, 30);
    glVertex2f(34, 30);
    glEndList();
    glBegin(GL_QUADS);
    glCallList(3);
    glEnd();
    fc_error(h, "inside");
    /* glCallList inside glBegin/glEnd while compiling */
    glNewList(4, GL_COMPILE);
    glTranslatef(0, 32, 0);
    glBegin(GL_QUADS);
    glCallList(3);
    glEnd();
    glEndList();
    glCallList(4);
    /* a list with a complete primitive called inside glBegin/glEnd */
    glBegin(GL_TRIANGLES);
    glCallList(1);
    glCallList(2);
    fc_error(h, "complete primitive inside begin");
    glEnd();
    fc_error(h, "final");
    fc_capture(h);
}

/* a new attribute after the first vertex wraps the vertex list; without a
 * value known at compile time the list is replayed by loopback */
static void upgrade_wrap(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    /* colour unknown at compile time: loopback (immediate mode's 0-2
     * quad diagonal) */
    glNewList(1, GL_COMPILE);
    glBegin(GL_QUADS);
    glVertex2f(2, 2);
    glColor3f(0, 1, 0);
    glVertex2f(30, 2);
    glColor3f(0, 0, 1);
    glVertex2f(30, 30);
    glColor3f(1, 1, 1);
    glVertex2f(2, 30);
    glEnd();
    glEndList();
    /* colour set before in the list: known, drawn indexed */
    glNewList(2, GL_COMPILE);
    glColor3f(1, 0, 0);
    glBegin(GL_QUADS);
    glVertex2f(34, 2);
    glColor3f(0, 1, 0);
    glVertex2f(62, 2);
    glColor3f(0, 0, 1);
    glVertex2f(62, 30);
    glColor3f(1, 1, 1);
    glVertex2f(34, 30);
    glEnd();
    glEndList();
    glColor3f(1, 0, 0);
    glCallList(1);
    glCallList(2);
    fc_capture(h);
    /* a strip and a line loop wrapped by a new attribute */
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(3, GL_COMPILE);
    glColor3f(1, 1, 0);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(2, 34);
    glVertex2f(10, 36);
    glVertex2f(3, 50);
    glNormal3f(0, 0, 1);
    glVertex2f(14, 52);
    glVertex2f(6, 62);
    glColor3f(0, 1, 1);
    glVertex2f(18, 60);
    glEnd();
    glBegin(GL_LINE_LOOP);
    glVertex2f(34, 34);
    glVertex2f(60, 36);
    glColor4f(1, 0, 1, 1);
    glVertex2f(58, 60);
    glVertex2f(36, 58);
    glEnd();
    glEndList();
    glCallList(3);
    fc_get_float(h, "current color", GL_CURRENT_COLOR, 4);
    fc_get_float(h, "current normal", GL_CURRENT_NORMAL, 3);
    fc_capture(h);
}

/* the current values a list leaves: its last vertex's attributes; an
 * attribute after the last vertex inside glBegin/glEnd is lost */
static void current_values(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glNormal3f(0, 1, 0);
    glVertex2f(2, 2);
    glVertex2f(30, 2);
    glColor3f(0, 0, 1);
    glVertex2f(2, 30);
    glColor3f(0, 1, 0);
    glNormal3f(1, 0, 0);
    glEnd();
    glEndList();
    glCallList(1);
    fc_get_float(h, "color", GL_CURRENT_COLOR, 4);
    fc_get_float(h, "normal", GL_CURRENT_NORMAL, 3);
    glRectf(34, 2, 62, 30);
    /* a colour outside glBegin/glEnd */
    glNewList(2, GL_COMPILE);
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    glEndList();
    glCallList(2);
    fc_get_float(h, "color 2", GL_CURRENT_COLOR, 4);
    glRectf(2, 34, 30, 62);
    /* colour material follows a list's last colour */
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glCallList(1);
    GLfloat d[4];
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, d);
    fc_blob(h, "diffuse", d, sizeof(d));
    glDisable(GL_COLOR_MATERIAL);
    /* glPushAttrib(GL_CURRENT_BIT) around a list */
    glPushAttrib(GL_CURRENT_BIT);
    glCallList(1);
    glPopAttrib();
    fc_get_float(h, "color after pop", GL_CURRENT_COLOR, 4);
    /* edge flag inside glBegin/glEnd */
    glNewList(3, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_FALSE);
    glVertex2f(34, 34);
    glEdgeFlag(GL_TRUE);
    glVertex2f(62, 34);
    glVertex2f(34, 62);
    glEnd();
    glEndList();
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1, 1, 1);
    glCallList(3);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    fc_get_boolean(h, "edge flag", GL_EDGE_FLAG, 1);
    fc_capture(h);
}

/* ---- more state in lists ---- */

static void more_state(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    static const GLubyte stipple_src[128 + 8] = { 0 };
    GLubyte stipple[136];
    for (int i = 0; i < 136; i++)
        stipple[i] = (GLubyte)(stipple_src[i] + (i * 37 + 11));
    glNewList(1, GL_COMPILE);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClearDepth(0.3);
    glClearStencil(3);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDepthFunc(GL_LEQUAL);
    glDepthRange(0.1, 0.9);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_POLYGON_STIPPLE);
    glPolygonStipple(stipple);
    glPixelStorei(GL_UNPACK_LSB_FIRST, 1);   /* executed now */
    glPolygonStipple(stipple + 8);
    glPixelStorei(GL_UNPACK_LSB_FIRST, 0);
    glColor4f(1, 0.5f, 0, 0.6f);
    glRectf(4, 4, 60, 60);
    glDisable(GL_POLYGON_STIPPLE);
    glLineWidth(3);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x33f1);
    glBegin(GL_LINES);
    glVertex3f(4, 40, 0.5f);
    glVertex3f(60, 50, 0.5f);
    glEnd();
    glPointSize(4);
    glBegin(GL_POINTS);
    glVertex2f(50, 10);
    glEnd();
    glScissor(8, 8, 40, 40);
    glEnable(GL_SCISSOR_TEST);
    glColorMask(1, 0, 1, 1);
    glHint(GL_FOG_HINT, GL_NICEST);
    glEndList();
    fcu_clear(0, 0, 0, 0, 1);
    glCallList(1);
    fc_get_float(h, "depth clear", GL_DEPTH_CLEAR_VALUE, 1);
    fc_get_float(h, "depth range", GL_DEPTH_RANGE, 2);
    fc_get_integer(h, "scissor", GL_SCISSOR_BOX, 4);
    fc_get_integer(h, "hint", GL_FOG_HINT, 1);
    fc_get_integer(h, "line stipple", GL_LINE_STIPPLE_PATTERN, 1);
    GLubyte got[128];
    glGetPolygonStipple(got);
    fc_blob(h, "stipple", got, sizeof(got));
    fc_capture(h);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(1, 1, 1, 1);
    glDisable(GL_LINE_STIPPLE);
    glDisable(GL_BLEND);
    /* fog and a clip plane, doubles stored as floats */
    fcu_clear(0, 0, 0, 0, 1);
    static const GLdouble plane[4] = { 1.0000001, 0.3333333333, 0, -20.123456789 };
    static const GLfloat fogc[4] = { 0.2f, 0.9f, 0.4f, 1 };
    glNewList(2, GL_COMPILE);
    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, -0.5f);
    glFogf(GL_FOG_END, 1.25f);
    glFogfv(GL_FOG_COLOR, fogc);
    glEnable(GL_FOG);
    glDepthRange(0.0, 1.0);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(2, 2, 0.9f);
    glColor3f(0, 1, 0);
    glVertex3f(62, 2, -0.9f);
    glColor3f(0, 0, 1);
    glVertex3f(2, 62, 0.1f);
    glEnd();
    glDisable(GL_FOG);
    glDisable(GL_CLIP_PLANE0);
    glEndList();
    glCallList(2);
    GLdouble eq[4];
    glGetClipPlane(GL_CLIP_PLANE0, eq);
    fc_blob(h, "clip plane", eq, sizeof(eq));
    fc_capture(h);
}

/* glPushAttrib/glPopAttrib compiled, and GL_LIST_BIT */
static void attrib_lists(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    glPushAttrib(GL_ENABLE_BIT | GL_LIST_BIT | GL_CURRENT_BIT);
    glEnable(GL_BLEND);
    glListBase(40);
    glColor3f(1, 0, 0);
    glRectf(2, 2, 30, 30);
    glPopAttrib();
    glEndList();
    glListBase(7);
    glCallList(1);
    fc_get_integer(h, "list base", GL_LIST_BASE, 1);
    fc_is_enabled(h, "blend", GL_BLEND);
    fc_get_float(h, "color", GL_CURRENT_COLOR, 4);
    fc_capture(h);
}

/* glRect variants, and glRectd (no save function in Mesa 22.3) */
static void rects(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    static const GLshort sv[4] = { 2, 2, 14, 14 };
    static const GLdouble dv[4] = { 18.5, 2.25, 30.75, 14.5 };
    glNewList(1, GL_COMPILE);
    glColor3f(1, 0, 0);
    glRectsv(sv, sv + 2);
    glColor3f(0, 1, 0);
    glRectdv(dv, dv + 2);
    glColor3f(0, 0, 1);
    glRectd(34.5, 2.5, 46.25, 14.75);
    glColor3f(1, 1, 0);
    glRecti(50, 2, 62, 14);
    glBegin(GL_TRIANGLES);
    glRectf(2, 18, 14, 30);    /* inside glBegin/glEnd: another quad */
    glEnd();
    glEndList();
    fc_error(h, "compile");
    glCallList(1);
    fc_error(h, "call");
    fc_capture(h);
}

/* a long primitive fills the compiler's 1 MiB vertex store and wraps */
static void long_strip(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 50000; i++) {
        const float t = (float)i / 50000.0f;
        glColor3f(t, 1.0f - t, (float)(i & 1));
        glVertex2f(2.0f + 60.0f * t, (i & 1) ? 40.0f : 4.0f + 20.0f * t);
    }
    glEnd();
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < 40000; i++) {
        const float a = 6.2831853f * (float)i / 40000.0f;
        glColor3f(1, 1, (float)(i & 1));
        glVertex2f(32 + 26 * cosf(a), 32 + 26 * sinf(a));
    }
    glEnd();
    glEndList();
    glCallList(1);
    fc_get_float(h, "color", GL_CURRENT_COLOR, 4);
    fc_capture(h);
}


/* line strips next to lines or strips are drawn as lines: the stipple
 * restarts at every segment; a line loop compiled last becomes a strip */
static void line_stipple(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x0f0f);
    glNewList(1, GL_COMPILE);
    for (int k = 0; k < 2; k++) {
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 0.5f * (float)k, 0);
        glVertex2f(2, 4 + 10.0f * (float)k);
        glVertex2f(19, 7 + 10.0f * (float)k);
        glVertex2f(40, 3 + 10.0f * (float)k);
        glVertex2f(62, 9 + 10.0f * (float)k);
        glEnd();
    }
    glBegin(GL_LINE_STRIP);   /* alone: stays a strip */
    glVertex2f(2, 30);
    glVertex2f(21, 33);
    glVertex2f(62, 28);
    glEnd();
    glEndList();
    glNewList(2, GL_COMPILE);
    glBegin(GL_LINE_LOOP);
    glColor3f(0, 1, 1);
    glVertex2f(4, 40);
    glVertex2f(60, 42);
    glVertex2f(50, 60);
    glVertex2f(8, 58);
    glEnd();
    glBegin(GL_LINE_LOOP);
    glVertex2f(20, 46);
    glVertex2f(40, 47);
    glVertex2f(30, 54);
    glEnd();
    glEndList();
    glCallList(1);
    glCallList(2);
    fc_capture(h);
    glDisable(GL_LINE_STIPPLE);
}

/* polygon offset, clipping and two-sided lighting over merged draws */
static void offset_clip(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glNewList(1, GL_COMPILE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 3);
    for (int k = 0; k < 3; k++) {
        glBegin(GL_QUADS);
        glColor3f(1, 0.3f * (float)k, 0.2f);
        glVertex3f(-6 + 24.0f * (float)k, -5, 0.3f);
        glColor3f(0.2f, 1, 0.3f * (float)k);
        glVertex3f(20 + 24.0f * (float)k, -3, -0.2f);
        glColor3f(0, 0.2f, 1);
        glVertex3f(22 + 24.0f * (float)k, 26, 0.5f);
        glColor3f(1, 1, 1);
        glVertex3f(-4 + 24.0f * (float)k, 24, -0.7f);
        glEnd();
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glEndList();
    glCallList(1);
    fc_capture(h);
    /* two-sided lighting, back faces */
    fcu_clear(0, 0, 0, 0, 1);
    static const GLfloat back[4] = { 0.9f, 0.2f, 0.1f, 1 }, front[4] = { 0.1f, 0.3f, 0.9f, 1 };
    glNewList(2, GL_COMPILE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glMaterialfv(GL_BACK, GL_DIFFUSE, back);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, front);
    glBegin(GL_TRIANGLE_FAN);
    glNormal3f(0, 0.3f, 0.95f);
    glVertex2f(32, 32);
    glVertex2f(60, 30);
    glNormal3f(0.2f, 0, 0.97f);
    glVertex2f(50, 55);
    glVertex2f(20, 70);
    glVertex2f(-5, 40);
    glVertex2f(10, 5);
    glEnd();
    glDisable(GL_LIGHTING);
    glEndList();
    glCallList(2);
    glFrontFace(GL_CW);
    glTranslatef(0, 0, 0.1f);
    glCallList(2);
    glFrontFace(GL_CCW);
    fc_capture(h);
}

/* glCallList while compiling forgets what the compiler knew: the repeated
 * glShadeModel and glMaterial after it are compiled */
static void redundant_state(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    static const GLfloat red[4] = { 1, 0, 0, 1 }, blue[4] = { 0, 0, 1, 1 };
    glNewList(1, GL_COMPILE);
    glShadeModel(GL_SMOOTH);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
    glEndList();
    glNewList(2, GL_COMPILE);
    glShadeModel(GL_FLAT);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glCallList(1);
    glShadeModel(GL_FLAT);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glBegin(GL_TRIANGLES);
    glNormal3f(0, 0, 1);
    glColor3f(1, 1, 0);
    glVertex2f(2, 2);
    glColor3f(0, 1, 1);
    glVertex2f(30, 2);
    glVertex2f(2, 30);
    glEnd();
    glDisable(GL_LIGHTING);
    smooth_quad(34, 2, 62, 30);
    /* without a call in between, the repeats are left out */
    glShadeModel(GL_SMOOTH);
    glShadeModel(GL_SMOOTH);
    smooth_quad(2, 34, 30, 62);
    glEndList();
    glShadeModel(GL_SMOOTH);
    glCallList(2);
    fc_get_integer(h, "shade model", GL_SHADE_MODEL, 1);
    fc_capture(h);
}

/* list names: glGenLists after the highest name used, the search for a
 * free block near the top of the name space, glDeleteLists ranges */
static void names(fc_h *h)
{
    fc_pixel_ortho(h);
    glNewList(1000, GL_COMPILE);
    glEndList();
    fc_value(h, "gen after 1000", glGenLists(2));
    glDeleteLists(1000, 3);
    fc_value(h, "gen after delete", glGenLists(1));
    fc_value(h, "islist 1000", glIsList(1000));
    fc_value(h, "islist 1003", glIsList(1003));
    glNewList(0xfffffff0u, GL_COMPILE);
    glEndList();
    fc_value(h, "islist high", glIsList(0xfffffff0u));
    fc_value(h, "gen near top", glGenLists(20));
    fc_value(h, "gen near top small", glGenLists(5));
    glDeleteLists(0xffffffe0u, 0x40);   /* wraps: deletes nothing */
    fc_value(h, "islist high after wrap", glIsList(0xfffffff0u));
    glDeleteLists(0xffffffe0u, 0x1f);
    fc_value(h, "islist high after delete", glIsList(0xfffffff0u));
    glDeleteLists(0, 2000);
    fc_value(h, "islist 1 after delete", glIsList(1));
    fc_value(h, "gen after all", glGenLists(1));
    fc_error(h, "final");
}

/* a list that calls lists while COMPILE_AND_EXECUTE, and glEndList inside
 * glBegin/glEnd */
static void nested_execute(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    smooth_quad(2, 2, 14, 14);
    glTranslatef(16, 0, 0);
    glEndList();
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glColor3f(1, 1, 0);
    glCallList(1);
    fc_get_integer(h, "list index while calling", GL_LIST_INDEX, 1);
    GLubyte ids[2] = { 1, 1 };
    glCallLists(2, GL_UNSIGNED_BYTE, ids);
    glEndList();
    fc_get_float(h, "modelview", GL_MODELVIEW_MATRIX, 16);
    fc_capture(h);
    glLoadIdentity();
    glTranslatef(0, 16, 0);
    glCallList(2);
    fc_capture(h);
    /* glEndList with a primitive open */
    glLoadIdentity();
    glNewList(3, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_TRIANGLES);
    glColor3f(0, 1, 0);
    glVertex2f(2, 40);
    glVertex2f(30, 40);
    glEndList();
    fc_error(h, "endlist inside begin c&e");
    glVertex2f(2, 62);
    glEnd();
    fc_error(h, "end after list");
    glNewList(4, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glVertex2f(34, 40);
    glEndList();
    fc_error(h, "endlist inside begin compile");
    glBegin(GL_TRIANGLES);
    glCallList(4);
    glVertex2f(62, 40);
    glVertex2f(34, 62);
    glEnd();
    fc_error(h, "call list 4 inside begin");
    glCallList(3);
    glVertex2f(2, 62);
    glEnd();
    fc_error(h, "final");
    fc_capture(h);
}

/* a second context sharing the first one's lists (OSMesaCreateContext's
 * sharelist); one that does not share has its own names */
static void shared_contexts(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(7, GL_COMPILE);
    smooth_quad(2, 2, 14, 14);
    glEndList();
    static GLubyte buf2[16 * 16 * 4];
    OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, fc_context(h));
    OSMesaContext alone = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    fc_value(h, "contexts", shared != NULL && alone != NULL);
    if (!shared || !alone)
        return;
    OSMesaMakeCurrent(shared, buf2, GL_UNSIGNED_BYTE, 16, 16);
    glViewport(0, 0, 16, 16);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, 16, 0, 16, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fc_value(h, "shared islist 7", glIsList(7));
    glCallList(7);
    fc_value(h, "shared gen", glGenLists(1));
    glNewList(9, GL_COMPILE);   /* defined here, called in the first */
    glColor3f(1, 1, 0);
    glRectf(18, 2, 30, 14);
    glEndList();
    glFinish();
    fc_capture_buffer(h, buf2, 16, 16, 16, OSMESA_RGBA, 1);
    OSMesaMakeCurrent(alone, buf2, GL_UNSIGNED_BYTE, 16, 16);
    fc_value(h, "alone islist 7", glIsList(7));
    fc_value(h, "alone gen", glGenLists(1));
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 32, 32);
    fc_value(h, "first islist 9", glIsList(9));
    glCallList(9);
    OSMesaDestroyContext(shared);
    OSMesaDestroyContext(alone);
    fc_value(h, "islist 7 after destroy", glIsList(7));
    glTranslatef(0, 16, 0);
    glCallList(7);
    fc_capture(h);
}

/* the list queries through every glGet, outside and inside lists */
static void queries(fc_h *h)
{
    static const GLenum pnames[] = { GL_LIST_BASE, GL_LIST_INDEX, GL_LIST_MODE, GL_MAX_LIST_NESTING };
    static const char *labels[] = { "list base", "list index", "list mode", "max nesting" };
    for (int round = 0; round < 3; round++) {
        if (round == 1) {
            glListBase(12345);
            glNewList(77, GL_COMPILE);
        } else if (round == 2) {
            glNewList(0x80000001u, GL_COMPILE_AND_EXECUTE);
            glListBase(0x80000000u);
        }
        for (int i = 0; i < 4; i++) {
            char label[64];
            snprintf(label, sizeof(label), "%s %d i", labels[i], round);
            fc_get_integer(h, label, pnames[i], 1);
            snprintf(label, sizeof(label), "%s %d f", labels[i], round);
            fc_get_float(h, label, pnames[i], 1);
            snprintf(label, sizeof(label), "%s %d b", labels[i], round);
            fc_get_boolean(h, label, pnames[i], 1);
            snprintf(label, sizeof(label), "%s %d d", labels[i], round);
            fc_get_double(h, label, pnames[i], 1);
        }
        if (round)
            glEndList();
    }
    fc_get_integer(h, "list base after", GL_LIST_BASE, 1);
    fc_error(h, "final");
}

/* pseudo-random primitive sequences compiled into lists: every mode, short
 * and incomplete primitives, attributes before, between and after
 * vertices (new attributes mid-primitive wrap the vertex list), state
 * changes between primitives, GL_COMPILE and GL_COMPILE_AND_EXECUTE */
static unsigned fuzz_seed;
static unsigned fuzz_next(unsigned n)
{
    fuzz_seed = fuzz_seed * 1103515245u + 12345u;
    return (fuzz_seed >> 16) % n;
}

static float fuzz_coord(void)
{
    return (float)fuzz_next(2400) / 32.0f - 5.0f;
}

static void fuzz_list(int variant)
{
    static const GLenum modes[] = { GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_LINE_STRIP,
                                    GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                    GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    const int nprims = 6 + (int)fuzz_next(10);
    for (int p = 0; p < nprims; p++) {
        const GLenum mode = modes[fuzz_next(10)];
        const int n = (int)fuzz_next(9);
        switch (fuzz_next(8)) {
        case 0: {
            const float r = (float)fuzz_next(4) / 3.0f, g = (float)fuzz_next(4) / 3.0f;
            glColor3f(r, g, 0.5f);
            break;
        }
        case 1:
            glShadeModel(fuzz_next(2) ? GL_FLAT : GL_SMOOTH);
            break;
        case 2:
            glNormal3f(0, (float)fuzz_next(3) / 4.0f, 1);
            break;
        default:
            break;
        }
        glBegin(mode);
        for (int v = 0; v < n; v++) {
            switch (fuzz_next(variant ? 6 : 4)) {
            case 0: {
                const float r = (float)fuzz_next(5) / 4.0f, g = (float)fuzz_next(5) / 4.0f;
                const float b = (float)fuzz_next(5) / 4.0f;
                glColor4f(r, g, b, 1);
                break;
            }
            case 1: {
                const GLubyte r = (GLubyte)fuzz_next(256), g = (GLubyte)fuzz_next(256);
                glColor3ub(r, g, 200);
                break;
            }
            case 4:
                glNormal3f((float)fuzz_next(3) / 3.0f, 0.5f, 0.8f);
                break;
            case 5:
                glEdgeFlag(fuzz_next(2) ? GL_TRUE : GL_FALSE);
                break;
            default:
                break;
            }
            const float x = fuzz_coord(), y = fuzz_coord();
            glVertex3f(x, y, (float)fuzz_next(100) / 100.0f - 0.5f);
        }
        if (fuzz_next(4) == 0)
            glColor3f(1, 1, 1);    /* after the last vertex */
        glEnd();
    }
}

static void fuzz(fc_h *h)
{
    fc_pixel_ortho(h);
    glPointSize(2);
    fuzz_seed = 20261121u;
    for (int frame = 0; frame < 8; frame++) {
        fcu_clear(0, 0, 0, 0, 1);
        glPolygonMode(GL_FRONT_AND_BACK, frame == 3 || frame == 7 ? GL_LINE : GL_FILL);
        if (frame >= 4) {
            glEnable(GL_LIGHTING);
            glEnable(GL_LIGHT0);
            glEnable(GL_COLOR_MATERIAL);
        }
        glNewList(1, frame & 1 ? GL_COMPILE_AND_EXECUTE : GL_COMPILE);
        fuzz_list(frame & 2);
        glEndList();
        glNewList(2, GL_COMPILE);
        if (frame & 2)
            glColor3f(0.2f, 0.4f, 0.6f);
        fuzz_list(frame & 2);
        glEndList();
        glTranslatef(2, 1, 0);
        glCallList(1);
        glCallList(2);
        glLoadIdentity();
        fc_get_float(h, "color", GL_CURRENT_COLOR, 4);
        fc_get_float(h, "normal", GL_CURRENT_NORMAL, 3);
        fc_error(h, "frame");
        fc_capture(h);
    }
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

/* an empty glBegin/glEnd: llvmpipe skips a multi-draw whose first draw is
 * empty, so in immediate mode the primitives of the same mode batched
 * after it are not drawn; a compiled list drops empty primitives */
static void empty_primitive(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    for (int pass = 0; pass < 2; pass++) {
        if (pass)
            glNewList(1, GL_COMPILE);
        glBegin(GL_TRIANGLES);
        glVertex2f(1, 1);
        glEnd();
        glBegin(GL_QUAD_STRIP);
        glEnd();
        glBegin(GL_QUAD_STRIP);
        glColor3f(1, 0, 0);
        glVertex2f(2 + 32.0f * (float)pass, 2);
        glVertex2f(30 + 32.0f * (float)pass, 3);
        glColor3f(0, 1, 0);
        glVertex2f(3 + 32.0f * (float)pass, 28);
        glVertex2f(29 + 32.0f * (float)pass, 30);
        glEnd();
        glBegin(GL_TRIANGLES);   /* a second run, drawn */
        glColor3f(0, 0, 1);
        glVertex2f(2 + 32.0f * (float)pass, 40);
        glVertex2f(30 + 32.0f * (float)pass, 40);
        glVertex2f(16 + 32.0f * (float)pass, 60);
        glEnd();
        if (pass) {
            glEndList();
            glCallList(1);
        }
    }
    fc_capture(h);
}

/* more pseudo-random lists: materials inside glBegin/glEnd, glRect,
 * compiled array draws, state changes and nested calls between
 * primitives, lists ending inside glBegin/glEnd */
static void fuzz_list2(int depth)
{
    static const GLenum modes[] = { GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_LINE_STRIP,
                                    GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                    GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    static GLfloat arr[12][2];
    for (int k = 0; k < 12; k++) {
        arr[k][0] = fuzz_coord();
        arr[k][1] = fuzz_coord();   /* separate statements: a defined order */
    }
    const int nprims = 4 + (int)fuzz_next(8);
    for (int p = 0; p < nprims; p++) {
        switch (fuzz_next(10)) {
        case 0: {
            GLfloat m[4] = { 0, 0.5f, 0, 1 };
            m[0] = (float)fuzz_next(4) / 3.0f;
            m[2] = (float)fuzz_next(4) / 3.0f;
            glMaterialfv(fuzz_next(2) ? GL_FRONT : GL_FRONT_AND_BACK, GL_DIFFUSE, m);
            break;
        }
        case 1: {
            const float x0 = fuzz_coord(), y0 = fuzz_coord();
            const float x1 = fuzz_coord(), y1 = fuzz_coord();
            glRectf(x0, y0, x1, y1);
            break;
        }
        case 2: {
            glEnableClientState(GL_VERTEX_ARRAY);
            glVertexPointer(2, GL_FLOAT, 0, arr);
            const GLenum mode = modes[fuzz_next(10)];
            const GLint first = (GLint)fuzz_next(4);
            glDrawArrays(mode, first, (GLsizei)fuzz_next(9));
            glDisableClientState(GL_VERTEX_ARRAY);
            break;
        }
        case 3:
            if (fuzz_next(2))
                glEnable(GL_LINE_STIPPLE);
            else
                glDisable(GL_LINE_STIPPLE);
            break;
        case 4:
            if (depth == 0)
                glCallList(10 + fuzz_next(3));
            break;
        case 5:
            glShadeModel(fuzz_next(2) ? GL_FLAT : GL_SMOOTH);
            break;
        default:
            break;
        }
        glBegin(modes[fuzz_next(10)]);
        const int n = (int)fuzz_next(10);
        for (int v = 0; v < n; v++) {
            switch (fuzz_next(7)) {
            case 0: {
                const float r = (float)fuzz_next(5) / 4.0f, g = (float)fuzz_next(5) / 4.0f;
                glColor3f(r, g, 0.3f);
                break;
            }
            case 1: {
                const GLfloat m[4] = { 0.2f, (float)fuzz_next(5) / 4.0f, 0.9f, 1 };
                glMaterialfv(GL_FRONT_AND_BACK, fuzz_next(2) ? GL_AMBIENT_AND_DIFFUSE : GL_EMISSION, m);
                break;
            }
            case 2:
                glNormal3f(0.1f * (float)fuzz_next(5), 0.2f, 0.9f);
                break;
            default:
                break;
            }
            const float x = fuzz_coord(), y = fuzz_coord();
            glVertex2f(x, y);
        }
        glEnd();
    }
}

static void fuzz_state(fc_h *h)
{
    fc_pixel_ortho(h);
    fuzz_seed = 77031u;
    glLineStipple(2, 0x3c6f);
    glEnable(GL_LIGHT0);
    for (int frame = 0; frame < 6; frame++) {
        fcu_clear(0, 0, 0, 0, 1);
        if (frame & 2)
            glEnable(GL_LIGHTING);
        else
            glDisable(GL_LIGHTING);
        for (int l = 10; l < 13; l++) {
            glNewList((GLuint)l, GL_COMPILE);
            fuzz_list2(1);
            glEndList();
        }
        glNewList(1, frame & 1 ? GL_COMPILE_AND_EXECUTE : GL_COMPILE);
        fuzz_list2(0);
        if (frame == 4) {
            glBegin(GL_TRIANGLE_FAN);     /* ended outside the list */
            glVertex2f(32, 32);
            glVertex2f(60, 40);
        }
        glEndList();
        if (frame == 4) {
            glGetError();
            glBegin(GL_TRIANGLE_FAN);
            glVertex2f(32, 32);
            glVertex2f(60, 40);
        }
        glVertex2f(40, 60);
        if (frame == 4)
            glEnd();
        glCallList(1);
        if (frame == 4) {
            glVertex2f(20, 62);
            glEnd();
        }
        fc_get_float(h, "color", GL_CURRENT_COLOR, 4);
        fc_error(h, "frame");
        fc_capture(h);
    }
    glDisable(GL_LIGHTING);
    glDisable(GL_LINE_STIPPLE);
}

/* GL_COMPILE_AND_EXECUTE executes the part of a primitive stored before a
 * new attribute wraps the vertex list: glBegin is executed and glEnd not
 * yet.  Commands executed at once then run through the save table, without
 * the glBegin/glEnd check of the dispatch (only their own, if any). */
static void immediate_inside_begin(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    static const GLfloat v[4][2] = { { 2, 2 }, { 30, 2 }, { 30, 30 }, { 2, 30 } };
    glNewList(1, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_TRIANGLES);
    glVertex2f(2, 2);
    glVertex2f(30, 4);
    glColor3f(1, 0, 0);          /* wraps: glBegin + 2 vertices executed */
    glVertex2f(16, 30);
    glGetError();
    fc_get_integer(h, "get inside", GL_LIST_INDEX, 1);
    fc_error(h, "get");
    glEnableClientState(GL_VERTEX_ARRAY);
    fc_error(h, "enable client state");
    glVertexPointer(2, GL_FLOAT, 0, v);
    fc_error(h, "vertex pointer");
    glPixelStorei(GL_PACK_ALIGNMENT, 2);
    fc_error(h, "pixel store");
    fc_is_enabled(h, "isenabled", GL_VERTEX_ARRAY);
    fc_error(h, "isenabled error");
    GLfloat lv[4] = { 0 };
    glGetLightfv(GL_LIGHT0, GL_DIFFUSE, lv);
    fc_blob(h, "light", lv, sizeof(lv));
    fc_error(h, "getlight");
    GLubyte px[4] = { 9, 9, 9, 9 };
    glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    fc_blob(h, "readpixels", px, sizeof(px));
    fc_error(h, "readpixels error");
    fc_value(h, "genlists", glGenLists(1));
    fc_error(h, "genlists error");
    glEnd();
    glDrawArrays(GL_QUADS, 0, 4);
    glEndList();
    fc_error(h, "endlist");
    fc_get_integer(h, "pack alignment", GL_PACK_ALIGNMENT, 1);
    glDisableClientState(GL_VERTEX_ARRAY);
    fc_capture(h);
}

/* the immediate-mode vertex format keeps an attribute a list set outside
 * glBegin/glEnd: the draw of the list's vertices only copies it to the
 * current values (FLUSH_FOR_DRAW with FLUSH_UPDATE_CURRENT), and the next
 * full flush copies it again, over what the list's last vertex made
 * current; a vertex list wrapped mid-primitive leaves Mesa inside
 * glBegin/glEnd until the next node, which then does not flush */
static void exec_format_current(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    glColor3f(0, 1, 0.5f);
    glBegin(GL_QUAD_STRIP);
    glColor3f(1, 1, 1);
    glVertex3f(1, 1, 0);
    glEnd();
    glEndList();
    glCallList(1);
    fc_get_float(h, "color right after", GL_CURRENT_COLOR, 4);
    glCallList(1);
    glFinish();
    fc_get_float(h, "color after a flush", GL_CURRENT_COLOR, 4);
    glNewList(2, GL_COMPILE);
    glNormal3f(0, 0, 1);
    glBegin(GL_LINE_LOOP);
    glColor3ub(215, 95, 200);
    glEnd();
    glBegin(GL_LINE_LOOP);
    glVertex3f(40.4f, 9.4f, -0.04f);
    glNormal3f(0, 0.5f, 0.8f);   /* wraps the vertex list */
    glVertex3f(9.7f, 13.4f, -0.08f);
    glEnd();
    glEndList();
    glCallList(2);
    fc_get_float(h, "normal right after", GL_CURRENT_NORMAL, 3);
    glCallList(2);
    glLoadIdentity();
    fc_get_float(h, "normal after a flush", GL_CURRENT_NORMAL, 3);
    fc_get_float(h, "color", GL_CURRENT_COLOR, 4);
    fc_capture(h);
}

/* selection and feedback through lists: the name-stack commands and
 * glPassThrough are compiled, glRenderMode, glSelectBuffer and
 * glFeedbackBuffer execute at once; a list's primitives are indexed draws
 * in feedback too */
static void select_feedback(fc_h *h)
{
    fc_pixel_ortho(h);
    static GLuint sel[64];
    static GLfloat fb[256];
    glNewList(1, GL_COMPILE);
    glInitNames();
    glPushName(7);
    glRectf(2, 2, 10, 10);
    glLoadName(8);
    glBegin(GL_TRIANGLES);
    glVertex2f(20, 2);
    glVertex2f(30, 2);
    glVertex2f(25, 12);
    glEnd();
    glPushName(9);
    glPassThrough(5.5f);
    smooth_quad(12, 14, 28, 30);
    glPopName();
    glPopName();
    glPopName();                 /* underflow in GL_SELECT */
    glEndList();
    glNewList(2, GL_COMPILE);
    glSelectBuffer(64, sel);     /* executed now */
    glRenderMode(GL_SELECT);     /* executed now */
    glEndList();
    fc_get_integer(h, "render mode after compile", GL_RENDER_MODE, 1);
    glCallList(2);
    glCallList(1);
    fc_error(h, "select");
    fc_value(h, "hits", glRenderMode(GL_RENDER));
    fc_blob(h, "select buffer", sel, sizeof(sel));
    glFeedbackBuffer(256, GL_3D_COLOR, fb);
    glRenderMode(GL_FEEDBACK);
    glCallList(1);
    fc_value(h, "feedback count", glRenderMode(GL_RENDER));
    fc_blob(h, "feedback buffer", fb, sizeof(fb));
    fc_error(h, "final");
}

/* an attribute outside glBegin/glEnd after more than 8 stored vertices
 * empties the immediate-mode vertex format, so the next glBegin starts a
 * new batch: an empty glBegin/glEnd then hides nothing after it (with 8
 * vertices or fewer it does); the same calls through a
 * GL_COMPILE_AND_EXECUTE list */
static void empty_after_points(fc_h *h)
{
    fc_pixel_ortho(h);
    for (int pass = 0; pass < 3; pass++) {
        fcu_clear(0, 0, 0, 0, 1);
        if (pass == 2)
            glNewList(1, GL_COMPILE_AND_EXECUTE);
        glColor3f(1, 1, 0);
        glBegin(GL_POINTS);
        for (int k = 0; k < (pass == 1 ? 8 : 9); k++)
            glVertex3f(3.0f + 6.0f * (float)k, 60, 0);
        glEnd();
        glNormal3f(0, 0, 1);
        glBegin(GL_TRIANGLE_STRIP);
        glEnd();
        glBegin(GL_TRIANGLE_STRIP);
        glVertex3f(4, 4, 0);
        glVertex3f(40, 6, 0);
        glVertex3f(6, 40, 0);
        glVertex3f(42, 44, 0);
        glEnd();
        if (pass == 2)
            glEndList();
        fc_capture(h);
    }
}

/* ---- colour index and buffer selection compiled ---- */

/* glIndex* are vertex attributes of the vertex-list compiler (also between
 * glBegin/glEnd), glClearIndex, glIndexMask, glDrawBuffer and glReadBuffer
 * are plain compiled commands (save_ClearIndex, save_IndexMask,
 * save_DrawBuffer, save_ReadBuffer); a refused glDrawBuffer is raised at
 * every call, not at compile time */
static void index_buffers(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLuint l = glGenLists(3);
    glNewList(l, GL_COMPILE);
    glIndexf(3.5f);
    glClearIndex(7.0f);
    glIndexMask(0x0f);
    glBegin(GL_TRIANGLES);
    glIndexi(9);
    glColor3f(1, 0, 0);
    glVertex2f(2, 2);
    glIndexs(10);
    glVertex2f(30, 4);
    glIndexub(11);
    glVertex2f(10, 29);
    glEnd();
    glEndList();
    fc_error(h, "compile index list");
    fc_get_float(h, "index not executed", GL_CURRENT_INDEX, 1);
    fc_get_integer(h, "clear index not executed", GL_INDEX_CLEAR_VALUE, 1);
    glCallList(l);
    fc_error(h, "call index list");
    fc_get_float(h, "index after list", GL_CURRENT_INDEX, 1);
    fc_get_integer(h, "clear index after list", GL_INDEX_CLEAR_VALUE, 1);
    fc_get_integer(h, "index mask after list", GL_INDEX_WRITEMASK, 1);
    fc_capture(h);

    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_FRONT_LEFT);
    glDrawBuffer(GL_AUX0);        /* refused when executed */
    glEndList();
    fc_error(h, "compile and execute buffers");
    fc_get_integer(h, "draw buffer", GL_DRAW_BUFFER, 1);
    fc_get_integer(h, "read buffer", GL_READ_BUFFER, 1);
    glDrawBuffer(GL_FRONT);
    glReadBuffer(GL_FRONT);
    glCallList(l + 1);
    fc_error(h, "call buffers list");
    fc_get_integer(h, "draw buffer after call", GL_DRAW_BUFFER, 1);
    fc_get_integer(h, "read buffer after call", GL_READ_BUFFER, 1);
    glTranslatef(30, 30, 0);
    glCallList(l);                /* nothing drawn in colour under GL_NONE */
    fc_capture(h);

    glNewList(l + 2, GL_COMPILE);
    glDrawBuffer(GL_FRONT_AND_BACK);
    glEndList();
    glCallList(l + 2);
    fc_error(h, "call front-and-back list");
    fc_get_integer(h, "draw buffer front and back", GL_DRAW_BUFFER, 1);
    glTranslatef(-20, 0, 0);
    glCallList(l);
    fc_capture(h);
}

const fc_case fc_cases_dlist[] = {
    FC_CASE_RGBA("dlist/basic", 64, 64, 3, "api dlist", basic),
    FC_CASE_RGBA("dlist/quad_diagonal", 64, 64, 2, "api dlist", quad_diagonal),
    FC_CASE_RGBA("dlist/compile_and_execute", 64, 64, 2, "api dlist", compile_and_execute),
    FC_CASE_RGBA("dlist/primitives", 128, 96, 2, "api dlist", primitives),
    FC_CASE_RGBA("dlist/merged_prims", 64, 32, 2, "api dlist polygon_mode", merged_prims),
    FC_CASE_RGBA("dlist/matrices", 64, 64, 2, "api dlist", matrices),
    FC_CASE_RGBA("dlist/lighting", 64, 64, 2, "api dlist lighting", lighting),
    FC_CASE_RGBA("dlist/nesting", 64, 64, 1, "api dlist", nesting),
    FC_CASE_RGBA("dlist/delete_redefine", 32, 32, 1, "api dlist", delete_redefine),
    FC_CASE_RGBA("dlist/call_lists_types", 64, 64, 3, "api dlist", call_lists_types),
    FC_CASE_RGBA("dlist/errors", 32, 32, 0, "api dlist errors query", errors),
    FC_CASE_RGBA("dlist/errors_execute", 32, 32, 0, "api dlist errors", errors_execute),
    FC_CASE_RGBA("dlist/arrays", 64, 64, 2, "api dlist varray", arrays),
    FC_CASE_RGBA("dlist/immediate_commands", 32, 32, 3, "api dlist readpix", immediate_commands),
    FC_CASE_RGBA("dlist/execute_order", 64, 64, 3, "api dlist lighting", execute_order),
    FC_CASE_RGBA("dlist/dangling", 64, 64, 1, "api dlist errors", dangling),
    FC_CASE_RGBA("dlist/upgrade_wrap", 64, 64, 2, "api dlist", upgrade_wrap),
    FC_CASE_RGBA("dlist/current_values", 64, 64, 1, "api dlist query polygon_mode", current_values),
    FC_CASE_RGBA("dlist/more_state", 64, 64, 2, "api dlist fog clip", more_state),
    FC_CASE_RGBA("dlist/attrib_lists", 32, 32, 1, "api dlist attrib", attrib_lists),
    FC_CASE_RGBA("dlist/rects", 64, 32, 1, "api dlist", rects),
    FC_CASE_RGBA("dlist/long_strip", 64, 64, 1, "api dlist", long_strip),
    FC_CASE_RGBA("dlist/line_stipple", 64, 64, 1, "api dlist lines", line_stipple),
    FC_CASE_RGBA("dlist/offset_clip", 64, 64, 2, "api dlist clip lighting", offset_clip),
    FC_CASE_RGBA("dlist/redundant_state", 64, 64, 1, "api dlist lighting", redundant_state),
    FC_CASE_RGBA("dlist/names", 32, 32, 0, "api dlist", names),
    FC_CASE_RGBA("dlist/nested_execute", 64, 64, 3, "api dlist errors", nested_execute),
    FC_CASE_RGBA("dlist/shared_contexts", 32, 32, 2, "api dlist osmesa", shared_contexts),
    FC_CASE_RGBA("dlist/queries", 32, 32, 0, "api dlist query", queries),
    FC_CASE_RGBA("dlist/fuzz", 64, 64, 8, "api dlist polygon_mode lighting", fuzz),
    FC_CASE_RGBA("dlist/empty_primitive", 64, 64, 1, "api dlist vertex", empty_primitive),
    FC_CASE_RGBA("dlist/fuzz_state", 64, 64, 6, "api dlist lighting lines varray", fuzz_state),
    FC_CASE_RGBA("dlist/immediate_inside_begin", 32, 32, 1, "api dlist errors", immediate_inside_begin),
    FC_CASE_RGBA("dlist/exec_format_current", 64, 64, 1, "api dlist query", exec_format_current),
    FC_CASE_RGBA("dlist/select_feedback", 32, 32, 0, "api dlist select feedback", select_feedback),
    FC_CASE_RGBA("dlist/empty_after_points", 64, 64, 3, "api dlist vertex vbo", empty_after_points),
    FC_CASE_RGBA("dlist/index_buffers", 64, 64, 3, "api dlist query", index_buffers),
    { 0 }
};
