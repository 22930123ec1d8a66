/*
 * Client-side vertex arrays (GL_CLIENT_VERTEX_ARRAY_BIT): gl*Pointer,
 * glInterleavedArrays, glEnable/DisableClientState, glGetPointerv,
 * glArrayElement, glDrawArrays,
 * glDrawElements, glDrawRangeElements, with Mesa 22.3's validation
 * [S: main/varray.c, main/enable.c:client_state, main/getstring.c,
 * main/draw.c].  Fetching and drawing live in tnl/t_array.c.
 *
 * Between glBegin and glEnd only glArrayElement is allowed: the oracle
 * dispatches every other entry point here through the BeginEnd table's
 * generic_nop, GL_INVALID_OPERATION without any effect
 * [S: main/context.c:generic_nop, vbo/vbo_exec_api.c:vbo_exec_Begin].
 *
 * glIndexPointer keeps its state, errors and queries only: colour index
 * mode does not draw.  Texture coordinate arrays are fetched per unit
 * (glClientActiveTexture) by tnl/t_array.c.
 */
/* the GL 1.4 pointer and multi-draw calls and GL_EXT_vertex_array's names
 * are declared by <GL/glext.h> only with GL_GLEXT_PROTOTYPES (which also
 * exports them: GLAPI) */
#define GL_GLEXT_PROTOTYPES 1
#include <stddef.h>

#include "main/dlist.h"
#include "main/groups.h"
#include "tnl/t_pipeline.h"

/* Only the BeginEnd dispatch table's generic_nop refuses the client-state
 * entry points (pointers, glInterleavedArrays, glEnable/DisableClientState,
 * glGetPointerv) inside glBegin/glEnd: Mesa's functions have no check of
 * their own, so they use ASSERT_OUTSIDE_BEGIN_END_DISPATCH (context.h):
 * while a list is compiled they run, also when a GL_COMPILE_AND_EXECUTE
 * list has left the executed glBegin open (a primitive wrapped by the
 * compiler runs by loopback up to the wrap; its glEnd runs when the rest
 * is compiled) [S: vbo/vbo_exec_api.c:vbo_exec_Begin keeps the save table,
 * main/enable.c:_mesa_EnableClientState, main/varray.c:_mesa_VertexPointer,
 * main/getstring.c:_mesa_GetPointerv]. */

/* Mesa's type bits [S: main/varray.c:type_to_bit] for the legal types of
 * each array on the desktop compatibility profile, limited to GL 1.5: the
 * oracle's GL_HALF_FLOAT (GL 3.0 / ARB_half_float_vertex) and
 * GL_(UNSIGNED_)INT_2_10_10_10_REV (GL 3.3 / ARB_vertex_type_2_10_10_10_rev)
 * have no bit, so they fail the type check with GL_INVALID_ENUM where the
 * oracle checks its legal types (README "Version and honesty") */
#define B_BYTE    (1u << 0)
#define B_UBYTE   (1u << 1)
#define B_SHORT   (1u << 2)
#define B_USHORT  (1u << 3)
#define B_INT     (1u << 4)
#define B_UINT    (1u << 5)
#define B_FLOAT   (1u << 7)
#define B_DOUBLE  (1u << 8)

static unsigned type_bit(GLenum type)
{
   switch (type) {
   case GL_BYTE: return B_BYTE;
   case GL_UNSIGNED_BYTE: return B_UBYTE;
   case GL_SHORT: return B_SHORT;
   case GL_UNSIGNED_SHORT: return B_USHORT;
   case GL_INT: return B_INT;
   case GL_UNSIGNED_INT: return B_UINT;
   case GL_FLOAT: return B_FLOAT;
   case GL_DOUBLE: return B_DOUBLE;
   default: return 0;
   }
}

/* _mesa_bytes_per_vertex_attrib */
static GLsizei element_size(GLenum type, GLint size)
{
   switch (type) {
   case GL_BYTE: case GL_UNSIGNED_BYTE: return size;
   case GL_SHORT: case GL_UNSIGNED_SHORT: return 2 * size;
   case GL_DOUBLE: return 8 * size;
   default: return 4 * size;
   }
}

