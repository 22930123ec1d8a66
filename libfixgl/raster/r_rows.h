/*
 * Row stores into memory that is not in this core's cache: a tile's lazy
 * clear (rows of 64 values, r_clear.c) and the copy of rows into the
 * user's buffer (osmesa.c).
 *
 * glibc's memset, wmemset and memcpy store rows of a few hundred bytes
 * with vector stores, and each store that misses reads its line first
 * (a read for ownership) only for the line to be overwritten whole.  The
 * string instructions (`rep stosl`, `rep movsb`, on CPUs with ERMSB)
 * write whole lines without reading them and still leave them in the
 * cache (unlike non-temporal stores, which send them to memory: slower
 * here, README "Threads (issue 17)").  On lines already in the cache
 * they cost the same as the vector stores.  glibc takes them itself only
 * from a few kilobytes up.
 *
 * Under AddressSanitizer and ThreadSanitizer the library calls stay, so
 * that the sanitizers see the accesses.
 */
#ifndef FGL_R_ROWS_H
#define FGL_R_ROWS_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <wchar.h>

#if defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define R_ROWS_STRING_OPS 1
#endif

/* from this many bytes a row takes the string instruction */
#define R_ROWS_MIN_BYTES 128u

/* n 32-bit values v at p (4-byte aligned) */
static inline void r_rows_fill32(void *p, uint32_t v, size_t n)
{
#ifdef R_ROWS_STRING_OPS
   if (n * 4u >= R_ROWS_MIN_BYTES) {
      __asm__ volatile("rep stosl" : "+D"(p), "+c"(n) : "a"(v) : "memory");
      return;
   }
#endif
#if __SIZEOF_WCHAR_T__ == 4
   wmemset(p, (wchar_t)v, n);
#else
   uint32_t *q = p;
   for (size_t i = 0; i < n; i++)
      q[i] = v;
#endif
}

/* n bytes from s to d (not overlapping) */
static inline void r_rows_copy(void *restrict d, const void *restrict s, size_t n)
{
#ifdef R_ROWS_STRING_OPS
   if (n >= R_ROWS_MIN_BYTES) {
      __asm__ volatile("rep movsb" : "+D"(d), "+S"(s), "+c"(n) : : "memory");
      return;
   }
#endif
   memcpy(d, s, n);
}

#endif
