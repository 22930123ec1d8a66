/* c_shading_paths.c - GL_WIN_phong_shading through the paths of fixgl's
 * pipeline that the scenes of c_shading.c do not reach: materials that
 * change between glBegin and glEnd (each primitive is lit with the
 * material of its provoking vertex), the vertex colour of colour material
 * outside [0, 1] (a material input, not clamped), quads on llvmpipe's
 * direct path and through draw's pipeline (the diagonal), two-sided
 * lighting while the draw module runs the pipeline for triangles
 * (GL_LINE_SMOOTH), smooth lines and points (draw's aaline/aapoint quads,
 * lit with the quads' own face), stippled and wide lines, and the polygon
 * stipple.
 *
 * Reference cases like c_shading.c's (tag reference, tolerance 1 LSB): on
 * fixgl the case calls glShadeModel(GL_PHONG_WIN); under FC_ORACLE it binds
 * the GLSL reference of conformance/reference/fcr_shading.c.  Where the
 * reference cannot express a call sequence (a glMaterial between glBegin
 * and glEnd reaches a GLSL program only after the draw), the oracle side
 * draws the same primitives with the material set outside glBegin/glEnd. */
#include "lt_util.h"
#include "fcr_shading.h"

#include <math.h>

#ifndef FC_ORACLE
#include <fixgl/fixgl.h>
#endif

#ifdef FC_ORACLE
static const struct fcr_face sp_blinn = { 0, 0.5f, 0.0f, 0.04f };
static struct fcr *sp_ref;
#endif

/* Per-fragment Blinn-Phong for what follows (after the state the reference
 * compiles in: enabled lights, light model, colour material). */
static void sp_begin(fc_h *h)
{
#ifdef FC_ORACLE
    int ok;
    glShadeModel(GL_SMOOTH);
    if (!sp_ref)
        sp_ref = fcr_create((fcr_getproc)OSMesaGetProcAddress);
    ok = sp_ref && fcr_bind(sp_ref, 1, &sp_blinn, &sp_blinn);
    fc_value(h, "reference bound", ok);
#else
    glShadeModel(GL_PHONG_WIN);
    fc_value(h, "reference bound", 1);
#endif
}

static void sp_end(void)
{
#ifdef FC_ORACLE
    if (sp_ref) {
        fcr_unbind(sp_ref);
        fcr_destroy(sp_ref);
        sp_ref = NULL;
    }
#endif
    glShadeModel(GL_SMOOTH);
}

static const float k_dim[3] = { 0.1f, 0.1f, 0.1f };
static const float k_white[3] = { 1, 1, 1 };
static const float k_warm[3] = { 0.85f, 0.75f, 0.6f };

static void sp_scene(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
}

/* A vertex of a dome over [-1,1]^2 (z = 0, the normal bent outwards by
 * `bend`): Gouraud and Phong differ inside big primitives. */
static void sp_dome_vertex(float x, float y, float s, float bend)
{
    glNormal3f(x * bend, y * bend, 1);
    glVertex3f(x * s, y * s, 0);
}

/* ---- materials between glBegin and glEnd --------------------------------- */

/* The material of triangle i of a 4x4 grid.  On the oracle, glMaterial
 * outside glBegin/glEnd only updates the vertex store's current values:
 * the GLSL program's gl_FrontMaterial follows when they are copied to the
 * context (vbo_exec_copy_to_current), which glGetMaterialfv forces
 * (FLUSH_VERTICES, FLUSH_CURRENT); without it a batch of several
 * glBegin/glEnd is drawn with the material of before the batch. */
static void sp_tri_material(int i)
{
    float t = (float)i / 32.0f;
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.9f - 0.6f * t, 0.3f + 0.5f * t, 0.2f + 0.7f * t, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.2f + 0.8f * t, 0.6f, 1.0f - 0.5f * t, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 4.0f + 3.5f * (float)i);
#ifdef FC_ORACLE
    GLfloat sync[4];
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, sync);
#endif
}

/* Triangles of a dome, each with a material of its own set before its
 * last (provoking) vertex; on fixgl all in one glBegin/glEnd, on the
 * oracle one glBegin/glEnd per triangle with the material set before it. */
static void phong_material_in_begin(fc_h *h)
{
    sp_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.4f, 0.5f, -2.8f, 1);
    sp_begin(h);
    glTranslatef(0, 0, -4);
#ifndef FC_ORACLE
    glBegin(GL_TRIANGLES);
