/* c_light_normal.c - normals: GL_NORMALIZE versus GL_RESCALE_NORMAL (and
 * both, and neither) under uniform and non-uniform modelview scales,
 * unnormalised and zero-length normals in object and eye space, and every
 * glNormal3{b,s,i,f,d}[v] variant (integer normals are converted with the
 * signed normalised mapping). */
#include "lt_util.h"

#include <math.h>

static const float k_black[3] = { 0, 0, 0 };
static const float k_dim[3] = { 0.08f, 0.08f, 0.08f };
static const float k_warm[3] = { 0.8f, 0.7f, 0.55f };
static const float k_cool[3] = { 0.3f, 0.45f, 0.8f };
static const float k_white[3] = { 1, 1, 1 };
static const float k_grey[3] = { 0.5f, 0.5f, 0.5f };
static const float k_half[3] = { 0.45f, 0.4f, 0.3f };

enum { SCALE_NONE, SCALE_NORMALIZE, SCALE_RESCALE, SCALE_BOTH };

/* A sphere under a rotation and a scale (uniform 0.7 or non-uniform
 * 1.3 x 0.6 x 0.9), shininess 3 (normals longer than 1 raise n.h above 1);
 * frame 1 a directional light (eye space only because
 * of the scale), frame 2 a positional light as well. */
static void scale_scene(fc_h *h, int uniform, int mode)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.3f, 0.3f, 0.3f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 3);
    lt_lamp(GL_LIGHT0, k_dim, k_half, k_grey, 0.6f, 0.8f, 1, 0);
    if (mode == SCALE_NORMALIZE || mode == SCALE_BOTH)
        glEnable(GL_NORMALIZE);
    if (mode == SCALE_RESCALE || mode == SCALE_BOTH)
        glEnable(GL_RESCALE_NORMAL);
    glTranslatef(0, 0, -4);
    glRotatef(25, 1, 0.2f, 0);
    if (uniform)
        glScalef(0.7f, 0.7f, 0.7f);
    else
        glScalef(1.3f, 0.6f, 0.9f);
    for (int f = 0; f < 2; f++) {
        if (f) {
            lt_clear();
            glPushMatrix();
            glLoadIdentity();
            lt_lamp(GL_LIGHT1, k_black, k_cool, k_grey, -1.2f, -0.6f, -2, 1);
            glPopMatrix();
        }
        lt_sphere(uniform ? 1.4f : 1.0f, 24, 16);
        fc_capture(h);
    }
}

static void scale_uniform_none(fc_h *h) { scale_scene(h, 1, SCALE_NONE); }
static void scale_uniform_normalize(fc_h *h) { scale_scene(h, 1, SCALE_NORMALIZE); }
static void scale_uniform_rescale(fc_h *h) { scale_scene(h, 1, SCALE_RESCALE); }
static void scale_nonuniform_none(fc_h *h) { scale_scene(h, 0, SCALE_NONE); }
static void scale_nonuniform_normalize(fc_h *h) { scale_scene(h, 0, SCALE_NORMALIZE); }
static void scale_nonuniform_rescale(fc_h *h) { scale_scene(h, 0, SCALE_RESCALE); }
static void scale_normalize_and_rescale(fc_h *h) { scale_scene(h, 0, SCALE_BOTH); }

/* Two spheres whose normals have length 0.4 (left) and 2.5 (right).
 * Frames 1-3 in object space (directional light, rotation only): as given,
 * GL_NORMALIZE, GL_RESCALE_NORMAL alone (factor 1 for a rotation).
 * Frame 4: a positional light (eye space), GL_NORMALIZE off. */
static void normals_unnormalized(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.4f, 0.8f, 1, 0);
    glTranslatef(0, 0, -4);
    glRotatef(15, 0, 1, 0);
    for (int f = 0; f < 4; f++) {
        lt_clear();
        if (f == 1)
            glEnable(GL_NORMALIZE);
        if (f == 2) {
            glDisable(GL_NORMALIZE);
            glEnable(GL_RESCALE_NORMAL);
        }
        if (f == 3) {
            glDisable(GL_RESCALE_NORMAL);
            lt_light(GL_LIGHT0, GL_POSITION, 0.4f, 1.2f, 1.5f, 1);
        }
        glPushMatrix();
        glTranslatef(-0.75f, 0, 0);
        lt_sphere_n(0.7f, 16, 12, 0.4f);
        glTranslatef(1.5f, 0, 0);
        lt_sphere_n(0.7f, 16, 12, 2.5f);
        glPopMatrix();
        fc_capture(h);
    }
}

/* A wavy patch where every third vertex has the normal (0,0,0).  Frames:
 * object space as given, object space GL_NORMALIZE (0 * 1/sqrt(0)),
 * eye space (uniform scale) as given, eye space GL_NORMALIZE. */
