/* fc_compare.c - oracle vs fixgl comparison of one case (see fc_compare.h). */
#include "fc_compare.h"

#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fc_result_note(struct fc_case_result *res, const char *fmt, ...)
{
    va_list ap;
    if (res->nnotes >= FC_MAX_NOTES) {
        res->dropped_notes++;
        return;
    }
    va_start(ap, fmt);
    vsnprintf(res->notes[res->nnotes++], FC_NOTE_LEN, fmt, ap);
    va_end(ap);
}

void fc_result_free(struct fc_case_result *res)
{
    free(res->documented);
    res->documented = NULL;
    res->ndocumented = 0;
}

const char *fc_result_status(const struct fc_case_result *res)
{
    if (res->crashed)
        return "error";
    if (res->pixels_beyond || res->depth_mismatches || res->error_mismatches ||
        res->query_mismatches || res->blob_mismatches || res->value_mismatches ||
        res->structure_mismatches)
        return "differs";
    /* colours within a reference case's tolerance (fc_case.h) */
    if (res->mismatched_pixels && res->tolerance <= 0)
        return "differs";
    if (res->blank)
        return "blank";
    return res->mismatched_pixels ? "agrees" : "exact";
}

int fc_status_passes(const char *status)
{
    return strcmp(status, "exact") == 0 || strcmp(status, "agrees") == 0;
}

static uint64_t umax(uint64_t a, uint64_t b) { return a > b ? a : b; }

int fc_frame_blank(const struct fc_frame_view *f)
{
    const struct fc_frame_hdr *h = &f->hdr;
    uint64_t bpp = h->bpp > 0 ? (uint64_t)h->bpp : 0, row = (uint64_t)(h->row_length > 0 ? h->row_length : 0);
    uint64_t w = (uint64_t)(h->width > 0 ? h->width : 0), hh = (uint64_t)(h->height > 0 ? h->height : 0);
    uint64_t dbpv = h->depth_bpv > 0 ? (uint64_t)h->depth_bpv : 0;

    if (bpp && w && hh && row >= w && f->color_len >= row * hh * bpp)
        for (uint64_t y = 0; y < hh; y++)
            for (uint64_t x = 0; x < w; x++)
                if (memcmp(f->color + (y * row + x) * bpp, f->color, (size_t)bpp) != 0)
                    return 0;
    if (dbpv && f->depth_len >= dbpv)
        for (uint64_t i = dbpv; i + dbpv <= f->depth_len; i += dbpv)
            if (memcmp(f->depth + i, f->depth, (size_t)dbpv) != 0)
                return 0;
    return 1;
}

void fc_compare_frame(const struct fc_frame_view *a, const struct fc_frame_view *b,
                      struct fc_frame_stats *st)
{
    fc_compare_frame_tol(a, b, 0, st);
}

void fc_compare_frame_tol(const struct fc_frame_view *a, const struct fc_frame_view *b,
                          int tolerance, struct fc_frame_stats *st)
{
    const struct fc_frame_hdr *ha = &a->hdr, *hb = &b->hdr;
    uint64_t pa = (uint64_t)ha->row_length * (uint64_t)ha->height;
    uint64_t pb = (uint64_t)hb->row_length * (uint64_t)hb->height;

    memset(st, 0, sizeof *st);
    st->pixels = umax(pa, pb);
    st->depth_values = umax(a->depth_len / (ha->depth_bpv ? (uint64_t)ha->depth_bpv : 1),
                            b->depth_len / (hb->depth_bpv ? (uint64_t)hb->depth_bpv : 1));
    if (ha->width != hb->width || ha->height != hb->height || ha->row_length != hb->row_length ||
        ha->format != hb->format || ha->bpp != hb->bpp) {
        st->layout_differs = 1;
        st->mismatched = st->beyond = st->pixels;
        st->max_diff = 255;
    } else {
        for (uint64_t p = 0; p < pa; p++) {
            const unsigned char *x = a->color + p * (uint64_t)ha->bpp, *y = b->color + p * (uint64_t)ha->bpp;
            int d = 0;
            for (int c = 0; c < ha->bpp; c++) {
                int e = abs((int)x[c] - (int)y[c]);
                d = e > d ? e : d;
            }
            if (d) {
                st->mismatched++;
                st->at_1 += d == 1;
                st->beyond += d > tolerance;
                st->max_diff = d > st->max_diff ? d : st->max_diff;
            }
        }
    }
    if (ha->depth_ok != hb->depth_ok || ha->depth_w != hb->depth_w ||
        ha->depth_h != hb->depth_h || ha->depth_bpv != hb->depth_bpv) {
        st->layout_differs = 1;
        st->depth_mismatches = st->depth_values;
    } else if (ha->depth_bpv) {
        for (uint64_t i = 0; i < st->depth_values; i++)
            if (memcmp(a->depth + i * (uint64_t)ha->depth_bpv, b->depth + i * (uint64_t)ha->depth_bpv,
                       (size_t)ha->depth_bpv) != 0)
                st->depth_mismatches++;
    }
}

