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
    { 0 }
};
