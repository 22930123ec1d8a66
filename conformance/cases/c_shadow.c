/* c_shadow.c - GL 1.4 depth textures and shadow comparison (tags gl14
 * shadow; ARB_depth_texture, ARB_shadow, EXT_shadow_funcs): images of
 * GL_DEPTH_COMPONENT and GL_DEPTH_COMPONENT16/24/32 from every client
 * type (the oracle's Z16, Z24X8 and Z32 storage), read back by
 * glGetTexImage; glCopyTexImage2D / glCopyTexSubImage2D from 16- and
 * 24-bit depth buffers; GL_DEPTH_TEXTURE_MODE, GL_TEXTURE_COMPARE_MODE and
 * GL_TEXTURE_COMPARE_FUNC (all eight functions) with their queries,
 * errors, texture objects and glPushAttrib; the sampling: r against the
 * stored depth at equality, r below 0 and above 1 (clamped), NEAREST,
 * LINEAR (the filtered comparisons, PCF), mipmaps, 1D textures (t is the
 * reference), projective coordinates, wraps with a border, the result
 * expanded by the depth texture mode through every texture environment;
 * and a two-pass shadow-mapping scene (the light's depth copied into a
 * texture, projected by eye-linear texgen). */
#define GL_GLEXT_PROTOTYPES 1
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

/* client data of up to 64x64 values of any type, and read-back room */
static union {
    float f[64 * 64];
    unsigned u[64 * 64];
    unsigned short us[2 * 64 * 64];
    unsigned char ub[4 * 64 * 64];
} g_img;
static unsigned char g_out[4 * 64 * 64 * 4];

/* Fills g_img with n depth values of `type` (seeded): a smooth ramp with
 * random steps, some values outside [0, 1] for the float types. */
static void depth_values(GLenum type, int w, int hgt, unsigned seed)
{
    rng_state = seed * 7919u + 17u;
    for (int j = 0; j < hgt; j++)
        for (int i = 0; i < w; i++) {
            const int k = j * w + i;
            const float base = ((float)i + 0.5f) / (float)w * 0.6f + ((float)j + 0.5f) / (float)hgt * 0.35f;
            const float v = base + (float)((int)(rng() % 200) - 100) * 0.0015f;
            const unsigned r = rng() | (rng() << 15) | (rng() << 30);
            switch (type) {
            case GL_FLOAT: g_img.f[k] = (k % 29 == 3) ? 1.25f : (k % 31 == 5) ? -0.25f : v; break;
            case GL_UNSIGNED_INT: case GL_INT: g_img.u[k] = (unsigned)(v * 4294967040.0f) ^ (r & 0xfffu); break;
            case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_HALF_FLOAT:
                g_img.us[k] = type == GL_HALF_FLOAT ? (unsigned short)(0x3000u + (r & 0x0bffu))
                                                     : (unsigned short)((unsigned)(v * 65535.0f) ^ (r & 15u));
                break;
            default: g_img.ub[k] = (unsigned char)((unsigned)(v * 255.0f) ^ (r & 3u)); break;
            }
        }
}

static void depth_image(GLenum target, int level, GLenum internal, GLenum type, int w, int hgt,
                        unsigned seed)
{
    depth_values(type, w, hgt, seed);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (target == GL_TEXTURE_1D)
        glTexImage1D(target, level, (GLint)internal, w, 0, GL_DEPTH_COMPONENT, type, g_img.ub);
    else
        glTexImage2D(target, level, (GLint)internal, w, hgt, 0, GL_DEPTH_COMPONENT, type, g_img.ub);
}

/* ---- the sampling cases ---- */

struct sp {
    const char *name;
    GLenum internal, type;
    GLenum min, mag;
    GLenum cmp_mode, func, depth_mode;
    GLenum wrap;
    int w, hgt;
    int dims;            /* 1 or 2 */
    int mip;             /* a chain of levels */
    int scene;           /* 0 the slab, 1 projective q, 2 env modes, 3 a colour texture */
};

#define CMP GL_COMPARE_R_TO_TEXTURE
#define D24 GL_DEPTH_COMPONENT24
#define D16 GL_DEPTH_COMPONENT16
#define D32 GL_DEPTH_COMPONENT32
#define DU GL_DEPTH_COMPONENT
#define N GL_NEAREST
#define L GL_LINEAR
#define E GL_CLAMP_TO_EDGE

