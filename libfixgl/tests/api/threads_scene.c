/*
 * threads_scene.c - tile-parallel rendering gives the same bits for every
 * thread count, with several contexts on several threads at once
 * (fixgl only).
 *
 * Four scenes that cover many tiles (a 300x200 buffer: 5x4 tiles of
 * 64x64, the last row and column partial) and the operations that must
 * rasterize the scene first: depth-tested and blended triangles, a
 * mipmapped texture replaced between frames, fog, lines and points of
 * several widths, smooth points and lines, the polygon stipple, lighting;
 * glReadPixels of what was just drawn, fed back through glDrawPixels;
 * glBitmap, glCopyPixels, scissored and masked clears, glAccum.
 *
 * The reference frames are rendered on the main thread with
 * FIXGL_NUM_THREADS=1 (the calling thread rasterizes, no worker).  Then,
 * for FIXGL_NUM_THREADS of 1, 2 and 4, four application threads each
 * create a context and render one scene frame after frame, all at once,
 * sharing the worker pool; every frame must equal its reference byte for
 * byte, colour and depth.
 *
 * THREADS_SCENE_FRAMES=N (2 to 24, default 24) renders the first N frames
 * only: the ThreadSanitizer run in CI takes 8 (.ci/run), which still holds
 * every periodic change of the scenes (their periods are 2 and 3), at a
 * third of the time (170 s there with 24).
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define W 300
#define H 200
#define SCENES 4
#define FRAMES 24
/* the frames rendered (THREADS_SCENE_FRAMES) */
static int nframes = FRAMES;
#define BUF_SIZE (W * H * 4)

static uint8_t texels[3][64 * 64 * 4];

static void make_texels(void)
{
  for (int v = 0; v < 3; v++)
    for (int i = 0; i < 64 * 64; i++) {
      const int x = i % 64, y = i / 64;
      uint8_t *t = &texels[v][4 * i];
      t[0] = (uint8_t)(((x ^ y) & 8) ? 255 : 40 * v);
      t[1] = (uint8_t)(x * 4);
      t[2] = (uint8_t)(y * 4 + 30 * v);
      t[3] = (uint8_t)(128 + x + y);
    }
}

static void projection(void)
{
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1.5, 1.5, -1.0, 1.0, 1.5, 20.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -4.0f);
}

/* depth, blending, a mipmapped texture replaced per frame, fog */
static void scene_depth_tex(int f, GLuint tex)
{
  glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  projection();
  glRotatef(7.0f * (float)f, 0.3f, 1.0f, 0.1f);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 40; i++) {
    const float a = (float)i * 0.61f + 0.05f * (float)f;
    glColor4f(0.5f + 0.5f * sinf(a), 0.5f + 0.5f * cosf(1.3f * a), (float)(i % 5) / 4.0f, 1.0f);
    glVertex3f(1.6f * cosf(a), 1.2f * sinf(a), 0.4f * sinf(3.0f * a));
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(1.6f * cosf(a + 1.0f), 1.2f * sinf(a + 1.7f), -0.5f);
    glColor3f(0.0f, 0.3f, 0.9f);
    glVertex3f(0.2f * cosf(2.0f * a), 0.2f, 0.8f * cosf(a));
  }
  glEnd();
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels[f % 3]);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels[(f + 1) % 3]);
  glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels[(f + 2) % 3]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2.0f);
  glFogf(GL_FOG_END, 8.0f);
  /* a floor, and screen-filling layers over it (work for every tile) */
  glBegin(GL_QUADS);
  glColor4f(1.0f, 1.0f, 1.0f, 0.7f);
  glTexCoord2f(0.0f, 0.0f); glVertex3f(-3.0f, -1.0f, 1.0f);
  glTexCoord2f(6.0f, 0.0f); glVertex3f(3.0f, -1.0f, 1.0f);
  glTexCoord2f(6.0f, 6.0f); glVertex3f(3.0f, -1.0f, -8.0f);
  glTexCoord2f(0.0f, 6.0f); glVertex3f(-3.0f, -1.0f, -8.0f);
  for (int l = 0; l < 6; l++) {
    const float z = 1.2f - 0.3f * (float)l;
    glColor4f(1.0f, 0.8f, 0.6f, 0.2f + 0.1f * (float)l);
    glTexCoord2f(0.0f, 0.0f); glVertex3f(-4.0f, -3.0f, z);
    glTexCoord2f(2.0f + (float)l, 0.0f); glVertex3f(4.0f, -3.0f, z);
    glTexCoord2f(2.0f + (float)l, 3.0f); glVertex3f(4.0f, 3.0f, z);
    glTexCoord2f(0.0f, 3.0f); glVertex3f(-4.0f, 3.0f, z);
  }
  glEnd();
  glDisable(GL_FOG);
  glDisable(GL_BLEND);
  glDisable(GL_TEXTURE_2D);
}

