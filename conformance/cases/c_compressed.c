/* c_compressed.c - GL 1.3 compressed textures with GL_EXT_texture_
 * compression_s3tc (tags gl13 compressed): glCompressedTexImage2D of the
 * four S3TC formats sampled through every filter (DXT1 in its four- and
 * three-colour modes, the transparent black of DXT1 RGBA, DXT3's alpha
 * nibbles, DXT5's seven- and five-alpha modes), sizes that are not
 * multiples of 4 (1x1, 2x2, 5x3, 13x7), mipmaps, glCompressedTexSubImage2D
 * on block boundaries and at the image's edge and its errors elsewhere,
 * the errors of every entry point (imageSize, targets, formats, borders,
 * levels), glGetCompressedTexImage round trips, the level queries
 * (GL_TEXTURE_COMPRESSED, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, the internal
 * format and channel sizes), proxies, display lists, the ARB names,
 * glGetTexImage of compressed images, the generic formats the oracle
 * stores uncompressed (GL_COMPRESSED_ALPHA, GL_COMPRESSED_INTENSITY) and
 * GL_TEXTURE_COMPRESSION_HINT. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

#define DXT1 GL_COMPRESSED_RGB_S3TC_DXT1_EXT
#define DXT1A GL_COMPRESSED_RGBA_S3TC_DXT1_EXT
#define DXT3 GL_COMPRESSED_RGBA_S3TC_DXT3_EXT
#define DXT5 GL_COMPRESSED_RGBA_S3TC_DXT5_EXT

static unsigned rng_state;

static unsigned rng(void)
{
    rng_state = rng_state * 1103515245u + 12345u;
    return (rng_state >> 16) & 0x7fff;
}

static unsigned char g_blocks[64 * 64];
static unsigned char g_out[64 * 64 * 4];

static int block_bytes(GLenum f) { return f == DXT1 || f == DXT1A ? 8 : 16; }

static int image_size(GLenum f, int w, int h)
{
    return ((w + 3) / 4) * ((h + 3) / 4) * block_bytes(f);
}

/* Random blocks for a w x h image of format f into g_blocks.  colour_mode:
 * 0 random, 1 c0 > c1 (four colours), 2 c0 <= c1 (DXT1's three colours and
 * black), 3 c0 == c1; alpha_mode (DXT5): 0 random, 1 a0 > a1 (seven
 * alphas), 2 a0 <= a1 (five, 0 and 255). */
static int make_blocks(GLenum f, int w, int h, unsigned seed, int colour_mode, int alpha_mode)
{
    rng_state = seed * 7919u + 17u;
    const int n = image_size(f, w, h), bb = block_bytes(f);
    for (int i = 0; i < n; i++)
        g_blocks[i] = (unsigned char)(rng() & 255);
    for (int b = 0; b < n / bb; b++) {
        unsigned char *p = g_blocks + b * bb;
        unsigned char *c = bb == 16 ? p + 8 : p;
        unsigned c0 = (unsigned)c[0] | (unsigned)c[1] << 8, c1 = (unsigned)c[2] | (unsigned)c[3] << 8;
        if ((colour_mode == 1 && c0 <= c1) || (colour_mode == 2 && c0 > c1)) {
            unsigned t = c0; c0 = c1; c1 = t;
        }
        if (colour_mode == 1 && c0 == c1)
            c0 = c1 + 1 > 0xffff ? c1 : c1 + 1, c1 = c0 == c1 ? c1 - 1 : c1;
        if (colour_mode == 3)
            c1 = c0;
        c[0] = (unsigned char)c0; c[1] = (unsigned char)(c0 >> 8);
        c[2] = (unsigned char)c1; c[3] = (unsigned char)(c1 >> 8);
        if (f == DXT5 && alpha_mode) {
            unsigned a0 = p[0], a1 = p[1];
            if ((alpha_mode == 1 && a0 <= a1) || (alpha_mode == 2 && a0 > a1)) {
                unsigned t = a0; a0 = a1; a1 = t;
            }
            if (alpha_mode == 1 && a0 == a1)
                a0 = a0 < 255 ? a0 + 1 : a0, a1 = a0 == a1 ? a1 - 1 : a1;
            p[0] = (unsigned char)a0; p[1] = (unsigned char)a1;
        }
    }
    return n;
}

static void upload(GLenum f, int level, int w, int h, unsigned seed, int cm, int am)
{
    const int n = make_blocks(f, w, h, seed, cm, am);
    glCompressedTexImage2D(GL_TEXTURE_2D, level, f, w, h, 0, n, g_blocks);
}

static void filters(GLenum min, GLenum mag)
{
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)min);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)mag);
}

/* A rotated quad over most of the buffer (texture coordinates lo..hi) on
 * a coloured background, then a quad of the whole texture at texel scale
 * in a corner; captured. */
static void scene_quad(fc_h *h, float lo, float hi)
{
    const fc_case *c = fc_this_case(h);
    const float w = (float)c->width, hh = (float)c->height;
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.1f, 0.3f, 0.5f, 1);
    glEnable(GL_TEXTURE_2D);
    const float x[4] = { w * 0.06f, w * 0.95f, w * 0.86f, w * 0.02f };
    const float y[4] = { hh * 0.08f, hh * 0.03f, hh * 0.97f, hh * 0.88f };
    const float s[4] = { lo, hi, hi, lo }, t[4] = { lo, lo, hi, hi };
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        glColor4f(0.3f + 0.2f * (float)k, 0.9f - 0.2f * (float)k, 0.6f, 0.7f);
        glTexCoord2f(s[k], t[k]);
        glVertex2f(x[k], y[k]);
    }
    glEnd();
    fc_capture(h);
}

/* A floor receding under a frustum (every level of a chain shows). */
static void scene_floor(fc_h *h, float rep)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 60);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glColor4f(1, 1, 1, 1);
    glTexCoord2f(0, 0); glVertex3f(-2, -1, -1.2f);
    glTexCoord2f(rep, 0); glVertex3f(2, -1, -1.2f);
    glTexCoord2f(rep, rep * 6); glVertex3f(2, -1, -50);
    glTexCoord2f(0, rep * 6); glVertex3f(-2, -1, -50);
    glEnd();
    fc_capture(h);
}

/* glGetTexImage (RGBA, bytes) of level `level`, w x h */
static void get_rgba(fc_h *h, const char *label, int level, int w, int hh)
{
    memset(g_out, 0xcd, sizeof g_out);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
    fc_error(h, label);
    fc_blob(h, label, g_out, (size_t)w * (size_t)hh * 4);
}

static void get_blocks(fc_h *h, const char *label, int level, int n)
{
    memset(g_out, 0xcd, sizeof g_out);
    glGetCompressedTexImage(GL_TEXTURE_2D, level, g_out);
    fc_error(h, label);
    fc_blob(h, label, g_out, (size_t)n + 16);
}

static void level_queries(fc_h *h, const char *label, GLenum target, int level)
{
    static const GLenum pn[] = { GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_INTERNAL_FORMAT,
        GL_TEXTURE_COMPRESSED, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, GL_TEXTURE_RED_SIZE,
        GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE,
        GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE, GL_TEXTURE_BORDER };
    char l[96];
    for (size_t i = 0; i < sizeof pn / sizeof pn[0]; i++) {
        GLint v = -7;
        glGetTexLevelParameteriv(target, level, pn[i], &v);
        snprintf(l, sizeof l, "%s pname 0x%x", label, pn[i]);
        fc_error(h, l);
        fc_value(h, l, v);
    }
}

/* ---- sampling cases ---- */

struct sp {
    const char *name;
    GLenum fmt;
    int w, h;
    int cm, am;          /* make_blocks modes */
    GLenum min, mag;
    int mip;             /* 1: a full chain, drawn on the floor */
    GLenum env;
    float lo, hi;
    GLenum wrap;
};

static const struct sp sample_params[] = {
    { "compressed/dxt1_rgb_4colour_nearest", DXT1, 16, 16, 1, 0, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt1_rgb_3colour_nearest", DXT1, 16, 16, 2, 0, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt1_rgba_4colour_nearest", DXT1A, 16, 16, 1, 0, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt1_rgba_3colour_nearest", DXT1A, 16, 16, 2, 0, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt1_rgb_linear", DXT1, 16, 16, 0, 0, GL_LINEAR, GL_LINEAR, 0, GL_REPLACE, -0.3f, 1.6f, GL_REPEAT },
    { "compressed/dxt1_rgba_linear_modulate", DXT1A, 16, 16, 0, 0, GL_LINEAR, GL_LINEAR, 0, GL_MODULATE, -0.3f, 1.6f, GL_REPEAT },
    { "compressed/dxt1_equal_endpoints", DXT1A, 8, 8, 3, 0, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt3_nearest", DXT3, 16, 16, 0, 0, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt3_linear", DXT3, 16, 16, 0, 0, GL_LINEAR, GL_LINEAR, 0, GL_MODULATE, -0.2f, 1.3f, GL_REPEAT },
    { "compressed/dxt3_3colour_blocks", DXT3, 16, 16, 2, 0, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt5_7alpha_nearest", DXT5, 16, 16, 0, 1, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt5_5alpha_nearest", DXT5, 16, 16, 0, 2, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt5_linear", DXT5, 16, 16, 0, 0, GL_LINEAR, GL_LINEAR, 0, GL_REPLACE, -0.4f, 1.4f, GL_REPEAT },
    { "compressed/dxt5_equal_endpoints", DXT5, 8, 8, 3, 2, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/dxt5_clamp_edge_linear", DXT5, 8, 8, 0, 0, GL_LINEAR, GL_LINEAR, 0, GL_REPLACE, -0.5f, 1.5f, GL_CLAMP_TO_EDGE },
    { "compressed/size_1x1", DXT1, 1, 1, 0, 0, GL_LINEAR, GL_LINEAR, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/size_2x2", DXT5, 2, 2, 0, 0, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/size_5x3", DXT3, 5, 3, 0, 0, GL_NEAREST, GL_NEAREST, 0, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/size_5x3_linear", DXT1A, 5, 3, 2, 0, GL_LINEAR, GL_LINEAR, 0, GL_REPLACE, -0.2f, 1.2f, GL_REPEAT },
    { "compressed/size_13x7_linear", DXT5, 13, 7, 0, 0, GL_LINEAR, GL_NEAREST, 0, GL_MODULATE, -0.2f, 2.2f, GL_REPEAT },
    { "compressed/mip_dxt1_nearest_nearest", DXT1, 32, 32, 0, 0, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, 1, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/mip_dxt1a_nearest_linear", DXT1A, 32, 32, 2, 0, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, 1, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/mip_dxt3_linear_nearest", DXT3, 32, 32, 0, 0, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, 1, GL_REPLACE, 0, 1, GL_REPEAT },
    { "compressed/mip_dxt5_linear_linear", DXT5, 32, 32, 0, 0, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1, GL_MODULATE, 0, 1, GL_REPEAT },
    { "compressed/mip_dxt5_npot_linear_linear", DXT5, 24, 10, 0, 0, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1, GL_REPLACE, 0, 1, GL_REPEAT },
};

static const struct sp *find_params(const char *name)
{
    for (size_t i = 0; i < sizeof sample_params / sizeof sample_params[0]; i++)
        if (strcmp(sample_params[i].name, name) == 0)
            return &sample_params[i];
    return NULL;
}

static void sample_case(fc_h *h)
{
    const struct sp *p = find_params(fc_this_case(h)->name);
    if (!p)
        return;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(p->min, p->mag);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)p->wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)p->wrap);
    int w = p->w, hh = p->h;
    for (int l = 0;; l++) {
        upload(p->fmt, l, w, hh, 5u + (unsigned)l * 13u, p->cm, p->am);
        if (!p->mip || (w == 1 && hh == 1))
            break;
        w = w > 1 ? w / 2 : 1;
        hh = hh > 1 ? hh / 2 : 1;
    }
    fc_error(h, "upload");
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)p->env);
    if (p->mip)
        scene_floor(h, 3.0f);
    else
        scene_quad(h, p->lo, p->hi);
    get_rgba(h, "glGetTexImage level 0", 0, p->w, p->h);
    get_blocks(h, "glGetCompressedTexImage level 0", 0, image_size(p->fmt, p->w, p->h));
    level_queries(h, "level 0", GL_TEXTURE_2D, 0);
    if (p->mip)
        level_queries(h, "level 2", GL_TEXTURE_2D, 2);
}

