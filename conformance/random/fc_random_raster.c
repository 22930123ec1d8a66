/* fc_random_raster.c - random scenes of primitives and per-fragment
 * operations, "random-raster/s<seed>-i<index>" (tag random-raster).  Like
 * the other families a scene is a pure function of (seed, index) and
 * nothing depends on GL results.
 *
 * A scene: a clear, viewport, depth range and projection from the plain
 * generator's helpers, then 1-10 primitives of every GL primitive type
 * (points, lines, strips, loops, the six polygon types, glRect), each after
 * a random subset of state changes:
 *   - points: glPointSize (integer, .5 and random fractional sizes),
 *     GL_POINT_SMOOTH;
 *   - lines: glLineWidth, glLineStipple with GL_LINE_STIPPLE,
 *     GL_LINE_SMOOTH;
 *   - polygons: glCullFace / glFrontFace / GL_CULL_FACE, glPolygonMode
 *     (front and back apart) with glEdgeFlag between vertices,
 *     glPolygonOffset with GL_POLYGON_OFFSET_FILL/LINE/POINT,
 *     glPolygonStipple with GL_POLYGON_STIPPLE;
 *   - 1-3 user clip planes given under the current modelview;
 *   - fog (linear, exp, exp2; start/end/density/colour);
 *   - scissor (boxes inside, across and outside the framebuffer), alpha
 *     test (references on u8 ties), stencil (function, reference, masks,
 *     all operations), blending (every GL 1.x factor pair, each equation,
 *     a blend colour), logic ops, colour and depth masks;
 *   - clears under the scissor and masks;
 *   - GL 1.4's vertex attributes and point parameters (issue 19), from
 *     streams of their own (a scene without them is the scene it was
 *     before they came): GL_COLOR_SUM with a secondary colour, the fog
 *     coordinate as GL_FOG_COORD_SRC, each set before a primitive (the
 *     current value, so the immediate, array and display-list paths of
 *     fc_emit.h draw the same), glPointParameter (distance attenuation,
 *     minimum and maximum size, fade threshold).
 * The structure of a scene (which state is on, which functions, which
 * primitive types: what llvmpipe compiles shaders for) repeats every
 * FC_RASTER_PROFILES indices with other values, as in the lit family, so
 * long runs reuse the oracle's shader cache. */
#define GL_GLEXT_PROTOTYPES 1   /* GL 1.4's secondary colour, fog coordinate, point parameters */
#include "fc_random.h"
#include "fc_random_shared.h"
#include "fc_rng.h"
#include "fc_trace.h"
#include "fc_trace_raster.h"
#include "fc_emit.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define FC_RASTER_PROFILES 256

/* call-trace wrappers (fc_trace.h) of the GL 1.4 entry points only this
 * family calls */
static inline void fct_glSecondaryColor3f(GLfloat a, GLfloat b, GLfloat c) { fc_trace_call("glSecondaryColor3f", 3, a, b, c, 0); glSecondaryColor3f(a, b, c); }
static inline void fct_glSecondaryColor3ub(GLubyte a, GLubyte b, GLubyte c) { fc_trace_calli("glSecondaryColor3ub", 3, a, b, c, 0); glSecondaryColor3ub(a, b, c); }
static inline void fct_glSecondaryColor3dv(const GLdouble *p) { fc_trace_vd("glSecondaryColor3dv", "GLdouble", 3, p); glSecondaryColor3dv(p); }
static inline void fct_glFogCoordf(GLfloat a) { fc_trace_call("glFogCoordf", 1, a, 0, 0, 0); glFogCoordf(a); }
static inline void fct_glFogCoordd(GLdouble a) { fc_trace_call("glFogCoordd", 1, a, 0, 0, 0); glFogCoordd(a); }
static inline void fct_glPointParameterf(GLenum p, GLfloat v) { fc_trace_enums_f("glPointParameterf", 1, p, 0, v); glPointParameterf(p, v); }
static inline void fct_glPointParameterfv(GLenum p, const GLfloat *v) { fc_trace_enums_vf("glPointParameterfv", 1, p, 0, p == GL_POINT_DISTANCE_ATTENUATION ? 3 : 1, v); glPointParameterfv(p, v); }

