/* c_eval.c - evaluators: glMap1/glMap2 for the vertex, colour, normal,
 * index and texture-coordinate targets, glEvalCoord, glEvalPoint,
 * glEvalMesh1/2 in every mode, GL_AUTO_NORMAL on lit surfaces, rational
 * (VERTEX_4) maps, custom strides and domains, reversed grids, glGetMap of
 * every query, errors, GL_EVAL_BIT push/pop and evaluators in display
 * lists. */
#include <stdio.h>
#include <string.h>

#include "cases.h"

static void setup(void)
{
    fcu_clear(0.0f, 0.0f, 0.0f, 1.0f, 1.0);
    fcu_ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
}

/* Curves of orders 1..8 and MAX_EVAL_ORDER, as line strips and points. */
static void curve_orders(fc_h *h)
{
    setup();
    glEnable(GL_MAP1_VERTEX_3);
    static const int orders[] = { 1, 2, 3, 4, 5, 6, 7, 8, 30 };
    for (size_t o = 0; o < sizeof orders / sizeof orders[0]; o++) {
        const int n = orders[o];
        GLfloat pts[30 * 3];
        for (int i = 0; i < n; i++) {
            pts[i * 3 + 0] = -0.9f + 1.8f * (float)i / (float)(n > 1 ? n - 1 : 1);
            pts[i * 3 + 1] = -0.9f + 0.2f * (float)o + ((i & 1) ? 0.37f : -0.11f);
            pts[i * 3 + 2] = 0.1f * (float)(i % 3);
        }
        glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, n, pts);
        fcu_color((int)o);
        glMapGrid1f(13 + (int)o, 0.0f, 1.0f);
        glEvalMesh1((o & 1) ? GL_POINT : GL_LINE, 0, 13 + (int)o);
    }
    fc_capture(h);
    fc_error(h, "after curves");
}

/* glEvalMesh1 with partial ranges, reversed grid, a double map with a
 * custom stride and domain, and VERTEX_4 over VERTEX_3. */
static void mesh1_modes(fc_h *h)
{
    setup();
    static const GLdouble cp[4 * 5] = {
        -0.8, -0.8, 0.0, 9, 9,  -0.2, 0.9, 0.0, 9, 9,
        0.4, -0.9, 0.0, 9, 9,   0.9, 0.7, 0.0, 9, 9,
    };
    glMap1d(GL_MAP1_VERTEX_3, 2.0, 5.0, 5, 4, cp);
    glEnable(GL_MAP1_VERTEX_3);
    glColor3f(1.0f, 1.0f, 1.0f);
    glMapGrid1d(20, 2.0, 5.0);
    glEvalMesh1(GL_LINE, 0, 20);
    glColor3f(1.0f, 0.0f, 0.0f);
    glMapGrid1f(9, 5.0f, 2.0f);             /* reversed */
    glEvalMesh1(GL_POINT, 2, 7);
    static const GLfloat cp4[3 * 4] = {
        -0.9f, 0.5f, 0.0f, 1.0f,  0.0f, 1.8f, 0.0f, 2.0f,  0.9f, 0.5f, 0.0f, 1.0f,
    };
    glMap1f(GL_MAP1_VERTEX_4, -1.0f, 1.0f, 4, 3, cp4);
    glEnable(GL_MAP1_VERTEX_4);
    glColor3f(0.0f, 1.0f, 0.0f);
    glMapGrid1f(17, -1.0f, 1.0f);
    glEvalMesh1(GL_LINE, 0, 17);
    glEvalMesh1(GL_LINE, 5, 3);             /* empty range */
    fc_capture(h);
    fc_error(h, "after meshes");
}

/* A bicubic patch, control points z-varied. */
static GLfloat patch[4][4][3];
static void make_patch(void)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            patch[i][j][0] = -0.8f + 0.53f * (float)j;
            patch[i][j][1] = -0.8f + 0.53f * (float)i;
            patch[i][j][2] = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? 0.9f : -0.3f + 0.1f * (float)(i + j);
        }
}

static void surface_modes(fc_h *h)
{
    make_patch();
    static const GLenum modes[3] = { GL_FILL, GL_LINE, GL_POINT };
    for (int m = 0; m < 3; m++) {
        setup();
        glEnable(GL_DEPTH_TEST);
        glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
        glEnable(GL_MAP2_VERTEX_3);
        static const GLfloat col[2][2][4] = {
            { { 1, 0, 0, 1 }, { 0, 1, 0, 1 } }, { { 0, 0, 1, 1 }, { 1, 1, 0, 1 } },
        };
        glMap2f(GL_MAP2_COLOR_4, 0.0f, 1.0f, 4, 2, 0.0f, 1.0f, 8, 2, &col[0][0][0]);
        glEnable(GL_MAP2_COLOR_4);
        glMapGrid2f(8, 0.0f, 1.0f, 6, 0.0f, 1.0f);
        glEvalMesh2(modes[m], 0, 8, 0, 6);
        fc_capture(h);
        fc_get_float(h, "current color", GL_CURRENT_COLOR, 4);
    }
    fc_error(h, "after surfaces");
}

