/* c_demo.c - animated legacy-style demos, compared frame by frame.
 *
 * demo/arrays_scene: a lit multi-object scene the way a GL 1.1 demo draws
 * it with client-side vertex arrays.  Five objects are generated once into
 * arrays of different types, sizes and strides:
 *   sphere    float positions and normals in separate arrays, ubyte colours
 *             with a padded stride, colour material (GL_AMBIENT_AND_DIFFUSE),
 *             GL_TRIANGLES through glDrawElements with GL_UNSIGNED_SHORT
 *             indices;
 *   torus     glInterleavedArrays(GL_N3F_V3F), GL_QUADS through
 *             glDrawElements with GL_UNSIGNED_INT indices;
 *   box       glInterleavedArrays(GL_C4F_N3F_V3F) with a padded stride,
 *             glDrawArrays(GL_QUADS), flat shaded, colour material on the
 *             diffuse only;
 *   cylinder  GL_SHORT positions (stride 8, scaled by the modelview) with
 *             GL_BYTE normals (gallivm's normalization) and GL_NORMALIZE,
 *             one GL_TRIANGLE_STRIP through glDrawElements with
 *             GL_UNSIGNED_BYTE indices, caps as GL_TRIANGLE_FAN
 *             glDrawArrays from first > 0;
 *   floor     GL_DOUBLE positions and GL_SHORT normals, glDrawArrays of
 *             GL_TRIANGLE_STRIPs.
 * Three lights: a dim directional one, a positional one circling the
 * objects with attenuation, and a spot light; per-object materials; a
 * camera orbiting over the frames (glFrustum, a look-at built from
 * glRotatef/glTranslatef); depth test.  Eight frames. */
#include <math.h>
#include <string.h>

#include "cases.h"
#include "lt_util.h"

#define DEMO_FRAMES 8

/* ---- geometry, generated once ---- */

enum { SPH_SL = 16, SPH_ST = 10, SPH_NV = (SPH_SL + 1) * (SPH_ST + 1),
       SPH_NI = SPH_SL * SPH_ST * 6 };
enum { TOR_MAJ = 18, TOR_MIN = 8, TOR_NV = TOR_MAJ * TOR_MIN, TOR_NI = TOR_MAJ * TOR_MIN * 4 };
enum { CYL_SL = 14, CYL_NV = 2 * (CYL_SL + 1) + 2 * (CYL_SL + 2), CYL_NI = 2 * (CYL_SL + 1) };
enum { FLR_N = 8, FLR_NV = (FLR_N + 1) * (FLR_N + 1) };

/* colour array element with a padded stride: 4 ubytes and 4 unused */
struct demo_col { GLubyte c[4]; GLubyte pad[4]; };
/* GL_C4F_N3F_V3F element with two trailing floats */
struct demo_box_vtx { GLfloat c[4], n[3], v[3], pad[2]; };
/* GL_SHORT position with a padding short: stride 8 */
struct demo_cyl_pos { GLshort p[3], pad; };

static struct demo_geom {
    GLfloat sph_v[SPH_NV][3], sph_n[SPH_NV][3];
    struct demo_col sph_c[SPH_NV];
    GLushort sph_i[SPH_NI];
    GLfloat tor[TOR_NV][6];                 /* N3F_V3F */
    GLuint tor_i[TOR_NI];
    struct demo_box_vtx box[24];
    struct demo_cyl_pos cyl_v[CYL_NV];
    GLbyte cyl_n[CYL_NV][4];                /* stride 4 */
    GLubyte cyl_i[CYL_NI];
    GLdouble flr_v[FLR_NV][3];
    GLshort flr_n[FLR_NV][3];
    GLuint flr_strip[FLR_N][2 * (FLR_N + 1)];
    int ready;
} G;

