/* c_points_lines.c - points and lines (libfixgl/ORACLE-NOTES.md "Line and
 * point rasterization"): point sizes at
 * subpixel positions, every line primitive flat and smooth, wide lines in
 * every octant, the diamond-exit rule at pixel centres and edges, clipping
 * at the frame edges, the near/far planes and w near 0, line stipple across
 * strip segments and loops, lit points and lines, and the errors and queries
 * of glPointSize, glLineWidth and glLineStipple. */
#include <math.h>

#include "cases.h"

/* Subpixel offsets of the point and line positions: pixel centre, the
 * pixel edges, 1/256 either side of them and a few odd fractions. */
static const float offs[] = {
    0.5f, 0.0f, 0.25f, 0.75f, 0.5f - 1.0f / 256, 0.5f + 1.0f / 256,
    1.0f / 256, 1.0f - 1.0f / 256, 0.125f, 0.875f, 0.5f - 1.0f / 512, 0.3f,
};
#define NOFFS (int)(sizeof offs / sizeof offs[0])

/* ---- points --------------------------------------------------------------- */

/* A grid of points of one size: x and y take every subpixel offset, colours
 * distinct per point, on a 12 x 12 raster of cells. */
static void points_grid(fc_h *h, float size)
{
    const float cell = size < 3.0f ? 5.0f : (float)(int)(size + 3.0f);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glPointSize(size);
    glBegin(GL_POINTS);
    for (int j = 0; j < NOFFS; j++) {
        for (int i = 0; i < NOFFS; i++) {
            fcu_color(i + 3 * j);
            glVertex2f(2.0f + cell * (float)i + offs[i], 2.0f + cell * (float)j + offs[j]);
        }
    }
    glEnd();
    fc_capture(h);
}

static void points_size_1(fc_h *h) { points_grid(h, 1.0f); }
static void points_size_1_5(fc_h *h) { points_grid(h, 1.5f); }
static void points_size_2(fc_h *h) { points_grid(h, 2.0f); }
static void points_size_2_5(fc_h *h) { points_grid(h, 2.5f); }
static void points_size_3(fc_h *h) { points_grid(h, 3.0f); }
static void points_size_4(fc_h *h) { points_grid(h, 4.0f); }
static void points_size_7_5(fc_h *h) { points_grid(h, 7.5f); }

/* Sizes between the whole numbers (the .5 rounding of llvmpipe's legacy
 * points goes down), tiny and huge sizes (clamped to 255). */
static void points_odd_sizes(fc_h *h)
{
    static const float sizes[] = { 0.1f, 0.5f, 1.49f, 1.51f, 2.49f, 2.51f, 3.5f,
                                   4.5f, 5.5f, 6.01f, 1e-6f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    for (int i = 0; i < 11; i++) {
        glPointSize(sizes[i]);
        fcu_color(i);
        glBegin(GL_POINTS);
        glVertex2f(5.0f + 11.0f * (float)(i % 5) + 0.3f, 6.0f + 11.0f * (float)(i / 5) + 0.6f);
        glEnd();
    }
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glPointSize(300.0f);
    fcu_color(3);
    glBegin(GL_POINTS);
    glVertex2f(20.25f, 30.75f);
    glEnd();
    fc_capture(h);
}

/* Smooth-shaded points with depth: colours and z from each vertex, the
 * depth test between overlapping wide points. */
static void points_depth(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glPointSize(9.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 24; i++) {
        glColor4f((float)i / 23.0f, 1.0f - (float)i / 29.0f, 0.3f + (float)(i % 5) / 7.0f, 0.5f);
        glVertex3f(4.0f + 2.3f * (float)i, 10.0f + 1.7f * (float)(i % 7), 0.9f - 0.07f * (float)(i % 11));
    }
    glEnd();
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 40; i++) {
        glColor3f((float)(i % 3) / 2.0f, (float)(i % 5) / 4.0f, (float)(i % 7) / 6.0f);
        glVertex3f(1.5f + 1.55f * (float)i, 40.0f + 10.0f * sinf((float)i * 0.4f), -0.9f + 0.045f * (float)i);
    }
    glEnd();
    fc_capture(h);
}

/* Perspective: points in a frustum (1/w != 1: the colour is premultiplied
 * by 1/w and divided again), some outside the near/far planes or the
 * sides (dropped by the centre test). */
static void points_perspective_clip(fc_h *h)
{
    glViewport(0, 0, 64, 64);
    fcu_frustum(-1, 1, -1, 1, 1, 10);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 64; i++) {
        const float z = -0.8f - 0.17f * (float)i;
        const float x = -1.3f + 0.043f * (float)i * (-z);
        const float y = 0.9f * sinf((float)i * 0.7f) * (-z);
        glColor3f((float)(i % 4) / 3.0f, (float)(i % 6) / 5.0f, 0.77f - (float)(i % 3) / 5.0f);
        glVertex3f(x, y, z);
    }
    glEnd();
    fc_capture(h);
}

/* Wide points whose centre is inside the frame but whose square is not,
 * and points just outside (dropped): a smaller viewport does not cut a
 * wide point either. */
static void points_frame_edges(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glPointSize(7.0f);
    glBegin(GL_POINTS);
    fcu_color(0); glVertex2f(0.5f, 0.5f);
    fcu_color(1); glVertex2f(31.5f, 0.25f);
    fcu_color(2); glVertex2f(0.0f, 16.0f);
    fcu_color(3); glVertex2f(32.0f, 16.0f);           /* on the right plane: inside */
    fcu_color(4); glVertex2f(32.01f, 20.0f);          /* outside: dropped */
    fcu_color(5); glVertex2f(16.0f, -0.01f);          /* outside: dropped */
    fcu_color(6); glVertex2f(16.0f, 32.0f);
    fcu_color(7); glVertex2f(31.9f, 31.9f);
    glEnd();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glViewport(8, 8, 16, 16);
    glPointSize(6.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 9; i++) {
        fcu_color(i);
        glVertex2f(3.5f * (float)i, 32.0f - 3.5f * (float)i);
    }
    glEnd();
    fc_capture(h);
}

/* Points with w near 0 and negative w (outside: dropped), and exactly on
 * the clip boundaries. */
static void points_w_near_zero(fc_h *h)
{
    glViewport(0, 0, 64, 64);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    fcu_clear(0, 0, 0, 0, 1);
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 24; i++) {
        const float w = (i % 4 == 0) ? 1e-6f : (i % 4 == 1) ? -0.05f : (i % 4 == 2) ? 0.02f : 1.0f;
        glColor3f(1.0f, (float)i / 23.0f, 0.3f);
        glVertex4f(0.0008f * (float)(i - 12) * w * 40.0f, 0.001f * (float)i * w * 30.0f, 0.0f, w);
    }
    glColor3f(0.0f, 1.0f, 1.0f);
    glVertex4f(1.0f, 0.5f, 0.0f, 1.0f);
    glVertex4f(-0.5f, -1.0f, 1.0f, 1.0f);
    glVertex4f(0.5f, 0.5f, -1.0f, 1.0f);
    glVertex4f(0.25f, 0.5f, 1.0001f, 1.0f);
    glEnd();
    fc_capture(h);
}

/* Flat-shaded points, and the current colour (no colour in the batch). */
static void points_flat(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glShadeModel(GL_FLAT);
    glPointSize(2.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 16; i++) {
        glColor3f((float)i / 15.0f, 0.5f, 1.0f - (float)i / 15.0f);
        glVertex2f(2.25f + 1.9f * (float)i, 2.75f + 1.7f * (float)i);
    }
    glEnd();
    glShadeModel(GL_SMOOTH);
    glColor3f(0.2f, 0.9f, 0.4f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 16; i++)
        glVertex2f(29.75f - 1.9f * (float)i, 2.75f + 1.7f * (float)i);
    glEnd();
    fc_capture(h);
}

/* ---- lines ---------------------------------------------------------------- */

static const float line_v[8][2] = {
    { 3.5f, 4.25f }, { 27.0f, 9.5f }, { 22.3f, 28.0f }, { 5.0f, 20.5f },
    { 14.5f, 14.5f }, { 29.75f, 30.25f }, { 2.0f, 29.0f }, { 16.0f, 2.0f },
};

static void line_prim(fc_h *h, GLenum mode, GLenum shade)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glShadeModel(shade);
    glBegin(mode);
    for (int i = 0; i < 8; i++) {
        glColor4f((float)(i % 3) / 2.0f, (float)(i % 4) / 3.0f, (float)(7 - i) / 7.0f, (float)i / 7.0f);
        glVertex2fv(line_v[i]);
    }
    glEnd();
    fc_capture(h);
    /* the same, 3 pixels wide */
    fcu_clear(0, 0, 0, 0, 1);
    glLineWidth(3.0f);
    glBegin(mode);
    for (int i = 0; i < 8; i++) {
        glColor4f((float)(i % 3) / 2.0f, (float)(i % 4) / 3.0f, (float)(7 - i) / 7.0f, (float)i / 7.0f);
        glVertex2fv(line_v[i]);
    }
    glEnd();
    fc_capture(h);
}

static void lines_smooth(fc_h *h) { line_prim(h, GL_LINES, GL_SMOOTH); }
static void lines_flat(fc_h *h) { line_prim(h, GL_LINES, GL_FLAT); }
static void line_strip_smooth(fc_h *h) { line_prim(h, GL_LINE_STRIP, GL_SMOOTH); }
static void line_strip_flat(fc_h *h) { line_prim(h, GL_LINE_STRIP, GL_FLAT); }
static void line_loop_smooth(fc_h *h) { line_prim(h, GL_LINE_LOOP, GL_SMOOTH); }
static void line_loop_flat(fc_h *h) { line_prim(h, GL_LINE_LOOP, GL_FLAT); }

/* A star of lines from the centre in 24 directions (every octant, the
 * axes and the diagonals), both directions of travel, at one width. */
static void line_star(fc_h *h, float width)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glLineWidth(width);
    glBegin(GL_LINES);
    for (int i = 0; i < 24; i++) {
        const float a = (float)i * (6.2831853f / 24.0f);
        const float r0 = 4.0f, r1 = 28.0f;
        const float cx = 32.3f, cy = 31.6f;
        fcu_color(i);
        if (i & 1) {
            glVertex2f(cx + r1 * cosf(a), cy + r1 * sinf(a));
            glColor3f(0.1f, 0.2f, 0.3f);
            glVertex2f(cx + r0 * cosf(a), cy + r0 * sinf(a));
        } else {
            glVertex2f(cx + r0 * cosf(a), cy + r0 * sinf(a));
            glColor3f(1.0f, 0.9f, 0.8f);
            glVertex2f(cx + r1 * cosf(a), cy + r1 * sinf(a));
        }
    }
    glEnd();
    fc_capture(h);
}

