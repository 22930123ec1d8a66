/* c_gl14_points.c - glPointParameter (GL 1.4): distance attenuation under
 * perspective and orthographic views, sizes at the GL_POINT_SIZE_MIN /
 * _MAX clamps (attenuated and not, min above max), the fade threshold
 * (which the oracle does not apply), smooth, lit, fogged, textured and
 * array-drawn attenuated points, display lists, the attribute stacks, and
 * the state of GL_POINT_SPRITE / GL_COORD_REPLACE with every query and
 * error.  Point sprites are drawn by c_gl14_sprite.c. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>

#include "cases.h"

/* One attenuation scene: a grid of points receding from z = -1 to -60
 * (perspective) or spread in depth (ortho), each its own colour. */
struct atten_cfg {
    float a[3];          /* GL_POINT_DISTANCE_ATTENUATION */
    float size, min, max;
    int persp;           /* frustum, else ortho */
    int smooth, lit, fog, tex, flat;
};

static void atten_view(fc_h *h, int persp)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    if (persp)
        fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 80);
    else
        fcu_ortho(-4, 4, -4, 4, 0.5, 80);
    glEnable(GL_DEPTH_TEST);
}

static void atten_points(int persp)
{
    glBegin(GL_POINTS);
    for (int i = 0; i < 36; i++) {
        const float z = -1.3f - 1.6f * (float)i;
        const float gx = (float)(i % 6) - 2.5f, gy = (float)(i / 6) - 2.5f;
        const float k = persp ? -z * 0.16f : 1.1f;
        glColor4f((float)(i % 3) / 2.0f, (float)(i % 5) / 4.0f, (float)(i % 7) / 6.0f,
                  0.4f + 0.6f * (float)(i % 2));
        glNormal3f(0.1f * gx, 0.1f * gy, 1.0f);
        glTexCoord2f(0.1f * (float)i, 0.7f);
        glVertex3f(gx * k, gy * k, z);
    }
    glEnd();
}

static void atten_run(fc_h *h, const struct atten_cfg *cfg)
{
    atten_view(h, cfg->persp);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, cfg->a);
    glPointSize(cfg->size);
    glPointParameterf(GL_POINT_SIZE_MIN, cfg->min);
    glPointParameterf(GL_POINT_SIZE_MAX, cfg->max);
    if (cfg->smooth) {
        glEnable(GL_POINT_SMOOTH);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    if (cfg->lit) {
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_COLOR_MATERIAL);
    }
    if (cfg->fog) {
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_START, 2);
        glFogf(GL_FOG_END, 50);
        if (cfg->fog == 2)
            glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
    }
    if (cfg->tex) {
        static GLubyte t[4 * 4 * 4];
        for (int i = 0; i < 64; i++)
            t[i] = (GLubyte)(i * 37);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glEnable(GL_TEXTURE_2D);
        if (cfg->tex == 2) {
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
            glEnable(GL_TEXTURE_GEN_S);
        }
    }
    if (cfg->flat)
        glShadeModel(GL_FLAT);
    fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
    atten_points(cfg->persp);
    fc_capture(h);
}

#define ATTEN_CASE(fname, ...)                                      \
    static void fname(fc_h *h)                                      \
    {                                                               \
        static const struct atten_cfg cfg = __VA_ARGS__;            \
        atten_run(h, &cfg);                                         \
    }

