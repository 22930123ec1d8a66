/*
 * Display lists (main/dlist.c): the hooks that GL entry points use while
 * a list is being compiled.
 *
 * Mesa switches the dispatch table to its "save" functions between
 * glNewList and glEndList [S: main/dlist.c:_mesa_NewList].  fixgl keeps
 * one entry point per command, and a compiled command starts with one
 * hook: while ctx->CompileFlag is set, FGL_SAVE stores the call (through
 * the save function generated from main/dlist_ops.h, or a hand-written
 * one for the commands that need more) and returns, unless the list is
 * GL_COMPILE_AND_EXECUTE, where the entry point goes on to execute it.
 * While a list executes (glCallList), CompileFlag is off, as in Mesa, so
 * the replayed calls execute.
 */
#ifndef FGL_MAIN_DLIST_H
#define FGL_MAIN_DLIST_H

#include "context.h"

/* argument kinds of dlist_ops.h: the C type of the parameter */
#define DL_CT_E  GLenum
#define DL_CT_I  GLint
#define DL_CT_SZ GLsizei
#define DL_CT_U  GLuint
#define DL_CT_F  GLfloat
#define DL_CT_B  GLboolean
#define DL_CT_BF GLbitfield
#define DL_CT_US GLushort
#define DL_CT_D  GLdouble
#define DL_CT_UB GLubyte
#define DL_CT_FU GLfloat

/* Prototypes: fgl_save_Name(ctx, args) stores the call and returns whether
 * the entry point goes on to execute it; fgl_dl_put_Name only stores (the
 * hand-written save functions of the DL_CUSTOM commands call it). */
#define DL_PUT_PROTO(Name, ...) void fgl_dl_put_##Name(struct fgl_context *ctx, __VA_ARGS__);
#define DL_SAVE_PROTO(Name, ...) bool fgl_save_##Name(struct fgl_context *ctx, __VA_ARGS__);
#define DL_PROTO(Name, ...) DL_PUT_PROTO(Name, __VA_ARGS__) DL_SAVE_PROTO(Name, __VA_ARGS__)
#define DL_OP0(Name)                                                            \
   void fgl_dl_put_##Name(struct fgl_context *ctx);                             \
   bool fgl_save_##Name(struct fgl_context *ctx);
