/* c_tex3d.c - GL 1.2 3D textures (tags gl12 tex3d): glTexImage3D,
 * glTexSubImage3D, glCopyTexSubImage3D and GL_EXT_texture3D's names,
 * sampled through every filter and every wrap mode on r (coordinates
 * outside [0,1] and exactly on texel boundaries), power-of-two and other
 * sizes, depth 1 and 1x1x1 images, mipmaps built by hand and by
 * GL_GENERATE_MIPMAP with the three-coordinate level of detail, the
 * general LOD path, the unpack and pack image modes (GL_*_IMAGE_HEIGHT,
 * GL_*_SKIP_IMAGES), borders, proxies of sizes too large, the errors of
 * each entry point, texgen on R and the texture matrix, display lists,
 * glPushAttrib(GL_TEXTURE_BIT), the target priority of a unit (3D before
 * 2D before 1D) and the queries of the 3D state. */
#define GL_GLEXT_PROTOTYPES 1
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

/* texel bytes of up to 32x32x32 RGBA plus room for the pack cases */
static unsigned char g_buf[32 * 32 * 32 * 4 + 4096];

/* Fills g_buf with n pseudo-random bytes (seeded). */
static void noise(size_t n, unsigned seed)
{
    rng_state = seed * 7919u + 17u;
    for (size_t i = 0; i < n; i++)
        g_buf[i] = (unsigned char)(rng() & 255);
}

/* A w x h x d RGBA image of level `level`, random texels (seeded). */
static void image3d(int level, int w, int h, int d, unsigned seed)
{
    noise((size_t)w * (size_t)h * (size_t)d * 4, seed);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, level, GL_RGBA, w, h, d, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
}

/* A full chain from w x h x d down to 1x1x1, each level its own texels. */
static void chain3d(int w, int h, int d, unsigned seed)
{
    for (int l = 0;; l++) {
        image3d(l, w, h, d, seed + (unsigned)l * 31u);
        if (w == 1 && h == 1 && d == 1)
            break;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        d = d > 1 ? d / 2 : 1;
    }
}

static void params3d(GLenum min, GLenum mag, GLenum ws, GLenum wt, GLenum wr)
{
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, (GLint)min);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, (GLint)mag);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, (GLint)ws);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, (GLint)wt);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, (GLint)wr);
}

/* ---- scenes ---- */

/* A rotated quad whose corners have r0..r3 (s, t from lo to hi), then a
 * strip of four bands of constant r (rc[0..3]) along the bottom;
 * captured. */
static void scene_slab(fc_h *h, float lo, float hi, const float r4[4], const float rc[4])
{
    const fc_case *c = fc_this_case(h);
    const float w = (float)c->width, hh = (float)c->height;
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glBegin(GL_TRIANGLES);
    const float x[4] = { w * 0.08f, w * 0.93f, w * 0.81f, w * 0.03f };
    const float y[4] = { hh * 0.30f, hh * 0.22f, hh * 0.95f, hh * 0.83f };
    const float s[4] = { lo, hi, hi, lo }, t[4] = { lo, lo, hi, hi };
    static const int idx[6] = { 0, 1, 2, 0, 2, 3 };
    for (int i = 0; i < 6; i++) {
        const int k = idx[i];
        glColor4f(0.3f + 0.2f * (float)k, 0.9f - 0.2f * (float)k, 0.5f, 0.8f);
        glTexCoord3f(s[k], t[k], r4[k]);
        glVertex2f(x[k], y[k]);
    }
    glEnd();
    for (int b = 0; b < 4; b++) {
        const float x0 = w * 0.25f * (float)b, x1 = x0 + w * 0.25f;
        glBegin(GL_QUADS);
        glTexCoord3f(lo, lo, rc[b]);
        glVertex2f(x0, 0);
        glTexCoord3f(hi, lo, rc[b]);
        glVertex2f(x1, 0);
        glTexCoord3f(hi, hi * 0.25f, rc[b]);
        glVertex2f(x1, hh * 0.2f);
        glTexCoord3f(lo, hi * 0.25f, rc[b]);
        glVertex2f(x0, hh * 0.2f);
        glEnd();
    }
    fc_capture(h);
}

/* A floor receding under a frustum, r running along it as well (the
 * level of detail weighs all three derivatives), and a wall whose r
 * changes faster than s and t; captured. */
