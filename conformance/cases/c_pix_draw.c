/* c_pix_draw.c - glBitmap, glDrawPixels and glCopyPixels: bitmap text with
 * the raster position advance, the unpack modes of bitmaps, the bitmap
 * cache's drawing order, images of each common format and type with zoom
 * (positive, negative, fractional) and pixel transfer, through the
 * per-fragment operations, depth and stencil images, copies of colour,
 * depth and stencil with overlapping regions and zoom, feedback and
 * selection records, display lists and errors. */
#define GL_GLEXT_PROTOTYPES 1   /* glMultiDrawArrays, glMultiDrawElements */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

/* ---- helpers ---- */

/* An 8x10 glyph per character of "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ "
 * made from a hash, rows bottom-up, MSB first: enough structure for
 * every bit pattern to show. */
static void glyph(int ch, GLubyte rows[10])
{
    unsigned v = (unsigned)ch * 2654435761u;
    for (int r = 0; r < 10; r++) {
        v ^= v << 13;
        v ^= v >> 17;
        v ^= v << 5;
        rows[r] = (GLubyte)(r == 0 || r == 9 ? 0 : (v & 0x7e));
    }
}

static void draw_text(const char *s)
{
    for (; *s; s++) {
        GLubyte rows[10];
        glyph(*s, rows);
        glBitmap(8, 10, 0.0f, 2.0f, 9.0f, 0.0f, rows);
    }
}

/* A w x h RGBA image with distinct values per pixel. */
static void make_rgba_ub(GLubyte *p, int w, int h, unsigned seed)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            GLubyte *q = p + 4 * (y * w + x);
            q[0] = (GLubyte)(x * 37 + y * 11 + seed);
            q[1] = (GLubyte)(y * 41 + x * 3 + seed * 7);
            q[2] = (GLubyte)((x ^ y) * 29 + seed * 13);
            q[3] = (GLubyte)(x * 17 + y * 23 + 40 + seed);
        }
}

static void make_rgba_f(GLfloat *p, int w, int h, unsigned seed)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            GLfloat *q = p + 4 * (y * w + x);
            q[0] = (float)((x * 37 + y * 11 + seed) % 97) / 96.0f;
            q[1] = (float)((y * 41 + x * 3 + seed * 7) % 89) / 88.0f;
            q[2] = (float)(((x ^ y) * 29 + seed * 13) % 83) / 82.0f;
            q[3] = (float)((x * 17 + y * 23 + seed) % 79) / 78.0f;
        }
}

static void window_pos(float x, float y, float z)
{
    /* with fc_pixel_ortho, object coordinates are window coordinates */
    glRasterPos3f(x, y, z);
}

static void raster_query(fc_h *h, const char *label)
{
    char l[96];
    snprintf(l, sizeof l, "%s pos", label);
    fc_get_float(h, l, GL_CURRENT_RASTER_POSITION, 4);
    snprintf(l, sizeof l, "%s valid", label);
    fc_get_boolean(h, l, GL_CURRENT_RASTER_POSITION_VALID, 1);
    snprintf(l, sizeof l, "%s error", label);
    fc_error(h, l);
}

/* ---- glBitmap ---- */

/* Legacy-demo text: lines of glyphs advanced by xmove, colours per line
 * (the raster colour is latched by glRasterPos), a fractional start. */
static void bitmap_text(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.1f, 0.2f, 1.0f, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const char *lines[] = { "HELLO WORLD 0123", "THE QUICK BROWN FOX", "JUMPS OVER 456789",
                            "LAZY DOG XYZ" };
    for (int i = 0; i < 4; i++) {
        glColor3f(1.0f - 0.2f * (float)i, 0.3f + 0.2f * (float)i, 0.5f);
        window_pos(3.0f + 0.25f * (float)i, 100.0f - 14.0f * (float)i + 0.5f, 0.0f);
        draw_text(lines[i]);
        raster_query(h, "after line");
    }
    /* glColor after glRasterPos does not change the text colour */
    window_pos(5.0f, 30.0f, 0.0f);
    glColor3f(0.0f, 1.0f, 0.0f);
    draw_text("AFTER COLOR");
    fc_capture(h);
}

/* Unpack modes: LSB first, alignments, skip pixels (not a multiple of 8),
 * skip rows, row length. */
static void bitmap_unpack(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    GLubyte bits[64];
    for (int i = 0; i < 64; i++)
        bits[i] = (GLubyte)(i * 73 + 19);
    glColor3f(1, 1, 0);
    int x = 2;
    for (int mode = 0; mode < 8; mode++) {
        glPixelStorei(GL_UNPACK_LSB_FIRST, mode & 1);
        glPixelStorei(GL_UNPACK_ALIGNMENT, (mode & 2) ? 1 : 4);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, (mode & 4) ? 3 : 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, mode / 4);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, (mode & 4) ? 21 : 0);
        window_pos((float)x, 4.0f, 0.0f);
        glBitmap(13, 9, 0, 0, 0, 0, bits);
        window_pos((float)x, 20.0f, 0.0f);
        glBitmap(5, 11, 0, 0, 0, 0, bits + 1);
        x += 15;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 9);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_LSB_FIRST, 0);
    window_pos(3.0f, 40.0f, 0.0f);
    glBitmap(23, 5, 0, 0, 0, 0, bits);
    fc_capture(h);
}

/* Origins and moves: fractional positions (floor of pos + 1e-4 - orig),
 * negative origins and moves, the raster position after each. */
static void bitmap_origin_move(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLubyte rows[10];
    glyph('Q', rows);
    static const float pos[][2] = {
        { 4.0f, 4.0f }, { 14.4999f, 4.0f }, { 24.99995f, 4.99995f }, { 34.5f, 5.5f },
        { 44.0f, 4.9999f }, { 54.00002f, 3.99992f },
    };
    for (int i = 0; i < 6; i++) {
        glColor3f(0.2f + 0.13f * (float)i, 1.0f, 0.5f);
        window_pos(pos[i][0], pos[i][1], 0.0f);
        glBitmap(8, 10, 0.0f, 0.0f, 0.0f, 0.0f, rows);
    }
    window_pos(10.0f, 30.0f, 0.0f);
    glColor3f(1, 0, 1);
    glBitmap(8, 10, -2.5f, 1.25f, 10.5f, -1.75f, rows);
    raster_query(h, "move 1");
    glBitmap(8, 10, 3.0f, -4.0f, -20.25f, 8.0f, rows);
    raster_query(h, "move 2");
    glBitmap(0, 0, 0, 0, 30.0f, 3.0f, NULL);
    raster_query(h, "move empty");
    glBitmap(8, 10, 0.0f, 0.0f, 0.0f, 0.0f, rows);
    fc_capture(h);
}

/* An invalid raster position draws nothing and does not move; bitmaps
 * partly outside the window; bitmaps too big for the cache (wider than
 * 512 or taller than 32). */
static void bitmap_clipped(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    static GLubyte big[70 * 40];
    for (int i = 0; i < (int)sizeof big; i++)
        big[i] = (GLubyte)(i * 31 + (i >> 3));
    glColor3f(1, 0.5f, 0);
    window_pos(-5.0f, 10.0f, 0.0f);       /* outside: invalid */
    raster_query(h, "invalid");
    glBitmap(16, 16, 0, 0, 7, 7, big);
    raster_query(h, "invalid after");
    window_pos(2.0f, 2.0f, 0.0f);
    glBitmap(16, 8, 5.0f, 3.0f, 0, 0, big);   /* starts left of / below 0 */
    window_pos(60.0f, 50.0f, 0.0f);
    glBitmap(24, 16, 0, 0, 0, 0, big);        /* past the top right */
    glColor3f(0.3f, 0.7f, 1.0f);
    window_pos(8.0f, 12.0f, 0.0f);
    glBitmap(40, 40, 0, 0, 0, 0, big);        /* taller than the cache */
    window_pos(1.0f, 30.0f, 0.0f);
    glBitmap(560, 3, 0, 0, 0, 0, big);        /* wider than the cache */
    fc_capture(h);
}

/* When the cache is drawn: state changes alone do not draw it, so the
 * bitmaps take the state of the last glBitmap call, and draws, clears and
 * reads draw it first. */