static void lines_width_1(fc_h *h) { line_star(h, 1.0f); }
static void lines_width_2(fc_h *h) { line_star(h, 2.0f); }
static void lines_width_3(fc_h *h) { line_star(h, 3.0f); }
static void lines_width_4(fc_h *h) { line_star(h, 4.0f); }
static void lines_width_5(fc_h *h) { line_star(h, 5.0f); }
static void lines_width_6(fc_h *h) { line_star(h, 6.0f); }
static void lines_width_7(fc_h *h) { line_star(h, 7.0f); }
static void lines_width_8(fc_h *h) { line_star(h, 8.0f); }
static void lines_width_9(fc_h *h) { line_star(h, 9.0f); }
static void lines_width_10(fc_h *h) { line_star(h, 10.0f); }
static void lines_width_0_4(fc_h *h) { line_star(h, 0.4f); }
static void lines_width_1_5(fc_h *h) { line_star(h, 1.5f); }
static void lines_width_2_5(fc_h *h) { line_star(h, 2.5f); }
static void lines_width_3_7(fc_h *h) { line_star(h, 3.7f); }

/* Short lines whose ends sit on pixel centres, pixel edges and 1/256
 * either side (the diamond-exit tests), in all four directions of each
 * axis and along the diagonals. */
static void lines_diamond(fc_h *h)
{
    static const float d[][2] = {
        { 3, 0 }, { -3, 0 }, { 0, 3 }, { 0, -3 }, { 3, 1 }, { -3, -1 }, { 1, 3 }, { -1, -3 },
        { 2, 2 }, { -2, 2 }, { 2, -2 }, { -2, -2 }, { 0.5f, 0 }, { 0, 0.5f }, { 3, -1 }, { -1, 3 },
    };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    for (int j = 0; j < NOFFS; j++) {
        glBegin(GL_LINES);
        for (int i = 0; i < 16; i++) {
            const float x = 4.0f + 7.5f * (float)(i % 8) + offs[j];
            const float y = 4.0f + 8.0f * (float)(i / 8) + 16.0f * (float)(j % 4) + offs[(j + i) % NOFFS];
            fcu_color(i + j);
            glVertex2f(x, y);
            glVertex2f(x + d[i][0], y + d[i][1]);
        }
        glEnd();
        if (j % 4 == 3) {
            fc_capture(h);
            fcu_clear(0, 0, 0, 0, 1);
        }
    }
}

/* Lines across the frame edges (cut by the draw region only when wide),
 * and through the viewport edges of a smaller viewport (clipped there). */
static void lines_frame_edges(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glLineWidth(5.0f);
    glBegin(GL_LINES);
    fcu_color(0); glVertex2f(-10.0f, 3.3f); glColor3f(0.2f, 0.7f, 1.0f); glVertex2f(40.0f, 5.1f);
    fcu_color(1); glVertex2f(0.0f, 0.0f); glColor3f(0.9f, 0.1f, 0.4f); glVertex2f(32.0f, 32.0f);
    fcu_color(2); glVertex2f(31.0f, -20.0f); glColor3f(0.5f, 0.5f, 0.0f); glVertex2f(29.5f, 50.0f);
    fcu_color(3); glVertex2f(1.0f, 15.0f); glColor3f(0.0f, 0.5f, 0.5f); glVertex2f(1.0f, 40.0f);
    fcu_color(4); glVertex2f(-5.0f, 30.5f); glColor3f(1.0f, 1.0f, 1.0f); glVertex2f(37.0f, 31.5f);
    glEnd();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glViewport(6, 6, 20, 20);
    glLineWidth(3.0f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 10; i++) {
        fcu_color(i);
        glVertex2f(-8.0f + 5.3f * (float)i, (i & 1) ? 40.0f : -6.5f + (float)i);
    }
    glEnd();
    fc_capture(h);
}

/* Lines cut by the near and far planes in a frustum (clipped ends get
 * window coordinates without FMA), and lines through w near 0. */
static void lines_clip_near_far(fc_h *h)
{
    glViewport(0, 0, 64, 64);
    fcu_frustum(-1, 1, -1, 1, 1, 8);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_LINES);
    for (int i = 0; i < 16; i++) {
        const float x = -0.9f + 0.12f * (float)i;
        glColor3f(1.0f, (float)i / 15.0f, 0.0f);
        glVertex3f(x * 0.5f, -0.4f + 0.05f * (float)i, -0.3f);                /* before near */
        glColor3f(0.0f, 0.3f, 1.0f - (float)i / 15.0f);
        glVertex3f(x * 9.0f, 0.3f * (float)(i % 5) - 0.2f, -12.0f);           /* beyond far */
    }
    glEnd();
    glLineWidth(2.0f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 12; i++) {
        glColor3f((float)(i % 2), (float)(i % 3) / 2.0f, 0.5f);
        glVertex3f(-1.5f + 0.3f * (float)i, 0.4f * cosf((float)i), -0.2f - 1.2f * (float)i);
    }
    glEnd();
    fc_capture(h);
}

static void lines_w_near_zero(fc_h *h)
{
    glViewport(0, 0, 64, 64);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_LINES);
    for (int i = 0; i < 12; i++) {
        const float w = (i % 3 == 0) ? 1e-6f : (i % 3 == 1) ? -0.05f : 0.02f;
        glColor3f(1.0f, 0.2f, (float)i / 11.0f);
        glVertex4f(-0.8f + 0.1f * (float)i, -0.7f, 0.0f, 1.0f);
        glColor3f(0.0f, 1.0f, 0.5f);
        glVertex4f(0.01f * (float)(i - 6), 0.02f * (float)i, 0.0f, w);
    }
    glEnd();
    fc_capture(h);
}

/* Lines with depth: interpolated z against a depth-tested quad. */
static void lines_depth(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.3f, 0.3f, 0.3f);
    fcu_rect(8.0f, 8.0f, 56.0f, 56.0f, 0.0f);
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    for (int i = 0; i < 16; i++) {
        glColor3f(1.0f, 0.0f, (float)i / 15.0f);
        glVertex3f(2.0f + 3.7f * (float)i, 2.5f, -0.9f + 0.03f * (float)i);
        glColor3f(0.0f, 1.0f, 0.0f);
        glVertex3f(62.0f - 2.9f * (float)i, 61.5f, 0.95f - 0.11f * (float)i);
    }
    glEnd();
    fc_capture(h);
}

/* A long strip and loop: past the 4096-vertex segments of Mesa's vsplit. */
static void lines_long_loop(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < 5000; i++) {
        const float a = (float)i * 0.0123f;
        glColor3f(0.5f + 0.5f * sinf(a * 3.0f), (float)(i % 256) / 255.0f, (float)(i % 7) / 6.0f);
        glVertex2f(32.0f + (4.0f + (float)i / 200.0f) * cosf(a), 32.0f + (4.0f + (float)i / 200.0f) * sinf(a));
    }
    glEnd();
    fc_capture(h);
}

/* Loops and strips longer than Mesa's 512 KiB vertex buffer: the vbo draws
 * a wrapped loop as strips (later sections from their second vertex, the
 * loop's first vertex appended at glEnd) and every section is a new draw
 * (the stipple counter restarts).  Jumping vertices make every segment
 * visible. */
static void lines_wrapped(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < 60000; i++) {
        const float a = (float)i * 2.39996f;
        const float r = 4.0f + (float)(i % 97) * 0.28f;
        glColor3f((float)(i % 5) / 4.0f, (float)(i % 256) / 255.0f, (float)(i % 3) / 2.0f);
        glVertex2f(32.0f + r * cosf(a), 32.0f + r * sinf(a));
    }
    glEnd();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x0f0f);
    for (int k = 0; k < 2; k++) {
        glBegin(k ? GL_LINE_LOOP : GL_LINE_STRIP);
        for (int i = 0; i < 40000; i++) {
            const float t = (float)i / 40000.0f;
            glColor3f(t, 1.0f - t, (float)k);
            glVertex2f(2.0f + 60.0f * t + (float)(i % 2) * 0.01f, k ? 40.0f + 20.0f * t : 6.0f + 20.0f * t);
        }
        glEnd();
    }
    fc_capture(h);
}

/* A line with one end at the clip-space origin with w = 0 (inside every
 * clip plane, window position NaN) is still set up by llvmpipe: its
 * corners snap to INT32_MIN, the corner, box and step arithmetic wraps in
 * 32 bits, and the binned tile / block coverage decides what is drawn,
 * often the whole draw region (found with random-raster/s1-i1249).
 * Widths 1, 3 and 10, either end NaN, x- and y-major other ends, the
 * viewport inside, below and left of the buffer, with and without a
 * scissor box, smooth and flat colours, depth test on. */
static void lines_w_zero_end(fc_h *h)
{
    static const float other[6][4] = {
        { -1.0f, -0.054f, -1.0f, 1.0f },
        { 0.6f, -0.9f, 0.2f, 1.0f },
        { -0.3f, 0.95f, 0.4f, 1.0f },
        { 0.25f, 0.1f, -0.5f, 0.5f },
        { 2.0f, -0.4f, 0.0f, 2.5f },
        { -0.01f, 0.7f, 0.9f, 1.0f },
    };
    static const int vp[3][4] = { { 0, 0, 48, 40 }, { 38, -10, 48, 10 }, { -20, 12, 30, 36 } };
    static const float widths[3] = { 1.0f, 3.0f, 10.0f };
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    for (int frame = 0; frame < 12; frame++) {
        glDisable(GL_SCISSOR_TEST);
        glViewport(0, 0, 63, 42);
        fcu_clear(0.86f, 0.34f, 0.4f, 0.57f, 1);
        const int *v = vp[frame % 3];
        glViewport(v[0], v[1], v[2], v[3]);
        if (frame & 4) {
            glScissor(44, -7, 61, 13);
            glEnable(GL_SCISSOR_TEST);
        }
        glShadeModel(frame & 8 ? GL_FLAT : GL_SMOOTH);
        glLineWidth(widths[(frame / 3) % 3]);
        for (int k = 0; k < 2; k++) {
            const float *o = other[(frame + 3 * k) % 6];
            glBegin(GL_LINES);
            if ((frame + k) & 1) {
                glColor3f(1, 0.9f, 0.3f * k);
                glVertex4f(0, 0, 0, 0);
                glColor3f(0.2f, 0.5f * k, 1);
                glVertex4fv(o);
            } else {
                glColor3f(0.2f, 0.5f * k, 1);
                glVertex4fv(o);
                glColor3f(1, 0.9f, 0.3f * k);
                glVertex4f(0, 0, 0, 0);
            }
            glEnd();
        }
        fc_capture(h);
    }
}

/* Robustness: w = 0 exactly (no outcode, non-finite window coordinates),
 * NaN and huge coordinates, the largest width and size. */
