/*
 * glEnable, glDisable, glIsEnabled.  Each capability belongs to the group
 * that owns its state; this file only dispatches.
 */
#include <stddef.h>

#include "main/groups.h"
#include "main/dlist.h"

/* The texture unit capabilities: the targets (a bit of the active
 * unit's Enabled, by FGL_TEX_* index) and the coordinate generation
 * enables (a bit of its TexGenEnabled, S = bit 0) [S: main/enable.c:
 * _mesa_set_enable, enable_texture, is_texture_enabled].  Returns the
 * unit's bitfield and the bit, or NULL when cap is neither. */
static unsigned *texture_cap(struct fgl_context *ctx, GLenum cap, unsigned *bit)
{
   static unsigned no_unit;   /* never written: see image_only_unit */
   struct fgl_texture_unit *u = ctx->Texture.CurrentUnit < FGL_MAX_TEXTURE_UNITS
                              ? &ctx->Texture.Unit[ctx->Texture.CurrentUnit] : NULL;
   if (!u) {
      switch (cap) {
      case GL_TEXTURE_1D: case GL_TEXTURE_2D: case GL_TEXTURE_3D:
      case GL_TEXTURE_CUBE_MAP:
      case GL_TEXTURE_GEN_S: case GL_TEXTURE_GEN_T:
      case GL_TEXTURE_GEN_R: case GL_TEXTURE_GEN_Q:
         *bit = 0;
         return &no_unit;
      default:
         return NULL;
      }
   }
   switch (cap) {
   case GL_TEXTURE_1D:       *bit = 1u << FGL_TEX_1D;   return &u->Enabled;
   case GL_TEXTURE_2D:       *bit = 1u << FGL_TEX_2D;   return &u->Enabled;
   case GL_TEXTURE_3D:       *bit = 1u << FGL_TEX_3D;   return &u->Enabled;
   case GL_TEXTURE_CUBE_MAP: *bit = 1u << FGL_TEX_CUBE; return &u->Enabled;
   case GL_TEXTURE_GEN_S:
   case GL_TEXTURE_GEN_T:
   case GL_TEXTURE_GEN_R:
   case GL_TEXTURE_GEN_Q:
      *bit = 1u << (cap - GL_TEXTURE_GEN_S);
      return &u->TexGenEnabled;
   default:
      return NULL;
   }
}

/* Whether unit `unit` has texture target `target` enabled. */
/* Units 8..191 have no fixed-function state: their target enables are
 * ignored and read as false (enable.c:enable_texture, is_texture_enabled
 * return for them), their coordinate generation enables are
 * GL_INVALID_OPERATION (get_texcoord_unit) and GL_INVALID_ENUM as glGet
 * values (get.c finds no value).  True when cap is of those and the
 * active unit is one of them. */
static bool image_only_unit(const struct fgl_context *ctx)
{
   return ctx->Texture.CurrentUnit >= FGL_MAX_TEXTURE_UNITS;
}

static bool is_texgen_cap(GLenum cap)
{
   return cap >= GL_TEXTURE_GEN_S && cap <= GL_TEXTURE_GEN_Q;
}

bool fgl_texture_target_enabled(const struct fgl_context *ctx, unsigned unit, GLenum target)
{
   const unsigned e = ctx->Texture.Unit[unit].Enabled;
   switch (target) {
   case GL_TEXTURE_1D:       return e & (1u << FGL_TEX_1D);
   case GL_TEXTURE_2D:       return e & (1u << FGL_TEX_2D);
   case GL_TEXTURE_3D:       return e & (1u << FGL_TEX_3D);
   case GL_TEXTURE_CUBE_MAP: return e & (1u << FGL_TEX_CUBE);
   default:                  return false;
   }
}

