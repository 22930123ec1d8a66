/* c_light_api.c - lighting state through the API: defaults and set/get
 * round trips of glLight{f,i}[v], glLightModel{f,i}[v], glMaterial{f,i}[v]
 * (read back with glGetLight{f,i}v / glGetMaterial{f,i}v and glGet*),
 * glColorMaterial, the enables (GL_LIGHTING, GL_LIGHTi, GL_COLOR_MATERIAL,
 * GL_NORMALIZE, GL_RESCALE_NORMAL) and GL_CURRENT_NORMAL after every
 * glNormal3 variant; then every bad enum and value, each followed by its
 * error and the state it must not have changed, and the commands that are
 * not allowed between glBegin/glEnd. */
#include "lt_util.h"

#include <limits.h>
#include <stdio.h>

#define GL_LIGHT8_BAD (GL_LIGHT0 + 8)

struct pname { GLenum pname; int count; const char *name; };

static const struct pname light_pn[] = {
    { GL_AMBIENT, 4, "GL_AMBIENT" },
    { GL_DIFFUSE, 4, "GL_DIFFUSE" },
    { GL_SPECULAR, 4, "GL_SPECULAR" },
    { GL_POSITION, 4, "GL_POSITION" },
    { GL_SPOT_DIRECTION, 3, "GL_SPOT_DIRECTION" },
    { GL_SPOT_EXPONENT, 1, "GL_SPOT_EXPONENT" },
    { GL_SPOT_CUTOFF, 1, "GL_SPOT_CUTOFF" },
    { GL_CONSTANT_ATTENUATION, 1, "GL_CONSTANT_ATTENUATION" },
    { GL_LINEAR_ATTENUATION, 1, "GL_LINEAR_ATTENUATION" },
    { GL_QUADRATIC_ATTENUATION, 1, "GL_QUADRATIC_ATTENUATION" },
};
#define N_LIGHT_PN (sizeof light_pn / sizeof light_pn[0])

static const struct pname mat_pn[] = {
    { GL_AMBIENT, 4, "GL_AMBIENT" },
    { GL_DIFFUSE, 4, "GL_DIFFUSE" },
    { GL_SPECULAR, 4, "GL_SPECULAR" },
    { GL_EMISSION, 4, "GL_EMISSION" },
    { GL_SHININESS, 1, "GL_SHININESS" },
    { GL_COLOR_INDEXES, 3, "GL_COLOR_INDEXES" },
};
#define N_MAT_PN (sizeof mat_pn / sizeof mat_pn[0])

static const struct pname state_pn[] = {
    { GL_LIGHT_MODEL_AMBIENT, 4, "GL_LIGHT_MODEL_AMBIENT" },
    { GL_LIGHT_MODEL_LOCAL_VIEWER, 1, "GL_LIGHT_MODEL_LOCAL_VIEWER" },
    { GL_LIGHT_MODEL_TWO_SIDE, 1, "GL_LIGHT_MODEL_TWO_SIDE" },
    { GL_LIGHT_MODEL_COLOR_CONTROL, 1, "GL_LIGHT_MODEL_COLOR_CONTROL" },
    { GL_MAX_LIGHTS, 1, "GL_MAX_LIGHTS" },
    { GL_SHADE_MODEL, 1, "GL_SHADE_MODEL" },
    { GL_COLOR_MATERIAL_FACE, 1, "GL_COLOR_MATERIAL_FACE" },
    { GL_COLOR_MATERIAL_PARAMETER, 1, "GL_COLOR_MATERIAL_PARAMETER" },
    { GL_CURRENT_NORMAL, 3, "GL_CURRENT_NORMAL" },
    { GL_LIGHTING, 1, "GL_LIGHTING" },
    { GL_COLOR_MATERIAL, 1, "GL_COLOR_MATERIAL" },
    { GL_NORMALIZE, 1, "GL_NORMALIZE" },
    { GL_RESCALE_NORMAL, 1, "GL_RESCALE_NORMAL" },
    { GL_LIGHT0, 1, "GL_LIGHT0" },
    { GL_LIGHT1, 1, "GL_LIGHT1" },
    { GL_LIGHT2, 1, "GL_LIGHT2" },
    { GL_LIGHT3, 1, "GL_LIGHT3" },
    { GL_LIGHT4, 1, "GL_LIGHT4" },
    { GL_LIGHT5, 1, "GL_LIGHT5" },
    { GL_LIGHT6, 1, "GL_LIGHT6" },
    { GL_LIGHT7, 1, "GL_LIGHT7" },
};
#define N_STATE_PN (sizeof state_pn / sizeof state_pn[0])

static const struct pname caps[] = {
    { GL_LIGHTING, 1, "GL_LIGHTING" },
    { GL_COLOR_MATERIAL, 1, "GL_COLOR_MATERIAL" },
    { GL_NORMALIZE, 1, "GL_NORMALIZE" },
    { GL_RESCALE_NORMAL, 1, "GL_RESCALE_NORMAL" },
    { GL_LIGHT0, 1, "GL_LIGHT0" },
    { GL_LIGHT1, 1, "GL_LIGHT1" },
    { GL_LIGHT2, 1, "GL_LIGHT2" },
    { GL_LIGHT3, 1, "GL_LIGHT3" },
    { GL_LIGHT4, 1, "GL_LIGHT4" },
    { GL_LIGHT5, 1, "GL_LIGHT5" },
    { GL_LIGHT6, 1, "GL_LIGHT6" },
    { GL_LIGHT7, 1, "GL_LIGHT7" },
};
#define N_CAPS (sizeof caps / sizeof caps[0])

