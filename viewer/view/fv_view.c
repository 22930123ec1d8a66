/*
 * fixgl-view: a model viewer on fixgl.
 *
 * fixgl renders every frame on the CPU into an OSMesa-style RGBA8 buffer
 * (libfixgl's OSMesa API); a GLFW window shows it through the system GL
 * reached only by glfwGetProcAddress (viewer/common/fv_present.c).  The
 * split view renders the same frame a second time with Mesa's libOSMesa,
 * loaded at run time (fv_osmesa.c), and shows fixgl | OSMesa | difference.
 * A headless mode renders the same view without a window (and without X).
 *
 * `fixgl-view --help` lists the options and keys (the key table below is
 * both the help and the dispatch).
 */
#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <GL/osmesa.h>
#include <fixgl/fixgl.h>
#include <fixgl/version.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "fv_gl.h"
#include "fv_grab.h"
#include "fv_model.h"
#include "fv_osmesa.h"
#include "fv_png.h"
#include "fv_present.h"
#include "fv_scene.h"

#ifdef FV_HAVE_FCR
#include "fcr_shading.h"
#endif

/* ---- the bundled models ------------------------------------------------ */

/* Where the build installs the bundled models (DATADIR/fixgl/models), and
 * the same directory relative to the installed executable's (BINDIR), for
 * an installed tree that was moved or not yet copied into place (DESTDIR). */
#ifndef FV_MODELS_DIR
#define FV_MODELS_DIR "/usr/local/share/fixgl/models"
#endif
#ifndef FV_MODELS_REL
#define FV_MODELS_REL "../share/fixgl/models"
#endif
#define FV_DEFAULT_MODEL "teapot.obj"
static const char *const bundled_models[] = { "teapot.obj", "lowpoly.obj", "sphere.ply",
                                              "torus.stl", "globe.obj", "colors.ply",
                                              "rgbcube.obj" };

/* --size: the width is at least 3 (the split view's three panels); 8192
 * bounds a frame (and each of the split view's buffers) to 256 MiB. */
#define FV_MIN_WIDTH 3
#define FV_MIN_HEIGHT 1
#define FV_MAX_SIZE 8192

static int has_default_model(const char *dir)
{
   char path[PATH_MAX];
   return snprintf(path, sizeof path, "%s/" FV_DEFAULT_MODEL, dir) < (int)sizeof path &&
          access(path, R_OK) == 0;
}

/* The directory of the bundled models, the first of: $FIXGL_VIEW_MODELS;
 * FV_MODELS_REL from the executable's directory (installed: the same
 * directory as FV_MODELS_DIR, or where a moved tree has it); `models`
 * beside the executable (the build tree, uninstalled:
 * build/viewer/view/models); FV_MODELS_DIR. */
static const char *models_dir(void)
{
   static char dir[PATH_MAX];
   if (dir[0])
      return dir;
   const char *env = getenv("FIXGL_VIEW_MODELS");
   if (env && *env) {
      snprintf(dir, sizeof dir, "%s", env);
      return dir;
   }
   char exe[PATH_MAX];
   ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
   if (n > 0) {
      exe[n] = 0;
      char *slash = strrchr(exe, '/');
      if (slash)
         *slash = 0;
      static const char *const rel[] = { FV_MODELS_REL, "models" };
      for (size_t i = 0; i < sizeof rel / sizeof rel[0]; i++) {
         char cand[PATH_MAX], real[PATH_MAX];
         if (snprintf(cand, sizeof cand, "%s/%s", exe, rel[i]) < (int)sizeof cand &&
             has_default_model(cand) && realpath(cand, real)) {
            snprintf(dir, sizeof dir, "%s", real);
            return dir;
         }
      }
   }
   snprintf(dir, sizeof dir, "%s", FV_MODELS_DIR);
   return dir;
}

/* MODEL as given when it exists or names a directory, else the bundled
 * model of that name when there is one; the bundled teapot without MODEL. */
static const char *model_path(const char *model)
{
   static char path[PATH_MAX];
   if (model && (access(model, F_OK) == 0 || strchr(model, '/')))
      return model;
   if (snprintf(path, sizeof path, "%s/%s", models_dir(), model ? model : FV_DEFAULT_MODEL) >=
       (int)sizeof path)
      return model ? model : FV_DEFAULT_MODEL;
   return !model || access(path, F_OK) == 0 ? path : model;
}

/* ---- the application ---------------------------------------------------- */

struct frame {
   unsigned char *rgba;   /* bottom-up RGBA8 */
   int w, h;
};

/* What the OSMesa side produced for the current frame. */
enum osmesa_status { OSM_OK, OSM_UNAVAILABLE, OSM_NO_REFERENCE };

static struct {
   /* options */
   const char *model_path;
   int headless, split, width, height, frames, info;
   float spin;
   int renderer_osmesa;
   enum fv_normals normals;
   const char *out, *osmesa_out, *screenshot, *screenshot_x11;
   const char *key_list;
   struct scripted {
      int key;                      /* key table index, or -1: a mouse action */
      int button;                   /* 0 drag, 1 right drag, 2 wheel */
      float dx, dy;
   } script[256];                   /* --keys: one per frame */
   int num_script;
   int quit;

   struct fv_model model;
   struct fv_scene scene;

   /* fixgl */
   OSMesaContext ctx;
   struct fv_gl gl;
   struct frame fixgl_frame;
   GLuint *fixgl_tex;             /* the model's textures in fixgl's context */
   int fixgl_phong, fixgl_ct;     /* GL_EXTENSIONS lists them */
   double fixgl_ms;

   /* OSMesa, opened on first use */
   int osmesa_tried;
   struct fv_osmesa *osmesa;
   const char *osmesa_why;
   struct fcr *ref;
   struct frame osmesa_frame;
   GLuint *osmesa_tex;            /* and in OSMesa's, made on first use */
   double osmesa_ms;
   enum osmesa_status osmesa_status;

   /* the split view's panels and the composed frame */
   struct frame shown;
   long diff_pixels;
   int diff_max;

   /* window */
   GLFWwindow *win;
   struct fv_present *present;
   int dirty, dragging, drag_button;
   double drag_x, drag_y;
   int shots;
} A = {
   .width = 0, .height = 0, .frames = 0,
};

static void die(const char *fmt, const char *arg)
{
   fprintf(stderr, "fixgl-view: ");
   fprintf(stderr, fmt, arg);
   fputc('\n', stderr);
   exit(1);
}

