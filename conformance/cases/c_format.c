/* c_format.c - every OSMesa colour format, OSMESA_Y_UP false,
 * OSMESA_ROW_LENGTH, the OSMesa query API, a second context, the legacy
 * OSMesaCreateContext and re-binding a context with another size. */
#include "cases.h"

#include <stdlib.h>
#include <string.h>

/* An asymmetric scene: which corner is which is visible in every format. */
static void format_scene(int w, int h)
{
    glViewport(0, 0, w, h);
    fcu_ortho(0, w, 0, h, -1, 1);
    glEnable(GL_DEPTH_TEST);
    fcu_clear(0.1f, 0.3f, 0.6f, 0.8f, 1);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 1); glVertex3f(1, 1, 0.5f);
    glColor4f(0, 1, 0, 0.5f); glVertex3f((float)w - 2, 3, 0);
    glColor4f(0, 0, 1, 0.25f); glVertex3f(3, (float)h - 1, -0.5f);
    glEnd();
    glShadeModel(GL_FLAT);
    fcu_color(3);
    fcu_rect((float)w - 6, (float)h - 5, (float)w - 1, (float)h - 1, 0);
}

static void format_basic(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    format_scene(c->width, c->height);
    fc_capture(h);
}

static void format_y_down(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    fc_pixel_store(h, OSMESA_Y_UP, 0);
    format_scene(c->width, c->height);
    fc_capture(h);
    fc_pixel_store(h, OSMESA_Y_UP, 1);       /* back to bottom-up for the next frame */
    glColor3f(1, 1, 1);
    fcu_rect(2, 2, 5, 5, -0.9f);
    fc_capture(h);
}

/* The buffer is allocated with 40-pixel rows; the image is 24 wide. */
static void format_row_length(fc_h *h)
{
    GLint v = -1;
    fc_pixel_store(h, OSMESA_ROW_LENGTH, 40);
    OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &v);
    fc_value(h, "OSMESA_ROW_LENGTH", v);
    format_scene(24, 20);
    fc_capture(h);
    fc_pixel_store(h, OSMESA_Y_UP, 0);
    glColor3f(1, 1, 1);
    fcu_rect(2, 2, 5, 5, -0.9f);
    fc_capture(h);
}

static void osmesa_queries(fc_h *h)
{
    static const GLint pnames[] = {
        OSMESA_WIDTH, OSMESA_HEIGHT, OSMESA_FORMAT, OSMESA_TYPE,
        OSMESA_ROW_LENGTH, OSMESA_Y_UP, OSMESA_MAX_WIDTH, OSMESA_MAX_HEIGHT,
    };
    GLint w = 0, ht = 0, fmt = 0;
    void *buf = NULL;
    OSMesaContext cur = OSMesaGetCurrentContext();

    for (size_t i = 0; i < sizeof pnames / sizeof pnames[0]; i++) {
        GLint v = -12345;
        OSMesaGetIntegerv(pnames[i], &v);
        fc_value(h, "OSMesaGetIntegerv", v);
    }
    fc_value(h, "OSMesaGetCurrentContext == ctx", cur == fc_context(h));
    fc_value(h, "OSMesaGetColorBuffer", OSMesaGetColorBuffer(fc_context(h), &w, &ht, &fmt, &buf));
    fc_value(h, "color buffer width", w);
    fc_value(h, "color buffer height", ht);
    fc_value(h, "color buffer format", fmt);
    fc_value(h, "color buffer == harness buffer", buf == fc_buffer(h));
    fc_value(h, "OSMesaGetProcAddress(glClear) != NULL", OSMesaGetProcAddress("glClear") != NULL);
    fc_value(h, "OSMesaGetProcAddress(glDepthFunc) != NULL", OSMesaGetProcAddress("glDepthFunc") != NULL);
    fc_documented_difference(h, "OSMesaGetProcAddress(bogus) != NULL",
                             "Mesa's glapi hands out a no-op stub for an unknown gl* name, "
                             "fixgl NULL (no silent no-op)");
    fc_value(h, "OSMesaGetProcAddress(bogus) != NULL", OSMesaGetProcAddress("glNoSuchFunctionAtAll") != NULL);
    fc_value(h, "OSMesaGetProcAddress(OSMesaGetDepthBuffer) != NULL",
             OSMesaGetProcAddress("OSMesaGetDepthBuffer") != NULL);
    /* Draw through the pointer returned for glClear. */
    {
        void (*clear)(GLbitfield) = (void (*)(GLbitfield))OSMesaGetProcAddress("glClear");
        glClearColor(0.25f, 0.5f, 0.75f, 1);
        if (clear)
            clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    fc_capture(h);
}

/* A second context with its own buffer and format, then back. */
static void second_context(fc_h *h)
{
    OSMesaContext ctx2 = OSMesaCreateContextExt(OSMESA_BGRA, 16, 0, 0, NULL);
    unsigned char *buf2 = malloc(20 * 12 * 4);
    GLint vp[4] = { -1, -1, -1, -1 };

    memset(buf2, 0x33, 20 * 12 * 4);
    format_scene(32, 32);                           /* first context */
    fc_value(h, "second OSMesaCreateContextExt != NULL", ctx2 != NULL);
    if (ctx2) {
        fc_value(h, "second OSMesaMakeCurrent", OSMesaMakeCurrent(ctx2, buf2, GL_UNSIGNED_BYTE, 20, 12));
        fc_value(h, "current == ctx2", OSMesaGetCurrentContext() == ctx2);
        glGetIntegerv(GL_VIEWPORT, vp);
        fc_blob(h, "second context initial viewport", vp, sizeof vp);
        format_scene(20, 12);
        fc_capture_buffer(h, buf2, 20, 12, 20, OSMESA_BGRA, 1);
        fc_value(h, "back to first", OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 32, 32));
        OSMesaDestroyContext(ctx2);
    }
    fc_get_integer(h, "first context viewport", GL_VIEWPORT, 4);
    glColor3f(1, 1, 1);
    fcu_rect(10, 10, 20, 20, -0.9f);
    fc_capture(h);
    free(buf2);
}

