/*
 * The viewer's scene (fv_scene.h).  The matrices are computed here, in
 * float, and loaded with glLoadMatrixf: both GLs receive the same numbers.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <fixgl/fixgl.h>

#include "fv_scene.h"

#ifdef FV_HAVE_FCR
#include "fcr_shading.h"
#endif

#define FV_PI 3.14159265358979323846
#define FOVY_DEG 40.0

static const float light_colors[FV_MAX_LIGHTS][3] = {
   { 1.0f, 1.0f, 1.0f }, { 1.0f, 0.75f, 0.5f }, { 0.45f, 0.65f, 1.0f }, { 0.5f, 1.0f, 0.55f },
   { 1.0f, 0.5f, 0.9f }, { 1.0f, 1.0f, 0.5f }, { 0.5f, 1.0f, 1.0f }, { 0.8f, 0.8f, 0.8f },
};

void fv_scene_init(struct fv_scene *s, const struct fv_model *m)
{
   memset(s, 0, sizeof *s);
   s->model = m;
   s->yaw = 30.0f;
   s->pitch = 20.0f;
   s->zoom = 1.0f;
   s->shade = FV_SMOOTH;
   s->roughness = 0.35f;
   s->metalness = 0.0f;
   s->background[0] = 0.10f, s->background[1] = 0.11f, s->background[2] = 0.14f;
   s->lights[0] = (struct fv_light){ .on = 1, .type = FV_DIRECTIONAL, .azimuth = -35.0f,
                                     .elevation = 35.0f, .distance = 3.0f,
                                     .color = { 1.0f, 1.0f, 1.0f } };
   s->num_lights = 1;
}

int fv_scene_add_light(struct fv_scene *s)
{
   if (s->num_lights >= FV_MAX_LIGHTS)
      return -1;
   int i = s->num_lights++;
   static const enum fv_light_type types[3] = { FV_POINT, FV_SPOT, FV_DIRECTIONAL };
   struct fv_light *l = &s->lights[i];
   l->on = 1;
   l->type = types[(i - 1) % 3];
   l->azimuth = 50.0f + 70.0f * (float)i;
   l->elevation = 15.0f + 10.0f * (float)(i % 3);
   l->distance = 2.5f;
   memcpy(l->color, light_colors[i], sizeof l->color);
   s->selected = i;
   return i;
}

int fv_scene_needs_phong(const struct fv_scene *s)
{
   return s->shade == FV_PHONG;
}

int fv_scene_needs_cook_torrance(const struct fv_scene *s)
{
   return s->cook_torrance;
}

void fv_scene_describe(const struct fv_scene *s, char *buf, int size)
{
   static const char *const names[] = { "flat", "smooth", "Phong" };
   if (s->cook_torrance)
      snprintf(buf, (size_t)size, "%s + Cook-Torrance (roughness %.2f, metalness %.2f)",
               names[s->shade], s->roughness, s->metalness);
   else
      snprintf(buf, (size_t)size, "%s", names[s->shade]);
}

/* ---- matrices (column-major, as glLoadMatrixf takes them) -------------- */

static void mat_identity(float m[16])
{
   memset(m, 0, 16 * sizeof(float));
   m[0] = m[5] = m[10] = m[15] = 1.0f;
}

static void mat_mul(float r[16], const float a[16], const float b[16])
{
   float t[16];
   for (int c = 0; c < 4; c++)
      for (int i = 0; i < 4; i++) {
         double v = 0.0;
         for (int k = 0; k < 4; k++)
            v += (double)a[k * 4 + i] * b[c * 4 + k];
         t[c * 4 + i] = (float)v;
      }
   memcpy(r, t, sizeof t);
}

static void mat_rotate(float m[16], double deg, int axis)
{
   double c = cos(deg * FV_PI / 180.0), s = sin(deg * FV_PI / 180.0);
   int a = (axis + 1) % 3, b = (axis + 2) % 3;
   mat_identity(m);
   m[a * 4 + a] = (float)c;
   m[a * 4 + b] = (float)s;
   m[b * 4 + a] = (float)-s;
   m[b * 4 + b] = (float)c;
}

