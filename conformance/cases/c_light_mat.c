/* c_light_mat.c - two-sided lighting (back material, both glFrontFace
 * orientations, flat shading, culling), glColorMaterial for every face x
 * mode with the colour changed between vertices (and the enable, mode
 * switch and glMaterial-override rules), glMaterial inside glBegin/glEnd,
 * and the lit alpha (material diffuse alpha). */
#include "lt_util.h"

#include <math.h>
#include <stdio.h>

static const float k_black[3] = { 0, 0, 0 };
static const float k_dim[3] = { 0.08f, 0.08f, 0.08f };
static const float k_warm[3] = { 0.75f, 0.7f, 0.6f };
static const float k_cool[3] = { 0.3f, 0.4f, 0.7f };
static const float k_white[3] = { 1, 1, 1 };

/* Called before each ribbon vertex: index i along the ribbon, side s (0
 * upper edge, 1 lower edge), t = i / n. */
typedef void (*vertex_hook)(int i, int s, float t);

/* A ribbon along x twisting about the x axis from -twist to +twist, so
 * that its ends show their back sides; one GL_TRIANGLE_STRIP, normals
 * perpendicular to the ribbon, counter-clockwise where the normal faces
 * the viewer. */
static void ribbon(int n, float w, float twist, vertex_hook hook)
{
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i <= n; i++) {
        float t = (float)i / (float)n;
        float x = -1.5f + 3 * t;
        double a = twist * (2 * t - 1);
        float c = (float)cos(a), s = (float)sin(a);
        for (int k = 0; k < 2; k++) {
            float e = k ? -w : w;
            if (hook)
                hook(i, k, t);
            glNormal3f(0, -s, c);
            glVertex3f(x, e * c, e * s);
        }
    }
    glEnd();
}

/* Perspective, the ribbon tilted towards the viewer; a directional and a
 * positional light; distinct front and back materials. */
static void ribbon_setup(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_mat(GL_FRONT, GL_AMBIENT, 0.3f, 0.2f, 0.1f, 1);
    lt_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.55f, 0.2f, 1);
    lt_mat(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1);
    glMaterialf(GL_FRONT, GL_SHININESS, 20);
    lt_mat(GL_BACK, GL_AMBIENT, 0.1f, 0.15f, 0.3f, 1);
    lt_mat(GL_BACK, GL_DIFFUSE, 0.15f, 0.4f, 0.7f, 1);
    lt_mat(GL_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.2f, 1);
    lt_mat(GL_BACK, GL_EMISSION, 0.0f, 0.05f, 0.1f, 1);
    glMaterialf(GL_BACK, GL_SHININESS, 15);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.3f, 0.8f, 1, 0);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_white, -1, -0.5f, 1.5f, 1);
    glTranslatef(0, 0, -4);
    glRotatef(20, 1, 0, 0);
    glRotatef(-10, 0, 1, 0);
}

static void ribbon_draw(vertex_hook hook)
{
    ribbon(32, 0.7f, 2.6, hook);
}

/* Two-sided lighting on: frame 1 glFrontFace(GL_CCW), frame 2 GL_CW (the
 * same triangles change sides, and so material and normal sign). */
