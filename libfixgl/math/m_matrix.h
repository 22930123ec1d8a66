/*
 * Mesa-exact float matrix arithmetic.
 *
 * Every builder reproduces the oracle's CPU code (ORACLE-NOTES.md "Vertex
 * transformation", its matrix builders): the same float operations in the same
 * order, so that the model-view-projection product handed to the vertex
 * stage is bit-identical.  Matrices are column-major (OpenGL layout):
 * element (row r, column c) is m[c*4 + r].
 *
 * Each matrix carries Mesa's geometry flags.  They matter for the result:
 * an affine×affine product uses the 3×4 multiply (no terms for the bottom
 * row), anything else the full 4×4 one, which differs in the sign of zeros
 * and in how Inf/NaN propagate.
 */
#ifndef FGL_M_MATRIX_H
#define FGL_M_MATRIX_H

#include <math.h>
#include <stdbool.h>

enum {
   MAT_FLAG_GENERAL       = 0x1,
   MAT_FLAG_ROTATION      = 0x2,
   MAT_FLAG_TRANSLATION   = 0x4,
   MAT_FLAG_UNIFORM_SCALE = 0x8,
   MAT_FLAG_GENERAL_SCALE = 0x10,
   MAT_FLAG_GENERAL_3D    = 0x20,
   MAT_FLAG_PERSPECTIVE   = 0x40,
   MAT_FLAG_SINGULAR      = 0x80,
   MAT_DIRTY_TYPE         = 0x100,
   MAT_DIRTY_FLAGS        = 0x200,
   MAT_DIRTY_INVERSE      = 0x400,
};

#define MAT_FLAGS_GEOMETRY (MAT_FLAG_GENERAL | MAT_FLAG_ROTATION | \
   MAT_FLAG_TRANSLATION | MAT_FLAG_UNIFORM_SCALE | MAT_FLAG_GENERAL_SCALE | \
   MAT_FLAG_GENERAL_3D | MAT_FLAG_PERSPECTIVE | MAT_FLAG_SINGULAR)
#define MAT_FLAGS_3D (MAT_FLAG_ROTATION | MAT_FLAG_TRANSLATION | \
   MAT_FLAG_UNIFORM_SCALE | MAT_FLAG_GENERAL_SCALE | MAT_FLAG_GENERAL_3D)
#define MAT_DIRTY (MAT_DIRTY_TYPE | MAT_DIRTY_FLAGS | MAT_DIRTY_INVERSE)

typedef struct fgl_matrix {
   float m[16];
   float inv[16];    /* Mesa's inverse for the matrix type (valid after
                      * fgl_matrix_analyse; identity when singular) */
   unsigned flags;   /* MAT_FLAG_* geometry flags and MAT_DIRTY_* */
   bool type_identity;  /* Mesa's type == MATRIX_IDENTITY: set by
                         * fgl_matrix_identity and fgl_matrix_analyse only */
} fgl_matrix;

void fgl_matrix_identity(fgl_matrix *mat);
void fgl_matrix_loadf(fgl_matrix *mat, const float m[16]);
void fgl_matrix_mul_floats(fgl_matrix *mat, const float m[16]);
void fgl_matrix_mul_matrix(fgl_matrix *dest, const fgl_matrix *a, const fgl_matrix *b);
void fgl_matrix_ortho(fgl_matrix *mat, float left, float right, float bottom,
                      float top, float nearval, float farval);
void fgl_matrix_frustum(fgl_matrix *mat, float left, float right, float bottom,
                        float top, float nearval, float farval);
void fgl_matrix_translate(fgl_matrix *mat, float x, float y, float z);
void fgl_matrix_scale(fgl_matrix *mat, float x, float y, float z);
void fgl_matrix_rotate(fgl_matrix *mat, float angle, float x, float y, float z);

/* Recompute the geometry flags and the inverse if they are dirty, as Mesa's
 * _math_matrix_analyse does before the matrix is used; MAT_FLAG_SINGULAR
 * records whether Mesa's inverse for the matrix's type failed. */
void fgl_matrix_analyse(fgl_matrix *mat);

/* True when the product with another 3D matrix may use the 3x4 multiply. */
static inline bool fgl_matrix_is_3d(unsigned flags)
{
   return (MAT_FLAGS_GEOMETRY & ~MAT_FLAGS_3D & flags) == 0;
}

/* _math_matrix_is_length_preserving: only rotations and translations. */
static inline bool fgl_matrix_is_length_preserving(unsigned flags)
{
   return (MAT_FLAGS_GEOMETRY & ~(MAT_FLAG_ROTATION | MAT_FLAG_TRANSLATION) & flags) == 0;
}

/* [S: main/macros.h:NORMALIZE_3FV] left-to-right squared length, one
 * reciprocal square root, no change for a zero vector (the CPU-side
 * normalisations: light state, raster position, evaluator auto-normals). */
static inline void fgl_normalize3(float v[3])
{
   float len = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
   if (len != 0.0f) {
      len = 1.0f / sqrtf(len);
      v[0] *= len;
      v[1] *= len;
      v[2] *= len;
   }
}

/* [S: math/m_matrix.h:TRANSFORM_NORMAL] the row vector n times the 3x3
 * part of the column-major m */
static inline void fgl_transform_normal(float to[3], const float n[3], const float *m)
{
   to[0] = n[0] * m[0] + n[1] * m[1] + n[2] * m[2];
   to[1] = n[0] * m[4] + n[1] * m[5] + n[2] * m[6];
   to[2] = n[0] * m[8] + n[1] * m[9] + n[2] * m[10];
}

#endif
