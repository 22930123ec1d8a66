/*
 * test_matrix.c - unit tests of math/m_matrix.c against hand-computed values.
 *
 * Every expected matrix below was worked out by hand from the builder's
 * float formulas (m_matrix.c, ORACLE-NOTES.md "Vertex transformation")
 * and is written as a
 * literal.  The cases are chosen so that the arithmetic is exact, except
 * for the sine/cosine of 90 and 180 degrees, whose float values are the
 * well-known ones (cosf((float)(pi/2)) = -0x1.777a5cp-25, sinf((float)pi) =
 * -0x1.777a5cp-24), and for the few sums with them and the general-axis
 * rotation, whose rounded results are derived step by step in comments.
 *
 * The expectations (matrices and flags) were also checked once against
 * Mesa 22.3.6's src/mesa/math/m_matrix.c built on its own.
 *
 * Matrices are compared bit for bit, so the sign of every zero is part of
 * the expectation: a zero is +0 unless all the terms that produce it are -0
 * (x*0 is -0 for negative x; -0 + +0 is +0).  Arrays are column-major, as
 * in GL: each line of an expected matrix is one column.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "math/m_matrix.h"

#include "check.h"

/* cosf/sinf of the float nearest to pi/2 and to pi. */
#define COS90 (-0x1.777a5cp-25f)  /* -4.37113883e-08 */
#define SIN180 (-0x1.777a5cp-24f) /* -8.74227766e-08 */

static const float ident[16] = {
   1, 0, 0, 0,
   0, 1, 0, 0,
   0, 0, 1, 0,
   0, 0, 0, 1,
};

static uint32_t bits(float f)
{
   uint32_t u;
   memcpy(&u, &f, sizeof u);
   return u;
}

/* Compares all 16 entries bit for bit and reports each mismatch with its
 * row and column. */
static void check_matrix_at(const char *file, int line, const char *what,
                            const float got[16], const float want[16])
{
   for (int i = 0; i < 16; i++) {
      if (bits(got[i]) != bits(want[i]))
         check_fail(file, line, "%s: m[%d] (row %d, col %d) = %a (%.9g), expected %a (%.9g)",
                    what, i, i % 4, i / 4, (double)got[i], (double)got[i],
                    (double)want[i], (double)want[i]);
   }
}
#define CHECK_MATRIX(what, got, want) check_matrix_at(__FILE__, __LINE__, what, got, want)

#define CHECK_FLAGS(what, got, want)                                          \
   CHECK((got) == (want), "%s: flags 0x%x, expected 0x%x", what,              \
         (unsigned)(got), (unsigned)(want))

/* A fresh matrix as glLoadIdentity leaves a new stack entry. */
static fgl_matrix fresh(void)
{
   fgl_matrix m;
   memset(&m, 0, sizeof m);
   fgl_matrix_identity(&m);
   return m;
}

static void test_identity_and_load(void)
{
   fgl_matrix m;
   for (int i = 0; i < 16; i++)
      m.m[i] = m.inv[i] = (float)(i + 7);
   /* like Mesa's _math_matrix_set_identity: the geometry flags stay, the
    * dirty bits go */
   m.flags = MAT_FLAG_PERSPECTIVE | MAT_FLAG_SINGULAR | MAT_DIRTY;
   fgl_matrix_identity(&m);
   CHECK_MATRIX("identity", m.m, ident);
   /* the inverse is set too (the analysis skips a clean matrix, and the
    * object-space lighting reads the inverse) */
   CHECK_MATRIX("identity inverse", m.inv, ident);
   CHECK_FLAGS("identity keeps geometry flags", m.flags,
               (unsigned)(MAT_FLAG_PERSPECTIVE | MAT_FLAG_SINGULAR));

   const float src[16] = {
      1, 2, 3, 4,   5, 6, 7, 8,   9, 10, 11, 12,   13, 14, 15, 16,
   };
   m.flags = MAT_FLAG_ROTATION;
   fgl_matrix_loadf(&m, src);
   CHECK_MATRIX("loadf", m.m, src);
   CHECK_FLAGS("loadf", m.flags, (unsigned)(MAT_FLAG_GENERAL | MAT_DIRTY));
}

