/*
 * Whole-buffer clears.  Values arrive already packed (the oracle packs the
 * clear colour with float_to_ubyte and the depth with util_pack64_z,
 * ORACLE-NOTES.md "Clears").
 */
#include "r_state.h"

#include <string.h>

void r_clear_color(const struct r_state *rs, const uint8_t rgba[4])
{
   const size_t n = (size_t)rs->width * (size_t)rs->height;
   uint8_t *p = rs->color;
   if (n == 0)
      return;
   memcpy(p, rgba, 4);
   /* double the filled prefix until the buffer is full */
   size_t done = 1;
   while (done < n) {
      const size_t chunk = done < n - done ? done : n - done;
      memcpy(p + 4 * done, p, 4 * chunk);
      done += chunk;
   }
}

void r_clear_depth_stencil(const struct r_state *rs, bool depth, uint32_t zvalue,
                           bool stencil, uint8_t svalue)
{
   const size_t n = (size_t)rs->width * (size_t)rs->height;
   switch (rs->zs_format) {
   case R_ZS_Z16:
      if (depth) {
         uint16_t *z = rs->zs;
         for (size_t i = 0; i < n; i++)
            z[i] = (uint16_t)zvalue;
      }
      break;
   case R_ZS_Z24X8:
   case R_ZS_Z24S8: {
      uint32_t *z = rs->zs;
      uint32_t keep = 0, set = 0;
      if (depth) set |= zvalue & 0xffffffu; else keep |= 0xffffffu;
      if (rs->zs_format == R_ZS_Z24S8) {
         if (stencil) set |= (uint32_t)svalue << 24; else keep |= 0xff000000u;
      }
      if (keep == 0) {
         /* a plain fill: no read of the old values */
         for (size_t i = 0; i < n; i++)
            z[i] = set;
      } else {
         for (size_t i = 0; i < n; i++)
            z[i] = (z[i] & keep) | set;
      }
      break;
   }
   case R_ZS_S8:
      if (stencil)
         memset(rs->zs, svalue, n);
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
