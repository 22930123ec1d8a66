/*
 * vertex_cache.c - glDrawElements through the vertex stage's post-transform
 * vertex cache (tnl/t_array.c) draws what glDrawArrays draws from the same
 * vertices written out in index order, which transforms and lights every
 * index on its own: the cache may only share work, never change a bit.
 *
 * The index lists reuse vertices near and far (a grid's shared corners),
 * collide in the cache (elements 256 apart, the cache's direct-mapped
 * slots), repeat an element within a triangle, and one draw is larger than
 * the scratch memory the vertex stage keeps (FGL_VBO_SCRATCH_KEEP) and is
 * followed by a small one.  Unlit colours, two-sided lighting with a spot
 * light and an attenuated point light, fog and texture coordinates
 * exercise every per-vertex output; triangles, strips, lines and points
 * every assembly (quads are left out: llvmpipe splits an indexed quad on
 * the other diagonal, so the two draws differ there by design).
 * Built against libfixgl only (suite api).
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define W 96
#define H 80
#define GRID 40                      /* GRID x GRID vertices */
#define NV (GRID * GRID + 256 * 3)   /* the grid, then cache colliders */

static float pos[NV][3], nrm[NV][3], col[NV][4], tex[NV][2];
static GLuint idx[80000];
static float xpos[80000][3], xnrm[80000][3], xcol[80000][4], xtex[80000][2];
static unsigned char img_a[W * H * 4], img_b[W * H * 4];
static unsigned char fb[W * H * 4];

static void build_vertices(void)
{
  for (int i = 0; i < NV; i++) {
    const int gx = i % GRID, gy = (i / GRID) % GRID;
    const float x = -1.2f + 2.4f * (float)gx / (GRID - 1) + (i >= GRID * GRID ? 0.013f : 0.0f);
    const float y = -1.1f + 2.2f * (float)gy / (GRID - 1);
    pos[i][0] = x;
    pos[i][1] = y;
    pos[i][2] = 0.3f * sinf(3.0f * x) * cosf(2.0f * y);
    const float nx = -0.9f * cosf(3.0f * x) * cosf(2.0f * y), ny = 0.6f * sinf(3.0f * x) * sinf(2.0f * y);
    const float len = sqrtf(nx * nx + ny * ny + 1.0f);
    nrm[i][0] = nx / len, nrm[i][1] = ny / len, nrm[i][2] = (i & 7) == 3 ? -1.0f / len : 1.0f / len;
    col[i][0] = 0.5f + 0.5f * x, col[i][1] = 0.5f + 0.5f * y, col[i][2] = (float)(i % 7) / 6.0f;
    col[i][3] = 1.0f;
    tex[i][0] = x * 2.0f, tex[i][1] = y * 3.0f;
  }
}

/* count indices for mode: grid triangles with far and colliding reuse */
static int build_indices(GLenum mode, int count)
{
  int n = 0;
  for (int k = 0; n < count; k++) {
    const int cell = k % ((GRID - 1) * (GRID - 1));
    const int cx = cell % (GRID - 1), cy = cell / (GRID - 1);
    const GLuint a = (GLuint)(cy * GRID + cx), b = a + GRID;
    GLuint tri[6] = { a, b, b + 1, a, b + 1, a + 1 };
    if (k % 5 == 1)
      tri[3] = (GLuint)(GRID * GRID + (a % 256));   /* slot of a, another element */
    if (k % 11 == 4)
      tri[5] = tri[4];                              /* a repeated element */
    if (k % 13 == 7)
      tri[1] = (GLuint)(GRID * GRID + 256 + (b % 512));
    for (int j = 0; j < 6 && n < count; j++)
      idx[n++] = tri[j];
  }
  (void)mode;
  return n;
}

static void set_arrays(const float (*p)[3], const float (*nr)[3], const float (*c)[4],
                       const float (*t)[2])
{
  glVertexPointer(3, GL_FLOAT, 0, p);
  glNormalPointer(GL_FLOAT, 0, nr);
  glColorPointer(4, GL_FLOAT, 0, c);
  glTexCoordPointer(2, GL_FLOAT, 0, t);
}

