/*
 * The start-up bench's reference: a bare OSMesa program (Mesa's, the
 * oracle) drawing the same small frame (a lit sphere of the same
 * triangles as glutSolidSphere's, drawn here with plain GL), no image
 * written; prints the same two numbers (startup_common.h).
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>

#include "startup_common.h"

static void sphere(double r, int slices, int stacks)
{
   for (int j = 0; j < stacks; j++) {
      double a0 = M_PI * j / stacks, a1 = M_PI * (j + 1) / stacks;
      glBegin(GL_QUAD_STRIP);
      for (int i = 0; i <= slices; i++) {
         double b = 2.0 * M_PI * i / slices;
         glNormal3d(sin(a1) * cos(b), sin(a1) * sin(b), cos(a1));
         glVertex3d(r * sin(a1) * cos(b), r * sin(a1) * sin(b), r * cos(a1));
         glNormal3d(sin(a0) * cos(b), sin(a0) * sin(b), cos(a0));
         glVertex3d(r * sin(a0) * cos(b), r * sin(a0) * sin(b), r * cos(a0));
      }
      glEnd();
   }
}

int main(void)
{
   static unsigned char buf[64 * 64 * 4];
   OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
   if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 64, 64))
      return 1;
   startup_mark();
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);
   glEnable(GL_LIGHTING);
   glEnable(GL_LIGHT0);
   sphere(0.8, 16, 12);
   glFinish();
   OSMesaDestroyContext(ctx);
   startup_report();
   return 0;
}
