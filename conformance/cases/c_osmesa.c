/* c_osmesa.c - the OSMesa API (issue 19, "OSMesa API"; ORACLE-NOTES.md
 * "OSMesa contexts and buffers"):
 *  - OSMesaCreateContextAttribs: the attribute lists both libraries refuse
 *    and the GL 1.x requests both honour (a context that draws); what
 *    fixgl cannot provide (a core profile, a version above 1.5) is a
 *    documented difference: the oracle, a GL 4.5 implementation, gives a
 *    context;
 *  - GL_UNSIGNED_SHORT and GL_FLOAT buffers (the oracle's
 *    R16G16B16A16_UNORM and R32G32B32A32_FLOAT render targets, RGBA
 *    order for every format of the RGBA family): which format/type pairs
 *    OSMesaMakeCurrent takes, clears (unclamped on floats), flat and
 *    smooth triangles, blending in the target's precision, lines and
 *    points, glReadPixels, OSMesaGetColorBuffer; each recorded as the
 *    application's buffer's bytes. */
#include "cases.h"

#include <stdio.h>
#include <string.h>

/* A context from `attribs` bound to a 4x4 RGBA ubyte buffer, cleared and
 * a triangle drawn; records whether it was created and what it drew, then
 * binds the harness's context again. */
static void try_attribs(fc_h *h, const char *label, const int *attribs)
{
    static GLubyte px[4 * 4 * 4];
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
    char l[96];
    snprintf(l, sizeof l, "%s: created", label);
    fc_value(h, l, ctx != NULL);
    if (!ctx)
        return;
    memset(px, 0xA5, sizeof px);
    snprintf(l, sizeof l, "%s: bound", label);
    fc_value(h, l, OSMesaMakeCurrent(ctx, px, GL_UNSIGNED_BYTE, 4, 4));
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-1, -1);
    glColor3f(0, 1, 0); glVertex2f(1, -1);
    glColor3f(0, 0, 1); glVertex2f(-1, 1);
    glEnd();
    glFinish();
    snprintf(l, sizeof l, "%s: pixels", label);
    fc_blob(h, l, px, sizeof px);
    snprintf(l, sizeof l, "%s: error", label);
    fc_value(h, l, (long long)glGetError());
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    const fc_case *c = fc_this_case(h);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, c->width, c->height);
}

#define A(...) ((const int[]){ __VA_ARGS__, 0 })

static void attribs_refused(fc_h *h)
{
    try_attribs(h, "unknown attribute", A(0x9999, 1));
    try_attribs(h, "OSMESA_Y_UP as an attribute", A(OSMESA_Y_UP, 0));
    try_attribs(h, "profile 0x1234", A(OSMESA_PROFILE, 0x1234));
    try_attribs(h, "format 0x1234", A(OSMESA_FORMAT, 0x1234));
    try_attribs(h, "depth -1", A(OSMESA_DEPTH_BITS, -1));
    try_attribs(h, "stencil -2", A(OSMESA_STENCIL_BITS, -2));
    try_attribs(h, "accum -1", A(OSMESA_ACCUM_BITS, -1));
    try_attribs(h, "major 0", A(OSMESA_CONTEXT_MAJOR_VERSION, 0));
    try_attribs(h, "minor -1", A(OSMESA_CONTEXT_MINOR_VERSION, -1));
    try_attribs(h, "major 0 then 1", A(OSMESA_CONTEXT_MAJOR_VERSION, 0,
                                       OSMESA_CONTEXT_MAJOR_VERSION, 1));
    try_attribs(h, "4.6", A(OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 6));
    try_attribs(h, "1.100", A(OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 100));
    try_attribs(h, "core 9.9", A(OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                 OSMESA_CONTEXT_MAJOR_VERSION, 9, OSMESA_CONTEXT_MINOR_VERSION, 9));
    fc_error(h, "end");
}

