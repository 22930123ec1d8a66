/*
 * Bezier curves and surfaces, Mesa's code with its float arithmetic and
 * order of operations kept as is (built with -ffp-contract=off, as the
 * oracle's CPU code is) [S: mesa/math/m_eval.c].  Copyright (C) 1999-2005
 * Brian Paul; evaluator code by Bernd Barsuhn, Jorn Hanselmann and
 * Ulrich Wendorf (MIT licence).
 */
#include "math/m_eval.h"
#include "context.h"

/* [S: m_eval.c:_math_init_eval] inv_tab[i] = 1.0F / i */
static float inv_tab[FGL_MAX_EVAL_ORDER] = { 0.0f,
#define INV(i) 1.0f / (float)(i)
   INV(1), INV(2), INV(3), INV(4), INV(5), INV(6), INV(7), INV(8), INV(9),
   INV(10), INV(11), INV(12), INV(13), INV(14), INV(15), INV(16), INV(17),
   INV(18), INV(19), INV(20), INV(21), INV(22), INV(23), INV(24), INV(25),
   INV(26), INV(27), INV(28), INV(29),
#undef INV
};

void fgl_horner_bezier_curve(const float *cp, float *out, float t,
                             unsigned dim, unsigned order)
{
   float s, powert, bincoeff;
   unsigned i, k;

   if (order >= 2) {
      bincoeff = (float) (order - 1);
      s = 1.0F - t;

      for (k = 0; k < dim; k++)
         out[k] = s * cp[k] + bincoeff * t * cp[dim + k];

      for (i = 2, cp += 2 * dim, powert = t * t; i < order;
           i++, powert *= t, cp += dim) {
         bincoeff *= (float) (order - i);
         bincoeff *= inv_tab[i];

         for (k = 0; k < dim; k++)
            out[k] = s * out[k] + bincoeff * powert * cp[k];
      }
   }
   else {                        /* order=1 -> constant curve */

      for (k = 0; k < dim; k++)
         out[k] = cp[k];
   }
}

/*
 * Tensor product Bezier surfaces
 *
 * Again the Horner scheme is used to compute a point on a
 * TP Bezier surface. First a control polygon for a curve
 * on the surface in one parameter direction is computed,
 * then the point on the curve for the other parameter
 * direction is evaluated.
 *
 * To store the curve control polygon additional storage
 * for max(uorder,vorder) points is needed in the
 * control net cn.
 */

void fgl_horner_bezier_surf(float *cn, float *out, float u, float v,
                            unsigned dim, unsigned uorder, unsigned vorder)
{
   float *cp = cn + uorder * vorder * dim;
   unsigned i, uinc = vorder * dim;

   if (vorder > uorder) {
      if (uorder >= 2) {
         float s, poweru, bincoeff;
         unsigned j, k;

         /* Compute the control polygon for the surface-curve in u-direction */
         for (j = 0; j < vorder; j++) {
            float *ucp = &cn[j * dim];

            /* Each control point is the point for parameter u on a */
            /* curve defined by the control polygons in u-direction */
            bincoeff = (float) (uorder - 1);
            s = 1.0F - u;

            for (k = 0; k < dim; k++)
               cp[j * dim + k] = s * ucp[k] + bincoeff * u * ucp[uinc + k];

            for (i = 2, ucp += 2 * uinc, poweru = u * u; i < uorder;
                 i++, poweru *= u, ucp += uinc) {
               bincoeff *= (float) (uorder - i);
               bincoeff *= inv_tab[i];

               for (k = 0; k < dim; k++)
                  cp[j * dim + k] =
                     s * cp[j * dim + k] + bincoeff * poweru * ucp[k];
            }
         }

         /* Evaluate curve point in v */
         fgl_horner_bezier_curve(cp, out, v, dim, vorder);
      }
      else                        /* uorder=1 -> cn defines a curve in v */
         fgl_horner_bezier_curve(cn, out, v, dim, vorder);
   }
   else {                        /* vorder <= uorder */

      if (vorder > 1) {
         unsigned i;

         /* Compute the control polygon for the surface-curve in u-direction */
         for (i = 0; i < uorder; i++, cn += uinc) {
            /* For constant i all cn[i][j] (j=0..vorder) are located */
            /* on consecutive memory locations, so we can use        */
            /* horner_bezier_curve to compute the control points     */

            fgl_horner_bezier_curve(cn, &cp[i * dim], v, dim, vorder);
         }

         /* Evaluate curve point in u */
         fgl_horner_bezier_curve(cp, out, u, dim, uorder);
      }
      else                        /* vorder=1 -> cn defines a curve in u */
         fgl_horner_bezier_curve(cn, out, u, dim, uorder);
   }
}

