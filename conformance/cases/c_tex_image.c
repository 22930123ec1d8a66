/* c_tex_image.c - texture images: glTexImage1D/2D for every legacy
 * internal format (the oracle quantizes each to its pipe format) read
 * back through glGetTexImage and glGetTexLevelParameter, proxies, borders
 * (the oracle strips them), NULL data, GL_OUT_OF_MEMORY for images
 * llvmpipe cannot create, glTexSubImage, glCopyTexImage and
 * glCopyTexSubImage from the colour buffer (clipped to it), and every
 * error path in Mesa's order. */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

#ifndef GL_RGB565
#define GL_RGB565 0x8D62
#endif

static const GLint formats[] = {
    1, 2, 3, 4,
    GL_ALPHA, GL_ALPHA4, GL_ALPHA8, GL_ALPHA12, GL_ALPHA16,
    GL_LUMINANCE, GL_LUMINANCE4, GL_LUMINANCE8, GL_LUMINANCE12, GL_LUMINANCE16,
    GL_LUMINANCE_ALPHA, GL_LUMINANCE4_ALPHA4, GL_LUMINANCE6_ALPHA2, GL_LUMINANCE8_ALPHA8,
    GL_LUMINANCE12_ALPHA4, GL_LUMINANCE12_ALPHA12, GL_LUMINANCE16_ALPHA16,
    GL_INTENSITY, GL_INTENSITY4, GL_INTENSITY8, GL_INTENSITY12, GL_INTENSITY16,
    GL_RGB, GL_R3_G3_B2, GL_RGB4, GL_RGB5, GL_RGB565, GL_RGB8, GL_RGB10, GL_RGB12, GL_RGB16,
    GL_RGBA, GL_RGBA2, GL_RGBA4, GL_RGB5_A1, GL_RGBA8, GL_RGB10_A2, GL_RGBA12, GL_RGBA16,
};
#define NFORMATS (sizeof formats / sizeof formats[0])

/* GL 1.5's level parameters.  The GL 3.0 ones the oracle also answers
 * (the *_TYPE values, GL_TEXTURE_STENCIL_SIZE, GL_TEXTURE_SHARED_SIZE, the
 * sample values) raise GL_INVALID_ENUM in fixgl (README "Version and
 * honesty"): honesty/tex_level_pnames records them. */
static const GLenum level_pnames[] = {
    GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH, GL_TEXTURE_INTERNAL_FORMAT,
    GL_TEXTURE_BORDER, GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
    GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE,
    GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_COMPRESSED,
};
#define NPNAMES (sizeof level_pnames / sizeof level_pnames[0])

/* Every level parameter of (target, level), integer and float. */
static void level_params(fc_h *h, const char *label, GLenum target, GLint level)
{
    GLint iv[NPNAMES];
    GLfloat fv[NPNAMES];
    for (size_t i = 0; i < NPNAMES; i++) {
        iv[i] = -77;
        fv[i] = -77.0f;
        glGetTexLevelParameteriv(target, level, level_pnames[i], &iv[i]);
        glGetTexLevelParameterfv(target, level, level_pnames[i], &fv[i]);
    }
    char l[128];
    snprintf(l, sizeof l, "%s params", label);
    fc_blob(h, l, iv, sizeof iv);
    snprintf(l, sizeof l, "%s paramsf", label);
    fc_blob(h, l, fv, sizeof fv);
    snprintf(l, sizeof l, "%s params error", label);
    fc_error(h, l);
}

static GLubyte readback[4 * 64 * 64 + 64];

/* glGetTexImage(GL_RGBA / GL_RGB / GL_BGRA, GL_UNSIGNED_BYTE) of a level
 * of at most 64x64 into a marked buffer. */
static void get_image(fc_h *h, const char *label, GLenum target, GLint level, GLenum format,
                      int w, int hh)
{
    memset(readback, 0xA5, sizeof readback);
    glGetTexImage(target, level, format, GL_UNSIGNED_BYTE, readback);
    char l[128];
    snprintf(l, sizeof l, "%s image", label);
    const size_t comps = format == GL_RGB || format == GL_BGR ? 3 : 4;
    fc_blob(h, l, readback, comps * (size_t)w * (size_t)hh + 16);
    snprintf(l, sizeof l, "%s image error", label);
    fc_error(h, l);
}

/* A w x h source image of 4-byte pixels covering many values. */
static GLubyte src[4 * 64 * 64];
static void fill_src(int seed)
{
    for (size_t i = 0; i < sizeof src; i++)
        src[i] = (GLubyte)((i * 37u + (size_t)seed * 101u + (i >> 4) * 13u) & 255u);
}

/* Every internal format from one client format, 2D and 1D. */
static void formats_from(fc_h *h, GLenum format, GLenum target)
{
    fill_src((int)format);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (size_t f = 0; f < NFORMATS; f++) {
        char l[64];
        snprintf(l, sizeof l, "0x%04x", (unsigned)formats[f]);
        if (target == GL_TEXTURE_1D)
            glTexImage1D(GL_TEXTURE_1D, 0, formats[f], 37, 0, format, GL_UNSIGNED_BYTE, src);
        else
            glTexImage2D(GL_TEXTURE_2D, 0, formats[f], 16, 11, 0, format, GL_UNSIGNED_BYTE,
                         src);
        fc_error(h, l);
        level_params(h, l, target, 0);
        get_image(h, l, target, 0, GL_RGBA, target == GL_TEXTURE_1D ? 37 : 16,
                  target == GL_TEXTURE_1D ? 1 : 11);
    }
}

static void formats_rgba(fc_h *h) { formats_from(h, GL_RGBA, GL_TEXTURE_2D); }
static void formats_rgb(fc_h *h) { formats_from(h, GL_RGB, GL_TEXTURE_2D); }
static void formats_lum(fc_h *h) { formats_from(h, GL_LUMINANCE, GL_TEXTURE_2D); }
static void formats_la(fc_h *h) { formats_from(h, GL_LUMINANCE_ALPHA, GL_TEXTURE_2D); }
static void formats_alpha(fc_h *h) { formats_from(h, GL_ALPHA, GL_TEXTURE_2D); }
static void formats_1d(fc_h *h) { formats_from(h, GL_RGBA, GL_TEXTURE_1D); }

/* glGetTexImage as RGB and BGRA; pack alignment and row length. */
static void readback_formats(fc_h *h)
{
    fill_src(3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    get_image(h, "rgba", GL_TEXTURE_2D, 0, GL_RGBA, 5, 3);
    get_image(h, "rgb", GL_TEXTURE_2D, 0, GL_RGB, 5, 3);
    get_image(h, "bgra", GL_TEXTURE_2D, 0, GL_BGRA, 5, 3);
    get_image(h, "bgr", GL_TEXTURE_2D, 0, GL_BGR, 5, 3);
    glPixelStorei(GL_PACK_ROW_LENGTH, 7);
    glPixelStorei(GL_PACK_SKIP_ROWS, 1);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
    get_image(h, "rgb row length", GL_TEXTURE_2D, 0, GL_RGB, 9, 5);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    get_image(h, "rgb align 8", GL_TEXTURE_2D, 0, GL_RGB, 8, 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 src);
    get_image(h, "la as bgr", GL_TEXTURE_2D, 0, GL_BGR, 8, 3);
    /* levels that do not exist read nothing */
    get_image(h, "missing level", GL_TEXTURE_2D, 3, GL_RGBA, 4, 4);
    get_image(h, "missing 1d", GL_TEXTURE_1D, 0, GL_RGBA, 4, 1);
    get_image(h, "3d", GL_TEXTURE_3D, 0, GL_RGBA, 4, 1);
}

/* The pixel store state applies to the upload. */
static void unpack_store(fc_h *h)
{
    fill_src(9);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 5, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, src);
    fc_error(h, "align 8");
    get_image(h, "align 8", GL_TEXTURE_2D, 0, GL_RGBA, 5, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 9);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    get_image(h, "row length skip", GL_TEXTURE_2D, 0, GL_RGBA, 5, 4);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE, 6, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, src);
    get_image(h, "1d skip", GL_TEXTURE_1D, 0, GL_RGBA, 6, 1);
}

