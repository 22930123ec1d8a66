/*
 * view-test: the tests of fixgl-view (suite `viewer`).  Each command runs
 * the viewer as a child process and checks what it wrote.
 *
 * Every command writes into DIR (emptied first): the viewer's output,
 * its stdout/stderr (NAME.out, NAME.err) and diff images.
 *
 *   view-test help VIEW DIR
 *       --help exits 0 and lists every option and key (the lists below:
 *       the viewer's documented interface)
 *   view-test errors VIEW DIR MODEL
 *       a missing model, a model that is not one, bad options: a clear
 *       message naming the problem, exit status 1 (model) or 2 (usage), no
 *       output file; without OSMesa (FIXGL_VIEW_OSMESA=none) --osmesa-out
 *       fails saying so and the split view still renders
 *   view-test info VIEW DIR MODEL
 *       the OSMesa side really is Mesa (its GL_RENDERER names llvmpipe) and
 *       the fixgl side is fixgl
 *   view-test render VIEW DIR MODEL [VIEWER ARGS...]
 *       a headless frame of fixgl and the same view rendered by the OSMesa
 *       side in the same process (--osmesa-out): bit-exact, or within 1 LSB
 *       per channel for Phong and Cook-Torrance (GLSL reference); and the
 *       frame's properties: the model is framed (the border is background),
 *       covers a good part of the frame, and is shaded (many colours).
 *       Fails, saying which, when the mode needs what the build lacks
 *       (fixgl's extension, the GLSL reference).
 *   view-test differ VIEW DIR MODEL ARGS_A -- ARGS_B
 *       two views that must differ (e.g. flat vs smooth)
 *   view-test same VIEW DIR MODEL ARGS_A -- ARGS_B
 *       two ways to the same view (e.g. scripted keys vs options): bit for
 *       bit the same frame
 *   view-test frames VIEW DIR MODEL
 *       --frames 4 --spin 15 ends on the frame a single render at yaw
 *       30 + 45 gives, bit for bit
 *   view-test colourful VIEW DIR MODEL [VIEWER ARGS...]
 *       the headless frame shows several hues (a texture's or per-vertex
 *       colours, not one material's shades)
 *   view-test bad VIEW DIR MODELS
 *       bad models (written here): NaN and infinite coordinates, no faces,
 *       lines only: a message saying what and how many, exit status 1, no
 *       output; a missing and an unreadable texture (MODELS/globe.obj
 *       copied without its images): a warning naming it, exit status 0, the
 *       frame drawn untextured; --size and --normals out of bounds: the
 *       limits stated, exit status 2
 *   view-test progress VIEW DIR MODEL
 *       --frames 6 on a terminal (a pseudo-terminal) draws a one-line
 *       progress bar; piped, stdout has no trace of it
 *   view-test window VIEW DIR XVFB MODEL [VIEWER ARGS...]
 *       the viewer in a real GLFW window on an Xvfb server started on a free
 *       display: after 3 frames the window read back through the system GL
 *       and as the X server shows it both equal the headless frame (RGB)
 */
#include <errno.h>
#include <fcntl.h>
#include <pty.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "fv_png.h"
#include "fv_xvfb.h"

static const char *view, *dir;

static void die(const char *fmt, ...)
{
   va_list ap;
   fputs("view-test: ", stderr);
   va_start(ap, fmt);
   vfprintf(stderr, fmt, ap);
   va_end(ap);
   fputc('\n', stderr);
   exit(1);
}

static char *path_in(const char *name)
{
   static char bufs[8][4096];
   static int next;
   char *b = bufs[next++ % 8];
   snprintf(b, sizeof bufs[0], "%s/%s", dir, name);
   return b;
}

static char *slurp(const char *path)
{
   FILE *f = fopen(path, "rb");
   if (!f)
      return calloc(1, 1);
   fseek(f, 0, SEEK_END);
   long n = ftell(f);
   fseek(f, 0, SEEK_SET);
   char *s = calloc((size_t)n + 1, 1);
   if (s && fread(s, 1, (size_t)n, f) != (size_t)n)
      s[0] = '\0';
   fclose(f);
   return s;
}

/* Runs the viewer with argv (NULL-terminated, argv[0] ignored), stdout and
 * stderr to DIR/NAME.out and .err, extra environment entries; returns the
 * exit status (-1: killed or timed out). */