static void gen_sphere(void)
{
    for (int st = 0; st <= SPH_ST; st++) {
        const double t = LT_PI * st / SPH_ST;
        for (int sl = 0; sl <= SPH_SL; sl++) {
            const double p = 2 * LT_PI * sl / SPH_SL;
            const int k = st * (SPH_SL + 1) + sl;
            const double d[3] = { sin(t) * cos(p), cos(t), sin(t) * sin(p) };
            for (int c = 0; c < 3; c++) {
                G.sph_n[k][c] = (GLfloat)d[c];
                G.sph_v[k][c] = (GLfloat)(0.6 * d[c]);
            }
            G.sph_c[k].c[0] = (GLubyte)(60 + 190 * sl / SPH_SL);
            G.sph_c[k].c[1] = (GLubyte)(40 + 200 * st / SPH_ST);
            G.sph_c[k].c[2] = (GLubyte)(230 - 20 * ((sl + st) % 8));
            G.sph_c[k].c[3] = 255;
            memset(G.sph_c[k].pad, 0xa5, sizeof G.sph_c[k].pad);
        }
    }
    int n = 0;
    for (int st = 0; st < SPH_ST; st++)
        for (int sl = 0; sl < SPH_SL; sl++) {
            const int a = st * (SPH_SL + 1) + sl, b = a + SPH_SL + 1;
            /* counter-clockwise seen from outside */
            const int q[6] = { a, a + 1, b, a + 1, b + 1, b };
            for (int i = 0; i < 6; i++)
                G.sph_i[n++] = (GLushort)q[i];
        }
}

static void gen_torus(void)
{
    const double R = 0.55, r = 0.2;
    for (int i = 0; i < TOR_MAJ; i++) {
        const double u = 2 * LT_PI * i / TOR_MAJ;
        for (int j = 0; j < TOR_MIN; j++) {
            const double v = 2 * LT_PI * j / TOR_MIN;
            const double n[3] = { cos(v) * cos(u), cos(v) * sin(u), sin(v) };
            GLfloat *e = G.tor[i * TOR_MIN + j];
            e[0] = (GLfloat)n[0], e[1] = (GLfloat)n[1], e[2] = (GLfloat)n[2];
            e[3] = (GLfloat)((R + r * cos(v)) * cos(u));
            e[4] = (GLfloat)((R + r * cos(v)) * sin(u));
            e[5] = (GLfloat)(r * sin(v));
        }
    }
    int n = 0;
    for (int i = 0; i < TOR_MAJ; i++)
        for (int j = 0; j < TOR_MIN; j++) {
            const int i1 = (i + 1) % TOR_MAJ, j1 = (j + 1) % TOR_MIN;
            G.tor_i[n++] = (GLuint)(i * TOR_MIN + j);
            G.tor_i[n++] = (GLuint)(i1 * TOR_MIN + j);
            G.tor_i[n++] = (GLuint)(i1 * TOR_MIN + j1);
            G.tor_i[n++] = (GLuint)(i * TOR_MIN + j1);
        }
}

