/*
 * enum_honesty: fixgl claims nothing it lacks (issue 19, "Version and
 * honesty").  An implementation of GL 1.5 without an extension must raise
 * GL_INVALID_ENUM for that extension's enums and for those of later GL
 * versions; fixgl exposes GL 1.x plus exactly the extensions its
 * GL_EXTENSIONS string lists.
 *
 * The test reads the system's <GL/gl.h> and <GL/glext.h> (paths given as
 * arguments), sorts every `#define GL_NAME value` by the block it is in
 * (`#ifndef GL_VERSION_x_y` or `#ifndef GL_<extension>`), and takes as
 * allowed the values of the GL 1.0-1.5 blocks, of gl.h's core, and of the
 * blocks of the extensions fixgl lists.  Every other value (one no allowed
 * name shares) is "foreign": for each, a set of calls whose only
 * questionable argument is that enum must raise GL_INVALID_ENUM, leave no
 * other error, and (the glGet* family) write nothing.  It also checks that
 * the version string names no version above 1.5.
 *
 * fixgl only (the oracle implements GL 4.5 and accepts these enums).
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <ctype.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define MAX_ENUMS 16384

struct def {
   char name[128];
   uint32_t value;
   int allowed;   /* 1 allowed block, 0 foreign block */
};

static struct def defs[MAX_ENUMS];
static int ndefs;
static const char *extensions;

