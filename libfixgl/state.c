/*
 * Derived state: one ordered validation pass before drawing.
 *
 * Order: matrices (analysis, then the MVP product), the lighting space
 * and light vectors (which need the analysed modelview), viewport
 * transform, then the raster core's state, which reads the framebuffer and
 * the per-fragment state.
 */
#include <math.h>
#include <string.h>

#include <fixgl/fixgl.h>

#include "math/m_gallivm.h"
#include "context.h"
#include "fgl_alloc.h"
#include "main/groups.h"

/* The fog blend's uniforms (prog_statevars.c: STATE_FOG_PARAMS_OPTIMIZED,
 * computed on the CPU in this order; STATE_FOG_COLOR, clamped for a
 * fixed-point colour buffer) and the fog coordinate as an input of the
 * fragment program (ff_fragment_shader.cpp: key->fog_mode from
 * _PackedEnabledMode). */
void fgl_fog_uniforms(const struct fgl_context *ctx, struct r_fs_state *fs)
{
   const struct fgl_fog_attrib *fog = &ctx->Fog;
   /* start == end gives val = 1, so f = c - end */
   const float val = fog->End == fog->Start ? 1.0f : -1.0f / (fog->End - fog->Start);
   fs->fog_params[0] = val;
   fs->fog_params[1] = fog->End * -val;
   /* density times double constants (M_LOG2E, 1/sqrt(ln 2)), then float */
   fs->fog_params[2] = (float)(fog->Density * 1.4426950408889634074);
   fs->fog_params[3] = (float)(fog->Density * 1.201122408786449815);
   for (int c = 0; c < 3; c++)
      fs->fog_color[c] = fog->Color[c];
}

static void update_fog(const struct fgl_context *ctx, struct r_fs_state *fs)
{
   const struct fgl_fog_attrib *fog = &ctx->Fog;
   if (!fog->Enabled) {
      fs->fog_mode = R_FOG_NONE;
      return;
   }
   fs->fog_mode = fog->Mode == GL_LINEAR ? R_FOG_LINEAR
                : fog->Mode == GL_EXP    ? R_FOG_EXP : R_FOG_EXP2;
   fgl_fog_uniforms(ctx, fs);
   fs->fs_inputs |= 1u << R_FS_FOG;
   fs->num_attribs = R_ATTR_FOG + 1;
}

/* ---- texturing ---------------------------------------------------------- */

static enum r_tex_wrap tex_wrap(GLenum w)
{
   switch (w) {
   case GL_CLAMP_TO_EDGE:     return R_WRAP_CLAMP_TO_EDGE;
   case GL_CLAMP:             return R_WRAP_CLAMP;
   case GL_CLAMP_TO_BORDER:   return R_WRAP_CLAMP_TO_BORDER;
   case GL_MIRRORED_REPEAT:   return R_WRAP_MIRRORED_REPEAT;
   case GL_MIRROR_CLAMP_EXT:  return R_WRAP_MIRROR_CLAMP;
   case GL_MIRROR_CLAMP_TO_EDGE: return R_WRAP_MIRROR_CLAMP_TO_EDGE;
   case GL_MIRROR_CLAMP_TO_BORDER_EXT: return R_WRAP_MIRROR_CLAMP_TO_BORDER;
   case GL_REPEAT:
   default:                   return R_WRAP_REPEAT;
   }
}

/* [S: util/u_math.h:util_quantize_lod_bias] */
static float quantize_lod_bias(float lod)
{
   lod = lod > -16.0f ? (lod > 16.0f ? 16.0f : lod) : -16.0f;
   return roundf(lod * 256.0f) / 256.0f;
}

static bool is_pot(int n)
{
   return n > 0 && (n & (n - 1)) == 0;
}

/* The parts of the sampler state r_tex_soa.c uses: which path samples
 * (use_aos [S: gallivm/lp_bld_sample_soa.c:lp_build_sample_soa_code]:
 * REPEAT / CLAMP_TO_EDGE on the used axes, else the float path), the LOD
 * bias and limits and their flags, the border colour. */
static void update_texture_general(const struct fgl_context *ctx, unsigned u,
                                   const struct fgl_texture_object *t, struct r_texture *rt)
{
   /* st_convert_sampler: sampler->lod_bias (the object's, quantized by
    * texparam.c) += the unit's (quantized by texenv.c); min_lod is kept
    * >= 0 (texparam.c) */
   rt->lod_bias = quantize_lod_bias(t->LodBias) + quantize_lod_bias(ctx->Texture.Unit[u].LodBias);
   rt->min_lod = t->MinLod > 0.0f ? t->MinLod : 0.0f;
   rt->max_lod = t->MaxLod;
   /* [S: lp_bld_sample.c:lp_sampler_static_sampler_state]: the LOD
    * flags, only with a mip filter or min != mag; max_lod is compared
    * with PIPE_MAX_TEXTURE_LEVELS - 1 = 15 */
   rt->lod_bias_non_zero = rt->lod_bias != 0.0f;
   rt->min_max_lod_equal = rt->apply_min_lod = rt->apply_max_lod = false;
   if (rt->mip != R_MIP_NONE || rt->min_img != rt->mag_img) {
      if (rt->min_lod == rt->max_lod) {
         rt->min_max_lod_equal = true;
      } else {
         rt->apply_min_lod = rt->min_lod > 0.0f;
         rt->apply_max_lod = rt->max_lod < 15.0f;
      }
   }
   /* lp_build_sample_soa_code: a view of one level (last_level 0) with
    * max_lod > 0 samples without the mip filter */
   if (rt->mip != R_MIP_NONE && rt->last_level == 0 && rt->max_lod > 0.0f)
      rt->mip = R_MIP_NONE;
   /* use_aos needs util_format_fits_8unorm [S: lp_bld_sample_soa.c:
    * lp_build_sample_soa_code] */
   rt->float_path = !(rt->wrap_s <= R_WRAP_CLAMP_TO_EDGE &&
                      (rt->dims == 1 || rt->wrap_t <= R_WRAP_CLAMP_TO_EDGE) &&
                      (rt->dims < 3 || rt->wrap_r <= R_WRAP_CLAMP_TO_EDGE)) ||
                    !fgl_tex_image_fits_unorm8(t->Image[rt->first_level]);
   rt->soa = rt->float_path || rt->lod_bias_non_zero || rt->min_max_lod_equal ||
             rt->apply_min_lod || rt->apply_max_lod;
   /* The border colour (clamped by glTexParameter): st_convert_sampler
    * translates a non-zero one by the base format (st_format.c:
    * st_translate_color); lp_build_sample_texel_soa replaces only the
    * channels the texture's format has (L8: rgb, A8: a, RGBX8: rgb), the
    * others keep the format's constants. */
   const GLenum base = t->Image[rt->first_level]->BaseFormat;
   float b[4];
   for (int c = 0; c < 4; c++)
      b[c] = t->BorderColor[c];
   rt->border_mask = 15;
   const bool nonzero = b[0] != 0.0f || b[1] != 0.0f || b[2] != 0.0f || b[3] != 0.0f;
   switch (base) {
   case GL_ALPHA:
      if (nonzero)
         b[0] = b[1] = b[2] = 0.0f;
      rt->border_mask = 8;
      break;
   case GL_LUMINANCE:
      if (nonzero) {
         b[1] = b[2] = b[0];
         b[3] = 1.0f;
      }
      rt->border_mask = 7;
      break;
   case GL_LUMINANCE_ALPHA:
      if (nonzero)
         b[1] = b[2] = b[0];
      break;
   case GL_INTENSITY:
      if (nonzero)
         b[1] = b[2] = b[3] = b[0];
      break;
   case GL_RGB:
      if (nonzero)
         b[3] = 1.0f;
      rt->border_mask = 7;
      break;
   default:
      break;
   }
   for (int c = 0; c < 4; c++)
      rt->border_color[c] = b[c];
}

