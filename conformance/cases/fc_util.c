/* fc_util.c - drawing helpers shared by the fixed cases (see cases.h). */
#include "cases.h"

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