static void two_side_ribbon(fc_h *h)
{
    ribbon_setup(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    for (int f = 0; f < 2; f++) {
        glFrontFace(f ? GL_CW : GL_CCW);
        fc_get_integer(h, "GL_FRONT_FACE", GL_FRONT_FACE, 1);
        lt_clear();
        ribbon_draw(NULL);
        fc_capture(h);
    }
}

/* Two-sided lighting off: back faces get the front material lit with the
 * unflipped normal; both orientations. */
static void two_side_off(fc_h *h)
{
    ribbon_setup(h);
    for (int f = 0; f < 2; f++) {
        glFrontFace(f ? GL_CW : GL_CCW);
        lt_clear();
        ribbon_draw(NULL);
        fc_capture(h);
    }
}

/* Flat shading with two-sided lighting: each triangle's provoking vertex
 * colour, front or back by the triangle's own orientation. */
static void two_side_flat(fc_h *h)
{
    ribbon_setup(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glShadeModel(GL_FLAT);
    for (int f = 0; f < 2; f++) {
        glFrontFace(f ? GL_CW : GL_CCW);
        lt_clear();
        ribbon_draw(NULL);
        fc_capture(h);
    }
}

/* A bowl (the lower half of a sphere) seen from above: the inside shows
 * back faces.  Frame 1 one-sided, frame 2 two-sided. */
static void bowl(float r, int slices, int stacks)
{
    for (int i = 0; i < stacks; i++) {
        double lat0 = -LT_PI / 2 + LT_PI / 2 * i / stacks, lat1 = -LT_PI / 2 + LT_PI / 2 * (i + 1) / stacks;
        glBegin(GL_TRIANGLE_STRIP);
        for (int j = 0; j <= slices; j++) {
            double lon = 2 * LT_PI * j / slices;
            for (int k = 0; k < 2; k++) {
                double lat = k ? lat0 : lat1;
                float x = (float)(cos(lat) * sin(lon)), y = (float)sin(lat), z = (float)(cos(lat) * cos(lon));
                glNormal3f(x, y, z);
                glVertex3f(x * r, y * r, z * r);
            }
        }
        glEnd();
    }
}

static void bowl_setup(fc_h *h)
{
    ribbon_setup(h);
    glLoadIdentity();
    glTranslatef(0, 0.2f, -4);
    glRotatef(55, 1, 0, 0);
}

static void two_side_bowl(fc_h *h)
{
    bowl_setup(h);
    for (int f = 0; f < 2; f++) {
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, f);
        fc_get_boolean(h, "GL_LIGHT_MODEL_TWO_SIDE", GL_LIGHT_MODEL_TWO_SIDE, 1);
        lt_clear();
        bowl(1.3f, 24, 8);
        fc_capture(h);
    }
}

/* Two-sided lighting with a spot, local viewer and separate specular
 * (frame 1), then culling of front faces (frame 2); frame 3 culls back
 * faces of the ribbon instead. */
static void two_side_spot_cull(fc_h *h)
{
    bowl_setup(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glPushMatrix();
    glLoadIdentity();
    lt_light(GL_LIGHT1, GL_POSITION, 0.5f, 1.5f, -2.5f, 1);
    lt_light(GL_LIGHT1, GL_SPOT_DIRECTION, -0.5f, -1.5f, -1.5f, 0);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 40);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 5);
    glPopMatrix();
    for (int f = 0; f < 3; f++) {
        if (f) {
            glEnable(GL_CULL_FACE);
            glCullFace(f == 1 ? GL_FRONT : GL_BACK);
        }
        lt_clear();
        if (f < 2) {
            bowl(1.3f, 24, 8);
        } else {
            glLoadIdentity();
            glTranslatef(0, 0, -4);
            glRotatef(20, 1, 0, 0);
            ribbon_draw(NULL);
        }
        fc_capture(h);
    }
}

/* ---- glColorMaterial ---------------------------------------------------- */

static void hue_hook(int i, int s, float t)
{
    (void)i;
    lt_hue(t + (s ? 0.5f : 0.0f), 1);
}

static void rec_colormat_state(fc_h *h)
{
    static const struct { GLenum face; const char *name; } faces[2] = {
        { GL_FRONT, "GL_FRONT" }, { GL_BACK, "GL_BACK" },
    };
    static const struct { GLenum pname; const char *name; } pn[4] = {
        { GL_AMBIENT, "GL_AMBIENT" }, { GL_DIFFUSE, "GL_DIFFUSE" },
        { GL_SPECULAR, "GL_SPECULAR" }, { GL_EMISSION, "GL_EMISSION" },
    };
    char label[64];
    fc_get_integer(h, "GL_COLOR_MATERIAL_FACE", GL_COLOR_MATERIAL_FACE, 1);
    fc_get_integer(h, "GL_COLOR_MATERIAL_PARAMETER", GL_COLOR_MATERIAL_PARAMETER, 1);
    fc_is_enabled(h, "GL_COLOR_MATERIAL", GL_COLOR_MATERIAL);
    fc_get_float(h, "GL_CURRENT_COLOR", GL_CURRENT_COLOR, 4);
    for (int f = 0; f < 2; f++)
        for (int p = 0; p < 4; p++) {
            snprintf(label, sizeof label, "material %s %s", faces[f].name, pn[p].name);
            lt_rec_material(h, label, faces[f].face, pn[p].pname);
        }
}

