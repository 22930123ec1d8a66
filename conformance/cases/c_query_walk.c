/* c_query_walk.c - state queries walked over every GL 1.3 state value
 * (tag "api query"): each enum through glGetIntegerv, glGetFloatv,
 * glGetDoublev, glGetBooleanv and glIsEnabled, with the error each raises,
 * at the initial state and after setting every state fixgl has a setter
 * for; conversions, bad input, strings, extensions, glGetPointerv,
 * OSMesaGetProcAddress; the colour-index calls and glDrawBuffer /
 * glReadBuffer of an RGBA-only, single-buffered OSMesa context.
 *
 * Only documented, intentional differences may differ
 * (fc_documented_difference): fixgl's implementation strings, its empty
 * compressed texture format list, and OSMesaGetProcAddress answering NULL
 * for functions fixgl lacks. */
#include "cases.h"
#include "fc_rng.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct qenum { GLenum e; const char *name; };
#define Q(e) { e, #e }

/* GL 1.3 state tables 6.5-6.31 (the imaging subset, which the oracle does
 * not support, is walked for its INVALID_ENUM), with the GL 1.2-1.4 and
 * extension values of features fixgl implements.  Not walked: values that
 * belong to extensions and later versions fixgl does not implement (the
 * oracle answers hundreds; fixgl raises INVALID_ENUM): GL_COLOR_SUM,
 * GL_MAX_TEXTURE_COORDS/IMAGE_UNITS, rectangle textures, anisotropy, vertex
 * attributes, and since GL 1.5 honesty (README "Version and honesty") no
 * value of a later version or unlisted extension either (GL 2.0's
 * GL_FRAGMENT_SHADER_DERIVATIVE_HINT, ARB_viewport_array's
 * GL_VIEWPORT_BOUNDS_RANGE): c_honesty.c records those as deliberate
 * differences. */
static const struct qenum walk[] = {
#include "query_walk_list.h"
};
#define NWALK (sizeof walk / sizeof walk[0])

/* Enough for the longest answer (the oracle's 12 compressed formats) and
 * the pre-filled pattern shows values written beyond it. */
#define WALK_COUNT 16

static void declare_walk_differences(fc_h *h)
{
    static const char why[] =
        "fixgl lists the compressed formats it implements, the three S3TC ones the oracle "
        "lists (DXT1 RGB, DXT3, DXT5); the oracle lists llvmpipe's 12, with FXT1 and ETC2/EAC";
    fc_documented_difference(h, "GL_NUM_COMPRESSED_TEXTURE_FORMATS", why);
    fc_documented_difference(h, "GL_COMPRESSED_TEXTURE_FORMATS", why);
}

static void walk_all(fc_h *h)
{
    char label[80];
    for (size_t i = 0; i < NWALK; i++) {
        fc_get_integer(h, walk[i].name, walk[i].e, WALK_COUNT);
        fc_error(h, walk[i].name);
        fc_get_float(h, walk[i].name, walk[i].e, WALK_COUNT);
        fc_error(h, walk[i].name);
        fc_get_double(h, walk[i].name, walk[i].e, WALK_COUNT);
        fc_error(h, walk[i].name);
        fc_get_boolean(h, walk[i].name, walk[i].e, WALK_COUNT);
        fc_error(h, walk[i].name);
        snprintf(label, sizeof label, "glIsEnabled(%s)", walk[i].name);
        fc_is_enabled(h, label, walk[i].e);
        fc_error(h, label);
    }
}

static void query_walk(fc_h *h)
{
    declare_walk_differences(h);
    walk_all(h);
}

/* Client-side arrays the modified walk points at (never drawn). */
static GLshort walk_vertices[64];

/* Every state value fixgl has a setter for, away from its initial value,
 * with values that exercise the conversions (half-way roundings,
 * normalised mappings of out-of-range colours, negative values). */
static void set_everything(fc_h *h, int nested)
{
    static const GLfloat ambient[4] = { 0.125f, -0.5f, 1.75f, 0.3f };
    static const GLfloat fogc[4] = { 0.1f, 0.9f, 0.5f, 0.25f };
    static const GLdouble plane[4] = { 1, -2, 0.5, 3 };
    static const GLenum hints[] = {
        GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT,
        GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT, GL_TEXTURE_COMPRESSION_HINT,
        GL_GENERATE_MIPMAP_HINT,
    };

    glPushAttrib(GL_ALL_ATTRIB_BITS);
    if (nested)
        glPushAttrib(GL_CURRENT_BIT | GL_FOG_BIT);
    glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    fc_error(h, "push");

    glColor4f(0.3f, -0.25f, 1.5f, 0.7f);
    glNormal3f(0.6f, -0.8f, 2.5f);
    glEdgeFlag(GL_FALSE);
    glIndexf(5.5f);
    glClearIndex(7.9f);
    glIndexMask(0x5a);
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glClearDepth(0.375);
    glClearStencil(5);
    glAlphaFunc(GL_GEQUAL, 0.4f);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
    glBlendColor(0.1f, 0.2f, 0.3f, 0.4f);
    glLogicOp(GL_XOR);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glScissor(1, 2, 10, 11);
    glStencilFunc(GL_LEQUAL, 3, 0x7f);
    glStencilOp(GL_KEEP, GL_INCR_WRAP, GL_DECR);
    glStencilMask(0x33);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glDepthRange(0.25, 0.875);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.5f);
    glFogf(GL_FOG_START, -2.5f);
    glFogf(GL_FOG_END, 7.5f);
    glFogfv(GL_FOG_COLOR, fogc);
    glFogf(GL_FOG_INDEX, 3.5f);
    glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE);
    glFrontFace(GL_CW);
    glCullFace(GL_FRONT_AND_BACK);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glPolygonOffset(1.5f, -2.5f);
    glShadeModel(GL_FLAT);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glColorMaterial(GL_BACK, GL_SPECULAR);
    glClipPlane(GL_CLIP_PLANE3, plane);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 2, -0.5, 0.75, 0.3, 7);
    glPushMatrix();
    glMatrixMode(GL_TEXTURE);
    glRotatef(30, 0, 0, 1);
    glPushMatrix();
    glScalef(2, 0.5f, 3);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(1.5f, -2.5f, 0.5f);
    glPushMatrix();
    glPushMatrix();
    glRotatef(-45, 1, 1, 0);
    glViewport(2, 3, 40, 30);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, 1);
    glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 5);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 6);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 7);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glPixelStorei(GL_PACK_SWAP_BYTES, 1);
    glPixelStorei(GL_PACK_LSB_FIRST, 1);
    glPixelStoref(GL_PACK_IMAGE_HEIGHT, 8.5f);
    glPixelStorei(GL_PACK_SKIP_IMAGES, 9);
    glPixelStorei(GL_PACK_ROW_LENGTH, 10);
    glPixelStorei(GL_PACK_SKIP_ROWS, 11);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 12);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPointSize(2.5f);
    glLineWidth(3.5f);
    glLineStipple(3, 0xf0f0);
    glListBase(7);
    for (size_t i = 0; i < sizeof hints / sizeof hints[0]; i++)
        glHint(hints[i], i % 2 ? GL_FASTEST : GL_NICEST);
    fc_error(h, "set state");

    /* every capability toggled from its initial value */
    glGetError();
    for (size_t i = 0; i < NWALK; i++) {
        GLboolean on = glIsEnabled(walk[i].e);
        if (glGetError() != GL_NO_ERROR)
            continue;       /* not a capability */
        if (on)
            glDisable(walk[i].e);
        else
            glEnable(walk[i].e);
    }
    fc_error(h, "toggle caps");

    glVertexPointer(3, GL_SHORT, 12, walk_vertices);
    glNormalPointer(GL_BYTE, 5, walk_vertices + 1);
    glColorPointer(4, GL_UNSIGNED_BYTE, 20, walk_vertices + 2);
    glIndexPointer(GL_SHORT, 6, walk_vertices + 3);
    glTexCoordPointer(2, GL_INT, 24, walk_vertices + 4);
    glEdgeFlagPointer(7, walk_vertices + 5);
    fc_error(h, "pointers");

    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_FRONT_AND_BACK);
    fc_error(h, "buffers");
}

static void query_walk_modified(fc_h *h)
{
    declare_walk_differences(h);
    set_everything(h, 0);
    walk_all(h);
}

/* The modified state walked in GL_SELECT with two names pushed, and in
 * GL_FEEDBACK, each time while a list is being compiled (queries run at
 * once: GL_LIST_INDEX, GL_LIST_MODE, GL_RENDER_MODE, the buffer sizes and
 * the name-stack depth are the values under test). */
static void query_walk_select_list(fc_h *h)
{
    static GLuint selbuf[64];
    static GLfloat fbbuf[64];
    declare_walk_differences(h);
    set_everything(h, 0);
    GLuint l = glGenLists(2);
    glSelectBuffer(64, selbuf);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(1);
    glPushName(2);
    glNewList(l, GL_COMPILE);
    fc_error(h, "select and compile");
    walk_all(h);
    glEndList();
    fc_value(h, "leave select", glRenderMode(GL_RENDER));
    glFeedbackBuffer(64, GL_3D_COLOR, fbbuf);
    glRenderMode(GL_FEEDBACK);
    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    fc_error(h, "feedback and compile");
    walk_all(h);
    glEndList();
    fc_value(h, "leave feedback", glRenderMode(GL_RENDER));
    fc_error(h, "end");
}

