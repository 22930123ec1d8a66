/* fc_emit.c - the emission layer of the random scenes (see fc_emit.h).
 *
 * Values.  A recorded attribute call keeps its raw arguments (every GL type
 * is exact in a double).  An array holds them either in the call's own type
 * or as the float immediate mode stores for the call, and the choice keeps
 * the oracle's value:
 *   - glArrayElement converts like the immediate-mode call of the array's
 *     type and size [S: main/api_arrayelt.c, AttribFuncsNV: normalized
 *     integers with main/macros.h BYTE_TO_FLOAT...]: an array of the calls'
 *     own type (uniform over the block) is exact, and so is a float (or
 *     double) array of the converted values;
 *   - an array draw fetches in draw's LLVM vertex shader with gallivm's
 *     normalization (lp_bld_conv.c), not main/macros.h: integer vertices
 *     and float / double values convert as immediate mode does, normalized
 *     integer colours and normals do not, so a draw takes colours and
 *     normals of other types as floats converted the immediate way, except
 *     ubyte and ushort colours when every call of the block used that type
 *     (gallivm's c * (1 / (2^n - 1)) may then differ from c / (2^n - 1) in
 *     the last bit; both renderers get the same array).
 * A normalized integer array is only used when every call of the block
 * has the array's size: an alpha of 255 or 65535 is not exactly the 1.0 a
 * three-component call gives.
 *
 * Current values.  glArrayElement sets them as the calls would; after an
 * array draw the block's last call of each attribute is issued again. */
#define GL_GLEXT_PROTOTYPES 1   /* buffer objects, multi-draws */
#define FC_EMIT_NO_MACROS
#include "fc_emit.h"
#include "fc_rng.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fce_recording, fce_record_blocks;
enum fce_path fce_path_now;

struct ev {
    unsigned char kind, type, size, vec;
    GLenum face, pname;             /* FCE_MATERIAL */
    int variant, n;                 /* FCE_MATERIAL: f, fv, i, iv; values */
    double v[4];
};

/* Structure of a scene's arrays: from the profile stream. */
struct policy {
    int use_draw;                   /* array draws where a block allows them */
    int vtype, ctype, ntype;        /* 0: the calls' type when uniform, 1: float, 2: double */
    int layout;                     /* 0, 1: separate arrays, tight or padded; 2: interleaved; 3: glInterleavedArrays when a format fits */
    int pad;                        /* padding bytes */
    int order;                      /* attribute order inside an interleaved vertex */
    int explicit_stride;            /* tight arrays: the element size rather than 0 */
    /* from a stream of their own (the other choices stay as they were) */
    int vbo;                        /* % of array blocks whose arrays are in a buffer object */
    int ibo;                        /* % of element draws whose indices are in one */
    int multi;                      /* % of draws issued as glMultiDrawArrays / Elements */
};

/* Display lists of a FCE_DLIST scene (see fce_dl_*). */
#define DL_DEFER_MAX 12
struct dl {
    int cut;                        /* % of glEnd that end the list being compiled */
    int cae;                        /* % of lists compiled with GL_COMPILE_AND_EXECUTE */
    int arrays;                     /* the blocks inside the lists through arrays */
    int open;                       /* a list is being compiled */
    GLenum mode;                    /* its mode */
    GLuint next;                    /* next list name (fixed names, never glGenLists) */
    GLuint deferred[DL_DEFER_MAX];  /* compiled with GL_COMPILE, not called yet */
    int ndeferred;
};

static struct {
    fc_rng val;                     /* per-block choices that compile nothing */
    fc_rng bo;                      /* per-block buffer object and multi-draw choices */
    struct policy P;
    struct dl D;
    GLenum mode;
    struct ev *ev;
    int nev, cap;
    int nbuf;
} E;

const char *fce_path_name(enum fce_path path)
{
    return path == FCE_ARRAYS ? "arrays" : path == FCE_DLIST ? "dlist" : "immediate";
}

enum fce_path fce_scene_begin(enum fce_family family, uint64_t seed, uint32_t index,
                              uint32_t profile)
{
    fc_rng k = fc_rng_make(seed, profile, 40 + (uint32_t)family);
    int p = (int)fc_rng_below(&k, 100);
    enum fce_path path = p < 45 ? FCE_ARRAYS : p < 75 ? FCE_DLIST : FCE_IMMEDIATE;
    /* the lit scenes take lists in a third of that share: the oracle
     * compiles new vertex-fetch and shader variants for the lists' merged
     * vertex formats (all of it: +34% CPU on 2000 scenes with a cold
     * shader cache; this: README "Emission paths") */
    if (family == FCE_LIT && path == FCE_DLIST && p >= 55)
        path = FCE_IMMEDIATE;
    /* FC_EMIT=immediate|arrays|dlist forces one path on every scene (both
     * renderers inherit the runner's environment) */
    const char *force = getenv("FC_EMIT");
    if (force && !strcmp(force, "immediate"))
        path = FCE_IMMEDIATE;
    else if (force && !strcmp(force, "arrays"))
        path = FCE_ARRAYS;
    else if (force && !strcmp(force, "dlist"))
        path = FCE_DLIST;
    struct policy *P = &E.P;
    P->use_draw = fc_rng_chance(&k, 80);
    int t[3];
    for (int i = 0; i < 3; i++) {
        int c = (int)fc_rng_below(&k, 10);
        t[i] = c < 5 ? 0 : c < 8 ? 1 : 2;
    }
    P->vtype = t[0], P->ctype = t[1], P->ntype = t[2];
    P->layout = (int)fc_rng_below(&k, 4);
    P->pad = 4 * fc_rng_range(&k, 0, 3);
    P->order = (int)fc_rng_below(&k, 24);
    P->explicit_stride = fc_rng_chance(&k, 50);
    struct dl *D = &E.D;
    memset(D, 0, sizeof *D);
    D->cut = fc_rng_chance(&k, 25) ? 100 : fc_rng_range(&k, 0, 60);
    D->cae = (int)fc_rng_below(&k, 3) * 50;
    D->arrays = fc_rng_chance(&k, 30);
    E.val = fc_rng_make(seed, index, 50 + (uint32_t)family);
    {
        /* GL 1.5 buffer objects and GL 1.4 multi-draws, from streams of
         * their own: in about half the scenes the arrays come from a
         * vertex buffer (glBufferData, glBufferSubData or a mapped
         * buffer), the indices from an element buffer, draws split into
         * glMultiDrawArrays / glMultiDrawElements */
        fc_rng kb = fc_rng_make(seed, profile, 60 + (uint32_t)family);
        static const int pct[4] = { 0, 0, 50, 100 };
        P->vbo = pct[fc_rng_below(&kb, 4)];
        P->ibo = pct[fc_rng_below(&kb, 4)];
        P->multi = pct[fc_rng_below(&kb, 4)];
        /* FC_EMIT_BO=V,I,M overrides the three shares (percent; for
         * bisecting a difference: 0,0,0 draws as before they existed) */
        const char *bo = getenv("FC_EMIT_BO");
        if (bo)
            sscanf(bo, "%d,%d,%d", &P->vbo, &P->ibo, &P->multi);
        E.bo = fc_rng_make(seed, index, 70 + (uint32_t)family);
    }
    E.nev = 0;
    E.nbuf = 0;
    fce_recording = 0;
    fce_path_now = path;
    fce_record_blocks = path == FCE_ARRAYS || (path == FCE_DLIST && D->arrays);
    if (fc_trace_out)
        fprintf(fc_trace_out, "/* emission path: %s%s */\n", fce_path_name(path),
                path == FCE_DLIST && D->arrays ? " (blocks through arrays)" : "");
    if (path == FCE_DLIST) {
        D->next = 1 + fc_rng_below(&E.val, 60);
        fce_dl_open();
    }
    return path;
}

