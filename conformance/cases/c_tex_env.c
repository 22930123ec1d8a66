/* c_tex_env.c - the texture environment of the fixed-function fragment
 * program (ff_fragment_shader.cpp on llvmpipe): every classic env mode
 * (REPLACE, MODULATE, DECAL, BLEND, ADD) on every base format (RGBA, RGB,
 * LUMINANCE, LUMINANCE_ALPHA, ALPHA, INTENSITY), with Mesa's derived
 * combiner state per format (texstate.c calculate_derived_texenv), on
 * unlit smooth geometry and on lit geometry with separate specular and
 * fog after texturing; then GL_COMBINE with every function, source,
 * operand and scale, texture colours and alphas spread over [0, 1]. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

static unsigned rng_state;

static unsigned rng(void)
{
    rng_state = rng_state * 1103515245u + 12345u;
    return (rng_state >> 16) & 0x7fff;
}

/* A 16x8 texture of base format `fmt` from pseudo-random bytes (the
 * client format carries the base format's components). */
static void env_texture(GLenum internal, GLenum fmt, unsigned seed)
{
    static unsigned char buf[16 * 8 * 4];
    rng_state = seed;
    for (size_t i = 0; i < sizeof buf; i++)
        buf[i] = (unsigned char)(rng() & 255);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, 16, 8, 0, fmt, GL_UNSIGNED_BYTE, buf);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
}

/* Frame: unlit smooth triangles with colours and alphas across [0, 1]. */
static void draw_unlit(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.25f, 0.5f, 0.75f, 0.5f, 1);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0.2f, 1);        glTexCoord2f(-0.1f, -0.2f); glVertex2f(1, 2);
    glColor4f(0, 1, 0.6f, 0.0f);     glTexCoord2f(1.2f, 0.1f);   glVertex2f(47, 4);
    glColor4f(0.3f, 0.2f, 1, 0.6f);  glTexCoord2f(0.4f, 1.3f);   glVertex2f(20, 46);
    glColor4f(0.9f, 0.9f, 0.1f, 0.3f); glTexCoord2f(0.9f, 1.1f); glVertex2f(47, 47);
    glColor4f(0.1f, 0.1f, 0.1f, 0.9f); glTexCoord2f(1.4f, -0.3f); glVertex2f(46, 8);
    glColor4f(0.6f, 0.0f, 0.8f, 0.45f); glTexCoord2f(0.2f, 0.8f); glVertex2f(24, 47);
    glEnd();
    fc_capture(h);
}

/* Frame: a lit sphere-ish fan (two lights, separate specular), fog. */
static void draw_lit(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 20);
    fcu_clear(0.25f, 0.5f, 0.75f, 0.5f, 1);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    const float p0[4] = { 1, 2, 3, 0 }, p1[4] = { -2, 1, 0, 1 };
    const float d1[4] = { 0.8f, 0.3f, 0.2f, 1 }, s0[4] = { 0.9f, 0.9f, 0.6f, 1 };
    glLightfv(GL_LIGHT0, GL_POSITION, p0);
    glLightfv(GL_LIGHT0, GL_SPECULAR, s0);
    glLightfv(GL_LIGHT1, GL_POSITION, p1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, d1);
    const float md[4] = { 0.7f, 0.6f, 0.9f, 0.55f }, ms[4] = { 0.6f, 0.6f, 0.6f, 1 };
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, md);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, ms);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2);
    glFogf(GL_FOG_END, 9);
    const float fc[4] = { 0.3f, 0.3f, 0.35f, 1 };
    glFogfv(GL_FOG_COLOR, fc);
    glBegin(GL_TRIANGLE_FAN);
    glNormal3f(0, 0, 1); glTexCoord2f(0.5f, 0.5f); glVertex3f(0, 0, -3);
    for (int i = 0; i <= 12; i++) {
        const float a = (float)i * 0.5235988f;
        const float x = cosf(a), y = sinf(a);
        glNormal3f(x, y, 0.4f);
        glTexCoord2f(0.5f + 0.6f * x, 0.5f + 0.6f * y);
        glVertex3f(1.6f * x, 1.6f * y, -3.5f - 2.5f * x);
    }
    glEnd();
    glDisable(GL_LIGHTING);
    glDisable(GL_FOG);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
    fc_capture(h);
}

/* ---- classic modes x base formats ---- */

