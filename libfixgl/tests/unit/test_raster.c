/*
 * test_raster.c - unit tests of the raster core's triangle setup
 * (raster/r_tri.c): snapping, edge functions and the fill rule.
 *
 * The rules (ORACLE-NOTES.md "Rasterization: snapping, fill rule, edge
 * functions", r_tri.c): window coordinates are y-down;
 * a vertex snaps to X = RNE((x - 0.5) * 256), so the centre of pixel
 * (px, py) is (256 px, 256 py); for each edge i->j of a triangle with
 * positive snapped area, dcdx = Yi - Yj, dcdy = Xi - Xj,
 * c = dcdx Xi - dcdy Yi, plus 1 if dcdx < 0 or (dcdx == 0 and dcdy < 0),
 * and a pixel is covered iff c - dcdx 256 px + dcdy 256 py > 0 on all
 * three edges.  On the image (row 0 at the top) that is "top-left" turned
 * upside down: centres exactly on a left edge or on a horizontal bottom
 * edge are covered, on a right or top edge they are not.
 *
 * Every expected coverage map below was derived by hand from those
 * formulas; the derivation is in the comment above each map.  The maps
 * were also checked once against the oracle (OSMesa 22.3.6, llvmpipe)
 * drawing the same triangles through glOrtho(0, 16, 0, 16) on a 16 x 16
 * buffer, where window coordinates are exact.  A map is one
 * string per row, row 0 first (y-down, as the buffer is stored): '#' is a
 * pixel covered exactly once, '.' a pixel never touched.  Several triangles
 * are drawn one at a time into fresh buffers and their hits are counted, so
 * a double hit shows up as '2' and a gap as '.' where '#' is expected.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raster/r_kernel.h"
#include "raster/r_state.h"
#include "raster/r_scene.h"
#include "raster/r_tri_cover.h"

#include "check.h"

#define MAX_W 32
#define MAX_H 32

/* One snap step is 1/256 pixel; TIE is half of it. */
#define TIE (0.5f / 256.0f)

struct tri {
   float x[3], y[3];
};

/* The state objects of make_state's r_state, which the tests edit. */
static struct r_fb_state t_fb;
static struct r_rast_state t_rast;
static struct r_dsa_state t_dsa;
static struct r_blend_state t_blend;
static struct r_fs_state t_fs;

static struct r_state make_state(uint8_t *color, int w, int h)
{
   struct r_state rs;
   memset(&rs, 0, sizeof rs);
   memset(&t_fb, 0, sizeof t_fb);
   memset(&t_rast, 0, sizeof t_rast);
   memset(&t_dsa, 0, sizeof t_dsa);
   memset(&t_blend, 0, sizeof t_blend);
   memset(&t_fs, 0, sizeof t_fs);
   rs.fb = &t_fb;
   rs.rast = &t_rast;
   rs.dsa = &t_dsa;
   rs.blend = &t_blend;
   rs.fs = &t_fs;
   t_fb.color = color;
   t_fb.zs = NULL;
   t_fb.zs_format = R_ZS_NONE;
   t_fb.width = w;
   t_fb.height = h;
   rs.x0 = 0;
   rs.y0 = 0;
   rs.x1 = w;
   rs.y1 = h;
   rs.px0 = rs.py0 = 0;
   rs.px1 = w;
   rs.py1 = h;
   t_dsa.depth_test = false;
   t_dsa.depth_func = R_LESS;
   t_dsa.depth_write = false;
   t_fs.num_attribs = 1;
   t_fs.fs_inputs = 1u << R_FS_COLOR0;
   rs.flat_mask = 1u; /* colour from the provoking vertex */
   return rs;
}

static struct r_vertex make_vertex(float x, float y, const float rgba[4])
{
   struct r_vertex v;
   memset(&v, 0, sizeof v);
   v.pos[0] = x;
   v.pos[1] = y;
   v.pos[2] = 0.5f;
   v.pos[3] = 1.0f;
   for (int c = 0; c < 4; c++)
      v.attr[0][c] = rgba[c];
   return v;
}

static const float white[4] = { 1.0f, 1.0f, 1.0f, 1.0f };

/* Draws triangle t with its vertices in the order (o[0], o[1], o[2]) in
 * white into a fresh w x h buffer (heap-allocated to its exact size, so
 * that AddressSanitizer sees any write outside it) and adds its hits to
 * count[].  A touched pixel that is not exactly white is reported. */
static void draw_and_count(const char *file, int line, const char *what,
                           const struct r_state *proto, const struct tri *t,
                           const int o[3], int w, int h, int *count)
{
   uint8_t *buf = calloc((size_t)w * (size_t)h, 4);
   if (!buf) {
      check_fail(file, line, "%s: out of memory", what);
      return;
   }
   struct r_state rs = *proto;
   struct r_fb_state fb = *proto->fb;
   fb.color = buf;
   fb.width = w;
   fb.height = h;
   rs.fb = &fb;
   struct r_vertex v[3];
   for (int i = 0; i < 3; i++)
      v[i] = make_vertex(t->x[o[i]], t->y[o[i]], white);
   r_triangle(&rs, &v[0], &v[1], &v[2]);
   for (int i = 0; i < w * h; i++) {
      const uint8_t *p = buf + 4 * i;
      if (p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 0)
         continue;
      if (p[0] == 255 && p[1] == 255 && p[2] == 255 && p[3] == 255)
         count[i]++;
      else
         check_fail(file, line, "%s: pixel (%d,%d) = %u,%u,%u,%u, expected white or untouched",
                    what, i % w, i / w, p[0], p[1], p[2], p[3]);
   }
   free(buf);
}

/* Compares hit counts with a map; on a mismatch prints both. */
static void compare_map(const char *file, int line, const char *what, const int *count,
                        const char *const *map, int w, int h)
{
   bool ok = true;
   for (int y = 0; y < h; y++)
      for (int x = 0; x < w; x++)
         if (count[y * w + x] != (map[y][x] == '#' ? 1 : 0))
            ok = false;
   if (ok)
      return;
   check_fail(file, line, "%s: coverage differs (row 0 first; got | expected):", what);
   for (int y = 0; y < h; y++) {
      char got[MAX_W + 1];
      for (int x = 0; x < w; x++) {
         const int n = count[y * w + x];
         got[x] = n == 0 ? '.' : n == 1 ? '#' : (char)('0' + (n > 9 ? 9 : n));
      }
      got[w] = '\0';
      fprintf(stderr, "    %2d  %s | %s\n", y, got, map[y]);
   }
}