void fgl_init_array(struct fgl_context *ctx)
{
   /* [S: main/arrayobj.c:init_array] */
   static const struct { GLint size; GLenum type; } init[FGL_ARRAY_COUNT] = {
      [FGL_ARRAY_VERTEX] = { 4, GL_FLOAT },
      [FGL_ARRAY_NORMAL] = { 3, GL_FLOAT },
      [FGL_ARRAY_COLOR] = { 4, GL_FLOAT },
      [FGL_ARRAY_INDEX] = { 1, GL_FLOAT },
      [FGL_ARRAY_TEXCOORD] = { 4, GL_FLOAT },
      [FGL_ARRAY_EDGEFLAG] = { 1, GL_UNSIGNED_BYTE },
      [FGL_ARRAY_FOGCOORD] = { 1, GL_FLOAT },
      [FGL_ARRAY_COLOR1] = { 3, GL_FLOAT },
      [FGL_ARRAY_TEXCOORD1 + 0] = { 4, GL_FLOAT }, [FGL_ARRAY_TEXCOORD1 + 1] = { 4, GL_FLOAT },
      [FGL_ARRAY_TEXCOORD1 + 2] = { 4, GL_FLOAT }, [FGL_ARRAY_TEXCOORD1 + 3] = { 4, GL_FLOAT },
      [FGL_ARRAY_TEXCOORD1 + 4] = { 4, GL_FLOAT }, [FGL_ARRAY_TEXCOORD1 + 5] = { 4, GL_FLOAT },
      [FGL_ARRAY_TEXCOORD1 + 6] = { 4, GL_FLOAT },
   };
   for (int i = 0; i < FGL_ARRAY_COUNT; i++) {
      ctx->Array.Array[i] = (struct fgl_client_array){
         .Enabled = false, .Size = init[i].size,
         .Type = init[i].type, .Stride = 0,
         .EffStride = element_size(init[i].type, init[i].size), .Ptr = NULL,
      };
   }
}

/* update_array: the arrays are read at draw time, nothing stored needs a
 * flush */
static void update_array(struct fgl_context *ctx, enum fgl_array_index a, GLint size,
                         GLenum type, GLsizei stride, const GLvoid *ptr)
{
   struct fgl_client_array *arr = &ctx->Array.Array[a];
   arr->Size = size;
   arr->Type = type;
   arr->Stride = stride;
   arr->EffStride = stride ? stride : element_size(type, size);
   arr->Ptr = ptr;
   /* the pointer is an offset into the GL_ARRAY_BUFFER bound now
    * [S: varray.c:update_array, _mesa_bind_vertex_buffer] */
   fgl_buffer_reference(ctx, &arr->BufferObj, ctx->Array.ArrayBufferObj);
}

/* validate_array_and_format then update_array [S: main/varray.c].  Note
 * that validate_array's errors (a negative stride) do not stop the update:
 * only validate_array_format's do.  Its order: the type (GL_INVALID_ENUM),
 * then the size (GL_INVALID_VALUE).  GL_BGRA as the size of glColorPointer
 * and glSecondaryColorPointer is GL 3.2's (ARB/EXT_vertex_array_bgra, not
 * listed): without the extension the oracle's get_array_format leaves the
 * size as given and the size range check refuses it with GL_INVALID_VALUE,
 * as GL 1.5 does for a bad size. */
static void pointer(enum fgl_array_index a, unsigned legal, GLint size_min,
                    GLint size_max, GLint size, GLenum type,
                    GLsizei stride, const GLvoid *ptr)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (stride < 0)
      fgl_error(ctx, GL_INVALID_VALUE);
   if (!(type_bit(type) & legal)) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (size < size_min || size > size_max) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   update_array(ctx, a, size, type, stride, ptr);
}

void GLAPIENTRY glVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
   pointer(FGL_ARRAY_VERTEX, B_SHORT | B_INT | B_FLOAT | B_DOUBLE, 2, 4, size, type, stride, ptr);
}

void GLAPIENTRY glNormalPointer(GLenum type, GLsizei stride, const GLvoid *ptr)
{
   pointer(FGL_ARRAY_NORMAL, B_BYTE | B_SHORT | B_INT | B_FLOAT | B_DOUBLE, 3, 3, 3, type, stride, ptr);
}

void GLAPIENTRY glColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
   pointer(FGL_ARRAY_COLOR, B_BYTE | B_UBYTE | B_SHORT | B_USHORT | B_INT | B_UINT |
           B_FLOAT | B_DOUBLE, 3, 4,
           size, type, stride, ptr);
}

