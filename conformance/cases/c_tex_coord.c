/* c_tex_coord.c - the vertex side of texturing: coordinate generation
 * (OBJECT_LINEAR, EYE_LINEAR, SPHERE_MAP, REFLECTION_MAP, NORMAL_MAP) under
 * moving modelviews, the texture matrices (per unit stacks, which units'
 * matrices apply), multitexture (glActiveTexture, glClientActiveTexture,
 * glMultiTexCoord, per-unit enables, arrays, lists, attribute stacks) and
 * the raster position's coordinates per unit.  The vertex program's
 * results are read through the GL_3D_COLOR_TEXTURE / GL_4D_COLOR_TEXTURE
 * feedback records (texture unit 0, which the oracle's program writes in
 * feedback mode; generation and matrix apply only to a unit with a
 * complete texture) and GL_CURRENT_RASTER_TEXTURE_COORDS. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

#define FB_MARK (-12345.0f)
#define FB_SIZE 2048

static GLfloat fbbuf[FB_SIZE];

static void fb_begin(GLenum type)
{
    for (size_t i = 0; i < FB_SIZE; i++)
        fbbuf[i] = FB_MARK;
    glFeedbackBuffer(FB_SIZE, type, fbbuf);
    glRenderMode(GL_FEEDBACK);
}

/* Back to GL_RENDER: the value count and the values written plus a few. */
static void fb_end(fc_h *h, const char *label)
{
    char l[128];
    const GLint n = glRenderMode(GL_RENDER);
    snprintf(l, sizeof l, "%s count", label);
    fc_value(h, l, n);
    int len = n < 0 ? FB_SIZE : n + 4;
    if (len > FB_SIZE)
        len = FB_SIZE;
    snprintf(l, sizeof l, "%s buffer", label);
    fc_blob(h, l, fbbuf, (size_t)len * sizeof(GLfloat));
}

static void persp(void)
{
    glViewport(0, 0, 32, 32);
    fcu_frustum(-1, 1, -1, 1, 1, 10);
}

/* A complete 2x2 RGBA texture bound to GL_TEXTURE_2D of the active unit,
 * which is enabled. */
static void complete_texture(void)
{
    static const GLubyte texels[16] = {
        255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128,
    };
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
}

/* Triangles with varying normals and coordinates, one crossing the near
 * plane, a clipped line and a point. */
static void scene(void)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-0.5f, -0.5f, -2.0f);
    glNormal3f(0.3f, 0.4f, 0.8f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex3f(0.5f, -0.5f, -2.0f);
    glNormal3f(-0.6f, 0.2f, 0.7f);
    glTexCoord4f(0.5f, 1.0f, 0.25f, 2.0f);
    glVertex3f(0.0f, 0.5f, -2.5f);
    /* crosses the near plane (z = -1) and the right side */
    glNormal3f(1.0f, 1.0f, 1.0f);
    glTexCoord3f(-1.0f, 2.0f, 3.0f);
    glVertex3f(-0.5f, 0.0f, -0.5f);
    glNormal3f(0.0f, -2.0f, 0.5f);
    glTexCoord1f(4.0f);
    glVertex3f(3.0f, -0.2f, -3.0f);
    glNormal3f(0.1f, 0.1f, -1.0f);
    glTexCoord4f(0.0f, 1.0f, 2.0f, 3.0f);
    glVertex4f(0.4f, 1.6f, -8.0f, 2.0f);
    glEnd();
    glBegin(GL_LINES);
    glNormal3f(0.5f, 0.5f, 0.5f);
    glTexCoord2f(0.125f, 0.5f);
    glVertex3f(-0.9f, 0.9f, -2.0f);
    glNormal3f(-0.25f, 0.75f, 0.1f);
    glTexCoord2f(0.875f, -0.5f);
    glVertex3f(0.9f, -0.9f, -0.25f);   /* clipped by the near plane */
    glEnd();
    glBegin(GL_POINTS);
    glNormal3f(0.0f, 1.0f, 0.0f);
    glTexCoord3f(0.3f, 0.6f, 0.9f);
    glVertex3f(0.25f, -0.25f, -1.5f);
    glEnd();
}

/* The scene under a few modelviews, each in its own feedback run. */
static void moving(fc_h *h, const char *label, GLenum fbtype)
{
    char l[128];
    for (int k = 0; k < 4; k++) {
        glMatrixMode(GL_MODELVIEW);
        glPushMatrix();
        switch (k) {
        case 0: break;
        case 1: glTranslatef(0.25f, -0.125f, -0.5f); break;
        case 2: glRotatef(37.0f, 0.2f, 0.9f, 0.4f); break;
        case 3:
            glTranslatef(0.1f, 0.2f, -0.3f);
            glRotatef(-21.0f, 1.0f, 0.0f, 0.5f);
            glScalef(1.5f, 0.75f, 1.25f);
            break;
        }
        fb_begin(fbtype);
        scene();
        snprintf(l, sizeof l, "%s mv%d", label, k);
        fb_end(h, l);
        glPopMatrix();
    }
}

static void gen_all(GLenum mode)
{
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, mode);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, mode);
    if (mode != GL_SPHERE_MAP)
        glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, mode);
    if (mode == GL_OBJECT_LINEAR || mode == GL_EYE_LINEAR)
        glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, mode);
}

static void gen_enable(unsigned mask, bool on)
{
    static const GLenum caps[4] = { GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                                    GL_TEXTURE_GEN_Q };
    for (int c = 0; c < 4; c++)
        if (mask & (1u << c)) {
            if (on)
                glEnable(caps[c]);
            else
                glDisable(caps[c]);
        }
}

static const GLfloat planes[4][4] = {
    { 1.0f, 0.5f, -0.25f, 0.125f },
    { -0.75f, 2.0f, 0.5f, 1.0f },
    { 0.3f, -0.2f, 1.5f, -2.0f },
    { 0.0f, 0.25f, -0.5f, 3.0f },
};

static void set_planes(GLenum pname)
{
    static const GLenum coords[4] = { GL_S, GL_T, GL_R, GL_Q };
    for (int c = 0; c < 4; c++)
        glTexGenfv(coords[c], pname, planes[c]);
}

/* OBJECT_LINEAR on every component: DP4 of the object position with the
 * planes, whatever the modelview; then with the texture disabled (no
 * generation: the vertex's coordinate), then generation enabled on one
 * component at a time. */
static void gen_object_linear(fc_h *h)
{
    persp();
    complete_texture();
    gen_all(GL_OBJECT_LINEAR);
    set_planes(GL_OBJECT_PLANE);
    gen_enable(0xf, true);
    moving(h, "stqr", GL_4D_COLOR_TEXTURE);
    glDisable(GL_TEXTURE_2D);
    moving(h, "texture disabled", GL_4D_COLOR_TEXTURE);
    glEnable(GL_TEXTURE_2D);
    char l[64];
    for (unsigned c = 0; c < 4; c++) {
        gen_enable(0xf, false);
        gen_enable(1u << c, true);
        snprintf(l, sizeof l, "only %u", c);
        fb_begin(GL_3D_COLOR_TEXTURE);
        scene();
        fb_end(h, l);
    }
    /* the default planes (s = x, t = y) */
    gen_enable(0xf, true);
    static const GLfloat s[4] = { 1, 0, 0, 0 }, t[4] = { 0, 1, 0, 0 }, z[4] = { 0, 0, 0, 0 };
    glTexGenfv(GL_S, GL_OBJECT_PLANE, s);
    glTexGenfv(GL_T, GL_OBJECT_PLANE, t);
    glTexGenfv(GL_R, GL_OBJECT_PLANE, z);
    glTexGenfv(GL_Q, GL_OBJECT_PLANE, z);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "default planes");
}

/* EYE_LINEAR: planes given under one modelview (transformed by its inverse
 * then), the scene drawn under others; with lighting off and on (the eye
 * coordinates put lighting in eye space) */
