/*
 * glxattribs - GLX_ARB_create_context and GLX 1.3 pbuffers, on Mesa's
 * libGL and on fixgl's (run_glx.py compare):
 *   - glXCreateContextAttribsARB with the attribute lists of the probe
 *     p_glx_create_context: each gives a context or the X error (code
 *     past the GLX error base or core code, minor opcode) the oracle
 *     gives; a version above 1.5 gives a context on Mesa (GL 4.5) and
 *     GLXBadFBConfig on fixgl (GL 1.5), as Mesa refuses a version it
 *     lacks (4.6 compatibility, 5.0);
 *   - pbuffers of a double- and a single-buffered config: their
 *     attributes (glXQueryDrawable), a scene drawn into each and read
 *     back with glReadPixels, the errors of a missing config and of a
 *     query of no or a destroyed pbuffer;
 *   - a window drawn by a context of glXCreateContextAttribsARB (1.5,
 *     compatibility profile, debug flag).
 * The images (the window, then the two pbuffers) go to one PPM file that
 * the runner compares; every result above is checked on the way (exit 1
 * with a message when one differs from the oracle's).
 */
#include <GL/gl.h>

#include "glx_frames.h"   /* <GL/glx.h>, and with it <GL/glxext.h> */

#define CHECK(cond)                                                           \
   do {                                                                       \
      if (!(cond)) {                                                          \
         fprintf(stderr, "glxattribs: check failed: %s (line %d)\n", #cond, __LINE__); \
         exit(1);                                                             \
      }                                                                       \
   } while (0)

static int glx_error_base;
static int last_error, last_minor, errors;

/* the error as the program sees it: GLX errors as 1000 + their number */
static int on_error(Display *dpy, XErrorEvent *ev)
{
   (void)dpy;
   const int c = ev->error_code;
   last_error = glx_error_base && c >= glx_error_base ? 1000 + c - glx_error_base : c;
   last_minor = ev->minor_code;
   errors++;
   return 0;
}

static void expect_error(Display *dpy, int code, int minor, const char *what)
{
   XSync(dpy, False);
   if (errors != 1 || last_error != code || last_minor != minor) {
      fprintf(stderr, "glxattribs: %s: %d errors, the last %d (minor %d); expected %d (minor %d)\n",
              what, errors, last_error, last_minor, code, minor);
      exit(1);
   }
   errors = 0;
}

static void expect_no_error(Display *dpy, const char *what)
{
   XSync(dpy, False);
   if (errors) {
      fprintf(stderr, "glxattribs: %s: X error %d (minor %d)\n", what, last_error, last_minor);
      exit(1);
   }
}

static void scene(int w, int h, float turn)
{
   glViewport(0, 0, w, h);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(-1, 1, -1, 1, -2, 2);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glRotatef(turn, 0, 0, 1);
   glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
   glClearDepth(1.0);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);
   glBegin(GL_TRIANGLES);
   glColor3f(1, 0, 0);
   glVertex3f(-0.9f, -0.8f, 0.5f);
   glColor3f(0, 1, 0);
   glVertex3f(0.9f, -0.6f, -0.5f);
   glColor3f(0, 0, 1);
   glVertex3f(0.0f, 0.9f, 0.0f);
   glColor3f(1, 1, 0);
   glVertex3f(-0.8f, 0.7f, 0.2f);
   glColor3f(0, 1, 1);
   glVertex3f(0.7f, 0.8f, 0.2f);
   glColor3f(1, 0, 1);
   glVertex3f(0.0f, -0.9f, -0.2f);
   glEnd();
   glDisable(GL_DEPTH_TEST);
}

/* What glReadPixels gives, top row first, appended to path as a PPM. */
static void append_read_pixels(const char *path, int w, int h)
{
   unsigned char *px = malloc((size_t)w * (size_t)h * 3);
   CHECK(px);
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, px);
   FILE *f = fopen(path, "ab");
   CHECK(f);
   fprintf(f, "P6\n%d %d\n255\n", w, h);
   for (int y = h - 1; y >= 0; y--)
      fwrite(px + (size_t)y * (size_t)w * 3, 1, (size_t)w * 3, f);
   CHECK(fclose(f) == 0);
   free(px);
}