static const int order_id[3] = { 0, 1, 2 };

/* The six vertex orders: three rotations of each winding. */
static const int orders[6][3] = {
   { 0, 1, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
   { 1, 0, 2 }, { 0, 2, 1 }, { 2, 1, 0 },
};

/* Draws the triangles (each once, in the given vertex order) and compares
 * the hit counts with map (h rows of equal length). */
static void check_tris_at(const char *file, int line, const char *what,
                          const struct tri *tris, int ntris, const char *const *map, int h)
{
   const int w = (int)strlen(map[0]);
   int count[MAX_W * MAX_H];
   memset(count, 0, sizeof count);
   uint8_t dummy[4];
   const struct r_state proto = make_state(dummy, w, h);
   for (int i = 0; i < ntris; i++)
      draw_and_count(file, line, what, &proto, &tris[i], order_id, w, h, count);
   compare_map(file, line, what, count, map, w, h);
}
#define CHECK_TRIS(what, tris, map) \
   check_tris_at(__FILE__, __LINE__, what, tris, (int)(sizeof(tris) / sizeof((tris)[0])), \
                 map, (int)(sizeof(map) / sizeof((map)[0])))

/* One triangle in all six vertex orders: CW and CCW, every rotation,
 * must give the same map. */
static void check_tri_all_orders_at(const char *file, int line, const char *what,
                                    const struct tri *t, const char *const *map, int h)
{
   const int w = (int)strlen(map[0]);
   uint8_t dummy[4];
   const struct r_state proto = make_state(dummy, w, h);
   for (int k = 0; k < 6; k++) {
      int count[MAX_W * MAX_H];
      char name[160];
      memset(count, 0, sizeof count);
      snprintf(name, sizeof name, "%s, vertex order (%d,%d,%d)", what,
               orders[k][0], orders[k][1], orders[k][2]);
      draw_and_count(file, line, name, &proto, t, orders[k], w, h, count);
      compare_map(file, line, name, count, map, w, h);
   }
}
#define CHECK_TRI_ALL_ORDERS(what, t, map) \
   check_tri_all_orders_at(__FILE__, __LINE__, what, t, map, \
                           (int)(sizeof(map) / sizeof((map)[0])))

/* ---------------------------------------------------------------------- */

/*
 * The square [2.5, 6.5] x [2.5, 6.5] (every corner on a pixel centre),
 * snapped corners (512, 512) .. (1536, 1536), split along the main
 * diagonal into
 *   A = (2.5,2.5) (2.5,6.5) (6.5,6.5)   area +1024^2
 *     left   (512,512)->(512,1536):   dcdx = -1024: +1, covered iff px >= 2
 *     bottom (512,1536)->(1536,1536): dcdx = 0, dcdy = -1024: +1,
 *            covered iff py <= 6
 *     diag   (1536,1536)->(512,512):  dcdx = dcdy = 1024, c = 0:
 *            covered iff py > px
 *   B = (2.5,2.5) (6.5,6.5) (6.5,2.5)   area +1024^2
 *     diag   (512,512)->(1536,1536):  dcdx = -1024: +1, covered iff px >= py
 *     right  (1536,1536)->(1536,512): dcdx = 1024, covered iff px <= 5
 *     top    (1536,512)->(512,512):   dcdx = 0, dcdy = 1024, covered iff py >= 3
 * The diagonal's centres (k,k) go to B only; the union is columns 2..5
 * (left edge in, right edge out) and rows 3..6 (top edge out, bottom in).
 */
static const struct tri tri_a = { { 2.5f, 2.5f, 6.5f }, { 2.5f, 6.5f, 6.5f } };
static const struct tri tri_b = { { 2.5f, 6.5f, 6.5f }, { 2.5f, 6.5f, 2.5f } };

static const char *const map_a[] = {
   "..........",
   "..........",
   "..........",
   "..#.......",
   "..##......",
   "..###.....",
   "..####....",
   "..........",
};
static const char *const map_b[] = {
   "..........",
   "..........",
   "..........",
   "...###....",
   "....##....",
   ".....#....",
   "..........",
   "..........",
};
static const char *const map_square[] = {
   "..........",
   "..........",
   "..........",
   "..####....",
   "..####....",
   "..####....",
   "..####....",
   "..........",
};

/*
 * The same square split along the other diagonal, which passes through the
 * centres with px + py = 8:
 *   C = (2.5,2.5) (2.5,6.5) (6.5,2.5)
 *     left px >= 2; (512,1536)->(1536,512): dcdx = 1024, c = 2^21,
 *     covered iff px + py < 8; top py >= 3
 *   D = (6.5,2.5) (2.5,6.5) (6.5,6.5)
 *     (1536,512)->(512,1536): dcdx = -1024: +1, covered iff px + py >= 8;
 *     bottom py <= 6; right px <= 5
 */
static const struct tri tri_c = { { 2.5f, 2.5f, 6.5f }, { 2.5f, 6.5f, 2.5f } };
static const struct tri tri_d = { { 6.5f, 2.5f, 6.5f }, { 2.5f, 6.5f, 6.5f } };

static const char *const map_c[] = {
   "..........",
   "..........",
   "..........",
   "..###.....",
   "..##......",
   "..#.......",
   "..........",
   "..........",
};
static const char *const map_d[] = {
   "..........",
   "..........",
   "..........",
   ".....#....",
   "....##....",
   "...###....",
   "..####....",
   "..........",
};

static void test_square_shared_diagonal(void)
{
   const struct tri ab[] = { tri_a, tri_b };
   const struct tri cd[] = { tri_c, tri_d };
   CHECK_TRI_ALL_ORDERS("square, lower-left half A", &tri_a, map_a);
   CHECK_TRI_ALL_ORDERS("square, upper-right half B", &tri_b, map_b);
   CHECK_TRIS("square A+B: no gap, no double hit", ab, map_square);
   CHECK_TRI_ALL_ORDERS("square, upper-left half C", &tri_c, map_c);
   CHECK_TRI_ALL_ORDERS("square, lower-right half D", &tri_d, map_d);
   CHECK_TRIS("square C+D: no gap, no double hit", cd, map_square);
}

/*
 * Slanted edges through pixel centres.
 * Apex up: (4.5,0.5) (0.5,4.5) (8.5,4.5), snapped (1024,0) (0,1024)
 * (2048,1024), area +2*1024^2.
 *   left  (1024,0)->(0,1024):     dcdx = -1024: +1, covered iff px+py >= 4
 *   base  (0,1024)->(2048,1024):  dcdx = 0, dcdy = -2048: +1, py <= 4
 *   right (2048,1024)->(1024,0):  dcdx = 1024, c = 2^20, covered iff
 *                                 px < py + 4
 * The apex centre (4,0) lies on both slanted edges: the right one
 * excludes it.
 */
static const struct tri tri_apex_up = { { 4.5f, 0.5f, 8.5f }, { 0.5f, 4.5f, 4.5f } };
static const char *const map_apex_up[] = {
   "..........",
   "...##.....",
   "..####....",
   ".######...",
   "########..",
   "..........",
};

/*
 * Apex down: (0.5,0.5) (4.5,4.5) (8.5,0.5), snapped (0,0) (1024,1024)
 * (2048,0), area +2*1024^2.
 *   left  (0,0)->(1024,1024):    dcdx = -1024: +1, covered iff px >= py
 *   right (1024,1024)->(2048,0): dcdx = 1024, covered iff px + py < 8
 *   top   (2048,0)->(0,0):       dcdx = 0, dcdy = 2048, covered iff py > 0
 * The apex centre (4,4) lies on both slanted edges: the right one
 * excludes it.
 */
static const struct tri tri_apex_down = { { 0.5f, 4.5f, 8.5f }, { 0.5f, 4.5f, 0.5f } };
static const char *const map_apex_down[] = {
   "..........",
   ".######...",
   "..####....",
   "...##.....",
   "..........",
   "..........",
};

static void test_slanted_edges(void)
{
   CHECK_TRI_ALL_ORDERS("apex-up triangle", &tri_apex_up, map_apex_up);
   CHECK_TRI_ALL_ORDERS("apex-down triangle", &tri_apex_down, map_apex_down);
}

/*
 * Snap ties.  (x - 0.5) * 256 = n + 0.5 is exact for these inputs, and
 * cvtps2dq rounds it to the even neighbour.
 *
 * (a) Left edge at x = 2.5 + TIE (512.5 -> 512, on the centres of column
 *     2, which the left edge includes) and right edge at x = 6.5 + TIE
 *     (1536.5 -> 1536, on the centres of column 6, excluded): columns
 *     2..5, as for the exact square.  Rounding half up would give columns
 *     3..6.
 */
#define XL (2.5f + TIE)
#define XR (6.5f + TIE)
static const struct tri tie_x[] = {
   { { XL, XL, XR }, { 2.5f, 6.5f, 6.5f } },
   { { XL, XR, XR }, { 2.5f, 6.5f, 2.5f } },
};

/*
 * (b) Top edge at y = 3.5 - TIE (767.5 -> 768, on the centres of row 3,
 *     which the top edge excludes) and bottom edge at y = 6.5 - TIE
 *     (1535.5 -> 1536, on row 6, included): rows 4..6.  Truncation would
 *     give rows 3..5.
 * (c) Top at 3.5 + TIE (768.5 -> 768) and bottom at 6.5 + TIE
 *     (1536.5 -> 1536): the same rows 4..6.
 */
#define YT1 (3.5f - TIE)
#define YB1 (6.5f - TIE)
#define YT2 (3.5f + TIE)
#define YB2 (6.5f + TIE)
static const struct tri tie_y_odd[] = {
   { { 2.5f, 2.5f, 6.5f }, { YT1, YB1, YB1 } },
   { { 2.5f, 6.5f, 6.5f }, { YT1, YB1, YT1 } },
};
static const struct tri tie_y_even[] = {
   { { 2.5f, 2.5f, 6.5f }, { YT2, YB2, YB2 } },
   { { 2.5f, 6.5f, 6.5f }, { YT2, YB2, YT2 } },
};
static const char *const map_rows_4_6[] = {
   "..........",
   "..........",
   "..........",
   "..........",
   "..####....",
   "..####....",
   "..####....",
   "..........",
};

/*
 * (d) A slanted edge.  (0.5,0.5) (0.5,4.5) (4.5 + TIE, 4.5): x = 4.5 + TIE
 *     snaps 1024.5 -> 1024, so this is the exact triangle (0,0) (0,1024)
 *     (1024,1024): left edge px >= 0, bottom py <= 4, and the diagonal
 *     (1024,1024)->(0,0) has dcdx = 1024 > 0, covered iff py > px: the
 *     centres (k,k) on it stay empty.  Rounded up to 1025, the diagonal
 *     would give E(k,k) = 256k > 0 and cover (1,1)..(4,4) too.
 * (e) (0.5,0.5) (0.5,4.5) (4.5, 4.5 - TIE): y snaps 1023.5 -> 1024, the
 *     same triangle.  Truncated to 1023 the base would slope (dcdx = 1 > 0,
 *     row 4 lost) and the diagonal would cover (1,1)..(3,3).
 */
static const struct tri tie_slant_x = { { 0.5f, 0.5f, 4.5f + TIE }, { 0.5f, 4.5f, 4.5f } };
static const struct tri tie_slant_y = { { 0.5f, 0.5f, 4.5f }, { 0.5f, 4.5f, 4.5f - TIE } };
static const char *const map_slant[] = {
   "..........",
   "#.........",
   "##........",
   "###.......",
   "####......",
   "..........",
};

static void test_snap_ties(void)
{
   CHECK_TRIS("x ties 512.5 and 1536.5 round to even", tie_x, map_square);
   CHECK_TRIS("y ties 767.5 and 1535.5 round to even", tie_y_odd, map_rows_4_6);
   CHECK_TRIS("y ties 768.5 and 1536.5 round to even", tie_y_even, map_rows_4_6);
   CHECK_TRI_ALL_ORDERS("slanted edge, x tie 1024.5", &tie_slant_x, map_slant);
   CHECK_TRI_ALL_ORDERS("slanted edge, y tie 1023.5", &tie_slant_y, map_slant);
}

/* Zero snapped area draws nothing, in every vertex order. */
static const char *const map_empty[] = {
   "..........",
   "..........",
   "..........",
   "..........",
   "..........",
   "..........",
   "..........",
   "..........",
   "..........",
   "..........",
};

static void test_degenerate(void)
{
   static const struct tri degenerate[] = {
      /* collinear, along pixel centres */
      { { 0.5f, 2.5f, 6.5f }, { 0.5f, 2.5f, 6.5f } },
      /* horizontal, along the centres of row 3 */
      { { 0.5f, 9.5f, 4.5f }, { 3.5f, 3.5f, 3.5f } },
      /* vertical, along column 5 */
      { { 5.5f, 5.5f, 5.5f }, { 9.5f, 0.5f, 4.5f } },
      /* two equal vertices */
      { { 3.5f, 3.5f, 6.5f }, { 3.5f, 3.5f, 1.5f } },
      /* one point */
      { { 3.5f, 3.5f, 3.5f }, { 3.5f, 3.5f, 3.5f } },
      /* not collinear in float, but the third vertex's y, 1024.25,
       * snaps onto the line (0,0)-(2048,2048) */
      { { 0.5f, 8.5f, 4.5f }, { 0.5f, 8.5f, 4.5f + 1.0f / 1024.0f } },
      /* a triangle smaller than one snap step: all three snap to (768,768) */
      { { 3.5f, 3.501f, 3.5f }, { 3.5f, 3.5f, 3.501f } },
   };
   for (size_t i = 0; i < sizeof degenerate / sizeof degenerate[0]; i++) {
      char what[64];
      snprintf(what, sizeof what, "degenerate triangle %zu", i);
      CHECK_TRI_ALL_ORDERS(what, &degenerate[i], map_empty);
   }
}

/* ---------------------------------------------------------------------- */

/* Deterministic sub-pixel offsets: exact positions, snap ties of both
 * parities, 1/256 steps, and positions that are not multiples of 1/256. */
static const float jitter[] = {
   0.0f, TIE, -TIE, 3.0f * TIE, -3.0f * TIE, 1.0f / 256.0f, -1.0f / 256.0f,
   0.25f, -0.375f, 0.5f, -0.5f, 1.0f, -1.0f + TIE, 0.5f + TIE, 0.1f,
   -0.3333f, 0.7f, -0.77f,
};
#define NJITTER ((int)(sizeof jitter / sizeof jitter[0]))

/*
 * A 6 x 6 grid of cells over [2.5, 26.5]^2 in a 32 x 32 buffer, each cell
 * split in two along alternating diagonals, every other triangle wound
 * clockwise.  Inner vertices move by the offsets above; border vertices
 * move only along their border, corners not at all.  The union is the
 * square, covered exactly once: columns 2..25, rows 3..26.
 */
static void test_mesh_exactly_once(int seed)
{
   enum { N = 6, W = 32, H = 32 };
   float vx[N + 1][N + 1], vy[N + 1][N + 1];
   for (int j = 0; j <= N; j++) {
      for (int i = 0; i <= N; i++) {
         const int k = (i * 7 + j * 3 + seed * 5) % NJITTER;
         const int l = (i * 5 + j * 11 + seed * 3 + 4) % NJITTER;
         vx[j][i] = 2.5f + 4.0f * (float)i;
         vy[j][i] = 2.5f + 4.0f * (float)j;
         if (i > 0 && i < N)
            vx[j][i] += jitter[k];
         if (j > 0 && j < N)
            vy[j][i] += jitter[l];
      }
   }

   int count[W * H];
   memset(count, 0, sizeof count);
   uint8_t dummy[4];
   const struct r_state proto = make_state(dummy, W, H);
   char what[64];
   snprintf(what, sizeof what, "mesh %d", seed);
   int n = 0;
   for (int j = 0; j < N; j++) {
      for (int i = 0; i < N; i++) {
         /* corners p00 p10 p01 p11 (x index, y index) */
         const float x00 = vx[j][i], y00 = vy[j][i];
         const float x10 = vx[j][i + 1], y10 = vy[j][i + 1];
         const float x01 = vx[j + 1][i], y01 = vy[j + 1][i];
         const float x11 = vx[j + 1][i + 1], y11 = vy[j + 1][i + 1];
         struct tri t[2];
         if ((i + j + seed) % 2 == 0) {
            t[0] = (struct tri){ { x00, x01, x11 }, { y00, y01, y11 } };
            t[1] = (struct tri){ { x00, x11, x10 }, { y00, y11, y10 } };
         } else {
            t[0] = (struct tri){ { x00, x01, x10 }, { y00, y01, y10 } };
            t[1] = (struct tri){ { x10, x01, x11 }, { y10, y01, y11 } };
         }
         for (int k = 0; k < 2; k++, n++)
            draw_and_count(__FILE__, __LINE__, what, &proto, &t[k],
                           orders[n % 6], W, H, count);
      }
   }

   int bad = 0;
   for (int y = 0; y < H; y++) {
      for (int x = 0; x < W; x++) {
         const int want = (x >= 2 && x <= 25 && y >= 3 && y <= 26) ? 1 : 0;
         if (count[y * W + x] != want && bad++ < 10)
            FAIL("%s: pixel (%d,%d) hit %d times, expected %d", what, x, y,
                 count[y * W + x], want);
      }
   }
   CHECK(bad == 0, "%s: %d pixel(s) not covered exactly as expected", what, bad);
}

/*
 * A fan around an inner point whose rim is the boundary of the rectangle
 * [4.5, 20.5] x [3.5, 19.5] (corners and points along the sides, some on
 * snap ties): the union is the rectangle, columns 4..19 and rows 4..19,
 * every pixel covered exactly once, wherever the centre lies.
 */
static void test_fan_exactly_once(float cx, float cy)
{
   enum { W = 24, H = 22 };
   static const float rim[][2] = {
      { 4.5f, 3.5f }, { 7.5f, 3.5f }, { 9.0f + TIE, 3.5f }, { 13.3f, 3.5f },
      { 20.5f, 3.5f }, { 20.5f, 8.5f - TIE }, { 20.5f, 10.0f }, { 20.5f, 19.5f },
      { 16.5f + 3.0f * TIE, 19.5f }, { 11.5f, 19.5f }, { 5.25f, 19.5f },
      { 4.5f, 19.5f }, { 4.5f, 15.5f + TIE }, { 4.5f, 11.5f }, { 4.5f, 6.7f },
   };
   const int nrim = (int)(sizeof rim / sizeof rim[0]);
   int count[W * H];
   memset(count, 0, sizeof count);
   uint8_t dummy[4];
   const struct r_state proto = make_state(dummy, W, H);
   char what[96];
   snprintf(what, sizeof what, "fan around (%a, %a)", (double)cx, (double)cy);
   for (int i = 0; i < nrim; i++) {
      const int j = (i + 1) % nrim;
      const struct tri t = { { cx, rim[i][0], rim[j][0] }, { cy, rim[i][1], rim[j][1] } };
      draw_and_count(__FILE__, __LINE__, what, &proto, &t, orders[i % 6], W, H, count);
   }
   int bad = 0;
   for (int y = 0; y < H; y++) {
      for (int x = 0; x < W; x++) {
         const int want = (x >= 4 && x <= 19 && y >= 4 && y <= 19) ? 1 : 0;
         if (count[y * W + x] != want && bad++ < 10)
            FAIL("%s: pixel (%d,%d) hit %d times, expected %d", what, x, y,
                 count[y * W + x], want);
      }
   }
   CHECK(bad == 0, "%s: %d pixel(s) not covered exactly as expected", what, bad);
}

/* ---------------------------------------------------------------------- */

/* Colours: flat shading takes the provoking vertex, the last one given,
 * whichever the winding; a smooth constant colour is exact. */
static void test_colours(void)
{
   enum { W = 10, H = 6 };
   static const float red[4] = { 1, 0, 0, 1 }, green[4] = { 0, 1, 0, 1 },
                      blue[4] = { 0, 0, 1, 1 }, half[4] = { 0.5f, 0.25f, 1.0f, 0.0f };
   uint8_t buf[W * H * 4];
   struct r_state rs = make_state(buf, W, H);
   /* the exact triangle of map_slant: 10 pixels */
   const struct r_vertex v0 = make_vertex(0.5f, 0.5f, red);
   const struct r_vertex v1 = make_vertex(0.5f, 4.5f, green);
   const struct r_vertex v2 = make_vertex(4.5f, 4.5f, blue);
   const struct {
      const struct r_vertex *a, *b, *c;
      uint8_t want[4];
      const char *what;
   } cases[] = {
      { &v0, &v1, &v2, { 0, 0, 255, 255 }, "flat (v0,v1,v2)" },
      { &v1, &v0, &v2, { 0, 0, 255, 255 }, "flat (v1,v0,v2), other winding" },
      { &v2, &v0, &v1, { 0, 255, 0, 255 }, "flat (v2,v0,v1)" },
      { &v1, &v2, &v0, { 255, 0, 0, 255 }, "flat (v1,v2,v0)" },
   };
   for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
      memset(buf, 0, sizeof buf);
      r_triangle(&rs, cases[k].a, cases[k].b, cases[k].c);
      int n = 0;
      for (int y = 0; y < H; y++) {
         for (int x = 0; x < W; x++) {
            const uint8_t *p = buf + 4 * (y * W + x);
            const bool in = map_slant[y][x] == '#';
            const uint8_t zero[4] = { 0, 0, 0, 0 };
            const uint8_t *want = in ? cases[k].want : zero;
            if (memcmp(p, want, 4) != 0 && n++ < 4)
               FAIL("%s: pixel (%d,%d) = %u,%u,%u,%u, expected %u,%u,%u,%u", cases[k].what,
                    x, y, p[0], p[1], p[2], p[3], want[0], want[1], want[2], want[3]);
         }
      }
   }

   /* smooth, every vertex (0.5, 0.25, 1, 0) with w = 1: the planes are
    * constant, RNE(127.5) = 128, RNE(63.75) = 64 */
   rs.flat_mask = 0;
   const struct r_vertex s0 = make_vertex(0.5f, 0.5f, half);
   const struct r_vertex s1 = make_vertex(0.5f, 4.5f, half);
   const struct r_vertex s2 = make_vertex(4.5f, 4.5f, half);
   memset(buf, 0, sizeof buf);
   r_triangle(&rs, &s0, &s1, &s2);
   int n = 0;
   for (int y = 0; y < H; y++) {
      for (int x = 0; x < W; x++) {
         const uint8_t *p = buf + 4 * (y * W + x);
         const bool in = map_slant[y][x] == '#';
         const bool ok = in ? (p[0] == 128 && p[1] == 64 && p[2] == 255 && p[3] == 0)
                            : (p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 0);
         if (!ok && n++ < 4)
            FAIL("smooth constant colour: pixel (%d,%d) = %u,%u,%u,%u, expected %s", x, y,
                 p[0], p[1], p[2], p[3], in ? "128,64,255,0" : "untouched");
      }
   }
}