/* ---- recording ---- */

static struct ev *push(void)
{
    if (E.nev == E.cap) {
        E.cap = E.cap ? 2 * E.cap : 256;
        E.ev = realloc(E.ev, (size_t)E.cap * sizeof *E.ev);
        if (!E.ev)
            abort();
    }
    struct ev *e = &E.ev[E.nev++];
    memset(e, 0, sizeof *e);
    return e;
}

void fce_rec_attr(int kind, int type, int size, int vec,
                  double a, double b, double c, double d)
{
    struct ev *e = push();
    e->kind = (unsigned char)kind, e->type = (unsigned char)type;
    e->size = (unsigned char)size, e->vec = (unsigned char)vec;
    e->v[0] = a, e->v[1] = b, e->v[2] = c, e->v[3] = d;
}

void fce_rec_material(int variant, GLenum face, GLenum pname, const double *v, int n)
{
    struct ev *e = push();
    e->kind = FCE_MATERIAL;
    e->variant = variant, e->face = face, e->pname = pname, e->n = n;
    for (int i = 0; i < n && i < 4; i++)
        e->v[i] = v[i];
}

void fce_block_begin(GLenum mode)
{
    fce_recording = 1;
    E.mode = mode;
    E.nev = 0;
}

/* ---- replaying one recorded call ---- */

#define FCE_CALL1(f, t) f(t[0])
#define FCE_CALL2(f, t) f(t[0], t[1])
#define FCE_CALL3(f, t) f(t[0], t[1], t[2])
#define FCE_CALL4(f, t) f(t[0], t[1], t[2], t[3])
#define FCE_REPLAY(K, pre, n, suf, T, TY)                                    \
    if (e->kind == K && e->size == n && e->type == TY) {                     \
        T t[4] = { (T)e->v[0], (T)e->v[1], (T)e->v[2], (T)e->v[3] };         \
        if (e->vec)                                                          \
            fct_##pre##n##suf##v(t);                                         \
        else                                                                 \
            FCE_CALL##n(fct_##pre##n##suf, t);                               \
        return;                                                              \
    }

static void replay(const struct ev *e)
{
    if (e->kind == FCE_MATERIAL) {
        GLfloat f[4] = { (GLfloat)e->v[0], (GLfloat)e->v[1], (GLfloat)e->v[2], (GLfloat)e->v[3] };
        GLint iv[4] = { (GLint)e->v[0], (GLint)e->v[1], (GLint)e->v[2], (GLint)e->v[3] };
        switch (e->variant) {
        case 0: fct_glMaterialf(e->face, e->pname, f[0]); break;
        case 1: fct_glMaterialfv(e->face, e->pname, f); break;
        case 2: fct_glMateriali(e->face, e->pname, iv[0]); break;
        default: fct_glMaterialiv(e->face, e->pname, iv); break;
        }
        return;
    }
    if (e->kind == FCE_EDGE) {
        const GLboolean b = (GLboolean)e->v[0];
        if (e->vec)
            fct_glEdgeFlagv(&b);
        else
            fct_glEdgeFlag(b);
        return;
    }
    FCE_ATTR_VARIANTS(FCE_REPLAY)
    abort();
}

/* ---- values ---- */

/* The float immediate mode stores for component c of a call
 * [S: vbo/vbo_attrib_tmp.h, main/macros.h, main/context.c
 * _mesa_ubyte_to_float_color_tab]: vertices are cast, colours and normals
 * of integer types normalized. */
static float imm_float(const struct ev *e, int c)
{
    const double v = e->v[c];
    if (e->kind == FCE_VERTEX || e->kind == FCE_EDGE || e->kind == FCE_TEXCOORD)
        return (float)v;
    switch (e->type) {
    case FCE_B: return (2.0F * (GLbyte)v + 1.0F) * (1.0F / 255.0F);
    case FCE_UB: return (float)(GLubyte)v / 255.0F;
    case FCE_S: return (2.0F * (GLshort)v + 1.0F) * (1.0F / 65535.0F);
    case FCE_US: return (GLfloat)(GLushort)v * (1.0F / 65535.0F);
    case FCE_I: return (GLfloat)((2.0F * (GLint)v + 1.0F) * (1.0F / 4294967294.0));
    case FCE_UI: return (GLfloat)((GLuint)v * (1.0F / 4294967295.0));
    default: return (float)v;
    }
}

static const GLenum gl_type[8] = {
    GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT,
    GL_FLOAT, GL_DOUBLE,
};
static const int type_bytes[8] = { 1, 1, 2, 2, 4, 4, 4, 8 };

