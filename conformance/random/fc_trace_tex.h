/* fc_trace_tex.h - call-trace wrappers (see fc_trace.h) of the entry
 * points only the texture family (fc_random_tex.c) calls: texture
 * coordinates, texture objects, images, parameters, environment,
 * coordinate generation and the pixel path. */
#ifndef FC_TRACE_TEX_H
#define FC_TRACE_TEX_H

#include "fc_trace.h"

#include <stdio.h>

#define FCT_TC1(suf, T, tr) \
    static inline void fct_glTexCoord1##suf(T a) { tr("glTexCoord1" #suf, 1, a, 0, 0, 0); glTexCoord1##suf(a); }
#define FCT_TC2(suf, T, tr) \
    static inline void fct_glTexCoord2##suf(T a, T b) { tr("glTexCoord2" #suf, 2, a, b, 0, 0); glTexCoord2##suf(a, b); }
#define FCT_TC3(suf, T, tr) \
    static inline void fct_glTexCoord3##suf(T a, T b, T c) { tr("glTexCoord3" #suf, 3, a, b, c, 0); glTexCoord3##suf(a, b, c); }
#define FCT_TC4(suf, T, tr) \
    static inline void fct_glTexCoord4##suf(T a, T b, T c, T d) { tr("glTexCoord4" #suf, 4, a, b, c, d); glTexCoord4##suf(a, b, c, d); }
#define FCT_TCV(n, suf, T, vtr, tname) \
    static inline void fct_glTexCoord##n##suf##v(const T *p) { vtr("glTexCoord" #n #suf "v", tname, n, p); glTexCoord##n##suf##v(p); }
#define FCT_TC_ALL(n)                                                        \
    FCT_TC##n(s, GLshort, fc_trace_calli) FCT_TCV(n, s, GLshort, fc_trace_vs, "GLshort") \
    FCT_TC##n(i, GLint, fc_trace_calli) FCT_TCV(n, i, GLint, fc_trace_vi, "GLint")       \
    FCT_TC##n(f, GLfloat, fc_trace_call) FCT_TCV(n, f, GLfloat, fc_trace_vf, "GLfloat")  \
    FCT_TC##n(d, GLdouble, fc_trace_call) FCT_TCV(n, d, GLdouble, fc_trace_vd, "GLdouble")
FCT_TC_ALL(1)
FCT_TC_ALL(2)
FCT_TC_ALL(3)
FCT_TC_ALL(4)
#undef FCT_TC1
#undef FCT_TC2
#undef FCT_TC3
#undef FCT_TC4
#undef FCT_TCV
#undef FCT_TC_ALL

static inline void fct_glBindTexture(GLenum t, GLuint n) { fc_trace_calli("glBindTexture", 2, t, n, 0, 0); glBindTexture(t, n); }
static inline void fct_glTexParameteri(GLenum t, GLenum p, GLint v) { fc_trace_enums_i("glTexParameteri", 2, t, p, v); glTexParameteri(t, p, v); }
static inline void fct_glTexParameterf(GLenum t, GLenum p, GLfloat v) { fc_trace_enums_f("glTexParameterf", 2, t, p, v); glTexParameterf(t, p, v); }
static inline void fct_glTexParameterfv(GLenum t, GLenum p, const GLfloat *v) { fc_trace_enums_vf("glTexParameterfv", 2, t, p, 4, v); glTexParameterfv(t, p, v); }
static inline void fct_glTexEnvi(GLenum t, GLenum p, GLint v) { fc_trace_enums_i("glTexEnvi", 2, t, p, v); glTexEnvi(t, p, v); }
static inline void fct_glTexEnvf(GLenum t, GLenum p, GLfloat v) { fc_trace_enums_f("glTexEnvf", 2, t, p, v); glTexEnvf(t, p, v); }
static inline void fct_glTexEnvfv(GLenum t, GLenum p, const GLfloat *v) { fc_trace_enums_vf("glTexEnvfv", 2, t, p, 4, v); glTexEnvfv(t, p, v); }
static inline void fct_glTexGeni(GLenum c, GLenum p, GLint v) { fc_trace_enums_i("glTexGeni", 2, c, p, v); glTexGeni(c, p, v); }
static inline void fct_glTexGenfv(GLenum c, GLenum p, const GLfloat *v) { fc_trace_enums_vf("glTexGenfv", 2, c, p, 4, v); glTexGenfv(c, p, v); }
static inline void fct_glPixelStorei(GLenum p, GLint v) { fc_trace_enums_i("glPixelStorei", 1, p, 0, v); glPixelStorei(p, v); }

