/* c_attrib.c - glPushAttrib/glPopAttrib: each server group pushed, changed
 * and popped, then queried and drawn; nested pushes with different masks;
 * GL_ALL_ATTRIB_BITS after changing everything; the stack depth, overflow,
 * underflow and glBegin/glEnd errors; and Mesa's ways: light positions and
 * clip planes come back in the eye space they were given in (not
 * re-transformed), GL_ENABLE_BIT leaves the light enables alone, the
 * colour-material materials on pop, and a popped current colour against a
 * colour still in the vertex format. */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

static void get_light(fc_h *h, const char *label, GLenum light, GLenum pname)
{
    GLfloat v[4] = { 0, 0, 0, 0 };
    glGetLightfv(light, pname, v);
    fc_blob(h, label, v, sizeof(v));
}

static void get_material(fc_h *h, const char *label, GLenum face, GLenum pname)
{
    GLfloat v[4] = { 0, 0, 0, 0 };
    glGetMaterialfv(face, pname, v);
    fc_blob(h, label, v, sizeof(v));
}

static void get_clip_plane(fc_h *h, const char *label, GLenum plane)
{
    GLdouble v[4] = { 0, 0, 0, 0 };
    glGetClipPlane(plane, v);
    fc_blob(h, label, v, sizeof(v));
}

/* A lit sphere-ish fan of triangles across the buffer. */
static void lit_grid(void)
{
    glBegin(GL_TRIANGLES);
    for (int j = 0; j < 4; j++) {
        for (int i = 0; i < 4; i++) {
            const float x = -0.9f + 0.45f * (float)i, y = -0.9f + 0.45f * (float)j;
            glNormal3f(x, y, 0.6f);
            glVertex3f(x, y, 0.0f);
            glNormal3f(x + 0.4f, y, 0.5f);
            glVertex3f(x + 0.42f, y, 0.0f);
            glNormal3f(x, y + 0.4f, 0.7f);
            glVertex3f(x, y + 0.42f, 0.0f);
        }
    }
    glEnd();
}

/* Stack depth query, overflow, underflow, glBegin/glEnd errors. */
static void stack_errors(fc_h *h)
{
    fc_get_integer(h, "max depth", GL_MAX_ATTRIB_STACK_DEPTH, 1);
    fc_get_integer(h, "depth 0", GL_ATTRIB_STACK_DEPTH, 1);
    glPopAttrib();
    fc_error(h, "underflow");
    for (int i = 0; i < 16; i++)
        glPushAttrib(i & 1 ? GL_ALL_ATTRIB_BITS : GL_CURRENT_BIT);
    fc_error(h, "16 pushes");
    fc_get_integer(h, "depth 16", GL_ATTRIB_STACK_DEPTH, 1);
    glPushAttrib(GL_ENABLE_BIT);
    fc_error(h, "overflow");
    fc_get_integer(h, "still 16", GL_ATTRIB_STACK_DEPTH, 1);
    glBegin(GL_POINTS);
    glPopAttrib();
    glEnd();
    fc_error(h, "pop inside glBegin/glEnd");
    fc_get_integer(h, "16 after pop in begin", GL_ATTRIB_STACK_DEPTH, 1);
    for (int i = 0; i < 16; i++)
        glPopAttrib();
    fc_error(h, "16 pops");
    glBegin(GL_POINTS);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glEnd();
    fc_error(h, "push inside glBegin/glEnd");
    fc_get_integer(h, "0 after push in begin", GL_ATTRIB_STACK_DEPTH, 1);
    /* masks of the texture, evaluator, list, pixel, accumulation and
     * multisample groups, and of no bit at all */
    glPushAttrib(GL_TEXTURE_BIT | GL_EVAL_BIT | GL_LIST_BIT | GL_PIXEL_MODE_BIT |
                 GL_ACCUM_BUFFER_BIT | GL_MULTISAMPLE_BIT);
    glPushAttrib(0);
    glPushAttrib(0x80000000u);
    fc_get_integer(h, "depth 3", GL_ATTRIB_STACK_DEPTH, 1);
    glPopAttrib();
    glPopAttrib();
    glPopAttrib();
    fc_error(h, "final");
}

