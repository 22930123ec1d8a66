/* c_tex_wrap.c - texture sampling through llvmpipe's float SoA path and
 * the general level-of-detail path (r_tex_soa.c): the wrap modes the
 * fixed-point path does not take (GL_CLAMP, CLAMP_TO_BORDER with border
 * colours, MIRRORED_REPEAT, the MIRROR_CLAMP family) with NEAREST, LINEAR
 * and mixed min/mag filters on power-of-two, non-power-of-two and 1D
 * textures, coordinates far outside [0,1], different wraps on s and t, the
 * border colour of every base format; then the LOD controls on both paths:
 * object and unit (GL_TEXTURE_FILTER_CONTROL) LOD bias, MIN_LOD / MAX_LOD
 * (including equal and crossed limits), BASE_LEVEL / MAX_LEVEL over hand
 * built mipmap chains.  The environment is GL_REPLACE unless a case says
 * otherwise. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

/* ---- textures ---- */

static unsigned rng_state;

static unsigned rng(void)
{
    rng_state = rng_state * 1103515245u + 12345u;
    return (rng_state >> 16) & 0x7fff;
}

/* Components of a client format of GL_UNSIGNED_BYTE texels. */
static int format_size(GLenum format)
{
    switch (format) {
    case GL_LUMINANCE:
    case GL_ALPHA:
    case GL_INTENSITY:
        return 1;
    case GL_LUMINANCE_ALPHA:
        return 2;
    case GL_RGB:
        return 3;
    default:
        return 4;
    }
}

/* A w x h image of pseudo-random texels (seeded), internal format ifmt
 * from client format `format`. */
static void noise_image_fmt(GLenum target, int level, int w, int h, unsigned seed,
                            GLint ifmt, GLenum format)
{
    static unsigned char buf[128 * 128 * 4];
    const int n = format_size(format);
    rng_state = seed * 7919u + (unsigned)(w * 131 + h);
    for (int i = 0; i < w * h * n; i++)
        buf[i] = (unsigned char)(rng() & 255);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (target == GL_TEXTURE_1D)
        glTexImage1D(GL_TEXTURE_1D, level, ifmt, w, 0, format, GL_UNSIGNED_BYTE, buf);
    else
        glTexImage2D(GL_TEXTURE_2D, level, ifmt, w, h, 0, format, GL_UNSIGNED_BYTE, buf);
}

static void noise_image(GLenum target, int level, int w, int h, unsigned seed)
{
    noise_image_fmt(target, level, w, h, seed, GL_RGBA, GL_RGBA);
}

static void tex_params(GLenum target, GLenum min, GLenum mag, GLenum wrap_s, GLenum wrap_t)
{
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)min);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)mag);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)wrap_s);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)wrap_t);
}

static void border(GLenum target, float r, float g, float b, float a)
{
    const GLfloat c[4] = { r, g, b, a };
    glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, c);
}

/* ---- scenes ---- */

/* A rotated quad in window coordinates (ortho) with texture coordinates
 * from lo to hi on both axes, smooth-coloured (REPLACE ignores it);
 * captured. */
static void scene_flat(fc_h *h, float lo, float hi)
{
    const fc_case *c = fc_this_case(h);
    const float w = (float)c->width, hh = (float)c->height;
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glBegin(GL_TRIANGLES);
    const float x[4] = { w * 0.08f, w * 0.93f, w * 0.81f, w * 0.03f };
    const float y[4] = { hh * 0.12f, hh * 0.04f, hh * 0.95f, hh * 0.83f };
    const float s[4] = { lo, hi, hi, lo }, t[4] = { lo, lo, hi, hi };
    static const int idx[6] = { 0, 1, 2, 0, 2, 3 };
    for (int i = 0; i < 6; i++) {
        const int k = idx[i];
        glColor4f(0.3f + 0.2f * (float)k, 0.9f - 0.2f * (float)k, 0.5f, 0.8f);
        glTexCoord2f(s[k], t[k]);
        glVertex2f(x[k], y[k]);
    }
    glEnd();
    fc_capture(h);
}

/* A floor receding from z = -1.5 to -40 under a frustum with the texture
 * repeated `rep` times from `off`, and a large triangle crossing the near
 * plane; captured.  The level of detail varies over the frame, so both
 * minified and magnified quads (and mixed 4x2 pixel groups) occur. */
static void scene_persp(fc_h *h, float off, float rep)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 60);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    glColor4f(1, 1, 1, 1);
    glTexCoord2f(off, off);               glVertex3f(-4, -1, -1.5f);
    glTexCoord2f(off + rep, off);         glVertex3f(4, -1, -1.5f);
    glTexCoord2f(off + rep, off + rep * 3); glVertex3f(4, -1, -40);
    glTexCoord2f(off, off + rep * 3);     glVertex3f(-4, -1, -40);
    glEnd();
    glBegin(GL_TRIANGLES);
    glTexCoord2f(off + 0.1f, off + 0.2f);   glVertex3f(-0.2f, 0.9f, 2.0f);
    glTexCoord2f(off + rep, off);           glVertex3f(2.5f, 0.1f, -12);
    glTexCoord2f(off + 0.3f, off + rep * 0.7f); glVertex3f(-1.5f, -0.4f, -6);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    fc_capture(h);
}

/* A 1D texture on horizontal bands: a triangle strip, lines and points
 * with s from lo to hi; captured. */
