/*
 * fixgl's GLUT: enough of the GLUT 3.7 API for legacy demos to compile
 * against <GL/glut.h> unchanged and run on fixgl (link -lfixglut -lfixgl).
 * The implementation is libfixglut (viewer/glut/, see its README.md): the
 * frames are rendered by fixgl into an OSMesa buffer and presented in a GLFW
 * window, or written to PNG in the headless mode.
 *
 * Limits: one window (glutCreateWindow succeeds once; sub-windows, overlays,
 * colour-index mode, game mode, joysticks and spaceballs are not provided);
 * glutSetCursor, glutPositionWindow and glutFullScreen in the headless mode
 * and glutIconifyWindow are accepted and do nothing.  freeglut's
 * extensions that libfixglut has: <GL/freeglut.h>.
 *
 * Headless mode and scripted runs (environment variables):
 *   FIXGLUT_HEADLESS=1     no window: frames are rendered off screen only
 *   FIXGLUT_FRAMES=N       glutMainLoop runs exactly N frames, then exits
 *                          (headless default: 1); the clock is deterministic
 *   FIXGLUT_FRAME_MS=M     the deterministic clock's step per frame (16)
 *   FIXGLUT_OUT=PATH       PNG output: a pattern with %d (each frame, e.g.
 *                          out/f%03d.png), a directory (each frame as
 *                          DIR/frame-NNNN.png) or a .png file (last frame)
 *   FIXGLUT_EVENTS=LIST    scripted events "FRAME:EVENT;...", see
 *                          viewer/glut/README.md
 *   FIXGLUT_SCREENSHOT=F   window mode: after the last frame, read the
 *                          window back through the system GL into PNG F
 *   FIXGLUT_SCREENSHOT_X11=F  the same frame as the X server shows the
 *                          window (XGetImage), into PNG F
 */
#ifndef FIXGL_GLUT_H
#define FIXGL_GLUT_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLUT_API_VERSION 3
#define FIXGLUT 1

/* Display mode bits */
#define GLUT_RGB                0x0000
#define GLUT_RGBA               0x0000
#define GLUT_INDEX              0x0001
#define GLUT_SINGLE             0x0000
#define GLUT_DOUBLE             0x0002
#define GLUT_ACCUM              0x0004
#define GLUT_ALPHA              0x0008
#define GLUT_DEPTH              0x0010
#define GLUT_STENCIL            0x0020
#define GLUT_MULTISAMPLE        0x0080
#define GLUT_STEREO             0x0100
#define GLUT_LUMINANCE          0x0200

/* Mouse */
#define GLUT_LEFT_BUTTON        0
#define GLUT_MIDDLE_BUTTON      1
#define GLUT_RIGHT_BUTTON       2
#define GLUT_DOWN               0
#define GLUT_UP                 1

/* Special keys */
#define GLUT_KEY_F1             1
#define GLUT_KEY_F2             2
#define GLUT_KEY_F3             3
#define GLUT_KEY_F4             4
#define GLUT_KEY_F5             5
#define GLUT_KEY_F6             6
#define GLUT_KEY_F7             7
#define GLUT_KEY_F8             8
#define GLUT_KEY_F9             9
#define GLUT_KEY_F10            10
#define GLUT_KEY_F11            11
#define GLUT_KEY_F12            12
#define GLUT_KEY_LEFT           100
#define GLUT_KEY_UP             101
#define GLUT_KEY_RIGHT          102
#define GLUT_KEY_DOWN           103
#define GLUT_KEY_PAGE_UP        104
#define GLUT_KEY_PAGE_DOWN      105
#define GLUT_KEY_HOME           106
#define GLUT_KEY_END            107
#define GLUT_KEY_INSERT         108

/* Entry / visibility / menu state */
#define GLUT_LEFT               0
#define GLUT_ENTERED            1
#define GLUT_MENU_NOT_IN_USE    0
#define GLUT_MENU_IN_USE        1
#define GLUT_NOT_VISIBLE        0
#define GLUT_VISIBLE            1