static int run_view(const char *name, char *const argv[], char *const env_add[], int timeout_s)
{
   char out[4200], err[4200];
   snprintf(out, sizeof out, "%s/%s.out", dir, name);
   snprintf(err, sizeof err, "%s/%s.err", dir, name);
   printf("$");
   for (int i = 1; argv[i]; i++)
      printf(" %s", argv[i]);
   printf("\n");
   fflush(stdout);
   pid_t pid = fork();
   if (pid < 0)
      die("fork failed");
   if (pid == 0) {
      int o = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
      int e = open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (o < 0 || e < 0)
         _exit(126);
      dup2(o, 1), dup2(e, 2);
      for (int i = 0; env_add && env_add[i]; i++)
         putenv(env_add[i]);
      execv(view, argv);
      fprintf(stderr, "view-test: cannot run %s: %s\n", view, strerror(errno));
      _exit(127);
   }
   int status = 0;
   for (int waited = 0;; waited++) {
      if (waitpid(pid, &status, WNOHANG) == pid)
         break;
      if (waited > timeout_s * 10) {
         kill(pid, SIGKILL);
         waitpid(pid, &status, 0);
         fprintf(stderr, "view-test: %s timed out\n", name);
         return -1;
      }
      usleep(100000);
   }
   char *so = slurp(out), *se = slurp(err);
   fputs(so, stdout);
   fputs(se, stdout);
   free(so), free(se);
   if (WIFEXITED(status))
      return WEXITSTATUS(status);
   fprintf(stderr, "view-test: %s died (signal %d)\n", name, WTERMSIG(status));
   return -1;
}

/* argv builder */
struct args {
   char *v[64];
   int n;
};

static void add(struct args *a, const char *s)
{
   if (a->n >= 62)
      die("too many arguments");
   a->v[a->n++] = (char *)s;
   a->v[a->n] = NULL;
}

static struct args args_of(const char *first)
{
   struct args a = { .n = 0 };
   add(&a, view);
   if (first)
      add(&a, first);
   return a;
}

struct image {
   int w, h;
   unsigned char *px;   /* RGBA8, top row first */
};

static struct image load(const char *path)
{
   struct image im;
   if (fv_png_read(path, &im.w, &im.h, &im.px) != 0)
      die("cannot read %s", path);
   return im;
}

/* Largest channel difference over the first nc channels; counts the
 * pixels at 0, 1 and more; writes a diff image when they differ. */
static int compare(const struct image *a, const struct image *b, int nc, const char *diff_path,
                   long counts[3])
{
   if (a->w != b->w || a->h != b->h)
      die("sizes differ: %dx%d vs %dx%d", a->w, a->h, b->w, b->h);
   int max = 0;
   counts[0] = counts[1] = counts[2] = 0;
   unsigned char *d = malloc((size_t)a->w * a->h * 4);
   for (long i = 0; i < (long)a->w * a->h; i++) {
      int m = 0;
      for (int c = 0; c < nc; c++) {
         int x = abs(a->px[i * 4 + c] - b->px[i * 4 + c]);
         m = x > m ? x : m;
      }
      counts[m == 0 ? 0 : m == 1 ? 1 : 2]++;
      max = m > max ? m : max;
      d[i * 4 + 0] = m ? 255 : a->px[i * 4 + 0] / 4;
      d[i * 4 + 1] = m > 1 ? 0 : m ? 160 : a->px[i * 4 + 1] / 4;
      d[i * 4 + 2] = m ? 0 : a->px[i * 4 + 2] / 4;
      d[i * 4 + 3] = 255;
   }
   if (max && diff_path)
      fv_png_write(diff_path, a->w, a->h, d, 0);
   free(d);
   return max;
}

/* ---- help ------------------------------------------------------------------ */

static const char *const options[] = {
   "--headless", "--size", "--shade", "--reflectance", "--roughness", "--metalness", "--yaw",
   "--pitch", "--zoom", "--spin", "--light", "--wireframe", "--cull", "--split", "--renderer",
   "--out", "--osmesa-out", "--frames", "--screenshot", "--screenshot-x11", "--keys", "--info",
   "--help", "--normals", "map_Kd", "map_d", "GL_COLOR_MATERIAL",
   "flat", "smooth", "phong", "cook-torrance", "blinn-phong", "directional", "point", "spot",
   "FIXGL_VIEW_OSMESA",
};

/* Every key the viewer handles (its key table), with a word of what it does. */
static const char *const keys[][2] = {
   { "1", "flat" }, { "2", "smooth" }, { "3", "Phong" }, { "4", "Cook-Torrance" },
   { "m", "reflectance model" }, { "r", "roughness" }, { "R", "roughness" },
   { "e", "metalness" }, { "E", "metalness" }, { "l", "add a light" },
   { "F1", "light 1" }, { "F2", "light 2" }, { "F3", "light 3" }, { "F4", "light 4" },
   { "F5", "light 5" }, { "F6", "light 6" }, { "F7", "light 7" }, { "F8", "light 8" },
   { "Tab", "next light" }, { "Left", "selected light" }, { "Right", "selected light" },
   { "Up", "selected light" }, { "Down", "selected light" }, { "PageUp", "closer" },
   { "PageDown", "away" }, { "w", "wireframe" }, { "c", "culling" }, { "s", "split view" },
   { "+", "zoom in" }, { "-", "zoom out" }, { "Home", "reset" }, { "x", "screenshot" },
   { "h", "help" }, { "q", "quit" }, { "Esc", "quit" },
   { "left drag", "orbit" }, { "right drag", "light" }, { "wheel", "zoom" },
};

