/*
 * GLX 1.4 over Xlib for libGL.so.1: a thin front end over fixgl's
 * contexts, as libfixgl/osmesa/osmesa.c is for OSMesa.
 *
 * The model is Mesa's client-side ("fake") GLX of its xlib frontends
 * (gallium/frontends/glx/xlib/glx_api.c) and the drawable handling of its
 * DRI software path (glx/drisw_glx.c): nothing is asked of the server's
 * GLX extension but its configs and, as the oracle sends them,
 * X_GLXCreateWindow/X_GLXDestroyWindow (a GLXWindow is an XID of its
 * own, mapped to its X window: glx_drawable.xdraw).  Every context renders with fixgl into a framebuffer per
 * drawable (colour, depth/stencil, accumulation) in fixgl's own memory;
 * glXSwapBuffers (a double-buffered config) or glFlush/glFinish (a
 * single-buffered one, and GLX pixmaps) present the colour buffer with
 * XPutImage, through MIT-SHM's XShmPutImage where the server has it.  The
 * drawable's size is asked of the server (XGetGeometry) at
 * glXMakeCurrent and after every glXSwapBuffers, and the buffers follow
 * it.
 *
 * Configs (GLXFBConfig, and the visuals of glXChooseVisual): the
 * server's own list (X_GLXGetFBConfigs), as the oracle's libGL (Mesa's
 * DRI GLX on Xvfb: drisw) takes it, less the configs fixgl cannot
 * render (multisampled, floating-point, 10-10-10 and 5-6-5 colour, no
 * 8-8-8 TrueColor/DirectColor visual): same IDs, visuals, attributes and
 * order.  Xvfb's GLX makes a visual for each config it offers on a
 * window, so a visual is one config's (glXGetConfig and glXCreateContext
 * of a visual use that config).  A server without GLX gets fixgl's own
 * list: the screen's default visual when it is 8-8-8 TrueColor (no
 * alpha) and the first 32-bit 8-8-8-8 TrueColor visual (alpha), each
 * single- and double-buffered, with depth/stencil 0/0, 16/0, 24/0, 24/8
 * or 32/0 (the oracle's Z16, Z24X8, Z24S8 and Z32_UNORM; its "larger
 * depth first" order makes GLX_DEPTH_SIZE 1 or 16 pick the 32-bit ones)
 * and accumulation 0 or 16 bits; there a visual stands for the config it
 * was last handed out for (glXChooseVisual, glXGetVisualFromFBConfig),
 * else its double-buffered config with 24 depth and 8 stencil bits.
 * glXChooseFBConfig and glXChooseVisual match and order them as Mesa's
 * glxcmds.c does (fbconfigs_compatible, fbconfig_compare, a stable sort
 * as glibc's qsort is), so a program asking the same of both gets the
 * same config.
 *
 * The per-display state (configs, drawables) hangs on the Display (its
 * extension data, freed by XCloseDisplay's close hook), the current GLX
 * context is thread-local: no other mutable state.
 *
 * Pbuffers (glXCreatePbuffer) are drawables of fixgl's memory alone: an
 * XID of the client's (XAllocID, as Mesa's client-side pbuffers), the
 * size asked for, nothing presented.  GLX_ARB_create_context
 * (glXCreateContextAttribsARB) checks its attributes in the oracle's
 * order and with its X errors (create_attribs_error), and refuses every
 * version above 1.5 as the oracle refuses a version it lacks.  GLX errors
 * are raised as X errors the client's handler sees (glx_error), with the
 * server's GLX codes when it has the extension.
 *
 * A double-buffered window has a separate front buffer (fb->Other,
 * main/buffers.c): black at first, drawn into under glDrawBuffer(GL_FRONT)
 * and shown by glFlush/glFinish when drawn into, left as it is by
 * glXSwapBuffers, which shows the back buffer, as the oracle's drisw.
 *
 * Not done, on purpose or not yet: separate read drawables (reads come
 * from the draw drawable); GL_FRONT_AND_BACK and GL_LEFT draw into the
 * back buffer only (into both on the oracle).
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/Xlibint.h>   /* XESetCloseDisplay */
#include <X11/extensions/XShm.h>
#include <GL/glxproto.h>   /* X_GLXGetFBConfigs */
#include <sys/ipc.h>
#include <sys/shm.h>

#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "context.h"
#include "main/groups.h"
#include "fgl_alloc.h"

#define GLXAPI __attribute__((visibility("default")))

#define GLX_MAX_SIZE 16384

static const char glx_extensions[] =
   "GLX_ARB_create_context GLX_ARB_create_context_profile "
   "GLX_ARB_get_proc_address GLX_EXT_swap_control GLX_MESA_swap_control "
   "GLX_SGI_swap_control";

/* GLX protocol: error numbers past the extension's error base, and the
 * minor opcodes the oracle names in its errors (glxproto.h) */
#define GLX_ERR_BAD_DRAWABLE     2    /* GLXBadDrawable */
#define GLX_ERR_BAD_FBCONFIG     9    /* GLXBadFBConfig */
#define GLX_ERR_BAD_PROFILE     13    /* GLXBadProfileARB */
#define GLX_OP_CREATE_PBUFFER   27    /* X_GLXCreatePbuffer */
#define GLX_OP_GET_DRAWABLE_ATTRIBUTES 29
#define GLX_OP_CREATE_CONTEXT_ATTRIBS  34  /* X_GLXCreateContextAttribsARB */

/* The largest pbuffer the configs report (GLX_MAX_PBUFFER_WIDTH/HEIGHT,
 * the oracle's values; GLX_MAX_PBUFFER_PIXELS is 0 there) */
#define GLX_MAX_PBUFFER 4096

/* ---- configs --------------------------------------------------------- */

struct __GLXFBConfigRec {
   int id;                 /* GLX_FBCONFIG_ID */
   int screen;
   VisualID visualid;      /* 0: no visual (pbuffers only) */
   int visual_depth;       /* 24 or 32 */
   int alpha;              /* 0 or 8 */
   bool db;
   int depth, stencil, accum;
   /* as the server reports them (GLX_X_VISUAL_TYPE, GLX_CONFIG_CAVEAT,
    * GLX_BUFFER_SIZE, GLX_DRAWABLE_TYPE, GLX_X_RENDERABLE,
    * GLX_VISUAL_SELECT_GROUP_SGIX, GLX_MAX_PBUFFER_*) */
   int visual_type, caveat, buffer_size, drawable_type, x_renderable, select_group;
   int max_pb_width, max_pb_height, max_pb_pixels;
};

/* The depth/stencil pairs of every visual, in fixgl's formats. */
static const int zs_pairs[][2] = { { 0, 0 }, { 16, 0 }, { 24, 0 }, { 24, 8 }, { 32, 0 } };

/* ---- drawables -------------------------------------------------------- */

struct glx_display;

struct glx_drawable {
   struct fgl_framebuffer fb;   /* first: FlushFront gets &fb */
   struct glx_display *disp;
   XID xid;                     /* the GLX drawable's ID */
   Drawable xdraw;              /* the X drawable shown into: xid, or a
                                 * GLXWindow's X window */
   bool pixmap;
   bool pbuffer;                /* no X drawable: sized by its creator */
   int pb_width, pb_height;     /* a pbuffer's size as asked for */
   bool pb_largest;
   bool has_buffer;
   /* a plain X window made current (not glXCreateWindow's): its buffers
    * go when no context is bound to it any more (release_drawable) */
   bool implicit;
   struct __GLXFBConfigRec cfg; /* the buffers' formats */
   void *depth_mem;
   /* presentation */
   GC gc;
   XImage *img;
   bool shm;                    /* img is an MIT-SHM image, attached */
   XShmSegmentInfo shminfo;
   int swap_interval;
   struct glx_drawable *next;
};

/* A visual handed out for a config (glXChooseVisual,
 * glXGetVisualFromFBConfig): glXGetConfig/glXCreateContext of it use it. */
struct glx_visual_choice {
   VisualID visualid;
   int config;                  /* index into configs */
   struct glx_visual_choice *next;
};

struct glx_display {
   Display *dpy;
   pthread_mutex_t lock;
   int nconfigs;
   struct __GLXFBConfigRec *configs;
   struct glx_drawable *drawables;
   struct glx_visual_choice *choices;
   struct __GLXcontextRec *contexts;   /* every context made for dpy */
   int has_shm;                 /* -1 not asked yet, 0, 1 */
   bool from_server;            /* configs: the server's GLX list */
   /* the server's GLX extension (its errors carry these codes), or 0 */
   int glx_opcode, glx_error_base, glx_event_base;
};

struct __GLXcontextRec {
   struct fgl_context *gl;
   struct glx_display *disp;    /* NULL once the display is closed */
   Display *dpy;
   struct __GLXFBConfigRec cfg;
   GLXDrawable draw, read;
   struct glx_drawable *bound;  /* the drawable its GL context draws into */
   struct glx_drawable *read_bound;  /* ... reads from, when another one */
   struct __GLXcontextRec *next;
};

/* The GLX context current on this thread (its GL context is the one
 * fgl_get_current() returns). */
static _Thread_local GLXContext current_glx;

static GLXContext current_context(void)
{
   if (current_glx && fgl_get_current() != current_glx->gl)
      current_glx = NULL;
   return current_glx;
}

/* ---- the per-display state ---------------------------------------------
 * Kept in the Display's extension data list, found by its free_private
 * function; XCloseDisplay calls close_display (registered through
 * XAddExtension's codes) while the connection is still open. */

static void free_drawable(struct glx_drawable *d, bool connected);
static void unbind_contexts(struct glx_display *gd, const struct glx_drawable *d);

static XExtData **display_ext_list(Display *dpy)
{
   XEDataObject obj;
   obj.display = dpy;
   return XEHeadOfExtensionList(obj);
}

static int ext_data_free(XExtData *data)
{
   /* the state itself is freed by close_display */
   data->private_data = NULL;
   return 0;
}

