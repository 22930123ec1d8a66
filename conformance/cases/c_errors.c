/* c_errors.c - bad input: invalid enums and values, commands that are not
 * allowed between glBegin/glEnd, nested glBegin, glEnd without glBegin, and
 * the first-error-wins rule.  The error is recorded after every call. */
#include "cases.h"

static void invalid_enums(fc_h *h)
{
    GLint iv[4];
    glMatrixMode(0x1234); fc_error(h, "glMatrixMode");
    glDepthFunc(GL_NEVER - 1); fc_error(h, "glDepthFunc below range");
    glDepthFunc(GL_ALWAYS + 1); fc_error(h, "glDepthFunc above range");
    glShadeModel(GL_FLAT + 2); fc_error(h, "glShadeModel");
    glEnable(0); fc_error(h, "glEnable(0)");
    /* GL_PATCHES + 1: bad in every version (GL_POLYGON + 1, an adjacency
     * mode, is foreign to GL 1.5: honesty/primitive_modes) */
    glBegin(0xF); fc_error(h, "glBegin(bad mode)");
    glVertex2f(0, 0); fc_error(h, "glVertex after failed glBegin");
    glEnd(); fc_error(h, "glEnd after failed glBegin");
    glGetIntegerv(0x1234, iv); fc_error(h, "glGetIntegerv");
    glClear(0x80000000u); fc_error(h, "glClear(bad bit)");
    glClear(GL_ACCUM_BUFFER_BIT); fc_error(h, "glClear(GL_ACCUM_BUFFER_BIT)");
    glClear(GL_STENCIL_BUFFER_BIT); fc_error(h, "glClear(GL_STENCIL_BUFFER_BIT)");
    fc_get_integer(h, "GL_SHADE_MODEL unchanged", GL_SHADE_MODEL, 1);
    fc_get_integer(h, "GL_DEPTH_FUNC unchanged", GL_DEPTH_FUNC, 1);
    fc_get_integer(h, "GL_MATRIX_MODE unchanged", GL_MATRIX_MODE, 1);
}

/* Each disallowed command in its own glBegin/glEnd block, the error read
 * after glEnd (glGetError itself is disallowed inside); the triangles of
 * the blocks still draw and are captured. */
static void inside_begin_end(fc_h *h)
{
    GLint iv[4];
    GLfloat fv[16];
    GLdouble dv[16];
    GLboolean bv[16];
    GLubyte px[4];
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    for (int k = 0; k < 20; k++) {
        float x = 8.0f * (float)(k % 8), y = 8.0f * (float)(k / 8);
        fcu_color(k);
        glBegin(GL_TRIANGLES);
        glVertex2f(x + 1, y + 1);
        switch (k) {
        case 0: glViewport(0, 0, 8, 8); break;
        case 1: glClear(GL_COLOR_BUFFER_BIT); break;
        case 2: glMatrixMode(GL_PROJECTION); break;
        case 3: glGetIntegerv(GL_VIEWPORT, iv); break;
        case 4: glGetFloatv(GL_MODELVIEW_MATRIX, fv); break;
        case 5: glGetDoublev(GL_MODELVIEW_MATRIX, dv); break;
        case 6: glGetBooleanv(GL_DEPTH_TEST, bv); break;
        case 7: glBegin(GL_TRIANGLES); break;
        case 8: glIsEnabled(GL_DEPTH_TEST); break;
        case 9: glEnable(GL_DEPTH_TEST); break;
        case 10: glDepthFunc(GL_NEVER); break;
        case 11: glShadeModel(GL_SMOOTH); break;
        case 12: glLoadIdentity(); break;
        case 13: glPushMatrix(); break;
        case 14: glClearColor(1, 1, 1, 1); break;
        case 15: glDepthRange(0.5, 0.6); break;
        case 16: glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px); break;
        case 17: glOrtho(0, 1, 0, 1, -1, 1); break;
        case 18: glGetError(); break;
        default: glDepthMask(GL_FALSE); break;
        }
        glVertex2f(x + 7, y + 1);
        glVertex2f(x + 3, y + 7);
        glEnd();
        fc_error(h, "after glEnd");
    }
    fc_get_integer(h, "GL_VIEWPORT", GL_VIEWPORT, 4);
    fc_get_integer(h, "GL_MATRIX_MODE", GL_MATRIX_MODE, 1);
    fc_get_integer(h, "GL_MODELVIEW_STACK_DEPTH", GL_MODELVIEW_STACK_DEPTH, 1);
    fc_get_integer(h, "GL_DEPTH_FUNC", GL_DEPTH_FUNC, 1);
    fc_get_integer(h, "GL_SHADE_MODEL", GL_SHADE_MODEL, 1);
    fc_get_float(h, "GL_COLOR_CLEAR_VALUE", GL_COLOR_CLEAR_VALUE, 4);
    fc_get_double(h, "GL_DEPTH_RANGE", GL_DEPTH_RANGE, 2);
    fc_get_boolean(h, "GL_DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, 1);
    fc_is_enabled(h, "GL_DEPTH_TEST", GL_DEPTH_TEST);
    fc_capture(h);
}