static const char *kind_name(uint32_t kind)
{
    switch (kind) {
    case FC_REC_VALUE: return "value";
    case FC_REC_ERROR: return "error";
    case FC_REC_QUERY: return "query";
    case FC_REC_BLOB: return "blob";
    case FC_REC_FRAME: return "frame";
    case FC_REC_DOCUMENTED: return "documented difference";
    case FC_REC_DRAWS_NOTHING: return "draws_nothing";
    default: return "record";
    }
}

/* Next record that takes part in the comparison. */
static int next_rec(const unsigned char *buf, size_t len, size_t *pos, struct fc_rec *r)
{
    while (fc_rec_next(buf, len, pos, r))
        if ((r->kind >= FC_REC_VALUE && r->kind <= FC_REC_FRAME) || r->kind == FC_REC_DOCUMENTED ||
            r->kind == FC_REC_DRAWS_NOTHING)
            return 1;
    return 0;
}

/* Formats up to 16 query values of a payload into out; trailing values
 * the query did not write (all bytes FC_FILL_BYTE) are counted, not shown. */
static void format_query(const struct fc_rec *r, char *out, size_t size)
{
    uint32_t head[2] = { 0, 0 };
    size_t n = 0, esize;
    uint32_t count, unwritten = 0;
    const unsigned char *p = r->payload + sizeof head;
    out[0] = 0;
    if (r->payload_len < sizeof head)
        return;
    memcpy(head, r->payload, sizeof head);
    esize = head[0] == FC_Q_DOUBLE ? 8 : head[0] == FC_Q_BOOL ? 1 : 4;
    count = head[1];
    if (r->payload_len < sizeof head + (uint64_t)count * esize)
        count = (uint32_t)((r->payload_len - sizeof head) / esize);
    while (count > 0) {
        const unsigned char *e = p + (size_t)(count - 1) * esize;
        size_t k = 0;
        while (k < esize && e[k] == FC_FILL_BYTE)
            k++;
        if (k < esize)
            break;
        count--;
        unwritten++;
    }
    n += (size_t)snprintf(out, size, "{");
    for (uint32_t i = 0; i < count && i < 16 && n < size; i++) {
        const char *sep = i ? "," : "";
        if (head[0] == FC_Q_INT) {
            int32_t v; memcpy(&v, p + 4 * i, 4);
            n += (size_t)snprintf(out + n, size - n, "%s%" PRId32, sep, v);
        } else if (head[0] == FC_Q_FLOAT) {
            float v; memcpy(&v, p + 4 * i, 4);
            n += (size_t)snprintf(out + n, size - n, "%s%.9g", sep, (double)v);
        } else if (head[0] == FC_Q_DOUBLE) {
            double v; memcpy(&v, p + 8 * i, 8);
            n += (size_t)snprintf(out + n, size - n, "%s%.17g", sep, v);
        } else {
            n += (size_t)snprintf(out + n, size - n, "%s%u", sep, p[i]);
        }
    }
    if (n < size)
        n += (size_t)snprintf(out + n, size - n, "%s}", count > 16 ? ",..." : "");
    if (unwritten && n < size)
        snprintf(out + n, size - n, " +%" PRIu32 " unwritten", unwritten);
}

/* What a case declared so far: documented differences
 * (fc_documented_difference) and draws_nothing; and its frames. */
#define FC_MAX_DECLARED 64
struct declared {
    struct fc_rec store[FC_MAX_DECLARED];       /* the oracle's declaration records */
    int hits[FC_MAX_DECLARED];
    int n;
    int draws_nothing;
    int frames, blank_frames;                   /* blank: on both sides */
    int first_drawn;                            /* index of the first frame that is not */
};

