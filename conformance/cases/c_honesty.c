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

/* ---- vertex array types: GL 3.0's GL_HALF_FLOAT (ARB_half_float_vertex),
 * GL 3.3's packed GL_(UNSIGNED_)INT_2_10_10_10_REV
 * (ARB_vertex_type_2_10_10_10_rev) and GL 3.2's GL_BGRA size of the colour
 * arrays (ARB/EXT_vertex_array_bgra), through every pointer call and its
 * EXT name, with the state each leaves (as varray/pointer_errors,
 * varray/queries, gl14/seccolor_api and gl14/fogcoord_api called them
 * before they were limited to GL 1.5).  Without the extensions GL 1.5
 * raises GL_INVALID_ENUM for the types and GL_INVALID_VALUE for the
 * GL_BGRA size (a bad size), and keeps the array's state. ---- */
static void varray_pointer_types(fc_h *h)
{
    static GLuint data[64];
    static const struct { GLint size; GLenum type; GLsizei stride; } calls[] = {
        { 4, GL_HALF_FLOAT, 0 }, { 3, GL_HALF_FLOAT, 6 }, { 1, GL_HALF_FLOAT, 0 },
        { 4, GL_INT_2_10_10_10_REV, 0 }, { 3, GL_INT_2_10_10_10_REV, 0 },
        { 4, GL_UNSIGNED_INT_2_10_10_10_REV, 8 }, { 3, GL_UNSIGNED_INT_2_10_10_10_REV, 0 },
        { GL_BGRA, GL_UNSIGNED_BYTE, 0 }, { GL_BGRA, GL_UNSIGNED_BYTE, 8 },
        { GL_BGRA, GL_UNSIGNED_BYTE, -2 }, { GL_BGRA, GL_FLOAT, 0 },
        { GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, 12 }, { GL_BGRA, GL_INT_2_10_10_10_REV, 0 },
        { GL_BGRA, GL_HALF_FLOAT, 0 }, { 4, GL_UNSIGNED_INT_10F_11F_11F_REV, 0 },
    };
    static const struct { const char *name; GLenum size_q, type_q, stride_q, ptr_q; } arrays[] = {
        { "vertex", GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE,
          GL_VERTEX_ARRAY_POINTER },
        { "normal", 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE, GL_NORMAL_ARRAY_POINTER },
        { "colour", GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE,
          GL_COLOR_ARRAY_POINTER },
        { "texcoord", GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE,
          GL_TEXTURE_COORD_ARRAY_STRIDE, GL_TEXTURE_COORD_ARRAY_POINTER },
        { "secondary", GL_SECONDARY_COLOR_ARRAY_SIZE, GL_SECONDARY_COLOR_ARRAY_TYPE,
          GL_SECONDARY_COLOR_ARRAY_STRIDE, GL_SECONDARY_COLOR_ARRAY_POINTER },
        { "fog", 0, GL_FOG_COORD_ARRAY_TYPE, GL_FOG_COORD_ARRAY_STRIDE, GL_FOG_COORD_ARRAY_POINTER },
        { "colour EXT", GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE,
          GL_COLOR_ARRAY_POINTER },
        { "vertex EXT", GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE,
          GL_VERTEX_ARRAY_POINTER },
        { "normal EXT", 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE, GL_NORMAL_ARRAY_POINTER },
        { "texcoord EXT", GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE,
          GL_TEXTURE_COORD_ARRAY_STRIDE, GL_TEXTURE_COORD_ARRAY_POINTER },
        { "secondary EXT", GL_SECONDARY_COLOR_ARRAY_SIZE, GL_SECONDARY_COLOR_ARRAY_TYPE,
          GL_SECONDARY_COLOR_ARRAY_STRIDE, GL_SECONDARY_COLOR_ARRAY_POINTER },
        { "fog EXT", 0, GL_FOG_COORD_ARRAY_TYPE, GL_FOG_COORD_ARRAY_STRIDE,
          GL_FOG_COORD_ARRAY_POINTER },
    };
    char l[96];
    for (size_t a = 0; a < sizeof arrays / sizeof arrays[0]; a++) {
        for (size_t i = 0; i < sizeof calls / sizeof calls[0]; i++) {
            const GLint sz = calls[i].size;
            const GLenum ty = calls[i].type;
            const GLsizei st = calls[i].stride;
            const GLvoid *p = data + i;
            switch (a) {
            case 0: glVertexPointer(sz, ty, st, p); break;
            case 1: glNormalPointer(ty, st, p); break;
            case 2: glColorPointer(sz, ty, st, p); break;
            case 3: glTexCoordPointer(sz, ty, st, p); break;
            case 4: glSecondaryColorPointer(sz, ty, st, p); break;
            case 5: glFogCoordPointer(ty, st, p); break;
            case 6: glColorPointerEXT(sz, ty, st, 4, p); break;
            case 7: glVertexPointerEXT(sz, ty, st, 4, p); break;
            case 8: glNormalPointerEXT(ty, st, 4, p); break;
            case 9: glTexCoordPointerEXT(sz, ty, st, 4, p); break;
            case 10: glSecondaryColorPointerEXT(sz, ty, st, p); break;
            default: glFogCoordPointerEXT(ty, st, p); break;
            }
            snprintf(l, sizeof l, "%s size %#x type %#x stride %d", arrays[a].name,
                     (unsigned)sz, ty, (int)st);
            fc_error(h, l);
            if (arrays[a].size_q)
                fc_get_integer(h, l, arrays[a].size_q, 1);
            fc_get_integer(h, l, arrays[a].type_q, 1);
            fc_get_integer(h, l, arrays[a].stride_q, 1);
            GLvoid *q = NULL;
            glGetPointerv(arrays[a].ptr_q, &q);
            fc_value(h, l, q == NULL ? -1 : (long long)((const GLuint *)q - data));
        }
    }
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
    FC_CASE("honesty/varray_pointer_types", 8, 8, OSMESA_RGBA, 24, 0, 0,
            "honesty api varray gl14 seccolor fogcoord query", varray_pointer_types),
    { 0 }
};
