/*
 * Vertex transform, as the oracle's fixed-function vertex shader computes it
 * (ORACLE-NOTES.md "Vertex transformation", "Colour conversion"):
 *   clip = ((x*C0 + y*C1) + z*C2) + w*C3   (MVP columns, every op rounded)
 *   oow  = 1/clip.w,  win = fma(clip*oow, scale, translate)
 * then the colours (the vertex colour, or the lit colours of t_light.c)
 * clamped to [0,1], and the fog coordinate (t_fog.c).
 */
#include "tnl/t_pipeline.h"
#include "raster/r_kernel.h"

#include <math.h>
#include <stddef.h>
#include <string.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "context.h"
#include "tnl/t_light.h"

/* User planes: bit 6 + i when the plane distance is negative, the distance
 * computed as a chain of fused multiply-adds in component order
 * [S: draw/draw_llvm.c:generate_clipmask (lp_build_fmuladd)]; unordered
 * like the view-volume tests, so a NaN distance is outside too (the clip
 * stage then discards the primitive). */
static inline unsigned user_clip_mask(const struct fgl_context *ctx, const float *p)
{
   unsigned m = 0, planes = ctx->Transform.ClipPlanesEnabled;
   while (planes) {
      const int i = __builtin_ctz(planes);
      const float *pl = ctx->_ClipUserPlane[i];
      planes &= planes - 1;
      float sum = pl[0] * p[0];
      sum = fmaf(pl[1], p[1], sum);
      sum = fmaf(pl[2], p[2], sum);
      sum = fmaf(pl[3], p[3], sum);
      if (!(0.0f <= sum))
         m |= 1u << (6 + i);
   }
   return m;
}

/* r_clamp01 of four components: minps(x, 1) then maxps(., 0) are
 * r_clamp01's two selects lane by lane (x < 1 ? x : 1, NaN -> 1; then
 * m > 0 ? m : 0), the same bits. */
static inline void clamp01x4(float *dst, const float *src)
{
#if defined(__SSE__) || defined(__x86_64__)
   const __m128 m = _mm_min_ps(_mm_loadu_ps(src), _mm_set1_ps(1.0f));
   _mm_storeu_ps(dst, _mm_max_ps(m, _mm_setzero_ps()));
#else
   for (int k = 0; k < 4; k++)
      dst[k] = r_clamp01(src[k]);
#endif
}

/* Whether the positions go eight at a time (t_vertex_avx2.c): a CPU
 * with AVX2 and FMA, and not FIXGL_KERNELS=reference (the scalar loops
 * below, which api/lit_kernels compares them with). */
static inline bool t_vertex_simd(const struct fgl_context *ctx)
{
#ifdef FGL_HAVE_BLOCK_KERNELS
   if (ctx->_Raster.reference_kernels)
      return false;
   __builtin_cpu_init();
   return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
   (void)ctx;
   return false;
#endif
}

/* Position, clip codes, window position and the unlit colour (already
 * clamped) of the batch's vertices first..first+n-1. */
