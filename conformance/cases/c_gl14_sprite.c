/* c_gl14_sprite.c - point sprites (GL_POINT_SPRITE with GL_COORD_REPLACE,
 * GL 1.4's ARB_point_sprite as the oracle rasterizes them: ORACLE-NOTES.md
 * "Point sprites"): sizes 1, 1.5, 2, 7.3 and 64 with centres on pixel
 * centres, pixel edges and the sub-pixel grid, the min/max clamps, both
 * origins, GL_COORD_REPLACE on unit 0, unit 1 or both, NEAREST, LINEAR
 * and mipmapped textures, distance attenuation, the fade threshold, point
 * smooth together with sprites, sprites partly outside the viewport and
 * the buffer, scissored, fogged (depth and fog coordinates), lit, flat,
 * blended and alpha-tested, depth-tested, through immediate mode, arrays,
 * glDrawElements, buffer objects and display lists, the varying rule of
 * texture coordinates while sprites are on (triangles too), texgen and
 * texture matrices (which the replaced coordinates ignore), glPolygonMode
 * GL_POINT, and large sprites across the 64x64 tiles of the threaded
 * rasterizer; then demo/sprite_particles: a particle system drawn as
 * textured, attenuated, fogged sprites from a buffer object, animated. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

/* An 8x8 RGBA texture whose texels are all distinct (alpha varying too),
 * bound to the active unit's GL_TEXTURE_2D with `filter`; `mip` builds
 * its levels (each level its own tint). */
/* flip: the image upside down (rows from the top), the GL 1.5 way to see
 * a sprite with t running downwards as the lower-left origin would */
static void sprite_texture_flip(GLenum min_filter, GLenum mag_filter, int mip, int flip)
{
    static GLubyte t[8 * 8 * 4];
    for (int lv = 0, n = 8; n >= 1; lv++, n /= 2) {
        for (int y = 0; y < n; y++)
            for (int x = 0; x < n; x++) {
                GLubyte *p = t + 4 * ((flip ? n - 1 - y : y) * n + x);
                p[0] = (GLubyte)(32 * x + 8 * lv + 4);
                p[1] = (GLubyte)(32 * y + 40 * lv + 2);
                p[2] = (GLubyte)(255 - 20 * x - 9 * y - 30 * lv);
                p[3] = (GLubyte)(128 + 15 * x - 6 * y);
            }
        glTexImage2D(GL_TEXTURE_2D, lv, GL_RGBA, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
        if (!mip)
            break;
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)min_filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)mag_filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glEnable(GL_TEXTURE_2D);
}

static void sprite_texture(GLenum min_filter, GLenum mag_filter, int mip)
{
    sprite_texture_flip(min_filter, mag_filter, mip, 0);
}

/* ---- sizes and placements ----
 * A row of sprites of one size per frame: centres on pixel centres
 * (where = 0), on pixel edges (1), on the 1/16 grid and anywhere (2),
 * each textured NEAREST so that the replaced coordinates show; frame 2
 * the same untextured and blended (coverage alone). */
static void size_run(fc_h *h, float size, int where)
{
    const fc_case *c = fc_this_case(h);
    fc_pixel_ortho(h);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    glPointSize(size);
    const int n = size > 20.0f ? 2 : 6;
    const float step = (float)c->width / (float)n;
    for (int f = 0; f < 2; f++) {
        if (f == 0) {
            sprite_texture(GL_NEAREST, GL_NEAREST, 0);
        } else {
            glDisable(GL_TEXTURE_2D);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE);
        }
        fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
        glBegin(GL_POINTS);
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                float x = step * ((float)i + 0.5f), y = step * ((float)j + 0.5f);
                x = floorf(x);
                y = floorf(y);
                if (where == 0) {
                    x += 0.5f;
                    y += 0.5f;
                } else if (where == 2) {
                    x += (float)((i * 5 + j * 3) % 16) / 16.0f;
                    y += (float)((i * 7 + j * 11) % 16) / 16.0f + 0.013f * (float)i;
                }
                fcu_color(i + j * n);
                glVertex2f(x, y);
            }
        glEnd();
        fc_capture(h);
    }
}

#define SIZE_CASE(fname, size, where) \
    static void fname(fc_h *h) { size_run(h, size, where); }
SIZE_CASE(size1_centre, 1.0f, 0)
SIZE_CASE(size1_edge, 1.0f, 1)
SIZE_CASE(size1_5_centre, 1.5f, 0)
SIZE_CASE(size1_5_edge, 1.5f, 1)
SIZE_CASE(size2_centre, 2.0f, 0)
SIZE_CASE(size2_edge, 2.0f, 1)
SIZE_CASE(size7_3_centre, 7.3f, 0)
SIZE_CASE(size7_3_edge, 7.3f, 1)
SIZE_CASE(size7_3_subpixel, 7.3f, 2)
SIZE_CASE(size64_centre, 64.0f, 0)
SIZE_CASE(size64_edge, 64.0f, 1)
SIZE_CASE(size_fraction_subpixel, 4.6f, 2)
SIZE_CASE(size_below_one, 0.3f, 2)

/* The sizes at the GL_POINT_SIZE_MIN / _MAX clamps (without attenuation
 * the size itself is clamped), frames: below the min, above the max, min
 * above max, fractional bounds. */
