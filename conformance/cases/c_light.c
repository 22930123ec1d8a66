/* c_light.c - lighting: each light type alone and eight at once, spot
 * cutoff/exponent corners (exactly at the cutoff, exponent 0 and 128,
 * cutoff 0, 90 and 180), each attenuation term alone and together, a light
 * lying on the lit surface, local versus infinite viewer, separate specular
 * colour, shininess 0 / 0.5 / 128, global ambient and emission, colours out
 * of [0,1], and light positions / spot directions captured under different
 * modelviews (glLight transforms them at call time). */
#include "lt_util.h"

#include <math.h>

static const float k_black[3] = { 0, 0, 0 };
static const float k_dim[3] = { 0.1f, 0.1f, 0.1f };
static const float k_white[3] = { 1, 1, 1 };
static const float k_warm[3] = { 0.85f, 0.75f, 0.6f };
static const float k_grey[3] = { 0.6f, 0.6f, 0.6f };

/* ---- light types -------------------------------------------------------- */

/* Directional light on a sphere; modelview is a translation only, so Mesa
 * lights in object space.  Frame 2: another direction and colour. */
static void light_directional(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    glTranslatef(0, 0, -4);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1, 2, 0);
    lt_sphere(1.1f, 24, 16);
    fc_capture(h);
    lt_clear();
    lt_light(GL_LIGHT0, GL_POSITION, -1, -0.5f, 0.6f, 0);
    lt_light(GL_LIGHT0, GL_DIFFUSE, 0.3f, 0.6f, 1, 1);
    lt_sphere(1.1f, 24, 16);
    fc_capture(h);
}

/* Positional light: a sphere, then a tessellated plane close to the light
 * (diffuse gradient and specular highlight across the plane). */
static void light_positional(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    glTranslatef(0, 0, -4);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1.3f, 1.0f, 1.6f, 1);
    lt_sphere(1.1f, 24, 16);
    fc_capture(h);
    lt_clear();
    lt_light(GL_LIGHT0, GL_POSITION, 0.3f, 0.2f, 0.7f, 1);
    lt_patch(-1.5f, -1.5f, 1.5f, 1.5f, 20);
    fc_capture(h);
}

/* Spot light on a plane (cone edge and falloff), then on a sphere from the
 * upper right. */
static void spot_scene(fc_h *h, float exponent, float cutoff)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_model(GL_LIGHT_MODEL_AMBIENT, 0.3f, 0.3f, 0.3f, 1);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.8f, 0.7f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.4f, 0.4f, 0.4f, 1);
    glTranslatef(0, 0, -4);
    lt_lamp(GL_LIGHT0, k_black, k_warm, k_white, 0, 0, 1.6f, 1);
    lt_light(GL_LIGHT0, GL_SPOT_DIRECTION, 0.25f, 0.15f, -1, 0);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
    lt_patch(-1.5f, -1.5f, 1.5f, 1.5f, 24);
    fc_capture(h);
    lt_clear();
    lt_light(GL_LIGHT0, GL_POSITION, 1.6f, 1.4f, 1.8f, 1);
    lt_light(GL_LIGHT0, GL_SPOT_DIRECTION, -1.6f, -1.4f, -1.8f, 0);
    lt_sphere(1.1f, 32, 20);
    fc_capture(h);
}

static void light_spot(fc_h *h) { spot_scene(h, 8, 30); }
static void spot_exponent_0(fc_h *h) { spot_scene(h, 0, 35); }
static void spot_exponent_128(fc_h *h) { spot_scene(h, 128, 60); }
static void spot_exponent_fraction(fc_h *h) { spot_scene(h, 2.5f, 40); }
static void spot_cutoff_180(fc_h *h) { spot_scene(h, 20, 180); }
static void spot_cutoff_90(fc_h *h) { spot_scene(h, 1, 90); }
static void spot_cutoff_0(fc_h *h) { spot_scene(h, 0, 0); }