/*
 * The direct de Casteljau algorithm is used when a point on the
 * surface and the tangent directions spanning the tangent plane
 * should be computed (this is needed to compute normals to the
 * surface). In this case the de Casteljau algorithm approach is
 * nicer because a point and the partial derivatives can be computed
 * at the same time. To get the correct tangent length du and dv
 * must be multiplied with the (u2-u1)/uorder-1 and (v2-v1)/vorder-1.
 * Since only the directions are needed, this scaling step is omitted.
 *
 * De Casteljau needs additional storage for uorder*vorder
 * values in the control net cn.
 */

void fgl_de_casteljau_surf(float *cn, float *out, float *du, float *dv,
                           float u, float v, unsigned dim,
                           unsigned uorder, unsigned vorder)
{
   float *dcn = cn + uorder * vorder * dim;
   float us = 1.0F - u, vs = 1.0F - v;
   unsigned h, i, j, k;
   unsigned minorder = uorder < vorder ? uorder : vorder;
   unsigned uinc = vorder * dim;
   unsigned dcuinc = vorder;

   /* Each component is evaluated separately to save buffer space  */
   /* This does not drasticaly decrease the performance of the     */
   /* algorithm. If additional storage for (uorder-1)*(vorder-1)   */
   /* points would be available, the components could be accessed  */
   /* in the innermost loop which could lead to less cache misses. */

#define CN(I,J,K) cn[(I)*uinc+(J)*dim+(K)]
#define DCN(I, J) dcn[(I)*dcuinc+(J)]
   if (minorder < 3) {
      if (uorder == vorder) {
         for (k = 0; k < dim; k++) {
            /* Derivative direction in u */
            du[k] = vs * (CN(1, 0, k) - CN(0, 0, k)) +
               v * (CN(1, 1, k) - CN(0, 1, k));

            /* Derivative direction in v */
            dv[k] = us * (CN(0, 1, k) - CN(0, 0, k)) +
               u * (CN(1, 1, k) - CN(1, 0, k));

            /* bilinear de Casteljau step */
            out[k] = us * (vs * CN(0, 0, k) + v * CN(0, 1, k)) +
               u * (vs * CN(1, 0, k) + v * CN(1, 1, k));
         }
      }
      else if (minorder == uorder) {
         for (k = 0; k < dim; k++) {
            /* bilinear de Casteljau step */
            DCN(1, 0) = CN(1, 0, k) - CN(0, 0, k);
            DCN(0, 0) = us * CN(0, 0, k) + u * CN(1, 0, k);

            for (j = 0; j < vorder - 1; j++) {
               /* for the derivative in u */
               DCN(1, j + 1) = CN(1, j + 1, k) - CN(0, j + 1, k);
               DCN(1, j) = vs * DCN(1, j) + v * DCN(1, j + 1);

               /* for the `point' */
               DCN(0, j + 1) = us * CN(0, j + 1, k) + u * CN(1, j + 1, k);
               DCN(0, j) = vs * DCN(0, j) + v * DCN(0, j + 1);
            }

            /* remaining linear de Casteljau steps until the second last step */
            for (h = minorder; h < vorder - 1; h++)
               for (j = 0; j < vorder - h; j++) {
                  /* for the derivative in u */
                  DCN(1, j) = vs * DCN(1, j) + v * DCN(1, j + 1);

                  /* for the `point' */
                  DCN(0, j) = vs * DCN(0, j) + v * DCN(0, j + 1);
               }

            /* derivative direction in v */
            dv[k] = DCN(0, 1) - DCN(0, 0);

            /* derivative direction in u */
            du[k] = vs * DCN(1, 0) + v * DCN(1, 1);

            /* last linear de Casteljau step */
            out[k] = vs * DCN(0, 0) + v * DCN(0, 1);
         }
      }
      else {                        /* minorder == vorder */

         for (k = 0; k < dim; k++) {
            /* bilinear de Casteljau step */
            DCN(0, 1) = CN(0, 1, k) - CN(0, 0, k);
            DCN(0, 0) = vs * CN(0, 0, k) + v * CN(0, 1, k);
            for (i = 0; i < uorder - 1; i++) {
               /* for the derivative in v */
               DCN(i + 1, 1) = CN(i + 1, 1, k) - CN(i + 1, 0, k);
               DCN(i, 1) = us * DCN(i, 1) + u * DCN(i + 1, 1);

               /* for the `point' */
               DCN(i + 1, 0) = vs * CN(i + 1, 0, k) + v * CN(i + 1, 1, k);
               DCN(i, 0) = us * DCN(i, 0) + u * DCN(i + 1, 0);
            }

            /* remaining linear de Casteljau steps until the second last step */
            for (h = minorder; h < uorder - 1; h++)
               for (i = 0; i < uorder - h; i++) {
                  /* for the derivative in v */
                  DCN(i, 1) = us * DCN(i, 1) + u * DCN(i + 1, 1);

                  /* for the `point' */
                  DCN(i, 0) = us * DCN(i, 0) + u * DCN(i + 1, 0);
               }

            /* derivative direction in u */
            du[k] = DCN(1, 0) - DCN(0, 0);

            /* derivative direction in v */
            dv[k] = us * DCN(0, 1) + u * DCN(1, 1);

            /* last linear de Casteljau step */
            out[k] = us * DCN(0, 0) + u * DCN(1, 0);
         }
      }
   }
   else if (uorder == vorder) {
      for (k = 0; k < dim; k++) {
         /* first bilinear de Casteljau step */
         for (i = 0; i < uorder - 1; i++) {
            DCN(i, 0) = us * CN(i, 0, k) + u * CN(i + 1, 0, k);
            for (j = 0; j < vorder - 1; j++) {
               DCN(i, j + 1) = us * CN(i, j + 1, k) + u * CN(i + 1, j + 1, k);
               DCN(i, j) = vs * DCN(i, j) + v * DCN(i, j + 1);
            }
         }

         /* remaining bilinear de Casteljau steps until the second last step */
         for (h = 2; h < minorder - 1; h++)
            for (i = 0; i < uorder - h; i++) {
               DCN(i, 0) = us * DCN(i, 0) + u * DCN(i + 1, 0);
               for (j = 0; j < vorder - h; j++) {
                  DCN(i, j + 1) = us * DCN(i, j + 1) + u * DCN(i + 1, j + 1);
                  DCN(i, j) = vs * DCN(i, j) + v * DCN(i, j + 1);
               }
            }

         /* derivative direction in u */
         du[k] = vs * (DCN(1, 0) - DCN(0, 0)) + v * (DCN(1, 1) - DCN(0, 1));

         /* derivative direction in v */
         dv[k] = us * (DCN(0, 1) - DCN(0, 0)) + u * (DCN(1, 1) - DCN(1, 0));

         /* last bilinear de Casteljau step */
         out[k] = us * (vs * DCN(0, 0) + v * DCN(0, 1)) +
            u * (vs * DCN(1, 0) + v * DCN(1, 1));
      }
   }
   else if (minorder == uorder) {
      for (k = 0; k < dim; k++) {
         /* first bilinear de Casteljau step */
         for (i = 0; i < uorder - 1; i++) {
            DCN(i, 0) = us * CN(i, 0, k) + u * CN(i + 1, 0, k);
            for (j = 0; j < vorder - 1; j++) {
               DCN(i, j + 1) = us * CN(i, j + 1, k) + u * CN(i + 1, j + 1, k);
               DCN(i, j) = vs * DCN(i, j) + v * DCN(i, j + 1);
            }
         }

         /* remaining bilinear de Casteljau steps until the second last step */
         for (h = 2; h < minorder - 1; h++)
            for (i = 0; i < uorder - h; i++) {
               DCN(i, 0) = us * DCN(i, 0) + u * DCN(i + 1, 0);
               for (j = 0; j < vorder - h; j++) {
                  DCN(i, j + 1) = us * DCN(i, j + 1) + u * DCN(i + 1, j + 1);
                  DCN(i, j) = vs * DCN(i, j) + v * DCN(i, j + 1);
               }
            }

         /* last bilinear de Casteljau step */
         DCN(2, 0) = DCN(1, 0) - DCN(0, 0);
         DCN(0, 0) = us * DCN(0, 0) + u * DCN(1, 0);
         for (j = 0; j < vorder - 1; j++) {
            /* for the derivative in u */
            DCN(2, j + 1) = DCN(1, j + 1) - DCN(0, j + 1);
            DCN(2, j) = vs * DCN(2, j) + v * DCN(2, j + 1);

            /* for the `point' */
            DCN(0, j + 1) = us * DCN(0, j + 1) + u * DCN(1, j + 1);
            DCN(0, j) = vs * DCN(0, j) + v * DCN(0, j + 1);
         }

         /* remaining linear de Casteljau steps until the second last step */
         for (h = minorder; h < vorder - 1; h++)
            for (j = 0; j < vorder - h; j++) {
               /* for the derivative in u */
               DCN(2, j) = vs * DCN(2, j) + v * DCN(2, j + 1);

               /* for the `point' */
               DCN(0, j) = vs * DCN(0, j) + v * DCN(0, j + 1);
            }

         /* derivative direction in v */
         dv[k] = DCN(0, 1) - DCN(0, 0);

         /* derivative direction in u */
         du[k] = vs * DCN(2, 0) + v * DCN(2, 1);

         /* last linear de Casteljau step */
         out[k] = vs * DCN(0, 0) + v * DCN(0, 1);
      }
   }
   else {                        /* minorder == vorder */

      for (k = 0; k < dim; k++) {
         /* first bilinear de Casteljau step */
         for (i = 0; i < uorder - 1; i++) {
            DCN(i, 0) = us * CN(i, 0, k) + u * CN(i + 1, 0, k);
            for (j = 0; j < vorder - 1; j++) {
               DCN(i, j + 1) = us * CN(i, j + 1, k) + u * CN(i + 1, j + 1, k);
               DCN(i, j) = vs * DCN(i, j) + v * DCN(i, j + 1);
            }
         }

         /* remaining bilinear de Casteljau steps until the second last step */
         for (h = 2; h < minorder - 1; h++)
            for (i = 0; i < uorder - h; i++) {
               DCN(i, 0) = us * DCN(i, 0) + u * DCN(i + 1, 0);
               for (j = 0; j < vorder - h; j++) {
                  DCN(i, j + 1) = us * DCN(i, j + 1) + u * DCN(i + 1, j + 1);
                  DCN(i, j) = vs * DCN(i, j) + v * DCN(i, j + 1);
               }
            }

         /* last bilinear de Casteljau step */
         DCN(0, 2) = DCN(0, 1) - DCN(0, 0);
         DCN(0, 0) = vs * DCN(0, 0) + v * DCN(0, 1);
         for (i = 0; i < uorder - 1; i++) {
            /* for the derivative in v */
            DCN(i + 1, 2) = DCN(i + 1, 1) - DCN(i + 1, 0);
            DCN(i, 2) = us * DCN(i, 2) + u * DCN(i + 1, 2);

            /* for the `point' */
            DCN(i + 1, 0) = vs * DCN(i + 1, 0) + v * DCN(i + 1, 1);
            DCN(i, 0) = us * DCN(i, 0) + u * DCN(i + 1, 0);
         }

         /* remaining linear de Casteljau steps until the second last step */
         for (h = minorder; h < uorder - 1; h++)
            for (i = 0; i < uorder - h; i++) {
               /* for the derivative in v */
               DCN(i, 2) = us * DCN(i, 2) + u * DCN(i + 1, 2);

               /* for the `point' */
               DCN(i, 0) = us * DCN(i, 0) + u * DCN(i + 1, 0);
            }

         /* derivative direction in u */
         du[k] = DCN(1, 0) - DCN(0, 0);

         /* derivative direction in v */
         dv[k] = us * DCN(0, 2) + u * DCN(1, 2);

         /* last linear de Casteljau step */
         out[k] = us * DCN(0, 0) + u * DCN(1, 0);
      }
   }
#undef DCN
#undef CN
}