static void size_clamps(fc_h *h)
{
    static const float cfg[4][3] = { { 2, 5.5f, 9 }, { 30, 2, 7.25f }, { 6, 11.5f, 4 },
                                     { 3.3f, 3.6f, 3.7f } };
    fc_pixel_ortho(h);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    sprite_texture(GL_NEAREST, GL_NEAREST, 0);
    for (int f = 0; f < 4; f++) {
        glPointSize(cfg[f][0]);
        glPointParameterf(GL_POINT_SIZE_MIN, cfg[f][1]);
        glPointParameterf(GL_POINT_SIZE_MAX, cfg[f][2]);
        fcu_clear(0, 0, 0, 1, 1);
        glBegin(GL_POINTS);
        for (int i = 0; i < 9; i++) {
            fcu_color(i);
            glVertex2f(8.3f + 16.0f * (float)(i % 3), 8.6f + 16.0f * (float)(i / 3));
        }
        glEnd();
        fc_capture(h);
    }
}

/* ---- textured sprites ---- */
struct tex_cfg {
    GLenum min, mag;
    int mip;
    int flip;            /* the image upside down (sprite_texture_flip) */
    int units;           /* bit u: unit u textured */
    int replace;         /* bit u: GL_COORD_REPLACE on unit u */
    int persp;           /* frustum, points at several depths */
    int env;             /* 0 MODULATE, 1 REPLACE, 2 DECAL, 3 ADD */
    int lower_left;      /* honesty: GL_POINT_SPRITE_COORD_ORIGIN GL_LOWER_LEFT
                          * (GL 2.0's; GL_INVALID_ENUM in fixgl, whose
                          * sprites keep ARB_point_sprite's upper left) */
};

static void tex_scene(fc_h *h, const struct tex_cfg *cfg)
{
    const fc_case *c = fc_this_case(h);
    if (cfg->persp) {
        glViewport(0, 0, c->width, c->height);
        fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 40);
        glEnable(GL_DEPTH_TEST);
    } else {
        fc_pixel_ortho(h);
    }
    static const GLenum envs[] = { GL_MODULATE, GL_REPLACE, GL_DECAL, GL_ADD };
    for (int u = 1; u >= 0; u--) {
        glActiveTexture(GL_TEXTURE0 + (GLenum)u);
        if (cfg->units & (1 << u)) {
            sprite_texture_flip(cfg->min, cfg->mag, cfg->mip, cfg->flip);
            if (u == 1) {
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
                glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
            } else {
                glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)envs[cfg->env]);
            }
        }
        glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, (cfg->replace >> u) & 1 ? GL_TRUE : GL_FALSE);
    }
    glEnable(GL_POINT_SPRITE);
    if (cfg->lower_left)
        glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    fcu_clear(0.05f, 0.1f, 0.2f, 1, 1);
    static const float sizes[] = { 1.0f, 2.5f, 4.0f, 6.3f, 9.0f, 12.7f, 16.0f, 23.5f };
    for (int i = 0; i < 8; i++) {
        glPointSize(sizes[i]);
        glBegin(GL_POINTS);
        for (int k = 0; k < 2; k++) {
            const int n = i * 2 + k;
            glColor4f(0.3f + 0.1f * (float)(n % 7), 1.0f - 0.05f * (float)n, 0.6f, 0.9f);
            glMultiTexCoord4f(GL_TEXTURE0, 0.11f * (float)n, 0.37f, 0.0f, 1.0f);
            glMultiTexCoord2f(GL_TEXTURE1, 0.6f, 0.05f * (float)n);
            if (cfg->persp) {
                const float z = -1.5f - 2.1f * (float)n;
                glVertex3f((0.23f * (float)(n % 4) - 0.36f) * -z, (0.2f * (float)(n / 4) - 0.35f) * -z, z);
            } else {
                const float x = 6.0f + (float)(n % 4) * ((float)c->width - 12.0f) / 3.0f;
                const float y = 6.0f + (float)(n / 4) * ((float)c->height - 12.0f) / 3.0f;
                glVertex2f(x + 0.37f * (float)k, y + 0.21f * (float)i);
            }
        }
        glEnd();
    }
    fc_capture(h);
    glActiveTexture(GL_TEXTURE0);
}

#define TEX_CASE(fname, ...)                               \
    static void fname(fc_h *h)                             \
    {                                                      \
        static const struct tex_cfg cfg = __VA_ARGS__;     \
        tex_scene(h, &cfg);                                \
    }
TEX_CASE(tex_nearest, { GL_NEAREST, GL_NEAREST, 0, 0, 1, 1, 0, 0, 0 })
TEX_CASE(tex_linear, { GL_LINEAR, GL_LINEAR, 0, 0, 1, 1, 0, 0, 0 })
TEX_CASE(tex_mipmap, { GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1, 0, 1, 1, 0, 0, 0 })
TEX_CASE(tex_mipmap_nearest, { GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, 1, 0, 1, 1, 0, 1, 0 })
TEX_CASE(flipped_image, { GL_NEAREST, GL_NEAREST, 0, 1, 1, 1, 0, 1, 0 })
TEX_CASE(flipped_image_linear, { GL_LINEAR, GL_LINEAR, 0, 1, 1, 1, 0, 0, 0 })
TEX_CASE(origin_lower_left, { GL_NEAREST, GL_NEAREST, 0, 0, 1, 1, 0, 1, 1 })
TEX_CASE(origin_lower_left_linear, { GL_LINEAR, GL_LINEAR, 0, 0, 1, 1, 0, 0, 1 })
TEX_CASE(unit0_only, { GL_NEAREST, GL_NEAREST, 0, 0, 3, 1, 0, 0, 0 })
TEX_CASE(unit1_only, { GL_LINEAR, GL_NEAREST, 0, 0, 3, 2, 0, 0, 0 })
TEX_CASE(both_units, { GL_NEAREST, GL_LINEAR, 0, 1, 3, 3, 0, 3, 0 })
TEX_CASE(no_replace, { GL_NEAREST, GL_NEAREST, 0, 0, 1, 0, 1, 0, 0 })
TEX_CASE(persp_nearest, { GL_NEAREST, GL_NEAREST, 0, 0, 1, 1, 1, 0, 0 })
TEX_CASE(persp_linear_two_units, { GL_LINEAR, GL_LINEAR, 0, 0, 3, 1, 1, 2, 0 })
TEX_CASE(persp_mipmap, { GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, 1, 1, 1, 1, 1, 1, 0 })

