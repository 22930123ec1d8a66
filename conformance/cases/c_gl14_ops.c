/* c_gl14_ops.c - GL 1.3/1.4 operations without a new vertex attribute:
 * glBlendFuncSeparate and glBlendEquationSeparate (every factor on each
 * side, the equations with MIN/MAX on one side only, textured and lit
 * draws, the colour buffer without alpha), glMultiDrawArrays and
 * glMultiDrawElements (an empty first draw, index pointers a fraction of
 * an index apart, NULL pointers, lists), GL_INCR_WRAP / GL_DECR_WRAP
 * around 0 and 255, glLoadTransposeMatrix / glMultTransposeMatrix, and
 * glSampleCoverage with the multisample enables (no samples in OSMesa
 * buffers: state only), with their queries, errors, lists and attribute
 * stacks. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

/* glBlendEquationSeparateEXT: not a symbol of the oracle's library (its
 * glapi hands it out by name only) */
typedef void (GLAPIENTRY *blend_eq_sep_fn)(GLenum, GLenum);
static void blend_equation_separate_ext(GLenum rgb, GLenum a)
{
    const blend_eq_sep_fn f = (blend_eq_sep_fn)OSMesaGetProcAddress("glBlendEquationSeparateEXT");
    if (f)
        f(rgb, a);
}

/* ---- separate blending ---- */

static const GLenum bs_factors[15] = {
    GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR,
    GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA,
    GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR,
    GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE,
};

/* A background of smooth colours with varied alpha. */
static void bs_background(void)
{
    glDisable(GL_BLEND);
    glBegin(GL_QUADS);
    glColor4f(0.9f, 0.1f, 0.3f, 0.2f); glVertex2f(0, 0);
    glColor4f(0.1f, 0.8f, 0.2f, 0.9f); glVertex2f(64, 0);
    glColor4f(0.3f, 0.3f, 0.9f, 0.5f); glVertex2f(64, 64);
    glColor4f(0.7f, 0.6f, 0.1f, 0.05f); glVertex2f(0, 64);
    glEnd();
    glEnable(GL_BLEND);
}

/* One smooth quad of cell (cx, cy) of an 8x8 grid of 8x8 cells. */
static void bs_cell(int cx, int cy)
{
    const float x = 8.0f * (float)cx, y = 8.0f * (float)cy;
    glBegin(GL_QUADS);
    glColor4f(0.2f, 0.7f, 0.9f, 0.6f); glVertex2f(x + 1, y + 1);
    glColor4f(0.8f, 0.3f, 0.1f, 0.3f); glVertex2f(x + 7, y + 1);
    glColor4f(0.5f, 0.9f, 0.4f, 1.0f); glVertex2f(x + 7, y + 7);
    glColor4f(0.1f, 0.1f, 0.6f, 0.0f); glVertex2f(x + 1, y + 7);
    glEnd();
}

/* Every rgb source factor against every alpha source factor (with fixed
 * destination factors), then the destination factors likewise: the
 * alpha channel shows in the captured RGBA bytes. */
static void blendsep_factors(fc_h *h)
{
    fc_pixel_ortho(h);
    glBlendColor(0.3f, 0.6f, 0.9f, 0.4f);
    for (int f = 0; f < 4; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        bs_background();
        for (int i = 0; i < 64; i++) {
            const GLenum a = bs_factors[(i + 3 * f) % 15], b = bs_factors[(i / 3 + 5 * f) % 15];
            if (f < 2)
                glBlendFuncSeparate(a, f ? GL_ONE_MINUS_SRC_ALPHA : GL_DST_COLOR, b,
                                    f ? GL_ONE : GL_ONE_MINUS_DST_ALPHA);
            else
                glBlendFuncSeparate(f == 2 ? GL_SRC_ALPHA : GL_ONE, a,
                                    f == 2 ? GL_ONE : GL_CONSTANT_ALPHA, b);
            bs_cell(i % 8, i / 8);
        }
        fc_capture(h);
    }
}

/* The equations apart: every pair of the five, with separate factors;
 * MIN/MAX on one side keep the other side's factors. */
static void blendsep_equations(fc_h *h)
{
    static const GLenum eqs[5] = { GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT,
                                   GL_MIN, GL_MAX };
    fc_pixel_ortho(h);
    for (int f = 0; f < 2; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        bs_background();
        if (f == 0)
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE);
        else
            glBlendFuncSeparateEXT(GL_DST_COLOR, GL_SRC_COLOR, GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA);
        for (int i = 0; i < 25; i++) {
            if (i & 1)
                glBlendEquationSeparate(eqs[i % 5], eqs[i / 5]);
            else
                blend_equation_separate_ext(eqs[i % 5], eqs[i / 5]);
            bs_cell(i % 5, i / 5);
        }
        glBlendEquation(GL_MAX);
        bs_cell(6, 6);
        glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
        bs_cell(6, 7);
        fc_capture(h);
    }
}

