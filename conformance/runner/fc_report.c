/* fc_report.c - HTML/JSON report and summary table (see fc_report.h). */
#include "fc_report.h"
#include "fc_image.h"
#include "fc_png.h"

#include <dirent.h>
#include <errno.h>
#include <inttypes.h>
#include <json-c/json.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define MAX_FRAME_IMAGES 8

struct frame_images {
    int index;
    struct fc_frame_stats st;
    int w, h, dw, dh;
    int has_heat, has_depth;
};

struct fc_report_entry {
    struct fc_report *report;
    char *name, *tags, *replay, *file_stem;
    struct fc_case_result res;
    const char *status;
    char *known_reason;         /* the known-differences entry, or NULL */
    int nframes;
    struct frame_images frames[MAX_FRAME_IMAGES];
};

struct fc_report {
    char *dir;
    char *renderer[2], *version[2];
    char *known_file;           /* --known, or NULL */
    struct fc_report_entry **entries;
    size_t n, cap;
};

static char *dup_str(const char *s)
{
    size_t n = strlen(s ? s : "") + 1;
    char *d = malloc(n);
    memcpy(d, s ? s : "", n);
    return d;
}

static int make_dir(const char *path)
{
    char *p = dup_str(path);
    for (char *s = p + 1; *s; s++) {
        if (*s == '/') {
            *s = 0;
            if (mkdir(p, 0777) != 0 && errno != EEXIST) {
                free(p);
                return 0;
            }
            *s = '/';
        }
    }
    int ok = mkdir(p, 0777) == 0 || errno == EEXIST;
    free(p);
    return ok;
}

static char *path_join(const char *a, const char *b)
{
    size_t n = strlen(a) + strlen(b) + 2;
    char *p = malloc(n);
    snprintf(p, n, "%s/%s", a, b);
    return p;
}

struct fc_report *fc_report_open(const char *dir)
{
    struct fc_report *r;
    char *img = path_join(dir, "img");
    DIR *d;
    struct dirent *de;

    if (!make_dir(img)) {
        fprintf(stderr, "fixgl-conform: cannot create %s: %s\n", img, strerror(errno));
        free(img);
        return NULL;
    }
    if ((d = opendir(img)) != NULL) {
        while ((de = readdir(d)) != NULL) {
            size_t n = strlen(de->d_name);
            if (n > 4 && strcmp(de->d_name + n - 4, ".png") == 0) {
                char *f = path_join(img, de->d_name);
                remove(f);
                free(f);
            }
        }
        closedir(d);
    }
    free(img);
    r = calloc(1, sizeof *r);
    r->dir = dup_str(dir);
    return r;
}

void fc_report_set_renderers(struct fc_report *r, const char *oracle_renderer,
                             const char *oracle_version, const char *fixgl_renderer,
                             const char *fixgl_version)
{
    const char *s[4] = { oracle_renderer, oracle_version, fixgl_renderer, fixgl_version };
    for (int i = 0; i < 2; i++) {
        free(r->renderer[i]);
        free(r->version[i]);
        r->renderer[i] = dup_str(s[2 * i]);
        r->version[i] = dup_str(s[2 * i + 1]);
    }
}

void fc_report_set_known_file(struct fc_report *r, const char *path)
{
    free(r->known_file);
    r->known_file = path ? dup_str(path) : NULL;
}

void fc_report_set_known(struct fc_report_entry *e, const char *reason)
{
    free(e->known_reason);
    e->known_reason = reason ? dup_str(reason) : NULL;
}

struct fc_report_entry *fc_report_begin_case(struct fc_report *r, const char *name,
                                             const char *tags, const char *replay)
{
    struct fc_report_entry *e = calloc(1, sizeof *e);
    e->report = r;
    e->name = dup_str(name);
    e->tags = dup_str(tags);
    e->replay = replay ? dup_str(replay) : NULL;
    e->file_stem = dup_str(name);
    for (char *s = e->file_stem; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') ||
              *s == '-' || *s == '_'))
            *s = '_';
    if (r->n == r->cap) {
        r->cap = r->cap ? 2 * r->cap : 256;
        r->entries = realloc(r->entries, r->cap * sizeof *r->entries);
    }
    r->entries[r->n++] = e;
    return e;
}

/* img/<stem>-f<index>-<what>.png, relative to the report directory. */
static void image_name(const struct fc_report_entry *e, int index, const char *what,
                       char *out, size_t size)
{
    snprintf(out, size, "img/%s-f%d-%s.png", e->file_stem, index, what);
}

static void write_png(const struct fc_report_entry *e, int index, const char *what,
                      int w, int h, const unsigned char *rgb)
{
    char rel[512];
    char *path;
    image_name(e, index, what, rel, sizeof rel);
    path = path_join(e->report->dir, rel);
    fc_png_write(path, w, h, 3, rgb);
    free(path);
}

