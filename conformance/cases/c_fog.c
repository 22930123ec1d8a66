/* c_fog.c - fog (GL_FOG, glFog, glHint).  The oracle's vertex program
 * writes |z_eye| (or, with GL_NV_fog_distance, the signed z or the radial
 * distance; or |fog coordinate|), interpolated with perspective; its
 * fragment program computes the LINEAR / EXP / EXP2 factor from
 * CPU-precomputed parameters with gallivm's exp2, clamps it and blends rgb
 * towards the fog colour after the colour sum.  The scenes span a wide
 * depth range under perspective (large triangles, so the interpolation is
 * visibly non-linear) and ortho, smooth and flat, then the corner cases of
 * the parameters, lit geometry, clipping, modelviews, hints, and the API's
 * errors and queries. */
#include "lt_util.h"

#include <math.h>
#include <stdio.h>

/* ---- API ---- */

static void rec_fog_state(fc_h *h, const char *what)
{
    char label[96];
    static const struct { GLenum pname; const char *name; int n; } q[] = {
        { GL_FOG_MODE, "GL_FOG_MODE", 1 },
        { GL_FOG_DENSITY, "GL_FOG_DENSITY", 1 },
        { GL_FOG_START, "GL_FOG_START", 1 },
        { GL_FOG_END, "GL_FOG_END", 1 },
        { GL_FOG_INDEX, "GL_FOG_INDEX", 1 },
        { GL_FOG_COLOR, "GL_FOG_COLOR", 4 },
        { GL_FOG_COORDINATE_SOURCE, "GL_FOG_COORDINATE_SOURCE", 1 },
        { GL_FOG_DISTANCE_MODE_NV, "GL_FOG_DISTANCE_MODE_NV", 1 },
        { GL_FOG_HINT, "GL_FOG_HINT", 1 },
    };
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
        snprintf(label, sizeof label, "%s %s f", what, q[i].name);
        fc_get_float(h, label, q[i].pname, q[i].n);
        snprintf(label, sizeof label, "%s %s i", what, q[i].name);
        fc_get_integer(h, label, q[i].pname, q[i].n);
        snprintf(label, sizeof label, "%s %s b", what, q[i].name);
        fc_get_boolean(h, label, q[i].pname, q[i].n);
        snprintf(label, sizeof label, "%s %s d", what, q[i].name);
        fc_get_double(h, label, q[i].pname, q[i].n);
    }
    snprintf(label, sizeof label, "%s GL_FOG", what);
    fc_is_enabled(h, label, GL_FOG);
}

/* Defaults, then every parameter through each entry point and read back
 * in the four types. */
static void api_roundtrip(fc_h *h)
{
    rec_fog_state(h, "default");
    glFogf(GL_FOG_MODE, (float)GL_LINEAR);
    glFogf(GL_FOG_DENSITY, 0.625f);
    glFogf(GL_FOG_START, -2.5f);
    glFogf(GL_FOG_END, 1e9f);
    glFogf(GL_FOG_INDEX, 3.75f);
    {
        const GLfloat c[4] = { 0.1f, 0.2f, 0.3f, 0.4f };
        glFogfv(GL_FOG_COLOR, c);
    }
    fc_error(h, "glFogf/fv");
    rec_fog_state(h, "glFogf");
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogi(GL_FOG_DENSITY, 3);
    glFogi(GL_FOG_START, -7);
    glFogi(GL_FOG_END, 2000000000);
    glFogi(GL_FOG_INDEX, 12);
    glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
    fc_error(h, "glFogi");
    rec_fog_state(h, "glFogi");
    {
        const GLint m = GL_EXP, d = 5, s = 1, e = -3, ix = -2, src = GL_FRAGMENT_DEPTH;
        const GLint dm = GL_EYE_PLANE;
        const GLint c[4] = { 2147483647, 0, -2147483647 - 1, 1073741824 };
        glFogiv(GL_FOG_MODE, &m);
        glFogiv(GL_FOG_DENSITY, &d);
        glFogiv(GL_FOG_START, &s);
        glFogiv(GL_FOG_END, &e);
        glFogiv(GL_FOG_INDEX, &ix);
        glFogiv(GL_FOG_COORDINATE_SOURCE, &src);
        glFogiv(GL_FOG_DISTANCE_MODE_NV, &dm);
        glFogiv(GL_FOG_COLOR, c);
    }
    fc_error(h, "glFogiv");
    rec_fog_state(h, "glFogiv");
    {
        const GLfloat m = (float)GL_LINEAR, d = 0.5f, src = (float)GL_FOG_COORDINATE;
        const GLfloat dm = (float)GL_EYE_PLANE_ABSOLUTE_NV;
        glFogfv(GL_FOG_MODE, &m);
        glFogfv(GL_FOG_DENSITY, &d);
        glFogfv(GL_FOG_COORDINATE_SOURCE, &src);
        glFogfv(GL_FOG_DISTANCE_MODE_NV, &dm);
    }
    fc_error(h, "glFogfv scalars");
    rec_fog_state(h, "glFogfv");
}

