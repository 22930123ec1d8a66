/* c_robust.c - hostile input found by the differential API fuzzer of
 * issue 18: calls that crashed fixgl, read or wrote out of bounds, hit
 * undefined behaviour under UBSan, ran far slower than the oracle, or
 * raised another GL error than Mesa 22.3.  Each case records the error
 * after every hostile call, draws something afterwards (so corrupt state
 * shows) and captures the frame.
 *
 * Where GL leaves a result undefined (pixels copied from outside the
 * window), the case restricts what it compares to the defined part with
 * the scissor test and says so. */
#define GL_GLEXT_PROTOTYPES 1
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include <time.h>
#include <xmmintrin.h>

#include "cases.h"

/* A stipple/bitmap pattern with no symmetry, so a wrong row length or
 * row order shows. */
static void pattern_bits(GLubyte *b, int n)
{
    for (int i = 0; i < n; i++)
        b[i] = (GLubyte)(i * 37 + (i >> 2) * 11 + 5);
}

/* A frame with something in it: four coloured quads at four depths, and
 * stencil values 1-4 where they are (stencil buffer needed for the last). */
static void scene_quads(int w, int hgt)
{
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    for (int i = 0; i < 4; i++) {
        const float x0 = (float)(i % 2) * (float)w / 2, y0 = (float)(i / 2) * (float)hgt / 2;
        glStencilFunc(GL_ALWAYS, i + 1, 0xff);
        fcu_color(i);
        fcu_rect(x0 + 1, y0 + 2, x0 + (float)w / 2 - 3, y0 + (float)hgt / 2 - 1,
                 -0.75f + 0.5f * (float)i);
    }
    glDisable(GL_STENCIL_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
}

/* ---- crashes ---- */

/* glMaterial inside glBegin/glEnd while compiling, after a glEvalCoord
 * (or glEvalPoint, glCallList) ended the list's vertices: Mesa stores it
 * as a MATERIAL node; fixgl wrapped a vertex list with no primitive. */
static void dlist_material_after_fallback(fc_h *h)
{
    static const GLfloat amb[4] = { 0.2f, 0.4f, 0.6f, 1.0f };
    static const GLfloat dif[4] = { 0.9f, 0.5f, 0.1f, 1.0f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(5, GL_COMPILE);
    glColor3f(0, 1, 0);
    glEndList();

    glNewList(4, GL_COMPILE);
    glBegin(GL_LINE_STRIP);
    glVertex4s(1, 1, 0, 1);
    glEvalCoord1f(-0.8846f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
    glVertex2f(30, 20);
    glEnd();
    glEndList();
    fc_error(h, "compile after glEvalCoord1f");

    glNewList(6, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_TRIANGLES);
    glVertex2f(2, 30);
    glEvalPoint1(3);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
    glMaterialf(GL_BACK, GL_SHININESS, 12.0f);
    glVertex2f(30, 40);
    glVertex2f(10, 60);
    glEnd();
    glEndList();
    fc_error(h, "compile and execute after glEvalPoint1");

    glNewList(7, GL_COMPILE);
    glBegin(GL_QUADS);
    glVertex2f(40, 2);
    glCallList(5);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, amb);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, dif);
    glVertex2f(60, 2);
    glVertex2f(60, 30);
    glVertex2f(40, 30);
    glEnd();
    glEndList();
    fc_error(h, "compile after glCallList");

    glCallList(4);
    fc_error(h, "call 4");
    glCallList(6);
    fc_error(h, "call 6");
    glCallList(7);
    fc_error(h, "call 7");
    glFinish();
    fc_get_float(h, "front ambient", GL_CURRENT_COLOR, 4);
    GLfloat m[4] = { -1, -1, -1, -1 };
    glGetMaterialfv(GL_FRONT, GL_AMBIENT, m);
    fc_blob(h, "GL_FRONT GL_AMBIENT", m, sizeof m);
    glGetMaterialfv(GL_BACK, GL_DIFFUSE, m);
    fc_blob(h, "GL_BACK GL_DIFFUSE", m, sizeof m);
    glGetMaterialfv(GL_FRONT, GL_EMISSION, m);
    fc_blob(h, "GL_FRONT GL_EMISSION", m, sizeof m);
    fc_capture(h);
}

/* The part of a glCopyPixels destination whose source lies in the window:
 * the rest reads pixels outside it, undefined in GL (Mesa draws nothing
 * there), so the copy is scissored to this part (an empty scissor when
 * nothing of the source is inside). */
static void scissor_defined(int W, int H, int rx, int ry, long long x, long long y,
                            long long w, long long hh)
{
    long long i0 = x < 0 ? -x : 0, j0 = y < 0 ? -y : 0;
    long long i1 = W - x < w ? W - x : w, j1 = H - y < hh ? H - y : hh;
    long long dx0 = rx + i0, dy0 = ry + j0, dx1 = rx + i1, dy1 = ry + j1;
    if (dx0 < 0) dx0 = 0;
    if (dy0 < 0) dy0 = 0;
    if (dx1 > W) dx1 = W;
    if (dy1 > H) dy1 = H;
    glEnable(GL_SCISSOR_TEST);
    if (dx1 <= dx0 || dy1 <= dy0)
        glScissor(0, 0, 0, 0);
    else
        glScissor((GLint)dx0, (GLint)dy0, (GLsizei)(dx1 - dx0), (GLsizei)(dy1 - dy0));
}

/* glCopyPixels with coordinates and sizes near INT_MAX/INT_MIN: Mesa clips
 * the source to the window; fixgl overflowed, crashed or tried to
 * allocate the unclipped size.  A copy larger than the largest texture
 * goes through a texture of the whole source in the oracle, sampled with
 * float coordinates that cannot address its rows: the depth and stencil
 * values it writes are not the copied ones, so those copies keep the
 * depth and stencil masks off (their colour, the raster colour, still
 * shows where fragments are).  Colour copies take the blit, exact, but for
 * a rectangle whose end passes INT_MAX: Mesa's _mesa_clip_readpixels and
 * _mesa_clip_drawpixels overflow then and blit other pixels, so those
 * are scissored away entirely (still called: no crash, same error). */
static void copypixels_huge(fc_h *h)
{
    static const struct { int rx, ry; GLint x, y; GLsizei w, hh; GLenum type; } c[] = {
        { 3, 5, INT_MAX, 57, 17, 128, GL_DEPTH },
        { 0, 0, -7, INT_MIN, 64, 65, GL_STENCIL },
        { 0, 0, -3, 40, 128, INT_MAX, GL_DEPTH },
        { 10, 4, -3, 40, 128, INT_MAX, GL_COLOR },
        { 1, 30, INT_MIN, INT_MIN, INT_MAX, INT_MAX, GL_COLOR },
        { 0, 0, 5, -2147483600, 20, INT_MAX, GL_STENCIL },
        { 33, 1, 2, 3, INT_MAX, INT_MAX, GL_DEPTH },
        { 40, 40, INT_MAX - 3, INT_MAX - 3, 8, 8, GL_COLOR },
        { 20, 20, -2147483000, 2, INT_MAX, 20, GL_COLOR },
        { 20, 0, -3, 40, 128, 16384, GL_DEPTH },
        { 0, 30, -3, 40, 128, 16385, GL_DEPTH },
        { 0, 50, 0, 40, 300, 2, GL_STENCIL },
    };
    const int W = 64, H = 64;
    fc_pixel_ortho(h);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    scene_quads(W, H);
    fc_capture(h);
    for (unsigned k = 0; k < sizeof c / sizeof c[0]; k++) {
        glDisable(GL_SCISSOR_TEST);
        fcu_color((int)k + 5);
        glRasterPos2i(c[k].rx, c[k].ry);
        /* depth copies write depth (and the raster colour) */
        if (c[k].type == GL_DEPTH) {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
        }
        scissor_defined(W, H, c[k].rx, c[k].ry, c[k].x, c[k].y, c[k].w, c[k].hh);
        const int huge = c[k].w > 16384 || c[k].hh > 16384;
        const int overflow = (long long)c[k].x + c[k].w > INT_MAX ||
                             (long long)c[k].y + c[k].hh > INT_MAX;
        if (overflow && c[k].type == GL_COLOR)
            glScissor(0, 0, 0, 0);
        if (huge) {
            glDepthMask(GL_FALSE);
            glStencilMask(0);
        }
        glCopyPixels(c[k].x, c[k].y, c[k].w, c[k].hh, c[k].type);
        fc_error(h, "glCopyPixels");
        glDepthMask(GL_TRUE);
        glStencilMask(0xff);
        glDisable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        fc_capture(h);
    }
    glDisable(GL_SCISSOR_TEST);
    fc_capture(h);
    /* stencil as colour, to compare it */
    GLubyte s[64 * 64];
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    fc_blob(h, "stencil", s, sizeof s);
    fc_error(h, "read stencil");
}

/* glBitmap with a huge or NaN origin or move: the raster position leaves
 * every integer range. */
static void bitmap_huge(fc_h *h)
{
    static const GLint wp[3] = { 7, 20, 27 };
    GLubyte b[32 * 40];
    pattern_bits(b, (int)sizeof b);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glColor3f(1, 1, 0);
    glWindowPos3iv(wp);
    glBitmap(65, 17, 0.26f, 1.39f, 18.5f, 255.0f, b);
    fc_error(h, "first bitmap");
    fc_get_float(h, "raster pos 1", GL_CURRENT_RASTER_POSITION, 4);
    glBitmap(39, 32, -6.3f, -1e20f, -8.96f, 9.35f, b);
    fc_error(h, "second bitmap");
    fc_get_float(h, "raster pos 2", GL_CURRENT_RASTER_POSITION, 4);
    fc_get_boolean(h, "valid 2", GL_CURRENT_RASTER_POSITION_VALID, 1);

    static const float vals[] = { 1e20f, -1e20f, 3e9f, -3e9f, 2147483520.0f, -2147483648.0f };
    const float nan = nanf("");
    for (unsigned i = 0; i < sizeof vals / sizeof vals[0]; i++) {
        glWindowPos2i(10, 10);
        glBitmap(8, 8, vals[i], 0, 0, 0, b);
        glBitmap(8, 8, 0, vals[i], 0, 0, b);
        glBitmap(8, 8, 0, 0, vals[i], 0, b);
        glBitmap(8, 8, 0, 0, 0, 0, b);
        glBitmap(8, 8, 0, 0, -vals[i], vals[i], b);
        glBitmap(8, 8, 0, 0, 0, 0, b);
        fc_error(h, "huge");
    }
    glWindowPos2i(20, 20);
    glBitmap(8, 8, nan, 0, 0, 0, b);
    glBitmap(8, 8, 0, nan, 0, 0, b);
    glBitmap(8, 8, 0, 0, 0, 0, b);
    fc_error(h, "nan origin");
    glBitmap(8, 8, 0, 0, nan, nan, b);
    glBitmap(8, 8, 0, 0, 0, 0, b);
    fc_error(h, "nan move");
    fc_get_boolean(h, "valid nan", GL_CURRENT_RASTER_POSITION_VALID, 1);
    glWindowPos2i(30, 3);
    glBitmap(16, 8, 0, 0, 0, 0, b);
    fc_capture(h);
}

/* glDrawArrays with a negative first: no error in Mesa (GL 1.x does not
 * define it); llvmpipe fetches the elements whose 32-bit offset overflows
 * as zeros, and a list compiles the vertices at their addresses (the
 * array starts three vertices into v, so those are v's). */
static void drawarrays_negative_first(fc_h *h)
{
    static const GLfloat v[] = { 1, 50, 20, 62, 3, 40,
                                 2, 2, 30, 4, 10, 29, 40, 40, 60, 40, 50, 60 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v + 6);
    glColor3f(1, 0, 0);
    glDrawArrays(GL_TRIANGLES, -1, 3);
    fc_error(h, "first -1");
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_TRIANGLES, INT_MIN, 3);
    fc_error(h, "first INT_MIN");
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glDrawArrays(GL_TRIANGLES, -3, 0);
    fc_error(h, "first -3 count 0");
    glDrawArrays(GL_TRIANGLES, -1, -1);
    fc_error(h, "first -1 count -1");
    glDrawArrays(0x7777, -1, 3);
    fc_error(h, "bad mode, first -1");
    glNewList(1, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, -2, 3);
    glDrawArrays(0x7777, -2, 3);
    glEndList();
    fc_error(h, "compiled first -2");
    glCallList(1);
    fc_error(h, "called first -2");
    fc_capture(h);
    fcu_clear(0, 0, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glDrawArrays(GL_TRIANGLES, -1, 3);
    glEnd();
    fc_error(h, "inside begin/end");
    glDrawArrays(GL_TRIANGLES, 3, 3);
    fc_error(h, "valid");
    static const GLuint idx[] = { 0x20000003u, 4, 0xFFFFFFFFu, 0x20000002u, 1, 0 };
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, idx);
    fc_error(h, "huge indices");
    glDisableClientState(GL_VERTEX_ARRAY);
    fc_capture(h);
}

