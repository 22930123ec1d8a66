/*
 * libfixglut core: initialisation, the window (GLFW) or the headless frame
 * loop, callbacks, timers, scripted events, glutGet.
 *
 * Rendering: the GL calls of the program go to the OSMesa context of the
 * library it is linked with (fixgl, or Mesa for libfixglut-osmesa); the
 * frame lives in an RGBA8 buffer.  glutSwapBuffers (or, single-buffered,
 * the end of each display callback) copies it to the "presented" frame,
 * which is drawn into the window (viewer/common/fv_present.c) and/or
 * written to PNG.
 */
#include <ctype.h>
#include <errno.h>
#include <GL/freeglut_ext.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "glut_internal.h"

#ifndef FIXGLUT_ORACLE
/* GLFW and Xlib through fv_glfw.h's table (FV_GLFW_DLOPEN): loaded by
 * glutInit in window mode, never by a headless run */
#include "fv_glfw.h"
#include "fv_grab.h"
#include "fv_present.h"
#endif

/* ---- state ------------------------------------------------------------ */

struct glut_timer {
   double due;            /* ms on the glut clock */
   unsigned long seq;     /* registration order among equal due times */
   void (*func)(int);
   int value;
};

struct glut_event {
   int frame;
   char *text;            /* "key:a", "special:LEFT", "mouse:left:down:10:20", ... */
};

static struct {
   bool inited;
   unsigned mode;
   int init_x, init_y, init_w, init_h;

   bool created;
   char *title;
   int w, h;              /* window (= frame) size */
   int x, y;
   OSMesaContext ctx;
   unsigned char *buf;    /* the context's colour buffer, bottom-up RGBA8 */
   unsigned char *shown;  /* the presented frame */
   unsigned char *overlay;/* shown + the open menu (window mode) */
   bool have_shown;

   void (*display)(void);
   void (*reshape)(int, int);
   void (*keyboard)(unsigned char, int, int);
   void (*keyboard_up)(unsigned char, int, int);
   void (*special)(int, int, int);
   void (*special_up)(int, int, int);
   void (*mouse)(int, int, int, int);
   void (*motion)(int, int);
   void (*passive)(int, int);
   void (*entry)(int);
   void (*visibility)(int);
   void (*idle)(void);
   void (*menu_status)(int, int, int);
   void (*menu_state)(int);

   bool redisplay;
   struct glut_timer *timers;
   int num_timers, cap_timers;
   unsigned long timer_seq;

   /* run control */
   bool headless;
   bool fixed_clock;
   long frames;           /* < 0: run until the window closes */
   double frame_ms;
   long frame;            /* current frame number */
   char *out;             /* FIXGLUT_OUT */
   char *screenshot;      /* FIXGLUT_SCREENSHOT */
   char *screenshot_x11;  /* FIXGLUT_SCREENSHOT_X11 */
   struct glut_event *events;
   int num_events;
   double t0;             /* real clock origin, seconds */

   bool wm_close;         /* the user closed the window (or the "close" event) */
   int modifiers;
   int mouse_x, mouse_y;
   unsigned buttons;      /* held buttons (bit per button) */
   unsigned char key_char[512]; /* GLFW key -> char delivered at press */

   /* freeglut's session and options (glutSetOption, glutMainLoopEvent,
    * glutLeaveMainLoop; README.md "freeglut extensions") */
   char *program;         /* argv[0], named in freeglut's error messages */
   bool started;          /* the window's first step (initial reshape) done */
   bool running;          /* inside glutMainLoop, not left */
   bool destroy_pending;  /* glutDestroyWindow: closed at the end of the step */
   bool fullscreen;
   int action_on_close;   /* GLUT_ACTION_EXIT (default), _GLUTMAINLOOP_RETURNS, _CONTINUE_EXECUTION */
   bool use_current_context;
   int direct_rendering, aux, samples;
   bool skip_stale_motion, visualize_normals, join_dots, allow_negative_position;
   int ctx_major, ctx_minor, ctx_flags, ctx_profile;
   void (*close)(void);
   void (*error_func)(const char *fmt, va_list ap);
   void (*warning_func)(const char *fmt, va_list ap);
   void *window_data;

#ifndef FIXGLUT_ORACLE
   GLFWwindow *win;
   struct fv_present *present;
   int windowed_x, windowed_y, windowed_w, windowed_h;   /* before glutFullScreen */
#endif
} G = {
   .init_x = -1, .init_y = -1, .init_w = 300, .init_h = 300,
   .frames = -1, .frame_ms = 16.0,
   .action_on_close = GLUT_ACTION_EXIT, .direct_rendering = GLUT_TRY_DIRECT_CONTEXT,
   .ctx_major = 1, .ctx_minor = 0,
};

/* Errors and warnings go to the program's glutInitErrorFunc /
 * glutInitWarningFunc when it set them (freeglut's fgError/fgWarning);
 * after an error the program ends (exit 1) even if its function returns. */
void glut_fatal(const char *fmt, ...)
{
   va_list ap;
   va_start(ap, fmt);
   if (G.error_func) {
      G.error_func(fmt, ap);
   } else {
      fputs("fixglut: ", stderr);
      vfprintf(stderr, fmt, ap);
      fputc('\n', stderr);
   }
   va_end(ap);
   exit(1);
}

void glut_warn(const char *fmt, ...)
{
   va_list ap;
   va_start(ap, fmt);
   if (G.warning_func) {
      G.warning_func(fmt, ap);
   } else {
      fputs("fixglut: warning: ", stderr);
      vfprintf(stderr, fmt, ap);
      fputc('\n', stderr);
   }
   va_end(ap);
}

/* freeglut's fgError where the program goes on when its error function
 * returns: the message in freeglut's words, "freeglut (PROGRAM): ...",
 * then exit(1) without an error function. */
static void freeglut_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void freeglut_error(const char *fmt, ...)
{
   va_list ap;
   va_start(ap, fmt);
   if (G.error_func) {
      G.error_func(fmt, ap);
      va_end(ap);
      return;
   }
   fprintf(stderr, "freeglut (%s): ", G.program ? G.program : "");
   vfprintf(stderr, fmt, ap);
   fputc('\n', stderr);
   va_end(ap);
   exit(1);
}

/* freeglut's FREEGLUT_EXIT_IF_NOT_INITIALISED */
static void require_init(const char *function)
{
   if (!G.inited)
      freeglut_error("ERROR:  Function <%s> called without first calling 'glutInit'.", function);
}

