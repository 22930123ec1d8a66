/*
 * fgl_alloc.c - the allocation wrappers and, in test builds, failure
 * injection (fgl_alloc.h).
 */
#include "fgl_alloc.h"

#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#ifdef FGL_ALLOC_FAIL_INJECTION

/* Test builds only (the objects of the suite `robust`): the allocation
 * counter and the one that is to fail. */
static atomic_long alloc_count;
static atomic_long fail_at;
static atomic_int failed;

void fgl_alloc_fail_at(long n)
{
   atomic_store(&failed, 0);
   atomic_store(&fail_at, n > 0 ? atomic_load(&alloc_count) + n : 0);
}

long fgl_alloc_count(void) { return atomic_load(&alloc_count); }
int fgl_alloc_failed(void) { return atomic_load(&failed); }

/* 1 when this allocation is the one to fail */
static int inject(void)
{
   long k = atomic_fetch_add(&alloc_count, 1) + 1;
   if (k == atomic_load(&fail_at)) {
      atomic_store(&failed, 1);
      return 1;
   }
   return 0;
}
#else
static inline int inject(void) { return 0; }
#endif

void *fgl_malloc(size_t size)
{
   return inject() ? NULL : malloc(size);
}

void *fgl_calloc(size_t n, size_t size)
{
   return inject() ? NULL : calloc(n, size);
}

void *fgl_realloc(void *p, size_t size)
{
   if (size == 0 || !inject())
      return realloc(p, size);
   return NULL;
}

void *fgl_aligned_alloc(size_t align, size_t size)
{
   void *p = NULL;
   if (inject() || posix_memalign(&p, align, size ? size : align) != 0)
      return NULL;
   return p;
}

void fgl_free(void *p)
{
   free(p);
}

/* A reference-counted block: the count, then the caller's bytes at
 * malloc's alignment. */
struct rc_block {
   atomic_size_t refs;
   _Alignas(max_align_t) unsigned char data[];
};

static struct rc_block *rc_block_of(const void *p)
{
   return (struct rc_block *)((unsigned char *)(uintptr_t)p - offsetof(struct rc_block, data));
}

void *fgl_rc_alloc(size_t size, int zeroed)
{
   if (size > SIZE_MAX - sizeof(struct rc_block))
      return NULL;
   struct rc_block *b = zeroed ? fgl_calloc(1, sizeof(*b) + size) : fgl_malloc(sizeof(*b) + size);
   if (!b)
      return NULL;
   atomic_init(&b->refs, 1);
   return b->data;
}

void fgl_rc_hold(const void *p)
{
   if (p)
      atomic_fetch_add_explicit(&rc_block_of(p)->refs, 1, memory_order_relaxed);
}

void fgl_rc_release(const void *p)
{
   if (!p)
      return;
   struct rc_block *b = rc_block_of(p);
   /* the last reference frees: what the other holders wrote before
    * dropping theirs happens before the free */
   if (atomic_fetch_sub_explicit(&b->refs, 1, memory_order_acq_rel) == 1)
      fgl_free(b);
}
