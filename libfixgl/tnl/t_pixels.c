/*
 * Pixel rectangles: glBitmap, glDrawPixels and glCopyPixels as the
 * oracle's state tracker draws them (st_cb_bitmap.c, st_cb_drawpixels.c):
 * the image becomes a texture, and a screen-aligned quad with a
 * passthrough vertex shader samples it (NEAREST, CLAMP_TO_EDGE) in a
 * fragment shader that replaces the fixed-function one, then the normal
 * per-fragment operations run.  This file is the quad's vertex side;
 * raster/r_pixels.c shades its fragments (r_pixel_fragment).
 *
 * Which pixel receives which texel is the quad's rasterization: the
 * corners go through the oracle's float arithmetic (clip coordinates
 * x / fb_width * 2 - 1, the viewport of cso_set_viewport_dims, fused),
 * the quad is the triangle fan (0,1,2), (0,2,3) of st_draw_quad, clipped
 * by draw's clipper (t_clip_polygon, against the view volume only: the
 * quad's rasterizer state has no user planes) when a corner lies outside,
 * and the texture coordinates are interpolated by the triangles' plane
 * equations (raster/r_tri.c), then sampled at floor(s * width),
 * floor(t * height).
 *
 * Nothing here knows GL: main/drawpix.c builds the images and quads.
 */
#include "tnl/t_pipeline.h"

#include <math.h>
#include <string.h>

/* One triangle of the quad: straight to the rasterizer when every corner
 * is inside, else through the clipper [S: draw/draw_pipe_clip.c:
 * clip_tri, do_clip_tri, emit_poly], the polygon fanned as
 * (P[i-1], P[i], P[0]). */
static void quad_tri(const struct r_state *rs, const struct t_clipper *c,
                     const struct t_vertex *v0, const struct t_vertex *v1,
                     const struct t_vertex *v2)
{
   if ((v0->mask | v1->mask | v2->mask) == 0) {
      r_triangle(rs, &v0->r, &v1->r, &v2->r);
      return;
   }
   struct t_clip_poly p;
   p.n = 3;
   p.v[0] = v0;
   p.v[1] = v1;
   p.v[2] = v2;
   p.edge[0] = p.edge[1] = p.edge[2] = true;
   p.ntmp = 0;
   t_clip_polygon(c, &p);
   for (unsigned i = 2; i < p.n; i++)
      r_triangle(rs, &p.v[i - 1]->r, &p.v[i]->r, &p.v[0]->r);
}

void t_pixel_rect(const struct r_state *rs_in, const struct r_pixel_image *pix,
                  const struct t_pixel_quad *q)
{
   /* the quad's rasterizer state [S: st_cb_drawpixels.c:draw_textured_quad,
    * st_cb_bitmap.c:init_bitmap_state]: only the scissor (the draw region)
    * of the user's; no stipple, offset, culling, two-sided colours; every
    * input smooth (the colour is the same at every corner) */
   struct r_state rs = *rs_in;
   /* (its own viewport covers the quad: the region not cut to the user's) */
   rs.px0 = rs.x0;
   rs.py0 = rs.y0;
   rs.px1 = rs.x1;
   rs.py1 = rs.y1;
   struct r_rast_state rast = *rs.rast;
   struct r_fs_state fs = *rs.fs;
   rs.pix = pix;
   rast.stipple = false;
   fs.aa = R_AA_NONE;
   rast.offset_units = rast.offset_scale = 0.0f;
   rast.cull_front = rast.cull_back = false;
   rast.twoside = false;
   rast.point_sprite = false;     /* (its own rasterizer: no sprite coordinates) */
   rast.sprite_coord_enable = 0;
   fs.phong = false;
   rs.flat_mask = 0;
   fs.fs_inputs = 1u << R_FS_COLOR0 | 1u << R_FS_TEX0;
   fs.num_attribs = R_ATTR_TEX0 + 1;
   rs.rast = &rast;
   rs.fs = &fs;
   r_choose_kernels(&rs);

   /* [S: st_cb_drawpixels.c:draw_textured_quad] clip coordinates, z from
    * [0,1] to [-1,1] */
   const float fw = (float)q->fb_width, fh = (float)q->fb_height;
   const float cx0 = q->x0 / fw * 2.0f - 1.0f;
   const float cy0 = q->y0 / fh * 2.0f - 1.0f;
   const float cx1 = q->x1 / fw * 2.0f - 1.0f;
   const float cy1 = q->y1 / fh * 2.0f - 1.0f;
   const float cz = q->z * 2.0f - 1.0f;

   /* [S: gallium/auxiliary/cso_cache/cso_context.c:cso_set_viewport_dims]
    * scale (w/2, -h/2, 0.5), translate (w/2, h/2, 0.5) for the y-down
    * window buffer (invert) */
   const float scale[3] = { fw * 0.5f, fh * -0.5f, 0.5f };
   const float translate[3] = { 0.5f * fw, 0.5f * fh, 0.5f };

   /* [S: st_draw.c:st_draw_quad] (x0, y1, s0, t0), (x1, y1, s1, t0),
    * (x1, y0, s1, t1), (x0, y0, s0, t1) as a triangle fan, where the
    * callers pass t0 for the y1 edge */
   const float cx[4] = { cx0, cx1, cx1, cx0 };
   const float cy[4] = { cy1, cy1, cy0, cy0 };
   const float s[4] = { q->s0, q->s1, q->s1, q->s0 };
   const float t[4] = { q->t_y1, q->t_y1, q->t_y0, q->t_y0 };
   struct t_vertex v[4];
   unsigned anymask = 0;
   for (int i = 0; i < 4; i++) {
      memset(&v[i], 0, sizeof(v[i]));
      v[i].clip[0] = cx[i];
      v[i].clip[1] = cy[i];
      v[i].clip[2] = cz;
      v[i].clip[3] = 1.0f;
      v[i].mask = t_clip_mask(v[i].clip);
      v[i].edge = true;
      anymask |= v[i].mask;
      /* the LLVM vertex path: x * (1/w), then fused with the viewport */
      const float oow = 1.0f / v[i].clip[3];
      for (int k = 0; k < 3; k++)
         v[i].r.pos[k] = fmaf(v[i].clip[k] * oow, scale[k], translate[k]);
      v[i].r.pos[3] = oow;
      for (int k = 0; k < 4; k++)
         v[i].r.attr[R_ATTR_COLOR0][k] = q->color[k];
      v[i].r.attr[R_ATTR_TEX0][0] = s[i];
      v[i].r.attr[R_ATTR_TEX0][1] = t[i];
      v[i].r.attr[R_ATTR_TEX0][2] = 0.0f;
      v[i].r.attr[R_ATTR_TEX0][3] = 1.0f;
   }

   if (anymask == 0) {
      /* llvmpipe's direct path: the fan's triangles */
      r_triangle(&rs, &v[0].r, &v[1].r, &v[2].r);
      r_triangle(&rs, &v[0].r, &v[2].r, &v[3].r);
      return;
   }
   /* draw's pipeline: each triangle clipped, its new vertices with the
    * quad's varyings (the colour and the image coordinate) */
   const struct t_clipper c = {
      .user_planes = NULL,
      .scale = scale,
      .translate = translate,
      .attrs = (1u << (R_ATTR_TEX0 + 1)) - 1u,
      .new_vertex = NULL,
      .data = NULL,
   };
   quad_tri(&rs, &c, &v[0], &v[1], &v[2]);
   quad_tri(&rs, &c, &v[0], &v[2], &v[3]);
}
