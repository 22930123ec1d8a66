/*
 * Evaluators (GL_EVAL_BIT): glMap1/glMap2, glGetMap, glMapGrid,
 * glEvalCoord, glEvalPoint, glEvalMesh and the GL_MAPn_* / GL_AUTO_NORMAL
 * enables.  [S: mesa/main/eval.c] for the map state and its errors,
 * [S: vbo/vbo_exec_eval.c, vbo/vbo_exec_api.c] for how an evaluated point
 * becomes vertex attributes and a glVertex, [S: main/draw.c:
 * _mesa_EvalMesh1, _mesa_EvalMesh2] for the meshes, and
 * [S: math/m_eval.c] (math/m_eval.c) for the arithmetic.
 *
 * Which maps the oracle evaluates [S: vbo_exec_eval.c:vbo_exec_eval_update]:
 * COLOR_4, the highest enabled TEXTURE_COORD_n, NORMAL and VERTEX_4 over
 * VERTEX_3.  GL_MAPn_INDEX maps are stored and queried but never
 * evaluated (vbo_exec_eval_update has no line for them).  The highest
 * enabled texture-coordinate map sets unit 0's coordinate (FGL_ATTR_TEX0,
 * eval/texcoord_maps).
 */
#include <math.h>
#include <string.h>

#include "main/groups.h"
#include "main/dlist.h"
#include "math/m_eval.h"
#include "tnl/t_vbo.h"

/* _mesa_evaluator_components, by target - GL_MAPn_COLOR_4 */
static const unsigned eval_components[FGL_EVAL_TARGETS] = {
   4,    /* COLOR_4 */
   1,    /* INDEX */
   3,    /* NORMAL */
   1, 2, 3, 4,   /* TEXTURE_COORD_1..4 */
   3,    /* VERTEX_3 */
   4,    /* VERTEX_4 */
};

enum {
   EV_COLOR4, EV_INDEX, EV_NORMAL, EV_TEX1, EV_TEX2, EV_TEX3, EV_TEX4,
   EV_VERTEX3, EV_VERTEX4,
};

/* index of a GL_MAP1_* target, or -1 */
static int map1_index(GLenum target)
{
   return target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4 ?
          (int)(target - GL_MAP1_COLOR_4) : -1;
}

static int map2_index(GLenum target)
{
   return target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4 ?
          (int)(target - GL_MAP2_COLOR_4) : -1;
}

unsigned fgl_eval_components(GLenum target)
{
   int t = map1_index(target);
   if (t < 0)
      t = map2_index(target);
   return t < 0 ? 0 : eval_components[t];
}

bool *fgl_eval_cap_flag(struct fgl_context *ctx, GLenum cap)
{
   int i;
   if (cap == GL_AUTO_NORMAL)
      return &ctx->EvalMap.AutoNormal;
   if ((i = map1_index(cap)) >= 0)
      return &ctx->EvalMap.Map1Enabled[i];
   if ((i = map2_index(cap)) >= 0)
      return &ctx->EvalMap.Map2Enabled[i];
   return NULL;
}

/* [S: main/eval.c:_mesa_init_eval] order 1 over [0, 1], one point each */
void fgl_init_eval(struct fgl_context *ctx)
{
   static const float initial[FGL_EVAL_TARGETS][4] = {
      { 1.0f, 1.0f, 1.0f, 1.0f },    /* color */
      { 1.0f },                      /* index */
      { 0.0f, 0.0f, 1.0f },          /* normal */
      { 0.0f, 0.0f, 0.0f, 1.0f },    /* texcoord */
      { 0.0f, 0.0f, 0.0f, 1.0f },
      { 0.0f, 0.0f, 0.0f, 1.0f },
      { 0.0f, 0.0f, 0.0f, 1.0f },
      { 0.0f, 0.0f, 0.0f, 1.0f },    /* vertex */
      { 0.0f, 0.0f, 0.0f, 1.0f },
   };
   struct fgl_eval_maps *em = &ctx->EvalMap;
   memset(em, 0, sizeof(*em));
   for (int t = 0; t < FGL_EVAL_TARGETS; t++) {
      struct fgl_eval_map1 *m1 = &em->Map1[t];
      struct fgl_eval_map2 *m2 = &em->Map2[t];
      m1->Order = 1;
      m1->u1 = 0.0f;
      m1->u2 = 1.0f;
      m2->Uorder = m2->Vorder = 1;
      m2->u1 = m2->v1 = 0.0f;
      m2->u2 = m2->v2 = 1.0f;
      /* du/dv stay 0: _mesa_init_eval does not set them (nothing reads
       * them before a glMap sets them, as the map has to be enabled and
       * evaluated with its du) */
      for (unsigned k = 0; k < eval_components[t]; k++)
         m1->Points[k] = m2->Points[k] = initial[t][k];
   }
   /* MapGrid1du, MapGrid2du and MapGrid2dv stay 0 as well: Mesa's context
    * is calloc'ed and only glMapGrid sets them, so a glEvalMesh before any
    * glMapGrid steps by 0 */
}

