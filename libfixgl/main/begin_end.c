/*
 * glBegin/glEnd and the per-vertex attribute calls (GL_CURRENT_BIT state).
 *
 * Integer colours are normalized with Mesa's macros (main/macros.h,
 * confirmed exhaustively against the oracle): signed types map (2c+1)/(2^n-1),
 * unsigned bytes use i/255.0f, other unsigned types multiply by the
 * reciprocal.  Double arguments are converted to float first.
 */
/* the GL 1.4 calls are declared by <GL/glext.h> only with
 * GL_GLEXT_PROTOTYPES: asking for the prototypes checks the definitions
 * below against them (and exports them: GLAPI) */
#define GL_GLEXT_PROTOTYPES 1
#include <string.h>

#include "main/conv.h"
#include "main/dlist.h"
#include "main/groups.h"

void fgl_init_current(struct fgl_context *ctx)
{
   static const float init[FGL_ATTR_COUNT][4] = {
      [FGL_ATTR_NORMAL] = { 0, 0, 1, 1 },
      [FGL_ATTR_COLOR0] = { 1, 1, 1, 1 },
      [FGL_ATTR_COLOR1] = { 0, 0, 0, 1 },
      [FGL_ATTR_FOG] = { 0, 0, 0, 1 },
      [FGL_ATTR_COLOR_INDEX] = { 1, 0, 0, 1 },
      [FGL_ATTR_TEX0] = { 0, 0, 0, 1 }, [FGL_ATTR_TEX1] = { 0, 0, 0, 1 },
      [FGL_ATTR_TEX2] = { 0, 0, 0, 1 }, [FGL_ATTR_TEX3] = { 0, 0, 0, 1 },
      [FGL_ATTR_TEX4] = { 0, 0, 0, 1 }, [FGL_ATTR_TEX5] = { 0, 0, 0, 1 },
      [FGL_ATTR_TEX6] = { 0, 0, 0, 1 }, [FGL_ATTR_TEX7] = { 0, 0, 0, 1 },
      [FGL_ATTR_EDGEFLAG] = { 1, 0, 0, 1 },
      [FGL_ATTR_MAT_FRONT_AMBIENT] = { 0.2f, 0.2f, 0.2f, 1.0f },
      [FGL_ATTR_MAT_BACK_AMBIENT] = { 0.2f, 0.2f, 0.2f, 1.0f },
      [FGL_ATTR_MAT_FRONT_DIFFUSE] = { 0.8f, 0.8f, 0.8f, 1.0f },
      [FGL_ATTR_MAT_BACK_DIFFUSE] = { 0.8f, 0.8f, 0.8f, 1.0f },
      [FGL_ATTR_MAT_FRONT_SPECULAR] = { 0, 0, 0, 1 },
      [FGL_ATTR_MAT_BACK_SPECULAR] = { 0, 0, 0, 1 },
      [FGL_ATTR_MAT_FRONT_EMISSION] = { 0, 0, 0, 1 },
      [FGL_ATTR_MAT_BACK_EMISSION] = { 0, 0, 0, 1 },
      [FGL_ATTR_MAT_FRONT_SHININESS] = { 0, 0, 0, 0 },
      [FGL_ATTR_MAT_BACK_SHININESS] = { 0, 0, 0, 0 },
      [FGL_ATTR_MAT_FRONT_INDEXES] = { 0, 1, 1, 0 },
      [FGL_ATTR_MAT_BACK_INDEXES] = { 0, 1, 1, 0 },
   };
   memcpy(ctx->Current.Attrib, init, sizeof(init));
}

/* ---- glBegin / glEnd ---- */

void fgl_exec_begin(struct fgl_context *ctx, GLenum mode)
{
   if (fgl_inside_begin_end(ctx)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   if (mode > GL_POLYGON) {
      /* GL 1.5's ten modes; the oracle's 4.5 context also takes the
       * adjacency modes and patches (README "Version and honesty") */
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   fgl_update_state(ctx);
   fgl_vbo_begin(ctx, mode);
   ctx->BeginMode = mode;
   ctx->ExecBeginEnd = true;
}

void fgl_exec_end(struct fgl_context *ctx)
{
   if (!fgl_inside_begin_end(ctx)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   ctx->ExecBeginEnd = false;
   fgl_vbo_end(ctx);
}

void GLAPIENTRY glBegin(GLenum mode)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      fgl_save_begin(ctx, mode);
      return;
   }
   fgl_exec_begin(ctx, mode);
}

void GLAPIENTRY glEnd(void)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      fgl_save_end(ctx);
      return;
   }
   fgl_exec_end(ctx);
}

