/* fc_run.c - renderer process scheduling (see fc_run.h). */
#include "fc_run.h"
#include "fc_cache.h"
#include "fc_record.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static const char *const side_name[2] = { "oracle", "fixgl" };

struct task {
    int side;
    size_t first, last;         /* items [first, last) */
    int id;
    pid_t pid;
    char out[512], log[512];
};

struct sched {
    const struct fc_run_cfg *cfg;
    struct fc_item *items;
    size_t n, next_ready;
    struct task *queue;         /* FIFO of tasks not started */
    size_t qhead, qtail, qcap;
    struct task *running;
    int nrunning, next_id, fatal;
    char *(*info)[2];
    fc_item_ready ready;
    void *ud;
};

static void push_task(struct sched *s, int side, size_t first, size_t last)
{
    if (s->qtail == s->qcap) {
        s->qcap = s->qcap ? 2 * s->qcap : 64;
        s->queue = realloc(s->queue, s->qcap * sizeof *s->queue);
    }
    memset(&s->queue[s->qtail], 0, sizeof s->queue[0]);
    s->queue[s->qtail].side = side;
    s->queue[s->qtail].first = first;
    s->queue[s->qtail].last = last;
    s->queue[s->qtail].id = s->next_id++;
    s->qtail++;
}

static int start_task(struct sched *s, struct task *t)
{
    const struct fc_run_cfg *cfg = s->cfg;
    size_t nargs = 5 + (t->last - t->first);
    const char **argv = calloc(nargs + 1, sizeof *argv);
    size_t a = 0;

    snprintf(t->out, sizeof t->out, "%s/tmp/%s-t%d.rec", cfg->work_dir, side_name[t->side], t->id);
    snprintf(t->log, sizeof t->log, "%s/logs/%s-t%d.log", cfg->work_dir, side_name[t->side], t->id);
    argv[a++] = cfg->renderer[t->side];
    if (cfg->extra_arg[t->side])
        argv[a++] = cfg->extra_arg[t->side];
    argv[a++] = "--out";
    argv[a++] = t->out;
    for (size_t i = t->first; i < t->last; i++)
        argv[a++] = s->items[i].name;
    t->pid = fork();
    if (t->pid == 0) {
        int fd = open(t->log, O_WRONLY | O_CREAT | O_TRUNC, 0666);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
        }
        execv(argv[0], (char *const *)argv);
        fprintf(stderr, "cannot execute %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    free(argv);
    if (t->pid < 0) {
        fprintf(stderr, "fixgl-conform: fork: %s\n", strerror(errno));
        return 0;
    }
    return 1;
}

static void print_log(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[512];
    if (!f)
        return;
    while (fgets(line, sizeof line, f))
        fprintf(stderr, "  | %s", line);
    fclose(f);
}

/* The whole file at path, with one more byte allocated after its len
 * bytes (room for a terminating NUL); NULL if it cannot be opened, read or
 * held. */
unsigned char *fc_read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf = NULL;
    size_t cap = 0, n = 0, got;
    *len = 0;
    if (!f)
        return NULL;
    do {
        if (n == cap) {
            cap = cap ? 2 * cap : 1 << 16;
            unsigned char *grown = realloc(buf, cap + 1);
            if (!grown) {
                free(buf);
                fclose(f);
                return NULL;
            }
            buf = grown;
        }
        got = fread(buf + n, 1, cap - n, f);
        n += got;
    } while (got > 0);
    if (ferror(f)) {
        free(buf);
        fclose(f);
        return NULL;
    }
    fclose(f);
    *len = n;
    return buf;
}

static void describe_exit(int status, const char *log, char *out, size_t size)
{
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGPROF)
        snprintf(out, size, "timed out: CPU time limit (log %s)", log);
    else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
        snprintf(out, size, "timed out: wall-clock limit (log %s)", log);
    else if (WIFSIGNALED(status))
        snprintf(out, size, "crashed: signal %d (%s) (log %s)", WTERMSIG(status),
                 strsignal(WTERMSIG(status)), log);
    else if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
        snprintf(out, size, "renderer exited with status %d (log %s)", WEXITSTATUS(status), log);
    else
        snprintf(out, size, "renderer stopped before the end of the case (log %s)", log);
}

static void store(struct fc_side_result *r, const unsigned char *p, size_t len, enum fc_side_state st)
{
    r->data = malloc(len ? len : 1);
    memcpy(r->data, p, len);
    r->len = len;
    r->state = st;
}

