/* c_pix_format.c - client pixel formats and types (main/pixelformat.c):
 * glReadPixels of a rendered scene in every format x type the oracle
 * takes (the array types, the packed types, BGR/BGRA/ABGR, luminance as
 * R+G+B), with pack states (alignment, row length, skips, byte swapping,
 * LSB first), the pixel transfer operations (scale/bias, colour maps,
 * index shift/offset, stencil maps, depth scale/bias), depth, stencil and
 * depth/stencil reads in every type, and the format/type errors.
 * Destination buffers are pre-filled so untouched bytes compare too. */
#include "cases.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FILL 0x5C
#define W 16
#define H 12

/* A scene with every channel spanning 0..255, alpha included, a depth
 * ramp and (with a stencil buffer) stencil values from several passes. */
static void scene(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glShadeModel(GL_SMOOTH);
    fcu_clear(0.2f, 0.45f, 0.8f, 0.3f, 0.6);
    glClearStencil(0x5a);
    glClear(GL_STENCIL_BUFFER_BIT);
    glBegin(GL_QUADS);
    glColor4f(1, 0, 0, 0); glVertex3f(0, 0, -1.0f);
    glColor4f(0, 1, 0, 1); glVertex3f(W - 2, 0, 0.3f);
    glColor4f(1, 1, 1, 0.5f); glVertex3f(W - 2, H - 1, 1.0f);
    glColor4f(0, 0, 1, 0.8f); glVertex3f(0, H - 1, -0.2f);
    glEnd();
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0xc3, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColor4f(0.9f, 0.1f, 0.6f, 1.0f);
    fcu_tri(2, 1, 12, 3, 5, 10);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    fcu_tri(1, 6, 15, 8, 9, 12);
    glDisable(GL_STENCIL_TEST);
    glDepthFunc(GL_LESS);
}

/* Reads a w x ht region at (x, y) into a generously sized, pre-filled
 * buffer and records it with the glGetError after the call. */
static void rd_any(fc_h *h, const char *label, int x, int y, int w, int ht, GLenum format,
               GLenum type)
{
    /* room for 4 components of the largest type, row lengths up to 40 and
     * skips up to 8 rows at alignment 8 */
    const size_t size = 8 * 4 * 48 * 24 + 64;
    unsigned char *buf = malloc(size);
    memset(buf, FILL, size);
    glReadPixels(x, y, w, ht, format, type, buf);
    fc_error(h, label);
    fc_blob(h, label, buf, size);
    free(buf);
}

/* rd_any for the GL 1.5 cases: a foreign format or type (cases.h
 * fc_foreign_pixel) is left out, it is an honesty case's (below). */
static void rd(fc_h *h, const char *label, int x, int y, int w, int ht, GLenum format,
               GLenum type)
{
    if (!fc_foreign_pixel(format, type))
        rd_any(h, label, x, y, w, ht, format, type);
}

static const GLenum color_formats[] = {
    GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_RG, GL_RGB, GL_BGR, GL_RGBA, GL_BGRA,
    GL_ABGR_EXT, GL_LUMINANCE, GL_LUMINANCE_ALPHA,
};
#define N_COLOR_FORMATS (sizeof(color_formats) / sizeof(color_formats[0]))

static void read_all_formats(fc_h *h, GLenum type, int x, int y, int w, int ht)
{
    char label[64];
    for (size_t i = 0; i < N_COLOR_FORMATS; i++) {
        snprintf(label, sizeof(label), "format %#x type %#x", color_formats[i], type);
        rd(h, label, x, y, w, ht, color_formats[i], type);
    }
}

#define TYPE_CASE(fn, type)                          \
    static void fn(fc_h *h)                          \
    {                                                \
        scene(h);                                    \
        read_all_formats(h, type, 0, 0, W, H);       \
        glPixelStorei(GL_PACK_ALIGNMENT, 1);         \
        read_all_formats(h, type, 3, 2, 7, 5);       \
    }
TYPE_CASE(read_ubyte, GL_UNSIGNED_BYTE)
TYPE_CASE(read_byte, GL_BYTE)
TYPE_CASE(read_ushort, GL_UNSIGNED_SHORT)
TYPE_CASE(read_short, GL_SHORT)
TYPE_CASE(read_uint, GL_UNSIGNED_INT)
TYPE_CASE(read_int, GL_INT)
TYPE_CASE(read_float, GL_FLOAT)

/* Honesty (GL_HALF_FLOAT is GL 3.0's / ARB_half_float_pixel's, unlisted):
 * every colour format as GL_HALF_FLOAT, GL_INVALID_ENUM in fixgl. */
static void read_half(fc_h *h)
{
    char label[64];
    scene(h);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1)
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
        for (size_t i = 0; i < N_COLOR_FORMATS; i++) {
            snprintf(label, sizeof(label), "format %#x type %#x", color_formats[i],
                     GL_HALF_FLOAT);
            rd_any(h, label, pass ? 3 : 0, pass ? 2 : 0, pass ? 7 : W, pass ? 5 : H,
                   color_formats[i], GL_HALF_FLOAT);
        }
    }
}

/* Honesty: GL_RG with every basic type and the packed float types of
 * GL 3.0 (EXT_packed_float, EXT_texture_shared_exponent). */
static void read_foreign_formats_types(fc_h *h)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
    char label[64];
    scene(h);
    for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
        snprintf(label, sizeof(label), "format %#x type %#x", GL_RG, types[t]);
        rd_any(h, label, 0, 0, W, H, GL_RG, types[t]);
    }
    rd_any(h, "rgb 10f_11f_11f", 1, 1, 13, 9, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV);
    rd_any(h, "rgb 5_9_9_9", 1, 1, 13, 9, GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    rd_any(h, "swapped rgb 10f_11f_11f", 1, 1, 13, 9, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV);
    rd_any(h, "swapped rgb 5_9_9_9", 1, 1, 13, 9, GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV);
}

/* GL_HALF_FLOAT_OES (0x8D61) is the same array type for the formats the
 * oracle's special case lets through */