/* GL_COLOR_BUFFER_BIT: alpha test, blend, logic op, masks, clear colour,
 * dither. */
static void color_buffer(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.3f);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glPushAttrib(GL_COLOR_BUFFER_BIT);
    glClearColor(1.5f, -0.5f, 0.1f, 0.0f);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glDisable(GL_ALPHA_TEST);
    glAlphaFunc(GL_LESS, 0.9f);
    glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glDisable(GL_DITHER);
    glDepthFunc(GL_NEVER);  /* not in the group */
    fc_get_float(h, "changed clear colour", GL_COLOR_CLEAR_VALUE, 4);
    glPopAttrib();
    fc_get_float(h, "clear colour", GL_COLOR_CLEAR_VALUE, 4);
    fc_is_enabled(h, "blend", GL_BLEND);
    fc_is_enabled(h, "alpha test", GL_ALPHA_TEST);
    fc_is_enabled(h, "logic op", GL_COLOR_LOGIC_OP);
    fc_is_enabled(h, "dither", GL_DITHER);
    fc_get_integer(h, "blend src", GL_BLEND_SRC, 1);
    fc_get_integer(h, "blend dst", GL_BLEND_DST, 1);
    fc_get_integer(h, "alpha func", GL_ALPHA_TEST_FUNC, 1);
    fc_get_float(h, "alpha ref", GL_ALPHA_TEST_REF, 1);
    fc_get_integer(h, "logic op mode", GL_LOGIC_OP_MODE, 1);
    fc_get_boolean(h, "colour mask", GL_COLOR_WRITEMASK, 4);
    fc_get_integer(h, "depth func kept", GL_DEPTH_FUNC, 1);
    glDepthFunc(GL_LESS);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    for (int i = 0; i < 8; i++) {
        glColor4f(0.9f, 0.2f * (float)i, 0.1f, 0.125f * (float)i);
        fcu_rect(8.0f * (float)i, 0, 8.0f * (float)i + 8.0f, 64, 0);
    }
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_CURRENT_BIT: colour, normal, edge flag back; a colour set after the
 * push and still in the vertex format when popping. */