static void gen_eye_linear(fc_h *h)
{
    persp();
    complete_texture();
    gen_all(GL_EYE_LINEAR);
    glPushMatrix();
    glTranslatef(0.5f, -1.0f, 0.25f);
    glRotatef(48.0f, 0.0f, 0.0f, 1.0f);
    glScalef(2.0f, 1.0f, 0.5f);
    set_planes(GL_EYE_PLANE);
    glPopMatrix();
    gen_enable(0xf, true);
    moving(h, "unlit", GL_4D_COLOR_TEXTURE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    moving(h, "lit", GL_4D_COLOR_TEXTURE);
    glDisable(GL_LIGHTING);
    /* mixed with object linear on T and Q */
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    moving(h, "mixed", GL_3D_COLOR_TEXTURE);
}

/* SPHERE_MAP on S and T: the eye normal (with GL_NORMALIZE, with
 * GL_RESCALE_NORMAL, raw) and the normalised eye position; R and Q are the
 * vertex's. */
static void gen_sphere_map(fc_h *h)
{
    persp();
    complete_texture();
    gen_all(GL_SPHERE_MAP);
    gen_enable(0x3, true);
    moving(h, "raw", GL_4D_COLOR_TEXTURE);
    glEnable(GL_NORMALIZE);
    moving(h, "normalize", GL_4D_COLOR_TEXTURE);
    glDisable(GL_NORMALIZE);
    glEnable(GL_RESCALE_NORMAL);
    moving(h, "rescale", GL_4D_COLOR_TEXTURE);
    glDisable(GL_RESCALE_NORMAL);
    /* lit: directional light, object space would do without texgen */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    moving(h, "lit", GL_4D_COLOR_TEXTURE);
    glDisable(GL_LIGHTING);
    /* sphere on S only, T from the vertex */
    gen_enable(0x2, false);
    moving(h, "s only", GL_3D_COLOR_TEXTURE);
}

/* REFLECTION_MAP and NORMAL_MAP on S, T, R (GL 1.3 cube map modes; the
 * vertex program computes them for any target). */
static void gen_reflection_normal(fc_h *h)
{
    persp();
    complete_texture();
    gen_all(GL_REFLECTION_MAP);
    gen_enable(0x7, true);
    moving(h, "reflection", GL_4D_COLOR_TEXTURE);
    glEnable(GL_NORMALIZE);
    moving(h, "reflection normalize", GL_4D_COLOR_TEXTURE);
    glDisable(GL_NORMALIZE);
    gen_all(GL_NORMAL_MAP);
    moving(h, "normal", GL_4D_COLOR_TEXTURE);
    glEnable(GL_RESCALE_NORMAL);
    moving(h, "normal rescale", GL_4D_COLOR_TEXTURE);
    glDisable(GL_RESCALE_NORMAL);
    /* one of each: S sphere, T reflection, R normal, Q eye linear */
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    set_planes(GL_EYE_PLANE);
    gen_enable(0xf, true);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    moving(h, "one of each lit", GL_4D_COLOR_TEXTURE);
}

/* Generation followed by the texture matrix, and the matrix alone; an
 * identity-valued matrix (glScale(1,1,1), glLoadIdentity after a rotation)
 * and a perspective one. */
static void matrix_feedback(fc_h *h)
{
    persp();
    complete_texture();
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.5f, 0.25f, -1.0f);
    glRotatef(30.0f, 0.0f, 0.3f, 1.0f);
    glScalef(2.0f, 3.0f, 4.0f);
    glMatrixMode(GL_MODELVIEW);
    moving(h, "matrix", GL_4D_COLOR_TEXTURE);
    gen_all(GL_OBJECT_LINEAR);
    set_planes(GL_OBJECT_PLANE);
    gen_enable(0x5, true);
    moving(h, "gen then matrix", GL_4D_COLOR_TEXTURE);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    moving(h, "sphere then matrix", GL_4D_COLOR_TEXTURE);
    gen_enable(0xf, false);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glScalef(1.0f, 1.0f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "scale 1");
    glMatrixMode(GL_TEXTURE);
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "identity after rotate");
    static const GLfloat p[16] = { 1, 0, 0, 0.5f, 0, 2, 0, 0.25f, 0, 0, 1, -1, 0.5f, 0, 0, 2 };
    glMatrixMode(GL_TEXTURE);
    glLoadMatrixf(p);
    glMatrixMode(GL_MODELVIEW);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "general");
    /* the matrix of a unit without a complete texture does not apply */
    glDisable(GL_TEXTURE_2D);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "texture disabled");
}

/* Which units' matrices apply after a change of another unit's matrix
 * alone: Mesa rebuilds the mask from the changed matrices only
 * (texstate.c:_mesa_update_texture_matrices), until the texture state is
 * validated again. */
static void matrix_other_unit(fc_h *h)
{
    persp();
    for (int u = 1; u >= 0; u--) {
        glActiveTexture(GL_TEXTURE0 + u);
        complete_texture();
    }
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.5f, 0.5f, 0.0f);
    glMatrixMode(GL_MODELVIEW);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "unit 0 matrix");
    glActiveTexture(GL_TEXTURE1);
    glMatrixMode(GL_TEXTURE);
    glScalef(2.0f, 2.0f, 2.0f);
    glMatrixMode(GL_MODELVIEW);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "after unit 1 matrix");
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "again");
    /* a texture state change revalidates */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "after texenv");
    glActiveTexture(GL_TEXTURE0);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "after active texture");
    /* unit 0 matrix changed while its texture is disabled, then enabled */
    glDisable(GL_TEXTURE_2D);
    glMatrixMode(GL_TEXTURE);
    glRotatef(45.0f, 0.0f, 0.0f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "disabled");
    glEnable(GL_TEXTURE_2D);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "enabled again");
    /* both changed before one draw */
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.0f, 1.0f, 0.0f);
    glActiveTexture(GL_TEXTURE1);
    glTranslatef(1.0f, 0.0f, 0.0f);
    glMatrixMode(GL_MODELVIEW);
    glActiveTexture(GL_TEXTURE0);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "both");
    /* glLoadIdentity leaves its matrix clean: after it alone no matrix
     * is dirty, and the mask empties */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "revalidated");
    glActiveTexture(GL_TEXTURE1);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glActiveTexture(GL_TEXTURE0);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "unit 1 load identity");
    /* glPushMatrix analyses the top: a push, a change and a pop back to
     * the same matrix */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glMatrixMode(GL_TEXTURE);
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, 1.0f);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    fb_begin(GL_4D_COLOR_TEXTURE);
    scene();
    fb_end(h, "push translate pop");
}