static void bitmap_cache_order(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.2f, 0.2f, 1.0f, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLubyte rows[10];
    glyph('M', rows);
    glColor4f(1, 0, 0, 0.5f);
    window_pos(4.0f, 4.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    /* blending enabled after the bitmap: still not drawn when the
     * triangle is, which draws it with the state validated last */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glDisable(GL_BLEND);
    glColor4f(0, 1, 0, 1);
    fcu_rect(6.0f, 6.0f, 30.0f, 9.0f, 0.0f);
    /* a colour change makes a new cache: the first drawn first */
    glColor4f(0, 0, 1, 1);
    window_pos(4.0f, 20.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glColor4f(1, 1, 0, 1);
    window_pos(8.0f, 22.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    /* depth test enabled after the last bitmap but before the flush */
    window_pos(4.0f, 40.0f, 0.5f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    GLubyte px[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    fc_blob(h, "read", px, sizeof px);
    glDisable(GL_DEPTH_TEST);
    /* the scissor: a change with the test on draws the cache */
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 40, 64);
    window_pos(30.0f, 50.0f, 0.0f);
    glColor4f(1, 0, 1, 1);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glScissor(0, 0, 44, 64);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glDisable(GL_SCISSOR_TEST);
    fc_capture(h);
    /* fog changed after the bitmaps: the cache's program is the last
     * validated one, its constants (fog colour, end) the current ones */
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, -1.0f);
    glFogf(GL_FOG_END, 1.0f);
    GLfloat fred[4] = { 1, 0, 0, 1 }, fblue[4] = { 0, 0, 1, 1 };
    glFogfv(GL_FOG_COLOR, fred);
    glColor4f(0, 1, 0, 1);
    window_pos(40.0f, 30.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glFogfv(GL_FOG_COLOR, fblue);
    glFogf(GL_FOG_END, 3.0f);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFinish();
    glDisable(GL_FOG);
    /* a bitmap left in the cache at the end of a frame */
    window_pos(50.0f, 4.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_ONE);
    fc_capture(h);
}

/* Through the per-fragment operations: depth test at the raster depth,
 * alpha test, blending, stencil, fog (the fog coordinate of the quad is
 * 0), logic op, colour mask. */
static void bitmap_fragment_ops(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.3f, 0.3f, 0.3f, 0.5f, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLubyte rows[10];
    glyph('W', rows);
    /* a depth ramp to test against */
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    glColor3f(0.1f, 0.2f, 0.1f);
    glVertex3f(0, 0, 0.9f);
    glVertex3f(64, 0, -0.9f);
    glVertex3f(64, 64, -0.9f);
    glVertex3f(0, 64, 0.9f);
    glEnd();
    glColor3f(1, 1, 1);
    for (int i = 0; i < 7; i++) {
        window_pos(2.0f + 9.0f * (float)i, 2.0f, -0.5f + 0.16f * (float)i);
        glBitmap(8, 10, 0, 0, 0, 0, rows);
    }
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    for (int i = 0; i < 4; i++) {
        glColor4f(0.9f, 0.4f, 0.1f, 0.3f + 0.15f * (float)i);
        window_pos(2.0f + 9.0f * (float)i, 14.0f, 0.0f);
        glBitmap(8, 10, 0, 0, 0, 0, rows);
    }
    glDisable(GL_ALPHA_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.2f, 0.9f, 0.7f, 0.6f);
    window_pos(40.0f, 14.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glDisable(GL_BLEND);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, -1.0f);
    glFogf(GL_FOG_END, 3.0f);
    GLfloat fogc[4] = { 0.0f, 0.0f, 1.0f, 1.0f };
    glFogfv(GL_FOG_COLOR, fogc);
    glColor3f(1, 0, 0);
    window_pos(2.0f, 28.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.7f);
    window_pos(12.0f, 28.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glDisable(GL_FOG);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glColor3f(1, 1, 1);
    window_pos(24.0f, 28.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glDisable(GL_COLOR_LOGIC_OP);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glColor3f(1, 1, 1);
    window_pos(36.0f, 28.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_SCISSOR_TEST);
    glScissor(4, 40, 20, 5);
    glColor3f(0, 1, 1);
    window_pos(2.0f, 38.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glDisable(GL_SCISSOR_TEST);
    fc_capture(h);
}

static void bitmap_stencil(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0, 0, 0, 1, 1.0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLubyte rows[10];
    glyph('S', rows);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 5, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glColor3f(1, 0, 0);
    window_pos(4.0f, 4.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 4, 0, rows);
    glBitmap(8, 10, 0, 0, 4, 0, rows);
    glBitmap(8, 10, 0, 0, 4, 0, rows);
    /* show the stencil */
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (int i = 1; i <= 3; i++) {
        glStencilFunc(GL_EQUAL, i, 0xff);
        glColor3f(0.3f * (float)i, 1.0f, 0.2f);
        fcu_rect(0, 0, 32, 20, 0);
    }
    glDisable(GL_STENCIL_TEST);
    fc_capture(h);
}

/* Feedback: GL_BITMAP_TOKEN with the raster position, colour and texture
 * coordinate, and the move; selection: no hit, but the move. */
static void bitmap_feedback_select(fc_h *h)
{
    fc_pixel_ortho(h);
    GLfloat fb[96];
    for (int i = 0; i < 96; i++)
        fb[i] = -7.0f;
    GLubyte rows[10];
    glyph('F', rows);
    glFeedbackBuffer(96, GL_4D_COLOR_TEXTURE, fb);
    glRenderMode(GL_FEEDBACK);
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    glTexCoord4f(1, 2, 3, 4);
    window_pos(10.5f, 12.25f, 0.5f);
    glBitmap(8, 10, 1, 2, 3.5f, -1.5f, rows);
    glBitmap(8, 10, 1, 2, 3.5f, -1.5f, rows);
    glPassThrough(9.0f);
    window_pos(-3.0f, 5.0f, 0.0f);
    glBitmap(8, 10, 1, 2, 3.5f, -1.5f, rows);
    fc_value(h, "feedback count", glRenderMode(GL_RENDER));
    fc_blob(h, "feedback", fb, sizeof fb);
    raster_query(h, "after feedback");
    GLfloat fb2[32];
    for (int i = 0; i < 32; i++)
        fb2[i] = -7.0f;
    glFeedbackBuffer(32, GL_2D, fb2);
    glRenderMode(GL_FEEDBACK);
    window_pos(1.0f, 2.0f, 0.0f);
    glBitmap(0, 0, 0, 0, 1.0f, 1.0f, NULL);
    fc_value(h, "feedback 2d count", glRenderMode(GL_RENDER));
    fc_blob(h, "feedback 2d", fb2, sizeof fb2);

    GLuint sel[16];
    for (int i = 0; i < 16; i++)
        sel[i] = 0xdeadbeef;
    glSelectBuffer(16, sel);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(3);
    window_pos(10.0f, 10.0f, 0.25f);
    glLoadName(4);
    glBitmap(8, 10, 0, 0, 5, 5, rows);
    glLoadName(5);
    fc_value(h, "select hits", glRenderMode(GL_RENDER));
    fc_blob(h, "select", sel, sizeof sel);
    raster_query(h, "after select");
    /* back in GL_RENDER: the glyph at the raster position the selected
     * glBitmap moved */
    fcu_clear(0, 0, 0, 1, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);   /* rows: one byte a row */
    glBitmap(8, 10, 0, 0, 0, 0, rows);
    fc_capture(h);
}

static void bitmap_dlist(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLuint base = glGenLists(40);
    for (int c = 0; c < 40; c++) {
        GLubyte rows[10];
        glyph("0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ .-"[c], rows);
        glNewList(base + (GLuint)c, GL_COMPILE);
        glBitmap(8, 10, 0.0f, 2.0f, 9.0f, 0.0f, rows);
        glEndList();
    }
    /* the unpack state at compile time counts, not at replay */
    glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
    glListBase(base - '0');
    glColor3f(1, 1, 0);
    window_pos(2.0f, 50.0f, 0.0f);
    glCallLists(5, GL_UNSIGNED_BYTE, "12345");
    raster_query(h, "after list text");
    glPixelStorei(GL_UNPACK_LSB_FIRST, 0);
    /* compile and execute, and a list of moves */
    GLubyte rows[10];
    glyph('Z', rows);
    glColor3f(0, 1, 1);
    window_pos(2.0f, 30.0f, 0.0f);
    GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE_AND_EXECUTE);
    glBitmap(8, 10, 0.0f, 0.0f, 10.0f, 1.0f, rows);
    glBitmap(8, 10, 0.0f, 0.0f, 10.0f, 1.0f, rows);
    glEndList();
    fc_error(h, "compile and execute");
    glCallList(l);
    raster_query(h, "after list");
    /* an empty bitmap in a list */
    GLuint e = glGenLists(1);
    glNewList(e, GL_COMPILE);
    glBitmap(0, 0, 0.0f, 0.0f, 5.0f, -5.0f, rows);
    glEndList();
    fc_error(h, "empty bitmap compiled");
    window_pos(20.0f, 10.0f, 0.0f);
    glCallList(e);
    raster_query(h, "after empty list");
    fc_capture(h);
}

static void bitmap_errors(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    GLubyte rows[10] = { 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff };
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    window_pos(5.0f, 5.0f, 0.0f);
    glBitmap(-1, 10, 0, 0, 3, 3, rows);
    fc_error(h, "negative width");
    raster_query(h, "negative width");
    glBitmap(8, -2, 0, 0, 3, 3, rows);
    fc_error(h, "negative height");
    glBegin(GL_POINTS);
    glBitmap(8, 10, 0, 0, 3, 3, rows);
    glEnd();
    fc_error(h, "inside begin/end");
    raster_query(h, "after begin/end");
    glBitmap(8, 10, 0, 0, 3, 3, NULL);
    fc_error(h, "null bitmap");
    raster_query(h, "null bitmap");
    glBitmap(8, 10, 0, 0, 3, 3, rows);
    fc_capture(h);
}

/* ---- glDrawPixels ---- */

/* Each common format with GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and
 * GL_FLOAT. */
static void drawpixels_formats(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.3f, 0.4f, 0.5f, 1.0);
    static GLubyte ub[4 * 9 * 7];
    static GLushort us[4 * 9 * 7];
    static GLfloat f[4 * 9 * 7];
    make_rgba_ub(ub, 9, 7, 3);
    for (int i = 0; i < 4 * 9 * 7; i++)
        us[i] = (GLushort)(ub[i] * 257 + (i * 13) % 200);
    make_rgba_f(f, 9, 7, 5);
    static const GLenum formats[] = { GL_RGBA, GL_RGB, GL_LUMINANCE, GL_LUMINANCE_ALPHA,
                                      GL_ALPHA, GL_RED, GL_GREEN, GL_BLUE, GL_BGR, GL_BGRA };
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int i = 0; i < 10; i++) {
        const float x = 1.0f + 10.0f * (float)(i % 6);
        const float y = 1.0f + 24.0f * (float)(i / 6);
        window_pos(x, y, 0.0f);
        glDrawPixels(9, 7, formats[i], GL_UNSIGNED_BYTE, ub);
        window_pos(x, y + 8.0f, 0.0f);
        glDrawPixels(9, 7, formats[i], GL_UNSIGNED_SHORT, us);
        window_pos(x, y + 16.0f, 0.0f);
        glDrawPixels(9, 7, formats[i], GL_FLOAT, f);
        fc_error(h, "format");
    }
    fc_capture(h);
}

/* Zoom: integer, negative, fractional, with integer and fractional
 * raster positions, partly outside the window. */
static void drawpixels_zoom(fc_h *h)
{
    static GLubyte img[4 * 7 * 5];
    make_rgba_ub(img, 7, 5, 11);
    static const float zooms[][2] = {
        { 2.0f, 3.0f }, { -1.0f, 1.0f }, { 1.0f, -1.0f }, { -2.0f, -1.5f },
        { 0.5f, 0.5f }, { 1.5f, 2.25f }, { 0.75f, 1.3f }, { 3.3f, 0.6f },
        { 1.01f, 0.99f }, { 2.5f, -2.5f },
    };
    for (int frame = 0; frame < 2; frame++) {
        fc_pixel_ortho(h);
        fcu_clear(0, 0, 0, 1, 1.0);
        for (int i = 0; i < 10; i++) {
            glPixelZoom(zooms[i][0], zooms[i][1]);
            const float fx = frame ? 0.37f + 0.1f * (float)i : 0.0f;
            const float fy = frame ? 0.61f - 0.05f * (float)i : 0.0f;
            window_pos(12.0f + 24.0f * (float)(i % 4) + fx, 12.0f + 20.0f * (float)(i / 4) + fy,
                       0.0f);
            glDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, img);
        }
        /* partly outside: zoomed (clipped by the draw module) and not
         * (clipped on the CPU) */
        glPixelZoom(2.0f, 2.0f);
        window_pos(90.0f, 60.0f, 0.0f);
        glDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, img);
        glPixelZoom(-1.5f, 1.0f);
        window_pos(3.0f, 2.0f, 0.0f);
        glDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, img);
        glPixelZoom(1.0f, 1.0f);
        window_pos(93.0f, 1.0f, 0.0f);
        glDrawPixels(7, 5, GL_RGBA, GL_UNSIGNED_BYTE, img);
        glPixelZoom(1.0f, 1.0f);
        fc_capture(h);
    }
}

/* Pixel transfer: scale and bias (in the shader), colour maps. */
static void drawpixels_transfer(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    static GLubyte ub[4 * 16 * 8];
    static GLfloat f[4 * 16 * 8];
    make_rgba_ub(ub, 16, 8, 1);
    make_rgba_f(f, 16, 8, 2);
    window_pos(1, 1, 0);
    glDrawPixels(16, 8, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_GREEN_BIAS, 0.25f);
    glPixelTransferf(GL_BLUE_SCALE, -1.0f);
    glPixelTransferf(GL_BLUE_BIAS, 1.0f);
    glPixelTransferf(GL_ALPHA_SCALE, 1.7f);
    window_pos(20, 1, 0);
    glDrawPixels(16, 8, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    window_pos(40, 1, 0);
    glDrawPixels(16, 8, GL_RGBA, GL_FLOAT, f);
    window_pos(1, 12, 0);
    glDrawPixels(16, 8, GL_LUMINANCE, GL_UNSIGNED_BYTE, ub);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_GREEN_BIAS, 0.0f);
    glPixelTransferf(GL_BLUE_SCALE, 1.0f);
    glPixelTransferf(GL_BLUE_BIAS, 0.0f);
    glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
    /* transfer on float data out of [0, 1] */
    static GLfloat wide[4 * 8 * 4];
    for (int i = 0; i < 4 * 8 * 4; i++)
        wide[i] = -0.75f + 0.07f * (float)i;
    glPixelTransferf(GL_RED_SCALE, 0.25f);
    glPixelTransferf(GL_GREEN_SCALE, -0.5f);
    glPixelTransferf(GL_GREEN_BIAS, 0.6f);
    window_pos(20, 24, 0);
    glDrawPixels(8, 4, GL_RGBA, GL_FLOAT, wide);
    fc_capture(h);
}

/* The other types: signed and 32-bit integers, the packed types,
 * GL_ABGR_EXT, swapped bytes.  (The half-float and GL_RG entries are
 * foreign to GL 1.5: left out here, honesty/drawpixels_foreign_types draws
 * them; the other entries keep their places.) */
static void drawpixels_types_of(fc_h *h, int foreign)
{
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.3f, 0.4f, 0.5f, 1.0);
    static GLubyte raw[4 * 4 * 7 * 6];
    for (int i = 0; i < (int)sizeof raw; i++)
        raw[i] = (GLubyte)(i * 151 + (i >> 2) * 7 + 3);
    static const struct { GLenum format, type; } ft[] = {
        { GL_RGBA, GL_BYTE }, { GL_RGB, GL_SHORT }, { GL_LUMINANCE, GL_INT },
        { GL_RGBA, GL_UNSIGNED_INT }, { GL_LUMINANCE_ALPHA, GL_HALF_FLOAT },
        { GL_RGB, GL_UNSIGNED_BYTE_3_3_2 }, { GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV },
        { GL_RGB, GL_UNSIGNED_SHORT_5_6_5 }, { GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV },
        { GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4 }, { GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV },
        { GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1 }, { GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV },
        { GL_RGBA, GL_UNSIGNED_INT_8_8_8_8 }, { GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV },
        { GL_RGBA, GL_UNSIGNED_INT_10_10_10_2 }, { GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV },
        { GL_ABGR_EXT, GL_UNSIGNED_BYTE }, { GL_RG, GL_UNSIGNED_BYTE }, { GL_RG, GL_FLOAT },
        { GL_ALPHA, GL_SHORT }, { GL_BGR, GL_BYTE }, { GL_RED, GL_UNSIGNED_INT },
        { GL_LUMINANCE, GL_HALF_FLOAT },
    };
    static GLhalf half[4 * 7 * 6];
    for (int i = 0; i < 4 * 7 * 6; i++)
        half[i] = (GLhalf)(0x3000 + i * 37);   /* 0.125 .. about 1.9 */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    for (int i = 0; i < (int)(sizeof ft / sizeof ft[0]); i++) {
        if (fc_foreign_pixel(ft[i].format, ft[i].type) != foreign)
            continue;
        window_pos(1.0f + 9.0f * (float)(i % 7), 1.0f + 8.0f * (float)(i / 7), 0.0f);
        glDrawPixels(7, 6, ft[i].format, ft[i].type,
                     ft[i].type == GL_HALF_FLOAT ? (const void *)half : raw);
        fc_error(h, "type");
    }
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
    window_pos(1, 40, 0);
    glDrawPixels(7, 6, GL_RGB, GL_UNSIGNED_SHORT, raw);
    window_pos(10, 40, 0);
    glDrawPixels(7, 6, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, raw);
    window_pos(19, 40, 0);
    glDrawPixels(7, 6, GL_LUMINANCE, GL_FLOAT, raw);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    fc_capture(h);
}

