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

#endif
