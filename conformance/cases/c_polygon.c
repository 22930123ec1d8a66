/* c_polygon.c - polygon state: glRect, glEdgeFlag, glPolygonMode state,
 * polygon offset (llvmpipe's setup and draw's offset stage, 16/24-bit
 * depth), polygon stipple, user clip planes and culling of every filled
 * primitive type, with the errors and queries of each entry point.
 * (glPolygonMode GL_LINE/GL_POINT rendering: c_polygon_mode.c.) */
#include "cases.h"
#include "lt_util.h"

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* ---- helpers ------------------------------------------------------------ */

/* Smooth triangle with per-vertex colours and depths. */
static void tri3(const float v[3][3], int c)
{
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; i++) {
        fcu_color(c + i);
        glVertex3fv(v[i]);
    }
    glEnd();
}

/* One primitive of each filled type, in window coordinates of a 32x32
 * buffer, smooth colours from the palette. */
static void draw_prim(GLenum mode)
{
    const float (*v)[2];
    int n;
    switch (mode) {
    case GL_TRIANGLES: v = fcu_tri_v; n = 6; break;
    case GL_TRIANGLE_STRIP: v = fcu_strip_v; n = 8; break;
    case GL_TRIANGLE_FAN: v = fcu_fan_v; n = 7; break;
    case GL_QUADS: v = fcu_quads_v; n = 8; break;
    case GL_QUAD_STRIP: v = fcu_qstrip_v; n = 8; break;
    default: v = fcu_poly_v; n = 6; break;
    }
    glBegin(mode);
    for (int i = 0; i < n; i++) {
        fcu_color(i);
        glVertex2fv(v[i]);
    }
    glEnd();
}

static void make_pattern(GLubyte p[128], int kind);

/* ---- GL_POLYGON_SMOOTH ---------------------------------------------------- */

/* GL_POLYGON_SMOOTH, as legacy antialiasing demos use it (with
 * SRC_ALPHA_SATURATE/ONE blending, front to back): the state tracker passes
 * it on as pipe_rasterizer_state.poly_smooth, which neither llvmpipe nor the
 * draw module reads, so polygons stay aliased; the enable and its query
 * still work. */
static void polygon_smooth(fc_h *h)
{
    static const GLenum modes[6] = {
        GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON,
    };
    fc_pixel_ortho(h);
    fc_is_enabled(h, "GL_POLYGON_SMOOTH default", GL_POLYGON_SMOOTH);
    glEnable(GL_POLYGON_SMOOTH);
    fc_is_enabled(h, "GL_POLYGON_SMOOTH on", GL_POLYGON_SMOOTH);
    glHint(GL_POLYGON_SMOOTH_HINT, GL_NICEST);
    for (int m = 0; m < 6; m++) {
        fcu_clear(0, 0, 0, 0, 1);
        glDisable(GL_BLEND);
        draw_prim(modes[m]);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);
        glTranslatef(0.37f, 0.21f, 0.0f);
        draw_prim(modes[m]);
        glLoadIdentity();
        fc_capture(h);
    }
    glDisable(GL_POLYGON_SMOOTH);
    fc_is_enabled(h, "GL_POLYGON_SMOOTH off", GL_POLYGON_SMOOTH);
    fc_error(h, "final");
}

/* ---- glRect --------------------------------------------------------------- */

/* Every glRect variant, corners in both orders, fractional corners. */
static void rect_variants(fc_h *h)
{
    static const GLshort s1[2] = { 1, 1 }, s2[2] = { 9, 7 };
    static const GLint i1[2] = { 11, 1 }, i2[2] = { 21, 9 };
    static const GLfloat f1[2] = { 23.25f, 1.5f }, f2[2] = { 30.75f, 10.5f };
    static const GLdouble d1[2] = { 9.5, 30.25 }, d2[2] = { 1.125, 21.75 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    fcu_color(0); glRects(1, 1, 9, 7);
    fcu_color(1); glRecti(21, 9, 11, 1);            /* reversed x and y */
    fcu_color(2); glRectf(1.5f, 12.5f, 9.25f, 19.75f);
    fcu_color(3); glRectd(21.75, 12.5, 11.5, 19.5);  /* reversed x */
    fcu_color(4); glRectf(23.5f, 19.5f, 30.5f, 12.5f); /* reversed y */
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    fcu_color(5); glRectsv(s1, s2);
    fcu_color(6); glRectiv(i1, i2);
    fcu_color(7); glRectfv(f1, f2);
    fcu_color(8); glRectdv(d1, d2);                 /* reversed x and y */
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    fcu_color(9); glVertex2f(12, 12); fcu_color(10); glVertex2f(30, 14); fcu_color(11); glVertex2f(20, 30);
    glEnd();
    fc_capture(h);
}

/* Reversed rectangles are clockwise: culled as back faces, drawn with
 * GL_FRONT culling; a glRect between glBegin/glEnd is an error. */
static void rect_cull_errors(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_CULL_FACE);
    fcu_color(0); glRectf(2, 2, 14, 14);
    fcu_color(1); glRectf(30, 2, 18, 14);           /* clockwise: culled */
    fcu_color(2); glRectf(2, 30, 14, 18);           /* clockwise: culled */
    fcu_color(3); glRectf(30, 30, 18, 18);          /* counter-clockwise */
    fc_capture(h);
    glCullFace(GL_FRONT);
    fcu_clear(0, 0, 0, 0, 1);
    fcu_color(0); glRectf(2, 2, 14, 14);
    fcu_color(1); glRecti(30, 2, 18, 14);
    fcu_color(2); glRectd(2, 30, 14, 18);
    fcu_color(3); glRects(30, 30, 18, 18);
    fc_capture(h);
    glDisable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES);
    glRectf(0, 0, 4, 4);
    glVertex2f(0, 0); glVertex2f(4, 0); glVertex2f(0, 4);
    glEnd();
    fc_error(h, "glRectf inside glBegin/glEnd");
    glFinish();
}

/* ---- glEdgeFlag and glPolygonMode state ---------------------------------- */

static void edge_flag_state(fc_h *h)
{
    GLboolean b = GL_FALSE;
    fc_pixel_ortho(h);
    fc_get_boolean(h, "GL_EDGE_FLAG default", GL_EDGE_FLAG, 1);
    glEdgeFlag(GL_FALSE);
    fc_get_boolean(h, "GL_EDGE_FLAG false", GL_EDGE_FLAG, 1);
    fc_get_integer(h, "GL_EDGE_FLAG false (int)", GL_EDGE_FLAG, 1);
    glEdgeFlagv(&b);
    b = GL_TRUE;
    glEdgeFlagv(&b);
    fc_get_boolean(h, "GL_EDGE_FLAG after glEdgeFlagv(TRUE)", GL_EDGE_FLAG, 1);
    glEdgeFlag(2);                                  /* stored as 2.0: not 1.0 */
    fc_get_boolean(h, "GL_EDGE_FLAG after glEdgeFlag(2)", GL_EDGE_FLAG, 1);
    fc_error(h, "edge flag calls");
    /* edge flags inside primitives: filled polygons ignore them, but they
     * join the vertex format */
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_QUADS);
    for (int i = 0; i < 8; i++) {
        glEdgeFlag((GLboolean)(i & 1));
        fcu_color(i);
        glVertex2fv(fcu_quads_v[i]);
    }
    glEnd();
    glBegin(GL_POLYGON);
    fcu_color(3);
    glVertex2f(20, 2);
    glEdgeFlag(GL_TRUE);
    glVertex2f(30, 4);
    glEdgeFlag(GL_FALSE);
    fcu_color(4);
    glVertex2f(28, 12);
    glVertex2f(21, 10);
    glEnd();
    fc_capture(h);
    fc_get_boolean(h, "GL_EDGE_FLAG after primitives", GL_EDGE_FLAG, 1);
    fc_error(h, "final");
}