#define glSecondaryColor3f fct_glSecondaryColor3f
#define glSecondaryColor3ub fct_glSecondaryColor3ub
#define glSecondaryColor3dv fct_glSecondaryColor3dv
#define glFogCoordf fct_glFogCoordf
#define glFogCoordd fct_glFogCoordd
#define glPointParameterf fct_glPointParameterf
#define glPointParameterfv fct_glPointParameterfv

static const GLenum prim_modes[11] = {
    GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES, GL_TRIANGLE_STRIP,
    GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON, 0 /* glRect */
};

static const GLenum blend_src[9] = {
    GL_ZERO, GL_ONE, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE,
};
static const GLenum blend_dst[8] = {
    GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA,
};
static const GLenum blend_const[4] = {
    GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA,
};
static const GLenum blend_eqs[5] = {
    GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX,
};
static const GLenum stencil_ops[8] = {
    GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP,
};
static const GLenum fog_modes[3] = { GL_LINEAR, GL_EXP, GL_EXP2 };

/* The structure of a scene: drawn from the profile stream. */
struct profile {
    GLenum modes[10];
    int nprim;
    int smooth_points, smooth_lines, stipple_lines;
    int cull, offset, pstipple, planes;
    int unfilled, edge_flags;   /* glPolygonMode; glEdgeFlag between vertices */
    GLenum mode_front, mode_back;
    int fog;                    /* 0 = off, else 1 + index into fog_modes */
    int scissor, alpha, stencil, blend, logic, cmask, dmask;
    GLenum alpha_func, stencil_func, sfail, zfail, zpass;
    GLenum bsrc, bdst, beq;
    GLenum logic_op;
    int flat, depth_test;
    GLenum depth_func;
    int masked_clear;
    /* GL 1.4 (make_profile14) */
    int seccolor, fogcoord, ptparams;
};

/* The GL 1.4 part of a profile, from a stream of its own */
static void make_profile14(fc_rng *k, struct profile *p)
{
    p->seccolor = fc_rng_chance(k, 20);
    p->fogcoord = p->fog && fc_rng_chance(k, 40);
    p->ptparams = fc_rng_chance(k, 20);
}

static void make_profile(fc_rng *k, struct profile *p)
{
    memset(p, 0, sizeof *p);
    p->nprim = fc_rng_range(k, 1, 10);
    for (int i = 0; i < p->nprim; i++)
        p->modes[i] = prim_modes[fc_rng_below(k, 11)];
    p->smooth_points = fc_rng_chance(k, 15);
    p->smooth_lines = fc_rng_chance(k, 15);
    p->stipple_lines = fc_rng_chance(k, 25);
    p->cull = fc_rng_chance(k, 20);
    p->offset = fc_rng_chance(k, 20);
    p->pstipple = fc_rng_chance(k, 15);
    p->planes = fc_rng_chance(k, 15) ? fc_rng_range(k, 1, 3) : 0;
    {
        static const GLenum fill_modes[3] = { GL_POINT, GL_LINE, GL_FILL };
        p->unfilled = fc_rng_chance(k, 20);
        p->mode_front = fill_modes[fc_rng_below(k, 3)];
        p->mode_back = fill_modes[fc_rng_below(k, 3)];
        p->edge_flags = fc_rng_chance(k, 40);
    }
    p->fog = fc_rng_chance(k, 25) ? 1 + (int)fc_rng_below(k, 3) : 0;
    p->scissor = fc_rng_chance(k, 25);
    p->alpha = fc_rng_chance(k, 20);
    p->stencil = fc_rng_chance(k, 25);
    p->blend = fc_rng_chance(k, 35);
    p->logic = fc_rng_chance(k, 10);
    p->cmask = fc_rng_chance(k, 10);
    p->dmask = fc_rng_chance(k, 10);
    p->alpha_func = fcr_depth_funcs[fc_rng_below(k, 8)];
    p->stencil_func = fcr_depth_funcs[fc_rng_below(k, 8)];
    p->sfail = stencil_ops[fc_rng_below(k, 8)];
    p->zfail = stencil_ops[fc_rng_below(k, 8)];
    p->zpass = stencil_ops[fc_rng_below(k, 8)];
    if (fc_rng_chance(k, 15)) {
        p->bsrc = blend_const[fc_rng_below(k, 4)];
        p->bdst = blend_const[fc_rng_below(k, 4)];
    } else {
        p->bsrc = blend_src[fc_rng_below(k, 9)];
        p->bdst = blend_dst[fc_rng_below(k, 8)];
    }
    p->beq = fc_rng_chance(k, 60) ? GL_FUNC_ADD : blend_eqs[fc_rng_below(k, 5)];
    p->logic_op = GL_CLEAR + fc_rng_below(k, 16);
    p->flat = fc_rng_chance(k, 40);
    p->depth_test = fc_rng_chance(k, 60);
    p->depth_func = fcr_depth_funcs[fc_rng_below(k, 8)];
    p->masked_clear = fc_rng_chance(k, 20);
    /* Smooth points and lines are drawn as triangles in the same draw as
     * the filled faces or outlines of a face with another polygon mode,
     * and the oracle then switches shaders and vertex layouts inside one
     * batch: it reads uninitialised vertex data (ORACLE-NOTES.md "Polygon
     * modes"), so such scenes have no defined reference.  Decided after
     * every draw from the stream, so other scenes keep their values. */
    if (p->unfilled && p->mode_front != p->mode_back)
        p->smooth_points = p->smooth_lines = 0;
}

