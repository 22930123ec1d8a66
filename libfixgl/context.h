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
#include <stddef.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>

#include "math/m_matrix.h"
#include "raster/r_scene.h"
#include "raster/r_state.h"
#include "tnl/t_vbo.h"

/* Implementation limits, matching the oracle's values (ORACLE-NOTES.md
 * "The oracle and its host", probe p_limits, and glGet queries on Mesa
 * 22.3). */
#define FGL_MAX_MODELVIEW_STACK_DEPTH  32
#define FGL_MAX_PROJECTION_STACK_DEPTH 32
#define FGL_MAX_TEXTURE_STACK_DEPTH    10
#define FGL_MAX_TEXTURE_UNITS          8
/* the units glActiveTexture takes (Const.MaxCombinedTextureImageUnits);
 * those past the eight above have a binding and a LOD bias only */
#define FGL_MAX_COMBINED_TEXTURE_UNITS 192
#define FGL_IMAGE_ONLY_UNITS (FGL_MAX_COMBINED_TEXTURE_UNITS - FGL_MAX_TEXTURE_UNITS)
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
/* Texture and evaluator limits, reported as the oracle reports them (its
 * Const values for llvmpipe; the 3D and cube-map sizes are queried only:
 * fixgl has no such textures) [S: main/config.h, gallium/drivers/
 * llvmpipe/lp_screen.c, lp_limits.h] */
#define FGL_MAX_TEXTURE_SIZE           16384   /* LP_MAX_TEXTURE_2D_LEVELS 15 */
#define FGL_MAX_3D_TEXTURE_SIZE        2048    /* LP_MAX_TEXTURE_3D_LEVELS 12 */
#define FGL_MAX_3D_TEXTURE_LEVELS      12      /* Const.Max3DTextureLevels */
#define FGL_MAX_CUBE_MAP_TEXTURE_SIZE  16384   /* LP_MAX_TEXTURE_CUBE_LEVELS 15 */
#define FGL_MAX_TEXTURE_LOD_BIAS       16.0f
#define FGL_MAX_EVAL_ORDER             30      /* MAX_EVAL_ORDER */
/* GL_MAX_ELEMENTS_VERTICES/INDICES: a recommendation only (fixgl draws any
 * count); Mesa reports Const.MaxArrayLockSize */
#define FGL_MAX_ELEMENTS               3000

/* Dirty bits, one per group of derived state. */
enum {
   FGL_NEW_MODELVIEW  = 1u << 0,
   FGL_NEW_PROJECTION = 1u << 1,
   FGL_NEW_VIEWPORT   = 1u << 2,
   FGL_NEW_DEPTH      = 1u << 3,
   FGL_NEW_LIGHT      = 1u << 4,   /* lighting state and shade model */
   FGL_NEW_BUFFERS    = 1u << 5,   /* framebuffer bound or resized */
   FGL_NEW_POLYGON    = 1u << 6,   /* front face, culling, offset, stipple, fill modes */
   FGL_NEW_SCISSOR    = 1u << 7,   /* scissor box and test */
   FGL_NEW_COLOR      = 1u << 8,   /* alpha test, blending, logic op, colour mask */
   FGL_NEW_STENCIL    = 1u << 9,   /* stencil test */
   FGL_NEW_FOG        = 1u << 10,  /* fog state and GL_FOG */
   FGL_NEW_CLIP       = 1u << 11,  /* user clip planes */
   FGL_NEW_POINT      = 1u << 12,  /* point size, smoothing */
   FGL_NEW_LINE       = 1u << 13,  /* line width, smoothing, stipple */
   FGL_NEW_RENDERMODE = 1u << 14,  /* glRenderMode: the draw pipeline's stages */
   FGL_NEW_PIXEL      = 1u << 15,  /* pixel transfer, zoom and maps (main/pixel.c) */
   FGL_NEW_TEXTURE    = 1u << 16,  /* texture objects, images, enables, units */
   FGL_NEW_TEXTURE_MATRIX = 1u << 17,  /* a texture matrix (Mesa's
                                        * _NEW_TEXTURE_MATRIX) */
};
#define FGL_NEW_ALL (~0u)

/* GL_CURRENT_BIT */
struct fgl_current_attrib {
   /* every vbo attribute's value outside the vertex format: normal, colour
    * and the materials (which GL groups with the lighting state) */
   float Attrib[FGL_ATTR_COUNT][4];
   /* the current raster position (glRasterPos, glWindowPos: main/rastpos.c)
    * [S: main/context.h, gl_current_attrib] */
   float RasterPos[4];                           /* (0, 0, 0, 1) */
   float RasterDistance;                         /* 0 */
   float RasterColor[4];                         /* (1, 1, 1, 1) */
   float RasterSecondaryColor[4];                /* (0, 0, 0, 1) */
   float RasterTexCoords[FGL_MAX_TEXTURE_UNITS][4]; /* (0, 0, 0, 1) */
   bool RasterPosValid;                          /* true */
};

/* GL_COLOR_BUFFER_BIT */
struct fgl_colorbuffer_attrib {
   float ClearColor[4];     /* as given; clamped when used or queried */
   bool Dither;             /* accepted and ignored, as llvmpipe does */
   /* alpha test (main/blend.c) */
   bool AlphaEnabled;
   GLenum AlphaFunc;
   float AlphaRef;          /* as given (Mesa's AlphaRefUnclamped) */
   /* blending: the factor pair and equation for rgb, and for alpha
    * (glBlendFuncSeparate, glBlendEquationSeparate) */
   bool BlendEnabled;
   GLenum BlendSrc, BlendDst;
   GLenum BlendEquation;
   GLenum BlendSrcA, BlendDstA;
   GLenum BlendEquationA;
   float BlendColor[4];     /* as given (Mesa's BlendColorUnclamped) */
   /* logic op */
   bool LogicOpEnabled;     /* GL_COLOR_LOGIC_OP */
   bool IndexLogicOpEnabled;   /* GL_INDEX_LOGIC_OP: no effect on RGBA */
   GLenum LogicOp;
   unsigned ColorMask;      /* bit 0 red .. bit 3 alpha */
   /* colour index state: stored and queried, no effect on the RGBA
    * buffer (main/clear.c) */
   GLuint IndexMask;        /* ~0 */
   GLuint ClearIndex;       /* 0; glClearIndex's (GLuint) cast of the float */
   /* glDrawBuffer (main/buffers.c): as given; GL_NONE draws no colour */
   GLenum DrawBuffer;
};

/* GL_SCISSOR_BIT */
struct fgl_scissor_attrib {
   bool Enabled;
   int X, Y, Width, Height;
};

/* GL_STENCIL_BUFFER_BIT (one state for both faces: GL 1.x) */
struct fgl_stencil_attrib {
   bool Enabled;
   GLenum Func;
   int Ref;                 /* as given; clamped to the buffer's range when used */
   GLuint ValueMask;
   GLuint WriteMask;
   GLenum FailFunc, ZFailFunc, ZPassFunc;
   GLuint Clear;
};

/* GL_DEPTH_BUFFER_BIT */
struct fgl_depth_attrib {
   GLenum Func;
   double Clear;            /* clamped to [0,1] */
   bool Test;
   GLboolean Mask;          /* as given (Mesa stores the byte: 255 queries as 255) */
};

/* GL_FOG_BIT, as Mesa's main/fog.c stores it */
struct fgl_fog_attrib {
   bool Enabled;                /* GL_FOG */
   GLenum Mode;                 /* GL_LINEAR, GL_EXP or GL_EXP2 */
   float Color[4];              /* clamped to [0,1] (NaN -> 0) */
   float ColorUnclamped[4];     /* as given */
   float Density, Start, End;
   float Index;                 /* GL_FOG_INDEX: stored, unused in RGBA */
   GLenum CoordinateSource;     /* GL_FRAGMENT_DEPTH or GL_FOG_COORDINATE */
   GLenum DistanceMode;         /* GL_NV_fog_distance: GL_EYE_RADIAL_NV,
                                 * GL_EYE_PLANE, GL_EYE_PLANE_ABSOLUTE_NV */
   bool ColorSumEnabled;        /* GL_COLOR_SUM (Mesa keeps it here too) */
};

/* GL_HINT_BIT: stored and reported; none of them changes the oracle's
 * output. */