/* The modified state, then glPopAttrib / glPopClientAttrib of everything
 * pushed: the walk must find the state glPopAttrib restores. */
static void query_walk_popped(fc_h *h)
{
    declare_walk_differences(h);
    set_everything(h, 0);
    glPopClientAttrib();
    glPopAttrib();
    fc_error(h, "pop");
    walk_all(h);
}

/* The same with a second, inner push of GL_CURRENT_BIT | GL_FOG_BIT:
 * Mesa's outer pop restores only the groups changed before the inner push
 * or after the inner pop, so everything set after the inner push stays
 * (ORACLE-NOTES.md "glPopAttrib"). */
static void query_walk_popped_nested(fc_h *h)
{
    declare_walk_differences(h);
    set_everything(h, 1);
    glPopClientAttrib();
    glPopAttrib();
    glPopAttrib();
    fc_error(h, "pop");
    walk_all(h);
}

/* Every getter between glBegin and glEnd: INVALID_OPERATION, nothing
 * written (the harness pre-fills the output), glIsEnabled false,
 * glGetString NULL, glGetError itself 0. */
static void query_in_begin_end(fc_h *h)
{
    static const GLenum pn[] = { GL_VIEWPORT, GL_CURRENT_COLOR, GL_DEPTH_TEST, GL_CURRENT_INDEX,
                                 GL_MODELVIEW_MATRIX, 0x1234 };
    void *p = (void *)&p;
    for (size_t i = 0; i < sizeof pn / sizeof pn[0]; i++) {
        glBegin(GL_POINTS);
        fc_get_integer(h, "glGetIntegerv in begin/end", pn[i], 16);
        glEnd();
        fc_error(h, "glGetIntegerv in begin/end");
        glBegin(GL_LINES);
        fc_get_float(h, "glGetFloatv in begin/end", pn[i], 16);
        glEnd();
        fc_error(h, "glGetFloatv in begin/end");
        glBegin(GL_TRIANGLES);
        fc_get_double(h, "glGetDoublev in begin/end", pn[i], 16);
        glEnd();
        fc_error(h, "glGetDoublev in begin/end");
        glBegin(GL_QUADS);
        fc_get_boolean(h, "glGetBooleanv in begin/end", pn[i], 16);
        glEnd();
        fc_error(h, "glGetBooleanv in begin/end");
        glBegin(GL_POLYGON);
        fc_is_enabled(h, "glIsEnabled in begin/end", pn[i]);
        glEnd();
        fc_error(h, "glIsEnabled in begin/end");
    }
    glEnable(GL_DITHER);
    glBegin(GL_POINTS);
    fc_is_enabled(h, "glIsEnabled(GL_DITHER) in begin/end", GL_DITHER);
    fc_value(h, "glGetString in begin/end", glGetString(GL_VENDOR) != NULL);
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
    fc_value(h, "glGetPointerv in begin/end leaves params", p == (void *)&p);
    fc_value(h, "glGetError in begin/end", (long long)glGetError());
    glEnd();
    fc_error(h, "after begin/end");
}

/* Bad pnames through every getter, with NULL output too (Mesa raises the
 * error before writing). */
static void query_bad_pnames(fc_h *h)
{
    static const GLenum bad[] = { 0, 1, 0x1234, 0xffff, 0xffffffffu, GL_POSITION, GL_AMBIENT,
                                  GL_TEXTURE_WRAP_S, GL_TEXTURE_ENV_MODE, GL_RGBA, GL_FLOAT,
                                  GL_COLOR_MATRIX, GL_HISTOGRAM, GL_VERTEX_ARRAY_POINTER,
                                  GL_LIGHT0 + 8 };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fc_get_integer(h, "glGetIntegerv(bad)", bad[i], 16);
        fc_error(h, "glGetIntegerv(bad)");
        fc_get_float(h, "glGetFloatv(bad)", bad[i], 16);
        fc_error(h, "glGetFloatv(bad)");
        fc_get_double(h, "glGetDoublev(bad)", bad[i], 16);
        fc_error(h, "glGetDoublev(bad)");
        fc_get_boolean(h, "glGetBooleanv(bad)", bad[i], 16);
        fc_error(h, "glGetBooleanv(bad)");
        fc_is_enabled(h, "glIsEnabled(bad)", bad[i]);
        fc_error(h, "glIsEnabled(bad)");
        glGetIntegerv(bad[i], NULL);
        fc_error(h, "glGetIntegerv(bad, NULL)");
        glGetFloatv(bad[i], NULL);
        fc_error(h, "glGetFloatv(bad, NULL)");
        glGetDoublev(bad[i], NULL);
        fc_error(h, "glGetDoublev(bad, NULL)");
        glGetBooleanv(bad[i], NULL);
        fc_error(h, "glGetBooleanv(bad, NULL)");
        fc_value(h, "glGetString(bad) != NULL", glGetString(bad[i]) != NULL);
        fc_error(h, "glGetString(bad)");
        void *p = (void *)&p;
        glGetPointerv(bad[i], &p);
        fc_value(h, "glGetPointerv(bad) leaves params", p == (void *)&p);
        fc_error(h, "glGetPointerv(bad)");
        glGetPointerv(bad[i], NULL);
        fc_error(h, "glGetPointerv(bad, NULL)");
    }
}

/* The four conversions of each value type, on values that probe them:
 * float -> int rounding (half-way, negative, overflowing, NaN), the
 * normalised mapping of colours and depth values, float -> boolean of
 * -0.0 and NaN, integer -> float/double/boolean of large masks. */
static void query_conversions(fc_h *h)
{
    static const float sizes[] = { 0.5f, 1.5f, 2.4999998f, 2.5f, 3.5f, 1e-30f, 300.0f };
    static const float fog[] = { -0.0f, 0.5f, -0.5f, -1.5f, -2.5f, 2147483520.0f, 2147483648.0f,
                                 -2147483648.0f, 1e10f, -1e10f, 1e30f, INFINITY, -INFINITY, NAN };
    static const float colors[] = { 0.0f, 1e-10f, 0.5f, 1.0f / 3.0f, 0.99999994f, 1.0f, -1.0f,
                                    2.0f, NAN, INFINITY };
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        glPointSize(sizes[i]);
        glLineWidth(sizes[i]);
        fc_get_integer(h, "GL_POINT_SIZE", GL_POINT_SIZE, 1);
        fc_get_boolean(h, "GL_POINT_SIZE", GL_POINT_SIZE, 1);
        fc_get_double(h, "GL_LINE_WIDTH", GL_LINE_WIDTH, 1);
        fc_get_integer(h, "GL_LINE_WIDTH", GL_LINE_WIDTH, 1);
    }
    for (size_t i = 0; i < sizeof fog / sizeof fog[0]; i++) {
        glFogf(GL_FOG_START, fog[i]);
        glFogf(GL_FOG_END, -fog[i]);
        glFogf(GL_FOG_INDEX, fog[i]);
        glPolygonOffset(fog[i], -fog[i]);
        fc_error(h, "set");
        const GLenum pn[] = { GL_FOG_START, GL_FOG_END, GL_FOG_INDEX, GL_POLYGON_OFFSET_FACTOR,
                              GL_POLYGON_OFFSET_UNITS };
        const char *nm[] = { "GL_FOG_START", "GL_FOG_END", "GL_FOG_INDEX",
                             "GL_POLYGON_OFFSET_FACTOR", "GL_POLYGON_OFFSET_UNITS" };
        for (int k = 0; k < 5; k++) {
            fc_get_integer(h, nm[k], pn[k], 1);
            fc_get_float(h, nm[k], pn[k], 1);
            fc_get_double(h, nm[k], pn[k], 1);
            fc_get_boolean(h, nm[k], pn[k], 1);
        }
    }
    for (size_t i = 0; i < sizeof colors / sizeof colors[0]; i++) {
        const float c = colors[i];
        glColor4f(c, -c, c * 0.5f, 1.0f - c);
        glClearColor(c, -c, c * 0.5f, 1.0f - c);
        glBlendColor(c, -c, c * 0.5f, 1.0f - c);
        glAlphaFunc(GL_LESS, c);
        glClearDepth(c);
        glDepthRange(c, 1.0 - c);
        glIndexf(c * 1000.0f);
        fc_error(h, "set");
        const GLenum pn[] = { GL_CURRENT_COLOR, GL_COLOR_CLEAR_VALUE, GL_BLEND_COLOR,
                              GL_ALPHA_TEST_REF, GL_DEPTH_CLEAR_VALUE, GL_DEPTH_RANGE,
                              GL_CURRENT_INDEX };
        const char *nm[] = { "GL_CURRENT_COLOR", "GL_COLOR_CLEAR_VALUE", "GL_BLEND_COLOR",
                             "GL_ALPHA_TEST_REF", "GL_DEPTH_CLEAR_VALUE", "GL_DEPTH_RANGE",
                             "GL_CURRENT_INDEX" };
        for (int k = 0; k < 7; k++) {
            fc_get_integer(h, nm[k], pn[k], 4);
            fc_get_float(h, nm[k], pn[k], 4);
            fc_get_double(h, nm[k], pn[k], 4);
            fc_get_boolean(h, nm[k], pn[k], 4);
        }
    }
    /* unsigned masks and the stencil reference, beyond INT_MAX */
    glStencilMask(0xffffffffu);
    glStencilFunc(GL_ALWAYS, 1000, 0x80000001u);
    glIndexMask(0x80000000u);
    const GLenum pn[] = { GL_STENCIL_WRITEMASK, GL_STENCIL_VALUE_MASK, GL_STENCIL_REF,
                          GL_INDEX_WRITEMASK };
    const char *nm[] = { "GL_STENCIL_WRITEMASK", "GL_STENCIL_VALUE_MASK", "GL_STENCIL_REF",
                         "GL_INDEX_WRITEMASK" };
    for (int k = 0; k < 4; k++) {
        fc_get_integer(h, nm[k], pn[k], 1);
        fc_get_float(h, nm[k], pn[k], 1);
        fc_get_double(h, nm[k], pn[k], 1);
        fc_get_boolean(h, nm[k], pn[k], 1);
    }
}

