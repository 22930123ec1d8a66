/*
 * llvmpipe's float SoA sampling path and its general level-of-detail
 * selection (LOD bias, MIN_LOD/MAX_LOD): the `texsoa` work fills this file
 * in (see r_state.h "textures" for the dispatch contract).
 *
 * PLACEHOLDER until then: the lookup is done by the AoS path with the fast
 * LOD, wraps other than REPEAT mapped to CLAMP_TO_EDGE; the result differs
 * from the oracle's for these samplers.
 *
 * Pieces of r_tex.c to build on: r_tex_rho (lp_build_rho, the same for
 * both LOD paths) and r_tex_filter_aos (the AoS filtering given minify,
 * the levels and the mip weight: llvmpipe keeps REPEAT / CLAMP_TO_EDGE
 * samplers on the AoS path whatever their LOD path).
 */
#include "r_state.h"

void r_tex_sample_soa(const struct r_texture *t, const float c[3], const float quad[3][3],
                      float out[4])
{
   struct r_texture aos = *t;
   if (aos.wrap_s != R_WRAP_REPEAT)
      aos.wrap_s = R_WRAP_CLAMP_TO_EDGE;
   if (aos.wrap_t != R_WRAP_REPEAT)
      aos.wrap_t = R_WRAP_CLAMP_TO_EDGE;
   aos.soa = false;
   r_tex_sample_aos(&aos, c, quad, out);
}
