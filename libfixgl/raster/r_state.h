/*
 * The raster core's view of the world.  It knows nothing of GL: the
 * context's validation pass (state.c) translates GL state into an r_state,
 * and the vertex stage hands it r_vertex triangles in window coordinates.
 *
 * Coordinates are y-down, as in the oracle (llvmpipe-facts.md §0): row 0 of
 * every buffer is the top row of the image.
 */
#ifndef FGL_R_STATE_H
#define FGL_R_STATE_H

#include <stdbool.h>
#include <stdint.h>

#define R_MAX_ATTRIBS 5

/* Varying slots: the colour written to the buffer, the secondary colour
 * the fragment stage adds to it (separate specular), and their back-face
 * versions for two-sided lighting; the coverage coordinates of the draw
 * module's smooth point and line quads (tnl/t_linepoint.c). */
enum {
   R_ATTR_COLOR0,
   R_ATTR_COLOR1,
   R_ATTR_BCOLOR0,
   R_ATTR_BCOLOR1,
   R_ATTR_AA,
};

/* Inputs of the fragment shader, after the back-face colours have been
 * chosen: the colour and the secondary colour. */
enum {
   R_FS_COLOR0,
   R_FS_COLOR1,
   R_FS_AA,          /* the aapoint/aaline generic input */
   R_FS_NUM_INPUTS,
};

/* The vertex slot that feeds fragment-shader input `input`, for a front-
 * or back-facing primitive (lp_state_setup.c:lp_twoside swaps the colour
 * inputs for back faces). */
static inline int r_fs_slot(int input, bool back)
{
   switch (input) {
   case R_FS_COLOR0: return back ? R_ATTR_BCOLOR0 : R_ATTR_COLOR0;
   case R_FS_COLOR1: return back ? R_ATTR_BCOLOR1 : R_ATTR_COLOR1;
   case R_FS_AA:     return R_ATTR_AA;
   default:          return input;
   }
}

/* Depth/stencil buffer layouts, as the OSMesa oracle allocates them. */
enum r_zs_format {
   R_ZS_NONE,
   R_ZS_Z16,       /* uint16_t depth */
   R_ZS_Z24X8,     /* uint32_t, depth in bits 0..23, bits 24..31 zero */
   R_ZS_Z24S8,     /* uint32_t, depth in bits 0..23, stencil in 24..31 */
   R_ZS_S8,        /* uint8_t stencil only */
};

/* Comparison functions, in GL's order (GL_NEVER + n). */
enum r_func {
   R_NEVER, R_LESS, R_EQUAL, R_LEQUAL, R_GREATER, R_NOTEQUAL, R_GEQUAL, R_ALWAYS,
};

/* Coverage lowering of the fragment shader for the draw module's smooth
 * point and line quads (r_aa.c). */
enum r_aa_mode {
   R_AA_NONE,
   R_AA_POINT,       /* nir_lower_aapoint_fs */
   R_AA_LINE,        /* nir_lower_aaline_fs */
};

/* A post-transform vertex: window position (x, y y-down, z in [0,1] before
 * clamping, w = 1/clip_w) and its varyings. */
struct r_vertex {
   float pos[4];
   float attr[R_MAX_ATTRIBS][4];
};

struct r_state {
   /* target */
   uint8_t *color;              /* RGBA8 */
   void *zs;
   enum r_zs_format zs_format;
   int width, height;

   /* pixels outside [x0,x1) x [y0,y1) are never touched (framebuffer,
    * later intersected with the scissor box) */
   int x0, y0, x1, y1;

   /* per-fragment operations */
   bool depth_test;
   enum r_func depth_func;
   bool depth_write;

   /* varyings (R_ATTR_* slots); the vertex stage fills num_attribs */
   int num_attribs;
   unsigned fs_inputs;          /* bit R_FS_*: inputs the fragment shader reads */
   uint32_t flat_mask;          /* bit i: attribute i uses the provoking vertex */
   bool color_sum;              /* colour += secondary colour (rgb) */
   bool twoside;                /* back-facing triangles use the BCOLOR slots */
   bool ccw_is_front;           /* a positive snapped area is front-facing */
   bool cull_front, cull_back;  /* faces not drawn */

   /* points and lines, as the state tracker clamps them
    * (st_atom_rasterizer.c): size in [0, 255], width in [1, 255] */
   float point_size;
   float line_width;

   /* smooth point/line quads: the fragment shader's coverage lowering
    * (R_FS_AA is then one of fs_inputs) */
   enum r_aa_mode aa;
};

/* The fragment stage (r_frag.c), shared by every primitive.
 * r_fragment_shader: the fixed-function fragment program, from the
 *   interpolated inputs (R_FS_*) to the fragment colour.
 * r_fragment_ops: the per-fragment operations in the specification's order
 *   on pixel (px, py) inside the draw region, with the fragment's depth
 *   before clamping. */
void r_fragment_shader(const struct r_state *rs, const float in[][4], float out[4]);
void r_fragment_ops(const struct r_state *rs, int px, int py, float z, const float color[4]);

/* The smooth point/line lowering appended to the fragment shader
 * (r_aa.c): false if the fragment is discarded, else color's alpha is
 * scaled by the coverage computed from the R_FS_AA input. */
bool r_fragment_aa(const struct r_state *rs, const float in[][4], float color[4]);

/* Rasterize one triangle; v2 is the provoking vertex. */
void r_triangle(const struct r_state *rs, const struct r_vertex *v0,
                const struct r_vertex *v1, const struct r_vertex *v2);

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

/* Clear whole buffers (the masked/scissored clear arrives with its issue). */
void r_clear_color(const struct r_state *rs, const uint8_t rgba[4]);
void r_clear_depth_stencil(const struct r_state *rs, bool depth, uint32_t zvalue,
                           bool stencil, uint8_t svalue);

/* gallivm's lp_build_clamp(x, 0, 1) = max(min(x, 1), 0) on x86 minps/maxps,
 * which return their second operand when one is NaN, so NaN becomes 1.
 * The oracle clamps vertex colours and fragment depth this way
 * (ORACLE-NOTES.md "Clamps and NaN"). */
static inline float r_clamp01(float x)
{
   const float m = x < 1.0f ? x : 1.0f;    /* minps(x, 1): NaN -> 1 */
   return m > 0.0f ? m : 0.0f;
}

/* Float -> unorm conversions of the oracle (llvmpipe-facts.md §1, §2). */
uint8_t r_float_to_unorm8(float c);
uint32_t r_depth_to_z24(float z);
uint16_t r_depth_to_z16(float z);

#endif
