/*
 * The viewer's scene: a model framed by its bounding sphere, an orbiting
 * camera, up to 8 GL lights in eye space, the shading mode; drawn through
 * a GL table (fv_gl.h) so that fixgl and OSMesa receive the same calls.
 */
#ifndef FV_SCENE_H
#define FV_SCENE_H

#include "fv_gl.h"
#include "fv_model.h"

enum fv_shade { FV_FLAT, FV_SMOOTH, FV_PHONG };
enum fv_light_type { FV_DIRECTIONAL, FV_POINT, FV_SPOT };

#define FV_MAX_LIGHTS 8

struct fv_light {
   int on;
   enum fv_light_type type;
   float azimuth, elevation;   /* degrees: direction from the model's centre, eye space */
   float distance;             /* point/spot: in model radii from the centre */
   float color[3];
};

struct fv_scene {
   const struct fv_model *model;
   float yaw, pitch;           /* degrees: the orbit */
   float zoom;                 /* 1: the bounding sphere fits the view */
   enum fv_shade shade;        /* glShadeModel: GL_FLAT, GL_SMOOTH, GL_PHONG_WIN */
   int cook_torrance;          /* GL_REFLECTANCE_MODEL_FIXGL: Cook-Torrance, else Blinn-Phong */
   float roughness, metalness;
   int wireframe, cull;
   struct fv_light lights[FV_MAX_LIGHTS];
   int num_lights, selected;
   float background[3];
};

/* The default scene: one white directional light from the upper left. */
void fv_scene_init(struct fv_scene *s, const struct fv_model *m);

/* Adds a light (point, spot, directional in turn, colours in turn) and
 * selects it; returns its index, or -1 when there are 8. */
int fv_scene_add_light(struct fv_scene *s);

/* What the scene's mode needs from the GL that draws it. */
int fv_scene_needs_phong(const struct fv_scene *s);
int fv_scene_needs_cook_torrance(const struct fv_scene *s);

/* "smooth", "Phong + Cook-Torrance (r 0.50, m 0.00)", ... */
void fv_scene_describe(const struct fv_scene *s, char *buf, int size);

struct fcr;

/* Draws the scene into the current context of gl, a w x h frame.  ref:
 * NULL draws with the fixed-function pipeline and fixgl's extensions
 * (GL_PHONG_WIN, GL_REFLECTANCE_MODEL_FIXGL); otherwise the GLSL reference
 * program (conformance/reference/fcr_shading.h) replaces them for Phong
 * and Cook-Torrance, on OSMesa.  Ends with glFinish.  Returns 0, or -1
 * when the reference's program did not compile (its log on stderr). */
int fv_scene_draw(const struct fv_scene *s, const struct fv_gl *gl, int w, int h,
                  struct fcr *ref);

#endif