static void attribs_compat(fc_h *h)
{
    try_attribs(h, "empty", A(0));
    try_attribs(h, "compat", A(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE));
    for (int minor = 0; minor <= 5; minor++) {
        char l[32];
        snprintf(l, sizeof l, "compat 1.%d", minor);
        try_attribs(h, l, A(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, minor));
    }
    try_attribs(h, "minor 5 alone", A(OSMESA_CONTEXT_MINOR_VERSION, 5));
    try_attribs(h, "core then compat", A(OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                         OSMESA_PROFILE, OSMESA_COMPAT_PROFILE));
    try_attribs(h, "major 3 then 1", A(OSMESA_CONTEXT_MAJOR_VERSION, 3,
                                       OSMESA_CONTEXT_MAJOR_VERSION, 1));
    try_attribs(h, "BGRA, depth 16, stencil 8, accum 16",
                A(OSMESA_FORMAT, OSMESA_BGRA, OSMESA_DEPTH_BITS, 16, OSMESA_STENCIL_BITS, 8,
                  OSMESA_ACCUM_BITS, 16, OSMESA_CONTEXT_MAJOR_VERSION, 1,
                  OSMESA_CONTEXT_MINOR_VERSION, 3));
    fc_error(h, "end");
}

/* What fixgl cannot provide: NULL there, a context in the oracle. */
static void attribs_unprovided(fc_h *h)
{
    static const char why[] = "deliberate: fixgl implements GL 1.x without a core profile "
                              "and refuses a core profile or a version above 1.5; the "
                              "oracle implements 4.5";
    const struct { const char *label; const int *attribs; } req[] = {
        { "core", A(OSMESA_PROFILE, OSMESA_CORE_PROFILE) },
        { "core 3.3", A(OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                        OSMESA_CONTEXT_MINOR_VERSION, 3) },
        { "compat 1.6", A(OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 6) },
        { "compat 2.1", A(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 2,
                          OSMESA_CONTEXT_MINOR_VERSION, 1) },
        { "compat 3.0", A(OSMESA_CONTEXT_MAJOR_VERSION, 3) },
        { "compat 4.5", A(OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5) },
    };
    for (size_t i = 0; i < sizeof req / sizeof req[0]; i++) {
        static GLubyte px[4 * 4 * 4];
        char l[64];
        snprintf(l, sizeof l, "%s: created", req[i].label);
        fc_documented_difference(h, l, why);
        OSMesaContext ctx = OSMesaCreateContextAttribs(req[i].attribs, NULL);
        fc_value(h, l, ctx != NULL);
        if (ctx) {
            OSMesaMakeCurrent(ctx, px, GL_UNSIGNED_BYTE, 4, 4);
            OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
            OSMesaDestroyContext(ctx);
        }
    }
    const fc_case *c = fc_this_case(h);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, c->width, c->height);
    fc_error(h, "end");
}

/* ---- wide buffers ---------------------------------------------------- */

#define WW 24
#define WH 16

static float wbuf[WW * WH * 4 * 2];   /* room for either type */

/* Binds a context of `format` to the wide buffer as `type` (the buffer
 * pre-filled with a pattern), runs `draw`, records the buffer's bytes and
 * binds the harness's context again. */
static void wide_run(fc_h *h, const char *label, GLenum format, GLenum type,
                     void (*draw)(fc_h *h), int depth, int accum)
{
    const int nc = format == OSMESA_RGB ? 3 : 4;
    const size_t size = (size_t)WW * WH * (size_t)nc * (type == GL_FLOAT ? 4 : 2);
    OSMesaContext ctx = OSMesaCreateContextExt(format, depth, 0, accum, NULL);
    char l[96];
    snprintf(l, sizeof l, "%s: created", label);
    fc_value(h, l, ctx != NULL);
    if (!ctx)
        return;
    memset(wbuf, 0, sizeof wbuf);
    snprintf(l, sizeof l, "%s: bound", label);
    const GLboolean ok = OSMesaMakeCurrent(ctx, wbuf, type, WW, WH);
    fc_value(h, l, ok);
    if (ok) {
        glViewport(0, 0, WW, WH);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0, WW, 0, WH, -1, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        draw(h);
        glFinish();
        snprintf(l, sizeof l, "%s: buffer", label);
        fc_blob(h, l, wbuf, size);
        snprintf(l, sizeof l, "%s: error", label);
        fc_value(h, l, (long long)glGetError());
        GLint w = 0, hh = 0, f = 0;
        void *b = NULL;
        snprintf(l, sizeof l, "%s: GetColorBuffer", label);
        fc_value(h, l, OSMesaGetColorBuffer(ctx, &w, &hh, &f, &b));
        fc_value(h, "  size", (long long)w * 1000 + hh);
        fc_value(h, "  format", f);
        fc_value(h, "  is the buffer", b == (void *)wbuf);
        GLint t = 0;
        OSMesaGetIntegerv(OSMESA_TYPE, &t);
        fc_value(h, "  OSMESA_TYPE", t);
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    const fc_case *c = fc_this_case(h);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, c->width, c->height);
}

