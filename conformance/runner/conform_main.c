/* conform_main.c - fixgl-conform: runs the conformance cases on the oracle
 * (Mesa OSMesa, llvmpipe) and on fixgl, compares every frame pixel by pixel
 * plus the recorded error/query/blob/value sequences, prints one line per
 * case and a per-tag summary, and writes the HTML/JSON report.
 * Exit status: 0 all exact (reference cases: within their tolerance), 1 some
 * case differs, failed or is blank (compares nothing: fc_case.h), or a
 * random family's scenes compare nothing too often (FC_BLANK_MAX_PERCENT), 2
 * usage/setup. */
#include "fc_cache.h"
#include "fc_compare.h"
#include "fc_report.h"
#include "fc_run.h"

#include <fixgl/version.h>

#include <fnmatch.h>
#include <getopt.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAX_FILTERS 32

struct options {
    const char *tags[MAX_FILTERS], *globs[MAX_FILTERS];
    int ntags, nglobs;
    long random;                /* number of random scenes */
    long random_lit;            /* number of random lit scenes */
    long random_raster;         /* number of random raster scenes */
    long random_tex;            /* number of random texture scenes */
    long random_shading;        /* number of random shading-extension scenes */
    uint64_t seed;
    long index;                 /* first scene index; >= 0 replays from there */
    const char *report, *renderer[2], *fixgl_arg;
    const char *known;          /* file of known differences, or NULL */
    const char *oracle_cache;   /* root of the oracle's result cache, or NULL */
    int jobs, list_only;
};

/* Known differences: case names (first word of each line; '#' comments)
 * and their reasons (the rest of the line).  They are reported as usual,
 * with the reason; only the exit status treats them apart. */
struct known {
    char **names, **reasons;
    size_t n;
};

static char *dup_str(const char *s);

struct ctx {
    struct fc_report *report;
    size_t total;
    const struct known *known;
    size_t unexpected, stale, expected;
    int self_compare;           /* the same renderer on both sides */
};

static int load_known(const char *path, struct known *k)
{
    char *line = NULL;
    size_t cap = 0;
    FILE *f = fopen(path, "r");
    memset(k, 0, sizeof *k);
    if (!f) {
        fprintf(stderr, "fixgl-conform: cannot read %s\n", path);
        return 0;
    }
    /* whole lines (the reasons run long) */
    while (getline(&line, &cap, f) >= 0) {
        char name[256];
        int end = 0;
        if (line[0] == '#' || sscanf(line, " %255s%n", name, &end) != 1)
            continue;
        char *reason = line + end;
        reason += strspn(reason, " \t");
        reason[strcspn(reason, "\r\n")] = '\0';
        k->names = realloc(k->names, (k->n + 1) * sizeof *k->names);
        k->reasons = realloc(k->reasons, (k->n + 1) * sizeof *k->reasons);
        k->names[k->n] = dup_str(name);
        k->reasons[k->n++] = dup_str(reason);
    }
    free(line);
    fclose(f);
    return 1;
}

/* The case's reason in the list ("" when it has none), or NULL. */
static const char *known_reason(const struct known *k, const char *name)
{
    for (size_t i = 0; k && i < k->n; i++)
        if (strcmp(k->names[i], name) == 0)
            return k->reasons[i];
    return NULL;
}