static void scene_persp(fc_h *h, float rep, float rrep, bool r_across)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 60);
    fcu_clear(0.2f, 0.1f, 0.3f, 1, 1);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    glColor4f(1, 1, 1, 1);
    /* r along the depth, or (r_across) from side to side */
    const float rn = r_across ? rrep : 0.1f, rf = r_across ? 0.0f : rrep;
    glTexCoord3f(0, 0, 0);              glVertex3f(-4, -1, -1.5f);
    glTexCoord3f(rep, 0, rn);           glVertex3f(4, -1, -1.5f);
    glTexCoord3f(rep, rep * 3, rn);     glVertex3f(4, -1, -40);
    glTexCoord3f(0, rep * 3, rf);       glVertex3f(-4, -1, -40);
    glEnd();
    glBegin(GL_TRIANGLES);
    glTexCoord3f(0.1f, 0.2f, 0.0f);            glVertex3f(-0.2f, 0.9f, -2.0f);
    glTexCoord3f(0.3f, 0.1f, rrep * 2.0f);     glVertex3f(2.5f, 0.1f, -12);
    glTexCoord3f(0.2f, 0.4f, rrep * 0.5f);     glVertex3f(-1.5f, -0.4f, -6);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    fc_capture(h);
}

/* ---- sampling cases, by parameters ---- */

struct sp {
    const char *name;
    int w, h, d;
    GLenum min, mag, wrap_s, wrap_t, wrap_r;
    int mip;            /* 0: one level; 1: a hand-built chain; 2: GL_GENERATE_MIPMAP;
                         * 3: a chain with LOD bias and MIN_LOD / MAX_LOD */
    int scene;          /* 0: slab; 1: perspective; 2: the same, r across */
    float lo, hi;       /* s, t range of the slab */
    float r4[4], rc[4]; /* r at the slab's corners, r of the four bands */
    float rrep;         /* perspective: r at the far end */
};

#define RSPAN { -1.3f, 0.4f, 2.45f, 0.9f }, { -0.6f, 0.5f, 1.0f, 1.7f }
#define RIN { 0.05f, 0.35f, 0.95f, 0.6f }, { 0.0f, 0.25f, 0.5f, 0.999f }

