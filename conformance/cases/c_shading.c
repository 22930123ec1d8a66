/* c_shading.c - fixgl's shading extensions (include/fixgl/shading.md):
 * GL_WIN_phong_shading (per-fragment lighting) and GL_FIXGL_cook_torrance
 * (per vertex under GL_SMOOTH/GL_FLAT, per fragment under GL_PHONG_WIN).
 *
 * The oracle has neither, so these are reference cases (fc_case.h): on
 * fixgl a case calls glShadeModel(GL_PHONG_WIN) and the Cook-Torrance
 * glMaterial parameters; under FC_ORACLE it binds the GLSL reference
 * (conformance/reference/fcr_shading.c), which evaluates the same equations
 * on OSMesa.  sh_begin/sh_end hide the difference.  The tolerance is 1 LSB
 * per channel (the agreement target); depth, errors and queries are
 * exact (the reference positions vertices with ftransform()).
 *
 * Covered: each light type (directional, point with attenuation, spot with
 * exponent 0 and 128 and cutoffs 30 and 90), eight lights, two-sided
 * lighting with a different back material, separate specular, colour
 * material (per-vertex colours, each tracked property), local viewer on
 * and off, shininess 0 and 128, roughness 0 (clamped), 0.05, 0.25, 0.5 and
 * 1, dielectrics (f0 0.04, 0.5), coloured and half metals, grazing light
 * and silhouettes, a light on the surface, strong perspective, clipping at
 * the near plane, big triangles with a highlight inside one triangle,
 * points and lines, polygon modes, display lists, vertex arrays,
 * GL_NORMALIZE and GL_RESCALE_NORMAL, a clipped height field, texturing,
 * the colour sum and the three fog modes after the lit colour, per-vertex Cook-Torrance under GL_SMOOTH and GL_FLAT,
 * and GL_PHONG_WIN without lighting.  Random scenes of all of it are the
 * random-shading family (random/fc_random_shading.c). */
#include "lt_util.h"
#include "sh_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef FC_ORACLE
#include <fixgl/fixgl.h>
#endif

/* ---- the shading under test ------------------------------------------- */

static const struct fcr_face sh_blinn = { 0, 0.5f, 0.0f, 0.04f };

static struct fcr_face sh_ct(float roughness, float metalness, float f0)
{
    struct fcr_face f = { 1, roughness, metalness, f0 };
    return f;
}

#ifdef FC_ORACLE
static struct fcr *sh_ref;
#else
/* fixgl: one face's GL_FIXGL_cook_torrance parameters */
static void sh_face(GLenum face, const struct fcr_face *f)
{
    glMateriali(face, GL_REFLECTANCE_MODEL_FIXGL, f->cook_torrance ? GL_COOK_TORRANCE_FIXGL : GL_BLINN_PHONG_FIXGL);
    glMaterialf(face, GL_ROUGHNESS_FIXGL, f->roughness);
    glMaterialf(face, GL_METALNESS_FIXGL, f->metalness);
    glMaterialf(face, GL_DIELECTRIC_F0_FIXGL, f->f0);
}
#endif

/* Selects the shading for what follows: mode (GL_PHONG_WIN, GL_SMOOTH or
 * GL_FLAT) and the reflectance model of each face.  Call it after the state
 * the reference compiles in (enabled lights, light model, colour material,
 * GL_NORMALIZE / GL_RESCALE_NORMAL; fcr_shading.h); light and material
 * colours may change afterwards.  Records whether the reference bound. */
void sh_begin(fc_h *h, enum sh_mode mode, const struct fcr_face *front, const struct fcr_face *back)
{
#ifdef FC_ORACLE
    int ok;
    glShadeModel(mode == SH_FLAT ? GL_FLAT : GL_SMOOTH);
    if (!sh_ref)
        sh_ref = fcr_create((fcr_getproc)OSMesaGetProcAddress);
    ok = sh_ref && fcr_bind(sh_ref, mode == SH_PHONG, front, back);
    fc_value(h, "reference bound", ok);
#else
    sh_face(GL_FRONT, front);
    sh_face(GL_BACK, back);
    glShadeModel(mode == SH_PHONG ? GL_PHONG_WIN : mode == SH_FLAT ? GL_FLAT : GL_SMOOTH);
    fc_value(h, "reference bound", 1);
#endif
}

/* Back to fixed-function GL_SMOOTH Blinn-Phong (the reference released;
 * every case calls it before it returns). */
void sh_end(void)
{
#ifdef FC_ORACLE
    if (sh_ref) {
        fcr_unbind(sh_ref);
        fcr_destroy(sh_ref);
        sh_ref = NULL;
    }
#else
    sh_face(GL_FRONT_AND_BACK, &sh_blinn);
#endif
    glShadeModel(GL_SMOOTH);
}

/* ---- scenes ------------------------------------------------------------- */

static const float k_dim[3] = { 0.1f, 0.1f, 0.1f };
static const float k_white[3] = { 1, 1, 1 };
static const float k_warm[3] = { 0.85f, 0.75f, 0.6f };
static const float k_cool[3] = { 0.4f, 0.6f, 1.0f };
static const float k_black[3] = { 0, 0, 0 };

/* Texture coordinates on sh_sphere's vertices (longitude, latitude). */
int sh_texcoords;

/* Sphere with unit normals and, when colored, a hue per vertex (colour
 * material), one triangle strip per stack. */