static void read_half_oes(fc_h *h)
{
    static const GLenum formats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE_ALPHA, GL_LUMINANCE,
                                     GL_ALPHA, GL_RG, GL_RED, GL_BGRA, GL_GREEN};
    char label[64];
    scene(h);
    for (size_t i = 0; i < sizeof(formats) / sizeof(formats[0]); i++) {
        snprintf(label, sizeof(label), "format %#x", formats[i]);
        rd_any(h, label, 2, 1, 11, 9, formats[i], 0x8D61);
    }
}

/* The packed types with every format they combine with. */
static void read_packed(fc_h *h)
{
    static const struct { GLenum type, formats[3]; } packed[] = {
        {GL_UNSIGNED_BYTE_3_3_2, {GL_RGB}},
        {GL_UNSIGNED_BYTE_2_3_3_REV, {GL_RGB}},
        {GL_UNSIGNED_SHORT_5_6_5, {GL_RGB}},
        {GL_UNSIGNED_SHORT_5_6_5_REV, {GL_RGB}},
        {GL_UNSIGNED_SHORT_4_4_4_4, {GL_RGBA, GL_BGRA, GL_ABGR_EXT}},
        {GL_UNSIGNED_SHORT_4_4_4_4_REV, {GL_RGBA, GL_BGRA, GL_ABGR_EXT}},
        {GL_UNSIGNED_SHORT_5_5_5_1, {GL_RGBA, GL_BGRA}},
        {GL_UNSIGNED_SHORT_1_5_5_5_REV, {GL_RGBA, GL_BGRA}},
        {GL_UNSIGNED_INT_8_8_8_8, {GL_RGBA, GL_BGRA, GL_ABGR_EXT}},
        {GL_UNSIGNED_INT_8_8_8_8_REV, {GL_RGBA, GL_BGRA, GL_ABGR_EXT}},
        {GL_UNSIGNED_INT_10_10_10_2, {GL_RGBA, GL_BGRA}},
        {GL_UNSIGNED_INT_2_10_10_10_REV, {GL_RGBA, GL_BGRA}},
        {GL_UNSIGNED_INT_10F_11F_11F_REV, {GL_RGB}},
        {GL_UNSIGNED_INT_5_9_9_9_REV, {GL_RGB}},
    };
    char label[64];
    scene(h);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) {
            glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
            glPixelStorei(GL_PACK_ALIGNMENT, 8);
        }
        for (size_t i = 0; i < sizeof(packed) / sizeof(packed[0]); i++) {
            for (int f = 0; f < 3 && packed[i].formats[f]; f++) {
                snprintf(label, sizeof(label), "pass %d format %#x type %#x", pass,
                         packed[i].formats[f], packed[i].type);
                rd(h, label, 1, 1, 13, 9, packed[i].formats[f], packed[i].type);
            }
        }
    }
}

/* Alignment, row length, skips and byte swapping on several types. */
static void read_pack_state(fc_h *h)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_INT, GL_FLOAT,
                                   GL_HALF_FLOAT, GL_UNSIGNED_SHORT_5_6_5};
    static const GLenum formats[] = {GL_RGB, GL_LUMINANCE_ALPHA, GL_BGR, GL_RGB, GL_ALPHA,
                                     GL_RGB};
    char label[96];
    scene(h);
    for (int s = 0; s < 5; s++) {
        static const int align[] = {1, 2, 4, 8, 2};
        static const int rowlen[] = {0, 11, 0, 17, 40};
        static const int skipp[] = {0, 2, 3, 0, 5};
        static const int skipr[] = {0, 1, 0, 4, 2};
        static const int swap[] = {0, 1, 0, 1, 1};
        glPixelStorei(GL_PACK_ALIGNMENT, align[s]);
        glPixelStorei(GL_PACK_ROW_LENGTH, rowlen[s]);
        glPixelStorei(GL_PACK_SKIP_PIXELS, skipp[s]);
        glPixelStorei(GL_PACK_SKIP_ROWS, skipr[s]);
        glPixelStorei(GL_PACK_SWAP_BYTES, swap[s]);
        glPixelStorei(GL_PACK_LSB_FIRST, s & 1);
        for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
            snprintf(label, sizeof(label), "state %d format %#x type %#x", s, formats[t],
                     types[t]);
            rd(h, label, 2, 1, 9, 7, formats[t], types[t]);
            snprintf(label, sizeof(label), "state %d clipped format %#x type %#x", s,
                     formats[t], types[t]);
            rd(h, label, -3, -2, 9, 7, formats[t], types[t]);
        }
    }
}

static void set_maps(void)
{
    GLfloat ramp[16], inv[4], a2[2] = {0.25f, 1.0f};
    for (int i = 0; i < 16; i++)
        ramp[i] = (float)(i * i) / 225.0f;
    for (int i = 0; i < 4; i++)
        inv[i] = 1.0f - (float)i / 3.0f;
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 16, ramp);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 4, inv);
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, a2);
}

/* Scale and bias (out of [0, 1] too), then the colour maps, on reads of
 * several formats and types; the clamp applies to the 8-bit types and
 * the R+G+B luminance only. */