static int find_declared(const struct declared *d, const struct fc_rec *r)
{
    for (int i = 0; i < d->n; i++)
        if (d->store[i].label_len == r->label_len &&
            memcmp(d->store[i].label, r->label, r->label_len) == 0)
            return i;
    return -1;
}

static void format_blob(const struct fc_rec *r, char *out, size_t size)
{
    size_t n = (size_t)snprintf(out, size, "%" PRIu64 " bytes \"", r->payload_len);
    for (uint64_t i = 0; i < r->payload_len && n + 2 < size; i++) {
        unsigned char ch = r->payload[i];
        out[n++] = ch >= 32 && ch < 127 && ch != '"' ? (char)ch : '.';
    }
    if (n + 2 < size) {
        out[n++] = '"';
        out[n] = 0;
    } else {
        snprintf(out + size - 5, 5, "...\"");
    }
}

/* A differing query/value/blob record pair: allowed and listed when its
 * label was declared a documented difference. */
static int documented(struct declared *d, const struct fc_rec *ra, const struct fc_rec *rb,
                      struct fc_case_result *res)
{
    int i = find_declared(d, ra);
    struct fc_documented *doc;
    if (i < 0)
        return 0;
    d->hits[i]++;
    if (res->ndocumented % 16 == 0) {
        struct fc_documented *m = realloc(res->documented, (size_t)(res->ndocumented + 16) * sizeof *m);
        if (!m)
            return 0;
        res->documented = m;
    }
    doc = &res->documented[res->ndocumented++];
    memset(doc, 0, sizeof *doc);
    snprintf(doc->label, sizeof doc->label, "%.*s", (int)ra->label_len, ra->label);
    snprintf(doc->reason, sizeof doc->reason, "%.*s", (int)d->store[i].payload_len,
             (const char *)d->store[i].payload);
    snprintf(doc->kind, sizeof doc->kind, "%s", kind_name(ra->kind));
    if (ra->kind == FC_REC_QUERY) {
        static const char *const qtype[] = { "query", "query int", "query float",
                                             "query double", "query boolean" };
        uint32_t t = 0;
        if (ra->payload_len >= 4)
            memcpy(&t, ra->payload, 4);
        snprintf(doc->kind, sizeof doc->kind, "%s", qtype[t <= FC_Q_BOOL ? t : 0]);
        format_query(ra, doc->oracle, sizeof doc->oracle);
        format_query(rb, doc->fixgl, sizeof doc->fixgl);
    } else if (ra->kind == FC_REC_VALUE) {
        int64_t va = 0, vb = 0;
        memcpy(&va, ra->payload, ra->payload_len >= 8 ? 8 : 0);
        memcpy(&vb, rb->payload, rb->payload_len >= 8 ? 8 : 0);
        snprintf(doc->oracle, sizeof doc->oracle, "%" PRId64, va);
        snprintf(doc->fixgl, sizeof doc->fixgl, "%" PRId64, vb);
    } else {
        format_blob(ra, doc->oracle, sizeof doc->oracle);
        format_blob(rb, doc->fixgl, sizeof doc->fixgl);
    }
    return 1;
}

static void compare_pair(const struct fc_rec *ra, const struct fc_rec *rb, int *frame,
                         struct fc_case_result *res, fc_frame_cb cb, void *ud, struct declared *d)
{
    int lab = (int)(ra->label_len < 60 ? ra->label_len : 60);
    int same = ra->payload_len == rb->payload_len &&
               memcmp(ra->payload, rb->payload, (size_t)ra->payload_len) == 0;

