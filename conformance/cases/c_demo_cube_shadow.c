/* c_demo_cube_shadow.c - demo/cube_shadow (issue 19 "Conformance": a
 * cube-map reflection scene with a shadow-mapped floor), animated in the
 * manner of demo/sprite_particles: each frame renders the light's view
 * into the lower-left 64x64 of the buffer (colour writes off, polygon
 * offset), copies that depth into a GL_DEPTH_COMPONENT24 texture with
 * glCopyTexSubImage2D, then draws the camera's view: a lit floor and an
 * orbiting box with the map projected by eye-linear texgen and compared
 * (GL_COMPARE_R_TO_TEXTURE, GL_LEQUAL, LINEAR: the filtered comparison)
 * on unit 0, and a sphere from buffer objects (glDrawElements with an
 * element buffer) with a mipmapped cube map on unit 1 through
 * GL_REFLECTION_MAP texgen, separate specular, shadowed by unit 0 too.
 * The light and the camera move.  Eight frames. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

#define CS_FRAMES 8
#define CS_MAP 64           /* the shadow map: the lower-left 64x64 */
#define CS_STACKS 10
#define CS_SLICES 16
#define CS_NV ((CS_STACKS + 1) * (CS_SLICES + 1))
#define CS_NI (CS_STACKS * CS_SLICES * 6)

/* The six faces of a sky cube, 32x32 down to 1x1 (a 2x2 box filter of
 * the level above): a vertical gradient per face, a checker, a bright
 * band on the +Y face. */