/* Returns a pointer to the flag for cap and its dirty bit, or NULL. */
static bool *cap_flag(struct fgl_context *ctx, GLenum cap, unsigned *dirty)
{
   /* GL_MAPn_* and GL_AUTO_NORMAL (main/eval.c) */
   bool *eval = fgl_eval_cap_flag(ctx, cap);
   if (eval) {
      *dirty = 0;
      return eval;
   }
   if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + FGL_MAX_LIGHTS) {
      *dirty = FGL_NEW_LIGHT;
      return &ctx->Light.Light[cap - GL_LIGHT0].Enabled;
   }
   switch (cap) {
   case GL_LIGHTING:
      *dirty = FGL_NEW_LIGHT;
      return &ctx->Light.Enabled;
   case GL_CULL_FACE:
      *dirty = FGL_NEW_POLYGON;
      return &ctx->Polygon.CullFlag;
   case GL_POLYGON_OFFSET_FILL:
      *dirty = FGL_NEW_POLYGON;
      return &ctx->Polygon.OffsetFill;
   case GL_POLYGON_OFFSET_LINE:
      *dirty = FGL_NEW_POLYGON;
      return &ctx->Polygon.OffsetLine;
   case GL_POLYGON_OFFSET_POINT:
      *dirty = FGL_NEW_POLYGON;
      return &ctx->Polygon.OffsetPoint;
   case GL_POLYGON_STIPPLE:
      *dirty = FGL_NEW_POLYGON;
      return &ctx->Polygon.StippleFlag;
   case GL_POLYGON_SMOOTH:
      /* stored and queried only: llvmpipe and draw never read
       * pipe_rasterizer_state.poly_smooth (polygon/polygon_smooth) */
      *dirty = 0;
      return &ctx->Polygon.SmoothFlag;
   case GL_COLOR_MATERIAL:
      *dirty = FGL_NEW_LIGHT;
      return &ctx->Light.ColorMaterialEnabled;
   case GL_NORMALIZE:
      *dirty = 0;   /* read at draw time (t_light.c) */
      return &ctx->Transform.Normalize;
   case GL_RESCALE_NORMAL:
      *dirty = 0;   /* read at draw time (t_light.c) */
      return &ctx->Transform.RescaleNormals;
   case GL_POINT_SMOOTH:
      *dirty = FGL_NEW_POINT;
      return &ctx->Point.SmoothFlag;
   case GL_POINT_SPRITE:
      *dirty = FGL_NEW_POINT;
      return &ctx->Point.PointSprite;
   case GL_LINE_SMOOTH:
      *dirty = FGL_NEW_LINE;
      return &ctx->Line.SmoothFlag;
   case GL_LINE_STIPPLE:
      *dirty = FGL_NEW_LINE;
      return &ctx->Line.StippleFlag;
   case GL_DEPTH_TEST:
      *dirty = FGL_NEW_DEPTH;
      return &ctx->Depth.Test;
   case GL_FOG:
      *dirty = FGL_NEW_FOG;
      return &ctx->Fog.Enabled;
   case GL_COLOR_SUM:
      *dirty = FGL_NEW_FOG;
      return &ctx->Fog.ColorSumEnabled;
   case GL_DITHER:
      *dirty = 0;
      return &ctx->Color.Dither;
   case GL_ALPHA_TEST:
      *dirty = FGL_NEW_COLOR;
      return &ctx->Color.AlphaEnabled;
   case GL_BLEND:
      *dirty = FGL_NEW_COLOR;
      return &ctx->Color.BlendEnabled;
   case GL_COLOR_LOGIC_OP:
      *dirty = FGL_NEW_COLOR;
      return &ctx->Color.LogicOpEnabled;
   case GL_INDEX_LOGIC_OP:
      /* stored and queried only: no index buffer */
      *dirty = 0;
      return &ctx->Color.IndexLogicOpEnabled;
   case GL_SCISSOR_TEST:
      *dirty = FGL_NEW_SCISSOR;
      return &ctx->Scissor.Enabled;
   case GL_STENCIL_TEST:
      *dirty = FGL_NEW_STENCIL;
      return &ctx->Stencil.Enabled;
   /* GL_MULTISAMPLE_BIT: stored and queried only, the framebuffer has no
    * multisample buffer (nor has the oracle's) */
   case GL_MULTISAMPLE:
      *dirty = 0;
      return &ctx->Multisample.Enabled;
   case GL_SAMPLE_ALPHA_TO_COVERAGE:
      *dirty = 0;
      return &ctx->Multisample.SampleAlphaToCoverage;
   case GL_SAMPLE_ALPHA_TO_ONE:
      *dirty = 0;
      return &ctx->Multisample.SampleAlphaToOne;
   case GL_SAMPLE_COVERAGE:
      *dirty = 0;
      return &ctx->Multisample.SampleCoverage;
   default:
      return NULL;
   }
}

/* GL_CLIP_PLANEi (= GL_CLIP_DISTANCEi), i < Const.MaxClipPlanes: a bit of
 * Transform.ClipPlanesEnabled [S: main/enable.c:_mesa_set_enable].  The
 * clip-space plane Mesa computes at enable time is derived at draw time
 * (state.c), from the same eye plane and projection. */
static bool clip_plane_cap(GLenum cap, unsigned *bit)
{
   if (cap < GL_CLIP_PLANE0 || cap >= GL_CLIP_PLANE0 + FGL_MAX_CLIP_PLANES)
      return false;
   *bit = 1u << (cap - GL_CLIP_PLANE0);
   return true;
}

/* The internal setter (Mesa's _mesa_set_enable): cap is valid or the call
 * returns false with nothing changed.  glPopAttrib restores the enable
 * group through it. */