/* Lit surfaces: GL_AUTO_NORMAL on a polynomial and a rational patch, and
 * a GL_MAP2_NORMAL map; orders where u < v, u > v, u == v. */
static void lit_surfaces(fc_h *h)
{
    make_patch();
    for (int variant = 0; variant < 5; variant++) {
        setup();
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        static const GLfloat lpos[4] = { 0.3f, 0.5f, 1.0f, 0.0f };
        glLightfv(GL_LIGHT0, GL_POSITION, lpos);
        glEnable(GL_NORMALIZE);
        glMatrixMode(GL_MODELVIEW);
        glRotatef(25.0f, 1.0f, 0.3f, 0.0f);
        switch (variant) {
        case 0:
            glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
            glEnable(GL_MAP2_VERTEX_3);
            glEnable(GL_AUTO_NORMAL);
            break;
        case 1: /* uorder 3, vorder 4 (u < v) */
            glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 3, &patch[0][0][0]);
            glEnable(GL_MAP2_VERTEX_3);
            glEnable(GL_AUTO_NORMAL);
            break;
        case 2: /* u > v, a 2-wide direction */
            glMap2f(GL_MAP2_VERTEX_3, -1.0f, 2.0f, 3, 2, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
            glEnable(GL_MAP2_VERTEX_3);
            glEnable(GL_AUTO_NORMAL);
            break;
        case 3: { /* rational */
            GLfloat p4[3][3][4];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) {
                    const float w = (i == 1 && j == 1) ? 2.0f : 1.0f;
                    p4[i][j][0] = (-0.8f + 0.8f * (float)j) * w;
                    p4[i][j][1] = (-0.8f + 0.8f * (float)i) * w;
                    p4[i][j][2] = (i == 1 || j == 1 ? 0.6f : -0.2f) * w;
                    p4[i][j][3] = w;
                }
            glMap2f(GL_MAP2_VERTEX_4, 0.0f, 1.0f, 4, 3, 0.0f, 1.0f, 12, 3, &p4[0][0][0]);
            glEnable(GL_MAP2_VERTEX_4);
            glEnable(GL_AUTO_NORMAL);
            break;
        }
        default: { /* a normal map */
            static const GLfloat nrm[2][2][3] = {
                { { -0.5f, -0.5f, 1.0f }, { 0.5f, -0.5f, 1.0f } },
                { { -0.5f, 0.5f, 1.0f }, { 0.5f, 0.5f, 1.0f } },
            };
            glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
            glEnable(GL_MAP2_VERTEX_3);
            glMap2f(GL_MAP2_NORMAL, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 6, 2, &nrm[0][0][0]);
            glEnable(GL_MAP2_NORMAL);
            break;
        }
        }
        glMapGrid2f(10, 0.0f, 1.0f, 10, 0.0f, 1.0f);
        if (variant == 2)
            glMapGrid2f(10, -1.0f, 2.0f, 10, 0.0f, 1.0f);
        glEvalMesh2(GL_FILL, 0, 10, 0, 10);
        fc_capture(h);
        fc_get_float(h, "current normal", GL_CURRENT_NORMAL, 3);
    }
    fc_error(h, "after lit");
}

/* glEvalCoord and glEvalPoint mixed with glVertex inside glBegin/glEnd,
 * colour maps with and without a vertex map, index and texture maps. */
static void eval_coord_mix(fc_h *h)
{
    setup();
    static const GLfloat line[2][3] = { { -0.9f, -0.5f, 0.0f }, { 0.9f, 0.6f, 0.0f } };
    static const GLfloat col[3][4] = { { 1, 0, 0, 1 }, { 0, 1, 0, 0.5f }, { 0, 0, 1, 1 } };
    static const GLfloat idx[2] = { 3.0f, 7.0f };
    static const GLfloat tex[2][2] = { { 0, 0 }, { 1, 1 } };
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &line[0][0]);
    glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 3, &col[0][0]);
    glMap1f(GL_MAP1_INDEX, 0.0f, 1.0f, 1, 2, idx);
    glMap1f(GL_MAP1_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 2, &tex[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glEnable(GL_MAP1_COLOR_4);
    glEnable(GL_MAP1_INDEX);
    glEnable(GL_MAP1_TEXTURE_COORD_2);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_LINE_STRIP);
    glVertex2f(-0.9f, 0.9f);
    glEvalCoord1f(0.25f);
    glVertex2f(0.0f, 0.9f);
    static const GLdouble u[1] = { 0.75 };
    glEvalCoord1dv(u);
    glEvalCoord1d(1.0);
    glVertex2f(0.9f, -0.9f);
    glEnd();
    fc_get_float(h, "current color after", GL_CURRENT_COLOR, 4);
    fc_get_float(h, "current index after", GL_CURRENT_INDEX, 1);
    glMapGrid1f(10, 0.0f, 1.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i <= 10; i += 2)
        glEvalPoint1(i);
    glEnd();
    /* a colour map without a vertex map: nothing drawn */
    glDisable(GL_MAP1_VERTEX_3);
    glBegin(GL_POINTS);
    glEvalCoord1f(0.5f);
    glEnd();
    /* 2D points */
    make_patch();
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2d(5, 0.0, 1.0, 5, 1.0, 0.0);
    glColor3f(1.0f, 0.0f, 1.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i <= 5; i++)
        glEvalPoint2(i, 5 - i);
    static const GLfloat uv[2] = { 0.3f, 0.6f };
    glEvalCoord2fv(uv);
    glEvalCoord2d(0.6, 0.3);
    static const GLdouble uvd[2] = { 0.1, 0.9 };
    glEvalCoord2dv(uvd);
    glEnd();
    fc_capture(h);
    fc_error(h, "after mix");
}

