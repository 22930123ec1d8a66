/* c_fragment.c - the per-fragment operations: scissor (drawing and
 * scissored/masked clears), alpha test, stencil, depth buffers of 16/24/32
 * bits, blending (every GL 1.x factor pair, equations, blend colour), logic
 * ops, colour/depth/stencil masks, and the errors and queries of their
 * entry points.  Tag `fragment`. */
#include "cases.h"

#include <math.h>

#ifndef GL_SRC1_COLOR
#define GL_SRC1_COLOR 0x88F9
#define GL_ONE_MINUS_SRC1_COLOR 0x88FA
#define GL_ONE_MINUS_SRC1_ALPHA 0x88FB
#endif
#ifndef GL_SRC1_ALPHA
#define GL_SRC1_ALPHA 0x8589
#endif
#ifndef GL_INCR_WRAP
#define GL_INCR_WRAP 0x8507
#define GL_DECR_WRAP 0x8508
#endif

static const GLenum funcs[8] = {
    GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS
};

/* Every GL 1.x blend factor (GL_SRC_ALPHA_SATURATE is also a legal
 * destination factor in the oracle: ARB_blend_func_extended). */
static const GLenum factors[15] = {
    GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR,
    GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA,
    GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR,
    GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA,
};

static const GLenum stencil_ops[8] = {
    GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP
};

/* A smooth-shaded quad with a colour (and alpha) per corner. */
static void grad_rect(float x0, float y0, float x1, float y1, float z,
                      const GLubyte c[4][4])
{
    glBegin(GL_QUADS);
    glColor4ubv(c[0]); glVertex3f(x0, y0, z);
    glColor4ubv(c[1]); glVertex3f(x1, y0, z);
    glColor4ubv(c[2]); glVertex3f(x1, y1, z);
    glColor4ubv(c[3]); glVertex3f(x0, y1, z);
    glEnd();
}

static const GLubyte bg_colors[4][4] = {
    { 255, 0, 40, 0 }, { 20, 255, 0, 255 }, { 0, 30, 255, 128 }, { 200, 200, 200, 77 },
};
static const GLubyte fg_colors[4][4] = {
    { 0, 128, 255, 255 }, { 255, 255, 0, 0 }, { 90, 0, 200, 200 }, { 255, 100, 50, 33 },
};

/* The background of the blending cases: a gradient in every channel
 * including alpha, drawn without blending. */
static void gradient_background(fc_h *h, float w, float hgt)
{
    (void)h;
    glDisable(GL_BLEND);
    grad_rect(0, 0, w, hgt, 0, bg_colors);
}

/* ---- scissor ---- */

/* Scissor boxes on pixel boundaries, partly and wholly outside the
 * framebuffer, empty, and the test switched off again. */
static void scissor_draw(fc_h *h)
{
    static const int boxes[][4] = {
        { 4, 6, 10, 12 }, { -5, -3, 12, 9 }, { 20, 25, 40, 40 }, { 31, 0, 1, 32 },
        { 0, 31, 32, 1 }, { 40, 40, 5, 5 }, { 8, 8, 0, 10 }, { -100, 5, 1000, 3 },
    };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_SCISSOR_TEST);
    fc_is_enabled(h, "GL_SCISSOR_TEST", GL_SCISSOR_TEST);
    for (int i = 0; i < 8; i++) {
        glScissor(boxes[i][0], boxes[i][1], boxes[i][2], boxes[i][3]);
        fcu_color(i);
        fcu_rect(0, 0, 32, 32, 0);
        fc_get_integer(h, "GL_SCISSOR_BOX", GL_SCISSOR_BOX, 4);
    }
    fc_capture(h);
    glDisable(GL_SCISSOR_TEST);
    fcu_color(9);
    fcu_rect(0, 0, 3, 3, 0);
    fc_capture(h);
}

/* Boxes with origins past 16 bits and sizes that overflow int: the oracle
 * keeps the box in 16-bit fields for drawing (65536 + x starts at x) but
 * in ints for clears; x + width wraps. */
static void scissor_huge(fc_h *h)
{
    static const int boxes[][4] = {
        { 65536 + 10, 4, 8, 8 }, { 4, 65536 + 20, 8, 8 }, { 131072 + 3, 131072 + 5, 100, 100 },
        { 65530, 0, 20, 12 }, { 2147483640, 0, 100, 32 }, { 5, 5, 2147483647, 3 },
        { -2147483647, 12, 2147483647, 3 }, { 20, 20, 65536 + 4, 65536 + 4 },
    };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_SCISSOR_TEST);
    for (int i = 0; i < 8; i++) {
        glScissor(boxes[i][0], boxes[i][1], boxes[i][2], boxes[i][3]);
        fcu_color(i);
        fcu_rect(0, 0, 32, 32, 0);
        fc_get_integer(h, "GL_SCISSOR_BOX", GL_SCISSOR_BOX, 4);
    }
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    for (int i = 0; i < 8; i++) {
        glScissor(boxes[i][0], boxes[i][1], boxes[i][2], boxes[i][3]);
        glClearColor(0.1f * (float)i, 1.0f - 0.1f * (float)i, 0.5f, 1);
        glClearDepth(0.1 * i);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    fc_capture(h);
}

/* Scissor with sloped triangles whose edges cross the box. */
static void scissor_triangles(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 1, 1);
    glEnable(GL_SCISSOR_TEST);
    glScissor(7, 5, 19, 17);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-3.5f, 2.25f);
    glColor3f(0, 1, 0); glVertex2f(30.3f, 10.7f);
    glColor3f(0, 0, 1); glVertex2f(12.1f, 35.9f);
    glEnd();
    fc_capture(h);
}

/* A larger buffer: scissor boxes crossing llvmpipe's 64x64 tiles, with
 * big triangles and a fan, and a scissored clear in between. */
static void scissor_tiles(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glEnable(GL_SCISSOR_TEST);
    glShadeModel(GL_SMOOTH);
    static const int boxes[3][4] = { { 60, 50, 9, 30 }, { 1, 63, 158, 3 }, { 100, 0, 60, 120 } };
    for (int i = 0; i < 3; i++) {
        glScissor(boxes[i][0], boxes[i][1], boxes[i][2], boxes[i][3]);
        glBegin(GL_TRIANGLE_FAN);
        glColor3f(1, 1, 1); glVertex2f(80.3f, 50.2f);
        for (int k = 0; k <= 12; k++) {
            const float a = 0.5235988f * (float)k;
            glColor3f(k & 1 ? 1.0f : 0.2f, (float)(k % 3) * 0.5f, 0.7f);
            glVertex2f(80.3f + 90.0f * cosf(a), 50.2f + 70.0f * sinf(a));
        }
        glEnd();
    }
    glScissor(30, 20, 70, 50);
    glClearColor(0.25f, 0.5f, 0.75f, 1);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    fc_capture(h);
}

/* Scissored colour clears: boxes inside, on the edges, outside, empty. */
static void scissor_clear_color(fc_h *h)
{
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_SCISSOR_TEST);
    glScissor(3, 4, 10, 7);
    glClearColor(1, 0.5f, 0.25f, 0.75f);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(-4, 20, 9, 40);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(28, -2, 10, 10);
    glClearColor(0.2f, 0.3f, 1.5f, -1);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(16, 16, 0, 5);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(50, 50, 5, 5);
    glClear(GL_COLOR_BUFFER_BIT);
    fc_capture(h);
    /* a box covering the whole buffer is a plain clear */
    glScissor(-1, -1, 40, 40);
    glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    fc_capture(h);
}

/* Scissored depth clears go through the quad's float depth path; each
 * clear value is then probed with GL_EQUAL and GL_LEQUAL rectangles at the
 * same depth, so any difference in the stored value shows. */