/* ---- attributes ---- */

static inline void color4(float r, float g, float b, float a, unsigned n)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_attr(ctx, FGL_ATTR_COLOR0, n, r, g, b, a);
}

static inline void vertex4(float x, float y, float z, float w, unsigned n)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_attr(ctx, FGL_ATTR_POS, n, x, y, z, w);
}

#define IDENT(x)           ((GLfloat)(x))

/* Only glColor3f/3fv are 3-component calls in Mesa's vbo; every other
 * variant goes through glColor4f with alpha 1 (api_loopback.c), which
 * matters for how the attribute's size is tracked (t_vbo.c). */
#define COLOR_FUNCS(suffix, type, CONV, N3)                                     \
   void GLAPIENTRY glColor3##suffix(type r, type g, type b)                     \
   { color4(CONV(r), CONV(g), CONV(b), 1.0f, N3); }                             \
   void GLAPIENTRY glColor4##suffix(type r, type g, type b, type a)             \
   { color4(CONV(r), CONV(g), CONV(b), CONV(a), 4); }                           \
   void GLAPIENTRY glColor3##suffix##v(const type *v)                           \
   { if (v) color4(CONV(v[0]), CONV(v[1]), CONV(v[2]), 1.0f, N3); }             \
   void GLAPIENTRY glColor4##suffix##v(const type *v)                           \
   { if (v) color4(CONV(v[0]), CONV(v[1]), CONV(v[2]), CONV(v[3]), 4); }

COLOR_FUNCS(b, GLbyte, BYTE_TO_FLOAT, 4)
COLOR_FUNCS(ub, GLubyte, UBYTE_TO_FLOAT, 4)
COLOR_FUNCS(s, GLshort, SHORT_TO_FLOAT, 4)
COLOR_FUNCS(us, GLushort, USHORT_TO_FLOAT, 4)
COLOR_FUNCS(i, GLint, INT_TO_FLOAT, 4)
COLOR_FUNCS(ui, GLuint, UINT_TO_FLOAT, 4)
COLOR_FUNCS(f, GLfloat, IDENT, 3)
COLOR_FUNCS(d, GLdouble, IDENT, 4)

static inline void normal3(float x, float y, float z)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_attr(ctx, FGL_ATTR_NORMAL, 3, x, y, z, 1.0f);
}

/* glNormal3*: three components, integers normalized like colours
 * (vbo_attrib_tmp.h) */
#define NORMAL_FUNCS(suffix, type, CONV)                                        \
   void GLAPIENTRY glNormal3##suffix(type x, type y, type z)                    \
   { normal3(CONV(x), CONV(y), CONV(z)); }                                      \
   void GLAPIENTRY glNormal3##suffix##v(const type *v)                          \
   { if (v) normal3(CONV(v[0]), CONV(v[1]), CONV(v[2])); }

NORMAL_FUNCS(b, GLbyte, BYTE_TO_FLOAT)
NORMAL_FUNCS(s, GLshort, SHORT_TO_FLOAT)
NORMAL_FUNCS(i, GLint, INT_TO_FLOAT)
NORMAL_FUNCS(f, GLfloat, IDENT)
NORMAL_FUNCS(d, GLdouble, IDENT)