/* ---- glMap1, glMap2 ---- */

/* map1 [S: main/eval.c:map1]; points are floats or doubles */
static void map1(struct fgl_context *ctx, GLenum target, GLfloat u1, GLfloat u2,
                 GLint ustride, GLint uorder, const GLfloat *pf, const GLdouble *pd)
{
   /* not in Mesa's begin/end dispatch table */
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (u1 == u2) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (uorder < 1 || uorder > FGL_MAX_EVAL_ORDER) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (!pf && !pd) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   /* _mesa_evaluator_components knows the GL_MAP2_* targets too: they
    * fail only after the stride and active texture checks (get_1d_map) */
   const int k = (int)fgl_eval_components(target);
   if (k == 0) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (ustride < k) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (ctx->Texture.CurrentUnit != 0) {
      /* OpenGL 1.2.1 spec, F.2.13 */
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   const int t = map1_index(target);
   if (t < 0) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   struct fgl_eval_map1 *map = &ctx->EvalMap.Map1[t];
   /* _mesa_copy_map_points1{f,d}: packed, doubles cast to float */
   float *p = map->Points;
   for (int i = 0; i < uorder; i++) {
      for (int c = 0; c < k; c++)
         *p++ = pf ? pf[(size_t)i * ustride + c] : (float)pd[(size_t)i * ustride + c];
   }
   map->Order = uorder;
   map->u1 = u1;
   map->u2 = u2;
   map->du = 1.0f / (u2 - u1);
}

/* map2 [S: main/eval.c:map2] */
static void map2(struct fgl_context *ctx, GLenum target, GLfloat u1, GLfloat u2,
                 GLint ustride, GLint uorder, GLfloat v1, GLfloat v2, GLint vstride,
                 GLint vorder, const GLfloat *pf, const GLdouble *pd)
{
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (u1 == u2 || v1 == v2) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (uorder < 1 || uorder > FGL_MAX_EVAL_ORDER ||
       vorder < 1 || vorder > FGL_MAX_EVAL_ORDER) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   /* map2 does not check points: _mesa_copy_map_points2* return NULL
    * and the map keeps no points (glGetMap GL_COEFF then writes nothing;
    * evaluating it would crash the oracle) */
   const int k = (int)fgl_eval_components(target);
   if (k == 0) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (ustride < k || vstride < k) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   if (ctx->Texture.CurrentUnit != 0) {
      fgl_error(ctx, GL_INVALID_OPERATION);
      return;
   }
   const int t = map2_index(target);
   if (t < 0) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   struct fgl_eval_map2 *map = &ctx->EvalMap.Map2[t];
   map->NoPoints = !pf && !pd;
   if (pf || pd) {
      /* _mesa_copy_map_points2{f,d}: u-major, then v, packed */
      float *p = map->Points;
      for (int i = 0; i < uorder; i++) {
         for (int j = 0; j < vorder; j++) {
            const size_t o = (size_t)i * ustride + (size_t)j * vstride;
            for (int c = 0; c < k; c++)
               *p++ = pf ? pf[o + c] : (float)pd[o + c];
         }
      }
   }
   map->Uorder = uorder;
   map->u1 = u1;
   map->u2 = u2;
   map->du = 1.0f / (u2 - u1);
   map->Vorder = vorder;
   map->v1 = v1;
   map->v2 = v2;
   map->dv = 1.0f / (v2 - v1);
}

void GLAPIENTRY glMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride,
                        GLint order, const GLfloat *points)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag &&
       !fgl_save_map1(ctx, target, u1, u2, stride, order, points, NULL))
      return;
   map1(ctx, target, u1, u2, stride, order, points, NULL);
}

