/*
 * The fixgl context: GL state grouped by attribute group, the immediate-mode
 * vertex store, derived state and the framebuffer it draws into.
 *
 * Conventions (after Mesa):
 *  - Each group struct lives in the file that owns the group (main/xxx.c):
 *    defaults, entry points, getters.
 *  - Fields whose name starts with '_' are derived; only fgl_update_state()
 *    writes them.
 *  - Entry points validate their arguments and raise GL errors with
 *    fgl_error(); internal setters trust their input.
 *  - A state change first calls FGL_FLUSH_VERTICES (draws what is batched
 *    with the old state), then marks its FGL_NEW_* dirty bit.
 */
#ifndef FGL_CONTEXT_H
#define FGL_CONTEXT_H

#include <GL/gl.h>
#include <stdbool.h>
#include <stdint.h>

#include "math/m_matrix.h"
#include "raster/r_state.h"
#include "tnl/t_vbo.h"

/* Implementation limits, matching the oracle's values (llvmpipe-facts t00
 * and glGet queries on Mesa 22.3). */
#define FGL_MAX_MODELVIEW_STACK_DEPTH  32
#define FGL_MAX_PROJECTION_STACK_DEPTH 32
#define FGL_MAX_TEXTURE_STACK_DEPTH    10
#define FGL_MAX_PROGRAM_STACK_DEPTH    4
#define FGL_MAX_TEXTURE_UNITS          8
#define FGL_MAX_PROGRAM_MATRICES       8
#define FGL_MAX_VIEWPORT_SIZE          16384
#define FGL_VIEWPORT_BOUNDS_MIN        (-32768)
#define FGL_VIEWPORT_BOUNDS_MAX        32767
#define FGL_SUBPIXEL_BITS              8
/* llvmpipe's point size and line width limits (lp_screen.c
 * llvmpipe_get_paramf: 1..255 for aliased and smooth, granularity 0.1) */
#define FGL_MIN_POINT_SIZE             1.0f
#define FGL_MAX_POINT_SIZE             255.0f
#define FGL_MIN_LINE_WIDTH             1.0f
#define FGL_MAX_LINE_WIDTH             255.0f
#define FGL_POINT_LINE_GRANULARITY     0.1f

/* Dirty bits, one per group of derived state. */
enum {
   FGL_NEW_MODELVIEW  = 1u << 0,
   FGL_NEW_PROJECTION = 1u << 1,
   FGL_NEW_VIEWPORT   = 1u << 2,
   FGL_NEW_DEPTH      = 1u << 3,
   FGL_NEW_LIGHT      = 1u << 4,   /* lighting state and shade model */
   FGL_NEW_BUFFERS    = 1u << 5,   /* framebuffer bound or resized */
   FGL_NEW_POLYGON    = 1u << 6,   /* front face, culling */
   FGL_NEW_POINT      = 1u << 7,   /* point size, smoothing */
   FGL_NEW_LINE       = 1u << 8,   /* line width, smoothing, stipple */
};
#define FGL_NEW_ALL (~0u)

/* GL_CURRENT_BIT */
struct fgl_current_attrib {
   /* every vbo attribute's value outside the vertex format: normal, colour
    * and the materials (which GL groups with the lighting state) */
   float Attrib[FGL_ATTR_COUNT][4];
};

/* GL_COLOR_BUFFER_BIT (clear colour so far) */
struct fgl_colorbuffer_attrib {
   float ClearColor[4];     /* as given; clamped when used or queried */
   bool Dither;             /* accepted and ignored, as llvmpipe does */
};

/* GL_DEPTH_BUFFER_BIT */
struct fgl_depth_attrib {
   GLenum Func;
   double Clear;            /* clamped to [0,1] */
   bool Test;
   bool Mask;
};

#define FGL_MAX_LIGHTS 8

/* One light source, as glLight stores it (position and spot direction in
 * eye space, transformed by the modelview at call time). */
struct fgl_light {
   float Ambient[4], Diffuse[4], Specular[4];
   float EyePosition[4];
   float SpotDirection[3];
   float SpotExponent, SpotCutoff;
   float CosCutoff;             /* cosf(cutoff), clamped to >= 0 */
   float ConstantAttenuation, LinearAttenuation, QuadraticAttenuation;
   bool Enabled;
};

struct fgl_light_model {
   float Ambient[4];
   bool LocalViewer, TwoSide;
   GLenum ColorControl;         /* GL_SINGLE_COLOR or GL_SEPARATE_SPECULAR_COLOR */
};

/* GL_LIGHTING_BIT.  The material values are vbo attributes and live in
 * ctx->Current.Attrib[FGL_ATTR_MAT_*], as Mesa's vbo keeps them current. */
