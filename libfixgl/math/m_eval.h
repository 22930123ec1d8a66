/*
 * Mesa-exact Bezier evaluation [S: mesa/math/m_eval.c]: the float
 * arithmetic and order of operations of Mesa's evaluators.
 */
#ifndef FGL_M_EVAL_H
#define FGL_M_EVAL_H

/* _math_horner_bezier_curve: the point for parameter t on the curve of
 * order control points of dim floats each */
void fgl_horner_bezier_curve(const float *cp, float *out, float t,
                             unsigned dim, unsigned order);

/* _math_horner_bezier_surf: cn holds uorder x vorder points of dim floats
 * and room for max(uorder, vorder) more (scratch) */
void fgl_horner_bezier_surf(float *cn, float *out, float u, float v,
                            unsigned dim, unsigned uorder, unsigned vorder);

/* _math_de_casteljau_surf: the point and the partial derivative
 * directions du, dv; cn has room for uorder * vorder scratch values */
void fgl_de_casteljau_surf(float *cn, float *out, float *du, float *dv,
                           float u, float v, unsigned dim,
                           unsigned uorder, unsigned vorder);

#endif
