/* c_accum.c - the accumulation buffer: glAccum (GL_LOAD, GL_ACCUM,
 * GL_MULT, GL_ADD, GL_RETURN) with values that round, wrap the oracle's
 * 16-bit buffer and clamp on return; glClearAccum and glClear of the
 * accumulation buffer under a scissor; GL_RETURN through colour masks and
 * scissor; accumulation anti-aliasing and motion blur; queries, errors,
 * glPushAttrib(GL_ACCUM_BUFFER_BIT) and compiled glAccum.
 *
 * The harness context has no accumulation buffer, so most cases make their
 * own context with OSMesaCreateContextExt(..., accumBits, ...), capture its
 * buffer with fc_capture_buffer and make the harness context current
 * again.  The accumulation buffer is only visible through GL_RETURN: the
 * cases return it at several scales and record the colour buffer with
 * glReadPixels. */
#include "cases.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define AW 32
#define AH 32

typedef struct accum_ctx {
    OSMesaContext ctx;
    unsigned char *buf;
    int w, ht;
    GLenum format;
} accum_ctx;

/* Makes a context with an accumulation buffer current (records whether
 * creation and binding worked). */
static int accum_begin(fc_h *h, accum_ctx *a, GLenum format, int accum_bits, int w, int ht)
{
    a->w = w;
    a->ht = ht;
    a->format = format;
    a->buf = malloc((size_t)w * (size_t)ht * 4);
    memset(a->buf, 0x5A, (size_t)w * (size_t)ht * 4);
    a->ctx = OSMesaCreateContextExt(format, 24, 8, accum_bits, NULL);
    fc_value(h, "accum context created", a->ctx != NULL);
    if (!a->ctx)
        return 0;
    GLboolean ok = OSMesaMakeCurrent(a->ctx, a->buf, GL_UNSIGNED_BYTE, w, ht);
    fc_value(h, "accum context current", ok);
    if (!ok)
        return 0;
    glViewport(0, 0, w, ht);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, ht, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    return 1;
}

static void accum_capture(fc_h *h, accum_ctx *a)
{
    fc_capture_buffer(h, a->buf, a->w, a->ht, a->w, a->format, 1);
}

/* Destroys the context and makes the harness context current again. */
static void accum_end(fc_h *h, accum_ctx *a)
{
    if (a->ctx) {
        glFinish();
        OSMesaDestroyContext(a->ctx);
    }
    free(a->buf);
    const fc_case *c = fc_this_case(h);
    OSMesaMakeCurrent(fc_context(h), fc_buffer(h), GL_UNSIGNED_BYTE, c->width, c->height);
}

/* Records the whole colour buffer (RGBA ubyte) and the error state. */
static void read_back(fc_h *h, accum_ctx *a, const char *label)
{
    size_t n = (size_t)a->w * (size_t)a->ht * 4;
    unsigned char *px = malloc(n);
    memset(px, 0xA7, n);
    glReadPixels(0, 0, a->w, a->ht, GL_RGBA, GL_UNSIGNED_BYTE, px);
    fc_blob(h, label, px, n);
    free(px);
    fc_error(h, label);
}

/* GL_RETURN at value, then read back */
static void ret(fc_h *h, accum_ctx *a, const char *label, float value)
{
    glAccum(GL_RETURN, value);
    fc_error(h, label);
    read_back(h, a, label);
}

/* A colour buffer with every channel spread over [0, 1]: smooth gradients
 * with alpha, plus flat saturated bands. */
static void scene(accum_ctx *a, int k)
{
    const float w = (float)a->w, ht = (float)a->ht;
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(0.1f * (float)k, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUADS);
    glColor4f(0.0f, 0.0f, 1.0f, 0.0f); glVertex2f(0, 0);
    glColor4f(1.0f, 0.0f, 0.5f, 0.3f); glVertex2f(w, 0);
    glColor4f(1.0f, 1.0f, 0.0f, 1.0f); glVertex2f(w, ht * 0.75f);
    glColor4f(0.0f, 1.0f, 0.25f, 0.7f); glVertex2f(0, ht * 0.75f);
    glEnd();
    fcu_color(k);
    fcu_rect(0, ht * 0.75f, w * 0.5f, ht, 0);
    glColor4f(0.5f, 0.25f, 0.75f, 0.5f);
    fcu_rect(w * 0.5f, ht * 0.75f, w, ht, 0);
}

