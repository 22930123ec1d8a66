/* c_polygon_mode.c - glPolygonMode rendering through draw's unfilled stage
 * (draw_pipe_unfilled.c): every primitive type as outlines and as vertex
 * points, flat and smooth; different front and back modes under both
 * front-face settings and culling (the state tracker's simplification of
 * the modes for culled faces); edge flags (hidden polygon diagonals, quads,
 * the current edge flag culling unfilled faces); wide, stippled and smooth
 * outlines, large and smooth points; polygon offset of lines and points
 * (hidden-line removal, the offset stage's first-triangle latch); lit
 * two-sided outlines; outlines cut by the near plane and user planes; long
 * polygons split by vsplit; the errors and queries. */
#include <math.h>
#include <stdbool.h>

#include "cases.h"

/* Per-vertex colours that vary smoothly, so smooth and flat outlines
 * differ (the flat colour is the triangle's provoking vertex, copied by
 * draw's flatshade stage before the edges are drawn). */
static void vcolor(int i)
{
    glColor3f(0.2f + 0.8f * (float)((i * 5) % 7) / 6.0f, (float)((i * 3) % 5) / 4.0f,
              1.0f - (float)((i * 2) % 9) / 8.0f);
}

/* Every filled primitive type in a 3 x 2 grid of 32 x 32 cells of a 96 x 64
 * buffer (the fcu_* shapes: both windings occur in strips, fans and in the
 * second row, which is mirrored). */
static void all_prims(void)
{
    static const GLenum modes[6] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                     GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    static const float (*const verts[6])[2] = { fcu_tri_v, fcu_strip_v, fcu_fan_v,
                                                fcu_quads_v, fcu_qstrip_v, fcu_poly_v };
    static const int counts[6] = { 6, 8, 7, 8, 8, 6 };
    for (int p = 0; p < 6; p++) {
        const float ox = 32.0f * (float)(p % 3), oy = 32.0f * (float)(p / 3);
        const bool mirror = p >= 3;
        glBegin(modes[p]);
        for (int i = 0; i < counts[p]; i++) {
            vcolor(i + p);
            const float x = verts[p][i][0] + 0.25f, y = verts[p][i][1] + 0.5f;
            glVertex3f(ox + (mirror ? 32.0f - x : x), oy + y, -0.5f + 0.04f * (float)i);
        }
        glEnd();
    }
}

static void prims_mode(fc_h *h, GLenum mode, GLenum shade)
{
    fc_pixel_ortho(h);
    glShadeModel(shade);
    glPolygonMode(GL_FRONT_AND_BACK, mode);
    fcu_clear(0, 0, 0, 0, 1);
    all_prims();
    fc_capture(h);
    /* larger: wide lines, large points */
    fcu_clear(0, 0, 0, 0, 1);
    glLineWidth(3.0f);
    glPointSize(4.0f);
    all_prims();
    fc_capture(h);
}

static void prims_line_smooth(fc_h *h) { prims_mode(h, GL_LINE, GL_SMOOTH); }
static void prims_line_flat(fc_h *h) { prims_mode(h, GL_LINE, GL_FLAT); }
static void prims_point_smooth(fc_h *h) { prims_mode(h, GL_POINT, GL_SMOOTH); }
static void prims_point_flat(fc_h *h) { prims_mode(h, GL_POINT, GL_FLAT); }

/* Front and back modes different, with each front-face setting and each
 * cull mode: culling replaces a culled face's mode by the other face's
 * (st_atom_rasterizer.c), so front LINE / back FILL with front faces
 * culled is all filled and takes llvmpipe's direct path (other quad
 * diagonal). */
