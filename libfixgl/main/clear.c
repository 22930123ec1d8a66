/*
 * Clearing: glClearColor (GL_COLOR_BUFFER_BIT state) and glClear.
 * The clear colour is packed with float_to_ubyte and depth with
 * util_pack_z, as the oracle does (llvmpipe-facts.md §1, §7).
 */
#include <math.h>

#include "main/groups.h"

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
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   ctx->Color.ClearColor[0] = red;
   ctx->Color.ClearColor[1] = green;
   ctx->Color.ClearColor[2] = blue;
   ctx->Color.ClearColor[3] = alpha;
}

/* util_pack_z for the 16- and 24-bit formats */
static uint32_t pack_z(double z, int bits)
{
   const double max = bits == 16 ? 65535.0 : 16777215.0;
   if (z == 0.0)
      return 0;
   if (z == 1.0)
      return (uint32_t)max;
   return (uint32_t)lrint(z * max);
}

void GLAPIENTRY glClear(GLbitfield mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
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
   fgl_update_state(ctx);
   const struct r_state *rs = &ctx->_Raster;

   if (mask & GL_COLOR_BUFFER_BIT) {
      uint8_t rgba[4];
      for (int i = 0; i < 4; i++)
         rgba[i] = r_float_to_unorm8(ctx->Color.ClearColor[i]);
      r_clear_color(rs, rgba);
   }
   /* the depth write mask applies to clears too */
   const bool depth = (mask & GL_DEPTH_BUFFER_BIT) && fb->DepthBits > 0 && ctx->Depth.Mask;
   const bool stencil = (mask & GL_STENCIL_BUFFER_BIT) && fb->StencilBits > 0;
   if (depth || stencil)
      r_clear_depth_stencil(rs, depth, pack_z(ctx->Depth.Clear, fb->DepthBits), stencil, 0);
}