ATTEN_CASE(atten_linear, { { 1, 0.25f, 0 }, 24, 0, 255, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_quadratic, { { 1, 0, 0.02f }, 30, 0, 255, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_constant, { { 4, 0, 0 }, 14, 0, 255, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_all_terms, { { 0.5f, 0.1f, 0.01f }, 18, 0, 255, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_small_constant, { { 0.01f, 0, 0.001f }, 3, 0, 255, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_ortho, { { 1, 0.3f, 0.005f }, 20, 0, 255, 0, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_min_clamp, { { 1, 0.5f, 0 }, 20, 6.5f, 255, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_max_clamp, { { 1, 0.05f, 0 }, 40, 0, 9.5f, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_min_above_max, { { 1, 0.2f, 0 }, 20, 12, 5, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_below_one, { { 1, 2, 0.5f }, 8, 0, 255, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_huge, { { 0.0001f, 0, 0 }, 0.09f, 0, 1000, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_negative_terms, { { 1, -0.02f, 0 }, 12, 0, 255, 1, 0, 0, 0, 0, 0 })
ATTEN_CASE(atten_smooth, { { 1, 0.2f, 0.004f }, 22, 0, 255, 1, 1, 0, 0, 0, 0 })
ATTEN_CASE(atten_lit, { { 1, 0.15f, 0.01f }, 20, 0, 255, 1, 0, 1, 0, 0, 0 })
ATTEN_CASE(atten_fog, { { 1, 0.15f, 0 }, 20, 0, 255, 1, 0, 0, 1, 0, 0 })
ATTEN_CASE(atten_fog_radial, { { 1, 0.15f, 0 }, 20, 0, 255, 1, 0, 0, 2, 0, 0 })
ATTEN_CASE(atten_textured, { { 1, 0.1f, 0.002f }, 26, 0, 255, 1, 0, 0, 0, 1, 0 })
ATTEN_CASE(atten_texgen_eye, { { 1, 0.1f, 0.002f }, 26, 0, 255, 1, 0, 0, 0, 2, 0 })
ATTEN_CASE(atten_flat_ortho, { { 2, 0.05f, 0.01f }, 16, 2, 12, 0, 0, 0, 0, 0, 1 })
ATTEN_CASE(atten_smooth_ortho_clamp, { { 1, 0.4f, 0 }, 30, 3, 14, 0, 1, 0, 0, 0, 0 })

/* Without attenuation the size itself is clamped to [min, max]: sizes
 * below, inside and above, min above max, a min of 0 (the legacy point is
 * still one pixel). */
static void minmax_plain(fc_h *h)
{
    static const float cfg[6][3] = {
        { 2, 5, 9 }, { 7, 5, 9 }, { 20, 5, 9 }, { 7, 12, 4 }, { 0.3f, 0, 255 }, { 300, 0, 400 },
    };
    fc_pixel_ortho(h);
    for (int f = 0; f < 6; f++) {
        glPointSize(cfg[f][0]);
        glPointParameterf(GL_POINT_SIZE_MIN, cfg[f][1]);
        glPointParameterf(GL_POINT_SIZE_MAX, cfg[f][2]);
        fcu_clear(0, 0, 0, 1, 1);
        glBegin(GL_POINTS);
        for (int i = 0; i < 9; i++) {
            fcu_color(i);
            glVertex2f(8.3f + 16.0f * (float)(i % 3), 8.6f + 16.0f * (float)(i / 3));
        }
        glEnd();
        fc_capture(h);
    }
}

/* The fade threshold above the point sizes, blended: the oracle fades
 * nothing; attenuated and not. */
static void fade_threshold(fc_h *h)
{
    atten_view(h, 1);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 25.0f);
    for (int f = 0; f < 2; f++) {
        const GLfloat a[3] = { 1, f ? 0.3f : 0, 0 };
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
        glPointSize(6.0f);
        fcu_clear(0.3f, 0.3f, 0.3f, 1, 1);
        atten_points(1);
        fc_capture(h);
    }
}

/* Arrays, glDrawElements, a display list that sets the parameters and
 * draws, GL_COMPILE_AND_EXECUTE. */
static void atten_arrays_dlist(fc_h *h)
{
    static GLfloat pos[24][3], col[24][3];
    static const GLushort idx[12] = { 23, 1, 21, 3, 19, 5, 17, 7, 15, 9, 13, 11 };
    for (int i = 0; i < 24; i++) {
        pos[i][0] = 0.3f * (float)(i % 6) - 0.8f;
        pos[i][1] = 0.35f * (float)(i / 6) - 0.6f;
        pos[i][2] = -1.5f - 2.2f * (float)i;
        pos[i][0] *= -pos[i][2] * 0.5f;
        pos[i][1] *= -pos[i][2] * 0.5f;
        col[i][0] = (float)(i % 4) / 3.0f;
        col[i][1] = 1.0f - (float)(i % 3) / 2.0f;
        col[i][2] = (float)(i % 5) / 4.0f;
    }
    atten_view(h, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glColorPointer(3, GL_FLOAT, 0, col);
    const GLfloat a[3] = { 1, 0.12f, 0.003f };
    const GLint ai[3] = { 1, 0, 0 };
    glPointSize(18);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
    fcu_clear(0, 0, 0, 1, 1);
    glDrawArrays(GL_POINTS, 0, 24);
    fc_capture(h);
    fcu_clear(0, 0, 0, 1, 1);
    glPointParameterf(GL_POINT_SIZE_MAX, 10.0f);
    glDrawElements(GL_POINTS, 12, GL_UNSIGNED_SHORT, idx);
    fc_capture(h);
    const GLuint l = glGenLists(2);
    glNewList(l, GL_COMPILE);
    glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, ai);
    glPointParameteri(GL_POINT_SIZE_MIN, 3);
    glPointParameterfEXT(GL_POINT_SIZE_MAX, 30.0f);
    glDrawArrays(GL_POINTS, 0, 24);
    glEndList();
    fc_get_float(h, "compiled only", GL_POINT_SIZE_MIN, 1);
    fcu_clear(0, 0, 0, 1, 1);
    glCallList(l);
    fc_get_float(h, "called", GL_POINT_DISTANCE_ATTENUATION, 3);
    fc_get_float(h, "called", GL_POINT_SIZE_MIN, 1);
    fc_capture(h);
    fcu_clear(0, 0, 0, 1, 1);
    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    glPointParameterfvARB(GL_POINT_DISTANCE_ATTENUATION, a);
    glPointParameterfARB(GL_POINT_SIZE_MIN, 0.5f);
    glDrawArrays(GL_POINTS, 0, 24);
    glEndList();
    fc_capture(h);
    glDeleteLists(l, 2);
}

/* Every parameter's default, set, query and error, through each entry
 * point; GL_POINT_SPRITE and GL_COORD_REPLACE as state.  (GL 2.0's
 * GL_POINT_SPRITE_COORD_ORIGIN is foreign to GL 1.5:
 * honesty/point_sprite_origin.) */
static void params_api(fc_h *h)
{
    static const GLenum q[] = { GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE,
                                GL_POINT_SPRITE_R_MODE_NV };
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
        fc_get_float(h, "default", q[i], 1);
        fc_get_integer(h, "default", q[i], 1);
    }
    fc_get_float(h, "default", GL_POINT_DISTANCE_ATTENUATION, 3);
    fc_get_double(h, "default", GL_POINT_DISTANCE_ATTENUATION, 3);
    fc_is_enabled(h, "default", GL_POINT_SPRITE);
    GLint iv = -1;
    glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &iv);
    fc_value(h, "coord replace default", iv);
    glPointParameterf(GL_POINT_SIZE_MIN, -1.0f);
    fc_error(h, "negative min");
    glPointParameterf(GL_POINT_SIZE_MAX, -0.5f);
    fc_error(h, "negative max");
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, -2.0f);
    fc_error(h, "negative threshold");
    glPointParameterf(GL_POINT_SIZE, 3.0f);
    fc_error(h, "bad pname");
    glPointParameteri(GL_POINT_SPRITE_R_MODE_NV, GL_S);
    fc_error(h, "r mode");
    fc_get_integer(h, "r mode", GL_POINT_SPRITE_R_MODE_NV, 1);
    glPointParameteri(GL_POINT_SPRITE_R_MODE_NV, GL_T);
    fc_error(h, "bad r mode");
    const GLfloat a[3] = { 2, 0.5f, 0.25f };
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
    fc_get_float(h, "attenuation", GL_POINT_DISTANCE_ATTENUATION, 3);
    glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 3.0f);
    fc_get_float(h, "attenuation by f", GL_POINT_DISTANCE_ATTENUATION, 3);
    const GLint ai[3] = { 4, 5, 6 };
    glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, ai);
    fc_get_integer(h, "attenuation by iv", GL_POINT_DISTANCE_ATTENUATION, 3);
    glPointParameteriv(GL_POINT_SIZE_MAX, ai);
    fc_get_float(h, "max by iv", GL_POINT_SIZE_MAX, 1);
    glPointParameterfvEXT(GL_POINT_FADE_THRESHOLD_SIZE, a);
    fc_get_float(h, "threshold by fv", GL_POINT_FADE_THRESHOLD_SIZE, 1);
    glEnable(GL_POINT_SPRITE);
    fc_error(h, "sprite enable");
    fc_is_enabled(h, "sprite on", GL_POINT_SPRITE);
    fc_get_boolean(h, "sprite on", GL_POINT_SPRITE, 1);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    fc_error(h, "coord replace");
    glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &iv);
    fc_value(h, "coord replace unit 0", iv);
    glActiveTexture(GL_TEXTURE3);
    glTexEnvf(GL_POINT_SPRITE, GL_COORD_REPLACE, 1.0f);
    glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &iv);
    fc_value(h, "coord replace unit 3", iv);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, 2);
    fc_error(h, "coord replace 2");
    glTexEnvi(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    fc_error(h, "sprite target bad pname");
    GLfloat fv = -1.0f;
    glGetTexEnvfv(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, &fv);
    fc_error(h, "get sprite target bad pname");
    glActiveTexture(GL_TEXTURE1);
    glGetTexEnvfv(GL_POINT_SPRITE, GL_COORD_REPLACE, &fv);
    fc_value(h, "coord replace unit 1", (long long)fv);
    glActiveTexture(GL_TEXTURE0);
    /* GL_POINT_BIT and GL_ENABLE_BIT */
    glPointSize(5.0f);
    glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
    glPushAttrib(GL_POINT_BIT);
    glPointParameterf(GL_POINT_SIZE_MIN, 4.0f);
    glPointParameterf(GL_POINT_SIZE_MAX, 44.0f);
    glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 9.0f);
    glPointParameteri(GL_POINT_SPRITE_R_MODE_NV, GL_R);
    glDisable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
    glPopAttrib();
    fc_get_float(h, "point popped", GL_POINT_SIZE_MIN, 1);
    fc_get_float(h, "point popped", GL_POINT_SIZE_MAX, 1);
    fc_get_float(h, "point popped", GL_POINT_DISTANCE_ATTENUATION, 3);
    fc_get_integer(h, "point popped", GL_POINT_SPRITE_R_MODE_NV, 1);
    fc_is_enabled(h, "point popped", GL_POINT_SPRITE);
    glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &iv);
    fc_value(h, "point popped coord replace", iv);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_POINT_SPRITE);
    glPopAttrib();
    fc_is_enabled(h, "enable popped", GL_POINT_SPRITE);
    glDisable(GL_POINT_SPRITE);
    /* compiled */
    const GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glPointParameterf(GL_POINT_SIZE_MAX, 17.0f);
    glPointParameterf(GL_POINT_SIZE_MIN, -4.0f);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
    glEnable(GL_POINT_SPRITE);
    glEndList();
    fc_error(h, "compile");
    glCallList(l);
    fc_error(h, "call");
    fc_get_float(h, "called", GL_POINT_SIZE_MAX, 1);
    fc_is_enabled(h, "called", GL_POINT_SPRITE);
    glDeleteLists(l, 1);
    glBegin(GL_POINTS);
    glPointParameterf(GL_POINT_SIZE_MIN, 1.0f);
    glEnd();
    fc_error(h, "inside begin");
}

