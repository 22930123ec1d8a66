/*
 * GLUT's geometric objects, drawn with immediate-mode GL calls only (so the
 * same calls run on fixgl and on Mesa): sphere and cone (GLU-quadric
 * layout: poles on the z axis, the cone's base in the z = 0 plane), cube,
 * torus (GLUT's doughnut), and the platonic solids (flat face normals;
 * the icosahedron is built from its 12 vertices, the dodecahedron as its
 * dual; faces wound counter-clockwise seen from outside).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "glut_internal.h"

#define PI 3.14159265358979323846

/* ---- sphere -------------------------------------------------------------- */

static void sphere(GLdouble r, GLint slices, GLint stacks, bool wire)
{
   if (slices < 2 || stacks < 1)
      return;
   if (!wire) {
      for (int i = 0; i < stacks; i++) {
         double t0 = PI * i / stacks, t1 = PI * (i + 1) / stacks;
         glBegin(GL_QUAD_STRIP);
         for (int j = 0; j <= slices; j++) {
            double p = 2.0 * PI * (j == slices ? 0 : j) / slices;
            double x0 = sin(t0) * cos(p), y0 = sin(t0) * sin(p), z0 = cos(t0);
            double x1 = sin(t1) * cos(p), y1 = sin(t1) * sin(p), z1 = cos(t1);
            glNormal3d(x0, y0, z0);
            glVertex3d(r * x0, r * y0, r * z0);
            glNormal3d(x1, y1, z1);
            glVertex3d(r * x1, r * y1, r * z1);
         }
         glEnd();
      }
      return;
   }
   for (int i = 1; i < stacks; i++) {           /* latitude circles */
      double t = PI * i / stacks;
      glBegin(GL_LINE_LOOP);
      for (int j = 0; j < slices; j++) {
         double p = 2.0 * PI * j / slices;
         double x = sin(t) * cos(p), y = sin(t) * sin(p), z = cos(t);
         glNormal3d(x, y, z);
         glVertex3d(r * x, r * y, r * z);
      }
      glEnd();
   }
   for (int j = 0; j < slices; j++) {            /* meridians */
      double p = 2.0 * PI * j / slices;
      glBegin(GL_LINE_STRIP);
      for (int i = 0; i <= stacks; i++) {
         double t = PI * i / stacks;
         double x = sin(t) * cos(p), y = sin(t) * sin(p), z = cos(t);
         glNormal3d(x, y, z);
         glVertex3d(r * x, r * y, r * z);
      }
      glEnd();
   }
}

GLUT_EXPORT void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks)
{
   sphere(radius, slices, stacks, false);
}

GLUT_EXPORT void glutWireSphere(GLdouble radius, GLint slices, GLint stacks)
{
   sphere(radius, slices, stacks, true);
}

/* ---- cone ---------------------------------------------------------------- */

