/*
 * The viewer's GL function table (fv_gl.h).
 */
#include <stdio.h>
#include <string.h>

#include "fv_gl.h"

void fv_gl_fixgl(struct fv_gl *gl)
{
   /* The names bind to libfixgl's exports: the viewer never links a
    * system GL (fv_present reaches that one through GLFW only). */
#define FV_GL_FIXGL(ret, name, params) gl->name = gl##name;
   FV_GL_FUNCS(FV_GL_FIXGL)
#undef FV_GL_FIXGL
}

int fv_gl_load(struct fv_gl *gl, fv_getproc getproc)
{
   int missing = 0;
#define FV_GL_LOAD(ret, name, params)                                            \
   gl->name = (ret (*) params)getproc("gl" #name);                               \
   if (!gl->name && !missing++)                                                  \
      fprintf(stderr, "fixgl-view: OSMesa has no gl" #name "\n");
   FV_GL_FUNCS(FV_GL_LOAD)
#undef FV_GL_LOAD
   return missing ? -1 : 0;
}

int fv_gl_has_extension(const struct fv_gl *gl, const char *ext)
{
   const char *all = (const char *)gl->GetString(GL_EXTENSIONS);
   size_t n = strlen(ext);
   for (const char *s = all; s && (s = strstr(s, ext)) != NULL; s += n) {
      if ((s == all || s[-1] == ' ') && (s[n] == ' ' || s[n] == '\0'))
         return 1;
   }
   return 0;
}
