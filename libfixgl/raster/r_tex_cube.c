/*
 * Cube map lookups (GL 1.3), as llvmpipe samples a PIPE_TEXTURE_CUBE
 * without seamless filtering (ORACLE-NOTES.md "Cube maps"; probe
 * p_cubemap) [S: gallivm/lp_bld_sample.c:lp_build_cube_lookup,
 * lp_build_rho; lp_bld_sample_soa.c:lp_build_sample_common,
 * lp_build_sample_soa_code].
 *
 * Each fragment picks its own face from its (s, t, r) (after the
 * projective divide): the major axis is x when |s| > |t|, else y, and z
 * when |r| >= max(|s|, |t|), so ties go to z over y over x; the sign of
 * the major coordinate ma picks the positive or negative face.  The face
 * coordinates are the two minor ones with the signs of the GL table,
 * scaled by |0.5 / ma| and offset by 0.5 (a multiply, then an add).  The
 * face is then sampled as a 2D texture whose s and t wraps are
 * CLAMP_TO_EDGE whatever the object's wraps (llvmpipe overrides them for
 * cube maps), on the AoS 8-bit path or the float path as for 2D.
 *
 * The level of detail (when the filters need one): under a mipmap filter
 * each pixel has its own, from its own derivatives of (s, t, r) (along x
 * its row's right - left, along y its column's bottom - top: the
 * quad's bottom-right pixel is needed, r_fs_quad.br); with min != mag
 * and no mipmap filter the quad has one, its top-left pixel's.  The
 * derivatives are carried onto that pixel's face,
 *    d(face s) = 0.5 * (d sc - sc * d ma / ma) / ma,
 * as gallivm computes them (1/ma a true division, then multiplies), and
 * rho is the 2D squared form of those derivatives times the face size,
 * 0 when it is infinite or NaN (q = 0: infinite coordinates).
 * With a LOD per pixel and min != mag, llvmpipe takes the float path
 * (state.c sets float_path), deciding the filter over the 8 pixels of the
 * vector: every pixel's LOD of both quads (r_tex_sample_float_lods).
 *
 * state.c marks a cube map `soa` (no fast kernel, no per-quad LOD
 * cache); the reference fragment program (r_frag.c) calls
 * r_tex_sample_cube with the whole quad (r_tex_sample, for other callers,
 * with its top-left pixel's derivatives only), and the face is sampled
 * through a copy of the r_texture whose `cube` is R_CUBE_FACE: its levels
 * point at the face's images and its `soa` is the one the face needs
 * (face_soa), and r_tex_rho still sees a cube (r_tex_cube_rho).
 */
#include "r_state.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#define SIGN 0x80000000u

/* The major axis of c [S: lp_build_cube_lookup]: as_ge_at is
 * lp_build_cmp(GREATER) and ar_ge_as_at lp_build_cmp(GEQUAL) against
 * lp_build_max(as, at) (maxps: the second operand when either is NaN),
 * both unordered compares (true for NaN).  0: x, 1: y, 2: z. */
static int major_axis(const float c[3])
{
   const float as = fabsf(c[0]), at = fabsf(c[1]), ar = fabsf(c[2]);
   const bool as_gt_at = !(as <= at);
   const float maxasat = as > at ? as : at;
   const bool ar_ge = !(ar < maxasat);
   return ar_ge ? 2 : as_gt_at ? 0 : 1;
}

/* The face's minor coordinates of a vector v (a coordinate or its
 * derivative) for major axis `axis` whose major coordinate has the sign
 * bit `sign` (lp_build_cube_lookup's snew*, tnew* by sign bit xors):
 * x: (-sign * r, -t), y: (s, sign * r), z: (sign * s, -t). */
static void face_minor(int axis, uint32_t sign, const float v[3], float *fs, float *ft)
{
   switch (axis) {
   case 0:
      *fs = r_u2f(r_f2u(v[2]) ^ SIGN ^ sign);
      *ft = r_u2f(r_f2u(v[1]) ^ SIGN);
      break;
   case 1:
      *fs = v[0];
      *ft = r_u2f(r_f2u(v[2]) ^ sign);
      break;
   default:
      *fs = r_u2f(r_f2u(v[0]) ^ sign);
      *ft = r_u2f(r_f2u(v[1]) ^ SIGN);
      break;
   }
}

/* The derivative form r_tex_cube_rho reads of pixel `pos` of a quad
 * (q4: TL, TR, BL, BR): its coordinates, then lp_build_ddx (its row's
 * right - left) and lp_build_ddy (its column's bottom - top). */
static void deriv_form(const float q4[4][3], unsigned pos, float q[3][3])
{
   for (int k = 0; k < 3; k++) {
      q[0][k] = q4[pos][k];
      q[1][k] = pos & 2 ? q4[3][k] - q4[2][k] : q4[1][k] - q4[0][k];
      q[2][k] = pos & 1 ? q4[3][k] - q4[1][k] : q4[2][k] - q4[0][k];
   }
}

