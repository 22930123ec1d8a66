/* test_selftest.c - end-to-end self-test of the harness with the oracle
 * renderer on both sides.
 *   argv: fixgl-conform, fixgl-render-osmesa, scratch directory
 *         [, fixgl-render-fixgl]
 * 1. all fixed cases (>= 40 core) and 50 random scenes: every case exact;
 *    50 random lit scenes (random-lit/s7-i*): every scene exact, so the lit
 *    generator is deterministic and two renderer processes draw the same;
 * 1b. with fixgl-render-fixgl: both renderers trace the same GL calls
 *    (FC_TRACE) for 40 lit and 10 plain random scenes;
 * 2. --perturb on the "fixgl" side: the chosen cases differ by exactly one
 *    pixel (channel diff 64) and one depth value per frame, with heat maps;
 * 3. --crash=NAME: that case is an error and the renderer restarts for the
 *    cases after it;
 * 4. the oracle cache (runner/fc_cache.h): a first run stores every case,
 *    a second reuses every one and its cached oracle side is exact against
 *    a fresh render; FC_EMIT=arrays is another key.
 * Runs 1-3 take the oracle side from the build's cache when the test's
 * environment names one (FIXGL_CONFORM_ORACLE_CACHE): a render of an
 * earlier process, compared with a fresh one.  FIXGL_CONFORM_ORACLE_RENDERER,
 * when set, replaces fixgl-render-osmesa (as it does for fixgl-conform). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static int failures;

#define CHECK(cond) do { if (!(cond)) { fprintf(stderr, "%s:%d: CHECK failed: %s\n", \
                                                 __FILE__, __LINE__, #cond); failures++; } } while (0)

static int run_env(char *const *argv, const char *trace)
{
    int status;
    pid_t pid = fork();
    if (pid == 0) {
        if (trace)
            setenv("FC_TRACE", trace, 1);
        execv(argv[0], argv);
        _exit(127);
    }
    if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status))
        return -1;
    return WEXITSTATUS(status);
}

static int run(char *const *argv)
{
    return run_env(argv, NULL);
}

/* Runs argv with stdout to `out` and, if env_name, that variable set. */
static int run_out(char *const *argv, const char *out, const char *env_name, const char *env_val)
{
    int status;
    pid_t pid = fork();
    if (pid == 0) {
        if (env_name)
            setenv(env_name, env_val, 1);
        if (!freopen(out, "w", stdout))
            _exit(126);
        execv(argv[0], argv);
        _exit(127);
    }
    if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status))
        return -1;
    return WEXITSTATUS(status);
}

static char *slurp(const char *dir, const char *name)
{
    char path[1024];
    FILE *f;
    char *buf = calloc(1, 4 << 20);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "r");
    if (f) {
        size_t n = fread(buf, 1, (4 << 20) - 1, f);
        buf[n] = 0;
        fclose(f);
    }
    return buf;
}

static int count(const char *hay, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(hay, needle); p; p = strstr(p + 1, needle))
        n++;
    return n;
}

/* The JSON object of one case (up to its closing brace). */
static char *case_json(const char *json, const char *name, char *out, size_t size)
{
    char key[256];
    const char *p, *end;
    snprintf(key, sizeof key, "{ \"name\": \"%s\"", name);
    p = strstr(json, key);
    out[0] = 0;
    if (!p)
        return out;
    end = strchr(p, '}');
    snprintf(out, size, "%.*s", (int)(end ? end - p + 1 : 0), p);
    return out;
}

static int file_nonempty(const char *dir, const char *name)
{
    char path[1024];
    FILE *f;
    long n = 0;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if ((f = fopen(path, "rb")) != NULL) {
        fseek(f, 0, SEEK_END);
        n = ftell(f);
        fclose(f);
    }
    return n > 0;
}