/* GL_LOAD at several values (rounding, negative, wrapping past 1 and
 * huge), each returned at several scales (clamping, negative) */
static void load_return(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, AW, AH)) {
        static const float loads[] = { 1.0f, 0.7f, 0.5f, 1.0f / 3.0f, -0.5f, -1.0f,
                                       1.00002f, 1.5f, 2.0f, -2.0f, 1e10f, 0.0f };
        static const float rets[] = { 1.0f, 0.5f, 2.0f, -1.0f, 1.0f / 0.7f, 3.0f, -2.5f };
        char label[64];
        for (size_t i = 0; i < sizeof loads / sizeof loads[0]; i++) {
            for (size_t j = 0; j < sizeof rets / sizeof rets[0]; j++) {
                scene(&a, (int)i);
                glAccum(GL_LOAD, loads[i]);
                snprintf(label, sizeof label, "LOAD %g RETURN %g", loads[i], rets[j]);
                ret(h, &a, label, rets[j]);
                /* the frame: LOAD 0.7, RETURN 1 (the last loads and
                 * returns give a uniform buffer, which compares nothing) */
                if (i == 1 && j == 0)
                    accum_capture(h, &a);
            }
        }
    }
    accum_end(h, &a);
}

/* GL_ACCUM of several frames at positive, negative and large values */
static void accum_op(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, AW, AH)) {
        static const float vals[][3] = {
            { 0.25f, 0.25f, 0.5f }, { 0.5f, -0.3f, 0.1f }, { 0.6f, 0.6f, 0.6f },
            { 1.5f, 0.5f, 1.0f }, { -1.0f, -0.75f, 0.0f }, { 0.125f, 0.0f, 3.0f },
        };
        char label[64];
        for (size_t i = 0; i < sizeof vals / sizeof vals[0]; i++) {
            scene(&a, 1);
            glAccum(GL_LOAD, 0.25f);
            for (int k = 0; k < 3; k++) {
                scene(&a, k + 2);
                glAccum(GL_ACCUM, vals[i][k]);
            }
            snprintf(label, sizeof label, "ACCUM set %zu RETURN 1", i);
            ret(h, &a, label, 1.0f);
            snprintf(label, sizeof label, "ACCUM set %zu RETURN -1", i);
            ret(h, &a, label, -1.0f);
            snprintf(label, sizeof label, "ACCUM set %zu RETURN 0.5", i);
            ret(h, &a, label, 0.5f);
        }
        accum_capture(h, &a);
    }
    accum_end(h, &a);
}

/* GL_MULT and GL_ADD: halving, doubling past the range, negative, zero,
 * huge and the no-op values */
static void mult_add(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, AW, AH)) {
        static const struct { GLenum op; float v; } ops[] = {
            { GL_MULT, 0.5f }, { GL_MULT, 2.0f }, { GL_MULT, 3.0f }, { GL_MULT, -1.0f },
            { GL_MULT, 0.0f }, { GL_MULT, 1.0f }, { GL_MULT, 1e10f }, { GL_MULT, 0.999f },
            { GL_ADD, 0.25f }, { GL_ADD, -0.5f }, { GL_ADD, 1.0f }, { GL_ADD, 3.0f },
            { GL_ADD, 0.0f }, { GL_ADD, -1.0f }, { GL_ADD, 1e-5f }, { GL_ADD, 0.3333f },
        };
        char label[64];
        for (size_t i = 0; i < sizeof ops / sizeof ops[0]; i++) {
            scene(&a, (int)i);
            glAccum(GL_LOAD, 0.8f);
            glAccum(ops[i].op, ops[i].v);
            glAccum(ops[i].op, ops[i].v);
            snprintf(label, sizeof label, "%s %g twice, RETURN 1",
                     ops[i].op == GL_MULT ? "MULT" : "ADD", ops[i].v);
            ret(h, &a, label, 1.0f);
            snprintf(label, sizeof label, "%s %g twice, RETURN -1",
                     ops[i].op == GL_MULT ? "MULT" : "ADD", ops[i].v);
            ret(h, &a, label, -1.0f);
        }
        /* chains: decay, then bias back */
        scene(&a, 3);
        glAccum(GL_LOAD, 1.0f);
        for (int k = 0; k < 5; k++)
            glAccum(GL_MULT, 0.5f);
        glAccum(GL_ADD, 0.2f);
        glAccum(GL_MULT, 2.0f);
        ret(h, &a, "chain RETURN 1", 1.0f);
        accum_capture(h, &a);   /* RETURN 4 saturates every pixel */
        ret(h, &a, "chain RETURN 4", 4.0f);
    }
    accum_end(h, &a);
}

