/*
 * Pixel rectangles: glBitmap, glDrawPixels and glCopyPixels as the
 * oracle's state tracker draws them (st_cb_bitmap.c, st_cb_drawpixels.c):
 * the image becomes a texture, and a screen-aligned quad with a
 * passthrough vertex shader samples it (NEAREST, CLAMP_TO_EDGE) in a
 * fragment shader that replaces the fixed-function one, then the normal
 * per-fragment operations run.
 *
 * Which pixel receives which texel is the quad's rasterization: the
 * corners go through the oracle's float arithmetic (clip coordinates
 * x / fb_width * 2 - 1, the viewport of cso_set_viewport_dims, fused),
 * the quad is the triangle fan (0,1,2), (0,2,3) of st_draw_quad, clipped
 * by draw's clipper when a corner lies outside the view volume, and the
 * texture coordinates are interpolated by the triangles' plane equations
 * (r_tri.c), then sampled at floor(s * width), floor(t * height).
 *
 * Nothing here knows GL: main/drawpix.c builds the images and quads.
 */
#include "r_state.h"

#include <math.h>
#include <string.h>

/* A corner of the quad in clip space with its window position. */
struct pix_vertex {
   float clip[4];
   unsigned mask;
   struct r_vertex r;
};

#define MAX_CLIPPED 16

/* draw_context.c:draw_create: the view-volume planes */
static const float view_planes[6][4] = {
   { -1, 0, 0, 1 }, { 1, 0, 0, 1 }, { 0, -1, 0, 1 },
   { 0, 1, 0, 1 },  { 0, 0, 1, 1 }, { 0, 0, -1, 1 },
};

/* [S: gallium/auxiliary/cso_cache/cso_context.c:cso_set_viewport_dims]
 * scale (w/2, -h/2, 0.5), translate (w/2, h/2, 0.5) for the y-down
 * window buffer (invert) */
struct pix_viewport {
   float scale[3], translate[3];
};

