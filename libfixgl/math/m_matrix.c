/*
 * Mesa-exact float matrix arithmetic (see m_matrix.h).
 *
 * Reproduces Mesa 22.3's src/mesa/math/m_matrix.c: the builders, the 3x4
 * and 4x4 products with their left-to-right sums, and the matrix analysis
 * that decides which product is used.  Order of operations is part of the
 * contract (ORACLE-NOTES.md "Vertex transformation"); the file is built
 * with -ffp-contract=off.
 */
#include "m_matrix.h"

#include <math.h>
#include <string.h>

#define M(row, col) m[(col) * 4 + (row)]

static const float identity[16] = {
   1, 0, 0, 0,
   0, 1, 0, 0,
   0, 0, 1, 0,
   0, 0, 0, 1,
};

/* Mesa's matrix types, used to pick the inverse that decides singularity. */
enum mat_type {
   MATRIX_GENERAL, MATRIX_IDENTITY, MATRIX_3D_NO_ROT, MATRIX_PERSPECTIVE,
   MATRIX_2D, MATRIX_2D_NO_ROT, MATRIX_3D,
};

/* product = a * b, full 4x4 (matmul4).  product may alias a. */
static void matmul4(float *product, const float *a, const float *b)
{
   for (int i = 0; i < 4; i++) {
      const float ai0 = a[i], ai1 = a[4 + i], ai2 = a[8 + i], ai3 = a[12 + i];
      product[i]      = ai0 * b[0]  + ai1 * b[1]  + ai2 * b[2]  + ai3 * b[3];
      product[4 + i]  = ai0 * b[4]  + ai1 * b[5]  + ai2 * b[6]  + ai3 * b[7];
      product[8 + i]  = ai0 * b[8]  + ai1 * b[9]  + ai2 * b[10] + ai3 * b[11];
      product[12 + i] = ai0 * b[12] + ai1 * b[13] + ai2 * b[14] + ai3 * b[15];
   }
}

/* product = a * b for affine a and b (matmul34): the bottom row is not
 * computed but set to (0,0,0,1).  product may alias a. */
static void matmul34(float *product, const float *a, const float *b)
{
   for (int i = 0; i < 3; i++) {
      const float ai0 = a[i], ai1 = a[4 + i], ai2 = a[8 + i], ai3 = a[12 + i];
      product[i]      = ai0 * b[0]  + ai1 * b[1]  + ai2 * b[2];
      product[4 + i]  = ai0 * b[4]  + ai1 * b[5]  + ai2 * b[6];
      product[8 + i]  = ai0 * b[8]  + ai1 * b[9]  + ai2 * b[10];
      product[12 + i] = ai0 * b[12] + ai1 * b[13] + ai2 * b[14] + ai3;
   }
   product[3] = 0.0f;
   product[7] = 0.0f;
   product[11] = 0.0f;
   product[15] = 1.0f;
}

/* Mesa's matrix_multf: post-multiply by m, which has the given flags. */
static void matrix_multf(fgl_matrix *mat, const float *m, unsigned flags)
{
   mat->flags |= flags | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE;
   if (fgl_matrix_is_3d(mat->flags))
      matmul34(mat->m, mat->m, m);
   else
      matmul4(mat->m, mat->m, m);
}

void fgl_matrix_identity(fgl_matrix *mat)
{
   /* Like _math_matrix_set_identity, the geometry flags are left alone: only
    * the dirty bits are cleared (the type becomes "identity"); the inverse is
    * the identity too. */
   memcpy(mat->m, identity, sizeof(identity));
   memcpy(mat->inv, identity, sizeof(identity));
   mat->flags &= ~(MAT_DIRTY_FLAGS | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE);
   mat->type_identity = true;
}

void fgl_matrix_loadf(fgl_matrix *mat, const float m[16])
{
   memcpy(mat->m, m, 16 * sizeof(float));
   mat->flags = MAT_FLAG_GENERAL | MAT_DIRTY;
}