static void cone(GLdouble base, GLdouble height, GLint slices, GLint stacks, bool wire)
{
   if (slices < 2 || stacks < 1)
      return;
   double len = sqrt(base * base + height * height);
   double nz = len > 0.0 ? base / len : 0.0, nr = len > 0.0 ? height / len : 1.0;
   if (!wire) {
      glBegin(GL_TRIANGLE_FAN);            /* the base, facing -z */
      glNormal3d(0.0, 0.0, -1.0);
      glVertex3d(0.0, 0.0, 0.0);
      for (int j = slices; j >= 0; j--) {
         double p = 2.0 * PI * (j == slices ? 0 : j) / slices;
         glVertex3d(base * cos(p), base * sin(p), 0.0);
      }
      glEnd();
      for (int i = 0; i < stacks; i++) {
         double r0 = base * (stacks - i) / stacks, r1 = base * (stacks - i - 1) / stacks;
         double z0 = height * i / stacks, z1 = height * (i + 1) / stacks;
         glBegin(GL_QUAD_STRIP);
         for (int j = 0; j <= slices; j++) {
            double p = 2.0 * PI * (j == slices ? 0 : j) / slices;
            double c = cos(p), s = sin(p);
            glNormal3d(c * nr, s * nr, nz);
            glVertex3d(r0 * c, r0 * s, z0);
            glVertex3d(r1 * c, r1 * s, z1);
         }
         glEnd();
      }
      return;
   }
   for (int i = 0; i < stacks; i++) {
      double r = base * (stacks - i) / stacks, z = height * i / stacks;
      glBegin(GL_LINE_LOOP);
      for (int j = 0; j < slices; j++) {
         double p = 2.0 * PI * j / slices;
         glNormal3d(cos(p) * nr, sin(p) * nr, nz);
         glVertex3d(r * cos(p), r * sin(p), z);
      }
      glEnd();
   }
   glBegin(GL_LINES);
   for (int j = 0; j < slices; j++) {
      double p = 2.0 * PI * j / slices;
      glNormal3d(cos(p) * nr, sin(p) * nr, nz);
      glVertex3d(base * cos(p), base * sin(p), 0.0);
      glVertex3d(0.0, 0.0, height);
   }
   glEnd();
}

GLUT_EXPORT void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks)
{
   cone(base, height, slices, stacks, false);
}

GLUT_EXPORT void glutWireCone(GLdouble base, GLdouble height, GLint slices, GLint stacks)
{
   cone(base, height, slices, stacks, true);
}

/* ---- cube ---------------------------------------------------------------- */