static int cmd_help(void)
{
   struct args a = args_of("--help");
   int rc = run_view("help", a.v, NULL, 30);
   if (rc != 0)
      die("--help exited with %d", rc);
   char *out = slurp(path_in("help.out"));
   int missing = 0;
   for (size_t i = 0; i < sizeof options / sizeof options[0]; i++)
      if (!strstr(out, options[i])) {
         fprintf(stderr, "view-test: --help does not mention %s\n", options[i]);
         missing++;
      }
   /* a key's line: two spaces, the key, spaces, its description */
   for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
      char *line = out;
      int found = 0;
      while ((line = strstr(line, "\n  ")) != NULL) {
         line += 3;
         size_t n = strlen(keys[i][0]);
         const char *eol = strchr(line, '\n');
         if (!strncmp(line, keys[i][0], n) && line[n] == ' ' && eol) {
            char *desc = strndup(line + n, (size_t)(eol - line - (long)n));
            found = desc && strstr(desc, keys[i][1]) != NULL;
            free(desc);
            if (found)
               break;
         }
      }
      if (!found) {
         fprintf(stderr, "view-test: --help lists no key \"%s\" (%s)\n", keys[i][0], keys[i][1]);
         missing++;
      }
   }
   free(out);
   if (missing)
      return 1;
   printf("--help lists %zu options and words, %zu keys and mouse actions\n",
          sizeof options / sizeof options[0], sizeof keys / sizeof keys[0]);
   return 0;
}

/* ---- errors ------------------------------------------------------------------ */

static int expect(const char *name, struct args *a, int status, const char *msg1, const char *msg2)
{
   int rc = run_view(name, a->v, NULL, 30);
   char errp[4200];
   snprintf(errp, sizeof errp, "%s/%s.err", dir, name);
   char *err = slurp(errp);
   int ok = rc == status && strstr(err, msg1) && (!msg2 || strstr(err, msg2));
   if (!ok)
      fprintf(stderr, "view-test: %s: exit %d (expected %d), stderr \"%s\" (expected \"%s\"%s%s)\n",
              name, rc, status, err, msg1, msg2 ? " and " : "", msg2 ? msg2 : "");
   free(err);
   return ok ? 0 : 1;
}

static int cmd_errors(const char *model)
{
   int failed = 0;
   const char *out = path_in("never.png");
   unlink(out);
   const char *missing = path_in("no-such-model.obj");
   struct args a = args_of("--headless");
   add(&a, "--out"), add(&a, out), add(&a, missing);
   failed += expect("missing-model", &a, 1, missing, "cannot open the model");

   const char *bogus = path_in("not-a-model.obj");
   FILE *f = fopen(bogus, "w");
   if (!f)
      die("cannot write %s", bogus);
   fputs("this is not a model\n", f);
   fclose(f);
   a = args_of("--headless");
   add(&a, "--out"), add(&a, out), add(&a, bogus);
   failed += expect("not-a-model", &a, 1, bogus, "cannot load the model");

   a = args_of("--headless");
   add(&a, "--shade"), add(&a, "toon"), add(&a, model);
   failed += expect("bad-shade", &a, 2, "--shade", "toon");
   a = args_of("--headless");
   add(&a, "--size"), add(&a, "big"), add(&a, model);
   failed += expect("bad-size", &a, 2, "--size", "big");
   a = args_of("--headless");
   add(&a, "--roughness"), add(&a, "1.5"), add(&a, model);
   failed += expect("bad-roughness", &a, 2, "--roughness", "1.5");
   a = args_of("--headless");
   add(&a, "--light"), add(&a, "laser"), add(&a, model);
   failed += expect("bad-light", &a, 2, "--light", "laser");
   a = args_of("--bogus-option");
   failed += expect("bad-option", &a, 2, "unknown option", "--bogus-option");
   a = args_of("--headless");
   add(&a, "--screenshot"), add(&a, out), add(&a, model);
   failed += expect("screenshot-headless", &a, 2, "--screenshot needs a window", NULL);

   /* without OSMesa: --osmesa-out fails saying why; the split view is
    * still drawn, its OSMesa and difference panels a note */
   static char no_osmesa[] = "FIXGL_VIEW_OSMESA=none";
   char *env_none[] = { no_osmesa, NULL };
   a = args_of("--headless");
   add(&a, "--osmesa-out"), add(&a, out), add(&a, model);
   int rc = run_view("no-osmesa", a.v, env_none, 30);
   char *err = slurp(path_in("no-osmesa.err"));
   if (rc != 1 || !strstr(err, "--osmesa-out: OSMesa disabled")) {
      fprintf(stderr, "view-test: no-osmesa: exit %d, stderr \"%s\"\n", rc, err);
      failed++;
   }
   free(err);
   const char *split = path_in("split-no-osmesa.png");
   a = args_of("--headless");
   add(&a, "--split"), add(&a, "--size"), add(&a, "240x100"), add(&a, "--out"), add(&a, split);
   add(&a, model);
   rc = run_view("split-no-osmesa", a.v, env_none, 30);
   char *so = slurp(path_in("split-no-osmesa.out"));
   if (rc != 0 || !strstr(so, "OSMesa: OSMesa disabled") || access(split, F_OK) != 0) {
      fprintf(stderr, "view-test: split-no-osmesa: exit %d, stdout \"%s\"\n", rc, so);
      failed++;
   }
   free(so);

   if (access(out, F_OK) == 0) {
      fprintf(stderr, "view-test: a failed run wrote %s\n", out);
      failed++;
   }
   printf("%d of 10 error cases as expected\n", 10 - failed);
   return failed ? 1 : 0;
}

