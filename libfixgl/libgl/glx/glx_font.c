/*
 * glXUseXFont: display lists of glBitmap calls made from the glyphs of an
 * X font, one list per character (glXUseXFont(3)).
 *
 * Each glyph is drawn by the server into a 1-bit pixmap (XDrawString16),
 * read back (XGetImage) and turned upside down into a GL bitmap whose
 * rows are a whole number of bytes (GL_UNPACK_ALIGNMENT 1 while the lists
 * are compiled): width rbearing - lbearing, height ascent + descent,
 * origin (-lbearing, descent - 1: one row higher than the manual page
 * says, as Mesa's DRI GLX has it), advance (width, 0).  A character
 * without a glyph (a blank, or one the font lacks: then with the font's
 * largest metrics) gets glBitmap(0, 0, ..., NULL), which a display list
 * drops (GL_OUT_OF_MEMORY, ORACLE-NOTES.md "Display lists"), so its
 * advance is lost, as in Mesa.  The same rules as Mesa's glx/xfont.c
 * (DRI_glXUseXFont), so that a program's text is drawn with the same
 * pixels (conformance/glx/glxapi.c).
 */
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#define GLXAPI __attribute__((visibility("default")))

/* The metrics of character c, or NULL when the font has none for it. */
static const XCharStruct *char_metrics(const XFontStruct *fs, unsigned c)
{
   const unsigned cols = fs->max_char_or_byte2 - fs->min_char_or_byte2 + 1;
   size_t index;
   if (fs->min_byte1 == fs->max_byte1) {   /* one row: a linear font */
      if (c < fs->min_char_or_byte2 || c > fs->max_char_or_byte2)
         return NULL;
      index = c - fs->min_char_or_byte2;
   } else {
      const unsigned b1 = c >> 8, b2 = c & 0xffu;
      if (b2 < fs->min_char_or_byte2 || b2 > fs->max_char_or_byte2 || b1 < fs->min_byte1 ||
          b1 > fs->max_byte1)
         return NULL;
      index = (size_t)(b1 - fs->min_byte1) * cols + (b2 - fs->min_char_or_byte2);
   }
   return fs->per_char ? &fs->per_char[index] : &fs->min_bounds;
}

/* The glyph of c drawn at (x, y) of a (8 * bytes_wide) x height pixmap,
 * into bitmap (bottom row first, most significant bit leftmost). */
static void glyph_bitmap(Display *dpy, Window win, GC gc, unsigned bytes_wide, unsigned height,
                         int x, int y, unsigned c, GLubyte *bitmap)
{
   const unsigned w = 8 * bytes_wide;
   Pixmap pm = XCreatePixmap(dpy, win, w, height, 1);
   XSetForeground(dpy, gc, 0);
   XFillRectangle(dpy, pm, gc, 0, 0, w, height);
   XSetForeground(dpy, gc, 1);
   XChar2b ch = { .byte1 = (unsigned char)((c >> 8) & 0xffu), .byte2 = (unsigned char)(c & 0xffu) };
   XDrawString16(dpy, pm, gc, x, y, &ch, 1);
   XImage *img = XGetImage(dpy, pm, 0, 0, w, height, 1, XYPixmap);
   if (img) {
      for (unsigned row = 0; row < height; row++)
         for (unsigned col = 0; col < w; col++)
            if (XGetPixel(img, (int)col, (int)row))
               bitmap[bytes_wide * (height - 1 - row) + col / 8] |= (GLubyte)(0x80u >> (col % 8));
      XDestroyImage(img);
   }
   XFreePixmap(dpy, pm);
}

GLXAPI void glXUseXFont(Font font, int first, int count, int listBase)
{
   Display *dpy = glXGetCurrentDisplay();
   if (!dpy || count <= 0)
      return;
   XFontStruct *fs = XQueryFont(dpy, font);
   if (!fs)
      return;
   const Window win = RootWindow(dpy, DefaultScreen(dpy));
   const int max_w = fs->max_bounds.rbearing - fs->min_bounds.lbearing;
   const int max_h = fs->max_bounds.ascent + fs->max_bounds.descent;
   GLubyte *bm = malloc((size_t)((max_w + 7) / 8 > 0 ? (max_w + 7) / 8 : 1) *
                        (size_t)(max_h > 0 ? max_h : 1));
   if (!bm) {
      XFreeFontInfo(NULL, fs, 1);
      return;
   }

   /* the unpack state the bitmaps are made for, the application's
    * restored after */
   GLint swap, lsb, row_length, skip_rows, skip_pixels, alignment;
   glGetIntegerv(GL_UNPACK_SWAP_BYTES, &swap);
   glGetIntegerv(GL_UNPACK_LSB_FIRST, &lsb);
   glGetIntegerv(GL_UNPACK_ROW_LENGTH, &row_length);
   glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skip_rows);
   glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skip_pixels);
   glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
   glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
   glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
   glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
   glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
   glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

   XGCValues values = {
      .foreground = BlackPixel(dpy, DefaultScreen(dpy)),
      .background = WhitePixel(dpy, DefaultScreen(dpy)),
      .font = fs->fid,
   };
   Pixmap tmp = XCreatePixmap(dpy, win, 10, 10, 1);
   GC gc = XCreateGC(dpy, tmp, GCForeground | GCBackground | GCFont, &values);
   XFreePixmap(dpy, tmp);

   for (int i = 0; i < count; i++) {
      const unsigned c = (unsigned)(first + i);
      const XCharStruct *m = char_metrics(fs, c);
      const bool valid = m != NULL;
      if (!m)
         m = &fs->max_bounds;
      const int width = m->rbearing - m->lbearing;
      const int height = m->ascent + m->descent;
      const int bytes_wide = (width + 7) / 8;
      glNewList((GLuint)(listBase + i), GL_COMPILE);
      if (valid && bytes_wide > 0 && height > 0) {
         memset(bm, 0, (size_t)bytes_wide * (size_t)height);
         glyph_bitmap(dpy, win, gc, (unsigned)bytes_wide, (unsigned)height, -m->lbearing,
                      m->ascent, c, bm);
         glBitmap(width, height, (GLfloat)-m->lbearing, (GLfloat)(m->descent - 1),
                  (GLfloat)m->width, 0.0f, bm);
      } else {
         glBitmap(0, 0, 0.0f, 0.0f, (GLfloat)m->width, 0.0f, NULL);
      }
      glEndList();
   }

   free(bm);
   XFreeFontInfo(NULL, fs, 1);
   XFreeGC(dpy, gc);
   glPixelStorei(GL_UNPACK_SWAP_BYTES, swap);
   glPixelStorei(GL_UNPACK_LSB_FIRST, lsb);
   glPixelStorei(GL_UNPACK_ROW_LENGTH, row_length);
   glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_rows);
   glPixelStorei(GL_UNPACK_SKIP_PIXELS, skip_pixels);
   glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
}
