/* fc_trace.h - optional call trace of the random scene generator.
 *
 * Included by fc_random.c after the GL headers.  Every GL call the generator
 * makes goes through an inline wrapper that first prints it as a C statement
 * (exact values, hex floats) to fc_trace_out when that is non-NULL, then
 * makes the call; arguments are evaluated once, so tracing never changes a
 * scene.  The renderer sets fc_trace_out from FC_TRACE=FILE:
 *   FC_TRACE=/dev/stdout fixgl-render-osmesa --out /dev/null random/s1-i5
 * prints the scene as a program body that replays it alone (to minimise a
 * mismatch or turn it into a fixed case).
 * Generated list: keep it in step with the calls fc_random.c and
 * fc_random_lit.c make (the lighting wrappers were added by hand; they call
 * through the fc_lit_gl table, see fc_lit_gl.h, and a traced scene replays
 * with plain GL calls). */
#ifndef FC_TRACE_H
#define FC_TRACE_H

#include "fc_case.h"
#include "fc_lit_gl.h"

#include <stdio.h>

extern FILE *fc_trace_out;

void fc_trace_call(const char *name, int n, double a, double b, double c, double d);
void fc_trace_call6(const char *name, double a, double b, double c, double d, double e, double f);
void fc_trace_calli(const char *name, int n, long long a, long long b, long long c, long long d);
void fc_trace_text(const char *text);
void fc_trace_vb(const char *name, const char *type, int n, const GLbyte *p);
void fc_trace_vs(const char *name, const char *type, int n, const GLshort *p);
void fc_trace_vi(const char *name, const char *type, int n, const GLint *p);
void fc_trace_vf(const char *name, const char *type, int n, const GLfloat *p);
void fc_trace_vd(const char *name, const char *type, int n, const GLdouble *p);
void fc_trace_vub(const char *name, const char *type, int n, const GLubyte *p);
void fc_trace_vus(const char *name, const char *type, int n, const GLushort *p);
void fc_trace_vui(const char *name, const char *type, int n, const GLuint *p);
void fc_trace_enums_f(const char *name, int nenum, long long e0, long long e1, double v);
void fc_trace_enums_i(const char *name, int nenum, long long e0, long long e1, long long v);
void fc_trace_enums_vf(const char *name, int nenum, long long e0, long long e1, int n, const GLfloat *p);
void fc_trace_enums_vi(const char *name, int nenum, long long e0, long long e1, int n, const GLint *p);

/* Values a glLight*v / glLightModel*v / glMaterial*v pname takes. */
static inline int fc_trace_count(GLenum pname)
{
    switch (pname) {
    case GL_SPOT_DIRECTION: case GL_COLOR_INDEXES: return 3;
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION:
    case GL_EMISSION: case GL_AMBIENT_AND_DIFFUSE: case GL_LIGHT_MODEL_AMBIENT: return 4;
    default: return 1;
    }
}

