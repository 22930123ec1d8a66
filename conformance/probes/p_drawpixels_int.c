/* p_drawpixels_int.c - glDrawPixels of GL_INT colour data: the oracle's
 * image texture holds each channel as 16-bit snorm, the top 16 bits of the
 * 32-bit value (x >> 16), sampled as s * (1/32767); not the float
 * x * 2^-31 of a 32-bit conversion.  The two differ in the last bit of the
 * 8-bit result where x * 255 / 2^31 lies just above a half.  Every
 * channel of every client format is checked against the 16-bit model, and
 * the float model must miss some (else the probe would not tell them
 * apart).  GL_UNSIGNED_INT colour data is held as 16-bit unorm, each
 * channel rounded to 16 bits, (x * 65535 + 2^31 - 1) / (2^32 - 1) (Mesa's
 * unorm-to-unorm narrowing), sampled as u * (1/65535): the truncating
 * x >> 16 and the float x * 2^-32 both miss some, among them the value
 * 1760094441, whose (float)x * 2^-32 * 255 is 104.5 (105 on the oracle).
 * ORACLE-NOTES.md "Bitmaps and pixel rectangles"; the API fuzzer's seed
 * 3000159. */
#include "probe.h"
#include <stdint.h>

static int rnd8(float x)
{
   if (x < 0.0f)
      x = 0.0f;
   if (x > 1.0f)
      x = 1.0f;
   return (int)lrintf(x * 255.0f);
}

int main(void)
{
   enum { W = 128, H = 128 };
   probe_init_ub(W, H);
   static int32_t px[W * H * 4];
   uint32_t s = 12345u;
   for (int i = 0; i < W * H * 4; i++) {
      s = s * 1664525u + 1013904223u;
      px[i] = (int32_t)(s & 0x7fffffffu);   /* non-negative: no clamp hides it */
      if (i % 7 == 0)
         px[i] = -px[i];
   }
   static const struct { GLenum format; int n; int ch[4]; const char *name; } f[] = {
      { GL_RGBA, 4, { 0, 1, 2, 3 }, "GL_RGBA" },
      { GL_BGRA, 4, { 2, 1, 0, 3 }, "GL_BGRA" },
      { GL_RGB, 3, { 0, 1, 2, -1 }, "GL_RGB" },
      { GL_LUMINANCE_ALPHA, 2, { 0, 3, -1, -1 }, "GL_LUMINANCE_ALPHA" },
      { GL_ALPHA, 1, { 3, -1, -1, -1 }, "GL_ALPHA" },
      { GL_RED, 1, { 0, -1, -1, -1 }, "GL_RED" },
   };
   for (size_t k = 0; k < sizeof f / sizeof f[0]; k++) {
      memset(g_buf, 0, (size_t)W * H * 4);
      const int h = H;   /* W x H pixels of at most 4 channels: px */
      glRasterPos2i(0, 0);
      glDrawPixels(W, h, f[k].format, GL_INT, px);
      glFinish();
      long bad16 = 0, badf = 0;
      for (int p = 0; p < W * h; p++)
         for (int c = 0; c < f[k].n; c++) {
            const int32_t v = px[p * f[k].n + c];
            const int got = g_buf[p * 4 + f[k].ch[c]];
            const int m16 = rnd8((float)(v >> 16) * (1.0f / 32767.0f));
            const int mf = rnd8((float)v * (1.0f / 2147483648.0f));
            bad16 += got != m16;
            badf += got != mf;
         }
      char what[160];
      snprintf(what, sizeof what, "%s GL_INT: channels off the 16-bit snorm model", f[k].name);
      probe_expect(what, bad16, 0);
      snprintf(what, sizeof what, "%s GL_INT: the float model misses some", f[k].name);
      probe_expect(what, badf > 0, 1);
   }
   /* GL_UNSIGNED_INT: random words, neighbours of every half step and the
    * exact tie 104.5 * 2^32 / 255 */
   static uint32_t ux[W * H * 4];
   for (int i = 0; i < W * H * 4; i++) {
      s = s * 1664525u + 1013904223u;
      ux[i] = s;
   }
   for (int i = 0; i < 4096; i++)
      ux[i] = (uint32_t)(((double)(i % 255) + 0.5) * 4294967296.0 / 255.0) + (uint32_t)((i / 255) % 5) - 2u;
   ux[4096] = 1760094441u;   /* (float)x * 2^-32 * 255 is 104.5 */
   for (size_t k = 0; k < sizeof f / sizeof f[0]; k++) {
      memset(g_buf, 0, (size_t)W * H * 4);
      glRasterPos2i(0, 0);
      glDrawPixels(W, H, f[k].format, GL_UNSIGNED_INT, ux);
      glFinish();
      long bad16 = 0, badshift = 0, badf = 0;
      for (int p = 0; p < W * H; p++)
         for (int c = 0; c < f[k].n; c++) {
            const uint32_t v = ux[p * f[k].n + c];
            const int got = g_buf[p * 4 + f[k].ch[c]];
            const uint32_t u16 = (uint32_t)(((uint64_t)v * 65535u + 0x7fffffffu) / 0xffffffffu);
            bad16 += got != rnd8((float)u16 * (1.0f / 65535.0f));
            badshift += got != rnd8((float)(v >> 16) * (1.0f / 65535.0f));
            badf += got != rnd8((float)v * (1.0f / 4294967296.0f));
         }
      char what[160];
      snprintf(what, sizeof what, "%s GL_UNSIGNED_INT: channels off the rounded 16-bit unorm model", f[k].name);
      probe_expect(what, bad16, 0);
      snprintf(what, sizeof what, "%s GL_UNSIGNED_INT: the x >> 16 and float models miss some", f[k].name);
      probe_expect(what, badshift > 0 && badf > 0, 1);
   }
   {
      /* the tie: (float)x * 2^-32 * 255 is 104.5 for both; x * 255 / 2^32
       * lies just above the half for 1760094441 (105), below for
       * 1760094440 (104) */
      const uint32_t tie[3] = { 1760094441u, 1760094440u, 1760094441u };
      memset(g_buf, 0, (size_t)W * H * 4);
      glRasterPos2i(0, 0);
      glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_INT, tie);
      glFinish();
      probe_expect("GL_RGB GL_UNSIGNED_INT 104.5: red (1760094441)", g_buf[0], 105);
      probe_expect("GL_RGB GL_UNSIGNED_INT 104.5: green (1760094440)", g_buf[1], 104);
   }
   probe_expect("no error", (long)glGetError(), GL_NO_ERROR);
   return probe_result();
}