static void current_bit(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
    glNormal3f(0.0f, 1.0f, 0.0f);
    glEdgeFlag(GL_FALSE);
    fcu_rect(0, 0, 4, 4, 0);       /* flushes the colour to the current values */
    glPushAttrib(GL_CURRENT_BIT);
    glColor3f(1.0f, 0.0f, 0.0f);
    glNormal3f(1.0f, 2.0f, 3.0f);
    glEdgeFlag(GL_TRUE);
    fcu_rect(4, 0, 8, 4, 0);
    glPopAttrib();
    fc_get_float(h, "colour after drawn change", GL_CURRENT_COLOR, 4);
    fc_get_float(h, "normal", GL_CURRENT_NORMAL, 3);
    fc_get_boolean(h, "edge flag", GL_EDGE_FLAG, 1);
    fcu_rect(0, 8, 32, 32, 0);
    /* the colour set after the push, not drawn before the pop */
    glPushAttrib(GL_CURRENT_BIT);
    glColor3f(0.0f, 1.0f, 0.0f);
    glPopAttrib();
    fc_get_float(h, "colour after undrawn change", GL_CURRENT_COLOR, 4);
    fcu_rect(32, 8, 64, 32, 0);
    fc_get_float(h, "colour after draw", GL_CURRENT_COLOR, 4);
    /* inside a batch: a vertex stored before the push */
    glPushAttrib(GL_CURRENT_BIT);
    glColor3f(0.0f, 0.0f, 1.0f);
    fcu_rect(0, 34, 32, 62, 0);
    glColor3f(1.0f, 1.0f, 0.0f);
    glPopAttrib();
    fc_get_float(h, "colour after batch", GL_CURRENT_COLOR, 4);
    fcu_rect(32, 34, 64, 62, 0);
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_DEPTH_BUFFER_BIT and GL_STENCIL_BUFFER_BIT (no stencil buffer: state
 * only), GL_SCISSOR_BIT. */
static void depth_scissor(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glClearDepth(0.75);
    glEnable(GL_SCISSOR_TEST);
    glScissor(4, 6, 50, 40);
    glStencilFunc(GL_EQUAL, 3, 0x0f);
    glStencilOp(GL_KEEP, GL_INCR, GL_DECR);
    glStencilMask(0xf0);
    glClearStencil(5);
    glPushAttrib(GL_DEPTH_BUFFER_BIT | GL_SCISSOR_BIT | GL_STENCIL_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glClearDepth(0.25);
    glScissor(0, 0, 10, 10);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 1, 0xff);
    glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
    glStencilMask(0x1);
    glClearStencil(1);
    glPopAttrib();
    fc_is_enabled(h, "depth test", GL_DEPTH_TEST);
    fc_get_integer(h, "depth func", GL_DEPTH_FUNC, 1);
    fc_get_boolean(h, "depth mask", GL_DEPTH_WRITEMASK, 1);
    fc_get_double(h, "clear depth", GL_DEPTH_CLEAR_VALUE, 1);
    fc_is_enabled(h, "scissor", GL_SCISSOR_TEST);
    fc_get_integer(h, "scissor box", GL_SCISSOR_BOX, 4);
    fc_is_enabled(h, "stencil", GL_STENCIL_TEST);
    fc_get_integer(h, "stencil func", GL_STENCIL_FUNC, 1);
    fc_get_integer(h, "stencil ref", GL_STENCIL_REF, 1);
    fc_get_integer(h, "stencil value mask", GL_STENCIL_VALUE_MASK, 1);
    fc_get_integer(h, "stencil write mask", GL_STENCIL_WRITEMASK, 1);
    fc_get_integer(h, "stencil fail", GL_STENCIL_FAIL, 1);
    fc_get_integer(h, "stencil zfail", GL_STENCIL_PASS_DEPTH_FAIL, 1);
    fc_get_integer(h, "stencil zpass", GL_STENCIL_PASS_DEPTH_PASS, 1);
    fc_get_integer(h, "clear stencil", GL_STENCIL_CLEAR_VALUE, 1);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fcu_color(1);
    fcu_rect(0, 0, 64, 64, 0.4f);
    fcu_color(2);
    fcu_rect(10, 10, 60, 60, 0.8f);
    fcu_color(3);
    fcu_rect(0, 20, 40, 64, -0.2f);
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_ENABLE_BIT: every enable back, but not the lights (Mesa 22.3 saves
 * them and never restores them). */
static void enable_bit(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_LIGHT1);
    glEnable(GL_CULL_FACE);
    glEnable(GL_CLIP_PLANE2);
    glEnable(GL_NORMALIZE);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_POLYGON_SMOOTH);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_LIGHT1);
    glEnable(GL_LIGHT3);
    glDisable(GL_CULL_FACE);
    glDisable(GL_CLIP_PLANE2);
    glEnable(GL_CLIP_PLANE5);
    glDisable(GL_NORMALIZE);
    glEnable(GL_RESCALE_NORMAL);
    glDisable(GL_AUTO_NORMAL);
    glDisable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP1_COLOR_4);
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_GEN_S);
    glDisable(GL_POLYGON_SMOOTH);
    glEnable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_FOG);
    glEnable(GL_LIGHTING);
    glEnable(GL_LINE_STIPPLE);
    glEnable(GL_POLYGON_STIPPLE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_SCISSOR_TEST);
    glDisable(GL_DITHER);
    glEnable(GL_INDEX_LOGIC_OP);
    glEnable(GL_VERTEX_ARRAY);   /* client state: not in the group */
    glPopAttrib();
    static const GLenum caps[] = {
        GL_LIGHT1, GL_LIGHT3, GL_CULL_FACE, GL_CLIP_PLANE2, GL_CLIP_PLANE5,
        GL_NORMALIZE, GL_RESCALE_NORMAL, GL_AUTO_NORMAL, GL_MAP2_VERTEX_3,
        GL_MAP1_COLOR_4, GL_TEXTURE_2D, GL_TEXTURE_GEN_S, GL_POLYGON_SMOOTH,
        GL_BLEND, GL_DEPTH_TEST, GL_FOG, GL_LIGHTING, GL_LINE_STIPPLE,
        GL_POLYGON_STIPPLE, GL_POLYGON_OFFSET_FILL, GL_POINT_SMOOTH,
        GL_SCISSOR_TEST, GL_DITHER, GL_INDEX_LOGIC_OP, GL_VERTEX_ARRAY,
    };
    for (unsigned i = 0; i < sizeof(caps) / sizeof(caps[0]); i++) {
        char label[32];
        snprintf(label, sizeof(label), "cap %u", i);
        fc_is_enabled(h, label, caps[i]);
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    fcu_clear(0, 0, 0, 0, 1);
    fcu_color(4);
    fcu_tri(2, 2, 60, 10, 20, 60);   /* clockwise in window space? both ways */
    fcu_tri(62, 62, 60, 4, 4, 50);
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_LIGHTING_BIT: lights pushed under one modelview and popped under
 * another keep their eye-space positions; light model, materials, colour
 * material, shade model. */
static void lighting_bit(fc_h *h)
{
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT2);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    const GLfloat pos0[4] = { 0.5f, 0.5f, 1.0f, 0.0f };
    const GLfloat pos2[4] = { -0.5f, 0.2f, 0.8f, 1.0f };
    const GLfloat dir2[3] = { 0.3f, 0.0f, -1.0f };
    const GLfloat red[4] = { 1.0f, 0.2f, 0.1f, 1.0f };
    glLightfv(GL_LIGHT0, GL_POSITION, pos0);
    glLightfv(GL_LIGHT2, GL_POSITION, pos2);
    glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, dir2);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 60.0f);
    glLightfv(GL_LIGHT2, GL_DIFFUSE, red);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    const GLfloat mdiff[4] = { 0.3f, 0.8f, 0.5f, 1.0f };
    const GLfloat mspec[4] = { 0.6f, 0.6f, 0.6f, 1.0f };
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, mdiff);
    glMaterialfv(GL_FRONT, GL_SPECULAR, mspec);
    glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
    glShadeModel(GL_FLAT);
    glPushAttrib(GL_LIGHTING_BIT);
    glLoadIdentity();
    glRotatef(-45.0f, 1.0f, 0.0f, 0.0f);
    const GLfloat pos0b[4] = { -1.0f, 0.0f, 0.3f, 1.0f };
    glLightfv(GL_LIGHT0, GL_POSITION, pos0b);
    glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, pos0b);
    glDisable(GL_LIGHT2);
    glEnable(GL_LIGHT5);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const GLfloat blue[4] = { 0.0f, 0.1f, 1.0f, 1.0f };
    glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
    glMaterialf(GL_FRONT, GL_SHININESS, 3.0f);
    glShadeModel(GL_SMOOTH);
    glDisable(GL_LIGHTING);
    glPopAttrib();
    /* popped under the second modelview */
    get_light(h, "light0 position", GL_LIGHT0, GL_POSITION);
    get_light(h, "light2 position", GL_LIGHT2, GL_POSITION);
    get_light(h, "light2 spot", GL_LIGHT2, GL_SPOT_DIRECTION);
    fc_is_enabled(h, "light2", GL_LIGHT2);
    fc_is_enabled(h, "light5", GL_LIGHT5);
    fc_is_enabled(h, "lighting", GL_LIGHTING);
    fc_get_boolean(h, "two side", GL_LIGHT_MODEL_TWO_SIDE, 1);
    fc_get_boolean(h, "local viewer", GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    fc_get_integer(h, "shade model", GL_SHADE_MODEL, 1);
    get_material(h, "front diffuse", GL_FRONT, GL_DIFFUSE);
    get_material(h, "front shininess", GL_FRONT, GL_SHININESS);
    lit_grid();
    fc_capture(h);
    /* the same after a modelview change after the pop */
    glLoadIdentity();
    fcu_clear(0, 0, 0, 0, 1);
    glFrontFace(GL_CW);
    lit_grid();
    fc_capture(h);
    fc_error(h, "final");
}