/* GL_COLOR_INDEX images through the I_TO_R/G/B/A maps (the index shift
 * and offset do not apply to the texture), GL_BITMAP indices. */
static void drawpixels_color_index(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    static GLubyte idx[12 * 8];
    for (int i = 0; i < 12 * 8; i++)
        idx[i] = (GLubyte)(i * 7 % 16);
    window_pos(1, 1, 0);
    glDrawPixels(12, 8, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);  /* default maps: 0 */
    fc_error(h, "default maps");
    GLfloat r[16], g[16], b[16], a[16];
    for (int i = 0; i < 16; i++) {
        r[i] = (float)i / 15.0f;
        g[i] = (float)(15 - i) / 15.0f;
        b[i] = (float)((i * 5) % 16) / 15.0f + 0.2f;
        a[i] = 0.5f + (float)i * 0.03f;
    }
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 16, r);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 16, g);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 16, b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 16, a);
    window_pos(14, 1, 0);
    glDrawPixels(12, 8, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 2);
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    window_pos(27, 1, 0);
    glDrawPixels(12, 8, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    static GLushort idx16[12 * 8];
    for (int i = 0; i < 12 * 8; i++)
        idx16[i] = (GLushort)(i * 3 + 0x100);
    window_pos(40, 1, 0);
    glDrawPixels(12, 8, GL_COLOR_INDEX, GL_UNSIGNED_SHORT, idx16);
    GLubyte bits[8 * 2] = { 0xa5, 0x3c, 0xff, 0x00, 0x81, 0x7e, 0x55, 0xaa,
                            0x12, 0x34, 0x56, 0x78, 0x9a, 0xbc, 0xde, 0xf0 };
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    window_pos(1, 12, 0);
    glDrawPixels(16, 8, GL_COLOR_INDEX, GL_BITMAP, bits);
    fc_error(h, "bitmap indices");
    glPixelZoom(2.0f, 1.5f);
    window_pos(20, 12, 0);
    glDrawPixels(12, 8, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
    glPixelZoom(1.0f, 1.0f);
    fc_capture(h);
}

/* Depth and stencil images of the other types. */
static void drawpixels_zs_types(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0, 0, 0, 1, 0.5);
    glClear(GL_STENCIL_BUFFER_BIT);
    static GLubyte raw[4 * 16 * 8];   /* the largest image: 16x8 GL_UNSIGNED_INT */
    for (int i = 0; i < (int)sizeof raw; i++)
        raw[i] = (GLubyte)(i * 89 + 11);
    static GLfloat sf[10 * 8];
    for (int i = 0; i < 10 * 8; i++)
        sf[i] = (float)(i % 13) + 0.75f;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    static const GLenum dt[] = { GL_UNSIGNED_BYTE, GL_BYTE, GL_SHORT, GL_INT };
    for (int i = 0; i < 4; i++) {
        glColor3f(0.25f * (float)(i + 1), 1.0f, 0.5f);
        window_pos(1.0f + 11.0f * (float)i, 1.0f, 0.0f);
        glDrawPixels(10, 8, GL_DEPTH_COMPONENT, dt[i], raw);
        fc_error(h, "depth type");
    }
    /* (a GL_UNSIGNED_SHORT image where this drew GL_HALF_FLOAT, foreign to
     * GL 1.5) */
    window_pos(45, 1, 0);
    glDrawPixels(10, 8, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, raw);
    glPixelTransferf(GL_DEPTH_SCALE, 0.7f);
    glPixelTransferf(GL_DEPTH_BIAS, -0.1f);
    window_pos(1, 11, 0);
    glDrawPixels(10, 8, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, raw);
    glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
    glDisable(GL_DEPTH_TEST);
    /* (GL_STENCIL_INDEX with GL_BITMAP hangs the oracle's
     * st_choose_matching_format: ORACLE-NOTES.md) */
    window_pos(1, 22, 0);
    glDrawPixels(10, 8, GL_STENCIL_INDEX, GL_FLOAT, sf);
    window_pos(12, 22, 0);
    glDrawPixels(10, 8, GL_STENCIL_INDEX, GL_SHORT, raw);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
    window_pos(23, 22, 0);
    glDrawPixels(16, 8, GL_STENCIL_INDEX, GL_UNSIGNED_INT, raw);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    window_pos(40, 22, 0);
    glDrawPixels(16, 8, GL_STENCIL_INDEX, GL_BYTE, raw);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (int v = 0; v < 16; v++) {
        glStencilFunc(GL_EQUAL, v, 0x0f);
        glColor3ub((GLubyte)(v * 16), (GLubyte)(255 - v * 16), (GLubyte)(v * 53));
        fcu_rect(0, 20, 64, 32, 0);
    }
    glDisable(GL_STENCIL_TEST);
    fc_capture(h);
}

/* GL_DEPTH_STENCIL images: depth and stencil written (depth ALWAYS under
 * the depth mask, whatever GL_DEPTH_TEST), no colour; both packed types,
 * with and without a depth transfer and the stencil map. */
static void drawpixels_depth_stencil(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0, 0, 0, 1, 1.0);
    glClear(GL_STENCIL_BUFFER_BIT);
    /* room past one image: later draws start up to two pixels in */
    static GLuint zs[12 * 10 + 2];
    static GLfloat zf[2 * (12 * 10 + 2)];
    for (int i = 0; i < 12 * 10 + 2; i++) {
        zs[i] = ((GLuint)(i * 139810u) << 8) | (GLuint)(i % 7);
        GLuint st = (GLuint)(i % 5 + 8);
        zf[2 * i] = (float)i / 130.0f - 0.05f;
        memcpy(&zf[2 * i + 1], &st, 4);
    }
    glColor3f(1, 0, 0);
    window_pos(1, 1, 0);
    glDrawPixels(12, 10, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, zs);
    window_pos(14, 1, 0);
    glDrawPixels(12, 10, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zf);
    glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
    window_pos(27, 1, 0);
    glDrawPixels(12, 10, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, zs + 1);
    window_pos(40, 1, 0);
    glDrawPixels(12, 10, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zf + 2);
    glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
    GLfloat smap[8] = { 7, 6, 5, 4, 3, 2, 1, 0 };
    glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 8, smap);
    glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
    glDepthMask(GL_FALSE);
    glStencilMask(0x3);
    glPixelZoom(1.5f, 1.5f);
    window_pos(1, 14, 0);
    glDrawPixels(12, 10, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, zs + 2);
    glPixelZoom(1.0f, 1.0f);
    glStencilMask(0xff);
    glDepthMask(GL_TRUE);
    glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (int v = 0; v < 16; v++) {
        glStencilFunc(GL_EQUAL, v, 0xff);
        glColor3ub((GLubyte)(v * 16), (GLubyte)(255 - v * 16), (GLubyte)(v * 53));
        fcu_rect(0, 0, 64, 40, 0);
    }
    glDisable(GL_STENCIL_TEST);
    fc_capture(h);
}

/* The quad's rasterizer state is its own: polygon stipple, culling,
 * polygon modes, polygon offset, flat shading, smooth points and lines,
 * two-sided lighting do not touch pixel rectangles. */