void fc_report_frame(void *entry, int index, const struct fc_frame_view *oracle,
                     const struct fc_frame_view *fixgl, const struct fc_frame_stats *st)
{
    struct fc_report_entry *e = entry;
    struct frame_images *fi;
    unsigned char *rgb;
    int w, h;

    if ((!st->mismatched && !st->depth_mismatches) || e->nframes >= MAX_FRAME_IMAGES)
        return;
    fi = &e->frames[e->nframes++];
    memset(fi, 0, sizeof *fi);
    fi->index = index;
    fi->st = *st;
    w = fi->w = fc_image_width(oracle);
    h = fi->h = fc_image_height(oracle);
    rgb = malloc((size_t)w * (size_t)h * 3 + 1);
    if (w > 0 && h > 0) {
        fc_image_color(oracle, rgb);
        write_png(e, index, "oracle", w, h, rgb);
        if (!st->layout_differs) {
            fc_image_heatmap(oracle, fixgl, rgb);
            write_png(e, index, "diff", w, h, rgb);
            fi->has_heat = 1;
        }
    }
    free(rgb);
    if (fc_image_width(fixgl) > 0 && fc_image_height(fixgl) > 0) {
        rgb = malloc((size_t)fc_image_width(fixgl) * (size_t)fc_image_height(fixgl) * 3);
        fc_image_color(fixgl, rgb);
        write_png(e, index, "fixgl", fc_image_width(fixgl), fc_image_height(fixgl), rgb);
        free(rgb);
    }
    if (st->depth_mismatches && !st->layout_differs && oracle->hdr.depth_w > 0 && oracle->hdr.depth_h > 0) {
        fi->dw = oracle->hdr.depth_w;
        fi->dh = oracle->hdr.depth_h;
        rgb = malloc((size_t)fi->dw * (size_t)fi->dh * 3);
        fc_image_depth_heatmap(oracle, fixgl, rgb);
        write_png(e, index, "depthdiff", fi->dw, fi->dh, rgb);
        free(rgb);
        fi->has_depth = 1;
    }
}

const char *fc_report_end_case(struct fc_report_entry *e, const struct fc_case_result *res)
{
    e->res = *res;
    e->status = fc_result_status(res);
    return e->status;
}

/* ---- agreement of the reference cases --------------------------------- */

/* Per tag of the cases with a colour tolerance (fc_case.h: the reference
 * cases, drawn on the oracle by a GLSL program), how close fixgl comes. */
struct agreement {
    char tag[48];
    int cases, exact, agrees, differs, error, tolerance;
    int max_lsb;
    uint64_t pixels, mismatched, at_1, beyond_1, beyond_tolerance, depth_mismatches;
};

#define MAX_AGREEMENT 16

static size_t collect_agreement(const struct fc_report *r, struct agreement *a, size_t max)
{
    size_t na = 0;
    memset(a, 0, max * sizeof *a);
    for (size_t i = 0; i < r->n; i++) {
        const struct fc_report_entry *e = r->entries[i];
        const struct fc_case_result *c = &e->res;
        if (c->tolerance <= 0)
            continue;
        for (const char *s = e->tags; *s;) {
            size_t k = strcspn(s, " "), j;
            for (j = 0; j < na; j++)
                if (strlen(a[j].tag) == k && strncmp(a[j].tag, s, k) == 0)
                    break;
            if (j == na && na < max && k > 0 && k < sizeof a[0].tag)
                memcpy(a[na++].tag, s, k);
            if (j < na) {
                struct agreement *g = &a[j];
                g->cases++;
                if (strcmp(e->status, "exact") == 0) g->exact++;
                else if (strcmp(e->status, "agrees") == 0) g->agrees++;
                else if (strcmp(e->status, "differs") == 0) g->differs++;
                else g->error++;
                g->tolerance = c->tolerance > g->tolerance ? c->tolerance : g->tolerance;
                g->max_lsb = c->max_channel_diff > g->max_lsb ? c->max_channel_diff : g->max_lsb;
                g->pixels += c->pixels;
                g->mismatched += c->mismatched_pixels;
                g->at_1 += c->pixels_at_1;
                g->beyond_1 += c->mismatched_pixels - c->pixels_at_1;
                g->beyond_tolerance += c->pixels_beyond;
                g->depth_mismatches += c->depth_mismatches;
            }
            s += k;
            s += strspn(s, " ");
        }
    }
    return na;
}

static void print_agreement(const struct fc_report *r, FILE *out)
{
    struct agreement a[MAX_AGREEMENT];
    size_t na = collect_agreement(r, a, MAX_AGREEMENT);
    if (!na)
        return;
    fprintf(out, "\nagreement of the reference cases (fixgl against the GLSL reference on the oracle):\n"
            "%-16s %6s %6s %6s %7s %7s %10s %9s %9s %8s\n", "tag", "cases", "exact", "agrees",
            "differs", "max LSB", "pixels", "at 1 LSB", "beyond 1", "depth");
    for (size_t j = 0; j < na; j++)
        fprintf(out, "%-16s %6d %6d %6d %7d %7d %10" PRIu64 " %9" PRIu64 " %9" PRIu64 " %8" PRIu64 "\n",
                a[j].tag, a[j].cases, a[j].exact, a[j].agrees, a[j].differs + a[j].error, a[j].max_lsb,
                a[j].pixels, a[j].at_1, a[j].beyond_1, a[j].depth_mismatches);
}

