/* c_clip.c - clipping against each of the six planes, crossing the near
 * plane in perspective, w near 0, vertices behind the eye, vertices exactly
 * on clip planes, degenerate triangles and non-finite coordinates. */
#include "cases.h"

#include <math.h>

/* Smooth triangle and quad (depth varying) crossing one clip plane of the
 * ortho box [-1,1]^3 on axis `axis`, side `side` (+1 or -1). */
static void clip_plane(fc_h *h, int axis, float side)
{
    float v[7][3] = {
        { -0.6f, -0.7f, -0.5f }, { 0.7f, -0.4f, 0.3f }, { -0.2f, 0.8f, 0.6f },
        { -0.8f, -0.2f, 0.1f }, { 0.1f, -0.9f, -0.4f }, { 0.6f, 0.5f, 0.2f }, { -0.3f, 0.4f, -0.7f },
    };
    static const float c[7][4] = {
        { 1, 0, 0, 1 }, { 0, 1, 0, 0.5f }, { 0, 0, 1, 1 }, { 1, 1, 0, 1 },
        { 0, 1, 1, 0 }, { 1, 0, 1, 1 }, { 1, 1, 1, 1 },
    };
    v[1][axis] = 1.7f * side;               /* one vertex of the triangle outside */
    v[4][axis] = 2.5f * side;               /* two vertices of the quad outside */
    v[5][axis] = 1.25f * side;
    glViewport(0, 0, 32, 32);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    fcu_clear(0, 0, 0, 0, 0.5);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; i++) { glColor4fv(c[i]); glVertex3fv(v[i]); }
    glEnd();
    glBegin(GL_QUADS);
    for (int i = 3; i < 7; i++) { glColor4fv(c[i]); glVertex3fv(v[i]); }
    glEnd();
    fc_capture(h);
}

static void clip_left(fc_h *h) { clip_plane(h, 0, -1); }
static void clip_right(fc_h *h) { clip_plane(h, 0, 1); }
static void clip_bottom(fc_h *h) { clip_plane(h, 1, -1); }
static void clip_top(fc_h *h) { clip_plane(h, 1, 1); }
/* glOrtho(..., -1, 1): eye z = +1 is the near plane, z = -1 the far one. */
static void clip_near(fc_h *h) { clip_plane(h, 2, 1); }
static void clip_far(fc_h *h) { clip_plane(h, 2, -1); }

/* Perspective triangles crossing the near plane, one vertex behind the eye. */
static void clip_near_perspective(fc_h *h)
{
    glViewport(0, 0, 64, 64);
    fcu_frustum(-0.5, 0.5, -0.5, 0.5, 1, 20);
    glEnable(GL_DEPTH_TEST);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(-2.0f, -1.5f, -4.0f);
    glColor3f(0, 1, 0); glVertex3f(2.0f, -1.0f, -5.0f);
    glColor3f(0, 0, 1); glVertex3f(0.3f, 0.5f, 2.0f);      /* behind the eye */
    glColor3f(1, 1, 0); glVertex3f(-1.0f, 0.2f, -0.5f);    /* between eye and near */
    glColor3f(0, 1, 1); glVertex3f(1.0f, 0.4f, -3.0f);
    glColor3f(1, 0, 1); glVertex3f(-0.5f, 1.5f, -1.0f);    /* exactly on near */
    glEnd();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1); glVertex3f(0, 0, -2);
    glColor3f(1, 0, 0); glVertex3f(3, 0, 1);
    glColor3f(0, 1, 0); glVertex3f(0, 3, 0);
    glColor3f(0, 0, 1); glVertex3f(-3, 0, -25);
    glColor3f(1, 1, 0); glVertex3f(0, -3, 0.5f);
    glColor3f(0, 1, 1); glVertex3f(3, 0, 1);
    glEnd();
    fc_capture(h);
}

/* Clip-space vertices (identity matrices) with w tiny, zero and negative. */
static void clip_w_near_zero(fc_h *h)
{
    static const float w[6] = { 1e-6f, -1e-6f, 0.0f, 1e-30f, -1e-3f, 1e-3f };
    glViewport(0, 0, 32, 32);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    for (int f = 0; f < 2; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glShadeModel(f ? GL_FLAT : GL_SMOOTH);
        for (int i = 0; i < 6; i++) {
            glBegin(GL_TRIANGLES);
            glColor3f(1, 0, 0); glVertex4f(-0.9f, -0.9f, 0.2f, 1.0f);
            glColor3f(0, 1, 0); glVertex4f(0.9f * w[i], -0.2f * w[i], 0.1f * w[i], w[i]);
            glColor3f(0, 0, 1); glVertex4f(-0.5f + 0.25f * (float)i, 0.9f, -0.3f, 1.0f);
            glEnd();
        }
        fc_capture(h);
    }
}

