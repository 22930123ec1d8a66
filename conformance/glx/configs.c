/*
 * configs - the GLX configs and visuals a program sees, on Mesa's libGL
 * and on fixgl's (run_glx.py configs): one text file per library that the
 * runner compares line by line.
 *
 *   - every FBConfig of glXGetFBConfigs, in its order, with the
 *     attributes of `fb_attrs` (glXGetFBConfigAttrib);
 *   - every visual of the screen (XGetVisualInfo) with the attributes of
 *     `vis_attrs` (glXGetConfig), or the error glXGetConfig returns;
 *   - the answers of glXChooseFBConfig (the list's IDs) and
 *     glXChooseVisual (the visual's ID) for the attribute lists below.
 *
 * A config with sample buffers, or with colour channels other than 8-8-8
 * (alpha 0 or 8) or not unsigned RGBA, is one fixgl cannot render (it
 * has no multisampling and 8-bit RGBA colour buffers only; Mesa's 10-10-10
 * and 5-6-5 configs have no visual, they serve pbuffers and pixmaps):
 * such configs are printed with a leading "-" (the runner drops them from
 * Mesa's list and requires fixgl to have none), and the chosen lists are
 * printed without them.  Everything else must be equal.
 *
 *   configs --out FILE.txt
 */
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const struct { int attr; const char *name; } fb_attrs[] = {
   { GLX_FBCONFIG_ID, "id" },
   { GLX_VISUAL_ID, "visual" },
   { GLX_X_VISUAL_TYPE, "vtype" },
   { GLX_BUFFER_SIZE, "buf" },
   { GLX_LEVEL, "level" },
   { GLX_DOUBLEBUFFER, "db" },
   { GLX_STEREO, "stereo" },
   { GLX_AUX_BUFFERS, "aux" },
   { GLX_RED_SIZE, "r" },
   { GLX_GREEN_SIZE, "g" },
   { GLX_BLUE_SIZE, "b" },
   { GLX_ALPHA_SIZE, "a" },
   { GLX_DEPTH_SIZE, "z" },
   { GLX_STENCIL_SIZE, "s" },
   { GLX_ACCUM_RED_SIZE, "ar" },
   { GLX_ACCUM_GREEN_SIZE, "ag" },
   { GLX_ACCUM_BLUE_SIZE, "ab" },
   { GLX_ACCUM_ALPHA_SIZE, "aa" },
   { GLX_SAMPLE_BUFFERS, "sb" },
   { GLX_SAMPLES, "samples" },
   { GLX_RENDER_TYPE, "render" },
   { GLX_DRAWABLE_TYPE, "drawable" },
   { GLX_X_RENDERABLE, "xr" },
   { GLX_CONFIG_CAVEAT, "caveat" },
   { GLX_TRANSPARENT_TYPE, "trans" },
   { GLX_SCREEN, "screen" },
   { GLX_MAX_PBUFFER_WIDTH, "pbw" },
   { GLX_MAX_PBUFFER_HEIGHT, "pbh" },
   { GLX_MAX_PBUFFER_PIXELS, "pbp" },
};

static const struct { int attr; const char *name; } vis_attrs[] = {
   { GLX_USE_GL, "use_gl" },
   { GLX_RGBA, "rgba" },
   { GLX_BUFFER_SIZE, "buf" },
   { GLX_LEVEL, "level" },
   { GLX_DOUBLEBUFFER, "db" },
   { GLX_STEREO, "stereo" },
   { GLX_AUX_BUFFERS, "aux" },
   { GLX_RED_SIZE, "r" },
   { GLX_GREEN_SIZE, "g" },
   { GLX_BLUE_SIZE, "b" },
   { GLX_ALPHA_SIZE, "a" },
   { GLX_DEPTH_SIZE, "z" },
   { GLX_STENCIL_SIZE, "s" },
   { GLX_ACCUM_RED_SIZE, "ar" },
   { GLX_ACCUM_GREEN_SIZE, "ag" },
   { GLX_ACCUM_BLUE_SIZE, "ab" },
   { GLX_ACCUM_ALPHA_SIZE, "aa" },
   { GLX_SAMPLE_BUFFERS, "sb" },
   { GLX_SAMPLES, "samples" },
   { GLX_X_VISUAL_TYPE, "vtype" },
   { GLX_CONFIG_CAVEAT, "caveat" },
};

#define N(a) (sizeof(a) / sizeof((a)[0]))

/* fixgl renders the config: single-sampled RGBA of 8 bits a channel
 * (alpha 0 or 8), unsigned */
static int renderable(Display *dpy, GLXFBConfig c)
{
   int sb = 0, render = 0, r = 0, g = 0, b = 0, a = 0;
   glXGetFBConfigAttrib(dpy, c, GLX_SAMPLE_BUFFERS, &sb);
   glXGetFBConfigAttrib(dpy, c, GLX_RENDER_TYPE, &render);
   glXGetFBConfigAttrib(dpy, c, GLX_RED_SIZE, &r);
   glXGetFBConfigAttrib(dpy, c, GLX_GREEN_SIZE, &g);
   glXGetFBConfigAttrib(dpy, c, GLX_BLUE_SIZE, &b);
   glXGetFBConfigAttrib(dpy, c, GLX_ALPHA_SIZE, &a);
   return sb == 0 && render == GLX_RGBA_BIT && r == 8 && g == 8 && b == 8 && (a == 0 || a == 8);
}

