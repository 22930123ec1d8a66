/*
 * Internal interface of the per-attribute-group files in main/: defaults
 * (spec tables) and the trusted setters other files call.
 */
#ifndef FGL_MAIN_GROUPS_H
#define FGL_MAIN_GROUPS_H

#include "context.h"

/* main/matrix.c */
bool fgl_init_matrix(struct fgl_context *ctx);
struct fgl_matrix_stack *fgl_matrix_stack_for_mode(struct fgl_context *ctx, GLenum mode);
void fgl_free_matrix(struct fgl_context *ctx);

/* main/colorindex.c: glClearIndex's (GLuint) cast of a float, as the
 * oracle's x86-64 build does it */
GLuint fgl_clear_index_cast(float c);

/* main/buffers.c: the window-system framebuffer was created anew */
void fgl_new_window_framebuffer(struct fgl_context *ctx);
/* main/buffers.c: a new context's draw and read buffers for a
 * double-buffered config (GLX): GL_BACK, as _mesa_init_color and
 * _mesa_initialize_window_framebuffer choose them */
void fgl_init_double_buffered(struct fgl_context *ctx);
void fgl_select_color_buffer(struct fgl_context *ctx);
const uint8_t *fgl_read_color(const struct fgl_context *ctx);

/* main/varray.c (GL_CLIENT_VERTEX_ARRAY_BIT) */
void fgl_init_array(struct fgl_context *ctx);
/* the array behind a GL_*_ARRAY client-state enum, or NULL */
struct fgl_client_array *fgl_client_array(struct fgl_context *ctx, GLenum cap);
/* glGet of the GL_*_ARRAY_{SIZE,TYPE,STRIDE} and GL_*_ARRAY values */
bool fgl_get_array_value(struct fgl_context *ctx, GLenum pname, int *value);

/* main/bufferobj.c (GL 1.5 buffer objects) */
bool fgl_init_bufobj(struct fgl_context *ctx);
void fgl_share_bufobjs(struct fgl_context *ctx, struct fgl_context *share);
void fgl_free_bufobj(struct fgl_context *ctx);
/* *slot := obj, the references moved (under the shared table's lock) */
void fgl_buffer_reference(struct fgl_context *ctx, struct fgl_buffer_object **slot,
                          struct fgl_buffer_object *obj);
/* a reference more (less) to every buffer a copy of the array state
 * holds (glPushClientAttrib's; release also clears them) */
void fgl_buffer_hold_array(struct fgl_context *ctx, const struct fgl_array_attrib *a);
void fgl_buffer_release_array(struct fgl_context *ctx, struct fgl_array_attrib *a);
/* glBindBuffer(target, name) of a valid target, trusted */
void fgl_bind_buffer_name(struct fgl_context *ctx, GLenum target, GLuint name);

/* main/queryobj.c (GL 1.5 occlusion queries) */
void fgl_free_queries(struct fgl_context *ctx);
/* the oracle flushed its scene (glFlush, glFinish, a read-back): every
 * query ended before is available, and the next command begins another
 * scene (fgl_lin_flushed) */
static inline void fgl_query_flushed(struct fgl_context *ctx)
{
   ctx->Query.FlushEpoch++;
   fgl_lin_flushed(ctx);
}

/* main/begin_end.c (GL_CURRENT_BIT) */
void fgl_init_current(struct fgl_context *ctx);

/* main/texobj.c */
bool fgl_init_texobj(struct fgl_context *ctx);
void fgl_share_texobjs(struct fgl_context *ctx, struct fgl_context *share);
void fgl_init_texenv(struct fgl_context *ctx);
void fgl_init_texgen(struct fgl_context *ctx);
void fgl_free_texobj(struct fgl_context *ctx);
void fgl_save_texobjs(struct fgl_context *ctx, struct fgl_attrib_node *node);
void fgl_restore_texobjs(struct fgl_context *ctx, const struct fgl_attrib_node *node);
/* the object bound to target on unit `unit` (the default object for 0 or
 * a name without an object) */
struct fgl_texture_object *fgl_bound_texture(struct fgl_context *ctx, unsigned unit,
                                             GLenum target);

/* main/teximage.c */
void fgl_free_tex_images(struct fgl_texture_object *t);
/* whether the oracle samples the image on its 8-bit AoS path (no channel
 * of its format wider than 8 bits; main/teximage.c) */
bool fgl_tex_image_fits_unorm8(const struct fgl_texture_image *img);
/* the bits of the oracle's depth format of a GL_DEPTH_COMPONENT image (16:
 * Z16_UNORM, 24: Z24X8_UNORM, 32: Z32_UNORM), 0 for a colour image
 * (main/teximage.c) */
int fgl_tex_image_depth_bits(const struct fgl_texture_image *img);
/* The texture coordinates (s, t) at which the oracle's mipmap blit
 * samples the level above for texel (i, j) of a w x h level: the planes
 * of the blit quad's two triangles (main/teximage.c) */
struct fgl_blit_quad {
   float s[2][3], t[2][3];   /* (a0', dadx, dady) per triangle */
   int w, h;
};
void fgl_blit_quad_init(struct fgl_blit_quad *q, int w, int h);
void fgl_blit_quad_coord(const struct fgl_blit_quad *q, int i, int j, float *s, float *t);