static double real_seconds(void)
{
   struct timespec ts;
   clock_gettime(CLOCK_MONOTONIC, &ts);
   return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* The glut clock in ms: deterministic (frame * step) in scripted runs. */
static double now_ms(void)
{
   if (G.fixed_clock)
      return (double)G.frame * G.frame_ms;
   return (real_seconds() - G.t0) * 1000.0;
}

static char *xstrdup(const char *s)
{
   char *d = strdup(s ? s : "");
   if (!d)
      glut_fatal("out of memory");
   return d;
}

/* ---- initialisation ----------------------------------------------------- */

/* One integer of an X geometry string as Xlib's ReadInteger reads it: an
 * optional sign, then any digits (none is 0); returns where it stopped. */
static const char *geometry_int(const char *s, int *value)
{
   int sign = 1;
   if (*s == '+' || *s == '-')
      sign = *s++ == '-' ? -1 : 1;
   unsigned v = 0;
   for (; *s >= '0' && *s <= '9'; s++)
      v = v * 10u + (unsigned)(*s - '0');
   *value = sign * (int)v;
   return s;
}

/* -geometry [=][W][{xX}H][{+-}X[{+-}Y]] by XParseGeometry's grammar (the
 * whole string or nothing; a field is bad when its reader consumed
 * nothing), applied as freeglut's glutInit does: a negative offset
 * counts from the right or bottom edge of the screen, less the window's
 * size. */
static void parse_geometry(const char *g)
{
   enum { W = 1, H = 2, X = 4, Y = 8, XNEG = 16, YNEG = 32 };
   int mask = 0, w = 0, h = 0, x = 0, y = 0;
   const char *s = g, *next;
   if (*s == '=')
      s++;
   if (*s && *s != '+' && *s != '-' && *s != 'x' && *s != 'X') {
      if ((next = geometry_int(s, &w)) == s)
         return;
      s = next;
      mask |= W;
   }
   if (*s == 'x' || *s == 'X') {
      s++;
      if ((next = geometry_int(s, &h)) == s)
         return;
      s = next;
      mask |= H;
   }
   if (*s == '+' || *s == '-') {
      const bool neg = *s++ == '-';
      if ((next = geometry_int(s, &x)) == s)
         return;
      s = next;
      x = neg ? -x : x;
      mask |= X | (neg ? XNEG : 0);
      if (*s == '+' || *s == '-') {
         const bool yneg = *s++ == '-';
         if ((next = geometry_int(s, &y)) == s)
            return;
         s = next;
         y = yneg ? -y : y;
         mask |= Y | (yneg ? YNEG : 0);
      }
   }
   if (*s != '\0')
      return;
   if (mask & W)
      G.init_w = w;
   if (mask & H)
      G.init_h = h;
   /* a position is used only when it has both offsets (freeglut's
    * Position.Use; glutGet(GLUT_INIT_WINDOW_X) is -1 otherwise) */
   if ((mask & (X | Y)) == (X | Y)) {
      G.init_x = (mask & XNEG) ? x + glutGet(GLUT_SCREEN_WIDTH) - G.init_w : x;
      G.init_y = (mask & YNEG) ? y + glutGet(GLUT_SCREEN_HEIGHT) - G.init_h : y;
   }
}

static void parse_events(const char *list)
{
   char *copy = xstrdup(list), *save = NULL;
   for (char *tok = strtok_r(copy, ";", &save); tok; tok = strtok_r(NULL, ";", &save)) {
      while (isspace((unsigned char)*tok))
         tok++;
      if (!*tok)
         continue;
      char *colon = strchr(tok, ':');
      char *end;
      long f = strtol(tok, &end, 10);
      if (!colon || end != colon || f < 0)
         glut_fatal("FIXGLUT_EVENTS: bad event \"%s\" (expected FRAME:EVENT)", tok);
      G.events = realloc(G.events, (size_t)(G.num_events + 1) * sizeof *G.events);
      if (!G.events)
         glut_fatal("out of memory");
      G.events[G.num_events].frame = (int)f;
      G.events[G.num_events].text = xstrdup(colon + 1);
      G.num_events++;
   }
   free(copy);
}

GLUT_EXPORT void glutInit(int *argcp, char **argv)
{
   if (G.inited)
      return;
   G.inited = true;
   G.t0 = real_seconds();
   free(G.program);
   G.program = xstrdup(argcp && argv && *argcp > 0 && argv[0] ? argv[0] : "");

   /* freeglut's options, as its glutInit takes them
    * (fghParseCommandLineArguments): -display NAME and -geometry SPEC
    * (each an error without its value), -direct, -indirect (an error
    * together), -iconic, -gldebug, -sync; they are removed from argv,
    * everything else stays, in order, for the program's own parsing.
    * The geometry is applied once the screen is known, below. */
   const char *geometry = NULL;
   if (argcp && argv) {
      const int argc = *argcp;
      int out = 1;
      for (int i = 1; i < argc; i++) {
         const char *a = argv[i];
         if (!strcmp(a, "-display") || !strcmp(a, "-geometry")) {
            if (++i >= argc)
               freeglut_error(!strcmp(a, "-display")
                                 ? "-display parameter must be followed by display name"
                                 : "-geometry parameter must be followed by window geometry settings");
            if (!strcmp(a, "-geometry"))
               geometry = argv[i];
         } else if (!strcmp(a, "-direct") || !strcmp(a, "-indirect")) {
            const bool direct = !strcmp(a, "-direct");
            if (G.direct_rendering == (direct ? GLUT_FORCE_INDIRECT_CONTEXT : GLUT_FORCE_DIRECT_CONTEXT))
               freeglut_error("parameters ambiguity, -direct and -indirect cannot be both specified");
            G.direct_rendering = direct ? GLUT_FORCE_DIRECT_CONTEXT : GLUT_FORCE_INDIRECT_CONTEXT;
         } else if (!strcmp(a, "-iconic") || !strcmp(a, "-gldebug") || !strcmp(a, "-sync")) {
            /* accepted, no effect */
         } else {
            argv[out++] = argv[i];
         }
      }
      if (out < argc)
         argv[out] = NULL;
      *argcp = out;
   }

   const char *e;
#ifdef FIXGLUT_ORACLE
   G.headless = true;    /* the oracle library has no window */
#else
   e = getenv("FIXGLUT_HEADLESS");
   G.headless = e && *e && strcmp(e, "0") != 0;
#endif
   if ((e = getenv("FIXGLUT_FRAMES")) && *e) {
      G.frames = strtol(e, NULL, 10);
      if (G.frames < 1)
         glut_fatal("FIXGLUT_FRAMES must be at least 1 (got \"%s\")", e);
      G.fixed_clock = true;
   } else if (G.headless) {
      G.frames = 1;
      G.fixed_clock = true;
   }
   if ((e = getenv("FIXGLUT_FRAME_MS")) && *e) {
      G.frame_ms = strtod(e, NULL);
      if (!(G.frame_ms > 0.0))
         glut_fatal("FIXGLUT_FRAME_MS must be positive (got \"%s\")", e);
   }
   if ((e = getenv("FIXGLUT_OUT")) && *e)
      G.out = xstrdup(e);
   if ((e = getenv("FIXGLUT_SCREENSHOT")) && *e)
      G.screenshot = xstrdup(e);
   if ((e = getenv("FIXGLUT_SCREENSHOT_X11")) && *e)
      G.screenshot_x11 = xstrdup(e);
   if ((e = getenv("FIXGLUT_EVENTS")) && *e)
      parse_events(e);

#ifndef FIXGLUT_ORACLE
   if (!G.headless) {
      if (fv_glfw_load() != 0)
         glut_fatal("cannot load GLFW for a window (set FIXGLUT_HEADLESS=1 to run without one)");
      if (!glfwInit())
         glut_fatal("cannot initialise GLFW (no display? set FIXGLUT_HEADLESS=1)");
   }
#endif
   if (geometry)
      parse_geometry(geometry);
}

GLUT_EXPORT void glutInitDisplayMode(unsigned int mode)
{
   G.mode = mode;
}

GLUT_EXPORT void glutInitDisplayString(const char *string)
{
   /* A subset: the words rgb(a), double, single, depth, stencil, accum,
    * alpha select the same bits as glutInitDisplayMode. */
   unsigned mode = 0;
   if (!string)
      return;
   if (strstr(string, "double"))
      mode |= GLUT_DOUBLE;
   if (strstr(string, "depth"))
      mode |= GLUT_DEPTH;
   if (strstr(string, "stencil"))
      mode |= GLUT_STENCIL;
   if (strstr(string, "accum"))
      mode |= GLUT_ACCUM;
   if (strstr(string, "alpha") || strstr(string, "rgba"))
      mode |= GLUT_ALPHA;
   G.mode = mode;
}

GLUT_EXPORT void glutInitWindowPosition(int x, int y)
{
   G.init_x = x;
   G.init_y = y;
}

GLUT_EXPORT void glutInitWindowSize(int width, int height)
{
   if (width > 0 && height > 0) {
      G.init_w = width;
      G.init_h = height;
   }
}

/* ---- the frame buffer --------------------------------------------------- */

static void bind_buffer(int w, int h)
{
   size_t n = (size_t)w * h * 4;
   unsigned char *buf = calloc(n, 1), *shown = calloc(n, 1), *overlay = calloc(n, 1);
   if (!buf || !shown || !overlay)
      glut_fatal("out of memory for a %dx%d frame", w, h);
   /* Keep what was presented, clipped/padded to the new size. */
   if (G.shown) {
      for (int y = 0; y < h && y < G.h; y++)
         memcpy(shown + (size_t)y * w * 4, G.shown + (size_t)y * G.w * 4,
                (size_t)(w < G.w ? w : G.w) * 4);
   }
   if (!OSMesaMakeCurrent(G.ctx, buf, GL_UNSIGNED_BYTE, w, h))
      glut_fatal("OSMesaMakeCurrent failed for %dx%d", w, h);
   free(G.buf);
   free(G.shown);
   free(G.overlay);
   G.buf = buf, G.shown = shown, G.overlay = overlay;
   G.w = w, G.h = h;
}

static void do_reshape(int w, int h)
{
   if (w < 1)
      w = 1;
   if (h < 1)
      h = 1;
   if (w != G.w || h != G.h)
      bind_buffer(w, h);
   if (G.reshape)
      G.reshape(w, h);
   else
      glViewport(0, 0, w, h);
   G.redisplay = true;
}

/* ---- window mode (GLFW) ------------------------------------------------- */

#ifndef FIXGLUT_ORACLE
static void present_window(const unsigned char *rgba)
{
   int fw, fh;
   glfwGetFramebufferSize(G.win, &fw, &fh);
   fv_present_frame(G.present, rgba, G.w, G.h, fw, fh);
   glfwSwapBuffers(G.win);
}
#endif

/* Presents the last frame again, with the open menu over it. */
void glut_represent(void)
{
#ifndef FIXGLUT_ORACLE
   if (!G.win || !G.have_shown)
      return;
   memcpy(G.overlay, G.shown, (size_t)G.w * G.h * 4);
   glut_menu_overlay(G.overlay, G.w, G.h);
   present_window(G.overlay);
#endif
}

static void present_frame(void)
{
   /* Mesa's llvmpipe renders in threads: the frame is complete after
    * glFinish (fixgl is synchronous). */
   glFinish();
   memcpy(G.shown, G.buf, (size_t)G.w * G.h * 4);
   G.have_shown = true;
   glut_represent();
}

void glut_menu_status(int status, int x, int y)
{
   if (G.menu_status)
      G.menu_status(status, x, y);
   if (G.menu_state)
      G.menu_state(status);
}

/* Dispatchers shared by the window's events and the scripted events. */
static void ev_key(unsigned char c, bool down)
{
   if (down && G.keyboard)
      G.keyboard(c, G.mouse_x, G.mouse_y);
   else if (!down && G.keyboard_up)
      G.keyboard_up(c, G.mouse_x, G.mouse_y);
}

static void ev_special(int key, bool down)
{
   if (down && G.special)
      G.special(key, G.mouse_x, G.mouse_y);
   else if (!down && G.special_up)
      G.special_up(key, G.mouse_x, G.mouse_y);
}

static void ev_motion(int x, int y)
{
   G.mouse_x = x, G.mouse_y = y;
   if (glut_popup.depth) {
      if (glut_popup_motion(x, y))
         glut_represent();
      return;
   }
   if (G.buttons && G.motion)
      G.motion(x, y);
   else if (!G.buttons && G.passive)
      G.passive(x, y);
}

static void ev_mouse(int button, int state, int x, int y)
{
   G.mouse_x = x, G.mouse_y = y;
   if (glut_popup.depth) {
      if (state == GLUT_UP && button == glut_popup.button) {
         glut_popup_release(x, y);
         glut_represent();
      }
      return;
   }
   if (button >= 0 && button < 3 && glut_attached[button] && state == GLUT_DOWN) {
      glut_popup_open(button, x, y);
      glut_represent();
      return;
   }
   if (button >= 0 && button < 32) {
      if (state == GLUT_DOWN)
         G.buttons |= 1u << button;
      else
         G.buttons &= ~(1u << button);
   }
   if (G.mouse)
      G.mouse(button, state, x, y);
}

#ifndef FIXGLUT_ORACLE
static int last_key_pressed = -1;

static int special_of_glfw(int key)
{
   if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12)
      return GLUT_KEY_F1 + (key - GLFW_KEY_F1);
   switch (key) {
   case GLFW_KEY_LEFT: return GLUT_KEY_LEFT;
   case GLFW_KEY_UP: return GLUT_KEY_UP;
   case GLFW_KEY_RIGHT: return GLUT_KEY_RIGHT;
   case GLFW_KEY_DOWN: return GLUT_KEY_DOWN;
   case GLFW_KEY_PAGE_UP: return GLUT_KEY_PAGE_UP;
   case GLFW_KEY_PAGE_DOWN: return GLUT_KEY_PAGE_DOWN;
   case GLFW_KEY_HOME: return GLUT_KEY_HOME;
   case GLFW_KEY_END: return GLUT_KEY_END;
   case GLFW_KEY_INSERT: return GLUT_KEY_INSERT;
   default: return -1;
   }
}