/* Vertices exactly on the cone: the spot looks straight down on a plane
 * from height 1 (then 0.5) with cutoff 45, and the grid (step 0.25) has
 * vertices at horizontal distance 1 (0.5) from the axis, where the
 * cosine of the angle equals cos(45 deg) up to rounding; the oracle's test
 * is strict (cosCutoff < d).  Frame 3: cutoff 45 plus the smallest float
 * step, frame 4 exponent 1 (edge values are small but not zero). */
static void spot_cutoff_exact(fc_h *h)
{
    static const float height[4] = { 1, 0.5f, 1, 1 };
    lt_ortho(h, 2);
    /* Shift the view by half a pixel so that the points are at pixel centres. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glTranslatef(1.0f / 64, 1.0f / 64, 0);
    glOrtho(-2, 2, -2, 2, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_LIGHTING);
    lt_model(GL_LIGHT_MODEL_AMBIENT, 0.1f, 0.1f, 0.1f, 1);
    lt_mat(GL_FRONT, GL_DIFFUSE, 1, 1, 1, 1);
    lt_mat(GL_FRONT, GL_AMBIENT, 1, 1, 1, 1);
    lt_lamp(GL_LIGHT0, k_black, k_grey, k_black, 0, 0, 1, 1);
    lt_light(GL_LIGHT0, GL_SPOT_DIRECTION, 0, 0, -1, 0);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 45);
    for (int f = 0; f < 4; f++) {
        lt_clear();
        lt_light(GL_LIGHT0, GL_POSITION, 0, 0, height[f], 1);
        if (f == 2)
            glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 45.000004f);
        if (f == 3) {
            glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 45);
            glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 1);
        }
        glShadeModel(GL_SMOOTH);
        lt_patch(-2, -2, 2, 2, 16);
        /* The grid vertices again as GL_POINTS (one pixel each, the
         * vertex's own colour, no interpolation), on top. */
        glDepthFunc(GL_ALWAYS);
        glBegin(GL_POINTS);
        glNormal3f(0, 0, 1);
        for (int j = 0; j <= 16; j++)
            for (int i = 0; i <= 16; i++)
                glVertex3f(-2 + 0.25f * (float)i, -2 + 0.25f * (float)j, 0);
        glEnd();
        glDepthFunc(GL_LESS);
        fc_capture(h);
    }
}

/* Eight lights of every kind at once on a sphere in front of a plane;
 * frame 2 with three of them disabled. */
static void eight_lights(fc_h *h)
{
    static const float col[8][3] = {
        { 0.4f, 0.05f, 0.05f }, { 0.05f, 0.35f, 0.05f }, { 0.05f, 0.05f, 0.4f }, { 0.3f, 0.3f, 0.05f },
        { 0.05f, 0.3f, 0.3f }, { 0.4f, 0.05f, 0.4f }, { 0.35f, 0.35f, 0.35f }, { 0.3f, 0.2f, 0.05f },
    };
    static const float pos[8][4] = {
        { 1, 0, 1, 0 }, { -1, 0.5f, 1, 0 }, { 0, -1, 0.5f, 0 }, { 1.5f, 1.5f, 1.5f, 1 },
        { -1.5f, -1, 1, 1 }, { 0, 2, 1, 1 }, { -1, -1, 2, 1 }, { 0, 0, 3, 1 },
    };
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1);
    glTranslatef(0, 0, -4.5f);
    for (int i = 0; i < 8; i++) {
        const float amb[3] = { col[i][0] * 0.1f, col[i][1] * 0.1f, col[i][2] * 0.1f };
        lt_lamp(GL_LIGHT0 + (GLenum)i, amb, col[i], col[i], pos[i][0], pos[i][1], pos[i][2], pos[i][3]);
    }
    glLightf(GL_LIGHT4, GL_LINEAR_ATTENUATION, 0.4f);
    lt_light(GL_LIGHT5, GL_SPOT_DIRECTION, 0, -1, -0.5f, 0);
    glLightf(GL_LIGHT5, GL_SPOT_CUTOFF, 25);
    glLightf(GL_LIGHT5, GL_SPOT_EXPONENT, 10);
    lt_light(GL_LIGHT6, GL_SPOT_DIRECTION, 0.3f, 0.3f, -1, 0);
    glLightf(GL_LIGHT6, GL_SPOT_CUTOFF, 15);
    glLightf(GL_LIGHT6, GL_SPOT_EXPONENT, 2);
    glLightf(GL_LIGHT7, GL_QUADRATIC_ATTENUATION, 0.1f);
    for (int f = 0; f < 2; f++) {
        if (f == 1) {
            lt_clear();
            glDisable(GL_LIGHT1);
            glDisable(GL_LIGHT4);
            glDisable(GL_LIGHT6);
        }
        lt_sphere(1, 24, 16);
        glPushMatrix();
        glTranslatef(0, 0, -1.2f);
        lt_patch(-2.5f, -2.5f, 2.5f, 2.5f, 16);
        glPopMatrix();
        fc_capture(h);
    }
}

