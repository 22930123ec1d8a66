/* fc_emit.h - how a random scene reaches GL: immediate mode, vertex arrays
 * or display lists, chosen per scene.
 *
 * The generators describe their primitives with glBegin / glColor /
 * glNormal / glMaterial / glEdgeFlag / glVertex / glEnd as before; this
 * header (included after fc_trace.h and fc_trace_raster.h) puts an
 * emission layer between those calls and the tracing wrappers:
 *   - FCE_IMMEDIATE: every call goes straight to GL (traced).
 *   - FCE_ARRAYS: the calls between glBegin and glEnd are recorded; at glEnd
 *     the block is issued from client-side vertex arrays built from the
 *     recorded values: glDrawArrays / glDrawElements / glDrawRangeElements
 *     (random index type, storage order, shared vertices) when the block is
 *     only per-vertex attributes, glBegin + glArrayElement + glEnd when it
 *     interleaves other calls (glMaterial, glEdgeFlag) or sets an attribute
 *     only after its first vertex.  Array types, sizes, strides and
 *     interleaving (glInterleavedArrays when a format fits) are chosen so
 *     that the oracle's conversions give the values immediate mode gives
 *     (fc_emit.c explains each rule); after an array draw the last value of
 *     each attribute is issued again so the current values are those of
 *     immediate mode.  From streams of their own (the other choices stay
 *     as they were), about half the scenes take the arrays from a vertex
 *     buffer object (glBufferData, glBufferSubData or glMapBuffer, at an
 *     offset, unbound before or after the draw), the indices from an
 *     element buffer, and split draws of whole primitives (with empty
 *     ones) into glMultiDrawArrays / glMultiDrawElements; FC_EMIT_BO=V,I,M
 *     sets the three shares (percent) for bisecting.
 *   - FCE_DLIST: everything is compiled into display lists (GL_COMPILE or
 *     GL_COMPILE_AND_EXECUTE, run in order through glCallList, glCallLists
 *     or nested lists; fc_emit.c "display lists"), the blocks inside them
 *     immediate or (per profile) through arrays.
 * The scene's content (what the generator draws) never depends on the
 * path: the layer draws from its own random streams, never from the
 * generator's.  The path and the array layouts are structure: in the lit
 * and raster families they come from the profile index (FC_LIT_PROFILES),
 * so the oracle's vertex-fetch variants repeat with the shaders.
 * FC_TRACE prints what is really issued (arrays as static data), so a
 * scene still replays as C, and starts with the path in a comment. */
#ifndef FC_EMIT_H
#define FC_EMIT_H

#include "fc_trace.h"
#include "fc_trace_raster.h"
#include "fc_trace_tex.h"

#include <stdint.h>

enum fce_path { FCE_IMMEDIATE, FCE_ARRAYS, FCE_DLIST };

/* Families (keys of the layer's random streams). */
enum fce_family { FCE_PLAIN = 1, FCE_LIT = 2, FCE_RASTER = 3, FCE_TEX = 4 };

/* Starts a scene: picks its path from (seed, profile) and resets the
 * layer.  profile is the index for the plain family, the profile index
 * for the lit and raster ones.  Returns the path. */
enum fce_path fce_scene_begin(enum fce_family family, uint64_t seed, uint32_t index,
                              uint32_t profile);
/* Name of a path ("immediate", "arrays", "dlist"). */
const char *fce_path_name(enum fce_path path);

/* ---- the layer's side (fc_emit.c) ---- */

enum fce_kind { FCE_VERTEX, FCE_COLOR, FCE_NORMAL, FCE_EDGE, FCE_MATERIAL, FCE_TEXCOORD };
enum fce_type { FCE_B, FCE_UB, FCE_S, FCE_US, FCE_I, FCE_UI, FCE_F, FCE_D };

extern int fce_recording;          /* inside a recorded glBegin / glEnd */
extern int fce_record_blocks;      /* blocks go through arrays */
extern enum fce_path fce_path_now;

void fce_rec_attr(int kind, int type, int size, int vec,
                  double a, double b, double c, double d);
void fce_rec_material(int variant, GLenum face, GLenum pname, const double *v, int n);
void fce_block_begin(GLenum mode);
void fce_block_end(void);
void fce_dl_open(void);
void fce_dl_block_end(void);
void fce_dl_sync(void);
void fce_dl_resume(void);