struct env_param {
    const char *name;
    GLenum mode, internal, fmt;
};

static const struct env_param env_params[] = {
#define EP(n, m, i, f) { n, m, i, f },
#define FORMATS(base, m) \
    EP(base "_rgba", m, GL_RGBA, GL_RGBA) \
    EP(base "_rgb", m, GL_RGB, GL_RGB) \
    EP(base "_l", m, GL_LUMINANCE, GL_LUMINANCE) \
    EP(base "_la", m, GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA) \
    EP(base "_a", m, GL_ALPHA, GL_ALPHA) \
    EP(base "_i", m, GL_INTENSITY, GL_LUMINANCE)
    FORMATS("texture/env_replace", GL_REPLACE)
    FORMATS("texture/env_modulate", GL_MODULATE)
    FORMATS("texture/env_decal", GL_DECAL)
    FORMATS("texture/env_blend", GL_BLEND)
    FORMATS("texture/env_add", GL_ADD)
#undef FORMATS
#undef EP
};

static void env_case(fc_h *h)
{
    const char *name = fc_this_case(h)->name;
    const struct env_param *p = env_params;
    for (size_t i = 0; i < sizeof env_params / sizeof env_params[0]; i++)
        if (strcmp(env_params[i].name, name) == 0)
            p = &env_params[i];
    env_texture(p->internal, p->fmt, 5);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)p->mode);
    const float ec[4] = { 0.8f, 0.35f, 0.1f, 0.6f };
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
    draw_unlit(h);
    draw_lit(h);
}

/* ---- GL_COMBINE ---- */

/* One combiner setting: function, three sources and operands (rgb and
 * alpha), scales. */
struct comb {
    GLenum rgb, alpha;
    GLenum src_rgb[3], opr_rgb[3];
    GLenum src_a[3], opr_a[3];
    float rgb_scale, alpha_scale;
};

static void set_comb(const struct comb *k)
{
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)k->rgb);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)k->alpha);
    for (int i = 0; i < 3; i++) {
        glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + i, (GLint)k->src_rgb[i]);
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, (GLint)k->opr_rgb[i]);
        glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + i, (GLint)k->src_a[i]);
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i, (GLint)k->opr_a[i]);
    }
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, k->rgb_scale);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, k->alpha_scale);
}

#define T GL_TEXTURE
#define K GL_CONSTANT
#define P GL_PRIMARY_COLOR
#define V GL_PREVIOUS
#define C GL_SRC_COLOR
#define NC GL_ONE_MINUS_SRC_COLOR
#define A GL_SRC_ALPHA
#define NA GL_ONE_MINUS_SRC_ALPHA

