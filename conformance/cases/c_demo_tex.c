/* c_demo_tex.c - a textured legacy-style demo, compared frame by frame.
 *
 * demo/textured_scene draws what a GL 1.x game or demo of the late 1990s
 * draws each frame:
 *   floor     a checker texture with a mipmap chain built by hand (box
 *             filtered), GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT, modulated by
 *             lighting; one large quad that reaches behind the camera, so
 *             it is clipped by the near plane and seen at grazing angles;
 *   crate     a rotating cube with an RGBA texture (GL_LINEAR,
 *             GL_CLAMP_TO_EDGE), lit, GL_MODULATE, texture coordinates
 *             from glTexCoord2f;
 *   orb       a sphere with a sphere-mapped luminance texture
 *             (GL_SPHERE_MAP texgen on S and T, GL_REPLACE);
 *   sign      a quad with a decal texture (GL_DECAL, alpha cut-outs) over
 *             a lit colour, its coordinates scaled by the texture matrix;
 *   logo      a 16x16 RGBA image through glDrawPixels with glPixelZoom
 *             and blending;
 *   mirror    glCopyPixels of part of the frame into a corner, zoomed;
 *   text      a HUD line drawn with glBitmap from an 8x8 bitmap font
 *             (glWindowPos for the start, the raster position advancing
 *             by each glyph's xmove).
 * A camera circling the scene over six frames (glFrustum, glRotatef,
 * glTranslatef), depth test, two lights. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cases.h"

#define TEX_FRAMES 6

enum { T_FLOOR = 11, T_CRATE, T_ORB, T_SIGN };

/* ---- textures, generated once per case ---- */

static GLubyte floor_tex[64 * 64 * 3];
static GLubyte crate_tex[32 * 32 * 4];
static GLubyte orb_tex[16 * 16];
static GLubyte sign_tex[16 * 8 * 4];
static GLubyte logo[16 * 16 * 4];

static void gen_textures(void)
{
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            GLubyte *t = &floor_tex[(y * 64 + x) * 3];
            const int on = ((x / 8) ^ (y / 8)) & 1;
            t[0] = (GLubyte)(on ? 200 : 40 + x);
            t[1] = (GLubyte)(on ? 180 : 60 + y);
            t[2] = (GLubyte)(on ? 150 : 90);
        }
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++) {
            GLubyte *t = &crate_tex[(y * 32 + x) * 4];
            const int edge = x < 3 || y < 3 || x > 28 || y > 28 || x == y || x == 31 - y;
            t[0] = (GLubyte)(edge ? 90 : 170 + (x * 7 + y * 3) % 40);
            t[1] = (GLubyte)(edge ? 60 : 120 + (x * 5) % 30);
            t[2] = (GLubyte)(edge ? 30 : 60);
            t[3] = (GLubyte)(edge ? 255 : 200);
        }
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            const int dx = x - 8, dy = y - 8;
            const int d = 255 - (dx * dx + dy * dy) * 4;
            orb_tex[y * 16 + x] = (GLubyte)(d < 0 ? 0 : d);
        }
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 16; x++) {
            GLubyte *t = &sign_tex[(y * 16 + x) * 4];
            t[0] = (GLubyte)(x * 16);
            t[1] = 255;
            t[2] = (GLubyte)(y * 32);
            t[3] = (GLubyte)(((x + y) % 3) ? 255 : 0);
        }
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            GLubyte *p = &logo[(y * 16 + x) * 4];
            const int ring = abs((x - 8) * (x - 8) + (y - 8) * (y - 8) - 30) < 12;
            p[0] = (GLubyte)(ring ? 255 : 20);
            p[1] = (GLubyte)(ring ? 200 : 20 + 8 * y);
            p[2] = (GLubyte)(ring ? 40 : 100);
            p[3] = (GLubyte)(ring ? 255 : 96);
        }
}

/* The floor's mipmap chain: each level the 2x2 box average (rounded
 * down) of the one above, uploaded level by level. */
static void upload_floor(void)
{
    static GLubyte levels[2][64 * 64 * 3];
    int w = 64, cur = 0;
    memcpy(levels[0], floor_tex, sizeof floor_tex);
    for (int level = 0;; level++) {
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, w, w, 0, GL_RGB, GL_UNSIGNED_BYTE, levels[cur]);
        if (w == 1)
            break;
        const int n = w / 2;
        for (int y = 0; y < n; y++)
            for (int x = 0; x < n; x++)
                for (int c = 0; c < 3; c++) {
                    const GLubyte *s = levels[cur];
                    const int sum = s[((2 * y) * w + 2 * x) * 3 + c] + s[((2 * y) * w + 2 * x + 1) * 3 + c] +
                                    s[((2 * y + 1) * w + 2 * x) * 3 + c] +
                                    s[((2 * y + 1) * w + 2 * x + 1) * 3 + c];
                    levels[1 - cur][(y * n + x) * 3 + c] = (GLubyte)(sum / 4);
                }
        cur = 1 - cur;
        w = n;
    }
}