static int close_display(Display *dpy, XExtCodes *codes)
{
   (void)codes;
   XExtData **head = display_ext_list(dpy);
   for (XExtData *e = head ? *head : NULL; e; e = e->next) {
      if (e->free_private != ext_data_free || !e->private_data)
         continue;
      struct glx_display *gd = (struct glx_display *)(void *)e->private_data;
      /* the contexts outlive the display: they draw nowhere from now on */
      unbind_contexts(gd, NULL);
      for (GLXContext c = gd->contexts; c; c = c->next) {
         c->disp = NULL;
         c->dpy = NULL;
      }
      /* (their GCs and MIT-SHM segments go with the connection: no
       * requests, as the oracle makes none here) */
      while (gd->drawables) {
         struct glx_drawable *d = gd->drawables;
         gd->drawables = d->next;
         free_drawable(d, false);
      }
      while (gd->choices) {
         struct glx_visual_choice *c = gd->choices;
         gd->choices = c->next;
         free(c);
      }
      free(gd->configs);
      pthread_mutex_destroy(&gd->lock);
      free(gd);
      e->private_data = NULL;
   }
   return 0;
}

static bool visual_is_888(const XVisualInfo *v)
{
   return (v->class == TrueColor || v->class == DirectColor) && v->red_mask == 0xff0000ul &&
          v->green_mask == 0xff00ul && v->blue_mask == 0xfful && v->bits_per_rgb >= 8 &&
          (v->depth == 24 || v->depth == 32);
}

static bool zs_supported(int depth, int stencil)
{
   for (size_t z = 0; z < sizeof(zs_pairs) / sizeof(zs_pairs[0]); z++)
      if (zs_pairs[z][0] == depth && zs_pairs[z][1] == stencil)
         return true;
   return false;
}

/* One of the server's FBConfigs (its attribute/value pairs) as a config
 * of fixgl's, if fixgl renders it: RGBA of 8 bits a channel, alpha 0 or
 * 8, single-sampled, no aux buffers, mono, level 0, a depth/stencil pair
 * of zs_pairs, accumulation 0 or 16 in every channel, a visual of 8-8-8
 * TrueColor or DirectColor. */
static bool server_config(Display *dpy, int screen, const CARD32 *p, int nattr,
                          struct __GLXFBConfigRec *c)
{
   int r = -1, g = -1, b = -1, render = 0, sb = 0, samples = 0, aux = 0, stereo = 0, level = 0;
   int ar = 0, ag = 0, ab = 0, aa = 0;
   memset(c, 0, sizeof(*c));
   c->screen = screen;
   c->visual_type = GLX_TRUE_COLOR;
   c->caveat = GLX_NONE;
   c->drawable_type = GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT;
   c->x_renderable = True;
   c->max_pb_width = c->max_pb_height = GLX_MAX_PBUFFER;
   c->alpha = -1;
   for (int i = 0; i < nattr; i++) {
      const int v = (int)p[2 * i + 1];
      switch ((int)p[2 * i]) {
      case GLX_FBCONFIG_ID:       c->id = v; break;
      case GLX_VISUAL_ID:         c->visualid = (VisualID)(CARD32)v; break;
      case GLX_X_VISUAL_TYPE:     c->visual_type = v; break;
      case GLX_CONFIG_CAVEAT:     c->caveat = v; break;
      case GLX_RGBA:              if (v) render |= GLX_RGBA_BIT; break;
      case GLX_RENDER_TYPE:       render = v; break;
      case GLX_BUFFER_SIZE:       c->buffer_size = v; break;
      case GLX_LEVEL:             level = v; break;
      case GLX_DOUBLEBUFFER:      c->db = v != 0; break;
      case GLX_STEREO:            stereo = v; break;
      case GLX_AUX_BUFFERS:       aux = v; break;
      case GLX_RED_SIZE:          r = v; break;
      case GLX_GREEN_SIZE:        g = v; break;
      case GLX_BLUE_SIZE:         b = v; break;
      case GLX_ALPHA_SIZE:        c->alpha = v; break;
      case GLX_DEPTH_SIZE:        c->depth = v; break;
      case GLX_STENCIL_SIZE:      c->stencil = v; break;
      case GLX_ACCUM_RED_SIZE:    ar = v; break;
      case GLX_ACCUM_GREEN_SIZE:  ag = v; break;
      case GLX_ACCUM_BLUE_SIZE:   ab = v; break;
      case GLX_ACCUM_ALPHA_SIZE:  aa = v; break;
      case GLX_SAMPLE_BUFFERS:    sb = v; break;
      case GLX_SAMPLES:           samples = v; break;
      case GLX_DRAWABLE_TYPE:     c->drawable_type = v; break;
      case GLX_X_RENDERABLE:      c->x_renderable = v; break;
      case GLX_VISUAL_SELECT_GROUP_SGIX: c->select_group = v; break;
      case GLX_MAX_PBUFFER_WIDTH:  c->max_pb_width = v; break;
      case GLX_MAX_PBUFFER_HEIGHT: c->max_pb_height = v; break;
      case GLX_MAX_PBUFFER_PIXELS: c->max_pb_pixels = v; break;
      default: break;
      }
   }
   c->accum = ar;
   /* the server (Xvfb) reports 0: the oracle's client has its driver's
    * limit */
   if (c->max_pb_width <= 0)
      c->max_pb_width = GLX_MAX_PBUFFER;
   if (c->max_pb_height <= 0)
      c->max_pb_height = GLX_MAX_PBUFFER;
   if (render != GLX_RGBA_BIT || r != 8 || g != 8 || b != 8 || (c->alpha != 0 && c->alpha != 8) ||
       sb || samples || aux || stereo || level || !zs_supported(c->depth, c->stencil) ||
       ag != ar || ab != ar || aa != ar || (ar != 0 && ar != 16) || !c->visualid)
      return false;
   XVisualInfo tmpl = { .visualid = c->visualid, .screen = screen };
   int n = 0;
   XVisualInfo *vi = XGetVisualInfo(dpy, VisualIDMask | VisualScreenMask, &tmpl, &n);
   const bool ok = vi && n == 1 && visual_is_888(vi);
   if (ok)
      c->visual_depth = vi->depth;
   if (vi)
      XFree(vi);
   return ok;
}

/* The configs of one screen as the server's GLX lists them
 * (X_GLXGetFBConfigs), those fixgl renders, in the server's order: the
 * oracle's libGL (Mesa's DRI GLX) takes its configs and visuals from
 * the same list.  -1 when the server has no GLX or does not answer. */
static int server_configs(struct glx_display *gd, int screen)
{
   Display *dpy = gd->dpy;
   xGLXGetFBConfigsReply reply;
   LockDisplay(dpy);
   xGLXGetFBConfigsReq *req = (xGLXGetFBConfigsReq *)_XGetRequest(dpy, 0, sz_xGLXGetFBConfigsReq);
   req->reqType = (CARD8)gd->glx_opcode;
   req->glxCode = X_GLXGetFBConfigs;
   req->screen = (CARD32)screen;
   if (!_XReply(dpy, (xReply *)&reply, 0, False)) {
      UnlockDisplay(dpy);
      SyncHandle();
      return -1;
   }
   const size_t words = (size_t)reply.length;
   const int nconf = (int)reply.numFBConfigs, nattr = (int)reply.numAttribs;
   CARD32 *data = words ? malloc(words * 4u) : NULL;
   if (words && !data) {
      _XEatDataWords(dpy, reply.length);
      UnlockDisplay(dpy);
      SyncHandle();
      return -1;
   }
   if (words)
      _XRead(dpy, (char *)data, (long)(words * 4u));
   UnlockDisplay(dpy);
   SyncHandle();
   if (nconf < 0 || nattr < 0 || (size_t)nconf * (size_t)nattr * 2u > words) {
      free(data);
      return -1;
   }
   struct __GLXFBConfigRec *grown =
      realloc(gd->configs, (size_t)(gd->nconfigs + nconf + 1) * sizeof(*gd->configs));
   if (!grown) {
      free(data);
      return -1;
   }
   gd->configs = grown;
   int kept = 0;
   for (int i = 0; i < nconf; i++) {
      struct __GLXFBConfigRec c;
      if (server_config(dpy, screen, data + (size_t)i * (size_t)nattr * 2u, nattr, &c)) {
         gd->configs[gd->nconfigs++] = c;
         kept++;
      }
   }
   free(data);
   return kept;
}

/* The configs of every screen: the default visual (if 8-8-8 TrueColor of
 * depth 24) and the first 8-8-8 TrueColor visual of depth 32. */
static bool build_configs(struct glx_display *gd)
{
   const int nscreens = ScreenCount(gd->dpy);
   if (gd->glx_opcode) {
      gd->from_server = true;
      for (int s = 0; s < nscreens; s++)
         if (server_configs(gd, s) < 0) {
            gd->from_server = false;
            break;
         }
      if (gd->from_server)
         return true;
      free(gd->configs);
      gd->configs = NULL;
      gd->nconfigs = 0;
   }
   const int per_visual = 2 * (int)(sizeof(zs_pairs) / sizeof(zs_pairs[0])) * 2;
   gd->configs = calloc((size_t)nscreens * 2u * (size_t)per_visual, sizeof(*gd->configs));
   if (!gd->configs)
      return false;
   for (int s = 0; s < nscreens; s++) {
      VisualID vids[2] = { 0, 0 };
      int depths[2] = { 0, 0 };
      XVisualInfo tmpl = { .screen = s };
      int n = 0;
      XVisualInfo *vis = XGetVisualInfo(gd->dpy, VisualScreenMask, &tmpl, &n);
      const VisualID def = XVisualIDFromVisual(DefaultVisual(gd->dpy, s));
      for (int i = 0; i < n; i++) {
         if (!visual_is_888(&vis[i]) || vis[i].class != TrueColor)
            continue;
         if (vis[i].visualid == def && vis[i].depth == 24) {
            vids[0] = vis[i].visualid;
            depths[0] = 24;
         } else if (vis[i].depth == 32 && !vids[1]) {
            vids[1] = vis[i].visualid;
            depths[1] = 32;
         }
      }
      if (vis)
         XFree(vis);
      for (int v = 0; v < 2; v++) {
         if (!vids[v])
            continue;
         for (int db = 1; db >= 0; db--)
            for (size_t z = 0; z < sizeof(zs_pairs) / sizeof(zs_pairs[0]); z++)
               for (int accum = 0; accum <= 16; accum += 16) {
                  struct __GLXFBConfigRec *c = &gd->configs[gd->nconfigs];
                  c->id = gd->nconfigs + 1;
                  c->screen = s;
                  c->visualid = vids[v];
                  c->visual_depth = depths[v];
                  c->alpha = depths[v] == 32 ? 8 : 0;
                  c->db = db != 0;
                  c->depth = zs_pairs[z][0];
                  c->stencil = zs_pairs[z][1];
                  c->accum = accum;
                  c->visual_type = GLX_TRUE_COLOR;
                  c->caveat = accum ? GLX_SLOW_CONFIG : GLX_NONE;
                  c->buffer_size = 24 + c->alpha;
                  c->drawable_type = GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT;
                  c->x_renderable = True;
                  c->max_pb_width = c->max_pb_height = GLX_MAX_PBUFFER;
                  gd->nconfigs++;
               }
      }
   }
   return true;
}

