/*
 * glut-glu: a program linked with libfixglut and the system libGLU
 * (-lfixglut -lfixgl -lGLU): both define gluPerspective, gluLookAt and
 * gluOrtho2D (libfixglut's own three, glut_glu.c).  Whichever the dynamic
 * linker binds, the matrices must be the same: each function is taken
 * from each library explicitly (dlsym on its handle) and the GL matrix it
 * leaves is compared bit for bit, for several arguments; the binding the
 * program's own calls got is reported.  Headless on fixgl.
 */
#include <GL/glut.h>
#include <GL/glu.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef void (*persp_fn)(GLdouble, GLdouble, GLdouble, GLdouble);
typedef void (*lookat_fn)(GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble,
                          GLdouble, GLdouble, GLdouble);
typedef void (*ortho_fn)(GLdouble, GLdouble, GLdouble, GLdouble);

struct glu_fns {
   const char *lib;
   persp_fn perspective;
   lookat_fn lookat;
   ortho_fn ortho2d;
};

static int load(struct glu_fns *f, const char *soname)
{
   void *h = dlopen(soname, RTLD_NOW | RTLD_NOLOAD);
   if (!h) {
      fprintf(stderr, "glut-glu: %s is not loaded: %s\n", soname, dlerror());
      return -1;
   }
   f->lib = soname;
   *(void **)&f->perspective = dlsym(h, "gluPerspective");
   *(void **)&f->lookat = dlsym(h, "gluLookAt");
   *(void **)&f->ortho2d = dlsym(h, "gluOrtho2D");
   if (!f->perspective || !f->lookat || !f->ortho2d) {
      fprintf(stderr, "glut-glu: %s lacks a GLU matrix function\n", soname);
      return -1;
   }
   return 0;
}

/* the matrix one library's three functions build, from the identity */
static void build(const struct glu_fns *f, int i, GLdouble m[16])
{
   double a = 0.37 * i;
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   f->perspective(20.0 + 13.0 * i, 0.5 + 0.3 * i, 0.1 + 0.05 * i, 10.0 + 17.0 * i);
   f->lookat(1.0 + a, -0.5 * a, 3.0 - a, 0.1 * i, 0.2, -0.3 * i, 0.05 * i, 1.0, 0.1);
   f->ortho2d(-1.0 - a, 2.0 + a * a, -0.75, 1.25 + a);
   glGetDoublev(GL_MODELVIEW_MATRIX, m);
}

static void display(void) {}

int main(int argc, char **argv)
{
   struct glu_fns glut, glu, linked;
   setenv("FIXGLUT_HEADLESS", "1", 1);
   glutInit(&argc, argv);
   glutInitWindowSize(8, 8);
   glutCreateWindow("glu");
   glutDisplayFunc(display);
   /* the program uses libGLU for more than the three (so it is linked) */
   printf("glut-glu: libGLU's gluErrorString(GLU_INVALID_ENUM): %s\n",
          (const char *)gluErrorString(GLU_INVALID_ENUM));
   if (load(&glut, "libfixglut.so.0") || load(&glu, "libGLU.so.1"))
      return 1;
   linked = (struct glu_fns){ "as linked", gluPerspective, gluLookAt, gluOrtho2D };
   Dl_info info;
   if (dladdr((void *)(size_t)linked.perspective, &info))
      printf("glut-glu: the program's gluPerspective is %s's\n", info.dli_fname);
   if (glut.perspective == glu.perspective) {
      fprintf(stderr, "glut-glu: both handles give the same gluPerspective\n");
      return 1;
   }
   int failures = 0, compared = 0;
   for (int i = 0; i < 12; i++) {
      GLdouble a[16], b[16], c[16];
      build(&glut, i, a);
      build(&glu, i, b);
      build(&linked, i, c);
      compared++;
      if (memcmp(a, b, sizeof a) != 0 || memcmp(a, c, sizeof a) != 0) {
         failures++;
         for (int k = 0; k < 16; k++)
            if (a[k] != b[k] || a[k] != c[k])
               fprintf(stderr, "glut-glu: case %d element %d: libfixglut %a libGLU %a linked %a\n",
                       i, k, a[k], b[k], c[k]);
      }
   }
   if (glGetError() != GL_NO_ERROR) {
      fprintf(stderr, "glut-glu: a GL error\n");
      failures++;
   }
   printf("glut-glu: %d cases, %d differ\n", compared, failures);
   return failures ? 1 : 0;
}
