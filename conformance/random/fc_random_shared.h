/* fc_random_shared.h - helpers of the plain random generator (fc_random.c)
 * that the lit scene generator (fc_random_lit.c) reuses.  Internal to
 * random/.  Every helper draws from the scene's own stream s->r, so reusing
 * them in another family never changes the plain scenes. */
#ifndef FC_RANDOM_SHARED_H
#define FC_RANDOM_SHARED_H

#include "fc_case.h"
#include "fc_rng.h"

enum space { SP_PIXEL, SP_BOX, SP_FRUSTUM, SP_CLIP, SP_MATRIX };

#define POOL 48

struct scene {
    fc_rng r;
    int w, h;                   /* framebuffer */
    int vw, vh;                 /* current viewport size */
    enum space space;
    double box[6];              /* SP_BOX: l r b t n f */
    double fr[6];               /* SP_FRUSTUM: l r b t n f */
    double pool[POOL][4];       /* earlier vertices, for shared edges */
    int npool;
    /* The witness (fcr_witness): the viewport's origin and the projection
     * as issued (column-major), and a stream of its own, so a witness
     * leaves the rest of the scene as it was. */
    int vx, vy;
    double proj[16];
    fc_rng vis;
};

extern const GLenum fcr_depth_funcs[8];
extern const GLenum fcr_modes[6];       /* the six polygon primitive types */

/* v (dim components) through a random glVertex variant. */
void fcr_emit_vertex(struct scene *s, const double v[4], int dim);
/* A fresh vertex of the scene's space (pixel centres, snap-grid ties,
 * bounds of the view volume, w near 0...); returns the glVertex dimension. */
int fcr_fresh_vertex(struct scene *s, double v[4]);
/* A random colour through a random glColor variant (any type, extremes). */
void fcr_emit_color(struct scene *s);
/* glViewport: the whole framebuffer, or (40%) a random offset and size;
 * sets s->vw, s->vh. */
void fcr_viewport(struct scene *s);
/* glDepthRange (40%) with special or random values. */
void fcr_depth_range(fc_rng *r);
/* A random matrix; perspective: last row (0 0 -1 0). */
void fcr_matrix(fc_rng *r, double m[16], int perspective);
/* glLoadMatrix / glMultMatrix of m, f or d. */
void fcr_load_or_mult(fc_rng *r, const double m[16]);
/* The projection of s->space (fills s->box / s->fr); leaves GL_MODELVIEW
 * the current matrix mode. */
void fcr_projection(struct scene *s);
/* Random clear colour and depth, then glClear(bits). */
void fcr_clear(fc_rng *r, GLbitfield bits);
/* The witness: a primitive that leaves visible pixels, so that a scene
 * whose own state hides everything (depth functions and clear depths that
 * reject every fragment, geometry outside the view volume, a viewport off
 * the window, fragment operations that discard or keep the colour) still
 * compares a drawing (a blank scene compares nothing).  A polygon of a
 * random type, random colours, vertices inside the part of the view
 * volume the window shows (window positions, depths and, through the
 * inverse of s->proj, object coordinates under an identity modelview),
 * drawn with glDepthFunc(GL_ALWAYS) inside glPushAttrib.  Every value
 * comes from s->vis.  The callers place it at a random point of the
 * scene, so later primitives test against what it wrote. */
void fcr_witness(struct scene *s);

#endif