static void polygon_mode_state(fc_h *h)
{
    fc_get_integer(h, "GL_POLYGON_MODE default", GL_POLYGON_MODE, 2);
    glPolygonMode(GL_FRONT, GL_LINE);
    fc_get_integer(h, "front line", GL_POLYGON_MODE, 2);
    glPolygonMode(GL_BACK, GL_POINT);
    fc_get_integer(h, "back point", GL_POLYGON_MODE, 2);
    fc_get_float(h, "back point (float)", GL_POLYGON_MODE, 2);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    fc_get_integer(h, "both fill", GL_POLYGON_MODE, 2);
    fc_error(h, "valid calls");
    glPolygonMode(GL_FRONT, GL_FILL + 1); fc_error(h, "bad mode");
    glPolygonMode(GL_LEFT, GL_LINE); fc_error(h, "bad face GL_LEFT");
    glPolygonMode(GL_FRONT, 0x933C); fc_error(h, "GL_FILL_RECTANGLE_NV");
    glPolygonMode(GL_LINE, GL_FRONT); fc_error(h, "swapped arguments");
    glPolygonMode(0, 0); fc_error(h, "both invalid");
    fc_get_integer(h, "unchanged after errors", GL_POLYGON_MODE, 2);
    glBegin(GL_TRIANGLES);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnd();
    fc_error(h, "inside glBegin/glEnd");
    fc_get_integer(h, "unchanged after glBegin error", GL_POLYGON_MODE, 2);
}

/* ---- polygon offset ------------------------------------------------------- */

/* Steep triangles (depth slopes in x, in y, both) under one offset setting;
 * depth test GL_ALWAYS so every fragment writes its offset depth. */
static void offset_scene(float factor, float units, bool fill)
{
    static const float tris[4][3][3] = {
        { { 1, 1, -0.9f }, { 30, 2, 0.8f }, { 6, 12, -0.2f } },          /* steep in x */
        { { 2, 14, 0.3f }, { 15, 16, 0.31f }, { 4, 31, -0.95f } },       /* steep in y */
        { { 17, 15, 0.99f }, { 31, 17, -0.99f }, { 22, 31, 0.5f } },     /* very steep */
        { { 18, 3, 0.1f }, { 31, 4, 0.1f }, { 25, 13, 0.1f } },          /* flat */
    };
    glViewport(0, 0, 32, 32);
    fcu_ortho(0, 32, 0, 32, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    fcu_clear(0, 0, 0, 0, 0.5);
    glPolygonOffset(factor, units);
    if (fill)
        glEnable(GL_POLYGON_OFFSET_FILL);
    for (int i = 0; i < 4; i++)
        tri3(tris[i], 3 * i);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

static void offset_factor(fc_h *h)
{
    offset_scene(1.0f, 0.0f, true); fc_capture(h);
    offset_scene(4.5f, 0.0f, true); fc_capture(h);
    offset_scene(-2.25f, 0.0f, true); fc_capture(h);
}

static void offset_units(fc_h *h)
{
    offset_scene(0.0f, 1.0f, true); fc_capture(h);
    offset_scene(0.0f, 1000.0f, true); fc_capture(h);
    offset_scene(0.0f, -37.5f, true); fc_capture(h);
}

static void offset_both(fc_h *h)
{
    offset_scene(1.0f, 1.0f, true); fc_capture(h);
    offset_scene(-1.5f, -3.0f, true); fc_capture(h);
    offset_scene(2.0f, -100000.0f, true); fc_capture(h);   /* clamps to 0 */
    offset_scene(0.0f, 0.0f, true); fc_capture(h);         /* enabled, no offset */
}

static void offset_z16(fc_h *h)
{
    offset_scene(1.0f, 1.0f, true); fc_capture(h);
    offset_scene(0.0f, -5.0f, true); fc_capture(h);
    offset_scene(-3.0f, 2.0f, true); fc_capture(h);
}

/* Coplanar decal: a perspective quad, then a smaller quad in the same plane
 * with a negative offset and GL_LESS; without offset it z-fights. */
static void offset_decal(fc_h *h)
{
    for (int pass = 0; pass < 3; pass++) {
        glViewport(0, 0, 64, 64);
        fcu_frustum(-1, 1, -1, 1, 1, 10);
        glRotatef(-60, 1, 0, 0);
        glRotatef(20, 0, 0, 1);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        fcu_clear(0, 0, 0, 0, 1);
        glTranslatef(0, 0, -2.5f);
        glColor3f(0.2f, 0.4f, 0.9f);
        glBegin(GL_QUADS);
        glVertex3f(-3, -3, 0); glVertex3f(3, -3, 0); glVertex3f(3, 3, 0); glVertex3f(-3, 3, 0);
        glEnd();
        if (pass > 0) {
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(pass == 1 ? -1.0f : 0.0f, pass == 1 ? -1.0f : -2.0f);
        }
        glColor3f(1, 0.8f, 0.1f);
        glBegin(GL_TRIANGLE_FAN);
        glVertex3f(0, 0, 0);
        for (int i = 0; i <= 12; i++) {
            const float a = (float)i * 0.5235988f;
            glVertex3f(1.5f * cosf(a), 1.5f * sinf(a), 0);
        }
        glEnd();
        glDisable(GL_POLYGON_OFFSET_FILL);
        fc_capture(h);
    }
}

/* Only GL_POLYGON_OFFSET_LINE or _POINT enabled: the oracle's llvmpipe setup
 * still offsets filled triangles (st_atom_rasterizer passes the offset
 * values whenever one of the three is on). */
static void offset_line_point_enable(fc_h *h)
{
    static const GLenum caps[2] = { GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT };
    for (int i = 0; i < 2; i++) {
        offset_scene(2.0f, 8.0f, false);
        glEnable(caps[i]);
        offset_scene(2.0f, 8.0f, false);
        glDisable(caps[i]);
        fc_capture(h);
    }
}

/* Offset triangles crossing the view volume (clipped triangles and the rest
 * of the draw go through draw's clipper, then the same setup). */
static void offset_clipped(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    fcu_clear(0, 0, 0, 0, 0.5);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 3.0f);
    glBegin(GL_TRIANGLES);
    fcu_color(0); glVertex3f(-1.5f, -0.8f, -0.9f);
    fcu_color(1); glVertex3f(0.9f, -0.6f, 1.4f);
    fcu_color(2); glVertex3f(-0.2f, 0.9f, 0.2f);
    fcu_color(3); glVertex3f(0.1f, 0.1f, 0.7f);
    fcu_color(4); glVertex3f(0.95f, 0.3f, -0.8f);
    fcu_color(5); glVertex3f(0.4f, 1.7f, 0.0f);
    glEnd();
    glBegin(GL_QUADS);                              /* clipped batch: 1-3 split */
    fcu_color(6); glVertex3f(-0.9f, -0.9f, -1.2f);
    fcu_color(7); glVertex3f(-0.1f, -0.95f, 0.3f);
    fcu_color(8); glVertex3f(-0.2f, -0.1f, 0.9f);
    fcu_color(9); glVertex3f(-0.95f, -0.2f, 0.1f);
    glEnd();
    fc_capture(h);
}

/* Perspective triangles crossing the near plane with offset, under a
 * reversed and a narrow depth range, with and without stipple (setup's
 * offset vs draw's per-vertex one). */
static void offset_perspective(fc_h *h)
{
    GLubyte pat[128];
    make_pattern(pat, 0);
    glPolygonStipple(pat);
    for (int k = 0; k < 4; k++) {
        glViewport(0, 0, 32, 32);
        fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 20);
        glDepthRange(k & 1 ? 0.9 : 0.3, k & 1 ? 0.1 : 0.35);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        fcu_clear(0, 0, 0, 0, 1);
        if (k >= 2)
            glEnable(GL_POLYGON_STIPPLE);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(k & 1 ? -2.0f : 3.0f, k & 1 ? 7.0f : -11.0f);
        glBegin(GL_TRIANGLES);
        fcu_color(0); glVertex3f(-2.0f, -1.5f, -4.0f);
        fcu_color(1); glVertex3f(2.0f, -1.0f, -5.0f);
        fcu_color(2); glVertex3f(0.3f, 0.5f, 2.0f);
        fcu_color(3); glVertex3f(-1.0f, 0.2f, -1.5f);
        fcu_color(4); glVertex3f(1.0f, 0.4f, -3.0f);
        fcu_color(5); glVertex3f(-0.5f, 1.5f, -1.0f);
        glEnd();
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i < 8; i++) {
            fcu_color(i + 6);
            glVertex3f(-1.5f + 0.4f * (float)(i / 2), (i & 1) ? 0.8f : -0.8f, -1.2f - 1.5f * (float)i);
        }
        glEnd();
        glDisable(GL_POLYGON_STIPPLE);
        fc_capture(h);
    }
}