/* Attenuated points across the near plane and the frame edges (a point
 * is kept or dropped whole by its centre), and glPointSize changes
 * between attenuated draws. */
static void atten_clip(fc_h *h)
{
    atten_view(h, 1);
    const GLfloat a[3] = { 0.2f, 0.3f, 0 };
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
    fcu_clear(0, 0, 0, 1, 1);
    for (int s = 0; s < 3; s++) {
        glPointSize(6.0f + 9.0f * (float)s);
        glBegin(GL_POINTS);
        for (int i = 0; i < 10; i++) {
            fcu_color(i + s);
            const float z = -0.7f - 0.25f * (float)i - 3.0f * (float)s;
            glVertex3f(-0.55f * -z + 0.11f * (float)i * -z, (0.3f * (float)s - 0.35f) * -z, z);
        }
        glEnd();
    }
    fc_capture(h);
}

/* A modelview with scale and rotation: the distance is |z_eye|, not the
 * object's z. */
static void atten_modelview(fc_h *h)
{
    atten_view(h, 1);
    const GLfloat a[3] = { 1, 0.2f, 0.01f };
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
    glPointSize(24);
    glTranslatef(0, 0, -6);
    glRotatef(60, 1, 0.3f, 0);
    glScalef(1.5f, 0.7f, 2.0f);
    fcu_clear(0, 0, 0, 1, 1);
    glBegin(GL_POINTS);
    for (int i = 0; i < 25; i++) {
        fcu_color(i);
        glVertex3f(0.5f * (float)(i % 5) - 1.0f, 0.5f * (float)(i / 5) - 1.0f, 0.3f * (float)(i % 3));
    }
    glEnd();
    fc_capture(h);
}