/* glDrawArrays with a negative first reads the elements below the array's
 * pointer: llvmpipe adds the wrapped 32-bit offset (first * stride) to the
 * pointer as a signed index, so element -2 of a 16-byte stride is 32 bytes
 * before the pointer; only an element whose offset ends at 4 GB or past
 * it is out of bounds (element -1 above).  fixgl added the offset unsigned
 * and read 4 GB past the pointer: zeros in the fuzzer's arena, a crash
 * here (found by the API fuzzer, seed 20: glInterleavedArrays(GL_C4UB_V3F),
 * glDrawArrays(GL_POLYGON, -2, 4096)).  Separate arrays, then interleaved
 * ones with elements below -1 only (element -1 of an interleaved set is
 * the attribute's bounds check against its offset in the merged binding,
 * conformance/fuzz/known-differences.txt). */
static void drawarrays_negative_first_before_pointer(fc_h *h)
{
    static const GLfloat v[] = { 4, 4, 40, 8, 10, 44, 1, 1,
                                 30, 30, 60, 34, 34, 60 };
    static const GLubyte c[] = { 255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 9,
                                 255, 255, 0, 255, 0, 255, 255, 255, 255, 0, 255, 255 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glShadeModel(GL_SMOOTH);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v + 8);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c + 16);
    glDrawArrays(GL_TRIANGLES, -4, 3);
    fc_error(h, "separate arrays, first -4");
    glDrawArrays(GL_TRIANGLES, -1, 4);
    fc_error(h, "separate arrays, first -1");
    fc_capture(h);
    struct { GLubyte c[4]; GLfloat p[3]; } iv[8] = {
        { { 255, 128, 0, 255 }, { 2, 60, 0 } },  { { 0, 128, 255, 255 }, { 62, 50, 0 } },
        { { 128, 255, 0, 255 }, { 20, 2, 0 } },  { { 1, 2, 3, 4 }, { 5, 6, 0 } },
        { { 5, 6, 7, 8 }, { 9, 10, 0 } },        { { 255, 255, 255, 255 }, { 40, 40, 0 } },
        { { 0, 0, 0, 255 }, { 50, 40, 0 } },     { { 0, 0, 0, 255 }, { 50, 50, 0 } },
    };
    fcu_clear(0, 0, 0, 0, 1);
    glInterleavedArrays(GL_C4UB_V3F, 0, &iv[5]);
    glDrawArrays(GL_POLYGON, -5, 3);
    fc_error(h, "interleaved, first -5");
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fc_error(h, "interleaved, first 0");
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    fc_capture(h);
}

/* A texture image call that fails validation leaves the vertex format
 * alone.  Mesa checks glCopyTexSubImage's target (no proxies) before
 * copy_texture_sub_image_err's FLUSH_VERTICES, and glTexSubImage flushes
 * in texture_sub_image, after every check; glCopyTexImage flushes first.
 * The format decides whether a shorter glTexCoord resets q: after
 * glMultiTexCoord1d, glTexCoord4f the active size stays 1, so a
 * glTexCoord3f keeps q = 4, unless a flush in between reset the format
 * (then q = 1).  glCallList of an unused name makes the next
 * FLUSH_VERTICES flush.  fixgl flushed before the checks (found by the API
 * fuzzer, seed 150: glCallList, glCopyTexSubImage1D(GL_PROXY_TEXTURE_1D),
 * glMultiTexCoord3dvARB). */
static void teximage_error_keeps_vertex_format(fc_h *h)
{
    static const GLubyte texel[4] = { 1, 2, 3, 4 };
    for (int k = 0; k < 7; k++) {
        glTexCoord4f(1, 2, 3, 4);
        glCallList(4321);
        switch (k) {
        case 0: glCopyTexSubImage1D(GL_PROXY_TEXTURE_1D, 0, 0, 0, 0, 1); break;
        case 1: glCopyTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1); break;
        case 2: glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 0, 0, 0, 1); break;
        case 3: glTexSubImage1D(GL_PROXY_TEXTURE_1D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel); break;
        case 4: glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel); break;
        case 5: glCopyTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGBA, 0, 0, 4, 0); break;
        default: glCopyTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 0, 0, 4, 4, 0); break;
        }
        fc_error(h, "texture image call");
        glMultiTexCoord1d(GL_TEXTURE0, 1.5);
        glTexCoord4f(1, 2, 3, 4);
        glMultiTexCoord3f(GL_TEXTURE8, 0.25f, 0.5f, 0.75f);   /* unit 8 & 7 */
        fc_error(h, "texture coordinates");
        fc_get_float(h, "current texture coordinates", GL_CURRENT_TEXTURE_COORDS, 4);
    }
}

/* The draw module fetches only the vertices of whole primitives
 * (draw_pt_trim_count): a one-vertex line strip, the fourth vertex of
 * GL_TRIANGLES, a quad strip's odd vertex are never read, whatever the
 * array.  fixgl fetched all of them, and with a negative stride (raised as
 * GL_INVALID_VALUE, but Mesa sets the array anyway) read 4 GB past the
 * array (found by the API fuzzer: glColorPointer(4, GL_FLOAT, -1, p);
 * glDrawArrays(GL_LINE_STRIP, 80, 1)).  The partial primitives below read
 * an array whose stride is negative at elements where the offset wraps
 * to below 4 GB; an in-bounds read there would leave the process. */
static void drawarrays_partial_primitive(fc_h *h)
{
    static const GLfloat v[] = { 4, 4, 60, 8, 30, 60, 10, 40, 50, 30, 40, 58,
                                 2, 20, 62, 2, 20, 50, 5, 60, 60, 62, 35, 2 };
    static GLfloat col[16 * 4];
    for (int i = 0; i < 16 * 4; i++)
        col[i] = (float)((i * 7) % 11) / 10.0f;
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glShadeModel(GL_SMOOTH);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(4, GL_FLOAT, -1, col + 8 * 4);
    fc_error(h, "glColorPointer stride -1");
    glDrawArrays(GL_LINE_STRIP, 80, 1);
    glDrawArrays(GL_LINES, 80, 1);
    glDrawArrays(GL_LINE_LOOP, 80, 1);
    glDrawArrays(GL_TRIANGLES, 80, 2);
    glDrawArrays(GL_TRIANGLE_FAN, 80, 2);
    glDrawArrays(GL_QUADS, 80, 3);
    glDrawArrays(GL_POLYGON, 80, 2);
    fc_error(h, "partial primitives, stride -1");
    static const GLuint idx[] = { 90, 91, 92, 93 };
    glDrawElements(GL_LINE_STRIP, 1, GL_UNSIGNED_INT, idx);
    glDrawElements(GL_QUAD_STRIP, 3, GL_UNSIGNED_INT, idx);
    fc_error(h, "partial indexed primitives, stride -1");
    /* whole primitives with the extra vertices past them */
    glColorPointer(4, GL_FLOAT, 0, col);
    glDrawArrays(GL_TRIANGLES, 0, 5);
    glDrawArrays(GL_QUAD_STRIP, 6, 5);
    glDrawArrays(GL_LINES, 8, 3);
    fc_error(h, "whole primitives and a partial one");
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    fc_capture(h);
}

/* glArrayElement's element offset is elt * stride in int arithmetic, as
 * Mesa's _mesa_array_element adds it to the pointer: it wraps in 32 bits.
 * fixgl multiplied in 64 bits and read 32 GB before the array for
 * glArrayElement(INT_MIN) with a 16-byte stride (found by the API
 * fuzzer), where the oracle reads element 0. */
static void arrayelement_wrapping_index(fc_h *h)
{
    static const GLfloat v[] = { 8, 8, 0, 1, 56, 12, 0, 1, 30, 58, 0, 1, 4, 50, 0, 1 };
    static const GLfloat c[] = { 1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 0, 1 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glShadeModel(GL_SMOOTH);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(4, GL_FLOAT, 0, v);
    glColorPointer(4, GL_FLOAT, 0, c);
    glBegin(GL_TRIANGLES);
    glArrayElement(INT_MIN);          /* 16 * INT_MIN wraps to 0: element 0 */
    glArrayElement(INT_MIN + 1);      /* element 1 */
    glArrayElement(2);
    glArrayElement(INT_MIN + 3);
    glArrayElement(INT_MIN + 2);
    glArrayElement(1);
    glEnd();
    fc_error(h, "glArrayElement(INT_MIN + i)");
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    fc_capture(h);
}

/* glDepthMask keeps the byte it is given (_mesa_DepthMask: Depth.Mask =
 * flag): glGetIntegerv, glGetBooleanv and glGetDoublev return 255 after
 * glDepthMask(255), glGetFloatv 1; a list and glPopAttrib restore it.
 * fixgl normalized it to 1 (found by the API fuzzer's state walk). */
static void depthmask_byte(fc_h *h)
{
    static const GLboolean flags[] = { 255, 2, 0, 1, 128 };
    for (size_t i = 0; i < sizeof flags; i++) {
        glDepthMask(flags[i]);
        fc_get_integer(h, "GL_DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, 1);
        fc_get_boolean(h, "GL_DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, 1);
        fc_get_float(h, "GL_DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, 1);
        fc_get_double(h, "GL_DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, 1);
        fc_error(h, "glDepthMask");
    }
    glNewList(1, GL_COMPILE);
    glDepthMask(7);
    glEndList();
    glPushAttrib(GL_DEPTH_BUFFER_BIT);
    glCallList(1);
    fc_get_integer(h, "GL_DEPTH_WRITEMASK after the list", GL_DEPTH_WRITEMASK, 1);
    glDepthMask(GL_FALSE);
    glPopAttrib();
    fc_get_integer(h, "GL_DEPTH_WRITEMASK after glPopAttrib", GL_DEPTH_WRITEMASK, 1);
    fc_error(h, "list, push and pop");
}

/* glDrawArrays/glDrawElements with GL_VERTEX_ARRAY disabled still draw
 * in the compatibility profile: every vertex at the current value of the
 * position attribute, (0, 0, 0, 1), with the enabled arrays' colours.
 * fixgl drew nothing (found by the API fuzzer through glRenderMode's
 * feedback count). */
static void drawarrays_no_position_array(fc_h *h)
{
    static const GLfloat c[] = { 1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1 };
    static const GLubyte idx[] = { 2, 1, 0 };
    GLfloat fb[64];
    GLuint sel[16];
    fcu_clear(0, 0, 0, 0, 1);
    glPointSize(5);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_FLOAT, 0, c);
    glDrawArrays(GL_POINTS, 0, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDrawElements(GL_LINES, 2, GL_UNSIGNED_BYTE, idx);
    fc_error(h, "drawn");
    fc_capture(h);
    glFeedbackBuffer(64, GL_3D_COLOR, fb);
    glRenderMode(GL_FEEDBACK);
    glDrawArrays(GL_POINTS, 1, 2);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, idx);
    fc_value(h, "feedback values", glRenderMode(GL_RENDER));
    for (int i = 0; i < 12; i++)
        fc_value(h, "feedback", (int)(fb[i] * 1000.0f));
    glSelectBuffer(16, sel);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(7);
    glDrawArrays(GL_LINE_STRIP, 0, 3);
    fc_value(h, "select hits", glRenderMode(GL_RENDER));
    fc_value(h, "select name", (int)sel[3]);
    glDisableClientState(GL_COLOR_ARRAY);
    glPointSize(1);
    fc_error(h, "feedback and select");
}

/* Triangle-class draws without a position array: every vertex at
 * (0, 0, 0, 1), so every triangle has three equal window positions.
 * Filled on both faces they draw nothing (fixgl returns at once: the
 * 2^31 - 1 vertices of robust/huge-draws); unfilled faces still draw
 * their zero-length edges or their points, selection still counts a hit
 * and feedback still records the polygons; an occlusion query counts no
 * sample for the filled ones.  Additive blending makes every point of
 * GL_POINT faces count in the centre pixel. */
static void drawarrays_no_position_faces(fc_h *h)
{
    static const GLenum modes[] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                    GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    static const GLubyte idx[] = { 0, 1, 2, 3, 4, 5, 6, 7 };
    static const GLenum faces[][2] = { { GL_FILL, GL_FILL }, { GL_POINT, GL_POINT },
                                       { GL_LINE, GL_FILL }, { GL_FILL, GL_POINT } };
    GLfloat fb[256];
    GLuint sel[16], q, samples = 99;
    fcu_clear(0, 0, 0, 0, 1);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glPointSize(3);
    glColor4ub(9, 5, 3, 1);
    for (unsigned f = 0; f < sizeof faces / sizeof faces[0]; f++) {
        glPolygonMode(GL_FRONT, faces[f][0]);
        glPolygonMode(GL_BACK, faces[f][1]);
        for (unsigned m = 0; m < sizeof modes / sizeof modes[0]; m++) {
            glDrawArrays(modes[m], (GLint)(f + m), 8);
            glDrawElements(modes[m], 6, GL_UNSIGNED_BYTE, idx);
        }
    }
    fc_error(h, "drawn");
    fc_capture(h);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glGenQueries(1, &q);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glDrawArrays(GL_QUADS, 0, 1 << 20);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 70000);
    glEndQuery(GL_SAMPLES_PASSED);
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &samples);
    fc_value(h, "samples of filled faces", samples);
    glDeleteQueries(1, &q);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glPolygonMode(GL_BACK, GL_POINT);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDisable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glFeedbackBuffer(256, GL_2D, fb);
    glRenderMode(GL_FEEDBACK);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDrawArrays(GL_QUADS, 0, 4);
    const GLint nfb = glRenderMode(GL_RENDER);
    fc_value(h, "feedback values", nfb);
    for (int i = 0; i < nfb && i < 40; i++)
        fc_value(h, "feedback", (int)(fb[i] * 1000.0f));
    glSelectBuffer(16, sel);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(5);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 5);
    fc_value(h, "select hits", glRenderMode(GL_RENDER));
    fc_value(h, "select name", (int)sel[3]);
    glDisable(GL_BLEND);
    glPointSize(1);
    fc_error(h, "query, feedback and select");
    fc_capture(h);
}

/* glDeleteLists before any list exists: fixgl passed its table's NULL
 * pointer to memmove (undefined behaviour that UBSan reports; found by
 * the libFuzzer target). */
static void deletelists_before_any(fc_h *h)
{
    glDeleteLists(1, 5);
    fc_error(h, "glDeleteLists(1, 5), no lists");
    glDeleteLists(0, 0);
    glDeleteLists(0xFFFFFFFFu, 2);
    fc_error(h, "glDeleteLists(0, 0), (~0, 2)");
    fc_value(h, "glIsList(1)", glIsList(1));
    fc_value(h, "glGenLists(3)", (int)glGenLists(3));
    glDeleteLists(2, 1);
    fc_value(h, "glIsList(3)", glIsList(3));
    fc_error(h, "then");
}

/* glTexImage3D / glTexSubImage3D compiled with a depth <= 0 and data:
 * the oracle's unpack_image checks only the width and height, and
 * _mesa_unpack_image's NULL for the depth is taken for a failed
 * allocation (GL_OUT_OF_MEMORY, fuzzer seed 1000447 of the long
 * campaign); a zero width, or a depth of 1, compiles without error. */
static void teximage3d_compile_depth(fc_h *h)
{
    /* large enough for every call below at depth 1 (the 12x2 GL_INT
     * stencil image: 96 bytes), which the list copies */
    static const GLubyte px[12 * 2 * 4] = { 0 };
    static const GLsizei depths[3] = { 1, 0, -65536 };
    for (int i = 0; i < 3; i++) {
        glNewList(1, GL_COMPILE);
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 2, 2, depths[i], GL_RGBA, GL_UNSIGNED_BYTE, px);
        fc_error(h, "compiled glTexSubImage3D");
        glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, depths[i], 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
        fc_error(h, "compiled glTexImage3D");
        glTexSubImage3D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 255, 3, 7, 3, 12, 2, depths[i],
                        GL_STENCIL_INDEX, GL_INT, px);
        fc_error(h, "compiled glTexSubImage3D, bad target and level");
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 0, 2, depths[i], GL_RGBA, GL_UNSIGNED_BYTE, px);
        fc_error(h, "compiled glTexSubImage3D, width 0");
        glEndList();
        glCallList(1);
        fc_error(h, "called");
    }
}