/* A cube map (r_tex_cube.c): its faces' levels, and the wraps llvmpipe
 * forces on cube maps, CLAMP_TO_EDGE on s and t whatever the object's
 * [S: lp_bld_sample_soa.c:lp_build_sample_soa_code, derived_sampler_state;
 * seamless filtering is off in the compatibility context]. */
static void update_texture_cube(const struct fgl_texture_object *t, struct r_texture *rt)
{
   rt->cube = R_CUBE_MAP;
   for (unsigned f = 0; f < 6; f++) {
      for (int l = rt->first_level; l <= rt->last_level; l++) {
         const struct fgl_texture_image *img = fgl_tex_face_image(t, f, l);
         rt->cube_data[f][l] = img->Data;
         rt->cube_store[f][l] = rt->level[l].store ? img->Store : NULL;
      }
   }
   rt->wrap_s = rt->wrap_t = R_WRAP_CLAMP_TO_EDGE;
}

/* The sampler view and sampler state the state tracker hands llvmpipe for
 * a complete texture object [S: st_atom_texture.c, st_atom_sampler.c:
 * st_convert_sampler; gallivm/lp_bld_sample.c:
 * lp_sampler_static_sampler_state]. */
static void update_texture(const struct fgl_context *ctx, unsigned u,
                           const struct fgl_texture_object *t, GLenum target,
                           struct r_texture *rt)
{
   int max_level = t->BaseLevel;
   fgl_texture_complete(t, &max_level);
   rt->dims = target == GL_TEXTURE_1D ? 1 : target == GL_TEXTURE_3D ? 3 : 2;
   rt->first_level = t->BaseLevel;
   const bool mipmapped = t->MinFilter != GL_NEAREST && t->MinFilter != GL_LINEAR;
   rt->last_level = mipmapped ? max_level : t->BaseLevel;
   for (int l = rt->first_level; l <= rt->last_level; l++) {
      const struct fgl_texture_image *img = t->Image[l];
      rt->level[l].width = img->Width;
      rt->level[l].height = rt->dims == 1 ? 1 : img->Height;
      rt->level[l].depth = rt->dims == 3 ? img->Depth : 1;
      rt->level[l].data = img->Data;
      /* the stored values of a format that is not 8 bits per channel,
       * for the float path */
      rt->level[l].store = fgl_tex_image_fits_unorm8(img) ? NULL : img->Store;
      rt->level[l].zvalues = img->ZValues;
      for (int c = 0; c < 4; c++) {
         const int bits = img->StoreBits[c];
         rt->level[l].store_bits[c] = (uint8_t)bits;
         rt->level[l].store_scale[c] = bits ? (float)(1.0 / (double)((1u << bits) - 1u)) : 1.0f;
      }
   }
   /* the resource's level-0 size (st_texture_create from the base image,
    * guess_and_alloc_texture: the base size scaled up to level 0) */
   const struct fgl_texture_image *base = t->Image[rt->first_level];
   const int w0 = t->Image[0] ? t->Image[0]->Width : base->Width << rt->first_level;
   const int h0 = t->Image[0] ? t->Image[0]->Height : base->Height << rt->first_level;
   const int d0 = t->Image[0] ? t->Image[0]->Depth : base->Depth << rt->first_level;
   rt->pot_s = is_pot(w0);
   rt->pot_t = rt->dims == 1 || is_pot(h0);
   rt->pot_r = rt->dims < 3 || is_pot(d0);
   switch (t->MinFilter) {
   case GL_NEAREST:                rt->min_img = R_TEX_NEAREST; rt->mip = R_MIP_NONE; break;
   case GL_LINEAR:                 rt->min_img = R_TEX_LINEAR;  rt->mip = R_MIP_NONE; break;
   case GL_NEAREST_MIPMAP_NEAREST: rt->min_img = R_TEX_NEAREST; rt->mip = R_MIP_NEAREST; break;
   case GL_LINEAR_MIPMAP_NEAREST:  rt->min_img = R_TEX_LINEAR;  rt->mip = R_MIP_NEAREST; break;
   case GL_NEAREST_MIPMAP_LINEAR:  rt->min_img = R_TEX_NEAREST; rt->mip = R_MIP_LINEAR; break;
   case GL_LINEAR_MIPMAP_LINEAR:
   default:                        rt->min_img = R_TEX_LINEAR;  rt->mip = R_MIP_LINEAR; break;
   }
   rt->mag_img = t->MagFilter == GL_NEAREST ? R_TEX_NEAREST : R_TEX_LINEAR;
   rt->wrap_s = tex_wrap(t->WrapS);
   rt->wrap_t = tex_wrap(t->WrapT);
   rt->wrap_r = rt->dims == 3 ? tex_wrap(t->WrapR) : R_WRAP_REPEAT;
   if (target == GL_TEXTURE_CUBE_MAP)
      update_texture_cube(t, rt);
   update_texture_general(ctx, u, t, rt);
   if (base->BaseFormat == GL_DEPTH_COMPONENT)
      fgl_update_texture_depth(t, rt);
   if (rt->cube) {
      /* a LOD per pixel (a mipmap filter) with min != mag: the float
       * path [S: lp_bld_sample_soa.c:lp_build_sample_soa_code, use_aos
       * needs num_lods <= num_quads or min == mag] */
      if (rt->mip != R_MIP_NONE && rt->min_img != rt->mag_img)
         rt->float_path = true;
      /* every lookup of a cube map goes to r_tex_cube.c */
      rt->face_soa = rt->soa || rt->float_path;
      rt->soa = true;
   }
}

static uint8_t comb_mode(GLenum env, GLenum mode)
{
   switch (mode) {
   case GL_REPLACE:                  return R_COMB_REPLACE;
   case GL_MODULATE:                 return R_COMB_MODULATE;
   case GL_ADD:        return env == GL_COMBINE4_NV ? R_COMB_ADD_PRODUCTS_NV : R_COMB_ADD;
   case GL_ADD_SIGNED: return env == GL_COMBINE4_NV ? R_COMB_ADD_PRODUCTS_SIGNED_NV
                                                    : R_COMB_ADD_SIGNED;
   case GL_INTERPOLATE:              return R_COMB_INTERPOLATE;
   case GL_SUBTRACT:                 return R_COMB_SUBTRACT;
   case GL_DOT3_RGB:                 return R_COMB_DOT3_RGB;
   case GL_DOT3_RGBA:                return R_COMB_DOT3_RGBA;
   case GL_DOT3_RGB_EXT:             return R_COMB_DOT3_RGB_EXT;
   case GL_DOT3_RGBA_EXT:            return R_COMB_DOT3_RGBA_EXT;
   case GL_MODULATE_ADD_ATI:         return R_COMB_MODULATE_ADD_ATI;
   case GL_MODULATE_SIGNED_ADD_ATI:  return R_COMB_MODULATE_SIGNED_ADD_ATI;
   case GL_MODULATE_SUBTRACT_ATI:
   default:                          return R_COMB_MODULATE_SUBTRACT_ATI;
   }
}

static uint8_t comb_src(GLenum src)
{
   switch (src) {
   case GL_TEXTURE:        return R_SRC_TEXTURE;
   case GL_PREVIOUS:       return R_SRC_PREVIOUS;
   case GL_PRIMARY_COLOR:  return R_SRC_PRIMARY_COLOR;
   case GL_CONSTANT:       return R_SRC_CONSTANT;
   case GL_ZERO:           return R_SRC_ZERO;
   case GL_ONE:            return R_SRC_ONE;
   default:                return (uint8_t)(R_SRC_TEXTURE0 + (src - GL_TEXTURE0));
   }
}

