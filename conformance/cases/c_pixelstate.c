/* c_pixelstate.c - the pixel transfer state entry points (no drawing:
 * c_pix_draw.c and c_readpix.c draw and read with it): glPixelTransfer{f,i}
 * through every glGet type, glPixelZoom, the ten pixel maps set with
 * glPixelMap{fv,uiv,usv} and read back with each glGetPixelMap type
 * (sizes 1, 2, 256 and the invalid ones, the oracle's conversions), the
 * errors, glPushAttrib(GL_PIXEL_MODE_BIT) (the maps are not part of it)
 * and display lists (compiled; glGetPixelMap executes at once). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cases.h"

#define NMAPS 10
static const GLenum maps[NMAPS] = {
    GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_G,
    GL_PIXEL_MAP_I_TO_B, GL_PIXEL_MAP_I_TO_A, GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G,
    GL_PIXEL_MAP_B_TO_B, GL_PIXEL_MAP_A_TO_A,
};
static const GLenum map_sizes[NMAPS] = {
    GL_PIXEL_MAP_I_TO_I_SIZE, GL_PIXEL_MAP_S_TO_S_SIZE, GL_PIXEL_MAP_I_TO_R_SIZE,
    GL_PIXEL_MAP_I_TO_G_SIZE, GL_PIXEL_MAP_I_TO_B_SIZE, GL_PIXEL_MAP_I_TO_A_SIZE,
    GL_PIXEL_MAP_R_TO_R_SIZE, GL_PIXEL_MAP_G_TO_G_SIZE, GL_PIXEL_MAP_B_TO_B_SIZE,
    GL_PIXEL_MAP_A_TO_A_SIZE,
};
static const char *const map_names[NMAPS] = {
    "I_TO_I", "S_TO_S", "I_TO_R", "I_TO_G", "I_TO_B", "I_TO_A",
    "R_TO_R", "G_TO_G", "B_TO_B", "A_TO_A",
};

#define NTRANSFER 14
static const GLenum transfer_pnames[NTRANSFER] = {
    GL_MAP_COLOR, GL_MAP_STENCIL, GL_INDEX_SHIFT, GL_INDEX_OFFSET,
    GL_RED_SCALE, GL_RED_BIAS, GL_GREEN_SCALE, GL_GREEN_BIAS,
    GL_BLUE_SCALE, GL_BLUE_BIAS, GL_ALPHA_SCALE, GL_ALPHA_BIAS,
    GL_DEPTH_SCALE, GL_DEPTH_BIAS,
};

/* Every glGet type of one state value */
static void get_all(fc_h *h, const char *label, GLenum pname)
{
    char l[96];
    snprintf(l, sizeof l, "%s i", label);
    fc_get_integer(h, l, pname, 1);
    snprintf(l, sizeof l, "%s f", label);
    fc_get_float(h, l, pname, 1);
    snprintf(l, sizeof l, "%s d", label);
    fc_get_double(h, l, pname, 1);
    snprintf(l, sizeof l, "%s b", label);
    fc_get_boolean(h, l, pname, 1);
}

static void transfer_state(fc_h *h, const char *label)
{
    char l[96];
    for (int i = 0; i < NTRANSFER; i++) {
        snprintf(l, sizeof l, "%s %d", label, i);
        get_all(h, l, transfer_pnames[i]);
    }
    snprintf(l, sizeof l, "%s zoomx", label);
    get_all(h, l, GL_ZOOM_X);
    snprintf(l, sizeof l, "%s zoomy", label);
    get_all(h, l, GL_ZOOM_Y);
}

/* One map read back with each glGetPixelMap type: its size, then the
 * buffers (pre-filled, a few entries past the size included). */