static void cube(GLdouble size, GLenum type)
{
   static const GLfloat n[6][3] = {
      { -1, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
   static const GLint faces[6][4] = {
      { 0, 1, 2, 3 }, { 3, 2, 6, 7 }, { 7, 6, 5, 4 }, { 4, 5, 1, 0 }, { 5, 6, 2, 1 }, { 7, 4, 0, 3 } };
   GLfloat v[8][3];
   GLfloat h = (GLfloat)size / 2.0f;
   for (int i = 0; i < 8; i++) {
      v[i][0] = (i & 4) ? h : -h;                 /* vertices 4..7 at +x */
      v[i][1] = (i == 2 || i == 3 || i == 6 || i == 7) ? h : -h;
      v[i][2] = (i == 1 || i == 2 || i == 5 || i == 6) ? h : -h;
   }
   for (int i = 5; i >= 0; i--) {
      glBegin(type);
      glNormal3fv(n[i]);
      for (int k = 0; k < 4; k++)
         glVertex3fv(v[faces[i][k]]);
      glEnd();
   }
}

GLUT_EXPORT void glutSolidCube(GLdouble size)
{
   cube(size, GL_QUADS);
}

GLUT_EXPORT void glutWireCube(GLdouble size)
{
   cube(size, GL_LINE_LOOP);
}

/* ---- torus (GLUT's doughnut) ----------------------------------------------- */

static void doughnut(GLfloat r, GLfloat R, GLint nsides, GLint rings)
{
   if (nsides < 1 || rings < 1)
      return;
   GLfloat ring_delta = 2.0f * (GLfloat)PI / (GLfloat)rings;
   GLfloat side_delta = 2.0f * (GLfloat)PI / (GLfloat)nsides;
   GLfloat theta = 0.0f, cos_theta = 1.0f, sin_theta = 0.0f;
   for (int i = rings - 1; i >= 0; i--) {
      GLfloat theta1 = theta + ring_delta;
      GLfloat cos_theta1 = cosf(theta1), sin_theta1 = sinf(theta1);
      GLfloat phi = 0.0f;
      glBegin(GL_QUAD_STRIP);
      for (int j = nsides; j >= 0; j--) {
         phi += side_delta;
         GLfloat cos_phi = cosf(phi), sin_phi = sinf(phi);
         GLfloat dist = R + r * cos_phi;
         glNormal3f(cos_theta1 * cos_phi, -sin_theta1 * cos_phi, sin_phi);
         glVertex3f(cos_theta1 * dist, -sin_theta1 * dist, r * sin_phi);
         glNormal3f(cos_theta * cos_phi, -sin_theta * cos_phi, sin_phi);
         glVertex3f(cos_theta * dist, -sin_theta * dist, r * sin_phi);
      }
      glEnd();
      theta = theta1, cos_theta = cos_theta1, sin_theta = sin_theta1;
   }
}

GLUT_EXPORT void glutSolidTorus(GLdouble inner, GLdouble outer, GLint sides, GLint rings)
{
   doughnut((GLfloat)inner, (GLfloat)outer, sides, rings);
}

GLUT_EXPORT void glutWireTorus(GLdouble inner, GLdouble outer, GLint sides, GLint rings)
{
   glPushAttrib(GL_POLYGON_BIT);
   glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
   doughnut((GLfloat)inner, (GLfloat)outer, sides, rings);
   glPopAttrib();
}

/* ---- platonic solids ------------------------------------------------------ */

/* Draws faces of `n` vertices each with flat normals; faces are wound
 * counter-clockwise seen from outside (checked against the centroid). */
static void polyhedron(const double (*v)[3], const int *faces, int nfaces, int n, double scale,
                       bool wire)
{
   for (int f = 0; f < nfaces; f++) {
      const int *ix = faces + f * n;
      double c[3] = { 0, 0, 0 };
      for (int k = 0; k < n; k++)
         for (int l = 0; l < 3; l++)
            c[l] += v[ix[k]][l];
      const double *a = v[ix[0]], *b = v[ix[1]], *d = v[ix[2]];
      double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      double e2[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
      double nn[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0] };
      bool flip = nn[0] * c[0] + nn[1] * c[1] + nn[2] * c[2] < 0.0;
      double len = sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
      double s = flip ? -1.0 / len : 1.0 / len;
      glBegin(wire ? GL_LINE_LOOP : n == 3 ? GL_TRIANGLES : GL_POLYGON);
      glNormal3d(nn[0] * s, nn[1] * s, nn[2] * s);
      for (int k = 0; k < n; k++) {
         const double *p = v[ix[flip ? n - 1 - k : k]];
         glVertex3d(p[0] * scale, p[1] * scale, p[2] * scale);
      }
      glEnd();
   }
}

static void tetrahedron(bool wire)
{
   static const double r3 = 0.57735026918962576451;   /* 1/sqrt(3): radius 1 */
   static const double v[4][3] = {
      { r3, r3, r3 }, { r3, -r3, -r3 }, { -r3, r3, -r3 }, { -r3, -r3, r3 } };
   static const int f[4][3] = { { 0, 1, 2 }, { 0, 3, 1 }, { 0, 2, 3 }, { 1, 3, 2 } };
   polyhedron(v, &f[0][0], 4, 3, 1.0, wire);
}

static void octahedron(bool wire)
{
   static const double v[6][3] = {
      { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
   static const int f[8][3] = {
      { 0, 4, 2 }, { 1, 2, 4 }, { 0, 3, 4 }, { 1, 4, 3 },
      { 0, 2, 5 }, { 1, 5, 2 }, { 0, 5, 3 }, { 1, 3, 5 } };
   polyhedron(v, &f[0][0], 8, 3, 1.0, wire);
}

/* Icosahedron: (0, +-1, +-phi) and cyclic permutations, normalised; its
 * 20 faces are the vertex triples at mutual distance 2 (before
 * normalisation), found in index order. */
static double ico_v[12][3];
static int ico_f[20][3];
/* Dodecahedron: the normalised face centres of the icosahedron scaled to
 * radius sqrt(3) (GLUT's size); face k surrounds icosahedron vertex k,
 * its 5 vertices ordered by angle around that vertex. */
static double dod_v[20][3];
static int dod_f[12][5];
static bool solids_built;

static void build_solids(void)
{
   const double phi = (1.0 + sqrt(5.0)) / 2.0;
   double raw[12][3];
   int n = 0;
   for (int perm = 0; perm < 3; perm++)
      for (int s1 = -1; s1 <= 1; s1 += 2)
         for (int s2 = -1; s2 <= 1; s2 += 2) {
            double p[3] = { 0.0, s1 * 1.0, s2 * phi };
            raw[n][perm] = p[0];
            raw[n][(perm + 1) % 3] = p[1];
            raw[n][(perm + 2) % 3] = p[2];
            n++;
         }
   double len = sqrt(1.0 + phi * phi);
   for (int i = 0; i < 12; i++)
      for (int l = 0; l < 3; l++)
         ico_v[i][l] = raw[i][l] / len;
   int nf = 0;
   for (int i = 0; i < 12; i++)
      for (int j = i + 1; j < 12; j++)
         for (int k = j + 1; k < 12; k++) {
            const double *a = raw[i], *b = raw[j], *c = raw[k];
            double dab = 0, dbc = 0, dca = 0;
            for (int l = 0; l < 3; l++) {
               dab += (a[l] - b[l]) * (a[l] - b[l]);
               dbc += (b[l] - c[l]) * (b[l] - c[l]);
               dca += (c[l] - a[l]) * (c[l] - a[l]);
            }
            if (fabs(dab - 4.0) < 1e-6 && fabs(dbc - 4.0) < 1e-6 && fabs(dca - 4.0) < 1e-6 &&
                nf < 20) {
               ico_f[nf][0] = i, ico_f[nf][1] = j, ico_f[nf][2] = k;
               nf++;
            }
         }
   for (int f = 0; f < 20; f++) {
      double c[3] = { 0, 0, 0 };
      for (int k = 0; k < 3; k++)
         for (int l = 0; l < 3; l++)
            c[l] += ico_v[ico_f[f][k]][l];
      double cl = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      for (int l = 0; l < 3; l++)
         dod_v[f][l] = c[l] / cl * sqrt(3.0);
   }
   for (int vtx = 0; vtx < 12; vtx++) {
      int ring[5], m = 0;
      for (int f = 0; f < 20 && m < 5; f++)
         if (ico_f[f][0] == vtx || ico_f[f][1] == vtx || ico_f[f][2] == vtx)
            ring[m++] = f;
      /* sort by angle in the plane orthogonal to the vertex direction */
      const double *axis = ico_v[vtx];
      double u[3], w[3], ang[5];
      double ref[3] = { dod_v[ring[0]][0], dod_v[ring[0]][1], dod_v[ring[0]][2] };
      double d = ref[0] * axis[0] + ref[1] * axis[1] + ref[2] * axis[2];
      for (int l = 0; l < 3; l++)
         u[l] = ref[l] - d * axis[l];
      w[0] = axis[1] * u[2] - axis[2] * u[1];
      w[1] = axis[2] * u[0] - axis[0] * u[2];
      w[2] = axis[0] * u[1] - axis[1] * u[0];
      for (int k = 0; k < 5; k++) {
         const double *p = dod_v[ring[k]];
         ang[k] = atan2(p[0] * w[0] + p[1] * w[1] + p[2] * w[2],
                        p[0] * u[0] + p[1] * u[1] + p[2] * u[2]);
      }
      for (int a = 0; a < 5; a++)
         for (int b = a + 1; b < 5; b++)
            if (ang[b] < ang[a]) {
               double ta = ang[a]; ang[a] = ang[b]; ang[b] = ta;
               int tr = ring[a]; ring[a] = ring[b]; ring[b] = tr;
            }
      memcpy(dod_f[vtx], ring, sizeof ring);
   }
   solids_built = true;
}

static void icosahedron(bool wire)
{
   if (!solids_built)
      build_solids();
   polyhedron((const double (*)[3])ico_v, &ico_f[0][0], 20, 3, 1.0, wire);
}

static void dodecahedron(bool wire)
{
   if (!solids_built)
      build_solids();
   polyhedron((const double (*)[3])dod_v, &dod_f[0][0], 12, 5, 1.0, wire);
}

GLUT_EXPORT void glutSolidTetrahedron(void) { tetrahedron(false); }
GLUT_EXPORT void glutWireTetrahedron(void) { tetrahedron(true); }
GLUT_EXPORT void glutSolidOctahedron(void) { octahedron(false); }
GLUT_EXPORT void glutWireOctahedron(void) { octahedron(true); }
GLUT_EXPORT void glutSolidIcosahedron(void) { icosahedron(false); }
GLUT_EXPORT void glutWireIcosahedron(void) { icosahedron(true); }
GLUT_EXPORT void glutSolidDodecahedron(void) { dodecahedron(false); }
GLUT_EXPORT void glutWireDodecahedron(void) { dodecahedron(true); }

/* ---- freeglut's cylinder ------------------------------------------------ */

/* freeglut 3's fghCircleTable with a negative count (the clockwise
 * circle its cylinder uses): n + 1 entries, the last the first again. */
static void cylinder_circle(GLfloat *sint, GLfloat *cost, int slices)
{
   const GLfloat angle = 2 * (GLfloat)M_PI / (GLfloat)(-slices);
   sint[0] = 0.0f;
   cost[0] = 1.0f;
   for (int i = 1; i < slices; i++) {
      sint[i] = (GLfloat)sin(angle * i);
      cost[i] = (GLfloat)cos(angle * i);
   }
   sint[slices] = sint[0];
   cost[slices] = cost[0];
}

/* freeglut 3's fghCylinder: the same vertices and normals (the closing
 * disks' rings repeated with axial normals), the same index order, drawn
 * as freeglut draws on OpenGL 1.1: vertex and normal arrays, one
 * glDrawElements per triangle strip (solid) or GL_LINES for the slices
 * and a GL_LINE_LOOP per stack ring (wire), so that a program draws the
 * same triangles on libfixglut as on freeglut. */
static void cylinder(GLfloat radius, GLfloat height, GLint slices, GLint stacks, bool wire)
{
   if (slices <= 0 || stacks < 1)
      return;
   const int nvert = slices * (stacks + 3) + 2;
   if (nvert > 65535)
      glut_warn("glutCylinder: too many slices or stacks requested, indices will wrap");
   const GLfloat zstep = height / (GLfloat)stacks;
   GLfloat *sint = malloc((size_t)(slices + 1) * sizeof *sint);
   GLfloat *cost = malloc((size_t)(slices + 1) * sizeof *cost);
   GLfloat *v = malloc((size_t)nvert * 3 * sizeof *v);
   GLfloat *n = malloc((size_t)nvert * 3 * sizeof *n);
   if (!sint || !cost || !v || !n)
      glut_fatal("out of memory for a cylinder");
   cylinder_circle(sint, cost, slices);

   int idx = 0;
   GLfloat z = 0.0f;
#define CYL_VERTEX(x, y, zz, nx, ny, nz) \
   (v[idx] = (x), v[idx + 1] = (y), v[idx + 2] = (zz), \
    n[idx] = (nx), n[idx + 1] = (ny), n[idx + 2] = (nz), idx += 3)
   CYL_VERTEX(0.0f, 0.0f, 0.0f, 0.0f, 0.0f, -1.0f);          /* the z = 0 disk's centre */
   for (int j = 0; j < slices; j++)
      CYL_VERTEX(cost[j] * radius, sint[j] * radius, z, 0.0f, 0.0f, -1.0f);
   for (int i = 0; i < stacks + 1; i++) {
      for (int j = 0; j < slices; j++)
         CYL_VERTEX(cost[j] * radius, sint[j] * radius, z, cost[j], sint[j], 0.0f);
      z += zstep;
   }
   z -= zstep;
   for (int j = 0; j < slices; j++)
      CYL_VERTEX(cost[j] * radius, sint[j] * radius, z, 0.0f, 0.0f, 1.0f);
   CYL_VERTEX(0.0f, 0.0f, height, 0.0f, 0.0f, 1.0f);         /* the far disk's centre */
#undef CYL_VERTEX

   glEnableClientState(GL_VERTEX_ARRAY);
   glEnableClientState(GL_NORMAL_ARRAY);
   glVertexPointer(3, GL_FLOAT, 0, v);
   glNormalPointer(GL_FLOAT, 0, n);
   if (wire) {
      GLushort *stack_idx = malloc((size_t)slices * (stacks + 1) * sizeof *stack_idx);
      GLushort *slice_idx = malloc((size_t)slices * 2 * sizeof *slice_idx);
      if (!stack_idx || !slice_idx)
         glut_fatal("out of memory for a cylinder");
      idx = 0;
      for (int i = 0; i < stacks + 1; i++) {
         GLushort offset = (GLushort)(1 + (i + 1) * slices);
         for (int j = 0; j < slices; j++)
            stack_idx[idx++] = (GLushort)(offset + j);
      }
      idx = 0;
      for (int i = 0; i < slices; i++) {
         GLushort offset = (GLushort)(1 + i);
         slice_idx[idx++] = (GLushort)(offset + slices);
         slice_idx[idx++] = (GLushort)(offset + (stacks + 1) * slices);
      }
      glDrawElements(GL_LINES, slices * 2, GL_UNSIGNED_SHORT, slice_idx);
      for (int i = 0; i < stacks + 1; i++)
         glDrawElements(GL_LINE_LOOP, slices, GL_UNSIGNED_SHORT, stack_idx + i * slices);
      free(stack_idx);
      free(slice_idx);
   } else {
      const int per_strip = (slices + 1) * 2;
      GLushort *strip = malloc((size_t)per_strip * (stacks + 2) * sizeof *strip);
      if (!strip)
         glut_fatal("out of memory for a cylinder");
      idx = 0;
      for (int j = 0; j < slices; j++, idx += 2) {
         strip[idx] = 0;
         strip[idx + 1] = (GLushort)(j + 1);
      }
      strip[idx] = 0;
      strip[idx + 1] = 1;
      idx += 2;
      for (int i = 0; i < stacks; i++, idx += 2) {
         GLushort offset = (GLushort)(1 + (i + 1) * slices);
         for (int j = 0; j < slices; j++, idx += 2) {
            strip[idx] = (GLushort)(offset + j);
            strip[idx + 1] = (GLushort)(offset + j + slices);
         }
         strip[idx] = offset;
         strip[idx + 1] = (GLushort)(offset + slices);
      }
      GLushort offset = (GLushort)(1 + (stacks + 2) * slices);
      for (int j = 0; j < slices; j++, idx += 2) {
         strip[idx] = (GLushort)(offset + j);
         strip[idx + 1] = (GLushort)(nvert - 1);
      }
      strip[idx] = offset;
      strip[idx + 1] = (GLushort)(nvert - 1);
      for (int i = 0; i < stacks + 2; i++)
         glDrawElements(GL_TRIANGLE_STRIP, per_strip, GL_UNSIGNED_SHORT, strip + i * per_strip);
      free(strip);
   }
   glDisableClientState(GL_VERTEX_ARRAY);
   glDisableClientState(GL_NORMAL_ARRAY);
   free(sint);
   free(cost);
   free(v);
   free(n);
}

GLUT_EXPORT void glutSolidCylinder(double radius, double height, GLint slices, GLint stacks)
{
   cylinder((GLfloat)radius, (GLfloat)height, slices, stacks, false);
}

GLUT_EXPORT void glutWireCylinder(double radius, double height, GLint slices, GLint stacks)
{
   cylinder((GLfloat)radius, (GLfloat)height, slices, stacks, true);
}
