/*
 * check.h - tiny assertion helper shared by the API tests.
 *
 * CHECK(cond, fmt, ...) records a failure (file, line, the condition and a
 * printf-style message) and carries on, so that one run reports every broken
 * expectation; FAIL(fmt, ...) records one unconditionally. Both may be used
 * from several threads. A test's main() ends with
 * `return check_report("name");`, which prints a one-line verdict and turns
 * any failure into exit status 1.
 */
#ifndef FIXGL_API_CHECK_H
#define FIXGL_API_CHECK_H

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>

static _Atomic int check_failures;

/* Prints one failure as a single line (one write, so threads don't mix). */
static void check_fail(const char *file, int line, const char *fmt, ...)
{
  char msg[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  check_failures++;
  fprintf(stderr, "%s:%d: %s\n", file, line, msg);
}

#define FAIL(...) check_fail(__FILE__, __LINE__, __VA_ARGS__)

/* The message must start with a string literal. */
#define CHECK(cond, ...)                               \
  do {                                                 \
    if (!(cond))                                       \
      FAIL("check failed: " #cond ": " __VA_ARGS__);   \
  } while (0)

static int check_report(const char *test_name)
{
  if (check_failures)
    fprintf(stderr, "%s: %d check(s) failed\n", test_name, (int)check_failures);
  else
    fprintf(stderr, "%s: all checks passed\n", test_name);
  return check_failures ? 1 : 0;
}

/* One step of a xorshift64 generator: the next state of *s, stored and
 * returned (random inputs for the tests; the state must not be 0). */
static inline uint64_t check_xorshift64(uint64_t *s)
{
  *s ^= *s << 13;
  *s ^= *s >> 7;
  *s ^= *s << 17;
  return *s;
}

#endif
