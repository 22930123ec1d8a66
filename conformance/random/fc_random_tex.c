/* fc_random_tex.c - random scenes of textured primitives,
 * "random-tex/s<seed>-i<index>" (tag random-tex).  Like the other families
 * a scene is a pure function of (seed, index) and nothing depends on GL
 * results (texture names are fixed, never from glGenTextures).
 *
 * A scene: a clear, viewport, depth range and projection from the plain
 * generator's helpers, then one texture (1D, 2D or 3D) built with glTexImage:
 *   - sizes powers of two or not (1 to 64 texels a side), every 8-bit
 *     internal format of GL 1.x (RGBA, RGB, LUMINANCE, LUMINANCE_ALPHA,
 *     (3D: depths of the same sizes, its own wrap on r, chosen from a
 *     stream of its own so that the other scenes stay as they were; cube
 *     maps the same way: six square faces, often with GL_REFLECTION_MAP
 *     or GL_NORMAL_MAP texgen on S, T and R; from the 3D stream, 2D textures
 *     of random S3TC blocks, DXT1 RGB/RGBA, DXT3 or DXT5, through
 *     glCompressedTexImage2D, or, in half of them, uncompressed levels
 *     the oracle's encoder compresses, through glTexImage2D; a third of
 *     those GL_COMPRESSED_LUMINANCE(_ALPHA), stored as LATC1/LATC2)
 *     ALPHA, INTENSITY, their sized 8-bit forms, 1-4 components) from
 *     unsigned-byte RGBA, RGB, LUMINANCE, LUMINANCE_ALPHA or ALPHA data
 *     under a random GL_UNPACK_ALIGNMENT; texels random, a checker, a
 *     gradient or a few colours on u8 extremes;
 *   - a mipmap chain built by hand (every level, levels of one colour
 *     each, or a level missing: the texture is then incomplete and the
 *     unit does not texture) when the minification filter uses one;
 *   - every minification and magnification filter, wrap modes REPEAT,
 *     CLAMP_TO_EDGE, CLAMP, CLAMP_TO_BORDER, MIRRORED_REPEAT per axis, a
 *     border colour, LOD clamps, base and maximum level, LOD biases;
 *   - an environment: MODULATE, REPLACE, DECAL, BLEND, ADD or COMBINE
 *     (every function, source, operand and scale), an environment colour;
 *   - in one scene structure of eight of the others (a stream of its
 *     own), a depth texture (GL 1.4: GL_DEPTH_COMPONENT, 16, 24 or 32
 *     from float, unsigned short, int or byte values) with the shadow
 *     comparison (any function) most of the time, any depth texture mode;
 *   - sometimes coordinate generation, a texture matrix, lighting, fog,
 *     blending;
 * and 1-6 primitives of every type with per-vertex texture coordinates
 * (1 to 4 components, in [0,1], beyond it, on texel centres, with q != 1).
 * The structure (which state is on, which filters, wraps and env
 * functions, which primitive types) repeats every FC_TEX_PROFILES indices
 * with other values, as in the lit and raster families, so long runs reuse
 * the oracle's shader cache. */
#define GL_GLEXT_PROTOTYPES 1   /* glWindowPos */
#include "fc_random.h"
#include "fc_random_shared.h"
#include "fc_rng.h"
#include "fc_trace.h"
#include "fc_trace_raster.h"
#include "fc_trace_tex.h"
#include "fc_emit.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FC_TEX_PROFILES 256

static void fct_glWindowPos2i(GLint x, GLint y) { fc_trace_calli("glWindowPos2i", 2, x, y, 0, 0); glWindowPos2i(x, y); }
static void fct_glWindowPos3f(GLfloat x, GLfloat y, GLfloat z) { fc_trace_call("glWindowPos3f", 3, x, y, z, 0); glWindowPos3f(x, y, z); }
#define glWindowPos2i fct_glWindowPos2i
#define glWindowPos3f fct_glWindowPos3f
#define glActiveTexture fct_glActiveTexture
#define glMultiTexCoord2f fct_glMultiTexCoord2f
#define glPixelZoom fct_glPixelZoom

static const GLenum prim_modes[10] = {
    GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES, GL_TRIANGLE_STRIP,
    GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON,
};
static const GLenum min_filters[6] = {
    GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
    GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR,
};
static const GLenum wraps[5] = {
    GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT,
};
static const GLenum env_modes[6] = { GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD, GL_COMBINE };
static const GLenum combine_rgb[8] = {
    GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE, GL_SUBTRACT,
    GL_DOT3_RGB, GL_DOT3_RGBA,
};
static const GLenum combine_sources[4] = { GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS };
static const GLenum operands_rgb[4] = {
    GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA,
};
static const GLenum operands_a[2] = { GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA };
/* internal format, and the source formats that fit it */
static const GLint internals[14] = {
    GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_INTENSITY,
    GL_RGBA8, GL_RGB8, GL_LUMINANCE8, GL_LUMINANCE8_ALPHA8, GL_ALPHA8, GL_INTENSITY8, 3, 4,
};
static const GLenum src_formats[5] = { GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA };
static const int src_components[5] = { 4, 3, 1, 2, 1 };