/* glMap2f compiled with a huge vorder: the list stores ustride =
 * components * vorder, which wraps in the oracle's int product; fixgl's
 * signed product was undefined behaviour (clang's UBSan, found by the
 * libFuzzer target in CI).  The replay raises the order's error again. */
static void map2_huge_order_compiled(fc_h *h)
{
    static const GLfloat pts[64] = { 0 };
    glNewList(1, GL_COMPILE_AND_EXECUTE);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, -2016688392, pts);
    glMap2f(GL_MAP2_VERTEX_4, 0, 1, 4, 2147483647, 0, 1, 8, 1431655766, pts);
    glEndList();
    fc_error(h, "compiled and executed");
    glCallList(1);
    fc_error(h, "replayed");
    GLint order[2] = { -1, -1 };
    glGetMapiv(GL_MAP2_VERTEX_3, GL_ORDER, order);
    fc_value(h, "MAP2_VERTEX_3 order u", order[0]);
    fc_value(h, "MAP2_VERTEX_3 order v", order[1]);
    fc_error(h, "after the query");
}

/* glCallLists(GL_FLOAT) of names past the int range or NaN: the oracle's
 * (GLint) cast is x86's cvttss2si, INT_MIN (no such list).  fixgl's C
 * cast was undefined behaviour (clang's UBSan, found by the libFuzzer
 * target). */
static void calllists_float_names(fc_h *h)
{
    const GLfloat names[] = { 1e20f, NAN, -3e9f, 2.0f, 2147483648.0f, 1.5f, -1.0f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    glColor3f(1, 0, 0);
    glRectf(2, 2, 20, 20);
    glEndList();
    glNewList(2, GL_COMPILE);
    glColor3f(0, 1, 0);
    glRectf(30, 30, 60, 50);
    glEndList();
    glCallLists(7, GL_FLOAT, names);
    fc_error(h, "glCallLists(GL_FLOAT)");
    glListBase(0x80000001u);
    glCallLists(1, GL_FLOAT, names);   /* INT_MIN + base: list 1 */
    fc_error(h, "with a base");
    glListBase(0);
    fc_capture(h);
}

/* Enum parameters given as floats out of the int range or NaN: the
 * oracle's (GLint) cast is x86's, INT_MIN, an invalid enum.  fixgl's C
 * casts were undefined behaviour (clang's UBSan, found by the libFuzzer
 * target): glTexGenf, glTexEnvf, and a compiled glCallLists(GL_FLOAT). */
static void float_enum_params(fc_h *h)
{
    const GLfloat names[] = { 3e26f, -3e26f, NAN, 1.0f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glTexGenf(GL_S, GL_TEXTURE_GEN_MODE, INFINITY);
    fc_error(h, "glTexGenf(GL_TEXTURE_GEN_MODE, inf)");
    glTexGenf(GL_T, GL_TEXTURE_GEN_MODE, 3e9f);
    fc_error(h, "glTexGenf(GL_TEXTURE_GEN_MODE, 3e9)");
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, NAN);
    fc_error(h, "glTexEnvf(GL_TEXTURE_ENV_MODE, NaN)");
    glTexEnvf(GL_TEXTURE_ENV, GL_COMBINE_RGB, -1e30f);
    fc_error(h, "glTexEnvf(GL_COMBINE_RGB, -1e30)");
    glNewList(1, GL_COMPILE);
    glColor3f(0, 0, 1);
    glRectf(5, 5, 40, 30);
    glEndList();
    glNewList(2, GL_COMPILE);
    glCallLists(4, GL_FLOAT, names);
    glEndList();
    fc_error(h, "compiled glCallLists(GL_FLOAT)");
    glCallList(2);
    fc_error(h, "called");
    fc_capture(h);
}

/* glClear under GL_SELECT or GL_FEEDBACK clears nothing (main/clear.c
 * clears in GL_RENDER mode only); fixgl cleared (found by the API
 * fuzzer). */
static void clear_in_select_feedback(fc_h *h)
{
    GLuint sel[8];
    GLfloat fb[8];
    fc_pixel_ortho(h);
    fcu_clear(0.25f, 0.5f, 0.75f, 1, 0.5f);
    glClearAccum(0.5f, 0.25f, 0, 1);
    glAccum(GL_LOAD, 1.0f);
    glColor3f(1, 0, 0);
    glRectf(4, 4, 40, 30);
    glClearColor(0, 1, 0, 1);
    glClearDepth(1.0);
    glClearStencil(3);
    glSelectBuffer(8, sel);
    glRenderMode(GL_SELECT);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT |
            GL_ACCUM_BUFFER_BIT);
    fc_value(h, "select", glRenderMode(GL_RENDER));
    glFeedbackBuffer(8, GL_2D, fb);
    glRenderMode(GL_FEEDBACK);
    glClear(GL_COLOR_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
    fc_value(h, "feedback", glRenderMode(GL_RENDER));
    fc_error(h, "glClear in select and feedback");
    fc_capture(h);
    glAccum(GL_RETURN, 1.0f);   /* the accumulation buffer kept its load */
    fc_error(h, "glAccum(GL_RETURN)");
    fc_capture(h);
}

/* glDrawPixels of GL_STENCIL_INDEX / GL_COLOR_INDEX floats past the
 * 64-bit range or NaN: the oracle's (GLuint) cast is x86-64's (0 there);
 * fixgl's C cast was undefined behaviour (clang's UBSan, found by the
 * libFuzzer target). */
static void drawpixels_float_indices(fc_h *h)
{
    const GLfloat idx[8] = { 1.72774e27f, NAN, -1e30f, 3.0f, 255.0f, 4294967296.0f,
                             -2.0f, 1e19f };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glWindowPos2i(4, 4);
    glPixelZoom(4, 4);
    glDrawPixels(8, 1, GL_STENCIL_INDEX, GL_FLOAT, idx);
    fc_error(h, "stencil indices");
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glColor3f(1, 1, 0);
    glRectf(0, 0, 64, 64);
    glDisable(GL_STENCIL_TEST);
    glWindowPos2i(4, 30);
    glDrawPixels(8, 1, GL_COLOR_INDEX, GL_FLOAT, idx);
    fc_error(h, "colour indices");
    glPixelZoom(1, 1);
    fc_capture(h);
}

/* A compiled glBegin/glEnd whose only commands are glEvalCoord (stored
 * as evaluator nodes, so the vertex list has no attribute and no buffer):
 * closing a line loop copied zero bytes from a NULL buffer (undefined
 * behaviour under UBSan; found by the libFuzzer target). */
static void dlist_loop_without_vertices(fc_h *h)
{
    static const GLfloat pts[2][3] = { { 4, 4, 0 }, { 60, 50, 0 } };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    glBegin(GL_LINE_LOOP);
    glEvalCoord1f(0.5f);
    glEvalCoord1f(0.25f);
    glEnd();
    glBegin(GL_LINE_LOOP);
    glEnd();
    glEndList();
    fc_error(h, "compiled");
    glCallList(1);
    fc_error(h, "called, no map");
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, &pts[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glColor3f(1, 1, 1);
    glCallList(1);
    glDisable(GL_MAP1_VERTEX_3);
    fc_error(h, "called with a map");
    fc_capture(h);
}

/* glReadPixels at x or y INT_MIN: clipped in wrapping int arithmetic,
 * the size becomes negative and nothing is read.  fixgl negated INT_MIN
 * (undefined behaviour under UBSan; found by the libFuzzer target). */
static void readpixels_int_min(fc_h *h)
{
    GLubyte px[4 * 4 * 4];
    fcu_clear(0.5f, 0.25f, 1, 1, 1);
    for (int i = 0; i < 3; i++) {
        memset(px, 0x5a, sizeof px);
        glReadPixels(i == 1 ? INT_MIN : 0, i == 0 ? INT_MIN : 0, 4, 4, GL_RGBA,
                     GL_UNSIGNED_BYTE, px);
        fc_error(h, "glReadPixels at INT_MIN");
        fc_value(h, "first byte", px[0]);
        fc_value(h, "last byte", px[sizeof px - 1]);
    }
}

/* ---- AddressSanitizer faults ---- */

/* A compiled glPolygonStipple replays its own 32x32 copy with the default
 * unpack state, whatever the unpack state when the list is called. */
static void dlist_polygon_stipple(fc_h *h)
{
    GLubyte p[128];
    pattern_bits(p, 128);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(6, GL_COMPILE_AND_EXECUTE);
    glPolygonStipple(p);
    glEndList();
    fc_error(h, "compile");
    glPixelStoref(GL_UNPACK_ROW_LENGTH, 200.4f);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 7);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    glCallList(6);
    fc_error(h, "call");
    GLubyte q[128];
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetPolygonStipple(q);
    fc_blob(h, "stipple (packed with the default state)", q, sizeof q);
    glEnable(GL_POLYGON_STIPPLE);
    glColor3f(0, 1, 1);
    fcu_rect(0, 0, 48, 40, 0);
    glDisable(GL_POLYGON_STIPPLE);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    fc_capture(h);
}

/* glMap1f/glMap2f with a negative stride (or one below the component
 * count) while compiling: the node keeps its own packed stride, so Mesa
 * raises no error when it executes, and reads before the caller's points
 * (the first list here: before pts) where fixgl reads nothing.  The
 * values of such a map are not compared: only a valid map is drawn. */
static void dlist_map_bad_stride(fc_h *h)
{
    GLfloat pts[64];
    for (int i = 0; i < 64; i++)
        pts[i] = (float)(i % 7) * 4.0f;
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, -1, 4, pts);
    glEndList();
    fc_error(h, "compile map1 stride -1");
    glCallList(1);
    fc_error(h, "call map1 stride -1");
    glNewList(2, GL_COMPILE);
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, -4, 4, pts + 32);
    glMap1d(GL_MAP1_VERTEX_4, 0, 1, -2, 2, (const GLdouble *)(const void *)(pts + 32));
    glEndList();
    fc_error(h, "compile map1 stride -4");
    glCallList(2);
    fc_error(h, "call map1 stride -4");
    glNewList(3, GL_COMPILE_AND_EXECUTE);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, -3, 2, 0, 1, 6, 2, pts + 32);
    glEndList();
    fc_error(h, "compile and execute map2 ustride -3");
    glNewList(4, GL_COMPILE);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, -5, 2, pts + 32);
    glMap2f(GL_MAP2_COLOR_4, 0, 1, 2, 2, 0, 1, 4, 2, pts + 32);
    glEndList();
    fc_error(h, "compile map2 vstride -5");
    glCallList(4);
    fc_error(h, "call map2");
    /* a valid map still works */
    static const GLfloat line[6] = { 4, 4, 0, 60, 50, 0 };
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, line);
    glEnable(GL_MAP1_VERTEX_3);
    glColor3f(1, 1, 1);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= 8; i++)
        glEvalCoord1f((float)i / 8.0f);
    glEnd();
    fc_error(h, "valid map");
    fc_capture(h);
}

