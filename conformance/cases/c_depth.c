/* c_depth.c - depth test: every function with ties, depth mask, depth
 * range (incl. reversed), glClearDepth values, 16/24/32-bit depth and
 * stencil contexts, no depth buffer, disabled test. */
#include "cases.h"

static const GLenum funcs[8] = {
    GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS
};

/* Column per function: reference rect at z = 0, then nearer, equal (tie)
 * and farther rects tested with that function (glOrtho(.., -1, 1) maps
 * object z to window depth 0.5 - z/2). */
static void depth_funcs(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    fcu_clear(0, 0, 0, 0, 1);
    for (int i = 0; i < 8; i++) {
        float x = 8.0f * (float)i;
        glDepthFunc(GL_ALWAYS);
        fcu_color(10);
        fcu_rect(x, 0, x + 8, 32, 0);
        glDepthFunc(funcs[i]);
        fcu_color(0); fcu_rect(x + 1, 2, x + 7, 10, 0.5f);     /* nearer: window z 0.25 */
        fcu_color(1); fcu_rect(x + 1, 12, x + 7, 20, 0);       /* tie */
        fcu_color(2); fcu_rect(x + 1, 22, x + 7, 30, -0.5f);   /* farther: window z 0.75 */
    }
    fc_capture(h);
    fc_get_integer(h, "GL_DEPTH_FUNC", GL_DEPTH_FUNC, 1);
}

/* The same sloped triangle drawn twice with each function: exact
 * interpolated-depth ties. */
static void depth_func_sloped_ties(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    for (int i = 0; i < 8; i++) {
        float x = 8.0f * (float)i;
        glDepthFunc(GL_LESS);
        fcu_color(10);
        glBegin(GL_TRIANGLES);
        glVertex3f(x + 0.3f, 1.2f, -0.9f); glVertex3f(x + 7.9f, 3.3f, 0.77f); glVertex3f(x + 2.1f, 31.0f, 0.1f);
        glEnd();
        glDepthFunc(funcs[i]);
        fcu_color(i);
        glBegin(GL_TRIANGLES);
        glVertex3f(x + 0.3f, 1.2f, -0.9f); glVertex3f(x + 7.9f, 3.3f, 0.77f); glVertex3f(x + 2.1f, 31.0f, 0.1f);
        glVertex3f(x + 0.5f, 30.0f, 0.9f); glVertex3f(x + 7.5f, 1.0f, -0.8f); glVertex3f(x + 7.7f, 31.5f, 0.3f);
        glEnd();
    }
    fc_capture(h);
}

/* Depth mask off: colour written, depth kept; back on. */
static void depth_mask(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    fcu_clear(0, 0, 0, 0, 1);
    glDepthMask(GL_FALSE);
    fc_get_boolean(h, "GL_DEPTH_WRITEMASK off", GL_DEPTH_WRITEMASK, 1);
    fcu_color(0); fcu_rect(2, 2, 20, 20, -0.5f);
    glClearDepth(0.25);
    glClear(GL_DEPTH_BUFFER_BIT);              /* masked: the clear must not write */
    fc_capture(h);
    glDepthMask(GL_TRUE);
    fcu_color(1); fcu_rect(10, 10, 30, 30, 0.2f);
    fcu_color(2); fcu_rect(6, 6, 14, 26, 0.5f);
    fc_capture(h);
    fc_get_boolean(h, "GL_DEPTH_WRITEMASK on", GL_DEPTH_WRITEMASK, 1);
}

/* Interpenetrating smooth triangles under several depth ranges. */
static void depth_scene(void)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(-0.9f, -0.9f, -1.0f);
    glColor3f(1, 1, 0); glVertex3f(0.9f, -0.6f, 1.0f);
    glColor3f(1, 0, 1); glVertex3f(-0.2f, 0.9f, 0.0f);
    glColor3f(0, 1, 0); glVertex3f(-0.9f, 0.5f, 0.9f);
    glColor3f(0, 1, 1); glVertex3f(0.1f, -0.95f, 0.2f);
    glColor3f(0, 0, 1); glVertex3f(0.95f, 0.9f, -0.7f);
    glEnd();
}