/* Colour material and the lighting/enable bits: the tracked materials on
 * pop, and whether the pop re-runs the colour material. */
static void color_material(fc_h *h)
{
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glColor3f(0.9f, 0.3f, 0.1f);
    glEnable(GL_COLOR_MATERIAL);
    glPushAttrib(GL_LIGHTING_BIT);
    glColor3f(0.1f, 0.9f, 0.4f);
    lit_grid();                   /* tracked material follows the colour */
    glPopAttrib();
    get_material(h, "diffuse after lighting pop", GL_FRONT, GL_DIFFUSE);
    get_material(h, "ambient after lighting pop", GL_FRONT, GL_AMBIENT);
    fc_get_float(h, "colour", GL_CURRENT_COLOR, 4);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_COLOR_MATERIAL);
    glColor3f(0.2f, 0.2f, 1.0f);
    glPopAttrib();                /* re-enables: the colour is loaded */
    get_material(h, "diffuse after enable pop", GL_FRONT, GL_DIFFUSE);
    glPushAttrib(GL_LIGHTING_BIT);
    glColorMaterial(GL_BACK, GL_SPECULAR);
    glDisable(GL_COLOR_MATERIAL);
    glColor3f(1.0f, 1.0f, 1.0f);
    glPopAttrib();
    fc_get_integer(h, "colour material face", GL_COLOR_MATERIAL_FACE, 1);
    fc_get_integer(h, "colour material parameter", GL_COLOR_MATERIAL_PARAMETER, 1);
    fc_is_enabled(h, "colour material", GL_COLOR_MATERIAL);
    get_material(h, "diffuse after second lighting pop", GL_FRONT, GL_DIFFUSE);
    get_material(h, "back specular", GL_BACK, GL_SPECULAR);
    fcu_clear(0, 0, 0, 0, 1);
    lit_grid();
    fc_capture(h);
    glDisable(GL_COLOR_MATERIAL);
    fcu_clear(0, 0, 0, 0, 1);
    lit_grid();
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_TRANSFORM_BIT: matrix mode, clip planes (stored eye planes, not
 * re-transformed), normalize, rescale; GL_VIEWPORT_BIT. */
