/* c_rasterpos.c - glRasterPos: the raster position, distance, colours and
 * texture coordinates under the modelview, projection, viewport and depth
 * range; clipping by the view volume and the user planes (valid false, the
 * other values kept); w != 1 and w == 0; every variant; fog distance; the
 * texture matrix; display lists; glPushAttrib(GL_CURRENT_BIT); selection
 * and feedback; errors inside glBegin/glEnd; queries in every type. */
#include <math.h>
#include <stdio.h>

#include "cases.h"

/* Every raster query of GL 1.5 as float (GL_CURRENT_RASTER_SECONDARY_COLOR
 * is GL 3.0's compatibility query, foreign to GL 1.5:
 * honesty/rasterpos_secondary_color records it). */
static void rp_query(fc_h *h, const char *label)
{
    char l[96];
    snprintf(l, sizeof l, "%s pos", label);
    fc_get_float(h, l, GL_CURRENT_RASTER_POSITION, 4);
    snprintf(l, sizeof l, "%s valid", label);
    fc_get_boolean(h, l, GL_CURRENT_RASTER_POSITION_VALID, 1);
    snprintf(l, sizeof l, "%s distance", label);
    fc_get_float(h, l, GL_CURRENT_RASTER_DISTANCE, 1);
    snprintf(l, sizeof l, "%s color", label);
    fc_get_float(h, l, GL_CURRENT_RASTER_COLOR, 4);
    snprintf(l, sizeof l, "%s index", label);
    fc_get_float(h, l, GL_CURRENT_RASTER_INDEX, 1);
    snprintf(l, sizeof l, "%s texcoords", label);
    fc_get_float(h, l, GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
    snprintf(l, sizeof l, "%s error", label);
    fc_error(h, l);
}

/* The same in the other query types. */
static void rp_query_types(fc_h *h, const char *label)
{
    char l[96];
    snprintf(l, sizeof l, "%s pos i", label);
    fc_get_integer(h, l, GL_CURRENT_RASTER_POSITION, 4);
    snprintf(l, sizeof l, "%s pos d", label);
    fc_get_double(h, l, GL_CURRENT_RASTER_POSITION, 4);
    snprintf(l, sizeof l, "%s pos b", label);
    fc_get_boolean(h, l, GL_CURRENT_RASTER_POSITION, 4);
    snprintf(l, sizeof l, "%s valid i", label);
    fc_get_integer(h, l, GL_CURRENT_RASTER_POSITION_VALID, 1);
    snprintf(l, sizeof l, "%s valid f", label);
    fc_get_float(h, l, GL_CURRENT_RASTER_POSITION_VALID, 1);
    snprintf(l, sizeof l, "%s distance i", label);
    fc_get_integer(h, l, GL_CURRENT_RASTER_DISTANCE, 1);
    snprintf(l, sizeof l, "%s distance d", label);
    fc_get_double(h, l, GL_CURRENT_RASTER_DISTANCE, 1);
    snprintf(l, sizeof l, "%s color i", label);
    fc_get_integer(h, l, GL_CURRENT_RASTER_COLOR, 4);
    snprintf(l, sizeof l, "%s color b", label);
    fc_get_boolean(h, l, GL_CURRENT_RASTER_COLOR, 4);
    snprintf(l, sizeof l, "%s texcoords i", label);
    fc_get_integer(h, l, GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
    snprintf(l, sizeof l, "%s texcoords d", label);
    fc_get_double(h, l, GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
}

/* Positions under an ortho and a perspective projection, a viewport off
 * the origin and a depth range, a rotated and scaled modelview. */
static void rp_transform(fc_h *h)
{
    rp_query(h, "initial");
    rp_query_types(h, "initial");
    glViewport(3, 5, 41, 27);
    glDepthRange(0.25, 0.8);
    fcu_ortho(-1.3, 1.7, -0.9, 1.1, -2, 3);
    glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
    glRasterPos3f(0.3f, -0.7f, 0.9f);
    rp_query(h, "ortho");
    rp_query_types(h, "ortho");
    glMatrixMode(GL_MODELVIEW);
    glRotatef(33.0f, 0.3f, 0.5f, 0.8f);
    glScalef(1.1f, 0.7f, 1.3f);
    glTranslatef(0.1f, -0.2f, 0.05f);
    glRasterPos3f(0.37f, 0.21f, -0.44f);
    rp_query(h, "ortho rotated");
    fcu_frustum(-0.7, 0.6, -0.5, 0.55, 1.0, 9.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.1f, 0.2f, -3.3f);
    glRotatef(-21.0f, 0.8f, 0.1f, 0.3f);
    glColor3f(0.9f, 0.1f, 0.3f);
    glRasterPos3f(0.5f, -0.3f, 0.7f);
    rp_query(h, "perspective");
    rp_query_types(h, "perspective");
    glRasterPos2f(-1.1f, 0.9f);
    rp_query(h, "perspective 2");
    glDepthRange(0.9, 0.1);
    glRasterPos2f(0.3f, 0.1f);
    rp_query(h, "reversed depth range");
}

/* Clipped by each view-volume plane and on the boundary: valid false and
 * the previous values kept; then a position inside again. */
static void rp_clipped(fc_h *h)
{
    static const float out[][4] = {
        { 1.01f, 0, 0, 1 }, { -1.01f, 0, 0, 1 }, { 0, 1.5f, 0, 1 }, { 0, -1.2f, 0, 1 },
        { 0, 0, 1.001f, 1 }, { 0, 0, -1.3f, 1 }, { 0.5f, 0.5f, 0.5f, -1 },
        { 1, 0, 0, 0 }, { 0, 0, 0, 0 },
    };
    static const float on[][4] = {
        { 1, 1, 1, 1 }, { -1, -1, -1, 1 }, { 2, -2, 2, 2 }, { 0.5f, 0.25f, 0.1f, 0 },
    };
    char l[64];
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    for (unsigned i = 0; i < sizeof out / sizeof out[0]; i++) {
        glColor3f(0.5f, 0.25f, 0.125f);
        glRasterPos3f(0.25f, -0.5f, 0.125f);
        glColor3f(1, 0, 1);
        glRasterPos4fv(out[i]);
        snprintf(l, sizeof l, "out %u", i);
        rp_query(h, l);
    }
    rp_query_types(h, "clipped");
    /* on the boundary: inside; w == 0 at the origin is inside too (the
     * division is then by 1) */
    for (unsigned i = 0; i < sizeof on / sizeof on[0]; i++) {
        glColor3f(0.1f * (float)i, 0.3f, 0.7f);
        glRasterPos4fv(on[i]);
        snprintf(l, sizeof l, "on %u", i);
        rp_query(h, l);
    }
    glRasterPos4f(0, 0, 0, 0);
    rp_query(h, "w zero origin");
    glRasterPos4f(0.3f, -0.2f, 0.4f, 2.5f);
    rp_query(h, "w 2.5");
    glRasterPos4f(-0.3f, -0.2f, -0.4f, -0.5f);
    rp_query(h, "w negative");
}

/* User clip planes in eye space, transformed by the projection. */
static void rp_user_planes(fc_h *h)
{
    static const GLdouble p0[4] = { 1, 0.5, 0, -0.1 };
    static const GLdouble p1[4] = { -0.3, 1, 0.2, 0.05 };
    glViewport(0, 0, 32, 32);
    fcu_frustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClipPlane(GL_CLIP_PLANE0, p0);
    glTranslatef(0, 0, -2);
    glClipPlane(GL_CLIP_PLANE2, p1);
    glEnable(GL_CLIP_PLANE0);
    glRasterPos3f(0.5f, 0.1f, 0);
    rp_query(h, "plane0 inside");
    glRasterPos3f(-0.5f, 0.1f, 0);
    rp_query(h, "plane0 outside");
    glEnable(GL_CLIP_PLANE2);
    glRasterPos3f(0.5f, 0.1f, 0);
    rp_query(h, "plane2 inside");
    glRasterPos3f(0.6f, -0.9f, 0);
    rp_query(h, "plane2 outside");
    glDisable(GL_CLIP_PLANE0);
    glRasterPos3f(-0.5f, 0.5f, 0);
    rp_query(h, "plane0 off");
    /* on plane 0 exactly (x = 0.1 - 0.5 y at z = 0 in eye space) */
    glDisable(GL_CLIP_PLANE2);
    glEnable(GL_CLIP_PLANE0);
    glLoadIdentity();
    glRasterPos3f(0.1f, 0.0f, -2.0f);
    rp_query(h, "plane0 boundary");
}

/* Every variant, with integer, short and double arguments. */
static void rp_variants(fc_h *h)
{
    static const GLshort sv[4] = { 3, -7, 2, 4 };
    static const GLint iv[4] = { -5, 9, -1, 3 };
    static const GLfloat fv[4] = { 1.25f, -2.5f, 0.75f, 1.5f };
    static const GLdouble dv[4] = { 0.1, -0.30000000000000004, 0.7, 1.0000001 };
    glViewport(2, 1, 60, 50);
    fcu_ortho(-10, 10, -12, 12, -5, 5);
    glRasterPos2s(3, -4);   rp_query(h, "2s");
    glRasterPos2i(-7, 8);   rp_query(h, "2i");
    glRasterPos2f(1.3f, 2.1f);   rp_query(h, "2f");
    glRasterPos2d(0.1, 0.2);   rp_query(h, "2d");
    glRasterPos3s(1, 2, 3);   rp_query(h, "3s");
    glRasterPos3i(-1, -2, -3);   rp_query(h, "3i");
    glRasterPos3f(0.3f, 0.6f, 0.9f);   rp_query(h, "3f");
    glRasterPos3d(0.7, -0.1, 4.99);   rp_query(h, "3d");
    glRasterPos4s(4, 6, 2, 2);   rp_query(h, "4s");
    glRasterPos4i(-9, 3, 1, 3);   rp_query(h, "4i");
    glRasterPos4f(0.5f, 0.25f, 0.125f, 0.3f);   rp_query(h, "4f");
    glRasterPos4d(1.1, 2.2, 3.3, 0.7);   rp_query(h, "4d");
    glRasterPos2sv(sv);   rp_query(h, "2sv");
    glRasterPos2iv(iv);   rp_query(h, "2iv");
    glRasterPos2fv(fv);   rp_query(h, "2fv");
    glRasterPos2dv(dv);   rp_query(h, "2dv");
    glRasterPos3sv(sv);   rp_query(h, "3sv");
    glRasterPos3iv(iv);   rp_query(h, "3iv");
    glRasterPos3fv(fv);   rp_query(h, "3fv");
    glRasterPos3dv(dv);   rp_query(h, "3dv");
    glRasterPos4sv(sv);   rp_query(h, "4sv");
    glRasterPos4iv(iv);   rp_query(h, "4iv");
    glRasterPos4fv(fv);   rp_query(h, "4fv");
    glRasterPos4dv(dv);   rp_query(h, "4dv");
    glRasterPos2i(100, 0);   rp_query(h, "2i out");
}

/* The raster distance with fog on and off, every fog mode and distance
 * mode (the raster distance ignores them), and the fog coordinate source. */
static void rp_fog_distance(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_frustum(-1, 1, -1, 1, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.3f, -0.2f, -4.7f);
    glRotatef(17.0f, 0.2f, 1.0f, 0.1f);
    glRasterPos3f(0.4f, 0.6f, -1.1f);
    rp_query(h, "fog off");
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glRasterPos3f(-0.4f, 0.3f, 2.1f);
    rp_query(h, "fog linear");
    glFogi(GL_FOG_MODE, GL_EXP2);
    glRasterPos3f(0.2f, 0.1f, 0.3f);
    rp_query(h, "fog exp2");
    glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
    glRasterPos3f(0.2f, 0.1f, 0.3f);
    rp_query(h, "fog coordinate source");
    glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
    glRasterPos3f(0.25f, 0.15f, 0.35f);
    rp_query(h, "fragment depth source");
}

/* Current colour and texture coordinate, through the texture matrix. */
static void rp_color_texcoord(fc_h *h)
{
    glViewport(0, 0, 16, 16);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glColor4f(1.5f, -0.25f, 0.3f, 0.7f);   /* unclamped current colour */
    glTexCoord4f(0.3f, 0.7f, -0.2f, 2.0f);
    glRasterPos2f(0, 0);
    rp_query(h, "unclamped colour");
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.5f, -0.25f, 1.0f);
    glRotatef(30.0f, 0, 0, 1);
    glScalef(2.0f, 0.5f, 1.5f);
    glMatrixMode(GL_MODELVIEW);
    glColor3ub(10, 200, 77);
    glRasterPos2f(0.5f, 0.5f);
    rp_query(h, "texture matrix");
    glBegin(GL_POINTS);
    glColor3f(0.1f, 0.2f, 0.3f);
    glTexCoord2f(0.9f, 0.8f);
    glEnd();
    glRasterPos2f(0.25f, 0.5f);
    rp_query(h, "current after glEnd");
}

/* Lit raster colours: Mesa's CPU lighting (front material only), in
 * object space (directional lights, rotation-only modelview) and in eye
 * space (positional, spot, local viewer, separate specular, a scaled
 * modelview); a normal facing away; colour material. */
static void rp_lit(fc_h *h)
{
    static const float pos0[4] = { 0.3f, 0.5f, 0.8f, 0.0f };
    static const float pos1[4] = { -1.0f, 2.0f, 1.5f, 1.0f };
    static const float amb[4] = { 0.1f, 0.15f, 0.2f, 1.0f };
    static const float dif[4] = { 0.7f, 0.5f, 0.9f, 1.0f };
    static const float spe[4] = { 0.9f, 0.8f, 0.4f, 1.0f };
    static const float mamb[4] = { 0.3f, 0.2f, 0.4f, 0.6f };
    static const float mdif[4] = { 0.8f, 0.6f, 0.3f, 0.45f };
    static const float mspe[4] = { 0.5f, 0.7f, 0.9f, 1.0f };
    static const float memi[4] = { 0.05f, 0.02f, 0.0f, 1.0f };
    static const float spot_dir[3] = { 0.4f, -0.7f, -0.5f };
    glViewport(0, 0, 32, 32);
    fcu_frustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, pos0);
    glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spe);
    glMaterialfv(GL_FRONT, GL_AMBIENT, mamb);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, mdif);
    glMaterialfv(GL_FRONT, GL_SPECULAR, mspe);
    glMaterialfv(GL_FRONT, GL_EMISSION, memi);
    glMaterialf(GL_FRONT, GL_SHININESS, 12.5f);
    glMaterialf(GL_BACK, GL_SHININESS, 3.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glTranslatef(0.1f, -0.2f, -4.0f);
    glRotatef(25.0f, 0.3f, 0.9f, 0.1f);
    glNormal3f(0.2f, 0.4f, 0.9f);
    glColor3f(0.1f, 0.9f, 0.5f);
    glRasterPos3f(0.3f, 0.2f, 0.1f);
    rp_query(h, "directional");
    glNormal3f(-0.2f, -0.4f, -0.9f);
    glRasterPos3f(0.3f, 0.2f, 0.1f);
    rp_query(h, "facing away");
    glNormal3f(0.5f, 0.3f, 0.6f);
    glScalef(1.5f, 0.8f, 1.1f);
    glRasterPos3f(0.2f, -0.2f, 0.3f);
    rp_query(h, "scaled modelview");
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glRasterPos3f(0.2f, -0.2f, 0.3f);
    rp_query(h, "two-sided");
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
    glEnable(GL_LIGHT1);
    glPushMatrix();
    glLoadIdentity();
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_SPECULAR, spe);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.05f);
    glPopMatrix();
    glRasterPos3f(0.1f, 0.3f, -0.2f);
    rp_query(h, "positional");
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glRasterPos3f(0.1f, 0.3f, -0.2f);
    rp_query(h, "local viewer");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glRasterPos3f(-0.3f, 0.1f, 0.2f);
    rp_query(h, "separate specular");
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot_dir);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 60.0f);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 3.5f);
    glRasterPos3f(-0.3f, 0.1f, 0.2f);
    rp_query(h, "spot");
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 5.0f);
    glRasterPos3f(-0.3f, 0.1f, 0.2f);
    rp_query(h, "spot outside cone");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
    glDisable(GL_LIGHT1);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(-40.0f, 1.0f, 0.2f, 0.0f);
    glEnable(GL_COLOR_MATERIAL);
    glColor4f(0.9f, 0.3f, 0.2f, 0.35f);
    glRasterPos3f(0.2f, 0.2f, 0.2f);
    rp_query(h, "color material");
    glDisable(GL_LIGHTING);
    glRasterPos3f(0.2f, 0.2f, 0.2f);
    rp_query(h, "lighting off");
}

