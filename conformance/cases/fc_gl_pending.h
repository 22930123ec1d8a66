/* fc_gl_pending.h - GL 1.x entry points the lighting cases call that
 * libfixgl may not export yet.
 *
 * The oracle (FC_ORACLE) gets them from Mesa as usual.  In the fixgl
 * renderer each one is declared a weak reference, and every call goes
 * through a macro that skips it when the symbol is not defined: the renderer
 * links against any libfixgl, a missing function is a no-op (the case then
 * differs from the oracle and is listed in known-differences.txt), and as
 * soon as libfixgl exports the function the renderer is relinked (meson
 * tracks libfixgl's exported symbols) and calls it directly.  An entry can
 * be deleted once libfixgl exports the function; nothing else changes.
 *
 * Include after <GL/gl.h> (cases.h), only in case files. */
#ifndef FC_GL_PENDING_H
#define FC_GL_PENDING_H

#include "cases.h"

#ifndef FC_ORACLE

#define FC_PENDING(f) extern __typeof__(f) f __attribute__((weak));
FC_PENDING(glNormal3b)
FC_PENDING(glNormal3bv)
FC_PENDING(glNormal3s)
FC_PENDING(glNormal3sv)
FC_PENDING(glNormal3i)
FC_PENDING(glNormal3iv)
FC_PENDING(glNormal3f)
FC_PENDING(glNormal3fv)
FC_PENDING(glNormal3d)
FC_PENDING(glNormal3dv)
FC_PENDING(glLightf)
FC_PENDING(glLighti)
FC_PENDING(glLightfv)
FC_PENDING(glLightiv)
FC_PENDING(glLightModelf)
FC_PENDING(glLightModeli)
FC_PENDING(glLightModelfv)
FC_PENDING(glLightModeliv)
FC_PENDING(glMaterialf)
FC_PENDING(glMateriali)
FC_PENDING(glMaterialfv)
FC_PENDING(glMaterialiv)
FC_PENDING(glGetLightfv)
FC_PENDING(glGetLightiv)
FC_PENDING(glGetMaterialfv)
FC_PENDING(glGetMaterialiv)
FC_PENDING(glColorMaterial)
FC_PENDING(glFrontFace)
FC_PENDING(glCullFace)
#undef FC_PENDING

/* A function-like macro is not expanded again inside its own replacement,
 * so the inner names are the (weak) functions. */
#define glNormal3b(x, y, z) (glNormal3b ? glNormal3b(x, y, z) : (void)0)
#define glNormal3bv(v) (glNormal3bv ? glNormal3bv(v) : (void)0)
#define glNormal3s(x, y, z) (glNormal3s ? glNormal3s(x, y, z) : (void)0)
#define glNormal3sv(v) (glNormal3sv ? glNormal3sv(v) : (void)0)
#define glNormal3i(x, y, z) (glNormal3i ? glNormal3i(x, y, z) : (void)0)
#define glNormal3iv(v) (glNormal3iv ? glNormal3iv(v) : (void)0)
#define glNormal3f(x, y, z) (glNormal3f ? glNormal3f(x, y, z) : (void)0)
#define glNormal3fv(v) (glNormal3fv ? glNormal3fv(v) : (void)0)
#define glNormal3d(x, y, z) (glNormal3d ? glNormal3d(x, y, z) : (void)0)
#define glNormal3dv(v) (glNormal3dv ? glNormal3dv(v) : (void)0)
#define glLightf(l, p, x) (glLightf ? glLightf(l, p, x) : (void)0)
#define glLighti(l, p, x) (glLighti ? glLighti(l, p, x) : (void)0)
#define glLightfv(l, p, v) (glLightfv ? glLightfv(l, p, v) : (void)0)
#define glLightiv(l, p, v) (glLightiv ? glLightiv(l, p, v) : (void)0)
#define glLightModelf(p, x) (glLightModelf ? glLightModelf(p, x) : (void)0)
#define glLightModeli(p, x) (glLightModeli ? glLightModeli(p, x) : (void)0)
#define glLightModelfv(p, v) (glLightModelfv ? glLightModelfv(p, v) : (void)0)
#define glLightModeliv(p, v) (glLightModeliv ? glLightModeliv(p, v) : (void)0)
#define glMaterialf(f, p, x) (glMaterialf ? glMaterialf(f, p, x) : (void)0)
#define glMateriali(f, p, x) (glMateriali ? glMateriali(f, p, x) : (void)0)
#define glMaterialfv(f, p, v) (glMaterialfv ? glMaterialfv(f, p, v) : (void)0)
#define glMaterialiv(f, p, v) (glMaterialiv ? glMaterialiv(f, p, v) : (void)0)
#define glGetLightfv(l, p, v) (glGetLightfv ? glGetLightfv(l, p, v) : (void)0)
#define glGetLightiv(l, p, v) (glGetLightiv ? glGetLightiv(l, p, v) : (void)0)
#define glGetMaterialfv(f, p, v) (glGetMaterialfv ? glGetMaterialfv(f, p, v) : (void)0)
#define glGetMaterialiv(f, p, v) (glGetMaterialiv ? glGetMaterialiv(f, p, v) : (void)0)
#define glColorMaterial(f, m) (glColorMaterial ? glColorMaterial(f, m) : (void)0)
#define glFrontFace(m) (glFrontFace ? glFrontFace(m) : (void)0)
#define glCullFace(m) (glCullFace ? glCullFace(m) : (void)0)

#endif /* !FC_ORACLE */

#endif
