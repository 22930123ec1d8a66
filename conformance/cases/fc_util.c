/* fc_util.c - drawing helpers shared by the fixed cases (see cases.h). */
#include "cases.h"

#include <string.h>

static const GLubyte palette[16][3] = {
    { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 }, { 255, 255, 0 },
    { 0, 255, 255 }, { 255, 0, 255 }, { 255, 128, 0 }, { 128, 0, 255 },
    { 0, 128, 64 }, { 255, 255, 255 }, { 128, 128, 128 }, { 64, 0, 0 },
    { 0, 64, 128 }, { 192, 255, 128 }, { 255, 160, 192 }, { 96, 64, 32 },
};

void fcu_clear(float r, float g, float b, float a, double depth)
{
    glClearColor(r, g, b, a);
    glClearDepth(depth);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void fcu_color(int i)
{
    glColor3ubv(palette[i & 15]);
}

void fcu_rect(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

void fcu_tri(float x0, float y0, float x1, float y1, float x2, float y2)
{
    glBegin(GL_TRIANGLES);
    glVertex2f(x0, y0);
    glVertex2f(x1, y1);
    glVertex2f(x2, y2);
    glEnd();
}

void fcu_ortho(double l, double r, double b, double t, double n, double f)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(l, r, b, t, n, f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void fcu_frustum(double l, double r, double b, double t, double n, double f)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(l, r, b, t, n, f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* Vertices of each primitive type in window coordinates (32x32 buffer). */
const float fcu_tri_v[6][2] = {
    { 2, 2 }, { 14, 3 }, { 6, 14 }, { 17, 18 }, { 30, 20 }, { 20, 30 },
};
const float fcu_strip_v[8][2] = {
    { 2, 4 }, { 4, 26 }, { 10, 2 }, { 12, 29 }, { 19, 3 }, { 21, 28 }, { 29, 5 }, { 30, 27 },
};
const float fcu_fan_v[7][2] = {
    { 16, 16 }, { 30, 16 }, { 26, 27 }, { 14, 31 }, { 3, 24 }, { 3, 8 }, { 15, 1 },
};
const float fcu_quads_v[8][2] = {
    { 2, 2 }, { 14, 3 }, { 13, 14 }, { 3, 13 }, { 17, 16 }, { 30, 18 }, { 29, 30 }, { 18, 28 },
};
const float fcu_qstrip_v[8][2] = {
    { 2, 3 }, { 3, 28 }, { 11, 2 }, { 10, 29 }, { 20, 4 }, { 21, 27 }, { 30, 2 }, { 29, 30 },
};
const float fcu_poly_v[6][2] = {
    { 16, 2 }, { 29, 9 }, { 28, 24 }, { 16, 30 }, { 4, 23 }, { 3, 8 },
};

void fcu_tex_level_image(GLenum target, int level, int w, int h)
{
    static const unsigned char pal[8][2][4] = {
        { { 255, 0, 0, 255 }, { 128, 0, 40, 200 } },
        { { 0, 255, 0, 230 }, { 0, 110, 60, 150 } },
        { { 0, 0, 255, 210 }, { 60, 40, 140, 100 } },
        { { 255, 255, 0, 190 }, { 120, 120, 20, 60 } },
        { { 0, 255, 255, 170 }, { 30, 100, 100, 30 } },
        { { 255, 0, 255, 150 }, { 90, 20, 90, 10 } },
        { { 255, 255, 255, 130 }, { 70, 70, 70, 0 } },
        { { 255, 128, 0, 110 }, { 10, 10, 10, 255 } },
    };
    static unsigned char buf[256 * 256 * 4];
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            memcpy(&buf[4 * (y * w + x)], pal[level & 7][(x ^ y) & 1], 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (target == GL_TEXTURE_1D)
        glTexImage1D(GL_TEXTURE_1D, level, GL_RGBA, w, 0, GL_RGBA, GL_UNSIGNED_BYTE, buf);
    else
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, buf);
}

void fcu_tex_level_chain(GLenum target, int w, int h)
{
    for (int l = 0;; l++) {
        fcu_tex_level_image(target, l, w, h);
        if (w == 1 && (h == 1 || target == GL_TEXTURE_1D))
            break;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
}