static inline void fct_glActiveTexture(GLenum u) { fc_trace_calli("glActiveTexture", 1, u, 0, 0, 0); glActiveTexture(u); }
static inline void fct_glMultiTexCoord2f(GLenum u, GLfloat s, GLfloat t) { fc_trace_enums_vf("glMultiTexCoord2fv", 1, u, 0, 2, (const GLfloat[]){ s, t }); glMultiTexCoord2f(u, s, t); }
static inline void fct_glPixelZoom(GLfloat x, GLfloat y) { fc_trace_call("glPixelZoom", 2, x, y, 0, 0); glPixelZoom(x, y); }

/* an image: its bytes as a static array in the trace */
static inline void fct_trace_image(const void *pixels, size_t n)
{
    if (!fc_trace_out)
        return;
    fprintf(fc_trace_out, "{ static const unsigned char img[%zu] = {", n ? n : 1);
    for (size_t i = 0; i < n; i++)
        fprintf(fc_trace_out, "%s%s0x%02x", i ? "," : "", i % 24 ? "" : "\n    ",
                ((const unsigned char *)pixels)[i]);
    fprintf(fc_trace_out, "%s };\n", n ? "" : "0");
}
static inline void fct_glTexImage2D(GLenum target, GLint level, GLint internal, GLsizei w,
                                    GLsizei h, GLint border, GLenum format, GLenum type,
                                    const void *pixels, size_t bytes)
{
    fct_trace_image(pixels, bytes);
    if (fc_trace_out)
        fprintf(fc_trace_out, "glTexImage2D(%#x, %d, %#x, %d, %d, %d, %#x, %#x, img); }\n",
                (unsigned)target, level, (unsigned)internal, w, h, border, (unsigned)format,
                (unsigned)type);
    glTexImage2D(target, level, internal, w, h, border, format, type, pixels);
}
static inline void fct_glTexImage3D(GLenum target, GLint level, GLint internal, GLsizei w,
                                    GLsizei h, GLsizei d, GLint border, GLenum format,
                                    GLenum type, const void *pixels, size_t bytes)
{
    fct_trace_image(pixels, bytes);
    if (fc_trace_out)
        fprintf(fc_trace_out, "glTexImage3D(%#x, %d, %#x, %d, %d, %d, %d, %#x, %#x, img); }\n",
                (unsigned)target, level, (unsigned)internal, w, h, d, border, (unsigned)format,
                (unsigned)type);
    glTexImage3D(target, level, internal, w, h, d, border, format, type, pixels);
}
static inline void fct_glCompressedTexImage2D(GLenum target, GLint level, GLenum internal,
                                              GLsizei w, GLsizei h, GLint border,
                                              GLsizei size, const void *data)
{
    fct_trace_image(data, (size_t)size);
    if (fc_trace_out)
        fprintf(fc_trace_out, "glCompressedTexImage2D(%#x, %d, %#x, %d, %d, %d, %d, img); }\n",
                (unsigned)target, level, (unsigned)internal, w, h, border, size);
    glCompressedTexImage2D(target, level, internal, w, h, border, size, data);
}
static inline void fct_glTexImage1D(GLenum target, GLint level, GLint internal, GLsizei w,
                                    GLint border, GLenum format, GLenum type,
                                    const void *pixels, size_t bytes)
{
    fct_trace_image(pixels, bytes);
    if (fc_trace_out)
        fprintf(fc_trace_out, "glTexImage1D(%#x, %d, %#x, %d, %d, %#x, %#x, img); }\n",
                (unsigned)target, level, (unsigned)internal, w, border, (unsigned)format,
                (unsigned)type);
    glTexImage1D(target, level, internal, w, border, format, type, pixels);
}

#endif