static void test_ortho(void)
{
   /* glOrtho(0, 256, 0, 128, -1, 1), the usual pixel-space projection:
    * 2/256, 2/128, -2/2 on the diagonal, -(256+0)/256 = -1 and
    * -(128+0)/128 = -1 as translation, -(1 + -1)/2 = -0 for z, which the
    * product with the identity (matmul34: 0*-1 + 0*-1 + 1*-0 + 0) turns
    * into +0. */
   fgl_matrix m = fresh();
   fgl_matrix_ortho(&m, 0.0f, 256.0f, 0.0f, 128.0f, -1.0f, 1.0f);
   const float want[16] = {
      0.0078125f, 0, 0, 0,
      0, 0.015625f, 0, 0,
      0, 0, -1, 0,
      -1, -1, 0, 1,
   };
   CHECK_MATRIX("ortho(0,256,0,128,-1,1)", m.m, want);
   CHECK_FLAGS("ortho before analyse", m.flags,
               (unsigned)(MAT_FLAG_GENERAL_SCALE | MAT_FLAG_TRANSLATION |
                          MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE));
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("ortho after analyse", m.flags,
               (unsigned)(MAT_FLAG_GENERAL_SCALE | MAT_FLAG_TRANSLATION));

   /* glOrtho(-2, 2, -1, 1, 1, 3): symmetric, so x/y translation is -0/4
    * and -0/2, +0 after the product; z: -2/2 = -1 and -(3+1)/2 = -2. */
   m = fresh();
   fgl_matrix_ortho(&m, -2.0f, 2.0f, -1.0f, 1.0f, 1.0f, 3.0f);
   const float want2[16] = {
      0.5f, 0, 0, 0,
      0, 1, 0, 0,
      0, 0, -1, 0,
      0, 0, -2, 1,
   };
   CHECK_MATRIX("ortho(-2,2,-1,1,1,3)", m.m, want2);

   /* Applied to a translation, ortho is post-multiplied: T * O.  With
    * T = translate(10, 20, 30): column 3 = T * O's column 3
    * = (1*0 + 10, 1*0 + 20, 1*-2 + 30) = (10, 20, 28). */
   m = fresh();
   fgl_matrix_translate(&m, 10.0f, 20.0f, 30.0f);
   fgl_matrix_ortho(&m, -2.0f, 2.0f, -1.0f, 1.0f, 1.0f, 3.0f);
   const float want3[16] = {
      0.5f, 0, 0, 0,
      0, 1, 0, 0,
      0, 0, -1, 0,
      10, 20, 28, 1,
   };
   CHECK_MATRIX("translate then ortho", m.m, want3);
}

static void test_frustum(void)
{
   /* glFrustum(-1, 1, -1, 1, 1, 3): x = y = 2*1/2 = 1, a = b = 0/2 = 0,
    * c = -(3+1)/(3-1) = -2, d = -(2*3*1)/2 = -3. */
   fgl_matrix m = fresh();
   fgl_matrix_frustum(&m, -1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 3.0f);
   const float want[16] = {
      1, 0, 0, 0,
      0, 1, 0, 0,
      0, 0, -2, -1,
      0, 0, -3, 0,
   };
   CHECK_MATRIX("frustum(-1,1,-1,1,1,3)", m.m, want);
   CHECK_FLAGS("frustum before analyse", m.flags,
               (unsigned)(MAT_FLAG_PERSPECTIVE | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE));
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("frustum after analyse", m.flags, (unsigned)MAT_FLAG_PERSPECTIVE);

   /* Off-centre glFrustum(0, 2, 0, 4, 2, 6): x = 4/2 = 2, y = 4/4 = 1,
    * a = 2/2 = 1 at (row 0, col 2), b = 4/4 = 1 at (row 1, col 2),
    * c = -8/4 = -2, d = -(2*6*2)/4 = -6. */
   m = fresh();
   fgl_matrix_frustum(&m, 0.0f, 2.0f, 0.0f, 4.0f, 2.0f, 6.0f);
   const float want2[16] = {
      2, 0, 0, 0,
      0, 1, 0, 0,
      1, 1, -2, -1,
      0, 0, -6, 0,
   };
   CHECK_MATRIX("frustum(0,2,0,4,2,6)", m.m, want2);
}