static const struct sp g_params[] = {
    { "shadow/nearest_lequal_z24", D24, GL_FLOAT, N, N, CMP, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/nearest_gequal_z24", D24, GL_FLOAT, N, N, CMP, GL_GEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/nearest_less_z24", D24, GL_FLOAT, N, N, CMP, GL_LESS, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/nearest_greater_z24", D24, GL_FLOAT, N, N, CMP, GL_GREATER, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/nearest_equal_z24", D24, GL_FLOAT, N, N, CMP, GL_EQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/nearest_notequal_z24", D24, GL_FLOAT, N, N, CMP, GL_NOTEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/nearest_always_z24", D24, GL_FLOAT, N, N, CMP, GL_ALWAYS, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/nearest_never_z24", D24, GL_FLOAT, N, N, CMP, GL_NEVER, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/linear_lequal_z24", D24, GL_FLOAT, L, L, CMP, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/linear_gequal_z16", D16, GL_UNSIGNED_SHORT, L, L, CMP, GL_GEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/linear_less_z32", D32, GL_UNSIGNED_INT, L, L, CMP, GL_LESS, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/linear_notequal_z24", D24, GL_FLOAT, L, L, CMP, GL_NOTEQUAL, GL_INTENSITY, E, 8, 8, 2, 0, 0 },
    { "shadow/linear_greater_npot", D24, GL_FLOAT, L, L, CMP, GL_GREATER, GL_LUMINANCE, GL_REPEAT, 7, 5, 2, 0, 0 },
    { "shadow/nearest_lequal_z16", D16, GL_UNSIGNED_SHORT, N, N, CMP, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/nearest_lequal_z32", D32, GL_UNSIGNED_INT, N, N, CMP, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/unsized_float", DU, GL_FLOAT, L, L, CMP, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/unsized_ushort", DU, GL_UNSIGNED_SHORT, L, L, CMP, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/unsized_uint", DU, GL_UNSIGNED_INT, L, L, CMP, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/unsized_ubyte", DU, GL_UNSIGNED_BYTE, N, N, CMP, GL_GEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/depth_luminance", D24, GL_FLOAT, N, N, GL_NONE, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/depth_intensity", D24, GL_FLOAT, N, N, GL_NONE, GL_LEQUAL, GL_INTENSITY, E, 8, 8, 2, 0, 0 },
    { "shadow/depth_alpha", D24, GL_FLOAT, N, N, GL_NONE, GL_LEQUAL, GL_ALPHA, E, 8, 8, 2, 0, 0 },
    { "honesty/depth_texture_mode_red", D24, GL_FLOAT, N, N, GL_NONE, GL_LEQUAL, GL_RED, E, 8, 8, 2, 0, 0 },
    { "shadow/depth_linear_z16", D16, GL_UNSIGNED_SHORT, L, L, GL_NONE, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 0 },
    { "shadow/depth_linear_z32", D32, GL_UNSIGNED_INT, L, L, GL_NONE, GL_LEQUAL, GL_INTENSITY, E, 8, 8, 2, 0, 0 },
    { "shadow/compare_alpha", D24, GL_FLOAT, L, L, CMP, GL_LEQUAL, GL_ALPHA, E, 8, 8, 2, 0, 0 },
    { "shadow/compare_intensity", D24, GL_FLOAT, N, N, CMP, GL_GEQUAL, GL_INTENSITY, E, 8, 8, 2, 0, 0 },
    { "honesty/depth_texture_mode_red_compare", D16, GL_UNSIGNED_SHORT, L, L, CMP, GL_LEQUAL, GL_RED, E, 8, 8, 2, 0, 0 },
    { "shadow/mip_nearest_nearest", D24, GL_FLOAT, GL_NEAREST_MIPMAP_NEAREST, N, CMP, GL_LEQUAL, GL_LUMINANCE, E, 16, 16, 2, 1, 0 },
    { "shadow/mip_linear_linear", D24, GL_FLOAT, GL_LINEAR_MIPMAP_LINEAR, L, CMP, GL_LEQUAL, GL_LUMINANCE, E, 16, 16, 2, 1, 0 },
    { "shadow/mip_linear_nearest_z16", D16, GL_UNSIGNED_SHORT, GL_LINEAR_MIPMAP_NEAREST, L, CMP, GL_GEQUAL, GL_LUMINANCE, E, 16, 8, 2, 1, 0 },
    { "shadow/tex1d_nearest", D24, GL_FLOAT, N, N, CMP, GL_LEQUAL, GL_LUMINANCE, E, 16, 1, 1, 0, 0 },
    { "shadow/tex1d_linear", D16, GL_UNSIGNED_SHORT, L, L, CMP, GL_GEQUAL, GL_INTENSITY, E, 16, 1, 1, 0, 0 },
    { "shadow/wrap_border_linear", D24, GL_FLOAT, L, L, CMP, GL_LEQUAL, GL_LUMINANCE, GL_CLAMP_TO_BORDER, 8, 8, 2, 0, 0 },
    { "shadow/wrap_clamp_linear", D24, GL_FLOAT, L, L, CMP, GL_GEQUAL, GL_LUMINANCE, GL_CLAMP, 8, 8, 2, 0, 0 },
    { "shadow/wrap_border_nocompare", D16, GL_UNSIGNED_SHORT, L, L, GL_NONE, GL_LEQUAL, GL_INTENSITY, GL_CLAMP_TO_BORDER, 8, 8, 2, 0, 0 },
    { "shadow/wrap_mirror_nearest", D24, GL_FLOAT, N, N, CMP, GL_LEQUAL, GL_LUMINANCE, GL_MIRRORED_REPEAT, 8, 8, 2, 0, 0 },
    { "shadow/minlin_magnear", D24, GL_FLOAT, L, N, CMP, GL_LEQUAL, GL_LUMINANCE, E, 4, 4, 2, 0, 0 },
    { "shadow/projective_q", D24, GL_FLOAT, L, L, CMP, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 1 },
    { "shadow/env_modes_luminance", D24, GL_FLOAT, L, L, CMP, GL_LEQUAL, GL_LUMINANCE, E, 8, 8, 2, 0, 2 },
    { "shadow/env_modes_intensity", D24, GL_FLOAT, L, L, CMP, GL_LEQUAL, GL_INTENSITY, E, 8, 8, 2, 0, 2 },
    { "shadow/env_modes_alpha", D24, GL_FLOAT, L, L, CMP, GL_LEQUAL, GL_ALPHA, E, 8, 8, 2, 0, 2 },
    { "honesty/depth_texture_mode_red_env", D24, GL_FLOAT, N, N, GL_NONE, GL_LEQUAL, GL_RED, E, 8, 8, 2, 0, 2 },
    { "shadow/colour_texture_compare", GL_RGBA, GL_UNSIGNED_BYTE, L, L, CMP, GL_NEVER, GL_LUMINANCE, E, 8, 8, 2, 0, 3 },
};

static const struct sp *find_params(const char *name)
{
    for (size_t i = 0; i < sizeof(g_params) / sizeof(g_params[0]); i++)
        if (strcmp(g_params[i].name, name) == 0)
            return &g_params[i];
    return NULL;
}

/* A quad over the upper part of the window, s and t from lo to hi, r
 * from r0 (left) to r1 (right) and along t, coloured per corner; then
 * four bands of constant r along the bottom (r4[b]).  For a 1D texture
 * the reference is t: t takes r's values and the bands keep s. */
static void scene_slab(fc_h *h, int dims, float lo, float hi, float r0, float r1, const float r4[4],
                       float q)
{
    const fc_case *c = fc_this_case(h);
    const float w = (float)c->width, hh = (float)c->height;
    glBegin(GL_QUADS);
    const float x[4] = { 0, w, w, 0 }, y[4] = { hh * 0.25f, hh * 0.25f, hh, hh };
    const float s[4] = { lo, hi, hi, lo }, t[4] = { lo, lo, hi, hi };
    const float r[4] = { r0, r1, r1 + 0.15f, r0 - 0.1f };
    for (int k = 0; k < 4; k++) {
        glColor4f(0.9f - 0.2f * (float)k, 0.4f + 0.15f * (float)k, 0.7f, 0.6f + 0.1f * (float)k);
        if (dims == 1)
            glTexCoord4f(s[k] * q, r[k] * q, 0.0f, q);
        else
            glTexCoord4f(s[k] * q, t[k] * q, r[k] * q, q);
        glVertex2f(x[k], y[k]);
    }
    glEnd();
    for (int b = 0; b < 4; b++) {
        const float x0 = w * 0.25f * (float)b, x1 = x0 + w * 0.25f;
        glBegin(GL_QUADS);
        glColor4f(1, 1, 1, 1);
        const float bs[4] = { 0.0f, 1.0f, 1.0f, 0.0f }, bt[4] = { 0.0f, 0.0f, 0.3f, 0.3f };
        const float bx[4] = { x0, x1, x1, x0 }, by[4] = { 0, 0, hh * 0.25f, hh * 0.25f };
        for (int k = 0; k < 4; k++) {
            if (dims == 1)
                glTexCoord3f(bs[k], r4[b], 0.0f);
            else
                glTexCoord3f(bs[k], bt[k], r4[b]);
            glVertex2f(bx[k], by[k]);
        }
        glEnd();
    }
}

static void set_params(GLenum target, const struct sp *p)
{
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)p->min);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)p->mag);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)p->wrap);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)p->wrap);
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, (GLint)p->cmp_mode);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, (GLint)p->func);
    glTexParameteri(target, GL_DEPTH_TEXTURE_MODE, (GLint)p->depth_mode);
    static const GLfloat border[4] = { 0.45f, 0.8f, 0.1f, 0.3f };
    glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, border);
}