/* Under attenuation llvmpipe cuts points and non-smooth lines to the
 * viewport rectangle (ORACLE-NOTES.md "Point parameters"): the report's
 * repro (40x40, viewport (5, 5, 30, 30), size 20 attenuated to 40 at the
 * centre: 900 pixels), as a sprite (930: the row below the viewport too),
 * smooth (not cut), a viewport below the window (nothing), one ending at
 * x = 0 (vpwh's truncation keeps column 0), wide lines, and points of
 * glPolygonMode GL_POINT; one frame each. */
static void atten_viewport(fc_h *h)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const GLfloat a[3] = { 0.25f, 0, 0 };
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
    static const int vps[][4] = { { 5, 5, 30, 30 }, { 5, -40, 30, 30 }, { -30, 5, 30, 30 },
                                  { 5, 40, 30, 30 }, { 3, 9, 20, 14 } };
    for (int mode = 0; mode < 3; mode++) {   /* legacy, sprite, smooth */
        if (mode == 1)
            glEnable(GL_POINT_SPRITE);
        if (mode == 2) {
            glDisable(GL_POINT_SPRITE);
            glEnable(GL_POINT_SMOOTH);
        }
        for (int i = 0; i < 5; i++) {
            glViewport(0, 0, 40, 40);
            fcu_clear(0, 0, 0, 1, 1);
            glViewport(vps[i][0], vps[i][1], vps[i][2], vps[i][3]);
            glPointSize(20.0f - 3.0f * (float)i);
            glBegin(GL_POINTS);
            fcu_color(i + mode);
            glVertex2f(vps[i][0] < 0 ? 0.99f : 0.1f * (float)i, vps[i][1] >= 40 ? -0.99f : 0.0f);
            glEnd();
            fc_capture(h);
        }
    }
    glDisable(GL_POINT_SMOOTH);
    /* wide lines and GL_POINT polygons, the viewport cut */
    glViewport(0, 0, 40, 40);
    fcu_clear(0, 0, 0, 1, 1);
    glViewport(5, 5, 30, 30);
    glLineWidth(9);
    glBegin(GL_LINES);
    fcu_color(1);
    glVertex2f(-0.5f, 0.95f);
    glVertex2f(0.7f, 0.8f);
    fcu_color(2);
    glVertex2f(-0.97f, -0.9f);
    glVertex2f(-0.9f, 0.4f);
    glEnd();
    glPointSize(5);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glBegin(GL_TRIANGLES);
    fcu_color(3);
    glVertex2f(0.99f, 0.99f);
    glVertex2f(0.2f, -0.99f);
    glVertex2f(0.99f, 0.2f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    fc_capture(h);
}