static void scissor_clear_depth(fc_h *h)
{
    static const double values[8] = { 0.3, 0.7, 0.1, 0.123456789, 0.5, 0.999, 1.0 / 3.0, 0.0 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_SCISSOR_TEST);
    for (int i = 0; i < 8; i++) {
        glScissor(8 * i, 0, 8, 32);
        glClearDepth(values[i]);
        glClear(GL_DEPTH_BUFFER_BIT);
    }
    fc_capture(h);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    for (int i = 0; i < 8; i++) {
        /* glOrtho(.., -1, 1): window z = 0.5 - z/2 */
        const float z = (float)(1.0 - 2.0 * values[i]);
        glDepthFunc(GL_EQUAL);
        fcu_color(i);
        fcu_rect(8.0f * i, 0, 8.0f * i + 8, 16, z);
        glDepthFunc(GL_LESS);
        fcu_color(i + 8);
        fcu_rect(8.0f * i, 16, 8.0f * i + 8, 32, z);
    }
    fc_capture(h);
}

/* Colour mask per channel and combinations, for plain clears (drawn as
 * quads when partly masked) and with a scissor. */
static void clear_color_mask(fc_h *h)
{
    fcu_clear(0.2f, 0.4f, 0.6f, 0.8f, 1);
    for (int m = 0; m < 16; m++) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(8 * (m % 4), 8 * (m / 4), 8, 8);
        glColorMask(m & 1, (m >> 1) & 1, (m >> 2) & 1, (m >> 3) & 1);
        glClearColor(1, 1, 1, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    fc_get_integer(h, "GL_COLOR_WRITEMASK", GL_COLOR_WRITEMASK, 4);
    fc_get_boolean(h, "GL_COLOR_WRITEMASK bool", GL_COLOR_WRITEMASK, 4);
    fc_capture(h);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    fc_capture(h);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    fc_capture(h);
}

/* Stencil clears: whole, scissored, under a partial write mask (quads), and
 * depth with stencil (cleared together when one of them is a quad). */
static void clear_stencil(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0x5a);
    fcu_clear(0, 0, 0, 0, 0.75);
    glClear(GL_STENCIL_BUFFER_BIT);
    fc_capture(h);
    glEnable(GL_SCISSOR_TEST);
    glScissor(2, 3, 12, 9);
    glClearStencil(0x1ff);
    glClear(GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glStencilMask(0x0f);
    glClearStencil(0xa3);
    glClearDepth(0.3);
    glClear(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fc_capture(h);
    glStencilMask(0xf0);
    glScissor(16, 16, 10, 10);
    glEnable(GL_SCISSOR_TEST);
    glClearStencil(-1);
    glClear(GL_STENCIL_BUFFER_BIT);
    glStencilMask(0);
    glDisable(GL_SCISSOR_TEST);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    fc_capture(h);
    fc_get_integer(h, "GL_STENCIL_CLEAR_VALUE", GL_STENCIL_CLEAR_VALUE, 1);
    /* show the stencil values as colours */
    glStencilMask(~0u);
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (int i = 0; i < 8; i++) {
        glStencilFunc(GL_EQUAL, 1 << i, 1u << i);
        fcu_color(i);
        fcu_rect(0, 4.0f * i, 32, 4.0f * i + 4, 0);
    }
    fc_capture(h);
}

/* Scissored depth clears with a depth mask off (nothing happens) and
 * depth+colour clears where only colour is masked. */
static void clear_mixed_masks(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 1, 1, 1);
    glEnable(GL_SCISSOR_TEST);
    glScissor(4, 4, 20, 20);
    glDepthMask(GL_FALSE);
    glClearDepth(0.25);
    glClearColor(1, 0, 0, 1);
    glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    fc_capture(h);
    glDepthMask(GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glClearColor(0.3f, 0.6f, 0.9f, 0.1f);
    glClearDepth(0.6);
    glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    fc_capture(h);
}

/* Scissored depth clears of a 16-bit buffer, probed with GL_EQUAL. */
static void scissor_clear_depth16(fc_h *h)
{
    scissor_clear_depth(h);
}

/* ---- alpha test ---- */

/* Each function against references at and between u8 steps: columns of
 * alpha values 0..255 around the reference. */
static void alpha_funcs(fc_h *h)
{
    static const float refs[4] = { 0.0f, 1.0f, 0.5f, 100.5f / 255.0f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_ALPHA_TEST);
    for (int r = 0; r < 4; r++) {
        for (int f = 0; f < 8; f++) {
            glAlphaFunc(funcs[f], refs[r]);
            const int base = r == 0 ? 0 : r == 1 ? 252 : r == 2 ? 125 : 98;
            for (int k = 0; k < 4; k++) {
                int a = base + k;
                if (a > 255)
                    a = 255;
                glColor4ub((GLubyte)(40 * f), (GLubyte)(60 * k + 40), (GLubyte)(60 * r), (GLubyte)a);
                const float x = 8.0f * (float)f + 2.0f * (float)k, y = 8.0f * (float)r;
                fcu_rect(x, y, x + 2, y + 8, 0);
            }
        }
    }
    fc_get_integer(h, "GL_ALPHA_TEST_FUNC", GL_ALPHA_TEST_FUNC, 1);
    fc_get_float(h, "GL_ALPHA_TEST_REF", GL_ALPHA_TEST_REF, 1);
    fc_capture(h);
}

/* References at u8 rounding ties (k + 0.5)/255 and just around them, with
 * smoothly interpolated alpha so every alpha value occurs. */
static void alpha_ref_ties(fc_h *h)
{
    static const GLubyte ramp[4][4] = {
        { 255, 255, 255, 0 }, { 255, 255, 255, 255 }, { 255, 255, 255, 255 }, { 255, 255, 255, 0 },
    };
    fc_pixel_ortho(h);
    glEnable(GL_ALPHA_TEST);
    for (int i = 0; i < 6; i++) {
        const float refs[6] = { 0.5f / 255.0f, 1.5f / 255.0f, 127.5f / 255.0f,
                                128.5f / 255.0f, 254.5f / 255.0f, 0.50196078f };
        fcu_clear(0, 0, 0, 0, 1);
        glAlphaFunc(i & 1 ? GL_GEQUAL : GL_LESS, refs[i]);
        grad_rect(0, 0, 64, 16, 0, ramp);
        glAlphaFunc(GL_EQUAL, refs[i]);
        grad_rect(0, 16, 64, 32, 0, ramp);
        fc_capture(h);
    }
}

/* Out-of-range references (clamped), NaN-free; queries clamp too. */
static void alpha_ref_clamp(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_LEQUAL, 2.5f);
    fc_get_float(h, "ref 2.5", GL_ALPHA_TEST_REF, 1);
    fc_get_integer(h, "ref 2.5 int", GL_ALPHA_TEST_REF, 1);
    glColor4f(1, 0, 0, 1);
    fcu_rect(0, 0, 16, 16, 0);
    glAlphaFunc(GL_GEQUAL, -3.0f);
    fc_get_double(h, "ref -3", GL_ALPHA_TEST_REF, 1);
    glColor4f(0, 1, 0, 0);
    fcu_rect(16, 0, 32, 16, 0);
    glAlphaFunc(GL_GREATER, 0.3f);
    fc_get_integer(h, "ref 0.3 int", GL_ALPHA_TEST_REF, 1);
    fc_get_boolean(h, "ref 0.3 bool", GL_ALPHA_TEST_REF, 1);
    glColor4f(0, 0, 1, 1.7f);       /* clamped alpha passes */
    fcu_rect(0, 16, 16, 32, 0);
    glColor4f(1, 1, 0, -0.2f);      /* clamped alpha fails */
    fcu_rect(16, 16, 32, 32, 0);
    fc_capture(h);
}

/* A NaN reference is clamped to 1 by the oracle's lp_build_clamp; the
 * query keeps Mesa's CLAMP of NaN. */
static void alpha_ref_nan(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_LESS, nanf(""));
    fc_get_float(h, "ref NaN", GL_ALPHA_TEST_REF, 1);
    fc_get_boolean(h, "ref NaN bool", GL_ALPHA_TEST_REF, 1);
    glBlendColor(nanf(""), 0.5f, -nanf(""), 1);
    fc_get_float(h, "blend colour NaN", GL_BLEND_COLOR, 4);
    glClearColor(nanf(""), 0.25f, 1, -nanf(""));
    fc_get_float(h, "clear colour NaN", GL_COLOR_CLEAR_VALUE, 4);
    glColor4f(1, 0, 0, 1);
    fcu_rect(0, 0, 16, 32, 0);
    glColor4f(0, 1, 0, 254.0f / 255.0f);
    fcu_rect(16, 0, 32, 32, 0);
    fc_capture(h);
}

