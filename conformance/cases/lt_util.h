/* lt_util.h - helpers shared by the lighting cases (c_light*.c): light,
 * material and light-model setters taking four floats, views, and lit
 * geometry (spheres, flat and wavy tessellated patches) with per-vertex
 * normals.  Every helper issues plain GL 1.x calls. */
#ifndef LT_UTIL_H
#define LT_UTIL_H

#include "cases.h"

#define LT_PI 3.14159265358979323846

/* glLightfv / glMaterialfv / glLightModelfv of a 4-vector. */
void lt_light(GLenum light, GLenum pname, float x, float y, float z, float w);
void lt_mat(GLenum face, GLenum pname, float r, float g, float b, float a);
void lt_model(GLenum pname, float r, float g, float b, float a);

/* A light with ambient, diffuse and specular colours (alpha 1) and a
 * position; enables it. */
void lt_lamp(GLenum light, const float amb[3], const float diff[3], const float spec[3],
             float x, float y, float z, float w);

/* Front and back: ambient 0.2, warm diffuse, grey specular, shininess 30. */
void lt_std_material(void);

/* Whole-buffer viewport; perspective (frustum near 1.5, far 20, the
 * framebuffer's aspect) or ortho (-s..s vertically, z -10..10) projection;
 * identity modelview; depth test (GL_LESS) on; colour and depth cleared to
 * a dark blue-grey / 1. */
void lt_persp(fc_h *h);
void lt_ortho(fc_h *h, float s);
void lt_clear(void);

/* Sphere of radius r at the origin, unit normals, counter-clockwise seen
 * from outside, one GL_TRIANGLE_STRIP per stack. */
void lt_sphere(float r, int slices, int stacks);
/* Sphere whose normals are scaled by ns (not unit length when ns != 1). */
void lt_sphere_n(float r, int slices, int stacks, float ns);
/* Flat patch [x0,x1]x[y0,y1] at z = 0, normal (0,0,1), n x n quads as
 * triangle strips, counter-clockwise seen from +z. */
void lt_patch(float x0, float y0, float x1, float y1, int n);
/* Height field z = amp*sin(f*x)*cos(f*y) over the same grid, unit normals. */
void lt_wave(float x0, float y0, float x1, float y1, int n, float amp, float f);
/* Per-vertex colour used by the colour-material cases: a saturated hue for
 * t in [0,1) (alpha a). */
void lt_hue(float t, float a);

/* Records glGetLightfv and glGetLightiv (glGetMaterialfv / iv) of one
 * pname as blobs; the output arrays are pre-filled with a fixed pattern. */
void lt_rec_light(fc_h *h, const char *label, GLenum light, GLenum pname);
void lt_rec_material(fc_h *h, const char *label, GLenum face, GLenum pname);

#endif