/* ---- a slow path ---- */

/* glGenLists(95134) then glDeleteLists(1, 65536): Mesa takes a few ms,
 * fixgl took 1.4 s (a move of the name table per name).  The case checks
 * the names each pair leaves, three times over; its time is not asserted
 * here (tests assert no timing: the slow path is for the fuzzer's
 * per-stream time limit, issue 18 section 2). */
static void genlists_delete_many(fc_h *h)
{
    for (int r = 0; r < 3; r++) {
        GLuint base = glGenLists(95134);
        glDeleteLists(base, 65536);
        fc_value(h, "base", base);
        fc_error(h, "gen/delete");
        fc_value(h, "glIsList(base + 65535)", glIsList(base + 65535));
        fc_value(h, "glIsList(base + 65536)", glIsList(base + 65536));
        fc_value(h, "glIsList(base + 95133)", glIsList(base + 95133));
        fc_value(h, "glIsList(base + 95134)", glIsList(base + 95134));
    }
    GLuint l = glGenLists(4);
    fc_value(h, "next", l);
    glDeleteLists(1, 300000);
    fc_error(h, "delete all");
    fc_value(h, "after delete all", glGenLists(2));
}

/* ---- GL errors that differed from the oracle ---- */

/* glGenTextures after glBindTexture(GL_TEXTURE_2D, 0xFFFFFFFF): Mesa's
 * quick path hands out the names after the largest one, wrapping. */
static void gentextures_after_max_name(fc_h *h)
{
    GLuint t[3] = { 77, 77, 77 };
    glBindTexture(GL_TEXTURE_2D, 0xFFFFFFFFu);
    fc_error(h, "bind max");
    glGenTextures(3, t);
    fc_error(h, "gen");
    fc_value(h, "names 0", t[0]);
    fc_value(h, "names 1", t[1]);
    fc_value(h, "names 2", t[2]);
    fc_value(h, "is max", glIsTexture(0xFFFFFFFFu));
    glBindTexture(GL_TEXTURE_2D, 2);
    glGenTextures(3, t);
    fc_error(h, "gen again");
    fc_value(h, "again 0", t[0]);
    fc_value(h, "again 1", t[1]);
    fc_value(h, "again 2", t[2]);
    glBindTexture(GL_TEXTURE_2D, 0);
    fc_error(h, "unbind");
}

/* glGenTextures between glBegin and glEnd: GL_INVALID_OPERATION, no name. */
static void gentextures_inside_begin_end(fc_h *h)
{
    GLuint t[2] = { 77, 77 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glColor3f(1, 0, 1);
    glBegin(GL_TRIANGLES);
    glVertex2f(1, 1);
    glGenTextures(2, t);
    glVertex2f(30, 2);
    glVertex2f(12, 30);
    glEnd();
    fc_error(h, "after glEnd");
    fc_value(h, "name 0", t[0]);
    fc_value(h, "name 1", t[1]);
    glGenTextures(2, t);
    fc_value(h, "then 0", t[0]);
    fc_value(h, "then 1", t[1]);
    fc_capture(h);
}

/* While a list is compiled, glGenTextures goes through the save dispatch
 * straight to _mesa_GenTextures, which never checks for glBegin/glEnd: a
 * GL_COMPILE_AND_EXECUTE list with an open glBegin (and a texture
 * coordinate after its vertex, which made fixgl execute the glBegin)
 * still generates names.  fixgl raised GL_INVALID_OPERATION (found by the
 * API fuzzer). */
static void gentextures_compiling_begin_end(fc_h *h)
{
    GLuint t[2] = { 77, 77 }, u[2] = { 77, 77 };
    static const GLdouble tc[2] = { 0.5, 0.25 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glColor3f(0, 1, 1);
    glNewList(3, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_TRIANGLES);
    glVertex2f(1, 1);
    glTexCoord2dv(tc);
    glGenTextures(2, t);
    glVertex2f(40, 4);
    glVertex2f(12, 50);
    glEnd();
    glEndList();
    fc_error(h, "GL_COMPILE_AND_EXECUTE");
    fc_value(h, "name 0", t[0]);
    fc_value(h, "name 1", t[1]);
    glNewList(4, GL_COMPILE);
    glBegin(GL_LINES);
    glVertex2f(3, 60);
    glGenTextures(2, u);
    glVertex2f(60, 30);
    glEnd();
    glEndList();
    fc_error(h, "GL_COMPILE");
    fc_value(h, "compiled 0", u[0]);
    fc_value(h, "compiled 1", u[1]);
    glCallList(4);
    fc_error(h, "called");
    fc_capture(h);
}

/* glBitmap with a negative size: compiled as is by glNewList(GL_COMPILE),
 * GL_INVALID_VALUE when it executes. */
static void bitmap_negative_compile(fc_h *h)
{
    GLubyte b[64];
    pattern_bits(b, 64);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glColor3f(1, 1, 1);
    glRasterPos2i(4, 4);
    glNewList(1, GL_COMPILE);
    glBitmap(-8, 8, 0, 0, 3, 3, b);
    glBitmap(-3, -2, 0, 0, 3, 3, b);
    glBitmap(8, 8, 0, 0, 10, 1, b);
    glEndList();
    fc_error(h, "compile");
    glCallList(1);
    fc_error(h, "call");
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glBitmap(-5, 8, 0, 0, 3, 3, b);
    glBitmap(8, 8, 0, 0, 10, 1, b);
    glEndList();
    fc_error(h, "compile and execute");
    glCallList(2);
    fc_error(h, "call 2");
    fc_get_float(h, "raster pos", GL_CURRENT_RASTER_POSITION, 4);
    fc_capture(h);
}

/* GL_TEXTURE_BORDER_COLOR through the scalar glTexParameter calls and
 * glTexParameteriv, outside a list, compiled and compiled-and-executed. */
static void texparam_border_color(fc_h *h)
{
    static const GLint iv[4] = { INT_MAX, INT_MAX / 2, 0, INT_MAX };
    GLfloat c[4];
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5f);
    fc_error(h, "glTexParameterf");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1);
    fc_error(h, "glTexParameteri");
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, iv);
    fc_error(h, "glTexParameteriv");
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, c);
    fc_blob(h, "border", c, sizeof c);
    glNewList(1, GL_COMPILE_AND_EXECUTE);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.25f);
    fc_error(h, "cae glTexParameterf");
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, c);
    fc_blob(h, "border cae f", c, sizeof c);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 3);
    fc_error(h, "cae glTexParameteri");
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, c);
    fc_blob(h, "border cae i", c, sizeof c);
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, iv);
    fc_error(h, "cae glTexParameteriv");
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, c);
    fc_blob(h, "border cae iv", c, sizeof c);
    glEndList();
    fc_error(h, "end list");
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5f);
    glNewList(2, GL_COMPILE);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.75f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, -2);
    glEndList();
    fc_error(h, "compile");
    glCallList(2);
    fc_error(h, "call");
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, c);
    fc_blob(h, "border called", c, sizeof c);
    glCallList(1);
    fc_error(h, "call 1");
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, c);
    fc_blob(h, "border called 1", c, sizeof c);
}

/* glGet of a texture unit's fixed-function state (GL_TEXTURE_GEN_S, ...)
 * with an active unit past the coordinate units. */
static void texgen_query_beyond_units(fc_h *h)
{
    static const GLenum pn[] = {
        GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q,
        GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_ENV_COLOR, GL_TEXTURE_ENV_MODE,
        GL_TEXTURE_MATRIX, GL_TEXTURE_STACK_DEPTH, GL_CURRENT_TEXTURE_COORDS,
        GL_TEXTURE_BINDING_2D,
    };
    static const GLenum units[] = { GL_TEXTURE7, GL_TEXTURE8, GL_TEXTURE31, GL_TEXTURE0 + 100 };
    for (unsigned u = 0; u < sizeof units / sizeof units[0]; u++) {
        glActiveTexture(units[u]);
        fc_error(h, "glActiveTexture");
        for (unsigned i = 0; i < sizeof pn / sizeof pn[0]; i++) {
            GLfloat f[16];
            GLboolean b[16];
            GLint iv[16];
            GLdouble d[16];
            glGetFloatv(pn[i], f);
            fc_error(h, "glGetFloatv");
            glGetBooleanv(pn[i], b);
            fc_error(h, "glGetBooleanv");
            glGetIntegerv(pn[i], iv);
            fc_error(h, "glGetIntegerv");
            glGetDoublev(pn[i], d);
            fc_error(h, "glGetDoublev");
            glIsEnabled(pn[i]);
            fc_error(h, "glIsEnabled");
        }
    }
    glActiveTexture(GL_TEXTURE0);
}

/* glMatrixMode(GL_TEXTUREi): Mesa takes a texture unit's stack, up to the
 * coordinate units. */
static void matrixmode_texture_unit(fc_h *h)
{
    static const GLenum modes[] = { GL_TEXTURE0, GL_TEXTURE3, GL_TEXTURE4, GL_TEXTURE7,
                                    GL_TEXTURE8, GL_TEXTURE31 };
    for (unsigned i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        glMatrixMode(modes[i]);
        fc_error(h, "glMatrixMode");
        fc_get_integer(h, "GL_MATRIX_MODE", GL_MATRIX_MODE, 1);
        glLoadIdentity();
        glTranslatef((float)i + 1, 2, 3);
        glPushMatrix();
        fc_error(h, "load, translate, push");
    }
    glMatrixMode(GL_TEXTURE);
    fc_error(h, "GL_TEXTURE");
    for (int u = 0; u < 8; u++) {
        glActiveTexture(GL_TEXTURE0 + (GLenum)u);
        fc_get_float(h, "GL_TEXTURE_MATRIX", GL_TEXTURE_MATRIX, 16);
        fc_get_integer(h, "GL_TEXTURE_STACK_DEPTH", GL_TEXTURE_STACK_DEPTH, 1);
    }
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_TEXTURE3);
    glPushAttrib(GL_TRANSFORM_BIT);
    glMatrixMode(GL_MODELVIEW);
    glPopAttrib();
    fc_get_integer(h, "GL_MATRIX_MODE popped", GL_MATRIX_MODE, 1);
    glPopMatrix();
    fc_error(h, "pop");
    glActiveTexture(GL_TEXTURE3);
    fc_get_integer(h, "GL_TEXTURE_STACK_DEPTH 3", GL_TEXTURE_STACK_DEPTH, 1);
    glActiveTexture(GL_TEXTURE0);
    glNewList(1, GL_COMPILE);
    glMatrixMode(GL_TEXTURE5);
    glLoadIdentity();
    glScalef(2, 2, 2);
    glEndList();
    glCallList(1);
    fc_error(h, "list");
    fc_get_integer(h, "GL_MATRIX_MODE list", GL_MATRIX_MODE, 1);
    glActiveTexture(GL_TEXTURE5);
    fc_get_float(h, "GL_TEXTURE_MATRIX 5", GL_TEXTURE_MATRIX, 16);
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_MODELVIEW);
}

