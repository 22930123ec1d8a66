/* p_format.c - the OSMesa buffer format and a depth buffer do not change
 * what a scene draws: no guard band and no "linear" rasterizer with
 * RGBA8 (ORACLE-NOTES.md "The oracle and its host"). */
#include "probe.h"

static unsigned char bufs[3][64 * 64 * 4];

static void scene(void)
{
   glViewport(0, 0, 64, 64);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0, 64, 0, 64, -1, 1);
   glClearColor(0, 0, 0, 0);
   glClear(GL_COLOR_BUFFER_BIT);
   glBegin(GL_TRIANGLES);
   glColor3f(1, 0, 0); glVertex2f(-10, 3.3f);
   glColor3f(0, 1, 0); glVertex2f(70.2f, 9.7f);
   glColor3f(0.2f, 0.3f, 1); glVertex2f(20.1f, 75.5f);
   glColor3f(0.9f, 0.9f, 0.1f); glVertex2f(40, 40);
   glColor3f(0.1f, 0.5f, 0.5f); glVertex2f(60, 44.4f);
   glColor3f(0.7f, 0.2f, 0.4f); glVertex2f(50.3f, 61);
   glEnd();
   glFinish();
}

int main(void)
{
   const GLenum fmt[3] = { OSMESA_RGBA, OSMESA_RGBA, OSMESA_BGRA };
   const int depth[3] = { 24, 0, 0 };
   for (int k = 0; k < 3; k++) {
      OSMesaContext c = OSMesaCreateContextExt(fmt[k], depth[k], 0, 0, NULL);
      if (!c || !OSMesaMakeCurrent(c, bufs[k], GL_UNSIGNED_BYTE, 64, 64))
         return 2;
      scene();
      OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
      OSMesaDestroyContext(c);
   }
   for (int i = 0; i < 64 * 64; i++) {
      unsigned char t = bufs[2][4 * i];
      bufs[2][4 * i] = bufs[2][4 * i + 2];
      bufs[2][4 * i + 2] = t;
   }
   long lit = 0;
   for (int i = 0; i < 64 * 64; i++) lit += bufs[0][4 * i] || bufs[0][4 * i + 1] || bufs[0][4 * i + 2];
   probe_expect("the scene draws something", lit > 1000, 1);
   for (int k = 1; k < 3; k++) {
      long nd = 0;
      for (int i = 0; i < 64 * 64 * 4; i++) nd += bufs[0][i] != bufs[k][i];
      probe_expect(k == 1 ? "RGBA without depth vs RGBA + depth 24: differing channels"
                          : "BGRA without depth vs RGBA + depth 24: differing channels", nd, 0);
   }
   return probe_result();
}