/* The strings differ on purpose (fixgl's own names, the version and the
 * extensions it implements): recorded as documented differences; their
 * errors, NULL results and the version format compare exactly. */
static void query_strings(fc_h *h)
{
    static const struct qenum names[] = { Q(GL_VENDOR), Q(GL_RENDERER), Q(GL_VERSION),
                                          Q(GL_EXTENSIONS) };
    fc_documented_difference(h, "GL_VENDOR", "fixgl's own vendor string");
    fc_documented_difference(h, "GL_RENDERER", "fixgl's own renderer string");
    fc_documented_difference(h, "GL_VERSION",
                             "fixgl reports the version it implements (1.5), the "
                             "oracle 4.5 Compatibility Profile");
    fc_documented_difference(h, "GL_EXTENSIONS",
                             "fixgl lists exactly the extensions it implements "
                             "(api/query_extensions checks each is the oracle's too)");
    fc_documented_difference(h, "GL_VERSION major", "1 for fixgl, 4 for the oracle");
    for (int i = 0; i < 4; i++) {
        const char *s = (const char *)glGetString(names[i].e);
        fc_error(h, names[i].name);
        fc_value(h, "glGetString != NULL", s != NULL);
        if (s)
            fc_blob(h, names[i].name, s, strlen(s));
        else
            fc_blob(h, names[i].name, "", 0);
        if (names[i].e == GL_VERSION && s) {
            /* "<major>.<minor>[.<release>][ <vendor info>]" */
            int major = 0, minor = -1, n = 0;
            int ok = sscanf(s, "%d.%d%n", &major, &minor, &n) == 2 &&
                     (s[n] == 0 || s[n] == ' ' || s[n] == '.');
            fc_value(h, "GL_VERSION is major.minor", ok);
            fc_value(h, "GL_VERSION major", major);
            fc_value(h, "GL_VERSION major >= 1", major >= 1);
        }
        if (names[i].e == GL_EXTENSIONS && s) {
            /* space separated GL_ names, no empty or repeated tokens */
            int ok = 1;
            for (const char *t = s; *t;) {
                size_t k = strcspn(t, " ");
                if (k && strncmp(t, "GL_", 3) != 0)
                    ok = 0;
                t += k;
                while (*t == ' ')
                    t++;
            }
            fc_value(h, "GL_EXTENSIONS tokens start with GL_", ok);
        }
    }
    glGetString(GL_VENDOR + 4);
    fc_error(h, "glGetString(bad)");
}

static int has_extension(const char *list, const char *name)
{
    size_t n = strlen(name);
    for (const char *t = list; t && *t;) {
        size_t k = strcspn(t, " ");
        if (k == n && strncmp(t, name, n) == 0)
            return 1;
        t += k;
        while (*t == ' ')
            t++;
    }
    return 0;
}

/* fixgl's extension list: every entry is advertised by the oracle too
 * (the same test on both sides: each name is present), every entry's
 * enums work as in the oracle, and the EXT entry points resolve. */
static void query_extensions(fc_h *h)
{
    static const char *const fixgl_ext[] = {
        "GL_EXT_blend_color", "GL_EXT_blend_minmax", "GL_EXT_blend_subtract",
        "GL_EXT_draw_range_elements", "GL_EXT_rescale_normal",
        "GL_EXT_separate_specular_color", "GL_EXT_stencil_wrap", "GL_NV_blend_square",
        "GL_NV_fog_distance",
        "GL_ARB_multitexture", "GL_ARB_texture_border_clamp", "GL_ARB_texture_env_add",
        "GL_ARB_texture_env_combine", "GL_ARB_texture_env_crossbar", "GL_ARB_texture_env_dot3",
        "GL_ARB_texture_mirrored_repeat", "GL_ARB_texture_non_power_of_two",
        "GL_ATI_texture_env_combine3", "GL_ATI_texture_mirror_once", "GL_EXT_abgr",
        "GL_EXT_bgra", "GL_EXT_packed_pixels", "GL_EXT_texture_edge_clamp",
        "GL_EXT_texture_env_add", "GL_EXT_texture_env_combine", "GL_EXT_texture_env_dot3",
        "GL_EXT_texture_lod_bias", "GL_EXT_texture_mirror_clamp",
        "GL_IBM_texture_mirrored_repeat", "GL_NV_texture_env_combine4",
        "GL_SGIS_texture_edge_clamp", "GL_SGIS_texture_lod", "GL_SGIS_generate_mipmap",
        "GL_ARB_multisample", "GL_ARB_point_parameters", "GL_ARB_transpose_matrix",
        "GL_EXT_blend_equation_separate", "GL_EXT_blend_func_separate", "GL_EXT_fog_coord",
        "GL_EXT_multi_draw_arrays", "GL_EXT_point_parameters", "GL_EXT_secondary_color",
        "GL_ARB_vertex_buffer_object", "GL_ARB_occlusion_query", "GL_EXT_vertex_array",
        "GL_ARB_point_sprite", "GL_EXT_texture3D", "GL_ARB_depth_texture", "GL_ARB_shadow",
        "GL_ARB_texture_compression", "GL_ARB_texture_cube_map",
        "GL_EXT_texture_compression_s3tc",
    };
    /* fixgl's own extensions (include/fixgl/shading.md), which the oracle
     * does not have: not counted among the others; libfixgl's api tests
     * check fixgl lists them */
    static const char *const fixgl_own[] = { "GL_WIN_phong_shading", "GL_FIXGL_cook_torrance" };
    const size_t n = sizeof fixgl_ext / sizeof fixgl_ext[0];
    const char *list = (const char *)glGetString(GL_EXTENSIONS);
    int others = 0;
    for (size_t i = 0; i < n; i++)
        fc_value(h, fixgl_ext[i], has_extension(list, fixgl_ext[i]));
    for (const char *t = list; t && *t;) {
        size_t k = strcspn(t, " ");
        int known = 0;
        for (size_t i = 0; i < n; i++)
            known |= strlen(fixgl_ext[i]) == k && strncmp(fixgl_ext[i], t, k) == 0;
        for (size_t i = 0; i < sizeof fixgl_own / sizeof fixgl_own[0]; i++)
            known |= strlen(fixgl_own[i]) == k && strncmp(fixgl_own[i], t, k) == 0;
        others += k && !known;
        t += k;
        while (*t == ' ')
            t++;
    }
    fc_documented_difference(h, "extensions beyond fixgl's",
                             "the oracle advertises the ~400 extensions of a GL 4.5 driver, "
                             "fixgl only those it implements");
    fc_value(h, "extensions beyond fixgl's", others > 0);
    /* the enums each extension brings */
    glBlendColor(0.25f, 0.5f, 0.75f, 1.0f);
    glBlendFunc(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA);
    fc_error(h, "EXT_blend_color");
    glBlendEquation(GL_MIN);
    glBlendEquation(GL_MAX);
    fc_error(h, "EXT_blend_minmax");
    glBlendEquation(GL_FUNC_SUBTRACT);
    glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
    fc_error(h, "EXT_blend_subtract");
    glEnable(GL_RESCALE_NORMAL);
    fc_error(h, "EXT_rescale_normal");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    fc_error(h, "EXT_separate_specular_color");
    glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INCR_WRAP);
    fc_error(h, "EXT_stencil_wrap");
    glBlendFunc(GL_SRC_COLOR, GL_DST_COLOR);
    fc_error(h, "NV_blend_square");
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
    glFogi(GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE_ABSOLUTE_NV);
    fc_error(h, "NV_fog_distance");
    glDrawRangeElements(GL_POINTS, 0, 0, 0, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "EXT_draw_range_elements");
    /* the texture extensions' enums, on a bound 2D texture and unit 1 */
    {
        static const GLubyte texel[16] = { 255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 9 };
        static const GLenum wraps[7] = {
            GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRROR_CLAMP_EXT,
            GL_MIRROR_CLAMP_TO_EDGE_EXT, GL_MIRROR_CLAMP_TO_BORDER_EXT, GL_MIRRORED_REPEAT_IBM,
        };
        static const GLenum funcs[8] = {
            GL_ADD, GL_COMBINE, GL_COMBINE4_NV, GL_MODULATE_ADD_ATI, GL_MODULATE_SIGNED_ADD_ATI,
            GL_MODULATE_SUBTRACT_ATI, GL_DOT3_RGB_EXT, GL_DOT3_RGBA,
        };
        glBindTexture(GL_TEXTURE_2D, 3);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
        fc_error(h, "ARB_texture_non_power_of_two");
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_BGRA, GL_UNSIGNED_BYTE, texel);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_ABGR_EXT, GL_UNSIGNED_BYTE, texel);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, texel);
        fc_error(h, "EXT_bgra, EXT_abgr, EXT_packed_pixels");
        for (int i = 0; i < 7; i++) {
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wraps[i]);
            fc_error(h, "texture wraps");
        }
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.5f);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -0.5f);
        fc_error(h, "EXT_texture_lod_bias");
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 0.5f);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 3.0f);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 4);
        fc_error(h, "SGIS_texture_lod");
        glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
        glHint(GL_GENERATE_MIPMAP_HINT, GL_NICEST);
        fc_get_integer(h, "GL_GENERATE_MIPMAP_HINT", GL_GENERATE_MIPMAP_HINT, 1);
        glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE);
        fc_error(h, "SGIS_generate_mipmap");
        for (int i = 0; i < 8; i++) {
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, i < 3 ? (GLint)funcs[i] : GL_COMBINE);
            if (i >= 3)
                glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)funcs[i]);
            fc_error(h, "texture env functions");
        }
        glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE1);
        fc_error(h, "ARB_texture_env_crossbar");
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        typedef void (GLAPIENTRY *active_fn)(GLenum);
        active_fn at = (active_fn)OSMesaGetProcAddress("glActiveTextureARB");
        if (at)
            at(GL_TEXTURE1_ARB);
        fc_get_integer(h, "GL_ACTIVE_TEXTURE via glActiveTextureARB", GL_ACTIVE_TEXTURE, 1);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, 0);
        fc_error(h, "ARB_multitexture");
        fc_value(h, "glMultiTexCoord2fARB", OSMesaGetProcAddress("glMultiTexCoord2fARB") != NULL);
        fc_value(h, "glClientActiveTextureARB", OSMesaGetProcAddress("glClientActiveTextureARB") != NULL);
    }
    fc_value(h, "glBlendColorEXT", OSMesaGetProcAddress("glBlendColorEXT") != NULL);
    fc_value(h, "glBlendEquationEXT", OSMesaGetProcAddress("glBlendEquationEXT") != NULL);
    fc_value(h, "glDrawRangeElementsEXT", OSMesaGetProcAddress("glDrawRangeElementsEXT") != NULL);
    /* GL_ARB_vertex_buffer_object, GL_ARB_occlusion_query, GL_EXT_vertex_array */
    static const char *const gl15_names[] = {
        "glBindBufferARB", "glBufferDataARB", "glMapBufferARB", "glGetBufferPointervARB",
        "glGenQueriesARB", "glBeginQueryARB", "glGetQueryObjectuivARB", "glVertexPointerEXT",
        "glColorPointerEXT", "glEdgeFlagPointerEXT", "glDrawArraysEXT", "glArrayElementEXT",
        "glGetPointervEXT", "glIndexPointerEXT", "glNormalPointerEXT", "glTexCoordPointerEXT",
    };
    for (size_t i = 0; i < sizeof gl15_names / sizeof gl15_names[0]; i++)
        fc_value(h, gl15_names[i], OSMesaGetProcAddress(gl15_names[i]) != NULL);
    /* an EXT entry point draws like the core one */
    typedef void (GLAPIENTRY *blend_color_fn)(GLclampf, GLclampf, GLclampf, GLclampf);
    blend_color_fn bc = (blend_color_fn)OSMesaGetProcAddress("glBlendColorEXT");
    if (bc)
        bc(0.5f, 0.125f, 1.0f, 0.25f);
    fc_get_float(h, "GL_BLEND_COLOR via glBlendColorEXT", GL_BLEND_COLOR, 4);
    fc_error(h, "glBlendColorEXT");
}

