/*
 * Clearing: glClearColor (GL_COLOR_BUFFER_BIT state) and glClear.
 * The clear colour is packed with float_to_ubyte and depth with
 * util_pack_z, as the oracle does (ORACLE-NOTES.md "Clears").
 */
#include <math.h>

#include "main/groups.h"
#include "main/dlist.h"
#include "raster/r_scene.h"

void fgl_init_color(struct fgl_context *ctx)
{
   for (int i = 0; i < 4; i++)
      ctx->Color.ClearColor[i] = 0.0f;
   ctx->Color.Dither = true;
}

void GLAPIENTRY glClearColor(GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ClearColor, red, green, blue, alpha);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   /* marked for glPopAttrib even when unchanged [S: main/clear.c] */
   ctx->PopAttribState |= GL_COLOR_BUFFER_BIT;
   ctx->Color.ClearColor[0] = red;
   ctx->Color.ClearColor[1] = green;
   ctx->Color.ClearColor[2] = blue;
   ctx->Color.ClearColor[3] = alpha;
}

/* util_pack_z for the 16-, 24- and 32-bit unorm formats (llrint for
 * Z32, lrint for the others: the same rounding in double) */
static uint32_t pack_z(double z, int bits)
{
   const double max = bits == 16 ? 65535.0 : bits == 32 ? 4294967295.0 : 16777215.0;
   if (z == 0.0)
      return 0;
   if (z == 1.0)
      return (uint32_t)max;
   return (uint32_t)llrint(z * max);
}

/* Mesa's is_scissor_enabled: a scissor that leaves part of the buffer out */
static bool scissor_cuts(const struct fgl_context *ctx, const struct fgl_framebuffer *fb)
{
   const struct fgl_scissor_attrib *s = &ctx->Scissor;
   return s->Enabled && (s->X > 0 || s->Y > 0 ||
                         (int)((unsigned)s->X + (unsigned)s->Width) < fb->Width ||
                         (int)((unsigned)s->Y + (unsigned)s->Height) < fb->Height);
}

/* clear_with_quad [S: state_tracker/st_cb_clear.c:clear_with_quad]: a quad
 * over the scissored bounds through the fragment stage, with blending,
 * logic op and alpha test off; colour under the colour mask; depth test
 * ALWAYS with writes; stencil test ALWAYS with every op REPLACE by the
 * clear value under the stencil write mask.  The quad's depth is
 * (float)(Clear * 2 - 1) in clip space, through the viewport transform of
 * the whole buffer (scale = translate = 0.5, fused: ORACLE-NOTES.md
 * "Vertex transformation"). */
static void clear_with_quad(struct fgl_context *ctx, bool color, bool depth, bool stencil,
                            const float clear_color[4], const float *lin_color)
{
   /* the clear's own depth-stencil-alpha and blend objects, for this
    * draw only */
   /* the quad's viewport: the draw regions are computed again after it
    * (probe p_vpcut_state) */
   fgl_vpcut_invalidate(ctx);
   struct r_state rs = ctx->_Raster;
   rs.samples = NULL;   /* a clear passes no sample (conformance/probes/p_query.c) */
   struct r_dsa_state dsa = *rs.dsa;
   struct r_blend_state blend = *rs.blend;
   dsa.alpha_test = false;
   blend.enable = false;
   blend.logic_op = false;
   blend.color_mask = color ? ctx->Color.ColorMask & 0xfu : 0u;
   dsa.depth_test = depth;
   dsa.depth_func = R_ALWAYS;
   dsa.depth_write = true;
   dsa.stencil_test = stencil;
   dsa.stencil_func = R_ALWAYS;
   dsa.stencil_ref = (uint8_t)ctx->Stencil.Clear;   /* pipe_stencil_ref is a ubyte */
   dsa.stencil_valuemask = 0xff;
   dsa.stencil_writemask = (uint8_t)(ctx->Stencil.WriteMask & 0xffu);
   dsa.stencil_fail = dsa.stencil_zfail = dsa.stencil_zpass = R_STENCIL_REPLACE;
   rs.dsa = &dsa;
   rs.blend = &blend;
   rs.full_ops = true;
   /* the quad spans Mesa's scissored bounds (_Xmin.._Ymax, int arithmetic);
    * the clear's rasterizer state has no scissor */
   int bbox[4];
   fgl_scissor_bounds(ctx, bbox);
   const int h = ctx->DrawBuffer->Height;
   rs.x0 = bbox[0];
   rs.x1 = bbox[1];
   rs.y0 = h - bbox[3];
   rs.y1 = h - bbox[2];

   const float zclip = (float)(ctx->Depth.Clear * 2.0f - 1.0f);
   const float z = fmaf(zclip, 0.5f, 0.5f);
   if (fgl_lin_binning(ctx)) {
      /* a command of the oracle's scene, which may take the linear path
       * (ORACLE-NOTES.md "GLX linear rectangles"): binned with its
       * colour on both ways, its objects the cache's so that the scene
       * can hold them */
      bool ok = true;
      rs.dsa = fgl_state_object(ctx, NULL, &dsa, sizeof(dsa), &ok);
      rs.blend = fgl_state_object(ctx, NULL, &blend, sizeof(blend), &ok);
      if (ok) {
         /* opaque (lp_setup_whole_tile): a full colour mask over the
          * buffer's channels drops what the tiles it covers hold */
         const unsigned surf = fgl_fb_channel_mask(ctx->DrawBuffer);
         if ((blend.color_mask & surf) == surf) {
            const int box[4] = { rs.x0, rs.y0, rs.x1, rs.y1 };
            r_scene_cover(&ctx->_Scene, &rs, box);
         }
         fgl_raster_quad(ctx, &rs, z, clear_color, lin_color);
         return;
      }
      rs.dsa = &dsa;   /* out of memory: drawn now, after the scene */
      rs.blend = &blend;
      fgl_scene_flush(ctx);
   }
   if (ctx->DrawBuffer->DrawBoth)   /* the other buffer too (main/buffers.c) */
      r_clear_quad(fgl_both_begin(ctx, &rs), z, clear_color);
   r_clear_quad(&rs, z, clear_color);
}