/* lines, points, smooth ones, the polygon stipple; a read-back fed into
 * glDrawPixels; glBitmap */
static void scene_lines_points(int f)
{
  static GLubyte stipple[128];
  for (int i = 0; i < 128; i++)
    stipple[i] = (GLubyte)((i & 4) ? 0xaa : 0x33);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, W, 0.0, H, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (int i = 0; i < 24; i++) {
    glLineWidth(1.0f + (float)(i % 6));
    if (i % 4 == 3)
      glEnable(GL_LINE_SMOOTH);
    glBegin(GL_LINES);
    glColor3f((float)(i % 3) / 2.0f, 1.0f - (float)i / 24.0f, 0.5f);
    glVertex2f(3.0f + 12.0f * (float)i, 5.0f + (float)f);
    glColor3f(1.0f, 0.2f, (float)(i % 2));
    glVertex2f(290.0f - 7.0f * (float)i, 190.0f - 3.0f * (float)f);
    glEnd();
    glDisable(GL_LINE_SMOOTH);
  }
  for (int i = 0; i < 30; i++) {
    glPointSize(1.0f + (float)(i % 9));
    if (i % 5 == 4)
      glEnable(GL_POINT_SMOOTH);
    glBegin(GL_POINTS);
    glColor3f(1.0f, (float)i / 30.0f, 0.0f);
    glVertex2f(10.0f * (float)i + 0.5f * (float)f, 100.0f + 40.0f * sinf((float)(i + f)));
    glEnd();
    glDisable(GL_POINT_SMOOTH);
  }
  glEnable(GL_POLYGON_STIPPLE);
  glPolygonStipple(stipple);
  glPolygonMode(GL_FRONT_AND_BACK, (f & 1) ? GL_LINE : GL_FILL);
  glBegin(GL_TRIANGLES);
  glColor3f(0.2f, 0.9f, 0.4f);
  glVertex2f(20.0f, 20.0f);
  glVertex2f(250.0f + (float)f, 60.0f);
  glVertex2f(120.0f, 180.0f);
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_POLYGON_STIPPLE);
  /* what was just drawn, read back and drawn elsewhere */
  static uint8_t block[40 * 30 * 4];
  glReadPixels(100 + f, 80, 40, 30, GL_RGBA, GL_UNSIGNED_BYTE, block);
  glRasterPos2i(5 + f, 150);
  glDrawPixels(40, 30, GL_RGBA, GL_UNSIGNED_BYTE, block);
  static const GLubyte bits[16] = { 0xff, 0xff, 0x81, 0x81, 0xbd, 0xbd, 0xa5, 0xa5,
                                    0xa5, 0xa5, 0xbd, 0xbd, 0x81, 0x81, 0xff, 0xff };
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glColor3f(1.0f, 1.0f, 0.0f);
  glRasterPos2i(200, 20 + f);
  for (int i = 0; i < 6; i++)
    glBitmap(16, 8, 0.0f, 0.0f, 17.0f, 0.0f, bits);
  /* and more lines over the bitmaps */
  glBegin(GL_LINE_STRIP);
  glColor3f(0.0f, 1.0f, 1.0f);
  for (int i = 0; i < 10; i++)
    glVertex2f(190.0f + 10.0f * (float)i, 15.0f + (float)((i * 7 + f) % 20));
  glEnd();
}

