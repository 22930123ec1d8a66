/* c_readpix.c - glReadPixels of colour (GL_RGBA/GL_RGB, GL_UNSIGNED_BYTE and
 * GL_FLOAT) and depth (GL_DEPTH_COMPONENT), with GL_PACK_ALIGNMENT 4 row
 * padding, regions partly outside the framebuffer and invalid arguments.
 * Destination buffers are pre-filled so untouched bytes compare too. */
#include "cases.h"

#include <stdlib.h>
#include <string.h>

#define FILL 0xA7

static void scene(fc_h *h)
{
    fc_pixel_ortho(h);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    fcu_clear(0.25f, 0.5f, 0.75f, 0.1f, 0.4);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 0.2f); glVertex3f(0, 0, -0.9f);
    glColor4f(0, 1, 0, 0.6f); glVertex3f(13, 2, 0.5f);
    glColor4f(0, 0, 1, 1.0f); glVertex3f(3, 11, 0.1f);
    glEnd();
}

/* Reads a w x h region at (x, y) into a padded, pre-filled buffer and
 * records it with the glGetError after the call. */
static void read_region(fc_h *h, const char *label, int x, int y, int w, int ht,
                        GLenum format, GLenum type)
{
    size_t comps = format == GL_RGBA ? 4 : format == GL_RGB ? 3 : 1;
    size_t elem = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4;
    size_t row = (comps * elem * (size_t)(w > 0 ? w : 0) + 3) & ~(size_t)3;
    size_t size = row * (size_t)(ht > 0 ? ht : 0) + 64;
    unsigned char *buf = malloc(size);
    memset(buf, FILL, size);
    glReadPixels(x, y, w, ht, format, type, buf);
    fc_error(h, label);
    fc_blob(h, label, buf, size);
    free(buf);
}

static void read_colour(fc_h *h)
{
    scene(h);
    read_region(h, "RGBA ubyte", 0, 0, 13, 11, GL_RGBA, GL_UNSIGNED_BYTE);
    read_region(h, "RGB ubyte odd width", 1, 2, 11, 7, GL_RGB, GL_UNSIGNED_BYTE);
    read_region(h, "RGB ubyte 1 wide", 5, 0, 1, 11, GL_RGB, GL_UNSIGNED_BYTE);
    read_region(h, "RGBA float", 0, 0, 13, 11, GL_RGBA, GL_FLOAT);
    read_region(h, "RGB float", 2, 3, 9, 5, GL_RGB, GL_FLOAT);
    fc_capture(h);
}

static void read_depth(fc_h *h)
{
    scene(h);
    read_region(h, "DEPTH float", 0, 0, 13, 11, GL_DEPTH_COMPONENT, GL_FLOAT);
    read_region(h, "DEPTH float sub", 3, 4, 5, 6, GL_DEPTH_COMPONENT, GL_FLOAT);
    fc_capture(h);
}

static void read_depth_int(fc_h *h)
{
    scene(h);
    read_region(h, "DEPTH uint", 0, 0, 13, 11, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT);
    read_region(h, "DEPTH ushort", 0, 0, 13, 11, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT);
}

/* Regions partly or wholly outside the framebuffer, and empty ones. */
static void read_clipped(fc_h *h)
{
    scene(h);
    read_region(h, "RGBA left-bottom outside", -3, -2, 8, 6, GL_RGBA, GL_UNSIGNED_BYTE);
    read_region(h, "RGB right-top outside", 9, 8, 10, 9, GL_RGB, GL_UNSIGNED_BYTE);
    read_region(h, "RGBA float all outside", 20, 20, 4, 4, GL_RGBA, GL_FLOAT);
    read_region(h, "DEPTH outside", -5, 5, 30, 3, GL_DEPTH_COMPONENT, GL_FLOAT);
    read_region(h, "zero size", 2, 2, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE);
}

static void read_errors(fc_h *h)
{
    scene(h);
    read_region(h, "negative width", 0, 0, -1, 2, GL_RGBA, GL_UNSIGNED_BYTE);
    read_region(h, "negative height", 0, 0, 2, -3, GL_RGBA, GL_UNSIGNED_BYTE);
    read_region(h, "bad format", 0, 0, 2, 2, 0x1234, GL_UNSIGNED_BYTE);
    read_region(h, "bad type", 0, 0, 2, 2, GL_RGBA, 0x1234);
    read_region(h, "depth format with RGBA-only type", 0, 0, 2, 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8);
}

static void read_no_depth(fc_h *h)
{
    scene(h);
    read_region(h, "DEPTH without depth buffer", 0, 0, 4, 4, GL_DEPTH_COMPONENT, GL_FLOAT);
    read_region(h, "RGB ubyte", 0, 0, 13, 11, GL_RGB, GL_UNSIGNED_BYTE);
}

const fc_case fc_cases_readpix[] = {
    FC_CASE_RGBA("core/readpixels_colour", 13, 11, 1, "core readpixels", read_colour),
    FC_CASE_RGBA("core/readpixels_depth_float", 13, 11, 1, "core readpixels depth", read_depth),
    FC_CASE_RGBA("core/readpixels_depth_integer", 13, 11, 0, "core readpixels depth", read_depth_int),
    FC_CASE_RGBA("core/readpixels_clipped_region", 13, 11, 0, "core readpixels", read_clipped),
    FC_CASE_RGBA("core/readpixels_errors", 13, 11, 0, "core readpixels error", read_errors),
    FC_CASE("core/readpixels_no_depth_buffer", 13, 11, OSMESA_RGB, 0, 0, 0, "core readpixels error",
            read_no_depth),
    { 0 }
};