/* ---- info ---------------------------------------------------------------------- */

/* Runs --info; returns its stdout (malloc'd). */
static char *info(const char *model)
{
   struct args a = args_of("--info");
   add(&a, model);
   if (run_view("info", a.v, NULL, 60) != 0)
      die("--info failed");
   return slurp(path_in("info.out"));
}

static int cmd_info(const char *model)
{
   char *s = info(model);
   const char *osm = strstr(s, "\nosmesa: ");
   const char *fx = strstr(s, "\nfixgl: ");
   int ok = 1;
   if (!fx || strncmp(fx, "\nfixgl: fixgl ", 14) != 0) {
      fprintf(stderr, "view-test: the fixgl side's GL_RENDERER is not fixgl's\n");
      ok = 0;
   }
   if (!osm) {
      fprintf(stderr, "view-test: no OSMesa line in --info\n");
      ok = 0;
   } else {
      const char *eol = strchr(osm + 1, '\n');
      char *line = strndup(osm + 1, eol ? (size_t)(eol - osm - 1) : strlen(osm + 1));
      if (!strstr(line, "llvmpipe") || !strstr(line, "Mesa")) {
         fprintf(stderr, "view-test: the OSMesa side is not Mesa's llvmpipe: %s\n", line);
         ok = 0;
      }
      free(line);
   }
   free(s);
   if (ok)
      printf("the OSMesa side is Mesa's llvmpipe, the fixgl side fixgl\n");
   return ok ? 0 : 1;
}

/* ---- render ------------------------------------------------------------------ */

/* The frame's properties: the border is the background (the model framed
 * by its bounding sphere with a margin), the model covers at least 2% of
 * the frame and spans at least 40% of its width or height, and it is shaded
 * (at least 12 distinct colours: a faceted model has few). */
static int properties(const struct image *im)
{
   const unsigned char *bg = im->px;
   long covered = 0;
   int x0 = im->w, x1 = -1, y0 = im->h, y1 = -1, border = 0;
   int ncolors = 0;
   unsigned *colors = malloc(64 * sizeof *colors);
   for (int y = 0; y < im->h; y++)
      for (int x = 0; x < im->w; x++) {
         const unsigned char *p = &im->px[((long)y * im->w + x) * 4];
         if (!memcmp(p, bg, 3))
            continue;
         covered++;
         x0 = x < x0 ? x : x0, x1 = x > x1 ? x : x1;
         y0 = y < y0 ? y : y0, y1 = y > y1 ? y : y1;
         if (x == 0 || y == 0 || x == im->w - 1 || y == im->h - 1)
            border++;
         unsigned c = (unsigned)p[0] << 16 | (unsigned)p[1] << 8 | p[2];
         int seen = 0;
         for (int i = 0; i < ncolors && !seen; i++)
            seen = colors[i] == c;
         if (!seen && ncolors < 64)
            colors[ncolors++] = c;
      }
   free(colors);
   double frac = (double)covered / ((double)im->w * im->h);
   double span_x = (x1 - x0 + 1) / (double)im->w, span_y = (y1 - y0 + 1) / (double)im->h;
   printf("frame %dx%d: model covers %.1f%%, spans %.0f%% x %.0f%%, %s%d colours, %d border pixels\n",
          im->w, im->h, 100.0 * frac, 100.0 * span_x, 100.0 * span_y, ncolors >= 64 ? ">= " : "",
          ncolors, border);
   int ok = 1;
   if (border) {
      fprintf(stderr, "view-test: the model touches the frame's border: not framed\n");
      ok = 0;
   }
   if (frac < 0.02 || (span_x < 0.4 && span_y < 0.4)) {
      fprintf(stderr, "view-test: the model is too small in the frame\n");
      ok = 0;
   }
   if (ncolors < 12) {
      fprintf(stderr, "view-test: only %d colours: not shaded\n", ncolors);
      ok = 0;
   }
   return ok;
}