struct fgl_hint_attrib {
   GLenum PerspectiveCorrection, PointSmooth, LineSmooth, PolygonSmooth, Fog;
   GLenum TextureCompression, GenerateMipmap;
   GLenum PhongWin;             /* GL_PHONG_HINT_WIN (include/fixgl/shading.md) */
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

/* A face's reflectance model (GL_FIXGL_cook_torrance,
 * include/fixgl/shading.md): lighting state set through glMaterial, not a
 * vertex attribute. */
struct fgl_reflectance {
   GLenum Model;                /* GL_BLINN_PHONG_FIXGL or GL_COOK_TORRANCE_FIXGL */
   float Roughness, Metalness, F0;
};

/* GL_LIGHTING_BIT.  The material values are vbo attributes and live in
 * ctx->Current.Attrib[FGL_ATTR_MAT_*], as Mesa's vbo keeps them current;
 * the reflectance models are state of the group (Reflectance). */
struct fgl_light_attrib {
   GLenum ShadeModel;
   bool Enabled;                /* GL_LIGHTING */
   struct fgl_light Light[FGL_MAX_LIGHTS];
   struct fgl_light_model Model;
   bool ColorMaterialEnabled;
   GLenum ColorMaterialFace, ColorMaterialMode;
   unsigned _ColorMaterialBitmask;  /* FGL_MAT_BIT_* that track the colour */
   struct fgl_reflectance Reflectance[2];   /* front, back */
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

/* GL_POLYGON_BIT */
struct fgl_polygon_attrib {
   GLenum FrontFace;        /* GL_CW or GL_CCW */
   GLenum CullFaceMode;     /* GL_FRONT, GL_BACK or GL_FRONT_AND_BACK */
   bool CullFlag;           /* GL_CULL_FACE */
   bool SmoothFlag;         /* GL_POLYGON_SMOOTH: no effect in the oracle */
   GLenum FrontMode, BackMode;  /* glPolygonMode: GL_POINT, GL_LINE, GL_FILL */
   float OffsetFactor, OffsetUnits;
   bool OffsetFill, OffsetLine, OffsetPoint;  /* GL_POLYGON_OFFSET_* */
   bool StippleFlag;        /* GL_POLYGON_STIPPLE */
};

/* glPixelStore state of one direction (Mesa's gl_pixelstore_attrib) */
struct fgl_pixelstore {
   int Alignment, RowLength, SkipPixels, SkipRows, ImageHeight, SkipImages;
   bool SwapBytes, LsbFirst;
};

#define FGL_MAX_CLIP_PLANES 8         /* Const.MaxClipPlanes with GLSL >= 1.30 */

/* GL_ACCUM_BUFFER_BIT (main/accum.c) */
struct fgl_accum_attrib {
   float ClearColor[4];     /* glClearAccum, clamped to [-1, 1] */
};

/* The pixel maps (glPixelMap, main/pixel.c) [S: main/mtypes.h,
 * gl_pixelmaps]: each has one entry, 0, at first. */
#define FGL_MAX_PIXEL_MAP_TABLE 256
struct fgl_pixelmap {
   GLint Size;
   float Map[FGL_MAX_PIXEL_MAP_TABLE];
};

struct fgl_pixelmaps {
   struct fgl_pixelmap RtoR, GtoG, BtoB, AtoA;
   struct fgl_pixelmap ItoR, ItoG, ItoB, ItoA;
   struct fgl_pixelmap ItoI, StoS;
};

/* GL_PIXEL_MODE_BIT [S: main/mtypes.h, gl_pixel_attrib]: pixel transfer
 * and zoom (main/pixel.c), and the read buffer */
struct fgl_pixel_attrib {
   GLenum ReadBuffer;       /* glReadBuffer (main/buffers.c): as given */
   float RedBias, RedScale;
   float GreenBias, GreenScale;
   float BlueBias, BlueScale;
   float AlphaBias, AlphaScale;
   float DepthBias, DepthScale;
   GLint IndexShift, IndexOffset;
   bool MapColorFlag;       /* GL_MAP_COLOR */
   bool MapStencilFlag;     /* GL_MAP_STENCIL */
   float ZoomX, ZoomY;
};

/* GL_EVAL_BIT [S: main/mtypes.h, gl_eval_attrib]: the map grids of
 * glMapGrid (main/eval.c); the GL_MAPn_* and GL_AUTO_NORMAL enables are
 * stored with the maps (struct fgl_eval_maps below, main/eval.c
 * fgl_eval_cap_flag) */
struct fgl_eval_attrib {
   GLint MapGrid1un;
   float MapGrid1u1, MapGrid1u2, MapGrid1du;
   GLint MapGrid2un, MapGrid2vn;
   float MapGrid2u1, MapGrid2u2, MapGrid2du;
   float MapGrid2v1, MapGrid2v2, MapGrid2dv;
};

/* The evaluator maps (main/eval.c) [S: main/mtypes.h, gl_1d_map,
 * gl_2d_map, gl_evaluators]: indexed by target - GL_MAP1_COLOR_4 and
 * target - GL_MAP2_COLOR_4.  The control points are Mesa's float copy,
 * packed (order x components); a 2D map keeps room after them for the
 * scratch values of the Horner and de Casteljau evaluation
 * (_mesa_copy_map_points2f's hsize/dsize). The enables (GL_MAPn_*,
 * GL_AUTO_NORMAL) are Mesa's gl_eval_attrib flags, saved by GL_EVAL_BIT
 * through attrib.c's cap list. */
#define FGL_EVAL_TARGETS 9
struct fgl_eval_map1 {
   GLint Order;
   float u1, u2, du;
   float Points[FGL_MAX_EVAL_ORDER * 4];
};
struct fgl_eval_map2 {
   GLint Uorder, Vorder;
   bool NoPoints;        /* glMap2 without points: Mesa's Points == NULL */
   float u1, u2, du, v1, v2, dv;
   float Points[FGL_MAX_EVAL_ORDER * FGL_MAX_EVAL_ORDER * 5];
};
struct fgl_eval_maps {
   struct fgl_eval_map1 Map1[FGL_EVAL_TARGETS];
   struct fgl_eval_map2 Map2[FGL_EVAL_TARGETS];
   bool Map1Enabled[FGL_EVAL_TARGETS], Map2Enabled[FGL_EVAL_TARGETS];
   bool AutoNormal;
};

/* The texture targets an object can be bound to: GL 1.5's, in the order
 * of the oracle's texobj.c:_mesa_tex_target_to_index (its rectangle, array,
 * buffer and multisample targets are GL_INVALID_ENUM in fixgl: README
 * "Version and honesty") */
enum fgl_tex_index {
   FGL_TEX_1D, FGL_TEX_2D, FGL_TEX_3D, FGL_TEX_CUBE,
   FGL_TEX_TARGETS,
};

/* GL_TEXTURE_BIT, as far as glGet reports it: the active unit and the
 * texture object names bound to each unit (0, the default textures); the
 * texture path adds the objects, environment and coordinate generation
 * [S: main/mtypes.h, gl_texture_attrib] */
struct fgl_texture_unit {
   GLuint Bound[FGL_TEX_TARGETS];   /* object names, 0 the default object */
   /* glEnable of the unit's targets (bit FGL_TEX_* of GL_TEXTURE_1D, 2D,
    * 3D, CUBE_MAP) and of its coordinate generation (bit 0 S .. 3 Q)
    * [S: mtypes.h, gl_fixedfunc_texture_unit Enabled, TexGenEnabled] */
   unsigned Enabled;
   unsigned TexGenEnabled;
   /* the texture environment (main/texenv.c) [S: mtypes.h,
    * gl_fixedfunc_texture_unit, gl_tex_env_combine_state] */
   GLenum EnvMode;
   float EnvColor[4];               /* clamped */
   float EnvColorUnclamped[4];
   GLenum CombineModeRGB, CombineModeA;
   GLenum SourceRGB[4], SourceA[4];
   GLenum OperandRGB[4], OperandA[4];
   unsigned ScaleShiftRGB, ScaleShiftA;
   float LodBias;                   /* GL_TEXTURE_FILTER_CONTROL */
   /* coordinate generation (main/texgen.c), S T R Q */
   GLenum GenMode[4];
   float ObjectPlane[4][4];
   float EyePlane[4][4];            /* in eye space (inverse modelview
                                     * applied when specified) */
};

/* Coordinate generation modes as bits (Mesa's TEXGEN_*, mtypes.h) and
 * those that need eye coordinates (TEXGEN_NEED_EYE_COORD) */
#define FGL_TEXGEN_SPHERE_MAP     0x1u
#define FGL_TEXGEN_OBJ_LINEAR     0x2u
#define FGL_TEXGEN_EYE_LINEAR     0x4u
#define FGL_TEXGEN_REFLECTION_MAP 0x8u
#define FGL_TEXGEN_NORMAL_MAP     0x10u
#define FGL_TEXGEN_NEED_EYE_COORD (FGL_TEXGEN_SPHERE_MAP | FGL_TEXGEN_REFLECTION_MAP | \
                                   FGL_TEXGEN_NORMAL_MAP | FGL_TEXGEN_EYE_LINEAR)

struct fgl_texture_attrib {
   GLuint CurrentUnit;      /* glActiveTexture - GL_TEXTURE0 */
   struct fgl_texture_unit Unit[FGL_MAX_TEXTURE_UNITS];
   /* the names bound to units 8..191 (GL_TEXTURE_BIT restores them like
    * the others') */
   GLuint ImageBound[FGL_IMAGE_ONLY_UNITS][FGL_TEX_TARGETS];
};

/* One mipmap level of a texture object (main/teximage.c)
 * [S: main/mtypes.h, gl_texture_image].  The texels are stored as RGBA8
 * whatever the base format, already expanded the way the oracle's sampler
 * swizzles its format (LUMINANCE: L, L, L, 1; ALPHA: 0, 0, 0, A;
 * INTENSITY: I, I, I, I; LUMINANCE_ALPHA: L, L, L, A; RGB: R, G, B, 1), so
 * the raster core filters four 8-bit channels alike; row 0 is the first
 * row the application gave (t = 0, the bottom of the image). */
#define FGL_MAX_TEXTURE_LEVELS 15   /* LP_MAX_TEXTURE_2D_LEVELS */

/* One of the oracle's texture resources (a pipe_resource an st texture
 * object or image holds), as far as it decides how glGetTexImage reads an
 * image (main/teximage.c "Storage"; ORACLE-NOTES.md "Compressed textures:
 * LATC", cube faces of mixed formats): Id 0 is none; ids are unique
 * within their texture object. */
struct fgl_tex_storage {
   unsigned Id;
   const struct fgl_tex_pipe_format *Format;   /* the pipe format ... */
   GLenum CompressedFormat;                    /* ... told apart */
   GLint Width0, Height0, Depth0;              /* level 0's size */
   GLint LastLevel;
};

struct fgl_texture_image {
   GLint Width, Height, Border;     /* Height 1 for 1D images */
   GLint Depth;                     /* 1 for 1D and 2D images */
   GLenum InternalFormat;           /* as the application gave it */
   GLenum BaseFormat;               /* GL_RGBA, GL_RGB, GL_LUMINANCE,
                                     * GL_LUMINANCE_ALPHA, GL_ALPHA or
                                     * GL_INTENSITY */
   /* Data, Store and ZValues are reference-counted blocks (fgl_rc_alloc:
    * the state objects that sample them hold them; main/teximage.c) */
   uint8_t *Data;                   /* Width * Height * Depth RGBA8
                                     * texels, slice by slice */
   /* the oracle's pipe format for the image (its channel bits, which
    * glGetTexLevelParameter reports; main/teximage.c) */
   const struct fgl_tex_pipe_format *Format;
   /* The values the oracle stores, in their own precision, for an image
    * whose pipe format has a channel of other than 8 bits (NULL for the
    * 8-bit formats, where Data is exact): Width * Height texels of four
    * uint16_t in Data's order (R, G, B, A after the base format's
    * expansion: L in R, G and B, I in all four), channel c an unsigned
    * integer of StoreBits[c] bits (1..16; its float is
    * Store[c] * (1.0f / ((1 << bits) - 1)), or bits 0: a constant of the
    * format, Store[c] is then 0 or 1).  Data holds each such value as the
    * oracle expands it to 8 bits (_mesa_unorm_to_unorm(x, bits, 8)). */
   uint16_t *Store;
   uint8_t StoreBits[4];
   /* a GL_DEPTH_COMPONENT image (BaseFormat): the oracle's stored depth
    * values, Width * Height * Depth texels of the pipe format's bits (16, 24 or
    * 32: fgl_tex_image_depth_bits; main/texdepth.c), else NULL */
   uint32_t *ZValues;
   /* an image of a compressed format (main/texcompress.c): the blocks as
    * the application gave them (glGetCompressedTexImage returns them),
    * BlocksSize bytes; Data holds the texels the oracle decodes from them.
    * NULL for an uncompressed image. */
   uint8_t *Blocks;
   size_t BlocksSize;
   /* the S3TC format of Blocks (InternalFormat, or the one the oracle
    * picks for GL_COMPRESSED_RGB/RGBA), 0 for an uncompressed image */
   GLenum CompressedFormat;
   /* the oracle's storage the image lives in (main/teximage.c
    * "Storage"): the object's, or one of its own */
   struct fgl_tex_storage Storage;
};

/* A texture object's state (main/texobj.c, texparam.c) and its images
 * (main/teximage.c) [S: main/mtypes.h, gl_texture_object,
 * gl_sampler_attrib] */
struct fgl_texture_object {
   GLuint Name;
   /* references: the shared table's while the name exists, and each unit
    * binding of each context (Mesa's RefCount, _mesa_reference_texobj);
    * the object and its images are freed with the last one, changed under
    * the table's lock; the default objects are not counted */
   unsigned RefCount;
   GLenum Target;           /* 0 until first bound */
   GLenum MinFilter, MagFilter;
   GLenum WrapS, WrapT, WrapR;
   float BorderColor[4];    /* clamped to [0,1] */
   float Priority;          /* [0,1] */
   float MinLod, MaxLod, LodBias;
   GLint BaseLevel, MaxLevel;
   bool GenerateMipmap;
   /* ARB_depth_texture / ARB_shadow (main/texdepth.c): GL_DEPTH_TEXTURE_MODE,
    * GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC */
   GLenum DepthMode, CompareMode, CompareFunc;
   /* the images, by level (NULL: none); glPopAttrib restores the
    * parameters above and keeps these */
   struct fgl_texture_image *Image[FGL_MAX_TEXTURE_LEVELS];
   /* a cube map's faces -X, +Y, -Y, +Z, -Z by level (face +X, the first,
    * is Image; fgl_tex_face_image) [S: mtypes.h, gl_texture_object
    * Image[MAX_FACES][MAX_TEXTURE_LEVELS]] */
   struct fgl_texture_image *FaceImage[5][FGL_MAX_TEXTURE_LEVELS];
   /* the oracle's storage of the object (stObj->pt; Id 0: none) and the
    * last storage id given out (main/teximage.c "Storage") */
   struct fgl_tex_storage Storage;
   unsigned StorageIds;
};

/* The image slot of face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z; 0 for the
 * targets without faces) at `level` of t. */
static inline struct fgl_texture_image **fgl_tex_face_slot(struct fgl_texture_object *t,
                                                           unsigned face, int level)
{
   return face ? &t->FaceImage[face - 1][level] : &t->Image[level];
}

static inline const struct fgl_texture_image *
fgl_tex_face_image(const struct fgl_texture_object *t, unsigned face, int level)
{
   return face ? t->FaceImage[face - 1][level] : t->Image[level];
}

/* The named objects and the default ones (Mesa's Shared->TexObjects and
 * Shared->DefaultTex): shared by the contexts of an OSMesaCreateContext
 * sharelist, freed with the last of them; the table is changed under
 * Lock. */
struct fgl_texture_objects {
   struct fgl_texture_object **Objs;   /* unordered */
   unsigned Count, Alloc;
   GLuint MaxName;                     /* names are never reused */
   struct fgl_texture_object Default[FGL_TEX_TARGETS];
   unsigned Refs;                      /* contexts sharing it */
   pthread_mutex_t Lock;
   /* [S: main/teximage.h:_mesa_lock_texture] Mesa's
    * Shared->TextureStateStamp: moved by every change of an object or
    * its images, in any context (fgl_tex_object_changed); render_batch
    * compares it (tnl/t_render.c, fgl_texture_local.DerivedStamp) */
   atomic_uint Stamp;
};

/* The per-context texture object state: Mesa's
 * ctx->Texture.NumCurrentTexUsed and ctx->Texture.ProxyTex */
struct fgl_texture_local {
   unsigned NumCurrentTexUsed;         /* units a glBindTexture changed */
   /* the objects bound to each unit, holding a reference (NULL: the
    * default object); ctx->Texture.Unit[u].Bound keeps their names for
    * glGet and GL_TEXTURE_BIT [S: mtypes.h, gl_texture_unit CurrentTex] */
   struct fgl_texture_object *Current[FGL_MAX_COMBINED_TEXTURE_UNITS][FGL_TEX_TARGETS];
   /* the LOD bias of units 8..191: glPopAttrib restores only the
    * fixed-function units' (attrib.c:pop_texture_group) */
   float ImageLodBias[FGL_IMAGE_ONLY_UNITS];
   /* the proxy objects of GL_PROXY_TEXTURE_1D, _2D, _3D and _CUBE_MAP:
    * images without texels */
   struct fgl_texture_object Proxy[4];
   /* [S: st_draw.c:prepare_draw, st_atom_texture.c:update_textures] the
    * oracle builds its sampler views from the objects at the draw that
    * finds its texture state dirty, not at the glBegin before it: the
    * texture-unit state objects state.c derived (DerivedPending, with
    * the shared Stamp of then) and no draw has used yet are derived again
    * by render_batch when another context changed an object since
    * (api/shared_textures step 1; ORACLE-NOTES.md "Another context's
    * change of a shared texture") */
   unsigned DerivedStamp;
   bool DerivedPending;
};

/* GL_MULTISAMPLE_BIT: the oracle's OSMesa buffers have no multisample
 * buffer, so none of it changes rendering [S: main/mtypes.h,
 * gl_multisample_attrib] */
struct fgl_multisample_attrib {
   bool Enabled;            /* GL_MULTISAMPLE: true */
   bool SampleAlphaToCoverage, SampleAlphaToOne, SampleCoverage;
   float SampleCoverageValue;   /* 1 */
   GLboolean SampleCoverageInvert;  /* as glSampleCoverage gave it (a
                                     * capability too: main/enable.c) */
};

/* GL_POINT_BIT (main/points.c) */
struct fgl_point_attrib {
   float Size;              /* as given (> 0); clamped when drawn */
   bool SmoothFlag;         /* GL_POINT_SMOOTH */
   /* glPointParameter (GL 1.4) */
   float MinSize, MaxSize;  /* GL_POINT_SIZE_MIN (0), _MAX (255) */
   float Threshold;         /* GL_POINT_FADE_THRESHOLD_SIZE (1): stored
                             * only, the oracle fades nothing */
   float Params[3];         /* GL_POINT_DISTANCE_ATTENUATION (1, 0, 0) */
   /* GL_POINT_SPRITE, glTexEnv's GL_COORD_REPLACE per unit (bit u);
    * the origin is ARB_point_sprite's upper left (GL 2.0's
    * GL_POINT_SPRITE_COORD_ORIGIN is no GL 1.5 state) */
   bool PointSprite;
   unsigned CoordReplace;
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
   float EyeUserPlane[FGL_MAX_CLIP_PLANES][4];  /* glClipPlane, in eye space */
   unsigned ClipPlanesEnabled;                  /* bit i: GL_CLIP_PLANEi */
   bool Normalize;          /* GL_NORMALIZE */
   bool RescaleNormals;     /* GL_RESCALE_NORMAL */
};

/* GL_LIST_BIT (main/dlist.c) */
struct fgl_list_attrib {
   GLuint ListBase;         /* glListBase */
};

/* The display lists and the list compiler (main/dlist.c) */
struct fgl_dlist_state;
#define FGL_MAX_LIST_NESTING 64   /* MAX_LIST_NESTING [S: main/config.h] */

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
   int DepthBits;             /* 0, 16, 24 or 32 */
   int StencilBits;           /* 0 or 8 */
   int AlphaBits;             /* 8, or 0 for the RGB formats */
   bool DoubleBuffer;         /* a double-buffered GLX drawable (libgl/): GL_DOUBLEBUFFER */
   /* A separate front colour buffer (a double-buffered GLX window,
    * libgl/), else NULL and GL_FRONT and GL_BACK both name Color (OSMesa,
    * single-buffered drawables).  With one, Color is the buffer
    * glDrawBuffer selects and Other the other one, same layout;
    * FrontIsColor tells which is which, OtherDefined is ColorDefined of
    * Other (main/buffers.c:fgl_select_color_buffer swaps them). */
   uint8_t *Other;
   bool FrontIsColor;
   bool OtherDefined;
   /* GL_FRONT_AND_BACK or GL_LEFT with a separate front: every colour
    * write goes to Color and Other (main/buffers.c "Both buffers"; set by
    * fgl_select_color_buffer) */
   bool DrawBoth;
   bool ColorR8G8B8A8;        /* the oracle's colour buffer format is R8G8B8A8_UNORM
                               * (OSMESA_RGBA), which glReadPixels packs from
                               * by other rules than B8G8R8A8 etc. */
   enum r_zs_format ZSFormat;
   uint8_t *Stencil;          /* stencil-only buffer (S8) when no depth */
   /* the accumulation buffer (main/accum.c): RGBA int16 scaled by 32767
    * (the oracle's R16G16B16A16_SNORM), same layout as Color; AccumBits
    * 16, or 0 and Accum NULL without one */
   int16_t *Accum;
   int AccumBits;
   /* the oracle's colour buffer is an sRGB format (GLX drawables:
    * B8G8R8A8_SRGB etc.): set by the framebuffer's owner; drawing and
    * reading are plain (GL_FRAMEBUFFER_SRGB off), glAccum unpacks and
    * packs through sRGB (main/accum.c) */
   bool Srgb;
   /* called by glFlush/glFinish to make the image visible to the owner */
   void (*FlushFront)(struct fgl_framebuffer *fb);
   /* the same in parts, when set: FlushFrontRect for every rectangle of a
    * partition of the buffer (any thread, any order, each rectangle once;
    * the scene's tiles), then FlushFrontEnd; the caller tests and clears
    * ColorDefined */
   void (*FlushFrontRect)(struct fgl_framebuffer *fb, int x0, int y0, int x1, int y1);
   void (*FlushFrontEnd)(struct fgl_framebuffer *fb);
   /* Mesa's rb->defined of the front colour buffer: set when a draw or a
    * clear is validated with the colour buffer bound (not under
    * glDrawBuffer(GL_NONE)) [S: state_tracker/st_atom_framebuffer.c];
    * FlushFront does its work only when set, and clears it
    * [S: state_tracker/st_manager.c:st_manager_flush_frontbuffer] */
   bool ColorDefined;
   /* whole-buffer clears not written yet (scene.c "Lazy clears") */
   struct r_lazy_clear Lazy;
   /* a wide colour buffer (r_fb_state.wide; OSMesa GL_UNSIGNED_SHORT and
    * GL_FLOAT): Width * Height pixels of four uint16_t or floats, RGBA,
    * beside Color (which then holds their RGBA8 conversion); never
    * cleared lazily */
   enum r_wide_format WideFormat;
   void *Wide;
};
#define FGL_LAZY_COLOR R_LAZY_COLOR
#define FGL_LAZY_ZS    R_LAZY_ZS

