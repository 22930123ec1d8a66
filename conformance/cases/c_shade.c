/* c_shade.c - smooth vs flat shading and the provoking vertex of every
 * primitive type, the batch-dependent GL_QUADS diagonal, perspective-correct
 * colour and colour rounding ties. */
#include "cases.h"


static void draw_prim(GLenum mode, const float (*v)[2], int n)
{
    glBegin(mode);
    for (int i = 0; i < n; i++) {
        fcu_color(i);
        glVertex2fv(v[i]);
    }
    glEnd();
}

/* Frame 1 smooth, frame 2 flat (shows the provoking vertex of each triangle). */
static void shade_prim(fc_h *h, GLenum mode, const float (*v)[2], int n)
{
    fc_pixel_ortho(h);
    for (int flat = 0; flat < 2; flat++) {
        glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
        fcu_clear(0, 0, 0, 0, 1);
        draw_prim(mode, v, n);
        fc_capture(h);
    }
    fc_get_integer(h, "GL_SHADE_MODEL", GL_SHADE_MODEL, 1);
}

static void shade_triangles(fc_h *h) { shade_prim(h, GL_TRIANGLES, fcu_tri_v, 6); }
static void shade_strip(fc_h *h) { shade_prim(h, GL_TRIANGLE_STRIP, fcu_strip_v, 8); }
static void shade_fan(fc_h *h) { shade_prim(h, GL_TRIANGLE_FAN, fcu_fan_v, 7); }
static void shade_quads(fc_h *h) { shade_prim(h, GL_QUADS, fcu_quads_v, 8); }
static void shade_quad_strip(fc_h *h) { shade_prim(h, GL_QUAD_STRIP, fcu_qstrip_v, 8); }
static void shade_polygon(fc_h *h) { shade_prim(h, GL_POLYGON, fcu_poly_v, 6); }

/* The smooth quad of probe t19 in a [0,1] ortho view. */
static void quad_a(void)
{
    static const float v[4][2] = { { 0, 0 }, { 0.5f, 0 }, { 0.5f, 0.5f }, { 0, 0.5f } };
    static const float c[4][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
    for (int i = 0; i < 4; i++) {
        glColor3fv(c[i]);
        glVertex2fv(v[i]);
    }
}

/* A second quad, crossing the right clip plane when off > 0. */
static void quad_b(float off)
{
    glColor3f(1, 1, 1);
    glVertex2f(0.6f, 0.6f);
    glColor3f(0, 1, 0);
    glVertex2f(0.9f + off, 0.6f);
    glColor3f(1, 0, 1);
    glVertex2f(0.9f + off, 0.9f);
    glColor3f(0, 0, 1);
    glVertex2f(0.6f, 0.9f);
}

static void quad_setup(void)
{
    glViewport(0, 0, 32, 32);
    fcu_ortho(0, 1, 0, 1, -1, 1);
    glShadeModel(GL_SMOOTH);
    fcu_clear(0, 0, 0, 0, 1);
}

static void quad_alone(fc_h *h)
{
    quad_setup();
    glBegin(GL_QUADS); quad_a(); glEnd();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_QUADS); quad_a(); quad_b(0); glEnd();         /* unclipped partner */
    fc_capture(h);
}

static void quad_clipped_same_begin(fc_h *h)
{
    quad_setup();
    glBegin(GL_QUADS); quad_a(); quad_b(0.5f); glEnd();
    fc_capture(h);
}

static void quad_clipped_separate_begin(fc_h *h)
{
    quad_setup();
    glBegin(GL_QUADS); quad_a(); glEnd();
    glBegin(GL_QUADS); quad_b(0.5f); glEnd();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);                    /* a state change splits the batch */
    glBegin(GL_QUADS); quad_a(); glEnd();
    glShadeModel(GL_SMOOTH);
    glDepthFunc(GL_LEQUAL);
    glBegin(GL_QUADS); quad_b(0.5f); glEnd();
    fc_capture(h);
}