static void smooth_tris(void)
{
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0.25f, 1); glVertex2f(0.5f, 0.25f);
    glColor4f(0, 1, 0.5f, 0.5f); glVertex2f(23.5f, 1.5f);
    glColor4f(0.2f, 0.3f, 1, 0); glVertex2f(3.25f, 15.75f);
    glColor4f(0.9f, 0.8f, 0.1f, 0.3f); glVertex2f(23.0f, 15.0f);
    glColor4f(0.1f, 0.6f, 0.7f, 0.9f); glVertex2f(12.3f, 15.9f);
    glColor4f(0.4f, 0.1f, 0.95f, 0.6f); glVertex2f(20.1f, 4.2f);
    glEnd();
}

static void draw_clears(fc_h *h)
{
    (void)h;
    glClearColor(0.3f, 0.6f, 0.123456f, 0.7f);
    glClear(GL_COLOR_BUFFER_BIT);
    /* a scissored clear (a quad) and a masked one, out-of-range values */
    glEnable(GL_SCISSOR_TEST);
    glScissor(2, 3, 9, 7);
    glClearColor(1.5f, -0.25f, 0.2f, 2.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glClearColor(0.0f, 0.9f, 0.45f, 0.1f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

static void draw_clear_range(fc_h *h)
{
    (void)h;
    glClearColor(2.0f, -0.5f, 0.333f, 1.25f);
    glClear(GL_COLOR_BUFFER_BIT);
}

static void draw_smooth(fc_h *h)
{
    (void)h;
    glClearColor(0.05f, 0.1f, 0.15f, 0.2f);
    glClear(GL_COLOR_BUFFER_BIT);
    smooth_tris();
    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    glColor4f(0.7f, 0.35f, 0.2f, 0.45f);
    glVertex2f(1, 1); glVertex2f(6, 1); glVertex2f(6, 5); glVertex2f(1, 5);
    glEnd();
    glShadeModel(GL_SMOOTH);
}

static void draw_blend(fc_h *h)
{
    (void)h;
    glClearColor(0.3f, 0.6f, 0.9f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);
    smooth_tris();
    glEnable(GL_BLEND);
    static const GLenum f[][2] = {
        { GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA }, { GL_ONE, GL_ONE },
        { GL_DST_COLOR, GL_ZERO }, { GL_ONE_MINUS_DST_ALPHA, GL_SRC_COLOR },
        { GL_SRC_ALPHA_SATURATE, GL_ONE }, { GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA },
    };
    glBlendColor(0.25f, 0.5f, 0.75f, 0.6f);
    for (int i = 0; i < 6; i++) {
        glBlendFunc(f[i][0], f[i][1]);
        glColor4f(0.8f - 0.1f * (float)i, 0.3f + 0.1f * (float)i, 0.55f, 0.35f + 0.1f * (float)i);
        const float x = (float)(i % 3) * 8.0f, y = (float)(i / 3) * 8.0f;
        glBegin(GL_TRIANGLES);
        glVertex2f(x, y); glVertex2f(x + 9, y + 1); glVertex2f(x + 2, y + 8);
        glEnd();
    }
    glBlendFunc(GL_ONE, GL_ONE);
    glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
    glColor4f(0.2f, 0.1f, 0.3f, 0.05f);
    glRectf(4, 4, 20, 12);
    glBlendEquation(GL_MIN);
    glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
    glRectf(0, 10, 12, 16);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
}

static void draw_lines_points(fc_h *h)
{
    (void)h;
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINES);
    glColor4f(1, 0.5f, 0.25f, 1); glVertex2f(0.5f, 0.5f);
    glColor4f(0, 0.25f, 1, 0.5f); glVertex2f(22.5f, 14.5f);
    glEnd();
    glPointSize(3);
    glBegin(GL_POINTS);
    glColor4f(0.33f, 0.66f, 0.99f, 0.5f); glVertex2f(5, 10);
    glColor4f(0.9f, 0.1f, 0.5f, 0.7f); glVertex2f(18, 4);
    glEnd();
}

static void draw_depth_alpha(fc_h *h)
{
    (void)h;
    glClearColor(0.2f, 0.2f, 0.2f, 0.2f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glColor4f(0.9f, 0.1f, 0.1f, 0.8f);
    glBegin(GL_TRIANGLES);
    glVertex3f(0, 0, 0.5f); glVertex3f(24, 0, -0.5f); glVertex3f(0, 16, 0);
    glEnd();
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.4f);
    smooth_tris();
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_DEPTH_TEST);
}

static void draw_readpixels(fc_h *h)
{
    draw_smooth(h);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glColor4f(0.6f, 0.7f, 0.8f, 0.9f);
    glRectf(8, 2, 16, 14);   /* sums above 1 in a float buffer */
    glDisable(GL_BLEND);
    static const GLenum types[] = { GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT };
    static unsigned char px[WW * WH * 16];
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int f = 0; f < 2; f++)
        for (int t = 0; t < 3; t++) {
            const GLenum fmt = f ? GL_RGB : GL_RGBA;
            memset(px, 0xA5, sizeof px);
            glReadPixels(1, 2, 20, 13, fmt, types[t], px);
            char l[48];
            snprintf(l, sizeof l, "read %s 0x%04x", f ? "RGB" : "RGBA", (unsigned)types[t]);
            fc_blob(h, l, px, (size_t)20 * 13 * (size_t)(f ? 3 : 4) *
                                  (types[t] == GL_FLOAT ? 4 : types[t] == GL_UNSIGNED_SHORT ? 2 : 1));
        }
    fc_get_integer(h, "GL_RED_BITS", GL_RED_BITS, 1);
    fc_get_integer(h, "GL_ALPHA_BITS", GL_ALPHA_BITS, 1);
}

