/*
 * The raster core's view of the world.  It knows nothing of GL: the
 * context's validation pass (state.c) translates GL state into an r_state,
 * and the vertex stage hands it r_vertex triangles in window coordinates.
 *
 * Coordinates are y-down, as in the oracle (ORACLE-NOTES.md "Window
 * coordinates and the y-down buffer"): row 0 of every buffer is the top row
 * of the image.
 */
#ifndef FGL_R_STATE_H
#define FGL_R_STATE_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>
#include <time.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "math/m_shade.h"

#define R_MAX_TEX_UNITS 8
#define R_MAX_ATTRIBS (9 + R_MAX_TEX_UNITS)

/* Varying slots: the colour written to the buffer, the secondary colour
 * the fragment stage adds to it (separate specular), their back-face
 * versions for two-sided lighting, the fog coordinate (x; y, z, w are
 * 0, 0, 1 as the oracle's vertex program writes them), and the coverage
 * coordinates of the draw module's smooth point and line quads
 * (tnl/t_linepoint.c; written after clipping, so never part of
 * num_attribs), then the texture coordinates of units 0..7 (unit 0's
 * slot is also filled for GL_FEEDBACK, outside num_attribs), then the
 * two varyings of GL_PHONG_WIN (include/fixgl/shading.md): the eye-space
 * normal as lighting transforms it (x, y, z; w is the face of an
 * unfilled polygon's lines and points, 1 front, 0 back, read from the
 * vertex only) and the eye position (x, y, z, w as the modelview gives
 * it).  Only the colour slots are clamped to [0,1]. */
enum {
   R_ATTR_COLOR0,
   R_ATTR_COLOR1,
   R_ATTR_BCOLOR0,
   R_ATTR_BCOLOR1,
   R_ATTR_FOG,
   R_ATTR_AA,
   R_ATTR_TEX0,      /* R_ATTR_TEX0 + u: texture unit u */
   R_ATTR_NORMAL = R_ATTR_TEX0 + R_MAX_TEX_UNITS,
   R_ATTR_EYEPOS,
   /* a point's size per vertex (x; r_rast_state.point_size_per_vertex):
    * the vertex program's PSIZ output under distance attenuation, read by
    * the point rasterizers only, never interpolated */
   R_ATTR_PSIZE,
};
_Static_assert(R_ATTR_PSIZE < R_MAX_ATTRIBS, "the point size has a slot");

/* Inputs of the fragment shader, after the back-face colours have been
 * chosen: the colour, the secondary colour, the fog coordinate, the
 * smooth point/line coverage coordinates, the texture coordinates
 * (s, t, r, q as interpolated), and GL_PHONG_WIN's eye-space normal and
 * eye position (r_fragment_phong lights the fragment with them). */
enum {
   R_FS_COLOR0,
   R_FS_COLOR1,
   R_FS_FOG,
   R_FS_AA,          /* the aapoint/aaline generic input */
   R_FS_TEX0,        /* R_FS_TEX0 + u: texture unit u */
   R_FS_NORMAL = R_FS_TEX0 + R_MAX_TEX_UNITS,
   R_FS_EYEPOS,
   R_FS_NUM_INPUTS,
};


/* A float's bits and back (memcpy: the same bits, no aliasing) */
static inline uint32_t r_f2u(float f)
{
   uint32_t u;
   memcpy(&u, &f, 4);
   return u;
}

static inline float r_u2f(uint32_t u)
{
   float f;
   memcpy(&f, &u, 4);
   return f;
}

/* The vertex slot that feeds fragment-shader input `input`, for a front-
 * or back-facing primitive (lp_state_setup.c:lp_twoside swaps the colour
 * inputs for back faces). */
static inline int r_fs_slot(int input, bool back)
{
   switch (input) {
   case R_FS_COLOR0: return back ? R_ATTR_BCOLOR0 : R_ATTR_COLOR0;
   case R_FS_COLOR1: return back ? R_ATTR_BCOLOR1 : R_ATTR_COLOR1;
   case R_FS_FOG:    return R_ATTR_FOG;
   case R_FS_AA:     return R_ATTR_AA;
   case R_FS_NORMAL: return R_ATTR_NORMAL;
   case R_FS_EYEPOS: return R_ATTR_EYEPOS;
   default:          return R_ATTR_TEX0 + (input - R_FS_TEX0);
   }
}

/* Depth/stencil buffer layouts, as the OSMesa oracle allocates them. */
enum r_zs_format {
   R_ZS_NONE,
   R_ZS_Z16,       /* uint16_t depth */
   R_ZS_Z24X8,     /* uint32_t, depth in bits 0..23, bits 24..31 zero */
   R_ZS_Z24S8,     /* uint32_t, depth in bits 0..23, stencil in 24..31 */
   R_ZS_S8,        /* uint8_t stencil only */
   R_ZS_Z32,       /* uint32_t depth, all 32 bits (GLX's Z32_UNORM configs) */
};

/* Comparison functions, in GL's order (GL_NEVER + n). */
enum r_func {
   R_NEVER, R_LESS, R_EQUAL, R_LEQUAL, R_GREATER, R_NOTEQUAL, R_GEQUAL, R_ALWAYS,
};

/* The fog blend of the fixed-function fragment program (GL_FOG_MODE). */
enum r_fog_mode {
   R_FOG_NONE,
   R_FOG_LINEAR,
   R_FOG_EXP,
   R_FOG_EXP2,
};

/* Stencil operations (lp_bld_depth.c lp_build_stencil_op_single). */
enum r_stencil_op {
   R_STENCIL_KEEP, R_STENCIL_ZERO, R_STENCIL_REPLACE, R_STENCIL_INCR,
   R_STENCIL_DECR, R_STENCIL_INCR_WRAP, R_STENCIL_DECR_WRAP, R_STENCIL_INVERT,
};

/* Blend equations and factors of GL 1.x (gallium's PIPE_BLEND_* and
 * PIPE_BLENDFACTOR_* subsets). */
enum r_blend_eq {
   R_BLEND_ADD, R_BLEND_SUBTRACT, R_BLEND_REVERSE_SUBTRACT, R_BLEND_MIN, R_BLEND_MAX,
};

enum r_blend_factor {
   R_BF_ZERO, R_BF_ONE,
   R_BF_SRC_COLOR, R_BF_INV_SRC_COLOR, R_BF_SRC_ALPHA, R_BF_INV_SRC_ALPHA,
   R_BF_DST_COLOR, R_BF_INV_DST_COLOR, R_BF_DST_ALPHA, R_BF_INV_DST_ALPHA,
   R_BF_SRC_ALPHA_SATURATE,
   R_BF_CONST_COLOR, R_BF_INV_CONST_COLOR, R_BF_CONST_ALPHA, R_BF_INV_CONST_ALPHA,
};

