/*
 * alloc_fail.c - resource exhaustion (issue 18 §4), suite `robust`.
 *
 * Built against libfixgl's objects compiled with allocation-failure
 * injection (fgl_alloc.h).  For each workload (a context, textures,
 * display lists, selection and feedback, vertex batches and arrays,
 * evaluators, the accumulation buffer, the pixel path, the tile scene) the
 * test first counts the allocations it makes (K), then runs it once for
 * every N in 1..K in a child process whose N-th allocation fails, and
 * requires of each run:
 *   - no crash (the child exits normally; under AddressSanitizer and
 *     LeakSanitizer a report, a leak included, makes it exit non-zero);
 *   - the failure is reported: a GL_OUT_OF_MEMORY from glGetError, or the
 *     OSMesa call that allocated returning NULL / GL_FALSE; or it is
 *     recovered entirely: no error, and the final colour buffers are the
 *     bytes of the run without a failure (the tile scene, out of memory,
 *     draws a primitive at once instead of binning it);
 *   - before the failure, no error at all (the workloads are valid GL).
 * The run without a failure must raise no error.  Every GL call is
 * followed by glGetError, so an error is attributed to its call.
 *
 *   robust-alloc-fail [WORKLOAD...]     (default: all)
 *   robust-alloc-fail --run NAME N      (one child run, for debugging)
 */
#define GL_GLEXT_PROTOTYPES 1   /* GL 1.5 buffers and queries */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "fgl_alloc.h"

/* What a workload saw. */
struct seen {
   int oom;            /* GL_OUT_OF_MEMORY raised */
   int osmesa_failed;  /* an OSMesa call reported failure */
   int early_error;    /* another error before any failure was reported */
   char first[160];    /* the first unexpected error */
   unsigned long long digest;   /* FNV-1a of the final colour buffers */
};

static struct seen S;

static void check(const char *what)
{
   GLenum e;
   while ((e = glGetError()) != GL_NO_ERROR) {
      if (e == GL_OUT_OF_MEMORY) {
         S.oom++;
      } else if (!S.oom && !S.osmesa_failed) {
         if (!S.early_error)
            snprintf(S.first, sizeof S.first, "%s: error 0x%04x", what, e);
         S.early_error++;
      }
   }
}

#define E(call) do { call; check(#call); } while (0)

struct ctx {
   OSMesaContext ctx;
   unsigned char *buf;
   size_t bytes;
};

/* A context made current, or 0 (reported as an OSMesa failure). */
static int begin(struct ctx *c, GLenum format, int depth, int stencil, int accum, int w, int h)
{
   c->bytes = (size_t)w * (size_t)h * 4;
   c->buf = malloc(c->bytes);
   memset(c->buf, 0, c->bytes);
   c->ctx = OSMesaCreateContextExt(format, depth, stencil, accum, NULL);
   if (!c->ctx) {
      S.osmesa_failed++;
      return 0;
   }
   if (!OSMesaMakeCurrent(c->ctx, c->buf, GL_UNSIGNED_BYTE, w, h)) {
      S.osmesa_failed++;
      return 0;
   }
   check("OSMesaMakeCurrent");
   return 1;
}

static void end(struct ctx *c)
{
   if (c->ctx) {
      glFinish();
      check("glFinish");
      OSMesaDestroyContext(c->ctx);
   }
   for (size_t i = 0; i < c->bytes; i++)
      S.digest = (S.digest ^ c->buf[i]) * 0x100000001b3ull;
   free(c->buf);
}

static void ortho(int w, int h)
{
   E(glMatrixMode(GL_PROJECTION));
   E(glLoadIdentity());
   E(glOrtho(0, w, 0, h, -1, 1));
   E(glMatrixMode(GL_MODELVIEW));
   E(glLoadIdentity());
}

/* ---- workloads -------------------------------------------------------- */

static void w_context(void)
{
   struct ctx c, d;
   if (begin(&c, OSMESA_RGBA, 24, 8, 0, 32, 32)) {
      E(glClearColor(0.25f, 0.5f, 0.75f, 1));
      E(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT));
      /* a second context, and a rebind at another size */
      if (begin(&d, OSMESA_BGRA, 16, 0, 0, 16, 8))
         E(glClear(GL_COLOR_BUFFER_BIT));
      end(&d);
      if (OSMesaMakeCurrent(c.ctx, c.buf, GL_UNSIGNED_BYTE, 16, 16))
         E(glClear(GL_COLOR_BUFFER_BIT));
      else
         S.osmesa_failed++;
   }
   end(&c);
}

