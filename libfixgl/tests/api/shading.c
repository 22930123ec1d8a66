/*
 * shading.c - fixgl's shading extensions through the API
 * (include/fixgl/shading.md; fixgl only: the oracle has neither).
 *
 *   extensions   GL_EXTENSIONS lists GL_WIN_phong_shading and
 *                GL_FIXGL_cook_torrance
 *   shade model  glShadeModel(GL_PHONG_WIN): query, errors, GL_LIGHTING_BIT,
 *                display lists; glHint(GL_PHONG_HINT_WIN): query, errors,
 *                GL_HINT_BIT
 *   material     the reflectance pnames per face through every glMaterial
 *                and glGetMaterial variant: defaults, faces, errors (state
 *                unchanged), glBegin/glEnd, glColorMaterial, GL_LIGHTING_BIT,
 *                display lists (compile, compile-and-execute, errors at
 *                execution)
 *   rendering    per-vertex Cook-Torrance under GL_FLAT and GL_SMOOTH
 *                against shading.md in double precision (shade_ref.h):
 *                directional and point lights, local viewer, two-sided,
 *                colour material, separate specular, metals and
 *                dielectrics, within 1 LSB; a Blinn-Phong scene is
 *                unchanged after a Cook-Torrance draw; a Blinn-Phong front
 *                face drawn with a Cook-Torrance back face (m_shade_point)
 *                stays within 1 LSB of the oracle-exact path; unlit
 *                GL_PHONG_WIN draws as GL_SMOOTH; glRasterPos's colours
 *                under Cook-Torrance
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <fixgl/fixgl.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "shade_ref.h"

#define W 16
#define H 16

static unsigned char buf[W * H * 4];

static GLenum error(void)
{
  return glGetError();
}

#define CHECK_ERROR(expected, what)                                          \
  do {                                                                       \
    GLenum e_ = error();                                                     \
    CHECK(e_ == (expected), "%s: error %#x, expected %#x", what, e_,         \
          (unsigned)(expected));                                             \
  } while (0)

static int has_extension(const char *list, const char *name)
{
  size_t n = strlen(name);
  for (const char *t = list; t && *t;) {
    size_t k = strcspn(t, " ");
    if (k == n && strncmp(t, name, n) == 0)
      return 1;
    t += k;
    while (*t == ' ')
      t++;
  }
  return 0;
}

static void test_extensions(void)
{
  const char *ext = (const char *)glGetString(GL_EXTENSIONS);
  CHECK(has_extension(ext, "GL_WIN_phong_shading"), "GL_WIN_phong_shading listed");
  CHECK(has_extension(ext, "GL_FIXGL_cook_torrance"), "GL_FIXGL_cook_torrance listed");
  CHECK_ERROR(GL_NO_ERROR, "glGetString");
}

static GLint get_int(GLenum pname)
{
  GLint v = -1;
  glGetIntegerv(pname, &v);
  return v;
}

static void test_shade_model(void)
{
  glShadeModel(GL_PHONG_WIN);
  CHECK_ERROR(GL_NO_ERROR, "glShadeModel(GL_PHONG_WIN)");
  CHECK(get_int(GL_SHADE_MODEL) == GL_PHONG_WIN, "GL_SHADE_MODEL %#x", get_int(GL_SHADE_MODEL));
  glShadeModel(GL_PHONG_HINT_WIN);
  CHECK_ERROR(GL_INVALID_ENUM, "glShadeModel(GL_PHONG_HINT_WIN)");
  CHECK(get_int(GL_SHADE_MODEL) == GL_PHONG_WIN, "unchanged after the error");
  glBegin(GL_TRIANGLES);
  glShadeModel(GL_FLAT);
  glEnd();
  CHECK_ERROR(GL_INVALID_OPERATION, "glShadeModel inside glBegin/glEnd");
  CHECK(get_int(GL_SHADE_MODEL) == GL_PHONG_WIN, "unchanged inside glBegin/glEnd");

  /* GL_LIGHTING_BIT */
  glPushAttrib(GL_LIGHTING_BIT);
  glShadeModel(GL_FLAT);
  glPopAttrib();
  CHECK(get_int(GL_SHADE_MODEL) == GL_PHONG_WIN, "GL_LIGHTING_BIT restores GL_PHONG_WIN");
  glShadeModel(GL_SMOOTH);
  glPushAttrib(GL_LIGHTING_BIT);
  glShadeModel(GL_PHONG_WIN);
  glPopAttrib();
  CHECK(get_int(GL_SHADE_MODEL) == GL_SMOOTH, "GL_LIGHTING_BIT restores GL_SMOOTH");
  glPushAttrib(GL_ENABLE_BIT);
  glShadeModel(GL_PHONG_WIN);
  glPopAttrib();
  CHECK(get_int(GL_SHADE_MODEL) == GL_PHONG_WIN, "not in GL_ENABLE_BIT");
  glShadeModel(GL_SMOOTH);

  /* display lists */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glShadeModel(GL_PHONG_WIN);
  glEndList();
  CHECK(get_int(GL_SHADE_MODEL) == GL_SMOOTH, "GL_COMPILE does not execute");
  glCallList(list);
  CHECK(get_int(GL_SHADE_MODEL) == GL_PHONG_WIN, "the list sets GL_PHONG_WIN");
  glShadeModel(GL_SMOOTH);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glShadeModel(GL_PHONG_WIN);
  glEndList();
  CHECK(get_int(GL_SHADE_MODEL) == GL_PHONG_WIN, "GL_COMPILE_AND_EXECUTE executes");
  glShadeModel(GL_SMOOTH);
  glCallList(list);
  CHECK(get_int(GL_SHADE_MODEL) == GL_PHONG_WIN, "and compiles");
  glDeleteLists(list, 1);
  glShadeModel(GL_SMOOTH);
  CHECK_ERROR(GL_NO_ERROR, "shade model lists");

  /* glHint(GL_PHONG_HINT_WIN) */
  CHECK(get_int(GL_PHONG_HINT_WIN) == GL_DONT_CARE, "hint default");
  glHint(GL_PHONG_HINT_WIN, GL_NICEST);
  CHECK_ERROR(GL_NO_ERROR, "glHint(GL_PHONG_HINT_WIN, GL_NICEST)");
  CHECK(get_int(GL_PHONG_HINT_WIN) == GL_NICEST, "hint set");
  glHint(GL_PHONG_HINT_WIN, GL_PHONG_WIN);
  CHECK_ERROR(GL_INVALID_ENUM, "glHint(bad mode)");
  glHint(GL_PHONG_WIN, GL_FASTEST);
  CHECK_ERROR(GL_INVALID_ENUM, "glHint(GL_PHONG_WIN)");
  CHECK(get_int(GL_PHONG_HINT_WIN) == GL_NICEST, "hint unchanged after errors");
  glPushAttrib(GL_HINT_BIT);
  glHint(GL_PHONG_HINT_WIN, GL_FASTEST);
  CHECK(get_int(GL_PHONG_HINT_WIN) == GL_FASTEST, "hint changed");
  glPopAttrib();
  CHECK(get_int(GL_PHONG_HINT_WIN) == GL_NICEST, "GL_HINT_BIT restores the hint");
  glHint(GL_PHONG_HINT_WIN, GL_DONT_CARE);
  CHECK_ERROR(GL_NO_ERROR, "hint");
}

