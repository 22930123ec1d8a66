/* fz_libfuzzer.c - fixgl-libfuzzer: coverage-guided fuzzing of fixgl alone
 * (clang -fsanitize=fuzzer,address,undefined; meson -Dfuzzer=true).
 *
 * The input bytes drive the same generator as the differential campaign
 * (fz_gen_bytes: every choice it makes reads the next bytes), so a mutation
 * changes entry points, enums, values and structure alike.  Each input runs
 * in a fresh context, which is destroyed afterwards: a crash, a hang
 * (-timeout), a leak or any sanitizer report is a finding.  The seed corpus
 * (fixgl-libfuzzer-corpus DIR N) holds the byte encodings of streams of
 * the first N seeds. */
#include "fz_exec.h"
#include "fz_gen.h"

#include <stdlib.h>

#define MAX_CALLS 400

static fz_call calls[MAX_CALLS];

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    setenv("FIXGL_NUM_THREADS", "1", 0);
    if (fz_exec_setup(NULL) < 0)
        abort();
    fz_gen_init(NULL);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const size_t n = fz_gen_bytes(data, size, calls, MAX_CALLS);
    OSMesaContext ctx = fz_exec_context();
    if (!ctx)
        abort();
    fz_exec_run(calls, n, NULL);
    fz_exec_final(NULL);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return 0;
}
