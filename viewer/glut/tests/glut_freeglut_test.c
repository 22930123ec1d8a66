/*
 * glut-freeglut: libfixglut's freeglut extensions, headless on fixgl,
 * each function exercised with freeglut's semantics (fg_main.c,
 * fg_state.c, fg_structure.c of freeglut 3.4):
 *   - glutSetOption / glutGet of freeglut's options, before and after
 *     glutExit (which resets them), GLUT_INIT_STATE;
 *   - glutMainLoopEvent: one step, no idle callback, timers and the
 *     display; glutLeaveMainLoop with GLUT_ACTION_GLUTMAINLOOP_RETURNS
 *     returns from glutMainLoop after the close callback, and a new
 *     session can start; with GLUT_ACTION_EXIT (the default) the process
 *     ends with status 0 (child process);
 *   - the user closing the window ("close" scripted event): the close
 *     callback, then exit 0 (GLUT_ACTION_EXIT) or glutMainLoop returns
 *     (GLUT_ACTION_CONTINUE_EXECUTION); glutWMCloseFunc is the same
 *     callback; glutDestroyWindow ends the loop;
 *   - glutInitContextVersion/Profile: 1.5 accepted; 2.0 and the core
 *     profile refused by glutCreateWindow with freeglut's message (through
 *     glutInitErrorFunc, and without one: exit 1, the message on stderr);
 *   - glutGetProcAddress of glut and gl names; glutFullScreenToggle;
 *     glutBitmapString/StrokeString with their lengths and heights;
 *     glutSolidCylinder/glutWireCylinder draw (pixels change), and leave
 *     the client arrays disabled.
 * Exit status 0 when every check holds.
 */
#include <GL/freeglut.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static int checks, failures;

#define CHECK(cond)                                                              \
   do {                                                                          \
      checks++;                                                                  \
      if (!(cond)) {                                                             \
         failures++;                                                             \
         fprintf(stderr, "glut-freeglut: %s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      }                                                                          \
   } while (0)

static char *argv0;
static int displays, idles, closes, timers;
static char error_text[512];

static void display(void)
{
   displays++;
   glClear(GL_COLOR_BUFFER_BIT);
   glutSwapBuffers();
}
static void idle(void) { idles++; }
static void on_close(void) { closes++; }
static void on_timer(int v) { timers += v; }
static void leave_in_idle(void)
{
   idles++;
   if (idles == 2)
      glutLeaveMainLoop();
}

static void error_func(const char *fmt, va_list ap)
{
   vsnprintf(error_text, sizeof error_text, fmt, ap);
}

static void session(int w, int h)
{
   int argc = 1;
   char *argv[] = { argv0, NULL };
   glutInit(&argc, argv);
   glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH);
   glutInitWindowSize(w, h);
   CHECK(glutCreateWindow("freeglut test") == 1);
   glutDisplayFunc(display);
}

/* Runs fn in a child process; returns its exit status, or -1; its stderr
 * (up to 1 KiB) into err when err is not NULL. */
static int in_child(void (*fn)(void), char *err, size_t errn)
{
   int fd[2];
   if (pipe(fd) != 0)
      return -1;
   fflush(NULL);
   pid_t pid = fork();
   if (pid == 0) {
      close(fd[0]);
      dup2(fd[1], 2);
      fn();
      _exit(42);   /* fn must not return */
   }
   close(fd[1]);
   size_t n = 0;
   ssize_t r;
   char sink[256];
   while ((r = read(fd[0], err && n + 1 < errn ? err + n : sink,
                    err && n + 1 < errn ? errn - 1 - n : sizeof sink)) > 0)
      if (err && n + 1 < errn)
         n += (size_t)r;
   if (err)
      err[n] = '\0';
   close(fd[0]);
   int status;
   if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status))
      return -1;
   return WEXITSTATUS(status);
}

static void child_leave_default(void)
{
   session(32, 32);
   glutIdleFunc(leave_in_idle);
   glutMainLoop();   /* GLUT_ACTION_EXIT: exits 0 after the loop */
   _exit(43);
}

