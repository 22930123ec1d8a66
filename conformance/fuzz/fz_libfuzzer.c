/* fz_libfuzzer.c - fixgl-libfuzzer: coverage-guided fuzzing of fixgl alone
 * (clang -fsanitize=fuzzer,address,undefined; meson -Dfuzzer=true).
 *
 * The input bytes drive the same generator as the differential campaign
 * (fz_gen_bytes: every choice it makes reads the next bytes), so a mutation
 * changes entry points, enums, values and structure alike.  Each input runs
 * in a fresh context, which is destroyed afterwards: a crash, a hang
 * (-timeout), a leak or any sanitizer report is a finding.  The seed corpus
 * (fixgl-libfuzzer-corpus DIR N) holds the byte encodings of streams of
 * the first N seeds.
 *
 * libFuzzer's statistics count inputs; the campaigns of issue 18 count GL
 * calls.  At a normal exit (libFuzzer's -runs, -max_total_time, the end
 * of a -merge or of a run over files) the target prints
 * "fixgl-libfuzzer: N calls in M inputs" to stderr and, when
 * FIXGL_FUZZ_CALLS_FILE names a file, appends the line
 * "N M" to it in one write (O_APPEND), so the processes of -jobs/-workers
 * or of several chunks of a long campaign add up (long-campaign.sh).  A
 * crash or a timeout ends the process without it: that run's count is
 * lost, and the finding is what matters. */
#include "fz_exec.h"
#include "fz_gen.h"

#include <fcntl.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static fz_call calls[FZ_LIBFUZZER_CALLS];
static uint64_t calls_run, inputs_run;

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void report_counts(void)
{
    const char *path = getenv("FIXGL_FUZZ_CALLS_FILE");
    fprintf(stderr, "fixgl-libfuzzer: %" PRIu64 " calls in %" PRIu64 " inputs\n",
            calls_run, inputs_run);
    if (path && *path) {
        char line[64];
        const int len = snprintf(line, sizeof line, "%" PRIu64 " %" PRIu64 "\n",
                                 calls_run, inputs_run);
        const int fd = open(path, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0 || write(fd, line, (size_t)len) != len)
            fprintf(stderr, "fixgl-libfuzzer: cannot append the counts to %s\n", path);
        if (fd >= 0)
            close(fd);
    }
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    setenv("FIXGL_NUM_THREADS", "1", 0);
    if (fz_exec_setup(NULL) < 0)
        abort();
    fz_gen_init(NULL);
    atexit(report_counts);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const size_t n = fz_gen_bytes(data, size, calls, FZ_LIBFUZZER_CALLS);
    OSMesaContext ctx = fz_exec_context();
    if (!ctx)
        abort();
    calls_run += fz_exec_run(calls, n, NULL);
    inputs_run++;
    fz_exec_final(NULL);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return 0;
}
