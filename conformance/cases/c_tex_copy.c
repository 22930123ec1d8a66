/* c_tex_copy.c - copies from the colour buffer into textures and generated
 * mipmaps in the formats of other than 8 bits per channel (issue 19,
 * "Open from earlier texture work"; ORACLE-NOTES.md "Copies into textures
 * and generated mipmaps", probe p_copy_tex):
 *  - glCopyTexImage/glCopyTexSubImage into an RGB internal format: the
 *    texture's alpha reads as 1, in glGetTexImage and when drawn; the
 *    GL 1.1 internal formats the oracle accepts there raise no error;
 *  - GL_R3_G3_B2 copies: the blit's rescale of each 8-bit channel;
 *  - GL_GENERATE_MIPMAP into 5-, 3-, 2-, 4-bit formats (the 8-bit blit
 *    result stored as the render target converts it) and into 10- and
 *    16-bit formats (sampled on the float path), read back in the
 *    format's own precision and drawn minified. */
#include "cases.h"

#include <GL/glext.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

static GLubyte src[64 * 64 * 4];
static GLushort src16[64 * 64 * 4];
static GLubyte readback[64 * 64 * 16];

static void fill(int seed)
{
    for (size_t i = 0; i < sizeof src; i++)
        src[i] = (GLubyte)((i * 37u + (size_t)seed * 101u + (i >> 4) * 13u + (i * i >> 7)) & 255u);
    for (size_t i = 0; i < sizeof src16 / sizeof src16[0]; i++)
        src16[i] = (GLushort)((i * 40503u + (size_t)seed * 7919u + (i * i * 13u)) & 0xffffu);
}

/* A picture with every kind of channel value: a smooth quad and a few
 * translucent triangles over a cleared buffer. */
static void picture(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    const float w = (float)c->width, hh = (float)c->height;
    fc_pixel_ortho(h);
    glClearColor(0.1f, 0.5f, 0.9f, 0.35f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glColor4f(1, 0, 0.2f, 0.1f); glVertex2f(0, 0);
    glColor4f(0, 1, 0.6f, 0.9f); glVertex2f(w, 0);
    glColor4f(0.3f, 0.2f, 1, 0.5f); glVertex2f(w, hh);
    glColor4f(0.9f, 0.8f, 0, 0.7f); glVertex2f(0, hh);
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor4f(0.05f, 0.95f, 0.45f, 0.2f);
    glVertex2f(w * 0.1f, hh * 0.2f); glVertex2f(w * 0.7f, hh * 0.3f); glVertex2f(w * 0.3f, hh * 0.9f);
    glEnd();
}

static void level_info(fc_h *h, const char *label, GLenum target, GLint level)
{
    static const GLenum pn[] = { GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_INTERNAL_FORMAT,
                                 GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                                 GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE,
                                 GL_TEXTURE_INTENSITY_SIZE };
    GLint v[9];
    for (int i = 0; i < 9; i++) {
        v[i] = -1;
        glGetTexLevelParameteriv(target, level, pn[i], &v[i]);
    }
    fc_blob(h, label, v, sizeof v);
}

/* Level `level` read back as RGBA in `type`, `bpt` bytes per texel. */
static void get_level(fc_h *h, const char *label, GLenum target, GLint level, GLenum type,
                      int bpt)
{
    GLint w = 0, hh = 0;
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &hh);
    if (w <= 0 || hh <= 0 || w > 64 || hh > 64) {
        fc_value(h, label, (long long)w * 1000 + hh);
        return;
    }
    memset(readback, 0xA5, sizeof readback);
    glGetTexImage(target, level, GL_RGBA, type, readback);
    fc_blob(h, label, readback, (size_t)w * (size_t)hh * (size_t)bpt);
}

/* ---- glCopyTexImage into RGB formats: alpha 1 ------------------------ */

static const GLint rgb_formats[] = { GL_RGB, GL_R3_G3_B2, GL_RGB4, GL_RGB5, GL_RGB8,
                                     GL_RGB10, GL_RGB12, GL_RGB16, GL_LUMINANCE,
                                     GL_LUMINANCE8, GL_LUMINANCE16 };

static void copy_rgb_alpha(fc_h *h)
{
    picture(h);
    fc_capture(h);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (size_t k = 0; k < sizeof rgb_formats / sizeof rgb_formats[0]; k++) {
        char l[64];
        snprintf(l, sizeof l, "copy 0x%04x", (unsigned)rgb_formats[k]);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, rgb_formats[k], 3, 2, 16, 8, 0);
        fc_error(h, l);
        level_info(h, l, GL_TEXTURE_2D, 0);
        get_level(h, l, GL_TEXTURE_2D, 0, GL_UNSIGNED_BYTE, 4);
        get_level(h, "ushort", GL_TEXTURE_2D, 0, GL_UNSIGNED_SHORT, 8);
    }
}