/* Every pname of one light (fv and iv blobs) and the error afterwards. */
static void rec_light_all(fc_h *h, GLenum light, const char *what)
{
    char label[96];
    for (size_t i = 0; i < N_LIGHT_PN; i++) {
        snprintf(label, sizeof label, "%s LIGHT%d %s", what, (int)(light - GL_LIGHT0), light_pn[i].name);
        lt_rec_light(h, label, light, light_pn[i].pname);
    }
    fc_error(h, what);
}

static void rec_material_all(fc_h *h, GLenum face, const char *what)
{
    char label[96];
    for (size_t i = 0; i < N_MAT_PN; i++) {
        snprintf(label, sizeof label, "%s %s %s", what, face == GL_FRONT ? "GL_FRONT" : "GL_BACK",
                 mat_pn[i].name);
        lt_rec_material(h, label, face, mat_pn[i].pname);
    }
    fc_error(h, what);
}

/* One state value with all four glGet types. */
static void rec_get(fc_h *h, const struct pname *p)
{
    fc_get_integer(h, p->name, p->pname, p->count);
    fc_get_float(h, p->name, p->pname, p->count);
    fc_get_double(h, p->name, p->pname, p->count);
    fc_get_boolean(h, p->name, p->pname, p->count);
}

static void rec_state_all(fc_h *h, const char *what)
{
    for (size_t i = 0; i < N_STATE_PN; i++)
        rec_get(h, &state_pn[i]);
    for (size_t i = 0; i < N_CAPS; i++)
        fc_is_enabled(h, caps[i].name, caps[i].pname);
    fc_error(h, what);
}

static void rec_model(fc_h *h)
{
    for (int i = 0; i < 4; i++)
        rec_get(h, &state_pn[i]);
}

/* ---- defaults and round trips ------------------------------------------- */

static void light_defaults(fc_h *h)
{
    for (int i = 0; i < 8; i++)
        rec_light_all(h, GL_LIGHT0 + (GLenum)i, "default");
}

static void material_defaults(fc_h *h)
{
    rec_material_all(h, GL_FRONT, "default");
    rec_material_all(h, GL_BACK, "default");
}

static void state_defaults(fc_h *h)
{
    rec_state_all(h, "default");
}

/* glEnable / glDisable of every lighting capability, one at a time and
 * all together. */
static void enable_disable(fc_h *h)
{
    char label[64];
    for (size_t i = 0; i < N_CAPS; i++) {
        glEnable(caps[i].pname);
        snprintf(label, sizeof label, "glEnable(%s)", caps[i].name);
        fc_error(h, label);
        fc_is_enabled(h, caps[i].name, caps[i].pname);
        fc_get_boolean(h, caps[i].name, caps[i].pname, 1);
        fc_get_integer(h, caps[i].name, caps[i].pname, 1);
    }
    rec_state_all(h, "all enabled");
    for (size_t i = 0; i < N_CAPS; i += 2)
        glDisable(caps[i].pname);
    rec_state_all(h, "every other disabled");
    for (size_t i = 0; i < N_CAPS; i++)
        glDisable(caps[i].pname);
    rec_state_all(h, "all disabled");
}

/* glLightfv of every pname on GL_LIGHT3 under a modelview with rotation,
 * translation and non-uniform scale (position and spot direction are
 * stored in eye coordinates), colours outside [0,1] (read back as
 * integers with the signed normalised mapping). */
