/* p_depth.c - depth: screen-linear z, the fused evaluation, polygon
 * offset, clamp, RNE(z * 16777215f); glClearDepth in double
 * (ORACLE-NOTES.md "Depth conversion and polygon offset").  Reads the raw
 * Z24X8 buffer with OSMesaGetDepthBuffer. */
#include "probe.h"

#define W 64
#define H 64

/* Random triangles in clip space (w != 1 for half of them) drawn with
 * glPolygonOffset(factor, units) (offset off when both are 0). */
static void run(int seed, float factor, float units, long *tot, long *bad, long *bad_trunc)
{
   if (factor != 0 || units != 0) {
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(factor, units);
   } else {
      glDisable(GL_POLYGON_OFFSET_FILL);
   }
   srand(seed);
   GLint zw, zh, bpv;
   void *zb;
   for (int iter = 0; iter < 100; iter++) {
      float cx[3], cy[3], cz[3], cw[3], gx[3], gy[3], gz[3];
      for (int i = 0; i < 3; i++) {
         float nx = (rand() % 2000) / 1000.0f - 1.0f, ny = (rand() % 2000) / 1000.0f - 1.0f;
         float nz = (rand() % 1999) / 1000.0f - 0.999f;
         cw[i] = (iter & 1) ? 1.0f : 0.5f + (rand() % 4000) / 1000.0f;
         cx[i] = nx * cw[i];
         cy[i] = ny * cw[i];
         cz[i] = nz * cw[i];
         float oow = 1.0f / cw[i];
         gx[i] = fmaf(cx[i] * oow, 32.0f, 32.0f);
         gy[i] = fmaf(cy[i] * oow, -32.0f, 32.0f);
         gz[i] = fmaf(cz[i] * oow, 0.5f, 0.5f);
      }
      glClearDepth(0.0);
      glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
      glBegin(GL_TRIANGLES);
      for (int i = 0; i < 3; i++) glVertex4f(cx[i], cy[i], cz[i], cw[i]);
      glEnd();
      glFinish();
      OSMesaGetDepthBuffer(g_ctx, &zw, &zh, &bpv, &zb);
      int o[3];
      if (setup_order(gx, gy, o) == 0) continue;
      struct plane_setup s = plane_init(gx, gy, o);
      float rz[3];
      plane_coef(&s, gz[o[0]], gz[o[1]], gz[o[2]], rz);
      /* polygon offset (lp_state_setup.c lp_do_offset_tri) */
      float dx01 = gx[o[0]] - gx[o[1]], dy01 = gy[o[0]] - gy[o[1]];
      float dx20 = gx[o[2]] - gx[o[0]], dy20 = gy[o[2]] - gy[o[0]];
      float ooa = 1.0f / (dx01 * dy20 - dy01 * dx20);
      float dz01 = gz[o[0]] - gz[o[1]], dz20 = gz[o[2]] - gz[o[0]];
      float ozx = fabsf((dz20 * dy01 - dy20 * dz01) * ooa);
      float ozy = fabsf((dx20 * dz01 - dz20 * dx01) * ooa);
      float mx = ozx > ozy ? ozx : ozy;
      float off = 0.0f;
      if (factor != 0 || units != 0)
         off = (float)((double)units * (1.0 / ((1 << 24) - 1)) * 2) + mx * factor;
      for (int py = 0; py < H; py++)
         for (int x = 0; x < W; x++) {
            unsigned zr = ((unsigned *)zb)[(H - 1 - py) * W + x] & 0xffffff;
            if (zr == 0) continue;
            float z = plane_eval(rz, x, py) + off;
            if (z < 0) z = 0;
            if (z > 1) z = 1;
            (*tot)++;
            if (zr != (unsigned)nearbyintf(z * 16777215.0f)) (*bad)++;
            if (zr != (unsigned)(z * 16777215.0f)) (*bad_trunc)++;
         }
   }
}

int main(void)
{
   static unsigned char cbuf[W * H * 4];
   g_ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
   if (!g_ctx || !OSMesaMakeCurrent(g_ctx, cbuf, GL_UNSIGNED_BYTE, W, H))
      return 2;
   glViewport(0, 0, W, H);
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_ALWAYS);
   GLint zw, zh, bpv;
   void *zb;
   OSMesaGetDepthBuffer(g_ctx, &zw, &zh, &bpv, &zb);
   probe_expect("depth buffer bytes per value (Z24X8)", bpv, 4);

   long tot = 0, bad = 0, trunc = 0;
   run(5, 0, 0, &tot, &bad, &trunc);
   printf("     no offset: %ld depths\n", tot);
   probe_expect("no offset: depths RNE(z*16777215f) misses", bad, 0);
   probe_expect("no offset: a truncating model misses some", trunc > 0, 1);

   const float sets[3][2] = { { 1.5f, 3.0f }, { -2.0f, -7.0f }, { 0.25f, 100.0f } };
   for (int k = 0; k < 3; k++) {
      char what[96];
      tot = bad = trunc = 0;
      run(5 + k, sets[k][0], sets[k][1], &tot, &bad, &trunc);
      snprintf(what, sizeof what, "glPolygonOffset(%g, %g): %ld depths, misses",
               sets[k][0], sets[k][1], tot);
      probe_expect(what, bad, 0);
   }

   /* glClearDepth(d): lrint(d * 0xffffff) in double. */
   const double ds[] = { 0.5, 0.3, 1.0 / 3.0, 0.7, 0.123456789, 0.999999999 };
   for (int i = 0; i < 6; i++) {
      glClearDepth(ds[i]);
      glClear(GL_DEPTH_BUFFER_BIT);
      glFinish();
      OSMesaGetDepthBuffer(g_ctx, &zw, &zh, &bpv, &zb);
      char what[64];
      snprintf(what, sizeof what, "glClearDepth(%.9g)", ds[i]);
      probe_expect(what, ((unsigned *)zb)[0] & 0xffffff, lrint(ds[i] * 0xffffff));
   }
   return probe_result();
}
