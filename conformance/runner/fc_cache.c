/* fc_cache.c - the oracle's result cache (see fc_cache.h). */
#include "fc_cache.h"
#include "fc_run.h"

#include <errno.h>
#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

extern char **environ;

struct fc_cache {
    char dir[1024];
};

/* FNV-1a, 64 bits: the key tells builds apart, it is not a defence. */
static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) {
        h ^= b[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

static uint64_t fnv_str(uint64_t h, const char *s)
{
    return fnv(h, s, strlen(s) + 1);    /* with its NUL: "ab","c" != "a","bc" */
}

static int hash_file(uint64_t *h, const char *path)
{
    unsigned char buf[65536];
    size_t got;
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    while ((got = fread(buf, 1, sizeof buf, f)) > 0)
        *h = fnv(*h, buf, got);
    fclose(f);
    return 1;
}

/* The environment the oracle's render may depend on.  Not the loader's
 * (LD_LIBRARY_PATH, LD_PRELOAD): their effect, the libraries loaded, is
 * hashed itself, and meson gives each build's tests its own
 * LD_LIBRARY_PATH (the build's libfixgl, which the oracle never loads). */
static int env_counts(const char *var)
{
    static const char *const prefix[] = { "FC_", "LP_", "GALLIUM_", "MESA_", "LIBGL_",
                                          "GALLIVM_", "DRAW_", "ST_", "SOFTPIPE_" };
    for (size_t i = 0; i < sizeof prefix / sizeof prefix[0]; i++)
        if (strncmp(var, prefix[i], strlen(prefix[i])) == 0)
            return 1;
    return 0;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The shared libraries the renderer loads (the dynamic loader's list) and
 * each one's size and modification time: a Mesa upgrade changes the key. */
static int hash_libraries(uint64_t *h, const char *renderer)
{
    const char *argv[2] = { renderer, NULL };
    char *list, *save = NULL;
    setenv("LD_TRACE_LOADED_OBJECTS", "1", 1);
    list = fc_run_capture(argv);
    unsetenv("LD_TRACE_LOADED_OBJECTS");
    if (!list)
        return 0;
    for (char *line = strtok_r(list, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        char *path = strstr(line, "=> "), *end;
        struct stat st;
        path = path ? path + 3 : line + strspn(line, " \t");
        if ((end = strstr(path, " (")) != NULL)
            *end = 0;
        *h = fnv_str(*h, path);
        if (path[0] == '/' && stat(path, &st) == 0) {
            int64_t v[2] = { (int64_t)st.st_size, (int64_t)st.st_mtime };
            *h = fnv(*h, v, sizeof v);
        }
    }
    free(list);
    return 1;
}

/* The CPU: llvmpipe compiles for the host's features (with FMA it fuses;
 * ORACLE-NOTES.md "The oracle and its host"). */
static void hash_cpu(uint64_t *h)
{
    char line[4096];
    FILE *f = fopen("/proc/cpuinfo", "r");
    int got = 0;
    if (!f)
        return;
    while (got < 2 && fgets(line, sizeof line, f))
        if (strncmp(line, "flags", 5) == 0 || strncmp(line, "model name", 10) == 0) {
            *h = fnv_str(*h, line);
            got++;
        }
    fclose(f);
}

struct fc_cache *fc_cache_open(const char *root, const char *renderer, const char *extra_arg)
{
    uint64_t h = 0xcbf29ce484222325ull;
    size_t nenv = 0;
    char **env = NULL;
    struct fc_cache *c;

    if (getenv("FC_TRACE")) {
        fprintf(stderr, "fixgl-conform: FC_TRACE is set: the oracle cache is not used\n");
        return NULL;
    }
    if (!hash_file(&h, renderer) || !hash_libraries(&h, renderer)) {
        fprintf(stderr, "fixgl-conform: cannot identify the oracle renderer %s: the oracle cache "
                "is not used\n", renderer);
        return NULL;
    }
    hash_cpu(&h);
    h = fnv_str(h, extra_arg ? extra_arg : "");
    for (char **e = environ; *e; e++)
        if (env_counts(*e)) {
            env = realloc(env, (nenv + 1) * sizeof *env);
            env[nenv++] = *e;
        }
    if (nenv)
        qsort(env, nenv, sizeof *env, cmp_str);
    for (size_t i = 0; i < nenv; i++)
        h = fnv_str(h, env[i]);
    free(env);

    c = calloc(1, sizeof *c);
    snprintf(c->dir, sizeof c->dir, "%s", root);
    if (mkdir(c->dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "fixgl-conform: cannot create %s: %s: the oracle cache is not used\n",
                c->dir, strerror(errno));
        free(c);
        return NULL;
    }
    snprintf(c->dir, sizeof c->dir, "%s/%016" PRIx64, root, h);
    if (mkdir(c->dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "fixgl-conform: cannot create %s: %s: the oracle cache is not used\n",
                c->dir, strerror(errno));
        free(c);
        return NULL;
    }
    return c;
}

void fc_cache_close(struct fc_cache *c)
{
    free(c);
}

const char *fc_cache_dir(const struct fc_cache *c)
{
    return c->dir;
}

static void entry_path(const struct fc_cache *c, const char *name, char *out, size_t size)
{
    int n = snprintf(out, size, "%s/", c->dir);
    for (const char *s = name; *s && (size_t)n + 5 < size; s++)
        out[n++] = *s == '/' ? '@' : *s;
    snprintf(out + n, size - (size_t)n, ".rec");
}

static void write_all(const char *path, const void *data, size_t len)
{
    char tmp[1100];
    FILE *f;
    snprintf(tmp, sizeof tmp, "%s.%ld.tmp", path, (long)getpid());
    if (!(f = fopen(tmp, "wb")))
        return;
    if (fwrite(data, 1, len, f) != len) {
        fclose(f);
        remove(tmp);
        return;
    }
    if (fclose(f) != 0 || rename(tmp, path) != 0)
        remove(tmp);
}

unsigned char *fc_cache_load(const struct fc_cache *c, const char *name, size_t *len)
{
    char path[1024];
    entry_path(c, name, path, sizeof path);
    return fc_read_file(path, len);
}

void fc_cache_store(const struct fc_cache *c, const char *name, const unsigned char *data, size_t len)
{
    char path[1024];
    entry_path(c, name, path, sizeof path);
    write_all(path, data, len);
}

char *fc_cache_load_info(const struct fc_cache *c, int which)
{
    char path[1100];
    size_t len;
    unsigned char *s;
    snprintf(path, sizeof path, "%s/info-%s", c->dir, which ? "version" : "renderer");
    if (!(s = fc_read_file(path, &len)))
        return NULL;
    s[len] = 0;     /* fc_read_file leaves room for it */
    return (char *)s;
}

void fc_cache_store_info(const struct fc_cache *c, int which, const char *text)
{
    char path[1100];
    snprintf(path, sizeof path, "%s/info-%s", c->dir, which ? "version" : "renderer");
    write_all(path, text, strlen(text));
}