static void sample_case(fc_h *h)
{
    const struct sp *p = find_params(fc_this_case(h)->name);
    if (!p)
        return;
    const GLenum target = p->dims == 1 ? GL_TEXTURE_1D : GL_TEXTURE_2D;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(target, tex);
    set_params(target, p);
    fc_error(h, "params");
    if (p->scene == 3) {
        for (int i = 0; i < p->w * p->hgt * 4; i++)
            g_img.ub[i] = (unsigned char)(i * 37 + 11);
        glTexImage2D(target, 0, GL_RGBA, p->w, p->hgt, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_img.ub);
    } else if (p->mip) {
        int w = p->w, hh = p->hgt;
        for (int l = 0;; l++) {
            depth_image(target, l, p->internal, p->type, w, hh, 5u + (unsigned)l * 13u);
            if (w == 1 && hh == 1)
                break;
            w = w > 1 ? w / 2 : 1;
            hh = hh > 1 ? hh / 2 : 1;
        }
    } else {
        depth_image(target, 0, p->internal, p->type, p->w, p->hgt, 5u);
    }
    fc_error(h, "image");
    glEnable(target);
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.1f, 0.3f, 0.5f, 1);
    /* the bottom bands: r at a stored value (that of texel (0, 0) as the
     * sampler reads it: read back as float), below 0, above 1, and 0.5 */
    float d0 = 0.5f;
    if (p->scene != 3) {
        float all[64 * 64];
        glGetTexImage(target, 0, GL_DEPTH_COMPONENT, GL_FLOAT, all);
        d0 = all[0];
    }
    const float r4[4] = { d0, -0.5f, 1.5f, 0.5f };
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    if (p->scene == 0 || p->scene == 3) {
        const float lo = p->wrap == E ? -0.2f : -0.6f, hi = p->wrap == E ? 1.2f : 1.6f;
        scene_slab(h, p->dims, p->mip ? -0.5f : lo, p->mip ? 3.0f : hi, -0.2f, 1.2f, r4, 1.0f);
    } else if (p->scene == 1) {
        scene_slab(h, p->dims, -0.2f, 1.2f, -0.1f, 1.1f, r4, 2.5f);
    } else {
        static const GLenum modes[4] = { GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD };
        static const GLfloat env[4] = { 0.3f, 0.9f, 0.5f, 0.25f };
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
        const fc_case *c = fc_this_case(h);
        for (int m = 0; m < 4; m++) {
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)modes[m]);
            glPushMatrix();
            glTranslatef((float)(m & 1) * (float)c->width * 0.5f, (float)(m >> 1) * (float)c->height * 0.5f, 0);
            glScalef(0.5f, 0.5f, 1);
            scene_slab(h, p->dims, -0.1f, 1.1f, -0.1f, 1.1f, r4, 1.0f);
            glPopMatrix();
        }
    }
    fc_capture(h);
    glDeleteTextures(1, &tex);
}

/* ---- equality of r and the stored depth, r outside [0, 1] ---- */

/* For each format, a uniform depth image; r exactly the value the
 * sampler reads (glGetTexImage's float is the same for Z16 and Z24 and
 * differs for Z32, both are drawn), through every function, in bands. */
static void equality_case(fc_h *h)
{
    static const GLenum internals[3] = { D16, D24, D32 };
    static const GLenum funcs[8] = { GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                     GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS };
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 1, 1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int f = 0; f < 3; f++) {
        GLuint tex;
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
        for (int i = 0; i < 16; i++)
            g_img.u[i] = 0x5a3c96e1u;
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internals[f], 4, 4, 0, GL_DEPTH_COMPONENT,
                     GL_UNSIGNED_INT, g_img.u);
        float back;
        glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, g_img.f);
        back = g_img.f[0];
        fc_blob(h, "read_back", &back, sizeof(back));
        /* the sampler's value: Z16 and Z24 (float)z * (float)(1/max) */
        const float samp16 = (float)(0x5a3cu) * (float)(1.0 / 65535.0);
        const float samp24 = (float)(0x5a3c96u) * (float)(1.0 / 16777215.0);
        const float rs[5] = { back, f == 0 ? samp16 : samp24, 0.0f, 1.0f, 0.35f };
        for (int k = 0; k < 8; k++) {
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLint)funcs[k]);
            for (int b = 0; b < 5; b++) {
                const float x0 = (float)(k * 8), y0 = (float)(f * 20 + b * 4);
                glBegin(GL_QUADS);
                glTexCoord3f(0, 0, rs[b]);
                glVertex2f(x0, y0);
                glTexCoord3f(1, 0, rs[b]);
                glVertex2f(x0 + 7, y0);
                glTexCoord3f(1, 1, rs[b]);
                glVertex2f(x0 + 7, y0 + 3);
                glTexCoord3f(0, 1, rs[b]);
                glVertex2f(x0, y0 + 3);
                glEnd();
            }
        }
        glDeleteTextures(1, &tex);
    }
    fc_capture(h);
}

/* r below 0 and above 1 against depths 0 and 1 (the clamp makes -0.5
 * equal to 0 and 1.5 equal to 1), NaN-free. */
static void range_case(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 1, 1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    const float d[4] = { 0.0f, 1.0f, 0.0f, 1.0f };
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
    static const GLenum funcs[4] = { GL_EQUAL, GL_LESS, GL_GREATER, GL_NOTEQUAL };
    const float rs[6] = { -0.5f, -1e-7f, 0.0f, 1.0f, 1.0000001f, 1.5f };
    for (int k = 0; k < 4; k++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLint)funcs[k]);
        for (int b = 0; b < 6; b++) {
            const float x0 = (float)(k * 8), y0 = (float)(b * 5);
            glBegin(GL_QUADS);
            glTexCoord3f(0, 0, rs[b]);
            glVertex2f(x0, y0);
            glTexCoord3f(1, 0, rs[b]);
            glVertex2f(x0 + 7, y0);
            glTexCoord3f(1, 1, rs[b]);
            glVertex2f(x0 + 7, y0 + 4);
            glTexCoord3f(0, 1, rs[b]);
            glVertex2f(x0, y0 + 4);
            glEnd();
        }
    }
    fc_capture(h);
    glDeleteTextures(1, &tex);
}