/* Custom strides (ustride/vstride bigger than the components, v-major
 * layout) and domains outside [0, 1], reversed grids, partial meshes. */
static void strides_domains(fc_h *h)
{
    setup();
    GLfloat big[3][4][6];   /* u along the middle index: vstride 6, ustride 24 */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            big[i][j][0] = -0.9f + 0.6f * (float)j;
            big[i][j][1] = -0.9f + 0.9f * (float)i;
            big[i][j][2] = 0.0f;
            big[i][j][3] = big[i][j][4] = big[i][j][5] = 77.0f;
        }
    /* v-major: u is the second index (stride 6), v the first (stride 24) */
    glMap2f(GL_MAP2_VERTEX_3, -2.0f, 3.0f, 6, 4, 10.0f, 4.0f, 24, 3, &big[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glColor3f(0.2f, 0.8f, 1.0f);
    glMapGrid2f(7, 3.0f, -2.0f, 5, 4.0f, 10.0f);
    glEvalMesh2(GL_LINE, 1, 6, 0, 4);
    glColor3f(1.0f, 0.5f, 0.0f);
    glEvalMesh2(GL_FILL, 2, 4, 1, 3);
    glEvalMesh2(GL_FILL, 3, 1, 0, 2);      /* empty */
    fc_capture(h);
    fc_error(h, "after strides");
}

static void get_all(fc_h *h, const char *label, GLenum target)
{
    char l[96];
    GLfloat f[30 * 30 * 4 + 4];
    GLdouble d[30 * 30 * 4 + 4];
    GLint iv[30 * 30 * 4 + 4];
    static const GLenum q[3] = { GL_COEFF, GL_ORDER, GL_DOMAIN };
    static const char *const qn[3] = { "coeff", "order", "domain" };
    for (int k = 0; k < 3; k++) {
        for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) {
            f[i] = -1234.5f;
            d[i] = -1234.5;
            iv[i] = -12345;
        }
        glGetMapfv(target, q[k], f);
        glGetMapdv(target, q[k], d);
        glGetMapiv(target, q[k], iv);
        snprintf(l, sizeof l, "%s %s f", label, qn[k]);
        fc_blob(h, l, f, 64 * sizeof f[0]);
        snprintf(l, sizeof l, "%s %s d", label, qn[k]);
        fc_blob(h, l, d, 64 * sizeof d[0]);
        snprintf(l, sizeof l, "%s %s i", label, qn[k]);
        fc_blob(h, l, iv, 64 * sizeof iv[0]);
    }
}

static const GLenum targets1[9] = {
    GL_MAP1_COLOR_4, GL_MAP1_INDEX, GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_1,
    GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3, GL_MAP1_TEXTURE_COORD_4,
    GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4,
};
static const GLenum targets2[9] = {
    GL_MAP2_COLOR_4, GL_MAP2_INDEX, GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_1,
    GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_TEXTURE_COORD_4,
    GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4,
};

/* glGetMap of every target and query: initial maps, then maps set with
 * strides, doubles (rounded to float), values that lroundf rounds. */
