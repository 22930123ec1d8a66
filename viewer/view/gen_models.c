/*
 * gen-models: writes the viewer's bundled models into a directory at build
 * time, one per format assimp reads for the viewer:
 *
 *   sphere.ply              a UV sphere with per-vertex normals (ASCII PLY)
 *   torus.stl               a torus, binary STL (facet normals only: the
 *                           viewer generates smooth ones)
 *   teapot.obj, teapot.mtl  Newell's teapot, its 32 Bezier patches
 *                           (viewer/glut/glut_teapot_data.h) tessellated,
 *                           no normals in the file (generated on loading)
 *   lowpoly.obj, lowpoly.mtl  a faceted low-poly house with seven materials
 *                           (Ka, Kd, Ks, Ke, Ns, d, illum 0/1/2), quads and
 *                           one normal per face
 *   globe.obj, globe.mtl, globe.png, ring_alpha.png
 *                           a textured globe (UVs, map_Kd) in a ring
 *                           (map_Kd and map_d: translucent stripes), the
 *                           images written through OpenImageIO
 *   colors.ply              a bumpy sphere with per-vertex colours (binary
 *                           PLY, uchar red green blue), no normals
 *   rgbcube.obj             the RGB colour cube: per-vertex colours in OBJ's
 *                           "v x y z r g b" form, quads, no normals, no MTL
 *
 *   gen-models DIR
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../glut/glut_teapot_data.h"
#include "fv_image.h"

#define PI 3.14159265358979323846

static FILE *open_out(const char *dir, const char *name, const char *mode)
{
   char path[4096];
   snprintf(path, sizeof path, "%s/%s", dir, name);
   FILE *f = fopen(path, mode);
   if (!f) {
      perror(path);
      exit(1);
   }
   return f;
}

static void close_out(FILE *f)
{
   if (ferror(f) || fclose(f) != 0) {
      fprintf(stderr, "gen-models: write error\n");
      exit(1);
   }
}

/* ---- sphere.ply ------------------------------------------------------------ */