static void offset_state(fc_h *h)
{
    fc_get_float(h, "GL_POLYGON_OFFSET_FACTOR default", GL_POLYGON_OFFSET_FACTOR, 1);
    fc_get_float(h, "GL_POLYGON_OFFSET_UNITS default", GL_POLYGON_OFFSET_UNITS, 1);
    glPolygonOffset(2.5f, -3.5f);
    fc_get_float(h, "factor", GL_POLYGON_OFFSET_FACTOR, 1);
    fc_get_integer(h, "factor (int)", GL_POLYGON_OFFSET_FACTOR, 1);
    fc_get_integer(h, "units (int)", GL_POLYGON_OFFSET_UNITS, 1);
    fc_get_double(h, "units (double)", GL_POLYGON_OFFSET_UNITS, 1);
    fc_get_boolean(h, "units (bool)", GL_POLYGON_OFFSET_UNITS, 1);
    static const GLenum caps[3] = { GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE,
                                    GL_POLYGON_OFFSET_POINT };
    for (int i = 0; i < 3; i++) {
        fc_is_enabled(h, "offset cap default", caps[i]);
        glEnable(caps[i]);
        fc_is_enabled(h, "offset cap enabled", caps[i]);
        fc_get_boolean(h, "offset cap as state", caps[i], 1);
        glDisable(caps[i]);
    }
    fc_error(h, "valid calls");
    glBegin(GL_TRIANGLES);
    glPolygonOffset(1, 1);
    glEnd();
    fc_error(h, "glPolygonOffset inside glBegin/glEnd");
    fc_get_float(h, "unchanged factor", GL_POLYGON_OFFSET_FACTOR, 1);
    glPolygonOffset(-0.0f, 1e30f);
    fc_get_float(h, "huge units", GL_POLYGON_OFFSET_UNITS, 1);
    fc_get_integer(h, "huge units (int)", GL_POLYGON_OFFSET_UNITS, 1);
    /* integer reads round half away from zero into a long, then keep the
     * low 32 bits */
    static const float vals[8] = { 2.5f, -2.5f, 0.49999997f, -0.5f, 3e9f, -5e9f, 2147483647.0f, 1e19f };
    for (int i = 0; i < 8; i++) {
        glPolygonOffset(vals[i], -vals[i]);
        fc_get_integer(h, "factor (int)", GL_POLYGON_OFFSET_FACTOR, 1);
        fc_get_integer(h, "units (int)", GL_POLYGON_OFFSET_UNITS, 1);
    }
    fc_error(h, "final");
}

/* ---- polygon stipple ------------------------------------------------------ */

static void make_pattern(GLubyte p[128], int kind)
{
    for (int row = 0; row < 32; row++) {
        for (int b = 0; b < 4; b++) {
            GLubyte v;
            switch (kind) {
            case 0: v = (row & 1) ? 0xaa : 0x55; break;                 /* checker */
            case 1: v = (row & 4) ? 0xff : 0x00; break;                 /* 4-row stripes */
            case 2: v = 0xf0; break;                                    /* 4-column stripes */
            default: v = (GLubyte)((row * 37 + b * 101 + 13) * 2654435761u >> 24); break;
            }
            p[row * 4 + b] = v;
        }
    }
    if (kind == 3)
        p[0] = 0x80;   /* bottom-left pixel of the pattern alone */
}

static void stipple_prims(fc_h *h, int kind)
{
    GLubyte pat[128];
    make_pattern(pat, kind);
    fc_pixel_ortho(h);
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    fcu_clear(0, 0, 0, 0, 1);
    draw_prim(GL_TRIANGLES);
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    draw_prim(GL_QUADS);
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    draw_prim(GL_POLYGON);
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    draw_prim(GL_QUAD_STRIP);
    fc_capture(h);
}

static void stipple_checker(fc_h *h) { stipple_prims(h, 0); }
static void stipple_stripes(fc_h *h)
{
    stipple_prims(h, 1);
    stipple_prims(h, 2);
}
static void stipple_random(fc_h *h) { stipple_prims(h, 3); }

/* The rasterizer's stipple before the state tracker first hands it a
 * pattern covers every pixel, while the state tracker's copy to compare
 * with starts all zero: a first glPolygonStipple of all zeros is no
 * change and the stipple still covers everything; after another pattern
 * the same zeros stipple everything away (probed on the oracle). */
static void stipple_first_zeros(fc_h *h)
{
    static const GLubyte zeros[128];
    GLubyte pat[128];
    make_pattern(pat, 3);
    fc_pixel_ortho(h);
    glEnable(GL_POLYGON_STIPPLE);
    const GLubyte *seq[3] = { zeros, pat, zeros };
    for (int f = 0; f < 3; f++) {
        glPolygonStipple(seq[f]);
        fcu_clear(0, 0, 0, 0, 1);
        draw_prim(GL_TRIANGLES);
        fc_capture(h);
    }
}

/* Every filled primitive type through draw's pipeline (stipple), smooth
 * and flat: the pipeline's decomposition and provoking vertices. */
static void stipple_all_prims(fc_h *h)
{
    static const GLenum modes[6] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                     GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    GLubyte pat[128];
    make_pattern(pat, 3);
    fc_pixel_ortho(h);
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    for (int flat = 0; flat < 2; flat++) {
        glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
        for (int m = 0; m < 6; m++) {
            fcu_clear(0, 0, 0, 0, 1);
            draw_prim(modes[m]);
            fc_capture(h);
        }
    }
}

/* Window heights that are not multiples of 32, and a viewport moved by odd
 * amounts: the pattern stays fixed to window coordinates. */
static void stipple_odd_window(fc_h *h)
{
    GLubyte pat[128];
    make_pattern(pat, 3);
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    for (int k = 0; k < 2; k++) {
        glViewport(3 + 5 * k, 7 - 4 * k, 32, 32);
        fcu_ortho(0, 32, 0, 32, -1, 1);
        fcu_clear(0, 0, 0, 0, 1);
        draw_prim(GL_TRIANGLE_FAN);
        fc_capture(h);
    }
}

/* glGetPolygonStipple: default pattern, a set pattern, NULL arguments,
 * errors inside glBegin/glEnd (state unchanged). */
static void stipple_get(fc_h *h)
{
    GLubyte pat[128], out[128];
    memset(out, 0x5a, sizeof out);
    glGetPolygonStipple(out);
    fc_blob(h, "default stipple", out, sizeof out);
    fc_is_enabled(h, "GL_POLYGON_STIPPLE default", GL_POLYGON_STIPPLE);
    make_pattern(pat, 3);
    glPolygonStipple(pat);
    memset(out, 0x5a, sizeof out);
    glGetPolygonStipple(out);
    fc_blob(h, "set stipple", out, sizeof out);
    glPolygonStipple(NULL);
    fc_error(h, "glPolygonStipple(NULL)");
    memset(out, 0x5a, sizeof out);
    glGetPolygonStipple(out);
    fc_blob(h, "after NULL", out, sizeof out);
    make_pattern(pat, 0);
    glBegin(GL_TRIANGLES);
    glPolygonStipple(pat);
    glEnd();
    fc_error(h, "glPolygonStipple inside glBegin/glEnd");
    glBegin(GL_TRIANGLES);
    glGetPolygonStipple(out);
    glEnd();
    fc_error(h, "glGetPolygonStipple inside glBegin/glEnd");
    memset(out, 0x5a, sizeof out);
    glGetPolygonStipple(out);
    fc_blob(h, "unchanged", out, sizeof out);
    glEnable(GL_POLYGON_STIPPLE);
    fc_get_boolean(h, "GL_POLYGON_STIPPLE enabled", GL_POLYGON_STIPPLE, 1);
    fc_error(h, "final");
}

