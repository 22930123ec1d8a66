/* p_color_conv.c - float -> unorm8 conversion of fragment colours and of
 * the clear colour (ORACLE-NOTES.md "Colour conversion"). */
#include "probe.h"

static int rne255(float v)
{
   if (!(v > 0)) v = 0;
   if (v > 1) v = 1;
   return (int)nearbyintf(v * 255.0f);
}

static float chan(int k, int c)
{
   float v = (float)k / 65535.0f;
   if (c == 0) return v;
   if (c == 1) return v * 0.999f;
   return (float)(k % 4096) / 4095.0f * 0.01f + (float)(k / 4096) / 15.0f;
}

int main(void)
{
   probe_init_ub(256, 256);
   glEnable(GL_DITHER); /* ignored by llvmpipe */
   clear0();
   glBegin(GL_POINTS);
   for (int y = 0; y < 256; y++)
      for (int x = 0; x < 256; x++) {
         int k = y * 256 + x;
         glColor4f(chan(k, 0), chan(k, 1), chan(k, 2), 1.0f);
         glVertex2f(x + 0.5f, y + 0.5f);
      }
   glEnd();
   glFinish();
   long bad = 0, bad_half_up = 0;
   for (int y = 0; y < 256; y++)
      for (int x = 0; x < 256; x++)
         for (int c = 0; c < 3; c++) {
            float v = chan(y * 256 + x, c);
            if (v > 1) v = 1;
            int got = px(x, y)[c];
            if (got != rne255(v)) bad++;
            if (got != (int)floorf(v * 255.0f + 0.5f)) bad_half_up++;
         }
   probe_expect("fragment colours (196608 channels, dither on): not RNE(c*255f)", bad, 0);
   printf("     (a round-half-up model misses %ld)\n", bad_half_up);

   /* ties of c * 255f: to even */
   const float ties[] = { 0.5f, 1.5f / 255, 2.5f / 255, 127.5f / 255, 128.5f / 255 };
   const int want[] = { 128, 2, 2, 128, 128 };
   clear0();
   glBegin(GL_POINTS);
   for (int i = 0; i < 5; i++) {
      glColor3f(ties[i], 0, 0);
      glVertex2f(i + 0.5f, 0.5f);
   }
   glEnd();
   glFinish();
   for (int i = 0; i < 5; i++) {
      char what[64];
      snprintf(what, sizeof what, "tie %.9g * 255f = %g", ties[i], ties[i] * 255.0f);
      probe_expect(what, px(i, 0)[0], want[i]);
   }

   /* Out of range: clamped. */
   clear0();
   glBegin(GL_POINTS);
   glColor4f(-0.5f, 1.5f, 0.0f, 1.0f);
   glVertex2f(0.5f, 0.5f);
   glEnd();
   glFinish();
   probe_expect("glColor -0.5 -> 0", px(0, 0)[0], 0);
   probe_expect("glColor 1.5 -> 255", px(0, 0)[1], 255);

   /* float_to_ubyte, the clear colour's packing: the low 8 bits of
    * c * (255/256) + 32768.0f.  The sum rounds c*255 to an integer once
    * more after the product's rounding, so it can part from RNE(c*255f)
    * only next to a tie k + 0.5: every float within 2^-10 of one. */
   long parted = 0, scanned = 0;
   for (int k = 0; k < 255; k++) {
      float lo = ((float)k + 0.5f - 0x1p-10f) / 255.0f, hi = ((float)k + 0.5f + 0x1p-10f) / 255.0f;
      for (float f = lo; f <= hi; f = nextafterf(f, 2.0f)) {
         union { float f; unsigned u; } m = { .f = f * (255.0f / 256.0f) + 32768.0f };
         scanned++;
         if ((int)(m.u & 0xff) != rne255(f)) parted++;
      }
   }
   printf("     %ld floats next to the ties scanned\n", scanned);
   probe_expect("float_to_ubyte parts from RNE(c*255f) next to a tie", parted, 0);

   /* The oracle's clear colour equals RNE(c*255f). */
   srand(22);
   long badc = 0;
   for (int i = 0; i < 2000; i++) {
      float v = (i < 256) ? ((float)i + 0.5f) / 255.0f : (float)rand() / (float)RAND_MAX;
      glClearColor(v, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT);
      glFinish();
      if (px(0, 0)[0] != rne255(v)) badc++;
   }
   probe_expect("glClearColor (2000 values, 256 ties): not RNE(c*255f)", badc, 0);
   return probe_result();
}
