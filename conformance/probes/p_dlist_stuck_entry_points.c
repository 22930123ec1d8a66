/* p_dlist_stuck_entry_points.c - which entry points the oracle refuses
 * while a display list has left it "inside glBegin/glEnd" (the defect of
 * p_dlist_stuck: a vertex list that ends mid-primitive sets
 * CurrentExecPrimitive in playback_copy_to_current, and nothing switches
 * ctx->Exec or the current dispatch to the BeginEnd table).  Only the
 * entry points with a begin/end check of their own (ASSERT_OUTSIDE_BEGIN_END
 * in the function: glGetError, glGetString, glIsEnabled, the display-list
 * calls, glFinish/glFlush, glIsTexture...) raise GL_INVALID_OPERATION;
 * every other one runs, since only the BeginEnd table's generic_nop would
 * have refused it (ORACLE-NOTES.md "OSMesa defects kept visible").
 *
 * Each check runs in a context of its own: the call raises no error
 * outside glBegin/glEnd; after the list it raises GL_INVALID_OPERATION or
 * nothing, read after the glEnd that leaves the stuck state (glGetError
 * itself refuses and returns 0 while stuck). */
#include "probe.h"

static const float va[3][2] = { { 1, 1 }, { 15, 1 }, { 1, 15 } };
static const GLuint idx[3] = { 0, 1, 2 };
static GLubyte img[64 * 64 * 4];
static GLfloat fb[64];
static GLuint ub[64];
static GLdouble pts[16] = { 0, 0, 0, 1, 1, 1 };
static GLubyte cbuf[32 * 32 * 4];