void sh_sphere(float r, int slices, int stacks, int colored)
{
    for (int i = 0; i < stacks; i++) {
        double lat[2] = { LT_PI * i / stacks - LT_PI / 2, LT_PI * (i + 1) / stacks - LT_PI / 2 };
        glBegin(GL_TRIANGLE_STRIP);
        for (int j = 0; j <= slices; j++) {
            double lon = 2 * LT_PI * j / slices;
            for (int k = 1; k >= 0; k--) {
                float x = (float)(cos(lat[k]) * sin(lon)), y = (float)sin(lat[k]),
                      z = (float)(cos(lat[k]) * cos(lon));
                if (colored)
                    lt_hue((float)j / (float)slices + 0.3f * y, 1.0f - 0.4f * (y > 0 ? y : -y));
                if (sh_texcoords)
                    glTexCoord2f(2.0f * (float)j / (float)slices, (float)((lat[k] + LT_PI / 2) / LT_PI));
                glNormal3f(x, y, z);
                glVertex3f(x * r, y * r, z * r);
            }
        }
        glEnd();
    }
}

/* Plane [x0,x1]x[y0,y1] at z = 0 with normal (0,0,nz), n x n quads as
 * triangle strips, counter-clockwise seen from +z. */
static void sh_plane(float x0, float y0, float x1, float y1, int n, float nz)
{
    glNormal3f(0, 0, nz);
    for (int j = 0; j < n; j++) {
        float ya = y0 + (y1 - y0) * (float)j / (float)n;
        float yb = y0 + (y1 - y0) * (float)(j + 1) / (float)n;
        glBegin(GL_TRIANGLE_STRIP);
        for (int i = 0; i <= n; i++) {
            float x = x0 + (x1 - x0) * (float)i / (float)n;
            glVertex3f(x, yb, 0);
            glVertex3f(x, ya, 0);
        }
        glEnd();
    }
}

/* Two big triangles covering [-s,s]^2 at z = 0 with the normals bent
 * outwards at the corners (a shallow dome): Gouraud interpolates the
 * corner colours, Phong finds the highlight inside a triangle. */
static void sh_big_quad(float s, float bend)
{
    static const float c[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    static const int idx[6] = { 0, 1, 2, 0, 2, 3 };
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 6; i++) {
        const float *v = c[idx[i]];
        glNormal3f(v[0] * bend, v[1] * bend, 1);
        glVertex3f(v[0] * s, v[1] * s, 0);
    }
    glEnd();
}

static void sh_material(void)
{
    lt_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.2f, 0.2f, 0.2f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.55f, 0.3f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.7f, 0.7f, 0.7f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_EMISSION, 0, 0, 0, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30);
}

/* Perspective view of a lit scene, camera at the origin looking down -z. */
static void sh_scene(fc_h *h)
{
    lt_persp(h);
    glEnable(GL_LIGHTING);
    sh_material();
}

/* A sphere at z = -4 lit by one light given in eye space. */
static void sh_sphere_case(fc_h *h, enum sh_mode mode, const struct fcr_face *f, float lx, float ly,
                           float lz, float lw)
{
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, lx, ly, lz, lw);
    sh_begin(h, mode, f, f);
    glTranslatef(0, 0, -4);
    sh_sphere(1.2f, 24, 16, 0);
    fc_capture(h);
    sh_end();
}

/* ---- Phong: light types -------------------------------------------------- */

static void phong_directional(fc_h *h)
{
    sh_sphere_case(h, SH_PHONG, &sh_blinn, 1, 1, 2, 0);
    /* another direction and colour, the program kept */
    lt_clear();
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    lt_light(GL_LIGHT0, GL_POSITION, -1, -0.5f, 0.6f, 0);
    lt_light(GL_LIGHT0, GL_DIFFUSE, 0.3f, 0.6f, 1, 1);
    sh_sphere(1.2f, 24, 16, 0);
    fc_capture(h);
    sh_end();
}

/* A point light close to a plane: the highlight and the attenuation
 * gradient across it. */
static void phong_point_attenuation(fc_h *h)
{
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.3f, 0.2f, -3.3f, 1);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.5f);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.4f);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.3f);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    sh_plane(-1.5f, -1.5f, 1.5f, 1.5f, 6, 1);
    fc_capture(h);
    sh_end();
}

static void spot_plane(fc_h *h, const struct fcr_face *f, float exponent, float cutoff)
{
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_black, k_white, k_white, 0.2f, 0.3f, -2.5f, 1);
    lt_light(GL_LIGHT0, GL_SPOT_DIRECTION, -0.1f, -0.2f, -1, 0);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
    sh_begin(h, SH_PHONG, f, f);
    glTranslatef(0, 0, -4);
    sh_plane(-1.6f, -1.6f, 1.6f, 1.6f, 4, 1);
    fc_capture(h);
    sh_end();
}

static void phong_spot_exp0(fc_h *h) { spot_plane(h, &sh_blinn, 0, 30); }
static void phong_spot_exp128(fc_h *h) { spot_plane(h, &sh_blinn, 128, 45); }
static void phong_spot_cutoff90(fc_h *h) { spot_plane(h, &sh_blinn, 4, 90); }

