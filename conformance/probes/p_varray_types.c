/* p_varray_types.c - the oracle (GL 4.5) accepts the vertex array types
 * and sizes of later versions that fixgl (GL 1.5) refuses, and checks a
 * pointer call's type before its size (ORACLE-NOTES.md "Client vertex
 * arrays", "GL 1.5 honesty"). */
#include "probe.h"

static GLuint data[16];

static long err(void)
{
   const GLenum e = glGetError();
   while (glGetError() != GL_NO_ERROR) {
   }
   return (long)e;
}

int main(void)
{
   probe_init_ub(8, 8);
   /* GL 3.0 half floats, GL 3.3 packed types, GL 3.2 GL_BGRA size */
   glVertexPointer(4, GL_HALF_FLOAT, 0, data);
   probe_expect("glVertexPointer GL_HALF_FLOAT accepted", err(), GL_NO_ERROR);
   glFogCoordPointer(GL_HALF_FLOAT, 0, data);
   probe_expect("glFogCoordPointer GL_HALF_FLOAT accepted", err(), GL_NO_ERROR);
   glNormalPointer(GL_INT_2_10_10_10_REV, 0, data);
   probe_expect("glNormalPointer GL_INT_2_10_10_10_REV (size 3) refused as an operation", err(),
                GL_INVALID_OPERATION);
   glColorPointer(4, GL_UNSIGNED_INT_2_10_10_10_REV, 0, data);
   probe_expect("glColorPointer GL_UNSIGNED_INT_2_10_10_10_REV accepted", err(), GL_NO_ERROR);
   glColorPointer(GL_BGRA, GL_UNSIGNED_BYTE, 0, data);
   probe_expect("glColorPointer GL_BGRA accepted", err(), GL_NO_ERROR);
   GLint v = 0;
   glGetIntegerv(GL_COLOR_ARRAY_SIZE, &v);
   probe_expect("GL_COLOR_ARRAY_SIZE reads GL_BGRA", v, GL_BGRA);
   glSecondaryColorPointer(GL_BGRA, GL_FLOAT, 0, data);
   probe_expect("glSecondaryColorPointer GL_BGRA GL_FLOAT: GL_INVALID_OPERATION", err(),
                GL_INVALID_OPERATION);
   /* the order fixgl keeps: the type (GL_INVALID_ENUM) before the size
    * (GL_INVALID_VALUE), and a negative stride (GL_INVALID_VALUE) before
    * both (the first error is the one kept) */
   glColorPointer(7, GL_BOOL, 0, data);
   probe_expect("bad type and size: GL_INVALID_ENUM", err(), GL_INVALID_ENUM);
   glTexCoordPointer(9, GL_FLOAT, 0, data);
   probe_expect("bad size: GL_INVALID_VALUE", err(), GL_INVALID_VALUE);
   glColorPointer(3, GL_BOOL, -4, data);
   probe_expect("negative stride with a bad type: GL_INVALID_VALUE", err(), GL_INVALID_VALUE);
   return probe_result();
}
