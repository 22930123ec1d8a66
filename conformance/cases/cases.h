/* cases.h - the fixed case groups and small drawing helpers shared by them. */
#ifndef FC_CASES_H
#define FC_CASES_H

#include "fc_case.h"

/* Table entry with the default buffer row length. */
#define FC_CASE(name, w, h, fmt, depth, stencil, frames, tags, fn) \
    { name, w, h, fmt, depth, stencil, frames, tags, fn, 0, 0, 0, 0 }
/* The same for a case whose frames show a cleared buffer on purpose: it
 * checks errors, queries or a clear value (draws_nothing, fc_case.h). */
#define FC_CASE_NODRAW(name, w, h, fmt, depth, stencil, frames, tags, fn) \
    { name, w, h, fmt, depth, stencil, frames, tags, fn, 0, 0, 0, FC_DRAWS_NOTHING }
/* RGBA, depth 24, no stencil. */
#define FC_CASE_RGBA(name, w, h, frames, tags, fn) \
    FC_CASE(name, w, h, OSMESA_RGBA, 24, 0, frames, tags, fn)

/* Each group table ends with an entry whose name is NULL. */
extern const fc_case fc_cases_fill[];
extern const fc_case fc_cases_shade[];
extern const fc_case fc_cases_clip[];
extern const fc_case fc_cases_rasterpos[];
extern const fc_case fc_cases_windowpos[];
extern const fc_case fc_cases_demo_tex[];
extern const fc_case fc_cases_depth[];
extern const fc_case fc_cases_format[];
extern const fc_case fc_cases_viewport[];
extern const fc_case fc_cases_matrix[];
extern const fc_case fc_cases_query[];
extern const fc_case fc_cases_query_walk[];
extern const fc_case fc_cases_vertex[];
extern const fc_case fc_cases_readpix[];
extern const fc_case fc_cases_pix_format[];
extern const fc_case fc_cases_pix_format_tex[];
extern const fc_case fc_cases_errors[];
extern const fc_case fc_cases_robust[];
extern const fc_case fc_cases_light[];
extern const fc_case fc_cases_light_space[];
extern const fc_case fc_cases_light_normal[];
extern const fc_case fc_cases_light_mat[];
extern const fc_case fc_cases_light_prim[];
extern const fc_case fc_cases_light_api[];
extern const fc_case fc_cases_fog[];
extern const fc_case fc_cases_fragment[];
extern const fc_case fc_cases_polygon[];
extern const fc_case fc_cases_points_lines[];
extern const fc_case fc_cases_polygon_mode[];
extern const fc_case fc_cases_varray[];
extern const fc_case fc_cases_attrib[];
extern const fc_case fc_cases_demo[];
extern const fc_case fc_cases_dlist[];
extern const fc_case fc_cases_select[];
extern const fc_case fc_cases_texstate[];
extern const fc_case fc_cases_tex_image[];
extern const fc_case fc_cases_accum[];
extern const fc_case fc_cases_eval[];
extern const fc_case fc_cases_pixelstate[];
extern const fc_case fc_cases_tex_coord[];
extern const fc_case fc_cases_tex_sample[];
extern const fc_case fc_cases_tex_env[];
extern const fc_case fc_cases_tex_wrap[];
extern const fc_case fc_cases_pix_draw[];
extern const fc_case fc_cases_shading[];
extern const fc_case fc_cases_shading_paths[];
extern const fc_case fc_cases_gl14_attr[];
extern const fc_case fc_cases_gl14_ops[];
extern const fc_case fc_cases_gl14_points[];
extern const fc_case fc_cases_gl14_sprite[];
extern const fc_case fc_cases_gl15[];
extern const fc_case fc_cases_tex3d[];
extern const fc_case fc_cases_shadow[];
extern const fc_case fc_cases_cubemap[];
extern const fc_case fc_cases_osmesa[];
extern const fc_case fc_cases_tex_copy[];
extern const fc_case fc_cases_compressed[];
extern const fc_case fc_cases_honesty[];
extern const fc_case fc_cases_demo_cube_shadow[];