static void raster_tc(fc_h *h, const char *label)
{
    char l[128];
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    fc_get_boolean(h, "valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
    for (int u = 0; u < 8; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        snprintf(l, sizeof l, "%s unit %d", label, u);
        fc_get_float(h, l, GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
    }
    glActiveTexture((GLenum)active);
}

/* glRasterPos: every unit's coordinate generated where the unit enables
 * generation (texture enabled or not), through its texture matrix. */
static void gen_rasterpos(fc_h *h)
{
    persp();
    static const GLenum modes[8] = { GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP,
                                      GL_REFLECTION_MAP, GL_NORMAL_MAP, GL_OBJECT_LINEAR,
                                      GL_EYE_LINEAR, GL_SPHERE_MAP };
    glPushMatrix();
    glRotatef(20.0f, 1.0f, 1.0f, 0.0f);
    for (int u = 0; u < 8; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        gen_all(modes[u]);
        set_planes(GL_OBJECT_PLANE);
        set_planes(GL_EYE_PLANE);
        gen_enable(u == 5 ? 0x5u : 0xfu, true);
        if (u & 1) {
            glMatrixMode(GL_TEXTURE);
            glTranslatef(0.125f * (float)u, 0.5f, -0.25f);
            glScalef(1.0f, 2.0f, (float)u);
            glMatrixMode(GL_MODELVIEW);
        }
        glMultiTexCoord4f(GL_TEXTURE0 + u, 0.1f * (float)u, 0.2f, 0.3f, 1.0f + (float)u);
    }
    glPopMatrix();
    glActiveTexture(GL_TEXTURE0);
    glNormal3f(0.2f, -0.4f, 0.9f);
    glRasterPos3f(0.25f, -0.5f, -2.0f);
    raster_tc(h, "unlit");
    glTranslatef(0.1f, 0.2f, -0.5f);
    glRotatef(-35.0f, 0.3f, 0.2f, 1.0f);
    glRasterPos4f(0.5f, 0.25f, -1.5f, 1.25f);
    raster_tc(h, "moved");
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glRasterPos3f(-0.25f, 0.125f, -2.5f);
    raster_tc(h, "lit");
    /* a texture on unit 2 puts its sphere map in _NeedEyeCoords */
    glActiveTexture(GL_TEXTURE2);
    complete_texture();
    glRasterPos3f(-0.25f, 0.125f, -2.5f);
    raster_tc(h, "lit eye coords");
    glDisable(GL_LIGHTING);
    glScalef(2.0f, 1.0f, 1.0f);
    glRasterPos3f(0.3f, -0.1f, -3.0f);
    raster_tc(h, "scaled");
    /* a zero normal */
    glNormal3f(0.0f, 0.0f, 0.0f);
    glRasterPos3f(0.3f, -0.1f, -3.0f);
    raster_tc(h, "zero normal");
    /* clipped: the coordinates keep their last values */
    glRasterPos3f(0.0f, 0.0f, 5.0f);
    raster_tc(h, "clipped");
}

static void stack_state(fc_h *h, const char *label)
{
    char l[128];
    snprintf(l, sizeof l, "%s depth", label);
    fc_get_integer(h, l, GL_TEXTURE_STACK_DEPTH, 1);
    snprintf(l, sizeof l, "%s matrix", label);
    fc_get_float(h, l, GL_TEXTURE_MATRIX, 16);
    snprintf(l, sizeof l, "%s active", label);
    fc_get_integer(h, l, GL_ACTIVE_TEXTURE, 1);
}

/* Per-unit texture matrix stacks: glMatrixMode(GL_TEXTURE) follows the
 * active unit, also when the unit changes in that mode; push/pop limits per
 * unit; the queries read the active unit's stack. */
static void matrix_stack(fc_h *h)
{
    char l[96];
    fc_get_integer(h, "max depth", GL_MAX_TEXTURE_STACK_DEPTH, 1);
    glMatrixMode(GL_TEXTURE);
    for (int u = 0; u < 8; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        for (int k = 0; k < u; k++) {
            glPushMatrix();
            glTranslatef((float)k, (float)u, 0.5f);
        }
        glRotatef(10.0f * (float)u, 0.0f, 0.0f, 1.0f);
    }
    for (int u = 7; u >= 0; u--) {
        glActiveTexture(GL_TEXTURE0 + u);
        snprintf(l, sizeof l, "unit %d", u);
        stack_state(h, l);
    }
    /* overflow of unit 3's stack only */
    glActiveTexture(GL_TEXTURE3);
    for (int k = 0; k < 12; k++) {
        glPushMatrix();
        snprintf(l, sizeof l, "push %d", k);
        fc_error(h, l);
    }
    stack_state(h, "unit 3 full");
    glActiveTexture(GL_TEXTURE4);
    stack_state(h, "unit 4 after");
    glActiveTexture(GL_TEXTURE0);
    glPopMatrix();
    fc_error(h, "pop unit 0 empty");
    glMatrixMode(GL_MODELVIEW);
    glActiveTexture(GL_TEXTURE5);
    /* modelview mode: the texture queries still read the active unit */
    stack_state(h, "modelview mode unit 5");
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glPopMatrix();
    stack_state(h, "unit 5 popped");
    /* glActiveTexture inside glBegin/glEnd, a matrix op between them */
    glBegin(GL_POINTS);
    glActiveTexture(GL_TEXTURE1);
    fc_error(h, "active texture in begin");
    glEnd();
    stack_state(h, "after begin");
    glMatrixMode(GL_MODELVIEW);
}

static void cur_all(fc_h *h, const char *label)
{
    char l[128];
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (int u = 0; u < 8; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        snprintf(l, sizeof l, "%s unit %d", label, u);
        fc_get_float(h, l, GL_CURRENT_TEXTURE_COORDS, 4);
    }
    glActiveTexture((GLenum)active);
}

/* Every glMultiTexCoord variant (and the ARB aliases), the unit taken from
 * the target's low three bits, the current value of each unit; inside
 * glBegin/glEnd; glPushAttrib(GL_CURRENT_BIT). */
static void multi_current(fc_h *h)
{
    static const GLshort sv[4] = { -3, 7, 32767, -32768 };
    static const GLint iv[4] = { 2147483647, -5, 9, 65536 };
    static const GLfloat fv[4] = { 0.25f, -1.5f, 1e20f, -0.0f };
    static const GLdouble dv[4] = { 1.0 / 3.0, 1e-40, -2.5e38, 7.125 };
    cur_all(h, "initial");
    glMultiTexCoord1s(GL_TEXTURE1, 5);
    glMultiTexCoord2s(GL_TEXTURE2, -2, 3);
    glMultiTexCoord3s(GL_TEXTURE3, 4, 5, 6);
    glMultiTexCoord4s(GL_TEXTURE4, 7, 8, 9, 10);
    glMultiTexCoord1sv(GL_TEXTURE5, sv);
    glMultiTexCoord2sv(GL_TEXTURE6, sv);
    glMultiTexCoord3sv(GL_TEXTURE7, sv);
    glMultiTexCoord4sv(GL_TEXTURE0, sv);
    cur_all(h, "s");
    glMultiTexCoord1i(GL_TEXTURE2, -7);
    glMultiTexCoord2i(GL_TEXTURE3, 16777217, 3);
    glMultiTexCoord3i(GL_TEXTURE4, 1, 2, 3);
    glMultiTexCoord4i(GL_TEXTURE5, 4, 3, 2, 1);
    glMultiTexCoord1iv(GL_TEXTURE6, iv);
    glMultiTexCoord2iv(GL_TEXTURE7, iv);
    glMultiTexCoord3iv(GL_TEXTURE0, iv);
    glMultiTexCoord4iv(GL_TEXTURE1, iv);
    cur_all(h, "i");
    glMultiTexCoord1f(GL_TEXTURE3, 0.5f);
    glMultiTexCoord2f(GL_TEXTURE4, 0.5f, -0.75f);
    glMultiTexCoord3f(GL_TEXTURE5, 1.0f, 2.0f, NAN);
    glMultiTexCoord4f(GL_TEXTURE6, 1.0f, 2.0f, 3.0f, 0.0f);
    glMultiTexCoord1fv(GL_TEXTURE7, fv);
    glMultiTexCoord2fv(GL_TEXTURE0, fv);
    glMultiTexCoord3fv(GL_TEXTURE1, fv);
    glMultiTexCoord4fv(GL_TEXTURE2, fv);
    cur_all(h, "f");
    glMultiTexCoord1d(GL_TEXTURE4, 0.1);
    glMultiTexCoord2d(GL_TEXTURE5, 0.1, 1e300);
    glMultiTexCoord3d(GL_TEXTURE6, -0.1, 2.0, 3.0);
    glMultiTexCoord4d(GL_TEXTURE7, 1, 2, 3, 4);
    glMultiTexCoord1dv(GL_TEXTURE0, dv);
    glMultiTexCoord2dv(GL_TEXTURE1, dv);
    glMultiTexCoord3dv(GL_TEXTURE2, dv);
    glMultiTexCoord4dv(GL_TEXTURE3, dv);
    cur_all(h, "d");
    glMultiTexCoord4fARB(GL_TEXTURE1, 9.0f, 8.0f, 7.0f, 6.0f);
    glMultiTexCoord2dARB(GL_TEXTURE2, 0.5, 0.25);
    glMultiTexCoord3ivARB(GL_TEXTURE3, iv);
    glMultiTexCoord1sARB(GL_TEXTURE4, 3);
    cur_all(h, "arb");
    /* targets outside the units: the low three bits pick one, no error */
    glMultiTexCoord2f(GL_TEXTURE0 + 8, 11.0f, 12.0f);
    fc_error(h, "texture8");
    glMultiTexCoord2f(GL_TEXTURE0 + 13, 13.0f, 14.0f);
    glMultiTexCoord2f(0, 15.0f, 16.0f);
    glMultiTexCoord2f(GL_TEXTURE0 - 1, 17.0f, 18.0f);
    fc_error(h, "bad targets");
    cur_all(h, "bad targets");
    /* glTexCoord is unit 0's, whatever the active unit */
    glActiveTexture(GL_TEXTURE3);
    glTexCoord2f(-1.0f, -2.0f);
    cur_all(h, "texcoord with unit 3 active");
    /* inside glBegin/glEnd, vertices in between */
    glBegin(GL_POINTS);
    glMultiTexCoord4f(GL_TEXTURE5, 0.5f, 0.5f, 0.5f, 0.5f);
    glVertex2f(0.0f, 0.0f);
    glMultiTexCoord1f(GL_TEXTURE5, 2.0f);
    glMultiTexCoord3f(GL_TEXTURE6, 2.0f, 3.0f, 4.0f);
    glVertex2f(0.0f, 0.0f);
    glEnd();
    cur_all(h, "after begin/end");
    /* the current bit saves and restores every unit */
    glPushAttrib(GL_CURRENT_BIT);
    for (int u = 0; u < 8; u++)
        glMultiTexCoord4f(GL_TEXTURE0 + u, (float)u, -1.0f, 0.0f, 1.0f);
    cur_all(h, "changed");
    glPopAttrib();
    cur_all(h, "popped");
    glActiveTexture(GL_TEXTURE0);
}

/* glActiveTexture / glClientActiveTexture errors and limits */
static void multi_errors(fc_h *h)
{
    fc_get_integer(h, "max units", GL_MAX_TEXTURE_UNITS, 1);
    /* (GL_MAX_TEXTURE_COORDS is GL 2.0's: honesty/get_pnames) */
    fc_get_integer(h, "active", GL_ACTIVE_TEXTURE, 1);
    fc_get_integer(h, "client active", GL_CLIENT_ACTIVE_TEXTURE, 1);
    glActiveTexture(GL_TEXTURE7);
    fc_error(h, "active 7");
    fc_get_integer(h, "active 7", GL_ACTIVE_TEXTURE, 1);
    glActiveTexture(GL_TEXTURE0 + 192);
    fc_error(h, "active 192");
    glActiveTexture(GL_TEXTURE0 - 1);
    fc_error(h, "active -1");
    glActiveTexture(0);
    fc_error(h, "active 0");
    fc_get_integer(h, "active after errors", GL_ACTIVE_TEXTURE, 1);
    glActiveTextureARB(GL_TEXTURE2);
    fc_get_integer(h, "active arb", GL_ACTIVE_TEXTURE, 1);
    glClientActiveTexture(GL_TEXTURE7);
    fc_error(h, "client 7");
    glClientActiveTexture(GL_TEXTURE0 + 8);
    fc_error(h, "client 8");
    glClientActiveTexture(GL_TEXTURE0 - 1);
    fc_error(h, "client -1");
    fc_get_integer(h, "client after errors", GL_CLIENT_ACTIVE_TEXTURE, 1);
    glClientActiveTextureARB(GL_TEXTURE5);
    fc_get_integer(h, "client arb", GL_CLIENT_ACTIVE_TEXTURE, 1);
    /* inside glBegin/glEnd: glActiveTexture is refused, the client unit
     * is not */
    glBegin(GL_POINTS);
    glActiveTexture(GL_TEXTURE4);
    glEnd();
    fc_error(h, "active in begin");
    glBegin(GL_POINTS);
    glClientActiveTexture(GL_TEXTURE4);
    glEnd();
    fc_error(h, "client in begin");
    fc_get_integer(h, "active after begin", GL_ACTIVE_TEXTURE, 1);
    fc_get_integer(h, "client after begin", GL_CLIENT_ACTIVE_TEXTURE, 1);
    /* the same unit again: no change, no error */
    glActiveTexture(GL_TEXTURE2);
    fc_error(h, "same unit");
}

static void enables(fc_h *h, const char *label)
{
    static const GLenum caps[8] = { GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D,
                                    GL_TEXTURE_CUBE_MAP, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T,
                                    GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q };
    char l[128];
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (int u = 0; u < 8; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        for (int c = 0; c < 8; c++) {
            snprintf(l, sizeof l, "%s unit %d cap %x", label, u, caps[c]);
            if (c & 1)
                fc_is_enabled(h, l, caps[c]);
            else
                fc_get_boolean(h, l, caps[c], 1);
        }
    }
    glActiveTexture((GLenum)active);
    snprintf(l, sizeof l, "%s active", label);
    fc_get_integer(h, l, GL_ACTIVE_TEXTURE, 1);
}

static void set_unit_enables(int seed)
{
    static const GLenum caps[8] = { GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D,
                                    GL_TEXTURE_CUBE_MAP, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T,
                                    GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q };
    for (int u = 0; u < 8; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        for (int c = 0; c < 8; c++) {
            if (((u * 7 + c * 3 + seed) % 5) < 2)
                glEnable(caps[c]);
            else
                glDisable(caps[c]);
        }
    }
}

/* Per-unit enables, glIsEnabled and glGet per active unit, the enable and
 * texture attribute groups saving every unit, the texture group restoring
 * the active unit (and the GL_TEXTURE matrix stack it selects). */
static void multi_enables(fc_h *h)
{
    enables(h, "initial");
    set_unit_enables(0);
    glActiveTexture(GL_TEXTURE3);
    enables(h, "set");
    glPushAttrib(GL_ENABLE_BIT);
    set_unit_enables(2);
    glActiveTexture(GL_TEXTURE6);
    enables(h, "changed under enable bit");
    glPopAttrib();
    enables(h, "enable bit popped");
    glPushAttrib(GL_TEXTURE_BIT);
    set_unit_enables(4);
    glActiveTexture(GL_TEXTURE1);
    enables(h, "changed under texture bit");
    glPopAttrib();
    enables(h, "texture bit popped");
    /* the texture bit restores the active unit, and the matrix stack */
    glMatrixMode(GL_TEXTURE);
    glActiveTexture(GL_TEXTURE2);
    glPushAttrib(GL_TEXTURE_BIT);
    glActiveTexture(GL_TEXTURE5);
    glTranslatef(1.0f, 2.0f, 3.0f);
    glPopAttrib();
    glTranslatef(4.0f, 5.0f, 6.0f);
    stack_state(h, "unit 2 after pop");
    glActiveTexture(GL_TEXTURE5);
    stack_state(h, "unit 5 after pop");
    /* the transform bit restores GL_TEXTURE mode on the active unit */
    glPushAttrib(GL_TRANSFORM_BIT);
    glMatrixMode(GL_MODELVIEW);
    glActiveTexture(GL_TEXTURE6);
    glPopAttrib();
    glScalef(2.0f, 2.0f, 2.0f);
    stack_state(h, "unit 6 after transform pop");
    glMatrixMode(GL_MODELVIEW);
    /* both bits together, enables changed on several units */
    glPushAttrib(GL_ENABLE_BIT | GL_TEXTURE_BIT);
    set_unit_enables(1);
    glPopAttrib();
    enables(h, "both popped");
    /* the texture bit keeps every unit's generation state */
    glActiveTexture(GL_TEXTURE3);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glPushAttrib(GL_TEXTURE_BIT);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glActiveTexture(GL_TEXTURE5);
    static const GLfloat op[4] = { 1.5f, -2.0f, 0.25f, 4.0f };
    glTexGenfv(GL_Q, GL_OBJECT_PLANE, op);
    glPopAttrib();
    for (int u = 3; u <= 5; u += 2) {
        glActiveTexture(GL_TEXTURE0 + u);
        GLint mode = -1;
        GLfloat plane[4] = { -1, -1, -1, -1 };
        glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode);
        glGetTexGenfv(GL_Q, GL_OBJECT_PLANE, plane);
        fc_value(h, u == 3 ? "unit 3 s mode" : "unit 5 s mode", mode);
        fc_blob(h, u == 3 ? "unit 3 q plane" : "unit 5 q plane", plane, sizeof plane);
    }
    fc_get_integer(h, "active after gen pop", GL_ACTIVE_TEXTURE, 1);
    /* bad caps for the active unit */
    glEnable(GL_TEXTURE_3D + 1);
    fc_error(h, "3d + 1");
    glIsEnabled(GL_TEXTURE_GEN_Q + 1);
    fc_error(h, "gen q + 1");
}

static const GLfloat arr_pos[4][3] = {
    { -0.6f, -0.6f, -2.0f }, { 0.6f, -0.6f, -2.0f },
    { 0.6f, 0.6f, -0.5f }, { -0.6f, 0.6f, -3.0f },
};

static const void *known_ptrs[8];

/* which of known_ptrs p is (-1: none) */
static int ptr_index(const void *p)
{
    for (int i = 0; i < 8; i++)
        if (known_ptrs[i] == p)
            return i;
    return -1;
}

static void array_state(fc_h *h, const char *label)
{
    char l[128];
    GLint client = 0;
    glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &client);
    for (int u = 0; u < 8; u++) {
        glClientActiveTexture(GL_TEXTURE0 + u);
        snprintf(l, sizeof l, "%s unit %d enabled", label, u);
        fc_is_enabled(h, l, GL_TEXTURE_COORD_ARRAY);
        snprintf(l, sizeof l, "%s unit %d size", label, u);
        fc_get_integer(h, l, GL_TEXTURE_COORD_ARRAY_SIZE, 1);
        snprintf(l, sizeof l, "%s unit %d type", label, u);
        fc_get_integer(h, l, GL_TEXTURE_COORD_ARRAY_TYPE, 1);
        snprintf(l, sizeof l, "%s unit %d stride", label, u);
        fc_get_integer(h, l, GL_TEXTURE_COORD_ARRAY_STRIDE, 1);
        GLvoid *p = NULL;
        glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &p);
        snprintf(l, sizeof l, "%s unit %d pointer", label, u);
        fc_value(h, l, ptr_index(p));
    }
    glClientActiveTexture((GLenum)client);
}