static void scene_1d(fc_h *h, float lo, float hi)
{
    const fc_case *c = fc_this_case(h);
    const float w = (float)c->width, hh = (float)c->height;
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glBegin(GL_TRIANGLE_STRIP);
    glTexCoord1f(lo);          glVertex2f(w * 0.05f, hh * 0.05f);
    glTexCoord1f(lo);          glVertex2f(w * 0.1f, hh * 0.45f);
    glTexCoord1f(hi);          glVertex2f(w * 0.95f, hh * 0.1f);
    glTexCoord1f(hi * 0.5f);   glVertex2f(w * 0.9f, hh * 0.5f);
    glEnd();
    glBegin(GL_LINES);
    for (int i = 0; i < 6; i++) {
        glTexCoord1f(lo + (float)i * 0.1f);
        glVertex2f(w * 0.02f, hh * (0.55f + 0.06f * (float)i));
        glTexCoord1f(hi - (float)i * 0.3f);
        glVertex2f(w * 0.98f, hh * (0.58f + 0.05f * (float)i));
    }
    glEnd();
    glPointSize(3);
    glBegin(GL_POINTS);
    for (int i = 0; i < 8; i++) {
        glTexCoord1f(lo + (hi - lo) * (float)i / 7.0f);
        glVertex2f(w * (0.1f + 0.11f * (float)i), hh * 0.93f);
    }
    glEnd();
    glPointSize(1);
    fc_capture(h);
}

/* ---- wrap modes: filter x wrap x size ---- */

struct wrap_param {
    const char *name;
    GLenum target;
    int w, h;
    GLenum min, mag, wrap_s, wrap_t;
    float lo, hi;       /* flat frame coordinate range */
    float off, rep;     /* perspective frame */
};

static const struct wrap_param wrap_params[] = {
#define WP(n, tg, w, h, mi, ma, ws, wt, lo, hi, off, rep) \
    { n, tg, w, h, mi, ma, ws, wt, lo, hi, off, rep },
#define FILTERS(base, tg, w, h, ws, wt, lo, hi, off, rep) \
    WP(base "_nearest", tg, w, h, GL_NEAREST, GL_NEAREST, ws, wt, lo, hi, off, rep) \
    WP(base "_linear", tg, w, h, GL_LINEAR, GL_LINEAR, ws, wt, lo, hi, off, rep) \
    WP(base "_minlin_magnear", tg, w, h, GL_LINEAR, GL_NEAREST, ws, wt, lo, hi, off, rep) \
    WP(base "_minnear_maglin", tg, w, h, GL_NEAREST, GL_LINEAR, ws, wt, lo, hi, off, rep)
    FILTERS("texture/wrap_clamp_pot", GL_TEXTURE_2D, 8, 4, GL_CLAMP, GL_CLAMP,
            -0.7f, 1.6f, -1.0f, 3.0f)
    FILTERS("texture/wrap_clamp_npot", GL_TEXTURE_2D, 5, 7, GL_CLAMP, GL_CLAMP,
            -0.7f, 1.6f, -1.0f, 3.0f)
    FILTERS("texture/wrap_border_pot", GL_TEXTURE_2D, 4, 8, GL_CLAMP_TO_BORDER,
            GL_CLAMP_TO_BORDER, -0.6f, 1.9f, -0.5f, 2.0f)
    FILTERS("texture/wrap_border_npot", GL_TEXTURE_2D, 7, 3, GL_CLAMP_TO_BORDER,
            GL_CLAMP_TO_BORDER, -0.6f, 1.9f, -0.5f, 2.0f)
    FILTERS("texture/wrap_mirror_pot", GL_TEXTURE_2D, 8, 8, GL_MIRRORED_REPEAT,
            GL_MIRRORED_REPEAT, -2.3f, 3.1f, -1.0f, 6.0f)
    FILTERS("texture/wrap_mirror_npot", GL_TEXTURE_2D, 6, 5, GL_MIRRORED_REPEAT,
            GL_MIRRORED_REPEAT, -2.3f, 3.1f, -1.0f, 6.0f)
    FILTERS("texture/wrap_mirror_min", GL_TEXTURE_2D, 64, 32, GL_MIRRORED_REPEAT,
            GL_MIRRORED_REPEAT, -3.3f, 4.1f, -4.0f, 9.0f)
    FILTERS("texture/wrap_border_min", GL_TEXTURE_2D, 37, 23, GL_CLAMP_TO_BORDER,
            GL_CLAMP_TO_BORDER, -1.3f, 2.1f, -0.5f, 3.0f)
    FILTERS("texture/wrap_clamp_min", GL_TEXTURE_2D, 40, 64, GL_CLAMP, GL_CLAMP,
            -1.3f, 2.1f, -0.5f, 3.0f)
    FILTERS("texture/wrap_mixed_border_mirror", GL_TEXTURE_2D, 8, 5, GL_CLAMP_TO_BORDER,
            GL_MIRRORED_REPEAT, -1.2f, 2.4f, -1.0f, 4.0f)
    FILTERS("texture/wrap_mixed_repeat_clamp", GL_TEXTURE_2D, 6, 8, GL_REPEAT, GL_CLAMP,
            -1.2f, 2.4f, -1.0f, 4.0f)
    FILTERS("texture/wrap_mixed_mirror_edge", GL_TEXTURE_2D, 16, 3, GL_MIRRORED_REPEAT,
            GL_CLAMP_TO_EDGE, -1.2f, 2.4f, -1.0f, 4.0f)
    FILTERS("texture/wrap_mixed_edge_border", GL_TEXTURE_2D, 5, 16, GL_CLAMP_TO_EDGE,
            GL_CLAMP_TO_BORDER, -1.2f, 2.4f, -1.0f, 4.0f)
    FILTERS("texture/wrap_mirror_clamp", GL_TEXTURE_2D, 8, 6, GL_MIRROR_CLAMP_EXT,
            GL_MIRROR_CLAMP_EXT, -1.8f, 1.7f, -2.0f, 4.0f)
    FILTERS("texture/wrap_mirror_clamp_edge", GL_TEXTURE_2D, 5, 8, GL_MIRROR_CLAMP_TO_EDGE,
            GL_MIRROR_CLAMP_TO_EDGE, -1.8f, 1.7f, -2.0f, 4.0f)
    FILTERS("texture/wrap_mirror_clamp_border", GL_TEXTURE_2D, 8, 7,
            GL_MIRROR_CLAMP_TO_BORDER_EXT, GL_MIRROR_CLAMP_TO_BORDER_EXT, -1.8f, 1.7f, -2.0f, 4.0f)
    FILTERS("texture/wrap_1x1_clamp", GL_TEXTURE_2D, 1, 1, GL_CLAMP, GL_CLAMP_TO_BORDER,
            -1.5f, 2.5f, -1.0f, 3.0f)
    FILTERS("texture/wrap_far_mirror", GL_TEXTURE_2D, 8, 4, GL_MIRRORED_REPEAT,
            GL_MIRRORED_REPEAT, -1000.3f, 1000.7f, -3000.0f, 400.0f)
    FILTERS("texture/wrap_far_clamp", GL_TEXTURE_2D, 4, 4, GL_CLAMP, GL_CLAMP_TO_BORDER,
            -3.0e9f, 3.0e9f, -1.0e6f, 1.0e5f)
    FILTERS("texture/wrap_1d_clamp", GL_TEXTURE_1D, 16, 1, GL_CLAMP, GL_CLAMP,
            -0.8f, 1.7f, -1.0f, 3.0f)
    FILTERS("texture/wrap_1d_border", GL_TEXTURE_1D, 13, 1, GL_CLAMP_TO_BORDER,
            GL_CLAMP_TO_BORDER, -0.8f, 1.7f, -1.0f, 3.0f)
    FILTERS("texture/wrap_1d_mirror", GL_TEXTURE_1D, 10, 1, GL_MIRRORED_REPEAT,
            GL_REPEAT, -3.3f, 4.2f, -2.0f, 7.0f)
#undef FILTERS
#undef WP
};