static void sphere_ply(const char *dir)
{
   enum { SLICES = 40, STACKS = 20 };
   FILE *f = open_out(dir, "sphere.ply", "w");
   int nv = 2 + (STACKS - 1) * SLICES;
   int nf = 2 * SLICES + 2 * SLICES * (STACKS - 2);
   fprintf(f, "ply\nformat ascii 1.0\ncomment fixgl-view: a UV sphere, radius 1\n"
              "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "property float nx\nproperty float ny\nproperty float nz\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n", nv, nf);
   fprintf(f, "0 1 0 0 1 0\n");
   for (int i = 1; i < STACKS; i++) {
      double th = PI * i / STACKS;
      for (int j = 0; j < SLICES; j++) {
         double ph = 2.0 * PI * j / SLICES;
         double x = sin(th) * sin(ph), y = cos(th), z = sin(th) * cos(ph);
         fprintf(f, "%.6f %.6f %.6f %.6f %.6f %.6f\n", x, y, z, x, y, z);
      }
   }
   fprintf(f, "0 -1 0 0 -1 0\n");
   const int south = nv - 1;
#define RING(i, j) (1 + ((i) - 1) * SLICES + ((j) % SLICES))
   for (int j = 0; j < SLICES; j++)
      fprintf(f, "3 0 %d %d\n", RING(1, j), RING(1, j + 1));
   for (int i = 1; i < STACKS - 1; i++)
      for (int j = 0; j < SLICES; j++) {
         fprintf(f, "3 %d %d %d\n", RING(i, j), RING(i + 1, j), RING(i + 1, j + 1));
         fprintf(f, "3 %d %d %d\n", RING(i, j), RING(i + 1, j + 1), RING(i, j + 1));
      }
   for (int j = 0; j < SLICES; j++)
      fprintf(f, "3 %d %d %d\n", RING(STACKS - 1, j), south, RING(STACKS - 1, j + 1));
#undef RING
   close_out(f);
}

/* ---- torus.stl ------------------------------------------------------------- */

static void put_f32(FILE *f, float v)
{
   uint32_t u;
   memcpy(&u, &v, 4);
   unsigned char b[4] = { (unsigned char)u, (unsigned char)(u >> 8), (unsigned char)(u >> 16),
                          (unsigned char)(u >> 24) };
   fwrite(b, 1, 4, f);
}

static void torus_point(int i, int j, int rings, int sides, float p[3])
{
   const double R = 1.0, r = 0.4;
   double u = 2.0 * PI * i / rings, v = 2.0 * PI * j / sides;
   p[0] = (float)((R + r * cos(v)) * cos(u));
   p[1] = (float)(r * sin(v));
   p[2] = (float)((R + r * cos(v)) * -sin(u));
}

static void stl_triangle(FILE *f, const float a[3], const float b[3], const float c[3])
{
   double e1[3], e2[3], n[3];
   for (int k = 0; k < 3; k++)
      e1[k] = b[k] - a[k], e2[k] = c[k] - a[k];
   n[0] = e1[1] * e2[2] - e1[2] * e2[1];
   n[1] = e1[2] * e2[0] - e1[0] * e2[2];
   n[2] = e1[0] * e2[1] - e1[1] * e2[0];
   double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
   for (int k = 0; k < 3; k++)
      put_f32(f, (float)(l > 0.0 ? n[k] / l : 0.0));
   for (int k = 0; k < 3; k++)
      put_f32(f, a[k]);
   for (int k = 0; k < 3; k++)
      put_f32(f, b[k]);
   for (int k = 0; k < 3; k++)
      put_f32(f, c[k]);
   fwrite("\0\0", 1, 2, f);
}

static void torus_stl(const char *dir)
{
   enum { RINGS = 48, SIDES = 24 };
   FILE *f = open_out(dir, "torus.stl", "wb");
   char header[80] = "fixgl-view: a torus, R 1, r 0.4 (binary STL)";
   fwrite(header, 1, sizeof header, f);
   uint32_t n = 2 * RINGS * SIDES;
   unsigned char nb[4] = { (unsigned char)n, (unsigned char)(n >> 8), (unsigned char)(n >> 16),
                           (unsigned char)(n >> 24) };
   fwrite(nb, 1, 4, f);
   for (int i = 0; i < RINGS; i++)
      for (int j = 0; j < SIDES; j++) {
         float p00[3], p10[3], p11[3], p01[3];
         torus_point(i, j, RINGS, SIDES, p00);
         torus_point(i + 1, j, RINGS, SIDES, p10);
         torus_point(i + 1, j + 1, RINGS, SIDES, p11);
         torus_point(i, j + 1, RINGS, SIDES, p01);
         stl_triangle(f, p00, p10, p11);
         stl_triangle(f, p00, p11, p01);
      }
   close_out(f);
}

/* ---- teapot.obj ------------------------------------------------------------ */

static double bernstein(int i, double t)
{
   static const double c[4] = { 1, 3, 3, 1 };
   return c[i] * pow(t, i) * pow(1.0 - t, 3 - i);
}

static void teapot_obj(const char *dir)
{
   enum { GRID = 10 };
   FILE *m = open_out(dir, "teapot.mtl", "w");
   fprintf(m, "# fixgl-view: porcelain\nnewmtl porcelain\nKa 0.2 0.2 0.22\nKd 0.75 0.78 0.85\n"
              "Ks 0.8 0.8 0.8\nNs 60\nd 1\nillum 2\n");
   close_out(m);
   FILE *f = open_out(dir, "teapot.obj", "w");
   fprintf(f, "# fixgl-view: Newell's teapot, 32 bicubic patches tessellated %dx%d;\n"
              "# no normals (the viewer generates smooth ones)\nmtllib teapot.mtl\n"
              "o teapot\nusemtl porcelain\n", GRID, GRID);
   int base = 1;
   for (int p = 0; p < 32; p++) {
      double pts[GRID + 1][GRID + 1][3];
      for (int a = 0; a <= GRID; a++)
         for (int b = 0; b <= GRID; b++) {
            double u = (double)a / GRID, v = (double)b / GRID, q[3] = { 0, 0, 0 };
            for (int j = 0; j < 4; j++)
               for (int k = 0; k < 4; k++) {
                  const float *cp = teapot_points[teapot_patches[p][j * 4 + k]];
                  double w = bernstein(j, u) * bernstein(k, v);
                  for (int c = 0; c < 3; c++)
                     q[c] += w * cp[c];
               }
            /* GLUT's orientation: the lid up +y (a 270 degree turn about x) */
            pts[a][b][0] = q[0], pts[a][b][1] = q[2], pts[a][b][2] = -q[1];
            fprintf(f, "v %.6f %.6f %.6f\n", pts[a][b][0], pts[a][b][1], pts[a][b][2]);
         }
      /* two triangles per cell, counter-clockwise seen from outside (the
       * patches' dP/du x dP/dv points inwards: GLUT's teapot has clockwise
       * front faces); the degenerate ones of the patches' poles are left out */
      for (int a = 0; a < GRID; a++)
         for (int b = 0; b < GRID; b++) {
            const int c[4][2] = { { a, b }, { a, b + 1 }, { a + 1, b + 1 }, { a + 1, b } };
            const int tri[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };
            for (int t = 0; t < 2; t++) {
               const double *v0 = pts[c[tri[t][0]][0]][c[tri[t][0]][1]];
               const double *v1 = pts[c[tri[t][1]][0]][c[tri[t][1]][1]];
               const double *v2 = pts[c[tri[t][2]][0]][c[tri[t][2]][1]];
               double e1[3], e2[3];
               for (int k = 0; k < 3; k++)
                  e1[k] = v1[k] - v0[k], e2[k] = v2[k] - v0[k];
               double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                      cz = e1[0] * e2[1] - e1[1] * e2[0];
               if (cx * cx + cy * cy + cz * cz < 1e-14)
                  continue;
               fprintf(f, "f");
               for (int k = 0; k < 3; k++)
                  fprintf(f, " %d", base + c[tri[t][k]][0] * (GRID + 1) + c[tri[t][k]][1]);
               fprintf(f, "\n");
            }
         }
      base += (GRID + 1) * (GRID + 1);
   }
   close_out(f);
}

/* ---- lowpoly.obj ----------------------------------------------------------- */

static FILE *obj;
static int obj_v, obj_vn;

/* A planar polygon (counter-clockwise seen from outside) with its own
 * normal: flat facets whatever the shading. */
static void face(int n, const double (*p)[3])
{
   double e1[3], e2[3];
   for (int k = 0; k < 3; k++)
      e1[k] = p[1][k] - p[0][k], e2[k] = p[2][k] - p[0][k];
   double nx = e1[1] * e2[2] - e1[2] * e2[1], ny = e1[2] * e2[0] - e1[0] * e2[2],
          nz = e1[0] * e2[1] - e1[1] * e2[0];
   double l = sqrt(nx * nx + ny * ny + nz * nz);
   fprintf(obj, "vn %.6f %.6f %.6f\n", nx / l, ny / l, nz / l);
   obj_vn++;
   for (int i = 0; i < n; i++)
      fprintf(obj, "v %.6f %.6f %.6f\n", p[i][0], p[i][1], p[i][2]);
   fprintf(obj, "f");
   for (int i = 0; i < n; i++)
      fprintf(obj, " %d//%d", obj_v + 1 + i, obj_vn);
   fprintf(obj, "\n");
   obj_v += n;
}

/* An axis-aligned box [x0,x1] x [y0,y1] x [z0,z1] as six quads. */
static void box(double x0, double y0, double z0, double x1, double y1, double z1)
{
   const double q[6][4][3] = {
      { { x0, y0, z1 }, { x1, y0, z1 }, { x1, y1, z1 }, { x0, y1, z1 } },   /* +z */
      { { x1, y0, z0 }, { x0, y0, z0 }, { x0, y1, z0 }, { x1, y1, z0 } },   /* -z */
      { { x1, y0, z1 }, { x1, y0, z0 }, { x1, y1, z0 }, { x1, y1, z1 } },   /* +x */
      { { x0, y0, z0 }, { x0, y0, z1 }, { x0, y1, z1 }, { x0, y1, z0 } },   /* -x */
      { { x0, y1, z1 }, { x1, y1, z1 }, { x1, y1, z0 }, { x0, y1, z0 } },   /* +y */
      { { x0, y0, z0 }, { x1, y0, z0 }, { x1, y0, z1 }, { x0, y0, z1 } },   /* -y */
   };
   for (int i = 0; i < 6; i++)
      face(4, q[i]);
}

static void lowpoly_obj(const char *dir)
{
   FILE *m = open_out(dir, "lowpoly.mtl", "w");
   fprintf(m,
      "# fixgl-view: the low-poly house's materials\n"
      "newmtl walls\nKa 0.25 0.24 0.2\nKd 0.85 0.8 0.7\nKs 0.15 0.15 0.15\nNs 8\nd 1\nillum 2\n\n"
      "newmtl roof\nKa 0.2 0.05 0.04\nKd 0.7 0.15 0.1\nKs 0.5 0.4 0.4\nNs 32\nd 1\nillum 2\n\n"
      "newmtl brick\nKa 0.15 0.1 0.08\nKd 0.5 0.3 0.25\nKs 0.9 0.9 0.9\nNs 10\nd 1\nillum 1\n\n"
      "newmtl door\nKa 0.1 0.06 0.03\nKd 0.35 0.2 0.1\nKs 0.3 0.3 0.3\nNs 20\nd 1\nillum 2\n\n"
      "newmtl glass\nKa 0.05 0.08 0.1\nKd 0.3 0.5 0.8\nKs 0.9 0.9 0.9\nNs 96\nd 0.5\nillum 2\n\n"
      "newmtl lamp\nKa 0 0 0\nKd 1 0.9 0.5\nKs 0 0 0\nKe 1 0.9 0.5\nNs 0\nd 1\nillum 0\n\n"
      "newmtl grass\nKa 0.08 0.15 0.06\nKd 0.3 0.6 0.25\nKs 0 0 0\nNs 0\nd 1\nillum 1\n");
   close_out(m);

   obj = open_out(dir, "lowpoly.obj", "w");
   fprintf(obj, "# fixgl-view: a faceted low-poly house (quads, one normal per face)\n"
                "mtllib lowpoly.mtl\no house\n");
   fprintf(obj, "usemtl walls\n");
   box(-1.0, 0.0, -0.75, 1.0, 1.2, 0.75);
   fprintf(obj, "usemtl roof\n");
   {
      const double a[4][3] = { { -1.1, 1.2, 0.85 }, { 1.1, 1.2, 0.85 }, { 1.1, 1.9, 0.0 }, { -1.1, 1.9, 0.0 } };
      const double b[4][3] = { { 1.1, 1.2, -0.85 }, { -1.1, 1.2, -0.85 }, { -1.1, 1.9, 0.0 }, { 1.1, 1.9, 0.0 } };
      const double c[3][3] = { { 1.1, 1.2, 0.85 }, { 1.1, 1.2, -0.85 }, { 1.1, 1.9, 0.0 } };
      const double d[3][3] = { { -1.1, 1.2, -0.85 }, { -1.1, 1.2, 0.85 }, { -1.1, 1.9, 0.0 } };
      const double e[4][3] = { { -1.1, 1.2, -0.85 }, { 1.1, 1.2, -0.85 }, { 1.1, 1.2, 0.85 }, { -1.1, 1.2, 0.85 } };
      face(4, a), face(4, b), face(3, c), face(3, d), face(4, e);
   }
   fprintf(obj, "usemtl brick\n");
   box(0.45, 1.4, -0.45, 0.7, 2.1, -0.2);
   fprintf(obj, "usemtl door\n");
   {
      const double q[4][3] = { { -0.2, 0.0, 0.76 }, { 0.2, 0.0, 0.76 }, { 0.2, 0.75, 0.76 }, { -0.2, 0.75, 0.76 } };
      face(4, q);
   }
   fprintf(obj, "usemtl glass\n");
   for (int s = -1; s <= 1; s += 2) {
      const double q[4][3] = { { 0.4 * s - 0.2, 0.5, 0.77 }, { 0.4 * s + 0.2, 0.5, 0.77 },
                               { 0.4 * s + 0.2, 0.9, 0.77 }, { 0.4 * s - 0.2, 0.9, 0.77 } };
      face(4, q);
      const double r[4][3] = { { 1.01, 0.5, 0.2 * s + 0.2 }, { 1.01, 0.5, 0.2 * s - 0.2 },
                               { 1.01, 0.9, 0.2 * s - 0.2 }, { 1.01, 0.9, 0.2 * s + 0.2 } };
      face(4, r);
   }
   fprintf(obj, "usemtl lamp\n");
   {
      /* an octahedron above the door */
      const double c[3] = { 0.0, 0.95, 0.9 }, r = 0.08;
      const double ax[6][3] = { { r, 0, 0 }, { 0, r, 0 }, { 0, 0, r }, { -r, 0, 0 }, { 0, -r, 0 }, { 0, 0, -r } };
      for (int sx = 0; sx < 2; sx++)
         for (int sy = 0; sy < 2; sy++)
            for (int sz = 0; sz < 2; sz++) {
               const double *X = ax[sx ? 3 : 0], *Y = ax[sy ? 4 : 1], *Z = ax[sz ? 5 : 2];
               double t[3][3];
               for (int k = 0; k < 3; k++)
                  t[0][k] = c[k] + X[k], t[1][k] = c[k] + Y[k], t[2][k] = c[k] + Z[k];
               /* counter-clockwise seen from outside: swap when the octant is odd */
               if ((sx + sy + sz) % 2)
                  for (int k = 0; k < 3; k++) {
                     double tmp = t[1][k];
                     t[1][k] = t[2][k], t[2][k] = tmp;
                  }
               face(3, (const double(*)[3])t);
            }
   }
   fprintf(obj, "usemtl grass\n");
   {
      /* a hexagonal slab under the house */
      double top[6][3], bot[6][3];
      for (int i = 0; i < 6; i++) {
         double a = 2.0 * PI * i / 6 + PI / 6;
         top[i][0] = 1.8 * cos(a), top[i][1] = 0.0, top[i][2] = -1.8 * sin(a);
         bot[i][0] = top[i][0], bot[i][1] = -0.15, bot[i][2] = top[i][2];
      }
      face(6, (const double(*)[3])top);
      double rb[6][3];
      for (int i = 0; i < 6; i++)
         memcpy(rb[i], bot[5 - i], sizeof rb[i]);
      face(6, (const double(*)[3])rb);
      for (int i = 0; i < 6; i++) {
         int j = (i + 1) % 6;
         const double q[4][3] = { { bot[i][0], bot[i][1], bot[i][2] }, { bot[j][0], bot[j][1], bot[j][2] },
                                  { top[j][0], top[j][1], top[j][2] }, { top[i][0], top[i][1], top[i][2] } };
         face(4, q);
      }
   }
   close_out(obj);
}

/* ---- globe.obj ------------------------------------------------------------- */

static void write_image(const char *dir, const char *name, int w, int h,
                        const unsigned char *rgba)
{
   char path[4096], err[512];
   snprintf(path, sizeof path, "%s/%s", dir, name);
   if (fv_image_write(path, w, h, rgba, err, sizeof err) != 0) {
      fprintf(stderr, "gen-models: %s: %s\n", path, err);
      exit(1);
   }
}

/* The globe's texture (128 x 64, top row first: the north pole): sea and
 * land by a few octaves of sines, ice caps, a grid every 60 degrees; the
 * ring's alpha (the same size, as map_d must be): stripes from opaque to
 * clear. */
static void globe_images(const char *dir)
{
   enum { W = 128, H = 64, RW = W, RH = H };
   static unsigned char px[W * H * 4], ring[RW * RH * 4];
   for (int y = 0; y < H; y++)
      for (int x = 0; x < W; x++) {
         double lon = 2.0 * PI * (x + 0.5) / W, lat = PI * (0.5 - (y + 0.5) / H);
         double land = sin(3.0 * lon) * cos(2.0 * lat) + 0.6 * sin(5.0 * lon + 1.3) * sin(3.0 * lat)
                       + 0.35 * cos(9.0 * lon - 2.0 * lat);
         unsigned char *p = &px[(y * W + x) * 4];
         if (fabs(lat) > 1.25) {
            p[0] = 235, p[1] = 240, p[2] = 250;                         /* ice */
         } else if (land > 0.15) {
            double h = land - 0.15;
            p[0] = (unsigned char)(60 + 120 * fmin(h, 1.0));
            p[1] = (unsigned char)(140 - 40 * fmin(h, 1.0));
            p[2] = (unsigned char)(50 + 20 * fmin(h, 1.0));
         } else {
            p[0] = 20, p[1] = (unsigned char)(70 + 40 * (land + 2.0) / 2.15), p[2] = 170;
         }
         if (x % (W / 6) == 0 || y % (H / 3) == 0)
            p[0] = p[1] = p[2] = 250;                                   /* the grid */
         p[3] = 255;
      }
   write_image(dir, "globe.png", W, H, px);
   for (int y = 0; y < RH; y++)
      for (int x = 0; x < RW; x++) {
         unsigned char *p = &ring[(y * RW + x) * 4];
         unsigned char a = (unsigned char)((x / 16) % 2 ? 255 : 64 + 12 * (x % 16));
         p[0] = p[1] = p[2] = a, p[3] = a;
      }
   write_image(dir, "ring_alpha.png", RW, RH, ring);
}

static void globe_obj(const char *dir)
{
   enum { SLICES = 32, STACKS = 16, RING = 48 };
   globe_images(dir);
   FILE *m = open_out(dir, "globe.mtl", "w");
   fprintf(m, "# fixgl-view: a textured globe in a translucent ring\n"
              "newmtl globe\nKa 0.3 0.3 0.3\nKd 1 1 1\nKs 0.4 0.4 0.4\nNs 30\nd 1\nillum 2\n"
              "map_Kd globe.png\n\n"
              "newmtl ring\nKa 0.3 0.25 0.2\nKd 0.9 0.75 0.5\nKs 0.2 0.2 0.2\nNs 10\nd 1\n"
              "illum 2\nmap_Kd globe.png\nmap_d ring_alpha.png\n");
   close_out(m);
   FILE *f = open_out(dir, "globe.obj", "w");
   fprintf(f, "# fixgl-view: a UV sphere (radius 1) textured by globe.png, a ring around it\n"
              "mtllib globe.mtl\no globe\nusemtl globe\n");
   /* the sphere: (SLICES + 1) x (STACKS + 1) vertices, the seam doubled */
   for (int i = 0; i <= STACKS; i++)
      for (int j = 0; j <= SLICES; j++) {
         double th = PI * i / STACKS, ph = 2.0 * PI * j / SLICES;
         double x = sin(th) * sin(ph), y = cos(th), z = sin(th) * cos(ph);
         fprintf(f, "v %.6f %.6f %.6f\nvt %.6f %.6f\nvn %.6f %.6f %.6f\n", x, y, z,
                 (double)j / SLICES, 1.0 - (double)i / STACKS, x, y, z);
      }
#define GV(i, j) (1 + (i) * (SLICES + 1) + (j))
   for (int i = 0; i < STACKS; i++)
      for (int j = 0; j < SLICES; j++) {
         int a = GV(i, j), b = GV(i + 1, j), c = GV(i + 1, j + 1), d = GV(i, j + 1);
         if (i > 0)
            fprintf(f, "f %d/%d/%d %d/%d/%d %d/%d/%d\n", a, a, a, b, b, b, d, d, d);
         if (i < STACKS - 1)
            fprintf(f, "f %d/%d/%d %d/%d/%d %d/%d/%d\n", b, b, b, c, c, c, d, d, d);
      }
#undef GV
   /* the ring: a tilted flat annulus (one face, its normal up), u around,
    * v across */
   const int base = (SLICES + 1) * (STACKS + 1);
   fprintf(f, "o ring\nusemtl ring\n");
   const double tilt = 0.35;
   for (int j = 0; j <= RING; j++)
      for (int k = 0; k < 2; k++) {
         double ph = 2.0 * PI * j / RING, r = k ? 1.7 : 1.25;
         double x = r * cos(ph), z = r * sin(ph);
         double y = -z * sin(tilt), zz = z * cos(tilt);
         fprintf(f, "v %.6f %.6f %.6f\nvt %.6f %.6f\n", x, y, zz, 2.0 * j / RING, (double)k);
      }
   fprintf(f, "vn 0 %.6f %.6f\n", cos(tilt), sin(tilt));
   const int up = base + 1;
   for (int j = 0; j < RING; j++) {
      int a = base + 1 + j * 2, b = a + 1, c = a + 3, d = a + 2;
      fprintf(f, "f %d/%d/%d %d/%d/%d %d/%d/%d %d/%d/%d\n", a, a, up, d, d, up, c, c, up, b, b, up);
   }
   close_out(f);
}

/* ---- colors.ply ------------------------------------------------------------ */

static void colors_ply(const char *dir)
{
   enum { SLICES = 36, STACKS = 18 };
   FILE *f = open_out(dir, "colors.ply", "wb");
   const int nv = (STACKS + 1) * SLICES, nf = 2 * SLICES * STACKS;
   fprintf(f, "ply\nformat binary_little_endian 1.0\n"
              "comment fixgl-view: a bumpy sphere with per-vertex colours, no normals\n"
              "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n", nv, nf);
   for (int i = 0; i <= STACKS; i++)
      for (int j = 0; j < SLICES; j++) {
         double th = PI * i / STACKS, ph = 2.0 * PI * j / SLICES;
         double r = 1.0 + 0.12 * sin(5.0 * ph) * sin(4.0 * th);
         float p[3] = { (float)(r * sin(th) * sin(ph)), (float)(r * cos(th)),
                        (float)(r * sin(th) * cos(ph)) };
         for (int k = 0; k < 3; k++)
            put_f32(f, p[k]);
         unsigned char c[3] = { (unsigned char)(127.5 + 127.0 * sin(ph)),
                                (unsigned char)(127.5 + 127.0 * cos(th)),
                                (unsigned char)(127.5 + 127.0 * cos(ph + 1.0)) };
         fwrite(c, 1, 3, f);
      }
   /* every quad as two triangles, counter-clockwise from outside (at the
    * poles: degenerate, kept: the file is as a scanner writes it) */
   for (int i = 0; i < STACKS; i++)
      for (int j = 0; j < SLICES; j++) {
         int32_t a = i * SLICES + j, b = (i + 1) * SLICES + j,
                 c = (i + 1) * SLICES + (j + 1) % SLICES, d = i * SLICES + (j + 1) % SLICES;
         const int32_t t[2][3] = { { a, b, c }, { a, c, d } };
         for (int k = 0; k < 2; k++) {
            fputc(3, f);
            for (int v = 0; v < 3; v++) {
               uint32_t u = (uint32_t)t[k][v];
               unsigned char b4[4] = { (unsigned char)u, (unsigned char)(u >> 8),
                                       (unsigned char)(u >> 16), (unsigned char)(u >> 24) };
               fwrite(b4, 1, 4, f);
            }
         }
      }
   close_out(f);
}

/* ---- rgbcube.obj ---------------------------------------------------------- */

static void rgbcube_obj(const char *dir)
{
   FILE *f = open_out(dir, "rgbcube.obj", "w");
   fprintf(f, "# fixgl-view: the RGB colour cube, a colour per vertex (v x y z r g b)\no rgbcube\n");
   for (int i = 0; i < 8; i++) {
      const int r = i & 1, g = (i >> 1) & 1, b = (i >> 2) & 1;
      fprintf(f, "v %d %d %d %d %d %d\n", 2 * r - 1, 2 * g - 1, 2 * b - 1, r, g, b);
   }
   /* counter-clockwise from outside; vertex i + 1 is (r, g, b) = bits of i */
   static const int q[6][4] = { { 1, 3, 7, 5 }, { 0, 4, 6, 2 }, { 2, 6, 7, 3 },
                                { 0, 1, 5, 4 }, { 4, 5, 7, 6 }, { 0, 2, 3, 1 } };
   for (int i = 0; i < 6; i++)
      fprintf(f, "f %d %d %d %d\n", q[i][0] + 1, q[i][1] + 1, q[i][2] + 1, q[i][3] + 1);
   close_out(f);
}

int main(int argc, char **argv)
{
   if (argc != 2) {
      fprintf(stderr, "usage: gen-models DIR\n");
      return 2;
   }
   sphere_ply(argv[1]);
   torus_stl(argv[1]);
   teapot_obj(argv[1]);
   lowpoly_obj(argv[1]);
   globe_obj(argv[1]);
   colors_ply(argv[1]);
   rgbcube_obj(argv[1]);
   return 0;
}