static uint8_t comb_opr(GLenum opr)
{
   switch (opr) {
   case GL_SRC_COLOR:           return R_OPR_COLOR;
   case GL_ONE_MINUS_SRC_COLOR: return R_OPR_ONE_MINUS_COLOR;
   case GL_SRC_ALPHA:           return R_OPR_ALPHA;
   case GL_ONE_MINUS_SRC_ALPHA:
   default:                     return R_OPR_ONE_MINUS_ALPHA;
   }
}

/* The number of arguments of a combiner function
 * [S: texstate.c:update_tex_combine]. */
static uint8_t comb_nargs(GLenum env, GLenum mode)
{
   switch (mode) {
   case GL_REPLACE:
      return 1;
   case GL_ADD:
   case GL_ADD_SIGNED:
      return env == GL_COMBINE4_NV ? 4 : 2;
   case GL_INTERPOLATE:
   case GL_MODULATE_ADD_ATI:
   case GL_MODULATE_SIGNED_ADD_ATI:
   case GL_MODULATE_SUBTRACT_ATI:
      return 3;
   default:
      return 2;
   }
}

/* The combiner state of a unit: the unit's own with GL_COMBINE, else the
 * one Mesa derives from the env mode and the base format
 * [S: texstate.c:calculate_derived_texenv, update_tex_combine,
 * pack_tex_combine]. */
static void update_combine(const struct fgl_texture_unit *tu, GLenum base_format,
                           struct r_tex_combine *k)
{
   GLenum mode_rgb, mode_a;
   GLenum src_rgb[4] = { GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_CONSTANT };
   GLenum src_a[4] = { GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_CONSTANT };
   GLenum opr_rgb[4] = { GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA, GL_SRC_ALPHA };
   GLenum opr_a[4] = { GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA };
   unsigned shift_rgb = 0, shift_a = 0;
   const GLenum env = tu->EnvMode;
   if (env == GL_COMBINE || env == GL_COMBINE4_NV) {
      mode_rgb = tu->CombineModeRGB;
      mode_a = tu->CombineModeA;
      for (int i = 0; i < 4; i++) {
         src_rgb[i] = tu->SourceRGB[i];
         src_a[i] = tu->SourceA[i];
         opr_rgb[i] = tu->OperandRGB[i];
         opr_a[i] = tu->OperandA[i];
      }
      shift_rgb = tu->ScaleShiftRGB;
      shift_a = tu->ScaleShiftA;
   } else {
      const GLenum f = base_format;
      if (f == GL_ALPHA)
         src_rgb[0] = GL_PREVIOUS;
      else if (f == GL_LUMINANCE || f == GL_RGB)
         src_a[0] = GL_PREVIOUS;
      switch (env) {
      case GL_REPLACE:
      case GL_MODULATE:
      default:
         mode_rgb = f == GL_ALPHA ? GL_REPLACE : env;
         mode_a = env;
         break;
      case GL_DECAL:
         mode_rgb = GL_INTERPOLATE;
         mode_a = GL_REPLACE;
         src_a[0] = GL_PREVIOUS;
         if (f == GL_ALPHA || f == GL_LUMINANCE || f == GL_LUMINANCE_ALPHA || f == GL_INTENSITY)
            src_rgb[0] = GL_PREVIOUS;
         else if (f == GL_RGB)
            mode_rgb = GL_REPLACE;
         else
            src_rgb[2] = GL_TEXTURE;
         break;
      case GL_BLEND:
         mode_rgb = GL_INTERPOLATE;
         mode_a = GL_MODULATE;
         if (f == GL_ALPHA) {
            mode_rgb = GL_REPLACE;
         } else {
            if (f == GL_INTENSITY) {
               mode_a = GL_INTERPOLATE;
               src_a[0] = GL_CONSTANT;
               opr_a[2] = GL_SRC_ALPHA;
            }
            src_rgb[2] = GL_TEXTURE;
            src_a[2] = GL_TEXTURE;
            src_rgb[0] = GL_CONSTANT;
            opr_rgb[2] = GL_SRC_COLOR;
         }
         break;
      case GL_ADD:
         mode_rgb = f == GL_ALPHA ? GL_REPLACE : GL_ADD;
         mode_a = f == GL_INTENSITY ? GL_ADD : GL_MODULATE;
         break;
      }
      if (src_rgb[0] == GL_PREVIOUS)
         mode_rgb = GL_REPLACE;
      if (src_a[0] == GL_PREVIOUS)
         mode_a = GL_REPLACE;
   }
   memset(k, 0, sizeof(*k));
   k->mode_rgb = comb_mode(env, mode_rgb);
   k->mode_a = comb_mode(env, mode_a);
   k->shift_rgb = (uint8_t)shift_rgb;
   k->shift_a = (uint8_t)shift_a;
   k->nargs_rgb = comb_nargs(env, mode_rgb);
   k->nargs_a = comb_nargs(env, mode_a);
   for (int i = 0; i < k->nargs_rgb; i++) {
      k->src_rgb[i] = comb_src(src_rgb[i]);
      k->opr_rgb[i] = comb_opr(opr_rgb[i]);
   }
   for (int i = 0; i < k->nargs_a; i++) {
      k->src_a[i] = comb_src(src_a[i]);
      k->opr_a[i] = comb_opr(opr_a[i]);
   }
}

/* A texture unit's state object holds the texel blocks it points at
 * while anybody holds the object (r_cso_lookup_held): the context's own
 * state, or a pending scene, which another context sharing the texture
 * cannot then free under it (main/teximage.c free_image).  Data, Store
 * and ZValues are fgl_rc_alloc blocks; a level or face not used is NULL.
 * (ORACLE-NOTES.md "Another context's change of a shared texture".) */
static void tex_unit_hold(const void *obj, bool hold)
{
   const struct r_texture *rt = &((const struct r_tex_unit *)obj)->tex;
   void (*const f)(const void *) = hold ? fgl_rc_hold : fgl_rc_release;
   for (int l = 0; l < R_MAX_TEX_LEVELS; l++) {
      f(rt->level[l].data);
      f(rt->level[l].store);
      f(rt->level[l].zvalues);
   }
   for (int face = 0; face < 6; face++) {
      for (int l = 0; l < R_MAX_TEX_LEVELS; l++) {
         f(rt->cube_data[face][l]);
         f(rt->cube_store[face][l]);
      }
   }
}

/* The state objects of every enabled texture unit
 * (ff_fragment_shader.cpp make_state_key: every unit with a complete
 * texture, walked up to the last one): the image and sampler, the
 * combiner, the environment colour.  False when out of memory. */