/* ---- sub-images ---- */

static void sub_case(fc_h *h)
{
    const char *name = fc_this_case(h)->name;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(GL_NEAREST, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    if (strcmp(name, "compressed/sub_block_edges") == 0) {
        upload(DXT5, 0, 16, 16, 3, 0, 0);
        int n = make_blocks(DXT5, 8, 4, 99, 0, 1);
        glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 8, 8, 4, DXT5, n, g_blocks);
        fc_error(h, "sub 8x4 at (4, 8)");
        n = make_blocks(DXT5, 4, 8, 77, 0, 2);
        glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 12, 0, 4, 8, DXT5, n, g_blocks);
        fc_error(h, "sub 4x8 at (12, 0)");
    } else if (strcmp(name, "compressed/sub_whole_image") == 0) {
        upload(DXT1, 0, 12, 8, 3, 1, 0);
        int n = make_blocks(DXT1, 12, 8, 41, 2, 0);
        glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 12, 8, DXT1, n, g_blocks);
        fc_error(h, "sub whole");
    } else if (strcmp(name, "compressed/sub_to_edge_npot") == 0) {
        upload(DXT3, 0, 7, 6, 3, 0, 0);
        int n = make_blocks(DXT3, 3, 2, 12, 0, 0);
        glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 3, 2, DXT3, n, g_blocks);
        fc_error(h, "sub 3x2 at (4, 4) to the edge");
        n = make_blocks(DXT3, 4, 2, 13, 0, 0);
        glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 4, 4, 2, DXT3, n, g_blocks);
        fc_error(h, "sub 4x2 at (0, 4) to the edge");
    } else if (strcmp(name, "compressed/sub_mip_level") == 0) {
        filters(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
        int w = 16;
        for (int l = 0; l < 5; l++, w /= 2)
            upload(DXT1A, l, w, w, 20u + (unsigned)l, 0, 0);
        int n = make_blocks(DXT1A, 4, 4, 55, 2, 0);
        glCompressedTexSubImage2D(GL_TEXTURE_2D, 1, 4, 4, 4, 4, DXT1A, n, g_blocks);
        fc_error(h, "sub level 1");
        n = make_blocks(DXT1A, 2, 2, 56, 2, 0);
        glCompressedTexSubImage2DARB(GL_TEXTURE_2D, 3, 0, 0, 2, 2, DXT1A, n, g_blocks);
        fc_error(h, "sub level 3 (ARB)");
        scene_floor(h, 2.0f);
        get_blocks(h, "level 1 blocks", 1, 32);
        return;
    }
    scene_quad(h, 0, 1);
    GLint w = 0, hh = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &hh);
    GLint fmt = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &fmt);
    get_rgba(h, "texels", 0, w, hh);
    get_blocks(h, "blocks", 0, image_size((GLenum)fmt, w, hh));
}

/* ---- errors ---- */

static void E(fc_h *h, const char *label) { fc_error(h, label); }

static void sub_errors_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, DXT1, 8, g_blocks);
    E(h, "no image");
    upload(DXT1, 0, 16, 12, 1, 0, 0);
    upload(DXT5, 1, 8, 6, 1, 0, 0);
    E(h, "images");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, DXT1, 8, g_blocks);
    E(h, "x offset off a block");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 6, 4, 4, DXT1, 8, g_blocks);
    E(h, "y offset off a block");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 3, 4, DXT1, 8, g_blocks);
    E(h, "width not a block, not at the edge");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 2, DXT1, 8, g_blocks);
    E(h, "height not a block, not at the edge");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 12, 8, 8, 4, DXT1, 16, g_blocks);
    E(h, "beyond the width");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 12, 4, 4, DXT1, 8, g_blocks);
    E(h, "beyond the height");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, -4, 0, 4, 4, DXT1, 8, g_blocks);
    E(h, "negative x");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -4, 4, DXT1, 0, g_blocks);
    E(h, "negative width, size 0");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -4, 4, DXT1, 8, g_blocks);
    E(h, "negative width, size 8");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, DXT1, 16, g_blocks);
    E(h, "imageSize too large");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, DXT1, 7, g_blocks);
    E(h, "imageSize too small");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, DXT1, -8, g_blocks);
    E(h, "imageSize negative");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, DXT5, 16, g_blocks);
    E(h, "format other than the image's");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_COMPRESSED_RGB, 8, g_blocks);
    E(h, "generic format");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, 8, g_blocks);
    E(h, "uncompressed format");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 4, 4, GL_RGBA, 8, g_blocks);
    E(h, "uncompressed format before the level");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 4, 4, GL_COMPRESSED_ALPHA, 8, g_blocks);
    E(h, "generic format before the level");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, DXT1A, 7, g_blocks);
    E(h, "other format, wrong imageSize");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, DXT1A, 8, g_blocks);
    E(h, "other format, misaligned");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 4, 4, DXT1, 8, g_blocks);
    E(h, "level -1");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 15, 0, 0, 4, 4, DXT1, 8, g_blocks);
    E(h, "level 15");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 2, 0, 0, 4, 4, DXT1, 8, g_blocks);
    E(h, "level without an image");
    glCompressedTexSubImage2D(GL_TEXTURE_1D, 0, 0, 0, 4, 4, DXT1, 8, g_blocks);
    E(h, "1D target");
    glCompressedTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 4, 4, DXT1, 8, g_blocks);
    E(h, "proxy target");
    glCompressedTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, DXT1, 8, g_blocks);
    E(h, "glCompressedTexSubImage1D");
    glCompressedTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 4, 4, 1, DXT1, 8, g_blocks);
    E(h, "glCompressedTexSubImage3D on 3D");
    glCompressedTexSubImage3D(GL_TEXTURE_2D, 0, 0, 0, 0, 4, 4, 1, DXT1, 8, g_blocks);
    E(h, "glCompressedTexSubImage3D on 2D");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 1, 4, 4, 4, 2, DXT5, 16, g_blocks);
    E(h, "level 1 to the edge");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, DXT1, 0, NULL);
    E(h, "empty region");
    glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 4, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 2, 0, 0, 4, 4, DXT1, 8, g_blocks);
    E(h, "uncompressed image");
    glBegin(GL_POINTS);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, DXT1, 8, g_blocks);
    glEnd();
    E(h, "inside begin/end");
    get_blocks(h, "blocks after the errors", 0, 8 * 4 * 3);
}

static void image_errors_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    make_blocks(DXT5, 16, 16, 9, 0, 0);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 8, 8, 0, 31, g_blocks);
    E(h, "imageSize short");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 8, 8, 0, 33, g_blocks);
    E(h, "imageSize long");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 8, 8, 0, -32, g_blocks);
    E(h, "imageSize negative");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT3, 5, 5, 0, 16, g_blocks);
    E(h, "5x5 DXT3 with one block's size");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 8, 8, 1, 32, g_blocks);
    E(h, "border 1");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 8, 8, 2, 32, g_blocks);
    E(h, "border 2");
    glCompressedTexImage2D(GL_TEXTURE_2D, -1, DXT1, 8, 8, 0, 32, g_blocks);
    E(h, "level -1");
    glCompressedTexImage2D(GL_TEXTURE_2D, 15, DXT1, 8, 8, 0, 32, g_blocks);
    E(h, "level 15");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, -4, 8, 0, 16, g_blocks);
    E(h, "negative width");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 8, -4, 0, 16, g_blocks);
    E(h, "negative height");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 32768, 4, 0, 65536, g_blocks);
    E(h, "too wide");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, 32, g_blocks);
    E(h, "uncompressed internal format");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 8, 8, 0, 32, g_blocks);
    E(h, "generic internal format");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 8, 8, 0, 32, g_blocks);
    E(h, "not a format");
    glCompressedTexImage2D(GL_TEXTURE_1D, 0, DXT1, 8, 8, 0, 32, g_blocks);
    E(h, "2D call on 1D");
    glCompressedTexImage2D(GL_TEXTURE_3D, 0, DXT1, 8, 8, 0, 32, g_blocks);
    E(h, "2D call on 3D");
    glCompressedTexImage1D(GL_TEXTURE_1D, 0, DXT1, 8, 0, 16, g_blocks);
    E(h, "glCompressedTexImage1D");
    glCompressedTexImage1D(GL_PROXY_TEXTURE_1D, 0, DXT1, 8, 0, 16, g_blocks);
    E(h, "glCompressedTexImage1D proxy");
    glCompressedTexImage1D(GL_TEXTURE_2D, 0, DXT1, 8, 0, 16, g_blocks);
    E(h, "glCompressedTexImage1D on 2D");
    glCompressedTexImage3D(GL_TEXTURE_3D, 0, DXT1, 8, 8, 1, 0, 32, g_blocks);
    E(h, "glCompressedTexImage3D");
    glCompressedTexImage3D(GL_PROXY_TEXTURE_3D, 0, DXT1, 8, 8, 1, 0, 32, g_blocks);
    E(h, "glCompressedTexImage3D proxy");
    glCompressedTexImage3D(GL_TEXTURE_2D, 0, DXT1, 8, 8, 1, 0, 32, g_blocks);
    E(h, "glCompressedTexImage3D on 2D");
    glCompressedTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 8, 8, 1, 0, 32, g_blocks);
    E(h, "glCompressedTexImage3D uncompressed format");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 0, 0, 0, 0, NULL);
    E(h, "0x0");
    level_queries(h, "0x0", GL_TEXTURE_2D, 0);
    glBegin(GL_POINTS);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 8, 8, 0, 32, g_blocks);
    glEnd();
    E(h, "inside begin/end");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1, 8, 8, 0, 32, g_blocks);
    E(h, "valid");
    level_queries(h, "after the errors", GL_TEXTURE_2D, 0);
}

