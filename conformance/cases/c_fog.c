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
#include <stdbool.h>
#include <stdio.h>

/* ---- scenes ---- */

/* Whole-buffer viewport, frustum from z = -1 to -30 (eye), depth test. */
static void fog_persp(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.6, 0.6, -0.6, 0.6, 1, 30);
    glEnable(GL_DEPTH_TEST);
}

/* Ortho view, eye z from -0.5 to -12. */
static void fog_ortho(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_ortho(-2, 2, -2, 2, 0.5, 12);
    glEnable(GL_DEPTH_TEST);
}

static void fog_clear(void)
{
    fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
}

/* A receding floor (two large smooth triangles from z = -1.2 to -28), a
 * wall at an angle and a small near triangle, each vertex its own colour. */
static void fog_draw_scene(void)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0.2f, 0.2f);  glVertex3f(-3, -1, -1.2f);
    glColor3f(0.2f, 1, 0.2f);  glVertex3f(3, -1, -1.2f);
    glColor3f(0.2f, 0.3f, 1);  glVertex3f(6, -1, -28);
    glColor3f(1, 0.2f, 0.2f);  glVertex3f(-3, -1, -1.2f);
    glColor3f(0.2f, 0.3f, 1);  glVertex3f(6, -1, -28);
    glColor4f(1, 1, 0.2f, 0.5f); glVertex3f(-6, -1, -28);
    /* wall: left near, right far */
    glColor3f(0.9f, 0.9f, 0.9f); glVertex3f(-1.5f, -1, -2);
    glColor3f(0.9f, 0.5f, 0.1f); glVertex3f(4, -1, -20);
    glColor3f(0.1f, 0.8f, 0.9f); glVertex3f(-1.5f, 3, -2.5f);
    glColor3f(0.1f, 0.8f, 0.9f); glVertex3f(-1.5f, 3, -2.5f);
    glColor3f(0.9f, 0.5f, 0.1f); glVertex3f(4, -1, -20);
    glColor3f(0.6f, 0.2f, 0.9f); glVertex3f(4, 8, -20);
    /* near triangle */
    glColor3f(1, 1, 1);        glVertex3f(0.2f, 0.1f, -1.5f);
    glColor3f(0, 0, 0);        glVertex3f(0.6f, 0.2f, -1.6f);
    glColor3f(1, 0, 1);        glVertex3f(0.3f, 0.5f, -1.4f);
    glEnd();
}

/* The same floor and wall under ortho (z from -0.6 to -11.5). */
static void fog_draw_ortho_scene(void)
{
    glBegin(GL_TRIANGLE_STRIP);
    glColor3f(1, 0.2f, 0.2f);  glVertex3f(-1.9f, -1.9f, -0.6f);
    glColor3f(0.2f, 1, 0.2f);  glVertex3f(1.9f, -1.9f, -3);
    glColor3f(0.2f, 0.3f, 1);  glVertex3f(-1.9f, 1.9f, -8);
    glColor3f(1, 1, 0.2f);     glVertex3f(1.9f, 1.9f, -11.5f);
    glEnd();
}

/* Sets mode and its parameters. */
static void fog_mode(GLenum mode, float a, float b)
{
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, (GLint)mode);
    if (mode == GL_LINEAR) {
        glFogf(GL_FOG_START, a);
        glFogf(GL_FOG_END, b);
    } else {
        glFogf(GL_FOG_DENSITY, a);
    }
}

static void fog_color(float r, float g, float b, float a)
{
    const GLfloat c[4] = { r, g, b, a };
    glFogfv(GL_FOG_COLOR, c);
}

/* Frame 1 smooth, frame 2 flat: the fog coordinate is interpolated in both
 * (only colours are flat-shaded). */
static void fog_persp_mode(fc_h *h, GLenum mode, float a, float b)
{
    fog_persp(h);
    fog_mode(mode, a, b);
    fog_color(0.7f, 0.75f, 0.8f, 1);
    for (int flat = 0; flat < 2; flat++) {
        glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
        fog_clear();
        fog_draw_scene();
        fc_capture(h);
    }
}