static void read_map(fc_h *h, const char *label, int m)
{
    char l[96];
    static GLfloat fv[260];
    static GLuint uiv[260];
    static GLushort usv[260];
    GLint size = 0;
    glGetIntegerv(map_sizes[m], &size);
    snprintf(l, sizeof l, "%s %s size", label, map_names[m]);
    fc_value(h, l, size);
    if (size < 0 || size > 256)
        size = 256;
    for (int i = 0; i < 260; i++) {
        fv[i] = -777.0f;
        uiv[i] = 0xdeadbeefu;
        usv[i] = 0xbeef;
    }
    glGetPixelMapfv(maps[m], fv);
    snprintf(l, sizeof l, "%s %s fv", label, map_names[m]);
    fc_blob(h, l, fv, (size_t)(size + 4) * sizeof fv[0]);
    glGetPixelMapuiv(maps[m], uiv);
    snprintf(l, sizeof l, "%s %s uiv", label, map_names[m]);
    fc_blob(h, l, uiv, (size_t)(size + 4) * sizeof uiv[0]);
    glGetPixelMapusv(maps[m], usv);
    snprintf(l, sizeof l, "%s %s usv", label, map_names[m]);
    fc_blob(h, l, usv, (size_t)(size + 4) * sizeof usv[0]);
    snprintf(l, sizeof l, "%s %s err", label, map_names[m]);
    fc_error(h, l);
}

static void read_maps(fc_h *h, const char *label)
{
    for (int m = 0; m < NMAPS; m++)
        read_map(h, label, m);
}

/* Values exercising the conversions: out of [0, 1], fractions near the
 * rounding points, negatives, large numbers. */
static GLfloat ftab[256];
static GLuint utab[256];
static GLushort stab[256];

static void fill_tables(void)
{
    static const GLfloat fspecial[16] = {
        -0.5f, 1.5f, 0.5f, 2.5f, -2.5f, 0.49999997f, 1.0f / 3.0f, 7.0f / 65535.0f,
        0.5f / 65535.0f, 1.5f / 65535.0f, 65535.5f, 70000.0f, 1e10f, -1e10f, 0.0f, 1.0f,
    };
    static const GLuint uspecial[8] = {
        0, 1, 2147483647u, 2147483648u, 4294967295u, 16777217u, 65535u, 123456789u,
    };
    static const GLushort sspecial[6] = { 0, 1, 32767, 32768, 65534, 65535 };
    for (int i = 0; i < 256; i++) {
        ftab[i] = i < 16 ? fspecial[i] : (GLfloat)(i * 37 % 251) / 173.0f - 0.2f;
        utab[i] = i < 8 ? uspecial[i] : (GLuint)i * 16843009u + 12345u * (GLuint)i;
        stab[i] = i < 6 ? sspecial[i] : (GLushort)(i * 257 + i * 3);
    }
}

/* ------------------------------------------------------------------ */

/* Every glPixelTransfer pname, set with f and i, through every glGet type */
static void transfer(fc_h *h)
{
    transfer_state(h, "initial");
    for (int i = 0; i < NTRANSFER; i++)
        glPixelTransferf(transfer_pnames[i], 0.75f + (float)i);
    fc_error(h, "set f");
    transfer_state(h, "after f");
    for (int i = 0; i < NTRANSFER; i++)
        glPixelTransferi(transfer_pnames[i], -3 - i);
    fc_error(h, "set i");
    transfer_state(h, "after i");
    /* the index shift and offset: casts of the float; Transferi through
     * a float (16777217 becomes 16777216) */
    glPixelTransferi(GL_INDEX_SHIFT, 16777217);
    glPixelTransferf(GL_INDEX_OFFSET, -2.7f);
    get_all(h, "shift 16777217", GL_INDEX_SHIFT);
    get_all(h, "offset -2.7", GL_INDEX_OFFSET);
    glPixelTransferf(GL_INDEX_OFFSET, 3e9f);
    get_all(h, "offset 3e9", GL_INDEX_OFFSET);
    glPixelTransferf(GL_INDEX_SHIFT, 2.9f);
    get_all(h, "shift 2.9", GL_INDEX_SHIFT);
    /* the flags: any non-zero, NaN included */
    glPixelTransferf(GL_MAP_COLOR, 0.0f);
    glPixelTransferf(GL_MAP_STENCIL, -0.0f);
    get_all(h, "flags 0", GL_MAP_COLOR);
    get_all(h, "flags -0", GL_MAP_STENCIL);
    glPixelTransferf(GL_MAP_COLOR, NAN);
    glPixelTransferf(GL_MAP_STENCIL, 1e-30f);
    get_all(h, "flags nan", GL_MAP_COLOR);
    get_all(h, "flags tiny", GL_MAP_STENCIL);
    /* large and odd floats through the integer and boolean queries */
    glPixelTransferf(GL_RED_SCALE, 1e30f);
    glPixelTransferf(GL_GREEN_BIAS, -1e30f);
    glPixelTransferf(GL_BLUE_SCALE, 0.5f);
    glPixelTransferf(GL_ALPHA_BIAS, -0.49f);
    glPixelTransferf(GL_DEPTH_SCALE, 2147483520.0f);
    glPixelTransferf(GL_DEPTH_BIAS, -0.0f);
    transfer_state(h, "odd");
    /* bad pnames: INVALID_ENUM, nothing changes */
    glPixelTransferf(GL_ZOOM_X, 2.0f);
    fc_error(h, "zoom_x pname");
    glPixelTransferi(GL_INDEX_BITS, 1);
    fc_error(h, "index_bits pname");
    glPixelTransferf(GL_MAP1_COLOR_4, 1.0f);
    fc_error(h, "map1 pname");
    glPixelTransferi(0, 0);
    fc_error(h, "zero pname");
    transfer_state(h, "after bad");
}

