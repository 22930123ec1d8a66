/* c_light_space.c - object-space versus eye-space lighting.  Mesa 22.3
 * lights in object space (raw normals, light directions brought back
 * through the inverse modelview) when only directional non-spot lights are
 * on, the viewer is infinite, the colour control is GL_SINGLE_COLOR and the
 * modelview is known to be length-preserving (only glRotate / glTranslate
 * so far); otherwise in eye space.  The two paths round differently, so the
 * same scene is drawn on both sides of each switch: a wavy patch and a
 * sphere under rotations and translations, then the same with a scale of 1,
 * a uniform scale, a rotation given as a matrix (glLoadMatrixf /
 * glMultMatrixf), a general matrix, and each state that forces eye space
 * while contributing nothing visible (a black positional light, a spot
 * cutoff on a directional light, separate specular without specular). */
#include "lt_util.h"

static const float k_black[3] = { 0, 0, 0 };
static const float k_dim[3] = { 0.08f, 0.08f, 0.08f };
static const float k_warm[3] = { 0.8f, 0.7f, 0.55f };
static const float k_cool[3] = { 0.25f, 0.35f, 0.6f };
static const float k_white[3] = { 1, 1, 1 };
static const float k_grey[3] = { 0.5f, 0.5f, 0.5f };

/* Two directional lights given in eye space (identity modelview). */
static void space_setup(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.5f, 0.7f, 1, 0);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_grey, -1, -0.3f, 0.5f, 0);
}

static void space_wave(void)
{
    lt_wave(-1.3f, -1.3f, 1.3f, 1.3f, 16, 0.2f, 3.5f);
}

static void space_view(int f)
{
    glLoadIdentity();
    glTranslatef(0, 0, -4);
    if (f & 1)
        glRotatef(-60, 0.3f, 1, 0.2f);
    else
        glRotatef(25, 1, 1, 0);
}

/* Rotations and translations only: object space.  Wave then sphere. */
static void space_object_rotate(fc_h *h)
{
    space_setup(h);
    for (int f = 0; f < 3; f++) {
        lt_clear();
        space_view(f);
        if (f < 2)
            space_wave();
        else
            lt_sphere(1.1f, 24, 16);
        fc_capture(h);
    }
}

/* Frame 1 object space; frame 2 the same modelview times glScalef(1,1,1):
 * Mesa's matrix flags then say "uniform scale", not length-preserving, so
 * lighting moves to eye space although the matrix is unchanged. */
static void space_eye_unit_scale(fc_h *h)
{
    space_setup(h);
    for (int f = 0; f < 2; f++) {
        lt_clear();
        space_view(0);
        if (f)
            glScalef(1, 1, 1);
        space_wave();
        fc_capture(h);
    }
}

/* Uniform scale 0.8: eye space; without normal rescaling (frame 1) the
 * transformed normals are longer than 1; GL_RESCALE_NORMAL (frame 2). */
static void space_eye_uniform_scale(fc_h *h)
{
    space_setup(h);
    for (int f = 0; f < 2; f++) {
        lt_clear();
        space_view(1);
        glScalef(0.8f, 0.8f, 0.8f);
        if (f)
            glEnable(GL_RESCALE_NORMAL);
        space_wave();
        fc_capture(h);
    }
}

/* The rotation of frame 1 (glRotatef) read back and given again as a
 * matrix: frame 2 glLoadMatrixf of the whole modelview, frame 3
 * glTranslatef then glMultMatrixf of the rotation alone.  Mesa classifies
 * such matrices from their values. */
static void space_matrix_rotation(fc_h *h)
{
    GLfloat mv[16], rot[16];
    space_setup(h);
    glPushMatrix();
    glLoadIdentity();
    glRotatef(-60, 0.3f, 1, 0.2f);
    glGetFloatv(GL_MODELVIEW_MATRIX, rot);
    glPopMatrix();
    for (int f = 0; f < 3; f++) {
        lt_clear();
        space_view(1);
        if (f == 0)
            glGetFloatv(GL_MODELVIEW_MATRIX, mv);
        if (f == 1)
            glLoadMatrixf(mv);
        if (f == 2) {
            glLoadIdentity();
            glTranslatef(0, 0, -4);
            glMultMatrixf(rot);
        }
        space_wave();
        fc_capture(h);
    }
    fc_get_float(h, "GL_MODELVIEW_MATRIX", GL_MODELVIEW_MATRIX, 16);
}