/* Two-sided ribbon with a hue per vertex tracked as (face, mode). */
static void colormat_case(fc_h *h, GLenum face, GLenum mode)
{
    ribbon_setup(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glColorMaterial(face, mode);
    glEnable(GL_COLOR_MATERIAL);
    ribbon_draw(hue_hook);
    fc_capture(h);
    rec_colormat_state(h);
}

#define COLORMAT(fname, face, mode) \
    static void fname(fc_h *h) { colormat_case(h, face, mode); }
COLORMAT(cm_front_ambient, GL_FRONT, GL_AMBIENT)
COLORMAT(cm_front_diffuse, GL_FRONT, GL_DIFFUSE)
COLORMAT(cm_front_specular, GL_FRONT, GL_SPECULAR)
COLORMAT(cm_front_emission, GL_FRONT, GL_EMISSION)
COLORMAT(cm_front_amb_diff, GL_FRONT, GL_AMBIENT_AND_DIFFUSE)
COLORMAT(cm_back_ambient, GL_BACK, GL_AMBIENT)
COLORMAT(cm_back_diffuse, GL_BACK, GL_DIFFUSE)
COLORMAT(cm_back_specular, GL_BACK, GL_SPECULAR)
COLORMAT(cm_back_emission, GL_BACK, GL_EMISSION)
COLORMAT(cm_back_amb_diff, GL_BACK, GL_AMBIENT_AND_DIFFUSE)
COLORMAT(cm_both_ambient, GL_FRONT_AND_BACK, GL_AMBIENT)
COLORMAT(cm_both_diffuse, GL_FRONT_AND_BACK, GL_DIFFUSE)
COLORMAT(cm_both_specular, GL_FRONT_AND_BACK, GL_SPECULAR)
COLORMAT(cm_both_emission, GL_FRONT_AND_BACK, GL_EMISSION)
COLORMAT(cm_both_amb_diff, GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE)

/* Enabling GL_COLOR_MATERIAL copies the current colour into the tracked
 * material, and after glDisable the material keeps it while the current
 * colour changes.  Frame 1: the front/back materials were just set with
 * glMaterialfv (ribbon_setup) and nothing was drawn since; the oracle
 * then keeps the glMaterialfv diffuse (its pending material update lands
 * after the enable's copy of the colour), also for drawing.  Frame 2:
 * disabled, another current colour.  Frame 3: enabled again with a new
 * colour (no pending glMaterial now), then disabled. */
static void colormat_enable_disable(fc_h *h)
{
    ribbon_setup(h);
    glColor4f(0.9f, 0.2f, 0.3f, 1);
    glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    rec_colormat_state(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    ribbon_draw(NULL);
    fc_capture(h);
    glDisable(GL_COLOR_MATERIAL);
    glColor4f(0.1f, 0.9f, 0.2f, 1);
    rec_colormat_state(h);
    lt_clear();
    ribbon_draw(NULL);
    fc_capture(h);
    glColor4f(0.2f, 0.3f, 0.9f, 1);
    glEnable(GL_COLOR_MATERIAL);
    glDisable(GL_COLOR_MATERIAL);
    glColor4f(0.9f, 0.9f, 0.1f, 1);
    rec_colormat_state(h);
    lt_clear();
    ribbon_draw(NULL);
    fc_capture(h);
}

/* glColorMaterial while enabled: the newly tracked property takes the
 * current colour, the previously tracked one keeps its last value
 * (frame 2); glMaterial of a tracked property while enabled (frame 3). */
static void colormat_switch_mode(fc_h *h)
{
    ribbon_setup(h);
    glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    ribbon_draw(hue_hook);
    fc_capture(h);
    glColor3f(0.2f, 0.9f, 0.9f);
    glColorMaterial(GL_FRONT_AND_BACK, GL_SPECULAR);
    rec_colormat_state(h);
    lt_clear();
    ribbon_draw(NULL);
    fc_capture(h);
    lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.1f, 0.1f, 0.1f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.1f, 0.8f, 0.1f, 1);
    rec_colormat_state(h);
    lt_clear();
    ribbon_draw(NULL);
    fc_capture(h);
}

/* Flat shading with colour material (the provoking vertex's colour is
 * the material of its lit colour), smooth for comparison. */
static void colormat_flat(fc_h *h)
{
    ribbon_setup(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    for (int f = 0; f < 2; f++) {
        glShadeModel(f ? GL_FLAT : GL_SMOOTH);
        lt_clear();
        ribbon_draw(hue_hook);
        fc_capture(h);
    }
}

/* ---- glMaterial inside glBegin/glEnd, alpha ----------------------------- */

static void material_hook(int i, int s, float t)
{
    float r = 0.5f + 0.5f * (float)sin(7 * t), g = 0.5f + 0.5f * (float)cos(5 * t);
    if (s == 0) {
        lt_mat(GL_FRONT, GL_DIFFUSE, r, g, 0.3f, 1);
        glMaterialf(GL_FRONT, GL_SHININESS, (float)(4 + 10 * (i % 5)));
    } else {
        lt_mat(GL_FRONT, GL_EMISSION, 0, 0, 0.4f * t, 1);
    }
    if (i % 3 == 0)
        lt_mat(GL_BACK, GL_DIFFUSE, g, 0.2f, r, 1);
    if (i % 4 == 1)
        lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, t, 1 - t, 0.5f, 1);
}

/* glMaterial between vertices of a strip (front diffuse, shininess and
 * emission, back diffuse, both specular); smooth then flat; the last
 * values remain the current material after glEnd. */
static void material_in_begin_end(fc_h *h)
{
    ribbon_setup(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    for (int f = 0; f < 2; f++) {
        glShadeModel(f ? GL_FLAT : GL_SMOOTH);
        lt_clear();
        ribbon_draw(material_hook);
        fc_capture(h);
    }
    lt_rec_material(h, "GL_FRONT GL_DIFFUSE", GL_FRONT, GL_DIFFUSE);
    lt_rec_material(h, "GL_FRONT GL_SHININESS", GL_FRONT, GL_SHININESS);
    lt_rec_material(h, "GL_FRONT GL_EMISSION", GL_FRONT, GL_EMISSION);
    lt_rec_material(h, "GL_BACK GL_DIFFUSE", GL_BACK, GL_DIFFUSE);
    lt_rec_material(h, "GL_BACK GL_SPECULAR", GL_BACK, GL_SPECULAR);
}

/* glMaterial once inside glBegin before the first vertex, and between the
 * triangles of one GL_TRIANGLES block (spheres of separate triangles). */
static void material_per_triangle(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.3f, 0.8f, 1, 0);
    glTranslatef(0, 0, -4);
    glBegin(GL_TRIANGLES);
    lt_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.8f, 0.3f, 1);
    for (int j = 0; j < 6; j++)
        for (int i = 0; i < 8; i++) {
            float x0 = -1.6f + 0.4f * (float)i, y0 = -1.2f + 0.4f * (float)j;
            if ((i + j) % 3 == 0)
                lt_mat(GL_FRONT, GL_DIFFUSE, 0.1f * (float)i, 0.3f, 0.15f * (float)j, 1);
            glNormal3f(-0.3f, -0.3f, 0.9f);
            glVertex3f(x0, y0, 0);
            glNormal3f(0.4f, -0.2f, 0.9f);
            glVertex3f(x0 + 0.38f, y0, 0);
            glNormal3f(0, 0.5f, 0.85f);
            glVertex3f(x0 + 0.19f, y0 + 0.38f, 0);
        }
    glEnd();
    fc_capture(h);
    lt_rec_material(h, "GL_FRONT GL_DIFFUSE", GL_FRONT, GL_DIFFUSE);
}

