/* c_tex_sample.c - texture sampling through llvmpipe's fixed-point AoS
 * path (libfixgl/ORACLE-NOTES.md "Texture sampling: the 8-bit path"):
 * every image filter and wrap mode of that
 * path (REPEAT, CLAMP_TO_EDGE) on power-of-two, non-power-of-two, 1x1 and
 * 1D textures, magnified and minified, with the per-quad level of detail
 * choosing between the magnification and minification filters; mipmap
 * chains built by hand with distinct colours per level, sampled across
 * levels on receding planes with every mipmap filter; perspective-correct
 * texturing of large triangles crossing the near plane; textured lines and
 * points.  The environment is GL_REPLACE unless a case says otherwise. */
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

/* A w x h RGBA texture of pseudo-random texels (seeded by its size), so
 * that every texel and every lerp weight shows. */
static void noise_image(GLenum target, int level, int w, int h, unsigned seed)
{
    static unsigned char buf[256 * 256 * 4];
    rng_state = seed * 7919u + (unsigned)(w * 131 + h);
    for (int i = 0; i < w * h * 4; i++)
        buf[i] = (unsigned char)(rng() & 255);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (target == GL_TEXTURE_1D)
        glTexImage1D(GL_TEXTURE_1D, level, GL_RGBA, w, 0, GL_RGBA, GL_UNSIGNED_BYTE, buf);
    else
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, buf);
}

static void tex_params(GLenum target, GLenum min, GLenum mag, GLenum wrap)
{
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)min);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)mag);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)wrap);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)wrap);
}

/* ---- scenes ---- */

/* Frame 1: a rotated quad in window coordinates (ortho) with texture
 * coordinates from -s0 to s1, smooth-coloured (REPLACE ignores it). */
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
        glColor4f(0.3f + 0.2f * (float)k, 0.9f - 0.2f * (float)k, 0.5f, 1.0f);
        glTexCoord2f(s[k], t[k]);
        glVertex2f(x[k], y[k]);
    }
    glEnd();
    fc_capture(h);
}

/* Frame 2: a floor receding from z = -1 to -40 under a frustum, with the
 * texture repeated `rep` times, and a large triangle crossing the near
 * plane (clipped: new vertices' coordinates interpolate in clip space). */
static void scene_persp(fc_h *h, float rep)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 60);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    glTexCoord2f(-0.3f, 0);         glVertex3f(-4, -1, -1.5f);
    glTexCoord2f(rep - 0.3f, 0);    glVertex3f(4, -1, -1.5f);
    glTexCoord2f(rep - 0.3f, rep * 3); glVertex3f(4, -1, -40);
    glTexCoord2f(-0.3f, rep * 3);   glVertex3f(-4, -1, -40);
    glEnd();
    glBegin(GL_TRIANGLES);
    glTexCoord2f(0.1f, 0.2f);       glVertex3f(-0.2f, 0.9f, 2.0f);
    glTexCoord2f(rep, 0.0f);        glVertex3f(2.5f, 0.1f, -12);
    glTexCoord2f(0.3f, rep * 0.7f); glVertex3f(-1.5f, -0.4f, -6);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    fc_capture(h);
}

/* ---- sampling cases: filter x wrap x size ---- */

struct sample_param {
    const char *name;
    GLenum target;
    int w, h;
    GLenum min, mag, wrap;
    float lo, hi;       /* frame 1 coordinate range */
    float rep;          /* frame 2 repetitions */
};

