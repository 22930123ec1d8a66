/*
 * The vertex stage: transform to clip space, clip test, geometric clipping,
 * primitive assembly.  Its output is r_vertex triangles for the raster core.
 */
#ifndef FGL_T_PIPELINE_H
#define FGL_T_PIPELINE_H

#include "raster/r_state.h"
#include "tnl/t_vbo.h"

struct fgl_context;

/* A vertex after the vertex "shader": clip-space position, outcode bits
 * (llvmpipe-facts.md §1 "Outcodes"), window position and varyings. */
struct t_vertex {
   float clip[4];
   unsigned mask;
   struct r_vertex r;
};

/* Transform n stored vertices (positions, colours) into out[]. */
void t_transform(const struct fgl_context *ctx, const struct fgl_vbo_vertex *in,
                 unsigned n, struct t_vertex *out);

/* Light n stored vertices (t_light.c): the R_ATTR_* colour slots of out[],
 * before the clamp. */
void t_light(const struct fgl_context *ctx, const struct fgl_vbo_vertex *in, unsigned n,
             struct t_vertex *out);

/* A triangle of a vsplit segment that takes draw's pipeline (`pipeline`)
 * or goes straight to llvmpipe: clipped against the view volume, culled and
 * coloured as draw's stages do, then rasterized; v2 is the provoking
 * vertex. */
void t_clip_triangle(struct fgl_context *ctx, const struct t_vertex *v0,
                     const struct t_vertex *v1, const struct t_vertex *v2, bool pipeline);

/* Clip a line (draw_pipe_clip.c:clip_line, do_clip_line); v1 is the
 * provoking vertex.  Returns false if nothing is left, else the clipped
 * ends in out[]. */
bool t_clip_line(const struct fgl_context *ctx, const struct t_vertex *v0,
                 const struct t_vertex *v1, struct t_vertex out[2]);

/* Points and lines after assembly (t_linepoint.c): clipping, then the draw
 * module's stipple stage, then the raster core.  `first` marks the first
 * line of a primitive (DRAW_PIPE_RESET_STIPPLE); `pipeline` that the point's
 * vsplit segment takes draw's pipeline because some vertex needs clipping. */
void t_point(struct fgl_context *ctx, const struct t_vertex *v, bool pipeline);
void t_line(struct fgl_context *ctx, const struct t_vertex *v0, const struct t_vertex *v1,
            bool first);

/* Draw a batch of immediate-mode primitives. */
void t_render_batch(struct fgl_context *ctx, const struct fgl_vbo_vertex *verts,
                    unsigned nverts, const struct fgl_vbo_prim *prims, unsigned nprims);

#endif
