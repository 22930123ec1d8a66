/* fz_corpus.c - fixgl-libfuzzer-corpus DIR N [CALLS]: writes the seed corpus
 * of fixgl-libfuzzer, the byte encodings of the first N seeds' streams.
 *
 * fz_gen_bytes reads each choice as the next 4 bytes (big-endian) and takes
 * it modulo the number of alternatives, so the bytes of a stream are the
 * PRNG's 32-bit draws of the same seed: the corpus decodes to exactly the
 * streams the differential campaign runs (fz_gen.c). */
#include "fz_gen.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: %s DIR N [CALLS]\n", argv[0]);
        return 2;
    }
    const unsigned n = (unsigned)atoi(argv[2]);
    const size_t max = argc > 3 ? (size_t)atoi(argv[3]) : 100;
    fz_call *calls = malloc(max * sizeof *calls);
    fz_gen_init(NULL);
    for (unsigned s = 1; s <= n; s++) {
        char path[1024];
        size_t len = 0;
        uint8_t *bytes = fz_gen_seed_bytes(s, calls, max, &len);
        snprintf(path, sizeof path, "%s/seed-%u", argv[1], s);
        FILE *f = fopen(path, "wb");
        if (!f || fwrite(bytes, 1, len, f) != len || fclose(f) != 0) {
            perror(path);
            return 1;
        }
        free(bytes);
    }
    free(calls);
    return 0;
}
