/*
 * Fonts: one stroke glyph set of our own for ASCII 32-126, drawn as GLUT's
 * stroke fonts (GL_LINE_STRIPs in units where the capitals are 100 high,
 * GLUT's metrics: height 119.05, descent 33.33) and rasterised at load time
 * into the bitmap fonts (drawn with glBitmap, as GLUT does).
 *
 * Glyph encoding: polylines separated by spaces; each point is two
 * characters, x in '0'..'6' and y in 'b' (-2), 'a' (-1), '0'..'6'; the
 * baseline is y = 0, the capitals reach y = 6, the lower case x-height
 * is 4, descenders reach -2.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glut_internal.h"

static const char *const glyphs[95] = {
   /* ' ' */ "",
   /* '!' */ "0602 0100",
   /* '"' */ "0604 2624",
   /* '#' */ "1115 3135 0444 0242",
   /* '$' */ "453616050413334241301001 2a26",
   /* '%' */ "0046 0616150506 3141403031",
   /* '&' */ "4014152635340201102042",
   /* ''' */ "0604",
   /* '(' */ "16050110",
   /* ')' */ "06151100",
   /* '*' */ "2521 0442 0244",
   /* '+' */ "2125 0343",
   /* ',' */ "11100a",
   /* '-' */ "0343",
   /* '.' */ "0100",
   /* '/' */ "0046",
   /* '0' */ "163645413010010516 0145",
   /* '1' */ "152620 1030",
   /* '2' */ "05163645440040",
   /* '3' */ "05163645443313 334241301001",
   /* '4' */ "30360242",
   /* '5' */ "460604344341301001",
   /* '6' */ "453616050110304142331302",
   /* '7' */ "064610",
   /* '8' */ "13040516364544331302011030414233",
   /* '9' */ "011030414536160504133344",
   /* ':' */ "0403 0100",
   /* ';' */ "1413 11100a",
   /* '<' */ "450341",
   /* '=' */ "0444 0242",
   /* '>' */ "054301",
   /* '?' */ "05163645442322 2120",
   /* '@' */ "3432121434 324245361605011040",
   /* 'A' */ "002640 1333",
   /* 'B' */ "00063645443303 3342413000",
   /* 'C' */ "4536160501103041",
   /* 'D' */ "00063645413000",
   /* 'E' */ "46060040 0333",
   /* 'F' */ "460600 0333",
   /* 'G' */ "45361605011030414323",
   /* 'H' */ "0006 4046 0343",
   /* 'I' */ "0626 1610 0020",
   /* 'J' */ "4641301001",
   /* 'K' */ "0006 4602 1340",
   /* 'L' */ "060040",
   /* 'M' */ "0006234640",
   /* 'N' */ "00064046",
   /* 'O' */ "163645413010010516",
   /* 'P' */ "00063645443303",
   /* 'Q' */ "163645413010010516 2240",
   /* 'R' */ "00063645443303 2340",
   /* 'S' */ "453616050413334241301001",
   /* 'T' */ "0646 2620",
   /* 'U' */ "060110304146",
   /* 'V' */ "062046",
   /* 'W' */ "0610243046",
   /* 'X' */ "0046 0640",
   /* 'Y' */ "062346 2320",
   /* 'Z' */ "06460040",
   /* '[' */ "16060010",
   /* '\' */ "0640",
   /* ']' */ "06161000",
   /* '^' */ "042644",
   /* '_' */ "0a4a",
   /* '`' */ "0615",
   /* 'a' */ "0314344340 421201103041",
   /* 'b' */ "0600 0314344341301001",
   /* 'c' */ "4334140301103041",
   /* 'd' */ "4640 4334140301103041",
   /* 'e' */ "02424334140301103041",
   /* 'f' */ "36261510 0424",
   /* 'g' */ "444a3b1b0a 4334140302113142",
   /* 'h' */ "0600 0314344340",
   /* 'i' */ "0400 0605",
   /* 'j' */ "141a0b 1615",
   /* 'k' */ "0600 3401 1230",
   /* 'l' */ "060110",
   /* 'm' */ "0004 03142320 23344340",
   /* 'n' */ "0004 0314344340",
   /* 'o' */ "143443413010010314",
   /* 'p' */ "040b 0314344341301001",
   /* 'q' */ "444b 4334140301103041",
   /* 'r' */ "0400 022434",
   /* 's' */ "43341403123241301001",
   /* 't' */ "16112030 0434",
   /* 'u' */ "0401103041 4440",
   /* 'v' */ "042044",
   /* 'w' */ "0410233044",
   /* 'x' */ "0044 0440",
   /* 'y' */ "0420 441b0b",
   /* 'z' */ "04440040",
   /* '{' */ "26151403121120",
   /* '|' */ "060a",
   /* '}' */ "06151423121100",
   /* '~' */ "03143344",
};