/* The four reflectance values of a face, through glGetMaterialfv. */
struct refl {
  float model, roughness, metalness, f0;
};

static struct refl get_refl(GLenum face)
{
  struct refl r = { -1, -1, -1, -1 };
  glGetMaterialfv(face, GL_REFLECTANCE_MODEL_FIXGL, &r.model);
  glGetMaterialfv(face, GL_ROUGHNESS_FIXGL, &r.roughness);
  glGetMaterialfv(face, GL_METALNESS_FIXGL, &r.metalness);
  glGetMaterialfv(face, GL_DIELECTRIC_F0_FIXGL, &r.f0);
  return r;
}

static int refl_is(GLenum face, GLenum model, float roughness, float metalness, float f0)
{
  const struct refl r = get_refl(face);
  return r.model == (float)model && r.roughness == roughness && r.metalness == metalness &&
         r.f0 == f0;
}

static void reset_refl(void)
{
  glMateriali(GL_FRONT_AND_BACK, GL_REFLECTANCE_MODEL_FIXGL, GL_BLINN_PHONG_FIXGL);
  glMaterialf(GL_FRONT_AND_BACK, GL_ROUGHNESS_FIXGL, 0.5f);
  glMaterialf(GL_FRONT_AND_BACK, GL_METALNESS_FIXGL, 0.0f);
  glMaterialf(GL_FRONT_AND_BACK, GL_DIELECTRIC_F0_FIXGL, 0.04f);
}