/* Keys GLUT delivers as ASCII control codes (no GLFW character event). */
static int control_char_of_glfw(int key, int mods)
{
   switch (key) {
   case GLFW_KEY_ESCAPE: return 27;
   case GLFW_KEY_ENTER: case GLFW_KEY_KP_ENTER: return 13;
   case GLFW_KEY_TAB: return 9;
   case GLFW_KEY_BACKSPACE: return 8;
   case GLFW_KEY_DELETE: return 127;
   default: break;
   }
   if ((mods & GLFW_MOD_CONTROL) && key >= GLFW_KEY_A && key <= GLFW_KEY_Z)
      return 1 + (key - GLFW_KEY_A);
   return -1;
}

static void cb_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
   (void)w, (void)scancode;
   G.modifiers = mods & (GLUT_ACTIVE_SHIFT | GLUT_ACTIVE_CTRL | GLUT_ACTIVE_ALT);
   int sp = special_of_glfw(key);
   if (sp >= 0) {
      if (action != GLFW_RELEASE)
         ev_special(sp, true);
      else
         ev_special(sp, false);
      return;
   }
   int c = control_char_of_glfw(key, mods);
   if (c >= 0) {
      if (key >= 0 && key < 512)
         G.key_char[key] = (unsigned char)c;
      if (action != GLFW_RELEASE)
         ev_key((unsigned char)c, true);
   }
   if (action == GLFW_RELEASE && key >= 0 && key < 512 && G.key_char[key]) {
      ev_key(G.key_char[key], false);
      G.key_char[key] = 0;
   }
   /* Printable keys arrive through cb_char right after this press. */
   if (action == GLFW_PRESS && c < 0 && key >= 0 && key < 512)
      last_key_pressed = key;
}
#endif