static void read_transfer(fc_h *h)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_FLOAT, GL_SHORT, GL_UNSIGNED_SHORT,
                                   GL_UNSIGNED_SHORT_4_4_4_4, GL_UNSIGNED_INT_10_10_10_2,
                                   GL_HALF_FLOAT, GL_UNSIGNED_INT_10F_11F_11F_REV,
                                   GL_UNSIGNED_INT_5_9_9_9_REV};
    static const GLenum formats[] = {GL_RGBA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_BGR};
    char label[96];
    scene(h);
    for (int s = 0; s < 4; s++) {
        if (s == 0) {
            glPixelTransferf(GL_RED_SCALE, 1.7f);
            glPixelTransferf(GL_GREEN_BIAS, -0.3f);
            glPixelTransferf(GL_ALPHA_SCALE, -0.5f);
            glPixelTransferf(GL_ALPHA_BIAS, 0.75f);
        } else if (s == 1) {
            set_maps();
            glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
        } else if (s == 2) {
            glPixelTransferf(GL_RED_SCALE, 1.0f);
            glPixelTransferf(GL_GREEN_BIAS, 0.0f);
            glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
            glPixelTransferf(GL_ALPHA_BIAS, 0.0f);
        } else {
            /* index shift/offset alone: no visible operation, but the
             * float path */
            glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
            glPixelTransferi(GL_INDEX_SHIFT, 1);
            glPixelTransferi(GL_INDEX_OFFSET, 3);
        }
        for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
            for (size_t f = 0; f < sizeof(formats) / sizeof(formats[0]); f++) {
                GLenum fmt = formats[f];
                if (types[t] == GL_UNSIGNED_SHORT_4_4_4_4 ||
                    types[t] == GL_UNSIGNED_INT_10_10_10_2)
                    fmt = f & 1 ? GL_BGRA : GL_RGBA;
                else if (types[t] == GL_UNSIGNED_INT_10F_11F_11F_REV ||
                         types[t] == GL_UNSIGNED_INT_5_9_9_9_REV)
                    fmt = GL_RGB;
                snprintf(label, sizeof(label), "transfer %d format %#x type %#x", s, fmt,
                         types[t]);
                rd(h, label, 0, 0, W, H, fmt, types[t]);
            }
        }
    }
}

static void read_depth_types(fc_h *h)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_HALF_FLOAT};
    char label[96];
    scene(h);
    for (int s = 0; s < 3; s++) {
        if (s == 1) {
            glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
            glPixelStorei(GL_PACK_ALIGNMENT, 2);
        } else if (s == 2) {
            glPixelTransferf(GL_DEPTH_SCALE, 1.5f);
            glPixelTransferf(GL_DEPTH_BIAS, -0.25f);
        }
        for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
            snprintf(label, sizeof(label), "depth %d type %#x", s, types[t]);
            rd(h, label, 1, 0, 13, 11, GL_DEPTH_COMPONENT, types[t]);
        }
    }
}

static void read_stencil_types(fc_h *h)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_HALF_FLOAT, GL_BITMAP};
    char label[96];
    scene(h);
    for (int s = 0; s < 5; s++) {
        if (s == 1) {
            glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
            glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
            glPixelStorei(GL_PACK_SKIP_PIXELS, 3);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
        } else if (s == 2) {
            glPixelTransferi(GL_INDEX_SHIFT, -2);
            glPixelTransferi(GL_INDEX_OFFSET, 7);
        } else if (s == 3) {
            GLfloat map[8] = {3, 250, 17, 0, 128, 64, 1, 99};
            glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 8, map);
            glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
        } else if (s == 4) {
            glPixelTransferi(GL_INDEX_SHIFT, 3);
            glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
        }
        for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
            /* GL_BITMAP without a stencil transfer operation reaches the
             * oracle's memcpy test, _mesa_format_from_format_and_type's
             * unreachable() (undefined behaviour: it hangs) */
            if (types[t] == GL_BITMAP && s < 2)
                continue;
            snprintf(label, sizeof(label), "stencil %d type %#x", s, types[t]);
            rd(h, label, 0, 0, W, H, GL_STENCIL_INDEX, types[t]);
            snprintf(label, sizeof(label), "stencil %d clipped type %#x", s, types[t]);
            rd(h, label, -5, 3, 19, 4, GL_STENCIL_INDEX, types[t]);
        }
    }
}

static void read_depth_stencil(fc_h *h)
{
    char label[96];
    scene(h);
    for (int s = 0; s < 4; s++) {
        if (s == 1) {
            glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
        } else if (s == 2) {
            glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
            glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
            glPixelTransferi(GL_INDEX_OFFSET, 1);
        } else if (s == 3) {
            glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
        }
        snprintf(label, sizeof(label), "depth/stencil %d 24_8", s);
        rd_any(h, label, 1, 1, 14, 10, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8);
        snprintf(label, sizeof(label), "depth/stencil %d float_32_24_8", s);
        rd_any(h, label, 1, 1, 14, 10, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV);
    }
}

/* Format/type combinations the oracle refuses, with the error it raises
 * ([S: glformats.c:_mesa_error_check_format_and_type], readpix.c). */
static void read_errors_of(fc_h *h, int foreign)
{
    static const struct { GLenum format, type; } bad[] = {
        {GL_RGBA, GL_BITMAP}, {GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4},
        {GL_RGBA, GL_UNSIGNED_SHORT_5_6_5}, {GL_BGR, GL_UNSIGNED_SHORT_5_6_5},
        {GL_BGR, GL_UNSIGNED_BYTE_3_3_2}, {GL_LUMINANCE, GL_UNSIGNED_INT_8_8_8_8},
        {GL_ABGR_EXT, GL_UNSIGNED_SHORT_5_5_5_1}, {GL_ABGR_EXT, GL_UNSIGNED_INT_10_10_10_2},
        {GL_RGB, GL_UNSIGNED_INT_2_10_10_10_REV}, {GL_RGBA, GL_UNSIGNED_INT_24_8},
        {GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8}, {GL_DEPTH_STENCIL, GL_UNSIGNED_INT},
        {GL_DEPTH_STENCIL, GL_FLOAT}, {GL_RGBA, GL_UNSIGNED_INT_10F_11F_11F_REV},
        {GL_BGR, GL_UNSIGNED_INT_10F_11F_11F_REV}, {GL_RGBA, GL_UNSIGNED_INT_5_9_9_9_REV},
        {GL_RGBA, GL_DOUBLE}, {GL_BGRA, 0x8D61 /* GL_HALF_FLOAT_OES */},
        {GL_RGBA_INTEGER, GL_FLOAT}, {GL_RGB_INTEGER, GL_UNSIGNED_SHORT_5_6_5}, {GL_INTENSITY, GL_UNSIGNED_BYTE}, {GL_COLOR_INDEX, GL_UNSIGNED_BYTE},
        {GL_COLOR_INDEX, GL_BITMAP}, {GL_COLOR_INDEX, GL_RGBA}, {GL_STENCIL_INDEX, GL_RGBA},
        {GL_STENCIL_INDEX, GL_UNSIGNED_BYTE}, {GL_DEPTH_COMPONENT, GL_BITMAP},
        {GL_RGBA_INTEGER, GL_UNSIGNED_BYTE}, {GL_RED_INTEGER, GL_FLOAT},
        {GL_RGBA8, GL_UNSIGNED_BYTE}, {GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT},
        {GL_RG, GL_UNSIGNED_SHORT_5_6_5}, {GL_STENCIL_INDEX, GL_UNSIGNED_SHORT_4_4_4_4},
        {0x1234, GL_FLOAT}, {GL_LUMINANCE_ALPHA, GL_BITMAP},
    };
    char label[96];
    scene(h);
    for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
        if (fc_foreign_pixel(bad[i].format, bad[i].type) != foreign)
            continue;
        snprintf(label, sizeof(label), "format %#x type %#x", bad[i].format, bad[i].type);
        rd_any(h, label, 0, 0, 4, 3, bad[i].format, bad[i].type);
    }
    glReadBuffer(GL_NONE);
    rd(h, "read buffer none, LUMINANCE", 0, 0, 4, 3, GL_LUMINANCE, GL_FLOAT);
    rd(h, "read buffer none, bad type", 0, 0, 4, 3, GL_LUMINANCE, GL_UNSIGNED_SHORT_5_6_5);
    rd(h, "read buffer none, DEPTH", 0, 0, 4, 3, GL_DEPTH_COMPONENT, GL_FLOAT);
}