/* Sprites cut at their bottom by the attenuated viewport or the scissor
 * box keep the row below it unless that row starts the next band of 64x64
 * tiles (ORACLE-NOTES.md "Point sprites"): an 80x72 window, viewports
 * ending at GL y = 8 (y-down row 64) and 20, the scissor alone without
 * attenuation. */
static void sprite_region_row(fc_h *h)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_POINT_SPRITE);
    const GLfloat a[3] = { 0.25f, 0, 0 }, none[3] = { 1, 0, 0 };
    for (int f = 0; f < 3; f++) {
        glViewport(0, 0, 80, 72);
        fcu_clear(0, 0, 0, 1, 1);
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, f < 2 ? a : none);
        glViewport(f == 1 ? 7 : 30, f == 0 ? 8 : 20, 40, 40);
        if (f == 2) {
            glScissor(20, 30, 30, 25);
            glEnable(GL_SCISSOR_TEST);
        }
        glPointSize(f < 2 ? 13.5f : 27);
        glBegin(GL_POINTS);
        fcu_color(f);
        glVertex2f(-0.3f, -0.45f);
        fcu_color(f + 4);
        glVertex2f(0.6f, -0.85f);
        glEnd();
        glDisable(GL_SCISSOR_TEST);
        fc_capture(h);
    }
}

/* llvmpipe's viewport cut of the draw region under attenuation is state
 * (ORACLE-NOTES.md "Point parameters", "The cut is state"; probe
 * p_vpcut_state): computed by the first primitive after a viewport,
 * scissor or framebuffer change, a flush or a pixel rectangle, with the
 * rasterizer bound then (a smooth point's or line's: no cut), and kept.
 * Each frame: a viewport from GL row 7, attenuation on, a first primitive,
 * an event (or none), then a wide smooth line and a wide point that reach
 * below the viewport. */
static void vpcut_tri(void)
{
    glBegin(GL_TRIANGLES);
    glColor3f(0, 0, 1);
    glVertex2f(40, 40);
    glVertex2f(41, 40);
    glVertex2f(40, 41);
    glEnd();
}