/* Fragments killed by the alpha test write neither depth nor stencil. */
static void alpha_kills_depth_stencil(fc_h *h)
{
    static const GLubyte ramp[4][4] = {
        { 255, 0, 0, 0 }, { 255, 0, 0, 255 }, { 255, 0, 0, 255 }, { 255, 0, 0, 0 },
    };
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0, 0, 0, 0, 1);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 7, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    grad_rect(0, 0, 32, 32, 0.5f, ramp);
    glDisable(GL_ALPHA_TEST);
    glStencilFunc(GL_EQUAL, 7, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDepthFunc(GL_ALWAYS);
    fcu_color(1);
    fcu_rect(0, 0, 32, 16, 0);
    fc_capture(h);
}

/* ---- stencil ---- */

/* Each function with a reference/mask against a buffer of values 0..255. */
static void stencil_funcs(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0, 0, 0, 0, 1);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    /* rows of stencil values 0x00, 0x3f, 0x40, 0x41, 0x7f, 0x80, 0xc1, 0xff */
    static const int vals[8] = { 0x00, 0x3f, 0x40, 0x41, 0x7f, 0x80, 0xc1, 0xff };
    glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    for (int i = 0; i < 8; i++) {
        glStencilFunc(GL_ALWAYS, vals[i], 0xff);
        fcu_rect(0, 4.0f * i, 64, 4.0f * i + 4, 0);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (int f = 0; f < 8; f++) {
        glStencilFunc(funcs[f], 0x41, 0xff);
        fcu_color(f);
        fcu_rect(8.0f * f, 0, 8.0f * f + 4, 32, 0);
        glStencilFunc(funcs[f], 0x4f, 0x70);      /* masked: compares 0x40 */
        fcu_color(f + 8);
        fcu_rect(8.0f * f + 4, 0, 8.0f * f + 8, 32, 0);
    }
    fc_get_integer(h, "GL_STENCIL_FUNC", GL_STENCIL_FUNC, 1);
    fc_get_integer(h, "GL_STENCIL_REF", GL_STENCIL_REF, 1);
    fc_get_integer(h, "GL_STENCIL_VALUE_MASK", GL_STENCIL_VALUE_MASK, 1);
    fc_capture(h);
}

/* Every op as the fail, zfail and zpass op; the stencil values land in the
 * captured depth/stencil buffer and are shown as colour too. */
static void stencil_ops_all(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0x80);
    fcu_clear(0, 0, 0, 0, 0.5);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    for (int o = 0; o < 8; o++) {
        const float x = 8.0f * (float)o;
        /* stencil fails (NEVER): fail op */
        glStencilFunc(GL_NEVER, 0x33, 0xff);
        glStencilOp(stencil_ops[o], GL_KEEP, GL_KEEP);
        fcu_color(o);
        fcu_rect(x, 0, x + 8, 8, 0.5f);
        /* stencil passes, depth fails (z 0.75 > 0.5): zfail op */
        glStencilFunc(GL_ALWAYS, 0x33, 0xff);
        glStencilOp(GL_KEEP, stencil_ops[o], GL_KEEP);
        fcu_rect(x, 8, x + 8, 16, -0.5f);
        /* both pass: zpass op, twice */
        glStencilOp(GL_KEEP, GL_KEEP, stencil_ops[o]);
        fcu_rect(x, 16, x + 8, 24, 0.5f);
        fcu_rect(x, 16, x + 8, 24, 0.6f);
        /* depth test off: zpass op */
        glDisable(GL_DEPTH_TEST);
        fcu_rect(x, 24, x + 8, 32, -0.9f);
        glEnable(GL_DEPTH_TEST);
    }
    fc_get_integer(h, "GL_STENCIL_FAIL", GL_STENCIL_FAIL, 1);
    fc_get_integer(h, "GL_STENCIL_PASS_DEPTH_FAIL", GL_STENCIL_PASS_DEPTH_FAIL, 1);
    fc_get_integer(h, "GL_STENCIL_PASS_DEPTH_PASS", GL_STENCIL_PASS_DEPTH_PASS, 1);
    fc_capture(h);
}

/* INCR/DECR saturate, the WRAP variants wrap: many overlapping passes from
 * 0 and from 255. */
static void stencil_wrap_saturate(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    for (int col = 0; col < 4; col++) {
        const GLenum op = col == 0 ? GL_INCR : col == 1 ? GL_DECR : col == 2 ? GL_INCR_WRAP : GL_DECR_WRAP;
        const int start = (col & 1) ? 2 : 253;
        glClearStencil(start);
        glEnable(GL_SCISSOR_TEST);
        glScissor(8 * col, 0, 8, 32);
        glClear(GL_STENCIL_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        glStencilOp(GL_KEEP, GL_KEEP, op);
        for (int n = 0; n < 5; n++)
            fcu_rect(8.0f * col, 0, 8.0f * col + 8, 6.0f * (float)n + 8, 0);
    }
    fc_capture(h);
}

/* Outlining: draw the object marking the stencil, then a larger copy only
 * where the stencil is not marked; several objects with different refs. */
static void stencil_outline(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    for (int i = 0; i < 3; i++) {
        const float cx = 12.0f + 20.0f * (float)i, cy = 16.0f;
        glStencilFunc(GL_ALWAYS, i + 1, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        fcu_color(i);
        fcu_tri(cx - 7.3f, cy - 6.1f, cx + 6.7f, cy - 5.2f, cx + 0.4f, cy + 8.8f);
        glStencilFunc(GL_NOTEQUAL, i + 1, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        fcu_color(9);
        fcu_tri(cx - 9.8f, cy - 8.0f, cx + 9.1f, cy - 7.0f, cx + 0.4f, cy + 11.9f);
    }
    fc_capture(h);
}

/* Capping / shadow-volume style counting: front faces increment and back
 * faces decrement on depth fail over a depth-tested scene, then the
 * shadowed region (stencil != 0) is darkened. */
static void stencil_capping(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0, 0, 0, 0, 1);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    /* scene: a floor and a box */
    fcu_color(10); fcu_rect(0, 0, 64, 32, -0.5f);
    fcu_color(6);  fcu_rect(20, 8, 40, 24, 0.2f);
    /* volume: two overlapping sloped quads, counted in two passes */
    glEnable(GL_STENCIL_TEST);
    glDepthMask(GL_FALSE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glEnable(GL_CULL_FACE);
    for (int pass = 0; pass < 2; pass++) {
        glCullFace(pass == 0 ? GL_BACK : GL_FRONT);
        glStencilOp(GL_KEEP, pass == 0 ? GL_INCR : GL_DECR, GL_KEEP);
        for (int v = 0; v < 2; v++) {
            const float x = 10.0f + 18.0f * (float)v;
            glBegin(GL_QUADS);
            /* front (ccw) near, back (cw) far */
            glVertex3f(x, 4, 0.9f); glVertex3f(x + 20, 4, 0.9f);
            glVertex3f(x + 20, 28, 0.9f); glVertex3f(x, 28, 0.9f);
            glVertex3f(x + 2, 6, -0.9f); glVertex3f(x + 2, 26, -0.9f);
            glVertex3f(x + 18, 26, -0.1f); glVertex3f(x + 18, 6, -0.1f);
            glEnd();
        }
    }
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_EQUAL);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_NOTEQUAL, 0, 0xff);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_CONSTANT_COLOR);
    glBlendColor(0.4f, 0.4f, 0.5f, 1);
    fcu_color(9); fcu_rect(0, 0, 64, 32, -0.5f);
    fcu_color(9); fcu_rect(20, 8, 40, 24, 0.2f);
    fc_capture(h);
}