static void get_map(fc_h *h)
{
    char l[64];
    for (int t = 0; t < 9; t++) {
        snprintf(l, sizeof l, "init1 %d", t);
        get_all(h, l, targets1[t]);
        snprintf(l, sizeof l, "init2 %d", t);
        get_all(h, l, targets2[t]);
    }
    GLdouble pts[40 * 6];
    for (int i = 0; i < 40 * 6; i++)
        pts[i] = -7.5 + 0.3 * i + 1e-9 * i;
    for (int t = 0; t < 9; t++) {
        glMap1d(targets1[t], -1.5, 2.5, 6, 3 + t, pts);
        snprintf(l, sizeof l, "set1 %d", t);
        get_all(h, l, targets1[t]);
        glMap2d(targets2[t], 0.5, -3.5, 12, 3, 2.5, 1.49, 5, 2 + (t & 1), pts + t);
        snprintf(l, sizeof l, "set2 %d", t);
        get_all(h, l, targets2[t]);
    }
    fc_get_float(h, "grid1 domain", GL_MAP1_GRID_DOMAIN, 2);
    fc_get_integer(h, "grid1 segments", GL_MAP1_GRID_SEGMENTS, 1);
    glMapGrid2d(3, 0.25, -0.75, 9, 4.5, 1.0);
    fc_get_float(h, "grid2 domain", GL_MAP2_GRID_DOMAIN, 4);
    fc_get_integer(h, "grid2 segments", GL_MAP2_GRID_SEGMENTS, 2);
    fc_get_integer(h, "max order", GL_MAX_EVAL_ORDER, 1);
    fc_error(h, "after gets");
}

/* Every error of glMap, glGetMap, glMapGrid, glEvalMesh, with the state
 * left unchanged. */
static void errors(fc_h *h)
{
    static const GLfloat p[64 * 4] = { 0.5f, 0.25f, 0.125f, 1.0f };
    glMap1f(GL_MAP1_VERTEX_3, 1.0f, 1.0f, 3, 2, p);   fc_error(h, "map1 u1==u2");
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 0, p);   fc_error(h, "map1 order 0");
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 31, p);  fc_error(h, "map1 order 31");
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, NULL); fc_error(h, "map1 null");
    glMap1f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 2, p);   fc_error(h, "map1 map2 target");
    glMap1f(GL_TEXTURE_2D, 0.0f, 1.0f, 3, 2, p);      fc_error(h, "map1 bad target");
    glMap1f(GL_MAP1_VERTEX_4, 0.0f, 1.0f, 3, 2, p);   fc_error(h, "map1 stride");
    glMap1f(GL_TEXTURE_2D, 1.0f, 1.0f, 3, 2, p);      fc_error(h, "map1 order of checks");
    glMap1d(GL_MAP1_NORMAL, 0.0, 1.0, 2, 2, (const GLdouble *)p); fc_error(h, "map1d stride");
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 2, 2, 6, 2, p); fc_error(h, "map2 v1==v2");
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 31, 0, 1, 6, 2, p); fc_error(h, "map2 uorder");
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 0, p); fc_error(h, "map2 vorder");
    glMap2f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, p); fc_error(h, "map2 map1 target");
    glMap2f(GL_MAP2_COLOR_4, 0, 1, 3, 2, 0, 1, 8, 2, p); fc_error(h, "map2 ustride");
    glMap2f(GL_MAP2_COLOR_4, 0, 1, 8, 2, 0, 1, 2, 2, p); fc_error(h, "map2 vstride");
    glMap2f(GL_FOG, 0, 1, 0, 0, 0, 1, 0, 0, p);        fc_error(h, "map2 order first");
    get_all(h, "vertex3 unchanged", GL_MAP1_VERTEX_3);
    get_all(h, "color2 unchanged", GL_MAP2_COLOR_4);
    GLfloat f[4];
    glGetMapfv(GL_TEXTURE_2D, GL_COEFF, f);            fc_error(h, "getmap bad target");
    glGetMapfv(GL_MAP1_INDEX, GL_TEXTURE_2D, f);       fc_error(h, "getmap bad query");
    GLint iv[4];
    glGetMapiv(GL_MAP2_INDEX, GL_MAP2_INDEX, iv);      fc_error(h, "getmapiv bad query");
    glMapGrid1f(0, 0.0f, 1.0f);                        fc_error(h, "grid1 un 0");
    glMapGrid2f(1, 0.0f, 1.0f, -1, 0.0f, 1.0f);        fc_error(h, "grid2 vn -1");
    glMapGrid2f(0, 0.0f, 1.0f, 1, 0.0f, 1.0f);         fc_error(h, "grid2 un 0");
    fc_get_float(h, "grid1 domain", GL_MAP1_GRID_DOMAIN, 2);
    fc_get_integer(h, "grid2 segments", GL_MAP2_GRID_SEGMENTS, 2);
    glEvalMesh1(GL_FILL, 0, 1);                        fc_error(h, "mesh1 fill");
    glEvalMesh2(GL_POLYGON, 0, 1, 0, 1);               fc_error(h, "mesh2 bad mode");
    glEvalMesh1(GL_POINT, 0, 3);                       fc_error(h, "mesh1 disabled");
    glBegin(GL_POINTS);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, p);
    glMapGrid1f(4, 0.0f, 1.0f);
    glEvalMesh1(GL_POINT, 0, 1);
    glGetMapfv(GL_MAP1_VERTEX_3, GL_ORDER, f);
    glEvalCoord1f(0.5f);
    glEvalPoint2(1, 1);
    glEnd();
    fc_error(h, "inside begin end");
    fc_get_float(h, "grid1 domain after", GL_MAP1_GRID_DOMAIN, 2);
    get_all(h, "vertex3 after", GL_MAP1_VERTEX_3);
    /* enables */
    for (int t = 0; t < 9; t++) {
        glEnable(targets1[t]);
        glEnable(targets2[t]);
    }
    glEnable(GL_AUTO_NORMAL);
    for (int t = 0; t < 9; t++) {
        char l[32];
        snprintf(l, sizeof l, "enabled1 %d", t);
        fc_is_enabled(h, l, targets1[t]);
        snprintf(l, sizeof l, "enabled2 %d", t);
        fc_is_enabled(h, l, targets2[t]);
    }
    fc_is_enabled(h, "auto normal", GL_AUTO_NORMAL);
    fc_error(h, "end");
}