/* Per function: frames with different sources, operands and scales. */
static const struct comb comb_frames[][4] = {
    /* REPLACE */
    { { GL_REPLACE, GL_REPLACE, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_REPLACE, GL_REPLACE, { K, P, K }, { NC, C, A }, { P, P, K }, { NA, A, A }, 2, 1 },
      { GL_REPLACE, GL_REPLACE, { T, P, K }, { A, C, A }, { K, P, K }, { A, A, A }, 4, 2 },
      { GL_REPLACE, GL_REPLACE, { P, P, K }, { NA, C, A }, { T, P, K }, { NA, A, A }, 1, 4 } },
    /* MODULATE */
    { { GL_MODULATE, GL_MODULATE, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_MODULATE, GL_MODULATE, { T, K, K }, { NC, A, A }, { T, K, K }, { NA, A, A }, 2, 2 },
      { GL_MODULATE, GL_MODULATE, { P, T, K }, { C, NA, A }, { P, T, K }, { A, NA, A }, 4, 1 },
      { GL_MODULATE, GL_MODULATE, { T, P, K }, { A, NC, A }, { T, V, K }, { A, A, A }, 1, 4 } },
    /* ADD */
    { { GL_ADD, GL_ADD, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_ADD, GL_ADD, { T, K, K }, { NC, C, A }, { T, K, K }, { NA, A, A }, 2, 1 },
      { GL_ADD, GL_ADD, { K, T, K }, { A, NC, A }, { P, T, K }, { A, NA, A }, 1, 2 },
      { GL_ADD, GL_ADD, { P, T, K }, { NA, C, A }, { P, T, K }, { NA, A, A }, 4, 4 } },
    /* ADD_SIGNED */
    { { GL_ADD_SIGNED, GL_ADD_SIGNED, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_ADD_SIGNED, GL_ADD_SIGNED, { T, K, K }, { NC, C, A }, { T, K, K }, { NA, A, A }, 2, 1 },
      { GL_ADD_SIGNED, GL_ADD_SIGNED, { P, T, K }, { C, NC, A }, { P, T, K }, { A, NA, A }, 1, 2 },
      { GL_ADD_SIGNED, GL_ADD_SIGNED, { K, P, K }, { A, NA, A }, { K, P, K }, { A, A, A }, 4, 4 } },
    /* INTERPOLATE */
    { { GL_INTERPOLATE, GL_INTERPOLATE, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_INTERPOLATE, GL_INTERPOLATE, { T, P, P }, { C, C, NC }, { T, P, P }, { A, A, NA }, 1, 1 },
      { GL_INTERPOLATE, GL_INTERPOLATE, { K, T, T }, { NC, C, A }, { K, T, T }, { NA, A, A }, 2, 2 },
      { GL_INTERPOLATE, GL_INTERPOLATE, { P, K, T }, { C, A, NA }, { P, K, T }, { A, A, NA }, 4, 1 } },
    /* SUBTRACT */
    { { GL_SUBTRACT, GL_SUBTRACT, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_SUBTRACT, GL_SUBTRACT, { P, T, K }, { C, C, A }, { P, T, K }, { A, A, A }, 2, 1 },
      { GL_SUBTRACT, GL_SUBTRACT, { K, T, K }, { NC, A, A }, { K, T, K }, { NA, A, A }, 1, 4 },
      { GL_SUBTRACT, GL_SUBTRACT, { T, K, K }, { NA, NC, A }, { T, K, K }, { A, NA, A }, 4, 2 } },
    /* DOT3_RGB */
    { { GL_DOT3_RGB, GL_MODULATE, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_DOT3_RGB, GL_REPLACE, { T, K, K }, { C, NC, A }, { P, K, K }, { A, A, A }, 2, 1 },
      { GL_DOT3_RGB, GL_ADD, { P, T, K }, { NC, A, A }, { P, T, K }, { A, NA, A }, 1, 4 },
      { GL_DOT3_RGB, GL_SUBTRACT, { K, P, K }, { C, C, A }, { K, T, K }, { A, A, A }, 4, 2 } },
    /* DOT3_RGBA */
    { { GL_DOT3_RGBA, GL_MODULATE, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_DOT3_RGBA, GL_REPLACE, { T, K, K }, { C, NC, A }, { P, K, K }, { A, A, A }, 2, 4 },
      { GL_DOT3_RGBA, GL_ADD, { P, T, K }, { NC, A, A }, { P, T, K }, { A, NA, A }, 1, 1 },
      { GL_DOT3_RGBA, GL_INTERPOLATE, { K, P, K }, { C, C, A }, { K, T, K }, { A, A, A }, 4, 2 } },
    /* mixed rgb / alpha functions */
    { { GL_MODULATE, GL_ADD, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_INTERPOLATE, GL_SUBTRACT, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 2, 1 },
      { GL_ADD_SIGNED, GL_REPLACE, { T, P, K }, { C, C, A }, { K, P, K }, { A, A, A }, 1, 2 },
      { GL_SUBTRACT, GL_INTERPOLATE, { T, P, K }, { C, C, A }, { T, P, T }, { A, A, NA }, 4, 4 } },
};

#define Z GL_ZERO
#define O GL_ONE
#define T0 GL_TEXTURE0
#define T1 GL_TEXTURE1

