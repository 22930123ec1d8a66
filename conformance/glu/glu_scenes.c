/*
 * glu_scenes - Debian's libGLU over an OSMesa context: one source, built
 * twice, against fixgl (-lfixgl -lGLU) and against Mesa's OSMesa (-lOSMesa
 * -lGLU), the oracle.  run_glu.py compares the two outputs byte for byte.
 *
 *    glu-scenes --list                 the scene names, one a line
 *    glu-scenes SCENE OUTFILE          runs one scene, writes its records
 *
 * A scene draws into a 128x128 RGBA8 buffer with a 24-bit depth buffer
 * and writes records: "R name length\n" then the bytes.  Each drawn frame
 * gives its colour and depth (glReadPixels), the GL errors raised by the
 * scene (glGetError until GL_NO_ERROR), and what GLU returns to the
 * program (gluScaleImage's pixels, mipmap levels read back, gluProject /
 * gluUnProject results, the tessellator's callbacks, GLU error codes).
 */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 128
#define H 128

static FILE *out;
static unsigned char colour[W * H * 4];

static void record(const char *name, const void *data, size_t n)
{
   fprintf(out, "R %s %zu\n", name, n);
   fwrite(data, 1, n, out);
}

static void record_text(const char *name, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
#include <stdarg.h>
static void record_text(const char *name, const char *fmt, ...)
{
   char buf[512];
   va_list ap;
   va_start(ap, fmt);
   int n = vsnprintf(buf, sizeof buf, fmt, ap);
   va_end(ap);
   record(name, buf, (size_t)n);
}

static void record_errors(const char *name)
{
   GLenum errs[16];
   int n = 0;
   GLenum e;
   while (n < 16 && (e = glGetError()) != GL_NO_ERROR)
      errs[n++] = e;
   record(name, errs, n * sizeof errs[0]);
}

static void record_frame(const char *name)
{
   char label[128];
   static GLuint depth[W * H];
   glFinish();
   snprintf(label, sizeof label, "%s.rgba", name);
   record(label, colour, sizeof colour);
   glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
   snprintf(label, sizeof label, "%s.depth", name);
   record(label, depth, sizeof depth);
   snprintf(label, sizeof label, "%s.errors", name);
   record_errors(label);
}

/* ---- common state ---------------------------------------------------------- */

static void clear(void)
{
   glClearColor(0.1f, 0.12f, 0.15f, 1.0f);
   glClearDepth(1.0);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static void camera(void)
{
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluPerspective(40.0, 1.0, 1.0, 20.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   gluLookAt(0.4, 1.2, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

static void lights(void)
{
   static const GLfloat pos0[4] = {2.0f, 3.0f, 4.0f, 0.0f};
   static const GLfloat pos1[4] = {-3.0f, -1.0f, 2.0f, 1.0f};
   static const GLfloat dif1[4] = {0.3f, 0.4f, 0.9f, 1.0f};
   static const GLfloat spec[4] = {0.8f, 0.8f, 0.8f, 1.0f};
   glEnable(GL_LIGHTING);
   glEnable(GL_LIGHT0);
   glEnable(GL_LIGHT1);
   glLightfv(GL_LIGHT0, GL_POSITION, pos0);
   glLightfv(GL_LIGHT1, GL_POSITION, pos1);
   glLightfv(GL_LIGHT1, GL_DIFFUSE, dif1);
   glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
   glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
   glEnable(GL_COLOR_MATERIAL);
   glEnable(GL_DEPTH_TEST);
   glEnable(GL_NORMALIZE);
}

static GLuint checker_texture(void)
{
   static GLubyte img[32][32][3];
   GLuint t;
   for (int y = 0; y < 32; y++)
      for (int x = 0; x < 32; x++) {
         int on = ((x >> 2) ^ (y >> 2)) & 1;
         img[y][x][0] = (GLubyte)(on ? 240 : 30 + 5 * x);
         img[y][x][1] = (GLubyte)(on ? 200 : 7 * y);
         img[y][x][2] = (GLubyte)(on ? 40 : 220);
      }
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 32, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, img);
   glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
   return t;
}

/* ---- quadrics ---------------------------------------------------------------- */

/* gluSphere and gluCylinder, filled, smooth normals, texture coordinates */
static void scene_quadric_textured(void)
{
   camera();
   lights();
   clear();
   checker_texture();
   glEnable(GL_TEXTURE_2D);
   GLUquadric *q = gluNewQuadric();
   gluQuadricTexture(q, GL_TRUE);
   gluQuadricNormals(q, GLU_SMOOTH);
   glColor3f(0.9f, 0.9f, 0.9f);
   glPushMatrix();
   glTranslatef(-0.8f, 0.3f, 0.0f);
   glRotatef(70.0f, 1.0f, 0.2f, 0.0f);
   gluSphere(q, 0.8, 20, 14);
   glPopMatrix();
   glPushMatrix();
   glTranslatef(0.9f, -0.4f, 0.0f);
   glRotatef(-60.0f, 1.0f, 0.0f, 0.3f);
   gluCylinder(q, 0.5, 0.25, 1.3, 16, 4);
   gluDisk(q, 0.1, 0.5, 16, 3);
   glPopMatrix();
   gluDeleteQuadric(q);
   record_frame("quadric-textured");
}

/* flat normals, GLU_INSIDE orientation, a partial disk, back faces culled */
static void scene_quadric_flat_inside(void)
{
   camera();
   lights();
   clear();
   glEnable(GL_CULL_FACE);
   GLUquadric *q = gluNewQuadric();
   gluQuadricNormals(q, GLU_FLAT);
   gluQuadricOrientation(q, GLU_INSIDE);
   glColor3f(0.8f, 0.5f, 0.2f);
   glPushMatrix();
   glTranslatef(-0.7f, 0.5f, -0.5f);
   gluSphere(q, 1.0, 12, 8);
   glPopMatrix();
   gluQuadricOrientation(q, GLU_OUTSIDE);
   glColor3f(0.3f, 0.8f, 0.4f);
   glPushMatrix();
   glTranslatef(0.8f, -0.6f, 0.5f);
   glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
   gluPartialDisk(q, 0.2, 0.8, 14, 3, 30.0, 250.0);
   gluQuadricOrientation(q, GLU_INSIDE);
   gluQuadricTexture(q, GL_TRUE);
   gluCylinder(q, 0.6, 0.6, 0.8, 10, 2);
   glPopMatrix();
   gluDeleteQuadric(q);
   record_frame("quadric-flat-inside");
}

/* draw styles: GLU_LINE, GLU_SILHOUETTE, GLU_POINT, unlit */
static void scene_quadric_styles(void)
{
   camera();
   clear();
   glEnable(GL_DEPTH_TEST);
   glPointSize(2.0f);
   GLUquadric *q = gluNewQuadric();
   gluQuadricDrawStyle(q, GLU_LINE);
   glColor3f(1.0f, 1.0f, 0.3f);
   glPushMatrix();
   glTranslatef(-1.0f, 0.8f, 0.0f);
   gluSphere(q, 0.6, 10, 7);
   glPopMatrix();
   gluQuadricDrawStyle(q, GLU_SILHOUETTE);
   glColor3f(0.3f, 1.0f, 1.0f);
   glPushMatrix();
   glTranslatef(1.0f, 0.8f, 0.0f);
   gluDisk(q, 0.2, 0.6, 12, 3);
   gluPartialDisk(q, 0.65, 0.8, 12, 2, -45.0, 200.0);
   glRotatef(80.0f, 1.0f, 0.0f, 0.0f);
   gluCylinder(q, 0.3, 0.1, 0.5, 9, 2);
   glPopMatrix();
   gluQuadricDrawStyle(q, GLU_POINT);
   glColor3f(1.0f, 0.4f, 0.9f);
   glPushMatrix();
   glTranslatef(-0.9f, -0.9f, 0.0f);
   gluSphere(q, 0.6, 12, 8);
   glPopMatrix();
   gluQuadricDrawStyle(q, GLU_LINE);
   glColor3f(0.5f, 0.6f, 1.0f);
   glPushMatrix();
   glTranslatef(0.9f, -0.9f, 0.0f);
   glRotatef(60.0f, 1.0f, 0.0f, 0.0f);
   gluCylinder(q, 0.4, 0.4, 0.8, 8, 3);
   gluPartialDisk(q, 0.0, 0.4, 8, 2, 0.0, 360.0);
   glPopMatrix();
   gluDeleteQuadric(q);
   record_frame("quadric-styles");
}

/* ---- mipmaps and scaled images -------------------------------------------------- */

static void read_levels(const char *name, GLenum target, GLenum format, GLenum type, int bpp)
{
   char label[96];
   for (int level = 0; level < 16; level++) {
      GLint w = 0, h = 0;
      glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
      glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &h);
      if (w == 0)
         break;
      size_t n = (size_t)w * h * bpp;
      unsigned char *px = malloc(n);
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glGetTexImage(target, level, format, type, px);
      snprintf(label, sizeof label, "%s.level%d.%dx%d", name, level, w, h);
      record(label, px, n);
      free(px);
   }
}

static void draw_textured_quads(void)
{
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluOrtho2D(0.0, W, 0.0, H);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glEnable(GL_TEXTURE_2D);
   glColor3f(1.0f, 1.0f, 1.0f);
   /* a large quad, and smaller ones that select the smaller levels */
   static const float sizes[4] = {96.0f, 24.0f, 9.0f, 4.0f};
   float x = 2.0f;
   for (int i = 0; i < 4; i++) {
      float s = sizes[i], y = i == 0 ? 30.0f : 4.0f;
      if (i == 0)
         x = 30.0f;
      glBegin(GL_QUADS);
      glTexCoord2f(0.0f, 0.0f); glVertex2f(x, y);
      glTexCoord2f(1.0f, 0.0f); glVertex2f(x + s, y + 0.3f * s);
      glTexCoord2f(1.0f, 1.0f); glVertex2f(x + 0.8f * s, y + s);
      glTexCoord2f(0.0f, 1.0f); glVertex2f(x - 0.1f * s, y + 0.9f * s);
      glEnd();
      x = i == 0 ? 2.0f : x + s + 6.0f;
   }
}

/* gluBuild2DMipmaps of an NPOT RGB image (37x23), trilinear */
static void scene_mipmap2d_rgb(void)
{
   static GLubyte img[23][37][3];
   for (int y = 0; y < 23; y++)
      for (int x = 0; x < 37; x++) {
         img[y][x][0] = (GLubyte)(x * 7 + y);
         img[y][x][1] = (GLubyte)(((x / 3 + y / 2) & 1) ? 255 : 10);
         img[y][x][2] = (GLubyte)(y * 11);
      }
   clear();
   GLuint t;
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   GLint r = gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 37, 23, GL_RGB, GL_UNSIGNED_BYTE, img);
   record_text("mipmap2d-rgb.return", "%d", r);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
   read_levels("mipmap2d-rgb", GL_TEXTURE_2D, GL_RGB, GL_UNSIGNED_BYTE, 3);
   draw_textured_quads();
   record_frame("mipmap2d-rgb");
}

/* other formats and types: luminance-alpha shorts, RGBA floats, packed
 * 5_6_5 and 4_4_4_4, with an unpack alignment of 4 and odd widths */
static void scene_mipmap2d_types(void)
{
   static GLushort la[19][13][2];
   static GLfloat rgba[11][29][4];
   /* GL_UNPACK_ALIGNMENT 4: a row of 21 (5) shorts is 42 (10) bytes, padded
    * to 44 (12); the arrays hold the padding, which GL skips */
   static GLushort p565[9][22];
   static GLushort p4444[7][6];
   for (int y = 0; y < 19; y++)
      for (int x = 0; x < 13; x++) {
         la[y][x][0] = (GLushort)(x * 5000 + y * 300);
         la[y][x][1] = (GLushort)(65535 - y * 3000);
      }
   for (int y = 0; y < 11; y++)
      for (int x = 0; x < 29; x++) {
         rgba[y][x][0] = (float)x / 28.0f;
         rgba[y][x][1] = (float)((x ^ y) & 3) / 3.0f;
         rgba[y][x][2] = 0.37f;
         rgba[y][x][3] = (float)y / 10.0f;
      }
   for (int y = 0; y < 9; y++)
      for (int x = 0; x < 21; x++)
         p565[y][x] = (GLushort)((x * 3) << 11 | (y * 7) << 5 | ((x + y) & 31));
   for (int y = 0; y < 7; y++)
      for (int x = 0; x < 5; x++)
         p4444[y][x] = (GLushort)(x * 0x3000 + y * 0x0210 + 0x000f);
   clear();
   GLuint t[4];
   glGenTextures(4, t);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
   glBindTexture(GL_TEXTURE_2D, t[0]);
   record_text("mipmap2d-types.la.return", "%d",
               gluBuild2DMipmaps(GL_TEXTURE_2D, GL_LUMINANCE_ALPHA, 13, 19, GL_LUMINANCE_ALPHA,
                                 GL_UNSIGNED_SHORT, la));
   read_levels("mipmap2d-types.la", GL_TEXTURE_2D, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, 2);
   glBindTexture(GL_TEXTURE_2D, t[1]);
   record_text("mipmap2d-types.float.return", "%d",
               gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 29, 11, GL_RGBA, GL_FLOAT, rgba));
   read_levels("mipmap2d-types.float", GL_TEXTURE_2D, GL_RGBA, GL_UNSIGNED_BYTE, 4);
   glBindTexture(GL_TEXTURE_2D, t[2]);
   record_text("mipmap2d-types.565.return", "%d",
               gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 21, 9, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, p565));
   read_levels("mipmap2d-types.565", GL_TEXTURE_2D, GL_RGB, GL_UNSIGNED_BYTE, 3);
   glBindTexture(GL_TEXTURE_2D, t[3]);
   record_text("mipmap2d-types.4444.return", "%d",
               gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 5, 7, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, p4444));
   read_levels("mipmap2d-types.4444", GL_TEXTURE_2D, GL_RGBA, GL_UNSIGNED_BYTE, 4);
   /* GLU's own errors: a bad format, a negative width */
   record_text("mipmap2d-types.badenum", "%d",
               gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 4, 4, GL_RGBA, GL_DOUBLE, rgba));
   record_text("mipmap2d-types.badsize", "%d",
               gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, -4, 4, GL_RGBA, GL_UNSIGNED_BYTE, rgba));
   glBindTexture(GL_TEXTURE_2D, t[1]);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
   draw_textured_quads();
   record_frame("mipmap2d-types");
}