/* The structure of a scene: drawn from the profile stream. */
struct profile {
    int nprim;
    GLenum modes[6];
    int tex1d;                  /* a 1D texture rather than 2D */
    int npot;                   /* sizes not powers of two */
    GLint internal;
    int src;                    /* index into src_formats */
    GLenum min_filter, mag_filter;
    GLenum wrap_s, wrap_t;
    int mip;                    /* 0 full chain, 1 single colours, 2 a level missing */
    int lod;                    /* MIN/MAX_LOD, BASE/MAX_LEVEL, LOD_BIAS set */
    int border_color;
    GLenum env;
    GLenum crgb, calpha;        /* COMBINE functions */
    GLenum src_rgb[3], src_a[3], op_rgb[3], op_a[3];
    int scale_rgb, scale_a;
    int texgen;                 /* 0 off, 1 OBJECT_LINEAR, 2 EYE_LINEAR, 3 SPHERE_MAP */
    int texmat;
    int lit, fog, blend, flat, depth_test;
    int tex_enabled;            /* GL_TEXTURE_1D/2D enabled (rarely off) */
    int unit1;                  /* a second unit: 0 off, 1 texgen, 2 a constant coordinate */
    GLenum env1;
    int pixels;                 /* pixel operations after the primitives */
    /* from a stream of its own (tex_scene): a 3D texture rather than 2D,
     * its wrap on r */
    int tex3d;
    GLenum wrap_r;
    /* from a stream of its own (tex_scene): a depth texture (GL 1.4) of
     * an internal format and client type, with the shadow comparison or
     * not, its function and GL_DEPTH_TEXTURE_MODE */
    int depth;
    GLint depth_internal;
    GLenum depth_type;
    int compare;
    GLenum compare_func, depth_mode;
    /* from another stream of its own: a cube map rather than 2D (faces
     * square), its texgen (0: the primitives' coordinates,
     * 1: REFLECTION_MAP, 2: NORMAL_MAP on S, T, R) */
    int cube;
    int cube_gen;
    /* from the same stream: a 2D texture of an S3TC format (0: none),
     * every level random blocks */
    GLenum dxt;
    /* from a stream of its own: an S3TC texture's levels given as
     * uncompressed images (the oracle's encoder compresses them), with
     * the S3TC format or the generic one the oracle stores it as
     * (GL_COMPRESSED_RGB for DXT1 RGB, GL_COMPRESSED_RGBA for DXT5) */
    int dxt_encode;
    GLint dxt_internal;
};

static void make_profile(fc_rng *k, struct profile *p)
{
    memset(p, 0, sizeof *p);
    p->nprim = fc_rng_range(k, 1, 6);
    for (int i = 0; i < p->nprim; i++)
        p->modes[i] = fc_rng_chance(k, 70) ? prim_modes[4 + fc_rng_below(k, 6)]
                                          : prim_modes[fc_rng_below(k, 4)];
    p->tex1d = fc_rng_chance(k, 15);
    p->npot = fc_rng_chance(k, 30);
    p->internal = internals[fc_rng_below(k, 14)];
    p->src = (int)fc_rng_below(k, 5);
    p->min_filter = min_filters[fc_rng_below(k, 6)];
    p->mag_filter = fc_rng_chance(k, 50) ? GL_NEAREST : GL_LINEAR;
    /* the fixed-point path's wraps most of the time */
    p->wrap_s = fc_rng_chance(k, 70) ? wraps[fc_rng_below(k, 2)] : wraps[fc_rng_below(k, 5)];
    p->wrap_t = fc_rng_chance(k, 70) ? wraps[fc_rng_below(k, 2)] : wraps[fc_rng_below(k, 5)];
    p->mip = fc_rng_chance(k, 80) ? (int)fc_rng_below(k, 2) : 2;
    p->lod = fc_rng_chance(k, 15);
    p->border_color = fc_rng_chance(k, 50);
    p->env = env_modes[fc_rng_below(k, 6)];
    p->crgb = combine_rgb[fc_rng_below(k, 8)];
    p->calpha = combine_rgb[fc_rng_below(k, 6)];
    for (int i = 0; i < 3; i++) {
        p->src_rgb[i] = combine_sources[fc_rng_below(k, 4)];
        p->src_a[i] = combine_sources[fc_rng_below(k, 4)];
        p->op_rgb[i] = operands_rgb[fc_rng_below(k, 4)];
        p->op_a[i] = operands_a[fc_rng_below(k, 2)];
    }
    p->scale_rgb = 1 << fc_rng_below(k, 3);
    p->scale_a = 1 << fc_rng_below(k, 3);
    p->texgen = fc_rng_chance(k, 15) ? 1 + (int)fc_rng_below(k, 3) : 0;
    p->texmat = fc_rng_chance(k, 15);
    p->lit = fc_rng_chance(k, 25);
    p->fog = fc_rng_chance(k, 10);
    p->blend = fc_rng_chance(k, 20);
    p->flat = fc_rng_chance(k, 20);
    p->depth_test = fc_rng_chance(k, 50);
    p->tex_enabled = fc_rng_chance(k, 95);
    p->unit1 = fc_rng_chance(k, 25) ? 1 + (int)fc_rng_below(k, 2) : 0;
    p->env1 = env_modes[fc_rng_below(k, 5)];
    p->pixels = fc_rng_chance(k, 30);
}

/* ---- the texture ---------------------------------------------------------- */

static int tex_size(fc_rng *r, int npot)
{
    static const int pot[8] = { 1, 2, 4, 8, 16, 32, 64, 8 };
    static const int odd[10] = { 3, 5, 6, 7, 10, 13, 17, 31, 33, 50 };
    return npot ? odd[fc_rng_below(r, 10)] : pot[fc_rng_below(r, 8)];
}

/* A byte on or next to the extremes, or any. */
static unsigned char texel_byte(fc_rng *r)
{
    switch (fc_rng_below(r, 6)) {
    case 0: return 0;
    case 1: return 255;
    case 2: return (unsigned char)(fc_rng_chance(r, 50) ? 127 : 128);
    default: return (unsigned char)fc_rng_below(r, 256);
    }
}

/* Uploads one level (w x h texels of n components, rows padded to align)
 * with a pattern: 0 random, 1 checker, 2 gradient, 3 one colour. */