/* glClearColor + glClearDepth + clear of colour and depth. */
void fcu_clear(float r, float g, float b, float a, double depth);
/* glColor3ub of a distinct, saturated palette colour (index taken mod 16). */
void fcu_color(int i);
/* Axis-aligned GL_QUADS rectangle at depth z in the current colour. */
void fcu_rect(float x0, float y0, float x1, float y1, float z);
/* One GL_TRIANGLES triangle (x, y pairs) at z = 0. */
void fcu_tri(float x0, float y0, float x1, float y1, float x2, float y2);
/* Sets the projection matrix (and returns to GL_MODELVIEW with identity). */
/* Level `level` of a hand-built mipmap chain (GL_TEXTURE_1D or 2D, RGBA,
 * up to 256x256): a checker of two colours distinct to the level, so
 * both the level and the texel show; and a full chain of them from
 * w x h down to 1x1. */
void fcu_tex_level_image(GLenum target, int level, int w, int h);
void fcu_tex_level_chain(GLenum target, int w, int h);
void fcu_ortho(double l, double r, double b, double t, double n, double f);
void fcu_frustum(double l, double r, double b, double t, double n, double f);

/* Vertices of each primitive type in window coordinates of a 32x32 buffer
 * (shared by the shading and lit-primitive cases). */
extern const float fcu_tri_v[6][2], fcu_strip_v[8][2], fcu_fan_v[7][2];
extern const float fcu_quads_v[8][2], fcu_qstrip_v[8][2], fcu_poly_v[6][2];

/* GL 1.5 honesty (README "Version and honesty"): a client pixel format or
 * type of a later GL version or of an extension fixgl does not list
 * (GL_RG, the *_INTEGER formats, GL_DEPTH_STENCIL, the half-float, 24_8
 * and packed float types).  fixgl raises GL_INVALID_ENUM for them where
 * the oracle's GL 4.5 context accepts them, so the GL 1.5 cases leave them
 * out and the honesty cases (c_honesty.c, tag honesty) record them.
 * Invalid values of every version (0x1234, GL_DOUBLE, GL_INTENSITY as a
 * client format) are not foreign: the error cases keep them. */
static inline int fc_foreign_pixel_format(GLenum format)
{
    switch (format) {
    case 0x8227 /* GL_RG */: case 0x8228 /* GL_RG_INTEGER */:
    case 0x84F9 /* GL_DEPTH_STENCIL */:
    case 0x8D94 /* GL_RED_INTEGER */: case 0x8D95 /* GL_GREEN_INTEGER */:
    case 0x8D96 /* GL_BLUE_INTEGER */: case 0x8D97 /* GL_ALPHA_INTEGER */:
    case 0x8D98 /* GL_RGB_INTEGER */: case 0x8D99 /* GL_RGBA_INTEGER */:
    case 0x8D9A /* GL_BGR_INTEGER */: case 0x8D9B /* GL_BGRA_INTEGER */:
    case 0x8D9C /* GL_LUMINANCE_INTEGER_EXT */: case 0x8D9D /* GL_LUMINANCE_ALPHA_INTEGER_EXT */:
        return 1;
    default:
        return 0;
    }
}

static inline int fc_foreign_pixel_type(GLenum type)
{
    switch (type) {
    case 0x140B /* GL_HALF_FLOAT */: case 0x8D61 /* GL_HALF_FLOAT_OES */:
    case 0x84FA /* GL_UNSIGNED_INT_24_8 */: case 0x8DAD /* GL_FLOAT_32_UNSIGNED_INT_24_8_REV */:
    case 0x8C3B /* GL_UNSIGNED_INT_10F_11F_11F_REV */: case 0x8C3E /* GL_UNSIGNED_INT_5_9_9_9_REV */:
        return 1;
    default:
        return 0;
    }
}

static inline int fc_foreign_pixel(GLenum format, GLenum type)
{
    return fc_foreign_pixel_format(format) || fc_foreign_pixel_type(type);
}

#endif