static void gen_box(void)
{
    /* six faces: normal, then two in-face axes giving CCW order */
    static const float f[6][3][3] = {
        { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
        { { -1, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 } },
        { { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 } },
        { { 0, -1, 0 }, { 1, 0, 0 }, { 0, 0, 1 } },
        { { 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0 } },
        { { 0, 0, -1 }, { 0, 1, 0 }, { 1, 0, 0 } },
    };
    static const float corner[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    const float half[3] = { 0.45f, 0.3f, 0.35f };
    for (int face = 0; face < 6; face++)
        for (int k = 0; k < 4; k++) {
            struct demo_box_vtx *e = &G.box[face * 4 + k];
            for (int c = 0; c < 3; c++) {
                const float p = f[face][0][c] + corner[k][0] * f[face][1][c] + corner[k][1] * f[face][2][c];
                e->v[c] = p * half[c];
                e->n[c] = f[face][0][c];
            }
            e->c[0] = 0.3f + 0.12f * (float)face;
            e->c[1] = 0.9f - 0.1f * (float)face;
            e->c[2] = 0.25f + 0.15f * (float)k;
            e->c[3] = 1.0f;
            e->pad[0] = e->pad[1] = -7.0f;
        }
}

static void gen_cylinder(void)
{
    /* side: pairs (top, bottom) per slice; positions in units of 1/1000 */
    const int r = 400, hy = 450;
    int n = 0;
    for (int s = 0; s <= CYL_SL; s++) {
        const double a = 2 * LT_PI * s / CYL_SL;
        const short x = (short)lround(r * cos(a)), z = (short)lround(-r * sin(a));
        const GLbyte nx = (GLbyte)lround(127 * cos(a)), nz = (GLbyte)lround(-127 * sin(a));
        for (int t = 0; t < 2; t++, n++) {
            G.cyl_v[n] = (struct demo_cyl_pos){ { x, (short)(t ? -hy : hy), z }, 0x5a5a };
            G.cyl_n[n][0] = nx, G.cyl_n[n][1] = 0, G.cyl_n[n][2] = nz, G.cyl_n[n][3] = 99;
        }
    }
    for (int i = 0; i < CYL_NI; i++)
        G.cyl_i[i] = (GLubyte)i;
    /* caps: centre then the rim, top counter-clockwise from +y, bottom
    * from -y */
    for (int cap = 0; cap < 2; cap++) {
        const short y = (short)(cap ? -hy : hy);
        const GLbyte ny = (GLbyte)(cap ? -127 : 127);
        G.cyl_v[n] = (struct demo_cyl_pos){ { 0, y, 0 }, 0x5a5a };
        G.cyl_n[n][0] = 0, G.cyl_n[n][1] = ny, G.cyl_n[n][2] = 0, G.cyl_n[n][3] = 99;
        n++;
        for (int s = 0; s <= CYL_SL; s++, n++) {
            const double a = 2 * LT_PI * (cap ? CYL_SL - s : s) / CYL_SL;
            G.cyl_v[n] = (struct demo_cyl_pos){
                { (short)lround(r * cos(a)), y, (short)lround(-r * sin(a)) }, 0x5a5a };
            G.cyl_n[n][0] = 0, G.cyl_n[n][1] = ny, G.cyl_n[n][2] = 0, G.cyl_n[n][3] = 99;
        }
    }
}

static void gen_floor(void)
{
    for (int i = 0; i <= FLR_N; i++)
        for (int j = 0; j <= FLR_N; j++) {
            const int k = i * (FLR_N + 1) + j;
            const double x = -2.0 + 4.0 * j / FLR_N, z = -2.0 + 4.0 * i / FLR_N;
            const double y = 0.06 * sin(2.1 * x) * cos(1.7 * z);
            G.flr_v[k][0] = x, G.flr_v[k][1] = y, G.flr_v[k][2] = z;
            /* normal of the height field, not normalised: GL_NORMALIZE is on */
            const double nx = -0.06 * 2.1 * cos(2.1 * x) * cos(1.7 * z);
            const double nz = 0.06 * 1.7 * sin(2.1 * x) * sin(1.7 * z);
            G.flr_n[k][0] = (GLshort)lround(nx * 30000);
            G.flr_n[k][1] = 30000;
            G.flr_n[k][2] = (GLshort)lround(nz * 30000);
        }
    for (int i = 0; i < FLR_N; i++)
        for (int j = 0; j <= FLR_N; j++) {
            /* row i first: counter-clockwise seen from +y */
            G.flr_strip[i][2 * j] = (GLuint)(i * (FLR_N + 1) + j);
            G.flr_strip[i][2 * j + 1] = (GLuint)((i + 1) * (FLR_N + 1) + j);
        }
}

static void demo_geometry(void)
{
    if (G.ready)
        return;
    gen_sphere();
    gen_torus();
    gen_box();
    gen_cylinder();
    gen_floor();
    G.ready = 1;
}

/* ---- drawing ---- */

static void mat(GLenum pname, float r, float g, float b, float a)
{
    lt_mat(GL_FRONT_AND_BACK, pname, r, g, b, a);
}

static void draw_sphere(void)
{
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, G.sph_v);
    glNormalPointer(GL_FLOAT, 0, G.sph_n);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct demo_col), G.sph_c);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    mat(GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 60.0f);
    mat(GL_EMISSION, 0, 0, 0, 1);
    glDrawElements(GL_TRIANGLES, SPH_NI, GL_UNSIGNED_SHORT, G.sph_i);
    glDisable(GL_COLOR_MATERIAL);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
}