static const struct comb comb_frames2[][4] = {
    /* GL_ZERO / GL_ONE sources (ATI_texture_env_combine3): constants the
     * compiler folds */
    { { GL_ADD_SIGNED, GL_ADD_SIGNED, { O, T, K }, { C, C, A }, { T, O, K }, { A, A, A }, 1, 1 },
      { GL_ADD_SIGNED, GL_MODULATE, { T, O, K }, { NC, NC, A }, { Z, T, K }, { NA, A, A }, 2, 1 },
      { GL_INTERPOLATE, GL_INTERPOLATE, { T, Z, O }, { C, C, NC }, { O, T, Z }, { A, NA, A }, 1, 1 },
      { GL_MODULATE, GL_ADD, { O, T, K }, { NC, C, A }, { Z, T, K }, { NA, A, A }, 4, 2 } },
    /* ATI_texture_env_combine3 functions */
    { { GL_MODULATE_ADD_ATI, GL_MODULATE_ADD_ATI, { T, P, K }, { C, C, C }, { T, P, K }, { A, A, A }, 1, 1 },
      { GL_MODULATE_SIGNED_ADD_ATI, GL_MODULATE_SIGNED_ADD_ATI, { T, P, K }, { C, NC, A }, { T, P, K }, { A, NA, A }, 1, 1 },
      { GL_MODULATE_SUBTRACT_ATI, GL_MODULATE_SUBTRACT_ATI, { T, P, K }, { NC, C, C }, { T, P, K }, { NA, A, A }, 2, 2 },
      { GL_MODULATE_SIGNED_ADD_ATI, GL_MODULATE_ADD_ATI, { P, K, T }, { C, C, A }, { K, T, P }, { A, A, A }, 4, 1 } },
    /* GL_TEXTUREn sources (the crossbar): unit 0's own texture, and a unit
     * without a texture (reads 0) */
    { { GL_MODULATE, GL_MODULATE, { T0, P, K }, { C, C, A }, { T0, P, K }, { A, A, A }, 1, 1 },
      { GL_ADD, GL_REPLACE, { T1, P, K }, { C, C, A }, { T1, P, K }, { A, A, A }, 1, 1 },
      { GL_INTERPOLATE, GL_ADD, { T0, T1, P }, { C, NC, C }, { T1, P, K }, { NA, A, A }, 2, 1 },
      { GL_SUBTRACT, GL_SUBTRACT, { P, T0, K }, { C, A, A }, { T0, T1, K }, { A, NA, A }, 1, 4 } },
    /* GL_DOT3_RGB_EXT / DOT3_RGBA_EXT: scales ignored as Mesa does */
    { { GL_DOT3_RGB_EXT, GL_MODULATE, { T, P, K }, { C, C, A }, { T, P, K }, { A, A, A }, 4, 2 },
      { GL_DOT3_RGBA_EXT, GL_MODULATE, { T, K, K }, { C, NC, A }, { P, K, K }, { A, A, A }, 2, 4 },
      { GL_DOT3_RGB_EXT, GL_REPLACE, { P, T, K }, { NC, A, A }, { T, T, K }, { NA, A, A }, 1, 4 },
      { GL_DOT3_RGBA, GL_MODULATE, { T, T, K }, { C, C, A }, { T, T, K }, { A, A, A }, 4, 4 } },
    /* one source in two products of INTERPOLATE: the compiler factors
     * a*b + a*c into a*(b + c) */
    { { GL_INTERPOLATE, GL_INTERPOLATE, { T, K, K }, { C, C, C }, { T, K, K }, { A, A, A }, 1, 1 },
      { GL_INTERPOLATE, GL_INTERPOLATE, { K, K, T }, { C, C, C }, { P, P, T }, { A, A, A }, 1, 1 },
      { GL_INTERPOLATE, GL_INTERPOLATE, { T, P, T }, { NC, C, C }, { P, T, V }, { A, NA, A }, 2, 1 },
      { GL_INTERPOLATE, GL_INTERPOLATE, { V, P, T }, { C, C, NC }, { T, T, K }, { NA, NA, A }, 1, 2 } },
};

static const char *const comb_names2[] = {
    "texture/env_combine_zero_one", "texture/env_combine_ati", "texture/env_combine_crossbar",
    "texture/env_combine_dot3_ext", "texture/env_combine_factor",
};

static void combine_case2(fc_h *h)
{
    const char *name = fc_this_case(h)->name;
    size_t f = 0;
    for (size_t i = 0; i < sizeof comb_names2 / sizeof comb_names2[0]; i++)
        if (strcmp(comb_names2[i], name) == 0)
            f = i;
    env_texture(GL_RGBA, GL_RGBA, 11);
    const float ec[4] = { 0.15f, 0.85f, 0.5f, 0.65f };
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
    for (int i = 0; i < 4; i++) {
        set_comb(&comb_frames2[f][i]);
        draw_unlit(h);
    }
    draw_lit(h);
}

