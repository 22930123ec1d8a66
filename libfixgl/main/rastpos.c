/*
 * glRasterPos{2,3,4}{s,i,f,d}[v] (GL_CURRENT_BIT's raster position).
 *
 * [S: state_tracker/st_cb_rasterpos.c:st_RasterPos] With the fixed-function
 * vertex program (no ARB vertex program or shader) the state tracker does
 * not go through the draw module: it calls main/rastpos.c:_mesa_RasterPos,
 * which computes the raster position on the CPU in plain C (x86-64 SSE
 * arithmetic, no fused multiply-adds, every operation rounded to float):
 *
 *   eye  = MV * obj, clip = P * eye     (TRANSFORM_POINT: each row summed
 *                                         left to right, not the MVP product
 *                                         the vertex program uses)
 *   clip test: near z, far z, then x/y (strict comparisons, a point on a
 *   plane is inside), then the user planes (dot in clip space < 0 is
 *   outside); outside: GL_CURRENT_RASTER_POSITION_VALID false, every other
 *   raster value kept
 *   d = 1/clip.w (1 when clip.w == 0), ndc = clip * d,
 *   win = ndc * scale + translate (_mesa_get_viewport_xform, y up),
 *   RasterPos.w = clip.w (not 1/w)
 *   distance: |eye.xyz| (sqrtf of the left-to-right sum of squares), or the
 *   current fog coordinate with GL_FOG_COORDINATE as the fog source
 *   colour: the current colours (lighting: shade_rastpos, see below)
 *   texture coordinates: texture matrix * current coordinate, every unit
 *   in GL_SELECT a valid raster position updates the hit record with its z.
 */
#include <math.h>

#include "main/groups.h"
#include "main/dlist.h"

/* [S: rastpos.c:TRANSFORM_POINT (macros.h)] q = m * p, each row summed
 * left to right, unfused. */
static void transform_point(float q[4], const float *m, const float p[4])
{
   const float p0 = p[0], p1 = p[1], p2 = p[2], p3 = p[3];
   for (int r = 0; r < 4; r++)
      q[r] = m[r] * p0 + m[4 + r] * p1 + m[8 + r] * p2 + m[12 + r] * p3;
}

/* [S: rastpos.c:viewclip_point_near_z, viewclip_point_far_z,
 * viewclip_point_xy, userclip_point] in this order; false when clipped. */
static bool rastpos_inside(const struct fgl_context *ctx, const float clip[4])
{
   if (clip[2] < -clip[3])
      return false;
   if (clip[2] > clip[3])
      return false;
   if (clip[0] > clip[3] || clip[0] < -clip[3] || clip[1] > clip[3] || clip[1] < -clip[3])
      return false;
   unsigned mask = ctx->Transform.ClipPlanesEnabled;
   while (mask) {
      const int p = __builtin_ctz(mask);
      const float *pl = ctx->_ClipUserPlane[p];
      mask &= mask - 1;
      const float dot = clip[0] * pl[0] + clip[1] * pl[1] + clip[2] * pl[2] + clip[3] * pl[3];
      if (dot < 0.0f)
         return false;
   }
   return true;
}

/* [S: feedback.c:_mesa_update_hitflag] */
static void update_hitflag(struct fgl_context *ctx, float z)
{
   struct fgl_selection *s = &ctx->Select;
   s->HitFlag = true;
   if (z < s->HitMinZ)
      s->HitMinZ = z;
   if (z > s->HitMaxZ)
      s->HitMaxZ = z;
}

/* [S: rastpos.c:_mesa_RasterPos] */
static void raster_pos(struct fgl_context *ctx, const float obj[4])
{
   struct fgl_current_attrib *cur = &ctx->Current;
   float eye[4], clip[4];

   ctx->PopAttribState |= GL_CURRENT_BIT;
   transform_point(eye, ctx->ModelviewStack.Top->m, obj);
   transform_point(clip, ctx->ProjectionStack.Top->m, eye);
   if (!rastpos_inside(ctx, clip)) {
      cur->RasterPosValid = false;
      return;
   }

   /* ndc = clip / w; _mesa_get_viewport_xform (y up, the scale and
    * translation of z computed in double) */
   const float d = clip[3] == 0.0f ? 1.0f : 1.0f / clip[3];
   const float ndc[3] = { clip[0] * d, clip[1] * d, clip[2] * d };
   const struct fgl_viewport_attrib *vp = &ctx->Viewport;
   const float half_w = 0.5f * (float)vp->Width, half_h = 0.5f * (float)vp->Height;
   const double n = vp->Near, f = vp->Far;
   const float scale[3] = { half_w, half_h, (float)(0.5 * (f - n)) };
   const float translate[3] = { half_w + (float)vp->X, half_h + (float)vp->Y,
                                (float)(0.5 * (n + f)) };
   for (int i = 0; i < 3; i++)
      cur->RasterPos[i] = ndc[i] * scale[i] + translate[i];
   cur->RasterPos[3] = clip[3];

   if (ctx->Fog.CoordinateSource == GL_FOG_COORDINATE)
      cur->RasterDistance = cur->FogCoord;
   else
      cur->RasterDistance = sqrtf(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);

   for (int k = 0; k < 4; k++) {
      cur->RasterColor[k] = cur->Attrib[FGL_ATTR_COLOR0][k];
      cur->RasterSecondaryColor[k] = cur->SecondaryColor[k];
   }

   /* no texture coordinate generation: the GL_TEXTURE_GEN_* enables are
    * not part of fixgl yet (TexGenEnabled is always 0) */
   for (int u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      const float *tc = u == 0 ? cur->Attrib[FGL_ATTR_TEX0] : cur->TexCoord[u];
      transform_point(cur->RasterTexCoords[u], ctx->TextureStack[u].Top->m, tc);
   }
   cur->RasterPosValid = true;

   if (ctx->RenderMode == GL_SELECT)
      update_hitflag(ctx, cur->RasterPos[2]);
}

