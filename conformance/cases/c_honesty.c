/* c_honesty.c - GL 1.5 honesty (tag honesty; README "Version and
 * honesty", issue 19): the enums of later GL versions and of extensions
 * fixgl does not list, called the way the GL 1.5 cases called them before
 * those cases were limited to GL 1.5.  fixgl raises GL_INVALID_ENUM for
 * each, as the GL 1.5 specification requires of an implementation
 * without the version or extension; the oracle implements GL 4.5 and
 * accepts them.  Every case here differs from the oracle by design and is
 * listed in known-differences.txt; the run still records the errors and
 * results, so a change on either side shows (a case that became exact is
 * reported as stale).  The pixel formats and types have their honesty
 * cases next to the pixel cases (c_pix_format.c, c_pix_draw.c), the
 * sprite origin's textured scenes in c_gl14_sprite.c. */
#define GL_GLEXT_PROTOTYPES 1
#include "cases.h"

#include <stdio.h>
#include <string.h>

/* ---- primitive modes: GL 3.2's adjacency modes, GL 4.0's patches ---- */
static void primitive_modes(fc_h *h)
{
    static const struct { GLenum mode; const char *name; } modes[] = {
        { GL_LINES_ADJACENCY, "lines adjacency" },
        { GL_LINE_STRIP_ADJACENCY, "line strip adjacency" },
        { GL_TRIANGLES_ADJACENCY, "triangles adjacency" },
        { GL_TRIANGLE_STRIP_ADJACENCY, "triangle strip adjacency" },
        { GL_PATCHES, "patches" },
    };
    static const GLfloat v[6][2] = { { 2, 2 }, { 28, 4 }, { 6, 28 }, { 30, 30 }, { 16, 2 }, { 2, 16 } };
    static const GLubyte idx[6] = { 0, 1, 2, 3, 4, 5 };
    char l[96];
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        glColor3f(0.2f + 0.15f * (float)i, 1.0f, 0.5f);
        glBegin(modes[i].mode);
        for (int k = 0; k < 6; k++)
            glVertex2fv(v[k]);
        glEnd();
        snprintf(l, sizeof l, "glBegin %s", modes[i].name);
        fc_error(h, l);
        glDrawArrays(modes[i].mode, 0, 6);
        snprintf(l, sizeof l, "arrays %s", modes[i].name);
        fc_error(h, l);
        glDrawElements(modes[i].mode, 6, GL_UNSIGNED_BYTE, idx);
        snprintf(l, sizeof l, "elements %s", modes[i].name);
        fc_error(h, l);
        glDrawRangeElements(modes[i].mode, 0, 5, 6, GL_UNSIGNED_BYTE, idx);
        snprintf(l, sizeof l, "range elements %s", modes[i].name);
        fc_error(h, l);
    }
    glDrawArrays(GL_PATCHES, -1, 3);
    fc_error(h, "GL_PATCHES, first -1");
    /* compiled: the error when the list is made */
    const GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_TRIANGLES_ADJACENCY);
    glVertex2f(1, 1);
    glEnd();
    glDrawArrays(GL_LINES_ADJACENCY, 0, 4);
    glEndList();
    fc_error(h, "compiled adjacency");
    glCallList(list);
    fc_error(h, "called adjacency");
    glDeleteLists(list, 1);
    glDisableClientState(GL_VERTEX_ARRAY);
    fc_capture(h);
}

/* ---- blend factors: ARB_blend_func_extended's dual-source factors ---- */
static void blend_factors(fc_h *h)
{
    glBlendFunc(GL_SRC1_ALPHA, GL_ONE_MINUS_SRC1_COLOR);
    fc_error(h, "glBlendFunc SRC1");
    fc_get_integer(h, "GL_BLEND_SRC SRC1", GL_BLEND_SRC, 1);
    fc_get_integer(h, "GL_BLEND_DST SRC1", GL_BLEND_DST, 1);
    glBlendFunc(GL_ONE_MINUS_SRC1_ALPHA, GL_SRC1_COLOR);
    fc_error(h, "glBlendFunc SRC1 b");
    glBlendFuncSeparate(GL_SRC1_COLOR, GL_ONE, GL_ONE, GL_ONE_MINUS_SRC1_ALPHA);
    fc_error(h, "glBlendFuncSeparate SRC1");
    fc_get_integer(h, "GL_BLEND_SRC_RGB", GL_BLEND_SRC_RGB, 1);
    fc_get_integer(h, "GL_BLEND_DST_ALPHA", GL_BLEND_DST_ALPHA, 1);
}