/* glPushAttrib(GL_EVAL_BIT) saves the enables and grids, not the maps. */
static void push_pop(fc_h *h)
{
    setup();
    static const GLfloat a[2][3] = { { -0.9f, -0.9f, 0 }, { 0.9f, 0.9f, 0 } };
    static const GLfloat b[2][3] = { { -0.9f, 0.9f, 0 }, { 0.9f, -0.9f, 0 } };
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &a[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(8, 0.0f, 1.0f);
    glPushAttrib(GL_EVAL_BIT);
    glDisable(GL_MAP1_VERTEX_3);
    glEnable(GL_MAP1_VERTEX_4);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid1f(3, 0.2f, 0.8f);
    glMapGrid2f(3, 0.2f, 0.8f, 4, 1.0f, 2.0f);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &b[0][0]);
    fc_is_enabled(h, "v3 pushed", GL_MAP1_VERTEX_3);
    glPopAttrib();
    fc_is_enabled(h, "v3 popped", GL_MAP1_VERTEX_3);
    fc_is_enabled(h, "v4 popped", GL_MAP1_VERTEX_4);
    fc_is_enabled(h, "auto popped", GL_AUTO_NORMAL);
    fc_get_float(h, "grid1", GL_MAP1_GRID_DOMAIN, 2);
    fc_get_integer(h, "grid1 n", GL_MAP1_GRID_SEGMENTS, 1);
    fc_get_float(h, "grid2", GL_MAP2_GRID_DOMAIN, 4);
    glColor3f(1, 1, 0);
    glEvalMesh1(GL_LINE, 0, 8);   /* the b map, the restored grid */
    fc_capture(h);
    fc_error(h, "end");
}

/* glMapGrid and glEvalMesh compiled into display lists (GL_COMPILE). */
static void dlist(fc_h *h)
{
    setup();
    make_patch();
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    static const GLfloat c[2][3] = { { -0.9f, 0.9f, 0 }, { 0.9f, 0.5f, 0 } };
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &c[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glMapGrid2f(6, 0.0f, 1.0f, 6, 0.0f, 1.0f);
    glEvalMesh2(GL_LINE, 0, 6, 0, 6);
    glMapGrid1d(5, 0.0, 1.0);
    glEvalMesh1(GL_POINT, 0, 5);
    glEvalMesh1(GL_FILL, 0, 5);
    glEndList();
    fc_error(h, "after compile");
    fc_get_integer(h, "grid2 n before call", GL_MAP2_GRID_SEGMENTS, 2);
    glColor3f(0.5f, 1.0f, 0.5f);
    glCallList(l);
    fc_error(h, "after call");
    fc_get_integer(h, "grid2 n after call", GL_MAP2_GRID_SEGMENTS, 2);
    fc_capture(h);
}

/* glMap1/glMap2 compiled (the points copied at compile time, with the
 * packed stride at replay; a bad stride is not an error when the list
 * runs), glEvalCoord and glEvalPoint compiled outside and inside
 * glBegin/glEnd mixed with glVertex, GL_COMPILE_AND_EXECUTE. */
static void dlist_maps(fc_h *h)
{
    setup();
    GLfloat pts[4][5];
    for (int i = 0; i < 4; i++) {
        pts[i][0] = -0.9f + 0.6f * (float)i;
        pts[i][1] = (i & 1) ? 0.8f : -0.6f;
        pts[i][2] = 0.0f;
        pts[i][3] = pts[i][4] = 55.0f;
    }
    GLuint l = glGenLists(4);
    glNewList(l, GL_COMPILE);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 5, 4, &pts[0][0]);
    glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 2, 2, &pts[0][0]);   /* stride < 4 */
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 31, &pts[0][0]);  /* error at replay */
    glEndList();
    fc_error(h, "after compile 1");
    for (int i = 0; i < 4; i++)
        pts[i][1] = 0.0f;                /* the list keeps its copy */
    get_all(h, "before call", GL_MAP1_VERTEX_3);
    glCallList(l);
    fc_error(h, "after call 1");
    get_all(h, "after call v3", GL_MAP1_VERTEX_3);
    get_all(h, "after call c4", GL_MAP1_COLOR_4);
    glEnable(GL_MAP1_VERTEX_3);

    static const GLdouble sq[2][2][3] = {
        { { -0.9, -0.9, 0.0 }, { -0.9, 0.9, 0.0 } },
        { { 0.9, -0.9, 0.0 }, { 0.9, 0.9, 0.0 } },
    };
    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    glMap2d(GL_MAP2_VERTEX_3, 0.0, 1.0, 6, 2, 0.0, 1.0, 3, 2, &sq[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glColor3f(0.0f, 0.0f, 1.0f);
    glEvalCoord1f(0.5f);             /* outside glBegin/glEnd */
    glBegin(GL_POINTS);
    glEvalCoord2f(0.25f, 0.25f);
    glEvalPoint2(1, 0);
    glEnd();
    glEndList();
    fc_error(h, "after compile 2");
    get_all(h, "after compile 2", GL_MAP2_VERTEX_3);

    glNewList(l + 2, GL_COMPILE);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_LINE_STRIP);
    glVertex2f(-0.9f, 0.9f);
    glEvalCoord1f(0.3f);
    glVertex2f(0.0f, 0.95f);
    glEvalCoord1d(0.9);
    glEvalPoint1(3);
    glVertex2f(0.9f, -0.9f);
    glEnd();
    glBegin(GL_POINTS);
    glEvalPoint1(1);
    glEvalPoint1(2);
    glEnd();
    glEndList();
    glMapGrid1f(4, 0.0f, 1.0f);
    glCallList(l + 2);
    glCallList(l + 1);
    glNewList(l + 3, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &pts[0][0]);  /* compile error */
    glEnd();
    glEndList();
    glCallList(l + 3);
    fc_error(h, "after calls");
    fc_capture(h);
}

