/* fc_trace_raster.h - call-trace wrappers (see fc_trace.h) of the entry
 * points only the raster family (fc_random_raster.c) calls: point and line
 * state, polygon state, clip planes, fog, per-fragment operations, glRect. */
#ifndef FC_TRACE_RASTER_H
#define FC_TRACE_RASTER_H

#include "fc_trace.h"

#include <stdio.h>

static inline void fct_glPointSize(GLfloat a) { fc_trace_call("glPointSize", 1, a, 0, 0, 0); glPointSize(a); }
static inline void fct_glLineWidth(GLfloat a) { fc_trace_call("glLineWidth", 1, a, 0, 0, 0); glLineWidth(a); }
static inline void fct_glLineStipple(GLint f, GLushort p) { fc_trace_calli("glLineStipple", 2, f, p, 0, 0); glLineStipple(f, p); }
static inline void fct_glCullFace(GLenum a) { fc_trace_calli("glCullFace", 1, a, 0, 0, 0); glCullFace(a); }
static inline void fct_glPolygonMode(GLenum f, GLenum m) { fc_trace_calli("glPolygonMode", 2, f, m, 0, 0); glPolygonMode(f, m); }
static inline void fct_glEdgeFlag(GLboolean f) { fc_trace_calli("glEdgeFlag", 1, f, 0, 0, 0); glEdgeFlag(f); }
static inline void fct_glEdgeFlagv(const GLboolean *f)
{
    if (fc_trace_out)
        fprintf(fc_trace_out, "{ static const GLboolean t[] = { %u }; glEdgeFlagv(t); }\n", (unsigned)*f);
    glEdgeFlagv(f);
}
static inline void fct_glPolygonOffset(GLfloat f, GLfloat u) { fc_trace_call("glPolygonOffset", 2, f, u, 0, 0); glPolygonOffset(f, u); }
static inline void fct_glPolygonStipple(const GLubyte *m) { fc_trace_vub("glPolygonStipple", "GLubyte", 128, m); glPolygonStipple(m); }
static inline void fct_glClipPlane(GLenum p, const GLdouble *eq)
{
    if (fc_trace_out)
        fprintf(fc_trace_out, "{ static const GLdouble t[] = { %a, %a, %a, %a }; glClipPlane(%#x, t); }\n",
                eq[0], eq[1], eq[2], eq[3], (unsigned)p);
    glClipPlane(p, eq);
}
static inline void fct_glFogi(GLenum p, GLint v) { fc_trace_enums_i("glFogi", 1, p, 0, v); glFogi(p, v); }
static inline void fct_glFogf(GLenum p, GLfloat v) { fc_trace_enums_f("glFogf", 1, p, 0, v); glFogf(p, v); }
static inline void fct_glFogfv(GLenum p, const GLfloat *v) { fc_trace_enums_vf("glFogfv", 1, p, 0, 4, v); glFogfv(p, v); }
static inline void fct_glScissor(GLint x, GLint y, GLsizei w, GLsizei h) { fc_trace_calli("glScissor", 4, x, y, w, h); glScissor(x, y, w, h); }
static inline void fct_glAlphaFunc(GLenum f, GLclampf r) { fc_trace_enums_f("glAlphaFunc", 1, f, 0, r); glAlphaFunc(f, r); }
static inline void fct_glStencilFunc(GLenum f, GLint r, GLuint m) { fc_trace_calli("glStencilFunc", 3, f, r, m, 0); glStencilFunc(f, r, m); }
static inline void fct_glStencilOp(GLenum a, GLenum b, GLenum c) { fc_trace_calli("glStencilOp", 3, a, b, c, 0); glStencilOp(a, b, c); }
static inline void fct_glStencilMask(GLuint m) { fc_trace_calli("glStencilMask", 1, m, 0, 0, 0); glStencilMask(m); }
static inline void fct_glClearStencil(GLint s) { fc_trace_calli("glClearStencil", 1, s, 0, 0, 0); glClearStencil(s); }
static inline void fct_glBlendFunc(GLenum s, GLenum d) { fc_trace_calli("glBlendFunc", 2, s, d, 0, 0); glBlendFunc(s, d); }
static inline void fct_glBlendEquation(GLenum e) { fc_trace_calli("glBlendEquation", 1, e, 0, 0, 0); glBlendEquation(e); }
static inline void fct_glBlendColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) { fc_trace_call("glBlendColor", 4, r, g, b, a); glBlendColor(r, g, b, a); }
static inline void fct_glLogicOp(GLenum o) { fc_trace_calli("glLogicOp", 1, o, 0, 0, 0); glLogicOp(o); }
static inline void fct_glColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) { fc_trace_calli("glColorMask", 4, r, g, b, a); glColorMask(r, g, b, a); }
static inline void fct_glRectf(GLfloat a, GLfloat b, GLfloat c, GLfloat d) { fc_trace_call("glRectf", 4, a, b, c, d); glRectf(a, b, c, d); }
static inline void fct_glRectd(GLdouble a, GLdouble b, GLdouble c, GLdouble d) { fc_trace_call("glRectd", 4, a, b, c, d); glRectd(a, b, c, d); }
static inline void fct_glRecti(GLint a, GLint b, GLint c, GLint d) { fc_trace_calli("glRecti", 4, a, b, c, d); glRecti(a, b, c, d); }
static inline void fct_glRectfv(const GLfloat *a, const GLfloat *b)
{
    if (fc_trace_out)
        fprintf(fc_trace_out, "{ static const GLfloat a[] = { %a, %a }, b[] = { %a, %a }; glRectfv(a, b); }\n",
                (double)a[0], (double)a[1], (double)b[0], (double)b[1]);
    glRectfv(a, b);
}

#define glPointSize fct_glPointSize
#define glLineWidth fct_glLineWidth
#define glLineStipple fct_glLineStipple
#define glCullFace fct_glCullFace
#define glPolygonMode fct_glPolygonMode
#define glEdgeFlag fct_glEdgeFlag
#define glEdgeFlagv fct_glEdgeFlagv
#define glPolygonOffset fct_glPolygonOffset
#define glPolygonStipple fct_glPolygonStipple
#define glClipPlane fct_glClipPlane
#define glFogi fct_glFogi
#define glFogf fct_glFogf
#define glFogfv fct_glFogfv
#define glScissor fct_glScissor
#define glAlphaFunc fct_glAlphaFunc
#define glStencilFunc fct_glStencilFunc
#define glStencilOp fct_glStencilOp
#define glStencilMask fct_glStencilMask
#define glClearStencil fct_glClearStencil
#define glBlendFunc fct_glBlendFunc
#define glBlendEquation fct_glBlendEquation
#define glBlendColor fct_glBlendColor
#define glLogicOp fct_glLogicOp
#define glColorMask fct_glColorMask
#define glRectf fct_glRectf
#define glRectd fct_glRectd
#define glRecti fct_glRecti
#define glRectfv fct_glRectfv

#endif