/* ---- texture targets: ARB_texture_rectangle, EXT_texture_array ---- */
static void rect_params(fc_h *h, const char *label, GLenum target)
{
    static const GLenum pnames[] = { GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER,
                                     GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R,
                                     GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL,
                                     GL_TEXTURE_PRIORITY };
    GLint iv[8];
    GLfloat fv[8];
    char l[96];
    for (size_t i = 0; i < 8; i++) {
        iv[i] = -77;
        fv[i] = -77.0f;
        glGetTexParameteriv(target, pnames[i], &iv[i]);
        glGetTexParameterfv(target, pnames[i], &fv[i]);
    }
    snprintf(l, sizeof l, "%s iv", label);
    fc_blob(h, l, iv, sizeof iv);
    snprintf(l, sizeof l, "%s fv", label);
    fc_blob(h, l, fv, sizeof fv);
    snprintf(l, sizeof l, "%s error", label);
    fc_error(h, l);
}

static void texture_targets(fc_h *h)
{
    GLuint t[5] = { 0, 0, 0, 0, 0 };
    GLint v = -5;
    static GLubyte readback[4 * 16 + 16];
    glGenTextures(3, t);
    glBindTexture(GL_TEXTURE_RECTANGLE, 77);
    fc_error(h, "rectangle, new name");
    fc_value(h, "is 77", glIsTexture(77));
    glGenTextures(2, t + 3);
    fc_blob(h, "gen after 77", t, sizeof t);
    const GLclampf half = 0.5f;
    glPrioritizeTextures(1, &t[4], &half);
    glBindTexture(GL_TEXTURE_RECTANGLE, t[4]);
    rect_params(h, "rect first bound", GL_TEXTURE_RECTANGLE);
    glBindTexture(GL_TEXTURE_RECTANGLE, 0);
    rect_params(h, "default rect", GL_TEXTURE_RECTANGLE);
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    fc_error(h, "rect min mipmap");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_S, GL_REPEAT);
    fc_error(h, "rect wrap repeat");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_BASE_LEVEL, 1);
    fc_error(h, "rect base 1");
    rect_params(h, "rect after sets", GL_TEXTURE_RECTANGLE);
    glEnable(GL_TEXTURE_RECTANGLE);
    fc_error(h, "enable rectangle");
    fc_is_enabled(h, "rectangle enabled", GL_TEXTURE_RECTANGLE);
    glDisable(GL_TEXTURE_RECTANGLE);
    fc_get_integer(h, "rectangle binding", GL_TEXTURE_BINDING_RECTANGLE, 1);
    glBindTexture(GL_TEXTURE_1D_ARRAY, t[0]);
    fc_error(h, "1d array bind");
    glBindTexture(GL_TEXTURE_2D_ARRAY, t[1]);
    fc_error(h, "2d array bind");
    glGetTexImage(GL_TEXTURE_RECTANGLE, 1, GL_RGBA, GL_UNSIGNED_BYTE, readback);
    fc_error(h, "get rect level 1");
    glGetTexLevelParameteriv(GL_TEXTURE_RECTANGLE, 1, GL_TEXTURE_WIDTH, &v);
    fc_error(h, "lp rect level 1");
    glGetTexLevelParameteriv(GL_TEXTURE_RECTANGLE, 0, GL_TEXTURE_WIDTH, &v);
    fc_error(h, "lp rect level 0");
    glGetTexLevelParameteriv(GL_TEXTURE_1D_ARRAY, 2, GL_TEXTURE_WIDTH, &v);
    fc_error(h, "lp 1d array level 2");
    fc_value(h, "lp value", v);
    glDeleteTextures(5, t);
}

/* ---- matrix modes: ARB_vertex_program's GL_MATRIX0_ARB.. ---- */
static void matrix_modes(fc_h *h)
{
    char l[64];
    for (int i = 0; i < 8; i++) {
        glMatrixMode(GL_MATRIX0_ARB + (GLenum)i);
        snprintf(l, sizeof l, "glMatrixMode(GL_MATRIX%d_ARB)", i);
        fc_error(h, l);
        fc_get_integer(h, l, GL_MATRIX_MODE, 1);
        glTranslatef(1.0f + (float)i, 2.0f, 3.0f);
        snprintf(l, sizeof l, "translate MATRIX%d", i);
        fc_error(h, l);
        glMatrixMode(GL_MODELVIEW);
        fc_get_float(h, l, GL_MODELVIEW_MATRIX, 16);
    }
    glMatrixMode(GL_MATRIX0_ARB + 8);
    fc_error(h, "glMatrixMode(GL_MATRIX0_ARB + 8)");
}