/* NV_texture_env_combine4: four arguments, ADD = a0*a1 + a2*a3. */
static void combine4_nv(fc_h *h)
{
    env_texture(GL_RGBA, GL_RGBA, 13);
    const float ec[4] = { 0.4f, 0.6f, 0.2f, 0.9f };
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
    static const GLenum modes[4] = { GL_ADD, GL_ADD_SIGNED, GL_ADD, GL_ADD_SIGNED };
    static const GLenum srcs[4][4] = { { T, P, K, V }, { P, K, T, O }, { T, T, P, Z }, { K, P, T, P } };
    static const GLenum oprs[4][4] = { { C, NC, A, C }, { C, C, NA, C }, { NC, A, C, C }, { A, NC, C, NA } };
    for (int f = 0; f < 4; f++) {
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE4_NV);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)modes[f]);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)modes[3 - f]);
        for (int i = 0; i < 4; i++) {
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + i, (GLint)srcs[f][i]);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, (GLint)oprs[f][i]);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + i, (GLint)srcs[3 - f][i]);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i,
                      (GLint)(oprs[f][i] == NC || oprs[f][i] == NA ? NA : A));
        }
        glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, (float)(1 << (f & 1)));
        glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, (float)(1 << (f >> 1)));
        draw_unlit(h);
    }
}

/* Texture alpha through the alpha test and blending; two-sided lighting
 * and flat shading under MODULATE. */
static void env_fragment_ops(fc_h *h)
{
    env_texture(GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, 17);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.3f);
    draw_unlit(h);
    glDisable(GL_ALPHA_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    draw_unlit(h);
    glDisable(GL_BLEND);
    glShadeModel(GL_FLAT);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    const float bd[4] = { 0.2f, 0.9f, 0.3f, 0.8f };
    glMaterialfv(GL_BACK, GL_DIFFUSE, bd);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    draw_lit(h);
}

static const char *const comb_names[] = {
    "texture/env_combine_replace", "texture/env_combine_modulate", "texture/env_combine_add",
    "texture/env_combine_add_signed", "texture/env_combine_interpolate",
    "texture/env_combine_subtract", "texture/env_combine_dot3_rgb",
    "texture/env_combine_dot3_rgba", "texture/env_combine_mixed",
};

static void combine_case(fc_h *h)
{
    const char *name = fc_this_case(h)->name;
    size_t f = 0;
    for (size_t i = 0; i < sizeof comb_names / sizeof comb_names[0]; i++)
        if (strcmp(comb_names[i], name) == 0)
            f = i;
    env_texture(GL_RGBA, GL_RGBA, 9);
    const float ec[4] = { 0.7f, 0.2f, 0.45f, 0.35f };
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
    for (int i = 0; i < 4; i++) {
        set_comb(&comb_frames[f][i]);
        draw_unlit(h);
    }
    draw_lit(h);
}

/* Random combiners: per frame random functions, sources (every source,
 * GL_ZERO/GL_ONE and GL_TEXTURE0/1 included), operands and scales for rgb
 * and alpha, on random smooth triangles over a random RGBA texture. */
static void random_combine(fc_h *h)
{
    static const GLenum fr[] = { GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE,
                                 GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA, GL_MODULATE_ADD_ATI,
                                 GL_MODULATE_SIGNED_ADD_ATI, GL_MODULATE_SUBTRACT_ATI };
    static const GLenum fa[] = { GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE,
                                 GL_SUBTRACT, GL_MODULATE_ADD_ATI, GL_MODULATE_SIGNED_ADD_ATI,
                                 GL_MODULATE_SUBTRACT_ATI };
    static const GLenum src[] = { GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS,
                                  GL_ZERO, GL_ONE, GL_TEXTURE0, GL_TEXTURE1,
                                  GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT };
    static const GLenum opr[] = { GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                  GL_ONE_MINUS_SRC_ALPHA };
    static const float scales[3] = { 1, 2, 4 };
    const fc_case *c = fc_this_case(h);
    unsigned seed = (unsigned)c->name[strlen(c->name) - 1] * 1237u;
    rng_state = seed;
    env_texture(GL_RGBA, GL_RGBA, rng());
    fc_pixel_ortho(h);
    for (int frame = 0; frame < c->frames; frame++) {
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)fr[rng() % (sizeof fr / sizeof fr[0])]);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)fa[rng() % (sizeof fa / sizeof fa[0])]);
        const bool same = (rng() % 3) == 0;   /* rgb and alpha arguments alike */
        for (int i = 0; i < 3; i++) {
            const GLenum s0 = src[rng() % (sizeof src / sizeof src[0])];
            const GLenum o0 = opr[rng() % 4];
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + i, (GLint)s0);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, (GLint)o0);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + i,
                      (GLint)(same ? s0 : src[rng() % (sizeof src / sizeof src[0])]));
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i,
                      (GLint)(same ? (o0 == GL_SRC_COLOR || o0 == GL_SRC_ALPHA ? GL_SRC_ALPHA
                                                                                : GL_ONE_MINUS_SRC_ALPHA)
                                   : opr[2 + rng() % 2]));
        }
        glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, scales[rng() % 3]);
        glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, scales[rng() % 3]);
        float ec[4];
        for (int k = 0; k < 4; k++)
            ec[k] = (float)(rng() % 1000) / 999.0f;
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
        fcu_clear(0.25f, 0.5f, 0.75f, 0.5f, 1);
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 12 * 3; i++) {
            glColor4f((float)(rng() % 256) / 255.0f, (float)(rng() % 256) / 255.0f,
                      (float)(rng() % 256) / 255.0f, (float)(rng() % 256) / 255.0f);
            glTexCoord2f((float)(rng() % 300) / 100.0f - 1.0f, (float)(rng() % 300) / 100.0f - 1.0f);
            glVertex2f((float)(rng() % 480) / 10.0f, (float)(rng() % 480) / 10.0f);
        }
        glEnd();
        fc_capture(h);
    }
}

