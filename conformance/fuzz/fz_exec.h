/* fz_exec.h - running a call stream in the library the executable links
 * (fz_exec.c); used by the differential executors and the libFuzzer
 * target. */
#ifndef FZ_EXEC_H
#define FZ_EXEC_H

#include "fz_table.h"

#define FZ_UNCHECKED 0xfffeu   /* between glBegin and glEnd: no glGetError */
#define FZ_SKIPPED   0xfffdu   /* the library lacks the entry point */

typedef struct {
    uint32_t err;       /* glGetError after the call */
    uint32_t ret;       /* its result (pointers: non-NULL) */
    uint64_t out;       /* digest of what it wrote through its output pointers */
} fz_result;

typedef struct {
    uint64_t color, depth, stencil, walk, persist;
} fz_final;

/* Maps the arenas, fills the input arena and resolves the entry points;
 * missing[i] (may be NULL) is set for entries the library lacks.  Returns
 * their number, or -1 when the arenas cannot be mapped. */
int fz_exec_setup(uint8_t *missing);
/* A context (RGBA, depth 24, stencil 8, accum 16) current on the colour
 * buffer (64x64 of a 256x256 area of zeros), every buffer cleared. */
OSMesaContext fz_exec_context(void);
/* Runs the calls; res (may be NULL) receives one result per call.
 * Returns the number of entry-point calls issued (the stream's calls the
 * library has, not the executor's glGetError checks). */
size_t fz_exec_run(const fz_call *calls, size_t n, fz_result *res);
/* Ends an open list, render mode and glBegin, walks the state and reads
 * the buffers back, and (f not NULL) digests them into f. */
void fz_exec_final(fz_final *f);

#endif