/* Per-unit coordinate arrays: pointers, enables and queries follow the
 * client active unit; glArrayElement sets every enabled unit's current
 * coordinate; unit 0's array feeds the feedback records;
 * glInterleavedArrays sets the client unit's; glPushClientAttrib. */
static void multi_arrays(fc_h *h)
{
    static const GLfloat tc0[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
    static const GLshort tc3[4][3] = { { 1, 2, 3 }, { -4, 5, 6 }, { 7, -8, 9 }, { 10, 11, -12 } };
    static const GLdouble tc7[4][4] = { { 0.1, 0.2, 0.3, 0.4 }, { 0.5, 0.6, 0.7, 0.8 },
                                        { 0.9, 1.0, 1.1, 1.2 }, { 1.3, 1.4, 1.5, 1.6 } };
    static const GLfloat inter[4][5] = { { 0.5f, 0.25f, -0.5f, -0.5f, -2.0f },
                                         { 0.75f, 0.5f, 0.5f, -0.5f, -2.0f },
                                         { 1.0f, 0.75f, 0.5f, 0.5f, -2.0f },
                                         { 1.25f, 1.0f, -0.5f, 0.5f, -2.0f } };
    known_ptrs[1] = arr_pos;
    known_ptrs[2] = tc0;
    known_ptrs[3] = tc3;
    known_ptrs[4] = tc7;
    known_ptrs[5] = inter;
    persp();
    array_state(h, "initial");
    glVertexPointer(3, GL_FLOAT, 0, arr_pos);
    glEnableClientState(GL_VERTEX_ARRAY);
    glClientActiveTexture(GL_TEXTURE3);
    glTexCoordPointer(3, GL_SHORT, 0, tc3);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE7);
    glTexCoordPointer(4, GL_DOUBLE, 32, tc7);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    array_state(h, "units 3 and 7");
    /* feedback: unit 0 has no array, its current value */
    fb_begin(GL_4D_COLOR_TEXTURE);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    fb_end(h, "no unit 0 array");
    glTexCoordPointer(2, GL_FLOAT, 0, tc0);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    static const GLubyte idx[6] = { 0, 1, 2, 0, 2, 3 };
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);
    fb_end(h, "unit 0 array");
    /* glArrayElement sets each unit's current value */
    glBegin(GL_POINTS);
    glArrayElement(2);
    glEnd();
    cur_all(h, "after array element");
    /* the same through the texture matrix and generation of unit 0 */
    complete_texture();
    glMatrixMode(GL_TEXTURE);
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glEnable(GL_TEXTURE_GEN_T);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    glBegin(GL_TRIANGLES);
    glArrayElement(0);
    glArrayElement(1);
    glArrayElement(3);
    glEnd();
    fb_end(h, "unit 0 generated");
    /* the client attribute stack saves every unit's array and the client
     * unit */
    glClientActiveTexture(GL_TEXTURE3);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE5);
    glTexCoordPointer(1, GL_INT, 12, arr_pos);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    array_state(h, "changed");
    glPopClientAttrib();
    fc_get_integer(h, "client unit popped", GL_CLIENT_ACTIVE_TEXTURE, 1);
    array_state(h, "popped");
    /* glInterleavedArrays sets the client unit's array only */
    glClientActiveTexture(GL_TEXTURE1);
    glInterleavedArrays(GL_T2F_V3F, 0, inter);
    array_state(h, "interleaved unit 1");
    glClientActiveTexture(GL_TEXTURE0);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glDrawArrays(GL_QUADS, 0, 4);
    fb_end(h, "interleaved");
    /* glEnableClientState of the coordinate array follows the client
     * unit, glEnable too */
    glClientActiveTexture(GL_TEXTURE6);
    glEnable(GL_TEXTURE_COORD_ARRAY);
    array_state(h, "enable 6");
    glClientActiveTexture(GL_TEXTURE0);
}