/* Everything behind the eye (w < 0 after projection) and mixed signs. */
static void clip_behind_eye(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_frustum(-1, 1, -1, 1, 1, 10);
    fcu_clear(0.1f, 0.2f, 0.3f, 0.4f, 1);
    glBegin(GL_TRIANGLES);                      /* all behind: mirrors onto the screen if w<0 mishandled */
    glColor3f(1, 0, 0); glVertex3f(-2, -2, 3);
    glColor3f(0, 1, 0); glVertex3f(2, -2, 3);
    glColor3f(0, 0, 1); glVertex3f(0, 2, 3);
    glEnd();
    glBegin(GL_QUADS);                          /* two in front, two behind */
    glColor3f(1, 1, 0); glVertex3f(-1, -1, -2);
    glColor3f(0, 1, 1); glVertex3f(1, -1, -2);
    glColor3f(1, 0, 1); glVertex3f(1, 1, 4);
    glColor3f(1, 1, 1); glVertex3f(-1, 1, 4);
    glEnd();
    fc_capture(h);
}

/* Vertices exactly on the clip planes x, y, z = +-w (identity matrices). */
static void clip_on_planes(fc_h *h)
{
    glViewport(0, 0, 32, 32);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex4f(-2, -2, -2, 2);
    glColor3f(0, 1, 0); glVertex4f(2, -2, 2, 2);
    glColor3f(0, 0, 1); glVertex4f(0, 2, 0, 2);
    glColor3f(1, 1, 0); glVertex4f(-1, 0.5f, 1, 1);
    glColor3f(0, 1, 1); glVertex4f(-0.5f, 1, -1, 1);
    glColor3f(1, 0, 1); glVertex4f(-1, 1, 0.25f, 1);
    glColor3f(1, 1, 1); glVertex4f(3, -3, 3, 3);       /* corner of the cube */
    glColor3f(0.5f, 0.5f, 0.5f); glVertex4f(3, 3, -3, 3);
    glColor3f(0.5f, 0, 0); glVertex4f(0.5f, 0, 0, 3);
    glEnd();
    fc_capture(h);
}

/* A polygon crossing all six planes at once. */
static void clip_all_planes(fc_h *h)
{
    glViewport(0, 0, 48, 48);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_POLYGON);
    glColor3f(1, 0, 0); glVertex3f(-1.8f, -0.3f, 1.6f);
    glColor3f(0, 1, 0); glVertex3f(0.1f, -1.9f, 0.9f);
    glColor3f(0, 0, 1); glVertex3f(1.7f, -0.2f, -1.7f);
    glColor3f(1, 1, 0); glVertex3f(0.2f, 1.6f, -1.2f);
    glColor3f(1, 0, 1); glVertex3f(-1.1f, 1.2f, 1.9f);
    glEnd();
    fc_capture(h);
    fc_error(h, "after polygon");
}

/* Zero-area and incomplete primitives: nothing but the valid ones draws. */
static void degenerate(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    fcu_color(0); fcu_tri(2, 2, 12, 12, 22, 22);               /* collinear */
    fcu_color(1); fcu_tri(5.5f, 5.5f, 5.5f, 5.5f, 5.5f, 5.5f); /* a point */
    fcu_color(2); fcu_tri(3, 20, 3, 20, 15, 28);               /* repeated vertex */
    fcu_color(3); fcu_tri(20.0f, 2.0f, 20.0f + 1.0f / 1024.0f, 30.0f, 20.0f, 30.0f); /* below snap */
    fcu_color(4);
    glBegin(GL_TRIANGLES); glVertex2f(24, 4); glVertex2f(30, 4); glEnd();   /* 2 vertices */
    glBegin(GL_QUADS); glVertex2f(24, 10); glVertex2f(30, 10); glVertex2f(30, 16); glEnd();
    glBegin(GL_POLYGON); glVertex2f(24, 20); glVertex2f(30, 20); glEnd();
    glBegin(GL_QUAD_STRIP); glVertex2f(24, 22); glVertex2f(24, 28); glVertex2f(30, 22); glEnd();
    glBegin(GL_TRIANGLE_STRIP); glVertex2f(1, 30); glVertex2f(5, 30); glEnd();
    glBegin(GL_TRIANGLE_FAN); glVertex2f(10, 30); glEnd();
    glBegin(GL_TRIANGLES); glEnd();                            /* empty */
    fcu_color(5);
    glBegin(GL_TRIANGLES);                                     /* valid + 2 leftover */
    glVertex2f(8, 14); glVertex2f(14, 14); glVertex2f(8, 18); glVertex2f(16, 2); glVertex2f(18, 2);
    glEnd();
    fc_capture(h);
    fc_error(h, "after degenerate primitives");
}