/* glCallList inside glBegin/glEnd of a list that begins a primitive, and
 * of a list holding a glDrawPixels. */
static void calllist_inside_begin_end(fc_h *h)
{
    GLubyte px[4 * 4 * 4];
    memset(px, 200, sizeof px);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glNewList(1, GL_COMPILE);
    glBegin(GL_LINES);
    glColor3f(1, 0, 0);
    glVertex2f(2, 2);
    glVertex2f(30, 30);
    glEnd();
    glEndList();
    glNewList(2, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glVertex2f(40, 2);
    glVertex2f(60, 2);
    glVertex2f(50, 20);
    glEnd();
    glEndList();
    glNewList(3, GL_COMPILE);
    glRasterPos2i(5, 40);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glEndList();
    glNewList(4, GL_COMPILE);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glEndList();
    fc_error(h, "compile");

    glColor3f(0, 1, 0);
    glBegin(GL_LINES);
    glCallList(1);
    glEnd();
    fc_error(h, "lines list inside GL_LINES");
    glBegin(GL_LINES);
    glVertex2f(2, 30);
    glCallList(1);
    glVertex2f(30, 2);
    glEnd();
    fc_error(h, "lines list after a vertex");
    glBegin(GL_LINES);
    glCallList(2);
    glEnd();
    fc_error(h, "triangles list inside GL_LINES");
    glBegin(GL_TRIANGLES);
    glCallList(3);
    glEnd();
    fc_error(h, "drawpixels list inside GL_TRIANGLES");
    glRasterPos2i(20, 40);
    glBegin(GL_POINTS);
    glCallList(4);
    glEnd();
    fc_error(h, "drawpixels only inside GL_POINTS");
    glNewList(5, GL_COMPILE);
    glBegin(GL_LINES);
    glCallList(1);
    glCallList(4);
    glEnd();
    glEndList();
    fc_error(h, "compile nested");
    glCallList(5);
    fc_error(h, "call nested");
    fc_capture(h);
}

/* glTexParameter level values out of range or fractional, directly and
 * through a list; glPushMatrix at each stack's limit. */
static void texparam_levels_and_push_limit(fc_h *h)
{
    static const GLint imax = INT_MAX;
    GLint v[2];
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &imax);
    fc_error(h, "max level INT_MAX");
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -0.74f);
    fc_error(h, "base level -0.74");
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3e9f);
    fc_error(h, "max level 3e9");
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2.9f);
    fc_error(h, "base level 2.9");
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, v);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, v + 1);
    fc_blob(h, "levels", v, sizeof v);
    glNewList(1, GL_COMPILE);
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &imax);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, INT_MAX - 64);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -0.74f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 5);
    glEndList();
    glCallList(1);
    fc_error(h, "list");
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, v);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, v + 1);
    fc_blob(h, "levels list", v, sizeof v);

    static const GLenum modes[] = { GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE };
    for (unsigned m = 0; m < 3; m++) {
        glMatrixMode(modes[m]);
        for (int i = 0; i < 40; i++)
            glPushMatrix();
        fc_error(h, "push to the limit");
        glPushMatrix();
        fc_error(h, "push past");
        glNewList(2, GL_COMPILE_AND_EXECUTE);
        glPushMatrix();
        glEndList();
        fc_error(h, "push past in a list");
        glCallList(2);
        fc_error(h, "push past calling it");
        glBegin(GL_POINTS);
        glPushMatrix();
        glEnd();
        fc_error(h, "push inside begin/end");
        for (int i = 0; i < 40; i++)
            glPopMatrix();
        fc_error(h, "pop");
    }
    glActiveTexture(GL_TEXTURE9);
    glMatrixMode(GL_TEXTURE);
    for (int i = 0; i < 12; i++)
        glPushMatrix();
    fc_error(h, "unit 9 push");
    for (int i = 0; i < 12; i++)
        glPopMatrix();
    fc_error(h, "unit 9 pop");
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_MODELVIEW);
}

/* ---- display list content ---- */

/* glTexImage2D of GL_COLOR_INDEX and GL_BITMAP data compiled into a list:
 * replayed, the texture holds the same texels as the first execution. */
static void dlist_teximage_color_index(fc_h *h)
{
    static const GLfloat rmap[4] = { 0.0f, 1.0f, 0.2f, 0.6f };
    static const GLfloat gmap[4] = { 1.0f, 0.0f, 0.8f, 0.3f };
    static const GLfloat bmap[4] = { 0.5f, 0.25f, 1.0f, 0.0f };
    static const GLfloat amap[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
    GLubyte idx[8 * 8], bits[8];
    for (int i = 0; i < 64; i++)
        idx[i] = (GLubyte)((i * 5 + i / 8) & 3);
    pattern_bits(bits, 8);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, rmap);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, gmap);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, bmap);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, amap);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    GLubyte tex[8 * 8 * 4];
    for (int k = 0; k < 2; k++) {
        const GLenum type = k ? GL_BITMAP : GL_UNSIGNED_BYTE;
        const void *data = k ? (const void *)bits : (const void *)idx;
        glNewList(1 + (GLuint)k, GL_COMPILE_AND_EXECUTE);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_COLOR_INDEX, type, data);
        glEndList();
        fc_error(h, "compile and execute");
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
        fc_blob(h, "first execution", tex, sizeof tex);
        fcu_rect(2 + 30.0f * (float)k, 2, 26 + 30.0f * (float)k, 26, 0);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, bits);
        glCallList(1 + (GLuint)k);
        fc_error(h, "replay");
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
        fc_blob(h, "replayed", tex, sizeof tex);
        fcu_rect(2 + 30.0f * (float)k, 32, 26 + 30.0f * (float)k, 58, 0);
    }
    glDisable(GL_TEXTURE_2D);
    fc_capture(h);
}

/* ---- huge but legal requests (issue 18 §4): they complete, or raise the
 * oracle's error, in bounded time and memory ---- */

/* The largest texture the limits allow: the proxy at GL_MAX_TEXTURE_SIZE
 * squared (no storage), and one past it; real images of the largest width
 * by 1 and 1 by the largest height, drawn. */
static void huge_texture(fc_h *h)
{
    GLint max = 0, w = -1;
    static GLubyte row[4 * 16384];
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
    fc_value(h, "GL_MAX_TEXTURE_SIZE", max);
    if (max <= 0 || max > 16384)
        return;
    for (int i = 0; i < 4 * max; i++)
        row[i] = (GLubyte)(i * 7 + (i >> 9));
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, max, max, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "proxy max x max");
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    fc_value(h, "proxy width", w);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 2 * max, max, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    fc_error(h, "proxy 2 max x max");
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    fc_value(h, "proxy width past the limit", w);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    for (int k = 0; k < 2; k++) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, k ? 1 : max, k ? max : 1, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, row);
        fc_error(h, k ? "1 x max" : "max x 1");
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0); glVertex2f(2, 2 + 30.0f * (float)k);
        glTexCoord2f(1, 0); glVertex2f(62, 2 + 30.0f * (float)k);
        glTexCoord2f(1, 1); glVertex2f(62, 28 + 30.0f * (float)k);
        glTexCoord2f(0, 1); glVertex2f(2, 28 + 30.0f * (float)k);
        glEnd();
    }
    glDisable(GL_TEXTURE_2D);
    fc_capture(h);
}

/* The largest viewport (GL_MAX_VIEWPORT_DIMS) and beyond it (clamped), a
 * triangle drawn through each: the part inside the window shows. */
static void huge_viewport(fc_h *h)
{
    GLint dims[2] = { 0, 0 };
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
    fc_value(h, "max viewport w", dims[0]);
    fc_value(h, "max viewport h", dims[1]);
    fcu_clear(0, 0, 0, 1, 1);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for (int k = 0; k < 3; k++) {
        const GLint x = k == 2 ? -dims[0] + 40 : 0, y = k == 1 ? -dims[1] / 2 : 0;
        glViewport(x, y, k == 2 ? INT_MAX : dims[0], k == 2 ? INT_MAX : dims[1]);
        fc_error(h, "glViewport");
        fc_get_integer(h, "GL_VIEWPORT", GL_VIEWPORT, 4);
        fcu_color(k);
        glBegin(GL_TRIANGLES);
        glVertex2f(-1, -1);
        glVertex2f(-1.0f + 40.0f / (float)dims[0], -1);
        glVertex2f(-1, -1.0f + 50.0f / (float)dims[1]);
        glEnd();
        fc_error(h, "draw");
    }
    fc_capture(h);
}

/* glCallLists of a million names: most name no list, every 1000th one of
 * three lists that draw; GL_UNSIGNED_INT and GL_2_BYTES. */
static void calllists_million(fc_h *h)
{
    enum { N = 1000000 };
    static GLuint names[N];
    static GLubyte two[2 * N];
    GLuint base = glGenLists(3);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 1, 1);
    for (GLuint k = 0; k < 3; k++) {
        glNewList(base + k, GL_COMPILE);
        fcu_color((int)k);
        glTranslatef(1, 0.5f, 0);
        fcu_rect(0, 0, 3, 2, 0);
        glEndList();
    }
    for (int i = 0; i < N; i++) {
        names[i] = i % 1000 == 0 ? base + (GLuint)(i / 1000 % 3) : 100000u + (GLuint)i;
        two[2 * i] = (GLubyte)(names[i] >> 8), two[2 * i + 1] = (GLubyte)names[i];
    }
    glCallLists(N, GL_UNSIGNED_INT, names);
    fc_error(h, "GL_UNSIGNED_INT");
    glLoadIdentity();
    glTranslatef(0, 30, 0);
    glScalef(0.05f, 1, 1);
    glCallLists(N, GL_2_BYTES, two);
    fc_error(h, "GL_2_BYTES");
    fc_capture(h);
}

/* An array draw after current-value calls only (no vertex stored since the
 * last flush) is FLUSH_FOR_DRAW with FLUSH_UPDATE_CURRENT: the values are
 * copied to the current ones and the immediate-mode vertex format stays,
 * with its sizes and the sizes of the last calls.  glTexCoord4f,
 * glMultiTexCoord1d, glTexCoord4f, a draw, glMultiTexCoord3f keeps q = 4
 * (fixgl reset the format at the draw and gave q = 1; the API fuzzer's
 * seed 150).  And glEvalPoint2 with GL_MAP2_NORMAL enabled after such a
 * draw evaluates the normal into that vertex format (seed 224). */
static void draw_keeps_vertex_format(fc_h *h)
{
    static const GLfloat v[] = { 4, 4, 28, 6, 14, 28 };
    static const GLuint idx[] = { 0, 1, 2 };
    fc_pixel_ortho(h);
    glVertexPointer(2, GL_FLOAT, 0, v);
    for (int k = 0; k < 6; k++) {
        if (k & 1)
            glEnableClientState(GL_VERTEX_ARRAY);
        else
            glDisableClientState(GL_VERTEX_ARRAY);
        glTexCoord4f(-0.5f, -0.75f, 5, 2);
        glMultiTexCoord1d(GL_TEXTURE0, 1.99);
        glTexCoord4f(-0.5f, -0.75f, 5, 4);
        if (k < 2)
            glDrawArrays(GL_TRIANGLES, 0, 3);
        else if (k < 4)
            glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, idx);
        else
            glDrawRangeElements(GL_LINE_LOOP, 0, 2, 3, GL_UNSIGNED_INT, idx);
        glMultiTexCoord3f(GL_TEXTURE0, 0.25f, 0.5f, 0.75f);
        fc_error(h, "draw");
        fc_get_float(h, "texture coordinates after the draw", GL_CURRENT_TEXTURE_COORDS, 4);
        glFinish();
        fc_get_float(h, "texture coordinates after a flush", GL_CURRENT_TEXTURE_COORDS, 4);
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    /* seed 224: GL_MAP2_NORMAL on, no map given: the default normal map */
    glEnable(GL_MAP2_NORMAL);
    glNormal3f(0.5f, 0.25f, 0);
    glMultiTexCoord2d(GL_TEXTURE5, 6, 1.03);
    glDrawElements(GL_TRIANGLE_STRIP, 3, GL_UNSIGNED_INT, idx);
    glEvalPoint2(0, 5);
    fc_error(h, "eval point");
    fc_get_float(h, "normal after glEvalPoint2", GL_CURRENT_NORMAL, 3);
    glDisable(GL_MAP2_NORMAL);
    fc_capture(h);
}

