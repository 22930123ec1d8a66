/*
 * glut-compare: runs a GLUT demo headless on fixgl and on Mesa's OSMesa
 * (the same source linked with libfixglut-osmesa) and compares their frames
 * bit by bit; or (--window) runs it on fixgl in a real GLFW window under
 * Xvfb and compares the window's screenshot with the headless frame.
 *
 *   glut-compare --out DIR --frames N [--events LIST] [--frame-ms M]
 *                --fixgl DEMO --oracle DEMO
 *   glut-compare --window --out DIR --frames N --fixgl DEMO --xvfb XVFB
 *
 * The window run writes two screenshots of the last frame: the system GL's
 * read-back of the presented back buffer and the X server's image of the
 * window after the swap (XGetImage); both must equal the headless frame.
 *
 * A frame that differs fails the test and leaves DIR/diff/frame-NNNN.png
 * (differing pixels red, equal ones dimmed).  There is no skip: a frame
 * that cannot be compared fails.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "fv_png.h"
#include "fv_xvfb.h"

static const char *out_dir, *events = "", *frame_ms, *fixgl_demo, *oracle_demo,
                  *xvfb;
static int frames = 1;
static bool window_mode;

static void die(const char *msg)
{
   fprintf(stderr, "glut-compare: %s\n", msg);
   exit(1);
}

static void make_dir(const char *path)
{
   char cmd[4096];
   snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", path, path);
   if (system(cmd) != 0)
      die("cannot prepare the output directory");
}

/* Runs argv0 with extra environment entries; returns its exit status. */
static int run(const char *argv0, char *const env_add[], int timeout_s)
{
   pid_t pid = fork();
   if (pid < 0)
      die("fork failed");
   if (pid == 0) {
      for (int i = 0; env_add[i]; i++)
         putenv(env_add[i]);
      execl(argv0, argv0, (char *)NULL);
      fprintf(stderr, "glut-compare: cannot run %s: %s\n", argv0, strerror(errno));
      _exit(127);
   }
   int status = 0;
   for (int waited = 0; ; waited++) {
      pid_t r = waitpid(pid, &status, WNOHANG);
      if (r == pid)
         break;
      if (waited > timeout_s * 10) {
         kill(pid, SIGKILL);
         waitpid(pid, &status, 0);
         fprintf(stderr, "glut-compare: %s timed out\n", argv0);
         return -1;
      }
      usleep(100000);
   }
   if (WIFEXITED(status))
      return WEXITSTATUS(status);
   fprintf(stderr, "glut-compare: %s died (signal %d)\n", argv0, WTERMSIG(status));
   return -1;
}

static void run_headless(const char *demo, const char *dir)
{
   static char e_headless[] = "FIXGLUT_HEADLESS=1";
   char e_frames[64], e_out[4200], e_events[8192], e_ms[64];
   snprintf(e_frames, sizeof e_frames, "FIXGLUT_FRAMES=%d", frames);
   snprintf(e_out, sizeof e_out, "FIXGLUT_OUT=%s/", dir);
   snprintf(e_events, sizeof e_events, "FIXGLUT_EVENTS=%s", events);
   snprintf(e_ms, sizeof e_ms, "FIXGLUT_FRAME_MS=%s", frame_ms ? frame_ms : "16");
   char *env[] = { e_headless, e_frames, e_out, e_events, e_ms, NULL };
   printf("running %s (%d frames, events \"%s\")\n", demo, frames, events);
   fflush(stdout);
   int rc = run(demo, env, 120);
   if (rc != 0) {
      fprintf(stderr, "glut-compare: %s exited with %d\n", demo, rc);
      exit(1);
   }
}

/* Compares two RGBA images (channels 0..nc-1); writes a diff image when
 * they differ.  Returns the number of differing pixels (-1: unreadable or
 * of different sizes). */