#endif
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++)
            for (int k = 0; k < 2; k++) {
                const float x0 = -1 + 0.5f * (float)i, y0 = -1 + 0.5f * (float)j;
                const float x1 = x0 + 0.5f, y1 = y0 + 0.5f;
                const float v[2][3][2] = { { { x0, y0 }, { x1, y0 }, { x1, y1 } },
                                           { { x0, y0 }, { x1, y1 }, { x0, y1 } } };
#ifdef FC_ORACLE
                sp_tri_material(2 * (4 * j + i) + k);
                glBegin(GL_TRIANGLES);
#endif
                for (int c = 0; c < 3; c++) {
#ifndef FC_ORACLE
                    if (c == 1)   /* after the first vertex, before the provoking one */
                        sp_tri_material(2 * (4 * j + i) + k);
#endif
                    sp_dome_vertex(v[k][c][0], v[k][c][1], 1.6f, 0.35f);
                }
#ifdef FC_ORACLE
                glEnd();
#endif
            }
#ifndef FC_ORACLE
    glEnd();
#endif
    fc_capture(h);
    sp_end();
}

/* The same with quads (their provoking vertex is the fourth: a material
 * set before it lights both triangles of the quad) and lines. */
static void phong_material_in_quads_lines(fc_h *h)
{
    sp_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.5f, 0.6f, 1, 0);
    sp_begin(h);
    glTranslatef(0, 0.3f, -4);
    static const float q[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
#ifndef FC_ORACLE
    glBegin(GL_QUADS);
#endif
    for (int i = 0; i < 4; i++) {
        const float ox = -1.2f + 0.8f * (float)i;
#ifdef FC_ORACLE
        sp_tri_material(7 * i + 3);
        glBegin(GL_QUADS);
#endif
        for (int c = 0; c < 4; c++) {
#ifndef FC_ORACLE
            if (c == 3)
                sp_tri_material(7 * i + 3);
#endif
            glNormal3f(q[c][0] * 0.5f, q[c][1] * 0.5f, 1);
            glVertex3f(ox + 0.35f * q[c][0], 0.35f * q[c][1], 0);
        }
#ifdef FC_ORACLE
        glEnd();
#endif
    }
#ifndef FC_ORACLE
    glEnd();
    glBegin(GL_LINE_STRIP);
#endif
    for (int i = 0; i <= 12; i++) {
        const float a = (float)(LT_PI * i / 12);
#ifdef FC_ORACLE
        if (i > 0) {
            /* the line (i-1, i): its provoking vertex is i */
            sp_tri_material(i);
            glBegin(GL_LINES);
            glNormal3f(cosf(a - (float)LT_PI / 12), 0.5f, sinf(a - (float)LT_PI / 12));
            glVertex3f(1.5f * cosf(a - (float)LT_PI / 12), -0.9f + 0.3f * sinf(a - (float)LT_PI / 12), 0);
            glNormal3f(cosf(a), 0.5f, sinf(a));
            glVertex3f(1.5f * cosf(a), -0.9f + 0.3f * sinf(a), 0);
            glEnd();
        }
#else
        if (i > 0)
            sp_tri_material(i);
        glNormal3f(cosf(a), 0.5f, sinf(a));
        glVertex3f(1.5f * cosf(a), -0.9f + 0.3f * sinf(a), 0);
#endif
    }
#ifndef FC_ORACLE
    glEnd();
#endif
    fc_capture(h);
    sp_end();
}

/* ---- colour material outside [0, 1] ---------------------------------------- */

static void phong_color_unclamped(fc_h *h)
{
    static const float col[4][4] = { { 1.6f, -0.3f, 0.4f, 1 }, { -0.5f, 1.4f, 0.2f, 1 },
                                     { 0.3f, 0.2f, 2.0f, 1 }, { 1.2f, 1.1f, -0.8f, 1 } };
    sp_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.3f, 0.4f, 1, 0);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    sp_begin(h);
    glTranslatef(0, 0, -4);
    glBegin(GL_TRIANGLE_FAN);
    glColor4f(0.5f, 0.5f, 0.5f, 1);
    sp_dome_vertex(0, 0, 1.6f, 0.3f);
    for (int i = 0; i <= 8; i++) {
        const float a = (float)(2 * LT_PI * i / 8);
        glColor4fv(col[i % 4]);
        sp_dome_vertex(cosf(a), sinf(a), 1.6f, 0.3f);
    }
    glEnd();
    fc_capture(h);
    sp_end();
    glDisable(GL_COLOR_MATERIAL);
}

/* ---- quads: the diagonal ---------------------------------------------------- */

/* Big quads with bent normals: llvmpipe's direct path splits them
 * (0,1,2)+(0,2,3); a quad strip and a draw with a vertex beyond the left
 * edge (draw's pipeline) split (0,1,3)+(1,2,3). */