/* glClearAccum (clamped to [-1, 1]) and glClear of the accumulation buffer,
 * whole and scissored, with the colour mask and draw buffer not applying */
static void clear_accum(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, AW, AH)) {
        static const float cv[][4] = {
            { 0.5f, 0.3f, 0.1f, 0.9f }, { -1.0f, 2.0f, -3.0f, 0.25f },
            { 1.0f, 1.0f, 1.0f, 1.0f }, { 0.0f, -0.0f, 1e-5f, -1e-5f },
            { 0.333f, 0.666f, 0.999f, 0.001f }, { -0.5f, -0.25f, -0.75f, -0.9f },
        };
        char label[64];
        for (size_t i = 0; i < sizeof cv / sizeof cv[0]; i++) {
            scene(&a, (int)i);
            glClearAccum(cv[i][0], cv[i][1], cv[i][2], cv[i][3]);
            glClear(GL_ACCUM_BUFFER_BIT);
            snprintf(label, sizeof label, "clear %zu RETURN 1", i);
            ret(h, &a, label, 1.0f);
            snprintf(label, sizeof label, "clear %zu RETURN -1", i);
            ret(h, &a, label, -1.0f);
        }
        /* scissored clear over a loaded buffer */
        scene(&a, 4);
        glAccum(GL_LOAD, 1.0f);
        glClearAccum(0.25f, 0.5f, 0.75f, 1.0f);
        glScissor(5, 7, 13, 9);
        glEnable(GL_SCISSOR_TEST);
        glClear(GL_ACCUM_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        ret(h, &a, "scissored clear RETURN 1", 1.0f);
        /* scissor partly outside, colour mask off and no draw buffer: the
         * accumulation buffer is still cleared */
        scene(&a, 5);
        glAccum(GL_LOAD, 0.5f);
        glClearAccum(-0.5f, 0.9f, 0.1f, 0.6f);
        glScissor(-4, 20, 20, 40);
        glEnable(GL_SCISSOR_TEST);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDrawBuffer(GL_NONE);
        glClear(GL_ACCUM_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
        glDrawBuffer(GL_FRONT);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDisable(GL_SCISSOR_TEST);
        ret(h, &a, "clipped scissor, masked, RETURN 1", 1.0f);
        ret(h, &a, "clipped scissor, masked, RETURN -1", -1.0f);
        /* an empty scissor clears nothing */
        glClearAccum(1, 1, 1, 1);
        glScissor(3, 3, 0, 5);
        glEnable(GL_SCISSOR_TEST);
        glClear(GL_ACCUM_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        ret(h, &a, "empty scissor RETURN 1", 1.0f);
        accum_capture(h, &a);
    }
    accum_end(h, &a);
}

/* GL_RETURN (and GL_LOAD / GL_ACCUM) limited by colour masks and scissor;
 * blending, dithering, logic op and alpha test do not apply */
static void return_mask_scissor(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, AW, AH)) {
        char label[64];
        for (unsigned m = 0; m < 16; m++) {
            scene(&a, 2);
            glAccum(GL_LOAD, 0.6f);
            scene(&a, 7);
            glColorMask((m & 1) != 0, (m & 2) != 0, (m & 4) != 0, (m & 8) != 0);
            snprintf(label, sizeof label, "RETURN 1.3 mask %u", m);
            ret(h, &a, label, 1.3f);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        }
        scene(&a, 3);
        glAccum(GL_LOAD, 1.0f);
        scene(&a, 8);
        glScissor(4, 6, 17, 11);
        glEnable(GL_SCISSOR_TEST);
        ret(h, &a, "RETURN 0.5 scissored", 0.5f);
        glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
        glScissor(10, -5, 40, 12);
        ret(h, &a, "RETURN 2 scissored, masked", 2.0f);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        /* LOAD and ACCUM under the scissor too */
        glScissor(2, 2, 9, 20);
        glAccum(GL_LOAD, -1.0f);
        glScissor(6, 10, 20, 5);
        glAccum(GL_ACCUM, 0.5f);
        glAccum(GL_MULT, 0.75f);
        glAccum(GL_ADD, 0.1f);
        glDisable(GL_SCISSOR_TEST);
        ret(h, &a, "after scissored LOAD/ACCUM/MULT/ADD RETURN 1", 1.0f);
        ret(h, &a, "after scissored LOAD/ACCUM/MULT/ADD RETURN -1", -1.0f);
        /* fragment operations do not apply to GL_RETURN */
        scene(&a, 4);
        glAccum(GL_LOAD, 0.5f);
        scene(&a, 9);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        glEnable(GL_ALPHA_TEST);
        glAlphaFunc(GL_NEVER, 0.0f);
        glEnable(GL_COLOR_LOGIC_OP);
        glLogicOp(GL_XOR);
        glEnable(GL_DITHER);
        ret(h, &a, "RETURN under blend, alpha test, logic op", 1.1f);
        glDisable(GL_BLEND);
        glDisable(GL_ALPHA_TEST);
        glDisable(GL_COLOR_LOGIC_OP);
        accum_capture(h, &a);
    }
    accum_end(h, &a);
}