/* ---- values ------------------------------------------------------------ */

/* A size for glPointSize / glLineWidth: small integers, halves, random. */
static double raster_size(fc_rng *r)
{
    static const double v[10] = { 1, 1.5, 2, 2.5, 3, 4, 5, 7.5, 0.5, 10 };
    return fc_rng_chance(r, 60) ? v[fc_rng_below(r, 10)] : (float)fc_rng_real(r, 0.1, 12);
}

/* A value in [0,1] on or next to a u8 step or tie. */
static double u8ish(fc_rng *r)
{
    switch (fc_rng_below(r, 5)) {
    case 0: return fc_rng_range(r, 0, 255) / 255.0;
    case 1: return (fc_rng_range(r, 0, 254) + 0.5) / 255.0;
    case 2: return fc_rng_chance(r, 50) ? 0.0 : 1.0;
    default: return fc_rng_unit(r);
    }
}

static void random_points_lines(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    glPointSize((GLfloat)raster_size(r));
    glLineWidth((GLfloat)raster_size(r));
    if (p->smooth_points) glEnable(GL_POINT_SMOOTH); else glDisable(GL_POINT_SMOOTH);
    if (p->smooth_lines) glEnable(GL_LINE_SMOOTH); else glDisable(GL_LINE_SMOOTH);
    if (p->stipple_lines) {
        glEnable(GL_LINE_STIPPLE);
        glLineStipple(fc_rng_range(r, 1, 4), (GLushort)fc_rng_below(r, 65536));
    } else {
        glDisable(GL_LINE_STIPPLE);
    }
}