static void zoom(fc_h *h)
{
    get_all(h, "initial x", GL_ZOOM_X);
    get_all(h, "initial y", GL_ZOOM_Y);
    static const GLfloat z[][2] = {
        { 2.0f, -1.5f }, { 0.0f, -0.0f }, { 1e30f, -1e30f }, { 0.4999f, 2.5f },
        { -3.5f, 1.0f / 3.0f }, { 1.0f, 1.0f },
    };
    char l[64];
    for (size_t i = 0; i < sizeof z / sizeof z[0]; i++) {
        glPixelZoom(z[i][0], z[i][1]);
        snprintf(l, sizeof l, "zoom %zu x", i);
        get_all(h, l, GL_ZOOM_X);
        snprintf(l, sizeof l, "zoom %zu y", i);
        get_all(h, l, GL_ZOOM_Y);
        snprintf(l, sizeof l, "zoom %zu err", i);
        fc_error(h, l);
    }
}

/* Every map set with glPixelMapfv, read back with each type */
static void maps_fv(fc_h *h)
{
    fill_tables();
    read_maps(h, "initial");
    fc_get_integer(h, "max table", GL_MAX_PIXEL_MAP_TABLE, 1);
    fc_get_float(h, "max table f", GL_MAX_PIXEL_MAP_TABLE, 1);
    for (int m = 0; m < NMAPS; m++)
        glPixelMapfv(maps[m], 16, ftab);
    fc_error(h, "set 16");
    read_maps(h, "16");
    for (int m = 0; m < NMAPS; m++)
        get_all(h, map_names[m], map_sizes[m]);
    for (int m = 0; m < NMAPS; m++)
        glPixelMapfv(maps[m], 256, ftab);
    fc_error(h, "set 256");
    read_maps(h, "256");
    for (int m = 0; m < NMAPS; m++)
        glPixelMapfv(maps[m], 1, &ftab[1]);
    fc_error(h, "set 1");
    read_maps(h, "1");
}

static void maps_uiv(fc_h *h)
{
    fill_tables();
    for (int m = 0; m < NMAPS; m++)
        glPixelMapuiv(maps[m], 8, utab);
    fc_error(h, "set 8");
    read_maps(h, "8");
    for (int m = 0; m < NMAPS; m++)
        glPixelMapuiv(maps[m], 256, utab);
    fc_error(h, "set 256");
    read_maps(h, "256");
    for (int m = 0; m < NMAPS; m++)
        glPixelMapuiv(maps[m], 2, &utab[3]);
    fc_error(h, "set 2");
    read_maps(h, "2");
}

static void maps_usv(fc_h *h)
{
    fill_tables();
    for (int m = 0; m < NMAPS; m++)
        glPixelMapusv(maps[m], 8, stab);
    fc_error(h, "set 8");
    read_maps(h, "8");
    for (int m = 0; m < NMAPS; m++)
        glPixelMapusv(maps[m], 256, stab);
    fc_error(h, "set 256");
    read_maps(h, "256");
    for (int m = 0; m < NMAPS; m++)
        glPixelMapusv(maps[m], 1, &stab[5]);
    fc_error(h, "set 1");
    read_maps(h, "1");
}