static void front_back_modes(fc_h *h)
{
    static const GLenum pairs[4][2] = {
        { GL_LINE, GL_POINT }, { GL_FILL, GL_LINE }, { GL_POINT, GL_FILL }, { GL_LINE, GL_FILL },
    };
    static const GLenum culls[4] = { 0, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
    fc_pixel_ortho(h);
    glPointSize(2.0f);
    for (int f = 0; f < 8; f++) {
        const GLenum *pm = pairs[f % 4];
        fcu_clear(0, 0, 0, 0, 1);
        glPolygonMode(GL_FRONT, pm[0]);
        glPolygonMode(GL_BACK, pm[1]);
        glFrontFace(f < 4 ? GL_CCW : GL_CW);
        for (int c = 0; c < 4; c++) {
            if (culls[c]) {
                glEnable(GL_CULL_FACE);
                glCullFace(culls[c]);
            } else {
                glDisable(GL_CULL_FACE);
            }
            /* a quad strip and a fan with both windings, one cell each */
            const float ox = 24.0f * (float)c;
            glBegin(GL_QUAD_STRIP);
            for (int i = 0; i < 8; i++) {
                vcolor(i + c);
                glVertex2f(ox + 2.0f + 2.6f * (float)i + ((i & 1) ? 1.5f : 0.0f), (i & 1) ? 30.0f : 3.0f + 0.5f * (float)i);
            }
            glEnd();
            glBegin(GL_TRIANGLE_FAN);
            vcolor(c);
            glVertex2f(ox + 12.0f, 46.0f);
            for (int i = 0; i < 7; i++) {
                vcolor(i + 3);
                const float a = (float)i * 1.1f - (i > 3 ? 2.0f : 0.0f);
                glVertex2f(ox + 12.0f + 10.5f * cosf(a), 46.0f + 12.5f * sinf(a));
            }
            glEnd();
            glBegin(GL_QUADS);   /* a quad (CCW) and its mirror (CW) */
            for (int i = 0; i < 4; i++) {
                vcolor(i);
                glVertex2f(ox + 3.0f + ((i == 1 || i == 2) ? 7.0f : 0.0f), 33.0f + (i >= 2 ? 6.0f : 0.0f) + 0.3f * (float)i);
            }
            for (int i = 3; i >= 0; i--) {
                vcolor(i + 4);
                glVertex2f(ox + 12.0f + ((i == 1 || i == 2) ? 8.0f : 0.0f), 32.5f + (i >= 2 ? 7.0f : 0.0f) + 0.2f * (float)i);
            }
            glEnd();
        }
        fc_capture(h);
    }
}

/* Edge flags: a polygon with hidden diagonals (a convex shape drawn as
 * pieces whose inner edges are off), quads with some edges off, triangles;
 * glEdgeFlag inside and outside glBegin/glEnd (both put the flag in the
 * vertex format), the value 2 (not 1.0: no edge), and a false current edge
 * flag without per-vertex flags, which culls the unfilled faces. */
static void edge_flags(fc_h *h)
{
    fc_pixel_ortho(h);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glPointSize(3.0f);
    for (int f = 0; f < 2; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        if (f == 1)
            glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
        /* a hexagon as two quads sharing a hidden edge */
        glBegin(GL_QUADS);
        for (int q = 0; q < 2; q++) {
            static const float hx[6] = { 10, 22, 28, 22, 10, 4 }, hy[6] = { 4, 4, 14, 24, 24, 14 };
            static const int idx[2][4] = { { 0, 1, 2, 5 }, { 5, 2, 3, 4 } };
            for (int i = 0; i < 4; i++) {
                /* the shared edge 2 -> 5 (quad 0's third vertex) and 5 -> 2
                 * (quad 1's first vertex) are hidden */
                glEdgeFlag((q == 0 && i == 2) || (q == 1 && i == 0) ? GL_FALSE : GL_TRUE);
                vcolor(idx[q][i]);
                glVertex2f(hx[idx[q][i]] + 0.5f, hy[idx[q][i]] + 0.5f);
            }
        }
        glEnd();
        /* a polygon whose every other edge is off, and 2.0 as a flag */
        glBegin(GL_POLYGON);
        for (int i = 0; i < 8; i++) {
            glEdgeFlag(i == 5 ? (GLboolean)2 : (GLboolean)(i & 1));
            vcolor(i);
            const float a = 0.785f * (float)i + 0.2f;
            glVertex2f(46.0f + 14.0f * cosf(a), 16.0f + 13.0f * sinf(a));
        }
        glEnd();
        /* triangles (both windings) with edge flags per vertex */
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 9; i++) {
            glEdgeFlag((GLboolean)((i % 4) != 1));
            vcolor(i);
            const float x = 3.0f + 20.0f * (float)(i / 3) + ((i % 3) == 1 ? 15.0f : 0.0f);
            const float y = 34.0f + ((i % 3) == 2 ? 26.0f : 0.0f) + ((i / 3) == 1 ? 2.0f : 0.0f);
            glVertex2f((i / 3) == 1 && (i % 3) ? x - ((i % 3) == 1 ? 15.0f : -8.0f) : x, y);
        }
        glEnd();
        glEdgeFlag(GL_TRUE);
        fc_capture(h);
    }
    /* glEdgeFlag outside glBegin/glEnd: it joins the vertex format, so the
     * following primitives have per-vertex flags (all false here) */
    fcu_clear(0, 0, 0, 0, 1);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEdgeFlag(GL_FALSE);
    glBegin(GL_TRIANGLES);
    vcolor(1); glVertex2f(4, 4); glVertex2f(30, 6); glVertex2f(10, 28);
    glEnd();
    glEdgeFlag(GL_TRUE);
    glBegin(GL_TRIANGLES);
    vcolor(2); glVertex2f(34, 4); glVertex2f(60, 6); glVertex2f(40, 28);
    glEnd();
    fc_capture(h);
    /* the current edge flag false after a flush (the query makes it
     * current and resets the vertex format): no per-vertex flags, so
     * unfilled faces are culled while filled ones are drawn */
    fcu_clear(0, 0, 0, 0, 1);
    glEdgeFlag(GL_FALSE);
    fc_get_boolean(h, "GL_EDGE_FLAG false", GL_EDGE_FLAG, 1);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_FILL);
    glBegin(GL_QUADS);
    for (int q = 0; q < 2; q++) {
        const float x0 = 4.0f + 30.0f * (float)q;
        vcolor(q);
        if (q == 0) {        /* counter-clockwise: front, outline culled */
            glVertex2f(x0, 4); glVertex2f(x0 + 24, 5); glVertex2f(x0 + 23, 28); glVertex2f(x0 + 1, 27);
        } else {             /* clockwise: back, filled */
            glVertex2f(x0 + 1, 27); glVertex2f(x0 + 23, 28); glVertex2f(x0 + 24, 5); glVertex2f(x0, 4);
        }
    }
    glEnd();
    fc_capture(h);
    glEdgeFlag(GL_TRUE);
    fc_get_boolean(h, "GL_EDGE_FLAG true", GL_EDGE_FLAG, 1);
}

