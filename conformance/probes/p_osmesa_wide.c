/* p_osmesa_wide.c - OSMesa's GL_UNSIGNED_SHORT and GL_FLOAT buffers
 * (ORACLE-NOTES.md "OSMesa contexts and buffers"): the oracle renders into
 * R16G16B16A16_UNORM and R32G32B32A32_FLOAT targets and copies them as
 * they are:
 *  - OSMesaMakeCurrent takes GL_UNSIGNED_SHORT and GL_FLOAT for RGBA,
 *    BGRA, ARGB and RGB (RGBA order in the buffer for all of the RGBA
 *    family), GL_UNSIGNED_BYTE as before;
 *  - a float clear is stored unclamped; a ushort clear is
 *    (int)(clamp(c) * 65535 + 0.5f);
 *  - a ushort fragment is the float fragment (as the float buffer holds
 *    it) converted by the magic of lp_build_clamped_float_to_unsigned_norm;
 *  - blending: float s*sa + d*(1-sa) unfused; ushort in 16-bit lanes
 *    (t = a*b, (t + (t >> 16) + 0x8000) >> 16, saturating add);
 *  - glReadPixels: from floats clamped, ubyte lrint(f*255); from ushort
 *    ubyte (u*255 + 32767)/65535 and float u*(1/65535). */
#include "probe.h"

#include <stdbool.h>
#include <stdint.h>

#define N 16

static float fbuf[N * N * 4], fbuf2[N * N * 4];
static unsigned short ubuf[N * N * 4];

static unsigned rnd = 3;
static float rf(void)
{
   rnd = rnd * 1103515245u + 12345u;
   return (float)((rnd >> 8) & 0xffff) / 65536.0f;
}

static unsigned to_u16(float v)
{
   const float x = v * (65535.0f / 65536.0f) + 128.0f;
   uint32_t u;
   memcpy(&u, &x, sizeof(u));
   return u & 0xffffu;
}

static unsigned mul16(unsigned a, unsigned b)
{
   const uint32_t t = a * b;
   return (t + (t >> 16) + 0x8000u) >> 16;
}

static void scene(void)
{
   glViewport(0, 0, N, N);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, N, 0, N, -1, 1);
   glClearColor(0.3f, 1.5f, -0.25f, 0.7f);
   glClear(GL_COLOR_BUFFER_BIT);
   glBegin(GL_TRIANGLES);
   glColor4f(1, 0, 0.2f, 1); glVertex2f(0, 0);
   glColor4f(0, 1, 0.6f, 0.5f); glVertex2f(N, 0);
   glColor4f(0.2f, 0.3f, 1, 0); glVertex2f(0, N);
   glEnd();
   glFinish();
}

