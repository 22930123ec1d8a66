/* fc_lit_gl.h - the lighting entry points of the lit random scenes.
 *
 * The generator calls them through pointers, so that the lit scenes also
 * exercise OSMesaGetProcAddress as legacy loaders use it: the oracle's are
 * Mesa's own functions (taken by name, so their types are checked at
 * compile time), fixgl's come from fixgl's OSMesaGetProcAddress (which
 * answers from libfixgl/main/api_list.h and gives NULL for a name it does
 * not implement, where Mesa's glapi hands out a no-op stub; the loader
 * aborts on NULL).  fc_lit_gl_load() fills the
 * table; the generator calls it at the start of every lit scene. */
#ifndef FC_LIT_GL_H
#define FC_LIT_GL_H

#include "fc_case.h"

/* X(gl name, member, parameter types) */
#define FC_LIT_GL_FUNCS(X)                                                   \
    X(glLightf, Lightf, (GLenum, GLenum, GLfloat))                           \
    X(glLightfv, Lightfv, (GLenum, GLenum, const GLfloat *))                 \
    X(glLighti, Lighti, (GLenum, GLenum, GLint))                             \
    X(glLightiv, Lightiv, (GLenum, GLenum, const GLint *))                   \
    X(glLightModelf, LightModelf, (GLenum, GLfloat))                         \
    X(glLightModelfv, LightModelfv, (GLenum, const GLfloat *))               \
    X(glLightModeli, LightModeli, (GLenum, GLint))                           \
    X(glLightModeliv, LightModeliv, (GLenum, const GLint *))                 \
    X(glMaterialf, Materialf, (GLenum, GLenum, GLfloat))                     \
    X(glMaterialfv, Materialfv, (GLenum, GLenum, const GLfloat *))           \
    X(glMateriali, Materiali, (GLenum, GLenum, GLint))                       \
    X(glMaterialiv, Materialiv, (GLenum, GLenum, const GLint *))             \
    X(glColorMaterial, ColorMaterial, (GLenum, GLenum))                      \
    X(glFrontFace, FrontFace, (GLenum))                                      \
    X(glNormal3b, Normal3b, (GLbyte, GLbyte, GLbyte))                        \
    X(glNormal3bv, Normal3bv, (const GLbyte *))                              \
    X(glNormal3s, Normal3s, (GLshort, GLshort, GLshort))                     \
    X(glNormal3sv, Normal3sv, (const GLshort *))                             \
    X(glNormal3i, Normal3i, (GLint, GLint, GLint))                           \
    X(glNormal3iv, Normal3iv, (const GLint *))                               \
    X(glNormal3f, Normal3f, (GLfloat, GLfloat, GLfloat))                     \
    X(glNormal3fv, Normal3fv, (const GLfloat *))                             \
    X(glNormal3d, Normal3d, (GLdouble, GLdouble, GLdouble))                  \
    X(glNormal3dv, Normal3dv, (const GLdouble *))

struct fc_lit_gl {
#define FC_LIT_GL_MEMBER(gl, m, params) void (GLAPIENTRY *m) params;
    FC_LIT_GL_FUNCS(FC_LIT_GL_MEMBER)
#undef FC_LIT_GL_MEMBER
};

extern struct fc_lit_gl fc_lit_gl;

void fc_lit_gl_load(void);

#endif