static const void *find_param(fc_h *h, const void *table, size_t n, size_t size)
{
    const char *name = fc_this_case(h)->name;
    for (size_t i = 0; i < n; i++) {
        const char *p = (const char *)table + i * size;
        if (strcmp(*(const char *const *)p, name) == 0)
            return p;
    }
    return table;
}

static void wrap_case(fc_h *h)
{
    const struct wrap_param *p = find_param(h, wrap_params,
                                            sizeof wrap_params / sizeof wrap_params[0],
                                            sizeof wrap_params[0]);
    glBindTexture(p->target, 1);
    noise_image(p->target, 0, p->w, p->h, 3);
    tex_params(p->target, p->min, p->mag, p->wrap_s, p->wrap_t);
    border(p->target, 0.9f, 0.45f, 0.1f, 0.6f);
    glEnable(p->target);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    if (p->target == GL_TEXTURE_1D) {
        scene_1d(h, p->lo, p->hi);
        scene_1d(h, p->off, p->off + p->rep);
        return;
    }
    scene_flat(h, p->lo, p->hi);
    scene_persp(h, p->off, p->rep);
    /* frame 3: the border colour as transparent black (the default, zero
     * border colour is not translated by the base format) */
    border(p->target, 0, 0, 0, 0);
    scene_flat(h, p->lo, p->hi);
}

/* The border colour and the base formats: each format's border is the
 * colour the state tracker translates (L: r,r,r,1; A: 0,0,0,a; I: r x4;
 * LA: r,r,r,a; RGB: r,g,b,1) put into the channels the format has, under
 * MODULATE on coloured geometry and under REPLACE; zero, out-of-range
 * (clamped) and ordinary border colours. */
static void wrap_border_formats(fc_h *h)
{
    static const struct { GLint ifmt; GLenum fmt; } fmts[] = {
        { GL_LUMINANCE8, GL_LUMINANCE }, { GL_ALPHA8, GL_ALPHA },
        { GL_INTENSITY8, GL_LUMINANCE }, { GL_LUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA },
        { GL_RGB8, GL_RGB }, { GL_RGBA8, GL_RGBA }, { 1, GL_LUMINANCE }, { 3, GL_RGB },
    };
    static const float borders[3][4] = {
        { 0.8f, 0.3f, 0.55f, 0.35f }, { 0, 0, 0, 0 }, { -0.5f, 1.5f, 0.25f, 2.0f },
    };
    glBindTexture(GL_TEXTURE_2D, 1);
    glEnable(GL_TEXTURE_2D);
    for (int b = 0; b < 3; b++) {
        for (int f = 0; f < 8; f++) {
            noise_image_fmt(GL_TEXTURE_2D, 0, 5, 4, (unsigned)f + 11u, fmts[f].ifmt, fmts[f].fmt);
            tex_params(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_BORDER,
                       f & 1 ? GL_CLAMP : GL_MIRRORED_REPEAT);
            glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, borders[b]);
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, b == 1 ? GL_REPLACE : GL_MODULATE);
            scene_flat(h, -0.6f, 1.5f);
        }
    }
    fc_error(h, "border formats");
}