void fgl_matrix_mul_floats(fgl_matrix *mat, const float m[16])
{
   mat->flags |= MAT_FLAG_GENERAL | MAT_DIRTY;
   matmul4(mat->m, mat->m, m);
}

void fgl_matrix_mul_matrix(fgl_matrix *dest, const fgl_matrix *a, const fgl_matrix *b)
{
   dest->flags = a->flags | b->flags | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE;
   if (fgl_matrix_is_3d(dest->flags))
      matmul34(dest->m, a->m, b->m);
   else
      matmul4(dest->m, a->m, b->m);
}

void fgl_matrix_ortho(fgl_matrix *mat, float left, float right, float bottom,
                      float top, float nearval, float farval)
{
   float m[16];
   M(0, 0) = 2.0f / (right - left);
   M(0, 1) = 0.0f;
   M(0, 2) = 0.0f;
   M(0, 3) = -(right + left) / (right - left);
   M(1, 0) = 0.0f;
   M(1, 1) = 2.0f / (top - bottom);
   M(1, 2) = 0.0f;
   M(1, 3) = -(top + bottom) / (top - bottom);
   M(2, 0) = 0.0f;
   M(2, 1) = 0.0f;
   M(2, 2) = -2.0f / (farval - nearval);
   M(2, 3) = -(farval + nearval) / (farval - nearval);
   M(3, 0) = 0.0f;
   M(3, 1) = 0.0f;
   M(3, 2) = 0.0f;
   M(3, 3) = 1.0f;
   matrix_multf(mat, m, MAT_FLAG_GENERAL_SCALE | MAT_FLAG_TRANSLATION);
}

void fgl_matrix_frustum(fgl_matrix *mat, float left, float right, float bottom,
                        float top, float nearval, float farval)
{
   float m[16];
   const float x = (2.0f * nearval) / (right - left);
   const float y = (2.0f * nearval) / (top - bottom);
   const float a = (right + left) / (right - left);
   const float b = (top + bottom) / (top - bottom);
   const float c = -(farval + nearval) / (farval - nearval);
   const float d = -(2.0f * farval * nearval) / (farval - nearval);
   M(0, 0) = x;    M(0, 1) = 0.0f; M(0, 2) = a;     M(0, 3) = 0.0f;
   M(1, 0) = 0.0f; M(1, 1) = y;    M(1, 2) = b;     M(1, 3) = 0.0f;
   M(2, 0) = 0.0f; M(2, 1) = 0.0f; M(2, 2) = c;     M(2, 3) = d;
   M(3, 0) = 0.0f; M(3, 1) = 0.0f; M(3, 2) = -1.0f; M(3, 3) = 0.0f;
   matrix_multf(mat, m, MAT_FLAG_PERSPECTIVE);
}

void fgl_matrix_translate(fgl_matrix *mat, float x, float y, float z)
{
   float *m = mat->m;
   m[12] = m[0] * x + m[4] * y + m[8]  * z + m[12];
   m[13] = m[1] * x + m[5] * y + m[9]  * z + m[13];
   m[14] = m[2] * x + m[6] * y + m[10] * z + m[14];
   m[15] = m[3] * x + m[7] * y + m[11] * z + m[15];
   mat->flags |= MAT_FLAG_TRANSLATION | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE;
}

void fgl_matrix_scale(fgl_matrix *mat, float x, float y, float z)
{
   float *m = mat->m;
   m[0] *= x;   m[4] *= y;   m[8]  *= z;
   m[1] *= x;   m[5] *= y;   m[9]  *= z;
   m[2] *= x;   m[6] *= y;   m[10] *= z;
   m[3] *= x;   m[7] *= y;   m[11] *= z;
   if (fabsf(x - y) < 1e-8f && fabsf(x - z) < 1e-8f)
      mat->flags |= MAT_FLAG_UNIFORM_SCALE;
   else
      mat->flags |= MAT_FLAG_GENERAL_SCALE;
   mat->flags |= MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE;
}