static void setup_state(int variant)
{
  glDisable(GL_LIGHTING);
  glDisable(GL_FOG);
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_DEPTH_TEST);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glShadeModel(variant == 3 ? GL_FLAT : GL_SMOOTH);
  if (variant == 1 || variant == 3) {
    static const GLfloat spot_pos[4] = { 0.5f, 0.8f, 2.0f, 1.0f }, spot_dir[3] = { -0.2f, -0.3f, -1.0f };
    static const GLfloat pt_pos[4] = { -1.0f, 0.2f, 1.0f, 1.0f }, white[4] = { 1, 1, 1, 1 };
    static const GLfloat spec[4] = { 0.8f, 0.7f, 0.5f, 1.0f };
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT2);
    glLightfv(GL_LIGHT0, GL_POSITION, spot_pos);
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, spot_dir);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 40.0f);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 7.0f);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT2, GL_POSITION, pt_pos);
    glLightfv(GL_LIGHT2, GL_DIFFUSE, spec);
    glLightf(GL_LIGHT2, GL_LINEAR_ATTENUATION, 0.4f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, variant == 3);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    glMaterialf(GL_BACK, GL_SHININESS, 5.0f);
    glEnable(GL_COLOR_MATERIAL);
    glEnableClientState(GL_NORMAL_ARRAY);
  }
  if (variant == 2) {
    static const GLfloat fog_col[4] = { 0.2f, 0.3f, 0.4f, 1.0f };
    static const GLubyte texel[4 * 4 * 3] = { 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 0,
                                              0, 255, 255, 255, 0, 255, 90, 90, 90, 200, 100, 50,
                                              10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120,
                                              130, 140, 150, 160, 170, 180, 190, 200, 210, 220, 230, 240 };
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.3f);
    glFogfv(GL_FOG_COLOR, fog_col);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texel);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  }
}

static void draw(GLenum mode, int n, int indexed, unsigned char *img)
{
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (indexed) {
    set_arrays((const float (*)[3])pos, (const float (*)[3])nrm, (const float (*)[4])col,
               (const float (*)[2])tex);
    glDrawElements(mode, n, GL_UNSIGNED_INT, idx);
    /* a small draw after the large one (the scratch arrays freed) */
    glDrawElements(mode, n < 30 ? n : 30, GL_UNSIGNED_INT, idx);
  } else {
    for (int i = 0; i < n; i++) {
      memcpy(xpos[i], pos[idx[i]], sizeof(xpos[i]));
      memcpy(xnrm[i], nrm[idx[i]], sizeof(xnrm[i]));
      memcpy(xcol[i], col[idx[i]], sizeof(xcol[i]));
      memcpy(xtex[i], tex[idx[i]], sizeof(xtex[i]));
    }
    set_arrays((const float (*)[3])xpos, (const float (*)[3])xnrm, (const float (*)[4])xcol,
               (const float (*)[2])xtex);
    glDrawArrays(mode, 0, n);
    glDrawArrays(mode, 0, n < 30 ? n : 30);
  }
  glFinish();
  memcpy(img, fb, sizeof(fb));
}

int main(void)
{
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  CHECK(ctx != NULL, "context");
  if (!ctx || !OSMesaMakeCurrent(ctx, fb, GL_UNSIGNED_BYTE, W, H))
    return check_report("vertex_cache");
  build_vertices();
  glMatrixMode(GL_PROJECTION);
  glFrustum(-0.6, 0.6, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0.0f, 0.0f, -2.6f);
  glRotatef(-35.0f, 1.0f, 0.2f, 0.0f);

  /* the background */
  unsigned char bg[4];
  glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  memcpy(bg, fb, 4);

  static const GLenum modes[] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_LINES, GL_POINTS };
  static const int counts[] = { 6 * (GRID - 1) * (GRID - 1), 75000 };
  for (int v = 0; v < 4; v++)
    for (unsigned m = 0; m < sizeof(modes) / sizeof(modes[0]); m++)
      for (int c = 0; c < 2; c++) {
        if (c == 1 && m != 0)
          continue;   /* the large draw once per variant */
        const int n = build_indices(modes[m], counts[c]);
        setup_state(v);
        draw(modes[m], n, 1, img_a);
        draw(modes[m], n, 0, img_b);
        int diff = 0;
        for (int i = 0; i < W * H * 4; i++)
          diff += img_a[i] != img_b[i];
        CHECK(diff == 0, "variant %d mode 0x%x count %d: %d bytes differ", v, modes[m], n, diff);
        int lit = 0;
        for (int i = 0; i < W * H * 4; i += 4)
          lit += memcmp(&img_a[i], bg, 4) != 0;
        CHECK(lit > 50, "variant %d mode 0x%x: only %d pixels drawn", v, modes[m], lit);
      }
  OSMesaDestroyContext(ctx);
  return check_report("vertex_cache");
}