/* Value and write masks: the test on masked bits, ops under write masks. */
static void stencil_masks(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0xcc);
    fcu_clear(0, 0, 0, 0, 1);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    static const GLuint wmasks[8] = { 0xff, 0x00, 0x0f, 0xf0, 0x55, 0x81, 0x1ff, 0xffffff7e };
    for (int i = 0; i < 8; i++) {
        glStencilMask(wmasks[i]);
        glStencilFunc(GL_ALWAYS, 0x3a, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, i & 1 ? GL_INVERT : GL_REPLACE);
        fcu_rect(8.0f * i, 0, 8.0f * i + 8, 16, 0);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
        fcu_rect(8.0f * i, 16, 8.0f * i + 8, 32, 0);
    }
    fc_get_integer(h, "GL_STENCIL_WRITEMASK int", GL_STENCIL_WRITEMASK, 1);
    fc_get_float(h, "GL_STENCIL_WRITEMASK float", GL_STENCIL_WRITEMASK, 1);
    fc_get_double(h, "GL_STENCIL_WRITEMASK double", GL_STENCIL_WRITEMASK, 1);
    fc_get_boolean(h, "GL_STENCIL_WRITEMASK bool", GL_STENCIL_WRITEMASK, 1);
    fc_capture(h);
    glStencilMask(0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (int i = 0; i < 4; i++) {
        glStencilFunc(GL_EQUAL, 0x0c << i, 0x0f << i);
        fcu_color(i);
        fcu_rect(0, 8.0f * i, 64, 8.0f * i + 4, 0.5f);
        glStencilFunc(GL_LESS, 0x80 >> i, 0xf0 >> i);
        fcu_color(i + 4);
        fcu_rect(0, 8.0f * i + 4, 64, 8.0f * i + 8, 0.5f);
    }
    fc_capture(h);
}

/* The reference is clamped to [0, 255] for the test, REPLACE and queries. */
static void stencil_ref_clamp(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0, 0, 0, 0, 1);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glStencilFunc(GL_ALWAYS, 300, 0xff);
    fc_get_integer(h, "GL_STENCIL_REF 300", GL_STENCIL_REF, 1);
    fcu_rect(0, 0, 16, 32, 0);
    glStencilFunc(GL_ALWAYS, -5, 0xff);
    fc_get_integer(h, "GL_STENCIL_REF -5", GL_STENCIL_REF, 1);
    fc_get_float(h, "GL_STENCIL_REF -5 float", GL_STENCIL_REF, 1);
    fcu_rect(16, 0, 32, 32, 0);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_EQUAL, 1000, ~0u);
    fc_get_integer(h, "GL_STENCIL_VALUE_MASK ~0", GL_STENCIL_VALUE_MASK, 1);
    fc_get_float(h, "GL_STENCIL_VALUE_MASK ~0 float", GL_STENCIL_VALUE_MASK, 1);
    fcu_color(3);
    fcu_rect(0, 0, 32, 16, 0);
    glStencilFunc(GL_LEQUAL, -1, ~0u);
    fcu_color(4);
    fcu_rect(0, 16, 32, 32, 0);
    fc_capture(h);
}

/* Stencil-only buffer (depth 0, stencil 8), and stencil test without a
 * stencil buffer (always passes). */
static void stencil_basic(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(3);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glStencilFunc(GL_LEQUAL, 2, 0xff);
    glStencilOp(GL_DECR, GL_INVERT, GL_INCR);
    for (int i = 0; i < 4; i++) {
        fcu_color(i);
        fcu_rect(4.0f * i, 4.0f * i, 32 - 4.0f * i, 32 - 4.0f * i, 0.1f * i);
    }
    fc_capture(h);
    fc_get_integer(h, "GL_STENCIL_BITS", GL_STENCIL_BITS, 1);
    fc_get_integer(h, "GL_STENCIL_REF", GL_STENCIL_REF, 1);
}

/* ---- blending ---- */

/* The factor pairs legacy programs use, over a gradient background. */
static void blend_common_pairs(fc_h *h)
{
    static const GLenum pairs[8][2] = {
        { GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA }, { GL_ONE, GL_ONE },
        { GL_DST_COLOR, GL_ZERO }, { GL_ONE, GL_ONE_MINUS_SRC_ALPHA },
        { GL_SRC_ALPHA_SATURATE, GL_ONE }, { GL_ZERO, GL_SRC_COLOR },
        { GL_SRC_ALPHA, GL_ONE }, { GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA },
    };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    gradient_background(h, 64, 32);
    glEnable(GL_BLEND);
    for (int i = 0; i < 8; i++) {
        glBlendFunc(pairs[i][0], pairs[i][1]);
        const float x = 8.0f * (float)i;
        grad_rect(x, 0, x + 8, 32, 0, fg_colors);
    }
    fc_get_integer(h, "GL_BLEND_SRC", GL_BLEND_SRC, 1);
    fc_get_integer(h, "GL_BLEND_DST", GL_BLEND_DST, 1);
    fc_is_enabled(h, "GL_BLEND", GL_BLEND);
    fc_capture(h);
}

/* Every src x dst factor pair (15 x 15 cells of 4x4 pixels), each a
 * gradient over the gradient background. */
static void blend_sweep(fc_h *h, const GLubyte bg[4][4], const GLubyte fg[4][4])
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glDisable(GL_BLEND);
    grad_rect(0, 0, 60, 60, 0, bg);
    glEnable(GL_BLEND);
    glBlendColor(0.2f, 0.6f, 0.9f, 0.35f);
    for (int s = 0; s < 15; s++) {
        for (int d = 0; d < 15; d++) {
            glBlendFunc(factors[s], factors[d]);
            const float x = 4.0f * (float)d, y = 4.0f * (float)s;
            grad_rect(x, y, x + 4, y + 4, 0, fg);
        }
    }
    fc_capture(h);
}

static void blend_sweep_a(fc_h *h)
{
    blend_sweep(h, bg_colors, fg_colors);
}

static void blend_sweep_b(fc_h *h)
{
    static const GLubyte bg[4][4] = {
        { 1, 254, 128, 255 }, { 127, 129, 3, 1 }, { 255, 255, 255, 200 }, { 0, 0, 0, 60 },
    };
    static const GLubyte fg[4][4] = {
        { 255, 255, 255, 255 }, { 0, 0, 0, 1 }, { 128, 127, 129, 127 }, { 17, 230, 99, 180 },
    };
    blend_sweep(h, bg, fg);
}

/* Every (value, factor) pair of the unorm8 multiply: pixel (x, y) blends
 * value x with alpha y.  gallivm's (t + (t >> 8) + 128) >> 8 differs from
 * round(x * y / 255) for 24 of the 65536 pairs (e.g. 152 * 229). First the
 * source term (SRC_ALPHA, ZERO), then the destination term (ZERO,
 * SRC_ALPHA) over a background of the values. */
static void blend_mul_exhaustive(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ZERO);
    glBegin(GL_QUADS);
    for (int y = 0; y < 256; y++) {
        for (int x = 0; x < 256; x++) {
            glColor4ub((GLubyte)x, (GLubyte)(255 - x), (GLubyte)(x ^ y), (GLubyte)y);
            glVertex2f((float)x, (float)y);
            glVertex2f((float)x + 1, (float)y);
            glVertex2f((float)x + 1, (float)y + 1);
            glVertex2f((float)x, (float)y + 1);
        }
    }
    glEnd();
    fc_capture(h);
    glDisable(GL_BLEND);
    glBegin(GL_QUADS);
    for (int x = 0; x < 256; x++) {
        glColor4ub((GLubyte)x, (GLubyte)(255 - x), (GLubyte)(x * 7), (GLubyte)(x * 3));
        glVertex2f((float)x, 0);
        glVertex2f((float)x + 1, 0);
        glVertex2f((float)x + 1, 256);
        glVertex2f((float)x, 256);
    }
    glEnd();
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_SRC_ALPHA);
    glBegin(GL_QUADS);
    for (int y = 0; y < 256; y++) {
        glColor4ub(0, 0, 0, (GLubyte)y);
        glVertex2f(0, (float)y);
        glVertex2f(256, (float)y);
        glVertex2f(256, (float)y + 1);
        glVertex2f(0, (float)y + 1);
    }
    glEnd();
    fc_capture(h);
}