/* The stipple rows follow the window height: re-binding the context to a
 * buffer of another height moves the pattern. */
static void stipple_rebind(fc_h *h)
{
    GLubyte pat[128], color[32 * 21 * 4];
    make_pattern(pat, 3);
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glColor3f(1, 0.5f, 0.25f);
    glRectf(0, 0, 32, 32);
    fc_capture(h);
    fc_value(h, "rebind 32x21", OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 32, 21));
    glViewport(0, 0, 32, 21);
    fcu_clear(0, 0, 0, 0, 1);
    glRectf(0, 0, 32, 32);
    memset(color, 0x33, sizeof color);
    glReadPixels(0, 0, 32, 21, GL_RGBA, GL_UNSIGNED_BYTE, color);
    fc_blob(h, "glReadPixels 32x21", color, sizeof color);
    /* a new pattern is inverted with the new height ... */
    make_pattern(pat, 1);
    pat[5] = 0x0f;
    glPolygonStipple(pat);
    fcu_clear(0, 0, 0, 0, 1);
    glRectf(0, 0, 32, 32);
    glReadPixels(0, 0, 32, 21, GL_RGBA, GL_UNSIGNED_BYTE, color);
    fc_blob(h, "new pattern at 32x21", color, sizeof color);
    /* ... which stays when going back to 32x32 */
    fc_value(h, "rebind 32x32", OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 32, 32));
    glViewport(0, 0, 32, 32);
    fcu_clear(0, 0, 0, 0, 1);
    glRectf(0, 0, 32, 32);
    fc_capture(h);
    /* setting the same pattern again changes nothing either */
    glPolygonStipple(pat);
    fcu_clear(0, 0, 0, 0, 1);
    glRectf(0, 0, 32, 32);
    fc_capture(h);
    fc_error(h, "final");
}

/* Stipple puts every triangle through draw's pipeline: offset per vertex
 * (clamped there), with depth. */
static void stipple_offset(fc_h *h)
{
    GLubyte pat[128];
    make_pattern(pat, 0);
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    offset_scene(1.5f, 20.0f, true); fc_capture(h);
    offset_scene(-2.0f, -4000000.0f, true); fc_capture(h);   /* saturates at 0 */
    glEnable(GL_POLYGON_OFFSET_LINE);
    offset_scene(3.0f, 3.0f, false); fc_capture(h);          /* line only: no offset */
}

/* Stipple with two-sided lighting and culling: facing from draw's float
 * determinant. */
static void stipple_twoside_cull(fc_h *h)
{
    GLubyte pat[128];
    make_pattern(pat, 1);
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    lt_ortho(h, 1.0f);
    glDepthFunc(GL_ALWAYS);
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    lt_lamp(GL_LIGHT0, (const float[3]){ 0.1f, 0.1f, 0.1f }, (const float[3]){ 0.9f, 0.8f, 0.2f },
            (const float[3]){ 0, 0, 0 }, 0.3f, 0.4f, 1.0f, 0.0f);
    lt_mat(GL_FRONT, GL_DIFFUSE, 1, 0.2f, 0.2f, 1);
    lt_mat(GL_BACK, GL_DIFFUSE, 0.2f, 0.3f, 1, 1);
    glNormal3f(0, 0, 1);
    lt_clear();
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.9f, -0.9f); glVertex2f(-0.1f, -0.9f); glVertex2f(-0.5f, -0.1f);   /* front */
    glVertex2f(0.1f, -0.9f); glVertex2f(0.5f, -0.1f); glVertex2f(0.9f, -0.9f);     /* back */
    glEnd();
    glBegin(GL_QUADS);
    glVertex2f(-0.9f, 0.1f); glVertex2f(-0.1f, 0.1f); glVertex2f(-0.1f, 0.9f); glVertex2f(-0.9f, 0.9f);
    glVertex2f(0.1f, 0.1f); glVertex2f(0.1f, 0.9f); glVertex2f(0.9f, 0.9f); glVertex2f(0.9f, 0.1f);
    glEnd();
    fc_capture(h);
    glEnable(GL_CULL_FACE);
    lt_clear();
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.9f, -0.9f); glVertex2f(-0.1f, -0.9f); glVertex2f(-0.5f, -0.1f);
    glVertex2f(0.1f, -0.9f); glVertex2f(0.5f, -0.1f); glVertex2f(0.9f, -0.9f);
    glEnd();
    glFrontFace(GL_CW);
    glBegin(GL_QUADS);
    glVertex2f(-0.9f, 0.1f); glVertex2f(-0.1f, 0.1f); glVertex2f(-0.1f, 0.9f); glVertex2f(-0.9f, 0.9f);
    glVertex2f(0.1f, 0.1f); glVertex2f(0.1f, 0.9f); glVertex2f(0.9f, 0.9f); glVertex2f(0.9f, 0.1f);
    glEnd();
    fc_capture(h);
}

/* ---- pixel storage modes ------------------------------------------------- */

static const GLenum store_pnames[16] = {
    GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, GL_PACK_IMAGE_HEIGHT,
    GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_IMAGES, GL_PACK_ALIGNMENT,
    GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT,
    GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_IMAGES, GL_UNPACK_ALIGNMENT,
};

static void pixelstore_state(fc_h *h)
{
    for (int i = 0; i < 16; i++)
        fc_get_integer(h, "default", store_pnames[i], 1);
    for (int i = 0; i < 16; i++)
        glPixelStorei(store_pnames[i], i == 7 || i == 15 ? 8 : 3 + i);
    for (int i = 0; i < 16; i++) {
        fc_get_integer(h, "set", store_pnames[i], 1);
        fc_get_boolean(h, "set (bool)", store_pnames[i], 1);
        fc_get_float(h, "set (float)", store_pnames[i], 1);
    }
    fc_error(h, "valid calls");
    static const GLint bad_align[4] = { 0, 3, 16, -4 };
    for (int i = 0; i < 4; i++) {
        glPixelStorei(GL_PACK_ALIGNMENT, bad_align[i]); fc_error(h, "bad pack alignment");
        glPixelStorei(GL_UNPACK_ALIGNMENT, bad_align[i]); fc_error(h, "bad unpack alignment");
    }
    for (int i = 0; i < 16; i++) {
        glPixelStorei(store_pnames[i], -1);
        fc_error(h, "negative value");
        fc_get_integer(h, "after -1", store_pnames[i], 1);
    }
    glPixelStorei(GL_PIXEL_MAP_I_TO_I, 1); fc_error(h, "bad pname");
    glPixelStorei(0, 0); fc_error(h, "pname 0");
    static const float fv[8] = { 2.5f, 2.49999f, 0.5f, -0.4f, 1.0f, 1e20f, 3e9f, 7.5f };
    for (int i = 0; i < 8; i++) {
        glPixelStoref(GL_UNPACK_ROW_LENGTH, fv[i]);
        fc_error(h, "glPixelStoref row length");
        fc_get_integer(h, "row length via glPixelStoref", GL_UNPACK_ROW_LENGTH, 1);
        glPixelStoref(GL_PACK_ALIGNMENT, fv[i]);
        fc_error(h, "glPixelStoref alignment");
        fc_get_integer(h, "alignment via glPixelStoref", GL_PACK_ALIGNMENT, 1);
        glPixelStoref(GL_PACK_LSB_FIRST, fv[i] - 1.0f);
        fc_get_integer(h, "lsb first via glPixelStoref", GL_PACK_LSB_FIRST, 1);
    }
    glBegin(GL_TRIANGLES);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glEnd();
    fc_error(h, "glPixelStorei inside glBegin/glEnd");
    fc_get_integer(h, "unchanged", GL_UNPACK_ALIGNMENT, 1);
}