/* ---- attenuation -------------------------------------------------------- */

/* Positional light with an ambient part near a plane and a sphere, with
 * attenuation factors k0, k1, k2 (the ambient term is attenuated too). */
static void atten_scene(fc_h *h, float k0, float k1, float k2)
{
    static const float amb[3] = { 0.25f, 0.2f, 0.15f };
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_model(GL_LIGHT_MODEL_AMBIENT, 0, 0, 0, 1);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 1, 1, 1, 1);
    glTranslatef(0, 0, -4);
    lt_lamp(GL_LIGHT0, amb, k_warm, k_white, -0.4f, 0.3f, 0.9f, 1);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, k0);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, k1);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, k2);
    lt_patch(-1.6f, -1.6f, 1.6f, 1.6f, 20);
    glTranslatef(0.6f, -0.5f, 0.5f);
    lt_sphere(0.45f, 16, 12);
    fc_capture(h);
}

static void atten_constant(fc_h *h) { atten_scene(h, 2.5f, 0, 0); }
static void atten_linear(fc_h *h) { atten_scene(h, 0, 1, 0); }
static void atten_quadratic(fc_h *h) { atten_scene(h, 0, 0, 1); }
static void atten_all(fc_h *h) { atten_scene(h, 0.3f, 0.4f, 0.5f); }

/* Attenuation is ignored for a directional light (frame 1) and combines
 * with the spot factor (frame 2); frame 3: constant 1 with the others 0,
 * the oracle's no-attenuation path, next to constant 1 + a tiny linear. */
static void atten_special(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    glTranslatef(0, 0, -4);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, -0.4f, 0.3f, 0.9f, 0);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 2);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 1);
    lt_sphere(1.1f, 24, 16);
    fc_capture(h);
    lt_clear();
    lt_light(GL_LIGHT0, GL_POSITION, 0.2f, 0.1f, 1.2f, 1);
    lt_light(GL_LIGHT0, GL_SPOT_DIRECTION, 0, 0, -1, 0);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 50);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 3);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.2f);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.3f);
    lt_patch(-1.6f, -1.6f, 1.6f, 1.6f, 20);
    fc_capture(h);
    lt_clear();
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0);
    glPushMatrix();
    glTranslatef(-0.75f, 0, 0);
    lt_sphere(0.7f, 16, 12);
    glPopMatrix();
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 1e-7f);
    glTranslatef(0.75f, 0, 0);
    lt_sphere(0.7f, 16, 12);
    fc_capture(h);
}

/* A positional light exactly on the lit surface, at a vertex of the grid
 * (the light vector of that vertex has length 0), on a wavy patch whose
 * other vertices face the light at various angles: frame 1 no attenuation,
 * frame 2 with attenuation, frame 3 a spot there.  Frame 4: a flat patch
 * with the light in its plane but off the vertices (n.L = 0 everywhere),
 * next to a directional light. */
