/* c_light_prim.c - lit primitives: every polygon type smooth and flat
 * (flat takes the provoking vertex's lit colour), lit lines and points,
 * and lit geometry crossing the near plane of a glFrustum (clipped
 * vertices interpolate lit colours; the inside of a cut sphere shows its
 * back material with two-sided lighting). */
#include "lt_util.h"

#include <math.h>

static const float k_black[3] = { 0, 0, 0 };
static const float k_dim[3] = { 0.08f, 0.08f, 0.08f };
static const float k_warm[3] = { 0.75f, 0.65f, 0.5f };
static const float k_cool[3] = { 0.25f, 0.35f, 0.6f };
static const float k_white[3] = { 1, 1, 1 };


/* A dome-like normal field over the 32x32 window: every vertex is lit
 * differently. */
static void dome_vertex(const float *v)
{
    glNormal3f((v[0] - 16) / 22, (v[1] - 16) / 22, 1);
    glVertex2fv(v);
}

static void prim_setup(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.05f, 0.06f, 0.12f, 1, 1);
    glEnable(GL_LIGHTING);
    glEnable(GL_NORMALIZE);
    lt_std_material();
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 10);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 24, 26, 18, 1);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_black, -1, -0.4f, 0.6f, 0);
}

/* Frame 1 smooth, frame 2 flat. */
static void lit_prim(fc_h *h, GLenum mode, const float (*v)[2], int n)
{
    prim_setup(h);
    for (int flat = 0; flat < 2; flat++) {
        glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
        fcu_clear(0.05f, 0.06f, 0.12f, 1, 1);
        glBegin(mode);
        for (int i = 0; i < n; i++)
            dome_vertex(v[i]);
        glEnd();
        fc_capture(h);
    }
}

static void lit_triangles(fc_h *h) { lit_prim(h, GL_TRIANGLES, fcu_tri_v, 6); }
static void lit_triangle_strip(fc_h *h) { lit_prim(h, GL_TRIANGLE_STRIP, fcu_strip_v, 8); }
static void lit_triangle_fan(fc_h *h) { lit_prim(h, GL_TRIANGLE_FAN, fcu_fan_v, 7); }
static void lit_quads(fc_h *h) { lit_prim(h, GL_QUADS, fcu_quads_v, 8); }
static void lit_quad_strip(fc_h *h) { lit_prim(h, GL_QUAD_STRIP, fcu_qstrip_v, 8); }
static void lit_polygon(fc_h *h) { lit_prim(h, GL_POLYGON, fcu_poly_v, 6); }

/* Lit points, lines, a line strip and a line loop; smooth then flat. */
static void lit_lines_points(fc_h *h)
{
    prim_setup(h);
    for (int flat = 0; flat < 2; flat++) {
        glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
        fcu_clear(0.05f, 0.06f, 0.12f, 1, 1);
        glBegin(GL_POINTS);
        for (int i = 0; i < 8; i++)
            dome_vertex(fcu_strip_v[i]);
        glEnd();
        glBegin(GL_LINES);
        for (int i = 0; i < 6; i++)
            dome_vertex(fcu_tri_v[i]);
        glEnd();
        glBegin(GL_LINE_LOOP);
        for (int i = 0; i < 6; i++)
            dome_vertex(fcu_poly_v[i]);
        glEnd();
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i < 7; i++)
            dome_vertex(fcu_fan_v[i]);
        glEnd();
        fc_capture(h);
    }
}

/* A floor of six large quads from behind the eye to far away, seen from
 * above at an angle, under a positional light: the near plane cuts the
 * first row, whose clipped vertices interpolate lit vertex colours
 * (smooth; frame 2 flat; frame 3 the light turned into a spot). */
static void near_clip_floor(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 8);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_black, -1, 1, 0.3f, 0);
    glRotatef(15, 1, 0, 0);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.3f, -0.5f, -2.6f, 1);
    for (int f = 0; f < 3; f++) {
        glShadeModel(f == 1 ? GL_FLAT : GL_SMOOTH);
        if (f == 2) {
            lt_light(GL_LIGHT0, GL_SPOT_DIRECTION, -0.2f, -1, -0.4f, 0);
            glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 50);
            glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 2);
        }
        lt_clear();
        glBegin(GL_QUADS);
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 2; i++) {
                float x0 = -3 + 3 * (float)i, z0 = 1 - 4 * (float)j;
                glNormal3f(0.1f * (float)i, 1, 0.1f * (float)j);
                glVertex3f(x0, -1, z0);
                glNormal3f(0, 1, 0);
                glVertex3f(x0 + 3, -1, z0);
                glNormal3f(-0.1f, 1, 0.05f);
                glVertex3f(x0 + 3, -1, z0 - 4);
                glNormal3f(0.05f, 1, -0.1f);
                glVertex3f(x0, -1, z0 - 4);
            }
        glEnd();
        fc_capture(h);
    }
}

/* A sphere cut by the near plane: its inside shows (back faces) with the
 * back material under two-sided lighting (frame 1), one-sided (frame 2). */
static void near_clip_sphere(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_mat(GL_BACK, GL_DIFFUSE, 0.2f, 0.5f, 0.8f, 1);
    lt_mat(GL_BACK, GL_SPECULAR, 0.4f, 0.4f, 0.1f, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.2f, 0.3f, -1.4f, 1);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_black, -1, 1, 0.3f, 0);
    glTranslatef(0.3f, 0.2f, -2.2f);
    glRotatef(30, 1, 1, 0);
    for (int f = 0; f < 2; f++) {
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, !f);
        lt_clear();
        lt_sphere(1.1f, 24, 16);
        fc_capture(h);
    }
}

const fc_case fc_cases_light_prim[] = {
    FC_CASE_RGBA("lighting/lit_triangles", 32, 32, 2, "lighting primitive shade", lit_triangles),
    FC_CASE_RGBA("lighting/lit_triangle_strip", 32, 32, 2, "lighting primitive shade", lit_triangle_strip),
    FC_CASE_RGBA("lighting/lit_triangle_fan", 32, 32, 2, "lighting primitive shade", lit_triangle_fan),
    FC_CASE_RGBA("lighting/lit_quads", 32, 32, 2, "lighting primitive shade", lit_quads),
    FC_CASE_RGBA("lighting/lit_quad_strip", 32, 32, 2, "lighting primitive shade", lit_quad_strip),
    FC_CASE_RGBA("lighting/lit_polygon", 32, 32, 2, "lighting primitive shade", lit_polygon),
    FC_CASE_RGBA("lighting/lit_lines_points", 32, 32, 2, "lighting primitive shade", lit_lines_points),
    FC_CASE_RGBA("lighting/near_clip_floor", 48, 48, 3, "lighting clip perspective", near_clip_floor),
    FC_CASE_RGBA("lighting/near_clip_sphere", 48, 48, 2, "lighting clip two_side", near_clip_sphere),
    { 0 }
};