/* glActiveTexture and glMultiTexCoord in display lists (glClientActiveTexture
 * executes at once) */
static void multi_dlist(fc_h *h)
{
    persp();
    glNewList(1, GL_COMPILE);
    glActiveTexture(GL_TEXTURE4);
    glMultiTexCoord2f(GL_TEXTURE4, 0.5f, 0.75f);
    glMultiTexCoord3f(GL_TEXTURE1, 1.0f, 2.0f, 3.0f);
    glClientActiveTexture(GL_TEXTURE2);
    glEnable(GL_TEXTURE_GEN_S);
    glEndList();
    fc_get_integer(h, "active after compile", GL_ACTIVE_TEXTURE, 1);
    fc_get_integer(h, "client after compile", GL_CLIENT_ACTIVE_TEXTURE, 1);
    cur_all(h, "after compile");
    glCallList(1);
    fc_get_integer(h, "active after call", GL_ACTIVE_TEXTURE, 1);
    cur_all(h, "after call");
    enables(h, "after call");
    glActiveTexture(GL_TEXTURE0);
    /* a list with vertices: multitexture coordinates in the vertex list */
    complete_texture();
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_TRIANGLES);
    glMultiTexCoord2f(GL_TEXTURE0, 0.25f, 0.5f);
    glMultiTexCoord4f(GL_TEXTURE3, 1.0f, 2.0f, 3.0f, 4.0f);
    glVertex3f(-0.5f, -0.5f, -2.0f);
    glMultiTexCoord1f(GL_TEXTURE0, 0.75f);
    glVertex3f(0.5f, -0.5f, -2.0f);
    glMultiTexCoord3f(GL_TEXTURE2, 5.0f, 6.0f, 7.0f);
    glTexCoord2f(-1.0f, 1.0f);
    glVertex3f(0.0f, 0.5f, -2.0f);
    glEnd();
    glEndList();
    cur_all(h, "after list 2");
    fb_begin(GL_4D_COLOR_TEXTURE);
    glCallList(2);
    fb_end(h, "list 2");
    glMatrixMode(GL_TEXTURE);
    glScalef(2.0f, 4.0f, 8.0f);
    glMatrixMode(GL_MODELVIEW);
    fb_begin(GL_4D_COLOR_TEXTURE);
    glCallList(2);
    fb_end(h, "list 2 matrix");
    /* glActiveTexture of a bad unit replays its error */
    glNewList(3, GL_COMPILE);
    glActiveTexture(GL_TEXTURE0 + 200);
    glEndList();
    fc_error(h, "compile bad unit");
    glCallList(3);
    fc_error(h, "call bad unit");
    glDeleteLists(1, 3);
}

/* The immediate-mode vertex format with other units' coordinates joining
 * mid-primitive (format upgrades, in attribute order), read back through
 * unit 0's feedback coordinate and the current values. */
static void multi_upgrade(fc_h *h)
{
    persp();
    fb_begin(GL_4D_COLOR_TEXTURE);
    glBegin(GL_TRIANGLES);
    glTexCoord2f(0.5f, 0.5f);
    glVertex3f(-0.5f, -0.5f, -2.0f);
    glMultiTexCoord3f(GL_TEXTURE5, 1.0f, 2.0f, 3.0f);
    glVertex3f(0.5f, -0.5f, -2.0f);
    glMultiTexCoord4f(GL_TEXTURE2, 4.0f, 3.0f, 2.0f, 1.0f);
    glTexCoord4f(0.25f, 0.75f, 1.0f, 2.0f);
    glVertex3f(0.0f, 0.5f, -2.0f);
    glMultiTexCoord1f(GL_TEXTURE5, 9.0f);
    glVertex3f(-0.5f, 0.5f, -2.0f);
    glTexCoord1f(3.0f);
    glVertex3f(0.5f, 0.5f, -2.0f);
    glMultiTexCoord2f(GL_TEXTURE7, 8.0f, 7.0f);
    glVertex3f(0.5f, 0.0f, -1.5f);
    glEnd();
    fb_end(h, "upgrades");
    cur_all(h, "after");
}

/* ---- rendered cases (sampling and environment from raster/r_tex.c) ---- */

/* A w x h RGBA image of coloured cells (each cell a distinct colour, with
 * a gradient inside so that filtering shows) bound to GL_TEXTURE_2D of the
 * active unit, with the given filter and wrap; the unit's 2D target is
 * enabled. */
static void cell_texture(int w, int h, unsigned seed, GLenum filter, GLenum wrap)
{
    static GLubyte img[64 * 64 * 4];
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            GLubyte *p = img + 4 * (y * w + x);
            const unsigned c = (unsigned)((x * 4) / w + 4 * ((y * 4) / h)) + seed;
            p[0] = (GLubyte)((c * 67u + (unsigned)x * 9u) & 255u);
            p[1] = (GLubyte)((c * 151u + (unsigned)y * 13u) & 255u);
            p[2] = (GLubyte)((c * 29u + 96u) & 255u);
            p[3] = (GLubyte)(255u - ((c * 37u) & 127u));
        }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
    glEnable(GL_TEXTURE_2D);
}

/* A sphere of stacks x slices quads with unit normals, radius r at z0 */
static void sphere(float r, float z0, int stacks, int slices)
{
    for (int i = 0; i < stacks; i++) {
        const float a0 = 3.14159265f * ((float)i / (float)stacks - 0.5f);
        const float a1 = 3.14159265f * ((float)(i + 1) / (float)stacks - 0.5f);
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= slices; j++) {
            const float b = 2.0f * 3.14159265f * (float)j / (float)slices;
            const float c0 = cosf(a0), c1 = cosf(a1);
            glNormal3f(c1 * cosf(b), sinf(a1), c1 * sinf(b));
            glVertex3f(r * c1 * cosf(b), r * sinf(a1), z0 + r * c1 * sinf(b));
            glNormal3f(c0 * cosf(b), sinf(a0), c0 * sinf(b));
            glVertex3f(r * c0 * cosf(b), r * sinf(a0), z0 + r * c0 * sinf(b));
        }
        glEnd();
    }
}

/* A tilted grid of quads (normals bent towards the edges), drawn with the
 * current state; its texture coordinates come from generation or are
 * glTexCoord (s, t) = position. */
static void grid(int n, bool texcoords)
{
    for (int i = 0; i < n; i++) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= n; j++) {
            for (int k = 1; k >= 0; k--) {
                const float x = -1.0f + 2.0f * (float)(i + k) / (float)n;
                const float y = -1.0f + 2.0f * (float)j / (float)n;
                glNormal3f(0.4f * x, 0.4f * y, 1.0f);
                if (texcoords)
                    glTexCoord2f(x, y);
                glVertex3f(x, y, -0.25f * x * y);
            }
        }
        glEnd();
    }
}

static void render_frame(fc_h *h, void (*draw)(void))
{
    fcu_clear(0.1f, 0.2f, 0.3f, 1.0f, 1.0);
    draw();
    fc_capture(h);
}

static void draw_grid_gen(void)
{
    grid(6, false);
}

static void draw_grid_tc(void)
{
    grid(6, true);
}

static void draw_sphere(void)
{
    sphere(0.8f, 0.0f, 10, 14);
}