static void get_errors_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    upload(DXT3, 0, 8, 8, 4, 0, 0);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
    get_blocks(h, "level 0", 0, 64);
    get_blocks(h, "uncompressed level 1", 1, 0);
    get_blocks(h, "level 2 without an image", 2, 0);
    get_blocks(h, "level -1", -1, 0);
    get_blocks(h, "level 15", 15, 0);
    memset(g_out, 0xcd, 64);
    glGetCompressedTexImage(GL_PROXY_TEXTURE_2D, 0, g_out);
    E(h, "proxy target");
    glGetCompressedTexImage(GL_TEXTURE_CUBE_MAP, 0, g_out);
    E(h, "cube map target");
    glGetCompressedTexImage(GL_TEXTURE_1D, 0, g_out);
    E(h, "1D without an image");
    glGetCompressedTexImage(GL_TEXTURE_3D, 0, g_out);
    E(h, "3D without an image");
    glGetCompressedTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, g_out);
    E(h, "cube face without an image");
    glGetCompressedTexImage(GL_TEXTURE_RECTANGLE, 0, g_out);
    E(h, "rectangle without an image");
    glGetCompressedTexImage(GL_TEXTURE_2D_ARRAY, 0, g_out);
    E(h, "2D array without an image");
    glTexImage2D(GL_TEXTURE_2D, 3, GL_RGBA, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
    glGetCompressedTexImage(GL_TEXTURE_2D, 3, g_out);
    E(h, "empty uncompressed level");
    glCompressedTexImage2D(GL_TEXTURE_2D, 4, DXT1, 0, 0, 0, 0, g_blocks);
    glGetCompressedTexImage(GL_TEXTURE_2D, 4, g_out);
    E(h, "empty compressed level");
    fc_blob(h, "empty compressed level", g_out, 64);
    glGetCompressedTexImage(GL_TEXTURE_2D, 0, NULL);
    E(h, "NULL pointer");
    glGetCompressedTexImageARB(GL_TEXTURE_2D, 0, g_out);
    E(h, "ARB name");
    fc_blob(h, "ARB name", g_out, 64);
    glBegin(GL_POINTS);
    glGetCompressedTexImage(GL_TEXTURE_2D, 0, g_out);
    glEnd();
    E(h, "inside begin/end");
    GLint v = -7;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v);
    E(h, "image size of an uncompressed level");
    fc_value(h, "image size of an uncompressed level", v);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 2, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v);
    E(h, "image size of a missing level");
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 2, GL_TEXTURE_COMPRESSED, &v);
    E(h, "compressed of a missing level");
    fc_value(h, "compressed of a missing level", v);
}

static void round_trip_case(fc_h *h)
{
    static const GLenum fmts[4] = { DXT1, DXT1A, DXT3, DXT5 };
    static const int sizes[4][2] = { { 16, 8 }, { 5, 3 }, { 1, 1 }, { 9, 14 } };
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    char l[64];
    for (int f = 0; f < 4; f++)
        for (int s = 0; s < 4; s++) {
            upload(fmts[f], 0, sizes[s][0], sizes[s][1], 31u * (unsigned)f + (unsigned)s, 0, 0);
            snprintf(l, sizeof l, "format %d size %d", f, s);
            get_blocks(h, l, 0, image_size(fmts[f], sizes[s][0], sizes[s][1]));
            get_rgba(h, l, 0, sizes[s][0], sizes[s][1]);
            level_queries(h, l, GL_TEXTURE_2D, 0);
        }
    /* glGetTexImage into other formats */
    upload(DXT5, 0, 8, 8, 3, 0, 0);
    static const GLenum out_fmt[4] = { GL_RGB, GL_LUMINANCE, GL_ALPHA, GL_LUMINANCE_ALPHA };
    for (int i = 0; i < 4; i++) {
        memset(g_out, 0xcd, 512);
        glGetTexImage(GL_TEXTURE_2D, 0, out_fmt[i], GL_UNSIGNED_BYTE, g_out);
        snprintf(l, sizeof l, "glGetTexImage format 0x%x", out_fmt[i]);
        E(h, l);
        fc_blob(h, l, g_out, 512);
    }
    memset(g_out, 0xcd, 1024);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, g_out);
    E(h, "glGetTexImage float");
    fc_blob(h, "glGetTexImage float", g_out, 1024);
}

static void proxy_case(fc_h *h)
{
    make_blocks(DXT5, 16, 16, 9, 0, 0);
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, DXT5, 16, 8, 0, 128, g_blocks);
    E(h, "proxy 16x8");
    level_queries(h, "proxy 16x8", GL_PROXY_TEXTURE_2D, 0);
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, DXT1, 16, 8, 0, 100, g_blocks);
    E(h, "proxy wrong imageSize");
    level_queries(h, "proxy after the wrong imageSize", GL_PROXY_TEXTURE_2D, 0);
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, DXT1, 32768, 4, 0, 65536, NULL);
    E(h, "proxy too wide");
    level_queries(h, "proxy too wide", GL_PROXY_TEXTURE_2D, 0);
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 3, DXT1A, 6, 5, 0, 32, NULL);
    E(h, "proxy level 3");
    level_queries(h, "proxy level 3", GL_PROXY_TEXTURE_2D, 3);
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, DXT1, -4, 4, 0, 8, NULL);
    E(h, "proxy negative width");
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 20, DXT1, 4, 4, 0, 8, NULL);
    E(h, "proxy level 20");
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, DXT1, 32768, 4, 0, 7, NULL);
    E(h, "proxy too wide, wrong imageSize");
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, DXT1, 16384, 16384, 0, 16384 * 8192, NULL);
    E(h, "proxy 16384 square");
    level_queries(h, "proxy 16384 square", GL_PROXY_TEXTURE_2D, 0);
    glCompressedTexImage2DARB(GL_PROXY_TEXTURE_2D, 0, DXT3, 4, 4, 0, 16, NULL);
    E(h, "proxy ARB");
    level_queries(h, "proxy ARB", GL_PROXY_TEXTURE_2D, 0);
}

static void dlist_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(GL_NEAREST, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    GLuint list = glGenLists(1);
    int n = make_blocks(DXT5, 16, 16, 8, 0, 0);
    glNewList(list, GL_COMPILE);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT5, 16, 16, 0, n, g_blocks);
    n = make_blocks(DXT5, 4, 4, 81, 0, 2);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 8, 4, 4, 4, DXT5, n, g_blocks);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 1, 4, 4, 4, DXT5, n, g_blocks);
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, DXT1, 4, 4, 0, 8, g_blocks);
    glCompressedTexImage3D(GL_PROXY_TEXTURE_2D, 0, DXT1, 4, 4, 1, 0, 8, g_blocks);
    glCompressedTexImage1D(GL_PROXY_TEXTURE_2D, 0, DXT1, 4, 0, 8, g_blocks);
    glEndList();
    E(h, "compile");
    level_queries(h, "proxy executed at compile time", GL_PROXY_TEXTURE_2D, 0);
    GLint v = -7;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v);
    fc_value(h, "width before glCallList", v);
    /* the blocks were copied at compile time */
    memset(g_blocks, 0, sizeof g_blocks);
    glCallList(list);
    E(h, "glCallList");
    E(h, "glCallList 2");
    scene_quad(h, 0, 1);
    get_blocks(h, "blocks", 0, 256);
    /* errors compiled: a negative imageSize (the copy fails: out of
     * memory at compile time), a wrong size (at execution) */
    GLuint l2 = glGenLists(1);
    glNewList(l2, GL_COMPILE);
    glCompressedTexImage2D(GL_TEXTURE_2D, 1, DXT1, 8, 8, 0, -5, g_blocks);
    E(h, "negative imageSize compiled");
    glCompressedTexImage2D(GL_TEXTURE_2D, 1, DXT1, 8, 8, 0, 31, g_blocks);
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, DXT1, 8, NULL);
    glEndList();
    E(h, "compile errors");
    glCallList(l2);
    E(h, "execute errors 1");
    E(h, "execute errors 2");
    glNewList(l2, GL_COMPILE_AND_EXECUTE);
    n = make_blocks(DXT1A, 8, 8, 3, 2, 0);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, DXT1A, 8, 8, 0, n, g_blocks);
    glEndList();
    E(h, "compile and execute");
    scene_quad(h, 0, 1);
}

static void queries_case(fc_h *h)
{
    GLint v = -7;
    glGetIntegerv(GL_TEXTURE_COMPRESSION_HINT, &v);
    fc_value(h, "hint default", v);
    glHint(GL_TEXTURE_COMPRESSION_HINT, GL_NICEST);
    E(h, "hint nicest");
    glGetIntegerv(GL_TEXTURE_COMPRESSION_HINT, &v);
    fc_value(h, "hint nicest", v);
    glPushAttrib(GL_HINT_BIT);
    glHint(GL_TEXTURE_COMPRESSION_HINT, GL_FASTEST);
    glGetIntegerv(GL_TEXTURE_COMPRESSION_HINT, &v);
    fc_value(h, "hint fastest", v);
    glPopAttrib();
    glGetIntegerv(GL_TEXTURE_COMPRESSION_HINT, &v);
    fc_value(h, "hint popped", v);
    glHint(GL_TEXTURE_COMPRESSION_HINT, GL_RGBA);
    E(h, "hint bad mode");
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    static const GLenum fmts[4] = { DXT1, DXT1A, DXT3, DXT5 };
    char l[64];
    for (int f = 0; f < 4; f++) {
        upload(fmts[f], 0, 6, 10, 2, 0, 0);
        snprintf(l, sizeof l, "format 0x%x", fmts[f]);
        level_queries(h, l, GL_TEXTURE_2D, 0);
    }
    GLfloat fv = -7;
    glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &fv);
    E(h, "image size as float");
    fc_value(h, "image size as float", (long long)fv);
}

/* the generic formats llvmpipe stores uncompressed */
static void generic_case(fc_h *h)
{
    const char *name = fc_this_case(h)->name;
    const GLenum f = strstr(name, "alpha") ? GL_COMPRESSED_ALPHA : GL_COMPRESSED_INTENSITY;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(GL_LINEAR, GL_LINEAR);
    rng_state = 77;
    for (int i = 0; i < 8 * 8 * 4; i++)
        g_out[i] = (unsigned char)rng();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
    E(h, "glTexImage2D");
    level_queries(h, "level 0", GL_TEXTURE_2D, 0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    scene_quad(h, -0.2f, 1.3f);
    get_rgba(h, "texels", 0, 8, 8);
    get_blocks(h, "glGetCompressedTexImage", 0, 0);
}

/* A DXT texture on unit 1 combined with an RGBA one on unit 0; a texture
 * object switch under glPushAttrib(GL_TEXTURE_BIT). */
static void multitex_case(fc_h *h)
{
    GLuint tex[2];
    glGenTextures(2, tex);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    filters(GL_LINEAR, GL_LINEAR);
    upload(DXT5, 0, 8, 8, 17, 0, 0);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PREVIOUS);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    fcu_tex_level_image(GL_TEXTURE_2D, 0, 16, 16);
    filters(GL_NEAREST, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    const fc_case *c = fc_this_case(h);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    const float w = (float)c->width, hh = (float)c->height;
    const float xy[4][2] = { { 2, 3 }, { w - 3, 1 }, { w - 1, hh - 2 }, { 1, hh - 4 } };
    const float st[4][2] = { { 0, 0 }, { 1.3f, 0 }, { 1.3f, 1.1f }, { 0, 1.1f } };
    for (int k = 0; k < 4; k++) {
        glColor4f(0.9f, 0.6f + 0.1f * (float)k, 0.4f, 1);
        glMultiTexCoord2f(GL_TEXTURE0, st[k][0], st[k][1]);
        glMultiTexCoord2f(GL_TEXTURE1, st[k][1] * 0.9f, st[k][0] * 1.2f);
        glVertex2f(xy[k][0], xy[k][1]);
    }
    glEnd();
    fc_capture(h);
    glActiveTexture(GL_TEXTURE1);
    glPushAttrib(GL_TEXTURE_BIT);
    glBindTexture(GL_TEXTURE_2D, 0);
    glPopAttrib();
    GLint b = -1;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &b);
    fc_value(h, "binding after the pop", b == (GLint)tex[1]);
    get_blocks(h, "unit 1 blocks", 0, 64);
}

