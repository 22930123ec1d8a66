/*
 * The fragment stage shared by triangles, lines and points: the
 * fixed-function fragment program (r_fragment_shader) and the per-fragment
 * operations in the specification's order (r_fragment_ops), with the
 * oracle's conversions (llvmpipe-facts.md §1, §2, §6).
 *
 * Primitives hand every covered pixel here with its interpolated depth and
 * fragment-shader inputs; nothing in this file knows which primitive a
 * fragment came from.
 */
#include "r_state.h"

#include <math.h>
#include <stddef.h>

#include "tnl/t_gallivm.h"

uint8_t r_float_to_unorm8(float c)
{
   /* RNE(min(c, 1) * 255) with a saturating pack: negative and NaN give 0. */
   if (!(c > 0.0f))
      return 0;
   if (c > 1.0f)
      c = 1.0f;
   return (uint8_t)lrintf(c * 255.0f);
}

/* The fragment shader restricts depth to [0,1] (lp_build_depth_clamp),
 * then converts with RNE (llvmpipe-facts.md §1). */
uint32_t r_depth_to_z24(float z)
{
   return (uint32_t)lrintf(r_clamp01(z) * 16777215.0f);
}

uint16_t r_depth_to_z16(float z)
{
   return (uint16_t)lrintf(r_clamp01(z) * 65535.0f);
}

static bool depth_compare(enum r_func func, uint32_t frag, uint32_t buf)
{
   switch (func) {
   case R_NEVER:    return false;
   case R_LESS:     return frag < buf;
   case R_EQUAL:    return frag == buf;
   case R_LEQUAL:   return frag <= buf;
   case R_GREATER:  return frag > buf;
   case R_NOTEQUAL: return frag != buf;
   case R_GEQUAL:   return frag >= buf;
   case R_ALWAYS:
   default:         return true;
   }
}

/* The fog factor of the fixed-function fragment program from the
 * interpolated fog coordinate fc, with the CPU-precomputed
 * STATE_FOG_PARAMS_OPTIMIZED p (ff_fragment_shader.cpp
 * emit_fog_instructions, as NIR hands it to gallivm: llvmpipe lowers ffma
 * and fsat, so every op is rounded on its own):
 *   LINEAR  fc * p[0] + p[1]             (fmul, fadd)
 *   EXP     exp2(-(fc * p[2]))
 *   EXP2    t = fc * p[3]; exp2(-(t * t))
 * exp2 is gallivm's approximation (lp_build_exp2), then fsat lowered to
 * fmin(fmax(f, 0), 1), where gallivm's fmax returns the other operand for
 * NaN (lp_bld_nir.c: GALLIVM_NAN_RETURN_OTHER): a NaN factor is 0. */
static float fog_factor(const struct r_state *rs, float fc)
{
   const float *p = rs->fog_params;
   float f;
   switch (rs->fog_mode) {
   case R_FOG_LINEAR:
      f = fc * p[0] + p[1];
      break;
   case R_FOG_EXP:
      f = t_gallivm_exp2(-(fc * p[2]));
      break;
   case R_FOG_EXP2:
   default: {
      const float t = fc * p[3];
      f = t_gallivm_exp2(-(t * t));
      break;
   }
   }
   f = f > 0.0f ? f : 0.0f;   /* fmax(f, 0): NaN -> 0 */
   return f < 1.0f ? f : 1.0f;
}

void r_fragment_shader(const struct r_state *rs, const float in[][4], float out[4])
{
   /* the fixed-function fragment program: the colour, plus the secondary
    * colour's rgb with separate specular (ff_fragment_shader.cpp
    * emit_instructions: rgb += spec.rgb) */
   for (int c = 0; c < 4; c++)
      out[c] = in[R_FS_COLOR0][c];
   if (rs->color_sum) {
      for (int c = 0; c < 3; c++)
         out[c] = out[c] + in[R_FS_COLOR1][c];
   }
   /* then fog on rgb (emit_fog_instructions): fogcolor * (1 - f) + rgb * f,
    * two fmuls and an fadd (lower_flrp keeps NIR from forming a lerp);
    * alpha passes */
   if (rs->fog_mode != R_FOG_NONE) {
      const float f = fog_factor(rs, in[R_FS_FOG][0]);
      const float g = 1.0f + -f;
      for (int c = 0; c < 3; c++)
         out[c] = rs->fog_color[c] * g + out[c] * f;
   }
}

void r_fragment_ops(const struct r_state *rs, int px, int py, float z, const float color[4])
{
   const size_t idx = (size_t)py * (size_t)rs->width + (size_t)px;

   if (rs->depth_test) {
      switch (rs->zs_format) {
      case R_ZS_Z16: {
         uint16_t *zb = (uint16_t *)rs->zs + idx;
         const uint16_t zv = r_depth_to_z16(z);
         if (!depth_compare(rs->depth_func, zv, *zb))
            return;
         if (rs->depth_write)
            *zb = zv;
         break;
      }
      case R_ZS_Z24X8:
      case R_ZS_Z24S8: {
         uint32_t *zb = (uint32_t *)rs->zs + idx;
         const uint32_t zv = r_depth_to_z24(z);
         if (!depth_compare(rs->depth_func, zv, *zb & 0xffffffu))
            return;
         if (rs->depth_write)
            *zb = (*zb & 0xff000000u) | zv;
         break;
      }
      default:
         break; /* no depth buffer: the test always passes */
      }
   }

   uint8_t *dst = rs->color + 4 * idx;
   dst[0] = r_float_to_unorm8(color[0]);
   dst[1] = r_float_to_unorm8(color[1]);
   dst[2] = r_float_to_unorm8(color[2]);
   dst[3] = r_float_to_unorm8(color[3]);
}