/* GL_COMPILE_AND_EXECUTE: the oracle runs glEvalMesh and glEvalCoord
 * through the current (save) dispatch while compiling, so their glBegin,
 * glEnd and the evaluated glVertex calls are compiled into the list as
 * well, and the list draws them again when called. */
static void dlist_compile_execute(fc_h *h)
{
    setup();
    static const GLfloat c[3][3] = { { -0.9f, -0.2f, 0 }, { 0.0f, 0.9f, 0 }, { 0.9f, -0.2f, 0 } };
    static const GLfloat col[2][4] = { { 1, 0, 0, 1 }, { 0, 1, 1, 1 } };
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 3, &c[0][0]);
    glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 2, &col[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glEnable(GL_MAP1_COLOR_4);
    glMapGrid1f(6, 0.0f, 1.0f);
    GLuint l = glGenLists(3);
    glColor3f(1.0f, 1.0f, 1.0f);
    glNewList(l, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_LINE_STRIP);
    glEvalCoord1f(0.0f);
    glEvalCoord1f(0.4f);
    glVertex2f(0.2f, -0.9f);
    glEvalCoord1f(1.0f);
    glEnd();
    glEndList();
    fc_error(h, "list 1");
    fc_get_float(h, "color after list 1", GL_CURRENT_COLOR, 4);
    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    glEvalMesh1(GL_LINE, 1, 5);
    glEndList();
    fc_error(h, "list 2");
    glNewList(l + 2, GL_COMPILE_AND_EXECUTE);
    glEvalPoint1(2);
    glEvalCoord1f(0.9f);
    glEndList();
    fc_error(h, "list 3");
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0f, -0.5f, 0.0f);
    glColor3f(0.5f, 0.5f, 1.0f);
    glCallList(l);
    glTranslatef(0.0f, 0.2f, 0.0f);
    glCallList(l + 1);
    glCallList(l + 2);
    fc_error(h, "calls");
    fc_get_float(h, "color after calls", GL_CURRENT_COLOR, 4);
    fc_capture(h);
}

/* The slot an attribute gets when glEvalCoord adds it to the vertex
 * format keeps what an earlier format left there: the evaluated colour
 * is restored to that stale value for the following glVertex calls and
 * after glEnd; normals and colours of different formats, a grown colour
 * (3 -> 4 components), and glMap2 without points (queried only). */