/* The clear quad's colour on llvmpipe's linear path, or NULL where the
 * path draws it as the ordinary one (ORACLE-NOTES.md "GLX partial
 * clears"); the quad is binned with both and the tiles choose ("GLX
 * linear bins").  The path is allowed (fgl_lin_capable) for a
 * B8G8R8A8 / B8G8R8X8 colour buffer (the oracle's GLX drawables, fb->Srgb:
 * their formats' linear views), no depth and no stencil buffer, one
 * colour buffer bound (not both buffers), every channel of the
 * (unclamped) clear colour in [0, 1], and the oracle's scene permits the
 * path (fgl_lin_permitted: not a scene begun by a whole-buffer clear
 * before the context's first draw; ORACLE-NOTES.md "GLX linear
 * rectangles"); the path takes each channel to a byte as
 * trunc(c * 256 - c) in float arithmetic (probed, 21,504 values near
 * every k/255 and 4,084 of a quarter-step ramp: exact), where the
 * fragment stage rounds c * 255.  The linear colour is byte / 255,
 * which the fragment stage takes back to that byte (fgl_lin_const_color).  Chosen once per
 * glClear; OSMesa buffers round (probed). */
static const float *quad_color(const struct fgl_context *ctx, float linear[4])
{
   if (!fgl_lin_capable(ctx) || !fgl_lin_permitted(ctx) ||
       !fgl_lin_const_color(ctx->Color.ClearColor, linear))
      return NULL;
   return linear;
}