/* Stores x (already in the array type's range) as type t. */
static void put(unsigned char *p, int t, double x)
{
    switch (t) {
    case FCE_B: { GLbyte v = (GLbyte)x; memcpy(p, &v, 1); break; }
    case FCE_UB: { GLubyte v = (GLubyte)x; memcpy(p, &v, 1); break; }
    case FCE_S: { GLshort v = (GLshort)x; memcpy(p, &v, 2); break; }
    case FCE_US: { GLushort v = (GLushort)x; memcpy(p, &v, 2); break; }
    case FCE_I: { GLint v = (GLint)x; memcpy(p, &v, 4); break; }
    case FCE_UI: { GLuint v = (GLuint)x; memcpy(p, &v, 4); break; }
    case FCE_F: { GLfloat v = (GLfloat)x; memcpy(p, &v, 4); break; }
    default: memcpy(p, &x, 8); break;
    }
}

/* ---- one block through arrays ---- */

enum { A_POS, A_COL, A_NRM, A_EDGE, A_TEX, A_COUNT };

struct attr {
    int on;                         /* an array of this attribute */
    int type, size, bytes;          /* array type, components, bytes per element */
    int raw;                        /* values in the calls' own type */
    int offset, stride;             /* of element 0 in the buffer; stride in bytes */
};

static int kind_attr(int kind)
{
    return kind == FCE_VERTEX ? A_POS : kind == FCE_COLOR ? A_COL : kind == FCE_NORMAL ? A_NRM
         : kind == FCE_EDGE ? A_EDGE : kind == FCE_TEXCOORD ? A_TEX : -1;
}

/* Chooses the array type and size of attribute a from the block's calls of
 * it (see the head comment). */
static void choose_type(struct attr *at, int a, int draw)
{
    int uniform_type = -1, uniform_size = -1, max_size = 0, shorts = 1, ints = 1;
    for (int i = 0; i < E.nev; i++) {
        const struct ev *e = &E.ev[i];
        if (kind_attr(e->kind) != a)
            continue;
        for (int c = 0; c < e->size; c++) {
            shorts &= e->v[c] == floor(e->v[c]) && fabs(e->v[c]) <= 32767;
            ints &= e->v[c] == floor(e->v[c]) && fabs(e->v[c]) <= 2147483647.0;
        }
        uniform_type = uniform_type == -1 ? e->type : uniform_type == e->type ? uniform_type : -2;
        uniform_size = uniform_size == -1 ? e->size : uniform_size == e->size ? uniform_size : -2;
        if (e->size > max_size)
            max_size = e->size;
    }
    /* texture coordinates convert with a cast like vertices
     * [S: vbo_attrib_tmp.h TexCoord*: ATTR*F of the values] and take the
     * vertices' policy */
    const int pol = a == A_POS || a == A_TEX ? E.P.vtype : a == A_COL ? E.P.ctype : E.P.ntype;
    at->size = max_size;
    at->raw = 0;
    if (a == A_EDGE) {
        at->type = FCE_UB, at->raw = 1;
    } else if (pol == 1) {
        at->type = FCE_F;
    } else if (pol == 2) {
        at->type = FCE_D;
    } else if ((a == A_POS || a == A_TEX) && (shorts || ints)) {
        /* vertices convert with a cast: integer values are exact in an
         * integer array whatever call gave them */
        at->type = shorts ? FCE_S : FCE_I, at->raw = 1;
    } else if (uniform_type < 0) {
        at->type = FCE_F;
    } else if (a == A_POS || a == A_TEX || uniform_type == FCE_F || uniform_type == FCE_D) {
        at->type = uniform_type, at->raw = 1;
    } else if (uniform_size < 0) {
        at->type = FCE_F;           /* normalized integers: one size only */
    } else if (!draw || (a == A_COL && (uniform_type == FCE_UB || uniform_type == FCE_US))) {
        at->type = uniform_type, at->raw = 1;
    } else {
        at->type = FCE_F;
    }
    at->bytes = at->size * type_bytes[at->type];
}

/* The formats with texture coordinates (at offset 0): T2F_V3F,
 * T4F_V4F, T2F_C4UB_V3F, T2F_C3F_V3F, T2F_N3F_V3F, T2F_C4F_N3F_V3F,
 * T4F_C4F_N3F_V4F [S: main/varray.c:_mesa_get_interleaved_layout]. */
static GLenum interleaved_tex_format(struct attr *at, int *coff, int *noff, int *voff, int *def)
{
    const struct attr *p = &at[A_POS], *c = &at[A_COL], *n = &at[A_NRM], *t = &at[A_TEX];
    const int f = 4;
    if (t->type != FCE_F)
        return 0;
    *coff = *noff = 0;
    if (t->size == 2 && p->size == 3) {
        if (!c->on && !n->on) {
            *voff = 2 * f, *def = 5 * f;
            return GL_T2F_V3F;
        }
        if (c->on && c->type == FCE_UB && c->size == 4 && !n->on) {
            *coff = 2 * f, *voff = 2 * f + 4, *def = 6 * f;
            return GL_T2F_C4UB_V3F;
        }
        if (c->on && c->type == FCE_F && c->size == 3 && !n->on) {
            *coff = 2 * f, *voff = 5 * f, *def = 8 * f;
            return GL_T2F_C3F_V3F;
        }
        if (!c->on && n->on) {
            *noff = 2 * f, *voff = 5 * f, *def = 8 * f;
            return GL_T2F_N3F_V3F;
        }
        if (c->on && c->type == FCE_F && c->size == 4 && n->on) {
            *coff = 2 * f, *noff = 6 * f, *voff = 9 * f, *def = 12 * f;
            return GL_T2F_C4F_N3F_V3F;
        }
    }
    if (t->size == 4 && p->size == 4) {
        if (!c->on && !n->on) {
            *voff = 4 * f, *def = 8 * f;
            return GL_T4F_V4F;
        }
        if (c->on && c->type == FCE_F && c->size == 4 && n->on) {
            *coff = 4 * f, *noff = 8 * f, *voff = 11 * f, *def = 15 * f;
            return GL_T4F_C4F_N3F_V4F;
        }
    }
    return 0;
}

/* glInterleavedArrays format matching the arrays, or 0
 * [S: main/varray.c:_mesa_get_interleaved_layout] */