static void phong_quads(fc_h *h)
{
    sp_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.6f, -0.2f, -3.0f, 1);
    sp_begin(h);
    glTranslatef(0, 0, -4);
    for (int pass = 0; pass < 2; pass++) {
        const float ox = pass ? -2.3f : -0.6f, oy = pass ? -0.9f : 0.7f;
        glBegin(GL_QUADS);
        glNormal3f(-0.6f, -0.1f, 1);
        glVertex3f(ox - 0.6f, oy - 0.6f, 0);
        glNormal3f(0.2f, -0.5f, 1);
        glVertex3f(ox + 0.7f, oy - 0.5f, 0);
        glNormal3f(0.6f, 0.4f, 1);
        glVertex3f(ox + 0.6f, oy + 0.6f, 0.2f);
        glNormal3f(-0.2f, 0.7f, 1);
        glVertex3f(ox - 0.5f, oy + 0.5f, 0);
        glEnd();
    }
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= 3; i++) {
        const float x = 0.4f + 0.45f * (float)i;
        glNormal3f(0.4f * (float)(i - 1), -0.5f, 1);
        glVertex3f(x, -1.5f, 0.1f * (float)i);
        glNormal3f(-0.3f * (float)(i - 1), 0.6f, 1);
        glVertex3f(x, -0.3f, -0.1f * (float)i);
    }
    glEnd();
    fc_capture(h);
    sp_end();
}

/* Homogeneous vertices: w near 0 (a point far away, clipped by the view
 * volume) and w negative, with an orthographic and a perspective
 * projection; the eye position the lighting uses is the modelview times
 * the vertex, xyz (its w ignored, shading.md), interpolated like every
 * varying of the clipped polygon. */
static void phong_homogeneous_w(fc_h *h)
{
    static const float v[3][4][4] = {
        { { -0.8f, -0.7f, 0, 1 }, { 0.02f, 0.01f, 0, 0.015f }, { -0.6f, 0.8f, 0.1f, 1 }, { 0 } },
        { { 0.1f, -0.9f, 0, 1 }, { 0.9f, -0.5f, 0.2f, 1 }, { 0.5f, 0.4f, -0.1f, -0.8f }, { 0 } },
        { { -0.2f, 0.9f, 0, 0.5f }, { 0.9f, 0.9f, 0, 1 }, { 0.4f, 0.1f, 0, 0.05f }, { 0 } },
    };
    for (int persp = 0; persp < 2; persp++) {
        if (persp)
            sp_scene(h);
        else {
            lt_ortho(h, 1.0f);
            glEnable(GL_LIGHTING);
            lt_std_material();
        }
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
        lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.2f, 0.3f, 0.5f, 1);
        sp_begin(h);
        if (persp)
            glTranslatef(0, 0, -2.5f);
        glBegin(GL_TRIANGLES);
        for (int t = 0; t < 3; t++)
            for (int c = 0; c < 3; c++) {
                glNormal3f(v[t][c][0] + 0.2f, v[t][c][1] - 0.1f, 1);
                glVertex4fv(v[t][c]);
            }
        glEnd();
        fc_capture(h);
        sp_end();
        lt_clear();
    }
}

/* ---- the draw module's stages -------------------------------------------- */

/* Two-sided lighting with GL_LINE_SMOOTH on: fixed-function two-sided
 * colours would take draw's pipeline for the triangles (quads split
 * (0,1,3)); under GL_PHONG_WIN there are none, as for the reference.
 * Then smooth lines, blended: draw's aaline quads. */