/* A depth level: w x h values of p->depth_type (float, unsigned short,
 * unsigned int or unsigned byte) with a pattern (0 random, 1 checker, 2
 * gradient, 3 one value; floats sometimes outside [0, 1]). */
static void upload_depth_level(fc_rng *r, const struct profile *p, int level, int w, int h,
                               int pattern, int align)
{
    const size_t bpp = p->depth_type == GL_UNSIGNED_BYTE ? 1 : p->depth_type == GL_UNSIGNED_SHORT ? 2 : 4;
    const size_t row = ((size_t)w * bpp + (size_t)align - 1) / (size_t)align * (size_t)align;
    const size_t bytes = row * (size_t)h;
    unsigned char *img = calloc(bytes ? bytes : 1, 1);
    if (!img)
        abort();
    const double a = fc_rng_real(r, -0.1, 1.1), b = fc_rng_real(r, -0.1, 1.1);
    const int cell = 1 << fc_rng_below(r, 3);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double v;
            switch (pattern) {
            case 0: v = fc_rng_real(r, -0.05, 1.05); break;
            case 1: v = ((x / cell + y / cell) & 1) ? a : b; break;
            case 2: v = (a * (w - x) + b * x) / (w + 1) + 0.4 * y / (h + 1); break;
            default: v = a; break;
            }
            const double c = v < 0 ? 0 : v > 1 ? 1 : v;
            unsigned char *t = img + (size_t)y * row + (size_t)x * bpp;
            if (p->depth_type == GL_FLOAT) {
                const float f = (float)v;
                memcpy(t, &f, 4);
            } else if (p->depth_type == GL_UNSIGNED_INT) {
                const unsigned u = (unsigned)(c * 4294967295.0);
                memcpy(t, &u, 4);
            } else if (p->depth_type == GL_UNSIGNED_SHORT) {
                const unsigned short u = (unsigned short)(c * 65535.0);
                memcpy(t, &u, 2);
            } else {
                *t = (unsigned char)(c * 255.0);
            }
        }
    if (p->tex1d)
        fct_glTexImage1D(GL_TEXTURE_1D, level, p->depth_internal, w, 0, GL_DEPTH_COMPONENT,
                         p->depth_type, img, bytes);
    else
        fct_glTexImage2D(GL_TEXTURE_2D, level, p->depth_internal, w, h, 0, GL_DEPTH_COMPONENT,
                         p->depth_type, img, bytes);
    free(img);
}

static void upload_level(fc_rng *r, const struct profile *p, int level, int w, int h0,
                         int d, int pattern, int align, int face)
{
    if (p->depth) {
        upload_depth_level(r, p, level, w, h0, pattern, align);
        return;
    }
    /* encoded levels but DXT5 ones under 4 texels wide and 2 or more
     * high: the oracle's encoder reads uninitialised memory for them
     * (ORACLE-NOTES.md "Compressed textures: the encoder") */
    const int latc = p->dxt == GL_COMPRESSED_LUMINANCE_LATC1_EXT ||
                     p->dxt == GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT;
    const int encode = p->dxt && p->dxt_encode &&
                       (latc || !(p->dxt == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT && w < 4 && h0 >= 2));
    /* LATC levels of that shape: one value (blocks of one value are
     * written without the uninitialised codes; ORACLE-NOTES.md
     * "Compressed textures: LATC") */
    if (latc && w < 4 && h0 >= 2)
        pattern = 3;
    if (p->dxt && !encode) {
        /* random blocks (pattern 3: one block repeated) */
        const int bb = p->dxt == GL_COMPRESSED_RGB_S3TC_DXT1_EXT ||
                       p->dxt == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT ? 8 : 16;
        const int size = ((w + 3) / 4) * ((h0 + 3) / 4) * bb;
        unsigned char *blocks = malloc((size_t)size);
        if (!blocks)
            abort();
        for (int i = 0; i < size; i++)
            blocks[i] = pattern == 3 && i >= bb ? blocks[i % bb] : (unsigned char)fc_rng_below(r, 256);
        fct_glCompressedTexImage2D(GL_TEXTURE_2D, level, p->dxt, w, h0, 0, size, blocks);
        free(blocks);
        return;
    }
    const int n = src_components[p->src];
    const int h = h0 * d;   /* a 3D image: d slices of h0 rows, one pattern */
    const size_t row = ((size_t)(w * n) + (size_t)align - 1) / (size_t)align * (size_t)align;
    const size_t bytes = row * (size_t)h;
    unsigned char *img = calloc(bytes ? bytes : 1, 1);
    unsigned char a[4], b[4];
    if (!img)
        abort();
    for (int c = 0; c < 4; c++)
        a[c] = texel_byte(r), b[c] = texel_byte(r);
    const int cell = 1 << fc_rng_below(r, 3);
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            unsigned char *t = img + (size_t)y * row + (size_t)(x * n);
            for (int c = 0; c < n; c++) {
                switch (pattern) {
                case 0: t[c] = texel_byte(r); break;
                case 1: t[c] = ((x / cell + y / cell) & 1) ? a[c] : b[c]; break;
                case 2: t[c] = (unsigned char)((a[c] * (w - x) + b[c] * x + 255 * y) / (w + h)); break;
                default: t[c] = a[c]; break;
                }
            }
        }
    }
    if (p->tex3d)
        fct_glTexImage3D(GL_TEXTURE_3D, level, p->internal, w, h0, d, 0, src_formats[p->src],
                         GL_UNSIGNED_BYTE, img, bytes);
    else if (p->tex1d)
        fct_glTexImage1D(GL_TEXTURE_1D, level, p->internal, w, 0, src_formats[p->src],
                         GL_UNSIGNED_BYTE, img, bytes);
    else
        fct_glTexImage2D(p->cube ? GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face : GL_TEXTURE_2D,
                         level, encode ? p->dxt_internal : p->internal, w, h, 0,
                         src_formats[p->src], GL_UNSIGNED_BYTE, img, bytes);
    free(img);
}