static struct glx_display *find_display(Display *dpy)
{
   XExtData **head = display_ext_list(dpy);
   for (XExtData *e = head ? *head : NULL; e; e = e->next)
      if (e->free_private == ext_data_free && e->private_data)
         return (struct glx_display *)(void *)e->private_data;
   return NULL;
}

static struct glx_display *get_display(Display *dpy)
{
   if (!dpy)
      return NULL;
   XLockDisplay(dpy);
   struct glx_display *gd = find_display(dpy);
   if (gd) {
      XUnlockDisplay(dpy);
      return gd;
   }
   gd = calloc(1, sizeof(*gd));
   XExtData *e = calloc(1, sizeof(*e));
   if (gd)
      gd->dpy = dpy;
   XExtCodes *codes = gd && e ? XAddExtension(dpy) : NULL;
   if (gd && !XQueryExtension(dpy, "GLX", &gd->glx_opcode, &gd->glx_event_base, &gd->glx_error_base))
      gd->glx_opcode = gd->glx_event_base = gd->glx_error_base = 0;
   if (!codes || !build_configs(gd)) {
      free(gd ? gd->configs : NULL);
      free(gd);
      free(e);
      XUnlockDisplay(dpy);
      return NULL;
   }
   gd->has_shm = -1;
   pthread_mutex_init(&gd->lock, NULL);
   e->number = codes->extension;
   e->free_private = ext_data_free;
   e->private_data = (XPointer)gd;
   XAddToExtensionList(display_ext_list(dpy), e);
   XESetCloseDisplay(dpy, codes->extension, close_display);
   XUnlockDisplay(dpy);
   return gd;
}

/* An X error for the client's error handler, as the oracle's
 * __glXSendError raises them: a GLX error (past the server's GLX error
 * base) or a core one (BadMatch, BadValue), with the GLX opcode and the
 * request's minor opcode. */
static void glx_error(Display *dpy, bool glx, int code, int minor, XID resource)
{
   struct glx_display *gd = find_display(dpy);
   xError err;
   memset(&err, 0, sizeof(err));
   LockDisplay(dpy);
   err.errorCode = (CARD8)(glx ? (gd ? gd->glx_error_base : 0) + code : code);
   err.sequenceNumber = (CARD16)dpy->request;
   err.resourceID = (CARD32)resource;
   err.minorCode = (CARD16)minor;
   err.majorCode = (CARD8)(gd ? gd->glx_opcode : 0);
   _XError(dpy, &err);
   UnlockDisplay(dpy);
}

/* ---- choosing configs --------------------------------------------------- */

#define DONT_CARE ((int)GLX_DONT_CARE)   /* -1, as an attribute list holds it */

/* What glXChooseFBConfig / glXChooseVisual asked for. */
struct glx_request {
   int rgba;               /* render type: needs GLX_RGBA_BIT */
   int db, stereo, level;  /* exact, DONT_CARE for db */
   int buffer_size, red, green, blue, alpha, depth, stencil;
   int accum_r, accum_g, accum_b, accum_a, aux, sample_buffers, samples;
   int drawable_type, x_renderable, visual_type, caveat, fbconfig_id, transparent;
};

static void request_defaults(struct glx_request *r, bool fbconfig)
{
   memset(r, 0, sizeof(*r));
   r->rgba = 1;
   r->db = fbconfig ? DONT_CARE : 0;
   r->drawable_type = GLX_WINDOW_BIT;
   r->x_renderable = DONT_CARE;
   r->visual_type = DONT_CARE;
   r->caveat = DONT_CARE;
   r->fbconfig_id = DONT_CARE;
   r->transparent = GLX_NONE;
}

/* One attribute and its value; false for an unknown attribute. */
static bool request_set(struct glx_request *r, int attr, int value)
{
   switch (attr) {
   case GLX_BUFFER_SIZE:       r->buffer_size = value; return true;
   case GLX_LEVEL:             r->level = value; return true;
   case GLX_DOUBLEBUFFER:      r->db = value; return true;
   case GLX_STEREO:            r->stereo = value; return true;
   case GLX_AUX_BUFFERS:       r->aux = value; return true;
   case GLX_RED_SIZE:          r->red = value; return true;
   case GLX_GREEN_SIZE:        r->green = value; return true;
   case GLX_BLUE_SIZE:         r->blue = value; return true;
   case GLX_ALPHA_SIZE:        r->alpha = value; return true;
   case GLX_DEPTH_SIZE:        r->depth = value; return true;
   case GLX_STENCIL_SIZE:      r->stencil = value; return true;
   case GLX_ACCUM_RED_SIZE:    r->accum_r = value; return true;
   case GLX_ACCUM_GREEN_SIZE:  r->accum_g = value; return true;
   case GLX_ACCUM_BLUE_SIZE:   r->accum_b = value; return true;
   case GLX_ACCUM_ALPHA_SIZE:  r->accum_a = value; return true;
   case GLX_SAMPLE_BUFFERS:    r->sample_buffers = value; return true;
   case GLX_SAMPLES:           r->samples = value; return true;
   case GLX_RENDER_TYPE:       r->rgba = (value & GLX_RGBA_BIT) != 0; return true;
   case GLX_DRAWABLE_TYPE:     r->drawable_type = value; return true;
   case GLX_X_RENDERABLE:      r->x_renderable = value; return true;
   case GLX_X_VISUAL_TYPE:     r->visual_type = value; return true;
   case GLX_CONFIG_CAVEAT:     r->caveat = value; return true;
   case GLX_FBCONFIG_ID:       r->fbconfig_id = value; return true;
   case GLX_TRANSPARENT_TYPE:  r->transparent = value; return true;
   case GLX_TRANSPARENT_INDEX_VALUE:
   case GLX_TRANSPARENT_RED_VALUE:
   case GLX_TRANSPARENT_GREEN_VALUE:
   case GLX_TRANSPARENT_BLUE_VALUE:
   case GLX_TRANSPARENT_ALPHA_VALUE:
   case GLX_MAX_PBUFFER_WIDTH:
   case GLX_MAX_PBUFFER_HEIGHT:
   case GLX_MAX_PBUFFER_PIXELS:
   case GLX_VISUAL_ID:
      return true;             /* ignored, as GLX says for these */
   default:
      return false;
   }
}

static int config_buffer_size(const struct __GLXFBConfigRec *c)
{
   return c->buffer_size;
}

static int config_caveat(const struct __GLXFBConfigRec *c)
{
   /* Mesa marks its configs with an accumulation buffer slow */
   return c->caveat;
}

#define MIN_OK(req, have) ((req) == DONT_CARE || (req) <= (have))

static bool config_matches(const struct __GLXFBConfigRec *c, const struct glx_request *r)
{
   if (!r->rgba)
      return false;
   if (r->db != DONT_CARE && (r->db != 0) != c->db)
      return false;
   if (r->stereo != DONT_CARE && r->stereo)
      return false;
   if (r->level != DONT_CARE && r->level != 0)
      return false;
   if (r->drawable_type != DONT_CARE && (r->drawable_type & ~c->drawable_type))
      return false;
   if (r->x_renderable != DONT_CARE && r->x_renderable != c->x_renderable)
      return false;
   if (r->visual_type != DONT_CARE && r->visual_type != c->visual_type)
      return false;
   if (r->caveat != DONT_CARE && r->caveat != config_caveat(c))
      return false;
   if (r->fbconfig_id != DONT_CARE && r->fbconfig_id != c->id)
      return false;
   if (r->transparent != DONT_CARE && r->transparent != GLX_NONE)
      return false;
   return MIN_OK(r->buffer_size, config_buffer_size(c)) && MIN_OK(r->red, 8) && MIN_OK(r->green, 8) &&
          MIN_OK(r->blue, 8) && MIN_OK(r->alpha, c->alpha) && MIN_OK(r->depth, c->depth) &&
          MIN_OK(r->stencil, c->stencil) && MIN_OK(r->accum_r, c->accum) &&
          MIN_OK(r->accum_g, c->accum) && MIN_OK(r->accum_b, c->accum) &&
          MIN_OK(r->accum_a, c->accum) && MIN_OK(r->aux, 0) && MIN_OK(r->sample_buffers, 0) &&
          MIN_OK(r->samples, 0);
}

/* Mesa's glxcmds.c:fbconfig_compare: caveat, then colour bits (larger,
 * zero first), buffer size (smaller), single before double buffering,
 * depth (larger, zero first), stencil (smaller), accumulation (larger,
 * zero first). */
static int prefer_larger_or_zero(int a, int b)
{
   if (a == b)
      return 0;
   if (a == 0)
      return -1;
   if (b == 0)
      return 1;
   return b - a;
}

static int config_compare(const struct __GLXFBConfigRec *a, const struct __GLXFBConfigRec *b)
{
   int d;
   if ((d = a->select_group - b->select_group) != 0)
      return d;
   if ((d = config_caveat(a) - config_caveat(b)) != 0)
      return d;
   if ((d = prefer_larger_or_zero(a->alpha, b->alpha)) != 0)
      return d;
   if ((d = config_buffer_size(a) - config_buffer_size(b)) != 0)
      return d;
   if (a->db != b->db)
      return a->db ? 1 : -1;
   if ((d = prefer_larger_or_zero(a->depth, b->depth)) != 0)
      return d;
   if ((d = a->stencil - b->stencil) != 0)
      return d;
   if ((d = prefer_larger_or_zero(a->accum, b->accum)) != 0)
      return d;
   if ((d = a->visual_type - b->visual_type) != 0)
      return d;
   if ((d = b->max_pb_width - a->max_pb_width) != 0)
      return d;
   if ((d = b->max_pb_height - a->max_pb_height) != 0)
      return d;
   if ((d = b->max_pb_pixels - a->max_pb_pixels) != 0)
      return d;
   /* equal for Mesa: glibc's qsort (a merge sort) keeps the list's order */
   return (a > b) - (a < b);
}