/* LINEAR across a depth edge: a step from 0.25 to 0.75 in the middle of
 * a 4x4 texture, magnified, r sweeping between the two, and r at each
 * side's value; the filtered comparisons give the fractions of PCF. */
static void pcf_edge_case(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 1, 1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    float d[16];
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++)
            d[j * 4 + i] = (i + j >= 3) ? 0.75f : 0.25f;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
    static const GLenum funcs[2] = { GL_LEQUAL, GL_GREATER };
    for (int k = 0; k < 2; k++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLint)funcs[k]);
        const float x0 = (float)(k * 32);
        glBegin(GL_QUADS);
        glTexCoord3f(0.1f, 0.05f, 0.2f);
        glVertex2f(x0, 0);
        glTexCoord3f(0.9f, 0.1f, 0.8f);
        glVertex2f(x0 + 32, 0);
        glTexCoord3f(0.95f, 0.9f, 0.5f);
        glVertex2f(x0 + 32, 48);
        glTexCoord3f(0.05f, 0.95f, 0.5f);
        glVertex2f(x0, 48);
        glEnd();
        /* r at each side's stored value */
        for (int b = 0; b < 2; b++) {
            const float r = b ? 0.75f : 0.25f, y0 = 48.0f + (float)b * 8.0f;
            glBegin(GL_QUADS);
            glTexCoord3f(0, 0.3f, r);
            glVertex2f(x0, y0);
            glTexCoord3f(1, 0.3f, r);
            glVertex2f(x0 + 32, y0);
            glTexCoord3f(1, 0.7f, r);
            glVertex2f(x0 + 32, y0 + 8);
            glTexCoord3f(0, 0.7f, r);
            glVertex2f(x0, y0 + 8);
            glEnd();
        }
    }
    fc_capture(h);
    glDeleteTextures(1, &tex);
}

/* ---- images: every type into every internal format, read back ---- */

static const GLenum g_internals[4] = { DU, D16, D24, D32 };
static const GLenum g_types[8] = { GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                                   GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_HALF_FLOAT };

static void read_back(fc_h *h, GLenum target, const char *label)
{
    static const GLenum out_types[6] = { GL_FLOAT, GL_UNSIGNED_INT, GL_UNSIGNED_SHORT,
                                         GL_UNSIGNED_BYTE, GL_SHORT, GL_INT };
    GLint w = 0, hh = 0;
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_HEIGHT, &hh);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int k = 0; k < 6; k++) {
        memset(g_out, 0xa5, sizeof(g_out));
        glGetTexImage(target, 0, GL_DEPTH_COMPONENT, out_types[k], g_out);
        char l[64];
        snprintf(l, sizeof(l), "%s_as_%x", label, out_types[k]);
        fc_blob(h, l, g_out, (size_t)w * (size_t)hh * 4);
    }
}

static void store_types_case(fc_h *h)
{
    for (int f = 0; f < 4; f++)
        for (int t = 0; t < 8; t++) {
            if (fc_foreign_pixel_type(g_types[t]))
                continue;   /* GL_HALF_FLOAT: not GL 1.5's (honesty cases) */
            char l[64];
            snprintf(l, sizeof(l), "f%d_t%d", f, t);
            depth_image(GL_TEXTURE_2D, 0, g_internals[f], g_types[t], 9, 7, 3u + (unsigned)t);
            fc_error(h, l);
            GLint v[3];
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v[0]);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v[1]);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v[2]);
            fc_blob(h, l, v, sizeof(v));
            read_back(h, GL_TEXTURE_2D, l);
        }
}

/* The depth transfer (scale, bias), byte swapping and row lengths on
 * the way in; the pack state and the depth transfer on the way out. */
static void transfer_case(fc_h *h)
{
    for (int f = 0; f < 4; f++) {
        char l[64];
        glPixelTransferf(GL_DEPTH_SCALE, 0.75f);
        glPixelTransferf(GL_DEPTH_BIAS, 0.125f);
        depth_image(GL_TEXTURE_2D, 0, g_internals[f], f & 1 ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT, 6, 5, 9u);
        glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
        glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
        snprintf(l, sizeof(l), "scale_bias_f%d", f);
        read_back(h, GL_TEXTURE_2D, l);
        glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
        depth_image(GL_TEXTURE_2D, 0, g_internals[f], f & 1 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT, 6, 5, 10u);
        depth_image(GL_TEXTURE_2D, 0, g_internals[f], GL_FLOAT, 6, 5, 10u);
        glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
        snprintf(l, sizeof(l), "swap_f%d", f);
        read_back(h, GL_TEXTURE_2D, l);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
        snprintf(l, sizeof(l), "pack_swap_f%d", f);
        read_back(h, GL_TEXTURE_2D, l);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
        glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
        glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
        snprintf(l, sizeof(l), "pack_scale_f%d", f);
        read_back(h, GL_TEXTURE_2D, l);
        glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
        glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
    }
    fc_error(h, "end");
}

/* glTexSubImage2D into each format, 1D images, a border */
static void subimage_case(fc_h *h)
{
    for (int f = 0; f < 4; f++) {
        char l[64];
        depth_image(GL_TEXTURE_2D, 0, g_internals[f], GL_FLOAT, 8, 8, 21u);
        depth_values(GL_UNSIGNED_SHORT, 3, 4, 22u);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 3, 4, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, g_img.us);
        depth_values(GL_FLOAT, 5, 2, 23u);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 0, 5, 2, GL_DEPTH_COMPONENT, GL_FLOAT, g_img.f);
        snprintf(l, sizeof(l), "sub_f%d", f);
        fc_error(h, l);
        read_back(h, GL_TEXTURE_2D, l);
        depth_image(GL_TEXTURE_1D, 0, g_internals[f], GL_UNSIGNED_INT, 12, 1, 24u);
        depth_values(GL_UNSIGNED_BYTE, 4, 1, 25u);
        glTexSubImage1D(GL_TEXTURE_1D, 0, 5, 4, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, g_img.ub);
        snprintf(l, sizeof(l), "sub1d_f%d", f);
        fc_error(h, l);
        read_back(h, GL_TEXTURE_1D, l);
    }
    depth_values(GL_FLOAT, 10, 6, 26u);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 10, 6, 1, GL_DEPTH_COMPONENT, GL_FLOAT, g_img.f);
    fc_error(h, "border");
    read_back(h, GL_TEXTURE_2D, "border");
}

/* ---- parameters, queries, errors ---- */