/* ---- attenuation and fade ---- */
static void atten_scene(fc_h *h, int textured, float min, float max, int blend)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 80);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    if (textured)
        sprite_texture(GL_LINEAR, GL_LINEAR, 0);
    const GLfloat a[3] = { 1, 0.12f, 0.004f };
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
    glPointSize(30.0f);
    glPointParameterf(GL_POINT_SIZE_MIN, min);
    glPointParameterf(GL_POINT_SIZE_MAX, max);
    if (blend) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 20.0f);
    }
    for (int f = 0; f < 2; f++) {
        fcu_clear(0.1f, 0.1f, 0.15f, 1, 1);
        glBegin(GL_POINTS);
        for (int i = 0; i < 30; i++) {
            const float z = -1.2f - 1.9f * (float)i - 0.7f * (float)f;
            const float k = -z * 0.16f;
            glColor4f((float)(i % 3) / 2.0f, (float)(i % 5) / 4.0f, (float)(i % 7) / 6.0f,
                      0.5f + 0.5f * (float)(i % 2));
            glVertex3f(((float)(i % 6) - 2.5f) * k, ((float)(i / 6) - 2.0f) * k, z);
        }
        glEnd();
        fc_capture(h);
    }
}

static void atten_persp(fc_h *h) { atten_scene(h, 1, 0, 255, 0); }
static void atten_untextured(fc_h *h) { atten_scene(h, 0, 0, 255, 0); }
static void atten_clamped(fc_h *h) { atten_scene(h, 1, 4.5f, 11.25f, 0); }
static void fade_threshold(fc_h *h) { atten_scene(h, 1, 0, 255, 1); }

/* ---- with the rest of the pipeline ---- */

/* Sprites partly outside the viewport (a viewport smaller than the
 * buffer: they are cut by the buffer, not the viewport) and the buffer's
 * edges, then scissored. */
static void offscreen_scissor(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    sprite_texture(GL_NEAREST, GL_NEAREST, 0);
    for (int f = 0; f < 3; f++) {
        glViewport(f == 0 ? 0 : 10, f == 0 ? 0 : 12, f == 0 ? c->width : 40, f == 0 ? c->height : 36);
        fcu_ortho(0, 1, 0, 1, -1, 1);
        if (f == 2) {
            glEnable(GL_SCISSOR_TEST);
            glScissor(14, 9, 30, 41);
        }
        fcu_clear(0, 0.2f, 0, 1, 1);
        glPointSize(f == 0 ? 21.5f : 17.0f);
        glBegin(GL_POINTS);
        for (int i = 0; i < 12; i++) {
            fcu_color(i);
            const float t = (float)i / 11.0f;
            glVertex2f(i % 2 ? 0.003f + 0.01f * t : 0.998f - 0.02f * t, t);
            glVertex2f(t, i % 2 ? 0.001f : 0.9995f);
        }
        glEnd();
        fc_capture(h);
    }
}

/* GL_POINT_SMOOTH with sprites on draws sprites (no smoothing); frames:
 * smooth and sprites, smooth alone, sprites again after smooth, all
 * blended. */
static void smooth_with_sprites(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_POINT_SMOOTH);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    sprite_texture(GL_LINEAR, GL_LINEAR, 0);
    for (int f = 0; f < 3; f++) {
        if (f == 1)
            glDisable(GL_POINT_SPRITE);
        else
            glEnable(GL_POINT_SPRITE);
        fcu_clear(0.2f, 0.2f, 0.2f, 1, 1);
        for (int i = 0; i < 6; i++) {
            glPointSize(3.0f + 3.3f * (float)i);
            glBegin(GL_POINTS);
            glColor4f(1.0f, 0.2f * (float)i, 0.5f, 0.8f);
            glVertex2f(8.0f + 10.3f * (float)i, 10.0f + 8.7f * (float)i);
            glEnd();
        }
        fc_capture(h);
    }
}

/* Fog: by depth (perspective), then by fog coordinates from glFogCoordf
 * and from an array, EXP2 and LINEAR. */
static void fog_scene(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 40);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    sprite_texture(GL_NEAREST, GL_LINEAR, 0);
    glEnable(GL_FOG);
    const float fc[4] = { 0.6f, 0.7f, 0.8f, 1 };
    glFogfv(GL_FOG_COLOR, fc);
    glPointSize(9.5f);
    static GLfloat pos[20][3], fogc[20];
    for (int i = 0; i < 20; i++) {
        pos[i][2] = -1.5f - 1.3f * (float)i;
        pos[i][0] = (0.2f * (float)(i % 5) - 0.4f) * -pos[i][2];
        pos[i][1] = (0.2f * (float)(i / 5) - 0.3f) * -pos[i][2];
        fogc[i] = 0.9f * (float)i - 2.0f;
    }
    for (int f = 0; f < 3; f++) {
        glFogi(GL_FOG_MODE, f == 2 ? GL_EXP2 : GL_LINEAR);
        glFogf(GL_FOG_START, 1.0f);
        glFogf(GL_FOG_END, 20.0f);
        glFogf(GL_FOG_DENSITY, 0.09f);
        glFogi(GL_FOG_COORD_SRC, f == 0 ? GL_FRAGMENT_DEPTH : GL_FOG_COORD);
        fcu_clear(0, 0, 0, 1, 1);
        if (f < 2) {
            glBegin(GL_POINTS);
            for (int i = 0; i < 20; i++) {
                fcu_color(i);
                glFogCoordf(fogc[i]);
                glVertex3fv(pos[i]);
            }
            glEnd();
        } else {
            glEnableClientState(GL_VERTEX_ARRAY);
            glEnableClientState(GL_FOG_COORD_ARRAY);
            glVertexPointer(3, GL_FLOAT, 0, pos);
            glFogCoordPointer(GL_FLOAT, 0, fogc);
            glColor3f(1, 0.5f, 0.25f);
            glDrawArrays(GL_POINTS, 0, 20);
            glDisableClientState(GL_VERTEX_ARRAY);
            glDisableClientState(GL_FOG_COORD_ARRAY);
        }
        fc_capture(h);
    }
}