/* Levels of different formats: the texture is incomplete (disabled). */
static void mixed_levels_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    int w = 8;
    for (int l = 0; l < 4; l++, w /= 2)
        upload(l == 2 ? DXT5 : DXT1, l, w, w, 3u + (unsigned)l, 0, 0);
    E(h, "levels");
    scene_floor(h, 2.0f);
    upload(DXT1, 2, 2, 2, 4, 0, 0);
    scene_floor(h, 2.0f);
    /* a compressed level replaced by an uncompressed one and back */
    fcu_tex_level_image(GL_TEXTURE_2D, 1, 4, 4);
    scene_floor(h, 2.0f);
    upload(DXT1, 1, 4, 4, 9, 0, 0);
    scene_floor(h, 2.0f);
}


/* ---- the encoder: uncompressed data into S3TC images ---- */

/* Client images for the encoder cases (RGBA bytes, tightly packed): kind
 * 0 random, 1 gradients (alpha down the rows), 2 random colours with an
 * alpha edge, 3 alpha in three levels over colour bands, 4 a few flat
 * colours (blocks of one or two colours), 5 greys close together, 6 one
 * value per 4x4 block. */
static unsigned char g_img[64 * 64 * 4];

static void make_image(int kind, int w, int h, unsigned seed)
{
    rng_state = seed * 104729u + 3u;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int c = 0; c < 4; c++) {
                int v;
                switch (kind) {
                case 0: v = (int)(rng() & 255); break;
                case 1:
                    v = c == 3 ? y * 255 / (h > 1 ? h - 1 : 1)
                               : (x * 255 / (w > 1 ? w - 1 : 1) + c * 40 + y * 3) & 255;
                    break;
                case 2: v = c == 3 ? (x < w / 2 ? 0 : 255) : (int)(rng() & 255); break;
                case 3: v = c == 3 ? (int)(rng() % 3) * 127 : (y * 30 + c * 50) & 255; break;
                case 4: v = ((x / 3 + y / 2) & 1) ? 40 + c * 60 : 250 - c * 30; break;
                case 6:   /* one value per 4x4 block */
                    v = c == 3 ? 200 - 90 * ((x / 4 + y / 4) & 1) : 60 + 70 * ((x / 4 + y / 4) & 1);
                    break;
                default: v = 120 + (int)(rng() % 6) + (c == 1 ? 2 : 0); break;
                }
                g_img[4 * (y * w + x) + c] = (unsigned char)v;
            }
}

/* What a case may read back of an encoded image.  The oracle's encoder
 * reads uninitialised stack memory for the texels of an image's first
 * block that lie outside the image (ORACLE-NOTES.md "Compressed
 * textures: the encoder"): DXT3 and DXT5 blocks of an image narrower or
 * shorter than 4 hold garbage there, so the cases compare their texels,
 * not their bytes; a DXT5 image narrower than 4 and 2 or more high can
 * get a garbage code in a texel of the image, so no case makes one. */
#define LATC1 GL_COMPRESSED_LUMINANCE_LATC1_EXT
#define LATC2 GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT
/* (LATC, the oracle's storage of GL_COMPRESSED_LUMINANCE(_ALPHA): its
 * encoder's code arrays are uninitialised likewise, so an image narrower
 * than 4 and 2 or more high can sample garbage unless each of its blocks
 * holds one value (written without codes); its bytes are compared for
 * images of at least 4x4.) */
static bool bytes_defined(GLenum f, int w, int h)
{
    return f == DXT1 || f == DXT1A || f == GL_COMPRESSED_RGB || (w >= 4 && h >= 4);
}

struct ep {
    const char *name;
    GLenum internal;
    int w, h, kind;
    GLenum min, mag, env;
    bool blend;
};

static const struct ep encode_params[] = {
    { "compressed/encode_dxt1_random", DXT1, 16, 16, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/encode_dxt1_gradient_linear", DXT1, 16, 16, 1, GL_LINEAR, GL_LINEAR, GL_MODULATE, false },
    { "compressed/encode_dxt1_flat_colours", DXT1, 12, 8, 4, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/encode_dxt1_close_greys", DXT1, 8, 8, 5, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/encode_dxt1_npot_13x6", DXT1, 13, 6, 1, GL_LINEAR, GL_LINEAR, GL_REPLACE, false },
    { "compressed/encode_dxt1_1x1", DXT1, 1, 1, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/encode_dxt1_2x2", DXT1, 2, 2, 0, GL_LINEAR, GL_LINEAR, GL_REPLACE, false },
    { "compressed/encode_dxt1_3x5", DXT1, 3, 5, 1, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/encode_dxt1a_alpha_edge", DXT1A, 16, 16, 2, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt1a_alpha_levels", DXT1A, 7, 9, 3, GL_LINEAR, GL_LINEAR, GL_MODULATE, true },
    { "compressed/encode_dxt1a_gradient", DXT1A, 16, 16, 1, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt1a_5x3", DXT1A, 5, 3, 2, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt3_random", DXT3, 16, 16, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt3_gradient_npot", DXT3, 33, 17, 1, GL_LINEAR, GL_LINEAR, GL_MODULATE, true },
    { "compressed/encode_dxt3_alpha_levels", DXT3, 8, 8, 3, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt3_1x1", DXT3, 1, 1, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt3_3x5", DXT3, 3, 5, 1, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt5_random", DXT5, 16, 16, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt5_gradient_linear", DXT5, 16, 16, 1, GL_LINEAR, GL_LINEAR, GL_MODULATE, true },
    { "compressed/encode_dxt5_alpha_edge", DXT5, 8, 8, 2, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt5_alpha_levels_npot", DXT5, 7, 9, 3, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt5_flat_colours", DXT5, 12, 8, 4, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt5_1x1", DXT5, 1, 1, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_dxt5_5x1", DXT5, 5, 1, 0, GL_LINEAR, GL_LINEAR, GL_REPLACE, true },
    { "compressed/encode_dxt5_13x6", DXT5, 13, 6, 0, GL_LINEAR, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_generic_rgb", GL_COMPRESSED_RGB, 16, 12, 1, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/encode_generic_rgba", GL_COMPRESSED_RGBA, 16, 12, 2, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/encode_generic_rgba_npot", GL_COMPRESSED_RGBA, 10, 6, 3, GL_LINEAR, GL_LINEAR, GL_MODULATE, true },
#define CL GL_COMPRESSED_LUMINANCE
#define CLA GL_COMPRESSED_LUMINANCE_ALPHA
    { "compressed/latc1_noise_nearest", CL, 16, 16, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/latc1_ramp_linear", CL, 16, 16, 1, GL_LINEAR, GL_LINEAR, GL_MODULATE, false },
    { "compressed/latc1_flat_blocks", CL, 12, 8, 4, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/latc1_close_values", CL, 8, 8, 5, GL_LINEAR, GL_NEAREST, GL_REPLACE, false },
    { "compressed/latc1_levels", CL, 8, 12, 3, GL_NEAREST, GL_LINEAR, GL_MODULATE, false },
    { "compressed/latc1_npot_13x6", CL, 13, 6, 0, GL_LINEAR, GL_LINEAR, GL_REPLACE, false },
    { "compressed/latc1_npot_33x17_noise", CL, 33, 17, 0, GL_LINEAR, GL_NEAREST, GL_MODULATE, false },
    { "compressed/latc1_1x1", CL, 1, 1, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/latc1_5x3_ramp", CL, 5, 3, 1, GL_LINEAR, GL_LINEAR, GL_REPLACE, false },
    { "compressed/latc1_3x5_flat", CL, 3, 5, 6, GL_NEAREST, GL_NEAREST, GL_REPLACE, false },
    { "compressed/latc1_2x2_flat_linear", CL, 2, 2, 6, GL_LINEAR, GL_LINEAR, GL_MODULATE, false },
    { "compressed/latc2_noise_nearest", CLA, 16, 16, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/latc2_ramp_linear", CLA, 16, 16, 1, GL_LINEAR, GL_LINEAR, GL_MODULATE, true },
    { "compressed/latc2_alpha_edge", CLA, 8, 8, 2, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/latc2_alpha_levels_npot", CLA, 7, 9, 3, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/latc2_flat_blocks", CLA, 12, 8, 4, GL_LINEAR, GL_LINEAR, GL_REPLACE, true },
    { "compressed/latc2_close_values", CLA, 8, 8, 5, GL_NEAREST, GL_LINEAR, GL_MODULATE, true },
    { "compressed/latc2_npot_13x6", CLA, 13, 6, 0, GL_LINEAR, GL_NEAREST, GL_REPLACE, true },
    { "compressed/latc2_1x1", CLA, 1, 1, 0, GL_NEAREST, GL_NEAREST, GL_REPLACE, true },
    { "compressed/latc2_5x1", CLA, 5, 1, 0, GL_LINEAR, GL_LINEAR, GL_REPLACE, true },
    { "compressed/latc2_3x5_flat", CLA, 3, 5, 6, GL_NEAREST, GL_NEAREST, GL_MODULATE, true },
#undef CL
#undef CLA
};

static const struct ep *find_encode(const char *name)
{
    for (size_t i = 0; i < sizeof encode_params / sizeof encode_params[0]; i++)
        if (strcmp(encode_params[i].name, name) == 0)
            return &encode_params[i];
    return NULL;
}

/* The stored format's blocks and texels of level `level` (w x h) of the
 * bound 2D texture; the blocks only where the oracle defines them. */
static void read_encoded(fc_h *h, const char *label, GLenum internal, int level, int w, int hh)
{
    char l[96];
    GLint fmt = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_INTERNAL_FORMAT, &fmt);
    snprintf(l, sizeof l, "%s texels", label);
    get_rgba(h, l, level, w, hh);
    if (bytes_defined(internal, w, hh) && (fmt == DXT1 || fmt == DXT1A || fmt == DXT3 ||
                                           fmt == DXT5 || fmt == LATC1 || fmt == LATC2)) {
        snprintf(l, sizeof l, "%s blocks", label);
        get_blocks(h, l, level, image_size((GLenum)fmt, w, hh));
    }
}

static void encode_case(fc_h *h)
{
    const struct ep *p = find_encode(fc_this_case(h)->name);
    if (!p)
        return;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(p->min, p->mag);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    make_image(p->kind, p->w, p->h, 11);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)p->internal, p->w, p->h, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 g_img);
    fc_error(h, "glTexImage2D");
    level_queries(h, "level 0", GL_TEXTURE_2D, 0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)p->env);
    if (p->blend) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    scene_quad(h, -0.1f, 1.2f);
    read_encoded(h, "level 0", p->internal, 0, p->w, p->h);
}

/* LATC images smaller than a block: 1x1, 2x3 and 3x2 (and 1x3, 3x1) of
 * random luminance (and alpha), GL_COMPRESSED_LUMINANCE(_ALPHA).  The
 * oracle's encoder reads the image's texels only (the block's end values
 * come from them alone), but the codes of the texels outside the image
 * are its stack garbage, which spills into the codes of the rows below
 * the first of an image narrower than 4 (ORACLE-NOTES.md "Compressed
 * textures: LATC"): the case draws each image's first row, magnified
 * with NEAREST, and reads back the texels of the 1-row and 1x1 images
 * only; the 2x3 and 3x2 images' other rows are compared where each of
 * their blocks holds one value (written without codes). */
static void latc_small_case(fc_h *h)
{
    static const int sz[5][2] = { { 1, 1 }, { 2, 3 }, { 3, 2 }, { 1, 3 }, { 3, 1 } };
    static const GLenum gen[2] = { GL_COMPRESSED_LUMINANCE, GL_COMPRESSED_LUMINANCE_ALPHA };
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.1f, 0.3f, 0.5f, 1);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLuint tex[20];
    glGenTextures(20, tex);
    char l[96];
    for (int f = 0; f < 2; f++)
        for (int k = 0; k < 5; k++)
            for (int flat = 0; flat < 2; flat++) {
                const int w = sz[k][0], hh = sz[k][1];
                glBindTexture(GL_TEXTURE_2D, tex[(f * 5 + k) * 2 + flat]);
                filters(GL_NEAREST, GL_NEAREST);
                make_image(flat ? 6 : 0, w, hh, 31u + (unsigned)(f * 5 + k));
                glTexImage2D(GL_TEXTURE_2D, 0, (GLint)gen[f], w, hh, 0, GL_RGBA,
                             GL_UNSIGNED_BYTE, g_img);
                snprintf(l, sizeof l, "format %d %dx%d%s", f, w, hh, flat ? " flat" : "");
                fc_error(h, l);
                /* the first row (all of it for a flat image), 4 pixels a texel */
                const float x0 = (float)(2 + 20 * k), y0 = (float)(2 + 16 * (2 * f + flat));
                const float t1 = flat ? 1.0f : 1.0f / (float)hh;
                const float ph = flat ? 4.0f * (float)hh : 4.0f;
                glBegin(GL_QUADS);
                glTexCoord2f(0, 0); glVertex2f(x0, y0);
                glTexCoord2f(1, 0); glVertex2f(x0 + 4.0f * (float)w, y0);
                glTexCoord2f(1, t1); glVertex2f(x0 + 4.0f * (float)w, y0 + ph);
                glTexCoord2f(0, t1); glVertex2f(x0, y0 + ph);
                glEnd();
                if (hh == 1 || w >= 4 || flat)
                    get_rgba(h, l, 0, w, hh);
            }
    fc_error(h, "drawn");
    fc_capture(h);
}

/* Client data of other formats, types and unpack modes into S3TC images:
 * the oracle converts it to RGB8 / RGBA8 first, as into such an image. */
static void encode_sources_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(GL_NEAREST, GL_NEAREST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    make_image(0, 16, 16, 23);
    static const GLenum fmts[4] = { DXT1, DXT1A, DXT3, DXT5 };
    static const GLenum src_fmt[5] = { GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_BGRA, GL_ALPHA };
    char l[96];
    for (int f = 0; f < 4; f++)
        for (int s = 0; s < 5; s++) {
            glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], 8, 8, 0, src_fmt[s], GL_UNSIGNED_BYTE,
                         g_img);
            snprintf(l, sizeof l, "format %d from 0x%x", f, src_fmt[s]);
            fc_error(h, l);
            read_encoded(h, l, fmts[f], 0, 8, 8);
        }
    /* other types */
    static float fsrc[8 * 8 * 4];
    for (int i = 0; i < 8 * 8 * 4; i++)
        fsrc[i] = (float)g_img[i] / 255.0f + (float)((int)(rng() % 9) - 4) / 3000.0f;
    for (int f = 0; f < 4; f++) {
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], 8, 8, 0, GL_RGBA, GL_FLOAT, fsrc);
        snprintf(l, sizeof l, "format %d from floats", f);
        fc_error(h, l);
        read_encoded(h, l, fmts[f], 0, 8, 8);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], 8, 8, 0, GL_RGBA,
                     GL_UNSIGNED_SHORT_4_4_4_4, g_img);
        snprintf(l, sizeof l, "format %d from 4_4_4_4", f);
        fc_error(h, l);
        read_encoded(h, l, fmts[f], 0, 8, 8);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], 8, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5,
                     g_img);
        snprintf(l, sizeof l, "format %d from 5_6_5", f);
        fc_error(h, l);
        read_encoded(h, l, fmts[f], 0, 8, 4);
    }
    /* unpack modes: row length, skips, alignment */
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 16);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
    for (int f = 0; f < 4; f++) {
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], 9, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        snprintf(l, sizeof l, "format %d with unpack skips", f);
        fc_error(h, l);
        read_encoded(h, l, fmts[f], 0, 9, 8);
    }
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT1, 5, 5, 0, GL_RGB, GL_UNSIGNED_BYTE, g_img);
    fc_error(h, "DXT1 from RGB rows aligned to 8");
    read_encoded(h, "DXT1 from RGB rows aligned to 8", DXT1, 0, 5, 5);
    /* pixel transfer: scale and bias before the encoder */
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.25f);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT5, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    fc_error(h, "DXT5 with scale and bias");
    read_encoded(h, "DXT5 with scale and bias", DXT5, 0, 8, 8);
    glPixelTransferf(GL_RED_SCALE, 1);
    glPixelTransferf(GL_ALPHA_BIAS, 0);
    /* no data: the storage as it is (zero blocks), then the same size again */
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT5, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "DXT5 without data");
    read_encoded(h, "DXT5 without data", DXT5, 0, 8, 8);
}

