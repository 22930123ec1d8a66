/* fz_exec.c - runs a call stream in one OSMesa context of the library the
 * executable is linked with (fixgl or the oracle), recording after every
 * call its GL error, its result and a digest of what it wrote through its
 * output pointers, and at the end digests of the colour, depth and stencil
 * buffers, of the select/feedback buffers and of a glGet state walk.
 *
 * Entry points are resolved by name at startup (fz_fn[], dlsym then
 * OSMesaGetProcAddress), so the generated table runs on either library.
 * Between a glBegin and its glEnd no glGetError is issued (it would itself
 * be an error there): those calls record FZ_UNCHECKED, and the first error
 * they raise is read after the glEnd. */
#include "fz_exec.h"
#include "fz_gen.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

struct qenum { GLenum e; const char *name; };
#define Q(e) { e, #e }
static const struct qenum walk[] = {
#include "query_walk_list.h"
};

static uint8_t *in_arena, *out_arena;
static int fn_begin = -1, fn_end = -1, fn_depthbuffer = -1;
/* glGetBufferPointerv(ARB): the mapping's address differs between the
 * libraries; only whether there is one is compared */
static int fn_bufptr = -1, fn_bufptr_arb = -1;

void *fz_ptr(int kind, int64_t off)
{
    if (kind == FZ_CTX)
        return OSMesaGetCurrentContext();
    if (kind == FZ_PTR_IN)
        return in_arena + off;
    if (off == FZ_PTR_COLOR)
        return out_arena + FZ_COLOR_OFF;
    return out_arena + off;
}

static void *map_fixed(uintptr_t base, size_t size)
{
    void *p = mmap((void *)base, size, PROT_READ | PROT_WRITE,
                   MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED_NOREPLACE | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED || p != (void *)base)
        return NULL;
    return p;
}

int fz_exec_setup(uint8_t *missing)
{
    int n_missing = 0;
    in_arena = map_fixed(FZ_IN_BASE - FZ_IN_BEFORE, FZ_IN_BEFORE + FZ_IN_AFTER);
    out_arena = map_fixed(FZ_OUT_BASE, FZ_OUT_SIZE);
    if (!in_arena || !out_arena)
        return -1;
    in_arena += FZ_IN_BEFORE;
    fz_fill_input_arena(in_arena, FZ_IN_SIZE);
    for (size_t i = 0; i < fz_table_count; i++) {
        void *sym = dlsym(RTLD_DEFAULT, fz_table[i].name);
        fz_proc f = NULL;
        if (sym)
            memcpy(&f, &sym, sizeof f);   /* POSIX: a data pointer to a function */
        else
            f = (fz_proc)OSMesaGetProcAddress(fz_table[i].name);
        fz_fn[i] = f;
        if (missing)
            missing[i] = f == NULL;
        n_missing += f == NULL;
    }
    fn_begin = fz_find_entry("glBegin");
    fn_end = fz_find_entry("glEnd");
    fn_depthbuffer = fz_find_entry("OSMesaGetDepthBuffer");
    fn_bufptr = fz_find_entry("glGetBufferPointerv");
    fn_bufptr_arb = fz_find_entry("glGetBufferPointervARB");
    return n_missing;
}

/* Every client array points into the input arena from the start, with
 * its default size, type and stride (so the state walk sees the defaults):
 * an array the stream enables without setting its pointer would otherwise
 * be read at NULL, a crash of the stream's own making.  The oracle's
 * secondary-colour and fog-coordinate arrays too, through its own entry
 * points (fixgl has neither). */
static void client_arrays(void)
{
    void *p = in_arena + FZ_IN_FLOATS;
    glVertexPointer(4, GL_FLOAT, 0, p);
    glNormalPointer(GL_FLOAT, 0, p);
    glColorPointer(4, GL_FLOAT, 0, p);
    glIndexPointer(GL_FLOAT, 0, p);
    glEdgeFlagPointer(0, in_arena + FZ_IN_SMALL);
    for (int u = 7; u >= 0; u--) {
        glClientActiveTexture(GL_TEXTURE0 + (GLenum)u);
        glTexCoordPointer(4, GL_FLOAT, 0, p);
    }
    typedef void (GLAPIENTRY *ptr3)(GLint, GLenum, GLsizei, const void *);
    typedef void (GLAPIENTRY *ptr2)(GLenum, GLsizei, const void *);
    fz_proc f = (fz_proc)OSMesaGetProcAddress("glSecondaryColorPointer");
    if (f)
        ((ptr3)f)(3, GL_FLOAT, 0, p);
    f = (fz_proc)OSMesaGetProcAddress("glFogCoordPointer");
    if (f)
        ((ptr2)f)(GL_FLOAT, 0, p);
    while (glGetError() != GL_NO_ERROR)
        ;
}

