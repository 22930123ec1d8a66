/*
 * The fragments of pixel rectangles: glBitmap, glDrawPixels and
 * glCopyPixels as the oracle's state tracker draws them
 * (st_cb_bitmap.c, st_cb_drawpixels.c): the image becomes a texture, and
 * a screen-aligned quad with a passthrough vertex shader (tnl/t_pixels.c
 * places, clips and rasterizes it) samples it (NEAREST, CLAMP_TO_EDGE) in
 * a fragment shader that replaces the fixed-function one, then the normal
 * per-fragment operations run.
 *
 * r_pixel_fragment is that fragment shader: the triangle rasterizer
 * (r_tri.c) calls it for each covered pixel of a quad (rs->pix set) with
 * the interpolated texture coordinate, which is sampled at
 * floor(s * width), floor(t * height).
 *
 * Nothing here knows GL: main/drawpix.c builds the images and quads.
 */
#include "r_state.h"

#include <math.h>
#include <string.h>

/* NEAREST with CLAMP_TO_EDGE on normalized coordinates
 * [S: gallivm/lp_bld_sample_aos.c:lp_build_sample_image_nearest,
 * lp_bld_sample_soa.c:lp_build_sample_wrap_nearest]: floor(s * size),
 * clamped to [0, size - 1]. */
static int nearest(float s, int size)
{
   const float f = floorf(s * (float)size);
   if (!(f > 0.0f))
      return 0;       /* also NaN: the clamp's max picks 0 */
   if (f >= (float)(size - 1))
      return size - 1;
   return (int)f;
}

/* The fixed-function fragment program for a fragment of the quad.  The
 * user's units read either the quad's own coordinate (pix->tex_quad:
 * glBitmap's gl_TexCoord[0] is the bitmap coordinate, interpolated with
 * real derivatives) or a constant, the same at every pixel of the quad
 * (derivatives 0: always magnified). */
static void pixel_shader(const struct r_state *rs, const float fin_in[][4],
                         const float *quad_tc, const struct r_fs_quad *quad, float color[4])
{
   if (!rs->fs->tex_units) {
      r_fragment_shader(rs, fin_in, NULL, color);
      return;
   }
   const struct r_pixel_image *pix = rs->pix;
   float fin[R_FS_NUM_INPUTS][4];
   memcpy(fin, fin_in, sizeof(fin));
   struct r_fs_quad q;
   for (int u = 0; u < R_MAX_TEX_UNITS; u++) {
      if ((pix->tex_quad & (1u << u)) && quad) {
         memcpy(fin[R_FS_TEX0 + u], quad_tc, sizeof(fin[0]));
         memcpy(q.tex[u], quad->tex[0], sizeof(q.tex[u]));
         memcpy(q.pair[u], quad->pair[0], sizeof(q.pair[u]));
         memcpy(q.br[u], quad->br[0], sizeof(q.br[u]));
         memcpy(q.pair_br[u], quad->pair_br[0], sizeof(q.pair_br[u]));
         continue;
      }
      memcpy(fin[R_FS_TEX0 + u], pix->tex_const[u], sizeof(fin[0]));
      for (int i = 0; i < 3; i++)
         for (int c = 0; c < 4; c++)
            q.tex[u][i][c] = q.pair[u][i][c] = pix->tex_const[u][c];
      for (int c = 0; c < 4; c++)
         q.br[u][c] = q.pair_br[u][c] = pix->tex_const[u][c];
   }
   q.pos = quad ? quad->pos : 0;
   r_fragment_shader(rs, (const float (*)[4])fin, &q, color);
}

/* A colour map looked up in the state tracker's 256x256 pixel-map texture
 * [S: st_atom_pixeltransfer.c:load_color_map_texture]: texel (i, j) holds
 * R map[j * size / 256], G map[i * size / 256] (and B, A maps, which no
 * lookup reaches) packed to unorm8 (util_pack_color) and read back as
 * t * (1/255); the map index is the nearest texel at the colour value. */