/* glGetPointerv of every pointer pname the oracle answers. */
static void query_get_pointerv(fc_h *h)
{
    static GLfloat data[64];
    static const struct qenum pn[] = {
        Q(GL_VERTEX_ARRAY_POINTER), Q(GL_NORMAL_ARRAY_POINTER), Q(GL_COLOR_ARRAY_POINTER),
        Q(GL_INDEX_ARRAY_POINTER), Q(GL_TEXTURE_COORD_ARRAY_POINTER),
        Q(GL_EDGE_FLAG_ARRAY_POINTER), Q(GL_FOG_COORD_ARRAY_POINTER),
        Q(GL_SECONDARY_COLOR_ARRAY_POINTER), Q(GL_FEEDBACK_BUFFER_POINTER),
        Q(GL_SELECTION_BUFFER_POINTER), Q(GL_DEBUG_CALLBACK_FUNCTION),
        Q(GL_DEBUG_CALLBACK_USER_PARAM),
    };
    for (int pass = 0; pass < 2; pass++) {
        for (size_t i = 0; i < sizeof pn / sizeof pn[0]; i++) {
            void *p = (void *)&p;
            glGetPointerv(pn[i].e, &p);
            /* the offset into data, or -1 for NULL, -2 for untouched */
            long long v = p == NULL ? -1 : p == (void *)&p ? -2
                        : (long long)((const char *)p - (const char *)data);
            fc_value(h, pn[i].name, v);
            fc_error(h, pn[i].name);
        }
        glVertexPointer(2, GL_FLOAT, 0, data + 1);
        glNormalPointer(GL_FLOAT, 12, data + 2);
        glColorPointer(4, GL_FLOAT, 16, data + 3);
        glIndexPointer(GL_FLOAT, 0, data + 4);
        glTexCoordPointer(1, GL_FLOAT, 0, data + 5);
        glEdgeFlagPointer(0, data + 6);
        fc_error(h, "pointers");
    }
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glVertexPointer(3, GL_FLOAT, 0, data + 9);
    glPopClientAttrib();
    void *p = NULL;
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
    fc_value(h, "GL_VERTEX_ARRAY_POINTER after pop",
             (long long)((const char *)p - (const char *)data));
}

/* Colour-index calls on the RGBA context: stored, queried, no effect on
 * drawing or clearing; errors between glBegin and glEnd. */
static void index_calls(fc_h *h)
{
    static const GLdouble dv = -3.75;
    static const GLfloat fv = 1e9f;
    static const GLint iv = -2147483647 - 1;
    static const GLshort sv = -32768;
    static const GLubyte ubv = 255;
    static const float clears[] = { 7.9f, -2.5f, 0.5f, 4294967295.0f, 4294967296.0f, 1e19f,
                                    -1e19f, NAN };

#define IDX(call, label)                                              \
    call;                                                             \
    fc_error(h, label);                                               \
    fc_get_integer(h, label, GL_CURRENT_INDEX, 1);                    \
    fc_get_float(h, label, GL_CURRENT_INDEX, 1);                      \
    fc_get_double(h, label, GL_CURRENT_INDEX, 1);                     \
    fc_get_boolean(h, label, GL_CURRENT_INDEX, 1)
    IDX(glIndexd(2.5), "glIndexd");
    IDX(glIndexdv(&dv), "glIndexdv");
    IDX(glIndexf(-0.5f), "glIndexf");
    IDX(glIndexfv(&fv), "glIndexfv");
    IDX(glIndexi(12345), "glIndexi");
    IDX(glIndexiv(&iv), "glIndexiv");
    IDX(glIndexs(-7), "glIndexs");
    IDX(glIndexsv(&sv), "glIndexsv");
    IDX(glIndexub(200), "glIndexub");
    IDX(glIndexubv(&ubv), "glIndexubv");
#undef IDX
    for (size_t i = 0; i < sizeof clears / sizeof clears[0]; i++) {
        glClearIndex(clears[i]);
        fc_error(h, "glClearIndex");
        fc_get_integer(h, "GL_INDEX_CLEAR_VALUE", GL_INDEX_CLEAR_VALUE, 1);
        fc_get_float(h, "GL_INDEX_CLEAR_VALUE", GL_INDEX_CLEAR_VALUE, 1);
        fc_get_boolean(h, "GL_INDEX_CLEAR_VALUE", GL_INDEX_CLEAR_VALUE, 1);
    }
    glIndexMask(0);
    fc_get_integer(h, "GL_INDEX_WRITEMASK 0", GL_INDEX_WRITEMASK, 1);
    glIndexMask(0xdeadbeefu);
    fc_get_integer(h, "GL_INDEX_WRITEMASK", GL_INDEX_WRITEMASK, 1);
    fc_get_double(h, "GL_INDEX_WRITEMASK", GL_INDEX_WRITEMASK, 1);
    fc_error(h, "glIndexMask");

    /* no effect on what is drawn and cleared */
    fc_pixel_ortho(h);
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glIndexi(3);
    glColor3f(1, 0.5f, 0);
    glVertex2f(2, 2);
    glIndexf(9.5f);
    glVertex2f(14, 3);
    glIndexub(1);
    glVertex2f(5, 13);
    glEnd();
    fc_error(h, "glIndex in begin/end");
    fc_get_float(h, "GL_CURRENT_INDEX after begin/end", GL_CURRENT_INDEX, 1);
    fc_capture(h);

    glBegin(GL_POINTS);
    glClearIndex(1.0f);
    glEnd();
    fc_error(h, "glClearIndex in begin/end");
    glBegin(GL_POINTS);
    glIndexMask(1);
    glEnd();
    fc_error(h, "glIndexMask in begin/end");
    fc_get_integer(h, "GL_INDEX_WRITEMASK", GL_INDEX_WRITEMASK, 1);
    fc_get_integer(h, "GL_INDEX_CLEAR_VALUE", GL_INDEX_CLEAR_VALUE, 1);
    fc_is_enabled(h, "GL_INDEX_LOGIC_OP", GL_INDEX_LOGIC_OP);
    glEnable(GL_INDEX_LOGIC_OP);
    glLogicOp(GL_INVERT);
    glClear(GL_COLOR_BUFFER_BIT);
    fcu_rect(4, 4, 12, 12, 0);
    fc_error(h, "GL_INDEX_LOGIC_OP");
    fc_capture(h);
}