OSMesaContext fz_exec_context(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
    /* Zeros, and every buffer cleared once: the oracle renders into a
     * zero-initialised buffer of its own and copies all of it to the
     * caller's at a flush (after a read-back even when nothing was drawn),
     * fixgl draws into the caller's: the contents of an area never drawn
     * or cleared are not defined by OSMesa, only equal when both are 0. */
    memset(out_arena + FZ_COLOR_OFF, 0, (size_t)FZ_COLOR_MAX * FZ_COLOR_MAX * 16);
    if (!ctx)
        return NULL;
    if (!OSMesaMakeCurrent(ctx, out_arena + FZ_COLOR_OFF, GL_UNSIGNED_BYTE, 64, 64)) {
        OSMesaDestroyContext(ctx);
        return NULL;
    }
    client_arrays();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
    glFinish();
    return ctx;
}

static uint64_t hash_bytes(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = p;
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        uint64_t w;
        memcpy(&w, b + i, 8);
        h = (h ^ w) * 0x100000001b3ull;
        h ^= h >> 29;
    }
    for (; i < n; i++)
        h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

#define HASH0 0xcbf29ce484222325ull

size_t fz_exec_run(const fz_call *calls, size_t n, fz_result *res)
{
    size_t issued = 0;
    int inside = 0;
    const int trace = getenv("FZ_TRACE") != NULL;   /* each call on stderr */
    for (size_t i = 0; i < n; i++) {
        const fz_call *c = &calls[i];
        const fz_entry *e;
        uint64_t out = HASH0, ret;
        if (c->fn >= fz_table_count || !fz_fn[c->fn]) {
            if (res)
                res[i] = (fz_result){ FZ_SKIPPED, 0, 0 };
            continue;
        }
        e = &fz_table[c->fn];
        for (int j = 0; j < e->nparams; j++)
            if (e->params[j].kind == FZ_PTR_OUT && c->a[j].i >= 0 && c->a[j].i < FZ_OUT_PERSIST)
                memset(out_arena + c->a[j].i, 0xa5, FZ_OUT_HASHED);
        if (trace)
            fprintf(stderr, "%zu %s\n", i, e->name);
        ret = fz_call_entry(c->fn, c->a);
        issued++;
        /* OSMesaGetDepthBuffer's last output is the buffer's address, which
         * differs from run to run: not compared, also where another
         * output's hashed bytes reach it (seed 453) */
        if ((int)c->fn == fn_depthbuffer) {
            const int64_t off = c->a[e->nparams - 1].i;
            if (off >= 0 && off < FZ_OUT_PERSIST)
                memset(out_arena + off, 0xa5, sizeof(void *));
        }
        if (((int)c->fn == fn_bufptr || (int)c->fn == fn_bufptr_arb) && c->a[2].i >= 0 &&
            c->a[2].i < FZ_OUT_PERSIST) {
            uint64_t p;
            memcpy(&p, out_arena + c->a[2].i, sizeof p);
            if (p != 0 && p != 0xa5a5a5a5a5a5a5a5ull) {
                p = 1;
                memcpy(out_arena + c->a[2].i, &p, sizeof p);
            }
        }
        for (int j = 0; j < e->nparams; j++)
            if (e->params[j].kind == FZ_PTR_OUT && c->a[j].i >= 0 && c->a[j].i < FZ_OUT_PERSIST
                && !((int)c->fn == fn_depthbuffer && j == e->nparams - 1))
                out = hash_bytes(out, out_arena + c->a[j].i, FZ_OUT_HASHED);
        if ((int)c->fn == fn_begin)
            inside = 1;
        if (!inside && res)
            res[i] = (fz_result){ glGetError(), (uint32_t)ret, out };
        else if (res)
            res[i] = (fz_result){ FZ_UNCHECKED, (uint32_t)ret, out };
        if ((int)c->fn == fn_end) {
            inside = 0;
            if (res)
                res[i].err = glGetError();
        }
        if (!inside && !res)
            glGetError();
    }
    if (inside)
        glEnd();
    return issued;
}

