/* fv_xvfb.c: a private Xvfb server for the window tests (fv_xvfb.h). */
#define _POSIX_C_SOURCE 200809L
#include "fv_xvfb.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

static pid_t xvfb_pid;

void fv_xvfb_stop(void)
{
   if (xvfb_pid > 0) {
      kill(xvfb_pid, SIGTERM);
      waitpid(xvfb_pid, NULL, 0);
      xvfb_pid = 0;
   }
}

int fv_xvfb_start(const char *xvfb, int first, int last)
{
   static int registered;
   for (int n = first; n < last; n++) {
      char lock[64], sock[64];
      snprintf(lock, sizeof lock, "/tmp/.X%d-lock", n);
      snprintf(sock, sizeof sock, "/tmp/.X11-unix/X%d", n);
      if (access(lock, F_OK) == 0 || access(sock, F_OK) == 0)
         continue;
      char display[16];
      snprintf(display, sizeof display, ":%d", n);
      pid_t pid = fork();
      if (pid < 0)
         return -1;
      if (pid == 0) {
         int null = open("/dev/null", O_WRONLY);
         if (null >= 0) {
            dup2(null, 1);
            dup2(null, 2);
         }
         execl(xvfb, xvfb, display, "-screen", "0", "640x480x24", "-nolisten", "tcp",
               (char *)NULL);
         _exit(127);
      }
      /* up to 10 s for the socket; an early exit means the number was taken */
      for (int i = 0; i < 100; i++) {
         int status;
         if (waitpid(pid, &status, WNOHANG) == pid) {
            pid = 0;
            break;
         }
         if (access(sock, F_OK) == 0) {
            xvfb_pid = pid;
            if (!registered) {
               atexit(fv_xvfb_stop);
               registered = 1;
            }
            usleep(200000);
            return n;
         }
         usleep(100000);
      }
      if (pid > 0) {
         kill(pid, SIGKILL);
         waitpid(pid, NULL, 0);
      }
   }
   return -1;
}
