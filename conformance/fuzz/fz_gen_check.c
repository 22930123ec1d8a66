/* fz_gen_check.c - fixgl-fuzz-gen-check [--seeds N] [--random N] [FILE...]:
 * the generator never makes a stream whose display lists are unbounded
 * work.
 *
 * GL allows lists to call lists 64 levels deep, so a list that calls
 * itself twice is 2^64 executions: the oracle hangs on it as fixgl does
 * (and crashes when the calls are inside glBegin), so such a stream is a
 * hang of the generator's own making, not a finding.  fz_gen.c bounds the
 * glCallList calls compiled into a list to lower names; this program
 * checks the streams it makes against GL's rules for what is compiled:
 *
 * - glNewList starts a list when none is open, the name is not 0, the mode
 *   is GL_COMPILE or GL_COMPILE_AND_EXECUTE and no executed glBegin is
 *   open; glEndList inside glBegin ends the list (ORACLE-NOTES.md
 *   "Display lists", "Which glNewList starts a list");
 * - while a list is open, glCallList(n) is compiled into it, and
 *   glCallLists is compiled with its names (any n > 0 is reported: the
 *   generator compiles it with no names);
 * - glEndList ends the open list; a list compiled again replaces the old.
 *
 * At the end of each stream (and at every glCallList executed outside a
 * list) the work of executing a list, 1 + the work of what it calls
 * (at most 64 levels, "Nesting" there), must stay under 10^6.
 * The streams: seeds 1..N of the differential campaign (300 calls each),
 * N random byte strings decoded as fixgl-libfuzzer decodes its inputs,
 * and each FILE (a libFuzzer input, e.g. a former timeout). */
#include "fz_gen.h"

#include <GL/gl.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_LISTS 256       /* lists tracked per stream (more: reported) */
#define MAX_CALLED 64       /* glCallList calls compiled into one list */
#define WORK_LIMIT 1000000.0

typedef struct {
    uint32_t name;
    unsigned ncalled;
    uint32_t called[MAX_CALLED];
} list_def;

static int fn_newlist, fn_endlist, fn_calllist, fn_calllists, fn_begin, fn_end;

static list_def *find(list_def *defs, unsigned n, uint32_t name)
{
    for (unsigned i = 0; i < n; i++)
        if (defs[i].name == name)
            return &defs[i];
    return NULL;
}

/* executions when list name is called at nesting depth depth (1-based) */
static double work(list_def *defs, unsigned n, uint32_t name, int depth)
{
    const list_def *d = find(defs, n, name);
    if (!d || depth > 64)
        return 0;
    double w = 1;
    for (unsigned i = 0; i < d->ncalled && w < WORK_LIMIT; i++)
        w += work(defs, n, d->called[i], depth + 1);
    return w;
}