/* lighting, two-sided; scissored and masked clears in the middle */
static void scene_lit(int f)
{
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.3f, 0.0f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  projection();
  glRotatef(11.0f * (float)f, 1.0f, 0.4f, 0.0f);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const GLfloat pos[4] = { 1.0f, 2.0f, 3.0f, 0.0f };
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  const GLfloat spec[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
  for (int j = 0; j < 12; j++) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= 16; i++) {
      for (int k = 0; k < 2; k++) {
        const float th = 6.2831853f * (float)i / 16.0f, ph = 3.1415926f * (float)(j + k) / 12.0f;
        const float x = sinf(ph) * cosf(th), y = cosf(ph), z = sinf(ph) * sinf(th);
        glNormal3f(x, y, z);
        glVertex3f(1.2f * x, 1.2f * y, 1.2f * z);
      }
    }
    glEnd();
    if (j == 5) {
      /* a scissored clear of colour, and a masked one, between strips */
      glEnable(GL_SCISSOR_TEST);
      glScissor(40 + f, 30, 100, 70);
      glClear(GL_COLOR_BUFFER_BIT);
      glDisable(GL_SCISSOR_TEST);
      glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
      glClearColor(0.0f, 0.5f, 0.0f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
  }
  glDisable(GL_LIGHTING);
}

/* many small triangles, glCopyPixels, the accumulation buffer */
static void scene_small(int f)
{
  glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, W, 0.0, H, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  /* enough triangles (five blocks of 600, blending on in every other)
   * that the scene goes to the workers several times while the next
   * primitives are binned (scene.c ASYNC_MIN_CMDS) */
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  uint32_t r = 12345u + (uint32_t)f;
  for (int b = 0; b < 5; b++) {
    if (b & 1)
      glEnable(GL_BLEND);
    else
      glDisable(GL_BLEND);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 600; i++) {
      r = r * 1664525u + 1013904223u;
      const float x = (float)(r >> 8 & 0xff) * 1.2f, y = (float)(r >> 16 & 0xff) * 0.8f;
      const float z = (float)(r & 0xff) / 255.0f - 0.5f;
      glColor4ub((GLubyte)r, (GLubyte)(r >> 5), (GLubyte)(r >> 11), (GLubyte)(r >> 3));
      glVertex3f(x, y, z);
      glVertex3f(x + 9.5f, y + 1.25f, z);
      glVertex3f(x + 3.0f, y + 8.75f, -z);
    }
    glEnd();
  }
  glDisable(GL_BLEND);
  glRasterPos2i(150, 100);
  glCopyPixels(10 + f, 10, 80, 60, GL_COLOR);
  glAccum(GL_LOAD, 0.5f);
  glBegin(GL_TRIANGLES);
  glColor3f(1.0f, 0.0f, 0.0f);
  glVertex3f(0.0f, 0.0f, 0.9f);
  glVertex3f(300.0f, 50.0f, 0.9f);
  glVertex3f(150.0f, 200.0f, 0.9f);
  glEnd();
  glAccum(GL_ACCUM, 0.5f);
  glAccum(GL_RETURN, 1.0f);
  /* a triangle clipped to a quad of w ~1.5e35 (fuzzer seed 3000366): its
   * perspective planes take denormal products, flushed in the oracle's
   * rasterizer threads; the workers once kept them (pixels that changed
   * with FIXGL_NUM_THREADS) */
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_TRIANGLES);
  glColor4f(-4.27294e-13f, -2.14219e-35f, 6.1083e+11f, -3.13026e-31f);
  glVertex4f(-1.979e-16f, 6.19298e+37f, 1.17068e+10f, 1.32819e+26f);
  glColor4f(-2.14219e-35f, 6.1083e+11f, -3.13026e-31f, -3.60428e+30f);
  glVertex4f(6.19298e+37f, 1.17068e+10f, 1.32819e+26f, -8.44828e-08f);
  glColor4f(6.1083e+11f, -3.13026e-31f, -3.60428e+30f, -2.07323e+37f);
  glVertex4f(1.17068e+10f, 1.32819e+26f, -8.44828e-08f, 1.53802e+35f);
  glEnd();
}

struct job {
  int scene;
  uint8_t (*frames)[BUF_SIZE];      /* FRAMES frames (colour) */
  uint32_t (*depth)[W * H];         /* and their depth buffers */
  const uint8_t (*ref)[BUF_SIZE];   /* NULL: record; else compare */
  const uint32_t (*ref_depth)[W * H];
  int threads;
  int mismatches;
};