/* Eight lights: directional, point, spot, each colour apart. */
static void phong_eight_lights(fc_h *h)
{
    static const float pos[8][4] = {
        { 1, 1, 1, 0 }, { -1, 0.5f, 0.5f, 0 }, { 0, -1, 0.3f, 0 }, { 2, 2, -2, 1 },
        { -2, -1, -2, 1 }, { 0, 2.5f, -3, 1 }, { 1.5f, -1.5f, -1, 1 }, { -0.5f, 0, -1, 1 },
    };
    sh_scene(h);
    for (int i = 0; i < 8; i++) {
        float d[3] = { 0.15f + 0.1f * (float)(i % 3), 0.1f + 0.08f * (float)i, 0.5f - 0.05f * (float)i };
        lt_lamp(GL_LIGHT0 + i, k_black, d, d, pos[i][0], pos[i][1], pos[i][2], pos[i][3]);
    }
    glLightf(GL_LIGHT3, GL_LINEAR_ATTENUATION, 0.3f);
    glLightf(GL_LIGHT4, GL_QUADRATIC_ATTENUATION, 0.1f);
    lt_light(GL_LIGHT5, GL_SPOT_DIRECTION, 0, -1, -0.3f, 0);
    glLightf(GL_LIGHT5, GL_SPOT_CUTOFF, 40);
    glLightf(GL_LIGHT5, GL_SPOT_EXPONENT, 10);
    lt_light(GL_LIGHT6, GL_SPOT_DIRECTION, -1, 1, -1, 0);
    glLightf(GL_LIGHT6, GL_SPOT_CUTOFF, 60);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    sh_sphere(1.2f, 20, 14, 0);
    fc_capture(h);
    sh_end();
}

/* ---- Phong: light model, material --------------------------------------- */

/* The left plane faces the viewer (front material); the right one is
 * drawn with glFrontFace(GL_CW), so it is back-facing, with normal
 * (0,0,-1): the back face lights it with -N = (0,0,1) and the back
 * material.  Frame 2 without two-sided lighting: the front material and N. */
static void phong_two_sided(fc_h *h)
{
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0, 0.5f, -2.5f, 1);
    lt_mat(GL_BACK, GL_DIFFUSE, 0.2f, 0.5f, 0.9f, 1);
    lt_mat(GL_BACK, GL_SPECULAR, 1, 0.8f, 0.2f, 1);
    glMaterialf(GL_BACK, GL_SHININESS, 8);
    for (int two = 1; two >= 0; two--) {
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, two);
        sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        glFrontFace(GL_CCW);
        sh_plane(-1.8f, -1.2f, -0.1f, 1.2f, 3, 1);
        glFrontFace(GL_CW);
        sh_plane(0.1f, -1.2f, 1.8f, 1.2f, 3, -1);
        glFrontFace(GL_CCW);
        fc_capture(h);
        sh_end();
        lt_clear();
    }
}

static void phong_separate_specular(fc_h *h)
{
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    lt_lamp(GL_LIGHT0, k_dim, k_cool, k_white, 1, 1.5f, 2, 0);
    lt_lamp(GL_LIGHT1, k_dim, k_warm, k_warm, -1, -0.5f, -2, 1);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    sh_sphere(1.2f, 24, 16, 0);
    fc_capture(h);
    sh_end();
}

/* Per-vertex colours tracked as ambient and diffuse, then as specular and
 * as emission (with a dimmer light). */
static void phong_color_material(fc_h *h)
{
    static const GLenum params[3] = { GL_AMBIENT_AND_DIFFUSE, GL_SPECULAR, GL_EMISSION };
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1, 2, 0);
    glEnable(GL_COLOR_MATERIAL);
    for (int i = 0; i < 3; i++) {
        glColorMaterial(GL_FRONT_AND_BACK, params[i]);
        sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        sh_sphere(1.2f, 24, 16, 1);
        fc_capture(h);
        sh_end();
        lt_clear();
        sh_material();
        if (i == 1)
            lt_light(GL_LIGHT0, GL_DIFFUSE, 0.3f, 0.3f, 0.3f, 1);
    }
    glDisable(GL_COLOR_MATERIAL);
}

/* Local viewer on and off, a point light near a plane seen obliquely. */
static void phong_local_viewer(fc_h *h)
{
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.5f, 1.5f, -3, 1);
    for (int lv = 1; lv >= 0; lv--) {
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, lv);
        sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
        glLoadIdentity();
        glTranslatef(0, -0.5f, -4);
        glRotatef(-60, 1, 0, 0);
        sh_plane(-2, -2, 2, 2, 4, 1);
        fc_capture(h);
        sh_end();
        lt_clear();
    }
}

static void shininess_case(fc_h *h, float shin)
{
    sh_scene(h);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shin);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1, 1, 1);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    sh_sphere(1.2f, 24, 16, 0);
    fc_capture(h);
    sh_end();
}

static void phong_shininess_0(fc_h *h) { shininess_case(h, 0); }
static void phong_shininess_128(fc_h *h) { shininess_case(h, 128); }

/* Unit-length normals scaled by the modelview (GL_RESCALE_NORMAL) and
 * normals of length 2.5 (GL_NORMALIZE), interpolated before the
 * renormalisation. */
static void phong_normalize(fc_h *h)
{
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1, 2, 0);
    glEnable(GL_RESCALE_NORMAL);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    glScalef(0.6f, 0.6f, 0.6f);
    sh_sphere(2.0f, 12, 8, 0);
    fc_capture(h);
    sh_end();
    lt_clear();
    glDisable(GL_RESCALE_NORMAL);
    glEnable(GL_NORMALIZE);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glLoadIdentity();
    glTranslatef(0, 0, -4);
    glScalef(1.0f, 0.7f, 1.3f);
    lt_sphere_n(1.2f, 12, 8, 2.5f);
    fc_capture(h);
    sh_end();
}

/* ---- Phong: geometry ---------------------------------------------------- */

/* Two triangles with a highlight in the middle of one of them: Gouraud
 * (frame 1, fixed function, exact) misses it, Phong (frame 2) shows it. */
static void phong_big_triangles(fc_h *h)
{
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.35f, 0.2f, -3.2f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 60);
    glTranslatef(0, 0, -4);
    sh_big_quad(1.6f, 0.3f);
    fc_capture(h);
    lt_clear();
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    sh_big_quad(1.6f, 0.3f);
    fc_capture(h);
    sh_end();
}

