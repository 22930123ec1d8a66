/*
 * Images through OpenImageIO's C++ API behind a small C interface, for
 * the viewer's textures (read: any format OpenImageIO knows) and the
 * bundled model's texture (written by gen_models.c).  Pixels are RGBA8.
 */
#ifndef FV_IMAGE_H
#define FV_IMAGE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

struct fv_image {
   int w, h;
   int channels;          /* in the file: 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA */
   unsigned char *rgba;   /* w x h RGBA8, bottom row first (GL's order); grey
                           * replicated, alpha 255 when the file has none */
};

/* Reads path; returns 0, or -1 with the reason in err (nothing printed). */
int fv_image_read(const char *path, struct fv_image *im, char *err, size_t err_size);

/* Writes w x h RGBA8 pixels given top row first (the format from the
 * name's extension); returns 0, or -1 with the reason in err. */
int fv_image_write(const char *path, int w, int h, const unsigned char *rgba, char *err,
                   size_t err_size);

void fv_image_free(struct fv_image *im);

#ifdef __cplusplus
}
#endif

#endif