static void light_fv_roundtrip(fc_h *h)
{
    static const GLfloat amb[4] = { -0.5f, 0.25f, 1.5f, 0.125f };
    static const GLfloat diff[4] = { 0.3f, 0.6f, 0.9f, 1 };
    static const GLfloat spec[4] = { 1, 0.999f, 0.001f, -1 };
    static const GLfloat pos[4] = { 1, 2, 3, 1 };
    static const GLfloat pos2[4] = { -2, 0.5f, 4, 2 };
    static const GLfloat pos0[4] = { 0.3f, -0.4f, 0.5f, 0 };
    static const GLfloat dir[4] = { 0.2f, -0.5f, -1, 99 };
    static const GLfloat expo = 12.75f, cut = 33.3f, k0 = 0.5f, k1 = 0.25f, k2 = 0.125f;
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(1, -2, -3);
    glRotatef(30, 0.2f, 1, 0.4f);
    glScalef(2, 0.5f, 3);
    glLightfv(GL_LIGHT3, GL_AMBIENT, amb);
    glLightfv(GL_LIGHT3, GL_DIFFUSE, diff);
    glLightfv(GL_LIGHT3, GL_SPECULAR, spec);
    glLightfv(GL_LIGHT3, GL_POSITION, pos);
    glLightfv(GL_LIGHT3, GL_SPOT_DIRECTION, dir);
    glLightfv(GL_LIGHT3, GL_SPOT_EXPONENT, &expo);
    glLightfv(GL_LIGHT3, GL_SPOT_CUTOFF, &cut);
    glLightfv(GL_LIGHT3, GL_CONSTANT_ATTENUATION, &k0);
    glLightfv(GL_LIGHT3, GL_LINEAR_ATTENUATION, &k1);
    glLightfv(GL_LIGHT3, GL_QUADRATIC_ATTENUATION, &k2);
    rec_light_all(h, GL_LIGHT3, "set fv");
    /* Changing the modelview afterwards changes nothing stored. */
    glLoadIdentity();
    glRotatef(90, 1, 0, 0);
    lt_rec_light(h, "after modelview change GL_POSITION", GL_LIGHT3, GL_POSITION);
    lt_rec_light(h, "after modelview change GL_SPOT_DIRECTION", GL_LIGHT3, GL_SPOT_DIRECTION);
    /* w = 2 and w = 0 positions under the rotation. */
    glLightfv(GL_LIGHT3, GL_POSITION, pos2);
    lt_rec_light(h, "w=2 GL_POSITION", GL_LIGHT3, GL_POSITION);
    glLightfv(GL_LIGHT3, GL_POSITION, pos0);
    lt_rec_light(h, "w=0 GL_POSITION", GL_LIGHT3, GL_POSITION);
    /* The projection matrix plays no part. */
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 10);
    glLightfv(GL_LIGHT3, GL_POSITION, pos);
    lt_rec_light(h, "under projection GL_POSITION", GL_LIGHT3, GL_POSITION);
    glMatrixMode(GL_MODELVIEW);
    /* Untouched neighbours. */
    rec_light_all(h, GL_LIGHT2, "neighbour");
    rec_light_all(h, GL_LIGHT4, "neighbour");
}

/* glLightiv: integer colours use the signed normalised mapping, positions,
 * directions and scalars are converted directly. */
static void light_iv_roundtrip(fc_h *h)
{
    static const GLint amb[4] = { INT_MAX, INT_MAX / 2, 0, -INT_MAX / 4 };
    static const GLint diff[4] = { 1, -1, INT_MIN, 1000 };
    static const GLint spec[4] = { INT_MAX, INT_MAX, INT_MAX, INT_MAX };
    static const GLint pos[4] = { 3, -2, 5, 1 };
    static const GLint dir[3] = { 0, -1, -1 };
    static const GLint expo = 7, cut = 45, k0 = 2, k1 = 1, k2 = 3;
    glLightiv(GL_LIGHT5, GL_AMBIENT, amb);
    glLightiv(GL_LIGHT5, GL_DIFFUSE, diff);
    glLightiv(GL_LIGHT5, GL_SPECULAR, spec);
    glLightiv(GL_LIGHT5, GL_POSITION, pos);
    glLightiv(GL_LIGHT5, GL_SPOT_DIRECTION, dir);
    glLightiv(GL_LIGHT5, GL_SPOT_EXPONENT, &expo);
    glLightiv(GL_LIGHT5, GL_SPOT_CUTOFF, &cut);
    glLightiv(GL_LIGHT5, GL_CONSTANT_ATTENUATION, &k0);
    glLightiv(GL_LIGHT5, GL_LINEAR_ATTENUATION, &k1);
    glLightiv(GL_LIGHT5, GL_QUADRATIC_ATTENUATION, &k2);
    rec_light_all(h, GL_LIGHT5, "set iv");
}

/* glLightf / glLighti of every scalar pname, then of vector pnames (not
 * scalar parameters: an error in the GL spec). */
static void light_scalar(fc_h *h)
{
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 100.5f);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 89.9f);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 1e-20f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 1e20f);
    rec_light_all(h, GL_LIGHT1, "glLightf");
    glLighti(GL_LIGHT1, GL_SPOT_EXPONENT, 128);
    glLighti(GL_LIGHT1, GL_SPOT_CUTOFF, 180);
    glLighti(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 3);
    glLighti(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0);
    glLighti(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 7);
    rec_light_all(h, GL_LIGHT1, "glLighti");
    glLightf(GL_LIGHT1, GL_POSITION, 2); fc_error(h, "glLightf(GL_POSITION)");
    glLightf(GL_LIGHT1, GL_AMBIENT, 0.5f); fc_error(h, "glLightf(GL_AMBIENT)");
    glLighti(GL_LIGHT1, GL_SPOT_DIRECTION, 1); fc_error(h, "glLighti(GL_SPOT_DIRECTION)");
    glLighti(GL_LIGHT1, GL_DIFFUSE, 1); fc_error(h, "glLighti(GL_DIFFUSE)");
    rec_light_all(h, GL_LIGHT1, "after vector pnames");
}

/* The spot direction is stored as the upper 3x3 of the modelview times
 * the given vector (scaled, then rotated); the boundary values of cutoff
 * (0, 90, 180) and exponent (0, 128) are accepted. */