void fgl_matrix_rotate(fgl_matrix *mat, float angle, float x, float y, float z)
{
   /* sin/cos of the angle converted in double, evaluated in float. */
   const float s = sinf((float)(angle * M_PI / 180.0));
   const float c = cosf((float)(angle * M_PI / 180.0));
   float m[16];
   bool optimized = false;

   memcpy(m, identity, sizeof(m));

   /* Rotations about a coordinate axis are filled in directly. */
   if (x == 0.0f) {
      if (y == 0.0f) {
         if (z != 0.0f) {
            optimized = true;
            M(0, 0) = c;
            M(1, 1) = c;
            if (z < 0.0f) { M(0, 1) = s;  M(1, 0) = -s; }
            else          { M(0, 1) = -s; M(1, 0) = s; }
         }
      } else if (z == 0.0f) {
         optimized = true;
         M(0, 0) = c;
         M(2, 2) = c;
         if (y < 0.0f) { M(0, 2) = -s; M(2, 0) = s; }
         else          { M(0, 2) = s;  M(2, 0) = -s; }
      }
   } else if (y == 0.0f) {
      if (z == 0.0f) {
         optimized = true;
         M(1, 1) = c;
         M(2, 2) = c;
         if (x < 0.0f) { M(1, 2) = s;  M(2, 1) = -s; }
         else          { M(1, 2) = -s; M(2, 1) = s; }
      }
   }

   if (!optimized) {
      const float mag = sqrtf(x * x + y * y + z * z);
      if (mag <= 1.0e-4f)
         return; /* no rotation, the matrix is left as it is */
      x /= mag;
      y /= mag;
      z /= mag;
      const float xx = x * x, yy = y * y, zz = z * z;
      const float xy = x * y, yz = y * z, zx = z * x;
      const float xs = x * s, ys = y * s, zs = z * s;
      const float one_c = 1.0f - c;
      M(0, 0) = (one_c * xx) + c;
      M(0, 1) = (one_c * xy) - zs;
      M(0, 2) = (one_c * zx) + ys;
      M(1, 0) = (one_c * xy) + zs;
      M(1, 1) = (one_c * yy) + c;
      M(1, 2) = (one_c * yz) - xs;
      M(2, 0) = (one_c * zx) - ys;
      M(2, 1) = (one_c * yz) + xs;
      M(2, 2) = (one_c * zz) + c;
   }
   matrix_multf(mat, m, MAT_FLAG_ROTATION);
}

/* ---- analysis (Mesa's analyse_from_scratch / analyse_from_flags) ---- */

#define ZERO(x) (1u << (x))
#define ONE(x)  (1u << ((x) + 16))

#define MASK_NO_TRX      (ZERO(12) | ZERO(13) | ZERO(14))
#define MASK_NO_2D_SCALE (ONE(0) | ONE(5))
#define MASK_IDENTITY    (ONE(0) | ZERO(4) | ZERO(8) | ZERO(12) | \
                          ZERO(1) | ONE(5) | ZERO(9) | ZERO(13) | \
                          ZERO(2) | ZERO(6) | ONE(10) | ZERO(14) | \
                          ZERO(3) | ZERO(7) | ZERO(11) | ONE(15))
#define MASK_2D_NO_ROT   (ZERO(4) | ZERO(8) | ZERO(1) | ZERO(9) | \
                          ZERO(2) | ZERO(6) | ONE(10) | ZERO(14) | \
                          ZERO(3) | ZERO(7) | ZERO(11) | ONE(15))
#define MASK_2D          (ZERO(8) | ZERO(9) | ZERO(2) | ZERO(6) | \
                          ONE(10) | ZERO(14) | ZERO(3) | ZERO(7) | \
                          ZERO(11) | ONE(15))
#define MASK_3D_NO_ROT   (ZERO(4) | ZERO(8) | ZERO(1) | ZERO(9) | \
                          ZERO(2) | ZERO(6) | ZERO(3) | ZERO(7) | \
                          ZERO(11) | ONE(15))