/* glTexSubImage2D into S3TC images: block boundaries, the edge, errors;
 * one image over another of the same size keeps the storage (a DXT5
 * block of one alpha leaves its second byte as it was). */
static void encode_sub_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(GL_NEAREST, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    static const GLenum fmts[4] = { DXT1, DXT1A, DXT3, DXT5 };
    char l[96];
    for (int f = 0; f < 4; f++) {
        make_image(1, 13, 10, 5u + (unsigned)f);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[f], 13, 10, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        make_image(f == 3 ? 2 : 0, 9, 6, 40u + (unsigned)f);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        snprintf(l, sizeof l, "format %d: 8x4 at (4, 4)", f);
        E(h, l);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 4, 5, 6, GL_RGBA, GL_UNSIGNED_BYTE, g_img + 16);
        snprintf(l, sizeof l, "format %d: 5x6 at (8, 4) to both edges", f);
        E(h, l);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        snprintf(l, sizeof l, "format %d: x off the grid", f);
        E(h, l);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 4, 4, 3, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        snprintf(l, sizeof l, "format %d: height not a block, not at the edge", f);
        E(h, l);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 3, 4, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        snprintf(l, sizeof l, "format %d: width not a block, not at the edge", f);
        E(h, l);
        /* a 1x2 region is an image of its own to the encoder: DXT1 only
         * (bytes_defined) */
        if (f < 2) {
            glTexSubImage2D(GL_TEXTURE_2D, 0, 12, 8, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
            snprintf(l, sizeof l, "format %d: 1x2 at (12, 8), the last block", f);
            E(h, l);
        }
        glTexSubImage2D(GL_TEXTURE_2D, 0, 12, 8, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        snprintf(l, sizeof l, "format %d: beyond the image", f);
        E(h, l);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        snprintf(l, sizeof l, "format %d: empty", f);
        E(h, l);
        snprintf(l, sizeof l, "format %d", f);
        read_encoded(h, l, fmts[f], 0, 13, 10);
        if (f == 0 || f == 3)
            scene_quad(h, 0, 1);
    }
    /* the same size and format again: the storage stays */
    make_image(1, 8, 8, 3);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT5, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    make_image(2, 8, 8, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT5, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    read_encoded(h, "DXT5 over DXT5 of the same size", DXT5, 0, 8, 8);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT5, 12, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    read_encoded(h, "DXT5 of another size", DXT5, 0, 12, 8);
}

/* glCopyTexImage2D / glCopyTexSubImage2D into S3TC images. */
static void encode_copy_case(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.4f, 0.6f, 0.8f, 1);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 0.1f); glVertex2f(1, 1);
    glColor4f(0, 1, 0, 0.5f); glVertex2f((float)c->width - 2, 4);
    glColor4f(0, 0, 1, 1); glVertex2f(12, (float)c->height - 3);
    glEnd();
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(GL_NEAREST, GL_NEAREST);
    static const GLenum fmts[6] = { DXT1, DXT1A, DXT3, DXT5, GL_COMPRESSED_RGB, GL_COMPRESSED_RGBA };
    char l[96];
    for (int f = 0; f < 6; f++) {
        glCopyTexImage2D(GL_TEXTURE_2D, 0, fmts[f], 2, 3, 20, 18, 0);
        snprintf(l, sizeof l, "copy into 0x%x", fmts[f]);
        E(h, l);
        level_queries(h, l, GL_TEXTURE_2D, 0);
        read_encoded(h, l, fmts[f], 0, 20, 18);
    }
    /* partly outside the buffer: the texels outside stay as stored */
    glCopyTexImage2D(GL_TEXTURE_2D, 0, DXT5, c->width - 9, 5, 16, 12, 0);
    E(h, "copy partly outside");
    read_encoded(h, "copy partly outside", DXT5, 0, 16, 12);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, DXT1, 2, 3, 18, 18, 1);
    E(h, "copy with a border");
    glCopyTexImage1D(GL_TEXTURE_1D, 0, DXT1, 0, 0, 16, 0);
    E(h, "1D copy into DXT1");
    /* sub-copies */
    glCopyTexImage2D(GL_TEXTURE_2D, 0, DXT3, 0, 0, 16, 16, 0);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 8, 10, 3, 8, 8);
    E(h, "sub-copy 8x8 at (4, 8)");
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 12, 0, 1, 1, 4, 4);
    E(h, "sub-copy to the edge");
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 1, 1, 4, 4);
    E(h, "sub-copy off the grid");
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, 4, 3);
    E(h, "sub-copy height not a block");
    read_encoded(h, "after the sub-copies", DXT3, 0, 16, 16);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_quad(h, 0, 1);
}

/* GL_GENERATE_MIPMAP of S3TC images: the base decoded, box-filtered along
 * an uncompressed chain, each level encoded. */
static void encode_mipmap_case(fc_h *h)
{
    const char *name = fc_this_case(h)->name;
    GLenum f = DXT1;
    int w = 32, hh = 32;
    if (strstr(name, "dxt1a"))
        f = DXT1A;
    else if (strstr(name, "dxt3"))
        f = DXT3;
    else if (strstr(name, "dxt5"))
        f = DXT5;
    else if (strstr(name, "generic"))
        f = GL_COMPRESSED_RGBA;
    else if (strstr(name, "latc1"))
        f = GL_COMPRESSED_LUMINANCE;
    else if (strstr(name, "latc2"))
        f = GL_COMPRESSED_LUMINANCE_ALPHA;
    if (strstr(name, "npot"))
        w = 24, hh = 10;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(strstr(name, "_nn")   ? GL_NEAREST_MIPMAP_NEAREST
            : strstr(name, "_nl") ? GL_NEAREST_MIPMAP_LINEAR
            : strstr(name, "_ln") ? GL_LINEAR_MIPMAP_NEAREST
                                  : GL_LINEAR_MIPMAP_LINEAR,
            strstr(name, "_nn") ? GL_NEAREST : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    /* DXT5 levels under 4 wide and 2 or more high may hold the oracle's
     * garbage codes (bytes_defined): the 32x32 chains stop at 4x4 */
    const bool dxt5 = f == DXT5 || f == GL_COMPRESSED_RGBA || f == GL_COMPRESSED_LUMINANCE ||
                      f == GL_COMPRESSED_LUMINANCE_ALPHA;
    const int max_level = dxt5 && w == 32 ? 3 : 1000;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, max_level);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (strstr(name, "compressed_base")) {
        const int n = make_blocks(f, w, hh, 21, 0, 0);
        glCompressedTexImage2D(GL_TEXTURE_2D, 0, f, w, hh, 0, n, g_blocks);
    } else {
        make_image(f == DXT5 || f == GL_COMPRESSED_RGBA || strstr(name, "ramp") ? 1 : 0, w, hh, 9);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, w, hh, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    }
    E(h, "base");
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    scene_floor(h, 3.0f);
    char l[64];
    for (int level = 0;; level++) {
        snprintf(l, sizeof l, "level %d", level);
        level_queries(h, l, GL_TEXTURE_2D, level);
        read_encoded(h, l, f, level, w, hh);
        if ((w == 1 && hh == 1) || level == max_level)
            break;
        w = w > 1 ? w / 2 : 1;
        hh = hh > 1 ? hh / 2 : 1;
    }
    /* a sub-image of the base regenerates the chain */
    make_image(2, 8, 8, 31);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    E(h, "sub-image of the base");
    read_encoded(h, "level 1 after the sub-image", f, 1, strstr(name, "npot") ? 12 : 16,
                 strstr(name, "npot") ? 5 : 16);
    scene_floor(h, 3.0f);
}