static void render_view(void)
{
    glViewport(0, 0, 48, 48);
    fcu_frustum(-0.6, 0.6, -0.6, 0.6, 1, 10);
    glTranslatef(0.0f, 0.0f, -3.0f);
}

/* OBJECT_LINEAR and EYE_LINEAR generation on a rotating grid: object
 * coordinates stick to the grid, eye coordinates to the view; NEAREST and
 * LINEAR, REPEAT and CLAMP_TO_EDGE. */
static void gen_render_linear(fc_h *h)
{
    static const GLfloat sp[4] = { 0.75f, 0.125f, 0.0f, 0.5f };
    static const GLfloat tp[4] = { -0.125f, 0.625f, 0.25f, 0.5f };
    render_view();
    glEnable(GL_DEPTH_TEST);
    for (int mode = 0; mode < 2; mode++) {
        const GLenum gm = mode ? GL_EYE_LINEAR : GL_OBJECT_LINEAR;
        const GLenum pl = mode ? GL_EYE_PLANE : GL_OBJECT_PLANE;
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, gm);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, gm);
        glTexGenfv(GL_S, pl, sp);
        glTexGenfv(GL_T, pl, tp);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
        for (int f = 0; f < 2; f++) {
            cell_texture(16, 16, (unsigned)(3 * mode + f), f ? GL_LINEAR : GL_NEAREST,
                         f ? GL_CLAMP_TO_EDGE : GL_REPEAT);
            glPushMatrix();
            glRotatef(25.0f + 20.0f * (float)f, 0.3f, 1.0f, 0.2f);
            glRotatef(-15.0f * (float)mode, 1.0f, 0.0f, 0.0f);
            render_frame(h, draw_grid_gen);
            glPopMatrix();
        }
    }
}

/* SPHERE_MAP on a lit sphere (GL_NORMALIZE off and on), modulated; the
 * sphere moved and scaled so that lighting and generation run in eye
 * space. */
static void gen_render_sphere(fc_h *h)
{
    render_view();
    glEnable(GL_DEPTH_TEST);
    cell_texture(32, 32, 7, GL_LINEAR, GL_REPEAT);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    render_frame(h, draw_sphere);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glPushMatrix();
    glTranslatef(0.2f, -0.1f, 0.3f);
    glRotatef(40.0f, 1.0f, 0.5f, 0.0f);
    render_frame(h, draw_sphere);
    glScalef(1.3f, 0.8f, 1.0f);
    glEnable(GL_NORMALIZE);
    render_frame(h, draw_sphere);
    glPopMatrix();
}

/* REFLECTION_MAP and NORMAL_MAP on S and T of a 2D texture (R generated
 * too, unused by 2D sampling) */
static void gen_render_reflection(fc_h *h)
{
    render_view();
    glEnable(GL_DEPTH_TEST);
    cell_texture(16, 16, 11, GL_LINEAR, GL_REPEAT);
    const GLenum modes[2] = { GL_REFLECTION_MAP, GL_NORMAL_MAP };
    for (int m = 0; m < 2; m++) {
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, (GLint)modes[m]);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, (GLint)modes[m]);
        glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, (GLint)modes[m]);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
        glEnable(GL_TEXTURE_GEN_R);
        glPushMatrix();
        glRotatef(30.0f * (float)(m + 1), 0.0f, 1.0f, 0.3f);
        render_frame(h, draw_sphere);
        glPopMatrix();
    }
}

/* The texture matrix: rotation and scale about the centre, a projective
 * matrix (q varies), and generation followed by the matrix. */
static void matrix_render(fc_h *h)
{
    render_view();
    cell_texture(16, 16, 5, GL_NEAREST, GL_REPEAT);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.5f, 0.5f, 0.0f);
    glRotatef(33.0f, 0.0f, 0.0f, 1.0f);
    glScalef(0.75f, 1.5f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    render_frame(h, draw_grid_tc);
    static const GLfloat proj[16] = { 1, 0, 0, 0.3f, 0, 1, 0, -0.2f, 0, 0, 1, 0, 0, 0, 0, 1 };
    glMatrixMode(GL_TEXTURE);
    glLoadMatrixf(proj);
    glMatrixMode(GL_MODELVIEW);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    render_frame(h, draw_grid_tc);
    static const GLfloat sp[4] = { 1.0f, 0.0f, 0.5f, 0.0f };
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_S, GL_EYE_PLANE, sp);
    glEnable(GL_TEXTURE_GEN_S);
    glRotatef(20.0f, 1.0f, 1.0f, 0.0f);
    render_frame(h, draw_grid_tc);
}

/* two units at once: unit 0 modulates a cell texture with the colour,
 * unit 1 adds (or decals, or blends) another, with its own coordinates:
 * glMultiTexCoord, then generation and a matrix on unit 1 */
static void draw_two_units(void)
{
    for (int i = 0; i < 5; i++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (int j = 0; j <= 5; j++) {
            for (int k = 0; k < 2; k++) {
                const float x = -1.0f + 0.4f * (float)(i + k), y = -1.0f + 0.4f * (float)j;
                glColor3f(0.5f + 0.5f * x, 0.5f + 0.5f * y, 0.75f);
                glMultiTexCoord2f(GL_TEXTURE0, 0.5f * x + 0.5f, 0.5f * y + 0.5f);
                glMultiTexCoord3f(GL_TEXTURE1, 2.0f * x, y * y, 1.0f);
                glVertex3f(x, y, -0.3f * x);
            }
        }
        glEnd();
    }
}

static void multi_render_two_units(fc_h *h)
{
    render_view();
    glRotatef(-20.0f, 1.0f, 0.2f, 0.0f);
    glActiveTexture(GL_TEXTURE0);
    cell_texture(16, 16, 1, GL_NEAREST, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glActiveTexture(GL_TEXTURE1);
    cell_texture(8, 8, 9, GL_LINEAR, GL_REPEAT);
    static const GLenum envs[3] = { GL_ADD, GL_DECAL, GL_BLEND };
    for (int e = 0; e < 3; e++) {
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)envs[e]);
        render_frame(h, draw_two_units);
    }
    /* unit 1's coordinates generated and transformed */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    static const GLfloat sp[4] = { 0.5f, 0.25f, 0.0f, 0.5f };
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, sp);
    glEnable(GL_TEXTURE_GEN_S);
    glMatrixMode(GL_TEXTURE);
    glRotatef(45.0f, 0.0f, 0.0f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    render_frame(h, draw_two_units);
    /* unit 0 disabled: unit 1 alone */
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_TEXTURE_2D);
    render_frame(h, draw_two_units);
    /* unit 0 back, matrix changed on unit 0 only (unit 1's matrix drops
     * out of the program: texture/matrix_other_unit) */
    glEnable(GL_TEXTURE_2D);
    render_frame(h, draw_two_units);
    glMatrixMode(GL_TEXTURE);
    glScalef(2.0f, 2.0f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    render_frame(h, draw_two_units);
}

/* Units 0..7 each with its own small texture and ADD (unit 0 REPLACE),
 * coordinates from glMultiTexCoord, generation on the odd units. */
static void draw_eight(void)
{
    glBegin(GL_QUADS);
    static const float v[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    for (int k = 0; k < 4; k++) {
        for (int u = 0; u < 8; u++)
            glMultiTexCoord2f(GL_TEXTURE0 + u, v[k][0] * (0.5f + 0.25f * (float)u),
                              v[k][1] * (1.0f + 0.125f * (float)u));
        glVertex2f(v[k][0], v[k][1]);
    }
    glEnd();
}

static void multi_render_eight_units(fc_h *h)
{
    render_view();
    for (int u = 0; u < 8; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        cell_texture(4, 4, (unsigned)(13 * u), (u & 2) ? GL_LINEAR : GL_NEAREST, GL_REPEAT);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, u == 0 ? GL_REPLACE : GL_ADD);
        if (u & 1) {
            const GLfloat tp[4] = { 0.0f, 0.5f + 0.1f * (float)u, 0.0f, 0.25f };
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
            glTexGenfv(GL_T, GL_EYE_PLANE, tp);
            glEnable(GL_TEXTURE_GEN_T);
        }
    }
    glActiveTexture(GL_TEXTURE0);
    glColor4f(0.1f, 0.1f, 0.1f, 1.0f);
    for (int u = 0; u < 8; u++)
        glMultiTexCoord2f(GL_TEXTURE0 + u, 0.0f, 0.0f);
    render_frame(h, draw_eight);
    glRotatef(30.0f, 0.2f, 0.2f, 1.0f);
    render_frame(h, draw_eight);
}

/* Two units from arrays (glClientActiveTexture), glDrawArrays,
 * glDrawElements and glArrayElement, and the same compiled in a list. */