bool fgl_set_enable(struct fgl_context *ctx, GLenum cap, bool state)
{
   unsigned bit;
   if (clip_plane_cap(cap, &bit)) {
      if (((ctx->Transform.ClipPlanesEnabled & bit) != 0) == state)
         return true;
      FGL_FLUSH_VERTICES(ctx, FGL_NEW_CLIP);
      if (state)
         ctx->Transform.ClipPlanesEnabled |= bit;
      else
         ctx->Transform.ClipPlanesEnabled &= ~bit;
      return true;
   }
   /* client-side arrays [S: main/enable.c:_mesa_set_enable -> client_state]:
    * read at draw time, no flush */
   struct fgl_client_array *arr = fgl_client_array(ctx, cap);
   if (arr) {
      arr->Enabled = state;
      return true;
   }
   /* the active unit's targets and coordinate generation: a flush when
    * the unit's bitfield changes */
   unsigned *tex = texture_cap(ctx, cap, &bit);
   if (tex && image_only_unit(ctx)) {
      if (is_texgen_cap(cap))
         fgl_error(ctx, GL_INVALID_OPERATION);
      return true;
   }
   if (tex) {
      const unsigned now = state ? *tex | bit : *tex & ~bit;
      if (now != *tex) {
         FGL_FLUSH_VERTICES(ctx, FGL_NEW_TEXTURE);
         *tex = now;
      }
      return true;
   }
   /* GL_SAMPLE_COVERAGE_INVERT: a capability too in Mesa's compatibility
    * context (enable.c), over the byte glSampleCoverage stores */
   if (cap == GL_SAMPLE_COVERAGE_INVERT) {
      ctx->Multisample.SampleCoverageInvert = state ? GL_TRUE : GL_FALSE;
      return true;
   }
   unsigned dirty = 0;
   bool *flag = cap_flag(ctx, cap, &dirty);
   if (!flag)
      return false;
   if (*flag == state)
      return true;
   if (cap == GL_COLOR_MATERIAL) {
      /* the current colour becomes the tracked materials */
      fgl_set_color_material_enabled(ctx, state);
      return true;
   }
   /* [S: main/enable.c:_mesa_set_enable GL_SCISSOR_TEST] a change draws
    * glBitmap's cache first */
   if (cap == GL_SCISSOR_TEST)
      fgl_flush_bitmap_cache(ctx);
   FGL_FLUSH_VERTICES(ctx, dirty);
   *flag = state;
   return true;
}

static void set_enable(GLenum cap, bool state)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag &&
       !(state ? fgl_save_Enable(ctx, cap) : fgl_save_Disable(ctx, cap)))
      return;
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (!fgl_set_enable(ctx, cap, state))
      fgl_error(ctx, GL_INVALID_ENUM);
}

void GLAPIENTRY glEnable(GLenum cap)
{
   set_enable(cap, true);
}

void GLAPIENTRY glDisable(GLenum cap)
{
   set_enable(cap, false);
}

GLboolean GLAPIENTRY glIsEnabled(GLenum cap)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return GL_FALSE;
   ASSERT_OUTSIDE_BEGIN_END_OWN_RET(ctx, GL_FALSE);
   unsigned dirty, bit;
   if (clip_plane_cap(cap, &bit))
      return (ctx->Transform.ClipPlanesEnabled & bit) ? GL_TRUE : GL_FALSE;
   const struct fgl_client_array *arr = fgl_client_array(ctx, cap);
   if (arr)
      return arr->Enabled ? GL_TRUE : GL_FALSE;
   const unsigned *tex = texture_cap(ctx, cap, &bit);
   if (tex && image_only_unit(ctx) && is_texgen_cap(cap)) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return GL_FALSE;
   }
   if (tex)
      return (*tex & bit) ? GL_TRUE : GL_FALSE;
   if (cap == GL_SAMPLE_COVERAGE_INVERT)
      return ctx->Multisample.SampleCoverageInvert;   /* the byte stored */
   const bool *flag = cap_flag(ctx, cap, &dirty);
   if (!flag) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return GL_FALSE;
   }
   return *flag ? GL_TRUE : GL_FALSE;
}

bool fgl_is_cap(struct fgl_context *ctx, GLenum pname, double *value)
{
   unsigned dirty, bit;
   if (clip_plane_cap(pname, &bit)) {
      *value = (ctx->Transform.ClipPlanesEnabled & bit) ? 1.0 : 0.0;
      return true;
   }
   const struct fgl_client_array *arr = fgl_client_array(ctx, pname);
   if (arr) {
      *value = arr->Enabled ? 1.0 : 0.0;
      return true;
   }
   const unsigned *tex = texture_cap(ctx, pname, &bit);
   if (tex && image_only_unit(ctx) && is_texgen_cap(pname))
      return false;
   if (tex) {
      *value = (*tex & bit) ? 1.0 : 0.0;
      return true;
   }
   if (pname == GL_SAMPLE_COVERAGE_INVERT) {
      *value = ctx->Multisample.SampleCoverageInvert;
      return true;
   }
   const bool *flag = cap_flag(ctx, pname, &dirty);
   if (!flag)
      return false;
   *value = *flag ? 1.0 : 0.0;
   return true;
}