/* A long plane receding to the horizon (w from 1.6 to 20). */
static void phong_perspective(fc_h *h)
{
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0, 0.5f, -6, 1);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.2f);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, -1, 0);
    glRotatef(-90, 1, 0, 0);
    sh_plane(-3, 1.6f, 3, 19, 3, 1);
    fc_capture(h);
    sh_end();
}

/* A plane through the near plane and behind the eye: clipped, new vertices
 * with interpolated normal and eye position. */
static void phong_clip_near(fc_h *h)
{
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.5f, 0.5f, -2.5f, 1);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, -0.8f, 0);
    glRotatef(-80, 1, 0, 0);
    glBegin(GL_TRIANGLES);
    glNormal3f(0.2f, 0, 1);
    glVertex3f(-2, -2, 0);
    glNormal3f(-0.2f, 0.1f, 1);
    glVertex3f(2, 1, 0);
    glNormal3f(0, -0.3f, 1);
    glVertex3f(-1, 8, 0);
    glEnd();
    fc_capture(h);
    sh_end();
}

/* A light exactly on the lit plane (n.l = 0 along the plane) and one just
 * above it, grazing. */
static void phong_light_on_surface(fc_h *h)
{
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.2f, 0.1f, -4, 1);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_white, -0.4f, 0.2f, -3.98f, 1);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    sh_plane(-1.5f, -1.5f, 1.5f, 1.5f, 3, 1);
    fc_capture(h);
    sh_end();
}

/* Silhouettes: a light behind the sphere, almost in the tangent plane of
 * the visible rim. */
static void phong_grazing(fc_h *h)
{
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 0.2f, -0.05f, 0);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    sh_sphere(1.3f, 32, 20, 0);
    fc_capture(h);
    sh_end();
}

/* Lines (a circle of normals and spokes) and points of a sphere. */
static void phong_lines(fc_h *h)
{
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1, 0, 1);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < 24; i++) {
        double a = 2 * LT_PI * i / 24;
        glNormal3f((float)cos(a), (float)sin(a), 0.3f);
        glVertex3f(1.4f * (float)cos(a), 1.4f * (float)sin(a), 0);
    }
    glEnd();
    glBegin(GL_LINES);
    for (int i = 0; i < 8; i++) {
        double a = 2 * LT_PI * i / 8 + 0.2;
        glNormal3f(0, 0, 1);
        glVertex3f(0, 0, 0.5f);
        glNormal3f((float)cos(a), (float)sin(a), -0.5f);
        glVertex3f(1.2f * (float)cos(a), 1.2f * (float)sin(a), -0.3f);
    }
    glEnd();
    fc_capture(h);
    sh_end();
}

static void phong_points(fc_h *h)
{
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1, 2, 0);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    for (int size = 1; size <= 3; size += 2) {
        glPointSize((float)size);
        glBegin(GL_POINTS);
        for (int i = 0; i < 9; i++)
            for (int j = 0; j < 12; j++) {
                double lat = LT_PI * (i + 0.5) / 9 - LT_PI / 2, lon = 2 * LT_PI * j / 12 + (size == 3 ? 0.26 : 0);
                float x = (float)(cos(lat) * sin(lon)), y = (float)sin(lat), z = (float)(cos(lat) * cos(lon));
                glNormal3f(x, y, z);
                glVertex3f(1.3f * x, 1.3f * y, 1.3f * z);
            }
        glEnd();
    }
    glPointSize(1);
    fc_capture(h);
    sh_end();
}

/* The geometry and its materials in a display list, called twice under
 * other modelviews; on fixgl the Cook-Torrance parameters of the second
 * list compile into it too. */
static void phong_dlist(fc_h *h)
{
    struct fcr_face metal = sh_ct(0.3f, 1, 0.04f);
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1, 2, 0);
    glNewList(1, GL_COMPILE);
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.3f, 0.7f, 0.4f, 1);
    sh_sphere(0.8f, 16, 10, 0);
    glEndList();
    glNewList(2, GL_COMPILE);
#ifndef FC_ORACLE
    sh_face(GL_FRONT_AND_BACK, &metal);
#endif
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.95f, 0.64f, 0.54f, 1);
    sh_sphere(0.8f, 16, 10, 0);
    glEndList();
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(-0.9f, 0, -4);
    glCallList(1);
    sh_end();
    sh_begin(h, SH_PHONG, &metal, &metal);
    glLoadIdentity();
    glTranslatef(0.9f, 0, -4);
    glCallList(2);
    fc_capture(h);
    sh_end();
    glDeleteLists(1, 2);
}

/* A sphere from vertex arrays (glDrawElements), colours tracked. */
static void phong_varray(fc_h *h)
{
    enum { SL = 16, ST = 10 };
    static float v[(SL + 1) * (ST + 1)][3], n[(SL + 1) * (ST + 1)][3], c[(SL + 1) * (ST + 1)][4];
    static GLushort idx[SL * ST * 6];
    int k = 0;
    for (int i = 0; i <= ST; i++)
        for (int j = 0; j <= SL; j++) {
            double lat = LT_PI * i / ST - LT_PI / 2, lon = 2 * LT_PI * j / SL;
            float *p = v[i * (SL + 1) + j], *q = n[i * (SL + 1) + j], *col = c[i * (SL + 1) + j];
            q[0] = (float)(cos(lat) * sin(lon));
            q[1] = (float)sin(lat);
            q[2] = (float)(cos(lat) * cos(lon));
            for (int a = 0; a < 3; a++)
                p[a] = 1.2f * q[a];
            col[0] = 0.5f + 0.5f * q[0];
            col[1] = 0.5f + 0.5f * q[1];
            col[2] = 0.6f;
            col[3] = 1;
        }
    for (int i = 0; i < ST; i++)
        for (int j = 0; j < SL; j++) {
            GLushort a = (GLushort)(i * (SL + 1) + j), b = (GLushort)(a + SL + 1);
            idx[k++] = a; idx[k++] = (GLushort)(a + 1); idx[k++] = (GLushort)(b + 1);
            idx[k++] = a; idx[k++] = (GLushort)(b + 1); idx[k++] = b;
        }
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 1, 1, 2, 0);
    glEnable(GL_COLOR_MATERIAL);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    glRotatef(30, 1, 1, 0);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glNormalPointer(GL_FLOAT, 0, n);
    glColorPointer(4, GL_FLOAT, 0, c);
    glDrawElements(GL_TRIANGLES, k, GL_UNSIGNED_SHORT, idx);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    fc_capture(h);
    sh_end();
    glDisable(GL_COLOR_MATERIAL);
}