static void vpcut_smooth(int points)
{
    glEnable(points ? GL_POINT_SMOOTH : GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glLineWidth(6);
    glPointSize(9);
    glBegin(points ? GL_POINTS : GL_LINES);
    glColor3f(1, 0, 0);
    glVertex2f(points ? 30 : 2, 9);
    if (!points)
        glVertex2f(60, 10);
    glEnd();
    glDisable(GL_BLEND);
    glDisable(points ? GL_POINT_SMOOTH : GL_LINE_SMOOTH);
}

static void vpcut_events(fc_h *h)
{
    static const GLfloat att[3] = { 1, 0.5f, 0.25f }, none[3] = { 1, 0, 0 };
    /* 3 rows of one byte at GL_UNPACK_ALIGNMENT 4: a row every 4 bytes */
    static const GLubyte bits[3 * 4] = { 0xff, 0, 0, 0, 0x81, 0, 0, 0, 0xff, 0, 0, 0 };
    const GLubyte rgba[4] = { 0, 200, 0, 255 };
    GLubyte rb[4];
    for (int f = 0; f < 24; f++) {
        glViewport(0, 0, 64, 64);
        glDepthRange(0, 1);
        fcu_clear(0, 0, 0, 0, 1);
        glViewport(0, 7, 64, 57);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0, 64, 7, 64, -1, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glScissor(0, 0, 64, 64);
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, f == 20 ? none : att);
        if (f == 12)
            vpcut_smooth(1);            /* a smooth point first: no cut */
        else if (f == 13) {
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            vpcut_tri();                /* polygon-mode lines: cut */
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        } else if (f == 1 || f == 21)
            vpcut_smooth(0);            /* a smooth line first: no cut */
        else
            vpcut_tri();                /* a triangle first: cut */
        switch (f) {
        case 2: glFinish(); break;
        case 3: glViewport(0, 7, 64, 56); break;
        case 4: glViewport(0, 7, 64, 57); break;            /* unchanged */
        case 5: glEnable(GL_SCISSOR_TEST); break;
        case 6: glScissor(0, 0, 60, 64); break;             /* test off */
        case 7: glDepthRange(0.25, 1); break;
        case 8:
            glRasterPos2f(50, 50);
            glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
            break;
        case 9: glClear(GL_COLOR_BUFFER_BIT); break;        /* a plain clear */
        case 10:
            glColorMask(1, 0, 1, 1);                        /* a quad clear */
            glClear(GL_COLOR_BUFFER_BIT);
            glColorMask(1, 1, 1, 1);
            break;
        case 11: glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rb); break;
        case 14:
            glRasterPos2f(50, 50);
            glBitmap(8, 3, 0, 0, 0, 0, bits);
            break;
        case 15: glFlush(); break;
        case 16:
            glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
            vpcut_tri();
            glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
            break;
        case 17: glViewport(0, 7, 64, 50); glViewport(0, 7, 64, 57); break;
        case 18:
            glScissor(0, 0, 60, 64);
            glEnable(GL_SCISSOR_TEST);
            glDisable(GL_SCISSOR_TEST);
            break;
        case 19:
            glRasterPos2f(50, 50);
            glCopyPixels(40, 40, 2, 2, GL_COLOR);
            break;
        case 20:                       /* decided before attenuation */
            glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
            break;
        case 21: vpcut_tri(); break;   /* after a smooth line: stays uncut */
        case 22:
            glEnable(GL_SCISSOR_TEST);
            vpcut_tri();
            glDisable(GL_SCISSOR_TEST);
            break;
        case 23:
            glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
            glViewport(0, 7, 64, 56);
            vpcut_tri();               /* decided without attenuation */
            glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
            break;
        default: break;
        }
        vpcut_smooth(0);
        glPointSize(12);
        glBegin(GL_POINTS);
        glColor3f(0, 1, 0);
        glVertex2f(20, 8);
        glEnd();
        vpcut_smooth(1);
        glPointSize(1);
        glLineWidth(1);
        fc_capture(h);
    }
}

/* The flushes llvmpipe makes on its own also mark the region (probe
 * p_vpcut_state): asking for a query result that is not ready, and a
 * texel write into the resource the pending scene samples; not a query
 * begun or ended, another texture's write, an image given new storage, a
 * deletion or glGetTexImage.  Each frame: a textured triangle first (the
 * region cut), the event, then a wide smooth line, a wide point and a
 * smooth point reaching below the viewport. */
static void vpcut_flush_events(fc_h *h)
{
    static const GLfloat att[3] = { 1, 0.5f, 0.25f };
    static GLubyte texels[8 * 8 * 4];
    for (int i = 0; i < (int)sizeof texels; i++)
        texels[i] = (GLubyte)(255 - i);
    static const GLubyte blocks[8] = { 0xff, 0xff, 0, 0, 0, 0, 0, 0 };
    for (int f = 0; f < 14; f++) {
        glViewport(0, 0, 64, 64);
        fcu_clear(0, 0, 0, 0, 1);
        glViewport(0, 7, 64, 57);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0, 64, 7, 64, -1, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
        GLuint t[2], q[2];
        GLuint r = 0;
        glGenTextures(2, t);
        glGenQueries(2, q);
        for (int i = 1; i >= 0; i--) {
            glBindTexture(GL_TEXTURE_2D, t[i]);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            if (f == 11 && i == 0)
                glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 4, 4,
                                       0, 8, blocks);
            else
                glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                             texels);
        }
        if (f == 2 || f == 3 || f == 4)
            glBeginQuery(GL_SAMPLES_PASSED, q[0]);
        glEnable(GL_TEXTURE_2D);
        vpcut_tri();
        glDisable(GL_TEXTURE_2D);
        switch (f) {
        case 1: glBeginQuery(GL_SAMPLES_PASSED, q[1]); break;
        case 2: glEndQuery(GL_SAMPLES_PASSED); break;
        case 3:                         /* not ready: llvmpipe flushes */
            glEndQuery(GL_SAMPLES_PASSED);
            glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &r);
            break;
        case 4:                         /* asked in vain: a flush */
            glEndQuery(GL_SAMPLES_PASSED);
            glGetQueryObjectuiv(q[0], GL_QUERY_RESULT_AVAILABLE, &r);
            break;
        case 5:
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
            break;
        case 6:
            glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels);
            break;
        case 7:
            glBindTexture(GL_TEXTURE_2D, t[1]);
            glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels);
            break;
        case 8:                         /* new storage */
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
            break;
        case 9: glDeleteTextures(1, &t[0]); break;
        case 10: {
            static GLubyte out[4 * 4 * 4];
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
            break;
        }
        case 11:
            glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4,
                                      GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, blocks);
            break;
        case 12:                        /* the level-1 image of the same resource */
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
            break;
        case 13:                        /* drawn without texturing in between */
            vpcut_tri();
            glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels);
            break;
        default: break;
        }
        vpcut_smooth(0);
        glPointSize(12);
        glBegin(GL_POINTS);
        glColor3f(0, 1, 0);
        glVertex2f(20, 8);
        glEnd();
        vpcut_smooth(1);
        glPointSize(1);
        glLineWidth(1);
        if (f == 1)
            glEndQuery(GL_SAMPLES_PASSED);
        fc_capture(h);
        glDeleteTextures(2, t);
        glDeleteQueries(2, q);
    }
}