/* Parses the output of a finished task; requeues what it did not run. */
static void finish_task(struct sched *s, struct task *t, int status)
{
    size_t len, pos = 0, start = 0, k = t->first;
    unsigned char *buf = fc_read_file(t->out, &len);
    struct fc_rec r;
    int in_case = 0;
    int clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;

    for (;;) {
        size_t here = pos;
        if (!buf || k >= t->last || !fc_rec_next(buf, len, &pos, &r))
            break;
        if (r.kind == FC_REC_INFO) {
            int w = fc_rec_label_is(&r, "version");
            if (!s->info[t->side][w]) {
                s->info[t->side][w] = malloc(r.payload_len + 1);
                memcpy(s->info[t->side][w], r.payload, r.payload_len);
                s->info[t->side][w][r.payload_len] = 0;
                if (t->side == FC_ORACLE && s->cfg->oracle_cache)
                    fc_cache_store_info(s->cfg->oracle_cache, w, s->info[t->side][w]);
            }
        } else if (r.kind == FC_REC_CASE) {
            if (!fc_rec_label_is(&r, s->items[k].name)) {
                fprintf(stderr, "fixgl-conform: %s renderer ran \"%.*s\", expected \"%s\"\n",
                        side_name[t->side], (int)r.label_len, r.label, s->items[k].name);
                s->fatal = 1;
                break;
            }
            start = here;
            in_case = 1;
        } else if (r.kind == FC_REC_END && in_case) {
            struct fc_side_result *res = &s->items[k++].side[t->side];
            int32_t st = FC_END_OK;
            memcpy(&st, r.payload, r.payload_len >= sizeof st ? sizeof st : 0);
            store(res, buf + start, pos - start, st == FC_END_OK ? FC_DONE : FC_FAILED);
            if (t->side == FC_ORACLE && st == FC_END_OK && s->cfg->oracle_cache)
                fc_cache_store(s->cfg->oracle_cache, s->items[k - 1].name, buf + start, pos - start);
            if (st != FC_END_OK)        /* the harness rejected the case (e.g. frame count) */
                snprintf(res->why, sizeof res->why, "harness: %.*s",
                         (int)(r.payload_len > sizeof st ? r.payload_len - sizeof st : 0),
                         (const char *)r.payload + sizeof st);
            in_case = 0;
        }
    }
    if (!s->fatal && k < t->last) {
        struct fc_side_result *res = &s->items[k].side[t->side];
        if (!in_case && k == t->first && WIFEXITED(status) && WEXITSTATUS(status) != 0) {
            /* nothing ran: the renderer could not start or refused (wrong oracle) */
            fprintf(stderr, "fixgl-conform: the %s renderer %s failed to start (status %d):\n",
                    side_name[t->side], s->cfg->renderer[t->side], WEXITSTATUS(status));
            print_log(t->log);
            s->fatal = 1;
        } else {
            store(res, in_case ? buf + start : (const unsigned char *)"", in_case ? len - start : 0, FC_FAILED);
            describe_exit(status, t->log, res->why, sizeof res->why);
            if (++k < t->last)
                push_task(s, t->side, k, t->last);
        }
    }
    free(buf);
    remove(t->out);
    if (clean) {
        struct stat st;
        if (stat(t->log, &st) == 0 && st.st_size == 0)
            remove(t->log);
    }
}

static int load_cached(struct fc_cache *cache, struct fc_item *item, int keep);

static void flush_ready(struct sched *s)
{
    while (s->next_ready < s->n && s->items[s->next_ready].side[0].state != FC_PENDING &&
           s->items[s->next_ready].side[1].state != FC_PENDING) {
        struct fc_side_result *o = &s->items[s->next_ready].side[FC_ORACLE];
        if (o->cached && !load_cached(s->cfg->oracle_cache, &s->items[s->next_ready], 1)) {
            store(o, (const unsigned char *)"", 0, FC_FAILED);
            snprintf(o->why, sizeof o->why, "its entry in the oracle cache %s changed during the run",
                     fc_cache_dir(s->cfg->oracle_cache));
        }
        o->cached = 0;
        s->ready(s->ud, &s->items[s->next_ready], s->next_ready);
        s->next_ready++;
    }
}

/* Creates base/tmp and base/logs, emptied of an earlier run's files. */
static int make_dirs(const char *base)
{
    char p[512], f[1024];
    const char *sub[2] = { "tmp", "logs" };
    for (int i = 0; i < 2; i++) {
        DIR *d;
        struct dirent *de;
        snprintf(p, sizeof p, "%s/%s", base, sub[i]);
        if (mkdir(p, 0777) != 0 && errno != EEXIST) {
            fprintf(stderr, "fixgl-conform: cannot create %s: %s\n", p, strerror(errno));
            return 0;
        }
        if ((d = opendir(p)) == NULL)
            continue;
        while ((de = readdir(d)) != NULL) {
            size_t n = strlen(de->d_name);
            if (n > 4 && (strcmp(de->d_name + n - 4, ".log") == 0 || strcmp(de->d_name + n - 4, ".rec") == 0)) {
                snprintf(f, sizeof f, "%s/%s", p, de->d_name);
                remove(f);
            }
        }
        closedir(d);
    }
    return 1;
}

/* The oracle side of item from the cache: the records of one whole case,
 * CASE (this case's name) to END with status FC_END_OK; 0 if absent or not
 * that (then the case is rendered, and stored again).  With keep, the
 * records are stored in the item; without, the item is only marked cached
 * (the run holds no more cached data at once than it held renders). */