static void usage(FILE *f)
{
    fprintf(f,
        "usage: fixgl-conform [options]\n"
        "  --tag T              only cases with tag T (repeatable)\n"
        "  --case GLOB          only cases whose name matches GLOB (repeatable)\n"
        "  --random N           add N random scenes, random/s<S>-i<I> (default 100, or 0\n"
        "                       when another family's count is given)\n"
        "  --random-lit N       add N random lit scenes, random-lit/s<S>-i<I> (tag random-lit;\n"
        "                       default 0): lights, materials, light models, normals\n"
        "  --random-raster N    add N random raster scenes, random-raster/s<S>-i<I> (tag\n"
        "                       random-raster; default 0): points, lines, polygon state,\n"
        "                       clip planes, fog, per-fragment operations\n"
        "  --random-tex N       add N random texture scenes, random-tex/s<S>-i<I> (tag\n"
        "                       random-tex; default 0): texture images, filters, wraps,\n"
        "                       mipmaps, environments, coordinates\n"
        "  --random-shading N   add N random scenes of fixgl's shading extensions,\n"
        "                       random-shading/s<S>-i<I> (tags reference, random-shading,\n"
        "                       phong / cook-torrance; default 0), against the GLSL reference\n"
        "  --seed S             random seed of every family (default 1)\n"
        "  --index I            replay random scene I of seed S alone (with --random N,\n"
        "                       --random-lit N, --random-raster N, --random-tex N or\n"
        "                       --random-shading N: scenes I..I+N-1 of that family)\n"
        "  --no-random          no plain random scenes\n"
        "  --jobs N             renderer processes at once (default: online CPUs)\n"
        "  --report DIR         report directory (default %s)\n"
        "  --oracle-renderer P  default $FIXGL_CONFORM_ORACLE_RENDERER, else %s\n"
        "  --fixgl-renderer P   default %s\n"
        "  --oracle-cache DIR   reuse the oracle's render of a case from DIR, keyed by the\n"
        "                       oracle renderer, its libraries, the case and the FC_/Mesa\n"
        "                       environment (fc_cache.h); default $FIXGL_CONFORM_ORACLE_CACHE\n"
        "  --no-oracle-cache    render every case on the oracle\n"
        "  --fixgl-arg ARG      extra argument for the fixgl renderer (test-only, e.g. --perturb)\n"
        "  --list               print the selected cases and exit\n"
        "  --known FILE         cases listed in FILE are known differences: still reported,\n"
        "                       but only other differences (or a listed case now exact) fail\n"
        "  --version            the versions of fixgl and of the oracle, Mesa\n"
        "Every option also as --opt=value.\n",
        FC_DEFAULT_REPORT, FC_DEFAULT_ORACLE, FC_DEFAULT_FIXGL);
}

