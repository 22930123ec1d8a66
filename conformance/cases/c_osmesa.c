/* c_osmesa.c - the OSMesa API (issue 19, "OSMesa API"; ORACLE-NOTES.md
 * "OSMesa contexts and buffers"):
 *  - OSMesaCreateContextAttribs: the attribute lists both libraries refuse
 *    and the GL 1.x requests both honour (a context that draws); what
 *    fixgl cannot provide (a core profile, a version above 1.5) is a
 *    documented difference: the oracle, a GL 4.5 implementation, gives a
 *    context. */
#include "cases.h"

#include <stdio.h>
#include <string.h>

/* A context from `attribs` bound to a 4x4 RGBA ubyte buffer, cleared and
 * a triangle drawn; records whether it was created and what it drew, then
 * binds the harness's context again. */
static void try_attribs(fc_h *h, const char *label, const int *attribs)
{
    static GLubyte px[4 * 4 * 4];
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
    char l[96];
    snprintf(l, sizeof l, "%s: created", label);
    fc_value(h, l, ctx != NULL);
    if (!ctx)
        return;
    memset(px, 0xA5, sizeof px);
    snprintf(l, sizeof l, "%s: bound", label);
    fc_value(h, l, OSMesaMakeCurrent(ctx, px, GL_UNSIGNED_BYTE, 4, 4));
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-1, -1);
    glColor3f(0, 1, 0); glVertex2f(1, -1);
    glColor3f(0, 0, 1); glVertex2f(-1, 1);
    glEnd();
    glFinish();
    snprintf(l, sizeof l, "%s: pixels", label);
    fc_blob(h, l, px, sizeof px);
    snprintf(l, sizeof l, "%s: error", label);
    fc_value(h, l, (long long)glGetError());
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    const fc_case *c = fc_this_case(h);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, c->width, c->height);
}

#define A(...) ((const int[]){ __VA_ARGS__, 0 })

static void attribs_refused(fc_h *h)
{
    try_attribs(h, "unknown attribute", A(0x9999, 1));
    try_attribs(h, "OSMESA_Y_UP as an attribute", A(OSMESA_Y_UP, 0));
    try_attribs(h, "profile 0x1234", A(OSMESA_PROFILE, 0x1234));
    try_attribs(h, "format 0x1234", A(OSMESA_FORMAT, 0x1234));
    try_attribs(h, "depth -1", A(OSMESA_DEPTH_BITS, -1));
    try_attribs(h, "stencil -2", A(OSMESA_STENCIL_BITS, -2));
    try_attribs(h, "accum -1", A(OSMESA_ACCUM_BITS, -1));
    try_attribs(h, "major 0", A(OSMESA_CONTEXT_MAJOR_VERSION, 0));
    try_attribs(h, "minor -1", A(OSMESA_CONTEXT_MINOR_VERSION, -1));
    try_attribs(h, "major 0 then 1", A(OSMESA_CONTEXT_MAJOR_VERSION, 0,
                                       OSMESA_CONTEXT_MAJOR_VERSION, 1));
    try_attribs(h, "4.6", A(OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 6));
    try_attribs(h, "1.100", A(OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 100));
    try_attribs(h, "core 9.9", A(OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                 OSMESA_CONTEXT_MAJOR_VERSION, 9, OSMESA_CONTEXT_MINOR_VERSION, 9));
    fc_error(h, "end");
}

static void attribs_compat(fc_h *h)
{
    try_attribs(h, "empty", A(0));
    try_attribs(h, "compat", A(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE));
    for (int minor = 0; minor <= 5; minor++) {
        char l[32];
        snprintf(l, sizeof l, "compat 1.%d", minor);
        try_attribs(h, l, A(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, minor));
    }
    try_attribs(h, "minor 5 alone", A(OSMESA_CONTEXT_MINOR_VERSION, 5));
    try_attribs(h, "core then compat", A(OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                         OSMESA_PROFILE, OSMESA_COMPAT_PROFILE));
    try_attribs(h, "major 3 then 1", A(OSMESA_CONTEXT_MAJOR_VERSION, 3,
                                       OSMESA_CONTEXT_MAJOR_VERSION, 1));
    try_attribs(h, "BGRA, depth 16, stencil 8, accum 16",
                A(OSMESA_FORMAT, OSMESA_BGRA, OSMESA_DEPTH_BITS, 16, OSMESA_STENCIL_BITS, 8,
                  OSMESA_ACCUM_BITS, 16, OSMESA_CONTEXT_MAJOR_VERSION, 1,
                  OSMESA_CONTEXT_MINOR_VERSION, 3));
    fc_error(h, "end");
}

/* What fixgl cannot provide: NULL there, a context in the oracle. */
static void attribs_unprovided(fc_h *h)
{
    static const char why[] = "deliberate: fixgl implements GL 1.x without a core profile "
                              "and refuses a core profile or a version above 1.5; the "
                              "oracle implements 4.5";
    const struct { const char *label; const int *attribs; } req[] = {
        { "core", A(OSMESA_PROFILE, OSMESA_CORE_PROFILE) },
        { "core 3.3", A(OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                        OSMESA_CONTEXT_MINOR_VERSION, 3) },
        { "compat 1.6", A(OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 6) },
        { "compat 2.1", A(OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 2,
                          OSMESA_CONTEXT_MINOR_VERSION, 1) },
        { "compat 3.0", A(OSMESA_CONTEXT_MAJOR_VERSION, 3) },
        { "compat 4.5", A(OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5) },
    };
    for (size_t i = 0; i < sizeof req / sizeof req[0]; i++) {
        static GLubyte px[4 * 4 * 4];
        char l[64];
        snprintf(l, sizeof l, "%s: created", req[i].label);
        fc_documented_difference(h, l, why);
        OSMesaContext ctx = OSMesaCreateContextAttribs(req[i].attribs, NULL);
        fc_value(h, l, ctx != NULL);
        if (ctx) {
            OSMesaMakeCurrent(ctx, px, GL_UNSIGNED_BYTE, 4, 4);
            OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
            OSMesaDestroyContext(ctx);
        }
    }
    const fc_case *c = fc_this_case(h);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, c->width, c->height);
    fc_error(h, "end");
}

const fc_case fc_cases_osmesa[] = {
    FC_CASE_RGBA("osmesa/attribs_refused", 8, 8, 0, "osmesa api", attribs_refused),
    FC_CASE_RGBA("osmesa/attribs_compat", 8, 8, 0, "osmesa api", attribs_compat),
    FC_CASE_RGBA("osmesa/attribs_unprovided", 8, 8, 0, "osmesa api", attribs_unprovided),
    { NULL, 0, 0, 0, 0, 0, 0, NULL, NULL, 0, 0, 0, 0 },
};