/* gluBuild1DMipmaps, drawn on a 1D-textured fan */
static void scene_mipmap1d(void)
{
   static GLubyte line[45][4];
   for (int x = 0; x < 45; x++) {
      line[x][0] = (GLubyte)(x * 5);
      line[x][1] = (GLubyte)((x & 4) ? 230 : 20);
      line[x][2] = (GLubyte)(255 - x * 5);
      line[x][3] = 255;
   }
   clear();
   GLuint t;
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_1D, t);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   record_text("mipmap1d.return", "%d",
               gluBuild1DMipmaps(GL_TEXTURE_1D, GL_RGBA, 45, GL_RGBA, GL_UNSIGNED_BYTE, line));
   read_levels("mipmap1d", GL_TEXTURE_1D, GL_RGBA, GL_UNSIGNED_BYTE, 4);
   glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluOrtho2D(-1.0, 1.0, -1.0, 1.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glEnable(GL_TEXTURE_1D);
   glBegin(GL_TRIANGLES);
   for (int i = 0; i < 12; i++) {
      double a0 = i * M_PI / 6.0, a1 = (i + 1) * M_PI / 6.0, r = 0.2 + 0.06 * i;
      glTexCoord1f(0.0f); glVertex2f(0.0f, 0.0f);
      glTexCoord1f((float)(i + 1) * 0.7f); glVertex2d(r * cos(a0), r * sin(a0));
      glTexCoord1f((float)(i + 2) * 0.7f); glVertex2d(r * cos(a1), r * sin(a1));
   }
   glEnd();
   record_frame("mipmap1d");
}