/* Accumulation anti-aliasing: n jittered frames, each accumulated with
 * 1/n, then returned */
static void antialias(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, AW, AH)) {
        static const float jitter8[8][2] = {
            { -0.334818f, 0.435331f }, { 0.286438f, -0.393495f },
            { 0.459462f, 0.141540f }, { -0.414498f, -0.192829f },
            { -0.183790f, 0.082102f }, { -0.079263f, -0.317383f },
            { 0.102254f, 0.299133f }, { 0.164216f, -0.054399f },
        };
        glClearAccum(0, 0, 0, 0);
        glClear(GL_ACCUM_BUFFER_BIT);
        for (int j = 0; j < 8; j++) {
            glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glLoadIdentity();
            glTranslatef(jitter8[j][0], jitter8[j][1], 0.0f);
            glShadeModel(GL_SMOOTH);
            glBegin(GL_TRIANGLES);
            glColor3f(1, 0.2f, 0.1f); glVertex2f(2.3f, 3.1f);
            glColor3f(0.2f, 1, 0.3f); glVertex2f(29.6f, 9.7f);
            glColor3f(0.1f, 0.3f, 1); glVertex2f(11.2f, 28.4f);
            glEnd();
            glColor3f(1, 1, 0.5f);
            glBegin(GL_LINES);
            glVertex2f(1.5f, 30.2f); glVertex2f(30.7f, 18.9f);
            glEnd();
            glAccum(GL_ACCUM, 1.0f / 8.0f);
        }
        glAccum(GL_RETURN, 1.0f);
        read_back(h, &a, "8 jittered frames");
        accum_capture(h, &a);
        /* 3 frames: 1/3 does not divide evenly */
        glClear(GL_ACCUM_BUFFER_BIT);
        for (int j = 0; j < 3; j++) {
            glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            glLoadIdentity();
            glTranslatef(jitter8[j][0], jitter8[j][1], 0.0f);
            fcu_color(j + 3);
            fcu_tri(3.3f, 2.2f, 28.8f, 14.1f, 6.6f, 27.5f);
            glAccum(j == 0 ? GL_LOAD : GL_ACCUM, 1.0f / 3.0f);
        }
        glAccum(GL_RETURN, 1.0f);
        read_back(h, &a, "3 jittered frames");
        accum_capture(h, &a);
    }
    accum_end(h, &a);
}

/* Motion blur: each frame decays the buffer (GL_MULT) and adds the new
 * frame (GL_ACCUM), then returns */