static int parse_args(int argc, char **argv, struct options *o)
{
    int explicit_random = 0, explicit_lit = 0;   /* explicit_lit: any other family */
    memset(o, 0, sizeof *o);
    o->random = 100;
    o->seed = 1;
    o->index = -1;
    o->report = FC_DEFAULT_REPORT;
    o->renderer[FC_ORACLE] = FC_DEFAULT_ORACLE;
    if (getenv("FIXGL_CONFORM_ORACLE_RENDERER") && *getenv("FIXGL_CONFORM_ORACLE_RENDERER"))
        o->renderer[FC_ORACLE] = getenv("FIXGL_CONFORM_ORACLE_RENDERER");
    if (getenv("FIXGL_CONFORM_ORACLE_CACHE") && *getenv("FIXGL_CONFORM_ORACLE_CACHE"))
        o->oracle_cache = getenv("FIXGL_CONFORM_ORACLE_CACHE");
    o->renderer[FC_FIXGL] = FC_DEFAULT_FIXGL;
    o->jobs = (int)sysconf(_SC_NPROCESSORS_ONLN);
    enum {
        OPT_NO_RANDOM = 256, OPT_LIST, OPT_VERSION, OPT_TAG, OPT_CASE, OPT_RANDOM, OPT_RANDOM_LIT,
        OPT_RANDOM_RASTER, OPT_RANDOM_TEX, OPT_RANDOM_SHADING, OPT_SEED, OPT_INDEX, OPT_JOBS,
        OPT_REPORT, OPT_ORACLE_RENDERER, OPT_FIXGL_RENDERER, OPT_FIXGL_ARG, OPT_KNOWN,
        OPT_ORACLE_CACHE, OPT_NO_ORACLE_CACHE,
    };
    static const struct option longopts[] = {
        { "help", no_argument, NULL, 'h' },
        { "version", no_argument, NULL, OPT_VERSION },
        { "no-random", no_argument, NULL, OPT_NO_RANDOM },
        { "list", no_argument, NULL, OPT_LIST },
        { "tag", required_argument, NULL, OPT_TAG },
        { "case", required_argument, NULL, OPT_CASE },
        { "random", required_argument, NULL, OPT_RANDOM },
        { "random-lit", required_argument, NULL, OPT_RANDOM_LIT },
        { "random-raster", required_argument, NULL, OPT_RANDOM_RASTER },
        { "random-tex", required_argument, NULL, OPT_RANDOM_TEX },
        { "random-shading", required_argument, NULL, OPT_RANDOM_SHADING },
        { "seed", required_argument, NULL, OPT_SEED },
        { "index", required_argument, NULL, OPT_INDEX },
        { "jobs", required_argument, NULL, OPT_JOBS },
        { "report", required_argument, NULL, OPT_REPORT },
        { "oracle-renderer", required_argument, NULL, OPT_ORACLE_RENDERER },
        { "fixgl-renderer", required_argument, NULL, OPT_FIXGL_RENDERER },
        { "fixgl-arg", required_argument, NULL, OPT_FIXGL_ARG },
        { "known", required_argument, NULL, OPT_KNOWN },
        { "oracle-cache", required_argument, NULL, OPT_ORACLE_CACHE },
        { "no-oracle-cache", no_argument, NULL, OPT_NO_ORACLE_CACHE },
        { NULL, 0, NULL, 0 },
    };
    int ch;
    opterr = 0;
    while ((ch = getopt_long(argc, argv, ":h", longopts, NULL)) != -1) {
        const char *v = optarg;
        switch (ch) {
        case 'h': usage(stdout); exit(0);
        case OPT_VERSION: puts(FIXGL_VERSION_BANNER("fixgl-conform")); exit(0);
        case OPT_NO_RANDOM: o->random = 0; explicit_random = 1; break;
        case OPT_LIST: o->list_only = 1; break;
        case OPT_TAG:
            if (o->ntags >= MAX_FILTERS) { fprintf(stderr, "fixgl-conform: more than %d --tag\n", MAX_FILTERS); return 0; }
            o->tags[o->ntags++] = v;
            break;
        case OPT_CASE:
            if (o->nglobs >= MAX_FILTERS) { fprintf(stderr, "fixgl-conform: more than %d --case\n", MAX_FILTERS); return 0; }
            o->globs[o->nglobs++] = v;
            break;
        case OPT_RANDOM: o->random = strtol(v, NULL, 10); explicit_random = 1; break;
        case OPT_RANDOM_LIT: o->random_lit = strtol(v, NULL, 10); explicit_lit = 1; break;
        case OPT_RANDOM_RASTER: o->random_raster = strtol(v, NULL, 10); explicit_lit = 1; break;
        case OPT_RANDOM_TEX: o->random_tex = strtol(v, NULL, 10); explicit_lit = 1; break;
        case OPT_RANDOM_SHADING: o->random_shading = strtol(v, NULL, 10); explicit_lit = 1; break;
        case OPT_SEED: o->seed = strtoull(v, NULL, 10); break;
        case OPT_INDEX: o->index = strtol(v, NULL, 10); break;
        case OPT_JOBS: o->jobs = atoi(v); break;
        case OPT_REPORT: o->report = v; break;
        case OPT_ORACLE_RENDERER: o->renderer[FC_ORACLE] = v; break;
        case OPT_FIXGL_RENDERER: o->renderer[FC_FIXGL] = v; break;
        case OPT_FIXGL_ARG: o->fixgl_arg = v; break;
        case OPT_KNOWN: o->known = v; break;
        case OPT_ORACLE_CACHE: o->oracle_cache = v; break;
        case OPT_NO_ORACLE_CACHE: o->oracle_cache = NULL; break;
        case ':': fprintf(stderr, "fixgl-conform: %s needs a value\n", argv[optind - 1]); return 0;
        default: fprintf(stderr, "fixgl-conform: unknown option %s\n", argv[optind - 1]); return 0;
        }
    }
    if (optind < argc) {
        fprintf(stderr, "fixgl-conform: unexpected argument %s\n", argv[optind]);
        return 0;
    }
    if (explicit_lit && !explicit_random)
        o->random = 0;
    else if (o->index >= 0 && !explicit_random)
        o->random = 1;
    o->jobs = o->jobs < 1 ? 1 : o->jobs;
    return o->random >= 0 && o->random_lit >= 0 && o->random_raster >= 0 && o->random_tex >= 0
           && o->random_shading >= 0;
}

static int has_tag(const char *tags, const char *tag)
{
    size_t n = strlen(tag);
    for (const char *s = tags; *s;) {
        size_t k = strcspn(s, " ");
        if (k == n && strncmp(s, tag, n) == 0)
            return 1;
        s += k;
        s += strspn(s, " ");
    }
    return 0;
}

static int selected(const struct options *o, const char *name, const char *tags)
{
    int ok = o->ntags == 0;
    for (int i = 0; i < o->ntags && !ok; i++)
        ok = has_tag(tags, o->tags[i]);
    if (!ok)
        return 0;
    ok = o->nglobs == 0;
    for (int i = 0; i < o->nglobs && !ok; i++)
        ok = fnmatch(o->globs[i], name, 0) == 0;
    return ok;
}