/* The oracle's draw pipeline (draw_pipe_validate.c:validate_pipeline), as
 * llvmpipe splits the rasterizer state between draw and its own setup
 * (lp_state_rasterizer.c:llvmpipe_create_rasterizer_state): while unfilled
 * polygons, polygon stipple, smooth points or lines, or line stipple are on
 * ("need_pipeline"), draw gets two-sided lighting and polygon offset and
 * llvmpipe's setup does neither.  Triangles take the pipeline
 * (draw_need_pipeline) when `always`, or when some vertex of their vsplit
 * segment needs clipping; points and lines when their own stage (aapoint,
 * aaline, line stipple) is on, or when clipped. */
struct fgl_draw_pipeline {
   bool always;             /* every triangle takes the pipeline (polygon
                             * stipple, unfilled, or an offset enable or
                             * two-sided lighting left to draw) */
   bool cull;               /* cull stage: float determinant, culling */
   bool cull_front, cull_back;
   bool front_ccw;
   bool twoside;            /* twoside stage: back colours by determinant */
   bool offset;             /* offset stage, per vertex (any GL_POLYGON_OFFSET_*
                             * left to draw) */
   bool offset_fill, offset_line, offset_point;  /* which fill modes it offsets */
   float offset_units, offset_scale;
   bool flatshade;          /* flatshade stage (precalc_flat: unfilled, line
                             * stipple, smooth lines) */
   bool unfilled;           /* unfilled stage: a fill mode is not GL_FILL */
   GLenum fill_front, fill_back;  /* after the state tracker's culling
                                   * simplification */
   bool edge_cull_front, edge_cull_back;  /* per batch: st->edgeflag_culls_prims
                                           * (unfilled faces culled when the
                                           * current edge flag is false) */
   bool line_stipple;       /* the line stipple stage (pattern != 0xffff):
                             * triangles and points that reach it restart
                             * the counter */
   unsigned caller_mxcsr;   /* per draw (tnl/t_render.c): the application's
                             * MXCSR at the draw's entry, in which the
                             * pipeline's triangles are set up; 0 outside a
                             * draw (the current state) */
};