/* Border 1: the oracle strips it (the inner image, border 0). */
static void border(fc_h *h)
{
    fill_src(5);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 6, 5, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    fc_error(h, "6x5");
    level_params(h, "6x5", GL_TEXTURE_2D, 0);
    get_image(h, "6x5", GL_TEXTURE_2D, 0, GL_RGBA, 4, 3);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGB5, 4, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    fc_error(h, "4x2");
    level_params(h, "4x2", GL_TEXTURE_2D, 1);
    get_image(h, "4x2", GL_TEXTURE_2D, 1, GL_RGBA, 2, 2);
    glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    fc_error(h, "2x2");
    level_params(h, "2x2", GL_TEXTURE_2D, 2);
    glTexImage2D(GL_TEXTURE_2D, 3, GL_RGBA, 1, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    fc_error(h, "1x3");
    glTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE_ALPHA, 10, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    fc_error(h, "1d");
    level_params(h, "1d", GL_TEXTURE_1D, 0);
    get_image(h, "1d", GL_TEXTURE_1D, 0, GL_RGBA, 8, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 8);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    get_image(h, "row length", GL_TEXTURE_2D, 0, GL_RGBA, 3, 2);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16386, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "too wide");
    glTexImage2D(GL_TEXTURE_2D, 14, GL_RGBA, 3, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    fc_error(h, "level 14 3x3");
    level_params(h, "level 14", GL_TEXTURE_2D, 14);
}

/* NULL data: the oracle's storage starts zeroed. */
static void null_data(fc_h *h)
{
    for (size_t f = 0; f < NFORMATS; f += 3) {
        char l[64];
        snprintf(l, sizeof l, "0x%04x", (unsigned)formats[f]);
        glTexImage2D(GL_TEXTURE_2D, 0, formats[f], 4, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        fc_error(h, l);
        get_image(h, l, GL_TEXTURE_2D, 0, GL_RGBA, 4, 3);
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "0x0");
    level_params(h, "0x0", GL_TEXTURE_2D, 0);
    get_image(h, "0x0", GL_TEXTURE_2D, 0, GL_RGBA, 1, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    level_params(h, "4x0", GL_TEXTURE_2D, 0);
    glTexImage1D(GL_TEXTURE_1D, 2, GL_ALPHA, 0, 0, GL_ALPHA, GL_UNSIGNED_BYTE, NULL);
    level_params(h, "1d 0", GL_TEXTURE_1D, 2);
}

/* Unsized internal formats take the client data's packed format. */
static void packed_types(fc_h *h)
{
    static const struct { GLint in; GLenum f, t; } c[] = {
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4 },
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV },
        { GL_RGBA, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV },
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1 },
        { GL_RGBA, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV },
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV },
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2 },
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT },
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_INT },
        { GL_RGBA, GL_RGBA, GL_FLOAT },
        { GL_RGBA, GL_BGRA, GL_UNSIGNED_BYTE },
        { GL_RGB, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1 },
        { GL_RGB, GL_RGB, GL_UNSIGNED_SHORT_5_6_5 },
        { GL_RGB, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV },
        { GL_RGB, GL_RGB, GL_UNSIGNED_BYTE_3_3_2 },
        { GL_RGB, GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV },
        { GL_RGB, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV },
        { GL_RGB, GL_RGB, GL_UNSIGNED_SHORT },
        { GL_LUMINANCE, GL_LUMINANCE, GL_UNSIGNED_SHORT },
        { GL_ALPHA, GL_ALPHA, GL_UNSIGNED_SHORT },
        { GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT },
        { GL_INTENSITY, GL_LUMINANCE, GL_UNSIGNED_SHORT },
        { 4, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4 },
        { 3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5 },
        { GL_RGBA8, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4 },
        { GL_LUMINANCE, GL_RGBA, GL_UNSIGNED_SHORT },
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        char l[64];
        snprintf(l, sizeof l, "%zu", i);
        glTexImage2D(GL_TEXTURE_2D, 0, c[i].in, 4, 4, 0, c[i].f, c[i].t, NULL);
        fc_error(h, l);
        level_params(h, l, GL_TEXTURE_2D, 0);
    }
}

/* Proxies: fields as given (border kept) or cleared, never an error
 * for sizes; GL_TEXTURE_2D untouched. */
static void proxy(fc_h *h)
{
    static const struct { GLint in; int level, w, hh, b; } c[] = {
        { GL_RGBA8, 0, 16384, 16384, 0 }, { GL_RGBA16, 0, 16384, 16384, 0 },
        { GL_RGBA16, 0, 16384, 8192, 0 }, { GL_RGB16, 0, 16384, 16384, 0 },
        { GL_RGB12, 0, 16384, 16383, 0 }, { GL_RGB10, 0, 16384, 16384, 0 },
        { GL_LUMINANCE16_ALPHA16, 0, 16384, 16384, 0 }, { GL_RGBA, 0, 16385, 1, 0 },
        { GL_RGBA, 0, 16386, 1, 1 }, { GL_RGBA, 0, 6, 6, 1 }, { GL_RGBA, 3, 2049, 1, 0 },
        { GL_RGBA, 3, 2048, 2048, 0 }, { GL_RGBA, 14, 1, 1, 0 }, { GL_RGBA, 14, 2, 1, 0 },
        { GL_RGBA, 14, 3, 3, 1 }, { GL_RGBA, 0, 1, 1, 1 }, { GL_INTENSITY12, 2, 5, 7, 0 },
        { GL_RGBA, 0, 0, 0, 0 }, { GL_R3_G3_B2, 1, 0, 9, 0 },
    };
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        char l[64];
        snprintf(l, sizeof l, "2d %zu", i);
        glTexImage2D(GL_PROXY_TEXTURE_2D, c[i].level, c[i].in, c[i].w, c[i].hh, c[i].b,
                     GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        fc_error(h, l);
        level_params(h, l, GL_PROXY_TEXTURE_2D, c[i].level);
        snprintf(l, sizeof l, "1d %zu", i);
        glTexImage1D(GL_PROXY_TEXTURE_1D, c[i].level, c[i].in, c[i].w, c[i].b, GL_RGBA,
                     GL_UNSIGNED_BYTE, NULL);
        fc_error(h, l);
        level_params(h, l, GL_PROXY_TEXTURE_1D, c[i].level);
    }
    level_params(h, "real 2d", GL_TEXTURE_2D, 0);
    /* errors other than sizes are raised for proxies too */
    glTexImage2D(GL_PROXY_TEXTURE_2D, 15, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "level 15");
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, -1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "negative");
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, 99, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "internal");
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 1, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "border 2");
    glTexImage2D(GL_PROXY_TEXTURE_1D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "1d proxy in 2d");
    glTexImage1D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "2d proxy in 1d");
    level_params(h, "after errors", GL_PROXY_TEXTURE_2D, 0);
    /* proxies are not sub-image or copy targets */
    glTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    fc_error(h, "sub proxy");
    glCopyTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 0, 0, 1, 1, 0);
    fc_error(h, "copy proxy");
    get_image(h, "get proxy", GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 1, 1);
}

/* Images llvmpipe cannot create: GL_OUT_OF_MEMORY, nothing changed. */
static void out_of_memory(fc_h *h)
{
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16, 16384, 16384, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 NULL);
    fc_error(h, "rgba16 16384^2");
    level_params(h, "after", GL_TEXTURE_2D, 0);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16, 16384, 16384, 0, GL_RGB, GL_UNSIGNED_BYTE, src);
    fc_error(h, "rgb16 16384^2");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16384, 16384, 0, GL_RGBA, GL_UNSIGNED_SHORT,
                 NULL);
    fc_error(h, "rgba ushort 16384^2");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA12, 16384, 16384, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                 NULL);
    fc_error(h, "rgba12 16384^2 border");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16, 16385, 16385, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 NULL);
    fc_error(h, "too large first");
    level_params(h, "end", GL_TEXTURE_2D, 0);
    get_image(h, "end", GL_TEXTURE_2D, 0, GL_RGBA, 2, 2);
}