static double now_ms(void)
{
   struct timespec ts;
   clock_gettime(CLOCK_MONOTONIC, &ts);
   return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static void frame_size(struct frame *f, int w, int h)
{
   if (f->rgba && f->w == w && f->h == h)
      return;
   free(f->rgba);
   f->rgba = calloc((size_t)w * h, 4);
   if (!f->rgba)
      die("out of memory for a %s frame", "RGBA");
   f->w = w, f->h = h;
}

/* ---- rendering ------------------------------------------------------------ */

static void render_fixgl(int w, int h)
{
   frame_size(&A.fixgl_frame, w, h);
   if (!OSMesaMakeCurrent(A.ctx, A.fixgl_frame.rgba, GL_UNSIGNED_BYTE, w, h))
      die("%s: OSMesaMakeCurrent failed", "fixgl");
   double t0 = now_ms();
   fv_scene_draw(&A.scene, &A.gl, A.fixgl_tex, w, h, NULL);
   A.fixgl_ms = now_ms() - t0;
   while (A.gl.GetError() != GL_NO_ERROR)
      ;  /* Phong/CT enums before libfixgl knows them: drawn smooth/Blinn-Phong */
}

static void open_osmesa(void)
{
   if (A.osmesa_tried)
      return;
   A.osmesa_tried = 1;
   A.osmesa = fv_osmesa_open(&A.osmesa_why);
   if (!A.osmesa)
      fprintf(stderr, "fixgl-view: no OSMesa side: %s\n", A.osmesa_why);
}

/* The scene needs the GLSL reference on OSMesa (Phong or Cook-Torrance). */
static int needs_reference(void)
{
   return fv_scene_needs_phong(&A.scene) || fv_scene_needs_cook_torrance(&A.scene);
}

static void render_osmesa(int w, int h)
{
   open_osmesa();
   frame_size(&A.osmesa_frame, w, h);
   if (!A.osmesa) {
      A.osmesa_status = OSM_UNAVAILABLE;
      return;
   }
   if (fv_osmesa_begin(A.osmesa, A.osmesa_frame.rgba, w, h) != 0) {
      A.osmesa_why = "OSMesaMakeCurrent failed";
      A.osmesa_status = OSM_UNAVAILABLE;
      return;
   }
   if (!A.osmesa_tex) {
      A.osmesa_tex = calloc((size_t)A.model.num_textures + 1, sizeof *A.osmesa_tex);
      if (!A.osmesa_tex)
         die("out of memory for %s's textures", "OSMesa");
      fv_scene_upload_textures(&A.model, fv_osmesa_gl(A.osmesa), A.osmesa_tex);
   }
   struct fcr *ref = NULL;
   if (needs_reference()) {
#ifdef FV_HAVE_FCR
      if (!A.ref)
         A.ref = fcr_create((fcr_getproc)fv_osmesa_getproc);
      ref = A.ref;
#endif
      if (!ref) {
         A.osmesa_status = OSM_NO_REFERENCE;
         return;
      }
   }
   double t0 = now_ms();
   int rc = fv_scene_draw(&A.scene, fv_osmesa_gl(A.osmesa), A.osmesa_tex, w, h, ref);
   A.osmesa_ms = now_ms() - t0;
   A.osmesa_status = rc == 0 ? OSM_OK : OSM_NO_REFERENCE;
}

/* The difference panel: equal pixels dimmed grey, differing ones by their
 * largest channel difference: 1 blue, 2-3 green, 4-15 yellow, 16+ red. */
static void diff_panel(const struct frame *a, const struct frame *b, unsigned char *out)
{
   A.diff_pixels = 0;
   A.diff_max = 0;
   for (long i = 0; i < (long)a->w * a->h; i++) {
      const unsigned char *p = &a->rgba[i * 4], *q = &b->rgba[i * 4];
      int d = 0;
      for (int c = 0; c < 4; c++)
         d = abs(p[c] - q[c]) > d ? abs(p[c] - q[c]) : d;
      unsigned char *o = &out[i * 4];
      if (d == 0) {
         unsigned char g = (unsigned char)((p[0] * 77 + p[1] * 150 + p[2] * 29) >> 10);
         o[0] = o[1] = o[2] = g;
      } else {
         static const unsigned char heat[4][3] = {
            { 40, 110, 255 }, { 40, 220, 60 }, { 255, 230, 40 }, { 255, 40, 30 } };
         int k = d == 1 ? 0 : d < 4 ? 1 : d < 16 ? 2 : 3;
         memcpy(o, heat[k], 3);
         A.diff_pixels++;
      }
      o[3] = 255;
      if (d > A.diff_max)
         A.diff_max = d;
   }
}

/* A panel OSMesa could not draw: a dark slate with a diagonal hatch. */
static void note_panel(unsigned char *out, int w, int h)
{
   for (int y = 0; y < h; y++)
      for (int x = 0; x < w; x++) {
         unsigned char *o = &out[((long)y * w + x) * 4];
         unsigned char v = ((x + y) / 8) % 2 ? 48 : 36;
         o[0] = v, o[1] = v, o[2] = (unsigned char)(v + 8), o[3] = 255;
      }
}

static void blit(struct frame *dst, int x0, const unsigned char *src, int w, int h)
{
   for (int y = 0; y < h; y++)
      memcpy(&dst->rgba[((long)y * dst->w + x0) * 4], &src[(long)y * w * 4], (size_t)w * 4);
}

/* Renders the current view into A.shown (w x h): fixgl's frame, or the
 * split view fixgl | OSMesa | difference in three panels. */
static void render(int w, int h)
{
   frame_size(&A.shown, w, h);
   if (!A.split) {
      render_fixgl(w, h);
      memcpy(A.shown.rgba, A.fixgl_frame.rgba, (size_t)w * h * 4);
      return;
   }
   int pw = w / 3 > 0 ? w / 3 : 1;
   render_fixgl(pw, h);
   render_osmesa(pw, h);
   memset(A.shown.rgba, 0, (size_t)w * h * 4);
   unsigned char *tmp = malloc((size_t)pw * h * 4);
   if (!tmp)
      die("out of memory for the %s panel", "difference");
   blit(&A.shown, 0, A.fixgl_frame.rgba, pw, h);
   if (A.osmesa_status == OSM_OK) {
      blit(&A.shown, pw, A.osmesa_frame.rgba, pw, h);
      diff_panel(&A.fixgl_frame, &A.osmesa_frame, tmp);
      blit(&A.shown, 2 * pw, tmp, pw, h);
   } else {
      note_panel(tmp, pw, h);
      blit(&A.shown, pw, tmp, pw, h);
      blit(&A.shown, 2 * pw, tmp, pw, h);
   }
   free(tmp);
}

/* Why the OSMesa panel is empty, or NULL. */
static const char *osmesa_note(void)
{
   switch (A.osmesa_status) {
   case OSM_UNAVAILABLE:
      return A.osmesa_why;
   case OSM_NO_REFERENCE:
#ifdef FV_HAVE_FCR
      return "the GLSL reference could not be compiled on OSMesa";
#else
      return "Phong/Cook-Torrance on OSMesa needs the GLSL reference "
             "(conformance/reference/fcr_shading.c), not in this build";
#endif
   default:
      return NULL;
   }
}

/* What fixgl cannot draw of the current mode, or NULL. */
static const char *fixgl_note(void)
{
   if (fv_scene_needs_phong(&A.scene) && !A.fixgl_phong)
      return "this libfixgl lacks GL_WIN_phong_shading: drawn smooth";
   if (fv_scene_needs_cook_torrance(&A.scene) && !A.fixgl_ct)
      return "this libfixgl lacks GL_FIXGL_cook_torrance: drawn Blinn-Phong";
   return NULL;
}

static void status_line(char *buf, size_t size)
{
   char mode[128];
   fv_scene_describe(&A.scene, mode, sizeof mode);
   const char *slash = strrchr(A.model_path, '/');
   int on = 0;
   for (int i = 0; i < A.scene.num_lights; i++)
      on += A.scene.lights[i].on;
   int n = snprintf(buf, size, "fixgl-view: %s (%u triangles) | %s | lights %d/%d, #%d selected%s%s | fixgl %.1f ms",
                    slash ? slash + 1 : A.model_path, A.model.num_tris, mode, on,
                    A.scene.num_lights, A.scene.selected + 1,
                    A.scene.wireframe ? " | wireframe" : "", A.scene.cull ? " | culling" : "",
                    A.fixgl_ms);
   const char *fn = fixgl_note();
   if (fn && n > 0 && (size_t)n < size)
      n += snprintf(buf + n, size - (size_t)n, " (%s)", fn);
   if (A.split && n > 0 && (size_t)n < size) {
      if (A.osmesa_status == OSM_OK)
         snprintf(buf + n, size - (size_t)n, " | OSMesa %.1f ms | difference: %ld px, max %d LSB",
                  A.osmesa_ms, A.diff_pixels, A.diff_max);
      else
         snprintf(buf + n, size - (size_t)n, " | OSMesa: %s", osmesa_note());
   }
}

static void write_png(const char *path, const struct frame *f)
{
   if (fv_png_write(path, f->w, f->h, f->rgba, 1) != 0)
      die("cannot write %s", path);
}

/* ---- mouse ---------------------------------------------------------------- */

/* A drag by (dx, dy) pixels: the left button orbits the camera, the right
 * one moves the selected light. */
static void mouse_drag(int right, float dx, float dy);
static void mouse_wheel(float steps);

/* ---- keys ----------------------------------------------------------------- */

static void key_shade(int mode, int ct)
{
   A.scene.shade = (enum fv_shade)mode;
   A.scene.cook_torrance = ct;
}
static void k_flat(void) { key_shade(FV_FLAT, 0); }
static void k_smooth(void) { key_shade(FV_SMOOTH, 0); }
static void k_phong(void) { key_shade(FV_PHONG, 0); }
static void k_ct(void) { key_shade(FV_PHONG, 1); }
static void k_model(void) { A.scene.cook_torrance = !A.scene.cook_torrance; }
static float clamp01(float v) { return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v; }
static void k_rough_dn(void) { A.scene.roughness = clamp01(A.scene.roughness - 0.05f); }
static void k_rough_up(void) { A.scene.roughness = clamp01(A.scene.roughness + 0.05f); }
static void k_metal_dn(void) { A.scene.metalness = clamp01(A.scene.metalness - 0.1f); }
static void k_metal_up(void) { A.scene.metalness = clamp01(A.scene.metalness + 0.1f); }
static void k_add_light(void)
{
   if (fv_scene_add_light(&A.scene) < 0)
      fprintf(stderr, "fixgl-view: %d lights is GL's maximum\n", FV_MAX_LIGHTS);
}
static void toggle_light(int i)
{
   if (i < A.scene.num_lights) {
      A.scene.lights[i].on = !A.scene.lights[i].on;
      A.scene.selected = i;
   }
}
static void k_l1(void) { toggle_light(0); }
static void k_l2(void) { toggle_light(1); }
static void k_l3(void) { toggle_light(2); }
static void k_l4(void) { toggle_light(3); }
static void k_l5(void) { toggle_light(4); }
static void k_l6(void) { toggle_light(5); }
static void k_l7(void) { toggle_light(6); }
static void k_l8(void) { toggle_light(7); }
static void k_next_light(void) { A.scene.selected = (A.scene.selected + 1) % A.scene.num_lights; }
static struct fv_light *sel(void) { return &A.scene.lights[A.scene.selected]; }
static void k_light_left(void) { sel()->azimuth -= 10.0f; }
static void k_light_right(void) { sel()->azimuth += 10.0f; }
static void k_light_up(void) { sel()->elevation = fminf(sel()->elevation + 10.0f, 89.0f); }
static void k_light_down(void) { sel()->elevation = fmaxf(sel()->elevation - 10.0f, -89.0f); }
static void k_light_near(void) { sel()->distance = fmaxf(sel()->distance / 1.2f, 1.05f); }
static void k_light_far(void) { sel()->distance = fminf(sel()->distance * 1.2f, 20.0f); }
static void k_wireframe(void) { A.scene.wireframe = !A.scene.wireframe; }
static void k_cull(void) { A.scene.cull = !A.scene.cull; }
static void k_split(void) { A.split = !A.split; }
static void k_zoom_in(void) { A.scene.zoom = fminf(A.scene.zoom * 1.1f, 20.0f); }
static void k_zoom_out(void) { A.scene.zoom = fmaxf(A.scene.zoom / 1.1f, 0.05f); }
static void k_reset(void)
{
   A.scene.yaw = 30.0f, A.scene.pitch = 20.0f, A.scene.zoom = 1.0f;
}
static void k_screenshot(void)
{
   char path[64];
   snprintf(path, sizeof path, "fixgl-view-%03d.png", A.shots++);
   write_png(path, &A.shown);
   printf("fixgl-view: wrote %s\n", path);
}
static void k_quit(void)
{
   A.quit = 1;
   if (A.win)
      glfwSetWindowShouldClose(A.win, GLFW_TRUE);
}
static void k_help(void);

struct key {
   int key, shift;        /* GLFW key; 1: with Shift, 0: without, -1: either */
   const char *name, *help;
   void (*fn)(void);
};

static const struct key keys[] = {
   { GLFW_KEY_1, -1, "1", "flat shading (GL_FLAT)", k_flat },
   { GLFW_KEY_2, -1, "2", "smooth shading (Gouraud, GL_SMOOTH)", k_smooth },
   { GLFW_KEY_3, -1, "3", "Phong shading (GL_PHONG_WIN, lit per fragment)", k_phong },
   { GLFW_KEY_4, -1, "4", "Cook-Torrance per fragment (GL_PHONG_WIN + GL_COOK_TORRANCE_FIXGL)", k_ct },
   { GLFW_KEY_M, -1, "m", "toggle the reflectance model Blinn-Phong / Cook-Torrance (per vertex under flat and smooth)", k_model },
   { GLFW_KEY_R, 0, "r", "Cook-Torrance roughness - 0.05", k_rough_dn },
   { GLFW_KEY_R, 1, "R", "Cook-Torrance roughness + 0.05", k_rough_up },
   { GLFW_KEY_E, 0, "e", "Cook-Torrance metalness - 0.1", k_metal_dn },
   { GLFW_KEY_E, 1, "E", "Cook-Torrance metalness + 0.1", k_metal_up },
   { GLFW_KEY_L, -1, "l", "add a light (point, spot, directional in turn; up to 8) and select it", k_add_light },
   { GLFW_KEY_F1, -1, "F1", "toggle light 1 (and select it)", k_l1 },
   { GLFW_KEY_F2, -1, "F2", "toggle light 2", k_l2 },
   { GLFW_KEY_F3, -1, "F3", "toggle light 3", k_l3 },
   { GLFW_KEY_F4, -1, "F4", "toggle light 4", k_l4 },
   { GLFW_KEY_F5, -1, "F5", "toggle light 5", k_l5 },
   { GLFW_KEY_F6, -1, "F6", "toggle light 6", k_l6 },
   { GLFW_KEY_F7, -1, "F7", "toggle light 7", k_l7 },
   { GLFW_KEY_F8, -1, "F8", "toggle light 8", k_l8 },
   { GLFW_KEY_TAB, -1, "Tab", "select the next light", k_next_light },
   { GLFW_KEY_LEFT, -1, "Left", "move the selected light left (azimuth - 10 degrees)", k_light_left },
   { GLFW_KEY_RIGHT, -1, "Right", "move the selected light right (azimuth + 10 degrees)", k_light_right },
   { GLFW_KEY_UP, -1, "Up", "move the selected light up (elevation + 10 degrees)", k_light_up },
   { GLFW_KEY_DOWN, -1, "Down", "move the selected light down (elevation - 10 degrees)", k_light_down },
   { GLFW_KEY_PAGE_UP, -1, "PageUp", "move the selected point/spot light closer", k_light_near },
   { GLFW_KEY_PAGE_DOWN, -1, "PageDown", "move the selected point/spot light away", k_light_far },
   { GLFW_KEY_W, -1, "w", "toggle wireframe (glPolygonMode GL_LINE)", k_wireframe },
   { GLFW_KEY_C, -1, "c", "toggle back-face culling", k_cull },
   { GLFW_KEY_S, -1, "s", "toggle the split view: fixgl | OSMesa | difference", k_split },
   { GLFW_KEY_EQUAL, -1, "+", "zoom in", k_zoom_in },
   { GLFW_KEY_KP_ADD, -1, "+", NULL, k_zoom_in },
   { GLFW_KEY_MINUS, -1, "-", "zoom out", k_zoom_out },
   { GLFW_KEY_KP_SUBTRACT, -1, "-", NULL, k_zoom_out },
   { GLFW_KEY_HOME, -1, "Home", "reset the view", k_reset },
   { GLFW_KEY_X, -1, "x", "screenshot: fixgl-view-NNN.png (what the window shows)", k_screenshot },
   { GLFW_KEY_H, -1, "h", "print this help", k_help },
   { GLFW_KEY_Q, -1, "q", "quit", k_quit },
   { GLFW_KEY_ESCAPE, -1, "Esc", "quit", k_quit },
};

static void print_keys(FILE *f)
{
   fprintf(f, "Mouse:\n"
              "  left drag      orbit the model\n"
              "  right drag     move the selected light\n"
              "  wheel          zoom\n"
              "Keys:\n");
   for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
      if (keys[i].help)
         fprintf(f, "  %-14s %s\n", keys[i].name, keys[i].help);
}

static void k_help(void)
{
   print_keys(stdout);
}

/* --keys: the names of the key table and the mouse actions drag:DX:DY,
 * rdrag:DX:DY and wheel:N, comma-separated. */
static void parse_keys(const char *list)
{
   char *copy = strdup(list), *save = NULL;
   for (char *t = strtok_r(copy, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
      struct scripted *sc = &A.script[A.num_script];
      size_t i = 0;
      while (i < sizeof keys / sizeof keys[0] && strcmp(keys[i].name, t))
         i++;
      char tail;
      int ok = A.num_script < 256;
      if (i < sizeof keys / sizeof keys[0]) {
         sc->key = (int)i;
      } else if (sscanf(t, "drag:%f:%f%c", &sc->dx, &sc->dy, &tail) == 2) {
         sc->key = -1, sc->button = 0;
      } else if (sscanf(t, "rdrag:%f:%f%c", &sc->dx, &sc->dy, &tail) == 2) {
         sc->key = -1, sc->button = 1;
      } else if (sscanf(t, "wheel:%f%c", &sc->dy, &tail) == 1) {
         sc->key = -1, sc->button = 2;
      } else {
         ok = 0;
      }
      if (!ok) {
         fprintf(stderr, "fixgl-view: --keys: no key or mouse action \"%s\" (see --help)\n", t);
         exit(2);
      }
      A.num_script++;
   }
   free(copy);
}

/* The scripted key or mouse action of this frame, before it is rendered. */
static void scripted_key(int frame)
{
   if (frame >= A.num_script)
      return;
   const struct scripted *sc = &A.script[frame];
   if (sc->key >= 0)
      keys[sc->key].fn();
   else if (sc->button == 2)
      mouse_wheel(sc->dy);
   else
      mouse_drag(sc->button, sc->dx, sc->dy);
}

static void usage(FILE *f)
{
   fprintf(f,
      "usage: fixgl-view [OPTIONS] [MODEL]\n"
      "\n"
      "Shows MODEL (OBJ with MTL, PLY, STL, ... through assimp; default: the\n"
      "bundled teapot) rendered by fixgl in a window.  The bundled models (MODEL\n"
      "also by name, e.g. teapot.obj):\n");
   for (size_t i = 0; i < sizeof bundled_models / sizeof bundled_models[0]; i++)
      fprintf(f, "  %s/%s\n", models_dir(), bundled_models[i]);
   fprintf(f,
      "\n"
      "Options:\n"
      "  --headless            no window (no X needed): render and write --out\n"
      "  --size WxH            frame size (default 800x600; headless 640x480;\n"
      "                        W from %d to %d, H from %d to %d)\n"
      "  --shade MODE          flat, smooth, phong or cook-torrance (default smooth;\n"
      "                        cook-torrance: per fragment, GL_PHONG_WIN)\n"
      "  --reflectance MODEL   blinn-phong or cook-torrance (the model under flat and\n"
      "                        smooth: Cook-Torrance per vertex)\n"
      "  --roughness R         Cook-Torrance roughness in [0, 1] (default 0.35)\n"
      "  --metalness M         Cook-Torrance metalness in [0, 1] (default 0)\n"
      "  --yaw DEG, --pitch DEG, --zoom F\n"
      "                        the camera's orbit (default 30, 20) and zoom (1: the\n"
      "                        model's bounding sphere fills the view)\n"
      "  --spin DEG            turn the model by DEG per frame\n"
      "  --light TYPE[:AZ:EL[:DIST]]\n"
      "                        a light (directional, point or spot) from azimuth AZ,\n"
      "                        elevation EL degrees (eye space), DIST model radii\n"
      "                        away; the first replaces the default light, up to 8\n"
      "  --normals KIND        file (default: the file's normals, generated smooth\n"
      "                        where it has none), smooth (all generated, averaged\n"
      "                        around each position) or flat (one per face)\n"
      "  --wireframe           glPolygonMode(GL_LINE)\n"
      "  --cull                back-face culling\n"
      "  --split               fixgl | OSMesa | difference side by side\n"
      "  --renderer NAME       fixgl (default) or osmesa: which one renders --out\n"
      "                        when not split\n"
      "  --out FILE.png        headless: the last frame; window: a screenshot of\n"
      "                        the last frame of --frames\n"
      "  --osmesa-out FILE.png headless: the same view rendered by OSMesa in the\n"
      "                        same process\n"
      "  --frames N            headless: render N frames (default 1) and print the\n"
      "                        frame time; window: quit after N frames; a progress\n"
      "                        bar on stdout when it is a terminal\n"
      "  --screenshot FILE     window: after --frames, the window's frame read back\n"
      "                        through the system GL\n"
      "  --screenshot-x11 FILE window: after --frames, the window as the X server\n"
      "                        shows it\n"
      "  --keys LIST           press these keys (names as below) and mouse actions\n"
      "                        (drag:DX:DY, rdrag:DX:DY in pixels, wheel:N),\n"
      "                        comma-separated, one per frame from the first\n"
      "  --info                print the model, the renderers and their extensions\n"
      "  --version             the versions of fixgl and of the oracle, Mesa\n"
      "  --help                this help\n"
      "\n"
      "The OSMesa side (split view) loads libOSMesa at run time (environment\n"
      "FIXGL_VIEW_OSMESA: another file, or none); Phong and Cook-Torrance are drawn\n"
      "there by the conformance suite's GLSL reference of include/fixgl/shading.md.\n"
      "\n"
      "Models: OBJ map_Kd (or map_Ka) and map_d textures (relative to the .mtl,\n"
      "read with OpenImageIO; one that cannot be read is a warning, the model drawn\n"
      "untextured) are drawn mipmapped with GL_MODULATE; per-vertex colours (PLY,\n"
      "OBJ) through GL_COLOR_MATERIAL.  A model without faces, or with NaN or\n"
      "infinite vertex coordinates, is refused (exit status 1).\n"
      "\n"
      "The bundled models' directory: FIXGL_VIEW_MODELS, else %s when installed\n"
      "there, else %s or models/ beside fixgl-view.\n"
      "\n",
      FV_MIN_WIDTH, FV_MAX_SIZE, FV_MIN_HEIGHT, FV_MAX_SIZE, FV_MODELS_DIR, FV_MODELS_REL);
   print_keys(f);
}

/* ---- options -------------------------------------------------------------- */

static int parse_light(const char *v, struct fv_light *l)
{
   char type[32];
   float az = -35.0f, el = 35.0f, dist = 2.5f;
   int n = sscanf(v, "%31[a-z]:%f:%f:%f", type, &az, &el, &dist);
   if (n < 1 || n == 2)
      return -1;
   if (!strcmp(type, "directional"))
      l->type = FV_DIRECTIONAL;
   else if (!strcmp(type, "point"))
      l->type = FV_POINT;
   else if (!strcmp(type, "spot"))
      l->type = FV_SPOT;
   else
      return -1;
   l->on = 1;
   l->azimuth = az, l->elevation = el, l->distance = dist;
   return 0;
}

static float parse_float(const char *opt, const char *v, float lo, float hi)
{
   char *end;
   errno = 0;
   float f = strtof(v, &end);
   if (errno || end == v || *end || !(f >= lo && f <= hi)) {
      fprintf(stderr, "fixgl-view: %s: bad value \"%s\" (%g..%g)\n", opt, v, lo, hi);
      exit(2);
   }
   return f;
}

/* The long options: `--opt value` and `--opt=value` alike (getopt_long). */
enum {
   OPT_HEADLESS = 256, OPT_SPLIT, OPT_WIREFRAME, OPT_CULL, OPT_INFO, OPT_VERSION, OPT_SIZE,
   OPT_SHADE, OPT_REFLECTANCE, OPT_ROUGHNESS, OPT_METALNESS, OPT_YAW, OPT_PITCH, OPT_ZOOM,
   OPT_SPIN, OPT_LIGHT, OPT_RENDERER, OPT_OUT, OPT_OSMESA_OUT, OPT_FRAMES, OPT_SCREENSHOT,
   OPT_SCREENSHOT_X11, OPT_KEYS, OPT_NORMALS,
};
static const struct option long_options[] = {
   { "help", no_argument, NULL, 'h' },
   { "version", no_argument, NULL, OPT_VERSION },
   { "headless", no_argument, NULL, OPT_HEADLESS },
   { "split", no_argument, NULL, OPT_SPLIT },
   { "wireframe", no_argument, NULL, OPT_WIREFRAME },
   { "cull", no_argument, NULL, OPT_CULL },
   { "info", no_argument, NULL, OPT_INFO },
   { "size", required_argument, NULL, OPT_SIZE },
   { "shade", required_argument, NULL, OPT_SHADE },
   { "reflectance", required_argument, NULL, OPT_REFLECTANCE },
   { "roughness", required_argument, NULL, OPT_ROUGHNESS },
   { "metalness", required_argument, NULL, OPT_METALNESS },
   { "yaw", required_argument, NULL, OPT_YAW },
   { "pitch", required_argument, NULL, OPT_PITCH },
   { "zoom", required_argument, NULL, OPT_ZOOM },
   { "spin", required_argument, NULL, OPT_SPIN },
   { "light", required_argument, NULL, OPT_LIGHT },
   { "renderer", required_argument, NULL, OPT_RENDERER },
   { "out", required_argument, NULL, OPT_OUT },
   { "osmesa-out", required_argument, NULL, OPT_OSMESA_OUT },
   { "frames", required_argument, NULL, OPT_FRAMES },
   { "screenshot", required_argument, NULL, OPT_SCREENSHOT },
   { "screenshot-x11", required_argument, NULL, OPT_SCREENSHOT_X11 },
   { "keys", required_argument, NULL, OPT_KEYS },
   { "normals", required_argument, NULL, OPT_NORMALS },
   { NULL, 0, NULL, 0 },
};

static void parse_options(int argc, char **argv, struct fv_scene *sc, struct fv_light *lights,
                          int *num_lights)
{
   int ch, opt_index = -1;
   opterr = 0;
   while ((ch = getopt_long(argc, argv, ":h", long_options, &opt_index)) != -1) {
      const char *v = optarg;
      /* the option's name, for messages */
      char a[32];
      snprintf(a, sizeof a, "--%s", opt_index >= 0 ? long_options[opt_index].name : "?");
      opt_index = -1;
      switch (ch) {
      case 'h':
         usage(stdout);
         exit(0);
      case OPT_VERSION:
         puts(FIXGL_VERSION_BANNER("fixgl-view"));
         exit(0);
      case OPT_HEADLESS: A.headless = 1; break;
      case OPT_SPLIT: A.split = 1; break;
      case OPT_WIREFRAME: sc->wireframe = 1; break;
      case OPT_CULL: sc->cull = 1; break;
      case OPT_INFO: A.info = 1; break;
      case ':':
         fprintf(stderr, "fixgl-view: %s needs a value (see --help)\n", argv[optind - 1]);
         exit(2);
      case '?':
         fprintf(stderr, "fixgl-view: unknown option %s (see --help)\n", argv[optind - 1]);
         exit(2);
      case OPT_SIZE: {
         char tail;
         if (sscanf(v, "%dx%d%c", &A.width, &A.height, &tail) != 2 || A.width < FV_MIN_WIDTH ||
             A.height < FV_MIN_HEIGHT || A.width > FV_MAX_SIZE || A.height > FV_MAX_SIZE) {
            fprintf(stderr, "fixgl-view: --size: bad size \"%s\": WxH, W from %d to %d "
                            "(the split view's three panels), H from %d to %d\n",
                    v, FV_MIN_WIDTH, FV_MAX_SIZE, FV_MIN_HEIGHT, FV_MAX_SIZE);
            exit(2);
         }
         break;
      }
      case OPT_NORMALS:
         if (!strcmp(v, "file")) A.normals = FV_NORMALS_FILE;
         else if (!strcmp(v, "smooth")) A.normals = FV_NORMALS_SMOOTH;
         else if (!strcmp(v, "flat")) A.normals = FV_NORMALS_FLAT;
         else {
            fprintf(stderr, "fixgl-view: --normals: file, smooth or flat, not \"%s\"\n", v);
            exit(2);
         }
         break;
      case OPT_SHADE:
         if (!strcmp(v, "flat")) sc->shade = FV_FLAT, sc->cook_torrance = 0;
         else if (!strcmp(v, "smooth") || !strcmp(v, "gouraud")) sc->shade = FV_SMOOTH, sc->cook_torrance = 0;
         else if (!strcmp(v, "phong")) sc->shade = FV_PHONG, sc->cook_torrance = 0;
         else if (!strcmp(v, "cook-torrance")) sc->shade = FV_PHONG, sc->cook_torrance = 1;
         else {
            fprintf(stderr, "fixgl-view: --shade: flat, smooth, phong or cook-torrance, not \"%s\"\n", v);
            exit(2);
         }
         break;
      case OPT_REFLECTANCE:
         if (!strcmp(v, "blinn-phong")) sc->cook_torrance = 0;
         else if (!strcmp(v, "cook-torrance")) sc->cook_torrance = 1;
         else {
            fprintf(stderr, "fixgl-view: --reflectance: blinn-phong or cook-torrance, not \"%s\"\n", v);
            exit(2);
         }
         break;
      case OPT_ROUGHNESS:
         sc->roughness = parse_float(a, v, 0.0f, 1.0f);
         break;
      case OPT_METALNESS:
         sc->metalness = parse_float(a, v, 0.0f, 1.0f);
         break;
      case OPT_YAW:
         sc->yaw = parse_float(a, v, -3600.0f, 3600.0f);
         break;
      case OPT_PITCH:
         sc->pitch = parse_float(a, v, -90.0f, 90.0f);
         break;
      case OPT_ZOOM:
         sc->zoom = parse_float(a, v, 0.05f, 20.0f);
         break;
      case OPT_SPIN:
         A.spin = parse_float(a, v, -360.0f, 360.0f);
         break;
      case OPT_LIGHT:
         if (*num_lights >= FV_MAX_LIGHTS || parse_light(v, &lights[*num_lights]) != 0) {
            fprintf(stderr, "fixgl-view: --light: bad light \"%s\" (TYPE[:AZ:EL[:DIST]], up to %d)\n",
                    v, FV_MAX_LIGHTS);
            exit(2);
         }
         ++*num_lights;
         break;
      case OPT_RENDERER:
         if (!strcmp(v, "fixgl")) A.renderer_osmesa = 0;
         else if (!strcmp(v, "osmesa")) A.renderer_osmesa = 1;
         else {
            fprintf(stderr, "fixgl-view: --renderer: fixgl or osmesa, not \"%s\"\n", v);
            exit(2);
         }
         break;
      case OPT_OUT:
         A.out = v;
         break;
      case OPT_OSMESA_OUT:
         A.osmesa_out = v;
         break;
      case OPT_FRAMES:
         A.frames = (int)parse_float(a, v, 1.0f, 1e6f);
         break;
      case OPT_SCREENSHOT:
         A.screenshot = v;
         break;
      case OPT_SCREENSHOT_X11:
         A.screenshot_x11 = v;
         break;
      case OPT_KEYS:
         A.key_list = v;
         break;
      default:
         fprintf(stderr, "fixgl-view: unknown option %s (see --help)\n", a);
         exit(2);
      }
   }
   for (int i = optind; i < argc; i++) {
      if (A.model_path) {
         fprintf(stderr, "fixgl-view: one model only (%s, %s)\n", A.model_path, argv[i]);
         exit(2);
      }
      A.model_path = argv[i];
   }
}

/* ---- progress ------------------------------------------------------------- */

/* --frames N: a one-line bar on stdout when it is a terminal (redrawn in
 * place with \r after each frame, the line ended after the last); nothing
 * when stdout is a file or a pipe. */
static void progress(int done, int total)
{
   static int tty = -1;
   if (tty < 0)
      tty = isatty(STDOUT_FILENO);
   if (!tty || total < 2 || done < 1 || done > total)
      return;
   enum { WIDTH = 40 };
   const int fill = (int)((long)WIDTH * done / total);
   char bar[WIDTH + 1];
   memset(bar, '#', (size_t)fill);
   memset(bar + fill, '.', (size_t)(WIDTH - fill));
   bar[WIDTH] = '\0';
   printf("\rfixgl-view: [%s] %d/%d frames%s", bar, done, total, done == total ? "\n" : "");
   fflush(stdout);
}

/* ---- headless --------------------------------------------------------------- */

static int run_headless(void)
{
   int frames = A.frames > 0 ? A.frames : 1;
   if (frames < A.num_script)
      frames = A.num_script;
   double total = 0.0;
   for (int f = 0; f < frames && !A.quit; f++) {
      if (f > 0)
         A.scene.yaw += A.spin;
      scripted_key(f);
      if (A.renderer_osmesa && !A.split) {
         frame_size(&A.shown, A.width, A.height);
         render_osmesa(A.width, A.height);
         if (A.osmesa_status != OSM_OK) {
            fprintf(stderr, "fixgl-view: --renderer osmesa: %s\n", osmesa_note());
            return 1;
         }
         memcpy(A.shown.rgba, A.osmesa_frame.rgba, (size_t)A.width * A.height * 4);
         total += A.osmesa_ms;
      } else {
         render(A.width, A.height);
         total += A.fixgl_ms;
      }
      progress(f + 1, frames);
   }
   char line[1024];
   status_line(line, sizeof line);
   printf("%s\n", line);
   if (frames > 1)
      printf("fixgl-view: %d frames of %dx%d, %.2f ms per frame (%s)\n", frames, A.width,
             A.height, total / frames, A.renderer_osmesa && !A.split ? "OSMesa" : "fixgl");
   if (!A.renderer_osmesa && fixgl_note())
      fprintf(stderr, "fixgl-view: warning: %s\n", fixgl_note());
   if (A.out)
      write_png(A.out, &A.shown);
   if (A.osmesa_out) {
      /* the same view, the same size, OSMesa in this process */
      int w = A.shown.w, h = A.shown.h;
      if (A.split)
         fprintf(stderr, "fixgl-view: --osmesa-out with --split: the OSMesa panel\n");
      else
         render_osmesa(w, h);
      if (A.osmesa_status != OSM_OK) {
         fprintf(stderr, "fixgl-view: --osmesa-out: %s\n", osmesa_note());
         return 1;
      }
      write_png(A.osmesa_out, &A.osmesa_frame);
   }
   return 0;
}

/* ---- the window ------------------------------------------------------------ */

static void cb_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
   (void)w, (void)scancode;
   if (action == GLFW_RELEASE)
      return;
   int shift = (mods & GLFW_MOD_SHIFT) != 0;
   /* '+' is Shift+'=' on most layouts */
   for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
      if (keys[i].key == key && (keys[i].shift < 0 || keys[i].shift == shift)) {
         keys[i].fn();
         A.dirty = 1;
         return;
      }
   }
}