/* The draw region [x0,x1) x [y0,y1) bounds every write. */
static void test_draw_region(void)
{
   enum { W = 10, H = 8 };
   uint8_t buf[W * H * 4];
   struct r_state rs = make_state(buf, W, H);
   rs.x0 = rs.px0 = 3;
   rs.x1 = rs.px1 = 5;
   rs.y0 = rs.py0 = 4;
   rs.y1 = rs.py1 = 6;
   memset(buf, 0, sizeof buf);
   const struct tri *sq[2] = { &tri_a, &tri_b };
   for (int k = 0; k < 2; k++) {
      struct r_vertex v[3];
      for (int i = 0; i < 3; i++)
         v[i] = make_vertex(sq[k]->x[i], sq[k]->y[i], white);
      r_triangle(&rs, &v[0], &v[1], &v[2]);
   }
   /* the square's columns 2..5 and rows 3..6, cut to columns 3..4, rows 4..5 */
   static const char *const map_cut[] = {
      "..........",
      "..........",
      "..........",
      "..........",
      "...##.....",
      "...##.....",
      "..........",
      "..........",
   };
   int count[W * H];
   for (int i = 0; i < W * H; i++)
      count[i] = buf[4 * i + 3] == 255 ? 1 : buf[4 * i + 3] == 0 ? 0 : 9;
   compare_map(__FILE__, __LINE__, "square in the region [3,5) x [4,6)", count, map_cut, W, H);
}

