/*
 * Whole-buffer clears, of the whole buffer or of a tile of it.  Values arrive already packed (the oracle packs the
 * clear colour with float_to_ubyte and the depth with util_pack64_z,
 * ORACLE-NOTES.md "Clears").
 */
#include "r_scene.h"

#include <string.h>
#include "r_rows.h"

/* n 32-bit values v at p (r_rows.h: whole lines written without being
 * read first) */
static void fill32(void *p, uint32_t v, size_t n)
{
   r_rows_fill32(p, v, n);
}

/* The rectangle as runs of n contiguous values: one run when it spans
 * whole rows, else one per row; run(i, p0, n) gets the index of the
 * run's first value. */
#define FOR_RUNS(fb, x0, y0, x1, y1, first, n, body)                          \
   do {                                                                       \
      const size_t w_ = (size_t)(fb)->width;                                  \
      if ((x0) == 0 && (x1) == (fb)->width) {                                 \
         const size_t first = (size_t)(y0) * w_;                              \
         const size_t n = (size_t)((y1) - (y0)) * w_;                         \
         body;                                                                \
      } else {                                                                \
         for (int y_ = (y0); y_ < (y1); y_++) {                               \
            const size_t first = (size_t)y_ * w_ + (size_t)(x0);              \
            const size_t n = (size_t)((x1) - (x0));                           \
            body;                                                             \
         }                                                                    \
      }                                                                       \
   } while (0)

void r_clear_color_rect(const struct r_fb_state *fb, int x0, int y0, int x1, int y1,
                        const uint8_t rgba[4])
{
   if (!fb->color || x0 >= x1 || y0 >= y1)
      return;
   uint32_t v;
   memcpy(&v, rgba, 4);
   uint32_t *c = (uint32_t *)(void *)fb->color;
   FOR_RUNS(fb, x0, y0, x1, y1, first, n, fill32(c + first, v, n));
}

void r_clear_wide_rect(const struct r_fb_state *fb, int x0, int y0, int x1, int y1,
                       const float rgba[4])
{
   if (!fb->wide || x0 >= x1 || y0 >= y1)
      return;
   if (fb->wide_format == R_WIDE_FLOAT) {
      float *c = fb->wide;
      FOR_RUNS(fb, x0, y0, x1, y1, first, n,
               for (size_t i = 0; i < n; i++) memcpy(c + 4 * (first + i), rgba, 16));
      return;
   }
   /* util_pack_color: util_iround(clamped * 65535), (int)(f + 0.5f)
    * (ORACLE-NOTES.md "OSMesa contexts and buffers") */
   uint16_t v[4];
   for (int k = 0; k < 4; k++)
      v[k] = (uint16_t)(int)(r_clamp01(rgba[k]) * 65535.0f + 0.5f);
   uint16_t *c = fb->wide;
   FOR_RUNS(fb, x0, y0, x1, y1, first, n,
            for (size_t i = 0; i < n; i++) memcpy(c + 4 * (first + i), v, 8));
}

/* n depth/stencil values from index `first` keep the bits `keep` and take
 * `set` (Z24X8 / Z24S8) */
static void zs32_runs(uint32_t *z, uint32_t keep, uint32_t set, size_t n)
{
   if (keep == 0) {
      fill32(z, set, n);   /* a plain fill: no read of the old values */
      return;
   }
   /* two values per 64-bit word (the loop the compiler vectorises) */
   const uint64_t keep2 = keep | (uint64_t)keep << 32, set2 = set | (uint64_t)set << 32;
   size_t i = 0;
   if (((uintptr_t)z & 7u) != 0 && n) {
      z[0] = (z[0] & keep) | set;
      i = 1;
   }
   for (; i + 2 <= n; i += 2) {
      uint64_t w;
      memcpy(&w, z + i, 8);
      w = (w & keep2) | set2;
      memcpy(z + i, &w, 8);
   }
   for (; i < n; i++)
      z[i] = (z[i] & keep) | set;
}

/* n Z16 values: pairs as 32-bit words when aligned */
static void z16_run(uint16_t *z, uint16_t v, size_t n)
{
   size_t i = 0;
   if (((uintptr_t)z & 3u) != 0 && n) {
      z[0] = v;
      i = 1;
   }
   fill32(z + i, (uint32_t)v * 0x10001u, (n - i) / 2);
   if ((n - i) & 1)
      z[n - 1] = v;
}