static void tex_image(int w, int h, GLubyte *px)
{
   for (int i = 0; i < w * h * 4; i++)
      px[i] = (GLubyte)(i * 37 + (i >> 3));
}

static void w_textures(void)
{
   struct ctx c;
   static GLubyte px[64 * 64 * 4], back[64 * 64 * 4];
   GLuint t[3] = { 0, 0, 0 };
   if (begin(&c, OSMESA_RGBA, 24, 0, 0, 64, 64)) {
      ortho(64, 64);
      tex_image(64, 64, px);
      E(glGenTextures(3, t));
      E(glBindTexture(GL_TEXTURE_2D, t[0]));
      E(glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE));
      E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR));
      E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
      E(glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 5, 16, 8, GL_RGB, GL_UNSIGNED_BYTE, px));
      E(glTexImage2D(GL_TEXTURE_2D, 1, GL_LUMINANCE_ALPHA, 32, 32, 0, GL_RGBA, GL_FLOAT, NULL));
      E(glBindTexture(GL_TEXTURE_1D, t[1]));
      E(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB5, 64, 0, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4, px));
      E(glBindTexture(GL_TEXTURE_2D, t[2]));
      E(glClearColor(0.5f, 0.25f, 0, 1));
      E(glClear(GL_COLOR_BUFFER_BIT));
      E(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 32, 32, 0));
      E(glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 0, 0, 8, 8));
      E(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
      E(glEnable(GL_TEXTURE_2D));
      glBegin(GL_QUADS);
      glTexCoord2f(0, 0); glVertex2f(0, 0);
      glTexCoord2f(1, 0); glVertex2f(64, 0);
      glTexCoord2f(1, 1); glVertex2f(64, 64);
      glTexCoord2f(0, 1); glVertex2f(0, 64);
      E(glEnd());
      E(glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back));
      E(glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 1024, 1024, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
      E(glDeleteTextures(2, t));
      E(glFinish());
   }
   end(&c);
}

static void w_dlists(void)
{
   struct ctx c;
   static GLubyte stipple[128], bitmap[32], px[16 * 16 * 4];   /* bitmap: 8 rows of 4 bytes (GL_UNPACK_ALIGNMENT 4) */
   static const GLfloat amb[4] = { 0.2f, 0.3f, 0.4f, 1 };
   static const GLfloat pts[4][3] = { { 0, 0, 0 }, { 10, 30, 0 }, { 40, 5, 0 }, { 60, 60, 0 } };
   if (begin(&c, OSMESA_RGBA, 24, 0, 0, 64, 64)) {
      ortho(64, 64);
      memset(stipple, 0xA5, sizeof stipple);
      memset(bitmap, 0x3C, sizeof bitmap);
      tex_image(16, 16, px);
      GLuint base = glGenLists(4);
      check("glGenLists");
      E(glNewList(base, GL_COMPILE));
      glBegin(GL_TRIANGLES);
      for (int i = 0; i < 300; i++) {
         glColor3f((float)(i % 7) / 7.0f, 0.5f, (float)(i % 3) / 3.0f);
         glVertex2f((float)(i % 64), (float)((i * 7) % 64));
      }
      E(glEnd());
      E(glMaterialfv(GL_FRONT, GL_AMBIENT, amb));
      E(glPolygonStipple(stipple));
      E(glBitmap(8, 8, 0, 0, 2, 2, bitmap));
      E(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, px));
      E(glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &pts[0][0]));
      E(glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px));
      E(glEndList());
      E(glNewList(base + 1, GL_COMPILE_AND_EXECUTE));
      E(glCallList(base));
      E(glRectf(1, 1, 20, 20));
      E(glEndList());
      GLuint names[3] = { 0, 1, 0 };
      E(glListBase(base));
      E(glCallLists(3, GL_UNSIGNED_INT, names));
      E(glDeleteLists(base, 4));
      E(glFinish());
   }
   end(&c);
}