static void pixels_raster_state(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    static GLubyte img[4 * 10 * 8];
    make_rgba_ub(img, 10, 8, 5);
    GLubyte stipple[128];
    for (int i = 0; i < 128; i++)
        stipple[i] = (GLubyte)(i & 1 ? 0xaa : 0x55);
    GLubyte rows[10];
    glyph('K', rows);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPolygonStipple(stipple);
    glEnable(GL_POLYGON_STIPPLE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(4.0f, 100.0f);
    glShadeModel(GL_FLAT);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x0f0f);
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glColor3f(1, 1, 0);
    window_pos(2, 2, 0.25f);
    glDrawPixels(10, 8, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glPixelZoom(1.5f, 2.0f);
    window_pos(14, 2, 0.25f);
    glDrawPixels(10, 8, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glPixelZoom(1.0f, 1.0f);
    window_pos(32, 2, 0.25f);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    glBitmap(8, 10, 0, 0, 9, 0, rows);
    window_pos(2, 24, 0.25f);
    glCopyPixels(2, 2, 28, 16, GL_COLOR);
    glDisable(GL_LIGHTING);
    fc_capture(h);
}

/* A 16-bit depth buffer: depth images and copies. */
static void pixels_depth16(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 0.6);
    static GLfloat zf[10 * 8];
    static GLushort zs[10 * 8];
    for (int i = 0; i < 10 * 8; i++) {
        zf[i] = (float)i / 79.0f;
        zs[i] = (GLushort)(i * 829);
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glColor3f(1, 0, 0);
    window_pos(2, 2, 0);
    glDrawPixels(10, 8, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    glColor3f(0, 1, 0);
    window_pos(14, 2, 0);
    glDrawPixels(10, 8, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, zs);
    glColor3f(0, 0, 1);
    window_pos(2, 14, 0);
    glCopyPixels(2, 2, 22, 8, GL_DEPTH);
    glDepthFunc(GL_GREATER);
    glColor3f(1, 0, 1);
    glPixelZoom(1.0f, 2.0f);
    window_pos(26, 2, 0);
    glCopyPixels(2, 2, 22, 8, GL_DEPTH);
    glPixelZoom(1.0f, 1.0f);
    glDisable(GL_DEPTH_TEST);
    fc_capture(h);
}

/* A stencil buffer without depth (S8): stencil images and copies; depth
 * images and copies are errors there. */
static void pixels_stencil_only_of(fc_h *h, int foreign)
{
    fc_pixel_ortho(h);
    glClearStencil(3);
    fcu_clear(0, 0, 0, 1, 1.0);
    glClear(GL_STENCIL_BUFFER_BIT);
    static GLubyte s[12 * 10];
    for (int i = 0; i < 12 * 10; i++)
        s[i] = (GLubyte)(i % 11);
    GLfloat z[4] = { 0.5f, 0.5f, 0.5f, 0.5f };
    window_pos(2, 2, 0);
    glDrawPixels(12, 10, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    window_pos(16, 2, 0);
    glCopyPixels(0, 0, 14, 12, GL_STENCIL);
    glDrawPixels(2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, z);
    fc_error(h, "depth image without depth");
    glCopyPixels(0, 0, 2, 2, GL_DEPTH);
    fc_error(h, "depth copy without depth");
    if (foreign) {
        glCopyPixels(0, 0, 2, 2, GL_DEPTH_STENCIL);
        fc_error(h, "depth stencil copy without depth");
        glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, z);
        fc_error(h, "depth stencil image without depth");
    }
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (int v = 0; v < 12; v++) {
        glStencilFunc(GL_EQUAL, v, 0xff);
        glColor3ub((GLubyte)(v * 20), (GLubyte)(255 - v * 20), (GLubyte)(v * 53));
        fcu_rect(0, 0, 32, 16, 0);
    }
    glDisable(GL_STENCIL_TEST);
    fc_capture(h);
}

/* No depth buffer at all. */
static void pixels_no_depth(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.5f, 0, 0, 1, 1.0);
    GLfloat z[4] = { 0.5f, 0.5f, 0.5f, 0.5f };
    window_pos(2, 2, 0);
    glDrawPixels(2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, z);
    fc_error(h, "depth image");
    glCopyPixels(0, 0, 2, 2, GL_DEPTH);
    fc_error(h, "depth copy");
    glCopyPixels(0, 0, 2, 2, GL_STENCIL);
    fc_error(h, "stencil copy");
    static GLubyte img[4 * 6 * 4];
    make_rgba_ub(img, 6, 4, 1);
    glEnable(GL_DEPTH_TEST);
    glDrawPixels(6, 4, GL_RGBA, GL_UNSIGNED_BYTE, img);
    fc_capture(h);
}

/* Degenerate and extreme zooms (zero, negative zero, tiny, huge: the
 * clipper's new vertices carry the texture coordinates), under a
 * perspective raster position; glDrawBuffer(GL_NONE) keeps depth. */
static void drawpixels_zoom_extreme(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    static GLubyte img[4 * 9 * 7];
    make_rgba_ub(img, 9, 7, 41);
    static const float z[][2] = {
        { 0.0f, 1.0f }, { 1.0f, 0.0f }, { -0.0f, -0.0f }, { 0.001f, 500.0f },
        { 300.0f, 0.05f }, { 1e4f, 1e4f }, { -7777.7f, 3.3f },
    };
    for (int i = 0; i < 7; i++) {
        glPixelZoom(z[i][0], z[i][1]);
        window_pos(3.0f + 8.0f * (float)i + 0.3f, 3.0f + 6.0f * (float)i + 0.7f, 0.0f);
        glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, img);
        fc_error(h, "zoom");
        if (i == 4 || i == 5)
            fc_capture(h);
    }
    glPixelZoom(1.0f, 1.0f);
    /* a perspective raster position: z and w from the projection */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glRasterPos3f(0.3f, -0.2f, -2.5f);
    glPixelZoom(2.0f, 2.0f);
    glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glRasterPos3f(-0.3f, 0.1f, -1.5f);
    glDrawBuffer(GL_NONE);
    glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glDrawBuffer(GL_FRONT);
    glPixelZoom(1.0f, 1.0f);
    GLfloat fb[32];
    for (int i = 0; i < 32; i++)
        fb[i] = -7.0f;
    glFeedbackBuffer(32, GL_4D_COLOR_TEXTURE, fb);
    glRenderMode(GL_FEEDBACK);
    glRasterPos4f(0.2f, 0.3f, -2.0f, 1.5f);
    glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, img);
    fc_value(h, "feedback count", glRenderMode(GL_RENDER));
    fc_blob(h, "feedback", fb, sizeof fb);
    glDisable(GL_DEPTH_TEST);
    fc_capture(h);
}

/* GL_MAP_COLOR through the shader's pixel-map lookups (see
 * known-differences.txt: the second lookup of nir_lower_drawpixels). */
static void drawpixels_map_color(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    static GLubyte ub[4 * 16 * 8];
    static GLfloat f[4 * 16 * 8];
    make_rgba_ub(ub, 16, 8, 1);
    make_rgba_f(f, 16, 8, 2);
    /* colour maps of different sizes */
    GLfloat rmap[256], gmap[7], bmap[64], amap[2];
    for (int i = 0; i < 256; i++)
        rmap[i] = 1.0f - (float)i / 255.0f;
    for (int i = 0; i < 7; i++)
        gmap[i] = (float)(i * i) / 36.0f;
    for (int i = 0; i < 64; i++)
        bmap[i] = (float)((i * 5) % 64) / 63.0f;
    amap[0] = 0.2f;
    amap[1] = 0.9f;
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, rmap);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 7, gmap);
    glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 64, bmap);
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, amap);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    window_pos(20, 12, 0);
    glDrawPixels(16, 8, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    window_pos(40, 12, 0);
    glDrawPixels(16, 8, GL_RGBA, GL_FLOAT, f);
    glPixelTransferf(GL_RED_BIAS, 0.3f);
    window_pos(1, 24, 0);
    glDrawPixels(16, 8, GL_RGB, GL_UNSIGNED_BYTE, ub);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    glPixelTransferf(GL_RED_BIAS, 0.0f);
    fc_capture(h);
}

/* Through the fragment operations: depth test at the raster depth,
 * blending, alpha test, fog, logic op, colour mask, scissor. */
static void drawpixels_fragment_ops(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.3f, 0.3f, 0.3f, 0.5f, 1.0);
    static GLubyte ub[4 * 12 * 10];
    make_rgba_ub(ub, 12, 10, 9);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    glColor3f(0.1f, 0.2f, 0.1f);
    glVertex3f(0, 0, 0.9f);
    glVertex3f(64, 0, -0.9f);
    glVertex3f(64, 64, -0.9f);
    glVertex3f(0, 64, 0.9f);
    glEnd();
    for (int i = 0; i < 4; i++) {
        window_pos(2.0f + 14.0f * (float)i, 2.0f, -0.6f + 0.4f * (float)i);
        glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    }
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    window_pos(2, 14, 0);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glBlendFunc(GL_ONE, GL_ONE);
    glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
    window_pos(16, 14, 0);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_LESS, 0.6f);
    window_pos(30, 14, 0);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glDisable(GL_ALPHA_TEST);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, -2.0f);
    glFogf(GL_FOG_END, 2.0f);
    GLfloat fogc[4] = { 1.0f, 0.0f, 1.0f, 1.0f };
    glFogfv(GL_FOG_COLOR, fogc);
    window_pos(44, 14, 0.5f);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 1.3f);
    window_pos(2, 26, 0);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glDisable(GL_FOG);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_AND_REVERSE);
    window_pos(16, 26, 0);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glDisable(GL_COLOR_LOGIC_OP);
    glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_FALSE);
    window_pos(30, 26, 0);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_SCISSOR_TEST);
    glScissor(46, 28, 7, 5);
    window_pos(44, 26, 0);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelZoom(1.5f, 1.5f);
    glScissor(3, 40, 12, 9);
    window_pos(2, 38, 0);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelZoom(1.0f, 1.0f);
    glDisable(GL_SCISSOR_TEST);
    /* lighting with separate specular: no secondary colour reaches it */
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    window_pos(30, 40, 0);
    glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glDisable(GL_LIGHTING);
    fc_capture(h);
}

/* Unpack state: skip pixels and rows, row length, alignment; clipped
 * with zoom 1 on every side. */
static void drawpixels_unpack(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    static GLubyte ub[4 * 20 * 16 + 64];
    make_rgba_ub(ub, 20, 16, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 20);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
    window_pos(2, 2, 0);
    glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    window_pos(14, 2, 0);
    glDrawPixels(7, 5, GL_RGB, GL_UNSIGNED_BYTE, ub);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    window_pos(24, 2, 0);
    glDrawPixels(7, 5, GL_LUMINANCE, GL_UNSIGNED_BYTE, ub);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    /* clipped by the window on each side */
    window_pos(-5, 20, 0);   /* invalid: nothing */
    glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    window_pos(0, 20, 0);
    glBitmap(0, 0, 0, 0, -4, -3, NULL);   /* move outside, still valid */
    glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    window_pos(58, 44, 0);
    glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    window_pos(30, 30, 0);
    glBitmap(0, 0, 0, 0, 0.4999f, -0.5f, NULL);
    glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    fc_capture(h);
}

/* GL_DEPTH_COMPONENT: the image's depth through the depth test, the
 * raster colour written; depth scale and bias. */
static void drawpixels_depth(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 0.5);
    static GLfloat zf[12 * 10];
    static GLushort zs[12 * 10];
    static GLuint zi[12 * 10];
    for (int i = 0; i < 12 * 10; i++) {
        zf[i] = (float)i / 119.0f * 1.2f - 0.1f;
        zs[i] = (GLushort)(i * 551);
        zi[i] = (GLuint)i * 35791394u + 12345u;
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glColor3f(1, 0, 0);
    window_pos(2, 2, 0.9f);
    glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    glColor3f(0, 1, 0);
    window_pos(16, 2, 0.9f);
    glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, zs);
    glColor3f(0, 0, 1);
    window_pos(30, 2, 0.9f);
    glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zi);
    glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.3f);
    glColor3f(1, 1, 0);
    window_pos(44, 2, 0);
    glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    window_pos(2, 16, 0);
    glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, zs);
    window_pos(16, 16, 0);
    glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zi);
    glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
    /* zoomed, and with the depth test off (no depth write) */
    glPixelZoom(2.0f, -1.5f);
    glColor3f(0, 1, 1);
    window_pos(30, 40, 0);
    glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    glPixelZoom(1.0f, 1.0f);
    glDisable(GL_DEPTH_TEST);
    glColor3f(1, 0, 1);
    window_pos(2, 40, 0);
    glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_FALSE);
    glColor3f(1, 1, 1);
    window_pos(50, 40, 0);
    glDrawPixels(12, 10, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    glDepthMask(GL_TRUE);
    fc_capture(h);
}