/* Without depth and stencil buffers the depth, stencil and colour-index
 * reads fail first on the missing buffer. */
static void read_errors_no_zs_of(fc_h *h, int foreign)
{
    static const struct { GLenum format, type; } bad[] = {
        {GL_STENCIL_INDEX, GL_UNSIGNED_BYTE}, {GL_STENCIL_INDEX, GL_RGBA},
        {GL_COLOR_INDEX, GL_UNSIGNED_BYTE}, {GL_COLOR_INDEX, 0x1234},
        {GL_DEPTH_COMPONENT, GL_FLOAT}, {GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8},
        {GL_DEPTH_STENCIL, GL_FLOAT}, {0x1234, GL_UNSIGNED_BYTE},
        {GL_RGBA_INTEGER, GL_UNSIGNED_BYTE}, {GL_LUMINANCE, GL_FLOAT},
    };
    char label[96];
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.7f, 0.4f, 0.9f, 1.0);
    for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
        if (fc_foreign_pixel(bad[i].format, bad[i].type) != foreign)
            continue;
        snprintf(label, sizeof(label), "format %#x type %#x", bad[i].format, bad[i].type);
        rd_any(h, label, 0, 0, 4, 3, bad[i].format, bad[i].type);
    }
}

static void read_errors(fc_h *h) { read_errors_of(h, 0); }
static void read_errors_foreign(fc_h *h) { read_errors_of(h, 1); }
static void read_errors_no_zs(fc_h *h) { read_errors_no_zs_of(h, 0); }
static void read_errors_no_zs_foreign(fc_h *h) { read_errors_no_zs_of(h, 1); }

#define ZS(name, fn) FC_CASE(name, W, H, OSMESA_RGBA, 24, 8, 0, "pixel readpixels", fn)

const fc_case fc_cases_pix_format[] = {
    ZS("pixel/readpixels_ubyte_formats", read_ubyte),
    ZS("pixel/readpixels_byte_formats", read_byte),
    ZS("pixel/readpixels_ushort_formats", read_ushort),
    ZS("pixel/readpixels_short_formats", read_short),
    ZS("pixel/readpixels_uint_formats", read_uint),
    ZS("pixel/readpixels_int_formats", read_int),
    ZS("pixel/readpixels_float_formats", read_float),
    ZS("pixel/readpixels_packed_types", read_packed),
    /* B8G8R8A8 / A8R8G8B8 buffers: the 10-bit fields pack through float */
    FC_CASE("pixel/readpixels_packed_types_bgra", W, H, OSMESA_BGRA, 24, 8, 0,
            "pixel readpixels", read_packed),
    FC_CASE("pixel/readpixels_packed_types_argb", W, H, OSMESA_ARGB, 24, 8, 0,
            "pixel readpixels", read_packed),
    FC_CASE("pixel/readpixels_ushort_formats_bgra", W, H, OSMESA_BGRA, 24, 8, 0,
            "pixel readpixels", read_ushort),
    ZS("pixel/readpixels_pack_state", read_pack_state),
    ZS("pixel/readpixels_transfer_ops", read_transfer),
    ZS("pixel/readpixels_depth_types", read_depth_types),
    ZS("pixel/readpixels_stencil_types", read_stencil_types),
    ZS("pixel/readpixels_format_type_errors", read_errors),
    FC_CASE("pixel/readpixels_errors_no_depth_stencil", W, H, OSMESA_BGRA, 0, 0, 0,
            "pixel readpixels error", read_errors_no_zs),
    /* Honesty: the oracle's GL 3.0 client formats and types, which fixgl
     * (GL 1.5 without ARB_half_float_pixel, ARB_texture_rg,
     * EXT_packed_depth_stencil, EXT_texture_integer, EXT_packed_float,
     * EXT_texture_shared_exponent) refuses with GL_INVALID_ENUM:
     * deliberate differences (known-differences.txt). */
    FC_CASE("honesty/readpixels_half_float_formats", W, H, OSMESA_RGBA, 24, 8, 0,
            "honesty pixel readpixels", read_half),
    FC_CASE("honesty/readpixels_half_float_oes", W, H, OSMESA_RGBA, 24, 8, 0,
            "honesty pixel readpixels", read_half_oes),
    FC_CASE("honesty/readpixels_depth_stencil", W, H, OSMESA_RGBA, 24, 8, 0,
            "honesty pixel readpixels", read_depth_stencil),
    FC_CASE("honesty/readpixels_rg_packed_float", W, H, OSMESA_RGBA, 24, 8, 0,
            "honesty pixel readpixels", read_foreign_formats_types),
    FC_CASE("honesty/readpixels_format_type_errors", W, H, OSMESA_RGBA, 24, 8, 0,
            "honesty pixel readpixels error", read_errors_foreign),
    FC_CASE("honesty/readpixels_errors_no_depth_stencil", W, H, OSMESA_BGRA, 0, 0, 0,
            "honesty pixel readpixels error", read_errors_no_zs_foreign),
    { 0 }
};