static void copy_sub_rgb_alpha(fc_h *h)
{
    picture(h);
    fc_capture(h);
    fill(5);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (size_t k = 0; k < sizeof rgb_formats / sizeof rgb_formats[0]; k++) {
        char l[64];
        snprintf(l, sizeof l, "sub 0x%04x", (unsigned)rgb_formats[k]);
        glTexImage2D(GL_TEXTURE_2D, 0, rgb_formats[k], 16, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 1, 5, 3, 9, 5);
        fc_error(h, l);
        get_level(h, l, GL_TEXTURE_2D, 0, GL_UNSIGNED_BYTE, 4);
    }
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB5, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 3, 2, 7, 10);
    get_level(h, "sub 1d", GL_TEXTURE_1D, 0, GL_UNSIGNED_BYTE, 4);
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 1, 9, 16, 0);
    get_level(h, "copy 1d", GL_TEXTURE_1D, 0, GL_UNSIGNED_BYTE, 4);
    fc_error(h, "end");
}

/* The copied RGB texture drawn: GL_REPLACE then blended by its alpha
 * (1: the texture covers), GL_MODULATE with a translucent colour, and
 * GL_DECAL (alpha 1: the texture's colour). */
static void copy_rgb_draw(fc_h *h)
{
    picture(h);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 16, 16, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glClearColor(0.7f, 0.2f, 0.3f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    static const GLenum modes[] = { GL_REPLACE, GL_MODULATE, GL_DECAL };
    for (int m = 0; m < 3; m++) {
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, modes[m]);
        glColor4f(0.9f, 0.8f, 0.7f, 0.4f);
        const float x = 1.0f + 10.0f * (float)m;
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0); glVertex2f(x, 2);
        glTexCoord2f(1, 0); glVertex2f(x + 9, 2);
        glTexCoord2f(1, 1); glVertex2f(x + 9, 30);
        glTexCoord2f(0, 1); glVertex2f(x, 30);
        glEnd();
    }
    fc_capture(h);
}

/* The internal formats glCopyTexImage takes (the GL 1.1 ones: no error)
 * and refuses (component counts, client formats: GL_INVALID_ENUM). */
static void copy_internal_formats(fc_h *h)
{
    static const GLint ok[] = {
        GL_ALPHA, GL_ALPHA4, GL_ALPHA8, GL_ALPHA12, GL_ALPHA16, GL_LUMINANCE, GL_LUMINANCE4,
        GL_LUMINANCE8, GL_LUMINANCE12, GL_LUMINANCE16, GL_LUMINANCE_ALPHA,
        GL_LUMINANCE4_ALPHA4, GL_LUMINANCE6_ALPHA2, GL_LUMINANCE8_ALPHA8,
        GL_LUMINANCE12_ALPHA4, GL_LUMINANCE12_ALPHA12, GL_LUMINANCE16_ALPHA16, GL_INTENSITY,
        GL_INTENSITY4, GL_INTENSITY8, GL_INTENSITY12, GL_INTENSITY16, GL_RGB, GL_R3_G3_B2,
        GL_RGB4, GL_RGB5, GL_RGB8, GL_RGB10, GL_RGB12, GL_RGB16, GL_RGBA, GL_RGBA2, GL_RGBA4,
        GL_RGB5_A1, GL_RGBA8, GL_RGB10_A2, GL_RGBA12, GL_RGBA16,
    };
    static const GLint bad[] = { 1, 2, 3, 4, GL_BGRA, GL_BGR, GL_COLOR_INDEX, 0x1234 };
    picture(h);
    fc_capture(h);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (size_t k = 0; k < sizeof ok / sizeof ok[0]; k++) {
        char l[64];
        snprintf(l, sizeof l, "0x%04x", (unsigned)ok[k]);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, ok[k], 4, 4, 4, 4, 0);
        fc_error(h, l);
        level_info(h, l, GL_TEXTURE_2D, 0);
        get_level(h, l, GL_TEXTURE_2D, 0, GL_UNSIGNED_BYTE, 4);
    }
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char l[64];
        snprintf(l, sizeof l, "bad 0x%04x", (unsigned)bad[k]);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, bad[k], 4, 4, 4, 4, 0);
        fc_error(h, l);
        level_info(h, l, GL_TEXTURE_2D, 0);
    }
}