/* Non-finite and huge coordinates, a singular modelview with lighting. */
static void rp_robust(fc_h *h)
{
    const float inf = INFINITY, nan = NAN;
    glViewport(0, 0, 16, 16);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glRasterPos4f(nan, 0.2f, 0.1f, 1.0f);
    rp_query(h, "nan x");
    glRasterPos4f(0.2f, 0.1f, 0.3f, nan);
    rp_query(h, "nan w");
    glRasterPos4f(inf, 0.2f, 0.1f, 1.0f);
    rp_query(h, "inf x");
    glRasterPos4f(0.5f, 0.2f, 0.1f, inf);
    rp_query(h, "inf w");
    glRasterPos4f(1e30f, -1e30f, 1e30f, 1e30f);
    rp_query(h, "huge");
    glRasterPos4f(1e-30f, 1e-30f, -1e-30f, 1e-38f);
    rp_query(h, "tiny w");
    glRasterPos4d(1e300, 0.0, 0.0, 1e300);
    rp_query(h, "double overflow");
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMatrixMode(GL_MODELVIEW);
    glScalef(1.0f, 0.0f, 1.0f);
    glNormal3f(0.3f, 0.4f, 0.5f);
    glRasterPos3f(0.2f, 0.3f, 0.4f);
    rp_query(h, "singular lit");
    glLoadIdentity();
    glNormal3f(0.0f, 0.0f, 0.0f);
    glRasterPos3f(0.2f, 0.3f, 0.4f);
    rp_query(h, "zero normal lit");
    /* Mesa's CLAMP(x, 0, 1) of the raster colours: NaN and -0 give +0 */
    glNormal3f(0.0f, 0.0f, 1.0f);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, (const GLfloat[]){ nan, -0.0f, 0.5f, nan });
    glMaterialfv(GL_FRONT, GL_AMBIENT, (const GLfloat[]){ 0.0f, -0.0f, 0.0f, 1.0f });
    glRasterPos3f(0.2f, 0.3f, 0.4f);
    rp_query(h, "nan material lit");
}