static const struct sample_param sample_params[] = {
#define SP(n, tg, w, h, mi, ma, wr, lo, hi, rep) { n, tg, w, h, mi, ma, wr, lo, hi, rep },
#define SIZES(base, tg, w, h, lo, hi, rep) \
    SP(base "_nearest_repeat", tg, w, h, GL_NEAREST, GL_NEAREST, GL_REPEAT, lo, hi, rep) \
    SP(base "_nearest_edge", tg, w, h, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, lo, hi, rep) \
    SP(base "_linear_repeat", tg, w, h, GL_LINEAR, GL_LINEAR, GL_REPEAT, lo, hi, rep) \
    SP(base "_linear_edge", tg, w, h, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, lo, hi, rep) \
    SP(base "_minlin_magnear_repeat", tg, w, h, GL_LINEAR, GL_NEAREST, GL_REPEAT, lo, hi, rep) \
    SP(base "_minnear_maglin_edge", tg, w, h, GL_NEAREST, GL_LINEAR, GL_CLAMP_TO_EDGE, lo, hi, rep)
    SIZES("texture/sample_2d_pot_mag", GL_TEXTURE_2D, 8, 4, -0.6f, 1.7f, 2.0f)
    SIZES("texture/sample_2d_npot_mag", GL_TEXTURE_2D, 5, 7, -0.6f, 1.7f, 2.0f)
    SIZES("texture/sample_2d_pot_min", GL_TEXTURE_2D, 64, 32, -2.3f, 3.1f, 6.0f)
    SIZES("texture/sample_2d_npot_min", GL_TEXTURE_2D, 37, 23, -2.3f, 3.1f, 6.0f)
    SIZES("texture/sample_2d_1x1", GL_TEXTURE_2D, 1, 1, -1.5f, 2.5f, 3.0f)
    SIZES("texture/sample_1d_pot", GL_TEXTURE_1D, 16, 1, -0.8f, 2.2f, 4.0f)
    SIZES("texture/sample_1d_npot", GL_TEXTURE_1D, 13, 1, -3.3f, 4.2f, 9.0f)
    SIZES("texture/sample_2d_wide", GL_TEXTURE_2D, 128, 2, -0.4f, 1.3f, 2.0f)
#undef SIZES
#undef SP
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

static void sample_case(fc_h *h)
{
    const struct sample_param *p = find_param(h, sample_params,
                                              sizeof sample_params / sizeof sample_params[0],
                                              sizeof sample_params[0]);
    glBindTexture(p->target, 1);
    noise_image(p->target, 0, p->w, p->h, 1);
    tex_params(p->target, p->min, p->mag, p->wrap);
    glEnable(p->target);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_flat(h, p->lo, p->hi);
    scene_persp(h, p->rep);
}

/* ---- mipmaps ---- */

struct mip_param {
    const char *name;
    GLenum target;
    int w, h;
    GLenum min, mag, wrap;
};

static const struct mip_param mip_params[] = {
#define MP(n, tg, w, h, mi, ma, wr) { n, tg, w, h, mi, ma, wr },
#define FILTERS(base, tg, w, h, wr) \
    MP(base "_nn", tg, w, h, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, wr) \
    MP(base "_ln", tg, w, h, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, wr) \
    MP(base "_nl", tg, w, h, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, wr) \
    MP(base "_ll", tg, w, h, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, wr) \
    MP(base "_ll_magnear", tg, w, h, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST, wr) \
    MP(base "_nn_maglin", tg, w, h, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, wr)
    FILTERS("texture/mip_2d_pot_repeat", GL_TEXTURE_2D, 32, 32, GL_REPEAT)
    FILTERS("texture/mip_2d_pot_edge", GL_TEXTURE_2D, 64, 16, GL_CLAMP_TO_EDGE)
    FILTERS("texture/mip_2d_npot_repeat", GL_TEXTURE_2D, 45, 27, GL_REPEAT)
    FILTERS("texture/mip_2d_npot_edge", GL_TEXTURE_2D, 23, 40, GL_CLAMP_TO_EDGE)
    FILTERS("texture/mip_1d_repeat", GL_TEXTURE_1D, 64, 1, GL_REPEAT)
    FILTERS("texture/mip_1d_npot_edge", GL_TEXTURE_1D, 50, 1, GL_CLAMP_TO_EDGE)
#undef FILTERS
#undef MP
};

static void mip_case(fc_h *h)
{
    const struct mip_param *p = find_param(h, mip_params,
                                           sizeof mip_params / sizeof mip_params[0],
                                           sizeof mip_params[0]);
    glBindTexture(p->target, 1);
    fcu_tex_level_chain(p->target, p->w, p->h);
    tex_params(p->target, p->min, p->mag, p->wrap);
    glEnable(p->target);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_flat(h, -3.0f, 9.0f);
    scene_persp(h, 8.0f);
    /* frame 3: magnified corner (levels chosen per quad around lod 0) */
    scene_flat(h, 0.1f, 0.9f);
}

/* ---- primitives ---- */

/* Textured lines and points: lines get their quad's derivatives from the
 * line's planes; points have none (magnified). */
static void lines_points(fc_h *h)
{
    fc_pixel_ortho(h);
    glBindTexture(GL_TEXTURE_2D, 1);
    fcu_tex_level_chain(GL_TEXTURE_2D, 16, 16);
    tex_params(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    fcu_clear(0, 0, 0, 1, 1);
    for (int i = 0; i < 8; i++) {
        glLineWidth(1.0f + (float)(i % 3));
        glBegin(GL_LINES);
        glColor3f(1, 1, 1);
        glTexCoord2f(0.0f, 0.1f * (float)i);
        glVertex2f(2.5f + (float)i, 3.0f + 7.0f * (float)i);
        glColor3f(0.5f, 1, 0.7f);
        glTexCoord2f(0.5f + 2.0f * (float)i, 1.3f);
        glVertex2f(60.0f - (float)i, 10.0f + 5.0f * (float)i);
        glEnd();
    }
    glBegin(GL_POINTS);
    for (int i = 0; i < 12; i++) {
        glTexCoord2f(0.09f * (float)i, 0.77f - 0.05f * (float)i);
        glVertex2f(4.5f + 5.0f * (float)i, 60.0f - 1.5f * (float)i);
    }
    glEnd();
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 6; i++) {
        glTexCoord2f(0.13f * (float)i, 0.31f * (float)i);
        glVertex2f(8.0f + 9.0f * (float)i, 50.0f);
    }
    glEnd();
    fc_capture(h);
    tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_LINEAR, GL_CLAMP_TO_EDGE);
    fc_capture(h);
}