static void draw_torus(void)
{
    glInterleavedArrays(GL_N3F_V3F, 0, G.tor);
    mat(GL_AMBIENT, 0.25f, 0.1f, 0.05f, 1);
    mat(GL_DIFFUSE, 0.85f, 0.45f, 0.1f, 1);
    mat(GL_SPECULAR, 0.6f, 0.5f, 0.3f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
    glDrawElements(GL_QUADS, TOR_NI, GL_UNSIGNED_INT, G.tor_i);
}

static void draw_box(void)
{
    glInterleavedArrays(GL_C4F_N3F_V3F, sizeof(struct demo_box_vtx), G.box);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    mat(GL_AMBIENT, 0.1f, 0.1f, 0.15f, 1);
    mat(GL_SPECULAR, 0.3f, 0.3f, 0.3f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 8.0f);
    glShadeModel(GL_FLAT);
    glDrawArrays(GL_QUADS, 0, 24);
    glShadeModel(GL_SMOOTH);
    glDisable(GL_COLOR_MATERIAL);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
}

static void draw_cylinder(void)
{
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_SHORT, sizeof(struct demo_cyl_pos), G.cyl_v);
    glNormalPointer(GL_BYTE, 4, G.cyl_n);
    mat(GL_AMBIENT, 0.05f, 0.2f, 0.1f, 1);
    mat(GL_DIFFUSE, 0.2f, 0.75f, 0.35f, 1);
    mat(GL_SPECULAR, 0.8f, 0.8f, 0.8f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 90.0f);
    glPushMatrix();
    glScalef(0.001f, 0.001f, 0.001f);
    glDrawElements(GL_TRIANGLE_STRIP, CYL_NI, GL_UNSIGNED_BYTE, G.cyl_i);
    glDrawArrays(GL_TRIANGLE_FAN, 2 * (CYL_SL + 1), CYL_SL + 2);
    glDrawArrays(GL_TRIANGLE_FAN, 2 * (CYL_SL + 1) + CYL_SL + 2, CYL_SL + 2);
    glPopMatrix();
    glDisableClientState(GL_NORMAL_ARRAY);
}

static void draw_floor(void)
{
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_DOUBLE, 0, G.flr_v);
    glNormalPointer(GL_SHORT, 0, G.flr_n);
    mat(GL_AMBIENT, 0.15f, 0.15f, 0.2f, 1);
    mat(GL_DIFFUSE, 0.5f, 0.55f, 0.7f, 1);
    mat(GL_SPECULAR, 0.2f, 0.2f, 0.2f, 1);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 4.0f);
    for (int i = 0; i < FLR_N; i++)
        glDrawElements(GL_TRIANGLE_STRIP, 2 * (FLR_N + 1), GL_UNSIGNED_INT, G.flr_strip[i]);
    glDisableClientState(GL_NORMAL_ARRAY);
}

static void arrays_scene(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    demo_geometry();
    glViewport(0, 0, c->width, c->height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    const double aspect = (double)c->width / c->height;
    glFrustum(-0.6 * aspect, 0.6 * aspect, -0.6, 0.6, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_NORMALIZE);
    glEnable(GL_CULL_FACE);
    glClearColor(0.08f, 0.09f, 0.12f, 1.0f);
    lt_model(GL_LIGHT_MODEL_AMBIENT, 0.15f, 0.15f, 0.15f, 1);

    /* GL_LIGHT0: dim directional; GL_LIGHT1: positional, circling, with
    * attenuation; GL_LIGHT2: spot from above-front */
    lt_light(GL_LIGHT0, GL_AMBIENT, 0, 0, 0, 1);
    lt_light(GL_LIGHT0, GL_DIFFUSE, 0.35f, 0.35f, 0.4f, 1);
    lt_light(GL_LIGHT0, GL_SPECULAR, 0.2f, 0.2f, 0.2f, 1);
    lt_light(GL_LIGHT1, GL_AMBIENT, 0.05f, 0.05f, 0.05f, 1);
    lt_light(GL_LIGHT1, GL_DIFFUSE, 1.0f, 0.85f, 0.6f, 1);
    lt_light(GL_LIGHT1, GL_SPECULAR, 1.0f, 1.0f, 0.9f, 1);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.6f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.15f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.05f);
    lt_light(GL_LIGHT2, GL_AMBIENT, 0, 0, 0, 1);
    lt_light(GL_LIGHT2, GL_DIFFUSE, 0.5f, 0.6f, 1.0f, 1);
    lt_light(GL_LIGHT2, GL_SPECULAR, 0.6f, 0.7f, 1.0f, 1);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 28.0f);
    glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 6.0f);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_LIGHT2);

    for (int f = 0; f < DEMO_FRAMES; f++) {
        const float t = (float)f / DEMO_FRAMES;
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        /* camera: distance 3.6, 22 degrees above the floor, orbiting */
        glLoadIdentity();
        glTranslatef(0.0f, -0.1f, -3.6f);
        glRotatef(22.0f + 6.0f * sinf(6.2831853f * t), 1, 0, 0);
        glRotatef(-30.0f + 45.0f * (float)f, 0, 1, 0);
        /* lights in world space */
        lt_light(GL_LIGHT0, GL_POSITION, -0.4f, 1.0f, 0.6f, 0);
        lt_light(GL_LIGHT1, GL_POSITION, 1.6f * cosf(2.1f * (float)f), 0.9f,
                    1.6f * sinf(2.1f * (float)f), 1);
        lt_light(GL_LIGHT2, GL_POSITION, 0.0f, 2.8f, 1.2f, 1);
        const float sd[4] = { 0.0f, -0.92f, -0.39f, 0.0f };
        glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, sd);

        glPushMatrix();
        glTranslatef(0, -0.62f, 0);
        draw_floor();
        glPopMatrix();

        glPushMatrix();
        glTranslatef(-0.9f, 0.0f, -0.6f);
        glRotatef(20.0f * (float)f, 0, 1, 0);
        draw_sphere();
        glPopMatrix();

        glPushMatrix();
        glTranslatef(0.9f, 0.1f, -0.5f);
        glRotatef(70.0f, 1, 0, 0);
        glRotatef(33.0f * (float)f, 0, 0, 1);
        draw_torus();
        glPopMatrix();

        glPushMatrix();
        glTranslatef(0.8f, -0.3f, 0.9f);
        glRotatef(-17.0f * (float)f + 10.0f, 0, 1, 0);
        draw_box();
        glPopMatrix();

        glPushMatrix();
        glTranslatef(-0.7f, -0.17f, 0.9f);
        glRotatef(12.0f * (float)f, 1, 0, 1);
        draw_cylinder();
        glPopMatrix();

        fc_capture(h);
    }
    fc_error(h, "final");
}

