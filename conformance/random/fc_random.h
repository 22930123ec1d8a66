/* fc_random.h - random differential scenes.  A scene is a case whose table
 * entry and GL call sequence are a pure function of (seed, index): both
 * renderers issue exactly the same calls and nothing depends on GL results.
 * Scene names are "random/s<seed>-i<index>" (tag random); the lit family
 * (fc_random_lit.c) is "random-lit/s<seed>-i<index>" (tag random-lit). */
#ifndef FC_RANDOM_H
#define FC_RANDOM_H

#include "fc_case.h"

#include <stdint.h>

#define FC_RANDOM_NAME_MAX 64

/* Parses a scene name; returns 1 on success. */
int fc_random_parse(const char *name, uint64_t *seed, uint32_t *index);

/* Fills the table entry of scene (seed, index); name must hold
 * FC_RANDOM_NAME_MAX bytes and outlives the entry. */
void fc_random_case(uint64_t seed, uint32_t index, fc_case *out, char *name);

/* The same for the lit scenes. */
int fc_random_lit_parse(const char *name, uint64_t *seed, uint32_t *index);
void fc_random_lit_case(uint64_t seed, uint32_t index, fc_case *out, char *name);

/* The same for the raster scenes (points, lines, fragment operations). */
int fc_random_raster_parse(const char *name, uint64_t *seed, uint32_t *index);
void fc_random_raster_case(uint64_t seed, uint32_t index, fc_case *out, char *name);

/* The same for the texture scenes (textures, texture state, pixel path). */
int fc_random_tex_parse(const char *name, uint64_t *seed, uint32_t *index);
void fc_random_tex_case(uint64_t seed, uint32_t index, fc_case *out, char *name);

/* The same for the shading-extension scenes (reference scenes: tags and
 * colour tolerance depend on the scene, see fc_random_shading.c). */
int fc_random_shading_parse(const char *name, uint64_t *seed, uint32_t *index);
void fc_random_shading_case(uint64_t seed, uint32_t index, fc_case *out, char *name);

#endif
