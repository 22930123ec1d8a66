/*
 * frozen_clock - an LD_PRELOAD library that stops the clock of programs
 * which animate by it: gettimeofday always answers the same instant.
 * glxgears turns its gears by 70 degrees per second of gettimeofday's
 * time; under this library every frame it draws is its first one (angle
 * 0), so the frames of two runs can be compared.
 */
#include <stddef.h>
#include <sys/time.h>

int gettimeofday(struct timeval *restrict tv, void *restrict tz)
{
   (void)tz;
   tv->tv_sec = 1000000000;   /* glibc declares tv nonnull */
   tv->tv_usec = 0;
   return 0;
}