/* OSMesaCreateContext (legacy entry point) sharing nothing. */
static void legacy_create(fc_h *h)
{
    OSMesaContext ctx2 = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf2 = calloc(16 * 16, 4);
    GLint bits = -1;

    fc_value(h, "OSMesaCreateContext != NULL", ctx2 != NULL);
    if (ctx2) {
        fc_value(h, "OSMesaMakeCurrent", OSMesaMakeCurrent(ctx2, buf2, GL_UNSIGNED_BYTE, 16, 16));
        glGetIntegerv(GL_DEPTH_BITS, &bits);
        fc_value(h, "legacy context GL_DEPTH_BITS", bits);
        format_scene(16, 16);
        fc_capture_buffer(h, buf2, 16, 16, 16, OSMESA_RGBA, 1);
        OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 16, 16);
        OSMesaDestroyContext(ctx2);
    }
    free(buf2);
}

/* Re-binding the current context to a smaller size: viewport and drawing. */
/* Re-binding the context to a smaller size: what the program sees through
 * the colour buffer, glReadPixels of colour and depth, and the viewport. */
static void rebind_draw(fc_h *h)
{
    format_scene(32, 32);
    fc_capture(h);
    fc_value(h, "rebind 16x8", OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, 16, 8));
    fc_get_integer(h, "GL_VIEWPORT after rebind", GL_VIEWPORT, 4);
    glColor3f(1, 1, 1);
    fcu_rect(-5, -5, 40, 4, -0.9f);
}

static void rebind_size(fc_h *h)
{
    GLuint depth[16 * 8];
    GLubyte color[16 * 8 * 4];
    rebind_draw(h);
    fc_blob(h, "colour buffer 16x8", fc_buffer(h), sizeof color);
    glReadPixels(0, 0, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, color);
    fc_blob(h, "glReadPixels colour", color, sizeof color);
    glReadPixels(0, 0, 16, 8, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    fc_blob(h, "glReadPixels depth", depth, sizeof depth);
    fc_error(h, "after reads");
}

/* The same through OSMesaGetDepthBuffer: the oracle keeps the row stride of
 * the size its depth snapshot was first made for (32 values), so the
 * 16x8 image it returns interleaves real rows with stale ones; fixgl
 * returns the current 16x8 buffer.  A known difference. */
static void rebind_size_snapshot(fc_h *h)
{
    rebind_draw(h);
    fc_capture_buffer(h, fc_buffer(h), 16, 8, 16, OSMESA_RGBA, 1);
}

const fc_case fc_cases_format[] = {
    FC_CASE("core/format_rgba", 24, 20, OSMESA_RGBA, 24, 0, 1, "core format", format_basic),
    FC_CASE("core/format_bgra", 24, 20, OSMESA_BGRA, 24, 0, 1, "core format", format_basic),
    FC_CASE("core/format_argb", 24, 20, OSMESA_ARGB, 24, 0, 1, "core format", format_basic),
    FC_CASE("core/format_rgb", 24, 20, OSMESA_RGB, 24, 0, 1, "core format", format_basic),
    FC_CASE("core/format_bgr", 24, 20, OSMESA_BGR, 24, 0, 1, "core format", format_basic),
    FC_CASE("core/format_bgra_no_depth", 24, 20, OSMESA_BGRA, 0, 0, 1, "core format", format_basic),
    FC_CASE("core/format_rgb_odd_width", 13, 7, OSMESA_RGB, 16, 0, 1, "core format", format_basic),
    /* The oracle's own OSMESA_RGB buffer, not the RGBA substitute (fc_case.h):
     * kept to show the oracle defect; a known difference. */
    { "core/format_rgb_raw_oracle", 24, 20, OSMESA_RGB, 24, 0, 1, "core format", format_basic, 0, 1, 0, 0 },
    FC_CASE("core/format_y_up_false", 24, 20, OSMESA_RGBA, 24, 0, 2, "core format", format_y_down),
    { "core/format_row_length", 24, 20, OSMESA_RGBA, 24, 0, 2, "core format", format_row_length, 40, 0, 0, 0 },
    /* queries, then a clear through OSMesaGetProcAddress (draws_nothing) */
    FC_CASE_NODRAW("core/osmesa_queries", 16, 16, OSMESA_RGBA, 24, 0, 1, "core format query", osmesa_queries),
    FC_CASE_RGBA("core/osmesa_second_context", 32, 32, 2, "core format", second_context),
    FC_CASE_RGBA("core/osmesa_create_context_legacy", 16, 16, 1, "core format", legacy_create),
    FC_CASE_RGBA("core/osmesa_rebind_smaller", 32, 32, 1, "core format viewport", rebind_size),
    FC_CASE_RGBA("core/osmesa_rebind_smaller_depth_snapshot", 32, 32, 2, "core format viewport",
                 rebind_size_snapshot),
    { 0 }
};