/* Separate blending on a textured draw and a lit one (the kernels those
 * states take), and on a colour buffer without alpha. */
static void blendsep_paths(fc_h *h)
{
    static GLubyte tex[4 * 4 * 4];
    for (int i = 0; i < 16; i++) {
        tex[4 * i + 0] = (GLubyte)(i * 16);
        tex[4 * i + 1] = (GLubyte)(255 - i * 12);
        tex[4 * i + 2] = 90;
        tex[4 * i + 3] = (GLubyte)(i * 17);
    }
    fc_pixel_ortho(h);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    fcu_clear(0, 0, 0, 0, 1);
    bs_background();
    /* the common alpha blend on rgb, another on alpha */
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glColor4f(1, 1, 1, 0.8f);
    glTexCoord2f(0, 0); glVertex2f(4, 4);
    glTexCoord2f(1, 0); glVertex2f(60, 4);
    glTexCoord2f(1, 1); glVertex2f(60, 30);
    glTexCoord2f(0, 1); glVertex2f(4, 30);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    const GLfloat diff[4] = { 0.8f, 0.6f, 0.3f, 0.45f };
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diff);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_SRC_ALPHA);
    glBegin(GL_TRIANGLES);
    glNormal3f(0.2f, 0.3f, 1); glVertex2f(2, 34);
    glNormal3f(-0.5f, 0.1f, 1); glVertex2f(62, 36);
    glNormal3f(0, -0.6f, 1); glVertex2f(30, 62);
    glEnd();
    fc_capture(h);
}

/* Points and wide lines (the line kernels) and a depth-tested overlap
 * with separate blending. */
static void blendsep_lines_points(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    bs_background();
    glEnable(GL_DEPTH_TEST);
    glBlendFuncSeparate(GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_DST_ALPHA, GL_ZERO);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_MAX);
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 16; i++) {
        glColor4f((float)(i % 4) / 3.0f, 0.5f, (float)(i / 4) / 3.0f, (float)i / 15.0f);
        glVertex3f(6.0f + 15.0f * (float)(i % 4), 6.0f + 15.0f * (float)(i / 4), 0.1f);
    }
    glEnd();
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE);
    glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_FUNC_ADD);
    glLineWidth(3.0f);
    glBegin(GL_LINES);
    for (int i = 0; i < 8; i++) {
        glColor4f(0.9f, (float)i / 7.0f, 0.2f, 0.25f + 0.1f * (float)i);
        glVertex3f(2.0f, 4.0f + 7.5f * (float)i, -0.2f);
        glColor4f(0.1f, 0.3f, (float)i / 7.0f, 0.9f);
        glVertex3f(62.0f, 60.0f - 7.0f * (float)i, 0.5f);
    }
    glEnd();
    fc_capture(h);
}

