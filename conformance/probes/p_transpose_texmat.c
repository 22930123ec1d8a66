/* p_transpose_texmat.c - glGet(GL_TRANSPOSE_TEXTURE_MATRIX) answers texture
 * unit 0's matrix whatever the active unit: Mesa's get table reads it as
 * CONTEXT_MATRIX_T(TextureMatrixStack), the first stack of the array, while
 * GL_TEXTURE_MATRIX is a custom value of the active unit (get.c
 * find_custom_value).  ORACLE-NOTES.md "Texture coordinates and
 * multitexture"; the API fuzzer's seed 1000655. */
#include "probe.h"

static void check(const char *what, GLenum pname, const float want[16])
{
   GLfloat m[16];
   for (int i = 0; i < 16; i++)
      m[i] = -7.0f;
   glGetFloatv(pname, m);
   int same = 1;
   for (int i = 0; i < 16; i++)
      same &= m[i] == want[i];
   probe_expect(what, same, 1);
}

int main(void)
{
   probe_init_ub(8, 8);
   float id[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
   /* unit 0's translate(5, 0, 0) * scale(2, 3, 4), row-major */
   float s0t[16] = { 2, 0, 0, 5, 0, 3, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1 };
   float s2[16] = { 6, 0, 0, 0, 0, 7, 0, 0, 0, 0, 8, 0, 0, 0, 0, 1 };
   glMatrixMode(GL_TEXTURE);
   glActiveTexture(GL_TEXTURE2);
   glScalef(6, 7, 8);
   check("unit 2 active, unit 0 identity: GL_TEXTURE_MATRIX is unit 2's", GL_TEXTURE_MATRIX, s2);
   check("unit 2 active: GL_TRANSPOSE_TEXTURE_MATRIX is unit 0's (identity)",
         GL_TRANSPOSE_TEXTURE_MATRIX, id);
   glActiveTexture(GL_TEXTURE0);
   glTranslatef(5, 0, 0);
   glScalef(2, 3, 4);
   check("unit 0 active: GL_TRANSPOSE_TEXTURE_MATRIX is unit 0's", GL_TRANSPOSE_TEXTURE_MATRIX, s0t);
   glActiveTexture(GL_TEXTURE2);
   check("unit 2 active again: GL_TRANSPOSE_TEXTURE_MATRIX is still unit 0's",
         GL_TRANSPOSE_TEXTURE_MATRIX, s0t);
   check("unit 2 active again: GL_TEXTURE_MATRIX is unit 2's", GL_TEXTURE_MATRIX, s2);
   probe_expect("no error", (long)glGetError(), GL_NO_ERROR);
   return probe_result();
}