static char *dup_str(const char *s)
{
    size_t n = strlen(s) + 1;
    return memcpy(malloc(n), s, n);
}

static void free_items(struct fc_item *items, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        free(items[i].name); free(items[i].tags); free(items[i].replay);
        free(items[i].side[0].data); free(items[i].side[1].data);
    }
    free(items);
}

static void add_item(struct fc_item **items, size_t *n, size_t *cap, const char *name,
                     const char *tags, const char *replay, int tolerance)
{
    if (*n == *cap) {
        *cap = *cap ? 2 * *cap : 256;
        *items = realloc(*items, *cap * sizeof **items);
    }
    memset(&(*items)[*n], 0, sizeof **items);
    (*items)[*n].name = dup_str(name);
    (*items)[*n].tags = dup_str(tags);
    (*items)[*n].replay = replay ? dup_str(replay) : NULL;
    (*items)[*n].tolerance = tolerance;
    ++*n;
}

/* count scenes of a random family ("random", "random-lit", ...) from
 * o->index on; replay_prefix selects the family on a replay command line
 * (the plain family is the default). */
static void add_random(const struct options *o, struct fc_item **items, size_t *n,
                       size_t *cap, const char *family, long count, const char *replay_prefix)
{
    for (long i = 0; i < count; i++) {
        char name[96], replay[128];
        uint64_t index = (uint64_t)(o->index >= 0 ? o->index : 0) + (uint64_t)i;
        snprintf(name, sizeof name, "%s/s%" PRIu64 "-i%" PRIu64, family, o->seed, index);
        snprintf(replay, sizeof replay, "%s--seed %" PRIu64 " --index %" PRIu64, replay_prefix,
                 o->seed, index);
        if (selected(o, name, family))
            add_item(items, n, cap, name, family, replay, 0);
    }
}

/* Adds the cases of a listing ("name\ttags[\ttolerance]" lines, the
 * renderer's --list and --list-random) that the filters select; replay_prefix
 * (NULL for fixed cases) gives each a replay command line.  0 on error. */