/* name, 1 if refused while stuck, the call */
#define CALLS \
 X(ClearAccum, 0, glClearAccum(0.1f,0,0,0)) \
 X(Accum, 0, glAccum(GL_ACCUM, 0.5f)) \
 X(PushAttrib, 0, glPushAttrib(GL_ALL_ATTRIB_BITS)) \
 X(PopAttrib, 0, glPopAttrib()) \
 X(Rectf, 1, glRectf(0,0,5,5)) \
 X(AlphaFunc, 0, glAlphaFunc(GL_LESS, 0.5f)) \
 X(BlendColor, 0, glBlendColor(0.5f,0.5f,0.5f,0.5f)) \
 X(BlendEquation, 0, glBlendEquation(GL_FUNC_SUBTRACT)) \
 X(BlendEquationSeparate, 0, glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_FUNC_ADD)) \
 X(BlendFunc, 0, glBlendFunc(GL_ONE, GL_ONE)) \
 X(BlendFuncSeparate, 0, glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE)) \
 X(ColorMask, 0, glColorMask(1,0,1,0)) \
 X(LogicOp, 0, glLogicOp(GL_XOR)) \
 X(IsBuffer, 1, glIsBuffer(1)) \
 X(DrawBuffer, 0, glDrawBuffer(GL_FRONT)) \
 X(ReadBuffer, 0, glReadBuffer(GL_FRONT)) \
 X(Clear, 0, glClear(GL_COLOR_BUFFER_BIT)) \
 X(ClearColor, 0, glClearColor(0.5f,0,0,0)) \
 X(ClipPlane, 0, glClipPlane(GL_CLIP_PLANE0, pts)) \
 X(ClearIndex, 0, glClearIndex(2)) \
 X(IndexMask, 0, glIndexMask(3)) \
 X(ClearDepth, 0, glClearDepth(0.5)) \
 X(DepthFunc, 0, glDepthFunc(GL_GREATER)) \
 X(DepthMask, 0, glDepthMask(0)) \
 X(DeleteLists, 1, glDeleteLists(100, 2)) \
 X(GenLists, 1, glGenLists(1)) \
 X(IsList, 1, glIsList(1)) \
 X(ListBase, 1, glListBase(3)) \
 X(NewList, 1, glNewList(50, GL_COMPILE)) \
 X(Bitmap, 0, glBitmap(8,1,0,0,1,1,img)) \
 X(CopyPixels, 0, glCopyPixels(0,0,4,4,GL_COLOR)) \
 X(DrawPixels, 0, glDrawPixels(2,2,GL_RGBA,GL_UNSIGNED_BYTE,img)) \
 X(Enable, 0, glEnable(GL_BLEND)) \
 X(Disable, 0, glDisable(GL_DITHER)) \
 X(IsEnabled, 1, glIsEnabled(GL_BLEND)) \
 X(EvalMesh1, 0, glEvalMesh1(GL_POINT, 0, 1)) \
 X(EvalMesh, 0, glEvalMesh2(GL_POINT, 0, 1, 0, 1)) \
 X(MapGrid1f, 0, glMapGrid1f(2, 0, 1)) \
 X(MapGrid2f, 0, glMapGrid2f(2, 0, 1, 2, 0, 1)) \
 X(Map1d, 0, glMap1d(GL_MAP1_VERTEX_3, 0, 1, 3, 2, pts)) \
 X(Map2d, 0, glMap2d(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 1, pts)) \
 X(InitNames, 0, glInitNames()) \
 X(LoadName, 0, glLoadName(1)) \
 X(PassThrough, 0, glPassThrough(1)) \
 X(PopName, 0, glPopName()) \
 X(PushName, 0, glPushName(1)) \
 X(RenderMode, 1, glRenderMode(GL_RENDER)) \
 X(Fogfv, 0, glFogf(GL_FOG_DENSITY, 0.5f)) \
 X(GetString, 1, glGetString(GL_VENDOR)) \
 X(Hint, 0, glHint(GL_FOG_HINT, GL_NICEST)) \
 X(ColorMaterial, 0, glColorMaterial(GL_FRONT, GL_AMBIENT)) \
 X(LightModelfv, 0, glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1)) \
 X(Lightfv, 0, glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 2)) \
 X(ShadeModel, 0, glShadeModel(GL_FLAT)) \
 X(Materialf, 0, glMaterialf(GL_FRONT, GL_SHININESS, 2)) \
 X(LineStipple, 0, glLineStipple(2, 0xf0f0)) \
 X(LineWidth, 0, glLineWidth(2)) \
 X(Frustum, 0, glFrustum(-1,1,-1,1,1,2)) \
 X(LoadMatrixf, 0, glLoadMatrixf(fb)) \
 X(LoadIdentity, 0, glLoadIdentity()) \
 X(MatrixMode, 0, glMatrixMode(GL_TEXTURE)) \
 X(MultMatrixf, 0, glMultMatrixf(fb)) \
 X(Ortho, 0, glOrtho(-1,1,-1,1,1,2)) \
 X(PopMatrix, 0, glPopMatrix()) \
 X(PushMatrix, 0, glPushMatrix()) \
 X(Rotatef, 0, glRotatef(1,0,0,1)) \
 X(Translatef, 0, glTranslatef(1,0,0)) \
 X(Scalef, 0, glScalef(1,2,1)) \
 X(Finish, 1, glFinish()) \
 X(Flush, 1, glFlush()) \
 X(SampleCoverage, 0, glSampleCoverage(0.5f, 0)) \
 X(PixelTransferf, 0, glPixelTransferf(GL_RED_SCALE, 2)) \
 X(PixelZoom, 0, glPixelZoom(2, 2)) \
 X(PixelMapfv, 0, glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 1, fb)) \
 X(PixelMapuiv, 0, glPixelMapuiv(GL_PIXEL_MAP_R_TO_R, 1, ub)) \
 X(PointSize, 0, glPointSize(2)) \
 X(PointParameterf, 0, glPointParameterf(GL_POINT_SIZE_MIN, 2)) \
 X(CullFace, 0, glCullFace(GL_FRONT)) \
 X(FrontFace, 0, glFrontFace(GL_CW)) \
 X(PolygonMode, 0, glPolygonMode(GL_FRONT, GL_LINE)) \
 X(PolygonOffset, 0, glPolygonOffset(1, 1)) \
 X(PolygonStipple, 0, glPolygonStipple(img)) \
 X(IsQuery, 1, glIsQuery(1)) \
 X(BeginQuery, 0, glBeginQuery(GL_SAMPLES_PASSED, 5)) \
 X(RasterPos2f, 0, glRasterPos2f(1, 1)) \
 X(WindowPos2f, 0, glWindowPos2f(1, 1)) \
 X(Scissor, 0, glScissor(0, 0, 5, 5)) \
 X(ClearStencil, 0, glClearStencil(1)) \
 X(StencilFunc, 0, glStencilFunc(GL_LESS, 1, 1)) \
 X(StencilMask, 0, glStencilMask(1)) \
 X(StencilOp, 0, glStencilOp(GL_KEEP, GL_KEEP, GL_INCR)) \
 X(CopyTexImage2D, 0, glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0)) \
 X(TexImage2D, 0, glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img)) \
 X(TexImage1D, 0, glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img)) \
 X(TexSubImage2D, 0, glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, img)) \
 X(CopyTexSubImage2D, 0, glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1)) \
 X(ActiveTexture, 0, glActiveTexture(GL_TEXTURE1)) \
 X(DrawArrays, 0, glDrawArrays(GL_TRIANGLES, 0, 3)) \
 X(DrawElements, 0, glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, idx)) \
 X(DepthRange, 0, glDepthRange(0.2, 0.8)) \
 X(Viewport, 0, glViewport(0, 0, 20, 20)) \
 X(GetError, 1, glGetError()) \
 X(GetIntegerv, 0, glGetIntegerv(GL_VIEWPORT, (GLint *)ub)) \
 X(GetTexParameterfv, 0, glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, fb)) \
 X(TexParameteri, 0, glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST)) \
 X(TexEnvi, 0, glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL)) \
 X(TexGeni, 0, glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR)) \
 X(BindTexture, 0, glBindTexture(GL_TEXTURE_2D, 3)) \
 X(GenTextures, 0, glGenTextures(1, ub)) \
 X(DeleteTextures, 0, glDeleteTextures(1, ub+10)) \
 X(PixelStorei, 0, glPixelStorei(GL_UNPACK_ALIGNMENT, 1)) \
 X(ReadPixels, 0, glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, img)) \
 X(VertexPointer, 0, glVertexPointer(2, GL_FLOAT, 0, va)) \
 X(EnableClientState, 0, glEnableClientState(GL_COLOR_ARRAY)) \
 X(ClientActiveTexture, 0, glClientActiveTexture(GL_TEXTURE1)) \
 X(PushClientAttrib, 0, glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS)) \
 X(GetPointerv, 0, glGetPointerv(GL_VERTEX_ARRAY_POINTER, (void **)fb)) \
 X(SelectBuffer, 0, glSelectBuffer(8, ub)) \
 X(FeedbackBuffer, 0, glFeedbackBuffer(8, GL_2D, fb)) \
 X(GetLightfv, 0, glGetLightfv(GL_LIGHT0, GL_AMBIENT, fb)) \
 X(GetMaterialfv, 0, glGetMaterialfv(GL_FRONT, GL_AMBIENT, fb)) \
 X(GetTexImage, 0, glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img)) \
 X(GetTexLevelParameteriv, 0, glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, (GLint *)ub)) \
 X(GetPixelMapfv, 0, glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, fb)) \
 X(GetMapdv, 0, glGetMapdv(GL_MAP1_VERTEX_3, GL_ORDER, (GLdouble *)fb)) \
 X(GetClipPlane, 0, glGetClipPlane(GL_CLIP_PLANE0, (GLdouble *)fb)) \
 X(GetPolygonStipple, 0, glGetPolygonStipple(img)) \
 X(GetTexEnvfv, 0, glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, fb)) \
 X(GetTexGenfv, 0, glGetTexGenfv(GL_S, GL_TEXTURE_GEN_MODE, fb)) \
 X(PrioritizeTextures, 0, glPrioritizeTextures(1, ub, fb)) \
 X(GenBuffers, 0, glGenBuffers(1, ub)) \
 X(BindBuffer, 0, glBindBuffer(GL_ARRAY_BUFFER, 0)) \
 X(GenQueries, 0, glGenQueries(1, ub)) \
 X(CompressedTexImage2D, 0, glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, 4, 4, 0, 8, img)) \
 X(CallList, 0, glCallList(77)) \
 X(Indexi, 0, glIndexi(2)) \
 X(EdgeFlag, 0, glEdgeFlag(0)) \
 X(ArrayElement, 0, glArrayElement(0)) \
 X(EvalCoord1f, 0, glEvalCoord1f(0.5f)) \
 X(Vertex2f, 0, glVertex2f(1, 1)) \
 X(Begin, 1, glBegin(GL_POINTS)) \
 X(MapBuffer, 1, glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY)) \
 X(UnmapBuffer, 1, glUnmapBuffer(GL_ARRAY_BUFFER)) \
 X(GetBufferSubData, 0, glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, img)) \
 X(BufferData, 0, glBufferData(GL_ARRAY_BUFFER, 16, img, GL_STATIC_DRAW)) \
 X(EndQuery, 0, glEndQuery(GL_SAMPLES_PASSED)) \
 X(AreTexturesResident, 1, glAreTexturesResident(1, ub+10, (GLboolean *)img)) \
 X(IsTexture, 1, glIsTexture(ub[10])) \

