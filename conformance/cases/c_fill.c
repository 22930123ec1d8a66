/* c_fill.c - fill rule and subpixel snapping cases: edges exactly through
 * pixel centres, shared edges (distinct flat colours expose gaps and double
 * hits), edges at 2.5 +- k/512, round-half-even ties, slivers, tiny and huge
 * triangles.  All use window-coordinate ortho on power-of-two buffers so the
 * vertex positions reach the rasterizer unrounded. */
#include "cases.h"

/* Square with all four edges through pixel centres, as one quad and as two
 * triangles with distinct flat colours (both diagonal orientations). */
static void fill_square(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    fcu_color(0);
    fcu_rect(2.5f, 2.5f, 6.5f, 6.5f, 0);
    fcu_color(1); fcu_tri(8.5f, 2.5f, 12.5f, 2.5f, 12.5f, 6.5f);
    fcu_color(2); fcu_tri(8.5f, 2.5f, 12.5f, 6.5f, 8.5f, 6.5f);
    fcu_color(3); fcu_tri(2.5f, 8.5f, 6.5f, 8.5f, 2.5f, 12.5f);
    fcu_color(4); fcu_tri(6.5f, 8.5f, 6.5f, 12.5f, 2.5f, 12.5f);
    fcu_color(5); fcu_rect(8.5f, 8.5f, 9.5f, 9.5f, 0);     /* one pixel centre */
    fcu_color(6); fcu_rect(11.0f, 8.0f, 12.0f, 9.0f, 0);   /* pixel-aligned */
    fc_capture(h);
}

/* Long shared diagonals through pixel centres, both windings. */
static void fill_shared_diagonal(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    fcu_color(0); fcu_tri(1.5f, 1.5f, 29.5f, 1.5f, 29.5f, 29.5f);
    fcu_color(1); fcu_tri(1.5f, 1.5f, 29.5f, 29.5f, 1.5f, 29.5f);
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    fcu_color(2); fcu_tri(1.5f, 29.5f, 29.5f, 1.5f, 29.5f, 29.5f);   /* clockwise */
    fcu_color(3); fcu_tri(1.5f, 29.5f, 1.5f, 1.5f, 29.5f, 1.5f);
    fcu_color(4); fcu_tri(3.5f, 4.5f, 25.5f, 15.5f, 6.5f, 27.5f);    /* slope 1:2 */
    fcu_color(5); fcu_tri(3.5f, 4.5f, 28.5f, 4.5f, 25.5f, 15.5f);
    fc_capture(h);
}

/* A fan around a pixel centre with rim vertices on pixel centres. */
static void fill_fan_centres(fc_h *h)
{
    static const float rim[][2] = {
        { 30.5f, 16.5f }, { 28.5f, 24.5f }, { 24.5f, 28.5f }, { 16.5f, 30.5f },
        { 8.5f, 28.5f }, { 4.5f, 24.5f }, { 2.5f, 16.5f }, { 4.5f, 8.5f },
        { 8.5f, 4.5f }, { 16.5f, 2.5f }, { 24.5f, 4.5f }, { 28.5f, 8.5f },
        { 30.5f, 16.5f },
    };
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_TRIANGLE_FAN);
    glVertex2f(16.5f, 16.5f);
    for (int i = 0; i < 13; i++) {
        fcu_color(i);
        glVertex2fv(rim[i]);
    }
    glEnd();
    fc_capture(h);
}

/* Left edges at 2.5 + k/512 (k = -6..6) in rows; top edges likewise. */
static void snap_subpixel(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    for (int k = -6; k <= 6; k++) {
        float y = 2.0f * (float)(k + 6);
        fcu_color(k + 6);
        fcu_rect(2.5f + (float)k / 512.0f, y, 6.5f, y + 1.0f, 0);
        fcu_rect(8.5f + (float)(k + 6) * 4.0f, 2.0f, 11.5f + (float)(k + 6) * 4.0f,
                 12.5f + (float)k / 512.0f, 0);
    }
    fc_capture(h);
}

/* Vertices exactly half-way between snap grid points (RNE ties) and one
 * ulp-ish off them, on sloped edges. */