static void random_texture(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    const GLenum target = p->cube    ? GL_TEXTURE_CUBE_MAP
                          : p->tex3d ? GL_TEXTURE_3D
                          : p->tex1d ? GL_TEXTURE_1D
                                     : GL_TEXTURE_2D;
    const int faces = p->cube ? 6 : 1;
    fct_glBindTexture(target, 1 + fc_rng_below(r, 3));
    static const int aligns[4] = { 1, 2, 4, 8 };
    GLint align = aligns[fc_rng_below(r, 4)];
    fct_glPixelStorei(GL_UNPACK_ALIGNMENT, align);
    int w = tex_size(r, p->npot), h = p->tex1d ? 1 : tex_size(r, p->npot);
    if (p->cube)
        h = w;   /* square faces */
    /* 3D: at most 16 texels deep */
    int d = p->tex3d ? 1 + (tex_size(r, p->npot) - 1) % 16 : 1;
    const int pattern = (int)fc_rng_below(r, 3);
    for (int f = 0; f < faces; f++)
        upload_level(r, p, 0, w, h, d, pattern, align, f);
    const int mipmapped = p->min_filter != GL_NEAREST && p->min_filter != GL_LINEAR;
    if (mipmapped || fc_rng_chance(r, 10)) {
        const int skip = p->mip == 2 ? fc_rng_range(r, 1, 6) : -1;
        for (int level = 1; w > 1 || h > 1 || d > 1; level++) {
            w = w > 1 ? w / 2 : 1;
            h = h > 1 ? h / 2 : 1;
            d = d > 1 ? d / 2 : 1;
            if (level == skip)
                continue;
            for (int f = 0; f < faces; f++)
                upload_level(r, p, level, w, h, d, p->mip == 1 ? 3 : (int)fc_rng_below(r, 4),
                             align, f);
        }
    }
    fct_glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)p->min_filter);
    fct_glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)p->mag_filter);
    fct_glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)p->wrap_s);
    if (!p->tex1d)
        fct_glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)p->wrap_t);
    if (p->tex3d)
        fct_glTexParameteri(target, GL_TEXTURE_WRAP_R, (GLint)p->wrap_r);
    if (p->depth) {
        if (p->compare)
            fct_glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
        fct_glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, (GLint)p->compare_func);
        fct_glTexParameteri(target, GL_DEPTH_TEXTURE_MODE, (GLint)p->depth_mode);
    }
    if (p->border_color) {
        GLfloat c[4];
        for (int i = 0; i < 4; i++)
            c[i] = (GLfloat)(fc_rng_chance(r, 50) ? fc_rng_range(r, 0, 255) / 255.0 : fc_rng_unit(r));
        fct_glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, c);
    }
    if (p->lod) {
        if (fc_rng_chance(r, 50))
            fct_glTexParameterf(target, GL_TEXTURE_MIN_LOD, (GLfloat)fc_rng_real(r, -2, 4));
        if (fc_rng_chance(r, 50))
            fct_glTexParameterf(target, GL_TEXTURE_MAX_LOD, (GLfloat)fc_rng_real(r, 0, 6));
        /* MAX_LEVEL never below BASE_LEVEL: the oracle can crash on such
         * a sampler view (its last level below the first; a fixed case,
         * texture/image_completeness_max_below_base, covers the rule) */
        int base = 0;
        if (fc_rng_chance(r, 40)) {
            base = fc_rng_range(r, 0, 2);
            fct_glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, base);
        }
        if (fc_rng_chance(r, 40))
            fct_glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, fc_rng_range(r, base, 6));
        if (fc_rng_chance(r, 50))
            fct_glTexParameterf(target, GL_TEXTURE_LOD_BIAS, (GLfloat)fc_rng_real(r, -3, 3));
        if (fc_rng_chance(r, 30))
            fct_glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, (GLfloat)fc_rng_real(r, -2, 2));
    }
    if (p->tex_enabled)
        glEnable(target);
}

static void random_env(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    GLfloat c[4];
    for (int i = 0; i < 4; i++)
        c[i] = (GLfloat)(fc_rng_chance(r, 50) ? fc_rng_range(r, 0, 255) / 255.0 : fc_rng_unit(r));
    fct_glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
    fct_glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)p->env);
    if (p->env != GL_COMBINE)
        return;
    fct_glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)p->crgb);
    fct_glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)p->calpha);
    for (int i = 0; i < 3; i++) {
        fct_glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + i, (GLint)p->src_rgb[i]);
        fct_glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + i, (GLint)p->src_a[i]);
        fct_glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, (GLint)p->op_rgb[i]);
        fct_glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i, (GLint)p->op_a[i]);
    }
    fct_glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, (GLfloat)p->scale_rgb);
    fct_glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, (GLfloat)p->scale_a);
}