static int coord_x(char c) { return c - '0'; }
static int coord_y(char c) { return c == 'a' ? -1 : c == 'b' ? -2 : c - '0'; }

/* The glyph's x extent on the grid (0..0 for an empty glyph). */
static void glyph_extent(const char *g, int *minx, int *maxx, int *miny, int *maxy)
{
   *minx = *miny = 99, *maxx = *maxy = -99;
   for (const char *p = g; *p; ) {
      if (*p == ' ') {
         p++;
         continue;
      }
      int x = coord_x(p[0]), y = coord_y(p[1]);
      if (x < *minx) *minx = x;
      if (x > *maxx) *maxx = x;
      if (y < *miny) *miny = y;
      if (y > *maxy) *maxy = y;
      p += 2;
   }
   if (*minx > *maxx)
      *minx = *maxx = *miny = *maxy = 0;
}

/* ---- stroke fonts --------------------------------------------------------- */

#define STROKE_UNIT (100.0f / 6.0f)       /* grid unit: capitals 100 high */
#define STROKE_XUNIT (0.75f * STROKE_UNIT)
#define STROKE_MONO_ADVANCE 104.76f        /* GLUT_STROKE_MONO_ROMAN's advance */
#define STROKE_SPACE 62.5f

static bool stroke_font(void *font)
{
   if (font != GLUT_STROKE_ROMAN && font != GLUT_STROKE_MONO_ROMAN) {
      glut_warn("not a stroke font: %p", font);
      return false;
   }
   return true;
}

static float stroke_advance(void *font, int c, float *xoff)
{
   int minx, maxx, miny, maxy;
   glyph_extent(glyphs[c - 32], &minx, &maxx, &miny, &maxy);
   float gw = (float)(maxx - minx) * STROKE_XUNIT;
   if (font == GLUT_STROKE_MONO_ROMAN) {
      *xoff = (STROKE_MONO_ADVANCE - gw) * 0.5f - (float)minx * STROKE_XUNIT;
      return STROKE_MONO_ADVANCE;
   }
   *xoff = STROKE_XUNIT - (float)minx * STROKE_XUNIT;
   return c == ' ' ? STROKE_SPACE : gw + 2.0f * STROKE_XUNIT;
}

GLUT_EXPORT void glutStrokeCharacter(void *font, int c)
{
   if (!stroke_font(font) || c < 32 || c > 126)
      return;
   float xoff;
   float adv = stroke_advance(font, c, &xoff);
   const char *p = glyphs[c - 32];
   while (*p) {
      if (*p == ' ') {
         p++;
         continue;
      }
      glBegin(GL_LINE_STRIP);
      while (*p && *p != ' ') {
         glVertex2f(xoff + (float)coord_x(p[0]) * STROKE_XUNIT,
                    (float)coord_y(p[1]) * STROKE_UNIT);
         p += 2;
      }
      glEnd();
   }
   glTranslatef(adv, 0.0f, 0.0f);
}

GLUT_EXPORT int glutStrokeWidth(void *font, int c)
{
   float xoff;
   if (!stroke_font(font) || c < 32 || c > 126)
      return 0;
   return (int)(stroke_advance(font, c, &xoff) + 0.5f);
}