/* Coverage lowering of the fragment shader for the draw module's smooth
 * point and line quads (r_aa.c). */
enum r_aa_mode {
   R_AA_NONE,
   R_AA_POINT,       /* nir_lower_aapoint_fs */
   R_AA_LINE,        /* nir_lower_aaline_fs */
};

/* ---- textures (r_tex.c, r_tex_soa.c) ----------------------------------
 *
 * A texture as the sampler sees it: its levels as RGBA8 texels (already
 * expanded from the base format, row 0 at t = 0), the gallium sampler state
 * the state tracker derives from the GL object and unit
 * [S: state_tracker/st_atom_sampler.c:st_convert_sampler,
 * st_atom_texture.c], and which of llvmpipe's two sampling paths the
 * oracle takes for it [S: gallivm/lp_bld_sample_soa.c:
 * lp_build_sample_soa_code, use_aos]:
 *  - the fixed-point AoS path (r_tex.c): 8-bit unorm texels (always, here)
 *    with wrap modes REPEAT or CLAMP_TO_EDGE on every used axis;
 *  - the float SoA path (r_tex_soa.c, owned by the `texsoa` work): any
 *    other wrap mode (GL_CLAMP, CLAMP_TO_BORDER, MIRRORED_REPEAT, the
 *    MIRROR_CLAMP family); min != mag filters there decide per 8 pixels
 *    (r_fs_quad.pair).
 * The level of detail is computed by one of two paths as well
 * [S: gallivm/lp_bld_sample.c:lp_build_lod_selector]: the fast one when the
 * sampler has no LOD bias and no min/max LOD clamp (r_tex.c), the general
 * one otherwise (r_tex_soa.c).  `soa` is set by state.c when either the
 * sampling or the LOD needs the general path; r_tex_sample then hands the
 * whole lookup to r_tex_sample_soa. */
#define R_MAX_TEX_LEVELS 15

enum r_tex_filter { R_TEX_NEAREST, R_TEX_LINEAR };
enum r_tex_mip { R_MIP_NONE, R_MIP_NEAREST, R_MIP_LINEAR };
enum r_tex_wrap {
   R_WRAP_REPEAT, R_WRAP_CLAMP_TO_EDGE,          /* the AoS path */
   R_WRAP_CLAMP, R_WRAP_CLAMP_TO_BORDER, R_WRAP_MIRRORED_REPEAT,
   R_WRAP_MIRROR_CLAMP, R_WRAP_MIRROR_CLAMP_TO_EDGE, R_WRAP_MIRROR_CLAMP_TO_BORDER,
};

struct r_tex_level {
   int width, height;            /* height 1 for 1D */
   int depth;                    /* 1 for 1D and 2D */
   const uint8_t *data;          /* width * height * depth RGBA8 texels,
                                  * slice z at z * width * height */
   /* a format of other than 8 bits per channel (float path only): the
    * stored values, four uint16_t per texel, channel c an integer of
    * store_bits[c] bits (0: a constant 0 or 1) read as
    * store[c] * store_scale[c] (NULL for the 8-bit formats) */
   const uint16_t *store;
   uint8_t store_bits[4];
   float store_scale[4];
   /* a depth texture (r_texture.depth_bits): width * height depth values
    * of depth_bits bits (r_tex_depth_value), else NULL */
   const uint32_t *zvalues;
};

struct r_texture {
   int dims;                     /* 1 (GL_TEXTURE_1D), 2 (GL_TEXTURE_2D) or
                                  * 3 (GL_TEXTURE_3D: the reference kernels
                                  * only, r_tex8_fast refuses it) */
   int first_level, last_level;  /* BaseLevel .. _MaxLevel */
   struct r_tex_level level[R_MAX_TEX_LEVELS];
   /* the resource's level-0 size is a power of two (the REPEAT wrap of
    * every level uses the pot or npot code by it; lp_bld_sample.c
    * lp_sampler_static_texture_state pot_width/pot_height) */
   bool pot_s, pot_t, pot_r;
   enum r_tex_filter min_img, mag_img;
   enum r_tex_mip mip;
   enum r_tex_wrap wrap_s, wrap_t, wrap_r;   /* wrap_r: 3D only */
   float border_color[4];        /* for r_tex_soa.c */
   float lod_bias;               /* object + unit bias (st_convert_sampler) */
   float min_lod, max_lod;       /* GL_TEXTURE_MIN_LOD / MAX_LOD */
   bool soa;                     /* the lookup goes to r_tex_sample_soa */
   /* for r_tex_soa.c: use_aos is false (the float SoA sampling); the
    * channels the border colour replaces (bit c: channel c; the format's
    * channels); lp_sampler_static_sampler_state's LOD flags */
   bool float_path;
   uint8_t border_mask;
   bool lod_bias_non_zero, apply_min_lod, apply_max_lod, min_max_lod_equal;
   /* a depth texture (GL_DEPTH_COMPONENT; main/texdepth.c
    * fgl_update_texture_depth, sampled on the float path only,
    * r_tex_soa.c): the bits of its format (16, 24, 32; 0 for a colour
    * texture), the shadow comparison (compare: GL_COMPARE_R_TO_TEXTURE;
    * compare_func: enum r_func, PIPE_FUNC_* order) and the
    * sampler view's swizzle of GL_DEPTH_TEXTURE_MODE (depth_swizzle[c]:
    * R_SWZ_X the value, R_SWZ_0, R_SWZ_1) */
   uint8_t depth_bits;
   bool compare;
   uint8_t compare_func;
   uint8_t depth_swizzle[4];
   /* GL_TEXTURE_CUBE_MAP (r_tex_cube.c; ORACLE-NOTES.md "Cube maps"):
    * R_CUBE_MAP for the cube map, which state.c marks `soa` so that every
    * lookup reaches r_tex_sample (the fast kernels refuse it at
    * validation); r_tex_sample selects each fragment's face and samples
    * a copy of this struct, R_CUBE_FACE, whose levels are that face's
    * (a 2D texture with CLAMP_TO_EDGE wraps, `soa` as face_soa, its rho
    * the cube's: r_tex_cube_rho).  Fields after `cube` are not copied. */
   uint8_t cube;
   bool face_soa;
   const uint8_t *cube_data[6][R_MAX_TEX_LEVELS];     /* +X, -X, +Y, -Y, +Z, -Z */
   const uint16_t *cube_store[6][R_MAX_TEX_LEVELS];
};
enum { R_CUBE_NONE, R_CUBE_MAP, R_CUBE_FACE };
enum { R_SWZ_X, R_SWZ_0, R_SWZ_1 };

