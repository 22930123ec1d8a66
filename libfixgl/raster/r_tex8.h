/*
 * Texture lookups 8 fragments at a time (issue 16 §2): the lanes of
 * llvmpipe's 8-wide fragment vector, a 4x2 half of a 4x4 block in
 * row-major order.  Lane i is pixel (x0 + (i & 3), y0 + (i >> 2)), x0 a
 * multiple of 4 and y0 even, so the vector holds two 2x2 quads side by
 * side:
 *   quad A = lanes {0, 1, 4, 5}: top-left 0, top-right 1, bottom-left 4
 *   quad B = lanes {2, 3, 6, 7}: top-left 2, top-right 3, bottom-left 6
 * Every lane's coordinate is computed, covered or not (as in the oracle),
 * since the level of detail of a quad comes from its TL, TR and BL lanes
 * (ORACLE-NOTES.md "Texture sampling: level of detail per quad").
 *
 * r_tex_sample8: c[k][i] is coordinate k (s, t, r after the projective
 * divide, exactly as r_tex_project computes it) of lane i; out[k][i] is
 * channel k of lane i's texel as floats, bit for bit what the scalar path
 * gives each lane:
 *  - a texture without `soa`: r_tex_lod_aos of the lane's quad (its TL,
 *    TR, BL coordinates), then r_tex_filter_aos with the lane's own
 *    coordinate (r_tri.c fill_quad + r_frag.c tex_color);
 *  - a texture with `soa`: r_tex_sample with the lane's quad's three
 *    coordinates and, when r_tex_need_pair, those of the other quad.
 * The implementation is chosen once, at the first call: the AVX2 + FMA
 * kernel (r_tex_avx2.c) when the library was built with it and the CPU
 * has both, else the portable one (r_tex8.c: the scalar functions lane by
 * lane).  The AVX2 kernel samples itself the textures r_tex8_fast accepts
 * and hands the others to the portable version.
 */
#ifndef FGL_R_TEX8_H
#define FGL_R_TEX8_H

#include <stdbool.h>

#include "r_state.h"

/* lanes of the fragment vector */
#define R_TEX8_LANES 8

void r_tex_sample8(const struct r_texture *t, const float c[3][8], float out[4][8]);

/* The implementations, for the unit test and the benchmark. */
typedef void (*r_tex_sample8_fn)(const struct r_texture *t, const float c[3][8],
                                 float out[4][8]);
void r_tex_sample8_portable(const struct r_texture *t, const float c[3][8], float out[4][8]);
/* The AVX2 kernel, or NULL when the library was built without it or the
 * CPU lacks AVX2 or FMA (__builtin_cpu_supports). */
r_tex_sample8_fn r_tex_sample8_avx2_fn(void);

/* Whether the AVX2 kernel samples t itself (else it calls the portable
 * version): no `soa`, 1D or 2D, RGBA8 levels (always, without `soa`),
 * wraps REPEAT (pot or npot) or CLAMP_TO_EDGE on the used axes; any
 * image filters, any mip filter. */
bool r_tex8_fast(const struct r_texture *t);

#endif
