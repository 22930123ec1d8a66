/*
 * fv_glfw.h with FV_GLFW_DLOPEN: GLFW and Xlib loaded at the first
 * window.
 */
#include <dlfcn.h>
#include <stdio.h>

#define FV_GLFW_TABLE_ONLY
#include "fv_glfw.h"

struct fv_glfw_table fv_glfw;

static int load_from(const char *soname, void **handle)
{
   *handle = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
   if (!*handle) {
      fprintf(stderr, "cannot load %s: %s\n", soname, dlerror());
      return -1;
   }
   return 0;
}

int fv_glfw_load(void)
{
   static int state;   /* 0: not tried, 1: loaded, -1: failed */
   void *glfw, *x11;
   if (state)
      return state > 0 ? 0 : -1;
   state = -1;
   if (load_from("libglfw.so.3", &glfw) || load_from("libX11.so.6", &x11))
      return -1;
#define FV_GLFW_SYM(lib, name) \
   if (!(*(void **)&fv_glfw.name = dlsym(lib, #name))) { \
      fprintf(stderr, "cannot find %s: %s\n", #name, dlerror()); \
      return -1; \
   }
#define FV_FROM_GLFW(ret, name, params) FV_GLFW_SYM(glfw, name)
#define FV_FROM_X11(ret, name, params) FV_GLFW_SYM(x11, name)
   FV_GLFW_FUNCS(FV_FROM_GLFW)
   FV_X11_FUNCS(FV_FROM_X11)
#undef FV_FROM_GLFW
#undef FV_FROM_X11
#undef FV_GLFW_SYM
   state = 1;
   return 0;
}