struct fgl_light_attrib {
   GLenum ShadeModel;
   bool Enabled;                /* GL_LIGHTING */
   struct fgl_light Light[FGL_MAX_LIGHTS];
   struct fgl_light_model Model;
   bool ColorMaterialEnabled;
   GLenum ColorMaterialFace, ColorMaterialMode;
   unsigned _ColorMaterialBitmask;  /* FGL_MAT_BIT_* that track the colour */
};

/* Bits of the material attributes, in vbo attribute order (Mesa's
 * MAT_BIT_*): bit i is FGL_ATTR_MAT_FIRST + i. */
#define FGL_MAT_BIT(attr) (1u << ((attr) - FGL_ATTR_MAT_FIRST))
#define FGL_MAT_BITS_FRONT 0x1555u    /* even bits: front */
#define FGL_MAT_BITS_BACK  0x2aaau    /* odd bits: back */
#define FGL_MAT_BITS_ALL   0x3fffu

/* Lighting state as the oracle's fixed-function vertex program sees it at
 * draw time (derived by fgl_update_lighting, main/light.c): the light
 * positions and directions in the lighting space, and the values Mesa
 * precomputes on the CPU (prog_statevars.c). */
struct fgl_light_derived {
   float Position[4];       /* STATE_LIGHT_POSITION, or _NORMALIZED when directional */
   float HalfVector[3];     /* STATE_LIGHT_HALF_VECTOR (directional light) */
   float SpotDirection[3];  /* STATE_LIGHT_SPOT_DIR_NORMALIZED */
   bool Positional, Spot, Attenuated;
};

struct fgl_lighting_derived {
   bool NeedEyeCoords;      /* ctx->_NeedEyeCoords: light in eye space */
   float NormalScale;       /* STATE_NORMAL_SCALE (_ModelViewInvScale) */
   unsigned EnabledLights;  /* bit i: GL_LIGHTi */
   struct fgl_light_derived Light[FGL_MAX_LIGHTS];
};

/* GL_POLYGON_BIT (so far) */
struct fgl_polygon_attrib {
   GLenum FrontFace;        /* GL_CW or GL_CCW */
   GLenum CullFaceMode;     /* GL_FRONT, GL_BACK or GL_FRONT_AND_BACK */
   bool CullFlag;           /* GL_CULL_FACE */
};

/* GL_POINT_BIT (main/points.c) */
struct fgl_point_attrib {
   float Size;              /* as given (> 0); clamped when drawn */
   bool SmoothFlag;         /* GL_POINT_SMOOTH */
};

/* GL_LINE_BIT (main/lines.c) */
struct fgl_line_attrib {
   float Width;             /* as given (> 0); clamped when drawn */
   bool SmoothFlag;         /* GL_LINE_SMOOTH */
   bool StippleFlag;        /* GL_LINE_STIPPLE */
   GLushort StipplePattern;
   GLint StippleFactor;     /* clamped to [1, 256] */
};

/* GL_TRANSFORM_BIT */
struct fgl_transform_attrib {
   GLenum MatrixMode;
   bool Normalize;          /* GL_NORMALIZE */
   bool RescaleNormals;     /* GL_RESCALE_NORMAL */
};

/* GL_VIEWPORT_BIT */
struct fgl_viewport_attrib {
   int X, Y, Width, Height;   /* after Mesa's clamping */
   float Near, Far;           /* clamped to [0,1]; float, as Mesa stores them */
};

struct fgl_matrix_stack {
   fgl_matrix *Top;
   fgl_matrix *Stack;
   unsigned Depth;            /* index of Top: 0-based */
   unsigned MaxDepth;
   unsigned DirtyFlag;        /* FGL_NEW_MODELVIEW, FGL_NEW_PROJECTION or 0 */
};

/* The framebuffer a context draws into (owned by the OSMesa layer). */
struct fgl_framebuffer {
   int Width, Height;
   uint8_t *Color;            /* RGBA8, row 0 = top (y-down, as the oracle) */
   void *Depth;               /* NULL, uint16_t (Z16) or uint32_t (Z24X8/Z24S8) */
   int DepthBits;             /* 0, 16 or 24 */
   int StencilBits;           /* 0 or 8 */
   int AlphaBits;             /* 8, or 0 for the RGB formats */
   enum r_zs_format ZSFormat;
   uint8_t *Stencil;          /* stencil-only buffer (S8) when no depth */
   /* called by glFlush/glFinish to make the image visible to the owner */
   void (*FlushFront)(struct fgl_framebuffer *fb);
};