/* Selection and feedback (Mesa's gl_selection and gl_feedback,
 * main/feedback.c; the draw stages that fill them, tnl/t_feedback.c). */
#define FGL_MAX_NAME_STACK_DEPTH 64   /* config.h MAX_NAME_STACK_DEPTH */
/* the values of a feedback vertex (feedback.c FB_*) */
#define FGL_FB_3D      0x1u
#define FGL_FB_4D      0x2u
#define FGL_FB_COLOR   0x4u
#define FGL_FB_TEXTURE 0x8u

struct fgl_feedback {
   GLenum Type;             /* GL_2D ... GL_4D_COLOR_TEXTURE */
   unsigned Mask;           /* FGL_FB_* of Type */
   GLfloat *Buffer;
   GLuint BufferSize;
   GLuint Count;            /* values emitted, also past BufferSize */
   /* the state tracker's feedback stage's reset_stipple_counter flag
    * (st_cb_feedback.c): its next line is a GL_LINE_RESET_TOKEN; kept
    * across draws and render modes, as the stage is created once */
   bool ResetStipple;
   /* the colour slots (R_ATTR_COLOR0..BCOLOR1) of that draw context's clip
    * stage's temporary vertices (draw_pipe_clip.c stage.tmp[], malloc'ed
    * once, observed zero): the clipper leaves flat attributes of a new
    * vertex as the slot last held them (t_clip.c) */
   float ClipTmp[32][4][4];
};

struct fgl_selection {
   GLuint *Buffer;
   GLuint BufferSize;
   GLuint BufferCount;      /* values written, also past BufferSize */
   GLuint Hits;
   GLuint NameStackDepth;
   GLuint NameStack[FGL_MAX_NAME_STACK_DEPTH];
   bool HitFlag;
   float HitMinZ, HitMaxZ;
};

/* The offset stage's latch (draw_pipe_offset.c:offset_first_tri): the
 * first triangle after a flush (each llvmpipe draw) picks the enable of its
 * face's fill mode, and every later triangle of the draw gets that units and
 * factor (or zeros). */
/* Draw's vbuf stage as far as the polygon stipple sees it
 * (draw_pipe_vbuf.c, draw_pipe_pstipple.c): points and lines are queued
 * into a batch that llvmpipe rasterizes when the vbuf flushes (another
 * primitive type, the end of the draw), with the fragment shader bound at
 * that time; the pstipple stage binds its stipple shader at the first
 * filled triangle of a draw and unbinds it when the draw is flushed.  Only
 * used while the polygon stipple is on (t_linepoint.c). */
enum t_vbuf_prim { T_VBUF_NONE, T_VBUF_POINTS, T_VBUF_LINES };

struct fgl_draw_vbuf {
   bool pstipple_bound;     /* pstip_first_tri ran since the last flush */
   enum t_vbuf_prim prim;   /* the queued batch's primitive type */
   unsigned setup_mxcsr;    /* the r_state.setup_mxcsr of its primitives */
   unsigned count, cap;
   struct r_vertex (*queue)[2];   /* a point uses [0] */
};

/* The triangles draw's pipeline queued in its vbuf, held in a scene that
 * may take llvmpipe's linear path until the vbuf is flushed, when they
 * are paired into rectangles (tnl/t_render.c t_lin_queue_tri) */
struct fgl_lin_queue {
   unsigned count, cap;
   unsigned setup_mxcsr;
   struct r_vertex (*tri)[3];
};

struct fgl_draw_offset_latch {
   bool latched;
   float units, scale;
};

/* A buffer object (GL 1.5, main/bufferobj.c) [S: mtypes.h
 * gl_buffer_object]: its data store, the user's mapping of it, and the
 * references that keep it alive: its name in the shared table, each
 * binding point and vertex array of every context, each glPushClientAttrib
 * copy.  A glDeleteBuffers frees the name at once; the object lives on
 * (DeletePending) while another context still has it bound. */
struct fgl_buffer_object {
   GLuint Name;
   unsigned RefCount;      /* changed under the table's Lock */
   bool DeletePending;
   GLsizeiptr Size;
   GLenum Usage;
   GLbitfield StorageFlags;   /* GL_MAP_READ_BIT | GL_MAP_WRITE_BIT after glBufferData */
   uint8_t *Data;             /* Size bytes (NULL for 0) */
   void *MapPointer;          /* the user's mapping (the whole store), or NULL */
   GLbitfield MapAccess;      /* its GL_MAP_READ_BIT / GL_MAP_WRITE_BIT */
};

/* The names of buffer objects, shared by the contexts of an
 * OSMesaCreateContext sharelist (Mesa's ctx->Shared->BufferObjects): a
 * name from glGenBuffers has no object until it is first bound
 * (DummyBufferObject), Obj NULL.  Sorted by name. */
struct fgl_buffer_objects {
   struct fgl_buffer_entry {
      GLuint Name;
      struct fgl_buffer_object *Obj;
   } *Entries;
   unsigned Count, Alloc;
   GLuint MaxName;            /* names are handed out above it */
   unsigned Refs;             /* contexts sharing it */
   pthread_mutex_t Lock;
};

/* An occlusion query (GL 1.5, main/queryobj.c) [S: mtypes.h
 * gl_query_object]: the raster core counts the samples that pass into
 * Counters (one per rasterizing thread, raster/r_state.h) while it is
 * active; the result is their sum. */
struct fgl_query_object {
   GLuint Id;
   bool Active;
   bool EverBound;            /* glBeginQuery ran on it once */
   bool Ready;                /* the result is known to be available */
   unsigned EndEpoch;         /* ctx->Query.FlushEpoch at its glEndQuery */
   uint64_t Result;
   struct r_sample_counter *Counters;   /* R_SAMPLE_SLOTS of them */
};

/* The context's queries (Mesa's ctx->Query: per context, not shared) */
struct fgl_query_state {
   struct fgl_query_object **Objs;   /* unordered */
   unsigned Count, Alloc;
   GLuint MaxName;
   struct fgl_query_object *CurrentOcclusion;   /* the active one, or NULL */
   /* the oracle's flushes of its scene (llvmpipe_flush: glFlush, glFinish,
    * read-backs, a result waited for, an availability asked for in vain),
    * counted: a query is available once one came after its glEndQuery */
   unsigned FlushEpoch;
};