static void quad_strip_and_polygon_clipped(fc_h *h)
{
    quad_setup();
    glBegin(GL_QUAD_STRIP);
    glColor3f(1, 0, 0); glVertex2f(0.05f, 0.05f);
    glColor3f(0, 1, 0); glVertex2f(0.05f, 0.45f);
    glColor3f(0, 0, 1); glVertex2f(0.45f, 0.1f);
    glColor3f(1, 1, 1); glVertex2f(0.4f, 0.4f);
    glColor3f(1, 1, 0); glVertex2f(1.4f, 0.2f);
    glColor3f(0, 1, 1); glVertex2f(1.3f, 0.5f);
    glEnd();
    glBegin(GL_POLYGON);
    glColor3f(1, 0, 0); glVertex2f(0.1f, 0.6f);
    glColor3f(0, 1, 0); glVertex2f(0.5f, 0.55f);
    glColor3f(0, 0, 1); glVertex2f(0.55f, 0.95f);
    glColor3f(1, 1, 1); glVertex2f(0.2f, 1.3f);
    glEnd();
    fc_capture(h);
}

/* Three flat-shaded quads whose diagonal shows: a non-planar one (depth
 * along the diagonal), a concave dart (coverage) and one whose 2nd and 4th
 * vertices coincide (only the (0,2) diagonal draws anything). */
static void flat_quads(int colour_per_vertex)
{
    static const float v[12][3] = {
        { 0.05f, 0.05f, 0.9f }, { 0.45f, 0.05f, -0.9f }, { 0.45f, 0.45f, 0.9f }, { 0.05f, 0.45f, -0.9f },
        { 0.55f, 0.55f, 0.0f }, { 0.95f, 0.55f, 0.5f }, { 0.65f, 0.65f, -0.5f }, { 0.55f, 0.95f, 0.2f },
        { 0.55f, 0.05f, 0.3f }, { 0.75f, 0.25f, -0.6f }, { 0.95f, 0.45f, 0.3f }, { 0.75f, 0.25f, -0.6f },
    };
    glBegin(GL_QUADS);
    for (int i = 0; i < 12; i++) {
        if (colour_per_vertex)
            glColor3f(i & 1 ? 1.0f : 0.25f, i & 2 ? 1.0f : 0.5f, 0.75f);
        glVertex3fv(v[i]);
    }
    glEnd();
}

/* The direct path's quad diagonal follows the setup's constant-interpolated
 * inputs, not the shade model: a flat batch whose colour is not a
 * fragment-shader input (unlit, colour outside the vertex format) is split
 * (0,1,2)+(0,2,3) like a smooth one (lp_setup_vbuf.c rect() when
 * !uses_constant_interp). */
static void quad_flat_constant_colour(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_ortho(0, 1, 0, 1, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    glColor3f(0.25f, 0.5f, 0.75f);
    flat_quads(0);                               /* colour constant: (0,2) */
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    flat_quads(1);                               /* flat colour input: (1,3) */
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LIGHTING);                       /* lit: always an input */
    glEnable(GL_LIGHT0);
    glNormal3f(0, 0, 1);
    flat_quads(0);
    fc_capture(h);
}

/* The flat colour is a constant-interpolated input only when the fragment
 * program still reads it after dead code goes: a GL_REPLACE unit of an
 * RGBA texture after it leaves no live use, and the direct path splits
 * (0,1,2)+(0,2,3) as for a smooth batch; a GL_ALPHA texture, a
 * GL_MODULATE unit, a GL_COMBINE source GL_PRIMARY_COLOR or the colour
 * sum keep it (the random-tex witness, s2-i107). */
static void quad_flat_dead_colour(fc_h *h)
{
    static const GLubyte rgba[2 * 2 * 4] = { 200, 40, 90, 255, 30, 220, 60, 128,
                                             90, 90, 250, 64, 250, 250, 20, 200 };
    static const GLubyte alpha[4] = { 40, 90, 160, 230 };
    GLuint t[2];
    glViewport(0, 0, 32, 32);
    fcu_ortho(0, 1, 0, 1, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    glGenTextures(2, t);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 2, 2, 0, GL_ALPHA, GL_UNSIGNED_BYTE, alpha);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glMultiTexCoord2f(GL_TEXTURE1, 0.75f, 0.75f);
    for (int f = 0; f < 8; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, t[f == 2 ? 1 : 0]);
        glEnable(GL_TEXTURE_2D);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, f == 1 ? GL_MODULATE : GL_REPLACE);
        if (f == 3) {                           /* unit 0 modulates, unit 1 replaces */
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_2D, t[0]);
            glEnable(GL_TEXTURE_2D);
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        }
        if (f == 4) {                           /* COMBINE: texture times PRIMARY_COLOR */
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
            glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
            glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_PRIMARY_COLOR);
        }
        if (f >= 5) {                           /* lit: dead, then the colour sum */
            glEnable(GL_LIGHTING);
            glEnable(GL_LIGHT0);
            glNormal3f(0, 0, 1);
            glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                          f == 6 ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
            if (f == 7)
                glEnable(GL_COLOR_SUM);
        }
        flat_quads(1);
        fc_capture(h);
        glActiveTexture(GL_TEXTURE1);
        glDisable(GL_TEXTURE_2D);
        glActiveTexture(GL_TEXTURE0);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        glDisable(GL_LIGHTING);
        glDisable(GL_COLOR_SUM);
    }
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(2, t);
}

