/* p_sprites.c - point sprites (ORACLE-NOTES.md "Point sprites"): with
 * GL_POINT_SPRITE on, a point is llvmpipe's square of sub-pixel edges
 * (fw = max(256, iround(size*256)), corner iround((x - 0.5)*256) - fw/2,
 * y alike; the pixels whose centres lie in [x0, x0 + fw) x (y0, y0 + fw]
 * of the y-down buffer), and a unit's GL_COORD_REPLACE coordinate is
 * (s, t, 0, 1) from planes over it, premultiplied by the vertex 1/w:
 * s = 0.5 + 256/fw * (px - (x - 0.5)), t the same down the buffer for
 * GL_UPPER_LEFT (up for GL_LOWER_LEFT), evaluated with two fused ops and
 * divided by the interpolated 1/w; GL_POINT_SMOOTH is ignored and the
 * fade threshold changes nothing; attenuated sizes are fractional.
 * Lines and triangles drawn with GL_POINT_SPRITE on read a replaced
 * unit's coordinates as (0, 0, 0, 0), given or generated (texgen), under
 * every wrap and filter: the same image as those coordinates given
 * explicitly with sprites off, and not the image of their own. */
#include "probe.h"

/* the covered pixels of a sprite, y-down, inclusive */
struct box {
   int x0, x1, y0, y1, fw;
};

static struct box sprite_box(float gx, float gy, float size)
{
   struct box b;
   if (size > 255.0f)
      size = 255.0f;
   b.fw = snap_iround(size);
   if (b.fw < 256)
      b.fw = 256;
   const int X0 = snap_iround(gx - 0.5f) - b.fw / 2, Y0 = snap_iround(gy - 0.5f) - b.fw / 2;
   const int X1 = X0 + b.fw, Y1 = Y0 + b.fw;
   b.x0 = (X0 + 255) >> 8;
   b.x1 = ((X1 + 255) >> 8) - 1;
   b.y0 = (Y0 >> 8) + 1;
   b.y1 = Y1 >> 8;
   return b;
}

/* window position of a clip-space vertex (x, y, 0, w) under identity
 * matrices and the viewport (0, 0, W, H): the fused viewport transform */
static void win_from_clip(float x, float y, float w, int Wd, int Hd, float *gx, float *gy,
                          float *oow)
{
   *oow = 1.0f / w;
   const float sx = 0.5f * (float)Wd, tx = 0.5f * (float)Wd + 0.0f;
   const float sy = -(0.5f * (float)Hd), ty = (float)Hd - (0.5f * (float)Hd + 0.0f);
   *gx = fmaf(x * *oow, sx, tx);
   *gy = fmaf(y * *oow, sy, ty);
}

/* texcoord_coef's plane of channel c, premultiplied by w0 */
static void coord_plane(int c, float gx, float gy, float w0, int fw, int lower, float r[3])
{
   const float xo = gx - 0.5f, yo = gy - 0.5f;
   float dadx = 0.0f, dady = 0.0f, a0;
   if (c == 0) {
      dadx = 256.0f / (float)fw;
      a0 = (float)(0.5 - (double)(dadx * xo + dady * yo));
   } else if (c == 1) {
      dady = 256.0f / (float)fw;
      if (lower)
         dady = -dady;
      a0 = (float)(0.5 - (double)(dadx * xo + dady * yo));
   } else {
      r[0] = c == 2 ? 0.0f : w0;
      r[1] = r[2] = 0.0f;
      return;
   }
   r[0] = a0 * w0;
   r[1] = dadx * w0;
   r[2] = dady * w0;
}

static float bits_equal(float a, float b)
{
   return memcmp(&a, &b, sizeof a) == 0;
}

/* sizes: the task's corners and random fractional ones */
static float pick_size(int i)
{
   static const float fixed[] = { 1.0f, 1.5f, 2.0f, 7.3f, 64.0f, 0.4f, 3.0f, 2.5f, 4.75f, 17.0f };
   if (i % 3 != 2)
      return fixed[(i / 3) % 10];
   return 0.2f + (float)(rand() % 4000) / 100.0f;
}