/* NaN, infinities and huge values in vertices, colours and matrices must
 * not crash; the rest of the scene still draws. */
static void non_finite(fc_h *h)
{
    const float nan = NAN, inf = INFINITY;
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(nan, 3); glVertex2f(30, 3); glVertex2f(15, 30);
    glColor3f(0, 1, 0); glVertex2f(2, 2); glVertex2f(inf, 5); glVertex2f(15, 30);
    glColor3f(0, 0, 1); glVertex2f(2, 2); glVertex2f(-inf, 5); glVertex3f(15, 30, inf);
    glColor3f(1, 1, 0); glVertex2f(2, 2); glVertex2f(3.0e38f, 3.0e38f); glVertex2f(2, 30);
    glColor3f(1, 0, 1); glVertex4f(2, 2, 0, nan); glVertex2f(30, 2); glVertex2f(30, 30);
    glColor3f(nan, 0.5f, inf); glVertex2f(4, 20); glVertex2f(12, 20); glVertex2f(8, 28);
    glColor3f(0, 1, 1); glVertex3d(1e300, 2, 0); glVertex3d(20, 20, -1e300); glVertex2d(28, 28);
    glEnd();
    fc_error(h, "after non-finite vertices");
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glScalef(nan, 1, 1);
    glBegin(GL_QUADS);
    glColor3f(1, 1, 1); glVertex2f(20, 20); glVertex2f(28, 20); glVertex2f(28, 28); glVertex2f(20, 28);
    glEnd();
    glPopMatrix();
    glColor3f(0.5f, 0.5f, 0.5f);
    fcu_rect(24, 2, 30, 8, 0);                  /* still draws normally */
    fc_capture(h);
    fc_error(h, "after NaN matrix");
}

/* A vertex exactly at the clip-space origin with w = 0 passes the clip
 * test and projects to NaN: the triangle is rasterized from INT32_MIN
 * snapped coordinates, where the oracle's tile / block coverage decides
 * what is drawn.  Depth test on and off, colour varying (smooth, flat) and
 * constant (set outside glBegin/glEnd), several triangle shapes. */
static void w_zero_vertex(fc_h *h)
{
    static const float tri[4][4] = {
        { 1.5592f / 8.5f - 1.0f, 1.0f - 1.9e-6f / 27.0f, 1.0e-6f / 8.5f - 1.0f, 1.0f - 4.94f / 27.0f },
        { -0.8f, -0.8f, 0.7f, -0.6f },
        { 0.9f, 0.9f, -0.9f, 0.95f },
        { -0.2f, 0.5f, 0.1f, -0.9f },
    };
    glViewport(0, 0, 17, 54);
    for (int frame = 0; frame < 4; frame++) {
        fcu_clear(0.5f, 0.5f, 0.5f, 0.5f, 1);
        if (frame & 1) glEnable(GL_DEPTH_TEST); else glDisable(GL_DEPTH_TEST);
        glShadeModel(frame & 2 ? GL_FLAT : GL_SMOOTH);
        for (int t = 0; t < 4; t++) {
            if (t == 1)
                glColor3f(0.2f, 0.4f, 0.6f);        /* constant colour */
            glBegin(GL_TRIANGLES);
            if (t >= 2) glColor3f(1, 0, 0);
            glVertex4f(tri[t][0], tri[t][1], 0.1f, 1.0f);
            if (t >= 2) glColor3f(0, 1, 0);
            glVertex4f(tri[t][2], tri[t][3], 0.1f, 1.0f);
            if (t >= 2) glColor3f(0, 0, 1);
            glVertex4f(0, 0, 0, 0);
            glEnd();
        }
        fc_capture(h);
    }
}

/* A triangle clipped at the far plane whose other vertices are the w = 0
 * origin and a normal vertex: the clipped polygon has NaN corners, and
 * neither side draws any of it (draws_nothing). */
static void w_zero_clipped(fc_h *h)
{
    glViewport(0, 0, 17, 54);
    fcu_clear(0.8f, 0.84f, 0.87f, 0.59f, 1);
    glEnable(GL_DEPTH_TEST);
    glRotatef(-159.7f, -0.55f, 1.72f, -0.0002f);
    glBegin(GL_TRIANGLES);
    glVertex3f(1, 1, 1.0758f);
    glVertex4f(0, 0, 0, 0);
    glVertex4d(-0.72, 0.955, 0.5566, 0.72);
    glEnd();
    fc_capture(h);
}