static void transform_viewport(fc_h *h)
{
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    fcu_clear(0, 0, 0, 0, 1);
    glViewport(4, 2, 56, 58);
    glDepthRange(0.2, 0.9);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    const GLdouble plane[4] = { 1.0, 0.5, 0.0, 0.2 };
    glClipPlane(GL_CLIP_PLANE1, plane);
    glEnable(GL_CLIP_PLANE1);
    glEnable(GL_NORMALIZE);
    glMatrixMode(GL_PROJECTION);
    glPushAttrib(GL_TRANSFORM_BIT | GL_VIEWPORT_BIT);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(-60.0f, 0.0f, 0.0f, 1.0f);
    const GLdouble plane2[4] = { -1.0, 0.0, 0.0, 0.5 };
    glClipPlane(GL_CLIP_PLANE1, plane2);
    glClipPlane(GL_CLIP_PLANE3, plane2);
    glEnable(GL_CLIP_PLANE3);
    glDisable(GL_NORMALIZE);
    glEnable(GL_RESCALE_NORMAL);
    glViewport(0, 0, 20, 30);
    glDepthRange(1.0, 0.0);
    glPopAttrib();
    fc_get_integer(h, "matrix mode", GL_MATRIX_MODE, 1);
    get_clip_plane(h, "plane1", GL_CLIP_PLANE1);
    get_clip_plane(h, "plane3", GL_CLIP_PLANE3);
    fc_is_enabled(h, "plane3", GL_CLIP_PLANE3);
    fc_is_enabled(h, "plane1", GL_CLIP_PLANE1);
    fc_is_enabled(h, "normalize", GL_NORMALIZE);
    fc_is_enabled(h, "rescale", GL_RESCALE_NORMAL);
    fc_get_integer(h, "viewport", GL_VIEWPORT, 4);
    fc_get_float(h, "depth range", GL_DEPTH_RANGE, 2);
    /* the popped matrix mode is the projection: this scales the scene */
    glScalef(0.8f, 0.8f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.5f, 0.0f);
    glVertex3f(-1.0f, -1.0f, -0.5f);
    glColor3f(0.0f, 0.5f, 1.0f);
    glVertex3f(1.0f, -0.8f, 0.5f);
    glColor3f(0.5f, 1.0f, 0.5f);
    glVertex3f(0.0f, 1.0f, 0.0f);
    glEnd();
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_POLYGON_BIT, GL_POLYGON_STIPPLE_BIT, GL_LINE_BIT, GL_POINT_BIT. */
static void raster_groups(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    GLubyte stipple[128];
    for (int i = 0; i < 128; i++)
        stipple[i] = (GLubyte)(0x55u << (i & 1));
    glPolygonStipple(stipple);
    glEnable(GL_POLYGON_STIPPLE);
    glPolygonMode(GL_BACK, GL_LINE);
    glCullFace(GL_FRONT);
    glPolygonOffset(1.0f, 2.0f);
    glLineWidth(3.0f);
    glLineStipple(2, 0x0f0f);
    glEnable(GL_LINE_STIPPLE);
    glPointSize(4.0f);
    glPushAttrib(GL_POLYGON_BIT | GL_POLYGON_STIPPLE_BIT | GL_LINE_BIT | GL_POINT_BIT);
    for (int i = 0; i < 128; i++)
        stipple[i] = 0xff;
    glPolygonStipple(stipple);
    glDisable(GL_POLYGON_STIPPLE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glCullFace(GL_BACK);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CW);
    glPolygonOffset(-1.0f, 0.0f);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glLineWidth(1.0f);
    glLineStipple(1, 0xffff);
    glDisable(GL_LINE_STIPPLE);
    glEnable(GL_LINE_SMOOTH);
    glPointSize(1.0f);
    glEnable(GL_POINT_SMOOTH);
    glPopAttrib();
    fc_get_integer(h, "polygon mode", GL_POLYGON_MODE, 2);
    fc_get_integer(h, "cull face mode", GL_CULL_FACE_MODE, 1);
    fc_is_enabled(h, "cull", GL_CULL_FACE);
    fc_get_integer(h, "front face", GL_FRONT_FACE, 1);
    fc_get_float(h, "offset factor", GL_POLYGON_OFFSET_FACTOR, 1);
    fc_get_float(h, "offset units", GL_POLYGON_OFFSET_UNITS, 1);
    fc_is_enabled(h, "offset line", GL_POLYGON_OFFSET_LINE);
    fc_is_enabled(h, "polygon stipple", GL_POLYGON_STIPPLE);
    fc_get_float(h, "line width", GL_LINE_WIDTH, 1);
    fc_get_integer(h, "line stipple pattern", GL_LINE_STIPPLE_PATTERN, 1);
    fc_get_integer(h, "line stipple repeat", GL_LINE_STIPPLE_REPEAT, 1);
    fc_is_enabled(h, "line stipple", GL_LINE_STIPPLE);
    fc_is_enabled(h, "line smooth", GL_LINE_SMOOTH);
    fc_get_float(h, "point size", GL_POINT_SIZE, 1);
    fc_is_enabled(h, "point smooth", GL_POINT_SMOOTH);
    GLubyte back[128];
    glGetPolygonStipple(back);
    fc_blob(h, "stipple", back, sizeof(back));
    fcu_color(5);
    fcu_tri(2, 2, 40, 4, 10, 40);      /* front: stippled */
    fcu_color(6);
    fcu_tri(62, 62, 60, 20, 20, 60);   /* back: lines */
    fcu_color(7);
    glBegin(GL_LINES);
    glVertex2f(2.5f, 60.5f);
    glVertex2f(40.5f, 45.5f);
    glEnd();
    glBegin(GL_POINTS);
    glVertex2f(50.5f, 10.5f);
    glEnd();
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_FOG_BIT and GL_HINT_BIT (the generate-mipmap hint is not restored by
 * Mesa's pop). */
static void fog_hint(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0.0f);
    glFogf(GL_FOG_END, 1.0f);
    const GLfloat fc[4] = { 0.2f, 0.9f, 0.3f, 1.0f };
    glFogfv(GL_FOG_COLOR, fc);
    glHint(GL_FOG_HINT, GL_NICEST);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_FASTEST);
    glPushAttrib(GL_FOG_BIT | GL_HINT_BIT);
    glDisable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 3.0f);
    glFogf(GL_FOG_END, 0.25f);
    const GLfloat fc2[4] = { 1.5f, -0.2f, 0.5f, 0.5f };
    glFogfv(GL_FOG_COLOR, fc2);
    glHint(GL_FOG_HINT, GL_FASTEST);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    glHint(GL_GENERATE_MIPMAP_HINT, GL_NICEST);
    glPopAttrib();
    fc_is_enabled(h, "fog", GL_FOG);
    fc_get_integer(h, "fog mode", GL_FOG_MODE, 1);
    fc_get_float(h, "fog density", GL_FOG_DENSITY, 1);
    fc_get_float(h, "fog end", GL_FOG_END, 1);
    fc_get_float(h, "fog colour", GL_FOG_COLOR, 4);
    fc_get_integer(h, "fog hint", GL_FOG_HINT, 1);
    fc_get_integer(h, "perspective hint", GL_PERSPECTIVE_CORRECTION_HINT, 1);
    fc_get_integer(h, "line smooth hint", GL_LINE_SMOOTH_HINT, 1);
    fc_get_integer(h, "generate mipmap hint", GL_GENERATE_MIPMAP_HINT, 1);
    glBegin(GL_QUADS);
    glColor3f(1.0f, 0.0f, 0.5f);
    glVertex3f(2, 2, 0.9f);
    glVertex3f(62, 2, -0.9f);
    glVertex3f(62, 62, 0.0f);
    glVertex3f(2, 62, 0.5f);
    glEnd();
    fc_capture(h);
    fc_error(h, "final");
}