/* Each equation with a few factor pairs (MIN/MAX ignore the factors). */
static void blend_equations(fc_h *h)
{
    static const GLenum eqs[5] = {
        GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX
    };
    static const GLenum pairs[3][2] = {
        { GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA }, { GL_ONE, GL_ONE }, { GL_DST_COLOR, GL_SRC_COLOR },
    };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    gradient_background(h, 60, 30);
    glEnable(GL_BLEND);
    for (int e = 0; e < 5; e++) {
        glBlendEquation(eqs[e]);
        for (int p = 0; p < 3; p++) {
            glBlendFunc(pairs[p][0], pairs[p][1]);
            const float x = 12.0f * (float)e, y = 10.0f * (float)p;
            grad_rect(x, y, x + 12, y + 10, 0, fg_colors);
        }
    }
    fc_get_integer(h, "GL_BLEND_EQUATION", GL_BLEND_EQUATION, 1);
    fc_get_integer(h, "GL_BLEND_EQUATION_ALPHA", GL_BLEND_EQUATION_ALPHA, 1);
    fc_capture(h);
}

/* Blend colour factors with several colours, including values outside
 * [0,1] (clamped for drawing and queries). */
static void blend_color(fc_h *h)
{
    static const float colors[4][4] = {
        { 0.5f, 0.25f, 0.75f, 0.5f }, { 1.5f, -0.5f, 0.3f, 2.0f },
        { 0.5f / 255.0f, 1.5f / 255.0f, 254.5f / 255.0f, 127.5f / 255.0f }, { 0, 0, 0, 0 },
    };
    static const GLenum pairs[4][2] = {
        { GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR }, { GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA },
        { GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA }, { GL_SRC_ALPHA, GL_CONSTANT_COLOR },
    };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    gradient_background(h, 64, 32);
    glEnable(GL_BLEND);
    for (int c = 0; c < 4; c++) {
        glBlendColor(colors[c][0], colors[c][1], colors[c][2], colors[c][3]);
        for (int p = 0; p < 4; p++) {
            glBlendFunc(pairs[p][0], pairs[p][1]);
            const float x = 16.0f * (float)c, y = 8.0f * (float)p;
            grad_rect(x, y, x + 16, y + 8, 0, fg_colors);
        }
        fc_get_float(h, "GL_BLEND_COLOR", GL_BLEND_COLOR, 4);
        fc_get_integer(h, "GL_BLEND_COLOR int", GL_BLEND_COLOR, 4);
    }
    fc_capture(h);
}

/* Blending into formats with the colour channels in other orders. */
static void blend_format(fc_h *h)
{
    blend_common_pairs(h);
}

/* Overlapping translucent layers (painter's order), with depth test. */
static void blend_layers(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.9f, 0.9f, 0.9f, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    for (int i = 0; i < 6; i++) {
        glColor4ub((GLubyte)(50 * i), (GLubyte)(255 - 40 * i), (GLubyte)(100 + 20 * i), (GLubyte)(60 + 30 * i));
        fcu_tri(3.0f * i, 2.0f + i, 30.0f - i, 4.0f * i, 10.0f + 2.0f * i, 30.0f - 2.0f * i);
    }
    glDepthMask(GL_TRUE);
    fc_capture(h);
}

/* ---- logic op ---- */

/* All sixteen ops over a gradient; the logic op replaces blending. */
static void logic_ops_all(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    gradient_background(h, 64, 32);
    glEnable(GL_COLOR_LOGIC_OP);
    glEnable(GL_BLEND);                   /* ignored while the logic op is on */
    glBlendFunc(GL_ZERO, GL_ZERO);
    for (int i = 0; i < 16; i++) {
        glLogicOp(GL_CLEAR + i);
        const float x = 8.0f * (float)(i % 8), y = 16.0f * (float)(i / 8);
        grad_rect(x, y, x + 8, y + 16, 0, fg_colors);
    }
    fc_get_integer(h, "GL_LOGIC_OP_MODE", GL_LOGIC_OP_MODE, 1);
    fc_is_enabled(h, "GL_COLOR_LOGIC_OP", GL_COLOR_LOGIC_OP);
    fc_capture(h);
    glDisable(GL_COLOR_LOGIC_OP);
    glBlendFunc(GL_ONE, GL_ONE);
    grad_rect(0, 0, 64, 8, 0, fg_colors);
    fc_capture(h);
}

/* Logic op under a colour mask. */
static void logic_op_masked(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    gradient_background(h, 32, 32);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    grad_rect(0, 0, 32, 16, 0, fg_colors);
    glLogicOp(GL_INVERT);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    grad_rect(0, 16, 32, 32, 0, fg_colors);
    fc_capture(h);
}

/* ---- masks ---- */

/* Colour mask per channel when drawing, with and without blending. */
static void color_mask_draw(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.5f, 0.5f, 0.5f, 0.5f, 1);
    for (int m = 0; m < 16; m++) {
        glColorMask(m & 1, (m >> 1) & 1, (m >> 2) & 1, (m >> 3) & 1);
        const float x = 4.0f * (float)m;
        if (m & 1)
            glEnable(GL_BLEND);
        else
            glDisable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        grad_rect(x, 0, x + 4, 32, 0, fg_colors);
    }
    fc_capture(h);
}

/* Depth mask with stencil: depth kept, stencil still written. */
static void depth_mask_stencil(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(1);
    fcu_clear(0, 0, 0, 0, 0.5);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_INCR, GL_REPLACE);
    glDepthMask(GL_FALSE);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    fcu_color(2); fcu_rect(2, 2, 20, 20, 0.5f);
    glStencilFunc(GL_GEQUAL, 5, 0xff);
    fcu_color(3); fcu_rect(10, 10, 30, 30, -0.5f);
    glDepthMask(GL_TRUE);
    glStencilFunc(GL_ALWAYS, 9, 0xff);
    fcu_color(4); fcu_rect(14, 2, 30, 12, 0.2f);
    fc_capture(h);
}

/* ---- depth buffers of 16/24/32 bits ---- */

/* Sloped interpenetrating triangles with LEQUAL and EQUAL ties. */
static void depth_bits_ties(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    for (int pass = 0; pass < 3; pass++) {
        glDepthFunc(pass == 0 ? GL_LESS : pass == 1 ? GL_LEQUAL : GL_EQUAL);
        fcu_color(pass * 3);
        glBegin(GL_TRIANGLES);
        glVertex3f(0.3f, 1.2f, -0.9f); glVertex3f(31.9f, 3.3f, 0.77f); glVertex3f(2.1f, 31.0f, 0.1f);
        glVertex3f(30.5f, 30.0f, 0.9f); glVertex3f(1.5f, 30.0f, -0.8f); glVertex3f(30.7f, 1.5f, 0.3f);
        glEnd();
    }
    fc_capture(h);
    /* scissored clear of part of it, then equal-depth probes */
    glEnable(GL_SCISSOR_TEST);
    glScissor(8, 8, 16, 16);
    glClearDepth(0.4);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glDepthFunc(GL_EQUAL);
    fcu_color(5);
    fcu_rect(0, 0, 32, 32, 0.2f);
    fc_capture(h);
}

/* ---- random state mixes ---- */