/* ------------------------------------------------------------------ */
/* Texture uploads: every client format x type stored into 8-bit       */
/* textures (texstore.c's paths), read back with glGetTexImage as      */
/* GL_RGBA / GL_UNSIGNED_BYTE.                                         */
/* ------------------------------------------------------------------ */

#define TW 7
#define TH 5

static unsigned next_rand(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return *s >> 8;
}

/* float values around [0, 1]: exact ends, k/255 and in-between values,
 * negatives and values above 1 */
static float rand_float(unsigned *s)
{
    const unsigned r = next_rand(s);
    switch (r % 8) {
    case 0: return 0.0f;
    case 1: return 1.0f;
    case 2: return (float)(r % 256) / 255.0f;
    case 3: return ((float)(r % 256) + 0.5f) / 255.0f;
    case 4: return -(float)(r % 100) / 64.0f;
    case 5: return 1.0f + (float)(r % 100) / 32.0f;
    default: return (float)(r % 100000) / 100000.0f;
    }
}

static unsigned short to_half(float f)
{
    /* round to nearest of the few exact halves we use: via the bits of f
     * truncated (values chosen so both sides agree on the input) */
    union { float f; unsigned u; } v = {f};
    const unsigned s = (v.u >> 16) & 0x8000;
    int e = (int)((v.u >> 23) & 0xff) - 127 + 15;
    if ((v.u & 0x7fffffff) == 0)
        return (unsigned short)s;
    if (e <= 0)
        return (unsigned short)s;
    if (e >= 31)
        return (unsigned short)(s | 0x7bff);
    return (unsigned short)(s | ((unsigned)e << 10) | ((v.u >> 13) & 0x3ff));
}

/* A client image buffer of `size` bytes holding values of `type`. */
static unsigned char *client_image(size_t size, GLenum type, unsigned seed)
{
    unsigned char *buf = malloc(size);
    unsigned s = seed;
    if (type == GL_FLOAT) {
        for (size_t i = 0; i + 4 <= size; i += 4) {
            const float f = rand_float(&s);
            memcpy(buf + i, &f, 4);
        }
    } else if (type == GL_HALF_FLOAT) {
        for (size_t i = 0; i + 2 <= size; i += 2) {
            const unsigned short hv = to_half(rand_float(&s));
            memcpy(buf + i, &hv, 2);
        }
    } else {
        for (size_t i = 0; i < size; i++)
            buf[i] = (unsigned char)next_rand(&s);
    }
    return buf;
}

/* Uploads a w x ht image of format/type into a texture of internal
 * format `internal` and records the error and the texels read back. */
static void up_any(fc_h *h, const char *label, GLint internal, int w, int ht, GLenum format,
                   GLenum type, unsigned seed)
{
    const size_t size = 8 * 4 * 48 * 24;
    unsigned char *img = client_image(size, type, seed);
    unsigned char back[TW * TH * 4 * 4 + 64];
    memset(back, FILL, sizeof(back));
    glTexImage2D(GL_TEXTURE_2D, 0, internal, w, ht, 0, format, type, img);
    fc_error(h, label);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    fc_error(h, label);
    fc_blob(h, label, back, sizeof(back));
    free(img);
}

/* up_any for the GL 1.5 cases: foreign formats and types left out. */
static void up(fc_h *h, const char *label, GLint internal, int w, int ht, GLenum format,
               GLenum type, unsigned seed)
{
    if (!fc_foreign_pixel(format, type))
        up_any(h, label, internal, w, ht, format, type, seed);
}

static void upload_all_formats(fc_h *h, GLenum type)
{
    char label[64];
    for (size_t i = 0; i < N_COLOR_FORMATS; i++) {
        snprintf(label, sizeof(label), "format %#x type %#x", color_formats[i], type);
        up(h, label, GL_RGBA8, TW, TH, color_formats[i], type, 17u + (unsigned)i);
    }
}

#define UPLOAD_CASE(fn, type)                       \
    static void fn(fc_h *h)                         \
    {                                               \
        upload_all_formats(h, type);                \
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);      \
        upload_all_formats(h, type);                \
    }
UPLOAD_CASE(upload_ubyte, GL_UNSIGNED_BYTE)
UPLOAD_CASE(upload_byte, GL_BYTE)
UPLOAD_CASE(upload_ushort, GL_UNSIGNED_SHORT)
UPLOAD_CASE(upload_short, GL_SHORT)
UPLOAD_CASE(upload_uint, GL_UNSIGNED_INT)
UPLOAD_CASE(upload_int, GL_INT)
UPLOAD_CASE(upload_float, GL_FLOAT)

/* Honesty: every colour format as GL_HALF_FLOAT, GL_RG with every basic
 * type, the packed float types (GL_INVALID_ENUM in fixgl). */
static void upload_half(fc_h *h)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
    char label[64];
    for (size_t i = 0; i < N_COLOR_FORMATS; i++) {
        snprintf(label, sizeof(label), "format %#x type %#x", color_formats[i], GL_HALF_FLOAT);
        up_any(h, label, GL_RGBA8, TW, TH, color_formats[i], GL_HALF_FLOAT, 17u + (unsigned)i);
    }
    for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
        snprintf(label, sizeof(label), "format %#x type %#x", GL_RG, types[t]);
        up_any(h, label, GL_RGBA8, TW, TH, GL_RG, types[t], 40u + (unsigned)t);
    }
    up_any(h, "rgb 10f_11f_11f", GL_RGBA8, TW, TH, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, 60u);
    up_any(h, "rgb 5_9_9_9", GL_RGBA8, TW, TH, GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV, 61u);
    up_any(h, "depth_stencil 24_8", GL_RGBA8, TW, TH, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 62u);
    up_any(h, "rgba_integer ubyte", GL_RGBA8, TW, TH, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, 63u);
}