static inline void transform_positions(const struct fgl_context *ctx,
                                       const struct fgl_vertex_view *in, unsigned first,
                                       unsigned n, const float *color, unsigned cstride,
                                       size_t clear_bytes, bool simd, struct t_vertex *out)
{
   const float *m = ctx->_ModelProjectMatrix.m;
   const float *s = ctx->_ViewportScale, *t = ctx->_ViewportTranslate;
   const bool lit = ctx->Light.Enabled;

#ifdef FGL_HAVE_BLOCK_KERNELS
   if (simd) {
#ifdef FGL_HAVE_AVX512_KERNELS
      if (ctx->_Raster.kernel_isa == R_ISA_AVX512)
         t_positions8_avx512(m, s, t, fgl_vv_attr(in, first, FGL_ATTR_POS), in->stride, n,
                             out + first);
      else
#endif
         t_positions8_avx2(m, s, t, fgl_vv_attr(in, first, FGL_ATTR_POS), in->stride, n,
                           out + first);
      const bool planes = ctx->Transform.ClipPlanesEnabled != 0;
      if (!clear_bytes && !planes && lit)
         return;
      for (unsigned i = first; i < first + n; i++) {
         struct t_vertex *v = &out[i];
         if (clear_bytes)
            memset(v->r.attr, 0, clear_bytes);
         if (planes)
            v->mask |= user_clip_mask(ctx, v->clip);
         if (!lit)
            clamp01x4(v->r.attr[R_ATTR_COLOR0], color + (size_t)i * cstride);
      }
      return;
   }
#else
   (void)simd;
#endif
   for (unsigned i = first; i < first + n; i++) {
      const float *p = fgl_vv_attr(in, i, FGL_ATTR_POS);
      struct t_vertex *v = &out[i];
      if (clear_bytes)
         memset(v->r.attr, 0, clear_bytes);
      t_mul_mad_chain(v->clip, m, p);
      v->mask = t_clip_mask(v->clip);
      if (ctx->Transform.ClipPlanesEnabled)
         v->mask |= user_clip_mask(ctx, v->clip);

      const float oow = 1.0f / v->clip[3];
      v->r.pos[0] = fmaf(v->clip[0] * oow, s[0], t[0]);
      v->r.pos[1] = fmaf(v->clip[1] * oow, s[1], t[1]);
      v->r.pos[2] = fmaf(v->clip[2] * oow, s[2], t[2]);
      v->r.pos[3] = oow;

      if (!lit)
         clamp01x4(v->r.attr[R_ATTR_COLOR0], color + (size_t)i * cstride);
   }
}

bool t_clip_masks_any(const struct fgl_context *ctx, const struct fgl_vertex_view *in,
                      unsigned first, unsigned n)
{
   const float *m = ctx->_ModelProjectMatrix.m;
   const bool planes = ctx->Transform.ClipPlanesEnabled != 0;
#ifdef FGL_HAVE_BLOCK_KERNELS
   if (!planes && n && t_vertex_simd(ctx)) {
#ifdef FGL_HAVE_AVX512_KERNELS
      if (ctx->_Raster.kernel_isa == R_ISA_AVX512)
         return t_clip_any8_avx512(m, fgl_vv_attr(in, first, FGL_ATTR_POS), in->stride, n);
#endif
      return t_clip_any8_avx2(m, fgl_vv_attr(in, first, FGL_ATTR_POS), in->stride, n);
   }
#endif
   for (unsigned i = first; i < first + n; i++) {
      float clip[4];
      t_mul_mad_chain(clip, m, fgl_vv_attr(in, i, FGL_ATTR_POS));
      if (t_clip_mask(clip) || (planes && user_clip_mask(ctx, clip)))
         return true;
   }
   return false;
}

/* Whether the vertex program computed the whole eye position (the
 * column MUL/MAD chain, get_eye_position) before the point size: for the
 * lighting, radial fog, or the texture coordinates of a unit the
 * fragment program reads with eye-linear, sphere-map or reflection-map
 * generation (ffvertex_prog.c: build_lighting, build_fog,
 * build_texture_transform run first) */
static bool eye_chain_before_psize(const struct fgl_context *ctx, bool eye_position, bool fog)
{
   if (eye_position || (fog && ctx->Fog.DistanceMode == GL_EYE_RADIAL_NV &&
                        ctx->Fog.CoordinateSource != GL_FOG_COORDINATE))
      return true;
   for (unsigned u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      if (!(ctx->_EnabledTexUnits & (1u << u)))
         continue;
      const struct fgl_texture_unit *t = &ctx->Texture.Unit[u];
      for (int c = 0; c < 4; c++)
         if ((t->TexGenEnabled & (1u << c)) &&
             (t->GenMode[c] == GL_EYE_LINEAR || t->GenMode[c] == GL_SPHERE_MAP ||
              t->GenMode[c] == GL_REFLECTION_MAP))
            return true;
   }
   return false;
}

