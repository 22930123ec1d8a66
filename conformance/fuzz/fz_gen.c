/* fz_gen.c - the call-stream generator of the API fuzzer.
 *
 * A stream mixes single calls of any entry of the table, with valid or
 * hostile arguments, and structured pieces that reach deeper state:
 * glBegin/glEnd blocks of per-vertex calls, display lists compiled around
 * other pieces, client vertex arrays and their draws, selection and
 * feedback, evaluator maps and meshes, texture images.
 *
 * Arguments.  Valid ones come from the parameter's enum class (gen_table.py)
 * or small ranges; hostile ones are any GL enum or random bits, NaN, +-Inf,
 * denormals, +-huge, 0, -0, negative and enormous sizes.  What a correct
 * library may read or write through a pointer must stay inside the
 * executor's arenas (fz_table.h), so sizes that decide how much are bounded
 * (bound_call): every size and count of a call with a pointer, the pixel
 * store values, the draws that read the client arrays, the evaluator
 * meshes.  Negative and enormous values stay where the GL validates them
 * against a limit before touching memory (framebuffer copies into
 * textures) or where no memory is involved (glCopyPixels, glViewport...). */
#include "fz_gen.h"

#include <GL/gl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const uint8_t *gen_disabled;

/* Entries the structured pieces use (-1 when not exported). */
enum {
    E_BEGIN, E_END, E_NEWLIST, E_ENDLIST, E_CALLLIST, E_CALLLISTS, E_GENLISTS, E_VERTEXPOINTER,
    E_COLORPOINTER, E_NORMALPOINTER, E_TEXCOORDPOINTER, E_INTERLEAVED, E_ENABLECLIENT,
    E_DRAWARRAYS, E_DRAWELEMENTS, E_ARRAYELEMENT, E_SELECTBUFFER, E_FEEDBACKBUFFER,
    E_RENDERMODE, E_INITNAMES, E_PUSHNAME, E_LOADNAME, E_MAP1F, E_MAP2F, E_ENABLE,
    E_MAPGRID1F, E_MAPGRID2F, E_EVALMESH1, E_EVALMESH2, E_EVALCOORD1F, E_EVALCOORD2F,
    E_BINDTEXTURE, E_TEXIMAGE2D, E_TEXPARAMETERI, E_VERTEX3F, E_COLOR4F, E_PASSTHROUGH,
    E_COUNT
};
static const char *const special_names[E_COUNT] = {
    "glBegin", "glEnd", "glNewList", "glEndList", "glCallList", "glCallLists", "glGenLists", "glVertexPointer",
    "glColorPointer", "glNormalPointer", "glTexCoordPointer", "glInterleavedArrays",
    "glEnableClientState", "glDrawArrays", "glDrawElements", "glArrayElement",
    "glSelectBuffer", "glFeedbackBuffer", "glRenderMode", "glInitNames", "glPushName",
    "glLoadName", "glMap1f", "glMap2f", "glEnable", "glMapGrid1f", "glMapGrid2f",
    "glEvalMesh1", "glEvalMesh2", "glEvalCoord1f", "glEvalCoord2f", "glBindTexture",
    "glTexImage2D", "glTexParameteri", "glVertex3f", "glColor4f", "glPassThrough",
};
static int special[E_COUNT];

/* Entries allowed inside glBegin/glEnd (GL 1.x 2.6.3) and all the others. */
static int *vertex_entries, *any_entries;
static size_t n_vertex_entries, n_any_entries;

/* --- bounds ---------------------------------------------------------------- */
enum { B_NONE, B_POINTER, B_TEXTURE, B_ARRAYS, B_MESH, B_LISTS, B_PIXELSTORE, B_SELECT,
       B_OSMESA };
static uint8_t *entry_bound;

static int starts_with(const char *s, const char *p) { return strncmp(s, p, strlen(p)) == 0; }

static int classify_bound(const fz_entry *e)
{
    static const char *const arrays[] = { "glDrawArrays", "glDrawElements",
        "glDrawRangeElements", "glArrayElement", "glMultiDrawArrays", "glMultiDrawArraysEXT",
        "glMultiDrawElements", "glMultiDrawElementsEXT", "glDrawArraysEXT",
        "glArrayElementEXT", NULL };
    static const char *const mesh[] = { "glEvalMesh1", "glEvalMesh2", "glEvalPoint1",
        "glEvalPoint2", NULL };
    /* copies from the framebuffer: enormous sizes stay (the GL checks
     * them against its limits); glTexImage's read client memory, and a
     * compiled one copies all of it before any check, as the oracle's
     * save_TexImage2D does, so they are bounded like every pointer call */
    static const char *const textures[] = { "glCopyTexImage1D", "glCopyTexImage2D",
        "glCopyTexSubImage1D", "glCopyTexSubImage2D", NULL };
    for (int i = 0; arrays[i]; i++)
        if (strcmp(e->name, arrays[i]) == 0)
            return B_ARRAYS;
    for (int i = 0; mesh[i]; i++)
        if (strcmp(e->name, mesh[i]) == 0)
            return B_MESH;
    for (int i = 0; textures[i]; i++)
        if (strcmp(e->name, textures[i]) == 0)
            return B_TEXTURE;
    if (starts_with(e->name, "glPixelStore"))
        return B_PIXELSTORE;
    if (strcmp(e->name, "glSelectBuffer") == 0 || strcmp(e->name, "glFeedbackBuffer") == 0)
        return B_SELECT;
    if (strcmp(e->name, "glGenLists") == 0 || strcmp(e->name, "glDeleteLists") == 0)
        return B_LISTS;
    if (starts_with(e->name, "OSMesa"))
        return B_OSMESA;
    for (int j = 0; j < e->nparams; j++)
        if (e->params[j].kind == FZ_PTR_IN || e->params[j].kind == FZ_PTR_OUT)
            return B_POINTER;
    return B_NONE;
}