#define DL_OP1(Name, A) DL_PROTO(Name, DL_CT_##A)
#define DL_OP2(Name, A, B) DL_PROTO(Name, DL_CT_##A, DL_CT_##B)
#define DL_OP3(Name, A, B, C) DL_PROTO(Name, DL_CT_##A, DL_CT_##B, DL_CT_##C)
#define DL_OP4(Name, A, B, C, D_) DL_PROTO(Name, DL_CT_##A, DL_CT_##B, DL_CT_##C, DL_CT_##D_)
#define DL_OP5(Name, A, B, C, D_, E_)                                           \
   DL_PROTO(Name, DL_CT_##A, DL_CT_##B, DL_CT_##C, DL_CT_##D_, DL_CT_##E_)
#define DL_OP6(Name, A, B, C, D_, E_, F_)                                        \
   DL_PROTO(Name, DL_CT_##A, DL_CT_##B, DL_CT_##C, DL_CT_##D_, DL_CT_##E_, DL_CT_##F_)
#define DL_OPV0(Name, VT, N) DL_PROTO(Name, const DL_CT_##VT *, unsigned)
#define DL_OPV1(Name, A, VT, N) DL_PROTO(Name, DL_CT_##A, const DL_CT_##VT *, unsigned)
#define DL_OPV2(Name, A, B, VT, N)                                              \
   DL_PROTO(Name, DL_CT_##A, DL_CT_##B, const DL_CT_##VT *, unsigned)
#define DL_CUSTOM0(Name) void fgl_dl_put_##Name(struct fgl_context *ctx);
#define DL_CUSTOM1(Name, A) DL_PUT_PROTO(Name, DL_CT_##A)
#define DL_CUSTOMV2(Name, A, B, VT, N)                                          \
   DL_PUT_PROTO(Name, DL_CT_##A, DL_CT_##B, const DL_CT_##VT *, unsigned)
#include "main/dlist_ops.h"
#include "main/dlist_ops_undef.h"
#undef DL_PROTO
#undef DL_PUT_PROTO
#undef DL_SAVE_PROTO

/* The replay of a glPrioritizeTextures node: Mesa compiles one node per
 * name and replays each as glPrioritizeTextures(1, &name, &priority)
 * [S: dlist.c:save_PrioritizeTextures, OPCODE_PRIORITIZE_TEXTURE]. */
static inline void glPrioritizeTexture1(GLuint texture, GLfloat priority)
{
   glPrioritizeTextures(1, &texture, &priority);
}

/* The hook at the top of a compiled entry point (after its context
 * fetch): store the call while compiling, and return unless the list is
 * GL_COMPILE_AND_EXECUTE. */
#define FGL_SAVE(ctx, Name, ...)                                                \
   do {                                                                         \
      if ((ctx)->CompileFlag && !fgl_save_##Name((ctx), __VA_ARGS__))           \
         return;                                                                \
   } while (0)
#define FGL_SAVE0(ctx, Name)                                                    \
   do {                                                                         \
      if ((ctx)->CompileFlag && !fgl_save_##Name(ctx))                          \
         return;                                                                \
   } while (0)

/* Hand-written save functions (Mesa's vbo_save_api.c and the dlist.c
 * functions that do more than store).  Each one does everything Mesa's
 * save function does, including executing under
 * GL_COMPILE_AND_EXECUTE: the entry point returns after it. */
void fgl_save_attr(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned n,
                   float x, float y, float z, float w);
void fgl_save_begin(struct fgl_context *ctx, GLenum mode);
void fgl_save_end(struct fgl_context *ctx);
void fgl_save_rect(struct fgl_context *ctx, float x1, float y1, float x2, float y2);
void fgl_save_material(struct fgl_context *ctx, GLenum face, GLenum pname,
                       const GLfloat *params);
void fgl_save_shade_model(struct fgl_context *ctx, GLenum mode);
void fgl_save_draw_arrays(struct fgl_context *ctx, GLenum mode, GLint first, GLsizei count);
void fgl_save_draw_elements(struct fgl_context *ctx, GLenum mode, GLsizei count,
                            GLenum type, const GLvoid *indices);
void fgl_save_draw_range_elements(struct fgl_context *ctx, GLenum mode, GLuint start,
                                  GLuint end, GLsizei count, GLenum type,
                                  const GLvoid *indices);
void fgl_save_multi_draw_arrays(struct fgl_context *ctx, GLenum mode, const GLint *first,
                                const GLsizei *count, GLsizei n);
void fgl_save_multi_draw_elements(struct fgl_context *ctx, GLenum mode, const GLsizei *count,
                                  GLenum type, const GLvoid *const *indices, GLsizei n);
void fgl_save_call_list(struct fgl_context *ctx, GLuint list);
/* the evaluator commands (main/eval.c); these return whether the entry
 * point goes on to execute, as the FGL_SAVE functions do */
bool fgl_save_map1(struct fgl_context *ctx, GLenum target, GLfloat u1, GLfloat u2,
                   GLint stride, GLint order, const GLfloat *pf, const GLdouble *pd);
bool fgl_save_map2(struct fgl_context *ctx, GLenum target, GLfloat u1, GLfloat u2,
                   GLint ustride, GLint uorder, GLfloat v1, GLfloat v2, GLint vstride,
                   GLint vorder, const GLfloat *pf, const GLdouble *pd);
bool fgl_save_eval_coord1(struct fgl_context *ctx, GLfloat u);
bool fgl_save_eval_coord2(struct fgl_context *ctx, GLfloat u, GLfloat v);
bool fgl_save_eval_point1(struct fgl_context *ctx, GLint i);
bool fgl_save_eval_point2(struct fgl_context *ctx, GLint i, GLint j);
void fgl_save_call_lists(struct fgl_context *ctx, GLsizei n, GLenum type, const GLvoid *lists);
bool fgl_save_prioritize_textures(struct fgl_context *ctx, GLsizei n, const GLuint *textures,
                                  const GLclampf *priorities);
/* glBitmap and glDrawPixels (main/drawpix.c keeps their images) */
bool fgl_save_bitmap(struct fgl_context *ctx, GLsizei width, GLsizei height, GLfloat xorig,
                     GLfloat yorig, GLfloat xmove, GLfloat ymove, const GLubyte *bits);
bool fgl_save_drawpixels(struct fgl_context *ctx, GLsizei width, GLsizei height,
                         GLenum format, GLenum type, const GLvoid *pixels);
uint8_t *fgl_make_bitmap_texture(const struct fgl_context *ctx, GLsizei width,
                                 GLsizei height, const GLubyte *bits);
void fgl_exec_list_bitmap(struct fgl_context *ctx, GLsizei width, GLsizei height,
                          GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
                          const uint8_t *tex);
GLvoid *fgl_pack_list_image(const struct fgl_context *ctx, GLsizei width, GLsizei height,
                            GLenum format, GLenum type, const GLvoid *pixels);
void fgl_exec_list_drawpixels(struct fgl_context *ctx, GLsizei width, GLsizei height,
                              GLenum format, GLenum type, const GLvoid *pixels);
/* the texture image commands (main/teximage.c); these return whether the
 * entry point goes on to execute */
bool fgl_save_tex_image(struct fgl_context *ctx, GLuint dims, GLenum target, GLint level,
                        GLint internal, GLsizei width, GLsizei height, GLint border,
                        GLenum format, GLenum type, const void *pixels);
bool fgl_save_tex_sub_image(struct fgl_context *ctx, GLuint dims, GLenum target, GLint level,
                            GLint xoffset, GLint yoffset, GLsizei width, GLsizei height,
                            GLenum format, GLenum type, const void *pixels);
bool fgl_save_copy_tex_image(struct fgl_context *ctx, GLuint dims, GLenum target,
                             GLint level, GLenum internal, GLint x, GLint y, GLsizei width,
                             GLsizei height, GLint border);
bool fgl_save_copy_tex_sub_image(struct fgl_context *ctx, GLuint dims, GLenum target,
                                 GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y,
                                 GLsizei width, GLsizei height);
/* the same for glTexImage3D, glTexSubImage3D, glCopyTexSubImage3D */
bool fgl_save_tex_image_3d(struct fgl_context *ctx, GLenum target, GLint level,
                           GLint internal, GLsizei width, GLsizei height, GLsizei depth,
                           GLint border, GLenum format, GLenum type, const void *pixels);
bool fgl_save_tex_sub_image_3d(struct fgl_context *ctx, GLenum target, GLint level,
                               GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width,
                               GLsizei height, GLsizei depth, GLenum format, GLenum type,
                               const void *pixels);
/* glCompressedTexImage1D/2D/3D (sub false; `format` the internal format,
 * offsets 0) and glCompressedTexSubImage1D/2D/3D (sub true) */
bool fgl_save_compressed_tex(struct fgl_context *ctx, GLuint dims, bool sub, GLenum target,
                             GLint level, GLenum format, GLint x, GLint y, GLint z, GLsizei w,
                             GLsizei h, GLsizei d, GLint border, GLsizei image_size,
                             const void *data);
bool fgl_save_copy_tex_sub_image_3d(struct fgl_context *ctx, GLenum target, GLint level,
                                    GLint xoffset, GLint yoffset, GLint zoffset, GLint x,
                                    GLint y, GLsizei width, GLsizei height);

/* A vertex attribute call (glVertex, glColor, glNormal, glEdgeFlag,
 * glArrayElement's attributes): compiled while compiling, else executed. */
static inline void fgl_attr(struct fgl_context *ctx, enum fgl_vbo_attr attr, unsigned n,
                            float x, float y, float z, float w)
{
   bool wrap = false;
   if (ctx->CompileFlag)
      fgl_save_attr(ctx, attr, n, x, y, z, w);
   else if (!fgl_vbo_attr_fast(&ctx->Vbo, attr, n, x, y, z, w, &wrap))
      fgl_vbo_attr(ctx, attr, n, x, y, z, w);
   else if (wrap)
      fgl_vbo_wrap(ctx);
}

/* Executing glBegin/glEnd without the hooks (main/begin_end.c), for the
 * vertex-list replay. */
void fgl_exec_begin(struct fgl_context *ctx, GLenum mode);
void fgl_exec_end(struct fgl_context *ctx);

/* Context lifetime and queries */
bool fgl_init_dlist(struct fgl_context *ctx);
void fgl_free_dlist(struct fgl_context *ctx);
/* OSMesaCreateContext's sharelist: ctx uses share's lists from now on */
void fgl_share_dlists(struct fgl_context *ctx, struct fgl_context *share);
/* glGet of GL_LIST_BASE, GL_LIST_INDEX, GL_LIST_MODE, GL_MAX_LIST_NESTING */
bool fgl_get_list_value(const struct fgl_context *ctx, GLenum pname, int *value);

#endif