/* glPointParameter's distance attenuation, per vertex, as the oracle's
 * vertex program computes it (ffvertex_prog.c build_atten_pointsize;
 * ORACLE-NOTES.md "Point parameters"):
 *   d = |z_eye|, t = d*a2 + a1, t = d*t + a0 (MADs as a multiply and an
 *   add), size = rsq(t) * Size, clamped to [max(MinSize, 1),
 *   min(MaxSize, 255)] (STATE_POINT_SIZE_CLAMPED), max then min */
static void point_sizes(const struct fgl_context *ctx, const struct fgl_vertex_view *in,
                        unsigned n, bool chain, struct t_vertex *out)
{
   const struct fgl_point_attrib *pt = &ctx->Point;
   const float *mv = ctx->ModelviewStack.Top->m;
   const float mn = pt->MinSize >= FGL_MIN_POINT_SIZE ? pt->MinSize : FGL_MIN_POINT_SIZE;
   const float mx = pt->MaxSize <= FGL_MAX_POINT_SIZE ? pt->MaxSize : FGL_MAX_POINT_SIZE;
   for (unsigned i = 0; i < n; i++) {
      const float *p = fgl_vv_attr(in, i, FGL_ATTR_POS);
      float z;
      if (chain) {
         float eye[4];
         t_mul_mad_chain(eye, mv, p);
         z = eye[2];
      } else {
         z = ((p[3] * mv[14] + p[2] * mv[10]) + p[1] * mv[6]) + p[0] * mv[2];
      }
      const float d = fabsf(z);
      float t = d * pt->Params[2] + pt->Params[1];
      t = d * t + pt->Params[0];
      float size = (1.0f / sqrtf(fabsf(t))) * pt->Size;
      size = size > mn ? size : mn;   /* maxps(size, min) */
      size = size < mx ? size : mx;   /* minps(size, max) */
      float *ps = out[i].r.attr[R_ATTR_PSIZE];
      ps[0] = size;
      ps[1] = ps[2] = 0.0f;
      ps[3] = 1.0f;
   }
}

/* The batch goes through the stages below chunk by chunk, each chunk of
 * vertices through every stage while its stored and transformed vertices
 * are in the cache, rather than stage by stage over the whole batch (up to
 * some 18,000 vertices of 416 bytes in and 312 out, megabytes streamed
 * from memory once per stage).  Each vertex is computed on its own as
 * before: only the order in which vertices are visited changes. */
#define T_CHUNK 128

