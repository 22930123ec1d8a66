/* sh_util.h - the shading-extension helpers of c_shading.c that the
 * random-shading scenes (random/fc_random_shading.c) share: select the
 * shading under test (fixgl's GL_PHONG_WIN / GL_FIXGL_cook_torrance, or the
 * GLSL reference conformance/reference/fcr_shading.c on the oracle) and
 * the test texture. */
#ifndef SH_UTIL_H
#define SH_UTIL_H

#include "fc_case.h"
#include "fcr_shading.h"

enum sh_mode { SH_PHONG, SH_SMOOTH, SH_FLAT };

/* Selects the shading for what follows: mode (GL_PHONG_WIN, GL_SMOOTH or
 * GL_FLAT) and the reflectance model of each face.  Call it after the state
 * the reference compiles in (enabled lights, light model, colour material,
 * GL_NORMALIZE / GL_RESCALE_NORMAL, GL_TEXTURE_2D, fog; fcr_shading.h);
 * light and material colours may change afterwards.  Records whether the
 * reference bound (fc_value "reference bound"). */
void sh_begin(fc_h *h, enum sh_mode mode, const struct fcr_face *front, const struct fcr_face *back);
/* Back to fixed-function GL_SMOOTH Blinn-Phong (the reference released). */
void sh_end(void);
/* Sphere of radius r, unit normals, colored: a hue per vertex; texture
 * coordinates when sh_texcoords is set. */
void sh_sphere(float r, int slices, int stacks, int colored);
extern int sh_texcoords;
/* A smooth 8x8 RGBA texture on GL_TEXTURE_2D (GL_LINEAR, GL_REPEAT,
 * GL_MODULATE), enabled. */
void sh_texture(void);

#endif