static void phong_two_sided_smooth_lines(fc_h *h)
{
    sp_scene(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    lt_mat(GL_BACK, GL_DIFFUSE, 0.2f, 0.7f, 0.9f, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.2f, 0.3f, 1, 0);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    sp_begin(h);
    glTranslatef(0, 0, -4);
    for (int face = 0; face < 2; face++) {
        /* inside the view volume: no clipping, llvmpipe's direct path */
        const float ox = face ? 0.55f : -0.55f, nz = face ? -1.0f : 1.0f;
        glBegin(GL_QUADS);
        for (int c = 0; c < 4; c++) {
            static const float q[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
            /* the back quad is wound clockwise */
            const int k = face ? 3 - c : c;
            /* not affine in the position: the diagonal shows */
            glNormal3f(0.6f * q[k][0], 0.6f * q[k][1], nz * (1.0f + 0.5f * q[k][0] * q[k][1]));
            glVertex3f(ox + 0.45f * q[k][0], 0.3f + 0.45f * q[k][1], 0);
        }
        glEnd();
    }
    glLineWidth(2);
    glBegin(GL_LINES);
    for (int i = 0; i < 6; i++) {
        const float a = (float)(LT_PI * i / 6);
        glNormal3f(0, 0, 1);
        glVertex3f(-1.4f, -0.8f - 0.1f * (float)i, 0.2f);
        glNormal3f(cosf(a), sinf(a), 0.4f);
        glVertex3f(1.4f, -1.3f + 0.08f * (float)i, -0.2f);
    }
    glEnd();
    glLineWidth(1);
    fc_capture(h);
    sp_end();
    glDisable(GL_BLEND);
    glDisable(GL_LINE_SMOOTH);
}

/* Smooth points (draw's aapoint quads), one-sided and two-sided: the
 * quads are triangles, lit with the face their own winding gives them
 * (the no-cull rasterizer of the stage, front_ccw); then the smooth points
 * of a two-sided sphere's polygons in GL_POINT mode (the back faces' too:
 * their quads are still triangles of their own, whatever face draw's
 * unfilled stage gave their vertices).  (Smooth lines of GL_LINE polygons
 * with the GLSL reference bound crash the oracle: not drawn.) */
static void phong_smooth_points(fc_h *h)
{
    sp_scene(h);
    lt_mat(GL_BACK, GL_DIFFUSE, 0.2f, 0.7f, 0.9f, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.5f, 0.5f, 1, 0);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int two = 0; two < 2; two++) {
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, two);
        sp_begin(h);
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        glPointSize(5);
        glBegin(GL_POINTS);
        for (int i = 0; i < 7; i++)
            for (int j = 0; j < 5; j++) {
                const float x = -1.5f + 0.5f * (float)i, y = -1 + 0.5f * (float)j;
                glNormal3f(0.5f * x, 0.5f * y, 1);
                glVertex3f(x, y, 0);
            }
        glEnd();
        glPointSize(1);
        fc_capture(h);
        sp_end();
    }
    lt_clear();
    sp_begin(h);
    glLoadIdentity();
    glTranslatef(0, 0, -4);
    glRotatef(30, 1, 0, 0);
    glPointSize(3);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    lt_sphere(1.3f, 10, 6);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glPointSize(1);
    fc_capture(h);
    sp_end();
    glDisable(GL_BLEND);
    glDisable(GL_POINT_SMOOTH);
}

/* Stippled and wide lines: draw's stipple stage cuts a line into
 * segments whose ends (and their normals and eye positions) it lerps in
 * window space, 1/w included. */
static void phong_line_stipple(fc_h *h)
{
    sp_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.5f, 0.8f, -2.5f, 1);
    sp_begin(h);
    glTranslatef(0, 0, -4);
    glRotatef(-50, 1, 0, 0);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x3f5a);
    for (int w = 1; w <= 3; w += 2) {
        glLineWidth((float)w);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= 10; i++) {
            const float a = (float)(LT_PI * i / 10);
            glNormal3f(cosf(a), 0.6f, sinf(a));
            glVertex3f(1.6f * cosf(a), -0.6f + 0.8f * (float)w / 3.0f, 1.2f * sinf(a) - 0.4f);
        }
        glEnd();
    }
    glLineWidth(1);
    glDisable(GL_LINE_STIPPLE);
    fc_capture(h);
    sp_end();
}

/* The polygon stipple's kill before the lighting of every fragment. */
static void phong_polygon_stipple(fc_h *h)
{
    GLubyte pattern[128];
    for (int i = 0; i < 128; i++)
        pattern[i] = (GLubyte)((i / 4) & 1 ? 0xcc : 0x5a);
    sp_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.3f, 0.4f, 1, 0);
    glEnable(GL_POLYGON_STIPPLE);
    glPolygonStipple(pattern);
    sp_begin(h);
    glTranslatef(0, 0, -4);
    lt_sphere(1.4f, 20, 12);
    fc_capture(h);
    sp_end();
    glDisable(GL_POLYGON_STIPPLE);
}

#define SP_CASE(name, w, h, frames, fn) \
    { name, w, h, OSMESA_RGBA, 24, 0, frames, "shading reference phong", fn, 0, 0, 1, 0 }

const fc_case fc_cases_shading_paths[] = {
    SP_CASE("shading/phong_material_in_begin", 64, 64, 1, phong_material_in_begin),
    SP_CASE("shading/phong_material_in_quads_lines", 64, 64, 1, phong_material_in_quads_lines),
    SP_CASE("shading/phong_color_unclamped", 48, 48, 1, phong_color_unclamped),
    SP_CASE("shading/phong_quads", 64, 64, 1, phong_quads),
    SP_CASE("shading/phong_homogeneous_w", 64, 64, 2, phong_homogeneous_w),
    SP_CASE("shading/phong_two_sided_smooth_lines", 64, 64, 1, phong_two_sided_smooth_lines),
    SP_CASE("shading/phong_smooth_points", 64, 48, 3, phong_smooth_points),
    SP_CASE("shading/phong_line_stipple", 64, 64, 1, phong_line_stipple),
    SP_CASE("shading/phong_polygon_stipple", 48, 48, 1, phong_polygon_stipple),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