static void random_texgen(struct scene *s, const struct profile *p)
{
    static const GLenum modes[3] = { GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP };
    fc_rng *r = &s->r;
    if (p->cube && p->cube_gen) {
        /* a cube map's texgen: S, T and R */
        const GLenum mode = p->cube_gen == 1 ? GL_REFLECTION_MAP : GL_NORMAL_MAP;
        for (int c = 0; c < 3; c++) {
            fct_glTexGeni(GL_S + (GLenum)c, GL_TEXTURE_GEN_MODE, (GLint)mode);
            glEnable(GL_TEXTURE_GEN_S + (GLenum)c);
        }
        return;
    }
    if (!p->texgen)
        return;
    for (int c = 0; c < 2; c++) {
        const GLenum coord = GL_S + (GLenum)c;
        GLfloat plane[4];
        for (int i = 0; i < 4; i++)
            plane[i] = (GLfloat)(fc_rng_chance(r, 30) ? 0.0 : fc_rng_real(r, -0.1, 0.1));
        fct_glTexGeni(coord, GL_TEXTURE_GEN_MODE, (GLint)modes[p->texgen - 1]);
        fct_glTexGenfv(coord, p->texgen == 2 ? GL_EYE_PLANE : GL_OBJECT_PLANE, plane);
        glEnable(GL_TEXTURE_GEN_S + (GLenum)c);
    }
}

static void random_texmatrix(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    if (!p->texmat)
        return;
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    switch (fc_rng_below(r, 3)) {
    case 0: glTranslatef((GLfloat)fc_rng_real(r, -1, 1), (GLfloat)fc_rng_real(r, -1, 1), 0); break;
    case 1: glRotatef((GLfloat)fc_rng_real(r, -180, 180), 0, 0, 1); break;
    default: glScalef((GLfloat)fc_rng_real(r, -3, 3), (GLfloat)fc_rng_real(r, -3, 3), 1); break;
    }
    glMatrixMode(GL_MODELVIEW);
}

static void random_light(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    if (!p->lit)
        return;
    GLfloat pos[4] = { (GLfloat)fc_rng_real(r, -1, 1), (GLfloat)fc_rng_real(r, -1, 1), 1, 0 };
    GLfloat dif[4] = { (GLfloat)fc_rng_unit(r), (GLfloat)fc_rng_unit(r), (GLfloat)fc_rng_unit(r), 1 };
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHTING);
    if (fc_rng_chance(r, 50))
        glEnable(GL_COLOR_MATERIAL);
    glNormal3f((GLfloat)fc_rng_real(r, -1, 1), (GLfloat)fc_rng_real(r, -1, 1), 1);
}

static void random_fragment(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    if (p->fog) {
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_START, (GLfloat)fc_rng_real(r, -1, 1));
        glFogf(GL_FOG_END, (GLfloat)fc_rng_real(r, 1, 20));
    }
    if (p->blend) {
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glEnable(GL_BLEND);
    }
}

/* ---- primitives ------------------------------------------------------------ */

/* A texture coordinate component. */
static double tc_value(fc_rng *r, int size)
{
    switch (fc_rng_below(r, 8)) {
    case 0: return fc_rng_range(r, -2, 3);
    case 1: return (fc_rng_range(r, 0, 2 * size) + 0.5) / size;     /* texel centres */
    case 2: return (double)(float)fc_rng_real(r, -3, 4);
    case 3: return fc_rng_range(r, 0, 8 * size) / (4.0 * size);     /* texel edges */
    case 4: return (double)(float)fc_rng_real(r, -1000, 1000);
    default: return (double)(float)fc_rng_unit(r);
    }
}

static void emit_texcoord(struct scene *s)
{
    fc_rng *r = &s->r;
    double t[4];
    const int n = fc_rng_chance(r, 10) ? 4 : fc_rng_chance(r, 10) ? 1 : fc_rng_chance(r, 10) ? 3 : 2;
    const int size = 1 << fc_rng_below(r, 6);
    for (int i = 0; i < 4; i++)
        t[i] = i < 3 ? tc_value(r, size) : 1.0;
    if (n == 4)
        t[3] = fc_rng_chance(r, 50) ? (double)(float)fc_rng_real(r, 0.25, 4) : fc_rng_range(r, -2, 3);
    int ints = 1;
    for (int i = 0; i < n; i++)
        ints &= t[i] == floor(t[i]) && fabs(t[i]) <= 32767;
    const int vec = fc_rng_chance(r, 40);
    int type = (int)fc_rng_below(r, ints ? 4 : 2);
#define TC(T, suf) do {                                                                  \
        T a[4] = { (T)t[0], (T)t[1], (T)t[2], (T)t[3] };                                 \
        if (vec) {                                                                       \
            if (n == 1) glTexCoord1##suf##v(a); else if (n == 2) glTexCoord2##suf##v(a); \
            else if (n == 3) glTexCoord3##suf##v(a); else glTexCoord4##suf##v(a);        \
        } else {                                                                         \
            if (n == 1) glTexCoord1##suf(a[0]); else if (n == 2) glTexCoord2##suf(a[0], a[1]); \
            else if (n == 3) glTexCoord3##suf(a[0], a[1], a[2]);                         \
            else glTexCoord4##suf(a[0], a[1], a[2], a[3]);                               \
        }                                                                                \
    } while (0)
    switch (type) {
    case 0: TC(GLfloat, f); break;
    case 1: TC(GLdouble, d); break;
    case 2: TC(GLshort, s); break;
    default: TC(GLint, i); break;
    }
#undef TC
}

static int vertex_count(fc_rng *r, GLenum mode)
{
    int n = fc_rng_range(r, 1, 4);
    switch (mode) {
    case GL_POINTS: return fc_rng_range(r, 1, 10);
    case GL_LINES: return 2 * n;
    case GL_LINE_STRIP: case GL_LINE_LOOP: return fc_rng_range(r, 2, 6);
    case GL_TRIANGLES: return 3 * n;
    case GL_QUADS: return 4 * n;
    case GL_QUAD_STRIP: return 2 + 2 * n;
    default: return 2 + n;
    }
}

/* A vertex well inside the view (60%: textures need covered pixels), or
 * one of the plain generator's fresh vertices (view-volume bounds, w near
 * 0, behind the eye...). */