/* The camera's distance from the model's centre: at zoom 1 the bounding
 * sphere fits the narrower of the two fields of view with a 10% margin. */
static double camera_distance(const struct fv_scene *s, int w, int h)
{
   double half = 0.5 * FOVY_DEG * FV_PI / 180.0;
   if (w < h)
      half = atan(tan(half) * w / h);
   return 1.1 * s->model->radius / sin(half) / s->zoom;
}

static void projection(const struct fv_scene *s, int w, int h, float p[16])
{
   double r = s->model->radius, d = camera_distance(s, w, h);
   double n = d - 1.05 * r, f = d + 1.05 * r;
   if (n < 0.01 * r)
      n = 0.01 * r;
   double t = n * tan(0.5 * FOVY_DEG * FV_PI / 180.0), a = (double)w / (h > 0 ? h : 1);
   /* glFrustum(-t a, t a, -t, t, n, f) */
   memset(p, 0, 16 * sizeof(float));
   p[0] = (float)(n / (t * a));
   p[5] = (float)(n / t);
   p[10] = (float)(-(f + n) / (f - n));
   p[11] = -1.0f;
   p[14] = (float)(-2.0 * f * n / (f - n));
}

/* Eye <- model: T(0, 0, -d) Rx(pitch) Ry(yaw) T(-centre). */
static void modelview(const struct fv_scene *s, int w, int h, float mv[16])
{
   float t[16], r[16];
   mat_identity(mv);
   mv[14] = (float)-camera_distance(s, w, h);
   mat_rotate(r, s->pitch, 0);
   mat_mul(mv, mv, r);
   mat_rotate(r, s->yaw, 1);
   mat_mul(mv, mv, r);
   mat_identity(t);
   t[12] = -s->model->center[0];
   t[13] = -s->model->center[1];
   t[14] = -s->model->center[2];
   mat_mul(mv, mv, t);
}

static void light_direction(const struct fv_light *l, float d[3])
{
   double az = l->azimuth * FV_PI / 180.0, el = l->elevation * FV_PI / 180.0;
   d[0] = (float)(cos(el) * sin(az));
   d[1] = (float)sin(el);
   d[2] = (float)(cos(el) * cos(az));
}

/* The lights, in eye space (the modelview is the identity). */
static void set_lights(const struct fv_scene *s, const struct fv_gl *gl, int w, int h)
{
   static const float black[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
   const double r = s->model->radius, dist = camera_distance(s, w, h);
   for (int i = 0; i < FV_MAX_LIGHTS; i++) {
      const struct fv_light *l = &s->lights[i];
      const GLenum li = GL_LIGHT0 + (GLenum)i;
      if (i >= s->num_lights || !l->on) {
         gl->Disable(li);
         continue;
      }
      float d[3], pos[4], col[4] = { l->color[0], l->color[1], l->color[2], 1.0f };
      light_direction(l, d);
      if (l->type == FV_DIRECTIONAL) {
         pos[0] = d[0], pos[1] = d[1], pos[2] = d[2], pos[3] = 0.0f;
      } else {
         pos[0] = (float)(d[0] * l->distance * r);
         pos[1] = (float)(d[1] * l->distance * r);
         pos[2] = (float)(d[2] * l->distance * r - dist);
         pos[3] = 1.0f;
      }
      gl->Enable(li);
      gl->Lightfv(li, GL_AMBIENT, black);
      gl->Lightfv(li, GL_DIFFUSE, col);
      gl->Lightfv(li, GL_SPECULAR, col);
      gl->Lightfv(li, GL_POSITION, pos);
      if (l->type == FV_SPOT) {
         /* aimed at the model's centre, its cone a little wider than the model */
         const float sd[3] = { -d[0], -d[1], -d[2] };
         double cut = atan(1.3 / l->distance) * 180.0 / FV_PI;
         gl->Lightfv(li, GL_SPOT_DIRECTION, sd);
         gl->Lightf(li, GL_SPOT_CUTOFF, (float)cut);
         gl->Lightf(li, GL_SPOT_EXPONENT, 8.0f);
      } else {
         gl->Lightf(li, GL_SPOT_CUTOFF, 180.0f);
      }
   }
}

static void set_material(const struct fv_gl *gl, const struct fv_material *m)
{
   if (!m->lit) {
      gl->Disable(GL_LIGHTING);
      gl->Color4fv(m->diffuse);
      return;
   }
   gl->Enable(GL_LIGHTING);
   gl->Materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, m->ambient);
   gl->Materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, m->diffuse);
   gl->Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, m->specular);
   gl->Materialfv(GL_FRONT_AND_BACK, GL_EMISSION, m->emission);
   gl->Materialf(GL_FRONT_AND_BACK, GL_SHININESS, m->shininess);
}

