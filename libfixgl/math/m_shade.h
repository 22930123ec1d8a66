/*
 * fixgl's lighting equations at one point, GL-free: the Blinn-Phong model
 * of GL 1.x and the Cook-Torrance model of GL_FIXGL_cook_torrance, exactly
 * as include/fixgl/shading.md writes them.  Used per vertex for
 * Cook-Torrance under GL_SMOOTH/GL_FLAT (tnl/t_light.c) and per fragment
 * under GL_PHONG_WIN (raster/r_frag.c).  The per-vertex Blinn-Phong of
 * GL_SMOOTH/GL_FLAT is NOT this code: it is t_light.c's replica of the
 * oracle's fixed-function vertex program.
 *
 * The context fills an m_shade_env at validation time (state.c); the
 * evaluation trusts it.
 */
#ifndef FGL_M_SHADE_H
#define FGL_M_SHADE_H

#include <stdbool.h>

#define M_SHADE_MAX_LIGHTS 8

enum m_shade_model {
   M_SHADE_BLINN_PHONG,
   M_SHADE_COOK_TORRANCE,
};

/* One face's material.  A property that GL_COLOR_MATERIAL tracks is
 * replaced by the vertex colour at evaluation time (color_material). */
struct m_shade_material {
   enum m_shade_model model;
   float ambient[4], diffuse[4], specular[4], emission[4];
   float shininess;
   float roughness, metalness, f0;    /* Cook-Torrance */
};

/* One enabled light, in eye space. */
struct m_shade_light {
   float ambient[4], diffuse[4], specular[4];
   float position[4];         /* as glLight stored it (w == 0: directional) */
   float spot_direction[3];   /* normalised */
   bool spot;                 /* cutoff != 180 */
   float spot_exponent, spot_cos_cutoff;   /* cosf(cutoff) */
   float kc, kl, kq;
};

/* Bits of color_material: which properties of which face track the
 * vertex colour. */
enum {
   M_SHADE_CM_AMBIENT = 1u << 0,
   M_SHADE_CM_DIFFUSE = 1u << 1,
   M_SHADE_CM_SPECULAR = 1u << 2,
   M_SHADE_CM_EMISSION = 1u << 3,
   M_SHADE_CM_BACK_SHIFT = 4,         /* the back face's bits are << 4 */
};

struct m_shade_env {
   unsigned num_lights;       /* the enabled lights, in index order */
   struct m_shade_light light[M_SHADE_MAX_LIGHTS];
   float global_ambient[4];
   bool local_viewer, two_side, separate_specular;
   struct m_shade_material material[2];   /* front, back */
   unsigned color_material;
};

/* Lights one point: n the eye-space normal (normalised here), p the eye
 * position (xyz), back the face (the back face uses -n and material[1];
 * without two_side every face is lit as the front one, so back may be the
 * raw facing),
 * color the vertex colour (read only for color_material; may be NULL when
 * it is 0).  primary: rgba clamped to [0,1]; secondary: the specular sum,
 * rgb clamped to [0,1] and a = 1, when separate_specular (else 0, 0, 0, 1).
 */
void m_shade_point(const struct m_shade_env *env, const float n[3], const float p[3],
                   bool back, const float color[4], float primary[4], float secondary[4]);

#endif /* FGL_M_SHADE_H */
