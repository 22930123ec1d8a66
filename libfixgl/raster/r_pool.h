/*
 * The worker pool: threads that run the items of jobs (a scene's tiles)
 * for any context, holding no GL state.
 *
 * A job is run by the thread that submits it together with up to
 * `threads - 1` workers; items are taken in index order from shared
 * counters (see Lanes), so which thread runs which item varies, but every item runs
 * exactly once, and r_pool_run returns after all of them finished.  Jobs
 * of several submitting threads (several contexts) run at once, the
 * workers going round them in turn.  Workers are created when a job first
 * asks for them, kept across jobs and contexts, and joined by
 * r_pool_shutdown (the last context destroyed, or the library unloaded).
 *
 * Lanes: a job may split its items into `lanes` consecutive ranges, each
 * with its own counter on its own cache line.  The thread of slot k takes
 * the items of lane k mod lanes first, then those left in the other lanes
 * in turn.  A submitter that gives each lane the items of one part of the
 * framebuffer, the same every frame, keeps that part's memory in one
 * core's cache (and the threads do not contend for one counter); the
 * taking from other lanes keeps the load balanced.
 */
#ifndef FGL_R_POOL_H
#define FGL_R_POOL_H

#include <stdbool.h>

#define R_POOL_MAX_LANES 8

/* A lane's counter, 64 bytes from any other field of the job (so on a
 * cache line of its own, without asking heap or stack for alignment). */
struct r_pool_lane {
   unsigned next;           /* the next item to take (atomic) */
   unsigned end;            /* one past the lane's last item */
   char pad[56];
};

struct r_job {
   /* runs item `item`; `slot` identifies the running thread within the
    * job: 0 for the submitting thread, 1 .. threads - 1 for workers */
   void (*run)(void *arg, unsigned item, unsigned slot);
   void *arg;
   unsigned count;          /* items 0 .. count - 1 */
   unsigned threads;        /* at most this many threads (>= 1) */
   /* 0 or 1: one lane; else lane k ends before lane_end[k] (the last
    * one at count), at most R_POOL_MAX_LANES */
   unsigned lanes;
   unsigned lane_end[R_POOL_MAX_LANES];

   /* the pool's bookkeeping: each claim of an item writes its lane's
    * counter, each thread leaving the items writes `done` once */
   char pad[64];
   struct r_pool_lane lane[R_POOL_MAX_LANES];
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