/* Under GL_COMPILE_AND_EXECUTE a vertex list wrapped inside glBegin/glEnd
 * executes its glBegin (vbo_save's loopback), and the dispatch stays the
 * save table: the state queries executed at once while compiling run
 * through it without the glBegin/glEnd check, the texture environment,
 * texgen and texture parameter queries too (fixgl refused these three
 * with GL_INVALID_OPERATION and wrote nothing; the API fuzzer's seeds 171
 * and 281).  A compiled command is executed through ctx->Exec, the
 * BeginEnd table while the glBegin is open: after glCallLists inside the
 * compiled glBegin (the compiler forgets that it is inside), glRasterPos,
 * glWindowPos, glClearAccum and glAccum are compiled and refused
 * (fixgl executed them; seed 261). */
static void compile_execute_inside_begin(fc_h *h)
{
    GLuint tex = 0;
    static const GLubyte texel[4 * 4] = { 10, 20, 30, 40 };
    static const GLubyte names[1] = { 0 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glRasterPos2f(3, 5);
    glNewList(1, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_TRIANGLES);
    glVertex2f(2, 2);
    glVertex2f(30, 4);
    glVertex4i(16, 30, 0, 1);    /* a larger position: wraps, glBegin executed */
    GLfloat f[4] = { -1, -1, -1, -1 };
    GLint iv[4] = { -1, -1, -1, -1 };
    GLdouble d[4] = { -1, -1, -1, -1 };
    glGetTexGenfv(GL_T, GL_OBJECT_PLANE, f);
    fc_blob(h, "glGetTexGenfv", f, sizeof f);
    glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, iv);
    fc_blob(h, "glGetTexGeniv", iv, sizeof iv);
    glGetTexGendv(GL_S, GL_EYE_PLANE, d);
    fc_blob(h, "glGetTexGendv", d, sizeof d);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
    fc_blob(h, "glGetTexEnvfv", f, sizeof f);
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv);
    fc_blob(h, "glGetTexEnviv", iv, sizeof iv);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
    fc_blob(h, "glGetTexParameterfv", f, sizeof f);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, iv);
    fc_blob(h, "glGetTexParameteriv", iv, sizeof iv);
    glEnd();
    glEndList();
    fc_error(h, "list 1");
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_POLYGON);
    glVertex2f(40, 40);
    glCallLists(0, GL_UNSIGNED_BYTE, names);   /* glBegin executed */
    glRasterPos2f(20, 20);
    glWindowPos2i(30, 30);
    glClearAccum(0.5f, 0.5f, 0.5f, 0.5f);
    glAccum(GL_LOAD, 1.0f);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, f);
    fc_blob(h, "raster position inside", f, sizeof f);
    glEnd();
    glEndList();
    fc_error(h, "list 2");
    fc_get_float(h, "raster position", GL_CURRENT_RASTER_POSITION, 4);
    fc_get_float(h, "accum clear value", GL_ACCUM_CLEAR_VALUE, 4);
    glCallList(2);
    fc_error(h, "list 2 called");
    fc_get_float(h, "raster position after the call", GL_CURRENT_RASTER_POSITION, 4);
    fc_get_float(h, "accum clear value after the call", GL_ACCUM_CLEAR_VALUE, 4);
    glDisable(GL_TEXTURE_GEN_T);
    glDeleteTextures(1, &tex);
    fc_capture(h);
}

/* Array draws longer than 65536 vertices are fetched and transformed
 * window by window (libfixgl/tnl/t_array.c, t_render.c t_render_source:
 * bounded memory, so that a draw of 2^31 - 1 vertices completes); the
 * result must be the draw of all the vertices at once: the vsplit segments
 * (4096, 4095 for triangles, 1024 for long fans and polygons) with their
 * clipping decisions, strip parity, a fan's and a polygon's vertex 0 and
 * edge flags, a loop's closing line and the line stipple counter across
 * segments.  Each mode draws 70001 vertices, some of its segments clipped
 * at the window's sides; unfilled polygons and line stipple in part. */
static void long_array_draws(fc_h *h)
{
    enum { N = 70001 };
    static GLfloat v[N][3];
    static GLubyte c[N][4];
    static GLboolean ef[N];
    uint32_t seed = 12345u;
    for (int i = 0; i < N; i++) {
        seed = seed * 1664525u + 1013904223u;
        const int seg = i / 4096;
        /* every third segment reaches past the window (clipped) */
        const float span = seg % 3 == 1 ? 90.0f : 56.0f;
        v[i][0] = 4.0f + (float)((seed >> 8) % 1000) * span / 1000.0f - (seg % 3 == 1 ? 16.0f : 0.0f);
        v[i][1] = 4.0f + (float)((seed >> 18) % 1000) * 56.0f / 1000.0f;
        v[i][2] = (float)((seed >> 4) % 255) / 256.0f - 0.5f;
        c[i][0] = (GLubyte)(seed >> 3), c[i][1] = (GLubyte)(seed >> 11);
        c[i][2] = (GLubyte)(seed >> 19), c[i][3] = 255;
        ef[i] = (seed >> 27) % 3 != 0;
    }
    fc_pixel_ortho(h);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    static const GLenum modes[] = { GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP,
                                    GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                                    GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        fcu_clear(0, 0, 0, 0, 1);
        glDrawArrays(modes[m], 0, N);
        fc_error(h, "draw");
        fc_capture(h);
    }
    /* unfilled with edge flags, line stipple, an odd first */
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glEdgeFlagPointer(0, ef);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(3, 0x3c5f);
    static const GLenum unfilled[] = { GL_TRIANGLE_FAN, GL_POLYGON, GL_QUAD_STRIP,
                                       GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLE_STRIP };
    for (size_t m = 0; m < sizeof unfilled / sizeof unfilled[0]; m++) {
        fcu_clear(0, 0, 0, 0, 1);
        glDrawArrays(unfilled[m], 3, N - 3);
        fc_error(h, "unfilled draw");
        fc_capture(h);
    }
    glDisable(GL_LINE_STIPPLE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisable(GL_DEPTH_TEST);
}

/* glBitmap with a negative size, compiled: the oracle makes its texture
 * from the sizes as unsigned (the height's low 16 bits) and raises
 * GL_OUT_OF_MEMORY when that needs more than 2 GiB, without compiling or
 * executing the call; smaller ones compile and raise GL_INVALID_VALUE when
 * executed (the API fuzzer's seed 1000699; probe p_bitmap_compile_negative).
 * No size here is one that crashes the oracle (a positive width with a
 * negative height whose texture it can make). */
static void bitmap_negative_compile_sizes(fc_h *h)
{
    static const GLsizei sizes[][2] = {
        { -64, 1 }, { -2147483647 - 1, 308 }, { -63, 308 }, { -64, 0 },
        { -64, -2147483647 - 1 }, { -64, -65535 }, { 100000, -1 },
        { 40000, -2147483647 + 3 }, { -1000, -1 }, { -1, -2147483647 - 1 },
    };
    GLubyte b[64];
    pattern_bits(b, 64);
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glColor3f(1, 1, 1);
    glRasterPos2i(4, 4);
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        glNewList(1, GL_COMPILE);
        glBitmap(sizes[i][0], sizes[i][1], 0, 0, 1, 2, b);
        fc_error(h, "compiled");
        glBitmap(8, 8, 0, 0, 9, 1, b);
        glEndList();
        glCallList(1);
        fc_error(h, "called");
        glNewList(2, GL_COMPILE_AND_EXECUTE);
        glBitmap(sizes[i][0], sizes[i][1], 0, 0, 1, 2, b);
        fc_error(h, "compiled and executed");
        glEndList();
        glCallList(2);
        fc_error(h, "called 2");
        fc_get_float(h, "raster pos", GL_CURRENT_RASTER_POSITION, 4);
    }
    fc_capture(h);
}

/* A white triangle in a 32x32 pixel frame, and the error after it. */
static void witness_triangle(fc_h *h)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 1);
    glVertex2f(2, 2);
    glVertex2f(30, 6);
    glVertex2f(14, 30);
    glEnd();
    fc_error(h, "a triangle");
}

/* A display list whose glBegin is split across two vertex lists (a new
 * attribute after the first vertex wraps the compiler's store) and whose
 * second vertex list also holds a compiled glDrawElements: that node does
 * not copy to the current values, so replaying it leaves the context inside
 * glBegin/glEnd with no primitive open in the immediate-mode store (Mesa's
 * CurrentExecPrimitive set by the first node).  glGetError reports nothing
 * there; the next glEnd leaves it like any glEnd (vbo_exec_End), and the
 * error raised by the list's compiled glBindTexture then shows (fixgl
 * stayed inside for good; fuzzer seeds 3000018 and 3000208; probe
 * p_end_after_list). */
static void end_after_list_mid_primitive(fc_h *h)
{
    static const GLfloat v[8] = { 4, 4, 28, 4, 28, 28, 4, 28 };
    static const GLubyte idx[2] = { 0, 1 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_VERTEX_ARRAY);
    glNewList(1, GL_COMPILE);
    glBindTexture(GL_PROXY_TEXTURE_3D, 4);   /* compiled: INVALID_ENUM when called */
    glBegin(GL_POINTS);
    glSecondaryColor3ui(5, 243, 0xffff0000u);
    glVertex2d(10, 10);
    glColor3ui(7, 6, 6);                     /* after a vertex: wraps */
    glColor3f(0.25f, 0.5f, 0.75f);
    glEnd();
    glDrawElements(GL_QUADS, 2, GL_UNSIGNED_BYTE, idx);
    glEndList();
    fc_error(h, "list 1 compiled");
    glCallList(1);
    fc_error(h, "list 1 called (inside: nothing reported)");
    glLineWidth(-1.0f);
    fc_error(h, "glLineWidth(-1) inside");
    glEnd();
    fc_error(h, "glEnd after the list");
    glLineWidth(-1.0f);
    fc_error(h, "glLineWidth(-1) after glEnd");
    glEnd();
    fc_error(h, "a second glEnd");
    witness_triangle(h);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDeleteLists(1, 1);
    fc_capture(h);
}

/* A list whose vertex list ends mid-primitive (the colour grows after the
 * last vertex, then a glDrawElements) leaves the oracle's
 * CurrentExecPrimitive inside glBegin/glEnd while its dispatch stays the
 * outside one: entry points without a check of their own run (glLineWidth
 * raises its GL_INVALID_VALUE, glBlendColor, glBlendFunc, glEnable,
 * glClearColor and glClear take effect, glGetTexParameteriv answers),
 * those with one refuse (glIsEnabled); glGetError reports nothing until
 * the glEnd (fixgl refused every call; fuzzer seed 3000503; probe
 * p_dlist_stuck_entry_points). */
static void stuck_list_entry_points(fc_h *h)
{
    static const GLfloat v[6] = { 1, 1, 15, 1, 1, 15 };
    static const GLuint idx[3] = { 0, 1, 2 };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_VERTEX_ARRAY);
    glNewList(1, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(20, 20);
    glColor3f(1, 0, 0); glVertex2f(30, 20);
    glColor3f(1, 0, 0); glVertex2f(20, 30);
    glColor4f(1, 0, 0, 1);                   /* after the last vertex */
    glEnd();
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, idx);
    glEndList();
    fc_error(h, "list compiled");
    glCallList(1);
    glLineWidth(-1.0f);
    fc_error(h, "glLineWidth(-1) while stuck (nothing reported)");
    glEnd();
    fc_error(h, "glEnd: glLineWidth's error");
    glCallList(1);
    (void)glIsEnabled(GL_BLEND);
    glEnd();
    fc_error(h, "glIsEnabled while stuck, glEnd");
    glCallList(1);
    glBlendColor(0, 1, 0.5f, 1);
    glBlendFunc(GL_CONSTANT_COLOR, GL_ZERO);
    glEnable(GL_BLEND);
    glClearColor(0.25f, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    GLint filter = 0;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
    glEnd();
    fc_error(h, "state calls while stuck, glEnd");
    fc_get_float(h, "blend colour", GL_BLEND_COLOR, 4);
    fc_get_float(h, "colour clear value", GL_COLOR_CLEAR_VALUE, 4);
    fc_get_float(h, "line width", GL_LINE_WIDTH, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 1);
    glVertex2f(2, 18);
    glVertex2f(30, 22);
    glVertex2f(14, 30);
    glEnd();
    fc_error(h, "a blended triangle");
    glDisable(GL_BLEND);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDeleteLists(1, 1);
    fc_capture(h);
}

