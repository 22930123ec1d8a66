/*
 * A screenshot of a GLFW window as the X server shows it (XGetImage on the
 * window), independent of any GL: what the user sees.
 */
#ifndef FV_GRAB_H
#define FV_GRAB_H

#ifdef __cplusplus
extern "C" {
#endif

struct GLFWwindow;

/* Reads the window's w x h pixels into rgba (bottom-up RGBA8, alpha 255).
 * Returns 0, or -1 with a message on stderr (not on X11, no image). */
int fv_grab_window(struct GLFWwindow *win, int w, int h, unsigned char *rgba);

#ifdef __cplusplus
}
#endif

#endif