/* Polygon-mode points of triangles clipped by the near and far planes and
 * by the viewport's sides: the new vertices' sizes are the clipper's lerp of
 * the attenuated sizes (draw_pipe_clip.c interp: every output), clamped
 * sizes above GL_POINT_SIZE_MIN; flat and smooth shading, smooth points.
 * (random-raster/s1-i1293) */
static void atten_unfilled_clip(fc_h *h)
{
    static const GLfloat att[3] = { 0.95f, 0.35f, 0.4f };
    for (int f = 0; f < 3; f++) {
        glViewport(0, 0, 64, 64);
        fcu_clear(0.2f, 0.2f, 0.3f, 1, 1);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0, 64, 0, 64, -1, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
        glPointParameterf(GL_POINT_SIZE_MIN, 3.4f);
        glPointSize(f == 1 ? 2.3f : 7.5f);
        glShadeModel(f == 0 ? GL_FLAT : GL_SMOOTH);
        if (f == 2)
            glEnable(GL_POINT_SMOOTH);
        glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
        glBegin(GL_TRIANGLES);
        fcu_color(1);
        glVertex3f(8, 10, -1.5f);
        fcu_color(2);
        glVertex3f(50, 14, 1.5f);
        fcu_color(3);
        glVertex3f(30, 55, 0.2f);
        fcu_color(4);
        glVertex3f(-20, 30, 0.5f);
        fcu_color(5);
        glVertex3f(40, 40, -0.3f);
        fcu_color(6);
        glVertex3f(90, 50, 1.8f);
        glEnd();
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glDisable(GL_POINT_SMOOTH);
        glShadeModel(GL_SMOOTH);
        fc_capture(h);
    }
}

/* The viewport cut under attenuation is the draw region of every
 * primitive, triangles too: a quad the clipper leaves whole although a
 * vertex sits at clip (0, 0, 0, 0) (inside every plane, its window
 * position not a number) reaches past the viewport, and llvmpipe cuts it
 * there (random-raster s2-i979: 91 pixels below the viewport); without
 * attenuation it is not cut. */
static void vpcut_triangle_w0(fc_h *h)
{
    static const GLfloat pos[4][4] = {
        { 0x0.0p+0f, 0x0.0p+0f, 0x0.0p+0f, 0x0.0p+0f },
        { 0x1.405bcc0000000p-21f, 0x1.1413940000000p-18f, -0x1.3b6ace0000000p-19f, 0x1.1413940000000p-18f },
        { 0x1.383be20000000p-17f, -0x1.2d038e0000000p-17f, -0x1.5823b00000000p-19f, -0x1.383be20000000p-17f },
        { -0x1.0000000000000p+0f, -0x1.4ed00c0000000p-1f, -0x1.1b0d620000000p+0f, 0x1.0000000000000p+0f } };
    static const GLfloat col[4][4] = {
        { -0x1.263b260000000p-1f, -0x1.0000000000000p+0f, -0x1.b305b40000000p-2f, 0x1.0001000000000p-16f },
        { -0x1.1348740000000p-1f, 0x1.0000000000000p-32f, 0x1.c070b00000000p-1f, 0x1.0000000000000p+0f },
        { 0x1.8fb6ea0000000p-1f, -0x1.7945b40000000p-7f, -0x1.0000000000000p+0f, 0x1.0000000000000p+0f },
        { 0x1.85a1860000000p-3f, 0x1.d2d3820000000p-1f, 0x1.ce81960000000p-6f, 0x1.4211ec0000000p-1f } };
    static const GLfloat atten[3] = { 1.0f, 0x1.58755p-5f, 0x1.1dab62p-10f };
    for (int f = 0; f < 2; f++) {
        glViewport(0, 0, 110, 69);
        fcu_clear(0.96f, 0.18f, 0.93f, 0.12f, 1);
        glViewport(18, -23, 56, 37);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        if (f == 0)
            glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glVertexPointer(4, GL_FLOAT, 0, pos);
        glColorPointer(4, GL_FLOAT, 0, col);
        glDrawArrays(GL_QUADS, 0, 4);
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_COLOR_ARRAY);
        static const GLfloat none[3] = { 1.0f, 0.0f, 0.0f };
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
        fc_error(h, "draw");
        fc_capture(h);
    }
}