static void get_params(fc_h *h, GLenum target, const char *label)
{
    static const GLenum pn[3] = { GL_DEPTH_TEXTURE_MODE, GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC };
    GLint iv[3];
    GLfloat fv[3];
    for (int k = 0; k < 3; k++) {
        glGetTexParameteriv(target, pn[k], &iv[k]);
        glGetTexParameterfv(target, pn[k], &fv[k]);
    }
    char l[64];
    snprintf(l, sizeof(l), "%s_iv", label);
    fc_blob(h, l, iv, sizeof(iv));
    snprintf(l, sizeof(l), "%s_fv", label);
    fc_blob(h, l, fv, sizeof(fv));
}

static void params_case(fc_h *h)
{
    get_params(h, GL_TEXTURE_2D, "default_2d");
    get_params(h, GL_TEXTURE_1D, "default_1d");
    get_params(h, GL_TEXTURE_3D, "default_3d");
    static const GLenum funcs[10] = { GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER,
                                      GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS, GL_NONE, GL_ZERO };
    for (int k = 0; k < 10; k++) {
        char l[32];
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLint)funcs[k]);
        snprintf(l, sizeof(l), "func_%d", k);
        fc_error(h, l);
        get_params(h, GL_TEXTURE_2D, l);
    }
    /* (GL_RED, ARB_texture_rg's: honesty/depth_texture_mode_red) */
    static const GLenum modes[8] = { GL_LUMINANCE, GL_INTENSITY, GL_ALPHA, GL_RGB, GL_RGBA,
                                     GL_LUMINANCE_ALPHA, GL_DEPTH_COMPONENT, GL_GREEN };
    for (int k = 0; k < 8; k++) {
        char l[32];
        glTexParameteri(GL_TEXTURE_1D, GL_DEPTH_TEXTURE_MODE, (GLint)modes[k]);
        snprintf(l, sizeof(l), "mode_%d", k);
        fc_error(h, l);
        get_params(h, GL_TEXTURE_1D, l);
    }
    static const GLenum cmodes[5] = { GL_COMPARE_R_TO_TEXTURE, GL_NONE, GL_LEQUAL, GL_ONE, 0x884D };
    for (int k = 0; k < 5; k++) {
        char l[32];
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_COMPARE_MODE, (GLint)cmodes[k]);
        snprintf(l, sizeof(l), "cmode_%d", k);
        fc_error(h, l);
        get_params(h, GL_TEXTURE_3D, l);
    }
    /* the float and vector forms */
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLfloat)GL_GREATER + 0.4f);
    fc_error(h, "f_round");
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLfloat)GL_LESS - 0.6f);
    fc_error(h, "f_round_down");
    get_params(h, GL_TEXTURE_2D, "after_f");
    const GLfloat fv = (GLfloat)GL_INTENSITY;
    glTexParameterfv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &fv);
    const GLint iv = GL_COMPARE_R_TO_TEXTURE;
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &iv);
    fc_error(h, "vectors");
    get_params(h, GL_TEXTURE_2D, "after_v");
    glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    fc_error(h, "proxy_target");
    glBegin(GL_POINTS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LESS);
    glEnd();
    fc_error(h, "in_begin");
    GLint x = -1;
    glBegin(GL_POINTS);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &x);
    glEnd();
    fc_error(h, "get_in_begin");
    fc_value(h, "get_in_begin_value", x);
}

/* The parameters belong to the texture object and to GL_TEXTURE_BIT. */
static void objects_attrib_case(fc_h *h)
{
    GLuint t[2];
    glGenTextures(2, t);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    get_params(h, GL_TEXTURE_2D, "obj1");
    glBindTexture(GL_TEXTURE_2D, t[0]);
    get_params(h, GL_TEXTURE_2D, "obj0");
    glPushAttrib(GL_TEXTURE_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_NEVER);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
    get_params(h, GL_TEXTURE_2D, "changed");
    glPopAttrib();
    get_params(h, GL_TEXTURE_2D, "popped");
    glBindTexture(GL_TEXTURE_2D, 0);
    glPushAttrib(GL_TEXTURE_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_ALWAYS);
    glPopAttrib();
    get_params(h, GL_TEXTURE_2D, "default_popped");
    /* a display list compiles the parameters and the image */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, (GLfloat)GL_NOTEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    depth_image(GL_TEXTURE_2D, 0, D16, GL_UNSIGNED_SHORT, 4, 4, 33u);
    glEndList();
    get_params(h, GL_TEXTURE_2D, "compiled");
    glBindTexture(GL_TEXTURE_2D, t[1]);
    glCallList(list);
    fc_error(h, "called");
    get_params(h, GL_TEXTURE_2D, "called");
    read_back(h, GL_TEXTURE_2D, "called");
    glDeleteLists(list, 1);
    glDeleteTextures(2, t);
}

static void level_params_case(fc_h *h)
{
    /* (GL 1.5's: the *_TYPE queries are GL 3.0's, honesty cases) */
    static const GLenum pn[] = { GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_WIDTH, GL_TEXTURE_RED_SIZE,
                                 GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE,
                                 GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_HEIGHT,
                                 GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_BORDER };
    const GLenum targets[4] = { GL_TEXTURE_2D, GL_PROXY_TEXTURE_2D, GL_TEXTURE_1D, GL_PROXY_TEXTURE_1D };
    for (int f = 0; f < 4; f++)
        for (int tg = 0; tg < 4; tg++) {
            const GLenum target = targets[tg];
            if (tg & 2)
                glTexImage1D(target, 0, (GLint)g_internals[f], 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
            else
                glTexImage2D(target, 0, (GLint)g_internals[f], 4, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
            GLint v[9];
            GLfloat fv[9];
            for (size_t k = 0; k < 9; k++) {
                glGetTexLevelParameteriv(target, 0, pn[k], &v[k]);
                glGetTexLevelParameterfv(target, 0, pn[k], &fv[k]);
            }
            char l[32];
            snprintf(l, sizeof(l), "f%d_t%d", f, tg);
            fc_blob(h, l, v, sizeof(v));
            fc_blob(h, l, fv, sizeof(fv));
            fc_error(h, l);
        }
    /* a colour texture's depth size and type */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    GLint v[2];
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v[0]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v[1]);
    fc_blob(h, "colour", v, sizeof(v));
}

static void errors_case(fc_h *h)
{
    float f[64] = { 0 };
    glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 2, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, f);
    fc_error(h, "tex3d");
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_DEPTH_COMPONENT24, 2, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, f);
    fc_error(h, "proxy3d");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_RGBA, GL_FLOAT, f);
    fc_error(h, "depth_internal_colour_format");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, f);
    fc_error(h, "colour_internal_depth_format");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 2, 2, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT_5_6_5, f);
    fc_error(h, "packed_type");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 2, 2, 0, GL_DEPTH_COMPONENT, GL_BITMAP, f);
    fc_error(h, "bitmap_type");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, f);
    fc_error(h, "good");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, f);
    fc_error(h, "sub_colour_format");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, f);
    fc_error(h, "sub_luminance");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, f);
    fc_error(h, "get_rgba");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_FLOAT, f);
    fc_error(h, "get_luminance");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, f);
    fc_error(h, "get_stencil");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT_5_6_5, f);
    fc_error(h, "get_packed");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_BYTE, f);
    fc_error(h, "get_byte");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_FLOAT, f);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, f);
    fc_error(h, "get_depth_of_colour");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, f);
    fc_error(h, "sub_depth_into_colour");
}