/* glReadPixels of every colour format in every type (packed ones
 * included; the pairs GL refuses record their error) from the wide
 * buffer; _transfer: under scale, bias and byte swapping. */
static void read_formats(fc_h *h, int transfer)
{
    draw_smooth(h);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glColor4f(0.6f, 0.7f, 0.8f, 0.9f);
    glRectf(8, 2, 16, 14);   /* sums above 1 in a float buffer */
    glDisable(GL_BLEND);
    static const GLenum formats[] = { GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_LUMINANCE,
                                      GL_LUMINANCE_ALPHA, GL_RGB, GL_BGR, GL_RGBA, GL_BGRA,
                                      GL_ABGR_EXT };
    static const int ncomp[] = { 1, 1, 1, 1, 1, 2, 3, 3, 4, 4, 4 };
    static const struct { GLenum t; int size; int packed; } types[] = {
        { GL_UNSIGNED_BYTE, 1, 0 }, { GL_BYTE, 1, 0 }, { GL_UNSIGNED_SHORT, 2, 0 },
        { GL_SHORT, 2, 0 }, { GL_UNSIGNED_INT, 4, 0 }, { GL_INT, 4, 0 }, { GL_FLOAT, 4, 0 },
        { GL_UNSIGNED_BYTE_3_3_2, 1, 1 }, { GL_UNSIGNED_BYTE_2_3_3_REV, 1, 1 },
        { GL_UNSIGNED_SHORT_5_6_5, 2, 1 }, { GL_UNSIGNED_SHORT_5_6_5_REV, 2, 1 },
        { GL_UNSIGNED_SHORT_4_4_4_4, 2, 1 }, { GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 1 },
        { GL_UNSIGNED_SHORT_5_5_5_1, 2, 1 }, { GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 1 },
        { GL_UNSIGNED_INT_8_8_8_8, 4, 1 }, { GL_UNSIGNED_INT_8_8_8_8_REV, 4, 1 },
        { GL_UNSIGNED_INT_10_10_10_2, 4, 1 }, { GL_UNSIGNED_INT_2_10_10_10_REV, 4, 1 },
    };
    static unsigned char px[WW * WH * 16];
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (transfer) {
        glPixelTransferf(GL_RED_SCALE, 0.5f);
        glPixelTransferf(GL_GREEN_BIAS, 0.25f);
        glPixelTransferf(GL_BLUE_SCALE, 1.5f);
        glPixelTransferf(GL_ALPHA_BIAS, -0.125f);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    }
    glGetError();
    for (size_t f = 0; f < sizeof formats / sizeof formats[0]; f++)
        for (size_t t = 0; t < sizeof types / sizeof types[0]; t++) {
            memset(px, 0xA5, sizeof px);
            glReadPixels(1, 2, 20, 13, formats[f], types[t].t, px);
            char l[64];
            snprintf(l, sizeof l, "read 0x%04x 0x%04x", (unsigned)formats[f], (unsigned)types[t].t);
            const GLenum err = glGetError();
            fc_value(h, l, (long long)err);
            if (err == GL_NO_ERROR)
                fc_blob(h, l, px, (size_t)20 * 13 * (size_t)types[t].size *
                                      (size_t)(types[t].packed ? 1 : ncomp[f]));
        }
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
}