static void cb_mouse(GLFWwindow *w, int button, int action, int mods)
{
   (void)mods;
   if (action == GLFW_PRESS && (button == GLFW_MOUSE_BUTTON_LEFT || button == GLFW_MOUSE_BUTTON_RIGHT)) {
      A.dragging = 1;
      A.drag_button = button;
      glfwGetCursorPos(w, &A.drag_x, &A.drag_y);
   } else if (action == GLFW_RELEASE && button == A.drag_button) {
      A.dragging = 0;
   }
}

static void cb_cursor(GLFWwindow *w, double x, double y)
{
   (void)w;
   if (!A.dragging)
      return;
   float dx = (float)(x - A.drag_x), dy = (float)(y - A.drag_y);
   A.drag_x = x, A.drag_y = y;
   mouse_drag(A.drag_button != GLFW_MOUSE_BUTTON_LEFT, dx, dy);
}

static void mouse_drag(int right, float dx, float dy)
{
   if (!right) {
      A.scene.yaw += 0.4f * dx;
      A.scene.pitch = fmaxf(-90.0f, fminf(90.0f, A.scene.pitch + 0.4f * dy));
   } else {
      sel()->azimuth += 0.4f * dx;
      sel()->elevation = fmaxf(-89.0f, fminf(89.0f, sel()->elevation - 0.4f * dy));
   }
   A.dirty = 1;
}