/* ---- hints: GL 2.0's GL_FRAGMENT_SHADER_DERIVATIVE_HINT ---- */
static void hints(fc_h *h)
{
    static const GLenum modes[3] = { GL_FASTEST, GL_NICEST, GL_DONT_CARE };
    char l[96];
    fc_get_integer(h, "GL_FRAGMENT_SHADER_DERIVATIVE_HINT default",
                   GL_FRAGMENT_SHADER_DERIVATIVE_HINT, 1);
    fc_error(h, "default error");
    for (int m = 0; m < 3; m++) {
        glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, modes[m]);
        snprintf(l, sizeof l, "GL_FRAGMENT_SHADER_DERIVATIVE_HINT set %d", m);
        fc_error(h, l);
        fc_get_integer(h, l, GL_FRAGMENT_SHADER_DERIVATIVE_HINT, 1);
    }
    glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_LINEAR);
    fc_error(h, "bad mode");
    glPushAttrib(GL_HINT_BIT);
    glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_FASTEST);
    glPopAttrib();
    fc_get_integer(h, "popped", GL_FRAGMENT_SHADER_DERIVATIVE_HINT, 1);
    fc_error(h, "popped error");
}

/* ---- point sprite origin: GL 2.0's GL_POINT_SPRITE_COORD_ORIGIN ---- */
static void point_sprite_origin(fc_h *h)
{
    fc_get_float(h, "default", GL_POINT_SPRITE_COORD_ORIGIN, 1);
    fc_get_integer(h, "default", GL_POINT_SPRITE_COORD_ORIGIN, 1);
    fc_error(h, "default error");
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    fc_error(h, "origin");
    fc_get_integer(h, "origin", GL_POINT_SPRITE_COORD_ORIGIN, 1);
    glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, (GLfloat)GL_UPPER_LEFT);
    fc_error(h, "origin f");
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LEFT);
    fc_error(h, "bad origin");
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    glPushAttrib(GL_POINT_BIT);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    glPopAttrib();
    fc_get_integer(h, "point popped", GL_POINT_SPRITE_COORD_ORIGIN, 1);
    fc_error(h, "popped error");
}

/* ---- glGet of values fixgl does not have ---- */
static void get_pnames(fc_h *h)
{
    static const struct { GLenum e; const char *name; } q[] = {
        { GL_FRAGMENT_SHADER_DERIVATIVE_HINT, "GL_FRAGMENT_SHADER_DERIVATIVE_HINT" },
        { GL_VIEWPORT_BOUNDS_RANGE, "GL_VIEWPORT_BOUNDS_RANGE" },
        { GL_MAX_TEXTURE_COORDS, "GL_MAX_TEXTURE_COORDS" },
        { GL_POINT_SPRITE_COORD_ORIGIN, "GL_POINT_SPRITE_COORD_ORIGIN" },
        { GL_CURRENT_RASTER_SECONDARY_COLOR, "GL_CURRENT_RASTER_SECONDARY_COLOR" },
    };
    char l[96];
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
        fc_get_integer(h, q[i].name, q[i].e, 4);
        fc_error(h, q[i].name);
        fc_get_float(h, q[i].name, q[i].e, 4);
        fc_error(h, q[i].name);
        fc_get_double(h, q[i].name, q[i].e, 4);
        fc_error(h, q[i].name);
        fc_get_boolean(h, q[i].name, q[i].e, 4);
        fc_error(h, q[i].name);
        snprintf(l, sizeof l, "glIsEnabled(%s)", q[i].name);
        fc_is_enabled(h, l, q[i].e);
        fc_error(h, l);
    }
    /* the same after glActiveTexture(GL_TEXTURE7) (a GL_MAX_TEXTURE_COORDS
     * query used to precede it) */
    glActiveTexture(GL_TEXTURE7);
    fc_error(h, "active 7");
    fc_get_integer(h, "active 7", GL_ACTIVE_TEXTURE, 1);
    glActiveTexture(GL_TEXTURE0);
}