static void light_on_surface(fc_h *h)
{
    lt_ortho(h, 1.2f);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0, 0, 0, 1);
    glRotatef(-30, 1, 0, 0);
    for (int f = 0; f < 4; f++) {
        if (f == 1)
            glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 1);
        if (f == 2) {
            glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0);
            lt_light(GL_LIGHT0, GL_SPOT_DIRECTION, 1, 1, 0, 0);
            glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 60);
        }
        lt_clear();
        if (f < 3) {
            lt_wave(-1, -1, 1, 1, 8, 0.3f, 3);
        } else {
            glLoadIdentity();
            glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
            lt_light(GL_LIGHT0, GL_POSITION, 0.3f, 0.1f, 0, 1);
            lt_lamp(GL_LIGHT1, k_black, k_grey, k_black, -1, 0.5f, 1, 0);
            lt_patch(-1, -1, 1, 1, 8);
        }
        fc_capture(h);
    }
}

/* ---- viewer, specular, shininess ---------------------------------------- */

/* Infinite (frame 1) versus local viewer (frame 2): specular highlights of
 * a directional and a positional light on a sphere (frames 1-2) and on a
 * plane (frames 3-4). */
static void viewer_local(fc_h *h)
{
    static const float blue[3] = { 0.2f, 0.4f, 0.9f };
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.5f, 0.35f, 0.2f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 60);
    glTranslatef(0, 0, -3.2f);
    lt_lamp(GL_LIGHT0, k_black, k_grey, k_white, 1, 0.8f, 0.5f, 0);
    lt_lamp(GL_LIGHT1, k_black, blue, blue, -1.2f, -0.3f, 1.5f, 1);
    for (int f = 0; f < 4; f++) {
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, f & 1);
        fc_get_integer(h, "GL_LIGHT_MODEL_LOCAL_VIEWER", GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
        lt_clear();
        if (f < 2) {
            lt_sphere(1.1f, 24, 16);
        } else {
            glPushMatrix();
            glRotatef(-25, 1, 0, 0);
            lt_patch(-1.6f, -1.6f, 1.6f, 1.6f, 24);
            glPopMatrix();
        }
        fc_capture(h);
    }
}

/* GL_SEPARATE_SPECULAR_COLOR off / on: a saturated red diffuse sphere with
 * a white highlight (the per-vertex sum is clamped before interpolation
 * when off; primary and secondary are interpolated separately when on). */
static void separate_specular(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 1, 0.15f, 0.1f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12);
    glTranslatef(0, 0, -4);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.8f, 1, 1, 0);
    for (int f = 0; f < 2; f++) {
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, f ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
        fc_get_integer(h, "GL_LIGHT_MODEL_COLOR_CONTROL", GL_LIGHT_MODEL_COLOR_CONTROL, 1);
        lt_clear();
        lt_sphere(1.1f, 12, 8);
        fc_capture(h);
    }
}

/* Separate specular on a plane lit by a positional light, smooth then flat
 * (flat uses the provoking vertex of both colours); frame 3: back to
 * GL_SINGLE_COLOR, flat. */
static void separate_specular_plane(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.2f, 0.3f, 0.9f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 1, 0.8f, 0.5f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
    glTranslatef(0, 0, -4);
    glRotatef(-30, 1, 0, 0);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 0.2f, 0.5f, 0.8f, 1);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    for (int f = 0; f < 3; f++) {
        glShadeModel(f ? GL_FLAT : GL_SMOOTH);
        if (f == 2)
            glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
        lt_clear();
        lt_patch(-1.5f, -1.5f, 1.5f, 1.5f, 12);
        fc_capture(h);
    }
}

/* A shininess value: directional light (object-space lighting), then a
 * positional light (eye space), on a sphere. */
static void shininess_scene(fc_h *h, float shininess)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.35f, 0.5f, 0.25f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
    lt_rec_material(h, "GL_SHININESS", GL_FRONT, GL_SHININESS);
    glTranslatef(0, 0, -4);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.7f, 0.9f, 1, 0);
    lt_sphere(1.1f, 24, 16);
    fc_capture(h);
    lt_clear();
    lt_light(GL_LIGHT0, GL_POSITION, 0.9f, 1.0f, 1.8f, 1);
    lt_sphere(1.1f, 24, 16);
    fc_capture(h);
}