/* Each invalid call raises Mesa's error and changes nothing. */
static void api_errors(fc_h *h)
{
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_DENSITY, 0.5f);
    glFogi(GL_FOG_MODE, GL_NICEST);
    fc_error(h, "mode GL_NICEST");
    glFogf(GL_FOG_MODE, (float)GL_LINEAR + 0.5f);
    fc_error(h, "mode LINEAR+0.5 (truncated)");
    glFogf(GL_FOG_MODE, 3e9f);
    fc_error(h, "mode 3e9");
    glFogf(GL_FOG_DENSITY, -0.25f);
    fc_error(h, "density -0.25");
    glFogi(GL_FOG_DENSITY, -1);
    fc_error(h, "density -1 (int)");
    glFogf(GL_FOG_DENSITY, -0.0f);
    fc_error(h, "density -0");
    glFogf(GL_FOG_DENSITY, NAN);
    fc_error(h, "density NaN");
    fc_get_float(h, "GL_FOG_DENSITY NaN", GL_FOG_DENSITY, 1);
    fc_get_boolean(h, "GL_FOG_DENSITY NaN b", GL_FOG_DENSITY, 1);
    glFogf(GL_FOG_DENSITY, 0.5f);
    glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_HINT);
    fc_error(h, "coordinate source GL_FOG_HINT");
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_LINEAR);
    fc_error(h, "distance mode GL_EYE_LINEAR");
    glFogf(GL_FOG_HINT, 1);
    fc_error(h, "pname GL_FOG_HINT");
    glFogi(GL_FOG, 1);
    fc_error(h, "pname GL_FOG");
    {
        const GLint iv[4] = { 1, 2, 3, 4 };
        const GLfloat fv[4] = { 1, 2, 3, 4 };
        glFogiv(GL_LIGHT0, iv);
        fc_error(h, "glFogiv bad pname");
        glFogfv(GL_DEPTH_TEST, fv);
        fc_error(h, "glFogfv bad pname");
    }
    rec_fog_state(h, "after errors");
    /* the scalar forms take the vector pname: (x, 0, 0, 0) */
    glFogf(GL_FOG_COLOR, 0.75f);
    fc_error(h, "glFogf GL_FOG_COLOR");
    fc_get_float(h, "GL_FOG_COLOR after glFogf", GL_FOG_COLOR, 4);
    glFogi(GL_FOG_COLOR, 1);
    fc_error(h, "glFogi GL_FOG_COLOR");
    fc_get_float(h, "GL_FOG_COLOR after glFogi", GL_FOG_COLOR, 4);
    /* inside glBegin/glEnd: GL_INVALID_OPERATION, reported after glEnd */
    glBegin(GL_TRIANGLES);
    glFogf(GL_FOG_START, 9);
    glFogi(GL_FOG_MODE, GL_EXP);
    glHint(GL_FOG_HINT, GL_NICEST);
    glEnd();
    fc_error(h, "inside begin/end");
    rec_fog_state(h, "after begin/end");
}

/* glHint: every GL 1.x target (and the later ones Mesa accepts in this
 * context), bad modes, bad targets, the queries. */
static void api_hints(fc_h *h)
{
    static const struct { GLenum target; const char *name; } t[] = {
        { GL_PERSPECTIVE_CORRECTION_HINT, "GL_PERSPECTIVE_CORRECTION_HINT" },
        { GL_POINT_SMOOTH_HINT, "GL_POINT_SMOOTH_HINT" },
        { GL_LINE_SMOOTH_HINT, "GL_LINE_SMOOTH_HINT" },
        { GL_POLYGON_SMOOTH_HINT, "GL_POLYGON_SMOOTH_HINT" },
        { GL_FOG_HINT, "GL_FOG_HINT" },
        { GL_TEXTURE_COMPRESSION_HINT, "GL_TEXTURE_COMPRESSION_HINT" },
        { GL_GENERATE_MIPMAP_HINT, "GL_GENERATE_MIPMAP_HINT" },
        { GL_FRAGMENT_SHADER_DERIVATIVE_HINT, "GL_FRAGMENT_SHADER_DERIVATIVE_HINT" },
    };
    static const GLenum modes[3] = { GL_FASTEST, GL_NICEST, GL_DONT_CARE };
    char label[96];
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        snprintf(label, sizeof label, "%s default", t[i].name);
        fc_get_integer(h, label, t[i].target, 1);
        for (int m = 0; m < 3; m++) {
            glHint(t[i].target, modes[m]);
            snprintf(label, sizeof label, "%s set %d", t[i].name, m);
            fc_error(h, label);
            fc_get_integer(h, label, t[i].target, 1);
        }
        glHint(t[i].target, GL_NICEST);
        glHint(t[i].target, GL_LINEAR);
        snprintf(label, sizeof label, "%s bad mode", t[i].name);
        fc_error(h, label);
        fc_get_float(h, label, t[i].target, 1);
        fc_get_boolean(h, label, t[i].target, 1);
    }
    glHint(GL_FOG, GL_NICEST);
    fc_error(h, "target GL_FOG");
    glHint(GL_CLIP_VOLUME_CLIPPING_HINT_EXT, GL_NICEST);
    fc_error(h, "target GL_CLIP_VOLUME_CLIPPING_HINT_EXT");
    glHint(0, GL_NICEST);
    fc_error(h, "target 0");
    glHint(0, 0);
    fc_error(h, "target 0 mode 0");
    glHint(GL_FOG_HINT, GL_FOG_HINT);
    fc_error(h, "mode GL_FOG_HINT");
    fc_get_integer(h, "GL_FOG_HINT final", GL_FOG_HINT, 1);
}

const fc_case fc_cases_fog[] = {
    FC_CASE_RGBA("fog/api_roundtrip", 8, 8, 0, "fragment fog api", api_roundtrip),
    FC_CASE_RGBA("fog/api_errors", 8, 8, 0, "fragment fog api error", api_errors),
    FC_CASE_RGBA("fog/api_hints", 8, 8, 0, "fragment fog api hint error", api_hints),
    { 0 },
};