static int add_listed(const struct options *o, char *list, struct fc_item **items, size_t *n,
                      size_t *cap, const char *replay_prefix)
{
    char *save = NULL;
    for (char *line = strtok_r(list, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        char *tab = strchr(line, '\t'), *tol, replay[128];
        int tolerance = 0;
        if (!tab)
            continue;
        *tab = 0;
        /* a third field: the colour tolerance of a reference case */
        if ((tol = strchr(tab + 1, '\t')) != NULL) {
            *tol = 0;
            tolerance = atoi(tol + 1);
            if (tolerance < 0 || tolerance > 255 || !has_tag(tab + 1, "reference")) {
                fprintf(stderr, "fixgl-conform: case %s declares a colour tolerance of %s LSB "
                        "without the \"reference\" tag (fc_case.h)\n", line, tol + 1);
                return 0;
            }
        }
        if (replay_prefix) {
            uint64_t seed, index;
            const char *s = strrchr(line, '/');
            if (!s || sscanf(s, "/s%" SCNu64 "-i%" SCNu64, &seed, &index) != 2) {
                fprintf(stderr, "fixgl-conform: bad random scene name %s\n", line);
                return 0;
            }
            snprintf(replay, sizeof replay, "%s--seed %" PRIu64 " --index %" PRIu64, replay_prefix,
                     seed, index);
        }
        if (selected(o, line, tab + 1))
            add_item(items, n, cap, line, tab + 1, replay_prefix ? replay : NULL, tolerance);
    }
    return 1;
}

/* count scenes of a random family whose tags and tolerance vary by scene:
 * the oracle renderer lists them (--list-random).  0 on error. */
static int add_random_listed(const struct options *o, struct fc_item **items, size_t *n,
                             size_t *cap, const char *family, long count, const char *replay_prefix)
{
    char seed[32], index[32], cnt[32];
    const char *argv[7] = { o->renderer[FC_ORACLE], "--list-random", family, seed, index, cnt, NULL };
    char *list;
    int ok;
    if (count == 0)
        return 1;
    snprintf(seed, sizeof seed, "%" PRIu64, o->seed);
    snprintf(index, sizeof index, "%ld", o->index >= 0 ? (long)o->index : 0L);
    snprintf(cnt, sizeof cnt, "%ld", count);
    if (!(list = fc_run_capture(argv))) {
        fprintf(stderr, "fixgl-conform: cannot list the %s scenes with %s\n", family, argv[0]);
        return 0;
    }
    ok = add_listed(o, list, items, n, cap, replay_prefix);
    free(list);
    return ok;
}

/* Fixed cases (from the oracle's --list), then the scenes of each random
 * family; 0 on error. */
static int build_items(const struct options *o, struct fc_item **out, size_t *n)
{
    struct fc_item *items = NULL;
    size_t cap = 0;
    *n = 0;
    if (o->index < 0) {
        const char *argv[3] = { o->renderer[FC_ORACLE], "--list", NULL };
        char *list = fc_run_capture(argv);
        int ok;
        if (!list) {
            fprintf(stderr, "fixgl-conform: cannot list the cases with %s\n", argv[0]);
            return 0;
        }
        ok = add_listed(o, list, &items, n, &cap, NULL);
        free(list);
        if (!ok) {
            free(items);
            return 0;
        }
    }
    add_random(o, &items, n, &cap, "random", o->random, "");
    add_random(o, &items, n, &cap, "random-lit", o->random_lit, "--random-lit 1 ");
    add_random(o, &items, n, &cap, "random-raster", o->random_raster, "--random-raster 1 ");
    add_random(o, &items, n, &cap, "random-tex", o->random_tex, "--random-tex 1 ");
    if (!add_random_listed(o, &items, n, &cap, "random-shading", o->random_shading,
                           "--random-shading 1 ")) {
        free(items);
        return 0;
    }
    *out = items;
    return 1;
}

/* The two paths name the same file (a symbolic link is the same renderer). */
static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    if (stat(a, &sa) != 0 || stat(b, &sb) != 0)
        return strcmp(a, b) == 0;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

static void on_ready(void *ud, struct fc_item *item, size_t index)
{
    struct ctx *c = ud;
    struct fc_case_result res;
    struct fc_report_entry *e = fc_report_begin_case(c->report, item->name, item->tags, item->replay);
    const char *status;
    char dots[64];
    int pad;

    memset(&res, 0, sizeof res);
    res.self_compare = c->self_compare;
    res.tolerance = item->tolerance;
    for (int s = 0; s < 2; s++) {
        if (item->side[s].state == FC_FAILED) {
            res.crashed = 1;
            fc_result_note(&res, "%s: %s", s == FC_ORACLE ? "oracle" : "fixgl", item->side[s].why);
        }
    }
    fc_compare_case(item->side[0].data, item->side[0].len, item->side[1].data, item->side[1].len,
                    &res, fc_report_frame, e);
    status = fc_report_end_case(e, &res);
    fc_report_set_known(e, known_reason(c->known, item->name));

    pad = 56 - (int)strlen(item->name);
    pad = pad < 2 ? 2 : pad > 63 ? 63 : pad;
    memset(dots, '.', (size_t)pad);
    dots[pad] = 0;
    printf("[%*zu/%zu] %s %s %s", c->total > 999 ? 5 : 4, index + 1, c->total, item->name, dots, status);
    if (strcmp(status, "differs") == 0)
        printf("  (%" PRIu64 " px, max diff %d, depth %" PRIu64 ", errors %d, queries %d, blobs %d, values %d)",
               res.mismatched_pixels, res.max_channel_diff, res.depth_mismatches, res.error_mismatches,
               res.query_mismatches, res.blob_mismatches, res.value_mismatches + res.structure_mismatches);
    else if (strcmp(status, "agrees") == 0)
        printf("  (within %d LSB: %" PRIu64 " px differ, max diff %d, %" PRIu64 " px at 1 LSB)",
               res.tolerance, res.mismatched_pixels, res.max_channel_diff, res.pixels_at_1);
    else if (res.crashed)
        printf("  (%s)", res.notes[0]);
    else if (res.blank)
        printf("  (compares nothing: %d frame%s, each a cleared buffer on both sides; "
               "draws_nothing is not declared)", res.frames, res.frames > 1 ? "s" : "");
    if (res.ndocumented)
        printf("  (%d documented difference%s)", res.ndocumented, res.ndocumented > 1 ? "s" : "");
    if (item->replay && strcmp(status, "exact") != 0)
        printf("  replay: fixgl-conform %s", item->replay);
    if (known_reason(c->known, item->name)) {
        if (fc_status_passes(status)) {
            printf("  (listed as a known difference: remove it from the list)");
            c->stale++;
        } else {
            printf("  [known difference]");
            c->expected++;
        }
    } else if (!fc_status_passes(status)) {
        c->unexpected++;
    }
    putchar('\n');
    fflush(stdout);
    for (int s = 0; s < 2; s++) {
        free(item->side[s].data);
        item->side[s].data = NULL;
    }
}

int main(int argc, char **argv)
{
    struct options o;
    struct fc_run_cfg cfg;
    struct fc_item *items = NULL;
    struct ctx c;
    char *info[2][2] = { { NULL, NULL }, { NULL, NULL } };
    size_t n;
    int rc, bad, blank_over = 0;

    if (!parse_args(argc, argv, &o)) {
        usage(stderr);
        return 2;
    }
    for (int s = 0; s < 2; s++) {
        if (access(o.renderer[s], X_OK) != 0) {
            fprintf(stderr, "fixgl-conform: %s renderer %s is not executable%s\n",
                    s == FC_ORACLE ? "oracle" : "fixgl", o.renderer[s],
                    s == FC_FIXGL ? " (libfixgl may not link yet; see the meson output)" : "");
            return 2;
        }
    }
    if (!build_items(&o, &items, &n))
        return 2;
    if (n == 0) {
        fprintf(stderr, "fixgl-conform: no case selected\n");
        return 2;
    }
    if (o.list_only) {
        for (size_t i = 0; i < n; i++) {
            if (items[i].tolerance)
                printf("%s\t%s\t%d\n", items[i].name, items[i].tags, items[i].tolerance);
            else
                printf("%s\t%s\n", items[i].name, items[i].tags);
        }
        free_items(items, n);
        return 0;
    }
    struct known known = { NULL, NULL, 0 };
    if (o.known && !load_known(o.known, &known))
        return 2;
    c.report = fc_report_open(o.report);
    if (c.report && o.known)
        fc_report_set_known_file(c.report, o.known);
    c.total = n;
    c.known = o.known ? &known : NULL;
    c.unexpected = c.stale = c.expected = 0;
    c.self_compare = same_file(o.renderer[FC_ORACLE], o.renderer[FC_FIXGL]);
    if (!c.report)
        return 2;
    memset(&cfg, 0, sizeof cfg);
    cfg.renderer[FC_ORACLE] = o.renderer[FC_ORACLE];
    cfg.renderer[FC_FIXGL] = o.renderer[FC_FIXGL];
    cfg.extra_arg[FC_FIXGL] = o.fixgl_arg;
    cfg.work_dir = o.report;
    cfg.jobs = o.jobs;
    if (o.oracle_cache)
        cfg.oracle_cache = fc_cache_open(o.oracle_cache, o.renderer[FC_ORACLE], NULL);
    printf("fixgl-conform: %zu cases, %d jobs\n  oracle %s\n  fixgl  %s\n", n, o.jobs,
           o.renderer[FC_ORACLE], o.renderer[FC_FIXGL]);
    fflush(stdout);
    rc = fc_run_items(&cfg, items, n, on_ready, &c, info);
    if (cfg.oracle_cache) {
        printf("oracle cache %s: %zu of %zu cases reused, %zu rendered\n",
               fc_cache_dir(cfg.oracle_cache), cfg.oracle_cached, n, n - cfg.oracle_cached);
        fc_cache_close(cfg.oracle_cache);
    }
    fc_report_set_renderers(c.report, info[0][0], info[0][1], info[1][0], info[1][1]);
    if (rc == 0)
        blank_over = fc_report_print_summary(c.report, stdout);
    else
        fprintf(stderr, "fixgl-conform: run aborted; the report holds the cases finished so far\n");
    bad = fc_report_finish(c.report);
    printf("report: %s/index.html\n", o.report);
    if (o.known)
        printf("known differences (%s): %zu still differ, %zu now exact; other differences: %zu\n",
               o.known, c.expected, c.stale, c.unexpected);
    free_items(items, n);
    for (int s = 0; s < 2; s++) {
        free(info[s][0]);
        free(info[s][1]);
    }
    for (size_t i = 0; i < known.n; i++) {
        free(known.names[i]);
        free(known.reasons[i]);
    }
    free(known.names);
    free(known.reasons);
    if (rc != 0 || bad < 0)
        return 2;
    if (blank_over) {
        printf("random families drawing nothing in too many of their scenes "
               "(FC_BLANK_MAX_PERCENT, fc_report.h): %d\n", blank_over);
        return 1;
    }
    if (o.known)
        return (c.unexpected || c.stale) ? 1 : 0;
    return bad ? 1 : 0;
}