/* Is the block (a GL_VERSION_x_y or an extension name) one fixgl has? */
static int block_allowed(const char *block)
{
   if (!block[0])
      return 1;   /* gl.h's core, outside any block */
   if (!strncmp(block, "GL_VERSION_", 11)) {
      int major = 0, minor = 0;
      if (sscanf(block + 11, "%d_%d", &major, &minor) != 2)
         return 0;
      return major == 1 && minor <= 5;
   }
   /* an extension: exactly its name in the space-separated list */
   const size_t n = strlen(block);
   for (const char *p = extensions; (p = strstr(p, block)) != NULL; p += n) {
      if ((p == extensions || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
         return 1;
   }
   return 0;
}

static int read_header(const char *path)
{
   FILE *f = fopen(path, "r");
   if (!f) {
      FAIL("cannot read %s", path);
      return 0;
   }
   char line[1024], block[128] = "";
   int depth = 0;   /* #if nesting inside the current block */
   int count = 0;
   while (fgets(line, sizeof line, f)) {
      char name[128], value[128];
      if (!block[0] && sscanf(line, "#ifndef %127s", name) == 1 && !strncmp(name, "GL_", 3) &&
          strcmp(name, "GL_GLEXT_VERSION") != 0) {
         snprintf(block, sizeof block, "%s", name);
         depth = 0;
         continue;
      }
      if (!strncmp(line, "#if", 3)) {
         depth++;
         continue;
      }
      if (!strncmp(line, "#endif", 6)) {
         if (depth > 0)
            depth--;
         else
            block[0] = '\0';
         continue;
      }
      if (sscanf(line, "#define %127s %127s", name, value) != 2 || strncmp(name, "GL_", 3) != 0)
         continue;
      if (!strcmp(name, "GL_GLEXT_VERSION") || !isdigit((unsigned char)value[0]))
         continue;
      char *end;
      const unsigned long long v = strtoull(value, &end, 0);
      if (v > 0xffffffffull)
         continue;
      if (ndefs == MAX_ENUMS) {
         FAIL("more than %d definitions", MAX_ENUMS);
         break;
      }
      struct def *d = &defs[ndefs++];
      snprintf(d->name, sizeof d->name, "%s", name);
      d->value = (uint32_t)v;
      d->allowed = block_allowed(block);
      count++;
   }
   fclose(f);
   return count;
}

static int value_allowed(uint32_t v)
{
   /* GL_CLIP_PLANE0 + i and GL_LIGHT0 + i are GL 1.0's names for every i
    * below the implementation's maximum (glext.h names GL_CLIP_DISTANCE6
    * and 7, GL 3.0's, with the values of planes 6 and 7) */
   GLint max_planes = 0, max_lights = 0;
   glGetIntegerv(GL_MAX_CLIP_PLANES, &max_planes);
   glGetIntegerv(GL_MAX_LIGHTS, &max_lights);
   if ((v >= GL_CLIP_PLANE0 && v < GL_CLIP_PLANE0 + (uint32_t)max_planes) ||
       (v >= GL_LIGHT0 && v < GL_LIGHT0 + (uint32_t)max_lights))
      return 1;
   for (int i = 0; i < ndefs; i++)
      if (defs[i].value == v && defs[i].allowed)
         return 1;
   return 0;
}

static int foreign_failures;

/* the call raised GL_INVALID_ENUM and nothing else */
static void expect_enum(const char *call, const struct def *d)
{
   const GLenum e = glGetError();
   const GLenum more = glGetError();
   if (e != GL_INVALID_ENUM || more != GL_NO_ERROR) {
      if (foreign_failures++ < 400)
         FAIL("%s(%s = 0x%04x): error 0x%04x then 0x%04x, want GL_INVALID_ENUM", call, d->name,
              (unsigned)d->value, (unsigned)e, (unsigned)more);
   }
   while (glGetError() != GL_NO_ERROR) {
   }
}

static void untouched(const char *call, const struct def *d, const void *buf, size_t n)
{
   const unsigned char *b = buf;
   for (size_t i = 0; i < n; i++)
      if (b[i] != 0xa5) {
         if (foreign_failures++ < 400)
            FAIL("%s(%s = 0x%04x) wrote its result", call, d->name, (unsigned)d->value);
         return;
      }
}

static void probe_foreign(const struct def *d)
{
   const GLenum v = (GLenum)d->value;
   union {
      GLint i[64];
      GLfloat f[64];
      GLdouble dd[32];
      GLboolean b[256];
   } buf;

   glEnable(v);
   expect_enum("glEnable", d);
   glDisable(v);
   expect_enum("glDisable", d);
   (void)glIsEnabled(v);
   expect_enum("glIsEnabled", d);

   memset(&buf, 0xa5, sizeof buf);
   glGetIntegerv(v, buf.i);
   expect_enum("glGetIntegerv", d);
   untouched("glGetIntegerv", d, &buf, sizeof buf);
   memset(&buf, 0xa5, sizeof buf);
   glGetFloatv(v, buf.f);
   expect_enum("glGetFloatv", d);
   untouched("glGetFloatv", d, &buf, sizeof buf);
   memset(&buf, 0xa5, sizeof buf);
   glGetDoublev(v, buf.dd);
   expect_enum("glGetDoublev", d);
   untouched("glGetDoublev", d, &buf, sizeof buf);
   memset(&buf, 0xa5, sizeof buf);
   glGetBooleanv(v, buf.b);
   expect_enum("glGetBooleanv", d);
   untouched("glGetBooleanv", d, &buf, sizeof buf);
   (void)glGetString(v);
   expect_enum("glGetString", d);

   glHint(v, GL_NICEST);
   expect_enum("glHint", d);
   glBindTexture(v, 0);
   expect_enum("glBindTexture", d);
   glTexParameteri(GL_TEXTURE_2D, v, 0);
   expect_enum("glTexParameteri", d);
   memset(&buf, 0xa5, sizeof buf);
   glGetTexParameteriv(GL_TEXTURE_2D, v, buf.i);
   expect_enum("glGetTexParameteriv", d);
   untouched("glGetTexParameteriv", d, &buf, sizeof buf);
   memset(&buf, 0xa5, sizeof buf);
   glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, v, buf.i);
   expect_enum("glGetTexLevelParameteriv", d);
   untouched("glGetTexLevelParameteriv", d, &buf, sizeof buf);
   glTexEnvi(GL_TEXTURE_ENV, v, 0);
   expect_enum("glTexEnvi", d);
   glPixelStorei(v, 0);
   expect_enum("glPixelStorei", d);
   glLightf(GL_LIGHT0, v, 0.0f);
   expect_enum("glLightf", d);
   glBlendFunc(v, GL_ZERO);
   expect_enum("glBlendFunc", d);
   glDepthFunc(v);
   expect_enum("glDepthFunc", d);
   glDrawArrays(v, 0, 0);
   expect_enum("glDrawArrays", d);
   glReadPixels(0, 0, 1, 1, v, GL_UNSIGNED_BYTE, buf.b);
   expect_enum("glReadPixels(format)", d);
   glReadPixels(0, 0, 1, 1, GL_RGBA, v, buf.b);
   expect_enum("glReadPixels(type)", d);
   glDrawPixels(1, 1, v, GL_UNSIGNED_BYTE, buf.b);
   expect_enum("glDrawPixels(format)", d);
   glDrawPixels(1, 1, GL_RGBA, v, buf.b);
   expect_enum("glDrawPixels(type)", d);
   glCopyPixels(0, 0, 1, 1, v);
   expect_enum("glCopyPixels", d);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, v, GL_UNSIGNED_BYTE, buf.b);
   expect_enum("glTexImage2D(format)", d);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, v, buf.b);
   expect_enum("glTexImage2D(type)", d);
   glTexImage2D(v, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, buf.b);
   expect_enum("glTexImage2D(target)", d);
   glBlendEquation(v);
   expect_enum("glBlendEquation", d);
   glStencilOp(v, GL_KEEP, GL_KEEP);
   expect_enum("glStencilOp", d);
   glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, (GLint)v);
   expect_enum("glTexGeni(mode)", d);
   glMatrixMode(v);
   expect_enum("glMatrixMode", d);
   /* the vertex array types (GL_HALF_FLOAT, GL_INT_2_10_10_10_REV...) */
   glVertexPointer(3, v, 0, buf.i);
   expect_enum("glVertexPointer", d);
   glNormalPointer(v, 0, buf.i);
   expect_enum("glNormalPointer", d);
   glColorPointer(4, v, 0, buf.i);
   expect_enum("glColorPointer", d);
   glTexCoordPointer(2, v, 0, buf.i);
   expect_enum("glTexCoordPointer", d);
   glSecondaryColorPointer(3, v, 0, buf.i);
   expect_enum("glSecondaryColorPointer", d);
   glFogCoordPointer(v, 0, buf.i);
   expect_enum("glFogCoordPointer", d);
}