static void random_polygon_state(struct scene *s, const struct profile *p)
{
    static const GLenum faces[3] = { GL_FRONT, GL_BACK, GL_FRONT_AND_BACK };
    fc_rng *r = &s->r;
    if (p->cull) {
        glEnable(GL_CULL_FACE);
        glCullFace(faces[fc_rng_below(r, 3)]);
        glFrontFace(fc_rng_chance(r, 50) ? GL_CCW : GL_CW);
    }
    if (p->unfilled) {
        if (p->mode_front == p->mode_back) {
            glPolygonMode(GL_FRONT_AND_BACK, p->mode_front);
        } else {
            glPolygonMode(GL_FRONT, p->mode_front);
            glPolygonMode(GL_BACK, p->mode_back);
        }
    }
    if (p->offset) {
        static const double f[6] = { 0, 1, -1, 2.5, 0.5, -4 };
        if (fc_rng_chance(r, 50)) glEnable(GL_POLYGON_OFFSET_LINE);
        if (fc_rng_chance(r, 30)) glEnable(GL_POLYGON_OFFSET_POINT);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset((GLfloat)(fc_rng_chance(r, 60) ? f[fc_rng_below(r, 6)] : fc_rng_real(r, -8, 8)),
                        (GLfloat)(fc_rng_chance(r, 60) ? f[fc_rng_below(r, 6)] : fc_rng_real(r, -50, 50)));
    }
    if (p->pstipple) {
        GLubyte mask[128];
        int kind = (int)fc_rng_below(r, 3);
        for (int i = 0; i < 128; i++) {
            mask[i] = kind == 0 ? (GLubyte)fc_rng_below(r, 256)
                    : kind == 1 ? ((i / 4) & 1 ? 0xaa : 0x55)      /* checker */
                    : (GLubyte)((i / 4) % 3 ? 0xff : 0x00);       /* stripes */
        }
        glPolygonStipple(mask);
        glEnable(GL_POLYGON_STIPPLE);
    }
    for (int i = 0; i < p->planes; i++) {
        GLdouble eq[4];
        for (int c = 0; c < 3; c++)
            eq[c] = fc_rng_chance(r, 30) ? 0.0 : (float)fc_rng_real(r, -1, 1);
        /* through the middle of the view, in the scene's units */
        eq[3] = s->space == SP_PIXEL ? -(eq[0] * s->vw + eq[1] * s->vh) * fc_rng_real(r, 0.2, 0.8)
                                     : (float)fc_rng_real(r, -0.5, 0.5);
        glClipPlane(GL_CLIP_PLANE0 + i, eq);
        glEnable(GL_CLIP_PLANE0 + i);
    }
}

static void random_fog(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    GLfloat color[4];
    if (!p->fog)
        return;
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, (GLint)fog_modes[p->fog - 1]);
    for (int i = 0; i < 4; i++)
        color[i] = (GLfloat)u8ish(r);
    glFogfv(GL_FOG_COLOR, color);
    /* eye distances: pixel space has z in [-1,1], the others reach 200 */
    double range = s->space == SP_PIXEL ? 1.0 : 20.0;
    double a = fc_rng_real(r, -range, range), b = fc_rng_real(r, -range, 2 * range);
    glFogf(GL_FOG_START, (GLfloat)(fc_rng_chance(r, 10) ? b : a));
    glFogf(GL_FOG_END, (GLfloat)b);
    glFogf(GL_FOG_DENSITY, (GLfloat)(fc_rng_chance(r, 10) ? 0.0 : fc_rng_real(r, 0, 3.0 / range)));
}

/* The GL 1.4 state of a scene (r: the scene's stream of it) */
static void random_state14(struct scene *s, const struct profile *p, fc_rng *r)
{
    if (p->seccolor)
        glEnable(GL_COLOR_SUM);
    if (p->fogcoord)
        glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    if (p->ptparams) {
        /* attenuations on the scale of the scene's eye distances */
        const double range = s->space == SP_PIXEL ? 1.0 : 20.0;
        GLfloat att[3] = { (GLfloat)(fc_rng_chance(r, 20) ? 1.0 : fc_rng_real(r, 0.05, 2.0)),
                           (GLfloat)(fc_rng_chance(r, 40) ? 0.0 : fc_rng_real(r, 0.0, 1.0 / range)),
                           (GLfloat)(fc_rng_chance(r, 40) ? 0.0
                                                          : fc_rng_real(r, 0.0, 1.0 / (range * range))) };
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
        if (fc_rng_chance(r, 50))
            glPointParameterf(GL_POINT_SIZE_MIN, (GLfloat)fc_rng_real(r, 0.0, 4.0));
        if (fc_rng_chance(r, 50)) {
            const GLfloat mx = (GLfloat)fc_rng_real(r, 0.5, 16.0);
            glPointParameterfv(GL_POINT_SIZE_MAX, &mx);
        }
        if (fc_rng_chance(r, 50))
            glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, (GLfloat)fc_rng_real(r, 0.0, 6.0));
    }
}