static void depth_range(fc_h *h)
{
    static const double r[5][2] = { { 0, 1 }, { 1, 0 }, { 0.25, 0.75 }, { 0.5, 0.5 }, { -1, 2 } };
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    for (int i = 0; i < 5; i++) {
        glDepthRange(r[i][0], r[i][1]);
        fc_get_double(h, "GL_DEPTH_RANGE d", GL_DEPTH_RANGE, 2);
        fc_get_float(h, "GL_DEPTH_RANGE f", GL_DEPTH_RANGE, 2);
        fc_get_integer(h, "GL_DEPTH_RANGE i", GL_DEPTH_RANGE, 2);
        fcu_clear(0, 0, 0, 0, 0.6);
        depth_scene();
        fc_capture(h);
    }
}

static void clear_depth(fc_h *h)
{
    static const double d[7] = { 0.0, 1.0, 0.5, 1.0 / 3.0, -1.0, 2.0, 0.999999 };
    fc_pixel_ortho(h);
    for (int i = 0; i < 7; i++) {
        glClearDepth(d[i]);
        glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
        fc_get_double(h, "GL_DEPTH_CLEAR_VALUE d", GL_DEPTH_CLEAR_VALUE, 1);
        fc_get_float(h, "GL_DEPTH_CLEAR_VALUE f", GL_DEPTH_CLEAR_VALUE, 1);
        fc_get_integer(h, "GL_DEPTH_CLEAR_VALUE i", GL_DEPTH_CLEAR_VALUE, 1);
        fc_capture(h);
    }
}

/* The same depth-sensitive scene for the depth/stencil size cases. */
static void depth_bits(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    fcu_clear(0.2f, 0.2f, 0.2f, 1, 0.7);
    depth_scene();
    fc_capture(h);
    fc_get_integer(h, "GL_DEPTH_BITS", GL_DEPTH_BITS, 1);
    fc_get_integer(h, "GL_STENCIL_BITS", GL_STENCIL_BITS, 1);
}

/* With the test disabled nothing writes depth; then enable and test. */
static void depth_disabled(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    fcu_clear(0, 0, 0, 0, 0.5);
    glDisable(GL_DEPTH_TEST);
    depth_scene();
    fc_capture(h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glColor3f(1, 1, 1);
    fcu_rect(-0.5f, -0.5f, 0.5f, 0.5f, 0.2f);
    fc_capture(h);
}

const fc_case fc_cases_depth[] = {
    FC_CASE_RGBA("core/depth_func_all", 64, 32, 1, "core depth", depth_funcs),
    FC_CASE_RGBA("core/depth_func_sloped_ties", 64, 32, 1, "core depth", depth_func_sloped_ties),
    FC_CASE_RGBA("core/depth_mask", 32, 32, 2, "core depth", depth_mask),
    FC_CASE_RGBA("core/depth_range", 32, 32, 5, "core depth", depth_range),
    /* frames of cleared buffers: the clear depth values (draws_nothing) */
    FC_CASE_NODRAW("core/clear_depth_values", 16, 16, OSMESA_RGBA, 24, 0, 7, "core depth", clear_depth),
    FC_CASE("core/depth_bits_16", 32, 32, OSMESA_RGBA, 16, 0, 1, "core depth", depth_bits),
    FC_CASE("core/depth_bits_24", 32, 32, OSMESA_RGBA, 24, 0, 1, "core depth", depth_bits),
    FC_CASE("core/depth_bits_32", 32, 32, OSMESA_RGBA, 32, 0, 1, "core depth", depth_bits),
    FC_CASE("core/depth_bits_24_stencil_8", 32, 32, OSMESA_RGBA, 24, 8, 1, "core depth", depth_bits),
    FC_CASE("core/depth_bits_16_stencil_8", 32, 32, OSMESA_RGBA, 16, 8, 1, "core depth", depth_bits),
    FC_CASE("core/depth_bits_0_stencil_8", 32, 32, OSMESA_RGBA, 0, 8, 1, "core depth", depth_bits),
    FC_CASE("core/depth_test_without_buffer", 32, 32, OSMESA_RGBA, 0, 0, 1, "core depth", depth_bits),
    FC_CASE_RGBA("core/depth_test_disabled", 32, 32, 2, "core depth", depth_disabled),
    { 0 }
};