/* Errors, queries, lists and the colour buffer group. */
static void blendsep_api(fc_h *h)
{
    fc_get_integer(h, "defaults", GL_BLEND_SRC_RGB, 1);
    fc_get_integer(h, "defaults", GL_BLEND_SRC_ALPHA, 1);
    fc_get_integer(h, "defaults", GL_BLEND_DST_RGB, 1);
    fc_get_integer(h, "defaults", GL_BLEND_DST_ALPHA, 1);
    fc_get_integer(h, "defaults", GL_BLEND_EQUATION_RGB, 1);
    fc_get_integer(h, "defaults", GL_BLEND_EQUATION_ALPHA, 1);
    glBlendFuncSeparate(GL_SRC_COLOR, GL_DST_ALPHA, GL_CONSTANT_COLOR, GL_SRC_ALPHA_SATURATE);
    fc_error(h, "func separate");
    fc_get_integer(h, "separate", GL_BLEND_SRC, 1);
    fc_get_integer(h, "separate", GL_BLEND_DST, 1);
    fc_get_integer(h, "separate", GL_BLEND_SRC_ALPHA, 1);
    fc_get_integer(h, "separate", GL_BLEND_DST_ALPHA, 1);
    glBlendFuncSeparate(GL_SRC_COLOR, GL_DST_ALPHA, GL_CONSTANT_COLOR, GL_SRC_ALPHA_SATURATE);
    fc_error(h, "func unchanged");
    static const GLenum bad[4][4] = {
        { GL_ZERO, GL_ONE, GL_ZERO, GL_LINE }, { GL_BLEND, GL_ONE, GL_ONE, GL_ONE },
        { GL_ONE, GL_ONE, GL_FUNC_ADD, GL_ONE }, { GL_ONE, 0x1234, GL_ONE, GL_ONE },
    };
    for (int i = 0; i < 4; i++) {
        char label[32];
        snprintf(label, sizeof label, "bad factor %d", i);
        glBlendFuncSeparate(bad[i][0], bad[i][1], bad[i][2], bad[i][3]);
        fc_error(h, label);
        fc_get_integer(h, label, GL_BLEND_DST_ALPHA, 1);
    }
    glBlendFunc(GL_ONE, GL_ONE);
    fc_get_integer(h, "func resets alpha", GL_BLEND_SRC_ALPHA, 1);
    fc_get_integer(h, "func resets alpha", GL_BLEND_DST_ALPHA, 1);
    glBlendEquationSeparate(GL_MIN, GL_FUNC_REVERSE_SUBTRACT);
    fc_error(h, "equation separate");
    fc_get_integer(h, "equation separate", GL_BLEND_EQUATION_RGB, 1);
    fc_get_integer(h, "equation separate", GL_BLEND_EQUATION_ALPHA, 1);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_LOGIC_OP);
    fc_error(h, "bad alpha equation");
    glBlendEquationSeparate(GL_ZERO, GL_FUNC_ADD);
    fc_error(h, "bad rgb equation");
    fc_get_integer(h, "after bad", GL_BLEND_EQUATION_ALPHA, 1);
    glBlendEquation(GL_MAX);
    fc_get_integer(h, "equation resets alpha", GL_BLEND_EQUATION_ALPHA, 1);
    /* GL_COLOR_BUFFER_BIT */
    glBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ONE_MINUS_DST_ALPHA, GL_DST_COLOR);
    glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
    glPushAttrib(GL_COLOR_BUFFER_BIT);
    glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
    glPopAttrib();
    fc_get_integer(h, "popped", GL_BLEND_SRC_RGB, 1);
    fc_get_integer(h, "popped", GL_BLEND_DST_ALPHA, 1);
    fc_get_integer(h, "popped", GL_BLEND_EQUATION_RGB, 1);
    fc_get_integer(h, "popped", GL_BLEND_EQUATION_ALPHA, 1);
    /* compiled */
    const GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glBlendFuncSeparate(GL_DST_ALPHA, GL_ZERO, GL_ONE, GL_SRC_COLOR);
    blend_equation_separate_ext(GL_FUNC_REVERSE_SUBTRACT, GL_MIN);
    glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_LINE);
    glEndList();
    fc_error(h, "compile");
    fc_get_integer(h, "compiled only", GL_BLEND_SRC_RGB, 1);
    glCallList(l);
    fc_error(h, "call");
    fc_get_integer(h, "called", GL_BLEND_SRC_RGB, 1);
    fc_get_integer(h, "called", GL_BLEND_DST_ALPHA, 1);
    fc_get_integer(h, "called", GL_BLEND_EQUATION_ALPHA, 1);
    glDeleteLists(l, 1);
    glBegin(GL_POINTS);
    glBlendFuncSeparate(GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
    glEnd();
    fc_error(h, "inside begin");
}

/* ---- multi-draws ---- */

static GLfloat md_pos[64][2];
static GLfloat md_col[64][4];

static void md_arrays(fc_h *h)
{
    fc_pixel_ortho(h);
    for (int i = 0; i < 64; i++) {
        md_pos[i][0] = 4.0f + 7.0f * (float)(i % 8) + (float)((i * 5) % 3);
        md_pos[i][1] = 4.0f + 7.0f * (float)(i / 8) + (float)((i * 7) % 4);
        md_col[i][0] = (float)(i % 4) / 3.0f;
        md_col[i][1] = (float)((i / 4) % 4) / 3.0f;
        md_col[i][2] = (float)(i % 7) / 6.0f;
        md_col[i][3] = 1.0f;
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, md_pos);
    glColorPointer(4, GL_FLOAT, 0, md_col);
}

/* Triangles, strips, fans and line strips in several draws, a draw with
 * a partial primitive, an empty draw in the middle, and an empty first
 * draw (the oracle draws none of the call then). */
static void multidraw_arrays(fc_h *h)
{
    md_arrays(h);
    static const GLint first[5][4] = {
        { 0, 9, 20, 40 }, { 0, 16, 30, 48 }, { 8, 3, 50, 20 }, { 0, 12, 24, 36 }, { 5, 10, 30, 44 },
    };
    static const GLsizei count[5][4] = {
        { 6, 7, 12, 3 }, { 8, 0, 9, 10 }, { 5, 6, 7, 4 }, { 0, 9, 9, 9 }, { 3, 3, 0, 9 },
    };
    static const GLenum modes[5] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                     GL_TRIANGLES, GL_LINE_STRIP };
    for (int f = 0; f < 5; f++) {
        fcu_clear(0, 0, 0, 1, 1);
        if (f == 2)
            glMultiDrawArraysEXT(modes[f], first[f], count[f], 4);
        else
            glMultiDrawArrays(modes[f], first[f], count[f], 4);
        fc_error(h, "multidraw");
        fc_capture(h);
    }
}

/* Index lists of each type, pointers in one array and apart, a pointer a
 * fraction of an index from the others, an empty first draw with both
 * layouts, a NULL pointer. */