/* GL_PHONG_WIN without lighting interpolates colours as GL_SMOOTH does
 * (the reference binds nothing): exact. */
static void phong_unlit(fc_h *h)
{
    lt_persp(h);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    sh_sphere(1.2f, 24, 16, 1);
    fc_capture(h);
    sh_end();
}

/* Polygon modes: the sphere's front faces as lines, its back faces (seen
 * through the gaps, two-sided) as points. */
static void phong_polygon_mode(fc_h *h)
{
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    lt_mat(GL_BACK, GL_DIFFUSE, 0.3f, 0.8f, 0.5f, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1, 2, 0);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glTranslatef(0, 0, -4);
    glRotatef(20, 1, 0, 0);
    sh_sphere(1.3f, 12, 8, 0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    fc_capture(h);
    sh_end();
}

/* A smooth 8x8 RGBA texture (GL_LINEAR, GL_REPEAT, GL_MODULATE). */
void sh_texture(void)
{
    static unsigned char img[8 * 8 * 4];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            unsigned char *t = &img[4 * (y * 8 + x)];
            t[0] = (unsigned char)(255 - 20 * x);
            t[1] = (unsigned char)(120 + 15 * y);
            t[2] = (unsigned char)(60 + 12 * ((x + y) & 7) * 2);
            t[3] = (unsigned char)(255 - 8 * x);
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
}

/* The lit colour goes on through the fragment pipeline: a GL_MODULATE
 * texture, the separate specular colour sum, then linear fog (frame 1);
 * EXP fog without texture, single colour (frame 2); EXP2 fog with the
 * texture and blending (frame 3). */
static void phong_texture_fog(fc_h *h)
{
    static const float fog_color[4] = { 0.3f, 0.35f, 0.5f, 1 };
    sh_scene(h);
    sh_texture();
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 1, 1, 2, 0);
    glFogfv(GL_FOG_COLOR, fog_color);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2.5f);
    glFogf(GL_FOG_END, 6);
    glEnable(GL_FOG);
    sh_texcoords = 1;
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    glTranslatef(0, 0, -4);
    glRotatef(-40, 1, 0, 0);
    sh_sphere(1.3f, 20, 12, 0);
    fc_capture(h);
    sh_end();
    lt_clear();
    glDisable(GL_TEXTURE_2D);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.2f);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    sh_sphere(1.3f, 20, 12, 0);
    fc_capture(h);
    sh_end();
    lt_clear();
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.25f);
    sh_begin(h, SH_PHONG, &sh_blinn, &sh_blinn);
    sh_sphere(1.3f, 20, 12, 0);
    fc_capture(h);
    sh_end();
    sh_texcoords = 0;
    glDisable(GL_BLEND);
    glDisable(GL_FOG);
    glDisable(GL_TEXTURE_2D);
}

/* ---- Cook-Torrance ------------------------------------------------------ */

/* A sphere per fragment with a point light and a local viewer: the lobe
 * shape of each roughness. */
static void ct_sphere(fc_h *h, enum sh_mode mode, struct fcr_face f, int local_viewer)
{
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local_viewer);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 2, 2, 0, 1);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_cool, -1, -0.3f, 0.5f, 0);
    sh_begin(h, mode, &f, &f);
    glTranslatef(0, 0, -4);
    sh_sphere(1.2f, 24, 16, 0);
    fc_capture(h);
    sh_end();
}

static void ct_rough_0(fc_h *h) { ct_sphere(h, SH_PHONG, sh_ct(0, 0, 0.04f), 1); }
static void ct_rough_005(fc_h *h) { ct_sphere(h, SH_PHONG, sh_ct(0.05f, 0, 0.04f), 1); }
static void ct_rough_025(fc_h *h) { ct_sphere(h, SH_PHONG, sh_ct(0.25f, 0, 0.04f), 1); }
static void ct_rough_05(fc_h *h) { ct_sphere(h, SH_PHONG, sh_ct(0.5f, 0, 0.04f), 1); }
static void ct_rough_1(fc_h *h) { ct_sphere(h, SH_PHONG, sh_ct(1, 0, 0.04f), 1); }
static void ct_dielectric_f0(fc_h *h) { ct_sphere(h, SH_PHONG, sh_ct(0.3f, 0, 0.5f), 0); }
static void ct_half_metal(fc_h *h) { ct_sphere(h, SH_PHONG, sh_ct(0.35f, 0.5f, 0.04f), 1); }
static void ct_smooth(fc_h *h) { ct_sphere(h, SH_SMOOTH, sh_ct(0.4f, 0, 0.04f), 1); }
static void ct_flat(fc_h *h) { ct_sphere(h, SH_FLAT, sh_ct(0.4f, 0.3f, 0.04f), 1); }
static void ct_smooth_rough_005(fc_h *h) { ct_sphere(h, SH_SMOOTH, sh_ct(0.05f, 0, 0.04f), 0); }