/* One client-side vertex array (GL_CLIENT_VERTEX_ARRAY_BIT, main/varray.c):
 * Mesa's gl_array_attributes with its buffer binding. */
struct fgl_client_array {
   bool Enabled;
   GLint Size;             /* components (4 for GL_BGRA) */
   GLenum Type;
   GLsizei Stride;         /* as given: the GL_*_ARRAY_STRIDE query */
   GLsizei EffStride;      /* stride, or the element size for 0 */
   const GLvoid *Ptr;      /* with BufferObj: the offset into its store */
   struct fgl_buffer_object *BufferObj;   /* GL_ARRAY_BUFFER when the pointer
                                           * was set (a reference), or NULL */
};

enum fgl_array_index {
   FGL_ARRAY_VERTEX,
   FGL_ARRAY_NORMAL,
   FGL_ARRAY_COLOR,
   FGL_ARRAY_INDEX,        /* state only: colour index mode does not draw */
   FGL_ARRAY_TEXCOORD,     /* unit 0's coordinate array */
   FGL_ARRAY_EDGEFLAG,
   FGL_ARRAY_FOGCOORD,     /* GL 1.4 arrays: glFogCoordPointer and */
   FGL_ARRAY_COLOR1,       /* glSecondaryColorPointer */
   FGL_ARRAY_TEXCOORD1,    /* units 1..7's coordinate arrays: */
   FGL_ARRAY_COUNT = FGL_ARRAY_TEXCOORD1 + FGL_MAX_TEXTURE_UNITS - 1,
};
/* texture unit u's coordinate array */
#define FGL_ARRAY_TEX(u) ((u) ? FGL_ARRAY_TEXCOORD1 + (u) - 1 : FGL_ARRAY_TEXCOORD)

struct fgl_array_attrib {
   struct fgl_client_array Array[FGL_ARRAY_COUNT];
   GLuint ActiveTexture;    /* glClientActiveTexture - GL_TEXTURE0 */
   /* GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER (references, or NULL) */
   struct fgl_buffer_object *ArrayBufferObj, *ElementBufferObj;
};

/* glPushClientAttrib (main/attrib.c) [S: main/attrib.c, gl_client_attrib_node] */
#define FGL_MAX_CLIENT_ATTRIB_STACK_DEPTH 16
struct fgl_client_attrib_node {
   GLbitfield Mask;
   struct fgl_pixelstore Pack, Unpack;
   struct fgl_array_attrib Array;
};

/* glPushAttrib (main/attrib.c) [S: main/attrib.c, gl_attrib_node]: one
 * copy of each server group; the table in attrib.c says which mask bit
 * saves which member, GL_TEXTURE_BIT, GL_EVAL_BIT, GL_PIXEL_MODE_BIT,
 * GL_ACCUM_BUFFER_BIT, GL_LIST_BIT and GL_MULTISAMPLE_BIT included. */
#define FGL_MAX_ATTRIB_STACK_DEPTH 16      /* MAX_ATTRIB_STACK_DEPTH */
#define FGL_ENABLE_ATTRIB_CAPS 54          /* caps restored by GL_ENABLE_BIT */
#define FGL_EVAL_ATTRIB_CAPS 19            /* ... by GL_EVAL_BIT */
struct fgl_attrib_node {
   GLbitfield Mask;
   GLbitfield OldPopAttribState;           /* ctx->PopAttribState at the push */
   struct fgl_colorbuffer_attrib Color;
   float Current[FGL_ATTR_MAT_FIRST][4];   /* ctx->Current, materials excluded */
   /* the rest of ctx->Current: RasterPos .. RasterPosValid */
   unsigned char CurrentExtra[sizeof(struct fgl_current_attrib) -
                              offsetof(struct fgl_current_attrib, RasterPos)];
   struct fgl_multisample_attrib Multisample;
   struct fgl_accum_attrib Accum;
   struct fgl_pixel_attrib Pixel;
   struct fgl_eval_attrib Eval;
   struct fgl_texture_attrib Texture;
   struct fgl_depth_attrib Depth;
   bool Enable[FGL_ENABLE_ATTRIB_CAPS];    /* GL_ENABLE_BIT, attrib.c's cap list */
   bool EvalEnable[FGL_EVAL_ATTRIB_CAPS];  /* GL_EVAL_BIT: map enables, auto normal */
   /* GL_ENABLE_BIT: every unit's target and coordinate generation
    * enables (attrib.c: attr->Texture[u], attr->TexGen[u]); GL_TEXTURE_BIT
    * keeps them with the units in Texture */
   unsigned TexEnabled[FGL_MAX_TEXTURE_UNITS];
   unsigned TexGenEnabled[FGL_MAX_TEXTURE_UNITS];
   /* GL_TEXTURE_BIT: the default objects, always; unit 0's bound objects
    * and LOD bias, saved only when the unit has had a texture bound
    * (Mesa's NumCurrentTexUsed), else left from an earlier push at this
    * depth (zero at first) */
   struct fgl_texture_object TexDefault[FGL_TEX_TARGETS];
   struct fgl_texture_object TexObj[FGL_TEX_TARGETS];
   float TexLodBias;
   bool TexSaved;
   struct fgl_fog_attrib Fog;
   struct fgl_hint_attrib Hint;
   struct fgl_light_attrib Light;
   float Material[FGL_ATTR_COUNT - FGL_ATTR_MAT_FIRST][4];  /* GL_LIGHTING_BIT */
   struct fgl_line_attrib Line;
   struct fgl_list_attrib List;
   struct fgl_point_attrib Point;
   struct fgl_polygon_attrib Polygon;
   uint32_t PolygonStipple[32];
   struct fgl_scissor_attrib Scissor;
   struct fgl_stencil_attrib Stencil;
   struct fgl_transform_attrib Transform;
   struct fgl_viewport_attrib Viewport;
};

/* The counters of fixglStats (main/stats.c), per context.  The raster
 * core adds to `raster` (raster/r_state.h struct r_stats) through
 * _Raster.stats; t_render_batch times each vertex batch and counts as the
 * vertex stage whatever of it is not the raster core's setup or raster
 * time (t_render.c, fgl_stats_batch_end). */
struct fgl_stats {
   struct r_stats raster;        /* summed over the threads */
   uint64_t batch_ns;            /* wall time in t_render_batch and in the
                                  * scene's rasterization */
   uint64_t vertex_ns;           /* t_render_batch's time minus the
                                  * rasterization inside it */
   uint64_t flush_ns;            /* wall time of the scene's rasterization */
   uint64_t batches;
   bool in_batch;                /* inside t_render_batch */
};

/* Timestamp of fgl_stats_batch_begin: the clock and the rasterization
 * time at the start of a batch. */
struct fgl_stats_mark {
   uint64_t t0, flush0, raster0;
};

struct fgl_scene_async;

struct fgl_context {
   /* ---- GL state, one struct per attribute group ---- */
   struct fgl_current_attrib Current;
   struct fgl_colorbuffer_attrib Color;
   struct fgl_depth_attrib Depth;
   struct fgl_fog_attrib Fog;
   struct fgl_hint_attrib Hint;
   struct fgl_light_attrib Light;
   struct fgl_polygon_attrib Polygon;
   struct fgl_scissor_attrib Scissor;
   struct fgl_stencil_attrib Stencil;
   struct fgl_point_attrib Point;
   struct fgl_line_attrib Line;
   struct fgl_transform_attrib Transform;
   struct fgl_viewport_attrib Viewport;
   uint32_t PolygonStipple[32];     /* GL_POLYGON_STIPPLE_BIT: row 0 = bottom,
                                     * bit 31 = leftmost column */
   struct fgl_pixelstore Pack, Unpack;  /* GL_CLIENT_PIXEL_STORE_BIT */
   struct fgl_array_attrib Array;       /* GL_CLIENT_VERTEX_ARRAY_BIT */
   /* accumulation buffer, pixel transfer and maps, evaluators, textures,
    * multisample (state only: OSMesa has no multisample buffers) */
   struct fgl_accum_attrib Accum;
   struct fgl_pixel_attrib Pixel;
   struct fgl_pixelmaps PixelMaps;
   struct fgl_eval_attrib Eval;
   struct fgl_eval_maps EvalMap;        /* main/eval.c */
   struct fgl_texture_attrib Texture;
   struct fgl_texture_objects *TexObjects;   /* shared */
   struct fgl_texture_local TexLocal;
   struct fgl_buffer_objects *BufObjects;    /* shared (main/bufferobj.c) */
   struct fgl_query_state Query;             /* main/queryobj.c */
   struct fgl_multisample_attrib Multisample;
   struct fgl_client_attrib_node ClientAttribStack[FGL_MAX_CLIENT_ATTRIB_STACK_DEPTH];
   unsigned ClientAttribStackDepth;
   struct fgl_attrib_node AttribStack[FGL_MAX_ATTRIB_STACK_DEPTH];
   unsigned AttribStackDepth;
   /* Mesa's ctx->PopAttribState: groups changed since the last push.
    * GL_LIGHTING_BIT and GL_CURRENT_BIT are marked by their setters; the
    * other groups are compared with PopAttribBaseline (attrib.c). */
   GLbitfield PopAttribState;
   /* the other groups as they were at the last push or pop, to tell which
    * changed since (main/attrib.c changed_groups) */
   struct fgl_attrib_node PopAttribBaseline;

   struct fgl_matrix_stack ModelviewStack;
   struct fgl_matrix_stack ProjectionStack;
   /* one per unit, and a scratch stack for units 8..191, where the
    * oracle's GL_TEXTURE matrix mode reads past its array (undefined;
    * nothing uses the scratch stack's matrix) */
   struct fgl_matrix_stack TextureStack[FGL_MAX_TEXTURE_UNITS + 1];
   struct fgl_matrix_stack *CurrentStack;