/* The current secondary colour and fog coordinate before a primitive */
static void random_attribs14(struct scene *s, const struct profile *p, fc_rng *r)
{
    if (p->seccolor && fc_rng_chance(r, 70)) {
        switch (fc_rng_below(r, 3)) {
        case 0:
            glSecondaryColor3f((GLfloat)u8ish(r), (GLfloat)u8ish(r), (GLfloat)u8ish(r));
            break;
        case 1:
            glSecondaryColor3ub((GLubyte)fc_rng_below(r, 256), (GLubyte)fc_rng_below(r, 256),
                                (GLubyte)fc_rng_below(r, 256));
            break;
        default: {
            const GLdouble c[3] = { fc_rng_real(r, -0.5, 1.5), fc_rng_unit(r), u8ish(r) };
            glSecondaryColor3dv(c);
            break;
        }
        }
    }
    if (p->fogcoord && fc_rng_chance(r, 70)) {
        const double range = s->space == SP_PIXEL ? 1.0 : 20.0;
        const double f = fc_rng_chance(r, 10) ? -fc_rng_real(r, 0.0, range)
                                              : fc_rng_real(r, 0.0, 2.0 * range);
        if (fc_rng_chance(r, 50))
            glFogCoordf((GLfloat)f);
        else
            glFogCoordd(f);
    }
}

static void random_fragment_state(struct scene *s, const struct profile *p)
{
    fc_rng *r = &s->r;
    if (p->scissor) {
        int x = fc_rng_range(r, -s->w / 4, s->w), y = fc_rng_range(r, -s->h / 4, s->h);
        glScissor(x, y, fc_rng_range(r, 0, s->w), fc_rng_range(r, 0, s->h));
        glEnable(GL_SCISSOR_TEST);
    }
    if (p->alpha) {
        glAlphaFunc(p->alpha_func, (GLclampf)u8ish(r));
        glEnable(GL_ALPHA_TEST);
    }
    if (p->stencil) {
        glStencilFunc(p->stencil_func, fc_rng_range(r, -1, 256),
                      fc_rng_chance(r, 50) ? 0xffffffffu : (GLuint)fc_rng_below(r, 256));
        glStencilOp(p->sfail, p->zfail, p->zpass);
        glStencilMask(fc_rng_chance(r, 60) ? 0xffffffffu : (GLuint)fc_rng_below(r, 256));
        glEnable(GL_STENCIL_TEST);
    }
    if (p->blend) {
        glBlendFunc(p->bsrc, p->bdst);
        if (p->beq != GL_FUNC_ADD || fc_rng_chance(r, 20))
            glBlendEquation(p->beq);
        glBlendColor((GLclampf)u8ish(r), (GLclampf)u8ish(r), (GLclampf)u8ish(r), (GLclampf)u8ish(r));
        glEnable(GL_BLEND);
    }
    if (p->logic) {
        glLogicOp(p->logic_op);
        glEnable(GL_COLOR_LOGIC_OP);
    }
    if (p->cmask)
        glColorMask((GLboolean)fc_rng_chance(r, 50), (GLboolean)fc_rng_chance(r, 50),
                    (GLboolean)fc_rng_chance(r, 50), (GLboolean)fc_rng_chance(r, 50));
    if (p->dmask)
        glDepthMask(GL_FALSE);
}

/* ---- primitives ---------------------------------------------------------- */

static int raster_vertex_count(fc_rng *r, GLenum mode)
{
    int n = fc_rng_range(r, 1, 5);
    switch (mode) {
    case GL_POINTS: return fc_rng_range(r, 1, 12);
    case GL_LINES: return 2 * n + (fc_rng_chance(r, 10) ? 1 : 0);
    case GL_LINE_STRIP: case GL_LINE_LOOP: return fc_rng_range(r, 1, 7);
    case GL_TRIANGLES: return 3 * n;
    case GL_QUADS: return 4 * n;
    case GL_QUAD_STRIP: return 2 + 2 * n;
    default: return 2 + n;
    }
}

static void random_vertex(struct scene *s, double v[4])
{
    fc_rng *r = &s->r;
    if (s->npool && fc_rng_chance(r, 20)) {
        memcpy(v, s->pool[fc_rng_below(r, (uint32_t)(s->npool < POOL ? s->npool : POOL))],
               4 * sizeof v[0]);
        return;
    }
    fcr_fresh_vertex(s, v);
}