#define MASK_3D          (ZERO(3) | ZERO(7) | ZERO(11) | ONE(15))
#define MASK_PERSPECTIVE (ZERO(4) | ZERO(12) | ZERO(1) | ZERO(13) | \
                          ZERO(2) | ZERO(6) | ZERO(3) | ZERO(7) | ZERO(15))

#define SQ(x) ((x) * (x))

static enum mat_type analyse_from_scratch(fgl_matrix *mat)
{
   const float *m = mat->m;
   unsigned mask = 0;
   enum mat_type type;

   for (unsigned i = 0; i < 16; i++)
      if (m[i] == 0.0f)
         mask |= 1u << i;
   if (m[0] == 1.0f)  mask |= 1u << 16;
   if (m[5] == 1.0f)  mask |= 1u << 21;
   if (m[10] == 1.0f) mask |= 1u << 26;
   if (m[15] == 1.0f) mask |= 1u << 31;

   mat->flags &= ~MAT_FLAGS_GEOMETRY;

   if ((mask & MASK_NO_TRX) != MASK_NO_TRX)
      mat->flags |= MAT_FLAG_TRANSLATION;

   if (mask == MASK_IDENTITY) {
      type = MATRIX_IDENTITY;
   } else if ((mask & MASK_2D_NO_ROT) == MASK_2D_NO_ROT) {
      type = MATRIX_2D_NO_ROT;
      if ((mask & MASK_NO_2D_SCALE) != MASK_NO_2D_SCALE)
         mat->flags |= MAT_FLAG_GENERAL_SCALE;
   } else if ((mask & MASK_2D) == MASK_2D) {
      const float mm = m[0] * m[0] + m[1] * m[1];
      const float m4m4 = m[4] * m[4] + m[5] * m[5];
      const float mm4 = m[0] * m[4] + m[1] * m[5];
      type = MATRIX_2D;
      if (SQ(mm - 1) > SQ(1e-6f) || SQ(m4m4 - 1) > SQ(1e-6f))
         mat->flags |= MAT_FLAG_GENERAL_SCALE;
      if (SQ(mm4) > SQ(1e-6f))
         mat->flags |= MAT_FLAG_GENERAL_3D;
      else
         mat->flags |= MAT_FLAG_ROTATION;
   } else if ((mask & MASK_3D_NO_ROT) == MASK_3D_NO_ROT) {
      type = MATRIX_3D_NO_ROT;
      if (SQ(m[0] - m[5]) < SQ(1e-6f) && SQ(m[0] - m[10]) < SQ(1e-6f)) {
         if (SQ(m[0] - 1.0f) > SQ(1e-6f))
            mat->flags |= MAT_FLAG_UNIFORM_SCALE;
      } else {
         mat->flags |= MAT_FLAG_GENERAL_SCALE;
      }
   } else if ((mask & MASK_3D) == MASK_3D) {
      const float c1 = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
      const float c2 = m[4] * m[4] + m[5] * m[5] + m[6] * m[6];
      const float c3 = m[8] * m[8] + m[9] * m[9] + m[10] * m[10];
      const float d1 = m[0] * m[4] + m[1] * m[5] + m[2] * m[6];
      type = MATRIX_3D;
      if (SQ(c1 - c2) < SQ(1e-6f) && SQ(c1 - c3) < SQ(1e-6f)) {
         if (SQ(c1 - 1.0f) > SQ(1e-6f))
            mat->flags |= MAT_FLAG_UNIFORM_SCALE;
      } else {
         mat->flags |= MAT_FLAG_GENERAL_SCALE;
      }
      if (SQ(d1) < SQ(1e-6f)) {
         /* cross(col0, col1) - col2 */
         const float cp0 = m[1] * m[6] - m[2] * m[5] - m[8];
         const float cp1 = m[2] * m[4] - m[0] * m[6] - m[9];
         const float cp2 = m[0] * m[5] - m[1] * m[4] - m[10];
         if (cp0 * cp0 + cp1 * cp1 + cp2 * cp2 < SQ(1e-6f))
            mat->flags |= MAT_FLAG_ROTATION;
         else
            mat->flags |= MAT_FLAG_GENERAL_3D;
      } else {
         mat->flags |= MAT_FLAG_GENERAL_3D;
      }
   } else if ((mask & MASK_PERSPECTIVE) == MASK_PERSPECTIVE && m[11] == -1.0f) {
      type = MATRIX_PERSPECTIVE;
      mat->flags |= MAT_FLAG_GENERAL;
   } else {
      type = MATRIX_GENERAL;
      mat->flags |= MAT_FLAG_GENERAL;
   }
   return type;
}