/* Sizes: out of [1, 256] always INVALID_VALUE, not a power of two only for
 * the maps from S_TO_S to I_TO_A; a bad map after the size tests; NULL */
static void sizes(fc_h *h)
{
    fill_tables();
    static const GLsizei bad[] = { 0, -1, 257, 3, 255, 100, 6 };
    char l[96];
    for (int m = 0; m < NMAPS; m++) {
        for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
            glPixelMapfv(maps[m], bad[i], ftab);
            snprintf(l, sizeof l, "%s fv %d", map_names[m], (int)bad[i]);
            fc_error(h, l);
            glPixelMapuiv(maps[m], bad[i], utab);
            snprintf(l, sizeof l, "%s uiv %d", map_names[m], (int)bad[i]);
            fc_error(h, l);
            glPixelMapusv(maps[m], bad[i], stab);
            snprintf(l, sizeof l, "%s usv %d", map_names[m], (int)bad[i]);
            fc_error(h, l);
            read_map(h, l, m);
        }
    }
    /* bad maps: INVALID_ENUM with a good size, INVALID_VALUE before */
    static const GLenum badmap[] = { GL_PIXEL_MAP_I_TO_I_SIZE, GL_MAP_COLOR, 0, GL_PIXEL_MAP_A_TO_A + 1 };
    for (size_t i = 0; i < sizeof badmap / sizeof badmap[0]; i++) {
        glPixelMapfv(badmap[i], 4, ftab);
        snprintf(l, sizeof l, "badmap %zu 4", i);
        fc_error(h, l);
        glPixelMapuiv(badmap[i], 3, utab);
        snprintf(l, sizeof l, "badmap %zu 3", i);
        fc_error(h, l);
        glPixelMapusv(badmap[i], 0, stab);
        snprintf(l, sizeof l, "badmap %zu 0", i);
        fc_error(h, l);
        glPixelMapfv(badmap[i], 300, ftab);
        snprintf(l, sizeof l, "badmap %zu 300", i);
        fc_error(h, l);
    }
    /* NULL values: ignored when the size is good, the size errors first */
    for (int m = 0; m < NMAPS; m++) {
        glPixelMapfv(maps[m], 4, NULL);
        glPixelMapuiv(maps[m], 2, NULL);
        glPixelMapusv(maps[m], 1, NULL);
        snprintf(l, sizeof l, "%s null", map_names[m]);
        fc_error(h, l);
        glPixelMapfv(maps[m], 0, NULL);
        snprintf(l, sizeof l, "%s null 0", map_names[m]);
        fc_error(h, l);
        glGetPixelMapfv(maps[m], NULL);
        glGetPixelMapuiv(maps[m], NULL);
        glGetPixelMapusv(maps[m], NULL);
        snprintf(l, sizeof l, "%s get null", map_names[m]);
        fc_error(h, l);
    }
    read_maps(h, "after null");
}

/* glBegin/glEnd and bad query maps */
static void errors(fc_h *h)
{
    fill_tables();
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, ftab);
    glBegin(GL_POINTS);
    glPixelTransferf(GL_RED_SCALE, 2.0f);
    fc_error(h, "transferf in begin");
    glPixelTransferi(GL_INDEX_SHIFT, 2);
    fc_error(h, "transferi in begin");
    glPixelZoom(2.0f, 3.0f);
    fc_error(h, "zoom in begin");
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, ftab);
    fc_error(h, "mapfv in begin");
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 2, utab);
    fc_error(h, "mapuiv in begin");
    glPixelMapusv(GL_PIXEL_MAP_S_TO_S, 2, stab);
    fc_error(h, "mapusv in begin");
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, ftab);
    fc_error(h, "bad size in begin");
    glPixelTransferf(GL_ZOOM_X, 2.0f);
    fc_error(h, "bad pname in begin");
    GLfloat fv[8] = { -1, -1, -1, -1, -1, -1, -1, -1 };
    glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, fv);
    fc_error(h, "getfv in begin");
    glEnd();
    fc_error(h, "end");
    fc_blob(h, "getfv in begin values", fv, sizeof fv);
    transfer_state(h, "after begin");
    read_map(h, "after begin", 6);
    read_map(h, "after begin", 0);
    read_map(h, "after begin", 1);
    /* bad query maps */
    GLuint uiv[4] = { 7, 7, 7, 7 };
    GLushort usv[4] = { 7, 7, 7, 7 };
    glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R_SIZE, fv);
    fc_error(h, "getfv bad");
    glGetPixelMapuiv(0, uiv);
    fc_error(h, "getuiv bad");
    glGetPixelMapusv(GL_MAP_COLOR, usv);
    fc_error(h, "getusv bad");
    fc_blob(h, "bad values fv", fv, sizeof fv);
    fc_blob(h, "bad values uiv", uiv, sizeof uiv);
    fc_blob(h, "bad values usv", usv, sizeof usv);
}