/* ---- wrappers of the calls the layer intercepts ---- */

#define FCE_SCALAR1(name, T) \
    static inline void fce_##name(T a) \
    { if (fce_recording) { fce_rec_attr(FCE_K_##name, FCE_T_##name, 1, 0, a, 0, 0, 1); return; } fct_##name(a); }
#define FCE_SCALAR2(name, T) \
    static inline void fce_##name(T a, T b) \
    { if (fce_recording) { fce_rec_attr(FCE_K_##name, FCE_T_##name, 2, 0, a, b, 0, 1); return; } fct_##name(a, b); }
#define FCE_SCALAR3(name, T) \
    static inline void fce_##name(T a, T b, T c) \
    { if (fce_recording) { fce_rec_attr(FCE_K_##name, FCE_T_##name, 3, 0, a, b, c, 1); return; } fct_##name(a, b, c); }
#define FCE_SCALAR4(name, T) \
    static inline void fce_##name(T a, T b, T c, T d) \
    { if (fce_recording) { fce_rec_attr(FCE_K_##name, FCE_T_##name, 4, 0, a, b, c, d); return; } fct_##name(a, b, c, d); }
#define FCE_VECTOR(name, T, n) \
    static inline void fce_##name(const T *p) \
    { if (fce_recording) { fce_rec_attr(FCE_K_##name, FCE_T_##name, n, 1, p[0], n > 1 ? p[n > 1 ? 1 : 0] : 0, n > 2 ? p[n > 2 ? 2 : 0] : 0, n > 3 ? p[n > 3 ? 3 : 0] : 1); return; } fct_##name(p); }

/* X(kind, gl prefix, size, suffix, C type, fce_type) */
#define FCE_ATTR_VARIANTS(X)                                                 \
    X(FCE_VERTEX, glVertex, 2, s, GLshort, FCE_S) X(FCE_VERTEX, glVertex, 2, i, GLint, FCE_I) \
    X(FCE_VERTEX, glVertex, 2, f, GLfloat, FCE_F) X(FCE_VERTEX, glVertex, 2, d, GLdouble, FCE_D) \
    X(FCE_VERTEX, glVertex, 3, s, GLshort, FCE_S) X(FCE_VERTEX, glVertex, 3, i, GLint, FCE_I) \
    X(FCE_VERTEX, glVertex, 3, f, GLfloat, FCE_F) X(FCE_VERTEX, glVertex, 3, d, GLdouble, FCE_D) \
    X(FCE_VERTEX, glVertex, 4, s, GLshort, FCE_S) X(FCE_VERTEX, glVertex, 4, i, GLint, FCE_I) \
    X(FCE_VERTEX, glVertex, 4, f, GLfloat, FCE_F) X(FCE_VERTEX, glVertex, 4, d, GLdouble, FCE_D) \
    X(FCE_COLOR, glColor, 3, b, GLbyte, FCE_B) X(FCE_COLOR, glColor, 3, ub, GLubyte, FCE_UB) \
    X(FCE_COLOR, glColor, 3, s, GLshort, FCE_S) X(FCE_COLOR, glColor, 3, us, GLushort, FCE_US) \
    X(FCE_COLOR, glColor, 3, i, GLint, FCE_I) X(FCE_COLOR, glColor, 3, ui, GLuint, FCE_UI) \
    X(FCE_COLOR, glColor, 3, f, GLfloat, FCE_F) X(FCE_COLOR, glColor, 3, d, GLdouble, FCE_D) \
    X(FCE_COLOR, glColor, 4, b, GLbyte, FCE_B) X(FCE_COLOR, glColor, 4, ub, GLubyte, FCE_UB) \
    X(FCE_COLOR, glColor, 4, s, GLshort, FCE_S) X(FCE_COLOR, glColor, 4, us, GLushort, FCE_US) \
    X(FCE_COLOR, glColor, 4, i, GLint, FCE_I) X(FCE_COLOR, glColor, 4, ui, GLuint, FCE_UI) \
    X(FCE_COLOR, glColor, 4, f, GLfloat, FCE_F) X(FCE_COLOR, glColor, 4, d, GLdouble, FCE_D) \
    X(FCE_NORMAL, glNormal, 3, b, GLbyte, FCE_B) X(FCE_NORMAL, glNormal, 3, s, GLshort, FCE_S) \
    X(FCE_NORMAL, glNormal, 3, i, GLint, FCE_I) X(FCE_NORMAL, glNormal, 3, f, GLfloat, FCE_F) \
    X(FCE_NORMAL, glNormal, 3, d, GLdouble, FCE_D) \
    X(FCE_TEXCOORD, glTexCoord, 1, s, GLshort, FCE_S) X(FCE_TEXCOORD, glTexCoord, 1, i, GLint, FCE_I) \
    X(FCE_TEXCOORD, glTexCoord, 1, f, GLfloat, FCE_F) X(FCE_TEXCOORD, glTexCoord, 1, d, GLdouble, FCE_D) \
    X(FCE_TEXCOORD, glTexCoord, 2, s, GLshort, FCE_S) X(FCE_TEXCOORD, glTexCoord, 2, i, GLint, FCE_I) \
    X(FCE_TEXCOORD, glTexCoord, 2, f, GLfloat, FCE_F) X(FCE_TEXCOORD, glTexCoord, 2, d, GLdouble, FCE_D) \
    X(FCE_TEXCOORD, glTexCoord, 3, s, GLshort, FCE_S) X(FCE_TEXCOORD, glTexCoord, 3, i, GLint, FCE_I) \
    X(FCE_TEXCOORD, glTexCoord, 3, f, GLfloat, FCE_F) X(FCE_TEXCOORD, glTexCoord, 3, d, GLdouble, FCE_D) \
    X(FCE_TEXCOORD, glTexCoord, 4, s, GLshort, FCE_S) X(FCE_TEXCOORD, glTexCoord, 4, i, GLint, FCE_I) \
    X(FCE_TEXCOORD, glTexCoord, 4, f, GLfloat, FCE_F) X(FCE_TEXCOORD, glTexCoord, 4, d, GLdouble, FCE_D)

/* the scalar and vector wrapper of one variant */
#define FCE_WRAP(kind, pre, n, suf, T, type)                                 \
    enum { FCE_K_##pre##n##suf = kind, FCE_T_##pre##n##suf = type,           \
           FCE_K_##pre##n##suf##v = kind, FCE_T_##pre##n##suf##v = type };   \
    FCE_SCALAR##n(pre##n##suf, T)                                            \
    FCE_VECTOR(pre##n##suf##v, T, n)
FCE_ATTR_VARIANTS(FCE_WRAP)
#undef FCE_WRAP

static inline void fce_glMaterialf(GLenum f, GLenum p, GLfloat v)
{
    double d = v;
    if (fce_recording) { fce_rec_material(0, f, p, &d, 1); return; }
    fct_glMaterialf(f, p, v);
}
static inline void fce_glMaterialfv(GLenum f, GLenum p, const GLfloat *v)
{
    double d[4];
    int n = fc_trace_count(p);
    if (fce_recording) {
        for (int i = 0; i < n; i++) d[i] = v[i];
        fce_rec_material(1, f, p, d, n);
        return;
    }
    fct_glMaterialfv(f, p, v);
}
static inline void fce_glMateriali(GLenum f, GLenum p, GLint v)
{
    double d = v;
    if (fce_recording) { fce_rec_material(2, f, p, &d, 1); return; }
    fct_glMateriali(f, p, v);
}
static inline void fce_glMaterialiv(GLenum f, GLenum p, const GLint *v)
{
    double d[4];
    int n = fc_trace_count(p);
    if (fce_recording) {
        for (int i = 0; i < n; i++) d[i] = v[i];
        fce_rec_material(3, f, p, d, n);
        return;
    }
    fct_glMaterialiv(f, p, v);
}
static inline void fce_glEdgeFlag(GLboolean b)
{
    if (fce_recording) { fce_rec_attr(FCE_EDGE, FCE_UB, 1, 0, b, 0, 0, 1); return; }
    fct_glEdgeFlag(b);
}
static inline void fce_glEdgeFlagv(const GLboolean *b)
{
    if (fce_recording) { fce_rec_attr(FCE_EDGE, FCE_UB, 1, 1, *b, 0, 0, 1); return; }
    fct_glEdgeFlagv(b);
}
static inline void fce_glBegin(GLenum mode)
{
    if (fce_record_blocks) { fce_block_begin(mode); return; }
    fct_glBegin(mode);
}
static inline void fce_glEnd(void)
{
    if (fce_recording)
        fce_block_end();
    else
        fct_glEnd();
    if (fce_path_now == FCE_DLIST)
        fce_dl_block_end();
}
/* results are read outside display lists */
static inline void fce_fc_capture(fc_h *h)
{
    fce_dl_sync();
    fct_fc_capture(h);
    fce_dl_resume();
}
static inline void fce_fc_error(fc_h *h, const char *label)
{
    fce_dl_sync();
    fc_error(h, label);
}

#ifndef FC_EMIT_NO_MACROS
#undef glVertex2s
#undef glVertex2sv
#undef glVertex2i
#undef glVertex2iv
#undef glVertex2f
#undef glVertex2fv
#undef glVertex2d
#undef glVertex2dv
#undef glVertex3s
#undef glVertex3sv
#undef glVertex3i
#undef glVertex3iv
#undef glVertex3f
#undef glVertex3fv
#undef glVertex3d
#undef glVertex3dv
#undef glVertex4s
#undef glVertex4sv
#undef glVertex4i
#undef glVertex4iv
#undef glVertex4f
#undef glVertex4fv
#undef glVertex4d
#undef glVertex4dv
#undef glColor3b
#undef glColor3bv
#undef glColor3s
#undef glColor3sv
#undef glColor3i
#undef glColor3iv
#undef glColor3f
#undef glColor3fv
#undef glColor3d
#undef glColor3dv
#undef glColor3ub
#undef glColor3ubv
#undef glColor3us
#undef glColor3usv
#undef glColor3ui
#undef glColor3uiv
#undef glColor4b
#undef glColor4bv
#undef glColor4s
#undef glColor4sv
#undef glColor4i
#undef glColor4iv
#undef glColor4f
#undef glColor4fv
#undef glColor4d
#undef glColor4dv
#undef glColor4ub
#undef glColor4ubv
#undef glColor4us
#undef glColor4usv
#undef glColor4ui
#undef glColor4uiv
#undef glNormal3b
#undef glNormal3bv
#undef glNormal3s
#undef glNormal3sv
#undef glNormal3i
#undef glNormal3iv
#undef glNormal3f
#undef glNormal3fv
#undef glNormal3d
#undef glNormal3dv
#undef glTexCoord1s
#undef glTexCoord1sv
#undef glTexCoord1i
#undef glTexCoord1iv
#undef glTexCoord1f
#undef glTexCoord1fv
#undef glTexCoord1d
#undef glTexCoord1dv
#undef glTexCoord2s
#undef glTexCoord2sv
#undef glTexCoord2i
#undef glTexCoord2iv
#undef glTexCoord2f
#undef glTexCoord2fv
#undef glTexCoord2d
#undef glTexCoord2dv
#undef glTexCoord3s
#undef glTexCoord3sv
#undef glTexCoord3i
#undef glTexCoord3iv
#undef glTexCoord3f
#undef glTexCoord3fv
#undef glTexCoord3d
#undef glTexCoord3dv
#undef glTexCoord4s
#undef glTexCoord4sv
#undef glTexCoord4i
#undef glTexCoord4iv
#undef glTexCoord4f
#undef glTexCoord4fv
#undef glTexCoord4d
#undef glTexCoord4dv
#undef glMaterialf
#undef glMaterialfv
#undef glMateriali
#undef glMaterialiv
#undef glEdgeFlag
#undef glEdgeFlagv
#undef glBegin
#undef glEnd
#undef fc_capture
#define glVertex2s fce_glVertex2s
#define glVertex2sv fce_glVertex2sv
#define glVertex2i fce_glVertex2i
#define glVertex2iv fce_glVertex2iv
#define glVertex2f fce_glVertex2f
#define glVertex2fv fce_glVertex2fv
#define glVertex2d fce_glVertex2d
#define glVertex2dv fce_glVertex2dv
#define glVertex3s fce_glVertex3s
#define glVertex3sv fce_glVertex3sv
#define glVertex3i fce_glVertex3i
#define glVertex3iv fce_glVertex3iv
#define glVertex3f fce_glVertex3f
#define glVertex3fv fce_glVertex3fv
#define glVertex3d fce_glVertex3d
#define glVertex3dv fce_glVertex3dv
#define glVertex4s fce_glVertex4s
#define glVertex4sv fce_glVertex4sv
#define glVertex4i fce_glVertex4i
#define glVertex4iv fce_glVertex4iv
#define glVertex4f fce_glVertex4f
#define glVertex4fv fce_glVertex4fv
#define glVertex4d fce_glVertex4d
#define glVertex4dv fce_glVertex4dv
#define glColor3b fce_glColor3b
#define glColor3bv fce_glColor3bv
#define glColor3s fce_glColor3s
#define glColor3sv fce_glColor3sv
#define glColor3i fce_glColor3i
#define glColor3iv fce_glColor3iv
#define glColor3f fce_glColor3f
#define glColor3fv fce_glColor3fv
#define glColor3d fce_glColor3d
#define glColor3dv fce_glColor3dv
#define glColor3ub fce_glColor3ub
#define glColor3ubv fce_glColor3ubv
#define glColor3us fce_glColor3us
#define glColor3usv fce_glColor3usv
#define glColor3ui fce_glColor3ui
#define glColor3uiv fce_glColor3uiv
#define glColor4b fce_glColor4b
#define glColor4bv fce_glColor4bv
#define glColor4s fce_glColor4s
#define glColor4sv fce_glColor4sv
#define glColor4i fce_glColor4i
#define glColor4iv fce_glColor4iv
#define glColor4f fce_glColor4f
#define glColor4fv fce_glColor4fv
#define glColor4d fce_glColor4d
#define glColor4dv fce_glColor4dv
#define glColor4ub fce_glColor4ub
#define glColor4ubv fce_glColor4ubv
#define glColor4us fce_glColor4us
#define glColor4usv fce_glColor4usv
#define glColor4ui fce_glColor4ui
#define glColor4uiv fce_glColor4uiv
#define glNormal3b fce_glNormal3b
#define glNormal3bv fce_glNormal3bv
#define glNormal3s fce_glNormal3s
#define glNormal3sv fce_glNormal3sv
#define glNormal3i fce_glNormal3i
#define glNormal3iv fce_glNormal3iv
#define glNormal3f fce_glNormal3f
#define glNormal3fv fce_glNormal3fv
#define glNormal3d fce_glNormal3d
#define glNormal3dv fce_glNormal3dv
#define glTexCoord1s fce_glTexCoord1s
#define glTexCoord1sv fce_glTexCoord1sv
#define glTexCoord1i fce_glTexCoord1i
#define glTexCoord1iv fce_glTexCoord1iv
#define glTexCoord1f fce_glTexCoord1f
#define glTexCoord1fv fce_glTexCoord1fv
#define glTexCoord1d fce_glTexCoord1d
#define glTexCoord1dv fce_glTexCoord1dv
#define glTexCoord2s fce_glTexCoord2s
#define glTexCoord2sv fce_glTexCoord2sv
#define glTexCoord2i fce_glTexCoord2i
#define glTexCoord2iv fce_glTexCoord2iv
#define glTexCoord2f fce_glTexCoord2f
#define glTexCoord2fv fce_glTexCoord2fv
#define glTexCoord2d fce_glTexCoord2d
#define glTexCoord2dv fce_glTexCoord2dv
#define glTexCoord3s fce_glTexCoord3s
#define glTexCoord3sv fce_glTexCoord3sv
#define glTexCoord3i fce_glTexCoord3i
#define glTexCoord3iv fce_glTexCoord3iv
#define glTexCoord3f fce_glTexCoord3f
#define glTexCoord3fv fce_glTexCoord3fv
#define glTexCoord3d fce_glTexCoord3d
#define glTexCoord3dv fce_glTexCoord3dv
#define glTexCoord4s fce_glTexCoord4s
#define glTexCoord4sv fce_glTexCoord4sv
#define glTexCoord4i fce_glTexCoord4i
#define glTexCoord4iv fce_glTexCoord4iv
#define glTexCoord4f fce_glTexCoord4f
#define glTexCoord4fv fce_glTexCoord4fv
#define glTexCoord4d fce_glTexCoord4d
#define glTexCoord4dv fce_glTexCoord4dv
#define glMaterialf fce_glMaterialf
#define glMaterialfv fce_glMaterialfv
#define glMateriali fce_glMateriali
#define glMaterialiv fce_glMaterialiv
#define glEdgeFlag fce_glEdgeFlag
#define glEdgeFlagv fce_glEdgeFlagv
#define glBegin fce_glBegin
#define glEnd fce_glEnd
#define fc_capture fce_fc_capture
#define fc_error fce_fc_error
#endif

#endif