static GLenum interleaved_format(struct attr *at, int *coff, int *noff, int *voff, int *def)
{
    const struct attr *p = &at[A_POS], *c = &at[A_COL], *n = &at[A_NRM], *t = &at[A_TEX];
    const int f = 4;
    if (at[A_EDGE].on || p->type != FCE_F || (n->on && n->type != FCE_F))
        return 0;
    if (t->on)
        return interleaved_tex_format(at, coff, noff, voff, def);
    if (p->size > 3)
        return 0;
    *coff = *noff = 0;
    if (!c->on && !n->on) {
        *voff = 0, *def = p->size * f;
        return p->size == 2 ? GL_V2F : GL_V3F;
    }
    if (c->on && c->type == FCE_UB && c->size == 4 && !n->on) {
        *voff = 4, *def = 4 + p->size * f;
        return p->size == 2 ? GL_C4UB_V2F : GL_C4UB_V3F;
    }
    if (p->size != 3)
        return 0;
    if (c->on && c->type == FCE_F && c->size == 3 && !n->on) {
        *voff = 3 * f, *def = 6 * f;
        return GL_C3F_V3F;
    }
    if (!c->on && n->on) {
        *voff = 3 * f, *def = 6 * f;
        return GL_N3F_V3F;
    }
    if (c->on && c->type == FCE_F && c->size == 4 && n->on) {
        *noff = 4 * f, *voff = 7 * f, *def = 10 * f;
        return GL_C4F_N3F_V3F;
    }
    return 0;
}

static int align_up(int x, int a)
{
    return (x + a - 1) / a * a;
}

static void trace_bytes(const unsigned char *p, int n)
{
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "static _Alignas(8) const unsigned char b%d[%d] = {", E.nbuf, n);
    for (int i = 0; i < n; i++)
        fprintf(fc_trace_out, "%s%s0x%02x", i ? "," : "", i % 24 ? "" : "\n    ", p[i]);
    fprintf(fc_trace_out, " };\n");
}

/* vbo_base >= 0: the arrays are in a vertex buffer from that byte */
static void trace_pointer(const char *name, int size, int type, int stride, int offset, int vbo_base)
{
    if (!fc_trace_out)
        return;
    char where[48];
    if (vbo_base >= 0)
        snprintf(where, sizeof where, "(const void *)%d", vbo_base + offset);
    else
        snprintf(where, sizeof where, "b%d + %d", E.nbuf, offset);
    if (size)
        fprintf(fc_trace_out, "%s(%d, %#x, %d, %s);\n", name, size, gl_type[type], stride, where);
    else if (type >= 0)
        fprintf(fc_trace_out, "%s(%#x, %d, %s);\n", name, gl_type[type], stride, where);
    else
        fprintf(fc_trace_out, "%s(%d, %s);\n", name, stride, where);
}

static void trace_indices(int itype, const void *idx, int n)
{
    if (!fc_trace_out)
        return;
    static const char *const names[3] = { "GLubyte", "GLushort", "GLuint" };
    fprintf(fc_trace_out, "static const %s x%d[%d] = {", names[itype], E.nbuf, n);
    for (int i = 0; i < n; i++) {
        unsigned v = itype == 0 ? ((const GLubyte *)idx)[i] : itype == 1 ? ((const GLushort *)idx)[i]
                   : ((const GLuint *)idx)[i];
        fprintf(fc_trace_out, "%s%s%u", i ? "," : "", i % 24 ? "" : "\n    ", v);
    }
    fprintf(fc_trace_out, " };\n");
}

static void client_state(GLenum cap, int on)
{
    fc_trace_calli(on ? "glEnableClientState" : "glDisableClientState", 1, cap, 0, 0, 0);
    if (on)
        glEnableClientState(cap);
    else
        glDisableClientState(cap);
}

static void shuffle(int *a, int n)
{
    for (int i = n - 1; i > 0; i--) {
        int j = (int)fc_rng_below(&E.val, (uint32_t)i + 1), t = a[i];
        a[i] = a[j], a[j] = t;
    }
}

/* ---- buffer objects and multi-draws ----
 *
 * Fixed names, never from glGenBuffers (GL 1.5 makes a buffer on the
 * first bind of a name); every block leaves both targets unbound. */
#define FCE_VBO 901u
#define FCE_IBO 902u

static void bind_buffer(GLenum target, GLuint name)
{
    if (fc_trace_out)
        fprintf(fc_trace_out, "glBindBuffer(%#x, %u);\n", target, name);
    glBindBuffer(target, name);
}

/* n bytes of data (named `tname` in the trace) into the buffer `name` at
 * byte `base`: glBufferData of the whole, glBufferData of undefined
 * storage then glBufferSubData in two pieces, or the same through
 * glMapBuffer; the buffer stays bound to target. */
static void upload(GLenum target, GLuint name, const unsigned char *data, int n, int base,
                   const char *tname)
{
    static const GLenum usage[3] = { GL_STREAM_DRAW, GL_STATIC_DRAW, GL_DYNAMIC_DRAW };
    fc_rng *r = &E.bo;
    const GLenum u = usage[fc_rng_below(r, 3)];
    const int size = base + n + 8 * fc_rng_range(r, 0, 2);
    const int how = (int)fc_rng_below(r, 3);
    bind_buffer(target, name);
    if (how == 0) {
        unsigned char *all = calloc(1, (size_t)size);
        if (!all)
            abort();
        memcpy(all + base, data, (size_t)n);
        if (fc_trace_out)
            fprintf(fc_trace_out, "{ static unsigned char all[%d]; memcpy(all + %d, %s%d, %d); "
                    "glBufferData(%#x, %d, all, %#x); }\n", size, base, tname, E.nbuf, n, target,
                    size, u);
        glBufferData(target, size, all, u);
        free(all);
        return;
    }
    if (fc_trace_out)
        fprintf(fc_trace_out, "glBufferData(%#x, %d, NULL, %#x);\n", target, size, u);
    glBufferData(target, size, NULL, u);
    if (how == 1) {
        const int k = n / 2;
        if (fc_trace_out)
            fprintf(fc_trace_out, "glBufferSubData(%#x, %d, %d, %s%d);\n"
                    "glBufferSubData(%#x, %d, %d, (const char *)%s%d + %d);\n",
                    target, base, k, tname, E.nbuf, target, base + k, n - k, tname, E.nbuf, k);
        glBufferSubData(target, base, k, data);
        glBufferSubData(target, base + k, n - k, data + k);
        return;
    }
    if (fc_trace_out)
        fprintf(fc_trace_out, "{ void *m = glMapBuffer(%#x, GL_WRITE_ONLY); if (m) { "
                "memcpy((char *)m + %d, %s%d, %d); glUnmapBuffer(%#x); } }\n",
                target, base, tname, E.nbuf, n, target);
    void *m = glMapBuffer(target, GL_WRITE_ONLY);
    if (m) {
        memcpy((char *)m + base, data, (size_t)n);
        glUnmapBuffer(target);
    }
}