/* glutGet */
#define GLUT_WINDOW_X                   100
#define GLUT_WINDOW_Y                   101
#define GLUT_WINDOW_WIDTH               102
#define GLUT_WINDOW_HEIGHT              103
#define GLUT_WINDOW_BUFFER_SIZE         104
#define GLUT_WINDOW_STENCIL_SIZE        105
#define GLUT_WINDOW_DEPTH_SIZE          106
#define GLUT_WINDOW_RED_SIZE            107
#define GLUT_WINDOW_GREEN_SIZE          108
#define GLUT_WINDOW_BLUE_SIZE           109
#define GLUT_WINDOW_ALPHA_SIZE          110
#define GLUT_WINDOW_ACCUM_RED_SIZE      111
#define GLUT_WINDOW_ACCUM_GREEN_SIZE    112
#define GLUT_WINDOW_ACCUM_BLUE_SIZE     113
#define GLUT_WINDOW_ACCUM_ALPHA_SIZE    114
#define GLUT_WINDOW_DOUBLEBUFFER        115
#define GLUT_WINDOW_RGBA                116
#define GLUT_WINDOW_PARENT              117
#define GLUT_WINDOW_NUM_CHILDREN        118
#define GLUT_WINDOW_COLORMAP_SIZE       119
#define GLUT_WINDOW_NUM_SAMPLES         120
#define GLUT_WINDOW_STEREO              121
#define GLUT_WINDOW_CURSOR              122
#define GLUT_SCREEN_WIDTH               200
#define GLUT_SCREEN_HEIGHT              201
#define GLUT_SCREEN_WIDTH_MM            202
#define GLUT_SCREEN_HEIGHT_MM           203
#define GLUT_MENU_NUM_ITEMS             300
#define GLUT_DISPLAY_MODE_POSSIBLE      400
#define GLUT_INIT_WINDOW_X              500
#define GLUT_INIT_WINDOW_Y              501
#define GLUT_INIT_WINDOW_WIDTH          502
#define GLUT_INIT_WINDOW_HEIGHT         503
#define GLUT_INIT_DISPLAY_MODE          504
#define GLUT_ELAPSED_TIME               700
#define GLUT_WINDOW_FORMAT_ID           123

/* glutDeviceGet */
#define GLUT_HAS_KEYBOARD               600
#define GLUT_HAS_MOUSE                  601
#define GLUT_NUM_MOUSE_BUTTONS          605

/* glutGetModifiers */
#define GLUT_ACTIVE_SHIFT       1
#define GLUT_ACTIVE_CTRL        2
#define GLUT_ACTIVE_ALT         4

/* glutSetCursor (accepted, no effect) */
#define GLUT_CURSOR_RIGHT_ARROW 0
#define GLUT_CURSOR_LEFT_ARROW  1
#define GLUT_CURSOR_INFO        2
#define GLUT_CURSOR_DESTROY     3
#define GLUT_CURSOR_HELP        4
#define GLUT_CURSOR_CYCLE       5
#define GLUT_CURSOR_SPRAY       6
#define GLUT_CURSOR_WAIT        7
#define GLUT_CURSOR_TEXT        8
#define GLUT_CURSOR_CROSSHAIR   9
#define GLUT_CURSOR_UP_DOWN     10
#define GLUT_CURSOR_LEFT_RIGHT  11
#define GLUT_CURSOR_INHERIT     100
#define GLUT_CURSOR_NONE        101
#define GLUT_CURSOR_FULL_CROSSHAIR 102

/* Fonts: opaque handles (the glyphs are fixgl's own, see README.md) */
#define GLUT_STROKE_ROMAN               ((void *)0x0000)
#define GLUT_STROKE_MONO_ROMAN          ((void *)0x0001)
#define GLUT_BITMAP_9_BY_15             ((void *)0x0002)
#define GLUT_BITMAP_8_BY_13             ((void *)0x0003)
#define GLUT_BITMAP_TIMES_ROMAN_10      ((void *)0x0004)
#define GLUT_BITMAP_TIMES_ROMAN_24      ((void *)0x0005)
#define GLUT_BITMAP_HELVETICA_10        ((void *)0x0006)
#define GLUT_BITMAP_HELVETICA_12        ((void *)0x0007)
#define GLUT_BITMAP_HELVETICA_18        ((void *)0x0008)

/* Initialisation */
void glutInit(int *argcp, char **argv);
void glutInitDisplayMode(unsigned int mode);
void glutInitDisplayString(const char *string);
void glutInitWindowPosition(int x, int y);
void glutInitWindowSize(int width, int height);
void glutMainLoop(void);