static void linear_persp(fc_h *h) { fog_persp_mode(h, GL_LINEAR, 1.5f, 25); }
static void exp_persp(fc_h *h) { fog_persp_mode(h, GL_EXP, 0.11f, 0); }
static void exp2_persp(fc_h *h) { fog_persp_mode(h, GL_EXP2, 0.09f, 0); }

/* The default mode (GL_EXP, density 1) with only glEnable(GL_FOG), and the
 * default black fog colour. */
static void default_params(fc_h *h)
{
    fog_persp(h);
    glEnable(GL_FOG);
    fog_clear();
    fog_draw_scene();
    fc_capture(h);
}

/* A large buffer of smooth fog gradients (many colour rounding ties):
 * one frame per mode. */
static void large_floor(fc_h *h)
{
    static const GLenum modes[3] = { GL_LINEAR, GL_EXP, GL_EXP2 };
    fog_persp(h);
    fog_color(0.45f, 0.5f, 0.55f, 1);
    for (int m = 0; m < 3; m++) {
        fog_mode(modes[m], modes[m] == GL_LINEAR ? 1.3f : 0.071f, 27);
        fog_clear();
        glBegin(GL_QUADS);
        for (int i = 0; i < 4; i++) {
            const float x = -6 + 3 * (float)i;
            glColor3f(0.2f * (float)i, 1, 0.3f);  glVertex3f(x, -1, -1.01f);
            glColor3f(1, 0.1f, 0.25f * (float)i); glVertex3f(x + 3, -1, -1.01f);
            glColor3f(0.3f, 0.2f, 1);             glVertex3f(x + 3, -1, -29);
            glColor3f(1, 1, 1);                   glVertex3f(x, -1, -29);
            glColor3f(0.9f, 0.3f * (float)i, 0);  glVertex3f(x, 8, -29);
            glColor3f(0, 0.6f, 0.2f * (float)i);  glVertex3f(x + 3, 8, -29);
            glColor3f(0.5f, 0.5f, 0.5f);          glVertex3f(x + 3, -1, -29);
            glColor3f(0.1f, 0.9f, 0.9f);          glVertex3f(x, -1, -29);
        }
        glEnd();
        fc_capture(h);
    }
}

/* Each mode under ortho, smooth then flat. */
static void modes_ortho(fc_h *h)
{
    static const GLenum modes[3] = { GL_LINEAR, GL_EXP, GL_EXP2 };
    fog_ortho(h);
    fog_color(0.2f, 0.6f, 0.3f, 1);
    for (int m = 0; m < 3; m++) {
        fog_mode(modes[m], modes[m] == GL_LINEAR ? 0.3f : 0.2f, 12);
        for (int flat = 0; flat < 2; flat++) {
            glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
            fog_clear();
            fog_draw_ortho_scene();
            fc_capture(h);
        }
    }
}

/* start == end: Mesa uses -1/(end-start) = 1 there, so f = z - end
 * (clamped): frames at end = 0, 5 and 30. */
static void start_equals_end(fc_h *h)
{
    static const float ends[3] = { 0, 5, 30 };
    fog_persp(h);
    fog_color(0.9f, 0.2f, 0.6f, 1);
    for (int i = 0; i < 3; i++) {
        fog_mode(GL_LINEAR, ends[i], ends[i]);
        fog_clear();
        fog_draw_scene();
        fc_capture(h);
    }
}

/* start > end (fog thins with distance), a range entirely in front of the
 * scene, one entirely behind it, and negative start / end. */
static void linear_ranges(fc_h *h)
{
    static const float r[4][2] = { { 20, 2 }, { -5, 0.5f }, { 40, 60 }, { -10, -1 } };
    fog_persp(h);
    fog_color(0.8f, 0.8f, 0.3f, 1);
    for (int i = 0; i < 4; i++) {
        fog_mode(GL_LINEAR, r[i][0], r[i][1]);
        fog_clear();
        fog_draw_scene();
        fc_capture(h);
    }
}

/* EXP and EXP2 with density 0 (no fog), tiny, large (the factor underflows
 * gallivm's exp2 clamp) and huge (infinite parameters). */