/* The border colour under blending and the alpha test (its alpha shows in
 * the frame), several colours on one texture object. */
static void wrap_border_blend(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    noise_image(GL_TEXTURE_2D, 0, 8, 8, 5);
    tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_LINEAR, GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    border(GL_TEXTURE_2D, 1.0f, 0.0f, 0.5f, 0.25f);
    scene_flat(h, -1.0f, 2.0f);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.3f);
    border(GL_TEXTURE_2D, 0.2f, 0.9f, 0.4f, 0.75f);
    scene_flat(h, -1.0f, 2.0f);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_BLEND);
}

/* q == 0: the coordinates are infinite, their derivatives NaN, so rho and
 * the level of detail are NaN.  lod_positive is an unordered compare, so
 * NaN counts as minified: with min filter != mag filter the min filter
 * samples (LINEAR on an infinite coordinate: NaN weights, black with alpha
 * 0 in the colour buffer).  Every filter pair x mip filter, on the AoS
 * (REPEAT) and the float path (MIRRORED_REPEAT, CLAMP), as a triangle and
 * as lines; one frame per combination (random-tex/s1-i561). */
static void wrap_lod_nan(fc_h *h)
{
    static const GLenum mins[6] = {
        GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
        GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR,
    };
    static const GLenum wraps[4][2] = {
        { GL_REPEAT, GL_REPEAT }, { GL_MIRRORED_REPEAT, GL_REPEAT },
        { GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT }, { GL_CLAMP, GL_MIRRORED_REPEAT },
    };
    const fc_case *c = fc_this_case(h);
    glBindTexture(GL_TEXTURE_2D, 1);
    fcu_tex_level_chain(GL_TEXTURE_2D, 4, 8);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    for (int w = 0; w < 4; w++) {
        for (int m = 0; m < 12; m++) {
            tex_params(GL_TEXTURE_2D, mins[m % 6], m < 6 ? GL_NEAREST : GL_LINEAR, wraps[w][0],
                       wraps[w][1]);
            fc_pixel_ortho(h);
            fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
            glTexCoord4f(0.34f, 0.77f, 0.5f, 0.0f);
            glBegin(GL_TRIANGLES);
            glVertex2f(1.0f, 1.0f);
            glVertex2f((float)c->width - 2.0f, 3.0f);
            glVertex2f(5.0f, (float)c->height * 0.5f);
            glEnd();
            glTexCoord4f(-1.5f, 0.25f, 0.0f, 0.0f);
            glBegin(GL_LINES);
            glVertex2f(2.0f, (float)c->height - 3.0f);
            glVertex2f((float)c->width - 1.0f, (float)c->height * 0.6f);
            glVertex2f((float)c->width * 0.5f, (float)c->height - 1.0f);
            glVertex2f((float)c->width * 0.75f, 2.0f);
            glEnd();
            fc_capture(h);
        }
    }
}

/* Projective triangles (q varies per vertex, so the level of detail varies
 * across each) with min filter != mag filter on the float path: 8 pixels
 * (two quads) are filtered together, linearly if either quad wants the
 * LINEAR filter, the other quad's weights rounded to 0 or 1 (GL_CLAMP then
 * reaches the border colour where NEAREST would not).  One frame per
 * wrap/filter combination. */