/* Depth: a constant-z triangle writes RNE(z * 16777215) (Z24) or
 * RNE(z * 65535) (Z16), compares as integers, and keeps stencil bits. */
static void test_depth(void)
{
   enum { W = 10, H = 8 };
   uint8_t buf[W * H * 4];
   uint32_t zs[W * H];
   struct r_state rs = make_state(buf, W, H);
   t_fb.zs = zs;
   t_fb.zs_format = R_ZS_Z24S8;
   t_dsa.depth_test = true;
   t_dsa.depth_func = R_LESS;
   t_dsa.depth_write = true;
   memset(buf, 0, sizeof buf);
   for (int i = 0; i < W * H; i++)
      zs[i] = 0xab000000u | 0xffffffu;

   static const float grey[4] = { 0.5f, 0.5f, 0.5f, 0.5f };
   static const float red[4] = { 1, 0, 0, 1 };
   struct r_vertex v[3];
   /* 0.25 * 16777215 = 4194303.75 -> 4194304 */
   for (int i = 0; i < 3; i++) {
      v[i] = make_vertex(tri_a.x[i], tri_a.y[i], grey);
      v[i].pos[2] = 0.25f;
   }
   r_triangle(&rs, &v[0], &v[1], &v[2]);
   /* a farther triangle (0.5 -> 8388607.5 -> 8388608) fails GL_LESS */
   for (int i = 0; i < 3; i++) {
      v[i] = make_vertex(tri_a.x[i], tri_a.y[i], red);
      v[i].pos[2] = 0.5f;
   }
   r_triangle(&rs, &v[0], &v[1], &v[2]);

   int bad = 0;
   for (int y = 0; y < H; y++) {
      for (int x = 0; x < W; x++) {
         const int i = y * W + x;
         const bool in = map_a[y][x] == '#';
         const uint32_t want_z = in ? 0xab000000u | 4194304u : 0xab000000u | 0xffffffu;
         const uint8_t want_c = in ? 128 : 0;
         if ((zs[i] != want_z || buf[4 * i] != want_c || buf[4 * i + 1] != want_c) &&
             bad++ < 4)
            FAIL("depth Z24S8: pixel (%d,%d) z 0x%08x colour %u,%u, expected 0x%08x %u,%u",
                 x, y, zs[i], buf[4 * i], buf[4 * i + 1], want_z, want_c, want_c);
      }
   }

   /* Z16, GL_LEQUAL, no depth write: 0.5 -> 32767.5 -> 32768 passes
    * against 32768 and fails against 32767 */
   uint16_t z16[W * H];
   t_fb.zs = z16;
   t_fb.zs_format = R_ZS_Z16;
   t_dsa.depth_func = R_LEQUAL;
   t_dsa.depth_write = false;
   memset(buf, 0, sizeof buf);
   for (int i = 0; i < W * H; i++)
      z16[i] = (i % 2) ? 32768 : 32767;
   r_triangle(&rs, &v[0], &v[1], &v[2]);
   bad = 0;
   for (int y = 0; y < H; y++) {
      for (int x = 0; x < W; x++) {
         const int i = y * W + x;
         const bool drawn = map_a[y][x] == '#' && (i % 2) == 1;
         const uint16_t want_z = (i % 2) ? 32768 : 32767;
         if ((z16[i] != want_z || buf[4 * i] != (drawn ? 255 : 0)) && bad++ < 4)
            FAIL("depth Z16: pixel (%d,%d) z %u red %u, expected %u %u", x, y,
                 (unsigned)z16[i], buf[4 * i], (unsigned)want_z, drawn ? 255u : 0u);
      }
   }
}

