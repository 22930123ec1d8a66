/*
 * cylinder_vs_freeglut: glutSolidCylinder and glutWireCylinder drawn by
 * fixgl into an OSMesa buffer, the shapes' GL calls made by one of two
 * GLUT libraries:
 *   - built against the system's <GL/freeglut.h> and linked with Debian's
 *     libglut (freeglut 3.4) and libfixgl: freeglut's own geometry code
 *     (its gl* calls bind to libfixgl, which the program links directly,
 *     before libglut's libGL.so.1); glutInit needs an X display (Xvfb);
 *   - built against fixgl's include/ and linked with libfixglut
 *     (FIXGLUT_HEADLESS=1).
 * Both write the same frames (RGBA and depth) to OUTFILE; the test
 * (run_vs_freeglut.py) requires them identical: the same vertices,
 * normals and order.  No window is created: freeglut's shapes draw with
 * the GL 1.1 path when no window is current.
 */
#include <GL/freeglut.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#define W 96
#define H 96

int main(int argc, char **argv)
{
   static unsigned char rgba[W * H * 4];
   static GLuint depth[W * H];
   if (argc < 2) {
      fprintf(stderr, "usage: %s OUTFILE\n", argv[0]);
      return 2;
   }
   const char *path = argv[1];
   glutInit(&argc, argv);
   OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
   if (!ctx || !OSMesaMakeCurrent(ctx, rgba, GL_UNSIGNED_BYTE, W, H)) {
      fprintf(stderr, "cylinder_vs_freeglut: no OSMesa context\n");
      return 1;
   }
   FILE *out = fopen(path, "wb");
   if (!out)
      return 1;
   static const struct { double r, h; int slices, stacks; int wire; } cases[] = {
      { 0.8, 1.5, 12, 3, 0 }, { 0.5, 2.0, 7, 1, 0 }, { 1.0, 0.6, 24, 5, 0 },
      { 0.8, 1.5, 12, 3, 1 }, { 0.6, 1.2, 9, 4, 1 }, { 0.3, 1.8, 3, 2, 0 },
   };
   for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
      glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glEnable(GL_DEPTH_TEST);
      glEnable(GL_LIGHTING);
      glEnable(GL_LIGHT0);
      glEnable(GL_COLOR_MATERIAL);
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 10.0);
      glMatrixMode(GL_MODELVIEW);
      glLoadIdentity();
      glTranslatef(0.0f, 0.0f, -4.0f);
      glRotatef(35.0f + 20.0f * (float)i, 1.0f, 0.4f, 0.1f);
      glTranslatef(0.0f, 0.0f, -0.7f);
      glColor3f(0.9f, 0.6f, 0.3f);
      if (cases[i].wire)
         glutWireCylinder(cases[i].r, cases[i].h, cases[i].slices, cases[i].stacks);
      else
         glutSolidCylinder(cases[i].r, cases[i].h, cases[i].slices, cases[i].stacks);
      glFinish();
      glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
      fwrite(rgba, 1, sizeof rgba, out);
      fwrite(depth, 1, sizeof depth, out);
      GLenum e = glGetError();
      fwrite(&e, sizeof e, 1, out);
   }
   OSMesaDestroyContext(ctx);
   return fclose(out) == 0 ? 0 : 1;
}