static bool update_tex_units(struct fgl_context *ctx, struct r_state *rs)
{
   bool ok = true;
   for (unsigned u = 0; u < R_MAX_TEX_UNITS; u++) {
      const struct r_tex_unit *obj = NULL;
      if (u < FGL_MAX_TEXTURE_UNITS && (ctx->_EnabledTexUnits & (1u << u))) {
         const struct fgl_texture_object *t = ctx->_CurrentTex[u];
         struct r_tex_unit ru;
         memset(&ru, 0, sizeof(ru));
         update_texture(ctx, u, t, ctx->_CurrentTexTarget[u], &ru.tex);
         const struct fgl_texture_unit *tu = &ctx->Texture.Unit[u];
         /* [S: texstate.c:update_tex_combine] a depth texture combines as
          * its GL_DEPTH_TEXTURE_MODE */
         const GLenum base = t->Image[t->BaseLevel]->BaseFormat;
         update_combine(tu, base == GL_DEPTH_COMPONENT ? t->DepthMode : base, &ru.comb);
         r_tex_combine_simplify(&ru.comb, (int)u);
         for (int c = 0; c < 4; c++)
            ru.env_color[c] = tu->EnvColor[c];
         obj = fgl_state_object_held(ctx, rs->tex[u], &ru, sizeof(ru), tex_unit_hold, &ok);
      }
      if (obj != rs->tex[u]) {
         r_cso_hold(obj);
         r_cso_release(rs->tex[u]);
         rs->tex[u] = obj;
      }
   }
   return ok;
}

/* GL comparison, stencil op, blend factor and equation enums to the raster
 * core's (st_atom_depth.c, st_atom_blend.c translate them the same way). */
static enum r_stencil_op stencil_op(GLenum op)
{
   switch (op) {
   case GL_ZERO:      return R_STENCIL_ZERO;
   case GL_REPLACE:   return R_STENCIL_REPLACE;
   case GL_INCR:      return R_STENCIL_INCR;
   case GL_DECR:      return R_STENCIL_DECR;
   case GL_INCR_WRAP: return R_STENCIL_INCR_WRAP;
   case GL_DECR_WRAP: return R_STENCIL_DECR_WRAP;
   case GL_INVERT:    return R_STENCIL_INVERT;
   case GL_KEEP:
   default:           return R_STENCIL_KEEP;
   }
}

static enum r_blend_factor blend_factor(GLenum f)
{
   switch (f) {
   case GL_ZERO:                     return R_BF_ZERO;
   case GL_SRC_COLOR:                return R_BF_SRC_COLOR;
   case GL_ONE_MINUS_SRC_COLOR:      return R_BF_INV_SRC_COLOR;
   case GL_SRC_ALPHA:                return R_BF_SRC_ALPHA;
   case GL_ONE_MINUS_SRC_ALPHA:      return R_BF_INV_SRC_ALPHA;
   case GL_DST_COLOR:                return R_BF_DST_COLOR;
   case GL_ONE_MINUS_DST_COLOR:      return R_BF_INV_DST_COLOR;
   case GL_DST_ALPHA:                return R_BF_DST_ALPHA;
   case GL_ONE_MINUS_DST_ALPHA:      return R_BF_INV_DST_ALPHA;
   case GL_SRC_ALPHA_SATURATE:       return R_BF_SRC_ALPHA_SATURATE;
   case GL_CONSTANT_COLOR:           return R_BF_CONST_COLOR;
   case GL_ONE_MINUS_CONSTANT_COLOR: return R_BF_INV_CONST_COLOR;
   case GL_CONSTANT_ALPHA:           return R_BF_CONST_ALPHA;
   case GL_ONE_MINUS_CONSTANT_ALPHA: return R_BF_INV_CONST_ALPHA;
   /* The fixed-function fragment program writes no second colour: the
    * oracle blends with an unwritten output (different garbage per run and
    * thread count, ORACLE-NOTES.md), fixgl with a second colour of 0. */
   case GL_SRC1_COLOR:
   case GL_SRC1_ALPHA:               return R_BF_ZERO;
   case GL_ONE_MINUS_SRC1_COLOR:
   case GL_ONE_MINUS_SRC1_ALPHA:     return R_BF_ONE;
   case GL_ONE:
   default:                          return R_BF_ONE;
   }
}

static enum r_blend_eq blend_eq(GLenum mode)
{
   switch (mode) {
   case GL_FUNC_SUBTRACT:         return R_BLEND_SUBTRACT;
   case GL_FUNC_REVERSE_SUBTRACT: return R_BLEND_REVERSE_SUBTRACT;
   case GL_MIN:                   return R_BLEND_MIN;
   case GL_MAX:                   return R_BLEND_MAX;
   case GL_FUNC_ADD:
   default:                       return R_BLEND_ADD;
   }
}

/* The depth, stencil and alpha test object. */
static void build_dsa(const struct fgl_context *ctx, struct r_dsa_state *o)
{
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;

   /* depth and stencil only with their buffers [S: st_atom_depth.c] */
   const bool has_depth = fb && fb->DepthBits > 0;
   const bool has_stencil = fb && fb->StencilBits > 0;
   o->depth_test = ctx->Depth.Test && has_depth;
   o->depth_func = (enum r_func)(ctx->Depth.Func - GL_NEVER);
   o->depth_write = ctx->Depth.Mask;

   const struct fgl_stencil_attrib *st = &ctx->Stencil;
   o->stencil_test = st->Enabled && has_stencil;
   o->stencil_func = (enum r_func)(st->Func - GL_NEVER);
   o->stencil_ref = (uint8_t)fgl_stencil_ref(ctx);
   o->stencil_valuemask = (uint8_t)(st->ValueMask & 0xffu);
   o->stencil_writemask = (uint8_t)(st->WriteMask & 0xffu);
   o->stencil_fail = stencil_op(st->FailFunc);
   o->stencil_zfail = stencil_op(st->ZFailFunc);
   o->stencil_zpass = stencil_op(st->ZPassFunc);

   /* alpha test: the reference clamped (lp_build_clamp: NaN -> 1) and
    * converted to unorm8 [S: lp_bld_alpha.c:lp_build_alpha_test] */
   const struct fgl_colorbuffer_attrib *c = &ctx->Color;
   o->alpha_test = c->AlphaEnabled;
   o->alpha_func = (enum r_func)(c->AlphaFunc - GL_NEVER);
   o->alpha_ref = (uint8_t)lrintf(r_clamp01(c->AlphaRef) * 255.0f);
   /* OSMESA_RGB buffers are R8G8B8, not an rgba8 variant: float compare;
    * GLX buffers without alpha are B8G8R8X8, an rgba8 variant: unorm8
    * (glx-linrect; ORACLE-NOTES.md "GLX linear rectangles") */
   o->alpha_test_float = fb && ((fb->AlphaBits == 0 && !fb->Srgb) || fb->Wide);
   o->alpha_ref_float = c->AlphaRef;
}

