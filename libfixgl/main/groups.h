/*
 * Internal interface of the per-attribute-group files in main/: defaults
 * (spec tables) and the trusted setters other files call.
 */
#ifndef FGL_MAIN_GROUPS_H
#define FGL_MAIN_GROUPS_H

#include "context.h"

/* main/matrix.c */
bool fgl_init_matrix(struct fgl_context *ctx);
void fgl_free_matrix(struct fgl_context *ctx);

/* main/begin_end.c (GL_CURRENT_BIT) */
void fgl_init_current(struct fgl_context *ctx);

/* main/clear.c (GL_COLOR_BUFFER_BIT) */
void fgl_init_color(struct fgl_context *ctx);

/* main/depth.c (GL_DEPTH_BUFFER_BIT) */
void fgl_init_depth(struct fgl_context *ctx);

/* main/light.c (GL_LIGHTING_BIT) */
void fgl_init_light(struct fgl_context *ctx);
/* _mesa_update_color_material: the materials that track the colour */
void fgl_update_color_material(struct fgl_context *ctx, const float color[4]);
void fgl_set_color_material_enabled(struct fgl_context *ctx, bool state);
/* _mesa_update_lighting, _mesa_update_tnl_spaces, compute_light_positions */
void fgl_update_lighting(struct fgl_context *ctx);

/* main/polygon.c (GL_POLYGON_BIT) */
void fgl_init_polygon(struct fgl_context *ctx);

/* main/points.c (GL_POINT_BIT), main/lines.c (GL_LINE_BIT) */
void fgl_init_point(struct fgl_context *ctx);
void fgl_init_line(struct fgl_context *ctx);

/* main/viewport.c (GL_VIEWPORT_BIT) */
void fgl_init_viewport(struct fgl_context *ctx);
void fgl_set_viewport(struct fgl_context *ctx, int x, int y, int width, int height);

/* main/misc.c: make the framebuffer's content visible to the application
 * (glFlush/glFinish). */
void fgl_flush_front(struct fgl_context *ctx);

/* main/enable.c: whether pname is a capability; its state in *value */
bool fgl_is_cap(struct fgl_context *ctx, GLenum pname, double *value);

#endif
