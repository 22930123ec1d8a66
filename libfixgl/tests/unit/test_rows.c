/*
 * test_rows.c - raster/r_rows.h (the string-instruction row fills and
 * copies of the lazy clears and of the copy into the user's buffer)
 * against plain loops, and raster/r_clear.c's rectangle clears, which use
 * them, against a per-pixel loop: random sizes (0 to a few rows of a
 * 1024-wide buffer, below and above R_ROWS_MIN_BYTES), offsets and
 * values, the bytes around the destination unchanged.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raster/r_rows.h"
#include "raster/r_scene.h"

#include "check.h"

static uint64_t rng = 0x9e3779b97f4a7c15ull;

static uint32_t rnd(void)
{
   return (uint32_t)(check_xorshift64(&rng) >> 16);
}

#define BUF 20000u
#define GUARD 256u

static void test_fill32(void)
{
   static uint32_t got[BUF], want[BUF];
   for (int iter = 0; iter < 3000; iter++) {
      const uint32_t before = rnd();
      for (unsigned i = 0; i < BUF; i++)
         got[i] = want[i] = before + i;
      const size_t n = iter % 4 == 0 ? rnd() % 40u : rnd() % (BUF - 2 * GUARD - 64);
      const size_t off = GUARD + rnd() % 64u;
      const uint32_t v = rnd() | (iter & 1 ? 0u : rnd() << 16);
      r_rows_fill32(got + off, v, n);
      for (size_t i = 0; i < n; i++)
         want[off + i] = v;
      if (memcmp(got, want, sizeof(got)) != 0) {
         FAIL("r_rows_fill32(+%zu, %08x, %zu) differs from the loop", off, v, n);
         return;
      }
   }
}

static void test_copy(void)
{
   static uint8_t src[BUF], got[BUF], want[BUF];
   for (int iter = 0; iter < 3000; iter++) {
      for (unsigned i = 0; i < BUF; i++) {
         src[i] = (uint8_t)rnd();
         got[i] = want[i] = (uint8_t)(i * 7u);
      }
      const size_t n = iter % 4 == 0 ? rnd() % 300u : rnd() % (BUF - 2 * GUARD - 64);
      const size_t doff = GUARD + rnd() % 64u, soff = rnd() % 64u;
      r_rows_copy(got + doff, src + soff, n);
      for (size_t i = 0; i < n; i++)
         want[doff + i] = src[soff + i];
      if (memcmp(got, want, sizeof(got)) != 0) {
         FAIL("r_rows_copy(+%zu, +%zu, %zu) differs from the loop", doff, soff, n);
         return;
      }
   }
}

/* r_clear_color_rect and r_clear_depth_stencil_rect on random buffers and
 * rectangles (whole rows, tiles, single pixels) against per-pixel
 * stores */
static void test_clear_rects(void)
{
   enum { W = 200, H = 70 };
   static uint32_t color[W * H], cwant[W * H], zs[W * H], zwant[W * H];
   static const enum r_zs_format formats[] = { R_ZS_Z24X8, R_ZS_Z24S8, R_ZS_Z32 };
   for (int iter = 0; iter < 3000; iter++) {
      const int w = 1 + (int)(rnd() % W), h = 1 + (int)(rnd() % H);
      for (int i = 0; i < W * H; i++) {
         color[i] = cwant[i] = rnd();
         zs[i] = zwant[i] = rnd();
      }
      const enum r_zs_format f = formats[rnd() % 3u];
      struct r_fb_state fb = { .color = (uint8_t *)color, .zs = zs, .zs_format = f,
                               .width = w, .height = h };
      int x0 = (int)(rnd() % (unsigned)(w + 1)), x1 = (int)(rnd() % (unsigned)(w + 1));
      int y0 = (int)(rnd() % (unsigned)(h + 1)), y1 = (int)(rnd() % (unsigned)(h + 1));
      if (iter % 3 == 0) {
         x0 = 0;
         x1 = w;   /* whole rows: one run */
      }
      if (x0 > x1) { const int t = x0; x0 = x1; x1 = t; }
      if (y0 > y1) { const int t = y0; y0 = y1; y1 = t; }
      uint8_t rgba[4];
      const uint32_t cv = rnd();
      memcpy(rgba, &cv, 4);
      const bool depth = rnd() & 1u, stencil = rnd() & 1u;
      const uint32_t zvalue = f == R_ZS_Z32 ? rnd() << 8 | (rnd() & 0xffu) : rnd() & 0xffffffu;
      const uint8_t svalue = (uint8_t)rnd();
      r_clear_color_rect(&fb, x0, y0, x1, y1, rgba);
      r_clear_depth_stencil_rect(&fb, x0, y0, x1, y1, depth, zvalue, stencil, svalue);
      for (int y = y0; y < y1; y++) {
         for (int x = x0; x < x1; x++) {
            uint32_t *z = &zwant[y * w + x];
            cwant[y * w + x] = cv;
            if (f == R_ZS_Z32) {
               if (depth)
                  *z = zvalue;
            } else if (f == R_ZS_Z24X8) {
               *z = depth ? zvalue : *z & 0xffffffu;   /* bits 24..31 zero */
            } else {
               if (depth)
                  *z = (*z & 0xff000000u) | zvalue;
               if (stencil)
                  *z = (*z & 0xffffffu) | (uint32_t)svalue << 24;
            }
         }
      }
      if (memcmp(color, cwant, sizeof(color)) != 0 || memcmp(zs, zwant, sizeof(zs)) != 0) {
         FAIL("clear of [%d,%d)x[%d,%d) in %dx%d (zs format %d, depth %d stencil %d) "
              "differs from the per-pixel stores", x0, x1, y0, y1, w, h, (int)f, depth,
              stencil);
         return;
      }
   }
}

int main(void)
{
   test_fill32();
   test_copy();
   test_clear_rects();
   return check_report("unit-rows");
}