/* A stored depth value as llvmpipe's sampler reads it [S: gallivm/
 * lp_bld_conv.c:lp_build_unsigned_norm_to_float]: up to 24 bits
 * (float)z * (float)(1 / (2^bits - 1)); 32 bits through the top 23, as the
 * mantissa of 1.0 + x, minus 1, times 2^23 / (2^23 - 1). */
static inline float r_tex_depth_value(uint32_t z, int bits)
{
   if (bits == 32) {
      const uint32_t u = (z >> 9) | 0x3f800000u;
      float f;
      memcpy(&f, &u, 4);
      return (f - 1.0f) * (float)(8388608.0 / 8388607.0);
   }
   return (float)z * (bits == 16 ? (float)(1.0 / 65535.0) : (float)(1.0 / 16777215.0));
}

/* Texture combiner state of one unit after Mesa derives it from the env
 * mode and the base format [S: main/texstate.c:calculate_derived_texenv,
 * update_tex_combine, pack_tex_combine] (GL_COMBINE takes the unit's own
 * combiner state).  Modes, sources and operands are Mesa's TEXENV_*
 * values [S: main/mtypes.h, TEXENV_MODE_*, TEXENV_SRC_*,
 * TEXENV_OPR_*]. */
enum r_comb_mode {
   R_COMB_REPLACE, R_COMB_MODULATE, R_COMB_ADD, R_COMB_ADD_SIGNED,
   R_COMB_INTERPOLATE, R_COMB_SUBTRACT, R_COMB_DOT3_RGB, R_COMB_DOT3_RGBA,
   R_COMB_DOT3_RGB_EXT, R_COMB_DOT3_RGBA_EXT, R_COMB_MODULATE_ADD_ATI,
   R_COMB_MODULATE_SIGNED_ADD_ATI, R_COMB_MODULATE_SUBTRACT_ATI,
   R_COMB_ADD_PRODUCTS_NV, R_COMB_ADD_PRODUCTS_SIGNED_NV,
};
enum r_comb_src {
   R_SRC_TEXTURE, R_SRC_TEXTURE0,  /* R_SRC_TEXTURE0 + n: GL_TEXTUREn */
   R_SRC_PREVIOUS = R_SRC_TEXTURE0 + R_MAX_TEX_UNITS,
   R_SRC_PRIMARY_COLOR, R_SRC_CONSTANT, R_SRC_ZERO, R_SRC_ONE,
};
enum r_comb_operand {
   R_OPR_COLOR, R_OPR_ONE_MINUS_COLOR, R_OPR_ALPHA, R_OPR_ONE_MINUS_ALPHA,
};

struct r_tex_combine {
   uint8_t mode_rgb, mode_a;     /* enum r_comb_mode */
   uint8_t shift_rgb, shift_a;   /* log2 of RGB_SCALE / ALPHA_SCALE */
   uint8_t nargs_rgb, nargs_a;
   uint8_t src_rgb[4], opr_rgb[4], src_a[4], opr_a[4];
   /* r_tex_combine_simplify (r_frag.c): the environment is, on every
    * channel c, one argument (REPLACE) or the product of two (MODULATE),
    * without saturation or scale; simple_arg[c][i] = R_SIMPLE_* source
    * * 8 + 4 for 1 - x + the component read (0..3) */
   bool simple;
   uint8_t simple_nargs[4];
   uint8_t simple_arg[4][2];
   /* the common forms of the RGB channels and of alpha (enum r_simple_fn):
    * the texture, PREVIOUS, or their product, in that order or the other,
    * channel by channel; R_SIMPLE_FN_ARGS: by simple_arg */
   uint8_t simple_fn_rgb, simple_fn_a;
};
enum r_simple_src {
   R_SIMPLE_TEXTURE, R_SIMPLE_PREVIOUS, R_SIMPLE_PRIMARY, R_SIMPLE_CONSTANT,
   R_SIMPLE_ZERO, R_SIMPLE_ONE,
};
enum r_simple_fn {
   R_SIMPLE_FN_ARGS, R_SIMPLE_FN_T, R_SIMPLE_FN_P, R_SIMPLE_FN_TP, R_SIMPLE_FN_PT,
};
/* Sets k->simple and the simple_* fields from the rest of k (unit: the
 * unit k belongs to). */
void r_tex_combine_simplify(struct r_tex_combine *k, int unit);

struct r_tex_unit {
   struct r_texture tex;
   struct r_tex_combine comb;
   float env_color[4];           /* GL_TEXTURE_ENV_COLOR, clamped */
};

/* The texture coordinates (s, t, r, q as interpolated) of the pixels of a
 * fragment's 2x2 quad that the level of detail needs: quads are aligned to
 * even y-down coordinates and the derivatives come from the quad's top-left
 * pixel, whether or not the other pixels are covered
 * [S: gallivm/lp_bld_quad.c:lp_build_packed_ddx_ddy_twocoord,
 * lp_bld_sample.c:lp_build_rho] (ORACLE-NOTES.md "Texture sampling: level
 * of detail per quad"). */
enum { R_QUAD_TL, R_QUAD_TR, R_QUAD_BL };
struct r_fs_quad {
   float tex[R_MAX_TEX_UNITS][3][4];   /* [unit][R_QUAD_*][s, t, r, q] */
   /* the same for the other quad of the fragment's 8-pixel vector (the
    * quads at x & ~3 and (x & ~3) + 2 of a 4x4 block are shaded together
    * [S: llvmpipe/lp_bld_interp.c, quad_offset_x/y]), filled only when
    * r_state.tex_pair is set (r_tex_soa.c) */
   float pair[R_MAX_TEX_UNITS][3][4];
   /* the quad's bottom-right pixel (filled only when r_fs_state.tex_cube
    * is set) and the fragment's place in its quad (bit 0: right column,
    * bit 1: bottom row): a mipmapped cube map takes each pixel's own
    * derivatives (r_tex_cube.c) */
   float br[R_MAX_TEX_UNITS][4];
   float pair_br[R_MAX_TEX_UNITS][4];   /* the pair quad's, with `pair` */
   unsigned pos;
};

/* A texture lookup (r_tex.c): the coordinate c (s, t, r after the
 * projective divide) of the fragment, those of its quad's top-left,
 * top-right and bottom-left pixels (for the level of detail), to the
 * texel as floats (t * (1/255) per channel for unorm8).  pair: the same
 * three coordinates of the other quad of the 8-pixel vector, needed (and
 * given, else NULL) when r_tex_need_pair(t). */