static bool test_flags(unsigned flags, unsigned allowed)
{
   return (MAT_FLAGS_GEOMETRY & ~allowed & flags) == 0;
}

static enum mat_type analyse_from_flags(const fgl_matrix *mat)
{
   const float *m = mat->m;
   if (test_flags(mat->flags, 0))
      return MATRIX_IDENTITY;
   if (test_flags(mat->flags, MAT_FLAG_TRANSLATION | MAT_FLAG_UNIFORM_SCALE |
                              MAT_FLAG_GENERAL_SCALE))
      return (m[10] == 1.0f && m[14] == 0.0f) ? MATRIX_2D_NO_ROT : MATRIX_3D_NO_ROT;
   if (test_flags(mat->flags, MAT_FLAGS_3D)) {
      if (m[8] == 0.0f && m[9] == 0.0f && m[2] == 0.0f && m[6] == 0.0f &&
          m[10] == 1.0f && m[14] == 0.0f)
         return MATRIX_2D;
      return MATRIX_3D;
   }
   if (m[4] == 0.0f && m[12] == 0.0f && m[1] == 0.0f && m[13] == 0.0f &&
       m[2] == 0.0f && m[6] == 0.0f && m[3] == 0.0f && m[7] == 0.0f &&
       m[11] == -1.0f && m[15] == 0.0f)
      return MATRIX_PERSPECTIVE;
   return MATRIX_GENERAL;
}

/* ---- inverses: Mesa's per-type inversion (m_matrix.c inv_mat_tab) -------
 * Each returns false for a matrix it considers singular; the caller then
 * stores the identity, as Mesa does.  The float operations and their order
 * are the oracle's. */

/* util_invert_mat4x4: Gaussian elimination with partial pivoting on the
 * rows of [M | I]; singular when a pivot is exactly zero. */