/* Stipple patterns read with unpack modes: LSB first, alignment 8, row
 * length, skipped rows and pixels (bit-shifting path, both bit orders). */
static void stipple_unpack_modes(fc_h *h)
{
    GLubyte data[1024], out[128];
    for (int i = 0; i < 1024; i++)
        data[i] = (GLubyte)((i * 2654435761u) >> 13);
    fc_pixel_ortho(h);
    glEnable(GL_POLYGON_STIPPLE);
    for (int k = 0; k < 6; k++) {
        glPixelStorei(GL_UNPACK_LSB_FIRST, k & 1);
        glPixelStorei(GL_UNPACK_ALIGNMENT, k == 2 ? 8 : k == 3 ? 1 : 4);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, k == 3 ? 45 : k == 5 ? 77 : 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, k >= 4 ? 3 : 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, k == 4 ? 5 : k == 5 ? 19 : k == 3 ? 8 : 0);
        glPixelStorei(GL_UNPACK_SWAP_BYTES, k == 2);   /* no effect on bitmaps */
        glPolygonStipple(data);
        memset(out, 0x5a, sizeof out);
        glGetPolygonStipple(out);
        fc_blob(h, "stipple as stored", out, sizeof out);
        fcu_clear(0, 0, 0, 0, 1);
        draw_prim(GL_QUADS);
        fc_capture(h);
    }
}

/* glGetPolygonStipple with pack modes, into a larger prefilled buffer (the
 * skip-pixels path clears the bits before the first pixel). */
static void stipple_pack_modes(fc_h *h)
{
    GLubyte pat[128], out[1024];
    make_pattern(pat, 3);
    glPolygonStipple(pat);
    for (int k = 0; k < 6; k++) {
        glPixelStorei(GL_PACK_LSB_FIRST, k & 1);
        glPixelStorei(GL_PACK_ALIGNMENT, k == 2 ? 8 : k == 3 ? 2 : 4);
        glPixelStorei(GL_PACK_ROW_LENGTH, k == 3 ? 45 : k == 5 ? 70 : 0);
        glPixelStorei(GL_PACK_SKIP_ROWS, k >= 4 ? 2 : 0);
        glPixelStorei(GL_PACK_SKIP_PIXELS, k == 4 ? 3 : k == 5 ? 13 : k == 3 ? 16 : 0);
        memset(out, 0xa5, sizeof out);
        glGetPolygonStipple(out);
        fc_blob(h, "packed stipple", out, sizeof out);
    }
    fc_error(h, "final");
}

/* glReadPixels with pack modes: alignment, row length, skips, byte swaps. */
static void pixelstore_readpixels(fc_h *h)
{
    static uint8_t buf[16384];
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    fcu_clear(0.1f, 0.2f, 0.3f, 0.4f, 0.25);
    draw_prim(GL_TRIANGLE_FAN);
    static const struct { GLint align, row, skip_px, skip_rows, swap; GLenum format, type; } m[] = {
        { 1, 0, 0, 0, 0, GL_RGB, GL_UNSIGNED_BYTE },
        { 2, 0, 0, 0, 0, GL_RGB, GL_UNSIGNED_BYTE },
        { 8, 0, 0, 0, 0, GL_RGB, GL_UNSIGNED_BYTE },
        { 4, 13, 2, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE },
        { 8, 11, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE },
        { 1, 0, 0, 0, 1, GL_RGB, GL_FLOAT },
        { 2, 9, 3, 0, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT },
        { 1, 7, 0, 2, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT },
        { 8, 0, 5, 0, 1, GL_DEPTH_COMPONENT, GL_FLOAT },
        { 2, 0, 0, 0, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT },
    };
    for (size_t k = 0; k < sizeof m / sizeof m[0]; k++) {
        glPixelStorei(GL_PACK_ALIGNMENT, m[k].align);
        glPixelStorei(GL_PACK_ROW_LENGTH, m[k].row);
        glPixelStorei(GL_PACK_SKIP_PIXELS, m[k].skip_px);
        glPixelStorei(GL_PACK_SKIP_ROWS, m[k].skip_rows);
        glPixelStorei(GL_PACK_SWAP_BYTES, m[k].swap);
        char label[64];
        memset(buf, 0x77, sizeof buf);
        glReadPixels(3, 5, 7, 6, m[k].format, m[k].type, buf);
        snprintf(label, sizeof label, "glReadPixels mode %d", (int)k);
        fc_blob(h, label, buf, 2048);
        memset(buf, 0x77, sizeof buf);
        glReadPixels(-2, 28, 5, 7, m[k].format, m[k].type, buf);   /* partly outside */
        snprintf(label, sizeof label, "glReadPixels partly outside, mode %d", (int)k);
        fc_blob(h, label, buf, 2048);
    }
    fc_error(h, "final");
}

/* GL_LINE_SMOOTH / GL_POINT_SMOOTH hand offset and two-sided colours to
 * draw, which then takes every triangle through its pipeline (quad split,
 * per-vertex offset, determinant facing); alone they change nothing for
 * triangles. */
static void smooth_caps_route_triangles(fc_h *h)
{
    static const GLenum caps[2] = { GL_LINE_SMOOTH, GL_POINT_SMOOTH };
    for (int i = 0; i < 2; i++) {
        glEnable(caps[i]);
        offset_scene(1.5f, 20.0f, true);
        glBegin(GL_QUADS);
        for (int k = 0; k < 8; k++) {
            fcu_color(k);
            glVertex3f(fcu_quads_v[k][0], fcu_quads_v[k][1], 0.1f * (float)(k & 3) - 0.2f);
        }
        glEnd();
        fc_capture(h);
        offset_scene(1.5f, 20.0f, false);       /* no offset: direct path */
        draw_prim(GL_QUADS);
        fc_capture(h);
        glDisable(caps[i]);
    }
    glEnable(GL_LINE_SMOOTH);
    lt_ortho(h, 1.0f);
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    lt_lamp(GL_LIGHT0, (const float[3]){ 0.1f, 0.1f, 0.1f }, (const float[3]){ 0.9f, 0.8f, 0.2f },
            (const float[3]){ 0, 0, 0 }, 0.3f, 0.4f, 1.0f, 0.0f);
    lt_mat(GL_FRONT, GL_DIFFUSE, 1, 0.2f, 0.2f, 1);
    lt_mat(GL_BACK, GL_DIFFUSE, 0.2f, 0.3f, 1, 1);
    glNormal3f(0, 0, 1);
    lt_clear();
    glBegin(GL_QUADS);
    glVertex2f(-0.9f, -0.9f); glVertex2f(-0.1f, -0.9f); glVertex2f(-0.1f, 0.9f); glVertex2f(-0.9f, 0.9f);
    glVertex2f(0.1f, -0.9f); glVertex2f(0.1f, 0.9f); glVertex2f(0.9f, 0.9f); glVertex2f(0.9f, -0.9f);
    glEnd();
    fc_capture(h);
}

/* ---- user clip planes ----------------------------------------------------- */

static void clip_scene_strip(void)
{
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 8; i++) {
        fcu_color(i);
        glVertex3f(fcu_strip_v[i][0] / 16.0f - 1.0f, fcu_strip_v[i][1] / 16.0f - 1.0f,
                   (float)i / 8.0f - 0.4f);
    }
    glEnd();
}

static void clip_setup(void)
{
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    fcu_clear(0, 0, 0, 0, 0.5);
}