static void mouse_wheel(float steps)
{
   A.scene.zoom = fmaxf(0.05f, fminf(20.0f, A.scene.zoom * powf(1.1f, steps)));
   A.dirty = 1;
}

static void cb_scroll(GLFWwindow *w, double dx, double dy)
{
   (void)w, (void)dx;
   mouse_wheel((float)dy);
}

static void cb_refresh(GLFWwindow *w)
{
   (void)w;
   A.dirty = 1;
}

static void present(int fw, int fh)
{
   /* Mesa's OSMesa and the window's GLX context share libglapi's current
    * dispatch: after an OSMesa frame, make the window's context current
    * again (through no context, so that GLX really rebinds it). */
   if (A.split) {
      glfwMakeContextCurrent(NULL);
      glfwMakeContextCurrent(A.win);
   }
   fv_present_frame(A.present, A.shown.rgba, A.shown.w, A.shown.h, fw, fh);
}

static void window_screenshots(int fw, int fh)
{
   unsigned char *px = malloc((size_t)fw * fh * 4);
   if (!px)
      die("out of memory for the %s", "screenshot");
   /* the frame presented again into the back buffer, read back through
    * the system GL, then shown (as libfixglut's FIXGLUT_SCREENSHOT) */
   present(fw, fh);
   fv_present_read(A.present, 0, fw, fh, px);
   glfwSwapBuffers(A.win);
   if (A.screenshot && fv_png_write(A.screenshot, fw, fh, px, 1) != 0)
      die("cannot write %s", A.screenshot);
   if (A.screenshot_x11) {
      fv_present_finish(A.present);
      int ww, wh;
      glfwGetWindowSize(A.win, &ww, &wh);
      unsigned char *xp = malloc((size_t)ww * wh * 4);
      if (!xp || fv_grab_window(A.win, ww, wh, xp) != 0 ||
          fv_png_write(A.screenshot_x11, ww, wh, xp, 1) != 0)
         die("cannot write the window's X11 image to %s", A.screenshot_x11);
      free(xp);
   }
   free(px);
}