enum {
#define X(n, r, c) T_##n,
   CALLS
#undef X
   T_COUNT
};
static const char *const names[] = {
#define X(n, r, c) #n,
   CALLS
#undef X
};
static const int refuses[] = {
#define X(n, r, c) r,
   CALLS
#undef X
};

static void call(int t)
{
   switch (t) {
#define X(n, r, c) case T_##n: (void)(c); break;
   CALLS
#undef X
   }
}

/* A fresh context with the stuck list (1), an empty list (77), texture
 * ub[10] with a 4x4 image, buffer ub[20] bound to GL_ARRAY_BUFFER, one
 * attribute group, matrix and name pushed; returns the error of call t,
 * issued after glCallList(1) when stuck, read after the glEnd. */
static int run(int t, int stuck)
{
   OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
   if (!c || !OSMesaMakeCurrent(c, cbuf, GL_UNSIGNED_BYTE, 32, 32)) {
      fprintf(stderr, "cannot create an OSMesa context\n");
      exit(2);
   }
   glEnableClientState(GL_VERTEX_ARRAY);
   glVertexPointer(2, GL_FLOAT, 0, va);
   glNewList(77, GL_COMPILE);
   glEndList();
   glNewList(1, GL_COMPILE);
   glBegin(GL_TRIANGLES);
   glColor3f(1, 0, 0); glVertex2f(20, 20);
   glColor3f(1, 0, 0); glVertex2f(30, 20);
   glColor3f(1, 0, 0); glVertex2f(20, 30);
   glColor4f(1, 0, 0, 1); /* after the last vertex: the colour grows */
   glEnd();
   glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, idx);
   glEndList();
   glGenTextures(1, ub + 10);
   glPushAttrib(GL_ALL_ATTRIB_BITS);
   glPushMatrix();
   glPushName(3);
   glBindTexture(GL_TEXTURE_2D, ub[10]);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
   glGenBuffers(1, ub + 20);
   glBindBuffer(GL_ARRAY_BUFFER, ub[20]);
   glBufferData(GL_ARRAY_BUFFER, 16, img, GL_STATIC_DRAW);
   if (t == T_UnmapBuffer)
      glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
   if (t == T_EndQuery)
      glBeginQuery(GL_SAMPLES_PASSED, 9);
   glFinish();
   int pre = glGetError();
   if (stuck)
      glCallList(1);
   call(t);
   if (stuck)
      glEnd();
   int err = glGetError();
   if (t == T_Begin)
      glEnd();
   /* not destroyed: OSMesaDestroyContext of some of these states crashes
    * the oracle */
   return pre ? -1 : err;
}

int main(void)
{
   for (int t = 0; t < T_COUNT; t++) {
      char what[96];
      snprintf(what, sizeof what, "gl%s outside glBegin/glEnd: error", names[t]);
      probe_expect(what, run(t, 0), GL_NO_ERROR);
      snprintf(what, sizeof what, "gl%s after the stuck list: error", names[t]);
      probe_expect(what, run(t, 1), refuses[t] ? GL_INVALID_OPERATION : GL_NO_ERROR);
   }
   return probe_result();
}