static void sky_cube(void)
{
    static GLubyte lv[6][32 * 32 * 4], tmp[32 * 32 * 4];
    for (int f = 0; f < 6; f++)
        for (int y = 0; y < 32; y++)
            for (int x = 0; x < 32; x++) {
                GLubyte *p = lv[f] + 4 * (y * 32 + x);
                const int chk = ((x >> 2) ^ (y >> 2)) & 1;
                p[0] = (GLubyte)(40 + 30 * f + 3 * y + (chk ? 30 : 0));
                p[1] = (GLubyte)(60 + 5 * y + 17 * f % 50);
                p[2] = (GLubyte)(200 - 4 * y + (chk ? 0 : 40));
                p[3] = 255;
                if (f == 2 && y > 12 && y < 18)
                    p[0] = p[1] = p[2] = 250;
            }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int f = 0; f < 6; f++) {
        int n = 32;
        memcpy(tmp, lv[f], sizeof tmp);
        for (int level = 0; n >= 1; level++, n /= 2) {
            glTexImage2D((GLenum)(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), level, GL_RGB8, n, n, 0,
                         GL_RGBA, GL_UNSIGNED_BYTE, tmp);
            const int m = n / 2;
            for (int y = 0; y < m; y++)
                for (int x = 0; x < m; x++)
                    for (int k = 0; k < 4; k++) {
                        const int s = tmp[4 * ((2 * y) * n + 2 * x) + k] + tmp[4 * ((2 * y) * n + 2 * x + 1) + k]
                                    + tmp[4 * ((2 * y + 1) * n + 2 * x) + k]
                                    + tmp[4 * ((2 * y + 1) * n + 2 * x + 1) + k];
                        tmp[4 * (y * m + x) + k] = (GLubyte)((s + 2) / 4);
                    }
        }
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

/* A box of half size s at (x, y, z), its faces as quads with normals. */
static void cs_box(float x, float y, float z, float s)
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

/* The floor: a 6x6 checker of quads (colour material). */
static void cs_floor(void)
{
    glBegin(GL_QUADS);
    glNormal3f(0, 1, 0);
    for (int j = 0; j < 6; j++)
        for (int i = 0; i < 6; i++) {
            const float x0 = -3.0f + (float)i, z0 = -3.0f + (float)j;
            const float g = ((i + j) & 1) ? 0.85f : 0.55f;
            glColor3f(g, g, g * 0.9f);
            glVertex3f(x0, 0.0f, z0);
            glVertex3f(x0, 0.0f, z0 + 1.0f);
            glVertex3f(x0 + 1.0f, 0.0f, z0 + 1.0f);
            glVertex3f(x0 + 1.0f, 0.0f, z0);
        }
    glEnd();
}

/* The sphere's vertices (position, normal) and triangle indices, in
 * world coordinates, written into the two buffers. */
static void cs_sphere_buffers(GLuint vbo, GLuint ibo, float cx, float cy, float cz, float r)
{
    static GLfloat vn[CS_NV][6];
    static GLushort idx[CS_NI];
    int k = 0;
    for (int i = 0; i <= CS_STACKS; i++) {
        const float ph = 3.14159265f * (float)i / CS_STACKS;
        for (int j = 0; j <= CS_SLICES; j++, k++) {
            const float th = 6.2831853f * (float)j / CS_SLICES;
            const float nx = sinf(ph) * cosf(th), ny = cosf(ph), nz = sinf(ph) * sinf(th);
            vn[k][0] = cx + r * nx;
            vn[k][1] = cy + r * ny;
            vn[k][2] = cz + r * nz;
            vn[k][3] = nx;
            vn[k][4] = ny;
            vn[k][5] = nz;
        }
    }
    k = 0;
    for (int i = 0; i < CS_STACKS; i++)
        for (int j = 0; j < CS_SLICES; j++) {
            const GLushort a = (GLushort)(i * (CS_SLICES + 1) + j), b = (GLushort)(a + CS_SLICES + 1);
            idx[k++] = a;
            idx[k++] = (GLushort)(a + 1);
            idx[k++] = b;
            idx[k++] = b;
            idx[k++] = (GLushort)(a + 1);
            idx[k++] = (GLushort)(b + 1);
        }
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof vn, vn, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
}

static void cs_sphere_draw(GLuint vbo, GLuint ibo)
{
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 6 * sizeof(GLfloat), (const void *)0);
    glNormalPointer(GL_FLOAT, 6 * sizeof(GLfloat), (const void *)(3 * sizeof(GLfloat)));
    glDrawElements(GL_TRIANGLES, CS_NI, GL_UNSIGNED_SHORT, (const void *)0);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

static void cube_shadow(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    GLuint tex[2], buf[2];
    glGenTextures(2, tex);
    glGenBuffers(2, buf);
    /* unit 1: the sky cube */
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    sky_cube();
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    static const GLenum str[3] = { GL_S, GL_T, GL_R };
    for (int k = 0; k < 3; k++)
        glTexGeni(str[k], GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    /* unit 0: the shadow map, its storage made once, each frame's depth
     * copied into it */
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, CS_MAP, CS_MAP, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    static const GLenum strq[4] = { GL_S, GL_T, GL_R, GL_Q };
    for (int k = 0; k < 4; k++)
        glTexGeni(strq[k], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    fc_error(h, "setup");

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    static const GLfloat amb[4] = { 0.25f, 0.25f, 0.3f, 1.0f };
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    const double aspect = (double)c->width / c->height;

    for (int f = 0; f < CS_FRAMES; f++) {
        const float la = 0.5f + 0.35f * (float)f;   /* the light's orbit, radians */
        const float lpos[4] = { 3.441f * sinf(la), 4.915f, 3.441f * cosf(la), 1.0f };
        const float bx = 1.3f * cosf(0.6f * (float)f), bz = 1.3f * sinf(0.6f * (float)f);
        const float sy = 1.0f + 0.2f * sinf(0.9f * (float)f);
        cs_sphere_buffers(buf[0], buf[1], -0.3f, sy, 0.1f, 0.7f);

        /* pass 1: depth from the light, into the lower-left corner */
        glViewport(0, 0, CS_MAP, CS_MAP);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-0.6, 0.6, -0.6, 0.6, 3.0, 12.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTranslatef(0.0f, 0.0f, -6.0f);
        glRotatef(55.0f, 1, 0, 0);
        glRotatef(-la * 57.29578f, 0, 1, 0);
        GLfloat light_proj[16], light_view[16];
        glGetFloatv(GL_PROJECTION_MATRIX, light_proj);
        glGetFloatv(GL_MODELVIEW_MATRIX, light_view);
        glClear(GL_DEPTH_BUFFER_BIT);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.5f, 4.0f);
        cs_floor();
        cs_box(bx, 0.35f, bz, 0.35f);
        cs_sphere_draw(buf[0], buf[1]);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, tex[0]);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, CS_MAP, CS_MAP);

        /* pass 2: the camera */
        glViewport(0, 0, c->width, c->height);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        fcu_frustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.5, 20.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTranslatef(0.0f, -0.7f, -6.5f);
        glRotatef(24.0f, 1, 0, 0);
        glRotatef(15.0f + 8.0f * (float)f, 0, 1, 0);
        glClearColor(0.1f, 0.1f, 0.18f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glLightfv(GL_LIGHT0, GL_POSITION, lpos);
        /* unit 0's texture matrix: bias * light projection * light view;
         * the eye planes, given under the camera, are object space */
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glTranslatef(0.5f, 0.5f, 0.5f);
        glScalef(0.5f, 0.5f, 0.5f);
        glMultMatrixf(light_proj);
        glMultMatrixf(light_view);
        glMatrixMode(GL_MODELVIEW);
        static const GLfloat planes[4][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
        for (int k = 0; k < 4; k++) {
            glTexGenfv(strq[k], GL_EYE_PLANE, planes[k]);
            glEnable((GLenum)(GL_TEXTURE_GEN_S + k));
        }
        glEnable(GL_TEXTURE_2D);
        glEnable(GL_LIGHTING);
        static const GLfloat black[4] = { 0, 0, 0, 1 }, spec[4] = { 0.9f, 0.9f, 0.8f, 1 };
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
        cs_floor();
        glColor3f(0.8f, 0.35f, 0.25f);
        cs_box(bx, 0.35f, bz, 0.35f);

        /* the mirror sphere: the cube map on unit 1 as well */
        glActiveTexture(GL_TEXTURE1);
        glEnable(GL_TEXTURE_CUBE_MAP);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
        glEnable(GL_TEXTURE_GEN_R);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
        glColor3f(0.95f, 0.95f, 1.0f);
        cs_sphere_draw(buf[0], buf[1]);
        glDisable(GL_TEXTURE_CUBE_MAP);
        glDisable(GL_TEXTURE_GEN_S);
        glDisable(GL_TEXTURE_GEN_T);
        glDisable(GL_TEXTURE_GEN_R);
        glActiveTexture(GL_TEXTURE0);
        glDisable(GL_TEXTURE_2D);
        glDisable(GL_LIGHTING);
        for (int k = 0; k < 4; k++)
            glDisable((GLenum)(GL_TEXTURE_GEN_S + k));
        fc_capture(h);
    }
    glDeleteBuffers(2, buf);
    glDeleteTextures(2, tex);
    fc_error(h, "final");
}

const fc_case fc_cases_demo_cube_shadow[] = {
    FC_CASE_RGBA("demo/cube_shadow", 160, 120, CS_FRAMES,
                 "gl13 gl14 gl15 cubemap shadow demo texgen vbo multitexture lighting", cube_shadow),
    { 0 },
};