/* An env colour outside [0, 1] (clamped when set, for the fixed-point
 * colour buffer) through BLEND and a combiner reading it. */
static void env_color_range(fc_h *h)
{
    env_texture(GL_LUMINANCE, GL_LUMINANCE, 21);
    const float ec[4] = { 1.5f, -0.5f, 0.5f, 3.0f };
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ec);
    fc_get_float(h, "env colour", GL_TEXTURE_ENV_COLOR, 4);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    draw_unlit(h);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_SUBTRACT);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_PRIMARY_COLOR);
    draw_unlit(h);
}

#define E(name) FC_CASE_RGBA(name, 48, 48, 2, "texture", env_case),
#define FORMATS(base) E(base "_rgba") E(base "_rgb") E(base "_l") E(base "_la") E(base "_a") E(base "_i")
#define CB(name) FC_CASE_RGBA(name, 48, 48, 5, "texture", combine_case),

const fc_case fc_cases_tex_env[] = {
    FORMATS("texture/env_replace")
    FORMATS("texture/env_modulate")
    FORMATS("texture/env_decal")
    FORMATS("texture/env_blend")
    FORMATS("texture/env_add")
    CB("texture/env_combine_replace")
    CB("texture/env_combine_modulate")
    CB("texture/env_combine_add")
    CB("texture/env_combine_add_signed")
    CB("texture/env_combine_interpolate")
    CB("texture/env_combine_subtract")
    CB("texture/env_combine_dot3_rgb")
    CB("texture/env_combine_dot3_rgba")
    CB("texture/env_combine_mixed")
    FC_CASE_RGBA("texture/env_combine_zero_one", 48, 48, 5, "texture", combine_case2),
    FC_CASE_RGBA("texture/env_combine_ati", 48, 48, 5, "texture", combine_case2),
    FC_CASE_RGBA("texture/env_combine_crossbar", 48, 48, 5, "texture", combine_case2),
    FC_CASE_RGBA("texture/env_combine_dot3_ext", 48, 48, 5, "texture", combine_case2),
    FC_CASE_RGBA("texture/env_combine_factor", 48, 48, 5, "texture", combine_case2),
    FC_CASE_RGBA("texture/env_combine4_nv", 48, 48, 4, "texture", combine4_nv),
    FC_CASE_RGBA("texture/env_combine_random_1", 48, 48, 12, "texture", random_combine),
    FC_CASE_RGBA("texture/env_combine_random_2", 48, 48, 12, "texture", random_combine),
    FC_CASE_RGBA("texture/env_combine_random_3", 48, 48, 12, "texture", random_combine),
    FC_CASE_RGBA("texture/env_combine_random_4", 48, 48, 12, "texture", random_combine),
    FC_CASE_RGBA("texture/env_color_range", 48, 48, 2, "texture", env_color_range),
    FC_CASE_RGBA("texture/env_fragment_ops", 48, 48, 3, "texture", env_fragment_ops),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 }
};