GLUT_EXPORT int glutStrokeLength(void *font, const unsigned char *s)
{
   float len = 0.0f, xoff;
   if (!stroke_font(font) || !s)
      return 0;
   for (; *s; s++)
      if (*s >= 32 && *s <= 126)
         len += stroke_advance(font, *s, &xoff);
   return (int)(len + 0.5f);
}

GLUT_EXPORT void glutStrokeString(void *font, const unsigned char *s)
{
   for (; s && *s; s++)
      glutStrokeCharacter(font, *s);
}

GLUT_EXPORT GLfloat glutStrokeHeight(void *font)
{
   return stroke_font(font) ? 119.05f : 0.0f;
}

/* ---- bitmap fonts ----------------------------------------------------- */

struct bitmap_font {
   void *handle;
   int cap;        /* capital height in pixels */
   int cell;       /* fixed advance, 0: proportional */
   int height;     /* glutBitmapHeight (freeglut's values) */
   int pen;        /* stroke width in pixels */
   struct glut_bitmap_glyph glyph[95];
   bool built;
};

static struct bitmap_font bitmap_fonts[] = {
   { GLUT_BITMAP_9_BY_15, 10, 9, 16, 1, { { 0 } }, false },
   { GLUT_BITMAP_8_BY_13, 9, 8, 14, 1, { { 0 } }, false },
   { GLUT_BITMAP_TIMES_ROMAN_10, 7, 0, 14, 1, { { 0 } }, false },
   { GLUT_BITMAP_TIMES_ROMAN_24, 17, 0, 29, 2, { { 0 } }, false },
   { GLUT_BITMAP_HELVETICA_10, 7, 0, 14, 1, { { 0 } }, false },
   { GLUT_BITMAP_HELVETICA_12, 9, 0, 16, 1, { { 0 } }, false },
   { GLUT_BITMAP_HELVETICA_18, 13, 0, 23, 1, { { 0 } }, false },
};

static void plot(unsigned char *bits, int stride, int w, int h, int x, int y, int pen)
{
   for (int dy = 0; dy < pen; dy++)
      for (int dx = 0; dx < pen; dx++) {
         int px = x + dx, py = y + dy;
         if (px >= 0 && px < w && py >= 0 && py < h)
            bits[py * stride + px / 8] |= (unsigned char)(0x80 >> (px % 8));
      }
}

static void build_glyph(struct bitmap_font *f, int c)
{
   struct glut_bitmap_glyph *g = &f->glyph[c - 32];
   const char *src = glyphs[c - 32];
   const float sy = (float)f->cap / 6.0f;
   const float sx = f->cell ? (float)(f->cell - 3 - (f->pen - 1)) / 4.0f : sy * 0.8f;
   int minx, maxx, miny, maxy;
   glyph_extent(src, &minx, &maxx, &miny, &maxy);
   int w = (int)lroundf((float)(maxx - minx) * sx) + f->pen;
   int h = (int)lroundf((float)(maxy - miny) * sy) + f->pen;
   int bottom = (int)lroundf((float)miny * sy);
   if (!*src)
      w = h = 0, bottom = 0;
   int stride = (w + 7) / 8;
   unsigned char *bits = calloc((size_t)(stride * h) + 1, 1);
   if (!bits)
      glut_fatal("out of memory");
   for (const char *p = src; *p; ) {
      if (*p == ' ') {
         p++;
         continue;
      }
      float x0 = (float)(coord_x(p[0]) - minx) * sx, y0 = (float)(coord_y(p[1]) - miny) * sy;
      p += 2;
      if (!*p || *p == ' ')
         plot(bits, stride, w, h, (int)lroundf(x0), (int)lroundf(y0), f->pen);
      while (*p && *p != ' ') {
         float x1 = (float)(coord_x(p[0]) - minx) * sx, y1 = (float)(coord_y(p[1]) - miny) * sy;
         float len = fmaxf(fabsf(x1 - x0), fabsf(y1 - y0));
         int steps = (int)ceilf(len * 2.0f);
         if (steps < 1)
            steps = 1;
         for (int i = 0; i <= steps; i++) {
            float t = (float)i / (float)steps;
            plot(bits, stride, w, h, (int)lroundf(x0 + (x1 - x0) * t),
                 (int)lroundf(y0 + (y1 - y0) * t), f->pen);
         }
         x0 = x1, y0 = y1;
         p += 2;
      }
   }
   g->width = w;
   g->height = h;
   g->bits = bits;
   if (f->cell) {
      g->xorig = -(float)((f->cell - w) / 2);
      g->advance = (float)f->cell;
   } else {
      g->xorig = -1.0f;
      g->advance = c == ' ' ? (float)lroundf(4.0f * sx) : (float)(w + 2);
   }
   g->yorig = (float)-bottom;
}

