/*
 * The two measurements of the start-up bench (glut_startup.py): the time
 * from exec to the first frame's drawing (the launcher puts its clock
 * before the exec into STARTUP_T0_NS, CLOCK_REALTIME nanoseconds) and the
 * peak resident size (VmHWM of /proc/self/status) at exit.
 */
#ifndef STARTUP_COMMON_H
#define STARTUP_COMMON_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double startup_ms = -1.0;

static void startup_mark(void)
{
   const char *t0 = getenv("STARTUP_T0_NS");
   struct timespec ts;
   if (startup_ms >= 0.0 || !t0)
      return;
   clock_gettime(CLOCK_REALTIME, &ts);
   long long now = (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
   startup_ms = (double)(now - strtoll(t0, NULL, 10)) / 1e6;
}

static long startup_vmhwm_kb(void)
{
   char line[256];
   long kb = -1;
   FILE *f = fopen("/proc/self/status", "r");
   if (!f)
      return -1;
   while (fgets(line, sizeof line, f))
      if (strncmp(line, "VmHWM:", 6) == 0)
         kb = strtol(line + 6, NULL, 10);
   fclose(f);
   return kb;
}

static void startup_report(void)
{
   printf("startup_ms %.3f\nvmhwm_kb %ld\n", startup_ms, startup_vmhwm_kb());
   fflush(stdout);
}

#endif