static void motion_blur(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, AW, AH)) {
        glClearAccum(0, 0, 0, 0);
        glClear(GL_ACCUM_BUFFER_BIT);
        char label[64];
        for (int f = 0; f < 10; f++) {
            glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            glLoadIdentity();
            glTranslatef(2.7f * (float)f, 1.3f * (float)f, 0.0f);
            glColor4f(1.0f, 0.8f, 0.3f, 1.0f);
            fcu_rect(1.0f, 1.0f, 7.5f, 6.5f, 0);
            glAccum(GL_MULT, 0.7f);
            glAccum(GL_ACCUM, 0.3f);
            glAccum(GL_RETURN, 1.0f);
            snprintf(label, sizeof label, "blur frame %d", f);
            read_back(h, &a, label);
        }
        accum_capture(h, &a);
    }
    accum_end(h, &a);
}

/* glGet of the accumulation state, for accumBits 0, 8, 16, 32 and 64 */
static void queries(fc_h *h)
{
    static const int bits[] = { 0, 1, 8, 16, 32, 64 };
    char label[64];
    for (size_t i = 0; i < sizeof bits / sizeof bits[0]; i++) {
        accum_ctx a;
        if (accum_begin(h, &a, OSMESA_RGBA, bits[i], 4, 4)) {
            snprintf(label, sizeof label, "accumBits %d: RED", bits[i]);
            fc_get_integer(h, label, GL_ACCUM_RED_BITS, 1);
            snprintf(label, sizeof label, "accumBits %d: GREEN", bits[i]);
            fc_get_integer(h, label, GL_ACCUM_GREEN_BITS, 1);
            snprintf(label, sizeof label, "accumBits %d: BLUE", bits[i]);
            fc_get_integer(h, label, GL_ACCUM_BLUE_BITS, 1);
            snprintf(label, sizeof label, "accumBits %d: ALPHA", bits[i]);
            fc_get_float(h, label, GL_ACCUM_ALPHA_BITS, 1);
            snprintf(label, sizeof label, "accumBits %d: glAccum", bits[i]);
            glAccum(GL_LOAD, 1.0f);
            fc_error(h, label);
        }
        accum_end(h, &a);
    }
    /* the harness context (accumBits 0) */
    fc_get_integer(h, "harness ACCUM_RED_BITS", GL_ACCUM_RED_BITS, 1);
    fc_get_float(h, "initial ACCUM_CLEAR_VALUE", GL_ACCUM_CLEAR_VALUE, 4);
    static const float cv[][4] = {
        { 0.5f, -0.25f, 0.125f, 1.0f }, { 2.0f, -3.0f, 1.0f, -1.0f },
        { 1e30f, -1e30f, 1e-30f, -1e-30f }, { 0.3f, 0.6f, 0.9f, -0.7f },
    };
    for (size_t i = 0; i < sizeof cv / sizeof cv[0]; i++) {
        glClearAccum(cv[i][0], cv[i][1], cv[i][2], cv[i][3]);
        snprintf(label, sizeof label, "ACCUM_CLEAR_VALUE %zu float", i);
        fc_get_float(h, label, GL_ACCUM_CLEAR_VALUE, 4);
        snprintf(label, sizeof label, "ACCUM_CLEAR_VALUE %zu int", i);
        fc_get_integer(h, label, GL_ACCUM_CLEAR_VALUE, 4);
        snprintf(label, sizeof label, "ACCUM_CLEAR_VALUE %zu double", i);
        fc_get_double(h, label, GL_ACCUM_CLEAR_VALUE, 4);
        snprintf(label, sizeof label, "ACCUM_CLEAR_VALUE %zu boolean", i);
        fc_get_boolean(h, label, GL_ACCUM_CLEAR_VALUE, 4);
    }
    glClearAccum(NAN, 0.5f, NAN, -NAN);
    fc_get_float(h, "ACCUM_CLEAR_VALUE NaN", GL_ACCUM_CLEAR_VALUE, 4);
}

/* Errors: a bad op before the missing buffer, glAccum and glClearAccum
 * inside glBegin/glEnd, and the cases that do nothing (GL_SELECT mode,
 * no read buffer for GL_LOAD, no draw buffer for GL_RETURN) */