/* GL_STENCIL_INDEX: written with the stencil write mask whatever the
 * stencil test; GL_MAP_STENCIL applies, the index shift does not. */
static void drawpixels_stencil(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0x10);
    fcu_clear(0, 0, 0, 1, 1.0);
    glClear(GL_STENCIL_BUFFER_BIT);
    static GLubyte s[16 * 12];
    static GLushort s16[16 * 12];
    for (int i = 0; i < 16 * 12; i++) {
        s[i] = (GLubyte)((i % 16) / 4 + (i / 16) / 3 * 4);
        s16[i] = (GLushort)(s[i] + 0x300);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 0, 0);
    window_pos(2, 2, 0);
    glDrawPixels(16, 12, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    glStencilMask(0x0c);
    window_pos(20, 2, 0);
    glDrawPixels(16, 12, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, s16);
    glStencilMask(0xff);
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 3);
    window_pos(38, 2, 0);
    glDrawPixels(16, 12, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    GLfloat smap[16];
    for (int i = 0; i < 16; i++)
        smap[i] = (float)(15 - i);
    glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 16, smap);
    glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
    glPixelZoom(1.5f, -1.25f);
    window_pos(2, 40, 0);
    glDrawPixels(16, 12, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    glPixelZoom(1.0f, 1.0f);
    /* a new array: unsigned bytes are copied as they are (memcpy
     * texstore: no map), shorts go through the map */
    static GLubyte s2[16 * 12];
    memcpy(s2, s, sizeof s2);
    window_pos(26, 40, 0);
    glDrawPixels(16, 12, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s2);
    static GLushort s3[16 * 12];
    for (int i = 0; i < 16 * 12; i++)
        s3[i] = s[i];
    window_pos(44, 40, 0);
    glDrawPixels(16, 12, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, s3);
    glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
    /* show the stencil values */
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (int v = 0; v < 32; v++) {
        glStencilFunc(GL_EQUAL, v, 0xff);
        glColor3ub((GLubyte)(v * 8), (GLubyte)(255 - v * 8), (GLubyte)(v * 37));
        fcu_rect(0, 0, 64, 64, 0);
    }
    glDisable(GL_STENCIL_TEST);
    fc_capture(h);
}

static void drawpixels_errors_of(fc_h *h, int foreign)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    GLubyte img[4 * 4 * 4];
    memset(img, 200, sizeof img);
    window_pos(2, 2, 0);
    glDrawPixels(-1, 4, GL_RGBA, GL_UNSIGNED_BYTE, img);
    fc_error(h, "negative width");
    glDrawPixels(4, 4, GL_RGBA, GL_BITMAP, img);
    fc_error(h, "rgba bitmap");
    glDrawPixels(4, 4, 0x1234, GL_UNSIGNED_BYTE, img);
    fc_error(h, "bad format");
    glDrawPixels(4, 4, GL_RGBA, 0x1234, img);
    fc_error(h, "bad type");
    glDrawPixels(4, 4, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, img);
    fc_error(h, "packed mismatch");
    if (foreign) {
        glDrawPixels(4, 4, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, img);
        fc_error(h, "integer format");
    }
    glDrawPixels(4, 4, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, img);
    fc_error(h, "no stencil buffer");
    if (foreign) {
        glDrawPixels(4, 4, GL_DEPTH_STENCIL, GL_UNSIGNED_BYTE, img);
        fc_error(h, "depth stencil bad type");
        glDrawPixels(4, 4, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, img);
        fc_error(h, "depth stencil no stencil");
    }
    glDrawPixels(4, 4, GL_INTENSITY, GL_UNSIGNED_BYTE, img);
    fc_error(h, "intensity");
    glBegin(GL_POINTS);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glEnd();
    fc_error(h, "inside begin/end");
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "null pixels");
    window_pos(100, 100, 0);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "null pixels invalid position");
    window_pos(30, 30, 0);
    glBitmap(0, 0, 0, 0, 40, 0, NULL);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "null pixels clipped away");
    glDrawPixels(0, 4, GL_RGBA, GL_UNSIGNED_BYTE, img);
    fc_error(h, "zero width");
    window_pos(5, 5, 0);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, img);
    fc_capture(h);
}

static void drawpixels_feedback_dlist(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    static GLubyte ub[4 * 8 * 6];
    make_rgba_ub(ub, 8, 6, 21);
    GLfloat fb[64];
    for (int i = 0; i < 64; i++)
        fb[i] = -7.0f;
    glFeedbackBuffer(64, GL_3D_COLOR, fb);
    glRenderMode(GL_FEEDBACK);
    glColor4f(0.5f, 0.25f, 1.0f, 0.75f);
    window_pos(3.5f, 4.25f, 0.125f);
    glDrawPixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glCopyPixels(0, 0, 4, 4, GL_COLOR);
    glDrawPixels(8, 6, GL_RGBA, GL_BITMAP, ub);
    fc_value(h, "feedback count", glRenderMode(GL_RENDER));
    fc_error(h, "feedback error");
    fc_blob(h, "feedback", fb, sizeof fb);
    GLuint sel[8];
    for (int i = 0; i < 8; i++)
        sel[i] = 0xdeadbeef;
    glSelectBuffer(8, sel);
    glRenderMode(GL_SELECT);
    glPushName(1);
    glDrawPixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glCopyPixels(0, 0, 4, 4, GL_COLOR);
    fc_value(h, "select hits", glRenderMode(GL_RENDER));
    fc_blob(h, "select", sel, sizeof sel);

    /* display lists: the image is copied with the compile-time unpack */
    GLuint l = glGenLists(2);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 8);
    glNewList(l, GL_COMPILE);
    glDrawPixels(6, 6, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glEndList();
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
    window_pos(20, 20, 0);
    glDrawPixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glCopyPixels(20, 20, 8, 6, GL_COLOR);
    glEndList();
    window_pos(2, 2, 0);
    glCallList(l);
    glPixelZoom(2, 2);
    window_pos(40, 2, 0);
    glCallList(l + 1);
    glPixelZoom(1, 1);
    fc_error(h, "lists");
    fc_capture(h);
}

/* ---- glCopyPixels ---- */

static void copy_scene(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.1f, 0.1f, 1.0f, 1.0);
    static GLubyte ub[4 * 24 * 20];
    make_rgba_ub(ub, 24, 20, 17);
    window_pos(8, 8, 0);
    glDrawPixels(24, 20, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(40, 4, 0.5f);
    glColor3f(0, 1, 0);
    glVertex3f(60, 10, -0.5f);
    glColor3f(0, 0, 1);
    glVertex3f(44, 30, 0.0f);
    glEnd();
}

/* Overlapping copies in every direction (the texture path keeps the
 * source intact), a disjoint copy (the blit), zoom 1. */
static void copypixels_overlap(fc_h *h)
{
    static const int moves[][2] = { { 3, 0 }, { -3, 0 }, { 0, 4 }, { 0, -4 }, { 5, -2 } };
    for (int i = 0; i < 5; i++) {
        copy_scene(h);
        window_pos(8.0f + (float)moves[i][0], 8.0f + (float)moves[i][1], 0.0f);
        glCopyPixels(8, 8, 24, 20, GL_COLOR);
        fc_error(h, "overlap");
        fc_capture(h);
    }
    copy_scene(h);
    /* disjoint: a blit, which ignores the colour mask */
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    window_pos(36, 34, 0);
    glCopyPixels(8, 8, 24, 20, GL_COLOR);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    /* partly outside the window as source and as destination */
    window_pos(2, 40, 0);
    glCopyPixels(40, 0, 30, 12, GL_COLOR);
    fc_capture(h);
}

/* With zoom and with per-fragment state (the texture path). */
static void copypixels_zoom_ops(fc_h *h)
{
    copy_scene(h);
    glPixelZoom(2.0f, 1.5f);
    window_pos(2, 30, 0);
    glCopyPixels(8, 8, 12, 10, GL_COLOR);
    glPixelZoom(-1.0f, -1.0f);
    window_pos(60, 60, 0);
    glCopyPixels(8, 8, 12, 10, GL_COLOR);
    glPixelZoom(0.5f, 0.75f);
    window_pos(40, 40, 0);
    glCopyPixels(8, 8, 24, 20, GL_COLOR);
    glPixelZoom(1.0f, 1.0f);
    fc_capture(h);
    copy_scene(h);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    window_pos(30, 30, 0);
    glCopyPixels(8, 8, 24, 20, GL_COLOR);
    glDisable(GL_BLEND);
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_BLUE_BIAS, 0.2f);
    window_pos(2, 40, 0);
    glCopyPixels(8, 8, 20, 20, GL_COLOR);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_BLUE_BIAS, 0.0f);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.4f);
    window_pos(40, 2, 0);
    glCopyPixels(8, 8, 20, 20, GL_COLOR);
    glDisable(GL_FOG);
    /* overlap with zoom 1 but blending: texture path */
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GEQUAL, 0.5f);
    window_pos(10, 10, 0);
    glCopyPixels(8, 8, 24, 20, GL_COLOR);
    glDisable(GL_ALPHA_TEST);
    fc_capture(h);
}

/* GL_DEPTH: the depth copied (through the depth test, with the current
 * colour, on the texture path; straight on the blit path). */
static void copypixels_depth(fc_h *h)
{
    copy_scene(h);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    glColor3f(0.2f, 0.4f, 0.2f);
    glVertex3f(0, 0, 0.9f);
    glVertex3f(64, 0, -0.9f);
    glVertex3f(64, 20, 0.7f);
    glVertex3f(0, 20, 0.1f);
    glEnd();
    glDepthFunc(GL_LESS);
    glColor3f(1, 1, 0);
    window_pos(2, 30, 0);
    glCopyPixels(0, 0, 30, 20, GL_DEPTH);        /* disjoint, zoom 1: blit */
    glColor3f(0, 1, 1);
    window_pos(4, 4, 0);
    glCopyPixels(0, 0, 30, 16, GL_DEPTH);        /* overlap: texture path */
    glPixelZoom(1.5f, 1.0f);
    glColor3f(1, 0, 1);
    window_pos(34, 22, 0);
    glCopyPixels(0, 0, 20, 20, GL_DEPTH);
    glPixelZoom(1.0f, 1.0f);
    glDisable(GL_DEPTH_TEST);
    fc_capture(h);
    /* read the depth back */
    static GLfloat z[64 * 64];
    glReadPixels(0, 0, 64, 64, GL_DEPTH_COMPONENT, GL_FLOAT, z);
    fc_blob(h, "depth", z, sizeof z);
}