float r_tex_cube_rho(const struct r_texture *t, const float q[3][3])
{
   const float *tl = q[0], *dx = q[1], *dy = q[2];
   const int axis = major_axis(tl);
   const float ma = tl[axis];
   const uint32_t sign = r_f2u(ma) & SIGN;
   float fs, ft, fsdx, ftdx, fsdy, ftdy;
   face_minor(axis, sign, tl, &fs, &ft);
   face_minor(axis, sign, dx, &fsdx, &ftdx);
   face_minor(axis, sign, dy, &fsdy, &ftdy);
   const float ima = 1.0f / ma;
   const float imahalf = 0.5f * ima;
   /* dx.s = 0.5 * (dx.sc - sc * dx.ma / ma) / ma, and so on */
   const float madxdivma = dx[axis] * ima;
   const float dsdx = (fsdx - madxdivma * fs) * imahalf;
   const float dtdx = (ftdx - madxdivma * ft) * imahalf;
   const float madydivma = dy[axis] * ima;
   const float dsdy = (fsdy - madydivma * fs) * imahalf;
   const float dtdy = (ftdy - madydivma * ft) * imahalf;
   /* lp_build_rho with explicit derivatives, no_rho_opt: size times
    * derivative, squared, s + t, the larger of x and y */
   const float fw = (float)t->level[t->first_level].width;
   const float fh = (float)t->level[t->first_level].height;
   float a = fw * dsdx, b = fh * dtdx, c = fw * dsdy, d = fh * dtdy;
   a = a * a;
   b = b * b;
   c = c * c;
   d = d * d;
   const float rx = a + b, ry = c + d;
   const float rho = rx > ry ? rx : ry;
   /* explicit derivatives only: an infinite or NaN rho (a coordinate
    * divided by q = 0) becomes 0, a magnified level 0 (lp_build_rho's
    * lp_build_is_inf_or_nan select; the implicit 1D/2D/3D rho keeps its
    * NaN, which minifies) */
   return (r_f2u(rho) & 0x7f800000u) == 0x7f800000u ? 0.0f : rho;
}

void r_tex_sample_cube(const struct r_texture *t, const float c[3], const float q4[4][3],
                       unsigned pos, const float (*p4)[3], float out[4])
{
   const int axis = major_axis(c);
   const float ma = c[axis];
   const uint32_t sign = r_f2u(ma) & SIGN;
   const int face = 2 * axis + (int)(sign >> 31);
   float fs, ft;
   face_minor(axis, sign, c, &fs, &ft);
   /* the projection: |0.5 * (1/ma)| with derivatives, else 0.5 / |ma|
    * (the same value) but 0 for ma = 0 (lp_build_cube_imapos) */
   const bool need_derivs =
      (t->min_img != t->mag_img || t->mip != R_MIP_NONE) && !t->min_max_lod_equal;
   const float ama = fabsf(ma);
   const float imahalfpos = need_derivs ? fabsf(0.5f * (1.0f / ma))
                            : ama > 0.0f ? 0.5f / ama : 0.0f;
   const float fc[3] = { fs * imahalfpos + 0.5f, ft * imahalfpos + 0.5f, 0.0f };
   struct r_texture ft_face;
   memcpy(&ft_face, t, offsetof(struct r_texture, cube));
   ft_face.cube = R_CUBE_FACE;
   ft_face.soa = t->face_soa;
   for (int l = t->first_level; l <= t->last_level; l++) {
      ft_face.level[l].data = t->cube_data[face][l];
      ft_face.level[l].store = t->cube_store[face][l];
   }
   float q[3][3], p[3][3];
   if (t->mip == R_MIP_NONE) {
      /* one LOD per quad, its top-left pixel's (the other quad's too) */
      deriv_form(q4, 0, q);
      if (p4)
         deriv_form(p4, 0, p);
      r_tex_sample(&ft_face, fc, (const float (*)[3])q, p4 ? (const float (*)[3])p : NULL,
                   out);
      return;
   }
   /* a LOD per pixel */
   deriv_form(q4, pos, q);
   if (!(t->float_path && t->min_img != t->mag_img)) {
      r_tex_sample(&ft_face, fc, (const float (*)[3])q, NULL, out);
      return;
   }
   /* min != mag with a LOD per pixel: the float path (use_aos needs
    * num_lods <= num_quads), linear filtering when any of the 8 pixels
    * needs it (lp_build_sample_general) */
   float others[7][3][3];
   const float (*op[7])[3];
   int n = 0;
   for (unsigned i = 0; i < 4; i++) {
      if (i != pos) {
         deriv_form(q4, i, others[n]);
         op[n] = (const float (*)[3])others[n];
         n++;
      }
   }
   for (unsigned i = 0; p4 && i < 4; i++) {
      deriv_form(p4, i, others[n]);
      op[n] = (const float (*)[3])others[n];
      n++;
   }
   r_tex_sample_float_lods(&ft_face, fc, (const float (*)[3])q, op, n, out);
}