/* The blend object: blending, logic op, colour mask. */
static void build_blend(const struct fgl_context *ctx, struct r_blend_state *o)
{
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   const struct fgl_colorbuffer_attrib *c = &ctx->Color;
   /* blending [S: st_atom_blend.c:st_update_blend]: the logic op wins;
    * MIN and MAX use factors ONE; blend colour by float_to_ubyte
    * (lp_setup.c:try_update_scene_state) */
   o->logic_op = c->LogicOpEnabled;
   o->logic_op_mode = c->LogicOp - GL_CLEAR;
   /* glDrawBuffer(GL_NONE): no colour buffer is bound (Mesa's
    * _NumColorDrawBuffers 0, [S: main/buffers.c:_mesa_drawbuffers],
    * st_atom_framebuffer.c:st_update_framebuffer_state binds no cbuf), the
    * fragments still reach depth and stencil (ORACLE-NOTES.md "Queries,
    * strings, buffers") */
   o->color_mask = c->DrawBuffer == GL_NONE ? 0u : c->ColorMask & 0xfu;
   o->enable = !c->LogicOpEnabled && c->BlendEnabled && o->color_mask != 0;
   o->blend_eq = blend_eq(c->BlendEquation);
   const bool minmax = o->blend_eq == R_BLEND_MIN || o->blend_eq == R_BLEND_MAX;
   o->blend_src = minmax ? R_BF_ONE : blend_factor(c->BlendSrc);
   o->blend_dst = minmax ? R_BF_ONE : blend_factor(c->BlendDst);
   /* the alpha channel's own equation and factors, kept only when they
    * differ from the rgb ones (equal states stay equal bytes) */
   const enum r_blend_eq eq_a = blend_eq(c->BlendEquationA);
   const bool minmax_a = eq_a == R_BLEND_MIN || eq_a == R_BLEND_MAX;
   const enum r_blend_factor src_a = minmax_a ? R_BF_ONE : blend_factor(c->BlendSrcA);
   const enum r_blend_factor dst_a = minmax_a ? R_BF_ONE : blend_factor(c->BlendDstA);
   if (eq_a != o->blend_eq || src_a != o->blend_src || dst_a != o->blend_dst) {
      o->separate_alpha = true;
      o->blend_eq_a = eq_a;
      o->blend_src_a = src_a;
      o->blend_dst_a = dst_a;
   }
   for (int i = 0; i < 4; i++)
      o->blend_color[i] = r_float_to_unorm8(c->BlendColor[i]);
   if (fb && fb->Wide) {
      memcpy(o->blend_color_f, c->BlendColor, sizeof(o->blend_color_f));
      for (int i = 0; i < 4; i++)
         o->blend_color_u16[i] = (float)m_gallivm_float_to_unorm16(r_clamp01(c->BlendColor[i]));
   }
   o->dst_alpha_one = fb && fb->AlphaBits == 0;
}

/* GL_PHONG_WIN with lighting (include/fixgl/shading.md): the fragments
 * are lit from the interpolated eye-space normal and eye position, two
 * varyings after the texture coordinates (t_phong.c, r_fragment_phong).
 * Not in GL_SELECT / GL_FEEDBACK, whose vertices carry the per-vertex lit
 * colours, as under GL_SMOOTH.  The environment is an object of its own,
 * looked up per batch (t_render.c).  The colour slots then hold the vertex
 * colour for both faces, and the face is the fragment's (gl_FrontFacing's):
 * no two-sided colours, neither llvmpipe's nor draw's, as for a shader on
 * the oracle (the state tracker's light_twoside is
 * GL_VERTEX_PROGRAM_TWO_SIDE's then
 * [S: main/state.h:_mesa_vertex_program_two_side_enabled]) */
static bool phong_on(const struct fgl_context *ctx)
{
   return ctx->Light.Enabled && ctx->Light.ShadeModel == GL_PHONG_WIN &&
          ctx->RenderMode == GL_RENDER;
}

/* two-sided lit colours (by llvmpipe or by draw) */
static bool twoside_on(const struct fgl_context *ctx)
{
   return ctx->Light.Enabled && ctx->Light.Model.TwoSide && !phong_on(ctx);
}

/* The fragment program object: its inputs, colour sum, fog, units. */
static void build_fs(const struct fgl_context *ctx, struct r_fs_state *o)
{
   /* colours: the lit front (and back, and secondary) colours, or the
    * vertex colour */
   const bool lit = ctx->Light.Enabled;
   /* ff_fragment_shader.cpp texenv_doing_secondary_color: separate
    * specular, or GL_COLOR_SUM */
   o->color_sum = (lit && ctx->Light.Model.ColorControl == GL_SEPARATE_SPECULAR_COLOR) ||
                  ctx->Fog.ColorSumEnabled;
   o->num_attribs = twoside_on(ctx) ? 4 : o->color_sum ? 2 : 1;
   o->fs_inputs = 1u << R_FS_COLOR0 | (o->color_sum ? 1u << R_FS_COLOR1 : 0u);
   /* fog: the fragment program reads the fog coordinate, which the
    * vertex stage writes to its own slot after the colours */
   update_fog(ctx, o);
   /* texture coordinates: a slot per unit up to the last enabled one
    * (ffvertex_prog.c writes the coordinate of every enabled unit) */
   for (unsigned u = 0; u < FGL_MAX_TEXTURE_UNITS && u < R_MAX_TEX_UNITS; u++) {
      if (ctx->_EnabledTexUnits & (1u << u)) {
         o->fs_inputs |= 1u << (R_FS_TEX0 + u);
         o->num_attribs = R_ATTR_TEX0 + (int)u + 1;
         o->tex_units |= 1u << u;
         o->tex_nr = (int)u + 1;
      }
   }
   o->phong = phong_on(ctx);
   if (o->phong) {
      /* r_fragment_phong writes the colour inputs: the secondary colour
       * is never interpolated, the vertex colour only when colour
       * material reads it */
      o->fs_inputs &= ~(1u << R_FS_COLOR1);
      if (!ctx->Light.ColorMaterialEnabled)
         o->fs_inputs &= ~(1u << R_FS_COLOR0);
      o->fs_inputs |= 1u << R_FS_NORMAL | 1u << R_FS_EYEPOS;
      o->num_attribs = R_ATTR_EYEPOS + 1;
   }
}

