/* fc_image.c - frame display conversion and heat maps (see fc_image.h). */
#include "fc_image.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

/* OSMesa format enums (from <GL/osmesa.h>; the runner is GL-free). */
#define FMT_BGRA 0x1
#define FMT_ARGB 0x2
#define FMT_RGB 0x1907
#define FMT_RGBA 0x1908
#define FMT_BGR 0x4

int fc_image_width(const struct fc_frame_view *f) { return f->hdr.row_length; }
int fc_image_height(const struct fc_frame_view *f) { return f->hdr.height; }

/* Byte offsets of R, G, B inside a pixel. */
static void channel_offsets(int format, int off[3])
{
    switch (format) {
    case FMT_BGRA: case FMT_BGR: off[0] = 2; off[1] = 1; off[2] = 0; break;
    case FMT_ARGB: off[0] = 1; off[1] = 2; off[2] = 3; break;
    default: off[0] = 0; off[1] = 1; off[2] = 2; break;
    }
}

/* Source row of display row y. */
static int src_row(const struct fc_frame_hdr *h, int y)
{
    return h->y_up ? h->height - 1 - y : y;
}

void fc_image_color(const struct fc_frame_view *f, unsigned char *rgb)
{
    const struct fc_frame_hdr *h = &f->hdr;
    int off[3];
    channel_offsets(h->format, off);
    for (int y = 0; y < h->height; y++) {
        const unsigned char *row = f->color + (size_t)src_row(h, y) * (size_t)h->row_length * (size_t)h->bpp;
        for (int x = 0; x < h->row_length; x++, rgb += 3)
            for (int c = 0; c < 3; c++)
                rgb[c] = h->bpp >= 3 ? row[(size_t)x * (size_t)h->bpp + (size_t)off[c]] : 0;
    }
}

void fc_heat_color(double d, double range, unsigned char out[3])
{
    double t = range > 1 ? log2(d) / log2(range) : 1.0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    if (t < 0.5) {              /* yellow -> red */
        out[0] = 255;
        out[1] = (unsigned char)lround(255.0 * (1.0 - 2.0 * t));
        out[2] = 0;
    } else {                    /* red -> magenta */
        out[0] = 255;
        out[1] = 0;
        out[2] = (unsigned char)lround(255.0 * (2.0 * t - 1.0));
    }
}

void fc_image_heatmap(const struct fc_frame_view *oracle, const struct fc_frame_view *fixgl,
                      unsigned char *rgb)
{
    const struct fc_frame_hdr *h = &oracle->hdr;
    int off[3];
    channel_offsets(h->format, off);
    for (int y = 0; y < h->height; y++) {
        size_t base = (size_t)src_row(h, y) * (size_t)h->row_length * (size_t)h->bpp;
        for (int x = 0; x < h->row_length; x++, rgb += 3) {
            const unsigned char *a = oracle->color + base + (size_t)x * (size_t)h->bpp;
            const unsigned char *b = fixgl->color + base + (size_t)x * (size_t)h->bpp;
            int d = 0;
            for (int c = 0; c < h->bpp; c++) {
                int e = a[c] > b[c] ? a[c] - b[c] : b[c] - a[c];
                d = e > d ? e : d;
            }
            if (d) {
                fc_heat_color(d, 255, rgb);
            } else {
                int lum = h->bpp >= 3 ? (a[off[0]] * 3 + a[off[1]] * 6 + a[off[2]]) / 10 : 0;
                rgb[0] = rgb[1] = rgb[2] = (unsigned char)(lum / 4);
            }
        }
    }
}

static uint32_t depth_at(const unsigned char *p, int bpv)
{
    uint16_t s;
    uint32_t v;
    if (bpv == 2) {
        memcpy(&s, p, 2);
        return s;
    }
    memcpy(&v, p, 4);
    return v;
}

void fc_image_depth_heatmap(const struct fc_frame_view *oracle, const struct fc_frame_view *fixgl,
                            unsigned char *rgb)
{
    const struct fc_frame_hdr *h = &oracle->hdr;
    int bpv = h->depth_bpv;
    double full = bpv == 2 ? 65535.0 : 16777215.0;   /* Z16, or Z24 in the low bits */
    for (int y = 0; y < h->depth_h; y++) {
        size_t row = (size_t)(h->depth_h - 1 - y) * (size_t)h->depth_w;
        for (int x = 0; x < h->depth_w; x++, rgb += 3) {
            size_t i = (row + (size_t)x) * (size_t)bpv;
            uint32_t a = depth_at(oracle->depth + i, bpv), b = depth_at(fixgl->depth + i, bpv);
            if (a != b) {
                fc_heat_color((double)(a > b ? a - b : b - a), 16777215.0, rgb);
            } else {
                rgb[0] = rgb[1] = rgb[2] = (unsigned char)(96.0 * (double)(bpv == 2 ? a : a & 0xFFFFFFu) / full);
            }
        }
    }
}