static const struct sp sample_params[] = {
    { "tex3d/nearest_repeat_pot", 8, 8, 8, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT,
      GL_REPEAT, 0, 0, -0.2f, 1.3f, RSPAN, 0 },
    { "tex3d/linear_repeat_pot", 8, 8, 8, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT,
      GL_REPEAT, 0, 0, -0.2f, 1.3f, RSPAN, 0 },
    { "tex3d/nearest_repeat_npot", 5, 6, 7, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT,
      GL_REPEAT, 0, 0, -0.2f, 1.3f, RSPAN, 0 },
    { "tex3d/linear_repeat_npot", 5, 6, 7, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT,
      GL_REPEAT, 0, 0, -0.2f, 1.3f, RSPAN, 0 },
    { "tex3d/linear_edge_npot", 7, 3, 5, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE,
      GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, 0, 0, -0.2f, 1.3f, RSPAN, 0 },
#define WR(n, mode)                                                                         \
    { "tex3d/wrap_r_" n "_nearest", 4, 4, 4, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT,  \
      mode, 0, 0, 0.0f, 1.0f, RSPAN, 0 },                                                  \
    { "tex3d/wrap_r_" n "_linear", 4, 4, 6, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT,     \
      mode, 0, 0, 0.0f, 1.0f, RSPAN, 0 }
    WR("repeat", GL_REPEAT),
    WR("edge", GL_CLAMP_TO_EDGE),
    WR("clamp", GL_CLAMP),
    WR("border", GL_CLAMP_TO_BORDER),
    WR("mirror", GL_MIRRORED_REPEAT),
    WR("mirror_clamp", GL_MIRROR_CLAMP_EXT),
    WR("mirror_clamp_edge", GL_MIRROR_CLAMP_TO_EDGE),
    WR("mirror_clamp_border", GL_MIRROR_CLAMP_TO_BORDER_EXT),
#undef WR
    { "tex3d/wrap_mixed_str", 4, 5, 6, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_BORDER,
      GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE, 0, 0, -0.4f, 1.4f, RSPAN, 0 },
    /* r exactly on texel boundaries and centres of a depth-4 image */
    { "tex3d/r_boundaries_nearest", 4, 4, 4, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT,
      GL_REPEAT, 0, 0, 0.0f, 1.0f, { 0.25f, 0.5f, 0.75f, 1.0f }, { 0.25f, 0.5f, 0.125f, 0.0f },
      0 },
    { "tex3d/r_boundaries_linear", 4, 4, 4, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT,
      GL_CLAMP_TO_EDGE, 0, 0, 0.0f, 1.0f, { 0.25f, 0.5f, 0.75f, 1.0f },
      { 0.125f, 0.375f, 0.5f, 0.875f }, 0 },
    /* depth 1 and 1x1x1 */
    { "tex3d/depth1_nearest", 8, 8, 1, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT,
      GL_REPEAT, 0, 0, -0.2f, 1.3f, RSPAN, 0 },
    { "tex3d/depth1_linear", 8, 8, 1, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT,
      GL_REPEAT, 0, 0, -0.2f, 1.3f, RSPAN, 0 },
    { "tex3d/depth1_mipmap", 16, 8, 1, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT,
      GL_REPEAT, GL_REPEAT, 1, 1, 0, 0, RIN, 1.0f },
    { "tex3d/size1x1x1_linear", 1, 1, 1, GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT,
      GL_CLAMP, 0, 0, -0.2f, 1.3f, RSPAN, 0 },
    { "tex3d/size1x1x1_mipmap", 1, 1, 1, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT,
      GL_REPEAT, GL_REPEAT, 1, 0, -0.2f, 1.3f, RSPAN, 0 },
    /* mipmaps: the LOD of three coordinates */
    { "tex3d/mip_nearest_nearest", 16, 16, 16, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST,
      GL_REPEAT, GL_REPEAT, GL_REPEAT, 1, 1, 0, 0, RIN, 2.0f },
    { "tex3d/mip_linear_nearest", 16, 16, 16, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT,
      GL_REPEAT, GL_REPEAT, 1, 1, 0, 0, RIN, 2.0f },
    { "tex3d/mip_nearest_linear", 16, 16, 16, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST,
      GL_REPEAT, GL_REPEAT, GL_REPEAT, 1, 1, 0, 0, RIN, 2.0f },
    { "tex3d/mip_linear_linear", 16, 16, 16, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT,
      GL_REPEAT, GL_REPEAT, 1, 1, 0, 0, RIN, 2.0f },
    { "tex3d/mip_r_dominant", 4, 4, 32, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT,
      GL_REPEAT, GL_REPEAT, 1, 1, 0, 0, RIN, 24.0f },
    { "tex3d/mip_r_across", 4, 4, 32, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT,
      GL_REPEAT, GL_CLAMP_TO_EDGE, 1, 2, 0, 0, RIN, 6.0f },
    { "tex3d/mip_r_across_bias", 8, 4, 16, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT,
      GL_REPEAT, GL_REPEAT, 3, 2, 0, 0, RIN, 3.0f },
    { "tex3d/mip_npot", 6, 10, 3, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT, GL_REPEAT,
      GL_REPEAT, 1, 1, 0, 0, RIN, 3.0f },
    { "tex3d/mip_float_path", 8, 8, 8, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT,
      GL_MIRRORED_REPEAT, GL_CLAMP, 1, 1, 0, 0, RIN, 3.0f },
    { "tex3d/mip_float_nearest", 8, 8, 8, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR,
      GL_CLAMP_TO_BORDER, GL_REPEAT, GL_MIRRORED_REPEAT, 1, 1, 0, 0, RIN, 3.0f },
    { "tex3d/minlin_magnear", 8, 8, 8, GL_LINEAR, GL_NEAREST, GL_REPEAT, GL_REPEAT,
      GL_REPEAT, 0, 1, 0, 0, RIN, 2.0f },
    { "tex3d/minnear_maglin_float", 8, 8, 8, GL_NEAREST, GL_LINEAR, GL_REPEAT, GL_REPEAT,
      GL_CLAMP_TO_BORDER, 0, 1, 0, 0, RIN, 2.0f },
    /* GL_GENERATE_MIPMAP */
    { "tex3d/genmipmap_pot", 8, 8, 8, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT,
      GL_REPEAT, GL_REPEAT, 2, 1, 0, 0, RIN, 2.0f },
    { "tex3d/genmipmap_npot", 7, 5, 6, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT,
      GL_REPEAT, GL_REPEAT, 2, 1, 0, 0, RIN, 2.0f },
    { "tex3d/genmipmap_deep", 2, 4, 16, GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST, GL_REPEAT,
      GL_REPEAT, GL_REPEAT, 2, 1, 0, 0, RIN, 8.0f },
};

static const struct sp *find_params(const char *name)
{
    for (size_t i = 0; i < sizeof(sample_params) / sizeof(sample_params[0]); i++)
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
    glBindTexture(GL_TEXTURE_3D, tex);
    params3d(p->min, p->mag, p->wrap_s, p->wrap_t, p->wrap_r);
    static const GLfloat border[4] = { 0.9f, 0.2f, 0.6f, 0.4f };
    glTexParameterfv(GL_TEXTURE_3D, GL_TEXTURE_BORDER_COLOR, border);
    if (p->mip == 1 || p->mip == 3) {
        chain3d(p->w, p->h, p->d, 11);
        if (p->mip == 3) {
            /* the general LOD path */
            glTexParameterf(GL_TEXTURE_3D, GL_TEXTURE_LOD_BIAS, 0.75f);
            glTexParameterf(GL_TEXTURE_3D, GL_TEXTURE_MIN_LOD, 0.5f);
            glTexParameterf(GL_TEXTURE_3D, GL_TEXTURE_MAX_LOD, 2.25f);
        }
    } else {
        if (p->mip == 2)
            glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
        image3d(0, p->w, p->h, p->d, 11);
    }
    fc_error(h, "image");
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    if (p->scene == 0) {
        scene_slab(h, p->lo, p->hi, p->r4, p->rc);
    } else {
        scene_persp(h, 4.0f, p->rrep, p->scene == 2);
        /* the same with the texture modulated, and the other side of the
         * floor's LOD range */
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        scene_persp(h, 1.0f, p->rrep * 0.25f, p->scene == 2);
    }
    glDeleteTextures(1, &tex);
}