static void draw_readpixels_formats(fc_h *h) { read_formats(h, 0); }
static void draw_readpixels_transfer(fc_h *h) { read_formats(h, 1); }

#define WIDE_CASE(fn, fmt, type, draw, depth)                                 \
    static void fn(fc_h *h) { wide_run(h, #fn, fmt, type, draw, depth, 0); }
#define WIDE_ACCUM_CASE(fn, fmt, type, draw)                                  \
    static void fn(fc_h *h) { wide_run(h, #fn, fmt, type, draw, 0, 16); }

/* glAccum reads and returns the wide colour values: loads and
 * accumulations of a smooth picture (values between the 8-bit steps),
 * a scissored GL_MULT, a GL_RETURN above 1 and a masked one */
static void draw_accum(fc_h *h)
{
    draw_smooth(h);
    glAccum(GL_LOAD, 0.5f);
    glClearColor(0.9f, 0.2f, 0.6f, 0.35f);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor4f(0.1f, 0.9f, 0.3f, 0.8f); glVertex2f(0, 0);
    glColor4f(0.7f, 0.2f, 0.95f, 0.1f); glVertex2f(24, 3);
    glColor4f(0.33f, 0.44f, 0.55f, 0.66f); glVertex2f(10, 16);
    glEnd();
    glAccum(GL_ACCUM, 0.5f);
    glEnable(GL_SCISSOR_TEST);
    glScissor(3, 2, 15, 11);
    glAccum(GL_MULT, 1.37f);
    glDisable(GL_SCISSOR_TEST);
    glAccum(GL_RETURN, 1.0f);
    fc_value(h, "accum error", (long long)glGetError());
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glEnable(GL_SCISSOR_TEST);
    glScissor(12, 0, 12, 16);
    glAccum(GL_RETURN, 0.3f);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

/* glCopyPixels of a wide buffer: a plain copy, a zoomed one and one with
 * pixel transfer scale and bias */
static void draw_copypixels(fc_h *h)
{
    draw_smooth(h);
    glRasterPos2i(13, 1);
    glCopyPixels(1, 2, 9, 6, GL_COLOR);
    glRasterPos2i(0, 9);
    glPixelZoom(1.5f, 1.25f);
    glCopyPixels(14, 8, 6, 5, GL_COLOR);
    glPixelZoom(1.0f, 1.0f);
    glPixelTransferf(GL_RED_SCALE, 0.75f);
    glPixelTransferf(GL_BLUE_BIAS, 0.1f);
    glRasterPos2i(16, 10);
    glCopyPixels(2, 3, 7, 5, GL_COLOR);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_BLUE_BIAS, 0.0f);
    fc_value(h, "copy error", (long long)glGetError());
}

/* Copies of a wide buffer into textures (8-bit and 16-bit internal
 * formats), read back and drawn */
static void draw_copytex(fc_h *h)
{
    draw_smooth(h);
    static const GLenum ifmt[] = { GL_RGBA16, GL_RGBA8, GL_RGB8, GL_RGB10_A2, GL_RGB5_A1,
                                   GL_LUMINANCE16, GL_LUMINANCE16_ALPHA16, GL_ALPHA16,
                                   GL_INTENSITY16, GL_RGB16, GL_RGBA4, GL_R3_G3_B2,
                                   GL_LUMINANCE8, GL_RGB12 };
    enum { NF = sizeof ifmt / sizeof ifmt[0] };
    static unsigned short img[8 * 8 * 4];
    GLuint tex[NF];
    glGenTextures(NF, tex);
    for (int i = 0; i < NF; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, ifmt[i], 2 + i % 8, 3 + i % 5, 8, 8, 0);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        memset(img, 0, sizeof img);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, img);
        char l[32];
        snprintf(l, sizeof l, "teximage %d", i);
        fc_blob(h, l, img, sizeof img);
    }
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 12, 6, 5, 4);
    memset(img, 0, sizeof img);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, img);
    fc_blob(h, "subimage", img, sizeof img);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(14, 8);
    glTexCoord2f(1, 0); glVertex2f(22, 8);
    glTexCoord2f(1, 1); glVertex2f(22, 16);
    glTexCoord2f(0, 1); glVertex2f(14, 16);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(NF, tex);
    fc_value(h, "copytex error", (long long)glGetError());
}