static void multidraw_elements(fc_h *h)
{
    md_arrays(h);
    static GLubyte ib[32];
    static GLushort is[34];
    static GLuint iu[32];
    /* read a byte off, its unsigned shorts are the odd bytes: small */
    static GLubyte odd[40];
    for (int i = 0; i < 40; i++)
        odd[i] = (GLubyte)((i & 1) ? (i * 7) % 64 : 0);
    for (int i = 0; i < 32; i++) {
        ib[i] = (GLubyte)((i * 13) % 64);
        is[i + 1] = (GLushort)((i * 29 + 3) % 64);
        iu[i] = (GLuint)((i * 11 + 7) % 64);
    }
    is[0] = 1;
    static const GLsizei cnt[4] = { 6, 9, 3, 12 };
    static const GLsizei cnt0[4] = { 0, 9, 3, 12 };
    for (int f = 0; f < 6; f++) {
        fcu_clear(0, 0, 0, 1, 1);
        switch (f) {
        case 0: {
            const GLvoid *p[4] = { ib, ib + 6, ib + 15, ib + 18 };
            glMultiDrawElements(GL_TRIANGLES, cnt, GL_UNSIGNED_BYTE, p, 4);
            break;
        }
        case 1: {
            const GLvoid *p[4] = { is + 1, is + 7, is + 20, is + 4 };
            glMultiDrawElementsEXT(GL_TRIANGLE_STRIP, cnt, GL_UNSIGNED_SHORT, p, 4);
            break;
        }
        case 2: {
            const GLvoid *p[4] = { iu, iu + 10, iu + 3, iu + 16 };
            glMultiDrawElements(GL_TRIANGLES, cnt0, GL_UNSIGNED_INT, p, 4);
            break;
        }
        case 3: {
            /* one pointer a byte off: one call per draw, the first empty */
            const GLvoid *p[4] = { is + 1, odd + 1, is + 12, is + 20 };
            glMultiDrawElements(GL_TRIANGLES, cnt0, GL_UNSIGNED_SHORT, p, 4);
            break;
        }
        case 4: {
            const GLvoid *p[4] = { iu, iu + 10, NULL, iu + 16 };
            glMultiDrawElements(GL_TRIANGLES, cnt, GL_UNSIGNED_INT, p, 4);
            break;
        }
        default: {
            const GLvoid *p[4] = { is + 1, odd + 1, is + 12, is + 20 };
            glMultiDrawElements(GL_LINE_LOOP, cnt, GL_UNSIGNED_SHORT, p, 4);
            break;
        }
        }
        fc_error(h, "multidraw elements");
        fc_capture(h);
    }
}

/* One driver call of several draws is one llvmpipe draw: the polygon
 * stipple stage binds its shader at the first filled triangle of the
 * call and keeps it to the call's end, so the points an unfilled back
 * face makes in a later draw of the call are stippled too (random-raster
 * s5-i59); fixgl drew each draw as a draw of its own.  Frames: a filled
 * quad, then back faces as points, one call; the back faces first; the
 * same as glMultiDrawArrays. */
static void multidraw_pstipple_points(fc_h *h)
{
    md_arrays(h);
    static GLubyte stip[128];
    for (int i = 0; i < 128; i++)
        stip[i] = (GLubyte)((i / 4) % 2 ? 0xaa : 0x55);
    glPolygonStipple(stip);
    glEnable(GL_POLYGON_STIPPLE);
    glPolygonMode(GL_FRONT, GL_FILL);
    glPolygonMode(GL_BACK, GL_POINT);
    glPointSize(5.0f);
    /* a front quad (counter-clockwise) and two back ones */
    static const GLubyte front[4] = { 0, 1, 9, 8 };
    static const GLubyte back1[4] = { 18, 26, 27, 19 };
    static const GLubyte back2[4] = { 36, 44, 45, 37 };
    static const GLsizei cnt[3] = { 4, 4, 4 };
    for (int f = 0; f < 2; f++) {
        fcu_clear(0, 0, 0, 1, 1);
        const GLvoid *p[3] = { f == 0 ? front : back1, f == 0 ? back1 : front, back2 };
        glMultiDrawElements(GL_QUADS, cnt, GL_UNSIGNED_BYTE, p, 3);
        fc_error(h, "multidraw elements");
        fc_capture(h);
    }
    /* the same quads as arrays: front, back, back */
    static GLfloat qv[12][2];
    static GLfloat qc[12][4];
    const GLubyte *q[3] = { front, back1, back2 };
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 4; j++) {
            memcpy(qv[4 * k + j], md_pos[q[k][j]], sizeof(qv[0]));
            memcpy(qc[4 * k + j], md_col[q[k][j]], sizeof(qc[0]));
        }
    glVertexPointer(2, GL_FLOAT, 0, qv);
    glColorPointer(4, GL_FLOAT, 0, qc);
    static const GLint first[3] = { 0, 4, 8 };
    fcu_clear(0, 0, 0, 1, 1);
    glMultiDrawArrays(GL_QUADS, first, cnt, 3);
    fc_error(h, "multidraw arrays");
    fc_capture(h);
}