static void w_select_feedback(void)
{
   struct ctx c;
   static GLuint sel[64];
   static GLfloat fb[512];
   if (begin(&c, OSMESA_RGBA, 24, 0, 0, 32, 32)) {
      ortho(32, 32);
      E(glSelectBuffer(64, sel));
      E(glRenderMode(GL_SELECT));
      E(glInitNames());
      for (int i = 0; i < 8; i++) {
         E(glPushName((GLuint)i));
         E(glRectf((float)i, 0, (float)i + 10, 10));
         E(glPopName());
      }
      E(glRenderMode(GL_RENDER));
      E(glFeedbackBuffer(512, GL_3D_COLOR, fb));
      E(glRenderMode(GL_FEEDBACK));
      glBegin(GL_TRIANGLE_STRIP);
      for (int i = 0; i < 12; i++)
         glVertex2f((float)(i * 3), (float)((i & 1) * 20));
      E(glEnd());
      E(glPassThrough(7));
      glBegin(GL_LINES);
      glVertex2f(1, 1); glVertex2f(30, 30);
      E(glEnd());
      E(glRenderMode(GL_RENDER));
   }
   end(&c);
}

static void w_vertices(void)
{
   struct ctx c;
   static GLfloat v[2000][2], col[2000][4];
   static GLushort idx[3000];
   if (begin(&c, OSMESA_RGBA, 24, 0, 0, 64, 64)) {
      ortho(64, 64);
      /* a batch that outgrows the vertex buffer */
      glBegin(GL_TRIANGLES);
      for (int i = 0; i < 6000; i++) {
         glColor4ub((GLubyte)i, (GLubyte)(i >> 3), 90, 255);
         glVertex2f((float)(i % 61), (float)((i * 13) % 63));
      }
      E(glEnd());
      glBegin(GL_POINTS);
      for (int i = 0; i < 500; i++)
         glVertex2f((float)(i % 64) + 0.5f, (float)(i / 8 % 64) + 0.5f);
      E(glEnd());
      glBegin(GL_LINE_LOOP);
      for (int i = 0; i < 300; i++)
         glVertex2f((float)(i % 60) + 1, (float)((i * 5) % 60) + 1);
      E(glEnd());
      for (int i = 0; i < 2000; i++) {
         v[i][0] = (float)(i % 64);
         v[i][1] = (float)((i * 7) % 64);
         col[i][0] = (float)(i % 5) / 5.0f, col[i][1] = 0.5f, col[i][2] = 0.25f, col[i][3] = 1;
      }
      for (int i = 0; i < 3000; i++)
         idx[i] = (GLushort)((i * 17) % 2000);
      E(glEnableClientState(GL_VERTEX_ARRAY));
      E(glEnableClientState(GL_COLOR_ARRAY));
      E(glVertexPointer(2, GL_FLOAT, 0, v));
      E(glColorPointer(4, GL_FLOAT, 0, col));
      E(glDrawArrays(GL_TRIANGLES, 0, 1998));
      E(glDrawElements(GL_TRIANGLES, 3000, GL_UNSIGNED_SHORT, idx));
      E(glDrawRangeElements(GL_LINES, 0, 1999, 3000, GL_UNSIGNED_SHORT, idx));
      E(glFinish());
   }
   end(&c);
}

static void w_eval(void)
{
   struct ctx c;
   static GLfloat ctl1[4][4], ctl2[4][4][3];
   if (begin(&c, OSMESA_RGBA, 24, 0, 0, 32, 32)) {
      ortho(32, 32);
      for (int i = 0; i < 4; i++) {
         ctl1[i][0] = (float)(i * 8), ctl1[i][1] = (float)((i * 11) % 32), ctl1[i][2] = 0, ctl1[i][3] = 1;
         for (int j = 0; j < 4; j++)
            ctl2[i][j][0] = (float)(i * 9), ctl2[i][j][1] = (float)(j * 9), ctl2[i][j][2] = 0;
      }
      E(glMap1f(GL_MAP1_VERTEX_4, 0, 1, 4, 4, &ctl1[0][0]));
      E(glEnable(GL_MAP1_VERTEX_4));
      E(glMapGrid1f(40, 0, 1));
      E(glEvalMesh1(GL_LINE, 0, 40));
      E(glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &ctl2[0][0][0]));
      E(glEnable(GL_MAP2_VERTEX_3));
      E(glMapGrid2f(12, 0, 1, 12, 0, 1));
      E(glEvalMesh2(GL_FILL, 0, 12, 0, 12));
      glBegin(GL_LINE_STRIP);
      for (int i = 0; i <= 20; i++)
         glEvalCoord1f((float)i / 20.0f);
      E(glEnd());
      E(glFinish());
   }
   end(&c);
}