/* Wide and stippled outlines: the stipple counter restarts at each
 * primitive's first triangle (every triangle of GL_TRIANGLES, strips and
 * fans, each quad, once per polygon) and runs on along its edges; large
 * and smooth points; smooth (aaline) outlines, blended. */
static void wide_stippled(fc_h *h)
{
    fc_pixel_ortho(h);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x0f3f);
    fcu_clear(0, 0, 0, 0, 1);
    all_prims();
    fc_capture(h);
    glLineStipple(3, 0x5555);
    glLineWidth(2.0f);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    all_prims();
    fc_capture(h);
    glShadeModel(GL_SMOOTH);
    glDisable(GL_LINE_STIPPLE);
    /* smooth outlines, blended */
    glLineWidth(1.5f);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    fcu_clear(0, 0, 0, 0, 1);
    all_prims();
    fc_capture(h);
    glDisable(GL_LINE_SMOOTH);
    /* points: large, then smooth with stipple on (each point restarts the
     * counter) */
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(5.0f);
    fcu_clear(0, 0, 0, 0, 1);
    all_prims();
    fc_capture(h);
    glEnable(GL_POINT_SMOOTH);
    glPointSize(4.5f);
    fcu_clear(0, 0, 0, 0, 1);
    all_prims();
    fc_capture(h);
    glDisable(GL_POINT_SMOOTH);
    glDisable(GL_BLEND);
}

/* Hidden-line removal: a filled pass with GL_POLYGON_OFFSET_FILL, then the
 * outlines at the same depth with GL_LEQUAL; the reverse (outlines pulled
 * forward by GL_POLYGON_OFFSET_LINE); points with GL_POLYGON_OFFSET_POINT;
 * then front FILL / back LINE in one draw with only one enable on: the
 * first triangle of each draw decides whether the offset stage offsets the
 * whole draw (draw_pipe_offset.c:offset_first_tri). */
static void offset_hidden_line(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    for (int f = 0; f < 3; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glPolygonOffset(f == 1 ? -1.0f : 1.0f, f == 1 ? -1.0f : 1.0f);
        if (f == 0)
            glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        all_prims();
        glDisable(GL_POLYGON_OFFSET_FILL);
        if (f == 1)
            glEnable(GL_POLYGON_OFFSET_LINE);
        if (f == 2)
            glEnable(GL_POLYGON_OFFSET_POINT);
        glPolygonMode(GL_FRONT_AND_BACK, f == 2 ? GL_POINT : GL_LINE);
        glPointSize(2.0f);
        all_prims();
        glDisable(GL_POLYGON_OFFSET_LINE);
        glDisable(GL_POLYGON_OFFSET_POINT);
        fc_capture(h);
    }
    /* the latch: front FILL, back LINE, GL_POLYGON_OFFSET_LINE only, over
     * a plane at the same depth; in one draw whose first triangle is front
     * (no offset for the whole draw), then one whose first is back */
    glDepthFunc(GL_LESS);
    glPolygonOffset(0.0f, -4.0f);
    for (int f = 0; f < 2; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glColor3f(0.3f, 0.3f, 0.3f);
        fcu_rect(0, 0, 96, 64, 0.2f);
        glPolygonMode(GL_FRONT, GL_FILL);
        glPolygonMode(GL_BACK, GL_LINE);
        glEnable(GL_POLYGON_OFFSET_LINE);
        glBegin(GL_TRIANGLES);
        for (int t = 0; t < 6; t++) {
            const bool back = (t % 2) == f;   /* f = 0: front first */
            const float x = 4.0f + 15.0f * (float)t;
            vcolor(t);
            glVertex3f(x, 6.0f, 0.2f);
            if (back) {
                glVertex3f(x + 6.0f, 56.0f, 0.2f);
                glVertex3f(x + 12.0f, 8.0f, 0.2f);
            } else {
                glVertex3f(x + 12.0f, 8.0f, 0.2f);
                glVertex3f(x + 6.0f, 56.0f, 0.2f);
            }
        }
        glEnd();
        glDisable(GL_POLYGON_OFFSET_LINE);
        fc_capture(h);
    }
    glDisable(GL_DEPTH_TEST);
}