/* Splits n vertices of `mode` into draws of whole primitives (the
 * independent modes only; one draw for the others), with empty draws
 * among them; start[i], count[i]; returns the number of draws. */
static int split_draws(GLenum mode, int n, int *start, int *count)
{
    fc_rng *r = &E.bo;
    const int unit = mode == GL_POINTS ? 1 : mode == GL_LINES ? 2 : mode == GL_TRIANGLES ? 3
                   : mode == GL_QUADS ? 4 : 0;
    int k = 0;
    for (int s = 0; s < n || k == 0;) {
        if (fc_rng_chance(r, 20)) {         /* an empty draw */
            start[k] = (int)fc_rng_below(r, (uint32_t)n + 1);
            count[k++] = 0;
        }
        int len = unit ? unit * fc_rng_range(r, 1, 3) : n - s;
        if (s + len >= n || n - (s + len) < unit)
            len = n - s;
        start[k] = s;
        count[k++] = len;
        s += len;
    }
    return k;
}

static void trace_ints(const char *name, const int *v, int n)
{
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "static const GLint %s%d[%d] = {", name, E.nbuf, n);
    for (int i = 0; i < n; i++)
        fprintf(fc_trace_out, "%s%d", i ? "," : "", v[i]);
    fprintf(fc_trace_out, " };\n");
}

