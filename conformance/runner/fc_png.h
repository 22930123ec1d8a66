/* fc_png.h - PNG files through OpenImageIO (fc_png.cpp), with a C interface. */
#ifndef FC_PNG_H
#define FC_PNG_H

#ifdef __cplusplus
extern "C" {
#endif

/* Writes an 8-bit image of `channels` interleaved channels, top row first.
 * Returns 1 on success; on failure prints OpenImageIO's message. */
int fc_png_write(const char *path, int width, int height, int channels, const unsigned char *pixels);

/* Reads an 8-bit image; *pixels is malloc'ed (free() it).  Returns 1 on success. */
int fc_png_read(const char *path, int *width, int *height, int *channels, unsigned char **pixels);

#ifdef __cplusplus
}
#endif

#endif