/* Inside glBegin/glEnd: INVALID_OPERATION, nothing changes. */
static void rp_errors(fc_h *h)
{
    glViewport(0, 0, 16, 16);
    glRasterPos2f(0.5f, 0.5f);
    glBegin(GL_POINTS);
    glRasterPos2f(-0.5f, -0.25f);
    glRasterPos4dv((const GLdouble[]){ 0.1, 0.2, 0.3, 1 });
    glEnd();
    rp_query(h, "inside begin");
    glBegin(GL_LINES);
    glRasterPos2f(5.0f, 5.0f);
    glEnd();
    rp_query(h, "clipped inside begin");
}

/* Compiled into display lists: GL_COMPILE, GL_COMPILE_AND_EXECUTE,
 * executed under a different transform. */
static void rp_dlist(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_ortho(-2, 2, -2, 2, -2, 2);
    GLuint l = glGenLists(2);
    glNewList(l, GL_COMPILE);
    glColor3f(0.3f, 0.6f, 0.9f);
    glRasterPos2d(0.30000001, -0.7);
    glEndList();
    rp_query(h, "after compile");
    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    glRasterPos3s(1, -1, 1);
    glRasterPos4iv((const GLint[]){ 1, 1, 1, 2 });
    glEndList();
    rp_query(h, "compile and execute");
    glCallList(l);
    rp_query(h, "call list");
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.5f, 0.25f, 0);
    glCallList(l + 1);
    rp_query(h, "call list translated");
    glNewList(l, GL_COMPILE);
    glBegin(GL_POINTS);
    glRasterPos2f(0.1f, 0.1f);
    glEnd();
    glEndList();
    rp_query(h, "compiled inside begin");
    glCallList(l);
    rp_query(h, "call list begin");
    /* a list with a raster position called between glBegin and glEnd */
    glNewList(l, GL_COMPILE);
    glRasterPos2f(-0.3f, 0.6f);
    glEndList();
    glBegin(GL_POINTS);
    glVertex2f(0.1f, 0.1f);
    glCallList(l);
    glEnd();
    rp_query(h, "call list inside begin");
    glDeleteLists(l, 2);
}