static bool invert_general(const float *m, float *out)
{
   float wtmp[4][8];
   float *r[4] = { wtmp[0], wtmp[1], wtmp[2], wtmp[3] };
   float *t;

   for (int i = 0; i < 4; i++) {
      for (int j = 0; j < 4; j++)
         r[i][j] = M(i, j);
      for (int j = 4; j < 8; j++)
         r[i][j] = j - 4 == i ? 1.0f : 0.0f;
   }

#define SWAP(a, b) (t = r[a], r[a] = r[b], r[b] = t)
   /* first variable */
   if (fabsf(r[3][0]) > fabsf(r[2][0])) SWAP(3, 2);
   if (fabsf(r[2][0]) > fabsf(r[1][0])) SWAP(2, 1);
   if (fabsf(r[1][0]) > fabsf(r[0][0])) SWAP(1, 0);
   if (r[0][0] == 0.0f)
      return false;
   float m1 = r[1][0] / r[0][0], m2 = r[2][0] / r[0][0], m3 = r[3][0] / r[0][0];
   for (int j = 1; j < 8; j++) {
      const float s = r[0][j];
      if (j >= 4 && s == 0.0f)
         continue;
      r[1][j] -= m1 * s;
      r[2][j] -= m2 * s;
      r[3][j] -= m3 * s;
   }

   /* second variable */
   if (fabsf(r[3][1]) > fabsf(r[2][1])) SWAP(3, 2);
   if (fabsf(r[2][1]) > fabsf(r[1][1])) SWAP(2, 1);
   if (r[1][1] == 0.0f)
      return false;
   m2 = r[2][1] / r[1][1];
   m3 = r[3][1] / r[1][1];
   for (int j = 2; j < 8; j++) {
      const float s = r[1][j];
      if (j >= 4 && s == 0.0f)
         continue;
      r[2][j] -= m2 * s;
      r[3][j] -= m3 * s;
   }

   /* third variable */
   if (fabsf(r[3][2]) > fabsf(r[2][2])) SWAP(3, 2);
   if (r[2][2] == 0.0f)
      return false;
   m3 = r[3][2] / r[2][2];
   for (int j = 3; j < 8; j++)
      r[3][j] -= m3 * r[2][j];
#undef SWAP

   if (r[3][3] == 0.0f)
      return false;

   /* back substitution */
   float s = 1.0f / r[3][3];
   for (int j = 4; j < 8; j++)
      r[3][j] *= s;

   m2 = r[2][3];
   s = 1.0f / r[2][2];
   for (int j = 4; j < 8; j++)
      r[2][j] = s * (r[2][j] - r[3][j] * m2);
   m1 = r[1][3];
   for (int j = 4; j < 8; j++)
      r[1][j] -= r[3][j] * m1;
   float m0 = r[0][3];
   for (int j = 4; j < 8; j++)
      r[0][j] -= r[3][j] * m0;

   m1 = r[1][2];
   s = 1.0f / r[1][1];
   for (int j = 4; j < 8; j++)
      r[1][j] = s * (r[1][j] - r[2][j] * m1);
   m0 = r[0][2];
   for (int j = 4; j < 8; j++)
      r[0][j] -= r[2][j] * m0;

   m0 = r[0][1];
   s = 1.0f / r[0][0];
   for (int j = 4; j < 8; j++)
      r[0][j] = s * (r[0][j] - r[1][j] * m0);

   for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++)
         out[j * 4 + i] = r[i][4 + j];
   return true;
}

/* The translation column of a 3D inverse: -(R^-1 t). */
static void invert_translation(const float *m, float *out)
{
#define O(row, col) out[(col) * 4 + (row)]
   for (int i = 0; i < 3; i++)
      O(i, 3) = -(M(0, 3) * O(i, 0) + M(1, 3) * O(i, 1) + M(2, 3) * O(i, 2));
}

/* invert_matrix_3d_general: adjugate / determinant of the 3x3 part, the
 * determinant accumulated as positive and negative products. */
static bool invert_3d_general(const float *m, float *out)
{
   float pos = 0.0f, neg = 0.0f, t;
#define ACC(expr) t = (expr); if (t >= 0.0f) pos += t; else neg += t
   ACC(M(0, 0) * M(1, 1) * M(2, 2));
   ACC(M(1, 0) * M(2, 1) * M(0, 2));
   ACC(M(2, 0) * M(0, 1) * M(1, 2));
   ACC(-M(2, 0) * M(1, 1) * M(0, 2));
   ACC(-M(1, 0) * M(0, 1) * M(2, 2));
   ACC(-M(0, 0) * M(2, 1) * M(1, 2));
#undef ACC
   float det = pos + neg;
   if (fabsf(det) < 1e-25f)
      return false;
   det = 1.0f / det;
   O(0, 0) = (  (M(1, 1) * M(2, 2) - M(2, 1) * M(1, 2)) * det);
   O(0, 1) = (- (M(0, 1) * M(2, 2) - M(2, 1) * M(0, 2)) * det);
   O(0, 2) = (  (M(0, 1) * M(1, 2) - M(1, 1) * M(0, 2)) * det);
   O(1, 0) = (- (M(1, 0) * M(2, 2) - M(2, 0) * M(1, 2)) * det);
   O(1, 1) = (  (M(0, 0) * M(2, 2) - M(2, 0) * M(0, 2)) * det);
   O(1, 2) = (- (M(0, 0) * M(1, 2) - M(1, 0) * M(0, 2)) * det);
   O(2, 0) = (  (M(1, 0) * M(2, 1) - M(2, 0) * M(1, 1)) * det);
   O(2, 1) = (- (M(0, 0) * M(2, 1) - M(2, 0) * M(0, 1)) * det);
   O(2, 2) = (  (M(0, 0) * M(1, 1) - M(1, 0) * M(0, 1)) * det);
   invert_translation(m, out);
   return true;
}

