/*
 * The display-list command table: one line per GL command that Mesa 22.3
 * compiles into a list with a plain node (its dlist.c save_* function
 * checks for glBegin/glEnd, flushes the vertex list being compiled, stores
 * the arguments and executes the command under GL_COMPILE_AND_EXECUTE;
 * execute_list calls the command with the stored arguments).
 *
 * This header is an X-macro: the includer defines the DL_OP* macros and
 * gets one expansion per line.  main/dlist.h makes the prototypes of the
 * save functions the entry points call, main/dlist.c the opcodes, the
 * save functions (fgl_save_Name: prologue + store) and the replay cases.
 * Adding a command is one line here and one FGL_SAVE hook at the top of
 * its entry point.
 *
 *   DL_OPn(Name, T1, ..., Tn)        glName with n scalar arguments (n = 0..6)
 *   DL_OPVk(Name, T1..Tk, VT, N)     glName with k scalars and a pointer to
 *                                    up to N values (the entry point's hook
 *                                    passes how many to read; the others
 *                                    are stored as 0)
 *   DL_CUSTOMn / DL_CUSTOMVk          same node and replay, but the entry
 *                                    point has a hand-written save function
 *                                    (in dlist.c) that calls fgl_dl_put_Name
 *
 * Argument kinds (node member, C type): E GLenum, I GLint, SZ GLsizei,
 * U GLuint, F GLfloat, B GLboolean, BF GLbitfield, US GLushort, D GLdouble
 * stored as a float, as Mesa stores every double argument (glFrustum,
 * glOrtho, glClearDepth, glDepthRange, glClipPlane), so the replay sees the
 * rounded value; FU a float that the replay reads back as the number of
 * its bit pattern (Mesa's glClearIndex replay); vectors: F floats, D
 * doubles stored as floats, UB bytes.
 *
 * Not here: glBegin/glEnd and the vertex attributes (the vertex-list
 * compiler, vbo_save_api.c), glCallList(s), glNewList, glRect, the array
 * draws, and every command Mesa executes at once during compilation
 * (queries, client state, pixel store, glReadPixels, glFlush, glFinish,
 * glGenTextures, glDeleteTextures, glIsTexture, glAreTexturesResident,
 * glGenLists, glDeleteLists, glIsList, glEndList, glRenderMode,
 * glFeedbackBuffer, glSelectBuffer).
 */

/* ---- GL_COLOR_BUFFER_BIT ---- */
DL_OP2(AlphaFunc, E, F)
DL_OP2(BlendFunc, E, E)      /* Mesa: BLEND_FUNC_SEPARATE(s, d, s, d) */
DL_OP1(BlendEquation, E)
DL_OP4(BlendFuncSeparate, E, E, E, E)
DL_OP2(BlendEquationSeparate, E, E)
DL_OP4(BlendColor, F, F, F, F)
DL_OP1(LogicOp, E)
DL_OP4(ColorMask, B, B, B, B)
DL_OP4(ClearColor, F, F, F, F)
DL_OP4(ClearAccum, F, F, F, F)   /* GL_ACCUM_BUFFER_BIT */
DL_OP2(Accum, E, F)
DL_OP1(Clear, BF)
DL_OP1(ClearIndex, FU)        /* Mesa replays the float's bits as a number */
DL_OP1(IndexMask, U)
DL_OP1(DrawBuffer, E)
DL_OP1(ReadBuffer, E)         /* GL_PIXEL_MODE_BIT state, compiled by Mesa */
DL_OP2(PixelTransferf, E, F)  /* glPixelTransferi: converted, then this */
DL_OP2(PixelZoom, F, F)
DL_OP5(CopyPixels, I, I, SZ, SZ, E)
DL_OPV2(PixelMapfv, E, SZ, F, 256) /* uiv/usv converted at compile time
                                    * (save_PixelMapuiv/usv); the hook
                                    * passes min(mapsize, 256) values */
