/*
 * glRasterPos{2,3,4}{s,i,f,d}[v] and glWindowPos{2,3}{s,i,f,d}[v]
 * (GL_CURRENT_BIT's raster position).
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
 *   colour: the current colours, or with lighting Mesa's CPU lighting
 *   (shade_rastpos, front material, below), not the vertex program's
 *   texture coordinates: texture matrix * current coordinate, every unit
 *   in GL_SELECT a valid raster position updates the hit record with its z.
 */
/* glWindowPos (GL 1.4) is declared by <GL/glext.h> only with
 * GL_GLEXT_PROTOTYPES: asking for the prototypes checks the definitions
 * below against them */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <string.h>

#include <fixgl/fixgl.h>

#include "main/groups.h"
#include "main/conv.h"
#include "main/dlist.h"
#include "math/m_shade.h"
#include "tnl/t_pipeline.h"

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
   /* the user planes: t_clip_dist's left-to-right dot in clip space */
   unsigned mask = ctx->Transform.ClipPlanesEnabled;
   while (mask) {
      const unsigned p = (unsigned)__builtin_ctz(mask);
      mask &= mask - 1;
      if (t_clip_dist(ctx, clip, 6 + p) < 0.0f)
         return false;
   }
   return true;
}

/* ---- lighting: [S: rastpos.c:shade_rastpos], not the vertex program ---- */