void fce_block_end(void)
{
    fce_recording = 0;
    fc_rng *r = &E.val;
    const int nev = E.nev;

    /* the vertices, and where each attribute is first and last given */
    int nvert = 0, first_vert = -1, last_vert = -1, others = 0;
    int first[A_COUNT], last[A_COUNT];
    for (int a = 0; a < A_COUNT; a++)
        first[a] = last[a] = -1;
    for (int i = 0; i < nev; i++) {
        const int a = kind_attr(E.ev[i].kind);
        if (a < 0 || a == A_EDGE)
            others = 1;             /* glMaterial, glEdgeFlag: glArrayElement */
        if (a < 0)
            continue;
        if (first[a] < 0)
            first[a] = i;
        last[a] = i;
        if (a == A_POS) {
            nvert++;
            if (first_vert < 0)
                first_vert = i;
            last_vert = i;
        }
    }
    struct attr at[A_COUNT];
    memset(at, 0, sizeof at);
    /* an attribute comes from an array when it is given before the first
     * vertex; otherwise its calls are issued as they are */
    int draw = nvert > 0 && E.P.use_draw && !others;
    for (int a = 0; a < A_COUNT; a++) {
        at[a].on = nvert > 0 && first[a] >= 0 && first[a] < first_vert;
        if (a == A_POS)
            at[a].on = nvert > 0;
        if (first[a] >= 0 && !at[a].on && a != A_POS)
            draw = 0;
    }
    for (int a = 0; a < A_COUNT; a++)
        if (at[a].on)
            choose_type(&at[a], a, draw);

    /* per-vertex packed values of each attribute (tight, element size) */
    int nattr_bytes = 0;
    for (int a = 0; a < A_COUNT; a++)
        nattr_bytes += at[a].on ? at[a].bytes : 0;
    unsigned char *packed = calloc((size_t)(nvert ? nvert : 1), (size_t)(nattr_bytes ? nattr_bytes : 1));
    if (!packed)
        abort();
    {
        int cur[A_COUNT] = { -1, -1, -1, -1, -1 }, k = 0;
        for (int i = 0; i < nev; i++) {
            const int a = kind_attr(E.ev[i].kind);
            if (a < 0)
                continue;
            cur[a] = i;
            if (a != A_POS)
                continue;
            unsigned char *dst = packed + (size_t)k * (size_t)nattr_bytes;
            for (int b = 0; b < A_COUNT; b++) {
                if (!at[b].on)
                    continue;
                const struct ev *e = &E.ev[cur[b]];
                const int tb = type_bytes[at[b].type];
                for (int c = 0; c < at[b].size; c++) {
                    /* components the call does not give: (0, 0, 0, 1),
                     * in its own type only for vertices (sizes are
                     * uniform for normalized raw arrays) */
                    double x = c < e->size ? (at[b].raw ? e->v[c] : (double)imm_float(e, c))
                                           : (c == 3 ? 1.0 : 0.0);
                    put(dst + c * tb, at[b].type, x);
                }
                dst += at[b].bytes;
            }
            k++;
        }
    }

    /* storage: order, shared vertices, leading unused vertices */
    int call = draw ? (int)fc_rng_below(r, 100) : 50;   /* <35 DrawArrays, <85 Elements, else Range */
    int lead = 0, nstore = nvert;
    int *slot = malloc(sizeof(int) * (size_t)(nvert + 1));      /* vertex k -> storage slot */
    int *src = malloc(sizeof(int) * (size_t)(nvert + 4));       /* storage slot -> vertex */
    if (!slot || !src)
        abort();
    if (call < 35) {
        lead = fc_rng_chance(r, 30) ? fc_rng_range(r, 1, 3) : 0;
        for (int i = 0; i < lead; i++)
            src[i] = 0;
        for (int k = 0; k < nvert; k++)
            slot[k] = lead + k, src[lead + k] = k;
        nstore = lead + nvert;
    } else {
        const int share = fc_rng_chance(r, 50), mix = fc_rng_chance(r, 50);
        nstore = 0;
        for (int k = 0; k < nvert; k++) {
            int s = -1;
            if (share)
                for (int j = 0; j < nstore && s < 0; j++)
                    if (!memcmp(packed + (size_t)src[j] * nattr_bytes, packed + (size_t)k * nattr_bytes,
                                (size_t)nattr_bytes))
                        s = j;
            if (s < 0) {
                s = nstore++;
                src[s] = k;
            }
            slot[k] = s;
        }
        if (mix && nstore > 1) {
            int *perm = malloc(sizeof(int) * (size_t)nstore), *inv = malloc(sizeof(int) * (size_t)nstore);
            if (!perm || !inv)
                abort();
            for (int i = 0; i < nstore; i++)
                perm[i] = i;
            shuffle(perm, nstore);              /* old slot i -> new slot perm[i] */
            for (int i = 0; i < nstore; i++)
                inv[perm[i]] = src[i];
            memcpy(src, inv, sizeof(int) * (size_t)nstore);
            for (int k = 0; k < nvert; k++)
                slot[k] = perm[slot[k]];
            free(perm);
            free(inv);
        }
    }

    /* layout */
    int coff = 0, noff = 0, voff = 0, def = 0, total = 0;
    GLenum ifmt = E.P.layout == 3 && nvert ? interleaved_format(at, &coff, &noff, &voff, &def) : 0;
    int istride = 0;
    if (ifmt) {
        istride = def + E.P.pad;
        at[A_COL].offset = coff, at[A_NRM].offset = noff, at[A_POS].offset = voff;
        at[A_TEX].offset = 0;
        for (int a = 0; a < A_COUNT; a++)
            at[a].stride = istride;
        total = istride * nstore;
    } else if (E.P.layout >= 2) {
        static const int perms[24][4] = {
            {0,1,2,3},{0,1,3,2},{0,2,1,3},{0,2,3,1},{0,3,1,2},{0,3,2,1},{1,0,2,3},{1,0,3,2},
            {1,2,0,3},{1,2,3,0},{1,3,0,2},{1,3,2,0},{2,0,1,3},{2,0,3,1},{2,1,0,3},{2,1,3,0},
            {2,3,0,1},{2,3,1,0},{3,0,1,2},{3,0,2,1},{3,1,0,2},{3,1,2,0},{3,2,0,1},{3,2,1,0},
        };
        /* texture coordinates go in at place order % 5 (the order of
         * the other four is as before they existed) */
        int seq[A_COUNT], ns = 0;
        for (int i = 0; i < 4; i++) {
            if (i == E.P.order % 5)
                seq[ns++] = A_TEX;
            seq[ns++] = perms[E.P.order][i];
        }
        if (ns == 4)
            seq[ns++] = A_TEX;
        int off = 0, al = 4;
        for (int i = 0; i < A_COUNT; i++) {
            struct attr *x = &at[seq[i]];
            if (!x->on)
                continue;
            const int a = x->type == FCE_D ? 8 : 4;
            if (a > al)
                al = a;
            off = align_up(off, a);
            x->offset = off;
            off += x->bytes;
        }
        const int stride = align_up(off, al) + E.P.pad;
        for (int a = 0; a < A_COUNT; a++)
            at[a].stride = stride;
        total = stride * nstore;
    } else {
        for (int a = 0; a < A_COUNT; a++) {
            if (!at[a].on)
                continue;
            at[a].stride = E.P.layout == 1 ? align_up(at[a].bytes + E.P.pad, 4) : at[a].bytes;
            at[a].offset = total;
            total = align_up(total + at[a].stride * nstore, 8);
        }
    }
    unsigned char *buf = calloc(1, (size_t)(total ? total : 1));
    if (!buf)
        abort();
    for (int s = 0; s < nstore; s++) {
        const unsigned char *v = packed + (size_t)src[s] * nattr_bytes;
        for (int a = 0; a < A_COUNT; a++) {
            if (!at[a].on)
                continue;
            memcpy(buf + at[a].offset + (size_t)s * at[a].stride, v, (size_t)at[a].bytes);
            v += at[a].bytes;
        }
    }

    /* issue */
    fc_trace_text("{");
    if (nvert)
        trace_bytes(buf, total);
    /* the arrays in a vertex buffer, at byte `base` (E.bo decides) */
    const int vbo = nvert && (int)fc_rng_below(&E.bo, 100) < E.P.vbo;
    int base = 0;
    if (vbo) {
        base = 8 * fc_rng_range(&E.bo, 0, 3);
        upload(GL_ARRAY_BUFFER, FCE_VBO, buf, total, base, "b");
    }
    /* where an array starts: in the buffer (an offset) or in memory */
#define ARRAY_AT(off) (vbo ? (const void *)(uintptr_t)(base + (off)) : (const void *)(buf + (off)))
    static const GLenum caps[A_COUNT] = {
        GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY, GL_EDGE_FLAG_ARRAY,
        GL_TEXTURE_COORD_ARRAY,
    };
    if (ifmt) {
        if (fc_trace_out && vbo)
            fprintf(fc_trace_out, "glInterleavedArrays(%#x, %d, (const void *)%d);\n", ifmt,
                    E.P.explicit_stride || E.P.pad ? istride : 0, base);
        else if (fc_trace_out)
            fprintf(fc_trace_out, "glInterleavedArrays(%#x, %d, b%d);\n", ifmt,
                    E.P.explicit_stride || E.P.pad ? istride : 0, E.nbuf);
        glInterleavedArrays(ifmt, E.P.explicit_stride || E.P.pad ? istride : 0, ARRAY_AT(0));
    } else if (nvert) {
        for (int a = 0; a < A_COUNT; a++) {
            if (!at[a].on)
                continue;
            /* a tight stride is given as 0 or as the element size */
            const int stride = E.P.layout == 0 && !E.P.explicit_stride ? 0 : at[a].stride;
            const void *p = ARRAY_AT(at[a].offset);
            const GLenum t = gl_type[at[a].type];
            switch (a) {
            case A_POS:
                trace_pointer("glVertexPointer", at[a].size, at[a].type, stride, at[a].offset, vbo ? base : -1);
                glVertexPointer(at[a].size, t, stride, p);
                break;
            case A_COL:
                trace_pointer("glColorPointer", at[a].size, at[a].type, stride, at[a].offset, vbo ? base : -1);
                glColorPointer(at[a].size, t, stride, p);
                break;
            case A_NRM:
                trace_pointer("glNormalPointer", 0, at[a].type, stride, at[a].offset, vbo ? base : -1);
                glNormalPointer(t, stride, p);
                break;
            case A_TEX:
                trace_pointer("glTexCoordPointer", at[a].size, at[a].type, stride, at[a].offset, vbo ? base : -1);
                glTexCoordPointer(at[a].size, t, stride, p);
                break;
            default:
                trace_pointer("glEdgeFlagPointer", 0, -1, stride, at[a].offset, vbo ? base : -1);
                glEdgeFlagPointer(stride, p);
                break;
            }
            client_state(caps[a], 1);
        }
    }
#undef ARRAY_AT
    /* the pointers hold the buffer: unbound before the draw or after */
    const int unbind_early = vbo && fc_rng_chance(&E.bo, 50);
    if (unbind_early)
        bind_buffer(GL_ARRAY_BUFFER, 0);
    const int multi = draw && (int)fc_rng_below(&E.bo, 100) < E.P.multi;
    int *mstart = NULL, *mcount = NULL, nmulti = 0;
    if (multi) {
        mstart = malloc(sizeof(int) * (size_t)(2 * nvert + 2));
        mcount = malloc(sizeof(int) * (size_t)(2 * nvert + 2));
        if (!mstart || !mcount)
            abort();
        nmulti = split_draws(E.mode, nvert, mstart, mcount);
    }

    if (draw && call < 35 && multi) {
        for (int i = 0; i < nmulti; i++)
            mstart[i] += lead;
        trace_ints("mf", mstart, nmulti);
        trace_ints("mc", mcount, nmulti);
        if (fc_trace_out)
            fprintf(fc_trace_out, "glMultiDrawArrays(%#x, mf%d, mc%d, %d);\n", E.mode, E.nbuf,
                    E.nbuf, nmulti);
        glMultiDrawArrays(E.mode, mstart, mcount, nmulti);
    } else if (draw && call < 35) {
        fc_trace_calli("glDrawArrays", 3, E.mode, lead, nvert, 0);
        glDrawArrays(E.mode, lead, nvert);
    } else if (draw) {
        const int range = call >= 85;
        int itype = (int)fc_rng_below(r, 3);
        if (itype == 0 && nstore > 256)
            itype = 1 + (int)fc_rng_below(r, 2);
        static const GLenum itypes[3] = { GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT };
        void *idx = malloc((size_t)nvert * 4);
        if (!idx)
            abort();
        int lo = nstore, hi = 0;
        for (int k = 0; k < nvert; k++) {
            if (itype == 0) ((GLubyte *)idx)[k] = (GLubyte)slot[k];
            else if (itype == 1) ((GLushort *)idx)[k] = (GLushort)slot[k];
            else ((GLuint *)idx)[k] = (GLuint)slot[k];
            lo = slot[k] < lo ? slot[k] : lo;
            hi = slot[k] > hi ? slot[k] : hi;
        }
        trace_indices(itype, idx, nvert);
        /* the indices in an element buffer, at byte ibase */
        static const int isize[3] = { 1, 2, 4 };
        const int ibo = (int)fc_rng_below(&E.bo, 100) < E.P.ibo;
        int ibase = 0;
        if (ibo) {
            ibase = isize[itype] * fc_rng_range(&E.bo, 0, 5);
            upload(GL_ELEMENT_ARRAY_BUFFER, FCE_IBO, idx, nvert * isize[itype], ibase, "x");
        }
        const void *iat = ibo ? (const void *)(uintptr_t)ibase : idx;
        char iname[32];
        if (ibo)
            snprintf(iname, sizeof iname, "(const void *)%d", ibase);
        else
            snprintf(iname, sizeof iname, "x%d", E.nbuf);
        if (range) {
            if (fc_trace_out)
                fprintf(fc_trace_out, "glDrawRangeElements(%#x, %d, %d, %d, %#x, %s);\n", E.mode,
                        lo, hi, nvert, itypes[itype], iname);
            glDrawRangeElements(E.mode, (GLuint)lo, (GLuint)hi, nvert, itypes[itype], iat);
        } else if (multi) {
            const void **ip = malloc(sizeof(void *) * (size_t)nmulti);
            if (!ip)
                abort();
            for (int i = 0; i < nmulti; i++)
                ip[i] = (const char *)iat + (size_t)mstart[i] * (size_t)isize[itype];
            trace_ints("mo", mstart, nmulti);
            trace_ints("mc", mcount, nmulti);
            if (fc_trace_out)
                fprintf(fc_trace_out, "{ const void *ip[%d]; for (int i = 0; i < %d; i++) "
                        "ip[i] = (const char *)%s + mo%d[i] * %d; "
                        "glMultiDrawElements(%#x, mc%d, %#x, ip, %d); }\n", nmulti, nmulti, iname,
                        E.nbuf, isize[itype], E.mode, E.nbuf, itypes[itype], nmulti);
            glMultiDrawElements(E.mode, mcount, itypes[itype], ip, nmulti);
            free(ip);
        } else {
            if (fc_trace_out)
                fprintf(fc_trace_out, "glDrawElements(%#x, %d, %#x, %s);\n", E.mode, nvert,
                        itypes[itype], iname);
            glDrawElements(E.mode, nvert, itypes[itype], iat);
        }
        if (ibo)
            bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        free(idx);
    } else {
        fct_glBegin(E.mode);
        int k = 0;
        for (int i = 0; i < nev; i++) {
            const struct ev *e = &E.ev[i];
            const int a = kind_attr(e->kind);
            if (a == A_POS) {
                fc_trace_calli("glArrayElement", 1, slot[k], 0, 0, 0);
                glArrayElement(slot[k]);
                k++;
            } else if (a < 0 || !at[a].on || i > last_vert) {
                replay(e);
            }
        }
        fct_glEnd();
    }
    if (vbo && !unbind_early)
        bind_buffer(GL_ARRAY_BUFFER, 0);
    free(mstart);
    free(mcount);
    if (draw) {
        /* the current values immediate mode leaves */
        if (last[A_COL] >= 0)
            replay(&E.ev[last[A_COL]]);
        if (last[A_NRM] >= 0)
            replay(&E.ev[last[A_NRM]]);
        if (last[A_TEX] >= 0)
            replay(&E.ev[last[A_TEX]]);
    }
    if (nvert) {
        for (int a = 0; a < A_COUNT; a++)
            if (at[a].on)
                client_state(caps[a], 0);
    }
    fc_trace_text("}");
    E.nbuf++;
    free(buf);
    free(packed);
    free(slot);
    free(src);
}