static int config_compare_qsort(const void *pa, const void *pb)
{
   return config_compare(*(const GLXFBConfig *)pa, *(const GLXFBConfig *)pb);
}

static void remember_visual(struct glx_display *gd, const struct __GLXFBConfigRec *c)
{
   pthread_mutex_lock(&gd->lock);
   struct glx_visual_choice *ch;
   for (ch = gd->choices; ch; ch = ch->next)
      if (ch->visualid == c->visualid)
         break;
   if (!ch && (ch = calloc(1, sizeof(*ch))) != NULL) {
      ch->visualid = c->visualid;
      ch->next = gd->choices;
      gd->choices = ch;
   }
   if (ch)
      ch->config = (int)(c - gd->configs);
   pthread_mutex_unlock(&gd->lock);
}

/* The config a visual stands for: the one it was handed out for, else
 * its double-buffered config with depth 24 and stencil 8; NULL for a
 * visual fixgl does not render to. */
static const struct __GLXFBConfigRec *config_of_visual(struct glx_display *gd, VisualID vid)
{
   const struct __GLXFBConfigRec *found = NULL;
   pthread_mutex_lock(&gd->lock);
   for (struct glx_visual_choice *ch = gd->choices; ch; ch = ch->next)
      if (ch->visualid == vid)
         found = &gd->configs[ch->config];
   pthread_mutex_unlock(&gd->lock);
   if (found)
      return found;
   /* the server's configs: a visual is one config's */
   for (int i = 0; gd->from_server && i < gd->nconfigs; i++)
      if (gd->configs[i].visualid == vid)
         return &gd->configs[i];
   for (int i = 0; i < gd->nconfigs; i++) {
      const struct __GLXFBConfigRec *c = &gd->configs[i];
      if (c->visualid == vid && c->db && c->depth == 24 && c->stencil == 8 && !c->accum)
         return c;
   }
   return NULL;
}

static XVisualInfo *visual_info(Display *dpy, const struct __GLXFBConfigRec *c)
{
   XVisualInfo tmpl = { .visualid = c->visualid, .screen = c->screen };
   int n = 0;
   return XGetVisualInfo(dpy, VisualIDMask | VisualScreenMask, &tmpl, &n);
}

GLXAPI GLXFBConfig *glXChooseFBConfig(Display *dpy, int screen, const int *attribList, int *nitems)
{
   struct glx_display *gd = get_display(dpy);
   if (nitems)
      *nitems = 0;
   if (!gd)
      return NULL;
   struct glx_request r;
   request_defaults(&r, true);
   for (int i = 0; attribList && attribList[i] != None; i += 2)
      if (!request_set(&r, attribList[i], attribList[i + 1]))
         return NULL;
   GLXFBConfig *list = malloc((size_t)(gd->nconfigs + 1) * sizeof(*list));
   if (!list)
      return NULL;
   int n = 0;
   for (int i = 0; i < gd->nconfigs; i++)
      if (gd->configs[i].screen == screen && config_matches(&gd->configs[i], &r))
         list[n++] = &gd->configs[i];
   if (n == 0) {
      free(list);
      return NULL;
   }
   qsort(list, (size_t)n, sizeof(*list), config_compare_qsort);
   if (nitems)
      *nitems = n;
   return list;
}

GLXAPI GLXFBConfig *glXGetFBConfigs(Display *dpy, int screen, int *nelements)
{
   struct glx_display *gd = get_display(dpy);
   if (nelements)
      *nelements = 0;
   if (!gd)
      return NULL;
   GLXFBConfig *list = malloc((size_t)(gd->nconfigs + 1) * sizeof(*list));
   if (!list)
      return NULL;
   int n = 0;
   for (int i = 0; i < gd->nconfigs; i++)
      if (gd->configs[i].screen == screen)
         list[n++] = &gd->configs[i];
   if (n == 0) {
      free(list);
      return NULL;
   }
   if (nelements)
      *nelements = n;
   return list;
}

/* The value of a config's attribute (glXGetFBConfigAttrib, glXGetConfig). */
static int config_attrib(const struct __GLXFBConfigRec *c, int attr, int *value)
{
   switch (attr) {
   case GLX_USE_GL:                *value = True; break;
   case GLX_RGBA:                  *value = True; break;
   case GLX_FBCONFIG_ID:           *value = c->id; break;
   case GLX_BUFFER_SIZE:           *value = config_buffer_size(c); break;
   case GLX_LEVEL:                 *value = 0; break;
   case GLX_DOUBLEBUFFER:          *value = c->db; break;
   case GLX_STEREO:                *value = False; break;
   case GLX_AUX_BUFFERS:           *value = 0; break;
   case GLX_RED_SIZE:
   case GLX_GREEN_SIZE:
   case GLX_BLUE_SIZE:             *value = 8; break;
   case GLX_ALPHA_SIZE:            *value = c->alpha; break;
   case GLX_DEPTH_SIZE:            *value = c->depth; break;
   case GLX_STENCIL_SIZE:          *value = c->stencil; break;
   case GLX_ACCUM_RED_SIZE:
   case GLX_ACCUM_GREEN_SIZE:
   case GLX_ACCUM_BLUE_SIZE:
   case GLX_ACCUM_ALPHA_SIZE:      *value = c->accum; break;
   case GLX_RENDER_TYPE:           *value = GLX_RGBA_BIT; break;
   case GLX_DRAWABLE_TYPE:         *value = c->drawable_type; break;
   case GLX_MAX_PBUFFER_WIDTH:     *value = c->max_pb_width; break;
   case GLX_MAX_PBUFFER_HEIGHT:    *value = c->max_pb_height; break;
   case GLX_X_RENDERABLE:          *value = c->x_renderable; break;
   case GLX_VISUAL_ID:             *value = (int)c->visualid; break;
   case GLX_X_VISUAL_TYPE:         *value = c->visual_type; break;
   case GLX_CONFIG_CAVEAT:         *value = config_caveat(c); break;
   case GLX_TRANSPARENT_TYPE:      *value = GLX_NONE; break;
   case GLX_TRANSPARENT_INDEX_VALUE:
   case GLX_TRANSPARENT_RED_VALUE:
   case GLX_TRANSPARENT_GREEN_VALUE:
   case GLX_TRANSPARENT_BLUE_VALUE:
   case GLX_TRANSPARENT_ALPHA_VALUE:
   case GLX_SAMPLE_BUFFERS:
   case GLX_SAMPLES:               *value = 0; break;
   case GLX_MAX_PBUFFER_PIXELS:    *value = c->max_pb_pixels; break;
   /* 0 as Xvfb's list reports it, although the oracle's buffers are sRGB
    * (ORACLE-NOTES.md "GLX sRGB buffers") */
   case GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB: *value = 0; break;
   default:
      return GLX_BAD_ATTRIBUTE;
   }
   return Success;
}

GLXAPI int glXGetFBConfigAttrib(Display *dpy, GLXFBConfig config, int attribute, int *value)
{
   (void)dpy;
   if (!config || !value)
      return GLX_BAD_VALUE;
   if (attribute == GLX_USE_GL || attribute == GLX_RGBA)
      return GLX_BAD_ATTRIBUTE;
   return config_attrib(config, attribute, value);
}

GLXAPI XVisualInfo *glXGetVisualFromFBConfig(Display *dpy, GLXFBConfig config)
{
   struct glx_display *gd = get_display(dpy);
   if (!gd || !config)
      return NULL;
   remember_visual(gd, config);
   return visual_info(dpy, config);
}

/* glXChooseVisual's list: booleans without a value (GLX_RGBA,
 * GLX_DOUBLEBUFFER, GLX_STEREO, GLX_USE_GL), the rest with one; the
 * best config by config_compare gives the visual. */
GLXAPI XVisualInfo *glXChooseVisual(Display *dpy, int screen, int *attribList)
{
   struct glx_display *gd = get_display(dpy);
   if (!gd)
      return NULL;
   struct glx_request r;
   /* without GLX_RGBA too: the oracle's chooser leaves the render type
    * free then (0, every config matches) */
   request_defaults(&r, false);
   for (int i = 0; attribList && attribList[i] != None;) {
      switch (attribList[i]) {
      case GLX_USE_GL:       i++; break;
      case GLX_RGBA:         r.rgba = 1; i++; break;
      case GLX_DOUBLEBUFFER: r.db = 1; i++; break;
      case GLX_STEREO:       r.stereo = 1; i++; break;
      default:
         if (!request_set(&r, attribList[i], attribList[i + 1]))
            return NULL;
         i += 2;
         break;
      }
   }
   const struct __GLXFBConfigRec *best = NULL;
   for (int i = 0; i < gd->nconfigs; i++) {
      const struct __GLXFBConfigRec *c = &gd->configs[i];
      if (c->screen == screen && config_matches(c, &r) && (!best || config_compare(c, best) < 0))
         best = c;
   }
   if (!best)
      return NULL;
   remember_visual(gd, best);
   return visual_info(dpy, best);
}

GLXAPI int glXGetConfig(Display *dpy, XVisualInfo *vis, int attrib, int *value)
{
   struct glx_display *gd = get_display(dpy);
   if (!gd || !vis || !value)
      return GLX_NO_EXTENSION;
   const struct __GLXFBConfigRec *c = config_of_visual(gd, vis->visualid);
   if (!c) {
      if (attrib == GLX_USE_GL) {
         *value = False;
         return Success;
      }
      return GLX_BAD_VISUAL;
   }
   if (attrib == GLX_FBCONFIG_ID || attrib == GLX_DRAWABLE_TYPE || attrib == GLX_RENDER_TYPE ||
       attrib == GLX_X_RENDERABLE || attrib == GLX_MAX_PBUFFER_WIDTH ||
       attrib == GLX_MAX_PBUFFER_HEIGHT || attrib == GLX_MAX_PBUFFER_PIXELS)
      return GLX_BAD_ATTRIBUTE;
   return config_attrib(c, attrib, value);
}

/* ---- buffers of a drawable ---------------------------------------------- */

static void destroy_image(struct glx_drawable *d, bool connected)
{
   if (!d->img)
      return;
   if (d->shm) {
      if (connected)
         XShmDetach(d->disp->dpy, &d->shminfo);
      d->img->data = NULL;
      shmdt(d->shminfo.shmaddr);
      d->shm = false;
   }
   XDestroyImage(d->img);
   d->img = NULL;
}