#ifndef FIXGLUT_ORACLE
static void cb_char(GLFWwindow *w, unsigned int codepoint)
{
   (void)w;
   if (codepoint > 255)
      return;   /* GLUT's keyboard callback carries one byte */
   if (last_key_pressed >= 0)
      G.key_char[last_key_pressed] = (unsigned char)codepoint;
   last_key_pressed = -1;
   ev_key((unsigned char)codepoint, true);
}

static void cb_mouse_button(GLFWwindow *w, int button, int action, int mods)
{
   double x, y;
   int b;
   glfwGetCursorPos(w, &x, &y);
   G.modifiers = mods & (GLUT_ACTIVE_SHIFT | GLUT_ACTIVE_CTRL | GLUT_ACTIVE_ALT);
   switch (button) {
   case GLFW_MOUSE_BUTTON_LEFT: b = GLUT_LEFT_BUTTON; break;
   case GLFW_MOUSE_BUTTON_MIDDLE: b = GLUT_MIDDLE_BUTTON; break;
   case GLFW_MOUSE_BUTTON_RIGHT: b = GLUT_RIGHT_BUTTON; break;
   default: b = button; break;
   }
   ev_mouse(b, action == GLFW_PRESS ? GLUT_DOWN : GLUT_UP, (int)x, (int)y);
}

/* The wheel as buttons 3 (up) and 4 (down), pressed and released, as
 * freeglut reports it to programs without a wheel callback. */
static void cb_scroll(GLFWwindow *w, double dx, double dy)
{
   (void)w, (void)dx;
   if (dy == 0.0)
      return;
   int b = dy > 0.0 ? 3 : 4;
   ev_mouse(b, GLUT_DOWN, G.mouse_x, G.mouse_y);
   ev_mouse(b, GLUT_UP, G.mouse_x, G.mouse_y);
}

static void cb_cursor(GLFWwindow *w, double x, double y)
{
   (void)w;
   ev_motion((int)x, (int)y);
}

static void cb_enter(GLFWwindow *w, int entered)
{
   (void)w;
   if (G.entry)
      G.entry(entered ? GLUT_ENTERED : GLUT_LEFT);
}

static void cb_size(GLFWwindow *w, int width, int height)
{
   (void)w;
   if (width > 0 && height > 0 && (width != G.w || height != G.h))
      do_reshape(width, height);
}

static void cb_refresh(GLFWwindow *w)
{
   (void)w;
   G.redisplay = true;
}

static void cb_iconify(GLFWwindow *w, int iconified)
{
   (void)w;
   if (G.visibility)
      G.visibility(iconified ? GLUT_NOT_VISIBLE : GLUT_VISIBLE);
   if (!iconified)
      G.redisplay = true;
}

static void cb_pos(GLFWwindow *w, int x, int y)
{
   (void)w;
   G.x = x, G.y = y;
}
#endif

GLUT_EXPORT int glutCreateWindow(const char *title)
{
   if (!G.inited)
      glut_fatal("glutCreateWindow called before glutInit");
   if (G.created)
      glut_fatal("only one window is supported (glutCreateWindow called twice)");
   if (G.mode & GLUT_INDEX)
      glut_fatal("colour-index mode is not supported");
   /* glutInitContextVersion/Profile: fixgl is OpenGL 1.5 with the
    * compatibility profile; anything else is refused as freeglut refuses a
    * context the driver cannot create */
   if (G.ctx_major > 1 || (G.ctx_major == 1 && G.ctx_minor > 5) ||
       G.ctx_profile == GLUT_CORE_PROFILE) {
      freeglut_error("Unable to create OpenGL %d.%d context (flags %x, profile %x)",
                     G.ctx_major, G.ctx_minor, G.ctx_flags, G.ctx_profile);
      return 0;
   }
   G.created = true;
   G.started = false;
   G.destroy_pending = false;
   G.fullscreen = false;
   G.frame = 0;
   G.title = xstrdup(title);

   /* GLUT_DEPTH, GLUT_STENCIL and GLUT_ACCUM select the context's ancillary
    * buffers; the colour buffer is always RGBA8 (GLUT_ALPHA or not). */
   G.ctx = OSMesaCreateContextExt(OSMESA_RGBA,
                                  (G.mode & GLUT_DEPTH) ? 24 : 0,
                                  (G.mode & GLUT_STENCIL) ? 8 : 0,
                                  (G.mode & GLUT_ACCUM) ? 16 : 0, NULL);
   if (!G.ctx)
      glut_fatal("cannot create the OSMesa context");
   G.x = G.init_x >= 0 ? G.init_x : 0;
   G.y = G.init_y >= 0 ? G.init_y : 0;

#ifndef FIXGLUT_ORACLE
   if (!G.headless) {
      glfwDefaultWindowHints();
      glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
      glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
      glfwWindowHint(GLFW_RED_BITS, 8);
      glfwWindowHint(GLFW_GREEN_BITS, 8);
      glfwWindowHint(GLFW_BLUE_BITS, 8);
      glfwWindowHint(GLFW_DEPTH_BITS, 0);
      glfwWindowHint(GLFW_STENCIL_BITS, 0);
      glfwWindowHint(GLFW_SAMPLES, 0);
      if (G.init_x >= 0 && G.init_y >= 0)
         glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
      G.win = glfwCreateWindow(G.init_w, G.init_h, G.title, NULL, NULL);
      if (!G.win)
         glut_fatal("cannot create the window");
      if (G.init_x >= 0 && G.init_y >= 0) {
         glfwSetWindowPos(G.win, G.init_x, G.init_y);
         glfwShowWindow(G.win);
      }
      glfwMakeContextCurrent(G.win);
      glfwSwapInterval(0);
      G.present = fv_present_create();
      if (!G.present)
         glut_fatal("the system GL cannot present frames");
      glfwSetKeyCallback(G.win, cb_key);
      glfwSetCharCallback(G.win, cb_char);
      glfwSetMouseButtonCallback(G.win, cb_mouse_button);
      glfwSetScrollCallback(G.win, cb_scroll);
      glfwSetCursorPosCallback(G.win, cb_cursor);
      glfwSetCursorEnterCallback(G.win, cb_enter);
      glfwSetWindowSizeCallback(G.win, cb_size);
      glfwSetWindowRefreshCallback(G.win, cb_refresh);
      glfwSetWindowIconifyCallback(G.win, cb_iconify);
      glfwSetWindowPosCallback(G.win, cb_pos);
      glfwGetWindowPos(G.win, &G.x, &G.y);
   }
#endif
   bind_buffer(G.init_w, G.init_h);
   G.redisplay = true;
   return 1;
}

/* The window and its context go, after the close callback (freeglut's
 * fgDestroyWindow); its other callbacks are forgotten. */
static void destroy_window(void)
{
   if (!G.created)
      return;
   void (*close)(void) = G.close;
   G.close = NULL;
   if (close)
      close();
   glFinish();
#ifndef FIXGLUT_ORACLE
   if (G.win) {
      fv_present_destroy(G.present);
      G.present = NULL;
      glfwDestroyWindow(G.win);
      G.win = NULL;
   }
#endif
   OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
   OSMesaDestroyContext(G.ctx);
   G.ctx = NULL;
   free(G.buf);
   free(G.shown);
   free(G.overlay);
   G.buf = G.shown = G.overlay = NULL;
   G.w = G.h = 0;
   G.have_shown = false;
   G.created = false;
   G.destroy_pending = false;
   G.redisplay = false;
   G.display = NULL;
   G.reshape = NULL;
   G.keyboard = G.keyboard_up = NULL;
   G.special = G.special_up = NULL;
   G.mouse = NULL;
   G.motion = G.passive = NULL;
   G.entry = G.visibility = NULL;
   G.window_data = NULL;
   free(G.title);
   G.title = NULL;
}