/* Lit, two-sided: the twoside stage picks the back colours by the float
 * determinant before the edges are drawn; flat and smooth, with separate
 * specular, front LINE and back POINT. */
static void lit_twoside(fc_h *h)
{
    static const float pos[4] = { 0.3f, 0.4f, 1.0f, 0.0f };
    static const float back_diffuse[4] = { 0.1f, 0.9f, 0.3f, 1.0f };
    fc_pixel_ortho(h);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glMaterialfv(GL_BACK, GL_DIFFUSE, back_diffuse);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glPointSize(3.0f);
    for (int f = 0; f < 3; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glShadeModel(f == 1 ? GL_FLAT : GL_SMOOTH);
        if (f == 2) {
            glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
            glPolygonMode(GL_BACK, GL_POINT);
        }
        glNormal3f(0.2f, 0.3f, 1.0f);
        all_prims();
        fc_capture(h);
    }
}

/* Outlines cut by the near plane (the new edge along the frustum plane is
 * not drawn) and by a user plane (the new edge is drawn), in perspective,
 * flat and smooth, stippled. */
static void clipped_outlines(fc_h *h)
{
    static const double plane[4] = { 1.0, 0.6, 0.0, 0.2 };
    glViewport(0, 0, 64, 64);
    for (int f = 0; f < 4; f++) {
        fcu_frustum(-1, 1, -1, 1, 1, 10);
        fcu_clear(0, 0, 0, 0, 1);
        glPolygonMode(GL_FRONT_AND_BACK, f == 3 ? GL_POINT : GL_LINE);
        glShadeModel(f == 1 ? GL_FLAT : GL_SMOOTH);
        glPointSize(3.0f);
        if (f >= 2) {
            glClipPlane(GL_CLIP_PLANE2, plane);
            glEnable(GL_CLIP_PLANE2);
        }
        if (f == 1) {
            glEnable(GL_LINE_STIPPLE);
            glLineStipple(2, 0x33ff);
        }
        /* a quad strip and a polygon crossing the near plane */
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i < 10; i++) {
            vcolor(i);
            const float z = 0.5f - 0.9f * (float)(i / 2);
            glVertex3f((i & 1) ? 1.4f : -1.6f, -1.3f + 0.1f * (float)i, z);
        }
        glEnd();
        glBegin(GL_POLYGON);
        for (int i = 0; i < 7; i++) {
            vcolor(i + 2);
            const float a = 0.9f * (float)i;
            glVertex3f(0.3f + 1.5f * cosf(a), 0.8f + 1.0f * sinf(a), -2.0f + 2.4f * sinf(a + 0.5f));
        }
        glEnd();
        glBegin(GL_TRIANGLES);
        vcolor(5);
        glVertex3f(-3.0f, 1.5f, -4.0f);
        vcolor(6);
        glVertex3f(-0.5f, -2.0f, 0.3f);
        vcolor(7);
        glVertex3f(-1.0f, 3.0f, -6.0f);
        glEnd();
        glDisable(GL_CLIP_PLANE2);
        glDisable(GL_LINE_STIPPLE);
        fc_capture(h);
    }
}

/* A polygon longer than vsplit's 4096 vertices is drawn as 1024-vertex fan
 * segments: the first triangle of each restarts the stipple counter, and
 * the edges from vertex 0 to a segment's first vertex are not polygon
 * edges.  A star-shaped outline of 5000 vertices, stippled. */
static void long_polygon(fc_h *h)
{
    fc_pixel_ortho(h);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x1f1f);
    for (int f = 0; f < 2; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glBegin(GL_POLYGON);
        const int n = f == 0 ? 5000 : 4096;
        for (int i = 0; i < n; i++) {
            const float a = 6.2831853f * (float)i / (float)n;
            const float r = 10.0f + 20.0f * (float)((i * 37) % 101) / 100.0f;
            glColor3f((float)(i % 7) / 6.0f, (float)(i % 11) / 10.0f, 0.5f);
            glVertex2f(32.0f + r * cosf(a), 32.0f + r * sinf(a));
        }
        glEnd();
        fc_capture(h);
    }
    glDisable(GL_LINE_STIPPLE);
}

