/* p_limits.c - the oracle's renderer and the limits fixgl reports like it
 * (ORACLE-NOTES.md "The oracle and its host"). */
#include "probe.h"

int main(void)
{
   probe_init_ub(16, 16);
   const char *r = (const char *)glGetString(GL_RENDERER);
   printf("GL_RENDERER %s\n", r);
   probe_expect("renderer is llvmpipe", strncmp(r, "llvmpipe", 8) == 0, 1);
   probe_expect("llvmpipe vectors are 256 bits", strstr(r, "256 bits") != NULL, 1);
   GLint v[2];
   GLfloat f[2];
   glGetIntegerv(GL_SUBPIXEL_BITS, v);
   probe_expect("GL_SUBPIXEL_BITS", v[0], 8);
   glGetIntegerv(GL_DEPTH_BITS, v);
   probe_expect("GL_DEPTH_BITS", v[0], 24);
   glGetIntegerv(GL_STENCIL_BITS, v);
   probe_expect("GL_STENCIL_BITS", v[0], 8);
   glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, f);
   probe_expect("GL_ALIASED_LINE_WIDTH_RANGE max", (long)f[1], 255);
   glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, f);
   probe_expect("GL_ALIASED_POINT_SIZE_RANGE max", (long)f[1], 255);
   glGetIntegerv(GL_MAX_LIGHTS, v);
   probe_expect("GL_MAX_LIGHTS", v[0], 8);
   glGetIntegerv(GL_MAX_TEXTURE_UNITS, v);
   probe_expect("GL_MAX_TEXTURE_UNITS", v[0], 8);
   glGetIntegerv(GL_MAX_TEXTURE_SIZE, v);
   probe_expect("GL_MAX_TEXTURE_SIZE", v[0], 16384);
   glGetIntegerv(GL_MAX_VIEWPORT_DIMS, v);
   probe_expect("GL_MAX_VIEWPORT_DIMS", v[0], 16384);
   probe_expect("GL_DITHER enabled by default", glIsEnabled(GL_DITHER), 1);
   return probe_result();
}