static void upload_packed(fc_h *h)
{
    static const struct { GLenum type, formats[3]; } packed[] = {
        {GL_UNSIGNED_BYTE_3_3_2, {GL_RGB}},
        {GL_UNSIGNED_BYTE_2_3_3_REV, {GL_RGB}},
        {GL_UNSIGNED_SHORT_5_6_5, {GL_RGB}},
        {GL_UNSIGNED_SHORT_5_6_5_REV, {GL_RGB}},
        {GL_UNSIGNED_SHORT_4_4_4_4, {GL_RGBA, GL_BGRA, GL_ABGR_EXT}},
        {GL_UNSIGNED_SHORT_4_4_4_4_REV, {GL_RGBA, GL_BGRA, GL_ABGR_EXT}},
        {GL_UNSIGNED_SHORT_5_5_5_1, {GL_RGBA, GL_BGRA}},
        {GL_UNSIGNED_SHORT_1_5_5_5_REV, {GL_RGBA, GL_BGRA}},
        {GL_UNSIGNED_INT_8_8_8_8, {GL_RGBA, GL_BGRA, GL_ABGR_EXT}},
        {GL_UNSIGNED_INT_8_8_8_8_REV, {GL_RGBA, GL_BGRA, GL_ABGR_EXT}},
        {GL_UNSIGNED_INT_10_10_10_2, {GL_RGBA, GL_BGRA}},
        {GL_UNSIGNED_INT_2_10_10_10_REV, {GL_RGBA, GL_BGRA}},
        {GL_UNSIGNED_INT_10F_11F_11F_REV, {GL_RGB}},
        {GL_UNSIGNED_INT_5_9_9_9_REV, {GL_RGB}},
    };
    char label[64];
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) {
            glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
        }
        for (size_t i = 0; i < sizeof(packed) / sizeof(packed[0]); i++) {
            for (int f = 0; f < 3 && packed[i].formats[f]; f++) {
                snprintf(label, sizeof(label), "pass %d format %#x type %#x", pass,
                         packed[i].formats[f], packed[i].type);
                up(h, label, GL_RGBA8, TW, TH, packed[i].formats[f], packed[i].type,
                   100u + (unsigned)(i * 3 + (size_t)f));
            }
        }
    }
}

/* The unpack state.  GL_UNPACK_SWAP_BYTES goes with zero skips only: the
 * oracle swaps the image into a temporary from its base address and then
 * applies the skips to that temporary (texstore.c:texstore_rgba), so
 * skipped texels read bytes it never wrote. */
static void upload_unpack_state(fc_h *h)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_INT, GL_FLOAT,
                                   GL_HALF_FLOAT, GL_UNSIGNED_SHORT_5_6_5};
    static const GLenum formats[] = {GL_RGB, GL_LUMINANCE_ALPHA, GL_BGR, GL_RGB, GL_ALPHA,
                                     GL_RGB};
    char label[96];
    for (int s = 0; s < 6; s++) {
        static const int align[] = {1, 2, 4, 8, 2, 8};
        static const int rowlen[] = {0, 11, 0, 17, 40, 13};
        static const int skipp[] = {0, 0, 3, 0, 5, 0};
        static const int skipr[] = {0, 0, 0, 4, 2, 0};
        static const int swap[] = {0, 1, 0, 0, 0, 1};
        glPixelStorei(GL_UNPACK_ALIGNMENT, align[s]);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, rowlen[s]);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, skipp[s]);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, skipr[s]);
        glPixelStorei(GL_UNPACK_SWAP_BYTES, swap[s]);
        for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
            snprintf(label, sizeof(label), "state %d format %#x type %#x", s, formats[t],
                     types[t]);
            up(h, label, GL_RGBA8, TW, TH, formats[t], types[t], 300u + (unsigned)t);
        }
    }
}

/* Pixel transfer on uploads: scale/bias, the colour maps, and the index
 * shift/offset alone (which sends the image through float); on that path
 * the oracle ignores SKIP_PIXELS and SKIP_ROWS (texstore_rgba converts
 * from the image's base address). */
static void upload_transfer(fc_h *h)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_FLOAT, GL_SHORT, GL_UNSIGNED_SHORT,
                                   GL_UNSIGNED_SHORT_4_4_4_4, GL_UNSIGNED_INT_10_10_10_2,
                                   GL_HALF_FLOAT, GL_UNSIGNED_INT_5_9_9_9_REV};
    char label[96];
    for (int s = 0; s < 5; s++) {
        if (s == 4) {
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
            glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, 10);
            glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
        }
        if (s == 0) {
            glPixelTransferf(GL_RED_SCALE, 1.7f);
            glPixelTransferf(GL_GREEN_BIAS, -0.3f);
            glPixelTransferf(GL_BLUE_SCALE, 0.37f);
            glPixelTransferf(GL_ALPHA_SCALE, -0.5f);
            glPixelTransferf(GL_ALPHA_BIAS, 0.75f);
        } else if (s == 1) {
            set_maps();
            glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
        } else if (s == 2) {
            glPixelTransferf(GL_RED_SCALE, 1.0f);
            glPixelTransferf(GL_GREEN_BIAS, 0.0f);
            glPixelTransferf(GL_BLUE_SCALE, 1.0f);
            glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
            glPixelTransferf(GL_ALPHA_BIAS, 0.0f);
        } else if (s == 3) {
            glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
            glPixelTransferi(GL_INDEX_OFFSET, 2);
        }
        for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
            GLenum fmt = t & 1 ? GL_RGBA : GL_LUMINANCE_ALPHA;
            if (types[t] == GL_UNSIGNED_SHORT_4_4_4_4 || types[t] == GL_UNSIGNED_INT_10_10_10_2)
                fmt = GL_BGRA;
            else if (types[t] == GL_UNSIGNED_INT_5_9_9_9_REV)
                fmt = GL_RGB;
            snprintf(label, sizeof(label), "transfer %d format %#x type %#x", s, fmt, types[t]);
            up(h, label, GL_RGBA8, TW, TH, fmt, types[t], 500u + (unsigned)t);
        }
    }
}