static void light_spot_state(fc_h *h)
{
    static const GLfloat d[4] = { 3, 4, 0, 0 };
    glScalef(2, 2, 2);
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, d);
    lt_rec_light(h, "scaled spot direction", GL_LIGHT0, GL_SPOT_DIRECTION);
    glLoadIdentity();
    glRotatef(45, 0, 0, 1);
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, d);
    lt_rec_light(h, "rotated spot direction", GL_LIGHT0, GL_SPOT_DIRECTION);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 0); fc_error(h, "cutoff 0");
    lt_rec_light(h, "cutoff 0", GL_LIGHT0, GL_SPOT_CUTOFF);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 90); fc_error(h, "cutoff 90");
    lt_rec_light(h, "cutoff 90", GL_LIGHT0, GL_SPOT_CUTOFF);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180); fc_error(h, "cutoff 180");
    lt_rec_light(h, "cutoff 180", GL_LIGHT0, GL_SPOT_CUTOFF);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0); fc_error(h, "exponent 0");
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 128); fc_error(h, "exponent 128");
    lt_rec_light(h, "exponent 128", GL_LIGHT0, GL_SPOT_EXPONENT);
}

/* glLightModel{f,i}[v] of every pname; read back with every glGet type. */
static void light_model_roundtrip(fc_h *h)
{
    static const GLfloat ambf[4] = { 0.1f, -0.2f, 1.7f, 0.5f };
    static const GLint ambi[4] = { INT_MAX, INT_MIN, INT_MAX / 3, 0 };
    static const GLfloat half = 0.5f, minus = -1;
    static const GLint two = 2, sep = GL_SEPARATE_SPECULAR_COLOR;
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambf); fc_error(h, "ambient fv");
    rec_model(h);
    glLightModeliv(GL_LIGHT_MODEL_AMBIENT, ambi); fc_error(h, "ambient iv");
    rec_model(h);
    glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, 0.5f); fc_error(h, "local viewer f 0.5");
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 2); fc_error(h, "two side i 2");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR); fc_error(h, "color control i");
    rec_model(h);
    glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, 0); fc_error(h, "local viewer f 0");
    glLightModelfv(GL_LIGHT_MODEL_TWO_SIDE, &minus); fc_error(h, "two side fv -1");
    glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, (GLfloat)GL_SINGLE_COLOR); fc_error(h, "color control f");
    rec_model(h);
    glLightModelfv(GL_LIGHT_MODEL_LOCAL_VIEWER, &half); fc_error(h, "local viewer fv 0.5");
    glLightModeliv(GL_LIGHT_MODEL_TWO_SIDE, &two); fc_error(h, "two side iv 2");
    glLightModeliv(GL_LIGHT_MODEL_COLOR_CONTROL, &sep); fc_error(h, "color control iv");
    rec_model(h);
    glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.75f); fc_error(h, "glLightModelf(GL_LIGHT_MODEL_AMBIENT)");
    rec_model(h);
    glLightModeli(GL_LIGHT_MODEL_AMBIENT, 1); fc_error(h, "glLightModeli(GL_LIGHT_MODEL_AMBIENT)");
    rec_model(h);
}

/* glMaterial{f,i}v of every pname for GL_FRONT, GL_BACK and
 * GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, colour indexes. */
static void material_roundtrip(fc_h *h)
{
    static const GLfloat a[4] = { 0.1f, 0.2f, 0.3f, 0.4f };
    static const GLfloat d[4] = { -0.5f, 1.5f, 0.75f, 0.25f };
    static const GLfloat s[4] = { 0.9f, 0.8f, 0.7f, 0.6f };
    static const GLfloat e[4] = { 0.05f, 0, 1, 1 };
    static const GLfloat shin = 12.5f;
    static const GLfloat idx[3] = { 1.5f, 7, 300 };
    static const GLint ai[4] = { INT_MAX, 0, INT_MIN, INT_MAX / 2 };
    static const GLint shini = 77;
    static const GLint idxi[3] = { 2, 5, 9 };
    glMaterialfv(GL_FRONT, GL_AMBIENT, a);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, d);
    glMaterialfv(GL_FRONT, GL_SPECULAR, s);
    glMaterialfv(GL_FRONT, GL_EMISSION, e);
    glMaterialfv(GL_FRONT, GL_SHININESS, &shin);
    glMaterialfv(GL_FRONT, GL_COLOR_INDEXES, idx);
    rec_material_all(h, GL_FRONT, "front fv");
    rec_material_all(h, GL_BACK, "front fv");
    glMaterialiv(GL_BACK, GL_AMBIENT, ai);
    glMaterialiv(GL_BACK, GL_SHININESS, &shini);
    glMaterialiv(GL_BACK, GL_COLOR_INDEXES, idxi);
    rec_material_all(h, GL_FRONT, "back iv");
    rec_material_all(h, GL_BACK, "back iv");
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, s);
    rec_material_all(h, GL_FRONT, "both ambient_and_diffuse");
    rec_material_all(h, GL_BACK, "both ambient_and_diffuse");
    glMaterialiv(GL_FRONT_AND_BACK, GL_EMISSION, ai);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0.5f);
    rec_material_all(h, GL_FRONT, "both emission iv, shininess f");
    rec_material_all(h, GL_BACK, "both emission iv, shininess f");
    glMateriali(GL_BACK, GL_SHININESS, 128);
    lt_rec_material(h, "glMateriali 128", GL_BACK, GL_SHININESS);
    glMaterialf(GL_FRONT, GL_SHININESS, 0);
    lt_rec_material(h, "glMaterialf 0", GL_FRONT, GL_SHININESS);
    /* Not tested: glMaterialf / glMateriali with a vector pname (an
     * INVALID_ENUM in the GL spec).  The oracle raises no error and reads
     * four values from its one-element parameter copy, so the material gets
     * uninitialised stack bytes (values differ from run to run). */
}