void GLAPIENTRY glMap1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride,
                        GLint order, const GLdouble *points)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag &&
       !fgl_save_map1(ctx, target, (GLfloat)u1, (GLfloat)u2, stride, order, NULL, points))
      return;
   map1(ctx, target, (GLfloat)u1, (GLfloat)u2, stride, order, NULL, points);
}

void GLAPIENTRY glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride,
                        GLint uorder, GLfloat v1, GLfloat v2, GLint vstride,
                        GLint vorder, const GLfloat *points)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag &&
       !fgl_save_map2(ctx, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder,
                      points, NULL))
      return;
   map2(ctx, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points, NULL);
}

void GLAPIENTRY glMap2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride,
                        GLint uorder, GLdouble v1, GLdouble v2, GLint vstride,
                        GLint vorder, const GLdouble *points)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   const GLfloat fu1 = (GLfloat)u1, fu2 = (GLfloat)u2;
   const GLfloat fv1 = (GLfloat)v1, fv2 = (GLfloat)v2;
   if (ctx->CompileFlag &&
       !fgl_save_map2(ctx, target, fu1, fu2, ustride, uorder, fv1, fv2, vstride, vorder,
                      NULL, points))
      return;
   map2(ctx, target, fu1, fu2, ustride, uorder, fv1, fv2, vstride, vorder, NULL, points);
}

/* ---- glGetMap ---- */

enum get_type { GET_F, GET_D, GET_I };

/* _mesa_GetnMap{f,d,i}vARB with bufSize INT_MAX */
static void get_map(GLenum target, GLenum query, void *out, enum get_type type)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   /* executed at once while compiling; outside begin/end only */
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   const int t1 = map1_index(target), t2 = map2_index(target);
   if (t1 < 0 && t2 < 0) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   const struct fgl_eval_map1 *m1 = t1 >= 0 ? &ctx->EvalMap.Map1[t1] : NULL;
   const struct fgl_eval_map2 *m2 = t2 >= 0 ? &ctx->EvalMap.Map2[t2] : NULL;
   const unsigned comps = eval_components[t1 >= 0 ? t1 : t2];
   float v[FGL_MAX_EVAL_ORDER * FGL_MAX_EVAL_ORDER * 4];
   const float *data = v;
   unsigned n;
   bool integer_rounded = false;   /* lroundf for glGetMapiv */

   switch (query) {
   case GL_COEFF:
      if (m1) {
         data = m1->Points;
         n = (unsigned)m1->Order * comps;
      } else {
         data = m2->Points;
         /* no points (glMap2 with NULL): nothing written */
         n = m2->NoPoints ? 0 : (unsigned)(m2->Uorder * m2->Vorder) * comps;
      }
      integer_rounded = true;
      break;
   case GL_ORDER:
      if (m1) {
         v[0] = (float)m1->Order;
         n = 1;
      } else {
         v[0] = (float)m2->Uorder;
         v[1] = (float)m2->Vorder;
         n = 2;
      }
      break;
   case GL_DOMAIN:
      if (m1) {
         v[0] = m1->u1;
         v[1] = m1->u2;
         n = 2;
      } else {
         v[0] = m2->u1;
         v[1] = m2->u2;
         v[2] = m2->v1;
         v[3] = m2->v2;
         n = 4;
      }
      integer_rounded = true;
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   for (unsigned i = 0; i < n; i++) {
      switch (type) {
      case GET_F:
         ((GLfloat *)out)[i] = data[i];
         break;
      case GET_D:
         ((GLdouble *)out)[i] = (GLdouble)data[i];
         break;
      case GET_I:
         /* orders are ints; coefficients and domains lroundf */
         ((GLint *)out)[i] = integer_rounded ? (GLint)lroundf(data[i]) : (GLint)data[i];
         break;
      }
   }
}