static void shininess_0(fc_h *h) { shininess_scene(h, 0); }
static void shininess_half(fc_h *h) { shininess_scene(h, 0.5f); }
static void shininess_128(fc_h *h) { shininess_scene(h, 128); }
static void shininess_fraction(fc_h *h) { shininess_scene(h, 7.3f); }

/* Global ambient and emission: no light enabled (frame 1: ambient only;
 * frame 2: plus emission), then one light (frame 3). */
static void ambient_emission(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.9f, 0.6f, 0.3f, 1);
    lt_model(GL_LIGHT_MODEL_AMBIENT, 0.5f, 0.4f, 0.3f, 1);
    glTranslatef(0, 0, -4);
    lt_sphere(1.1f, 16, 12);
    fc_capture(h);
    lt_clear();
    lt_mat(GL_FRONT_AND_BACK, GL_EMISSION, 0.1f, 0.0f, 0.3f, 1);
    lt_sphere(1.1f, 16, 12);
    fc_capture(h);
    lt_clear();
    lt_lamp(GL_LIGHT2, k_dim, k_grey, k_white, -1, 1, 1, 0);
    lt_sphere(1.1f, 16, 12);
    fc_capture(h);
}

/* Light and material colours outside [0,1] (negative light colours
 * subtract; the sum is clamped per vertex). */
static void colors_out_of_range(fc_h *h)
{
    static const float amb[3] = { -0.2f, 0.1f, 0.3f };
    static const float diff[3] = { 2.0f, 1.5f, -0.5f };
    static const float spec[3] = { -1.0f, 0.5f, 3.0f };
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    glTranslatef(0, 0, -4);
    lt_lamp(GL_LIGHT0, amb, diff, spec, 0.5f, 0.8f, 1, 0);
    lt_sphere(1.1f, 24, 16);
    fc_capture(h);
    lt_clear();
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 1.5f, -0.3f, 0.4f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_EMISSION, -0.2f, 0.2f, 0, 1);
    lt_model(GL_LIGHT_MODEL_AMBIENT, 0.3f, -0.5f, 0.2f, 1);
    lt_sphere(1.1f, 24, 16);
    fc_capture(h);
}

/* ---- light positions under different modelviews ------------------------- */

/* Camera from glRotate/glTranslate; the light is placed in world space
 * under it and keeps its eye position when the object then rotates
 * (frame 1); frame 2 respecifies it after the object rotation, so it turns
 * with the object. */
static void light_fixed_at_call(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    glTranslatef(0, 0, -4.5f);
    glRotatef(20, 1, 0, 0);
    glRotatef(-35, 0, 1, 0);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1.5f, 1.5f, 1, 1);
    glPushMatrix();
    glRotatef(70, 0, 0, 1);
    glRotatef(50, 1, 0, 0);
    lt_wave(-1.3f, -1.3f, 1.3f, 1.3f, 20, 0.15f, 3);
    fc_capture(h);
    lt_clear();
    lt_light(GL_LIGHT0, GL_POSITION, 1.5f, 1.5f, 1, 1);
    lt_wave(-1.3f, -1.3f, 1.3f, 1.3f, 20, 0.15f, 3);
    glPopMatrix();
    fc_capture(h);
}

/* Headlight: positional light at the eye, set with an identity modelview;
 * the camera moves afterwards (frames 1, 2), the light stays at the eye. */
static void light_headlight(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 0, 0, 0, 1);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.05f);
    for (int f = 0; f < 2; f++) {
        lt_clear();
        glLoadIdentity();
        glTranslatef(0.3f * (float)f, 0, -4.5f + (float)f);
        glRotatef(30 + 40 * (float)f, 1, 0.5f, 0);
        lt_sphere(0.9f, 20, 14);
        glTranslatef(0, 0, -1);
        lt_patch(-2, -2, 2, 2, 12);
        fc_capture(h);
    }
}