struct fgl_context {
   /* ---- GL state, one struct per attribute group ---- */
   struct fgl_current_attrib Current;
   struct fgl_colorbuffer_attrib Color;
   struct fgl_depth_attrib Depth;
   struct fgl_light_attrib Light;
   struct fgl_polygon_attrib Polygon;
   struct fgl_point_attrib Point;
   struct fgl_line_attrib Line;
   struct fgl_transform_attrib Transform;
   struct fgl_viewport_attrib Viewport;

   struct fgl_matrix_stack ModelviewStack;
   struct fgl_matrix_stack ProjectionStack;
   struct fgl_matrix_stack TextureStack[FGL_MAX_TEXTURE_UNITS];
   struct fgl_matrix_stack ProgramStack[FGL_MAX_PROGRAM_MATRICES];
   struct fgl_matrix_stack *CurrentStack;

   /* enable flags of GL 1.x features still to come (main/enable.c) */
#define FGL_PENDING_CAPS 43
   bool PendingCaps[FGL_PENDING_CAPS];

   /* ---- immediate mode ---- */
   GLenum BeginMode;          /* FGL_OUTSIDE_BEGIN_END when not inside */
   struct fgl_vbo Vbo;
   /* the draw module's line stipple counter (draw_pipe_stipple.c): reset
    * by the first line of a primitive, kept across draws otherwise */
   unsigned StippleCounter;

   /* ---- errors ---- */
   GLenum ErrorValue;

   /* ---- derived state (written by fgl_update_state only) ---- */
   unsigned NewState;
   fgl_matrix _ModelProjectMatrix;
   struct fgl_lighting_derived _Lighting;
   float _ViewportScale[3], _ViewportTranslate[3];
   struct r_state _Raster;
   /* llvmpipe leaves two-sided lighting to the draw module while line
    * stipple or smooth points/lines are on (lp_state_rasterizer.c
    * need_pipeline, clear_flags), and draw then runs every triangle through
    * its pipeline (draw_need_pipeline: light_twoside): float-determinant
    * culling and colour choice, the pipeline's quad split */
   bool _DrawTwosideTris;

   /* ---- framebuffer ---- */
   struct fgl_framebuffer *DrawBuffer;
   bool ViewportInitialized;
};

#define FGL_OUTSIDE_BEGIN_END 0xffffu

/* The current context of the calling thread (the only mutable global). */
struct fgl_context *fgl_get_current(void);
void fgl_set_current(struct fgl_context *ctx);

struct fgl_context *fgl_context_create(void);
void fgl_context_destroy(struct fgl_context *ctx);
void fgl_context_bind_framebuffer(struct fgl_context *ctx, struct fgl_framebuffer *fb);

/* Record a GL error; the first one since the last glGetError wins. */
void fgl_error(struct fgl_context *ctx, GLenum error);

/* Mesa's FLUSH_VERTICES: draw whatever the immediate-mode store has
 * batched (if a primitive was stored since the last flush) and reset the
 * vertex format. */
void fgl_flush_vertices(struct fgl_context *ctx);

/* Mesa's FLUSH_CURRENT: copy the values of the vertex format's attributes
 * to ctx->Current (colour material included), keeping the format. */
void fgl_flush_current(struct fgl_context *ctx);

/* Recompute derived state for the dirty groups, in dependency order. */
void fgl_update_state(struct fgl_context *ctx);

static inline bool fgl_inside_begin_end(const struct fgl_context *ctx)
{
   return ctx->BeginMode != FGL_OUTSIDE_BEGIN_END;
}

/* Entry point prologue: fetch the current context; return if there is none. */
#define GET_CURRENT_CONTEXT(C) struct fgl_context *C = fgl_get_current()

/* Commands not allowed between glBegin and glEnd raise INVALID_OPERATION. */
#define ASSERT_OUTSIDE_BEGIN_END_RET(ctx, ret)             \
   do {                                                    \
      if (fgl_inside_begin_end(ctx)) {                     \
         fgl_error(ctx, GL_INVALID_OPERATION);             \
         return ret;                                       \
      }                                                    \
   } while (0)
#define ASSERT_OUTSIDE_BEGIN_END(ctx) ASSERT_OUTSIDE_BEGIN_END_RET(ctx, )

/* Flush batched vertices before a state change and mark it dirty. */
#define FGL_FLUSH_VERTICES(ctx, newstate)                  \
   do {                                                    \
      fgl_flush_vertices(ctx);                             \
      (ctx)->NewState |= (newstate);                       \
   } while (0)

/* Public API symbols; everything else is hidden by default. */
#define FGLAPI __attribute__((visibility("default")))

#endif