/* GL_PIXEL_MODE_BIT saves transfer and zoom, not the maps */
static void pushpop(fc_h *h)
{
    fill_tables();
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferi(GL_INDEX_OFFSET, 7);
    glPixelTransferi(GL_MAP_STENCIL, 1);
    glPixelZoom(2.0f, -2.0f);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 4, ftab);
    glPushAttrib(GL_PIXEL_MODE_BIT);
    for (int i = 0; i < NTRANSFER; i++)
        glPixelTransferf(transfer_pnames[i], 3.25f);
    glPixelZoom(-1.0f, 0.25f);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, &ftab[4]);
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 4, utab);
    transfer_state(h, "pushed");
    glPopAttrib();
    fc_error(h, "pop");
    transfer_state(h, "popped");
    read_map(h, "popped", 7);
    read_map(h, "popped", 0);
    /* other groups do not save it */
    glPushAttrib(GL_ALL_ATTRIB_BITS & ~GL_PIXEL_MODE_BIT);
    glPixelTransferf(GL_BLUE_BIAS, -1.0f);
    glPixelZoom(3.0f, 3.0f);
    glPopAttrib();
    transfer_state(h, "other groups");
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glPixelTransferf(GL_BLUE_BIAS, 0.125f);
    glPixelZoom(4.0f, 5.0f);
    glPopAttrib();
    transfer_state(h, "all bits");
    fc_error(h, "end");
}

/* A transfer or zoom value changed and set back still marks the group for
 * glPopAttrib (Mesa's FLUSH_VERTICES(.., GL_PIXEL_MODE_BIT)), whose restore
 * flushes through glReadBuffer: seen on a colour left in the vertex format
 * after the push of GL_CURRENT_BIT.  A map changed back does not mark it. */
static void pushpop_flush(fc_h *h)
{
    static const struct { int kind; const char *label; } steps[] = {
        { 0, "zoom back" }, { 1, "transfer back" }, { 2, "map" }, { 3, "nothing" },
    };
    fc_pixel_ortho(h);
    fcu_clear(0, 0, 0, 0, 1);
    char l[64];
    for (int i = 0; i < 4; i++) {
        glColor3f(0.2f, 0.4f, 0.6f);
        fcu_rect((float)(i * 8), 0, (float)(i * 8 + 4), 4, 0);
        glPushAttrib(GL_CURRENT_BIT | GL_PIXEL_MODE_BIT);
        if (steps[i].kind == 0) {
            glPixelZoom(2.0f, 2.0f);
            glPixelZoom(1.0f, 1.0f);
        } else if (steps[i].kind == 1) {
            glPixelTransferf(GL_RED_SCALE, 2.0f);
            glPixelTransferf(GL_RED_SCALE, 1.0f);
        } else if (steps[i].kind == 2) {
            const GLfloat v[2] = { 0.5f, 0.25f };
            glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, v);
            glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 1, v);
        }
        glColor3f(0.0f, 1.0f, 0.0f);
        glPopAttrib();
        snprintf(l, sizeof l, "%s colour", steps[i].label);
        fc_get_float(h, l, GL_CURRENT_COLOR, 4);
        fcu_rect((float)(i * 8), 4, (float)(i * 8 + 8), 12, 0);
        snprintf(l, sizeof l, "%s colour after draw", steps[i].label);
        fc_get_float(h, l, GL_CURRENT_COLOR, 4);
    }
    fc_capture(h);
    fc_error(h, "final");
}