/* freeglut's fgDeinitialize: the window destroyed, timers and options
 * back to their defaults; glutInit may start a new session. */
static void deinitialize(void)
{
   destroy_window();
   G.idle = NULL;
   G.menu_status = NULL;
   G.menu_state = NULL;
   G.num_timers = 0;
   for (int i = 0; i < G.num_events; i++)
      free(G.events[i].text);
   free(G.events);
   G.events = NULL;
   G.num_events = 0;
   free(G.out);
   free(G.screenshot);
   free(G.screenshot_x11);
   G.out = G.screenshot = G.screenshot_x11 = NULL;
   G.mode = 0;
   G.init_x = G.init_y = -1;
   G.init_w = G.init_h = 300;
   G.frames = -1;
   G.frame_ms = 16.0;
   G.fixed_clock = false;
   G.action_on_close = GLUT_ACTION_EXIT;
   G.use_current_context = false;
   G.direct_rendering = GLUT_TRY_DIRECT_CONTEXT;
   G.aux = G.samples = 0;
   G.skip_stale_motion = G.visualize_normals = G.join_dots = G.allow_negative_position = false;
   G.ctx_major = 1, G.ctx_minor = 0, G.ctx_flags = 0, G.ctx_profile = 0;
   G.running = false;
   G.inited = false;
}

/* Closed at the end of the loop's step, after the close callback; in
 * glutMainLoop the loop then ends (no window is left). */
GLUT_EXPORT void glutDestroyWindow(int win)
{
   if (win != 1 || !G.created)
      return;
   G.destroy_pending = true;
}

GLUT_EXPORT int glutGetWindow(void)
{
   return G.created ? 1 : 0;
}

GLUT_EXPORT void glutSetWindow(int win)
{
   if (win != 1)
      glut_warn("glutSetWindow(%d): there is only window 1", win);
}

GLUT_EXPORT void glutPostRedisplay(void)
{
   G.redisplay = true;
}

GLUT_EXPORT void glutSwapBuffers(void)
{
   if (G.created)
      present_frame();
}

GLUT_EXPORT void glutSetWindowTitle(const char *title)
{
   free(G.title);
   G.title = xstrdup(title);
#ifndef FIXGLUT_ORACLE
   if (G.win)
      glfwSetWindowTitle(G.win, G.title);
#endif
}

GLUT_EXPORT void glutSetIconTitle(const char *title)
{
   (void)title;
}

GLUT_EXPORT void glutReshapeWindow(int width, int height)
{
   if (!G.created || width < 1 || height < 1)
      return;
#ifndef FIXGLUT_ORACLE
   if (G.win) {
      glfwSetWindowSize(G.win, width, height);   /* cb_size reshapes */
      return;
   }
#endif
   do_reshape(width, height);
}

GLUT_EXPORT void glutPositionWindow(int x, int y)
{
#ifndef FIXGLUT_ORACLE
   if (G.win) {
      glfwSetWindowPos(G.win, x, y);
      return;
   }
#endif
   G.x = x, G.y = y;
}

GLUT_EXPORT void glutShowWindow(void)
{
#ifndef FIXGLUT_ORACLE
   if (G.win)
      glfwShowWindow(G.win);
#endif
}

GLUT_EXPORT void glutHideWindow(void)
{
#ifndef FIXGLUT_ORACLE
   if (G.win)
      glfwHideWindow(G.win);
#endif
}

/* A documented no-op. */
GLUT_EXPORT void glutIconifyWindow(void) {}
GLUT_EXPORT void glutSetCursor(int cursor) { (void)cursor; }

/* Full screen on the primary monitor through GLFW (the window's size
 * change reshapes the frame); headless, only the state glutGet
 * (GLUT_FULL_SCREEN) reports changes: the frame keeps its size. */
static void set_full_screen(bool on)
{
   if (!G.created || on == G.fullscreen)
      return;
   G.fullscreen = on;
#ifndef FIXGLUT_ORACLE
   if (G.win) {
      if (on) {
         GLFWmonitor *mon = glfwGetPrimaryMonitor();
         const GLFWvidmode *vm = mon ? glfwGetVideoMode(mon) : NULL;
         if (!vm) {
            G.fullscreen = false;
            return;
         }
         glfwGetWindowPos(G.win, &G.windowed_x, &G.windowed_y);
         glfwGetWindowSize(G.win, &G.windowed_w, &G.windowed_h);
         glfwSetWindowMonitor(G.win, mon, 0, 0, vm->width, vm->height, vm->refreshRate);
      } else {
         glfwSetWindowMonitor(G.win, NULL, G.windowed_x, G.windowed_y, G.windowed_w,
                              G.windowed_h, 0);
      }
   }
#endif
}

GLUT_EXPORT void glutFullScreen(void) { set_full_screen(true); }
GLUT_EXPORT void glutLeaveFullScreen(void) { set_full_screen(false); }
GLUT_EXPORT void glutFullScreenToggle(void) { set_full_screen(!G.fullscreen); }

GLUT_EXPORT void glutWarpPointer(int x, int y)
{
#ifndef FIXGLUT_ORACLE
   if (G.win)
      glfwSetCursorPos(G.win, x, y);
#endif
   G.mouse_x = x, G.mouse_y = y;
}

/* ---- callbacks ---------------------------------------------------------- */

GLUT_EXPORT void glutDisplayFunc(void (*func)(void))
{
   if (!func)
      glut_fatal("glutDisplayFunc: NULL display callback");
   G.display = func;
}
GLUT_EXPORT void glutReshapeFunc(void (*func)(int, int)) { G.reshape = func; }
GLUT_EXPORT void glutKeyboardFunc(void (*func)(unsigned char, int, int)) { G.keyboard = func; }
GLUT_EXPORT void glutKeyboardUpFunc(void (*func)(unsigned char, int, int)) { G.keyboard_up = func; }
GLUT_EXPORT void glutSpecialFunc(void (*func)(int, int, int)) { G.special = func; }
GLUT_EXPORT void glutSpecialUpFunc(void (*func)(int, int, int)) { G.special_up = func; }
GLUT_EXPORT void glutMouseFunc(void (*func)(int, int, int, int)) { G.mouse = func; }
GLUT_EXPORT void glutMotionFunc(void (*func)(int, int)) { G.motion = func; }
GLUT_EXPORT void glutPassiveMotionFunc(void (*func)(int, int)) { G.passive = func; }
GLUT_EXPORT void glutEntryFunc(void (*func)(int)) { G.entry = func; }
GLUT_EXPORT void glutVisibilityFunc(void (*func)(int)) { G.visibility = func; }
GLUT_EXPORT void glutIdleFunc(void (*func)(void)) { G.idle = func; }
GLUT_EXPORT void glutMenuStatusFunc(void (*func)(int, int, int)) { G.menu_status = func; }
GLUT_EXPORT void glutMenuStateFunc(void (*func)(int)) { G.menu_state = func; }
/* freeglut: the window's close (destroy) callback; glutWMCloseFunc is
 * the same callback under its older name */