/* a coordinate on a pixel centre, a pixel edge, the 1/16 grid or anywhere */
static float pick_coord(int lo, int hi, int kind)
{
   const int n = lo + rand() % (hi - lo);
   switch (kind & 3) {
   case 0: return (float)n + 0.5f;
   case 1: return (float)n;
   case 2: return (float)n + (float)(rand() % 16) / 16.0f;
   default: return (float)n + (float)rand() / (float)RAND_MAX;
   }
}

/* coverage and the replaced coordinate of unit 0, written out by an ARB
 * fragment program into a float buffer: `persp` draws in clip space with
 * w in [0.5, 4.5) */
static void coords(int persp, int lower, long *n, long *bad_cover, long *bad_coord)
{
   enum { W = 72, H = 72 };
   static float buf[W * H * 4];
   probe_init_float(buf, W, H);
   const char *fp = "!!ARBfp1.0\nMOV result.color, fragment.texcoord[0];\nEND\n";
   GLuint id;
   glGenProgramsARB(1, &id);
   glBindProgramARB(GL_FRAGMENT_PROGRAM_ARB, id);
   glProgramStringARB(GL_FRAGMENT_PROGRAM_ARB, GL_PROGRAM_FORMAT_ASCII_ARB, (GLsizei)strlen(fp), fp);
   glEnable(GL_FRAGMENT_PROGRAM_ARB);
   glEnable(GL_POINT_SPRITE);
   glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
   glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, lower ? GL_LOWER_LEFT : GL_UPPER_LEFT);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   srand(11 + persp * 2 + lower);
   for (int iter = 0; iter < 150; iter++) {
      const float size = pick_size(iter);
      const float w = persp ? 0.5f + (float)(rand() % 400) / 100.0f : 1.0f;
      /* a centre in the window, then back to clip space */
      const float wx = pick_coord(4, W - 4, iter), wy = pick_coord(4, H - 4, iter >> 2);
      const float cx = (wx / (0.5f * W) - 1.0f) * w, cy = (wy / (0.5f * H) - 1.0f) * w;
      float gx, gy, oow;
      win_from_clip(cx, cy, w, W, H, &gx, &gy, &oow);
      glPointSize(size);
      glClearColor(-7, -7, -7, -7);
      glClear(GL_COLOR_BUFFER_BIT);
      glBegin(GL_POINTS);
      glTexCoord4f(9, 9, 9, 9);
      glVertex4f(cx, cy, 0.0f, w);
      glEnd();
      glFinish();
      const struct box b = sprite_box(gx, gy, size);
      float pl[4][3];
      for (int c = 0; c < 4; c++)
         coord_plane(c, gx, gy, oow, b.fw, lower, pl[c]);
      for (int py = 0; py < H; py++)
         for (int x = 0; x < W; x++) {
            const float *p = buf + 4 * ((H - 1 - py) * W + x);
            const int in = x >= b.x0 && x <= b.x1 && py >= b.y0 && py <= b.y1;
            const int got = p[0] != -7.0f;
            (*n)++;
            if (in != got) {
               (*bad_cover)++;
               continue;
            }
            if (!in)
               continue;
            const float ww = fmaf(0.0f, (float)py, fmaf(0.0f, (float)x, oow));
            for (int c = 0; c < 4; c++) {
               const float want = plane_eval(pl[c], x, py) * (1.0f / ww);
               if (!bits_equal(p[c], want))
                  (*bad_coord)++;
            }
         }
   }
   glDisable(GL_FRAGMENT_PROGRAM_ARB);
   glDeleteProgramsARB(1, &id);
   OSMesaDestroyContext(g_ctx);
}

/* coverage, colour and alpha of untextured sprites in an RGBA8 buffer:
 * smooth on or off, a fade threshold above the size, attenuated sizes */