/* Coloured metals: gold, copper and a blue metal side by side. */
static void ct_metals(fc_h *h)
{
    static const float base[3][3] = { { 1.0f, 0.766f, 0.336f }, { 0.955f, 0.638f, 0.538f }, { 0.3f, 0.5f, 0.9f } };
    static const float rough[3] = { 0.2f, 0.45f, 0.7f };
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 1, 2, 1, 1);
    for (int i = 0; i < 3; i++) {
        struct fcr_face f = sh_ct(rough[i], 1, 0.04f);
        lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, base[i][0], base[i][1], base[i][2], 1);
        sh_begin(h, SH_PHONG, &f, &f);
        glLoadIdentity();
        glTranslatef(-1.3f + 1.3f * (float)i, 0, -4);
        sh_sphere(0.6f, 20, 12, 0);
        sh_end();
    }
    fc_capture(h);
}

/* Point light with attenuation and a spot with exponent 0 and 128 on a
 * rough dielectric plane. */
static void ct_spot_attenuation(fc_h *h)
{
    struct fcr_face f = sh_ct(0.3f, 0, 0.04f);
    spot_plane(h, &f, 0, 35);
    lt_clear();
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 128);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.5f);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.25f);
    sh_begin(h, SH_PHONG, &f, &f);
    sh_plane(-1.6f, -1.6f, 1.6f, 1.6f, 4, 1);
    fc_capture(h);
    sh_end();
}

/* Grazing: light almost in the tangent plane of the rim, seen by a local
 * viewer (n.v small at the silhouette: G and the 1/(4 n.v) term). */
static void ct_grazing(fc_h *h)
{
    struct fcr_face f = sh_ct(0.2f, 0.6f, 0.04f);
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.9f, 0.85f, 0.8f, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, -1, 0.3f, -0.1f, 0);
    sh_begin(h, SH_PHONG, &f, &f);
    glTranslatef(0, 0, -4);
    sh_sphere(1.3f, 32, 20, 0);
    fc_capture(h);
    sh_end();
}

/* Front Cook-Torrance, back Blinn-Phong (per fragment), then both
 * Cook-Torrance with different parameters per vertex. */
static void ct_two_sided(fc_h *h)
{
    struct fcr_face front = sh_ct(0.3f, 1, 0.04f), back = sh_ct(0.6f, 0, 0.2f);
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0, 0.5f, -2.5f, 1);
    lt_mat(GL_BACK, GL_DIFFUSE, 0.2f, 0.5f, 0.9f, 1);
    for (int pass = 0; pass < 2; pass++) {
        sh_begin(h, pass ? SH_SMOOTH : SH_PHONG, &front, pass ? &back : &sh_blinn);
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        sh_plane(-1.8f, -1.2f, -0.1f, 1.2f, 6, 1);
        glFrontFace(GL_CW);
        sh_plane(0.1f, -1.2f, 1.8f, 1.2f, 6, -1);
        glFrontFace(GL_CCW);
        fc_capture(h);
        sh_end();
        lt_clear();
    }
}

/* The base colour from per-vertex colours (GL_DIFFUSE tracked), per
 * fragment and per vertex. */
static void ct_color_material(fc_h *h)
{
    struct fcr_face f = sh_ct(0.35f, 0.5f, 0.04f);
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 1, 1, 2, 0);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    for (int pass = 0; pass < 2; pass++) {
        sh_begin(h, pass ? SH_SMOOTH : SH_PHONG, &f, &f);
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        sh_sphere(1.2f, 24, 16, 1);
        fc_capture(h);
        sh_end();
        lt_clear();
    }
    glDisable(GL_COLOR_MATERIAL);
}

static void ct_separate_specular(fc_h *h)
{
    struct fcr_face f = sh_ct(0.25f, 0.2f, 0.04f);
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    lt_lamp(GL_LIGHT0, k_dim, k_cool, k_white, 1, 1.5f, 2, 0);
    lt_lamp(GL_LIGHT1, k_dim, k_warm, k_warm, -1.5f, -0.5f, -2, 1);
    sh_begin(h, SH_PHONG, &f, &f);
    glTranslatef(0, 0, -4);
    sh_sphere(1.2f, 24, 16, 0);
    fc_capture(h);
    sh_end();
}

/* The highlight inside one big triangle, per fragment. */
static void ct_big_triangles(fc_h *h)
{
    struct fcr_face f = sh_ct(0.15f, 0, 0.04f);
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 0.35f, 0.2f, -3.2f, 1);
    sh_begin(h, SH_PHONG, &f, &f);
    glTranslatef(0, 0, -4);
    sh_big_quad(1.6f, 0.3f);
    fc_capture(h);
    sh_end();
}

/* Lines and points per fragment, per vertex under GL_FLAT. */
static void ct_points_lines(fc_h *h)
{
    struct fcr_face f = sh_ct(0.3f, 0.5f, 0.04f);
    sh_scene(h);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1, 1, 0);
    for (int pass = 0; pass < 2; pass++) {
        sh_begin(h, pass ? SH_FLAT : SH_PHONG, &f, &f);
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= 16; i++) {
            double a = LT_PI * i / 16;
            glNormal3f((float)cos(a), (float)sin(a), 0.5f);
            glVertex3f(1.4f * (float)cos(a), 1.4f * (float)sin(a) - 0.2f, 0);
        }
        glEnd();
        glPointSize(2);
        glBegin(GL_POINTS);
        for (int i = 0; i < 30; i++) {
            double a = 2 * LT_PI * i / 30;
            glNormal3f((float)cos(a), (float)sin(a), (float)(0.3 + 0.02 * i));
            glVertex3f(0.9f * (float)cos(a), 0.9f * (float)sin(a) - 0.5f, 0.1f);
        }
        glEnd();
        glPointSize(1);
        fc_capture(h);
        sh_end();
        lt_clear();
    }
}

