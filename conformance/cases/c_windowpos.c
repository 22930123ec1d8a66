/* c_windowpos.c - glWindowPos (GL 1.4, declared by <GL/glext.h> with
 * GL_GLEXT_PROTOTYPES): every variant, z mapped into the depth range and
 * clamped, the raster colour clamped and texture coordinates copied
 * without the texture matrix, the valid bit set after a clipped
 * glRasterPos, display lists, selection, glPushAttrib, errors. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>

#include "cases.h"

static void wp_query(fc_h *h, const char *label)
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
    snprintf(l, sizeof l, "%s texcoords", label);
    fc_get_float(h, l, GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
    snprintf(l, sizeof l, "%s error", label);
    fc_error(h, l);
}

/* Every variant, under a depth range, with z below, inside and above
 * [0, 1]; a clamped colour; texture coordinates under a texture matrix
 * (which glWindowPos ignores); a modelview that glWindowPos ignores. */
static void wp_variants(fc_h *h)
{
    static const GLshort s2[2] = { 3, 4 }, s3[3] = { -5, 6, 1 };
    static const GLint i2[2] = { 7, -8 }, i3[3] = { 9, 10, 0 };
    static const GLfloat f2[2] = { 1.25f, 2.75f }, f3[3] = { 11.5f, -12.25f, 0.375f };
    static const GLdouble d2[2] = { 13.125, 14.0625 }, d3[3] = { 15.5, 16.5, 0.7 };
    glDepthRange(0.25, 0.8);
    glMatrixMode(GL_MODELVIEW);
    glRotatef(30.0f, 0, 0, 1);
    glMatrixMode(GL_TEXTURE);
    glScalef(2, 3, 4);
    glMatrixMode(GL_MODELVIEW);
    glColor4f(1.5f, -0.5f, 0.25f, 0.75f);
    glTexCoord4f(0.1f, 0.2f, 0.3f, 0.4f);
    wp_query(h, "initial");
    glWindowPos2s(1, 2);     wp_query(h, "2s");
    glWindowPos2i(-3, 40);   wp_query(h, "2i");
    glWindowPos2f(0.5f, 1.5f); wp_query(h, "2f");
    glWindowPos2d(2.25, -3.5); wp_query(h, "2d");
    glWindowPos3s(4, 5, 1);  wp_query(h, "3s");
    glWindowPos3i(6, 7, 2);  wp_query(h, "3i z above");
    glWindowPos3f(8.5f, 9.5f, -0.5f); wp_query(h, "3f z below");
    glWindowPos3f(8.5f, 9.5f, 0.3f); wp_query(h, "3f z inside");
    glWindowPos3d(10.75, 11.25, 0.9); wp_query(h, "3d");
    glWindowPos2sv(s2);  wp_query(h, "2sv");
    glWindowPos2iv(i2);  wp_query(h, "2iv");
    glWindowPos2fv(f2);  wp_query(h, "2fv");
    glWindowPos2dv(d2);  wp_query(h, "2dv");
    glWindowPos3sv(s3);  wp_query(h, "3sv");
    glWindowPos3iv(i3);  wp_query(h, "3iv");
    glWindowPos3fv(f3);  wp_query(h, "3fv");
    glWindowPos3dv(d3);  wp_query(h, "3dv");
    glDepthRange(0.9, 0.1);
    glWindowPos3f(1, 2, 0.25f); wp_query(h, "reversed depth range");
}

/* A clipped glRasterPos leaves the position invalid; glWindowPos makes
 * it valid again; glRasterPos's lighting does not apply. */
static void wp_valid(fc_h *h)
{
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glRasterPos3f(5.0f, 0.0f, 0.0f);
    wp_query(h, "clipped");
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glColor3f(0.3f, 0.6f, 0.9f);
    glWindowPos2f(3.0f, 4.0f);
    wp_query(h, "window pos lit");
    glRasterPos2f(0.0f, 0.0f);
    wp_query(h, "raster pos lit");
}

/* Compiled (every variant stored as four floats) and replayed; compile
 * and execute; glPushAttrib(GL_CURRENT_BIT) restores it. */
static void wp_dlist(fc_h *h)
{
    GLuint l = glGenLists(2);
    glDepthRange(0.2, 0.6);
    glNewList(l, GL_COMPILE);
    glWindowPos3d(5.5, 6.5, 0.5);
    glEndList();
    wp_query(h, "compiled");
    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    glWindowPos2i(7, 9);
    glEndList();
    wp_query(h, "compile and execute");
    glCallList(l);
    wp_query(h, "call list");
    glDepthRange(0.5, 1.0);
    glCallList(l);
    wp_query(h, "call list new depth range");
    glPushAttrib(GL_CURRENT_BIT);
    glWindowPos2f(20.0f, 21.0f);
    glPopAttrib();
    wp_query(h, "popped");
    glDeleteLists(l, 2);
}

/* A hit record at the window z; GL_INVALID_OPERATION inside glBegin. */
static void wp_select_errors(fc_h *h)
{
    static GLuint sel[32];
    for (int i = 0; i < 32; i++)
        sel[i] = 0xcdcdcdu;
    glSelectBuffer(32, sel);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(3);
    glWindowPos3f(1, 1, 0.25f);
    glWindowPos3f(1, 1, 0.75f);
    fc_value(h, "select hits", glRenderMode(GL_RENDER));
    fc_blob(h, "select buffer", sel, sizeof sel);
    glWindowPos2f(2, 3);
    glBegin(GL_POINTS);
    glWindowPos2f(9, 9);
    glEnd();
    wp_query(h, "inside begin");
    /* and it draws nothing by itself */
    fc_capture(h);
}

const fc_case fc_cases_windowpos[] = {
    FC_CASE_RGBA("pixel/windowpos_variants", 48, 40, 0, "pixel rasterpos windowpos", wp_variants),
    FC_CASE_RGBA("pixel/windowpos_valid", 32, 32, 0, "pixel rasterpos windowpos", wp_valid),
    FC_CASE_RGBA("pixel/windowpos_dlist", 32, 32, 0, "pixel rasterpos windowpos dlist", wp_dlist),
    /* glWindowPos draws nothing by itself (draws_nothing) */
    FC_CASE_NODRAW("pixel/windowpos_select_errors", 16, 16, OSMESA_RGBA, 24, 0, 1,
                   "pixel rasterpos windowpos select", wp_select_errors),
    { 0 }
};