/* state only: colour index arrays never draw in RGBA mode */
void GLAPIENTRY glIndexPointer(GLenum type, GLsizei stride, const GLvoid *ptr)
{
   pointer(FGL_ARRAY_INDEX, B_UBYTE | B_SHORT | B_INT | B_FLOAT | B_DOUBLE, 1, 1,
           1, type, stride, ptr);
}

/* the client active unit's array [S: varray.c:_mesa_TexCoordPointer:
 * VERT_ATTRIB_TEX(ctx->Array.ActiveTexture)] */
void GLAPIENTRY glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   pointer(FGL_ARRAY_TEX(ctx->Array.ActiveTexture), B_SHORT | B_INT | B_FLOAT | B_DOUBLE, 1, 4, size, type, stride, ptr);
}

void GLAPIENTRY glEdgeFlagPointer(GLsizei stride, const GLvoid *ptr)
{
   pointer(FGL_ARRAY_EDGEFLAG, B_UBYTE, 1, 1, 1, GL_UNSIGNED_BYTE, stride, ptr);
}

/* glSecondaryColorPointer (GL 1.4, EXT alias): three or four components
 * or GL_BGRA [S: main/varray.c:_mesa_SecondaryColorPointer: sizes 3 to
 * BGRA_OR_4, normalized] */
void GLAPIENTRY glSecondaryColorPointer(GLint size, GLenum type, GLsizei stride,
                                        const GLvoid *ptr)
{
   pointer(FGL_ARRAY_COLOR1, B_BYTE | B_UBYTE | B_SHORT | B_USHORT | B_INT | B_UINT |
           B_FLOAT | B_DOUBLE, 3, 4,
           size, type, stride, ptr);
}

void GLAPIENTRY glSecondaryColorPointerEXT(GLint size, GLenum type, GLsizei stride,
                                           const GLvoid *ptr)
{
   glSecondaryColorPointer(size, type, stride, ptr);
}

/* glFogCoordPointer (GL 1.4, EXT alias): one float component
 * [S: main/varray.c:_mesa_FogCoordPointer] */
void GLAPIENTRY glFogCoordPointer(GLenum type, GLsizei stride, const GLvoid *ptr)
{
   pointer(FGL_ARRAY_FOGCOORD, B_FLOAT | B_DOUBLE, 1, 1, 1, type, stride, ptr);
}

void GLAPIENTRY glFogCoordPointerEXT(GLenum type, GLsizei stride, const GLvoid *ptr)
{
   glFogCoordPointer(type, stride, ptr);
}

/* glInterleavedArrays [S: main/varray.c:_mesa_InterleavedArrays,
 * _mesa_get_interleaved_layout]: the arrays of the format enabled with
 * their pointers (a stride of 0 becomes the format's stride, which the
 * stride queries then return), the others disabled. */