/* Per-vertex Cook-Torrance in a display list and from vertex arrays. */
static void ct_dlist_varray(fc_h *h)
{
    static const float v[6][3] = { { -1.5f, -1.2f, 0 }, { 1.5f, -1.2f, 0 }, { 0, 1.5f, -0.5f },
                                   { -1.2f, 0.5f, 0.3f }, { 0.4f, -1.4f, 0.6f }, { 1.4f, 1.0f, -0.4f } };
    static const float n[6][3] = { { -0.5f, -0.4f, 1 }, { 0.5f, -0.4f, 1 }, { 0, 0.6f, 1 },
                                   { -0.6f, 0.2f, 0.8f }, { 0.1f, -0.7f, 0.7f }, { 0.6f, 0.5f, 0.6f } };
    struct fcr_face f = sh_ct(0.3f, 0.8f, 0.04f);
    sh_scene(h);
    glEnable(GL_NORMALIZE);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 0.5f, 0.8f, 1, 0);
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.9f, 0.6f, 0.3f, 1);
    sh_begin(h, SH_SMOOTH, &f, &f);
    glTranslatef(0, 0, -4);
    glNewList(1, GL_COMPILE);
    sh_sphere(0.7f, 16, 10, 0);
    glEndList();
    glPushMatrix();
    glTranslatef(-0.8f, 0.6f, 0);
    glCallList(1);
    glPopMatrix();
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glNormalPointer(GL_FLOAT, 0, n);
    glTranslatef(0.5f, -0.3f, 0);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    fc_capture(h);
    sh_end();
    glDeleteLists(1, 1);
}

/* Cook-Torrance through the fragment pipeline: textured, separate
 * specular and linear fog, per fragment then per vertex. */
static void ct_texture_fog(fc_h *h)
{
    static const float fog_color[4] = { 0.5f, 0.45f, 0.4f, 1 };
    struct fcr_face f = sh_ct(0.3f, 0.4f, 0.04f);
    sh_scene(h);
    sh_texture();
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 2, 2, 0, 1);
    glFogfv(GL_FOG_COLOR, fog_color);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 3);
    glFogf(GL_FOG_END, 5.5f);
    glEnable(GL_FOG);
    sh_texcoords = 1;
    for (int pass = 0; pass < 2; pass++) {
        sh_begin(h, pass ? SH_SMOOTH : SH_PHONG, &f, &f);
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        glRotatef(30, 0, 1, 0);
        sh_sphere(1.3f, 20, 12, 0);
        fc_capture(h);
        sh_end();
        lt_clear();
    }
    sh_texcoords = 0;
    glDisable(GL_FOG);
    glDisable(GL_TEXTURE_2D);
}

/* Per-vertex Cook-Torrance with GL_RESCALE_NORMAL under a uniform scale,
 * then GL_NORMALIZE with normals of length 2.5 under a non-uniform one:
 * shading.md's n includes either before N = normalize(n). */
static void ct_rescale_normalize(fc_h *h)
{
    struct fcr_face f = sh_ct(0.2f, 0.3f, 0.04f);
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_warm, k_white, 1, 1.5f, 1, 0);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_white, -2, -1, -1, 1);
    for (int pass = 0; pass < 2; pass++) {
        glEnable(pass ? GL_NORMALIZE : GL_RESCALE_NORMAL);
        sh_begin(h, SH_SMOOTH, &f, &f);
        glLoadIdentity();
        glTranslatef(0, 0, -4);
        glRotatef(25, 1, 1, 0);
        if (pass) {
            glScalef(1.2f, 0.8f, 1.1f);
            lt_sphere_n(1.1f, 32, 20, 2.5f);
        } else {
            glScalef(0.7f, 0.7f, 0.7f);
            sh_sphere(1.9f, 32, 20, 0);
        }
        fc_capture(h);
        sh_end();
        glDisable(pass ? GL_NORMALIZE : GL_RESCALE_NORMAL);
        lt_clear();
    }
}

/* Perspective and a local viewer on a receding plane, rough metal. */
static void ct_perspective(fc_h *h)
{
    struct fcr_face f = sh_ct(0.25f, 1, 0.04f);
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.95f, 0.93f, 0.88f, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 0, 1, -8, 1);
    sh_begin(h, SH_PHONG, &f, &f);
    glTranslatef(0, -1, 0);
    glRotatef(-90, 1, 0, 0);
    sh_plane(-3, 1.6f, 3, 19, 3, 1);
    fc_capture(h);
    sh_end();
}

/* A height field larger than the viewport (clipped at its edges), two
 * lights, a rough metal, per fragment then per vertex. */
static void ct_wave_clipped(fc_h *h)
{
    struct fcr_face f = sh_ct(0.4f, 0.9f, 0.04f);
    sh_scene(h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.56f, 0.57f, 0.58f, 1);
    lt_lamp(GL_LIGHT0, k_dim, k_white, k_white, 1, 1, -2, 1);
    lt_lamp(GL_LIGHT1, k_black, k_cool, k_cool, -1, 0.5f, 1, 0);
    for (int pass = 0; pass < 2; pass++) {
        sh_begin(h, pass ? SH_SMOOTH : SH_PHONG, &f, &f);
        glLoadIdentity();
        glTranslatef(0, 0, -3.5f);
        glRotatef(-35, 1, 0, 0);
        lt_wave(-3, -3, 3, 3, 14, 0.25f, 2.2f);
        fc_capture(h);
        sh_end();
        lt_clear();
    }
}

