/*
 * fgl_alloc.h - every allocation of libfixgl goes through these wrappers
 * (issue 18 §4: resource exhaustion).
 *
 * fgl_malloc, fgl_calloc, fgl_realloc and fgl_free behave as their libc
 * counterparts (internal, hidden like the rest of the library).  A caller
 * that gets NULL raises GL_OUT_OF_MEMORY (or fails the OSMesa call) and
 * leaves the state as it was; nothing else may assume an allocation
 * succeeds.
 *
 * Failure injection (test builds only: FGL_ALLOC_FAIL_INJECTION, which the
 * build defines for the objects of the suite `robust`, never for the
 * library itself): fgl_alloc_fail_at(n) makes the n-th allocation from
 * then on return NULL (one allocation: later ones succeed again, so the
 * recovery is exercised too); fgl_alloc_count() counts the allocations
 * made so far and fgl_alloc_failed() whether the injected failure has
 * happened.  Counted are fgl_malloc, fgl_calloc, and fgl_realloc to a
 * non-zero size, on every thread (atomics: the raster pool's workers
 * allocate too).
 */
#ifndef FGL_ALLOC_H
#define FGL_ALLOC_H

#include <stddef.h>

void *fgl_malloc(size_t size);
void *fgl_calloc(size_t n, size_t size);
void *fgl_realloc(void *p, size_t size);
/* size bytes at a multiple of align (a power of two, a multiple of
 * sizeof(void *)); freed with fgl_free */
void *fgl_aligned_alloc(size_t align, size_t size);
void fgl_free(void *p);

/* Reference-counted blocks: storage that outlives its owner while someone
 * else still reads it (texel images, which a pending scene of another
 * context sharing the texture may still sample: main/teximage.c, state.c
 * update_tex_units).  fgl_rc_alloc gives size bytes (zeroed if asked),
 * aligned as malloc's, with one reference, or NULL; fgl_rc_hold adds a
 * reference and fgl_rc_release drops one, freeing the block with the
 * last.  Both ignore NULL.  The count is atomic: any thread may drop. */
void *fgl_rc_alloc(size_t size, int zeroed);
void fgl_rc_hold(const void *p);
void fgl_rc_release(const void *p);

#ifdef FGL_ALLOC_FAIL_INJECTION
void fgl_alloc_fail_at(long n);
long fgl_alloc_count(void);
int fgl_alloc_failed(void);
#endif

#endif