static long compare(const char *a_path, const char *b_path, const char *diff_path, int nc)
{
   int aw, ah, bw, bh;
   unsigned char *a, *b;
   if (fv_png_read(a_path, &aw, &ah, &a) != 0)
      return -1;
   if (fv_png_read(b_path, &bw, &bh, &b) != 0) {
      free(a);
      return -1;
   }
   if (aw != bw || ah != bh) {
      fprintf(stderr, "glut-compare: %s is %dx%d, %s is %dx%d\n", a_path, aw, ah, b_path, bw, bh);
      free(a), free(b);
      return -1;
   }
   long n = 0;
   int maxd = 0;
   unsigned char *d = malloc((size_t)aw * ah * 4);
   if (!d)
      die("out of memory");
   for (long i = 0; i < (long)aw * ah; i++) {
      bool same = true;
      for (int c = 0; c < nc; c++) {
         int diff = abs(a[i * 4 + c] - b[i * 4 + c]);
         if (diff) {
            same = false;
            if (diff > maxd)
               maxd = diff;
         }
      }
      if (!same)
         n++;
      d[i * 4 + 0] = same ? a[i * 4] / 4 : 255;
      d[i * 4 + 1] = same ? a[i * 4 + 1] / 4 : 0;
      d[i * 4 + 2] = same ? a[i * 4 + 2] / 4 : 0;
      d[i * 4 + 3] = 255;
   }
   if (n) {
      printf("  %ld pixels differ (max channel difference %d): %s\n", n, maxd, diff_path);
      fv_png_write(diff_path, aw, ah, d, 0);
   }
   free(a), free(b), free(d);
   return n;
}

/* The frame is not blank: at least two distinct colours. */
static bool has_content(const char *path)
{
   int w, h;
   unsigned char *p;
   if (fv_png_read(path, &w, &h, &p) != 0)
      return false;
   bool content = false;
   for (long i = 1; i < (long)w * h && !content; i++)
      content = memcmp(p, p + i * 4, 3) != 0;
   free(p);
   return content;
}

static int compare_headless(void)
{
   char fdir[4096], odir[4096], ddir[4096];
   snprintf(fdir, sizeof fdir, "%s/fixgl", out_dir);
   snprintf(odir, sizeof odir, "%s/oracle", out_dir);
   snprintf(ddir, sizeof ddir, "%s/diff", out_dir);
   make_dir(fdir), make_dir(odir), make_dir(ddir);

   run_headless(oracle_demo, odir);
   char last[4200];
   snprintf(last, sizeof last, "%s/frame-%04d.png", odir, frames - 1);
   if (!has_content(last)) {
      fprintf(stderr, "glut-compare: the oracle's last frame is blank\n");
      return 1;
   }
   run_headless(fixgl_demo, fdir);

   int failed = 0;
   for (int f = 0; f < frames; f++) {
      char a[4200], b[4200], d[4200];
      snprintf(a, sizeof a, "%s/frame-%04d.png", fdir, f);
      snprintf(b, sizeof b, "%s/frame-%04d.png", odir, f);
      snprintf(d, sizeof d, "%s/frame-%04d.png", ddir, f);
      long n = compare(a, b, d, 4);
      printf("frame %d: %s\n", f, n == 0 ? "exact" : n < 0 ? "ERROR" : "DIFFERS");
      if (n != 0)
         failed++;
   }
   printf("%d of %d frames exact\n", frames - failed, frames);
   return failed ? 1 : 0;
}

/* ---- the real window under Xvfb ----------------------------------------- */