static int cmd_render(const char *model, int argc, char **argv)
{
   /* what the mode needs */
   int phong = 0, ct = 0;
   for (int i = 0; i + 1 < argc; i++) {
      if (!strcmp(argv[i], "--shade") && !strcmp(argv[i + 1], "phong"))
         phong = 1;
      if (!strcmp(argv[i], "--shade") && !strcmp(argv[i + 1], "cook-torrance"))
         phong = ct = 1;
      if (!strcmp(argv[i], "--reflectance") && !strcmp(argv[i + 1], "cook-torrance"))
         ct = 1;
   }
   if (phong || ct) {
      char *s = info(model);
      const char *why = NULL;
      if (phong && !strstr(s, "GL_WIN_phong_shading yes"))
         why = "libfixgl does not advertise GL_WIN_phong_shading";
      else if (ct && !strstr(s, "GL_FIXGL_cook_torrance yes"))
         why = "libfixgl does not advertise GL_FIXGL_cook_torrance";
      else if (!strstr(s, "GLSL reference yes"))
         why = "the OSMesa side has no GLSL reference (conformance/reference/fcr_shading.c)";
      free(s);
      if (why)
         die("%s", why);
   }
   const int tolerance = phong || ct ? 1 : 0;
   const char *fx = path_in("fixgl.png"), *osm = path_in("osmesa.png");
   unlink(fx), unlink(osm);
   struct args a = args_of("--headless");
   add(&a, "--size"), add(&a, "200x150");
   for (int i = 0; i < argc; i++)
      add(&a, argv[i]);
   add(&a, "--out"), add(&a, fx), add(&a, "--osmesa-out"), add(&a, osm), add(&a, model);
   int rc = run_view("render", a.v, NULL, 120);
   if (rc != 0)
      die("the viewer exited with %d", rc);
   struct image f = load(fx), o = load(osm);
   long counts[3];
   int max = compare(&f, &o, 4, path_in("diff.png"), counts);
   printf("fixgl vs OSMesa (same process): max %d LSB; pixels exact %ld, at 1 LSB %ld, beyond %ld "
          "(allowed: %d)\n", max, counts[0], counts[1], counts[2], tolerance);
   int ok = max <= tolerance;
   if (!ok)
      fprintf(stderr, "view-test: fixgl and OSMesa differ (diff image %s)\n", path_in("diff.png"));
   ok &= properties(&f);
   free(f.px), free(o.px);
   return ok ? 0 : 1;
}

/* ---- differ -------------------------------------------------------------------- */

static int cmd_differ(const char *model, int argc, char **argv, int same)
{
   int sep = 0;
   while (sep < argc && strcmp(argv[sep], "--"))
      sep++;
   if (sep == argc)
      die("differ: ARGS_A -- ARGS_B");
   const char *pa = path_in("a.png"), *pb = path_in("b.png");
   struct args a = args_of("--headless");
   add(&a, "--size"), add(&a, "200x150");
   for (int i = 0; i < sep; i++)
      add(&a, argv[i]);
   add(&a, "--out"), add(&a, pa), add(&a, model);
   struct args b = args_of("--headless");
   add(&b, "--size"), add(&b, "200x150");
   for (int i = sep + 1; i < argc; i++)
      add(&b, argv[i]);
   add(&b, "--out"), add(&b, pb), add(&b, model);
   if (run_view("a", a.v, NULL, 120) != 0 || run_view("b", b.v, NULL, 120) != 0)
      die("the viewer failed");
   struct image ia = load(pa), ib = load(pb);
   long counts[3];
   int max = compare(&ia, &ib, 3, NULL, counts);
   long n = counts[1] + counts[2];
   printf("the two views differ in %ld pixels (max %d)\n", n, max);
   free(ia.px), free(ib.px);
   if (same) {
      if (n)
         fprintf(stderr, "view-test: the two views should be the same\n");
      return n ? 1 : 0;
   }
   if (n < (long)ia.w * ia.h / 100) {
      fprintf(stderr, "view-test: the views should differ in at least 1%% of the pixels\n");
      return 1;
   }
   return 0;
}

/* ---- frames -------------------------------------------------------------------- */

static int cmd_frames(const char *model)
{
   const char *p4 = path_in("spin4.png"), *p1 = path_in("yaw75.png");
   struct args a = args_of("--headless");
   add(&a, "--size"), add(&a, "160x120"), add(&a, "--frames"), add(&a, "4");
   add(&a, "--spin"), add(&a, "15"), add(&a, "--out"), add(&a, p4), add(&a, model);
   struct args b = args_of("--headless");
   add(&b, "--size"), add(&b, "160x120"), add(&b, "--yaw"), add(&b, "75");
   add(&b, "--out"), add(&b, p1), add(&b, model);
   if (run_view("spin4", a.v, NULL, 120) != 0 || run_view("yaw75", b.v, NULL, 120) != 0)
      die("the viewer failed");
   char *out = slurp(path_in("spin4.out"));
   int timed = strstr(out, "4 frames of 160x120") && strstr(out, "ms per frame");
   free(out);
   if (!timed)
      die("--frames 4 printed no frame time");
   struct image ia = load(p4), ib = load(p1);
   long counts[3];
   int max = compare(&ia, &ib, 4, path_in("diff.png"), counts);
   free(ia.px), free(ib.px);
   printf("frame 4 of --spin 15 vs --yaw 75: %s\n", max ? "DIFFERS" : "exact");
   return max ? 1 : 0;
}

/* ---- colourful ------------------------------------------------------------------ */

/* The hue sextant of a pixel with some saturation, or -1. */
static int hue_sextant(const unsigned char *p)
{
   int r = p[0], g = p[1], b = p[2];
   int mx = r > g ? (r > b ? r : b) : (g > b ? g : b), mn = r < g ? (r < b ? r : b) : (g < b ? g : b);
   if (mx - mn < 40)
      return -1;
   double h = mx == r ? (double)(g - b) / (mx - mn) : mx == g ? 2.0 + (double)(b - r) / (mx - mn)
                                                               : 4.0 + (double)(r - g) / (mx - mn);
   if (h < 0.0)
      h += 6.0;
   return (int)h % 6;
}