/* gluLookAt built from glMultMatrixf (orthonormal basis) and glTranslatef;
 * a sun (directional) and a lamp (positional) are set in world space under
 * it; floor and two spheres.  Frame 2 moves the eye and respecifies the
 * lights; frame 3 moves it again without respecifying (the lights keep
 * their eye-space positions). */
static void look_at(float ex, float ey, float ez)
{
    float f[3] = { -ex, -ey, -ez }, up[3] = { 0, 1, 0 }, s[3], u[3];
    float l = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int i = 0; i < 3; i++)
        f[i] /= l;
    s[0] = f[1] * up[2] - f[2] * up[1];
    s[1] = f[2] * up[0] - f[0] * up[2];
    s[2] = f[0] * up[1] - f[1] * up[0];
    l = sqrtf(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int i = 0; i < 3; i++)
        s[i] /= l;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    const GLfloat m[16] = {
        s[0], u[0], -f[0], 0,
        s[1], u[1], -f[1], 0,
        s[2], u[2], -f[2], 0,
        0, 0, 0, 1,
    };
    glLoadIdentity();
    glMultMatrixf(m);
    glTranslatef(-ex, -ey, -ez);
}

static void lookat_scene(void)
{
    glPushMatrix();
    glRotatef(-90, 1, 0, 0);
    lt_patch(-2.5f, -2.5f, 2.5f, 2.5f, 16);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(-0.7f, 0.6f, 0.2f);
    lt_sphere(0.6f, 20, 14);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.8f, 0.4f, -0.6f);
    lt_sphere(0.4f, 16, 12);
    glPopMatrix();
}

static void light_lookat_multmatrix(fc_h *h)
{
    static const float sun[3] = { 0.5f, 0.45f, 0.4f };
    static const float lamp[3] = { 0.5f, 0.6f, 0.9f };
    static const float eye[3][3] = { { 2.5f, 2, 3.5f }, { -3, 1.5f, 2.5f }, { 0.5f, 3.5f, 2.5f } };
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    for (int f = 0; f < 3; f++) {
        lt_clear();
        look_at(eye[f][0], eye[f][1], eye[f][2]);
        if (f < 2) {
            lt_lamp(GL_LIGHT0, k_dim, sun, sun, 0.3f, 1, 0.4f, 0);
            lt_lamp(GL_LIGHT1, k_black, lamp, lamp, -0.5f, 1.2f, 1.2f, 1);
        }
        lookat_scene();
        fc_capture(h);
    }
}

/* Spot direction given under a rotation and a non-uniform scale (the
 * direction is transformed by the upper 3x3 and normalised), then the
 * modelview is reset to draw a plane; frame 2 under a rotation only. */
static void spot_direction_modelview(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_model(GL_LIGHT_MODEL_AMBIENT, 0.25f, 0.25f, 0.25f, 1);
    lt_std_material();
    for (int f = 0; f < 2; f++) {
        lt_clear();
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        glPushMatrix();
        glRotatef(20, 0, 0, 1);
        if (f == 0)
            glScalef(3, 0.5f, 1.5f);
        lt_lamp(GL_LIGHT0, k_black, k_warm, k_white, 0, 0, 1.2f, 1);
        lt_light(GL_LIGHT0, GL_SPOT_DIRECTION, 0.3f, 0.1f, -1, 0);
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 35);
        glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 4);
        glPopMatrix();
        lt_patch(-1.6f, -1.6f, 1.6f, 1.6f, 24);
        fc_capture(h);
    }
}

/* Positional lights with w != 1: w = 2, w = 0.5 and w = -1 (xyz / w). */
static void light_position_w(fc_h *h)
{
    static const float w[3] = { 2, 0.5f, -1 };
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    glTranslatef(0, 0, -4);
    glRotatef(-20, 1, 0, 0);
    for (int f = 0; f < 3; f++) {
        lt_clear();
        lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white,
                0.5f * w[f], 0.4f * w[f], (f == 1 ? 0.6f : 1.0f) * w[f], w[f]);
        lt_patch(-1.6f, -1.6f, 1.6f, 1.6f, 20);
        fc_capture(h);
    }
}