/* Every glTexImage error, in Mesa's order (several wrong at once). */
static void tex_image_errors(fc_h *h)
{
    static const GLubyte px[64] = { 1, 2, 3, 4 };
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    fc_error(h, "valid");
#define E(label, call) do { call; fc_error(h, label); } while (0)
    E("target 3d", glTexImage2D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("target 1d", glTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("target 2d in 1d", glTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("target env", glTexImage1D(GL_TEXTURE_ENV, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("target before level", glTexImage2D(GL_TEXTURE_3D, -1, 99, -1, 1, 2, 0x1234, GL_UNSIGNED_BYTE, px));
    E("level -1", glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("level 15", glTexImage2D(GL_TEXTURE_2D, 15, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("level 14 2x1", glTexImage2D(GL_TEXTURE_2D, 14, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("level 14 1x1", glTexImage2D(GL_TEXTURE_2D, 14, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("level first", glTexImage2D(GL_TEXTURE_2D, -1, 99, -1, 1, 2, 0x1234, 0x1234, px));
    E("border 2", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("border -1", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, -1, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("border before size", glTexImage2D(GL_TEXTURE_2D, 0, 99, -1, 1, 2, 0x1234, GL_UNSIGNED_BYTE, px));
    E("border 1 width 1", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("width -1", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("height -1", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, -1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("size before format", glTexImage2D(GL_TEXTURE_2D, 0, 99, -1, 1, 0, 0x1234, GL_UNSIGNED_BYTE, px));
    E("width 16385", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16385, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
    E("1d width 16385", glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16385, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
    E("level 3 2049", glTexImage2D(GL_TEXTURE_2D, 3, GL_RGBA, 4, 2049, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
    E("format", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, 0x1234, GL_UNSIGNED_BYTE, px));
    E("type", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, 0x1234, px));
    E("format intensity", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_INTENSITY, GL_UNSIGNED_BYTE, px));
    E("bitmap rgba", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_BITMAP, px));
    E("rgb 4444", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, px));
    E("rgba 565", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, px));
    E("lum 5551", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_SHORT_5_5_5_1, px));
    E("format before internal", glTexImage2D(GL_TEXTURE_2D, 0, 99, 1, 1, 0, 0x1234, GL_UNSIGNED_BYTE, px));
    E("internal 0", glTexImage2D(GL_TEXTURE_2D, 0, 0, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("internal 5", glTexImage2D(GL_TEXTURE_2D, 0, 5, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("internal bgra", glTexImage2D(GL_TEXTURE_2D, 0, GL_BGRA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("internal 99", glTexImage2D(GL_TEXTURE_2D, 0, 99, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("internal color index", glTexImage2D(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("format depth", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, px));
    E("format stencil", glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, px));
    E("1d level 15", glTexImage1D(GL_TEXTURE_1D, 15, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("1d border 3", glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 3, GL_RGBA, GL_UNSIGNED_BYTE, px));
    E("1d internal", glTexImage1D(GL_TEXTURE_1D, 0, 77, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
    glBegin(GL_POINTS);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glEnd();
    fc_error(h, "inside begin/end");
    level_params(h, "unchanged", GL_TEXTURE_2D, 0);
    get_image(h, "unchanged", GL_TEXTURE_2D, 0, GL_RGBA, 1, 1);
    level_params(h, "level 14", GL_TEXTURE_2D, 14);
#undef E
}

/* glTexSubImage1D/2D: regions, formats, store state, errors. */
static void sub_image(fc_h *h)
{
    fill_src(11);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 6, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 1, 3, 4, GL_RGB, GL_UNSIGNED_BYTE, src + 100);
    fc_error(h, "rgb region");
    get_image(h, "rgb region", GL_TEXTURE_2D, 0, GL_RGBA, 8, 6);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 5, 8, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, src + 7);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 7, 0, 1, 6, GL_ALPHA, GL_UNSIGNED_BYTE, src + 9);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 0, 2, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "edges");
    get_image(h, "edges", GL_TEXTURE_2D, 0, GL_RGBA, 8, 6);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 10);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 4, 3, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    get_image(h, "store", GL_TEXTURE_2D, 0, GL_RGBA, 8, 6);
    /* quantized formats */
    static const GLint q[] = { GL_RGB5, GL_RGBA4, GL_RGB5_A1, GL_R3_G3_B2, GL_LUMINANCE4_ALPHA4,
                               GL_RGB10_A2, GL_INTENSITY, GL_ALPHA12 };
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
        char l[64];
        snprintf(l, sizeof l, "fmt 0x%04x", (unsigned)q[i]);
        glTexImage2D(GL_TEXTURE_2D, 1, q[i], 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        glTexSubImage2D(GL_TEXTURE_2D, 1, 1, 0, 3, 3, GL_RGBA, GL_UNSIGNED_BYTE, src + 40);
        fc_error(h, l);
        get_image(h, l, GL_TEXTURE_2D, 1, GL_RGBA, 4, 4);
    }
    /* 1D */
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 9, 0, GL_RGB, GL_UNSIGNED_BYTE, src);
    glTexSubImage1D(GL_TEXTURE_1D, 0, 4, 5, GL_RGBA, GL_UNSIGNED_BYTE, src + 200);
    fc_error(h, "1d");
    get_image(h, "1d", GL_TEXTURE_1D, 0, GL_RGBA, 9, 1);
    /* border-stripped image: offsets from 0 */
    glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexSubImage2D(GL_TEXTURE_2D, 2, -1, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, src);
    fc_error(h, "border offset -1");
    glTexSubImage2D(GL_TEXTURE_2D, 2, 2, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, src + 300);
    get_image(h, "border", GL_TEXTURE_2D, 2, GL_RGBA, 4, 4);
    /* errors */
#define E(label, call) do { call; fc_error(h, label); } while (0)
    E("target", glTexSubImage2D(GL_TEXTURE_1D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("target 1d", glTexSubImage1D(GL_TEXTURE_2D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("level -1", glTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("level 15", glTexSubImage2D(GL_TEXTURE_2D, 15, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("no level", glTexSubImage2D(GL_TEXTURE_2D, 5, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("width -1", glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("negative before level", glTexSubImage2D(GL_TEXTURE_2D, 5, 0, 0, 1, -1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("format", glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, src));
    E("type", glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_BITMAP, src));
    E("packed", glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, src));
    E("depth", glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, src));
    E("xoffset -1", glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("x past", glTexSubImage2D(GL_TEXTURE_2D, 0, 5, 0, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("y past", glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 6, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("y -1", glTexSubImage2D(GL_TEXTURE_2D, 0, 0, -1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("format before size", glTexSubImage2D(GL_TEXTURE_2D, 0, 50, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, src));
    E("1d past", glTexSubImage1D(GL_TEXTURE_1D, 0, 8, 2, GL_RGBA, GL_UNSIGNED_BYTE, src));
    E("1d yoffset ignored", glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, src));
    glBegin(GL_POINTS);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glEnd();
    fc_error(h, "inside begin/end");
#undef E
    get_image(h, "final", GL_TEXTURE_2D, 0, GL_RGBA, 8, 6);
}

/* A picture in the colour buffer to copy from. */
static void draw_picture(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 1); glVertex2f(0, 0);
    glColor4f(0, 1, 0, 0.5f); glVertex2f(32, 4);
    glColor4f(0, 0, 1, 0.25f); glVertex2f(8, 24);
    glColor4f(1, 1, 0, 0.75f); glVertex2f(30, 30);
    glColor4f(0, 1, 1, 0.1f); glVertex2f(2, 31);
    glColor4f(1, 0, 1, 0.9f); glVertex2f(31, 10);
    glEnd();
}

static void copy_image(fc_h *h)
{
    draw_picture(h);
    fc_capture(h);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 5, 16, 12, 0);
    fc_error(h, "rgba");
    level_params(h, "rgba", GL_TEXTURE_2D, 0);
    get_image(h, "rgba", GL_TEXTURE_2D, 0, GL_RGBA, 16, 12);
    static const GLenum q[] = { GL_RGB, GL_LUMINANCE, GL_ALPHA, GL_LUMINANCE_ALPHA,
                                GL_INTENSITY, GL_RGB5, GL_RGBA4, GL_RGB5_A1, GL_RGB565,
                                GL_LUMINANCE4_ALPHA4, GL_RGB10_A2, GL_RGBA16, GL_RGB8 };
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
        char l[64];
        snprintf(l, sizeof l, "fmt 0x%04x", (unsigned)q[i]);
        glCopyTexImage2D(GL_TEXTURE_2D, 1, q[i], 7, 2, 8, 8, 0);
        fc_error(h, l);
        level_params(h, l, GL_TEXTURE_2D, 1);
        get_image(h, l, GL_TEXTURE_2D, 1, GL_RGBA, 8, 8);
    }
    /* partly outside the framebuffer: a new image keeps zeros there */
    glCopyTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, -3, 28, 8, 8, 0);
    fc_error(h, "outside");
    get_image(h, "outside", GL_TEXTURE_2D, 2, GL_RGBA, 8, 8);
    glCopyTexImage2D(GL_TEXTURE_2D, 3, GL_RGB, 29, -2, 6, 4, 0);
    get_image(h, "outside rgb", GL_TEXTURE_2D, 3, GL_RGBA, 6, 4);
    /* the same size and format again reuses the storage: texels copied
     * from outside keep their old values */
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 20, 25, 16, 12, 0);
    fc_error(h, "reuse");
    get_image(h, "reuse", GL_TEXTURE_2D, 0, GL_RGBA, 16, 12);
    glCopyTexImage2D(GL_TEXTURE_2D, 4, GL_RGBA, 100, 100, 4, 4, 0);
    get_image(h, "all outside", GL_TEXTURE_2D, 4, GL_RGBA, 4, 4);
    /* border 1 */
    glCopyTexImage2D(GL_TEXTURE_2D, 5, GL_RGBA, 4, 4, 6, 5, 1);
    fc_error(h, "border");
    level_params(h, "border", GL_TEXTURE_2D, 5);
    get_image(h, "border", GL_TEXTURE_2D, 5, GL_RGBA, 4, 3);
    /* 1D */
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 5, 9, 20, 0);
    fc_error(h, "1d");
    level_params(h, "1d", GL_TEXTURE_1D, 0);
    get_image(h, "1d", GL_TEXTURE_1D, 0, GL_RGBA, 20, 1);
    glCopyTexImage1D(GL_TEXTURE_1D, 1, GL_LUMINANCE, 25, 31, 10, 1);
    get_image(h, "1d border", GL_TEXTURE_1D, 1, GL_RGBA, 8, 1);
    /* sub images */
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 10, 10, 5, 4);
    fc_error(h, "sub");
    get_image(h, "sub", GL_TEXTURE_2D, 0, GL_RGBA, 16, 12);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -4, 30, 8, 8);
    fc_error(h, "sub outside");
    get_image(h, "sub outside", GL_TEXTURE_2D, 0, GL_RGBA, 16, 12);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 1, 1, 1, 3, 3, 4, 4);
    get_image(h, "sub quantized", GL_TEXTURE_2D, 1, GL_RGBA, 8, 8);
    glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 3, 0, 0, 7);
    fc_error(h, "sub 1d");
    get_image(h, "sub 1d", GL_TEXTURE_1D, 0, GL_RGBA, 20, 1);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 1, 1, 0, 3);
    fc_error(h, "sub empty");
    /* errors */
#define E(label, call) do { call; fc_error(h, label); } while (0)
    E("copy target", glCopyTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 1, 1, 0));
    E("copy target 3d", glCopyTexImage2D(GL_TEXTURE_3D, 0, GL_RGBA, 0, 0, 1, 1, 0));
    E("copy level", glCopyTexImage2D(GL_TEXTURE_2D, 15, GL_RGBA, 0, 0, 1, 1, 0));
    E("copy level -1", glCopyTexImage2D(GL_TEXTURE_2D, -1, 99, 0, 0, 1, 1, 5));
    E("copy border", glCopyTexImage2D(GL_TEXTURE_2D, 0, 99, 0, 0, 1, 1, 2));
    E("copy internal 4", glCopyTexImage2D(GL_TEXTURE_2D, 0, 4, 0, 0, 1, 1, 0));
    E("copy internal 1", glCopyTexImage1D(GL_TEXTURE_1D, 0, 1, 0, 0, 1, 0));
    E("copy internal 99", glCopyTexImage2D(GL_TEXTURE_2D, 0, 99, 0, 0, 1, 1, 0));
    E("copy internal depth", glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_COLOR_INDEX, 0, 0, 1, 1, 0));
    E("copy width -1", glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -1, 1, 0));
    E("copy width 16385", glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 16385, 1, 0));
    E("copy border 1 width 1", glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 1, 4, 1));
    E("sub target", glCopyTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1));
    E("sub level", glCopyTexSubImage2D(GL_TEXTURE_2D, 15, 0, 0, 0, 0, 1, 1));
    E("sub no image", glCopyTexSubImage2D(GL_TEXTURE_2D, 9, 0, 0, 0, 0, 1, 1));
    E("sub width -1", glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, -1, 1));
    E("sub past", glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 10, 0, 0, 0, 7, 1));
    E("sub y past", glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 11, 0, 0, 1, 2));
    E("sub offset -1", glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, -1, 0, 0, 1, 1));
    E("sub 1d past", glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 19, 0, 0, 2));
    /* (glReadBuffer(GL_NONE) then glCopyTexImage2D crashes the oracle:
     * not compared) */
    glBegin(GL_POINTS);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 1, 1, 0);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1);
    glEnd();
    fc_error(h, "inside begin/end");
#undef E
    level_params(h, "final", GL_TEXTURE_2D, 0);
    get_image(h, "final", GL_TEXTURE_2D, 0, GL_RGBA, 16, 12);
}

/* Every 8-bit value of each channel copied into the small formats: the
 * oracle truncates into its 5-5-5(-1) and 5-6-5 formats and rounds into
 * 4-4-4-4, 4-4 luminance/alpha and 10-10-10-2. */
static void copy_values(fc_h *h, const GLint *fmts, size_t n)
{
    fc_pixel_ortho(h);
    glBegin(GL_POINTS);
    for (int i = 0; i < 256; i++) {
        glColor4ub((GLubyte)i, (GLubyte)(255 - i), (GLubyte)(i * 7), (GLubyte)(i * 3 + 1));
        glVertex2f((float)i + 0.5f, 0.5f);
    }
    glEnd();
    fc_capture(h);
    for (size_t k = 0; k < n; k++) {
        char l[64];
        snprintf(l, sizeof l, "fmt 0x%04x", (unsigned)fmts[k]);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, fmts[k], 0, 0, 256, 1, 0);
        fc_error(h, l);
        memset(readback, 0xA5, sizeof readback);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
        fc_blob(h, l, readback, 4 * 256);
        /* a sub-image copy converts the same way */
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 128, 0, 128, 1);
        memset(readback, 0xA5, sizeof readback);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
        fc_blob(h, "sub", readback, 4 * 256);
    }
}

static void copy_values_small(fc_h *h)
{
    static const GLint f[] = { GL_RGB5, GL_RGB5_A1, GL_RGB565, GL_RGBA4, GL_RGBA2, GL_RGB4,
                               GL_LUMINANCE4_ALPHA4, GL_RGB10_A2, GL_RGB10, GL_ALPHA4,
                               GL_INTENSITY16, GL_LUMINANCE6_ALPHA2 };
    copy_values(h, f, sizeof f / sizeof f[0]);
}

static void copy_values_r3g3b2(fc_h *h)
{
    static const GLint f[] = { GL_R3_G3_B2 };
    copy_values(h, f, 1);
}

/* Display lists: glTexImage and glTexSubImage copy the client image at
 * compile time under the unpack state of then (replayed with the default
 * packing), proxies execute at once, copies replay from the colour
 * buffer of the call, queries execute at once. */
static void lists(fc_h *h)
{
    fill_src(31);
    GLuint l = glGenLists(4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 6);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glNewList(l, GL_COMPILE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5_A1, 4, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_LUMINANCE, 2, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, src);
    glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_ALPHA8, 5, 0, GL_ALPHA, GL_UNSIGNED_BYTE, src);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, src + 50);
    glTexSubImage1D(GL_TEXTURE_1D, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, src + 90);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGB4, 16, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 7, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexSubImage2D(GL_TEXTURE_2D, 9, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, src);
    level_params(h, "proxy while compiling", GL_PROXY_TEXTURE_2D, 0);
    level_params(h, "proxy 1d while compiling", GL_PROXY_TEXTURE_1D, 0);
    level_params(h, "2d while compiling", GL_TEXTURE_2D, 0);
    get_image(h, "get while compiling", GL_TEXTURE_2D, 0, GL_RGBA, 1, 1);
    glEndList();
    fc_error(h, "compiled");
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    memset(src, 0, 256);   /* the list holds its own copy */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glCallList(l);
    fc_error(h, "called");
    level_params(h, "l0", GL_TEXTURE_2D, 0);
    get_image(h, "l0", GL_TEXTURE_2D, 0, GL_RGBA, 4, 3);
    get_image(h, "l1", GL_TEXTURE_2D, 1, GL_RGBA, 2, 1);
    get_image(h, "l2", GL_TEXTURE_2D, 2, GL_RGBA, 1, 1);
    get_image(h, "1d", GL_TEXTURE_1D, 0, GL_RGBA, 5, 1);
    fc_get_integer(h, "unpack alignment", GL_UNPACK_ALIGNMENT, 1);
    fc_get_integer(h, "unpack row length", GL_UNPACK_ROW_LENGTH, 1);
    /* swapped bytes are undone at compile time */
    static const GLushort us[8] = { 0x1234, 0xfedc, 0x00ff, 0x8001, 0x4321, 0x0102, 0x7f80, 9 };
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    glTexImage2D(GL_TEXTURE_2D, 3, GL_LUMINANCE, 2, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, us);
    glEndList();
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    get_image(h, "executed", GL_TEXTURE_2D, 3, GL_RGBA, 2, 2);
    glTexImage2D(GL_TEXTURE_2D, 3, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glCallList(l + 1);
    get_image(h, "replayed", GL_TEXTURE_2D, 3, GL_RGBA, 2, 2);
    /* copies */
    draw_picture(h);
    glNewList(l + 2, GL_COMPILE);
    glCopyTexImage2D(GL_TEXTURE_2D, 4, GL_RGB, 4, 4, 8, 8, 0);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 4, 2, 2, 20, 20, 4, 4);
    glCopyTexImage1D(GL_TEXTURE_1D, 1, GL_RGBA, 3, 3, 9, 0);
    glCopyTexSubImage1D(GL_TEXTURE_1D, 1, 1, 10, 10, 4);
    glCopyTexImage2D(GL_TEXTURE_2D, 4, 3, 0, 0, 8, 8, 0);
    glEndList();
    fc_error(h, "copies compiled");
    level_params(h, "copy before call", GL_TEXTURE_2D, 4);
    fc_capture(h);
    glCallList(l + 2);
    fc_error(h, "copies called");
    get_image(h, "copy 2d", GL_TEXTURE_2D, 4, GL_RGBA, 8, 8);
    get_image(h, "copy 1d", GL_TEXTURE_1D, 1, GL_RGBA, 9, 1);
    /* glBegin while compiling: the image calls are errors, not compiled */
    glNewList(l + 3, GL_COMPILE);
    glBegin(GL_POINTS);
    glTexImage2D(GL_TEXTURE_2D, 5, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 4, 0, 0, 0, 0, 1, 1);
    glEnd();
    glEndList();
    fc_error(h, "inside begin compiled");
    glCallList(l + 3);
    fc_error(h, "inside begin called");
    level_params(h, "level 5", GL_TEXTURE_2D, 5);
    glDeleteLists(l, 4);
    fc_error(h, "deleted");
}

/* Texture objects shared through OSMesaCreateContext's sharelist: names,
 * images and the default objects are shared, proxies are not; a context
 * that does not share has its own.  Deleting an object in one context
 * unbinds it there only. */
static void sharing(fc_h *h)
{
    fill_src(41);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    GLuint t[2];
    glGenTextures(2, t);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 5, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 20);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 7, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    static GLubyte buf2[8 * 8 * 4];
    OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, fc_context(h));
    OSMesaContext alone = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    fc_value(h, "contexts", shared != NULL && alone != NULL);
    if (!shared || !alone)
        return;
    OSMesaMakeCurrent(shared, buf2, GL_UNSIGNED_BYTE, 8, 8);
    level_params(h, "shared default", GL_TEXTURE_2D, 0);
    get_image(h, "shared default", GL_TEXTURE_2D, 0, GL_RGBA, 3, 1);
    level_params(h, "shared proxy", GL_PROXY_TEXTURE_2D, 0);
    fc_value(h, "shared istexture t0", glIsTexture(t[0]));
    fc_value(h, "shared istexture t1", glIsTexture(t[1]));
    glBindTexture(GL_TEXTURE_2D, t[0]);
    level_params(h, "shared t0", GL_TEXTURE_2D, 0);
    get_image(h, "shared t0", GL_TEXTURE_2D, 0, GL_RGBA, 5, 2);
    GLuint n = 0;
    glGenTextures(1, &n);
    fc_value(h, "shared gen", n);
    glBindTexture(GL_TEXTURE_2D, n);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE4_ALPHA4, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, src + 60);
    glDeleteTextures(1, &t[1]);
    fc_get_integer(h, "shared binding", GL_TEXTURE_BINDING_2D, 1);
    fc_error(h, "shared");
    OSMesaMakeCurrent(alone, buf2, GL_UNSIGNED_BYTE, 8, 8);
    level_params(h, "alone default", GL_TEXTURE_2D, 0);
    fc_value(h, "alone istexture t0", glIsTexture(t[0]));
    glGenTextures(1, &n);
    fc_value(h, "alone gen", n);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 8, 8);
    get_image(h, "first t0", GL_TEXTURE_2D, 0, GL_RGBA, 5, 2);
    fc_value(h, "first istexture t1", glIsTexture(t[1]));
    glBindTexture(GL_TEXTURE_2D, 3);
    level_params(h, "first 3", GL_TEXTURE_2D, 0);
    OSMesaDestroyContext(shared);
    OSMesaDestroyContext(alone);
    level_params(h, "after destroy", GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    get_image(h, "default after destroy", GL_TEXTURE_2D, 0, GL_RGBA, 3, 1);
    fc_error(h, "end");
}

/* An object deleted in one context while bound in another stays that
 * context's binding (Mesa's reference count) with its images, without a
 * name; rebinding the name makes a new object. */
static void sharing_delete_bound(fc_h *h)
{
    fill_src(43);
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 5, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    static GLubyte buf2[8 * 8 * 4];
    OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, fc_context(h));
    fc_value(h, "context", shared != NULL);
    if (!shared)
        return;
    OSMesaMakeCurrent(shared, buf2, GL_UNSIGNED_BYTE, 8, 8);
    glDeleteTextures(1, &t);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 8, 8);
    fc_get_integer(h, "binding", GL_TEXTURE_BINDING_2D, 1);
    fc_value(h, "istexture", glIsTexture(t));
    level_params(h, "orphan", GL_TEXTURE_2D, 0);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 9, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    level_params(h, "orphan respecified", GL_TEXTURE_2D, 0);
    /* a pop that finds the name bound keeps the object */
    glPushAttrib(GL_TEXTURE_BIT);
    glPopAttrib();
    level_params(h, "orphan popped", GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_2D, t);
    level_params(h, "rebound", GL_TEXTURE_2D, 0);
    /* a pop that finds another object rebinds the name: the orphan is
     * gone, the new object of the name stays */
    GLuint t2 = 0;
    glGenTextures(1, &t2);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, t2);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    OSMesaMakeCurrent(shared, buf2, GL_UNSIGNED_BYTE, 8, 8);
    glBindTexture(GL_TEXTURE_2D, t2);
    glDeleteTextures(1, &t2);
    fc_get_integer(h, "deleter's binding", GL_TEXTURE_BINDING_2D, 1);
    glBindTexture(GL_TEXTURE_2D, t2);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 8, 8);
    level_params(h, "unit 1 orphan", GL_TEXTURE_2D, 0);
    glPushAttrib(GL_TEXTURE_BIT);
    glBindTexture(GL_TEXTURE_2D, 0);
    glPopAttrib();
    fc_get_integer(h, "unit 1 popped binding", GL_TEXTURE_BINDING_2D, 1);
    level_params(h, "unit 1 popped", GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    OSMesaDestroyContext(shared);
    fc_error(h, "end");
}