static void density_extremes(fc_h *h)
{
    static const float d[4] = { 0, 1e-4f, 40, 1e38f };
    fog_persp(h);
    fog_color(0.3f, 0.5f, 0.9f, 1);
    for (int m = 0; m < 2; m++) {
        for (int i = 0; i < 4; i++) {
            fog_mode(m ? GL_EXP2 : GL_EXP, d[i], 0);
            fog_clear();
            fog_draw_scene();
            fc_capture(h);
        }
    }
}

/* Fog colour alpha leaves the fragment alpha alone (the scene has alpha
 * 0.5 at one vertex); components outside [0,1] are clamped (and read back
 * clamped); NaN becomes 0. */
static void color_alpha(fc_h *h)
{
    fog_persp(h);
    fog_mode(GL_LINEAR, 1, 20);
    fog_color(0.4f, 0.9f, 0.6f, 0.25f);
    fog_clear();
    fog_draw_scene();
    fc_capture(h);
    fog_color(2, -1, 0.5f, 7);
    fog_clear();
    fog_draw_scene();
    fc_capture(h);
    fc_get_float(h, "GL_FOG_COLOR", GL_FOG_COLOR, 4);
    fc_get_integer(h, "GL_FOG_COLOR int", GL_FOG_COLOR, 4);
    /* Mesa's CLAMP makes a NaN component 0 */
    fog_color(NAN, 0.5f, 0.5f, 1);
    fog_clear();
    fog_draw_scene();
    fc_capture(h);
    fc_get_float(h, "GL_FOG_COLOR NaN", GL_FOG_COLOR, 4);
    fc_get_integer(h, "GL_FOG_COLOR NaN int", GL_FOG_COLOR, 4);
}

/* Fog on every primitive type, with a tilted modelview so that z varies
 * across each one, smooth then flat. */
static void primitives(fc_h *h)
{
    static const GLenum modes[6] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                     GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    static const float (*verts[6])[2] = { fcu_tri_v, fcu_strip_v, fcu_fan_v,
                                          fcu_quads_v, fcu_qstrip_v, fcu_poly_v };
    static const int counts[6] = { 6, 8, 7, 8, 8, 6 };
    fog_persp(h);
    fog_mode(GL_EXP, 0.25f, 0);
    fog_color(1, 1, 1, 1);
    for (int flat = 0; flat < 2; flat++) {
        glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
        fog_clear();
        for (int p = 0; p < 6; p++) {
            glLoadIdentity();
            glTranslatef(-1.6f + 1.1f * (float)(p % 3), p < 3 ? 0.1f : -1.6f, -4);
            glRotatef(-65, 1, 0.2f, 0);
            glScalef(1.0f / 32, 1.0f / 32, 1.0f / 32);
            glBegin(modes[p]);
            for (int i = 0; i < counts[p]; i++) {
                fcu_color(i + p);
                glVertex2fv(verts[p][i]);
            }
            glEnd();
        }
        fc_capture(h);
    }
}

/* The eye z is what counts: the same object under modelviews that move it
 * along z, rotate it about x, scale it, and a general matrix (the DP4 of
 * the third row). */
static void modelview(fc_h *h)
{
    static const GLfloat general[16] = {
        1, 0.2f, -0.3f, 0,
        0.1f, 0.9f, 0.4f, 0,
        0.3f, -0.2f, 1.2f, 0,
        0.5f, -0.3f, -7, 1,
    };
    fog_persp(h);
    fog_mode(GL_LINEAR, 2, 14);
    fog_color(0.5f, 0.5f, 0.55f, 1);
    for (int f = 0; f < 4; f++) {
        fog_clear();
        glLoadIdentity();
        switch (f) {
        case 0:
            glTranslatef(0.3f, 0, -6);
            break;
        case 1:
            glTranslatef(0, 0, -7);
            glRotatef(-70, 1, 0, 0);
            break;
        case 2:
            glTranslatef(0, 0.5f, -5);
            glRotatef(30, 0, 1, 0);
            glScalef(2.5f, 1.5f, 3);
            break;
        default:
            glLoadMatrixf(general);
            break;
        }
        glBegin(GL_QUADS);
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                const float x0 = -2 + (float)i, y0 = -2 + (float)j;
                fcu_color(i + 4 * j);
                glVertex3f(x0, y0, 0.3f * (float)i);
                glVertex3f(x0 + 1, y0, 0.3f * (float)(i + 1));
                glVertex3f(x0 + 1, y0 + 1, -0.2f * (float)j);
                glVertex3f(x0, y0 + 1, 0);
            }
        }
        glEnd();
        fc_capture(h);
    }
}

