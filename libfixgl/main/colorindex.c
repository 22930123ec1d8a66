/*
 * Colour index calls on an RGBA context, as on the oracle's RGBA-only
 * OSMesa context: glIndex* set the current index (GL_CURRENT_INDEX),
 * glClearIndex the index clear value, glIndexMask the index write mask.
 * All are stored and queried, and none changes what is drawn or cleared:
 * an RGBA framebuffer has no index buffer.
 */
#include <stdint.h>

#include "main/groups.h"
#include "main/dlist.h"

/* [S: vbo/vbo_attrib_tmp.h, _mesa_Index*]: the index is a one-component
 * float vbo attribute (VBO_ATTRIB_COLOR_INDEX), settable between glBegin
 * and glEnd, in the vertex format like any other (so it takes part in the
 * batching, and becomes current at a flush, marking GL_CURRENT_BIT for
 * glPopAttrib); the integer variants convert with a plain (GLfloat) cast. */
static void set_index(float c)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   fgl_attr(ctx, FGL_ATTR_COLOR_INDEX, 1, c, 0.0f, 0.0f, 1.0f);
}

/* (the vector forms ignore NULL, like fixgl's other vertex attributes;
 * Mesa would crash) */
void GLAPIENTRY glIndexd(GLdouble c) { set_index((GLfloat)c); }
void GLAPIENTRY glIndexdv(const GLdouble *c) { if (c) set_index((GLfloat)c[0]); }
void GLAPIENTRY glIndexf(GLfloat c) { set_index(c); }
void GLAPIENTRY glIndexfv(const GLfloat *c) { if (c) set_index(c[0]); }
void GLAPIENTRY glIndexi(GLint c) { set_index((GLfloat)c); }
void GLAPIENTRY glIndexiv(const GLint *c) { if (c) set_index((GLfloat)c[0]); }
void GLAPIENTRY glIndexs(GLshort c) { set_index((GLfloat)c); }
void GLAPIENTRY glIndexsv(const GLshort *c) { if (c) set_index((GLfloat)c[0]); }
void GLAPIENTRY glIndexub(GLubyte c) { set_index((GLfloat)c); }
void GLAPIENTRY glIndexubv(const GLubyte *c) { if (c) set_index((GLfloat)c[0]); }

/* [S: main/clear.c:_mesa_ClearIndex]: ctx->Color.ClearIndex = (GLuint) c,
 * without a flush.  The cast is done as the oracle's x86-64 build does it
 * (cvttss2si into a 64-bit register, low 32 bits kept): negative values
 * wrap, NaN and values beyond 2^63 give 0.  Between glBegin and glEnd the
 * call is not in Mesa's begin/end dispatch: INVALID_OPERATION. */
GLuint fgl_clear_index_cast(float c)
{
   GLuint v = 0;
   if (c > -9223372036854775808.0f && c < 9223372036854775808.0f)
      v = (GLuint)(uint64_t)(int64_t)c;
   return v;
}

void GLAPIENTRY glClearIndex(GLfloat c)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, ClearIndex, c);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   ctx->PopAttribState |= GL_COLOR_BUFFER_BIT;
   ctx->Color.ClearIndex = fgl_clear_index_cast(c);
}

/* [S: main/masks.c:_mesa_IndexMask] */
void GLAPIENTRY glIndexMask(GLuint mask)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   FGL_SAVE(ctx, IndexMask, mask);
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   if (ctx->Color.IndexMask == mask)
      return;
   FGL_FLUSH_VERTICES(ctx, 0);
   ctx->PopAttribState |= GL_COLOR_BUFFER_BIT;
   ctx->Color.IndexMask = mask;
}
