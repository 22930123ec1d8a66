/*
 * The worker pool (r_pool.h): one mutex and condition variable for the
 * list of jobs that have items left; items are claimed with an atomic
 * counter, outside the lock.
 *
 * Waking a sleeping thread costs tens of microseconds on a virtual
 * machine (a futex wake-up, an interrupt to a halted CPU), which is a
 * large part of a frame that takes a millisecond (gears): so an idle
 * worker spins a little while for the next job before it sleeps, and the
 * submitter waiting for the workers' last tiles spins before it sleeps.
 * Both spins are bounded (SPIN_NS), so an idle pool sleeps, and both
 * yield the CPU every few microseconds (sched_yield), so that on a
 * machine with more runnable threads than CPUs a spinning thread does not
 * hold a CPU that the thread it waits for (or a thread of the same
 * frame) needs; on an idle CPU the yield returns at once.
 */
#include "r_pool.h"

#include <pthread.h>
#include <sched.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>
#include "fgl_alloc.h"

/* How long a thread spins for an event (a job to join, the last workers
 * leaving a job) before it sleeps on the condition variable: about the
 * vertex stage of a small frame, so that a worker is still awake when the
 * next glFinish hands it the tiles (gears, two threads: 10% more frames
 * than with 50 us, lit200 3%). */
#define SPIN_NS 300000u