static void robust_points_lines(fc_h *h)
{
    glViewport(0, 0, 128, 128);
    fcu_ortho(-1, 1, -1, 1, -1, 1);
    fcu_clear(0, 0, 0, 0, 1);
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    glColor3f(1, 0, 0);
    glVertex4f(0.0f, 0.0f, 0.0f, 0.0f);
    glVertex4f(NAN, 0.5f, 0.0f, 1.0f);
    glVertex4f(0.5f, 0.5f, 0.0f, 1.0f);
    glEnd();
    glBegin(GL_LINES);
    glColor3f(0, 1, 0);
    glVertex4f(0.0f, 0.0f, 0.0f, 0.0f);
    glVertex4f(0.5f, -0.5f, 0.0f, 1.0f);
    glVertex4f(NAN, 0.2f, 0.0f, 1.0f);
    glVertex4f(0.5f, -0.7f, 0.0f, 1.0f);
    glVertex4f(-1e30f, -0.3f, 0.0f, 1.0f);
    glVertex4f(1e30f, -0.2f, 0.0f, 1.0f);
    glVertex4f(-0.9f, 0.9f, 0.0f, 1.0f);
    glVertex4f(-0.9f, 0.9f, 0.0f, 1.0f);     /* zero length */
    glEnd();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glLineWidth(255.0f);
    glBegin(GL_LINES);
    glColor3f(0, 0, 1); glVertex2f(-0.9f, -0.95f);
    glColor3f(1, 1, 0); glVertex2f(0.9f, 0.95f);
    glEnd();
    glPointSize(255.0f);
    glBegin(GL_POINTS);
    glColor3f(1, 0, 1); glVertex2f(0.7f, -0.7f);
    glEnd();
    fc_capture(h);
    /* NaN size and width are accepted (Mesa only rejects <= 0) */
    fcu_clear(0, 0, 0, 0, 1);
    glPointSize(NAN); fc_error(h, "glPointSize(NaN)");
    glLineWidth(NAN); fc_error(h, "glLineWidth(NaN)");
    glBegin(GL_POINTS);
    glColor3f(1, 0.5f, 0); glVertex2f(0.3f, 0.3f);
    glEnd();
    glBegin(GL_LINES);
    glColor3f(0, 0.5f, 1); glVertex2f(-0.8f, 0.1f); glVertex2f(0.8f, 0.4f);
    glEnd();
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_LINE_SMOOTH);
    glBegin(GL_POINTS);
    glColor3f(1, 0.5f, 0); glVertex2f(-0.3f, -0.3f);
    glEnd();
    glBegin(GL_LINES);
    glColor3f(0, 0.5f, 1); glVertex2f(-0.8f, -0.1f); glVertex2f(0.8f, -0.4f);
    glEnd();
    glDisable(GL_POINT_SMOOTH);
    glDisable(GL_LINE_SMOOTH);
    fc_capture(h);
    glPointSize(255.0f);
    glLineWidth(255.0f);
    /* smooth: zero-length and tiny lines, the largest point, w = 0 */
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    glLineWidth(4.0f);
    glBegin(GL_LINES);
    glColor4f(1, 1, 0, 0.9f);
    glVertex2f(-0.5f, 0.5f); glVertex2f(-0.5f, 0.5f);
    glVertex2f(0.5f, 0.5f); glVertex2f(0.501f, 0.502f);
    glVertex4f(0.0f, 0.0f, 0.0f, 0.0f); glVertex2f(0.2f, 0.2f);
    glEnd();
    glBegin(GL_POINTS);
    glColor4f(0, 1, 1, 0.7f);
    glVertex2f(0.1f, -0.3f);
    glVertex4f(0.0f, 0.0f, 0.0f, 0.0f);
    glEnd();
    fc_capture(h);
}

/* ---- stipple -------------------------------------------------------------- */

static void stipple_strip(fc_h *h, int factor, GLushort pattern, GLenum mode)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(factor, pattern);
    for (int k = 0; k < 3; k++) {
        glBegin(mode);
        for (int i = 0; i < 7; i++) {
            glColor3f((float)(i % 2), (float)k / 2.0f, (float)i / 6.0f);
            glVertex2f(3.3f + 9.1f * (float)i, 6.0f + 20.0f * (float)k + ((i & 1) ? 9.7f : 0.4f));
        }
        glEnd();
    }
    fc_capture(h);
}

static void stipple_strip_f1(fc_h *h) { stipple_strip(h, 1, 0x0f0f, GL_LINE_STRIP); }
static void stipple_strip_f2(fc_h *h) { stipple_strip(h, 2, 0x3c5b, GL_LINE_STRIP); }
static void stipple_strip_f3(fc_h *h) { stipple_strip(h, 3, 0xaaaa, GL_LINE_STRIP); }
static void stipple_loop_f2(fc_h *h) { stipple_strip(h, 2, 0x1337, GL_LINE_LOOP); }
static void stipple_lines_f1(fc_h *h) { stipple_strip(h, 1, 0x00ff, GL_LINES); }

/* Stipple with wide and flat-shaded lines, a pattern of all ones (no
 * stippling), and a clipped strip (clipping comes first). */
static void stipple_mixed(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x7777);
    glLineWidth(3.0f);
    glShadeModel(GL_FLAT);
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < 6; i++) {
        fcu_color(i);
        glVertex2f(32.0f + 24.0f * cosf((float)i * 1.047f), 32.0f + 24.0f * sinf((float)i * 1.047f));
    }
    glEnd();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glShadeModel(GL_SMOOTH);
    glLineWidth(1.0f);
    glLineStipple(4, 0xffff);
    glBegin(GL_LINES);
    glColor3f(1, 0, 0); glVertex2f(2.0f, 2.0f);
    glColor3f(0, 1, 0); glVertex2f(60.0f, 30.0f);
    glEnd();
    glLineStipple(2, 0x5f5f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 8; i++) {
        glColor3f((float)(i % 2), 0.5f, (float)i / 7.0f);
        glVertex2f(-20.0f + 14.0f * (float)i, 40.0f + ((i & 1) ? 20.0f : -5.0f));
    }
    glEnd();
    fc_capture(h);
}

/* What restarts the stipple counter between primitives: a strip whose
 * first segment is clipped away continues the count, unless a smooth point,
 * a point of a draw that needs clipping or a triangle taking draw's
 * pipeline (two-sided lighting with stipple on) passed the stipple stage in
 * between; plain points of an unclipped draw do not. */
static void stipple_counter_resets(fc_h *h)
{
    fc_pixel_ortho(h);
    for (int f = 0; f < 3; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glEnable(GL_LINE_STIPPLE);
        glLineStipple(1, 0x1f3f);
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 1, 0);
        glVertex2f(2.0f, 4.0f); glVertex2f(61.0f, 4.0f); glVertex2f(61.0f, 9.3f);
        glEnd();
        if (f == 0) {
            glEnable(GL_POINT_SMOOTH);
            glPointSize(3.0f);
        }
        if (f == 1) {
            static const float pos[4] = { 0.0f, 0.0f, 1.0f, 0.0f };
            glEnable(GL_LIGHTING);
            glEnable(GL_LIGHT0);
            glLightfv(GL_LIGHT0, GL_POSITION, pos);
            glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
            fcu_tri(10.0f, 20.0f, 20.0f, 30.0f, 30.0f, 20.0f);   /* clockwise */
            glDisable(GL_LIGHTING);
        } else {
            glBegin(GL_POINTS);
            glColor3f(0, 1, 1);
            glVertex2f(32.0f, 32.0f);
            glEnd();
        }
        if (f == 2) {
            /* plain points, one of them outside: the draw takes the
             * pipeline, and the visible point restarts the counter */
            glLineStipple(1, 0x3f1f);
            glBegin(GL_LINE_STRIP);
            glColor3f(1, 1, 0);
            glVertex2f(2.0f, 14.0f); glVertex2f(61.0f, 14.0f); glVertex2f(61.0f, 19.3f);
            glEnd();
            glBegin(GL_POINTS);
            glColor3f(0, 1, 1);
            glVertex2f(40.0f, 32.0f);
            glVertex2f(-40.0f, 32.0f);
            glEnd();
            glBegin(GL_LINE_STRIP);
            glColor3f(1, 0, 1);
            glVertex2f(-30.0f, 40.0f); glVertex2f(-2.0f, 40.0f); glVertex2f(61.5f, 40.0f);
            glVertex2f(3.5f, 45.0f);
            glEnd();
        }
        glDisable(GL_POINT_SMOOTH);
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 0, 1);
        glVertex2f(-30.0f, 50.0f); glVertex2f(-2.0f, 50.0f); glVertex2f(61.5f, 50.0f);
        glVertex2f(3.5f, 58.0f);
        glEnd();
        fc_capture(h);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
    }
    /* triangles: a draw with a clipped triangle takes the pipeline and its
     * visible triangle restarts the counter (frame 4); an unclipped draw
     * goes straight to llvmpipe and does not (frame 5); with culling, a
     * culled triangle does not (frame 6) */
    for (int f = 0; f < 3; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glLineStipple(1, 0x1f3f);
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 1, 0);
        glVertex2f(2.0f, 4.0f); glVertex2f(61.0f, 4.0f); glVertex2f(61.0f, 9.3f);
        glEnd();
        if (f == 2) {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
        }
        glColor3f(0.3f, 0.6f, 0.9f);
        glBegin(GL_TRIANGLES);
        if (f == 2) {     /* clockwise: culled */
            glVertex2f(10.0f, 20.0f); glVertex2f(20.0f, 30.0f); glVertex2f(30.0f, 20.0f);
        } else {
            glVertex2f(10.0f, 20.0f); glVertex2f(30.0f, 20.0f); glVertex2f(20.0f, 30.0f);
        }
        if (f != 1) {
            glVertex2f(-10.0f, 20.0f); glVertex2f(-30.0f, 20.0f); glVertex2f(-20.0f, 30.0f);
        }
        glEnd();
        glDisable(GL_CULL_FACE);
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 0, 1);
        glVertex2f(-30.0f, 50.0f); glVertex2f(-2.0f, 50.0f); glVertex2f(61.5f, 50.0f);
        glVertex2f(3.5f, 58.0f);
        glEnd();
        fc_capture(h);
    }
    /* vsplit segments (frame 7): 1365 triangles outside the view fill the
     * first 4095-vertex segment of a GL_TRIANGLES draw; the visible one
     * after them is in an unclipped segment, straight to llvmpipe: no
     * restart.  The same with 1364 outside triangles puts it in the
     * clipped segment (frame 8): restart. */
    for (int f = 0; f < 2; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 1, 0);
        glVertex2f(2.0f, 4.0f); glVertex2f(61.0f, 4.0f); glVertex2f(61.0f, 9.3f);
        glEnd();
        glColor3f(0.3f, 0.6f, 0.9f);
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 1365 - f; i++) {
            glVertex2f(-10.0f, 20.0f); glVertex2f(-30.0f, 20.0f); glVertex2f(-20.0f, 30.0f);
        }
        glVertex2f(10.0f, 20.0f); glVertex2f(30.0f, 20.0f); glVertex2f(20.0f, 30.0f);
        glEnd();
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 0, 1);
        glVertex2f(-30.0f, 50.0f); glVertex2f(-2.0f, 50.0f); glVertex2f(61.5f, 50.0f);
        glVertex2f(3.5f, 58.0f);
        glEnd();
        fc_capture(h);
    }
    /* fans: up to 4096 vertices one segment (frame 9: the back faces
     * around an outside vertex put the whole fan in the pipeline, its front
     * faces restart the counter); longer ones in segments of 1024 (frame
     * 10: the first segment holds the outside vertex and only back faces,
     * culled; the others, vertex 0 and vertices 1023 on, are inside and
     * front-facing, straight to llvmpipe: no restart; frame 11: the rim
     * turns at vertex 900, front faces in the clipped segment: restart). */
    for (int f = 0; f < 3; f++) {
        const int turn = f == 2 ? 900 : 1023;
        const int nv = f == 0 ? 1400 : 5000;
        fcu_clear(0, 0, 0, 0, 1);
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 1, 0);
        glVertex2f(2.0f, 4.0f); glVertex2f(61.0f, 4.0f); glVertex2f(61.0f, 9.3f);
        glEnd();
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glColor3f(0.3f, 0.6f, 0.9f);
        glBegin(GL_TRIANGLE_FAN);
        glVertex2f(32.0f, 28.0f);
        for (int i = 1; i < nv; i++) {
            /* clockwise (back) up to `turn`, then counter-clockwise */
            const float a = i <= turn ? 3.0f - 0.002f * (float)i
                                      : 3.0f - 0.002f * (float)turn + 0.001f * (float)(i - turn);
            const float r = i == 5 ? 200.0f : 14.0f;
            glVertex2f(32.0f + r * cosf(a), 28.0f + r * sinf(a));
        }
        glEnd();
        glDisable(GL_CULL_FACE);
        glBegin(GL_LINE_STRIP);
        glColor3f(1, 0, 1);
        glVertex2f(-30.0f, 50.0f); glVertex2f(-2.0f, 50.0f); glVertex2f(61.5f, 50.0f);
        glVertex2f(3.5f, 58.0f);
        glEnd();
        fc_capture(h);
    }
}

