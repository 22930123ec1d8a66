/*
 * fixgl's own API.  The library is used through the standard OpenGL 1.x
 * entry points (<GL/gl.h>) and the OSMesa-compatible context API
 * (<GL/osmesa.h>); this header adds what is specific to fixgl.
 */
#ifndef FIXGL_FIXGL_H
#define FIXGL_FIXGL_H

#ifdef __cplusplus
extern "C" {
#endif

#define FIXGL_VERSION_MAJOR 0
#define FIXGL_VERSION_MINOR 1
#define FIXGL_VERSION_PATCH 0

/* The library's version as "major.minor.patch". */
const char *fixglGetVersion(void);

#ifdef __cplusplus
}
#endif

#endif /* FIXGL_FIXGL_H */