static void wrap_minmag_vector(fc_h *h)
{
    static const GLenum wraps[6][2] = {
        { GL_CLAMP, GL_CLAMP }, { GL_MIRROR_CLAMP_EXT, GL_MIRROR_CLAMP_EXT },
        { GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT }, { GL_MIRRORED_REPEAT, GL_CLAMP },
        { GL_MIRROR_CLAMP_TO_EDGE, GL_REPEAT }, { GL_CLAMP, GL_MIRROR_CLAMP_TO_BORDER_EXT },
    };
    const fc_case *c = fc_this_case(h);
    glBindTexture(GL_TEXTURE_2D, 1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int f = 0; f < 12; f++) {
        const int w = 12 + (f * 5) % 21, hh = 9 + (f * 7) % 24;
        noise_image(GL_TEXTURE_2D, 0, w, hh, (unsigned)f + 20u);
        tex_params(GL_TEXTURE_2D, f & 1 ? GL_NEAREST : GL_LINEAR, f & 1 ? GL_LINEAR : GL_NEAREST,
                   wraps[f % 6][0], wraps[f % 6][1]);
        border(GL_TEXTURE_2D, 0.95f, 0.05f, 0.5f, 0.7f);
        fc_pixel_ortho(h);
        fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
        rng_state = (unsigned)f * 977u + 5u;
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 60; i++) {
            const float q = 0.2f + (float)(rng() % 1000) / 250.0f;
            const float range = 0.5f + (float)(rng() % 100) / 25.0f;
            const float s = ((float)(rng() % 2000) / 1000.0f - 1.0f) * range + 0.5f;
            const float t = ((float)(rng() % 2000) / 1000.0f - 1.0f) * range + 0.5f;
            glTexCoord4f(s * q, t * q, 0, q);
            glVertex2f((float)(rng() % (unsigned)(c->width * 16)) / 16.0f,
                       (float)(rng() % (unsigned)(c->height * 16)) / 16.0f);
        }
        glEnd();
        fc_capture(h);
    }
    /* s <= 0 everywhere (column 0 or the border), the level of detail
     * crossing 0 along diagonals: at each crossing, 8-pixel groups mix
     * minified and magnified quads */
    glBindTexture(GL_TEXTURE_2D, 1);
    noise_image(GL_TEXTURE_2D, 0, 64, 64, 9);
    for (int f = 0; f < 4; f++) {
        tex_params(GL_TEXTURE_2D, f & 1 ? GL_NEAREST : GL_LINEAR, f & 1 ? GL_LINEAR : GL_NEAREST,
                   f & 2 ? GL_MIRROR_CLAMP_EXT : GL_CLAMP, GL_CLAMP);
        border(GL_TEXTURE_2D, 0.95f, 0.05f, 0.5f, 0.7f);
        fc_pixel_ortho(h);
        fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
        const float w = (float)c->width, hh = (float)c->height;
        for (int k = 0; k < 3; k++) {
            const float sc = 0.5f + 0.5f * (float)k, y0 = hh * (float)k / 3.0f, y1 = y0 + hh / 3.0f;
            const float sneg = f & 2 ? -0.0f : -0.3f;
            glBegin(GL_QUADS);
            glTexCoord4f(sneg, 0, 0, 1);                 glVertex2f(0, y0);
            glTexCoord4f(sneg * 3.0f, sc * 3.0f, 0, 3.0f); glVertex2f(w, y0);
            glTexCoord4f(sneg * 0.5f, sc * 1.5f, 0, 0.5f); glVertex2f(w, y1);
            glTexCoord4f(sneg * 2.0f, sc * 0.6f, 0, 2.0f); glVertex2f(0, y1);
            glEnd();
        }
        fc_capture(h);
    }
}

/* Random samplers (seeded): size (power of two or not, 1D or 2D), a full
 * mipmap chain of noise, wraps on s and t from all eight modes, min, mag
 * and mip filters, border colour, object and unit LOD bias, MIN_LOD /
 * MAX_LOD, BASE_LEVEL / MAX_LEVEL, on projective triangles.  One frame
 * each. */
static void wrap_random(fc_h *h)
{
    static const GLenum wraps[8] = {
        GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT,
        GL_MIRROR_CLAMP_EXT, GL_MIRROR_CLAMP_TO_EDGE, GL_MIRROR_CLAMP_TO_BORDER_EXT,
    };
    static const GLenum mins[6] = {
        GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
        GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR,
    };
    const fc_case *c = fc_this_case(h);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int f = 0; f < c->frames; f++) {
        rng_state = (unsigned)f * 7717u + 3u;
        const bool is1d = f % 4 == 3;
        const GLenum target = is1d ? GL_TEXTURE_1D : GL_TEXTURE_2D;
        glDisable(GL_TEXTURE_1D);
        glDisable(GL_TEXTURE_2D);
        glEnable(target);
        glBindTexture(target, (GLuint)(1 + is1d));
        int w = 1 << (rng() % 6), hh = is1d ? 1 : 1 << (rng() % 6);
        if (rng() % 3 == 0) {
            w += (int)(rng() % 3);
            hh += is1d ? 0 : (int)(rng() % 3);
        }
        int nl = 0;
        for (int lw = w, lh = hh;; lw = lw > 1 ? lw / 2 : 1, lh = lh > 1 ? lh / 2 : 1) {
            noise_image(target, nl, lw, lh, (unsigned)f * 31u + (unsigned)nl);
            nl++;
            if (lw == 1 && lh == 1)
                break;
        }
        tex_params(target, mins[rng() % 6], rng() % 2 ? GL_LINEAR : GL_NEAREST,
                   wraps[rng() % 8], wraps[rng() % 8]);
        border(target, (float)(rng() % 256) / 255.0f, (float)(rng() % 256) / 255.0f,
               (float)(rng() % 256) / 255.0f, (float)(rng() % 256) / 255.0f);
        glTexParameterf(target, GL_TEXTURE_LOD_BIAS,
                        rng() % 2 ? (float)((int)(rng() % 64) - 32) / 8.0f : 0.0f);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS,
                  rng() % 3 == 0 ? (float)((int)(rng() % 64) - 32) / 8.0f : 0.0f);
        glTexParameterf(target, GL_TEXTURE_MIN_LOD,
                        rng() % 3 == 0 ? (float)((int)(rng() % 40) - 10) / 8.0f : -1000.0f);
        glTexParameterf(target, GL_TEXTURE_MAX_LOD,
                        rng() % 3 == 0 ? (float)((int)(rng() % 40) - 10) / 8.0f : 1000.0f);
        const int base = rng() % 4 == 0 ? (int)(rng() % (unsigned)nl) : 0;
        glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, base);
        glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, rng() % 4 == 0 ? base + (int)(rng() % 4) : 1000);
        fc_pixel_ortho(h);
        fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
        const float range = 1.0f + (float)(rng() % 16);
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 12; i++) {
            const float q = rng() % 3 ? 0.2f + (float)(rng() % 1000) / 250.0f : 1.0f;
            const float s = ((float)(rng() % 2000) / 1000.0f - 1.0f) * range + 0.5f;
            const float t = ((float)(rng() % 2000) / 1000.0f - 1.0f) * range + 0.5f;
            glTexCoord4f(s * q, t * q, 0, q);
            glVertex2f((float)(rng() % (unsigned)(c->width * 16)) / 16.0f,
                       (float)(rng() % (unsigned)(c->height * 16)) / 16.0f);
        }
        glEnd();
        fc_capture(h);
    }
    fc_error(h, "random samplers");
}