/* Triangles crossing the near plane (and one the far plane): the clipper's
 * new vertices interpolate the fog coordinate like the colours. */
static void near_clip(fc_h *h)
{
    fog_persp(h);
    fog_color(0.9f, 0.9f, 0.95f, 1);
    for (int m = 0; m < 2; m++) {
        fog_mode(m ? GL_EXP2 : GL_LINEAR, m ? 0.12f : 0.0f, 12);
        fog_clear();
        glBegin(GL_TRIANGLES);
        glColor3f(1, 0, 0);  glVertex3f(-1, -0.6f, 2);
        glColor3f(0, 1, 0);  glVertex3f(1.2f, -0.5f, 1);
        glColor3f(0, 0, 1);  glVertex3f(0.2f, 0.4f, -9);
        glColor3f(1, 1, 0);  glVertex3f(-0.2f, 0.6f, -0.5f);
        glColor3f(0, 1, 1);  glVertex3f(-2, 1.5f, -6);
        glColor3f(1, 0, 1);  glVertex3f(0.5f, -1, -45);
        glEnd();
        glShadeModel(GL_FLAT);
        glBegin(GL_QUADS);
        glColor3f(0.8f, 0.4f, 0);  glVertex3f(0.3f, 0.2f, 0.5f);
        glColor3f(0.2f, 0.4f, 0);  glVertex3f(1.5f, 0.2f, -10);
        glColor3f(0.8f, 0.9f, 0);  glVertex3f(1.5f, 1.2f, -12);
        glColor3f(0.2f, 0.4f, 1);  glVertex3f(0.3f, 1.2f, 0.2f);
        glEnd();
        glShadeModel(GL_SMOOTH);
        fc_capture(h);
    }
}

/* Lit sphere and wave in fog: frame 1 a directional light (object-space
 * lighting: the fog z comes from the DP4), frame 2 separate specular (eye
 * space, fog after the colour sum), frame 3 a positional light (the eye
 * position of the lighting code is reused), frame 4 a local viewer,
 * frame 5 two-sided lighting of a wave seen from both sides. */
static void lit(fc_h *h)
{
    static const float dim[3] = { 0.1f, 0.1f, 0.1f }, warm[3] = { 0.9f, 0.7f, 0.5f };
    static const float white[3] = { 1, 1, 1 };
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    fog_mode(GL_LINEAR, 3, 9);
    fog_color(0.4f, 0.45f, 0.6f, 1);
    for (int f = 0; f < 5; f++) {
        lt_clear();
        glLoadIdentity();
        if (f == 2) {
            lt_lamp(GL_LIGHT0, dim, warm, white, 1, 2, 1, 1);
        } else {
            lt_lamp(GL_LIGHT0, dim, warm, white, 0.5f, 0.7f, 1, 0);
        }
        lt_model(GL_LIGHT_MODEL_COLOR_CONTROL, (float)(f == 1 ? GL_SEPARATE_SPECULAR_COLOR
                                                              : GL_SINGLE_COLOR), 0, 0, 0);
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, f == 3);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, f == 4);
        glTranslatef(0, 0, -6);
        glRotatef(-50, 1, 0.3f, 0);
        if (f == 4) {
            lt_wave(-2.5f, -2.5f, 2.5f, 2.5f, 14, 0.4f, 2.5f);
        } else {
            lt_sphere(1.8f, 24, 16);
            glTranslatef(1.5f, 0, -4);
            lt_sphere(1.2f, 16, 12);
        }
        fc_capture(h);
    }
}

