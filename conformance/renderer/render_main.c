/* render_main.c - a conformance renderer.  The same source builds
 * fixgl-render-osmesa (Mesa, FC_ORACLE defined) and fixgl-render-fixgl.
 *
 *   fixgl-render-X --list                       case names, tags and (reference
 *                                               cases) the colour tolerance in LSB
 *   fixgl-render-X --list-random FAMILY SEED INDEX COUNT
 *                                               the same for scenes INDEX..
 *                                               INDEX+COUNT-1 of a random family
 *                                               (the runner asks it for families
 *                                               whose tags vary by scene)
 *   fixgl-render-X [--perturb] [--crash=NAME] --out FILE NAME...
 *
 * --out runs the named cases (fixed names, random/s<seed>-i<index>,
 * random-lit/..., random-raster/..., random-tex/..., random-shading/...) in order and writes their records to FILE,
 * after two FC_REC_INFO records with GL_RENDERER and GL_VERSION.  Each case gets
 * FC_CASE_CPU_SECONDS of CPU time (SIGPROF ends the process: a case that
 * spins) and FC_CASE_WALL_SECONDS of wall-clock time (SIGALRM: a case that
 * blocks).  The limit that catches a spinning case counts CPU time, not
 * wall time, so that it does not depend on the load of the machine: on a
 * shared 2-core machine running the conformance suites with 2 jobs, the
 * oracle's texture/image_rendered (24 s alone) once passed the former
 * 60-second wall-clock limit.  The wall-clock limit only has to catch a
 * process that waits forever, so it is generous.  Test-only switches for the harness
 * self-test: --perturb alters every captured frame (see fc_harness.h),
 * FC_TRACE=FILE prints the GL calls of random scenes to FILE (fc_trace.h).
 * --crash=NAME dies with SIGSEGV right after starting case NAME.
 * The oracle refuses to run unless GL_RENDERER contains "llvmpipe", and it
 * runs llvmpipe with one rasterizer thread (LP_NUM_THREADS=1): with several
 * threads Mesa 22.3 is not deterministic on some scenes (random/s1-i98 gave
 * 8 different images in 30 runs, differing at a 64-pixel tile boundary),
 * while one thread always gives the most frequent threaded result. */
#include "fc_harness.h"
#include "fc_random.h"
#include "fc_record.h"

#include <fixgl/version.h>

#include <getopt.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <unistd.h>

extern FILE *fc_trace_out;   /* fc_trace.c: random scene call trace */

/* Per case: CPU seconds of the whole process (every thread: fixgl's
 * workers and llvmpipe's rasterizer thread count) and wall-clock seconds
 * (below meson's test timeouts, so that the runner names the case). */
#define FC_CASE_CPU_SECONDS 60
#define FC_CASE_WALL_SECONDS 400

/* name, tags and (reference cases) the colour tolerance */
static void print_case(const fc_case *c)
{
    if (c->tolerance_lsb)
        printf("%s\t%s\t%d\n", c->name, c->tags, c->tolerance_lsb);
    else
        printf("%s\t%s\n", c->name, c->tags);
}

static int list_cases(void)
{
    for (size_t i = 0; i < fc_case_count(); i++)
        print_case(fc_case_at(i));
    return 0;
}

static const fc_case *find_case(const char *name, fc_case *scratch, char *namebuf);

/* --list-random: name, tags and tolerance of count scenes of family. */
#ifdef FC_ORACLE
#define RENDERER_NAME "fixgl-render-osmesa"
#else
#define RENDERER_NAME "fixgl-render-fixgl"
#endif
#define RENDER_USAGE \
    "usage: %s --list | --list-random FAMILY SEED INDEX COUNT | --version |\n" \
    "       [--perturb] [--crash=NAME] --out FILE CASE...   (--opt=value as well)\n"

static int list_random(const char *family, const char *seed, const char *index, const char *count)
{
    const unsigned long long first = strtoull(index, NULL, 10);
    const long n = strtol(count, NULL, 10);
    for (long i = 0; i < n; i++) {
        char name[FC_RANDOM_NAME_MAX + 32], namebuf[FC_RANDOM_NAME_MAX];
        fc_case scratch;
        const fc_case *c;
        snprintf(name, sizeof name, "%s/s%s-i%llu", family, seed, first + (unsigned long long)i);
        if (!(c = find_case(name, &scratch, namebuf))) {
            fprintf(stderr, "renderer: unknown case %s\n", name);
            return 2;
        }
        print_case(c);
    }
    return fflush(stdout) == 0 ? 0 : 2;
}

/* Writes the renderer identification; returns 0 if the oracle is wrong. */
static int write_info(FILE *out)
{
    static unsigned char buf[16 * 16 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    const char *renderer, *version;

    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16)) {
        fprintf(stderr, "renderer: cannot create the identification context\n");
        return 0;
    }
    renderer = (const char *)glGetString(GL_RENDERER);
    version = (const char *)glGetString(GL_VERSION);
    renderer = renderer ? renderer : "(null)";
    version = version ? version : "(null)";