static void plain(long *n, long *bad)
{
   enum { S = 64 };
   probe_init_ub(S, S);
   glEnable(GL_POINT_SPRITE);
   srand(5);
   for (int iter = 0; iter < 300; iter++) {
      const int atten = iter % 3 == 2;
      float size = pick_size(iter);
      const float x = pick_coord(3, S - 3, iter), y = pick_coord(3, S - 3, iter >> 2);
      const float d = 0.5f + (float)(rand() % 4000) / 100.0f;
      const float a[3] = { 0.2f + (float)(rand() % 100) / 50.0f, (float)(rand() % 100) / 200.0f,
                           (float)(rand() % 100) / 4000.0f };
      if (atten) {
         glMatrixMode(GL_PROJECTION);
         glLoadIdentity();
         glOrtho(0, S, 0, S, 0.1, 1000);
         glMatrixMode(GL_MODELVIEW);
         glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, a);
         glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
         glPointParameterf(GL_POINT_SIZE_MAX, 60.0f);
      } else {
         const float none[3] = { 1, 0, 0 };
         glMatrixMode(GL_PROJECTION);
         glLoadIdentity();
         glOrtho(0, S, 0, S, -1, 1);
         glMatrixMode(GL_MODELVIEW);
         glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
         glPointParameterf(GL_POINT_SIZE_MAX, 255.0f);
      }
      if (iter & 1)
         glEnable(GL_POINT_SMOOTH);
      else
         glDisable(GL_POINT_SMOOTH);
      glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, (iter & 2) ? 100.0f : 1.0f);
      glPointSize(size);
      clear0();
      glColor4f(1.0f, 0.5f, 0.25f, 0.5f);
      glBegin(GL_POINTS);
      glVertex3f(x, y, atten ? -d : 0.0f);
      glEnd();
      glFinish();
      if (atten) {
         float t = d * a[2] + a[1];
         t = d * t + a[0];
         float s = (1.0f / sqrtf(fabsf(t))) * size;
         s = s > 1.0f ? s : 1.0f;
         size = s < 60.0f ? s : 60.0f;
      }
      /* the window position under glOrtho (z does not enter x, y) */
      float gx, gy;
      win_from_ortho(x, y, S, S, &gx, &gy);
      const struct box b = sprite_box(gx, gy, size);
      for (int py = 0; py < S; py++)
         for (int px2 = 0; px2 < S; px2++) {
            const unsigned char *p = px(px2, S - 1 - py);
            const int in = px2 >= b.x0 && px2 <= b.x1 && py >= b.y0 && py <= b.y1;
            (*n)++;
            if (in ? (p[0] != 255 || p[1] != 128 || p[2] != 64 || p[3] != 128)
                   : (p[0] | p[1] | p[2] | p[3]) != 0)
               (*bad)++;
         }
   }
   OSMesaDestroyContext(g_ctx);
   free(g_buf);
}

/* lines and triangles with sprites on: frame `mode` 0 the sprite state
 * (GL_COORD_REPLACE on unit `unit`), 1 sprites off and that unit's
 * coordinates (0, 0, 0, 0), 2 sprites off, the coordinates as given */
static void zero_scene(int mode, int unit, int texgen)
{
   static const float v[3][6] = { { 0.3f, 0.6f, 0.2f, 2.0f, 0, 0 },
                                  { 0.9f, 0.2f, 0.2f, 1.0f, 64, 0 },
                                  { 0.5f, 0.95f, 0.7f, 0.5f, 0, 64 } };
   glClear(GL_COLOR_BUFFER_BIT);
   if (mode == 0)
      glEnable(GL_POINT_SPRITE);
   else
      glDisable(GL_POINT_SPRITE);
   glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
   if (texgen && mode != 1) {
      glEnable(GL_TEXTURE_GEN_S);
      glEnable(GL_TEXTURE_GEN_T);
   } else {
      glDisable(GL_TEXTURE_GEN_S);
      glDisable(GL_TEXTURE_GEN_T);
   }
   glBegin(GL_TRIANGLES);
   for (int i = 0; i < 3; i++) {
      glColor4f(0.2f + 0.3f * (float)i, 0.5f, 0.9f - 0.2f * (float)i, 0.8f);
      for (int u = 0; u < 2; u++) {
         if (mode == 1 && u == unit)
            glMultiTexCoord4f(GL_TEXTURE0 + (GLenum)u, 0, 0, 0, 0);
         else
            glMultiTexCoord4f(GL_TEXTURE0 + (GLenum)u, v[i][0] + 0.1f * (float)u, v[i][1], v[i][2],
                              v[i][3]);
      }
      glVertex2f(v[i][4], v[i][5]);
   }
   glEnd();
   glBegin(GL_LINES);
   glMultiTexCoord4f(GL_TEXTURE0 + (GLenum)unit, mode == 1 ? 0.0f : 0.6f, mode == 1 ? 0.0f : 0.6f,
                     0.0f, mode == 1 ? 0.0f : 1.0f);
   glVertex2f(0, 60.5f);
   glVertex2f(64, 60.5f);
   glEnd();
   glFinish();
}