/* Which eye z the fog coordinate is: the lighting code's eye position
 * (the modelview's column MUL/MAD chain: a positional light, or a local
 * viewer with a specular term) or the DP4 with the third row (object-space
 * lighting, eye-space lighting without either, no lighting).  The two sum
 * in opposite orders and differ in the last bits, which only a fog ramp a
 * few ulps wide shows: a fan on a tilted plane that the modelview turns
 * back to eye z = -4 (each vertex's z off by a few ulps), with LINEAR fog
 * from 4 - 2^-19 to 4 + 2^-20 (a width that is no power of two, so the
 * factor's multiply rounds). */
static void eye_position_reuse(fc_h *h)
{
    static const float dim[3] = { 0.1f, 0.1f, 0.1f }, warm[3] = { 0.9f, 0.7f, 0.5f };
    static const float white[3] = { 1, 1, 1 };
    lt_persp(h);
    lt_std_material();
    fog_mode(GL_LINEAR, 4.0f - 1.0f / 524288, 4.0f + 1.0f / 1048576);
    fog_color(0.1f, 0.9f, 0.3f, 1);
    for (int f = 0; f < 6; f++) {
        lt_clear();
        glLoadIdentity();
        glDisable(GL_LIGHT0);
        glDisable(GL_LIGHT1);
        if (f == 1)
            lt_lamp(GL_LIGHT1, dim, warm, white, 0.5f, 1, 1, 1);
        else
            lt_lamp(GL_LIGHT0, dim, warm, white, 0.3f, 0.5f, 1, 0);
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                      f == 3 ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
        /* frame 2: local viewer (eye position); frame 4: local viewer
         * without a specular term (no eye position) */
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, f == 2 || f == 4);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, f == 4 ? 0.0f : 30.0f);
        if (f < 5)
            glEnable(GL_LIGHTING);
        else
            glDisable(GL_LIGHTING);
        glTranslatef(0.1f, -0.05f, -4);
        glRotatef(37, 1, 0.3f, 0.1f);
        glColor3f(0.8f, 0.6f, 0.4f);
        glNormal3f(0.2f, 0.1f, 1);
        /* the plane z' = 0 of the inverse rotation, in object space */
        glPushMatrix();
        glLoadIdentity();
        glRotatef(-37, 1, 0.3f, 0.1f);
        GLfloat inv[16];
        glGetFloatv(GL_MODELVIEW_MATRIX, inv);
        glPopMatrix();
        glBegin(GL_TRIANGLE_FAN);
        for (int i = 0; i < 10; i++) {
            const float u = i ? 1.7f * (float)cos(i * 0.7) : 0.05f;
            const float v = i ? 1.7f * (float)sin(i * 0.7) : 0.02f;
            glVertex3f(inv[0] * u + inv[4] * v, inv[1] * u + inv[5] * v, inv[2] * u + inv[6] * v);
        }
        glEnd();
        fc_capture(h);
    }
}

/* GL_NV_fog_distance under the same few-ulps LINEAR ramp: frames 1-2 the
 * radial distance (DP3, RSQ, RCP of the full eye position) of a patch of
 * the sphere of radius 3.98 around the eye (where 1/rsq(d) and sqrt(d)
 * often differ), unlit and lit; frame 3 the signed
 * GL_EYE_PLANE z of the tilted plane at z = -4 with the ramp around -4. */
