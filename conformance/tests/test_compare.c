/* test_compare.c - unit test of the comparison, heat map and report code on
 * synthetic frames with known differences.  argv[1]: scratch report dir. */
#include "fc_compare.h"
#include "fc_image.h"
#include "fc_png.h"
#include "fc_record.h"
#include "fc_report.h"

#define FIXGL_TRICKY "fixgl-v \"q\" \\ \t \x01 a/b"

#include <json-c/json.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 8
#define H 4
#define FMT_RGBA 0x1908
#define FMT_BGRA 0x1

static int failures;

#define CHECK(cond) do { if (!(cond)) { fprintf(stderr, "%s:%d: CHECK failed: %s\n", \
                                                 __FILE__, __LINE__, #cond); failures++; } } while (0)

struct stream { char *buf; size_t len; FILE *f; };

static void open_stream(struct stream *s)
{
    s->buf = NULL;
    s->len = 0;
    s->f = open_memstream(&s->buf, &s->len);
}

/* A W x H frame: colour from (x, y, c), depth from (x, y). */
static void write_frame(FILE *f, int format, int width, const unsigned char *color,
                        const unsigned int *depth)
{
    int32_t hdr[FC_FRAME_HDR_FIELDS] = { width, H, width, format, 4, 1, 1, width, H, 4 };
    fc_rec_write(f, FC_REC_FRAME, "frame", hdr, sizeof hdr, color, (uint64_t)width * H * 4,
                 depth, (uint64_t)width * H * 4);
}

static void base_images(unsigned char *color, unsigned int *depth)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            unsigned char *p = color + 4 * (y * W + x);
            p[0] = (unsigned char)(30 * x);
            p[1] = (unsigned char)(60 * y);
            p[2] = 100;
            p[3] = 255;
            depth[y * W + x] = (unsigned int)(0x10000 * (x + 1) + y);
        }
}

static void write_common(FILE *f, uint32_t err, int32_t q, const char *blob, int64_t value)
{
    uint32_t qh[2] = { FC_Q_INT, 1 };
    fc_rec_write(f, FC_REC_CASE, "unit/case", NULL, 0, NULL, 0, NULL, 0);
    fc_rec_write(f, FC_REC_ERROR, "err", &err, sizeof err, NULL, 0, NULL, 0);
    fc_rec_write(f, FC_REC_QUERY, "GL_X", qh, sizeof qh, &q, sizeof q, NULL, 0);
    fc_rec_write(f, FC_REC_BLOB, "blob", blob, strlen(blob), NULL, 0, NULL, 0);
    fc_rec_write(f, FC_REC_VALUE, "value", &value, sizeof value, NULL, 0, NULL, 0);
}

static void end_case(FILE *f)
{
    int32_t st = FC_END_OK;
    fc_rec_write(f, FC_REC_END, "unit/case", &st, sizeof st, NULL, 0, NULL, 0);
    fclose(f);
}

/* Reads one pixel of a report PNG. */
static int png_pixel(const char *dir, const char *name, int x, int y, unsigned char out[3])
{
    char path[1024];
    int w, h, ch;
    unsigned char *px;
    snprintf(path, sizeof path, "%s/img/%s", dir, name);
    if (!fc_png_read(path, &w, &h, &ch, &px))
        return 0;
    if (x >= w || y >= h || ch != 3) {
        free(px);
        return 0;
    }
    memcpy(out, px + 3 * (y * w + x), 3);
    free(px);
    return 1;
}