GLUT_EXPORT void glutCloseFunc(void (*func)(void)) { G.close = func; }
GLUT_EXPORT void glutWMCloseFunc(void (*func)(void)) { G.close = func; }
GLUT_EXPORT void glutInitErrorFunc(void (*func)(const char *fmt, va_list ap)) { G.error_func = func; }
GLUT_EXPORT void glutInitWarningFunc(void (*func)(const char *fmt, va_list ap)) { G.warning_func = func; }
GLUT_EXPORT void glutSetWindowData(void *data) { G.window_data = data; }
GLUT_EXPORT void *glutGetWindowData(void) { return G.window_data; }

GLUT_EXPORT void glutInitContextVersion(int major, int minor)
{
   G.ctx_major = major;
   G.ctx_minor = minor;
}
GLUT_EXPORT void glutInitContextFlags(int flags) { G.ctx_flags = flags; }
GLUT_EXPORT void glutInitContextProfile(int profile) { G.ctx_profile = profile; }

/* freeglut's options (fg_state.c glutSetOption); glutGet reads them back */
GLUT_EXPORT void glutSetOption(GLenum what, int value)
{
   require_init("glutSetOption");
   switch (what) {
   case GLUT_INIT_WINDOW_X: G.init_x = value; break;
   case GLUT_INIT_WINDOW_Y: G.init_y = value; break;
   case GLUT_INIT_WINDOW_WIDTH: G.init_w = value; break;
   case GLUT_INIT_WINDOW_HEIGHT: G.init_h = value; break;
   case GLUT_INIT_DISPLAY_MODE: G.mode = (unsigned)value; break;
   case GLUT_ACTION_ON_WINDOW_CLOSE: G.action_on_close = value; break;
   case GLUT_RENDERING_CONTEXT: G.use_current_context = value == GLUT_USE_CURRENT_CONTEXT; break;
   case GLUT_DIRECT_RENDERING: G.direct_rendering = value; break;
   case GLUT_WINDOW_CURSOR: glutSetCursor(value); break;
   case GLUT_AUX: G.aux = value; break;
   case GLUT_MULTISAMPLE: G.samples = value; break;
   case GLUT_SKIP_STALE_MOTION_EVENTS: G.skip_stale_motion = value != 0; break;
   case GLUT_GEOMETRY_VISUALIZE_NORMALS: G.visualize_normals = value != 0; break;
   case GLUT_STROKE_FONT_DRAW_JOIN_DOTS: G.join_dots = value != 0; break;
   case GLUT_ALLOW_NEGATIVE_WINDOW_POSITION: G.allow_negative_position = value != 0; break;
   default:
      glut_warn("glutSetOption(): missing enum handle %d", (int)what);
      break;
   }
}

GLUT_EXPORT void glutTimerFunc(unsigned int millis, void (*func)(int), int value)
{
   if (!func)
      return;
   if (G.num_timers == G.cap_timers) {
      G.cap_timers = G.cap_timers ? 2 * G.cap_timers : 16;
      G.timers = realloc(G.timers, (size_t)G.cap_timers * sizeof *G.timers);
      if (!G.timers)
         glut_fatal("out of memory");
   }
   G.timers[G.num_timers++] = (struct glut_timer){
      .due = now_ms() + millis, .seq = G.timer_seq++, .func = func, .value = value };
}

/* Fires the timers due by `now`, earliest first; timers registered by
 * the callbacks wait for the next frame. */
static void run_timers(double now)
{
   unsigned long limit = G.timer_seq;
   for (;;) {
      int best = -1;
      for (int i = 0; i < G.num_timers; i++) {
         const struct glut_timer *t = &G.timers[i];
         if (t->seq >= limit || t->due > now)
            continue;
         if (best < 0 || t->due < G.timers[best].due ||
             (t->due == G.timers[best].due && t->seq < G.timers[best].seq))
            best = i;
      }
      if (best < 0)
         return;
      struct glut_timer t = G.timers[best];
      G.timers[best] = G.timers[--G.num_timers];
      t.func(t.value);
   }
}

/* ---- glutGet and friends ------------------------------------------------ */

static int get_integer(GLenum pname)
{
   GLint v = 0;
   glGetIntegerv(pname, &v);
   return v;
}

GLUT_EXPORT int glutGet(GLenum type)
{
   switch (type) {
   case GLUT_WINDOW_X: return G.created ? G.x : 0;
   case GLUT_WINDOW_Y: return G.created ? G.y : 0;
   case GLUT_WINDOW_WIDTH: return G.created ? G.w : 0;
   case GLUT_WINDOW_HEIGHT: return G.created ? G.h : 0;
   case GLUT_WINDOW_BUFFER_SIZE:
      return G.created ? get_integer(GL_RED_BITS) + get_integer(GL_GREEN_BITS) +
                         get_integer(GL_BLUE_BITS) + get_integer(GL_ALPHA_BITS) : 0;
   case GLUT_WINDOW_STENCIL_SIZE: return G.created ? get_integer(GL_STENCIL_BITS) : 0;
   case GLUT_WINDOW_DEPTH_SIZE: return G.created ? get_integer(GL_DEPTH_BITS) : 0;
   case GLUT_WINDOW_RED_SIZE: return G.created ? get_integer(GL_RED_BITS) : 0;
   case GLUT_WINDOW_GREEN_SIZE: return G.created ? get_integer(GL_GREEN_BITS) : 0;
   case GLUT_WINDOW_BLUE_SIZE: return G.created ? get_integer(GL_BLUE_BITS) : 0;
   case GLUT_WINDOW_ALPHA_SIZE: return G.created ? get_integer(GL_ALPHA_BITS) : 0;
   case GLUT_WINDOW_ACCUM_RED_SIZE: return G.created ? get_integer(GL_ACCUM_RED_BITS) : 0;
   case GLUT_WINDOW_ACCUM_GREEN_SIZE: return G.created ? get_integer(GL_ACCUM_GREEN_BITS) : 0;
   case GLUT_WINDOW_ACCUM_BLUE_SIZE: return G.created ? get_integer(GL_ACCUM_BLUE_BITS) : 0;
   case GLUT_WINDOW_ACCUM_ALPHA_SIZE: return G.created ? get_integer(GL_ACCUM_ALPHA_BITS) : 0;
   case GLUT_WINDOW_DOUBLEBUFFER: return (G.mode & GLUT_DOUBLE) ? 1 : 0;
   case GLUT_WINDOW_RGBA: return 1;
   case GLUT_WINDOW_PARENT: return 0;
   case GLUT_WINDOW_NUM_CHILDREN: return 0;
   case GLUT_WINDOW_COLORMAP_SIZE: return 0;
   case GLUT_WINDOW_NUM_SAMPLES: return 0;
   case GLUT_WINDOW_STEREO: return 0;
   case GLUT_WINDOW_CURSOR: return GLUT_CURSOR_INHERIT;
   case GLUT_WINDOW_FORMAT_ID: return 0;
   case GLUT_SCREEN_WIDTH:
   case GLUT_SCREEN_HEIGHT:
   case GLUT_SCREEN_WIDTH_MM:
   case GLUT_SCREEN_HEIGHT_MM: {
      /* Headless: a 1280x1024 screen at 96 dpi. */
      int sw = 1280, sh = 1024;
#ifndef FIXGLUT_ORACLE
      if (!G.headless) {
         const GLFWvidmode *vm = glfwGetVideoMode(glfwGetPrimaryMonitor());
         if (vm)
            sw = vm->width, sh = vm->height;
      }
#endif
      if (type == GLUT_SCREEN_WIDTH)
         return sw;
      if (type == GLUT_SCREEN_HEIGHT)
         return sh;
      return (int)((type == GLUT_SCREEN_WIDTH_MM ? sw : sh) * 25.4 / 96.0 + 0.5);
   }
   case GLUT_MENU_NUM_ITEMS:
      return glut_current_menu ? glut_menus[glut_current_menu - 1].num_items : 0;
   case GLUT_DISPLAY_MODE_POSSIBLE: return (G.mode & (GLUT_INDEX | GLUT_STEREO)) ? 0 : 1;
   case GLUT_INIT_WINDOW_X: return G.init_x;
   case GLUT_INIT_WINDOW_Y: return G.init_y;
   case GLUT_INIT_WINDOW_WIDTH: return G.init_w;
   case GLUT_INIT_WINDOW_HEIGHT: return G.init_h;
   case GLUT_INIT_DISPLAY_MODE: return (int)G.mode;
   case GLUT_ELAPSED_TIME: return (int)now_ms();
   /* freeglut's */
   case GLUT_INIT_STATE: return G.inited ? 1 : 0;
   case GLUT_ACTION_ON_WINDOW_CLOSE: return G.action_on_close;
   case GLUT_VERSION: return FIXGLUT_FREEGLUT_VERSION;
   case GLUT_RENDERING_CONTEXT:
      return G.use_current_context ? GLUT_USE_CURRENT_CONTEXT : GLUT_CREATE_NEW_CONTEXT;
   case GLUT_DIRECT_RENDERING: return G.direct_rendering;
   case GLUT_FULL_SCREEN: return G.fullscreen ? 1 : 0;
   case GLUT_AUX: return G.aux;
   case GLUT_MULTISAMPLE: return G.samples;
   case GLUT_SKIP_STALE_MOTION_EVENTS: return G.skip_stale_motion;
   case GLUT_GEOMETRY_VISUALIZE_NORMALS: return G.visualize_normals;
   case GLUT_STROKE_FONT_DRAW_JOIN_DOTS: return G.join_dots;
   case GLUT_ALLOW_NEGATIVE_WINDOW_POSITION: return G.allow_negative_position;
   case GLUT_INIT_MAJOR_VERSION: return G.ctx_major;
   case GLUT_INIT_MINOR_VERSION: return G.ctx_minor;
   case GLUT_INIT_FLAGS: return G.ctx_flags;
   case GLUT_INIT_PROFILE: return G.ctx_profile;
   case GLUT_WINDOW_BORDER_WIDTH:
   case GLUT_WINDOW_BORDER_HEIGHT:
   case GLUT_WINDOW_SRGB: return 0;
   default:
      glut_warn("glutGet: unknown query %u", (unsigned)type);
      return -1;
   }
}