/* gluScaleImage up and down, several formats and types */
static void scene_scale_image(void)
{
   static GLubyte rgb[17][23][3];
   static GLfloat lum[5][7];
   static GLushort rgba[13][6][4];
   static GLubyte outb[64 * 64 * 4];
   static GLfloat outf[64 * 64];
   static GLushort outs[64 * 64 * 4];
   for (int y = 0; y < 17; y++)
      for (int x = 0; x < 23; x++) {
         rgb[y][x][0] = (GLubyte)(x * 11);
         rgb[y][x][1] = (GLubyte)(y * 15);
         rgb[y][x][2] = (GLubyte)((x * y) & 255);
      }
   for (int y = 0; y < 5; y++)
      for (int x = 0; x < 7; x++)
         lum[y][x] = (float)(x * x + y) / 40.0f;
   for (int y = 0; y < 13; y++)
      for (int x = 0; x < 6; x++)
         for (int c = 0; c < 4; c++)
            rgba[y][x][c] = (GLushort)(x * 9000 + y * 4000 + c * 1234);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   int r = gluScaleImage(GL_RGB, 23, 17, GL_UNSIGNED_BYTE, rgb, 10, 7, GL_UNSIGNED_BYTE, outb);
   record_text("scale.rgb-down.return", "%d", r);
   record("scale.rgb-down", outb, 10 * 7 * 3);
   r = gluScaleImage(GL_RGB, 23, 17, GL_UNSIGNED_BYTE, rgb, 61, 40, GL_UNSIGNED_BYTE, outb);
   record_text("scale.rgb-up.return", "%d", r);
   record("scale.rgb-up", outb, 61 * 40 * 3);
   r = gluScaleImage(GL_LUMINANCE, 7, 5, GL_FLOAT, lum, 30, 3, GL_FLOAT, outf);
   record_text("scale.lum-float.return", "%d", r);
   record("scale.lum-float", outf, 30 * 3 * sizeof(GLfloat));
   r = gluScaleImage(GL_RGBA, 6, 13, GL_UNSIGNED_SHORT, rgba, 11, 4, GL_UNSIGNED_BYTE, outb);
   record_text("scale.rgba-short.return", "%d", r);
   record("scale.rgba-short", outb, 11 * 4 * 4);
   r = gluScaleImage(GL_RGBA, 6, 13, GL_UNSIGNED_SHORT, rgba, 6, 13, GL_UNSIGNED_SHORT, outs);
   record_text("scale.rgba-same.return", "%d", r);
   record("scale.rgba-same", outs, 6 * 13 * 4 * sizeof(GLushort));
   r = gluScaleImage(GL_RGB, 23, 17, GL_DOUBLE, rgb, 10, 7, GL_UNSIGNED_BYTE, outb);
   record_text("scale.bad.return", "%d %s", r, (const char *)gluErrorString((GLenum)r));
   /* the up-scaled image drawn */
   clear();
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluOrtho2D(0.0, W, 0.0, H);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   gluScaleImage(GL_RGB, 23, 17, GL_UNSIGNED_BYTE, rgb, 61, 40, GL_UNSIGNED_BYTE, outb);
   glRasterPos2i(5, 70);
   glDrawPixels(61, 40, GL_RGB, GL_UNSIGNED_BYTE, outb);
   glRasterPos2i(70, 10);
   glPixelZoom(2.0f, 3.0f);
   glDrawPixels(30, 3, GL_LUMINANCE, GL_FLOAT, outf);
   record_frame("scale");
}