/* glGetTexImage of every base format as every client format and type
 * (pixelformat's packer; luminance reads back as R, not R+G+B), with
 * pack state and SWAP_BYTES. */
static void readback_types_of(fc_h *h, const GLint *internals, size_t ni)
{
    static const GLenum fmts[] = { GL_RGBA, GL_RGB, GL_BGRA, GL_BGR, GL_ABGR_EXT, GL_RED,
                                   GL_GREEN, GL_BLUE, GL_ALPHA, GL_LUMINANCE,
                                   GL_LUMINANCE_ALPHA };
    static const GLenum types[] = { GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                    GL_UNSIGNED_INT, GL_INT, GL_FLOAT };
    static const struct { GLenum f, t; } packed[] = {
        { GL_RGB, GL_UNSIGNED_BYTE_3_3_2 }, { GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV },
        { GL_RGB, GL_UNSIGNED_SHORT_5_6_5 }, { GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV },
        { GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4 }, { GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV },
        { GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1 }, { GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV },
        { GL_RGBA, GL_UNSIGNED_INT_8_8_8_8 }, { GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV },
        { GL_RGBA, GL_UNSIGNED_INT_10_10_10_2 }, { GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV },
    };
    fill_src(51);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    static GLubyte out[4 * 4 * 5 * 3 + 64];
    for (size_t k = 0; k < ni; k++) {
        glTexImage2D(GL_TEXTURE_2D, 0, internals[k], 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
        for (size_t f = 0; f < sizeof fmts / sizeof fmts[0]; f++)
            for (size_t t = 0; t < sizeof types / sizeof types[0]; t++) {
                char l[96];
                snprintf(l, sizeof l, "0x%04x 0x%04x 0x%04x", (unsigned)internals[k],
                         (unsigned)fmts[f], (unsigned)types[t]);
                memset(out, 0xA5, sizeof out);
                glGetTexImage(GL_TEXTURE_2D, 0, fmts[f], types[t], out);
                fc_blob(h, l, out, sizeof out);
                fc_error(h, l);
            }
        for (size_t i = 0; i < sizeof packed / sizeof packed[0]; i++) {
            char l[96];
            snprintf(l, sizeof l, "0x%04x 0x%04x 0x%04x", (unsigned)internals[k],
                     (unsigned)packed[i].f, (unsigned)packed[i].t);
            memset(out, 0xA5, sizeof out);
            glGetTexImage(GL_TEXTURE_2D, 0, packed[i].f, packed[i].t, out);
            fc_blob(h, l, out, sizeof out);
            fc_error(h, l);
        }
        /* pack state */
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
        glPixelStorei(GL_PACK_ALIGNMENT, 8);
        glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
        memset(out, 0xA5, sizeof out);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT, out);
        fc_blob(h, "swap", out, sizeof out);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    }
}