static uint64_t now_ns(void)
{
   struct timespec ts;
   clock_gettime(CLOCK_MONOTONIC, &ts);
   return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

static inline void cpu_relax(void)
{
#if defined(__x86_64__) || defined(__i386__)
   __builtin_ia32_pause();
#endif
}

/* Spins until *p != v (atomic loads), at most SPIN_NS; whether it did.
 * Every 64 pauses (a few microseconds) it yields the CPU: with both CPUs
 * shared with other processes (load 13-15 on 2 CPUs, 2026-11-30), two
 * threads' gears and lit200 ran 11 % and 16 % more frames a second and
 * took 13 % and 8 % less CPU time (README "Threads (issue 17)"). */
static bool spin_until_changed(const unsigned *p, unsigned v)
{
   uint64_t t0 = 0;
   for (unsigned i = 0;; i++) {
      if (__atomic_load_n(p, __ATOMIC_ACQUIRE) != v)
         return true;
      cpu_relax();
      if ((i & 63u) == 63u) {
         sched_yield();
         const uint64_t t = now_ns();
         if (t0 == 0)
            t0 = t;
         else if (t - t0 > SPIN_NS)
            return false;
      }
   }
}

/* the pool itself: the one piece of process-wide mutable state besides
 * the current context, and it holds no GL state */
static struct {
   pthread_mutex_t lock;
   pthread_cond_t work;       /* a job was queued, or shutdown */
   pthread_cond_t finished;   /* a worker left a job */
   struct r_job *head, *tail; /* jobs with items left to claim */
   pthread_t *threads;
   unsigned nthreads;
   bool quit;
   unsigned users;            /* r_pool_ref minus r_pool_unref */
   unsigned queued;           /* jobs appended so far (atomic, for spinning) */
} pool = {
   .lock = PTHREAD_MUTEX_INITIALIZER,
   .work = PTHREAD_COND_INITIALIZER,
   .finished = PTHREAD_COND_INITIALIZER,
};

unsigned r_pool_cpus(void)
{
   const long n = sysconf(_SC_NPROCESSORS_ONLN);
   return n > 0 ? (unsigned)n : 1u;
}

static void unlink_job(struct r_job *job)
{
   if (job->prev_job)
      job->prev_job->next_job = job->next_job;
   else if (pool.head == job)
      pool.head = job->next_job;
   if (job->next_job)
      job->next_job->prev_job = job->prev_job;
   else if (pool.tail == job)
      pool.tail = job->prev_job;
   job->prev_job = job->next_job = NULL;
}

static void append_job(struct r_job *job)
{
   job->next_job = NULL;
   job->prev_job = pool.tail;
   if (pool.tail)
      pool.tail->next_job = job;
   else
      pool.head = job;
   pool.tail = job;
}

/* A job queued for the workers (under the lock); spinning workers see
 * pool.queued change. */
static void queue_job(struct r_job *job)
{
   append_job(job);
   __atomic_fetch_add(&pool.queued, 1, __ATOMIC_RELEASE);
}

/* Claims and runs items of job until none are left. */
static void run_items(struct r_job *job, unsigned slot)
{
   unsigned ran = 0;
   const unsigned lanes = job->lanes > 1 ? job->lanes : 1;
   for (unsigned l = 0; l < lanes; l++) {
      struct r_pool_lane *lane = &job->lane[(slot + l) % lanes];
      for (;;) {
         /* (a lane's counter passes its end by at most one per thread) */
         if (__atomic_load_n(&lane->next, __ATOMIC_RELAXED) >= lane->end)
            break;
         const unsigned i = __atomic_fetch_add(&lane->next, 1, __ATOMIC_RELAXED);
         if (i >= lane->end)
            break;
         job->run(job->arg, i, slot);
         ran++;
      }
   }
   /* counted once per thread: `done` reaches `count` when the last
    * thread has left the items */
   if (ran)
      __atomic_fetch_add(&job->done, ran, __ATOMIC_RELEASE);
}

static void *worker_main(void *arg)
{
   (void)arg;
   bool spun = false;   /* spun since the last job */
   pthread_mutex_lock(&pool.lock);
   for (;;) {
      /* the first job that still takes a helper, then moved to the back
       * so that the next worker serves another one */
      struct r_job *job = pool.head;
      while (job && job->helpers + 1 >= job->threads)
         job = job->next_job;
      if (!job) {
         if (pool.quit)
            break;
         if (!spun) {
            /* a while awake first: the next job often follows soon */
            const unsigned q = __atomic_load_n(&pool.queued, __ATOMIC_RELAXED);
            spun = true;
            pthread_mutex_unlock(&pool.lock);
            spin_until_changed(&pool.queued, q);
            pthread_mutex_lock(&pool.lock);
            continue;
         }
         pthread_cond_wait(&pool.work, &pool.lock);
         continue;
      }
      spun = false;
      const unsigned slot = ++job->helpers;
      __atomic_fetch_add(&job->active, 1, __ATOMIC_RELAXED);
      unlink_job(job);
      append_job(job);
      pthread_mutex_unlock(&pool.lock);

      run_items(job, slot);

      pthread_mutex_lock(&pool.lock);
      /* no item left to claim: off the list (the submitter may have done
       * it already) */
      if (job->prev_job || job->next_job || pool.head == job)
         unlink_job(job);
      /* the last access to the job: its submitter may return now */
      __atomic_fetch_sub(&job->active, 1, __ATOMIC_RELEASE);
      pthread_cond_broadcast(&pool.finished);
   }
   pthread_mutex_unlock(&pool.lock);
   return NULL;
}

/* Makes sure `want` workers exist (under the lock); fewer when threads
 * cannot be created. */
static void ensure_workers(unsigned want)
{
   if (pool.nthreads >= want || pool.quit)
      return;
   pthread_t *t = fgl_realloc(pool.threads, want * sizeof(*t));
   if (!t)
      return;
   pool.threads = t;
   while (pool.nthreads < want) {
      if (pthread_create(&pool.threads[pool.nthreads], NULL, worker_main, NULL) != 0)
         return;
      pool.nthreads++;
   }
}

void r_pool_submit(struct r_job *job)
{
   const unsigned lanes = job->lanes > 1 ? job->lanes : 1;
   for (unsigned l = 0; l < lanes; l++) {
      job->lane[l].next = l ? job->lane_end[l - 1] : 0;
      job->lane[l].end = l + 1 < lanes ? job->lane_end[l] : job->count;
   }
   job->done = 0;
   job->helpers = 0;
   job->active = 0;
   job->prev_job = job->next_job = NULL;
   if (job->threads > 1 && job->count > 0) {
      pthread_mutex_lock(&pool.lock);
      ensure_workers(job->threads - 1);
      if (pool.nthreads > 0) {
         queue_job(job);
         pthread_cond_broadcast(&pool.work);
      }
      pthread_mutex_unlock(&pool.lock);
   }
}

bool r_pool_finished(const struct r_job *job)
{
   return __atomic_load_n(&job->done, __ATOMIC_ACQUIRE) == job->count;
}

void r_pool_wait(struct r_job *job)
{
   run_items(job, 0);

   if (job->threads > 1 && job->count > 0) {
      pthread_mutex_lock(&pool.lock);
      if (job->prev_job || job->next_job || pool.head == job)
         unlink_job(job);
      /* the items the workers claimed are finished when every worker
       * has left the job (no worker joins it once it is off the list):
       * spin a while for the last ones, then sleep */
      unsigned active = __atomic_load_n(&job->active, __ATOMIC_ACQUIRE);
      pthread_mutex_unlock(&pool.lock);
      while (active > 0 && spin_until_changed(&job->active, active))
         active = __atomic_load_n(&job->active, __ATOMIC_ACQUIRE);
      if (active > 0) {
         pthread_mutex_lock(&pool.lock);
         while (__atomic_load_n(&job->active, __ATOMIC_ACQUIRE) > 0)
            pthread_cond_wait(&pool.finished, &pool.lock);
         pthread_mutex_unlock(&pool.lock);
      }
   }
   /* pairs with the workers' release increments: their writes are
    * visible to the caller now */
   (void)__atomic_load_n(&job->done, __ATOMIC_ACQUIRE);
}

void r_pool_run(struct r_job *job)
{
   r_pool_submit(job);
   r_pool_wait(job);
}

void r_pool_shutdown(void)
{
   pthread_mutex_lock(&pool.lock);
   pool.quit = true;
   pthread_cond_broadcast(&pool.work);
   const unsigned n = pool.nthreads;
   pthread_t *t = pool.threads;
   pool.threads = NULL;
   pool.nthreads = 0;
   pthread_mutex_unlock(&pool.lock);
   for (unsigned i = 0; i < n; i++)
      pthread_join(t[i], NULL);
   fgl_free(t);
   pthread_mutex_lock(&pool.lock);
   pool.quit = false;
   pthread_mutex_unlock(&pool.lock);
}

void r_pool_ref(void)
{
   pthread_mutex_lock(&pool.lock);
   pool.users++;
   pthread_mutex_unlock(&pool.lock);
}

void r_pool_unref(void)
{
   pthread_mutex_lock(&pool.lock);
   const bool last = --pool.users == 0;
   pthread_mutex_unlock(&pool.lock);
   if (last)
      r_pool_shutdown();
}

/* the library unloaded (or the process exits) with workers alive */
__attribute__((destructor)) static void pool_fini(void)
{
   r_pool_shutdown();
}