    if (ra->kind != rb->kind || ra->label_len != rb->label_len ||
        memcmp(ra->label, rb->label, ra->label_len) != 0) {
        res->structure_mismatches++;
        fc_result_note(res, "record order differs: oracle %s \"%.*s\", fixgl %s \"%.*s\"",
                       kind_name(ra->kind), lab, ra->label, kind_name(rb->kind),
                       (int)(rb->label_len < 60 ? rb->label_len : 60), rb->label);
        return;
    }
    switch (ra->kind) {
    case FC_REC_FRAME: {
        struct fc_frame_view a, b;
        struct fc_frame_stats st;
        if (!fc_frame_parse(ra, &a.hdr, &a.color, &a.color_len, &a.depth, &a.depth_len) ||
            !fc_frame_parse(rb, &b.hdr, &b.color, &b.color_len, &b.depth, &b.depth_len)) {
            res->structure_mismatches++;
            fc_result_note(res, "frame %d: malformed frame record", *frame);
            break;
        }
        fc_compare_frame_tol(&a, &b, res->tolerance, &st);
        st.blank = fc_frame_blank(&a) && fc_frame_blank(&b);
        if (st.blank)
            d->blank_frames++;
        else if (d->frames == d->blank_frames)
            d->first_drawn = *frame;
        d->frames++;
        res->frames++;
        res->pixels += st.pixels;
        res->mismatched_pixels += st.mismatched;
        res->pixels_at_1 += st.at_1;
        res->pixels_beyond += st.beyond;
        res->max_channel_diff = st.max_diff > res->max_channel_diff ? st.max_diff : res->max_channel_diff;
        res->depth_values += st.depth_values;
        res->depth_mismatches += st.depth_mismatches;
        if (st.layout_differs)
            fc_result_note(res, "frame %d layout: oracle %dx%d row %d fmt 0x%x depth %d:%dx%dx%d, "
                           "fixgl %dx%d row %d fmt 0x%x depth %d:%dx%dx%d", *frame,
                           a.hdr.width, a.hdr.height, a.hdr.row_length, (unsigned)a.hdr.format,
                           a.hdr.depth_ok, a.hdr.depth_w, a.hdr.depth_h, a.hdr.depth_bpv,
                           b.hdr.width, b.hdr.height, b.hdr.row_length, (unsigned)b.hdr.format,
                           b.hdr.depth_ok, b.hdr.depth_w, b.hdr.depth_h, b.hdr.depth_bpv);
        if (cb)
            cb(ud, *frame, &a, &b, &st);
        ++*frame;
        break;
    }
    case FC_REC_ERROR: {
        uint32_t ea = 0, eb = 0;
        memcpy(&ea, ra->payload, ra->payload_len >= 4 ? 4 : 0);
        memcpy(&eb, rb->payload, rb->payload_len >= 4 ? 4 : 0);
        if (!same) {
            res->error_mismatches++;
            fc_result_note(res, "glGetError \"%.*s\": oracle 0x%04x, fixgl 0x%04x", lab, ra->label, ea, eb);
        }
        break;
    }
    case FC_REC_DOCUMENTED:
        /* same label (checked above) and same reason */
        if (!same) {
            res->structure_mismatches++;
            fc_result_note(res, "documented difference \"%.*s\": the reasons differ", lab, ra->label);
        } else if (find_declared(d, ra) < 0) {
            if (d->n == FC_MAX_DECLARED) {
                res->structure_mismatches++;
                fc_result_note(res, "more than %d documented differences declared", FC_MAX_DECLARED);
            } else {
                d->store[d->n] = *ra;
                d->hits[d->n++] = 0;
            }
        }
        break;
    case FC_REC_DRAWS_NOTHING: {
        int32_t how = 1;
        memcpy(&how, ra->payload, ra->payload_len >= 4 ? 4 : 0);
        if (!same) {
            res->structure_mismatches++;
            fc_result_note(res, "the sides declare draws_nothing differently");
        }
        d->draws_nothing = how;
        break;
    }
    case FC_REC_VALUE: {
        int64_t va = 0, vb = 0;
        memcpy(&va, ra->payload, ra->payload_len >= 8 ? 8 : 0);
        memcpy(&vb, rb->payload, rb->payload_len >= 8 ? 8 : 0);
        if (!same && documented(d, ra, rb, res))
            break;
        if (!same) {
            res->value_mismatches++;
            fc_result_note(res, "value \"%.*s\": oracle %" PRId64 ", fixgl %" PRId64, lab, ra->label, va, vb);
        }
        break;
    }
    case FC_REC_QUERY:
        if (!same && documented(d, ra, rb, res))
            break;
        if (!same) {
            char qa[96], qb[96];
            format_query(ra, qa, sizeof qa);
            format_query(rb, qb, sizeof qb);
            res->query_mismatches++;
            fc_result_note(res, "query \"%.*s\": oracle %s, fixgl %s", lab, ra->label, qa, qb);
        }
        break;
    case FC_REC_BLOB:
        if (!same && documented(d, ra, rb, res))
            break;
        if (!same) {
            uint64_t n = ra->payload_len < rb->payload_len ? ra->payload_len : rb->payload_len, nd = 0, first = n;
            for (uint64_t i = 0; i < n; i++) {
                if (ra->payload[i] != rb->payload[i]) {
                    if (nd == 0)
                        first = i;
                    nd++;
                }
            }
            res->blob_mismatches++;
            if (first < n)
                fc_result_note(res, "blob \"%.*s\": %" PRIu64 " of %" PRIu64 " bytes differ, first at %" PRIu64
                               " (oracle 0x%02x, fixgl 0x%02x)", lab, ra->label, nd, n, first,
                               ra->payload[first], rb->payload[first]);
            else
                fc_result_note(res, "blob \"%.*s\": sizes differ (oracle %" PRIu64 ", fixgl %" PRIu64 ")",
                               lab, ra->label, ra->payload_len, rb->payload_len);
        }
        break;
    default:
        break;
    }
}