static void readback_types(fc_h *h)
{
    static const GLint f[] = { GL_RGBA8, GL_RGB8, GL_LUMINANCE8, GL_LUMINANCE8_ALPHA8,
                               GL_ALPHA8, GL_INTENSITY8 };
    readback_types_of(h, f, sizeof f / sizeof f[0]);
}

/* The formats of other than 8 bits read back: the oracle converts the
 * stored n-bit values, fixgl their 8-bit expansion (the same values for
 * 8-bit types, which image_formats_* check). */
static void readback_types_precision(fc_h *h)
{
    static const GLint f[] = { GL_RGB5, GL_RGBA4, GL_RGB5_A1, GL_R3_G3_B2,
                               GL_LUMINANCE4_ALPHA4, GL_RGB10_A2, GL_RGBA16, GL_LUMINANCE16 };
    readback_types_of(h, f, sizeof f / sizeof f[0]);
}

/* Uploads of float, 16-bit, packed and transfer-scaled data into the
 * formats of other than 8 bits per channel, read back as float and
 * 16-bit: the oracle converts the client data straight to the stored
 * precision (texstore: RGBA float and transfer results through
 * _mesa_pack_float_rgba_row, RGBA ubyte through _mesa_pack_ubyte_rgba_row
 * even into 10-bit fields, 16-bit arrays channel by channel). */