static void child_close_exit(void)
{
   setenv("FIXGLUT_EVENTS", "2:close", 1);
   session(32, 32);
   glutMainLoop();
   _exit(43);
}

static void child_core_profile(void)
{
   int argc = 1;
   char *argv[] = { argv0, NULL };
   glutInitErrorFunc(NULL);   /* freeglut's default: the message, then exit 1 */
   glutInit(&argc, argv);
   glutInitContextVersion(3, 2);
   glutInitContextProfile(GLUT_CORE_PROFILE);
   glutCreateWindow("core");
   _exit(43);
}

static void check_options(void)
{
   CHECK(glutGet(GLUT_INIT_STATE) == 1);
   CHECK(glutGet(GLUT_ACTION_ON_WINDOW_CLOSE) == GLUT_ACTION_EXIT);
   glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_CONTINUE_EXECUTION);
   CHECK(glutGet(GLUT_ACTION_ON_WINDOW_CLOSE) == GLUT_ACTION_CONTINUE_EXECUTION);
   CHECK(glutGet(GLUT_RENDERING_CONTEXT) == GLUT_CREATE_NEW_CONTEXT);
   glutSetOption(GLUT_RENDERING_CONTEXT, GLUT_USE_CURRENT_CONTEXT);
   CHECK(glutGet(GLUT_RENDERING_CONTEXT) == GLUT_USE_CURRENT_CONTEXT);
   glutSetOption(GLUT_INIT_DISPLAY_MODE, GLUT_DOUBLE | GLUT_STENCIL);
   CHECK(glutGet(GLUT_INIT_DISPLAY_MODE) == (GLUT_DOUBLE | GLUT_STENCIL));
   glutSetOption(GLUT_INIT_WINDOW_WIDTH, 77);
   glutSetOption(GLUT_INIT_WINDOW_HEIGHT, 55);
   CHECK(glutGet(GLUT_INIT_WINDOW_WIDTH) == 77 && glutGet(GLUT_INIT_WINDOW_HEIGHT) == 55);
   glutSetOption(GLUT_DIRECT_RENDERING, GLUT_FORCE_DIRECT_CONTEXT);
   CHECK(glutGet(GLUT_DIRECT_RENDERING) == GLUT_FORCE_DIRECT_CONTEXT);
   glutSetOption(GLUT_SKIP_STALE_MOTION_EVENTS, 5);
   CHECK(glutGet(GLUT_SKIP_STALE_MOTION_EVENTS) == 1);
   glutSetOption(GLUT_AUX, 2);
   CHECK(glutGet(GLUT_AUX) == 2);
   CHECK(glutGet(GLUT_VERSION) == 30400);
   glutInitContextVersion(1, 3);
   glutInitContextFlags(GLUT_DEBUG);
   glutInitContextProfile(GLUT_COMPATIBILITY_PROFILE);
   CHECK(glutGet(GLUT_INIT_MAJOR_VERSION) == 1 && glutGet(GLUT_INIT_MINOR_VERSION) == 3);
   CHECK(glutGet(GLUT_INIT_FLAGS) == GLUT_DEBUG);
   CHECK(glutGet(GLUT_INIT_PROFILE) == GLUT_COMPATIBILITY_PROFILE);
   /* glutExit: the session ends, the options are freeglut's defaults again */
   glutExit();
   CHECK(glutGet(GLUT_INIT_STATE) == 0);
   int argc = 1;
   char *argv[] = { argv0, NULL };
   glutInit(&argc, argv);
   CHECK(glutGet(GLUT_ACTION_ON_WINDOW_CLOSE) == GLUT_ACTION_EXIT);
   CHECK(glutGet(GLUT_RENDERING_CONTEXT) == GLUT_CREATE_NEW_CONTEXT);
   CHECK(glutGet(GLUT_INIT_MAJOR_VERSION) == 1 && glutGet(GLUT_INIT_MINOR_VERSION) == 0);
   CHECK(glutGet(GLUT_INIT_WINDOW_WIDTH) == 300);
   glutExit();
}