static int run_window(void)
{
   if (!glfwInit())
      die("cannot initialise GLFW (no display? try %s)", "--headless");
   glfwDefaultWindowHints();
   glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
   glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
   glfwWindowHint(GLFW_RED_BITS, 8);
   glfwWindowHint(GLFW_GREEN_BITS, 8);
   glfwWindowHint(GLFW_BLUE_BITS, 8);
   glfwWindowHint(GLFW_DEPTH_BITS, 0);
   glfwWindowHint(GLFW_STENCIL_BITS, 0);
   glfwWindowHint(GLFW_SAMPLES, 0);
   A.win = glfwCreateWindow(A.width, A.height, "fixgl-view", NULL, NULL);
   if (!A.win) {
      glfwTerminate();
      die("cannot create the window (no display? try %s)", "--headless");
   }
   glfwMakeContextCurrent(A.win);
   glfwSwapInterval(0);
   A.present = fv_present_create();
   if (!A.present)
      die("the system GL cannot present %s", "frames");
   glfwSetKeyCallback(A.win, cb_key);
   glfwSetMouseButtonCallback(A.win, cb_mouse);
   glfwSetCursorPosCallback(A.win, cb_cursor);
   glfwSetScrollCallback(A.win, cb_scroll);
   glfwSetWindowRefreshCallback(A.win, cb_refresh);

   A.dirty = 1;
   int frame = 0;
   while (!glfwWindowShouldClose(A.win)) {
      if (A.frames > 0 || A.spin != 0.0f)
         glfwPollEvents();
      else
         glfwWaitEventsTimeout(0.5);
      int fw, fh;
      glfwGetFramebufferSize(A.win, &fw, &fh);
      if (fw <= 0 || fh <= 0)
         continue;
      if (fw != A.shown.w || fh != A.shown.h)
         A.dirty = 1;
      if (A.spin != 0.0f && frame > 0) {
         A.scene.yaw += A.spin;
         A.dirty = 1;
      }
      if (frame < A.num_script) {
         scripted_key(frame);
         A.dirty = 1;
      }
      if (glfwWindowShouldClose(A.win))
         break;
      if (!A.dirty && A.frames == 0)
         continue;
      A.dirty = 0;
      render(fw, fh);
      char title[1024];
      status_line(title, sizeof title);
      glfwSetWindowTitle(A.win, title);
      frame++;
      if (A.frames > 0)
         progress(frame, A.frames > A.num_script ? A.frames : A.num_script);
      if (A.frames > 0 && frame >= A.frames && frame >= A.num_script) {
         if (A.screenshot || A.screenshot_x11)
            window_screenshots(fw, fh);
         else {
            present(fw, fh);
            glfwSwapBuffers(A.win);
         }
         if (A.out)
            write_png(A.out, &A.shown);
         break;
      }
      present(fw, fh);
      glfwSwapBuffers(A.win);
   }
   fv_present_destroy(A.present);
   glfwDestroyWindow(A.win);
   glfwTerminate();
   return 0;
}

