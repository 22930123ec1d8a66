/* c_matrix.c - matrix builders (float and double entry points, queried
 * back bit-exactly), stack push/pop to overflow and underflow on every
 * stack, invalid arguments, and rendering through composed transforms. */
#include "cases.h"

static void query_matrix(fc_h *h, const char *label, GLenum pname)
{
    fc_get_float(h, label, pname, 16);
    fc_get_double(h, label, pname, 16);
}

static void matrix_builders(fc_h *h)
{
    static const GLfloat mf[16] = {
        1.5f, 0.25f, -2, 0, 0.125f, 3, 0.5f, 0, -1, 2, 0.75f, 0, 10, -20, 30, 1,
    };
    static const GLdouble md[16] = {
        0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6,
    };
    glMatrixMode(GL_MODELVIEW);
    query_matrix(h, "identity", GL_MODELVIEW_MATRIX);
    glTranslatef(1.25f, -3.5f, 0.1f); query_matrix(h, "glTranslatef", GL_MODELVIEW_MATRIX);
    glTranslated(0.1, 0.2, 0.3); query_matrix(h, "glTranslated", GL_MODELVIEW_MATRIX);
    glRotatef(30, 0, 0, 1); query_matrix(h, "glRotatef z", GL_MODELVIEW_MATRIX);
    glRotatef(-45, 1, 0, 0); query_matrix(h, "glRotatef x", GL_MODELVIEW_MATRIX);
    glRotatef(90, 0, 2, 0); query_matrix(h, "glRotatef y unnormalised", GL_MODELVIEW_MATRIX);
    glRotated(17.3, 1, 2, 3); query_matrix(h, "glRotated general", GL_MODELVIEW_MATRIX);
    glRotatef(10, 0, 0, 0); query_matrix(h, "glRotatef zero axis", GL_MODELVIEW_MATRIX);
    glRotated(360.0, -1, 0.5, 0.25); query_matrix(h, "glRotated 360", GL_MODELVIEW_MATRIX);
    glScalef(2, -0.5f, 3); query_matrix(h, "glScalef", GL_MODELVIEW_MATRIX);
    glScaled(0.1, 10, 0); query_matrix(h, "glScaled zero", GL_MODELVIEW_MATRIX);
    glLoadMatrixf(mf); query_matrix(h, "glLoadMatrixf", GL_MODELVIEW_MATRIX);
    glMultMatrixd(md); query_matrix(h, "glMultMatrixd", GL_MODELVIEW_MATRIX);
    glMultMatrixf(mf); query_matrix(h, "glMultMatrixf", GL_MODELVIEW_MATRIX);
    glLoadMatrixd(md); query_matrix(h, "glLoadMatrixd", GL_MODELVIEW_MATRIX);
    glLoadIdentity(); query_matrix(h, "glLoadIdentity", GL_MODELVIEW_MATRIX);
    glMatrixMode(GL_PROJECTION);
    glOrtho(-3, 5, -1.5, 2.5, 0.5, 100); query_matrix(h, "glOrtho", GL_PROJECTION_MATRIX);
    glLoadIdentity();
    glFrustum(-0.3, 0.7, -0.2, 0.4, 0.1, 1000); query_matrix(h, "glFrustum", GL_PROJECTION_MATRIX);
    glOrtho(0, 1, 0, 1, -1, 1); query_matrix(h, "glFrustum*glOrtho", GL_PROJECTION_MATRIX);
    glMatrixMode(GL_MODELVIEW);
    query_matrix(h, "modelview via float/double", GL_MODELVIEW_MATRIX);
    fc_get_integer(h, "GL_MODELVIEW_MATRIX as int", GL_MODELVIEW_MATRIX, 16);
    fc_get_integer(h, "GL_PROJECTION_MATRIX as int", GL_PROJECTION_MATRIX, 16);
    fc_get_boolean(h, "GL_PROJECTION_MATRIX as bool", GL_PROJECTION_MATRIX, 16);
    fc_error(h, "after builders");
}

/* Push until the stack overflows, then pop until it underflows. */
static void stack_limits(fc_h *h, GLenum mode, GLenum depth_pname, GLenum max_pname)
{
    GLint max = 0;
    glMatrixMode(mode);
    fc_error(h, "glMatrixMode");
    glGetIntegerv(max_pname, &max);
    fc_value(h, "max stack depth", max);
    for (int i = 0; i < max + 2 && i < 64; i++) {
        glTranslatef((float)i, 0, 0);
        glPushMatrix();
        fc_error(h, "glPushMatrix");
        fc_get_integer(h, "stack depth", depth_pname, 1);
    }
    query_matrix(h, "top after overflow", mode == GL_MODELVIEW ? GL_MODELVIEW_MATRIX :
                 mode == GL_PROJECTION ? GL_PROJECTION_MATRIX : GL_TEXTURE_MATRIX);
    for (int i = 0; i < max + 2 && i < 64; i++) {
        glPopMatrix();
        fc_error(h, "glPopMatrix");
        fc_get_integer(h, "stack depth", depth_pname, 1);
    }
    query_matrix(h, "bottom after underflow", mode == GL_MODELVIEW ? GL_MODELVIEW_MATRIX :
                 mode == GL_PROJECTION ? GL_PROJECTION_MATRIX : GL_TEXTURE_MATRIX);
    glMatrixMode(GL_MODELVIEW);
}