/* The rasterizer object and the draw module's pipeline stages. */
static void build_rast(struct fgl_context *ctx, struct r_rast_state *o)
{
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   const bool twoside = twoside_on(ctx);
   /* GL's counter-clockwise is a positive snapped area in the y-down
    * window buffer (the state tracker's front_ccw for OSMesa) */
   o->ccw_is_front = ctx->Polygon.FrontFace == GL_CCW;
   const GLenum cull = ctx->Polygon.CullFlag ? ctx->Polygon.CullFaceMode : GL_NONE;
   o->cull_front = cull == GL_FRONT || cull == GL_FRONT_AND_BACK;
   o->cull_back = cull == GL_BACK || cull == GL_FRONT_AND_BACK;
   /* flat_mask is set per batch by t_render_batch */

   /* [S: lp_state_rasterizer.c:llvmpipe_create_rasterizer_state] with
    * unfilled polygons, smooth points or lines, line stipple or the
    * polygon stipple (need_pipeline) the draw module does two-sided
    * colours and polygon offset (clear_flags on llvmpipe's copy), else
    * llvmpipe's setup does them; facing and culling are decided by both
    * (draw's cull stage, then the setup's area sign).  The state
    * tracker turns an all-ones line stipple pattern off
    * (st_atom_rasterizer.c). */
   const struct fgl_polygon_attrib *pg = &ctx->Polygon;
   /* [S: st_atom_rasterizer.c] the fill modes, simplified when culling
    * is on: a culled front face takes the back mode and a culled back
    * face the front mode (both the back mode with GL_FRONT_AND_BACK) */
   GLenum fill_front = pg->FrontMode, fill_back = pg->BackMode;
   if (o->cull_front)
      fill_front = fill_back;
   if (o->cull_back)
      fill_back = fill_front;
   const bool unfilled = fill_front != GL_FILL || fill_back != GL_FILL;
   const bool line_stipple = ctx->Line.StippleFlag && ctx->Line.StipplePattern != 0xffff;
   const bool need_pipeline = unfilled || pg->StippleFlag || fgl_point_smooth(ctx) ||
                              ctx->Line.SmoothFlag || line_stipple;
   const bool any_offset = pg->OffsetFill || pg->OffsetLine || pg->OffsetPoint;
   /* util_get_depth_format_mrd: 1/(2^bits - 1), D24 without a unorm
    * depth buffer; units scaled in double, then stored as float */
   const double mrd = fb && fb->DepthBits == 16   ? 1.0 / 65535.0
                      : fb && fb->DepthBits == 32 ? 1.0 / 4294967295.0
                                                  : 1.0 / 16777215.0;
   const float units = (float)((double)pg->OffsetUnits * mrd * 2.0);
   const bool lp_offset = any_offset && !need_pipeline;
   o->offset_units = lp_offset ? units : 0.0f;
   o->offset_scale = lp_offset ? pg->OffsetFactor : 0.0f;
   o->twoside = twoside && !need_pipeline;

   /* the rows: inverted at draw time (fgl_update_stipple) */
   o->stipple = pg->StippleFlag;
   memcpy(o->stipple_rows, ctx->_StippleRows, sizeof(o->stipple_rows));

   /* st_atom_rasterizer.c: the size clamped to [Point.MinSize,
    * Point.MaxSize] = [0, 255], the width to [MinLineWidth(AA),
    * MaxLineWidth(AA)] = [1, 255], with Mesa's CLAMP(X, MIN, MAX) =
    * X > MIN ? (X > MAX ? MAX : X) : MIN, so NaN becomes MIN */
   const float size = ctx->Point.Size, width = ctx->Line.Width;
   const float pmin = ctx->Point.MinSize, pmax = ctx->Point.MaxSize;
   o->point_size = size > pmin ? (size > pmax ? pmax : size) : pmin;
   /* a distance attenuation other than (1, 0, 0): the vertex program
    * writes each point's size (st_atom_rasterizer.c point_size_per_vertex,
    * ffvertex_prog.c build_atten_pointsize) */
   o->point_size_per_vertex = fgl_point_attenuated(ctx);
   /* [S: st_atom_rasterizer.c] GL_POINT_SPRITE: point_quad_rasterization,
    * sprite_coord_enable from the units' GL_COORD_REPLACE, the origin
    * upper left (GL 1.5 has no GL_POINT_SPRITE_COORD_ORIGIN; OSMesa's
    * buffer is Y_0_TOP, so no flip), and point_smooth off
    * (fgl_point_smooth) */
   if (ctx->Point.PointSprite) {
      o->point_sprite = true;
      o->sprite_coord_enable = (uint8_t)(ctx->Point.CoordReplace & ((1u << R_MAX_TEX_UNITS) - 1u));
   }
   o->line_width = width > FGL_MIN_LINE_WIDTH
                 ? (width > FGL_MAX_LINE_WIDTH ? FGL_MAX_LINE_WIDTH : width)
                 : FGL_MIN_LINE_WIDTH;

   struct fgl_draw_pipeline *dp = &ctx->_DrawPipeline;
   /* draw_pipe_validate.c:draw_need_pipeline for triangles: stipple,
    * unfilled, or an offset enable or two-sided lighting left to draw */
   dp->always = unfilled || pg->StippleFlag || (need_pipeline && (any_offset || twoside));
   dp->twoside = twoside && need_pipeline;
   /* draw_pipe_offset.c:offset_first_tri: the enable of the fill mode
    * of the first triangle's face (t_clip.c) */
   dp->offset = need_pipeline && any_offset;
   dp->offset_fill = pg->OffsetFill;
   dp->offset_line = pg->OffsetLine;
   dp->offset_point = pg->OffsetPoint;
   dp->offset_units = units;
   dp->offset_scale = pg->OffsetFactor;
   /* draw_pipe_validate.c: precalc_flat (wide lines never: llvmpipe's
    * threshold is 10000) */
   dp->flatshade = unfilled || line_stipple || ctx->Line.SmoothFlag;
   dp->unfilled = unfilled;
   dp->fill_front = fill_front;
   dp->fill_back = fill_back;
   dp->front_ccw = o->ccw_is_front;
   dp->cull_front = o->cull_front;
   dp->cull_back = o->cull_back;
   /* draw_pipe_validate.c: the cull stage runs when a stage needs the
    * determinant or culling is on */
   dp->cull = dp->cull_front || dp->cull_back || unfilled ||
              (need_pipeline && (any_offset || twoside));
   /* the line stipple stage: triangles and points that reach it restart
    * the counter (draw_pipe_stipple.c) */
   dp->line_stipple = line_stipple;

   if (ctx->RenderMode != GL_RENDER) {
      /* GL_SELECT and GL_FEEDBACK draw with the state tracker's own
       * draw context (st_draw_feedback.c, st_draw.c:st_get_draw_context),
       * given the full rasterizer state: it has no vbuf backend, so
       * every primitive takes the pipeline (draw_pt.c: PT_PIPELINE when
       * !draw->render); draw_pipe_validate.c:validate_pipeline then
       * inserts twoside and offset whenever enabled, flatshade only for
       * unfilled polygons (line stipple, aaline and wide lines are
       * disabled or not installed there), the cull stage for unfilled,
       * offset, two-sided or culling.  Its mrd is never set
       * (draw_set_zs_format is llvmpipe's), so the offset units are 0:
       * units * 0.0 * 2 in double (draw_pipe_offset.c:offset_first_tri) */
      dp->always = true;
      dp->twoside = twoside;
      dp->offset = any_offset;
      dp->offset_units = (float)((double)pg->OffsetUnits * 0.0 * 2.0);
      dp->flatshade = unfilled;
      dp->cull = dp->cull_front || dp->cull_back || unfilled || any_offset || twoside;
      dp->line_stipple = false;
   }
}

/* The raster state of the smooth point and line quads: the draw module
 * binds its rasterizer "no cull" state for them (draw_context.c:
 * draw_get_rasterizer_no_cull: no culling, no two-sided colours, no offset,
 * front_ccw) and a fragment shader that also reads the aa coordinates; the
 * polygon stipple shader is not bound for them (the pstipple stage passes
 * points and lines through). */
static bool update_aa_states(struct fgl_context *ctx)
{
   const struct r_state *rs = &ctx->_Raster;
   bool ok = true;
   for (int m = 0; m < 2; m++) {
      struct r_state *aa = &ctx->_RasterAA[m];
      const bool on = m == 0 ? fgl_point_smooth(ctx) : ctx->Line.SmoothFlag;
      r_state_release(aa);
      memset(aa, 0, sizeof(*aa));
      if (!on)
         continue;
      struct r_rast_state rast = *rs->rast;
      rast.cull_front = false;
      rast.cull_back = false;
      rast.twoside = false;
      rast.offset_units = 0.0f;
      rast.offset_scale = 0.0f;
      rast.stipple = false;
      rast.ccw_is_front = true;
      struct r_fs_state fs = *rs->fs;
      fs.fs_inputs |= 1u << R_FS_AA;
      fs.aa = m == 0 ? R_AA_POINT : R_AA_LINE;
      *aa = *rs;
      aa->rast = NULL;
      aa->fs = NULL;
      r_state_hold(aa);
      aa->rast = fgl_state_object(ctx, NULL, &rast, sizeof(rast), &ok);
      r_cso_hold(aa->rast);
      aa->fs = fgl_state_object(ctx, NULL, &fs, sizeof(fs), &ok);
      r_cso_hold(aa->fs);
      if (!ok) {
         r_state_release(aa);
         memset(aa, 0, sizeof(*aa));
         return false;
      }
      r_choose_kernels(aa);
   }
   return true;
}

const void *fgl_state_object(struct fgl_context *ctx, const void *old, const void *obj,
                             size_t size, bool *ok)
{
   return fgl_state_object_held(ctx, old, obj, size, NULL, ok);
}

const void *fgl_state_object_held(struct fgl_context *ctx, const void *old, const void *obj,
                                  size_t size, r_cso_hold_fn on_hold, bool *ok)
{
   const void *o = r_cso_lookup_held(&ctx->_StateCache, obj, size, on_hold);
   if (!o) {
      *ok = false;
      return old;
   }
   return o;
}