static void free_buffers(struct glx_drawable *d)
{
   fgl_lazy_fini(&d->fb);
   fgl_free(d->fb.Color);
   fgl_free(d->fb.Other);
   fgl_free(d->depth_mem);
   fgl_free(d->fb.Stencil);
   fgl_free(d->fb.Accum);
   d->depth_mem = NULL;
   d->fb.Color = NULL;
   d->fb.Other = NULL;
   d->fb.Depth = NULL;
   d->fb.Stencil = NULL;
   d->fb.Accum = NULL;
   d->has_buffer = false;
}

static void free_drawable(struct glx_drawable *d, bool connected)
{
   destroy_image(d, connected);
   if (d->gc && connected)
      XFreeGC(d->disp->dpy, d->gc);
   free_buffers(d);
   fgl_free(d);
}

static void present(struct glx_drawable *d, const uint8_t *color);

/* glFlush/glFinish of a single-buffered drawable: the image to the X
 * drawable, when a draw or clear defined it since the last time. */
static void flush_front(struct fgl_framebuffer *fb)
{
   if (!fb->ColorDefined)
      return;
   fb->ColorDefined = false;
   present((struct glx_drawable *)(void *)fb, fb->Color);
}

/* glFlush/glFinish of a double-buffered window: its front buffer to the
 * X window when it was drawn into since the last time (the oracle's
 * front renderbuffer's "defined", st_manager_flush_frontbuffer); the
 * back buffer is glXSwapBuffers's. */
static void flush_front_db(struct fgl_framebuffer *fb)
{
   bool *defined = fb->FrontIsColor ? &fb->ColorDefined : &fb->OtherDefined;
   if (!*defined)
      return;
   *defined = false;
   present((struct glx_drawable *)(void *)fb, fb->FrontIsColor ? fb->Color : fb->Other);
}

static enum r_zs_format zs_format(const struct __GLXFBConfigRec *c)
{
   if (c->depth == 24)
      return c->stencil ? R_ZS_Z24S8 : R_ZS_Z24X8;
   if (c->depth == 32)
      return R_ZS_Z32;
   return c->depth == 16 ? R_ZS_Z16 : R_ZS_NONE;
}

/* (Re)allocates the buffers for width x height. */
static bool alloc_buffers(struct glx_drawable *d, int width, int height)
{
   const size_t n = (size_t)width * (size_t)height;
   free_buffers(d);
   struct fgl_framebuffer *fb = &d->fb;
   fb->Width = width;
   fb->Height = height;
   fb->DepthBits = d->cfg.depth;
   fb->StencilBits = d->cfg.stencil;
   fb->AlphaBits = d->cfg.alpha;
   /* the oracle's DRI software buffers are B8G8R8A8/B8G8R8X8 */
   fb->ColorR8G8B8A8 = false;
   /* ... and sRGB formats (B8G8R8A8_SRGB, B8G8R8X8_SRGB: the oracle's
    * dri_fill_st_visual takes the sRGB variant of every 8-bit visual,
    * whatever GLX_FRAMEBUFFER_SRGB_CAPABLE says); only glAccum sees it
    * (ORACLE-NOTES.md "GLX sRGB buffers", glx-accum) */
   fb->Srgb = true;
   fb->DoubleBuffer = d->cfg.db;
   fb->ZSFormat = zs_format(&d->cfg);
   /* a double-buffered window has a separate front buffer (Other), black
    * at first as the oracle's; glDrawBuffer selects the one drawn */
   const bool separate_front = d->cfg.db && !d->pixmap && !d->pbuffer;
   fb->FlushFront = !d->cfg.db ? flush_front : separate_front ? flush_front_db : NULL;
   fb->FlushFrontRect = NULL;
   fb->FlushFrontEnd = NULL;
   fb->AccumBits = d->cfg.accum;
   fb->Color = fgl_calloc(n, 4);
   fb->Other = separate_front ? fgl_calloc(n, 4) : NULL;
   fb->FrontIsColor = false;
   fb->OtherDefined = false;
   if (fb->ZSFormat != R_ZS_NONE) {
      const size_t bpv = fb->ZSFormat == R_ZS_Z16 ? 2 : 4;
      /* 2112 bytes past a page boundary, as osmesa.c (4K aliasing) */
      d->depth_mem = fgl_calloc(n * bpv + 4096, 1);
      fb->Depth = d->depth_mem ? (uint8_t *)d->depth_mem + 2048 + 64 : NULL;
   }
   if (d->cfg.accum > 0)
      fb->Accum = fgl_calloc(n, 4 * sizeof(int16_t));
   if (!fb->Color || (separate_front && !fb->Other) || (fb->ZSFormat != R_ZS_NONE && !fb->Depth) ||
       (d->cfg.accum > 0 && !fb->Accum)) {
      free_buffers(d);
      return false;
   }
   d->has_buffer = true;
   return true;
}

static struct glx_drawable *find_drawable(struct glx_display *gd, XID xid)
{
   pthread_mutex_lock(&gd->lock);
   struct glx_drawable *d = gd->drawables;
   while (d && d->xid != xid)
      d = d->next;
   pthread_mutex_unlock(&gd->lock);
   return d;
}

static struct glx_drawable *add_drawable(struct glx_display *gd, XID xid,
                                         const struct __GLXFBConfigRec *cfg, bool pixmap)
{
   struct glx_drawable *d = fgl_calloc(1, sizeof(*d));
   if (!d)
      return NULL;
   d->disp = gd;
   d->xid = xid;
   d->xdraw = xid;
   d->cfg = *cfg;
   d->pixmap = pixmap;
   pthread_mutex_lock(&gd->lock);
   d->next = gd->drawables;
   gd->drawables = d;
   pthread_mutex_unlock(&gd->lock);
   return d;
}

/* The contexts bound to d (to any drawable when d is NULL) draw nowhere
 * from now on: their buffers are about to go.  What the current one has
 * binned is drawn first; the others were flushed when they stopped being
 * current. */
static void unbind_contexts(struct glx_display *gd, const struct glx_drawable *d)
{
   GLXContext cur = current_context();
   pthread_mutex_lock(&gd->lock);
   for (GLXContext c = gd->contexts; c; c = c->next) {
      if (c->read_bound && (!d || c->read_bound == d)) {
         /* (reads from the draw drawable from now on) */
         fgl_context_bind_read_framebuffer(c->gl, NULL);
         c->read_bound = NULL;
      }
      if (!c->bound || (d && c->bound != d))
         continue;
      if (c == cur)
         fgl_scene_flush(c->gl);
      fgl_context_bind_framebuffer(c->gl, NULL);   /* (and no read one) */
      c->bound = NULL;
      c->read_bound = NULL;
   }
   pthread_mutex_unlock(&gd->lock);
}

static void remove_drawable(struct glx_display *gd, XID xid)
{
   pthread_mutex_lock(&gd->lock);
   struct glx_drawable **p = &gd->drawables;
   while (*p && (*p)->xid != xid)
      p = &(*p)->next;
   struct glx_drawable *d = *p;
   if (d)
      *p = d->next;
   pthread_mutex_unlock(&gd->lock);
   if (!d)
      return;
   unbind_contexts(gd, d);
   free_drawable(d, true);
}

/* The drawable's size from the server; the buffers follow it (ctx, when
 * given, is the context drawing into it: what it holds is drawn before
 * the buffers go, and it is bound to the new ones). */
static bool update_size(struct glx_drawable *d, struct fgl_context *ctx)
{
   Window root;
   int x, y;
   unsigned w = 0, h = 0, bw, depth;
   if (d->pbuffer) {
      w = (unsigned)d->pb_width;
      h = (unsigned)d->pb_height;
   } else if (!XGetGeometry(d->disp->dpy, d->xdraw, &root, &x, &y, &w, &h, &bw, &depth)) {
      return d->has_buffer;
   }
   if (w < 1)
      w = 1;
   if (h < 1)
      h = 1;
   if (w > GLX_MAX_SIZE)
      w = GLX_MAX_SIZE;
   if (h > GLX_MAX_SIZE)
      h = GLX_MAX_SIZE;
   if (d->has_buffer && d->fb.Width == (int)w && d->fb.Height == (int)h)
      return true;
   if (ctx)
      fgl_scene_flush(ctx);
   if (!alloc_buffers(d, (int)w, (int)h))
      return false;
   if (ctx)
      fgl_context_bind_framebuffer(ctx, &d->fb);
   return true;
}

/* ---- presentation ------------------------------------------------------- */

/* The X error trap around XShmAttach: MIT-SHM can be there and still
 * fail (a server in another IPC namespace).  Thread-local, set only
 * inside the trap. */
static _Thread_local bool shm_failed;

static int shm_error_handler(Display *dpy, XErrorEvent *ev)
{
   (void)dpy;
   (void)ev;
   shm_failed = true;
   return 0;
}

static bool create_shm_image(struct glx_drawable *d, Visual *visual, int w, int h)
{
   Display *dpy = d->disp->dpy;
   d->img = XShmCreateImage(dpy, visual, (unsigned)d->cfg.visual_depth, ZPixmap, NULL,
                            &d->shminfo, (unsigned)w, (unsigned)h);
   if (!d->img)
      return false;
   const size_t size = (size_t)d->img->bytes_per_line * (size_t)h;
   d->shminfo.shmid = shmget(IPC_PRIVATE, size, IPC_CREAT | 0600);
   if (d->shminfo.shmid < 0)
      goto fail_image;
   d->shminfo.shmaddr = d->img->data = shmat(d->shminfo.shmid, NULL, 0);
   if (d->shminfo.shmaddr == (char *)-1)
      goto fail_id;
   d->shminfo.readOnly = False;
   XSync(dpy, False);
   int (*old)(Display *, XErrorEvent *) = XSetErrorHandler(shm_error_handler);
   shm_failed = false;
   XShmAttach(dpy, &d->shminfo);
   XSync(dpy, False);
   XSetErrorHandler(old);
   shmctl(d->shminfo.shmid, IPC_RMID, NULL);
   if (shm_failed) {
      shmdt(d->shminfo.shmaddr);
      d->img->data = NULL;
      XDestroyImage(d->img);
      d->img = NULL;
      return false;
   }
   d->shm = true;
   return true;
fail_id:
   shmctl(d->shminfo.shmid, IPC_RMID, NULL);
fail_image:
   d->img->data = NULL;
   XDestroyImage(d->img);
   d->img = NULL;
   return false;
}

