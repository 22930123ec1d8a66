/* fcr_shading.h - the GLSL reference of fixgl's shading extensions
 * (GL_WIN_phong_shading, GL_FIXGL_cook_torrance): a GLSL program on Mesa's
 * OSMesa that evaluates the equations of include/fixgl/shading.md, written
 * from that document alone, so that the conformance cases (and the viewer's
 * split view) can draw on the oracle what fixgl draws with its extensions.
 *
 * Everything goes through getproc (OSMesaGetProcAddress): the conformance
 * oracle links libOSMesa, the viewer dlopens it and must not see any other
 * gl* symbol.  GL-header-free.
 *
 *   struct fcr *r = fcr_create((fcr_getproc)OSMesaGetProcAddress);
 *   ... set up lights, materials, light model, colour material as usual ...
 *   fcr_bind(r, 1, &front, &back);      per fragment (GL_PHONG_WIN)
 *   ... draw ...
 *   fcr_unbind(r);
 *   fcr_destroy(r);
 *
 * The program replaces the fixed-function vertex and fragment stages: its
 * output is the lit colour sum, primary + secondary.rgb, with the vertex
 * position of ftransform() (bit-identical to the fixed-function position),
 * then what the fixed-function fragment stage does with it as far as the
 * cases need: a GL_MODULATE GL_TEXTURE_2D on unit 0 (identity texture
 * matrix) and fog (GL_LINEAR, GL_EXP, GL_EXP2; fog coordinate = fragment
 * depth).  Other texture environments make fcr_bind fail. */
#ifndef FCR_SHADING_H
#define FCR_SHADING_H

typedef void (*fcr_proc)(void);
typedef fcr_proc (*fcr_getproc)(const char *name);

/* One face's GL_FIXGL_cook_torrance parameters (shading.md). */
struct fcr_face {
    int cook_torrance;          /* 0: GL_BLINN_PHONG_FIXGL, 1: GL_COOK_TORRANCE_FIXGL */
    float roughness, metalness, f0;
};

struct fcr;

/* For the current context (OSMesa, GL 2.0+ with GLSL); NULL when an entry
 * point is missing. */
struct fcr *fcr_create(fcr_getproc getproc);
/* Deletes the programs (the context that created r must be current). */
void fcr_destroy(struct fcr *r);

/* Binds the program for the current fixed-function state, read back with
 * glGet / glIsEnabled: the enabled lights, GL_LIGHT_MODEL_LOCAL_VIEWER,
 * _TWO_SIDE and _COLOR_CONTROL, GL_COLOR_MATERIAL (face, parameter),
 * GL_NORMALIZE and GL_RESCALE_NORMAL, GL_TEXTURE_2D, GL_FOG and the fog
 * mode, start, end and density.  Light and material values are read
 * by the program at draw time (gl_LightSource, gl_FrontMaterial, ...), so
 * they may change while it is bound; the state read here may not.
 * per_fragment: every fragment is lit with the interpolated eye-space
 * normal and position (GL_PHONG_WIN); else every vertex (GL_SMOOTH or
 * GL_FLAT as glShadeModel says; the caller sets GL_SMOOTH for
 * per_fragment).  With lighting disabled nothing is bound (fixed function:
 * what GL_PHONG_WIN does without lighting).  A program is compiled once per
 * state combination and kept in r.  Returns 1, or 0 when the program does
 * not compile (the log goes to stderr).  Raises no GL error. */
int fcr_bind(struct fcr *r, int per_fragment, const struct fcr_face *front,
             const struct fcr_face *back);
/* Back to fixed function (glUseProgram(0), GL_VERTEX_PROGRAM_TWO_SIDE off). */
void fcr_unbind(struct fcr *r);

#endif