static void test_material(void)
{
  /* defaults */
  CHECK(refl_is(GL_FRONT, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "front defaults");
  CHECK(refl_is(GL_BACK, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "back defaults");
  GLint iv[4] = { -1, -1, -1, -1 };
  glGetMaterialiv(GL_FRONT, GL_REFLECTANCE_MODEL_FIXGL, iv);
  CHECK(iv[0] == GL_BLINN_PHONG_FIXGL && iv[1] == -1, "glGetMaterialiv model %#x", iv[0]);
  CHECK_ERROR(GL_NO_ERROR, "defaults");

  /* every setter, per face */
  glMateriali(GL_FRONT, GL_REFLECTANCE_MODEL_FIXGL, GL_COOK_TORRANCE_FIXGL);
  CHECK(refl_is(GL_FRONT, GL_COOK_TORRANCE_FIXGL, 0.5f, 0.0f, 0.04f), "glMateriali front");
  CHECK(refl_is(GL_BACK, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "back untouched");
  glMaterialf(GL_BACK, GL_ROUGHNESS_FIXGL, 0.25f);
  const GLfloat metal = 0.75f;
  glMaterialfv(GL_FRONT_AND_BACK, GL_METALNESS_FIXGL, &metal);
  const GLint model = GL_COOK_TORRANCE_FIXGL, one = 1;
  glMaterialiv(GL_BACK, GL_REFLECTANCE_MODEL_FIXGL, &model);
  glMaterialiv(GL_FRONT, GL_DIELECTRIC_F0_FIXGL, &one);
  CHECK(refl_is(GL_FRONT, GL_COOK_TORRANCE_FIXGL, 0.5f, 0.75f, 1.0f), "front set");
  CHECK(refl_is(GL_BACK, GL_COOK_TORRANCE_FIXGL, 0.25f, 0.75f, 0.04f), "back set");
  glMaterialf(GL_FRONT_AND_BACK, GL_ROUGHNESS_FIXGL, 0.0f);
  glMaterialf(GL_FRONT_AND_BACK, GL_ROUGHNESS_FIXGL, 1.0f);
  CHECK(refl_is(GL_FRONT, GL_COOK_TORRANCE_FIXGL, 1.0f, 0.75f, 1.0f), "range ends");
  CHECK_ERROR(GL_NO_ERROR, "setters");
  /* glGetMaterialiv rounds */
  glMaterialf(GL_FRONT, GL_ROUGHNESS_FIXGL, 0.75f);
  glMaterialf(GL_FRONT, GL_METALNESS_FIXGL, 0.25f);
  glGetMaterialiv(GL_FRONT, GL_ROUGHNESS_FIXGL, &iv[0]);
  glGetMaterialiv(GL_FRONT, GL_METALNESS_FIXGL, &iv[1]);
  glGetMaterialiv(GL_BACK, GL_REFLECTANCE_MODEL_FIXGL, &iv[2]);
  CHECK(iv[0] == 1 && iv[1] == 0 && iv[2] == GL_COOK_TORRANCE_FIXGL, "iv %d %d %#x", iv[0],
        iv[1], iv[2]);
  reset_refl();
  CHECK(refl_is(GL_FRONT, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "reset front");
  CHECK(refl_is(GL_BACK, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "reset back");

  /* errors, state unchanged */
  glMaterialf(GL_FRONT, GL_REFLECTANCE_MODEL_FIXGL, (GLfloat)GL_SMOOTH);
  CHECK_ERROR(GL_INVALID_ENUM, "bad model");
  glMaterialf(GL_FRONT, GL_REFLECTANCE_MODEL_FIXGL, (GLfloat)GL_COOK_TORRANCE_FIXGL + 0.5f);
  CHECK_ERROR(GL_INVALID_ENUM, "a model between the enums");
  glMateriali(GL_FRONT, GL_ROUGHNESS_FIXGL, 2);
  CHECK_ERROR(GL_INVALID_VALUE, "roughness 2");
  glMaterialf(GL_BACK, GL_ROUGHNESS_FIXGL, -0.001f);
  CHECK_ERROR(GL_INVALID_VALUE, "roughness < 0");
  glMaterialf(GL_FRONT_AND_BACK, GL_METALNESS_FIXGL, 1.001f);
  CHECK_ERROR(GL_INVALID_VALUE, "metalness > 1");
  glMaterialf(GL_FRONT, GL_DIELECTRIC_F0_FIXGL, NAN);
  CHECK_ERROR(GL_INVALID_VALUE, "f0 NaN");
  glMaterialf(GL_FRONT, GL_DIELECTRIC_F0_FIXGL, INFINITY);
  CHECK_ERROR(GL_INVALID_VALUE, "f0 inf");
  glMaterialf(GL_LEFT, GL_ROUGHNESS_FIXGL, 0.25f);
  CHECK_ERROR(GL_INVALID_ENUM, "bad face");
  glMaterialf(GL_LEFT, GL_ROUGHNESS_FIXGL, 5.0f);
  CHECK_ERROR(GL_INVALID_ENUM, "bad face before a bad value");
  glMaterialf(GL_FRONT, GL_REFLECTANCE_MODEL_FIXGL + 6, 0.25f);
  CHECK_ERROR(GL_INVALID_ENUM, "an unknown pname next to the range");
  glBegin(GL_POINTS);
  glMaterialf(GL_FRONT, GL_ROUGHNESS_FIXGL, 0.25f);
  glMateriali(GL_FRONT, GL_REFLECTANCE_MODEL_FIXGL, GL_COOK_TORRANCE_FIXGL);
  glEnd();
  CHECK_ERROR(GL_INVALID_OPERATION, "inside glBegin/glEnd");
  CHECK(refl_is(GL_FRONT, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "errors change nothing");
  CHECK(refl_is(GL_BACK, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "errors change nothing");
  float f = -1.0f;
  glGetMaterialfv(GL_FRONT_AND_BACK, GL_ROUGHNESS_FIXGL, &f);
  CHECK_ERROR(GL_INVALID_ENUM, "glGetMaterialfv(GL_FRONT_AND_BACK)");
  CHECK(f == -1.0f, "nothing written");
  glGetMaterialiv(GL_FRONT, GL_REFLECTANCE_MODEL_FIXGL + 6, iv);
  CHECK_ERROR(GL_INVALID_ENUM, "glGetMaterialiv(bad pname)");
  glColorMaterial(GL_FRONT, GL_ROUGHNESS_FIXGL);
  CHECK_ERROR(GL_INVALID_ENUM, "glColorMaterial(GL_ROUGHNESS_FIXGL)");
  glColorMaterial(GL_FRONT, GL_REFLECTANCE_MODEL_FIXGL);
  CHECK_ERROR(GL_INVALID_ENUM, "glColorMaterial(GL_REFLECTANCE_MODEL_FIXGL)");
  CHECK(get_int(GL_COLOR_MATERIAL_PARAMETER) == GL_AMBIENT_AND_DIFFUSE, "unchanged");

  /* GL_LIGHTING_BIT saves them; GL_CURRENT_BIT does not */
  glMateriali(GL_BACK, GL_REFLECTANCE_MODEL_FIXGL, GL_COOK_TORRANCE_FIXGL);
  glPushAttrib(GL_LIGHTING_BIT);
  glMaterialf(GL_FRONT_AND_BACK, GL_ROUGHNESS_FIXGL, 0.125f);
  glMateriali(GL_BACK, GL_REFLECTANCE_MODEL_FIXGL, GL_BLINN_PHONG_FIXGL);
  glMaterialf(GL_FRONT, GL_DIELECTRIC_F0_FIXGL, 0.5f);
  glPopAttrib();
  CHECK(refl_is(GL_FRONT, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "front restored");
  CHECK(refl_is(GL_BACK, GL_COOK_TORRANCE_FIXGL, 0.5f, 0.0f, 0.04f), "back restored");
  glPushAttrib(GL_CURRENT_BIT | GL_ENABLE_BIT);
  glMaterialf(GL_FRONT, GL_METALNESS_FIXGL, 0.5f);
  glPopAttrib();
  CHECK(refl_is(GL_FRONT, GL_BLINN_PHONG_FIXGL, 0.5f, 0.5f, 0.04f), "not GL_CURRENT_BIT");
  reset_refl();
  CHECK_ERROR(GL_NO_ERROR, "push/pop");

  /* display lists */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMateriali(GL_FRONT, GL_REFLECTANCE_MODEL_FIXGL, GL_COOK_TORRANCE_FIXGL);
  glMaterialf(GL_BACK, GL_ROUGHNESS_FIXGL, 0.125f);
  glMaterialf(GL_FRONT, GL_METALNESS_FIXGL, 2.0f);   /* the error comes at execution */
  glEndList();
  CHECK_ERROR(GL_NO_ERROR, "compiling: no value check");
  CHECK(refl_is(GL_FRONT, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "GL_COMPILE: unchanged");
  CHECK(refl_is(GL_BACK, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "GL_COMPILE: unchanged");
  glCallList(list);
  CHECK_ERROR(GL_INVALID_VALUE, "executing: the metalness error");
  CHECK(refl_is(GL_FRONT, GL_COOK_TORRANCE_FIXGL, 0.5f, 0.0f, 0.04f), "list: front");
  CHECK(refl_is(GL_BACK, GL_BLINN_PHONG_FIXGL, 0.125f, 0.0f, 0.04f), "list: back");
  reset_refl();
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glMaterialf(GL_FRONT_AND_BACK, GL_DIELECTRIC_F0_FIXGL, 0.25f);
  glEndList();
  CHECK(refl_is(GL_BACK, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.25f), "compile and execute");
  reset_refl();
  glCallList(list);
  CHECK(refl_is(GL_FRONT, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.25f), "compiled too");
  reset_refl();
  glNewList(list, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glMaterialf(GL_FRONT, GL_ROUGHNESS_FIXGL, 0.25f);
  glEnd();
  glEndList();
  CHECK_ERROR(GL_NO_ERROR, "GL_COMPILE: the error is compiled");
  glCallList(list);
  CHECK_ERROR(GL_INVALID_OPERATION, "inside glBegin/glEnd in a list");
  CHECK(refl_is(GL_FRONT, GL_BLINN_PHONG_FIXGL, 0.5f, 0.0f, 0.04f), "list error: unchanged");
  glNewList(list, GL_COMPILE);
  glMaterialf(GL_LEFT, GL_ROUGHNESS_FIXGL, 0.25f);
  glEndList();
  glCallList(list);
  CHECK_ERROR(GL_INVALID_ENUM, "a bad face in a list");
  glDeleteLists(list, 1);
  CHECK_ERROR(GL_NO_ERROR, "lists");
}

/* ---- rendering ---- */

static void setup_view(void)
{
  glViewport(0, 0, W, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -10, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
}

static const unsigned char *pixel(int x, int y)
{
  glFinish();
  return buf + ((size_t)y * W + (size_t)x) * 4;
}

/* The fixgl state of one scene, mirrored into the double reference. */
struct scene {
  struct shade_ref_env env;
  struct shade_ref_material mat[2];
  bool two_side, color_material;   /* colour material: GL_DIFFUSE of both faces */
};

static void apply_scene(const struct scene *s)
{
  glDisable(GL_COLOR_MATERIAL);   /* every material below is set */
  for (int i = 0; i < 8; i++)
    glDisable(GL_LIGHT0 + i);
  for (int i = 0; i < s->env.num_lights; i++) {
    const struct shade_ref_light *l = &s->env.light[i];
    float v[4];
#define SETL(pname, src, n)                    \
  for (int k = 0; k < 4; k++)                  \
    v[k] = k < (n) ? (float)(src)[k] : 1.0f;   \
  glLightfv(GL_LIGHT0 + i, pname, v);
    SETL(GL_AMBIENT, l->ambient, 3);
    SETL(GL_DIFFUSE, l->diffuse, 3);
    SETL(GL_SPECULAR, l->specular, 3);
    SETL(GL_POSITION, l->position, 4);
#undef SETL
    glLightf(GL_LIGHT0 + i, GL_CONSTANT_ATTENUATION, (float)l->kc);
    glLightf(GL_LIGHT0 + i, GL_LINEAR_ATTENUATION, (float)l->kl);
    glLightf(GL_LIGHT0 + i, GL_QUADRATIC_ATTENUATION, (float)l->kq);
    glEnable(GL_LIGHT0 + i);
  }
  const float ga[4] = { (float)s->env.global_ambient[0], (float)s->env.global_ambient[1],
                        (float)s->env.global_ambient[2], 1.0f };
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ga);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, s->env.local_viewer);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, s->two_side);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL,
                s->env.separate_specular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
  for (int f = 0; f < 2; f++) {
    const GLenum face = f ? GL_BACK : GL_FRONT;
    const struct shade_ref_material *m = &s->mat[f];
    float v[4];
#define SETM(pname, src, n)                    \
  for (int k = 0; k < 4; k++)                  \
    v[k] = k < (n) ? (float)(src)[k] : 1.0f;   \
  glMaterialfv(face, pname, v);
    SETM(GL_AMBIENT, m->ambient, 3);
    SETM(GL_DIFFUSE, m->diffuse, 4);
    SETM(GL_SPECULAR, m->specular, 3);
    SETM(GL_EMISSION, m->emission, 3);
#undef SETM
    glMaterialf(face, GL_SHININESS, (float)m->shininess);
    glMateriali(face, GL_REFLECTANCE_MODEL_FIXGL,
                m->cook_torrance ? GL_COOK_TORRANCE_FIXGL : GL_BLINN_PHONG_FIXGL);
    glMaterialf(face, GL_ROUGHNESS_FIXGL, (float)m->roughness);
    glMaterialf(face, GL_METALNESS_FIXGL, (float)m->metalness);
    glMaterialf(face, GL_DIELECTRIC_F0_FIXGL, (float)m->f0);
  }
  glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
  if (s->color_material)
    glEnable(GL_COLOR_MATERIAL);
  else
    glDisable(GL_COLOR_MATERIAL);
  glEnable(GL_LIGHTING);
}

/* Compares the pixel with the reference colour (primary + secondary,
 * clamped) within 1 LSB; returns the largest difference. */
static int compare_pixel(const char *what, int x, int y, const double prim[4],
                         const double sec[3])
{
  const unsigned char *p = pixel(x, y);
  int worst = 0;
  for (int k = 0; k < 4; k++) {
    double v = prim[k] + (k < 3 ? sec[k] : 0.0);
    v = v > 1.0 ? 1.0 : v;
    const int d = abs((int)p[k] - (int)lrint(v * 255.0));
    if (d > worst)
      worst = d;
  }
  CHECK(worst <= 1, "%s: pixel (%d,%d) = %d %d %d %d, reference %.1f %.1f %.1f %.1f", what, x,
        y, p[0], p[1], p[2], p[3], (prim[0] + sec[0]) * 255, (prim[1] + sec[1]) * 255,
        (prim[2] + sec[2]) * 255, prim[3] * 255);
  return worst;
}

/* How a triangle is drawn. */
enum draw { IMMEDIATE, ARRAYS, LIST, SMOOTH };

/* One flat-shaded triangle covering the pixel at the centre, its provoking
 * (last) vertex at eye position pv with normal n and colour c, lit by the
 * scene; the pixel is checked against the reference at that vertex.  The
 * first vertices get other colours and normals (a black colour, the
 * normal reversed), except for SMOOTH, which draws a GL_SMOOTH triangle
 * whose vertices are all the same (for a scene that lights them alike). */
static void draw_triangle(const char *what, const struct scene *s, const float n[3],
                          const float pv[3], const float c[4], bool back, enum draw how)
{
  setup_view();
  apply_scene(s);
  glShadeModel(how == SMOOTH ? GL_SMOOTH : GL_FLAT);
  /* counter-clockwise (front) or clockwise (back) around the centre */
  const float x1 = back ? 0.0f : 0.9f, y1 = back ? 0.9f : -0.9f;
  const float x2 = back ? 0.9f : 0.0f, y2 = back ? -0.9f : 0.9f;
  const float black[4] = { 0, 0, 0, 1 };
  const float *c0 = how == SMOOTH ? c : black;
  const float n0[3] = { how == SMOOTH ? n[0] : -n[0], how == SMOOTH ? n[1] : -n[1],
                        how == SMOOTH ? n[2] : -n[2] };
  const float pos[9] = { -0.9f, -0.9f, pv[2], x1, y1, pv[2], x2, y2, pv[2] };
  const float col[12] = { c0[0], c0[1], c0[2], c0[3], c0[0], c0[1], c0[2], c0[3],
                          c[0], c[1], c[2], c[3] };
  const float nrm[9] = { n0[0], n0[1], n0[2], n0[0], n0[1], n0[2], n[0], n[1], n[2] };
  GLuint list = 0;
  if (how == LIST) {
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
  }
  if (how == ARRAYS) {
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glColorPointer(4, GL_FLOAT, 0, col);
    glNormalPointer(GL_FLOAT, 0, nrm);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
  } else {
    glBegin(GL_TRIANGLES);
    for (int v = 0; v < 3; v++) {
      glColor4fv(col + 4 * v);
      glNormal3fv(nrm + 3 * v);
      glVertex3fv(pos + 3 * v);
    }
    glEnd();
  }
  if (how == LIST) {
    glEndList();
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(list);
    glDeleteLists(list, 1);
  }
  glShadeModel(GL_SMOOTH);
  /* the reference at the provoking vertex */
  const double P[3] = { back ? 0.9 : 0.0, back ? -0.9 : 0.9, pv[2] };
  struct shade_ref_material m = s->mat[back && s->two_side ? 1 : 0];
  if (s->color_material)
    for (int k = 0; k < 4; k++)
      m.diffuse[k] = c[k];
  double nn[3] = { n[0], n[1], n[2] };
  if (back && s->two_side)
    for (int k = 0; k < 3; k++)
      nn[k] = -nn[k];
  double prim[4], sec[3], un[6];
  shade_ref_point(&s->env, &m, nn, P, prim, sec, un);
  compare_pixel(what, W / 2, H / 2, prim, sec);
}

static void flat_triangle(const char *what, const struct scene *s, const float n[3],
                          const float pv[3], const float c[4], bool back)
{
  draw_triangle(what, s, n, pv, c, back, IMMEDIATE);
}

static void base_scene(struct scene *s)
{
  memset(s, 0, sizeof(*s));
  s->env.num_lights = 1;
  struct shade_ref_light *l = &s->env.light[0];
  for (int k = 0; k < 3; k++) {
    l->ambient[k] = 0.05;
    l->diffuse[k] = 0.6;
    l->specular[k] = 0.5;
  }
  l->position[0] = 0.3;
  l->position[1] = 0.4;
  l->position[2] = 1.0;
  l->kc = 1.0;
  l->spot_cutoff_cos = -2.0;   /* no spot */
  s->env.global_ambient[0] = s->env.global_ambient[1] = s->env.global_ambient[2] = 0.1;
  for (int f = 0; f < 2; f++) {
    struct shade_ref_material *m = &s->mat[f];
    m->cook_torrance = true;
    for (int k = 0; k < 3; k++) {
      m->ambient[k] = 0.2;
      m->specular[k] = 0.8;
    }
    m->diffuse[0] = f ? 0.2 : 0.7;
    m->diffuse[1] = 0.45;
    m->diffuse[2] = f ? 0.8 : 0.25;
    m->diffuse[3] = 1.0;
    m->shininess = 20.0;
    m->roughness = 0.5;
    m->f0 = 0.04;
  }
}

static void test_render_cook_torrance(void)
{
  struct scene s;
  const float n[3] = { 0.0f, 0.0f, 1.0f }, tilted[3] = { 0.2f, -0.1f, 0.9f };
  const float pv[3] = { 0.0f, 0.9f, -1.0f }, white[4] = { 1, 1, 1, 1 };
  const float orange[4] = { 1.0f, 0.5f, 0.125f, 0.75f };

  base_scene(&s);
  flat_triangle("CT dielectric, directional", &s, n, pv, white, false);
  flat_triangle("CT tilted normal", &s, tilted, pv, white, false);
  s.mat[0].metalness = 1.0;
  s.mat[0].roughness = 0.25;
  flat_triangle("CT metal", &s, tilted, pv, white, false);
  s.mat[0].metalness = 0.4;
  s.mat[0].roughness = 1.0;
  s.mat[0].f0 = 0.5;
  s.env.separate_specular = true;
  flat_triangle("CT separate specular", &s, tilted, pv, white, false);

  /* a local viewer, a point light with attenuation */
  base_scene(&s);
  s.env.local_viewer = true;
  s.env.light[0].position[0] = 0.5;
  s.env.light[0].position[1] = 2.0;
  s.env.light[0].position[2] = 1.0;
  s.env.light[0].position[3] = 1.0;
  s.env.light[0].kl = 0.2;
  s.env.light[0].kq = 0.05;
  flat_triangle("CT point light, local viewer", &s, tilted, pv, white, false);
  s.mat[0].roughness = 0.05;
  s.env.light[0].specular[0] = 0.01;
  flat_triangle("CT roughness 0.05", &s, tilted, pv, white, false);

  /* two-sided: a clockwise triangle shows its back material */
  base_scene(&s);
  s.two_side = true;
  s.mat[1].roughness = 0.3;
  s.mat[1].metalness = 0.6;
  const float away[3] = { 0.1f, 0.2f, -0.9f };
  flat_triangle("CT two-sided back face", &s, away, pv, white, true);
  flat_triangle("CT two-sided front face", &s, tilted, pv, white, false);
  s.two_side = false;
  flat_triangle("CT back face without two-sided", &s, tilted, pv, white, true);

  /* colour material: the provoking vertex's colour is the base colour */
  base_scene(&s);
  s.color_material = true;
  s.mat[0].metalness = 0.5;
  flat_triangle("CT colour material", &s, tilted, pv, orange, false);
  draw_triangle("CT colour material, vertex arrays", &s, tilted, pv, orange, false, ARRAYS);
  draw_triangle("CT colour material, display list", &s, tilted, pv, orange, false, LIST);
  /* GL_SMOOTH: a directional light and an infinite viewer light every
   * vertex alike */
  draw_triangle("CT colour material, GL_SMOOTH", &s, tilted, pv, orange, false, SMOOTH);
  s.mat[0].roughness = 0.1;
  s.mat[0].metalness = 1.0;
  draw_triangle("CT metal, GL_SMOOTH", &s, n, pv, orange, false, SMOOTH);

  /* a Blinn-Phong front face drawn through m_shade_point (the back face
   * is Cook-Torrance) */
  base_scene(&s);
  s.mat[0].cook_torrance = false;
  flat_triangle("Blinn-Phong face in a CT draw", &s, tilted, pv, white, false);

  /* glRasterPos lights the raster position like a vertex (front face) */
  base_scene(&s);
  s.env.local_viewer = true;
  s.env.separate_specular = true;
  s.env.light[0].position[3] = 1.0;
  s.env.light[0].kl = 0.25;
  s.mat[0].roughness = 0.3;
  s.mat[0].metalness = 0.5;
  setup_view();
  apply_scene(&s);
  glNormal3fv(tilted);
  glRasterPos3f(0.25f, -0.5f, -1.5f);
  float rc[4], rs[4];
  glGetFloatv(GL_CURRENT_RASTER_COLOR, rc);
  /* GL 1.5 has no query of the raster secondary colour (GL 3.0's
   * GL_CURRENT_RASTER_SECONDARY_COLOR raises GL_INVALID_ENUM: README
   * "Version and honesty"); the same raster position without separate
   * specular shows the sum in GL_CURRENT_RASTER_COLOR */
  glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, rs);
  CHECK_ERROR(GL_INVALID_ENUM, "raster secondary colour query");
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glRasterPos3f(0.25f, -0.5f, -1.5f);
  glGetFloatv(GL_CURRENT_RASTER_COLOR, rs);
  {
    const double n3[3] = { tilted[0], tilted[1], tilted[2] }, P[3] = { 0.25, -0.5, -1.5 };
    double prim[4], sec[3], un[6];
    shade_ref_point(&s.env, &s.mat[0], n3, P, prim, sec, un);
    double worst = 0.0;
    for (int k = 0; k < 4; k++)
      worst = fmax(worst, fabs(rc[k] - prim[k]));
    for (int k = 0; k < 3; k++)
      worst = fmax(worst, fabs(rs[k] - fmin(1.0, prim[k] + sec[k])));
    CHECK(worst < 1e-5, "raster colour %g %g %g %g, summed %g %g %g vs %g %g %g %g + %g %g %g",
          rc[0], rc[1], rc[2], rc[3], rs[0], rs[1], rs[2], prim[0], prim[1], prim[2], prim[3],
          sec[0], sec[1], sec[2]);
    CHECK(sec[0] > 0.0 && prim[0] > sec[0], "a lit raster position");
  }

  glDisable(GL_LIGHTING);
  glDisable(GL_COLOR_MATERIAL);
  reset_refl();
  CHECK_ERROR(GL_NO_ERROR, "rendering");
}

/* A smooth Blinn-Phong scene: a fan of triangles with varying normals, a
 * point light, a local viewer, specular highlights. */
static void draw_bp_scene(void)
{
  setup_view();
  const float pos[4] = { 0.5f, 0.8f, 2.0f, 1.0f }, spec[4] = { 1, 1, 1, 1 };
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
  glEnable(GL_LIGHTING);
  /* GL's per-vertex lighting uses the normal as given, shading.md's
   * equations a normalised one: the same with GL_NORMALIZE */
  glEnable(GL_NORMALIZE);
  glBegin(GL_TRIANGLE_FAN);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glVertex3f(0.0f, 0.0f, 0.0f);
  for (int i = 0; i <= 8; i++) {
    const float a = (float)i * 0.785398f;
    glNormal3f(cosf(a) * 0.7f, sinf(a) * 0.7f, 0.5f);
    glVertex3f(cosf(a), sinf(a), -0.3f);
  }
  glEnd();
  glDisable(GL_LIGHTING);
  glDisable(GL_NORMALIZE);
  glFinish();
}

static void test_render_paths(void)
{
  static unsigned char a[W * H * 4], b[W * H * 4];
  draw_bp_scene();
  memcpy(a, buf, sizeof(a));
  /* (a metal: a dielectric's diffuse term is GL's) */
  glMateriali(GL_FRONT_AND_BACK, GL_REFLECTANCE_MODEL_FIXGL, GL_COOK_TORRANCE_FIXGL);
  glMaterialf(GL_FRONT_AND_BACK, GL_METALNESS_FIXGL, 1.0f);
  draw_bp_scene();
  CHECK(memcmp(a, buf, sizeof(a)) != 0, "Cook-Torrance changes the image");
  glMateriali(GL_FRONT_AND_BACK, GL_REFLECTANCE_MODEL_FIXGL, GL_BLINN_PHONG_FIXGL);
  draw_bp_scene();
  CHECK(memcmp(a, buf, sizeof(a)) == 0, "back to Blinn-Phong: the same image");

  /* the front face's Blinn-Phong through m_shade_point: within 1 LSB */
  glMateriali(GL_BACK, GL_REFLECTANCE_MODEL_FIXGL, GL_COOK_TORRANCE_FIXGL);
  draw_bp_scene();
  int worst = 0, differ = 0;
  for (size_t i = 0; i < sizeof(a); i++) {
    const int d = abs((int)a[i] - (int)buf[i]);
    worst = d > worst ? d : worst;
    differ += d != 0;
  }
  printf("Blinn-Phong through m_shade_point: %d of %zu channels differ, by at most %d\n",
         differ, sizeof(a), worst);
  CHECK(worst <= 1, "m_shade_point's Blinn-Phong within 1 LSB of t_light's: %d", worst);
  reset_refl();

  /* unlit GL_PHONG_WIN is GL_SMOOTH */
  for (int mode = 0; mode < 2; mode++) {
    setup_view();
    glShadeModel(mode ? GL_PHONG_WIN : GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex2f(-1, -1);
    glColor3f(0, 1, 0);
    glVertex2f(1, -1);
    glColor3f(0, 0, 1);
    glVertex2f(0, 1);
    glEnd();
    glFinish();
    memcpy(mode ? b : a, buf, sizeof(a));
  }
  glShadeModel(GL_SMOOTH);
  CHECK(memcmp(a, b, sizeof(a)) == 0, "unlit GL_PHONG_WIN draws as GL_SMOOTH");
  CHECK_ERROR(GL_NO_ERROR, "paths");
}

int main(void)
{
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
    FAIL("no context");
    return check_report("shading");
  }
  test_extensions();
  test_shade_model();
  test_material();
  test_render_cook_torrance();
  test_render_paths();
  OSMesaDestroyContext(ctx);
  return check_report("shading");
}