static char *slurp(const char *dir, const char *name)
{
    char path[1024];
    FILE *f;
    char *buf = calloc(1, 1 << 20);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "r");
    if (f) {
        size_t n = fread(buf, 1, (1 << 20) - 1, f);
        buf[n] = 0;
        fclose(f);
    }
    return buf;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "report-unit";
    unsigned char ca[W * H * 4], cb[W * H * 4];
    unsigned int da[W * H], db[W * H];
    struct stream a, b;
    struct fc_case_result res;
    struct fc_report *rep = fc_report_open(dir);
    struct fc_report_entry *e;
    unsigned char px[3], heat[3];
    char *json, *html;

    CHECK(rep != NULL);
    if (!rep)
        return 1;
    base_images(ca, da);
    base_images(cb, db);
    cb[4 * (1 * W + 2) + 1] += 5;               /* pixel (2,1): G +5 */
    cb[4 * (3 * W + 7) + 3] -= 200;             /* pixel (7,3): A -200 */
    db[0] += 1; db[5] ^= 0x100; db[31] = 0;     /* three depth values */

    /* 1. known differences */
    open_stream(&a);
    open_stream(&b);
    write_common(a.f, 0x0500, 7, "abcdef", 1);
    write_common(b.f, 0x0000, 7, "abXdeY", 1);
    write_frame(a.f, FMT_RGBA, W, ca, da);
    write_frame(b.f, FMT_RGBA, W, cb, db);
    end_case(a.f);
    end_case(b.f);
    memset(&res, 0, sizeof res);
    e = fc_report_begin_case(rep, "unit/case", "unit core", NULL);
    fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)b.buf, b.len, &res, fc_report_frame, e);
    CHECK(strcmp(fc_report_end_case(e, &res), "differs") == 0);
    CHECK(res.frames == 1);
    CHECK(res.pixels == W * H);
    CHECK(res.mismatched_pixels == 2);
    CHECK(res.max_channel_diff == 200);
    CHECK(res.depth_mismatches == 3);
    CHECK(res.depth_values == W * H);
    CHECK(res.error_mismatches == 1);
    CHECK(res.query_mismatches == 0);
    CHECK(res.blob_mismatches == 1);
    CHECK(res.value_mismatches == 0);
    CHECK(res.structure_mismatches == 0);
    CHECK(res.nnotes == 2);
    CHECK(strstr(res.notes[0], "oracle 0x0500, fixgl 0x0000") != NULL);
    CHECK(strstr(res.notes[1], "2 of 6 bytes differ, first at 2") != NULL);

    /* heat map: y_up, so buffer row 1 is display row H-2 */
    fc_heat_color(5, 255, heat);
    CHECK(png_pixel(dir, "unit_case-f0-diff.png", 2, H - 2, px) && memcmp(px, heat, 3) == 0);
    fc_heat_color(200, 255, heat);
    CHECK(png_pixel(dir, "unit_case-f0-diff.png", 7, 0, px) && memcmp(px, heat, 3) == 0);
    CHECK(png_pixel(dir, "unit_case-f0-diff.png", 0, H - 1, px) && px[0] == px[1] && px[1] == px[2] &&
          px[0] == (0 * 3 + 0 * 6 + 100) / 10 / 4);
    /* oracle and fixgl images, the right way up */
    CHECK(png_pixel(dir, "unit_case-f0-oracle.png", 3, H - 1, px) && px[0] == 90 && px[1] == 0 && px[2] == 100);
    CHECK(png_pixel(dir, "unit_case-f0-fixgl.png", 2, H - 2, px) && px[1] == 65);
    /* depth heat map: value 5 = (5,0) differs, (6,0) does not */
    CHECK(png_pixel(dir, "unit_case-f0-depthdiff.png", 5, H - 1, px) && px[0] == 255);
    CHECK(png_pixel(dir, "unit_case-f0-depthdiff.png", 6, H - 1, px) && px[0] == px[1]);

    /* 2. identical records are exact */
    memset(&res, 0, sizeof res);
    e = fc_report_begin_case(rep, "unit/same", "unit", "--seed 3 --index 4");
    fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)a.buf, a.len, &res, fc_report_frame, e);
    CHECK(strcmp(fc_report_end_case(e, &res), "exact") == 0);
    CHECK(res.mismatched_pixels == 0 && res.depth_mismatches == 0 && res.nnotes == 0);
    free(a.buf);
    free(b.buf);

    /* 3. different layouts and a missing record */
    open_stream(&a);
    open_stream(&b);
    write_common(a.f, 0, 1, "x", 1);
    write_common(b.f, 0, 2, "x", 0);
    write_frame(a.f, FMT_RGBA, W, ca, da);
    write_frame(b.f, FMT_BGRA, W, ca, da);
    write_frame(a.f, FMT_RGBA, W, ca, da);
    end_case(a.f);
    end_case(b.f);
    memset(&res, 0, sizeof res);
    e = fc_report_begin_case(rep, "unit/layout", "unit", NULL);
    fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)b.buf, b.len, &res, fc_report_frame, e);
    CHECK(strcmp(fc_report_end_case(e, &res), "differs") == 0);
    CHECK(res.mismatched_pixels == W * H && res.max_channel_diff == 255);
    CHECK(res.query_mismatches == 1 && res.value_mismatches == 1);
    CHECK(res.structure_mismatches == 1);
    free(a.buf);
    free(b.buf);

    /* 4. a crashed side is an error */
    memset(&res, 0, sizeof res);
    res.crashed = 1;
    e = fc_report_begin_case(rep, "unit/crash", "unit", NULL);
    fc_compare_case(NULL, 0, NULL, 0, &res, fc_report_frame, e);
    CHECK(strcmp(fc_report_end_case(e, &res), "error") == 0);

    /* 6. documented differences: a declared label may differ (listed with
     * its reason and values), an undeclared one may not; errors are never
     * allowed; a declaration whose records all compare equal is stale;
     * declarations must match on both sides */
    {
        static const char why[] = "implementation string";
        uint32_t qh[2] = { FC_Q_INT, 1 };
        int32_t qa = 1, qb = 2;
        int64_t va = 5, vb = 6;
        uint32_t ea = 0x500, eb = 0;
        open_stream(&a);
        open_stream(&b);
        for (int side = 0; side < 2; side++) {
            FILE *f = side ? b.f : a.f;
            fc_rec_write(f, FC_REC_CASE, "unit/doc", NULL, 0, NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_DOCUMENTED, "GL_VENDOR", why, strlen(why), NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_DOCUMENTED, "limit", why, strlen(why), NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_DOCUMENTED, "stale", why, strlen(why), NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_BLOB, "GL_VENDOR", side ? "fixgl" : "Mesa", side ? 5 : 4,
                         NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_QUERY, "limit", qh, sizeof qh, side ? &qb : &qa, 4, NULL, 0);
            fc_rec_write(f, FC_REC_QUERY, "limit", qh, sizeof qh, &qa, 4, NULL, 0);
            fc_rec_write(f, FC_REC_VALUE, "stale", &va, 8, NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_VALUE, "other", side ? &vb : &va, 8, NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_ERROR, "limit", side ? &eb : &ea, 4, NULL, 0, NULL, 0);
            end_case(f);
        }
        memset(&res, 0, sizeof res);
        e = fc_report_begin_case(rep, "unit/doc", "unit", NULL);
        fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)b.buf, b.len, &res, fc_report_frame, e);
        CHECK(res.ndocumented == 2);
        CHECK(res.ndocumented == 2 && strcmp(res.documented[0].label, "GL_VENDOR") == 0 &&
              strcmp(res.documented[0].reason, why) == 0 &&
              strstr(res.documented[0].oracle, "Mesa") && strstr(res.documented[0].fixgl, "fixgl"));
        CHECK(res.ndocumented == 2 && strcmp(res.documented[1].oracle, "{1}") == 0 &&
              strcmp(res.documented[1].fixgl, "{2}") == 0);
        CHECK(res.query_mismatches == 0 && res.blob_mismatches == 0);
        CHECK(res.value_mismatches == 1);       /* "other" */
        CHECK(res.error_mismatches == 1);       /* errors are never documented */
        CHECK(res.structure_mismatches == 1);   /* "stale" compared equal */
        CHECK(strcmp(fc_report_end_case(e, &res), "differs") == 0);
        free(a.buf);
        free(b.buf);

        /* only documented differences: exact; a stale declaration differs */
        open_stream(&a);
        open_stream(&b);
        for (int side = 0; side < 2; side++) {
            FILE *f = side ? b.f : a.f;
            fc_rec_write(f, FC_REC_CASE, "unit/doc2", NULL, 0, NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_DOCUMENTED, "limit", why, strlen(why), NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_DOCUMENTED, "stale", why, strlen(why), NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_QUERY, "limit", qh, sizeof qh, side ? &qb : &qa, 4, NULL, 0);
            fc_rec_write(f, FC_REC_VALUE, "stale", &va, 8, NULL, 0, NULL, 0);
            end_case(f);
        }
        memset(&res, 0, sizeof res);
        e = fc_report_begin_case(rep, "unit/doc_stale", "unit", NULL);
        fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)b.buf, b.len, &res, fc_report_frame, e);
        CHECK(res.ndocumented == 1 && res.structure_mismatches == 1);
        CHECK(res.nnotes == 1 && strstr(res.notes[0], "\"stale\" compared equal") != NULL);
        CHECK(strcmp(fc_report_end_case(e, &res), "differs") == 0);
        /* the same renderer on both sides: no stale check */
        memset(&res, 0, sizeof res);
        res.self_compare = 1;
        e = fc_report_begin_case(rep, "unit/doc_self", "unit", NULL);
        fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)a.buf, a.len, &res, fc_report_frame, e);
        CHECK(res.ndocumented == 0 && res.structure_mismatches == 0);
        CHECK(strcmp(fc_report_end_case(e, &res), "exact") == 0);
        free(a.buf);
        free(b.buf);

        /* the stale declaration removed: exact, the difference listed */
        open_stream(&a);
        open_stream(&b);
        for (int side = 0; side < 2; side++) {
            FILE *f = side ? b.f : a.f;
            fc_rec_write(f, FC_REC_CASE, "unit/doc3", NULL, 0, NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_DOCUMENTED, "limit", why, strlen(why), NULL, 0, NULL, 0);
            fc_rec_write(f, FC_REC_QUERY, "limit", qh, sizeof qh, side ? &qb : &qa, 4, NULL, 0);
            end_case(f);
        }
        memset(&res, 0, sizeof res);
        e = fc_report_begin_case(rep, "unit/doc_ok", "unit", NULL);
        fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)b.buf, b.len, &res, fc_report_frame, e);
        CHECK(res.ndocumented == 1 && res.structure_mismatches == 0 && res.nnotes == 0);
        CHECK(strcmp(fc_report_end_case(e, &res), "exact") == 0);
        free(a.buf);
        free(b.buf);

        /* different reasons on the two sides: a structure mismatch */
        open_stream(&a);
        open_stream(&b);
        fc_rec_write(a.f, FC_REC_CASE, "unit/doc4", NULL, 0, NULL, 0, NULL, 0);
        fc_rec_write(b.f, FC_REC_CASE, "unit/doc4", NULL, 0, NULL, 0, NULL, 0);
        fc_rec_write(a.f, FC_REC_DOCUMENTED, "limit", why, strlen(why), NULL, 0, NULL, 0);
        fc_rec_write(b.f, FC_REC_DOCUMENTED, "limit", "other", 5, NULL, 0, NULL, 0);
        end_case(a.f);
        end_case(b.f);
        memset(&res, 0, sizeof res);
        fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)b.buf, b.len, &res, NULL, NULL);
        CHECK(res.structure_mismatches == 1);
        fc_result_free(&res);
        free(a.buf);
        free(b.buf);
    }

    /* 7. reference cases (fc_case.h tolerance_lsb): with a tolerance of 1,
     * a channel 1 off agrees, a channel 2 off differs; depth stays exact;
     * the same frames without a tolerance differ; the agreement section
     * of summary.json sums them per tag */
    {
        unsigned char c1[W * H * 4], c2[W * H * 4];
        unsigned int d1[W * H];
        struct { const char *name; const unsigned char *fix; int tol, depth; const char *status; } t[] = {
            { "unit/tol_1", c1, 1, 0, "agrees" },
            { "unit/tol_2", c2, 1, 0, "differs" },
            { "unit/tol_0", c1, 0, 0, "differs" },
            { "unit/tol_depth", c1, 1, 1, "differs" },
            { "unit/tol_same", ca, 1, 0, "exact" },
        };
        memcpy(c1, ca, sizeof c1);
        memcpy(c2, ca, sizeof c2);
        memcpy(d1, da, sizeof d1);
        c1[4 * 5 + 0] += 1;                     /* pixel (5,0): R +1 */
        c1[4 * 9 + 2] -= 1;                     /* pixel (1,1): B -1 */
        c2[4 * 5 + 0] += 1;
        c2[4 * 9 + 2] -= 2;                     /* B -2: beyond 1 LSB */
        d1[3] += 1;
        for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
            open_stream(&a);
            open_stream(&b);
            write_common(a.f, 0, 1, "x", 1);
            write_common(b.f, 0, 1, "x", 1);
            write_frame(a.f, FMT_RGBA, W, ca, da);
            write_frame(b.f, FMT_RGBA, W, t[i].fix, t[i].depth ? d1 : da);
            end_case(a.f);
            end_case(b.f);
            memset(&res, 0, sizeof res);
            res.tolerance = t[i].tol;
            e = fc_report_begin_case(rep, t[i].name, t[i].tol ? "unit reference phong" : "unit", NULL);
            fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)b.buf, b.len, &res,
                            fc_report_frame, e);
            CHECK(strcmp(fc_report_end_case(e, &res), t[i].status) == 0);
            CHECK(fc_status_passes(t[i].status) == (strcmp(t[i].status, "differs") != 0));
            if (t[i].fix != ca) {
                CHECK(res.mismatched_pixels == 2);
                CHECK(res.pixels_at_1 == (t[i].fix == c1 ? 2u : 1u));
                CHECK(res.pixels_beyond == (t[i].tol == 0 ? 2u : t[i].fix == c1 ? 0u : 1u));
                CHECK(res.max_channel_diff == (t[i].fix == c1 ? 1 : 2));
            }
            free(a.buf);
            free(b.buf);
        }
    }

    /* 5. BGRA display conversion */
    {
        struct fc_frame_view v;
        unsigned char rgb[W * H * 3];
        memset(&v, 0, sizeof v);
        v.hdr.width = v.hdr.row_length = W;
        v.hdr.height = H;
        v.hdr.format = FMT_BGRA;
        v.hdr.bpp = 4;
        v.hdr.y_up = 0;
        v.color = ca;
        fc_image_color(&v, rgb);
        CHECK(rgb[3 * 3 + 0] == 100 && rgb[3 * 3 + 2] == 90);  /* (3,0): B<->R swapped */
    }

    /* 9. cases that compare nothing (fc_case.h draws_nothing): frames of a
     * cleared buffer on both sides make a case "blank" unless it declares
     * FC_DRAWS_NOTHING; a declaration with a drawn frame (or no frame) is
     * stale; a generated scene (FC_MAY_DRAW_NOTHING) is counted, not failed;
     * the padding of a row longer than the width does not count */
    {
        unsigned char flat[W * H * 4], padded[(W + 2) * H * 4], drawn[W * H * 4];
        unsigned int zflat[W * H];
        struct { const char *name; int declare; int frames; int drawn; int row; const char *status;
                 int allowed; } t[] = {
            { "unit/blank", 0, 2, 0, W, "blank", 0 },
            { "unit/blank_declared", FC_DRAWS_NOTHING, 2, 0, W, "exact", 0 },
            { "unit/blank_stale", FC_DRAWS_NOTHING, 2, 1, W, "differs", 0 },
            { "unit/blank_no_frame", FC_DRAWS_NOTHING, 0, 0, W, "differs", 0 },
            { "unit/drawn", 0, 2, 1, W, "exact", 0 },
            { "unit/no_frame", 0, 0, 0, W, "exact", 0 },
            { "unit/generated_blank", FC_MAY_DRAW_NOTHING, 1, 0, W, "exact", 1 },
            { "unit/generated_drawn", FC_MAY_DRAW_NOTHING, 1, 1, W, "exact", 0 },
            { "unit/blank_padded_rows", 0, 1, 0, W + 2, "blank", 0 },
        };
        for (size_t i = 0; i < sizeof padded / 4; i++) {
            int pad = (int)(i % (W + 2)) >= W;
            padded[4 * i + 0] = pad ? 0xCD : 10;
            padded[4 * i + 1] = 20, padded[4 * i + 2] = 30, padded[4 * i + 3] = 40;
        }
        for (size_t i = 0; i < sizeof flat / 4; i++)
            flat[4 * i + 0] = 10, flat[4 * i + 1] = 20, flat[4 * i + 2] = 30, flat[4 * i + 3] = 40;
        for (int i = 0; i < W * H; i++)
            zflat[i] = 0xffffff;
        memcpy(drawn, flat, sizeof drawn);
        drawn[4 * 9 + 1] = 21;                  /* one pixel drawn */
        for (size_t k = 0; k < sizeof t / sizeof t[0]; k++) {
            int32_t how = t[k].declare;
            open_stream(&a);
            open_stream(&b);
            for (int side = 0; side < 2; side++) {
                FILE *f = side ? b.f : a.f;
                fc_rec_write(f, FC_REC_CASE, t[k].name, NULL, 0, NULL, 0, NULL, 0);
                if (how)
                    fc_rec_write(f, FC_REC_DRAWS_NOTHING, "draws nothing", &how, sizeof how,
                                 NULL, 0, NULL, 0);
                for (int fr = 0; fr < t[k].frames; fr++) {
                    int32_t hdr[FC_FRAME_HDR_FIELDS] = { W, H, t[k].row, FMT_RGBA, 4, 1, 1, W, H, 4 };
                    const unsigned char *c = t[k].drawn && fr == 1 % t[k].frames ? drawn : flat;
                    if (t[k].row != W)          /* padding bytes that differ */
                        c = padded;
                    fc_rec_write(f, FC_REC_FRAME, "frame", hdr, sizeof hdr, c,
                                 (uint64_t)t[k].row * H * 4, zflat, sizeof zflat);
                }
                end_case(f);
            }
            memset(&res, 0, sizeof res);
            fc_compare_case((unsigned char *)a.buf, a.len, (unsigned char *)b.buf, b.len, &res, NULL, NULL);
            if (strcmp(fc_result_status(&res), t[k].status) != 0 || res.blank_allowed != t[k].allowed) {
                fprintf(stderr, "%s: status %s (expected %s), blank_allowed %d\n", t[k].name,
                        fc_result_status(&res), t[k].status, res.blank_allowed);
                failures++;
            }
            CHECK(!fc_status_passes("blank"));
            fc_result_free(&res);
            free(a.buf);
            free(b.buf);
        }
    }

    /* a version string that needs escaping: quotes, a backslash, a tab,
     * a control character, a slash */
    fc_report_set_renderers(rep, "oracle-r", "oracle-v", "fixgl-r", FIXGL_TRICKY);
    CHECK(fc_report_finish(rep) == 8);      /* + tol_2, tol_0, tol_depth */
    json = slurp(dir, "summary.json");
    {   /* valid JSON (json-c parses it back) of the same shape */
        json_object *root = json_tokener_parse(json), *v, *cases, *c0, *tags;
        CHECK(root != NULL);
        CHECK(root && json_object_object_get_ex(root, "fixgl_version", &v) &&
              strcmp(json_object_get_string(v), FIXGL_TRICKY) == 0);
        CHECK(root && json_object_object_get_ex(root, "cases", &cases) &&
              json_object_is_type(cases, json_type_array) && json_object_array_length(cases) >= 10);
        c0 = root && cases ? json_object_array_get_idx(cases, 0) : NULL;
        CHECK(c0 && json_object_object_get_ex(c0, "name", &v) &&
              strcmp(json_object_get_string(v), "unit/case") == 0);
        CHECK(c0 && json_object_object_get_ex(c0, "tags", &tags) && json_object_array_length(tags) == 2);
        CHECK(c0 && json_object_object_get_ex(c0, "pixels", &v) && json_object_get_int64(v) == 32);
        CHECK(root && json_object_object_get_ex(root, "agreement", &v) &&
              json_object_is_type(v, json_type_object));
        json_object_put(root);
    }
    html = slurp(dir, "index.html");
    CHECK(strstr(json, "\"oracle\": \"oracle-r oracle-v\"") != NULL);
    CHECK(strstr(json, "{ \"name\": \"unit/case\", \"tags\": [ \"unit\", \"core\" ], \"frames\": 1, \"pixels\": 32, "
                       "\"mismatched_pixels\": 2, \"max_channel_diff\": 200, \"depth_mismatches\": 3, "
                       "\"error_mismatches\": 1") != NULL);
    CHECK(strstr(json, "\"name\": \"unit/same\"") && strstr(json, "\"status\": \"exact\", \"replay\": \"--seed 3 --index 4\""));
    CHECK(strstr(json, "\"status\": \"error\"") != NULL);
    CHECK(strstr(html, "img/unit_case-f0-diff.png") != NULL);
    CHECK(strstr(html, "oracle 0x0500, fixgl 0x0000") != NULL);
    CHECK(strstr(html, "img/unit_same") == NULL);
    CHECK(strstr(json, "\"name\": \"unit/doc_ok\"") != NULL &&
          strstr(json, "\"documented_differences\": [ { \"label\": \"limit\", \"kind\": \"query int\", "
                       "\"reason\": \"implementation string\", \"oracle\": \"{1}\", \"fixgl\": \"{2}\" } ]") != NULL);
    CHECK(strstr(html, "Documented differences (4)") != NULL);
    CHECK(strstr(json, "\"name\": \"unit/tol_1\"") &&
          strstr(json, "\"status\": \"agrees\", \"tolerance_lsb\": 1, \"pixels_at_1\": 2, "
                       "\"pixels_beyond_1\": 0, \"pixels_beyond_tolerance\": 0"));
    /* tol_1, tol_2, tol_depth, tol_same: 4 cases, 1 bit-exact, 1 agrees */
    CHECK(strstr(json, "\"phong\": { \"cases\": 4, \"bit_exact_cases\": 1, \"agreeing_cases\": 1, "
                       "\"differing_cases\": 2, \"error_cases\": 0, \"tolerance_lsb\": 1, \"max_lsb\": 2, "
                       "\"pixels_compared\": 128, \"pixels_exact\": 122, \"pixels_at_1_lsb\": 5, "
                       "\"pixels_beyond_1_lsb\": 1, \"pixels_beyond_tolerance\": 1, \"depth_mismatches\": 1 }") != NULL);
    CHECK(strstr(html, "Agreement of the reference cases") != NULL);
    CHECK(strstr(html, "img/unit_tol_1-f0-diff.png") != NULL);
    free(json);
    free(html);
    if (failures)
        fprintf(stderr, "%d check(s) failed\n", failures);
    else
        printf("comparison/report unit test passed; report: %s/index.html\n", dir);
    return failures != 0;
}