void r_clear_depth_stencil_rect(const struct r_fb_state *fb, int x0, int y0, int x1, int y1,
                                bool depth, uint32_t zvalue, bool stencil, uint8_t svalue)
{
   if (!fb->zs || x0 >= x1 || y0 >= y1)
      return;
   switch (fb->zs_format) {
   case R_ZS_Z16:
      if (depth) {
         uint16_t *z = fb->zs;
         FOR_RUNS(fb, x0, y0, x1, y1, first, n, z16_run(z + first, (uint16_t)zvalue, n));
      }
      break;
   case R_ZS_Z24X8:
   case R_ZS_Z24S8: {
      uint32_t *z = fb->zs;
      uint32_t keep = 0, set = 0;
      if (depth) set |= zvalue & 0xffffffu; else keep |= 0xffffffu;
      if (fb->zs_format == R_ZS_Z24S8) {
         if (stencil) set |= (uint32_t)svalue << 24; else keep |= 0xff000000u;
      }
      FOR_RUNS(fb, x0, y0, x1, y1, first, n, zs32_runs(z + first, keep, set, n));
      break;
   }
   case R_ZS_Z32:
      if (depth) {
         uint32_t *z = fb->zs;
         FOR_RUNS(fb, x0, y0, x1, y1, first, n, zs32_runs(z + first, 0u, zvalue, n));
      }
      break;
   case R_ZS_S8:
      if (stencil) {
         uint8_t *z = fb->zs;
         FOR_RUNS(fb, x0, y0, x1, y1, first, n, memset(z + first, svalue, n));
      }
      break;
   case R_ZS_NONE:
   default:
      break;
   }
}

_Static_assert(R_TILE_LOG2 == R_LAZY_TILE_LOG2, "the lazy clears' tiles are the scene's");

void r_lazy_resolve_tiles(struct r_lazy_clear *lz, const struct r_fb_state *fb, unsigned what,
                          int tx0, int ty0, int tx1, int ty1)
{
   for (int ty = ty0; ty <= ty1; ty++) {
      for (int tx = tx0; tx <= tx1; tx++) {
         uint8_t *t = &lz->tiles[(size_t)ty * (size_t)lz->tiles_x + (size_t)tx];
         /* (a buffer fb lacks keeps its bit: nothing was written) */
         const unsigned b = *t & what & (fb->color ? R_LAZY_COLOR : 0u);
         const unsigned bz = *t & what & (fb->zs ? R_LAZY_ZS : 0u);
         if (!(b | bz))
            continue;
         const int x0 = tx * R_TILE_SIZE, y0 = ty * R_TILE_SIZE;
         const int x1 = x0 + R_TILE_SIZE < fb->width ? x0 + R_TILE_SIZE : fb->width;
         const int y1 = y0 + R_TILE_SIZE < fb->height ? y0 + R_TILE_SIZE : fb->height;
         if (b)
            r_clear_color_rect(fb, x0, y0, x1, y1, lz->rgba);
         if (bz)
            r_clear_depth_stencil_rect(fb, x0, y0, x1, y1, lz->depth, lz->zvalue, lz->stencil,
                                       lz->svalue);
         *t = (uint8_t)(*t & ~(b | bz));
      }
   }
}

void r_clear_color(const struct r_state *rs, const uint8_t rgba[4])
{
   r_clear_color_rect(rs->fb, 0, 0, rs->fb->width, rs->fb->height, rgba);
}

void r_clear_depth_stencil(const struct r_state *rs, bool depth, uint32_t zvalue,
                           bool stencil, uint8_t svalue)
{
   r_clear_depth_stencil_rect(rs->fb, 0, 0, rs->fb->width, rs->fb->height, depth, zvalue,
                              stencil, svalue);
}

void r_clear_quad(const struct r_state *rs, float z, const float color[4])
{
   /* the quad's edges lie on pixel boundaries (the draw region), so it
    * covers exactly the region's pixels, each with the quad's constant
    * depth and colour */
   for (int y = rs->y0; y < rs->y1; y++)
      for (int x = rs->x0; x < rs->x1; x++)
         r_fragment_ops(rs, x, y, z, color);
}