static bool ensure_image(struct glx_drawable *d, int w, int h)
{
   if (d->img && d->img->width == w && d->img->height == h)
      return true;
   destroy_image(d, true);
   Display *dpy = d->disp->dpy;
   XVisualInfo *vi = visual_info(dpy, &d->cfg);
   if (!vi)
      return false;
   Visual *visual = vi->visual;
   XFree(vi);
   if (d->disp->has_shm < 0)
      d->disp->has_shm = XShmQueryExtension(dpy) ? 1 : 0;
   if (d->disp->has_shm && create_shm_image(d, visual, w, h))
      return true;
   if (d->disp->has_shm)
      d->disp->has_shm = 0;   /* it failed once: plain XPutImage from now on */
   d->img = XCreateImage(dpy, visual, (unsigned)d->cfg.visual_depth, ZPixmap, 0, NULL,
                         (unsigned)w, (unsigned)h, 32, 0);
   if (!d->img)
      return false;
   d->img->data = malloc((size_t)d->img->bytes_per_line * (size_t)h);
   if (!d->img->data) {
      XDestroyImage(d->img);
      d->img = NULL;
      return false;
   }
   return true;
}

/* The colour buffer (RGBA8, top row first) to the X drawable: 32-bit
 * pixels 0xAARRGGBB in the server's byte order (alpha 0xff without an
 * alpha channel). */
static void present(struct glx_drawable *d, const uint8_t *color)
{
   struct fgl_framebuffer *fb = &d->fb;
   if (!d->has_buffer || d->pbuffer)
      return;
   fgl_lazy_resolve(fb, FGL_LAZY_COLOR);
   const int w = fb->Width, h = fb->Height;
   if (!ensure_image(d, w, h) || d->img->bits_per_pixel != 32)
      return;
   if (!d->gc)
      d->gc = XCreateGC(d->disp->dpy, d->xdraw, 0, NULL);
   const bool msb = d->img->byte_order == MSBFirst;
   const bool alpha = d->cfg.alpha > 0 && d->cfg.visual_depth == 32;
   for (int y = 0; y < h; y++) {
      const uint8_t *src = color + (size_t)y * (size_t)w * 4;
      uint8_t *dst = (uint8_t *)d->img->data + (size_t)y * (size_t)d->img->bytes_per_line;
      for (int x = 0; x < w; x++, src += 4, dst += 4) {
         const uint8_t a = alpha ? src[3] : 0xff;
         if (msb) {
            dst[0] = a; dst[1] = src[0]; dst[2] = src[1]; dst[3] = src[2];
         } else {
            dst[0] = src[2]; dst[1] = src[1]; dst[2] = src[0]; dst[3] = a;
         }
      }
   }
   Display *dpy = d->disp->dpy;
   if (d->shm) {
      XShmPutImage(dpy, d->xdraw, d->gc, d->img, 0, 0, 0, 0, (unsigned)w, (unsigned)h, False);
      /* the next frame overwrites the segment: the server has read it */
      XSync(dpy, False);
   } else {
      XPutImage(dpy, d->xdraw, d->gc, d->img, 0, 0, 0, 0, (unsigned)w, (unsigned)h);
      XFlush(dpy);
   }
}

/* ---- contexts ----------------------------------------------------------- */

static GLXContext create_context(struct glx_display *gd, const struct __GLXFBConfigRec *cfg,
                                 GLXContext share)
{
   GLXContext c = fgl_calloc(1, sizeof(*c));
   if (!c)
      return NULL;
   /* display lists, textures and buffers are shared with share's */
   c->gl = fgl_context_create(share ? share->gl : NULL);
   if (!c->gl) {
      fgl_free(c);
      return NULL;
   }
   if (cfg->db)
      fgl_init_double_buffered(c->gl);
   c->disp = gd;
   c->dpy = gd->dpy;
   c->cfg = *cfg;
   pthread_mutex_lock(&gd->lock);
   c->next = gd->contexts;
   gd->contexts = c;
   pthread_mutex_unlock(&gd->lock);
   return c;
}

GLXAPI GLXContext glXCreateContext(Display *dpy, XVisualInfo *vis, GLXContext shareList, Bool direct)
{
   (void)direct;
   struct glx_display *gd = get_display(dpy);
   if (!gd || !vis)
      return NULL;
   const struct __GLXFBConfigRec *cfg = config_of_visual(gd, vis->visualid);
   return cfg ? create_context(gd, cfg, shareList) : NULL;
}

GLXAPI GLXContext glXCreateNewContext(Display *dpy, GLXFBConfig config, int renderType,
                                      GLXContext shareList, Bool direct)
{
   (void)direct;
   struct glx_display *gd = get_display(dpy);
   if (!gd || !config || renderType != GLX_RGBA_TYPE)
      return NULL;
   return create_context(gd, config, shareList);
}

/* GLX_ARB_create_context: the attributes checked in the oracle's order
 * (the glx suite's glx-glxattribs): an undefined version (major below 1,
 * 1.6+, 2.2+, 3.4+), colour index from 3.0 on and forward compatibility
 * before 3.0 are BadMatch; unknown flag bits BadValue; a profile mask
 * other than core or compatibility GLXBadProfileARB; an unknown attribute
 * and colour index BadValue; a version the library lacks GLXBadFBConfig
 * (minor opcode 0, as the oracle raises it).  fixgl is GL 1.5: every
 * version above it is refused that way, whatever the profile.  Returns
 * the error (code, whether GLX's, minor opcode) or false. */
struct attribs_error {
   bool glx;
   int code, minor;
};

static bool create_attribs_error(const int *attribs, struct attribs_error *e)
{
   int major = 1, minor = 0, flags = 0, profile = GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB;
   int render_type = GLX_RGBA_TYPE;
   bool unknown = false;
   for (int i = 0; attribs && attribs[i] != None; i += 2) {
      switch (attribs[i]) {
      case GLX_CONTEXT_MAJOR_VERSION_ARB: major = attribs[i + 1]; break;
      case GLX_CONTEXT_MINOR_VERSION_ARB: minor = attribs[i + 1]; break;
      case GLX_CONTEXT_FLAGS_ARB:         flags = attribs[i + 1]; break;
      case GLX_CONTEXT_PROFILE_MASK_ARB:  profile = attribs[i + 1]; break;
      case GLX_RENDER_TYPE:               render_type = attribs[i + 1]; break;
      default:                            unknown = true; break;
      }
   }
   const int known_flags = GLX_CONTEXT_DEBUG_BIT_ARB | GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB |
                           0x4 /* robust access */ | 0x8 /* reset isolation */;
   e->glx = false;
   e->minor = GLX_OP_CREATE_CONTEXT_ATTRIBS;
   if (major < 1 || (major == 1 && minor > 5) || (major == 2 && minor > 1) ||
       (major == 3 && minor > 3) || minor < 0 ||
       (render_type == GLX_COLOR_INDEX_TYPE && major >= 3) ||
       ((flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB) && major < 3)) {
      e->code = BadMatch;
   } else if (flags & ~known_flags) {
      e->code = BadValue;
   } else if (profile != GLX_CONTEXT_CORE_PROFILE_BIT_ARB &&
              profile != GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB) {
      e->glx = true;
      e->code = GLX_ERR_BAD_PROFILE;
   } else if (unknown || render_type != GLX_RGBA_TYPE) {
      e->code = BadValue;
   } else if (major > 1) {
      e->glx = true;
      e->code = GLX_ERR_BAD_FBCONFIG;
      e->minor = 0;
   } else {
      return false;
   }
   return true;
}

GLXAPI GLXContext glXCreateContextAttribsARB(Display *dpy, GLXFBConfig config, GLXContext shareContext,
                                             Bool direct, const int *attribList)
{
   (void)direct;
   struct glx_display *gd = get_display(dpy);
   if (!gd)
      return NULL;
   struct attribs_error e;
   if (!config) {
      glx_error(dpy, true, GLX_ERR_BAD_FBCONFIG, GLX_OP_CREATE_CONTEXT_ATTRIBS, 0);
      return NULL;
   }
   if (create_attribs_error(attribList, &e)) {
      glx_error(dpy, e.glx, e.code, e.minor, 0);
      return NULL;
   }
   return create_context(gd, config, shareContext);
}

GLXAPI void glXDestroyContext(Display *dpy, GLXContext ctx)
{
   (void)dpy;
   if (!ctx)
      return;
   if (ctx->disp) {
      pthread_mutex_lock(&ctx->disp->lock);
      GLXContext *p = &ctx->disp->contexts;
      while (*p && *p != ctx)
         p = &(*p)->next;
      if (*p)
         *p = ctx->next;
      pthread_mutex_unlock(&ctx->disp->lock);
   }
   if (current_context() == ctx) {
      fgl_set_current(NULL);
      current_glx = NULL;
   }
   /* (what it has binned is drawn into its drawable's buffers, if any) */
   fgl_context_destroy(ctx->gl);
   fgl_free(ctx);
}

/* A context bound to other drawables lets go of the ones it was bound to
 * (glXMakeCurrent(dpy, None, NULL) does not): the oracle's GLX then
 * destroys the DRI drawable of a plain X window that no context is bound
 * to any more, and its buffers with it; bound again, it has new ones,
 * black, with a zero depth buffer (ORACLE-NOTES.md "GLX read drawables";
 * glXCreateWindow windows, pixmaps and pbuffers keep theirs).  Their
 * drawing was finished when the context left them. */
static void release_drawable(struct glx_display *gd, struct glx_drawable *d)
{
   if (!d || !d->implicit || !d->has_buffer)
      return;
   bool held = false;
   pthread_mutex_lock(&gd->lock);
   for (GLXContext c = gd->contexts; c && !held; c = c->next)
      held = c->bound == d || c->read_bound == d;
   pthread_mutex_unlock(&gd->lock);
   if (!held)
      free_buffers(d);
}