/* glPushAttrib(GL_CURRENT_BIT) saves the raster state, glPopAttrib
 * restores it (valid flag included); other bits do not. */
static void rp_attrib(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glColor3f(0.2f, 0.3f, 0.4f);
    glRasterPos3f(0.1f, 0.2f, 0.3f);
    glPushAttrib(GL_CURRENT_BIT);
    glColor3f(0.9f, 0.8f, 0.7f);
    glRasterPos3f(-0.5f, 0.6f, -0.7f);
    rp_query(h, "pushed");
    glRasterPos3f(3, 0, 0);
    rp_query(h, "pushed clipped");
    glPopAttrib();
    rp_query(h, "popped");
    glRasterPos3f(3, 0, 0);
    glPushAttrib(GL_ALL_ATTRIB_BITS & ~GL_CURRENT_BIT);
    glRasterPos3f(0.5f, 0.5f, 0.5f);
    glPopAttrib();
    rp_query(h, "other bits");
    glPushAttrib(GL_CURRENT_BIT);
    glPopAttrib();
    rp_query(h, "push pop valid");
}

/* In GL_SELECT a valid raster position is a hit at its window z; a
 * clipped one is not; GL_FEEDBACK writes nothing. */
static void rp_select_feedback(fc_h *h)
{
    static GLuint sel[64];
    static GLfloat fb[64];
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    for (int i = 0; i < 64; i++)
        sel[i] = 0xabababu;
    glSelectBuffer(64, sel);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(7);
    glRasterPos3f(0.1f, 0.2f, 0.3f);
    glRasterPos3f(0.1f, 0.2f, -0.6f);
    glLoadName(8);
    glRasterPos3f(3.0f, 0.2f, 0.3f);
    glLoadName(9);
    glRasterPos3f(0.1f, 0.2f, 0.9f);
    fc_value(h, "select hits", glRenderMode(GL_RENDER));
    fc_blob(h, "select buffer", sel, sizeof sel);
    rp_query(h, "after select");
    for (int i = 0; i < 64; i++)
        fb[i] = -12345.0f;
    glFeedbackBuffer(64, GL_3D_COLOR_TEXTURE, fb);
    glRenderMode(GL_FEEDBACK);
    glRasterPos3f(0.4f, -0.2f, 0.1f);
    glPassThrough(1.0f);
    glRasterPos3f(-0.4f, 0.2f, 0.1f);
    fc_value(h, "feedback count", glRenderMode(GL_RENDER));
    fc_blob(h, "feedback buffer", fb, sizeof fb);
    rp_query(h, "after feedback");
}