static void distance_ulps(fc_h *h)
{
    static const float dim[3] = { 0.1f, 0.1f, 0.1f }, warm[3] = { 0.9f, 0.7f, 0.5f };
    static const float white[3] = { 1, 1, 1 };
    const float e = 1.0f / 524288;
    lt_persp(h);
    lt_std_material();
    lt_lamp(GL_LIGHT0, dim, warm, white, 0.3f, 0.5f, 1, 0);
    fog_color(0.1f, 0.9f, 0.3f, 1);
    for (int f = 0; f < 3; f++) {
        lt_clear();
        glLoadIdentity();
        if (f == 1)
            glEnable(GL_LIGHTING);
        else
            glDisable(GL_LIGHTING);
        glColor3f(0.8f, 0.6f, 0.4f);
        glNormal3f(0.2f, 0.1f, 1);
        if (f < 2) {
            glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
            fog_mode(GL_LINEAR, 3.98f - e, 3.98f + e);
            glRotatef(4, 0.2f, 1, 0.4f);
            for (int j = 0; j < 10; j++) {
                glBegin(GL_TRIANGLE_STRIP);
                for (int i = 0; i <= 10; i++) {
                    for (int k = 1; k >= 0; k--) {
                        const double a = -0.27 + 0.054 * i, b = -0.27 + 0.054 * (j + k);
                        glVertex3f((float)(3.98 * sin(a) * cos(b)), (float)(3.98 * sin(b)),
                                   (float)(-3.98 * cos(a) * cos(b)));
                    }
                }
                glEnd();
            }
        } else {
            glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE);
            fog_mode(GL_LINEAR, -4 - e, -4 + e);
            GLfloat inv[16];
            glRotatef(-37, 1, 0.3f, 0.1f);
            glGetFloatv(GL_MODELVIEW_MATRIX, inv);
            glLoadIdentity();
            glTranslatef(0.1f, -0.05f, -4);
            glRotatef(37, 1, 0.3f, 0.1f);
            glBegin(GL_TRIANGLE_FAN);
            for (int i = 0; i < 10; i++) {
                const float u = i ? 1.7f * (float)cos(i * 0.7) : 0.05f;
                const float v = i ? 1.7f * (float)sin(i * 0.7) : 0.02f;
                glVertex3f(inv[0] * u + inv[4] * v, inv[1] * u + inv[5] * v,
                           inv[2] * u + inv[6] * v);
            }
            glEnd();
        }
        fc_capture(h);
    }
}

/* GL_FOG_HINT (and the perspective hint) in every value draws the same
 * image in the oracle. */
static void hint_values(fc_h *h)
{
    static const GLenum modes[3] = { GL_DONT_CARE, GL_FASTEST, GL_NICEST };
    fog_persp(h);
    fog_mode(GL_EXP2, 0.09f, 0);
    fog_color(0.7f, 0.7f, 0.7f, 1);
    for (int i = 0; i < 3; i++) {
        glHint(GL_FOG_HINT, modes[i]);
        glHint(GL_PERSPECTIVE_CORRECTION_HINT, modes[i]);
        fog_clear();
        fog_draw_scene();
        fc_capture(h);
        fc_get_integer(h, "GL_FOG_HINT", GL_FOG_HINT, 1);
    }
}

/* GL_NV_fog_distance: the signed eye z (GL_EYE_PLANE: negative in front of
 * the eye, so LINEAR with a negative range shows it), the radial distance
 * (GL_EYE_RADIAL_NV, from the full eye position), back to the default. */
static void distance_mode(fc_h *h)
{
    fog_persp(h);
    fog_color(0.85f, 0.8f, 0.6f, 1);
    glRotatef(20, 0, 1, 0);
    for (int f = 0; f < 5; f++) {
        switch (f) {
        case 0:
            glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE);
            fog_mode(GL_LINEAR, -25, -1);
            break;
        case 1:
            fog_mode(GL_EXP, 0.1f, 0);
            break;
        case 2:
            glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
            fog_mode(GL_LINEAR, 1, 25);
            break;
        case 3:
            fog_mode(GL_EXP2, 0.08f, 0);
            break;
        default:
            glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE_ABSOLUTE_NV);
            break;
        }
        fog_clear();
        fog_draw_scene();
        fc_capture(h);
        fc_get_integer(h, "GL_FOG_DISTANCE_MODE_NV", GL_FOG_DISTANCE_MODE_NV, 1);
    }
}

/* Radial distance with lighting: the eye position chain either way. */
static void distance_radial_lit(fc_h *h)
{
    static const float dim[3] = { 0.1f, 0.1f, 0.1f }, warm[3] = { 0.9f, 0.7f, 0.5f };
    static const float white[3] = { 1, 1, 1 };
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_lamp(GL_LIGHT0, dim, warm, white, 0.5f, 0.7f, 1, 0);
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
    fog_mode(GL_EXP, 0.2f, 0);
    fog_color(0.4f, 0.45f, 0.6f, 1);
    glTranslatef(0.5f, 0, -6);
    lt_sphere(2, 24, 16);
    fc_capture(h);
}

