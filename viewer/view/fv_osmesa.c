/*
 * Mesa's libOSMesa loaded at run time (fv_osmesa.h).
 */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <GL/osmesa.h>   /* types and constants only: no OSMesa* symbol is referenced */

#include "fv_osmesa.h"

/* AddressSanitizer refuses RTLD_DEEPBIND (google/sanitizers issue 611): in
 * a sanitized build the library gets a link-map namespace of its own
 * instead, where fixgl's exports are not visible either. */
#if defined(__SANITIZE_ADDRESS__)
#define FV_DLOPEN(name) dlmopen(LM_ID_NEWLM, (name), RTLD_LOCAL | RTLD_NOW)
#else
#define FV_DLOPEN(name) dlopen((name), RTLD_LOCAL | RTLD_NOW | RTLD_DEEPBIND)
#endif

typedef OSMesaContext (*pfn_create_attribs)(const int *attribs, OSMesaContext share);
typedef void (*pfn_destroy)(OSMesaContext ctx);
typedef GLboolean (*pfn_make_current)(OSMesaContext ctx, void *buf, GLenum type, GLsizei w,
                                      GLsizei h);
typedef OSMESAproc (*pfn_getproc)(const char *name);

struct fv_osmesa {
   void *lib;
   char path[256];
   pfn_create_attribs CreateContextAttribs;
   pfn_destroy DestroyContext;
   pfn_make_current MakeCurrent;
   OSMesaContext ctx;
   struct fv_gl gl;
};

/* One OSMesa per process: fv_osmesa_getproc needs no handle (the GLSL
 * reference's getproc has no user pointer). */
static struct fv_osmesa *the_osmesa;

/* dlsym's object pointer as a function pointer (POSIX guarantees it). */
static fv_proc sym(void *lib, const char *name)
{
   void *p = dlsym(lib, name);
   fv_proc f;
   memcpy(&f, &p, sizeof f);
   return f;
}

fv_proc fv_osmesa_getproc(const char *name)
{
   if (!the_osmesa)
      return NULL;
   fv_proc f = sym(the_osmesa->lib, name);
   if (!f) {
      pfn_getproc gp = (pfn_getproc)sym(the_osmesa->lib, "OSMesaGetProcAddress");
      if (gp)
         return (fv_proc)gp(name);
   }
   return f;
}

struct fv_osmesa *fv_osmesa_open(const char **why)
{
   static const char *const names[] = { "libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so" };
   const char *env = getenv("FIXGL_VIEW_OSMESA");
   if (the_osmesa) {
      *why = "OSMesa is already open";
      return NULL;
   }
   if (env && !strcmp(env, "none")) {
      *why = "OSMesa disabled (FIXGL_VIEW_OSMESA=none)";
      return NULL;
   }
   struct fv_osmesa *o = calloc(1, sizeof *o);
   if (!o) {
      *why = "out of memory";
      return NULL;
   }
   if (env && *env) {
      o->lib = FV_DLOPEN(env);
      snprintf(o->path, sizeof o->path, "%s", env);
   } else {
      for (size_t i = 0; !o->lib && i < sizeof names / sizeof names[0]; i++) {
         o->lib = FV_DLOPEN(names[i]);
         snprintf(o->path, sizeof o->path, "%s", names[i]);
      }
   }
   if (!o->lib) {
      *why = "libOSMesa not found (Debian: libosmesa6)";
      free(o);
      return NULL;
   }
   o->CreateContextAttribs = (pfn_create_attribs)sym(o->lib, "OSMesaCreateContextAttribs");
   o->DestroyContext = (pfn_destroy)sym(o->lib, "OSMesaDestroyContext");
   o->MakeCurrent = (pfn_make_current)sym(o->lib, "OSMesaMakeCurrent");
   the_osmesa = o;
   if (!o->CreateContextAttribs || !o->DestroyContext || !o->MakeCurrent ||
       fv_gl_load(&o->gl, fv_osmesa_getproc) != 0) {
      *why = "libOSMesa lacks an entry point";
      fv_osmesa_close(o);
      return NULL;
   }
   /* OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL), called as the
    * attribute list it builds [S: frontends/osmesa/osmesa.c:OSMesaCreateContextExt] */
   static const int attribs[] = {
      OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
      OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0,
   };
   o->ctx = o->CreateContextAttribs(attribs, NULL);
   if (!o->ctx) {
      *why = "OSMesaCreateContextAttribs failed";
      fv_osmesa_close(o);
      return NULL;
   }
   return o;
}

void fv_osmesa_close(struct fv_osmesa *o)
{
   if (!o)
      return;
   if (o->ctx)
      o->DestroyContext(o->ctx);
   /* The library stays loaded: llvmpipe's threads and atexit handlers
    * outlive dlclose badly. */
   if (the_osmesa == o)
      the_osmesa = NULL;
   free(o);
}

int fv_osmesa_begin(struct fv_osmesa *o, unsigned char *rgba, int w, int h)
{
   return o->MakeCurrent(o->ctx, rgba, GL_UNSIGNED_BYTE, w, h) ? 0 : -1;
}

const struct fv_gl *fv_osmesa_gl(const struct fv_osmesa *o)
{
   return &o->gl;
}

const char *fv_osmesa_path(const struct fv_osmesa *o)
{
   return o->path;
}