#define VERTEX_FUNCS(suffix, type)                                              \
   void GLAPIENTRY glVertex2##suffix(type x, type y)                            \
   { vertex4((GLfloat)x, (GLfloat)y, 0.0f, 1.0f, 2); }                          \
   void GLAPIENTRY glVertex3##suffix(type x, type y, type z)                    \
   { vertex4((GLfloat)x, (GLfloat)y, (GLfloat)z, 1.0f, 3); }                    \
   void GLAPIENTRY glVertex4##suffix(type x, type y, type z, type w)            \
   { vertex4((GLfloat)x, (GLfloat)y, (GLfloat)z, (GLfloat)w, 4); }              \
   void GLAPIENTRY glVertex2##suffix##v(const type *v)                          \
   { if (v) vertex4((GLfloat)v[0], (GLfloat)v[1], 0.0f, 1.0f, 2); }             \
   void GLAPIENTRY glVertex3##suffix##v(const type *v)                          \
   { if (v) vertex4((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2], 1.0f, 3); }    \
   void GLAPIENTRY glVertex4##suffix##v(const type *v)                          \
   { if (v) vertex4((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2], (GLfloat)v[3], 4); }

VERTEX_FUNCS(s, GLshort)
VERTEX_FUNCS(i, GLint)
VERTEX_FUNCS(f, GLfloat)
VERTEX_FUNCS(d, GLdouble)

/* glTexCoord{1,2,3,4}{s,i,f,d}[v]: texture unit 0's coordinate with as many
 * components as the call names (the missing ones 0, 0, 1), integers and
 * doubles cast to float, never normalized [S: vbo/vbo_attrib_tmp.h:
 * TAG(TexCoord1f..4fv); main/api_loopback.c:_mesa_TexCoord1d.. call
 * TexCoordNf with the same N]. */
static inline void texcoord4(float s, float t, float r, float q, unsigned n)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_attr(ctx, FGL_ATTR_TEX0, n, s, t, r, q);
}

#define TEXCOORD_FUNCS(suffix, type)                                            \
   void GLAPIENTRY glTexCoord1##suffix(type s)                                  \
   { texcoord4((GLfloat)s, 0.0f, 0.0f, 1.0f, 1); }                              \
   void GLAPIENTRY glTexCoord2##suffix(type s, type t)                          \
   { texcoord4((GLfloat)s, (GLfloat)t, 0.0f, 1.0f, 2); }                        \
   void GLAPIENTRY glTexCoord3##suffix(type s, type t, type r)                  \
   { texcoord4((GLfloat)s, (GLfloat)t, (GLfloat)r, 1.0f, 3); }                  \
   void GLAPIENTRY glTexCoord4##suffix(type s, type t, type r, type q)          \
   { texcoord4((GLfloat)s, (GLfloat)t, (GLfloat)r, (GLfloat)q, 4); }            \
   void GLAPIENTRY glTexCoord1##suffix##v(const type *v)                        \
   { if (v) texcoord4((GLfloat)v[0], 0.0f, 0.0f, 1.0f, 1); }                    \
   void GLAPIENTRY glTexCoord2##suffix##v(const type *v)                        \
   { if (v) texcoord4((GLfloat)v[0], (GLfloat)v[1], 0.0f, 1.0f, 2); }           \
   void GLAPIENTRY glTexCoord3##suffix##v(const type *v)                        \
   { if (v) texcoord4((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2], 1.0f, 3); }  \
   void GLAPIENTRY glTexCoord4##suffix##v(const type *v)                        \
   { if (v) texcoord4((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2], (GLfloat)v[3], 4); }

TEXCOORD_FUNCS(s, GLshort)
TEXCOORD_FUNCS(i, GLint)
TEXCOORD_FUNCS(f, GLfloat)
TEXCOORD_FUNCS(d, GLdouble)

/* glMultiTexCoord{1,2,3,4}{s,i,f,d}[v] (GL 1.3) and their ARB aliases:
 * texture unit (target & 7)'s coordinate.  The vbo never checks the
 * target: any value, GL_TEXTURE8 or 0 included, selects a unit by its low
 * three bits, without an error [S: vbo/vbo_attrib_tmp.h:
 * TAG(MultiTexCoord1f..4fv): attr = (target & 0x7) + VBO_ATTRIB_TEX0;
 * main/api_loopback.c:_mesa_MultiTexCoord1d.. call MultiTexCoordNf]. */
static inline void multi_texcoord4(GLenum target, float s, float t, float r, float q,
                                   unsigned n)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_attr(ctx, (enum fgl_vbo_attr)(FGL_ATTR_TEX0 + (target & 7u)), n, s, t, r, q);
}

