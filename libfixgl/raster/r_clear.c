/*
 * Whole-buffer clears.  Values arrive already packed (the oracle packs the
 * clear colour with float_to_ubyte and the depth with util_pack64_z,
 * ORACLE-NOTES.md "Clears").
 */
#include "r_state.h"

#include <string.h>
#include <wchar.h>

/* n 32-bit values v at p: glibc's wmemset (wchar_t is 32 bits on the
 * targets that have it) is a vectorised fill that never reads the buffer;
 * memset when the four bytes are equal. */
static void fill32(void *p, uint32_t v, size_t n)
{
   if ((v & 0xffu) * 0x01010101u == v) {
      memset(p, (int)(v & 0xffu), 4 * n);
      return;
   }
#if __SIZEOF_WCHAR_T__ == 4
   wmemset(p, (wchar_t)v, n);
#else
   uint32_t *q = p;
   for (size_t i = 0; i < n; i++)
      q[i] = v;
#endif
}

void r_clear_color(const struct r_state *rs, const uint8_t rgba[4])
{
   const size_t n = (size_t)rs->fb->width * (size_t)rs->fb->height;
   uint32_t v;
   memcpy(&v, rgba, 4);
   fill32(rs->fb->color, v, n);
}

void r_clear_depth_stencil(const struct r_state *rs, bool depth, uint32_t zvalue,
                           bool stencil, uint8_t svalue)
{
   const size_t n = (size_t)rs->fb->width * (size_t)rs->fb->height;
   switch (rs->fb->zs_format) {
   case R_ZS_Z16:
      if (depth) {
         uint16_t *z = rs->fb->zs;
         /* pairs of values as 32-bit words, then an odd last one */
         const uint32_t pair = (zvalue & 0xffffu) * 0x10001u;
         if (((uintptr_t)z & 3u) == 0) {
            fill32(z, pair, n / 2);
            if (n & 1)
               z[n - 1] = (uint16_t)zvalue;
         } else {
            for (size_t i = 0; i < n; i++)
               z[i] = (uint16_t)zvalue;
         }
      }
      break;
   case R_ZS_Z24X8:
   case R_ZS_Z24S8: {
      uint32_t *z = rs->fb->zs;
      uint32_t keep = 0, set = 0;
      if (depth) set |= zvalue & 0xffffffu; else keep |= 0xffffffu;
      if (rs->fb->zs_format == R_ZS_Z24S8) {
         if (stencil) set |= (uint32_t)svalue << 24; else keep |= 0xff000000u;
      }
      if (keep == 0) {
         fill32(z, set, n);   /* a plain fill: no read of the old values */
      } else {
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
      break;
   }
   case R_ZS_S8:
      if (stencil)
         memset(rs->fb->zs, svalue, n);
      break;
   case R_ZS_NONE:
   default:
      break;
   }
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