static float map_lookup(const struct r_pixel_image *pix, int map, float v)
{
   const int size = pix->map_size[map];
   const int k = nearest(v, 256) * size / 256;
   return (float)r_float_to_unorm8(pix->maps[map][k]) * (float)(1.0 / 255.0);
}

void r_pixel_fragment(const struct r_state *rs, int px, int py, const float in[][4], float z,
                      const struct r_fs_quad *quad)
{
   const struct r_pixel_image *pix = rs->pix;
   const float *tc = in[R_FS_TEX0];
   const int i = nearest(tc[0], pix->width);
   const int j = nearest(tc[1], pix->height);
   const size_t idx = (size_t)j * (size_t)pix->width + (size_t)i;
   /* the inputs of the fixed-function program: the passthrough vertex
    * shader writes no secondary colour and no fog coordinate, and llvmpipe
    * reads inputs no vertex output feeds as zeros
    * [S: llvmpipe/lp_state_derived.c:compute_vertex_info,
    * draw/draw_vertex.h:draw_emit_vertex_attr (DRAW_ATTR_NONEXIST)] */
   float fin[R_FS_NUM_INPUTS][4];
   memset(fin, 0, sizeof(fin));
   float color[4];

   switch (pix->kind) {
   case R_PIX_BITMAP:
      /* [S: compiler/nir/nir_lower_bitmap.c] kill if the texel != 0 */
      if (pix->mask[idx] != 0)
         return;
      memcpy(fin[R_FS_COLOR0], in[R_FS_COLOR0], sizeof(fin[0]));
      pixel_shader(rs, (const float (*)[4])fin, tc, quad, color);
      r_fragment_ops(rs, px, py, z, color);
      return;
   case R_PIX_COLOR: {
      /* [S: compiler/nir/nir_lower_drawpixels.c:lower_color] the texel
       * replaces gl_Color; scale and bias, then the maps */
      float c[4];
      memcpy(c, pix->texels + 4 * idx, sizeof(c));
      if (pix->scale_bias)
         for (int k = 0; k < 4; k++)
            c[k] = c[k] * pix->scale[k] + pix->bias[k];
      if (pix->map_color) {
         /* [S: nir_lower_drawpixels.c:lower_color] two lookups, at
          * (r, g) and (b, a), keeping channels x and y of each.  The first
          * reads the pixel-map texture: R map by r, G map by g.  The
          * second has no texture deref and texture_index 0, which is the
          * drawpix image itself (drawpix_sampler 0): blue and alpha become
          * the red and green of the image texel nearest to (b, a)
          * (probed: a 1x1 image gives its own red and green) */
         const float r = map_lookup(pix, 0, c[0]), g = map_lookup(pix, 1, c[1]);
         const size_t k = (size_t)nearest(c[3], pix->height) * (size_t)pix->width +
                          (size_t)nearest(c[2], pix->width);
         c[0] = r;
         c[1] = g;
         c[2] = pix->texels[4 * k + 0];
         c[3] = pix->texels[4 * k + 1];
      }
      memcpy(fin[R_FS_COLOR0], c, sizeof(c));
      pixel_shader(rs, (const float (*)[4])fin, tc, quad, color);
      r_fragment_ops(rs, px, py, z, color);
      return;
   }
   case R_PIX_DEPTH:
      /* [S: st_cb_drawpixels.c:make_drawpix_z_stencil_program_nir] depth
       * from the texture, the vertex colour as is */
      r_fragment_ops(rs, px, py, pix->texels[idx], in[R_FS_COLOR0]);
      return;
   case R_PIX_STENCIL:
   default: {
      /* the exported stencil value is the reference of the state set up
       * by the caller (func ALWAYS, zpass REPLACE) */
      struct r_dsa_state dsa = *rs->dsa;
      struct r_state s = *rs;
      dsa.stencil_ref = pix->mask[idx];
      s.dsa = &dsa;
      r_fragment_ops(&s, px, py, z, in[R_FS_COLOR0]);
      return;
   }
   }
}