/* Mipmapped textures on the float path: every mip filter with the wraps
 * that take it, on the receding floor. */
struct wmip_param {
    const char *name;
    int w, h;
    GLenum min, mag, wrap_s, wrap_t;
};

static const struct wmip_param wmip_params[] = {
#define MP(n, w, h, mi, ma, ws, wt) { n, w, h, mi, ma, ws, wt },
#define MIPS(base, w, h, ws, wt) \
    MP(base "_nn", w, h, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, ws, wt) \
    MP(base "_ln", w, h, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, ws, wt) \
    MP(base "_nl", w, h, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, ws, wt) \
    MP(base "_ll", w, h, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, ws, wt) \
    MP(base "_ll_magnear", w, h, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST, ws, wt) \
    MP(base "_nn_maglin", w, h, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, ws, wt)
    MIPS("texture/wrap_mip_border", 32, 32, GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER)
    MIPS("texture/wrap_mip_mirror", 64, 16, GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT)
    MIPS("texture/wrap_mip_clamp_npot", 45, 27, GL_CLAMP, GL_REPEAT)
#undef MIPS
#undef MP
};

static void wrap_mip_case(fc_h *h)
{
    const struct wmip_param *p = find_param(h, wmip_params,
                                            sizeof wmip_params / sizeof wmip_params[0],
                                            sizeof wmip_params[0]);
    glBindTexture(GL_TEXTURE_2D, 1);
    fcu_tex_level_chain(GL_TEXTURE_2D, p->w, p->h);
    tex_params(GL_TEXTURE_2D, p->min, p->mag, p->wrap_s, p->wrap_t);
    border(GL_TEXTURE_2D, 0.1f, 0.8f, 0.7f, 0.5f);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_flat(h, -3.0f, 9.0f);
    scene_persp(h, -2.0f, 8.0f);
    scene_flat(h, -0.2f, 1.1f);
}

/* ---- level of detail ---- */

/* One frame per setting of the LOD controls on a mipmapped texture. */
struct lod_setting {
    float obj_bias, unit_bias, min_lod, max_lod;
    int base, max_level;
};

struct lod_param {
    const char *name;
    GLenum target;
    int w, h;
    GLenum min, mag, wrap;
    int n;
    struct lod_setting set[8];
};