void r_tex_sample(const struct r_texture *t, const float c[3], const float quad[3][3],
                  const float (*pair)[3], float out[4]);
/* The AoS path with the fast LOD (r_tex.c), whatever `soa` says. */
void r_tex_sample_aos(const struct r_texture *t, const float c[3], const float quad[3][3],
                      float out[4]);
/* The fast level-of-detail selection's results (r_tex.c
 * r_tex_lod_aos): they depend on the quad's coordinates alone, so every
 * pixel of a 2x2 quad shares them (llvmpipe computes one LOD per quad,
 * ORACLE-NOTES.md "Texture sampling: level of detail per quad") and the
 * primitives compute them once per quad. */
struct r_tex_lod {
   bool minify;                  /* the min image filter (else mag) */
   int level0, level1;           /* absolute level indices */
   int weight;                   /* 8-bit mip lerp weight */
};
/* lp_build_lod_selector's fast path and lp_build_{nearest,linear}_mip_levels
 * on a quad's projected coordinates (TL, TR, BL): r_tex_sample_aos is
 * r_tex_lod_aos, then r_tex_filter_aos with its results. */
void r_tex_lod_aos(const struct r_texture *t, const float quad[3][3], struct r_tex_lod *lod);
/* The projective divide of a lookup's coordinate (s, t, r, q) to
 * (s, t, r) [S: ff_fragment_shader.cpp:load_texture]: vec coord * frcp(q),
 * the reciprocal a true divide in gallivm. */
static inline void r_tex_project(const float v[4], float out[3])
{
   const float r = 1.0f / v[3];
   out[0] = v[0] * r;
   out[1] = v[1] * r;
   out[2] = v[2] * r;
}
/* lp_build_rho of a quad's projected coordinates (TL, TR, BL) with the
 * size of the first level: squared for 2D and 3D (the r term added last),
 * max(|ds|) * W for 1D (r_tex.c), shared by both LOD paths. */
float r_tex_rho(const struct r_texture *t, const float q[3][3]);
/* The cube map lookup (r_tex_cube.c): the face and face coordinates of
 * c, then the lookup of that face; q4: the coordinates (after the
 * projective divide) of the fragment's quad, TL, TR, BL, BR, pos the
 * fragment's place in it (bit 0 the right column, bit 1 the bottom row),
 * p4 those of the other quad of its 8-pixel vector (r_tex_need_pair) or
 * NULL. */
void r_tex_sample_cube(const struct r_texture *t, const float c[3], const float q4[4][3],
                       unsigned pos, const float (*p4)[3], float out[4]);
/* lp_build_rho of a cube map (r_tex_cube.c): q is the derivative form
 * r_tex_sample_cube passes (deriv_form), the (s, t, r) of the pixel
 * whose LOD it is and its x and y derivatives; squared, the first
 * level's size applied. */
float r_tex_cube_rho(const struct r_texture *t, const float q[3][3]);

/* The AoS filtering alone, given the LOD selector's results (for the
 * general LOD path with REPEAT / CLAMP_TO_EDGE, which llvmpipe still
 * filters on the AoS path): minify picks the min or mag image filter
 * (when they differ), level0/level1 are absolute level indices and weight
 * the 8-bit mip lerp weight (R_MIP_LINEAR; 0 for one level). */
void r_tex_filter_aos(const struct r_texture *t, const float c[3], bool minify,
                      int level0, int level1, int weight, float out[4]);
/* The dispatch point of the float SoA path and the general LOD path
 * (r_tex_soa.c): called by r_tex_sample for a texture with `soa` set. */
void r_tex_sample_soa(const struct r_texture *t, const float c[3], const float quad[3][3],
                      const float (*pair)[3], float out[4]);
/* The float path (r_tex_soa.c) of one pixel whose LOD comes from quad,
 * min != mag decided over it and the n_others other LODs of its 8-pixel
 * vector (r_tex_cube.c: a LOD per pixel). */
void r_tex_sample_float_lods(const struct r_texture *t, const float c[3],
                             const float quad[3][3], const float (*const *others)[3],
                             int n_others, float out[4]);
/* The float path with different min and mag filters decides per 8
 * pixels (r_tex_soa.c): the lookup needs the pair quad. */
static inline bool r_tex_need_pair(const struct r_texture *t)
{
   return t->soa && t->float_path && t->min_img != t->mag_img;
}

/* A post-transform vertex: window position (x, y y-down, z in [0,1] before
 * clamping, w = 1/clip_w) and its varyings. */
struct r_vertex {
   float pos[4];
   float attr[R_MAX_ATTRIBS][4];
};

/* A triangle's block kernel (r_kernel.h): shades every covered pixel of
 * the triangle's box. */
struct r_state;
struct r_tri_setup;
struct r_tri_cover;
typedef void (*r_tri_kernel)(const struct r_state *rs, const struct r_tri_setup *ts,
                             const struct r_tri_cover *cv);

/* Counters of the raster core, for the benchmark's breakdown of a frame
 * (fixglGetStats): r_state.stats is NULL unless a program asked for them,
 * and the primitives then add what they did and the time it took. */
struct r_stats {
   uint64_t fragments;          /* pixels shaded: covered, inside the region */
   uint64_t setup_ns;           /* primitive setup: coverage planes, inputs */
   uint64_t raster_ns;          /* coverage and fragments after the setup */
};