/* ---- images, sub-images, copies, pixel store ---- */

static const float g_rspan[4] = { -0.1f, 0.3f, 1.1f, 0.7f };
static const float g_rbands[4] = { 0.1f, 0.4f, 0.6f, 0.9f };

/* glTexSubImage3D into the middle of each of two levels, NEAREST and
 * mipmapped, then a sub-image at the far corner (x, y, z offsets). */
static void subimage_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    params3d(GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT, GL_REPEAT);
    image3d(0, 8, 8, 8, 3);
    noise(3 * 2 * 4 * 4, 99);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 2, 3, 1, 3, 2, 4, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 7, 7, 7, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, g_buf + 5);
    fc_error(h, "sub");
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);
    glDeleteTextures(1, &tex);
}

/* Unpacking with GL_UNPACK_IMAGE_HEIGHT, SKIP_IMAGES, ROW_LENGTH,
 * SKIP_ROWS, SKIP_PIXELS and ALIGNMENT, into glTexImage3D and
 * glTexSubImage3D (RGB bytes: rows padded by the alignment). */
static void unpack_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    params3d(GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT, GL_REPEAT);
    noise(sizeof(g_buf), 5);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 9);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 2);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 4, 5, 3, 0, GL_RGB, GL_UNSIGNED_BYTE, g_buf);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 3);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 1, 2, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, g_buf + 11);
    fc_error(h, "unpack");
    fc_get_integer(h, "unpack_image_height", GL_UNPACK_IMAGE_HEIGHT, 1);
    fc_get_integer(h, "unpack_skip_images", GL_UNPACK_SKIP_IMAGES, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);
    glDeleteTextures(1, &tex);
}

/* glGetTexImage of a 3D texture (two levels, two formats) with
 * GL_PACK_IMAGE_HEIGHT, SKIP_IMAGES and the 2D modes; the whole
 * destination is compared, padding included. */
static void getteximage_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    chain3d(4, 3, 5, 21);
    static unsigned char out[4096];
    memset(out, 0xa5, sizeof(out));
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_PACK_IMAGE_HEIGHT, 4);
    glPixelStorei(GL_PACK_SKIP_IMAGES, 1);
    glPixelStorei(GL_PACK_SKIP_ROWS, 1);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 6);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGB, GL_UNSIGNED_BYTE, out);
    fc_blob(h, "level0_rgb", out, sizeof(out));
    memset(out, 0x5a, sizeof(out));
    glPixelStorei(GL_PACK_IMAGE_HEIGHT, 0);
    glPixelStorei(GL_PACK_SKIP_IMAGES, 2);
    glGetTexImage(GL_TEXTURE_3D, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
    fc_blob(h, "level1_rgba", out, sizeof(out));
    memset(out, 0x33, sizeof(out));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_SKIP_IMAGES, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glGetTexImage(GL_TEXTURE_3D, 2, GL_LUMINANCE_ALPHA, GL_FLOAT, out);
    fc_blob(h, "level2_la_float", out, sizeof(out));
    fc_get_integer(h, "pack_image_height", GL_PACK_IMAGE_HEIGHT, 1);
    fc_get_integer(h, "pack_skip_images", GL_PACK_SKIP_IMAGES, 1);
    fc_error(h, "get");
    glDeleteTextures(1, &tex);
}

/* A border of 1 on every axis (the oracle strips it: 4x4x4 inside a
 * 6x6x6 image), and one with depth 2 (nothing inside on r). */
static void border_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    params3d(GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT, GL_REPEAT);
    noise(6 * 6 * 6 * 4, 7);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 6, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "border");
    GLint v;
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &v);
    fc_value(h, "width", v);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v);
    fc_value(h, "depth", v);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_BORDER, &v);
    fc_value(h, "border", v);
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_slab(h, -0.3f, 1.2f, g_rspan, g_rbands);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "border_depth2");
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v);
    fc_value(h, "depth2", v);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_HEIGHT, &v);
    fc_value(h, "height2", v);
    glDeleteTextures(1, &tex);
}