/* Errors and queries, and that a rejected call leaves the drawing mode. */
static void polygon_mode_api(fc_h *h)
{
    fc_pixel_ortho(h);
    fc_get_integer(h, "GL_POLYGON_MODE default", GL_POLYGON_MODE, 2);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    fc_get_integer(h, "front line back point", GL_POLYGON_MODE, 2);
    fc_get_double(h, "as double", GL_POLYGON_MODE, 2);
    fc_get_boolean(h, "as boolean", GL_POLYGON_MODE, 2);
    glPolygonMode(GL_FRONT, GL_POINT + 3); fc_error(h, "bad mode");
    glPolygonMode(GL_BACK + 1, GL_FILL); fc_error(h, "bad face");
    glBegin(GL_TRIANGLES);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    vcolor(0); glVertex2f(4, 4); glVertex2f(28, 6); glVertex2f(12, 28);   /* front: GL_LINE */
    vcolor(1); glVertex2f(36, 28); glVertex2f(60, 6); glVertex2f(40, 4);  /* back: GL_POINT */
    glEnd();
    fc_error(h, "inside glBegin/glEnd");
    fc_get_integer(h, "unchanged", GL_POLYGON_MODE, 2);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    vcolor(0); glVertex2f(4, 4); glVertex2f(28, 6); glVertex2f(12, 28);
    vcolor(1); glVertex2f(36, 28); glVertex2f(60, 6); glVertex2f(40, 4);
    glEnd();
    fc_capture(h);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    fc_get_integer(h, "back to fill", GL_POLYGON_MODE, 2);
    fc_error(h, "final");
}

/* Mixed fill modes in one draw with the polygon stipple or smooth lines on:
 * front faces filled, back faces outlined. */
static void mixed_modes_stages(fc_h *h)
{
    GLubyte pat[128];
    for (int i = 0; i < 128; i++)
        pat[i] = (GLubyte)((i & 4) ? 0xcc : 0x33);
    fc_pixel_ortho(h);
    glPolygonStipple(pat);
    for (int f = 0; f < 4; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glPolygonMode(GL_FRONT, f < 2 ? GL_FILL : GL_LINE);
        glPolygonMode(GL_BACK, f < 2 ? GL_LINE : GL_FILL);
        if (f % 2 == 0)
            glEnable(GL_POLYGON_STIPPLE);
        else
            glEnable(GL_LINE_SMOOTH);
        all_prims();
        glDisable(GL_POLYGON_STIPPLE);
        glDisable(GL_LINE_SMOOTH);
        fc_capture(h);
    }
}

/* The polygon stipple and the points and lines of unfilled faces in one
 * draw (draw_pipe_pstipple.c: the stipple shader is bound at the first
 * filled triangle of a draw and kept until the draw ends; draw_pipe_vbuf.c
 * hands llvmpipe each run of points or lines when the primitive type
 * changes): outlines and vertex points after the first filled face, and
 * the run just before it, are stippled; earlier runs and other draws are
 * not.  Frame 0: points, fill, points; 1: wide lines, fill, lines; 2:
 * points, lines (flushing the points unstippled), fill, points; 3: a fill
 * draw, then the points in a GL_QUADS draw (not stippled) and in a second
 * GL_TRIANGLES primitive of the fill's draw (stippled). */