/* Windows (one window) */
int glutCreateWindow(const char *title);
void glutDestroyWindow(int win);
int glutGetWindow(void);
void glutSetWindow(int win);
void glutPostRedisplay(void);
void glutSwapBuffers(void);
void glutSetWindowTitle(const char *title);
void glutSetIconTitle(const char *title);
void glutReshapeWindow(int width, int height);
void glutPositionWindow(int x, int y);
void glutShowWindow(void);
void glutHideWindow(void);
void glutIconifyWindow(void);
void glutFullScreen(void);
void glutSetCursor(int cursor);
void glutWarpPointer(int x, int y);

/* Menus */
int glutCreateMenu(void (*func)(int value));
void glutDestroyMenu(int menu);
int glutGetMenu(void);
void glutSetMenu(int menu);
void glutAddMenuEntry(const char *label, int value);
void glutAddSubMenu(const char *label, int submenu);
void glutChangeToMenuEntry(int item, const char *label, int value);
void glutChangeToSubMenu(int item, const char *label, int submenu);
void glutRemoveMenuItem(int item);
void glutAttachMenu(int button);
void glutDetachMenu(int button);

/* Callbacks */
void glutDisplayFunc(void (*func)(void));
void glutReshapeFunc(void (*func)(int width, int height));
void glutKeyboardFunc(void (*func)(unsigned char key, int x, int y));
void glutKeyboardUpFunc(void (*func)(unsigned char key, int x, int y));
void glutSpecialFunc(void (*func)(int key, int x, int y));
void glutSpecialUpFunc(void (*func)(int key, int x, int y));
void glutMouseFunc(void (*func)(int button, int state, int x, int y));
void glutMotionFunc(void (*func)(int x, int y));
void glutPassiveMotionFunc(void (*func)(int x, int y));
void glutEntryFunc(void (*func)(int state));
void glutVisibilityFunc(void (*func)(int state));
void glutIdleFunc(void (*func)(void));
void glutTimerFunc(unsigned int millis, void (*func)(int value), int value);
void glutMenuStatusFunc(void (*func)(int status, int x, int y));
void glutMenuStateFunc(void (*func)(int status));

/* State */
int glutGet(GLenum type);
int glutDeviceGet(GLenum type);
int glutGetModifiers(void);
int glutExtensionSupported(const char *name);

/* Fonts */
void glutBitmapCharacter(void *font, int character);
int glutBitmapWidth(void *font, int character);
int glutBitmapLength(void *font, const unsigned char *string);
void glutBitmapString(void *font, const unsigned char *string);
int glutBitmapHeight(void *font);
void glutStrokeCharacter(void *font, int character);
int glutStrokeWidth(void *font, int character);
int glutStrokeLength(void *font, const unsigned char *string);
void glutStrokeString(void *font, const unsigned char *string);
GLfloat glutStrokeHeight(void *font);

/* GLU's matrix helpers, provided by libfixglut (classic <GL/glut.h>
 * includes <GL/glu.h>); for the rest of GLU link the system libGLU after
 * -lfixgl (viewer/glut/README.md "GLU"): its three are the same. */
void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top);
void gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar);
void gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ,
               GLdouble centerX, GLdouble centerY, GLdouble centerZ,
               GLdouble upX, GLdouble upY, GLdouble upZ);

/* Geometric objects */
void glutWireSphere(GLdouble radius, GLint slices, GLint stacks);
void glutSolidSphere(GLdouble radius, GLint slices, GLint stacks);
void glutWireCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
void glutSolidCone(GLdouble base, GLdouble height, GLint slices, GLint stacks);
void glutWireCube(GLdouble size);
void glutSolidCube(GLdouble size);
void glutWireTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);
void glutSolidTorus(GLdouble innerRadius, GLdouble outerRadius, GLint sides, GLint rings);
void glutWireDodecahedron(void);
void glutSolidDodecahedron(void);
void glutWireTeapot(GLdouble size);
void glutSolidTeapot(GLdouble size);
void glutWireOctahedron(void);
void glutSolidOctahedron(void);
void glutWireTetrahedron(void);
void glutSolidTetrahedron(void);
void glutWireIcosahedron(void);
void glutSolidIcosahedron(void);

#ifdef __cplusplus
}
#endif

#endif /* FIXGL_GLUT_H */