static void check_main_loop_event(void)
{
   displays = idles = timers = closes = 0;
   session(40, 30);
   glutIdleFunc(idle);
   glutTimerFunc(20, on_timer, 5);       /* due at 20 ms: the step of frame 2 (32 ms) */
   glutCloseFunc(on_close);
   glutMainLoopEvent();                  /* frame 0: initial reshape and display */
   CHECK(displays == 1);
   CHECK(idles == 0);                    /* glutMainLoopEvent calls no idle callback */
   glutMainLoopEvent();                  /* frame 1: nothing pending */
   CHECK(displays == 1 && timers == 0);
   glutPostRedisplay();
   glutMainLoopEvent();                  /* frame 2: the timer, the display */
   CHECK(displays == 2 && timers == 5);
   CHECK(glutGet(GLUT_ELAPSED_TIME) == 48);
   glutDestroyWindow(glutGetWindow());
   CHECK(closes == 0);                   /* closed at the end of the next step */
   glutMainLoopEvent();
   CHECK(closes == 1);
   CHECK(glutGetWindow() == 0);
   glutExit();
}

static void check_leave_returns(void)
{
   displays = idles = closes = 0;
   session(40, 30);
   glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
   glutIdleFunc(leave_in_idle);
   glutWMCloseFunc(on_close);            /* freeglut: the same callback as glutCloseFunc */
   glutMainLoop();                       /* returns: left in the second idle */
   CHECK(idles == 2);
   CHECK(closes == 1);                   /* the window was destroyed on the way out */
   CHECK(glutGet(GLUT_INIT_STATE) == 0);
   /* a new session after the loop returned */
   displays = 0;
   setenv("FIXGLUT_EVENTS", "1:close", 1);
   session(20, 20);
   glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_CONTINUE_EXECUTION);
   glutCloseFunc(on_close);
   glutMainLoop();                       /* the user closes the window in frame 1 */
   CHECK(closes == 2);
   CHECK(displays == 1);
   unsetenv("FIXGLUT_EVENTS");
}