static void test_translate_scale(void)
{
   fgl_matrix m = fresh();
   fgl_matrix_translate(&m, 3.0f, -4.0f, 0.5f);
   const float want[16] = {
      1, 0, 0, 0,
      0, 1, 0, 0,
      0, 0, 1, 0,
      3, -4, 0.5f, 1,
   };
   CHECK_MATRIX("translate(3,-4,0.5)", m.m, want);
   CHECK_FLAGS("translate", m.flags,
               (unsigned)(MAT_FLAG_TRANSLATION | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE));
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("translate after analyse", m.flags, (unsigned)MAT_FLAG_TRANSLATION);

   /* scale then translate: M * T, the translation goes through the scale */
   m = fresh();
   fgl_matrix_scale(&m, 2.0f, 3.0f, 4.0f);
   fgl_matrix_translate(&m, 1.0f, 1.0f, 1.0f);
   const float want2[16] = {
      2, 0, 0, 0,
      0, 3, 0, 0,
      0, 0, 4, 0,
      2, 3, 4, 1,
   };
   CHECK_MATRIX("scale(2,3,4) then translate(1,1,1)", m.m, want2);
   CHECK_FLAGS("scale then translate", m.flags,
               (unsigned)(MAT_FLAG_GENERAL_SCALE | MAT_FLAG_TRANSLATION |
                          MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE));

   /* translate then scale: T * S, the translation is untouched */
   m = fresh();
   fgl_matrix_translate(&m, 1.0f, 1.0f, 1.0f);
   fgl_matrix_scale(&m, 2.0f, 3.0f, 4.0f);
   const float want3[16] = {
      2, 0, 0, 0,
      0, 3, 0, 0,
      0, 0, 4, 0,
      1, 1, 1, 1,
   };
   CHECK_MATRIX("translate(1,1,1) then scale(2,3,4)", m.m, want3);

   /* glScale multiplies whole columns: a negative factor turns the zeros of
    * its column into -0. */
   m = fresh();
   fgl_matrix_scale(&m, -1.0f, 2.0f, 1.0f);
   const float want4[16] = {
      -1, -0.0f, -0.0f, -0.0f,
      0, 2, 0, 0,
      0, 0, 1, 0,
      0, 0, 0, 1,
   };
   CHECK_MATRIX("scale(-1,2,1)", m.m, want4);
   CHECK_FLAGS("scale(-1,2,1)", m.flags,
               (unsigned)(MAT_FLAG_GENERAL_SCALE | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE));

   m = fresh();
   fgl_matrix_scale(&m, 2.0f, 2.0f, 2.0f);
   CHECK_FLAGS("scale(2,2,2) is uniform", m.flags,
               (unsigned)(MAT_FLAG_UNIFORM_SCALE | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE));
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("scale(2,2,2) after analyse", m.flags, (unsigned)MAT_FLAG_UNIFORM_SCALE);

   /* a zero scale is singular (3D without rotation: a zero diagonal entry) */
   m = fresh();
   fgl_matrix_scale(&m, 0.0f, 0.0f, 0.0f);
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("scale(0,0,0) after analyse", m.flags,
               (unsigned)(MAT_FLAG_UNIFORM_SCALE | MAT_FLAG_SINGULAR));

   /* m[10] == 1: the 2D test, M(1,1) == 0 is singular */
   m = fresh();
   fgl_matrix_scale(&m, 1.0f, 0.0f, 1.0f);
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("scale(1,0,1) after analyse", m.flags,
               (unsigned)(MAT_FLAG_GENERAL_SCALE | MAT_FLAG_SINGULAR));
}