struct attribs_case {
   int attribs[9];
   int error;          /* 0: a context; GLX errors as 1000 + n */
   int minor;
};

#define MAJ GLX_CONTEXT_MAJOR_VERSION_ARB
#define MIN GLX_CONTEXT_MINOR_VERSION_ARB
#define FLAGS GLX_CONTEXT_FLAGS_ARB
#define PROFILE GLX_CONTEXT_PROFILE_MASK_ARB

/* the oracle's answers (Mesa 22.3 on Xvfb): BadMatch 8, BadValue 2,
 * GLXBadFBConfig 1009, GLXBadProfileARB 1013; X_GLXCreateContextAttribsARB 34 */
static const struct attribs_case cases[] = {
   { { None }, 0, 0 },
   { { MAJ, 1, MIN, 5, None }, 0, 0 },
   { { MAJ, 1, MIN, 0, None }, 0, 0 },
   { { MAJ, 1, MIN, 1, PROFILE, GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None }, 0, 0 },
   { { PROFILE, GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB, None }, 0, 0 },
   { { FLAGS, GLX_CONTEXT_DEBUG_BIT_ARB, None }, 0, 0 },
   { { GLX_RENDER_TYPE, GLX_RGBA_TYPE, None }, 0, 0 },
   { { MAJ, 9, MIN, 9, None }, 1009, 0 },
   { { MAJ, 5, MIN, 0, None }, 1009, 0 },
   { { MAJ, 4, MIN, 7, None }, 1009, 0 },
   { { MAJ, 1, MIN, 9, None }, 8, 34 },
   { { MAJ, 2, MIN, 2, None }, 8, 34 },
   { { MAJ, 3, MIN, 4, None }, 8, 34 },
   { { MAJ, 0, None }, 8, 34 },
   { { MAJ, 2, MIN, 1, FLAGS, GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB, None }, 8, 34 },
   { { 0x1234, 1, None }, 2, 34 },
   { { PROFILE, 0x10, None }, 1013, 34 },
   { { FLAGS, 0x100, None }, 2, 34 },
   { { GLX_RENDER_TYPE, GLX_COLOR_INDEX_TYPE, None }, 2, 34 },
   { { 0x1234, 1, PROFILE, 0x10, None }, 1013, 34 },
   { { PROFILE, 0x10, FLAGS, 0x100, None }, 2, 34 },
   { { MAJ, 1, MIN, 9, FLAGS, 0x100, None }, 8, 34 },
   { { MAJ, 9, MIN, 9, GLX_RENDER_TYPE, GLX_COLOR_INDEX_TYPE, None }, 8, 34 },
};

/* versions Mesa's llvmpipe has and fixgl (GL 1.5) has not */
static const int above_15[][6] = {
   { MAJ, 2, MIN, 1, None },
   { MAJ, 3, MIN, 3, None },
   { MAJ, 3, MIN, 2, PROFILE, GLX_CONTEXT_CORE_PROFILE_BIT_ARB },
};

