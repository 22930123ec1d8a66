/*
 * fixgl's <GL/freeglut_ext.h>: the freeglut extensions libfixglut
 * provides (viewer/glut/README.md, "freeglut extensions"), with
 * freeglut 3.4's names and values, so that programs written for freeglut
 * compile unchanged against include/GL/.  Functions freeglut has and
 * libfixglut does not (joysticks, game mode, multi-pointer, GLES
 * attributes, sub-windows' extras) are not declared: a program using them
 * fails to compile rather than to link.
 */
#ifndef FIXGL_FREEGLUT_EXT_H
#define FIXGL_FREEGLUT_EXT_H

#include <stdarg.h>
#include <GL/glut.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FREEGLUT 1
/* the freeglut release whose extension API this follows; also
 * glutGet(GLUT_VERSION) */
#define FIXGLUT_FREEGLUT_VERSION 30400

/* glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, ...) */
#define GLUT_ACTION_EXIT                    0
#define GLUT_ACTION_GLUTMAINLOOP_RETURNS    1
#define GLUT_ACTION_CONTINUE_EXECUTION      2

/* glutSetOption(GLUT_RENDERING_CONTEXT, ...) */
#define GLUT_CREATE_NEW_CONTEXT             0
#define GLUT_USE_CURRENT_CONTEXT            1

/* glutSetOption(GLUT_DIRECT_RENDERING, ...) */
#define GLUT_FORCE_INDIRECT_CONTEXT         0
#define GLUT_ALLOW_DIRECT_CONTEXT           1
#define GLUT_TRY_DIRECT_CONTEXT             2
#define GLUT_FORCE_DIRECT_CONTEXT           3

/* glutGet / glutSetOption */
#define GLUT_INIT_STATE                     0x007C
#define GLUT_WINDOW_SRGB                    0x007D
#define GLUT_ACTION_ON_WINDOW_CLOSE         0x01F9
#define GLUT_WINDOW_BORDER_WIDTH            0x01FA
#define GLUT_WINDOW_BORDER_HEIGHT           0x01FB
#define GLUT_WINDOW_HEADER_HEIGHT           0x01FB
#define GLUT_VERSION                        0x01FC
#define GLUT_RENDERING_CONTEXT              0x01FD
#define GLUT_DIRECT_RENDERING               0x01FE
#define GLUT_FULL_SCREEN                    0x01FF
#define GLUT_INIT_MAJOR_VERSION             0x0200
#define GLUT_INIT_MINOR_VERSION             0x0201
#define GLUT_INIT_FLAGS                     0x0202
#define GLUT_INIT_PROFILE                   0x0203
#define GLUT_SKIP_STALE_MOTION_EVENTS       0x0204
#define GLUT_GEOMETRY_VISUALIZE_NORMALS     0x0205
#define GLUT_STROKE_FONT_DRAW_JOIN_DOTS     0x0206
#define GLUT_ALLOW_NEGATIVE_WINDOW_POSITION 0x0207
#define GLUT_AUX                            0x1000

/* glutInitContextFlags / glutInitContextProfile */
#define GLUT_DEBUG                          0x0001
#define GLUT_FORWARD_COMPATIBLE             0x0002
#define GLUT_CORE_PROFILE                   0x0001
#define GLUT_COMPATIBILITY_PROFILE          0x0002

/* The main loop */
void glutMainLoopEvent(void);
void glutLeaveMainLoop(void);
void glutExit(void);

/* Windows */
void glutFullScreenToggle(void);
void glutLeaveFullScreen(void);
void glutCloseFunc(void (*callback)(void));
void glutWMCloseFunc(void (*callback)(void));
void glutSetWindowData(void *data);
void *glutGetWindowData(void);

/* Options */
void glutSetOption(GLenum option_flag, int value);

/* Fonts (also declared by <GL/glut.h>) */
int glutBitmapHeight(void *font);
GLfloat glutStrokeHeight(void *font);
void glutBitmapString(void *font, const unsigned char *string);
void glutStrokeString(void *font, const unsigned char *string);

/* Shapes: freeglut's cylinder, its vertices in freeglut's order */
void glutWireCylinder(double radius, double height, GLint slices, GLint stacks);
void glutSolidCylinder(double radius, double height, GLint slices, GLint stacks);

/* Extension functions: glut* names are libfixglut's, any other name is
 * looked up in the GL library (OSMesaGetProcAddress) */
typedef void (*GLUTproc)(void);
GLUTproc glutGetProcAddress(const char *procName);

/* Context requests: fixgl gives OpenGL 1.5, compatibility profile;
 * glutCreateWindow refuses a later version or the core profile with
 * freeglut's error ("Unable to create OpenGL M.N context ...") */
void glutInitContextVersion(int majorVersion, int minorVersion);
void glutInitContextFlags(int flags);
void glutInitContextProfile(int profile);
void glutInitErrorFunc(void (*callback)(const char *fmt, va_list ap));
void glutInitWarningFunc(void (*callback)(const char *fmt, va_list ap));

#ifdef __cplusplus
}
#endif

#endif /* FIXGL_FREEGLUT_EXT_H */