static void test_rotate(void)
{
   /* 90 degrees about +z: M(0,0) = M(1,1) = c, M(0,1) = -s, M(1,0) = s. */
   fgl_matrix m = fresh();
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 0.0f, 1.0f);
   const float rz[16] = {
      COS90, 1, 0, 0,
      -1, COS90, 0, 0,
      0, 0, 1, 0,
      0, 0, 0, 1,
   };
   CHECK_MATRIX("rotate(90, 0,0,1)", m.m, rz);
   CHECK_FLAGS("rotate", m.flags,
               (unsigned)(MAT_FLAG_ROTATION | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE));
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("rotate after analyse", m.flags, (unsigned)MAT_FLAG_ROTATION);

   /* -z (any length): the signs of s swap */
   m = fresh();
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 0.0f, -3.0f);
   const float rzn[16] = {
      COS90, -1, 0, 0,
      1, COS90, 0, 0,
      0, 0, 1, 0,
      0, 0, 0, 1,
   };
   CHECK_MATRIX("rotate(90, 0,0,-3)", m.m, rzn);

   /* 90 degrees about +y: M(0,2) = s, M(2,0) = -s. */
   m = fresh();
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 1.0f, 0.0f);
   const float ry[16] = {
      COS90, 0, -1, 0,
      0, 1, 0, 0,
      1, 0, COS90, 0,
      0, 0, 0, 1,
   };
   CHECK_MATRIX("rotate(90, 0,1,0)", m.m, ry);

   /* 180 degrees about +x: c = -1, s = SIN180; M(1,2) = -s, M(2,1) = s. */
   m = fresh();
   fgl_matrix_rotate(&m, 180.0f, 1.0f, 0.0f, 0.0f);
   const float rx[16] = {
      1, 0, 0, 0,
      0, -1, SIN180, 0,
      0, -SIN180, -1, 0,
      0, 0, 0, 1,
   };
   CHECK_MATRIX("rotate(180, 1,0,0)", m.m, rx);

   /* The axis-aligned cases have no magnitude test: a tiny x axis still
    * rotates, exactly like (1,0,0). */
   fgl_matrix m2 = fresh();
   m = fresh();
   fgl_matrix_rotate(&m, 180.0f, 1e-5f, 0.0f, 0.0f);
   fgl_matrix_rotate(&m2, 180.0f, 1.0f, 0.0f, 0.0f);
   CHECK_MATRIX("rotate(180, 1e-5,0,0) vs (1,0,0)", m.m, m2.m);

   /* General axis (0, 3, 4): normalised by sqrtf(25) = 5 to (0, 0.6f, 0.8f);
    * one_c = 1 - COS90 rounds to 1.  Then
    *   M(1,1) = 0.6f*0.6f + c = 0.36f + c  -> 0x1.70a3d6p-2 (0.36f - 1 ulp)
    *   M(2,2) = 0.8f*0.8f + c              -> 0x1.47ae14p-1
    *   M(1,2) = M(2,1) = 0.6f*0.8f         -> 0x1.eb852p-2
    *   M(0,1) = -zs = -0.8f, M(1,0) = 0.8f, M(0,2) = 0.6f, M(2,0) = -0.6f. */
   m = fresh();
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 3.0f, 4.0f);
   const float rg[16] = {
      COS90, 0.8f, -0.6f, 0,
      -0.8f, 0x1.70a3d6p-2f, 0x1.eb852p-2f, 0,
      0.6f, 0x1.eb852p-2f, 0x1.47ae14p-1f, 0,
      0, 0, 0, 1,
   };
   CHECK_MATRIX("rotate(90, 0,3,4)", m.m, rg);

   /* Angle 0 through the general path: (1-1)*xx + 1 etc., the identity. */
   m = fresh();
   fgl_matrix_rotate(&m, 0.0f, 1.0f, 1.0f, 0.0f);
   CHECK_MATRIX("rotate(0, 1,1,0)", m.m, ident);
   CHECK_FLAGS("rotate(0, 1,1,0)", m.flags,
               (unsigned)(MAT_FLAG_ROTATION | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE));

   /* A null axis is no rotation at all: matrix and flags untouched. */
   m = fresh();
   fgl_matrix_scale(&m, 2.0f, 3.0f, 4.0f);
   fgl_matrix_analyse(&m);
   const fgl_matrix before = m;
   fgl_matrix_rotate(&m, 45.0f, 0.0f, 0.0f, 0.0f);
   CHECK_MATRIX("rotate(45, 0,0,0)", m.m, before.m);
   CHECK_FLAGS("rotate(45, 0,0,0)", m.flags, before.flags);
   fgl_matrix_rotate(&m, 45.0f, 5e-5f, 5e-5f, 0.0f); /* |axis| <= 1e-4 */
   CHECK_MATRIX("rotate(45, 5e-5,5e-5,0)", m.m, before.m);
   CHECK_FLAGS("rotate(45, 5e-5,5e-5,0)", m.flags, before.flags);

   /* Post-multiplication: translate then rotate keeps the translation;
    * rotate then translate rotates it: R(90 z) * (1, 2, 0) =
    * (c*1 + -1*2, 1*1 + c*2, 0).  c + -2 rounds to -2, but 1 + 2c
    * = 1 - 8.74e-8 is nearer to 1 - 2^-24 than to 1 - 2^-23 or to 1. */
   m = fresh();
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 0.0f, 1.0f);
   fgl_matrix_translate(&m, 1.0f, 2.0f, 0.0f);
   const float rt[16] = {
      COS90, 1, 0, 0,
      -1, COS90, 0, 0,
      0, 0, 1, 0,
      -2, 0x1.fffffep-1f, 0, 1,
   };
   CHECK_MATRIX("rotate(90 z) then translate(1,2,0)", m.m, rt);

   m = fresh();
   fgl_matrix_translate(&m, 1.0f, 2.0f, 0.0f);
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 0.0f, 1.0f);
   const float tr[16] = {
      COS90, 1, 0, 0,
      -1, COS90, 0, 0,
      0, 0, 1, 0,
      1, 2, 0, 1,
   };
   CHECK_MATRIX("translate(1,2,0) then rotate(90 z)", m.m, tr);
}