void GLAPIENTRY glGetMapfv(GLenum target, GLenum query, GLfloat *v)
{
   get_map(target, query, v, GET_F);
}

void GLAPIENTRY glGetMapdv(GLenum target, GLenum query, GLdouble *v)
{
   get_map(target, query, v, GET_D);
}

void GLAPIENTRY glGetMapiv(GLenum target, GLenum query, GLint *v)
{
   get_map(target, query, v, GET_I);
}

/* ---- glMapGrid ---- */

void GLAPIENTRY glMapGrid1f(GLint un, GLfloat u1, GLfloat u2)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, MapGrid1f, un, u1, u2);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (un < 1) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   ctx->Eval.MapGrid1un = un;
   ctx->Eval.MapGrid1u1 = u1;
   ctx->Eval.MapGrid1u2 = u2;
   ctx->Eval.MapGrid1du = (u2 - u1) / (GLfloat)un;
}

void GLAPIENTRY glMapGrid1d(GLint un, GLdouble u1, GLdouble u2)
{
   glMapGrid1f(un, (GLfloat)u1, (GLfloat)u2);
}

void GLAPIENTRY glMapGrid2f(GLint un, GLfloat u1, GLfloat u2,
                            GLint vn, GLfloat v1, GLfloat v2)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, MapGrid2f, un, u1, u2, vn, v1, v2);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (un < 1 || vn < 1) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   FGL_FLUSH_VERTICES(ctx, 0);
   ctx->Eval.MapGrid2un = un;
   ctx->Eval.MapGrid2u1 = u1;
   ctx->Eval.MapGrid2u2 = u2;
   ctx->Eval.MapGrid2du = (u2 - u1) / (GLfloat)un;
   ctx->Eval.MapGrid2vn = vn;
   ctx->Eval.MapGrid2v1 = v1;
   ctx->Eval.MapGrid2v2 = v2;
   ctx->Eval.MapGrid2dv = (v2 - v1) / (GLfloat)vn;
}

void GLAPIENTRY glMapGrid2d(GLint un, GLdouble u1, GLdouble u2,
                            GLint vn, GLdouble v1, GLdouble v2)
{
   glMapGrid2f(un, (GLfloat)u1, (GLfloat)u2, vn, (GLfloat)v1, (GLfloat)v2);
}

/* ---- evaluation ---- */

/* vbo_exec_eval_update: the attribute each enabled map feeds and the map
 * index, in vbo attribute order (NORMAL, COLOR0, TEX0), as the fixup and
 * evaluation loops of _mesa_EvalCoord and vbo_exec_do_EvalCoord run
 * 1..VBO_ATTRIB_TEX7; the vertex map apart.  TEXTURE_COORD_4 wins over 3,
 * 2 and 1.  GL_MAP*_INDEX is never evaluated (vbo_exec_eval_update has no
 * entry for it). */
struct active_map {
   int attr;
   int index;
};

#define EV_MAX_ACTIVE 3

static unsigned active_maps(const bool *enabled, struct active_map out[EV_MAX_ACTIVE],
                            int *vertex)
{
   unsigned n = 0;
   if (enabled[EV_NORMAL])
      out[n++] = (struct active_map){ FGL_ATTR_NORMAL, EV_NORMAL };
   if (enabled[EV_COLOR4])
      out[n++] = (struct active_map){ FGL_ATTR_COLOR0, EV_COLOR4 };
   for (int t = EV_TEX4; t >= EV_TEX1; t--) {
      if (enabled[t]) {
         out[n++] = (struct active_map){ FGL_ATTR_TEX0, t };
         break;
      }
   }
   *vertex = enabled[EV_VERTEX4] ? EV_VERTEX4 : enabled[EV_VERTEX3] ? EV_VERTEX3 : -1;
   return n;
}

/* the attributes in vbo attribute order (position first, as the fixup loop
 * of _mesa_EvalCoord runs 0..VBO_ATTRIB_TEX7) */