int main(int argc, char **argv)
{
   if (argc != 3) {
      fprintf(stderr, "usage: %s GL/gl.h GL/glext.h\n", argv[0]);
      return 2;
   }
   enum { W = 4, H = 4 };
   static unsigned char fb[W * H * 4];
   OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
   if (!ctx || !OSMesaMakeCurrent(ctx, fb, GL_UNSIGNED_BYTE, W, H)) {
      FAIL("no context");
      return check_report("enum_honesty");
   }
   extensions = (const char *)glGetString(GL_EXTENSIONS);
   CHECK(extensions != NULL, "GL_EXTENSIONS");
   if (!extensions)
      return check_report("enum_honesty");

   const int n_gl = read_header(argv[1]);
   const int n_ext = read_header(argv[2]);
   CHECK(n_gl > 500 && n_ext > 3000, "definitions read: %d in gl.h, %d in glext.h", n_gl, n_ext);

   /* the version string */
   const char *version = (const char *)glGetString(GL_VERSION);
   CHECK(version && !strncmp(version, "1.", 2) && version[2] >= '1' && version[2] <= '5' &&
            (version[3] == ' ' || version[3] == '.' || version[3] == '\0'),
         "GL_VERSION \"%s\" names a version from 1.1 to 1.5", version ? version : "(null)");

   /* each foreign value once */
   int foreign = 0, probed = 0;
   for (int i = 0; i < ndefs; i++) {
      if (defs[i].allowed || value_allowed(defs[i].value))
         continue;
      foreign++;
      int seen = 0;
      for (int j = 0; j < i && !seen; j++)
         seen = defs[j].value == defs[i].value;
      if (seen)
         continue;
      probe_foreign(&defs[i]);
      probed++;
   }
   /* a sanity bound: glext.h holds thousands of enums beyond GL 1.5 */
   CHECK(probed > 1000, "only %d foreign values probed", probed);
   printf("enum_honesty: %d definitions, %d foreign names, %d foreign values probed with 43 calls "
          "each, %d wrong answers\n",
          ndefs, foreign, probed, foreign_failures);
   CHECK(foreign_failures == 0, "%d calls accepted an enum fixgl does not have", foreign_failures);

   /* GL 1.x enums that only a later version accepts in a place: the value
    * is allowed, its use there is not.  GL_DEPTH_TEXTURE_MODE GL_RED is
    * ARB_texture_rg's (GL 3.0); the texture keeps GL_LUMINANCE. */
   while (glGetError() != GL_NO_ERROR)
      ;
   glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RED);
   CHECK(glGetError() == GL_INVALID_ENUM, "GL_DEPTH_TEXTURE_MODE GL_RED: GL_INVALID_ENUM");
   const GLfloat red = (GLfloat)GL_RED;
   glTexParameterfv(GL_TEXTURE_1D, GL_DEPTH_TEXTURE_MODE, &red);
   CHECK(glGetError() == GL_INVALID_ENUM, "glTexParameterfv GL_DEPTH_TEXTURE_MODE GL_RED: GL_INVALID_ENUM");
   GLint mode = 0;
   glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &mode);
   CHECK(mode == GL_LUMINANCE, "GL_DEPTH_TEXTURE_MODE after GL_RED: %#x", (unsigned)mode);
   glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
   CHECK(glGetError() == GL_NO_ERROR, "GL_DEPTH_TEXTURE_MODE GL_ALPHA: no error");

   /* GL_UNSIGNED_INT_2_10_10_10_REV is a GL 1.2 pixel type, a vertex
    * array type only from GL 3.3 (ARB_vertex_type_2_10_10_10_rev): GL 1.5
    * raises GL_INVALID_ENUM.  GL_BGRA is a GL 1.2 pixel format, the size
    * of a colour array only from GL 3.2 (ARB/EXT_vertex_array_bgra): GL
    * 1.5 raises GL_INVALID_VALUE, a bad size, after the type check.  Each
    * leaves the array as it was. */
   static GLuint arr[16];
   glColorPointer(3, GL_UNSIGNED_BYTE, 0, arr);
   glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, arr);
   glVertexPointer(2, GL_SHORT, 0, arr);
   glNormalPointer(GL_BYTE, 0, arr);
   glTexCoordPointer(2, GL_SHORT, 0, arr);
   CHECK(glGetError() == GL_NO_ERROR, "GL 1.5 pointers: no error");
   glVertexPointer(4, GL_UNSIGNED_INT_2_10_10_10_REV, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_ENUM, "glVertexPointer 2_10_10_10_REV: GL_INVALID_ENUM");
   glNormalPointer(GL_UNSIGNED_INT_2_10_10_10_REV, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_ENUM, "glNormalPointer 2_10_10_10_REV: GL_INVALID_ENUM");
   glColorPointer(4, GL_UNSIGNED_INT_2_10_10_10_REV, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_ENUM, "glColorPointer 2_10_10_10_REV: GL_INVALID_ENUM");
   glTexCoordPointer(4, GL_UNSIGNED_INT_2_10_10_10_REV, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_ENUM, "glTexCoordPointer 2_10_10_10_REV: GL_INVALID_ENUM");
   glSecondaryColorPointer(4, GL_UNSIGNED_INT_2_10_10_10_REV, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_ENUM, "glSecondaryColorPointer 2_10_10_10_REV: GL_INVALID_ENUM");
   glColorPointer(GL_BGRA, GL_UNSIGNED_BYTE, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_VALUE, "glColorPointer GL_BGRA: GL_INVALID_VALUE");
   glColorPointerEXT(GL_BGRA, GL_UNSIGNED_BYTE, 0, 4, arr + 1);
   CHECK(glGetError() == GL_INVALID_VALUE, "glColorPointerEXT GL_BGRA: GL_INVALID_VALUE");
   glSecondaryColorPointer(GL_BGRA, GL_UNSIGNED_BYTE, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_VALUE, "glSecondaryColorPointer GL_BGRA: GL_INVALID_VALUE");
   glSecondaryColorPointerEXT(GL_BGRA, GL_UNSIGNED_BYTE, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_VALUE, "glSecondaryColorPointerEXT GL_BGRA: GL_INVALID_VALUE");
   /* the type is checked first: a foreign type with GL_BGRA is an enum error */
   glColorPointer(GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_ENUM, "glColorPointer GL_BGRA 2_10_10_10_REV: GL_INVALID_ENUM");
   glColorPointer(GL_BGRA, GL_FLOAT, 0, arr + 1);
   CHECK(glGetError() == GL_INVALID_VALUE, "glColorPointer GL_BGRA GL_FLOAT: GL_INVALID_VALUE");
   CHECK(glGetError() == GL_NO_ERROR, "one error per call");
   GLint q[2] = { 0, 0 };
   glGetIntegerv(GL_COLOR_ARRAY_SIZE, &q[0]);
   glGetIntegerv(GL_COLOR_ARRAY_TYPE, &q[1]);
   CHECK(q[0] == 3 && q[1] == GL_UNSIGNED_BYTE, "colour array kept: size %d type %#x", q[0],
         (unsigned)q[1]);
   glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &q[0]);
   glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &q[1]);
   CHECK(q[0] == 3 && q[1] == GL_UNSIGNED_BYTE, "secondary colour array kept: size %d type %#x",
         q[0], (unsigned)q[1]);
   glGetIntegerv(GL_VERTEX_ARRAY_TYPE, &q[0]);
   glGetIntegerv(GL_NORMAL_ARRAY_TYPE, &q[1]);
   CHECK(q[0] == GL_SHORT && q[1] == GL_BYTE, "vertex, normal arrays kept: %#x %#x",
         (unsigned)q[0], (unsigned)q[1]);
   GLvoid *ptr = NULL;
   glGetPointerv(GL_COLOR_ARRAY_POINTER, &ptr);
   CHECK(ptr == (GLvoid *)arr, "colour array pointer kept");

   OSMesaDestroyContext(ctx);
   return check_report("enum_honesty");
}