static void errors(fc_h *h)
{
    /* the harness context has no accumulation buffer */
    static const GLenum ops[] = { GL_ACCUM, GL_LOAD, GL_RETURN, GL_MULT, GL_ADD };
    char label[64];
    for (size_t i = 0; i < sizeof ops / sizeof ops[0]; i++) {
        glAccum(ops[i], 0.5f);
        snprintf(label, sizeof label, "no accum buffer: op 0x%x", ops[i]);
        fc_error(h, label);
    }
    glAccum(GL_ADD, 0.0f);
    fc_error(h, "no accum buffer: ADD 0");
    glAccum(GL_MULT, 1.0f);
    fc_error(h, "no accum buffer: MULT 1");
    glAccum(0x1234, 0.5f);
    fc_error(h, "no accum buffer: bad op");
    glClear(GL_ACCUM_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    fc_error(h, "no accum buffer: glClear(GL_ACCUM_BUFFER_BIT)");
    glClearAccum(0.5f, 0.5f, 0.5f, 0.5f);
    fc_error(h, "no accum buffer: glClearAccum");

    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, 8, 8)) {
        glAccum(GL_POLYGON, 1.0f);
        fc_error(h, "bad op GL_POLYGON");
        glAccum(GL_ACCUM_BUFFER_BIT, 1.0f);
        fc_error(h, "bad op GL_ACCUM_BUFFER_BIT");
        glAccum(GL_RETURN + 1, 1.0f);
        fc_error(h, "bad op GL_RETURN + 1");
        scene(&a, 1);
        glAccum(GL_LOAD, 0.5f);
        glBegin(GL_TRIANGLES);
        glAccum(GL_LOAD, 1.0f);
        glClearAccum(1, 0, 0, 1);
        glEnd();
        fc_error(h, "inside glBegin/glEnd");
        fc_get_float(h, "clear value after glBegin/glEnd", GL_ACCUM_CLEAR_VALUE, 4);
        ret(h, &a, "after glBegin/glEnd RETURN 1", 1.0f);
        /* no read buffer: GL_LOAD and GL_ACCUM read nothing */
        scene(&a, 2);
        glReadBuffer(GL_NONE);
        glAccum(GL_LOAD, 1.0f);
        glAccum(GL_ACCUM, 1.0f);
        fc_error(h, "LOAD without read buffer");
        glReadBuffer(GL_FRONT);
        ret(h, &a, "LOAD without read buffer RETURN 1", 1.0f);
        /* no draw buffer: GL_RETURN writes nothing */
        scene(&a, 3);
        glDrawBuffer(GL_NONE);
        glAccum(GL_RETURN, 1.0f);
        fc_error(h, "RETURN without draw buffer");
        glDrawBuffer(GL_FRONT);
        read_back(h, &a, "RETURN without draw buffer");
        /* feedback mode: glAccum and the accumulation clear do nothing */
        GLfloat fb[64];
        glFeedbackBuffer(64, GL_2D, fb);
        glRenderMode(GL_FEEDBACK);
        glAccum(GL_LOAD, 0.25f);
        glClearAccum(1, 1, 1, 1);
        glClear(GL_ACCUM_BUFFER_BIT);
        fc_error(h, "feedback mode");
        glRenderMode(GL_RENDER);
        ret(h, &a, "after feedback mode RETURN 1", 1.0f);
        accum_capture(h, &a);
    }
    accum_end(h, &a);
}