bool fgl_set_shade_env(struct fgl_context *ctx)
{
   struct r_state *rs = &ctx->_Raster;
   bool ok = true;
   const struct m_shade_env *o = fgl_state_object(ctx, rs->shade_env, &ctx->_ShadeEnv,
                                                  sizeof(ctx->_ShadeEnv), &ok);
   if (o != rs->shade_env) {
      r_cso_hold(o);
      r_cso_release(rs->shade_env);
      rs->shade_env = o;
   }
   if (!ok)
      fgl_error(ctx, GL_OUT_OF_MEMORY);
   return rs->shade_env != NULL;
}

/* Points slot (an object of the r_state, held by it) to the object equal
 * to obj: the new one is held, the old one released. */
#define SET_OBJECT(ctx, slot, obj, ok)                                       \
   do {                                                                      \
      const void *o_ = fgl_state_object(ctx, slot, &(obj), sizeof(obj), ok); \
      if (o_ != (const void *)(slot)) {                                      \
         r_cso_hold(o_);                                                     \
         r_cso_release(slot);                                                \
         (slot) = o_;                                                        \
      }                                                                      \
   } while (0)

/* The raster state: each object whose groups are dirty, then the
 * variant's kernels.  Returns the groups not done (out of memory). */
struct r_fb_state fgl_fb_raster_state(const struct fgl_framebuffer *fb)
{
   struct r_fb_state o;
   memset(&o, 0, sizeof(o));
   o.color = fb->Color;
   o.zs = fb->Depth ? fb->Depth : (void *)fb->Stencil;
   o.zs_format = fb->ZSFormat;
   o.width = fb->Width;
   o.height = fb->Height;
   o.wide_format = fb->Wide ? fb->WideFormat : R_WIDE_NONE;
   o.wide = fb->Wide;
   return o;
}

static unsigned update_raster(struct fgl_context *ctx, unsigned dirty)
{
   struct r_state *rs = &ctx->_Raster;
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   unsigned failed = 0;
   bool ok;

   if (dirty & FGL_NEW_BUFFERS) {
      struct r_fb_state o;
      memset(&o, 0, sizeof(o));
      if (fb)
         o = fgl_fb_raster_state(fb);
      ok = true;
      SET_OBJECT(ctx, rs->fb, o, &ok);
      if (!ok) {
         /* out of memory: no buffer at all rather than the last one,
          * which a rebind may have resized or freed (the context's empty
          * framebuffer object; the draw region below is empty too, and
          * the group is validated again by the next call) */
         r_cso_hold(ctx->_NullFb);
         r_cso_release(rs->fb);
         rs->fb = ctx->_NullFb;
      }
      failed |= ok ? 0u : FGL_NEW_BUFFERS;
      /* drawing directly (one thread), a triangle writes the lazy clears
       * of its box (scene.c); the scene's tiles write their own */
      rs->lazy = ok && fb && ctx->_NumThreads == 1 ? &ctx->DrawBuffer->Lazy : NULL;
   }
   if (dirty & (FGL_NEW_BUFFERS | FGL_NEW_SCISSOR)) {
      /* scissor: the draw region [S: st_atom_scissor.c:st_update_scissor;
       * lp_setup.c try_update_scene_state draw_regions] */
      int region[4];
      fgl_scissor_draw_region(ctx, region);
      rs->x0 = region[0];
      rs->y0 = region[1];
      rs->x1 = region[2];
      rs->y1 = region[3];
      if (failed & FGL_NEW_BUFFERS)
         rs->x0 = rs->y0 = rs->x1 = rs->y1 = 0;
   }
   if (dirty & (FGL_NEW_BUFFERS | FGL_NEW_DEPTH | FGL_NEW_STENCIL | FGL_NEW_COLOR)) {
      struct r_dsa_state o;
      memset(&o, 0, sizeof(o));
      build_dsa(ctx, &o);
      ok = true;
      SET_OBJECT(ctx, rs->dsa, o, &ok);
      failed |= ok ? 0u : FGL_NEW_DEPTH;
   }
   if (dirty & (FGL_NEW_BUFFERS | FGL_NEW_COLOR)) {
      struct r_blend_state o;
      memset(&o, 0, sizeof(o));
      build_blend(ctx, &o);
      ok = true;
      SET_OBJECT(ctx, rs->blend, o, &ok);
      failed |= ok ? 0u : FGL_NEW_COLOR;
   }
   if (dirty & FGL_NEW_TEXTURE) {
      ctx->TexLocal.DerivedStamp =
         atomic_load_explicit(&ctx->TexObjects->Stamp, memory_order_acquire);
      ctx->TexLocal.DerivedPending = true;
      if (!update_tex_units(ctx, rs))
         failed |= FGL_NEW_TEXTURE;
   }
   if (dirty & (FGL_NEW_LIGHT | FGL_NEW_FOG | FGL_NEW_TEXTURE | FGL_NEW_RENDERMODE)) {
      struct r_fs_state o;
      memset(&o, 0, sizeof(o));
      build_fs(ctx, &o);
      /* out of memory (update_tex_units): a unit whose first object could
       * not be made does not texture */
      for (int u = 0; u < o.tex_nr; u++)
         if (!rs->tex[u])
            o.tex_units &= ~(1u << u);
      o.tex_nr = o.tex_units ? 32 - __builtin_clz(o.tex_units) : 0;
      for (int u = 0; u < o.tex_nr; u++) {
         if (rs->tex[u]) {
            o.tex_pair |= r_tex_need_pair(&rs->tex[u]->tex);
            o.tex_cube |= rs->tex[u]->tex.cube != R_CUBE_NONE;
         }
      }
      ok = true;
      SET_OBJECT(ctx, rs->fs, o, &ok);
      failed |= ok ? 0u : FGL_NEW_FOG;
      if (rs->fs && !rs->fs->phong && rs->shade_env) {
         r_cso_release(rs->shade_env);
         rs->shade_env = NULL;
      }
   }
   if (dirty & (FGL_NEW_POLYGON | FGL_NEW_LIGHT | FGL_NEW_POINT | FGL_NEW_LINE |
                FGL_NEW_RENDERMODE | FGL_NEW_BUFFERS)) {
      struct r_rast_state o;
      memset(&o, 0, sizeof(o));
      build_rast(ctx, &o);
      ok = true;
      SET_OBJECT(ctx, rs->rast, o, &ok);
      failed |= ok ? 0u : FGL_NEW_POLYGON;
   }
   /* an object that could never be made (the first validation of a
    * context, out of memory): no kernel to choose, the draw stays off */
   if (!rs->fb || !rs->rast || !rs->dsa || !rs->blend || !rs->fs)
      return failed;
   r_choose_kernels(rs);
   if (!update_aa_states(ctx))
      failed |= FGL_NEW_POINT;
   return failed;
}

/* The region of points and non-smooth lines (r_state.px0..py1) and of the
 * smooth point and line quads (_RasterAA[].x0..y1): the draw region, cut
 * to the viewport while ctx->_VpCut (ORACLE-NOTES.md "Point parameters";
 * probes p_point_viewport, p_vpcut_state): vpwh, (int)(x0 + 0.499f) ..
 * (int)(x1 - 0.501f) inclusive, truncated toward zero, in y-down window
 * coordinates.  The smooth quads are cut pixel by pixel too. */