void GLAPIENTRY glClear(GLbitfield mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, Clear, mask);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   if (mask & ~(GLbitfield)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT |
                            GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT)) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   const struct fgl_framebuffer *fb = ctx->DrawBuffer;
   if (!fb)
      return;
   /* [S: main/clear.c:clear] buffers are cleared in GL_RENDER mode only:
    * under GL_SELECT and GL_FEEDBACK glClear changes nothing */
   if (ctx->RenderMode != GL_RENDER)
      return;
   /* [S: st_cb_clear.c:st_Clear] glBitmap's cache is drawn first */
   fgl_flush_bitmap_cache(ctx);
   fgl_update_state(ctx);
   fgl_vpcut_validate(ctx, false);   /* ST_PIPELINE_CLEAR: the scissor */
   if (ctx->Color.DrawBuffer != GL_NONE)
      fgl_mark_color_defined(ctx->DrawBuffer);

   /* Which buffers take a plain clear and which a quad
    * [S: main/clear.c:clear; state_tracker/st_cb_clear.c:st_Clear].
    * llvmpipe has no PIPE_CAP_CLEAR_SCISSORED, so a scissor that cuts the
    * buffer makes a quad; so do a partial colour mask (over the buffer's
    * channels) and a partial stencil write mask.  A fully masked buffer and
    * depth with writes off are not cleared. */
   const bool scissor = scissor_cuts(ctx, fb);
   const unsigned surf_mask = fgl_fb_channel_mask(fb);
   /* no colour buffer is cleared under glDrawBuffer(GL_NONE) */
   const unsigned cmask = ctx->Color.DrawBuffer == GL_NONE ? 0u
                                                         : ctx->Color.ColorMask & surf_mask;
   bool color_quad = false, color_clear = false;
   if ((mask & GL_COLOR_BUFFER_BIT) && cmask != 0) {
      if (scissor || cmask != surf_mask)
         color_quad = true;
      else
         color_clear = true;
   }
   bool depth_quad = false, depth_clear = false;
   if ((mask & GL_DEPTH_BUFFER_BIT) && fb->DepthBits > 0 && ctx->Depth.Mask) {
      if (scissor)
         depth_quad = true;
      else
         depth_clear = true;
   }
   bool stencil_quad = false, stencil_clear = false;
   const unsigned swmask = ctx->Stencil.WriteMask & 0xffu;
   if ((mask & GL_STENCIL_BUFFER_BIT) && fb->StencilBits > 0 && swmask != 0) {
      if (scissor || swmask != 0xffu)
         stencil_quad = true;
      else
         stencil_clear = true;
   }
   /* depth and stencil are always cleared together */
   if ((depth_quad || stencil_quad) && (depth_clear || stencil_clear)) {
      depth_quad |= depth_clear;
      stencil_quad |= stencil_clear;
      depth_clear = stencil_clear = false;
   }

   /* a whole-buffer clear is a command of the oracle's scene, without a
    * draw's validation (a scene it begins before any draw does not permit
    * the linear path) */
   if (color_clear || depth_clear || stencil_clear)
      fgl_lin_command(ctx);
   /* a wide colour buffer (OSMesa GL_UNSIGNED_SHORT, GL_FLOAT) is cleared
    * at once, after what the scene holds, with the clear colour packed as
    * st_Clear packs it (r_clear_wide_rect), its RGBA8 image beside it */
   if (color_clear && fb->Wide) {
      fgl_scene_flush(ctx);
      fgl_lazy_resolve(ctx->DrawBuffer, FGL_LAZY_COLOR);
      uint8_t rgba[4];
      for (int i = 0; i < 4; i++)
         rgba[i] = r_float_to_unorm8(ctx->Color.ClearColor[i]);
      r_clear_wide_rect(ctx->_Raster.fb, 0, 0, fb->Width, fb->Height, ctx->Color.ClearColor);
      r_clear_color_rect(ctx->_Raster.fb, 0, 0, fb->Width, fb->Height, rgba);
      color_clear = false;
   }

   /* whole-buffer clears: a command of the scene (each tile cleared by
    * the thread that then draws it) */
   if (color_clear || depth_clear || stencil_clear) {
      uint8_t rgba[4] = { 0, 0, 0, 0 };
      if (color_clear)
         for (int i = 0; i < 4; i++)
            rgba[i] = r_float_to_unorm8(ctx->Color.ClearColor[i]);
      fgl_raster_clear(ctx, color_clear, rgba, depth_clear,
                       depth_clear ? pack_z(ctx->Depth.Clear, fb->DepthBits) : 0u,
                       stencil_clear, (uint8_t)ctx->Stencil.Clear);
   }
   if (color_quad || depth_quad || stencil_quad) {
      /* drawn at once, after what the scene holds, or binned in a scene
       * that may take the linear path (clear_with_quad) */
      fgl_lin_draw(ctx);   /* the quad is a draw */
      if (!fgl_lin_binning(ctx))
         fgl_scene_flush(ctx);
      float linear[4];
      clear_with_quad(ctx, color_quad, depth_quad, stencil_quad, ctx->Color.ClearColor,
                      quad_color(ctx, linear));
   }
   /* the accumulation buffer last, in software [S: state_tracker/
    * st_cb_clear.c:st_Clear; main/accum.c:_mesa_clear_accum_buffer]; only
    * in GL_RENDER mode [S: main/clear.c:clear] */
   if ((mask & GL_ACCUM_BUFFER_BIT) && ctx->RenderMode == GL_RENDER)
      fgl_clear_accum_buffer(ctx);
}