/* A general (sheared) modelview from glMultMatrixf: eye space, normals
 * through the inverse transpose; frame 2 with GL_NORMALIZE. */
static void space_matrix_general(fc_h *h)
{
    static const GLfloat shear[16] = {
        1, 0.3f, 0, 0,
        0.4f, 1, 0.2f, 0,
        0, -0.25f, 1.1f, 0,
        0, 0, 0, 1,
    };
    space_setup(h);
    for (int f = 0; f < 2; f++) {
        lt_clear();
        space_view(0);
        glMultMatrixf(shear);
        if (f)
            glEnable(GL_NORMALIZE);
        space_wave();
        fc_capture(h);
    }
}

/* Frame 1 object space; frame 2 the same view plus a state that forces
 * eye space. */
static void space_forced(fc_h *h, int what)
{
    space_setup(h);
    if (what == 2)
        lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0, 0, 0, 1);
    for (int f = 0; f < 2; f++) {
        lt_clear();
        glLoadIdentity();
        if (f) {
            switch (what) {
            case 0:     /* a positional light with black colours */
                lt_lamp(GL_LIGHT2, k_black, k_black, k_black, 0.5f, 0.5f, 0, 1);
                break;
            case 1:     /* a spot cutoff on a directional light */
                glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 30);
                break;
            case 2:     /* separate specular, no specular material */
                glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
                break;
            default:    /* local viewer */
                glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
                break;
            }
        }
        space_view(0);
        space_wave();
        glTranslatef(0.3f, -0.2f, 0.8f);
        lt_sphere(0.4f, 16, 12);
        fc_capture(h);
    }
}

static void space_forced_positional(fc_h *h) { space_forced(h, 0); }
static void space_forced_spot(fc_h *h) { space_forced(h, 1); }
static void space_forced_separate_specular(fc_h *h) { space_forced(h, 2); }
static void space_forced_local_viewer(fc_h *h) { space_forced(h, 3); }

/* Large translations that cancel through a rotation (the modelview has
 * translation components near 1000 that nearly cancel): object space
 * (frame 1); frame 2 adds a uniform scale of 1.0001 (eye space, normals
 * slightly longer than 1). */
static void space_far_translation(fc_h *h)
{
    space_setup(h);
    for (int f = 0; f < 2; f++) {
        lt_clear();
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        glTranslatef(1000, 500, 0);
        glRotatef(90, 0, 0, 1);
        glTranslatef(-500, 1000, 0);
        glRotatef(-35, 1, 0, 0.5f);
        if (f)
            glScalef(1.0001f, 1.0001f, 1.0001f);
        lt_sphere(1.1f, 24, 16);
        fc_capture(h);
    }
    fc_get_float(h, "GL_MODELVIEW_MATRIX", GL_MODELVIEW_MATRIX, 16);
}

/* Mesa analyses a dirty modelview at glLight(GL_SPOT_DIRECTION), at
 * glPushMatrix and at a draw, not at glLight(GL_POSITION).  An analysis
 * replaces the geometry flags that glMultMatrixf left ("general") with what
 * the values show ("rotation"), and glLoadIdentity keeps them: after
 * glLoadIdentity, glTranslatef and a non-uniform glScalef the modelview is
 * then a "3D" matrix (adjugate inverse), else a "general" one (pivoting
 * inverse), and the eye-space normal's z differs by one ulp.  The diffuse
 * material puts each channel of the flat result right at a rounding tie, so
 * the whole quad shows which inverse was used.  Frames: analysed by the
 * spot direction of a light whose cutoff stays 180, by glPushMatrix, by a
 * draw; not analysed, with a light position set in between.  Then the
 * analysed case again, followed by a glMultMatrixf of the identity (skipped)
 * and of an identity with a -0.0 entry: Mesa compares with memcmp, so that
 * one is multiplied, makes the matrix "general" and dirty, and the next
 * analysis from scratch finds a translation and scale (reciprocal inverse). */