static const GLenum buffer_enums[] = {
    GL_NONE, GL_FRONT_LEFT, GL_FRONT_RIGHT, GL_BACK_LEFT, GL_BACK_RIGHT, GL_FRONT, GL_BACK,
    GL_LEFT, GL_RIGHT, GL_FRONT_AND_BACK, GL_AUX0, GL_AUX1, GL_AUX2, GL_AUX3, 0x040D,
    GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT7, GL_COLOR_ATTACHMENT8, GL_COLOR_ATTACHMENT31,
    GL_COLOR_ATTACHMENT31 + 1, GL_DEPTH, GL_STENCIL, GL_COLOR, GL_DEPTH_ATTACHMENT, 0x1234,
};

/* Which glDrawBuffer / glReadBuffer values the single-buffered OSMesa
 * framebuffer accepts, the error of each other, the state left. */
static void buffer_values(fc_h *h)
{
    for (size_t i = 0; i < sizeof buffer_enums / sizeof buffer_enums[0]; i++) {
        glDrawBuffer(GL_FRONT_LEFT);
        glReadBuffer(GL_BACK);
        glDrawBuffer(buffer_enums[i]);
        fc_error(h, "glDrawBuffer");
        fc_get_integer(h, "GL_DRAW_BUFFER", GL_DRAW_BUFFER, 1);
        glReadBuffer(buffer_enums[i]);
        fc_error(h, "glReadBuffer");
        fc_get_integer(h, "GL_READ_BUFFER", GL_READ_BUFFER, 1);
        fc_get_boolean(h, "GL_READ_BUFFER", GL_READ_BUFFER, 1);
    }
    glBegin(GL_POINTS);
    glDrawBuffer(GL_FRONT);
    glEnd();
    fc_error(h, "glDrawBuffer in begin/end");
    glBegin(GL_POINTS);
    glReadBuffer(GL_FRONT);
    glEnd();
    fc_error(h, "glReadBuffer in begin/end");
    fc_get_integer(h, "GL_DRAW_BUFFER", GL_DRAW_BUFFER, 1);
    fc_get_integer(h, "GL_READ_BUFFER", GL_READ_BUFFER, 1);
}

/* Drawing and clearing under each accepted draw buffer: GL_NONE writes no
 * colour but depth and stencil; every left/front/back name draws into the
 * one buffer. */
static void draw_buffer_render(fc_h *h)
{
    static const GLenum draw[] = { GL_NONE, GL_BACK, GL_FRONT_AND_BACK, GL_LEFT, GL_BACK_LEFT,
                                   GL_FRONT_LEFT };
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    for (size_t i = 0; i < sizeof draw / sizeof draw[0]; i++) {
        glDrawBuffer(GL_FRONT);
        glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
        glClearDepth(1.0);
        glClearStencil(0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glDrawBuffer(draw[i]);
        fc_error(h, "glDrawBuffer");
        fcu_color((int)i);
        fcu_rect(2, 2, 12, 10, 0.25f);
        fcu_color((int)i + 5);
        fcu_rect(6, 5, 15, 14, -0.5f);
        fc_capture(h);
        /* a clear under this draw buffer: colour only if it names one */
        glClearColor(0.9f, 0.8f, 0.7f, 0.6f);
        glClearDepth(0.5);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        fc_capture(h);
    }
    /* scissored (quad) clear and a masked clear under GL_NONE */
    glDrawBuffer(GL_NONE);
    glEnable(GL_SCISSOR_TEST);
    glScissor(3, 4, 6, 5);
    glClearColor(1, 1, 0, 1);
    glClearDepth(0.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    fc_capture(h);
}

/* glReadPixels from each read buffer: GL_NONE has no colour to read
 * (INVALID_OPERATION before the format/type checks, nothing written),
 * depth still reads; the other names read the one buffer. */
static void read_buffer_render(fc_h *h)
{
    static const GLenum rb[] = { GL_NONE, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, GL_LEFT,
                                 GL_BACK_LEFT, GL_FRONT_LEFT };
    fc_pixel_ortho(h);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    fcu_color(3);
    fcu_rect(1, 1, 9, 7, 0.5f);
    fc_capture(h);
    for (size_t i = 0; i < sizeof rb / sizeof rb[0]; i++) {
        GLubyte px[8 * 8 * 4];
        GLfloat z[8 * 8];
        glReadBuffer(rb[i]);
        fc_error(h, "glReadBuffer");
        memset(px, 0xab, sizeof px);
        glReadPixels(0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, px);
        fc_error(h, "glReadPixels RGBA");
        fc_blob(h, "RGBA", px, sizeof px);
        memset(px, 0xab, sizeof px);
        glReadPixels(0, 0, 8, 8, GL_RGB, GL_FLOAT + 0x100, px);
        fc_error(h, "glReadPixels RGB, bad type");
        if (rb[i] == GL_NONE) {
            /* every colour format: no colour buffer, before the format
             * and type checks */
            glReadPixels(0, 0, 8, 8, GL_LUMINANCE, GL_UNSIGNED_BYTE, px);
            fc_error(h, "glReadPixels LUMINANCE");
            glReadPixels(0, 0, 8, 8, GL_BGRA, GL_UNSIGNED_BYTE, NULL);
            fc_error(h, "glReadPixels BGRA NULL");
            glReadPixels(0, 0, 8, 8, GL_RED, GL_INT, px);
            fc_error(h, "glReadPixels RED");
            fc_blob(h, "untouched", px, sizeof px);
        }
        glReadPixels(0, 0, -1, 8, GL_RGBA, GL_UNSIGNED_BYTE, px);
        fc_error(h, "glReadPixels negative width");
        memset(z, 0xab, sizeof z);
        glReadPixels(0, 0, 8, 8, GL_DEPTH_COMPONENT, GL_FLOAT, z);
        fc_error(h, "glReadPixels depth");
        fc_blob(h, "depth", z, sizeof z);
    }
}

/* The GL 1.4 client arrays: accepted by glEnableClientState and glEnable,
 * reported by glIsEnabled and glGet, saved by glPushClientAttrib.  (Not
 * drawn: fixgl has no pointer call for them.) */
static void client_state_gl14(fc_h *h)
{
    static const struct qenum caps[] = { Q(GL_FOG_COORD_ARRAY), Q(GL_SECONDARY_COLOR_ARRAY) };
    for (int i = 0; i < 2; i++) {
        fc_is_enabled(h, caps[i].name, caps[i].e);
        glEnableClientState(caps[i].e);
        fc_error(h, "glEnableClientState");
        fc_is_enabled(h, caps[i].name, caps[i].e);
        fc_get_boolean(h, caps[i].name, caps[i].e, 1);
        fc_get_integer(h, caps[i].name, caps[i].e, 1);
        glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        glDisableClientState(caps[i].e);
        fc_error(h, "glDisableClientState");
        fc_is_enabled(h, caps[i].name, caps[i].e);
        glPopClientAttrib();
        fc_is_enabled(h, "after pop", caps[i].e);
        glDisable(caps[i].e);
        fc_error(h, "glDisable");
        fc_is_enabled(h, caps[i].name, caps[i].e);
        glEnable(caps[i].e);
        fc_error(h, "glEnable");
        fc_is_enabled(h, caps[i].name, caps[i].e);
        glDisableClientState(caps[i].e);
    }
    /* neighbours that are not client arrays */
    static const GLenum bad[] = { GL_POINT_SPRITE, GL_FOG_COORD_SRC, 0x1234,
                                  GL_TEXTURE_2D, GL_LIGHTING };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        glEnableClientState(bad[i]);
        fc_error(h, "glEnableClientState(not an array)");
        glDisableClientState(bad[i]);
        fc_error(h, "glDisableClientState(not an array)");
    }
    glBegin(GL_POINTS);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glEnd();
    fc_error(h, "glEnableClientState in begin/end");
    fc_is_enabled(h, "GL_FOG_COORD_ARRAY", GL_FOG_COORD_ARRAY);
}

/* glEnable/glDisable of every capability of the walk, read back through
 * glIsEnabled and the four getters. */
static void caps_toggle(fc_h *h)
{
    for (size_t i = 0; i < NWALK; i++) {
        char label[80];
        if (walk[i].e == GL_NUM_COMPRESSED_TEXTURE_FORMATS ||
            walk[i].e == GL_COMPRESSED_TEXTURE_FORMATS)
            continue;   /* documented in the walks */
        snprintf(label, sizeof label, "glEnable(%s)", walk[i].name);
        glEnable(walk[i].e);
        fc_error(h, label);
        fc_is_enabled(h, label, walk[i].e);
        fc_get_integer(h, label, walk[i].e, 1);
        fc_get_double(h, label, walk[i].e, 1);
        snprintf(label, sizeof label, "glDisable(%s)", walk[i].name);
        glDisable(walk[i].e);
        fc_error(h, label);
        fc_is_enabled(h, label, walk[i].e);
        fc_get_boolean(h, label, walk[i].e, 1);
        fc_error(h, label);
    }
}

/* OSMesaGetProcAddress: every entry point fixgl implements resolves on both
 * sides; for names of functions fixgl lacks the oracle hands out a no-op
 * stub and fixgl NULL (documented). */
static void getprocaddress(fc_h *h)
{
    static const char *const present[] = {
        "glBegin", "glEnd", "glGetIntegerv", "glIndexi", "glClearIndex", "glIndexMask",
        "glDrawBuffer", "glReadBuffer", "glGetPointerv", "glLightfv", "glBlendColor",
        "OSMesaGetProcAddress", "OSMesaMakeCurrent",
    };
    static const char *const absent[] = { "", "foo", "OSMesaFoo", "GLBegin", "g" };
    static const char *const stubbed[] = { "glFooBar", "glCreateShader", "gl", "glx" };
    for (size_t i = 0; i < sizeof present / sizeof present[0]; i++)
        fc_value(h, present[i], OSMesaGetProcAddress(present[i]) != NULL);
    for (size_t i = 0; i < sizeof absent / sizeof absent[0]; i++)
        fc_value(h, absent[i], OSMesaGetProcAddress(absent[i]) != NULL);
    for (size_t i = 0; i < sizeof stubbed / sizeof stubbed[0]; i++) {
        fc_documented_difference(h, stubbed[i],
                                 "a gl* name fixgl does not implement: Mesa's glapi hands out a "
                                 "no-op dispatch stub, fixgl NULL (no silent no-op)");
        fc_value(h, stubbed[i], OSMesaGetProcAddress(stubbed[i]) != NULL);
    }
    /* a function through its pointer is the function */
    typedef void (GLAPIENTRY *index_mask_fn)(GLuint);
    index_mask_fn im = (index_mask_fn)OSMesaGetProcAddress("glIndexMask");
    if (im)
        im(0x77);
    fc_get_integer(h, "GL_INDEX_WRITEMASK via pointer", GL_INDEX_WRITEMASK, 1);
    fc_error(h, "getprocaddress");
}

/* glArrayElement with an index array: the index goes into the vertex
 * format like glIndex (and becomes GL_CURRENT_INDEX), drawing as without
 * it; glDrawArrays ignores it. */
static void index_array_element(fc_h *h)
{
    static const GLfloat v[8] = { 2, 2, 14, 3, 13, 14, 3, 12 };
    static const GLubyte c[16] = { 255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255 };
    static const GLshort idx[4] = { 7, -3, 300, 42 };
    fc_pixel_ortho(h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    glIndexPointer(GL_SHORT, 0, idx);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_INDEX_ARRAY);
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; i++)
        glArrayElement(i);
    glEnd();
    fc_get_float(h, "GL_CURRENT_INDEX after glArrayElement", GL_CURRENT_INDEX, 1);
    fc_capture(h);
    glIndexi(5);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fc_get_float(h, "GL_CURRENT_INDEX after glDrawArrays", GL_CURRENT_INDEX, 1);
    fc_capture(h);
    fc_error(h, "index arrays");
}