/* glCopyTexSubImage3D from the framebuffer into two slices (one partly
 * outside the buffer), then sampled. */
static void copy_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    params3d(GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT, GL_CLAMP_TO_EDGE);
    image3d(0, 8, 8, 4, 13);
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 1, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(0, 0);
    glColor3f(0, 1, 0); glVertex2f(20, 2);
    glColor3f(0, 0, 1); glVertex2f(5, 18);
    glEnd();
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 1, 2, 3, 6, 5);
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 4, 0, 3, -2, 10, 4, 8);
    fc_error(h, "copy");
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 4, 0, 0, 2, 2);
    fc_error(h, "copy_z_out");
    glCopyTexSubImage3D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 0, 2, 2);
    fc_error(h, "copy_target");
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);
    glDeleteTextures(1, &tex);
}

/* Other internal formats on both sampling paths. */
static void formats_case(fc_h *h)
{
    static const GLenum ifmt[4] = { GL_LUMINANCE, GL_ALPHA, GL_RGB5_A1, GL_LUMINANCE8_ALPHA8 };
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    for (int i = 0; i < 4; i++) {
        params3d(GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT,
                 i & 1 ? GL_CLAMP_TO_BORDER : GL_REPEAT);
        noise(6 * 4 * 5 * 4, 40u + (unsigned)i);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage3D(GL_TEXTURE_3D, 0, (GLint)ifmt[i], 6, 4, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     g_buf);
        scene_slab(h, -0.1f, 1.1f, g_rspan, g_rbands);
    }
    fc_error(h, "formats");
    glDeleteTextures(1, &tex);
}

/* ---- coordinates ---- */

/* r from texgen (OBJECT_LINEAR and EYE_LINEAR) and through a texture
 * matrix that rotates r into s. */
static void texgen_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    params3d(GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT, GL_MIRRORED_REPEAT);
    image3d(0, 4, 8, 8, 17);
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    const GLfloat plane[4] = { 0.02f, 0.015f, 0.0f, -0.3f };
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_R, GL_OBJECT_PLANE, plane);
    glEnable(GL_TEXTURE_GEN_R);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_R, GL_EYE_PLANE, plane);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);
    glDisable(GL_TEXTURE_GEN_R);
    glMatrixMode(GL_TEXTURE);
    glRotatef(35.0f, 0.3f, 1.0f, 0.2f);
    glTranslatef(0.1f, 0.0f, 0.25f);
    glMatrixMode(GL_MODELVIEW);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    /* glTexCoord4f: r and s divided by q */
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glBegin(GL_TRIANGLES);
    glTexCoord4f(0, 0, 0, 1);          glVertex2f(2, 2);
    glTexCoord4f(2, 0, 1.5f, 2);       glVertex2f(30, 4);
    glTexCoord4f(0, 0.5f, 0.2f, 0.5f); glVertex2f(8, 30);
    glEnd();
    fc_capture(h);
    glDeleteTextures(1, &tex);
}

/* A 3D texture on unit 1 over a 2D texture on unit 0, vertex arrays with
 * three texture coordinates. */
static void multitex_case(fc_h *h)
{
    GLuint tex[2];
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    noise(8 * 8 * 4, 51);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_3D, tex[1]);
    params3d(GL_LINEAR, GL_NEAREST, GL_REPEAT, GL_CLAMP_TO_EDGE, GL_REPEAT);
    image3d(0, 4, 4, 4, 52);
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    static const GLfloat pos[8] = { 2, 2, 60, 5, 58, 60, 4, 55 };
    static const GLfloat tc0[8] = { 0, 0, 1, 0, 1, 1, 0, 1 };
    static const GLfloat tc1[12] = { 0, 0, -0.5f, 1.5f, 0, 0.3f, 1.2f, 1, 1.4f, 0, 1, 0.8f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glClientActiveTexture(GL_TEXTURE0);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, tc0);
    glClientActiveTexture(GL_TEXTURE1);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(3, GL_FLOAT, 0, tc1);
    glDrawArrays(GL_QUADS, 0, 4);
    fc_capture(h);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glActiveTexture(GL_TEXTURE0);
    glDeleteTextures(2, tex);
}

/* ---- state ---- */

/* The unit's target priority: 3D over 2D over 1D when complete; an
 * incomplete 3D texture gives the unit to 2D. */
static void priority_case(fc_h *h)
{
    GLuint tex[3];
    glGenTextures(3, tex);
    glBindTexture(GL_TEXTURE_1D, tex[0]);
    noise(8 * 4, 61);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    noise(8 * 8 * 4, 62);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_3D, tex[2]);
    image3d(0, 4, 4, 4, 63);   /* mipmap filter, one level: incomplete */
    glEnable(GL_TEXTURE_1D);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);   /* 2D */
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);   /* 3D */
    glDisable(GL_TEXTURE_3D);
    glDisable(GL_TEXTURE_2D);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);   /* 1D */
    fc_is_enabled(h, "enabled_3d", GL_TEXTURE_3D);
    glDeleteTextures(3, tex);
}