int main(int argc, char **argv)
{
   struct frames_opts opts;
   frames_parse(argc, argv, &opts, 2);
   Display *dpy = XOpenDisplay(NULL);
   CHECK(dpy);
   const int screen = DefaultScreen(dpy);
   int event_base = 0;
   CHECK(glXQueryExtension(dpy, &glx_error_base, &event_base));
   const char *ext = glXQueryExtensionsString(dpy, screen);
   CHECK(strstr(ext, "GLX_ARB_create_context "));
   CHECK(strstr(ext, "GLX_ARB_create_context_profile"));
   PFNGLXCREATECONTEXTATTRIBSARBPROC create_attribs = (PFNGLXCREATECONTEXTATTRIBSARBPROC)
      glXGetProcAddressARB((const GLubyte *)"glXCreateContextAttribsARB");
   CHECK(create_attribs);
   XSetErrorHandler(on_error);

   static const int fb_attribs[] = {
      GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT | GLX_PBUFFER_BIT, GLX_RENDER_TYPE, GLX_RGBA_BIT,
      GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_DEPTH_SIZE, 16,
      GLX_DOUBLEBUFFER, True, None,
   };
   int n = 0;
   GLXFBConfig *configs = glXChooseFBConfig(dpy, screen, fb_attribs, &n);
   CHECK(configs && n > 0);
   GLXFBConfig db_config = configs[0];
   int value = 0;
   CHECK(glXGetFBConfigAttrib(dpy, db_config, GLX_DRAWABLE_TYPE, &value) == Success);
   CHECK(value & GLX_PBUFFER_BIT);
   CHECK(glXGetFBConfigAttrib(dpy, db_config, GLX_MAX_PBUFFER_WIDTH, &value) == Success && value == 4096);
   CHECK(glXGetFBConfigAttrib(dpy, db_config, GLX_MAX_PBUFFER_HEIGHT, &value) == Success && value == 4096);

   /* the attribute lists */
   for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
      errors = 0;
      GLXContext c = create_attribs(dpy, db_config, NULL, True, cases[i].attribs);
      XSync(dpy, False);
      if (cases[i].error == 0) {
         if (!c || errors) {
            fprintf(stderr, "glxattribs: case %zu: no context (error %d)\n", i, errors ? last_error : 0);
            return 1;
         }
         glXDestroyContext(dpy, c);
      } else {
         CHECK(!c);
         char what[32];
         snprintf(what, sizeof(what), "case %zu", i);
         expect_error(dpy, cases[i].error, cases[i].minor, what);
      }
   }
   errors = 0;
   CHECK(!create_attribs(dpy, NULL, NULL, True, cases[0].attribs));
   expect_error(dpy, 1009, 34, "no config");

   /* a window drawn by a context of glXCreateContextAttribsARB */
   static const int gl15[] = {
      MAJ, 1, MIN, 5, PROFILE, GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB,
      FLAGS, GLX_CONTEXT_DEBUG_BIT_ARB, None,
   };
   GLXContext ctx = create_attribs(dpy, db_config, NULL, True, gl15);
   CHECK(ctx);
   XVisualInfo *vi = glXGetVisualFromFBConfig(dpy, db_config);
   CHECK(vi);
   XSetWindowAttributes swa = {
      .colormap = XCreateColormap(dpy, RootWindow(dpy, screen), vi->visual, AllocNone),
      .border_pixel = 0,
      .event_mask = StructureNotifyMask,
   };
   const int w = 160, h = 120;
   Window win = XCreateWindow(dpy, RootWindow(dpy, screen), 0, 0, (unsigned)w, (unsigned)h, 0,
                              vi->depth, InputOutput, vi->visual,
                              CWColormap | CWBorderPixel | CWEventMask, &swa);
   XMapWindow(dpy, win);
   for (XEvent ev;;) {
      XNextEvent(dpy, &ev);
      if (ev.type == MapNotify)
         break;
   }
   CHECK(glXMakeContextCurrent(dpy, win, win, ctx));
   const char *renderer = (const char *)glGetString(GL_RENDERER);
   CHECK(renderer);
   const int fixgl = strstr(renderer, "fixgl") != NULL;

   /* versions above 1.5: Mesa's contexts, fixgl's GLXBadFBConfig */
   for (size_t i = 0; i < sizeof(above_15) / sizeof(above_15[0]); i++) {
      int attribs[7];
      memcpy(attribs, above_15[i], sizeof(above_15[i]));
      attribs[6] = None;
      errors = 0;
      GLXContext c = create_attribs(dpy, db_config, NULL, True, attribs);
      XSync(dpy, False);
      if (fixgl) {
         CHECK(!c);
         expect_error(dpy, 1009, 0, "a version above 1.5 on fixgl");
      } else {
         CHECK(c && !errors);
         glXDestroyContext(dpy, c);
      }
   }

   for (int f = 0; f < opts.frames; f++) {
      scene(w, h, 10.0f * (float)f);
      glXSwapBuffers(dpy, win);
   }
   glFinish();
   print_renderer();
   write_drawable_ppm(dpy, win, vi->visual, opts.out, 0);

   /* pbuffers: double-buffered (the window's config), then single */
   /* (with the window bit: the oracle's first pbuffer-only configs are
    * 10-bit ones, which fixgl has not) */
   static const int sb_attribs[] = {
      GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT | GLX_PBUFFER_BIT, GLX_RENDER_TYPE, GLX_RGBA_BIT,
      GLX_DEPTH_SIZE, 16, GLX_DOUBLEBUFFER, False, None,
   };
   int nsb = 0;
   GLXFBConfig *sb = glXChooseFBConfig(dpy, screen, sb_attribs, &nsb);
   CHECK(sb && nsb > 0);
   GLXFBConfig pb_configs[2] = { db_config, sb[0] };
   for (int k = 0; k < 2; k++) {
      const int pw = k ? 48 : 64, ph = k ? 72 : 40;
      const int pattribs[] = { GLX_PBUFFER_WIDTH, pw, GLX_PBUFFER_HEIGHT, ph,
                               GLX_PRESERVED_CONTENTS, k ? False : True, None };
      errors = 0;
      GLXPbuffer pb = glXCreatePbuffer(dpy, pb_configs[k], pattribs);
      expect_no_error(dpy, "glXCreatePbuffer");
      CHECK(pb != None);
      unsigned q = 777;
      glXQueryDrawable(dpy, pb, GLX_WIDTH, &q);
      CHECK(q == (unsigned)pw);
      glXQueryDrawable(dpy, pb, GLX_HEIGHT, &q);
      CHECK(q == (unsigned)ph);
      /* (asked False for the second: the oracle reports True) */
      glXQueryDrawable(dpy, pb, GLX_PRESERVED_CONTENTS, &q);
      CHECK(q == 1);
      glXQueryDrawable(dpy, pb, GLX_LARGEST_PBUFFER, &q);
      CHECK(q == 0);
      int id = 0;
      CHECK(glXGetFBConfigAttrib(dpy, pb_configs[k], GLX_FBCONFIG_ID, &id) == Success);
      glXQueryDrawable(dpy, pb, GLX_FBCONFIG_ID, &q);
      CHECK(q == (unsigned)id);
      q = 777;
      glXQueryDrawable(dpy, pb, 0x1234, &q);
      CHECK(q == 0);
      expect_no_error(dpy, "glXQueryDrawable");

      GLXContext pctx = glXCreateNewContext(dpy, pb_configs[k], GLX_RGBA_TYPE, ctx, True);
      CHECK(pctx);
      CHECK(glXMakeContextCurrent(dpy, pb, pb, pctx));
      GLint iv[4];
      glGetIntegerv(GL_DOUBLEBUFFER, iv);
      CHECK(iv[0] == (k ? GL_FALSE : GL_TRUE));
      glGetIntegerv(GL_DRAW_BUFFER, iv);
      CHECK(iv[0] == (k ? GL_FRONT : GL_BACK));
      glGetIntegerv(GL_VIEWPORT, iv);
      CHECK(iv[0] == 0 && iv[1] == 0 && iv[2] == pw && iv[3] == ph);
      scene(pw, ph, 25.0f + 40.0f * (float)k);
      append_read_pixels(opts.out, pw, ph);
      CHECK(glXMakeContextCurrent(dpy, None, None, NULL));
      glXDestroyContext(dpy, pctx);
      glXDestroyPbuffer(dpy, pb);
      expect_no_error(dpy, "glXDestroyPbuffer");
      q = 777;
      glXQueryDrawable(dpy, pb, GLX_WIDTH, &q);
      expect_error(dpy, 1002, 29, "a query of a destroyed pbuffer");
      CHECK(q == 777);
   }
   unsigned q = 777;
   glXQueryDrawable(dpy, None, GLX_WIDTH, &q);
   expect_error(dpy, 1002, 29, "a query of None");
   CHECK(q == 777);
   static const int p16[] = { GLX_PBUFFER_WIDTH, 16, GLX_PBUFFER_HEIGHT, 16, None };
   CHECK(glXCreatePbuffer(dpy, NULL, p16) == None);
   expect_error(dpy, 1009, 27, "a pbuffer without a config");

   glXDestroyContext(dpy, ctx);
   XFree(sb);
   XFree(vi);
   XFree(configs);
   XDestroyWindow(dpy, win);
   XCloseDisplay(dpy);
   return 0;
}