void GLAPIENTRY glInterleavedArrays(GLenum format, GLsizei stride, const GLvoid *pointer)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (stride < 0) {
      fgl_error(ctx, GL_INVALID_VALUE);
      return;
   }
   const int f = (int)sizeof(GLfloat), c = 4;
   /* t, c, v components; colour type; colour, normal, vertex offsets;
    * default stride */
   int tc = 0, cc = 0, vc = 0, coff = 0, noff = 0, voff = 0, def = 0;
   bool nflag = false;
   GLenum ctype = GL_FLOAT;
   switch (format) {
   case GL_V2F: vc = 2; def = 2 * f; break;
   case GL_V3F: vc = 3; def = 3 * f; break;
   case GL_C4UB_V2F: cc = 4; vc = 2; ctype = GL_UNSIGNED_BYTE; voff = c; def = c + 2 * f; break;
   case GL_C4UB_V3F: cc = 4; vc = 3; ctype = GL_UNSIGNED_BYTE; voff = c; def = c + 3 * f; break;
   case GL_C3F_V3F: cc = 3; vc = 3; voff = 3 * f; def = 6 * f; break;
   case GL_N3F_V3F: nflag = true; vc = 3; voff = 3 * f; def = 6 * f; break;
   case GL_C4F_N3F_V3F:
      cc = 4; nflag = true; vc = 3; noff = 4 * f; voff = 7 * f; def = 10 * f;
      break;
   case GL_T2F_V3F: tc = 2; vc = 3; voff = 2 * f; def = 5 * f; break;
   case GL_T4F_V4F: tc = 4; vc = 4; voff = 4 * f; def = 8 * f; break;
   case GL_T2F_C4UB_V3F:
      tc = 2; cc = 4; vc = 3; ctype = GL_UNSIGNED_BYTE; coff = 2 * f; voff = c + 2 * f;
      def = c + 5 * f;
      break;
   case GL_T2F_C3F_V3F: tc = 2; cc = 3; vc = 3; coff = 2 * f; voff = 5 * f; def = 8 * f; break;
   case GL_T2F_N3F_V3F:
      tc = 2; nflag = true; vc = 3; noff = 2 * f; voff = 5 * f; def = 8 * f;
      break;
   case GL_T2F_C4F_N3F_V3F:
      tc = 2; cc = 4; nflag = true; vc = 3; coff = 2 * f; noff = 6 * f; voff = 9 * f;
      def = 12 * f;
      break;
   case GL_T4F_C4F_N3F_V4F:
      tc = 4; cc = 4; nflag = true; vc = 4; coff = 4 * f; noff = 8 * f; voff = 11 * f;
      def = 15 * f;
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   if (stride == 0)
      stride = def;
   const GLubyte *p = pointer;
   struct fgl_client_array *A = ctx->Array.Array;
   A[FGL_ARRAY_EDGEFLAG].Enabled = false;
   A[FGL_ARRAY_INDEX].Enabled = false;
   /* the client active unit's coordinate array */
   const enum fgl_array_index tex = FGL_ARRAY_TEX(ctx->Array.ActiveTexture);
   A[tex].Enabled = tc != 0;
   if (tc)
      update_array(ctx, tex, tc, GL_FLOAT, stride, p);
   A[FGL_ARRAY_COLOR].Enabled = cc != 0;
   if (cc)
      update_array(ctx, FGL_ARRAY_COLOR, cc, ctype, stride, p + coff);
   A[FGL_ARRAY_NORMAL].Enabled = nflag;
   if (nflag)
      update_array(ctx, FGL_ARRAY_NORMAL, 3, GL_FLOAT, stride, p + noff);
   A[FGL_ARRAY_VERTEX].Enabled = true;
   update_array(ctx, FGL_ARRAY_VERTEX, vc, GL_FLOAT, stride, p + voff);
}

struct fgl_client_array *fgl_client_array(struct fgl_context *ctx, GLenum cap)
{
   switch (cap) {
   case GL_VERTEX_ARRAY: return &ctx->Array.Array[FGL_ARRAY_VERTEX];
   case GL_NORMAL_ARRAY: return &ctx->Array.Array[FGL_ARRAY_NORMAL];
   case GL_COLOR_ARRAY: return &ctx->Array.Array[FGL_ARRAY_COLOR];
   case GL_INDEX_ARRAY: return &ctx->Array.Array[FGL_ARRAY_INDEX];
   case GL_TEXTURE_COORD_ARRAY:
      return &ctx->Array.Array[FGL_ARRAY_TEX(ctx->Array.ActiveTexture)];
   case GL_EDGE_FLAG_ARRAY: return &ctx->Array.Array[FGL_ARRAY_EDGEFLAG];
   /* GL 1.4 arrays (tnl/t_array.c fetches them) */
   case GL_FOG_COORD_ARRAY: return &ctx->Array.Array[FGL_ARRAY_FOGCOORD];
   case GL_SECONDARY_COLOR_ARRAY: return &ctx->Array.Array[FGL_ARRAY_COLOR1];
   default: return NULL;
   }
}

/* client_state [S: main/enable.c] */
static void client_state(GLenum cap, bool state)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   struct fgl_client_array *arr = fgl_client_array(ctx, cap);
   if (!arr) {
      fgl_error(ctx, GL_INVALID_ENUM);
      return;
   }
   arr->Enabled = state;
}

void GLAPIENTRY glEnableClientState(GLenum cap)
{
   client_state(cap, true);
}

void GLAPIENTRY glDisableClientState(GLenum cap)
{
   client_state(cap, false);
}

static int buffer_name(const struct fgl_buffer_object *obj)
{
   return obj ? (int)obj->Name : 0;
}