void fc_compare_case(const unsigned char *a, size_t alen, const unsigned char *b, size_t blen,
                     struct fc_case_result *res, fc_frame_cb cb, void *ud)
{
    size_t pa = 0, pb = 0;
    struct fc_rec ra, rb;
    int frame = 0;
    struct declared *d = calloc(1, sizeof *d);

    if (!d) {
        res->crashed = 1;
        fc_result_note(res, "out of memory");
        return;
    }

    for (;;) {
        int ha = next_rec(a, alen, &pa, &ra), hb = next_rec(b, blen, &pb, &rb);
        if (!ha && !hb)
            break;
        if (ha && hb) {
            compare_pair(&ra, &rb, &frame, res, cb, ud, d);
            continue;
        }
        res->structure_mismatches++;
        if (ha)
            fc_result_note(res, "only the oracle recorded %s \"%.*s\"", kind_name(ra.kind),
                           (int)(ra.label_len < 60 ? ra.label_len : 60), ra.label);
        else
            fc_result_note(res, "only fixgl recorded %s \"%.*s\"", kind_name(rb.kind),
                           (int)(rb.label_len < 60 ? rb.label_len : 60), rb.label);
    }
    /* A case whose frames all show a cleared buffer on both sides compares
     * no drawing; unless it declares draws_nothing, which is stale when a
     * frame shows something drawn (fc_case.h).  Only meaningful when both
     * sides recorded the whole case. */
    if (!res->crashed && !res->structure_mismatches) {
        if (d->draws_nothing == FC_MAY_DRAW_NOTHING) {
            if (d->frames > 0 && d->blank_frames == d->frames) {
                res->blank_allowed = 1;
                fc_result_note(res, "a generated scene that compares nothing: each of its %d frame%s "
                               "shows a cleared buffer on both sides", d->frames, d->frames > 1 ? "s" : "");
            }
        } else if (!d->draws_nothing && d->frames > 0 && d->blank_frames == d->frames) {
            res->blank = 1;
            fc_result_note(res, "compares nothing: each of the %d frame%s shows a cleared buffer "
                           "(every pixel alike, every depth value alike) on both sides; fix the case, "
                           "or set draws_nothing in its table entry if it draws nothing on purpose",
                           d->frames, d->frames > 1 ? "s" : "");
        } else if (d->draws_nothing && d->blank_frames < d->frames) {
            res->structure_mismatches++;
            fc_result_note(res, "declares draws_nothing, but frame %d shows something drawn: "
                           "remove the declaration", d->first_drawn);
        } else if (d->draws_nothing && d->frames == 0) {
            res->structure_mismatches++;
            fc_result_note(res, "declares draws_nothing, but captures no frame: remove the declaration");
        }
    }
    /* a declaration whose records all compared equal is stale (only
     * meaningful when both sides recorded the whole case) */
    if (!res->crashed && !res->structure_mismatches && !res->self_compare) {
        for (int i = 0; i < d->n; i++) {
            if (d->hits[i] == 0) {
                res->structure_mismatches++;
                fc_result_note(res, "documented difference \"%.*s\" compared equal: remove the declaration",
                               (int)(d->store[i].label_len < 60 ? d->store[i].label_len : 60),
                               d->store[i].label);
            }
        }
    }
    free(d);
}