/* One oblique plane cutting a strip, both sides, and a plane depending on z. */
static void clipplane_strip(fc_h *h)
{
    static const GLdouble eqs[3][4] = {
        { 1, 0.5, 0, 0.1 }, { -1, -0.5, 0, -0.1 }, { 0.3, -0.2, 1, 0.05 },
    };
    for (int i = 0; i < 3; i++) {
        clip_setup();
        glClipPlane(GL_CLIP_PLANE0 + i, eqs[i]);
        glEnable(GL_CLIP_PLANE0 + i);
        clip_scene_strip();
        glDisable(GL_CLIP_PLANE0 + i);
        fc_capture(h);
    }
}

/* Six and eight planes together around a fan and a polygon. */
static void clipplane_many(fc_h *h)
{
    for (int n = 6; n <= 8; n += 2) {
        clip_setup();
        for (int i = 0; i < n; i++) {
            const double a = (double)i * 6.283185307179586 / n + 0.3;
            const GLdouble eq[4] = { -cos(a), -sin(a), 0.1 * (i & 1), 0.7 };
            glClipPlane(GL_CLIP_PLANE0 + i, eq);
            glEnable(GL_CLIP_PLANE0 + i);
        }
        glBegin(GL_TRIANGLE_FAN);
        for (int i = 0; i < 7; i++) {
            fcu_color(i);
            glVertex2f(fcu_fan_v[i][0] / 16.0f - 1.0f, fcu_fan_v[i][1] / 16.0f - 1.0f);
        }
        glEnd();
        fc_capture(h);
        clip_setup();
        glBegin(GL_POLYGON);
        for (int i = 0; i < 6; i++) {
            fcu_color(i + 3);
            glVertex3f(fcu_poly_v[i][0] / 16.0f - 1.0f, fcu_poly_v[i][1] / 16.0f - 1.0f,
                       0.1f * (float)i - 0.3f);
        }
        glEnd();
        fc_capture(h);
        for (int i = 0; i < n; i++)
            glDisable(GL_CLIP_PLANE0 + i);
    }
}

/* Planes given under rotated, scaled and translated modelviews (transformed
 * to eye space at call time), drawn under yet another modelview. */
static void clipplane_modelview(fc_h *h)
{
    static const GLdouble eq0[4] = { 1, 0, 0, 0 }, eq1[4] = { 0, 1, 0, 0.2 },
                          eq2[4] = { 1, 1, 0.5, -0.1 };
    clip_setup();
    glPushMatrix();
    glRotatef(30, 0, 0, 1);
    glClipPlane(GL_CLIP_PLANE0, eq0);
    glLoadIdentity();
    glScalef(2, 0.5f, 1);
    glTranslatef(0.1f, -0.3f, 0);
    glClipPlane(GL_CLIP_PLANE1, eq1);
    glLoadIdentity();
    glRotatef(-70, 0.3f, 0.2f, 1);
    glTranslatef(-0.2f, 0.1f, 0.1f);
    glClipPlane(GL_CLIP_PLANE2, eq2);
    glPopMatrix();
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE1);
    glRotatef(15, 0, 0, 1);
    clip_scene_strip();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 0.5);
    glDisable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE2);
    clip_scene_strip();
    fc_capture(h);
    GLdouble out[4];
    for (int i = 0; i < 3; i++) {
        glGetClipPlane(GL_CLIP_PLANE0 + i, out);
        fc_blob(h, "glGetClipPlane", out, sizeof out);
    }
    glDisable(GL_CLIP_PLANE1);
    glDisable(GL_CLIP_PLANE2);
}

/* Perspective: the clip-space plane uses the projection current at draw
 * time (set before or after glClipPlane, while enabled or disabled). */
static void clipplane_projection(fc_h *h)
{
    static const GLdouble eq[4] = { 1, 0.3, 0.2, 0.5 };
    glViewport(0, 0, 32, 32);
    glEnable(GL_DEPTH_TEST);
    fcu_ortho(-2, 2, -2, 2, -1, 1);
    glClipPlane(GL_CLIP_PLANE3, eq);
    fcu_frustum(-1, 1, -1, 1, 1, 10);      /* resets the modelview only */
    glEnable(GL_CLIP_PLANE3);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_QUADS);
    for (int i = 0; i < 8; i++) {
        fcu_color(i);
        glVertex3f(fcu_quads_v[i][0] / 8.0f - 2.0f, fcu_quads_v[i][1] / 8.0f - 2.0f,
                   -2.0f - 0.1f * (float)i);
    }
    glEnd();
    fc_capture(h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 1.5, -1, 1, 1.5, 8);
    glMatrixMode(GL_MODELVIEW);
    fcu_clear(0, 0, 0, 0, 1);
    draw_prim(GL_QUAD_STRIP);              /* window coords far off: mostly clipped */
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i < 8; i++) {
        fcu_color(i + 4);
        glVertex3f(fcu_qstrip_v[i][0] / 8.0f - 2.0f, fcu_qstrip_v[i][1] / 8.0f - 2.0f, -3.0f);
    }
    glEnd();
    fc_capture(h);
    glDisable(GL_CLIP_PLANE3);
}

/* Planes exactly through vertices (distances +-0), and planes that keep or
 * reject everything. */
static void clipplane_through_vertices(fc_h *h)
{
    static const GLdouble eqs[4][4] = {
        { 1, 0, 0, 0 },          /* x = 0: through vertices */
        { 0, -1, 0, 0.25 },      /* y = 0.25 */
        { 1, 1, 0, 0 },          /* diagonal through the centre vertex */
        { 0, 0, 0, -1 },         /* rejects everything */
    };
    for (int k = 0; k < 4; k++) {
        clip_setup();
        glClipPlane(GL_CLIP_PLANE5, eqs[k]);
        glEnable(GL_CLIP_PLANE5);
        glBegin(GL_TRIANGLE_FAN);
        fcu_color(0); glVertex2f(0, 0);
        fcu_color(1); glVertex2f(0.75f, 0);
        fcu_color(2); glVertex2f(0.75f, 0.25f);
        fcu_color(3); glVertex2f(0, 0.75f);
        fcu_color(4); glVertex2f(-0.5f, 0.25f);
        fcu_color(5); glVertex2f(-0.75f, -0.75f);
        fcu_color(6); glVertex2f(0, -0.75f);
        fcu_color(7); glVertex2f(0.75f, 0);
        glEnd();
        glDisable(GL_CLIP_PLANE5);
        fc_capture(h);
    }
}

/* A vertex on a user plane by the clip stage's plain dot product (0) but
 * outside by the vertex shader's fused one (-2.9e-11): its clip mask bit
 * sends the draw through the pipeline, which only shows in the quad's
 * diagonal (the clipper keeps the vertex). */
static void clipplane_fused_distance(fc_h *h)
{
    static const GLdouble eq[4] = { -0.1f, 0.1f, 0, 0 };
    const float x = 0.04296875f;
    for (int k = 0; k < 2; k++) {
        glViewport(0, 0, 32, 32);
        fcu_clear(0, 0, 0, 0, 1);
        glClipPlane(GL_CLIP_PLANE0, eq);
        if (k)
            glEnable(GL_CLIP_PLANE0);
        glBegin(GL_QUADS);
        fcu_color(0); glVertex2f(-0.9f, -0.5f);
        fcu_color(1); glVertex2f(x, x);
        fcu_color(2); glVertex2f(0.2f, 0.9f);
        fcu_color(3); glVertex2f(-0.8f, 0.7f);
        glEnd();
        fc_capture(h);
    }
    glDisable(GL_CLIP_PLANE0);
}

/* Quads and quad strips cut by a plane: the draw takes the pipeline, which
 * changes the quad diagonal; flat shading too. */