static void w_accum(void)
{
   struct ctx c;
   if (begin(&c, OSMESA_RGBA, 24, 8, 16, 32, 32)) {
      ortho(32, 32);
      E(glClearAccum(0.1f, 0.2f, 0.3f, 0.4f));
      E(glClear(GL_COLOR_BUFFER_BIT | GL_ACCUM_BUFFER_BIT));
      E(glColor3f(1, 0.5f, 0.25f));
      E(glRectf(2, 2, 20, 20));
      E(glAccum(GL_LOAD, 0.5f));
      E(glRectf(10, 10, 30, 30));
      E(glAccum(GL_ACCUM, 0.5f));
      E(glAccum(GL_MULT, 1.5f));
      E(glAccum(GL_RETURN, 1.0f));
      E(glFinish());
   }
   end(&c);
}

static void w_pixels(void)
{
   struct ctx c;
   static GLubyte px[48 * 48 * 4], back[48 * 48 * 4];
   static GLfloat z[48 * 48];
   static GLubyte bm[8 * 16];
   if (begin(&c, OSMESA_RGBA, 24, 8, 0, 48, 48)) {
      ortho(48, 48);
      tex_image(48, 48, px);
      memset(bm, 0x5A, sizeof bm);
      E(glRasterPos2i(2, 3));
      E(glDrawPixels(40, 40, GL_RGBA, GL_UNSIGNED_BYTE, px));
      E(glPixelZoom(1.5f, -0.5f));
      E(glDrawPixels(20, 20, GL_LUMINANCE, GL_UNSIGNED_BYTE, px));
      E(glPixelZoom(1, 1));
      E(glCopyPixels(0, 0, 20, 20, GL_COLOR));
      E(glCopyPixels(5, 5, 20, 20, GL_DEPTH));
      E(glCopyPixels(5, 5, 20, 20, GL_STENCIL));
      E(glBitmap(64, 16, 0, 0, 3, 1, bm));
      E(glReadPixels(0, 0, 48, 48, GL_RGBA, GL_UNSIGNED_BYTE, back));
      E(glReadPixels(0, 0, 48, 48, GL_DEPTH_COMPONENT, GL_FLOAT, z));
      E(glReadPixels(0, 0, 48, 48, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, back));
      E(glReadPixels(0, 0, 40, 40, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, back));
      E(glFinish());
   }
   end(&c);
}

/* The tile scene: a large buffer, many triangles over several tiles and
 * states, drawn at glFinish by the worker pool. */
