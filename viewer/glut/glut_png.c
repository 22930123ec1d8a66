/*
 * PNG frames of the GLUT layer through libpng, loaded (dlopen) when the
 * first frame is written: a program that writes no image never maps
 * libpng or zlib.  Only the simplified API (png_image_*) is used, so the
 * three functions below are all that is looked up.  png.h supplies the
 * types; nothing of libpng is linked.
 */
#include <dlfcn.h>
#include <png.h>
#include <stdio.h>
#include <string.h>

#include "glut_internal.h"

#define GLUT_PNG_SONAME "libpng16.so.16"

static struct {
   bool tried;
   int (*write_to_file)(png_imagep, const char *, int, const void *, png_int_32, const void *);
   void (*image_free)(png_imagep);
} png;

static bool load_libpng(void)
{
   if (png.tried)
      return png.write_to_file != NULL;
   png.tried = true;
   void *h = dlopen(GLUT_PNG_SONAME, RTLD_NOW | RTLD_LOCAL);
   if (!h) {
      glut_warn("cannot load %s to write PNG frames: %s", GLUT_PNG_SONAME, dlerror());
      return false;
   }
   *(void **)&png.write_to_file = dlsym(h, "png_image_write_to_file");
   *(void **)&png.image_free = dlsym(h, "png_image_free");
   if (!png.write_to_file || !png.image_free) {
      glut_warn("%s lacks png_image_write_to_file", GLUT_PNG_SONAME);
      png.write_to_file = NULL;
      return false;
   }
   return true;
}

int glut_png_write(const char *path, int w, int h, const unsigned char *rgba, bool bottom_up)
{
   if (!load_libpng())
      return -1;
   png_image img;
   memset(&img, 0, sizeof img);
   img.version = PNG_IMAGE_VERSION;
   img.width = (png_uint_32)w;
   img.height = (png_uint_32)h;
   img.format = PNG_FORMAT_RGBA;
   /* a negative row stride: the buffer's first row is the image's bottom */
   png_int_32 stride = bottom_up ? -(png_int_32)w * 4 : (png_int_32)w * 4;
   if (!png.write_to_file(&img, path, 0, rgba, stride, NULL)) {
      glut_warn("cannot write %s: %s", path, img.message);
      png.image_free(&img);
      return -1;
   }
   return 0;
}
