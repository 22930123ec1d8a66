/*
 * The textured block kernels of the bilinear REPEAT lookup (r_block_tex_avx2.c,
 * its part 2): a translation unit of their own, compiled in parallel
 * with the others.
 */
#define R_BLOCK_TEX_PART 2
#include "r_block_tex_avx2.c"