static void end_without_begin(fc_h *h)
{
    glEnd(); fc_error(h, "glEnd without glBegin");
    glEnd(); glEnd(); fc_error(h, "two more glEnd");
    glBegin(GL_QUADS); glBegin(GL_QUADS); glEnd(); fc_error(h, "nested glBegin");
    glEnd(); fc_error(h, "glEnd after nested block closed");
    glBegin(GL_TRIANGLES); glEnd(); fc_error(h, "empty block");
}

/* Only the first error is kept until glGetError reads it. */
static void first_error_wins(fc_h *h)
{
    glMatrixMode(0x1234);               /* INVALID_ENUM */
    glViewport(0, 0, -1, -1);           /* INVALID_VALUE */
    glEnd();                            /* INVALID_OPERATION */
    fc_error(h, "first");
    fc_error(h, "then clear");
    glViewport(0, 0, -1, -1);
    glMatrixMode(0x1234);
    fc_error(h, "value before enum");
    glPopMatrix();                      /* stack underflow */
    glMatrixMode(0x1234);
    fc_error(h, "underflow first");
}

static void invalid_values(fc_h *h)
{
    glViewport(0, 0, -1, 4); fc_error(h, "glViewport negative width");
    glViewport(0, 0, 4, -1); fc_error(h, "glViewport negative height");
    glViewport(-5, -5, 0, 0); fc_error(h, "glViewport zero size");
    fc_get_integer(h, "GL_VIEWPORT", GL_VIEWPORT, 4);
    glDepthRange(-3, 7); fc_error(h, "glDepthRange out of range (clamped)");
    fc_get_double(h, "GL_DEPTH_RANGE", GL_DEPTH_RANGE, 2);
    glClearColor(-1, 2, 0.5f, 9); fc_error(h, "glClearColor out of range");
    fc_get_float(h, "GL_COLOR_CLEAR_VALUE", GL_COLOR_CLEAR_VALUE, 4);
    glClearDepth(-2); fc_error(h, "glClearDepth out of range");
    fc_get_double(h, "GL_DEPTH_CLEAR_VALUE", GL_DEPTH_CLEAR_VALUE, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fc_capture(h);
}

const fc_case fc_cases_errors[] = {
    FC_CASE_RGBA("core/error_invalid_enums", 8, 8, 0, "core error", invalid_enums),
    FC_CASE_RGBA("core/error_inside_begin_end", 64, 24, 1, "core error", inside_begin_end),
    FC_CASE_RGBA("core/error_end_without_begin", 8, 8, 0, "core error", end_without_begin),
    FC_CASE_RGBA("core/error_first_error_wins", 8, 8, 0, "core error", first_error_wins),
    /* the frame shows the clamped clear values (draws_nothing) */
    FC_CASE_NODRAW("core/error_invalid_values", 8, 8, OSMESA_RGBA, 24, 0, 1, "core error", invalid_values),
    { 0 }
};
