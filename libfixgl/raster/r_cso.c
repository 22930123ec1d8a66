/*
 * The cache of state objects (r_state.h "the state objects"): one per
 * context, looked up by the validation pass with an object it has just
 * built on its stack, answered with the shared immutable copy of equal
 * bytes.  A handful of objects per kind is the working set of real
 * programs (gears: three materials' worth of states; a viewer: two), so
 * the cache is a short array searched by hash; it evicts the least
 * recently used object that nobody holds once more than R_CSO_CACHE_MAX
 * are cached.
 */
#include "r_state.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "fgl_alloc.h"

struct r_cso_entry {
   uint64_t hash;
   uint64_t used;              /* the cache's clock at the last lookup */
   size_t size;
   unsigned holds;             /* r_cso_hold minus r_cso_release */
   r_cso_hold_fn on_hold;      /* r_cso_lookup_held's, or NULL */
   _Alignas(max_align_t) unsigned char obj[];
};

static struct r_cso_entry *entry_of(const void *obj)
{
   return (struct r_cso_entry *)((unsigned char *)(uintptr_t)obj -
                                 offsetof(struct r_cso_entry, obj));
}

/* FNV-1a over 64-bit words, then the tail bytes */
static uint64_t hash_bytes(const void *p, size_t size)
{
   const unsigned char *b = p;
   uint64_t h = 0xcbf29ce484222325ull ^ size;
   size_t i = 0;
   for (; i + 8 <= size; i += 8) {
      uint64_t w;
      memcpy(&w, b + i, 8);
      h = (h ^ w) * 0x100000001b3ull;
      h ^= h >> 29;
   }
   for (; i < size; i++)
      h = (h ^ b[i]) * 0x100000001b3ull;
   return h;
}

/* Drops the least recently used entry nobody holds, if there is one. */
static void evict_one(struct r_cso_cache *c)
{
   unsigned victim = c->count;
   for (unsigned i = 0; i < c->count; i++)
      if (c->entry[i]->holds == 0 && (victim == c->count || c->entry[i]->used < c->entry[victim]->used))
         victim = i;
   if (victim == c->count)
      return;
   fgl_free(c->entry[victim]);
   c->entry[victim] = c->entry[--c->count];
}

const void *r_cso_lookup(struct r_cso_cache *c, const void *obj, size_t size)
{
   return r_cso_lookup_held(c, obj, size, NULL);
}

const void *r_cso_lookup_held(struct r_cso_cache *c, const void *obj, size_t size,
                              r_cso_hold_fn on_hold)
{
   const uint64_t h = hash_bytes(obj, size);
   c->clock++;
   for (unsigned i = 0; i < c->count; i++) {
      struct r_cso_entry *e = c->entry[i];
      if (e->hash == h && e->size == size && e->on_hold == on_hold &&
          memcmp(e->obj, obj, size) == 0) {
         e->used = c->clock;
         return e->obj;
      }
   }
   if (c->count >= R_CSO_CACHE_MAX)
      evict_one(c);
   if (c->count == c->capacity) {
      const unsigned cap = c->capacity ? 2 * c->capacity : 16;
      struct r_cso_entry **n = fgl_realloc(c->entry, cap * sizeof(*n));
      if (!n)
         return NULL;
      c->entry = n;
      c->capacity = cap;
   }
   struct r_cso_entry *e = fgl_malloc(sizeof(*e) + size);
   if (!e)
      return NULL;
   e->hash = h;
   e->used = c->clock;
   e->size = size;
   e->holds = 0;
   e->on_hold = on_hold;
   memcpy(e->obj, obj, size);
   c->entry[c->count++] = e;
   return e->obj;
}

void r_cso_hold(const void *obj)
{
   if (!obj)
      return;
   struct r_cso_entry *e = entry_of(obj);
   if (e->holds++ == 0 && e->on_hold)
      e->on_hold(e->obj, true);
}

void r_cso_release(const void *obj)
{
   if (!obj)
      return;
   struct r_cso_entry *e = entry_of(obj);
   if (--e->holds == 0 && e->on_hold)
      e->on_hold(e->obj, false);
}

void r_state_hold(const struct r_state *rs)
{
   r_cso_hold(rs->fb);
   r_cso_hold(rs->rast);
   r_cso_hold(rs->dsa);
   r_cso_hold(rs->blend);
   r_cso_hold(rs->fs);
   for (int u = 0; u < R_MAX_TEX_UNITS; u++)
      r_cso_hold(rs->tex[u]);
   r_cso_hold(rs->shade_env);
}

void r_state_release(const struct r_state *rs)
{
   r_cso_release(rs->fb);
   r_cso_release(rs->rast);
   r_cso_release(rs->dsa);
   r_cso_release(rs->blend);
   r_cso_release(rs->fs);
   for (int u = 0; u < R_MAX_TEX_UNITS; u++)
      r_cso_release(rs->tex[u]);
   r_cso_release(rs->shade_env);
}

void r_cso_cache_fini(struct r_cso_cache *c)
{
   for (unsigned i = 0; i < c->count; i++) {
      /* an object still held (by the context's own state) lets go of
       * what it holds */
      if (c->entry[i]->holds && c->entry[i]->on_hold)
         c->entry[i]->on_hold(c->entry[i]->obj, false);
      fgl_free(c->entry[i]);
   }
   fgl_free(c->entry);
   memset(c, 0, sizeof(*c));
}