/* glColorMaterial of every face x mode, enabled and disabled. */
static void color_material_state(fc_h *h)
{
    static const GLenum faces[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
    static const GLenum modes[5] = { GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE };
    for (int e = 0; e < 2; e++) {
        if (e)
            glEnable(GL_COLOR_MATERIAL);
        for (int f = 0; f < 3; f++)
            for (int m = 0; m < 5; m++) {
                glColorMaterial(faces[f], modes[m]);
                fc_error(h, "glColorMaterial");
                fc_get_integer(h, "GL_COLOR_MATERIAL_FACE", GL_COLOR_MATERIAL_FACE, 1);
                fc_get_integer(h, "GL_COLOR_MATERIAL_PARAMETER", GL_COLOR_MATERIAL_PARAMETER, 1);
            }
    }
    fc_is_enabled(h, "GL_COLOR_MATERIAL", GL_COLOR_MATERIAL);
}

/* GL_CURRENT_NORMAL after every glNormal3 variant, including extreme
 * integers (signed normalised conversion), unnormalised and huge values,
 * and a normal given inside glBegin/glEnd. */
static void rec_normal(fc_h *h, const char *what)
{
    fc_error(h, what);
    fc_get_float(h, what, GL_CURRENT_NORMAL, 3);
    fc_get_double(h, what, GL_CURRENT_NORMAL, 3);
    fc_get_integer(h, what, GL_CURRENT_NORMAL, 3);
    fc_get_boolean(h, what, GL_CURRENT_NORMAL, 3);
}

static void current_normal(fc_h *h)
{
    static const GLbyte bv[3] = { -128, 127, 0 };
    static const GLbyte bv2[3] = { -1, 0, 1 };
    static const GLshort sv[3] = { -32768, 32767, 1 };
    static const GLint iv[3] = { INT_MIN, INT_MAX, 0 };
    static const GLfloat fv[3] = { 3, -4, 12 };
    static const GLdouble dv[3] = { 0.1, 0.2, 0.3 };
    rec_normal(h, "default");
    glNormal3b(-128, 127, 0); rec_normal(h, "glNormal3b extremes");
    glNormal3bv(bv2); rec_normal(h, "glNormal3bv -1 0 1");
    glNormal3bv(bv); rec_normal(h, "glNormal3bv extremes");
    glNormal3s(-32768, 32767, 0); rec_normal(h, "glNormal3s extremes");
    glNormal3s(-1, 0, 1); rec_normal(h, "glNormal3s -1 0 1");
    glNormal3sv(sv); rec_normal(h, "glNormal3sv");
    glNormal3i(INT_MIN, INT_MAX, 0); rec_normal(h, "glNormal3i extremes");
    glNormal3i(1, -1, 2); rec_normal(h, "glNormal3i small");
    glNormal3iv(iv); rec_normal(h, "glNormal3iv");
    glNormal3f(3, -4, 12); rec_normal(h, "glNormal3f unnormalised");
    glNormal3f(1e30f, -1e30f, 0); rec_normal(h, "glNormal3f huge");
    glNormal3f(-0.0f, 0, 0); rec_normal(h, "glNormal3f zero");
    glNormal3fv(fv); rec_normal(h, "glNormal3fv");
    glNormal3d(0.1, 0.2, 0.3); rec_normal(h, "glNormal3d");
    glNormal3d(1e40, -1e-50, 2); rec_normal(h, "glNormal3d out of float range");
    glNormal3dv(dv); rec_normal(h, "glNormal3dv");
    glBegin(GL_TRIANGLES);
    glNormal3f(0.25f, 0.5f, -1);
    glVertex2f(0, 0);
    glNormal3f(-0.6f, 0.8f, 0);
    glVertex2f(1, 0);
    glEnd();
    /* The oracle crashes in OSMesaDestroyContext when immediate-mode
     * vertices are still buffered (never flushed) at that point. */
    glFinish();
    rec_normal(h, "set inside glBegin/glEnd");
}

/* ---- errors ------------------------------------------------------------- */

/* Bad light names and pnames for every glLight / glGetLight entry point;
 * GL_LIGHT0 and GL_LIGHT7 are unchanged afterwards. */
static void errors_light_enum(fc_h *h)
{
    static const GLfloat fv[4] = { 0.5f, 0.5f, 0.5f, 1 };
    static const GLint iv[4] = { 1, 1, 1, 1 };
    GLfloat out_f[4] = { -7, -7, -7, -7 };
    GLint out_i[4] = { -7, -7, -7, -7 };
    glLightfv(GL_LIGHT8_BAD, GL_DIFFUSE, fv); fc_error(h, "glLightfv(GL_LIGHT0+8)");
    glLightfv(GL_LIGHT0 - 1, GL_DIFFUSE, fv); fc_error(h, "glLightfv(GL_LIGHT0-1)");
    glLightfv(0, GL_DIFFUSE, fv); fc_error(h, "glLightfv(0)");
    glLightiv(GL_LIGHT8_BAD, GL_AMBIENT, iv); fc_error(h, "glLightiv(GL_LIGHT0+8)");
    glLightf(GL_LIGHT8_BAD, GL_SPOT_EXPONENT, 2); fc_error(h, "glLightf(GL_LIGHT0+8)");
    glLighti(GL_LIGHT8_BAD, GL_SPOT_CUTOFF, 20); fc_error(h, "glLighti(GL_LIGHT0+8)");
    glLightfv(GL_LIGHT0, GL_SHININESS, fv); fc_error(h, "glLightfv(GL_SHININESS)");
    glLightfv(GL_LIGHT0, GL_EMISSION, fv); fc_error(h, "glLightfv(GL_EMISSION)");
    glLightfv(GL_LIGHT0, 0x1234, fv); fc_error(h, "glLightfv(0x1234)");
    glLightiv(GL_LIGHT7, GL_LIGHT_MODEL_AMBIENT, iv); fc_error(h, "glLightiv(GL_LIGHT_MODEL_AMBIENT)");
    glLightf(GL_LIGHT7, GL_SHININESS, 3); fc_error(h, "glLightf(GL_SHININESS)");
    glLighti(GL_LIGHT7, 0, 3); fc_error(h, "glLighti(0)");
    glGetLightfv(GL_LIGHT8_BAD, GL_DIFFUSE, out_f); fc_error(h, "glGetLightfv(GL_LIGHT0+8)");
    glGetLightiv(GL_LIGHT8_BAD, GL_DIFFUSE, out_i); fc_error(h, "glGetLightiv(GL_LIGHT0+8)");
    glGetLightfv(GL_LIGHT0, GL_SHININESS, out_f); fc_error(h, "glGetLightfv(GL_SHININESS)");
    glGetLightiv(GL_LIGHT0, 0x1234, out_i); fc_error(h, "glGetLightiv(0x1234)");
    fc_blob(h, "glGetLight outputs after errors f", out_f, sizeof out_f);
    fc_blob(h, "glGetLight outputs after errors i", out_i, sizeof out_i);
    rec_light_all(h, GL_LIGHT0, "unchanged");
    rec_light_all(h, GL_LIGHT7, "unchanged");
}

/* Out-of-range values: spot exponent < 0 and > 128, cutoff outside [0,90]
 * other than 180, negative attenuation; each error recorded, then the
 * value (unchanged). */
static void errors_light_value(fc_h *h)
{
    static const struct { GLenum pname; GLfloat v; const char *what; } bad[] = {
        { GL_SPOT_EXPONENT, -1, "exponent -1" },
        { GL_SPOT_EXPONENT, -0.001f, "exponent -0.001" },
        { GL_SPOT_EXPONENT, 128.001f, "exponent 128.001" },
        { GL_SPOT_EXPONENT, 129, "exponent 129" },
        { GL_SPOT_CUTOFF, -1, "cutoff -1" },
        { GL_SPOT_CUTOFF, 90.01f, "cutoff 90.01" },
        { GL_SPOT_CUTOFF, 91, "cutoff 91" },
        { GL_SPOT_CUTOFF, 179.9f, "cutoff 179.9" },
        { GL_SPOT_CUTOFF, 180.1f, "cutoff 180.1" },
        { GL_SPOT_CUTOFF, 360, "cutoff 360" },
        { GL_CONSTANT_ATTENUATION, -1, "constant -1" },
        { GL_LINEAR_ATTENUATION, -0.5f, "linear -0.5" },
        { GL_QUADRATIC_ATTENUATION, -1e-6f, "quadratic -1e-6" },
    };
    glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 5);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 30);
    glLightf(GL_LIGHT2, GL_CONSTANT_ATTENUATION, 2);
    glLightf(GL_LIGHT2, GL_LINEAR_ATTENUATION, 0.5f);
    glLightf(GL_LIGHT2, GL_QUADRATIC_ATTENUATION, 0.25f);
    fc_error(h, "valid set-up");
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        glLightf(GL_LIGHT2, bad[i].pname, bad[i].v);
        fc_error(h, bad[i].what);
        lt_rec_light(h, bad[i].what, GL_LIGHT2, bad[i].pname);
    }
    /* The integer and vector forms. */
    glLighti(GL_LIGHT2, GL_SPOT_EXPONENT, 200); fc_error(h, "glLighti exponent 200");
    glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 91); fc_error(h, "glLighti cutoff 91");
    glLighti(GL_LIGHT2, GL_LINEAR_ATTENUATION, -1); fc_error(h, "glLighti linear -1");
    {
        static const GLfloat neg = -3;
        static const GLint negi = -3;
        glLightfv(GL_LIGHT2, GL_SPOT_EXPONENT, &neg); fc_error(h, "glLightfv exponent -3");
        glLightiv(GL_LIGHT2, GL_SPOT_CUTOFF, &negi); fc_error(h, "glLightiv cutoff -3");
    }
    rec_light_all(h, GL_LIGHT2, "unchanged");
}

