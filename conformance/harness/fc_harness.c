/* fc_harness.c - runs one case: context and buffer set-up, the recording
 * helpers of fc_case.h, and the final checks.  Compiled into each renderer
 * against that renderer's GL/OSMesa headers. */
#include "fc_harness.h"
#include "fc_record.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct fc_h {
    const fc_case *c;
    OSMesaContext ctx;
    unsigned char *buf;
    unsigned char *shadow;      /* oracle, OSMESA_RGB cases: the RGBA buffer
                                 * actually rendered (see fc_case.h) */
    int row_length;
    int y_up;
    int frames;
    int perturb;
    FILE *out;
};

/* Fill pattern of fresh colour buffers and of glGet output arrays. */
#define FC_FILL FC_FILL_BYTE
#define FC_MAX_QUERY 32

int fc_format_bpp(GLenum format)
{
    switch (format) {
    case OSMESA_RGBA: case OSMESA_BGRA: case OSMESA_ARGB: return 4;
    case OSMESA_RGB: case OSMESA_BGR: return 3;
    default: return 0;
    }
}

void fc_capture_buffer(fc_h *h, const void *buf, int width, int height,
                       int row_length, GLenum format, int y_up)
{
    int32_t v[FC_FRAME_HDR_FIELDS];
    GLint dw = 0, dh = 0, dbpv = 0;
    void *dbuf = NULL;
    OSMesaContext cur;
    GLboolean dok = GL_FALSE;
    size_t clen, dlen = 0;
    unsigned char *color, *depth = NULL;

    glFinish();
    cur = OSMesaGetCurrentContext();
    if (cur)
        dok = OSMesaGetDepthBuffer(cur, &dw, &dh, &dbpv, &dbuf);
    if (!dok || !dbuf || dw < 0 || dh < 0 || dbpv < 0)
        dok = GL_FALSE, dw = dh = dbpv = 0;
    v[0] = width; v[1] = height; v[2] = row_length; v[3] = (int32_t)format;
    v[4] = fc_format_bpp(format); v[5] = y_up; v[6] = dok;
    v[7] = dw; v[8] = dh; v[9] = dbpv;

    clen = (size_t)row_length * (size_t)height * (size_t)v[4];
    color = malloc(clen ? clen : 1);
    memcpy(color, buf, clen);
    if (dok) {
        dlen = (size_t)dw * (size_t)dh * (size_t)dbpv;
        depth = malloc(dlen ? dlen : 1);
        memcpy(depth, dbuf, dlen);
    }
    if (h->perturb) {   /* test-only: a known one-pixel difference */
        if (clen)
            color[0] ^= 0x40;
        if (dlen)
            depth[0] ^= 0x01;
    }
    fc_rec_write(h->out, FC_REC_FRAME, "frame", v, sizeof v, color, clen, depth, dlen);
    free(color);
    free(depth);
    h->frames++;
}

/* Oracle OSMESA_RGB substitute: the RGBA shadow buffer, converted to the
 * case's RGB layout (same row length, same rows). */
static void shadow_to_rgb(fc_h *h)
{
    size_t n = (size_t)h->row_length * (size_t)h->c->height;
    glFinish();
    for (size_t i = 0; i < n; i++)
        memcpy(h->buf + 3 * i, h->shadow + 4 * i, 3);
}

void fc_capture(fc_h *h)
{
    if (h->shadow)
        shadow_to_rgb(h);
    fc_capture_buffer(h, h->buf, h->c->width, h->c->height, h->row_length,
                      h->c->format, h->y_up);
}

void fc_error(fc_h *h, const char *label)
{
    uint32_t e = glGetError();
    fc_rec_write(h->out, FC_REC_ERROR, label, &e, sizeof e, NULL, 0, NULL, 0);
}

static void write_query(fc_h *h, const char *label, uint32_t type, int count,
                        const void *data, size_t elem)
{
    uint32_t head[2] = { type, (uint32_t)count };
    fc_rec_write(h->out, FC_REC_QUERY, label, head, sizeof head,
                 data, (uint64_t)count * elem, NULL, 0);
}

static int clamp_count(int count)
{
    return count < 0 ? 0 : count > FC_MAX_QUERY ? FC_MAX_QUERY : count;
}

void fc_get_integer(fc_h *h, const char *label, GLenum pname, int count)
{
    GLint v[FC_MAX_QUERY * 2];
    memset(v, FC_FILL, sizeof v);
    glGetIntegerv(pname, v);
    write_query(h, label, FC_Q_INT, clamp_count(count), v, sizeof v[0]);
}

void fc_get_float(fc_h *h, const char *label, GLenum pname, int count)
{
    GLfloat v[FC_MAX_QUERY * 2];
    memset(v, FC_FILL, sizeof v);
    glGetFloatv(pname, v);
    write_query(h, label, FC_Q_FLOAT, clamp_count(count), v, sizeof v[0]);
}