/* Lit sprites (colour material, two lights) and flat-shaded ones with the
 * colour sum. */
static void lit_flat(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 40);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    sprite_texture(GL_LINEAR, GL_NEAREST, 0);
    glPointSize(12.0f);
    for (int f = 0; f < 2; f++) {
        if (f == 0) {
            glEnable(GL_LIGHTING);
            glEnable(GL_LIGHT0);
            glEnable(GL_COLOR_MATERIAL);
            glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
            const float spec[4] = { 1, 1, 1, 1 };
            glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
            glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12.0f);
        } else {
            glDisable(GL_LIGHTING);
            glShadeModel(GL_FLAT);
            glEnable(GL_COLOR_SUM);
        }
        fcu_clear(0, 0, 0, 1, 1);
        glBegin(GL_POINTS);
        for (int i = 0; i < 16; i++) {
            const float z = -2.0f - 0.9f * (float)i;
            fcu_color(i);
            glSecondaryColor3f(0.1f * (float)(i % 4), 0.0f, 0.2f);
            glNormal3f(0.2f * (float)(i % 4) - 0.3f, 0.2f * (float)(i / 4) - 0.3f, 1.0f);
            glVertex3f((0.25f * (float)(i % 4) - 0.37f) * -z, (0.25f * (float)(i / 4) - 0.37f) * -z, z);
        }
        glEnd();
        fc_capture(h);
    }
}

/* Alpha test on the texture's alpha, blending, depth test with
 * overlapping sprites at several depths. */
static void alpha_depth(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    sprite_texture(GL_LINEAR, GL_LINEAR, 0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_DEPTH_TEST);
    for (int f = 0; f < 2; f++) {
        if (f == 0) {
            glEnable(GL_ALPHA_TEST);
            glAlphaFunc(GL_GREATER, 0.55f);
        } else {
            glDisable(GL_ALPHA_TEST);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE);
            glDepthMask(GL_FALSE);
        }
        fcu_clear(0, 0, 0, 1, 1);
        glPointSize(19.0f);
        glBegin(GL_POINTS);
        for (int i = 0; i < 14; i++) {
            fcu_color(i);
            glVertex3f(10.0f + 3.7f * (float)i, 12.0f + 2.9f * (float)(i % 5), 0.9f - 0.13f * (float)i);
        }
        glEnd();
        fc_capture(h);
    }
}

/* The same sprites through glDrawArrays, glDrawElements, a buffer object
 * and a display list (which compiles the sprite state too). */
static void arrays_vbo_dlist(fc_h *h)
{
    static GLfloat pos[18][2], col[18][4], tc[18][2];
    static const GLubyte idx[9] = { 17, 0, 15, 2, 13, 4, 11, 6, 9 };
    for (int i = 0; i < 18; i++) {
        pos[i][0] = 5.5f + 10.0f * (float)(i % 6) + 0.25f * (float)(i / 6);
        pos[i][1] = 8.0f + 19.0f * (float)(i / 6) + 0.5f * (float)(i % 2);
        col[i][0] = (float)(i % 3) / 2.0f;
        col[i][1] = (float)(i % 4) / 3.0f;
        col[i][2] = 1.0f - (float)i / 17.0f;
        col[i][3] = 1.0f;
        tc[i][0] = 0.3f;
        tc[i][1] = (float)i / 17.0f;
    }
    fc_pixel_ortho(h);
    sprite_texture(GL_NEAREST, GL_NEAREST, 0);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    glPointSize(8.6f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glColorPointer(4, GL_FLOAT, 0, col);
    glTexCoordPointer(2, GL_FLOAT, 0, tc);
    fcu_clear(0, 0, 0, 1, 1);
    glDrawArrays(GL_POINTS, 0, 18);
    fc_capture(h);
    fcu_clear(0, 0, 0, 1, 1);
    glDrawElements(GL_POINTS, 9, GL_UNSIGNED_BYTE, idx);
    fc_capture(h);
    GLuint buf[2];
    glGenBuffers(2, buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof pos + sizeof col, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof pos, pos);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof pos, sizeof col, col);
    glVertexPointer(2, GL_FLOAT, 0, (const void *)0);
    glColorPointer(4, GL_FLOAT, 0, (const void *)sizeof pos);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
    fcu_clear(0, 0, 0, 1, 1);
    glPointSize(5.0f);
    glDrawElements(GL_POINTS, 9, GL_UNSIGNED_BYTE, (const void *)0);
    glPointSize(2.0f);
    glDrawArrays(GL_POINTS, 0, 18);
    fc_capture(h);
    const GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glDisable(GL_POINT_SPRITE);
    glPointSize(7.0f);
    glDrawArrays(GL_POINTS, 0, 9);
    glEnable(GL_POINT_SPRITE);
    glDrawArrays(GL_POINTS, 9, 9);
    glEndList();
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    fcu_clear(0, 0, 0, 1, 1);
    glCallList(l);
    fc_capture(h);
    glDeleteLists(l, 1);
    glDeleteBuffers(2, buf);
}