static void emit(struct scene *s, const double v[4])
{
    int dim = v[3] != 1 ? 4 : 3;
    fcr_emit_vertex(s, v, dim);
    memcpy(s->pool[s->npool++ % POOL], v, 4 * sizeof v[0]);
}

static void random_rect(struct scene *s)
{
    fc_rng *r = &s->r;
    double a[4], b[4];
    random_vertex(s, a);
    random_vertex(s, b);
    if (fc_rng_chance(r, 90))
        fcr_emit_color(s);
    switch (fc_rng_below(r, 4)) {
    case 0: glRectf((GLfloat)a[0], (GLfloat)a[1], (GLfloat)b[0], (GLfloat)b[1]); break;
    case 1: glRectd(a[0], a[1], b[0], b[1]); break;
    case 2: glRecti((GLint)a[0], (GLint)a[1], (GLint)b[0], (GLint)b[1]); break;
    default: {
        GLfloat p0[2] = { (GLfloat)a[0], (GLfloat)a[1] }, p1[2] = { (GLfloat)b[0], (GLfloat)b[1] };
        glRectfv(p0, p1);
        break;
    }
    }
}

static void random_raster_primitive(struct scene *s, const struct profile *p, GLenum mode)
{
    fc_rng *r = &s->r;
    double v[4];
    if (mode == 0) {
        random_rect(s);
        return;
    }
    int n = raster_vertex_count(r, mode);
    glBegin(mode);
    for (int k = 0; k < n; k++) {
        random_vertex(s, v);
        if (fc_rng_chance(r, 90))
            fcr_emit_color(s);
        if (p->edge_flags && fc_rng_chance(r, 40)) {
            if (fc_rng_chance(r, 50)) {
                glEdgeFlag((GLboolean)fc_rng_chance(r, 50));
            } else {
                const GLboolean f = (GLboolean)fc_rng_chance(r, 50);
                glEdgeFlagv(&f);
            }
        }
        emit(s, v);
    }
    glEnd();
}

/* The witness (fcr_witness) under the scene's state, except that each
 * profile setting that can hide or keep every fragment (scissor, alpha
 * and stencil tests, blending, logic op, colour mask, culling, stipple,
 * clip planes, and polygon modes, whose outlines and points the current
 * edge flag can hide) stays on for it with a chance of 15% only. */
static void raster_witness(struct scene *s, const struct profile *p)
{
    fc_rng *v = &s->vis;
    glPushAttrib(GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT | GL_POLYGON_BIT);
    if (p->unfilled && !fc_rng_chance(v, 15))        /* outlines and points: edge flags */
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    if (p->scissor && !fc_rng_chance(v, 15)) glDisable(GL_SCISSOR_TEST);
    if (p->alpha && !fc_rng_chance(v, 15)) glDisable(GL_ALPHA_TEST);
    if (p->stencil && !fc_rng_chance(v, 15)) glDisable(GL_STENCIL_TEST);
    if (p->blend && !fc_rng_chance(v, 15)) glDisable(GL_BLEND);
    if (p->logic && !fc_rng_chance(v, 15)) glDisable(GL_COLOR_LOGIC_OP);
    if (p->cmask && !fc_rng_chance(v, 15)) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (p->cull && !fc_rng_chance(v, 15)) glDisable(GL_CULL_FACE);
    if (p->pstipple && !fc_rng_chance(v, 15)) glDisable(GL_POLYGON_STIPPLE);
    if (p->planes && !fc_rng_chance(v, 15))
        for (int i = 0; i < p->planes; i++)
            glDisable(GL_CLIP_PLANE0 + i);
    fcr_witness(s);
    glPopAttrib();
}