/* [S: rastpos.c:rasterpos] every variant converts to four floats, then
 * FLUSH_VERTICES, FLUSH_CURRENT and the state update; while compiling,
 * every variant is stored as glRasterPos4f (dlist.c:save_RasterPos*). */
static void rasterpos(GLfloat x, GLfloat y, GLfloat z, GLfloat w)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, RasterPos4f, x, y, z, w);
   /* only the BeginEnd dispatch's generic_nop checks for glBegin/glEnd */
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   fgl_flush_current(ctx);
   fgl_update_state(ctx);
   const float p[4] = { x, y, z, w };
   raster_pos(ctx, p);
}

void GLAPIENTRY glRasterPos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { rasterpos(x, y, z, w); }
void GLAPIENTRY glRasterPos2d(GLdouble x, GLdouble y) { rasterpos((GLfloat)x, (GLfloat)y, 0.0f, 1.0f); }
void GLAPIENTRY glRasterPos2f(GLfloat x, GLfloat y) { rasterpos(x, y, 0.0f, 1.0f); }
void GLAPIENTRY glRasterPos2i(GLint x, GLint y) { rasterpos((GLfloat)x, (GLfloat)y, 0.0f, 1.0f); }
void GLAPIENTRY glRasterPos2s(GLshort x, GLshort y) { rasterpos(x, y, 0.0f, 1.0f); }
void GLAPIENTRY glRasterPos3d(GLdouble x, GLdouble y, GLdouble z)
{
   rasterpos((GLfloat)x, (GLfloat)y, (GLfloat)z, 1.0f);
}
void GLAPIENTRY glRasterPos3f(GLfloat x, GLfloat y, GLfloat z) { rasterpos(x, y, z, 1.0f); }
void GLAPIENTRY glRasterPos3i(GLint x, GLint y, GLint z)
{
   rasterpos((GLfloat)x, (GLfloat)y, (GLfloat)z, 1.0f);
}
void GLAPIENTRY glRasterPos3s(GLshort x, GLshort y, GLshort z) { rasterpos(x, y, z, 1.0f); }
void GLAPIENTRY glRasterPos4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w)
{
   rasterpos((GLfloat)x, (GLfloat)y, (GLfloat)z, (GLfloat)w);
}
void GLAPIENTRY glRasterPos4i(GLint x, GLint y, GLint z, GLint w)
{
   rasterpos((GLfloat)x, (GLfloat)y, (GLfloat)z, (GLfloat)w);
}
void GLAPIENTRY glRasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w) { rasterpos(x, y, z, w); }
void GLAPIENTRY glRasterPos2dv(const GLdouble *v) { rasterpos((GLfloat)v[0], (GLfloat)v[1], 0.0f, 1.0f); }
void GLAPIENTRY glRasterPos2fv(const GLfloat *v) { rasterpos(v[0], v[1], 0.0f, 1.0f); }
void GLAPIENTRY glRasterPos2iv(const GLint *v) { rasterpos((GLfloat)v[0], (GLfloat)v[1], 0.0f, 1.0f); }
void GLAPIENTRY glRasterPos2sv(const GLshort *v) { rasterpos(v[0], v[1], 0.0f, 1.0f); }
void GLAPIENTRY glRasterPos3dv(const GLdouble *v)
{
   rasterpos((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2], 1.0f);
}
void GLAPIENTRY glRasterPos3fv(const GLfloat *v) { rasterpos(v[0], v[1], v[2], 1.0f); }
void GLAPIENTRY glRasterPos3iv(const GLint *v)
{
   rasterpos((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2], 1.0f);
}
void GLAPIENTRY glRasterPos3sv(const GLshort *v) { rasterpos(v[0], v[1], v[2], 1.0f); }
void GLAPIENTRY glRasterPos4dv(const GLdouble *v)
{
   rasterpos((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2], (GLfloat)v[3]);
}
void GLAPIENTRY glRasterPos4fv(const GLfloat *v) { rasterpos(v[0], v[1], v[2], v[3]); }
void GLAPIENTRY glRasterPos4iv(const GLint *v)
{
   rasterpos((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2], (GLfloat)v[3]);
}
void GLAPIENTRY glRasterPos4sv(const GLshort *v) { rasterpos(v[0], v[1], v[2], v[3]); }