/* ---- lit points and lines -------------------------------------------------- */

static void lit_points_lines(fc_h *h)
{
    static const float pos[4] = { 0.3f, 0.5f, 1.0f, 0.0f };
    static const float diff[4] = { 0.9f, 0.7f, 0.2f, 1.0f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diff);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 16; i++) {
        glNormal3f(cosf((float)i * 0.4f), sinf((float)i * 0.4f), (float)(i % 3) - 1.0f);
        glVertex2f(3.5f + 3.7f * (float)i, 5.5f);
    }
    glEnd();
    glLineWidth(2.0f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 12; i++) {
        glNormal3f(sinf((float)i * 0.5f), 0.3f, cosf((float)i * 0.5f));
        glVertex2f(3.0f + 5.0f * (float)i, 20.0f + ((i & 1) ? 12.0f : 0.0f));
    }
    glEnd();
    glShadeModel(GL_FLAT);
    glBegin(GL_LINES);
    for (int i = 0; i < 8; i++) {
        glNormal3f(0.0f, (float)i / 7.0f, 1.0f - (float)i / 7.0f);
        glVertex2f(3.0f + 7.0f * (float)i, 40.0f);
        glNormal3f(1.0f, 0.0f, (float)i / 7.0f);
        glVertex2f(7.0f + 7.0f * (float)i, 60.0f);
    }
    glEnd();
    fc_capture(h);

    /* perspective, separate specular, a positional light; lines through
     * the near plane (lit colours lerped by the clipper), stippled strips
     * and points */
    {
        static const float lpos[4] = { 0.5f, 1.0f, 0.5f, 1.0f };
        static const float spec[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
        glViewport(0, 0, 64, 64);
        fcu_frustum(-1, 1, -1, 1, 1, 20);
        fcu_clear(0, 0, 0, 0, 1);
        glShadeModel(GL_SMOOTH);
        glEnable(GL_DEPTH_TEST);
        glLightfv(GL_LIGHT0, GL_POSITION, lpos);
        glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12.0f);
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
        glBegin(GL_LINES);
        for (int i = 0; i < 12; i++) {
            glNormal3f(0.1f * (float)i, 1.0f, 0.3f);
            glVertex3f(-1.0f + 0.18f * (float)i, -0.6f, 0.5f);
            glNormal3f(0.0f, 0.5f, 1.0f);
            glVertex3f(-3.0f + 0.5f * (float)i, 0.4f, -8.0f);
        }
        glEnd();
        glEnable(GL_LINE_STIPPLE);
        glLineStipple(2, 0x6db6);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i < 10; i++) {
            glNormal3f(sinf((float)i), cosf((float)i), 0.5f);
            glVertex3f(-2.0f + 0.45f * (float)i, 0.8f - 0.1f * (float)i, -2.0f - 0.9f * (float)i);
        }
        glEnd();
        glPointSize(2.0f);
        glBegin(GL_POINTS);
        for (int i = 0; i < 20; i++) {
            glNormal3f(cosf((float)i * 0.3f), 0.4f, sinf((float)i * 0.3f));
            glVertex3f(-1.5f + 0.15f * (float)i, -0.2f, -1.5f - 0.4f * (float)i);
        }
        glEnd();
        fc_capture(h);
    }
}

/* ---- smooth points and lines (no blending: the coverage shows in the
 * alpha channel; raster/smooth_blend_* blend) ------------------------------- */

static void points_smooth(fc_h *h)
{
    static const float sizes[] = { 1.0f, 2.0f, 2.5f, 3.0f, 4.0f, 5.5f, 7.5f, 9.0f, 12.0f, 15.0f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_POINT_SMOOTH);
    for (int i = 0; i < 10; i++) {
        glPointSize(sizes[i]);
        glBegin(GL_POINTS);
        for (int j = 0; j < 4; j++) {
            glColor4f((float)i / 9.0f, (float)j / 3.0f, 0.6f, j & 1 ? 1.0f : 0.5f);
            glVertex2f(8.0f + 16.0f * (float)j + offs[(i + j) % NOFFS],
                       6.0f + 12.5f * (float)i + offs[(3 * i + j) % NOFFS]);
        }
        glEnd();
    }
    fc_capture(h);
}

static void points_smooth_perspective(fc_h *h)
{
    glViewport(0, 0, 64, 64);
    fcu_frustum(-1, 1, -1, 1, 1, 10);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_POINT_SMOOTH);
    glShadeModel(GL_FLAT);
    glPointSize(6.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 40; i++) {
        const float z = -1.2f - 0.2f * (float)i;
        glColor4f((float)(i % 4) / 3.0f, (float)(i % 6) / 5.0f, 0.7f, 0.3f + (float)(i % 3) * 0.3f);
        glVertex3f((-0.9f + 0.045f * (float)i) * (-z), 0.7f * sinf((float)i) * (-z), z);
    }
    glEnd();
    fc_capture(h);
}

static void lines_smooth_aa(fc_h *h, float width)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LINE_SMOOTH);
    glLineWidth(width);
    glBegin(GL_LINES);
    for (int i = 0; i < 16; i++) {
        const float a = (float)i * (6.2831853f / 16.0f) + 0.1f;
        glColor4f(1.0f, (float)i / 15.0f, 0.2f, 1.0f);
        glVertex2f(32.0f + 5.0f * cosf(a), 32.0f + 5.0f * sinf(a));
        glColor4f(0.2f, 0.4f, 1.0f, 0.6f);
        glVertex2f(32.0f + 28.0f * cosf(a), 32.0f + 28.0f * sinf(a));
    }
    glEnd();
    fc_capture(h);
}

static void lines_smooth_w1(fc_h *h) { lines_smooth_aa(h, 1.0f); }
static void lines_smooth_w1_5(fc_h *h) { lines_smooth_aa(h, 1.5f); }
static void lines_smooth_w3(fc_h *h) { lines_smooth_aa(h, 3.0f); }
static void lines_smooth_w6(fc_h *h) { lines_smooth_aa(h, 6.0f); }

/* Smooth strips and loops: flat shading, very short segments (half length
 * doubled instead of extended), stipple with rectangular lengths, and
 * clipped ends. */
static void lines_smooth_mixed(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LINE_SMOOTH);
    glShadeModel(GL_FLAT);
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < 7; i++) {
        fcu_color(i);
        glVertex2f(32.0f + 20.0f * cosf((float)i * 0.9f), 32.0f + 20.0f * sinf((float)i * 0.9f));
    }
    glEnd();
    glShadeModel(GL_SMOOTH);
    glBegin(GL_LINES);
    for (int i = 0; i < 8; i++) {
        glColor4f(1.0f, 1.0f, (float)i / 7.0f, 1.0f);
        glVertex2f(4.0f + 7.0f * (float)i, 4.0f);
        glVertex2f(4.0f + 7.0f * (float)i + 0.1f * (float)i, 4.0f + 0.05f * (float)i);
    }
    glEnd();
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x33ff);
    glLineWidth(2.0f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 9; i++) {
        glColor4f((float)(i % 2), 0.5f, (float)i / 8.0f, 0.8f);
        glVertex2f(-10.0f + 10.0f * (float)i, 32.0f + ((i & 1) ? 25.0f : -20.0f));
    }
    glEnd();
    fc_capture(h);
}

/* Smooth points and lines with two-sided lighting: the draw module's quads
 * use its no-cull rasterizer, so the front colour on every quad. */
static void smooth_lit_twoside(fc_h *h)
{
    static const float pos[4] = { -0.3f, 0.5f, 1.0f, 0.0f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glEnable(GL_CULL_FACE);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_LINE_SMOOTH);
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 8; i++) {
        glNormal3f(cosf((float)i), sinf((float)i), 0.5f);
        glVertex2f(5.0f + 7.5f * (float)i, 8.0f);
    }
    glEnd();
    glLineWidth(2.0f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 8; i++) {
        glNormal3f(sinf((float)i), 0.2f, cosf((float)i));
        glVertex2f(5.0f + 7.5f * (float)i, 30.0f + ((i & 1) ? 20.0f : 0.0f));
    }
    glEnd();
    fc_capture(h);
}

/* ---- many pseudo-random points and lines (a fixed LCG, so the same
 * calls reach both renderers) ---------------------------------------------- */