/* While GL_POINT_SPRITE is on every texture coordinate is a varying of
 * the fixed-function fragment program: a coordinate set once before
 * glBegin is interpolated (not read as a constant), for triangles too;
 * frames: sprite off, sprite on without replacement, triangles and
 * lines with sprites on. */
static void varying_rule(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 40);
    sprite_texture(GL_NEAREST, GL_NEAREST, 0);
    glPointSize(6.0f);
    for (int f = 0; f < 3; f++) {
        if (f == 0)
            glDisable(GL_POINT_SPRITE);
        else
            glEnable(GL_POINT_SPRITE);
        fcu_clear(0, 0, 0, 1, 1);
        glTexCoord2f(0.4375f, 0.3125f);
        glColor3f(1, 1, 1);
        glBegin(f == 2 ? GL_TRIANGLES : GL_POINTS);
        for (int i = 0; i < 12; i++) {
            const float z = -1.1f - 2.7f * (float)i;
            glVertex3f((0.09f * (float)i - 0.45f) * -z, (0.3f * (float)(i % 3) - 0.3f) * -z, z);
        }
        glEnd();
        glBegin(GL_LINES);
        glVertex3f(-2.0f, -1.9f, -4.0f);
        glVertex3f(9.0f, 3.0f, -30.0f);
        glEnd();
        fc_capture(h);
    }
}

/* Texture coordinate generation and a texture matrix on the unit: the
 * replaced coordinates ignore both; a second unit keeps its generated
 * ones. */
static void texgen_matrix(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 40);
    for (int u = 0; u < 2; u++) {
        glActiveTexture(GL_TEXTURE0 + (GLenum)u);
        sprite_texture(u ? GL_LINEAR : GL_NEAREST, GL_NEAREST, 0);
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glRotatef(30.0f, 0, 0, 1);
        glScalef(2.0f, 0.5f, 1.0f);
        glMatrixMode(GL_MODELVIEW);
        if (u == 1)
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    }
    glActiveTexture(GL_TEXTURE0);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    glEnable(GL_POINT_SPRITE);
    glPointSize(11.0f);
    fcu_clear(0, 0, 0, 1, 1);
    glBegin(GL_POINTS);
    for (int i = 0; i < 16; i++) {
        const float z = -2.0f - 0.8f * (float)i;
        glColor3f(1, 1, 1);
        glVertex3f((0.25f * (float)(i % 4) - 0.37f) * -z, (0.25f * (float)(i / 4) - 0.37f) * -z, z);
    }
    glEnd();
    fc_capture(h);
}

/* Lines and polygons drawn while GL_POINT_SPRITE is on read the texture
 * coordinates of the units with GL_COORD_REPLACE as (0, 0, 0, 0), given
 * or generated (llvmpipe links no vertex output to them): s/q = 0/0 under
 * each wrap mode and filter; the other unit keeps its coordinates, glBitmap
 * and glDrawPixels (their own rasterizer state) theirs, and sprites their
 * replaced ones.  Frames: unit 0 replaced (NEAREST, then LINEAR, over the
 * four wraps), unit 1 replaced, both, then GL_POINT_SPRITE off
 * (ORACLE-NOTES.md "Point sprites"; probe p_sprites). */