/* A large smooth triangle with very different w per vertex. */
static void persp_colour(fc_h *h)
{
    glViewport(0, 0, 128, 128);
    fcu_frustum(-1, 1, -1, 1, 1, 100);
    glShadeModel(GL_SMOOTH);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(-1.5f, -1.2f, -1.5f);
    glColor3f(0, 1, 0); glVertex3f(60.0f, -50.0f, -90.0f);
    glColor3f(0, 0, 1); glVertex3f(-20.0f, 35.0f, -40.0f);
    glColor4f(1, 1, 0, 0.5f); glVertex3f(0.9f, 0.9f, -1.0f);
    glColor4f(0, 1, 1, 0.25f); glVertex3f(3.0f, 0.5f, -5.0f);
    glColor4f(1, 0, 1, 1); glVertex3f(0.2f, 3.0f, -6.0f);
    glEnd();
    fc_capture(h);
}

/* Gradients whose per-pixel values straddle the x.5/255 rounding ties,
 * plus out-of-range vertex colours (clamped per vertex). */
static void colour_ties(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_SMOOTH);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_QUADS);
    glColor3f(0.5f / 255.0f, 128.5f / 255.0f, 1.0f);
    glVertex2f(0, 0);
    glColor3f(64.5f / 255.0f, 0.5f, 254.5f / 255.0f);
    glVertex2f(64, 0);
    glColor3f(64.5f / 255.0f, 0.5f, 254.5f / 255.0f);
    glVertex2f(64, 16);
    glColor3f(0.5f / 255.0f, 128.5f / 255.0f, 1.0f);
    glVertex2f(0, 16);
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor4f(2.0f, -1.0f, 0.5f, 3.0f); glVertex2f(0, 17);
    glColor4f(-0.5f, 1.5f, 1e30f, -2.0f); glVertex2f(64, 20);
    glColor4f(0.25f, 0.75f, -1e30f, 0.5f); glVertex2f(20, 64);
    glEnd();
    fc_capture(h);
}

const fc_case fc_cases_shade[] = {
    FC_CASE_RGBA("core/shade_triangles", 32, 32, 2, "core shade", shade_triangles),
    FC_CASE_RGBA("core/shade_triangle_strip", 32, 32, 2, "core shade", shade_strip),
    FC_CASE_RGBA("core/shade_triangle_fan", 32, 32, 2, "core shade", shade_fan),
    FC_CASE_RGBA("core/shade_quads", 32, 32, 2, "core shade", shade_quads),
    FC_CASE_RGBA("core/shade_quad_strip", 32, 32, 2, "core shade", shade_quad_strip),
    FC_CASE_RGBA("core/shade_polygon", 32, 32, 2, "core shade", shade_polygon),
    FC_CASE_RGBA("core/quad_diagonal_alone", 32, 32, 2, "core shade quad", quad_alone),
    FC_CASE_RGBA("core/quad_diagonal_clipped_same_begin", 32, 32, 1, "core shade quad clip",
                 quad_clipped_same_begin),
    FC_CASE_RGBA("core/quad_diagonal_clipped_separate_begin", 32, 32, 2, "core shade quad clip",
                 quad_clipped_separate_begin),
    FC_CASE_RGBA("core/quad_strip_polygon_clipped", 32, 32, 1, "core shade quad clip",
                 quad_strip_and_polygon_clipped),
    FC_CASE_RGBA("core/quad_diagonal_flat_constant_colour", 32, 32, 3, "core shade quad",
                 quad_flat_constant_colour),
    FC_CASE_RGBA("core/quad_diagonal_flat_dead_colour", 32, 32, 8, "core shade quad",
                 quad_flat_dead_colour),
    FC_CASE_RGBA("core/perspective_colour_large", 128, 128, 1, "core shade perspective", persp_colour),
    FC_CASE_RGBA("core/colour_rounding_ties", 64, 64, 1, "core shade", colour_ties),
    { 0 }
};