/* A long GL_QUADS primitive with and without glIndex between its
 * vertices: the index is one more float in the vertex format, so Mesa's
 * vbo wraps the primitive into draws at other vertices (21845 instead of
 * 26214 here).  (This scene does not make the wrap point visible: the
 * oracle draws both passes alike; it checks the index path of a long
 * primitive.) */
static void index_batching(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    for (int pass = 0; pass < 2; pass++) {
        glBegin(GL_QUADS);
        for (int q = 0; q < 7500; q++) {
            if (pass)
                glIndexi(q);
            if (q >= 5120 && q < 5461) {
                glColor3ub(255, 0, 0);
                glVertex2f(-0.5f + (float)(q % 3), 1);
                glColor3ub(0, 255, 0);
                glVertex2f(31, 0.5f);
                glColor3ub(0, 0, 255);
                glVertex2f(31.5f, 31);
                glColor3ub(255, 255, 255);
                glVertex2f(1, 31.5f);
            } else if (q == 5750) {
                glColor3ub(255, 255, 0);
                glVertex2f(-2, 2);
                glVertex2f(1, 2);
                glVertex2f(1, 3);
                glVertex2f(-2, 3);
            } else {
                glColor3ub(0, 0, 0);
                for (int k = 0; k < 4; k++)
                    glVertex2f(16, 16);
            }
        }
        glEnd();
        fc_capture(h);
    }
    fc_get_float(h, "GL_CURRENT_INDEX", GL_CURRENT_INDEX, 1);
}

/* The draw buffer is context state and survives a rebind to another
 * buffer; the read buffer lives in the OSMesa framebuffer, which a rebind
 * to another size makes anew: back to GL_FRONT. */