/* ---- display lists ----
 *
 * A FCE_DLIST scene compiles everything it issues into display lists with
 * fixed names: a list is open from the scene's start; a glEnd ends it
 * (with the policy's probability) and opens the next; fc_capture and
 * fc_error, which read results, end it first.  A list compiled with
 * GL_COMPILE_AND_EXECUTE has run when it ends; the GL_COMPILE ones wait
 * (in order) until the next GL_COMPILE_AND_EXECUTE list opens or a result
 * is read, then run through glCallList each, glCallLists (every type,
 * glListBase) or a parent list calling them (one or two levels of
 * nesting).  Nothing is executed twice and the order of the commands never
 * changes, so the scene draws what it draws in immediate mode.  With the
 * policy's `arrays`, the blocks inside the lists go through the arrays
 * path (client state and pointers execute at once, the draws compile). */

static void dl_newlist(GLuint name, GLenum mode)
{
    fc_trace_calli("glNewList", 2, name, mode, 0, 0);
    glNewList(name, mode);
}

static void dl_endlist(void)
{
    fc_trace_text("glEndList();");
    glEndList();
}

static void dl_calllist(GLuint name)
{
    fc_trace_calli("glCallList", 1, name, 0, 0, 0);
    glCallList(name);
}

/* glCallLists of names[0..n) with a random type; top: at top level, where
 * a glListBase may offset the names */