/* Colour indices through the I_TO_R/G/B/A maps (shifted and offset),
 * every index type, GL_BITMAP with LSB_FIRST.  The oracle reads the
 * width*height indices as one span from the first pixel (no row padding)
 * and then addresses the RGBA image it made from them with the unpack
 * state a second time (texstore.c:texstore_rgba); the states keep every
 * texel inside that image (beyond it the oracle reads past its buffer). */
static void set_index_maps(void)
{
    GLfloat r[16], g[16], b[4], a[2] = {0.2f, 0.9f};
    for (int i = 0; i < 16; i++) {
        r[i] = (float)i / 15.0f;
        g[i] = 1.0f - (float)(i * i) / 225.0f;
    }
    for (int i = 0; i < 4; i++)
        b[i] = (float)i * 0.3f;
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 16, r);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 16, g);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, a);
}

static void upload_color_index_types(fc_h *h, const GLenum *types, size_t ntypes)
{
    char label[96];
    set_index_maps();
    for (int s = 0; s < 5; s++) {
        if (s == 1) {
            glPixelTransferi(GL_INDEX_SHIFT, 2);
            glPixelTransferi(GL_INDEX_OFFSET, -3);
        } else if (s == 2) {
            glPixelTransferi(GL_INDEX_SHIFT, -1);
            glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
            glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
        } else if (s == 3) {
            /* scale/bias and MAP_COLOR do not apply to indices */
            glPixelTransferf(GL_RED_SCALE, 0.5f);
            glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
            glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
        } else if (s == 4) {
            /* the skips applied twice, rows 2 pixels apart */
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, 2);
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
            glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
        }
        for (size_t t = 0; t < ntypes; t++) {
            snprintf(label, sizeof(label), "index %d type %#x", s, types[t]);
            up_any(h, label, GL_RGBA8, TW, TH, GL_COLOR_INDEX, types[t], 700u + (unsigned)t);
        }
    }
}

static void upload_color_index(fc_h *h)
{   /* GL 1.5's index types only */
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_BITMAP};
    upload_color_index_types(h, types, sizeof(types) / sizeof(types[0]));
}

static void upload_color_index_half(fc_h *h)
{
    static const GLenum types[] = {GL_HALF_FLOAT};
    upload_color_index_types(h, types, 1);
}

/* The 8-bit base formats other than RGBA (Mesa's rebase: luminance and
 * intensity take red). */
static void upload_bases(fc_h *h)
{
    static const GLint internals[] = {GL_LUMINANCE8, GL_ALPHA8, GL_LUMINANCE8_ALPHA8,
                                      GL_INTENSITY8, GL_RGB8, GL_RGBA8};
    static const struct { GLenum format, type; } src[] = {
        {GL_RGBA, GL_UNSIGNED_BYTE}, {GL_BGRA, GL_FLOAT}, {GL_LUMINANCE_ALPHA, GL_SHORT},
        {GL_RGB, GL_UNSIGNED_SHORT_5_6_5}, {GL_ALPHA, GL_UNSIGNED_INT},
        {GL_COLOR_INDEX, GL_UNSIGNED_BYTE},
    };
    char label[96];
    GLfloat m[4] = {0.1f, 0.5f, 0.7f, 1.0f};
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, m);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, m);
    for (size_t i = 0; i < sizeof(internals) / sizeof(internals[0]); i++) {
        for (size_t k = 0; k < sizeof(src) / sizeof(src[0]); k++) {
            snprintf(label, sizeof(label), "internal %#x format %#x type %#x", internals[i],
                     src[k].format, src[k].type);
            up(h, label, internals[i], TW, TH, src[k].format, src[k].type,
               900u + (unsigned)(i * 8 + k));
        }
    }
}

/* Unsized internal formats: the oracle picks the texture format that
 * matches format/type when it has the internal format's base
 * (st_format.c:st_choose_format), e.g. R16G16B16A16 for GL_RGBA +
 * GL_UNSIGNED_SHORT; read back as 8 bits the values agree with the 8-bit
 * store. */
static void upload_unsized(fc_h *h)
{
    static const GLint internals[] = {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA,
                                      GL_ALPHA, GL_INTENSITY, 3, 4};
    static const struct { GLenum format, type; } src[] = {
        {GL_RGBA, GL_UNSIGNED_SHORT}, {GL_BGRA, GL_UNSIGNED_BYTE}, {GL_RGB, GL_FLOAT},
        {GL_LUMINANCE, GL_UNSIGNED_SHORT}, {GL_ALPHA, GL_UNSIGNED_BYTE},
        {GL_LUMINANCE_ALPHA, GL_BYTE}, {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8},
        {GL_BGR, GL_HALF_FLOAT},
    };
    char label[96];
    for (size_t i = 0; i < sizeof(internals) / sizeof(internals[0]); i++) {
        for (size_t k = 0; k < sizeof(src) / sizeof(src[0]); k++) {
            snprintf(label, sizeof(label), "internal %#x format %#x type %#x", internals[i],
                     src[k].format, src[k].type);
            up(h, label, internals[i], TW, TH, src[k].format, src[k].type,
               1100u + (unsigned)(i * 8 + k));
        }
    }
}

/* glTexImage1D takes the same path (one row; SKIP_ROWS still applies). */
static void upload_1d(fc_h *h)
{
    static const struct { GLenum format, type; } src[] = {
        {GL_RGBA, GL_UNSIGNED_BYTE}, {GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV},
        {GL_LUMINANCE_ALPHA, GL_FLOAT}, {GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV},
        {GL_COLOR_INDEX, GL_BITMAP}, {GL_RED, GL_INT},
    };
    char label[96];
    set_index_maps();
    for (int s = 0; s < 2; s++) {
        if (s == 1) {
            glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, 9);
        }
        for (size_t k = 0; k < sizeof(src) / sizeof(src[0]); k++) {
            if (s == 1 && src[k].format == GL_COLOR_INDEX)
                continue;   /* the colour-index image addressed twice reads past it */
            const size_t size = 8 * 4 * 48 * 24;
            unsigned char *img = client_image(size, src[k].type, 1300u + (unsigned)k);
            unsigned char back[TW * 4 + 64];
            memset(back, FILL, sizeof(back));
            snprintf(label, sizeof(label), "1D %d format %#x type %#x", s, src[k].format,
                     src[k].type);
            glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, TW, 0, src[k].format, src[k].type, img);
            fc_error(h, label);
            glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
            fc_error(h, label);
            fc_blob(h, label, back, sizeof(back));
            free(img);
        }
    }
}