/* splitmix64 */
static unsigned long long mix_next(unsigned long long *st)
{
    unsigned long long z = (*st += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static int mix_int(unsigned long long *st, int n)
{
    return (int)(mix_next(st) % (unsigned long long)n);
}

static float mix_float(unsigned long long *st, float lo, float hi)
{
    return lo + (hi - lo) * (float)(mix_next(st) >> 40) / 16777216.0f;
}

/* Smooth triangles under random per-fragment state: scissor, alpha test,
 * stencil, depth, blending, logic op, masks, and scissored/masked clears
 * in between.  A pure function of the seed. */
static void random_mix(fc_h *h, unsigned long long seed)
{
    static const GLenum eqs[5] = {
        GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX
    };
    unsigned long long st = seed;
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0.3f, 0.2f, 0.1f, 0.6f, 1);
    glClear(GL_STENCIL_BUFFER_BIT);
    for (int i = 0; i < 60; i++) {
        switch (mix_int(&st, 12)) {
        case 0:
            if (mix_int(&st, 2)) {
                glEnable(GL_SCISSOR_TEST);
                glScissor(mix_int(&st, 70) - 5, mix_int(&st, 70) - 5, mix_int(&st, 60), mix_int(&st, 60));
            } else {
                glDisable(GL_SCISSOR_TEST);
            }
            break;
        case 1:
            if (mix_int(&st, 3)) {
                glEnable(GL_ALPHA_TEST);
                glAlphaFunc(funcs[mix_int(&st, 8)], mix_float(&st, -0.1f, 1.1f));
            } else {
                glDisable(GL_ALPHA_TEST);
            }
            break;
        case 2:
            if (mix_int(&st, 4)) {
                glEnable(GL_STENCIL_TEST);
                glStencilFunc(funcs[mix_int(&st, 8)], mix_int(&st, 300) - 20, (GLuint)mix_next(&st));
                glStencilOp(stencil_ops[mix_int(&st, 8)], stencil_ops[mix_int(&st, 8)],
                            stencil_ops[mix_int(&st, 8)]);
            } else {
                glDisable(GL_STENCIL_TEST);
            }
            break;
        case 3:
            glStencilMask(mix_int(&st, 2) ? ~0u : (GLuint)mix_next(&st));
            break;
        case 4:
            if (mix_int(&st, 4)) {
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(funcs[mix_int(&st, 8)]);
            } else {
                glDisable(GL_DEPTH_TEST);
            }
            glDepthMask(mix_int(&st, 4) != 0);
            break;
        case 5:
        case 6:
            if (mix_int(&st, 4)) {
                glEnable(GL_BLEND);
                glBlendFunc(factors[mix_int(&st, 15)], factors[mix_int(&st, 15)]);
                glBlendEquation(eqs[mix_int(&st, 5)]);
                glBlendColor(mix_float(&st, -0.2f, 1.2f), mix_float(&st, 0, 1),
                             mix_float(&st, 0, 1), mix_float(&st, 0, 1));
            } else {
                glDisable(GL_BLEND);
            }
            break;
        case 7:
            if (mix_int(&st, 4) == 0) {
                glEnable(GL_COLOR_LOGIC_OP);
                glLogicOp(GL_CLEAR + mix_int(&st, 16));
            } else {
                glDisable(GL_COLOR_LOGIC_OP);
            }
            break;
        case 8: {
            const int m = mix_int(&st, 3) ? 15 : mix_int(&st, 16);
            glColorMask(m & 1, (m >> 1) & 1, (m >> 2) & 1, (m >> 3) & 1);
            break;
        }
        case 9: {
            static const GLbitfield bits[4] = {
                GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT, GL_STENCIL_BUFFER_BIT,
                GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
            };
            glClearColor(mix_float(&st, 0, 1), mix_float(&st, 0, 1), mix_float(&st, 0, 1), mix_float(&st, 0, 1));
            glClearDepth(mix_float(&st, 0, 1));
            glClearStencil(mix_int(&st, 256));
            glClear(bits[mix_int(&st, 4)]);
            break;
        }
        default:
            break;
        }
        glBegin(GL_TRIANGLES);
        for (int v = 0; v < 3; v++) {
            glColor4f(mix_float(&st, -0.1f, 1.1f), mix_float(&st, 0, 1), mix_float(&st, 0, 1),
                      mix_float(&st, -0.1f, 1.1f));
            glVertex3f(mix_float(&st, -8, 72), mix_float(&st, -8, 72), mix_float(&st, -1.2f, 1.2f));
        }
        glEnd();
        if (i == 29)
            fc_capture(h);
    }
    fc_capture(h);
}

static void random_mix_1(fc_h *h) { random_mix(h, 1); }
static void random_mix_2(fc_h *h) { random_mix(h, 2); }
static void random_mix_3(fc_h *h) { random_mix(h, 3); }
static void random_mix_4(fc_h *h) { random_mix(h, 4); }
static void random_mix_5(fc_h *h) { random_mix(h, 5); }
static void random_mix_6(fc_h *h) { random_mix(h, 6); }
static void random_mix_7(fc_h *h) { random_mix(h, 7); }
static void random_mix_8(fc_h *h) { random_mix(h, 8); }

/* ---- errors and queries ---- */

static void errors_enums(fc_h *h)
{
    fc_pixel_ortho(h);
    glAlphaFunc(GL_NEVER - 1, 0.5f); fc_error(h, "glAlphaFunc bad");
    glAlphaFunc(GL_ALWAYS + 1, 0.5f); fc_error(h, "glAlphaFunc above");
    glBlendFunc(GL_SRC_ALPHA, GL_SRC_ALPHA_SATURATE); fc_error(h, "glBlendFunc dst saturate");
    glBlendFunc(GL_ONE, GL_ZERO);
    glBlendFunc(0x1234, GL_ONE); fc_error(h, "glBlendFunc bad src");
    glBlendFunc(GL_ONE, 0x1234); fc_error(h, "glBlendFunc bad dst");
    glBlendFunc(GL_ONE, GL_ZERO); fc_error(h, "glBlendFunc no change");
    /* (the dual-source SRC1 factors are ARB_blend_func_extended's, foreign
     * to GL 1.5: honesty/blend_factors) */
    glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE_MINUS_CONSTANT_ALPHA); fc_error(h, "glBlendFunc saturate");
    glBlendFunc(GL_ONE, GL_ZERO);
    glBlendEquation(GL_FUNC_ADD + 100); fc_error(h, "glBlendEquation bad");
    glBlendEquation(GL_LOGIC_OP); fc_error(h, "glBlendEquation GL_LOGIC_OP");
    glLogicOp(GL_CLEAR - 1); fc_error(h, "glLogicOp below");
    glLogicOp(GL_SET + 1); fc_error(h, "glLogicOp above");
    glStencilFunc(GL_NEVER - 1, 0, 0); fc_error(h, "glStencilFunc bad");
    glStencilOp(0, GL_KEEP, GL_KEEP); fc_error(h, "glStencilOp sfail 0");
    glStencilOp(GL_KEEP, GL_ALWAYS, GL_KEEP); fc_error(h, "glStencilOp zfail bad");
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR + 10); fc_error(h, "glStencilOp zpass bad");
    glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT); fc_error(h, "glStencilOp wrap");
    glScissor(1, 2, -1, 4); fc_error(h, "glScissor negative width");
    glScissor(1, 2, 3, -4); fc_error(h, "glScissor negative height");
    glScissor(-10, -20, 0, 0); fc_error(h, "glScissor negative origin");
    glEnable(GL_SCISSOR_TEST); fc_error(h, "glEnable scissor");
    glEnable(GL_STENCIL_TEST); fc_error(h, "glEnable stencil");
    glEnable(GL_COLOR_LOGIC_OP); fc_error(h, "glEnable logic op");
    glEnable(GL_INDEX_LOGIC_OP); fc_error(h, "glEnable index logic op");
    fc_get_integer(h, "GL_SCISSOR_BOX", GL_SCISSOR_BOX, 4);
    fc_get_integer(h, "GL_ALPHA_TEST_FUNC", GL_ALPHA_TEST_FUNC, 1);
    fc_get_integer(h, "GL_BLEND_DST", GL_BLEND_DST, 1);
    fc_get_integer(h, "GL_BLEND_EQUATION", GL_BLEND_EQUATION, 1);
    fc_get_integer(h, "GL_LOGIC_OP_MODE", GL_LOGIC_OP_MODE, 1);
    fc_get_integer(h, "GL_STENCIL_FUNC", GL_STENCIL_FUNC, 1);
    fc_get_integer(h, "GL_STENCIL_FAIL", GL_STENCIL_FAIL, 1);
    fc_get_integer(h, "GL_STENCIL_PASS_DEPTH_FAIL", GL_STENCIL_PASS_DEPTH_FAIL, 1);
    fc_get_integer(h, "GL_STENCIL_PASS_DEPTH_PASS", GL_STENCIL_PASS_DEPTH_PASS, 1);
}