static inline float dot4(const float *a, const float *b)
{
   return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

/* [S: draw/draw_llvm.c:generate_clipmask] unordered compares: NaN is
 * outside */
static unsigned clipmask(const float c[4])
{
   unsigned m = 0;
   if (!(c[0] <= c[3])) m |= 1u;
   if (!(-c[3] <= c[0])) m |= 2u;
   if (!(c[1] <= c[3])) m |= 4u;
   if (!(-c[3] <= c[1])) m |= 8u;
   if (!(-c[3] <= c[2])) m |= 16u;
   if (!(c[2] <= c[3])) m |= 32u;
   return m;
}

static inline float lerp(float t, float out, float in)
{
   return out + t * (in - out);
}

/* [S: draw/draw_pipe_clip.c:interp] a new vertex: every attribute lerped,
 * window coordinates in C without FMA */
static void interp(const struct pix_viewport *vp, struct pix_vertex *dst, float t,
                   const struct pix_vertex *out, const struct pix_vertex *in)
{
   for (int i = 0; i < 4; i++)
      dst->clip[i] = lerp(t, out->clip[i], in->clip[i]);
   dst->mask = 0;
   const float oow = 1.0f / dst->clip[3];
   for (int i = 0; i < 3; i++)
      dst->r.pos[i] = dst->clip[i] * oow * vp->scale[i] + vp->translate[i];
   dst->r.pos[3] = oow;
   for (int a = 0; a <= R_ATTR_TEX0; a++)
      for (int c = 0; c < 4; c++)
         dst->r.attr[a][c] = lerp(t, out->r.attr[a][c], in->r.attr[a][c]);
}

/* [S: draw/draw_pipe_clip.c:do_clip_tri, emit_poly] the view-volume planes
 * only (the quad's rasterizer state has no user planes); the polygon is
 * fanned as (P[i-1], P[i], P[0]) */
static void clip_tri(const struct r_state *rs, const struct pix_viewport *vp,
                     const struct pix_vertex *v0, const struct pix_vertex *v1,
                     const struct pix_vertex *v2)
{
   unsigned mask = v0->mask | v1->mask | v2->mask;
   if (mask == 0) {
      r_triangle(rs, &v0->r, &v1->r, &v2->r);
      return;
   }
   if (v0->mask & v1->mask & v2->mask)
      return;

   struct pix_vertex tmp[MAX_CLIPPED + 2];
   unsigned tmpnr = 0;
   const struct pix_vertex *a[MAX_CLIPPED + 1], *b[MAX_CLIPPED + 1];
   const struct pix_vertex **inlist = a, **outlist = b;
   unsigned n = 3;
   inlist[0] = v0;
   inlist[1] = v1;
   inlist[2] = v2;
   while (mask && n >= 3) {
      const int p = __builtin_ctz(mask);
      const float *plane = view_planes[p];
      const struct pix_vertex *vert_prev = inlist[0];
      float dp_prev = dot4(vert_prev->clip, plane);
      unsigned outcount = 0;
      mask &= ~(1u << p);
      if (!isfinite(dp_prev) || n >= MAX_CLIPPED)
         return;
      inlist[n] = inlist[0];
      for (unsigned i = 1; i <= n; i++) {
         const struct pix_vertex *vert = inlist[i];
         const float dp = dot4(vert->clip, plane);
         bool different_sign;
         if (!isfinite(dp))
            return;
         if (dp_prev >= 0.0f) {
            if (outcount >= MAX_CLIPPED)
               return;
            outlist[outcount++] = vert_prev;
            different_sign = dp < 0.0f;
         } else {
            different_sign = !(dp < 0.0f);
         }
         if (different_sign) {
            if (tmpnr >= MAX_CLIPPED + 1 || outcount >= MAX_CLIPPED)
               return;
            struct pix_vertex *nv = &tmp[tmpnr++];
            outlist[outcount++] = nv;
            const float denom = dp - dp_prev;
            if (dp < 0.0f) {
               if (-dp < dp_prev)
                  interp(vp, nv, dp / denom, vert, vert_prev);
               else
                  interp(vp, nv, -dp_prev / denom, vert_prev, vert);
            } else {
               if (-dp_prev < dp)
                  interp(vp, nv, -dp_prev / denom, vert_prev, vert);
               else
                  interp(vp, nv, dp / denom, vert, vert_prev);
            }
         }
         vert_prev = vert;
         dp_prev = dp;
      }
      const struct pix_vertex **t = inlist;
      inlist = outlist;
      outlist = t;
      n = outcount;
   }
   for (unsigned i = 2; i < n; i++)
      r_triangle(rs, &inlist[i - 1]->r, &inlist[i]->r, &inlist[0]->r);
}

void r_pixel_rect(const struct r_state *rs_in, const struct r_pixel_image *pix,
                  const struct r_pixel_quad *q)
{
   /* the quad's rasterizer state [S: st_cb_drawpixels.c:draw_textured_quad,
    * st_cb_bitmap.c:init_bitmap_state]: only the scissor (the draw region)
    * of the user's; no stipple, offset, culling, two-sided colours; every
    * input smooth (the colour is the same at every corner) */
   struct r_state rs = *rs_in;
   struct r_rast_state rast = *rs.rast;
   struct r_fs_state fs = *rs.fs;
   rs.pix = pix;
   rast.stipple = false;
   fs.aa = R_AA_NONE;
   rast.offset_units = rast.offset_scale = 0.0f;
   rast.cull_front = rast.cull_back = false;
   rast.twoside = false;
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

   const struct pix_viewport vp = {
      .scale = { fw * 0.5f, fh * -0.5f, 0.5f },
      .translate = { 0.5f * fw, 0.5f * fh, 0.5f },
   };

   /* [S: st_draw.c:st_draw_quad] (x0, y1, s0, t0), (x1, y1, s1, t0),
    * (x1, y0, s1, t1), (x0, y0, s0, t1) as a triangle fan, where the
    * callers pass t0 for the y1 edge */
   const float cx[4] = { cx0, cx1, cx1, cx0 };
   const float cy[4] = { cy1, cy1, cy0, cy0 };
   const float s[4] = { q->s0, q->s1, q->s1, q->s0 };
   const float t[4] = { q->t_y1, q->t_y1, q->t_y0, q->t_y0 };
   struct pix_vertex v[4];
   unsigned anymask = 0;
   for (int i = 0; i < 4; i++) {
      memset(&v[i], 0, sizeof(v[i]));
      v[i].clip[0] = cx[i];
      v[i].clip[1] = cy[i];
      v[i].clip[2] = cz;
      v[i].clip[3] = 1.0f;
      v[i].mask = clipmask(v[i].clip);
      anymask |= v[i].mask;
      /* the LLVM vertex path: x * (1/w), then fused with the viewport */
      const float oow = 1.0f / v[i].clip[3];
      for (int c = 0; c < 3; c++)
         v[i].r.pos[c] = fmaf(v[i].clip[c] * oow, vp.scale[c], vp.translate[c]);
      v[i].r.pos[3] = oow;
      for (int c = 0; c < 4; c++)
         v[i].r.attr[R_ATTR_COLOR0][c] = q->color[c];
      v[i].r.attr[R_ATTR_TEX0][0] = s[i];
      v[i].r.attr[R_ATTR_TEX0][1] = t[i];
      v[i].r.attr[R_ATTR_TEX0][2] = 0.0f;
      v[i].r.attr[R_ATTR_TEX0][3] = 1.0f;
   }

   if (anymask == 0) {
      /* llvmpipe's direct path: the fan's triangles */
      r_triangle(&rs, &v[0].r, &v[1].r, &v[2].r);
      r_triangle(&rs, &v[0].r, &v[2].r, &v[3].r);
   } else {
      /* draw's pipeline: each triangle clipped */
      clip_tri(&rs, &vp, &v[0], &v[1], &v[2]);
      clip_tri(&rs, &vp, &v[0], &v[2], &v[3]);
   }
}

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
         continue;
      }
      memcpy(fin[R_FS_TEX0 + u], pix->tex_const[u], sizeof(fin[0]));
      for (int i = 0; i < 3; i++)
         for (int c = 0; c < 4; c++)
            q.tex[u][i][c] = q.pair[u][i][c] = pix->tex_const[u][c];
   }
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
      if (pix->raw_color) {
         r_fragment_ops(rs, px, py, z, c);
         return;
      }
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
      if (pix->with_stencil) {
         struct r_dsa_state dsa = *rs->dsa;
         struct r_state s = *rs;
         dsa.stencil_ref = pix->mask[idx];
         s.dsa = &dsa;
         r_fragment_ops(&s, px, py, pix->texels[idx], in[R_FS_COLOR0]);
      } else {
         r_fragment_ops(rs, px, py, pix->texels[idx], in[R_FS_COLOR0]);
      }
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