static void tex_vertex(struct scene *s, double v[4])
{
    fc_rng *r = &s->r;
    if (fc_rng_chance(r, 40) || (s->space != SP_PIXEL && s->space != SP_FRUSTUM)) {
        fcr_fresh_vertex(s, v);
        return;
    }
    v[3] = 1;
    if (s->space == SP_PIXEL) {
        v[0] = (float)fc_rng_real(r, -0.2 * s->vw, 1.2 * s->vw);
        v[1] = (float)fc_rng_real(r, -0.2 * s->vh, 1.2 * s->vh);
        v[2] = (float)fc_rng_real(r, -0.9, 0.9);
        return;
    }
    /* in the frustum: eye depth from just past the near plane to 30 near
     * distances (or the far plane), x and y across the view and beyond */
    const double n = s->fr[4], f = s->fr[5] < 30 * n ? s->fr[5] : 30 * n;
    const double ze = -(float)fc_rng_real(r, n * 1.001, f * 0.999);
    v[0] = (float)(fc_rng_real(r, s->fr[0], s->fr[1]) * 1.3 * -ze / n);
    v[1] = (float)(fc_rng_real(r, s->fr[2], s->fr[3]) * 1.3 * -ze / n);
    v[2] = ze;
}

static void random_primitive(struct scene *s, GLenum mode)
{
    fc_rng *r = &s->r;
    double v[4];
    const int n = vertex_count(r, mode);
    glBegin(mode);
    for (int k = 0; k < n; k++) {
        if (s->npool && fc_rng_chance(r, 15))
            memcpy(v, s->pool[fc_rng_below(r, (uint32_t)(s->npool < POOL ? s->npool : POOL))],
                   sizeof v);
        else
            tex_vertex(s, v);
        if (fc_rng_chance(r, 60))
            fcr_emit_color(s);
        if (k == 0 || fc_rng_chance(r, 85))
            emit_texcoord(s);
        fcr_emit_vertex(s, v, v[3] != 1 ? 4 : 3);
        memcpy(s->pool[s->npool++ % POOL], v, sizeof v);
    }
    glEnd();
}

/* Unit 1: a small 2D texture (REPEAT, LINEAR or NEAREST) with its own
 * environment, its coordinates from OBJECT_LINEAR texgen or one constant
 * glMultiTexCoord; then unit 0 is active again. */
static void random_unit1(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    if (!p->unit1)
        return;
    glActiveTexture(GL_TEXTURE1);
    fct_glBindTexture(GL_TEXTURE_2D, 7);
    const int w = 1 << fc_rng_below(r, 4), h = 1 << fc_rng_below(r, 4);
    unsigned char img[8 * 8 * 4];
    for (int i = 0; i < w * h * 4; i++)
        img[i] = texel_byte(r);
    /* rows of 4 * w bytes: no padding under an alignment of 4 */
    fct_glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    fct_glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, img,
                     (size_t)(w * h * 4));
    fct_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, fc_rng_chance(r, 50) ? GL_LINEAR : GL_NEAREST);
    fct_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, fc_rng_chance(r, 50) ? GL_LINEAR : GL_NEAREST);
    fct_glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)p->env1);
    if (p->unit1 == 1) {
        for (int c = 0; c < 2; c++) {
            GLfloat plane[4];
            for (int i = 0; i < 4; i++)
                plane[i] = (GLfloat)fc_rng_real(r, -0.2, 0.2);
            fct_glTexGeni(GL_S + (GLenum)c, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
            fct_glTexGenfv(GL_S + (GLenum)c, GL_OBJECT_PLANE, plane);
            glEnable(GL_TEXTURE_GEN_S + (GLenum)c);
        }
    } else {
        glMultiTexCoord2f(GL_TEXTURE1, (GLfloat)fc_rng_unit(r), (GLfloat)fc_rng_unit(r));
    }
    glEnable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
}

/* glBitmap, glDrawPixels and glCopyPixels at random raster positions,
 * with zoom, under the scene's texture, fog and blend state. */
static void random_pixels(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    static const GLfloat zooms[7] = { 1, 1, 2, 0.5f, -1, 1.5f, 3 };
    if (!p->pixels)
        return;
    const int n = fc_rng_range(r, 1, 3);
    for (int i = 0; i < n; i++) {
        if (fc_rng_chance(r, 50))
            glWindowPos2i(fc_rng_range(r, -4, s->w), fc_rng_range(r, -4, s->h));
        else
            glWindowPos3f((GLfloat)fc_rng_real(r, -4, s->w), (GLfloat)fc_rng_real(r, -4, s->h),
                          (GLfloat)fc_rng_unit(r));
        glPixelZoom(zooms[fc_rng_below(r, 7)], zooms[fc_rng_below(r, 7)]);
        const int w = fc_rng_range(r, 1, 24), h = fc_rng_range(r, 1, 24);
        unsigned char img[24 * 24 * 4];
        /* tight rows: the trace holds exactly the bytes GL reads */
        fct_glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        switch (fc_rng_below(r, 3)) {
        case 0: {
            for (int k = 0; k < 24 * 24 * 4; k++)
                img[k] = (unsigned char)fc_rng_below(r, 256);
            fct_trace_image(img, (size_t)((w + 7) / 8 * h));
            if (fc_trace_out)
                fprintf(fc_trace_out, "glBitmap(%d, %d, 0, 0, %d, %d, img); }\n", w, h, w / 2, -h / 3);
            glBitmap(w, h, 0.0f, 0.0f, (GLfloat)(w / 2), (GLfloat)(-h / 3), img);
            break;
        }
        case 1: {
            const int src = (int)fc_rng_below(r, 5);
            for (int k = 0; k < 24 * 24 * 4; k++)
                img[k] = texel_byte(r);
            fct_trace_image(img, (size_t)(w * h * src_components[src]));
            if (fc_trace_out)
                fprintf(fc_trace_out, "glDrawPixels(%d, %d, %#x, GL_UNSIGNED_BYTE, img); }\n", w, h,
                        (unsigned)src_formats[src]);
            glDrawPixels(w, h, src_formats[src], GL_UNSIGNED_BYTE, img);
            break;
        }
        default: {
            const int x = fc_rng_range(r, -4, s->w), y = fc_rng_range(r, -4, s->h);
            const GLenum type = fc_rng_chance(r, 80) ? GL_COLOR : GL_DEPTH;
            if (fc_trace_out)
                fprintf(fc_trace_out, "glCopyPixels(%d, %d, %d, %d, %#x);\n", x, y, w, h, (unsigned)type);
            glCopyPixels(x, y, w, h, type);
            break;
        }
        }
    }
    glPixelZoom(1, 1);
}