/* Compiled into lists (each non-empty draw a compiled draw), and the
 * errors of both calls. */
static void multidraw_dlist_errors(fc_h *h)
{
    md_arrays(h);
    static const GLint first[3] = { 0, 10, 30 };
    static const GLsizei count[3] = { 6, 0, 9 };
    static const GLsizei bad[3] = { 6, -1, 9 };
    static const GLubyte idx[12] = { 0, 9, 18, 27, 36, 45, 1, 10, 19, 28, 37, 46 };
    static const GLsizei ecount[2] = { 6, 6 };
    const GLvoid *eptr[2] = { idx, idx + 6 };
    const GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glMultiDrawArrays(GL_TRIANGLES, first, count, 3);
    glMultiDrawElements(GL_LINE_STRIP, ecount, GL_UNSIGNED_BYTE, eptr, 2);
    glMultiDrawArrays(GL_TRIANGLES, first, bad, 3);
    glMultiDrawArrays(GL_QUADS + 20, first, count, 3);
    glMultiDrawArrays(GL_TRIANGLES, first, count, -2);
    glEndList();
    fc_error(h, "compile");
    fcu_clear(0, 0, 0, 1, 1);
    glCallList(l);
    fc_error(h, "call");
    fc_capture(h);
    glDeleteLists(l, 1);
    glMultiDrawArrays(GL_TRIANGLES, first, bad, 3);
    fc_error(h, "negative count");
    glMultiDrawArrays(GL_TRIANGLES, first, count, -1);
    fc_error(h, "negative draw count");
    glMultiDrawArrays(0x1234, first, count, 3);
    fc_error(h, "bad mode");
    glMultiDrawArrays(0x1234, first, bad, 3);
    fc_error(h, "bad mode and count");
    glMultiDrawArrays(0x1234, first, count, -1);
    fc_error(h, "bad mode and draw count");
    glMultiDrawArrays(GL_TRIANGLES, first, bad, -1);
    fc_error(h, "bad draw count and count");
    glMultiDrawArrays(GL_TRIANGLES, first, count, 0);
    fc_error(h, "no draws");
    glMultiDrawElements(0x1234, bad, GL_UNSIGNED_BYTE, eptr, 2);
    fc_error(h, "elements bad mode and count");
    glMultiDrawElements(GL_TRIANGLES, bad, GL_FLOAT, eptr, 2);
    fc_error(h, "elements bad count and type");
    glMultiDrawElements(GL_TRIANGLES, ecount, GL_FLOAT, eptr, -1);
    fc_error(h, "elements bad type and draw count");
    glMultiDrawElements(0x1234, ecount, GL_UNSIGNED_BYTE, eptr, -1);
    fc_error(h, "elements bad mode and draw count");
    glMultiDrawElements(GL_TRIANGLES, ecount, GL_FLOAT, eptr, 2);
    fc_error(h, "bad type");
    glMultiDrawElements(0x1234, ecount, GL_FLOAT, eptr, 2);
    fc_error(h, "bad mode and type");
    glMultiDrawElements(GL_TRIANGLES, bad, GL_UNSIGNED_BYTE, eptr, 2);
    fc_error(h, "elements negative count");
    glMultiDrawElements(GL_TRIANGLES, ecount, GL_UNSIGNED_BYTE, eptr, -3);
    fc_error(h, "elements negative draw count");
    glBegin(GL_TRIANGLES);
    glMultiDrawArrays(GL_TRIANGLES, first, count, 3);
    glEnd();
    fc_error(h, "inside begin");
}

/* ---- stencil wrap ---- */

static void stencil_wrap(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(254);
    glClear(GL_STENCIL_BUFFER_BIT);
    fcu_clear(0, 0, 0, 1, 1);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    /* overlapping rects: INCR_WRAP three times (254 -> 1), DECR_WRAP on
     * cleared 254 and on wrapped values, INCR and DECR for contrast */
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    for (int k = 0; k < 3; k++)
        fcu_rect(2, 2 + 4 * (float)k, 30, 30, 0);
    glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    for (int k = 0; k < 3; k++)
        fcu_rect(20 + 4 * (float)k, 10, 46, 46, 0);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    fcu_rect(2, 36, 14, 46, 0);
    fcu_rect(2, 36, 14, 46, 0);
    glStencilOp(GL_INCR_WRAP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_NEVER, 0, 0xff);
    fcu_rect(36, 2, 46, 8, 0);
    glStencilMask(0x0f);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    fcu_rect(8, 8, 40, 16, 0);
    glStencilMask(0xff);
    /* show the values */
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    static const GLint vals[8] = { 0, 1, 255, 254, 253, 252, 251, 244 };
    for (int i = 0; i < 8; i++) {
        glStencilFunc(GL_EQUAL, vals[i], 0xff);
        fcu_color(i + 1);
        fcu_rect(0, 0, 48, 48, 0);
    }
    fc_get_integer(h, "ops", GL_STENCIL_FAIL, 1);
    glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INCR_WRAP + 5);
    fc_error(h, "bad op");
    fc_capture(h);
}