static void w_scene(void)
{
   struct ctx c;
   if (begin(&c, OSMESA_RGBA, 24, 8, 0, 300, 200)) {
      ortho(300, 200);
      E(glEnable(GL_DEPTH_TEST));
      E(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
      for (int k = 0; k < 40; k++) {
         E(glColor3ub((GLubyte)(k * 50), (GLubyte)(k * 20), 200));
         if (k % 5 == 0) {
            E(glEnable(GL_BLEND));
            E(glBlendFunc(GL_SRC_ALPHA, (GLenum)(k % 10 ? GL_ONE : GL_ZERO)));
         }
         glBegin(GL_TRIANGLES);
         for (int i = 0; i < 30; i++) {
            glVertex3f((float)((k * 37 + i * 11) % 300), (float)((i * 17) % 200), 0.1f * (float)(i % 7));
            glVertex3f((float)((k * 37 + i * 11 + 90) % 300), (float)((i * 17 + 40) % 200), 0.5f);
            glVertex3f((float)((k * 37 + i * 11 + 30) % 300), (float)((i * 17 + 120) % 200), -0.3f);
         }
         E(glEnd());
         if (k % 13 == 12)
            E(glFlush());
      }
      E(glFinish());
   }
   end(&c);
}

/* GL 1.5 buffer objects (the shared table, stores, arrays and indices
 * from them, a list compiled from them, a second context sharing them)
 * and occlusion queries */
static void w_buffers_queries(void)
{
   struct ctx c;
   static GLfloat v[300][2];
   static GLushort idx[600];
   for (int i = 0; i < 300; i++) {
      v[i][0] = (float)(i % 64);
      v[i][1] = (float)((i * 7) % 64);
   }
   for (int i = 0; i < 600; i++)
      idx[i] = (GLushort)((i * 17) % 300);
   if (begin(&c, OSMESA_RGBA, 24, 0, 0, 64, 64)) {
      ortho(64, 64);
      GLuint b[40], q[3];
      E(glGenBuffers(40, b));
      for (int i = 0; i < 40; i++)
         E(glBindBuffer(GL_ARRAY_BUFFER, b[i]));
      E(glBufferData(GL_ARRAY_BUFFER, sizeof(v), v, GL_STATIC_DRAW));
      E(glBufferSubData(GL_ARRAY_BUFFER, 8, 16, v[10]));
      E(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[0]));
      E(glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(idx), idx, GL_DYNAMIC_DRAW));
      E(glEnableClientState(GL_VERTEX_ARRAY));
      GLint ab = 0;
      E(glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &ab));
      E(glVertexPointer(2, GL_FLOAT, 0, ab ? NULL : (const GLvoid *)v));
      E(glGenQueries(3, q));
      E(glBeginQuery(GL_SAMPLES_PASSED, q[0]));
      E(glDrawArrays(GL_TRIANGLES, 0, 297));
      E(glDrawElements(GL_TRIANGLES, 600, GL_UNSIGNED_SHORT, NULL));
      E(glEndQuery(GL_SAMPLES_PASSED));
      GLuint r = 0;
      E(glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &r));
      /* (an offset, only while an element buffer is bound: after a failed
       * glBindBuffer it would be a client pointer) */
      GLint eb = 0;
      E(glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &eb));
      E(glNewList(1, GL_COMPILE));
      E(glDrawElements(GL_LINES, 200, GL_UNSIGNED_SHORT, eb ? (const GLvoid *)20 : idx));
      E(glEndList());
      void *m = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
      check("glMapBuffer");
      if (m)
         E(glUnmapBuffer(GL_ARRAY_BUFFER));
      E(glBeginQuery(GL_SAMPLES_PASSED, 77));
      E(glCallList(1));
      E(glEndQuery(GL_SAMPLES_PASSED));
      E(glGetQueryObjectuiv(77, GL_QUERY_RESULT_AVAILABLE, &r));
      E(glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT));
      E(glBindBuffer(GL_ARRAY_BUFFER, 0));
      E(glPopClientAttrib());
      OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, c.ctx);
      if (!shared) {
         S.osmesa_failed++;
      } else {
         static unsigned char buf2[16 * 16 * 4];
         if (OSMesaMakeCurrent(shared, buf2, GL_UNSIGNED_BYTE, 16, 16)) {
            E(glBindBuffer(GL_ARRAY_BUFFER, b[1]));
            E(glDeleteBuffers(40, b));
            OSMesaMakeCurrent(c.ctx, c.buf, GL_UNSIGNED_BYTE, 64, 64);
         } else {
            S.osmesa_failed++;
            OSMesaMakeCurrent(c.ctx, c.buf, GL_UNSIGNED_BYTE, 64, 64);
         }
         OSMesaDestroyContext(shared);
      }
      E(glDrawArrays(GL_POINTS, 0, 300));
      E(glDeleteQueries(3, q));
      E(glFinish());
   }
   end(&c);
}

static const struct workload {
   const char *name;
   void (*fn)(void);
} workloads[] = {
   { "buffers_queries", w_buffers_queries },
   { "context", w_context },
   { "textures", w_textures },
   { "dlists", w_dlists },
   { "select_feedback", w_select_feedback },
   { "vertices", w_vertices },
   { "eval", w_eval },
   { "accum", w_accum },
   { "pixels", w_pixels },
   { "scene", w_scene },
};

/* ---- driver ----------------------------------------------------------- */

/* In the child: runs w with the n-th allocation failing (n = 0: none);
 * exits 0 when the run meets the requirements, 1 otherwise, and writes the
 * allocation count and the digest of the final buffers to fd.  baseline:
 * the digest of the run without a failure. */