/* glPushAttrib(GL_TEXTURE_BIT) / GL_ENABLE_BIT save the 3D binding, the
 * enable and WRAP_R; the queries of the 3D state. */
static void attrib_case(fc_h *h)
{
    GLuint tex[2];
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_3D, tex[0]);
    params3d(GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT, GL_CLAMP_TO_EDGE);
    image3d(0, 4, 4, 4, 71);
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glPushAttrib(GL_TEXTURE_BIT);
    glBindTexture(GL_TEXTURE_3D, tex[1]);
    params3d(GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT, GL_MIRRORED_REPEAT);
    image3d(0, 2, 2, 2, 72);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP);
    glDisable(GL_TEXTURE_3D);
    fc_get_integer(h, "binding_inside", GL_TEXTURE_BINDING_3D, 1);
    fc_is_enabled(h, "enabled_inside", GL_TEXTURE_3D);
    glPopAttrib();
    fc_get_integer(h, "binding_after", GL_TEXTURE_BINDING_3D, 1);
    fc_is_enabled(h, "enabled_after", GL_TEXTURE_3D);
    GLint v = 0;
    glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &v);
    fc_value(h, "wrap_r_after", v);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_TEXTURE_3D);
    glPopAttrib();
    fc_is_enabled(h, "enabled_enable_bit", GL_TEXTURE_3D);
    fc_get_integer(h, "max_3d_size", GL_MAX_3D_TEXTURE_SIZE, 1);
    fc_get_boolean(h, "enabled_get", GL_TEXTURE_3D, 1);
    glBindTexture(GL_TEXTURE_3D, tex[1]);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v);
    fc_value(h, "depth_level0", v);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 1, GL_TEXTURE_DEPTH, &v);
    fc_value(h, "depth_level1", v);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH, &v);
    fc_value(h, "depth_2d", v);
    fc_error(h, "attrib");
    glDeleteTextures(2, tex);
}

/* Display lists: glTexImage3D (its image copied with the unpack modes at
 * compile time), glTexSubImage3D and glCopyTexSubImage3D compiled, a proxy
 * executed at once, errors compiled. */
static void dlist_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    params3d(GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT, GL_REPEAT);
    GLuint list = glGenLists(1);
    noise(sizeof(g_buf), 81);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 5);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
    glNewList(list, GL_COMPILE);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 3, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, g_buf);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 1, 2, 2, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, g_buf + 9);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 64, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexImage3D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 3, 0, 0, 2, 2);
    glEndList();
    fc_error(h, "compile");
    GLint v = 0;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v);
    fc_value(h, "proxy_depth_at_compile", v);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
    noise(sizeof(g_buf), 82);   /* the list keeps its own copy */
    fc_pixel_ortho(h);
    fcu_clear(0.5f, 0.5f, 0.1f, 1, 1);
    glCallList(list);
    fc_error(h, "call");
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);
    glDeleteLists(list, 1);
    glDeleteTextures(1, &tex);
}

/* GL_EXT_texture3D's names through OSMesaGetProcAddress. */
typedef void (GLAPIENTRY *teximage3d_fn)(GLenum, GLint, GLenum, GLsizei, GLsizei, GLsizei, GLint,
                                         GLenum, GLenum, const GLvoid *);
typedef void (GLAPIENTRY *texsubimage3d_fn)(GLenum, GLint, GLint, GLint, GLint, GLsizei, GLsizei,
                                            GLsizei, GLenum, GLenum, const GLvoid *);
typedef void (GLAPIENTRY *copytexsubimage3d_fn)(GLenum, GLint, GLint, GLint, GLint, GLint, GLint,
                                                GLsizei, GLsizei);