/* Point sprites (GL 1.4, ARB_point_sprite) in about two in five of the
 * 2D structures that draw points, from streams of their own (the other
 * draws stay as they were): GL_COORD_REPLACE on unit 0 (mostly) and on
 * the second unit when there is one (half of them), sizes from 1 to 40,
 * sometimes distance attenuation with the min/max clamps and a fade
 * threshold.  The scene's lines and polygons are drawn with the sprite
 * state on too (a replaced unit reads (0, 0, 0, 0) there: ORACLE-NOTES.md
 * "Point sprites"). */
static void fct_glPointParameterfv(GLenum pname, int n, const GLfloat *v)
{
    fc_trace_enums_vf("glPointParameterfv", 1, pname, 0, n, v);
    glPointParameterfv(pname, v);
}

static void random_sprites(const struct profile *p, uint64_t seed, uint32_t index)
{
    fc_rng ks = fc_rng_make(seed, index % FC_TEX_PROFILES, 18);
    int points = 0;
    for (int i = 0; i < p->nprim; i++)
        points |= p->modes[i] == GL_POINTS;
    if (!points || p->tex1d || p->tex3d || p->cube || p->depth || !fc_rng_chance(&ks, 40))
        return;
    const int replace = fc_rng_chance(&ks, 80), atten = fc_rng_chance(&ks, 35);
    const int replace1 = p->unit1 && fc_rng_chance(&ks, 50);
    fc_rng r = fc_rng_make(seed, index, 24);
    glEnable(GL_POINT_SPRITE);
    fct_glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, replace);
    if (replace1) {
        glActiveTexture(GL_TEXTURE1);
        fct_glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
        glActiveTexture(GL_TEXTURE0);
    }
    glPointSize((GLfloat)fc_rng_real(&r, 1.0, 40.0));
    if (atten) {
        const GLfloat a[3] = { 1.0f, (GLfloat)fc_rng_real(&r, 0.0, 0.5), (GLfloat)fc_rng_real(&r, 0.0, 0.1) };
        const GLfloat lo = (GLfloat)fc_rng_real(&r, 0.0, 4.0), hi = (GLfloat)fc_rng_real(&r, 8.0, 64.0);
        const GLfloat fade = (GLfloat)fc_rng_real(&r, 0.0, 4.0);
        fct_glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, 3, a);
        fct_glPointParameterfv(GL_POINT_SIZE_MIN, 1, &lo);
        fct_glPointParameterfv(GL_POINT_SIZE_MAX, 1, &hi);
        fct_glPointParameterfv(GL_POINT_FADE_THRESHOLD_SIZE, 1, &fade);
    }
}