static void multi_render_arrays(fc_h *h)
{
    static GLfloat pos[36][3], tc0[36][2];
    static GLshort tc1[36][2];
    static GLushort idx[150];
    int n = 0;
    for (int j = 0; j < 6; j++)
        for (int i = 0; i < 6; i++) {
            const float x = -1.0f + 0.4f * (float)i, y = -1.0f + 0.4f * (float)j;
            pos[n][0] = x;
            pos[n][1] = y;
            pos[n][2] = -0.2f * y;
            tc0[n][0] = 0.3f * x + 0.5f;
            tc0[n][1] = 0.6f * y;
            tc1[n][0] = (GLshort)(i - 2);
            tc1[n][1] = (GLshort)(j * 2 - 5);
            n++;
        }
    int m = 0;
    for (int j = 0; j < 5; j++)
        for (int i = 0; i < 5; i++) {
            const GLushort a = (GLushort)(j * 6 + i);
            idx[m++] = a;
            idx[m++] = (GLushort)(a + 1);
            idx[m++] = (GLushort)(a + 7);
            idx[m++] = a;
            idx[m++] = (GLushort)(a + 7);
            idx[m++] = (GLushort)(a + 6);
        }
    render_view();
    glRotatef(25.0f, 0.0f, 1.0f, 0.1f);
    glActiveTexture(GL_TEXTURE0);
    cell_texture(16, 16, 2, GL_LINEAR, GL_REPEAT);
    glActiveTexture(GL_TEXTURE1);
    cell_texture(8, 8, 6, GL_NEAREST, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glMatrixMode(GL_TEXTURE);
    glScalef(0.25f, 0.125f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glEnableClientState(GL_VERTEX_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    glTexCoordPointer(2, GL_FLOAT, 0, tc0);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE1);
    glTexCoordPointer(2, GL_SHORT, 0, tc1);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    fcu_clear(0.1f, 0.2f, 0.3f, 1.0f, 1.0);
    glDrawElements(GL_TRIANGLES, m, GL_UNSIGNED_SHORT, idx);
    fc_capture(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 1.0f, 1.0);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 36);
    fc_capture(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 1.0f, 1.0);
    glNewList(5, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    for (int k = 0; k < m; k++)
        glArrayElement(idx[k]);
    glEnd();
    glEndList();
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glCallList(5);
    fc_capture(h);
    glDeleteLists(5, 1);
    glClientActiveTexture(GL_TEXTURE0);
}

/* Large triangles crossing the near plane with three units: the clipper
 * interpolates every unit's coordinate (unit 1 eye-linear generated, unit
 * 2 through a projective matrix), flat and smooth, filled and as lines. */
static void draw_clipped(void)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.5f, 0.25f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
    glMultiTexCoord4f(GL_TEXTURE2, 0.0f, 0.0f, 0.0f, 1.0f);
    glVertex3f(-2.0f, -1.5f, 2.5f);
    glColor3f(0.25f, 1.0f, 0.5f);
    glMultiTexCoord2f(GL_TEXTURE0, 4.0f, 0.5f);
    glMultiTexCoord4f(GL_TEXTURE2, 2.0f, 0.0f, 0.0f, 2.0f);
    glVertex3f(2.5f, -1.0f, -6.0f);
    glColor3f(0.5f, 0.25f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 1.0f, 3.0f);
    glMultiTexCoord4f(GL_TEXTURE2, 0.5f, 1.5f, 0.0f, 0.5f);
    glVertex3f(-0.5f, 2.0f, -1.0f);
    glColor3f(0.9f, 0.9f, 0.2f);
    glMultiTexCoord2f(GL_TEXTURE0, -1.0f, -1.0f);
    glMultiTexCoord4f(GL_TEXTURE2, 1.0f, 1.0f, 0.0f, 1.0f);
    glVertex3f(1.5f, 1.5f, 2.0f);
    glVertex3f(-2.5f, 0.5f, -7.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 2.0f, -2.0f);
    glVertex3f(2.0f, -2.0f, -2.0f);
    glEnd();
}

static void multi_render_clipped(fc_h *h)
{
    glViewport(0, 0, 48, 48);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 20);
    glTranslatef(0.0f, 0.0f, -2.5f);
    glEnable(GL_DEPTH_TEST);
    glActiveTexture(GL_TEXTURE0);
    cell_texture(16, 16, 4, GL_LINEAR, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glActiveTexture(GL_TEXTURE1);
    cell_texture(8, 8, 8, GL_NEAREST, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    static const GLfloat sp[4] = { 0.3f, 0.1f, 0.05f, 0.5f }, tp[4] = { 0.0f, 0.4f, -0.1f, 0.0f };
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_S, GL_EYE_PLANE, sp);
    glTexGenfv(GL_T, GL_EYE_PLANE, tp);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glActiveTexture(GL_TEXTURE2);
    cell_texture(16, 16, 12, GL_NEAREST, GL_CLAMP_TO_EDGE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    static const GLfloat proj[16] = { 1, 0, 0, 0.25f, 0, 1, 0, 0.5f, 0, 0, 1, 0, 0, 0, 0, 1 };
    glMatrixMode(GL_TEXTURE);
    glLoadMatrixf(proj);
    glMatrixMode(GL_MODELVIEW);
    glActiveTexture(GL_TEXTURE0);
    render_frame(h, draw_clipped);
    glShadeModel(GL_FLAT);
    render_frame(h, draw_clipped);
    glShadeModel(GL_SMOOTH);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    render_frame(h, draw_clipped);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glEnable(GL_CLIP_PLANE0);
    static const GLdouble cp[4] = { 1.0, 0.5, 0.0, 0.25 };
    glClipPlane(GL_CLIP_PLANE0, cp);
    glRotatef(15.0f, 0.0f, 0.0f, 1.0f);
    render_frame(h, draw_clipped);
}

/* glActiveTexture of the units past the fixed-function ones: the oracle
 * takes every combined image unit (192), which have a binding and a LOD
 * bias only (ORACLE-NOTES.md "Units 8..191").  GL_TEXTURE matrix mode and
 * GL_TRANSPOSE_TEXTURE_MATRIX on them read past the oracle's arrays and
 * are left out. */
static void multi_active_image_units(fc_h *h)
{
    glActiveTexture(GL_TEXTURE0 + 8);
    fc_error(h, "active 8");
    fc_get_integer(h, "active 8", GL_ACTIVE_TEXTURE, 1);
    glActiveTexture(GL_TEXTURE0 + 192);
    fc_error(h, "active 192");
    glActiveTexture(GL_TEXTURE0 + 191);
    fc_error(h, "active 191");
    fc_get_integer(h, "active 191", GL_ACTIVE_TEXTURE, 1);

    /* objects and images on unit 100 */
    GLubyte texels[4 * 4 * 4];
    for (int i = 0; i < (int)sizeof texels; i++)
        texels[i] = (GLubyte)(i * 37 + 11);
    glActiveTexture(GL_TEXTURE0 + 100);
    glBindTexture(GL_TEXTURE_2D, 5);
    glBindTexture(GL_TEXTURE_1D, 6);
    fc_error(h, "bind");
    fc_get_integer(h, "binding 2d", GL_TEXTURE_BINDING_2D, 1);
    fc_get_integer(h, "binding 1d", GL_TEXTURE_BINDING_1D, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    fc_error(h, "image");
    GLint v = -1;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
    fc_value(h, "min filter", v);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
    fc_value(h, "width", v);

    /* the environment: ignored, reads nothing; the LOD bias works */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    fc_error(h, "env mode");
    glTexEnvi(GL_TEXTURE_ENV, 0x1234, 5);
    fc_error(h, "env bad pname");
    glTexEnvi(0x1234, GL_TEXTURE_ENV_MODE, GL_DECAL);
    fc_error(h, "env bad target");
    v = 77;
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
    fc_error(h, "get env mode");
    fc_value(h, "get env mode", v);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.5f);
    fc_error(h, "lod bias");
    GLfloat f = 0.0f;
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &f);
    fc_value(h, "lod bias x4", (long long)(f * 4.0f));
    glTexEnvi(GL_TEXTURE_FILTER_CONTROL, 0x1234, 0);
    fc_error(h, "filter control bad pname");

    /* coordinate generation, enables, unit queries */
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    fc_error(h, "texgen");
    glTexGeni(0x1234, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    fc_error(h, "texgen bad coord");
    glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &v);
    fc_error(h, "get texgen");
    glEnable(GL_TEXTURE_2D);
    fc_error(h, "enable 2d");
    fc_is_enabled(h, "2d", GL_TEXTURE_2D);
    fc_get_integer(h, "2d", GL_TEXTURE_2D, 1);
    glDisable(GL_TEXTURE_1D);
    fc_error(h, "disable 1d");
    glEnable(GL_TEXTURE_GEN_S);
    fc_error(h, "enable gen s");
    fc_is_enabled(h, "gen s", GL_TEXTURE_GEN_S);
    fc_get_integer(h, "gen s", GL_TEXTURE_GEN_S, 1);
    fc_get_float(h, "matrix", GL_TEXTURE_MATRIX, 16);
    fc_get_integer(h, "stack depth", GL_TEXTURE_STACK_DEPTH, 1);
    fc_get_float(h, "coords", GL_CURRENT_TEXTURE_COORDS, 4);
    fc_get_float(h, "raster coords", GL_CURRENT_RASTER_TEXTURE_COORDS, 4);

    /* GL_TEXTURE_BIT restores the binding, not the LOD bias */
    glPushAttrib(GL_TEXTURE_BIT);
    glBindTexture(GL_TEXTURE_2D, 0);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.5f);
    glActiveTexture(GL_TEXTURE0 + 3);
    glPopAttrib();
    fc_error(h, "pop");
    fc_get_integer(h, "popped active", GL_ACTIVE_TEXTURE, 1);
    fc_get_integer(h, "popped binding", GL_TEXTURE_BINDING_2D, 1);
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &f);
    fc_value(h, "popped lod bias x4", (long long)(f * 4.0f));

    /* deleting the object unbinds it there too */
    GLuint name = 5;
    glDeleteTextures(1, &name);
    fc_get_integer(h, "deleted binding", GL_TEXTURE_BINDING_2D, 1);
    fc_get_integer(h, "1d binding", GL_TEXTURE_BINDING_1D, 1);

    /* a display list replays the unit */
    glNewList(1, GL_COMPILE);
    glActiveTexture(GL_TEXTURE0 + 150);
    glEndList();
    glActiveTexture(GL_TEXTURE0);
    glCallList(1);
    fc_error(h, "list");
    fc_get_integer(h, "list active", GL_ACTIVE_TEXTURE, 1);
    glDeleteLists(1, 1);

    /* unit 0 still textures: a quad with the unit-0 image */
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 7);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(-1, -1);
    glTexCoord2f(1, 0); glVertex2f(1, -1);
    glTexCoord2f(1, 1); glVertex2f(1, 1);
    glTexCoord2f(0, 1); glVertex2f(-1, 1);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    fc_error(h, "end");
}