#define DEF_LOD -1000.0f, 1000.0f, 0, 1000
static const struct lod_param lod_params[] = {
    { "texture/lod_bias_object", GL_TEXTURE_2D, 32, 32, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR,
      GL_REPEAT, 6,
      { { 1.5f, 0, DEF_LOD }, { -1.25f, 0, DEF_LOD }, { 0.3f, 0, DEF_LOD },
        { 4.0f, 0, DEF_LOD }, { 0.001f, 0, DEF_LOD }, { -16.5f, 0, DEF_LOD } } },
    { "texture/lod_bias_object_nearest", GL_TEXTURE_2D, 32, 16, GL_NEAREST_MIPMAP_NEAREST,
      GL_NEAREST, GL_CLAMP_TO_EDGE, 5,
      { { 0.5f, 0, DEF_LOD }, { -0.5f, 0, DEF_LOD }, { 1.75f, 0, DEF_LOD },
        { 0.0019f, 0, DEF_LOD }, { 2.5f, 0, DEF_LOD } } },
    { "texture/lod_bias_unit", GL_TEXTURE_2D, 32, 32, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR,
      GL_REPEAT, 5,
      { { 0, 1.0f, DEF_LOD }, { 0, -2.0f, DEF_LOD }, { 1.0f, -1.0f, DEF_LOD },
        { 0.75f, 0.5f, DEF_LOD }, { 16.0f, 16.0f, DEF_LOD } } },
    { "texture/lod_bias_minmag", GL_TEXTURE_2D, 16, 16, GL_LINEAR, GL_NEAREST,
      GL_REPEAT, 4,
      { { 2.0f, 0, DEF_LOD }, { -3.0f, 0, DEF_LOD }, { 0, 0.6f, DEF_LOD },
        { 0.25f, 0.25f, DEF_LOD } } },
    { "texture/lod_bias_minmag_nearest", GL_TEXTURE_2D, 16, 8, GL_NEAREST_MIPMAP_LINEAR,
      GL_LINEAR, GL_CLAMP_TO_EDGE, 4,
      { { 1.0f, 0, DEF_LOD }, { -1.0f, 0, DEF_LOD }, { 0.125f, 0, DEF_LOD },
        { 0, 3.0f, DEF_LOD } } },
    { "texture/lod_minmax", GL_TEXTURE_2D, 32, 32, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR,
      GL_REPEAT, 8,
      { { 0, 0, 1.0f, 2.5f, 0, 1000 }, { 0, 0, -1.0f, 0.5f, 0, 1000 },
        { 0, 0, 2.0f, 2.0f, 0, 1000 }, { 0, 0, -3.0f, 0.0f, 0, 1000 },
        { 0, 0, 3.0f, 1.0f, 0, 1000 }, { 0, 0, -1000.0f, 14.5f, 0, 1000 },
        { 0, 0, -1000.0f, 15.0f, 0, 1000 }, { 1.0f, 0, 0.5f, 3.25f, 0, 1000 } } },
    { "texture/lod_minmax_nearest", GL_TEXTURE_2D, 16, 32, GL_NEAREST_MIPMAP_NEAREST,
      GL_LINEAR, GL_REPEAT, 6,
      { { 0, 0, 1.5f, 1000.0f, 0, 1000 }, { 0, 0, -1000.0f, 1.4f, 0, 1000 },
        { 0, 0, 0.25f, 0.25f, 0, 1000 }, { 0, 0, 0.0f, 0.0f, 0, 1000 },
        { -2.0f, 0, 0.5f, 1000.0f, 0, 1000 }, { 0, 0, -1000.0f, -0.5f, 0, 1000 } } },
    { "texture/lod_base_max_level", GL_TEXTURE_2D, 64, 32, GL_LINEAR_MIPMAP_LINEAR,
      GL_LINEAR, GL_REPEAT, 6,
      { { 0, 0, -1000.0f, 1000.0f, 1, 1000 }, { 0, 0, -1000.0f, 1000.0f, 2, 4 },
        { 0, 0, -1000.0f, 1000.0f, 0, 2 }, { 0, 0, -1000.0f, 1000.0f, 3, 3 },
        { 1.5f, 0, -1000.0f, 1000.0f, 2, 1000 }, { 0, 0, 1.0f, 2.0f, 1, 5 } } },
    { "texture/lod_base_level_nearest", GL_TEXTURE_2D, 32, 32, GL_NEAREST_MIPMAP_NEAREST,
      GL_NEAREST, GL_CLAMP_TO_EDGE, 4,
      { { 0, 0, -1000.0f, 1000.0f, 2, 1000 }, { 0, 0, -1000.0f, 1000.0f, 4, 1000 },
        { 0, 0, -1000.0f, 1000.0f, 1, 2 }, { -1.0f, 0, -1000.0f, 1000.0f, 5, 1000 } } },
    { "texture/lod_base_level_nomip", GL_TEXTURE_2D, 32, 16, GL_LINEAR, GL_NEAREST,
      GL_REPEAT, 3,
      { { 0, 0, -1000.0f, 1000.0f, 1, 1000 }, { 0, 0, -1000.0f, 1000.0f, 3, 1000 },
        { 0.5f, 0, -1000.0f, 1000.0f, 2, 1000 } } },
    { "texture/lod_soa_border", GL_TEXTURE_2D, 32, 32, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR,
      GL_CLAMP_TO_BORDER, 5,
      { { 1.0f, 0, DEF_LOD }, { -1.5f, 0, DEF_LOD }, { 0, 0, 1.0f, 2.0f, 0, 1000 },
        { 0, 0.5f, -1000.0f, 1000.0f, 1, 3 }, { 0, 0, 1.5f, 1.5f, 0, 1000 } } },
    { "texture/lod_soa_mirror_nearest", GL_TEXTURE_2D, 16, 32, GL_NEAREST_MIPMAP_NEAREST,
      GL_LINEAR, GL_MIRRORED_REPEAT, 4,
      { { 0.5f, 0, DEF_LOD }, { -0.75f, 0, DEF_LOD }, { 0, 0, 0.5f, 1.5f, 0, 1000 },
        { 0, 0, -1000.0f, 1000.0f, 2, 1000 } } },
    { "texture/lod_1d", GL_TEXTURE_1D, 64, 1, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT, 4,
      { { 1.0f, 0, DEF_LOD }, { -2.0f, 0, DEF_LOD }, { 0, 0, 1.0f, 3.0f, 0, 1000 },
        { 0, 0, -1000.0f, 1000.0f, 2, 4 } } },
    { "texture/lod_1d_clamp", GL_TEXTURE_1D, 32, 1, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR,
      GL_CLAMP, 3,
      { { 0.5f, 0, DEF_LOD }, { 0, 0, 2.0f, 2.0f, 0, 1000 }, { 0, 0, -1000.0f, 1000.0f, 1, 3 } } },
};
#undef DEF_LOD

static void lod_case(fc_h *h)
{
    const struct lod_param *p = find_param(h, lod_params,
                                           sizeof lod_params / sizeof lod_params[0],
                                           sizeof lod_params[0]);
    glBindTexture(p->target, 1);
    fcu_tex_level_chain(p->target, p->w, p->h);
    tex_params(p->target, p->min, p->mag, p->wrap, p->wrap);
    border(p->target, 0.6f, 0.2f, 0.9f, 0.4f);
    glEnable(p->target);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int i = 0; i < p->n; i++) {
        const struct lod_setting *s = &p->set[i];
        glTexParameterf(p->target, GL_TEXTURE_LOD_BIAS, s->obj_bias);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, s->unit_bias);
        glTexParameterf(p->target, GL_TEXTURE_MIN_LOD, s->min_lod);
        glTexParameterf(p->target, GL_TEXTURE_MAX_LOD, s->max_lod);
        glTexParameteri(p->target, GL_TEXTURE_BASE_LEVEL, s->base);
        glTexParameteri(p->target, GL_TEXTURE_MAX_LEVEL, s->max_level);
        if (p->target == GL_TEXTURE_1D)
            scene_1d(h, -2.0f + 0.1f * (float)i, 9.0f);
        else
            scene_persp(h, -1.0f + 0.1f * (float)i, 8.0f);
    }
    fc_error(h, "lod settings");
}