   /* ---- immediate mode ---- */
   GLenum BeginMode;          /* FGL_OUTSIDE_BEGIN_END when not inside */
   /* Mesa's ctx->Exec is the BeginEnd dispatch table: set by a glBegin
    * that executes (vbo_exec_Begin), cleared by glEnd (vbo_exec_End).  A
    * vertex list's playback sets BeginMode alone (CurrentExecPrimitive,
    * playback_copy_to_current), so the two part when a list ends
    * mid-primitive (ORACLE-NOTES.md "Display lists stuck inside
    * Begin/End") */
   bool ExecBeginEnd;
   struct fgl_vbo Vbo;
   /* the draw module's line stipple counter (draw_pipe_stipple.c): reset
    * by the first line of a primitive, kept across draws otherwise */
   unsigned StippleCounter;

   /* ---- display lists (main/dlist.c) ---- */
   struct fgl_list_attrib List;       /* GL_LIST_BIT */
   bool CompileFlag;          /* compiling a list: entry points store calls
                               * (off while a list executes) */
   bool ExecuteFlag;          /* true, except while compiling GL_COMPILE */
   struct fgl_dlist_state *ListState;

   /* ---- selection and feedback (main/feedback.c) ---- */
   GLenum RenderMode;
   struct fgl_feedback Feedback;
   struct fgl_selection Select;

   /* ---- glBitmap's cache (main/drawpix.c) [S: st_cb_bitmap.c] ---- */
   struct fgl_bitmap_cache {
      bool Pending;            /* bitmaps accumulated, not drawn yet */
      int XPos, YPos;          /* GL window position of the 512x32 image */
      float ZPos;
      float Color[4];
      int FbWidth, FbHeight;
      uint8_t Buffer[512 * 32]; /* R8 texels, row 0 at YPos: 0 draws */
      struct r_state Raster;   /* the state last validated (the cso state
                                * the cache is drawn with) */
      unsigned TexVarying;     /* its program's gl_TexCoord[u] inputs */
   } BitmapCache;

   /* ---- glDrawPixels' image cache (main/drawpix.c)
    * [S: st_cb_drawpixels.c:search_drawpixels_cache] ---- */
   struct fgl_drawpix_cache {
      struct fgl_drawpix_cache_entry {
         GLsizei Width, Height;
         GLenum Format, Type;
         const void *UserPointer;
         uint8_t *Image;          /* copy of the client bytes */
         float *Texels;           /* the texture made of them */
         uint8_t *Mask;
         unsigned Age;
      } Entries[4];
      unsigned Age;
   } DrawpixCache;

   /* ---- errors ---- */
   GLenum ErrorValue;

   /* ---- derived state (written by fgl_update_state only) ---- */
   unsigned NewState;
   fgl_matrix _ModelProjectMatrix;
   struct fgl_lighting_derived _Lighting;
   float _ViewportScale[3], _ViewportTranslate[3];
   float _ClipUserPlane[FGL_MAX_CLIP_PLANES][4];  /* clip-space planes */
   struct fgl_draw_pipeline _DrawPipeline;
   struct fgl_draw_offset_latch _DrawOffset;
   struct fgl_draw_vbuf _DrawVbuf;
   struct fgl_lin_queue _LinQueue;
   /* the draws of one glMultiDrawArrays/Elements driver call are one
    * llvmpipe draw (draw_vbo's loop, one draw_flush at its end): a draw
    * after the first continues it (_MultiDrawCont), one before the last
    * leaves it open (_MultiDrawMore: its vbuf and polygon stipple stage,
    * the offset latch) */
   bool _MultiDrawCont, _MultiDrawMore;
   bool _LinPairs;   /* the batch's setup may pair triangles (rect()) */
   uint32_t _StipplePattern[32];   /* the pattern _StippleRows was made
                                    * from (all zero at first, as the
                                    * state tracker's copy) */
   uint32_t _StippleRows[32];      /* its rows for the rasterizer object */
   /* The raster state of the draws (the variant: state objects, draw
    * region, kernels; raster/r_state.h), its objects held, and the cache
    * of state objects they come from (state.c builds them) */
   struct r_state _Raster;
   /* the raster state of the smooth point [0] and line [1] quads (each
    * zero while its smoothing is off), validated with _Raster */
   struct r_state _RasterAA[2];
   /* the draws into both buffers (fb->DrawBoth; main/buffers.c "Both
    * buffers"): the raster state of the other buffer for the primitive
    * being drawn, made from its r_state (same objects, but the colour is
    * fb->Other and depth and stencil are tested, not written); its fb
    * and dsa objects are these copies, not the cache's */
   struct fgl_both_target {
      struct r_state rs;
      struct r_fb_state fb;
      struct r_dsa_state dsa;
   } _Both;
   /* llvmpipe's draw region under point attenuation is state
    * (ORACLE-NOTES.md "Point parameters", "The cut is state"; probe
    * p_vpcut_state): _VpCutDirty is set when a draw validates another
    * viewport, scissor rectangle or scissor enable than _VpCutKey, and
    * when the oracle would flush its scene or draw a pixel rectangle; the
    * next primitive then decides _VpCut (the region cut to the viewport:
    * a size per vertex, and not a smooth point or line, whose draw stage
    * binds a rasterizer without one), kept until the next change
    * (state.c fgl_vpcut_*) */
   bool _VpCutDirty, _VpCut;
   struct fgl_vpcut_key {
      float scale[3], translate[3];
      int x0, y0, x1, y1;
      int scissor;
   } _VpCutKey;
   struct r_cso_cache _StateCache;
   /* the framebuffer object of no framebuffer (held; context.c), which
    * _Raster.fb falls back to when a framebuffer's cannot be made */
   const struct r_fb_state *_NullFb;
   /* GL_PHONG_WIN: the shading environment of the batch being drawn, as
    * built before it becomes _Raster.shade_env (tnl/t_render.c) */
   struct m_shade_env _ShadeEnv;
   /* the primitives and clears binned since the last flush (scene.c),
    * rasterized by _NumThreads threads (FIXGL_NUM_THREADS) */
   struct r_scene _Scene;
   /* the earlier scene the workers rasterize meanwhile (scene.c), or NULL */
   struct fgl_scene_async *_SceneAsync;
   unsigned _NumThreads;
   /* fixglStats (main/stats.c): the benchmark's counters; _Raster.stats
    * points to Stats.raster while they are enabled, else it is NULL */
   struct fgl_stats Stats;
   /* texture units that texture fragments: enabled, with a complete
    * texture (main/texstate.c) [S: texstate.c:update_ff_texture_state] */
   unsigned _EnabledTexUnits;                     /* bit u: unit u */
   /* the texture resources the oracle's pending scene samples: each
    * object drawn with since the flush of Query.FlushEpoch
    * _SceneTexEpoch, with its resource (Storage.Id) then; _SceneTexFull:
    * more than fit, any write counts (main/teximage.c fgl_tex_written) */
   struct {
      const struct fgl_texture_object *Obj;
      unsigned Storage;
   } _SceneTex[32];
   unsigned _SceneTexCount, _SceneTexEpoch;
   bool _SceneTexFull;
   /* llvmpipe's linear path (ORACLE-NOTES.md "GLX linear rectangles",
    * probe glx-linlatch): _LinPermit, what the last draw validated (its
    * framebuffer could take the path: fgl_lin_capable); _LinScene, the
    * oracle's open scene's latch of it, taken by the scene's first
    * command (FGL_LIN_NONE: no command since the oracle's last flush) */
   bool _LinPermit;
   uint8_t _LinScene;
   /* set by the vertex stage around the two triangles of a rectangle of
    * such a scene (tnl/t_render.c): _LinTri, their enum r_lin; _LinColor,
    * their colour on the linear way (R_LIN_COLOR) */
   uint8_t _LinTri;
   uint8_t _LinPoint;   /* the same for a legacy point */
   float _LinColor[4];
   /* R_LIN_INTERP: the rectangle's colour planes and box (_LinInterpId
    * numbers the rectangles) */
   struct r_lin_interp _LinInterp;
   uint32_t _LinInterpId;
   /* the pair being drawn is a rectangle of llvmpipe's rect(), set up from
    * its corners (rv0, rv2, rv1): _LinRectSetup, which its triangles take
    * instead of their own */
   bool _LinRect;
   struct r_tri_setup *_LinRectSetup;
   /* the batch's colour is the current colour, a constant of the
    * fragment program (unlit, not in the vertex format) */
   bool _LinColorConst;
   struct fgl_texture_object *_CurrentTex[FGL_MAX_TEXTURE_UNITS];
   GLenum _CurrentTexTarget[FGL_MAX_TEXTURE_UNITS];  /* GL_TEXTURE_1D or 2D */
   int _CurrentTexMaxLevel[FGL_MAX_TEXTURE_UNITS];   /* fgl_texture_complete's */
   /* the vertex side of those units [S: texstate.c:update_texgen,
    * _mesa_update_texture_matrices]: bit u when the unit's texture matrix
    * applies (Mesa's _TexMatEnabled), when it generates coordinates
    * (_TexGenEnabled); the FGL_TEXGEN_* modes in use (_GenFlags) */
   unsigned _TexMatEnabled;
   unsigned _TexGenEnabled;
   unsigned _GenFlags;
   /* bit u: the last draw's vertex format had unit u's coordinate
    * [S: draw.c:_mesa_set_varying_vp_inputs, _VaryingInputs]; with
    * _TexGenEnabled and _TexMatEnabled it decides whether the fixed-function
    * fragment program reads gl_TexCoord[u] or the current coordinate
    * (ff_fragment_shader.cpp:filter_fp_input_mask), which pixel
    * rectangles see (main/drawpix.c) */
   unsigned _VaryingTexUnits;

   /* ---- framebuffer ---- */
   struct fgl_framebuffer *DrawBuffer;
   /* the framebuffer read from (glReadPixels, glCopyPixels,
    * glCopyTexImage, glAccum) when it is another one than DrawBuffer (a
    * separate read drawable: glXMakeContextCurrent), else NULL; see
    * fgl_read_fb */
   struct fgl_framebuffer *ReadFb;
   bool ViewportInitialized;
};