/* ---- depth, stencil, scissor, viewport ---- */
DL_OP1(DepthFunc, E)
DL_OP1(DepthMask, B)
DL_OP1(ClearDepth, D)
DL_OP1(ClearStencil, I)
DL_OP3(StencilFunc, E, I, U)
DL_OP3(StencilOp, E, E, E)
DL_OP1(StencilMask, U)
DL_OP4(Scissor, I, I, SZ, SZ)
DL_OP4(Viewport, I, I, SZ, SZ)
DL_OP2(DepthRange, D, D)
/* ---- polygons, points, lines, hints ---- */
DL_OP1(FrontFace, E)
DL_OP1(CullFace, E)
DL_OP2(PolygonMode, E, E)
DL_OP2(PolygonOffset, F, F)
DL_OPV0(PolygonStipple, UB, 128)   /* unpacked at compile time (hook) */
DL_OP1(PointSize, F)
DL_OPV1(PointParameterfv, E, F, 3)  /* every glPointParameter form, as 3 floats */
DL_OP2(SampleCoverage, F, B)
DL_OP1(LineWidth, F)
DL_OP2(LineStipple, I, US)
DL_OP2(Hint, E, E)
/* ---- transform ---- */
DL_OPV1(ClipPlane, E, D, 4)
DL_OP1(MatrixMode, E)
DL_OP0(PushMatrix)
DL_OP0(PopMatrix)
DL_OP0(LoadIdentity)
DL_OPV0(LoadMatrixf, F, 16)        /* glLoadMatrixd: converted, then this */
DL_OPV0(MultMatrixf, F, 16)
DL_OP6(Ortho, D, D, D, D, D, D)
DL_OP6(Frustum, D, D, D, D, D, D)
DL_OP3(Translatef, F, F, F)        /* the d variants convert, then these */
DL_OP3(Scalef, F, F, F)
DL_OP4(Rotatef, F, F, F, F)
/* ---- enables, fog, lighting ---- */
DL_OP1(Enable, E)
DL_OP1(Disable, E)
DL_OPV1(Fogfv, E, F, 4)            /* glFog{f,i,iv}: converted, then this */
DL_OPV2(Lightfv, E, E, F, 4)       /* glLight{f,i,iv}: likewise */
DL_OPV1(LightModelfv, E, F, 4)
DL_OP2(ColorMaterial, E, E)
DL_CUSTOM1(ShadeModel, E)          /* executes first, skips a repeat */
DL_CUSTOMV2(Materialfv, E, E, F, 4)/* outside glBegin/glEnd: likewise */
/* ---- evaluators ---- */
DL_OP3(MapGrid1f, I, F, F)         /* glMapGrid1d: converted, then this */
DL_OP6(MapGrid2f, I, F, F, I, F, F)
DL_OP3(EvalMesh1, E, I, I)
DL_OP5(EvalMesh2, E, I, I, I, I)
/* ---- selection and feedback ---- */
DL_OP0(InitNames)
DL_OP1(LoadName, U)
DL_OP1(PushName, U)
DL_OP0(PopName)
DL_OP1(PassThrough, F)
/* ---- the raster position ---- */
DL_OP4(RasterPos4f, F, F, F, F) /* every glRasterPos variant: converted, then this */
DL_OP4(WindowPos4fMESA, F, F, F, F) /* every glWindowPos variant (replay: rastpos.c) */
/* ---- textures ---- */
DL_OP2(BindTexture, E, U)
DL_OP1(ActiveTexture, E)            /* glActiveTextureARB too */
DL_OPV2(TexParameterfv, E, E, F, 4) /* glTexParameter{f,i,iv}: params[0] as
                                     * float, the rest 0 (hooks) */
DL_OPV2(TexEnvfv, E, E, F, 4)       /* glTexEnv{f,i,iv}: converted (hooks) */
DL_OPV2(TexGenfv, E, E, F, 4)       /* glTexGen{i,f,d}[v]: converted (hooks) */
DL_OP2(PrioritizeTexture1, U, F)    /* glPrioritizeTextures: one node per
                                     * name, replayed as a call with n = 1
                                     * (main/dlist.h) */

/* ---- occlusion queries (GL 1.5: Mesa compiles them, save_BeginQueryARB,
 * save_EndQueryARB) ---- */
DL_OP2(BeginQuery, E, U)           /* glBeginQueryARB too */
DL_OP1(EndQuery, E)

/* ---- attribute stack, lists ---- */
DL_OP1(PushAttrib, BF)
DL_OP0(PopAttrib)
DL_OP1(ListBase, U)
DL_CUSTOM0(End)                    /* a glEnd without its glBegin */