WIDE_CASE(float_clears, OSMESA_RGBA, GL_FLOAT, draw_clears, 0)
WIDE_CASE(float_clear_range, OSMESA_RGBA, GL_FLOAT, draw_clear_range, 0)
WIDE_CASE(float_smooth, OSMESA_RGBA, GL_FLOAT, draw_smooth, 0)
WIDE_CASE(float_blend, OSMESA_RGBA, GL_FLOAT, draw_blend, 0)
WIDE_CASE(float_lines_points, OSMESA_RGBA, GL_FLOAT, draw_lines_points, 0)
WIDE_CASE(float_depth_alpha, OSMESA_RGBA, GL_FLOAT, draw_depth_alpha, 24)
WIDE_CASE(float_readpixels, OSMESA_RGBA, GL_FLOAT, draw_readpixels, 0)
WIDE_CASE(float_bgra, OSMESA_BGRA, GL_FLOAT, draw_smooth, 0)
WIDE_CASE(float_rgb, OSMESA_RGB, GL_FLOAT, draw_blend, 0)
WIDE_CASE(ushort_clears, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_clears, 0)
WIDE_CASE(ushort_clear_range, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_clear_range, 0)
WIDE_CASE(ushort_smooth, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_smooth, 0)
WIDE_CASE(ushort_blend, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_blend, 0)
WIDE_CASE(ushort_lines_points, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_lines_points, 0)
WIDE_CASE(ushort_depth_alpha, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_depth_alpha, 16)
WIDE_CASE(ushort_readpixels, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_readpixels, 0)
WIDE_CASE(ushort_argb, OSMESA_ARGB, GL_UNSIGNED_SHORT, draw_blend, 0)
WIDE_CASE(ushort_rgb_clear, OSMESA_RGB, GL_UNSIGNED_SHORT, draw_smooth, 0)
WIDE_CASE(ushort_readpixels_formats, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_readpixels_formats, 0)
WIDE_CASE(float_readpixels_formats, OSMESA_RGBA, GL_FLOAT, draw_readpixels_formats, 0)
WIDE_CASE(ushort_readpixels_transfer, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_readpixels_transfer, 0)
WIDE_CASE(float_readpixels_transfer, OSMESA_RGBA, GL_FLOAT, draw_readpixels_transfer, 0)
WIDE_CASE(float_rgb_readpixels_formats, OSMESA_RGB, GL_FLOAT, draw_readpixels_formats, 0)
WIDE_CASE(float_bgra_readpixels_formats, OSMESA_BGRA, GL_FLOAT, draw_readpixels_formats, 0)
WIDE_ACCUM_CASE(ushort_accum, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_accum)
WIDE_ACCUM_CASE(float_accum, OSMESA_RGBA, GL_FLOAT, draw_accum)
WIDE_ACCUM_CASE(float_bgra_accum, OSMESA_BGRA, GL_FLOAT, draw_accum)
WIDE_CASE(ushort_copypixels, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_copypixels, 0)
WIDE_CASE(float_copypixels, OSMESA_RGBA, GL_FLOAT, draw_copypixels, 0)
WIDE_CASE(ushort_copytex, OSMESA_RGBA, GL_UNSIGNED_SHORT, draw_copytex, 0)
WIDE_CASE(float_copytex, OSMESA_RGBA, GL_FLOAT, draw_copytex, 0)