#ifdef FC_ORACLE
    if (!strstr(renderer, "llvmpipe")) {
        fprintf(stderr, "oracle: GL_RENDERER is \"%s\"; the oracle must be llvmpipe "
                "(unset GALLIUM_DRIVER / LIBGL_ALWAYS_SOFTWARE overrides)\n", renderer);
        OSMesaDestroyContext(ctx);
        return 0;
    }
#endif
    fc_rec_write(out, FC_REC_INFO, "renderer", renderer, strlen(renderer), NULL, 0, NULL, 0);
    fc_rec_write(out, FC_REC_INFO, "version", version, strlen(version), NULL, 0, NULL, 0);
    OSMesaDestroyContext(ctx);
    return 1;
}

static const fc_case *find_case(const char *name, fc_case *scratch, char *namebuf)
{
    uint64_t seed;
    uint32_t index;

    if (fc_random_parse(name, &seed, &index)) {
        fc_random_case(seed, index, scratch, namebuf);
        return scratch;
    }
    if (fc_random_lit_parse(name, &seed, &index)) {
        fc_random_lit_case(seed, index, scratch, namebuf);
        return scratch;
    }
    if (fc_random_raster_parse(name, &seed, &index)) {
        fc_random_raster_case(seed, index, scratch, namebuf);
        return scratch;
    }
    if (fc_random_tex_parse(name, &seed, &index)) {
        fc_random_tex_case(seed, index, scratch, namebuf);
        return scratch;
    }
    if (fc_random_shading_parse(name, &seed, &index)) {
        fc_random_shading_case(seed, index, scratch, namebuf);
        return scratch;
    }
    for (size_t i = 0; i < fc_case_count(); i++)
        if (strcmp(fc_case_at(i)->name, name) == 0)
            return fc_case_at(i);
    return NULL;
}

int main(int argc, char **argv)
{
    const char *out_path = NULL, *crash = NULL;
    int perturb = 0, first = 1;
    FILE *out;

    enum { OPT_LIST = 256, OPT_LIST_RANDOM, OPT_PERTURB, OPT_CRASH, OPT_OUT, OPT_VERSION };
    static const struct option longopts[] = {
        { "list", no_argument, NULL, OPT_LIST },
        { "list-random", no_argument, NULL, OPT_LIST_RANDOM },
        { "perturb", no_argument, NULL, OPT_PERTURB },
        { "crash", required_argument, NULL, OPT_CRASH },
        { "out", required_argument, NULL, OPT_OUT },
        { "version", no_argument, NULL, OPT_VERSION },
        { "help", no_argument, NULL, 'h' },
        { NULL, 0, NULL, 0 },
    };
    int list = 0, list_rnd = 0, bad = 0, ch;
    opterr = 0;
    while ((ch = getopt_long(argc, argv, "+h", longopts, NULL)) != -1) {
        switch (ch) {
        case OPT_LIST: list = 1; break;
        case OPT_LIST_RANDOM: list_rnd = 1; break;
        case OPT_PERTURB: perturb = 1; break;
        case OPT_CRASH: crash = optarg; break;
        case OPT_OUT: out_path = optarg; break;
        case OPT_VERSION: puts(FIXGL_VERSION_BANNER(RENDERER_NAME)); return 0;
        case 'h': printf(RENDER_USAGE, argv[0]); return 0;
        default: bad = 1; break;
        }
    }
    first = optind;
    if (list && first == argc && !list_rnd && !bad)
        return list_cases();
    if (list_rnd && argc - first == 4 && !list && !bad)
        return list_random(argv[first], argv[first + 1], argv[first + 2], argv[first + 3]);
    if (!out_path || list || list_rnd || bad) {
        fprintf(stderr, RENDER_USAGE, argv[0]);
        return 2;
    }
#ifdef FC_ORACLE
    setenv("LP_NUM_THREADS", "1", 1);
#endif
    out = fopen(out_path, "wb");
    if (!out) {
        perror(out_path);
        return 2;
    }
    if (!write_info(out))
        return 3;
    if (getenv("FC_TRACE") && !(fc_trace_out = fopen(getenv("FC_TRACE"), "w")))
        perror(getenv("FC_TRACE"));
    for (int i = first; i < argc; i++) {
        fc_case scratch;
        char namebuf[FC_RANDOM_NAME_MAX];
        const fc_case *c = find_case(argv[i], &scratch, namebuf);
        if (!c) {
            fprintf(stderr, "renderer: unknown case %s\n", argv[i]);
            return 2;
        }
        const struct itimerval cpu_limit = { .it_value = { .tv_sec = FC_CASE_CPU_SECONDS } };
        setitimer(ITIMER_PROF, &cpu_limit, NULL);
        alarm(FC_CASE_WALL_SECONDS);
        if (crash && strcmp(crash, c->name) == 0) {
            fc_rec_write(out, FC_REC_CASE, c->name, NULL, 0, NULL, 0, NULL, 0);
            raise(SIGSEGV);
        }
        if (fc_trace_out)
            fprintf(fc_trace_out, "/* case %s: %dx%d format 0x%x depth %d stencil %d */\n",
                    c->name, c->width, c->height, (unsigned)c->format, c->depth_bits,
                    c->stencil_bits);
        fc_run_case(c, out, perturb);
    }
    return fclose(out) == 0 ? 0 : 2;
}