/* The clock of the counters (read only when r_state.stats is set). */
static inline uint64_t r_stats_now(void)
{
   struct timespec ts;
   clock_gettime(CLOCK_MONOTONIC, &ts);
   return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

/* ---- the state objects ------------------------------------------------
 *
 * What the raster core needs of the GL state, in immutable objects in the
 * manner of gallium's constant state objects (CSOs), one per group that
 * changes together.  The validation pass (state.c) builds each from the
 * GL state of its dirty groups only and looks it up in the context's
 * cache (r_cso_lookup, keyed by the object's bytes), so a scene that
 * switches between a few states builds each once; a draw's r_state
 * (below) points to one object of each kind.  An object is never written
 * after the cache returns it: any number of r_states, and threads, may
 * read it.  The builders zero an object before filling it, so equal
 * states are equal bytes, padding included. */

/* The framebuffer target. */
/* A wide colour buffer: OSMesa's GL_UNSIGNED_SHORT and GL_FLOAT buffers,
 * which the oracle renders into as R16G16B16A16_UNORM and
 * R32G32B32A32_FLOAT targets (ORACLE-NOTES.md "OSMesa contexts and
 * buffers"): four uint16_t or four floats per pixel, RGBA, y-down. */
enum r_wide_format { R_WIDE_NONE, R_WIDE_UNORM16, R_WIDE_FLOAT };

struct r_fb_state {
   uint8_t *color;              /* RGBA8 (NULL: no colour buffer) */
   void *zs;
   enum r_zs_format zs_format;
   int width, height;
   /* a wide target (else R_WIDE_NONE, NULL): the colour as the oracle
    * keeps it, written by the reference kernels' r_fragment_ops (no block
    * kernel is chosen for it) and by r_clear_wide; `color` then holds
    * its RGBA8 conversion for the readers of 8-bit pixels */
   enum r_wide_format wide_format;
   void *wide;
};

/* r_clear.c: the rectangle of fb's wide target cleared to `rgba` (as
 * st_Clear's util_pack_color packs it: unclamped floats, or unorm16 by
 * util_iround) */
void r_clear_wide_rect(const struct r_fb_state *fb, int x0, int y0, int x1, int y1,
                       const float rgba[4]);

/* The rasterizer: facing, culling, offset, stipple, point and line size
 * (st_atom_rasterizer.c, llvmpipe_create_rasterizer_state). */
struct r_rast_state {
   bool twoside;                /* back-facing triangles use the BCOLOR slots */
   bool ccw_is_front;           /* a positive snapped area is front-facing */
   bool cull_front, cull_back;  /* faces not drawn */
   /* polygon offset of llvmpipe's triangle setup (lp_do_offset_tri): added
    * to every fragment's depth; both 0 when the draw pipeline applies the
    * offset instead, or no GL_POLYGON_OFFSET_* is enabled */
   float offset_units;          /* GL units * mrd * 2 */
   float offset_scale;          /* GL factor */
   /* polygon stipple (draw's pstipple stage: a fragment kill before any
    * per-fragment operation); row i applies to y-down pixel rows i mod 32,
    * bit 31 - (x mod 32) to columns x mod 32 */
   bool stipple;
   uint32_t stipple_rows[32];
   /* points and lines, as the state tracker clamps them
    * (st_atom_rasterizer.c): size in [0, 255], width in [1, 255] */
   float point_size;
   float line_width;
   /* each point's size is its vertex's R_ATTR_PSIZE (the vertex program
    * computes it: glPointParameter's distance attenuation), point_size
    * unused */
   bool point_size_per_vertex;
   /* point sprites (GL_POINT_SPRITE: the state tracker's
    * point_quad_rasterization): a point is llvmpipe's square of sub-pixel
    * edges (r_point.c sprite) instead of the legacy whole-pixel one, and
    * the texture coordinates of the units in sprite_coord_enable (bit u:
    * unit u, GL_COORD_REPLACE) are its planes (s, t, 0, 1), t growing down
    * the y-down buffer (ARB_point_sprite's upper-left origin) */
   bool point_sprite;
   uint8_t sprite_coord_enable;
};

/* The fragment inputs of a line or triangle that read (0, 0, 0, 0): the
 * texture coordinates of the units whose coordinates sprites replace
 * (sprite_coord_enable, set only with point_sprite).  llvmpipe links no
 * vertex output to them, whatever the primitive (ORACLE-NOTES.md "Point
 * sprites"; probe p_sprites); in ts (r_tri_setup) after its setup. */
struct r_tri_setup;
void r_zero_sprite_inputs(const struct r_rast_state *rast, struct r_tri_setup *ts);

/* A point's size: its vertex's or the rasterizer's */
static inline float r_point_size(const struct r_rast_state *rast, const float psize[4])
{
   return rast->point_size_per_vertex ? psize[0] : rast->point_size;
}

/* Depth, stencil and alpha test, in the order r_fragment_ops applies
 * them. */
struct r_dsa_state {
   bool alpha_test;
   enum r_func alpha_func;
   uint8_t alpha_ref;           /* clamped, RNE(ref * 255) */
   bool alpha_test_float;       /* buffer not an rgba8 variant (OSMESA_RGB):
                                 * float compare with the unclamped ref */
   float alpha_ref_float;

   bool stencil_test;           /* only with a stencil buffer */
   enum r_func stencil_func;
   uint8_t stencil_ref;         /* clamped to [0, 255] */
   uint8_t stencil_valuemask, stencil_writemask;
   enum r_stencil_op stencil_fail, stencil_zfail, stencil_zpass;

   bool depth_test;             /* only with a depth buffer */
   enum r_func depth_func;
   bool depth_write;
};

/* Blending, logic op and colour mask. */
struct r_blend_state {
   bool enable;                 /* blending; off when the logic op is on */
   enum r_blend_eq blend_eq;
   enum r_blend_factor blend_src, blend_dst;  /* ONE for MIN/MAX */
   /* glBlendFuncSeparate / glBlendEquationSeparate: the alpha channel's
    * equation and factors differ from the rgb ones above (set only then:
    * else they are zero and the alpha channel takes the rgb ones) */
   bool separate_alpha;
   enum r_blend_eq blend_eq_a;
   enum r_blend_factor blend_src_a, blend_dst_a;
   uint8_t blend_color[4];
   bool logic_op;               /* GL_COLOR_LOGIC_OP */
   unsigned logic_op_mode;      /* GL op - GL_CLEAR (0..15) */
   unsigned color_mask;         /* bit 0 red .. bit 3 alpha */
   bool dst_alpha_one;          /* colour buffer without alpha bits */
   float blend_color_f[4];      /* the blend colour as floats (wide targets) */
   float blend_color_u16[4];    /* ... as unorm16 (R_WIDE_UNORM16 targets), whole
                                 * numbers kept as floats for wide_factor */
};

/* The fragment program: the varyings it reads, colour sum, fog, the
 * texture units it walks, the coverage lowering of smooth points and
 * lines, per-fragment lighting. */
struct r_fs_state {
   /* varyings (R_ATTR_* slots) the vertex stage writes */
   int num_attribs;
   unsigned fs_inputs;          /* bit R_FS_*: inputs the fragment shader reads */
   bool color_sum;              /* colour += secondary colour (rgb) */

   /* fog, applied to the colour (after the colour sum) from the
    * interpolated R_FS_FOG input */
   enum r_fog_mode fog_mode;
   float fog_params[4];         /* STATE_FOG_PARAMS_OPTIMIZED: -1/(end-start),
                                 * end/(end-start), density/ln 2,
                                 * density/sqrt(ln 2) */
   float fog_color[3];          /* clamped to [0,1] */

   /* smooth point/line quads: the fragment shader's coverage lowering
    * (R_FS_AA is then one of fs_inputs) */
   enum r_aa_mode aa;

   /* texturing: bit u of tex_units is set for each unit with a complete
    * texture (ff_fragment_shader.cpp key->unit[u].enabled), units
    * 0 .. tex_nr - 1 are walked in order (nr_enabled_units); the fragment
    * program is untouched (no per-pixel cost) when tex_units is 0 */
   unsigned tex_units;
   int tex_nr;
   /* some unit's lookup needs the pair quad (r_tex_need_pair): the
    * primitives fill r_fs_quad.pair */
   bool tex_pair;
   /* some unit samples a cube map: the primitives fill r_fs_quad.br */
   bool tex_cube;

   /* GL_PHONG_WIN with lighting (include/fixgl/shading.md): every
    * fragment is lit by r_fragment_phong from the interpolated R_FS_NORMAL
    * and R_FS_EYEPOS inputs (then among fs_inputs) with r_state.shade_env;
    * the lit colours replace the R_FS_COLOR0/COLOR1 inputs, whose
    * interpolated value is the vertex colour (for colour material).  The
    * face is the rasterizer's (shade_env->two_side: a back-facing triangle,
    * or an unfilled back face's lines and points, use the back material);
    * the smooth point and line quads are triangles of their own, with the
    * face their winding gives them under the aa stages' front_ccw (as
    * llvmpipe's triangle setup decides gl_FrontFacing: from the area, never
    * from the face draw's unfilled stage puts into the vertices). */
   bool phong;
};

/* An occlusion query's counters of samples that pass the fragment tests
 * (alpha, stencil, depth; scissor and the primitive's coverage and kills
 * before them): one per thread that rasterizes (the scene's worker slot,
 * 0 when drawing directly), each on a cache line of its own; the query's
 * result is their sum.  The reference kernels count per fragment
 * (r_fragment_ops), the block kernels per 4x2 half from its pass mask. */
#define R_SAMPLE_SLOTS 64
struct r_sample_counter {
   uint64_t n;
   uint64_t pad[7];
};

/* A draw's raster state (the raster variant): one object of each kind,
 * what is the draw's own (the draw region, the interpolation of the
 * batch, the pixel image, the counters), and the kernels chosen for the
 * combination.  Small, copied freely; the objects it points to are
 * shared and never written. */
/* Whole-buffer clears not yet written into the buffers' memory, by 64x64
 * tiles (the context's lazy clears, scene.c "Lazy clears"): per tile,
 * R_LAZY_COLOR and R_LAZY_ZS while the tile holds, logically, the clear
 * value that its memory does not; `pending` is set while some tile may. */
struct r_lazy_clear {
   uint8_t *tiles;
   int tiles_x, tiles_y;
   unsigned pending;
   uint8_t rgba[4];
   bool depth, stencil;
   uint32_t zvalue;
   uint8_t svalue;
};
#define R_LAZY_COLOR 1u
#define R_LAZY_ZS    2u
#define R_LAZY_TILE_LOG2 6   /* the scene's tiles (r_scene.h R_TILE_LOG2) */
/* Writes the lazy clears `what` of the tiles tx0..tx1, ty0..ty1 (inclusive,
 * in range) into fb's memory (r_clear.c). */
void r_lazy_resolve_tiles(struct r_lazy_clear *lz, const struct r_fb_state *fb, unsigned what,
                          int tx0, int ty0, int tx1, int ty1);

struct r_state {
   const struct r_fb_state *fb;
   const struct r_rast_state *rast;
   const struct r_dsa_state *dsa;
   const struct r_blend_state *blend;
   const struct r_fs_state *fs;
   /* unit u's image, sampler and environment, for the units in
    * fs->tex_units (else NULL) */
   const struct r_tex_unit *tex[R_MAX_TEX_UNITS];
   /* fs->phong's lighting environment (else NULL) */
   const struct m_shade_env *shade_env;

   /* pixels outside [x0,x1) x [y0,y1) are never touched (framebuffer,
    * intersected with the scissor box) */
   int x0, y0, x1, y1;
   /* the region of points, of lines that are not smooth and of triangles
    * (x0..y1 is the scissored region of clears and binning): the draw
    * region, cut to the viewport rectangle when the context decided so
    * (ORACLE-NOTES.md "Point parameters": llvmpipe's vpwh scissor, state
    * decided by the first primitive after a change; the smooth quads'
    * x0..y1 are cut with it);
    * a sprite may shade the row at py1 below it (r_point.c sprite) */
   int px0, py0, px1, py1;

   /* bit i: attribute i uses the provoking vertex (the vertex stage sets
    * it per batch) */
   uint32_t flat_mask;
   /* the pstipple fragment shader is bound for points and lines too: tnl
    * sets it while it hands llvmpipe a vbuf batch of points or lines that
    * is flushed after the first filled triangle of a draw (t_linepoint.c
    * t_vbuf_flush); the same kill as triangles' */
   bool stipple_points_lines;
   /* the MXCSR a triangle's setup (its planes, r_tri.c setup_shade) runs
    * in, or 0 for the current one (the draw's FTZ|DAZ): tnl sets it to the
    * application's while it hands over the triangles of draw's pipeline,
    * which llvmpipe sets up at draw_flush, after draw_vbo restored the
    * caller's state; the pixels stay under the draw's (ORACLE-NOTES.md
    * "Interpolation", probe p_setup_fpstate) */
   unsigned setup_mxcsr;
   /* glBitmap, glDrawPixels, glCopyPixels (r_pixels.c, drawn by
    * tnl/t_pixels.c): the state tracker's textured quad replaces the
    * fragment shader; NULL for every other primitive */
   const struct r_pixel_image *pix;
   /* the benchmark's counters, or NULL (the usual case) */
   struct r_stats *stats;
   /* the lazy clears of fb, written by a triangle's box before it is
    * drawn (r_lazy_touch), or NULL: a context drawing directly (one
    * thread) points it to its framebuffer's */
   struct r_lazy_clear *lazy;
   /* the active occlusion query's counter of this thread, or NULL (the
    * usual case: nothing counted); the scene's tiles point it to the slot
    * of the thread that replays them */
   struct r_sample_counter *samples;

   /* Chosen by r_choose_kernels from the objects: whoever points the
    * r_state to other objects calls it again. */
   /* an alpha test, stencil test, blending, logic op or colour mask is
    * active; when false, fragments take the depth test and a plain store
    * only */
   bool full_ops;
   bool reference_kernels;       /* FIXGL_KERNELS=reference: no others */
   /* which build of the fast kernels runs (enum r_isa, r_kernel_isa in
    * r_kernel.h): R_ISA_NONE under FIXGL_KERNELS=reference or on a CPU
    * without AVX2 */
   uint8_t kernel_isa;
   /* triangles' block kernels (r_kernel.h), [colour flat]; NULL means the
    * reference kernels */
   r_tri_kernel tri_kernel[2];
   /* the same for lines and points (r_line.c, r_point.c): chosen as if
    * the polygon stipple were off, which lines and points ignore unless
    * the pstipple shader is bound (stipple_points_lines, set per batch:
    * they then take the reference kernels) */
   r_tri_kernel line_kernel[2];
};

/* Before the pixels of the box x0..x1, y0..y1 (inclusive, inside the
 * buffer) are drawn: its tiles' lazy clears are written.  Per primitive,
 * so cheap when there is nothing to write. */
static inline void r_lazy_touch(const struct r_state *rs, int x0, int y0, int x1, int y1)
{
   struct r_lazy_clear *lz = rs->lazy;
   if (!lz || !lz->pending)
      return;
   const int tx0 = x0 >> R_LAZY_TILE_LOG2, tx1 = x1 >> R_LAZY_TILE_LOG2;
   const int ty0 = y0 >> R_LAZY_TILE_LOG2, ty1 = y1 >> R_LAZY_TILE_LOG2;
   for (int ty = ty0; ty <= ty1; ty++)
      for (int tx = tx0; tx <= tx1; tx++)
         if (lz->tiles[(size_t)ty * (size_t)lz->tiles_x + (size_t)tx]) {
            r_lazy_resolve_tiles(lz, rs->fb, R_LAZY_COLOR | R_LAZY_ZS, tx0, ty0, tx1, ty1);
            return;
         }
}

/* Sets full_ops and chooses the kernels of rs for its objects (r_tri.c). */
void r_choose_kernels(struct r_state *rs);

/* The cache of state objects (r_cso.c), one per context: r_cso_lookup
 * returns the cached object whose bytes equal obj's size bytes (a copy
 * made now if there is none), or NULL when out of memory.  The cache
 * holds every object it returned until r_cso_cache_fini, or until it
 * evicts it: it keeps at most R_CSO_CACHE_MAX objects that nobody holds,
 * dropping the least recently looked-up one.  Whoever keeps an object
 * beyond the next lookup holds it (r_cso_hold) and releases it after
 * (r_cso_release); r_state_hold/r_state_release do it for every object
 * of an r_state. */
#define R_CSO_CACHE_MAX 64
struct r_cso_entry;
struct r_cso_cache {
   struct r_cso_entry **entry;
   unsigned count, capacity;
   uint64_t clock;
};
const void *r_cso_lookup(struct r_cso_cache *c, const void *obj, size_t size);
/* r_cso_lookup of an object that points at storage of its own lifetime
 * (a texture unit's texels): on_hold(obj, true) runs when the object
 * becomes held (r_cso_hold from no holds) and on_hold(obj, false) when the
 * last hold is released (or the cache is finished with holds left), so
 * the storage lives while anybody holds the object.  An object is equal
 * only to one looked up with the same on_hold. */
typedef void (*r_cso_hold_fn)(const void *obj, bool hold);
const void *r_cso_lookup_held(struct r_cso_cache *c, const void *obj, size_t size,
                              r_cso_hold_fn on_hold);
void r_cso_hold(const void *obj);
void r_cso_release(const void *obj);
void r_state_hold(const struct r_state *rs);
void r_state_release(const struct r_state *rs);
void r_cso_cache_fini(struct r_cso_cache *c);

/* The image a pixel rectangle samples (r_pixels.c), NEAREST with
 * CLAMP_TO_EDGE, normalized coordinates; row 0 is t = 0. */
enum r_pixel_kind {
   R_PIX_BITMAP,     /* R8 texels: a texel != 0 kills (nir_lower_bitmap) */
   R_PIX_COLOR,      /* RGBA float texels replace the fragment program's
                      * primary colour (nir_lower_drawpixels) */
   R_PIX_DEPTH,      /* float depth texels: the fragment depth; the colour
                      * is the vertex colour (drawpix Z shader) */
   R_PIX_STENCIL,    /* stencil texels exported as the stencil reference */
};

struct r_pixel_image {
   enum r_pixel_kind kind;
   int width, height;
   const uint8_t *mask;      /* R_PIX_BITMAP, R_PIX_STENCIL */
   const float *texels;      /* R_PIX_COLOR: 4 floats a texel; R_PIX_DEPTH: 1 */
   /* R_PIX_COLOR: the shader's pixel transfer, texel * scale + bias
    * (fmul, fadd: llvmpipe lowers ffma), then the colour maps */
   bool scale_bias;
   float scale[4], bias[4];
   bool map_color;
   const float *maps[4];     /* R, G, B, A maps (GL_PIXEL_MAP_x_TO_x) */
   int map_size[4];
   /* R_PIX_STENCIL with R_PIX_DEPTH values too (GL_DEPTH_STENCIL) */
   bool with_stencil;
   /* R_PIX_COLOR: the texel is the fragment colour, no fixed-function
    * program (glCopyPixels of GL_DEPTH_STENCIL_TO_RGBA/BGRA_NV) */
   bool raw_color;
   /* The texture coordinates the user's units (r_state.tex_units) see:
    * units in tex_quad read the quad's own coordinate (s, t, 0, 1) with
    * its derivatives (glBitmap's gl_TexCoord[0]), the others the constant
    * tex_const[u] */
   unsigned tex_quad;
   float tex_const[R_MAX_TEX_UNITS][4];
};

/* The fragment stage of a pixel rectangle: fragment (px, py) with the
 * interpolated inputs and depth (r_tri.c calls it instead of the
 * fragment shader when rs->pix is set); quad: the quad coordinate
 * (R_FS_TEX0) at the fragment's quad in tex[0] (and pair[0]), given when
 * the image's tex_quad and rs->fs->tex_units are not 0. */
void r_pixel_fragment(const struct r_state *rs, int px, int py, const float in[][4], float z,
                      const struct r_fs_quad *quad);

/* The fragment stage (r_frag.c), shared by every primitive.
 * r_fragment_shader: the fixed-function fragment program, from the
 *   interpolated inputs (R_FS_*) to the fragment colour; quad holds the
 *   texture coordinates of the fragment's quad (read only for the units
 *   in tex_units; NULL when tex_units is 0).
 * r_fragment_ops: the per-fragment operations in the specification's order
 *   on pixel (px, py) inside the draw region, with the fragment's depth
 *   before clamping. */
void r_fragment_shader(const struct r_state *rs, const float in[][4],
                       const struct r_fs_quad *quad, float out[4]);
void r_fragment_ops(const struct r_state *rs, int px, int py, float z, const float color[4]);
/* r_fragment_shader with the fast LOD of the fragment's quad already
 * selected (r_tex_lod_aos) for the units in tex_units whose texture does
 * not have `soa` set: lod[u] for unit u (a triangle's per-quad cache);
 * lod NULL is r_fragment_shader. */
void r_fragment_shader_lod(const struct r_state *rs, const float in[][4],
                           const struct r_fs_quad *quad, const struct r_tex_lod *lod,
                           float out[4]);

/* GL_PHONG_WIN's lighting of one fragment (r_frag.c): replaces in's
 * R_FS_COLOR0 (and R_FS_COLOR1) with m_shade_point's primary (and
 * secondary) colour for the normal in[R_FS_NORMAL], the eye position
 * in[R_FS_EYEPOS], the face `back` and the vertex colour in[R_FS_COLOR0].
 * Called by the primitives before r_fragment_shader when rs->fs->phong. */
void r_fragment_phong(const struct r_state *rs, float in[][4], bool back);

/* The smooth point/line lowering appended to the fragment shader
 * (r_aa.c): false if the fragment is discarded, else color's alpha is
 * scaled by the coverage computed from the R_FS_AA input. */
bool r_fragment_aa(const struct r_state *rs, const float in[][4], float color[4]);

/* Rasterize one triangle; v2 is the provoking vertex. */
void r_triangle(const struct r_state *rs, const struct r_vertex *v0,
                const struct r_vertex *v1, const struct r_vertex *v2);

/* What r_triangle can cover of a triangle, for the scene's binning: 0
 * nothing (its snapped area is zero, its facing is culled, or its box
 * misses the draw region and the framebuffer); 1 at most the pixels of
 * box = [x0, x1) x [y0, y1) (its snapped positions' box, cut to them)
 * that `edges` (r_tri_edges_miss_tile; set for boxes of 2+ tiles) does
 * not exclude; 2 unknown (non-finite or huge positions: any pixel). */
struct r_tri_edges {
   int64_t c[3], dcdx[3], dcdy[3], eo[3];
   /* the snapped box's right column and bottom row (inclusive, not cut
    * to the draw region): whether llvmpipe adds those region planes */
   int32_t bx1, by1;
};
int r_triangle_box(const struct r_state *rs, const struct r_vertex *v0,
                   const struct r_vertex *v1, const struct r_vertex *v2, int box[4],
                   struct r_tri_edges *edges);

/* For a box of kind 1: true when the triangle of `edges` covers no pixel
 * of the 64x64 tile whose top-left pixel is (x, y) (a multiple of 64):
 * llvmpipe's trivial reject, conservative. */
bool r_tri_edges_miss_tile(const struct r_tri_edges *edges, int x, int y);
/* ... and true when it covers every pixel of it (no edge cuts it: the
 * tiles llvmpipe shades whole, lp_setup_whole_tile) */
bool r_tri_edges_cover_tile(const struct r_tri_edges *edges, int x, int y);

/* Rasterize one non-antialiased point (r_point.c; llvmpipe's legacy
 * points, lp_setup_point.c). */
void r_point(const struct r_state *rs, const struct r_vertex *v);

/* Rasterize one non-antialiased line (r_line.c; lp_setup_line.c with the
 * diamond-exit emulation); v1 is the provoking vertex. */
void r_line(const struct r_state *rs, const struct r_vertex *v0, const struct r_vertex *v1);

/* llvmpipe's util_iround (u_math.h, the C version on x86-64): +-0.5, then
 * truncate; NaN and out-of-range values give INT32_MIN, as cvttss2si. */
static inline int32_t r_iround(float f)
{
   const float r = f >= 0.0f ? f + 0.5f : f - 0.5f;
   if (!(r >= -2147483648.0f && r < 2147483648.0f))
      return INT32_MIN;
   return (int32_t)r;
}

/* subpixel_snap of lp_setup_line.c and lp_setup_point.c */
static inline int32_t r_subpixel_snap(float a)
{
   return r_iround(256.0f * a);
}

/* Whether the polygon stipple keeps pixel (px, py): row py mod 32 of
 * stipple_rows, bit 31 - (px mod 32) (draw's pstipple stage samples a
 * 32x32 texture of the pattern at the window position and kills the
 * fragment before anything else [S: draw/draw_pipe_pstipple.c,
 * util/u_pstipple.c]). */
static inline bool r_stipple_pass(const struct r_state *rs, int px, int py)
{
   return (rs->rast->stipple_rows[py & 31] >> (31 - (px & 31))) & 1u;
}

/* Clear whole buffers. */
void r_clear_color(const struct r_state *rs, const uint8_t rgba[4]);
void r_clear_depth_stencil(const struct r_state *rs, bool depth, uint32_t zvalue,
                           bool stencil, uint8_t svalue);
/* A clear drawn as a quad covering the draw region, every pixel a fragment
 * at depth z with colour `color` through r_fragment_ops (the state tracker's
 * clear_with_quad). */
void r_clear_quad(const struct r_state *rs, float z, const float color[4]);

/* Per-pixel loops are compiled twice, with and without the FMA
 * instruction set, and the loader picks the clone the CPU runs (GCC's
 * target_clones, an ifunc): with FMA, fmaf() becomes one vfmadd
 * instruction instead of a libm call.  The result is the same either way
 * (fmaf is always the fused operation); only the speed differs. */
/* (Not under ThreadSanitizer, which instruments the clones' resolver, run
 * by the loader before its runtime exists.) */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__) && \
    !defined(__SANITIZE_THREAD__)