/* A(r,c) = 4c + r + 1: column-major 1..16. */
static const float mat_a[16] = {
   1, 2, 3, 4,   5, 6, 7, 8,   9, 10, 11, 12,   13, 14, 15, 16,
};
/* B: one non-zero per row and column: B(0,1) = 1, B(1,2) = 2, B(2,3) = 3,
 * B(3,0) = 4. */
static const float mat_b[16] = {
   0, 0, 0, 4,
   1, 0, 0, 0,
   0, 2, 0, 0,
   0, 0, 3, 0,
};
/* A*B: column c of the product is A * column c of B,
 * col 0 = 4*A.col3, col 1 = A.col0, col 2 = 2*A.col1, col 3 = 3*A.col2. */
static const float mat_ab[16] = {
   52, 56, 60, 64,
   1, 2, 3, 4,
   10, 12, 14, 16,
   27, 30, 33, 36,
};
/* B*A: row r of the product is B's row r times A,
 * row 0 = A.row1, row 1 = 2*A.row2, row 2 = 3*A.row3, row 3 = 4*A.row0. */
static const float mat_ba[16] = {
   2, 6, 12, 4,
   6, 14, 24, 20,
   10, 22, 36, 36,
   14, 30, 48, 52,
};

static void test_multiply(void)
{
   fgl_matrix a, b, d;
   memset(&a, 0, sizeof a);
   memset(&b, 0, sizeof b);
   memset(&d, 0, sizeof d);
   fgl_matrix_loadf(&a, mat_a);
   fgl_matrix_loadf(&b, mat_b);

   fgl_matrix_mul_matrix(&d, &a, &b);
   CHECK_MATRIX("mul_matrix(A, B)", d.m, mat_ab);
   CHECK_FLAGS("mul_matrix flags", d.flags,
               (unsigned)(MAT_FLAG_GENERAL | MAT_DIRTY));
   fgl_matrix_mul_matrix(&d, &b, &a);
   CHECK_MATRIX("mul_matrix(B, A)", d.m, mat_ba);

   /* glMultMatrix post-multiplies the current matrix */
   fgl_matrix_mul_floats(&a, mat_b);
   CHECK_MATRIX("A.mul_floats(B)", a.m, mat_ab);
   CHECK_FLAGS("mul_floats flags", a.flags, (unsigned)(MAT_FLAG_GENERAL | MAT_DIRTY));

   fgl_matrix_loadf(&a, mat_a);
   fgl_matrix_loadf(&b, mat_b);
   fgl_matrix_mul_floats(&b, mat_a);
   CHECK_MATRIX("B.mul_floats(A)", b.m, mat_ba);

   /* Affine x affine uses the 3x4 product: the bottom row is set to
    * (0,0,0,1) and no term of a's column 3 is multiplied by b's bottom
    * row.  With an infinite translation in a, the full product computes
    * a(0,3) * b(3,0) = inf * 0 = NaN in m[0]; the 3x4 one does not. */
   fgl_matrix r = fresh();
   fgl_matrix_rotate(&r, 90.0f, 0.0f, 0.0f, 1.0f);
   a = fresh();
   a.m[12] = INFINITY;
   a.flags = MAT_FLAG_TRANSLATION;
   fgl_matrix_mul_matrix(&d, &a, &r);
   CHECK(bits(d.m[0]) == bits(COS90), "affine product: m[0] = %a, expected %a",
         (double)d.m[0], (double)COS90);
   CHECK(bits(d.m[15]) == bits(1.0f), "affine product: m[15] = %a, expected 1",
         (double)d.m[15]);
   CHECK(isinf(d.m[12]) && d.m[12] > 0.0f, "affine product: m[12] = %a, expected inf",
         (double)d.m[12]);
   CHECK_FLAGS("affine product flags", d.flags,
               (unsigned)(MAT_FLAG_TRANSLATION | MAT_FLAG_ROTATION |
                          MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE));
   CHECK(fgl_matrix_is_3d(d.flags), "affine product flags 0x%x should be 3D",
         (unsigned)d.flags);

   a.flags = MAT_FLAG_PERSPECTIVE;
   fgl_matrix_mul_matrix(&d, &a, &r);
   CHECK(isnan(d.m[0]), "general product: m[0] = %a, expected NaN (inf * 0)",
         (double)d.m[0]);
   CHECK(!fgl_matrix_is_3d(d.flags), "general product flags 0x%x should not be 3D",
         (unsigned)d.flags);

   /* The same choice inside the builders: a stale PERSPECTIVE flag left by
    * glLoadIdentity (the geometry flags survive it) makes glRotate use the
    * full product. */
   a = fresh();
   a.m[12] = INFINITY;
   fgl_matrix_rotate(&a, 90.0f, 0.0f, 0.0f, 1.0f);
   CHECK(bits(a.m[0]) == bits(COS90), "rotate on affine: m[0] = %a, expected %a",
         (double)a.m[0], (double)COS90);
   a.flags = MAT_FLAG_PERSPECTIVE;
   fgl_matrix_identity(&a);
   a.m[12] = INFINITY;
   fgl_matrix_rotate(&a, 90.0f, 0.0f, 0.0f, 1.0f);
   CHECK(isnan(a.m[0]), "rotate after a stale perspective flag: m[0] = %a, expected NaN",
         (double)a.m[0]);
}