/* ---- GL_R3_G3_B2 copies ---------------------------------------------- */

/* A smooth picture copied into R3_G3_B2, read back (3_3_2 packed and
 * RGBA ubyte) and drawn magnified. */
static void copy_r3g3b2_picture(fc_h *h)
{
    picture(h);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_R3_G3_B2, 0, 0, 32, 32, 0);
    fc_error(h, "copy");
    memset(readback, 0xA5, sizeof readback);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, readback);
    fc_blob(h, "3_3_2", readback, 32 * 32);
    get_level(h, "rgba", GL_TEXTURE_2D, 0, GL_UNSIGNED_BYTE, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0.1f, 0.2f); glVertex2f(0, 0);
    glTexCoord2f(0.6f, 0.2f); glVertex2f(32, 0);
    glTexCoord2f(0.6f, 0.7f); glVertex2f(32, 32);
    glTexCoord2f(0.1f, 0.7f); glVertex2f(0, 32);
    glEnd();
    fc_capture(h);
}

/* Every 8-bit value through glCopyTexSubImage2D and glCopyTexImage1D into
 * R3_G3_B2 (the whole image and a part of it). */
static void copy_r3g3b2_sub(fc_h *h)
{
    fc_pixel_ortho(h);
    glBegin(GL_POINTS);
    for (int i = 0; i < 256; i++) {
        glColor4ub((GLubyte)(255 - i), (GLubyte)(i * 5), (GLubyte)i, (GLubyte)(i * 3));
        glVertex2f((float)i + 0.5f, 0.5f);
    }
    glEnd();
    fc_capture(h);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    fill(9);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R3_G3_B2, 256, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 256, 1);
    fc_error(h, "sub 2d");
    memset(readback, 0xA5, sizeof readback);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, readback);
    fc_blob(h, "sub 2d", readback, 256);
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_R3_G3_B2, 0, 0, 256, 0);
    fc_error(h, "copy 1d");
    memset(readback, 0xA5, sizeof readback);
    glGetTexImage(GL_TEXTURE_1D, 0, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, readback);
    fc_blob(h, "copy 1d", readback, 256);
    glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 100, 7, 0, 64);
    memset(readback, 0xA5, sizeof readback);
    glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
    fc_blob(h, "sub 1d", readback, 4 * 256);
}

/* A copy into R3_G3_B2 with GL_GENERATE_MIPMAP: the copied level and the
 * generated ones. */
static void copy_r3g3b2_genmipmap(fc_h *h)
{
    picture(h);
    fc_capture(h);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_R3_G3_B2, 1, 3, 16, 16, 0);
    for (GLint l = 0; l <= 4; l++) {
        char m[32];
        snprintf(m, sizeof m, "L%d", (int)l);
        get_level(h, m, GL_TEXTURE_2D, l, GL_UNSIGNED_BYTE, 4);
    }
}

/* ---- GL_GENERATE_MIPMAP in other formats ----------------------------- */

/* The chain generated from a w x h image of internal format `internal`
 * (client data RGBA ubyte, or ushort when `wide_src`), each level read
 * back as ubyte RGBA and in `type` (bpt bytes per texel). */
static void chain(fc_h *h, GLenum target, GLint internal, int w, int hh, bool wide_src,
                  GLenum type, int bpt)
{
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexParameteri(target, GL_GENERATE_MIPMAP, GL_TRUE);
    if (target == GL_TEXTURE_1D)
        glTexImage1D(target, 0, internal, w, 0, GL_RGBA, wide_src ? GL_UNSIGNED_SHORT
                                                                 : GL_UNSIGNED_BYTE,
                     wide_src ? (const void *)src16 : (const void *)src);
    else
        glTexImage2D(target, 0, internal, w, hh, 0, GL_RGBA,
                     wide_src ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE,
                     wide_src ? (const void *)src16 : (const void *)src);
    fc_error(h, "image");
    for (GLint l = 0; l < 8; l++) {
        GLint lw = 0, lh = 0;
        glGetTexLevelParameteriv(target, l, GL_TEXTURE_WIDTH, &lw);
        glGetTexLevelParameteriv(target, l, GL_TEXTURE_HEIGHT, &lh);
        char m[48];
        snprintf(m, sizeof m, "0x%04x L%d", (unsigned)internal, (int)l);
        fc_value(h, m, (long long)lw * 1000 + lh);
        if (lw == 0)
            break;
        get_level(h, m, target, l, GL_UNSIGNED_BYTE, 4);
        get_level(h, "own type", target, l, type, bpt);
        if (lw == 1 && lh == 1)
            break;
    }
}

