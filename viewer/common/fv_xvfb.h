/*
 * A private Xvfb server for the window tests (libfixglut's glut-compare,
 * fixgl-view's view-test): started on a free display number, stopped at
 * exit.
 */
#ifndef FV_XVFB_H
#define FV_XVFB_H

#ifdef __cplusplus
extern "C" {
#endif

/* Starts XVFB (the server's path) with one 640x480x24 screen on the first
 * free display number in [first, last) and waits (up to 10 s) for its
 * socket.  Returns the display number, or -1.  The server is stopped by
 * fv_xvfb_stop, which is also registered with atexit. */
int fv_xvfb_start(const char *xvfb, int first, int last);
void fv_xvfb_stop(void);

#ifdef __cplusplus
}
#endif

#endif