/* GL_FOG_COORDINATE_SOURCE = GL_FOG_COORDINATE: the fog coordinate is the
 * current one (0, never set here), so f = 1 for EXP and end/(end-start)
 * for LINEAR, and NaN for EXP with an infinite density; back to
 * GL_FRAGMENT_DEPTH. */
static void coord_source(fc_h *h)
{
    fog_persp(h);
    fog_color(0.2f, 0.9f, 0.9f, 1);
    fc_get_integer(h, "GL_FOG_COORDINATE_SOURCE default", GL_FOG_COORDINATE_SOURCE, 1);
    glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
    fc_error(h, "source fog coordinate");
    fc_get_integer(h, "GL_FOG_COORDINATE_SOURCE", GL_FOG_COORDINATE_SOURCE, 1);
    for (int f = 0; f < 4; f++) {
        if (f == 0)
            fog_mode(GL_LINEAR, -2, 6);
        if (f == 1)
            fog_mode(GL_EXP, 0.5f, 0);
        if (f == 2)   /* 0 * inf: a NaN factor, which the clamp makes 0 */
            fog_mode(GL_EXP, 1e38f, 0);
        if (f == 3)
            glFogf(GL_FOG_COORDINATE_SOURCE, (float)GL_FRAGMENT_DEPTH);
        fog_clear();
        fog_draw_scene();
        fc_capture(h);
    }
}

/* glEnable / glDisable / glIsEnabled(GL_FOG); parameters set while fog is
 * off take effect when it is turned on. */
static void enable_disable(fc_h *h)
{
    fog_persp(h);
    fc_is_enabled(h, "GL_FOG default", GL_FOG);
    fc_get_boolean(h, "GL_FOG bool", GL_FOG, 1);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_END, 10);
    fog_color(1, 0.5f, 0, 1);
    fog_clear();
    fog_draw_scene();
    fc_capture(h);
    glEnable(GL_FOG);
    fc_is_enabled(h, "GL_FOG on", GL_FOG);
    fog_clear();
    fog_draw_scene();
    fc_capture(h);
    glDisable(GL_FOG);
    fc_is_enabled(h, "GL_FOG off", GL_FOG);
    fog_clear();
    fog_draw_scene();
    fc_capture(h);
}

/* Deterministic pseudo-random scenes (a local LCG, so the case is the same
 * in both renderers): per frame a mode with random parameters, fog colour,
 * shade model, modelview, lighting or not, the colour per vertex or
 * constant, and 40 triangles spread through the view volume (some crossing
 * the near plane). */
static unsigned fog_rng;

static float fog_rand(float lo, float hi)
{
    fog_rng = fog_rng * 1664525u + 1013904223u;
    return lo + (hi - lo) * (float)(fog_rng >> 8) * (1.0f / 16777216.0f);
}