/* The generated chain drawn minified with each mipmap filter. */
static void draw_minified(fc_h *h, GLenum target)
{
    static const GLenum mins[] = { GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                   GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR };
    fc_pixel_ortho(h);
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(target);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int m = 0; m < 4; m++) {
        glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)mins[m]);
        const float x = (float)(m % 2) * 16.0f, y = (float)(m / 2) * 16.0f;
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0); glVertex2f(x, y);
        glTexCoord2f(1, 0); glVertex2f(x + 5, y);
        glTexCoord2f(1, 1); glVertex2f(x + 16, y + 13);
        glTexCoord2f(0, 1); glVertex2f(x, y + 11);
        glEnd();
    }
    glDisable(target);
    fc_capture(h);
}

#define GENMIP(fn, internal, w, hh, wide, type, bpt)                          \
    static void fn(fc_h *h)                                                   \
    {                                                                         \
        fill((int)(internal));                                                \
        chain(h, GL_TEXTURE_2D, internal, w, hh, wide, type, bpt);            \
        draw_minified(h, GL_TEXTURE_2D);                                      \
    }

GENMIP(genmip_rgba16, GL_RGBA16, 16, 16, true, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_rgba16_npot, GL_RGBA16, 13, 6, true, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_rgba12_ub, GL_RGBA12, 16, 8, false, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_rgb16, GL_RGB16, 8, 16, true, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_rgb10_a2, GL_RGB10_A2, 16, 16, true, GL_UNSIGNED_INT_10_10_10_2, 4)
GENMIP(genmip_rgb10_npot, GL_RGB10, 11, 7, true, GL_UNSIGNED_INT_2_10_10_10_REV, 4)
GENMIP(genmip_l16_a16_i16, GL_LUMINANCE16, 16, 16, true, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_la16, GL_LUMINANCE16_ALPHA16, 16, 4, true, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_alpha16, GL_ALPHA16, 8, 8, true, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_intensity16, GL_INTENSITY16, 9, 9, true, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_rgb5_a1, GL_RGB5_A1, 16, 16, false, GL_UNSIGNED_SHORT_5_5_5_1, 2)
GENMIP(genmip_rgb565, GL_RGB565, 16, 12, false, GL_UNSIGNED_SHORT_5_6_5, 2)
GENMIP(genmip_rgb5, GL_RGB5, 10, 16, false, GL_UNSIGNED_SHORT_5_5_5_1, 2)
GENMIP(genmip_r3g3b2, GL_R3_G3_B2, 16, 16, false, GL_UNSIGNED_BYTE_3_3_2, 1)
GENMIP(genmip_rgba4, GL_RGBA4, 16, 16, false, GL_UNSIGNED_SHORT_4_4_4_4, 2)
GENMIP(genmip_rgba2, GL_RGBA2, 12, 16, false, GL_UNSIGNED_SHORT_4_4_4_4, 2)
GENMIP(genmip_l4a4, GL_LUMINANCE4_ALPHA4, 16, 16, false, GL_UNSIGNED_BYTE, 4)
/* the blit quad's planes (probe p_genmip_planes): odd and square NPOT
 * sizes, a chain with a level of width 1 and the 2-bit alpha rescale */
GENMIP(genmip_rgba16_odd_square, GL_RGBA16, 15, 15, true, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_rgba16_tall, GL_RGBA16, 3, 23, true, GL_UNSIGNED_SHORT, 8)
GENMIP(genmip_rgb10_a2_npot, GL_RGB10_A2, 21, 10, true, GL_UNSIGNED_INT_10_10_10_2, 4)

/* 1D chains in a 16-bit and a 5-bit format */
static void genmip_1d(fc_h *h)
{
    fill(77);
    chain(h, GL_TEXTURE_1D, GL_RGBA16, 32, 1, true, GL_UNSIGNED_SHORT, 8);
    chain(h, GL_TEXTURE_1D, GL_RGB5_A1, 27, 1, false, GL_UNSIGNED_SHORT_5_5_5_1, 2);
    draw_minified(h, GL_TEXTURE_1D);
}

/* glTexSubImage into the base level regenerates the chain; a base level
 * of 1 generates from there */