/* GL_COMPRESSED_LUMINANCE(_ALPHA), stored as LATC1/LATC2: other client
 * formats and types, pixel transfer, sub-images (on block boundaries, to
 * the edge, errors off the grid), one image over another of the same size
 * (a block of one value keeps its second byte), copies from the colour
 * buffer, the queries of 1D, 2D and cube-face images, 3D images. */
static void latc_more_case(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    const bool two = strstr(c->name, "latc2") != NULL;
    const GLenum f = two ? GL_COMPRESSED_LUMINANCE_ALPHA : GL_COMPRESSED_LUMINANCE;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    filters(GL_NEAREST, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    char l[96];
    if (strstr(c->name, "sources")) {
        make_image(0, 16, 16, 23);
        static const GLenum src_fmt[6] = { GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_BGRA,
                                           GL_ALPHA, GL_RGBA };
        for (int k = 0; k < 6; k++) {
            glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, src_fmt[k], GL_UNSIGNED_BYTE, g_img);
            snprintf(l, sizeof l, "from 0x%x", src_fmt[k]);
            fc_error(h, l);
            read_encoded(h, l, f, 0, 8, 8);
        }
        static float fsrc[8 * 8 * 4];
        for (int i = 0; i < 8 * 8 * 4; i++)
            fsrc[i] = (float)g_img[i] / 255.0f + (float)((int)(rng() % 9) - 4) / 3000.0f;
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, GL_RGBA, GL_FLOAT, fsrc);
        fc_error(h, "from floats");
        read_encoded(h, "from floats", f, 0, 8, 8);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, g_img);
        fc_error(h, "from 4_4_4_4");
        read_encoded(h, "from 4_4_4_4", f, 0, 8, 8);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 16);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 9, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        fc_error(h, "unpack skips");
        read_encoded(h, "unpack skips", f, 0, 9, 8);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glPixelTransferf(GL_RED_SCALE, 0.5f);
        glPixelTransferf(GL_ALPHA_BIAS, 0.25f);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        fc_error(h, "scale and bias");
        read_encoded(h, "scale and bias", f, 0, 8, 8);
        glPixelTransferf(GL_RED_SCALE, 1);
        glPixelTransferf(GL_ALPHA_BIAS, 0);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        fc_error(h, "without data");
        read_encoded(h, "without data", f, 0, 8, 8);
        scene_quad(h, 0, 1);
    } else if (strstr(c->name, "sub")) {
        make_image(1, 13, 10, 5);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 13, 10, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        make_image(0, 9, 6, 40);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        E(h, "8x4 at (4, 4)");
        glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 4, 5, 6, GL_RGBA, GL_UNSIGNED_BYTE, g_img + 16);
        E(h, "5x6 at (8, 4) to both edges");
        glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        E(h, "x off the grid");
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 4, 4, 3, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        E(h, "height not a block, not at the edge");
        glTexSubImage2D(GL_TEXTURE_2D, 0, 12, 8, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        E(h, "beyond the image");
        glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        E(h, "empty");
        read_encoded(h, "after the sub-images", f, 0, 13, 10);
        scene_quad(h, 0, 1);
        /* the same size again: the storage stays */
        make_image(0, 8, 8, 3);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        make_image(6, 8, 8, 4);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        read_encoded(h, "one-value blocks over an image of the same size", f, 0, 8, 8);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 12, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        read_encoded(h, "another size", f, 0, 12, 8);
    } else if (strstr(c->name, "copies")) {
        fc_pixel_ortho(h);
        fcu_clear(0.2f, 0.4f, 0.6f, 0.8f, 1);
        glBegin(GL_TRIANGLES);
        glColor4f(1, 0, 0, 0.1f); glVertex2f(1, 1);
        glColor4f(0, 1, 0, 0.5f); glVertex2f((float)c->width - 2, 4);
        glColor4f(0.6f, 0, 1, 1); glVertex2f(12, (float)c->height - 3);
        glEnd();
        glCopyTexImage2D(GL_TEXTURE_2D, 0, f, 2, 3, 20, 18, 0);
        E(h, "copy");
        level_queries(h, "copy", GL_TEXTURE_2D, 0);
        read_encoded(h, "copy", f, 0, 20, 18);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, f, c->width - 9, 5, 16, 12, 0);
        E(h, "copy partly outside");
        read_encoded(h, "copy partly outside", f, 0, 16, 12);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, f, 0, 0, 16, 16, 0);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 8, 10, 3, 8, 8);
        E(h, "sub-copy 8x8 at (4, 8)");
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 1, 1, 4, 4);
        E(h, "sub-copy off the grid");
        read_encoded(h, "after the sub-copies", f, 0, 16, 16);
        glEnable(GL_TEXTURE_2D);
        scene_quad(h, 0, 1);
    } else if (strstr(c->name, "3d")) {
        /* 3D images of the generic formats: the oracle compresses them
         * too, each slice an image of its own to the encoder */
        const GLenum g = strstr(c->name, "generic_rgba") ? GL_COMPRESSED_RGBA
                         : strstr(c->name, "generic_rgb") ? GL_COMPRESSED_RGB
                                                          : f;
        const int n = g == GL_COMPRESSED_RGBA || g == GL_COMPRESSED_LUMINANCE_ALPHA ? 192 : 96;
        make_image(strstr(c->name, "ramp") ? 1 : 0, 8, 24, 7);
        GLuint t3;
        glGenTextures(1, &t3);
        glBindTexture(GL_TEXTURE_3D, t3);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexImage3D(GL_TEXTURE_3D, 0, (GLint)g, 8, 8, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        E(h, "3D");
        level_queries(h, "3D", GL_TEXTURE_3D, 0);
        memset(g_out, 0xcd, sizeof g_out);
        glGetCompressedTexImage(GL_TEXTURE_3D, 0, g_out);
        E(h, "glGetCompressedTexImage of the 3D image");
        fc_blob(h, "3D blocks", g_out, (size_t)n);
        glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
        fc_blob(h, "3D texels", g_out, 8 * 8 * 3 * 4);
        /* a sub-image across slices 1 and 2, on the block grid */
        make_image(0, 4, 8, 8);
        glTexSubImage3D(GL_TEXTURE_3D, 0, 4, 0, 1, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        E(h, "glTexSubImage3D");
        memset(g_out, 0xcd, sizeof g_out);
        glGetCompressedTexImage(GL_TEXTURE_3D, 0, g_out);
        fc_blob(h, "3D blocks after the sub-image", g_out, (size_t)n);
        glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
        fc_blob(h, "3D texels after the sub-image", g_out, 8 * 8 * 3 * 4);
        /* drawn: r across the slices */
        fc_pixel_ortho(h);
        fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
        glEnable(GL_TEXTURE_3D);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        glBegin(GL_QUADS);
        glTexCoord3f(0, 0, 0); glVertex2f(1, 1);
        glTexCoord3f(1.2f, 0, 0.3f); glVertex2f((float)c->width - 1, 1);
        glTexCoord3f(1.2f, 1.1f, 1); glVertex2f((float)c->width - 1, (float)c->height - 1);
        glTexCoord3f(0, 1.1f, 0.7f); glVertex2f(1, (float)c->height - 1);
        glEnd();
        glDisable(GL_TEXTURE_3D);
        fc_capture(h);
        if (strstr(c->name, "mipmap")) {
            /* GL_GENERATE_MIPMAP of a 3D image: 8x8x4, then 4x4x2 ... */
            make_image(1, 8, 32, 17);
            glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
            glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 1);
            glTexImage3D(GL_TEXTURE_3D, 0, (GLint)g, 8, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
            E(h, "3D with GL_GENERATE_MIPMAP");
            level_queries(h, "3D level 1", GL_TEXTURE_3D, 1);
            memset(g_out, 0xcd, sizeof g_out);
            glGetCompressedTexImage(GL_TEXTURE_3D, 1, g_out);
            E(h, "glGetCompressedTexImage of level 1");
            fc_blob(h, "level 1 blocks", g_out, (size_t)n / 6);
            glGetTexImage(GL_TEXTURE_3D, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
            fc_blob(h, "level 1 texels", g_out, 4 * 4 * 2 * 4);
        }
    } else {
        /* queries: 2D, 1D (stored uncompressed), a cube face */
        make_image(0, 8, 8, 2);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        level_queries(h, "2D", GL_TEXTURE_2D, 0);
        glTexImage2D(GL_PROXY_TEXTURE_2D, 0, (GLint)f, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        level_queries(h, "2D proxy", GL_PROXY_TEXTURE_2D, 0);
        GLuint t1;
        glGenTextures(1, &t1);
        glBindTexture(GL_TEXTURE_1D, t1);
        glTexImage1D(GL_TEXTURE_1D, 0, (GLint)f, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        E(h, "1D");
        level_queries(h, "1D", GL_TEXTURE_1D, 0);
        glGetCompressedTexImage(GL_TEXTURE_1D, 0, g_out);
        E(h, "glGetCompressedTexImage of the 1D image");
        GLuint tc;
        glGenTextures(1, &tc);
        glBindTexture(GL_TEXTURE_CUBE_MAP, tc);
        for (int face = 0; face < 6; face++) {
            make_image(face & 1 ? 1 : 0, 8, 8, 50u + (unsigned)face);
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face, 0, (GLint)f, 8, 8, 0,
                         GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        }
        E(h, "cube faces");
        level_queries(h, "cube face -Y", GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0);
        memset(g_out, 0xcd, sizeof g_out);
        glGetCompressedTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, g_out);
        E(h, "glGetCompressedTexImage of a face");
        fc_blob(h, "face -Y blocks", g_out, two ? 64 : 32);
        glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_Z, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, g_out);
        E(h, "glGetTexImage of a face");
        fc_blob(h, "face +Z texels", g_out, 8 * 8 * 2);
    }
}

/* Cube-map faces of mixed formats (DXT1 blocks, LATC1 from
 * GL_COMPRESSED_LUMINANCE, then DXT1 again): glGetTexImage of each face.
 * The oracle reads the faces specified before the last change of format
 * through Mesa's CPU decoders, the others through the sampler
 * (ORACLE-NOTES.md "Compressed textures: LATC"; main/teximage.c
 * "Storage"). */
static void cube_mixed_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    char l[96];
    for (int face = 0; face < 6; face++) {
        const GLenum target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face;
        if (face == 1) {
            make_image(0, 8, 8, 80);
            glTexImage2D(target, 0, GL_COMPRESSED_LUMINANCE, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                         g_img);
        } else {
            const int n = make_blocks(DXT1A, 8, 8, 81u + (unsigned)face, 0, 0);
            glCompressedTexImage2D(target, 0, DXT1A, 8, 8, 0, n, g_blocks);
        }
        snprintf(l, sizeof l, "face %d", face);
        E(h, l);
    }
    for (int face = 0; face < 6; face++) {
        const GLenum target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face;
        snprintf(l, sizeof l, "face %d", face);
        level_queries(h, l, target, 0);
        memset(g_out, 0xcd, 8 * 8 * 4);
        glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
        fc_blob(h, l, g_out, 8 * 8 * 4);
    }
}

/* Reads back every face of the bound cube map (GL_RGBA bytes) under
 * `stage`, and face `ff` also as floats. */
static void read_faces(fc_h *h, const char *stage, int ff)
{
    char l[96];
    for (int face = 0; face < 6; face++) {
        const GLenum target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face;
        snprintf(l, sizeof l, "%s: face %d", stage, face);
        memset(g_out, 0xcd, 8 * 8 * 4);
        glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
        fc_blob(h, l, g_out, 8 * 8 * 4);
        if (face == ff) {
            static float fl[8 * 8 * 4];
            glGetTexImage(target, 0, GL_RGBA, GL_FLOAT, fl);
            snprintf(l, sizeof l, "%s: face %d as floats", stage, face);
            fc_blob(h, l, fl, sizeof fl);
        }
    }
    E(h, stage);
}

/* One face of an 8x8 cube map in `kind`: DXT1A/DXT1/DXT3/DXT5 random
 * blocks, 'U' RGBA8 data, 'L' / 'A' GL_COMPRESSED_LUMINANCE(_ALPHA), 'E'
 * DXT5 encoded from data. */
static void cube_face(GLenum target, int kind, unsigned seed)
{
    if (kind == 'U' || kind == 'L' || kind == 'A' || kind == 'E') {
        make_image(0, 8, 8, seed);
        const GLint internal = kind == 'U'   ? GL_RGBA8
                               : kind == 'L' ? GL_COMPRESSED_LUMINANCE
                               : kind == 'A' ? GL_COMPRESSED_LUMINANCE_ALPHA
                                             : (GLint)DXT5;
        glTexImage2D(target, 0, internal, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    } else {
        const int n = make_blocks((GLenum)kind, 8, 8, seed, 0, 0);
        glCompressedTexImage2D(target, 0, (GLenum)kind, 8, 8, 0, n, g_blocks);
    }
}

/* Where the oracle keeps each image decides how glGetTexImage reads a
 * compressed one (ORACLE-NOTES.md "Compressed textures: LATC", cube
 * faces of mixed formats; main/teximage.c "Storage"):
 *  - _more: faces DXT3 DXT3 DXT5 RGBA8 LATC2 DXT5(encoded): faces 0-4
 *    before the last change of format read through Mesa's CPU decoders;
 *  - _redrawn: DXT5 DXT5 RGBA8 DXT5 DXT5 DXT5, read; face 2 given DXT5
 *    blocks, read (faces 0 and 1 still in resources of their own); the
 *    cube map drawn (complete: the oracle moves every face into the
 *    object's resource), read again;
 *  - _levels (2D): GL_LINEAR, level 0 DXT1 (a one-level resource), then
 *    levels 1-3: level 0 keeps its own; read; drawn with a mipmap filter,
 *    read again. */
static void mixed_storage_case(fc_h *h)
{
    const char *name = fc_this_case(h)->name;
    GLuint tex;
    glGenTextures(1, &tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    fc_pixel_ortho(h);
    if (strstr(name, "_levels")) {
        glBindTexture(GL_TEXTURE_2D, tex);
        filters(GL_LINEAR, GL_NEAREST);
        for (int l = 0; l < 4; l++)
            upload(DXT1A, l, 8 >> l, 8 >> l, 300u + (unsigned)l, 0, 0);
        E(h, "levels");
        char l[64];
        for (int pass = 0; pass < 2; pass++) {
            for (int lv = 0; lv < 2; lv++) {
                snprintf(l, sizeof l, "pass %d level %d", pass, lv);
                memset(g_out, 0xcd, 8 * 8 * 4);
                glGetTexImage(GL_TEXTURE_2D, lv, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
                fc_blob(h, l, g_out, (size_t)(8 >> lv) * (size_t)(8 >> lv) * 4);
            }
            filters(GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST);
            glEnable(GL_TEXTURE_2D);
            glBegin(GL_QUADS);
            glTexCoord2f(0, 0); glVertex2f(0, 0);
            glTexCoord2f(1, 0); glVertex2f(16, 0);
            glTexCoord2f(1, 1); glVertex2f(16, 16);
            glTexCoord2f(0, 1); glVertex2f(0, 16);
            glEnd();
            glDisable(GL_TEXTURE_2D);
            fc_capture(h);
        }
        E(h, "read back");
        return;
    }
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    const bool more = strstr(name, "_more") != NULL;
    static const int kinds_more[6] = { DXT3, DXT3, DXT5, 'U', 'A', 'E' };
    static const int kinds_redrawn[6] = { DXT5, DXT5, 'U', DXT5, DXT5, DXT5 };
    for (int face = 0; face < 6; face++)
        cube_face(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face,
                  more ? kinds_more[face] : kinds_redrawn[face], 400u + (unsigned)face);
    E(h, "faces");
    read_faces(h, "specified", more ? 2 : 0);
    if (more)
        return;
    cube_face(GL_TEXTURE_CUBE_MAP_NEGATIVE_X + 1, DXT5, 420u);
    read_faces(h, "face 2 again", 0);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glBegin(GL_QUADS);
    glTexCoord3f(1, -0.5f, -0.5f); glVertex2f(0, 0);
    glTexCoord3f(1, 0.5f, -0.5f); glVertex2f(16, 0);
    glTexCoord3f(1, 0.5f, 0.5f); glVertex2f(16, 16);
    glTexCoord3f(1, -0.5f, 0.5f); glVertex2f(0, 16);
    glEnd();
    glDisable(GL_TEXTURE_CUBE_MAP);
    fc_capture(h);
    read_faces(h, "drawn", 0);
}

/* S3TC images on cube-map faces: glCompressedTexImage2D, glTexImage2D
 * (encoded), sub-images, glGetCompressedTexImage of a face. */
static void cube_case(fc_h *h)
{
    const char *name = fc_this_case(h)->name;
    const bool encoded = strstr(name, "encoded") != NULL;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* one format for all faces (faces of different formats:
     * compressed/cube_faces_mixed_formats*) */
    char l[96];
    for (int face = 0; face < 6; face++) {
        const GLenum target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face;
        const GLenum f = encoded ? DXT5 : DXT1A;
        if (encoded) {
            make_image(face % 4, 8, 8, 60u + (unsigned)face);
            glTexImage2D(target, 0, (GLint)(face == 5 ? GL_COMPRESSED_RGBA : DXT5), 8, 8, 0,
                         GL_RGBA, GL_UNSIGNED_BYTE, g_img);
        } else {
            const int n = make_blocks(DXT5, 8, 8, 70u + (unsigned)face, 0, 0);
            glCompressedTexImage2D(target, 0, f, 8, 8, 0,
                                   f == DXT1 || f == DXT1A ? n / 2 : n, g_blocks);
        }
        snprintf(l, sizeof l, "face %d", face);
        E(h, l);
    }
    /* a sub-image of one face, then errors */
    if (encoded) {
        make_image(0, 4, 4, 99);
        glTexSubImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, 4, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE,
                        g_img);
    } else {
        const int n = make_blocks(DXT1A, 4, 4, 98, 2, 0);
        glCompressedTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Z, 0, 4, 4, 4, 4, DXT1A, n, g_blocks);
    }
    E(h, "sub-image of a face");
    glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, DXT1, 8, 4, 0, 16, g_blocks);
    E(h, "face not square");
    glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP, 0, DXT1, 8, 8, 0, 32, g_blocks);
    E(h, "the cube-map target");
    glCompressedTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, DXT5, 16, 16, 0, 256, NULL);
    E(h, "cube-map proxy");
    level_queries(h, "cube-map proxy", GL_PROXY_TEXTURE_CUBE_MAP, 0);
    glCompressedTexSubImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 0, 0, 0, 4, 4, DXT5, 16, g_blocks);
    E(h, "sub-image of another format");
    for (int face = 0; face < 6; face++) {
        const GLenum target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face;
        snprintf(l, sizeof l, "face %d", face);
        level_queries(h, l, target, 0);
        memset(g_out, 0xcd, 256);
        glGetCompressedTexImage(target, 0, g_out);
        E(h, l);
        GLint fmt = 0;
        glGetTexLevelParameteriv(target, 0, GL_TEXTURE_INTERNAL_FORMAT, &fmt);
        fc_blob(h, l, g_out, (size_t)image_size((GLenum)fmt, 8, 8) + 16);
        memset(g_out, 0xcd, 8 * 8 * 4);
        glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_out);
        fc_blob(h, l, g_out, 8 * 8 * 4);
    }
    glGetCompressedTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 1, g_out);
    E(h, "face level without an image");
    /* drawn: a quad whose coordinates sweep every face */
    const fc_case *c = fc_this_case(h);
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    const int n = 6;
    for (int face = 0; face < n; face++) {
        const float x0 = (float)c->width * (float)face / (float)n,
                    x1 = (float)c->width * (float)(face + 1) / (float)n;
        static const float dir[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 },
                                         { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
        const float *d = dir[face];
        glBegin(GL_QUADS);
        for (int k = 0; k < 4; k++) {
            const float u = k == 1 || k == 2 ? 0.9f : -0.9f, v = k >= 2 ? 0.9f : -0.9f;
            /* a direction near the face's axis, spread over the face */
            const float s = d[0] != 0 ? d[0] : u, t = d[1] != 0 ? d[1] : (d[0] != 0 ? u : v),
                        r = d[2] != 0 ? d[2] : v;
            glTexCoord3f(s, t, r);
            glVertex2f(k == 1 || k == 2 ? x1 : x0, k >= 2 ? (float)c->height - 1 : 1);
        }
        glEnd();
    }
    fc_capture(h);
}