/* Every new entry point between glBegin and glEnd: INVALID_OPERATION and
 * state unchanged; the triangle still draws. */
static void errors_begin_end(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    for (int k = 0; k < 11; k++) {
        fcu_color(k);
        glBegin(GL_TRIANGLES);
        glVertex2f(2.0f * k, 0);
        switch (k) {
        case 0: glScissor(0, 0, 4, 4); break;
        case 1: glAlphaFunc(GL_LESS, 0.5f); break;
        case 2: glBlendFunc(GL_ZERO, GL_ZERO); break;
        case 3: glBlendEquation(GL_MIN); break;
        case 4: glBlendColor(1, 1, 1, 1); break;
        case 5: glLogicOp(GL_XOR); break;
        case 6: glColorMask(0, 0, 0, 0); break;
        case 7: glStencilFunc(GL_NEVER, 1, 1); break;
        case 8: glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO); break;
        case 9: glStencilMask(0); break;
        case 10: glClearStencil(5); break;
        }
        glVertex2f(2.0f * k + 8, 0);
        glVertex2f(2.0f * k + 4, 30);
        glEnd();
        fc_error(h, "inside glBegin/glEnd");
    }
    fc_capture(h);
    fc_get_integer(h, "GL_SCISSOR_BOX", GL_SCISSOR_BOX, 4);
    fc_get_integer(h, "GL_ALPHA_TEST_FUNC", GL_ALPHA_TEST_FUNC, 1);
    fc_get_integer(h, "GL_BLEND_SRC", GL_BLEND_SRC, 1);
    fc_get_integer(h, "GL_BLEND_EQUATION", GL_BLEND_EQUATION, 1);
    fc_get_float(h, "GL_BLEND_COLOR", GL_BLEND_COLOR, 4);
    fc_get_integer(h, "GL_LOGIC_OP_MODE", GL_LOGIC_OP_MODE, 1);
    fc_get_integer(h, "GL_COLOR_WRITEMASK", GL_COLOR_WRITEMASK, 4);
    fc_get_integer(h, "GL_STENCIL_FUNC", GL_STENCIL_FUNC, 1);
    fc_get_integer(h, "GL_STENCIL_FAIL", GL_STENCIL_FAIL, 1);
    fc_get_integer(h, "GL_STENCIL_WRITEMASK", GL_STENCIL_WRITEMASK, 1);
    fc_get_integer(h, "GL_STENCIL_CLEAR_VALUE", GL_STENCIL_CLEAR_VALUE, 1);
}

static const struct { GLenum pname; int n; const char *name; } qlist[] = {
    { GL_SCISSOR_BOX, 4, "GL_SCISSOR_BOX" },
    { GL_SCISSOR_TEST, 1, "GL_SCISSOR_TEST" },
    { GL_ALPHA_TEST, 1, "GL_ALPHA_TEST" },
    { GL_ALPHA_TEST_FUNC, 1, "GL_ALPHA_TEST_FUNC" },
    { GL_ALPHA_TEST_REF, 1, "GL_ALPHA_TEST_REF" },
    { GL_BLEND, 1, "GL_BLEND" },
    { GL_BLEND_SRC, 1, "GL_BLEND_SRC" },
    { GL_BLEND_DST, 1, "GL_BLEND_DST" },
    { GL_BLEND_SRC_ALPHA, 1, "GL_BLEND_SRC_ALPHA" },
    { GL_BLEND_DST_ALPHA, 1, "GL_BLEND_DST_ALPHA" },
    { GL_BLEND_EQUATION, 1, "GL_BLEND_EQUATION" },
    { GL_BLEND_EQUATION_ALPHA, 1, "GL_BLEND_EQUATION_ALPHA" },
    { GL_BLEND_COLOR, 4, "GL_BLEND_COLOR" },
    { GL_COLOR_LOGIC_OP, 1, "GL_COLOR_LOGIC_OP" },
    { GL_LOGIC_OP_MODE, 1, "GL_LOGIC_OP_MODE" },
    { GL_COLOR_WRITEMASK, 4, "GL_COLOR_WRITEMASK" },
    { GL_DITHER, 1, "GL_DITHER" },
    { GL_STENCIL_TEST, 1, "GL_STENCIL_TEST" },
    { GL_STENCIL_FUNC, 1, "GL_STENCIL_FUNC" },
    { GL_STENCIL_REF, 1, "GL_STENCIL_REF" },
    { GL_STENCIL_VALUE_MASK, 1, "GL_STENCIL_VALUE_MASK" },
    { GL_STENCIL_WRITEMASK, 1, "GL_STENCIL_WRITEMASK" },
    { GL_STENCIL_FAIL, 1, "GL_STENCIL_FAIL" },
    { GL_STENCIL_PASS_DEPTH_FAIL, 1, "GL_STENCIL_PASS_DEPTH_FAIL" },
    { GL_STENCIL_PASS_DEPTH_PASS, 1, "GL_STENCIL_PASS_DEPTH_PASS" },
    { GL_STENCIL_CLEAR_VALUE, 1, "GL_STENCIL_CLEAR_VALUE" },
    { GL_STENCIL_BITS, 1, "GL_STENCIL_BITS" },
};

static void query_all(fc_h *h)
{
    for (size_t i = 0; i < sizeof qlist / sizeof qlist[0]; i++) {
        fc_get_integer(h, qlist[i].name, qlist[i].pname, qlist[i].n);
        fc_get_float(h, qlist[i].name, qlist[i].pname, qlist[i].n);
        fc_get_double(h, qlist[i].name, qlist[i].pname, qlist[i].n);
        fc_get_boolean(h, qlist[i].name, qlist[i].pname, qlist[i].n);
    }
    fc_is_enabled(h, "GL_SCISSOR_TEST", GL_SCISSOR_TEST);
    fc_is_enabled(h, "GL_ALPHA_TEST", GL_ALPHA_TEST);
    fc_is_enabled(h, "GL_BLEND", GL_BLEND);
    fc_is_enabled(h, "GL_COLOR_LOGIC_OP", GL_COLOR_LOGIC_OP);
    fc_is_enabled(h, "GL_STENCIL_TEST", GL_STENCIL_TEST);
}

static void query_defaults(fc_h *h)
{
    query_all(h);
}

static void query_set(fc_h *h)
{
    glScissor(-3, 5, 70000, 2);
    glEnable(GL_SCISSOR_TEST);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_NOTEQUAL, 0.123f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE);
    glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
    glBlendColor(0.1f, -2.0f, 3.0f, 0.999f);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_NAND);
    glColorMask(GL_TRUE, GL_FALSE, 2, GL_FALSE);
    glDisable(GL_DITHER);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_GEQUAL, 77, 0x12345678u);
    glStencilMask(0x80000001u);
    glStencilOp(GL_INVERT, GL_INCR_WRAP, GL_DECR);
    glClearStencil(-7);
    query_all(h);
}