/* Which format/type pairs OSMesaMakeCurrent takes (GL_FALSE for the
 * others), and a context rebound from ubyte to float to ushort and back
 * to ubyte keeps drawing. */
static void wide_types(fc_h *h)
{
    static const GLenum fmts[] = { OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB,
                                   OSMESA_RGB_565, OSMESA_COLOR_INDEX };
    static const GLenum types[] = { GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT,
                                    GL_UNSIGNED_SHORT_5_6_5, GL_BYTE, GL_HALF_FLOAT,
                                    GL_UNSIGNED_INT };
    for (size_t f = 0; f < sizeof fmts / sizeof fmts[0]; f++) {
        OSMesaContext ctx = OSMesaCreateContextExt(fmts[f], 0, 0, 0, NULL);
        if (!ctx)
            continue;
        for (size_t t = 0; t < sizeof types / sizeof types[0]; t++) {
            if (fmts[f] == OSMESA_RGB_565 && types[t] == GL_UNSIGNED_SHORT_5_6_5)
                continue;   /* fixgl has no 5-6-5 buffers (known) */
            char l[64];
            snprintf(l, sizeof l, "format 0x%x type 0x%04x", (unsigned)fmts[f], (unsigned)types[t]);
            fc_value(h, l, OSMesaMakeCurrent(ctx, wbuf, types[t], 8, 8));
        }
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        OSMesaDestroyContext(ctx);
    }
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    static const GLenum seq[] = { GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_SHORT, GL_UNSIGNED_BYTE };
    for (int i = 0; i < 4; i++) {
        memset(wbuf, 0, sizeof wbuf);
        OSMesaMakeCurrent(ctx, wbuf, seq[i], 8, 8);
        glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        glColor3f(1, 0, 0); glVertex2f(-1, -1);
        glColor3f(0, 1, 0); glVertex2f(1, -1);
        glColor3f(0, 0, 1); glVertex2f(-1, 1);
        glEnd();
        glFinish();
        char l[32];
        snprintf(l, sizeof l, "rebind %d", i);
        fc_blob(h, l, wbuf, (size_t)8 * 8 * 4 * (seq[i] == GL_FLOAT ? 4 : seq[i] == GL_UNSIGNED_SHORT ? 2 : 1));
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    const fc_case *c = fc_this_case(h);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, c->width, c->height);
}

