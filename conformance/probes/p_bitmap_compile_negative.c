/* p_bitmap_compile_negative.c - an oracle defect: glBitmap with a negative
 * width or height is compiled by glNewList without the GL_INVALID_VALUE
 * check (raised when the node executes), but Mesa's save_Bitmap first
 * makes the bitmap's texture with the sizes as they are
 * (st_make_bitmap_texture): a negative size becomes a huge unsigned one,
 * and whether llvmpipe can lay out and allocate that texture decides:
 * a width of -63 or more (rounded up to a multiple of 64 it wraps to 0)
 * compiles with no error, -64 and below raise GL_OUT_OF_MEMORY (the API
 * fuzzer's seed 312), a zero height compiles; a huge negative height can
 * crash the oracle (not probed).  fixgl compiles every negative size
 * without a texture and no error (ORACLE-NOTES.md "OSMesa defects kept
 * visible"). */
#include "probe.h"

static GLenum compile_bitmap(GLsizei w, GLsizei h)
{
   static const GLubyte bits[64] = { 0 };
   glNewList(1, GL_COMPILE);
   glBitmap(w, h, 0, 0, 1, 1, bits);
   const GLenum e = glGetError();
   glEndList();
   return e;
}

int main(void)
{
   probe_init_ub(8, 8);
   probe_expect("glBitmap(-5, 2) compiled", compile_bitmap(-5, 2), GL_NO_ERROR);
   probe_expect("glBitmap(-63, 1) compiled", compile_bitmap(-63, 1), GL_NO_ERROR);
   probe_expect("glBitmap(-57, -100) compiled", compile_bitmap(-57, -100), GL_NO_ERROR);
   probe_expect("glBitmap(-1000, 0) compiled", compile_bitmap(-1000, 0), GL_NO_ERROR);
   probe_expect("glBitmap(-64, 1) compiled (defect: GL_OUT_OF_MEMORY)", compile_bitmap(-64, 1),
                GL_OUT_OF_MEMORY);
   probe_expect("glBitmap(-100000, 2) compiled (defect: GL_OUT_OF_MEMORY)",
                compile_bitmap(-100000, 2), GL_OUT_OF_MEMORY);
   /* the texture's height is pipe_resource's 16 bits of the size, its row
    * the width aligned to 4 and 64 in 32 bits; more than 2 GiB fails
    * (the API fuzzer's seed 1000699: glBitmap(INT_MIN, 308) under
    * GL_COMPILE_AND_EXECUTE, neither compiled nor executed) */
   probe_expect("glBitmap(INT_MIN, 308) compiled (defect: GL_OUT_OF_MEMORY)",
                compile_bitmap(-2147483647 - 1, 308), GL_OUT_OF_MEMORY);
   probe_expect("glBitmap(-64, -65535) compiled (16-bit height 1: GL_OUT_OF_MEMORY)",
                compile_bitmap(-64, -65535), GL_OUT_OF_MEMORY);
   probe_expect("glBitmap(-64, INT_MIN) compiled (16-bit height 0)",
                compile_bitmap(-64, -2147483647 - 1), GL_NO_ERROR);
   probe_expect("glBitmap(-64, 0) compiled", compile_bitmap(-64, 0), GL_NO_ERROR);
   probe_expect("glBitmap(100000, -1) compiled (100032 x 65536 bytes: GL_OUT_OF_MEMORY)",
                compile_bitmap(100000, -1), GL_OUT_OF_MEMORY);
   probe_expect("glBitmap(40000, INT_MIN + 4) compiled (40000 x 4 bytes)",
                compile_bitmap(40000, -2147483647 + 3), GL_NO_ERROR);
   return probe_result();
}