static int vertex_call(const char *n)
{
    static const char *const prefixes[] = { "glVertex", "glColor3", "glColor4", "glNormal3",
        "glTexCoord", "glMultiTexCoord", "glEvalCoord", "glEvalPoint", "glMaterial",
        "glEdgeFlag", "glIndex", "glArrayElement", "glCallList", "glSecondaryColor",
        "glFogCoord", NULL };
    if (strcmp(n, "glIndexMask") == 0 || strcmp(n, "glIndexPointer") == 0 ||
        strcmp(n, "glEdgeFlagPointer") == 0 || strcmp(n, "glColorPointer") == 0 ||
        starts_with(n, "glSecondaryColorPointer") || starts_with(n, "glFogCoordPointer") ||
        strcmp(n, "glIndexPointerEXT") == 0 || strcmp(n, "glEdgeFlagPointerEXT") == 0)
        return 0;
    for (int i = 0; prefixes[i]; i++)
        if (starts_with(n, prefixes[i]))
            return 1;
    return 0;
}

int fz_find_entry(const char *name)
{
    for (size_t i = 0; i < fz_table_count; i++)
        if (strcmp(fz_table[i].name, name) == 0)
            return (int)i;
    return -1;
}

void fz_gen_init(const uint8_t *disabled)
{
    gen_disabled = disabled;
    for (int i = 0; i < E_COUNT; i++) {
        special[i] = fz_find_entry(special_names[i]);
        if (special[i] >= 0 && disabled && disabled[special[i]])
            special[i] = -1;
    }
    free(vertex_entries);
    free(any_entries);
    free(entry_bound);
    vertex_entries = malloc(fz_table_count * sizeof *vertex_entries);
    any_entries = malloc(fz_table_count * sizeof *any_entries);
    entry_bound = malloc(fz_table_count);
    n_vertex_entries = n_any_entries = 0;
    for (size_t i = 0; i < fz_table_count; i++) {
        entry_bound[i] = (uint8_t)classify_bound(&fz_table[i]);
        if (disabled && disabled[i])
            continue;
        any_entries[n_any_entries++] = (int)i;
        if (vertex_call(fz_table[i].name))
            vertex_entries[n_vertex_entries++] = (int)i;
    }
}

