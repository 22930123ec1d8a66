/*
 * t_light_shade8_avx2: per-vertex Cook-Torrance eight vertices at a time
 * (t_light.c light_shade8, shade8_prepare's batches), AVX2 + FMA, in the
 * archive of such code (meson.build); called only on a CPU that runs it.
 *
 * Every lane does light_shade's operations for its vertex, in its order:
 *  - n: t_eye_normal (t_phong.c), the inverse modelview's rows times the
 *    normal, (m0*x + m1*y) + m2*z, then GL_NORMALIZE's
 *    n * (1/sqrt((z*z + y*y) + x*x)) or GL_RESCALE_NORMAL's n * scale;
 *  - P: t_mul_mad_chain, ((x*M0 + y*M1) + z*M2) + w*M3, xyz;
 *  - the lighting: m_shade8_eval (math/m_shade_avx2.h), each lane
 *    m_shade_point_prepared's bits, per face;
 * every multiply and add rounded on its own (-ffp-contract=off), so the
 * colours are the scalar path's.  The inputs are gathered (lanes past the
 * batch's end read its group's first vertex), the outputs transposed to
 * the vertices' colour slots.
 */
#include "tnl/t_light.h"

#include "math/m_shade_avx2.h"

/* the four channel vectors c[0..3] of 8 lanes to the lanes' rgba, vertex
 * l of the group at out[l][slot] (l < cnt) */
static inline void store_rgba8(const v8 c[4], struct t_vertex *out, unsigned cnt, int slot)
{
   const v8 t0 = _mm256_unpacklo_ps(c[0], c[1]), t1 = _mm256_unpackhi_ps(c[0], c[1]);
   const v8 t2 = _mm256_unpacklo_ps(c[2], c[3]), t3 = _mm256_unpackhi_ps(c[2], c[3]);
   /* q[j]: vertices j (low half) and j + 4 (high half) */
   const v8 q[4] = { _mm256_shuffle_ps(t0, t2, 0x44), _mm256_shuffle_ps(t0, t2, 0xee),
                     _mm256_shuffle_ps(t1, t3, 0x44), _mm256_shuffle_ps(t1, t3, 0xee) };
   for (unsigned l = 0; l < cnt; l++) {
      const __m128 v = l < 4 ? _mm256_castps256_ps128(q[l]) : _mm256_extractf128_ps(q[l - 4], 1);
      _mm_storeu_ps(out[l].r.attr[slot], v);
   }
}

void t_light_shade8_avx2(const struct fgl_context *ctx, const struct t_light_batch *lb,
                         const struct fgl_vertex_view *in, unsigned first, unsigned n,
                         struct t_vertex *out)
{
   const struct m_shade_env *env = &lb->env;
   const struct t_eye_normal *en = &lb->en;
   const int sides = ctx->Light.Model.TwoSide ? 2 : 1;
   const float *m = ctx->ModelviewStack.Top->m;
   const float *inv = en->inv;
   const bool colour = env->color_material != 0;
   const int vstride = (int)in->stride;
   const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);

   for (unsigned i = first; i < first + n; i += M_SHADE_LANES) {
      const unsigned cnt = first + n - i < M_SHADE_LANES ? first + n - i : M_SHADE_LANES;
      /* the lanes' vertices relative to i: lane < cnt ? lane : 0 */
      const __m256i l =
         _mm256_and_si256(lane, _mm256_cmpgt_epi32(_mm256_set1_epi32((int)cnt), lane));

      /* n = t_eye_normal */
      const float *nb = lb->normal + (size_t)i * lb->nstride;
      const __m256i ni = _mm256_mullo_epi32(l, _mm256_set1_epi32((int)lb->nstride));
      v8 nin[3], N[3];
      for (int k = 0; k < 3; k++)
         nin[k] = _mm256_i32gather_ps(nb + k, ni, 4);
      for (int r = 0; r < 3; r++)
         N[r] = vadd(vadd(vmul(vset(inv[4 * r]), nin[0]), vmul(vset(inv[4 * r + 1]), nin[1])),
                     vmul(vset(inv[4 * r + 2]), nin[2]));
      if (en->normalize) {
         const v8 d = vadd(vadd(vmul(N[2], N[2]), vmul(N[1], N[1])), vmul(N[0], N[0]));
         const v8 k = vdiv(vset(1.0f), _mm256_sqrt_ps(d));
         for (int r = 0; r < 3; r++)
            N[r] = vmul(N[r], k);
      } else if (en->rescale) {
         for (int r = 0; r < 3; r++)
            N[r] = vmul(N[r], vset(en->scale));
      }

      /* P = t_mul_mad_chain(modelview, position), xyz */
      const float *pb = fgl_vv_attr(in, i, FGL_ATTR_POS);
      const __m256i pi = _mm256_mullo_epi32(l, _mm256_set1_epi32(vstride));
      v8 pin[4], P[3];
      for (int k = 0; k < 4; k++)
         pin[k] = _mm256_i32gather_ps(pb + k, pi, 4);
      for (int r = 0; r < 3; r++) {
         v8 acc = vmul(pin[0], vset(m[r]));
         acc = vadd(vmul(pin[1], vset(m[4 + r])), acc);
         acc = vadd(vmul(pin[2], vset(m[8 + r])), acc);
         P[r] = vadd(vmul(pin[3], vset(m[12 + r])), acc);
      }

      /* the vertex colours, where a property tracks them */
      v8 C[4] = { _mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps(),
                  _mm256_setzero_ps() };
      if (colour) {
         const float *cb = lb->color + (size_t)i * lb->cstride;
         const __m256i ci = _mm256_mullo_epi32(l, _mm256_set1_epi32((int)lb->cstride));
         for (int k = 0; k < 4; k++)
            C[k] = _mm256_i32gather_ps(cb + k, ci, 4);
      }

      for (int s = 0; s < sides; s++) {
         v8 prim[4], sec[4];
         m_shade8_eval(env, N, P, s == 1, C, prim, sec);
         store_rgba8(prim, out + i, cnt, 2 * s);
         store_rgba8(sec, out + i, cnt, 2 * s + 1);
      }
   }
}