bool fgl_get_array_value(struct fgl_context *ctx, GLenum pname, int *value)
{
   const struct fgl_client_array *A = ctx->Array.Array;
   switch (pname) {
   case GL_VERTEX_ARRAY_SIZE: *value = A[FGL_ARRAY_VERTEX].Size; return true;
   case GL_VERTEX_ARRAY_TYPE: *value = (int)A[FGL_ARRAY_VERTEX].Type; return true;
   case GL_VERTEX_ARRAY_STRIDE: *value = A[FGL_ARRAY_VERTEX].Stride; return true;
   case GL_NORMAL_ARRAY_TYPE: *value = (int)A[FGL_ARRAY_NORMAL].Type; return true;
   case GL_NORMAL_ARRAY_STRIDE: *value = A[FGL_ARRAY_NORMAL].Stride; return true;
   case GL_COLOR_ARRAY_SIZE: *value = A[FGL_ARRAY_COLOR].Size; return true;
   case GL_COLOR_ARRAY_TYPE: *value = (int)A[FGL_ARRAY_COLOR].Type; return true;
   case GL_COLOR_ARRAY_STRIDE: *value = A[FGL_ARRAY_COLOR].Stride; return true;
   case GL_INDEX_ARRAY_TYPE: *value = (int)A[FGL_ARRAY_INDEX].Type; return true;
   case GL_INDEX_ARRAY_STRIDE: *value = A[FGL_ARRAY_INDEX].Stride; return true;
   /* the client active unit's */
   case GL_TEXTURE_COORD_ARRAY_SIZE: *value = A[FGL_ARRAY_TEX(ctx->Array.ActiveTexture)].Size; return true;
   case GL_TEXTURE_COORD_ARRAY_TYPE: *value = (int)A[FGL_ARRAY_TEX(ctx->Array.ActiveTexture)].Type; return true;
   case GL_TEXTURE_COORD_ARRAY_STRIDE: *value = A[FGL_ARRAY_TEX(ctx->Array.ActiveTexture)].Stride; return true;
   case GL_EDGE_FLAG_ARRAY_STRIDE: *value = A[FGL_ARRAY_EDGEFLAG].Stride; return true;
   case GL_FOG_COORD_ARRAY_TYPE: *value = (int)A[FGL_ARRAY_FOGCOORD].Type; return true;
   case GL_FOG_COORD_ARRAY_STRIDE: *value = A[FGL_ARRAY_FOGCOORD].Stride; return true;
   case GL_SECONDARY_COLOR_ARRAY_SIZE:
      *value = A[FGL_ARRAY_COLOR1].Size;
      return true;
   case GL_SECONDARY_COLOR_ARRAY_TYPE: *value = (int)A[FGL_ARRAY_COLOR1].Type; return true;
   case GL_SECONDARY_COLOR_ARRAY_STRIDE: *value = A[FGL_ARRAY_COLOR1].Stride; return true;
   /* GL_EXT_vertex_array counts: CONST(0) [S: main/get_hash_params.py] */
   case GL_VERTEX_ARRAY_COUNT_EXT:
   case GL_NORMAL_ARRAY_COUNT_EXT:
   case GL_COLOR_ARRAY_COUNT_EXT:
   case GL_INDEX_ARRAY_COUNT_EXT:
   case GL_TEXTURE_COORD_ARRAY_COUNT_EXT:
   case GL_EDGE_FLAG_ARRAY_COUNT_EXT:
      *value = 0;
      return true;
   case GL_CLIENT_ACTIVE_TEXTURE: *value = GL_TEXTURE0 + (int)ctx->Array.ActiveTexture; return true;
   /* GL 1.5: the buffers bound to the targets and to each array (a
    * deleted one still bound to an array keeps its name) */
   case GL_ARRAY_BUFFER_BINDING: *value = buffer_name(ctx->Array.ArrayBufferObj); return true;
   case GL_ELEMENT_ARRAY_BUFFER_BINDING: *value = buffer_name(ctx->Array.ElementBufferObj); return true;
   case GL_VERTEX_ARRAY_BUFFER_BINDING: *value = buffer_name(A[FGL_ARRAY_VERTEX].BufferObj); return true;
   case GL_NORMAL_ARRAY_BUFFER_BINDING: *value = buffer_name(A[FGL_ARRAY_NORMAL].BufferObj); return true;
   case GL_COLOR_ARRAY_BUFFER_BINDING: *value = buffer_name(A[FGL_ARRAY_COLOR].BufferObj); return true;
   case GL_INDEX_ARRAY_BUFFER_BINDING: *value = buffer_name(A[FGL_ARRAY_INDEX].BufferObj); return true;
   case GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING:
      *value = buffer_name(A[FGL_ARRAY_TEX(ctx->Array.ActiveTexture)].BufferObj);
      return true;
   case GL_EDGE_FLAG_ARRAY_BUFFER_BINDING: *value = buffer_name(A[FGL_ARRAY_EDGEFLAG].BufferObj); return true;
   case GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING: *value = buffer_name(A[FGL_ARRAY_COLOR1].BufferObj); return true;
   case GL_FOG_COORD_ARRAY_BUFFER_BINDING: *value = buffer_name(A[FGL_ARRAY_FOGCOORD].BufferObj); return true;
   default: return false;
   }
}