/* Z32 (llvmpipe's Z32_UNORM): trunc(z * 2^31) = t, stored (t << 1) - (t >> 31):
 * 0 -> 0, 1 -> 0xffffffff, 0.5 -> 0x80000000, and depths a quarter of a
 * 24-bit step apart are told apart (GL_LESS passes the nearer one);
 * r_clear_depth_stencil_rect writes the whole word. */
static void test_depth_z32(void)
{
   CHECK(r_depth_to_z32(0.0f) == 0u, "z32");
   CHECK(r_depth_to_z32(1.0f) == 0xffffffffu, "z32");
   CHECK(r_depth_to_z32(2.0f) == 0xffffffffu, "z32");
   CHECK(r_depth_to_z32(-1.0f) == 0u, "z32");
   CHECK(r_depth_to_z32(0.5f) == 0x80000000u, "z32");
   CHECK(r_depth_to_z32(0.25f) == 0x40000000u, "z32");
   /* 2^-31 and its neighbours: trunc(1.5) = 1 -> 2, trunc(0.75) = 0 */
   CHECK(r_depth_to_z32(0x1.8p-31f) == 2u, "z32");
   CHECK(r_depth_to_z32(0x1.8p-32f) == 0u, "z32");
   /* just below 1: trunc((1 - 2^-24) * 2^31) = 2^31 - 2^7 */
   CHECK(r_depth_to_z32(0x1.fffffep-1f) == (uint32_t)((0x80000000u - 0x80u) << 1), "z32");

   enum { W = 10, H = 8 };
   uint8_t buf[W * H * 4];
   uint32_t z32[W * H];
   struct r_state rs = make_state(buf, W, H);
   t_fb.zs = z32;
   t_fb.zs_format = R_ZS_Z32;
   t_fb.width = W;
   t_fb.height = H;
   t_dsa.depth_test = true;
   t_dsa.depth_func = R_LESS;
   t_dsa.depth_write = true;
   memset(buf, 0, sizeof buf);
   r_clear_depth_stencil_rect(&t_fb, 0, 0, W, H, true, 0xdeadbeefu, true, 0x55);
   for (int i = 0; i < W * H; i++)
      CHECK(z32[i] == 0xdeadbeefu, "z32");
   static const float grey[4] = { 0.5f, 0.5f, 0.5f, 0.5f };
   static const float red[4] = { 1, 0, 0, 1 };
   struct r_vertex v[3];
   /* one float step apart (2^-27, an eighth of a 24-bit step): one 24-bit
    * value, two 32-bit ones */
   const float za = 0.09375f, zb = 0.09375f - 0x1p-27f;
   for (int i = 0; i < 3; i++) {
      v[i] = make_vertex(tri_a.x[i], tri_a.y[i], grey);
      v[i].pos[2] = za;
   }
   r_triangle(&rs, &v[0], &v[1], &v[2]);
   for (int i = 0; i < 3; i++) {
      v[i] = make_vertex(tri_a.x[i], tri_a.y[i], red);
      v[i].pos[2] = zb;
   }
   r_triangle(&rs, &v[0], &v[1], &v[2]);
   const uint32_t want_in = r_depth_to_z32(zb);
   CHECK(want_in == 0x18000000u - 32u, "z32");
   CHECK(r_depth_to_z24(zb) == r_depth_to_z24(za), "z32");   /* one 24-bit value */
   int bad = 0;
   for (int y = 0; y < H; y++) {
      for (int x = 0; x < W; x++) {
         const int i = y * W + x;
         const bool in = map_a[y][x] == '#';
         const uint32_t want_z = in ? want_in : 0xdeadbeefu;
         if ((z32[i] != want_z || buf[4 * i] != (in ? 255 : 0)) && bad++ < 4)
            FAIL("depth Z32: pixel (%d,%d) z 0x%08x red %u, expected 0x%08x %u", x, y, z32[i],
                 buf[4 * i], want_z, in ? 255u : 0u);
      }
   }
}