static void fixup_attrs(struct fgl_context *ctx, const struct active_map *am, unsigned n,
                        int vertex, bool auto_normal)
{
   if (vertex >= 0)
      fgl_vbo_fixup(ctx, FGL_ATTR_POS, eval_components[vertex]);
   for (unsigned i = 0; i < n; i++) {
      const struct active_map *m = &am[i];
      if (ctx->Vbo.active_size[m->attr] != eval_components[m->index])
         fgl_vbo_fixup(ctx, (enum fgl_vbo_attr)m->attr, eval_components[m->index]);
   }
   if (auto_normal && ctx->Vbo.active_size[FGL_ATTR_NORMAL] != 3)
      fgl_vbo_fixup(ctx, FGL_ATTR_NORMAL, 3);
}

/* COPY_SZ_4V into the current vertex's attribute (its format size) */
static void set_attr(struct fgl_context *ctx, int attr, const float data[4])
{
   float *cur = ctx->Vbo.current[attr];
   const unsigned sz = ctx->Vbo.attr_size[attr];
   for (unsigned i = 0; i < sz && i < 4; i++)
      cur[i] = data[i];
}

/* _mesa_EvalCoord1f + vbo_exec_do_EvalCoord1f: the maps' values replace
 * the current vertex's attributes for one glVertex, then the vertex's
 * attribute values are restored (the memcpy of exec->vtx.vertex) */