static void stack_modelview(fc_h *h)
{
    stack_limits(h, GL_MODELVIEW, GL_MODELVIEW_STACK_DEPTH, GL_MAX_MODELVIEW_STACK_DEPTH);
}

static void stack_projection(fc_h *h)
{
    stack_limits(h, GL_PROJECTION, GL_PROJECTION_STACK_DEPTH, GL_MAX_PROJECTION_STACK_DEPTH);
}

static void stack_texture(fc_h *h)
{
    stack_limits(h, GL_TEXTURE, GL_TEXTURE_STACK_DEPTH, GL_MAX_TEXTURE_STACK_DEPTH);
}

static void matrix_invalid(fc_h *h)
{
    glMatrixMode(GL_PROJECTION);
    glOrtho(1, 1, 0, 1, 0, 1); fc_error(h, "glOrtho l == r");
    glOrtho(0, 1, 2, 2, 0, 1); fc_error(h, "glOrtho b == t");
    glOrtho(0, 1, 0, 1, 3, 3); fc_error(h, "glOrtho n == f");
    glFrustum(-1, 1, -1, 1, 0, 10); fc_error(h, "glFrustum near 0");
    glFrustum(-1, 1, -1, 1, -1, 10); fc_error(h, "glFrustum near < 0");
    glFrustum(-1, 1, -1, 1, 1, -10); fc_error(h, "glFrustum far < 0");
    glFrustum(-1, 1, -1, 1, 2, 2); fc_error(h, "glFrustum near == far");
    glFrustum(1, 1, -1, 1, 1, 2); fc_error(h, "glFrustum l == r");
    query_matrix(h, "projection unchanged", GL_PROJECTION_MATRIX);
    glMatrixMode(GL_COLOR); fc_error(h, "glMatrixMode(GL_COLOR)");
    glMatrixMode(0x1234); fc_error(h, "glMatrixMode(bogus)");
    fc_get_integer(h, "GL_MATRIX_MODE", GL_MATRIX_MODE, 1);
    glMatrixMode(GL_MODELVIEW);
}

/* Rendering through pushed/popped, rotated, scaled and loaded matrices. */
static void matrix_render(fc_h *h)
{
    static const GLdouble m[16] = {
        0.8, 0.3, 0, 0, -0.3, 0.8, 0, 0, 0, 0, 1, 0, -0.1, 0.2, 0, 1,
    };
    glViewport(0, 0, 64, 64);
    fcu_frustum(-1, 1, -1, 1, 2, 50);
    glEnable(GL_DEPTH_TEST);
    fcu_clear(0, 0, 0, 0, 1);
    glTranslatef(0, 0, -6);
    for (int i = 0; i < 6; i++) {
        glPushMatrix();
        glRotatef(60.0f * (float)i + 7.5f, 0.3f, 0.2f, 1.0f);
        glTranslated(1.7, 0, 0.5 * i - 1);
        glScalef(0.6f, 1.4f, 1);
        glRotated(33.0 * i, 1, 1, 0);
        glBegin(GL_QUADS);
        fcu_color(i); glVertex3f(-1, -1, 0);
        fcu_color(i + 1); glVertex3f(1, -1, 0);
        fcu_color(i + 2); glVertex3f(1, 1, 0);
        fcu_color(i + 3); glVertex3f(-1, 1, 0);
        glEnd();
        glPopMatrix();
    }
    glMultMatrixd(m);
    glColor3f(1, 1, 1);
    fcu_rect(-0.5f, -0.5f, 0.5f, 0.5f, 1);
    fc_capture(h);
}

const fc_case fc_cases_matrix[] = {
    FC_CASE_RGBA("core/matrix_builders_query", 8, 8, 0, "core matrix query", matrix_builders),
    FC_CASE_RGBA("core/matrix_stack_modelview", 8, 8, 0, "core matrix error", stack_modelview),
    FC_CASE_RGBA("core/matrix_stack_projection", 8, 8, 0, "core matrix error", stack_projection),
    FC_CASE_RGBA("core/matrix_stack_texture", 8, 8, 0, "core matrix error", stack_texture),
    FC_CASE_RGBA("core/matrix_invalid_arguments", 8, 8, 0, "core matrix error", matrix_invalid),
    FC_CASE_RGBA("core/matrix_render_transforms", 64, 64, 1, "core matrix perspective", matrix_render),
    { 0 }
};
