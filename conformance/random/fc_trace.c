/* fc_trace.c - printing side of fc_trace.h, and the lighting entry-point
 * table of fc_lit_gl.h (this file does not include fc_trace.h, whose macros
 * would rename the functions the table takes). */
#include "fc_lit_gl.h"

#include <stdio.h>
#include <stdlib.h>

FILE *fc_trace_out;
struct fc_lit_gl fc_lit_gl;

void fc_lit_gl_load(void)
{
#ifdef FC_ORACLE
#define FC_LIT_GL_LOAD(gl, m, params) fc_lit_gl.m = gl;
#else
#define FC_LIT_GL_LOAD(gl, m, params)                                        \
    if (!(fc_lit_gl.m = (void (GLAPIENTRY *) params)OSMesaGetProcAddress(#gl))) { \
        fprintf(stderr, "renderer: OSMesaGetProcAddress(\"%s\") is NULL\n", #gl); \
        abort();                                                             \
    }
#endif
    FC_LIT_GL_FUNCS(FC_LIT_GL_LOAD)
#undef FC_LIT_GL_LOAD
}

void fc_trace_call(const char *name, int n, double a, double b, double c, double d);
void fc_trace_call6(const char *name, double a, double b, double c, double d, double e, double f);
void fc_trace_calli(const char *name, int n, long long a, long long b, long long c, long long d);
void fc_trace_text(const char *text);
void fc_trace_enums_f(const char *name, int nenum, long long e0, long long e1, double v);
void fc_trace_enums_i(const char *name, int nenum, long long e0, long long e1, long long v);
void fc_trace_enums_vf(const char *name, int nenum, long long e0, long long e1, int n, const GLfloat *p);
void fc_trace_enums_vi(const char *name, int nenum, long long e0, long long e1, int n, const GLint *p);

static void values(int n, const double *v)
{
    for (int i = 0; i < n; i++)
        fprintf(fc_trace_out, "%s%a", i ? ", " : "", v[i]);
}

void fc_trace_call(const char *name, int n, double a, double b, double c, double d)
{
    double v[4] = { a, b, c, d };
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "%s(", name);
    values(n, v);
    fprintf(fc_trace_out, ");\n");
}

void fc_trace_call6(const char *name, double a, double b, double c, double d, double e, double f)
{
    double v[6] = { a, b, c, d, e, f };
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "%s(", name);
    values(6, v);
    fprintf(fc_trace_out, ");\n");
}

void fc_trace_calli(const char *name, int n, long long a, long long b, long long c, long long d)
{
    long long v[4] = { a, b, c, d };
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "%s(", name);
    for (int i = 0; i < n; i++)
        fprintf(fc_trace_out, "%s%#llx", i ? ", " : "", v[i]);
    fprintf(fc_trace_out, ");\n");
}

void fc_trace_text(const char *text)
{
    if (fc_trace_out)
        fprintf(fc_trace_out, "%s\n", text);
}

static void enums(int nenum, long long e0, long long e1)
{
    fprintf(fc_trace_out, "%#llx", e0);
    if (nenum > 1)
        fprintf(fc_trace_out, ", %#llx", e1);
}

/* name(e0[, e1], v): glLightf, glMaterialf, glLightModelf. */
void fc_trace_enums_f(const char *name, int nenum, long long e0, long long e1, double v)
{
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "%s(", name);
    enums(nenum, e0, e1);
    fprintf(fc_trace_out, ", %a);\n", v);
}

/* name(e0[, e1], v): glLighti, glMateriali, glLightModeli. */
void fc_trace_enums_i(const char *name, int nenum, long long e0, long long e1, long long v)
{
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "%s(", name);
    enums(nenum, e0, e1);
    fprintf(fc_trace_out, ", %lld);\n", v);
}

/* name(e0[, e1], t) with an array of n values: glLightfv, glMaterialiv... */
void fc_trace_enums_vf(const char *name, int nenum, long long e0, long long e1, int n, const GLfloat *p)
{
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "{ static const GLfloat t[] = { ");
    for (int i = 0; i < n; i++)
        fprintf(fc_trace_out, "%s%a", i ? ", " : "", (double)p[i]);
    fprintf(fc_trace_out, " }; %s(", name);
    enums(nenum, e0, e1);
    fprintf(fc_trace_out, ", t); }\n");
}

void fc_trace_enums_vi(const char *name, int nenum, long long e0, long long e1, int n, const GLint *p)
{
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "{ static const GLint t[] = { ");
    for (int i = 0; i < n; i++)
        fprintf(fc_trace_out, "%s%lld", i ? ", " : "", (long long)p[i]);
    fprintf(fc_trace_out, " }; %s(", name);
    enums(nenum, e0, e1);
    fprintf(fc_trace_out, ", t); }\n");
}

#define VEC(suf, T, fmt, cast)                                               \
    void fc_trace_v##suf(const char *name, const char *type, int n, const T *p); \
    void fc_trace_v##suf(const char *name, const char *type, int n, const T *p) \
    {                                                                        \
        if (!fc_trace_out)                                                   \
            return;                                                          \
        fprintf(fc_trace_out, "{ static const %s t[] = { ", type);           \
        for (int i = 0; i < n; i++)                                          \
            fprintf(fc_trace_out, "%s" fmt, i ? ", " : "", (cast)p[i]);      \
        fprintf(fc_trace_out, " }; %s(t); }\n", name);                       \
    }
VEC(b, GLbyte, "%lld", long long)
VEC(s, GLshort, "%lld", long long)
VEC(i, GLint, "%lld", long long)
VEC(ub, GLubyte, "%llu", unsigned long long)
VEC(us, GLushort, "%llu", unsigned long long)
VEC(ui, GLuint, "%lluu", unsigned long long)
VEC(f, GLfloat, "%a", double)
VEC(d, GLdouble, "%a", double)