#define FGL_OUTSIDE_BEGIN_END 0xffffu

/* The current context of the calling thread (the only mutable global). */
struct fgl_context *fgl_get_current(void);
void fgl_set_current(struct fgl_context *ctx);
/* The variable behind them (context.c), read inline by the entry points'
 * GET_CURRENT_CONTEXT: with initial-exec TLS one load at a fixed offset
 * from the thread pointer, without a call (whose spills and reloads of
 * the arguments cost the attribute calls of immediate mode more than the
 * load).  Hidden, as every symbol but the API. */
#if defined(__GNUC__) && defined(__ELF__)
#define FGL_TLS_INITIAL_EXEC __attribute__((tls_model("initial-exec")))
#else
#define FGL_TLS_INITIAL_EXEC
#endif
extern _Thread_local struct fgl_context *fgl_current_context FGL_TLS_INITIAL_EXEC;

/* A new context; with share, its display lists, texture objects and
 * buffer objects are share's (OSMesa's sharelist, GLX's shareList). */
struct fgl_context *fgl_context_create(struct fgl_context *share);
void fgl_context_destroy(struct fgl_context *ctx);
void fgl_context_bind_framebuffer(struct fgl_context *ctx, struct fgl_framebuffer *fb);
/* The framebuffer ctx reads from: fb, or the draw framebuffer when fb is
 * NULL or the same (context.c). */
void fgl_context_bind_read_framebuffer(struct fgl_context *ctx, struct fgl_framebuffer *fb);
/* The framebuffer the read operations read (ReadFb or DrawBuffer), its
 * lazy clears written (main/buffers.c). */
struct fgl_framebuffer *fgl_read_fb(const struct fgl_context *ctx);

/* Record a GL error; the first one since the last glGetError wins. */
void fgl_error(struct fgl_context *ctx, GLenum error);
/* fgl_malloc/fgl_calloc that raise GL_OUT_OF_MEMORY when they fail (the
 * first error wins, so a later error of the failing path does not hide
 * it); for the entry points' temporary buffers (fgl_alloc.h). */
void *fgl_malloc_gl(const struct fgl_context *ctx, size_t size);
void *fgl_calloc_gl(const struct fgl_context *ctx, size_t n, size_t size);
void *fgl_realloc_gl(const struct fgl_context *ctx, void *p, size_t size);

/* Mesa's FLUSH_VERTICES: draw whatever the immediate-mode store has
 * batched (if a primitive was stored since the last flush) and reset the
 * vertex format. */
void fgl_flush_vertices(struct fgl_context *ctx);

/* Mesa's FLUSH_CURRENT: copy the values of the vertex format's attributes
 * to ctx->Current (colour material included), keeping the format. */
void fgl_flush_current(struct fgl_context *ctx);

/* Mesa's FLUSH_FOR_DRAW (main/context.h), which an array draw and the
 * replay of a display list's vertex list do first:
 * vbo_exec_FlushVertices(ctx, NeedFlush).  With a primitive stored since
 * the last flush it is FLUSH_VERTICES; with only attributes set (NeedFlush
 * is FLUSH_UPDATE_CURRENT) their values are copied to ctx->Current and
 * *stay in the immediate-mode vertex format* (the format is not reset, so
 * sizes and active sizes carry over to the next attribute calls), and the
 * next FLUSH_VERTICES flushes; inside glBegin/glEnd nothing. */
void fgl_flush_for_draw(struct fgl_context *ctx);

/* Recompute derived state for the dirty groups, in dependency order. */
void fgl_update_state(struct fgl_context *ctx);
/* The shading environment of m_shade_point (math/m_shade.h) from the
 * current lighting state (main/light.c): the enabled lights in eye space,
 * the light model, both faces' current materials and reflectance models,
 * and the colour material bits when GL_COLOR_MATERIAL is on. */
struct m_shade_env;
void fgl_update_shade_env(const struct fgl_context *ctx, struct m_shade_env *env);
/* The fog uniforms of the fragment program (STATE_FOG_PARAMS_OPTIMIZED,
 * STATE_FOG_COLOR) from the current fog state into fs (state.c) */
void fgl_fog_uniforms(const struct fgl_context *ctx, struct r_fs_state *fs);
/* The scene (scene.c): primitives and whole-buffer clears go to the
 * scene of the context; fgl_scene_flush rasterizes them, and must run
 * before anything reads or replaces the framebuffer, or changes a
 * texture image. */
#define FGL_MAX_THREADS 64
_Static_assert(FGL_MAX_THREADS == R_SAMPLE_SLOTS, "a query counter per thread");
unsigned fgl_num_threads(void);
void fgl_scene_flush(struct fgl_context *ctx);
/* Draws into both buffers (fb->DrawBoth, main/buffers.c): what the
 * scene holds drawn and every lazy clear written (the primitive is then
 * drawn directly), fb->Other marked defined, and the raster state of the
 * other buffer for a primitive of the state rs returned. */
const struct r_state *fgl_both_begin(struct fgl_context *ctx, const struct r_state *rs);
/* A draw or clear is validated with the colour buffer bound: Mesa's
 * rb->defined of each buffer drawn (see ColorDefined). */
static inline void fgl_mark_color_defined(struct fgl_framebuffer *fb)
{
   fb->ColorDefined = true;
   if (fb->DrawBoth)
      fb->OtherDefined = true;
}
/* Frees the scenes (after a flush). */
void fgl_scene_fini(struct fgl_context *ctx);
/* fgl_scene_flush, then the framebuffer's FlushFront (glFlush, glFinish):
 * by tiles, each copied by the thread that drew it, when the framebuffer
 * can (FlushFrontRect) */
void fgl_scene_flush_front(struct fgl_context *ctx);
/* The viewport cut of the draw region (state.c; ORACLE-NOTES.md "Point
 * parameters"): fgl_vpcut_validate compares what a draw (draw true) or a
 * clear (false: the scissor rectangle only) validated with what the last
 * one did; fgl_vpcut_invalidate marks the region for recomputation (the
 * oracle flushed its scene, or drew a pixel rectangle or a clear quad with
 * a viewport of its own); fgl_vpcut_decide is called by the first
 * primitive after that (aa: a smooth point's or line's quads). */
void fgl_vpcut_validate(struct fgl_context *ctx, bool draw);
static inline void fgl_vpcut_invalidate(struct fgl_context *ctx)
{
   ctx->_VpCutDirty = true;
}
void fgl_vpcut_decide(struct fgl_context *ctx, bool aa);
/* The latch of llvmpipe's linear path (ORACLE-NOTES.md "GLX linear
 * rectangles"): a scene permits the path when the draw validated last
 * before its first command could take it; a scene begun by a
 * whole-buffer clear before any draw of the context does not.
 * fgl_lin_draw: a draw (primitives, a clear quad, a pixel rectangle)
 * validates the current framebuffer, then is a command of the scene;
 * fgl_lin_command: a whole-buffer clear, a command without validation;
 * fgl_lin_flushed: the oracle flushed its scene (glFlush, glFinish, a
 * swap, a read-back); fgl_lin_permitted: the open scene permits it. */
enum { FGL_LIN_NONE, FGL_LIN_ROUND, FGL_LIN_LINEAR };
/* The colour channels fb stores (bit 0 red .. bit 3 alpha): a colour
 * mask over all of them writes every channel */
static inline unsigned fgl_fb_channel_mask(const struct fgl_framebuffer *fb)
{
   return fb->AlphaBits > 0 ? 0xfu : 0x7u;
}
/* Rule 1 of ORACLE-NOTES.md "GLX linear arithmetic": a constant colour on
 * llvmpipe's linear path, each channel in [0, 1] to the byte
 * trunc(c * 256 - c) in float; out is byte / 255, which the fragment
 * stage takes back to that byte.  False (out unset) when a channel is
 * outside [0, 1]: the path refuses it. */
static inline bool fgl_lin_const_color(const float c[4], float out[4])
{
   for (int i = 0; i < 4; i++)
      if (!(c[i] >= 0.0f && c[i] <= 1.0f))
         return false;
   for (int i = 0; i < 4; i++) {
      const float t = c[i] * 256.0f - c[i];
      out[i] = (float)(unsigned)t / 255.0f;
   }
   return true;
}
static inline bool fgl_lin_capable(const struct fgl_context *ctx)
{
   /* check_linear_rasterizer [S: llvmpipe/lp_state_derived.c]: one
    * B8G8R8A8/X8 colour buffer (fixgl's GLX drawables: Srgb), no depth
    * or stencil buffer */
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   return fb && fb->Srgb && fb->DepthBits == 0 && fb->StencilBits == 0 && !fb->DrawBoth &&
          ctx->Color.DrawBuffer != GL_NONE;
}
static inline void fgl_lin_command(struct fgl_context *ctx)
{
   if (ctx->_LinScene == FGL_LIN_NONE)
      ctx->_LinScene = ctx->_LinPermit ? FGL_LIN_LINEAR : FGL_LIN_ROUND;
}
static inline void fgl_lin_draw(struct fgl_context *ctx)
{
   ctx->_LinPermit = fgl_lin_capable(ctx);
   fgl_lin_command(ctx);
}
static inline void fgl_lin_flushed(struct fgl_context *ctx)
{
   ctx->_LinScene = FGL_LIN_NONE;
}
static inline bool fgl_lin_permitted(const struct fgl_context *ctx)
{
   return ctx->_LinScene == FGL_LIN_LINEAR;
}
/* The framebuffer permits the linear path (fgl_lin_capable): the scene's
 * commands are binned (on any number of threads) and held until the
 * oracle's flush, when each tile decides (raster/r_scene.h enum r_lin)
 * if the scene permits it (fgl_lin_permitted; else every command is
 * R_LIN_NO), and rectangles are set up as llvmpipe's rect() sets them
 * up either way */
static inline bool fgl_lin_binning(const struct fgl_context *ctx)
{
   return fgl_lin_capable(ctx);
}
void fgl_raster_triangle(struct fgl_context *ctx, const struct r_state *rs,
                         const struct r_vertex *v0, const struct r_vertex *v1,
                         const struct r_vertex *v2);