static inline void fct_glVertex2s(GLshort a, GLshort b) { fc_trace_call("glVertex2s", 2, (double)a, (double)b, 0.0, 0.0); glVertex2s(a, b); }
static inline void fct_glVertex2sv(const GLshort *p) { fc_trace_vs("glVertex2sv", "GLshort", 2, p); glVertex2sv(p); }
static inline void fct_glVertex2i(GLint a, GLint b) { fc_trace_call("glVertex2i", 2, (double)a, (double)b, 0.0, 0.0); glVertex2i(a, b); }
static inline void fct_glVertex2iv(const GLint *p) { fc_trace_vi("glVertex2iv", "GLint", 2, p); glVertex2iv(p); }
static inline void fct_glVertex2f(GLfloat a, GLfloat b) { fc_trace_call("glVertex2f", 2, (double)a, (double)b, 0.0, 0.0); glVertex2f(a, b); }
static inline void fct_glVertex2fv(const GLfloat *p) { fc_trace_vf("glVertex2fv", "GLfloat", 2, p); glVertex2fv(p); }
static inline void fct_glVertex2d(GLdouble a, GLdouble b) { fc_trace_call("glVertex2d", 2, (double)a, (double)b, 0.0, 0.0); glVertex2d(a, b); }
static inline void fct_glVertex2dv(const GLdouble *p) { fc_trace_vd("glVertex2dv", "GLdouble", 2, p); glVertex2dv(p); }
static inline void fct_glVertex3s(GLshort a, GLshort b, GLshort c) { fc_trace_call("glVertex3s", 3, (double)a, (double)b, (double)c, 0.0); glVertex3s(a, b, c); }
static inline void fct_glVertex3sv(const GLshort *p) { fc_trace_vs("glVertex3sv", "GLshort", 3, p); glVertex3sv(p); }
static inline void fct_glVertex3i(GLint a, GLint b, GLint c) { fc_trace_call("glVertex3i", 3, (double)a, (double)b, (double)c, 0.0); glVertex3i(a, b, c); }
static inline void fct_glVertex3iv(const GLint *p) { fc_trace_vi("glVertex3iv", "GLint", 3, p); glVertex3iv(p); }
static inline void fct_glVertex3f(GLfloat a, GLfloat b, GLfloat c) { fc_trace_call("glVertex3f", 3, (double)a, (double)b, (double)c, 0.0); glVertex3f(a, b, c); }
static inline void fct_glVertex3fv(const GLfloat *p) { fc_trace_vf("glVertex3fv", "GLfloat", 3, p); glVertex3fv(p); }
static inline void fct_glVertex3d(GLdouble a, GLdouble b, GLdouble c) { fc_trace_call("glVertex3d", 3, (double)a, (double)b, (double)c, 0.0); glVertex3d(a, b, c); }
static inline void fct_glVertex3dv(const GLdouble *p) { fc_trace_vd("glVertex3dv", "GLdouble", 3, p); glVertex3dv(p); }
static inline void fct_glVertex4s(GLshort a, GLshort b, GLshort c, GLshort d) { fc_trace_call("glVertex4s", 4, (double)a, (double)b, (double)c, (double)d); glVertex4s(a, b, c, d); }
static inline void fct_glVertex4sv(const GLshort *p) { fc_trace_vs("glVertex4sv", "GLshort", 4, p); glVertex4sv(p); }
static inline void fct_glVertex4i(GLint a, GLint b, GLint c, GLint d) { fc_trace_call("glVertex4i", 4, (double)a, (double)b, (double)c, (double)d); glVertex4i(a, b, c, d); }
static inline void fct_glVertex4iv(const GLint *p) { fc_trace_vi("glVertex4iv", "GLint", 4, p); glVertex4iv(p); }
static inline void fct_glVertex4f(GLfloat a, GLfloat b, GLfloat c, GLfloat d) { fc_trace_call("glVertex4f", 4, (double)a, (double)b, (double)c, (double)d); glVertex4f(a, b, c, d); }
static inline void fct_glVertex4fv(const GLfloat *p) { fc_trace_vf("glVertex4fv", "GLfloat", 4, p); glVertex4fv(p); }
static inline void fct_glVertex4d(GLdouble a, GLdouble b, GLdouble c, GLdouble d) { fc_trace_call("glVertex4d", 4, (double)a, (double)b, (double)c, (double)d); glVertex4d(a, b, c, d); }
static inline void fct_glVertex4dv(const GLdouble *p) { fc_trace_vd("glVertex4dv", "GLdouble", 4, p); glVertex4dv(p); }
static inline void fct_glColor3b(GLbyte a, GLbyte b, GLbyte c) { fc_trace_call("glColor3b", 3, (double)a, (double)b, (double)c, 0.0); glColor3b(a, b, c); }
static inline void fct_glColor3bv(const GLbyte *p) { fc_trace_vb("glColor3bv", "GLbyte", 3, p); glColor3bv(p); }
static inline void fct_glColor3s(GLshort a, GLshort b, GLshort c) { fc_trace_call("glColor3s", 3, (double)a, (double)b, (double)c, 0.0); glColor3s(a, b, c); }
static inline void fct_glColor3sv(const GLshort *p) { fc_trace_vs("glColor3sv", "GLshort", 3, p); glColor3sv(p); }
static inline void fct_glColor3i(GLint a, GLint b, GLint c) { fc_trace_call("glColor3i", 3, (double)a, (double)b, (double)c, 0.0); glColor3i(a, b, c); }
static inline void fct_glColor3iv(const GLint *p) { fc_trace_vi("glColor3iv", "GLint", 3, p); glColor3iv(p); }
static inline void fct_glColor3f(GLfloat a, GLfloat b, GLfloat c) { fc_trace_call("glColor3f", 3, (double)a, (double)b, (double)c, 0.0); glColor3f(a, b, c); }
static inline void fct_glColor3fv(const GLfloat *p) { fc_trace_vf("glColor3fv", "GLfloat", 3, p); glColor3fv(p); }
static inline void fct_glColor3d(GLdouble a, GLdouble b, GLdouble c) { fc_trace_call("glColor3d", 3, (double)a, (double)b, (double)c, 0.0); glColor3d(a, b, c); }
static inline void fct_glColor3dv(const GLdouble *p) { fc_trace_vd("glColor3dv", "GLdouble", 3, p); glColor3dv(p); }
static inline void fct_glColor3ub(GLubyte a, GLubyte b, GLubyte c) { fc_trace_call("glColor3ub", 3, (double)a, (double)b, (double)c, 0.0); glColor3ub(a, b, c); }
static inline void fct_glColor3ubv(const GLubyte *p) { fc_trace_vub("glColor3ubv", "GLubyte", 3, p); glColor3ubv(p); }
static inline void fct_glColor3us(GLushort a, GLushort b, GLushort c) { fc_trace_call("glColor3us", 3, (double)a, (double)b, (double)c, 0.0); glColor3us(a, b, c); }
static inline void fct_glColor3usv(const GLushort *p) { fc_trace_vus("glColor3usv", "GLushort", 3, p); glColor3usv(p); }
static inline void fct_glColor3ui(GLuint a, GLuint b, GLuint c) { fc_trace_call("glColor3ui", 3, (double)a, (double)b, (double)c, 0.0); glColor3ui(a, b, c); }
static inline void fct_glColor3uiv(const GLuint *p) { fc_trace_vui("glColor3uiv", "GLuint", 3, p); glColor3uiv(p); }
static inline void fct_glColor4b(GLbyte a, GLbyte b, GLbyte c, GLbyte d) { fc_trace_call("glColor4b", 4, (double)a, (double)b, (double)c, (double)d); glColor4b(a, b, c, d); }
static inline void fct_glColor4bv(const GLbyte *p) { fc_trace_vb("glColor4bv", "GLbyte", 4, p); glColor4bv(p); }
static inline void fct_glColor4s(GLshort a, GLshort b, GLshort c, GLshort d) { fc_trace_call("glColor4s", 4, (double)a, (double)b, (double)c, (double)d); glColor4s(a, b, c, d); }
static inline void fct_glColor4sv(const GLshort *p) { fc_trace_vs("glColor4sv", "GLshort", 4, p); glColor4sv(p); }
static inline void fct_glColor4i(GLint a, GLint b, GLint c, GLint d) { fc_trace_call("glColor4i", 4, (double)a, (double)b, (double)c, (double)d); glColor4i(a, b, c, d); }
static inline void fct_glColor4iv(const GLint *p) { fc_trace_vi("glColor4iv", "GLint", 4, p); glColor4iv(p); }
static inline void fct_glColor4f(GLfloat a, GLfloat b, GLfloat c, GLfloat d) { fc_trace_call("glColor4f", 4, (double)a, (double)b, (double)c, (double)d); glColor4f(a, b, c, d); }
static inline void fct_glColor4fv(const GLfloat *p) { fc_trace_vf("glColor4fv", "GLfloat", 4, p); glColor4fv(p); }
static inline void fct_glColor4d(GLdouble a, GLdouble b, GLdouble c, GLdouble d) { fc_trace_call("glColor4d", 4, (double)a, (double)b, (double)c, (double)d); glColor4d(a, b, c, d); }
static inline void fct_glColor4dv(const GLdouble *p) { fc_trace_vd("glColor4dv", "GLdouble", 4, p); glColor4dv(p); }
static inline void fct_glColor4ub(GLubyte a, GLubyte b, GLubyte c, GLubyte d) { fc_trace_call("glColor4ub", 4, (double)a, (double)b, (double)c, (double)d); glColor4ub(a, b, c, d); }
static inline void fct_glColor4ubv(const GLubyte *p) { fc_trace_vub("glColor4ubv", "GLubyte", 4, p); glColor4ubv(p); }
static inline void fct_glColor4us(GLushort a, GLushort b, GLushort c, GLushort d) { fc_trace_call("glColor4us", 4, (double)a, (double)b, (double)c, (double)d); glColor4us(a, b, c, d); }
static inline void fct_glColor4usv(const GLushort *p) { fc_trace_vus("glColor4usv", "GLushort", 4, p); glColor4usv(p); }
static inline void fct_glColor4ui(GLuint a, GLuint b, GLuint c, GLuint d) { fc_trace_call("glColor4ui", 4, (double)a, (double)b, (double)c, (double)d); glColor4ui(a, b, c, d); }
static inline void fct_glColor4uiv(const GLuint *p) { fc_trace_vui("glColor4uiv", "GLuint", 4, p); glColor4uiv(p); }
static inline void fct_glViewport(GLint a0, GLint a1, GLsizei a2, GLsizei a3) { fc_trace_calli("glViewport", 4, a0, a1, a2, a3); glViewport(a0, a1, a2, a3); }
static inline void fct_glDepthRange(GLclampd a0, GLclampd a1) { fc_trace_call("glDepthRange", 2, (double)a0, (double)a1, 0.0, 0.0); glDepthRange(a0, a1); }
static inline void fct_glOrtho(GLdouble a0, GLdouble a1, GLdouble a2, GLdouble a3, GLdouble a4, GLdouble a5) { fc_trace_call6("glOrtho", a0, a1, a2, a3, a4, a5); glOrtho(a0, a1, a2, a3, a4, a5); }
static inline void fct_glFrustum(GLdouble a0, GLdouble a1, GLdouble a2, GLdouble a3, GLdouble a4, GLdouble a5) { fc_trace_call6("glFrustum", a0, a1, a2, a3, a4, a5); glFrustum(a0, a1, a2, a3, a4, a5); }
static inline void fct_glTranslatef(GLfloat a0, GLfloat a1, GLfloat a2) { fc_trace_call("glTranslatef", 3, (double)a0, (double)a1, (double)a2, 0.0); glTranslatef(a0, a1, a2); }
static inline void fct_glTranslated(GLdouble a0, GLdouble a1, GLdouble a2) { fc_trace_call("glTranslated", 3, (double)a0, (double)a1, (double)a2, 0.0); glTranslated(a0, a1, a2); }
static inline void fct_glScalef(GLfloat a0, GLfloat a1, GLfloat a2) { fc_trace_call("glScalef", 3, (double)a0, (double)a1, (double)a2, 0.0); glScalef(a0, a1, a2); }
static inline void fct_glScaled(GLdouble a0, GLdouble a1, GLdouble a2) { fc_trace_call("glScaled", 3, (double)a0, (double)a1, (double)a2, 0.0); glScaled(a0, a1, a2); }
static inline void fct_glRotatef(GLfloat a0, GLfloat a1, GLfloat a2, GLfloat a3) { fc_trace_call("glRotatef", 4, (double)a0, (double)a1, (double)a2, (double)a3); glRotatef(a0, a1, a2, a3); }
static inline void fct_glRotated(GLdouble a0, GLdouble a1, GLdouble a2, GLdouble a3) { fc_trace_call("glRotated", 4, (double)a0, (double)a1, (double)a2, (double)a3); glRotated(a0, a1, a2, a3); }
static inline void fct_glClearColor(GLclampf a0, GLclampf a1, GLclampf a2, GLclampf a3) { fc_trace_call("glClearColor", 4, (double)a0, (double)a1, (double)a2, (double)a3); glClearColor(a0, a1, a2, a3); }
static inline void fct_glClearDepth(GLclampd a0) { fc_trace_call("glClearDepth", 1, (double)a0, 0.0, 0.0, 0.0); glClearDepth(a0); }
static inline void fct_glMatrixMode(GLenum a0) { fc_trace_calli("glMatrixMode", 1, a0, 0, 0, 0); glMatrixMode(a0); }
static inline void fct_glShadeModel(GLenum a0) { fc_trace_calli("glShadeModel", 1, a0, 0, 0, 0); glShadeModel(a0); }
static inline void fct_glDepthFunc(GLenum a0) { fc_trace_calli("glDepthFunc", 1, a0, 0, 0, 0); glDepthFunc(a0); }
static inline void fct_glEnable(GLenum a0) { fc_trace_calli("glEnable", 1, a0, 0, 0, 0); glEnable(a0); }
static inline void fct_glDisable(GLenum a0) { fc_trace_calli("glDisable", 1, a0, 0, 0, 0); glDisable(a0); }
static inline void fct_glBegin(GLenum a0) { fc_trace_calli("glBegin", 1, a0, 0, 0, 0); glBegin(a0); }
static inline void fct_glClear(GLbitfield a0) { fc_trace_calli("glClear", 1, a0, 0, 0, 0); glClear(a0); }
static inline void fct_glDepthMask(GLboolean a0) { fc_trace_calli("glDepthMask", 1, a0, 0, 0, 0); glDepthMask(a0); }
static inline void fct_glLoadIdentity(void) { fc_trace_text("glLoadIdentity();"); glLoadIdentity(); }
static inline void fct_glEnd(void) { fc_trace_text("glEnd();"); glEnd(); }
static inline void fct_glPushMatrix(void) { fc_trace_text("glPushMatrix();"); glPushMatrix(); }
static inline void fct_glPopMatrix(void) { fc_trace_text("glPopMatrix();"); glPopMatrix(); }
static inline void fct_glPushAttrib(GLbitfield a0) { fc_trace_calli("glPushAttrib", 1, a0, 0, 0, 0); glPushAttrib(a0); }
static inline void fct_glPopAttrib(void) { fc_trace_text("glPopAttrib();"); glPopAttrib(); }
static inline void fct_glLoadMatrixf(const GLfloat *p) { fc_trace_vf("glLoadMatrixf", "GLfloat", 16, p); glLoadMatrixf(p); }
static inline void fct_glLoadMatrixd(const GLdouble *p) { fc_trace_vd("glLoadMatrixd", "GLdouble", 16, p); glLoadMatrixd(p); }
static inline void fct_glMultMatrixf(const GLfloat *p) { fc_trace_vf("glMultMatrixf", "GLfloat", 16, p); glMultMatrixf(p); }
static inline void fct_glMultMatrixd(const GLdouble *p) { fc_trace_vd("glMultMatrixd", "GLdouble", 16, p); glMultMatrixd(p); }
/* Lighting: called through fc_lit_gl (see fc_lit_gl.h). */
static inline void fct_glLightf(GLenum a0, GLenum a1, GLfloat v) { fc_trace_enums_f("glLightf", 2, a0, a1, (double)v); fc_lit_gl.Lightf(a0, a1, v); }
static inline void fct_glLightfv(GLenum a0, GLenum a1, const GLfloat *p) { fc_trace_enums_vf("glLightfv", 2, a0, a1, fc_trace_count(a1), p); fc_lit_gl.Lightfv(a0, a1, p); }
static inline void fct_glLighti(GLenum a0, GLenum a1, GLint v) { fc_trace_enums_i("glLighti", 2, a0, a1, v); fc_lit_gl.Lighti(a0, a1, v); }
static inline void fct_glLightiv(GLenum a0, GLenum a1, const GLint *p) { fc_trace_enums_vi("glLightiv", 2, a0, a1, fc_trace_count(a1), p); fc_lit_gl.Lightiv(a0, a1, p); }
static inline void fct_glLightModelf(GLenum a0, GLfloat v) { fc_trace_enums_f("glLightModelf", 1, a0, 0, (double)v); fc_lit_gl.LightModelf(a0, v); }
static inline void fct_glLightModelfv(GLenum a0, const GLfloat *p) { fc_trace_enums_vf("glLightModelfv", 1, a0, 0, fc_trace_count(a0), p); fc_lit_gl.LightModelfv(a0, p); }
static inline void fct_glLightModeli(GLenum a0, GLint v) { fc_trace_enums_i("glLightModeli", 1, a0, 0, v); fc_lit_gl.LightModeli(a0, v); }
static inline void fct_glLightModeliv(GLenum a0, const GLint *p) { fc_trace_enums_vi("glLightModeliv", 1, a0, 0, fc_trace_count(a0), p); fc_lit_gl.LightModeliv(a0, p); }
static inline void fct_glMaterialf(GLenum a0, GLenum a1, GLfloat v) { fc_trace_enums_f("glMaterialf", 2, a0, a1, (double)v); fc_lit_gl.Materialf(a0, a1, v); }
static inline void fct_glMaterialfv(GLenum a0, GLenum a1, const GLfloat *p) { fc_trace_enums_vf("glMaterialfv", 2, a0, a1, fc_trace_count(a1), p); fc_lit_gl.Materialfv(a0, a1, p); }
static inline void fct_glMateriali(GLenum a0, GLenum a1, GLint v) { fc_trace_enums_i("glMateriali", 2, a0, a1, v); fc_lit_gl.Materiali(a0, a1, v); }
static inline void fct_glMaterialiv(GLenum a0, GLenum a1, const GLint *p) { fc_trace_enums_vi("glMaterialiv", 2, a0, a1, fc_trace_count(a1), p); fc_lit_gl.Materialiv(a0, a1, p); }
static inline void fct_glColorMaterial(GLenum a0, GLenum a1) { fc_trace_calli("glColorMaterial", 2, a0, a1, 0, 0); fc_lit_gl.ColorMaterial(a0, a1); }
static inline void fct_glFrontFace(GLenum a0) { fc_trace_calli("glFrontFace", 1, a0, 0, 0, 0); fc_lit_gl.FrontFace(a0); }
static inline void fct_glNormal3b(GLbyte a, GLbyte b, GLbyte c) { fc_trace_call("glNormal3b", 3, (double)a, (double)b, (double)c, 0.0); fc_lit_gl.Normal3b(a, b, c); }
static inline void fct_glNormal3bv(const GLbyte *p) { fc_trace_vb("glNormal3bv", "GLbyte", 3, p); fc_lit_gl.Normal3bv(p); }
static inline void fct_glNormal3s(GLshort a, GLshort b, GLshort c) { fc_trace_call("glNormal3s", 3, (double)a, (double)b, (double)c, 0.0); fc_lit_gl.Normal3s(a, b, c); }
static inline void fct_glNormal3sv(const GLshort *p) { fc_trace_vs("glNormal3sv", "GLshort", 3, p); fc_lit_gl.Normal3sv(p); }
static inline void fct_glNormal3i(GLint a, GLint b, GLint c) { fc_trace_call("glNormal3i", 3, (double)a, (double)b, (double)c, 0.0); fc_lit_gl.Normal3i(a, b, c); }
static inline void fct_glNormal3iv(const GLint *p) { fc_trace_vi("glNormal3iv", "GLint", 3, p); fc_lit_gl.Normal3iv(p); }
static inline void fct_glNormal3f(GLfloat a, GLfloat b, GLfloat c) { fc_trace_call("glNormal3f", 3, (double)a, (double)b, (double)c, 0.0); fc_lit_gl.Normal3f(a, b, c); }
static inline void fct_glNormal3fv(const GLfloat *p) { fc_trace_vf("glNormal3fv", "GLfloat", 3, p); fc_lit_gl.Normal3fv(p); }
static inline void fct_glNormal3d(GLdouble a, GLdouble b, GLdouble c) { fc_trace_call("glNormal3d", 3, (double)a, (double)b, (double)c, 0.0); fc_lit_gl.Normal3d(a, b, c); }
static inline void fct_glNormal3dv(const GLdouble *p) { fc_trace_vd("glNormal3dv", "GLdouble", 3, p); fc_lit_gl.Normal3dv(p); }
static inline void fct_fc_capture(fc_h *h) { fc_trace_text("/* fc_capture(h); */"); fc_capture(h); }