#define MULTI_TEXCOORD_FUNCS(suffix, type, ARB)                                  \
   void GLAPIENTRY glMultiTexCoord1##suffix##ARB(GLenum u, type s)               \
   { multi_texcoord4(u, (GLfloat)s, 0.0f, 0.0f, 1.0f, 1); }                      \
   void GLAPIENTRY glMultiTexCoord2##suffix##ARB(GLenum u, type s, type t)       \
   { multi_texcoord4(u, (GLfloat)s, (GLfloat)t, 0.0f, 1.0f, 2); }                \
   void GLAPIENTRY glMultiTexCoord3##suffix##ARB(GLenum u, type s, type t, type r) \
   { multi_texcoord4(u, (GLfloat)s, (GLfloat)t, (GLfloat)r, 1.0f, 3); }          \
   void GLAPIENTRY glMultiTexCoord4##suffix##ARB(GLenum u, type s, type t, type r, \
                                                 type q)                         \
   { multi_texcoord4(u, (GLfloat)s, (GLfloat)t, (GLfloat)r, (GLfloat)q, 4); }    \
   void GLAPIENTRY glMultiTexCoord1##suffix##v##ARB(GLenum u, const type *v)     \
   { if (v) multi_texcoord4(u, (GLfloat)v[0], 0.0f, 0.0f, 1.0f, 1); }            \
   void GLAPIENTRY glMultiTexCoord2##suffix##v##ARB(GLenum u, const type *v)     \
   { if (v) multi_texcoord4(u, (GLfloat)v[0], (GLfloat)v[1], 0.0f, 1.0f, 2); }   \
   void GLAPIENTRY glMultiTexCoord3##suffix##v##ARB(GLenum u, const type *v)     \
   { if (v) multi_texcoord4(u, (GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2],      \
                            1.0f, 3); }                                          \
   void GLAPIENTRY glMultiTexCoord4##suffix##v##ARB(GLenum u, const type *v)     \
   { if (v) multi_texcoord4(u, (GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2],      \
                            (GLfloat)v[3], 4); }

MULTI_TEXCOORD_FUNCS(s, GLshort, )
MULTI_TEXCOORD_FUNCS(i, GLint, )
MULTI_TEXCOORD_FUNCS(f, GLfloat, )
MULTI_TEXCOORD_FUNCS(d, GLdouble, )
MULTI_TEXCOORD_FUNCS(s, GLshort, ARB)
MULTI_TEXCOORD_FUNCS(i, GLint, ARB)
MULTI_TEXCOORD_FUNCS(f, GLfloat, ARB)
MULTI_TEXCOORD_FUNCS(d, GLdouble, ARB)

/* glSecondaryColor3* (GL 1.4) and their EXT aliases: the vbo attribute
 * COLOR1, always three components (alpha keeps its current 1), integers
 * normalized as glColor's [S: main/api_loopback.c:_mesa_SecondaryColor3b..
 * call SecondaryColor3fEXT; vbo/vbo_attrib_tmp.h:TAG(SecondaryColor3fEXT):
 * ATTR3F(VBO_ATTRIB_COLOR1)]. */
static inline void secondary_color3(float r, float g, float b)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_attr(ctx, FGL_ATTR_COLOR1, 3, r, g, b, 1.0f);
}

#define SECONDARY_COLOR_FUNCS(suffix, type, CONV, EXT)                          \
   void GLAPIENTRY glSecondaryColor3##suffix##EXT(type r, type g, type b)       \
   { secondary_color3(CONV(r), CONV(g), CONV(b)); }                             \
   void GLAPIENTRY glSecondaryColor3##suffix##v##EXT(const type *v)             \
   { if (v) secondary_color3(CONV(v[0]), CONV(v[1]), CONV(v[2])); }

#define SECONDARY_COLOR_ALL(EXT)                                                \
   SECONDARY_COLOR_FUNCS(b, GLbyte, BYTE_TO_FLOAT, EXT)                         \
   SECONDARY_COLOR_FUNCS(ub, GLubyte, UBYTE_TO_FLOAT, EXT)                      \
   SECONDARY_COLOR_FUNCS(s, GLshort, SHORT_TO_FLOAT, EXT)                       \
   SECONDARY_COLOR_FUNCS(us, GLushort, USHORT_TO_FLOAT, EXT)                    \
   SECONDARY_COLOR_FUNCS(i, GLint, INT_TO_FLOAT, EXT)                           \
   SECONDARY_COLOR_FUNCS(ui, GLuint, UINT_TO_FLOAT, EXT)                        \
   SECONDARY_COLOR_FUNCS(f, GLfloat, IDENT, EXT)                                \
   SECONDARY_COLOR_FUNCS(d, GLdouble, IDENT, EXT)