static void update_point_region(struct fgl_context *ctx)
{
   struct r_state *rs = &ctx->_Raster;
   int x0 = rs->x0, y0 = rs->y0, x1 = rs->x1, y1 = rs->y1;
   if (ctx->_VpCut) {
      const float sx = fabsf(ctx->_ViewportScale[0]), sy = fabsf(ctx->_ViewportScale[1]);
      const float tx = ctx->_ViewportTranslate[0], ty = ctx->_ViewportTranslate[1];
      const int vx0 = (int)((tx - sx) + 0.499f), vx1 = (int)((tx + sx) - 0.501f) + 1;
      const int vy0 = (int)((ty - sy) + 0.499f), vy1 = (int)((ty + sy) - 0.501f) + 1;
      if (x0 < vx0) x0 = vx0;
      if (y0 < vy0) y0 = vy0;
      if (x1 > vx1) x1 = vx1;
      if (y1 > vy1) y1 = vy1;
      if (x0 >= x1 || y0 >= y1)
         x0 = y0 = x1 = y1 = 0;
   }
   rs->px0 = x0;
   rs->py0 = y0;
   rs->px1 = x1;
   rs->py1 = y1;
   for (int m = 0; m < 2; m++) {
      struct r_state *aa = &ctx->_RasterAA[m];
      if (!aa->fs)
         continue;
      aa->x0 = aa->px0 = x0;
      aa->y0 = aa->py0 = y0;
      aa->x1 = aa->px1 = x1;
      aa->y1 = aa->py1 = y1;
   }
}

/* [S: llvmpipe/lp_setup.c: lp_setup_set_viewports, lp_setup_set_scissors,
 * lp_setup_bind_rasterizer (the scissor flag), try_update_scene_state]
 * llvmpipe marks its draw regions dirty when the state tracker hands it
 * another viewport or scissor rectangle (cso and st compare with the last
 * ones) or a rasterizer of another scissor flag: at a draw's validation,
 * and for the scissor rectangle at a clear's (ST_PIPELINE_CLEAR).  The
 * viewport here is the pipe's, depth range included. */
void fgl_vpcut_validate(struct fgl_context *ctx, bool draw)
{
   const struct r_state *rs = &ctx->_Raster;
   struct fgl_vpcut_key k = ctx->_VpCutKey;
   k.x0 = rs->x0;
   k.y0 = rs->y0;
   k.x1 = rs->x1;
   k.y1 = rs->y1;
   if (draw) {
      memcpy(k.scale, ctx->_ViewportScale, sizeof(k.scale));
      memcpy(k.translate, ctx->_ViewportTranslate, sizeof(k.translate));
      k.scissor = ctx->Scissor.Enabled;
   }
   if (memcmp(&k, &ctx->_VpCutKey, sizeof(k)) != 0) {
      ctx->_VpCutKey = k;
      ctx->_VpCutDirty = true;
   }
}

/* [S: lp_setup.c:try_update_scene_state; draw_pipe_aaline.c:
 * aaline_first_line, draw_pipe_aapoint.c:aapoint_first_point] the first
 * primitive that reaches llvmpipe's setup after the regions were marked
 * dirty recomputes them with the rasterizer bound then: the draw's, or
 * for smooth points and lines the draw module's "no cull" one, which has
 * no size per vertex (no cut); kept until the next change */
void fgl_vpcut_decide(struct fgl_context *ctx, bool aa)
{
   const struct r_state *rs = &ctx->_Raster;
   ctx->_VpCutDirty = false;
   ctx->_VpCut = !aa && rs->rast && rs->rast->point_size_per_vertex;
   update_point_region(ctx);
}

void fgl_update_state(struct fgl_context *ctx)
{
   const unsigned dirty = ctx->NewState;
   if (!dirty)
      return;

   if (dirty & (FGL_NEW_MODELVIEW | FGL_NEW_PROJECTION)) {
      /* update_modelview_project: analyse both, then P * MV */
      fgl_matrix_analyse(ctx->ModelviewStack.Top);
      fgl_matrix_analyse(ctx->ProjectionStack.Top);
      fgl_matrix_mul_matrix(&ctx->_ModelProjectMatrix, ctx->ProjectionStack.Top,
                            ctx->ModelviewStack.Top);
   }

   /* [S: main/state.c:_mesa_update_state_locked] the texture matrices,
    * the texture state (which units texture, their coordinate generation
    * and matrices), then the lighting space, which eye-space coordinate
    * generation moves to eye coordinates (_mesa_update_tnl_spaces) */
   if (dirty & FGL_NEW_TEXTURE_MATRIX)
      fgl_update_texture_matrices(ctx);
   if (dirty & FGL_NEW_TEXTURE)
      fgl_update_texture_state(ctx);

   if (dirty & (FGL_NEW_MODELVIEW | FGL_NEW_LIGHT | FGL_NEW_TEXTURE))
      fgl_update_lighting(ctx);

   if (dirty & (FGL_NEW_VIEWPORT | FGL_NEW_BUFFERS)) {
      /* _mesa_get_viewport_xform, then the state tracker's flip to the
       * y-down window buffer (ORACLE-NOTES.md "Window coordinates and the
       * y-down buffer") */
      const struct fgl_viewport_attrib *vp = &ctx->Viewport;
      const float half_w = 0.5f * (float)vp->Width;
      const float half_h = 0.5f * (float)vp->Height;
      const float fb_h = ctx->DrawBuffer ? (float)ctx->DrawBuffer->Height : 0.0f;
      ctx->_ViewportScale[0] = half_w;
      ctx->_ViewportTranslate[0] = half_w + (float)vp->X;
      ctx->_ViewportScale[1] = -half_h;
      ctx->_ViewportTranslate[1] = fb_h - (half_h + (float)vp->Y);
      const double n = vp->Near, f = vp->Far;   /* computed in double */
      ctx->_ViewportScale[2] = (float)(0.5 * (f - n));
      ctx->_ViewportTranslate[2] = (float)(0.5 * (n + f));
   }

   if (dirty & (FGL_NEW_CLIP | FGL_NEW_PROJECTION))
      fgl_update_clip_planes(ctx);

   unsigned failed = 0;
   if (dirty & (FGL_NEW_BUFFERS | FGL_NEW_DEPTH | FGL_NEW_LIGHT | FGL_NEW_POLYGON |
                FGL_NEW_FOG | FGL_NEW_SCISSOR | FGL_NEW_STENCIL | FGL_NEW_COLOR |
                FGL_NEW_POINT | FGL_NEW_LINE | FGL_NEW_RENDERMODE | FGL_NEW_TEXTURE)) {
      failed = update_raster(ctx, dirty);
      if (failed)
         fgl_error(ctx, GL_OUT_OF_MEMORY);
   }
   /* (after update_raster: the smooth quads' states copy the draw's) */
   update_point_region(ctx);

   /* a group whose object could not be made is validated again */
   ctx->NewState = failed;
}

/* [S: st_atom_stipple.c:st_update_polygon_stipple] At each draw, when the
 * pattern differs from the one last handed to the driver, it is inverted
 * for the y-down window buffer with the current window height:
 * dest[i] = src[(height - 1 - i) & 31].  A later change of the window
 * height alone (re-binding the context to a buffer of another height)
 * keeps the old inversion, despite the function's comment. */
void fgl_update_stipple(struct fgl_context *ctx)
{
   if (memcmp(ctx->_StipplePattern, ctx->PolygonStipple, sizeof(ctx->_StipplePattern)) == 0)
      return;
   memcpy(ctx->_StipplePattern, ctx->PolygonStipple, sizeof(ctx->_StipplePattern));
   const unsigned h = ctx->DrawBuffer ? (unsigned)ctx->DrawBuffer->Height : 0u;
   for (unsigned i = 0; i < 32; i++)
      ctx->_StippleRows[i] = ctx->PolygonStipple[(h - 1 - i) & 0x1f];
   ctx->NewState |= FGL_NEW_POLYGON;
   fgl_update_state(ctx);
}