/* The same texture object rebound and its image replaced between draws;
 * an incomplete mipmap chain (no texturing: the unit drops out). */
static void rebind_incomplete(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    noise_image(GL_TEXTURE_2D, 0, 8, 8, 2);
    tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    scene_flat(h, -0.2f, 1.3f);
    noise_image(GL_TEXTURE_2D, 0, 4, 16, 3);
    scene_flat(h, -0.2f, 1.3f);
    tex_params(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    scene_flat(h, -0.2f, 1.3f);
    glBindTexture(GL_TEXTURE_2D, 2);
    fcu_tex_level_chain(GL_TEXTURE_2D, 8, 8);
    tex_params(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT);
    scene_flat(h, -2.2f, 4.3f);
}


/* Projective texture coordinates: q varies per vertex, so the lookup
 * divides by the interpolated q (coord * frcp(q)) before the level of
 * detail; ortho and perspective, with mipmaps. */
static void projective(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    fcu_tex_level_chain(GL_TEXTURE_2D, 32, 16);
    tex_params(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glBegin(GL_TRIANGLES);
    glTexCoord4f(0.1f, 0.2f, 0, 1.0f);   glVertex2f(2, 3);
    glTexCoord4f(2.4f, 0.1f, 0, 3.0f);   glVertex2f(62, 5);
    glTexCoord4f(0.5f, 1.9f, 0, 0.5f);   glVertex2f(30, 61);
    glTexCoord4f(-1.0f, 3.0f, 0, 2.0f);  glVertex2f(61, 62);
    glTexCoord4f(4.0f, -2.0f, 0, -1.5f); glVertex2f(40, 20);
    glTexCoord4f(0.3f, 0.7f, 0, 0.25f);  glVertex2f(10, 55);
    glEnd();
    fc_capture(h);
    tex_params(GL_TEXTURE_2D, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 60);
    fcu_clear(0, 0, 0, 1, 1);
    glBegin(GL_QUADS);
    glTexCoord4f(0, 0, 0, 1);       glVertex3f(-4, -1, -1.5f);
    glTexCoord4f(8, 0, 0, 2);       glVertex3f(4, -1, -1.5f);
    glTexCoord4f(4, 12, 0, 0.5f);   glVertex3f(4, -1, -40);
    glTexCoord4f(0, 3, 0, 1.25f);   glVertex3f(-4, -1, -40);
    glEnd();
    fc_capture(h);
}

/* A texture coordinate set once before glBegin (the current value), on
 * perspective triangles, at coordinates on exact LINEAR rounding ties
 * and NEAREST texel edges. */
static void const_coord(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    noise_image(GL_TEXTURE_2D, 0, 4, 4, 4);
    tex_params(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    const fc_case *c = fc_this_case(h);
    for (int frame = 0; frame < 2; frame++) {
        glViewport(0, 0, c->width, c->height);
        fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 60);
        fcu_clear(0, 0, 0, 1, 1);
        for (int i = 0; i < 16; i++) {
            const float x = -3.0f + 0.4f * (float)(i % 4), y = -1.0f + 0.6f * (float)(i / 4);
            /* (k + 0.5) / 1024: s * 4 * 256 is a tie */
            glTexCoord2f(((float)(i * 37 % 1024) + 0.5f) / 1024.0f,
                         ((float)(i * 91 % 1024) + 0.5f) / 1024.0f);
            glBegin(GL_TRIANGLES);
            glVertex3f(x, y, -2.0f - 0.5f * (float)i);
            glVertex3f(x + 1.5f, y - 0.3f, -9.0f);
            glVertex3f(x + 0.2f, y + 1.2f, -4.0f);
            glEnd();
        }
        fc_capture(h);
        tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_REPEAT);
    }
}

/* GL_TEXTURE_BASE_LEVEL / MAX_LEVEL: the chain from level 1, cut at 3
 * (the levels range, not a LOD clamp: still the fast path). */
static void base_max_level(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    fcu_tex_level_chain(GL_TEXTURE_2D, 64, 64);
    tex_params(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_persp(h, 10.0f);
    tex_params(GL_TEXTURE_2D, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT);
    scene_flat(h, -1.0f, 7.0f);
}

/* Texturing with polygon stipple, flat shading, smooth points and lines
 * (the draw module's quads, drawn as triangles), culling and polygon
 * offset. */
static void raster_state(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    fcu_tex_level_chain(GL_TEXTURE_2D, 16, 16);
    tex_params(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    GLubyte pat[128];
    for (int i = 0; i < 128; i++)
        pat[i] = (GLubyte)(0x5a ^ (i * 13));
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    glShadeModel(GL_FLAT);
    scene_flat(h, -0.5f, 2.5f);
    glDisable(GL_POLYGON_STIPPLE);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_LINE_SMOOTH);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glPointSize(6.0f);
    glLineWidth(3.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 6; i++) {
        glTexCoord2f(0.17f * (float)i, 0.4f);
        glVertex2f(6.0f + 10.0f * (float)i, 10.0f);
    }
    glEnd();
    glBegin(GL_LINES);
    glTexCoord2f(0, 0); glVertex2f(3, 20);
    glTexCoord2f(3, 1); glVertex2f(60, 50);
    glTexCoord2f(0, 2); glVertex2f(5, 60);
    glTexCoord2f(1, 0); glVertex2f(58, 30);
    glEnd();
    fc_capture(h);
}

/* Different wraps on s and t; GL_TEXTURE_1D and 2D enabled together (2D
 * wins); the 1D texture minified on a receding plane. */
static void mixed_wrap(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    noise_image(GL_TEXTURE_2D, 0, 6, 8, 5);
    tex_params(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_1D, 2);
    noise_image(GL_TEXTURE_1D, 0, 8, 1, 6);
    tex_params(GL_TEXTURE_1D, GL_NEAREST, GL_LINEAR, GL_REPEAT);
    glEnable(GL_TEXTURE_1D);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_flat(h, -1.3f, 2.1f);
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    scene_persp(h, 5.0f);
    glDisable(GL_TEXTURE_2D);
    scene_persp(h, 7.0f);
}

/* Large triangles crossing the near plane in a bigger buffer: clipped
 * vertices get their texture coordinates by the clipper's lerp, then
 * perspective-correct interpolation over hundreds of pixels. */
static void persp_large(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    fcu_tex_level_chain(GL_TEXTURE_2D, 64, 64);
    tex_params(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.6, 0.6, -0.45, 0.45, 0.5, 100);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glRotatef(17.0f, 0.2f, 1.0f, 0.1f);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 1);       glTexCoord2f(0, 0);   glVertex3f(-30, -2, 10);
    glColor3f(1, 0.8f, 0.6f); glTexCoord2f(20, 0);  glVertex3f(30, -2, 10);
    glColor3f(0.6f, 0.8f, 1); glTexCoord2f(10, 40); glVertex3f(0, -2, -90);
    glColor3f(0.9f, 0.9f, 0.9f); glTexCoord2f(-3, 1); glVertex3f(-3, 4, 3);
    glColor3f(0.7f, 1, 0.7f); glTexCoord2f(5, 2);   glVertex3f(6, -1, -25);
    glColor3f(1, 0.7f, 0.7f); glTexCoord2f(1, 9);   glVertex3f(-2, 9, -40);
    glEnd();
    fc_capture(h);
    tex_params(GL_TEXTURE_2D, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, GL_CLAMP_TO_EDGE);
    glRotatef(-40.0f, 1.0f, 0.0f, 0.0f);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(-0.5f, -0.5f); glVertex3f(-20, -3, 5);
    glTexCoord2f(1.5f, -0.5f);  glVertex3f(20, -3, 5);
    glTexCoord2f(1.5f, 1.5f);   glVertex3f(20, -3, -60);
    glTexCoord2f(-0.5f, 1.5f);  glVertex3f(-20, -3, -60);
    glEnd();
    fc_capture(h);
}

/* Texture coordinates from arrays (glDrawArrays, glDrawElements), a
 * display list, and polygon mode GL_LINE / GL_POINT (the draw module's
 * unfilled stage). */
static void arrays_lists(fc_h *h)
{
    glBindTexture(GL_TEXTURE_2D, 1);
    fcu_tex_level_chain(GL_TEXTURE_2D, 32, 32);
    tex_params(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    static const GLfloat v[8][2] = { { 2, 2 }, { 30, 4 }, { 60, 3 }, { 4, 30 },
                                     { 33, 31 }, { 61, 28 }, { 3, 61 }, { 58, 60 } };
    static const GLfloat t[8][2] = { { 0, 0 }, { 1.5f, 0.1f }, { 3.2f, -0.2f }, { 0.2f, 1.4f },
                                     { 1.7f, 1.6f }, { 2.9f, 1.1f }, { -0.4f, 3.3f }, { 2.5f, 3.0f } };
    static const GLubyte idx[] = { 0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glTexCoordPointer(2, GL_FLOAT, 0, t);
    glDrawElements(GL_QUADS, 12, GL_UNSIGNED_BYTE, idx);
    fc_capture(h);
    fcu_clear(0, 0, 0, 1, 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 8);
    fc_capture(h);
    glNewList(1, GL_COMPILE);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 6);
    glEndList();
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    fcu_clear(0, 0, 0, 1, 1);
    glCallList(1);
    fc_capture(h);
    fcu_clear(0, 0, 0, 1, 1);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glLineWidth(2.0f);
    glCallList(1);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(3.0f);
    glTranslatef(1.5f, 0.5f, 0);
    glCallList(1);
    fc_capture(h);
}

/* Extreme coordinates: huge s and t (the fixed-point conversions
 * overflow), q = 0 at a vertex (infinite and NaN coordinates), for every
 * filter and wrap of the AoS path. */
static void extreme_coords(fc_h *h)
{
    static const GLenum filt[4][2] = { { GL_NEAREST, GL_NEAREST }, { GL_LINEAR, GL_LINEAR },
                                       { GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST },
                                       { GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR } };
    glBindTexture(GL_TEXTURE_2D, 1);
    fcu_tex_level_chain(GL_TEXTURE_2D, 8, 8);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    fc_pixel_ortho(h);
    for (int f = 0; f < 4; f++) {
        tex_params(GL_TEXTURE_2D, filt[f][0], filt[f][1], f & 1 ? GL_CLAMP_TO_EDGE : GL_REPEAT);
        fcu_clear(0, 0, 0, 1, 1);
        glBegin(GL_TRIANGLES);
        glTexCoord2f(3e9f, -2e9f);   glVertex2f(1, 1);
        glTexCoord2f(-1e8f, 5e7f);   glVertex2f(30, 2);
        glTexCoord2f(1e6f, 1e6f);    glVertex2f(15, 30);
        glTexCoord4f(0.5f, 0.5f, 0, 0);  glVertex2f(33, 33);
        glTexCoord4f(1, 2, 0, 1);        glVertex2f(62, 35);
        glTexCoord4f(0, 0, 0, 0);        glVertex2f(50, 62);
        glTexCoord2f(16777216.0f, 8388609.5f); glVertex2f(2, 34);
        glTexCoord2f(-16777215.0f, 0.5f);      glVertex2f(30, 40);
        glTexCoord2f(1e30f, -1e30f);           glVertex2f(10, 62);
        glEnd();
        fc_capture(h);
    }
}

/* Random scenes: per frame a random texture size (1..70 each way, 1D or
 * 2D), random filters, wraps, mipmap chain, env mode, and 24 random
 * triangles, half of them in perspective with random w. */
static float frand(float lo, float hi)
{
    return lo + (hi - lo) * (float)(rng() & 0x7fff) / 32767.0f;
}

static void random_scenes(fc_h *h)
{
    static const GLenum mins[6] = { GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
                                    GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                                    GL_LINEAR_MIPMAP_LINEAR };
    static const GLenum envs[5] = { GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD };
    const fc_case *c = fc_this_case(h);
    unsigned seed = (unsigned)c->name[strlen(c->name) - 1] * 977u;
    for (int frame = 0; frame < c->frames; frame++) {
        rng_state = seed + (unsigned)frame * 7717u;
        const bool is1d = (rng() % 5) == 0;
        const GLenum target = is1d ? GL_TEXTURE_1D : GL_TEXTURE_2D;
        int w = 1 + (int)(rng() % 70), hh = is1d ? 1 : 1 + (int)(rng() % 70);
        if (rng() & 1) {
            /* power of two */
            w = 1 << (rng() % 7);
            hh = is1d ? 1 : 1 << (rng() % 7);
        }
        const GLenum min = mins[rng() % 6], mag = (rng() & 1) ? GL_LINEAR : GL_NEAREST;
        const GLenum ws = (rng() & 1) ? GL_REPEAT : GL_CLAMP_TO_EDGE;
        const GLenum wt = (rng() & 1) ? GL_REPEAT : GL_CLAMP_TO_EDGE;
        const GLenum env = envs[rng() % 5];
        const unsigned tseed = rng();
        glDisable(GL_TEXTURE_1D);
        glDisable(GL_TEXTURE_2D);
        glBindTexture(target, (GLuint)(frame + 1));
        if (min == GL_NEAREST || min == GL_LINEAR) {
            noise_image(target, 0, w, hh, tseed);
        } else {
            int lw = w, lh = hh;
            for (int l = 0;; l++) {
                noise_image(target, l, lw, lh, tseed + (unsigned)l);
                if (lw == 1 && lh == 1)
                    break;
                lw = lw > 1 ? lw / 2 : 1;
                lh = lh > 1 ? lh / 2 : 1;
            }
        }
        rng_state = seed * 31u + (unsigned)frame;
        glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)min);
        glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)mag);
        glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)ws);
        glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)wt);
        glEnable(target);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env);
        const float ec[4] = { frand(0, 1), frand(0, 1), frand(0, 1), frand(0, 1) };
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
        glViewport(0, 0, c->width, c->height);
        fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 50);
        fcu_clear(0.1f, 0.2f, 0.3f, 0.4f, 1);
        glEnable(GL_DEPTH_TEST);
        const float range = frand(0.2f, 12.0f);
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 24 * 3; i++) {
            glColor4f(frand(0, 1), frand(0, 1), frand(0, 1), frand(0, 1));
            const float q = (rng() % 4) == 0 ? frand(0.3f, 3.0f) : 1.0f;
            glTexCoord4f(frand(-range, range) * q, frand(-range, range) * q, 0, q);
            glVertex3f(frand(-6, 6), frand(-6, 6), frand(-40, -1.2f));
        }
        glEnd();
        glDisable(GL_DEPTH_TEST);
        fc_capture(h);
    }
}