static void stipple_after_fill(fc_h *h)
{
    GLubyte pat[128];
    for (int i = 0; i < 128; i++)
        pat[i] = (GLubyte)((i & 8) ? 0xe3 : 0x5a);
    fc_pixel_ortho(h);
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    glPointSize(7.0f);
    glLineWidth(3.0f);
    /* cell k of a 4 x 2 grid: counter-clockwise (front) or clockwise */
    #define CELL_TRI(k, ccw)                                                        \
        do {                                                                        \
            const float ox = 24.0f * (float)((k) % 4), oy = 32.0f * (float)((k) / 4); \
            vcolor(k); glVertex3f(ox + 2.5f, oy + 3.5f, -0.2f);                     \
            vcolor((k) + 1);                                                        \
            if (ccw) glVertex3f(ox + 21.5f, oy + 5.5f, 0.1f);                       \
            else glVertex3f(ox + 6.5f, oy + 29.5f, 0.1f);                           \
            vcolor((k) + 2);                                                        \
            if (ccw) glVertex3f(ox + 6.5f, oy + 29.5f, 0.3f);                       \
            else glVertex3f(ox + 21.5f, oy + 5.5f, 0.3f);                           \
        } while (0)
    for (int f = 0; f < 4; f++) {
        fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
        glPolygonMode(GL_FRONT, GL_FILL);
        glPolygonMode(GL_BACK, f == 1 ? GL_LINE : GL_POINT);
        if (f < 2) {
            glBegin(GL_TRIANGLES);
            CELL_TRI(0, false);
            CELL_TRI(1, false);
            CELL_TRI(2, true);
            CELL_TRI(3, false);
            CELL_TRI(4, false);
            glEnd();
        } else if (f == 2) {
            glPolygonMode(GL_FRONT, GL_LINE);
            glPolygonMode(GL_BACK, GL_POINT);
            glFrontFace(GL_CW);
            glBegin(GL_TRIANGLES);
            CELL_TRI(0, false);   /* points (back with GL_CW) */
            CELL_TRI(1, true);    /* lines: flush the points */
            glEnd();
            glPolygonMode(GL_FRONT, GL_FILL);
            glBegin(GL_TRIANGLES);
            CELL_TRI(2, true);    /* fill */
            CELL_TRI(3, false);
            CELL_TRI(5, true);
            CELL_TRI(6, false);
            glEnd();
            glPolygonMode(GL_FRONT, GL_LINE);
            glBegin(GL_TRIANGLES);
            CELL_TRI(4, false);
            CELL_TRI(7, true);    /* lines, then a filled face */
            glEnd();
            glFrontFace(GL_CCW);
        } else {
            glBegin(GL_TRIANGLES);
            CELL_TRI(0, true);
            glEnd();
            glBegin(GL_QUADS);
            glVertex2f(26.5f, 3.5f); glVertex2f(26.5f, 28.5f);
            glVertex2f(44.5f, 28.5f); glVertex2f(44.5f, 3.5f);
            glEnd();
            glBegin(GL_TRIANGLES);
            CELL_TRI(2, false);
            CELL_TRI(3, true);
            glEnd();
            glBegin(GL_TRIANGLES);
            CELL_TRI(4, false);
            CELL_TRI(5, false);
            glEnd();
        }
        fc_capture(h);
    }
    #undef CELL_TRI
}

/* Zero-area faces through draw's offset stage (draw_pipe_offset.c:
 * do_offset_tri): det = 0 makes inv_det infinite and the depth slopes NaN,
 * so the offset is NaN even when the face's mode has its offset off
 * (NaN * 0), and SATURATE = CLAMP(z, 0, 1) turns the NaN z into 0: the
 * outlines and points are drawn at depth 0 and pass GL_LESS against 0.5
 * (llvmpipe would clamp a NaN fragment depth to 1).  Frames: lines with
 * GL_POLYGON_OFFSET_FILL on, points with GL_POLYGON_OFFSET_POINT on, a
 * degenerate glRect outlined with both on under GL_EQUAL against 0, and a
 * non-degenerate face in the same draw first (its latch picks the offset). */
static void offset_zero_area(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glLineWidth(3.0f);
    glPointSize(5.0f);
    glPolygonOffset(2.0f, 3.0f);
    for (int f = 0; f < 4; f++) {
        glClearDepth(f == 2 ? 0.0 : 0.5);
        fcu_clear(0, 0, 0, 0, 1);
        glDepthFunc(f == 2 ? GL_EQUAL : GL_LESS);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_POLYGON_OFFSET_LINE);
        glDisable(GL_POLYGON_OFFSET_POINT);
        glPolygonMode(GL_FRONT_AND_BACK, f == 1 ? GL_POINT : GL_LINE);
        if (f == 0 || f == 3)
            glEnable(GL_POLYGON_OFFSET_FILL);
        if (f == 1)
            glEnable(GL_POLYGON_OFFSET_POINT);
        if (f == 2) {
            glEnable(GL_POLYGON_OFFSET_FILL);
            glEnable(GL_POLYGON_OFFSET_LINE);
            glRectf(20.5f, 4.5f, 20.5f, 40.5f);
            glRectf(30.5f, 50.5f, 60.5f, 50.5f);
        } else {
            glBegin(GL_TRIANGLES);
            if (f == 3) {
                glColor3f(0, 0, 1);
                glVertex3f(40.5f, 4.5f, 0.6f); glVertex3f(60.5f, 8.5f, 0.2f); glVertex3f(45.5f, 30.5f, 0.4f);
            }
            glColor3f(1, 0, 0);
            glVertex3f(4.5f, 4.5f, 0.8f); glVertex3f(20.5f, 20.5f, 0.2f); glVertex3f(36.5f, 36.5f, 0.9f);
            glColor3f(0, 1, 0);
            glVertex3f(10.5f, 50.5f, 0.7f); glVertex3f(10.5f, 50.5f, 0.7f); glVertex3f(50.5f, 56.5f, 0.7f);
            glEnd();
        }
        fc_capture(h);
    }
}

/* ---- pseudo-random scenes (a fixed LCG: the same calls on both sides) ---- */