/* main/texdepth.c: the images of GL_DEPTH_COMPONENT textures
 * (ARB_depth_texture) as the oracle stores and reads them back */
/* Unpacks a w x h GL_DEPTH_COMPONENT client image of `type` into texels
 * (x, y) of slice z of img; false for a type it does not convert. */
bool fgl_tex_store_depth(struct fgl_context *ctx, struct fgl_texture_image *img,
                         const struct fgl_pixelstore *unpack, int x, int y, int z, int w,
                         int h, GLenum type, const void *pixels);
/* glGetTexImage(GL_DEPTH_COMPONENT, type) of slice z of img into dst */
void fgl_tex_get_depth(struct fgl_context *ctx, const struct fgl_texture_image *img, int z,
                       GLenum type, void *dst);
/* glCopyTexImage / glCopyTexSubImage of the depth buffer's rectangle
 * (x, y, w, h) (clipped to the framebuffer, GL y up) to texels
 * (xoff, yoff) of slice zoff of img */
void fgl_tex_copy_depth(struct fgl_context *ctx, struct fgl_texture_image *img, GLint xoff,
                        GLint yoff, GLint zoff, GLint x, GLint y, GLsizei w, GLsizei h);
/* level dst of a depth texture generated from the level above, src
 * (GL_GENERATE_MIPMAP) */
void fgl_tex_gen_mip_depth(const struct fgl_texture_image *src, struct fgl_texture_image *dst);
/* the sampler state of a complete depth texture (state.c update_texture,
 * after the colour texture's) */
void fgl_update_texture_depth(const struct fgl_texture_object *t, struct r_texture *rt);
/* what GL_TEXTURE_INTERNAL_FORMAT reports for img (main/teximage.c) */
GLenum fgl_tex_reported_internal_format(const struct fgl_texture_image *img);
/* teximage.c's helpers for main/texcompress.c: the object an image call
 * on `target` changes, its number of levels, the legal sizes, a new image
 * of an S3TC format (its base GL_RGB or GL_RGBA; no texels allocated),
 * replacing level `level` of t by img (NULL: none) */
struct fgl_texture_object *fgl_tex_target_object(struct fgl_context *ctx, GLenum target);
int fgl_tex_max_levels(GLenum target);
bool fgl_tex_legal_dimensions(GLenum target, GLuint dims, GLint level, GLint w, GLint h,
                              GLint d, GLint border);
struct fgl_texture_image *fgl_tex_new_compressed_image(int w, int h, int d, GLenum internal,
                                                       GLenum base);
void fgl_tex_set_image(struct fgl_texture_object *t, GLenum target, GLint level,
                       struct fgl_texture_image *img);
/* the image slot of `target` (a 2D target, a cube face or a proxy) at
 * `level` of t */
struct fgl_texture_image **fgl_tex_image_slot(struct fgl_texture_object *t, GLenum target,
                                              GLint level);
/* after level `level` of `target`'s image changed: GL_GENERATE_MIPMAP's
 * levels below it (teximage.c check_gen_mipmap) */
void fgl_tex_image_changed(struct fgl_context *ctx, struct fgl_texture_object *t,
                           GLenum target, GLint level);
/* a 2D target, a cube face or a cube-map proxy (glCompressedTexImage2D's
 * targets) */
bool fgl_tex_is_2d_image_target(GLenum target, bool proxies);
/* main/texcompress.c: the bytes of a w x h x d image of an S3TC format */
GLint fgl_compressed_image_size(GLenum format, GLsizei w, GLsizei h, GLsizei d);

/* main/texstate.c: the units that texture fragments (_EnabledTexUnits,
 * _CurrentTex) */
void fgl_update_texture_state(struct fgl_context *ctx);
void fgl_update_texture_matrices(struct fgl_context *ctx);
bool fgl_texture_complete(const struct fgl_texture_object *t, int *max_level);
/* The oracle's finalization of a complete texture t drawn with (levels up
 * to max_level, fgl_texture_complete's): its images move into the
 * object's resource (main/teximage.c "Storage") */
void fgl_tex_finalize_storage(struct fgl_texture_object *t, int max_level);
/* A draw samples the textures of the enabled units: the oracle finalizes
 * them, and its scene references their resources until its next flush
 * (main/teximage.c) */
void fgl_tex_note_scene_use(struct fgl_context *ctx);
/* Texels were written into img of t: a flush of the oracle's scene when
 * it samples img's resource (main/teximage.c) */
void fgl_tex_written(struct fgl_context *ctx, const struct fgl_texture_object *t,
                     const struct fgl_texture_image *img);

/* main/clear.c (GL_COLOR_BUFFER_BIT) */
void fgl_init_color(struct fgl_context *ctx);

/* main/accum.c (GL_ACCUM_BUFFER_BIT) */
void fgl_init_accum(struct fgl_context *ctx);
/* glClear's GL_ACCUM_BUFFER_BIT: the scissored bounds to the clear value */
void fgl_clear_accum_buffer(struct fgl_context *ctx);