static void clipplane_quads(fc_h *h)
{
    static const GLdouble eq[4] = { -1, 0.2, 0, 0.5 };
    for (int flat = 0; flat < 2; flat++) {
        clip_setup();
        glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
        glClipPlane(GL_CLIP_PLANE1, eq);
        glEnable(GL_CLIP_PLANE1);
        glBegin(GL_QUADS);
        for (int i = 0; i < 8; i++) {
            fcu_color(i);
            glVertex3f(fcu_quads_v[i][0] / 16.0f - 1.0f, fcu_quads_v[i][1] / 16.0f - 1.0f,
                       0.2f * (float)(i & 3) - 0.3f);
        }
        glEnd();
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i < 8; i++) {
            fcu_color(i + 2);
            glVertex3f(fcu_qstrip_v[i][0] / 32.0f - 1.0f, fcu_qstrip_v[i][1] / 32.0f, 0.0f);
        }
        glEnd();
        glDisable(GL_CLIP_PLANE1);
        fc_capture(h);
    }
    glShadeModel(GL_SMOOTH);
}

static void clipplane_state(fc_h *h)
{
    static const GLdouble eq[4] = { 1.5, -2.25, 0.125, 1e-40 };
    GLdouble out[4];
    fc_get_integer(h, "GL_MAX_CLIP_PLANES", GL_MAX_CLIP_PLANES, 1);
    for (int i = 0; i < 8; i++) {
        memset(out, 0x5a, sizeof out);
        glGetClipPlane(GL_CLIP_PLANE0 + i, out);
        fc_blob(h, "default plane", out, sizeof out);
        fc_is_enabled(h, "plane default", GL_CLIP_PLANE0 + i);
    }
    glTranslatef(1, 2, 3);
    glClipPlane((GL_CLIP_PLANE0 + 7), eq);
    glGetClipPlane((GL_CLIP_PLANE0 + 7), out);
    fc_blob(h, "plane 7 under translation", out, sizeof out);
    glEnable((GL_CLIP_PLANE0 + 7));
    fc_is_enabled(h, "plane 7", (GL_CLIP_PLANE0 + 7));
    fc_get_boolean(h, "plane 7 as state", (GL_CLIP_PLANE0 + 7), 1);
    fc_get_integer(h, "plane 7 as state (int)", (GL_CLIP_PLANE0 + 7), 1);
    fc_error(h, "valid calls");
    glClipPlane(GL_CLIP_PLANE0 + 8, eq); fc_error(h, "glClipPlane(plane 8)");
    glClipPlane(GL_CLIP_PLANE0 - 1, eq); fc_error(h, "glClipPlane(plane -1)");
    glGetClipPlane(GL_CLIP_PLANE0 + 8, out); fc_error(h, "glGetClipPlane(plane 8)");
    glEnable(GL_CLIP_PLANE0 + 8); fc_error(h, "glEnable(plane 8)");
    glIsEnabled(GL_CLIP_PLANE0 + 8); fc_error(h, "glIsEnabled(plane 8)");
    glBegin(GL_TRIANGLES);
    glClipPlane(GL_CLIP_PLANE0, eq);
    glEnd();
    fc_error(h, "glClipPlane inside glBegin/glEnd");
    glBegin(GL_TRIANGLES);
    glGetClipPlane(GL_CLIP_PLANE0, out);
    glEnd();
    fc_error(h, "glGetClipPlane inside glBegin/glEnd");
    memset(out, 0x5a, sizeof out);
    glGetClipPlane(GL_CLIP_PLANE0, out);
    fc_blob(h, "plane 0 unchanged", out, sizeof out);
    glDisable((GL_CLIP_PLANE0 + 7));
    fc_error(h, "final");
}

/* ---- culling -------------------------------------------------------------- */