static unsigned lcg_next(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return *s >> 8;
}

static float lcg_float(unsigned *s, float lo, float hi)
{
    return lo + (hi - lo) * (float)(lcg_next(s) & 0xffff) / 65536.0f;
}

/* Random primitives under random unfilled state: modes per face, front
 * face, culling, shading, edge flags, line width and stipple, point size,
 * offset enables, two-sided lighting, a user clip plane, depth test,
 * perspective with near-plane crossings. */
static void random_scenes(fc_h *h)
{
    static const GLenum prims[6] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                     GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    static const GLenum fills[3] = { GL_POINT, GL_LINE, GL_FILL };
    static const GLenum culls[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
    unsigned seed = 4242u;
    glViewport(0, 0, 64, 64);
    static const float pos[4] = { 0.3f, -0.4f, 1.0f, 0.0f };
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glEnable(GL_COLOR_MATERIAL);
    for (int f = 0; f < 8; f++) {
        if (f & 1)
            fcu_frustum(-1, 1, -1, 1, 1, 8);
        else
            fcu_ortho(-1, 1, -1, 1, -1, 1);
        fcu_clear(0, 0, 0, 0, 1);
        for (int d = 0; d < 6; d++) {
            glPolygonMode(GL_FRONT, fills[lcg_next(&seed) % 3]);
            glPolygonMode(GL_BACK, fills[lcg_next(&seed) % 3]);
            glFrontFace(lcg_next(&seed) & 1 ? GL_CW : GL_CCW);
            if (lcg_next(&seed) % 3 == 0) {
                glEnable(GL_CULL_FACE);
                glCullFace(culls[lcg_next(&seed) % 3]);
            } else {
                glDisable(GL_CULL_FACE);
            }
            glShadeModel(lcg_next(&seed) & 1 ? GL_FLAT : GL_SMOOTH);
            glLineWidth((float)(1 + lcg_next(&seed) % 3));
            glPointSize((float)(1 + lcg_next(&seed) % 4));
            if (lcg_next(&seed) % 3 == 0) {
                glEnable(GL_LINE_STIPPLE);
                const GLint repeat = (GLint)(1 + lcg_next(&seed) % 3);
                glLineStipple(repeat, (GLushort)(lcg_next(&seed) | 1u));
            } else {
                glDisable(GL_LINE_STIPPLE);
            }
            const unsigned off = lcg_next(&seed) % 8;
            if (off & 1) glEnable(GL_POLYGON_OFFSET_FILL); else glDisable(GL_POLYGON_OFFSET_FILL);
            if (off & 2) glEnable(GL_POLYGON_OFFSET_LINE); else glDisable(GL_POLYGON_OFFSET_LINE);
            if (off & 4) glEnable(GL_POLYGON_OFFSET_POINT); else glDisable(GL_POLYGON_OFFSET_POINT);
            const float factor = lcg_float(&seed, -2.0f, 2.0f);
            glPolygonOffset(factor, lcg_float(&seed, -4.0f, 4.0f));
            /* no smooth points or lines here: a rasterizer change after a
             * draw that ran draw's aapoint/aaline stage leaves llvmpipe on
             * the previous state (raster/oracle_stale_rasterizer_after_aa) */
            if (lcg_next(&seed) & 1) glEnable(GL_LIGHTING); else glDisable(GL_LIGHTING);
            if (lcg_next(&seed) % 3 == 0) {
                const double px = lcg_float(&seed, -1, 1);
                const double plane[4] = { px, 1.0, 0.3, lcg_float(&seed, -0.5f, 0.5f) };
                glClipPlane(GL_CLIP_PLANE1, plane);
                glEnable(GL_CLIP_PLANE1);
            } else {
                glDisable(GL_CLIP_PLANE1);
            }
            const bool edges = lcg_next(&seed) % 3 == 0;
            const GLenum prim = prims[lcg_next(&seed) % 6];
            const int n = 3 + (int)(lcg_next(&seed) % 10);
            glBegin(prim);
            for (int i = 0; i < n; i++) {
                if (edges)
                    glEdgeFlag((GLboolean)(lcg_next(&seed) % 3 != 0));
                /* one call per statement: a defined order of the draws */
                const float r = lcg_float(&seed, 0, 1), g = lcg_float(&seed, 0, 1);
                glColor3f(r, g, lcg_float(&seed, 0, 1));
                glNormal3f(r - 0.5f, g - 0.5f, 1.0f);
                const float z = (f & 1) ? lcg_float(&seed, -6.0f, 0.5f) : lcg_float(&seed, -0.9f, 0.9f);
                const float s = (f & 1) ? (-z > 0.3f ? -z : 0.3f) : 1.0f;
                const float x = lcg_float(&seed, -1.1f, 1.1f) * s;
                glVertex3f(x, lcg_float(&seed, -1.1f, 1.1f) * s, z);
            }
            glEnd();
            glEdgeFlag(GL_TRUE);
        }
        fc_capture(h);
    }
    glDisable(GL_CLIP_PLANE1);
}

/* An oracle defect (known-differences.txt): when a rasterizer state change
 * follows a draw that ran draw's pipeline with the aapoint (or aaline) stage
 * in it, the stage's flush inside draw_set_rasterizer_state rebinds the
 * previous rasterizer (draw->rast_handle is updated only after the flush),
 * so llvmpipe->rasterizer keeps the old state (flat shading, two-sided
 * lighting, offset of its setup) until the next rasterizer change, while
 * its setup and draw get the new one.  Frame 0: a flat triangle, clipped
 * (the pipeline runs) with GL_POINT_SMOOTH on; frame 1: smooth shading and
 * GL_POINT_SMOOTH off, drawn flat by the oracle; frame 2: after a further
 * rasterizer change (culling on), smooth again. */
static void stale_rasterizer(fc_h *h)
{
    fc_pixel_ortho(h);
    for (int f = 0; f < 3; f++) {
        if (f == 0) {
            glShadeModel(GL_FLAT);
            glEnable(GL_POINT_SMOOTH);
        } else if (f == 1) {
            glShadeModel(GL_SMOOTH);
            glDisable(GL_POINT_SMOOTH);
        } else {
            glEnable(GL_CULL_FACE);
        }
        const float dx = f == 0 ? -10.0f : 0.0f;
        fcu_clear(0, 0, 0, 0, 1);
        glBegin(GL_TRIANGLES);
        glColor3f(1, 0, 0); glVertex2f(2 + dx, 2);
        glColor3f(0, 1, 0); glVertex2f(60 + dx, 4);
        glColor3f(0, 0, 1); glVertex2f(20 + dx, 60);
        glEnd();
        fc_capture(h);
    }
}

const fc_case fc_cases_polygon_mode[] = {
    FC_CASE_RGBA("raster/polygon_mode_line_smooth", 96, 64, 2, "raster polygon_mode", prims_line_smooth),
    FC_CASE_RGBA("raster/polygon_mode_line_flat", 96, 64, 2, "raster polygon_mode", prims_line_flat),
    FC_CASE_RGBA("raster/polygon_mode_point_smooth", 96, 64, 2, "raster polygon_mode", prims_point_smooth),
    FC_CASE_RGBA("raster/polygon_mode_point_flat", 96, 64, 2, "raster polygon_mode", prims_point_flat),
    FC_CASE_RGBA("raster/polygon_mode_front_back", 96, 64, 8, "raster polygon_mode cull", front_back_modes),
    FC_CASE_RGBA("raster/polygon_mode_edge_flags", 64, 64, 4, "raster polygon_mode", edge_flags),
    FC_CASE_RGBA("raster/polygon_mode_wide_stippled", 96, 64, 5, "raster polygon_mode stipple smooth", wide_stippled),
    FC_CASE_RGBA("raster/polygon_mode_offset", 96, 64, 5, "raster polygon_mode offset", offset_hidden_line),
    FC_CASE("raster/polygon_mode_offset_z16", 96, 64, OSMESA_RGBA, 16, 0, 5, "raster polygon_mode offset", offset_hidden_line),
    FC_CASE_RGBA("raster/polygon_mode_lit_twoside", 96, 64, 3, "raster polygon_mode lighting", lit_twoside),
    FC_CASE_RGBA("raster/polygon_mode_clipped", 64, 64, 4, "raster polygon_mode clip", clipped_outlines),
    FC_CASE_RGBA("raster/polygon_mode_long_polygon", 64, 64, 2, "raster polygon_mode stipple", long_polygon),
    FC_CASE_RGBA("raster/polygon_mode_api", 64, 32, 1, "raster polygon_mode api errors query", polygon_mode_api),
    FC_CASE_RGBA("raster/polygon_mode_mixed_stages", 96, 64, 4, "raster polygon_mode stipple smooth", mixed_modes_stages),
    FC_CASE_RGBA("raster/polygon_mode_stipple_after_fill", 96, 64, 4, "raster polygon_mode stipple", stipple_after_fill),
    FC_CASE_RGBA("raster/polygon_mode_offset_zero_area", 64, 64, 4, "raster polygon_mode offset", offset_zero_area),
    FC_CASE_RGBA("raster/polygon_mode_random", 64, 64, 8, "raster polygon_mode offset stipple clip", random_scenes),
    FC_CASE_RGBA("raster/oracle_stale_rasterizer_after_aa", 64, 64, 3, "raster smooth", stale_rasterizer),
    { 0 }
};