static void alpha_hook(int i, int s, float t)
{
    (void)i;
    lt_hue(t + (s ? 0.5f : 0.0f), 0.15f + 0.7f * t);
}

/* The lit alpha is the material's diffuse alpha (ambient, specular and
 * emission alphas ignored): frame 1 diffuse alpha 0.25, frame 2 0.6 with
 * other alphas set, frame 3 colour material AMBIENT_AND_DIFFUSE with a
 * per-vertex alpha, frame 4 the same with GL_SPECULAR tracked (alpha from
 * the material again). */
static void material_alpha(fc_h *h)
{
    ribbon_setup(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    for (int f = 0; f < 4; f++) {
        lt_clear();
        if (f == 0) {
            lt_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.55f, 0.2f, 0.25f);
        } else if (f == 1) {
            lt_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.55f, 0.2f, 0.6f);
            lt_mat(GL_FRONT, GL_AMBIENT, 0.3f, 0.2f, 0.1f, 0.1f);
            lt_mat(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 0.9f);
            lt_mat(GL_BACK, GL_DIFFUSE, 0.2f, 0.5f, 0.9f, 0.75f);
        } else if (f == 2) {
            glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
            glEnable(GL_COLOR_MATERIAL);
        } else {
            glColorMaterial(GL_FRONT_AND_BACK, GL_SPECULAR);
        }
        if (f < 2)
            ribbon_draw(NULL);
        else
            ribbon(32, 0.7f, 2.6, alpha_hook);
        fc_capture(h);
    }
}

