/*
 * The worker pool: threads that run the items of jobs (a scene's tiles)
 * for any context, holding no GL state.
 *
 * A job is run by the thread that submits it together with up to
 * `threads - 1` workers; items are taken in index order from a shared
 * counter, so which thread runs which item varies, but every item runs
 * exactly once, and r_pool_run returns after all of them finished.  Jobs
 * of several submitting threads (several contexts) run at once, the
 * workers going round them in turn.  Workers are created when a job first
 * asks for them, kept across jobs and contexts, and joined by
 * r_pool_shutdown (the last context destroyed, or the library unloaded).
 */
#ifndef FGL_R_POOL_H
#define FGL_R_POOL_H

#include <stdbool.h>

struct r_job {
   /* runs item `item`; `slot` identifies the running thread within the
    * job: 0 for the submitting thread, 1 .. threads - 1 for workers */
   void (*run)(void *arg, unsigned item, unsigned slot);
   void *arg;
   unsigned count;          /* items 0 .. count - 1 */
   unsigned threads;        /* at most this many threads (>= 1) */

   /* the pool's bookkeeping */
   unsigned next;           /* the next item to take (atomic) */
   unsigned done;           /* items finished (atomic) */
   unsigned helpers;        /* workers that joined (under the pool lock) */
   unsigned active;         /* workers inside the job (under the pool lock) */
   struct r_job *prev_job, *next_job;
};

/* Runs every item of job (threads > 1 may use workers); returns when all
 * are done.  Any thread may call it, for different jobs at once.  It is
 * r_pool_submit then r_pool_wait. */
void r_pool_run(struct r_job *job);

/* Hands job to the workers (threads > 1: up to threads - 1 of them) and
 * returns at once; the job and what it reads must stay alive and
 * unchanged until r_pool_wait(job) returns, which must be called once. */
void r_pool_submit(struct r_job *job);

/* Whether every item of a submitted job has finished (then r_pool_wait
 * does not block for long: it only waits for the workers to leave). */
bool r_pool_finished(const struct r_job *job);

/* The caller runs the items of a submitted job that no worker took, then
 * waits until every item has finished and every worker has left the job;
 * the items' writes are visible to the caller afterwards. */
void r_pool_wait(struct r_job *job);

/* Joins every worker (no job may be running).  The next job with
 * threads > 1 creates them again. */
void r_pool_shutdown(void);

/* The contexts that may run jobs: the pool joins its workers when the
 * last one is gone (r_pool_unref). */
void r_pool_ref(void);
void r_pool_unref(void);

/* The number of online CPUs (the default number of threads). */
unsigned r_pool_cpus(void);

#endif