static void copypixels_stencil(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0);
    fcu_clear(0, 0, 0, 1, 1.0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    fcu_tri(2, 2, 30, 6, 10, 28);
    fcu_tri(4, 20, 28, 2, 24, 26);
    fcu_rect(8, 8, 20, 14, 0);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    window_pos(34, 2, 0);
    glCopyPixels(0, 0, 30, 30, GL_STENCIL);       /* blit */
    window_pos(3, 34, 0);
    glCopyPixels(0, 0, 30, 28, GL_STENCIL);
    window_pos(5, 1, 0);
    glStencilMask(0x06);
    glCopyPixels(0, 0, 20, 20, GL_STENCIL);       /* overlap */
    glStencilMask(0xff);
    glPixelZoom(1.0f, 0.5f);
    window_pos(34, 34, 0);
    glCopyPixels(0, 0, 30, 30, GL_STENCIL);
    glPixelZoom(1.0f, 1.0f);
    for (int v = 0; v < 8; v++) {
        glStencilFunc(GL_EQUAL, v, 0xff);
        glColor3ub((GLubyte)(v * 32), (GLubyte)(255 - v * 32), (GLubyte)(v * 97));
        fcu_rect(0, 0, 64, 64, 0);
    }
    glDisable(GL_STENCIL_TEST);
    fc_capture(h);
}

static void copypixels_errors_of(fc_h *h, int foreign)
{
    copy_scene(h);
    window_pos(30, 30, 0);
    glCopyPixels(0, 0, -1, 5, GL_COLOR);
    fc_error(h, "negative width");
    glCopyPixels(0, 0, 5, 5, GL_RGBA);
    fc_error(h, "bad type");
    glCopyPixels(0, 0, 5, 5, GL_STENCIL);
    fc_error(h, "no stencil");
    if (foreign) {
        glCopyPixels(0, 0, 5, 5, GL_DEPTH_STENCIL);
        fc_error(h, "no depth stencil");
        glCopyPixels(0, 0, 5, 5, 0x886E /* GL_DEPTH_STENCIL_TO_RGBA_NV */);
        fc_error(h, "nv type");
    }
    glBegin(GL_POINTS);
    glCopyPixels(0, 0, 5, 5, GL_COLOR);
    glEnd();
    fc_error(h, "inside begin/end");
    glReadBuffer(GL_NONE);
    glCopyPixels(0, 0, 5, 5, GL_COLOR);
    fc_error(h, "no read buffer");
    glReadBuffer(GL_FRONT);
    glCopyPixels(0, 0, 0, 5, GL_COLOR);
    fc_error(h, "zero width");
    fc_capture(h);
}

/* GL_DEPTH_STENCIL_TO_RGBA_NV / BGRA_NV (NV_copy_depth_to_color): the
 * depth and stencil bytes as a colour. */
static void copypixels_depth_to_color(fc_h *h)
{
    fc_pixel_ortho(h);
    glClearStencil(0x5a);
    fcu_clear(0, 0, 0, 1, 0.3);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0xc3, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 1);
    glVertex3f(1, 1, -0.8f);
    glVertex3f(30, 4, 0.6f);
    glVertex3f(8, 30, 0.1f);
    glEnd();
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    window_pos(32, 0, 0);
    glCopyPixels(0, 0, 32, 32, GL_DEPTH_STENCIL_TO_RGBA_NV);
    fc_error(h, "rgba");
    window_pos(0, 32, 0);
    glCopyPixels(0, 0, 32, 32, GL_DEPTH_STENCIL_TO_BGRA_NV);
    fc_error(h, "bgra");
    glPixelZoom(0.5f, 0.5f);
    window_pos(40, 40, 0);
    glCopyPixels(0, 0, 32, 32, GL_DEPTH_STENCIL_TO_RGBA_NV);
    glPixelZoom(1, 1);
    fc_capture(h);
}

/* Cache edges: a run of bitmaps wider than the 512-texel cache, bitmaps
 * above and below the rows it holds, raster depths within and beyond its
 * 1e-6, -0 and 0 colours, a 32-row bitmap (not centred), one just wider
 * than the cache; glDrawPixels and glCopyPixels after bitmaps. */
static void bitmap_cache_edges(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLubyte rows[34 * 2];
    for (int i = 0; i < 68; i++)
        rows[i] = (GLubyte)(0x81 ^ (i * 37));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glColor3f(1, 1, 1);
    window_pos(1, 1, 0);
    for (int i = 0; i < 70; i++) {
        glColor3f((float)(i % 3) * 0.5f, 1.0f, 0.25f);
        glBitmap(9, 6, 0, 0, 9.0f, (i % 5 == 4) ? -1.0f : 0.5f, rows);
    }
    /* depth: same within 1e-6, then beyond */
    glColor3f(1, 0, 0);
    window_pos(2, 20, 0.5f);
    glBitmap(9, 6, 0, 0, 9.0f, 0.0f, rows);
    window_pos(11, 20, 0.5000005f);
    glBitmap(9, 6, 0, 0, 9.0f, 0.0f, rows);
    window_pos(20, 20, 0.502f);
    glBitmap(9, 6, 0, 0, 9.0f, 0.0f, rows);
    /* colours -0 and 0 compare equal */
    glColor3f(-0.0f, 1.0f, 0.0f);
    window_pos(30, 20, 0.0f);
    glBitmap(9, 6, 0, 0, 9.0f, 0.0f, rows);
    glColor3f(0.0f, 1.0f, 0.0f);
    window_pos(39, 20, 0.0f);
    glBitmap(9, 6, 0, 0, 9.0f, 0.0f, rows);
    /* rows above and below the cache's */
    glColor3f(0, 0, 1);
    window_pos(2, 40, 0);
    glBitmap(9, 6, 0, 0, 0.0f, 14.0f, rows);
    glBitmap(9, 6, 0, 0, 0.0f, -28.0f, rows);
    glBitmap(16, 32, 0, 0, 20.0f, 0.0f, rows);
    glBitmap(16, 33, 0, 0, 20.0f, 0.0f, rows);
    glDisable(GL_DEPTH_TEST);
    /* a DrawPixels, a CopyPixels right after bitmaps */
    static GLubyte img[4 * 6 * 5];
    make_rgba_ub(img, 6, 5, 3);
    glColor3f(1, 1, 0);
    window_pos(50, 50, 0);
    glBitmap(9, 6, 0, 0, 0.0f, 0.0f, rows);
    glDrawPixels(6, 5, GL_RGBA, GL_UNSIGNED_BYTE, img);
    window_pos(50, 40, 0);
    glBitmap(9, 6, 0, 0, 0.0f, 0.0f, rows);
    window_pos(56, 30, 0);
    glCopyPixels(50, 40, 9, 6, GL_COLOR);
    fc_capture(h);
}

/* Zoomed images crossing each window edge, large and tiny zooms, zoom
 * under a scissor, a zoomed image entirely outside. */
static void drawpixels_zoom_clip(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1.0);
    static GLubyte img[4 * 9 * 7];
    make_rgba_ub(img, 9, 7, 29);
    static const float cfg[][4] = {
        { -5.0f, 20.0f, 2.5f, 1.5f },  { 60.0f, 10.0f, 1.75f, 2.0f },
        { 20.0f, -6.0f, 1.5f, 3.0f },  { 30.0f, 60.0f, 2.0f, 1.25f },
        { 5.0f, 5.0f, -2.0f, -2.0f },  { 60.0f, 60.0f, -1.5f, 3.5f },
        { 40.0f, 30.0f, 7.3f, 5.1f },  { 10.0f, 40.0f, 0.1f, 0.2f },
        { 100.0f, 10.0f, 2.0f, 2.0f }, { 45.0f, 2.0f, 0.33f, 4.0f },
    };
    for (int i = 0; i < 10; i++) {
        glPixelZoom(cfg[i][2], cfg[i][3]);
        window_pos(2, 2, 0);
        glBitmap(0, 0, 0, 0, cfg[i][0] - 2.0f, cfg[i][1] - 2.0f, NULL);
        glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, img);
        if (i == 6)
            fc_capture(h);
    }
    glEnable(GL_SCISSOR_TEST);
    glScissor(10, 10, 13, 17);
    glPixelZoom(3.0f, 3.0f);
    window_pos(5, 5, 0);
    glDrawPixels(9, 7, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glDisable(GL_SCISSOR_TEST);
    glPixelZoom(1.0f, 1.0f);
    fc_capture(h);
}

/* glCopyPixels under the scissor (the blit clips to it), a copy reading
 * bitmaps still in the cache, and from a display list. */
static void copypixels_scissor_list(fc_h *h)
{
    copy_scene(h);
    glEnable(GL_SCISSOR_TEST);
    glScissor(36, 30, 20, 12);
    window_pos(34, 28, 0);
    glCopyPixels(8, 8, 24, 20, GL_COLOR);        /* blit, clipped */
    glScissor(10, 10, 12, 9);
    window_pos(12, 11, 0);
    glCopyPixels(8, 8, 24, 20, GL_COLOR);        /* overlap, texture path */
    glDisable(GL_SCISSOR_TEST);
    GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glCopyPixels(40, 4, 20, 20, GL_COLOR);
    glEndList();
    window_pos(2, 40, 0);
    glCallList(l);
    glPixelZoom(0.5f, -0.5f);
    window_pos(40, 63, 0);
    glCallList(l);
    glPixelZoom(1.0f, 1.0f);
    fc_capture(h);
}

/* ---- textured pixel rectangles ---- */

/* A 2D texture of `size` texels with every mip level (a colour pattern
 * of its own per level) or only level 0, on the active unit. */