static void stale_slots(fc_h *h)
{
    setup();
    glEnable(GL_DEPTH_TEST);
    /* a batch with colour (offset 0) and normal (offset 4) */
    glBegin(GL_TRIANGLES);
    glColor4f(0.25f, 0.5f, 0.75f, 0.625f);
    glNormal3f(0.125f, 0.375f, 0.875f);
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(-0.8f, -1.0f);
    glVertex2f(-1.0f, -0.8f);
    glEnd();
    glDepthFunc(GL_LEQUAL);          /* flushes: the format is emptied */
    static const GLfloat line[2][3] = { { -0.9f, -0.5f, 0.0f }, { 0.9f, 0.6f, 0.0f } };
    static const GLfloat col[2][4] = { { 1, 0, 0, 1 }, { 0, 1, 0, 1 } };
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &line[0][0]);
    glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 2, &col[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glEnable(GL_MAP1_COLOR_4);
    /* normal first (offset 0..2), then the colour joins at 3..6 */
    glBegin(GL_LINE_STRIP);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex2f(-0.9f, 0.9f);
    glEvalCoord1f(0.5f);
    glVertex2f(0.9f, 0.9f);
    glEnd();
    fc_get_float(h, "color after normal format", GL_CURRENT_COLOR, 4);
    fc_get_float(h, "normal after", GL_CURRENT_NORMAL, 3);
    glDepthFunc(GL_LESS);
    /* a 3-component colour grown to 4 by the map */
    glBegin(GL_LINE_STRIP);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex2f(-0.9f, 0.0f);
    glEvalCoord1f(0.25f);
    glVertex2f(0.9f, 0.0f);
    glEnd();
    fc_get_float(h, "color after grown", GL_CURRENT_COLOR, 4);
    /* auto normal only (no vertex map): the normal joins the format */
    glDisable(GL_MAP1_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glBegin(GL_POINTS);
    glColor3f(1.0f, 1.0f, 0.0f);
    glEvalCoord2f(0.5f, 0.5f);
    glVertex2f(0.5f, -0.7f);
    glEnd();
    fc_get_float(h, "normal after auto", GL_CURRENT_NORMAL, 3);
    fc_capture(h);
    glMap2f(GL_MAP2_INDEX, 0.0f, 1.0f, 1, 2, 0.0f, 1.0f, 2, 2, NULL);
    fc_error(h, "map2 null");
    get_all(h, "map2 null", GL_MAP2_INDEX);
    fc_error(h, "end");
}

/* Before any glMapGrid the mesh steps are 0 (Mesa never initialises
 * MapGrid*du/dv): every mesh vertex is at u1 + i1 * 0; glEvalPoint
 * computes its step from the grid. */
static void grid_initial(fc_h *h)
{
    setup();
    static const GLfloat c[3][3] = { { -0.9f, -0.9f, 0 }, { 0.0f, 0.9f, 0 }, { 0.9f, -0.9f, 0 } };
    glMap1f(GL_MAP1_VERTEX_3, -1.0f, 1.0f, 3, 3, &c[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glPointSize(3.0f);
    glColor3f(1.0f, 0.0f, 0.0f);
    glEvalMesh1(GL_POINT, 0, 4);
    glEvalMesh1(GL_LINE, 0, 4);
    glColor3f(0.0f, 1.0f, 0.0f);
    glBegin(GL_POINTS);
    glEvalPoint1(1);
    glEvalPoint1(-1);
    glEnd();
    GLfloat sq[2][2][3] = {
        { { -0.5f, -0.5f, 0.0f }, { -0.5f, 0.5f, 0.0f } },
        { { 0.5f, -0.5f, 0.0f }, { 0.5f, 0.5f, 0.0f } },
    };
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 6, 2, 0.0f, 1.0f, 3, 2, &sq[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glColor3f(0.0f, 0.0f, 1.0f);
    glEvalMesh2(GL_FILL, 0, 3, 0, 3);
    glEvalMesh2(GL_POINT, 0, 3, 0, 3);
    glBegin(GL_POINTS);
    glEvalPoint2(1, 0);
    glEnd();
    fc_capture(h);
    fc_error(h, "end");
}

/* Texture-coordinate maps feed texture unit 0's coordinate (the highest
 * enabled TEXTURE_COORD_n wins), seen in GL_4D_COLOR_TEXTURE feedback and
 * in the current values and the vertex format they leave. */
static void texcoord_maps(fc_h *h)
{
    static GLfloat fb[1024];
    static const GLfloat line[2][3] = { { -0.9f, -0.5f, 0.0f }, { 0.9f, 0.6f, 0.5f } };
    static const GLfloat tc1[3][1] = { { 0.0f }, { 2.5f }, { -1.0f } };
    static const GLfloat tc2[2][2] = { { 0.25f, 1.0f }, { 0.75f, -0.5f } };
    static const GLfloat tc3[2][2][3] = {
        { { 0, 0, 0.5f }, { 1, 0, 0.25f } }, { { 0, 1, 0.125f }, { 1, 1, 1 } } };
    static const GLfloat tc4[2][2][4] = {
        { { 0, 0, 0, 1 }, { 2, 0, 0, 2 } }, { { 0, 3, 1, 1 }, { 1, 1, 1, 0.5f } } };
    setup();
    make_patch();
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 2, &line[0][0]);
    glMap1f(GL_MAP1_TEXTURE_COORD_1, 0.0f, 1.0f, 1, 3, &tc1[0][0]);
    glMap1f(GL_MAP1_TEXTURE_COORD_2, 0.0f, 1.0f, 2, 2, &tc2[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glEnable(GL_MAP1_TEXTURE_COORD_1);
    glMapGrid1f(4, 0.0f, 1.0f);

    glFeedbackBuffer(1024, GL_4D_COLOR_TEXTURE, fb);
    glRenderMode(GL_FEEDBACK);
    glEvalMesh1(GL_LINE, 0, 4);          /* TEXTURE_COORD_1 */
    glEnable(GL_MAP1_TEXTURE_COORD_2);
    glEvalMesh1(GL_POINT, 1, 3);         /* 2 wins over 1 */
    glBegin(GL_LINE_STRIP);
    glTexCoord4f(9, 8, 7, 6);
    glVertex2f(-0.5f, 0.9f);
    glEvalCoord1f(0.375f);               /* the map's coordinate, then back */
    glVertex2f(0.5f, 0.9f);
    glEnd();
    GLint n = glRenderMode(GL_RENDER);
    fc_value(h, "feedback values 1d", n);
    if (n > 0)
        fc_blob(h, "feedback 1d", fb, (size_t)n * sizeof(GLfloat));
    fc_get_float(h, "texcoord after 1d", GL_CURRENT_TEXTURE_COORDS, 4);

    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
    glMap2f(GL_MAP2_TEXTURE_COORD_3, 0.0f, 1.0f, 3, 2, 0.0f, 1.0f, 6, 2, &tc3[0][0][0]);
    glMap2f(GL_MAP2_TEXTURE_COORD_4, 0.0f, 1.0f, 4, 2, 0.0f, 1.0f, 8, 2, &tc4[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_TEXTURE_COORD_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(3, 0.0f, 1.0f, 2, 0.0f, 1.0f);
    glRenderMode(GL_FEEDBACK);
    glEvalMesh2(GL_FILL, 0, 3, 0, 2);    /* TEXTURE_COORD_3 */
    glEnable(GL_MAP2_TEXTURE_COORD_4);
    glEvalMesh2(GL_LINE, 1, 2, 0, 1);    /* 4 wins */
    n = glRenderMode(GL_RENDER);
    fc_value(h, "feedback values 2d", n);
    if (n > 0)
        fc_blob(h, "feedback 2d", fb, (size_t)n * sizeof(GLfloat));
    fc_get_float(h, "texcoord after 2d", GL_CURRENT_TEXTURE_COORDS, 4);
    fc_get_float(h, "normal after 2d", GL_CURRENT_NORMAL, 3);

    /* the same maps rendered (texture coordinates do not change the image
     * while no texture is complete) */
    glEnable(GL_DEPTH_TEST);
    glEvalMesh2(GL_FILL, 0, 3, 0, 2);
    glEvalMesh1(GL_LINE, 0, 4);
    fc_capture(h);
    fc_error(h, "end");
}

const fc_case fc_cases_eval[] = {
    FC_CASE_RGBA("eval/curve_orders", 64, 64, 1, "eval", curve_orders),
    FC_CASE_RGBA("eval/mesh1_modes", 48, 48, 1, "eval", mesh1_modes),
    FC_CASE_RGBA("eval/surface_modes", 48, 48, 3, "eval", surface_modes),
    FC_CASE_RGBA("eval/lit_surfaces", 48, 48, 5, "eval light", lit_surfaces),
    FC_CASE_RGBA("eval/eval_coord_mix", 48, 48, 1, "eval", eval_coord_mix),
    FC_CASE_RGBA("eval/strides_domains", 48, 48, 1, "eval", strides_domains),
    FC_CASE_RGBA("eval/get_map", 8, 8, 0, "eval query", get_map),
    FC_CASE_RGBA("eval/errors", 8, 8, 0, "eval errors query", errors),
    FC_CASE_RGBA("eval/push_pop", 32, 32, 1, "eval attrib", push_pop),
    FC_CASE_RGBA("eval/dlist", 48, 48, 1, "eval dlist", dlist),
    FC_CASE_RGBA("eval/dlist_maps", 48, 48, 1, "eval dlist", dlist_maps),
    FC_CASE_RGBA("eval/grid_initial", 32, 32, 1, "eval", grid_initial),
    FC_CASE_RGBA("eval/stale_slots", 32, 32, 1, "eval", stale_slots),
    FC_CASE_RGBA("eval/dlist_compile_execute", 48, 48, 1, "eval dlist", dlist_compile_execute),
    FC_CASE_RGBA("eval/texcoord_maps", 48, 48, 1, "eval feedback texture", texcoord_maps),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