const fc_case fc_cases_light_mat[] = {
    FC_CASE_RGBA("lighting/two_side_ribbon", 64, 48, 2, "lighting two_side", two_side_ribbon),
    FC_CASE_RGBA("lighting/two_side_off", 64, 48, 2, "lighting two_side", two_side_off),
    FC_CASE_RGBA("lighting/two_side_flat", 64, 48, 2, "lighting two_side shade", two_side_flat),
    FC_CASE_RGBA("lighting/two_side_bowl", 48, 48, 2, "lighting two_side", two_side_bowl),
    FC_CASE_RGBA("lighting/two_side_spot_cull", 48, 48, 3, "lighting two_side spot viewer specular",
                 two_side_spot_cull),
    FC_CASE_RGBA("lighting/colormat_front_ambient", 64, 48, 1, "lighting color_material", cm_front_ambient),
    FC_CASE_RGBA("lighting/colormat_front_diffuse", 64, 48, 1, "lighting color_material", cm_front_diffuse),
    FC_CASE_RGBA("lighting/colormat_front_specular", 64, 48, 1, "lighting color_material", cm_front_specular),
    FC_CASE_RGBA("lighting/colormat_front_emission", 64, 48, 1, "lighting color_material", cm_front_emission),
    FC_CASE_RGBA("lighting/colormat_front_ambient_and_diffuse", 64, 48, 1, "lighting color_material",
                 cm_front_amb_diff),
    FC_CASE_RGBA("lighting/colormat_back_ambient", 64, 48, 1, "lighting color_material", cm_back_ambient),
    FC_CASE_RGBA("lighting/colormat_back_diffuse", 64, 48, 1, "lighting color_material", cm_back_diffuse),
    FC_CASE_RGBA("lighting/colormat_back_specular", 64, 48, 1, "lighting color_material", cm_back_specular),
    FC_CASE_RGBA("lighting/colormat_back_emission", 64, 48, 1, "lighting color_material", cm_back_emission),
    FC_CASE_RGBA("lighting/colormat_back_ambient_and_diffuse", 64, 48, 1, "lighting color_material",
                 cm_back_amb_diff),
    FC_CASE_RGBA("lighting/colormat_both_ambient", 64, 48, 1, "lighting color_material", cm_both_ambient),
    FC_CASE_RGBA("lighting/colormat_both_diffuse", 64, 48, 1, "lighting color_material", cm_both_diffuse),
    FC_CASE_RGBA("lighting/colormat_both_specular", 64, 48, 1, "lighting color_material", cm_both_specular),
    FC_CASE_RGBA("lighting/colormat_both_emission", 64, 48, 1, "lighting color_material", cm_both_emission),
    FC_CASE_RGBA("lighting/colormat_both_ambient_and_diffuse", 64, 48, 1, "lighting color_material",
                 cm_both_amb_diff),
    FC_CASE_RGBA("lighting/colormat_enable_disable", 64, 48, 3, "lighting color_material", colormat_enable_disable),
    FC_CASE_RGBA("lighting/colormat_switch_mode", 64, 48, 3, "lighting color_material material",
                 colormat_switch_mode),
    FC_CASE_RGBA("lighting/colormat_flat", 64, 48, 2, "lighting color_material shade", colormat_flat),
    FC_CASE_RGBA("lighting/material_in_begin_end", 64, 48, 2, "lighting material shade", material_in_begin_end),
    FC_CASE_RGBA("lighting/material_per_triangle", 48, 48, 1, "lighting material", material_per_triangle),
    FC_CASE_RGBA("lighting/material_alpha", 64, 48, 4, "lighting material color_material", material_alpha),
    { 0 }
};