static void buffer_rebind(fc_h *h)
{
    static unsigned char same[8 * 8 * 4], bigger[12 * 10 * 4];
    OSMesaContext ctx = fc_context(h);
    void *own = fc_buffer(h);
    struct { void *buf; int w, h; const char *label; } seq[] = {
        { own, 8, 8, "same buffer" }, { same, 8, 8, "other buffer, same size" },
        { bigger, 12, 10, "bigger buffer" }, { own, 8, 8, "back to 8x8" },
    };
    for (size_t i = 0; i < sizeof seq / sizeof seq[0]; i++) {
        glDrawBuffer(i % 2 ? GL_NONE : GL_LEFT);
        glReadBuffer(i % 2 ? GL_BACK : GL_FRONT_AND_BACK);
        fc_error(h, "set");
        fc_value(h, seq[i].label, OSMesaMakeCurrent(ctx, seq[i].buf, GL_UNSIGNED_BYTE,
                                                   seq[i].w, seq[i].h));
        fc_get_integer(h, "GL_DRAW_BUFFER", GL_DRAW_BUFFER, 1);
        fc_get_integer(h, "GL_READ_BUFFER", GL_READ_BUFFER, 1);
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    fc_value(h, "rebind after release", OSMesaMakeCurrent(ctx, own, GL_UNSIGNED_BYTE, 8, 8));
    fc_get_integer(h, "GL_DRAW_BUFFER", GL_DRAW_BUFFER, 1);
    fc_get_integer(h, "GL_READ_BUFFER", GL_READ_BUFFER, 1);
}

/* ---- query fuzz: random setter calls (valid and not), then the walk ---- */

static float fuzz_float(fc_rng *r)
{
    static const float special[] = {
        0.0f, -0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 1.5f, 2.5f, -2.5f, 3.5f, 1e-40f, 1e-10f,
        0.99999994f, 1.0000001f, 255.5f, 65535.5f, 3e9f, -3e9f, 2147483520.0f, 1e10f,
        -1e10f, 1e30f, INFINITY, -INFINITY, NAN, 1.0f / 3.0f, 0.1f,
    };
    if (fc_rng_below(r, 3) == 0)
        return special[fc_rng_below(r, sizeof special / sizeof special[0])];
    return (float)((double)fc_rng_range(r, -3000, 3000) / 1000.0);
}

static int fuzz_int(fc_rng *r)
{
    static const int special[] = { 0, 1, -1, 2, 7, 8, 255, 256, -256, 65535, 16384, 16385,
                                   32767, -32768, 2147483647, -2147483647 - 1 };
    if (fc_rng_below(r, 2) == 0)
        return special[fc_rng_below(r, sizeof special / sizeof special[0])];
    return fc_rng_range(r, -40, 40);
}

static GLenum fuzz_enum(fc_rng *r, const GLenum *valid, size_t n)
{
    static const GLenum junk[] = { 0, 1, 0x1234, GL_FLOAT, GL_RGBA, GL_TEXTURE_2D, GL_LIGHT0,
                                   GL_NONE, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
    if (fc_rng_below(r, 5) == 0)
        return junk[fc_rng_below(r, sizeof junk / sizeof junk[0])];
    return valid[fc_rng_below(r, (uint32_t)n)];
}

#define FUZZ_ENUM(r, ...) \
    fuzz_enum(r, (const GLenum[]){ __VA_ARGS__ }, sizeof((const GLenum[]){ __VA_ARGS__ }) / sizeof(GLenum))
#define FUNCS GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS
#define FACTORS GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, \
    GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, \
    GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR, GL_CONSTANT_ALPHA
#define STENCIL_OPS GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, \
    GL_DECR_WRAP
#define HINT_TARGETS GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT, \
    GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT, GL_TEXTURE_COMPRESSION_HINT, GL_GENERATE_MIPMAP_HINT
#define PIXEL_STORES GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, \
    GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_IMAGES, \
    GL_PACK_ALIGNMENT, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, \
    GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_IMAGES, \
    GL_UNPACK_ALIGNMENT

/* One random state call, recorded with its error.  Each call draws from
 * its own stream (one value of the case's), so that a call can be left
 * out when reducing a failing sequence without changing the others. */
static void fuzz_call(fc_h *h, fc_rng *outer)
{
    fc_rng stream = { fc_rng_next(outer) }, *r = &stream;
    float f[16];
    for (int i = 0; i < 16; i++)
        f[i] = fuzz_float(r);
    const int i0 = fuzz_int(r), i1 = fuzz_int(r), i2 = fuzz_int(r), i3 = fuzz_int(r);
    const unsigned op = fc_rng_below(r, 46);
    switch (op) {
    case 0: glColor4f(f[0], f[1], f[2], f[3]); break;
    case 1: glNormal3f(f[0], f[1], f[2]); break;
    case 2: glIndexf(f[0]); break;
    case 3: glClearColor(f[0], f[1], f[2], f[3]); break;
    case 4: glClearDepth(f[0]); break;
    case 5: glClearIndex(f[0]); break;
    case 6: glClearStencil(i0); break;
    case 7: glAlphaFunc(FUZZ_ENUM(r, FUNCS), f[0]); break;
    case 8: glBlendFunc(FUZZ_ENUM(r, FACTORS), FUZZ_ENUM(r, FACTORS)); break;
    case 9: glBlendEquation(FUZZ_ENUM(r, GL_FUNC_ADD, GL_FUNC_SUBTRACT,
                                      GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX)); break;
    case 10: glBlendColor(f[0], f[1], f[2], f[3]); break;
    case 11: glLogicOp(FUZZ_ENUM(r, GL_CLEAR, GL_AND, GL_COPY, GL_XOR, GL_NOR, GL_SET,
                                 GL_INVERT, GL_NAND)); break;
    case 12: glColorMask(i0 & 1, i1 & 1, i2 & 1, i3 & 1); break;
    case 13: glScissor(i0, i1, i2, i3); break;
    case 14: glStencilFunc(FUZZ_ENUM(r, FUNCS), i0, (GLuint)i1); break;
    case 15: glStencilOp(FUZZ_ENUM(r, STENCIL_OPS), FUZZ_ENUM(r, STENCIL_OPS),
                         FUZZ_ENUM(r, STENCIL_OPS)); break;
    case 16: glStencilMask((GLuint)i0); break;
    case 17: glDepthFunc(FUZZ_ENUM(r, FUNCS)); break;
    case 18: glDepthMask(i0 & 1); break;
    case 19: glDepthRange(f[0], f[1]); break;
    case 20: glFogf(FUZZ_ENUM(r, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_INDEX), f[0]);
        break;
    case 21: glFogi(FUZZ_ENUM(r, GL_FOG_MODE, GL_FOG_COORDINATE_SOURCE, GL_FOG_DISTANCE_MODE_NV),
                    (GLint)FUZZ_ENUM(r, GL_LINEAR, GL_EXP, GL_EXP2, GL_FOG_COORDINATE,
                                     GL_FRAGMENT_DEPTH, GL_EYE_RADIAL_NV, GL_EYE_PLANE,
                                     GL_EYE_PLANE_ABSOLUTE_NV)); break;
    case 22: glFogfv(GL_FOG_COLOR, f); break;
    case 23: glFrontFace(FUZZ_ENUM(r, GL_CW, GL_CCW)); break;
    case 24: glCullFace(FUZZ_ENUM(r, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK)); break;
    case 25: glPolygonMode(FUZZ_ENUM(r, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK),
                           FUZZ_ENUM(r, GL_POINT, GL_LINE, GL_FILL)); break;
    case 26: glPolygonOffset(f[0], f[1]); break;
    case 27: glShadeModel(FUZZ_ENUM(r, GL_FLAT, GL_SMOOTH)); break;
    case 28: glLightModelf(FUZZ_ENUM(r, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE),
                           f[0]); break;
    case 29: glLightModelfv(GL_LIGHT_MODEL_AMBIENT, f); break;
    case 30: glColorMaterial(FUZZ_ENUM(r, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK),
                             FUZZ_ENUM(r, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION,
                                       GL_AMBIENT_AND_DIFFUSE)); break;
    case 31: glViewport(i0, i1, i2, i3); break;
    case 32: glPixelStoref(FUZZ_ENUM(r, PIXEL_STORES), f[0]); break;
    case 33: glPixelStorei(FUZZ_ENUM(r, PIXEL_STORES), i0); break;
    case 34: glPointSize(f[0]); break;
    case 35: glLineWidth(f[0]); break;
    case 36: glLineStipple(i0, (GLushort)i1); break;
    case 37: glHint(FUZZ_ENUM(r, HINT_TARGETS), FUZZ_ENUM(r, GL_FASTEST, GL_NICEST, GL_DONT_CARE));
        break;
    case 38:
    case 39: {
        const struct qenum *q = &walk[fc_rng_below(r, (uint32_t)NWALK)];
        if (op == 38)
            glEnable(q->e);
        else
            glDisable(q->e);
        break;
    }
    case 40: glIndexMask((GLuint)i0); break;
    case 41: glDrawBuffer(buffer_enums[fc_rng_below(r, sizeof buffer_enums / sizeof buffer_enums[0])]);
        break;
    case 42: glReadBuffer(buffer_enums[fc_rng_below(r, sizeof buffer_enums / sizeof buffer_enums[0])]);
        break;
    case 43:
        glMatrixMode(FUZZ_ENUM(r, GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE));
        glLoadMatrixf(f);
        break;
    case 44:
        if (i0 & 1)
            glPushAttrib((GLbitfield)fc_rng_next(r));
        else
            glPopAttrib();
        break;
    default: glEdgeFlag(i0 & 1); break;
    }
    char label[32];
    snprintf(label, sizeof label, "fuzz op %u", op);
    fc_error(h, label);
}

/* 400 random state calls (query_fuzz_<seed>: valid and invalid enums,
 * special floats, nested glPushAttrib/glPopAttrib with random masks), each
 * with its error, then the whole walk.  Seeds 0-63, and 174, 193 and 645,
 * which found glMatrixMode(GL_TEXTURE)'s mark, GL_INDEX_LOGIC_OP in the
 * colour group and the clear values a pop sets without flushing (seeds
 * up to 1499 were exact when this was written). */
static void query_fuzz(fc_h *h)
{
    const int seed = atoi(fc_this_case(h)->name + sizeof "api/query_fuzz_" - 1);
    fc_rng r = fc_rng_make(0x5eed, (uint32_t)seed, 7);
    declare_walk_differences(h);
    for (int i = 0; i < 400; i++)
        fuzz_call(h, &r);
    walk_all(h);
}

/* ---- nested glPushAttrib: what an outer glPopAttrib restores ---- */

static void query_attrib_state(fc_h *h, const char *when)
{
    static const struct qenum pn[] = {
        Q(GL_VIEWPORT), Q(GL_DEPTH_RANGE), Q(GL_CULL_FACE), Q(GL_LIGHTING), Q(GL_LIGHT0),
        Q(GL_SHADE_MODEL), Q(GL_FOG), Q(GL_FOG_START), Q(GL_COLOR_CLEAR_VALUE),
        Q(GL_SCISSOR_BOX), Q(GL_SCISSOR_TEST), Q(GL_LINE_WIDTH), Q(GL_POINT_SIZE),
        Q(GL_CURRENT_COLOR), Q(GL_CURRENT_INDEX), Q(GL_LIGHT_MODEL_AMBIENT),
        Q(GL_ATTRIB_STACK_DEPTH), Q(GL_DRAW_BUFFER), Q(GL_INDEX_WRITEMASK),
    };
    char label[96];
    for (size_t i = 0; i < sizeof pn / sizeof pn[0]; i++) {
        snprintf(label, sizeof label, "%s %s", when, pn[i].name);
        fc_get_float(h, label, pn[i].e, 4);
    }
    fc_error(h, when);
}

static void lit_quad(fc_h *h)
{
    fc_pixel_ortho(h);
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    glVertex2f(2, 2);
    glNormal3f(0.6f, 0, 0.8f);
    glVertex2f(14, 2);
    glNormal3f(0, 0.6f, 0.8f);
    glVertex2f(14, 14);
    glNormal3f(-0.6f, 0, 0.8f);
    glVertex2f(2, 14);
    glEnd();
}

/* Changes made only under an inner push (whatever its mask) are kept by
 * the outer pop; changes made before the inner push or after the inner
 * pop are restored. */
static void attrib_nested(fc_h *h)
{
    static const GLfloat amb[4] = { 0.5f, 0.25f, 0.125f, 1 };
    glClearColor(0.1f, 0.2f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    query_attrib_state(h, "initial");

    /* 1. everything changed under the inner push of another group */
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glPushAttrib(GL_POINT_BIT);
    glViewport(4, 4, 8, 8);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glShadeModel(GL_FLAT);
    glEnable(GL_FOG);
    glFogf(GL_FOG_START, -3);
    glClearColor(0.9f, 0.1f, 0.1f, 1);
    glLineWidth(3);
    glIndexMask(0x0f);
    glDrawBuffer(GL_BACK);
    glPopAttrib();
    glPopAttrib();
    query_attrib_state(h, "inner only");
    lit_quad(h);
    fc_capture(h);

    /* 2. changes before the inner push and after the inner pop */
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glScissor(1, 2, 3, 4);
    glEnable(GL_SCISSOR_TEST);
    glPushAttrib(GL_VIEWPORT_BIT | GL_ENABLE_BIT);
    glScissor(5, 6, 7, 8);
    glViewport(0, 0, 16, 16);
    glDisable(GL_LIGHTING);
    glPopAttrib();
    glPointSize(4);
    glPopAttrib();
    query_attrib_state(h, "before and after");

    /* 3. three levels, one group changed at each */
    glPushAttrib(GL_VIEWPORT_BIT);
    glViewport(1, 1, 10, 10);
    glPushAttrib(GL_ENABLE_BIT);
    glDepthRange(0.25, 0.5);
    glEnable(GL_CULL_FACE);
    glPushAttrib(GL_FOG_BIT);
    glFogf(GL_FOG_START, 5);
    glViewport(2, 2, 9, 9);
    glPopAttrib();
    query_attrib_state(h, "three levels, 1 pop");
    glPopAttrib();
    query_attrib_state(h, "three levels, 2 pops");
    glPopAttrib();
    query_attrib_state(h, "three levels, 3 pops");

    /* 4. the current colour under an inner push of the lighting group */
    glColor3f(1, 0, 0);
    glPushAttrib(GL_CURRENT_BIT);
    glPushAttrib(GL_LIGHTING_BIT);
    glColor3f(0, 1, 0);
    glIndexi(9);
    glPopAttrib();
    glPopAttrib();
    query_attrib_state(h, "current under lighting push");
    glClear(GL_COLOR_BUFFER_BIT);
    lit_quad(h);
    fc_capture(h);
}

/* The current values under nested pushes: a colour or index set under an
 * inner push of another group becomes current (and marks GL_CURRENT_BIT)
 * at the inner pop's flush, so the outer pop keeps it. */
static void attrib_nested_current(fc_h *h)
{
    static const struct { GLbitfield inner; int color, index; } seq[] = {
        { 0, 1, 0 }, { 0, 1, 1 }, { 0, 0, 1 }, { GL_LIGHTING_BIT, 1, 0 },
        { GL_LIGHTING_BIT, 0, 1 }, { GL_LIGHTING_BIT, 1, 1 }, { GL_FOG_BIT, 1, 1 },
        { GL_CURRENT_BIT, 1, 1 },
    };
    for (size_t i = 0; i < sizeof seq / sizeof seq[0]; i++) {
        glColor3f(1, 0, 0);
        glIndexf(1);
        fc_get_float(h, "GL_CURRENT_COLOR reset", GL_CURRENT_COLOR, 4);
        glPushAttrib(GL_CURRENT_BIT);
        if (seq[i].inner)
            glPushAttrib(seq[i].inner);
        if (seq[i].color)
            glColor3f(0, 1, 0);
        if (seq[i].index)
            glIndexi(9);
        if (seq[i].inner)
            glPopAttrib();
        glPopAttrib();
        fc_get_float(h, "GL_CURRENT_COLOR", GL_CURRENT_COLOR, 4);
        fc_get_float(h, "GL_CURRENT_INDEX", GL_CURRENT_INDEX, 1);
    }
    /* the index set before the inner push, flushed only at the inner pop */
    glIndexf(1);
    fc_get_float(h, "GL_CURRENT_INDEX reset", GL_CURRENT_INDEX, 1);
    glPushAttrib(GL_CURRENT_BIT);
    glIndexi(9);
    glPushAttrib(GL_FOG_BIT);
    glPopAttrib();
    glPopAttrib();
    fc_get_float(h, "GL_CURRENT_INDEX before inner push", GL_CURRENT_INDEX, 1);
    fc_error(h, "nested current");
}

const fc_case fc_cases_query_walk[] = {
    FC_CASE("api/query_walk", 16, 16, OSMESA_RGBA, 24, 8, 0, "api query", query_walk),
    FC_CASE("api/query_walk_modified", 16, 16, OSMESA_RGBA, 24, 8, 0, "api query",
            query_walk_modified),
    FC_CASE("api/query_walk_select_list", 16, 16, OSMESA_RGBA, 24, 8, 0,
            "api query select feedback dlist", query_walk_select_list),
    FC_CASE("api/query_walk_popped", 16, 16, OSMESA_RGBA, 24, 8, 0, "api query",
            query_walk_popped),
    FC_CASE("api/query_walk_popped_nested", 16, 16, OSMESA_RGBA, 24, 8, 0, "api query",
            query_walk_popped_nested),
    /* the oracle's own OSMESA_RGB context (its buffer bits), nothing drawn */
    { "api/query_walk_rgb_nodepth", 16, 16, OSMESA_RGB, 0, 0, 0, "api query", query_walk, 0, 1, 0, 0 },
    FC_CASE_RGBA("api/query_in_begin_end", 8, 8, 0, "api query", query_in_begin_end),
    FC_CASE_RGBA("api/query_bad_pnames", 8, 8, 0, "api query", query_bad_pnames),
    FC_CASE_RGBA("api/query_conversions", 8, 8, 0, "api query", query_conversions),
    FC_CASE_RGBA("api/query_strings", 8, 8, 0, "api query", query_strings),
    FC_CASE_RGBA("api/query_extensions", 8, 8, 0, "api query", query_extensions),
    FC_CASE_RGBA("api/query_get_pointerv", 8, 8, 0, "api query", query_get_pointerv),
    FC_CASE_RGBA("api/query_caps_toggle", 8, 8, 0, "api query", caps_toggle),
    FC_CASE_RGBA("api/client_state_gl14", 8, 8, 0, "api query", client_state_gl14),
    FC_CASE_RGBA("api/getprocaddress", 8, 8, 0, "api query", getprocaddress),
    FC_CASE_RGBA("api/index_calls", 16, 16, 2, "api query", index_calls),
    FC_CASE_RGBA("api/buffer_values", 8, 8, 0, "api query", buffer_values),
    FC_CASE_RGBA("api/buffer_rebind", 8, 8, 0, "api query", buffer_rebind),
    FC_CASE("api/draw_buffer_render", 16, 16, OSMESA_RGBA, 24, 8, 13, "api query",
            draw_buffer_render),
    FC_CASE_RGBA("api/read_buffer_render", 8, 8, 1, "api query", read_buffer_render),
    FC_CASE_RGBA("api/attrib_nested", 16, 16, 2, "api query attrib", attrib_nested),
    FC_CASE_RGBA("api/attrib_nested_current", 8, 8, 0, "api query attrib", attrib_nested_current),
    FC_CASE_RGBA("api/query_fuzz_0", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_1", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_2", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_3", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_4", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_5", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_6", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_7", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_8", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_9", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_10", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_11", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_12", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_13", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_14", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_15", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_16", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_17", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_18", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_19", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_20", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_21", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_22", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_23", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_24", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_25", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_26", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_27", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_28", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_29", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_30", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_31", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_32", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_33", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_34", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_35", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_36", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_37", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_38", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_39", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_40", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_41", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_42", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_43", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_44", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_45", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_46", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_47", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_48", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_49", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_50", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_51", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_52", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_53", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_54", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_55", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_56", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_57", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_58", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_59", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_60", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_61", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_62", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_63", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_174", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_193", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/query_fuzz_645", 8, 8, 0, "api query", query_fuzz),
    FC_CASE_RGBA("api/index_batching", 32, 32, 2, "api query", index_batching),
    FC_CASE_RGBA("api/index_array_element", 16, 16, 2, "api query varray", index_array_element),
    FC_CASE("api/query_walk_bgra_z16", 16, 16, OSMESA_BGRA, 16, 0, 0, "api query", query_walk),
    FC_CASE("api/query_walk_stencil_only", 16, 16, OSMESA_ARGB, 0, 8, 0, "api query", query_walk),
    { 0 }
};
