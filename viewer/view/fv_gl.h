/*
 * The GL functions the viewer's scene calls, as a table of pointers: the
 * same drawing code renders with fixgl (the table holds libfixgl's own gl*,
 * which the viewer links) or with Mesa's OSMesa (loaded at run time with
 * dlopen, the table filled through dlsym/OSMesaGetProcAddress, see
 * fv_osmesa.h), so that both sides receive exactly the same calls.
 */
#ifndef FV_GL_H
#define FV_GL_H

#include <GL/gl.h>

/* X(return type, name without the gl prefix, parameter list) */
#define FV_GL_FUNCS(X)                                                              \
   X(void, Enable, (GLenum cap))                                                    \
   X(void, Disable, (GLenum cap))                                                   \
   X(void, ShadeModel, (GLenum mode))                                               \
   X(void, Hint, (GLenum target, GLenum mode))                                      \
   X(void, Clear, (GLbitfield mask))                                                \
   X(void, ClearColor, (GLclampf r, GLclampf g, GLclampf b, GLclampf a))            \
   X(void, Viewport, (GLint x, GLint y, GLsizei w, GLsizei h))                      \
   X(void, MatrixMode, (GLenum mode))                                               \
   X(void, LoadMatrixf, (const GLfloat *m))                                         \
   X(void, LoadIdentity, (void))                                                    \
   X(void, Lightfv, (GLenum light, GLenum pname, const GLfloat *params))            \
   X(void, Lightf, (GLenum light, GLenum pname, GLfloat param))                     \
   X(void, LightModelfv, (GLenum pname, const GLfloat *params))                     \
   X(void, LightModeli, (GLenum pname, GLint param))                                \
   X(void, Materialfv, (GLenum face, GLenum pname, const GLfloat *params))          \
   X(void, Materialf, (GLenum face, GLenum pname, GLfloat param))                   \
   X(void, Materiali, (GLenum face, GLenum pname, GLint param))                     \
   X(void, PolygonMode, (GLenum face, GLenum mode))                                 \
   X(void, CullFace, (GLenum mode))                                                 \
   X(void, FrontFace, (GLenum mode))                                                \
   X(void, DepthFunc, (GLenum func))                                                \
   X(void, DepthMask, (GLboolean flag))                                             \
   X(void, ColorMask, (GLboolean r, GLboolean g, GLboolean b, GLboolean a))         \
   X(void, BlendFunc, (GLenum sfactor, GLenum dfactor))                             \
   X(void, EnableClientState, (GLenum array))                                       \
   X(void, DisableClientState, (GLenum array))                                      \
   X(void, VertexPointer, (GLint size, GLenum type, GLsizei stride, const GLvoid *p)) \
   X(void, NormalPointer, (GLenum type, GLsizei stride, const GLvoid *p))           \
   X(void, DrawElements, (GLenum mode, GLsizei count, GLenum type, const GLvoid *i)) \
   X(void, TexCoordPointer, (GLint size, GLenum type, GLsizei stride, const GLvoid *p)) \
   X(void, ColorPointer, (GLint size, GLenum type, GLsizei stride, const GLvoid *p)) \
   X(void, ColorMaterial, (GLenum face, GLenum mode))                               \
   X(void, GenTextures, (GLsizei n, GLuint *textures))                              \
   X(void, DeleteTextures, (GLsizei n, const GLuint *textures))                     \
   X(void, BindTexture, (GLenum target, GLuint texture))                            \
   X(void, TexParameteri, (GLenum target, GLenum pname, GLint param))               \
   X(void, TexEnvi, (GLenum target, GLenum pname, GLint param))                     \
   X(void, PixelStorei, (GLenum pname, GLint param))                                \
   X(void, TexImage2D, (GLenum target, GLint level, GLint internal, GLsizei w,      \
                        GLsizei h, GLint border, GLenum format, GLenum type,        \
                        const GLvoid *pixels))                                      \
   X(void, Color4fv, (const GLfloat *v))                                            \
   X(void, Finish, (void))                                                          \
   X(GLenum, GetError, (void))                                                      \
   X(const GLubyte *, GetString, (GLenum name))                                     \
   X(void, GetIntegerv, (GLenum pname, GLint *params))

struct fv_gl {
#define FV_GL_MEMBER(ret, name, params) ret (*name) params;
   FV_GL_FUNCS(FV_GL_MEMBER)
#undef FV_GL_MEMBER
};

/* A function's address by its GL name ("glEnable"), or NULL. */
typedef void (*fv_proc)(void);
typedef fv_proc (*fv_getproc)(const char *name);

/* The table of libfixgl's own entry points. */
void fv_gl_fixgl(struct fv_gl *gl);

/* Fills the table through getproc; returns 0, or -1 naming the first
 * missing function on stderr. */
int fv_gl_load(struct fv_gl *gl, fv_getproc getproc);

/* Whether the context's GL_EXTENSIONS lists ext (a whole word). */
int fv_gl_has_extension(const struct fv_gl *gl, const char *ext);

#endif