void GLAPIENTRY glGetPointerv(GLenum pname, GLvoid **params)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   ASSERT_OUTSIDE_BEGIN_END_DISPATCH(ctx);
   if (!params)
      return;
   const struct fgl_client_array *A = ctx->Array.Array;
   switch (pname) {
   case GL_VERTEX_ARRAY_POINTER: *params = (GLvoid *)A[FGL_ARRAY_VERTEX].Ptr; break;
   case GL_NORMAL_ARRAY_POINTER: *params = (GLvoid *)A[FGL_ARRAY_NORMAL].Ptr; break;
   case GL_COLOR_ARRAY_POINTER: *params = (GLvoid *)A[FGL_ARRAY_COLOR].Ptr; break;
   case GL_INDEX_ARRAY_POINTER: *params = (GLvoid *)A[FGL_ARRAY_INDEX].Ptr; break;
   case GL_TEXTURE_COORD_ARRAY_POINTER:
      *params = (GLvoid *)A[FGL_ARRAY_TEX(ctx->Array.ActiveTexture)].Ptr;
      break;
   case GL_EDGE_FLAG_ARRAY_POINTER: *params = (GLvoid *)A[FGL_ARRAY_EDGEFLAG].Ptr; break;
   /* main/feedback.c */
   case GL_FEEDBACK_BUFFER_POINTER: *params = (GLvoid *)ctx->Feedback.Buffer; break;
   case GL_SELECTION_BUFFER_POINTER: *params = (GLvoid *)ctx->Select.Buffer; break;
   case GL_FOG_COORD_ARRAY_POINTER: *params = (GLvoid *)A[FGL_ARRAY_FOGCOORD].Ptr; break;
   case GL_SECONDARY_COLOR_ARRAY_POINTER: *params = (GLvoid *)A[FGL_ARRAY_COLOR1].Ptr; break;
   /* GL_KHR_debug's callback and its parameter: fixgl has no
    * glDebugMessageCallback, so they stay NULL as the oracle's default */
   case GL_DEBUG_CALLBACK_FUNCTION:
   case GL_DEBUG_CALLBACK_USER_PARAM:
      *params = NULL;
      break;
   default:
      fgl_error(ctx, GL_INVALID_ENUM);
      break;
   }
}

/* ---- drawing ---- */

/* valid_prim_mode_custom [S: main/draw.c] for GL 1.5: its ten modes.
 * (The oracle's 4.5 context also takes the adjacency modes, and patches
 * with GL_INVALID_OPERATION: README "Version and honesty".) */
static GLenum valid_prim_mode(GLenum mode)
{
   return mode > GL_POLYGON ? GL_INVALID_ENUM : GL_NO_ERROR;
}

/* validate_DrawElements_common [S: main/draw.c]: count, mode, then the
 * index type. */
static GLenum validate_draw_elements(GLenum mode, GLsizei count, GLenum type)
{
   const GLenum err = count < 0 ? GL_INVALID_VALUE : valid_prim_mode(mode);
   if (err)
      return err;
   return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT ||
          type == GL_UNSIGNED_INT ? GL_NO_ERROR : GL_INVALID_ENUM;
}

void GLAPIENTRY glDrawArrays(GLenum mode, GLint first, GLsizei count)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      fgl_save_draw_arrays(ctx, mode, first, count);
      return;
   }
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_flush_for_draw(ctx);
   t_set_draw_inputs(ctx);
   GLenum err = count < 0 ? GL_INVALID_VALUE : valid_prim_mode(mode);
   if (err) {
      fgl_error(ctx, err);
      return;
   }
   t_draw_arrays(ctx, mode, first, count, 0, NULL);
}