#define SH_CASE(name, w, h, frames, tags, fn) \
    { name, w, h, OSMESA_RGBA, 24, 0, frames, "shading reference " tags, fn, 0, 0, 1, 0 }

const fc_case fc_cases_shading[] = {
    SH_CASE("shading/phong_directional", 64, 64, 2, "phong", phong_directional),
    SH_CASE("shading/phong_point_attenuation", 64, 64, 1, "phong", phong_point_attenuation),
    SH_CASE("shading/phong_spot_exp0", 64, 64, 1, "phong", phong_spot_exp0),
    SH_CASE("shading/phong_spot_exp128", 64, 64, 1, "phong", phong_spot_exp128),
    SH_CASE("shading/phong_spot_cutoff90", 64, 64, 1, "phong", phong_spot_cutoff90),
    SH_CASE("shading/phong_eight_lights", 64, 64, 1, "phong", phong_eight_lights),
    SH_CASE("shading/phong_two_sided", 64, 48, 2, "phong", phong_two_sided),
    SH_CASE("shading/phong_separate_specular", 64, 64, 1, "phong", phong_separate_specular),
    SH_CASE("shading/phong_color_material", 48, 48, 3, "phong", phong_color_material),
    SH_CASE("shading/phong_local_viewer", 64, 64, 2, "phong", phong_local_viewer),
    SH_CASE("shading/phong_shininess_0", 48, 48, 1, "phong", phong_shininess_0),
    SH_CASE("shading/phong_shininess_128", 64, 64, 1, "phong", phong_shininess_128),
    SH_CASE("shading/phong_normalize", 48, 48, 2, "phong", phong_normalize),
    SH_CASE("shading/phong_big_triangles", 64, 64, 2, "phong", phong_big_triangles),
    SH_CASE("shading/phong_perspective", 64, 64, 1, "phong", phong_perspective),
    SH_CASE("shading/phong_clip_near", 64, 64, 1, "phong", phong_clip_near),
    SH_CASE("shading/phong_light_on_surface", 64, 64, 1, "phong", phong_light_on_surface),
    SH_CASE("shading/phong_grazing", 64, 64, 1, "phong", phong_grazing),
    SH_CASE("shading/phong_lines", 64, 64, 1, "phong", phong_lines),
    SH_CASE("shading/phong_points", 64, 64, 1, "phong", phong_points),
    SH_CASE("shading/phong_dlist", 64, 48, 1, "phong cook-torrance", phong_dlist),
    SH_CASE("shading/phong_varray", 48, 48, 1, "phong", phong_varray),
    SH_CASE("shading/phong_unlit", 32, 32, 1, "phong", phong_unlit),
    SH_CASE("shading/phong_polygon_mode", 64, 64, 1, "phong", phong_polygon_mode),
    SH_CASE("shading/phong_texture_fog", 64, 64, 3, "phong", phong_texture_fog),
    SH_CASE("shading/ct_rough_0", 64, 64, 1, "phong cook-torrance", ct_rough_0),
    SH_CASE("shading/ct_rough_005", 64, 64, 1, "phong cook-torrance", ct_rough_005),
    SH_CASE("shading/ct_rough_025", 64, 64, 1, "phong cook-torrance", ct_rough_025),
    SH_CASE("shading/ct_rough_05", 64, 64, 1, "phong cook-torrance", ct_rough_05),
    SH_CASE("shading/ct_rough_1", 64, 64, 1, "phong cook-torrance", ct_rough_1),
    SH_CASE("shading/ct_dielectric_f0", 64, 64, 1, "phong cook-torrance", ct_dielectric_f0),
    SH_CASE("shading/ct_half_metal", 64, 64, 1, "phong cook-torrance", ct_half_metal),
    SH_CASE("shading/ct_metals", 96, 48, 1, "phong cook-torrance", ct_metals),
    SH_CASE("shading/ct_spot_attenuation", 64, 64, 2, "phong cook-torrance", ct_spot_attenuation),
    SH_CASE("shading/ct_grazing", 64, 64, 1, "phong cook-torrance", ct_grazing),
    SH_CASE("shading/ct_two_sided", 64, 48, 2, "phong cook-torrance", ct_two_sided),
    SH_CASE("shading/ct_color_material", 48, 48, 2, "phong cook-torrance", ct_color_material),
    SH_CASE("shading/ct_separate_specular", 64, 64, 1, "phong cook-torrance", ct_separate_specular),
    SH_CASE("shading/ct_big_triangles", 64, 64, 1, "phong cook-torrance", ct_big_triangles),
    SH_CASE("shading/ct_points_lines", 64, 64, 2, "phong cook-torrance", ct_points_lines),
    SH_CASE("shading/ct_perspective", 64, 64, 1, "phong cook-torrance", ct_perspective),
    SH_CASE("shading/ct_texture_fog", 64, 64, 2, "phong cook-torrance", ct_texture_fog),
    SH_CASE("shading/ct_smooth", 64, 64, 1, "cook-torrance", ct_smooth),
    SH_CASE("shading/ct_flat", 64, 64, 1, "cook-torrance", ct_flat),
    SH_CASE("shading/ct_smooth_rough_005", 64, 64, 1, "cook-torrance", ct_smooth_rough_005),
    SH_CASE("shading/ct_dlist_varray", 64, 64, 1, "cook-torrance", ct_dlist_varray),
    SH_CASE("shading/ct_rescale_normalize", 64, 64, 2, "cook-torrance", ct_rescale_normalize),
    SH_CASE("shading/ct_wave_clipped", 64, 48, 2, "phong cook-torrance", ct_wave_clipped),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