/* The bias and limits as the queries return them (the quantization and
 * the clamp of min_lod happen only in the sampler state). */
static void lod_queries(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.3333f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -2.5f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 123.0f);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -20.0f);
    fc_get_float(h, "lod bias", GL_TEXTURE_LOD_BIAS, 1);
    GLfloat f[4];
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, f);
    fc_blob(h, "object bias", f, sizeof(GLfloat));
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, f);
    fc_blob(h, "min lod", f, sizeof(GLfloat));
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, f);
    fc_blob(h, "max lod", f, sizeof(GLfloat));
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, f);
    fc_blob(h, "unit bias", f, sizeof(GLfloat));
    fc_get_float(h, "max lod bias", GL_MAX_TEXTURE_LOD_BIAS, 1);
    fc_error(h, "queries");
}

const fc_case fc_cases_tex_wrap[] = {
#define WC(n) FC_CASE_RGBA(n "_nearest", 48, 48, 3, "texture", wrap_case),        \
              FC_CASE_RGBA(n "_linear", 48, 48, 3, "texture", wrap_case),         \
              FC_CASE_RGBA(n "_minlin_magnear", 48, 48, 3, "texture", wrap_case), \
              FC_CASE_RGBA(n "_minnear_maglin", 48, 48, 3, "texture", wrap_case)
    WC("texture/wrap_clamp_pot"),
    WC("texture/wrap_clamp_npot"),
    WC("texture/wrap_border_pot"),
    WC("texture/wrap_border_npot"),
    WC("texture/wrap_mirror_pot"),
    WC("texture/wrap_mirror_npot"),
    WC("texture/wrap_mirror_min"),
    WC("texture/wrap_border_min"),
    WC("texture/wrap_clamp_min"),
    WC("texture/wrap_mixed_border_mirror"),
    WC("texture/wrap_mixed_repeat_clamp"),
    WC("texture/wrap_mixed_mirror_edge"),
    WC("texture/wrap_mixed_edge_border"),
    WC("texture/wrap_mirror_clamp"),
    WC("texture/wrap_mirror_clamp_edge"),
    WC("texture/wrap_mirror_clamp_border"),
    WC("texture/wrap_1x1_clamp"),
    WC("texture/wrap_far_mirror"),
    WC("texture/wrap_far_clamp"),
#undef WC
#define WC1(n) FC_CASE_RGBA(n "_nearest", 48, 32, 2, "texture", wrap_case),        \
               FC_CASE_RGBA(n "_linear", 48, 32, 2, "texture", wrap_case),         \
               FC_CASE_RGBA(n "_minlin_magnear", 48, 32, 2, "texture", wrap_case), \
               FC_CASE_RGBA(n "_minnear_maglin", 48, 32, 2, "texture", wrap_case)
    WC1("texture/wrap_1d_clamp"),
    WC1("texture/wrap_1d_border"),
    WC1("texture/wrap_1d_mirror"),
#undef WC1
    FC_CASE_RGBA("texture/wrap_border_formats", 40, 40, 24, "texture", wrap_border_formats),
    FC_CASE_RGBA("texture/wrap_border_blend", 40, 40, 2, "texture fragment", wrap_border_blend),
    FC_CASE_RGBA("texture/wrap_minmag_vector", 48, 48, 16, "texture", wrap_minmag_vector),
    FC_CASE_RGBA("texture/wrap_lod_nan", 24, 24, 48, "texture", wrap_lod_nan),
    FC_CASE_RGBA("texture/wrap_random", 48, 48, 32, "texture", wrap_random),
#define MC(n) FC_CASE_RGBA(n "_nn", 64, 64, 3, "texture", wrap_mip_case),         \
              FC_CASE_RGBA(n "_ln", 64, 64, 3, "texture", wrap_mip_case),         \
              FC_CASE_RGBA(n "_nl", 64, 64, 3, "texture", wrap_mip_case),         \
              FC_CASE_RGBA(n "_ll", 64, 64, 3, "texture", wrap_mip_case),         \
              FC_CASE_RGBA(n "_ll_magnear", 64, 64, 3, "texture", wrap_mip_case), \
              FC_CASE_RGBA(n "_nn_maglin", 64, 64, 3, "texture", wrap_mip_case)
    MC("texture/wrap_mip_border"),
    MC("texture/wrap_mip_mirror"),
    MC("texture/wrap_mip_clamp_npot"),
#undef MC
    FC_CASE_RGBA("texture/lod_bias_object", 64, 64, 6, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_bias_object_nearest", 64, 64, 5, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_bias_unit", 64, 64, 5, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_bias_minmag", 64, 64, 4, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_bias_minmag_nearest", 64, 64, 4, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_minmax", 64, 64, 8, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_minmax_nearest", 64, 64, 6, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_base_max_level", 64, 64, 6, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_base_level_nearest", 64, 64, 4, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_base_level_nomip", 64, 64, 3, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_soa_border", 64, 64, 5, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_soa_mirror_nearest", 64, 64, 4, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_1d", 64, 32, 4, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_1d_clamp", 64, 32, 3, "texture", lod_case),
    FC_CASE_RGBA("texture/lod_queries", 8, 8, 0, "texture query", lod_queries),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