static struct bitmap_font *bitmap_font(void *font)
{
   for (size_t i = 0; i < sizeof bitmap_fonts / sizeof bitmap_fonts[0]; i++) {
      struct bitmap_font *f = &bitmap_fonts[i];
      if (f->handle != font)
         continue;
      if (!f->built) {
         for (int c = 32; c <= 126; c++)
            build_glyph(f, c);
         f->built = true;
      }
      return f;
   }
   glut_warn("not a bitmap font: %p", font);
   return NULL;
}

const struct glut_bitmap_glyph *glut_bitmap_glyph(void *font, int c)
{
   struct bitmap_font *f;
   if (c < 32 || c > 126 || !(f = bitmap_font(font)))
      return NULL;
   return &f->glyph[c - 32];
}

/* glBitmap is referenced weakly: a libfixgl without it (before the pixel
 * drawing work lands) still runs programs; their bitmap text is then
 * missing, and said so once on stderr. */
#pragma weak glBitmap

GLUT_EXPORT void glutBitmapCharacter(void *font, int c)
{
   const struct glut_bitmap_glyph *g = glut_bitmap_glyph(font, c);
   if (!g)
      return;
   void (*volatile bitmap)(GLsizei, GLsizei, GLfloat, GLfloat, GLfloat, GLfloat,
                           const GLubyte *) = glBitmap;
   if (!bitmap) {
      static bool warned;
      if (!warned)
         glut_warn("this GL library has no glBitmap: bitmap text is not drawn");
      warned = true;
      return;
   }
   /* GLUT's unpack state for glyphs: defaults with byte alignment, the
    * program's state restored afterwards. */
   GLint swap, lsb, row, skip_rows, skip_pixels, align;
   glGetIntegerv(GL_UNPACK_SWAP_BYTES, &swap);
   glGetIntegerv(GL_UNPACK_LSB_FIRST, &lsb);
   glGetIntegerv(GL_UNPACK_ROW_LENGTH, &row);
   glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skip_rows);
   glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skip_pixels);
   glGetIntegerv(GL_UNPACK_ALIGNMENT, &align);
   glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
   glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
   glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
   glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
   glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   bitmap(g->width, g->height, g->xorig, g->yorig, g->advance, 0.0f, g->bits);
   glPixelStorei(GL_UNPACK_SWAP_BYTES, swap);
   glPixelStorei(GL_UNPACK_LSB_FIRST, lsb);
   glPixelStorei(GL_UNPACK_ROW_LENGTH, row);
   glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_rows);
   glPixelStorei(GL_UNPACK_SKIP_PIXELS, skip_pixels);
   glPixelStorei(GL_UNPACK_ALIGNMENT, align);
}

GLUT_EXPORT int glutBitmapWidth(void *font, int c)
{
   const struct glut_bitmap_glyph *g = glut_bitmap_glyph(font, c);
   return g ? (int)g->advance : 0;
}

GLUT_EXPORT int glutBitmapLength(void *font, const unsigned char *s)
{
   int len = 0;
   for (; s && *s; s++)
      len += glutBitmapWidth(font, *s);
   return len;
}

GLUT_EXPORT void glutBitmapString(void *font, const unsigned char *s)
{
   for (; s && *s; s++)
      glutBitmapCharacter(font, *s);
}

GLUT_EXPORT int glutBitmapHeight(void *font)
{
   struct bitmap_font *f = bitmap_font(font);
   return f ? f->height : 0;
}