/* glPushAttrib(GL_ACCUM_BUFFER_BIT) saves and restores the clear value */
static void push_pop(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, 8, 8)) {
        glClearAccum(0.25f, -0.5f, 0.75f, 1.0f);
        glPushAttrib(GL_ACCUM_BUFFER_BIT);
        glClearAccum(-1.0f, 0.1f, 0.2f, 0.3f);
        fc_get_float(h, "changed", GL_ACCUM_CLEAR_VALUE, 4);
        glPushAttrib(GL_COLOR_BUFFER_BIT);
        glClearAccum(0.9f, 0.9f, 0.9f, 0.9f);
        glPopAttrib();
        fc_get_float(h, "not restored by the colour group", GL_ACCUM_CLEAR_VALUE, 4);
        glPopAttrib();
        fc_get_float(h, "restored", GL_ACCUM_CLEAR_VALUE, 4);
        scene(&a, 1);
        glClear(GL_ACCUM_BUFFER_BIT);
        ret(h, &a, "clear with the restored value, RETURN 1", 1.0f);
        ret(h, &a, "clear with the restored value, RETURN -1", -1.0f);
        glPushAttrib(GL_ALL_ATTRIB_BITS);
        glClearAccum(0, 0, 0, 0);
        glPopAttrib();
        fc_get_float(h, "restored by GL_ALL_ATTRIB_BITS", GL_ACCUM_CLEAR_VALUE, 4);
        fc_error(h, "push/pop");
        accum_capture(h, &a);
    }
    accum_end(h, &a);
}

/* glAccum and glClearAccum compiled into display lists (GL_COMPILE and
 * GL_COMPILE_AND_EXECUTE); a bad op raises its error at execution */
static void display_list(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, 16, 16)) {
        GLuint l = glGenLists(3);
        glNewList(l, GL_COMPILE);
        glClearAccum(0.1f, 0.2f, 0.3f, 0.4f);
        glClear(GL_ACCUM_BUFFER_BIT);
        glAccum(GL_ACCUM, 0.5f);
        glAccum(GL_MULT, 1.5f);
        glAccum(GL_ADD, -0.125f);
        glEndList();
        fc_error(h, "compile");
        fc_get_float(h, "clear value not set by GL_COMPILE", GL_ACCUM_CLEAR_VALUE, 4);
        scene(&a, 2);
        glCallList(l);
        fc_error(h, "call");
        fc_get_float(h, "clear value after call", GL_ACCUM_CLEAR_VALUE, 4);
        ret(h, &a, "list RETURN 1", 1.0f);

        glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
        glAccum(GL_LOAD, 0.75f);
        glAccum(GL_RETURN, 0.9f);
        glAccum(0x1234, 1.0f);
        glEndList();
        fc_error(h, "compile and execute, bad op");
        read_back(h, &a, "compile and execute");
        scene(&a, 5);
        glCallList(l + 1);
        fc_error(h, "replay, bad op");
        read_back(h, &a, "replay");

        /* glAccum compiled inside an open glBegin is an error at compile */
        glNewList(l + 2, GL_COMPILE);
        glBegin(GL_POINTS);
        glAccum(GL_LOAD, 1.0f);
        glEnd();
        glEndList();
        fc_error(h, "compiled inside glBegin");
        glCallList(l + 2);
        fc_error(h, "replay of the list with the error");
        glDeleteLists(l, 3);
        accum_capture(h, &a);
    }
    accum_end(h, &a);
}

/* GL_RETURN alone does not make glFinish copy the image: the oracle copies
 * only after a draw or a clear since the last copy */
static void return_flush(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, 16, 16)) {
        scene(&a, 3);
        glAccum(GL_LOAD, 0.5f);
        accum_capture(h, &a);
        glAccum(GL_RETURN, 1.7f);
        accum_capture(h, &a);
        /* a clear of the accumulation buffer only validates the colour buffer */
        glClear(GL_ACCUM_BUFFER_BIT);
        accum_capture(h, &a);
        glAccum(GL_RETURN, 1.0f);
        glBegin(GL_POINTS);
        glEnd();
        accum_capture(h, &a);
    }
    accum_end(h, &a);
}

/* BGRA and ARGB buffers and a buffer without alpha (OSMESA_RGB: alpha
 * unpacks as 1) of odd sizes */