static void check_context_requests(void)
{
   int argc = 1;
   char *argv[] = { argv0, NULL };
   glutInit(&argc, argv);
   glutInitErrorFunc(error_func);
   glutInitContextVersion(2, 0);
   error_text[0] = '\0';
   CHECK(glutCreateWindow("gl2") == 0);
   CHECK(strcmp(error_text, "Unable to create OpenGL 2.0 context (flags 0, profile 0)") == 0);
   glutInitContextVersion(1, 5);
   glutInitContextProfile(GLUT_CORE_PROFILE);
   CHECK(glutCreateWindow("core") == 0);
   CHECK(strcmp(error_text, "Unable to create OpenGL 1.5 context (flags 0, profile 1)") == 0);
   glutInitContextProfile(GLUT_COMPATIBILITY_PROFILE);
   glutInitDisplayMode(GLUT_RGBA | GLUT_DEPTH);
   glutInitWindowSize(64, 48);
   CHECK(glutCreateWindow("1.5") == 1);
   glutDisplayFunc(display);

   /* glutGetProcAddress: glut names are the library's, gl names GL's */
   CHECK(glutGetProcAddress("glutSolidCylinder") == (GLUTproc)glutSolidCylinder);
   CHECK(glutGetProcAddress("glutMainLoopEvent") == (GLUTproc)glutMainLoopEvent);
   CHECK(glutGetProcAddress("glutNoSuchFunction") == NULL);
   void (*clear_color)(GLclampf, GLclampf, GLclampf, GLclampf) =
      (void (*)(GLclampf, GLclampf, GLclampf, GLclampf))glutGetProcAddress("glClearColor");
   CHECK(clear_color != NULL);
   if (clear_color) {
      GLfloat c[4];
      clear_color(0.25f, 0.5f, 0.75f, 1.0f);
      glGetFloatv(GL_COLOR_CLEAR_VALUE, c);
      CHECK(c[0] == 0.25f && c[1] == 0.5f && c[2] == 0.75f);
   }
   CHECK(glutGetProcAddress("glNoSuchFunction") == NULL);

   /* full screen: a state, headless */
   CHECK(glutGet(GLUT_FULL_SCREEN) == 0);
   glutFullScreenToggle();
   CHECK(glutGet(GLUT_FULL_SCREEN) == 1);
   glutLeaveFullScreen();
   CHECK(glutGet(GLUT_FULL_SCREEN) == 0);
   glutFullScreen();
   glutFullScreenToggle();
   CHECK(glutGet(GLUT_FULL_SCREEN) == 0);
   CHECK(glutGet(GLUT_WINDOW_WIDTH) == 64);

   /* fonts: lengths are the sums of the advances (a stroke string's in
    * float, rounded: 3 x 104.76), heights freeglut's */
   const unsigned char *s = (const unsigned char *)"Hi!";
   CHECK(glutBitmapLength(GLUT_BITMAP_9_BY_15, s) == 27);
   CHECK(glutBitmapHeight(GLUT_BITMAP_9_BY_15) == 16);
   CHECK(glutBitmapHeight(GLUT_BITMAP_HELVETICA_18) == 23);
   CHECK(glutStrokeLength(GLUT_STROKE_MONO_ROMAN, s) == 314);
   CHECK(glutStrokeHeight(GLUT_STROKE_ROMAN) > 119.0f && glutStrokeHeight(GLUT_STROKE_ROMAN) < 119.1f);

   /* strings and cylinders draw; the client arrays are left disabled */
   static unsigned char before[64 * 48 * 4], after[64 * 48 * 4];
   glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glReadPixels(0, 0, 64, 48, GL_RGBA, GL_UNSIGNED_BYTE, before);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(-2.0, 2.0, -1.5, 1.5, -5.0, 5.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glRotatef(60.0f, 1.0f, 0.0f, 0.0f);
   glutSolidCylinder(0.8, 1.0, 12, 2);
   glReadPixels(0, 0, 64, 48, GL_RGBA, GL_UNSIGNED_BYTE, after);
   CHECK(memcmp(before, after, sizeof after) != 0);
   CHECK(!glIsEnabled(GL_VERTEX_ARRAY) && !glIsEnabled(GL_NORMAL_ARRAY));
   glClear(GL_COLOR_BUFFER_BIT);
   glutWireCylinder(0.8, 1.0, 12, 2);
   glReadPixels(0, 0, 64, 48, GL_RGBA, GL_UNSIGNED_BYTE, before);
   CHECK(memcmp(before, after, sizeof after) != 0);   /* wire differs from solid */
   glClear(GL_COLOR_BUFFER_BIT);
   glLoadIdentity();
   glRasterPos2f(-1.9f, 0.0f);
   glutBitmapString(GLUT_BITMAP_8_BY_13, s);
   GLfloat pos[4];
   glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
   CHECK(pos[0] > 1.0f);                 /* the raster position advanced over the string */
   CHECK(glGetError() == GL_NO_ERROR);
   glutExit();
}

int main(int argc, char **argv)
{
   (void)argc;
   argv0 = argv[0];
   setenv("FIXGLUT_HEADLESS", "1", 1);
   setenv("FIXGLUT_FRAMES", "100", 1);
   setenv("FIXGLUT_FRAME_MS", "16", 1);
   unsetenv("FIXGLUT_OUT");
   unsetenv("FIXGLUT_EVENTS");

   int argc1 = 1;
   char *argv1[] = { argv0, NULL };
   glutInit(&argc1, argv1);
   check_options();
   check_main_loop_event();
   check_leave_returns();
   check_context_requests();

   char err[1024];
   CHECK(in_child(child_leave_default, NULL, 0) == 0);
   CHECK(in_child(child_close_exit, NULL, 0) == 0);
   CHECK(in_child(child_core_profile, err, sizeof err) == 1);
   CHECK(strstr(err, "freeglut (") != NULL &&
         strstr(err, "): Unable to create OpenGL 3.2 context (flags 0, profile 1)") != NULL);

   printf("glut-freeglut: %d checks, %d failed\n", checks, failures);
   return failures ? 1 : 0;
}