static void setup_textures(void)
{
    glBindTexture(GL_TEXTURE_2D, T_FLOOR);
    upload_floor();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

    glBindTexture(GL_TEXTURE_2D, T_CRATE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, crate_tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    glBindTexture(GL_TEXTURE_2D, T_ORB);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, orb_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);

    glBindTexture(GL_TEXTURE_2D, T_SIGN);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, sign_tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

/* ---- an 8x8 bitmap font of digits and a few letters ---- */

/* Seven-segment glyphs: bit 0 top, 1 upper right, 2 lower right, 3
 * bottom, 4 lower left, 5 upper left, 6 middle. */
static const unsigned char seg[16] = {
    0x3f, 0x06, 0x5b, 0x4f, 0x66, 0x6d, 0x7d, 0x07, 0x7f, 0x6f,   /* 0-9 */
    0x77, 0x7c, 0x39, 0x5e, 0x79, 0x71,                           /* A-F */
};

/* The glyph's 8 rows, bottom row first, as glBitmap reads them. */
static void glyph(int g, GLubyte rows[8])
{
    const unsigned s = seg[g & 15];
    memset(rows, 0, 8);
    if (s & 0x01) rows[6] |= 0x3c;
    if (s & 0x40) rows[3] |= 0x3c;
    if (s & 0x08) rows[0] |= 0x3c;
    for (int r = 4; r < 6; r++) {
        if (s & 0x20) rows[r] |= 0x20;
        if (s & 0x02) rows[r] |= 0x04;
    }
    for (int r = 1; r < 3; r++) {
        if (s & 0x10) rows[r] |= 0x20;
        if (s & 0x04) rows[r] |= 0x04;
    }
}

static void hud_text(const char *text)
{
    for (const char *p = text; *p; p++) {
        GLubyte rows[8];
        const int g = *p >= '0' && *p <= '9' ? *p - '0' : *p >= 'A' && *p <= 'F' ? 10 + *p - 'A' : -1;
        if (g < 0) {
            glBitmap(0, 0, 0, 0, 8, 0, NULL);   /* a space: the advance only */
            continue;
        }
        glyph(g, rows);
        glBitmap(8, 8, 0.0f, 0.0f, 8.0f, 0.0f, rows);
    }
}

/* ---- objects ---- */

static void mat(GLenum pname, float r, float g, float b, float a)
{
    const GLfloat v[4] = { r, g, b, a };
    glMaterialfv(GL_FRONT_AND_BACK, pname, v);
}

static void draw_floor(void)
{
    glBindTexture(GL_TEXTURE_2D, T_FLOOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    mat(GL_AMBIENT_AND_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
    glNormal3f(0, 1, 0);
    glBegin(GL_QUADS);
    glTexCoord2f(-6, -6); glVertex3f(-30, 0, -30);
    glTexCoord2f(-6, 6);  glVertex3f(-30, 0, 30);
    glTexCoord2f(6, 6);   glVertex3f(30, 0, 30);
    glTexCoord2f(6, -6);  glVertex3f(30, 0, -30);
    glEnd();
}

static void draw_crate(float angle)
{
    static const float n[6][3] = { {0,0,1}, {0,0,-1}, {1,0,0}, {-1,0,0}, {0,1,0}, {0,-1,0} };
    glBindTexture(GL_TEXTURE_2D, T_CRATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    mat(GL_AMBIENT_AND_DIFFUSE, 1.0f, 1.0f, 1.0f, 1.0f);
    glPushMatrix();
    glTranslatef(-1.5f, 1.0f, 0.5f);
    glRotatef(angle, 0.3f, 1.0f, 0.2f);
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; f++) {
        const float *a = n[f];
        /* two axes spanning the face */
        const float u[3] = { a[1] != 0 ? 1.0f : a[2] != 0 ? 1.0f : 0.0f, 0.0f,
                             a[0] != 0 ? 1.0f : 0.0f };
        const float v[3] = { a[1] * u[2] - a[2] * u[1], a[2] * u[0] - a[0] * u[2],
                             a[0] * u[1] - a[1] * u[0] };
        static const float c[4][2] = { {0,0}, {1,0}, {1,1}, {0,1} };
        glNormal3fv(a);
        for (int k = 0; k < 4; k++) {
            const float s = c[k][0] * 2 - 1, t = c[k][1] * 2 - 1;
            glTexCoord2f(c[k][0], c[k][1]);
            glVertex3f(a[0] + s * u[0] + t * v[0], a[1] + s * u[1] + t * v[1],
                       a[2] + s * u[2] + t * v[2]);
        }
    }
    glEnd();
    glPopMatrix();
}

static void draw_orb(float angle)
{
    glBindTexture(GL_TEXTURE_2D, T_ORB);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glPushMatrix();
    glTranslatef(1.5f, 1.2f, -0.5f);
    glRotatef(angle * 0.5f, 0, 1, 0);
    for (int i = 0; i < 10; i++) {
        const float t0 = (float)M_PI * i / 10 - (float)M_PI / 2, t1 = (float)M_PI * (i + 1) / 10 - (float)M_PI / 2;
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= 16; j++) {
            const float p = 2 * (float)M_PI * j / 16;
            glNormal3f(cosf(t1) * cosf(p), sinf(t1), cosf(t1) * sinf(p));
            glVertex3f(cosf(t1) * cosf(p), sinf(t1), cosf(t1) * sinf(p));
            glNormal3f(cosf(t0) * cosf(p), sinf(t0), cosf(t0) * sinf(p));
            glVertex3f(cosf(t0) * cosf(p), sinf(t0), cosf(t0) * sinf(p));
        }
        glEnd();
    }
    glPopMatrix();
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
}

static void draw_sign(float t)
{
    glBindTexture(GL_TEXTURE_2D, T_SIGN);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(t * 0.1f, 0, 0);
    glScalef(2, 1, 1);
    glMatrixMode(GL_MODELVIEW);
    mat(GL_AMBIENT_AND_DIFFUSE, 0.2f, 0.3f, 0.8f, 1.0f);
    glNormal3f(0, 0, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex3f(-1, 2.5f, -2);
    glTexCoord2f(1, 0); glVertex3f(1, 2.5f, -2);
    glTexCoord2f(1, 1); glVertex3f(1, 3.5f, -2);
    glTexCoord2f(0, 1); glVertex3f(-1, 3.5f, -2);
    glEnd();
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
}

static void textured_scene(fc_h *h)
{
    gen_textures();
    setup_textures();
    const GLfloat l0[4] = { 0.4f, 1.0f, 0.6f, 0.0f }, l1[4] = { -2.0f, 3.0f, 2.0f, 1.0f };
    const GLfloat amb[4] = { 0.25f, 0.25f, 0.3f, 1.0f }, d1[4] = { 0.8f, 0.7f, 0.5f, 1.0f };
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, d1);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.1f);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.1f, 0.15f, 0.25f, 1.0f);

    for (int frame = 0; frame < TEX_FRAMES; frame++) {
        const float angle = 17.0f + 23.0f * (float)frame;
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-0.16, 0.16, -0.12, 0.12, 0.2, 60.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTranslatef(0, -1.2f, -6.0f);
        glRotatef(12.0f, 1, 0, 0);
        glRotatef(angle, 0, 1, 0);
        glLightfv(GL_LIGHT0, GL_POSITION, l0);
        glLightfv(GL_LIGHT1, GL_POSITION, l1);

        glEnable(GL_LIGHTING);
        glEnable(GL_TEXTURE_2D);
        draw_floor();
        draw_crate(angle * 2.0f);
        glDisable(GL_LIGHTING);
        draw_orb(angle);
        glEnable(GL_LIGHTING);
        draw_sign((float)frame);
        glDisable(GL_TEXTURE_2D);
        glDisable(GL_LIGHTING);

        /* 2D overlay: logo, mirror, text */
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glWindowPos2i(4 + frame, 4);
        glPixelZoom(2.0f, 1.5f);
        glDrawPixels(16, 16, GL_RGBA, GL_UNSIGNED_BYTE, logo);
        glPixelZoom(1.0f, 1.0f);
        glDisable(GL_BLEND);
        glWindowPos2i(112, 84);
        glPixelZoom(0.5f, 0.5f);
        glCopyPixels(40, 30, 80, 60, GL_COLOR);
        glPixelZoom(1.0f, 1.0f);
        glColor3f(1.0f, 0.9f, 0.2f);
        /* one byte per glyph row */
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glWindowPos2i(44, 110);
        {
            char text[32];
            snprintf(text, sizeof text, "F%d %03d", frame, (int)angle);
            hud_text(text);
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glEnable(GL_DEPTH_TEST);
        fc_capture(h);
    }
    fc_error(h, "textured scene");
}

const fc_case fc_cases_demo_tex[] = {
    FC_CASE_RGBA("demo/textured_scene", 160, 120, TEX_FRAMES, "texture pixel demo", textured_scene),
    { 0 }
};