static void formats(fc_h *h)
{
    static const GLenum fmts[] = { OSMESA_BGRA, OSMESA_ARGB };
    char label[64];
    for (size_t i = 0; i < sizeof fmts / sizeof fmts[0]; i++) {
        accum_ctx a;
        if (accum_begin(h, &a, fmts[i], 16, 13, 7)) {
            scene(&a, (int)i);
            glAccum(GL_LOAD, 0.9f);
            scene(&a, (int)i + 4);
            glAccum(GL_ACCUM, -0.3f);
            glAccum(GL_MULT, 1.25f);
            snprintf(label, sizeof label, "format %zu RETURN 1", i);
            ret(h, &a, label, 1.0f);
            glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
            snprintf(label, sizeof label, "format %zu masked RETURN 0.6", i);
            ret(h, &a, label, 0.6f);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glClear(GL_DEPTH_BUFFER_BIT);
            accum_capture(h, &a);
        }
        accum_end(h, &a);
    }
}

/* Rebinding the context to another buffer of the same size keeps the
 * accumulation buffer; a new size makes a new one (the oracle's new buffer
 * holds garbage, as its first one does, so the case clears it first) */
static void rebind(fc_h *h)
{
    accum_ctx a;
    if (accum_begin(h, &a, OSMESA_RGBA, 16, 8, 8)) {
        scene(&a, 3);
        glAccum(GL_LOAD, 0.8f);
        unsigned char *other = malloc(8 * 8 * 4);
        memset(other, 0x33, 8 * 8 * 4);
        fc_value(h, "same size", OSMesaMakeCurrent(a.ctx, other, GL_UNSIGNED_BYTE, 8, 8));
        glClear(GL_DEPTH_BUFFER_BIT);
        ret(h, &a, "same size rebind RETURN 1", 1.0f);
        fc_capture_buffer(h, other, 8, 8, 8, OSMESA_RGBA, 1);
        unsigned char *big = malloc(12 * 6 * 4);
        memset(big, 0x44, 12 * 6 * 4);
        fc_value(h, "new size", OSMesaMakeCurrent(a.ctx, big, GL_UNSIGNED_BYTE, 12, 6));
        glViewport(0, 0, 12, 6);
        glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
        glClearAccum(-0.25f, 0.25f, 0.5f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
        glAccum(GL_ACCUM, 0.5f);
        glAccum(GL_RETURN, 1.5f);
        fc_error(h, "new size");
        unsigned char px[12 * 6 * 4];
        glReadPixels(0, 0, 12, 6, GL_RGBA, GL_UNSIGNED_BYTE, px);
        fc_blob(h, "new size RETURN 1.5", px, sizeof px);
        /* no capture here: after a resize the oracle's OSMesaGetDepthBuffer
         * returns its old, smaller mapping with the new size */
        glFinish();
        OSMesaMakeCurrent(a.ctx, a.buf, GL_UNSIGNED_BYTE, 8, 8);
        free(other);
        free(big);
    }
    accum_end(h, &a);
}

const fc_case fc_cases_accum[] = {
    FC_CASE_RGBA("accum/load_return", 8, 8, 1, "accum", load_return),
    FC_CASE_RGBA("accum/accum_op", 8, 8, 1, "accum", accum_op),
    FC_CASE_RGBA("accum/mult_add", 8, 8, 1, "accum", mult_add),
    FC_CASE_RGBA("accum/clear", 8, 8, 1, "accum clear", clear_accum),
    FC_CASE_RGBA("accum/return_mask_scissor", 8, 8, 1, "accum scissor", return_mask_scissor),
    FC_CASE_RGBA("accum/antialias", 8, 8, 2, "accum", antialias),
    FC_CASE_RGBA("accum/motion_blur", 8, 8, 1, "accum", motion_blur),
    FC_CASE_RGBA("accum/queries", 8, 8, 0, "accum query", queries),
    FC_CASE_RGBA("accum/errors", 8, 8, 1, "accum error", errors),
    /* the frame returns a cleared accumulation buffer (draws_nothing) */
    FC_CASE_NODRAW("accum/push_pop", 8, 8, OSMESA_RGBA, 24, 0, 1, "accum attrib", push_pop),
    FC_CASE_RGBA("accum/display_list", 8, 8, 1, "accum dlist", display_list),
    FC_CASE_RGBA("accum/return_flush", 8, 8, 4, "accum", return_flush),
    FC_CASE_RGBA("accum/formats", 8, 8, 2, "accum format", formats),
    FC_CASE_RGBA("accum/rebind", 8, 8, 1, "accum", rebind),
    { 0 }
};