SECONDARY_COLOR_ALL()
SECONDARY_COLOR_ALL(EXT)

/* glFogCoord{f,d}[v] (GL 1.4) and their EXT aliases: the one-component vbo
 * attribute FOG, doubles cast to float [S: vbo/vbo_attrib_tmp.h:
 * TAG(FogCoordfEXT): ATTR1F(VBO_ATTRIB_FOG); api_loopback.c:
 * _mesa_FogCoordd]. */
static inline void fog_coord(float f)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_attr(ctx, FGL_ATTR_FOG, 1, f, 0.0f, 0.0f, 1.0f);
}

#define FOG_COORD_FUNCS(suffix, type, EXT)                                      \
   void GLAPIENTRY glFogCoord##suffix##EXT(type f) { fog_coord((GLfloat)f); }   \
   void GLAPIENTRY glFogCoord##suffix##v##EXT(const type *v)                    \
   { if (v) fog_coord((GLfloat)v[0]); }

FOG_COORD_FUNCS(f, GLfloat, )
FOG_COORD_FUNCS(d, GLdouble, )
FOG_COORD_FUNCS(f, GLfloat, EXT)
FOG_COORD_FUNCS(d, GLdouble, EXT)

/* glEdgeFlag: a one-component vbo attribute, 1.0 or 0.0 (any non-zero
 * GLboolean converts as its value) [S: vbo/vbo_attrib_tmp.h:EdgeFlag].  It
 * only matters to unfilled polygons; GL_EDGE_FLAG reads it back. */
static inline void edge_flag(GLboolean flag)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_attr(ctx, FGL_ATTR_EDGEFLAG, 1, (GLfloat)flag, 0.0f, 0.0f, 1.0f);
}

void GLAPIENTRY glEdgeFlag(GLboolean flag)
{
   edge_flag(flag);
}

void GLAPIENTRY glEdgeFlagv(const GLboolean *flag)
{
   if (flag)
      edge_flag(*flag);
}

/* glRect: one GL_QUADS primitive (x1,y1) (x2,y1) (x2,y2) (x1,y2) through
 * the immediate-mode path, other types converted to float first
 * [S: main/draw.c:_mesa_Rectf, _mesa_Rectd...]; inside glBegin/glEnd it is
 * an INVALID_OPERATION.  While compiling, every variant but glRectd is
 * save_Rectf [S: vbo/vbo_save_api.c], a quad of the vertex list whatever
 * the compiler's state; Mesa has no save_Rectd, so glRectd runs
 * _mesa_Rectf, whose glBegin/glVertex/glEnd are compiled. */
static void rectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_OWN(ctx);
   glBegin(GL_QUADS);
   glVertex2f(x1, y1);
   glVertex2f(x2, y1);
   glVertex2f(x2, y2);
   glVertex2f(x1, y2);
   glEnd();
}

static void rect_save(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag)
      fgl_save_rect(ctx, x1, y1, x2, y2);
   else
      rectf(x1, y1, x2, y2);
}

#define RECT_FUNCS(suffix, type, RECT)                                          \
   void GLAPIENTRY glRect##suffix(type x1, type y1, type x2, type y2)           \
   { RECT((GLfloat)x1, (GLfloat)y1, (GLfloat)x2, (GLfloat)y2); }                \
   void GLAPIENTRY glRect##suffix##v(const type *v1, const type *v2)            \
   { if (v1 && v2) rect_save((GLfloat)v1[0], (GLfloat)v1[1], (GLfloat)v2[0], (GLfloat)v2[1]); }

RECT_FUNCS(s, GLshort, rect_save)
RECT_FUNCS(i, GLint, rect_save)
RECT_FUNCS(f, GLfloat, rect_save)
RECT_FUNCS(d, GLdouble, rectf)