/* --- the source of choices ---------------------------------------------- */
static uint64_t splitmix(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static uint32_t next32(fz_src *s)
{
    if (!s->bytes) {
        const uint32_t r = (uint32_t)(splitmix(&s->state) >> 32);
        if (s->rec) {
            if (s->rec_len + 4 > s->rec_cap) {
                s->rec_cap *= 2;
                s->rec = realloc(s->rec, s->rec_cap);
            }
            for (int i = 0; i < 4; i++)
                s->rec[s->rec_len++] = (uint8_t)(r >> (24 - 8 * i));
        }
        return r;
    }
    uint32_t v = 0;
    for (int i = 0; i < 4; i++)
        v = v << 8 | (s->pos < s->len ? s->bytes[s->pos++] : 0);
    return v;
}

static int exhausted(const fz_src *s) { return s->bytes && s->pos >= s->len; }

static uint32_t below(fz_src *s, uint32_t n) { return n ? next32(s) % n : 0; }
static int chance(fz_src *s, unsigned percent) { return below(s, 100) < percent; }
static double unit(fz_src *s) { return next32(s) / 4294967296.0; }

/* --- arguments ------------------------------------------------------------ */
static double hostile_float(fz_src *s)
{
    static const double v[] = { NAN, -NAN, INFINITY, -INFINITY, 1e-40, -1e-40, 5e-324,
        1e20, -1e20, 3.4028234663852886e38, -3.4028234663852886e38, 1e38, 0.0, -0.0,
        1e300, -1e300, 2147483648.0, -2147483649.0, 4294967296.0, 0.5, 1e-7, 65536.0 };
    return v[below(s, sizeof v / sizeof v[0])];
}

static int64_t hostile_int(fz_src *s)
{
    static const int64_t v[] = { -1, INT32_MIN, INT32_MAX, 1 << 16, 1 << 24, 1 << 30,
        -65536, 0, -2, 255, 256, 32768, 65535, 4096 };
    if (chance(s, 25))
        return (int32_t)next32(s);
    return v[below(s, sizeof v / sizeof v[0])];
}

static uint32_t enum_value(fz_src *s, int cls, unsigned valid)
{
    if (cls >= 0 && fz_enum_classes[cls].count && chance(s, valid))
        return fz_enum_classes[cls].values[below(s, (uint32_t)fz_enum_classes[cls].count)];
    if (chance(s, 60))
        return fz_all_enums[below(s, (uint32_t)fz_all_enum_count)];
    switch (below(s, 4)) {
    case 0: return 0;
    case 1: return 0xffffffffu;
    case 2: return next32(s);
    default: {
        uint32_t v = (cls >= 0 && fz_enum_classes[cls].count
                          ? fz_enum_classes[cls].values[below(s, (uint32_t)fz_enum_classes[cls].count)]
                          : 0x1400) + 1;
        /* GL_POLYGON + 1 is GL_LINES_ADJACENCY, a mode of GL 3.2 that the
         * oracle (GL 4.5) draws and fixgl (GL 1.5) refuses: the first
         * value after every version's modes instead (GL_PATCHES + 1) */
        return v == 0xA ? 0xF : v;
    }
    }
}

static uint32_t bits_value(fz_src *s, int cls, unsigned valid)
{
    if (cls >= 0 && chance(s, valid)) {
        uint32_t m = 0;
        for (size_t i = 0; i < fz_enum_classes[cls].count; i++)
            if (chance(s, 40))
                m |= fz_enum_classes[cls].values[i];
        return m;
    }
    return chance(s, 50) ? 0xffffffffu : next32(s);
}

/* An input pointer: a region of the arena (floats, doubles, small
 * integers, random bytes), 8-byte aligned (a GLdouble * must be). */
static int64_t in_offset(fz_src *s)
{
    static const uint32_t regions[] = { FZ_IN_FLOATS, FZ_IN_DOUBLES, FZ_IN_SMALL, FZ_IN_RANDOM };
    return regions[below(s, 4)] + (int64_t)below(s, 1u << 19) * 8;
}

static void gen_args(fz_src *s, int fn, fz_call *c, unsigned valid)
{
    const fz_entry *e = &fz_table[fn];
    memset(c, 0, sizeof *c);
    c->fn = (uint32_t)fn;
    for (int j = 0; j < e->nparams; j++) {
        const fz_param *p = &e->params[j];
        fz_arg *a = &c->a[j];
        int ok = chance(s, valid);
        switch (p->kind) {
        case FZ_ENUM: a->i = enum_value(s, p->cls, valid); break;
        case FZ_BITFIELD: a->i = bits_value(s, p->cls, valid); break;
        case FZ_BOOL: a->i = ok ? below(s, 2) : (chance(s, 50) ? 2 : 255); break;
        case FZ_I8: a->i = ok ? (int64_t)below(s, 8) : (int8_t)next32(s); break;
        case FZ_U8: a->i = ok ? (int64_t)below(s, 256) : 255; break;
        case FZ_I16: a->i = ok ? (int64_t)below(s, 16) - 2 : (int16_t)next32(s); break;
        case FZ_U16: a->i = ok ? (int64_t)below(s, 16) : (uint16_t)next32(s); break;
        case FZ_I32: case FZ_SIZE: case FZ_U32:
            if (ok)
                a->i = chance(s, 70) ? (int64_t)below(s, 17) : (int64_t)below(s, 513) - 1;
            else
                a->i = hostile_int(s);
            if (p->kind == FZ_U32)
                a->i = (uint32_t)a->i;
            break;
        case FZ_F32: case FZ_F64:
            if (ok)
                a->d = chance(s, 20) ? (double)below(s, 9) - 1 : (unit(s) * 4.0 - 2.0);
            else
                a->d = hostile_float(s);
            if (p->kind == FZ_F32)
                a->d = (float)a->d;
            break;
        case FZ_PTR_IN: a->i = in_offset(s); break;
        case FZ_PTR_OUT: a->i = (int64_t)below(s, FZ_OUT_WINDOW / 16) * 16; break;
        case FZ_CTX: a->i = 0; break;
        }
    }
}

/* Keeps what a call may read or write inside the arenas (see the top). */
static int64_t cap(int64_t v, int64_t max, int enormous_ok)
{
    if (v <= max)
        return v;
    if (enormous_ok && v >= (1 << 16))
        return v;
    return v % (max + 1);
}

static void bound_call(fz_call *c)
{
    const fz_entry *e = &fz_table[c->fn];
    const int b = entry_bound[c->fn];
    int64_t max;
    int enormous = 0;

    switch (b) {
    case B_NONE: return;
    case B_POINTER: max = 512; break;
    case B_TEXTURE: max = 512; enormous = 1; break;
    case B_ARRAYS: max = 4096; break;
    case B_MESH: max = 16; break;   /* meshes of at most 17x17 points: a list may replay them many times */
    case B_LISTS: max = 100000; break;
    case B_PIXELSTORE: max = 64; break;
    case B_SELECT: max = 1 << 20; break;
    case B_OSMESA: max = FZ_COLOR_MAX; break;
    default: return;
    }
    for (int j = 0; j < e->nparams; j++) {
        const int k = e->params[j].kind;
        fz_arg *a = &c->a[j];
        if ((k == FZ_I32 || k == FZ_SIZE) && b == B_MESH && (int32_t)a->i < -max)
            a->i = (int32_t)a->i % (max + 1);   /* a mesh from INT_MIN: 2^31 steps */
        else if (k == FZ_I32 || k == FZ_SIZE)
            a->i = cap((int32_t)a->i, max, enormous);
        else if (k == FZ_U32 && b != B_POINTER)
            a->i = (uint32_t)cap((uint32_t)a->i, max, enormous);
        else if ((k == FZ_F32 || k == FZ_F64) && b == B_PIXELSTORE && a->d > (double)max)
            a->d = fmod(a->d, (double)max);
        else if (k == FZ_PTR_OUT && b == B_SELECT)
            a->i = FZ_OUT_PERSIST + (a->i % (4 << 20));
        else if (k == FZ_PTR_OUT && b == B_OSMESA && strcmp(e->name, "OSMesaMakeCurrent") == 0)
            a->i = FZ_PTR_COLOR;
    }
    /* the indices of glDrawElements: small values (the arrays' reads stay
     * inside the arena) */
    if (b == B_ARRAYS)
        for (int j = 0; j < e->nparams; j++)
            if (e->params[j].kind == FZ_PTR_IN)
                c->a[j].i = FZ_IN_SMALL + c->a[j].i % (1 << 20);
    /* the multi-draws: at most 16 draws (their counts and firsts are the
     * small values above), glMultiDrawElements' index lists from the
     * pointer table */
    if (b == B_ARRAYS && starts_with(e->name, "glMultiDraw"))
        for (int j = 0; j < e->nparams; j++) {
            if (e->params[j].kind == FZ_SIZE && strcmp(e->params[j].name, "drawcount") == 0)
                c->a[j].i = (int32_t)c->a[j].i % 17;
            else if (e->params[j].kind == FZ_PTR_IN && strcmp(e->params[j].name, "indices") == 0)
                c->a[j].i = FZ_IN_PTRS + 8 * (c->a[j].i % 8000);
        }
    /* +Inf pixel-store values: fmod gives NaN, which converts to INT_MIN
     * (invalid) on both sides, as -Inf does. */
}

/* --- stream structure ------------------------------------------------------ */
typedef struct {
    fz_src *s;
    fz_call *out;
    size_t n, max;
    int depth;
    uint32_t compiling;   /* the list being compiled, or 0 */
    unsigned list_calls;  /* glCallList calls compiled into it */
} gen;

static int room(const gen *g) { return g->n < g->max && !exhausted(g->s); }

/* the bound a glNewList sets for the calls compiled after it: its name
 * (1 for name 0, whose glNewList fails), or the lower bound already set
 * since the last glEndList (see emit) */
static uint32_t list_bound(uint32_t bound, const fz_call *newlist)
{
    const uint32_t name = (uint32_t)newlist->a[0].i ? (uint32_t)newlist->a[0].i : 1;
    return bound && bound < name ? bound : name;
}

static fz_call *emit(gen *g, int fn, unsigned valid)
{
    if (fn < 0 || !room(g))
        return NULL;
    fz_call *c = &g->out[g->n++];
    gen_args(g->s, fn, c, valid);
    bound_call(c);
    /* A negative stride raises GL_INVALID_VALUE, and the oracle sets the
     * array all the same (validate_array does not return): what a draw
     * then reads is where llvmpipe's 32-bit offsets lead, undefined.  The
     * error and the stored state are compared; the array is set again
     * validly before anything can draw from it. */
    if (starts_with(fz_table[fn].name, "gl") && strstr(fz_table[fn].name, "Pointer") &&
        !strstr(fz_table[fn].name, "Get")) {
        const fz_entry *e = &fz_table[fn];
        for (int j = 0; j < e->nparams; j++)
            if (strcmp(e->params[j].name, "stride") == 0 && (int32_t)c->a[j].i < 0 && room(g)) {
                fz_call *v = &g->out[g->n++];
                *v = *c;
                for (int k = 0; k < e->nparams; k++) {
                    const char *pn = e->params[k].name;
                    if (strcmp(pn, "size") == 0)
                        v->a[k].i = 4;
                    else if (strcmp(pn, "type") == 0)
                        v->a[k].i = GL_FLOAT;
                    else if (strcmp(pn, "stride") == 0)
                        v->a[k].i = 0;
                    else if (e->params[k].kind == FZ_PTR_IN)
                        v->a[k].i = FZ_IN_FLOATS;
                }
                break;
            }
    }
    /* Lists call only lists of lower names, at most twice each (a list
     * compiled while list n is compiled calls below n): with cycles or
     * a large fan-out, nesting to 64 levels is exponential work in both
     * libraries, a hang of the stream's own making.  (The oracle also
     * crashes when a list being compiled calls itself inside glBegin.)
     * Which glNewList starts a list is not modelled (a bad mode, name 0,
     * an open glBegin or an open list make it fail), so the bound is the
     * lowest name of every glNewList since the last glEndList: a failed
     * outer glNewList(7, bad mode) followed by glNewList(4, GL_COMPILE)
     * compiles list 4, which must not call 4 (it called itself twice:
     * 2^64 calls through 64 levels, the long campaign's timeouts of
     * chunks 17 and b7; the oracle hangs on such a list too, and crashes
     * when the calls are inside glBegin).  When the outer one is the list
     * compiled (the inner glNewList raises GL_INVALID_OPERATION), the
     * lower bound is only stricter; the next glEndList ends it.
     * display_list() renames its list after this, and sets the bound
     * again. */
    if (fn == special[E_NEWLIST]) {
        if (!g->compiling)
            g->list_calls = 0;
        g->compiling = list_bound(g->compiling, c);
    } else if (fn == special[E_ENDLIST]) {
        g->compiling = 0;
    } else if (g->compiling && fn == special[E_CALLLIST]) {
        c->a[0].i = g->list_calls++ < 2 ? below(g->s, g->compiling) : 0;
    } else if (g->compiling && fn == special[E_CALLLISTS]) {
        c->a[0].i = 0;   /* no names: the call and its errors only */
    }
    return c;
}

static void set_int(fz_call *c, int j, int64_t v) { if (c) c->a[j].i = v; }

static void piece(gen *g);

static void random_call(gen *g)
{
    if (n_any_entries)
        emit(g, any_entries[below(g->s, (uint32_t)n_any_entries)], 80);
}

static void begin_end(gen *g)
{
    fz_call *b = emit(g, special[E_BEGIN], 92);
    (void)b;
    for (uint32_t i = 0, n = 1 + below(g->s, 12); i < n && room(g); i++) {
        if (n_vertex_entries && chance(g->s, 85))
            emit(g, vertex_entries[below(g->s, (uint32_t)n_vertex_entries)], 85);
        else
            random_call(g);
    }
    emit(g, special[E_END], 100);
}

static void display_list(gen *g)
{
    const uint32_t outer = g->compiling;
    fz_call *c = emit(g, special[E_NEWLIST], 90);
    const uint32_t name = 1 + below(g->s, 8);
    set_int(c, 0, chance(g->s, 90) ? name : c ? c->a[0].i : 0);
    /* the bound of the list's calls is the name it is compiled under (the
     * name emit() saw was the random one: a list renamed 5 but bounded by
     * a random 2^30 called itself, 2^64 calls through 64 levels) */
    if (c)
        g->compiling = list_bound(outer, c);
    g->depth++;
    for (uint32_t i = 0, n = 1 + below(g->s, 6); i < n && room(g); i++)
        piece(g);
    g->depth--;
    emit(g, special[E_ENDLIST], 100);
    if (chance(g->s, 60)) {
        c = emit(g, special[E_CALLLIST], 100);
        set_int(c, 0, name);
    }
}

static void vertex_arrays(gen *g)
{
    static const int ptrs[] = { E_VERTEXPOINTER, E_COLORPOINTER, E_NORMALPOINTER,
                                E_TEXCOORDPOINTER };
    static const uint32_t arrays[] = { GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY,
                                       GL_TEXTURE_COORD_ARRAY };
    if (chance(g->s, 25)) {
        fz_call *c = emit(g, special[E_INTERLEAVED], 90);
        if (c && chance(g->s, 70))
            c->a[1].i = 0;
    } else {
        for (int k = 0; k < 4; k++) {
            if (k && chance(g->s, 50))
                continue;
            fz_call *c = emit(g, special[ptrs[k]], 92);
            if (c && k != 2) {      /* size, type, stride */
                c->a[0].i = chance(g->s, 90) ? (k == 1 ? 3 + below(g->s, 2) : 2 + below(g->s, 3))
                                             : c->a[0].i;
                if (chance(g->s, 60))
                    c->a[1].i = GL_FLOAT;
                c->a[2].i = chance(g->s, 70) ? 0 : c->a[2].i % 65;
                c->a[3].i = FZ_IN_FLOATS + (int64_t)below(g->s, 1u << 17) * 8;
            } else if (c) {         /* glNormalPointer: type, stride */
                if (chance(g->s, 60))
                    c->a[0].i = GL_FLOAT;
                c->a[1].i = chance(g->s, 70) ? 0 : c->a[1].i % 65;
                c->a[2].i = FZ_IN_FLOATS + (int64_t)below(g->s, 1u << 17) * 8;
            }
            c = emit(g, special[E_ENABLECLIENT], 100);
            set_int(c, 0, arrays[k]);
        }
    }
    for (uint32_t i = 0, n = 1 + below(g->s, 3); i < n && room(g); i++) {
        fz_call *c;
        switch (below(g->s, 4)) {
        case 0: c = emit(g, special[E_DRAWARRAYS], 92);
            if (c && chance(g->s, 80)) {
                c->a[1].i = below(g->s, 8);
                c->a[2].i = below(g->s, 40);
            }
            break;
        case 1: c = emit(g, special[E_DRAWELEMENTS], 92);
            if (c && chance(g->s, 80)) {
                c->a[1].i = below(g->s, 40);
                c->a[3].i = FZ_IN_SMALL + (int64_t)below(g->s, 1u << 17) * 8;
            }
            break;
        case 2: begin_end(g); break;
        default: random_call(g); break;
        }
    }
}

static void select_feedback(gen *g)
{
    const int feedback = chance(g->s, 50);
    fz_call *c = emit(g, special[feedback ? E_FEEDBACKBUFFER : E_SELECTBUFFER], 90);
    if (c && chance(g->s, 80))
        c->a[0].i = 1 + below(g->s, 4096);
    c = emit(g, special[E_RENDERMODE], 95);
    set_int(c, 0, feedback ? GL_FEEDBACK : GL_SELECT);
    if (!feedback)
        emit(g, special[E_INITNAMES], 100);
    for (uint32_t i = 0, n = 1 + below(g->s, 6); i < n && room(g); i++) {
        if (!feedback && chance(g->s, 30))
            emit(g, special[chance(g->s, 50) ? E_PUSHNAME : E_LOADNAME], 90);
        else if (feedback && chance(g->s, 15))
            emit(g, special[E_PASSTHROUGH], 80);
        else
            piece(g);
    }
    c = emit(g, special[E_RENDERMODE], 100);
    set_int(c, 0, GL_RENDER);
}

static void evaluators(gen *g)
{
    const int two = chance(g->s, 50);
    fz_call *c = emit(g, special[two ? E_MAP2F : E_MAP1F], 90);
    if (c && chance(g->s, 85)) {
        if (two) {          /* target u1 u2 ustride uorder v1 v2 vstride vorder points */
            c->a[3].i = 4 + below(g->s, 2);
            c->a[4].i = 1 + below(g->s, 5);
            c->a[7].i = c->a[3].i * c->a[4].i;
            c->a[8].i = 1 + below(g->s, 5);
            c->a[9].i = FZ_IN_FLOATS + (int64_t)below(g->s, 1u << 17) * 8;
        } else {            /* target u1 u2 stride order points */
            c->a[3].i = 4 + below(g->s, 2);
            c->a[4].i = 1 + below(g->s, 6);
            c->a[5].i = FZ_IN_FLOATS + (int64_t)below(g->s, 1u << 17) * 8;
        }
    }
    if (c) {
        fz_call *en = emit(g, special[E_ENABLE], 100);
        set_int(en, 0, c->a[0].i);
    }
    c = emit(g, special[two ? E_MAPGRID2F : E_MAPGRID1F], 90);
    if (c && chance(g->s, 80))
        c->a[0].i = below(g->s, 12), two ? (void)(c->a[3].i = below(g->s, 12)) : (void)0;
    for (uint32_t i = 0, n = 1 + below(g->s, 3); i < n && room(g); i++) {
        if (chance(g->s, 50)) {
            c = emit(g, special[two ? E_EVALMESH2 : E_EVALMESH1], 92);
            if (c && chance(g->s, 80)) {
                c->a[1].i = below(g->s, 4);
                c->a[2].i = c->a[1].i + below(g->s, 10);
                if (two) {
                    c->a[3].i = below(g->s, 4);
                    c->a[4].i = c->a[3].i + below(g->s, 10);
                }
            }
        } else {
            emit(g, special[E_BEGIN], 90);
            for (uint32_t k = 0, m = 1 + below(g->s, 8); k < m; k++)
                emit(g, special[two ? E_EVALCOORD2F : E_EVALCOORD1F], 90);
            emit(g, special[E_END], 100);
        }
    }
}

static void texture(gen *g)
{
    fz_call *c = emit(g, special[E_BINDTEXTURE], 90);
    if (c && chance(g->s, 80))
        c->a[1].i = below(g->s, 4);
    c = emit(g, special[E_TEXIMAGE2D], 90);
    if (c && chance(g->s, 70)) {  /* target level ifmt w h border format type pixels */
        c->a[1].i = below(g->s, 3);
        c->a[3].i = 1u << below(g->s, 6);
        c->a[4].i = 1u << below(g->s, 6);
        c->a[5].i = chance(g->s, 90) ? 0 : c->a[5].i;
    }
    for (uint32_t i = 0, n = below(g->s, 3); i < n; i++)
        emit(g, special[E_TEXPARAMETERI], 90);
    c = emit(g, special[E_ENABLE], 100);
    set_int(c, 0, GL_TEXTURE_2D);
    begin_end(g);
}

static void piece(gen *g)
{
    const uint32_t r = below(g->s, 100);
    if (r < 45 || g->depth > 2)
        random_call(g);
    else if (r < 65)
        begin_end(g);
    else if (r < 72)
        display_list(g);
    else if (r < 81)
        vertex_arrays(g);
    else if (r < 87)
        select_feedback(g);
    else if (r < 93)
        evaluators(g);
    else
        texture(g);
}

static size_t generate(fz_src *s, fz_call *out, size_t max)
{
    gen g = { s, out, 0, max, 0, 0, 0 };
    /* a visible scene to start from */
    fz_call *c;
    while (room(&g)) {
        if (g.n == 0 && chance(s, 70)) {
            c = emit(&g, special[E_BEGIN], 100);
            set_int(c, 0, GL_TRIANGLES);
            for (int i = 0; i < 3; i++) {
                c = emit(&g, special[E_COLOR4F], 100);
                if (c)
                    for (int k = 0; k < 4; k++)
                        c->a[k].d = (float)unit(s);
                c = emit(&g, special[E_VERTEX3F], 100);
                if (c)
                    for (int k = 0; k < 3; k++)
                        c->a[k].d = (float)(unit(s) * 2 - 1);
            }
            emit(&g, special[E_END], 100);
        }
        piece(&g);
    }
    return g.n;
}

size_t fz_gen_seed(uint64_t seed, fz_call *out, size_t max)
{
    fz_src s = { seed * 0x2545f4914f6cdd1dull + 1, NULL, 0, 0, NULL, 0, 0 };
    return generate(&s, out, max);
}

uint8_t *fz_gen_seed_bytes(uint64_t seed, fz_call *out, size_t max, size_t *len)
{
    fz_src s = { seed * 0x2545f4914f6cdd1dull + 1, NULL, 0, 0, malloc(4096), 0, 4096 };
    generate(&s, out, max);
    *len = s.rec_len;
    return s.rec;
}

size_t fz_gen_bytes(const uint8_t *data, size_t len, fz_call *out, size_t max)
{
    fz_src s = { 0, data, len, 0, NULL, 0, 0 };
    return generate(&s, out, max);
}

/* --- the input arena --------------------------------------------------------- */
void fz_fill_input_arena(uint8_t *arena, size_t size)
{
    uint64_t st = 0x243f6a8885a308d3ull;
    for (size_t off = 0; off + 8 <= size; off += 8) {
        const uint64_t r = splitmix(&st);
        uint8_t *p = arena + off;
        if (off >= FZ_IN_FLOATS && off < FZ_IN_DOUBLES) {
            float f[2] = { (float)((r & 0xffff) / 16384.0 - 2.0),
                           (float)(((r >> 16) & 0xffff) / 16384.0 - 2.0) };
            memcpy(p, f, 8);
        } else if (off >= FZ_IN_DOUBLES && off < FZ_IN_SMALL) {
            double d = (double)(r & 0xffffff) / 4194304.0 - 2.0;
            memcpy(p, &d, 8);
        } else if (off >= FZ_IN_SMALL && off < FZ_IN_RANDOM) {
            uint32_t u[2] = { (uint32_t)(r & 0xff), (uint32_t)((r >> 8) & 0xff) };
            memcpy(p, u, 8);
        } else if (off >= FZ_IN_PTRS) {
            const uint64_t v = FZ_IN_BASE + FZ_IN_SMALL + (r & 0xfffff);
            memcpy(p, &v, 8);
        } else if (off >= FZ_IN_RANDOM) {
            /* no signalling NaNs, as floats or doubles: GL leaves NaN input
             * unspecified (2.1.1) and the oracle keeps a payload that
             * fixgl's conversions quiet */
            uint64_t q = r;
            if ((q & 0x7ff0000000000000ull) == 0x7ff0000000000000ull && (q & 0x000fffffffffffffull))
                q |= 0x0008000000000000ull;
            for (int h = 0; h < 2; h++) {
                const uint32_t w = (uint32_t)(q >> (32 * h));
                if ((w & 0x7f800000u) == 0x7f800000u && (w & 0x007fffffu))
                    q |= (uint64_t)0x00400000u << (32 * h);
            }
            memcpy(p, &q, 8);
        } else {
            memset(p, (off >> 20) & 1 ? 0 : (int)(r & 0xff), 8);
        }
    }
}

/* --- stream files and C output ---------------------------------------------- */
int fz_write_stream(const char *path, const fz_call *calls, size_t n)
{
    FILE *f = fopen(path, "wb");
    uint64_t count = n;
    if (!f)
        return -1;
    int ok = fwrite(&count, sizeof count, 1, f) == 1 &&
             (n == 0 || fwrite(calls, sizeof *calls, n, f) == n);
    return fclose(f) == 0 && ok ? 0 : -1;
}

fz_call *fz_read_stream(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    uint64_t count;
    fz_call *calls = NULL;
    if (!f)
        return NULL;
    if (fread(&count, sizeof count, 1, f) == 1 && count < (1u << 24)) {
        calls = malloc((count ? count : 1) * sizeof *calls);
        if (calls && fread(calls, sizeof *calls, count, f) != count) {
            free(calls);
            calls = NULL;
        }
    }
    fclose(f);
    *n = calls ? (size_t)count : 0;
    return calls;
}

size_t fz_gen_file(const char *path, fz_call *out, size_t max, size_t *len)
{
    FILE *f = fopen(path, "rb");
    uint8_t *data = NULL;
    size_t cap = 0, got, n = FZ_GEN_FILE_ERROR;
    *len = 0;
    if (!f)
        return FZ_GEN_FILE_ERROR;
    do {
        if (*len == cap) {
            uint8_t *grown = realloc(data, cap = cap ? 2 * cap : 4096);
            if (!grown)
                goto out;
            data = grown;
        }
        got = fread(data + *len, 1, cap - *len, f);
        *len += got;
    } while (got > 0);
    if (!ferror(f))
        n = fz_gen_bytes(data, *len, out, max);
out:
    free(data);
    fclose(f);
    return n;
}

static void print_arg(FILE *f, const fz_param *p, const fz_arg *a)
{
    uint32_t u32;
    uint64_t u64;
    float fl;
    switch (p->kind) {
    case FZ_F32:
        fl = (float)a->d;
        memcpy(&u32, &fl, 4);
        fprintf(f, "f32(0x%08x) /* %g */", u32, (double)fl);
        break;
    case FZ_F64:
        memcpy(&u64, &a->d, 8);
        fprintf(f, "f64(0x%016llxull) /* %g */", (unsigned long long)u64, a->d);
        break;
    case FZ_PTR_IN: fprintf(f, "IN(0x%llx)", (unsigned long long)a->i); break;
    case FZ_PTR_OUT:
        if (a->i == FZ_PTR_COLOR)
            fprintf(f, "COLOR");
        else
            fprintf(f, "OUT(0x%llx)", (unsigned long long)a->i);
        break;
    case FZ_CTX: fprintf(f, "ctx"); break;
    case FZ_ENUM: case FZ_BITFIELD: case FZ_U32:
        fprintf(f, "0x%x", (unsigned)(uint32_t)a->i);
        break;
    case FZ_U8: case FZ_U16: case FZ_BOOL:
        fprintf(f, "%u", (unsigned)(uint32_t)a->i);
        break;
    default:
        if ((int32_t)a->i == INT32_MIN)
            fprintf(f, "(-2147483647 - 1)");
        else
            fprintf(f, "%d", (int)(int32_t)a->i);
        break;
    }
}

void fz_print_c(FILE *f, const fz_call *calls, size_t n, const char *comment)
{
    fprintf(f,
        "/* %s\n"
        " * Replays the stream on either library:\n"
        " *   cc repro.c -o repro-osmesa -lOSMesa -lm\n"
        " *   cc repro.c -o repro-fixgl -I include -L build/libfixgl -lfixgl -lm\n"
        " * It prints glGetError after every call.  Pointer arguments point into\n"
        " * the fuzzer's input arena (the same deterministic contents,\n"
        " * conformance/fuzz/fz_gen.c fz_fill_input_arena) and output arena,\n"
        " * mapped at the executor's addresses. */\n"
        "#include <GL/gl.h>\n#include <GL/osmesa.h>\n"
        "#include <stdint.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n"
        "#include <sys/mman.h>\n\n"
        "#define IN(o) ((void *)(0x%llxull + (o)))\n"
        "#define OUT(o) ((void *)(0x%llxull + (o)))\n"
        "#define COLOR OUT(0x%x)\n"
        "static float f32(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }\n"
        "static double f64(uint64_t u) { double d; memcpy(&d, &u, 8); return d; }\n"
        "static void err(int i) { printf(\"%%d: 0x%%x\\n\", i, glGetError()); }\n"
        "static void ret(int i, unsigned v) { printf(\"%%d: returns %%u\\n\", i, v); }\n"
        "static void output(int i, const void *p)   /* what the call wrote there */\n{\n"
        "    uint64_t h = 0xcbf29ce484222325ull;\n"
        "    for (int k = 0; k < %u; k++)\n"
        "        h = (h ^ ((const uint8_t *)p)[k]) * 0x100000001b3ull;\n"
        "    printf(\"%%d: output %%016llx\\n\", i, (unsigned long long)h);\n}\n\n"
        "static uint64_t splitmix(uint64_t *s)\n{\n"
        "    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);\n"
        "    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;\n"
        "    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;\n"
        "    return z ^ (z >> 31);\n}\n\n"
        "static void fill(uint8_t *arena, size_t size)\n{\n"
        "    uint64_t st = 0x243f6a8885a308d3ull;\n"
        "    for (size_t off = 0; off + 8 <= size; off += 8) {\n"
        "        const uint64_t r = splitmix(&st);\n"
        "        uint8_t *p = arena + off;\n"
        "        if (off >= 0x%xu && off < 0x%xu) {\n"
        "            float f[2] = { (float)((r & 0xffff) / 16384.0 - 2.0),\n"
        "                           (float)(((r >> 16) & 0xffff) / 16384.0 - 2.0) };\n"
        "            memcpy(p, f, 8);\n"
        "        } else if (off >= 0x%xu && off < 0x%xu) {\n"
        "            double d = (double)(r & 0xffffff) / 4194304.0 - 2.0;\n"
        "            memcpy(p, &d, 8);\n"
        "        } else if (off >= 0x%xu && off < 0x%xu) {\n"
        "            uint32_t u[2] = { (uint32_t)(r & 0xff), (uint32_t)((r >> 8) & 0xff) };\n"
        "            memcpy(p, u, 8);\n"
        "        } else if (off >= 0x%xu) {\n"
        "            const uint64_t v = 0x%llxull + (r & 0xfffff);\n"
        "            memcpy(p, &v, 8);\n"
        "        } else if (off >= 0x%xu) {\n"
        "            uint64_t q = r;\n"
        "            if ((q & 0x7ff0000000000000ull) == 0x7ff0000000000000ull && (q & 0x000fffffffffffffull))\n"
        "                q |= 0x0008000000000000ull;\n"
        "            for (int h = 0; h < 2; h++) {\n"
        "                const uint32_t w = (uint32_t)(q >> (32 * h));\n"
        "                if ((w & 0x7f800000u) == 0x7f800000u && (w & 0x007fffffu))\n"
        "                    q |= (uint64_t)0x00400000u << (32 * h);\n"
        "            }\n"
        "            memcpy(p, &q, 8);\n"
        "        } else {\n"
        "            memset(p, (off >> 20) & 1 ? 0 : (int)(r & 0xff), 8);\n"
        "        }\n    }\n}\n\n",
        comment, (unsigned long long)FZ_IN_BASE, (unsigned long long)FZ_OUT_BASE,
        FZ_COLOR_OFF, FZ_OUT_HASHED, FZ_IN_FLOATS, FZ_IN_DOUBLES, FZ_IN_DOUBLES, FZ_IN_SMALL, FZ_IN_SMALL,
        FZ_IN_RANDOM, FZ_IN_PTRS, (unsigned long long)(FZ_IN_BASE + FZ_IN_SMALL), FZ_IN_RANDOM);
    fprintf(f,
        "int main(void)\n{\n"
        "    uint8_t *in = mmap((uint8_t *)IN(0) - 0x%llxull, 0x%llxull, PROT_READ | PROT_WRITE,\n"
        "                       MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED_NOREPLACE | MAP_NORESERVE,\n"
        "                       -1, 0) + 0x%llxull;\n"
        "    uint8_t *out = mmap(OUT(0), 0x%xu, PROT_READ | PROT_WRITE,\n"
        "                        MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED_NOREPLACE, -1, 0);\n"
        "    if (in != IN(0) || out != OUT(0))\n        return 2;\n"
        "    fill(in, 0x%xu);\n"
        "    memset(COLOR, 0, %d * %d * 16);\n"
        "    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);\n"
        "    if (!ctx || !OSMesaMakeCurrent(ctx, COLOR, GL_UNSIGNED_BYTE, 64, 64))\n"
        "        return 2;\n"
        "    (void)ctx;\n"
        "    /* the executor's client arrays (fz_exec.c client_arrays) */\n"
        "    glVertexPointer(4, GL_FLOAT, 0, IN(0x%x));\n"
        "    glNormalPointer(GL_FLOAT, 0, IN(0x%x));\n"
        "    glColorPointer(4, GL_FLOAT, 0, IN(0x%x));\n"
        "    glIndexPointer(GL_FLOAT, 0, IN(0x%x));\n"
        "    glEdgeFlagPointer(0, IN(0x%x));\n"
        "    for (int u = 7; u >= 0; u--) {\n"
        "        glClientActiveTexture(GL_TEXTURE0 + (GLenum)u);\n"
        "        glTexCoordPointer(4, GL_FLOAT, 0, IN(0x%x));\n"
        "    }\n"
        "    OSMESAproc sp = OSMesaGetProcAddress(\"glSecondaryColorPointer\");\n"
        "    OSMESAproc fp = OSMesaGetProcAddress(\"glFogCoordPointer\");\n"
        "    if (sp)\n"
        "        ((void (*)(GLint, GLenum, GLsizei, const void *))sp)(3, GL_FLOAT, 0, IN(0x%x));\n"
        "    if (fp)\n"
        "        ((void (*)(GLenum, GLsizei, const void *))fp)(GL_FLOAT, 0, IN(0x%x));\n"
        "    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT |\n"
        "            GL_ACCUM_BUFFER_BIT);\n"
        "    glFinish();\n"
        "    while (glGetError())\n        ;\n",
        (unsigned long long)FZ_IN_BEFORE,
        (unsigned long long)(FZ_IN_BEFORE + FZ_IN_AFTER), (unsigned long long)FZ_IN_BEFORE,
        FZ_OUT_SIZE, FZ_IN_SIZE, FZ_COLOR_MAX,
        FZ_COLOR_MAX, FZ_IN_FLOATS, FZ_IN_FLOATS, FZ_IN_FLOATS, FZ_IN_FLOATS, FZ_IN_SMALL,
        FZ_IN_FLOATS, FZ_IN_FLOATS, FZ_IN_FLOATS);
    int inside = 0;   /* no glGetError between glBegin and glEnd (fz_exec.c) */
    for (size_t i = 0; i < n; i++) {
        const fz_entry *e = &fz_table[calls[i].fn];
        for (int j = 0; j < e->nparams; j++)
            if (e->params[j].kind == FZ_PTR_OUT && calls[i].a[j].i >= 0 &&
                calls[i].a[j].i < FZ_OUT_PERSIST)
                fprintf(f, "    memset(OUT(0x%llx), 0xa5, %u);\n",
                        (unsigned long long)calls[i].a[j].i, FZ_OUT_HASHED);
        if (e->ret == FZ_RET_PTR)
            fprintf(f, "    ret(%zu, NULL != %s(", i, e->name);
        else if (e->ret == FZ_RET_INT)
            fprintf(f, "    ret(%zu, (unsigned)%s(", i, e->name);
        else
            fprintf(f, "    %s(", e->name);
        inside |= strcmp(e->name, "glBegin") == 0;
        for (int j = 0; j < e->nparams; j++) {
            if (j)
                fprintf(f, ", ");
            print_arg(f, &e->params[j], &calls[i].a[j]);
        }
        if (strcmp(e->name, "glEnd") == 0)
            inside = 0;
        fprintf(f, e->ret == FZ_RET_VOID ? ");\n" : "));\n");
        for (int j = 0; j < e->nparams; j++)
            if (e->params[j].kind == FZ_PTR_OUT && calls[i].a[j].i >= 0 &&
                calls[i].a[j].i < FZ_OUT_PERSIST && strcmp(e->name, "OSMesaGetDepthBuffer"))
                fprintf(f, "    output(%zu, OUT(0x%llx));\n", i, (unsigned long long)calls[i].a[j].i);
        if (!inside)
            fprintf(f, "    err(%zu);\n", i);
    }
    /* what the executor does after the stream (fz_exec_run: a glEnd when
     * the stream ends inside glBegin/glEnd; fz_exec_final: glEndList,
     * glRenderMode(GL_RENDER)), so the reproducer draws what the executor
     * compared (seed 3000589: a line strip left open) */
    if (inside)
        fprintf(f, "    glEnd();\n");
    fprintf(f, "    glEndList();\n"
               "    glRenderMode(GL_RENDER);\n"
               "    while (glGetError())\n"
               "        ;\n");
    fprintf(f, "    glFinish();\n"
               "    uint64_t h = 0xcbf29ce484222325ull;   /* the colour buffer's digest */\n"
               "    for (size_t i = 0; i < %d * %d * 16; i++)\n"
               "        h = (h ^ ((uint8_t *)COLOR)[i]) * 0x100000001b3ull;\n"
               "    printf(\"colour buffer digest %%016llx\\n\", (unsigned long long)h);\n"
               "    return 0;\n}\n", FZ_COLOR_MAX, FZ_COLOR_MAX);
}