static void replaced_on_lines_polygons(fc_h *h)
{
    static const GLenum wraps[4] = { GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER,
                                     GL_MIRRORED_REPEAT };
    static const GLfloat border[4] = { 0.9f, 0.2f, 0.6f, 0.8f };
    /* 8 rows of one byte at GL_UNPACK_ALIGNMENT 4: a row every 4 bytes */
    static const GLubyte bits[8 * 4] = { 0xf0, 0, 0, 0, 0x0f, 0, 0, 0, 0xaa, 0, 0, 0, 0x55, 0, 0, 0,
                                         0xff, 0, 0, 0, 0x81, 0, 0, 0, 0x3c, 0, 0, 0, 0x66, 0, 0, 0 };
    static GLubyte img[6 * 5 * 4];
    for (int i = 0; i < 6 * 5 * 4; i++)
        img[i] = (GLubyte)(i * 29 + 7);
    for (int u = 0; u < 2; u++) {
        glActiveTexture(GL_TEXTURE0 + (GLenum)u);
        sprite_texture(GL_NEAREST, GL_NEAREST, 0);
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, u ? GL_ADD : GL_MODULATE);
    }
    glEnable(GL_POINT_SPRITE);
    glPointSize(5.0f);
    for (int f = 0; f < 4; f++) {
        for (int u = 0; u < 2; u++) {
            glActiveTexture(GL_TEXTURE0 + (GLenum)u);
            glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, (f == 0 && u == 0) || (f == 1 && u == 1) || f >= 2);
        }
        if (f == 3)
            glDisable(GL_POINT_SPRITE);
        fc_pixel_ortho(h);
        fcu_clear(0.1f, 0.1f, 0.2f, 1, 1);
        for (int k = 0; k < 8; k++) {
            const GLenum filter = k < 4 ? GL_NEAREST : GL_LINEAR;
            for (int u = 0; u < 2; u++) {
                glActiveTexture(GL_TEXTURE0 + (GLenum)u);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filter);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)filter);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wraps[k % 4]);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wraps[(k + 1) % 4]);
            }
            const float x = 2.0f + 12.0f * (float)k;
            glBegin(GL_TRIANGLES);
            glColor3f(1.0f, 0.8f, 0.6f);
            glMultiTexCoord4f(GL_TEXTURE0, 0.1f, 0.2f, 0.0f, 1.0f);
            glMultiTexCoord2f(GL_TEXTURE1, 0.7f, 0.1f);
            glVertex2f(x, 2.0f);
            glMultiTexCoord4f(GL_TEXTURE0, 0.9f, 0.3f, 0.5f, 2.0f);
            glMultiTexCoord2f(GL_TEXTURE1, 0.2f, 0.8f);
            glVertex2f(x + 11.0f, 4.0f);
            glMultiTexCoord4f(GL_TEXTURE0, 0.4f, 0.95f, 0.0f, 0.5f);
            glMultiTexCoord2f(GL_TEXTURE1, 0.5f, 0.5f);
            glVertex2f(x + 3.0f, 24.0f);
            glEnd();
            glBegin(GL_LINES);
            glVertex2f(x, 27.5f);
            glMultiTexCoord2f(GL_TEXTURE0, 0.3f, 0.6f);
            glVertex2f(x + 11.0f, 30.5f);
            glEnd();
            glBegin(GL_POINTS);
            glVertex2f(x + 5.5f, 36.0f);
            glEnd();
        }
        /* eye-linear texgen on both units: a strip of quads */
        glActiveTexture(GL_TEXTURE0);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        for (int u = 0; u < 2; u++) {
            static const GLfloat ps[4] = { 0.031f, -0.017f, 0.0f, 0.13f };
            static const GLfloat pt[4] = { -0.023f, 0.041f, 0.0f, 0.3f };
            glActiveTexture(GL_TEXTURE0 + (GLenum)u);
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
            glTexGenfv(GL_S, GL_EYE_PLANE, ps);
            glTexGenfv(GL_T, GL_EYE_PLANE, pt);
            glEnable(GL_TEXTURE_GEN_S);
            glEnable(GL_TEXTURE_GEN_T);
        }
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= 6; i++) {
            glColor3f(0.9f, 1.0f - 0.1f * (float)i, 0.7f);
            glVertex2f(2.0f + 15.0f * (float)i, 40.0f + (float)(i % 2));
            glVertex2f(2.0f + 15.0f * (float)i, 52.0f);
        }
        glEnd();
        for (int u = 0; u < 2; u++) {
            glActiveTexture(GL_TEXTURE0 + (GLenum)u);
            glDisable(GL_TEXTURE_GEN_S);
            glDisable(GL_TEXTURE_GEN_T);
        }
        glActiveTexture(GL_TEXTURE0);
        /* pixel rectangles keep the raster position's coordinates */
        glMultiTexCoord2f(GL_TEXTURE0, 0.6f, 0.3f);
        glMultiTexCoord2f(GL_TEXTURE1, 0.2f, 0.9f);
        glRasterPos2f(4.0f, 56.0f);
        glBitmap(8, 8, 0, 0, 0, 0, bits);
        glRasterPos2f(20.0f, 56.0f);
        glDrawPixels(6, 5, GL_RGBA, GL_UNSIGNED_BYTE, img);
        fc_error(h, "frame");
        fc_capture(h);
    }
}

/* glPolygonMode GL_POINT: a polygon's vertices drawn as sprites (front
 * and back modes, culling off), with polygon offset on points. */
static void polygon_mode_points(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    sprite_texture(GL_NEAREST, GL_NEAREST, 0);
    glPolygonMode(GL_FRONT, GL_POINT);
    glPolygonMode(GL_BACK, GL_LINE);
    glEnable(GL_POLYGON_OFFSET_POINT);
    glPolygonOffset(1.0f, 2.0f);
    glEnable(GL_DEPTH_TEST);
    glPointSize(7.5f);
    fcu_clear(0, 0, 0, 1, 1);
    glBegin(GL_QUADS);
    glColor3f(1, 0.5f, 0);
    glVertex2f(8.2f, 8.4f);
    glVertex2f(40.5f, 9.0f);
    glVertex2f(38.0f, 30.5f);
    glVertex2f(10.0f, 28.25f);
    glColor3f(0, 0.5f, 1);
    glVertex2f(20.0f, 35.0f);
    glVertex2f(22.0f, 56.0f);
    glVertex2f(55.5f, 57.0f);
    glVertex2f(54.0f, 36.5f);
    glEnd();
    fc_capture(h);
}

/* Large sprites on a 200x160 buffer across the 64x64 tiles of the
 * threaded rasterizer (tile corners and edges), textured and blended. */
static void tiles(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    sprite_texture(GL_LINEAR, GL_LINEAR, 0);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    static const float at[][3] = { { 64, 64, 40 }, { 128.5f, 64.5f, 33.3f }, { 63.7f, 128.2f, 90 },
                                   { 192, 100, 70 }, { 100, 140, 255 }, { 30, 30, 17 } };
    for (int i = 0; i < 6; i++) {
        glPointSize(at[i][2]);
        glBegin(GL_POINTS);
        glColor4f(0.3f + 0.1f * (float)i, 0.9f - 0.1f * (float)i, 0.5f, 0.7f);
        glVertex2f(at[i][0], at[i][1]);
        glEnd();
    }
    fc_capture(h);
}

/* ---- demo/sprite_particles ----
 * A fountain of particles the way a GL 1.x particle demo draws it:
 * positions and fog coordinates computed on the CPU each frame and
 * written into a buffer object (glBufferSubData, then glMapBuffer in
 * later frames), colours in a second buffer, drawn with glDrawArrays as
 * point sprites (GL_COORD_REPLACE, a LINEAR mipmapped round blob
 * texture, GL_MODULATE), distance attenuation clamped to [2, 48], fog by
 * fog coordinate (the particle's age), additive blending with depth
 * writes off over a depth-tested floor drawn first; the camera orbits.
 * Eight frames. */
#define PART_FRAMES 8
#define PART_N 600

struct particle {
    float p[3], v[3], age;
};