/* Nested pushes with different masks pop in order. */
static void nested(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glColor3f(1.0f, 0.0f, 0.0f);
    glPointSize(2.0f);
    glPushAttrib(GL_CURRENT_BIT | GL_POINT_BIT);
    glColor3f(0.0f, 1.0f, 0.0f);
    glPointSize(5.0f);
    glEnable(GL_BLEND);
    glPushAttrib(GL_ENABLE_BIT);
    glColor3f(0.0f, 0.0f, 1.0f);
    glPointSize(7.0f);
    glDisable(GL_BLEND);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 32, 64);
    glPushAttrib(GL_SCISSOR_BIT | GL_POINT_BIT);
    glScissor(0, 0, 16, 16);
    glPointSize(9.0f);
    fc_get_integer(h, "depth 3", GL_ATTRIB_STACK_DEPTH, 1);
    glBegin(GL_POINTS);
    glVertex2f(8.5f, 8.5f);
    glEnd();
    glPopAttrib();
    fc_get_integer(h, "scissor box 2", GL_SCISSOR_BOX, 4);
    fc_get_float(h, "point size 7", GL_POINT_SIZE, 1);
    glBegin(GL_POINTS);
    glVertex2f(20.5f, 20.5f);
    glVertex2f(40.5f, 20.5f);
    glEnd();
    glPopAttrib();
    fc_is_enabled(h, "blend back on", GL_BLEND);
    fc_is_enabled(h, "scissor off", GL_SCISSOR_TEST);
    fc_get_float(h, "point size still 7", GL_POINT_SIZE, 1);
    fc_get_float(h, "colour blue", GL_CURRENT_COLOR, 4);
    glBlendFunc(GL_ONE, GL_ONE);
    glBegin(GL_POINTS);
    glVertex2f(40.5f, 40.5f);
    glEnd();
    glPopAttrib();
    fc_get_float(h, "point size 2", GL_POINT_SIZE, 1);
    fc_get_float(h, "colour red", GL_CURRENT_COLOR, 4);
    fc_get_integer(h, "depth 0", GL_ATTRIB_STACK_DEPTH, 1);
    glBegin(GL_POINTS);
    glVertex2f(50.5f, 50.5f);
    glEnd();
    fc_capture(h);
    fc_error(h, "final");
}