/* GL_INDEX_SHIFT outside [-31, 31]: colour indices through glDrawPixels
 * and glTexImage2D (GL_COLOR_INDEX, GL_UNSIGNED_INT) with shifts 40, -40,
 * INT_MIN, 33 and -33 (and 8 / -8 as witnesses), mapped by 256-entry
 * I_TO_R/G/B/A maps; the oracle's C shifts by the count modulo 32 as x86
 * does (commit e01c896; the long libFuzzer campaign's UBSan report). */
static void index_shift_huge(fc_h *h)
{
    static const GLint shifts[7] = { 8, -8, 40, -40, INT_MIN, 33, -33 };
    static const GLuint idx[8] = {
        0x12345678u, 0x9abcdef0u, 0x00000001u, 0x80000000u,
        0x000000ffu, 0x0000ff00u, 0x00ff0000u, 0xff000000u,
    };
    GLfloat r[256], g[256], b[256], a[256];
    for (int i = 0; i < 256; i++) {
        r[i] = (GLfloat)i / 255.0f;
        g[i] = (GLfloat)((i * 7) & 255) / 255.0f;
        b[i] = (GLfloat)(255 - i) / 255.0f;
        a[i] = 1.0f;
    }
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 256, r);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 256, g);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 256, b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 256, a);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int k = 0; k < 7; k++) {
        glPixelTransferi(GL_INDEX_SHIFT, shifts[k]);
        glPixelTransferi(GL_INDEX_OFFSET, k == 6 ? 3 : 0);
        fc_error(h, "glPixelTransferi(GL_INDEX_SHIFT)");
        fc_get_float(h, "index shift", GL_INDEX_SHIFT, 1);
        glWindowPos2i(0, 2 * k);
        glDrawPixels(8, 1, GL_COLOR_INDEX, GL_UNSIGNED_INT, idx);
        fc_error(h, "glDrawPixels of indices");
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 1, 0, GL_COLOR_INDEX, GL_UNSIGNED_INT, idx);
        fc_error(h, "glTexImage2D of indices");
        glEnable(GL_TEXTURE_2D);
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0); glVertex2f(16, (GLfloat)(2 * k));
        glTexCoord2f(1, 0); glVertex2f(32, (GLfloat)(2 * k));
        glTexCoord2f(1, 1); glVertex2f(32, (GLfloat)(2 * k + 2));
        glTexCoord2f(0, 1); glVertex2f(16, (GLfloat)(2 * k + 2));
        glEnd();
        glDisable(GL_TEXTURE_2D);
        fc_error(h, "the textured quad");
    }
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    fc_capture(h);
}

/* A point whose window y lies beyond the int range of the 24.8 snap
 * (a viewport origin near INT_MIN): llvmpipe's y0 = snap(y) - 1 wraps
 * (lp_setup_point.c), nothing is drawn (the long libFuzzer campaign's
 * UBSan report at r_point.c); then a point in the normal viewport. */
static void point_huge_viewport_y(fc_h *h)
{
    glViewport(0, -2000000000, 32, 32);
    glPointSize(3);
    glBegin(GL_POINTS);
    glColor3f(1, 0, 0);
    glVertex2f(0, 0);
    glVertex2f(0.5f, -0.5f);
    glEnd();
    fc_error(h, "points at y near INT_MIN");
    glViewport(0, 0, 32, 32);
    glBegin(GL_POINTS);
    glColor3f(0, 1, 0);
    glVertex2f(0.25f, 0.25f);
    glEnd();
    fc_error(h, "witness point");
    fc_capture(h);
}

/* glGet(GL_TRANSPOSE_TEXTURE_MATRIX) reads texture unit 0's matrix on
 * every active unit (the oracle's get table: CONTEXT_MATRIX_T of the
 * first stack), GL_TEXTURE_MATRIX the active unit's (the API fuzzer's
 * seed 1000655: glActiveTexture, glMatrixMode, glScaled; probe
 * p_transpose_texmat). */
static void transpose_texture_matrix_unit(fc_h *h)
{
    static const GLenum units[4] = { GL_TEXTURE1, GL_TEXTURE0, GL_TEXTURE3, GL_TEXTURE7 };
    glMatrixMode(GL_TEXTURE);
    glActiveTexture(GL_TEXTURE0);
    glScaled(1e20, -3.5, 0.25);
    glTranslated(2, 0, -1);
    glActiveTexture(GL_TEXTURE1);
    glRotated(30, 0, 0, 1);
    glActiveTexture(GL_TEXTURE3);
    glScaled(2, 2, 2);
    fc_error(h, "matrices");
    for (int i = 0; i < 4; i++) {
        glActiveTexture(units[i]);
        fc_get_float(h, "texture matrix", GL_TEXTURE_MATRIX, 16);
        fc_get_float(h, "transpose texture matrix", GL_TRANSPOSE_TEXTURE_MATRIX, 16);
        fc_get_double(h, "transpose texture matrix (double)", GL_TRANSPOSE_TEXTURE_MATRIX, 16);
        fc_get_integer(h, "transpose texture matrix (int)", GL_TRANSPOSE_TEXTURE_MATRIX, 16);
    }
    glActiveTexture(GL_TEXTURE0);
    glLoadIdentity();
    glActiveTexture(GL_TEXTURE1);
    fc_get_float(h, "transpose after unit 0 reset", GL_TRANSPOSE_TEXTURE_MATRIX, 16);
    glLoadIdentity();
    glActiveTexture(GL_TEXTURE3);
    glLoadIdentity();
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_MODELVIEW);
}

/* glTexParameterf of an integer parameter at the edges of the int range:
 * Mesa rounds and clamps with float compares against INT_MAX and INT_MIN,
 * which are 2^31 and -2^31 as floats, so 2^31 itself is converted as x86
 * converts 2^31 + 0.5, to INT_MIN (a GL_INVALID_VALUE for the levels);
 * the next float up clamps to INT_MAX (libFuzzer under UBSan found the
 * conversion of 2^31 in fixgl). */
static void texparameterf_int_edges(fc_h *h)
{
    static const float vals[] = {
        2147483648.0f, 4294967296.0f, 2147483520.0f, -2147483648.0f,
        -2147483904.0f, 1e30f, -1e30f, 1000.5f, -0.5f,
    };
    static const GLenum pnames[] = { GL_TEXTURE_MAX_LEVEL, GL_TEXTURE_BASE_LEVEL };
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    for (int p = 0; p < 2; p++)
        for (int i = 0; i < (int)(sizeof vals / sizeof vals[0]); i++) {
            glTexParameteri(GL_TEXTURE_2D, pnames[p], p == 0 ? 1000 : 0);
            glTexParameterf(GL_TEXTURE_2D, pnames[p], vals[i]);
            fc_error(h, "glTexParameterf");
            GLint v = -7;
            glGetTexParameteriv(GL_TEXTURE_2D, pnames[p], &v);
            fc_value(h, "level", v);
        }
    glDeleteTextures(1, &tex);
}

/* glPrioritizeTextures while compiling, between glBegin and glEnd: the
 * compiler's begin/end check comes before n is looked at, so a negative n
 * there is GL_INVALID_OPERATION (compiled, and raised at once under
 * GL_COMPILE_AND_EXECUTE), a valid call too; outside glBegin/glEnd a
 * negative n is GL_INVALID_VALUE (fixgl raised GL_INVALID_VALUE inside and
 * compiled nothing; fuzzer seed 338 of the seed-7 campaign; probe
 * p_prioritize_inside). */
static void prioritize_inside_compile(fc_h *h)
{
    static const GLuint names[2] = { 1, 2 };
    static const GLclampf prio[2] = { 0.5f, 0.25f };
    GLuint tex[2];
    GLfloat p = -1.0f;
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glBindTexture(GL_TEXTURE_2D, 0);
    glNewList(1, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_TRIANGLE_FAN);
    glPrioritizeTextures(-1, names, prio);
    glEnd();
    fc_error(h, "n = -1 inside glBegin, compile and execute");
    glBegin(GL_POINTS);
    glPrioritizeTextures(2, names, prio);
    glEnd();
    fc_error(h, "n = 2 inside glBegin, compile and execute");
    glPrioritizeTextures(-1, names, prio);
    fc_error(h, "n = -1 outside glBegin, compile and execute");
    glEndList();
    fc_error(h, "list 1 ended");
    glCallList(1);
    fc_error(h, "list 1 called");
    glNewList(2, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glPrioritizeTextures(-1, names, prio);
    glColor3f(1, 1, 1);
    glVertex2f(2, 2);
    glVertex2f(30, 6);
    glVertex2f(14, 30);
    glEnd();
    glEndList();
    fc_error(h, "list 2 compiled");
    glCallList(2);
    fc_error(h, "list 2 called");
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
    fc_value(h, "priority of texture 2 * 4", (long long)(p * 4.0f));
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteLists(1, 2);
    glDeleteTextures(2, tex);
    fc_capture(h);
}

/* glDrawElements from a bound element buffer without a data store (bound
 * but never given data, or glBufferData of size 0) draws nothing: no
 * feedback, no selection hit (st_draw.c prepare_indexed_draw; rendering it
 * crashes the oracle, so only feedback and selection).  fixgl read every
 * index as 0 and fed back the first vertex's degenerate triangles (fuzzer
 * seed 440 of the seed-7 campaign: glRenderMode returned 494 against 342;
 * probe p_element_buffer_no_store). */
static void element_buffer_no_store(fc_h *h)
{
    static const GLfloat v[4][4] = { { 1.13666f, -0.265503f, -1.24915f, 1.72406f },
                                     { 0.5f, -0.5f, 0, 1 }, { 0.5f, 0.5f, 0, 1 },
                                     { -0.5f, 0.5f, 0, 1 } };
    static GLfloat fb[512];
    static GLuint sb[64];
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    fcu_clear(0, 0, 0, 0, 1);
    glVertexPointer(4, GL_FLOAT, 0, v);
    glEnableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 5);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1)
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, 0, NULL, GL_STATIC_DRAW);
        glFeedbackBuffer(512, GL_4D_COLOR_TEXTURE, fb);
        glRenderMode(GL_FEEDBACK);
        glDrawElements(GL_QUAD_STRIP, 6, GL_UNSIGNED_BYTE, (const GLvoid *)0);
        glDrawElements(GL_QUAD_STRIP, 6, GL_UNSIGNED_BYTE, (const GLvoid *)0x40);
        glDrawElements(GL_POINTS, 2, GL_UNSIGNED_SHORT, (const GLvoid *)0x40);
        fc_value(h, "feedback values", glRenderMode(GL_RENDER));
        glSelectBuffer(64, sb);
        glRenderMode(GL_SELECT);
        glInitNames();
        glPushName(7);
        glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, (const GLvoid *)0x40);
        fc_value(h, "selection hits", glRenderMode(GL_RENDER));
        fc_error(h, "no store");
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glDeleteBuffers(1, (const GLuint[]){ 5 });
    glDrawArrays(GL_TRIANGLES, 1, 3);   /* the witness: rendered, no element buffer */
    fc_error(h, "witness");
    glDisableClientState(GL_VERTEX_ARRAY);
    fc_capture(h);
}

/* The first vertex list a context compiles, cut by glEvalCoord after one
 * vertex of a GL_TRIANGLE_STRIP (the API fuzzer's seeds 279 and 145;
 * probe p_dlist_first_begin; ORACLE-NOTES.md "OSMesa defects kept
 * visible"): vbo_save's copy_vertices leaves the open strip no vertex, so
 * its node has no index, and with no save buffer made yet (current_bo)
 * Mesa reuses the NULL one and sets the node's counts to 0: its replay has
 * no glBegin and the list's glEnd raises GL_INVALID_OPERATION, at the
 * compile-and-execute and at every glCallList.  The same list compiled
 * again (the buffer exists now) raises nothing; a witness triangle. */