GLUT_EXPORT int glutDeviceGet(GLenum type)
{
   switch (type) {
   case GLUT_HAS_KEYBOARD: return 1;
   case GLUT_HAS_MOUSE: return 1;
   case GLUT_NUM_MOUSE_BUTTONS: return 3;
   default: return 0;
   }
}

GLUT_EXPORT int glutGetModifiers(void)
{
   return G.modifiers;
}

GLUT_EXPORT int glutExtensionSupported(const char *name)
{
   const char *ext = (const char *)glGetString(GL_EXTENSIONS);
   size_t n = name ? strlen(name) : 0;
   if (!ext || !n || strchr(name, ' '))
      return 0;
   for (const char *p = ext; (p = strstr(p, name)) != NULL; p += n) {
      if ((p == ext || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
         return 1;
   }
   return 0;
}

/* ---- scripted events ---------------------------------------------------- */

static int special_of_name(const char *s)
{
   static const struct { const char *name; int key; } names[] = {
      { "LEFT", GLUT_KEY_LEFT }, { "UP", GLUT_KEY_UP }, { "RIGHT", GLUT_KEY_RIGHT },
      { "DOWN", GLUT_KEY_DOWN }, { "PAGE_UP", GLUT_KEY_PAGE_UP },
      { "PAGE_DOWN", GLUT_KEY_PAGE_DOWN }, { "HOME", GLUT_KEY_HOME }, { "END", GLUT_KEY_END },
      { "INSERT", GLUT_KEY_INSERT },
   };
   if ((s[0] == 'F' || s[0] == 'f') && isdigit((unsigned char)s[1])) {
      int n = atoi(s + 1);
      if (n >= 1 && n <= 12)
         return GLUT_KEY_F1 + n - 1;
   }
   for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
      if (!strcasecmp(s, names[i].name))
         return names[i].key;
   return -1;
}

static int button_of_name(const char *s)
{
   if (!strcmp(s, "left"))
      return GLUT_LEFT_BUTTON;
   if (!strcmp(s, "middle"))
      return GLUT_MIDDLE_BUTTON;
   if (!strcmp(s, "right"))
      return GLUT_RIGHT_BUTTON;
   if (isdigit((unsigned char)s[0]))
      return atoi(s);
   return -1;
}

/* KEY: one character, or #N (decimal code, e.g. #27 for Escape). */
static int key_of_text(const char *s)
{
   if (s[0] == '#' && isdigit((unsigned char)s[1]))
      return atoi(s + 1) & 0xff;
   if (s[0] && !s[1])
      return (unsigned char)s[0];
   return -1;
}

static void run_event(const char *text)
{
   char buf[256];
   char *f[8] = { 0 };
   int n = 0;
   snprintf(buf, sizeof buf, "%s", text);
   /* fields separated by ':'; a key field may itself be ':' ("key::") */
   char *p = buf;
   while (n < 8) {
      f[n++] = p;
      char *c = strchr(p, ':');
      if (!c)
         break;
      if (n == 2 && c == p && (!strcmp(f[0], "key") || !strcmp(f[0], "keyup")))
         c = strchr(p + 1, ':');  /* the key is ':' itself */
      if (!c)
         break;
      *c = '\0';
      p = c + 1;
   }
   const char *what = f[0];
   if ((!strcmp(what, "key") || !strcmp(what, "keyup")) && n >= 2 && key_of_text(f[1]) >= 0) {
      if (n >= 4)
         G.mouse_x = atoi(f[2]), G.mouse_y = atoi(f[3]);
      ev_key((unsigned char)key_of_text(f[1]), what[3] != 'u');
   } else if ((!strcmp(what, "special") || !strcmp(what, "specialup")) && n >= 2 &&
              special_of_name(f[1]) >= 0) {
      ev_special(special_of_name(f[1]), what[7] != 'u');
   } else if (!strcmp(what, "mouse") && n >= 5 && button_of_name(f[1]) >= 0 &&
              (!strcmp(f[2], "down") || !strcmp(f[2], "up"))) {
      ev_mouse(button_of_name(f[1]), !strcmp(f[2], "down") ? GLUT_DOWN : GLUT_UP,
               atoi(f[3]), atoi(f[4]));
   } else if (!strcmp(what, "motion") && n >= 3) {
      ev_motion(atoi(f[1]), atoi(f[2]));
   } else if (!strcmp(what, "mods") && n >= 2) {
      int m = 0;
      if (strstr(f[1], "shift"))
         m |= GLUT_ACTIVE_SHIFT;
      if (strstr(f[1], "ctrl"))
         m |= GLUT_ACTIVE_CTRL;
      if (strstr(f[1], "alt"))
         m |= GLUT_ACTIVE_ALT;
      G.modifiers = m;
   } else if (!strcmp(what, "menu") && n >= 3 && button_of_name(f[1]) >= 0) {
      if (!glut_menu_choose_path(button_of_name(f[1]), f[2]))
         glut_fatal("FIXGLUT_EVENTS: \"%s\": no such menu entry", text);
   } else if (!strcmp(what, "reshape") && n >= 3) {
      glutReshapeWindow(atoi(f[1]), atoi(f[2]));
   } else if (!strcmp(what, "redisplay")) {
      G.redisplay = true;
   } else if (!strcmp(what, "close")) {
      G.wm_close = true;
   } else {
      glut_fatal("FIXGLUT_EVENTS: unknown or malformed event \"%s\"", text);
   }
}

/* ---- output ------------------------------------------------------------- */

static bool is_directory(const char *path)
{
   struct stat st;
   size_t n = strlen(path);
   return (n && path[n - 1] == '/') || (stat(path, &st) == 0 && S_ISDIR(st.st_mode));
}

/* Writes the presented frame per FIXGLUT_OUT; last: the run's final frame. */
static void write_frame(bool last)
{
   char path[4096];
   if (!G.out)
      return;
   if (strstr(G.out, "%")) {
      snprintf(path, sizeof path, G.out, (int)G.frame);
   } else if (is_directory(G.out)) {
      mkdir(G.out, 0777);
      snprintf(path, sizeof path, "%s/frame-%04ld.png", G.out, G.frame);
   } else {
      if (!last)
         return;
      snprintf(path, sizeof path, "%s", G.out);
   }
   if (glut_png_write(path, G.w, G.h, G.shown, true) != 0)
      glut_fatal("cannot write %s", path);
}

static void write_screenshot(void)
{
#ifndef FIXGLUT_ORACLE
   if ((!G.screenshot && !G.screenshot_x11) || !G.win)
      return;
   int fw, fh;
   glfwGetFramebufferSize(G.win, &fw, &fh);
   unsigned char *px = malloc((size_t)fw * fh * 4);
   if (!px)
      glut_fatal("out of memory");
   /* The presented frame drawn again into the back buffer, read back
    * through the system GL, then shown. */
   memcpy(G.overlay, G.shown, (size_t)G.w * G.h * 4);
   glut_menu_overlay(G.overlay, G.w, G.h);
   fv_present_frame(G.present, G.overlay, G.w, G.h, fw, fh);
   fv_present_read(G.present, 0, fw, fh, px);
   glfwSwapBuffers(G.win);
   if (G.screenshot && glut_png_write(G.screenshot, fw, fh, px, true) != 0)
      glut_fatal("cannot write %s", G.screenshot);
   /* What the X server shows in the window once the buffers are swapped. */
   if (G.screenshot_x11) {
      fv_present_finish(G.present);
      int ww, wh;
      glfwGetWindowSize(G.win, &ww, &wh);
      unsigned char *xp = malloc((size_t)ww * wh * 4);
      if (!xp)
         glut_fatal("out of memory");
      if (fv_grab_window(G.win, ww, wh, xp) != 0 ||
          glut_png_write(G.screenshot_x11, ww, wh, xp, true) != 0)
         glut_fatal("cannot write the window's X11 image to %s", G.screenshot_x11);
      free(xp);
   }
   free(px);
#endif
}

/* ---- the main loop ------------------------------------------------------ */

#ifndef FIXGLUT_ORACLE
static double next_timer_due(void)
{
   double due = -1.0;
   for (int i = 0; i < G.num_timers; i++)
      if (due < 0.0 || G.timers[i].due < due)
         due = G.timers[i].due;
   return due;
}
#endif

/* The window closed by the user (window manager), the "close" event, or
 * the end of a FIXGLUT_FRAMES run: freeglut's WM_DELETE_WINDOW handling. */
static void close_by_user(void)
{
   G.wm_close = false;
   destroy_window();
   if (G.action_on_close == GLUT_ACTION_EXIT) {
      deinitialize();
      exit(0);
   }
   if (G.action_on_close == GLUT_ACTION_GLUTMAINLOOP_RETURNS)
      G.running = false;
}

/* One step of the loop (a frame): window events, the frame's scripted
 * events, timers, the idle callback (glutMainLoop only, as freeglut's
 * glutMainLoopEvent calls none), the display callback when a redisplay is
 * pending, the frame written; then a window glutDestroyWindow or the user
 * closed goes. */
static void loop_step(bool with_idle)
{
   if (!G.started) {
      /* the window's first step: its initial reshape (freeglut's
       * GLUT_INIT_WORK) */
      G.started = true;
      if (!G.display)
         glut_fatal("no display callback for the window");
      do_reshape(G.w, G.h);
      if (G.visibility)
         G.visibility(GLUT_VISIBLE);
   }
#ifndef FIXGLUT_ORACLE
   if (G.win) {
      if (G.fixed_clock || G.idle || G.redisplay || !with_idle) {
         glfwPollEvents();
      } else {
         double due = next_timer_due();
         double wait = due < 0.0 ? 0.5 : (due - now_ms()) / 1000.0;
         if (wait > 0.0)
            glfwWaitEventsTimeout(wait > 0.5 ? 0.5 : wait);
         else
            glfwPollEvents();
      }
      if (G.win && glfwWindowShouldClose(G.win))
         G.wm_close = true;
   }
#endif
   if (G.wm_close) {
      close_by_user();
      return;
   }
   for (int i = 0; i < G.num_events && G.created; i++)
      if (G.events[i].frame == G.frame)
         run_event(G.events[i].text);
   if (G.created && !G.wm_close && !G.destroy_pending) {
      run_timers(now_ms());
      if (with_idle && G.idle)
         G.idle();
   }
   if (G.created && G.redisplay && !G.wm_close && !G.destroy_pending) {
      G.redisplay = false;
      G.display();
      if (!(G.mode & GLUT_DOUBLE))
         present_frame();   /* single-buffered: the frame as flushed */
   }
   if (!G.created)
      return;
   bool last = G.frames >= 0 && G.frame + 1 >= G.frames;
   write_frame(last);
   if (last)
      write_screenshot();
   G.frame++;
   if (G.destroy_pending)
      destroy_window();
   else if (G.wm_close || (G.frames >= 0 && G.frame >= G.frames))
      close_by_user();   /* a FIXGLUT_FRAMES run ends as if the user closed the window */
}

GLUT_EXPORT void glutMainLoop(void)
{
   if (!G.created)
      glut_fatal("glutMainLoop: no window was created");
   if (!G.display)
      glut_fatal("glutMainLoop: no display callback for the window");
   G.running = true;
   while (G.running && G.created)
      loop_step(true);
   /* left (glutLeaveMainLoop), or no window is left: freeglut
    * deinitialises, then ends the program unless told otherwise */
   int action = G.action_on_close;
   deinitialize();
   if (action == GLUT_ACTION_EXIT)
      exit(0);
}

GLUT_EXPORT void glutMainLoopEvent(void)
{
   require_init("glutMainLoopEvent");
   if (G.created)
      loop_step(false);
}

GLUT_EXPORT void glutLeaveMainLoop(void)
{
   require_init("glutLeaveMainLoop");
   G.running = false;
}

GLUT_EXPORT void glutExit(void)
{
   if (G.inited)
      deinitialize();
}