/* ---- demo/gears: three gears in display lists ----
 *
 * A clone, written for the suite, of the classic gears demo: each gear is
 * one display list (GL_COMPILE) holding its material and its geometry:
 * flat-shaded faces and teeth (GL_QUAD_STRIP, GL_QUADS, glShadeModel
 * GL_FLAT), the inner cylinder smooth (glShadeModel GL_SMOOTH inside the
 * list); a positional light, lighting, depth test, culling and
 * GL_NORMALIZE; the gears turn over eight frames.  Odd frames draw through
 * a frame list compiled with GL_COMPILE_AND_EXECUTE that calls the gear
 * lists (nesting) under its own transforms; even frames call the gear
 * lists directly. */

#define GEAR_FRAMES 8

/* One gear: inner radius r0, outer radius r1 (at the teeth's middle),
 * width w, n teeth of depth d; front face at z = w/2. */
static void gear(float r0, float r1, float w, int n, float d)
{
    const float ra = r1 - d / 2.0f, rb = r1 + d / 2.0f;   /* teeth root, tip */
    const float da = 2.0f * (float)LT_PI / (float)n / 4.0f;  /* quarter tooth */
    const float hz = 0.5f * w;

    glShadeModel(GL_FLAT);
    glNormal3f(0, 0, 1);
    /* front face: ring from r0 to the teeth root */
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= n; i++) {
        const float a = (float)i * 2.0f * (float)LT_PI / (float)n;
        glVertex3f(r0 * cosf(a), r0 * sinf(a), hz);
        glVertex3f(ra * cosf(a), ra * sinf(a), hz);
        if (i < n) {
            glVertex3f(r0 * cosf(a), r0 * sinf(a), hz);
            glVertex3f(ra * cosf(a + 3 * da), ra * sinf(a + 3 * da), hz);
        }
    }
    glEnd();
    /* front sides of the teeth */
    glBegin(GL_QUADS);
    for (int i = 0; i < n; i++) {
        const float a = (float)i * 2.0f * (float)LT_PI / (float)n;
        glVertex3f(ra * cosf(a), ra * sinf(a), hz);
        glVertex3f(rb * cosf(a + da), rb * sinf(a + da), hz);
        glVertex3f(rb * cosf(a + 2 * da), rb * sinf(a + 2 * da), hz);
        glVertex3f(ra * cosf(a + 3 * da), ra * sinf(a + 3 * da), hz);
    }
    glEnd();

    glNormal3f(0, 0, -1);
    /* back face */
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= n; i++) {
        const float a = (float)i * 2.0f * (float)LT_PI / (float)n;
        glVertex3f(ra * cosf(a), ra * sinf(a), -hz);
        glVertex3f(r0 * cosf(a), r0 * sinf(a), -hz);
        if (i < n) {
            glVertex3f(ra * cosf(a + 3 * da), ra * sinf(a + 3 * da), -hz);
            glVertex3f(r0 * cosf(a), r0 * sinf(a), -hz);
        }
    }
    glEnd();
    /* back sides of the teeth */
    glBegin(GL_QUADS);
    for (int i = 0; i < n; i++) {
        const float a = (float)i * 2.0f * (float)LT_PI / (float)n;
        glVertex3f(ra * cosf(a + 3 * da), ra * sinf(a + 3 * da), -hz);
        glVertex3f(rb * cosf(a + 2 * da), rb * sinf(a + 2 * da), -hz);
        glVertex3f(rb * cosf(a + da), rb * sinf(a + da), -hz);
        glVertex3f(ra * cosf(a), ra * sinf(a), -hz);
    }
    glEnd();

    /* outward faces of the teeth, one normal per face */
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i < n; i++) {
        const float a = (float)i * 2.0f * (float)LT_PI / (float)n;
        float ux = rb * cosf(a + da) - ra * cosf(a), uy = rb * sinf(a + da) - ra * sinf(a);
        const float len = sqrtf(ux * ux + uy * uy);
        ux /= len, uy /= len;
        glVertex3f(ra * cosf(a), ra * sinf(a), hz);
        glVertex3f(ra * cosf(a), ra * sinf(a), -hz);
        glNormal3f(uy, -ux, 0);                       /* rising flank */
        glVertex3f(rb * cosf(a + da), rb * sinf(a + da), hz);
        glVertex3f(rb * cosf(a + da), rb * sinf(a + da), -hz);
        glNormal3f(cosf(a), sinf(a), 0);               /* tip */
        glVertex3f(rb * cosf(a + 2 * da), rb * sinf(a + 2 * da), hz);
        glVertex3f(rb * cosf(a + 2 * da), rb * sinf(a + 2 * da), -hz);
        ux = ra * cosf(a + 3 * da) - rb * cosf(a + 2 * da);
        uy = ra * sinf(a + 3 * da) - rb * sinf(a + 2 * da);
        glNormal3f(uy, -ux, 0);                       /* falling flank */
        glVertex3f(ra * cosf(a + 3 * da), ra * sinf(a + 3 * da), hz);
        glVertex3f(ra * cosf(a + 3 * da), ra * sinf(a + 3 * da), -hz);
        glNormal3f(cosf(a), sinf(a), 0);               /* root */
    }
    glVertex3f(ra, 0, hz);
    glVertex3f(ra, 0, -hz);
    glEnd();

    /* the bore: smooth */
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= n; i++) {
        const float a = (float)i * 2.0f * (float)LT_PI / (float)n;
        glNormal3f(-cosf(a), -sinf(a), 0);
        glVertex3f(r0 * cosf(a), r0 * sinf(a), -hz);
        glVertex3f(r0 * cosf(a), r0 * sinf(a), hz);
    }
    glEnd();
}