/* ---- summary table ---------------------------------------------------- */

struct tag_count {
    char tag[48];
    int cases, exact, agrees, differs, blank, error;
    int blank_allowed;          /* generated scenes that compare nothing */
};

static int has_tag_word(const char *tags, const char *tag, size_t n)
{
    for (const char *s = tags; *s;) {
        size_t k = strcspn(s, " ");
        if (k == n && strncmp(s, tag, n) == 0)
            return 1;
        s += k;
        s += strspn(s, " ");
    }
    return 0;
}

static void count_into(struct tag_count *t, const struct fc_report_entry *e)
{
    t->cases++;
    t->blank_allowed += e->res.blank_allowed;
    if (strcmp(e->status, "exact") == 0) t->exact++;
    else if (strcmp(e->status, "agrees") == 0) t->agrees++;
    else if (strcmp(e->status, "differs") == 0) t->differs++;
    else if (strcmp(e->status, "blank") == 0) t->blank++;
    else t->error++;
}

/* Distinct tags in first-seen order (at most max). */
static size_t collect_tags(const struct fc_report *r, struct tag_count *t, size_t max)
{
    size_t nt = 0;
    memset(t, 0, max * sizeof *t);
    for (size_t i = 0; i < r->n; i++) {
        for (const char *s = r->entries[i]->tags; *s;) {
            size_t k = strcspn(s, " "), j;
            for (j = 0; j < nt; j++)
                if (strlen(t[j].tag) == k && strncmp(t[j].tag, s, k) == 0)
                    break;
            if (j == nt && nt < max && k > 0 && k < sizeof t[0].tag) {
                memcpy(t[nt].tag, s, k);
                nt++;
            }
            s += k;
            s += strspn(s, " ");
        }
    }
    for (size_t j = 0; j < nt; j++)
        for (size_t i = 0; i < r->n; i++)
            if (has_tag_word(r->entries[i]->tags, t[j].tag, strlen(t[j].tag)))
                count_into(&t[j], r->entries[i]);
    return nt;
}

/* Per random family (the part of the name before '/'), the generated
 * scenes that compare nothing (FC_MAY_DRAW_NOTHING, fc_case.h); returns
 * the number of families of at least FC_BLANK_MIN_SCENES scenes of which
 * more than FC_BLANK_MAX_PERCENT % compare nothing. */
static int print_blank_allowed(const struct fc_report *r, FILE *out)
{
    struct { char family[32]; int scenes, blank; } f[16];
    size_t nf = 0;
    int over = 0;
    for (size_t i = 0; i < r->n; i++) {
        const struct fc_report_entry *e = r->entries[i];
        size_t k = strcspn(e->name, "/"), j;
        if (!e->replay || k >= sizeof f[0].family)     /* generated scenes have a replay line */
            continue;
        for (j = 0; j < nf; j++)
            if (strlen(f[j].family) == k && strncmp(f[j].family, e->name, k) == 0)
                break;
        if (j == nf) {
            if (nf == sizeof f / sizeof f[0])
                continue;
            memset(&f[nf], 0, sizeof f[nf]);
            memcpy(f[nf++].family, e->name, k);
        }
        f[j].scenes++;
        f[j].blank += e->res.blank_allowed;
    }
    for (size_t j = 0; j < nf; j++) {
        const int bound = strcmp(f[j].family, "random-tex") == 0 ? FC_BLANK_MAX_PERCENT_TEX
                                                                 : FC_BLANK_MAX_PERCENT;
        const int bad = f[j].scenes >= FC_BLANK_MIN_SCENES && 100 * f[j].blank > bound * f[j].scenes;
        over += bad;
        fprintf(out, "%s: %d of %d generated scenes compare nothing (every frame a cleared buffer; "
                "%s %d%%)\n", f[j].family, f[j].blank, f[j].scenes,
                bad ? "the family fails: more than" : "allowed up to", bound);
    }
    return over;
}

int fc_report_print_summary(const struct fc_report *r, FILE *out)
{
    struct tag_count t[64], total;
    size_t nt = collect_tags(r, t, 64);
    uint64_t px = 0, mism = 0, dmism = 0;
    int ndoc = 0, ndoc_cases = 0;

    memset(&total, 0, sizeof total);
    for (size_t i = 0; i < r->n; i++) {
        count_into(&total, r->entries[i]);
        ndoc += r->entries[i]->res.ndocumented;
        ndoc_cases += r->entries[i]->res.ndocumented > 0;
        px += r->entries[i]->res.pixels;
        mism += r->entries[i]->res.mismatched_pixels;
        dmism += r->entries[i]->res.depth_mismatches;
    }
    fprintf(out, "\n%-16s %7s %7s %7s %7s %7s %7s\n", "tag", "cases", "exact", "agrees", "differs",
            "blank", "error");
    for (size_t j = 0; j < nt; j++)
        fprintf(out, "%-16s %7d %7d %7d %7d %7d %7d\n", t[j].tag, t[j].cases, t[j].exact, t[j].agrees,
                t[j].differs, t[j].blank, t[j].error);
    fprintf(out, "%-16s %7d %7d %7d %7d %7d %7d\n", "TOTAL", total.cases, total.exact, total.agrees,
            total.differs, total.blank, total.error);
    if (total.blank)
        fprintf(out, "blank cases: %d compare nothing (every frame a cleared buffer on both sides, "
                "no draws_nothing declaration): they fail like differences\n", total.blank);
    const int blank_over = print_blank_allowed(r, out);
    fprintf(out, "mismatched pixels: %" PRIu64 " of %" PRIu64 "; depth mismatches: %" PRIu64 "\n",
            mism, px, dmism);
    if (ndoc)
        fprintf(out, "documented differences: %d records in %d cases (listed in the report)\n",
                ndoc, ndoc_cases);
    print_agreement(r, out);
    fprintf(out, "oracle: %s | %s\n", r->renderer[0] ? r->renderer[0] : "?", r->version[0] ? r->version[0] : "?");
    fprintf(out, "fixgl:  %s | %s\n", r->renderer[1] ? r->renderer[1] : "?", r->version[1] ? r->version[1] : "?");
    return blank_over;
}