void GLAPIENTRY glDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid *indices)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      fgl_save_draw_elements(ctx, mode, count, type, indices);
      return;
   }
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_flush_for_draw(ctx);
   t_set_draw_inputs(ctx);
   const GLenum err = validate_draw_elements(mode, count, type);
   if (err) {
      fgl_error(ctx, err);
      return;
   }
   t_draw_arrays(ctx, mode, 0, count, type, indices);
}

void GLAPIENTRY glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                    GLenum type, const GLvoid *indices)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      fgl_save_draw_range_elements(ctx, mode, start, end, count, type, indices);
      return;
   }
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_flush_for_draw(ctx);
   t_set_draw_inputs(ctx);
   /* _mesa_validate_DrawRangeElements: end < start first */
   const GLenum err = end < start ? GL_INVALID_VALUE
                                  : validate_draw_elements(mode, count, type);
   if (err) {
      fgl_error(ctx, err);
      return;
   }
   /* the range only bounds what the driver uploads; callers must keep
    * their indices inside it (out-of-range fetches are undefined) */
   t_draw_arrays(ctx, mode, 0, count, type, indices);
}

/* Draw i of n of one driver call (i == n: after the call) */
static void multi_draw(struct fgl_context *ctx, GLsizei i, GLsizei n)
{
   ctx->_MultiDrawCont = i > 0 && i < n;
   ctx->_MultiDrawMore = i + 1 < n;
}

/* glMultiDrawArrays (GL 1.4) and its EXT alias [S: main/draw.c:
 * _mesa_MultiDrawArrays, main/api_validate.c:
 * _mesa_validate_MultiDrawArrays]: the draw count, the mode, then each
 * count (gl14/multidraw_dlist_errors); every draw then goes to the driver
 * in one call, which llvmpipe skips whole when the first draw is empty
 * (llvmpipe_draw_vbo: !draws[0].count; ORACLE-NOTES.md "GL 1.4 vertex
 * attributes and operations").  fixgl draws them one after the other as
 * one draw (multi_draw). */
void GLAPIENTRY glMultiDrawArrays(GLenum mode, const GLint *first, const GLsizei *count,
                                  GLsizei n)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      fgl_save_multi_draw_arrays(ctx, mode, first, count, n);
      return;
   }
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_flush_for_draw(ctx);
   t_set_draw_inputs(ctx);
   GLenum err = n < 0 ? GL_INVALID_VALUE : valid_prim_mode(mode);
   for (GLsizei i = 0; !err && i < n; i++)
      if (count[i] < 0)
         err = GL_INVALID_VALUE;
   if (err) {
      fgl_error(ctx, err);
      return;
   }
   if (n == 0 || count[0] == 0)
      return;
   for (GLsizei i = 0; i < n; i++) {
      multi_draw(ctx, i, n);
      t_draw_arrays(ctx, mode, first[i], count[i], 0, NULL);
   }
   multi_draw(ctx, n, n);
   t_vbuf_end_draw(ctx);   /* (closed already unless the last draws were empty) */
}

void GLAPIENTRY glMultiDrawArraysEXT(GLenum mode, const GLint *first, const GLsizei *count,
                                     GLsizei n)
{
   glMultiDrawArrays(mode, first, count, n);
}

/* glMultiDrawElements (GL 1.4) and its EXT alias [S: main/draw.c:
 * _mesa_MultiDrawElementsEXT, _mesa_validated_multidrawelements;
 * main/api_validate.c:_mesa_validate_MultiDrawElements]: the draw count,
 * the mode, the index type, then each count are checked; a NULL index
 * pointer cancels the whole call without an error when the indices are
 * the client's (with an element buffer it is offset 0).  The
 * draws whose index pointers are a whole number of indices apart are one
 * driver call (skipped whole when the first is empty, as
 * glMultiDrawArrays); otherwise each non-empty draw is a call of its
 * own. */