/* ---- glGetTexLevelParameter's GL 3.0 pnames ---- */
static void tex_level_pnames(fc_h *h)
{
    static const struct { GLenum e; const char *name; } q[] = {
        { GL_TEXTURE_RED_TYPE, "GL_TEXTURE_RED_TYPE" },
        { GL_TEXTURE_GREEN_TYPE, "GL_TEXTURE_GREEN_TYPE" },
        { GL_TEXTURE_BLUE_TYPE, "GL_TEXTURE_BLUE_TYPE" },
        { GL_TEXTURE_ALPHA_TYPE, "GL_TEXTURE_ALPHA_TYPE" },
        { GL_TEXTURE_LUMINANCE_TYPE, "GL_TEXTURE_LUMINANCE_TYPE" },
        { GL_TEXTURE_INTENSITY_TYPE, "GL_TEXTURE_INTENSITY_TYPE" },
        { GL_TEXTURE_DEPTH_TYPE, "GL_TEXTURE_DEPTH_TYPE" },
        { GL_TEXTURE_STENCIL_SIZE, "GL_TEXTURE_STENCIL_SIZE" },
        { GL_TEXTURE_SHARED_SIZE, "GL_TEXTURE_SHARED_SIZE" },
        { GL_TEXTURE_SAMPLES, "GL_TEXTURE_SAMPLES" },
        { GL_TEXTURE_FIXED_SAMPLE_LOCATIONS, "GL_TEXTURE_FIXED_SAMPLE_LOCATIONS" },
        { GL_TEXTURE_BUFFER_DATA_STORE_BINDING, "GL_TEXTURE_BUFFER_DATA_STORE_BINDING" },
        { GL_TEXTURE_BUFFER_OFFSET, "GL_TEXTURE_BUFFER_OFFSET" },
        { GL_TEXTURE_BUFFER_SIZE, "GL_TEXTURE_BUFFER_SIZE" },
    };
    static const GLubyte px[4 * 4 * 4] = { 10, 20, 30, 40, 50, 60, 70, 80 };
    static const GLint internals[] = { GL_RGBA8, GL_LUMINANCE8, GL_ALPHA8, GL_INTENSITY8 };
    char l[128];
    for (size_t k = 0; k < sizeof internals / sizeof internals[0]; k++) {
        glTexImage2D(GL_TEXTURE_2D, 0, internals[k], 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
        for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
            GLint iv = -77;
            GLfloat fv = -77.0f;
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, q[i].e, &iv);
            snprintf(l, sizeof l, "internal %#x %s iv", internals[k], q[i].name);
            fc_error(h, l);
            fc_value(h, l, iv);
            glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, q[i].e, &fv);
            snprintf(l, sizeof l, "internal %#x %s fv error", internals[k], q[i].name);
            fc_error(h, l);
        }
    }
}

/* ---- GL 3.0's GL_CURRENT_RASTER_SECONDARY_COLOR query (as
 * gl14/rasterpos and the pixel/rasterpos_* cases made it) ---- */
static void rasterpos_secondary_color(fc_h *h)
{
    fc_pixel_ortho(h);
    fc_get_float(h, "initial secondary", GL_CURRENT_RASTER_SECONDARY_COLOR, 4);
    fc_error(h, "initial error");
    glSecondaryColor3f(0.3f, 1.5f, -0.25f);
    glFogCoordf(-2.5f);
    glRasterPos2f(10, 10);
    fc_get_float(h, "raster secondary", GL_CURRENT_RASTER_SECONDARY_COLOR, 4);
    fc_error(h, "raster error");
    glWindowPos2f(3, 4);
    fc_get_float(h, "window secondary", GL_CURRENT_RASTER_SECONDARY_COLOR, 4);
    fc_error(h, "window error");
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glRasterPos2f(12, 12);
    fc_get_float(h, "lit raster secondary", GL_CURRENT_RASTER_SECONDARY_COLOR, 4);
    fc_error(h, "lit raster error");
    glDisable(GL_LIGHTING);
    glRasterPos4f(1e30f, 0, 0, 1);
    fc_get_float(h, "clipped secondary", GL_CURRENT_RASTER_SECONDARY_COLOR, 4);
    fc_error(h, "clipped error");
}

const fc_case fc_cases_honesty[] = {
    FC_CASE_RGBA("honesty/primitive_modes", 32, 32, 1, "honesty api varray", primitive_modes),
    FC_CASE("honesty/blend_factors", 16, 16, OSMESA_RGBA, 24, 0, 0,
            "honesty api fragment blend", blend_factors),
    FC_CASE("honesty/texture_targets", 16, 16, OSMESA_RGBA, 24, 0, 0,
            "honesty api texture texstate", texture_targets),
    FC_CASE("honesty/matrix_modes", 16, 16, OSMESA_RGBA, 24, 0, 0,
            "honesty api matrix", matrix_modes),
    FC_CASE("honesty/hints", 16, 16, OSMESA_RGBA, 24, 0, 0, "honesty api fog hint",
            hints),
    FC_CASE("honesty/point_sprite_origin", 16, 16, OSMESA_RGBA, 24, 0, 0,
            "honesty api gl14 points sprite", point_sprite_origin),
    FC_CASE("honesty/get_pnames", 16, 16, OSMESA_RGBA, 24, 0, 0, "honesty api query",
            get_pnames),
    FC_CASE("honesty/tex_level_pnames", 16, 16, OSMESA_RGBA, 24, 0, 0,
            "honesty api texture query", tex_level_pnames),
    FC_CASE("honesty/rasterpos_secondary_color", 32, 32, OSMESA_RGBA, 24, 0, 0,
            "honesty pixel gl14 rasterpos seccolor query", rasterpos_secondary_color),
    { 0 }
};