/* GL_ALL_ATTRIB_BITS after changing everything: the state of the first
 * frame again. */
static void scene(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    lit_grid();
    glBegin(GL_LINES);
    glVertex3f(-0.9f, 0.8f, 0.2f);
    glVertex3f(0.9f, 0.6f, -0.2f);
    glEnd();
    glBegin(GL_POINTS);
    glVertex3f(0.5f, -0.5f, 0.0f);
    glEnd();
}

static void all_bits(fc_h *h)
{
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_FOG);
    glFogf(GL_FOG_DENSITY, 0.7f);
    glPointSize(3.0f);
    glLineWidth(2.0f);
    glColor3f(0.8f, 0.7f, 0.2f);
    glNormal3f(0.0f, 0.0f, 1.0f);
    scene();
    fc_capture(h);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glClearColor(0.5f, 0.0f, 0.0f, 0.0f);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glEnable(GL_LIGHT1);
    glDisable(GL_LIGHT0);
    glDisable(GL_FOG);
    glFogf(GL_FOG_DENSITY, 0.1f);
    glPointSize(6.0f);
    glLineWidth(1.0f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glNormal3f(1.0f, 0.0f, 0.0f);
    glViewport(0, 0, 16, 16);
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 1, 3, 3);
    glEnable(GL_BLEND);
    glColorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glShadeModel(GL_FLAT);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glMatrixMode(GL_PROJECTION);
    glEnable(GL_CLIP_PLANE0);
    glHint(GL_FOG_HINT, GL_NICEST);
    const GLfloat spec[4] = { 1, 1, 1, 1 };
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1.0f);
    scene();
    fc_capture(h);
    glPopAttrib();
    fc_get_integer(h, "matrix mode", GL_MATRIX_MODE, 1);
    fc_get_integer(h, "viewport", GL_VIEWPORT, 4);
    fc_is_enabled(h, "light1", GL_LIGHT1);
    fc_is_enabled(h, "light0", GL_LIGHT0);
    fc_get_integer(h, "depth 0", GL_ATTRIB_STACK_DEPTH, 1);
    scene();
    fc_capture(h);
    fc_error(h, "final");
}