static void tex2d_levels(GLuint name, int size, bool mips, unsigned seed)
{
    glBindTexture(GL_TEXTURE_2D, name);
    static GLubyte img[64 * 64 * 4];
    for (int level = 0, s = size; s >= 1; level++, s /= 2) {
        make_rgba_ub(img, s, s, seed + (unsigned)level * 7u);
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
        if (!mips)
            break;
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                    mips ? GL_LINEAR_MIPMAP_NEAREST : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

/* A textured triangle with per-vertex coordinates on the units in
 * `units` (they become the fragment program's varyings). */
static void textured_tri(unsigned units)
{
    static const float v[3][4] = { { 2, 2, 0.1f, 0.2f }, { 20, 3, 0.9f, 0.1f }, { 4, 22, 0.3f, 0.8f } };
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; i++) {
        for (int u = 0; u < 2; u++)
            if (units & (1u << u))
                glMultiTexCoord2f(GL_TEXTURE0 + (GLenum)u, v[i][2], v[i][3]);
        glVertex2f(v[i][0], v[i][1]);
    }
    glEnd();
}

/* glBitmap under a mipmapped 2D texture: with the coordinate varying
 * (in the last draw's vertex format, or made by texgen or the texture
 * matrix) the unit reads the bitmap quad's own 0..1 coordinate, whose
 * derivatives pick the level (a bitmap too big for the cache spans its
 * own texture; a cached one the 512x32 cache); otherwise the current
 * coordinate, the same at every pixel (magnified). */
static void bitmap_textured_2d(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.1f, 0.1f, 1.0f, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    tex2d_levels(1, 64, true, 11u);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    GLubyte tall[8 * 40], rows[10];
    for (int i = 0; i < (int)sizeof tall; i++)
        tall[i] = (GLubyte)(0xff ^ (i * 37));
    glyph('W', rows);
    for (int frame = 0; frame < 4; frame++) {
        glColor4f(1, 1, 1, 1);
        if (frame == 2) {
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
            glEnable(GL_TEXTURE_GEN_S);
        } else if (frame == 3) {
            glDisable(GL_TEXTURE_GEN_S);
            glMatrixMode(GL_TEXTURE);
            glLoadIdentity();
            glScalef(2.0f, 0.5f, 1.0f);
            glMatrixMode(GL_MODELVIEW);
        }
        /* frame 1: the coordinate outside the batch's vertex format */
        textured_tri(frame == 1 ? 0u : 1u);
        glTexCoord4f(0.7f, 0.3f, 0.0f, 1.0f);
        window_pos(24.0f + 2.0f * (float)frame, 4.0f, 0.0f);
        glBitmap(64, 40, 0, 0, 0, 0, tall);
        window_pos(4.0f, 48.0f, 0.0f);
        glBitmap(8, 10, 0, 0, 10, 0, rows);
        glBitmap(8, 10, 0, 0, 10, 0, rows);
        glFinish();
        fc_capture(h);
        fcu_clear(0.1f, 0.1f, 0.1f, 1.0f, 1.0);
    }
}

/* An array draw call changes which coordinates the fragment program reads
 * as varyings before it validates anything, so one that draws nothing
 * (an empty draw, a glMultiDrawArrays or glMultiDrawElements whose first
 * count is 0, an invalid count) still decides how the next
 * glBitmap's unit 0 reads its coordinate: the enabled coordinate array
 * makes it the quad's own (mipmapped by its derivatives), a disabled one
 * the current coordinate.  Frame 5: the triangle's coordinate varies, the
 * empty draw has no coordinate array.  Found with random-tex/s1-i892. */
static void bitmap_textured_empty_draws(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.1f, 0.1f, 1.0f, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    tex2d_levels(1, 64, true, 5u);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    GLubyte tall[8 * 40];
    for (int i = 0; i < (int)sizeof tall; i++)
        tall[i] = (GLubyte)(0xff ^ (i * 29));
    static const GLfloat pos[3][2] = { { 60, 60 }, { 61, 60 }, { 60, 61 } };
    static const GLfloat tc[3][2] = { { 0.2f, 0.4f }, { 0.6f, 0.1f }, { 0.9f, 0.9f } };
    static const GLint first[2] = { 0, 0 };
    static const GLsizei counts[2] = { 0, 3 };
    static const GLubyte idx[3] = { 0, 1, 2 };
    const GLvoid *const idxs[2] = { idx, idx };
    static const GLsizei ecounts[2] = { 0, 3 };
    for (int frame = 0; frame < 6; frame++) {
        glColor4f(1, 1, 1, 1);
        textured_tri(frame == 5 ? 1u : 0u);
        glVertexPointer(2, GL_FLOAT, 0, pos);
        glTexCoordPointer(2, GL_FLOAT, 0, tc);
        glEnableClientState(GL_VERTEX_ARRAY);
        if (frame != 5)
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        switch (frame) {
        case 0: glDrawArrays(GL_POINTS, 0, 0); break;
        case 1: glMultiDrawArrays(GL_POINTS, first, counts, 2); break;
        case 2: glDrawArrays(GL_POINTS, 0, -1); break;
        case 3: glDrawElements(GL_POINTS, 0, GL_UNSIGNED_BYTE, idx); break;
        case 4: glMultiDrawElements(GL_POINTS, ecounts, GL_UNSIGNED_BYTE, idxs, 2); break;
        default: glDrawArrays(GL_TRIANGLES, 0, 2); break;
        }
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoord4f(0.7f, 0.3f, 0.0f, 1.0f);
        window_pos(24.0f, 4.0f, 0.0f);
        glBitmap(64, 40, 0, 0, 0, 0, tall);
        glFinish();
        fc_capture(h);
        fcu_clear(0.1f, 0.1f, 0.1f, 1.0f, 1.0);
    }
}

/* glDrawPixels and glCopyPixels under two units: unit 0 reads the current
 * coordinate of unit 0 (nir_lower_drawpixels' gl_TexCoord[0]), unit 1
 * (0, 0, 0, 0) whatever its current coordinate; both magnified.  Then the
 * same with the coordinates outside the last batch, with texgen and with
 * a texture matrix (all of them without effect on the pixels). */
static void drawpixels_textured_units(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.1f, 0.1f, 1.0f, 1.0);
    glActiveTexture(GL_TEXTURE0);
    tex2d_levels(1, 8, true, 3u);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glActiveTexture(GL_TEXTURE1);
    tex2d_levels(2, 4, false, 5u);
    /* min != mag: the lookup at q = 0 has NaN coordinates and derivatives,
     * and llvmpipe's unordered rho > 1 compare minifies (NEAREST) */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glActiveTexture(GL_TEXTURE0);
    GLubyte img[12 * 10 * 4];
    make_rgba_ub(img, 12, 10, 9u);
    for (int frame = 0; frame < 4; frame++) {
        if (frame == 2) {
            glActiveTexture(GL_TEXTURE1);
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
            glEnable(GL_TEXTURE_GEN_T);
            glActiveTexture(GL_TEXTURE0);
        } else if (frame == 3) {
            glMatrixMode(GL_TEXTURE);
            glRotatef(30.0f, 0, 0, 1);
            glMatrixMode(GL_MODELVIEW);
        }
        textured_tri(frame == 1 ? 0u : 3u);
        glMultiTexCoord4f(GL_TEXTURE0, 0.3f + 0.1f * (float)frame, 0.6f, 0.0f, 1.0f);
        glMultiTexCoord4f(GL_TEXTURE1, 0.8f, 0.2f + 0.2f * (float)frame, 0.0f, 1.0f);
        glColor4f(0.5f, 0.7f, 1.0f, 1.0f);
        window_pos(26.0f, 4.0f, 0.0f);
        glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, img);
        glPixelZoom(1.5f, -1.0f);
        window_pos(42.0f, 40.0f, 0.0f);
        glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, img);
        glPixelZoom(1.0f, 1.0f);
        window_pos(4.0f, 40.0f, 0.0f);
        glCopyPixels(0, 0, 24, 20, GL_COLOR);
        fc_capture(h);
        fcu_clear(0.1f, 0.1f, 0.1f, 1.0f, 1.0);
    }
}

/* A 1D texture with mipmaps under glCopyPixels and glBitmap: the copy
 * reads the current s (magnified), the bitmap's coordinate spans the
 * quad (minified for a wide bitmap), and with fog and blending on. */
static void copypixels_textured_1d(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.2f, 0.1f, 0.3f, 1.0f, 1.0);
    glBindTexture(GL_TEXTURE_1D, 3);
    static GLubyte img[64 * 4];
    for (int level = 0, s = 64; s >= 1; level++, s /= 2) {
        make_rgba_ub(img, s, 1, 21u + (unsigned)level);
        glTexImage1D(GL_TEXTURE_1D, level, GL_RGBA, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    }
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_1D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    GLubyte wide[64 * 8];
    for (int i = 0; i < (int)sizeof wide; i++)
        wide[i] = (GLubyte)(i * 29 + 5);
    for (int frame = 0; frame < 2; frame++) {
        if (frame == 1) {
            glEnable(GL_FOG);
            glFogi(GL_FOG_MODE, GL_LINEAR);
            glFogf(GL_FOG_START, 0.0f);
            glFogf(GL_FOG_END, 2.0f);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        }
        textured_tri(1u);
        glTexCoord1f(0.55f);
        glColor4f(0.9f, 0.4f, 0.2f, 0.6f);
        window_pos(30.0f, 2.0f, 0.0f);
        glCopyPixels(0, 0, 22, 22, GL_COLOR);
        window_pos(0.0f, 30.0f, 0.0f);
        glBitmap(64, 8, 0, 0, 0, 0, wide);
        window_pos(0.0f, 44.0f, 0.0f);
        glPixelZoom(0.5f, 2.0f);
        glCopyPixels(0, 28, 64, 10, GL_COLOR);
        glPixelZoom(1.0f, 1.0f);
        fc_capture(h);
        glDisable(GL_FOG);
        glDisable(GL_BLEND);
        fcu_clear(0.2f, 0.1f, 0.3f, 1.0f, 1.0);
    }
}

/* The bitmap cache is drawn before a texture image changes or is read
 * (st_cb_texture.c: st_TexSubImage, st_GetTexSubImage,
 * st_CopyTexSubImage): cached bitmaps sample the texture as it was, and
 * a copy into a texture reads them. */
static void bitmap_cache_teximage(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.1f, 0.1f, 1.0f, 1.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    tex2d_levels(1, 8, false, 13u);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    GLubyte rows[10];
    glyph('A', rows);
    static GLubyte red[8 * 8 * 4];
    for (int i = 0; i < 8 * 8; i++) {
        red[4 * i] = 255;
        red[4 * i + 3] = 255;
    }
    textured_tri(1u);
    glColor4f(1, 1, 1, 1);
    /* glTexSubImage */
    window_pos(4.0f, 30.0f, 0.0f);
    glBitmap(8, 10, 0, 0, 10, 0, rows);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, red);
    glBitmap(8, 10, 0, 0, 10, 0, rows);
    /* an empty glTexSubImage draws nothing */
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
    /* glTexImage */
    tex2d_levels(1, 8, false, 17u);
    glBitmap(8, 10, 0, 0, 10, 0, rows);
    /* glGetTexImage, then the texture changes again */
    static GLubyte back[8 * 8 * 4];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    fc_blob(h, "teximage", back, sizeof back);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, red);
    glBitmap(8, 10, 0, 0, 10, 0, rows);
    /* glCopyTexSubImage and glCopyTexImage read the cached bitmaps */
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 30, 8, 8);
    glBitmap(8, 10, 0, 0, 10, 0, rows);
    glBindTexture(GL_TEXTURE_2D, 4);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 44, 30, 8, 8, 0);
    glBindTexture(GL_TEXTURE_2D, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    fc_blob(h, "copied", back, sizeof back);
    glBindTexture(GL_TEXTURE_2D, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    fc_blob(h, "copied2", back, sizeof back);
    fc_capture(h);
}


/* The GL 1.5 cases and their honesty halves: the GL_DEPTH_STENCIL,
 * *_INTEGER, half-float, GL_RG and NV_copy_depth_to_color calls the
 * oracle's GL 4.5 context accepts and fixgl (GL 1.5 without those
 * extensions) refuses with GL_INVALID_ENUM (README "Version and
 * honesty"; known-differences.txt lists the honesty cases). */

/* GL_INT colour images go through a 16-bit snorm texture (the top 16 bits
 * of each value): values whose 8-bit result lies next to a half, random
 * and negative ones, with a scale and bias in the shader (ORACLE-NOTES.md
 * "Bitmaps and pixel rectangles", probe p_drawpixels_int; fuzzer seed
 * 3000159). */
static void drawpixels_int_snorm16(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 0.4f, 1.0);
    static GLint img[40 * 30 * 4];
    unsigned s = 777u;
    for (int i = 0; i < 40 * 30 * 4; i++) {
        s = s * 1664525u + 1013904223u;
        img[i] = (GLint)(s & 0x7fffffffu);
        if (i % 11 == 0)
            img[i] = -img[i];
    }
    /* the fuzzer's value and neighbours of every half step k + 0.5 */
    img[0] = 1065334784;
    for (int k = 0; k < 255 && 4 + 4 * k < 40 * 30 * 4; k++)
        img[4 + 4 * k] = (GLint)(((double)k + 0.5) / 255.0 * 2147483648.0) + (k % 5) * 4096;
    window_pos(1, 1, 0);
    glDrawPixels(40, 30, GL_RGBA, GL_INT, img);
    fc_error(h, "rgba");
    window_pos(44, 1, 0);
    glDrawPixels(20, 30, GL_LUMINANCE_ALPHA, GL_INT, img);
    window_pos(1, 34, 0);
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_RED_BIAS, 0.25f);
    glPixelTransferf(GL_ALPHA_SCALE, 2.0f);
    glDrawPixels(40, 12, GL_BGRA, GL_INT, img + 400);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_RED_BIAS, 0.0f);
    glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
    window_pos(44, 34, 0);
    glDrawPixels(20, 12, GL_ALPHA, GL_INT, img);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    fc_error(h, "transfer, swapped");
    fc_capture(h);
}
/* glDrawPixels of GL_UNSIGNED_INT colour data: the oracle's image texture
 * is 16-bit unorm, each channel rounded to 16 bits (Mesa's unorm-to-unorm
 * narrowing), so a value whose 32-bit conversion x * 255 / (2^32 - 1) lies
 * at or next to a half rounds as the 16-bit texel does; every client
 * format, with a scale and bias in the shader (ORACLE-NOTES.md "Bitmaps
 * and pixel rectangles", probe p_drawpixels_int). */