static void replaced_zero(long *n, long *bad, long *own)
{
   probe_init_ub(64, 64);
   static unsigned char tex[16 * 16 * 4], img[3][64 * 64 * 4];
   for (int i = 0; i < 16 * 16 * 4; i++)
      tex[i] = (unsigned char)(i * 37 + i / 7);
   static const GLenum wr[4] = { GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER,
                                 GL_MIRRORED_REPEAT };
   static const GLenum fl[2] = { GL_NEAREST, GL_LINEAR };
   static const GLfloat ps[4] = { 0.031f, -0.017f, 0.0f, 0.13f }, pt[4] = { -0.023f, 0.041f, 0.0f, 0.3f };
   for (int u = 0; u < 2; u++) {
      glActiveTexture(GL_TEXTURE0 + (GLenum)u);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
      glEnable(GL_TEXTURE_2D);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, u ? GL_ADD : GL_MODULATE);
      glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
      glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
      glTexGenfv(GL_S, GL_EYE_PLANE, ps);
      glTexGenfv(GL_T, GL_EYE_PLANE, pt);
   }
   for (int unit = 0; unit < 2; unit++) {
      glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
      glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
      for (int w = 0; w < 4; w++)
         for (int f = 0; f < 2; f++)
            for (int texgen = 0; texgen < 2; texgen++) {
               glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
               glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wr[w]);
               glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wr[(w + 1) % 4]);
               glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)fl[f]);
               glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)fl[f]);
               for (int mode = 0; mode < 3; mode++) {
                  zero_scene(mode, unit, texgen);
                  memcpy(img[mode], g_buf, sizeof img[mode]);
               }
               for (int i = 0; i < 64 * 64 * 4; i++) {
                  (*n)++;
                  *bad += img[0][i] != img[1][i];
                  *own += img[0][i] != img[2][i];
               }
            }
      glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
      glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
   }
   OSMesaDestroyContext(g_ctx);
   free(g_buf);
}

int main(void)
{
   long n = 0, cover = 0, coord = 0;
   for (int persp = 0; persp < 2; persp++)
      for (int lower = 0; lower < 2; lower++)
         coords(persp, lower, &n, &cover, &coord);
   printf("     600 sprites, %ld pixels\n", n);
   probe_expect("sprites: pixels covered differently", cover, 0);
   probe_expect("sprites: replaced coordinate channels differing", coord, 0);
   long n2 = 0, bad = 0;
   plain(&n2, &bad);
   printf("     300 sprites (smooth, fade threshold, attenuation), %ld pixels\n", n2);
   probe_expect("sprites: plain pixels differing", bad, 0);
   long n3 = 0, bad3 = 0, own3 = 0;
   replaced_zero(&n3, &bad3, &own3);
   printf("     lines and triangles with a replaced unit, %ld channels\n", n3);
   probe_expect("replaced unit on lines/triangles: channels off (0, 0, 0, 0)", bad3, 0);
   probe_expect("replaced unit on lines/triangles: differs from its own coordinates", own3 > 0, 1);
   return probe_result();
}