static void raster_scene(fc_h *h)
{
    const fc_case *c = fc_this_case(h);
    struct scene s;
    struct profile p;
    uint64_t seed;
    uint32_t index;

    fc_lit_gl_load();       /* glFrontFace goes through the fc_lit_gl table */
    memset(&s, 0, sizeof s);
    fc_random_raster_parse(c->name, &seed, &index);
    fc_rng k = fc_rng_make(seed, index % FC_RASTER_PROFILES, 8);
    make_profile(&k, &p);
    fc_rng k14 = fc_rng_make(seed, index % FC_RASTER_PROFILES, 43);
    make_profile14(&k14, &p);
    fc_rng r14 = fc_rng_make(seed, index, 44);
    fce_scene_begin(FCE_RASTER, seed, index, index % FC_RASTER_PROFILES);
    s.r = fc_rng_make(seed, index, 7);
    s.vis = fc_rng_make(seed, index, 31);
    s.w = c->width;
    s.h = c->height;
    s.space = (enum space)(fc_rng_below(&k, 100) < 60 ? SP_PIXEL : 1 + fc_rng_below(&k, 4));

    fcr_clear(&s.r, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    fcr_viewport(&s);
    fcr_depth_range(&s.r);
    fcr_projection(&s);
    glLoadIdentity();
    if (p.depth_test)
        glEnable(GL_DEPTH_TEST);
    glDepthFunc(p.depth_func);
    glShadeModel(p.flat ? GL_FLAT : GL_SMOOTH);

    random_polygon_state(&s, &p);
    random_fog(&s, &p);
    random_fragment_state(&s, &p);
    random_state14(&s, &p, &r14);
    if (p.masked_clear) {
        glClearStencil(fc_rng_range(&s.r, 0, 255));
        fcr_clear(&s.r, GL_COLOR_BUFFER_BIT | (fc_rng_chance(&s.r, 50) ? GL_DEPTH_BUFFER_BIT : 0) |
                         (fc_rng_chance(&s.r, 50) ? GL_STENCIL_BUFFER_BIT : 0));
    }

    const int witness = fc_rng_range(&s.vis, 0, p.nprim);    /* before primitive witness */
    for (int i = 0; i <= p.nprim; i++) {
        if (i == witness)
            raster_witness(&s, &p);
        if (i == p.nprim)
            break;
        random_points_lines(&s, &p);
        random_attribs14(&s, &p, &r14);
        random_raster_primitive(&s, &p, p.modes[i]);
        if (c->frames == 2 && i == p.nprim / 2)
            fc_capture(h);
    }
    fc_capture(h);
    fc_error(h, "scene glGetError");
}

int fc_random_raster_parse(const char *name, uint64_t *seed, uint32_t *index)
{
    char tail;
    return sscanf(name, "random-raster/s%" SCNu64 "-i%" SCNu32 "%c", seed, index, &tail) == 2;
}

void fc_random_raster_case(uint64_t seed, uint32_t index, fc_case *out, char *name)
{
    /* No OSMESA_RGB: the harness compares RGB cases against the oracle
     * drawing into RGBA (its own RGB buffers are corrupt, fc_case.h), where
     * destination alpha and the alpha test differ from a real RGB buffer
     * (ORACLE-NOTES.md "Per-fragment operations"). */
    static const GLenum formats[10] = {
        OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA, OSMESA_RGBA,
        OSMESA_RGBA, OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_BGRA,
    };
    static const int depths[12] = { 24, 24, 24, 24, 24, 24, 24, 24, 16, 32, 16, 0 };
    fc_rng r = fc_rng_make(seed, index, 9);
    fc_rng k = fc_rng_make(seed, index % FC_RASTER_PROFILES, 10);
    int size = (int)fc_rng_below(&r, 100);

    snprintf(name, FC_RANDOM_NAME_MAX, "random-raster/s%" PRIu64 "-i%" PRIu32, seed, index);
    memset(out, 0, sizeof *out);
    out->draws_nothing = FC_MAY_DRAW_NOTHING;   /* a generated scene (fc_case.h) */
    out->name = name;
    if (size < 90) {
        out->width = fc_rng_range(&r, 16, 128);
        out->height = fc_rng_range(&r, 16, 128);
    } else {
        out->width = fc_rng_range(&r, 129, 256);
        out->height = fc_rng_range(&r, 129, 256);
    }
    out->format = formats[fc_rng_below(&k, 10)];
    out->depth_bits = depths[fc_rng_below(&k, 12)];
    out->stencil_bits = fc_rng_chance(&k, 50) ? 8 : 0;
    out->frames = fc_rng_chance(&k, 25) ? 2 : 1;
    out->tags = "random-raster";
    out->fn = raster_scene;
}