static int compare_window(void)
{
   char hdir[4096], wdir[4096], ddir[4096];
   snprintf(hdir, sizeof hdir, "%s/headless", out_dir);
   snprintf(wdir, sizeof wdir, "%s/window", out_dir);
   snprintf(ddir, sizeof ddir, "%s/diff", out_dir);
   make_dir(hdir), make_dir(wdir), make_dir(ddir);

   run_headless(fixgl_demo, hdir);

   int n = fv_xvfb_start(xvfb, 97, 160);
   if (n < 0) {
      fprintf(stderr, "glut-compare: cannot start %s on a free display\n", xvfb);
      return 1;
   }
   char e_display[32], e_frames[64], e_shot[4200], e_shot_x11[4200], e_ms[64], e_asan[4200];
   snprintf(e_display, sizeof e_display, "DISPLAY=:%d", n);
   snprintf(e_frames, sizeof e_frames, "FIXGLUT_FRAMES=%d", frames);
   snprintf(e_shot, sizeof e_shot, "FIXGLUT_SCREENSHOT=%s/screenshot.png", wdir);
   snprintf(e_shot_x11, sizeof e_shot_x11, "FIXGLUT_SCREENSHOT_X11=%s/x11.png", wdir);
   snprintf(e_ms, sizeof e_ms, "FIXGLUT_FRAME_MS=%s", frame_ms ? frame_ms : "16");
   /* Under AddressSanitizer: leaks inside the system's GL and X libraries
    * (loaded by GLFW) are not ours; everything else is still checked. */
   const char *asan = getenv("ASAN_OPTIONS");
   snprintf(e_asan, sizeof e_asan, "ASAN_OPTIONS=%s%sdetect_leaks=0", asan ? asan : "",
            asan && *asan ? ":" : "");
   static char e_headless[] = "FIXGLUT_HEADLESS=0";
   static char e_events[] = "FIXGLUT_EVENTS=";
   static char e_out[] = "FIXGLUT_OUT=";
   char *env[] = { e_display, e_frames, e_shot, e_shot_x11, e_ms, e_asan, e_headless, e_events,
                   e_out, NULL };
   printf("running %s in a window on Xvfb :%d (%d frames)\n", fixgl_demo, n, frames);
   fflush(stdout);
   int rc = run(fixgl_demo, env, 120);
   fv_xvfb_stop();
   if (rc != 0) {
      fprintf(stderr, "glut-compare: %s in a window exited with %d\n", fixgl_demo, rc);
      return 1;
   }
   char b[4200];
   snprintf(b, sizeof b, "%s/frame-%04d.png", hdir, frames - 1);
   if (!has_content(b)) {
      fprintf(stderr, "glut-compare: the headless frame is blank\n");
      return 1;
   }
   /* Both screenshots, RGB (the window's visual need not keep alpha): the
    * back buffer read through the system GL as presented, and the window
    * as the X server shows it after the swap. */
   static const char *const shots[2] = { "screenshot.png", "x11.png" };
   static const char *const what[2] = { "system-GL read-back", "X server image" };
   int failed = 0;
   for (int i = 0; i < 2; i++) {
      char a[4200], d[4200];
      snprintf(a, sizeof a, "%s/%s", wdir, shots[i]);
      snprintf(d, sizeof d, "%s/%s", ddir, shots[i]);
      long diff = compare(a, b, d, 3);
      printf("window (%s) vs headless frame %d: %s\n", what[i], frames - 1,
             diff == 0 ? "exact" : diff < 0 ? "ERROR" : "DIFFERS");
      if (diff != 0)
         failed++;
   }
   return failed ? 1 : 0;
}

int main(int argc, char **argv)
{
   for (int i = 1; i < argc; i++) {
      const char *a = argv[i];
      const char *v = i + 1 < argc ? argv[i + 1] : NULL;
      if (!strcmp(a, "--window")) {
         window_mode = true;
         continue;
      }
      if (!v)
         die("missing option value");
      if (!strcmp(a, "--out")) out_dir = v;
      else if (!strcmp(a, "--frames")) frames = atoi(v);
      else if (!strcmp(a, "--events")) events = v;
      else if (!strcmp(a, "--frame-ms")) frame_ms = v;
      else if (!strcmp(a, "--fixgl")) fixgl_demo = v;
      else if (!strcmp(a, "--oracle")) oracle_demo = v;
      else if (!strcmp(a, "--xvfb")) xvfb = v;
      else die("unknown option");
      i++;
   }
   if (!out_dir || !fixgl_demo || frames < 1 || (window_mode ? !xvfb : !oracle_demo))
      die("usage: see the comment at the top of glut_compare.c");
   return window_mode ? compare_window() : compare_headless();
}