static void ext_case(fc_h *h)
{
    teximage3d_fn ti = (teximage3d_fn)OSMesaGetProcAddress("glTexImage3DEXT");
    texsubimage3d_fn tsi = (texsubimage3d_fn)OSMesaGetProcAddress("glTexSubImage3DEXT");
    copytexsubimage3d_fn ctsi = (copytexsubimage3d_fn)OSMesaGetProcAddress("glCopyTexSubImage3DEXT");
    fc_value(h, "have_ext", ti != NULL && tsi != NULL && ctsi != NULL);
    fc_value(h, "have_core", OSMesaGetProcAddress("glTexImage3D") != NULL &&
                                 OSMesaGetProcAddress("glTexSubImage3D") != NULL &&
                                 OSMesaGetProcAddress("glCopyTexSubImage3D") != NULL);
    if (!ti || !tsi || !ctsi)
        return;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    params3d(GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT, GL_REPEAT);
    noise(4 * 4 * 4 * 4, 91);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    ti(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    tsi(GL_TEXTURE_3D, 0, 1, 0, 2, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf + 64);
    fc_pixel_ortho(h);
    fcu_clear(0.3f, 0.3f, 0.3f, 1, 1);
    fcu_color(3);
    fcu_rect(0, 0, 10, 10, 0);
    ctsi(GL_TEXTURE_3D, 0, 0, 0, 3, 4, 4, 4, 4);
    fc_error(h, "ext");
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    scene_slab(h, 0.0f, 1.0f, g_rspan, g_rbands);
    glDeleteTextures(1, &tex);
}

/* ---- proxies and errors ---- */

static void proxy_query(fc_h *h, const char *label, int level)
{
    char buf[64];
    static const GLenum pn[4] = { GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH,
                                  GL_TEXTURE_INTERNAL_FORMAT };
    for (int i = 0; i < 4; i++) {
        GLint v = -7;
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, level, pn[i], &v);
        snprintf(buf, sizeof(buf), "%s_%d", label, i);
        fc_value(h, buf, v);
    }
}

/* Proxies: legal sizes, 2048 on one axis, past 2048, too large for
 * llvmpipe's 2 GiB, levels past the 3D maximum, borders. */
static void proxy_case(fc_h *h)
{
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 64, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    proxy_query(h, "legal", 0);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 2048, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    proxy_query(h, "max_w", 0);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 1, 1, 4096, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    proxy_query(h, "over_d", 0);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 1024, 1024, 1024, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, NULL);
    proxy_query(h, "huge", 0);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 512, 512, 512, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 NULL);
    proxy_query(h, "half_gib", 0);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_LUMINANCE8, 1024, 1024, 512, 0, GL_LUMINANCE,
                 GL_UNSIGNED_BYTE, NULL);
    proxy_query(h, "l8_big", 0);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 3, GL_RGBA, 256, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    proxy_query(h, "level3", 3);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 3, GL_RGBA, 257, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    proxy_query(h, "level3_over", 3);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 6, 6, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    proxy_query(h, "border", 0);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 6, 6, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    proxy_query(h, "border_d1", 0);
    fc_error(h, "proxies");
    glTexImage3D(GL_PROXY_TEXTURE_3D, 12, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "level12");
    glTexImage3D(GL_PROXY_TEXTURE_3D, 11, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "level11");
    proxy_query(h, "level11", 11);
    GLint v = -1;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 12, GL_TEXTURE_WIDTH, &v);
    fc_error(h, "query_level12");
    fc_value(h, "query_level12_v", v);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v);
    fc_value(h, "default_depth", v);
}

/* The errors of the three entry points, each after a good call. */
static void errors_case(fc_h *h)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    noise(4 * 4 * 4 * 4, 3);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "good");
    glTexImage3D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "target_2d");
    glTexImage3D(GL_TEXTURE_3D, -1, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "level_neg");
    glTexImage3D(GL_TEXTURE_3D, 12, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "level_12");
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, -1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "depth_neg");
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "border_2");
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4097, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "depth_too_big");
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1024, 1024, 1024, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 NULL);
    fc_error(h, "too_much_memory");
    glTexImage3D(GL_TEXTURE_3D, 0, 0x1234, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "internal_bad");
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, g_buf);
    fc_error(h, "format_type");
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, 0x1234, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "format_bad");
    GLint v = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v);
    fc_value(h, "depth_kept", v);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_good");
    glTexSubImage3D(GL_TEXTURE_2D, 0, 0, 0, 0, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_target");
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 3, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_z_over");
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, -1, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_z_neg");
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 2, 2, -1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_depth_neg");
    glTexSubImage3D(GL_TEXTURE_3D, 1, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_no_level");
    glTexSubImage3D(GL_TEXTURE_3D, 12, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    fc_error(h, "sub_level_12");
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "sub_empty");
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 0, 0, 4, 4);
    fc_error(h, "copy_good");
    glCopyTexSubImage3D(GL_PROXY_TEXTURE_3D, 0, 0, 0, 0, 0, 0, 4, 4);
    fc_error(h, "copy_proxy");
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 0, 0, 5, 4);
    fc_error(h, "copy_w_over");
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, -1, 0, 0, 1, 1);
    fc_error(h, "copy_z_neg");
    glCopyTexSubImage3D(GL_TEXTURE_3D, 2, 0, 0, 0, 0, 0, 1, 1);
    fc_error(h, "copy_no_level");
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 0, 0, -1, 1);
    fc_error(h, "copy_w_neg");
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_LINEAR);
    fc_error(h, "wrap_r_bad");
    glBegin(GL_TRIANGLES);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, g_buf);
    glEnd();
    fc_error(h, "in_begin");
    glDeleteTextures(1, &tex);
    fc_capture(h);
}

