/* fc_record.c - writer and reader of the renderer record stream (see fc_record.h). */
#include "fc_record.h"

#include <string.h>

int fc_rec_write(FILE *f, uint32_t kind, const char *label,
                 const void *p1, uint64_t n1, const void *p2, uint64_t n2,
                 const void *p3, uint64_t n3)
{
    uint32_t head[2] = { kind, (uint32_t)(label ? strlen(label) : 0) };
    uint64_t total = n1 + n2 + n3;
    int ok = fwrite(head, sizeof head, 1, f) == 1 &&
             fwrite(&total, sizeof total, 1, f) == 1 &&
             (head[1] == 0 || fwrite(label, head[1], 1, f) == 1) &&
             (n1 == 0 || fwrite(p1, (size_t)n1, 1, f) == 1) &&
             (n2 == 0 || fwrite(p2, (size_t)n2, 1, f) == 1) &&
             (n3 == 0 || fwrite(p3, (size_t)n3, 1, f) == 1);
    return fflush(f) == 0 && ok;
}

int fc_rec_next(const unsigned char *buf, size_t len, size_t *pos, struct fc_rec *out)
{
    uint32_t head[2];
    uint64_t plen;
    size_t p = *pos;

    if (len - p < sizeof head + sizeof plen)
        return 0;
    memcpy(head, buf + p, sizeof head);
    memcpy(&plen, buf + p + sizeof head, sizeof plen);
    p += sizeof head + sizeof plen;
    if (head[1] > len - p || plen > len - p - head[1])
        return 0;
    out->kind = head[0];
    out->label = (const char *)buf + p;
    out->label_len = head[1];
    out->payload = buf + p + head[1];
    out->payload_len = plen;
    *pos = p + head[1] + (size_t)plen;
    return 1;
}

int fc_frame_parse(const struct fc_rec *r, struct fc_frame_hdr *hdr,
                   const unsigned char **color, uint64_t *color_len,
                   const unsigned char **depth, uint64_t *depth_len)
{
    int32_t v[FC_FRAME_HDR_FIELDS];
    uint64_t cl, dl;

    if (r->kind != FC_REC_FRAME || r->payload_len < sizeof v)
        return 0;
    memcpy(v, r->payload, sizeof v);
    hdr->width = v[0]; hdr->height = v[1]; hdr->row_length = v[2];
    hdr->format = v[3]; hdr->bpp = v[4]; hdr->y_up = v[5];
    hdr->depth_ok = v[6]; hdr->depth_w = v[7]; hdr->depth_h = v[8];
    hdr->depth_bpv = v[9];
    if (hdr->width < 0 || hdr->height < 0 || hdr->row_length < 0 || hdr->bpp < 0 ||
        hdr->depth_w < 0 || hdr->depth_h < 0 || hdr->depth_bpv < 0)
        return 0;
    cl = (uint64_t)hdr->row_length * (uint64_t)hdr->height * (uint64_t)hdr->bpp;
    dl = hdr->depth_ok ? (uint64_t)hdr->depth_w * (uint64_t)hdr->depth_h * (uint64_t)hdr->depth_bpv : 0;
    if (r->payload_len != sizeof v + cl + dl)
        return 0;
    *color = r->payload + sizeof v;
    *color_len = cl;
    *depth = r->payload + sizeof v + cl;
    *depth_len = dl;
    return 1;
}

int fc_rec_label_is(const struct fc_rec *r, const char *s)
{
    size_t n = strlen(s);
    return n == r->label_len && memcmp(r->label, s, n) == 0;
}