/* The reflectance model: fixgl's GL_FIXGL_cook_torrance (include/fixgl/
 * shading.md), or on OSMesa the GLSL reference, bound last: it reads the
 * fixed-function state just set (lighting, colour material, texturing).
 * Returns 0, or -1 when the reference's program did not compile. */
static int set_reflectance(const struct fv_scene *s, const struct fv_gl *gl,
                           const struct fv_material *m, struct fcr *ref)
{
   if (!ref) {
      if (m->lit) {
         gl->Materiali(GL_FRONT_AND_BACK, GL_REFLECTANCE_MODEL_FIXGL,
                       s->cook_torrance ? GL_COOK_TORRANCE_FIXGL : GL_BLINN_PHONG_FIXGL);
         if (s->cook_torrance) {
            gl->Materialf(GL_FRONT_AND_BACK, GL_ROUGHNESS_FIXGL, s->roughness);
            gl->Materialf(GL_FRONT_AND_BACK, GL_METALNESS_FIXGL, s->metalness);
         }
      }
      return 0;
   }
#ifdef FV_HAVE_FCR
   if (!m->lit) {
      fcr_unbind(ref);
      return 0;
   }
   const struct fcr_face f = { s->cook_torrance, s->roughness, s->metalness, 0.04f };
   if (!fcr_bind(ref, s->shade == FV_PHONG, &f, &f))
      return -1;
#else
   (void)s;
#endif
   return 0;
}

void fv_scene_upload_textures(const struct fv_model *m, const struct fv_gl *gl, GLuint *names)
{
   if (m->num_textures == 0)
      return;
   gl->GenTextures(m->num_textures, names);
   gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
   for (int i = 0; i < m->num_textures; i++) {
      const struct fv_texture *t = &m->textures[i];
      gl->BindTexture(GL_TEXTURE_2D, names[i]);
      gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
      gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
      gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
      /* the whole chain from level 0, by the GL (OpenGL 1.4) */
      gl->TexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
      gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, t->w, t->h, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     t->rgba);
   }
   gl->BindTexture(GL_TEXTURE_2D, 0);
}

/* The mesh's texture and per-vertex colours, after its material. */
static void set_arrays(const struct fv_gl *gl, const struct fv_mesh *me, const GLuint *textures)
{
   if (textures && me->texture >= 0) {
      gl->Enable(GL_TEXTURE_2D);
      gl->BindTexture(GL_TEXTURE_2D, textures[me->texture]);
      gl->TexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      gl->EnableClientState(GL_TEXTURE_COORD_ARRAY);
      gl->TexCoordPointer(2, GL_FLOAT, 0, me->uv);
   } else {
      gl->Disable(GL_TEXTURE_2D);
      gl->DisableClientState(GL_TEXTURE_COORD_ARRAY);
   }
   if (me->col) {
      /* lit: the colours replace the material's ambient and diffuse */
      if (me->mat.lit) {
         gl->ColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
         gl->Enable(GL_COLOR_MATERIAL);
      }
      gl->EnableClientState(GL_COLOR_ARRAY);
      gl->ColorPointer(4, GL_FLOAT, 0, me->col);
   } else {
      gl->Disable(GL_COLOR_MATERIAL);
      gl->DisableClientState(GL_COLOR_ARRAY);
   }
}

