/* fc_run.h - runs the two renderers over a list of cases: chunks of cases
 * per renderer process, up to `jobs` processes at once, a crashed or timed
 * out case is marked failed and the renderer restarts after it. */
#ifndef FC_RUN_H
#define FC_RUN_H

#include <stddef.h>

enum { FC_ORACLE = 0, FC_FIXGL = 1 };

enum fc_side_state { FC_PENDING = 0, FC_DONE, FC_FAILED };

struct fc_side_result {
    unsigned char *data;        /* the case's records, CASE..END (partial if failed) */
    size_t len;
    enum fc_side_state state;
    int cached;                 /* FC_DONE in the oracle cache: data is read
                                 * just before the item is handed over */
    char why[1024];             /* failure description */
};

struct fc_item {
    char *name, *tags, *replay;
    int tolerance;              /* colour tolerance in LSB (reference cases), else 0 */
    struct fc_side_result side[2];
};

struct fc_cache;

struct fc_run_cfg {
    const char *renderer[2];    /* executable paths */
    const char *extra_arg[2];   /* optional extra argument (test-only --perturb) */
    const char *work_dir;       /* tmp/ and logs/ are created below it */
    int jobs;
    struct fc_cache *oracle_cache;  /* or NULL (fc_cache.h) */
    size_t oracle_cached;       /* out: cases whose oracle side came from the cache */
};

/* Called in item order once both sides of an item are finished. */
typedef void (*fc_item_ready)(void *ud, struct fc_item *item, size_t index);

/* Runs all items; with an oracle cache, the oracle side of a cached case
 * is read from it (cfg->oracle_cached counts them) and every case the
 * oracle finishes is stored in it.  info[side][0] / [1] receive malloc'ed GL_RENDERER /
 * GL_VERSION strings.  Returns 0, or -1 if a renderer could not start or
 * refused to run (the reason is printed). */
int fc_run_items(struct fc_run_cfg *cfg, struct fc_item *items, size_t n,
                 fc_item_ready ready, void *ud, char *info[2][2]);

/* Runs argv[0] with argv and returns its stdout (malloc'ed, NUL-terminated),
 * or NULL if it could not run or failed. */
char *fc_run_capture(const char *const *argv);

/* The whole file at path (malloc'ed, *len bytes, one more byte allocated
 * for a terminating NUL), or NULL if it cannot be opened, read or held. */
unsigned char *fc_read_file(const char *path, size_t *len);

#endif
