/* c_query.c - glGet{Integer,Float,Double,Boolean}v and glIsEnabled of all
 * state of the first slice, at defaults and after setting it, glEnable /
 * glDisable of several capabilities, and glGetString validity. */
#include "cases.h"

struct pname { GLenum pname; int count; const char *label; };

static const struct pname state[] = {
    { GL_VIEWPORT, 4, "GL_VIEWPORT" },
    { GL_DEPTH_RANGE, 2, "GL_DEPTH_RANGE" },
    { GL_MODELVIEW_MATRIX, 16, "GL_MODELVIEW_MATRIX" },
    { GL_PROJECTION_MATRIX, 16, "GL_PROJECTION_MATRIX" },
    { GL_MODELVIEW_STACK_DEPTH, 1, "GL_MODELVIEW_STACK_DEPTH" },
    { GL_PROJECTION_STACK_DEPTH, 1, "GL_PROJECTION_STACK_DEPTH" },
    { GL_MATRIX_MODE, 1, "GL_MATRIX_MODE" },
    { GL_COLOR_CLEAR_VALUE, 4, "GL_COLOR_CLEAR_VALUE" },
    { GL_DEPTH_CLEAR_VALUE, 1, "GL_DEPTH_CLEAR_VALUE" },
    { GL_SHADE_MODEL, 1, "GL_SHADE_MODEL" },
    { GL_DEPTH_FUNC, 1, "GL_DEPTH_FUNC" },
    { GL_DEPTH_WRITEMASK, 1, "GL_DEPTH_WRITEMASK" },
    { GL_DEPTH_TEST, 1, "GL_DEPTH_TEST" },
    { GL_CURRENT_COLOR, 4, "GL_CURRENT_COLOR" },
    { GL_MAX_VIEWPORT_DIMS, 2, "GL_MAX_VIEWPORT_DIMS" },
    { GL_MAX_MODELVIEW_STACK_DEPTH, 1, "GL_MAX_MODELVIEW_STACK_DEPTH" },
    { GL_MAX_PROJECTION_STACK_DEPTH, 1, "GL_MAX_PROJECTION_STACK_DEPTH" },
    { GL_SUBPIXEL_BITS, 1, "GL_SUBPIXEL_BITS" },
    { GL_RED_BITS, 1, "GL_RED_BITS" },
    { GL_GREEN_BITS, 1, "GL_GREEN_BITS" },
    { GL_BLUE_BITS, 1, "GL_BLUE_BITS" },
    { GL_ALPHA_BITS, 1, "GL_ALPHA_BITS" },
    { GL_DEPTH_BITS, 1, "GL_DEPTH_BITS" },
    { GL_STENCIL_BITS, 1, "GL_STENCIL_BITS" },
};

static const struct pname caps[] = {
    { GL_DEPTH_TEST, 1, "GL_DEPTH_TEST" },
    { GL_DITHER, 1, "GL_DITHER" },
    { GL_CULL_FACE, 1, "GL_CULL_FACE" },
    { GL_BLEND, 1, "GL_BLEND" },
    { GL_LIGHTING, 1, "GL_LIGHTING" },
    { GL_TEXTURE_2D, 1, "GL_TEXTURE_2D" },
    { GL_SCISSOR_TEST, 1, "GL_SCISSOR_TEST" },
    { GL_ALPHA_TEST, 1, "GL_ALPHA_TEST" },
    { GL_STENCIL_TEST, 1, "GL_STENCIL_TEST" },
    { GL_FOG, 1, "GL_FOG" },
    { GL_NORMALIZE, 1, "GL_NORMALIZE" },
    { GL_POLYGON_OFFSET_FILL, 1, "GL_POLYGON_OFFSET_FILL" },
};

static void query_all(fc_h *h, const struct pname *p, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        fc_get_integer(h, p[i].label, p[i].pname, p[i].count);
        fc_get_float(h, p[i].label, p[i].pname, p[i].count);
        fc_get_double(h, p[i].label, p[i].pname, p[i].count);
        fc_get_boolean(h, p[i].label, p[i].pname, p[i].count);
        fc_error(h, p[i].label);
    }
}

static void query_defaults(fc_h *h)
{
    query_all(h, state, sizeof state / sizeof state[0]);
    for (size_t i = 0; i < sizeof caps / sizeof caps[0]; i++)
        fc_is_enabled(h, caps[i].label, caps[i].pname);
}

static void query_after_set(fc_h *h)
{
    glViewport(3, -4, 21, 19);
    glDepthRange(0.8, 0.125);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 2, -0.5, 0.75, 0.3, 7);
    glPushMatrix();
    glMatrixMode(GL_MODELVIEW);
    glRotatef(33, 1, 1, 1);
    glPushMatrix();
    glPushMatrix();
    glScalef(-2, 1e-3f, 3e9f);
    glClearColor(0.1f, -0.5f, 1.5f, 0.999f);
    glClearDepth(0.3);
    glShadeModel(GL_FLAT);
    glDepthFunc(GL_GEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glColor4f(0.25f, -1.0f, 2.0f, 1.0f / 3.0f);
    query_all(h, state, sizeof state / sizeof state[0]);
    glColor4ub(1, 2, 254, 255);
    query_all(h, state + 13, 1);                /* GL_CURRENT_COLOR */
    glColor3i(-2147483647 - 1, 0, 2147483647);
    query_all(h, state + 13, 1);
}

static void query_caps(fc_h *h)
{
    for (size_t i = 0; i < sizeof caps / sizeof caps[0]; i++) {
        glEnable(caps[i].pname);
        fc_error(h, "glEnable");
        fc_is_enabled(h, caps[i].label, caps[i].pname);
        fc_get_boolean(h, caps[i].label, caps[i].pname, 1);
        glDisable(caps[i].pname);
        fc_error(h, "glDisable");
        fc_is_enabled(h, caps[i].label, caps[i].pname);
    }
    glEnable(GL_DITHER);                        /* leave the default back on */
    glEnable(0x1234); fc_error(h, "glEnable(bogus)");
    glDisable(0x1234); fc_error(h, "glDisable(bogus)");
    fc_is_enabled(h, "glIsEnabled(bogus)", 0x1234);
    fc_error(h, "glIsEnabled(bogus)");
}

/* Strings differ between implementations by design: only their presence
 * and the errors are compared. */
static void query_strings(fc_h *h)
{
    static const GLenum names[4] = { GL_VENDOR, GL_RENDERER, GL_VERSION, GL_EXTENSIONS };
    for (int i = 0; i < 4; i++) {
        fc_value(h, "glGetString != NULL", glGetString(names[i]) != NULL);
        fc_error(h, "glGetString");
    }
    fc_value(h, "glGetString(bogus) != NULL", glGetString(0x1234) != NULL);
    fc_error(h, "glGetString(bogus)");
}

const fc_case fc_cases_query[] = {
    FC_CASE_RGBA("core/query_defaults", 20, 10, 0, "core query", query_defaults),
    FC_CASE_RGBA("core/query_after_set", 20, 10, 0, "core query", query_after_set),
    FC_CASE_RGBA("core/query_enable_caps", 8, 8, 0, "core query", query_caps),
    FC_CASE_RGBA("core/query_strings", 8, 8, 0, "core query", query_strings),
    { 0 }
};