/* glMaterial: shininess > 128 and < 0, bad faces and pnames;
 * glGetMaterial with GL_FRONT_AND_BACK and bad pnames. */
static void errors_material(fc_h *h)
{
    static const GLfloat fv[4] = { 0.5f, 0.5f, 0.5f, 1 };
    GLfloat out_f[4] = { -7, -7, -7, -7 };
    GLint out_i[4] = { -7, -7, -7, -7 };
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
    fc_error(h, "valid set-up");
    glMaterialf(GL_FRONT, GL_SHININESS, 128.5f); fc_error(h, "shininess 128.5");
    glMaterialf(GL_BACK, GL_SHININESS, 129); fc_error(h, "shininess 129");
    glMaterialf(GL_FRONT, GL_SHININESS, -1); fc_error(h, "shininess -1");
    glMateriali(GL_FRONT_AND_BACK, GL_SHININESS, 1000); fc_error(h, "glMateriali shininess 1000");
    glMaterialfv(GL_FRONT, GL_SHININESS, &fv[0]); fc_error(h, "glMaterialfv shininess 0.5 (valid)");
    lt_rec_material(h, "shininess front", GL_FRONT, GL_SHININESS);
    lt_rec_material(h, "shininess back", GL_BACK, GL_SHININESS);
    glMaterialfv(GL_FRONT_LEFT, GL_DIFFUSE, fv); fc_error(h, "face GL_FRONT_LEFT");
    glMaterialfv(GL_NONE, GL_DIFFUSE, fv); fc_error(h, "face GL_NONE");
    glMaterialfv(0x1234, GL_DIFFUSE, fv); fc_error(h, "face 0x1234");
    glMaterialf(GL_LEFT, GL_SHININESS, 5); fc_error(h, "glMaterialf face GL_LEFT");
    glMaterialfv(GL_FRONT, GL_POSITION, fv); fc_error(h, "pname GL_POSITION");
    glMaterialfv(GL_FRONT, GL_SPOT_EXPONENT, fv); fc_error(h, "pname GL_SPOT_EXPONENT");
    glMaterialfv(GL_BACK, 0x1234, fv); fc_error(h, "pname 0x1234");
    glGetMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, out_f); fc_error(h, "glGetMaterialfv(GL_FRONT_AND_BACK)");
    glGetMaterialiv(GL_FRONT_AND_BACK, GL_SHININESS, out_i); fc_error(h, "glGetMaterialiv(GL_FRONT_AND_BACK)");
    glGetMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, out_f); fc_error(h, "glGetMaterialfv(GL_AMBIENT_AND_DIFFUSE)");
    glGetMaterialfv(GL_FRONT, GL_POSITION, out_f); fc_error(h, "glGetMaterialfv(GL_POSITION)");
    glGetMaterialiv(GL_NONE, GL_DIFFUSE, out_i); fc_error(h, "glGetMaterialiv(GL_NONE)");
    fc_blob(h, "glGetMaterial outputs after errors f", out_f, sizeof out_f);
    fc_blob(h, "glGetMaterial outputs after errors i", out_i, sizeof out_i);
    rec_material_all(h, GL_FRONT, "unchanged");
    rec_material_all(h, GL_BACK, "unchanged");
}