static unsigned lcg_next(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static float lcg_float(unsigned *s, float lo, float hi)
{
    return lo + (hi - lo) * (float)(lcg_next(s) & 0xffff) / 65536.0f;
}

/* mode 0: lines, 1: points, 2: stippled strips, 3: smooth lines and points */
static void random_prims(fc_h *h, int mode)
{
    unsigned seed = 12345u + (unsigned)mode * 777u;
    fc_pixel_ortho(h);
    for (int frame = 0; frame < 4; frame++) {
        fcu_clear(0, 0, 0, 0, 1);
        if (mode == 2)
            glEnable(GL_LINE_STIPPLE);
        if (mode == 3) {
            glEnable(GL_LINE_SMOOTH);
            glEnable(GL_POINT_SMOOTH);
        }
        for (int n = 0; n < 60; n++) {
            const float width = (lcg_next(&seed) & 3) == 0 ? lcg_float(&seed, 0.5f, 8.0f)
                                                            : (float)(1 + lcg_next(&seed) % 6);
            glLineWidth(width);
            glPointSize(width);
            glShadeModel(lcg_next(&seed) & 1 ? GL_FLAT : GL_SMOOTH);
            if (mode == 2)
                glLineStipple((int)(1 + lcg_next(&seed) % 3), (GLushort)lcg_next(&seed));
            const GLenum prim = mode == 1 ? GL_POINTS
                              : mode == 2 ? (lcg_next(&seed) & 1 ? GL_LINE_STRIP : GL_LINE_LOOP)
                              : mode == 3 ? (lcg_next(&seed) & 1 ? GL_POINTS : GL_LINES)
                              : GL_LINES;
            const int nv = mode == 2 ? 3 + (int)(lcg_next(&seed) % 4) : 2;
            glBegin(prim);
            for (int i = 0; i < nv; i++) {
                glColor4f(lcg_float(&seed, 0, 1), lcg_float(&seed, 0, 1), lcg_float(&seed, 0, 1),
                          lcg_float(&seed, 0.2f, 1));
                const float x = (float)(lcg_next(&seed) % (72 * 16)) / 16.0f - 4.0f;
                const float y = (float)(lcg_next(&seed) % (72 * 16)) / 16.0f - 4.0f;
                glVertex3f(x, y, lcg_float(&seed, -1, 1));
            }
            glEnd();
        }
        fc_capture(h);
    }
}

static void random_lines(fc_h *h) { random_prims(h, 0); }
static void random_points(fc_h *h) { random_prims(h, 1); }
static void random_stipple(fc_h *h) { random_prims(h, 2); }
static void random_smooth(fc_h *h) { random_prims(h, 3); }

/* Triangles while line stipple or smooth points/lines are on: llvmpipe
 * then lets the draw module do two-sided lighting (lp_state_rasterizer.c
 * need_pipeline, clear_flags), so lit two-sided triangles take the draw
 * pipeline; unlit ones still go straight to llvmpipe. */
static void quads_with_line_state(fc_h *h)
{
    static const float q[4][2] = { { 4.5f, 3.25f }, { 58.0f, 9.5f }, { 50.75f, 60.0f }, { 7.0f, 44.5f } };
    fc_pixel_ortho(h);
    for (int f = 0; f < 5; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        if (f == 4) {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_FRONT);
            glLineStipple(1, 0x0ff0);
            glEnable(GL_LINE_STIPPLE);
        }
        if (f == 0 || f == 3) {
            glEnable(GL_LINE_STIPPLE);
            glLineStipple(1, 0x00ff);
        }
        if (f == 1)
            glEnable(GL_POINT_SMOOTH);
        if (f == 2)
            glEnable(GL_LINE_SMOOTH);
        if (f == 3) {
            static const float pos[4] = { 0.2f, 0.3f, 1.0f, 0.0f };
            glEnable(GL_LIGHTING);
            glEnable(GL_LIGHT0);
            glLightfv(GL_LIGHT0, GL_POSITION, pos);
            glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
            glEnable(GL_COLOR_MATERIAL);
        }
        glBegin(GL_QUADS);
        for (int i = 0; i < 4; i++) {
            glColor3f(i == 0 || i == 3 ? 1.0f : 0.0f, i == 1 ? 1.0f : 0.2f, i == 2 ? 1.0f : 0.1f);
            glNormal3f(0.3f * (float)i, 0.5f, 1.0f);
            glVertex2fv(q[i]);
        }
        glEnd();
        glBegin(GL_QUADS);   /* clockwise: back-facing */
        for (int i = 3; i >= 0; i--) {
            glColor3f(0.5f, (float)i / 3.0f, 1.0f - (float)i / 3.0f);
            glNormal3f(0.0f, 0.2f * (float)i, -1.0f);
            glVertex2f(q[i][0] * 0.5f + 16.0f, q[i][1] * 0.5f + 16.0f);
        }
        glEnd();
        fc_capture(h);
        glDisable(GL_LINE_STIPPLE);
        glDisable(GL_POINT_SMOOTH);
        glDisable(GL_LINE_SMOOTH);
    }
    /* the other primitives in draw's pipeline: a quad strip, a polygon and
     * a triangle strip, lit two-sided with smooth lines on */
    glDisable(GL_CULL_FACE);
    glEnable(GL_LINE_SMOOTH);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i < 8; i++) {
        glColor3f((float)(i % 3) / 2.0f, (float)i / 7.0f, 1.0f - (float)(i % 2));
        glNormal3f(0.1f * (float)i, 0.5f, (i & 2) ? 1.0f : -1.0f);
        glVertex2f(3.0f + 8.0f * (float)(i / 2) + (float)(i % 2) * 2.5f, (i & 1) ? 30.0f : 3.5f);
    }
    glEnd();
    glBegin(GL_POLYGON);
    for (int i = 0; i < 6; i++) {
        glColor3f((float)i / 5.0f, 1.0f - (float)i / 5.0f, 0.5f);
        glNormal3f(0.0f, 0.3f, 1.0f - 0.3f * (float)i);
        glVertex2f(48.0f + 12.0f * cosf((float)i * 1.047f), 20.0f + 12.0f * sinf((float)i * 1.047f));
    }
    glEnd();
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 10; i++) {
        glColor3f(1.0f - (float)i / 9.0f, 0.4f, (float)i / 9.0f);
        glNormal3f(0.2f, (float)(i % 3) - 1.0f, 0.7f);
        glVertex2f(4.0f + 6.5f * (float)i, (i & 1) ? 60.0f : 40.0f + (float)(i % 3));
    }
    glEnd();
    fc_capture(h);
}

/* Slivers whose snapped orientation differs from the float determinant's
 * (found by search, each covering one pixel): in a draw that needs
 * clipping, draw's cull stage culls on the determinant before llvmpipe
 * culls on the snapped area; unclipped, only the area counts. */
static void cull_slivers(fc_h *h)
{
    static const float sl[8][6] = {
        { 2.03125f, 34.984375f, 6.818359375f, 35.9853515625f, 11.60546875f, 36.984375f },
        { 8.0625f, 28.55859375f, 10.3359375f, 28.95166015625f, 17.15625f, 30.1328125f },
        { 35.27734375f, 37.46484375f, 39.7412109375f, 38.20849609375f, 53.1328125f, 40.4375f },
        { 30.89453125f, 34.40625f, 41.3564453125f, 34.52099609375f, 44.84375f, 34.55859375f },
        { 15.31640625f, 57.31640625f, 20.9970703125f, 56.56689453125f, 22.890625f, 56.31640625f },
        { 14.7890625f, 41.23828125f, 18.8232421875f, 41.337890625f, 30.92578125f, 41.6328125f },
        { 31.05859375f, 47.16796875f, 32.1435546875f, 47.41943359375f, 35.3984375f, 48.16796875f },
        { 18.80078125f, 21.6953125f, 23.5361328125f, 21.447265625f, 37.7421875f, 20.6953125f },
    };
    fc_pixel_ortho(h);
    glEnable(GL_CULL_FACE);
    for (int f = 0; f < 6; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glCullFace(f % 3 == 0 ? GL_BACK : f % 3 == 1 ? GL_FRONT : GL_FRONT_AND_BACK);
        if (f == 2)
            glDisable(GL_CULL_FACE);
        glBegin(GL_TRIANGLES);
        for (int i = 0; i < 8; i++) {
            fcu_color(i);
            glVertex2f(sl[i][0], sl[i][1]);
            glVertex2f(sl[i][2], sl[i][3]);
            glVertex2f(sl[i][4], sl[i][5]);
        }
        if (f < 3) {   /* one triangle needing clipping: the draw takes the pipeline */
            glColor3f(1, 1, 1);
            glVertex2f(50.0f, 2.0f); glVertex2f(80.0f, 2.0f); glVertex2f(60.0f, 10.0f);
        }
        glEnd();
        glEnable(GL_CULL_FACE);
        fc_capture(h);
    }
}

/* ---- errors and queries ----------------------------------------------------- */

