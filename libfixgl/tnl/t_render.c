/*
 * Primitive assembly: immediate-mode primitives to triangles, in the vertex
 * orders the oracle uses (llvmpipe-facts.md §2 "Flat shading" and "quad
 * diagonal"; Mesa lp_setup_vbuf.c and draw_decompose_tmp.h), with the
 * provoking vertex last in every triangle:
 *   TRIANGLES       (i, i+1, i+2)
 *   TRIANGLE_STRIP  (i, i+1, i+2) for even i, (i+1, i, i+2) for odd i
 *   TRIANGLE_FAN    (0, i+1, i+2)
 *   POLYGON         (i+1, i+2, 0)      provoking vertex = first vertex
 *   QUADS           (0,1,2)+(0,2,3) on llvmpipe's direct path,
 *                   (0,1,3)+(1,2,3) with a flat colour input or through
 *                   the draw pipeline
 *   QUAD_STRIP      direct:   (k,k+1,k+3) then (k+2,k,k+3)
 *                   pipeline: (k+2,k,k+3) then (k,k+1,k+3)
 * A draw goes through the draw pipeline, segment by segment (4096 vertices,
 * Mesa's vsplit), when any vertex of the segment needs clipping, and
 * always when the state needs the pipeline's stages (polygon stipple,
 * unfilled polygons: ctx->_DrawPipeline.always).  The pipeline decision of
 * non-quad primitives is made for the whole primitive.
 */
#include "tnl/t_pipeline.h"

#include <stdlib.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "context.h"

#define SEGMENT_SIZE 4096

struct render {
   const struct fgl_context *ctx;
   const struct t_vertex *v;     /* transformed vertices of the draw */
   bool pipeline;                /* the current segment takes the draw pipeline */
};

static inline void tri(const struct render *r, unsigned a, unsigned b, unsigned c)
{
   t_clip_triangle(r->ctx, &r->v[a], &r->v[b], &r->v[c], r->pipeline);
}

/* Vertices [start, start+count) of a segment need the draw pipeline. */
static bool segment_clipped(const struct render *r, unsigned start, unsigned count)
{
   if (r->ctx->_DrawPipeline.always)
      return true;
   unsigned m = 0;
   for (unsigned i = start; i < start + count; i++)
      m |= r->v[i].mask;
   return m != 0;
}

static void render_quads(struct render *r, unsigned start, unsigned count,
                         bool constant_interp)
{
   count &= ~3u;
   for (unsigned seg = 0; seg < count; seg += SEGMENT_SIZE) {
      const unsigned n = count - seg < SEGMENT_SIZE ? count - seg : SEGMENT_SIZE;
      r->pipeline = segment_clipped(r, start + seg, n);
      const bool split13 = constant_interp || r->pipeline;
      for (unsigned i = start + seg; i < start + seg + n; i += 4) {
         if (split13) {
            tri(r, i, i + 1, i + 3);
            tri(r, i + 1, i + 2, i + 3);
         } else {
            tri(r, i, i + 1, i + 2);
            tri(r, i, i + 2, i + 3);
         }
      }
   }
}

static void render_quad_strip(struct render *r, unsigned start, unsigned count)
{
   count &= ~1u;
   if (count < 4)
      return;
   /* vsplit: segments of SEGMENT_SIZE vertices overlapping by one pair */
   for (unsigned seg = 0; seg + 2 < count; seg += SEGMENT_SIZE - 2) {
      const unsigned n = count - seg < SEGMENT_SIZE ? count - seg : SEGMENT_SIZE;
      r->pipeline = segment_clipped(r, start + seg, n);
      for (unsigned k = start + seg; k + 3 < start + seg + n; k += 2) {
         if (r->pipeline) {
            tri(r, k + 2, k, k + 3);
            tri(r, k, k + 1, k + 3);
         } else {
            tri(r, k, k + 1, k + 3);
            tri(r, k + 2, k, k + 3);
         }
      }
      if (seg + n >= count)
         break;
   }
}