const fc_case fc_cases_rasterpos[] = {
    FC_CASE_RGBA("pixel/rasterpos_transform", 48, 40, 0, "pixel rasterpos", rp_transform),
    FC_CASE_RGBA("pixel/rasterpos_clipped", 32, 32, 0, "pixel rasterpos clip", rp_clipped),
    FC_CASE_RGBA("pixel/rasterpos_user_planes", 32, 32, 0, "pixel rasterpos clip", rp_user_planes),
    FC_CASE_RGBA("pixel/rasterpos_variants", 64, 52, 0, "pixel rasterpos", rp_variants),
    FC_CASE_RGBA("pixel/rasterpos_fog_distance", 32, 32, 0, "pixel rasterpos fog", rp_fog_distance),
    FC_CASE_RGBA("pixel/rasterpos_color_texcoord", 16, 16, 0, "pixel rasterpos", rp_color_texcoord),
    FC_CASE_RGBA("pixel/rasterpos_lit", 32, 32, 0, "pixel rasterpos light", rp_lit),
    FC_CASE_RGBA("pixel/rasterpos_robust", 16, 16, 0, "pixel rasterpos robust", rp_robust),
    FC_CASE_RGBA("pixel/rasterpos_errors", 16, 16, 0, "pixel rasterpos errors", rp_errors),
    FC_CASE_RGBA("pixel/rasterpos_dlist", 32, 32, 0, "pixel rasterpos dlist", rp_dlist),
    FC_CASE_RGBA("pixel/rasterpos_attrib", 32, 32, 0, "pixel rasterpos attrib", rp_attrib),
    FC_CASE_RGBA("pixel/rasterpos_select_feedback", 32, 32, 0, "pixel rasterpos select",
                 rp_select_feedback),
    { 0 }
};