static void eval_coord1(struct fgl_context *ctx, GLfloat u)
{
   struct fgl_eval_maps *em = &ctx->EvalMap;
   struct active_map am[EV_MAX_ACTIVE];
   int vertex;
   const unsigned n = active_maps(em->Map1Enabled, am, &vertex);

   if (vertex < 0 && n == 0)
      return;
   fixup_attrs(ctx, am, n, vertex, false);

   float saved[FGL_ATTR_COUNT][4];
   memcpy(saved, ctx->Vbo.current, sizeof(saved));

   for (unsigned i = 0; i < n; i++) {
      const struct fgl_eval_map1 *map = &em->Map1[am[i].index];
      const float uu = (u - map->u1) * map->du;
      float data[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
      fgl_horner_bezier_curve(map->Points, data, uu, eval_components[am[i].index],
                              (unsigned)map->Order);
      set_attr(ctx, am[i].attr, data);
   }
   /* the vertex: EvalCoord1f is a no-op without a vertex map */
   if (vertex >= 0) {
      const struct fgl_eval_map1 *map = &em->Map1[vertex];
      const float uu = (u - map->u1) * map->du;
      float v[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
      const unsigned sz = eval_components[vertex];
      fgl_horner_bezier_curve(map->Points, v, uu, sz, (unsigned)map->Order);
      /* CALL_Vertex*fv(ctx->CurrentServerDispatch): while a list is
       * compiled (GL_COMPILE_AND_EXECUTE) the vertex is compiled too */
      fgl_attr(ctx, FGL_ATTR_POS, sz, v[0], v[1], v[2], v[3]);
   }
   memcpy(ctx->Vbo.current, saved, sizeof(saved));
}

/* _mesa_EvalCoord2f + vbo_exec_do_EvalCoord2f */
static void eval_coord2(struct fgl_context *ctx, GLfloat u, GLfloat v)
{
   struct fgl_eval_maps *em = &ctx->EvalMap;
   struct active_map am[EV_MAX_ACTIVE];
   int vertex;
   const unsigned n = active_maps(em->Map2Enabled, am, &vertex);

   if (vertex < 0 && n == 0 && !em->AutoNormal)
      return;
   fixup_attrs(ctx, am, n, vertex, em->AutoNormal);

   float saved[FGL_ATTR_COUNT][4];
   memcpy(saved, ctx->Vbo.current, sizeof(saved));

   for (unsigned i = 0; i < n; i++) {
      struct fgl_eval_map2 *map = &em->Map2[am[i].index];
      const float uu = (u - map->u1) * map->du;
      const float vv = (v - map->v1) * map->dv;
      float data[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
      fgl_horner_bezier_surf(map->Points, data, uu, vv, eval_components[am[i].index],
                             (unsigned)map->Uorder, (unsigned)map->Vorder);
      set_attr(ctx, am[i].attr, data);
   }
   if (vertex >= 0) {
      struct fgl_eval_map2 *map = &em->Map2[vertex];
      const float uu = (u - map->u1) * map->du;
      const float vv = (v - map->v1) * map->dv;
      const unsigned sz = eval_components[vertex];
      float p[4] = { 0.0f, 0.0f, 0.0f, 1.0f };

      if (em->AutoNormal) {
         float du[4], dv[4], normal[4];
         fgl_de_casteljau_surf(map->Points, p, du, dv, uu, vv, sz,
                               (unsigned)map->Uorder, (unsigned)map->Vorder);
         if (sz == 4) {
            /* the derivatives of the projected (rational) surface, up to
             * a positive factor */
            du[0] = du[0] * p[3] - du[3] * p[0];
            du[1] = du[1] * p[3] - du[3] * p[1];
            du[2] = du[2] * p[3] - du[3] * p[2];

            dv[0] = dv[0] * p[3] - dv[3] * p[0];
            dv[1] = dv[1] * p[3] - dv[3] * p[1];
            dv[2] = dv[2] * p[3] - dv[3] * p[2];
         }
         /* CROSS3, NORMALIZE_3FV [S: main/macros.h] */
         normal[0] = du[1] * dv[2] - du[2] * dv[1];
         normal[1] = du[2] * dv[0] - du[0] * dv[2];
         normal[2] = du[0] * dv[1] - du[1] * dv[0];
         fgl_normalize3(normal);
         normal[3] = 1.0f;
         set_attr(ctx, FGL_ATTR_NORMAL, normal);
      } else {
         fgl_horner_bezier_surf(map->Points, p, uu, vv, sz,
                                (unsigned)map->Uorder, (unsigned)map->Vorder);
      }
      /* Vertex4fv when the position's format size is 4, else Vertex3fv */
      const unsigned psz = ctx->Vbo.attr_size[FGL_ATTR_POS] == 4 ? 4 : 3;
      fgl_attr(ctx, FGL_ATTR_POS, psz, p[0], p[1], p[2], psz == 4 ? p[3] : 1.0f);
   }
   memcpy(ctx->Vbo.current, saved, sizeof(saved));
}

void GLAPIENTRY glEvalCoord1f(GLfloat u)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag && !fgl_save_eval_coord1(ctx, u))
      return;
   eval_coord1(ctx, u);
}

void GLAPIENTRY glEvalCoord1fv(const GLfloat *u)
{
   glEvalCoord1f(u[0]);
}

void GLAPIENTRY glEvalCoord1d(GLdouble u)
{
   glEvalCoord1f((GLfloat)u);
}

void GLAPIENTRY glEvalCoord1dv(const GLdouble *u)
{
   glEvalCoord1f((GLfloat)u[0]);
}

void GLAPIENTRY glEvalCoord2f(GLfloat u, GLfloat v)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag && !fgl_save_eval_coord2(ctx, u, v))
      return;
   eval_coord2(ctx, u, v);
}

void GLAPIENTRY glEvalCoord2fv(const GLfloat *u)
{
   glEvalCoord2f(u[0], u[1]);
}

void GLAPIENTRY glEvalCoord2d(GLdouble u, GLdouble v)
{
   glEvalCoord2f((GLfloat)u, (GLfloat)v);
}

void GLAPIENTRY glEvalCoord2dv(const GLdouble *u)
{
   glEvalCoord2f((GLfloat)u[0], (GLfloat)u[1]);
}

/* [S: vbo_exec_api.c:_mesa_EvalPoint1]: du from the grid each time */
void GLAPIENTRY glEvalPoint1(GLint i)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag && !fgl_save_eval_point1(ctx, i))
      return;
   const GLfloat du = (ctx->Eval.MapGrid1u2 - ctx->Eval.MapGrid1u1) /
                      (GLfloat)ctx->Eval.MapGrid1un;
   const GLfloat u = i * du + ctx->Eval.MapGrid1u1;
   eval_coord1(ctx, u);
}