/* The walk's digest; with FZ_WALK=FILE in the environment also every
 * value of the walk, written to FILE (debugging: diff two of them). */
static uint64_t state_walk(void)
{
    uint64_t h = HASH0;
    FILE *walk_out = getenv("FZ_WALK") ? fopen(getenv("FZ_WALK"), "w") : NULL;
    for (size_t i = 0; i < sizeof walk / sizeof walk[0]; i++) {
        GLint iv[16];
        GLfloat fv[16];
        GLboolean bv[16];
        GLenum e = walk[i].e;
        if (e == GL_NUM_COMPRESSED_TEXTURE_FORMATS || e == GL_COMPRESSED_TEXTURE_FORMATS)
            continue;   /* fixgl lists 3 of the oracle's 12 (c_query_walk.c documents it) */
        memset(iv, 0x5a, sizeof iv);
        memset(fv, 0x5a, sizeof fv);
        memset(bv, 0x5a, sizeof bv);
        glGetIntegerv(e, iv);
        GLenum e1 = glGetError();
        glGetFloatv(e, fv);
        GLenum e2 = glGetError();
        glGetBooleanv(e, bv);
        GLenum e3 = glGetError();
        GLboolean en = glIsEnabled(e);
        GLenum e4 = glGetError();
        if (walk_out) {   /* FZ_WALK: each value, to compare two walks */
            fprintf(walk_out, "%s: errors %x %x %x %x, enabled %d,", walk[i].name, e1, e2, e3,
                    e4, en);
            for (int k = 0; k < 16; k++)
                fprintf(walk_out, " %d/%a/%d", iv[k], fv[k], bv[k]);
            fputc('\n', walk_out);
        }
        h = hash_bytes(h, iv, sizeof iv);
        h = hash_bytes(h, fv, sizeof fv);
        h = hash_bytes(h, bv, sizeof bv);
        GLenum errs[5] = { e1, e2, e3, en, e4 };
        h = hash_bytes(h, errs, sizeof errs);
    }
    if (walk_out)
        fclose(walk_out);
    return h;
}

void fz_exec_final(fz_final *f)
{
    GLint w = 0, h = 0;
    static GLuint depth[FZ_COLOR_MAX * FZ_COLOR_MAX];
    static GLubyte stencil[FZ_COLOR_MAX * FZ_COLOR_MAX];

    glEndList();
    glRenderMode(GL_RENDER);
    while (glGetError() != GL_NO_ERROR)
        ;
    glFinish();
    const uint64_t walk_digest = state_walk();
    static const GLenum pack[] = { GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH,
                                   GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS };
    for (size_t i = 0; i < sizeof pack / sizeof pack[0]; i++)
        glPixelStorei(pack[i], 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
    glReadBuffer(GL_FRONT);
    OSMesaGetIntegerv(OSMESA_WIDTH, &w);
    OSMesaGetIntegerv(OSMESA_HEIGHT, &h);
    if (w < 0 || w > FZ_COLOR_MAX || h < 0 || h > FZ_COLOR_MAX)
        w = h = 0;
    memset(depth, 0, sizeof depth);
    memset(stencil, 0, sizeof stencil);
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
    while (glGetError() != GL_NO_ERROR)
        ;
    glFinish();
    if (!f)
        return;   /* the libFuzzer target: the calls were the point */
    f->walk = walk_digest;
    if (getenv("FZ_DUMP")) {   /* debugging: the colour area as raw bytes */
        FILE *d = fopen(getenv("FZ_DUMP"), "wb");
        if (d) {
            fwrite(out_arena + FZ_COLOR_OFF, 1, (size_t)FZ_COLOR_MAX * FZ_COLOR_MAX * 16, d);
            fclose(d);
        }
    }
    f->color = hash_bytes(HASH0, out_arena + FZ_COLOR_OFF, (size_t)FZ_COLOR_MAX * FZ_COLOR_MAX * 16);
    f->depth = hash_bytes(HASH0, depth, sizeof depth);
    f->stencil = hash_bytes(HASH0, stencil, sizeof stencil);
    f->persist = hash_bytes(HASH0, out_arena + FZ_OUT_PERSIST, 8u << 20);
}