GLXAPI Bool glXMakeContextCurrent(Display *dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx)
{
   GLXContext cur = current_context();
   if (!ctx) {
      if (cur)
         fgl_flush_front(cur->gl);
      fgl_set_current(NULL);
      current_glx = NULL;
      return True;
   }
   struct glx_display *gd = get_display(dpy);
   /* (a context of a closed display, or of another one: BadMatch) */
   if (!gd || draw == None || ctx->disp != gd)
      return False;
   struct glx_drawable *d = find_drawable(gd, draw);
   if (d && memcmp(&d->cfg, &ctx->cfg, sizeof(d->cfg)) != 0 &&
       (d->cfg.visualid != ctx->cfg.visualid || d->pixmap)) {
      return False;   /* BadMatch: another visual */
   }
   if (!d && (d = add_drawable(gd, draw, &ctx->cfg, false)) != NULL)
      d->implicit = true;
   if (!d)
      return False;
   /* like _mesa_make_current, finish the work of the previous binding */
   if (cur && (cur != ctx || cur->bound != d))
      fgl_flush_front(cur->gl);
   if (memcmp(&d->cfg, &ctx->cfg, sizeof(d->cfg)) != 0) {
      /* a window drawn by a context of another config of its visual:
       * buffers of the new config's formats */
      d->cfg = ctx->cfg;
      free_buffers(d);
   }
   if (!update_size(d, NULL))
      return False;
   /* a separate read drawable (GLX 1.3): glReadPixels, glCopyPixels,
    * glCopyTexImage and glAccum read its buffers (main/buffers.c
    * fgl_read_fb); of the context's config too */
   struct glx_drawable *rd = NULL;
   if (read != None && read != draw) {
      rd = find_drawable(gd, read);
      if (rd && memcmp(&rd->cfg, &ctx->cfg, sizeof(rd->cfg)) != 0 &&
          (rd->cfg.visualid != ctx->cfg.visualid || rd->pixmap))
         return False;   /* BadMatch */
      if (!rd && (rd = add_drawable(gd, read, &ctx->cfg, false)) != NULL)
         rd->implicit = true;
      if (!rd)
         return False;
      if (memcmp(&rd->cfg, &ctx->cfg, sizeof(rd->cfg)) != 0) {
         rd->cfg = ctx->cfg;
         free_buffers(rd);
      }
      if (!update_size(rd, NULL))
         return False;
   }
   struct glx_drawable *const old_draw = ctx->bound, *const old_read = ctx->read_bound;
   ctx->dpy = dpy;
   ctx->draw = draw;
   ctx->read = read;
   ctx->bound = d;
   ctx->read_bound = rd;
   fgl_context_bind_framebuffer(ctx->gl, &d->fb);
   fgl_context_bind_read_framebuffer(ctx->gl, rd ? &rd->fb : NULL);
   release_drawable(gd, old_draw);
   if (old_read != old_draw)
      release_drawable(gd, old_read);
   fgl_set_current(ctx->gl);
   current_glx = ctx;
   return True;
}

GLXAPI Bool glXMakeCurrent(Display *dpy, GLXDrawable drawable, GLXContext ctx)
{
   return glXMakeContextCurrent(dpy, drawable, drawable, ctx);
}

GLXAPI GLXContext glXGetCurrentContext(void)
{
   return current_context();
}

GLXAPI GLXDrawable glXGetCurrentDrawable(void)
{
   GLXContext c = current_context();
   return c ? c->draw : None;
}

GLXAPI GLXDrawable glXGetCurrentReadDrawable(void)
{
   GLXContext c = current_context();
   return c ? c->read : None;
}

GLXAPI Display *glXGetCurrentDisplay(void)
{
   GLXContext c = current_context();
   return c ? c->dpy : NULL;
}

GLXAPI Bool glXIsDirect(Display *dpy, GLXContext ctx)
{
   (void)dpy;
   return ctx ? True : False;
}

GLXAPI void glXCopyContext(Display *dpy, GLXContext src, GLXContext dst, unsigned long mask)
{
   /* no attribute groups are copied between fixgl contexts */
   (void)dpy;
   (void)src;
   (void)dst;
   (void)mask;
}

GLXAPI int glXQueryContext(Display *dpy, GLXContext ctx, int attribute, int *value)
{
   (void)dpy;
   if (!ctx || !value)
      return GLX_BAD_CONTEXT;
   switch (attribute) {
   case GLX_FBCONFIG_ID: *value = ctx->cfg.id; return Success;
   case GLX_RENDER_TYPE: *value = GLX_RGBA_TYPE; return Success;
   case GLX_SCREEN:      *value = ctx->cfg.screen; return Success;
   default:              return GLX_BAD_ATTRIBUTE;
   }
}

GLXAPI void glXSwapBuffers(Display *dpy, GLXDrawable drawable)
{
   struct glx_display *gd = get_display(dpy);
   struct glx_drawable *d = gd ? find_drawable(gd, drawable) : NULL;
   /* (a plain window no context is bound to has no buffers: release_drawable) */
   if (!d || !d->cfg.db || !d->has_buffer)
      return;
   GLXContext cur = current_context();
   struct fgl_context *ctx = cur && cur->bound == d ? cur->gl : NULL;
   /* an implicit glFlush of the current context, as Mesa's */
   if (ctx)
      fgl_flush_front(ctx);
   /* the back buffer (the front stays as it is, as the oracle's) */
   present(d, d->fb.Other && d->fb.FrontIsColor ? d->fb.Other : d->fb.Color);
   /* the size of the next frame */
   update_size(d, ctx);
}

GLXAPI void glXWaitGL(void)
{
   GLXContext c = current_context();
   if (c)
      fgl_flush_front(c->gl);
}

GLXAPI void glXWaitX(void)
{
   GLXContext c = current_context();
   if (c && c->dpy)
      XSync(c->dpy, False);
}

/* ---- GLX drawables ------------------------------------------------------ */

/* A GLXWindow is an XID of its own, mapped to the X window
 * [S: glx/glx_pbuffer.c:CreateDrawable]: the oracle allocates it from the
 * display (XAllocID) and sends X_GLXCreateWindow, so the server checks
 * the window and the config and raises their errors (BadWindow,
 * GLXBadFBConfig, BadMatch, BadIDChoice), then its drisw makes the
 * drawable's GC (a bad window: BadDrawable of X_CreateGC) and returns the
 * XID whatever the server said.  fixgl does the same (the request only
 * when the server has GLX; the configs' IDs are the server's then), so
 * the X window made current beside its GLXWindow has buffers of its own
 * (ORACLE-NOTES.md "GLX windows").  No config: GLXBadFBConfig, None. */
GLXAPI GLXWindow glXCreateWindow(Display *dpy, GLXFBConfig config, Window win, const int *attribList)
{
   struct glx_display *gd = get_display(dpy);
   if (!gd)
      return None;
   if (!config) {
      glx_error(dpy, true, GLX_ERR_BAD_FBCONFIG, X_GLXCreateWindow, 0);
      return None;
   }
   CARD32 nattr = 0;
   while (attribList && attribList[2 * nattr] != None)
      nattr++;
   XID xid;
   LockDisplay(dpy);
   if (gd->glx_opcode && gd->from_server) {
      xGLXCreateWindowReq *req;
      GetReqExtra(GLXCreateWindow, 8 * nattr, req);
      req->reqType = (CARD8)gd->glx_opcode;
      req->glxCode = X_GLXCreateWindow;
      req->screen = (CARD32)config->screen;
      req->fbconfig = (CARD32)config->id;
      req->window = (CARD32)win;
      req->glxwindow = (CARD32)(xid = XAllocID(dpy));
      req->numAttribs = nattr;
      CARD32 *data = (CARD32 *)(req + 1);
      for (CARD32 i = 0; i < 2 * nattr; i++)
         data[i] = (CARD32)attribList[i];
   } else {
      xid = XAllocID(dpy);
   }
   UnlockDisplay(dpy);
   SyncHandle();
   struct glx_drawable *d = add_drawable(gd, xid, config, false);
   if (!d)
      return None;
   d->xdraw = win;
   d->gc = XCreateGC(dpy, win, 0, NULL);
   return xid;
}

/* [S: glx/glx_pbuffer.c:DestroyDrawable]: X_GLXDestroyWindow (the
 * server's GLXBadWindow for an ID that is no GLXWindow: unknown, the X
 * window's own, destroyed before), then the drawable and its buffers. */
GLXAPI void glXDestroyWindow(Display *dpy, GLXWindow window)
{
   struct glx_display *gd = get_display(dpy);
   if (!gd || window == None)
      return;
   if (gd->glx_opcode && gd->from_server) {
      LockDisplay(dpy);
      xGLXDestroyWindowReq *req;
      GetReq(GLXDestroyWindow, req);
      req->reqType = (CARD8)gd->glx_opcode;
      req->glxCode = X_GLXDestroyWindow;
      req->glxwindow = (CARD32)window;
      UnlockDisplay(dpy);
      SyncHandle();
   }
   struct glx_drawable *d = find_drawable(gd, window);
   if (d && d->xdraw != d->xid)
      remove_drawable(gd, window);
}

/* glXDestroyPixmap, glXDestroyGLXPixmap, glXDestroyPbuffer: fixgl's
 * pixmaps and pbuffers are its own (no request) */
static void destroy_drawable(Display *dpy, GLXDrawable draw)
{
   struct glx_display *gd = get_display(dpy);
   if (gd)
      remove_drawable(gd, draw);
}

GLXAPI GLXPixmap glXCreatePixmap(Display *dpy, GLXFBConfig config, Pixmap pixmap, const int *attribList)
{
   (void)attribList;
   struct glx_display *gd = get_display(dpy);
   if (!gd || !config || pixmap == None)
      return None;
   /* a pixmap is single-buffered: glFlush/glFinish write it */
   struct __GLXFBConfigRec cfg = *config;
   cfg.db = false;
   remove_drawable(gd, pixmap);
   return add_drawable(gd, pixmap, &cfg, true) ? pixmap : None;
}

GLXAPI void glXDestroyPixmap(Display *dpy, GLXPixmap pixmap)
{
   destroy_drawable(dpy, pixmap);
}

GLXAPI GLXPixmap glXCreateGLXPixmap(Display *dpy, XVisualInfo *vis, Pixmap pixmap)
{
   struct glx_display *gd = get_display(dpy);
   const struct __GLXFBConfigRec *cfg = gd && vis ? config_of_visual(gd, vis->visualid) : NULL;
   return cfg ? glXCreatePixmap(dpy, (GLXFBConfig)(uintptr_t)cfg, pixmap, NULL) : None;
}

