/* p_bitmap_compile_null.c - glBitmap with no pixels (a NULL pointer) while
 * a display list is compiled: save_Bitmap has no texture to make of it
 * (st_make_bitmap_texture gives none), raises GL_OUT_OF_MEMORY and stores
 * nothing; under GL_COMPILE_AND_EXECUTE it is not executed either.  Its
 * raster position move is lost, whatever the size (glXUseXFont's blank
 * glyphs, glBitmap(0, 0, 0, 0, dx, 0, NULL), do not advance in Mesa's
 * text: ORACLE-NOTES.md "Display lists").  Outside a list, and with
 * pixels, the move happens. */
#include "probe.h"

/* The raster position's x after glRasterPos2i(1, 1) and the bitmap,
 * executed (no list), compiled then called, or compiled and executed. */
static long after_bitmap(GLsizei w, GLsizei h, const GLubyte *bits, int how, GLenum *err)
{
   GLfloat p[4];
   glGetError();
   if (how == 0) {
      glRasterPos2i(1, 1);
      glBitmap(w, h, 0, 0, 3, 0, bits);
      *err = glGetError();
   } else {
      glNewList(1, how == 1 ? GL_COMPILE : GL_COMPILE_AND_EXECUTE);
      glRasterPos2i(1, 1);
      glBitmap(w, h, 0, 0, 3, 0, bits);
      *err = glGetError();
      glEndList();
      if (how == 1) {
         glRasterPos2i(1, 1);
         glCallList(1);
      }
   }
   glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
   return (long)p[0];
}

int main(void)
{
   static const GLubyte bits[8] = { 0x80, 0x40 };
   GLenum err;
   probe_init_ub(8, 8);
   probe_expect("glBitmap(0, 0, NULL) executed: x", after_bitmap(0, 0, NULL, 0, &err), 4);
   probe_expect("  error", err, GL_NO_ERROR);
   probe_expect("glBitmap(0, 0, bits) compiled: x", after_bitmap(0, 0, bits, 1, &err), 4);
   probe_expect("  error", err, GL_NO_ERROR);
   probe_expect("glBitmap(0, 0, NULL) compiled: x", after_bitmap(0, 0, NULL, 1, &err), 1);
   probe_expect("  error", err, GL_OUT_OF_MEMORY);
   probe_expect("glBitmap(0, 5, NULL) compiled: x", after_bitmap(0, 5, NULL, 1, &err), 1);
   probe_expect("  error", err, GL_OUT_OF_MEMORY);
   probe_expect("glBitmap(-1, 0, NULL) compiled: x", after_bitmap(-1, 0, NULL, 1, &err), 1);
   probe_expect("  error", err, GL_OUT_OF_MEMORY);
   probe_expect("glBitmap(0, 0, NULL) compiled and executed: x", after_bitmap(0, 0, NULL, 2, &err), 1);
   probe_expect("  error", err, GL_OUT_OF_MEMORY);
   probe_expect("glBitmap(8, 2, bits) compiled and executed: x", after_bitmap(8, 2, bits, 2, &err), 4);
   probe_expect("  error", err, GL_NO_ERROR);
   return probe_result();
}