#define glVertex2s fct_glVertex2s
#define glVertex2sv fct_glVertex2sv
#define glVertex2i fct_glVertex2i
#define glVertex2iv fct_glVertex2iv
#define glVertex2f fct_glVertex2f
#define glVertex2fv fct_glVertex2fv
#define glVertex2d fct_glVertex2d
#define glVertex2dv fct_glVertex2dv
#define glVertex3s fct_glVertex3s
#define glVertex3sv fct_glVertex3sv
#define glVertex3i fct_glVertex3i
#define glVertex3iv fct_glVertex3iv
#define glVertex3f fct_glVertex3f
#define glVertex3fv fct_glVertex3fv
#define glVertex3d fct_glVertex3d
#define glVertex3dv fct_glVertex3dv
#define glVertex4s fct_glVertex4s
#define glVertex4sv fct_glVertex4sv
#define glVertex4i fct_glVertex4i
#define glVertex4iv fct_glVertex4iv
#define glVertex4f fct_glVertex4f
#define glVertex4fv fct_glVertex4fv
#define glVertex4d fct_glVertex4d
#define glVertex4dv fct_glVertex4dv
#define glColor3b fct_glColor3b
#define glColor3bv fct_glColor3bv
#define glColor3s fct_glColor3s
#define glColor3sv fct_glColor3sv
#define glColor3i fct_glColor3i
#define glColor3iv fct_glColor3iv
#define glColor3f fct_glColor3f
#define glColor3fv fct_glColor3fv
#define glColor3d fct_glColor3d
#define glColor3dv fct_glColor3dv
#define glColor3ub fct_glColor3ub
#define glColor3ubv fct_glColor3ubv
#define glColor3us fct_glColor3us
#define glColor3usv fct_glColor3usv
#define glColor3ui fct_glColor3ui
#define glColor3uiv fct_glColor3uiv
#define glColor4b fct_glColor4b
#define glColor4bv fct_glColor4bv
#define glColor4s fct_glColor4s
#define glColor4sv fct_glColor4sv
#define glColor4i fct_glColor4i
#define glColor4iv fct_glColor4iv
#define glColor4f fct_glColor4f
#define glColor4fv fct_glColor4fv
#define glColor4d fct_glColor4d
#define glColor4dv fct_glColor4dv
#define glColor4ub fct_glColor4ub
#define glColor4ubv fct_glColor4ubv
#define glColor4us fct_glColor4us
#define glColor4usv fct_glColor4usv
#define glColor4ui fct_glColor4ui
#define glColor4uiv fct_glColor4uiv
#define glViewport fct_glViewport
#define glDepthRange fct_glDepthRange
#define glOrtho fct_glOrtho
#define glFrustum fct_glFrustum
#define glTranslatef fct_glTranslatef
#define glTranslated fct_glTranslated
#define glScalef fct_glScalef
#define glScaled fct_glScaled
#define glRotatef fct_glRotatef
#define glRotated fct_glRotated
#define glClearColor fct_glClearColor
#define glClearDepth fct_glClearDepth
#define glMatrixMode fct_glMatrixMode
#define glShadeModel fct_glShadeModel
#define glDepthFunc fct_glDepthFunc
#define glEnable fct_glEnable
#define glDisable fct_glDisable
#define glBegin fct_glBegin
#define glClear fct_glClear
#define glDepthMask fct_glDepthMask
#define glLoadIdentity fct_glLoadIdentity
#define glEnd fct_glEnd
#define glPushMatrix fct_glPushMatrix
#define glPopMatrix fct_glPopMatrix
#define glPushAttrib fct_glPushAttrib
#define glPopAttrib fct_glPopAttrib
#define glLoadMatrixf fct_glLoadMatrixf
#define glLoadMatrixd fct_glLoadMatrixd
#define glMultMatrixf fct_glMultMatrixf
#define glMultMatrixd fct_glMultMatrixd
#define glLightf fct_glLightf
#define glLightfv fct_glLightfv
#define glLighti fct_glLighti
#define glLightiv fct_glLightiv
#define glLightModelf fct_glLightModelf
#define glLightModelfv fct_glLightModelfv
#define glLightModeli fct_glLightModeli
#define glLightModeliv fct_glLightModeliv
#define glMaterialf fct_glMaterialf
#define glMaterialfv fct_glMaterialfv
#define glMateriali fct_glMateriali
#define glMaterialiv fct_glMaterialiv
#define glColorMaterial fct_glColorMaterial
#define glFrontFace fct_glFrontFace
#define glNormal3b fct_glNormal3b
#define glNormal3bv fct_glNormal3bv
#define glNormal3s fct_glNormal3s
#define glNormal3sv fct_glNormal3sv
#define glNormal3i fct_glNormal3i
#define glNormal3iv fct_glNormal3iv
#define glNormal3f fct_glNormal3f
#define glNormal3fv fct_glNormal3fv
#define glNormal3d fct_glNormal3d
#define glNormal3dv fct_glNormal3dv
#define fc_capture fct_fc_capture

#endif