/* The scene's triangles, lines and legacy points are set up once, when
 * binned (r_scene.c, r_triangle_box_setup, r_line_box_setup,
 * r_point_box_setup), each into the tiles it reaches, and each tile draws
 * that setup (r_triangle_binned, r_line_binned, r_point_binned): the
 * bytes must be those of r_triangle, r_line or r_point drawing the same
 * primitives directly.  Random triangles, lines (of widths 1, 2.5, 3 and
 * 4.5) or points (of sizes 1, 2.5, 3 and 8.5) over several 64x64 tiles,
 * partly off the buffer, smooth or flat, two-sided or not, with a depth
 * test and a scissored draw region, with the reference kernels and with
 * the block kernels where the CPU has them. */
static uint32_t scene_rng = 12345u;
static float scene_rand(float lo, float hi)
{
   scene_rng ^= scene_rng << 13;
   scene_rng ^= scene_rng >> 17;
   scene_rng ^= scene_rng << 5;
   return lo + (hi - lo) * (float)(scene_rng >> 8) / 16777216.0f;
}

static void test_scene_setup_once(bool flat, bool twoside, bool kernels, int prim)
{
   const bool lines = prim == 2, points = prim == 1;
   enum { W = 200, H = 150, N = 400 };
   static uint8_t ca[W * H * 4], cb[W * H * 4];
   static uint32_t za[W * H], zb[W * H];
   static struct r_vertex v[N][3];
   struct r_cso_cache cache;
   memset(&cache, 0, sizeof cache);
   struct r_state proto = make_state(ca, W, H);
   t_fb.zs = za;
   t_fb.zs_format = R_ZS_Z24S8;
   t_dsa.depth_test = true;
   t_dsa.depth_func = R_LESS;
   t_dsa.depth_write = true;
   t_rast.twoside = twoside;
   t_rast.cull_front = t_rast.cull_back = false;
   t_rast.line_width = lines ? (flat ? 3.0f : 1.0f) + (twoside ? 1.5f : 0.0f) : 1.0f;
   t_rast.point_size = points ? (flat ? 3.0f : 1.0f) + (twoside ? 5.5f : 0.0f) : 1.0f;
   t_blend.color_mask = 0xfu;
   proto.flat_mask = flat ? 1u << R_ATTR_COLOR0 | 1u << R_ATTR_BCOLOR0 : 0u;
   proto.x0 = 3;
   proto.y0 = 5;
   proto.x1 = W - 7;
   proto.y1 = H - 2;
   proto.px0 = proto.x0;
   proto.py0 = proto.y0;
   proto.px1 = proto.x1;
   proto.py1 = proto.y1;
   /* the scene holds its states' objects: they come from a cache */
   struct r_state rs = proto;
   rs.rast = r_cso_lookup(&cache, &t_rast, sizeof t_rast);
   rs.dsa = r_cso_lookup(&cache, &t_dsa, sizeof t_dsa);
   rs.blend = r_cso_lookup(&cache, &t_blend, sizeof t_blend);
   rs.fs = r_cso_lookup(&cache, &t_fs, sizeof t_fs);
   t_fb.zs = za;
   t_fb.color = ca;
   const struct r_fb_state *fba = r_cso_lookup(&cache, &t_fb, sizeof t_fb);
   t_fb.zs = zb;
   t_fb.color = cb;
   const struct r_fb_state *fbb = r_cso_lookup(&cache, &t_fb, sizeof t_fb);
   rs.reference_kernels = !kernels;
   rs.kernel_isa = kernels ? (uint8_t)r_kernel_isa(NULL) : R_ISA_NONE;
   for (int i = 0; i < N; i++) {
      /* mostly small triangles, some across many tiles */
      const float cx = scene_rand(-20.0f, W + 20.0f), cy = scene_rand(-20.0f, H + 20.0f);
      const float r = i % 8 == 0 ? 90.0f : 12.0f;
      for (int k = 0; k < 3; k++) {
         struct r_vertex *p = &v[i][k];
         memset(p, 0, sizeof *p);
         p->pos[0] = cx + scene_rand(-r, r);
         p->pos[1] = cy + scene_rand(-r, r);
         p->pos[2] = scene_rand(0.0f, 1.0f);
         p->pos[3] = scene_rand(0.25f, 2.0f);
         for (int c = 0; c < 4; c++) {
            p->attr[R_ATTR_COLOR0][c] = scene_rand(0.0f, 1.0f);
            p->attr[R_ATTR_BCOLOR0][c] = scene_rand(0.0f, 1.0f);
         }
      }
   }
   memset(ca, 0, sizeof ca);
   memset(cb, 0, sizeof cb);
   for (int i = 0; i < W * H; i++)
      za[i] = zb[i] = 0xffffffu;

   /* A: directly */
   rs.fb = fba;
   r_choose_kernels(&rs);
   for (int i = 0; i < N; i++) {
      if (lines)
         r_line(&rs, &v[i][0], &v[i][1]);
      else if (points)
         r_point(&rs, &v[i][0]);
      else
         r_triangle(&rs, &v[i][0], &v[i][1], &v[i][2]);
   }
   /* B: binned, then tile by tile */
   rs.fb = fbb;
   r_choose_kernels(&rs);
   struct r_scene scene;
   memset(&scene, 0, sizeof scene);
   for (int i = 0; i < N; i++)
      CHECK(lines    ? r_scene_line(&scene, &rs, &v[i][0], &v[i][1])
            : points ? r_scene_point(&scene, &rs, &v[i][0])
                     : r_scene_triangle(&scene, &rs, &v[i][0], &v[i][1], &v[i][2]),
            "binned %d", i);
   unsigned set_up = 0;
   for (uint32_t i = 0; i < scene.ncmds; i++)
      set_up += (lines    ? (const void *)scene.cmds[i].line
                 : points ? (const void *)scene.cmds[i].point
                          : (const void *)scene.cmds[i].tri) != NULL;
   /* (lines: those reaching one or two tiles keep their vertices) */
   CHECK(set_up > (lines ? N / 16 : N / 4), "%u of %u binned primitives set up when binned",
         set_up, scene.ncmds);
   for (unsigned t = 0; t < r_scene_tiles(&scene); t++)
      r_scene_run_tile(&scene, t, NULL, 0);
   r_scene_fini(&scene);

   int bad = 0, drawn = 0, coloured = 0;
   for (int i = 0; i < W * H; i++) {
      drawn += za[i] != 0xffffffu;
      coloured += ca[4 * i + 3] != 0;
      if ((memcmp(&ca[4 * i], &cb[4 * i], 4) != 0 || za[i] != zb[i]) && bad++ < 4)
         FAIL("scene setup (vertices %d, flat %d, twoside %d, kernels %d): pixel (%d,%d) colour %08x z %06x, "
              "direct %08x z %06x", prim, flat, twoside, kernels, i % W, i / W,
              (unsigned)(cb[4 * i] | cb[4 * i + 1] << 8 | cb[4 * i + 2] << 16 | (uint32_t)cb[4 * i + 3] << 24),
              (unsigned)zb[i],
              (unsigned)(ca[4 * i] | ca[4 * i + 1] << 8 | ca[4 * i + 2] << 16 | (uint32_t)ca[4 * i + 3] << 24),
              (unsigned)za[i]);
   }
   const int enough = points ? N / 2 : lines ? W * H / 10 : W * H / 4;
   CHECK(drawn > enough && coloured > enough, "the primitives drew %d pixels, %d coloured",
         drawn, coloured);
   r_cso_cache_fini(&cache);
}