/* no depth buffer: glCopyTexImage of a depth format has no source */
static void copy_no_depth_case(fc_h *h)
{
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 4, 4, 0);
    fc_error(h, "copy2d");
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT24, 0, 0, 4, 0);
    fc_error(h, "copy1d");
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
    fc_error(h, "copy_colour");
    float f[16] = { 0 };
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, f);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2);
    fc_error(h, "copy_sub");
}

/* ---- copies from the depth buffer ---- */

/* A scene with depth: overlapping tilted triangles (depth test on). */
static void depth_scene(fc_h *h, int variant)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    fcu_clear(0.2f, 0.2f, 0.2f, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    for (int k = 0; k < 6; k++) {
        const float a = (float)(k + variant) * 0.9f;
        fcu_color(k);
        glVertex3f(-0.9f + 0.1f * (float)k, -0.8f, -0.9f + 0.3f * (float)k);
        glVertex3f(0.9f, -0.5f + 0.2f * (float)k, 0.8f - 0.25f * a);
        glVertex3f(-0.3f + 0.1f * a, 0.95f, 0.1f * (float)k - 0.2f);
    }
    glEnd();
    glDisable(GL_DEPTH_TEST);
}

/* Draws the texture on unit 0 over the window, comparing r = 0.5 (mode
 * per `cmp`), then captures. */
static void show_texture(fc_h *h, bool cmp)
{
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, cmp ? GL_COMPARE_R_TO_TEXTURE : GL_NONE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    fc_pixel_ortho(h);
    const fc_case *c = fc_this_case(h);
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, 0.3f);
    glVertex2f(0, 0);
    glTexCoord3f(1, 0, 0.7f);
    glVertex2f((float)c->width, 0);
    glTexCoord3f(1, 1, 0.6f);
    glVertex2f((float)c->width, (float)c->height);
    glTexCoord3f(0, 1, 0.4f);
    glVertex2f(0, (float)c->height);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    fc_capture(h);
}

static void copy_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    for (int f = 0; f < 4; f++) {
        depth_scene(h, f);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, g_internals[f], 0, 0, 32, 32, 0);
        char l[32];
        snprintf(l, sizeof(l), "copy_f%d", f);
        fc_error(h, l);
        read_back(h, GL_TEXTURE_2D, l);
        /* a sub-rectangle partly outside the buffer, after another scene */
        depth_scene(h, f + 5);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 6, 20, -3, 16, 12);
        snprintf(l, sizeof(l), "sub_f%d", f);
        fc_error(h, l);
        read_back(h, GL_TEXTURE_2D, l);
        if (f == 2 || f == 1)
            show_texture(h, f == 2);
    }
    /* 1D, and a border */
    depth_scene(h, 9);
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT, 3, 7, 20, 0);
    fc_error(h, "copy1d");
    read_back(h, GL_TEXTURE_1D, "copy1d");
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 2, 2, 10, 8, 1);
    fc_error(h, "border");
    read_back(h, GL_TEXTURE_2D, "border");
    glDeleteTextures(1, &tex);
}

/* ---- two-pass shadow mapping ---- */

static void box(float x, float y, float z, float s)
{
    static const float n[6][3] = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 } };
    static const float v[6][4][3] = {
        { { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } },
        { { -1, -1, -1 }, { -1, 1, -1 }, { 1, 1, -1 }, { 1, -1, -1 } },
        { { 1, -1, -1 }, { 1, 1, -1 }, { 1, 1, 1 }, { 1, -1, 1 } },
        { { -1, -1, -1 }, { -1, -1, 1 }, { -1, 1, 1 }, { -1, 1, -1 } },
        { { -1, 1, -1 }, { -1, 1, 1 }, { 1, 1, 1 }, { 1, 1, -1 } },
        { { -1, -1, -1 }, { 1, -1, -1 }, { 1, -1, 1 }, { -1, -1, 1 } },
    };
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; f++) {
        glNormal3fv(n[f]);
        for (int k = 0; k < 4; k++)
            glVertex3f(x + s * v[f][k][0], y + s * v[f][k][1], z + s * v[f][k][2]);
    }
    glEnd();
}

static void shadow_geometry(void)
{
    glBegin(GL_QUADS);   /* the floor */
    glNormal3f(0, 1, 0);
    glVertex3f(-3, 0, -3);
    glVertex3f(-3, 0, 3);
    glVertex3f(3, 0, 3);
    glVertex3f(3, 0, -3);
    glEnd();
    box(-0.6f, 0.7f, 0.2f, 0.5f);
    box(0.9f, 0.4f, -0.7f, 0.4f);
}