static void store_precision(fc_h *h)
{
    static const GLint internals[] = {
        GL_RGB10_A2, GL_RGB10, GL_RGBA16, GL_RGB12, GL_LUMINANCE16, GL_LUMINANCE12_ALPHA4,
        GL_INTENSITY16, GL_ALPHA12, GL_RGB5_A1, GL_RGBA4, GL_R3_G3_B2, GL_RGB5,
        GL_LUMINANCE4_ALPHA4, GL_RGBA2, GL_RGB565,
    };
    static const struct { GLenum f, t; } clients[] = {
        { GL_RGBA, GL_FLOAT }, { GL_RGB, GL_FLOAT }, { GL_LUMINANCE, GL_FLOAT },
        { GL_BGRA, GL_FLOAT }, { GL_RGBA, GL_UNSIGNED_SHORT },
        { GL_BGRA, GL_UNSIGNED_SHORT }, { GL_RGBA, GL_SHORT }, { GL_RGBA, GL_UNSIGNED_INT },
        { GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV }, { GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1 },
        { GL_RGB, GL_UNSIGNED_BYTE }, { GL_RGBA, GL_UNSIGNED_BYTE },
        { GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE },
    };
    static GLfloat fsrc[4 * 7 * 5];
    for (size_t i = 0; i < sizeof fsrc / sizeof fsrc[0]; i++)
        fsrc[i] = (float)((i * 7919u) % 1000u) / 999.0f * 1.2f - 0.1f;
    fill_src(71);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    static GLubyte out[4 * 4 * 7 * 5 + 64];
    for (size_t k = 0; k < sizeof internals / sizeof internals[0]; k++) {
        for (size_t c = 0; c <= sizeof clients / sizeof clients[0]; c++) {
            /* the last pass: RGBA ubyte under a transfer scale (float path) */
            const bool scaled = c == sizeof clients / sizeof clients[0];
            const GLenum f = scaled ? GL_RGB : clients[c].f;
            const GLenum t = scaled ? GL_UNSIGNED_BYTE : clients[c].t;
            if (scaled)
                glPixelTransferf(GL_GREEN_SCALE, 0.7f);
            const void *data = t == GL_FLOAT ? (const void *)fsrc : (const void *)src;
            glTexImage2D(GL_TEXTURE_2D, 0, internals[k], 7, 5, 0, f, t, data);
            if (scaled)
                glPixelTransferf(GL_GREEN_SCALE, 1.0f);
            char l[96];
            snprintf(l, sizeof l, "0x%04x 0x%04x 0x%04x", (unsigned)internals[k], (unsigned)f,
                     (unsigned)t);
            fc_error(h, l);
            memset(out, 0xA5, sizeof out);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
            fc_blob(h, l, out, sizeof out);
            memset(out, 0xA5, sizeof out);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, out);
            snprintf(l, sizeof l, "0x%04x 0x%04x 0x%04x ushort", (unsigned)internals[k],
                     (unsigned)f, (unsigned)t);
            fc_blob(h, l, out, sizeof out);
            /* a sub-image of float data over it */
            glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 1, 3, 2, GL_RGBA, GL_FLOAT, fsrc + 40);
            memset(out, 0xA5, sizeof out);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
            snprintf(l, sizeof l, "0x%04x 0x%04x 0x%04x sub", (unsigned)internals[k],
                     (unsigned)f, (unsigned)t);
            fc_blob(h, l, out, sizeof out);
            fc_error(h, l);
        }
    }
}

/* ------------------------------------------------------------------ */
/* GL_GENERATE_MIPMAP: the oracle regenerates the levels below the base
 * by util_gen_mipmap's bilinear blits (texture/genmipmap_*). */

/* Every level of the bound target that exists, as RGBA bytes, with its
 * level parameters. */
static void get_levels(fc_h *h, const char *label, GLenum target)
{
    for (GLint l = 0; l < 8; l++) {
        GLint w = 0, hh = 0;
        glGetTexLevelParameteriv(target, l, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(target, l, GL_TEXTURE_HEIGHT, &hh);
        char m[96];
        snprintf(m, sizeof m, "%s L%d", label, (int)l);
        fc_value(h, m, (long long)w * 1000 + hh);
        if (w == 0 || w > 64 || hh > 64)
            continue;
        level_params(h, m, target, l);
        get_image(h, m, target, l, GL_RGBA, w, hh);
        /* the levels after a chain's 1x1 end keep older images, which
         * the oracle reads back from another resource (not modelled) */
        if (w == 1 && hh == 1)
            break;
    }
}

/* A minified textured quad per filter, then the frame. */
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
        const float sz = 5.0f + (float)m * 3.0f;
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0); glVertex2f(x, y);
        glTexCoord2f(1, 0); glVertex2f(x + sz, y);
        glTexCoord2f(1, 1); glVertex2f(x + sz, y + sz);
        glTexCoord2f(0, 1); glVertex2f(x, y + sz);
        glEnd();
    }
    glDisable(target);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
    fc_capture(h);
}

/* 2D, every 8-bit base format, power-of-two and other sizes */
static void genmipmap_2d(fc_h *h)
{
    static const GLint internals[] = { GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA,
                                       GL_ALPHA, GL_INTENSITY, GL_RGBA8 };
    static const int sizes[][2] = { { 16, 16 }, { 13, 9 }, { 8, 3 }, { 5, 12 }, { 1, 7 } };
    fill_src(81);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    for (size_t k = 0; k < sizeof internals / sizeof internals[0]; k++)
        for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++) {
            if (k != 0 && z > 1)
                continue;
            glTexImage2D(GL_TEXTURE_2D, 0, internals[k], sizes[z][0], sizes[z][1], 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, src);
            char l[64];
            snprintf(l, sizeof l, "0x%04x %dx%d", (unsigned)internals[k], sizes[z][0],
                     sizes[z][1]);
            fc_error(h, l);
            get_levels(h, l, GL_TEXTURE_2D);
            if (z == 1)
                draw_minified(h, GL_TEXTURE_2D);
        }
}

/* 1D */
static void genmipmap_1d(fc_h *h)
{
    fill_src(82);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_1D, GL_GENERATE_MIPMAP, GL_TRUE);
    static const int widths[] = { 32, 37, 6 };
    for (size_t z = 0; z < 3; z++) {
        glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, widths[z], 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
        char l[32];
        snprintf(l, sizeof l, "1d %d", widths[z]);
        get_levels(h, l, GL_TEXTURE_1D);
        draw_minified(h, GL_TEXTURE_1D);
    }
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 11, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 100);
    get_levels(h, "1d rgb", GL_TEXTURE_1D);
}

/* Which calls regenerate: glTexSubImage of the base level, not of another
 * level; BASE_LEVEL and MAX_LEVEL bound the chain; the flag off keeps the
 * levels; glCopyTexImage / glCopyTexSubImage of the base level; a
 * display list replays it. */