/* Display lists: compiled (uiv/usv converted at compile time), replayed;
 * compiled errors raised at replay; glGetPixelMap executes at once */
static void dlist(fc_h *h)
{
    fill_tables();
    const GLuint list = glGenLists(2);
    glNewList(list, GL_COMPILE);
    glPixelTransferf(GL_GREEN_SCALE, 0.25f);
    glPixelTransferi(GL_INDEX_SHIFT, -4);
    glPixelTransferf(GL_ZOOM_Y, 1.0f);          /* error at replay */
    glPixelZoom(0.5f, 8.0f);
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, ftab);
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_G, 64, utab);
    glPixelMapusv(GL_PIXEL_MAP_S_TO_S, 4, stab);
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 5, utab);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 3, ftab);  /* error at replay */
    GLfloat fv[4] = { -1, -1, -1, -1 };
    glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, fv);    /* executes now */
    fc_error(h, "compile");
    glEndList();
    fc_blob(h, "get while compiling", fv, sizeof fv);
    transfer_state(h, "after compile");
    read_maps(h, "after compile");
    glCallList(list);
    fc_error(h, "call");
    transfer_state(h, "after call");
    read_maps(h, "after call");

    /* GL_COMPILE_AND_EXECUTE: errors now, and again at replay */
    glNewList(list + 1, GL_COMPILE_AND_EXECUTE);
    glPixelTransferf(GL_ALPHA_BIAS, 0.375f);
    glPixelTransferi(GL_MAP_COLOR, 1);
    glPixelZoom(-2.0f, 1.5f);
    glPixelMapusv(GL_PIXEL_MAP_A_TO_A, 16, &stab[1]);
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_A, 7, utab);   /* error */
    fc_error(h, "compile and execute");
    glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 2, &ftab[2]);
    glEndList();
    transfer_state(h, "after compile and execute");
    read_maps(h, "after compile and execute");
    glPixelTransferf(GL_ALPHA_BIAS, 0.0f);
    glPixelTransferi(GL_MAP_COLOR, 0);
    glPixelZoom(1.0f, 1.0f);
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 1, ftab);
    glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 1, ftab);
    glCallList(list + 1);
    fc_error(h, "call 2");
    transfer_state(h, "after call 2");
    read_maps(h, "after call 2");

    /* inside glBegin/glEnd while compiling: a compiled error */
    glNewList(list, GL_COMPILE);
    glBegin(GL_POINTS);
    glPixelTransferf(GL_RED_BIAS, 0.5f);
    glPixelZoom(3.0f, 3.0f);
    glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, ftab);
    glEnd();
    glEndList();
    fc_error(h, "compile in begin");
    glCallList(list);
    fc_error(h, "call in begin");
    transfer_state(h, "after call in begin");
    read_map(h, "after call in begin", 8);
    glDeleteLists(list, 2);
}

const fc_case fc_cases_pixelstate[] = {
    FC_CASE_RGBA("pixelstate/transfer", 8, 8, 0, "pixel api", transfer),
    FC_CASE_RGBA("pixelstate/zoom", 8, 8, 0, "pixel api", zoom),
    FC_CASE_RGBA("pixelstate/maps_fv", 8, 8, 0, "pixel api", maps_fv),
    FC_CASE_RGBA("pixelstate/maps_uiv", 8, 8, 0, "pixel api", maps_uiv),
    FC_CASE_RGBA("pixelstate/maps_usv", 8, 8, 0, "pixel api", maps_usv),
    FC_CASE_RGBA("pixelstate/sizes", 8, 8, 0, "pixel api errors", sizes),
    FC_CASE_RGBA("pixelstate/errors", 8, 8, 0, "pixel api errors", errors),
    FC_CASE_RGBA("pixelstate/pushpop", 8, 8, 0, "pixel api attrib", pushpop),
    FC_CASE_RGBA("pixelstate/pushpop_flush", 32, 16, 1, "pixel api attrib", pushpop_flush),
    FC_CASE_RGBA("pixelstate/dlist", 8, 8, 0, "pixel api dlist", dlist),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