/* A w = 0 origin vertex under a scissor box: the triangle's bounding box
 * comes from its finite vertices, so a side of the scissor box beyond it
 * adds no plane, and the NaN edges reach past it; the oracle then writes
 * colour and depth outside the scissor box, up to the framebuffer edge of
 * the 64x64 tiles it bins (found with random-raster/s1-i467, i1873).
 * Scissor boxes around, left of and inside the finite part, a quad strip
 * (flat, quads split 0-1-3) and triangles, depth test on (LESS, ALWAYS)
 * and off. */
static void w_zero_scissor(fc_h *h)
{
    static const int box[4][4] = {
        { -19, 8, 43, 50 }, { 27, 25, 35, 109 }, { 5, 70, 20, 30 }, { 0, 0, 90, 40 },
    };
    for (int frame = 0; frame < 8; frame++) {
        glDisable(GL_SCISSOR_TEST);
        fcu_clear(0.1f, 0.2f, 0.3f, 0.4f, frame & 4 ? 0.5 : 1.0);
        if (frame & 4) glEnable(GL_DEPTH_TEST); else glDisable(GL_DEPTH_TEST);
        glDepthFunc(frame & 1 ? GL_ALWAYS : GL_LESS);     /* NaN depth is 1 */
        const int *b = box[frame & 3];
        glScissor(b[0], b[1], b[2], b[3]);
        glEnable(GL_SCISSOR_TEST);
        glShadeModel(GL_FLAT);
        glColor3f(1, 1, 1);
        glBegin(GL_QUAD_STRIP);
        glVertex4i(0, 0, 0, 0);
        glVertex3d(-0.72, -0.333, -1.0);
        glVertex4d(-0.62, -0.733, -0.587, 0.62);
        glVertex4d(-0.62, -0.733, -0.587, 0.62);
        glEnd();
        glShadeModel(GL_SMOOTH);
        glBegin(GL_TRIANGLES);
        glColor3f(1, 0, 0); glVertex3f(0.56f, 0.67f, -0.9f);
        glColor3f(0, 1, 0); glVertex4f(0.83f, 0.27f, -0.9f, 0.99f);
        glColor3f(0, 0, 1); glVertex4f(0, 0, 0, 0);
        glEnd();
        fc_capture(h);
    }
}

const fc_case fc_cases_clip[] = {
    FC_CASE_RGBA("core/clip_plane_left", 32, 32, 1, "core clip", clip_left),
    FC_CASE_RGBA("core/clip_plane_right", 32, 32, 1, "core clip", clip_right),
    FC_CASE_RGBA("core/clip_plane_bottom", 32, 32, 1, "core clip", clip_bottom),
    FC_CASE_RGBA("core/clip_plane_top", 32, 32, 1, "core clip", clip_top),
    FC_CASE_RGBA("core/clip_plane_near", 32, 32, 1, "core clip depth", clip_near),
    FC_CASE_RGBA("core/clip_plane_far", 32, 32, 1, "core clip depth", clip_far),
    FC_CASE_RGBA("core/clip_near_perspective", 64, 64, 2, "core clip perspective", clip_near_perspective),
    FC_CASE_RGBA("core/clip_w_near_zero", 32, 32, 2, "core clip", clip_w_near_zero),
    FC_CASE_RGBA("core/clip_behind_eye", 32, 32, 1, "core clip perspective", clip_behind_eye),
    FC_CASE_RGBA("core/clip_vertices_on_planes", 32, 32, 1, "core clip", clip_on_planes),
    FC_CASE_RGBA("core/clip_polygon_all_planes", 48, 48, 1, "core clip", clip_all_planes),
    FC_CASE_RGBA("core/degenerate_primitives", 32, 32, 1, "core fill", degenerate),
    FC_CASE_RGBA("core/non_finite_coordinates", 32, 32, 1, "core clip robust", non_finite),
    FC_CASE_RGBA("core/w_zero_vertex", 17, 54, 4, "core clip robust", w_zero_vertex),
    FC_CASE_NODRAW("core/w_zero_clipped", 17, 54, OSMESA_RGBA, 24, 0, 1, "core clip robust", w_zero_clipped),
    FC_CASE("core/w_zero_scissor", 90, 115, OSMESA_RGBA, 24, 0, 8, "core clip robust scissor", w_zero_scissor),
    FC_CASE("core/w_zero_scissor_bgra", 65, 119, OSMESA_BGRA, 16, 8, 8, "core clip robust scissor", w_zero_scissor),
    { 0 }
};
