/* fc_cache.h - a content-keyed cache of the oracle's per-case records.
 *
 * The oracle's render of a case depends on the oracle renderer (its binary,
 * with the case code compiled in, and the shared libraries it loads: Mesa),
 * the host's CPU, the case name (random scenes carry their seed and index
 * in it), the extra renderer argument and a few environment variables
 * (FC_*, Mesa's); never on fixgl's configuration (FIXGL_NUM_THREADS,
 * FIXGL_KERNELS).  The cache key hashes all of these, so runs that compare
 * several fixgl configurations with the same cases render each case on the
 * oracle once.  Layout: ROOT/<key>/<case name, '/' as '@'>.rec holds the
 * case's records (CASE..END) exactly as the renderer wrote them;
 * ROOT/<key>/info-renderer and info-version its GL_RENDERER / GL_VERSION.
 * Only cases the oracle finished (FC_END_OK) are stored; entries are
 * written to a temporary file and renamed, so concurrent runs are safe. */
#ifndef FC_CACHE_H
#define FC_CACHE_H

#include <stddef.h>

struct fc_cache;

/* Opens (creates) the cache of `renderer` run with `extra_arg` (may be
 * NULL) below root.  NULL, with the reason printed, when the key cannot be
 * computed or the directory not created, or when FC_TRACE is set (a trace
 * needs the render to happen). */
struct fc_cache *fc_cache_open(const char *root, const char *renderer, const char *extra_arg);
void fc_cache_close(struct fc_cache *c);

/* The directory of this key. */
const char *fc_cache_dir(const struct fc_cache *c);

/* The stored records of case `name` (malloc'ed), or NULL. */
unsigned char *fc_cache_load(const struct fc_cache *c, const char *name, size_t *len);
void fc_cache_store(const struct fc_cache *c, const char *name, const unsigned char *data, size_t len);

/* which 0: GL_RENDERER, 1: GL_VERSION (the order of fc_run_items' info). */
char *fc_cache_load_info(const struct fc_cache *c, int which);
void fc_cache_store_info(const struct fc_cache *c, int which, const char *text);

#endif