void GLAPIENTRY glMultiDrawElements(GLenum mode, const GLsizei *count, GLenum type,
                                    const GLvoid *const *indices, GLsizei n)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   if (ctx->CompileFlag) {
      fgl_save_multi_draw_elements(ctx, mode, count, type, indices, n);
      return;
   }
   ASSERT_OUTSIDE_BEGIN_END(ctx);
   fgl_flush_for_draw(ctx);
   t_set_draw_inputs(ctx);
   GLenum err = n < 0 ? GL_INVALID_VALUE : valid_prim_mode(mode);
   if (!err && type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT &&
       type != GL_UNSIGNED_INT)
      err = GL_INVALID_ENUM;
   for (GLsizei i = 0; !err && i < n; i++)
      if (count[i] < 0)
         err = GL_INVALID_VALUE;
   if (err) {
      fgl_error(ctx, err);
      return;
   }
   /* only client indices: with an element buffer bound, 0 is an offset
    * (ORACLE-NOTES.md "GL 1.4 vertex attributes and operations";
    * api_validate.c: !VAO->IndexBufferObj) */
   if (!ctx->Array.ElementBufferObj)
      for (GLsizei i = 0; i < n; i++)
         if (!indices[i])
            return;
   if (n == 0)
      return;
   /* one driver call when every pointer is a whole number of indices from
    * the lowest one */
   const uintptr_t size = type == GL_UNSIGNED_BYTE ? 1u : type == GL_UNSIGNED_SHORT ? 2u : 4u;
   uintptr_t min_ptr = (uintptr_t)indices[0];
   for (GLsizei i = 1; i < n; i++)
      if ((uintptr_t)indices[i] < min_ptr)
         min_ptr = (uintptr_t)indices[i];
   bool one_call = true;
   for (GLsizei i = 0; i < n; i++)
      if (((uintptr_t)indices[i] - min_ptr) % size != 0)
         one_call = false;
   if (one_call && count[0] == 0)
      return;
   /* (one call: draws as one; the empty ones are no draws of vsplit's) */
   GLsizei last = -1;
   for (GLsizei i = 0; i < n; i++)
      if (count[i] > 0)
         last = i;
   bool first_done = false;
   for (GLsizei i = 0; i < n; i++) {
      if (count[i] <= 0)
         continue;
      if (one_call) {
         ctx->_MultiDrawCont = first_done;
         ctx->_MultiDrawMore = i != last;
      }
      t_draw_arrays(ctx, mode, 0, count[i], type, indices[i]);
      first_done = true;
   }
   multi_draw(ctx, n, n);
   t_vbuf_end_draw(ctx);   /* (closed already unless the last draws were empty) */
}

void GLAPIENTRY glMultiDrawElementsEXT(GLenum mode, const GLsizei *count, GLenum type,
                                       const GLvoid *const *indices, GLsizei n)
{
   glMultiDrawElements(mode, count, type, indices, n);
}

void GLAPIENTRY glArrayElement(GLint i)
{
   GET_CURRENT_CONTEXT(ctx);
   if (!ctx)
      return;
   t_array_element(ctx, i);
}

/* ---- GL_EXT_vertex_array's names [S: main/varray.c:_mesa_VertexPointerEXT
 * and its siblings]: the count is ignored ---- */

void GLAPIENTRY glVertexPointerEXT(GLint size, GLenum type, GLsizei stride, GLsizei count,
                                   const GLvoid *ptr)
{
   (void)count;
   glVertexPointer(size, type, stride, ptr);
}

void GLAPIENTRY glNormalPointerEXT(GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr)
{
   (void)count;
   glNormalPointer(type, stride, ptr);
}

void GLAPIENTRY glColorPointerEXT(GLint size, GLenum type, GLsizei stride, GLsizei count,
                                  const GLvoid *ptr)
{
   (void)count;
   glColorPointer(size, type, stride, ptr);
}

void GLAPIENTRY glIndexPointerEXT(GLenum type, GLsizei stride, GLsizei count, const GLvoid *ptr)
{
   (void)count;
   glIndexPointer(type, stride, ptr);
}

void GLAPIENTRY glTexCoordPointerEXT(GLint size, GLenum type, GLsizei stride, GLsizei count,
                                     const GLvoid *ptr)
{
   (void)count;
   glTexCoordPointer(size, type, stride, ptr);
}

void GLAPIENTRY glEdgeFlagPointerEXT(GLsizei stride, GLsizei count, const GLboolean *ptr)
{
   (void)count;
   glEdgeFlagPointer(stride, ptr);
}

void GLAPIENTRY glGetPointervEXT(GLenum pname, GLvoid **params)
{
   glGetPointerv(pname, params);
}

void GLAPIENTRY glArrayElementEXT(GLint i)
{
   glArrayElement(i);
}

void GLAPIENTRY glDrawArraysEXT(GLenum mode, GLint first, GLsizei count)
{
   glDrawArrays(mode, first, count);
}