static void draw_mesh(const struct fv_gl *gl, const struct fv_mesh *me)
{
   gl->VertexPointer(3, GL_FLOAT, 0, me->pos);
   gl->NormalPointer(GL_FLOAT, 0, me->nrm);
   gl->DrawElements(GL_TRIANGLES, (GLsizei)me->num_idx, GL_UNSIGNED_INT, me->idx);
}

static int translucent(const struct fv_model *m, const struct fv_mesh *me, const GLuint *textures)
{
   return me->mat.diffuse[3] < 1.0f ||
          (textures && me->texture >= 0 && m->textures[me->texture].translucent);
}

int fv_scene_draw(const struct fv_scene *s, const struct fv_gl *gl, const GLuint *textures,
                  int w, int h, struct fcr *ref)
{
   int rc = 0;
   float p[16], mv[16];
   projection(s, w, h, p);
   modelview(s, w, h, mv);

   gl->Viewport(0, 0, w, h);
   gl->ClearColor(s->background[0], s->background[1], s->background[2], 1.0f);
   gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   gl->Enable(GL_DEPTH_TEST);
   gl->DepthFunc(GL_LESS);
   gl->MatrixMode(GL_PROJECTION);
   gl->LoadMatrixf(p);
   gl->MatrixMode(GL_MODELVIEW);
   gl->LoadIdentity();
   set_lights(s, gl, w, h);
   gl->LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
   gl->LoadMatrixf(mv);

   /* GL_PHONG_WIN on fixgl; the reference does the per-fragment work
    * itself over GL_SMOOTH's interpolation on OSMesa. */
   gl->ShadeModel(s->shade == FV_FLAT ? GL_FLAT
                  : s->shade == FV_PHONG && !ref ? GL_PHONG_WIN : GL_SMOOTH);
   gl->PolygonMode(GL_FRONT_AND_BACK, s->wireframe ? GL_LINE : GL_FILL);
   if (s->cull) {
      gl->Enable(GL_CULL_FACE);
      gl->CullFace(GL_BACK);
   } else {
      gl->Disable(GL_CULL_FACE);
   }
   gl->EnableClientState(GL_VERTEX_ARRAY);
   gl->EnableClientState(GL_NORMAL_ARRAY);

   /* Opaque meshes first, then the translucent ones (MTL d < 1, or a
    * texture with alpha below 1) blended
    * over them without writing depth, nor alpha: the frame stays opaque, as
    * a window shows it (the X server's image of a window whose frame had
    * alpha < 1 differed from its RGB by 1 LSB under Xvfb). */
   for (int pass = 0; pass < 2; pass++) {
      if (pass == 1) {
         gl->Enable(GL_BLEND);
         gl->BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
         gl->DepthMask(GL_FALSE);
         gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
      }
      for (int i = 0; i < s->model->num_meshes; i++) {
         const struct fv_mesh *me = &s->model->meshes[i];
         if (translucent(s->model, me, textures) != (pass == 1))
            continue;
         /* the colour material off while glMaterial sets the material */
         gl->Disable(GL_COLOR_MATERIAL);
         set_material(gl, &me->mat);
         set_arrays(gl, me, textures);
         if (set_reflectance(s, gl, &me->mat, ref) != 0)
            rc = -1;
         draw_mesh(gl, me);
      }
   }
#ifdef FV_HAVE_FCR
   if (ref)
      fcr_unbind(ref);
#endif
   gl->Disable(GL_BLEND);
   gl->DepthMask(GL_TRUE);
   gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
   gl->DisableClientState(GL_VERTEX_ARRAY);
   gl->DisableClientState(GL_NORMAL_ARRAY);
   gl->DisableClientState(GL_TEXTURE_COORD_ARRAY);
   gl->DisableClientState(GL_COLOR_ARRAY);
   gl->Disable(GL_TEXTURE_2D);
   gl->Disable(GL_COLOR_MATERIAL);
   gl->Finish();
   return rc;
}