/* ---- transpose matrices ---- */

static void transpose(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    static const GLfloat pf[16] = {
        0.8f, 0.0f, 0.0f, 0.0f,  0.0f, 0.9f, 0.0f, 0.0f,
        0.0f, 0.0f, -1.1f, -1.0f,  0.0f, 0.0f, -1.0f, 0.0f,
    };
    static const GLdouble md[16] = {
        0.9, -0.3, 0.1, 0.05,  0.25, 0.8, -0.2, -0.1,  0.1, 0.2, 0.95, -2.5,  0, 0, 0, 1,
    };
    static const GLfloat rf[16] = {
        0.98f, -0.2f, 0.0f, 0.1f,  0.2f, 0.98f, 0.0f, 0.0f,  0.0f, 0.0f, 1.0f, 0.0f,  0, 0, 0, 1,
    };
    glMatrixMode(GL_PROJECTION);
    glLoadTransposeMatrixf(pf);
    fc_get_float(h, "projection", GL_PROJECTION_MATRIX, 16);
    fc_get_float(h, "projection", GL_TRANSPOSE_PROJECTION_MATRIX, 16);
    glMatrixMode(GL_MODELVIEW);
    glLoadTransposeMatrixd(md);
    glMultTransposeMatrixf(rf);
    fc_get_float(h, "modelview", GL_MODELVIEW_MATRIX, 16);
    fc_get_double(h, "modelview", GL_TRANSPOSE_MODELVIEW_MATRIX, 16);
    fcu_clear(0, 0, 0, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(-1, -1, 0);
    glColor3f(0, 1, 0); glVertex3f(1, -0.8f, 0.3f);
    glColor3f(0, 0, 1); glVertex3f(0, 1, -0.4f);
    glEnd();
    fc_capture(h);
    /* the same through a list and the ARB names */
    const GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glLoadTransposeMatrixdARB(md);
    glMultTransposeMatrixdARB(md);
    glMultTransposeMatrixfARB(rf);
    glEndList();
    glLoadTransposeMatrixfARB(rf);
    fc_get_float(h, "arb", GL_MODELVIEW_MATRIX, 16);
    glCallList(l);
    fc_get_float(h, "list", GL_MODELVIEW_MATRIX, 16);
    glDeleteLists(l, 1);
    fcu_clear(0, 0, 0, 1, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 0); glVertex3f(-1, -1, 0);
    glColor3f(0, 1, 1); glVertex3f(1, -0.8f, 0.3f);
    glColor3f(1, 0, 1); glVertex3f(0, 1, -0.4f);
    glEnd();
    fc_capture(h);
    glMatrixMode(GL_TEXTURE);
    glMultTransposeMatrixd(md);
    fc_get_float(h, "texture", GL_TRANSPOSE_TEXTURE_MATRIX, 16);
    glBegin(GL_POINTS);
    glLoadTransposeMatrixf(pf);
    glEnd();
    fc_error(h, "inside begin");
    fc_get_float(h, "after begin", GL_TEXTURE_MATRIX, 16);
}

/* ---- multisample state ---- */

static void multisample_state(fc_h *h)
{
    static const GLenum caps[4] = { GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE,
                                    GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE };
    for (int i = 0; i < 4; i++)
        fc_is_enabled(h, "default", caps[i]);
    fc_get_float(h, "default", GL_SAMPLE_COVERAGE_VALUE, 1);
    fc_get_integer(h, "default", GL_SAMPLE_COVERAGE_INVERT, 1);
    fc_get_integer(h, "default", GL_SAMPLE_BUFFERS, 1);
    fc_get_integer(h, "default", GL_SAMPLES, 1);
    static const float vals[5] = { 0.25f, -3.0f, 7.0f, 0.0f, 1.0f };
    static const GLboolean inv[5] = { GL_TRUE, GL_FALSE, 2, GL_TRUE, GL_FALSE };
    for (int i = 0; i < 5; i++) {
        char label[32];
        snprintf(label, sizeof label, "coverage %d", i);
        if (i == 2)
            glSampleCoverageARB(vals[i], inv[i]);
        else
            glSampleCoverage(vals[i], inv[i]);
        fc_error(h, label);
        fc_get_float(h, label, GL_SAMPLE_COVERAGE_VALUE, 1);
        fc_get_integer(h, label, GL_SAMPLE_COVERAGE_INVERT, 1);
        fc_get_boolean(h, label, GL_SAMPLE_COVERAGE_INVERT, 1);
    }
    glSampleCoverage(NAN, GL_FALSE);
    fc_get_boolean(h, "nan", GL_SAMPLE_COVERAGE_VALUE, 1);
    glSampleCoverage(0.5f, GL_TRUE);
    for (int i = 0; i < 4; i++)
        glEnable(caps[i]);
    glPushAttrib(GL_MULTISAMPLE_BIT);
    glSampleCoverage(0.75f, GL_FALSE);
    for (int i = 0; i < 4; i++)
        glDisable(caps[i]);
    glPopAttrib();
    for (int i = 0; i < 4; i++)
        fc_is_enabled(h, "popped", caps[i]);
    fc_get_float(h, "popped", GL_SAMPLE_COVERAGE_VALUE, 1);
    fc_get_integer(h, "popped", GL_SAMPLE_COVERAGE_INVERT, 1);
    glPushAttrib(GL_ENABLE_BIT);
    for (int i = 0; i < 4; i++)
        glDisable(caps[i]);
    glPopAttrib();
    for (int i = 0; i < 4; i++)
        fc_is_enabled(h, "enable popped", caps[i]);
    const GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glSampleCoverage(0.125f, GL_FALSE);
    glEndList();
    fc_get_float(h, "compiled", GL_SAMPLE_COVERAGE_VALUE, 1);
    glCallList(l);
    fc_get_float(h, "called", GL_SAMPLE_COVERAGE_VALUE, 1);
    glDeleteLists(l, 1);
    glBegin(GL_POINTS);
    glSampleCoverage(0.3f, GL_TRUE);
    glEnd();
    fc_error(h, "inside begin");
    /* drawing with every multisample enable on changes nothing */
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0.5f, 0.2f, 0.3f); glVertex2f(2, 2);
    glColor4f(0.2f, 1, 0.5f, 0.7f); glVertex2f(30, 4);
    glColor4f(0.5f, 0.2f, 1, 0.1f); glVertex2f(10, 30);
    glEnd();
    fc_capture(h);
}