const fc_case fc_cases_gl14_points[] = {
    FC_CASE_RGBA("gl14/points_atten_linear", 64, 64, 1, "gl14 points", atten_linear),
    FC_CASE_RGBA("gl14/points_atten_quadratic", 64, 64, 1, "gl14 points", atten_quadratic),
    FC_CASE_RGBA("gl14/points_atten_constant", 64, 64, 1, "gl14 points", atten_constant),
    FC_CASE_RGBA("gl14/points_atten_all_terms", 64, 64, 1, "gl14 points", atten_all_terms),
    FC_CASE_RGBA("gl14/points_atten_small_constant", 64, 64, 1, "gl14 points", atten_small_constant),
    FC_CASE_RGBA("gl14/points_atten_ortho", 64, 64, 1, "gl14 points", atten_ortho),
    FC_CASE_RGBA("gl14/points_atten_min_clamp", 64, 64, 1, "gl14 points", atten_min_clamp),
    FC_CASE_RGBA("gl14/points_atten_max_clamp", 64, 64, 1, "gl14 points", atten_max_clamp),
    FC_CASE_RGBA("gl14/points_atten_min_above_max", 64, 64, 1, "gl14 points", atten_min_above_max),
    FC_CASE_RGBA("gl14/points_atten_below_one", 64, 64, 1, "gl14 points", atten_below_one),
    FC_CASE_RGBA("gl14/points_atten_huge", 64, 64, 1, "gl14 points", atten_huge),
    FC_CASE_RGBA("gl14/points_atten_negative_terms", 64, 64, 1, "gl14 points", atten_negative_terms),
    FC_CASE_RGBA("gl14/points_atten_smooth", 64, 64, 1, "gl14 points smooth", atten_smooth),
    FC_CASE_RGBA("gl14/points_atten_lit", 64, 64, 1, "gl14 points lighting", atten_lit),
    FC_CASE_RGBA("gl14/points_atten_fog", 64, 64, 1, "gl14 points fog", atten_fog),
    FC_CASE_RGBA("gl14/points_atten_fog_radial", 64, 64, 1, "gl14 points fog", atten_fog_radial),
    FC_CASE_RGBA("gl14/points_atten_textured", 64, 64, 1, "gl14 points texture", atten_textured),
    FC_CASE_RGBA("gl14/points_atten_texgen_eye", 64, 64, 1, "gl14 points texture", atten_texgen_eye),
    FC_CASE_RGBA("gl14/points_atten_flat_ortho", 64, 64, 1, "gl14 points", atten_flat_ortho),
    FC_CASE_RGBA("gl14/points_atten_smooth_ortho_clamp", 64, 64, 1, "gl14 points smooth",
                 atten_smooth_ortho_clamp),
    FC_CASE_RGBA("gl14/points_minmax_plain", 48, 48, 6, "gl14 points", minmax_plain),
    FC_CASE_RGBA("gl14/points_fade_threshold", 64, 64, 2, "gl14 points", fade_threshold),
    FC_CASE_RGBA("gl14/points_arrays_dlist", 64, 64, 4, "gl14 points varray dlist", atten_arrays_dlist),
    FC_CASE_RGBA("gl14/points_atten_clip", 64, 64, 1, "gl14 points clip", atten_clip),
    FC_CASE_RGBA("gl14/points_atten_modelview", 64, 64, 1, "gl14 points", atten_modelview),
    FC_CASE_RGBA("gl14/points_atten_viewport", 40, 40, 16, "gl14 points sprite smooth",
                 atten_viewport),
    FC_CASE_RGBA("gl14/sprite_region_row", 80, 72, 3, "gl14 points sprite scissor",
                 sprite_region_row),
    FC_CASE_RGBA("gl14/points_vpcut_events", 64, 64, 24, "gl14 points smooth scissor",
                 vpcut_events),
    FC_CASE_RGBA("gl14/points_vpcut_flush_events", 64, 64, 14, "gl14 points smooth query",
                 vpcut_flush_events),
    FC_CASE_RGBA("gl14/points_atten_unfilled_clip", 64, 64, 3, "gl14 points clip polygon",
                 atten_unfilled_clip),
    FC_CASE_RGBA("gl14/points_vpcut_triangle_w0", 110, 69, 2, "gl14 points clip",
                 vpcut_triangle_w0),
    FC_CASE_RGBA("gl14/points_params_api", 8, 8, 0, "gl14 points api error attrib dlist", params_api),
    { 0 },
};