static void dl_calllists(const GLuint *names, int n, int top)
{
    fc_rng *r = &E.val;
    GLuint lo = names[0], hi = names[0];
    for (int i = 1; i < n; i++) {
        lo = names[i] < lo ? names[i] : lo;
        hi = names[i] > hi ? names[i] : hi;
    }
    const GLuint base = top && fc_rng_chance(r, 40) ? fc_rng_below(r, lo + 1) : 0;
    static const GLenum types[10] = {
        GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT,
        GL_FLOAT, GL_2_BYTES, GL_3_BYTES, GL_4_BYTES,
    };
    int t;
    do
        t = (int)fc_rng_below(r, 10);
    while ((t == 0 && hi - base > 127) || (t == 1 && hi - base > 255));
    union { GLbyte b[4 * DL_DEFER_MAX + 4]; GLubyte ub[4 * DL_DEFER_MAX + 4];
            GLshort s[DL_DEFER_MAX]; GLushort us[DL_DEFER_MAX]; GLint i[DL_DEFER_MAX];
            GLuint ui[DL_DEFER_MAX]; GLfloat f[DL_DEFER_MAX]; } a;
    int bytes = 0;
    for (int k = 0; k < n; k++) {
        const GLuint v = names[k] - base;
        switch (t) {
        case 0: a.b[k] = (GLbyte)v; bytes = n; break;
        case 1: a.ub[k] = (GLubyte)v; bytes = n; break;
        case 2: a.s[k] = (GLshort)v; break;
        case 3: a.us[k] = (GLushort)v; break;
        case 4: a.i[k] = (GLint)v; break;
        case 5: a.ui[k] = v; break;
        case 6: a.f[k] = (GLfloat)v; break;
        default: {                  /* GL_n_BYTES: big-endian */
            const int nb = t - 5;
            for (int j = 0; j < nb; j++)
                a.ub[k * nb + j] = (GLubyte)(v >> (8 * (nb - 1 - j)));
            bytes = n * nb;
            break;
        }
        }
    }
    if (base) {
        fc_trace_calli("glListBase", 1, base, 0, 0, 0);
        glListBase(base);
    }
    if (fc_trace_out) {
        fprintf(fc_trace_out, "{ static const %s c[] = { ",
                t == 2 ? "GLshort" : t == 3 ? "GLushort" : t == 4 ? "GLint" : t == 5 ? "GLuint"
                : t == 6 ? "GLfloat" : t == 0 ? "GLbyte" : "GLubyte");
        const int m = bytes ? bytes : n;
        for (int k = 0; k < m; k++) {
            if (k)
                fputs(", ", fc_trace_out);
            switch (t) {
            case 0: fprintf(fc_trace_out, "%d", a.b[k]); break;
            case 2: fprintf(fc_trace_out, "%d", a.s[k]); break;
            case 3: fprintf(fc_trace_out, "%u", a.us[k]); break;
            case 4: fprintf(fc_trace_out, "%d", a.i[k]); break;
            case 5: fprintf(fc_trace_out, "%uu", a.ui[k]); break;
            case 6: fprintf(fc_trace_out, "%a", (double)a.f[k]); break;
            default: fprintf(fc_trace_out, "%u", a.ub[k]); break;
            }
        }
        fprintf(fc_trace_out, " }; glCallLists(%d, %#x, c); }\n", n, types[t]);
    }
    glCallLists(n, types[t], &a);
    if (base) {
        fc_trace_calli("glListBase", 1, 0, 0, 0, 0);
        glListBase(0);
    }
}

/* Runs the deferred GL_COMPILE lists, in order (no list is open). */
static void dl_flush(void)
{
    struct dl *D = &E.D;
    fc_rng *r = &E.val;
    const int n = D->ndeferred;
    if (!n)
        return;
    D->ndeferred = 0;
    const int how = (int)fc_rng_below(r, 100);
    if (how < 30) {
        for (int i = 0; i < n; i++)
            dl_calllist(D->deferred[i]);
    } else if (how < 60) {
        dl_calllists(D->deferred, n, 1);
    } else {
        /* nested: a parent list calls them, maybe through a grandparent */
        const GLuint parent = D->next++;
        dl_newlist(parent, GL_COMPILE);
        if (fc_rng_chance(r, 50)) {
            for (int i = 0; i < n; i++)
                dl_calllist(D->deferred[i]);
        } else {
            dl_calllists(D->deferred, n, 0);
        }
        dl_endlist();
        if (fc_rng_chance(r, 40)) {
            const GLuint top = D->next++;
            dl_newlist(top, GL_COMPILE);
            dl_calllist(parent);
            dl_endlist();
            dl_calllist(top);
        } else {
            dl_calllist(parent);
        }
    }
}

static void dl_close(void)
{
    struct dl *D = &E.D;
    dl_endlist();
    D->open = 0;
    if (D->mode == GL_COMPILE)
        D->deferred[D->ndeferred++] = D->next - 1;
}

void fce_dl_open(void)
{
    struct dl *D = &E.D;
    const GLenum mode = fc_rng_chance(&E.val, D->cae) ? GL_COMPILE_AND_EXECUTE : GL_COMPILE;
    /* the waiting lists run before this one's commands */
    if (mode == GL_COMPILE_AND_EXECUTE || D->ndeferred == DL_DEFER_MAX)
        dl_flush();
    dl_newlist(D->next++, mode);
    D->open = 1;
    D->mode = mode;
}

void fce_dl_block_end(void)
{
    struct dl *D = &E.D;
    if (D->open && fc_rng_chance(&E.val, D->cut)) {
        dl_close();
        fce_dl_open();
    }
}

void fce_dl_sync(void)
{
    struct dl *D = &E.D;
    if (fce_path_now != FCE_DLIST)
        return;
    if (D->open)
        dl_close();
    dl_flush();
}

void fce_dl_resume(void)
{
    if (fce_path_now == FCE_DLIST && !E.D.open)
        fce_dl_open();
}
