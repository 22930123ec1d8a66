/* p_clip_psize.c - the clipper lerps the point size (ORACLE-NOTES.md
 * "Point parameters": "The clipper lerps the point size"): a polygon-mode
 * (GL_POINT) triangle under attenuation with one vertex beyond the far
 * plane; the vertex where the polygon comes back in (edge B-C: it takes
 * B's edge flag, so it is drawn; the one where it goes out is not) takes
 * out + t*(in - out) of the attenuated sizes, t = dp_out / (dp_out - dp_in)
 * (draw_pipe_clip.c do_clip_tri, interp), drawn as a legacy square of
 * n = max(1, ((iround(size*256) + 127) & ~255) >> 8) pixels. */
#include "probe.h"

static int count(int x0, int y0, int x1, int y1)
{
   int n = 0;
   for (int y = y0; y <= y1; y++)
      for (int x = x0; x <= x1; x++)
         n += px(x, y)[0] != 0 || px(x, y)[1] != 0 || px(x, y)[2] != 0;
   return n;
}

static int legacy_n(float size)
{
   int n = (((int)lrintf(size * 256.0f) + 127) & ~255) >> 8;
   return n < 1 ? 1 : n;
}

int main(void)
{
   for (int k = 0; k < 4; k++) {
      const float size = 9.0f + 1.7f * (float)k, zb = -2.0f - 0.6f * (float)k;
      const float att[3] = { 1.0f, 0.0f, 0.25f };
      probe_init_ub(64, 64);
      glViewport(0, 0, 64, 64);
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(0, 64, 0, 64, -1, 1);
      glMatrixMode(GL_MODELVIEW);
      glLoadIdentity();
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT);
      glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
      glPointSize(size);
      glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
      glBegin(GL_TRIANGLES);
      glColor3f(1, 1, 1);
      glVertex3f(6, 8, 0);      /* A, inside */
      glVertex3f(58, 8, zb);    /* B, beyond the far plane (z_clip = -z) */
      glVertex3f(4, 62, 0);     /* C, inside */
      glEnd();
      glFinish();
      /* sizes at A and B: d = |z_eye| */
      const float sa = (1.0f / sqrtf(1.0f)) * size;
      const float tb = 1.0f + 0.25f * (-zb) * (-zb);
      const float sb = (1.0f / sqrtf(tb)) * size;
      /* far plane (0, 0, -1, 1) on z_clip = -z: dp = 1 + z */
      const float dpc = 1.0f, dpb = 1.0f + zb;
      const float t = dpb / (dpb - dpc);
      const float s = sb + t * (sa - sb);
      const float x = 58.0f + t * (4.0f - 58.0f), y = 8.0f + t * (62.0f - 8.0f);
      const int n = legacy_n(s);
      /* the new point on B-C, away from A's and C's squares;
       * the one on A-B is not drawn (its edge flag is off) */
      const int r = n / 2 + 1;
      const int got = count((int)x - r, (int)y - r, (int)x + r, (int)y + r);
      const int ab = count(16, 0, 63, 20);
      printf("size %.2f zb %.2f: new vertex (%.2f, %.2f) size %.3f -> %dx%d, drawn %d; A-B %d\n",
             size, zb, x, y, s, n, n, got, ab);
      probe_expect("the vertex made on A-B draws no point", ab, 0);
      probe_expect("the new vertex's point is a square of the lerped size", got, n * n);
      OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
      OSMesaDestroyContext(g_ctx);
      free(g_buf);
   }
   return probe_result();
}