static void drawpixels_uint_unorm16(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0.1f, 0.2f, 0.3f, 0.4f, 1.0);
    static GLuint img[40 * 30 * 4];
    unsigned s = 4242u;
    for (int i = 0; i < 40 * 30 * 4; i++) {
        s = s * 1664525u + 1013904223u;
        img[i] = s;
    }
    /* the tie 104.5 and neighbours of every half step k + 0.5 */
    img[0] = 1760094441u;   /* (float)x * 2^-32 * 255 is 104.5 */
    img[1] = 1760094440u;
    for (int k = 0; k < 255 && 4 + 4 * k < 40 * 30 * 4; k++)
        img[4 + 4 * k] = (GLuint)(((double)k + 0.5) / 255.0 * 4294967296.0) + (GLuint)(k % 5) - 2u;
    window_pos(1, 1, 0);
    glDrawPixels(40, 30, GL_RGB, GL_UNSIGNED_INT, img);
    fc_error(h, "rgb");
    window_pos(44, 1, 0);
    glDrawPixels(20, 30, GL_RGBA, GL_UNSIGNED_INT, img);
    window_pos(1, 34, 0);
    glPixelTransferf(GL_GREEN_SCALE, 0.5f);
    glPixelTransferf(GL_GREEN_BIAS, 0.25f);
    glDrawPixels(40, 12, GL_BGRA, GL_UNSIGNED_INT, img + 400);
    glPixelTransferf(GL_GREEN_SCALE, 1.0f);
    glPixelTransferf(GL_GREEN_BIAS, 0.0f);
    window_pos(44, 34, 0);
    glDrawPixels(10, 12, GL_LUMINANCE_ALPHA, GL_UNSIGNED_INT, img);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
    window_pos(56, 34, 0);
    glDrawPixels(10, 12, GL_LUMINANCE, GL_UNSIGNED_INT, img);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    fc_error(h, "transfer, swapped");
    fc_capture(h);
}
static void drawpixels_types(fc_h *h) { drawpixels_types_of(h, 0); }
static void drawpixels_foreign_types(fc_h *h) { drawpixels_types_of(h, 1); }
static void drawpixels_errors(fc_h *h) { drawpixels_errors_of(h, 0); }
static void drawpixels_foreign_errors(fc_h *h) { drawpixels_errors_of(h, 1); }
static void copypixels_errors(fc_h *h) { copypixels_errors_of(h, 0); }
static void copypixels_foreign_errors(fc_h *h) { copypixels_errors_of(h, 1); }
static void pixels_stencil_only(fc_h *h) { pixels_stencil_only_of(h, 0); }
static void pixels_stencil_only_foreign(fc_h *h) { pixels_stencil_only_of(h, 1); }
const fc_case fc_cases_pix_draw[] = {
    FC_CASE_RGBA("pixel/bitmap_text", 180, 110, 1, "pixel bitmap", bitmap_text),
    FC_CASE_RGBA("pixel/bitmap_unpack", 128, 48, 1, "pixel bitmap", bitmap_unpack),
    FC_CASE_RGBA("pixel/bitmap_origin_move", 80, 48, 1, "pixel bitmap", bitmap_origin_move),
    FC_CASE_RGBA("pixel/bitmap_clipped", 72, 64, 1, "pixel bitmap", bitmap_clipped),
    FC_CASE_RGBA("pixel/bitmap_cache_order", 64, 64, 2, "pixel bitmap", bitmap_cache_order),
    FC_CASE_RGBA("pixel/bitmap_cache_edges", 64, 64, 1, "pixel bitmap", bitmap_cache_edges),
    FC_CASE_RGBA("pixel/bitmap_fragment_ops", 64, 64, 1, "pixel bitmap",
                 bitmap_fragment_ops),
    FC_CASE("pixel/bitmap_stencil", 32, 24, OSMESA_RGBA, 24, 8, 1, "pixel bitmap stencil",
            bitmap_stencil),
    FC_CASE_RGBA("pixel/bitmap_feedback_select", 32, 32, 1, "pixel bitmap feedback select",
                 bitmap_feedback_select),
    FC_CASE_RGBA("pixel/bitmap_dlist", 64, 64, 1, "pixel bitmap dlist", bitmap_dlist),
    FC_CASE_RGBA("pixel/bitmap_errors", 32, 32, 1, "pixel bitmap errors", bitmap_errors),
    FC_CASE_RGBA("pixel/drawpixels_formats", 64, 48, 1, "pixel drawpixels",
                 drawpixels_formats),
    FC_CASE_RGBA("pixel/drawpixels_zoom", 100, 64, 2, "pixel drawpixels", drawpixels_zoom),
    FC_CASE_RGBA("pixel/drawpixels_zoom_clip", 64, 64, 2, "pixel drawpixels",
                 drawpixels_zoom_clip),
    FC_CASE_RGBA("pixel/drawpixels_zoom_extreme", 64, 64, 3, "pixel drawpixels feedback",
                 drawpixels_zoom_extreme),
    FC_CASE_RGBA("pixel/drawpixels_transfer", 64, 40, 1, "pixel drawpixels",
                 drawpixels_transfer),
    FC_CASE_RGBA("pixel/drawpixels_types", 64, 48, 1, "pixel drawpixels", drawpixels_types),
    FC_CASE_RGBA("pixel/drawpixels_int_snorm16", 68, 48, 1, "pixel drawpixels", drawpixels_int_snorm16),
    FC_CASE_RGBA("pixel/drawpixels_uint_unorm16", 68, 48, 1, "pixel drawpixels", drawpixels_uint_unorm16),
    FC_CASE_RGBA("pixel/drawpixels_color_index", 64, 24, 1, "pixel drawpixels",
                 drawpixels_color_index),
    FC_CASE("pixel/drawpixels_zs_types", 64, 32, OSMESA_RGBA, 24, 8, 1,
            "pixel drawpixels depth stencil", drawpixels_zs_types),
    FC_CASE("honesty/drawpixels_depth_stencil", 64, 40, OSMESA_RGBA, 24, 8, 1,
            "honesty pixel drawpixels depth stencil", drawpixels_depth_stencil),
    FC_CASE_RGBA("honesty/drawpixels_foreign_types", 64, 48, 1, "honesty pixel drawpixels",
                 drawpixels_foreign_types),
    FC_CASE_RGBA("honesty/drawpixels_errors", 32, 32, 1, "honesty pixel drawpixels errors",
                 drawpixels_foreign_errors),
    FC_CASE_RGBA("honesty/copypixels_errors", 64, 64, 1, "honesty pixel copypixels errors",
                 copypixels_foreign_errors),
    FC_CASE("honesty/drawpixels_stencil_only", 32, 16, OSMESA_RGBA, 0, 8, 1,
            "honesty pixel drawpixels copypixels stencil errors", pixels_stencil_only_foreign),
    FC_CASE_RGBA("pixel/drawpixels_map_color", 64, 40, 1, "pixel drawpixels",
                 drawpixels_map_color),
    FC_CASE_RGBA("pixel/drawpixels_fragment_ops", 64, 64, 1, "pixel drawpixels",
                 drawpixels_fragment_ops),
    FC_CASE_RGBA("pixel/drawpixels_unpack", 64, 48, 1, "pixel drawpixels", drawpixels_unpack),
    FC_CASE_RGBA("pixel/drawpixels_depth", 64, 64, 1, "pixel drawpixels depth",
                 drawpixels_depth),
    FC_CASE("pixel/drawpixels_stencil", 64, 64, OSMESA_RGBA, 24, 8, 1,
            "pixel drawpixels stencil", drawpixels_stencil),
    FC_CASE_RGBA("pixel/drawpixels_errors", 32, 32, 1, "pixel drawpixels errors",
                 drawpixels_errors),
    FC_CASE_RGBA("pixel/drawpixels_feedback_dlist", 64, 32, 1,
                 "pixel drawpixels feedback dlist", drawpixels_feedback_dlist),
    FC_CASE_RGBA("pixel/copypixels_overlap", 64, 64, 6, "pixel copypixels",
                 copypixels_overlap),
    FC_CASE_RGBA("pixel/copypixels_zoom_ops", 64, 64, 2, "pixel copypixels",
                 copypixels_zoom_ops),
    FC_CASE_RGBA("pixel/copypixels_depth", 64, 64, 1, "pixel copypixels depth",
                 copypixels_depth),
    FC_CASE("pixel/copypixels_stencil", 64, 64, OSMESA_RGBA, 24, 8, 1,
            "pixel copypixels stencil", copypixels_stencil),
    FC_CASE("honesty/copypixels_depth_to_color", 64, 64, OSMESA_RGBA, 24, 8, 1,
            "honesty pixel copypixels depth stencil", copypixels_depth_to_color),
    FC_CASE_RGBA("pixel/copypixels_scissor_list", 64, 64, 1, "pixel copypixels dlist",
                 copypixels_scissor_list),
    FC_CASE_RGBA("pixel/copypixels_errors", 64, 64, 1, "pixel copypixels errors",
                 copypixels_errors),
    FC_CASE_RGBA("pixel/drawpixels_raster_state", 64, 48, 1, "pixel drawpixels bitmap",
                 pixels_raster_state),
    FC_CASE("pixel/drawpixels_depth16", 48, 24, OSMESA_RGBA, 16, 0, 1,
            "pixel drawpixels copypixels depth", pixels_depth16),
    FC_CASE("pixel/drawpixels_stencil_only", 32, 16, OSMESA_RGBA, 0, 8, 1,
            "pixel drawpixels copypixels stencil errors", pixels_stencil_only),
    FC_CASE("pixel/drawpixels_no_depth", 16, 16, OSMESA_RGBA, 0, 0, 1,
            "pixel drawpixels copypixels errors", pixels_no_depth),
    FC_CASE_RGBA("pixel/bitmap_textured_2d", 96, 64, 4, "pixel bitmap texture mipmap texgen texmat",
                 bitmap_textured_2d),
    FC_CASE_RGBA("pixel/bitmap_textured_empty_draws", 96, 64, 6,
                 "pixel bitmap texture mipmap varray multidraw errors", bitmap_textured_empty_draws),
    FC_CASE_RGBA("pixel/drawpixels_textured_units", 64, 64, 4,
                 "pixel drawpixels copypixels texture multitexture texgen texmat",
                 drawpixels_textured_units),
    FC_CASE_RGBA("pixel/copypixels_textured_1d", 64, 64, 2,
                 "pixel copypixels bitmap texture mipmap fog", copypixels_textured_1d),
    FC_CASE_RGBA("pixel/bitmap_cache_textured_teximage", 64, 48, 1, "pixel bitmap texture",
                 bitmap_cache_teximage),
    { 0 }
};
