/* fc_trace.c - printing side of fc_trace.h. */
#include <GL/gl.h>
#include <stdio.h>

FILE *fc_trace_out;

void fc_trace_call(const char *name, int n, double a, double b, double c, double d);
void fc_trace_call6(const char *name, double a, double b, double c, double d, double e, double f);
void fc_trace_calli(const char *name, int n, long long a, long long b, long long c, long long d);
void fc_trace_text(const char *text);

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