/* ---- main --------------------------------------------------------------------- */

static void print_info(void)
{
   int coloured = 0;
   for (int i = 0; i < A.model.num_meshes; i++)
      coloured += A.model.meshes[i].col != NULL;
   printf("model: %s: %d meshes (%d with per-vertex colours), %d textures, %u triangles, "
          "bounding sphere centre (%g, %g, %g) radius %g\n",
          A.model_path, A.model.num_meshes, coloured, A.model.num_textures, A.model.num_tris,
          A.model.center[0],
          A.model.center[1], A.model.center[2], A.model.radius);
   printf("fixgl: %s, %s; GL_WIN_phong_shading %s, GL_FIXGL_cook_torrance %s\n",
          (const char *)A.gl.GetString(GL_RENDERER), (const char *)A.gl.GetString(GL_VERSION),
          A.fixgl_phong ? "yes" : "no", A.fixgl_ct ? "yes" : "no");
   open_osmesa();
   if (!A.osmesa) {
      printf("osmesa: none (%s)\n", A.osmesa_why);
      return;
   }
   frame_size(&A.osmesa_frame, 4, 4);
   fv_osmesa_begin(A.osmesa, A.osmesa_frame.rgba, 4, 4);
   const struct fv_gl *gl = fv_osmesa_gl(A.osmesa);
   int ref = 0;
#ifdef FV_HAVE_FCR
   if (!A.ref)
      A.ref = fcr_create((fcr_getproc)fv_osmesa_getproc);
   ref = A.ref != NULL;
#endif
   printf("osmesa: %s (%s), %s; GLSL reference %s\n", (const char *)gl->GetString(GL_RENDERER),
          fv_osmesa_path(A.osmesa), (const char *)gl->GetString(GL_VERSION),
          ref ? "yes" : "no");
}