static float dot3(const float a[3], const float b[3])
{
   return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* A light's values as Mesa's CPU state derives them: light.c
 * compute_light_positions (in eye space with _NeedEyeCoords, else in
 * object space through the inverse modelview: the same values
 * fgl_update_lighting keeps in ctx->_Lighting, read from there) and
 * _mesa_update_material (the light colours times the front material). */
struct rp_light {
   const float *Position, *VPInfNorm, *HInfNorm, *NormSpotDirection;
   float VPInfSpotAttenuation;
   float MatAmbient[3], MatDiffuse[3], MatSpecular[3];
   bool Positional, Spot;
};

static void rp_light_state(const struct fgl_context *ctx, int i, struct rp_light *r)
{
   const struct fgl_light *l = &ctx->Light.Light[i];
   const struct fgl_light_derived *ld = &ctx->_Lighting.Light[i];
   const float (*mat)[4] = (const float (*)[4])ctx->Current.Attrib;
   r->Positional = ld->Positional;
   r->Spot = ld->Spot;
   /* directional: Position is _VP_inf_norm, HalfVector _h_inf_norm */
   r->Position = r->VPInfNorm = ld->Position;
   r->HInfNorm = ld->HalfVector;
   r->NormSpotDirection = ld->SpotDirection;
   r->VPInfSpotAttenuation = 1.0f;
   if (r->Spot && !r->Positional) {
      const float pv_dot_dir = -dot3(r->VPInfNorm, r->NormSpotDirection);
      r->VPInfSpotAttenuation = pv_dot_dir > l->CosCutoff ? powf(pv_dot_dir, l->SpotExponent)
                                                          : 0.0f;
   }
   for (int k = 0; k < 3; k++) {
      r->MatAmbient[k] = l->Ambient[k] * mat[FGL_ATTR_MAT_FRONT_AMBIENT][k];
      r->MatDiffuse[k] = l->Diffuse[k] * mat[FGL_ATTR_MAT_FRONT_DIFFUSE][k];
      r->MatSpecular[k] = l->Specular[k] * mat[FGL_ATTR_MAT_FRONT_SPECULAR][k];
   }
}

/* [S: rastpos.c:shade_rastpos] front material only; `vertex` is the
 * object-space position even when the lights are in eye space (as Mesa
 * passes it); the results clamped to [0, 1]. */
static void shade_rastpos(const struct fgl_context *ctx, const float vertex[4],
                          const float normal[3], const float eye_z_dir[3],
                          float rcolor[4], float rspec[4])
{
   const float (*mat)[4] = (const float (*)[4])ctx->Current.Attrib;
   float diffuse_color[4], specular_color[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
   /* _BaseColor = emission + material ambient * scene ambient */
   for (int k = 0; k < 3; k++)
      diffuse_color[k] = mat[FGL_ATTR_MAT_FRONT_EMISSION][k] +
                         mat[FGL_ATTR_MAT_FRONT_AMBIENT][k] * ctx->Light.Model.Ambient[k];
   diffuse_color[3] = fgl_clamp01(mat[FGL_ATTR_MAT_FRONT_DIFFUSE][3]);

   for (int i = 0; i < FGL_MAX_LIGHTS; i++) {
      const struct fgl_light *l = &ctx->Light.Light[i];
      if (!l->Enabled)
         continue;
      struct rp_light r;
      rp_light_state(ctx, i, &r);
      float attenuation, vp[3], diffuse_contrib[3], specular_contrib[3];
      if (!r.Positional) {
         for (int k = 0; k < 3; k++)
            vp[k] = r.VPInfNorm[k];
         attenuation = r.VPInfSpotAttenuation;
      } else {
         for (int k = 0; k < 3; k++)
            vp[k] = r.Position[k] - vertex[k];
         const float d = sqrtf(dot3(vp, vp));
         if (d > 1.0e-6f) {
            const float invd = 1.0f / d;
            for (int k = 0; k < 3; k++)
               vp[k] = vp[k] * invd;
         }
         attenuation = 1.0f / (l->ConstantAttenuation +
                               d * (l->LinearAttenuation + d * l->QuadraticAttenuation));
         if (r.Spot) {
            const float pv_dot_dir = -dot3(vp, r.NormSpotDirection);
            if (pv_dot_dir < l->CosCutoff)
               continue;
            attenuation *= powf(pv_dot_dir, l->SpotExponent);
         }
      }
      if (attenuation < 1e-3f)
         continue;
      const float n_dot_vp = dot3(normal, vp);
      if (n_dot_vp < 0.0f) {
         for (int k = 0; k < 3; k++)
            diffuse_color[k] += attenuation * r.MatAmbient[k];
         continue;
      }
      for (int k = 0; k < 3; k++) {
         diffuse_contrib[k] = r.MatAmbient[k];
         diffuse_contrib[k] += n_dot_vp * r.MatDiffuse[k];
         specular_contrib[k] = 0.0f;
      }
      const float *h;
      if (ctx->Light.Model.LocalViewer) {
         float v[3] = { vertex[0], vertex[1], vertex[2] };
         fgl_normalize3(v);
         for (int k = 0; k < 3; k++)
            vp[k] = vp[k] - v[k];
         fgl_normalize3(vp);
         h = vp;
      } else if (r.Positional) {
         for (int k = 0; k < 3; k++)
            vp[k] += eye_z_dir[k];
         fgl_normalize3(vp);
         h = vp;
      } else {
         h = r.HInfNorm;
      }
      const float n_dot_h = dot3(normal, h);
      if (n_dot_h > 0.0f) {
         const float spec_coef = powf(n_dot_h, mat[FGL_ATTR_MAT_FRONT_SHININESS][0]);
         if (spec_coef > 1.0e-10f) {
            float *dst = ctx->Light.Model.ColorControl == GL_SEPARATE_SPECULAR_COLOR
                            ? specular_contrib : diffuse_contrib;
            for (int k = 0; k < 3; k++)
               dst[k] += spec_coef * r.MatSpecular[k];
         }
      }
      for (int k = 0; k < 3; k++) {
         diffuse_color[k] += attenuation * diffuse_contrib[k];
         specular_color[k] += attenuation * specular_contrib[k];
      }
   }
   for (int k = 0; k < 4; k++) {
      rcolor[k] = fgl_clamp01(diffuse_color[k]);
      rspec[k] = fgl_clamp01(specular_color[k]);
   }
}

static inline float dot4(const float *a, const float *b)
{
   return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

/* [S: rastpos.c:compute_texgen] in C on the CPU, left-to-right sums: the
 * sphere map terms always, then each enabled coordinate's mode */
static void compute_texgen(const struct fgl_texture_unit *t, const float obj[4],
                           const float eye[4], const float normal[3], float tc[4])
{
   float u[3] = { eye[0], eye[1], eye[2] };
   fgl_normalize3(u);
   const float two_nu = 2.0f * (normal[0] * u[0] + normal[1] * u[1] + normal[2] * u[2]);
   const float r[3] = { u[0] - normal[0] * two_nu, u[1] - normal[1] * two_nu,
                        u[2] - normal[2] * two_nu };
   const float m = r[0] * r[0] + r[1] * r[1] + (r[2] + 1.0f) * (r[2] + 1.0f);
   const float m_inv = m > 0.0f ? 0.5f * (1.0f / sqrtf(m)) : 0.0f;
   for (int c = 0; c < 4; c++) {
      if (!(t->TexGenEnabled & (1u << c)))
         continue;
      switch (t->GenMode[c]) {
      case GL_OBJECT_LINEAR: tc[c] = dot4(obj, t->ObjectPlane[c]); break;
      case GL_EYE_LINEAR:    tc[c] = dot4(eye, t->EyePlane[c]); break;
      case GL_SPHERE_MAP:    tc[c] = r[c] * m_inv + 0.5f; break;
      case GL_REFLECTION_MAP: tc[c] = r[c]; break;
      case GL_NORMAL_MAP:    tc[c] = normal[c]; break;
      default:               return;   /* _mesa_problem */
      }
   }
}

/* [S: rastpos.c:_mesa_RasterPos] */
static void raster_pos(struct fgl_context *ctx, const float obj[4])
{
   struct fgl_current_attrib *cur = &ctx->Current;
   float eye[4], clip[4];

   ctx->PopAttribState |= GL_CURRENT_BIT;
   fgl_matrix_analyse(ctx->ModelviewStack.Top);   /* the inverse, for lighting */
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
      cur->RasterDistance = cur->Attrib[FGL_ATTR_FOG][0];
   else
      cur->RasterDistance = sqrtf(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);

   /* the normal for lighting and texgen: with _NeedEyeCoords
    * (light.c:_mesa_update_tnl_spaces; no point attenuation in fixgl)
    * through the inverse modelview, not normalized or rescaled; else the
    * object normal */
   const bool eye_coords = ctx->_Lighting.NeedEyeCoords;
   const float *norm = cur->Attrib[FGL_ATTR_NORMAL];
   float eyenorm[3];
   if (eye_coords) {
      fgl_transform_normal(eyenorm, norm, ctx->ModelviewStack.Top->inv);
      norm = eyenorm;
   }
   if (ctx->Light.Enabled && (ctx->Light.Reflectance[0].Model == GL_COOK_TORRANCE_FIXGL ||
                              ctx->Light.Reflectance[1].Model == GL_COOK_TORRANCE_FIXGL)) {
      /* GL_FIXGL_cook_torrance: the raster position is lit like a vertex
       * (t_light.c light_shade, include/fixgl/shading.md), front face,
       * with the vertices' n and P (t_eye_normal, the column chain) */
      struct m_shade_env env;
      struct t_eye_normal en;
      float n[3], P[4];
      fgl_update_shade_env(ctx, &env);
      t_eye_normal_init(ctx, &en);
      t_eye_normal(&en, cur->Attrib[FGL_ATTR_NORMAL], n);
      t_mul_mad_chain(P, ctx->ModelviewStack.Top->m, obj);
      m_shade_point_prepared(&env, n, P, false, cur->Attrib[FGL_ATTR_COLOR0], cur->RasterColor,
                             cur->RasterSecondaryColor);
   } else if (ctx->Light.Enabled) {
      float eye_z_dir[3] = { 0.0f, 0.0f, 1.0f };
      if (!eye_coords) {
         /* compute_light_positions: TRANSFORM_NORMAL of (0, 0, 1) */
         static const float z[3] = { 0.0f, 0.0f, 1.0f };
         fgl_transform_normal(eye_z_dir, z, ctx->ModelviewStack.Top->m);
      }
      shade_rastpos(ctx, obj, norm, eye_z_dir, cur->RasterColor,
                    cur->RasterSecondaryColor);
   } else {
      for (int k = 0; k < 4; k++) {
         cur->RasterColor[k] = cur->Attrib[FGL_ATTR_COLOR0][k];
         cur->RasterSecondaryColor[k] = cur->Attrib[FGL_ATTR_COLOR1][k];
      }
   }

   /* every unit's coordinate: generated where the unit enables it,
    * whether or not it textures, then through its texture matrix
    * (TRANSFORM_POINT, unanalysed) */
   for (int u = 0; u < FGL_MAX_TEXTURE_UNITS; u++) {
      float tc[4];
      memcpy(tc, cur->Attrib[FGL_ATTR_TEX0 + u], sizeof(tc));
      if (ctx->Texture.Unit[u].TexGenEnabled)
         compute_texgen(&ctx->Texture.Unit[u], obj, eye, norm, tc);
      transform_point(cur->RasterTexCoords[u], ctx->TextureStack[u].Top->m, tc);
   }
   cur->RasterPosValid = true;

   if (ctx->RenderMode == GL_SELECT)
      t_update_hitflag(ctx, cur->RasterPos[2]);
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
   ASSERT_OUTSIDE_BEGIN_END(ctx);
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

/* ---- glWindowPos (GL 1.4) ---- */

/* [S: rastpos.c:window_pos3f, window_pos4f] the window position as
 * given, z mapped into the depth range (CLAMP(z, 0, 1) * (far - near) +
 * near, in float), always valid; the distance from the fog coordinate with
 * GL_FOG_COORDINATE as the fog source, else 0; the current colours clamped
 * (no lighting) and the current texture coordinates (no texture matrix);
 * in GL_SELECT the hit record takes the z.  While compiling, every variant
 * is stored as Mesa's glWindowPos4fMESA (dlist.c:save_WindowPos*). */
static void window_pos(GLfloat x, GLfloat y, GLfloat z)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, WindowPos4fMESA, x, y, z, 1.0f);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   FGL_FLUSH_VERTICES(ctx, 0);
   fgl_flush_current(ctx);
   struct fgl_current_attrib *cur = &ctx->Current;
   ctx->PopAttribState |= GL_CURRENT_BIT;
   const float n = ctx->Viewport.Near, f = ctx->Viewport.Far;
   cur->RasterPos[0] = x;
   cur->RasterPos[1] = y;
   cur->RasterPos[2] = fgl_clamp01(z) * (f - n) + n;
   cur->RasterPos[3] = 1.0f;
   cur->RasterPosValid = true;
   cur->RasterDistance = ctx->Fog.CoordinateSource == GL_FOG_COORDINATE
                       ? cur->Attrib[FGL_ATTR_FOG][0] : 0.0f;
   for (int k = 0; k < 4; k++) {
      cur->RasterColor[k] = fgl_clamp01(cur->Attrib[FGL_ATTR_COLOR0][k]);
      cur->RasterSecondaryColor[k] = fgl_clamp01(cur->Attrib[FGL_ATTR_COLOR1][k]);
   }
   for (int u = 0; u < FGL_MAX_TEXTURE_UNITS; u++)
      for (int k = 0; k < 4; k++)
         cur->RasterTexCoords[u][k] = cur->Attrib[FGL_ATTR_TEX0 + u][k];
   if (ctx->RenderMode == GL_SELECT)
      t_update_hitflag(ctx, cur->RasterPos[2]);
}

/* the list replay of glWindowPos4fMESA: window_pos4f sets w after */
void fgl_window_pos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w)
{
   window_pos(x, y, z);
   GET_CURRENT_CONTEXT(ctx);
   if (ctx)
      ctx->Current.RasterPos[3] = w;
}

void GLAPIENTRY glWindowPos2d(GLdouble x, GLdouble y) { window_pos((GLfloat)x, (GLfloat)y, 0.0f); }
void GLAPIENTRY glWindowPos2f(GLfloat x, GLfloat y) { window_pos(x, y, 0.0f); }
void GLAPIENTRY glWindowPos2i(GLint x, GLint y) { window_pos((GLfloat)x, (GLfloat)y, 0.0f); }
void GLAPIENTRY glWindowPos2s(GLshort x, GLshort y) { window_pos(x, y, 0.0f); }
void GLAPIENTRY glWindowPos3d(GLdouble x, GLdouble y, GLdouble z)
{
   window_pos((GLfloat)x, (GLfloat)y, (GLfloat)z);
}
void GLAPIENTRY glWindowPos3f(GLfloat x, GLfloat y, GLfloat z) { window_pos(x, y, z); }
void GLAPIENTRY glWindowPos3i(GLint x, GLint y, GLint z)
{
   window_pos((GLfloat)x, (GLfloat)y, (GLfloat)z);
}
void GLAPIENTRY glWindowPos3s(GLshort x, GLshort y, GLshort z) { window_pos(x, y, z); }
void GLAPIENTRY glWindowPos2dv(const GLdouble *v) { window_pos((GLfloat)v[0], (GLfloat)v[1], 0.0f); }
void GLAPIENTRY glWindowPos2fv(const GLfloat *v) { window_pos(v[0], v[1], 0.0f); }
void GLAPIENTRY glWindowPos2iv(const GLint *v) { window_pos((GLfloat)v[0], (GLfloat)v[1], 0.0f); }
void GLAPIENTRY glWindowPos2sv(const GLshort *v) { window_pos(v[0], v[1], 0.0f); }
void GLAPIENTRY glWindowPos3dv(const GLdouble *v)
{
   window_pos((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2]);
}
void GLAPIENTRY glWindowPos3fv(const GLfloat *v) { window_pos(v[0], v[1], v[2]); }
void GLAPIENTRY glWindowPos3iv(const GLint *v)
{
   window_pos((GLfloat)v[0], (GLfloat)v[1], (GLfloat)v[2]);
}
void GLAPIENTRY glWindowPos3sv(const GLshort *v) { window_pos(v[0], v[1], v[2]); }