/* ---- matrices ---------------------------------------------------------------- */

static void scene_matrices(void)
{
   GLdouble mv[16], pr[16], wx, wy, wz, ox, oy, oz;
   GLint vp[4];
   char text[2048];
   int n = 0;
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluPerspective(53.0, 1.3, 0.7, 31.0);
   glGetDoublev(GL_PROJECTION_MATRIX, pr);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   gluLookAt(1.5, -2.25, 6.0, 0.1, 0.3, -0.2, 0.1, 1.0, 0.05);
   glRotated(17.0, 0.3, 0.4, 0.5);
   glGetDoublev(GL_MODELVIEW_MATRIX, mv);
   glGetIntegerv(GL_VIEWPORT, vp);
   record("matrices.perspective", pr, sizeof pr);
   record("matrices.lookat", mv, sizeof mv);
   for (int i = 0; i < 6; i++) {
      double p[3] = {0.3 * i - 0.7, 0.11 * i * i - 0.5, 0.25 * i - 1.0};
      int r1 = gluProject(p[0], p[1], p[2], mv, pr, vp, &wx, &wy, &wz);
      int r2 = gluUnProject(wx, wy, wz, mv, pr, vp, &ox, &oy, &oz);
      n += snprintf(text + n, sizeof text - n, "%d %a %a %a %d %a %a %a\n",
                    r1, wx, wy, wz, r2, ox, oy, oz);
   }
   record("matrices.project", text, (size_t)n);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluOrtho2D(-2.0, 3.0, -1.5, 2.5);
   glGetDoublev(GL_PROJECTION_MATRIX, pr);
   record("matrices.ortho2d", pr, sizeof pr);
   /* the same matrices drawing a frame */
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluPerspective(53.0, 1.3, 0.7, 31.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   gluLookAt(1.5, -2.25, 6.0, 0.1, 0.3, -0.2, 0.1, 1.0, 0.05);
   clear();
   lights();
   GLUquadric *q = gluNewQuadric();
   glColor3f(0.7f, 0.7f, 0.2f);
   gluSphere(q, 1.1, 18, 12);
   gluDeleteQuadric(q);
   record_frame("matrices");
}

/* ---- the tessellator ------------------------------------------------------------ */

static char trace[1 << 16];
static int trace_n;
static GLdouble combined[256][6];
static int num_combined;

static void GLAPIENTRY tess_begin(GLenum type)
{
   trace_n += snprintf(trace + trace_n, sizeof trace - trace_n, "begin %#x\n", type);
   glBegin(type);
}

static void GLAPIENTRY tess_vertex(void *data)
{
   const GLdouble *v = data;
   trace_n += snprintf(trace + trace_n, sizeof trace - trace_n, "v %a %a\n", v[0], v[1]);
   glColor3dv(v + 3);
   glVertex3dv(v);
}

static void GLAPIENTRY tess_end(void)
{
   trace_n += snprintf(trace + trace_n, sizeof trace - trace_n, "end\n");
   glEnd();
}

static void GLAPIENTRY tess_edge(GLboolean flag)
{
   trace_n += snprintf(trace + trace_n, sizeof trace - trace_n, "edge %d\n", flag);
   glEdgeFlag(flag);
}

/* interpolates position and colour of the new vertex */
static void GLAPIENTRY tess_combine(GLdouble coords[3], void *data[4], GLfloat weight[4], void **out_data)
{
   GLdouble *v = combined[num_combined++ & 255];
   v[0] = coords[0];
   v[1] = coords[1];
   v[2] = coords[2];
   for (int c = 3; c < 6; c++) {
      v[c] = 0.0;
      for (int i = 0; i < 4; i++)
         if (data[i])
            v[c] += weight[i] * ((GLdouble *)data[i])[c];
   }
   trace_n += snprintf(trace + trace_n, sizeof trace - trace_n, "combine %a %a\n", v[0], v[1]);
   *out_data = v;
}

static void GLAPIENTRY tess_error(GLenum err)
{
   trace_n += snprintf(trace + trace_n, sizeof trace - trace_n, "error %#x\n", err);
}

static GLUtesselator *new_tess(void)
{
   GLUtesselator *t = gluNewTess();
   gluTessCallback(t, GLU_TESS_BEGIN, (void (GLAPIENTRY *)(void))tess_begin);
   gluTessCallback(t, GLU_TESS_VERTEX, (void (GLAPIENTRY *)(void))tess_vertex);
   gluTessCallback(t, GLU_TESS_END, (void (GLAPIENTRY *)(void))tess_end);
   gluTessCallback(t, GLU_TESS_COMBINE, (void (GLAPIENTRY *)(void))tess_combine);
   gluTessCallback(t, GLU_TESS_ERROR, (void (GLAPIENTRY *)(void))tess_error);
   gluTessNormal(t, 0.0, 0.0, 1.0);
   return t;
}

/* a concave outline, a hole, and an overlapping square: each contour's
 * vertices are x, y, z, r, g, b */
static GLdouble outline[8][6] = {
   {-0.9, -0.9, 0, 1, 0.2, 0.2}, {0.9, -0.9, 0, 0.2, 1, 0.2}, {0.9, 0.9, 0, 0.2, 0.2, 1},
   {0.1, 0.9, 0, 1, 1, 0.2},     {0.0, 0.0, 0, 1, 0.2, 1},    {-0.1, 0.9, 0, 0.2, 1, 1},
   {-0.9, 0.9, 0, 1, 1, 1},      {-0.6, 0.2, 0, 0.5, 0.5, 0.5},
};
static GLdouble hole[4][6] = {
   {-0.5, -0.6, 0, 0, 0, 1}, {-0.5, -0.1, 0, 0, 1, 0}, {0.5, -0.1, 0, 1, 0, 0}, {0.5, -0.6, 0, 1, 1, 0},
};
static GLdouble square[4][6] = {
   {-0.3, -0.8, 0, 1, 0.5, 0}, {0.7, -0.8, 0, 0, 0.5, 1}, {0.7, 0.3, 0, 0.5, 1, 0}, {-0.3, 0.3, 0, 1, 0, 0.5},
};

static void tess_shapes(GLUtesselator *t)
{
   gluTessBeginPolygon(t, NULL);
   gluTessBeginContour(t);
   for (int i = 0; i < 8; i++)
      gluTessVertex(t, outline[i], outline[i]);
   gluTessEndContour(t);
   gluTessBeginContour(t);
   for (int i = 0; i < 4; i++)
      gluTessVertex(t, hole[i], hole[i]);
   gluTessEndContour(t);
   gluTessBeginContour(t);
   for (int i = 0; i < 4; i++)
      gluTessVertex(t, square[i], square[i]);
   gluTessEndContour(t);
   gluTessEndPolygon(t);
}

static void ortho_grid_cell(int i)
{
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluOrtho2D(-1.0, 1.0, -1.0, 1.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glTranslated(-2.0 / 3.0 + (i % 3) * (2.0 / 3.0), 0.5 - (i / 3) * 1.0, 0.0);
   glScaled(0.32, 0.48, 1.0);
}

/* every winding rule, with the combine callback */
static void scene_tess_winding(void)
{
   static const GLenum rules[5] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO,
                                   GLU_TESS_WINDING_POSITIVE, GLU_TESS_WINDING_NEGATIVE,
                                   GLU_TESS_WINDING_ABS_GEQ_TWO};
   clear();
   GLUtesselator *t = new_tess();
   trace_n = 0;
   for (int i = 0; i < 5; i++) {
      ortho_grid_cell(i);
      gluTessProperty(t, GLU_TESS_WINDING_RULE, rules[i]);
      tess_shapes(t);
   }
   /* an edge-flag callback forces independent triangles; drawn as lines */
   gluTessCallback(t, GLU_TESS_EDGE_FLAG, (void (GLAPIENTRY *)(void))tess_edge);
   gluTessProperty(t, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
   ortho_grid_cell(5);
   glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
   tess_shapes(t);
   glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
   gluDeleteTess(t);
   record("tess-winding.trace", trace, (size_t)trace_n);
   record_frame("tess-winding");
}

/* a self-intersecting star: the combine callback's new vertices */
static void scene_tess_combine(void)
{
   static GLdouble star[5][6];
   clear();
   for (int i = 0; i < 5; i++) {
      double a = M_PI / 2.0 + i * 4.0 * M_PI / 5.0;
      star[i][0] = 0.9 * cos(a);
      star[i][1] = 0.9 * sin(a);
      star[i][2] = 0.0;
      star[i][3] = i & 1 ? 1.0 : 0.1;
      star[i][4] = i * 0.25;
      star[i][5] = 1.0 - i * 0.2;
   }
   GLUtesselator *t = new_tess();
   trace_n = 0;
   num_combined = 0;
   static const GLenum rules[2] = {GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_ODD};
   for (int k = 0; k < 2; k++) {
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      gluOrtho2D(-1.0, 1.0, -1.0, 1.0);
      glMatrixMode(GL_MODELVIEW);
      glLoadIdentity();
      glTranslated(k ? 0.5 : -0.5, 0.0, 0.0);
      glScaled(0.48, 0.9, 1.0);
      gluTessProperty(t, GLU_TESS_WINDING_RULE, rules[k]);
      gluTessBeginPolygon(t, NULL);
      gluTessBeginContour(t);
      for (int i = 0; i < 5; i++)
         gluTessVertex(t, star[i], star[i]);
      gluTessEndContour(t);
      gluTessEndPolygon(t);
   }
   gluDeleteTess(t);
   record_text("tess-combine.count", "%d", num_combined);
   record("tess-combine.trace", trace, (size_t)trace_n);
   record_frame("tess-combine");
}

/* GLU_TESS_BOUNDARY_ONLY: the boundary drawn as line loops */
static void scene_tess_boundary(void)
{
   clear();
   GLUtesselator *t = new_tess();
   trace_n = 0;
   gluTessProperty(t, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
   static const GLenum rules[3] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_POSITIVE,
                                   GLU_TESS_WINDING_ABS_GEQ_TWO};
   for (int i = 0; i < 3; i++) {
      ortho_grid_cell(i + (i > 1 ? 1 : 0));
      gluTessProperty(t, GLU_TESS_WINDING_RULE, rules[i]);
      tess_shapes(t);
   }
   /* the tolerance property read back, and an error: a bad property */
   GLdouble v = -1.0;
   gluGetTessProperty(t, GLU_TESS_BOUNDARY_ONLY, &v);
   gluTessProperty(t, GLU_TESS_WINDING_RULE, 12345.0);
   gluDeleteTess(t);
   record_text("tess-boundary.property", "%g", v);
   record("tess-boundary.trace", trace, (size_t)trace_n);
   record_frame("tess-boundary");
}

/* ---- NURBS -------------------------------------------------------------------- */

static GLfloat surf_ctl[4][4][3];
static GLfloat surf_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};

static void init_surface(void)
{
   for (int u = 0; u < 4; u++)
      for (int v = 0; v < 4; v++) {
         surf_ctl[u][v][0] = 2.0f * ((GLfloat)u - 1.5f) / 1.5f;
         surf_ctl[u][v][1] = 2.0f * ((GLfloat)v - 1.5f) / 1.5f;
         surf_ctl[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 2.5f : -1.5f;
      }
}

static void nurbs_camera(void)
{
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluPerspective(45.0, 1.0, 3.0, 12.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glTranslatef(0.0f, 0.0f, -7.0f);
   glRotatef(-55.0f, 1.0f, 0.0f, 0.0f);
   glRotatef(25.0f, 0.0f, 0.0f, 1.0f);
}

static void GLAPIENTRY nurbs_error(GLenum err)
{
   trace_n += snprintf(trace + trace_n, sizeof trace - trace_n, "nurbs error %#x\n", err);
}

static GLUnurbs *new_nurbs(void)
{
   GLUnurbs *n = gluNewNurbsRenderer();
   gluNurbsCallback(n, GLU_ERROR, (void (GLAPIENTRY *)(void))nurbs_error);
   return n;
}

/* a lit surface, GLU_SAMPLING_TOLERANCE, then GLU_DOMAIN_DISTANCE */
static void scene_nurbs_surface(void)
{
   init_surface();
   nurbs_camera();
   clear();
   lights();
   glEnable(GL_AUTO_NORMAL);
   trace_n = 0;
   GLUnurbs *n = new_nurbs();
   gluNurbsProperty(n, GLU_SAMPLING_METHOD, GLU_PATH_LENGTH);
   gluNurbsProperty(n, GLU_SAMPLING_TOLERANCE, 25.0f);
   gluNurbsProperty(n, GLU_DISPLAY_MODE, GLU_FILL);
   glColor3f(0.8f, 0.6f, 0.3f);
   glPushMatrix();
   glTranslatef(-1.0f, 0.0f, 0.0f);
   glScalef(0.5f, 0.5f, 0.5f);
   gluBeginSurface(n);
   gluNurbsSurface(n, 8, surf_knots, 8, surf_knots, 4 * 3, 3, &surf_ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
   gluEndSurface(n);
   glPopMatrix();
   gluNurbsProperty(n, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
   gluNurbsProperty(n, GLU_U_STEP, 7.0f);
   gluNurbsProperty(n, GLU_V_STEP, 5.0f);
   glColor3f(0.3f, 0.6f, 0.9f);
   glPushMatrix();
   glTranslatef(1.1f, 0.0f, 0.0f);
   glScalef(0.5f, 0.5f, 0.5f);
   gluBeginSurface(n);
   gluNurbsSurface(n, 8, surf_knots, 8, surf_knots, 4 * 3, 3, &surf_ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
   gluEndSurface(n);
   glPopMatrix();
   GLfloat v = 0.0f;
   gluGetNurbsProperty(n, GLU_SAMPLING_TOLERANCE, &v);
   gluDeleteNurbsRenderer(n);
   record_text("nurbs-surface.tolerance", "%a", v);
   record("nurbs-surface.trace", trace, (size_t)trace_n);
   record_frame("nurbs-surface");
}

/* a surface trimmed by a piecewise-linear outer loop and a NURBS hole;
 * GLU_OUTLINE_POLYGON and GLU_OUTLINE_PATCH beside the filled one */
static void scene_nurbs_trim(void)
{
   static GLfloat edge[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
   static GLfloat curve_pts[4][2] = {{0.25f, 0.5f}, {0.25f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.5f}};
   static GLfloat curve_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
   static GLfloat pwl[3][2] = {{0.75f, 0.5f}, {0.5f, 0.25f}, {0.25f, 0.5f}};
   static const GLfloat modes[3] = {GLU_FILL, GLU_OUTLINE_POLYGON, GLU_OUTLINE_PATCH};
   init_surface();
   clear();
   trace_n = 0;
   GLUnurbs *n = new_nurbs();
   gluNurbsProperty(n, GLU_SAMPLING_TOLERANCE, 40.0f);
   for (int m = 0; m < 3; m++) {
      nurbs_camera();
      glTranslatef(-1.4f + 1.4f * m, 0.6f * (m - 1), 0.0f);
      glScalef(0.45f, 0.45f, 0.45f);
      if (m == 0) {
         lights();
         glEnable(GL_AUTO_NORMAL);
      } else {
         glDisable(GL_LIGHTING);
      }
      glColor3f(0.9f, 0.4f + 0.2f * m, 0.3f);
      gluNurbsProperty(n, GLU_DISPLAY_MODE, modes[m]);
      gluBeginSurface(n);
      gluNurbsSurface(n, 8, surf_knots, 8, surf_knots, 4 * 3, 3, &surf_ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
      gluBeginTrim(n);
      gluPwlCurve(n, 5, &edge[0][0], 2, GLU_MAP1_TRIM_2);
      gluEndTrim(n);
      gluBeginTrim(n);
      gluNurbsCurve(n, 8, curve_knots, 2, &curve_pts[0][0], 4, GLU_MAP1_TRIM_2);
      gluPwlCurve(n, 3, &pwl[0][0], 2, GLU_MAP1_TRIM_2);
      gluEndTrim(n);
      gluEndSurface(n);
   }
   gluDeleteNurbsRenderer(n);
   record("nurbs-trim.trace", trace, (size_t)trace_n);
   record_frame("nurbs-trim");
}

/* gluNurbsCurve: a cubic and a rational (homogeneous) curve, and an error:
 * a knot vector too short */
static void scene_nurbs_curve(void)
{
   static GLfloat ctl[6][3] = {{-1.5f, -1.0f, 0}, {-1.0f, 1.5f, 0}, {-0.2f, -1.2f, 0},
                               {0.4f, 1.4f, 0},   {1.0f, -0.8f, 0}, {1.6f, 0.9f, 0}};
   static GLfloat knots[10] = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3};
   static GLfloat rat[3][4] = {{1.0f, 0.0f, 0.0f, 1.0f}, {0.7071f, 0.7071f, 0.0f, 0.7071f}, {0.0f, 1.0f, 0.0f, 1.0f}};
   static GLfloat rknots[6] = {0, 0, 0, 1, 1, 1};
   clear();
   trace_n = 0;
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   gluOrtho2D(-2.0, 2.0, -2.0, 2.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   GLUnurbs *n = new_nurbs();
   gluNurbsProperty(n, GLU_SAMPLING_TOLERANCE, 5.0f);
   glLineWidth(2.0f);
   glColor3f(1.0f, 0.8f, 0.2f);
   gluBeginCurve(n);
   gluNurbsCurve(n, 10, knots, 3, &ctl[0][0], 4, GL_MAP1_VERTEX_3);
   gluEndCurve(n);
   glColor3f(0.2f, 0.9f, 1.0f);
   glLineWidth(1.0f);
   glTranslatef(-0.5f, -1.5f, 0.0f);
   gluBeginCurve(n);
   gluNurbsCurve(n, 6, rknots, 4, &rat[0][0], 3, GL_MAP1_VERTEX_4);
   gluEndCurve(n);
   gluBeginCurve(n);
   gluNurbsCurve(n, 3, knots, 3, &ctl[0][0], 4, GL_MAP1_VERTEX_3);
   gluEndCurve(n);
   gluDeleteNurbsRenderer(n);
   record("nurbs-curve.trace", trace, (size_t)trace_n);
   record_frame("nurbs-curve");
}

/* ---- GL errors raised through GLU ------------------------------------------------ */

/* GLU passes bad targets and formats on to GL, and draws inside a
 * glBegin/glEnd the program left open: the GL errors (and what is drawn
 * regardless) must be the oracle's */
static void scene_gl_errors(void)
{
   static GLubyte img[6][5][4];
   char text[256];
   int n = 0;
   memset(img, 200, sizeof img);
   camera();
   clear();
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   /* a 3D target: glTexImage2D's GL_INVALID_ENUM */
   n += snprintf(text + n, sizeof text - n, "%d ",
                 gluBuild2DMipmaps(GL_TEXTURE_3D, GL_RGBA, 5, 6, GL_RGBA, GL_UNSIGNED_BYTE, img));
   record_errors("gl-errors.target");
   /* an internal format GL refuses: GL_INVALID_VALUE */
   n += snprintf(text + n, sizeof text - n, "%d ",
                 gluBuild2DMipmaps(GL_TEXTURE_2D, 7, 5, 6, GL_RGBA, GL_UNSIGNED_BYTE, img));
   record_errors("gl-errors.internalformat");
   /* a level-count GLU accepts for a 1D texture bound as 2D */
   n += snprintf(text + n, sizeof text - n, "%d ",
                 gluBuild1DMipmaps(GL_TEXTURE_2D, GL_RGBA, 5, GL_RGBA, GL_UNSIGNED_BYTE, img));
   record_errors("gl-errors.target1d");
   record("gl-errors.returns", text, (size_t)n);
   /* a quadric inside glBegin: GLU's own glBegin is GL_INVALID_OPERATION */
   GLUquadric *q = gluNewQuadric();
   glColor3f(0.9f, 0.3f, 0.3f);
   glBegin(GL_TRIANGLES);
   glVertex3f(-1.0f, -1.0f, 0.0f);
   gluDisk(q, 0.0, 0.5, 8, 1);
   glVertex3f(1.0f, -1.0f, 0.0f);
   glVertex3f(0.0f, 1.0f, 0.0f);
   glEnd();
   record_errors("gl-errors.nested");
   gluSphere(q, 0.6, 10, 8);
   gluDeleteQuadric(q);
   /* gluLookAt and gluPerspective inside glBegin/glEnd */
   glBegin(GL_POINTS);
   gluPerspective(30.0, 1.0, 1.0, 10.0);
   gluLookAt(0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
   glEnd();
   record_frame("gl-errors");
}

/* ---- the table -------------------------------------------------------------- */

static const struct {
   const char *name;
   void (*draw)(void);
} scenes[] = {
   {"quadric-textured", scene_quadric_textured},
   {"quadric-flat-inside", scene_quadric_flat_inside},
   {"quadric-styles", scene_quadric_styles},
   {"mipmap2d-rgb", scene_mipmap2d_rgb},
   {"mipmap2d-types", scene_mipmap2d_types},
   {"mipmap1d", scene_mipmap1d},
   {"scale-image", scene_scale_image},
   {"matrices", scene_matrices},
   {"tess-winding", scene_tess_winding},
   {"tess-combine", scene_tess_combine},
   {"tess-boundary", scene_tess_boundary},
   {"nurbs-surface", scene_nurbs_surface},
   {"nurbs-trim", scene_nurbs_trim},
   {"nurbs-curve", scene_nurbs_curve},
   {"gl-errors", scene_gl_errors},
};

int main(int argc, char **argv)
{
   const int n = (int)(sizeof scenes / sizeof scenes[0]);
   if (argc == 2 && strcmp(argv[1], "--list") == 0) {
      for (int i = 0; i < n; i++)
         puts(scenes[i].name);
      return 0;
   }
   if (argc != 3) {
      fprintf(stderr, "usage: %s --list | SCENE OUTFILE\n", argv[0]);
      return 2;
   }
   for (int i = 0; i < n; i++) {
      if (strcmp(argv[1], scenes[i].name) != 0)
         continue;
      OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
      if (!ctx || !OSMesaMakeCurrent(ctx, colour, GL_UNSIGNED_BYTE, W, H)) {
         fprintf(stderr, "%s: cannot create an OSMesa context\n", argv[0]);
         return 1;
      }
      out = fopen(argv[2], "wb");
      if (!out) {
         perror(argv[2]);
         return 1;
      }
      scenes[i].draw();
      if (fclose(out) != 0) {
         perror(argv[2]);
         return 1;
      }
      OSMesaDestroyContext(ctx);
      return 0;
   }
   fprintf(stderr, "%s: no scene %s\n", argv[0], argv[1]);
   return 2;
}