int main(int argc, char **argv)
{
   struct fv_light lights[FV_MAX_LIGHTS];
   int num_lights = 0;
   struct fv_scene opts;
   fv_scene_init(&opts, NULL);
   parse_options(argc, argv, &opts, lights, &num_lights);
   A.model_path = model_path(A.model_path);
   if (A.key_list)
      parse_keys(A.key_list);
   if (!A.width)
      A.width = A.headless ? 640 : 800, A.height = A.headless ? 480 : 600;
   if (A.headless && (A.screenshot || A.screenshot_x11)) {
      fprintf(stderr, "fixgl-view: --screenshot needs a window (use --out when headless)\n");
      return 2;
   }

   if (fv_model_load(&A.model, A.model_path, A.normals) != 0)
      return 1;
   A.scene = opts;
   A.scene.model = &A.model;
   for (int i = 0; i < num_lights; i++) {
      A.scene.lights[i] = lights[i];
      if (i == 0)
         memcpy(A.scene.lights[0].color, (float[3]){ 1.0f, 1.0f, 1.0f }, sizeof(float[3]));
      else {
         static const float c[3][3] = { { 1.0f, 0.75f, 0.5f }, { 0.45f, 0.65f, 1.0f },
                                        { 0.5f, 1.0f, 0.55f } };
         memcpy(A.scene.lights[i].color, c[(i - 1) % 3], sizeof c[0]);
      }
   }
   if (num_lights)
      A.scene.num_lights = num_lights;

   A.ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
   if (!A.ctx)
      die("cannot create %s's context", "fixgl");
   fv_gl_fixgl(&A.gl);
   frame_size(&A.fixgl_frame, 4, 4);
   OSMesaMakeCurrent(A.ctx, A.fixgl_frame.rgba, GL_UNSIGNED_BYTE, 4, 4);
   A.fixgl_phong = fv_gl_has_extension(&A.gl, "GL_WIN_phong_shading");
   A.fixgl_ct = fv_gl_has_extension(&A.gl, "GL_FIXGL_cook_torrance");
   A.fixgl_tex = calloc((size_t)A.model.num_textures + 1, sizeof *A.fixgl_tex);
   if (!A.fixgl_tex)
      die("out of memory for %s's textures", "fixgl");
   fv_scene_upload_textures(&A.model, &A.gl, A.fixgl_tex);

   int rc;
   if (A.info) {
      print_info();
      rc = 0;
   } else {
      rc = A.headless ? run_headless() : run_window();
   }
#ifdef FV_HAVE_FCR
   if (A.ref) {
      fv_osmesa_begin(A.osmesa, A.osmesa_frame.rgba, A.osmesa_frame.w, A.osmesa_frame.h);
      fcr_destroy(A.ref);
   }
#endif
   fv_osmesa_close(A.osmesa);
   OSMesaDestroyContext(A.ctx);
   fv_model_free(&A.model);
   free(A.fixgl_frame.rgba);
   free(A.osmesa_frame.rgba);
   free(A.fixgl_tex);
   free(A.osmesa_tex);
   free(A.shown.rgba);
   return rc;
}
