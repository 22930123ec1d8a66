/*
 * PNG files through OpenImageIO's C++ API behind a small C interface
 * (shared by libfixglut, its tests and the viewer).  Pixels are RGBA8.
 */
#ifndef FV_PNG_H
#define FV_PNG_H

#ifdef __cplusplus
extern "C" {
#endif

/* Writes w x h RGBA8 pixels; bottom_up: the first row is the image's
 * bottom row (GL order).  Returns 0, or -1 with a message on stderr. */
int fv_png_write(const char *path, int w, int h, const unsigned char *rgba, int bottom_up);

/* Reads an image as RGBA8 (alpha 255 when the file has none), top row
 * first; *rgba is malloc'd.  Returns 0, or -1 with a message on stderr. */
int fv_png_read(const char *path, int *w, int *h, unsigned char **rgba);

#ifdef __cplusplus
}
#endif

#endif