/* ---- files ------------------------------------------------------------ */

static void html_str(FILE *f, const char *s)
{
    for (; *s; s++) {
        switch (*s) {
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '&': fputs("&amp;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
    }
}

/* summary.json is built as a json-c tree and written by json-c (escaping
 * included): one line, ", " and ": " between members (SPACED), slashes
 * as they are. */
static void jadd_str(json_object *o, const char *key, const char *s)
{
    json_object_object_add(o, key, json_object_new_string(s ? s : ""));
}

static void jadd_int(json_object *o, const char *key, int64_t v)
{
    json_object_object_add(o, key, json_object_new_int64(v));
}

static void jadd_u64(json_object *o, const char *key, uint64_t v)
{
    json_object_object_add(o, key, json_object_new_uint64(v));
}

/* The space-separated tags as a JSON array of strings. */
static json_object *json_tags(const char *tags)
{
    json_object *a = json_object_new_array();
    for (const char *s = tags; *s;) {
        size_t k = strcspn(s, " ");
        if (k) {
            char buf[64];
            snprintf(buf, sizeof buf, "%.*s", (int)(k < 63 ? k : 63), s);
            json_object_array_add(a, json_object_new_string(buf));
        }
        s += k;
        s += strspn(s, " ");
    }
    return a;
}

static json_object *json_case(const struct fc_report_entry *e)
{
    const struct fc_case_result *c = &e->res;
    json_object *o = json_object_new_object();
    jadd_str(o, "name", e->name);
    json_object_object_add(o, "tags", json_tags(e->tags));
    jadd_int(o, "frames", c->frames);
    jadd_u64(o, "pixels", c->pixels);
    jadd_u64(o, "mismatched_pixels", c->mismatched_pixels);
    jadd_int(o, "max_channel_diff", c->max_channel_diff);
    jadd_u64(o, "depth_mismatches", c->depth_mismatches);
    jadd_int(o, "error_mismatches", c->error_mismatches);
    jadd_int(o, "query_mismatches", c->query_mismatches);
    jadd_int(o, "blob_mismatches", c->blob_mismatches);
    jadd_int(o, "value_mismatches", c->value_mismatches);
    jadd_int(o, "structure_mismatches", c->structure_mismatches);
    json_object_object_add(o, "blank", json_object_new_boolean(c->blank));
    json_object_object_add(o, "blank_allowed", json_object_new_boolean(c->blank_allowed));
    jadd_str(o, "status", e->status);
    if (c->tolerance) {
        jadd_int(o, "tolerance_lsb", c->tolerance);
        jadd_u64(o, "pixels_at_1", c->pixels_at_1);
        jadd_u64(o, "pixels_beyond_1", c->mismatched_pixels - c->pixels_at_1);
        jadd_u64(o, "pixels_beyond_tolerance", c->pixels_beyond);
    }
    if (e->replay)
        jadd_str(o, "replay", e->replay);
    if (c->ndocumented) {
        json_object *docs = json_object_new_array();
        for (int k = 0; k < c->ndocumented; k++) {
            const struct fc_documented *d = &c->documented[k];
            json_object *doc = json_object_new_object();
            jadd_str(doc, "label", d->label);
            jadd_str(doc, "kind", d->kind);
            jadd_str(doc, "reason", d->reason);
            jadd_str(doc, "oracle", d->oracle);
            jadd_str(doc, "fixgl", d->fixgl);
            json_object_array_add(docs, doc);
        }
        json_object_object_add(o, "documented_differences", docs);
    }
    return o;
}

static int write_json(const struct fc_report *r)
{
    char *path = path_join(r->dir, "summary.json");
    char oracle[512];
    json_object *root = json_object_new_object(), *cases = json_object_new_array();
    snprintf(oracle, sizeof oracle, "%s %s", r->renderer[0] ? r->renderer[0] : "",
             r->version[0] ? r->version[0] : "");
    jadd_str(root, "oracle", oracle);
    jadd_str(root, "oracle_renderer", r->renderer[0]);
    jadd_str(root, "oracle_version", r->version[0]);
    jadd_str(root, "fixgl_renderer", r->renderer[1]);
    jadd_str(root, "fixgl_version", r->version[1]);
    for (size_t i = 0; i < r->n; i++)
        json_object_array_add(cases, json_case(r->entries[i]));
    json_object_object_add(root, "cases", cases);
    {
        struct agreement a[MAX_AGREEMENT];
        size_t na = collect_agreement(r, a, MAX_AGREEMENT);
        json_object *agreement = json_object_new_object();
        /* per tag of the reference cases: how close fixgl comes to the
         * GLSL reference (max LSB, pixels at 1 LSB and beyond) */
        for (size_t j = 0; j < na; j++) {
            json_object *t = json_object_new_object();
            jadd_int(t, "cases", a[j].cases);
            jadd_int(t, "bit_exact_cases", a[j].exact);
            jadd_int(t, "agreeing_cases", a[j].agrees);
            jadd_int(t, "differing_cases", a[j].differs);
            jadd_int(t, "error_cases", a[j].error);
            jadd_int(t, "tolerance_lsb", a[j].tolerance);
            jadd_int(t, "max_lsb", a[j].max_lsb);
            jadd_u64(t, "pixels_compared", a[j].pixels);
            jadd_u64(t, "pixels_exact", a[j].pixels - a[j].mismatched);
            jadd_u64(t, "pixels_at_1_lsb", a[j].at_1);
            jadd_u64(t, "pixels_beyond_1_lsb", a[j].beyond_1);
            jadd_u64(t, "pixels_beyond_tolerance", a[j].beyond_tolerance);
            jadd_u64(t, "depth_mismatches", a[j].depth_mismatches);
            json_object_object_add(agreement, a[j].tag, t);
        }
        json_object_object_add(root, "agreement", agreement);
    }
    int ok = json_object_to_file_ext(path, root, JSON_C_TO_STRING_SPACED | JSON_C_TO_STRING_NOSLASHESCAPE) == 0;
    json_object_put(root);
    free(path);
    return ok;
}

static void html_image(FILE *f, const struct fc_report_entry *e, int index, const char *what,
                       const char *caption, int w, int h)
{
    char rel[512];
    int scale = w > 0 && h > 0 ? 256 / (w > h ? w : h) : 1;
    scale = scale < 1 ? 1 : scale > 8 ? 8 : scale;
    image_name(e, index, what, rel, sizeof rel);
    fprintf(f, "<figure><img src=\"%s\" width=\"%d\" height=\"%d\"><figcaption>%s</figcaption></figure>\n",
            rel, w * scale, h * scale, caption);
}

static const char *known_name(const struct fc_report *r)
{
    const char *slash = r->known_file ? strrchr(r->known_file, '/') : NULL;
    return slash ? slash + 1 : r->known_file ? r->known_file : "known-differences.txt";
}

/* Why a case that does not pass differs: its reason in the list of known
 * differences, or "unlisted" (red).  A listed case that passes says it
 * should leave the list.  long_form: a paragraph of the case's section,
 * else a cell of the table of all cases. */
static void html_reason(FILE *f, const struct fc_report_entry *e, int long_form)
{
    const int passes = fc_status_passes(e->status);
    if (passes && !e->known_reason)
        return;
    if (long_form)
        fputs("<p class=\"reason\">", f);
    if (passes) {
        fputs("<span class=\"unlisted\">listed in ", f);
        html_str(f, known_name(e->report));
        fputs(" but passes: remove it from the list</span>", f);
    } else if (!e->known_reason) {
        fputs("<span class=\"unlisted\">unlisted</span>", f);
        if (long_form) {
            fputs(": not in ", f);
            html_str(f, known_name(e->report));
            fputs(e->report->known_file ? "" : " (the run was given no --known list)", f);
        }
    } else {
        if (long_form) {
            fputs("known difference (", f);
            html_str(f, known_name(e->report));
            fputs("): ", f);
        }
        html_str(f, e->known_reason[0] ? e->known_reason : "(listed without a reason)");
    }
    if (long_form)
        fputs("</p>\n", f);
}

/* Anchors of the summary's links: the first row of each tag in the table
 * of all cases holds an anchor tag-TAG; #tag-TAG:STATUS filters by both. */
static void html_tag_link(FILE *f, const char *tag, const char *status, const char *text)
{
    fputs("<a href=\"#tag-", f);
    html_str(f, tag);
    if (status)
        fprintf(f, ":%s", status);
    fputs("\">", f);
    html_str(f, text);
    fputs("</a>", f);
}

static void html_count(FILE *f, const char *tag, const char *status, int n, const char *cls)
{
    char num[16];
    snprintf(num, sizeof num, "%d", n);
    fprintf(f, "<td%s%s%s>", cls && n ? " class=\"" : "", cls && n ? cls : "", cls && n ? "\"" : "");
    if (n)
        html_tag_link(f, tag, status, num);
    else
        fputs("0", f);
    fputs("</td>", f);
}

/* The filter of the table of all cases: by tag and status, from the
 * controls or from the address's #tag-TAG[:STATUS] (the summary's links);
 * plain JavaScript, in the page. */
static const char filter_script[] =
    "<script>\n"
    "function fcFilter() {\n"
    "  var tag = document.getElementById('filter-tag').value;\n"
    "  var st = document.getElementById('filter-status').value, shown = 0;\n"
    "  var rows = document.querySelectorAll('#all-cases tr[data-status]');\n"
    "  for (var i = 0; i < rows.length; i++) {\n"
    "    var r = rows[i], tags = ' ' + r.getAttribute('data-tags') + ' ';\n"
    "    var s = r.getAttribute('data-status'), u = r.getAttribute('data-known') === 'unlisted';\n"
    "    var ok = (!tag || tags.indexOf(' ' + tag + ' ') >= 0) &&\n"
    "             (!st || s === st || (st === 'not-passing' && s !== 'exact' && s !== 'agrees') ||\n"
    "              (st === 'unlisted' && u));\n"
    "    r.style.display = ok ? '' : 'none';\n"
    "    shown += ok ? 1 : 0;\n"
    "  }\n"
    "  document.getElementById('filter-count').textContent = shown + ' of ' + rows.length + ' cases shown';\n"
    "}\n"
    "function fcFromHash() {\n"
    "  var m = /^#tag-([^:]*)(?::(.*))?$/.exec(decodeURIComponent(location.hash));\n"
    "  if (!m) return;\n"
    "  document.getElementById('filter-tag').value = m[1];\n"
    "  document.getElementById('filter-status').value = m[2] || '';\n"
    "  fcFilter();\n"
    "  document.getElementById('all-cases').scrollIntoView();\n"
    "}\n"
    "window.addEventListener('hashchange', fcFromHash);\n"
    "fcFromHash();\n"
    "fcFilter();\n"
    "</script>\n";

static void html_case(FILE *f, const struct fc_report_entry *e)
{
    const struct fc_case_result *c = &e->res;
    fprintf(f, "<section id=\"");
    html_str(f, e->file_stem);
    fprintf(f, "\"><h2 class=\"%s\">", e->status);
    html_str(f, e->name);
    fprintf(f, " &mdash; %s</h2>\n", e->status);
    html_reason(f, e, 1);
    fputs("<p>tags: ", f);
    html_str(f, e->tags);
    fprintf(f, "<br>frames %d, pixels %" PRIu64 ", <b>mismatched pixels %" PRIu64 "</b>, max channel diff %d, "
            "depth mismatches %" PRIu64 " of %" PRIu64 ", error mismatches %d, query mismatches %d, "
            "blob mismatches %d, value mismatches %d, record-structure mismatches %d</p>\n",
            c->frames, c->pixels, c->mismatched_pixels, c->max_channel_diff, c->depth_mismatches,
            c->depth_values, c->error_mismatches, c->query_mismatches, c->blob_mismatches,
            c->value_mismatches, c->structure_mismatches);
    if (c->tolerance)
        fprintf(f, "<p>reference case, tolerance %d LSB: %" PRIu64 " pixels at 1 LSB, %" PRIu64
                " beyond 1 LSB, %" PRIu64 " beyond the tolerance</p>\n", c->tolerance, c->pixels_at_1,
                c->mismatched_pixels - c->pixels_at_1, c->pixels_beyond);
    fputs("<p>replay: <code>fixgl-conform ", f);
    if (e->replay) {
        html_str(f, e->replay);
    } else {
        fputs("--case ", f);
        html_str(f, e->name);
    }
    fputs("</code></p>\n", f);
    if (c->nnotes) {
        fputs("<ul class=\"notes\">\n", f);
        for (int i = 0; i < c->nnotes; i++) {
            fputs("<li>", f);
            html_str(f, c->notes[i]);
            fputs("</li>\n", f);
        }
        if (c->dropped_notes)
            fprintf(f, "<li>... %d more</li>\n", c->dropped_notes);
        fputs("</ul>\n", f);
    }
    for (int i = 0; i < e->nframes; i++) {
        const struct frame_images *fi = &e->frames[i];
        fprintf(f, "<div class=\"frame\"><p>frame %d: %" PRIu64 " of %" PRIu64 " pixels differ, max diff %d, "
                "depth %" PRIu64 " of %" PRIu64 "%s</p>\n", fi->index, fi->st.mismatched, fi->st.pixels,
                fi->st.max_diff, fi->st.depth_mismatches, fi->st.depth_values,
                fi->st.layout_differs ? " (layout differs)" : "");
        html_image(f, e, fi->index, "oracle", "oracle", fi->w, fi->h);
        html_image(f, e, fi->index, "fixgl", "fixgl", fi->w, fi->h);
        if (fi->has_heat)
            html_image(f, e, fi->index, "diff", "colour diff", fi->w, fi->h);
        if (fi->has_depth)
            html_image(f, e, fi->index, "depthdiff", "depth diff", fi->dw, fi->dh);
        fputs("</div>\n", f);
    }
    fputs("</section>\n", f);
}

static int write_html(const struct fc_report *r)
{
    char *path = path_join(r->dir, "index.html");
    FILE *f = fopen(path, "w");
    struct tag_count t[64];
    size_t nt = collect_tags(r, t, 64);
    free(path);
    if (!f)
        return 0;
    fputs("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>fixgl conformance</title>\n"
          "<style>body{font-family:sans-serif;margin:1em 2em}img{image-rendering:pixelated;"
          "border:1px solid #888;background:#222}figure{display:inline-block;margin:0 1em 1em 0}"
          "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 8px;text-align:right}"
          "td:first-child{text-align:left}.differs{color:#b60}.error{color:#c00}.exact{color:#080}"
          ".agrees{color:#06a}.blank{color:#a0a}.unlisted{color:#d00;font-weight:bold}"
          ".reason{font-style:italic}td.reason{text-align:left;font-size:smaller}"
          "section{border-top:1px solid #ccc}.notes{font-family:monospace}</style></head><body>\n"
          "<h1>fixgl conformance report</h1>\n<p>oracle: <b>", f);
    html_str(f, r->renderer[0] ? r->renderer[0] : "?");
    fputs(" &mdash; ", f);
    html_str(f, r->version[0] ? r->version[0] : "?");
    fputs("</b><br>fixgl: ", f);
    html_str(f, r->renderer[1] ? r->renderer[1] : "?");
    fputs(" &mdash; ", f);
    html_str(f, r->version[1] ? r->version[1] : "?");
    fputs("</p>\n<p>Heat maps: matching pixels are the oracle image dimmed; differing pixels go from "
          "yellow (difference 1) through red to magenta (255), log scale. Depth heat maps use a "
          "24-bit scale.</p>\n", f);
    fputs("<p>Known differences: ", f);
    if (r->known_file)
        html_str(f, r->known_file);
    else
        fputs("none given (--known)", f);
    fputs("; a case that does not pass shows its reason from that list, or "
          "<span class=\"unlisted\">unlisted</span>. Each tag and count links to the tag's rows "
          "in the <a href=\"#all-cases\">table of all cases</a>.</p>\n"
          "<table id=\"summary\"><tr><th>tag</th><th>cases</th><th>exact</th><th>agrees</th>"
          "<th>differs</th><th>blank</th><th>error</th><th>unlisted</th><th>blank, allowed</th></tr>\n", f);
    for (size_t j = 0; j < nt; j++) {
        int unlisted = 0;
        for (size_t i = 0; i < r->n; i++)
            unlisted += !fc_status_passes(r->entries[i]->status) && !r->entries[i]->known_reason &&
                        has_tag_word(r->entries[i]->tags, t[j].tag, strlen(t[j].tag));
        fputs("<tr><td>", f);
        html_tag_link(f, t[j].tag, NULL, t[j].tag);
        fprintf(f, "</td><td>%d</td>", t[j].cases);
        html_count(f, t[j].tag, "exact", t[j].exact, "exact");
        html_count(f, t[j].tag, "agrees", t[j].agrees, "agrees");
        html_count(f, t[j].tag, "differs", t[j].differs, "differs");
        html_count(f, t[j].tag, "blank", t[j].blank, "blank");
        html_count(f, t[j].tag, "error", t[j].error, "error");
        html_count(f, t[j].tag, "unlisted", unlisted, "unlisted");
        fprintf(f, "<td>%d</td></tr>\n", t[j].blank_allowed);
    }
    fputs("</table>\n<p><span class=\"blank\">blank</span>: a case whose every frame shows a cleared "
          "buffer (every pixel alike, every depth value alike) on both sides compares no drawing; "
          "it fails like a difference unless its table entry declares <code>draws_nothing</code> "
          "(conformance/harness/fc_case.h). <i>blank, allowed</i>: generated scenes "
          "(FC_MAY_DRAW_NOTHING) that compare nothing; counted, not failed.</p>\n", f);
    {
        struct agreement a[MAX_AGREEMENT];
        size_t na = collect_agreement(r, a, MAX_AGREEMENT);
        if (na) {
            fputs("<h2>Agreement of the reference cases</h2>\n<p>Cases tagged <code>reference</code> "
                  "draw their oracle side with a GLSL program on OSMesa that evaluates the equations of "
                  "<code>include/fixgl/shading.md</code>; a case <span class=\"agrees\">agrees</span> when "
                  "no colour channel differs by more than its tolerance and depth, errors and queries "
                  "are exact. Their heat maps are below with the other non-exact cases.</p>\n"
                  "<table><tr><th>tag</th><th>cases</th><th>bit-exact</th><th>agree</th><th>differ</th>"
                  "<th>tolerance</th><th>max LSB</th><th>pixels</th><th>at 1 LSB</th><th>beyond 1 LSB</th>"
                  "<th>beyond tolerance</th><th>depth mismatches</th></tr>\n", f);
            for (size_t j = 0; j < na; j++)
                fprintf(f, "<tr><td>%s</td><td>%d</td><td>%d</td><td>%d</td><td>%d</td><td>%d</td>"
                        "<td>%d</td><td>%" PRIu64 "</td><td>%" PRIu64 "</td><td>%" PRIu64 "</td><td>%" PRIu64
                        "</td><td>%" PRIu64 "</td></tr>\n", a[j].tag, a[j].cases, a[j].exact, a[j].agrees,
                        a[j].differs + a[j].error, a[j].tolerance, a[j].max_lsb, a[j].pixels, a[j].at_1,
                        a[j].beyond_1, a[j].beyond_tolerance, a[j].depth_mismatches);
            fputs("</table>\n", f);
        }
    }
    for (size_t i = 0; i < r->n; i++)
        if (strcmp(r->entries[i]->status, "exact") != 0)
            html_case(f, r->entries[i]);
    int ndoc = 0;
    for (size_t i = 0; i < r->n; i++)
        ndoc += r->entries[i]->res.ndocumented;
    if (ndoc) {
        fprintf(f, "<h2>Documented differences (%d)</h2>\n<p>Records that differ from the oracle on "
                "purpose, each declared by its case with the reason (fc_documented_difference); "
                "they do not make a case differ.</p>\n<table><tr><th>case</th><th>label</th>"
                "<th>record</th><th>reason</th><th>oracle</th><th>fixgl</th></tr>\n", ndoc);
        for (size_t i = 0; i < r->n; i++) {
            const struct fc_report_entry *e = r->entries[i];
            for (int k = 0; k < e->res.ndocumented; k++) {
                const struct fc_documented *d = &e->res.documented[k];
                const char *cells[6] = { e->name, d->label, d->kind, d->reason, d->oracle, d->fixgl };
                fputs("<tr>", f);
                for (int j = 0; j < 6; j++) {
                    fputs("<td style=\"text-align:left\">", f);
                    html_str(f, cells[j]);
                    fputs("</td>", f);
                }
                fputs("</tr>\n", f);
            }
        }
        fputs("</table>\n", f);
    }
    fputs("<h2>All cases</h2>\n<p class=\"filter\"><label>tag <select id=\"filter-tag\" "
          "onchange=\"fcFilter()\"><option value=\"\">all</option>", f);
    for (size_t j = 0; j < nt; j++) {
        fputs("<option>", f);
        html_str(f, t[j].tag);
        fputs("</option>", f);
    }
    fputs("</select></label> <label>status <select id=\"filter-status\" onchange=\"fcFilter()\">"
          "<option value=\"\">all</option><option>exact</option><option>agrees</option>"
          "<option>differs</option><option>blank</option><option>error</option>"
          "<option value=\"not-passing\">not passing</option>"
          "<option value=\"unlisted\">unlisted</option></select></label> "
          "<span id=\"filter-count\"></span></p>\n"
          "<table id=\"all-cases\"><tr><th>case</th><th>tags</th><th>status</th>"
          "<th>mismatched pixels</th><th>reason</th></tr>\n", f);
    size_t first[64];
    for (size_t j = 0; j < nt; j++) {
        first[j] = 0;
        while (first[j] < r->n && !has_tag_word(r->entries[first[j]]->tags, t[j].tag, strlen(t[j].tag)))
            first[j]++;
    }
    for (size_t i = 0; i < r->n; i++) {
        const struct fc_report_entry *e = r->entries[i];
        fputs("<tr data-tags=\"", f);
        html_str(f, e->tags);
        fprintf(f, "\" data-status=\"%s\" data-known=\"%s\"><td>", e->status,
                fc_status_passes(e->status) ? "" : e->known_reason ? "listed" : "unlisted");
        /* the first row of each of its tags holds the tag's anchor */
        for (size_t j = 0; j < nt; j++) {
            if (first[j] == i) {
                fputs("<a id=\"tag-", f);
                html_str(f, t[j].tag);
                fputs("\"></a>", f);
            }
        }
        if (strcmp(e->status, "exact") != 0) {
            fputs("<a href=\"#", f);
            html_str(f, e->file_stem);
            fputs("\">", f);
            html_str(f, e->name);
            fputs("</a>", f);
        } else {
            html_str(f, e->name);
        }
        fputs("</td><td style=\"text-align:left\">", f);
        html_str(f, e->tags);
        fprintf(f, "</td><td class=\"%s\">%s</td><td>%" PRIu64 "</td><td class=\"reason\">", e->status,
                e->status, e->res.mismatched_pixels);
        html_reason(f, e, 0);
        fputs("</td></tr>\n", f);
    }
    fputs("</table>\n", f);
    fputs(filter_script, f);
    fputs("</body></html>\n", f);
    return fclose(f) == 0;
}

int fc_report_finish(struct fc_report *r)
{
    int bad = 0, ok = write_json(r) && write_html(r);
    if (!ok)
        fprintf(stderr, "fixgl-conform: cannot write the report in %s\n", r->dir);
    for (size_t i = 0; i < r->n; i++) {
        struct fc_report_entry *e = r->entries[i];
        bad += !fc_status_passes(e->status);
        free(e->name); free(e->tags); free(e->replay); free(e->file_stem); free(e->known_reason);
        fc_result_free(&e->res);
        free(e);
    }
    for (int i = 0; i < 2; i++) {
        free(r->renderer[i]);
        free(r->version[i]);
    }
    free(r->entries);
    free(r->known_file);
    free(r->dir);
    free(r);
    return ok ? bad : -1;
}
