/* c_tex_copy.c - copies from the colour buffer into textures and generated
 * mipmaps in the formats of other than 8 bits per channel (issue 19,
 * "Open from earlier texture work"; ORACLE-NOTES.md "Copies into textures
 * and generated mipmaps"):
 *  - glCopyTexImage/glCopyTexSubImage into an RGB internal format: the
 *    texture's alpha reads as 1, in glGetTexImage and when drawn; the
 *    GL 1.1 internal formats the oracle accepts there raise no error;
 *  - the 10-bit channels of a copy into 10-10-10-X: the blit's unorm16
 *    shifted. */
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

const fc_case fc_cases_tex_copy[] = {
    FC_CASE_RGBA("texture/copy_rgb_alpha", 32, 16, 1, "texture", copy_rgb_alpha),
    FC_CASE_RGBA("texture/copy_sub_rgb_alpha", 32, 16, 1, "texture", copy_sub_rgb_alpha),
    FC_CASE_RGBA("texture/copy_rgb_draw", 32, 32, 1, "texture", copy_rgb_draw),
    FC_CASE_RGBA("texture/copy_internal_formats", 16, 16, 1, "texture", copy_internal_formats),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