static void tex_scene(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    struct scene s;
    struct profile p;
    uint64_t seed;
    uint32_t index;

    fc_lit_gl_load();
    memset(&s, 0, sizeof s);
    fc_random_tex_parse(c->name, &seed, &index);
    fc_rng k = fc_rng_make(seed, index % FC_TEX_PROFILES, 12);
    make_profile(&k, &p);
    {
        /* 3D textures in one scene structure of eight, from a stream of
         * their own */
        fc_rng k3 = fc_rng_make(seed, index % FC_TEX_PROFILES, 15);
        p.tex3d = !p.tex1d && fc_rng_chance(&k3, 12);
        p.wrap_r = fc_rng_chance(&k3, 60) ? wraps[fc_rng_below(&k3, 2)]
                                          : wraps[fc_rng_below(&k3, 5)];
        /* S3TC textures in about one 2D structure of eight, drawn from
         * the same stream after the 3D choice (the other scenes keep their
         * draws) */
        static const GLenum dxt[4] = { GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
            GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
            GL_COMPRESSED_RGBA_S3TC_DXT5_EXT };
        const int use_dxt = fc_rng_chance(&k3, 12);
        const GLenum f = dxt[fc_rng_below(&k3, 4)];
        p.dxt = !p.tex1d && !p.tex3d && use_dxt ? f : 0;
        /* half of them encoded from uncompressed levels, from a stream
         * of their own */
        fc_rng ke = fc_rng_make(seed, index % FC_TEX_PROFILES, 23);
        p.dxt_encode = fc_rng_chance(&ke, 50);
        const int generic = fc_rng_chance(&ke, 30);
        p.dxt_internal = (GLint)p.dxt;
        if (generic && p.dxt == GL_COMPRESSED_RGB_S3TC_DXT1_EXT)
            p.dxt_internal = GL_COMPRESSED_RGB;
        if (generic && p.dxt == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT)
            p.dxt_internal = GL_COMPRESSED_RGBA;
        /* of the encoded ones, about a third GL_COMPRESSED_LUMINANCE(_ALPHA),
         * which the oracle stores as LATC1/LATC2, from a stream of their
         * own (p.dxt only names the stored format: levels are always
         * given uncompressed) */
        fc_rng kl = fc_rng_make(seed, index % FC_TEX_PROFILES, 24);
        if (p.dxt && p.dxt_encode && fc_rng_chance(&kl, 35)) {
            const int two = fc_rng_chance(&kl, 50);
            p.dxt = two ? GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT : GL_COMPRESSED_LUMINANCE_LATC1_EXT;
            p.dxt_internal = two ? GL_COMPRESSED_LUMINANCE_ALPHA : GL_COMPRESSED_LUMINANCE;
        }
        /* cube maps in about one structure of ten, from another stream */
        fc_rng kc = fc_rng_make(seed, index % FC_TEX_PROFILES, 16);
        p.cube = !p.tex1d && !p.tex3d && !p.dxt && fc_rng_chance(&kc, 11);
        p.cube_gen = fc_rng_chance(&kc, 60) ? 1 + (int)fc_rng_below(&kc, 2) : 0;
    }
    {
        /* depth textures with or without the shadow comparison in one
         * scene structure of eight of the others, from a stream of their
         * own */
        static const GLint dint[4] = { GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16,
                                       GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32 };
        static const GLenum dtype[4] = { GL_FLOAT, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT,
                                         GL_UNSIGNED_BYTE };
        /* (GL_RED, ARB_texture_rg's, is no GL 1.5 mode) */
        static const GLenum dmode[3] = { GL_LUMINANCE, GL_INTENSITY, GL_ALPHA };
        fc_rng kd = fc_rng_make(seed, index % FC_TEX_PROFILES, 17);
        p.depth = !p.tex3d && !p.cube && !p.dxt && fc_rng_chance(&kd, 12);
        p.depth_internal = dint[fc_rng_below(&kd, 4)];
        p.depth_type = dtype[fc_rng_below(&kd, 4)];
        p.compare = fc_rng_chance(&kd, 80);
        p.compare_func = GL_NEVER + fc_rng_below(&kd, 8);
        p.depth_mode = dmode[fc_rng_chance(&kd, 70) ? 0 : fc_rng_below(&kd, 3)];
    }
    fce_scene_begin(FCE_TEX, seed, index, index % FC_TEX_PROFILES);
    s.r = fc_rng_make(seed, index, 11);
    s.w = c->width;
    s.h = c->height;
    {
        const uint32_t sp = fc_rng_below(&k, 100);
        s.space = sp < 45 ? SP_PIXEL : sp < 85 ? SP_FRUSTUM : (enum space)(1 + fc_rng_below(&k, 4));
    }

    /* a clear the primitives can pass the depth test against */
    glClearColor((GLclampf)fc_rng_unit(&s.r), (GLclampf)fc_rng_unit(&s.r),
                 (GLclampf)fc_rng_unit(&s.r), (GLclampf)fc_rng_unit(&s.r));
    glClearDepth(fc_rng_chance(&s.r, 80) ? 1.0 : fc_rng_real(&s.r, 0.5, 1.0));
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fcr_viewport(&s);
    fcr_depth_range(&s.r);
    fcr_projection(&s);
    glLoadIdentity();
    if (p.depth_test)
        glEnable(GL_DEPTH_TEST);
    glShadeModel(p.flat ? GL_FLAT : GL_SMOOTH);

    random_texture(&s, &p);
    random_env(&s, &p);
    random_unit1(&s, &p);
    random_texgen(&s, &p);
    random_texmatrix(&s, &p);
    random_light(&s, &p);
    random_fragment(&s, &p);
    random_sprites(&p, seed, index);

    /* the witness (fcr_witness: a polygon inside the visible view volume,
     * drawn with GL_ALWAYS under the scene's texture state), from a stream
     * of its own, before primitive `witness` (after the last at nprim), so
     * that a scene whose primitives all miss still compares something */
    s.vis = fc_rng_make(seed, index, 32);
    const int witness = fc_rng_range(&s.vis, 0, p.nprim);
    for (int i = 0; i < p.nprim; i++) {
        if (i == witness)
            fcr_witness(&s);
        random_primitive(&s, p.modes[i]);
        if (c->frames == 2 && i == p.nprim / 2)
            fc_capture(h);
    }
    if (witness == p.nprim)
        fcr_witness(&s);
    random_pixels(&s, &p);
    fc_capture(h);
    fc_error(h, "scene glGetError");
}

int fc_random_tex_parse(const char *name, uint64_t *seed, uint32_t *index)
{
    char tail;
    return sscanf(name, "random-tex/s%" SCNu64 "-i%" SCNu32 "%c", seed, index, &tail) == 2;
}

void fc_random_tex_case(uint64_t seed, uint32_t index, fc_case *out, char *name)
{
    static const GLenum formats[8] = {
        OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA,
        OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB,
    };
    fc_rng r = fc_rng_make(seed, index, 13);
    fc_rng k = fc_rng_make(seed, index % FC_TEX_PROFILES, 14);

    snprintf(name, FC_RANDOM_NAME_MAX, "random-tex/s%" PRIu64 "-i%" PRIu32, seed, index);
    memset(out, 0, sizeof *out);
    out->draws_nothing = FC_MAY_DRAW_NOTHING;   /* a generated scene (fc_case.h) */
    out->name = name;
    out->width = fc_rng_range(&r, 16, 96);
    out->height = fc_rng_range(&r, 16, 96);
    out->format = formats[fc_rng_below(&k, 8)];
    out->depth_bits = fc_rng_chance(&k, 80) ? 24 : 16;
    out->frames = fc_rng_chance(&k, 20) ? 2 : 1;
    out->tags = "random-tex";
    out->fn = tex_scene;
}