/* invert_matrix_3d: angle-preserving matrices by (scaled) transpose. */
static bool invert_3d(const fgl_matrix *mat, float *out)
{
   const float *m = mat->m;
   if (!test_flags(mat->flags, MAT_FLAG_ROTATION | MAT_FLAG_TRANSLATION | MAT_FLAG_UNIFORM_SCALE))
      return invert_3d_general(m, out);

   if (mat->flags & MAT_FLAG_UNIFORM_SCALE) {
      float scale = M(0, 0) * M(0, 0) + M(0, 1) * M(0, 1) + M(0, 2) * M(0, 2);
      if (scale == 0.0f)
         return false;
      scale = 1.0f / scale;
      for (int i = 0; i < 3; i++)
         for (int j = 0; j < 3; j++)
            O(j, i) = scale * M(i, j);
   } else if (mat->flags & MAT_FLAG_ROTATION) {
      for (int i = 0; i < 3; i++)
         for (int j = 0; j < 3; j++)
            O(j, i) = M(i, j);
   } else {
      /* pure translation */
      memcpy(out, identity, sizeof(identity));
      O(0, 3) = -M(0, 3);
      O(1, 3) = -M(1, 3);
      O(2, 3) = -M(2, 3);
      return true;
   }
   if (mat->flags & MAT_FLAG_TRANSLATION)
      invert_translation(m, out);
   else
      O(0, 3) = O(1, 3) = O(2, 3) = 0.0f;
   return true;
}

/* invert_matrix_3d_no_rot and invert_matrix_2d_no_rot */
static bool invert_no_rot(const fgl_matrix *mat, float *out, int dims)
{
   const float *m = mat->m;
   for (int i = 0; i < dims; i++)
      if (M(i, i) == 0)
         return false;
   memcpy(out, identity, sizeof(identity));
   for (int i = 0; i < dims; i++)
      O(i, i) = 1.0f / M(i, i);
   if (mat->flags & MAT_FLAG_TRANSLATION)
      for (int i = 0; i < dims; i++)
         O(i, 3) = -(M(i, 3) * O(i, i));
   return true;
}
#undef O

static bool invert(const fgl_matrix *mat, enum mat_type type, float *out)
{
   switch (type) {
   case MATRIX_IDENTITY:
      memcpy(out, identity, sizeof(identity));
      return true;
   case MATRIX_3D_NO_ROT:
      return invert_no_rot(mat, out, 3);
   case MATRIX_2D_NO_ROT:
      return invert_no_rot(mat, out, 2);
   case MATRIX_2D:
   case MATRIX_3D:
      return invert_3d(mat, out);
   case MATRIX_PERSPECTIVE:   /* Mesa's perspective inverse is disabled */
   case MATRIX_GENERAL:
   default:
      return invert_general(mat->m, out);
   }
}

void fgl_matrix_analyse(fgl_matrix *mat)
{
   if (!(mat->flags & (MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE)))
      return;
   enum mat_type type;
   if (mat->flags & MAT_DIRTY_FLAGS)
      type = analyse_from_scratch(mat);
   else
      type = analyse_from_flags(mat);
   mat->type_identity = type == MATRIX_IDENTITY;
   /* matrix_invert: a singular matrix gets the identity as its inverse */
   if (invert(mat, type, mat->inv)) {
      mat->flags &= ~MAT_FLAG_SINGULAR;
   } else {
      mat->flags |= MAT_FLAG_SINGULAR;
      memcpy(mat->inv, identity, sizeof(identity));
   }
   mat->flags &= ~MAT_DIRTY;
}