void fgl_raster_line(struct fgl_context *ctx, const struct r_state *rs,
                     const struct r_vertex *v0, const struct r_vertex *v1);
/* What llvmpipe's linear path makes of a rectangle (a point, a tile a
 * triangle covers) with corners v[0..n-1] in the current state: enum
 * r_lin, ctx->_LinColor set for R_LIN_COLOR (scene.c) */
uint8_t fgl_lin_color_kind(struct fgl_context *ctx, const struct r_vertex *const *v, int n);
/* the current state is opaque to llvmpipe's bins (lp_setup_whole_tile
 * then drops what a tile it covers holds) */
bool fgl_lin_opaque(const struct fgl_context *ctx);
/* a clear quad of a scene that may take the linear path (fgl_lin_binning):
 * lin_color its colour on that path, NULL when the path draws it as the
 * ordinary one */
void fgl_raster_quad(struct fgl_context *ctx, const struct r_state *rs, float z,
                     const float color[4], const float *lin_color);
void fgl_raster_point(struct fgl_context *ctx, const struct r_state *rs,
                      const struct r_vertex *v);
void fgl_raster_clear(struct fgl_context *ctx, bool color, const uint8_t rgba[4], bool depth,
                      uint32_t zvalue, bool stencil, uint8_t svalue);
/* Lazy clears (scene.c): writes the pending clears of `what`
 * (FGL_LAZY_*) into fb's memory; frees fb's tiles (its buffers go). */
void fgl_lazy_resolve(struct fgl_framebuffer *fb, unsigned what);
/* The raster core's view of fb's buffers (state.c), as validation builds
 * the r_state's framebuffer object. */
struct r_fb_state fgl_fb_raster_state(const struct fgl_framebuffer *fb);
void fgl_lazy_fini(struct fgl_framebuffer *fb);
/* _Raster.shade_env := the object equal to _ShadeEnv (state.c); false
 * when there is none (out of memory, GL_OUT_OF_MEMORY raised). */
bool fgl_set_shade_env(struct fgl_context *ctx);
/* The state object equal to obj (size bytes) from the context's cache
 * (state.c); old, and *ok set to false, when out of memory. */
const void *fgl_state_object(struct fgl_context *ctx, const void *old, const void *obj,
                             size_t size, bool *ok);
/* The same for an object that holds storage while it is held
 * (r_cso_lookup_held: a texture unit's texels). */
const void *fgl_state_object_held(struct fgl_context *ctx, const void *old, const void *obj,
                                  size_t size, r_cso_hold_fn on_hold, bool *ok);
/* At each draw: the polygon stipple rows, when the pattern changed. */
void fgl_update_stipple(struct fgl_context *ctx);
/* fixglStats (main/stats.c): around a vertex batch while the counters are
 * enabled (ctx->_Raster.stats non-NULL), the batch's time into
 * ctx->Stats. */
void fgl_stats_batch_begin(struct fgl_context *ctx, struct fgl_stats_mark *mark);
void fgl_stats_batch_end(struct fgl_context *ctx, const struct fgl_stats_mark *mark);
/* fgl_scene_flush while counting: a rasterization of ns wall time */
void fgl_stats_flush(struct fgl_context *ctx, uint64_t ns);

/* the active unit's matrix stack (the scratch stack past unit 7) */
static inline struct fgl_matrix_stack *fgl_texture_stack(struct fgl_context *ctx)
{
   const unsigned u = ctx->Texture.CurrentUnit;
   return &ctx->TextureStack[u < FGL_MAX_TEXTURE_UNITS ? u : FGL_MAX_TEXTURE_UNITS];
}

/* The units whose gl_TexCoord[u] the fixed-function fragment program
 * reads as a varying: the last draw's vertex format had the coordinate,
 * or texgen or the texture matrix compute it per vertex; it reads the
 * other units' current coordinates as constants
 * [S: ff_fragment_shader.cpp:filter_fp_input_mask, load_texture] */
static inline unsigned fgl_tex_varying_units(const struct fgl_context *ctx)
{
   /* with GL_POINT_SPRITE on, every unit's (the sprite may replace it) */
   if (ctx->Point.PointSprite)
      return (1u << FGL_MAX_TEXTURE_UNITS) - 1u;
   return ctx->_VaryingTexUnits | ctx->_TexGenEnabled | ctx->_TexMatEnabled;
}

static inline unsigned fgl_tex_constant_units(const struct fgl_context *ctx)
{
   return ~fgl_tex_varying_units(ctx) & ((1u << FGL_MAX_TEXTURE_UNITS) - 1u);
}

static inline bool fgl_inside_begin_end(const struct fgl_context *ctx)
{
   return ctx->BeginMode != FGL_OUTSIDE_BEGIN_END;
}

/* Entry point prologue: fetch the current context; return if there is none. */
#define GET_CURRENT_CONTEXT(C) struct fgl_context *C = fgl_current_context

/* Commands not allowed between glBegin and glEnd raise INVALID_OPERATION.
 * Most of Mesa's have no check of their own: the BeginEnd dispatch table's
 * generic_nop refuses them, and they are reached through ctx->Exec (the
 * current dispatch outside display-list compilation, and the table a
 * compiled command executes through), so they test ExecBeginEnd.  A list
 * left mid-primitive (BeginMode inside, ExecBeginEnd not) lets them run
 * (probe p_dlist_stuck_entry_points). */
#define ASSERT_OUTSIDE_BEGIN_END_RET(ctx, ret)             \
   do {                                                    \
      if ((ctx)->ExecBeginEnd) {                           \
         fgl_error(ctx, GL_INVALID_OPERATION);             \
         return ret;                                       \
      }                                                    \
   } while (0)
#define ASSERT_OUTSIDE_BEGIN_END(ctx) ASSERT_OUTSIDE_BEGIN_END_RET(ctx, )

/* Mesa's own check, ASSERT_OUTSIDE_BEGIN_END(_WITH_RETVAL) in the entry
 * point (_mesa_inside_begin_end: CurrentExecPrimitive), which a list left
 * mid-primitive also trips: glGetError, glGetString, glIsEnabled,
 * glIsList, glGenLists, glDeleteLists, glListBase, glNewList, glRenderMode,
 * glFinish, glFlush, glIsTexture, glAreTexturesResident, glIsBuffer,
 * glMapBuffer, glUnmapBuffer, glIsQuery, glRect, and glBegin/glEnd
 * themselves (probe p_dlist_stuck_entry_points). */
#define ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, ret)         \
   do {                                                    \
      if (fgl_inside_begin_end(ctx)) {                     \
         fgl_error(ctx, GL_INVALID_OPERATION);             \
         return ret;                                       \
      }                                                    \
   } while (0)
#define ASSERT_OUTSIDE_BEGIN_END_OWN(ctx) ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, )

/* The same for the commands executed at once while compiling (not
 * compiled into lists) whose only check is the BeginEnd dispatch table's
 * generic_nop: while a list is compiled the dispatch is the save table,
 * whose entries for them are the plain _mesa_ functions
 * (main/dlist.c:_mesa_init_dispatch_save), so they run even when a
 * GL_COMPILE_AND_EXECUTE list has left a glBegin open.  A compiled command
 * is executed under GL_COMPILE_AND_EXECUTE through ctx->Exec, which is the
 * BeginEnd table while a glBegin is open (vbo_exec_Begin), so it takes
 * ASSERT_OUTSIDE_BEGIN_END after its FGL_SAVE (`robust/compile_execute_inside_begin`). */
#define ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, ret)    \
   do {                                                    \
      if (!(ctx)->CompileFlag)                             \
         ASSERT_OUTSIDE_BEGIN_END_RET(ctx, ret);           \
   } while (0)
#define ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx) ASSERT_OUTSIDE_BEGIN_END_DISPATCH_RET(ctx, )

/* Flush batched vertices before a state change and mark it dirty.  The
 * lighting group's setters also mark it changed for glPopAttrib (Mesa
 * passes GL_LIGHTING_BIT to FLUSH_VERTICES in each of them). */
#define FGL_FLUSH_VERTICES(ctx, newstate)                  \
   do {                                                    \
      fgl_flush_vertices(ctx);                             \
      (ctx)->NewState |= (newstate);                       \
      if ((newstate) & FGL_NEW_LIGHT)                      \
         (ctx)->PopAttribState |= GL_LIGHTING_BIT;         \
   } while (0)

/* A texture object or one of its images changed: this context's texture
 * state is dirty, and the shared objects' Stamp moves (Mesa's
 * _mesa_lock_texture) for a draw of another context whose texture state
 * was derived before (tnl/t_render.c render_batch). */
static inline void fgl_tex_object_changed(struct fgl_context *ctx)
{
   ctx->NewState |= FGL_NEW_TEXTURE;
   atomic_fetch_add_explicit(&ctx->TexObjects->Stamp, 1u, memory_order_release);
}

/* [S: feedback.h:_mesa_feedback_token] one value into the feedback
 * buffer; values past its end are counted only (the overflow glRenderMode
 * reports as -1). */
static inline void fgl_feedback_token(struct fgl_context *ctx, GLfloat token)
{
   if (ctx->Feedback.Count < ctx->Feedback.BufferSize)
      ctx->Feedback.Buffer[ctx->Feedback.Count] = token;
   ctx->Feedback.Count++;
}

/* ctx->Point._Attenuated [S: main/points.c] */
static inline bool fgl_point_attenuated(const struct fgl_context *ctx)
{
   const float *p = ctx->Point.Params;
   return p[0] != 1.0f || p[1] != 0.0f || p[2] != 0.0f;
}

/* The rasterizer's point_smooth [S: st_atom_rasterizer.c]: GL_POINT_SMOOTH
 * is ignored while GL_POINT_SPRITE is on (no aapoint stage) */
static inline bool fgl_point_smooth(const struct fgl_context *ctx)
{
   return ctx->Point.SmoothFlag && !ctx->Point.PointSprite;
}

/* Public API symbols; everything else is hidden by default. */
#define FGLAPI __attribute__((visibility("default")))

#endif