T_FMA_CLONES
void t_transform(const struct fgl_context *ctx, const struct fgl_vertex_view *in,
                 unsigned n, struct t_vertex *out, enum t_edge_source edges)
{
   unsigned cstride;
   const float *color = fgl_vbo_attr_ptr(ctx, in, FGL_ATTR_COLOR0, &cstride);
   const bool lit = ctx->Light.Enabled;
   /* GL_PHONG_WIN: lit per fragment, from t_phong's varyings */
   const bool phong = ctx->_Raster.fs->phong;
   const bool fog = (ctx->_Raster.fs->fs_inputs & (1u << R_FS_FOG)) != 0;
   /* [S: ffvertex_prog.c:make_state_key] in GL_FEEDBACK the vertex
    * program always writes TEX0 (for the feedback records); otherwise it
    * writes the coordinate of each unit enabled with a complete texture
    * (texstate.c:update_ff_texture_state) */
   const unsigned tex_units = ctx->_EnabledTexUnits | (ctx->RenderMode == GL_FEEDBACK ? 1u : 0u);
   /* the colour slots below the fog slot (and the slots below the Phong
    * varyings) that this draw does not use are still clipped and
    * interpolated: give them a value.  Only the draw's varyings, the
    * slots below num_attribs, are ever read (clipping, flat shading and
    * the raster core stop there). */
   const size_t clear_bytes = fog || ctx->_EnabledTexUnits || phong
                                 ? (size_t)ctx->_Raster.fs->num_attribs * sizeof(out->r.attr[0])
                                 : 0;
   /* draw_llvm.c do_clamp_vertex_color: every colour output; under
    * GL_PHONG_WIN the vertex colour is a material input of the lighting
    * per fragment, unclamped (as a generic varying of the reference).
    * Unlit, the vertex colour is clamped as it is copied
    * (transform_positions) and the other colour slots are zeros. */
   const int nattr = ctx->_Raster.fs->num_attribs;
   const int ncolor = phong || !lit ? 0 : nattr < R_ATTR_FOG ? nattr : R_ATTR_FOG;
   const bool color_sum = !phong && ctx->_Raster.fs->color_sum;
   unsigned c1stride = 0;
   const float *color1 = color_sum && !lit
                       ? fgl_vbo_attr_ptr(ctx, in, FGL_ATTR_COLOR1, &c1stride) : NULL;
   const bool no_col1 = color_sum && lit &&
                        ctx->Light.Model.ColorControl != GL_SEPARATE_SPECULAR_COLOR;

   /* the lighting's per-batch values (uniforms, material sources, the
    * Cook-Torrance lights), prepared once for all chunks */
   struct t_light_batch lb;
   bool eye_position = false;
   const bool psize = ctx->_Raster.rast->point_size_per_vertex;
   if (phong) {
      /* shading.md: the fog coordinate of a vertex lit by the shading
       * extensions is |P.z|, P the eye position they light with (the
       * column chain) */
      eye_position = true;
   } else if (lit) {
      t_light_prepare(ctx, in, &lb);
      eye_position = lb.eye_position;
   }
   /* the colour slots the lighting left clamped */
   const unsigned clamped = !phong && lit ? lb.clamped : 0u;
   const bool psize_chain = psize && eye_chain_before_psize(ctx, eye_position, fog);
   const bool simd = t_vertex_simd(ctx);

   for (unsigned first = 0; first < n; first += T_CHUNK) {
      const unsigned cnt = n - first < T_CHUNK ? n - first : T_CHUNK;
      transform_positions(ctx, in, first, cnt, color, cstride, clear_bytes, simd, out);
      const struct fgl_vertex_view inf = fgl_vv_from(in, first);

      /* ffvertex_prog.c: build_texture_transform (after build_lighting,
       * independent of it) */
      if (tex_units)
         t_texcoord(ctx, &inf, cnt, tex_units, out + first);

      if (phong)
         t_phong(ctx, &inf, cnt, out + first);
      else if (lit)
         t_light_run(ctx, &lb, in, first, cnt, out);

      if (ncolor > (int)clamped)
         for (unsigned i = first; i < first + cnt; i++)
            for (int a = (int)clamped; a < ncolor; a++)
               clamp01x4(out[i].r.attr[a], out[i].r.attr[a]);

      /* GL_COLOR_SUM: unlit, the vertex program passes the secondary
       * colour through (clamped as every colour output); lit with a
       * single colour it writes no COL1, which the fragment program then
       * reads as 0 (ORACLE-NOTES.md "Secondary colour and fog
       * coordinate") */
      if (color1)
         for (unsigned i = first; i < first + cnt; i++)
            clamp01x4(out[i].r.attr[R_ATTR_COLOR1], color1 + (size_t)i * c1stride);
      else if (no_col1)
         for (unsigned i = first; i < first + cnt; i++)
            for (int a = R_ATTR_COLOR1; a < ncolor; a += 2)
               memset(out[i].r.attr[a], 0, sizeof(out[i].r.attr[a]));

      /* ffvertex_prog.c: build_fog after build_lighting */
      if (fog)
         t_fog(ctx, &inf, cnt, eye_position, out + first);

      /* build_atten_pointsize, last */
      if (psize)
         point_sizes(ctx, &inf, cnt, psize_chain, out + first);

      for (unsigned i = first; i < first + cnt; i++)
         out[i].edge = edges == T_EDGES_SET ||
                       (edges == T_EDGES_FROM_DATA && fgl_vv_attr(in, i, FGL_ATTR_EDGEFLAG)[0] == 1.0f);
   }
}
