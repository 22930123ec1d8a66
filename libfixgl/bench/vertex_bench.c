/*
 * vertex_bench.c - the vertex stage's throughput alone: the bench's
 * 100 x 100 sphere (60,000 vertices of 20,000 triangles, the grid's 10,201
 * vertices shared) with every face culled (glCullFace(GL_FRONT_AND_BACK)),
 * so the raster core only rejects the triangles it is given: what is left
 * is submission (glColor/glNormal/glVertex into the vbo, or the array
 * fetch), transform, lighting and primitive assembly.
 *
 * Usage: fixgl-bench-vertex [SECONDS [MODE...]]   (default 2, every mode)
 * Modes: color  immediate mode, glColor3fv + glVertex3fv, unlit
 *        lit    immediate mode, glNormal3fv + glVertex3fv, one directional
 *               light with specular
 *        decolor, delit   the same through glDrawElements (the
 *               post-transform vertex cache shares the grid's vertices)
 * Output, one line per mode:  vertex MODE ns_per_vertex X mvert_per_s Y
 * (per submitted vertex or index, CPU time of the process from
 * clock_gettime(CLOCK_PROCESS_CPUTIME_ID), so other processes on the
 * machine disturb it less than wall-clock time).
 */
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <fixgl/version.h>

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define ST 100
#define SL 100

static float pos[(ST + 1) * (SL + 1)][3];
static GLuint idx[ST * SL * 6];
static int nidx;

static double cpu_seconds(void)
{
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static void build_sphere(void)
{
  for (int i = 0; i <= ST; i++)
    for (int j = 0; j <= SL; j++) {
      const float th = 3.14159265f * (float)i / ST, ph = 6.2831853f * (float)j / SL;
      float *p = pos[i * (SL + 1) + j];
      p[0] = sinf(th) * cosf(ph);
      p[1] = cosf(th);
      p[2] = sinf(th) * sinf(ph);
    }
  for (int i = 0; i < ST; i++)
    for (int j = 0; j < SL; j++) {
      const GLuint a = (GLuint)(i * (SL + 1) + j), b = a + SL + 1;
      const GLuint t[6] = { a, b, b + 1, a, b + 1, a + 1 };
      for (int k = 0; k < 6; k++)
        idx[nidx++] = t[k];
    }
}

static void frame(int lit, int elements)
{
  if (elements) {
    glDrawElements(GL_TRIANGLES, nidx, GL_UNSIGNED_INT, idx);
  } else {
    glBegin(GL_TRIANGLES);
    for (int k = 0; k < nidx; k++) {
      const float *p = pos[idx[k]];
      if (lit)
        glNormal3fv(p);
      else
        glColor3fv(p);
      glVertex3fv(p);
    }
    glEnd();
  }
  glFinish();
}

static void run(const char *mode, double seconds)
{
  const int lit = strstr(mode, "lit") != NULL, elements = strncmp(mode, "de", 2) == 0;
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT_AND_BACK);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.48, 0.48, -0.36, 0.36, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.0f, 0.0f, -3.0f);
  glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  if (lit) {
    static const GLfloat white[4] = { 1, 1, 1, 1 };
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  } else {
    glDisable(GL_LIGHTING);
  }
  if (elements) {
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, pos);
    if (lit) {
      glEnableClientState(GL_NORMAL_ARRAY);
      glNormalPointer(GL_FLOAT, 0, pos);
    } else {
      glEnableClientState(GL_COLOR_ARRAY);
      glColorPointer(3, GL_FLOAT, 0, pos);
    }
  }
  for (int i = 0; i < 3; i++)   /* warm-up */
    frame(lit, elements);
  long frames = 0;
  const double t0 = cpu_seconds();
  double t;
  do {
    frame(lit, elements);
    frames++;
    t = cpu_seconds() - t0;
  } while (t < seconds);
  const double verts = (double)frames * nidx;
  printf("vertex %s ns_per_vertex %.1f mvert_per_s %.1f\n", mode, t * 1e9 / verts,
         verts / t * 1e-6);
}

int main(int argc, char **argv)
{
  /* [--seconds S] [SECONDS] [MODE...]: as bench.c */
  static const struct option longopts[] = {
    { "seconds", required_argument, NULL, 's' },
    { "version", no_argument, NULL, 'V' },
    { "help", no_argument, NULL, 'h' },
    { NULL, 0, NULL, 0 },
  };
#define VBENCH_USAGE "usage: %s [--seconds S | SECONDS] [MODE...]   (modes color, lit, decolor,\n" \
                     "       delit; default 2 s each; --opt=value as well) | --version\n"
  double seconds = 2.0;
  int ch, bad = 0;
  char *end;
  while ((ch = getopt_long(argc, argv, "h", longopts, NULL)) != -1) {
    switch (ch) {
    case 's': seconds = strtod(optarg, &end); bad |= *end != 0; break;
    case 'V': puts(FIXGL_VERSION_BANNER("fixgl-bench-vertex")); return 0;
    case 'h': printf(VBENCH_USAGE, argv[0]); return 0;
    default: bad = 1; break;
    }
  }
  if (optind < argc && strtod(argv[optind], &end) > 0.0 && *end == 0)
    seconds = strtod(argv[optind++], NULL);
  if (bad || !(seconds > 0.0)) {
    fprintf(stderr, VBENCH_USAGE, argv[0]);
    return 2;
  }
  static const char *all[] = { "color", "lit", "decolor", "delit" };
  static unsigned char buf[64 * 64 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 64, 64)) {
    fprintf(stderr, "fixgl-bench-vertex: no context\n");
    return 1;
  }
  build_sphere();
  if (optind < argc)
    for (int i = optind; i < argc; i++)
      run(argv[i], seconds);
  else
    for (unsigned i = 0; i < sizeof(all) / sizeof(all[0]); i++)
      run(all[i], seconds);
  OSMesaDestroyContext(ctx);
  return 0;
}