/* Every filled primitive type, both front-face settings, every cull mode. */
static void cull_prims(fc_h *h, GLenum mode)
{
    static const GLenum faces[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
    fc_pixel_ortho(h);
    glEnable(GL_CULL_FACE);
    for (int ff = 0; ff < 2; ff++) {
        glFrontFace(ff ? GL_CW : GL_CCW);
        for (int c = 0; c < 3; c++) {
            glCullFace(faces[c]);
            fcu_clear(0, 0, 0, 0, 1);
            draw_prim(mode);
            fc_capture(h);
        }
    }
}

static void cull_triangles(fc_h *h) { cull_prims(h, GL_TRIANGLES); }
static void cull_strip(fc_h *h) { cull_prims(h, GL_TRIANGLE_STRIP); }
static void cull_fan(fc_h *h) { cull_prims(h, GL_TRIANGLE_FAN); }
static void cull_quads(fc_h *h) { cull_prims(h, GL_QUADS); }
static void cull_quad_strip(fc_h *h) { cull_prims(h, GL_QUAD_STRIP); }
static void cull_polygon(fc_h *h) { cull_prims(h, GL_POLYGON); }

/* Mixed windings (a bow-tie polygon, a folded strip) clipped by the view
 * volume: the clipped draw culls by draw's determinant, then the setup's
 * area sign. */
static void cull_clipped(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glEnable(GL_CULL_FACE);
    for (int c = 0; c < 2; c++) {
        glCullFace(c ? GL_FRONT : GL_BACK);
        fcu_clear(0, 0, 0, 0, 1);
        glBegin(GL_TRIANGLE_STRIP);
        fcu_color(0); glVertex2f(-1.4f, -0.9f);
        fcu_color(1); glVertex2f(-0.9f, 0.9f);
        fcu_color(2); glVertex2f(-0.3f, -0.8f);
        fcu_color(3); glVertex2f(-0.6f, 0.7f);     /* folds back */
        fcu_color(4); glVertex2f(0.4f, -0.7f);
        fcu_color(5); glVertex2f(0.3f, 1.3f);
        glEnd();
        glBegin(GL_QUADS);                      /* bow tie */
        fcu_color(6); glVertex2f(0.2f, -0.95f);
        fcu_color(7); glVertex2f(1.3f, -0.2f);
        fcu_color(8); glVertex2f(1.2f, -0.9f);
        fcu_color(9); glVertex2f(0.3f, -0.1f);
        glEnd();
        fc_capture(h);
    }
}

/* ---- mixed -------------------------------------------------------------- */

static uint32_t lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static float frand(uint32_t *s, float lo, float hi)
{
    return lo + (hi - lo) * (float)(lcg(s) & 0xffff) / 65535.0f;
}

/* Random frames mixing everything: offsets (llvmpipe's or draw's), stipple,
 * user planes, culling, front face, shade model, perspective and ortho,
 * every filled primitive type, vertices outside the view volume. */
static void polygon_mix(fc_h *h)
{
    static const GLenum modes[6] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                     GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    uint32_t seed = 12345u;
    glViewport(0, 0, 64, 64);
    glEnable(GL_DEPTH_TEST);
    for (int frame = 0; frame < 6; frame++) {
        if (frame & 1)
            fcu_frustum(-1, 1, -1, 1, 1, 6);
        else
            fcu_ortho(-1, 1, -1, 1, -1, 1);
        if (frame & 1)
            glTranslatef(0, 0, -3);
        glRotatef(frand(&seed, -40, 40), frand(&seed, -1, 1), frand(&seed, -1, 1), 1);
        fcu_clear(0, 0, 0, 0, 1);
        glShadeModel(lcg(&seed) & 1 ? GL_FLAT : GL_SMOOTH);
        glFrontFace(lcg(&seed) & 1 ? GL_CW : GL_CCW);
        if (lcg(&seed) % 3 == 0) {
            glEnable(GL_CULL_FACE);
            glCullFace(lcg(&seed) & 1 ? GL_FRONT : GL_BACK);
        } else {
            glDisable(GL_CULL_FACE);
        }
        GLubyte pat[128];
        for (int i = 0; i < 128; i++)
            pat[i] = (GLubyte)lcg(&seed);
        glPolygonStipple(pat);
        if (frame >= 2 && (lcg(&seed) & 1))
            glEnable(GL_POLYGON_STIPPLE);
        else
            glDisable(GL_POLYGON_STIPPLE);
        const int nplanes = (int)(lcg(&seed) % 4);
        for (int i = 0; i < 8; i++) {
            if (i < nplanes) {
                const GLdouble eq[4] = { frand(&seed, -1, 1), frand(&seed, -1, 1),
                                         frand(&seed, -1, 1), frand(&seed, 0, 0.8f) };
                glClipPlane(GL_CLIP_PLANE0 + i, eq);
                glEnable(GL_CLIP_PLANE0 + i);
            } else {
                glDisable(GL_CLIP_PLANE0 + i);
            }
        }
        for (int p = 0; p < 24; p++) {
            if (lcg(&seed) & 1) {
                glEnable(GL_POLYGON_OFFSET_FILL);
                glPolygonOffset(frand(&seed, -4, 4), frand(&seed, -50, 50));
            } else {
                glDisable(GL_POLYGON_OFFSET_FILL);
            }
            const GLenum mode = modes[lcg(&seed) % 6];
            const int n = 3 + (int)(lcg(&seed) % 6);
            const float cx = frand(&seed, -0.8f, 0.8f), cy = frand(&seed, -0.8f, 0.8f);
            glBegin(mode);
            for (int v = 0; v < n; v++) {
                glColor3f(frand(&seed, 0, 1), frand(&seed, 0, 1), frand(&seed, 0, 1));
                glVertex3f(cx + frand(&seed, -0.7f, 0.7f), cy + frand(&seed, -0.7f, 0.7f),
                           frand(&seed, -1.2f, 1.2f));
            }
            glEnd();
        }
        fc_capture(h);
    }
}

const fc_case fc_cases_polygon[] = {
    FC_CASE_RGBA("polygon/polygon_smooth", 32, 32, 6, "raster polygon", polygon_smooth),
    FC_CASE_RGBA("polygon/rect_variants", 32, 32, 2, "raster polygon", rect_variants),
    FC_CASE_RGBA("polygon/rect_cull_errors", 32, 32, 2, "raster polygon", rect_cull_errors),
    FC_CASE_RGBA("polygon/edge_flag_state", 32, 32, 1, "raster polygon", edge_flag_state),
    FC_CASE_RGBA("polygon/polygon_mode_state", 8, 8, 0, "raster polygon", polygon_mode_state),
    FC_CASE_RGBA("polygon/offset_factor", 32, 32, 3, "raster polygon offset", offset_factor),
    FC_CASE_RGBA("polygon/offset_units", 32, 32, 3, "raster polygon offset", offset_units),
    FC_CASE_RGBA("polygon/offset_factor_and_units", 32, 32, 4, "raster polygon offset", offset_both),
    FC_CASE("polygon/offset_z16", 32, 32, OSMESA_RGBA, 16, 0, 3, "raster polygon offset", offset_z16),
    FC_CASE("polygon/offset_z24s8", 32, 32, OSMESA_RGBA, 24, 8, 3, "raster polygon offset", offset_z16),
    FC_CASE_RGBA("polygon/offset_decal", 64, 64, 3, "raster polygon offset", offset_decal),
    FC_CASE_RGBA("polygon/offset_line_point_enable", 32, 32, 2, "raster polygon offset", offset_line_point_enable),
    FC_CASE_RGBA("polygon/offset_clipped", 32, 32, 1, "raster polygon offset clip", offset_clipped),
    FC_CASE_RGBA("polygon/offset_perspective", 32, 32, 4, "raster polygon offset clip stipple", offset_perspective),
    FC_CASE("polygon/offset_perspective_z16", 32, 32, OSMESA_RGBA, 16, 0, 4, "raster polygon offset clip stipple", offset_perspective),
    FC_CASE_RGBA("polygon/offset_state", 8, 8, 0, "raster polygon offset", offset_state),
    FC_CASE_RGBA("polygon/stipple_checker", 32, 32, 4, "raster polygon stipple", stipple_checker),
    FC_CASE_RGBA("polygon/stipple_first_zeros", 32, 32, 3, "raster polygon stipple",
                 stipple_first_zeros),
    FC_CASE_RGBA("polygon/stipple_stripes", 32, 32, 8, "raster polygon stipple", stipple_stripes),
    FC_CASE_RGBA("polygon/stipple_random_odd_size", 37, 29, 4, "raster polygon stipple", stipple_random),
    FC_CASE_RGBA("polygon/stipple_all_prims", 32, 32, 12, "raster polygon stipple", stipple_all_prims),
    FC_CASE_RGBA("polygon/stipple_odd_window", 45, 43, 2, "raster polygon stipple", stipple_odd_window),
    FC_CASE_RGBA("polygon/stipple_rebind", 32, 32, 3, "raster polygon stipple", stipple_rebind),
    FC_CASE_RGBA("polygon/stipple_get", 8, 8, 0, "raster polygon stipple", stipple_get),
    FC_CASE_RGBA("polygon/pixelstore_state", 8, 8, 0, "raster polygon pixelstore", pixelstore_state),
    FC_CASE_RGBA("polygon/stipple_unpack_modes", 32, 32, 6, "raster polygon stipple pixelstore", stipple_unpack_modes),
    FC_CASE_RGBA("polygon/stipple_pack_modes", 8, 8, 0, "raster polygon stipple pixelstore", stipple_pack_modes),
    FC_CASE_RGBA("polygon/pixelstore_readpixels", 32, 32, 0, "raster polygon pixelstore", pixelstore_readpixels),
    FC_CASE("polygon/pixelstore_readpixels_z16", 32, 32, OSMESA_RGBA, 16, 0, 0, "raster polygon pixelstore", pixelstore_readpixels),
    FC_CASE_RGBA("polygon/smooth_caps_route_triangles", 32, 32, 5, "raster polygon offset", smooth_caps_route_triangles),
    FC_CASE_RGBA("polygon/stipple_offset", 32, 32, 3, "raster polygon stipple offset", stipple_offset),
    FC_CASE_RGBA("polygon/stipple_twoside_cull", 32, 32, 2, "raster polygon stipple lighting", stipple_twoside_cull),
    FC_CASE_RGBA("polygon/clipplane_strip", 32, 32, 3, "raster polygon clip", clipplane_strip),
    FC_CASE_RGBA("polygon/clipplane_many", 32, 32, 4, "raster polygon clip", clipplane_many),
    FC_CASE_RGBA("polygon/clipplane_modelview", 32, 32, 2, "raster polygon clip", clipplane_modelview),
    FC_CASE_RGBA("polygon/clipplane_projection", 32, 32, 2, "raster polygon clip", clipplane_projection),
    FC_CASE_RGBA("polygon/clipplane_through_vertices", 32, 32, 4, "raster polygon clip", clipplane_through_vertices),
    FC_CASE_RGBA("polygon/clipplane_fused_distance", 32, 32, 2, "raster polygon clip", clipplane_fused_distance),
    FC_CASE_RGBA("polygon/clipplane_quads", 32, 32, 2, "raster polygon clip", clipplane_quads),
    FC_CASE_RGBA("polygon/clipplane_state", 8, 8, 0, "raster polygon clip", clipplane_state),
    FC_CASE_RGBA("polygon/cull_triangles", 32, 32, 6, "raster polygon cull", cull_triangles),
    FC_CASE_RGBA("polygon/cull_triangle_strip", 32, 32, 6, "raster polygon cull", cull_strip),
    FC_CASE_RGBA("polygon/cull_triangle_fan", 32, 32, 6, "raster polygon cull", cull_fan),
    FC_CASE_RGBA("polygon/cull_quads", 32, 32, 6, "raster polygon cull", cull_quads),
    FC_CASE_RGBA("polygon/cull_quad_strip", 32, 32, 6, "raster polygon cull", cull_quad_strip),
    FC_CASE_RGBA("polygon/cull_polygon", 32, 32, 6, "raster polygon cull", cull_polygon),
    FC_CASE_RGBA("polygon/cull_clipped", 32, 32, 2, "raster polygon cull clip", cull_clipped),
    FC_CASE_RGBA("polygon/mix_random", 64, 64, 6, "raster polygon offset stipple clip cull", polygon_mix),
    FC_CASE("polygon/mix_random_z16", 64, 64, OSMESA_RGBA, 16, 0, 6, "raster polygon offset stipple clip cull", polygon_mix),
    { 0 }
};