/* glTexImage2D errors of the S3TC formats. */
static void encode_errors_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    make_image(0, 8, 8, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT1, 8, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    E(h, "border 1");
    glTexImage1D(GL_TEXTURE_1D, 0, (GLint)DXT1, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    E(h, "1D image");
    glTexImage1D(GL_PROXY_TEXTURE_1D, 0, (GLint)DXT5, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    E(h, "1D proxy");
    glTexImage3D(GL_TEXTURE_3D, 0, (GLint)DXT1, 8, 8, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    E(h, "3D image");
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT3, 8, 8, 0, GL_DEPTH_COMPONENT, GL_FLOAT, g_img);
    E(h, "depth data");
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT3, -4, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    E(h, "negative width");
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, (GLint)DXT3, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    E(h, "proxy");
    level_queries(h, "proxy", GL_PROXY_TEXTURE_2D, 0);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 6, 6, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    E(h, "generic proxy");
    level_queries(h, "generic proxy", GL_PROXY_TEXTURE_2D, 0);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_COMPRESSED_RGBA, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img);
    E(h, "generic 1D");
    level_queries(h, "generic 1D", GL_TEXTURE_1D, 0);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)DXT1A, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    E(h, "0x0");
    level_queries(h, "0x0", GL_TEXTURE_2D, 0);
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    fc_value(h, "GL_EXT_texture_compression_s3tc listed",
             ext && strstr(ext, "GL_EXT_texture_compression_s3tc") != NULL);
}