static void point_line_state(fc_h *h)
{
    fc_get_float(h, "GL_POINT_SIZE", GL_POINT_SIZE, 1);
    fc_get_float(h, "GL_POINT_SIZE_RANGE", GL_POINT_SIZE_RANGE, 2);
    fc_get_float(h, "GL_POINT_SIZE_GRANULARITY", GL_POINT_SIZE_GRANULARITY, 1);
    fc_get_double(h, "GL_POINT_SIZE_GRANULARITY (double)", GL_POINT_SIZE_GRANULARITY, 1);
    fc_get_float(h, "GL_ALIASED_POINT_SIZE_RANGE", GL_ALIASED_POINT_SIZE_RANGE, 2);
    fc_get_float(h, "GL_SMOOTH_POINT_SIZE_RANGE", GL_SMOOTH_POINT_SIZE_RANGE, 2);
    fc_get_float(h, "GL_LINE_WIDTH", GL_LINE_WIDTH, 1);
    fc_get_float(h, "GL_LINE_WIDTH_RANGE", GL_LINE_WIDTH_RANGE, 2);
    fc_get_float(h, "GL_LINE_WIDTH_GRANULARITY", GL_LINE_WIDTH_GRANULARITY, 1);
    fc_get_float(h, "GL_ALIASED_LINE_WIDTH_RANGE", GL_ALIASED_LINE_WIDTH_RANGE, 2);
    fc_get_float(h, "GL_SMOOTH_LINE_WIDTH_RANGE", GL_SMOOTH_LINE_WIDTH_RANGE, 2);
    fc_get_float(h, "GL_SMOOTH_LINE_WIDTH_GRANULARITY", GL_SMOOTH_LINE_WIDTH_GRANULARITY, 1);
    fc_get_integer(h, "GL_LINE_STIPPLE_PATTERN", GL_LINE_STIPPLE_PATTERN, 1);
    fc_get_integer(h, "GL_LINE_STIPPLE_REPEAT", GL_LINE_STIPPLE_REPEAT, 1);
    fc_is_enabled(h, "GL_POINT_SMOOTH", GL_POINT_SMOOTH);
    fc_is_enabled(h, "GL_LINE_SMOOTH", GL_LINE_SMOOTH);
    fc_is_enabled(h, "GL_LINE_STIPPLE", GL_LINE_STIPPLE);
    fc_get_boolean(h, "GL_LINE_STIPPLE (boolean)", GL_LINE_STIPPLE, 1);

    glPointSize(0.0f); fc_error(h, "glPointSize(0)");
    glPointSize(-2.0f); fc_error(h, "glPointSize(-2)");
    glPointSize(NAN); fc_error(h, "glPointSize(NaN)");
    glPointSize(1000.0f); fc_error(h, "glPointSize(1000)");
    fc_get_float(h, "GL_POINT_SIZE 1000", GL_POINT_SIZE, 1);
    fc_get_integer(h, "GL_POINT_SIZE int", GL_POINT_SIZE, 1);
    glPointSize(2.6f); fc_error(h, "glPointSize(2.6)");
    fc_get_integer(h, "GL_POINT_SIZE 2.6 int", GL_POINT_SIZE, 1);
    fc_get_double(h, "GL_POINT_SIZE 2.6 double", GL_POINT_SIZE, 1);

    glLineWidth(0.0f); fc_error(h, "glLineWidth(0)");
    glLineWidth(-1.0f); fc_error(h, "glLineWidth(-1)");
    glLineWidth(0.25f); fc_error(h, "glLineWidth(0.25)");
    fc_get_float(h, "GL_LINE_WIDTH 0.25", GL_LINE_WIDTH, 1);
    glLineWidth(999.0f); fc_error(h, "glLineWidth(999)");
    fc_get_float(h, "GL_LINE_WIDTH 999", GL_LINE_WIDTH, 1);
    fc_get_boolean(h, "GL_LINE_WIDTH bool", GL_LINE_WIDTH, 1);

    glLineStipple(0, 0x1234); fc_error(h, "glLineStipple(0, ...)");
    fc_get_integer(h, "GL_LINE_STIPPLE_REPEAT 0", GL_LINE_STIPPLE_REPEAT, 1);
    fc_get_integer(h, "GL_LINE_STIPPLE_PATTERN 0x1234", GL_LINE_STIPPLE_PATTERN, 1);
    glLineStipple(-5, 0xfedc); fc_error(h, "glLineStipple(-5, ...)");
    fc_get_integer(h, "GL_LINE_STIPPLE_REPEAT -5", GL_LINE_STIPPLE_REPEAT, 1);
    fc_get_float(h, "GL_LINE_STIPPLE_PATTERN float", GL_LINE_STIPPLE_PATTERN, 1);
    glLineStipple(1000, 0x8001); fc_error(h, "glLineStipple(1000, ...)");
    fc_get_integer(h, "GL_LINE_STIPPLE_REPEAT 1000", GL_LINE_STIPPLE_REPEAT, 1);
    fc_get_boolean(h, "GL_LINE_STIPPLE_PATTERN bool", GL_LINE_STIPPLE_PATTERN, 1);

    glEnable(GL_POINT_SMOOTH); fc_error(h, "glEnable(GL_POINT_SMOOTH)");
    glEnable(GL_LINE_SMOOTH); fc_error(h, "glEnable(GL_LINE_SMOOTH)");
    glEnable(GL_LINE_STIPPLE); fc_error(h, "glEnable(GL_LINE_STIPPLE)");
    fc_is_enabled(h, "GL_POINT_SMOOTH on", GL_POINT_SMOOTH);
    fc_is_enabled(h, "GL_LINE_SMOOTH on", GL_LINE_SMOOTH);
    fc_is_enabled(h, "GL_LINE_STIPPLE on", GL_LINE_STIPPLE);
    glDisable(GL_LINE_SMOOTH);
    fc_is_enabled(h, "GL_LINE_SMOOTH off", GL_LINE_SMOOTH);

    /* not allowed between glBegin and glEnd: state unchanged */
    glBegin(GL_POINTS); glPointSize(5.0f); glEnd(); fc_error(h, "glPointSize in begin/end");
    glBegin(GL_LINES); glLineWidth(5.0f); glEnd(); fc_error(h, "glLineWidth in begin/end");
    glBegin(GL_LINES); glLineStipple(3, 0x0f0f); glEnd(); fc_error(h, "glLineStipple in begin/end");
    fc_get_float(h, "GL_POINT_SIZE after", GL_POINT_SIZE, 1);
    fc_get_float(h, "GL_LINE_WIDTH after", GL_LINE_WIDTH, 1);
    fc_get_integer(h, "GL_LINE_STIPPLE_REPEAT after", GL_LINE_STIPPLE_REPEAT, 1);
    fc_get_integer(h, "GL_LINE_STIPPLE_PATTERN after", GL_LINE_STIPPLE_PATTERN, 1);
    /* an unchanged size is not checked */
    glLineWidth(999.0f); fc_error(h, "glLineWidth unchanged");
}

/* ---- points and lines with the other stages --------------------------------- */

/* Legacy antialiasing as demos use it: smooth points and lines blended with
 * SRC_ALPHA / ONE_MINUS_SRC_ALPHA over a background (the coverage alpha of
 * the aapoint/aaline lowering goes through the unorm8 blend). */
static void smooth_blend_points(fc_h *h)
{
    static const float sizes[] = { 1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 4.0f, 5.5f, 8.0f, 11.0f, 16.0f };
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.4f, 1.0f, 1);
    glEnable(GL_POINT_SMOOTH);
    glHint(GL_POINT_SMOOTH_HINT, GL_NICEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int i = 0; i < 10; i++) {
        glPointSize(sizes[i]);
        glBegin(GL_POINTS);
        for (int j = 0; j < 4; j++) {
            glColor4f(1.0f, (float)j / 3.0f, 0.2f + 0.08f * (float)i, 1.0f - 0.15f * (float)j);
            glVertex2f(6.0f + 13.0f * (float)j + offs[(i + j) % NOFFS],
                       4.0f + 12.0f * (float)i + offs[(3 * i + j) % NOFFS]);
        }
        glEnd();
    }
    fc_capture(h);
    /* overlapping points with depth: the blend of one smooth point over
     * another, the depth test on the quad's z */
    fcu_clear(1.0f, 1.0f, 1.0f, 1.0f, 1);
    glEnable(GL_DEPTH_TEST);
    glPointSize(9.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 30; i++) {
        glColor4f((float)(i % 3) / 2.0f, (float)(i % 5) / 4.0f, (float)(i % 7) / 6.0f, 0.6f);
        glVertex3f(5.0f + 1.9f * (float)i, 20.0f + 15.0f * sinf((float)i * 0.5f) + 0.37f * (float)i,
                   0.5f - 0.03f * (float)(i % 9));
    }
    glEnd();
    fc_capture(h);
}

static void smooth_blend_lines(fc_h *h)
{
    static const float widths[] = { 1.0f, 1.5f, 2.0f, 3.5f };
    fc_pixel_ortho(h);
    for (int f = 0; f < 4; f++) {
        fcu_clear(0.0f, 0.0f, 0.0f, 1.0f, 1);
        glEnable(GL_LINE_SMOOTH);
        glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glLineWidth(widths[f]);
        /* a star of lines at every angle */
        glBegin(GL_LINES);
        for (int i = 0; i < 24; i++) {
            const float a = (float)i * 0.2618f + 0.05f;
            glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
            glVertex2f(32.0f + 3.0f * cosf(a), 32.0f + 3.0f * sinf(a));
            glColor4f((float)(i % 2), 0.5f, (float)(i % 3) / 2.0f, 0.7f);
            glVertex2f(32.0f + 29.0f * cosf(a), 32.0f + 29.0f * sinf(a));
        }
        glEnd();
        /* an antialiased wireframe loop with depth, overlapping the star */
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glBegin(GL_LINE_LOOP);
        for (int i = 0; i < 9; i++) {
            fcu_color(i);
            glVertex3f(32.0f + 22.0f * cosf((float)i * 0.7f), 32.0f + 18.0f * sinf((float)i * 0.7f),
                       0.3f * sinf((float)i));
        }
        glEnd();
        glDisable(GL_DEPTH_TEST);
        fc_capture(h);
    }
}

/* Fog on points and lines: legacy, wide, stippled and smooth, in
 * perspective, with every fog mode; lines cut by the near plane (the fog
 * coordinate of the new end is interpolated by the clipper). */
static void points_lines_fog(fc_h *h)
{
    static const GLenum modes[3] = { GL_LINEAR, GL_EXP, GL_EXP2 };
    static const float fogc[4] = { 0.6f, 0.7f, 0.9f, 1.0f };
    for (int f = 0; f < 4; f++) {
        glViewport(0, 0, 64, 64);
        fcu_frustum(-1, 1, -1, 1, 1, 12);
        fcu_clear(0, 0, 0, 0, 1);
        glEnable(GL_FOG);
        glFogfv(GL_FOG_COLOR, fogc);
        glFogi(GL_FOG_MODE, (GLint)modes[f % 3]);
        glFogf(GL_FOG_START, 1.5f);
        glFogf(GL_FOG_END, 9.0f);
        glFogf(GL_FOG_DENSITY, 0.21f);
        glEnable(GL_DEPTH_TEST);
        glShadeModel(f == 1 ? GL_FLAT : GL_SMOOTH);
        if (f == 2)
            glEnable(GL_POINT_SMOOTH);
        if (f == 3) {
            glEnable(GL_LINE_SMOOTH);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        }
        glPointSize(f == 0 ? 1.0f : 4.0f);
        glBegin(GL_POINTS);
        for (int i = 0; i < 40; i++) {
            const float z = -1.2f - 0.25f * (float)i;
            glColor3f(1.0f, (float)(i % 4) / 3.0f, 0.2f);
            glVertex3f((-0.9f + 0.045f * (float)i) * -z, (0.6f + 0.2f * sinf((float)i)) * -z, z);
        }
        glEnd();
        glLineWidth(f == 0 ? 1.0f : 2.5f);
        if (f == 1) {
            glEnable(GL_LINE_STIPPLE);
            glLineStipple(2, 0x5f5f);
        }
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i < 12; i++) {
            const float z = 0.5f - 1.0f * (float)i;   /* the first ends are behind the near plane */
            glColor3f((float)(i % 2), 0.3f, (float)i / 11.0f);
            glVertex3f((-0.8f + 0.14f * (float)i) * 3.0f, ((i & 1) ? -0.3f : -0.9f) * 3.0f, z);
        }
        glEnd();
        glBegin(GL_LINES);
        for (int i = 0; i < 6; i++) {
            glColor3f(0.2f, 1.0f, (float)i / 5.0f);
            glVertex3f(-2.5f + 0.9f * (float)i, 0.0f, -1.1f);
            glVertex3f(-6.0f + 2.1f * (float)i, 2.0f, -11.5f);
        }
        glEnd();
        fc_capture(h);
        glDisable(GL_POINT_SMOOTH);
        glDisable(GL_LINE_SMOOTH);
        glDisable(GL_LINE_STIPPLE);
        glDisable(GL_BLEND);
        glShadeModel(GL_SMOOTH);
    }
}

/* Points and lines through the per-fragment operations: a scissor box that
 * cuts wide points and lines, a stencil mask written by points and tested
 * by lines, the alpha test against the smooth coverage alpha. */