GLXAPI void glXDestroyGLXPixmap(Display *dpy, GLXPixmap pixmap)
{
   destroy_drawable(dpy, pixmap);
}

/* A pbuffer of the config's formats [S: glx/glx_pbuffer.c:CreatePbuffer]:
 * GLX_PBUFFER_WIDTH/HEIGHT (0 by default) and GLX_LARGEST_PBUFFER (False;
 * the size asked for is always given, as the oracle gives it); the
 * contents are always preserved (the oracle reports
 * GLX_PRESERVED_CONTENTS True whatever was asked); other attributes are
 * ignored, as the oracle ignores them.  No config: GLXBadFBConfig. */
GLXAPI GLXPbuffer glXCreatePbuffer(Display *dpy, GLXFBConfig config, const int *attribList)
{
   struct glx_display *gd = get_display(dpy);
   if (!gd)
      return None;
   if (!config) {
      glx_error(dpy, true, GLX_ERR_BAD_FBCONFIG, GLX_OP_CREATE_PBUFFER, 0);
      return None;
   }
   int width = 0, height = 0;
   bool largest = false;
   for (int i = 0; attribList && attribList[i] != None; i += 2) {
      switch (attribList[i]) {
      case GLX_PBUFFER_WIDTH:      width = attribList[i + 1]; break;
      case GLX_PBUFFER_HEIGHT:     height = attribList[i + 1]; break;
      case GLX_LARGEST_PBUFFER:    largest = attribList[i + 1] != 0; break;
      default:                     break;
      }
   }
   if (width < 0 || height < 0 || width > GLX_MAX_SIZE || height > GLX_MAX_SIZE) {
      glx_error(dpy, false, BadValue, GLX_OP_CREATE_PBUFFER, 0);
      return None;
   }
   XLockDisplay(dpy);
   const XID xid = XAllocID(dpy);
   XUnlockDisplay(dpy);
   struct glx_drawable *d = add_drawable(gd, xid, config, false);
   if (!d)
      return None;
   d->pbuffer = true;
   /* a 0x0 pbuffer reports its size; its buffers hold one pixel */
   d->pb_width = width;
   d->pb_height = height;
   d->pb_largest = largest;
   return xid;
}

GLXAPI void glXDestroyPbuffer(Display *dpy, GLXPbuffer pbuf)
{
   destroy_drawable(dpy, pbuf);
}

/* [S: glx/glx_pbuffer.c:__glXGetDrawableAttribute] None or a drawable
 * GLX does not know: GLXBadDrawable, *value untouched; else *value is 0
 * for an attribute without a value. */
GLXAPI void glXQueryDrawable(Display *dpy, GLXDrawable draw, int attribute, unsigned int *value)
{
   struct glx_display *gd = get_display(dpy);
   struct glx_drawable *d = gd && draw != None ? find_drawable(gd, draw) : NULL;
   if (!gd || !value)
      return;
   if (!d) {
      glx_error(dpy, true, GLX_ERR_BAD_DRAWABLE, GLX_OP_GET_DRAWABLE_ATTRIBUTES, draw);
      return;
   }
   *value = 0;
   switch (attribute) {
   case GLX_WIDTH:
      *value = d->pbuffer ? (unsigned)d->pb_width : d->has_buffer ? (unsigned)d->fb.Width : 0;
      return;
   case GLX_HEIGHT:
      *value = d->pbuffer ? (unsigned)d->pb_height : d->has_buffer ? (unsigned)d->fb.Height : 0;
      return;
   case GLX_PRESERVED_CONTENTS:
      *value = d->pbuffer;
      return;
   case GLX_LARGEST_PBUFFER:
      *value = d->pbuffer && d->pb_largest;
      return;
   case GLX_FBCONFIG_ID:
      *value = (unsigned)d->cfg.id;
      return;
   case GLX_SWAP_INTERVAL_EXT:
      *value = (unsigned)d->swap_interval;
      return;
   case GLX_MAX_SWAP_INTERVAL_EXT:
      *value = 1;
      return;
   default:
      return;
   }
}

GLXAPI void glXSelectEvent(Display *dpy, GLXDrawable draw, unsigned long event_mask)
{
   /* fixgl sends no GLX events */
   (void)dpy;
   (void)draw;
   (void)event_mask;
}

GLXAPI void glXGetSelectedEvent(Display *dpy, GLXDrawable draw, unsigned long *event_mask)
{
   (void)dpy;
   (void)draw;
   if (event_mask)
      *event_mask = 0;
}

/* ---- swap control: accepted, no effect (presentation never waits) -------- */

GLXAPI void glXSwapIntervalEXT(Display *dpy, GLXDrawable drawable, int interval)
{
   struct glx_display *gd = get_display(dpy);
   struct glx_drawable *d = gd ? find_drawable(gd, drawable) : NULL;
   if (d && interval >= 0)
      d->swap_interval = interval;
}

GLXAPI int glXSwapIntervalMESA(unsigned int interval)
{
   GLXContext c = current_context();
   if (!c || !c->bound)
      return GLX_BAD_CONTEXT;
   c->bound->swap_interval = (int)interval;
   return 0;
}

GLXAPI int glXGetSwapIntervalMESA(void)
{
   GLXContext c = current_context();
   return c && c->bound ? c->bound->swap_interval : 0;
}

GLXAPI int glXSwapIntervalSGI(int interval)
{
   if (interval <= 0)
      return GLX_BAD_VALUE;
   return glXSwapIntervalMESA((unsigned)interval);
}

/* ---- queries ------------------------------------------------------------ */

GLXAPI Bool glXQueryExtension(Display *dpy, int *errorBase, int *eventBase)
{
   /* GLX is done in the client: any display has it; the error and event
    * bases are the server's GLX extension's (those of the errors
    * glx_error raises), 0 without one */
   struct glx_display *gd = get_display(dpy);
   if (errorBase)
      *errorBase = gd ? gd->glx_error_base : 0;
   if (eventBase)
      *eventBase = gd ? gd->glx_event_base : 0;
   return dpy ? True : False;
}

GLXAPI Bool glXQueryVersion(Display *dpy, int *major, int *minor)
{
   if (major)
      *major = 1;
   if (minor)
      *minor = 4;
   return dpy ? True : False;
}

static const char *glx_string(int name)
{
   switch (name) {
   case GLX_VENDOR:     return "fixgl";
   case GLX_VERSION:    return "1.4 fixgl " FIXGL_VERSION_STRING;
   case GLX_EXTENSIONS: return glx_extensions;
   default:             return NULL;
   }
}

GLXAPI const char *glXGetClientString(Display *dpy, int name)
{
   (void)dpy;
   return glx_string(name);
}

GLXAPI const char *glXQueryServerString(Display *dpy, int screen, int name)
{
   (void)dpy;
   (void)screen;
   return glx_string(name);
}

GLXAPI const char *glXQueryExtensionsString(Display *dpy, int screen)
{
   (void)dpy;
   (void)screen;
   return glx_extensions;
}

struct glx_proc {
   const char *name;
   __GLXextFuncPtr proc;
};

#define GLX_PROC(f) { #f, (__GLXextFuncPtr)(void (*)(void))(f) }
static const struct glx_proc glx_procs[] = {
   GLX_PROC(glXChooseFBConfig),        GLX_PROC(glXChooseVisual),
   GLX_PROC(glXCopyContext),           GLX_PROC(glXCreateContext),
   GLX_PROC(glXCreateContextAttribsARB),
   GLX_PROC(glXCreateGLXPixmap),       GLX_PROC(glXCreateNewContext),
   GLX_PROC(glXCreatePbuffer),         GLX_PROC(glXCreatePixmap),
   GLX_PROC(glXCreateWindow),          GLX_PROC(glXDestroyContext),
   GLX_PROC(glXDestroyGLXPixmap),      GLX_PROC(glXDestroyPbuffer),
   GLX_PROC(glXDestroyPixmap),         GLX_PROC(glXDestroyWindow),
   GLX_PROC(glXGetClientString),       GLX_PROC(glXGetConfig),
   GLX_PROC(glXGetCurrentContext),     GLX_PROC(glXGetCurrentDisplay),
   GLX_PROC(glXGetCurrentDrawable),    GLX_PROC(glXGetCurrentReadDrawable),
   GLX_PROC(glXGetFBConfigAttrib),     GLX_PROC(glXGetFBConfigs),
   GLX_PROC(glXGetProcAddress),        GLX_PROC(glXGetProcAddressARB),
   GLX_PROC(glXGetSelectedEvent),      GLX_PROC(glXGetSwapIntervalMESA),
   GLX_PROC(glXGetVisualFromFBConfig), GLX_PROC(glXIsDirect),
   GLX_PROC(glXMakeContextCurrent),    GLX_PROC(glXMakeCurrent),
   GLX_PROC(glXQueryContext),          GLX_PROC(glXQueryDrawable),
   GLX_PROC(glXQueryExtension),        GLX_PROC(glXQueryExtensionsString),
   GLX_PROC(glXQueryServerString),     GLX_PROC(glXQueryVersion),
   GLX_PROC(glXSelectEvent),           GLX_PROC(glXSwapBuffers),
   GLX_PROC(glXSwapIntervalEXT),       GLX_PROC(glXSwapIntervalMESA),
   GLX_PROC(glXSwapIntervalSGI),       GLX_PROC(glXUseXFont),
   GLX_PROC(glXWaitGL),                GLX_PROC(glXWaitX),
};

/* The GL entry points as OSMesaGetProcAddress gives them (NULL for a name
 * fixgl does not implement, libfixgl/osmesa/osmesa.c), and the GLX ones. */
GLXAPI __GLXextFuncPtr glXGetProcAddressARB(const GLubyte *procName)
{
   const char *name = (const char *)procName;
   if (!name)
      return NULL;
   if (strncmp(name, "glX", 3) == 0) {
      for (size_t i = 0; i < sizeof(glx_procs) / sizeof(glx_procs[0]); i++)
         if (strcmp(glx_procs[i].name, name) == 0)
            return glx_procs[i].proc;
      return NULL;
   }
   return (__GLXextFuncPtr)OSMesaGetProcAddress(name);
}

GLXAPI __GLXextFuncPtr glXGetProcAddress(const GLubyte *procName)
{
   return glXGetProcAddressARB(procName);
}