int main(int argc, char **argv)
{
    char dir[4][1024], obj[2048], *json;
    if (argc != 4 && argc != 5) {
        fprintf(stderr, "usage: %s fixgl-conform fixgl-render-osmesa scratch-dir [fixgl-render-fixgl]\n", argv[0]);
        return 2;
    }
    /* the oracle renderer the conformance runs use (.ci/run's sanitized
     * step: the regular build's, whose renders are in the cache; the
     * oracle renderer is never sanitized) */
    if (getenv("FIXGL_CONFORM_ORACLE_RENDERER") && *getenv("FIXGL_CONFORM_ORACLE_RENDERER"))
        argv[2] = getenv("FIXGL_CONFORM_ORACLE_RENDERER");
    snprintf(dir[3], sizeof dir[3], "%s/lit", argv[3]);
    for (int i = 0; i < 3; i++)
        snprintf(dir[i], sizeof dir[i], "%s/%s", argv[3], i == 0 ? "exact" : i == 1 ? "perturb" : "crash");

    {   /* 1. oracle against itself */
        char *a[] = { argv[1], "--random", "50", "--seed", "7", "--jobs", "2", "--oracle-renderer", argv[2],
                      "--fixgl-renderer", argv[2], "--report", dir[0], NULL };
        int cases, rc = run(a);
        CHECK(rc == 0);
        json = slurp(dir[0], "summary.json");
        cases = count(json, "{ \"name\": ");
        CHECK(cases >= 90);
        CHECK(count(json, "\"tags\": [ \"core\"") >= 40);
        CHECK(count(json, "\"tags\": [ \"random\" ]") == 50);
        CHECK(count(json, "\"status\": \"exact\"") == cases);
        CHECK(strstr(json, "\"oracle\": \"llvmpipe") != NULL);
        free(json);
    }
    {   /* 1. random lit scenes, oracle against itself */
        char *a[] = { argv[1], "--random-lit", "50", "--seed", "7", "--tag", "random-lit", "--jobs", "2",
                      "--oracle-renderer", argv[2], "--fixgl-renderer", argv[2], "--report", dir[3], NULL };
        CHECK(run(a) == 0);
        json = slurp(dir[3], "summary.json");
        CHECK(count(json, "{ \"name\": ") == 50);
        CHECK(count(json, "\"tags\": [ \"random-lit\" ]") == 50);
        CHECK(count(json, "\"name\": \"random-lit/s7-i49\"") == 1);
        CHECK(count(json, "\"status\": \"exact\"") == count(json, "{ \"name\": "));
        free(json);
    }
    if (argc == 5) {   /* 1b. the oracle and fixgl renderers issue the same calls */
        char out[2][1100], trace[2][1100], *text[2];
        char *a[2][56];
        for (int s = 0; s < 2; s++) {
            int k = 0;
            snprintf(out[s], sizeof out[s], "%s/trace-%d.bin", dir[3], s);
            snprintf(trace[s], sizeof trace[s], "%s/trace-%d.txt", dir[3], s);
            a[s][k++] = argv[s == 0 ? 2 : 4];
            a[s][k++] = "--out";
            a[s][k++] = out[s];
            for (int i = 0; i < 50; i++) {
                static char names[50][40];
                if (i < 40)
                    snprintf(names[i], sizeof names[i], "random-lit/s11-i%d", 3 * i);
                else
                    snprintf(names[i], sizeof names[i], "random/s11-i%d", i);
                a[s][k++] = names[i];
            }
            a[s][k] = NULL;
            CHECK(run_env(a[s], trace[s]) == 0);
            text[s] = slurp(dir[3], s == 0 ? "trace-0.txt" : "trace-1.txt");
        }
        CHECK(strlen(text[0]) > 100000);
        CHECK(count(text[0], "glLightfv") > 40 && count(text[0], "glNormal3") > 1000);
        CHECK(strcmp(text[0], text[1]) == 0);
        free(text[0]);
        free(text[1]);
    }
    {   /* 2. perturbed: one pixel and one depth value per frame */
        char *a[] = { argv[1], "--no-random", "--case", "core/fill_rule_square", "--case", "core/depth_range",
                      "--case", "core/query_defaults", "--oracle-renderer", argv[2], "--fixgl-renderer", argv[2],
                      "--fixgl-arg", "--perturb", "--report", dir[1], NULL };
        CHECK(run(a) == 1);
        json = slurp(dir[1], "summary.json");
        CHECK(count(json, "{ \"name\": ") == 3);
        case_json(json, "core/fill_rule_square", obj, sizeof obj);
        CHECK(strstr(obj, "\"frames\": 1, \"pixels\": 256, \"mismatched_pixels\": 1, \"max_channel_diff\": 64, "
                          "\"depth_mismatches\": 1, \"error_mismatches\": 0") != NULL);
        CHECK(strstr(obj, "\"status\": \"differs\"") != NULL);
        case_json(json, "core/depth_range", obj, sizeof obj);
        CHECK(strstr(obj, "\"frames\": 5, \"pixels\": 5120, \"mismatched_pixels\": 5, \"max_channel_diff\": 64, "
                          "\"depth_mismatches\": 5") != NULL);
        case_json(json, "core/query_defaults", obj, sizeof obj);
        CHECK(strstr(obj, "\"status\": \"exact\"") != NULL);
        CHECK(file_nonempty(dir[1], "img/core_fill_rule_square-f0-diff.png"));
        CHECK(file_nonempty(dir[1], "img/core_fill_rule_square-f0-oracle.png"));
        CHECK(file_nonempty(dir[1], "img/core_depth_range-f4-depthdiff.png"));
        CHECK(!file_nonempty(dir[1], "img/core_query_defaults-f0-diff.png"));
        free(json);
    }
    {   /* 3. a crash in one case; the cases after it still run */
        char *a[] = { argv[1], "--no-random", "--case", "core/fill_*", "--jobs", "1",
                      "--oracle-renderer", argv[2], "--fixgl-renderer", argv[2],
                      "--fixgl-arg", "--crash=core/fill_shared_diagonal", "--report", dir[2], NULL };
        CHECK(run(a) == 1);
        json = slurp(dir[2], "summary.json");
        case_json(json, "core/fill_shared_diagonal", obj, sizeof obj);
        CHECK(strstr(obj, "\"status\": \"error\"") != NULL);
        CHECK(count(json, "\"status\": \"error\"") == 1);
        CHECK(count(json, "\"status\": \"exact\"") == count(json, "{ \"name\": ") - 1);
        case_json(json, "core/fill_fan_pixel_centres", obj, sizeof obj);
        CHECK(strstr(obj, "\"status\": \"exact\"") != NULL);
        free(json);
    }
    {   /* 4. the oracle cache */
        char cache[1100], out[1100], cmd[1200], line[256];
        long cases = -1, reused = -1, rendered = -1;
        snprintf(cache, sizeof cache, "%s/oracle-cache", argv[3]);
        snprintf(out, sizeof out, "%s/cache-run.txt", argv[3]);
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", cache);
        CHECK(system(cmd) == 0);
        char *a[] = { argv[1], "--no-random", "--case", "core/fill_*", "--case", "random/*", "--random", "10",
                      "--seed", "3", "--jobs", "2", "--oracle-renderer", argv[2], "--fixgl-renderer", argv[2],
                      "--oracle-cache", cache, "--report", dir[3], NULL };
        for (int pass = 0; pass < 3; pass++) {
            FILE *f;
            CHECK(run_out(a, out, pass == 2 ? "FC_EMIT" : NULL, "arrays") == 0);
            reused = rendered = -1;
            if ((f = fopen(out, "r")) != NULL) {
                while (fgets(line, sizeof line, f)) {
                    long c;
                    if (sscanf(line, "fixgl-conform: %ld cases", &c) == 1)
                        cases = pass == 0 ? c : cases;
                    if (strncmp(line, "oracle cache ", 13) == 0 && strstr(line, ": "))
                        sscanf(strstr(line, ": ") + 2, "%ld of %*d cases reused, %ld rendered",
                               &reused, &rendered);
                }
                fclose(f);
            }
            CHECK(cases >= 12);
            /* pass 0 stores, pass 1 reuses, pass 2 (FC_EMIT=arrays) is another key */
            CHECK(reused == (pass == 1 ? cases : 0));
            CHECK(rendered == (pass == 1 ? 0 : cases));
            json = slurp(dir[3], "summary.json");
            CHECK(count(json, "{ \"name\": ") == cases);
            CHECK(count(json, "\"status\": \"exact\"") == cases);
            CHECK(strstr(json, "\"oracle\": \"llvmpipe") != NULL);
            free(json);
        }
    }
    if (failures) {
        fprintf(stderr, "%d check(s) failed; reports under %s\n", failures, argv[3]);
        return 1;
    }
    printf("harness self-test passed; reports: %s/{exact,lit,perturb,crash}/index.html\n", argv[3]);
    return 0;
}