static void genmip_sub_base(fc_h *h)
{
    fill(13);
    chain(h, GL_TEXTURE_2D, GL_RGB10_A2, 16, 16, true, GL_UNSIGNED_INT_10_10_10_2, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 2, 6, 5, GL_RGBA, GL_UNSIGNED_SHORT, src16 + 400);
    get_level(h, "after sub L1", GL_TEXTURE_2D, 1, GL_UNSIGNED_INT_10_10_10_2, 4);
    get_level(h, "after sub L2", GL_TEXTURE_2D, 2, GL_UNSIGNED_INT_10_10_10_2, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA16, 8, 8, 0, GL_RGBA, GL_UNSIGNED_SHORT, src16 + 900);
    get_level(h, "base 1 L2", GL_TEXTURE_2D, 2, GL_UNSIGNED_SHORT, 8);
    get_level(h, "base 1 L3", GL_TEXTURE_2D, 3, GL_UNSIGNED_SHORT, 8);
    fc_error(h, "end");
    draw_minified(h, GL_TEXTURE_2D);
}

const fc_case fc_cases_tex_copy[] = {
    FC_CASE_RGBA("texture/copy_rgb_alpha", 32, 16, 1, "texture", copy_rgb_alpha),
    FC_CASE_RGBA("texture/copy_sub_rgb_alpha", 32, 16, 1, "texture", copy_sub_rgb_alpha),
    FC_CASE_RGBA("texture/copy_rgb_draw", 32, 32, 1, "texture", copy_rgb_draw),
    FC_CASE_RGBA("texture/copy_internal_formats", 16, 16, 1, "texture", copy_internal_formats),
    FC_CASE_RGBA("texture/copy_r3g3b2_picture", 32, 32, 1, "texture", copy_r3g3b2_picture),
    FC_CASE_RGBA("texture/copy_r3g3b2_sub", 256, 1, 1, "texture", copy_r3g3b2_sub),
    FC_CASE_RGBA("texture/copy_r3g3b2_genmipmap", 24, 24, 1, "texture", copy_r3g3b2_genmipmap),
    FC_CASE_RGBA("texture/genmipmap_rgba16", 32, 32, 1, "texture", genmip_rgba16),
    FC_CASE_RGBA("texture/genmipmap_rgba16_npot", 32, 32, 1, "texture", genmip_rgba16_npot),
    FC_CASE_RGBA("texture/genmipmap_rgba16_odd_square", 32, 32, 1, "texture", genmip_rgba16_odd_square),
    FC_CASE_RGBA("texture/genmipmap_rgba16_tall", 32, 32, 1, "texture", genmip_rgba16_tall),
    FC_CASE_RGBA("texture/genmipmap_rgb10_a2_npot", 32, 32, 1, "texture", genmip_rgb10_a2_npot),
    FC_CASE_RGBA("texture/genmipmap_rgba12_ubyte", 32, 32, 1, "texture", genmip_rgba12_ub),
    FC_CASE_RGBA("texture/genmipmap_rgb16", 32, 32, 1, "texture", genmip_rgb16),
    FC_CASE_RGBA("texture/genmipmap_rgb10_a2", 32, 32, 1, "texture", genmip_rgb10_a2),
    FC_CASE_RGBA("texture/genmipmap_rgb10_npot", 32, 32, 1, "texture", genmip_rgb10_npot),
    FC_CASE_RGBA("texture/genmipmap_luminance16", 32, 32, 1, "texture", genmip_l16_a16_i16),
    FC_CASE_RGBA("texture/genmipmap_lum16_alpha16", 32, 32, 1, "texture", genmip_la16),
    FC_CASE_RGBA("texture/genmipmap_alpha16", 32, 32, 1, "texture", genmip_alpha16),
    FC_CASE_RGBA("texture/genmipmap_intensity16", 32, 32, 1, "texture", genmip_intensity16),
    FC_CASE_RGBA("texture/genmipmap_rgb5_a1", 32, 32, 1, "texture", genmip_rgb5_a1),
    FC_CASE_RGBA("texture/genmipmap_rgb565", 32, 32, 1, "texture", genmip_rgb565),
    FC_CASE_RGBA("texture/genmipmap_rgb5", 32, 32, 1, "texture", genmip_rgb5),
    FC_CASE_RGBA("texture/genmipmap_r3g3b2", 32, 32, 1, "texture", genmip_r3g3b2),
    FC_CASE_RGBA("texture/genmipmap_rgba4", 32, 32, 1, "texture", genmip_rgba4),
    FC_CASE_RGBA("texture/genmipmap_rgba2", 32, 32, 1, "texture", genmip_rgba2),
    FC_CASE_RGBA("texture/genmipmap_lum4_alpha4", 32, 32, 1, "texture", genmip_l4a4),
    FC_CASE_RGBA("texture/genmipmap_1d_wide", 32, 32, 1, "texture", genmip_1d),
    FC_CASE_RGBA("texture/genmipmap_sub_base_wide", 32, 32, 1, "texture", genmip_sub_base),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