static void render_prim(struct render *r, const struct fgl_vbo_prim *p,
                        bool constant_interp)
{
   const unsigned s = p->start, n = p->count;
   r->pipeline = segment_clipped(r, s, n);
   switch (p->mode) {
   case GL_TRIANGLES:
      for (unsigned i = 0; i + 2 < n; i += 3)
         tri(r, s + i, s + i + 1, s + i + 2);
      break;
   case GL_TRIANGLE_STRIP:
      for (unsigned i = 0; i + 2 < n; i++) {
         if (i & 1)
            tri(r, s + i + 1, s + i, s + i + 2);
         else
            tri(r, s + i, s + i + 1, s + i + 2);
      }
      break;
   case GL_TRIANGLE_FAN:
      for (unsigned i = 0; i + 2 < n; i++)
         tri(r, s, s + i + 1, s + i + 2);
      break;
   case GL_POLYGON:
      for (unsigned i = 0; i + 2 < n; i++)
         tri(r, s + i + 1, s + i + 2, s);
      break;
   case GL_QUADS:
      render_quads(r, s, n, constant_interp);
      break;
   case GL_QUAD_STRIP:
      render_quad_strip(r, s, n);
      break;
   default:
      /* points and lines arrive with their own issue */
      break;
   }
}

void t_render_batch(struct fgl_context *ctx, const struct fgl_vbo_vertex *verts,
                    unsigned nverts, const struct fgl_vbo_prim *prims, unsigned nprims)
{
   fgl_update_state(ctx);
   if (!ctx->DrawBuffer)
      return;
   fgl_update_stipple(ctx);

   struct t_vertex *tv = malloc((size_t)nverts * sizeof(*tv));
   if (!tv)
      return;

   /* The oracle draws with denormals flushed: draw_vbo sets DAZ and FTZ
    * around the vertex shader, clipping and triangle setup, and the
    * rasterizer runs with them too (draw_pt.c:draw_vbo and
    * lp_rast.c:lp_rast_queue_scene, util_fpstate_set_denorms_to_zero), while
    * the state (matrix products, light vectors) was derived before, without
    * them.  So from here on a denormal operand counts as zero and a
    * denormal result becomes zero (ORACLE-NOTES.md "Clamps and NaN"). */
#if defined(__SSE__) || defined(__x86_64__)
   const unsigned mxcsr = _mm_getcsr();
   _mm_setcsr(mxcsr | 0x8040u);   /* FTZ (bit 15) | DAZ (bit 6) */
#endif
   t_transform(ctx, verts, nverts, tv);

   struct render r = { ctx, tv, false };
   const bool flat = ctx->Light.ShadeModel == GL_FLAT;
   /* A colour that is not part of the batch's vertex format is the current
    * colour for every vertex, and Mesa's fixed-function fragment program
    * then reads it as a constant instead of interpolating it
    * (ff_fragment_shader.cpp: get_gl_Color without VARYING_BIT_COL0), so it
    * is exact even where interpolation is not (w = 0, NaN positions;
    * ORACLE-NOTES.md "Vertex batching"). */
   const bool color_varying = ctx->Vbo.attr_size[FGL_ATTR_COLOR0] != 0;
   if (ctx->Light.Enabled)
      /* lit colours are always varyings of the vertex program
       * (ff_fragment_shader.cpp: COL0/COL1 are possible inputs whenever
       * lighting is on), so only flat shading makes them constant */
      ctx->_Raster.flat_mask = flat ? 0xfu : 0u;
   else
      ctx->_Raster.flat_mask = flat || !color_varying ? 1u : 0u;
   /* llvmpipe's direct path draws a quad as (0,1,2)+(0,2,3) unless its
    * setup variant has a constant-interpolated input
    * (lp_setup_vbuf.c:lp_setup_draw_arrays, rect() when
    * !uses_constant_interp).  Only a colour input can be one, and only with
    * flat shading (lp_state_setup.c:lp_make_setup_variant_key,
    * LP_INTERP_COLOR becomes LP_INTERP_CONSTANT): a flat-shaded batch whose
    * colour is not a fragment-shader input (unlit, colour outside the
    * vertex format) still gets the (0,2) diagonal (ORACLE-NOTES.md
    * "Vertex batching"). */
   const bool constant_interp = flat && (ctx->Light.Enabled || color_varying);
   for (unsigned i = 0; i < nprims; i++)
      render_prim(&r, &prims[i], constant_interp);
#if defined(__SSE__) || defined(__x86_64__)
   _mm_setcsr(mxcsr);
#endif
   free(tv);
}