const fc_case fc_cases_osmesa[] = {
    FC_CASE_RGBA("osmesa/wide_types", 8, 8, 0, "osmesa api", wide_types),
    FC_CASE_RGBA("osmesa/float_clears", 8, 8, 0, "osmesa", float_clears),
    FC_CASE_RGBA("osmesa/float_clear_range", 8, 8, 0, "osmesa", float_clear_range),
    FC_CASE_RGBA("osmesa/float_smooth", 8, 8, 0, "osmesa", float_smooth),
    FC_CASE_RGBA("osmesa/float_blend", 8, 8, 0, "osmesa", float_blend),
    FC_CASE_RGBA("osmesa/float_lines_points", 8, 8, 0, "osmesa", float_lines_points),
    FC_CASE_RGBA("osmesa/float_depth_alpha", 8, 8, 0, "osmesa", float_depth_alpha),
    FC_CASE_RGBA("osmesa/float_readpixels", 8, 8, 0, "osmesa pixel", float_readpixels),
    FC_CASE_RGBA("osmesa/float_bgra", 8, 8, 0, "osmesa", float_bgra),
    FC_CASE_RGBA("osmesa/float_rgb", 8, 8, 0, "osmesa", float_rgb),
    FC_CASE_RGBA("osmesa/ushort_clears", 8, 8, 0, "osmesa", ushort_clears),
    FC_CASE_RGBA("osmesa/ushort_clear_range", 8, 8, 0, "osmesa", ushort_clear_range),
    FC_CASE_RGBA("osmesa/ushort_smooth", 8, 8, 0, "osmesa", ushort_smooth),
    FC_CASE_RGBA("osmesa/ushort_blend", 8, 8, 0, "osmesa", ushort_blend),
    FC_CASE_RGBA("osmesa/ushort_lines_points", 8, 8, 0, "osmesa", ushort_lines_points),
    FC_CASE_RGBA("osmesa/ushort_depth_alpha", 8, 8, 0, "osmesa", ushort_depth_alpha),
    FC_CASE_RGBA("osmesa/ushort_readpixels", 8, 8, 0, "osmesa pixel", ushort_readpixels),
    FC_CASE_RGBA("osmesa/ushort_argb", 8, 8, 0, "osmesa", ushort_argb),
    FC_CASE_RGBA("osmesa/ushort_rgb_clear", 8, 8, 0, "osmesa", ushort_rgb_clear),
    FC_CASE_RGBA("osmesa/ushort_accum", 8, 8, 0, "osmesa accum", ushort_accum),
    FC_CASE_RGBA("osmesa/float_accum", 8, 8, 0, "osmesa accum", float_accum),
    FC_CASE_RGBA("osmesa/float_bgra_accum", 8, 8, 0, "osmesa accum", float_bgra_accum),
    FC_CASE_RGBA("osmesa/ushort_copypixels", 8, 8, 0, "osmesa pixel", ushort_copypixels),
    FC_CASE_RGBA("osmesa/float_copypixels", 8, 8, 0, "osmesa pixel", float_copypixels),
    FC_CASE_RGBA("osmesa/ushort_copytex", 8, 8, 0, "osmesa texture", ushort_copytex),
    FC_CASE_RGBA("osmesa/float_copytex", 8, 8, 0, "osmesa texture", float_copytex),
    FC_CASE_RGBA("osmesa/ushort_readpixels_formats", 8, 8, 0, "osmesa pixel", ushort_readpixels_formats),
    FC_CASE_RGBA("osmesa/float_readpixels_formats", 8, 8, 0, "osmesa pixel", float_readpixels_formats),
    FC_CASE_RGBA("osmesa/ushort_readpixels_transfer", 8, 8, 0, "osmesa pixel", ushort_readpixels_transfer),
    FC_CASE_RGBA("osmesa/float_readpixels_transfer", 8, 8, 0, "osmesa pixel", float_readpixels_transfer),
    FC_CASE_RGBA("osmesa/float_rgb_readpixels_formats", 8, 8, 0, "osmesa pixel", float_rgb_readpixels_formats),
    FC_CASE_RGBA("osmesa/float_bgra_readpixels_formats", 8, 8, 0, "osmesa pixel", float_bgra_readpixels_formats),
    FC_CASE_RGBA("osmesa/attribs_refused", 8, 8, 0, "osmesa api", attribs_refused),
    FC_CASE_RGBA("osmesa/attribs_compat", 8, 8, 0, "osmesa api", attribs_compat),
    FC_CASE_RGBA("osmesa/attribs_unprovided", 8, 8, 0, "osmesa api", attribs_unprovided),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