#define R_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define R_FMA_CLONES
#endif

/* Round to nearest, ties to even, of a value known to fit in an int32 (the
 * oracle's cvtps2dq): one cvtss2si under the default rounding mode instead
 * of a libm call. */
static inline int32_t r_round_even(float f)
{
#if defined(__SSE__) || defined(__x86_64__)
   return _mm_cvt_ss2si(_mm_set_ss(f));
#else
   return (int32_t)lrintf(f);
#endif
}

/* gallivm's lp_build_clamp(x, 0, 1) = max(min(x, 1), 0) on x86 minps/maxps,
 * which return their second operand when one is NaN, so NaN becomes 1.
 * The oracle clamps vertex colours and fragment depth this way
 * (ORACLE-NOTES.md "Clamps and NaN"). */
static inline float r_clamp01(float x)
{
   const float m = x < 1.0f ? x : 1.0f;    /* minps(x, 1): NaN -> 1 */
   return m > 0.0f ? m : 0.0f;
}

/* Float -> unorm conversions of the oracle (ORACLE-NOTES.md "Colour
 * conversion", "Depth conversion and polygon offset"). */
uint8_t r_float_to_unorm8(float c);
uint32_t r_depth_to_z24(float z);
uint16_t r_depth_to_z16(float z);
uint32_t r_depth_to_z32(float z);

#endif