const fc_case fc_cases_light[] = {
    FC_CASE_RGBA("lighting/light_directional", 48, 48, 2, "lighting light_type", light_directional),
    FC_CASE_RGBA("lighting/light_positional", 48, 48, 2, "lighting light_type", light_positional),
    FC_CASE_RGBA("lighting/light_spot", 48, 48, 2, "lighting light_type spot", light_spot),
    FC_CASE_RGBA("lighting/eight_lights", 64, 64, 2, "lighting light_type spot attenuation", eight_lights),
    FC_CASE_RGBA("lighting/spot_cutoff_exact", 64, 64, 4, "lighting spot", spot_cutoff_exact),
    FC_CASE_RGBA("lighting/spot_exponent_0", 48, 48, 2, "lighting spot", spot_exponent_0),
    FC_CASE_RGBA("lighting/spot_exponent_128", 48, 48, 2, "lighting spot", spot_exponent_128),
    FC_CASE_RGBA("lighting/spot_exponent_fraction", 48, 48, 2, "lighting spot", spot_exponent_fraction),
    FC_CASE_RGBA("lighting/spot_cutoff_180", 48, 48, 2, "lighting spot", spot_cutoff_180),
    FC_CASE_RGBA("lighting/spot_cutoff_90", 48, 48, 2, "lighting spot", spot_cutoff_90),
    FC_CASE_RGBA("lighting/spot_cutoff_0", 48, 48, 2, "lighting spot", spot_cutoff_0),
    FC_CASE_RGBA("lighting/atten_constant", 48, 48, 1, "lighting attenuation", atten_constant),
    FC_CASE_RGBA("lighting/atten_linear", 48, 48, 1, "lighting attenuation", atten_linear),
    FC_CASE_RGBA("lighting/atten_quadratic", 48, 48, 1, "lighting attenuation", atten_quadratic),
    FC_CASE_RGBA("lighting/atten_all", 48, 48, 1, "lighting attenuation", atten_all),
    FC_CASE_RGBA("lighting/atten_directional_spot_unit", 48, 48, 3, "lighting attenuation spot", atten_special),
    FC_CASE_RGBA("lighting/light_on_surface", 32, 32, 4, "lighting attenuation robust", light_on_surface),
    FC_CASE_RGBA("lighting/viewer_local", 48, 48, 4, "lighting viewer specular", viewer_local),
    FC_CASE_RGBA("lighting/separate_specular", 48, 48, 2, "lighting specular", separate_specular),
    FC_CASE_RGBA("lighting/separate_specular_plane", 48, 48, 3, "lighting specular shade", separate_specular_plane),
    FC_CASE_RGBA("lighting/shininess_0", 48, 48, 2, "lighting specular", shininess_0),
    FC_CASE_RGBA("lighting/shininess_half", 48, 48, 2, "lighting specular", shininess_half),
    FC_CASE_RGBA("lighting/shininess_128", 48, 48, 2, "lighting specular", shininess_128),
    FC_CASE_RGBA("lighting/shininess_fraction", 48, 48, 2, "lighting specular", shininess_fraction),
    FC_CASE_RGBA("lighting/ambient_emission", 48, 48, 3, "lighting material", ambient_emission),
    FC_CASE_RGBA("lighting/colors_out_of_range", 48, 48, 2, "lighting material", colors_out_of_range),
    FC_CASE_RGBA("lighting/light_fixed_at_call", 48, 48, 2, "lighting modelview", light_fixed_at_call),
    FC_CASE_RGBA("lighting/light_headlight", 48, 48, 2, "lighting modelview", light_headlight),
    FC_CASE_RGBA("lighting/light_lookat_multmatrix", 64, 48, 3, "lighting modelview", light_lookat_multmatrix),
    FC_CASE_RGBA("lighting/spot_direction_modelview", 48, 48, 2, "lighting modelview spot", spot_direction_modelview),
    FC_CASE_RGBA("lighting/light_position_w", 48, 48, 3, "lighting modelview", light_position_w),
    { 0 }
};