/* The logic op wins over separate blending; the colour mask over it. */
static void blendsep_logicop_mask(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    bs_background();
    glBlendFuncSeparate(GL_SRC_COLOR, GL_ONE, GL_ZERO, GL_DST_ALPHA);
    glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
    for (int i = 0; i < 16; i++) {
        if (i == 4)
            glEnable(GL_COLOR_LOGIC_OP);
        if (i == 8) {
            glDisable(GL_COLOR_LOGIC_OP);
            glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        }
        if (i == 12)
            glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
        glLogicOp(GL_XOR + (GLenum)(i % 3));
        bs_cell(i % 8, i / 8 + 2 * (i / 8));
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    fc_capture(h);
}

/* Points, line strips and quads in multi-draws; a draw whose count
 * leaves a partial primitive. */
static void multidraw_modes(fc_h *h)
{
    md_arrays(h);
    static const GLint first[3] = { 0, 20, 41 };
    static const GLsizei count[3] = { 9, 11, 7 };
    static const GLenum modes[4] = { GL_POINTS, GL_LINE_LOOP, GL_QUADS, GL_QUAD_STRIP };
    glPointSize(3);
    for (int f = 0; f < 4; f++) {
        fcu_clear(0, 0, 0, 1, 1);
        glMultiDrawArrays(modes[f], first, count, 3);
        fc_capture(h);
    }
}

/* The wrap operations under a value mask and a partial write mask, and
 * on the depth-fail path. */
static void stencil_wrap_masks(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    fcu_clear(0, 0, 0, 1, 1);
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilMask(0x3f);
    glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    fcu_rect(2, 2, 40, 40, 0);           /* 0 -> 255 masked to 0x3f */
    glStencilMask(0xff);
    glStencilOp(GL_KEEP, GL_INCR_WRAP, GL_DECR_WRAP);
    glDepthFunc(GL_LESS);
    fcu_rect(10, 10, 46, 30, 0.5f);      /* depth fails over the first: INCR_WRAP */
    fcu_rect(20, 0, 30, 46, -0.5f);      /* passes: DECR_WRAP */
    glDepthFunc(GL_ALWAYS);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    static const GLint vals[6] = { 0x3f, 0x40, 0x3e, 0xff, 0x00, 0x3d };
    for (int i = 0; i < 6; i++) {
        glStencilFunc(GL_EQUAL, vals[i], i == 5 ? 0x0f : 0xff);
        fcu_color(i + 2);
        fcu_rect(0, 0, 48, 48, 0);
    }
    fc_capture(h);
}

/* Found by the fuzzer (seeds 5 and 50 of the campaign with the GL 1.4
 * table): queries between a compiled glBegin and glEnd run (the save
 * dispatch has no begin/end check), so their own errors show. */
static void get_in_compiled_begin(fc_h *h)
{
    GLfloat f[16];
    GLdouble d[16];
    const GLuint l = glGenLists(1);
    for (int mode = 0; mode < 2; mode++) {
        glNewList(l, mode ? GL_COMPILE_AND_EXECUTE : GL_COMPILE);
        glBegin(GL_TRIANGLES);
        glVertex2i(2, 12);
        glGetTexParameterfv(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WRAP_R, f);
        fc_error(h, mode ? "tex parameter, compile and execute" : "tex parameter, compile");
        glGetTexGendv(GL_S + 0x1000, GL_OBJECT_PLANE, d);
        fc_error(h, mode ? "texgen, compile and execute" : "texgen, compile");
        glGetTexGendv(GL_S, GL_OBJECT_PLANE, d);
        fc_error(h, "texgen valid");
        glEnd();
        glEndList();
        fc_error(h, "end");
    }
    glBegin(GL_TRIANGLES);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, f);
    fc_error(h, "tex parameter inside begin");
    glGetTexGendv(GL_S, GL_OBJECT_PLANE, d);
    fc_error(h, "texgen inside begin");
    glEnd();
    glDeleteLists(l, 1);
}