const fc_case fc_cases_compressed[] = {
#define SC(n) FC_CASE_RGBA(n, 40, 40, 1, "gl13 compressed", sample_case)
    SC("compressed/dxt1_rgb_4colour_nearest"),
    SC("compressed/dxt1_rgb_3colour_nearest"),
    SC("compressed/dxt1_rgba_4colour_nearest"),
    SC("compressed/dxt1_rgba_3colour_nearest"),
    SC("compressed/dxt1_rgb_linear"),
    SC("compressed/dxt1_rgba_linear_modulate"),
    SC("compressed/dxt1_equal_endpoints"),
    SC("compressed/dxt3_nearest"),
    SC("compressed/dxt3_linear"),
    SC("compressed/dxt3_3colour_blocks"),
    SC("compressed/dxt5_7alpha_nearest"),
    SC("compressed/dxt5_5alpha_nearest"),
    SC("compressed/dxt5_linear"),
    SC("compressed/dxt5_equal_endpoints"),
    SC("compressed/dxt5_clamp_edge_linear"),
    SC("compressed/size_1x1"),
    SC("compressed/size_2x2"),
    SC("compressed/size_5x3"),
    SC("compressed/size_5x3_linear"),
    SC("compressed/size_13x7_linear"),
    SC("compressed/mip_dxt1_nearest_nearest"),
    SC("compressed/mip_dxt1a_nearest_linear"),
    SC("compressed/mip_dxt3_linear_nearest"),
    SC("compressed/mip_dxt5_linear_linear"),
    SC("compressed/mip_dxt5_npot_linear_linear"),
#undef SC
    FC_CASE_RGBA("compressed/sub_block_edges", 40, 40, 1, "gl13 compressed", sub_case),
    FC_CASE_RGBA("compressed/sub_whole_image", 40, 40, 1, "gl13 compressed", sub_case),
    FC_CASE_RGBA("compressed/sub_to_edge_npot", 40, 40, 1, "gl13 compressed", sub_case),
    FC_CASE_RGBA("compressed/sub_mip_level", 40, 40, 1, "gl13 compressed", sub_case),
    FC_CASE_RGBA("compressed/sub_errors", 16, 16, 0, "gl13 compressed errors", sub_errors_case),
    FC_CASE_RGBA("compressed/image_errors", 16, 16, 0, "gl13 compressed errors", image_errors_case),
    FC_CASE_RGBA("compressed/get_errors", 16, 16, 0, "gl13 compressed errors", get_errors_case),
    FC_CASE_RGBA("compressed/get_round_trip", 16, 16, 0, "gl13 compressed", round_trip_case),
    FC_CASE_RGBA("compressed/proxy", 16, 16, 0, "gl13 compressed", proxy_case),
    FC_CASE_RGBA("compressed/dlist", 40, 40, 2, "gl13 compressed dlist", dlist_case),
    FC_CASE_RGBA("compressed/queries_and_hint", 16, 16, 0, "gl13 compressed", queries_case),
    FC_CASE_RGBA("compressed/generic_alpha", 40, 40, 1, "gl13 compressed", generic_case),
    FC_CASE_RGBA("compressed/generic_intensity", 40, 40, 1, "gl13 compressed", generic_case),
    FC_CASE_RGBA("compressed/multitexture_pushattrib", 40, 40, 1, "gl13 compressed", multitex_case),
    FC_CASE_RGBA("compressed/mixed_levels", 40, 40, 4, "gl13 compressed", mixed_levels_case),
#define EC(n) FC_CASE_RGBA(n, 40, 40, 1, "gl13 compressed", encode_case)
    EC("compressed/encode_dxt1_random"),
    EC("compressed/encode_dxt1_gradient_linear"),
    EC("compressed/encode_dxt1_flat_colours"),
    EC("compressed/encode_dxt1_close_greys"),
    EC("compressed/encode_dxt1_npot_13x6"),
    EC("compressed/encode_dxt1_1x1"),
    EC("compressed/encode_dxt1_2x2"),
    EC("compressed/encode_dxt1_3x5"),
    EC("compressed/encode_dxt1a_alpha_edge"),
    EC("compressed/encode_dxt1a_alpha_levels"),
    EC("compressed/encode_dxt1a_gradient"),
    EC("compressed/encode_dxt1a_5x3"),
    EC("compressed/encode_dxt3_random"),
    EC("compressed/encode_dxt3_gradient_npot"),
    EC("compressed/encode_dxt3_alpha_levels"),
    EC("compressed/encode_dxt3_1x1"),
    EC("compressed/encode_dxt3_3x5"),
    EC("compressed/encode_dxt5_random"),
    EC("compressed/encode_dxt5_gradient_linear"),
    EC("compressed/encode_dxt5_alpha_edge"),
    EC("compressed/encode_dxt5_alpha_levels_npot"),
    EC("compressed/encode_dxt5_flat_colours"),
    EC("compressed/encode_dxt5_1x1"),
    EC("compressed/encode_dxt5_5x1"),
    EC("compressed/encode_dxt5_13x6"),
    EC("compressed/encode_generic_rgb"),
    EC("compressed/encode_generic_rgba"),
    EC("compressed/encode_generic_rgba_npot"),
#define LE(n) FC_CASE_RGBA(n, 40, 40, 1, "gl13 compressed latc", encode_case)
    LE("compressed/latc1_noise_nearest"),
    LE("compressed/latc1_ramp_linear"),
    LE("compressed/latc1_flat_blocks"),
    LE("compressed/latc1_close_values"),
    LE("compressed/latc1_levels"),
    LE("compressed/latc1_npot_13x6"),
    LE("compressed/latc1_npot_33x17_noise"),
    LE("compressed/latc1_1x1"),
    LE("compressed/latc1_5x3_ramp"),
    LE("compressed/latc1_3x5_flat"),
    LE("compressed/latc1_2x2_flat_linear"),
    LE("compressed/latc2_noise_nearest"),
    LE("compressed/latc2_ramp_linear"),
    LE("compressed/latc2_alpha_edge"),
    LE("compressed/latc2_alpha_levels_npot"),
    LE("compressed/latc2_flat_blocks"),
    LE("compressed/latc2_close_values"),
    LE("compressed/latc2_npot_13x6"),
    LE("compressed/latc2_1x1"),
    LE("compressed/latc2_5x1"),
    LE("compressed/latc2_3x5_flat"),
#undef EC
#undef LE
#define LC(n, w, hh, fr, f) FC_CASE_RGBA(n, w, hh, fr, "gl13 compressed latc", f)
    LC("compressed/latc1_sources", 40, 40, 1, latc_more_case),
    LC("compressed/latc2_sources", 40, 40, 1, latc_more_case),
    LC("compressed/latc1_sub_images", 40, 40, 1, latc_more_case),
    LC("compressed/latc2_sub_images", 40, 40, 1, latc_more_case),
    LC("compressed/latc1_copies", 40, 40, 1, latc_more_case),
    LC("compressed/latc2_copies", 40, 40, 1, latc_more_case),
    LC("compressed/latc1_queries_targets", 16, 16, 0, latc_more_case),
    LC("compressed/latc2_queries_targets", 16, 16, 0, latc_more_case),
    LC("compressed/latc1_3d_slices", 40, 40, 1, latc_more_case),
    LC("compressed/latc2_3d_slices", 40, 40, 1, latc_more_case),
    LC("compressed/latc1_3d_generic_rgb_slices", 40, 40, 1, latc_more_case),
    LC("compressed/latc1_3d_generic_rgba_ramp_slices", 40, 40, 1, latc_more_case),
    LC("compressed/latc1_3d_mipmap", 40, 40, 1, latc_more_case),
    LC("compressed/latc2_3d_mipmap", 40, 40, 1, latc_more_case),
    LC("compressed/latc1_3d_generic_rgba_mipmap", 40, 40, 1, latc_more_case),
    LC("compressed/latc1_mipmap_ll", 40, 40, 2, encode_mipmap_case),
    LC("compressed/latc1_mipmap_nn_npot", 40, 40, 2, encode_mipmap_case),
    LC("compressed/latc1_mipmap_nl_ramp", 40, 40, 2, encode_mipmap_case),
    LC("compressed/latc2_mipmap_ln", 40, 40, 2, encode_mipmap_case),
    LC("compressed/latc2_mipmap_ll_npot", 40, 40, 2, encode_mipmap_case),
    LC("compressed/latc2_mipmap_nn_ramp", 40, 40, 2, encode_mipmap_case),
#undef LC
    FC_CASE_RGBA("compressed/encode_sources", 16, 16, 0, "gl13 compressed", encode_sources_case),
    FC_CASE_RGBA("compressed/encode_sub_images", 40, 40, 2, "gl13 compressed", encode_sub_case),
    FC_CASE_RGBA("compressed/encode_copies", 40, 40, 1, "gl13 compressed", encode_copy_case),
    FC_CASE_RGBA("compressed/encode_mipmap_dxt1", 40, 40, 2, "gl13 compressed", encode_mipmap_case),
    FC_CASE_RGBA("compressed/encode_mipmap_dxt1a", 40, 40, 2, "gl13 compressed", encode_mipmap_case),
    FC_CASE_RGBA("compressed/encode_mipmap_dxt3", 40, 40, 2, "gl13 compressed", encode_mipmap_case),
    FC_CASE_RGBA("compressed/encode_mipmap_dxt5", 40, 40, 2, "gl13 compressed", encode_mipmap_case),
    FC_CASE_RGBA("compressed/encode_mipmap_generic_npot", 40, 40, 2, "gl13 compressed", encode_mipmap_case),
    FC_CASE_RGBA("compressed/encode_mipmap_dxt1_npot", 40, 40, 2, "gl13 compressed", encode_mipmap_case),
    FC_CASE_RGBA("compressed/encode_mipmap_dxt5_compressed_base", 40, 40, 2, "gl13 compressed", encode_mipmap_case),
    FC_CASE_RGBA("compressed/encode_mipmap_dxt1a_compressed_base", 40, 40, 2, "gl13 compressed", encode_mipmap_case),
    FC_CASE_RGBA("compressed/encode_errors", 16, 16, 0, "gl13 compressed errors", encode_errors_case),
    FC_CASE_RGBA("compressed/cube_faces_blocks", 48, 16, 1, "gl13 compressed cubemap", cube_case),
    FC_CASE_RGBA("compressed/cube_faces_encoded", 48, 16, 1, "gl13 compressed cubemap", cube_case),
    FC_CASE_RGBA("compressed/cube_faces_mixed_formats", 16, 16, 0, "gl13 compressed cubemap latc",
                 cube_mixed_case),
    FC_CASE_RGBA("compressed/latc_small_images", 104, 68, 1, "gl13 compressed latc",
                 latc_small_case),
    FC_CASE_RGBA("compressed/cube_faces_mixed_formats_more", 16, 16, 0,
                 "gl13 compressed cubemap latc", mixed_storage_case),
    FC_CASE_RGBA("compressed/cube_faces_mixed_formats_redrawn", 16, 16, 1,
                 "gl13 compressed cubemap", mixed_storage_case),
    FC_CASE_RGBA("compressed/mixed_storage_levels", 16, 16, 2, "gl13 compressed",
                 mixed_storage_case),
    { 0 },
};