static void normals_zero_length(fc_h *h)
{
    lt_ortho(h, 1.2f);
    glEnable(GL_LIGHTING);
    lt_std_material();
    lt_mat(GL_FRONT_AND_BACK, GL_EMISSION, 0.05f, 0.05f, 0.1f, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.4f, 0.6f, 1, 0);
    for (int f = 0; f < 4; f++) {
        int k = 0;
        lt_clear();
        glLoadIdentity();
        glRotatef(-20, 1, 0, 0);
        if (f >= 2)
            glScalef(1.05f, 1.05f, 1.05f);
        if (f & 1)
            glEnable(GL_NORMALIZE);
        else
            glDisable(GL_NORMALIZE);
        for (int j = 0; j < 8; j++) {
            glBegin(GL_TRIANGLE_STRIP);
            for (int i = 0; i <= 8; i++) {
                for (int r = 1; r >= 0; r--) {
                    float x = -1 + 0.25f * (float)i, y = -1 + 0.25f * (float)(j + r);
                    float z = 0.25f * sinf(3 * x) * cosf(3 * y);
                    if (k++ % 3 == 0)
                        glNormal3f(0, 0, 0);
                    else
                        glNormal3f(-0.75f * cosf(3 * x) * cosf(3 * y), 0.75f * sinf(3 * x) * sinf(3 * y), 1);
                    glVertex3f(x, y, z);
                }
            }
            glEnd();
        }
        fc_capture(h);
    }
    fc_get_float(h, "GL_CURRENT_NORMAL", GL_CURRENT_NORMAL, 3);
}

/* One glNormal3 variant: 0 b, 1 bv, 2 s, 3 sv, 4 i, 5 iv, 6 f, 7 fv, 8 d,
 * 9 dv.  Integer types get round(v * mag). */
static void normal_variant(int t, double x, double y, double z, double mag)
{
    GLbyte b[3] = { (GLbyte)lround(x * mag), (GLbyte)lround(y * mag), (GLbyte)lround(z * mag) };
    GLshort s[3] = { (GLshort)lround(x * mag), (GLshort)lround(y * mag), (GLshort)lround(z * mag) };
    GLint i[3] = { (GLint)llround(x * mag), (GLint)llround(y * mag), (GLint)llround(z * mag) };
    GLfloat f[3] = { (GLfloat)(x * mag), (GLfloat)(y * mag), (GLfloat)(z * mag) };
    GLdouble d[3] = { x * mag, y * mag, z * mag };
    switch (t) {
    case 0: glNormal3b(b[0], b[1], b[2]); break;
    case 1: glNormal3bv(b); break;
    case 2: glNormal3s(s[0], s[1], s[2]); break;
    case 3: glNormal3sv(s); break;
    case 4: glNormal3i(i[0], i[1], i[2]); break;
    case 5: glNormal3iv(i); break;
    case 6: glNormal3f(f[0], f[1], f[2]); break;
    case 7: glNormal3fv(f); break;
    case 8: glNormal3d(d[0], d[1], d[2]); break;
    default: glNormal3dv(d); break;
    }
}

/* Ten panels (two rows of five), each a lit fan whose rim normals lean
 * outwards, given with one glNormal3 variant.  Frame 1: full-scale values
 * (127, 32767, 2147483647, 1.0), no GL_NORMALIZE.  Frame 2: small
 * magnitudes (20, 300, 5e6, 0.3) with GL_NORMALIZE. */
static void normal_types(fc_h *h)
{
    static const double full[10] = { 127, 127, 32767, 32767, 2147483647.0, 2147483647.0, 1, 1, 1, 1 };
    static const double small[10] = { 20, 20, 300, 300, 5e6, 5e6, 0.3, 0.3, 0.3, 0.3 };
    lt_ortho(h, 1);
    glEnable(GL_LIGHTING);
    lt_std_material();
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.4f, 0.5f, 1, 0);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_white, -1.5f, -0.2f, 1, 1);
    for (int fr = 0; fr < 2; fr++) {
        const double *mag = fr ? small : full;
        lt_clear();
        if (fr)
            glEnable(GL_NORMALIZE);
        for (int t = 0; t < 10; t++) {
            float cx = -1.6f + 0.8f * (float)(t % 5), cy = t < 5 ? 0.5f : -0.5f;
            glBegin(GL_TRIANGLE_FAN);
            normal_variant(t, 0, 0, 1, mag[t]);
            glVertex2f(cx, cy);
            for (int k = 0; k <= 8; k++) {
                double a = 2 * LT_PI * (k % 8) / 8 + 0.3;
                normal_variant(t, 0.77 * cos(a), 0.77 * sin(a), 0.64, mag[t]);
                glVertex2f(cx + 0.38f * (float)cos(a), cy + 0.46f * (float)sin(a));
            }
            glEnd();
        }
        fc_capture(h);
    }
}

const fc_case fc_cases_light_normal[] = {
    FC_CASE_RGBA("lighting/normal_scale_uniform_none", 48, 48, 2, "lighting normals", scale_uniform_none),
    FC_CASE_RGBA("lighting/normal_scale_uniform_normalize", 48, 48, 2, "lighting normals", scale_uniform_normalize),
    FC_CASE_RGBA("lighting/normal_scale_uniform_rescale", 48, 48, 2, "lighting normals", scale_uniform_rescale),
    FC_CASE_RGBA("lighting/normal_scale_nonuniform_none", 48, 48, 2, "lighting normals", scale_nonuniform_none),
    FC_CASE_RGBA("lighting/normal_scale_nonuniform_normalize", 48, 48, 2, "lighting normals",
                 scale_nonuniform_normalize),
    FC_CASE_RGBA("lighting/normal_scale_nonuniform_rescale", 48, 48, 2, "lighting normals", scale_nonuniform_rescale),
    FC_CASE_RGBA("lighting/normal_normalize_and_rescale", 48, 48, 2, "lighting normals", scale_normalize_and_rescale),
    FC_CASE_RGBA("lighting/normal_unnormalized", 64, 40, 4, "lighting normals space", normals_unnormalized),
    FC_CASE_RGBA("lighting/normal_zero_length", 48, 48, 4, "lighting normals robust", normals_zero_length),
    FC_CASE_RGBA("lighting/normal_types", 64, 32, 2, "lighting normals", normal_types),
    { 0 }
};