static void points_lines_fragment_ops(fc_h *h)
{
    fc_pixel_ortho(h);
    /* scissor */
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_SCISSOR_TEST);
    glScissor(9, 13, 37, 29);
    glPointSize(7.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 36; i++) {
        fcu_color(i);
        glVertex2f(3.0f + 10.0f * (float)(i % 6) + offs[i % NOFFS], 5.0f + 10.0f * (float)(i / 6) + offs[(i + 5) % NOFFS]);
    }
    glEnd();
    glLineWidth(3.0f);
    glEnable(GL_LINE_SMOOTH);
    glBegin(GL_LINES);
    for (int i = 0; i < 8; i++) {
        fcu_color(i + 7);
        glVertex2f(1.0f + 3.0f * (float)i, 60.0f);
        glVertex2f(40.0f + 2.5f * (float)i, 2.0f + 0.5f * (float)i);
    }
    glEnd();
    glDisable(GL_LINE_SMOOTH);
    glDisable(GL_SCISSOR_TEST);
    fc_capture(h);

    /* stencil: points (legacy and smooth) write 1, then lines draw where
     * the stencil is not 1 */
    fcu_clear(0, 0, 0, 0, 1);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glPointSize(6.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 25; i++) {
        fcu_color(i);
        glVertex2f(6.0f + 12.0f * (float)(i % 5) + 0.3f, 6.0f + 12.0f * (float)(i / 5) + 0.6f);
    }
    glEnd();
    glEnable(GL_POINT_SMOOTH);
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 16; i++) {
        fcu_color(i + 3);
        glVertex2f(12.0f + 12.0f * (float)(i % 4), 12.0f + 12.0f * (float)(i / 4));
    }
    glEnd();
    glDisable(GL_POINT_SMOOTH);
    glStencilFunc(GL_NOTEQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
    glLineWidth(2.0f);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x7777);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 14; i++) {
        glColor3f(1.0f, (float)i / 13.0f, 0.5f);
        glVertex2f(2.0f + 4.5f * (float)i, (i & 1) ? 60.0f : 3.0f);
    }
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    glStencilFunc(GL_EQUAL, 2, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColor3f(0.0f, 1.0f, 1.0f);
    fcu_rect(0, 0, 64, 64, 0);   /* shows the pixels the strip hit twice */
    glDisable(GL_STENCIL_TEST);
    fc_capture(h);

    /* alpha test on the coverage alpha of smooth points and lines */
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.4f);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_LINE_SMOOTH);
    glPointSize(10.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 9; i++) {
        glColor4f(1.0f, 0.5f, (float)i / 8.0f, 0.5f + 0.06f * (float)i);
        glVertex2f(8.0f + 12.0f * (float)(i % 5) + offs[i], 8.0f + 12.0f * (float)(i / 5));
    }
    glEnd();
    glLineWidth(4.0f);
    glBegin(GL_LINES);
    for (int i = 0; i < 5; i++) {
        glColor4f(0.3f, 1.0f, 0.6f, 0.45f + 0.13f * (float)i);
        glVertex2f(3.0f, 36.0f + 5.0f * (float)i);
        glVertex2f(61.0f, 38.0f + 6.3f * (float)i);
    }
    glEnd();
    glAlphaFunc(GL_LESS, 0.6f);
    glBegin(GL_LINES);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glVertex2f(30.0f, 2.0f);
    glVertex2f(36.0f, 62.0f);
    glEnd();
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_POINT_SMOOTH);
    glDisable(GL_LINE_SMOOTH);
    fc_capture(h);
}

/* Polygon offset together with line state: line stipple or smooth lines
 * (or smooth points) make llvmpipe hand the offset to draw, so every
 * triangle takes draw's pipeline (quad diagonal 0-1-3/1-2-3, per-vertex
 * saturated offset from the float determinant) instead of the setup's
 * per-fragment offset.  A hidden-line pass: filled quads with offset, then
 * lines at the same depth that pass GL_LESS only where the offset pushed
 * the fill back. */
static void offset_with_line_state(fc_h *h)
{
    static const float q[4][3] = { { 4.5f, 3.25f, -0.8f }, { 58.0f, 9.5f, 0.3f },
                                   { 50.75f, 60.0f, 0.7f }, { 7.0f, 44.5f, -0.1f } };
    fc_pixel_ortho(h);
    for (int f = 0; f < 5; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(f == 4 ? -1.5f : 1.0f, f == 4 ? -3.0f : 2.0f);
        if (f == 1 || f == 4) {
            glEnable(GL_LINE_STIPPLE);
            glLineStipple(1, 0xf0f0);
        }
        if (f == 2)
            glEnable(GL_LINE_SMOOTH);
        if (f == 3)
            glEnable(GL_POINT_SMOOTH);
        glBegin(GL_QUADS);
        for (int i = 0; i < 4; i++) {
            glColor3f(i == 0 || i == 3 ? 1.0f : 0.0f, i == 1 ? 1.0f : 0.2f, i == 2 ? 1.0f : 0.1f);
            glVertex3fv(q[i]);
        }
        glEnd();
        glBegin(GL_TRIANGLE_FAN);
        glColor3f(0.5f, 0.5f, 0.5f);
        glVertex3f(32.0f, 32.0f, 0.0f);
        for (int i = 0; i < 7; i++) {
            glColor3f((float)(i % 2), 0.4f, (float)i / 6.0f);
            glVertex3f(32.0f + 20.0f * cosf((float)i), 32.0f + 20.0f * sinf((float)i), 0.2f * sinf(3.0f * (float)i));
        }
        glEnd();
        glDisable(GL_POLYGON_OFFSET_FILL);
        /* the outlines at the same depth */
        glColor3f(1.0f, 1.0f, 1.0f);
        glBegin(GL_LINE_LOOP);
        for (int i = 0; i < 4; i++)
            glVertex3fv(q[i]);
        glEnd();
        glBegin(GL_LINE_LOOP);
        for (int i = 0; i < 7; i++)
            glVertex3f(32.0f + 20.0f * cosf((float)i), 32.0f + 20.0f * sinf((float)i), 0.2f * sinf(3.0f * (float)i));
        glEnd();
        fc_capture(h);
        glDisable(GL_LINE_STIPPLE);
        glDisable(GL_LINE_SMOOTH);
        glDisable(GL_POINT_SMOOTH);
    }
}

/* User clip planes cutting points and lines: lines are cut at the plane
 * (do_clip_line's parameter from the C dot product), points are dropped
 * when the vertex mask has the plane's bit (the fused distance), so a plane
 * through a point's centre decides by the sign of the fused distance; wide,
 * stippled and smooth lines, smooth points, flat colours of clipped ends. */
static void clipplane_points_lines(fc_h *h)
{
    static const double p0[4] = { 1.0, 0.35, 0.0, -30.0 };
    static const double p1[4] = { -0.2, -1.0, 0.0, 50.0 };
    static const double p2[4] = { 0.0, 1.0, 0.0, -16.0 };   /* y = 16 exactly */
    fc_pixel_ortho(h);
    for (int f = 0; f < 4; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glClipPlane(GL_CLIP_PLANE0, p0);
        glClipPlane(GL_CLIP_PLANE3, p1);
        glClipPlane(GL_CLIP_PLANE5, p2);
        glEnable(GL_CLIP_PLANE0);
        glEnable(GL_CLIP_PLANE3);
        if (f >= 2)
            glEnable(GL_CLIP_PLANE5);
        glShadeModel(f == 1 ? GL_FLAT : GL_SMOOTH);
        if (f == 2) {
            glEnable(GL_LINE_SMOOTH);
            glEnable(GL_POINT_SMOOTH);
        }
        if (f == 3) {
            glEnable(GL_LINE_STIPPLE);
            glLineStipple(2, 0x3f3f);
        }
        glPointSize(f == 0 ? 1.0f : 3.0f);
        glBegin(GL_POINTS);
        for (int i = 0; i < 64; i++) {
            fcu_color(i);
            /* some points exactly on the planes */
            glVertex2f(2.0f + (float)(i % 8) * 8.0f, (i & 8) ? 16.0f : 2.0f + (float)(i / 8) * 8.0f);
        }
        glEnd();
        glLineWidth(f == 0 ? 1.0f : 2.0f + (float)f * 0.5f);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i < 10; i++) {
            glColor3f((float)(i % 2), (float)i / 9.0f, 1.0f - (float)i / 9.0f);
            glVertex2f(1.0f + 6.8f * (float)i, (i & 1) ? 62.0f : 4.0f);
        }
        glEnd();
        glBegin(GL_LINE_LOOP);
        for (int i = 0; i < 6; i++) {
            fcu_color(i + 2);
            glVertex2f(32.0f + 27.0f * cosf((float)i * 1.047f + 0.2f), 32.0f + 27.0f * sinf((float)i * 1.047f + 0.2f));
        }
        glEnd();
        glBegin(GL_LINES);   /* lines from and to points on the y = 16 plane */
        for (int i = 0; i < 6; i++) {
            fcu_color(i + 9);
            glVertex2f(5.0f + 9.0f * (float)i, 16.0f);
            glVertex2f(9.0f + 9.0f * (float)i, 16.0f - 10.0f + 4.0f * (float)i);
        }
        glEnd();
        fc_capture(h);
        glDisable(GL_CLIP_PLANE0);
        glDisable(GL_CLIP_PLANE3);
        glDisable(GL_CLIP_PLANE5);
        glDisable(GL_LINE_SMOOTH);
        glDisable(GL_POINT_SMOOTH);
        glDisable(GL_LINE_STIPPLE);
    }
    /* in perspective, under a rotated modelview, with the near plane too */
    glViewport(0, 0, 64, 64);
    fcu_frustum(-1, 1, -1, 1, 1, 10);
    fcu_clear(0, 0, 0, 0, 1);
    glRotatef(25.0f, 0.3f, 0.2f, 1.0f);
    static const double pe[4] = { 0.4, 1.0, 0.2, 0.3 };
    glClipPlane(GL_CLIP_PLANE1, pe);
    glEnable(GL_CLIP_PLANE1);
    glLoadIdentity();
    glPointSize(2.0f);
    glLineWidth(1.5f);
    glBegin(GL_LINES);
    for (int i = 0; i < 16; i++) {
        glColor3f(1.0f, (float)(i % 4) / 3.0f, (float)i / 15.0f);
        glVertex3f(-1.5f + 0.2f * (float)i, -1.2f, 0.5f);
        glVertex3f(-2.5f + 0.33f * (float)i, 1.8f, -6.0f);
    }
    glEnd();
    glBegin(GL_POINTS);
    for (int i = 0; i < 48; i++) {
        glColor3f(0.3f, 1.0f, (float)(i % 3) / 2.0f);
        glVertex3f(-2.0f + 0.09f * (float)i * 2.0f, 1.5f * sinf((float)i), -1.5f - 0.1f * (float)i);
    }
    glEnd();
    glDisable(GL_CLIP_PLANE1);
    fc_capture(h);
}

/* The polygon stipple is draw's pstipple stage, which passes points and
 * lines through: smooth points and lines (quads of triangles in draw's
 * no-cull state) and legacy ones are not stippled, the triangles drawn
 * with them are. */