void GLAPIENTRY glEvalPoint2(GLint i, GLint j)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag && !fgl_save_eval_point2(ctx, i, j))
      return;
   const GLfloat du = (ctx->Eval.MapGrid2u2 - ctx->Eval.MapGrid2u1) /
                      (GLfloat)ctx->Eval.MapGrid2un;
   const GLfloat dv = (ctx->Eval.MapGrid2v2 - ctx->Eval.MapGrid2v1) /
                      (GLfloat)ctx->Eval.MapGrid2vn;
   const GLfloat u = i * du + ctx->Eval.MapGrid2u1;
   const GLfloat v = j * dv + ctx->Eval.MapGrid2v1;
   eval_coord2(ctx, u, v);
}

/* [S: main/draw.c:_mesa_EvalMesh1]: u = u1 + i1 * du, then u += du */
void GLAPIENTRY glEvalMesh1(GLenum mode, GLint i1, GLint i2)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, EvalMesh1, mode, i1, i2);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   GLenum prim;
   switch (mode) {
   case GL_POINT:
      prim = GL_POINTS;
      break;
   case GL_LINE:
      prim = GL_LINE_STRIP;
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (!ctx->EvalMap.Map1Enabled[EV_VERTEX4] && !ctx->EvalMap.Map1Enabled[EV_VERTEX3])
      return;
   const GLfloat du = ctx->Eval.MapGrid1du;
   GLfloat u = ctx->Eval.MapGrid1u1 + i1 * du;
   /* CALL_Begin/EvalCoord1f/End(ctx->CurrentServerDispatch): the entry
    * points, which compile them as well under GL_COMPILE_AND_EXECUTE */
   glBegin(prim);
   for (GLint i = i1; i <= i2; i++, u += du)
      glEvalCoord1f(u);
   glEnd();
}

/* [S: main/draw.c:_mesa_EvalMesh2]: points in one GL_POINTS, lines as a
 * GL_LINE_STRIP per row then per column, fill as a GL_TRIANGLE_STRIP per
 * row of (u, v), (u, v + dv); through the entry points, as for
 * glEvalMesh1 */
void GLAPIENTRY glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, EvalMesh2, mode, i1, i2, j1, j2);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   switch (mode) {
   case GL_POINT:
   case GL_LINE:
   case GL_FILL:
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (!ctx->EvalMap.Map2Enabled[EV_VERTEX4] && !ctx->EvalMap.Map2Enabled[EV_VERTEX3])
      return;
   const GLfloat du = ctx->Eval.MapGrid2du;
   const GLfloat dv = ctx->Eval.MapGrid2dv;
   const GLfloat v1 = ctx->Eval.MapGrid2v1 + j1 * dv;
   const GLfloat u1 = ctx->Eval.MapGrid2u1 + i1 * du;
   GLfloat u, v;
   GLint i, j;

   switch (mode) {
   case GL_POINT:
      glBegin(GL_POINTS);
      for (v = v1, j = j1; j <= j2; j++, v += dv)
         for (u = u1, i = i1; i <= i2; i++, u += du)
            glEvalCoord2f(u, v);
      glEnd();
      break;
   case GL_LINE:
      for (v = v1, j = j1; j <= j2; j++, v += dv) {
         glBegin(GL_LINE_STRIP);
         for (u = u1, i = i1; i <= i2; i++, u += du)
            glEvalCoord2f(u, v);
         glEnd();
      }
      for (u = u1, i = i1; i <= i2; i++, u += du) {
         glBegin(GL_LINE_STRIP);
         for (v = v1, j = j1; j <= j2; j++, v += dv)
            glEvalCoord2f(u, v);
         glEnd();
      }
      break;
   default:
      for (v = v1, j = j1; j < j2; j++, v += dv) {
         glBegin(GL_TRIANGLE_STRIP);
         for (u = u1, i = i1; i <= i2; i++, u += du) {
            glEvalCoord2f(u, v);
            glEvalCoord2f(u, v + dv);
         }
         glEnd();
      }
      break;
   }
}