/* A coordinate that cannot vary (set outside glBegin/glEnd, no texgen, an
 * identity texture matrix) is a constant of the fragment program: the
 * oracle reads the current coordinate, never interpolates it.  A triangle
 * with the w = 0 origin as a vertex shows it: interpolating the constant
 * gives NaN there (texel 0 of a NEAREST REPEAT lookup), the constant
 * gives its own texel.  Frames: unit 0 constant (smooth, flat, LINEAR),
 * unit 1 constant beside a varying unit 0, the coordinate per vertex
 * (varying), a texture matrix and texgen (varying again), and a line
 * strip and points through the same units. */
static void draw_w_zero(void)
{
    static const float tri[3][4] = {
        { -0.8f, -0.8f, 0.7f, -0.6f },
        { 0.9f, 0.9f, -0.9f, 0.95f },
        { -0.2f, 0.5f, 0.1f, -0.9f },
    };
    for (int t = 0; t < 3; t++) {
        glBegin(GL_TRIANGLES);
        glVertex4f(tri[t][0], tri[t][1], 0.1f, 1.0f);
        glVertex4f(tri[t][2], tri[t][3], 0.1f, 1.0f);
        glVertex4f(0, 0, 0, 0);
        glEnd();
    }
}

static void draw_w_zero_varying(void)
{
    glBegin(GL_TRIANGLES);
    glMultiTexCoord2f(GL_TEXTURE0, 0.8f, 0.5f);
    glVertex4f(-0.8f, -0.8f, 0.1f, 1.0f);
    glVertex4f(0.7f, -0.6f, 0.1f, 1.0f);
    glVertex4f(0, 0, 0, 0);
    glEnd();
}

static void draw_w_zero_lines(void)
{
    glBegin(GL_LINE_STRIP);
    glVertex4f(-0.8f, -0.8f, 0.1f, 1.0f);
    glVertex4f(0.7f, -0.6f, 0.1f, 1.0f);
    glVertex4f(0.9f, 0.9f, 0.1f, 1.0f);
    glEnd();
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    glVertex4f(-0.5f, 0.5f, 0.1f, 1.0f);
    glVertex4f(0.5f, 0.5f, 0.3f, 2.0f);
    glEnd();
    glPointSize(1.0f);
}

static void strip_texture(GLenum filter)
{
    static const GLubyte texels[32] = {
        0, 14, 255, 128, 55, 0, 78, 77, 0, 0, 60, 0, 0, 255, 128, 255,
        255, 64, 127, 191, 127, 0, 70, 126, 128, 71, 44, 0, 0, 149, 128, 128,
    };
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)filter);
    glEnable(GL_TEXTURE_2D);
}

static void coord_constant_w_zero(fc_h *h)
{
    glViewport(0, 0, 17, 54);
    glColor4f(0.2f, 0.4f, 0.6f, 1.0f);
    glActiveTexture(GL_TEXTURE0);
    strip_texture(GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glMultiTexCoord2f(GL_TEXTURE0, 0.826f, 0.8f);
    render_frame(h, draw_w_zero);                 /* constant, smooth */
    glShadeModel(GL_FLAT);
    render_frame(h, draw_w_zero);                 /* constant, flat */
    glShadeModel(GL_SMOOTH);
    strip_texture(GL_LINEAR);
    render_frame(h, draw_w_zero);                 /* constant, LINEAR */
    strip_texture(GL_NEAREST);
    /* unit 1 constant beside a varying unit 0 */
    glActiveTexture(GL_TEXTURE1);
    strip_texture(GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glMultiTexCoord2f(GL_TEXTURE1, 0.3f, 0.2f);
    render_frame(h, draw_w_zero_varying);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    render_frame(h, draw_w_zero_varying);         /* unit 0 varying */
    /* a texture matrix computes the coordinate per vertex: varying */
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.125f, 0.0f, 0.0f);
    render_frame(h, draw_w_zero);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    /* texgen on s: varying */
    static const GLfloat sp[4] = { 0.25f, 0.5f, 0.0f, 0.5f };
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, sp);
    glEnable(GL_TEXTURE_GEN_S);
    render_frame(h, draw_w_zero);
    glDisable(GL_TEXTURE_GEN_S);
    /* the same again after the generation is off: constant */
    render_frame(h, draw_w_zero);
    render_frame(h, draw_w_zero_lines);
    glDisable(GL_TEXTURE_2D);
    fc_error(h, "end");
}

const fc_case fc_cases_tex_coord[] = {
    FC_CASE_RGBA("texture/gen_object_linear", 32, 32, 0, "texture feedback", gen_object_linear),
    FC_CASE_RGBA("texture/gen_eye_linear", 32, 32, 0, "texture feedback lighting", gen_eye_linear),
    FC_CASE_RGBA("texture/gen_sphere_map", 32, 32, 0, "texture feedback lighting", gen_sphere_map),
    FC_CASE_RGBA("texture/gen_reflection_normal", 32, 32, 0, "texture feedback lighting",
                 gen_reflection_normal),
    FC_CASE_RGBA("texture/gen_rasterpos", 32, 32, 0, "texture rasterpos", gen_rasterpos),
    FC_CASE_RGBA("texture/matrix_feedback", 32, 32, 0, "texture feedback", matrix_feedback),
    FC_CASE_RGBA("texture/matrix_other_unit", 32, 32, 0, "texture feedback", matrix_other_unit),
    FC_CASE_RGBA("texture/matrix_stack", 16, 16, 0, "texture api matrix", matrix_stack),
    FC_CASE_RGBA("texture/multi_current", 16, 16, 0, "texture api", multi_current),
    FC_CASE_RGBA("texture/multi_errors", 16, 16, 0, "texture api errors", multi_errors),
    FC_CASE_RGBA("texture/multi_enables", 16, 16, 0, "texture api attrib", multi_enables),
    FC_CASE_RGBA("texture/multi_arrays", 32, 32, 0, "texture varray feedback", multi_arrays),
    FC_CASE_RGBA("texture/multi_dlist", 32, 32, 0, "texture dlist feedback", multi_dlist),
    FC_CASE_RGBA("texture/multi_upgrade", 32, 32, 0, "texture feedback", multi_upgrade),
    FC_CASE_RGBA("texture/multi_active_image_units", 8, 8, 0, "texture api errors",
                 multi_active_image_units),
    FC_CASE_RGBA("texture/gen_render_linear", 48, 48, 4, "texture render", gen_render_linear),
    FC_CASE_RGBA("texture/gen_render_sphere", 48, 48, 3, "texture render lighting",
                 gen_render_sphere),
    FC_CASE_RGBA("texture/gen_render_reflection", 48, 48, 2, "texture render",
                 gen_render_reflection),
    FC_CASE_RGBA("texture/matrix_render", 48, 48, 3, "texture render", matrix_render),
    FC_CASE_RGBA("texture/multi_render_two_units", 48, 48, 7, "texture render",
                 multi_render_two_units),
    FC_CASE_RGBA("texture/multi_render_eight_units", 48, 48, 2, "texture render",
                 multi_render_eight_units),
    FC_CASE_RGBA("texture/multi_render_arrays", 48, 48, 3, "texture render varray dlist",
                 multi_render_arrays),
    FC_CASE_RGBA("texture/multi_render_clipped", 48, 48, 4, "texture render clip",
                 multi_render_clipped),
    FC_CASE_RGBA("texture/coord_constant_w_zero", 17, 54, 9, "texture render clip robust",
                 coord_constant_w_zero),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