/* Found by the fuzzer (seed 43): glEvalCoord outside glBegin/glEnd puts
 * the evaluated attributes in the immediate-mode vertex format, which a
 * query's flush keeps; an array draw after it must not read it. */
static void draw_after_eval_format(fc_h *h)
{
    md_arrays(h);
    glDisableClientState(GL_COLOR_ARRAY);
    glColor3f(0.9f, 0.8f, 0.2f);
    static const GLfloat cp[4][4] = { { 1, 0, 0, 1 }, { 0, 1, 0, 1 }, { 0, 0, 1, 1 }, { 1, 1, 1, 1 } };
    glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &cp[0][0]);
    glEnable(GL_MAP2_COLOR_4);
    static const GLushort idx[8] = { 0, 9, 18, 27, 36, 45, 54, 63 };
    for (int f = 0; f < 2; f++) {
        fcu_clear(0, 0, 0, 1, 1);
        glEvalCoord2f(0.25f, 0.75f);
        if (f) {
            GLfloat c[4];
            glGetFloatv(GL_CURRENT_COLOR, c);
        }
        glDrawElements(GL_LINES, 8, GL_UNSIGNED_SHORT, idx);
        glDrawArrays(GL_TRIANGLES, 0, 6);
        fc_capture(h);
    }
}

const fc_case fc_cases_gl14_ops[] = {
    FC_CASE_RGBA("gl14/blendsep_factors", 64, 64, 4, "gl14 blendsep fragment", blendsep_factors),
    FC_CASE_RGBA("gl14/blendsep_equations", 64, 64, 2, "gl14 blendsep fragment", blendsep_equations),
    FC_CASE_RGBA("gl14/blendsep_paths", 64, 64, 1, "gl14 blendsep fragment texture lighting",
                 blendsep_paths),
    FC_CASE_RGBA("gl14/blendsep_lines_points", 64, 64, 1, "gl14 blendsep fragment points",
                 blendsep_lines_points),
    FC_CASE_RGBA("gl14/blendsep_api", 8, 8, 0, "gl14 blendsep api error dlist attrib", blendsep_api),
    FC_CASE_RGBA("gl14/multidraw_arrays", 64, 64, 5, "gl14 multidraw varray", multidraw_arrays),
    FC_CASE_RGBA("gl14/multidraw_elements", 64, 64, 6, "gl14 multidraw varray", multidraw_elements),
    FC_CASE_RGBA("gl14/multidraw_pstipple_points", 64, 64, 3, "gl14 multidraw varray",
                 multidraw_pstipple_points),
    FC_CASE_RGBA("gl14/multidraw_dlist_errors", 64, 64, 1, "gl14 multidraw varray dlist error",
                 multidraw_dlist_errors),
    FC_CASE("gl14/stencil_wrap", 48, 48, OSMESA_RGBA, 24, 8, 1, "gl14 stencilwrap fragment",
            stencil_wrap),
    FC_CASE_RGBA("gl13/transpose", 48, 48, 2, "gl13 transpose matrix dlist", transpose),
    FC_CASE_RGBA("gl14/blendsep_logicop_mask", 64, 64, 1, "gl14 blendsep fragment",
                 blendsep_logicop_mask),
    FC_CASE_RGBA("dlist/get_in_compiled_begin", 8, 8, 0, "dlist error texture", get_in_compiled_begin),
    FC_CASE_RGBA("varray/draw_after_eval_format", 64, 64, 2, "varray eval", draw_after_eval_format),
    FC_CASE_RGBA("gl14/multidraw_modes", 64, 64, 4, "gl14 multidraw varray", multidraw_modes),
    FC_CASE("gl14/stencil_wrap_masks", 48, 48, OSMESA_RGBA, 24, 8, 1, "gl14 stencilwrap fragment",
            stencil_wrap_masks),
    FC_CASE_RGBA("gl13/multisample_state", 32, 32, 1, "gl13 multisample api attrib dlist",
                 multisample_state),
    { 0 },
};
