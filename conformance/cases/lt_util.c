/* lt_util.c - helpers shared by the lighting cases (see lt_util.h). */
#include "lt_util.h"

#include <math.h>
#include <string.h>

void lt_light(GLenum light, GLenum pname, float x, float y, float z, float w)
{
    const GLfloat v[4] = { x, y, z, w };
    glLightfv(light, pname, v);
}

void lt_mat(GLenum face, GLenum pname, float r, float g, float b, float a)
{
    const GLfloat v[4] = { r, g, b, a };
    glMaterialfv(face, pname, v);
}

void lt_model(GLenum pname, float r, float g, float b, float a)
{
    const GLfloat v[4] = { r, g, b, a };
    glLightModelfv(pname, v);
}

void lt_lamp(GLenum light, const float amb[3], const float diff[3], const float spec[3],
             float x, float y, float z, float w)
{
    lt_light(light, GL_AMBIENT, amb[0], amb[1], amb[2], 1);
    lt_light(light, GL_DIFFUSE, diff[0], diff[1], diff[2], 1);
    lt_light(light, GL_SPECULAR, spec[0], spec[1], spec[2], 1);
    lt_light(light, GL_POSITION, x, y, z, w);
    glEnable(light);
}

void lt_std_material(void)
{
    lt_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.2f, 0.2f, 0.2f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.55f, 0.3f, 1);
    lt_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.7f, 0.7f, 0.7f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30);
}

static void lt_viewport(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    glViewport(0, 0, c->width, c->height);
}

static double lt_aspect(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    return (double)c->width / (double)c->height;
}

void lt_persp(fc_h *h)
{
    double a = lt_aspect(h);
    lt_viewport(h);
    fcu_frustum(-0.5 * a, 0.5 * a, -0.5, 0.5, 1.5, 20);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    lt_clear();
}

void lt_ortho(fc_h *h, float s)
{
    double a = lt_aspect(h);
    lt_viewport(h);
    fcu_ortho(-s * a, s * a, -s, s, -10, 10);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    lt_clear();
}

void lt_clear(void)
{
    fcu_clear(0.05f, 0.06f, 0.12f, 1, 1);
}

static void sphere_vertex(float r, float ns, double lat, double lon)
{
    float x = (float)(cos(lat) * sin(lon)), y = (float)sin(lat), z = (float)(cos(lat) * cos(lon));
    glNormal3f(x * ns, y * ns, z * ns);
    glVertex3f(x * r, y * r, z * r);
}

void lt_sphere_n(float r, int slices, int stacks, float ns)
{
    for (int i = 0; i < stacks; i++) {
        double lat0 = LT_PI * i / stacks - LT_PI / 2, lat1 = LT_PI * (i + 1) / stacks - LT_PI / 2;
        glBegin(GL_TRIANGLE_STRIP);
        for (int j = 0; j <= slices; j++) {
            double lon = 2 * LT_PI * j / slices;
            sphere_vertex(r, ns, lat1, lon);
            sphere_vertex(r, ns, lat0, lon);
        }
        glEnd();
    }
}

void lt_sphere(float r, int slices, int stacks)
{
    lt_sphere_n(r, slices, stacks, 1.0f);
}

void lt_patch(float x0, float y0, float x1, float y1, int n)
{
    glNormal3f(0, 0, 1);
    for (int j = 0; j < n; j++) {
        float ya = y0 + (y1 - y0) * (float)j / (float)n;
        float yb = y0 + (y1 - y0) * (float)(j + 1) / (float)n;
        glBegin(GL_TRIANGLE_STRIP);
        for (int i = 0; i <= n; i++) {
            float x = x0 + (x1 - x0) * (float)i / (float)n;
            glVertex3f(x, yb, 0);
            glVertex3f(x, ya, 0);
        }
        glEnd();
    }
}

static void wave_vertex(float x, float y, float amp, float f)
{
    double z = amp * sin(f * x) * cos(f * y);
    double dx = amp * f * cos(f * x) * cos(f * y), dy = -amp * f * sin(f * x) * sin(f * y);
    double l = sqrt(dx * dx + dy * dy + 1);
    glNormal3f((float)(-dx / l), (float)(-dy / l), (float)(1 / l));
    glVertex3f(x, y, (float)z);
}

void lt_wave(float x0, float y0, float x1, float y1, int n, float amp, float f)
{
    for (int j = 0; j < n; j++) {
        float ya = y0 + (y1 - y0) * (float)j / (float)n;
        float yb = y0 + (y1 - y0) * (float)(j + 1) / (float)n;
        glBegin(GL_TRIANGLE_STRIP);
        for (int i = 0; i <= n; i++) {
            float x = x0 + (x1 - x0) * (float)i / (float)n;
            wave_vertex(x, yb, amp, f);
            wave_vertex(x, ya, amp, f);
        }
        glEnd();
    }
}

void lt_hue(float t, float a)
{
    float h = 6.0f * (t - floorf(t));
    int k = (int)h;
    float f = h - (float)k, q = 1 - f;
    float r, g, b;
    switch (k % 6) {
    case 0: r = 1; g = f; b = 0; break;
    case 1: r = q; g = 1; b = 0; break;
    case 2: r = 0; g = 1; b = f; break;
    case 3: r = 0; g = q; b = 1; break;
    case 4: r = f; g = 0; b = 1; break;
    default: r = 1; g = 0; b = q; break;
    }
    glColor4f(r, g, b, a);
}

void lt_rec_light(fc_h *h, const char *label, GLenum light, GLenum pname)
{
    GLfloat fv[4];
    GLint iv[4];
    memset(fv, 0xCD, sizeof fv);
    memset(iv, 0xCD, sizeof iv);
    glGetLightfv(light, pname, fv);
    fc_blob(h, label, fv, sizeof fv);
    glGetLightiv(light, pname, iv);
    fc_blob(h, label, iv, sizeof iv);
}

void lt_rec_material(fc_h *h, const char *label, GLenum face, GLenum pname)
{
    GLfloat fv[4];
    GLint iv[4];
    memset(fv, 0xCD, sizeof fv);
    memset(iv, 0xCD, sizeof iv);
    glGetMaterialfv(face, pname, fv);
    fc_blob(h, label, fv, sizeof fv);
    glGetMaterialiv(face, pname, iv);
    fc_blob(h, label, iv, sizeof iv);
}