/* The triangles' block coverage (r_cover_tri: a snapped box of at most
 * 512 pixels each way skips r_cover_planes' 64-bit bound test and reduces
 * the edges in 32 bits) equals r_cover_planes' on random exact triangles
 * of boxes up to 16,000 pixels (the limit of 512, past it, and where the
 * bound test fails) anywhere in the snapped range, over random cuts of
 * their box (a draw region, a tile). */
/* a random float in [lo, hi) from *s (test_cover_tri's own sequence) */
static float cover_rand(uint64_t *s, float lo, float hi)
{
   return lo + (hi - lo) * (float)(check_xorshift64(s) >> 40) / 16777216.0f;
}

static void test_cover_tri(void)
{
   uint64_t rng = 0x9e3779b97f4a7c15u;
   int checked = 0, small = 0, bad = 0, unbounded = 0;
   for (int i = 0; i < 200000; i++) {
      /* a corner anywhere in [0, 2^22) pixels (in 1/256), or near 0 (the
       * box partly at negative x or y), then the vertices within `span`
       * pixels of it */
      const float lo = i % 8 < 4 ? -600.0f : 0.0f, hi = i % 8 < 4 ? 100.0f : 4194304.0f;
      const int32_t ox = (int32_t)(cover_rand(&rng, lo, hi) * 256.0f);
      const int32_t oy = (int32_t)(cover_rand(&rng, lo, hi) * 256.0f);
      const int mode = i % 5;
      const float span = mode == 0   ? 16.0f
                         : mode == 1 ? 100.0f
                         : mode == 2 ? 512.5f
                         : mode == 3 ? 700.0f
                                     : 16000.0f;   /* the bound test fails */
      int32_t X[3], Y[3];
      for (int k = 0; k < 3; k++) {
         X[k] = ox + (int32_t)(cover_rand(&rng, 0.0f, span) * 256.0f);
         Y[k] = oy + (int32_t)(cover_rand(&rng, 0.0f, span) * 256.0f);
      }
      if (i % 16 == 3) {
         /* the box's extreme corners */
         X[0] = ox;
         X[1] = ox + (int32_t)(span * 256.0f);
         Y[1] = oy;
         Y[2] = oy + (int32_t)(span * 256.0f);
      }
      const int64_t area = (int64_t)(X[0] - X[1]) * (Y[2] - Y[0]) -
                           (int64_t)(X[2] - X[0]) * (Y[0] - Y[1]);
      if (area == 0)
         continue;
      if (area < 0) {
         int32_t t = X[0]; X[0] = X[1]; X[1] = t;
         t = Y[0]; Y[0] = Y[1]; Y[1] = t;
      }
      struct r_plane p[3];
      int32_t b[4];
      if (!r_tri_snapped_edges(X, Y, p, b))
         continue;
      /* the box clamped to x, y >= 0 (moved there when it is not), then
       * a random cut of it */
      int32_t bx0 = b[0], bx1 = b[1], by0 = b[2], by1 = b[3];
      if (bx1 < 0 || by1 < 0)
         continue;
      if (bx0 < 0) bx0 = 0;
      if (by0 < 0) by0 = 0;
      const int32_t x0 = bx0 + (int32_t)cover_rand(&rng, 0.0f, (float)(bx1 - bx0 + 1) * 0.5f);
      const int32_t x1 = bx1 - (int32_t)cover_rand(&rng, 0.0f, (float)(bx1 - x0 + 1) * 0.5f);
      const int32_t y0 = by0 + (int32_t)cover_rand(&rng, 0.0f, (float)(by1 - by0 + 1) * 0.5f);
      const int32_t y1 = by1 - (int32_t)cover_rand(&rng, 0.0f, (float)(by1 - y0 + 1) * 0.5f);
      struct r_tri_cover a, c;
      memset(&a, 0x55, sizeof a);
      memset(&c, 0x55, sizeof c);
      const bool ra = r_cover_planes(p, 3, x0, y0, x1, y1, &a);
      const bool rc = r_cover_tri(p, b, x0, y0, x1, y1, &c);
      small += b[1] - b[0] <= 512 && b[3] - b[2] <= 512;
      checked++;
      unbounded += !ra;
      if ((ra != rc || memcmp(&a, &c, sizeof a) != 0) && bad++ < 4)
         FAIL("cover of (%d,%d) (%d,%d) (%d,%d) over %d..%d x %d..%d: r_cover_planes %d "
            "c %d %d %d, r_cover_tri %d c %d %d %d",
            X[0], Y[0], X[1], Y[1], X[2], Y[2], x0, x1, y0, y1, ra, a.c[0], a.c[1], a.c[2], rc,
            c.c[0], c.c[1], c.c[2]);
   }
   CHECK(bad == 0, "cover_tri: %d covers differ", bad);
   CHECK(checked > 120000 && small > 50000 && checked - small > 20000 && unbounded > 5000,
         "cover_tri: %d triangles checked, %d small, %d failing the bound", checked, small,
         unbounded);
}

int main(void)
{
   test_cover_tri();
   test_square_shared_diagonal();
   test_slanted_edges();
   test_snap_ties();
   test_degenerate();
   for (int seed = 0; seed < 6; seed++)
      test_mesh_exactly_once(seed);
   test_fan_exactly_once(11.5f, 10.5f);                          /* a pixel centre */
   test_fan_exactly_once(11.5f + TIE, 10.5f - 3.0f * TIE);       /* snap ties */
   test_fan_exactly_once(13.123f, 9.87f);
   test_fan_exactly_once(4.5f + 1.0f / 256.0f, 11.5f);           /* next to the rim */
   test_colours();
   test_draw_region();
   test_depth();
   test_depth_z32();
   for (int m = 0; m < 24; m++)
      test_scene_setup_once(m & 1, (m >> 1) & 1, (m >> 2) & 1, 3 - (m >> 3));
   return check_report("unit-raster");
}