static int cmd_colourful(const char *model, int argc, char **argv)
{
   const char *fx = path_in("frame.png");
   struct args a = args_of("--headless");
   add(&a, "--size"), add(&a, "200x150");
   for (int i = 0; i < argc; i++)
      add(&a, argv[i]);
   add(&a, "--out"), add(&a, fx), add(&a, model);
   if (run_view("colourful", a.v, NULL, 120) != 0)
      die("the viewer failed");
   struct image im = load(fx);
   long per[6] = { 0 };
   for (long i = 0; i < (long)im.w * im.h; i++) {
      int k = hue_sextant(&im.px[i * 4]);
      if (k >= 0)
         per[k]++;
   }
   int hues = 0;
   for (int k = 0; k < 6; k++)
      hues += per[k] >= 30;
   printf("pixels per hue sextant: %ld %ld %ld %ld %ld %ld; %d hues of 30 pixels or more\n", per[0],
          per[1], per[2], per[3], per[4], per[5], hues);
   free(im.px);
   if (hues < 3) {
      fprintf(stderr, "view-test: fewer than 3 hues: the texture or the colours are not drawn\n");
      return 1;
   }
   return 0;
}

/* ---- bad models ------------------------------------------------------------------ */

static void write_file(const char *path, const char *text)
{
   FILE *f = fopen(path, "w");
   if (!f || fputs(text, f) < 0 || fclose(f) != 0)
      die("cannot write %s", path);
}

static void copy_file(const char *from, const char *to)
{
   char *s = slurp(from);
   if (!s[0])
      die("cannot read %s", from);
   write_file(to, s);
   free(s);
}

/* Runs the viewer headless on model with --out; checks the exit status,
 * that stderr holds every string of msgs (NULL-terminated), and that
 * --out was written exactly when the status is 0. */
static int expect_model(const char *name, const char *model, const char *extra, int status,
                        const char *const *msgs)
{
   char out[4200];
   snprintf(out, sizeof out, "%s/%s.png", dir, name);
   unlink(out);
   struct args a = args_of("--headless");
   add(&a, "--size"), add(&a, "160x120");
   if (extra)
      add(&a, "--normals"), add(&a, extra);
   add(&a, "--out"), add(&a, out), add(&a, model);
   int rc = run_view(name, a.v, NULL, 60);
   char errp[4200];
   snprintf(errp, sizeof errp, "%s/%s.err", dir, name);
   char *err = slurp(errp);
   int ok = rc == status;
   for (int i = 0; msgs[i]; i++)
      if (!strstr(err, msgs[i])) {
         fprintf(stderr, "view-test: %s: stderr lacks \"%s\"\n", name, msgs[i]);
         ok = 0;
      }
   if ((access(out, F_OK) == 0) != (status == 0)) {
      fprintf(stderr, "view-test: %s: --out %s\n", name, status ? "written" : "not written");
      ok = 0;
   }
   if (rc != status)
      fprintf(stderr, "view-test: %s: exit %d, expected %d\n", name, rc, status);
   free(err);
   return ok;
}