static void genmipmap_calls(fc_h *h)
{
    fill_src(83);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, src + 500);
    get_levels(h, "sub base", GL_TEXTURE_2D);
    glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, src + 900);
    get_levels(h, "sub level 1", GL_TEXTURE_2D);
    /* NULL data still regenerates (from the zeroed image) */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    get_levels(h, "null", GL_TEXTURE_2D);
    /* base level 1, max level 3 */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    get_levels(h, "level 0 not base", GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 300);
    get_levels(h, "base 1 max 3", GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 700);
    get_levels(h, "base 1 max 1", GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
    /* off: nothing regenerates */
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 1000);
    get_levels(h, "off", GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    /* copies from a picture */
    draw_picture(h);
    fc_capture(h);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 5, 16, 12, 0);
    get_levels(h, "copy", GL_TEXTURE_2D);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 2, 20, 18, 8, 8);
    get_levels(h, "copy sub", GL_TEXTURE_2D);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 7, 16, 12, 0);   /* reuses the storage */
    get_levels(h, "copy reuse", GL_TEXTURE_2D);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 1, 1, 9, 6, 0);
    get_levels(h, "copy lum", GL_TEXTURE_2D);
    /* a display list */
    const GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 64);
    glEndList();
    glCallList(list);
    get_levels(h, "list", GL_TEXTURE_2D);
    glDeleteLists(list, 1);
    fc_error(h, "end");
}

/* The formats of other than 8 bits per channel */
static void genmipmap_formats(fc_h *h)
{
    static const GLint internals[] = { GL_RGB5_A1, GL_RGBA4, GL_RGB565, GL_R3_G3_B2,
                                       GL_LUMINANCE4_ALPHA4, GL_RGB10_A2, GL_RGBA16,
                                       GL_LUMINANCE16, GL_ALPHA16, GL_INTENSITY16 };
    fill_src(84);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    for (size_t k = 0; k < sizeof internals / sizeof internals[0]; k++) {
        glTexImage2D(GL_TEXTURE_2D, 0, internals[k], 8, 6, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
        char l[32];
        snprintf(l, sizeof l, "0x%04x", (unsigned)internals[k]);
        get_levels(h, l, GL_TEXTURE_2D);
    }
}

/* The images as the oracle samples them: every internal format drawn
 * NEAREST with GL_REPLACE and GL_MODULATE (a 4x4 texture on a 6x6 cell;
 * each texel at least one pixel), then images made by glCopyTexImage,
 * glTexSubImage and a stripped border. */
static void draw_cell(int i, int cols)
{
    const float x = (float)(i % cols) * 6.0f, y = (float)(i / cols) * 6.0f;
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(x, y);
    glTexCoord2f(1, 0); glVertex2f(x + 6, y);
    glTexCoord2f(1, 1); glVertex2f(x + 6, y + 6);
    glTexCoord2f(0, 1); glVertex2f(x, y + 6);
    glEnd();
}

static bool wide_format(GLint f)
{
    switch (f) {
    case GL_ALPHA12: case GL_ALPHA16: case GL_LUMINANCE12: case GL_LUMINANCE16:
    case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12: case GL_LUMINANCE16_ALPHA16:
    case GL_INTENSITY12: case GL_INTENSITY16: case GL_RGB10: case GL_RGB12: case GL_RGB16:
    case GL_RGB10_A2: case GL_RGBA12: case GL_RGBA16:
        return true;
    default:
        return false;
    }
}

/* wide: only the formats of more than 8 bits per channel (the oracle
 * samples them on its float path), else the others */
static void rendered_of(fc_h *h, bool wide)
{
    fill_src(61);
    fc_pixel_ortho(h);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    static const GLenum modes[2] = { GL_REPLACE, GL_MODULATE };
    for (int m = 0; m < 2; m++) {
        glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
        glClear(GL_COLOR_BUFFER_BIT);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)modes[m]);
        glColor4f(0.9f, 0.7f, 0.5f, 0.6f);
        int cell = 0;
        for (size_t f = 0; f < NFORMATS; f++) {
            if (wide_format(formats[f]) != wide)
                continue;
            glTexImage2D(GL_TEXTURE_2D, 0, formats[f], 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                         src + 16 * f);
            draw_cell(cell++, 8);
        }
        fc_capture(h);
    }
    /* copies, sub-images, a border */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    static const GLint cf[] = { GL_RGB5, GL_RGB5_A1, GL_RGB565, GL_RGBA4, GL_LUMINANCE,
                                GL_ALPHA, GL_INTENSITY, GL_LUMINANCE_ALPHA, GL_RGB10_A2,
                                GL_RGBA, GL_RGBA16, GL_LUMINANCE16 };
    int cell = 16;
    for (size_t i = 0; i < sizeof cf / sizeof cf[0]; i++) {
        if (wide_format(cf[i]) != wide)
            continue;
        glCopyTexImage2D(GL_TEXTURE_2D, 0, (GLenum)cf[i], (GLint)(5 * i), 3, 4, 4, 0);
        draw_cell(cell++, 8);
    }
    if (!wide) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5_A1, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, src + 300);
        draw_cell(cell++, 8);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA4, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, src + 500);
        draw_cell(cell++, 8);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE4_ALPHA4, 4, 4, 0, GL_LUMINANCE_ALPHA,
                     GL_UNSIGNED_BYTE, src + 700);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2);
        draw_cell(cell++, 8);
    }
    fc_capture(h);
}

static void rendered(fc_h *h) { rendered_of(h, false); }
static void rendered_wide(fc_h *h) { rendered_of(h, true); }

/* Mipmap completeness from the images (texobj.c:
 * _mesa_test_texobj_completeness): a level of another internal format or
 * size, a missing level, levels of one internal format stored in
 * different formats (GL_RGBA from 4-4-4-4 data), zero-sized base. */
static void chain(GLint base_if, GLint l1_if, GLenum l1_type, int l1_size, bool l2)
{
    static GLushort us[64];
    for (int i = 0; i < 64; i++)
        us[i] = (GLushort)(i * 0x1357u + 0x0f0fu);
    glTexImage2D(GL_TEXTURE_2D, 0, base_if, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    if (l1_type == GL_UNSIGNED_SHORT_4_4_4_4)
        glTexImage2D(GL_TEXTURE_2D, 1, l1_if, l1_size, l1_size, 0, GL_RGBA, l1_type, us);
    else
        glTexImage2D(GL_TEXTURE_2D, 1, l1_if, l1_size, l1_size, 0, GL_RGBA, l1_type, src + 300);
    if (l2)
        glTexImage2D(GL_TEXTURE_2D, 2, l1_if, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 600);
    glTexImage2D(GL_TEXTURE_2D, 3, l1_if, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 700);
}

static void completeness(fc_h *h)
{
    fill_src(71);
    fc_pixel_ortho(h);
    glClearColor(0.3f, 0.3f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glColor3f(0.9f, 0.1f, 0.5f);
    static const struct { GLint b, l1; GLenum t; int size; bool l2; } c[] = {
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, 4, true },      /* complete */
        { GL_RGBA, GL_RGB, GL_UNSIGNED_BYTE, 4, true },       /* format differs */
        { GL_RGBA, GL_RGBA8, GL_UNSIGNED_BYTE, 4, true },     /* RGBA vs RGBA8 */
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, 3, true },      /* size */
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, 4, false },     /* missing level 2 */
        { GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 4, true }, /* 4-4-4-4 storage */
        { GL_RGB5, GL_RGB5, GL_UNSIGNED_BYTE, 4, true },
        { GL_LUMINANCE4_ALPHA4, GL_LUMINANCE4_ALPHA4, GL_UNSIGNED_BYTE, 4, true },
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        GLuint t;
        glGenTextures(1, &t);
        glBindTexture(GL_TEXTURE_2D, t);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        chain(c[i].b, c[i].l1, c[i].t, c[i].size, c[i].l2);
        const float x = (float)(i % 4) * 10.0f, y = (float)(i / 4) * 10.0f;
        /* 8x8 texels on 4x4 pixels: level 1 */
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0); glVertex2f(x, y);
        glTexCoord2f(1, 0); glVertex2f(x + 4, y);
        glTexCoord2f(1, 1); glVertex2f(x + 4, y + 4);
        glTexCoord2f(0, 1); glVertex2f(x, y + 4);
        glEnd();
        /* magnified: level 0 */
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0); glVertex2f(x + 4, y);
        glTexCoord2f(0.5f, 0); glVertex2f(x + 10, y);
        glTexCoord2f(0.5f, 0.5f); glVertex2f(x + 10, y + 6);
        glTexCoord2f(0, 0.5f); glVertex2f(x + 4, y + 6);
        glEnd();
    }
    fc_capture(h);
    /* a zero-sized base, then BASE_LEVEL past it */
    glClear(GL_COLOR_BUFFER_BIT);
    glBindTexture(GL_TEXTURE_2D, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    draw_cell(0, 6);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    draw_cell(1, 6);
    /* MAX_LEVEL < BASE_LEVEL: mipmap-incomplete only */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    draw_cell(2, 6);
    fc_capture(h);
}