static void gear_place(GLuint list, float x, float y, float angle)
{
    glPushMatrix();
    glTranslatef(x, y, 0);
    glRotatef(angle, 0, 0, 1);
    glCallList(list);
    glPopMatrix();
}

static void gears(fc_h *h)
{
    static const GLfloat light_pos[4] = { 5, 5, 10, 0 };
    static const GLfloat red[4] = { 0.8f, 0.1f, 0, 1 }, green[4] = { 0, 0.8f, 0.2f, 1 };
    static const GLfloat blue[4] = { 0.2f, 0.2f, 1, 1 };
    const fc_case *c = fc_this_case(h);
    const float aspect = (float)c->height / (float)c->width;

    glViewport(0, 0, c->width, c->height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -aspect, aspect, 5, 60);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -40);

    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_NORMALIZE);

    glNewList(1, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    gear(1.0f, 4.0f, 1.0f, 20, 0.7f);
    glEndList();
    glNewList(2, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
    gear(0.5f, 2.0f, 2.0f, 10, 0.7f);
    glEndList();
    glNewList(3, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
    gear(1.3f, 2.0f, 0.5f, 10, 0.7f);
    glEndList();
    fc_error(h, "lists compiled");

    glClearColor(0, 0, 0, 1);
    for (int f = 0; f < GEAR_FRAMES; f++) {
        const float angle = 7.0f * (float)f + 3.0f;
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glPushMatrix();
        glRotatef(20.0f + 4.0f * (float)f, 1, 0, 0);
        glRotatef(30.0f - 6.0f * (float)f, 0, 1, 0);
        glRotatef(0.0f, 0, 0, 1);
        if (f & 1) {
            /* a frame list calling the gear lists */
            glNewList(10, GL_COMPILE_AND_EXECUTE);
            gear_place(1, -3.0f, -2.0f, angle);
            gear_place(2, 3.1f, -2.0f, -2.0f * angle - 9.0f);
            gear_place(3, -3.1f, 4.2f, -2.0f * angle - 25.0f);
            glEndList();
        } else {
            gear_place(1, -3.0f, -2.0f, angle);
            gear_place(2, 3.1f, -2.0f, -2.0f * angle - 9.0f);
            gear_place(3, -3.1f, 4.2f, -2.0f * angle - 25.0f);
        }
        glPopMatrix();
        fc_capture(h);
    }
    fc_is_enabled(h, "GL_NORMALIZE", GL_NORMALIZE);
    fc_error(h, "final");
}

/* ---- display lists and client state ----
 *
 * A glColor after the first vertex of a glBegin compiled with
 * GL_COMPILE_AND_EXECUTE makes the list compiler wrap the primitive: what
 * precedes runs at once by loopback (an executed glBegin), the rest (and
 * the executed glEnd) when the list is flushed.  Client-state calls made
 * in between are executed, not compiled, and only the BeginEnd dispatch
 * table would refuse them: during compilation the oracle runs them, with
 * no error.  glGetError has its own check and raises GL_INVALID_OPERATION
 * there.  (Found by the random scenes' display-list path.) */
static void dlist_client_state_after_wrap(fc_h *h)
{
    static const GLfloat v[4][3] = { { 4, 4, 0 }, { 40, 6, 0 }, { 36, 40, 0 }, { 6, 30, 0 } };
    static const GLfloat v2[4][2] = { { 30, 30 }, { 60, 34 }, { 58, 60 }, { 32, 58 } };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE_AND_EXECUTE);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glEnableClientState(GL_VERTEX_ARRAY);
    glBegin(GL_QUADS);
    glArrayElement(0);
    glColor3f(1, 0.5f, 0);          /* a new attribute: the compiler wraps */
    glArrayElement(1);
    glArrayElement(2);
    glArrayElement(3);
    glEnd();
    glDisableClientState(GL_VERTEX_ARRAY);
    fc_is_enabled(h, "vertex array after disable", GL_VERTEX_ARRAY);
    glInterleavedArrays(GL_V2F, 0, v2);
    fc_get_integer(h, "vertex array size", GL_VERTEX_ARRAY_SIZE, 1);
    GLvoid *p = NULL;
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
    fc_value(h, "pointer is v2", p == (const GLvoid *)v2);
    glEnableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glEndList();
    fc_error(h, "after the list");
    glColor3f(0, 0.5f, 1);
    glDrawArrays(GL_QUADS, 0, 4);
    fc_capture(h);

    /* the same list body, with glGetError between the wrapped glEnd and
     * glEndList */
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_QUADS);
    glVertex3fv(v[0]);
    glColor3f(0.2f, 1, 0.2f);
    glVertex3fv(v[1]);
    glVertex3fv(v[2]);
    glVertex3fv(v[3]);
    glEnd();
    fc_error(h, "inside the list, after the wrapped glEnd");
    glEndList();
    fc_error(h, "after the second list");
    glCallList(1);
    fc_capture(h);
    fc_error(h, "final");
}

const fc_case fc_cases_demo[] = {
    FC_CASE_RGBA("demo/arrays_scene", 160, 120, DEMO_FRAMES, "api demo", arrays_scene),
    FC_CASE_RGBA("demo/gears", 160, 128, GEAR_FRAMES, "api demo dlist", gears),
    FC_CASE_RGBA("dlist/client_state_after_wrap", 64, 64, 2, "api varray dlist errors query",
                 dlist_client_state_after_wrap),
    { 0 }
};