static void polygon_stipple_points_lines(fc_h *h)
{
    GLubyte pat[128];
    for (int i = 0; i < 128; i++)
        pat[i] = (GLubyte)((i & 4) ? 0xcc : 0x33);
    fc_pixel_ortho(h);
    for (int f = 0; f < 2; f++) {
        fcu_clear(0, 0, 0, 0, 1);
        glPolygonStipple(pat);
        glEnable(GL_POLYGON_STIPPLE);
        if (f == 1) {
            glEnable(GL_POINT_SMOOTH);
            glEnable(GL_LINE_SMOOTH);
        }
        glColor3f(0.2f, 0.4f, 1.0f);
        fcu_rect(2, 2, 30, 30, 0);
        glPointSize(6.0f);
        glBegin(GL_POINTS);
        for (int i = 0; i < 16; i++) {
            fcu_color(i);
            glVertex2f(6.0f + 7.0f * (float)(i % 4), 36.0f + 7.0f * (float)(i / 4));
        }
        glEnd();
        glLineWidth(3.0f);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i < 7; i++) {
            fcu_color(i + 4);
            glVertex2f(34.0f + 4.5f * (float)i, (i & 1) ? 60.0f : 4.0f);
        }
        glEnd();
        glColor3f(1.0f, 0.4f, 0.2f);
        fcu_rect(20, 20, 44, 44, 0);
        fc_capture(h);
        glDisable(GL_POINT_SMOOTH);
        glDisable(GL_LINE_SMOOTH);
        glDisable(GL_POLYGON_STIPPLE);
    }
}

const fc_case fc_cases_points_lines[] = {
    FC_CASE_RGBA("raster/points_size_1", 64, 64, 1, "raster points", points_size_1),
    FC_CASE_RGBA("raster/points_size_1_5", 64, 64, 1, "raster points", points_size_1_5),
    FC_CASE_RGBA("raster/points_size_2", 64, 64, 1, "raster points", points_size_2),
    FC_CASE_RGBA("raster/points_size_2_5", 64, 64, 1, "raster points", points_size_2_5),
    FC_CASE_RGBA("raster/points_size_3", 64, 64, 1, "raster points", points_size_3),
    FC_CASE_RGBA("raster/points_size_4", 96, 96, 1, "raster points", points_size_4),
    FC_CASE_RGBA("raster/points_size_7_5", 128, 128, 1, "raster points", points_size_7_5),
    FC_CASE_RGBA("raster/points_odd_sizes", 64, 64, 2, "raster points", points_odd_sizes),
    FC_CASE_RGBA("raster/points_depth", 64, 64, 1, "raster points depth", points_depth),
    FC_CASE_RGBA("raster/points_perspective_clip", 64, 64, 1, "raster points clip", points_perspective_clip),
    FC_CASE_RGBA("raster/points_frame_edges", 32, 32, 2, "raster points clip", points_frame_edges),
    FC_CASE_RGBA("raster/points_w_near_zero", 64, 64, 1, "raster points clip", points_w_near_zero),
    FC_CASE_RGBA("raster/points_flat", 32, 32, 1, "raster points", points_flat),
    FC_CASE_RGBA("raster/lines_smooth", 32, 32, 2, "raster lines", lines_smooth),
    FC_CASE_RGBA("raster/lines_flat", 32, 32, 2, "raster lines", lines_flat),
    FC_CASE_RGBA("raster/line_strip_smooth", 32, 32, 2, "raster lines", line_strip_smooth),
    FC_CASE_RGBA("raster/line_strip_flat", 32, 32, 2, "raster lines", line_strip_flat),
    FC_CASE_RGBA("raster/line_loop_smooth", 32, 32, 2, "raster lines", line_loop_smooth),
    FC_CASE_RGBA("raster/line_loop_flat", 32, 32, 2, "raster lines", line_loop_flat),
    FC_CASE_RGBA("raster/lines_width_1", 64, 64, 1, "raster lines", lines_width_1),
    FC_CASE_RGBA("raster/lines_width_2", 64, 64, 1, "raster lines", lines_width_2),
    FC_CASE_RGBA("raster/lines_width_3", 64, 64, 1, "raster lines", lines_width_3),
    FC_CASE_RGBA("raster/lines_width_4", 64, 64, 1, "raster lines", lines_width_4),
    FC_CASE_RGBA("raster/lines_width_5", 64, 64, 1, "raster lines", lines_width_5),
    FC_CASE_RGBA("raster/lines_width_6", 64, 64, 1, "raster lines", lines_width_6),
    FC_CASE_RGBA("raster/lines_width_7", 64, 64, 1, "raster lines", lines_width_7),
    FC_CASE_RGBA("raster/lines_width_8", 64, 64, 1, "raster lines", lines_width_8),
    FC_CASE_RGBA("raster/lines_width_9", 64, 64, 1, "raster lines", lines_width_9),
    FC_CASE_RGBA("raster/lines_width_10", 64, 64, 1, "raster lines", lines_width_10),
    FC_CASE_RGBA("raster/lines_width_0_4", 64, 64, 1, "raster lines", lines_width_0_4),
    FC_CASE_RGBA("raster/lines_width_1_5", 64, 64, 1, "raster lines", lines_width_1_5),
    FC_CASE_RGBA("raster/lines_width_2_5", 64, 64, 1, "raster lines", lines_width_2_5),
    FC_CASE_RGBA("raster/lines_width_3_7", 64, 64, 1, "raster lines", lines_width_3_7),
    FC_CASE_RGBA("raster/lines_diamond_exit", 64, 64, 3, "raster lines", lines_diamond),
    FC_CASE_RGBA("raster/lines_frame_edges", 32, 32, 2, "raster lines clip", lines_frame_edges),
    FC_CASE_RGBA("raster/lines_clip_near_far", 64, 64, 1, "raster lines clip", lines_clip_near_far),
    FC_CASE_RGBA("raster/lines_w_near_zero", 64, 64, 1, "raster lines clip", lines_w_near_zero),
    FC_CASE_RGBA("raster/lines_depth", 64, 64, 1, "raster lines depth", lines_depth),
    FC_CASE_RGBA("raster/lines_long_loop", 64, 64, 1, "raster lines", lines_long_loop),
    FC_CASE_RGBA("raster/lines_wrapped_vertex_buffer", 64, 64, 2, "raster lines stipple vbo", lines_wrapped),
    FC_CASE_RGBA("raster/points_lines_robust", 128, 128, 4, "raster lines points robust", robust_points_lines),
    FC_CASE_RGBA("raster/lines_w_zero_end", 63, 42, 12, "raster lines clip robust", lines_w_zero_end),
    FC_CASE("raster/lines_w_zero_end_bgra", 63, 42, OSMESA_BGRA, 0, 0, 12, "raster lines clip robust", lines_w_zero_end),
    FC_CASE_RGBA("raster/stipple_strip_f1", 64, 64, 1, "raster lines stipple", stipple_strip_f1),
    FC_CASE_RGBA("raster/stipple_strip_f2", 64, 64, 1, "raster lines stipple", stipple_strip_f2),
    FC_CASE_RGBA("raster/stipple_strip_f3", 64, 64, 1, "raster lines stipple", stipple_strip_f3),
    FC_CASE_RGBA("raster/stipple_loop_f2", 64, 64, 1, "raster lines stipple", stipple_loop_f2),
    FC_CASE_RGBA("raster/stipple_lines_f1", 64, 64, 1, "raster lines stipple", stipple_lines_f1),
    FC_CASE_RGBA("raster/stipple_mixed", 64, 64, 2, "raster lines stipple clip", stipple_mixed),
    FC_CASE_RGBA("raster/stipple_counter_resets", 64, 64, 11, "raster lines stipple", stipple_counter_resets),
    FC_CASE_RGBA("raster/lit_points_lines", 64, 64, 2, "raster lighting", lit_points_lines),
    FC_CASE_RGBA("raster/points_smooth", 64, 128, 1, "raster points smooth", points_smooth),
    FC_CASE_RGBA("raster/points_smooth_perspective", 64, 64, 1, "raster points smooth depth", points_smooth_perspective),
    FC_CASE_RGBA("raster/lines_smooth_w1", 64, 64, 1, "raster lines smooth", lines_smooth_w1),
    FC_CASE_RGBA("raster/lines_smooth_w1_5", 64, 64, 1, "raster lines smooth", lines_smooth_w1_5),
    FC_CASE_RGBA("raster/lines_smooth_w3", 64, 64, 1, "raster lines smooth", lines_smooth_w3),
    FC_CASE_RGBA("raster/lines_smooth_w6", 64, 64, 1, "raster lines smooth", lines_smooth_w6),
    FC_CASE_RGBA("raster/lines_smooth_mixed", 64, 64, 2, "raster lines smooth stipple clip", lines_smooth_mixed),
    FC_CASE_RGBA("raster/smooth_lit_twoside", 64, 64, 1, "raster smooth lighting", smooth_lit_twoside),
    FC_CASE_RGBA("raster/random_lines", 64, 64, 4, "raster lines", random_lines),
    FC_CASE_RGBA("raster/random_points", 64, 64, 4, "raster points", random_points),
    FC_CASE_RGBA("raster/random_stipple", 64, 64, 4, "raster lines stipple", random_stipple),
    FC_CASE_RGBA("raster/random_smooth", 64, 64, 4, "raster lines points smooth", random_smooth),
    FC_CASE_RGBA("raster/quads_with_line_state", 64, 64, 6, "raster quad lighting", quads_with_line_state),
    FC_CASE_RGBA("raster/cull_slivers_pipeline", 64, 64, 6, "raster cull clip", cull_slivers),
    FC_CASE_RGBA("raster/point_line_state", 16, 16, 0, "raster api errors query", point_line_state),
    FC_CASE_RGBA("raster/smooth_blend_points", 64, 128, 2, "raster points smooth fragment", smooth_blend_points),
    FC_CASE_RGBA("raster/smooth_blend_lines", 64, 64, 4, "raster lines smooth fragment", smooth_blend_lines),
    FC_CASE_RGBA("raster/points_lines_fog", 64, 64, 4, "raster lines points fog", points_lines_fog),
    FC_CASE("raster/points_lines_fragment_ops", 64, 64, OSMESA_RGBA, 24, 8, 3, "raster lines points fragment", points_lines_fragment_ops),
    FC_CASE_RGBA("raster/offset_with_line_state", 64, 64, 5, "raster offset lines stipple smooth", offset_with_line_state),
    FC_CASE("raster/offset_with_line_state_z16", 64, 64, OSMESA_RGBA, 16, 0, 5, "raster offset lines stipple smooth", offset_with_line_state),
    FC_CASE_RGBA("raster/clipplane_points_lines", 64, 64, 5, "raster lines points clip", clipplane_points_lines),
    FC_CASE_RGBA("raster/polygon_stipple_points_lines", 64, 64, 2, "raster lines points stipple smooth", polygon_stipple_points_lines),
    { 0 }
};
