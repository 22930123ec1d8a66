/* fc_case.h - the conformance case API.
 *
 * A case is a plain C function that drives GL 1.x like a legacy program.
 * The harness creates the OSMesa context and colour buffer described by the
 * case's table entry, makes it current, calls the function with a handle,
 * records a final glGetError() and destroys the context.  Everything a case
 * wants compared between the oracle (Mesa llvmpipe) and fixgl goes through
 * the fc_* recording helpers below.
 *
 * The same case sources are compiled into both renderers; the GL/OSMesa
 * headers come from Mesa for the oracle and from fixgl (plus the system
 * <GL/gl.h>) for fixgl. */
#ifndef FC_CASE_H
#define FC_CASE_H

#include "fc_record.h"

#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stddef.h>

typedef struct fc_h fc_h;
typedef void (*fc_case_fn)(fc_h *h);

typedef struct fc_case {
    const char *name;       /* unique, "group/name" */
    int width, height;      /* framebuffer size */
    GLenum format;          /* OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR */
    int depth_bits, stencil_bits;
    int frames;             /* number of fc_capture* calls the case makes */
    const char *tags;       /* space separated, e.g. "core depth" */
    fc_case_fn fn;
    int row_length;         /* colour buffer row length in pixels; 0 = width */
    int raw_oracle_rgb;     /* OSMESA_RGB only: 1 = let the oracle render into
                             * its own OSMESA_RGB buffer (see below) */
    int tolerance_lsb;      /* 0 = colours exact; N > 0: only for a case tagged
                             * "reference" (see below) */
    int draws_nothing;      /* FC_DRAWS_NOTHING: every frame the case
                             * captures shows a cleared buffer on purpose;
                             * FC_MAY_DRAW_NOTHING: a generated scene (see
                             * below); 0: the case draws */
} fc_case;

/* Cases that compare nothing.  A frame whose colour pixels are all alike
 * and whose depth values are all alike shows a cleared (or untouched)
 * buffer: nothing drawn shows in it.  A case that captures frames, all of
 * them such on both sides, compares no drawing at all, which is what a
 * broken case looks like (geometry outside the view, a wrong projection,
 * a draw the state discards): the runner reports it as "blank", which
 * fails like a difference.  A case that checks only errors, queries or a
 * clear value, and captures frames of a cleared buffer on purpose, sets
 * draws_nothing; the runner then requires that none of its frames shows
 * anything drawn (the declaration is stale otherwise, and fails too).
 * Cases that capture no frame (frames = 0) compare records only and are
 * not concerned.  The random families' scenes set FC_MAY_DRAW_NOTHING: a
 * generated state (a depth function, a matrix, clip coordinates) may
 * discard everything, which no single scene can declare; the runner counts
 * and lists those scenes per family ("blank, allowed") without failing. */
/* (FC_DRAWS_NOTHING and FC_MAY_DRAW_NOTHING: fc_record.h) */

/* Reference cases.  A case that exercises something the oracle does not
 * have (fixgl's shading extensions) draws its reference differently: the
 * source is compiled into both renderers, and under FC_ORACLE the case
 * issues other calls (a GLSL program on OSMesa evaluating the same
 * equations, conformance/reference/) where the fixgl side calls the
 * extension.  Such a case carries the tag "reference" and declares in
 * tolerance_lsb how far a colour channel may differ (the two sides round
 * float arithmetic differently).  The runner measures per frame the
 * largest channel difference and the pixels at 1 LSB and beyond; the case
 * "agrees" when no channel differs by more than tolerance_lsb and depth,
 * errors, queries, blobs and values are exact.  A tolerance on a case
 * without the "reference" tag is a setup error of the runner, so nothing
 * else can loosen. */

/* The oracle's OSMESA_RGB colour buffers are corrupt: llvmpipe stores every
 * shaded fragment of a 3-byte-per-pixel render target with misplaced 4-byte
 * writes (and a clear can zero whole pixels), so neighbouring pixels get
 * bytes of each other.  Unless a case sets raw_oracle_rgb, the oracle side
 * renders an OSMESA_RGB case into an OSMESA_RGBA context and buffer and
 * converts that buffer to the case's RGB layout at every capture, which is
 * what a correct OSMESA_RGB buffer holds.  Cases that query alpha bits or
 * read alpha back must set raw_oracle_rgb. */

/* Captures a frame: glFinish(), then the whole user colour buffer exactly as
 * laid out and the raw OSMesaGetDepthBuffer() contents. */
void fc_capture(fc_h *h);
/* Same for another colour buffer (e.g. one bound to a second context). */
void fc_capture_buffer(fc_h *h, const void *buf, int width, int height,
                       int row_length, GLenum format, int y_up);

/* Records glGetError() under a label. */
void fc_error(fc_h *h, const char *label);

/* Records glGet*v(pname) (count values, the output array is pre-filled with
 * a fixed pattern so unwritten values compare equal) and glIsEnabled(cap). */
void fc_get_integer(fc_h *h, const char *label, GLenum pname, int count);
void fc_get_float(fc_h *h, const char *label, GLenum pname, int count);
void fc_get_double(fc_h *h, const char *label, GLenum pname, int count);
void fc_get_boolean(fc_h *h, const char *label, GLenum pname, int count);
void fc_is_enabled(fc_h *h, const char *label, GLenum cap);

/* Records arbitrary bytes (glReadPixels results, ...) and integer values
 * (OSMesa return values, pointer comparisons, ...). */
void fc_blob(fc_h *h, const char *label, const void *data, size_t size);
void fc_value(fc_h *h, const char *label, long long value);

/* Declares a documented, intentional difference: the query, value and blob
 * records labelled `label` that the case records afterwards may differ
 * from the oracle because of `reason` (an implementation string, a limit
 * fixgl chooses on purpose...).  Such a difference does not make the case
 * differ; the runner lists it, with its reason and both values, in the
 * report (index.html, summary.json).  Nothing else is loosened: errors and
 * frames always compare, every other label compares exactly, and a
 * declared label whose records all compare equal makes the case differ
 * (the declaration is stale).  Both renderers run the same declaration, so
 * the reason is part of the compared record stream. */
void fc_documented_difference(fc_h *h, const char *label, const char *reason);

/* OSMesaPixelStore on the current context; the harness remembers OSMESA_Y_UP
 * so frames are displayed the right way up in the report. */
void fc_pixel_store(fc_h *h, GLint pname, GLint value);

/* The harness-created context, its colour buffer and the case entry. */
OSMesaContext fc_context(fc_h *h);
void *fc_buffer(fc_h *h);
const fc_case *fc_this_case(fc_h *h);

/* Bytes per pixel of an OSMesa colour format (0 if unknown). */
int fc_format_bpp(GLenum format);

/* Convenience used by many cases: viewport = whole framebuffer, projection =
 * glOrtho(0, w, 0, h, -1, 1) so object coordinates are window coordinates,
 * modelview = identity. */
void fc_pixel_ortho(fc_h *h);

#endif