static void child(const struct workload *w, long n, int fd, unsigned long long baseline)
{
   long count, before;
   int failed;
   unsigned long long out[2];
   memset(&S, 0, sizeof S);
   S.digest = 0xcbf29ce484222325ull;
   before = fgl_alloc_count();
   fgl_alloc_fail_at(n);
   w->fn();
   count = fgl_alloc_count() - before;
   failed = fgl_alloc_failed();
   out[0] = (unsigned long long)count;
   out[1] = S.digest;
   if (fd >= 0 && write(fd, out, sizeof out) != (ssize_t)sizeof out)
      _exit(3);
   if (S.early_error) {
      printf("  %s N=%ld: %s%s\n", w->name, n, S.first,
             failed ? " (after the failed allocation, before any report of it)" : "");
      exit(1);
   }
   if (failed && !S.oom && !S.osmesa_failed && S.digest != baseline) {
      printf("  %s N=%ld: allocation %ld failed, no GL_OUT_OF_MEMORY nor OSMesa failure "
             "reported it, and the result differs from the run without a failure\n", w->name, n, n);
      exit(1);
   }
   if (!failed && (S.oom || S.osmesa_failed)) {
      printf("  %s N=%ld: GL_OUT_OF_MEMORY or an OSMesa failure without a failed allocation\n",
             w->name, n);
      exit(1);
   }
   exit(0);
}

/* Runs one child; returns its exit status (0 ok), the allocation count
 * and the digest of its final buffers. */
static int run(const struct workload *w, long n, unsigned long long baseline, long *count,
               unsigned long long *digest)
{
   int fd[2], status;
   pid_t pid;
   unsigned long long in[2] = { 0, 0 };
   if (pipe(fd) != 0)
      return -1;
   fflush(stdout);
   pid = fork();
   if (pid == 0) {
      close(fd[0]);
      child(w, n, fd[1], baseline);
   }
   close(fd[1]);
   *count = -1;
   if (read(fd[0], in, sizeof in) == (ssize_t)sizeof in) {
      *count = (long)in[0];
      *digest = in[1];
   }
   close(fd[0]);
   if (pid < 0 || waitpid(pid, &status, 0) != pid)
      return -1;
   if (WIFSIGNALED(status)) {
      printf("  %s N=%ld: killed by signal %d (%s)\n", w->name, n, WTERMSIG(status),
             strsignal(WTERMSIG(status)));
      return 128 + WTERMSIG(status);
   }
   return WEXITSTATUS(status);
}

int main(int argc, char **argv)
{
   int bad = 0, selected = 0;
   long total_runs = 0;

   if (argc == 4 && strcmp(argv[1], "--run") == 0) {
      for (size_t i = 0; i < sizeof workloads / sizeof workloads[0]; i++)
         if (strcmp(workloads[i].name, argv[2]) == 0)
            child(&workloads[i], atol(argv[3]), -1, 0);
      fprintf(stderr, "no workload %s\n", argv[2]);
      return 2;
   }
   for (size_t i = 0; i < sizeof workloads / sizeof workloads[0]; i++) {
      const struct workload *w = &workloads[i];
      long k = 0, c;
      unsigned long long base = 0, d;
      int wbad = 0, want = argc <= 1;
      for (int a = 1; a < argc; a++)
         want |= strcmp(argv[a], w->name) == 0;
      if (!want)
         continue;
      selected++;
      /* the run without a failure: valid, no error, and how many
       * allocations it makes */
      if (run(w, 0, 0, &k, &base) != 0 || k <= 0) {
         printf("%-16s FAIL: the run without an allocation failure (%ld allocations)\n", w->name, k);
         bad++;
         continue;
      }
      for (long n = 1; n <= k; n++) {
         int st = run(w, n, base, &c, &d);
         total_runs++;
         if (st != 0) {
            wbad++;
            if (wbad > 20) {
               printf("  %s: more failures left out\n", w->name);
               break;
            }
         }
      }
      printf("%-16s %5ld allocations, %5ld failure runs: %s\n", w->name, k, k,
             wbad ? "FAIL" : "ok");
      bad += wbad != 0;
   }
   if (!selected) {
      fprintf(stderr, "no such workload\n");
      return 2;
   }
   printf("%ld runs with a failing allocation; %d workload(s) failed\n", total_runs, bad);
   return bad != 0;
}