static void random_scenes(fc_h *h)
{
    static const GLenum modes[3] = { GL_LINEAR, GL_EXP, GL_EXP2 };
    static const float dim[3] = { 0.1f, 0.1f, 0.1f }, warm[3] = { 0.9f, 0.7f, 0.5f };
    static const float white[3] = { 1, 1, 1 };
    fog_rng = 12345u;
    fog_persp(h);
    lt_std_material();
    for (int f = 0; f < 16; f++) {
        const GLenum mode = modes[f % 3];
        const float a = fog_rand(0, 10), b = fog_rand(2, 30);
        fog_mode(mode, mode == GL_LINEAR ? a : fog_rand(0.01f, 0.4f), b);
        fog_color(fog_rand(0, 1), fog_rand(0, 1), fog_rand(0, 1), fog_rand(0, 1));
        glShadeModel(f & 1 ? GL_FLAT : GL_SMOOTH);
        const bool lit = f % 4 == 2 || f % 4 == 3;
        if (lit) {
            glEnable(GL_LIGHTING);
            glLoadIdentity();
            lt_lamp(GL_LIGHT0, dim, warm, white, fog_rand(-1, 1), fog_rand(-1, 1), 1,
                    f & 1 ? 1.0f : 0.0f);
        } else {
            glDisable(GL_LIGHTING);
        }
        glLoadIdentity();
        glRotatef(fog_rand(-30, 30), fog_rand(-1, 1), fog_rand(-1, 1), fog_rand(-1, 1));
        glTranslatef(fog_rand(-1, 1), fog_rand(-1, 1), fog_rand(-2, 1));
        fog_clear();
        const bool constant = f % 8 == 4 || f % 8 == 7;
        if (constant)
            glColor4f(fog_rand(0, 1), fog_rand(0, 1), fog_rand(0, 1), fog_rand(0, 1));
        glBegin(GL_TRIANGLES);
        for (int t = 0; t < 40; t++) {
            const float cx = fog_rand(-8, 8), cy = fog_rand(-8, 8), cz = fog_rand(-28, 0);
            for (int v = 0; v < 3; v++) {
                if (!constant)
                    glColor4f(fog_rand(0, 1), fog_rand(0, 1), fog_rand(0, 1), fog_rand(0, 1));
                glNormal3f(fog_rand(-1, 1), fog_rand(-1, 1), 1);
                glVertex3f(cx + fog_rand(-4, 4), cy + fog_rand(-4, 4), cz + fog_rand(-6, 6));
            }
        }
        glEnd();
        fc_capture(h);
    }
}

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
    FC_CASE_RGBA("fog/linear_persp", 64, 64, 2, "fragment fog", linear_persp),
    FC_CASE_RGBA("fog/exp_persp", 64, 64, 2, "fragment fog", exp_persp),
    FC_CASE_RGBA("fog/exp2_persp", 64, 64, 2, "fragment fog", exp2_persp),
    FC_CASE_RGBA("fog/default_params", 64, 64, 1, "fragment fog", default_params),
    FC_CASE_RGBA("fog/large_floor", 160, 160, 3, "fragment fog", large_floor),
    FC_CASE_RGBA("fog/modes_ortho", 48, 48, 6, "fragment fog", modes_ortho),
    FC_CASE_RGBA("fog/start_equals_end", 64, 64, 3, "fragment fog", start_equals_end),
    FC_CASE_RGBA("fog/linear_ranges", 64, 64, 4, "fragment fog", linear_ranges),
    FC_CASE_RGBA("fog/density_extremes", 64, 64, 8, "fragment fog", density_extremes),
    FC_CASE_RGBA("fog/color_alpha", 64, 64, 3, "fragment fog", color_alpha),
    FC_CASE_RGBA("fog/primitives", 64, 64, 2, "fragment fog", primitives),
    FC_CASE_RGBA("fog/modelview", 64, 64, 4, "fragment fog", modelview),
    FC_CASE_RGBA("fog/near_clip", 64, 64, 2, "fragment fog clip", near_clip),
    FC_CASE_RGBA("fog/lit", 64, 64, 5, "fragment fog lighting", lit),
    FC_CASE_RGBA("fog/eye_position_reuse", 64, 64, 6, "fragment fog lighting", eye_position_reuse),
    FC_CASE_RGBA("fog/hint_values", 64, 64, 3, "fragment fog hint", hint_values),
    FC_CASE_RGBA("fog/distance_mode", 64, 64, 5, "fragment fog", distance_mode),
    FC_CASE_RGBA("fog/distance_ulps", 64, 64, 3, "fragment fog lighting", distance_ulps),
    FC_CASE_RGBA("fog/distance_radial_lit", 64, 64, 1, "fragment fog lighting", distance_radial_lit),
    FC_CASE_RGBA("fog/coord_source", 64, 64, 4, "fragment fog", coord_source),
    FC_CASE_RGBA("fog/enable_disable", 64, 64, 3, "fragment fog", enable_disable),
    FC_CASE_RGBA("fog/random_scenes", 96, 96, 16, "fragment fog lighting", random_scenes),
    FC_CASE_RGBA("fog/api_roundtrip", 8, 8, 0, "fragment fog api", api_roundtrip),
    FC_CASE_RGBA("fog/api_errors", 8, 8, 0, "fragment fog api error", api_errors),
    FC_CASE_RGBA("fog/api_hints", 8, 8, 0, "fragment fog api hint error", api_hints),
    { 0 },
};