/* a deterministic generator of the demo (no libc rand) */
static unsigned part_rng = 12345u;
static float part_rand(void)
{
    part_rng = part_rng * 1664525u + 1013904223u;
    return (float)(part_rng >> 8) * (1.0f / 16777216.0f);
}

static void part_spawn(struct particle *q)
{
    const float a = 6.2831853f * part_rand(), r = 0.15f * part_rand();
    q->p[0] = r * cosf(a);
    q->p[1] = 0.0f;
    q->p[2] = r * sinf(a);
    q->v[0] = 0.6f * cosf(a) * part_rand();
    q->v[1] = 2.2f + 0.8f * part_rand();
    q->v[2] = 0.6f * sinf(a) * part_rand();
    q->age = 0.0f;
}

static void blob_texture(void)
{
    static GLubyte t[32 * 32 * 4];
    for (int n = 32, lv = 0; n >= 1; n /= 2, lv++) {
        for (int y = 0; y < n; y++)
            for (int x = 0; x < n; x++) {
                const float dx = ((float)x + 0.5f) / (float)n - 0.5f;
                const float dy = ((float)y + 0.5f) / (float)n - 0.5f;
                float k = 1.0f - 2.0f * sqrtf(dx * dx + dy * dy);
                k = k < 0.0f ? 0.0f : k;
                GLubyte *p = t + 4 * (y * n + x);
                p[0] = p[1] = p[2] = 255;
                p[3] = (GLubyte)(255.0f * k * k);
            }
        glTexImage2D(GL_TEXTURE_2D, lv, GL_RGBA, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

static void sprite_particles(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    static struct particle part[PART_N];
    /* per vertex: x, y, z, fog coordinate; colours RGBA ubyte */
    static GLfloat vtx[PART_N][4];
    static GLubyte col[PART_N][4];
    part_rng = 12345u;
    for (int i = 0; i < PART_N; i++) {
        part_spawn(&part[i]);
        /* staggered start: run each particle some steps */
        const int steps = i % 40;
        for (int s = 0; s < steps; s++) {
            part[i].p[0] += 0.03f * part[i].v[0];
            part[i].p[1] += 0.03f * part[i].v[1];
            part[i].p[2] += 0.03f * part[i].v[2];
            part[i].v[1] -= 0.03f * 2.5f;
            part[i].age += 0.03f;
        }
    }
    glViewport(0, 0, c->width, c->height);
    const double aspect = (double)c->width / c->height;
    fcu_frustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 30.0);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.02f, 0.02f, 0.06f, 1.0f);
    blob_texture();
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    const GLfloat atten[3] = { 0.0f, 0.0f, 0.02f };
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
    glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
    glPointParameterf(GL_POINT_SIZE_MAX, 48.0f);
    glPointSize(9.0f);
    const float fogcol[4] = { 0.02f, 0.02f, 0.06f, 1.0f };
    glFogfv(GL_FOG_COLOR, fogcol);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0.2f);
    glFogf(GL_FOG_END, 1.6f);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);

    GLuint buf[2];
    glGenBuffers(2, buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof vtx, NULL, GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, buf[1]);
    glBufferData(GL_ARRAY_BUFFER, sizeof col, NULL, GL_STREAM_DRAW);

    for (int f = 0; f < PART_FRAMES; f++) {
        /* simulate */
        for (int i = 0; i < PART_N; i++) {
            struct particle *q = &part[i];
            q->p[0] += 0.05f * q->v[0];
            q->p[1] += 0.05f * q->v[1];
            q->p[2] += 0.05f * q->v[2];
            q->v[1] -= 0.05f * 2.5f;
            q->age += 0.05f;
            if (q->p[1] < 0.0f) {
                q->p[1] = -q->p[1];
                q->v[1] = -0.45f * q->v[1];
            }
            if (q->age > 2.2f)
                part_spawn(q);
            vtx[i][0] = q->p[0];
            vtx[i][1] = q->p[1];
            vtx[i][2] = q->p[2];
            vtx[i][3] = q->age;
            const float k = 1.0f - q->age / 2.2f;
            col[i][0] = (GLubyte)(255.0f * (0.6f + 0.4f * k));
            col[i][1] = (GLubyte)(255.0f * (0.25f + 0.6f * k * k));
            col[i][2] = (GLubyte)(255.0f * 0.2f * k);
            col[i][3] = (GLubyte)(255.0f * (0.35f + 0.6f * k));
        }
        glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
        if (f % 2 == 0) {
            glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof vtx, vtx);
        } else {
            void *m = glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
            if (m) {
                memcpy(m, vtx, sizeof vtx);
                glUnmapBuffer(GL_ARRAY_BUFFER);
            }
        }
        glBindBuffer(GL_ARRAY_BUFFER, buf[1]);
        glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof col, col);

        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glLoadIdentity();
        glTranslatef(0.0f, -0.9f, -4.2f);
        glRotatef(18.0f, 1, 0, 0);
        glRotatef(11.0f * (float)f, 0, 1, 0);

        /* the floor: depth-tested, written, untextured */
        glDisable(GL_TEXTURE_2D);
        glDisable(GL_FOG);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        glBegin(GL_QUADS);
        for (int j = 0; j < 4; j++)
            for (int i = 0; i < 4; i++) {
                const float x0 = -2.0f + (float)i, z0 = -2.0f + (float)j;
                const float g = ((i + j) & 1) ? 0.22f : 0.12f;
                glColor3f(g, g, g + 0.05f);
                glVertex3f(x0, 0.0f, z0);
                glVertex3f(x0, 0.0f, z0 + 1.0f);
                glVertex3f(x0 + 1.0f, 0.0f, z0 + 1.0f);
                glVertex3f(x0 + 1.0f, 0.0f, z0);
            }
        glEnd();

        /* the particles */
        glEnable(GL_TEXTURE_2D);
        glEnable(GL_POINT_SPRITE);
        glEnable(GL_FOG);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE);
        glDepthMask(GL_FALSE);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glEnableClientState(GL_FOG_COORD_ARRAY);
        glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
        glVertexPointer(3, GL_FLOAT, 4 * sizeof(GLfloat), (const void *)0);
        glFogCoordPointer(GL_FLOAT, 4 * sizeof(GLfloat), (const void *)(3 * sizeof(GLfloat)));
        glBindBuffer(GL_ARRAY_BUFFER, buf[1]);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, (const void *)0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glDrawArrays(GL_POINTS, 0, PART_N);
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_COLOR_ARRAY);
        glDisableClientState(GL_FOG_COORD_ARRAY);
        glDisable(GL_POINT_SPRITE);
        fc_capture(h);
    }
    glDeleteBuffers(2, buf);
    fc_error(h, "final");
}