static int cmd_bad(const char *models)
{
   int failed = 0, cases = 0;
   char p[4200], q[4200];

   /* NaN and infinite coordinates: two NaN vertices, one infinite, one of
    * them used twice (counted once) */
   snprintf(p, sizeof p, "%s/nan.obj", dir);
   write_file(p, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 1 0\nv 1 nan 1\nv 0 inf 0\n"
                 "f 1 2 3\nf 1 2 4\nf 2 3 5\nf 1 3 6\nf 3 4 5\n");
   static const char *const nan_msgs[] = { "nan.obj", "has 3 vertices with NaN or infinite coordinates",
                                           "(nan, 1, 0)", "inf", NULL };
   failed += !expect_model("nan", p, NULL, 1, nan_msgs), cases++;
   /* flat normals split the vertices: still three */
   failed += !expect_model("nan-flat", p, "flat", 1, nan_msgs), cases++;
   snprintf(p, sizeof p, "%s/inf.ply", dir);
   write_file(p, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                 "end_header\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n");
   static const char *const inf_msgs[] = { "inf.ply", "has 1 vertex with NaN or infinite coordinates",
                                           "(0, -inf, 0)", NULL };
   failed += !expect_model("inf", p, NULL, 1, inf_msgs), cases++;

   /* no faces */
   snprintf(p, sizeof p, "%s/empty.obj", dir);
   write_file(p, "# vertices, no faces\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
   static const char *const empty_msgs[] = { "empty.obj", "is empty: 3 vertices and no faces", NULL };
   failed += !expect_model("empty-obj", p, NULL, 1, empty_msgs), cases++;
   snprintf(p, sizeof p, "%s/empty.ply", dir);
   write_file(p, "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                 "property float z\nelement face 0\nproperty list uchar int vertex_indices\n"
                 "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n");
   static const char *const empty_ply[] = { "empty.ply", "is empty: 4 vertices and no faces", NULL };
   failed += !expect_model("empty-ply", p, NULL, 1, empty_ply), cases++;
   snprintf(p, sizeof p, "%s/lines.obj", dir);
   write_file(p, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n");
   static const char *const lines_msgs[] = { "lines.obj", "is empty", "no triangles", NULL };
   failed += !expect_model("lines-only", p, NULL, 1, lines_msgs), cases++;

   /* textures: the globe without its images, then with garbage for one */
   char src[4200];
   snprintf(src, sizeof src, "%s/globe.obj", models);
   snprintf(p, sizeof p, "%s/globe.obj", dir);
   copy_file(src, p);
   snprintf(src, sizeof src, "%s/globe.mtl", models);
   snprintf(q, sizeof q, "%s/globe.mtl", dir);
   copy_file(src, q);
   static const char *const missing_msgs[] = { "warning", "texture", "globe.png", "drawn untextured",
                                                NULL };
   failed += !expect_model("texture-missing", p, NULL, 0, missing_msgs), cases++;
   snprintf(q, sizeof q, "%s/globe.png", dir);
   write_file(q, "not a PNG\n");
   snprintf(q, sizeof q, "%s/ring_alpha.png", dir);
   snprintf(src, sizeof src, "%s/ring_alpha.png", models);
   struct image ra = load(src);
   fv_png_write(q, ra.w, ra.h, ra.px, 0);
   free(ra.px);
   static const char *const garbage_msgs[] = { "warning", "globe.png", "cannot read", NULL };
   failed += !expect_model("texture-unreadable", p, NULL, 0, garbage_msgs), cases++;
   /* the untextured globe is not the textured one */
   snprintf(src, sizeof src, "%s/globe.obj", models);
   static const char *const none[] = { NULL };
   failed += !expect_model("texture-present", src, NULL, 0, none), cases++;
   struct image t = load(path_in("texture-present.png")), u = load(path_in("texture-missing.png"));
   long counts[3];
   int max = compare(&t, &u, 3, NULL, counts);
   printf("textured vs untextured globe: %ld pixels differ (max %d)\n", counts[1] + counts[2], max);
   if (counts[1] + counts[2] < (long)t.w * t.h / 20) {
      fprintf(stderr, "view-test: the globe without its texture looks textured\n");
      failed++;
   }
   free(t.px), free(u.px), cases++;

   /* --size and --normals: the limits stated */
   static const char *const sizes[] = { "2x100", "9000x100", "100x0", "100x8193", "100x100x3" };
   for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
      struct args a = args_of("--headless");
      add(&a, "--size"), add(&a, sizes[i]), add(&a, src);
      char name[64];
      snprintf(name, sizeof name, "size-%zu", i);
      failed += expect(name, &a, 2, "W from 3 to 8192", "H from 1 to 8192") != 0, cases++;
   }
   struct args a = args_of("--headless");
   add(&a, "--normals"), add(&a, "bent"), add(&a, src);
   failed += expect("normals-bent", &a, 2, "--normals: file, smooth or flat", "bent") != 0, cases++;

   printf("%d of %d bad-model cases as expected\n", cases - failed, cases);
   return failed ? 1 : 0;
}

/* ---- progress ------------------------------------------------------------------ */

static int cmd_progress(const char *model)
{
   struct args a = args_of("--headless");
   add(&a, "--size"), add(&a, "64x48"), add(&a, "--frames"), add(&a, "6"), add(&a, "--spin"),
      add(&a, "10"), add(&a, model);
   /* piped (run_view: stdout a file) */
   if (run_view("piped", a.v, NULL, 60) != 0)
      die("the viewer failed");
   char *out = slurp(path_in("piped.out")), *err = slurp(path_in("piped.err"));
   int ok = 1;
   if (strchr(out, '\r') || strstr(out, "[#") || strstr(out, "/6 frames") || strchr(err, '\r') ||
       strstr(err, "[#")) {
      fprintf(stderr, "view-test: a progress bar while stdout is not a terminal\n");
      ok = 0;
   }
   if (!strstr(out, "6 frames of 64x48")) {
      fprintf(stderr, "view-test: piped: no frame summary\n");
      ok = 0;
   }
   free(out), free(err);

   /* on a pseudo-terminal */
   int master;
   pid_t pid = forkpty(&master, NULL, NULL, NULL);
   if (pid < 0)
      die("forkpty: %s", strerror(errno));
   if (pid == 0) {
      execv(view, a.v);
      _exit(127);
   }
   char buf[65536];
   size_t n = 0;
   for (;;) {
      ssize_t k = read(master, buf + n, sizeof buf - 1 - n);
      if (k <= 0)
         break;   /* EIO once the child has closed the terminal */
      n += (size_t)k;
      if (n >= sizeof buf - 1)
         break;
   }
   buf[n] = '\0';
   close(master);
   int status;
   waitpid(pid, &status, 0);
   if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      die("the viewer on a terminal failed");
   int bars = 0;
   for (const char *s = buf; (s = strstr(s, "\rfixgl-view: [")) != NULL; s++)
      bars++;
   printf("on a terminal: %d redraws of the bar, %s\n", bars,
          strstr(buf, "6/6 frames") ? "the last at 6/6" : "never at 6/6");
   if (bars != 6 || !strstr(buf, "] 1/6 frames") || !strstr(buf, "[########################################] 6/6 frames")) {
      fprintf(stderr, "view-test: no one-line progress bar on a terminal: \"%s\"\n", buf);
      ok = 0;
   }
   if (ok)
      printf("progress bar on a terminal only\n");
   return ok ? 0 : 1;
}

/* ---- window -------------------------------------------------------------------- */

static int cmd_window(const char *xvfb, const char *model, int argc, char **argv)
{
   const char *head = path_in("headless.png"), *shot = path_in("screenshot.png"),
              *x11 = path_in("x11.png");
   unlink(head), unlink(shot), unlink(x11);
   struct args h = args_of("--headless");
   add(&h, "--size"), add(&h, "300x200");
   for (int i = 0; i < argc; i++)
      add(&h, argv[i]);
   add(&h, "--out"), add(&h, head), add(&h, model);
   if (run_view("headless", h.v, NULL, 120) != 0)
      die("the headless run failed");

   int n = fv_xvfb_start(xvfb, 160, 240);
   if (n < 0)
      die("cannot start %s on a free display", xvfb);
   char e_display[32], e_asan[4200];
   snprintf(e_display, sizeof e_display, "DISPLAY=:%d", n);
   /* Under AddressSanitizer, as libfixglut's window test: the system GL
    * and X libraries GLFW loads leak (three blocks, allocated by the GL
    * driver glfwTerminate unloads: LeakSanitizer's stale module map names
    * "libfixgl+0x58edd3", past libfixgl's last section); everything else
    * is still checked. */
   const char *asan = getenv("ASAN_OPTIONS");
   snprintf(e_asan, sizeof e_asan, "ASAN_OPTIONS=%s%sdetect_leaks=0", asan ? asan : "",
            asan && *asan ? ":" : "");
   char *env[] = { e_display, e_asan, NULL };
   struct args w = args_of("--size");
   add(&w, "300x200"), add(&w, "--frames"), add(&w, "3");
   for (int i = 0; i < argc; i++)
      add(&w, argv[i]);
   add(&w, "--screenshot"), add(&w, shot), add(&w, "--screenshot-x11"), add(&w, x11);
   add(&w, model);
   int rc = run_view("window", w.v, env, 120);
   fv_xvfb_stop();
   if (rc != 0)
      die("the viewer in a window on Xvfb :%d exited with %d", n, rc);

   struct image ih = load(head);
   int split = 0;
   for (int i = 0; i < argc; i++)
      split |= !strcmp(argv[i], "--split");
   if (!split && !properties(&ih))
      return 1;
   static const char *const what[2] = { "system-GL read-back", "X server image" };
   const char *files[2] = { shot, x11 };
   int failed = 0;
   for (int i = 0; i < 2; i++) {
      struct image iw = load(files[i]);
      long counts[3];
      char d[64];
      snprintf(d, sizeof d, "diff-%d.png", i);
      int max = compare(&iw, &ih, 3, path_in(d), counts);
      printf("window (%s) vs headless: %s\n", what[i], max ? "DIFFERS" : "exact");
      failed += max != 0;
      free(iw.px);
   }
   free(ih.px);
   return failed ? 1 : 0;
}

int main(int argc, char **argv)
{
   if (argc < 4)
      die("usage: see the comment at the top of view_test.c");
   const char *cmd = argv[1];
   view = argv[2];
   dir = argv[3];
   char cmdline[4400];
   snprintf(cmdline, sizeof cmdline, "rm -rf '%s' && mkdir -p '%s'", dir, dir);
   if (system(cmdline) != 0)
      die("cannot prepare %s", dir);
   if (!strcmp(cmd, "help"))
      return cmd_help();
   if (argc < 5)
      die("usage: see the comment at the top of view_test.c");
   if (!strcmp(cmd, "info"))
      return cmd_info(argv[4]);
   if (!strcmp(cmd, "errors"))
      return cmd_errors(argv[4]);
   if (!strcmp(cmd, "render"))
      return cmd_render(argv[4], argc - 5, argv + 5);
   if (!strcmp(cmd, "differ"))
      return cmd_differ(argv[4], argc - 5, argv + 5, 0);
   if (!strcmp(cmd, "same"))
      return cmd_differ(argv[4], argc - 5, argv + 5, 1);
   if (!strcmp(cmd, "frames"))
      return cmd_frames(argv[4]);
   if (!strcmp(cmd, "colourful"))
      return cmd_colourful(argv[4], argc - 5, argv + 5);
   if (!strcmp(cmd, "bad"))
      return cmd_bad(argv[4]);
   if (!strcmp(cmd, "progress"))
      return cmd_progress(argv[4]);
   if (!strcmp(cmd, "window") && argc >= 6)
      return cmd_window(argv[4], argv[5], argc - 6, argv + 6);
   die("unknown command %s", cmd);
}