/* analyse from scratch (after loadf): geometry flags and singularity. */
static void check_analysis_at(int line, const char *what, const float src[16], unsigned want)
{
   fgl_matrix m;
   memset(&m, 0, sizeof m);
   fgl_matrix_loadf(&m, src);
   fgl_matrix_analyse(&m);
   if (m.flags != want)
      check_fail(__FILE__, line, "analyse %s: flags 0x%x, expected 0x%x", what,
                 m.flags, want);
}
#define CHECK_ANALYSIS(what, src, want) check_analysis_at(__LINE__, what, src, want)

static void test_analyse(void)
{
   CHECK_ANALYSIS("identity", ident, 0u);

   const float t3[16] = { 1, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0,  3, 4, 5, 1 };
   CHECK_ANALYSIS("3D translation", t3, (unsigned)MAT_FLAG_TRANSLATION);
   const float t2[16] = { 1, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0,  3, 4, 0, 1 };
   CHECK_ANALYSIS("2D translation", t2, (unsigned)MAT_FLAG_TRANSLATION);

   const float s3[16] = { 2, 0, 0, 0,  0, 3, 0, 0,  0, 0, 4, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("3D general scale", s3, (unsigned)MAT_FLAG_GENERAL_SCALE);
   const float su[16] = { 2, 0, 0, 0,  0, 2, 0, 0,  0, 0, 2, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("uniform scale", su, (unsigned)MAT_FLAG_UNIFORM_SCALE);
   const float s2[16] = { 2, 0, 0, 0,  0, 2, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("2D scale", s2, (unsigned)MAT_FLAG_GENERAL_SCALE);
   const float s2sing[16] = { 1, 0, 0, 0,  0, 0, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("2D singular scale", s2sing,
                  (unsigned)(MAT_FLAG_GENERAL_SCALE | MAT_FLAG_SINGULAR));

   /* 2D rotation by 90 degrees: columns (0,1), (-1,0) are unit and
    * orthogonal */
   const float r2[16] = { 0, 1, 0, 0,  -1, 0, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("2D rotation", r2, (unsigned)MAT_FLAG_ROTATION);
   /* 3D rotation by 90 about x: col0 x col1 = (1,0,0) x (0,0,1) = (0,-1,0)
    * = col2 */
   const float r3[16] = { 1, 0, 0, 0,  0, 0, 1, 0,  0, -1, 0, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("3D rotation", r3, (unsigned)MAT_FLAG_ROTATION);
   /* rotation about x with cos = 0.6f, sin = 0.8f: |col1|^2 = 0.6f^2 + 0.8f^2
    * is 1 within 1e-6, col0 x col1 = (0, -0.8f, 0.6f) = col2 */
   const float rx68[16] = { 1, 0, 0, 0,  0, 0.6f, 0.8f, 0,  0, -0.8f, 0.6f, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("3D rotation (0.6, 0.8)", rx68, (unsigned)MAT_FLAG_ROTATION);
   /* the same with col2 negated: col0 x col1 - col2 = (0, -1.6f, 1.2f) */
   const float rx68m[16] = { 1, 0, 0, 0,  0, 0.6f, 0.8f, 0,  0, 0.8f, -0.6f, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("3D reflection (0.6, 0.8)", rx68m, (unsigned)MAT_FLAG_GENERAL_3D);
   /* swapping x and z is orthonormal, but col0 x col1 = (0,0,1) x (0,1,0)
    * = (-1,0,0) = -col2: not a rotation */
   const float swap_xz[16] = { 0, 0, 1, 0,  0, 1, 0, 0,  1, 0, 0, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("3D reflection", swap_xz, (unsigned)MAT_FLAG_GENERAL_3D);
   /* swapping x and y has z untouched, so it takes the 2D test, which only
    * checks that the columns are unit and orthogonal (Mesa has no
    * handedness test there) */
   const float swap_xy[16] = { 0, 1, 0, 0,  1, 0, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("2D reflection", swap_xy, (unsigned)MAT_FLAG_ROTATION);
   /* 2D shear x += y: |col1|^2 = 2, col0.col1 = 1 */
   const float shear[16] = { 1, 0, 0, 0,  1, 1, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("2D shear", shear,
                  (unsigned)(MAT_FLAG_GENERAL_SCALE | MAT_FLAG_GENERAL_3D));
   /* col1 = col0: the 3x3 determinant's six products sum to 0 */
   const float dup[16] = { 1, 0, 0, 0,  1, 0, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("2D with equal columns", dup,
                  (unsigned)(MAT_FLAG_GENERAL_3D | MAT_FLAG_SINGULAR));

   /* perspective (m[11] = -1, m[15] = 0): the determinant is
    * M(0,0) M(1,1) M(2,3), so M(2,3) = 0 is singular; M(2,3) = m[14] also
    * counts as a translation */
   const float persp[16] = { 1, 0, 0, 0,  0, 1, 0, 0,  0, 0, -2, -1,  0, 0, -3, 0 };
   CHECK_ANALYSIS("perspective", persp,
                  (unsigned)(MAT_FLAG_GENERAL | MAT_FLAG_TRANSLATION));
   const float persp0[16] = { 1, 0, 0, 0,  0, 1, 0, 0,  0, 0, -2, -1,  0, 0, 0, 0 };
   CHECK_ANALYSIS("perspective with M(2,3) = 0", persp0,
                  (unsigned)(MAT_FLAG_GENERAL | MAT_FLAG_SINGULAR));

   /* general: projective in x (bottom row (1,0,0,1)), determinant 1 */
   const float gen[16] = { 1, 0, 0, 1,  0, 1, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1 };
   CHECK_ANALYSIS("general", gen, (unsigned)MAT_FLAG_GENERAL);
   CHECK_ANALYSIS("general singular (1..16)", mat_a,
                  (unsigned)(MAT_FLAG_GENERAL | MAT_FLAG_TRANSLATION | MAT_FLAG_SINGULAR));
   /* B is a 4-cycle permutation times diag(1,2,3,4): determinant -24;
    * m[14] = 3 is a translation */
   CHECK_ANALYSIS("general (B)", mat_b,
                  (unsigned)(MAT_FLAG_GENERAL | MAT_FLAG_TRANSLATION));

   /* From flags (after builders): rotation then a zero uniform scale is
    * singular through the uniform-scale test, rotation then a singular
    * general scale through the 3x3 determinant. */
   fgl_matrix m = fresh();
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 0.0f, 1.0f);
   fgl_matrix_scale(&m, 0.0f, 0.0f, 0.0f);
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("rotate, scale(0,0,0)", m.flags,
               (unsigned)(MAT_FLAG_ROTATION | MAT_FLAG_UNIFORM_SCALE | MAT_FLAG_SINGULAR));

   m = fresh();
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 0.0f, 1.0f);
   fgl_matrix_scale(&m, 2.0f, 0.0f, 1.0f);
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("rotate, scale(2,0,1)", m.flags,
               (unsigned)(MAT_FLAG_ROTATION | MAT_FLAG_GENERAL_SCALE | MAT_FLAG_SINGULAR));

   m = fresh();
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 0.0f, 1.0f);
   fgl_matrix_scale(&m, 2.0f, 3.0f, 1.0f);
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("rotate, scale(2,3,1)", m.flags,
               (unsigned)(MAT_FLAG_ROTATION | MAT_FLAG_GENERAL_SCALE));

   /* Nothing dirty: analyse leaves the flags alone, even stale ones. */
   m = fresh();
   m.flags = MAT_FLAG_PERSPECTIVE;
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("clean matrix", m.flags, (unsigned)MAT_FLAG_PERSPECTIVE);
}

static const float identity16[16] = { 1, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1 };

/* Inverses as Mesa computes them per matrix type (values and the singular
 * flag checked against Mesa 22.3.6's m_matrix.c built alone). */
static void test_inverse(void)
{
   /* pure translation: negated translation */
   fgl_matrix m = fresh();
   fgl_matrix_translate(&m, 1.0f, -2.0f, 4.0f);
   fgl_matrix_analyse(&m);
   const float want_t[16] = { 1, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0,  -1, 2, -4, 1 };
   CHECK_MATRIX("inverse of translate(1,-2,4)", m.inv, want_t);

   /* rotation by 90 degrees about z: the transpose */
   m = fresh();
   fgl_matrix_rotate(&m, 90.0f, 0.0f, 0.0f, 1.0f);
   fgl_matrix_analyse(&m);
   for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++)
         CHECK(m.inv[j * 4 + i] == m.m[i * 4 + j], "rotate inverse (%d,%d) = %a, want %a",
               i, j, (double)m.inv[j * 4 + i], (double)m.m[i * 4 + j]);

   /* scale without rotation: reciprocal diagonal, 1/3 in float */
   m = fresh();
   fgl_matrix_scale(&m, 2.0f, 4.0f, 3.0f);
   fgl_matrix_analyse(&m);
   CHECK(m.inv[0] == 0.5f && m.inv[5] == 0.25f && m.inv[10] == 1.0f / 3.0f && m.inv[15] == 1.0f,
         "scale inverse diagonal %a %a %a", (double)m.inv[0], (double)m.inv[5], (double)m.inv[10]);

   /* Perspective-type matrices use the general (pivoting) inverse: this one
    * has a zero pivot, so it is singular and its inverse is the identity. */
   const float persp[16] = { 0, 0, 0, 0,  0, 1, 0, 0,  0, 0, -2, -1,  0, 0, -3, 0 };
   m = fresh();
   fgl_matrix_loadf(&m, persp);
   fgl_matrix_analyse(&m);
   CHECK_FLAGS("singular perspective (Mesa: 0x85)", m.flags, 0x85u);
   CHECK_MATRIX("identity inverse of a singular matrix", m.inv, identity16);

   /* A general matrix with determinant 0 whose elimination leaves a rounding
    * residue instead of an exact zero pivot: Mesa calls it invertible. */
   const float gen[16] = { 3, -1, -1, -1,  1, -1, -2, -3,  -1, -1, 0, 1,  0, 1, 1, 1 };
   m = fresh();
   fgl_matrix_loadf(&m, gen);
   fgl_matrix_analyse(&m);
   CHECK(!(m.flags & MAT_FLAG_SINGULAR), "near-singular general matrix: flags 0x%x", m.flags);

   /* A tiny diagonal: the cofactor determinant underflows, the pivots do not. */
   const float tiny[16] = { 1e-12f, 0, 0, 0,  0, 1e-12f, 0, 0,  0, 0, 1e-12f, 0,  0, 0, 0, 1e-12f };
   m = fresh();
   fgl_matrix_loadf(&m, tiny);
   fgl_matrix_analyse(&m);
   CHECK(!(m.flags & MAT_FLAG_SINGULAR), "tiny diagonal: flags 0x%x", m.flags);
   CHECK(m.inv[0] == 1.0f / 1e-12f, "tiny diagonal inverse %a", (double)m.inv[0]);
}

int main(void)
{
   test_identity_and_load();
   test_ortho();
   test_frustum();
   test_translate_scale();
   test_rotate();
   test_multiply();
   test_analyse();
   test_inverse();
   return check_report("unit-matrix");
}