const fc_case fc_cases_tex3d[] = {
#define SC(n) FC_CASE_RGBA(n, 48, 48, 1, "gl12 tex3d", sample_case)
#define SP(n) FC_CASE_RGBA(n, 48, 48, 2, "gl12 tex3d", sample_case)
    SC("tex3d/nearest_repeat_pot"),
    SC("tex3d/linear_repeat_pot"),
    SC("tex3d/nearest_repeat_npot"),
    SC("tex3d/linear_repeat_npot"),
    SC("tex3d/linear_edge_npot"),
    SC("tex3d/wrap_r_repeat_nearest"),
    SC("tex3d/wrap_r_repeat_linear"),
    SC("tex3d/wrap_r_edge_nearest"),
    SC("tex3d/wrap_r_edge_linear"),
    SC("tex3d/wrap_r_clamp_nearest"),
    SC("tex3d/wrap_r_clamp_linear"),
    SC("tex3d/wrap_r_border_nearest"),
    SC("tex3d/wrap_r_border_linear"),
    SC("tex3d/wrap_r_mirror_nearest"),
    SC("tex3d/wrap_r_mirror_linear"),
    SC("tex3d/wrap_r_mirror_clamp_nearest"),
    SC("tex3d/wrap_r_mirror_clamp_linear"),
    SC("tex3d/wrap_r_mirror_clamp_edge_nearest"),
    SC("tex3d/wrap_r_mirror_clamp_edge_linear"),
    SC("tex3d/wrap_r_mirror_clamp_border_nearest"),
    SC("tex3d/wrap_r_mirror_clamp_border_linear"),
    SC("tex3d/wrap_mixed_str"),
    SC("tex3d/r_boundaries_nearest"),
    SC("tex3d/r_boundaries_linear"),
    SC("tex3d/depth1_nearest"),
    SC("tex3d/depth1_linear"),
    SP("tex3d/depth1_mipmap"),
    SC("tex3d/size1x1x1_linear"),
    SC("tex3d/size1x1x1_mipmap"),
    SP("tex3d/mip_nearest_nearest"),
    SP("tex3d/mip_linear_nearest"),
    SP("tex3d/mip_nearest_linear"),
    SP("tex3d/mip_linear_linear"),
    SP("tex3d/mip_r_dominant"),
    SP("tex3d/mip_r_across"),
    SP("tex3d/mip_r_across_bias"),
    SP("tex3d/mip_npot"),
    SP("tex3d/mip_float_path"),
    SP("tex3d/mip_float_nearest"),
    SP("tex3d/minlin_magnear"),
    SP("tex3d/minnear_maglin_float"),
    SP("tex3d/genmipmap_pot"),
    SP("tex3d/genmipmap_npot"),
    SP("tex3d/genmipmap_deep"),
#undef SC
#undef SP
    FC_CASE_RGBA("tex3d/subimage", 48, 48, 1, "gl12 tex3d", subimage_case),
    FC_CASE_RGBA("tex3d/unpack_image_modes", 48, 48, 1, "gl12 tex3d", unpack_case),
    FC_CASE_RGBA("tex3d/getteximage_pack", 16, 16, 0, "gl12 tex3d", getteximage_case),
    FC_CASE_RGBA("tex3d/border", 48, 48, 1, "gl12 tex3d", border_case),
    FC_CASE_RGBA("tex3d/copy_sub_image", 48, 48, 1, "gl12 tex3d", copy_case),
    FC_CASE_RGBA("tex3d/formats", 48, 48, 4, "gl12 tex3d", formats_case),
    FC_CASE_RGBA("tex3d/texgen_r_matrix", 32, 32, 4, "gl12 tex3d", texgen_case),
    FC_CASE_RGBA("tex3d/multitexture_arrays", 64, 64, 1, "gl12 tex3d", multitex_case),
    FC_CASE_RGBA("tex3d/target_priority", 48, 48, 3, "gl12 tex3d", priority_case),
    FC_CASE_RGBA("tex3d/attrib_queries", 48, 48, 1, "gl12 tex3d", attrib_case),
    FC_CASE_RGBA("tex3d/dlist", 48, 48, 1, "gl12 tex3d", dlist_case),
    FC_CASE_RGBA("tex3d/ext_aliases", 32, 32, 1, "gl12 tex3d", ext_case),
    FC_CASE_RGBA("tex3d/proxy", 16, 16, 0, "gl12 tex3d", proxy_case),
    FC_CASE_NODRAW("tex3d/errors", 16, 16, OSMESA_RGBA, 24, 0, 1, "gl12 tex3d", errors_case),
    { 0 },
};
