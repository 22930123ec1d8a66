/*
 * The OSMesa side of the split view: Mesa's libOSMesa (llvmpipe, the
 * project's oracle) loaded at run time, so the viewer runs without it.
 *
 * The process is linked with libfixgl, which exports the same gl* and
 * OSMesa* names.  The library is opened with RTLD_LOCAL | RTLD_NOW |
 * RTLD_DEEPBIND: RTLD_LOCAL keeps its symbols out of the global scope (so
 * nothing of fixgl binds to Mesa), RTLD_DEEPBIND makes its own calls to its
 * own exports (OSMesaGetCurrentContext from glFinish's front-buffer flush,
 * OSMesaCreateContextExt -> OSMesaCreateContextAttribs, ...) resolve inside
 * the library instead of to fixgl's functions of the same name.  Every
 * entry point is taken with dlsym on the handle (OSMesaGetProcAddress for
 * what dlsym does not find).  Built with AddressSanitizer, which refuses
 * RTLD_DEEPBIND, the library is opened with dlmopen in a new link-map
 * namespace instead.
 *
 * Mesa's GL context is current on the calling thread through libglapi;
 * the GLX context of a window (fv_present) is too, so fv_osmesa_begin must
 * precede each frame drawn here and the window's context be made current
 * again before presenting.
 */
#ifndef FV_OSMESA_H
#define FV_OSMESA_H

#include "fv_gl.h"

struct fv_osmesa;

/* Loads libOSMesa (the environment variable FIXGL_VIEW_OSMESA names
 * another file, or "none" to do without) and creates an RGBA context with
 * 24 depth and 8 stencil bits.  NULL when unavailable, with the reason in
 * *why (a static string). */
struct fv_osmesa *fv_osmesa_open(const char **why);
void fv_osmesa_close(struct fv_osmesa *o);

/* Makes the context current on rgba (w x h, bottom-up RGBA8, kept by the
 * caller); returns 0, or -1. */
int fv_osmesa_begin(struct fv_osmesa *o, unsigned char *rgba, int w, int h);

/* The GL table of Mesa's functions. */
const struct fv_gl *fv_osmesa_gl(const struct fv_osmesa *o);

/* Any Mesa GL function by name (for the GLSL reference's shader calls). */
fv_proc fv_osmesa_getproc(const char *name);

/* The file that was loaded. */
const char *fv_osmesa_path(const struct fv_osmesa *o);

#endif