static void dlist_first_begin_eval(fc_h *h)
{
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    for (int k = 0; k < 2; k++) {
        glNewList(2 + (GLuint)k, GL_COMPILE_AND_EXECUTE);
        glBegin(GL_TRIANGLE_STRIP);
        glVertex3i(1, 2, 3);
        if (k)
            glEvalPoint1(3);
        else
            glEvalCoord2d(0.5, 0.5);
        glEnd();
        fc_error(h, "the list's glEnd (compile and execute)");
        glEndList();
        fc_error(h, "glEndList");
        glCallList(2 + (GLuint)k);
        fc_error(h, "glCallList");
        glCallList(2 + (GLuint)k);
        fc_error(h, "glCallList again");
    }
    witness_triangle(h);
    glDeleteLists(2, 2);
    fc_capture(h);
}

/* The floating-point state of line setup (ORACLE-NOTES.md
 * "Interpolation", probe p_setup_fpstate_lines): lines of draw's pipeline
 * (a vertex of their vsplit segment needs clipping, line stipple, smooth
 * lines, the edges of unfilled polygons) are set up when llvmpipe flushes
 * draw after draw_vbo restored the application's MXCSR; direct lines
 * under draw_vbo's FTZ|DAZ.  Short lines at clip w 1.5e35 whose colour
 * changes by 0.003 have denormal plane derivatives: kept by setup without
 * FTZ, read as 0 by the shader.  Each kind is drawn with the default MXCSR
 * and with FTZ|DAZ set by the program around the draw; points, whose
 * setup does not depend on it, too. */
static void fpl_vertex(float x, float y, float c)
{
    const float w = 1.5e35f;
    glColor4f(c, c, 1.0f - c, 1.0f);
    glVertex4f((2.0f * x / 64 - 1.0f) * w, (2.0f * y / 64 - 1.0f) * w, 0.0f, w);
}

static void fpl_lines(GLenum mode, int clipped)
{
    glBegin(mode);
    for (int i = 0; i < 6; i++) {
        const float a = i & 1 ? 0.5f : 0.503f, b = i & 1 ? 0.503f : 0.5f;
        fpl_vertex(40 + 3 * i, 10 + 8 * i, a);
        fpl_vertex(42 + 3 * i, 10.5f + 8 * i, b);
    }
    fpl_vertex(8, 60, 0.99f);
    fpl_vertex(12, 20, 1.0f);
    if (clipped) {
        glColor4f(0, 1, 0, 1);
        glVertex4f(-3.0f, -0.9f, 0.0f, 1.0f);
        glVertex4f(-0.8f, -0.9f, 0.0f, 1.0f);
    }
    glEnd();
}

static void fpl_draw(fc_h *h, int kind, unsigned csr)
{
    fcu_clear(0.1f, 0.1f, 0.1f, 1, 1);
    const unsigned saved = _mm_getcsr();
    _mm_setcsr(csr);
    switch (kind) {
    case 0: fpl_lines(GL_LINES, 0); break;   /* direct */
    case 1: fpl_lines(GL_LINES, 1); break;   /* pipeline: clipped */
    case 2: fpl_lines(GL_LINE_STRIP, 1); break;
    case 3:   /* stipple: always the pipeline */
        glEnable(GL_LINE_STIPPLE);
        glLineStipple(1, 0xf0f3);
        fpl_lines(GL_LINES, 0);
        glDisable(GL_LINE_STIPPLE);
        break;
    case 4:   /* aaline: triangles of the pipeline */
        glEnable(GL_LINE_SMOOTH);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        fpl_lines(GL_LINES, 0);
        glDisable(GL_LINE_SMOOTH);
        glDisable(GL_BLEND);
        break;
    case 5:   /* unfilled triangles' edges, then through the polygon
               * stipple's vbuf batch (all flushed at draw_flush; not
               * modelled: a filled face between them, whose vbuf_first_tri
               * flushes the lines before it inside draw_vbo, and the
               * face itself, flushed by the next line) */
    case 6:
        glPolygonMode(GL_FRONT, GL_LINE);
        if (kind == 6) {
            GLubyte pattern[128];
            pattern_bits(pattern, 128);
            glEnable(GL_POLYGON_STIPPLE);
            glPolygonStipple(pattern);
        }
        glBegin(GL_TRIANGLES);
        for (int t = 0; t < 3; t++) {
            const float x = 8 + 18 * t, y = 8 + 16 * t;
            fpl_vertex(x, y, 0.5f);
            fpl_vertex(x + 3, y + 1, 0.503f);
            fpl_vertex(x, y + 6, 0.501f);
        }
        glEnd();
        glPolygonMode(GL_FRONT, GL_FILL);
        glDisable(GL_POLYGON_STIPPLE);
        break;
    default:   /* points, plain and smooth, with a clipped one */
        glPointSize(3);
        glBegin(GL_POINTS);
        for (int i = 0; i < 8; i++)
            fpl_vertex(6 + 7 * i, 10 + 6 * i, 0.3f + 0.05f * i);
        glVertex4f(-3.0f, -0.9f, 0.0f, 1.0f);
        glEnd();
        glEnable(GL_POINT_SMOOTH);
        glBegin(GL_POINTS);
        for (int i = 0; i < 8; i++)
            fpl_vertex(13 + 7 * i, 4 + 6 * i, 0.3f + 0.05f * i);
        glEnd();
        glDisable(GL_POINT_SMOOTH);
        glPointSize(1);
        break;
    }
    glFinish();
    _mm_setcsr(saved);
    fc_capture(h);
}

static void setup_caller_fpstate_lines(fc_h *h)
{
    const unsigned def = _mm_getcsr() & ~0x8040u, ftz = def | 0x8040u;   /* FTZ | DAZ */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    for (int kind = 0; kind < 8; kind++) {
        fpl_draw(h, kind, def);
        fpl_draw(h, kind, ftz);
    }
}

/* A stippled line longer than 2^31 pixels (ORACLE-NOTES.md "A stippled
 * line's length in pixels"; the long libFuzzer campaign's chunk 8): the
 * clipper's t = dp0 / (dp0 - dp1) overflows to 0 for a vertex at clip x
 * -2.98e38, which stays where it is, 1.66e38 pixels left of the window;
 * the stipple stage's length converts to INT32_MIN: no dash, the counter
 * moves by 2^31, which the next line of the strip shows. */
static void stipple_huge_length(fc_h *h)
{
    static const GLushort patterns[2] = { 3, 0x0f3f };
    static const GLint factors[2] = { 13, 3 };
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_LINE_STIPPLE);
    for (int k = 0; k < 2; k++) {
        fcu_clear(0, 0, 0, 1, 1);
        glLineStipple(factors[k], patterns[k]);
        for (int m = 0; m < 3; m++) {
            const float y = -0.8f + 0.55f * (float)m;
            glBegin(m == 2 ? GL_LINE_LOOP : GL_LINE_STRIP);
            glColor3f(1, 0, 0);
            if (m == 1)   /* a visible line first */
                glVertex2f(-0.9f, y + 0.3f);
            glVertex4f(-2.98028591e+38f, y * 57.5029831f, 0.0f, 57.5029831f);
            glColor3f(0, 1, 0);
            glVertex4f(-4.0100436e-12f, y * 2.4798858e+38f, 0.0f, 2.4798858e+38f);
            glColor3f(1, 1, 0);
            glVertex2f(0.9f, y + 0.2f);
            glVertex2f(0.2f, y + 0.45f);
            glEnd();
        }
        fc_error(h, "stippled strips through a line 1.66e38 pixels long");
        fc_capture(h);
    }
    glDisable(GL_LINE_STIPPLE);
}

#define ROBUST(name, w, h, frames, fn) \
    FC_CASE("robust/" name, w, h, OSMESA_RGBA, 24, 8, frames, "robust", fn)

const fc_case fc_cases_robust[] = {
    ROBUST("dlist_material_after_fallback", 64, 64, 1, dlist_material_after_fallback),
    ROBUST("copypixels_huge", 64, 64, 14, copypixels_huge),
    ROBUST("bitmap_huge", 64, 64, 1, bitmap_huge),
    ROBUST("drawarrays_negative_first", 64, 64, 4, drawarrays_negative_first),
    ROBUST("drawarrays_negative_first_before_pointer", 64, 64, 2,
           drawarrays_negative_first_before_pointer),
    ROBUST("drawarrays_partial_primitive", 64, 64, 1, drawarrays_partial_primitive),
    ROBUST("teximage_error_keeps_vertex_format", 8, 8, 0, teximage_error_keeps_vertex_format),
    ROBUST("arrayelement_wrapping_index", 64, 64, 1, arrayelement_wrapping_index),
    ROBUST("depthmask_byte", 8, 8, 0, depthmask_byte),
    ROBUST("drawarrays_no_position_array", 32, 32, 1, drawarrays_no_position_array),
    ROBUST("drawarrays_no_position_faces", 32, 32, 2, drawarrays_no_position_faces),
    ROBUST("deletelists_before_any", 8, 8, 0, deletelists_before_any),
    ROBUST("map2_huge_order_compiled", 8, 8, 0, map2_huge_order_compiled),
    ROBUST("calllists_float_names", 64, 64, 1, calllists_float_names),
    ROBUST("float_enum_params", 64, 64, 1, float_enum_params),
    ROBUST("clear_in_select_feedback", 64, 64, 2, clear_in_select_feedback),
    ROBUST("drawpixels_float_indices", 64, 64, 1, drawpixels_float_indices),
    ROBUST("dlist_loop_without_vertices", 64, 64, 1, dlist_loop_without_vertices),
    ROBUST("readpixels_int_min", 8, 8, 0, readpixels_int_min),
    ROBUST("dlist_polygon_stipple", 64, 64, 1, dlist_polygon_stipple),
    ROBUST("dlist_map_bad_stride", 64, 64, 1, dlist_map_bad_stride),
    ROBUST("genlists_delete_many", 8, 8, 0, genlists_delete_many),
    ROBUST("gentextures_after_max_name", 8, 8, 0, gentextures_after_max_name),
    ROBUST("gentextures_inside_begin_end", 32, 32, 1, gentextures_inside_begin_end),
    ROBUST("gentextures_compiling_begin_end", 64, 64, 1, gentextures_compiling_begin_end),
    ROBUST("bitmap_negative_compile", 64, 64, 1, bitmap_negative_compile),
    ROBUST("texparam_border_color", 8, 8, 0, texparam_border_color),
    ROBUST("texgen_query_beyond_units", 8, 8, 0, texgen_query_beyond_units),
    ROBUST("matrixmode_texture_unit", 8, 8, 0, matrixmode_texture_unit),
    ROBUST("calllist_inside_begin_end", 64, 64, 1, calllist_inside_begin_end),
    ROBUST("texparam_levels_and_push_limit", 8, 8, 0, texparam_levels_and_push_limit),
    ROBUST("dlist_teximage_color_index", 64, 64, 1, dlist_teximage_color_index),
    ROBUST("huge_texture", 64, 64, 1, huge_texture),
    ROBUST("huge_viewport", 64, 64, 1, huge_viewport),
    ROBUST("calllists_million", 64, 64, 1, calllists_million),
    ROBUST("draw_keeps_vertex_format", 32, 32, 1, draw_keeps_vertex_format),
    ROBUST("compile_execute_inside_begin", 64, 64, 1, compile_execute_inside_begin),
    ROBUST("long_array_draws", 64, 64, 16, long_array_draws),
    ROBUST("texparameterf_int_edges", 8, 8, 0, texparameterf_int_edges),
    ROBUST("teximage3d_compile_depth", 8, 8, 0, teximage3d_compile_depth),
    ROBUST("bitmap_negative_compile_sizes", 64, 64, 1, bitmap_negative_compile_sizes),
    ROBUST("transpose_texture_matrix_unit", 8, 8, 0, transpose_texture_matrix_unit),
    ROBUST("end_after_list_mid_primitive", 32, 32, 1, end_after_list_mid_primitive),
    ROBUST("prioritize_inside_compile", 32, 32, 1, prioritize_inside_compile),
    ROBUST("element_buffer_no_store", 32, 32, 1, element_buffer_no_store),
    ROBUST("point_huge_viewport_y", 32, 32, 1, point_huge_viewport_y),
    ROBUST("stuck_list_entry_points", 32, 32, 1, stuck_list_entry_points),
    ROBUST("index_shift_huge", 32, 16, 1, index_shift_huge),
    ROBUST("setup_caller_fpstate_lines", 64, 64, 16, setup_caller_fpstate_lines),
    ROBUST("stipple_huge_length", 64, 64, 2, stipple_huge_length),
    ROBUST("dlist_first_begin_eval", 32, 32, 1, dlist_first_begin_eval),
    { 0 }
};