static void *render(void *arg)
{
  struct job *j = arg;
  static _Thread_local uint8_t buf[BUF_SIZE];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
    FAIL("scene %d: cannot create and bind a context", j->scene);
    return NULL;
  }
  GLuint tex = 0;
  glGenTextures(1, &tex);
  for (int f = 0; f < nframes; f++) {
    switch (j->scene) {
    case 0: scene_depth_tex(f, tex); break;
    case 1: scene_lines_points(f); break;
    case 2: scene_lit(f); break;
    default: scene_small(f); break;
    }
    glFinish();
    GLint w, h, bpv;
    void *zbuf;
    uint32_t depth[W * H];
    memset(depth, 0, sizeof(depth));
    /* OSMesa's depth buffer is a snapshot taken at glFinish */
    if (OSMesaGetDepthBuffer(ctx, &w, &h, &bpv, &zbuf) && bpv == 4 && w == W && h == H)
      memcpy(depth, zbuf, sizeof(depth));
    else
      FAIL("scene %d: no 32-bit depth buffer", j->scene);
    if (!j->ref) {
      memcpy(j->frames[f], buf, BUF_SIZE);
      memcpy(j->depth[f], depth, sizeof(depth));
    } else if (memcmp(j->ref[f], buf, BUF_SIZE) != 0 ||
               memcmp(j->ref_depth[f], depth, sizeof(depth)) != 0) {
      if (j->mismatches++ == 0) {
        int first = -1;
        for (int i = 0; i < BUF_SIZE && first < 0; i++)
          if (j->ref[f][i] != buf[i])
            first = i / 4;
        FAIL("scene %d, FIXGL_NUM_THREADS=%d: frame %d differs from the one-thread frame "
             "(first colour difference at pixel %d, %d)",
             j->scene, j->threads, f, first < 0 ? -1 : first % W, first < 0 ? -1 : first / W);
      }
    }
  }
  CHECK(glGetError() == GL_NO_ERROR, "scene %d: no GL error", j->scene);
  glDeleteTextures(1, &tex);
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(ctx);
  return NULL;
}

int main(void)
{
  const char *nf = getenv("THREADS_SCENE_FRAMES");
  if (nf && atoi(nf) >= 2 && atoi(nf) <= FRAMES)
    nframes = atoi(nf);
  else if (nf)
    FAIL("THREADS_SCENE_FRAMES=%s: 2 to %d", nf, FRAMES);
  make_texels();
  static uint8_t ref[SCENES][FRAMES][BUF_SIZE];
  static uint32_t ref_depth[SCENES][FRAMES][W * H];

  /* the references: one thread, one context after the other */
  setenv("FIXGL_NUM_THREADS", "1", 1);
  for (int s = 0; s < SCENES; s++) {
    struct job j = { .scene = s, .frames = ref[s], .depth = ref_depth[s], .threads = 1 };
    render(&j);
  }
  /* the scenes differ from one another and change from frame to frame */
  CHECK(memcmp(ref[0][0], ref[0][1], BUF_SIZE) != 0 && memcmp(ref[1][0], ref[2][0], BUF_SIZE) != 0,
        "the frames differ");

  static const int counts[] = { 1, 2, 4 };
  for (unsigned c = 0; c < sizeof(counts) / sizeof(counts[0]); c++) {
    char v[8];
    snprintf(v, sizeof v, "%d", counts[c]);
    setenv("FIXGL_NUM_THREADS", v, 1);
    pthread_t t[SCENES];
    struct job j[SCENES];
    for (int s = 0; s < SCENES; s++) {
      j[s] = (struct job){ .scene = s, .ref = (const uint8_t (*)[BUF_SIZE])ref[s],
                           .ref_depth = (const uint32_t (*)[W * H])ref_depth[s],
                           .threads = counts[c] };
      if (pthread_create(&t[s], NULL, render, &j[s]) != 0) {
        FAIL("cannot create thread %d", s);
        t[s] = 0;
      }
    }
    for (int s = 0; s < SCENES; s++)
      if (t[s])
        pthread_join(t[s], NULL);
    for (int s = 0; s < SCENES; s++)
      CHECK(j[s].mismatches == 0, "scene %d, %d threads: %d of %d frames differ", s, counts[c],
            j[s].mismatches, nframes);
  }
  return check_report("threads_scene");
}