void fc_get_double(fc_h *h, const char *label, GLenum pname, int count)
{
    GLdouble v[FC_MAX_QUERY * 2];
    memset(v, FC_FILL, sizeof v);
    glGetDoublev(pname, v);
    write_query(h, label, FC_Q_DOUBLE, clamp_count(count), v, sizeof v[0]);
}

void fc_get_boolean(fc_h *h, const char *label, GLenum pname, int count)
{
    GLboolean v[FC_MAX_QUERY * 2];
    memset(v, FC_FILL, sizeof v);
    glGetBooleanv(pname, v);
    write_query(h, label, FC_Q_BOOL, clamp_count(count), v, sizeof v[0]);
}

void fc_is_enabled(fc_h *h, const char *label, GLenum cap)
{
    GLboolean v = glIsEnabled(cap);
    write_query(h, label, FC_Q_BOOL, 1, &v, sizeof v);
}

void fc_blob(fc_h *h, const char *label, const void *data, size_t size)
{
    fc_rec_write(h->out, FC_REC_BLOB, label, data, size, NULL, 0, NULL, 0);
}

void fc_value(fc_h *h, const char *label, long long value)
{
    int64_t v = value;
    fc_rec_write(h->out, FC_REC_VALUE, label, &v, sizeof v, NULL, 0, NULL, 0);
}

void fc_documented_difference(fc_h *h, const char *label, const char *reason)
{
    fc_rec_write(h->out, FC_REC_DOCUMENTED, label, reason, strlen(reason), NULL, 0, NULL, 0);
}

void fc_pixel_store(fc_h *h, GLint pname, GLint value)
{
    OSMesaPixelStore(pname, value);
    if (pname == OSMESA_Y_UP)
        h->y_up = value != 0;
}

OSMesaContext fc_context(fc_h *h) { return h->ctx; }
void *fc_buffer(fc_h *h) { return h->buf; }
const fc_case *fc_this_case(fc_h *h) { return h->c; }

void fc_pixel_ortho(fc_h *h)
{
    glViewport(0, 0, h->c->width, h->c->height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, h->c->width, 0, h->c->height, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void fc_run_case(const fc_case *c, FILE *out, int perturb)
{
    fc_h h = { c, NULL, NULL, NULL, c->row_length > c->width ? c->row_length : c->width,
               1, 0, perturb, out };
    size_t size = (size_t)h.row_length * (size_t)c->height * (size_t)fc_format_bpp(c->format);
    GLenum format = c->format;
    void *target;
    char msg[160] = "";
    int32_t status = FC_END_OK;
    GLboolean made = GL_FALSE;

    fc_rec_write(out, FC_REC_CASE, c->name, NULL, 0, NULL, 0, NULL, 0);
    if (c->draws_nothing) {
        int32_t how = c->draws_nothing;
        fc_rec_write(out, FC_REC_DRAWS_NOTHING, "draws nothing", &how, sizeof how, NULL, 0, NULL, 0);
    }
    h.buf = malloc(size ? size : 1);
    memset(h.buf, FC_FILL, size ? size : 1);
    target = h.buf;
#ifdef FC_ORACLE
    if (format == OSMESA_RGB && !c->raw_oracle_rgb) {
        size_t n = (size_t)h.row_length * (size_t)c->height * 4;
        h.shadow = malloc(n ? n : 1);
        memset(h.shadow, FC_FILL, n ? n : 1);
        format = OSMESA_RGBA;
        target = h.shadow;
    }
#endif
    h.ctx = OSMesaCreateContextExt(format, c->depth_bits, c->stencil_bits, 0, NULL);
    fc_value(&h, "OSMesaCreateContextExt != NULL", h.ctx != NULL);
    if (h.ctx) {
        made = OSMesaMakeCurrent(h.ctx, target, GL_UNSIGNED_BYTE, c->width, c->height);
        fc_value(&h, "OSMesaMakeCurrent", made);
    }
    if (made) {
        c->fn(&h);
        fc_error(&h, "final glGetError");
        if (h.frames != c->frames) {
            status = FC_END_HARNESS;
            snprintf(msg, sizeof msg, "case captured %d frames, its table entry says %d",
                     h.frames, c->frames);
        }
    }
    /* The oracle's OSMesaDestroyContext crashes when vertices are still
     * queued (a glBegin/glEnd with nothing flushed since): flush first. */
    if (made && OSMesaGetCurrentContext())
        glFinish();
    if (h.ctx)
        OSMesaDestroyContext(h.ctx);
    free(h.buf);
    free(h.shadow);
    fc_rec_write(out, FC_REC_END, c->name, &status, sizeof status, msg, strlen(msg), NULL, 0);
}