#define S(name) FC_CASE_RGBA(name, 64, 64, 2, "texture", sample_case),
#define SIZES(base) S(base "_nearest_repeat") S(base "_nearest_edge") S(base "_linear_repeat") \
    S(base "_linear_edge") S(base "_minlin_magnear_repeat") S(base "_minnear_maglin_edge")
#define M(name) FC_CASE_RGBA(name, 64, 64, 3, "texture", mip_case),
#define FILTERS(base) M(base "_nn") M(base "_ln") M(base "_nl") M(base "_ll") \
    M(base "_ll_magnear") M(base "_nn_maglin")

const fc_case fc_cases_tex_sample[] = {
    SIZES("texture/sample_2d_pot_mag")
    SIZES("texture/sample_2d_npot_mag")
    SIZES("texture/sample_2d_pot_min")
    SIZES("texture/sample_2d_npot_min")
    SIZES("texture/sample_2d_1x1")
    SIZES("texture/sample_1d_pot")
    SIZES("texture/sample_1d_npot")
    SIZES("texture/sample_2d_wide")
    FILTERS("texture/mip_2d_pot_repeat")
    FILTERS("texture/mip_2d_pot_edge")
    FILTERS("texture/mip_2d_npot_repeat")
    FILTERS("texture/mip_2d_npot_edge")
    FILTERS("texture/mip_1d_repeat")
    FILTERS("texture/mip_1d_npot_edge")
    FC_CASE_RGBA("texture/sample_projective", 64, 64, 2, "texture", projective),
    FC_CASE_RGBA("texture/sample_const_coord", 64, 64, 2, "texture", const_coord),
    FC_CASE_RGBA("texture/mip_base_max_level", 64, 64, 2, "texture", base_max_level),
    FC_CASE_RGBA("texture/sample_raster_state", 64, 64, 2, "texture", raster_state),
    FC_CASE_RGBA("texture/sample_mixed_wrap", 64, 64, 3, "texture", mixed_wrap),
    FC_CASE_RGBA("texture/sample_persp_large", 160, 120, 2, "texture", persp_large),
    FC_CASE_RGBA("texture/sample_arrays_lists", 64, 64, 4, "texture varray dlist", arrays_lists),
    FC_CASE_RGBA("texture/sample_extreme_coords", 64, 64, 4, "texture", extreme_coords),
    FC_CASE_RGBA("texture/sample_random_1", 96, 96, 8, "texture", random_scenes),
    FC_CASE_RGBA("texture/sample_random_2", 96, 96, 8, "texture", random_scenes),
    FC_CASE_RGBA("texture/sample_random_3", 96, 96, 8, "texture", random_scenes),
    FC_CASE_RGBA("texture/sample_random_4", 96, 96, 8, "texture", random_scenes),
    FC_CASE_RGBA("texture/sample_lines_points", 64, 64, 2, "texture", lines_points),
    FC_CASE_RGBA("texture/sample_rebind_incomplete", 48, 48, 4, "texture", rebind_incomplete),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 }
};