/* main/blend.c (GL_COLOR_BUFFER_BIT: alpha test, blending, logic op,
 * colour mask) */
void fgl_init_blend(struct fgl_context *ctx);

/* main/scissor.c (GL_SCISSOR_BIT) */
void fgl_init_scissor(struct fgl_context *ctx);
void fgl_set_scissor(struct fgl_context *ctx, int x, int y, int width, int height);
/* the scissored draw bounds (Mesa's _Xmin, _Xmax, _Ymin, _Ymax), y-up */
void fgl_scissor_bounds(const struct fgl_context *ctx, int bbox[4]);
/* the draw region of primitives: x0, y0, x1, y1, y-down, exclusive */
void fgl_scissor_draw_region(const struct fgl_context *ctx, int region[4]);

/* main/stencil.c (GL_STENCIL_BUFFER_BIT) */
void fgl_init_stencil(struct fgl_context *ctx);
/* _mesa_get_stencil_ref: the reference clamped to the buffer's range */
int fgl_stencil_ref(const struct fgl_context *ctx);

/* main/depth.c (GL_DEPTH_BUFFER_BIT) */
void fgl_init_depth(struct fgl_context *ctx);

/* main/fog.c (GL_FOG_BIT) */
void fgl_init_fog(struct fgl_context *ctx);

/* main/hint.c (GL_HINT_BIT) */
void fgl_init_hint(struct fgl_context *ctx);
/* the value of hint target; false for a target glHint refuses */
bool fgl_get_hint(struct fgl_context *ctx, GLenum target, GLenum *value);

/* main/light.c (GL_LIGHTING_BIT) */
void fgl_init_light(struct fgl_context *ctx);
/* _mesa_update_color_material: the materials that track the colour */
void fgl_update_color_material(struct fgl_context *ctx, const float color[4]);
void fgl_set_color_material_enabled(struct fgl_context *ctx, bool state);
/* _mesa_update_lighting, _mesa_update_tnl_spaces, compute_light_positions */
void fgl_update_lighting(struct fgl_context *ctx);

/* main/polygon.c (GL_POLYGON_BIT) */
void fgl_init_polygon(struct fgl_context *ctx);

/* main/clip.c (user clip planes, GL_TRANSFORM_BIT): the clip-space planes
 * of the enabled GL_CLIP_PLANEi from the eye planes and the projection */
void fgl_update_clip_planes(struct fgl_context *ctx);

/* main/pixelstore.c (GL_CLIENT_PIXEL_STORE_BIT): defaults, and the
 * GL_BITMAP packing of the polygon stipple with a pixel-store state */
void fgl_init_pixelstore(struct fgl_context *ctx);
void fgl_unpack_stipple(const struct fgl_pixelstore *p, const uint8_t *pattern,
                        uint32_t dest[32]);
void fgl_pack_stipple(const struct fgl_pixelstore *p, const uint32_t pattern[32],
                      uint8_t *dest);
/* main/points.c (GL_POINT_BIT), main/lines.c (GL_LINE_BIT) */
void fgl_init_point(struct fgl_context *ctx);
void fgl_init_eval(struct fgl_context *ctx);
/* the flag of an evaluator capability (GL_MAPn_*, GL_AUTO_NORMAL), or NULL */
bool *fgl_eval_cap_flag(struct fgl_context *ctx, GLenum cap);
/* _mesa_evaluator_components: 0 for a target that is no map */
unsigned fgl_eval_components(GLenum target);
void fgl_init_line(struct fgl_context *ctx);

/* main/viewport.c (GL_VIEWPORT_BIT) */
void fgl_init_viewport(struct fgl_context *ctx);
void fgl_set_viewport(struct fgl_context *ctx, int x, int y, int width, int height);

/* main/misc.c: make the framebuffer's content visible to the application
 * (glFlush/glFinish). */
void fgl_flush_front(struct fgl_context *ctx);
/* main/drawpix.c: draw the bitmaps glBitmap has accumulated
 * [S: st_cb_bitmap.c:st_flush_bitmap_cache]; every draw, clear, pixel
 * read or copy, scissor change and flush calls it first */
void fgl_flush_bitmap_cache(struct fgl_context *ctx);
/* main/drawpix.c: frees glDrawPixels' image cache */
void fgl_free_drawpix_cache(struct fgl_context *ctx);

/* main/enable.c: whether pname is a capability; its state in *value */
bool fgl_is_cap(struct fgl_context *ctx, GLenum pname, double *value);
bool fgl_set_enable(struct fgl_context *ctx, GLenum cap, bool state);
bool fgl_texture_target_enabled(const struct fgl_context *ctx, unsigned unit, GLenum target);

/* main/rastpos.c: the replay of a compiled glWindowPos (Mesa's
 * glWindowPos4fMESA) */
void fgl_window_pos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w);

/* main/feedback.c (selection and feedback) */
void fgl_init_feedback(struct fgl_context *ctx);
/* glGet of GL_RENDER_MODE, the name stack and the buffer sizes and type */
bool fgl_get_feedback_value(struct fgl_context *ctx, GLenum pname, int *value);

#endif
