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
    { 0 },
};