/* MAX_LEVEL < BASE_LEVEL with a non-mipmap filter: complete, sampled
 * through a sampler view whose last level is below its first */
static void completeness_max_below_base(fc_h *h)
{
    fill_src(73);
    fc_pixel_ortho(h);
    glClearColor(0.3f, 0.3f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    draw_cell(0, 6);
    fc_capture(h);
}

/* glGetTexImage and glGetTexLevelParameter errors. */
static void query_errors(fc_h *h)
{
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_LUMINANCE, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
#define E(label, call) do { call; fc_error(h, label); } while (0)
    E("get target proxy", glGetTexImage(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback));
    E("get target env", glGetTexImage(GL_TEXTURE_ENV, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback));
    E("get level", glGetTexImage(GL_TEXTURE_2D, 15, GL_RGBA, GL_UNSIGNED_BYTE, readback));
    E("get level -1", glGetTexImage(GL_TEXTURE_2D, -1, 0x1234, GL_UNSIGNED_BYTE, readback));
    E("get 3d level 12", glGetTexImage(GL_TEXTURE_3D, 12, GL_RGBA, GL_UNSIGNED_BYTE, readback));
    E("get 3d level 11", glGetTexImage(GL_TEXTURE_3D, 11, GL_RGBA, GL_UNSIGNED_BYTE, readback));
    E("get format", glGetTexImage(GL_TEXTURE_2D, 0, 0x1234, GL_UNSIGNED_BYTE, readback));
    E("get type", glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, 0x1234, readback));
    E("get packed", glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, readback));
    E("get depth", glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, readback));
    E("get depth no image", glGetTexImage(GL_TEXTURE_2D, 4, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, readback));
    GLint v = -5;
    E("lp target", glGetTexLevelParameteriv(GL_TEXTURE_ENV, 0, GL_TEXTURE_WIDTH, &v));
    E("lp target cube", glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v));
    E("lp level 15", glGetTexLevelParameteriv(GL_TEXTURE_2D, 15, GL_TEXTURE_WIDTH, &v));
    E("lp level -1", glGetTexLevelParameteriv(GL_TEXTURE_1D, -1, GL_TEXTURE_WIDTH, &v));
    E("lp 3d level 12", glGetTexLevelParameteriv(GL_TEXTURE_3D, 12, GL_TEXTURE_WIDTH, &v));
    E("lp pname", glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ENV_MODE, &v));
    E("lp pname min filter", glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_MIN_FILTER, &v));
    E("lp compressed size", glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v));
    E("lp compressed size none", glGetTexLevelParameteriv(GL_TEXTURE_2D, 7, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v));
    fc_value(h, "untouched", v);
    glBegin(GL_POINTS);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
    glEnd();
    fc_error(h, "inside begin/end");
    fc_value(h, "untouched 2", v);
#undef E
    level_params(h, "level 1", GL_TEXTURE_2D, 1);
    level_params(h, "3d", GL_TEXTURE_3D, 0);
    level_params(h, "cube face", GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 3);
    level_params(h, "proxy cube", GL_PROXY_TEXTURE_CUBE_MAP, 0);
    level_params(h, "proxy 1d none", GL_PROXY_TEXTURE_1D, 4);
}

/* Images belong to the bound object: binding, deleting, levels. */
static void objects(fc_h *h)
{
    GLuint t[3];
    glGenTextures(3, t);
    fill_src(21);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGB5, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 8);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 2, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, src + 40);
    level_params(h, "t1", GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    level_params(h, "t0", GL_TEXTURE_2D, 0);
    level_params(h, "t0 1", GL_TEXTURE_2D, 1);
    get_image(h, "t0", GL_TEXTURE_2D, 0, GL_RGBA, 3, 3);
    glBindTexture(GL_TEXTURE_2D, 0);
    level_params(h, "default", GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_1D, t[2]);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_INTENSITY, 4, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, src);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glDeleteTextures(1, &t[0]);
    fc_error(h, "delete bound");
    level_params(h, "after delete", GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    get_image(h, "t1", GL_TEXTURE_2D, 0, GL_RGBA, 2, 5);
    glDeleteTextures(2, &t[1]);
    level_params(h, "1d after delete", GL_TEXTURE_1D, 0);
    /* the default texture keeps its images across binds */
    glBindTexture(GL_TEXTURE_2D, 0);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glBindTexture(GL_TEXTURE_2D, 77);
    level_params(h, "new name", GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    get_image(h, "default", GL_TEXTURE_2D, 0, GL_RGBA, 2, 2);
}

const fc_case fc_cases_tex_image[] = {
    FC_CASE_RGBA("texture/image_formats_rgba", 8, 8, 0, "texture", formats_rgba),
    FC_CASE_RGBA("texture/image_formats_rgb", 8, 8, 0, "texture", formats_rgb),
    FC_CASE_RGBA("texture/image_formats_luminance", 8, 8, 0, "texture", formats_lum),
    FC_CASE_RGBA("texture/image_formats_lum_alpha", 8, 8, 0, "texture", formats_la),
    FC_CASE_RGBA("texture/image_formats_alpha", 8, 8, 0, "texture", formats_alpha),
    FC_CASE_RGBA("texture/image_formats_1d", 8, 8, 0, "texture", formats_1d),
    FC_CASE_RGBA("texture/image_readback_formats", 8, 8, 0, "texture", readback_formats),
    FC_CASE_RGBA("texture/image_readback_types", 8, 8, 0, "texture pixel", readback_types),
    FC_CASE_RGBA("texture/image_readback_types_precision", 8, 8, 0, "texture pixel",
                 readback_types_precision),
    FC_CASE_RGBA("texture/image_store_precision", 8, 8, 0, "texture pixel", store_precision),
    FC_CASE_RGBA("texture/image_unpack_store", 8, 8, 0, "texture", unpack_store),
    FC_CASE_RGBA("texture/genmipmap_2d", 32, 32, 7, "texture", genmipmap_2d),
    FC_CASE_RGBA("texture/genmipmap_1d", 32, 32, 3, "texture", genmipmap_1d),
    FC_CASE_RGBA("texture/genmipmap_calls", 32, 32, 1, "texture dlist", genmipmap_calls),
    FC_CASE_RGBA("texture/genmipmap_formats", 8, 8, 0, "texture", genmipmap_formats),
    FC_CASE_RGBA("texture/image_border", 8, 8, 0, "texture", border),
    FC_CASE_RGBA("texture/image_null_data", 8, 8, 0, "texture", null_data),
    FC_CASE_RGBA("texture/image_packed_types", 8, 8, 0, "texture", packed_types),
    FC_CASE_RGBA("texture/image_proxy", 8, 8, 0, "texture", proxy),
    FC_CASE_RGBA("texture/image_out_of_memory", 8, 8, 0, "texture", out_of_memory),
    FC_CASE_RGBA("texture/image_errors", 8, 8, 0, "texture", tex_image_errors),
    FC_CASE_RGBA("texture/image_subimage", 8, 8, 0, "texture", sub_image),
    FC_CASE_RGBA("texture/image_copy", 32, 32, 1, "texture", copy_image),
    FC_CASE_RGBA("texture/image_copy_values", 256, 1, 1, "texture", copy_values_small),
    FC_CASE_RGBA("texture/image_copy_r3g3b2", 256, 1, 1, "texture", copy_values_r3g3b2),
    FC_CASE_RGBA("texture/image_query_errors", 8, 8, 0, "texture", query_errors),
    FC_CASE_RGBA("texture/image_objects", 8, 8, 0, "texture", objects),
    FC_CASE_RGBA("texture/image_dlist", 32, 32, 1, "texture dlist", lists),
    FC_CASE_RGBA("texture/image_sharing", 8, 8, 0, "texture api", sharing),
    FC_CASE_RGBA("texture/image_rendered", 48, 36, 3, "texture", rendered),
    FC_CASE_RGBA("texture/image_rendered_wide", 48, 36, 3, "texture", rendered_wide),
    FC_CASE_RGBA("texture/image_completeness", 40, 20, 2, "texture", completeness),
    FC_CASE_RGBA("texture/image_completeness_max_below_base", 8, 8, 1, "texture",
                 completeness_max_below_base),
    FC_CASE_RGBA("texture/image_sharing_delete_bound", 8, 8, 0, "texture api",
                 sharing_delete_bound),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
