/* fz_gen.h - call streams from the table of entry points.
 *
 * The same generator serves the differential campaign (a stream per seed,
 * fz_gen_seed) and the libFuzzer target (a stream decoded from the input
 * bytes, fz_gen_bytes): every choice it makes is a number drawn from an
 * fz_src, which is either a PRNG or the fuzzer's bytes. */
#ifndef FZ_GEN_H
#define FZ_GEN_H

#include "fz_table.h"

#include <stdint.h>
#include <stdio.h>

typedef struct {
    uint64_t state;          /* PRNG state (bytes == NULL) */
    const uint8_t *bytes;    /* libFuzzer input, or NULL */
    size_t len, pos;
    uint8_t *rec;            /* PRNG draws recorded as bytes, or NULL */
    size_t rec_len, rec_cap;
} fz_src;

/* Resolves the entries the structured parts of a stream use.  disabled[i]
 * (may be NULL) excludes entry i: the oracle lacks it. */
void fz_gen_init(const uint8_t *disabled);

/* Up to max calls (at least 1 when max > 0) of the stream of seed. */
size_t fz_gen_seed(uint64_t seed, fz_call *out, size_t max);
/* The stream of seed, and (*bytes, malloc'ed) the input bytes that
 * fz_gen_bytes decodes into the same stream. */
uint8_t *fz_gen_seed_bytes(uint64_t seed, fz_call *out, size_t max, size_t *len);
/* The most calls fixgl-libfuzzer decodes from one input. */
#define FZ_LIBFUZZER_CALLS 400
/* Up to max calls decoded from data (stops when the bytes run out). */
size_t fz_gen_bytes(const uint8_t *data, size_t len, fz_call *out, size_t max);

/* The calls decoded from the bytes of the file at path (a libFuzzer input),
 * as fz_gen_bytes; *len its size.  FZ_GEN_FILE_ERROR when it cannot be
 * read. */
#define FZ_GEN_FILE_ERROR ((size_t)-1)
size_t fz_gen_file(const char *path, fz_call *out, size_t max, size_t *len);

/* Fills the input arena (deterministic, the same in every process). */
void fz_fill_input_arena(uint8_t *arena, size_t size);

/* Index of the entry named name, or -1. */
int fz_find_entry(const char *name);

/* Writes calls as a C program that replays them on OSMesa or fixgl. */
void fz_print_c(FILE *f, const fz_call *calls, size_t n, const char *comment);

/* Stream files: a count then the calls. */
int fz_write_stream(const char *path, const fz_call *calls, size_t n);
fz_call *fz_read_stream(const char *path, size_t *n);

/* Input arena layout: offsets (from FZ_IN_BASE) of the regions a pointer
 * argument starts in. */
#define FZ_IN_FLOATS   (16u << 20)   /* floats in [-2, 2) */
#define FZ_IN_DOUBLES  (20u << 20)   /* doubles in [-2, 2) */
#define FZ_IN_SMALL    (24u << 20)   /* uint32 in [0, 256) */
#define FZ_IN_RANDOM   (28u << 20)   /* random bytes (and beyond 32 MB) */
/* the last 64 KB: pointers into FZ_IN_SMALL at any alignment (the index
 * lists of glMultiDrawElements read an array of pointers) */
#define FZ_IN_PTRS     (FZ_IN_SIZE - (64u << 10))
#define FZ_COLOR_OFF   (40u << 20)   /* the colour buffer, in the output arena */
#define FZ_COLOR_MAX   256           /* its largest width and height */
#define FZ_PTR_COLOR   (-1)          /* argument: the colour buffer */

#endif