static void shadow_map_case(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    const int sm = 32;   /* the map: the lower-left 32x32 of the buffer */
    const bool linear = strstr(c->name, "pcf") != NULL;
    /* pass 1: depth from the light */
    glViewport(0, 0, sm, sm);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 2, 12);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(50, 1, 0, 0);
    glRotatef(-25, 0, 1, 0);
    glTranslatef(-1.5f, -5.0f, -3.0f);
    GLfloat light_proj[16], light_view[16];
    glGetFloatv(GL_PROJECTION_MATRIX, light_proj);
    glGetFloatv(GL_MODELVIEW_MATRIX, light_view);
    fcu_clear(0, 0, 0, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 4.0f);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    shadow_geometry();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, sm, sm, 0);
    fc_error(h, "copy");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    /* pass 2: the camera's view, lit, the map projected by eye-linear
     * texgen: planes = bias * light projection * light view; the eye
     * planes are given under the camera's view matrix, whose inverse
     * they take */
    glViewport(0, 0, c->width, c->height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.5, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, -0.8f, -6.0f);
    glRotatef(30, 1, 0, 0);
    glRotatef(20, 0, 1, 0);
    fcu_clear(0.1f, 0.1f, 0.2f, 1, 1);
    /* texture matrix: bias * light_proj * light_view (applied to the eye
     * planes' object-space identity: texgen gives object coordinates) */
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.5f);
    glScalef(0.5f, 0.5f, 0.5f);
    glMultMatrixf(light_proj);
    glMultMatrixf(light_view);
    glMatrixMode(GL_MODELVIEW);
    static const GLfloat px[4] = { 1, 0, 0, 0 }, py[4] = { 0, 1, 0, 0 }, pz[4] = { 0, 0, 1, 0 },
                         pw[4] = { 0, 0, 0, 1 };
    /* eye-linear planes given under the camera matrix: the eye
     * coordinates times its inverse are the object coordinates */
    glTexGenfv(GL_S, GL_EYE_PLANE, px);
    glTexGenfv(GL_T, GL_EYE_PLANE, py);
    glTexGenfv(GL_R, GL_EYE_PLANE, pz);
    glTexGenfv(GL_Q, GL_EYE_PLANE, pw);
    static const GLenum coords[4] = { GL_S, GL_T, GL_R, GL_Q };
    for (int k = 0; k < 4; k++)
        glTexGeni(coords[k], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glEnable(GL_TEXTURE_GEN_Q);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    static const GLfloat lp[4] = { 1.5f, 5.0f, 3.0f, 1.0f };
    glLightfv(GL_LIGHT0, GL_POSITION, lp);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.9f, 0.8f, 0.6f);
    shadow_geometry();
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    fc_capture(h);
    /* the same from a display list, with GL_ALPHA mode and alpha test */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glColor4f(0.3f, 0.9f, 0.4f, 1.0f);
    shadow_geometry();
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_TEXTURE_2D);
    glEndList();
    fcu_clear(0.1f, 0.1f, 0.2f, 1, 1);
    glCallList(list);
    fc_capture(h);
    glDeleteLists(list, 1);
    glDeleteTextures(1, &tex);
}

/* Two units: a colour texture on unit 0, the shadow comparison on unit 1
 * (GL_COMBINE takes the comparison's luminance as an argument). */
static void multitexture_case(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 1, 1);
    GLuint t[2];
    glGenTextures(2, t);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    fcu_tex_level_image(GL_TEXTURE_2D, 0, 8, 8);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    depth_image(GL_TEXTURE_2D, 0, D24, GL_FLOAT, 8, 8, 41u);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_TEXTURE);
    static const GLfloat env[4] = { 0.1f, 0.1f, 0.4f, 1 };
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    glBegin(GL_QUADS);
    static const float xy[4][2] = { { 0, 0 }, { 48, 0 }, { 48, 48 }, { 0, 48 } };
    for (int k = 0; k < 4; k++) {
        glMultiTexCoord2f(GL_TEXTURE0, xy[k][0] / 24.0f, xy[k][1] / 24.0f);
        glMultiTexCoord3f(GL_TEXTURE1, xy[k][0] / 48.0f, xy[k][1] / 48.0f, 0.1f + 0.02f * xy[k][0]);
        glColor3f(1, 0.9f, 0.8f);
        glVertex2f(xy[k][0], xy[k][1]);
    }
    glEnd();
    fc_capture(h);
    glActiveTexture(GL_TEXTURE0);
    glDeleteTextures(2, t);
}

/* The texture matrix scales and offsets r (and q) before the comparison,
 * with vertex arrays. */
static void texmatrix_case(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 1, 1);
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    depth_image(GL_TEXTURE_2D, 0, D16, GL_UNSIGNED_SHORT, 8, 8, 51u);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    glEnable(GL_TEXTURE_2D);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0, 0, 0.2f);
    glScalef(1.1f, 0.9f, 0.7f);
    glRotatef(15, 0, 0, 1);
    glMatrixMode(GL_MODELVIEW);
    static const GLfloat v[] = { 2, 2, 46, 4, 44, 46, 3, 40 };
    static const GLfloat tc[] = { 0, 0, 0.1f, 1, 1, 0, 0.9f, 1, 1, 1, 0.5f, 1.3f, 0, 1, 1.2f, 0.8f };
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glTexCoordPointer(4, GL_FLOAT, 0, tc);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    fc_capture(h);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glDeleteTextures(1, &tex);
}

/* GL_GENERATE_MIPMAP on depth textures: each level read back, then
 * sampled with a mipmap filter and the comparison. */
static void genmipmap_case(fc_h *h)
{
    /* shadow/genmipmap_z32: GL_DEPTH_COMPONENT32 alone */
    const bool z32 = strstr(fc_this_case(h)->name, "z32") != NULL;
    for (int f = z32 ? 3 : 0; f < (z32 ? 4 : 3); f++) {
        GLuint tex;
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
        depth_image(GL_TEXTURE_2D, 0, g_internals[f], f == 1 ? GL_UNSIGNED_SHORT : GL_FLOAT, 16, f == 3 ? 6 : 16, 61u + (unsigned)f);
        for (int l = 1; l < 5; l++) {
            GLint w = 0, hh = 0;
            glGetTexLevelParameteriv(GL_TEXTURE_2D, l, GL_TEXTURE_WIDTH, &w);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, l, GL_TEXTURE_HEIGHT, &hh);
            memset(g_out, 0xa5, sizeof(g_out));
            glGetTexImage(GL_TEXTURE_2D, l, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, g_out);
            char lb[32];
            snprintf(lb, sizeof(lb), "f%d_l%d", f, l);
            fc_blob(h, lb, g_out, (size_t)(w * hh * 4));
        }
        if (f == 2 || f == 3) {
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
            glEnable(GL_TEXTURE_2D);
            fc_pixel_ortho(h);
            fcu_clear(0.1f, 0.2f, 0.3f, 1, 1);
            const float r4[4] = { 0.3f, 0.5f, 0.6f, 0.8f };
            scene_slab(h, 2, -0.5f, 4.0f, 0.1f, 0.9f, r4, 1.0f);
            fc_capture(h);
            glDisable(GL_TEXTURE_2D);
        }
        glDeleteTextures(1, &tex);
    }
    if (z32)
        return;
    /* 1D */
    glTexParameteri(GL_TEXTURE_1D, GL_GENERATE_MIPMAP, GL_TRUE);
    depth_image(GL_TEXTURE_1D, 0, D24, GL_FLOAT, 16, 1, 71u);
    for (int l = 1; l < 5; l++) {
        memset(g_out, 0xa5, sizeof(g_out));
        glGetTexImage(GL_TEXTURE_1D, l, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, g_out);
        char lb[32];
        snprintf(lb, sizeof(lb), "1d_l%d", l);
        fc_blob(h, lb, g_out, (size_t)(16 >> l) * 4);
    }
}