static void space_matrix_analysed(fc_h *h)
{
    static const GLfloat rot[16] = {
        -0x1.892bf4p-1f, 0x1.15721p-1f, 0x1.5dc3f4p-2f, 0,
        -0x1.f00c44p-2f, -0x1.ae2ac4p-1f, 0x1.f359b2p-3f, 0,
        0x1.ad286cp-2f, 0x1.64b812p-6f, 0x1.d0bb54p-1f, 0,
        0, 0, 0, 1,
    };
    static const GLfloat dir[3] = { -0.5f, 0.4f, -0.75f };
    static const GLfloat pos[4] = { 0.3f, 0.2f, 1, 0 };
    static const GLfloat ident[2][16] = {
        { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 },
        { 1, -0.0f, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 },
    };
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -10, 10);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    lt_model(GL_LIGHT_MODEL_AMBIENT, 0, 0, 0, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0x1.81500ep-3f, 0x1.851be2p-3f, 0x1.7d843cp-3f, 1);
    for (int f = 0; f < 6; f++) {
        fcu_clear(0, 0, 0, 1, 1);
        glLoadIdentity();
        glMultMatrixf(rot);
        if (f == 0 || f >= 4)
            glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, dir);
        if (f == 1) {
            glPushMatrix();
            glPopMatrix();
        }
        if (f == 2) {
            glBegin(GL_TRIANGLES);
            glVertex2f(5, 5);
            glVertex2f(6, 5);
            glVertex2f(5, 6);
            glEnd();
        }
        if (f == 3)
            glLightfv(GL_LIGHT1, GL_POSITION, pos);
        glLoadIdentity();
        glTranslatef(0.05f, -0.1f, -4);
        glScalef(0x1.ab07f8p-1f, 0x1.af766cp-1f, 0x1.e40376p-2f);
        if (f >= 4)
            glMultMatrixf(ident[f - 4]);
        glBegin(GL_QUADS);
        glNormal3f(0, 0, 1);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(1, 1);
        glVertex2f(-1, 1);
        glEnd();
        fc_capture(h);
    }
}

const fc_case fc_cases_light_space[] = {
    FC_CASE_RGBA("lighting/space_object_rotate", 48, 48, 3, "lighting space", space_object_rotate),
    FC_CASE_RGBA("lighting/space_eye_unit_scale", 48, 48, 2, "lighting space", space_eye_unit_scale),
    FC_CASE_RGBA("lighting/space_eye_uniform_scale", 48, 48, 2, "lighting space normals", space_eye_uniform_scale),
    FC_CASE_RGBA("lighting/space_matrix_rotation", 48, 48, 3, "lighting space", space_matrix_rotation),
    FC_CASE_RGBA("lighting/space_matrix_general", 48, 48, 2, "lighting space normals", space_matrix_general),
    FC_CASE_RGBA("lighting/space_forced_positional", 48, 48, 2, "lighting space", space_forced_positional),
    FC_CASE_RGBA("lighting/space_forced_spot", 48, 48, 2, "lighting space spot", space_forced_spot),
    FC_CASE_RGBA("lighting/space_forced_separate_specular", 48, 48, 2, "lighting space specular",
                 space_forced_separate_specular),
    FC_CASE_RGBA("lighting/space_forced_local_viewer", 48, 48, 2, "lighting space viewer", space_forced_local_viewer),
    FC_CASE_RGBA("lighting/space_matrix_analysed", 32, 32, 6, "lighting space normals",
                 space_matrix_analysed),
    FC_CASE_RGBA("lighting/space_far_translation", 48, 48, 2, "lighting space", space_far_translation),
    { 0 }
};