const fc_case fc_cases_fragment[] = {
    FC_CASE_RGBA("fragment/scissor_draw", 32, 32, 2, "fragment", scissor_draw),
    FC_CASE_RGBA("fragment/scissor_huge", 32, 32, 2, "fragment", scissor_huge),
    FC_CASE_RGBA("fragment/scissor_triangles", 32, 32, 1, "fragment", scissor_triangles),
    FC_CASE_RGBA("fragment/scissor_tiles", 160, 120, 1, "fragment", scissor_tiles),
    FC_CASE_RGBA("fragment/scissor_clear_color", 32, 32, 2, "fragment", scissor_clear_color),
    FC_CASE_RGBA("fragment/scissor_clear_depth", 64, 32, 2, "fragment", scissor_clear_depth),
    FC_CASE("fragment/scissor_clear_depth_16", 64, 32, OSMESA_RGBA, 16, 0, 2, "fragment", scissor_clear_depth16),
    FC_CASE("fragment/scissor_clear_depth_stencil", 64, 32, OSMESA_RGBA, 24, 8, 2, "fragment", scissor_clear_depth),
    FC_CASE_RGBA("fragment/clear_color_mask", 32, 32, 3, "fragment", clear_color_mask),
    FC_CASE("fragment/clear_color_mask_bgra", 32, 32, OSMESA_BGRA, 24, 0, 3, "fragment", clear_color_mask),
    FC_CASE("fragment/clear_stencil", 32, 32, OSMESA_RGBA, 24, 8, 4, "fragment", clear_stencil),
    FC_CASE("fragment/clear_stencil_only", 32, 32, OSMESA_RGBA, 0, 8, 4, "fragment", clear_stencil),
    FC_CASE("fragment/clear_mixed_masks", 32, 32, OSMESA_RGBA, 24, 8, 2, "fragment", clear_mixed_masks),
    FC_CASE_RGBA("fragment/alpha_funcs", 64, 32, 1, "fragment", alpha_funcs),
    FC_CASE_RGBA("fragment/alpha_ref_ties", 64, 32, 6, "fragment", alpha_ref_ties),
    FC_CASE_RGBA("fragment/alpha_ref_clamp", 32, 32, 1, "fragment", alpha_ref_clamp),
    FC_CASE_RGBA("fragment/alpha_ref_nan", 32, 32, 1, "fragment", alpha_ref_nan),
    FC_CASE("fragment/alpha_kills_depth_stencil", 32, 32, OSMESA_RGBA, 24, 8, 1, "fragment", alpha_kills_depth_stencil),
    FC_CASE("fragment/stencil_funcs", 64, 32, OSMESA_RGBA, 24, 8, 1, "fragment", stencil_funcs),
    FC_CASE("fragment/stencil_ops", 64, 32, OSMESA_RGBA, 24, 8, 1, "fragment", stencil_ops_all),
    FC_CASE("fragment/stencil_wrap_saturate", 32, 32, OSMESA_RGBA, 24, 8, 1, "fragment", stencil_wrap_saturate),
    FC_CASE("fragment/stencil_outline", 64, 32, OSMESA_RGBA, 24, 8, 1, "fragment", stencil_outline),
    FC_CASE("fragment/stencil_capping", 64, 32, OSMESA_RGBA, 24, 8, 1, "fragment", stencil_capping),
    FC_CASE("fragment/stencil_masks", 64, 32, OSMESA_RGBA, 24, 8, 2, "fragment", stencil_masks),
    FC_CASE("fragment/stencil_ref_clamp", 32, 32, OSMESA_RGBA, 24, 8, 1, "fragment", stencil_ref_clamp),
    FC_CASE("fragment/stencil_only_buffer", 32, 32, OSMESA_RGBA, 0, 8, 1, "fragment", stencil_basic),
    FC_CASE("fragment/stencil_depth16", 32, 32, OSMESA_RGBA, 16, 8, 1, "fragment", stencil_basic),
    FC_CASE("fragment/stencil_without_buffer", 32, 32, OSMESA_RGBA, 24, 0, 1, "fragment", stencil_basic),
    FC_CASE_RGBA("fragment/blend_common_pairs", 64, 32, 1, "fragment", blend_common_pairs),
    FC_CASE_RGBA("fragment/blend_sweep_all_pairs_a", 64, 64, 1, "fragment", blend_sweep_a),
    FC_CASE_RGBA("fragment/blend_sweep_all_pairs_b", 64, 64, 1, "fragment", blend_sweep_b),
    FC_CASE_RGBA("fragment/blend_mul_exhaustive", 256, 256, 2, "fragment", blend_mul_exhaustive),
    FC_CASE_RGBA("fragment/blend_equations", 64, 32, 1, "fragment", blend_equations),
    FC_CASE_RGBA("fragment/blend_color", 64, 32, 1, "fragment", blend_color),
    FC_CASE("fragment/blend_bgra", 64, 32, OSMESA_BGRA, 24, 0, 1, "fragment", blend_format),
    FC_CASE("fragment/blend_argb", 64, 32, OSMESA_ARGB, 24, 0, 1, "fragment", blend_format),
    FC_CASE_RGBA("fragment/blend_layers", 32, 32, 1, "fragment", blend_layers),
    FC_CASE_RGBA("fragment/logic_ops_all", 64, 32, 2, "fragment", logic_ops_all),
    FC_CASE_RGBA("fragment/logic_op_masked", 32, 32, 1, "fragment", logic_op_masked),
    FC_CASE_RGBA("fragment/color_mask_draw", 64, 32, 1, "fragment", color_mask_draw),
    FC_CASE("fragment/depth_mask_stencil", 32, 32, OSMESA_RGBA, 24, 8, 1, "fragment", depth_mask_stencil),
    FC_CASE("fragment/depth_bits_16_ties", 32, 32, OSMESA_RGBA, 16, 0, 2, "fragment", depth_bits_ties),
    FC_CASE("fragment/depth_bits_24_ties", 32, 32, OSMESA_RGBA, 24, 0, 2, "fragment", depth_bits_ties),
    FC_CASE("fragment/depth_bits_32_ties", 32, 32, OSMESA_RGBA, 32, 0, 2, "fragment", depth_bits_ties),
    FC_CASE("fragment/depth_bits_24s8_ties", 32, 32, OSMESA_RGBA, 24, 8, 2, "fragment", depth_bits_ties),
    FC_CASE("fragment/random_mix_1", 64, 64, OSMESA_RGBA, 24, 8, 2, "fragment", random_mix_1),
    FC_CASE("fragment/random_mix_2", 64, 64, OSMESA_RGBA, 24, 8, 2, "fragment", random_mix_2),
    FC_CASE("fragment/random_mix_3", 64, 64, OSMESA_BGRA, 24, 8, 2, "fragment", random_mix_3),
    FC_CASE("fragment/random_mix_4", 64, 64, OSMESA_ARGB, 24, 8, 2, "fragment", random_mix_4),
    FC_CASE("fragment/random_mix_5", 64, 64, OSMESA_RGBA, 16, 0, 2, "fragment", random_mix_5),
    FC_CASE("fragment/random_mix_6", 64, 64, OSMESA_RGBA, 0, 8, 2, "fragment", random_mix_6),
    FC_CASE("fragment/random_mix_7", 64, 64, OSMESA_RGBA, 32, 0, 2, "fragment", random_mix_7),
    FC_CASE("fragment/random_mix_8", 64, 64, OSMESA_RGBA, 24, 8, 2, "fragment", random_mix_8),
    FC_CASE_RGBA("fragment/errors_enums", 32, 32, 0, "fragment error", errors_enums),
    FC_CASE("fragment/errors_begin_end", 32, 32, OSMESA_RGBA, 24, 8, 1, "fragment error", errors_begin_end),
    FC_CASE("fragment/query_defaults", 16, 16, OSMESA_RGBA, 24, 8, 0, "fragment query", query_defaults),
    FC_CASE("fragment/query_set", 16, 16, OSMESA_RGBA, 24, 8, 0, "fragment query", query_set),
    FC_CASE("fragment/query_set_no_stencil", 16, 16, OSMESA_RGBA, 24, 0, 0, "fragment query", query_set),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