/* The depth transfer and the colour transfer around glCopyTexImage of a
 * depth format: the copy is a blit unless a colour transfer operation is
 * on (st_CopyTexSubImage's _ImageTransferState), and the depth scale and
 * bias then apply. */
static void copy_transfer_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    for (int k = 0; k < 3; k++) {
        depth_scene(h, k);
        glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
        glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
        if (k == 1)
            glPixelTransferf(GL_RED_SCALE, 0.5f);
        if (k == 2)
            glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, k == 0 ? D24 : k == 1 ? D16 : D32, 0, 0, 32, 32, 0);
        glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
        glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
        glPixelTransferf(GL_RED_SCALE, 1.0f);
        glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
        char lb[32];
        snprintf(lb, sizeof(lb), "transfer_%d", k);
        fc_error(h, lb);
        read_back(h, GL_TEXTURE_2D, lb);
    }
    show_texture(h, true);
    glDeleteTextures(1, &tex);
}

const fc_case fc_cases_shadow[] = {
#define SC(n) FC_CASE_RGBA(n, 48, 48, 1, "gl14 shadow", sample_case)
    SC("shadow/nearest_lequal_z24"),
    SC("shadow/nearest_gequal_z24"),
    SC("shadow/nearest_less_z24"),
    SC("shadow/nearest_greater_z24"),
    SC("shadow/nearest_equal_z24"),
    SC("shadow/nearest_notequal_z24"),
    SC("shadow/nearest_always_z24"),
    SC("shadow/nearest_never_z24"),
    SC("shadow/linear_lequal_z24"),
    SC("shadow/linear_gequal_z16"),
    SC("shadow/linear_less_z32"),
    SC("shadow/linear_notequal_z24"),
    SC("shadow/linear_greater_npot"),
    SC("shadow/nearest_lequal_z16"),
    SC("shadow/nearest_lequal_z32"),
    SC("shadow/unsized_float"),
    SC("shadow/unsized_ushort"),
    SC("shadow/unsized_uint"),
    SC("shadow/unsized_ubyte"),
    SC("shadow/depth_luminance"),
    SC("shadow/depth_intensity"),
    SC("shadow/depth_alpha"),
    SC("shadow/depth_linear_z16"),
    SC("shadow/depth_linear_z32"),
    SC("shadow/compare_alpha"),
    SC("shadow/compare_intensity"),
    SC("shadow/mip_nearest_nearest"),
    SC("shadow/mip_linear_linear"),
    SC("shadow/mip_linear_nearest_z16"),
    SC("shadow/tex1d_nearest"),
    SC("shadow/tex1d_linear"),
    SC("shadow/wrap_border_linear"),
    SC("shadow/wrap_clamp_linear"),
    SC("shadow/wrap_border_nocompare"),
    SC("shadow/wrap_mirror_nearest"),
    SC("shadow/minlin_magnear"),
    SC("shadow/projective_q"),
    SC("shadow/env_modes_luminance"),
    SC("shadow/env_modes_intensity"),
    SC("shadow/env_modes_alpha"),
    SC("shadow/colour_texture_compare"),
#undef SC
    /* GL_DEPTH_TEXTURE_MODE GL_RED is ARB_texture_rg's (GL 3.0), which
     * fixgl does not list: GL_INVALID_ENUM, and the texture keeps
     * GL_LUMINANCE (known-differences.txt) */
#define HC(n) FC_CASE_RGBA(n, 48, 48, 1, "honesty gl14 shadow", sample_case)
    HC("honesty/depth_texture_mode_red"),
    HC("honesty/depth_texture_mode_red_compare"),
    HC("honesty/depth_texture_mode_red_env"),
#undef HC
    FC_CASE_RGBA("shadow/equality", 64, 64, 1, "gl14 shadow", equality_case),
    FC_CASE_RGBA("shadow/r_out_of_range", 32, 32, 1, "gl14 shadow", range_case),
    FC_CASE_RGBA("shadow/pcf_edge", 64, 64, 1, "gl14 shadow", pcf_edge_case),
    FC_CASE_RGBA("shadow/multitexture_combine", 48, 48, 1, "gl14 shadow", multitexture_case),
    FC_CASE_RGBA("shadow/texture_matrix_arrays", 48, 48, 1, "gl14 shadow", texmatrix_case),
    FC_CASE_RGBA("shadow/map_two_pass", 64, 64, 2, "gl14 shadow", shadow_map_case),
    FC_CASE_RGBA("shadow/map_two_pass_pcf", 64, 64, 2, "gl14 shadow", shadow_map_case),
    FC_CASE("shadow/map_two_pass_z16", 64, 64, OSMESA_RGBA, 16, 0, 2, "gl14 shadow", shadow_map_case),
    FC_CASE_RGBA("shadow/copy_from_depth24", 32, 32, 2, "gl14 shadow", copy_case),
    FC_CASE("shadow/copy_from_depth16", 32, 32, OSMESA_RGBA, 16, 0, 2, "gl14 shadow", copy_case),
    FC_CASE("shadow/copy_from_depth32", 32, 32, OSMESA_RGBA, 32, 8, 2, "gl14 shadow", copy_case),
    FC_CASE_RGBA("shadow/genmipmap", 48, 48, 1, "gl14 shadow", genmipmap_case),
    FC_CASE_RGBA("shadow/genmipmap_z32", 48, 48, 1, "gl14 shadow", genmipmap_case),
    FC_CASE_RGBA("shadow/copy_transfer", 32, 32, 1, "gl14 shadow", copy_transfer_case),
    FC_CASE("shadow/copy_no_depth_buffer", 16, 16, OSMESA_RGBA, 0, 0, 0, "gl14 shadow", copy_no_depth_case),
    FC_CASE("shadow/store_types", 16, 16, OSMESA_RGBA, 24, 0, 0, "gl14 shadow", store_types_case),
    FC_CASE("shadow/pixel_transfer", 16, 16, OSMESA_RGBA, 24, 0, 0, "gl14 shadow", transfer_case),
    FC_CASE("shadow/subimage_1d_border", 16, 16, OSMESA_RGBA, 24, 0, 0, "gl14 shadow", subimage_case),
    FC_CASE("shadow/parameters", 16, 16, OSMESA_RGBA, 24, 0, 0, "gl14 shadow", params_case),
    FC_CASE("shadow/objects_attrib_dlist", 16, 16, OSMESA_RGBA, 24, 0, 0, "gl14 shadow", objects_attrib_case),
    FC_CASE("shadow/level_parameters", 16, 16, OSMESA_RGBA, 24, 0, 0, "gl14 shadow", level_params_case),
    FC_CASE("shadow/errors", 16, 16, OSMESA_RGBA, 24, 0, 0, "gl14 shadow", errors_case),
    { 0 },
};
