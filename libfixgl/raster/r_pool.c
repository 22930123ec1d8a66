/*
 * The worker pool (r_pool.h): one mutex and condition variable for the
 * list of jobs that have items left; items are claimed with an atomic
 * counter, outside the lock.
 */
#include "r_pool.h"

#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>
#include "fgl_alloc.h"

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

/* Claims and runs items of job until none are left. */
static void run_items(struct r_job *job, unsigned slot)
{
   for (;;) {
      const unsigned i = __atomic_fetch_add(&job->next, 1, __ATOMIC_RELAXED);
      if (i >= job->count)
         return;
      job->run(job->arg, i, slot);
      __atomic_fetch_add(&job->done, 1, __ATOMIC_RELEASE);
   }
}

static void *worker_main(void *arg)
{
   (void)arg;
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
         pthread_cond_wait(&pool.work, &pool.lock);
         continue;
      }
      const unsigned slot = ++job->helpers;
      job->active++;
      unlink_job(job);
      append_job(job);
      pthread_mutex_unlock(&pool.lock);

      run_items(job, slot);

      pthread_mutex_lock(&pool.lock);
      /* no item left to claim: off the list (the submitter may have done
       * it already) */
      if (job->prev_job || job->next_job || pool.head == job)
         unlink_job(job);
      job->active--;
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
   job->next = 0;
   job->done = 0;
   job->helpers = 0;
   job->active = 0;
   job->prev_job = job->next_job = NULL;
   if (job->threads > 1 && job->count > 0) {
      pthread_mutex_lock(&pool.lock);
      ensure_workers(job->threads - 1);
      if (pool.nthreads > 0) {
         append_job(job);
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
       * has left the job */
      while (job->active > 0)
         pthread_cond_wait(&pool.finished, &pool.lock);
      pthread_mutex_unlock(&pool.lock);
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