/* glLightModel bad pnames and colour-control values. */
static void errors_light_model(fc_h *h)
{
    static const GLfloat fv[4] = { 0.5f, 0.5f, 0.5f, 1 };
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    fc_error(h, "valid set-up");
    glLightModelfv(GL_AMBIENT, fv); fc_error(h, "pname GL_AMBIENT");
    glLightModelfv(0x1234, fv); fc_error(h, "pname 0x1234");
    glLightModeli(GL_LIGHT0, 1); fc_error(h, "pname GL_LIGHT0");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, 0); fc_error(h, "color control 0");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR + 1); fc_error(h, "color control +1");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_TRUE); fc_error(h, "color control GL_TRUE");
    glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, 0.5f); fc_error(h, "color control 0.5f");
    rec_model(h);
}

/* glColorMaterial bad faces and modes. */
static void errors_color_material(fc_h *h)
{
    glColorMaterial(GL_BACK, GL_SPECULAR);
    fc_error(h, "valid set-up");
    glColorMaterial(GL_NONE, GL_DIFFUSE); fc_error(h, "face GL_NONE");
    glColorMaterial(GL_FRONT_LEFT, GL_DIFFUSE); fc_error(h, "face GL_FRONT_LEFT");
    glColorMaterial(GL_FRONT, GL_SHININESS); fc_error(h, "mode GL_SHININESS");
    glColorMaterial(GL_FRONT, GL_POSITION); fc_error(h, "mode GL_POSITION");
    glColorMaterial(GL_FRONT, GL_COLOR_INDEXES); fc_error(h, "mode GL_COLOR_INDEXES");
    glColorMaterial(GL_FRONT, 0); fc_error(h, "mode 0");
    fc_get_integer(h, "GL_COLOR_MATERIAL_FACE", GL_COLOR_MATERIAL_FACE, 1);
    fc_get_integer(h, "GL_COLOR_MATERIAL_PARAMETER", GL_COLOR_MATERIAL_PARAMETER, 1);
}