#define SPRITE(name, w, h, frames, tags, fn) \
    FC_CASE_RGBA("gl14/sprite_" name, w, h, frames, "gl14 points sprite " tags, fn)

const fc_case fc_cases_gl14_sprite[] = {
    SPRITE("size1_centre", 48, 48, 2, "", size1_centre),
    SPRITE("size1_edge", 48, 48, 2, "", size1_edge),
    SPRITE("size1_5_centre", 48, 48, 2, "", size1_5_centre),
    SPRITE("size1_5_edge", 48, 48, 2, "", size1_5_edge),
    SPRITE("size2_centre", 48, 48, 2, "", size2_centre),
    SPRITE("size2_edge", 48, 48, 2, "", size2_edge),
    SPRITE("size7_3_centre", 64, 64, 2, "texture", size7_3_centre),
    SPRITE("size7_3_edge", 64, 64, 2, "texture", size7_3_edge),
    SPRITE("size7_3_subpixel", 64, 64, 2, "texture", size7_3_subpixel),
    SPRITE("size64_centre", 150, 150, 2, "texture", size64_centre),
    SPRITE("size64_edge", 150, 150, 2, "texture", size64_edge),
    SPRITE("size_fraction_subpixel", 64, 64, 2, "texture", size_fraction_subpixel),
    SPRITE("size_below_one", 48, 48, 2, "", size_below_one),
    SPRITE("size_clamps", 48, 48, 4, "texture", size_clamps),
    SPRITE("tex_nearest", 96, 96, 1, "texture", tex_nearest),
    SPRITE("tex_linear", 96, 96, 1, "texture", tex_linear),
    SPRITE("tex_mipmap", 96, 96, 1, "texture", tex_mipmap),
    SPRITE("tex_mipmap_nearest", 96, 96, 1, "texture", tex_mipmap_nearest),
    /* the lower-left origin is GL 2.0's: the same scenes with the image
     * upside down, and the origin itself as honesty cases (below) */
    SPRITE("flipped_image", 96, 96, 1, "texture", flipped_image),
    SPRITE("flipped_image_linear", 96, 96, 1, "texture", flipped_image_linear),
    SPRITE("unit0_only", 96, 96, 1, "texture multitexture", unit0_only),
    SPRITE("unit1_only", 96, 96, 1, "texture multitexture", unit1_only),
    SPRITE("both_units", 96, 96, 1, "texture multitexture", both_units),
    SPRITE("no_replace", 96, 96, 1, "texture", no_replace),
    SPRITE("persp_nearest", 96, 96, 1, "texture", persp_nearest),
    SPRITE("persp_linear_two_units", 96, 96, 1, "texture multitexture", persp_linear_two_units),
    SPRITE("persp_mipmap", 96, 96, 1, "texture", persp_mipmap),
    SPRITE("atten_persp", 80, 80, 2, "texture", atten_persp),
    SPRITE("atten_untextured", 80, 80, 2, "", atten_untextured),
    SPRITE("atten_clamped", 80, 80, 2, "texture", atten_clamped),
    SPRITE("fade_threshold", 80, 80, 2, "texture blend", fade_threshold),
    SPRITE("offscreen_scissor", 64, 64, 3, "texture scissor clip", offscreen_scissor),
    SPRITE("smooth_with_sprites", 80, 64, 3, "texture smooth blend", smooth_with_sprites),
    SPRITE("fog", 80, 80, 3, "texture fog fogcoord varray", fog_scene),
    SPRITE("lit_flat", 80, 80, 2, "texture lighting seccolor", lit_flat),
    SPRITE("alpha_depth", 72, 40, 2, "texture fragment blend", alpha_depth),
    SPRITE("arrays_vbo_dlist", 64, 64, 4, "texture varray vbo dlist", arrays_vbo_dlist),
    SPRITE("varying_rule", 80, 80, 3, "texture", varying_rule),
    SPRITE("texgen_matrix", 80, 80, 1, "texture multitexture texgen", texgen_matrix),
    SPRITE("polygon_mode_points", 64, 64, 1, "texture polygon", polygon_mode_points),
    SPRITE("replaced_on_lines_polygons", 100, 66, 4, "texture multitexture texgen", replaced_on_lines_polygons),
    SPRITE("tiles", 200, 160, 1, "texture blend threads", tiles),
    FC_CASE_RGBA("demo/sprite_particles", 160, 120, PART_FRAMES,
                 "gl14 points sprite demo vbo fogcoord texture", sprite_particles),
    FC_CASE_RGBA("honesty/sprite_origin_lower_left", 96, 96, 1,
                 "honesty gl14 points sprite texture", origin_lower_left),
    FC_CASE_RGBA("honesty/sprite_origin_lower_left_linear", 96, 96, 1,
                 "honesty gl14 points sprite texture", origin_lower_left_linear),
    { 0 },
};