int main(void)
{
   /* which pairs bind */
   const GLenum fmts[5] = { OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR };
   const GLenum types[3] = { GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT };
   long taken = 0;
   for (int f = 0; f < 5; f++) {
      OSMesaContext c = OSMesaCreateContextExt(fmts[f], 0, 0, 0, NULL);
      for (int t = 0; t < 3; t++)
         taken = taken * 2 + (c && OSMesaMakeCurrent(c, fbuf, types[t], 4, 4));
      OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
      if (c)
         OSMesaDestroyContext(c);
   }
   probe_expect("format x type taken (bits, RGBA..BGR x UB, US, F)", taken, 077770);

   OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
   OSMesaContext cb = OSMesaCreateContextExt(OSMESA_BGRA, 0, 0, 0, NULL);
   OSMesaMakeCurrent(c, fbuf, GL_FLOAT, N, N);
   scene();
   probe_expect("float clear stored unclamped (1.5, -0.25)",
                fbuf[4 * (N * N - 1) + 1] == 1.5f && fbuf[4 * (N * N - 1) + 2] == -0.25f, 1);
   OSMesaMakeCurrent(cb, fbuf2, GL_FLOAT, N, N);
   scene();
   probe_expect("BGRA float buffer: RGBA order (bytes differing from RGBA's)",
                memcmp(fbuf, fbuf2, sizeof fbuf) != 0, 0);
   OSMesaMakeCurrent(c, ubuf, GL_UNSIGNED_SHORT, N, N);
   scene();
   long bad = 0, cleared = 0;
   for (int i = 0; i < N * N; i++) {
      /* the clear shows where the float buffer holds the clear colour */
      const bool clear = fbuf[4 * i] == 0.3f && fbuf[4 * i + 1] == 1.5f;
      for (int k = 0; k < 4; k++) {
         const float v = fbuf[4 * i + k];
         const float cl = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
         const unsigned want = clear ? (unsigned)(int)(cl * 65535.0f + 0.5f) : to_u16(v);
         bad += ubuf[4 * i + k] != want;
      }
      cleared += clear;
   }
   probe_expect("ushort buffer vs the float one converted (channels off)", bad, 0);
   probe_expect("some pixels cleared", cleared > 10, 1);

   /* readback */
   OSMesaMakeCurrent(c, fbuf, GL_FLOAT, N, N);
   scene();
   static unsigned char rb[N * N * 4];
   static float rfl[N * N * 4];
   glReadPixels(0, 0, N, N, GL_RGBA, GL_UNSIGNED_BYTE, rb);
   glReadPixels(0, 0, N, N, GL_RGBA, GL_FLOAT, rfl);
   bad = 0;
   for (int i = 0; i < N * N * 4; i++) {
      const float v = fbuf[i], cl = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
      bad += rb[i] != (unsigned char)lrintf(cl * 255.0f) || rfl[i] != cl;
   }
   probe_expect("glReadPixels of the float buffer (ubyte, float) off", bad, 0);
   OSMesaMakeCurrent(c, ubuf, GL_UNSIGNED_SHORT, N, N);
   scene();
   glReadPixels(0, 0, N, N, GL_RGBA, GL_UNSIGNED_BYTE, rb);
   glReadPixels(0, 0, N, N, GL_RGBA, GL_FLOAT, rfl);
   bad = 0;
   for (int i = 0; i < N * N * 4; i++)
      bad += rb[i] != (ubuf[i] * 255u + 32767u) / 65535u ||
             rfl[i] != (float)ubuf[i] * (1.0f / 65535.0f);
   probe_expect("glReadPixels of the ushort buffer (ubyte, float) off", bad, 0);

   /* other formats and types (readpix.c read_rgba_pixels,
    * _mesa_format_convert; libfixgl pixelformat.c fgl_pack_wide): from
    * ushort, a plain type channel by channel, a packed one of fields up to
    * 8 bits through the rounded byte and its rounded field, wider fields
    * through float and (int)(f * max + 0.5f), luminance R+G+B clamped; from
    * floats, clamped, then as float */
   {
      static unsigned short rs[N * N * 4];
      static unsigned int r32[N * N];
      long b1 = 0, b2 = 0, b3 = 0, b4 = 0;
      glReadPixels(0, 0, N, N, GL_BGRA, GL_UNSIGNED_SHORT, rs);
      for (int i = 0; i < N * N; i++)
         for (int c = 0; c < 4; c++)
            b1 += rs[4 * i + c] != ubuf[4 * i + (c == 3 ? 3 : 2 - c)];
      glReadPixels(0, 0, N, N, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, rs);
      for (int i = 0; i < N * N; i++) {
         unsigned f[3];
         for (int c = 0; c < 3; c++) {
            const unsigned u8 = (ubuf[4 * i + c] * 255u + 32767u) / 65535u, bits = c == 1 ? 6 : 5;
            f[c] = (u8 * ((1u << bits) - 1) + 127u) / 255u;
         }
         b2 += rs[i] != (unsigned short)(f[0] << 11 | f[1] << 5 | f[2]);
      }
      glReadPixels(0, 0, N, N, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, r32);
      for (int i = 0; i < N * N; i++) {
         unsigned w = 0;
         for (int c = 0; c < 4; c++) {
            const float f = (float)ubuf[4 * i + c] * (1.0f / 65535.0f);
            const unsigned max = c == 3 ? 3u : 1023u;
            w |= (unsigned)(int)(f * (float)max + 0.5f) << (c == 3 ? 0 : 22 - 10 * c);
         }
         b3 += r32[i] != w;
      }
      glReadPixels(0, 0, N, N, GL_LUMINANCE, GL_FLOAT, rfl);
      for (int i = 0; i < N * N; i++) {
         float sum = 0.0f;
         for (int c = 0; c < 3; c++)
            sum += (float)ubuf[4 * i + c] * (1.0f / 65535.0f);
         b4 += rfl[i] != (sum < 1.0f ? sum : 1.0f);
      }
      probe_expect("ushort buffer as GL_BGRA ushort: channels off", b1, 0);
      probe_expect("ushort buffer as GL_RGB 5_6_5 (byte, then field, both rounded): off", b2, 0);
      probe_expect("ushort buffer as GL_RGBA 10_10_10_2 (through float): off", b3, 0);
      probe_expect("ushort buffer as GL_LUMINANCE float (R+G+B clamped): off", b4, 0);
      OSMesaMakeCurrent(c, fbuf, GL_FLOAT, N, N);
      scene();
      static short rsh[N * N];
      glReadPixels(0, 0, N, N, GL_BGRA, GL_UNSIGNED_SHORT, rs);
      glReadPixels(0, 0, N, N, GL_RED, GL_SHORT, rsh);
      long b5 = 0;
      for (int i = 0; i < N * N; i++) {
         for (int c = 0; c < 4; c++) {
            const float v = fbuf[4 * i + (c == 3 ? 3 : 2 - c)];
            const float cl = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
            b5 += rs[4 * i + c] != (unsigned short)lrintf(cl * 65535.0f);
         }
         const float v = fbuf[4 * i], cl = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
         b5 += rsh[i] != (short)lrintf(cl * 32767.0f);
      }
      probe_expect("float buffer as GL_BGRA ushort and GL_RED short (clamped): off", b5, 0);
      OSMesaMakeCurrent(c, ubuf, GL_UNSIGNED_SHORT, N, N);
   }

   /* blending on random colours */
   long badf = 0, badu = 0;
   for (int it = 0; it < 300; it++) {
      const float d[4] = { rf(), rf(), rf(), rf() }, s[4] = { rf(), rf(), rf(), rf() };
      for (int pass = 0; pass < 2; pass++) {
         if (pass == 0)
            OSMesaMakeCurrent(c, fbuf, GL_FLOAT, 4, 4);
         else
            OSMesaMakeCurrent(c, ubuf, GL_UNSIGNED_SHORT, 4, 4);
         glViewport(0, 0, 4, 4);
         glMatrixMode(GL_PROJECTION);
         glLoadIdentity();
         glClearColor(d[0], d[1], d[2], d[3]);
         glClear(GL_COLOR_BUFFER_BIT);
         glEnable(GL_BLEND);
         glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
         glColor4f(s[0], s[1], s[2], s[3]);
         glRectf(-1, -1, 1, 1);
         glDisable(GL_BLEND);
         glFinish();
      }
      for (int k = 0; k < 4; k++) {
         const float want = s[k] * s[3] + d[k] * (1.0f - s[3]);
         badf += memcmp(&want, &fbuf[k], 4) != 0;
         const unsigned a16 = to_u16(s[3]), d16 = (unsigned)(int)(d[k] * 65535.0f + 0.5f);
         unsigned r = mul16(to_u16(s[k]), a16) + mul16(d16, 65535u - a16);
         badu += ubuf[k] != (r > 65535u ? 65535u : r);
      }
   }
   probe_expect("float blending off the unfused model (of 1200)", badf, 0);
   probe_expect("ushort blending off the 16-bit lanes model (of 1200)", badu, 0);
   OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
   return probe_result();
}
