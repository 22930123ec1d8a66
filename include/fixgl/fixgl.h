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

/* ---- GL_WIN_phong_shading ------------------------------------------------
 * glShadeModel(GL_PHONG_WIN) lights every fragment with the GL lighting
 * equation, from the perspective-correctly interpolated eye-space normal
 * (renormalised) and eye position.  Values are Microsoft's (glext.h).
 * The exact equations: include/fixgl/shading.md. */
#ifndef GL_WIN_phong_shading
#define GL_WIN_phong_shading 1
#define GL_PHONG_WIN                 0x80EA
#define GL_PHONG_HINT_WIN            0x80EB
#endif

/* ---- GL_FIXGL_cook_torrance ----------------------------------------------
 * A per-face reflectance model for the ordinary GL lights:
 *   glMateriali(face, GL_REFLECTANCE_MODEL_FIXGL, GL_COOK_TORRANCE_FIXGL)
 *   glMaterialf(face, GL_ROUGHNESS_FIXGL, r)        r  in [0,1], default 0.5
 *   glMaterialf(face, GL_METALNESS_FIXGL, m)        m  in [0,1], default 0
 *   glMaterialf(face, GL_DIELECTRIC_F0_FIXGL, f0)   f0 in [0,1], default 0.04
 * GGX distribution, Schlick's Fresnel, Smith-Schlick-GGX geometry; per
 * vertex under GL_SMOOTH / GL_FLAT, per fragment under GL_PHONG_WIN.
 * The exact equations: include/fixgl/shading.md. */
#ifndef GL_FIXGL_cook_torrance
#define GL_FIXGL_cook_torrance 1
#define GL_REFLECTANCE_MODEL_FIXGL   0x6F00
#define GL_BLINN_PHONG_FIXGL         0x6F01
#define GL_COOK_TORRANCE_FIXGL       0x6F02
#define GL_ROUGHNESS_FIXGL           0x6F03
#define GL_METALNESS_FIXGL           0x6F04
#define GL_DIELECTRIC_F0_FIXGL       0x6F05
#endif

/* The library's version as "major.minor.patch". */
const char *fixglGetVersion(void);

/* ---- Counters for the benchmark's breakdown of a frame -------------------
 * Per context (the current one), off by default; while off they cost one
 * predicted branch per vertex batch and per primitive.  Call them outside
 * glBegin/glEnd: each first draws the vertices batched so far (under the
 * setting they were batched with).
 *
 *   fixglStats(1)        start counting (the counters keep their values)
 *   fixglStats(0)        stop counting
 *   fixglResetStats()    all counters to 0
 *   fixglGetStats(&s)    read them
 *
 * Times are CLOCK_MONOTONIC nanoseconds.  The raster core counts the
 * fragments it shades (covered pixels inside the draw region: viewport
 * and scissor box) and its time in primitive setup and in coverage plus
 * the fragment stage; the vertex stage is everything else in a vertex
 * batch (state validation, transform, lighting, clipping, primitive
 * assembly).  glClear and glFinish's copy are in none of them.  So
 * raster_ns / fragments is the time per shaded fragment, and
 * vertex_ns + setup_ns + raster_ns = batch_ns, plus the raster core's time
 * in primitives drawn outside a vertex batch (pixel rectangles), if any. */
struct fixgl_stats {
   unsigned long long fragments;   /* fragments shaded */
   unsigned long long setup_ns;    /* primitive setup (raster core; summed
                                    * over the rasterizing threads) */
   unsigned long long raster_ns;   /* coverage and fragments (raster core;
                                    * summed over the threads) */
   unsigned long long vertex_ns;   /* vertex stage: the vertex batches' wall
                                    * time minus the rasterization in them */
   unsigned long long batch_ns;    /* wall time of the vertex batches and of
                                    * the rasterization of their primitives */
   unsigned long long batches;     /* vertex batches drawn */
   int enabled;                    /* fixglStats' current setting */
};

void fixglStats(int enable);
void fixglResetStats(void);
void fixglGetStats(struct fixgl_stats *out);

#ifdef __cplusplus
}
#endif

#endif /* FIXGL_FIXGL_H */
