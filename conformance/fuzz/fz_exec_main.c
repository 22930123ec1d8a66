/* fz_exec_main.c - the fuzzer's executor, built once per library:
 * fixgl-fuzz-exec-fixgl and fixgl-fuzz-exec-osmesa (FC_ORACLE).
 *
 *   fixgl-fuzz-exec-X --missing            names of table entries the library lacks
 *   fixgl-fuzz-exec-X STREAM RESULT [SECONDS]
 *
 * Runs the stream file in a fresh context and writes RESULT: the number of
 * calls, one fz_result per call, then the fz_final digests.  SIGALRM after
 * SECONDS (default 10) ends a hung stream; the runner tells a crash, a hang
 * and a clean exit apart by the exit status.  The oracle runs llvmpipe with
 * one thread (LP_NUM_THREADS=1), as the conformance renderer does. */
#include "fz_exec.h"
#include "fz_gen.h"

#include <fixgl/version.h>

#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* the entry points an executor lacks, one flag each (file scope: it lives
 * as long as the process, on every return path) */
static uint8_t *missing;

#ifdef FC_ORACLE
#define FZ_EXEC_NAME "fixgl-fuzz-exec-osmesa"
#else
#define FZ_EXEC_NAME "fixgl-fuzz-exec-fixgl"
#endif
#define FZ_EXEC_USAGE "usage: %s --missing | --version | STREAM RESULT [SECONDS]\n"

int main(int argc, char **argv)
{
    missing = calloc(fz_table_count, 1);
    size_t n;
    fz_call *calls;
    fz_result *res;
    fz_final fin;
    FILE *f;

#ifdef FC_ORACLE
    setenv("LP_NUM_THREADS", "1", 1);
#endif
    if (!missing || fz_exec_setup(missing) < 0) {
        fprintf(stderr, "fuzz-exec: cannot map the arenas\n");
        return 3;
    }
    static const struct option longopts[] = {
        { "missing", no_argument, NULL, 'm' },
        { "version", no_argument, NULL, 'V' },
        { "help", no_argument, NULL, 'h' },
        { NULL, 0, NULL, 0 },
    };
    int ch, list_missing = 0, bad = 0;
    while ((ch = getopt_long(argc, argv, "h", longopts, NULL)) != -1) {
        switch (ch) {
        case 'm': list_missing = 1; break;
        case 'V': puts(FIXGL_VERSION_BANNER(FZ_EXEC_NAME)); return 0;
        case 'h': printf(FZ_EXEC_USAGE, argv[0]); return 0;
        default: bad = 1; break;
        }
    }
    const int nargs = argc - optind;
    if (list_missing && !bad && nargs == 0) {
        for (size_t i = 0; i < fz_table_count; i++)
            if (missing[i])
                printf("%s\n", fz_table[i].name);
        return 0;
    }
    if (bad || list_missing || nargs < 2 || nargs > 3) {
        fprintf(stderr, FZ_EXEC_USAGE, argv[0]);
        return 2;
    }
    argv += optind - 1;   /* argv[1] STREAM, argv[2] RESULT, argv[3] SECONDS */
    alarm(nargs == 3 ? (unsigned)atoi(argv[3]) : 10u);
    if (!(calls = fz_read_stream(argv[1], &n))) {
        fprintf(stderr, "fuzz-exec: cannot read %s\n", argv[1]);
        return 2;
    }
    if (!fz_exec_context()) {
        fprintf(stderr, "fuzz-exec: cannot create a context\n");
        return 3;
    }
    res = calloc(n ? n : 1, sizeof *res);
    fz_exec_run(calls, n, res);
    fz_exec_final(&fin);
    if (!(f = fopen(argv[2], "wb")))
        return 2;
    uint64_t count = n;
    fwrite(&count, sizeof count, 1, f);
    fwrite(res, sizeof *res, n, f);
    fwrite(&fin, sizeof fin, 1, f);
    return fclose(f) == 0 ? 0 : 2;
}