static void snap_ties(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    for (int i = 0; i < 8; i++) {
        float t = (float)(2 * i + 1) / 512.0f;
        float x = 1.5f + 8.0f * (float)(i & 3), y = 1.5f + 16.0f * (float)(i >> 2);
        fcu_color(i);
        fcu_tri(x + t, y + t, x + 6.0f - t, y + 1.0f + t, x + 1.0f + t, y + 13.0f - t);
        fcu_color(i + 8);
        fcu_tri(x + 6.0f - t, y + 1.0f + t, x + 6.5f + t, y + 12.0f, x + 1.0f + t, y + 13.0f - t);
    }
    fc_capture(h);
}

/* Slivers thinner than a pixel and triangles smaller than one. */
static void fill_slivers_tiny(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    for (int i = 0; i < 8; i++) {
        float x = 2.0f + 3.5f * (float)i, w = (float)(i + 1) / 256.0f;
        fcu_color(i);
        fcu_tri(x, 1.0f, x + w, 1.0f, x + 2.0f + w, 30.0f);          /* near-vertical */
        fcu_tri(1.0f, 33.0f + x, 60.0f, 33.0f + x + w, 1.0f, 33.0f + x + 2.0f * w); /* near-horizontal */
    }
    for (int i = 0; i < 16; i++) {
        float x = 32.0f + 2.0f * (float)(i & 7) + (float)i / 16.0f, y = 4.0f + 3.0f * (float)(i >> 3);
        fcu_color(i);
        fcu_tri(x + 0.3f, y + 0.3f, x + 0.7f, y + 0.4f, x + 0.45f, y + 0.9f); /* may miss the centre */
        fcu_tri(x, y + 12.0f, x + 1.0f / 256.0f, y + 12.0f, x, y + 12.0f + 1.0f / 256.0f);
    }
    fc_capture(h);
}

/* Very large window coordinates (clipped before setup). */
static void fill_huge(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_SMOOTH);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-1.0e5f, -3.0e4f);
    glColor3f(0, 1, 0); glVertex2f(2.0e6f, 17.25f);
    glColor3f(0, 0, 1); glVertex2f(13.5f, 3.0e7f);
    glColor3f(1, 1, 0); glVertex2f(1.0e9f, 1.0e9f);
    glColor3f(0, 1, 1); glVertex2f(-1.0e9f, 20.0f);
    glColor3f(1, 0, 1); glVertex2f(31.5f, 31.5f);
    glEnd();
    fc_capture(h);
}

/* A strip mesh on 1/256 positions with distinct flat colours per triangle. */
static void fill_strip_mesh(fc_h *h)
{
    fc_pixel_ortho(h);
    glShadeModel(GL_FLAT);
    fcu_clear(0, 0, 0, 0, 1);
    for (int row = 0; row < 4; row++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (int i = 0; i < 12; i++) {
            float x = 1.0f + 5.25f * (float)(i / 2) + (float)((i * 37 + row * 11) % 256) / 256.0f;
            float y = 2.0f + 14.0f * (float)row + (i & 1 ? 11.0f : 0.0f) + (float)((i * 53) % 256) / 256.0f;
            fcu_color(i + row);
            glVertex2f(x, y);
        }
        glEnd();
    }
    fc_capture(h);
}

const fc_case fc_cases_fill[] = {
    FC_CASE_RGBA("core/fill_rule_square", 16, 16, 1, "core fill", fill_square),
    FC_CASE_RGBA("core/fill_shared_diagonal", 32, 32, 2, "core fill", fill_shared_diagonal),
    FC_CASE_RGBA("core/fill_fan_pixel_centres", 32, 32, 1, "core fill", fill_fan_centres),
    FC_CASE_RGBA("core/snap_subpixel_512", 64, 32, 1, "core fill snap", snap_subpixel),
    FC_CASE_RGBA("core/snap_round_half_even", 32, 32, 1, "core fill snap", snap_ties),
    FC_CASE_RGBA("core/fill_slivers_tiny", 64, 64, 1, "core fill", fill_slivers_tiny),
    FC_CASE_RGBA("core/fill_huge_coordinates", 32, 32, 1, "core fill clip", fill_huge),
    FC_CASE_RGBA("core/fill_strip_mesh_subpixel", 64, 64, 1, "core fill snap", fill_strip_mesh),
    { 0 }
};
