/*
 * fixgl's lighting equations at one point, GL-free: the Blinn-Phong model
 * of GL 1.x and the Cook-Torrance model of GL_FIXGL_cook_torrance, exactly
 * as include/fixgl/shading.md writes them.  Used per vertex for
 * Cook-Torrance under GL_SMOOTH/GL_FLAT (tnl/t_light.c) and per fragment
 * under GL_PHONG_WIN (raster/r_frag.c).  The per-vertex Blinn-Phong of
 * GL_SMOOTH/GL_FLAT is NOT this code: it is t_light.c's replica of the
 * oracle's fixed-function vertex program.
 *
 * The context fills an m_shade_env at validation time (main/light.c
 * fgl_update_shade_env, once per batch); the evaluation trusts it.
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

/* What the equations compute from the lights, the light model and the
 * reflectance parameters alone, the same at every point (m_shade_prepare):
 * the same operations as shading.md writes them per point, done once. */
struct m_shade_light_prep {
   float L[3];       /* p.w == 0: normalize(p.xyz); else p.xyz / p.w */
   float H[3];       /* p.w == 0 without local viewer: normalize(L + (0, 0, 1)) */
   float spot;       /* p.w == 0: the spot factor (1 without a spot) */
};

struct m_shade_material_prep {   /* Cook-Torrance */
   float a2;                     /* alpha*alpha, alpha = r*r, r = max(roughness, 1/32) */
   float a2_minus_1;             /* a2 - 1 */
   float k, one_minus_k;         /* (r + 1)*(r + 1) / 8, 1 - k */
   float metal, one_minus_metal; /* m, 1 - m */
   float f0_dielectric;          /* f0 * (1 - m), F0's first term */
};

struct m_shade_prep {
   struct m_shade_light_prep light[M_SHADE_MAX_LIGHTS];
   struct m_shade_material_prep material[2];
};

struct m_shade_env {
   unsigned num_lights;       /* the enabled lights, in index order */
   struct m_shade_light light[M_SHADE_MAX_LIGHTS];
   float global_ambient[4];
   bool local_viewer, two_side, separate_specular;
   struct m_shade_material material[2];   /* front, back */
   unsigned color_material;
   /* filled by m_shade_prepare from the fields above, for
    * m_shade_point_prepared; depends on no material colour nor the shininess */
   struct m_shade_prep prep;
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

/* Fills env->prep from the lights, the light model and the reflectance
 * parameters of env.  Call it again after changing any of them; the
 * material colours and shininess may change without it (they are read per
 * point). */
void m_shade_prepare(struct m_shade_env *env);

/* m_shade_point with env->prep (m_shade_prepare; fgl_update_shade_env
 * calls it) instead of computing it for the point: the same bits, for the
 * per-vertex and per-fragment paths, whose environment is filled once per
 * batch. */
void m_shade_point_prepared(const struct m_shade_env *env, const float n[3], const float p[3],
                      bool back, const float color[4], float primary[4], float secondary[4]);

/* Eight points at once, structure of arrays (lane i of n[k], p[k],
 * color[k], primary[k], secondary[k] is point i's component k): lane i's
 * outputs are bit for bit m_shade_point_prepared's on lane i's inputs, for
 * every environment (env->prep filled by m_shade_prepare).  The face is
 * the call's, for the 8 lanes; color may be NULL when the face tracks no
 * property (as for m_shade_point_prepared).
 *
 * m_shade_point8 is resolved once, when the library is loaded: the AVX2 +
 * FMA kernel (math/m_shade_avx2.c) on a CPU that has both, else the
 * portable one (math/m_shade8.c, m_shade_point_prepared lane by lane).
 * Both are also callable directly (tests, benchmarks);
 * m_shade_point8_avx2 exists only where M_SHADE_HAVE_AVX2 is defined (an
 * x86-64 build with the SIMD kernels: meson's simd_kernels) and
 * may be called only when m_shade_point8_avx2_supported().
 * (ISO C before C2X does not convert float (*)[8] to const float (*)[8]
 * silently: a caller with non-const arrays casts them,
 * (const float (*)[M_SHADE_LANES])n, or -Wpedantic warns.) */
#define M_SHADE_LANES 8

void m_shade_point8(const struct m_shade_env *env, const float n[3][M_SHADE_LANES],
                    const float p[3][M_SHADE_LANES], bool back,
                    const float color[4][M_SHADE_LANES], float primary[4][M_SHADE_LANES],
                    float secondary[4][M_SHADE_LANES]);

void m_shade_point8_portable(const struct m_shade_env *env, const float n[3][M_SHADE_LANES],
                             const float p[3][M_SHADE_LANES], bool back,
                             const float color[4][M_SHADE_LANES],
                             float primary[4][M_SHADE_LANES],
                             float secondary[4][M_SHADE_LANES]);

#if defined(__x86_64__) && defined(__GNUC__) && defined(FGL_HAVE_BLOCK_KERNELS)
#define M_SHADE_HAVE_AVX2 1
void m_shade_point8_avx2(const struct m_shade_env *env, const float n[3][M_SHADE_LANES],
                         const float p[3][M_SHADE_LANES], bool back,
                         const float color[4][M_SHADE_LANES], float primary[4][M_SHADE_LANES],
                         float secondary[4][M_SHADE_LANES]);
#endif

/* Whether this CPU runs m_shade_point8_avx2 (AVX2 and FMA, with the OS's
 * YMM state), i.e. whether m_shade_point8 is the AVX2 kernel. */
bool m_shade_point8_avx2_supported(void);

#endif /* FGL_M_SHADE_H */