static int load_cached(struct fc_cache *cache, struct fc_item *item, int keep)
{
    size_t len, pos = 0;
    unsigned char *buf = fc_cache_load(cache, item->name, &len);
    struct fc_rec r;
    int ok = 0;
    if (!buf)
        return 0;
    if (fc_rec_next(buf, len, &pos, &r) && r.kind == FC_REC_CASE && fc_rec_label_is(&r, item->name)) {
        for (;;) {
            if (!fc_rec_next(buf, len, &pos, &r) || r.kind == FC_REC_CASE)
                break;
            if (r.kind == FC_REC_END) {
                int32_t st = FC_END_OK + 1;
                if (r.payload_len >= sizeof st)
                    memcpy(&st, r.payload, sizeof st);
                ok = st == FC_END_OK && pos == len;
                break;
            }
        }
    }
    if (ok && keep) {
        store(&item->side[FC_ORACLE], buf, len, FC_DONE);
    } else if (ok) {
        item->side[FC_ORACLE].state = FC_DONE;
        item->side[FC_ORACLE].cached = 1;
    }
    free(buf);
    return ok;
}

int fc_run_items(struct fc_run_cfg *cfg, struct fc_item *items, size_t n,
                 fc_item_ready ready, void *ud, char *info[2][2])
{
    struct sched s;
    int jobs = cfg->jobs > 0 ? cfg->jobs : 1;
    size_t chunk = (n + (size_t)jobs * 4 - 1) / ((size_t)jobs * 4);

    chunk = chunk < 1 ? 1 : chunk > 32 ? 32 : chunk;
    memset(&s, 0, sizeof s);
    s.cfg = cfg;
    s.items = items;
    s.n = n;
    s.info = info;
    s.ready = ready;
    s.ud = ud;
    s.running = calloc((size_t)jobs, sizeof *s.running);
    if (!make_dirs(cfg->work_dir))
        return -1;
    cfg->oracle_cached = 0;
    for (size_t i = 0; cfg->oracle_cache && i < n; i++)
        cfg->oracle_cached += (size_t)load_cached(cfg->oracle_cache, &items[i], 0);
    for (int w = 0; cfg->oracle_cache && w < 2; w++)
        info[FC_ORACLE][w] = fc_cache_load_info(cfg->oracle_cache, w);
    for (size_t i = 0; i < n; i += chunk) {
        size_t end = i + chunk < n ? i + chunk : n;
        /* the oracle: the runs of cases not in the cache */
        for (size_t a = i; a < end;) {
            size_t b;
            if (items[a].side[FC_ORACLE].state != FC_PENDING) {
                a++;
                continue;
            }
            for (b = a; b < end && items[b].side[FC_ORACLE].state == FC_PENDING; b++)
                ;
            push_task(&s, FC_ORACLE, a, b);
            a = b;
        }
        push_task(&s, FC_FIXGL, i, end);
    }

    while (!s.fatal && (s.qhead < s.qtail || s.nrunning > 0)) {
        int status;
        pid_t pid;
        while (!s.fatal && s.nrunning < jobs && s.qhead < s.qtail) {
            struct task *t = &s.running[s.nrunning];
            *t = s.queue[s.qhead++];
            if (!start_task(&s, t))
                s.fatal = 1;
            else
                s.nrunning++;
        }
        if (s.nrunning == 0)
            break;
        pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno == EINTR)
                continue;
            fprintf(stderr, "fixgl-conform: waitpid: %s\n", strerror(errno));
            s.fatal = 1;
            break;
        }
        for (int i = 0; i < s.nrunning; i++) {
            if (s.running[i].pid == pid) {
                struct task t = s.running[i];
                s.running[i] = s.running[--s.nrunning];
                finish_task(&s, &t, status);
                break;
            }
        }
        flush_ready(&s);
    }
    for (int i = 0; i < s.nrunning; i++) {     /* only after a fatal error */
        kill(s.running[i].pid, SIGKILL);
        waitpid(s.running[i].pid, NULL, 0);
    }
    free(s.running);
    free(s.queue);
    return s.fatal ? -1 : 0;
}

char *fc_run_capture(const char *const *argv)
{
    int fd[2], status;
    pid_t pid;
    char *buf = NULL;
    size_t n = 0, cap = 0;
    ssize_t got;

    if (pipe(fd) != 0)
        return NULL;
    pid = fork();
    if (pid == 0) {
        dup2(fd[1], 1);
        close(fd[0]);
        close(fd[1]);
        execv(argv[0], (char *const *)argv);
        _exit(127);
    }
    close(fd[1]);
    if (pid < 0) {
        close(fd[0]);
        return NULL;
    }
    do {
        if (n + 1 >= cap) {
            cap = cap ? 2 * cap : 4096;
            buf = realloc(buf, cap);
        }
        got = read(fd[0], buf + n, cap - n - 1);
        n += got > 0 ? (size_t)got : 0;
    } while (got > 0 || (got < 0 && errno == EINTR));
    close(fd[0]);
    buf[n] = 0;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        free(buf);
        return NULL;
    }
    return buf;
}