/* glGetTexImage in every format x type from 8-bit textures of each base
 * format (texgetimage.c:get_tex_rgba_uncompressed: L/I read as
 * (L, 0, 0, 1), luminance = R, only a clamp for LUMINANCE destinations
 * of unsigned types, no pixel transfer), with pack states. */
static void get_all(fc_h *h, const char *what, int foreign)
{
    static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_HALF_FLOAT};
    static const struct { GLenum type, format; } packed[] = {
        {GL_UNSIGNED_BYTE_3_3_2, GL_RGB}, {GL_UNSIGNED_SHORT_5_6_5_REV, GL_RGB},
        {GL_UNSIGNED_SHORT_4_4_4_4, GL_ABGR_EXT}, {GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_BGRA},
        {GL_UNSIGNED_INT_8_8_8_8, GL_RGBA}, {GL_UNSIGNED_INT_10_10_10_2, GL_RGBA},
        {GL_UNSIGNED_INT_2_10_10_10_REV, GL_BGRA}, {GL_UNSIGNED_INT_10F_11F_11F_REV, GL_RGB},
        {GL_UNSIGNED_INT_5_9_9_9_REV, GL_RGB},
    };
    const size_t size = 8 * 4 * 48 * 24;
    unsigned char *buf = malloc(size);
    char label[96];
    for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
        for (size_t f = 0; f < N_COLOR_FORMATS; f++) {
            if (fc_foreign_pixel(color_formats[f], types[t]) != foreign)
                continue;
            memset(buf, FILL, size);
            glGetTexImage(GL_TEXTURE_2D, 0, color_formats[f], types[t], buf);
            snprintf(label, sizeof(label), "%s format %#x type %#x", what, color_formats[f],
                     types[t]);
            fc_error(h, label);
            fc_blob(h, label, buf, size);
        }
    }
    for (size_t k = 0; k < sizeof(packed) / sizeof(packed[0]); k++) {
        if (fc_foreign_pixel(packed[k].format, packed[k].type) != foreign)
            continue;
        memset(buf, FILL, size);
        glGetTexImage(GL_TEXTURE_2D, 0, packed[k].format, packed[k].type, buf);
        snprintf(label, sizeof(label), "%s format %#x type %#x", what, packed[k].format,
                 packed[k].type);
        fc_error(h, label);
        fc_blob(h, label, buf, size);
    }
    free(buf);
}

static void get_teximage_of(fc_h *h, int foreign)
{
    static const GLint internals[] = {GL_RGBA8, GL_RGB8, GL_LUMINANCE8, GL_LUMINANCE8_ALPHA8,
                                      GL_INTENSITY8, GL_ALPHA8};
    unsigned char *img = client_image(TW * TH * 4, GL_UNSIGNED_BYTE, 4242u);
    char what[64];
    /* pixel transfer does not apply to glGetTexImage */
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    for (size_t i = 0; i < sizeof(internals) / sizeof(internals[0]); i++) {
        glPixelTransferf(GL_RED_SCALE, 1.0f);
        glTexImage2D(GL_TEXTURE_2D, 0, internals[i], TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     img);
        glPixelTransferf(GL_RED_SCALE, 0.5f);
        snprintf(what, sizeof(what), "internal %#x", internals[i]);
        get_all(h, what, foreign);
    }
    free(img);
}

static void get_teximage_pack_state(fc_h *h)
{
    unsigned char *img = client_image(TW * TH * 4, GL_UNSIGNED_BYTE, 4343u);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_PACK_ROW_LENGTH, 11);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
    glPixelStorei(GL_PACK_SKIP_ROWS, 3);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    get_all(h, "pack state", 0);
    free(img);
}

static void get_teximage(fc_h *h) { get_teximage_of(h, 0); }
/* Honesty: the GL 3.0 formats and types of the same walk. */
static void get_teximage_foreign(fc_h *h) { get_teximage_of(h, 1); }

#define TX(name, fn) FC_CASE(name, 8, 8, OSMESA_RGBA, 0, 0, 0, "pixel teximage", fn)

const fc_case fc_cases_pix_format_tex[] = {
    TX("pixel/teximage_unpack_ubyte", upload_ubyte),
    TX("pixel/teximage_unpack_byte", upload_byte),
    TX("pixel/teximage_unpack_ushort", upload_ushort),
    TX("pixel/teximage_unpack_short", upload_short),
    TX("pixel/teximage_unpack_uint", upload_uint),
    TX("pixel/teximage_unpack_int", upload_int),
    TX("pixel/teximage_unpack_float", upload_float),
    TX("pixel/teximage_unpack_packed_types", upload_packed),
    TX("pixel/teximage_unpack_state", upload_unpack_state),
    TX("pixel/teximage_unpack_transfer_ops", upload_transfer),
    TX("pixel/teximage_unpack_color_index", upload_color_index),
    TX("pixel/teximage_unpack_base_formats", upload_bases),
    TX("pixel/teximage_unpack_unsized_internal", upload_unsized),
    TX("pixel/teximage_unpack_1d", upload_1d),
    TX("pixel/getteximage_formats_types", get_teximage),
    TX("pixel/getteximage_pack_state", get_teximage_pack_state),
    /* Honesty (as the readpixels ones above) */
    FC_CASE("honesty/teximage_unpack_half_float", 8, 8, OSMESA_RGBA, 0, 0, 0,
            "honesty pixel teximage", upload_half),
    FC_CASE("honesty/teximage_unpack_color_index_half_float", 8, 8, OSMESA_RGBA, 0, 0, 0,
            "honesty pixel teximage", upload_color_index_half),
    FC_CASE("honesty/getteximage_formats_types", 8, 8, OSMESA_RGBA, 0, 0, 0,
            "honesty pixel teximage", get_teximage_foreign),
    { 0 }
};