/* 0 when the stream is bounded work, else prints why and returns 1 */
static int check(const fz_call *calls, size_t n, const char *what)
{
    static list_def defs[MAX_LISTS];
    unsigned ndefs = 0;
    list_def open = { 0, 0, { 0 } };
    int compiling = 0, exec_begin = 0;
    GLenum mode = 0;
    for (size_t i = 0; i < n; i++) {
        const fz_call *c = &calls[i];
        const int fn = (int)c->fn;
        if (fn == fn_newlist) {
            const uint32_t name = (uint32_t)c->a[0].i;
            const GLenum m = (GLenum)c->a[1].i;
            if (!compiling && name != 0 && !exec_begin &&
                (m == GL_COMPILE || m == GL_COMPILE_AND_EXECUTE)) {
                compiling = 1;
                mode = m;
                open = (list_def){ name, 0, { 0 } };
            }
        } else if (fn == fn_endlist) {
            if (compiling) {
                list_def *d = find(defs, ndefs, open.name);
                if (!d) {
                    if (ndefs == MAX_LISTS) {
                        printf("%s: more than %d lists\n", what, MAX_LISTS);
                        return 1;
                    }
                    d = &defs[ndefs++];
                }
                *d = open;
                compiling = 0;
            }
        } else if (fn == fn_calllist) {
            const uint32_t name = (uint32_t)c->a[0].i;
            if (compiling && open.ncalled == MAX_CALLED) {
                printf("%s: call %zu: over %d glCallList in list %u\n", what, i, MAX_CALLED,
                       open.name);
                return 1;
            }
            if (compiling)
                open.called[open.ncalled++] = name;
            if (!compiling || mode == GL_COMPILE_AND_EXECUTE) {
                const double w = work(defs, ndefs, name, 1);
                if (w >= WORK_LIMIT) {
                    printf("%s: call %zu: glCallList(%u) executes at least %.0f lists\n", what,
                           i, name, w);
                    return 1;
                }
            }
        } else if (fn == fn_calllists) {
            if (compiling && (int32_t)c->a[0].i > 0) {
                printf("%s: call %zu: glCallLists(%d, ...) compiled into list %u\n", what, i,
                       (int)(int32_t)c->a[0].i, open.name);
                return 1;
            }
        } else if (fn == fn_begin) {
            if ((!compiling || mode == GL_COMPILE_AND_EXECUTE) && (uint64_t)c->a[0].i <= GL_POLYGON)
                exec_begin = 1;
        } else if (fn == fn_end) {
            exec_begin = 0;
        }
    }
    for (unsigned k = 0; k < ndefs; k++) {
        const double w = work(defs, ndefs, defs[k].name, 1);
        if (w >= WORK_LIMIT) {
            printf("%s: list %u executes at least %.0f lists\n", what, defs[k].name, w);
            return 1;
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    static const struct option longopts[] = {
        { "seeds", required_argument, NULL, 's' }, { "random", required_argument, NULL, 'r' },
        { NULL, 0, NULL, 0 } };
    unsigned long seeds = 2000, random_inputs = 2000;
    int ch, failed = 0;
    while ((ch = getopt_long(argc, argv, "", longopts, NULL)) != -1) {
        if (ch == 's')
            seeds = strtoul(optarg, NULL, 10);
        else if (ch == 'r')
            random_inputs = strtoul(optarg, NULL, 10);
        else
            return 2;
    }
    fz_gen_init(NULL);
    fn_newlist = fz_find_entry("glNewList");
    fn_endlist = fz_find_entry("glEndList");
    fn_calllist = fz_find_entry("glCallList");
    fn_calllists = fz_find_entry("glCallLists");
    fn_begin = fz_find_entry("glBegin");
    fn_end = fz_find_entry("glEnd");
    if (fn_newlist < 0 || fn_endlist < 0 || fn_calllist < 0 || fn_calllists < 0 ||
        fn_begin < 0 || fn_end < 0) {
        fprintf(stderr, "fixgl-fuzz-gen-check: the table lacks the list entry points\n");
        return 2;
    }
    static fz_call calls[FZ_LIBFUZZER_CALLS > 300 ? FZ_LIBFUZZER_CALLS : 300];
    char what[1100];
    unsigned long streams = 0, lists_calls = 0;
    for (; optind < argc; optind++) {
        size_t len;
        const size_t n = fz_gen_file(argv[optind], calls, FZ_LIBFUZZER_CALLS, &len);
        if (n == FZ_GEN_FILE_ERROR) {
            fprintf(stderr, "fixgl-fuzz-gen-check: cannot read %s\n", argv[optind]);
            return 2;
        }
        snprintf(what, sizeof what, "input %s", argv[optind]);
        failed += check(calls, n, what);
        streams++;
    }
    for (unsigned long s = 1; s <= seeds; s++) {
        const size_t n = fz_gen_seed(s, calls, 300);
        snprintf(what, sizeof what, "seed %lu", s);
        failed += check(calls, n, what);
        streams++;
        for (size_t i = 0; i < n; i++)
            lists_calls += (int)calls[i].fn == fn_calllist;
    }
    /* random bytes: a splitmix sequence, lengths 1..8192 */
    uint64_t st = 0x9e3779b97f4a7c15ull;
    static uint8_t bytes[8192];
    for (unsigned long r = 1; r <= random_inputs; r++) {
        size_t len;
        for (size_t k = 0; k < sizeof bytes; k += 8) {
            uint64_t z = (st += 0x9e3779b97f4a7c15ull);
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
            z ^= z >> 31;
            memcpy(bytes + k, &z, 8);
        }
        len = 1 + (size_t)(bytes[0] | bytes[1] << 8) % sizeof bytes;
        const size_t n = fz_gen_bytes(bytes, len, calls, FZ_LIBFUZZER_CALLS);
        snprintf(what, sizeof what, "random input %lu", r);
        failed += check(calls, n, what);
        streams++;
        for (size_t i = 0; i < n; i++)
            lists_calls += (int)calls[i].fn == fn_calllist;
    }
    printf("fixgl-fuzz-gen-check: %lu streams (%lu glCallList), %d with unbounded list work\n",
           streams, lists_calls, failed);
    return failed ? 1 : 0;
}
