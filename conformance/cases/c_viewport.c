/* c_viewport.c - odd viewports: negative offsets, partially outside, 1x1,
 * zero and invalid sizes, odd sizes, larger than the maximum. */
#include "cases.h"

/* A smooth NDC scene: a full-viewport quad and a triangle touching the
 * viewport edges, drawn into the given viewport. */
static void vp_scene(GLint x, GLint y, GLsizei w, GLsizei h)
{
    glViewport(x, y, w, h);
    glBegin(GL_QUADS);
    glColor3f(0.2f, 0, 0); glVertex2f(-1, -1);
    glColor3f(0, 0.2f, 0); glVertex2f(1, -1);
    glColor3f(0, 0, 0.2f); glVertex2f(1, 1);
    glColor3f(0.2f, 0.2f, 0); glVertex2f(-1, 1);
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-1, -1);
    glColor3f(0, 1, 0); glVertex2f(1, -0.5f);
    glColor3f(0, 0, 1); glVertex2f(0.25f, 1);
    glEnd();
}

static void vp_case(fc_h *h, const GLint (*v)[4], int n)
{
    fcu_clear(0, 0, 0, 0, 1);
    for (int i = 0; i < n; i++) {
        vp_scene(v[i][0], v[i][1], v[i][2], v[i][3]);
        fc_error(h, "glViewport");
        fc_get_integer(h, "GL_VIEWPORT", GL_VIEWPORT, 4);
        fc_get_float(h, "GL_VIEWPORT f", GL_VIEWPORT, 4);
    }
    fc_capture(h);
}

static void vp_negative(fc_h *h)
{
    static const GLint v[2][4] = { { -7, -3, 20, 18 }, { -40, 10, 45, 9 } };
    vp_case(h, v, 2);
}

static void vp_partial(fc_h *h)
{
    static const GLint v[2][4] = { { 20, 12, 30, 40 }, { 3, 25, 100, 7 } };
    vp_case(h, v, 2);
}

static void vp_tiny(fc_h *h)
{
    static const GLint v[4][4] = { { 3, 4, 1, 1 }, { 10, 10, 1, 2 }, { 20, 5, 2, 1 }, { 31, 31, 1, 1 } };
    vp_case(h, v, 4);
}

static void vp_zero(fc_h *h)
{
    static const GLint v[3][4] = { { 5, 5, 0, 0 }, { 5, 5, 0, 10 }, { 5, 5, 10, 0 } };
    vp_case(h, v, 3);
}

static void vp_invalid(fc_h *h)
{
    static const GLint v[3][4] = { { 4, 4, 20, 20 }, { 0, 0, -1, 10 }, { 0, 0, 10, -5 } };
    vp_case(h, v, 3);
}

static void vp_odd(fc_h *h)
{
    static const GLint v[2][4] = { { 3, 5, 37, 23 }, { 1, 2, 13, 29 } };
    vp_case(h, v, 2);
}

static void vp_huge(fc_h *h)
{
    static const GLint v[2][4] = { { -20000, -100, 50000, 40000 }, { 2, 3, 16384, 16385 } };
    vp_case(h, v, 2);
    fc_get_integer(h, "GL_MAX_VIEWPORT_DIMS", GL_MAX_VIEWPORT_DIMS, 2);
}

/* Viewport changed between primitives of the same frame and depth range. */
static void vp_sequence(fc_h *h)
{
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    for (int i = 0; i < 6; i++) {
        glDepthRange(0.1 * i, 1.0 - 0.15 * i);
        vp_scene(5 * i - 3, 7 * i - 5, 17 + 3 * i, 11 + 4 * i);
    }
    fc_capture(h);
}

const fc_case fc_cases_viewport[] = {
    FC_CASE_RGBA("core/viewport_negative_offset", 32, 32, 1, "core viewport", vp_negative),
    FC_CASE_RGBA("core/viewport_partially_outside", 32, 32, 1, "core viewport", vp_partial),
    FC_CASE_RGBA("core/viewport_1x1", 32, 32, 1, "core viewport", vp_tiny),
    /* a viewport of zero width or height draws nothing (draws_nothing) */
    FC_CASE_NODRAW("core/viewport_zero_size", 32, 32, OSMESA_RGBA, 24, 0, 1, "core viewport", vp_zero),
    FC_CASE_RGBA("core/viewport_negative_size_error", 32, 32, 1, "core viewport error", vp_invalid),
    FC_CASE_RGBA("core/viewport_odd_size", 48, 40, 1, "core viewport", vp_odd),
    FC_CASE_RGBA("core/viewport_beyond_max", 32, 32, 1, "core viewport", vp_huge),
    FC_CASE_RGBA("core/viewport_sequence", 48, 48, 1, "core viewport depth", vp_sequence),
    { 0 }
};