int main(int argc, char **argv)
{
   if (argc != 3 || strcmp(argv[1], "--out") != 0) {
      fprintf(stderr, "usage: %s --out FILE.txt\n", argv[0]);
      return 2;
   }
   Display *dpy = XOpenDisplay(NULL);
   if (!dpy) {
      fprintf(stderr, "configs: no display\n");
      return 1;
   }
   FILE *f = fopen(argv[2], "w");
   if (!f) {
      perror(argv[2]);
      return 1;
   }
   const int screen = DefaultScreen(dpy);
   printf("vendor: %s\n", glXGetClientString(dpy, GLX_VENDOR));

   int n = 0;
   GLXFBConfig *all = glXGetFBConfigs(dpy, screen, &n);
   int kept = 0;
   for (int i = 0; i < n; i++) {
      const int ok = renderable(dpy, all[i]);
      kept += ok;
      fprintf(f, "%sfbconfig", ok ? "" : "-");
      for (size_t a = 0; a < N(fb_attrs); a++) {
         int v = -12345;
         const int err = glXGetFBConfigAttrib(dpy, all[i], fb_attrs[a].attr, &v);
         if (err)
            fprintf(f, " %s=err%d", fb_attrs[a].name, err);
         else
            fprintf(f, " %s=%d", fb_attrs[a].name, v);
      }
      fputc('\n', f);
   }
   printf("%d fbconfigs, %d renderable\n", n, kept);

   XVisualInfo tmpl = { .screen = screen };
   int nv = 0;
   XVisualInfo *vis = XGetVisualInfo(dpy, VisualScreenMask, &tmpl, &nv);
   int glvis = 0;
   for (int i = 0; i < nv; i++) {
      int sb = 0;
      if (glXGetConfig(dpy, &vis[i], GLX_SAMPLE_BUFFERS, &sb) == Success && sb) {
         fprintf(f, "-visual 0x%lx\n", (unsigned long)vis[i].visualid);
         continue;
      }
      fprintf(f, "visual 0x%lx class=%d depth=%d", (unsigned long)vis[i].visualid, vis[i].class,
              vis[i].depth);
      int use = 0;
      glXGetConfig(dpy, &vis[i], GLX_USE_GL, &use);
      glvis += use != 0;
      for (size_t a = 0; a < N(vis_attrs); a++) {
         int v = -12345;
         const int err = glXGetConfig(dpy, &vis[i], vis_attrs[a].attr, &v);
         if (err)
            fprintf(f, " %s=err%d", vis_attrs[a].name, err);
         else
            fprintf(f, " %s=%d", vis_attrs[a].name, v);
      }
      fputc('\n', f);
   }
   printf("%d visuals, %d with GL\n", nv, glvis);

   /* glXChooseFBConfig: the renderable configs of each answer, in order */
   static const int fb_lists[][16] = {
      { None },
      { GLX_DOUBLEBUFFER, True, None },
      { GLX_DOUBLEBUFFER, False, None },
      { GLX_RED_SIZE, 1, GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1, GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 1, None },
      { GLX_ALPHA_SIZE, 1, GLX_DEPTH_SIZE, 24, GLX_STENCIL_SIZE, 8, None },
      { GLX_ACCUM_RED_SIZE, 1, GLX_DOUBLEBUFFER, True, None },
      { GLX_X_VISUAL_TYPE, GLX_DIRECT_COLOR, None },
      { GLX_DRAWABLE_TYPE, GLX_PIXMAP_BIT, GLX_DEPTH_SIZE, 16, None },
      { GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, GLX_X_RENDERABLE, GLX_DONT_CARE, None },
      { GLX_BUFFER_SIZE, 32, GLX_DOUBLEBUFFER, GLX_DONT_CARE, None },
      { GLX_CONFIG_CAVEAT, GLX_NONE, GLX_STENCIL_SIZE, 1, None },
   };
   for (size_t l = 0; l < N(fb_lists); l++) {
      int m = 0;
      GLXFBConfig *got = glXChooseFBConfig(dpy, screen, fb_lists[l], &m);
      fprintf(f, "choosefb %zu:", l);
      for (int i = 0; i < m; i++) {
         if (!renderable(dpy, got[i]))
            continue;
         int id = 0;
         glXGetFBConfigAttrib(dpy, got[i], GLX_FBCONFIG_ID, &id);
         fprintf(f, " %d", id);
      }
      fputc('\n', f);
      if (got)
         XFree(got);
   }

   /* glXChooseVisual: the visual of each answer */
   static int vis_lists[][16] = {
      { GLX_RGBA, None },
      { GLX_RGBA, GLX_DOUBLEBUFFER, None },
      { GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1, None },
      { GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 16, GLX_STENCIL_SIZE, 1, None },
      { GLX_RGBA, GLX_RED_SIZE, 1, GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1, GLX_ALPHA_SIZE, 1, None },
      { GLX_RGBA, GLX_DEPTH_SIZE, 24, None },
      { GLX_RGBA, GLX_DOUBLEBUFFER, GLX_ACCUM_RED_SIZE, 8, None },
      { GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 24, GLX_STENCIL_SIZE, 8, GLX_ALPHA_SIZE, 8, None },
      { GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1, None },
      { GLX_RGBA, GLX_BUFFER_SIZE, 32, GLX_DEPTH_SIZE, 32, None },
   };
   for (size_t l = 0; l < N(vis_lists); l++) {
      XVisualInfo *v = glXChooseVisual(dpy, screen, vis_lists[l]);
      fprintf(f, "choosevisual %zu: 0x%lx depth=%d\n", l, v ? (unsigned long)v->visualid : 0ul,
              v ? v->depth : 0);
      if (v)
         XFree(v);
   }
   if (all)
      XFree(all);
   if (vis)
      XFree(vis);
   if (fclose(f) != 0) {
      perror(argv[2]);
      return 1;
   }
   XCloseDisplay(dpy);
   return 0;
}