const fc_case fc_cases_attrib[] = {
    FC_CASE_RGBA("attrib/stack_errors", 16, 16, 0, "api attrib errors query", stack_errors),
    FC_CASE_RGBA("attrib/color_buffer", 64, 64, 1, "api attrib", color_buffer),
    FC_CASE_RGBA("attrib/current", 64, 64, 1, "api attrib", current_bit),
    FC_CASE("attrib/depth_scissor_stencil", 64, 64, OSMESA_RGBA, 24, 8, 1, "api attrib", depth_scissor),
    FC_CASE_RGBA("attrib/enable", 64, 64, 1, "api attrib", enable_bit),
    FC_CASE_RGBA("attrib/lighting", 64, 64, 2, "api attrib lighting", lighting_bit),
    FC_CASE_RGBA("attrib/color_material", 64, 64, 2, "api attrib lighting", color_material),
    FC_CASE_RGBA("attrib/transform_viewport", 64, 64, 1, "api attrib clip", transform_viewport),
    FC_CASE_RGBA("attrib/raster_groups", 64, 64, 1, "api attrib polygon", raster_groups),
    FC_CASE_RGBA("attrib/fog_hint", 64, 64, 1, "api attrib fog", fog_hint),
    FC_CASE_RGBA("attrib/nested", 64, 64, 1, "api attrib", nested),
    FC_CASE_RGBA("attrib/all_bits", 64, 64, 3, "api attrib lighting", all_bits),
    { 0 }
};