/* glEnable / glDisable / glIsEnabled of GL_LIGHT0 + 8. */
static void errors_enable(fc_h *h)
{
    glEnable(GL_LIGHT8_BAD); fc_error(h, "glEnable(GL_LIGHT0+8)");
    glDisable(GL_LIGHT8_BAD); fc_error(h, "glDisable(GL_LIGHT0+8)");
    fc_is_enabled(h, "GL_LIGHT0+8", GL_LIGHT8_BAD);
    fc_error(h, "glIsEnabled(GL_LIGHT0+8)");
    fc_get_boolean(h, "GL_LIGHT0+8", GL_LIGHT8_BAD, 1);
    fc_error(h, "glGetBooleanv(GL_LIGHT0+8)");
    rec_state_all(h, "unchanged");
}

/* Lighting commands inside glBegin/glEnd: glLight, glLightModel,
 * glColorMaterial, glGetLight, glGetMaterial, glEnable(GL_LIGHTING) are
 * INVALID_OPERATION (error read after glEnd); glMaterial and glNormal are
 * allowed and take effect per vertex.  The lit triangles are captured. */
static void errors_inside_begin_end(fc_h *h)
{
    static const GLfloat red[4] = { 1, 0.1f, 0.1f, 1 };
    static const GLfloat pos[4] = { -1, 0, 1, 0 };
    GLfloat out_f[4];
    fc_pixel_ortho(h);
    fcu_clear(0.05f, 0.06f, 0.12f, 1, 1);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    lt_std_material();
    for (int k = 0; k < 10; k++) {
        float x = 8.0f * (float)(k % 5), y = 8.0f * (float)(k / 5);
        glBegin(GL_TRIANGLES);
        glNormal3f(0.3f, 0.3f, 1);
        glVertex2f(x + 1, y + 1);
        switch (k) {
        case 0: glLightfv(GL_LIGHT0, GL_POSITION, pos); break;
        case 1: glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1); break;
        case 2: glColorMaterial(GL_FRONT, GL_EMISSION); break;
        case 3: glGetLightfv(GL_LIGHT0, GL_DIFFUSE, out_f); break;
        case 4: glGetMaterialfv(GL_FRONT, GL_DIFFUSE, out_f); break;
        case 5: glEnable(GL_LIGHTING); break;
        case 6: glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 10); break;
        case 7: glMaterialfv(GL_FRONT, GL_DIFFUSE, red); break;
        case 8: glNormal3f(-1, 0.2f, 0.5f); break;
        default: glMaterialf(GL_FRONT, GL_SHININESS, 2); break;
        }
        glVertex2f(x + 7, y + 1);
        glVertex2f(x + 3, y + 7);
        glEnd();
        fc_error(h, "after glEnd");
    }
    rec_light_all(h, GL_LIGHT0, "after blocks");
    rec_material_all(h, GL_FRONT, "after blocks");
    rec_state_all(h, "after blocks");
    fc_capture(h);
}

const fc_case fc_cases_light_api[] = {
    FC_CASE_RGBA("lighting/api_light_defaults", 8, 8, 0, "lighting api", light_defaults),
    FC_CASE_RGBA("lighting/api_material_defaults", 8, 8, 0, "lighting api", material_defaults),
    FC_CASE_RGBA("lighting/api_state_defaults", 8, 8, 0, "lighting api", state_defaults),
    FC_CASE_RGBA("lighting/api_enable_disable", 8, 8, 0, "lighting api", enable_disable),
    FC_CASE_RGBA("lighting/api_light_fv", 8, 8, 0, "lighting api", light_fv_roundtrip),
    FC_CASE_RGBA("lighting/api_light_iv", 8, 8, 0, "lighting api", light_iv_roundtrip),
    FC_CASE_RGBA("lighting/api_light_scalar", 8, 8, 0, "lighting api error", light_scalar),
    FC_CASE_RGBA("lighting/api_light_spot_state", 8, 8, 0, "lighting api spot", light_spot_state),
    FC_CASE_RGBA("lighting/api_light_model", 8, 8, 0, "lighting api error", light_model_roundtrip),
    FC_CASE_RGBA("lighting/api_material", 8, 8, 0, "lighting api error", material_roundtrip),
    FC_CASE_RGBA("lighting/api_color_material", 8, 8, 0, "lighting api color_material", color_material_state),
    FC_CASE_RGBA("lighting/api_current_normal", 8, 8, 0, "lighting api normals", current_normal),
    FC_CASE_RGBA("lighting/api_error_light_enum", 8, 8, 0, "lighting api error", errors_light_enum),
    FC_CASE_RGBA("lighting/api_error_light_value", 8, 8, 0, "lighting api error", errors_light_value),
    FC_CASE_RGBA("lighting/api_error_material", 8, 8, 0, "lighting api error", errors_material),
    FC_CASE_RGBA("lighting/api_error_light_model", 8, 8, 0, "lighting api error", errors_light_model),
    FC_CASE_RGBA("lighting/api_error_color_material", 8, 8, 0, "lighting api error", errors_color_material),
    FC_CASE_RGBA("lighting/api_error_enable", 8, 8, 0, "lighting api error", errors_enable),
    FC_CASE_RGBA("lighting/api_error_inside_begin_end", 40, 16, 1, "lighting api error", errors_inside_begin_end),
    { 0 }
};
