/*
 * GLFW (and the two Xlib calls of fv_grab.c) for the window glue.
 *
 * Linked directly (the viewer), this header is <GLFW/glfw3.h>.  Built
 * with FV_GLFW_DLOPEN (libfixglut), every function below is a pointer of
 * the table fv_glfw, filled by fv_glfw_load() from libglfw.so.3 and
 * libX11.so.6 when the window mode starts (libfixglut: glutInit without
 * FIXGLUT_HEADLESS): a headless program never maps GLFW or Xlib
 * (measured: linking both costs a bare program about 3.5 ms of start-up
 * and 1.3 MB resident).  The call sites are the same
 * in both builds.
 */
#ifndef FV_GLFW_H
#define FV_GLFW_H

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

/* GLFW's native X11 access (<GLFW/glfw3native.h> would pull in its own
 * GL headers); Display and Window as void * and XID. */
#ifndef FV_GLFW_DLOPEN
#ifdef X_H
Display *glfwGetX11Display(void);
Window glfwGetX11Window(GLFWwindow *window);
#endif
#else

/* X(return type, name, parameters) */
#define FV_GLFW_FUNCS(X) \
   X(int, glfwInit, (void)) \
   X(void, glfwTerminate, (void)) \
   X(void, glfwDefaultWindowHints, (void)) \
   X(void, glfwWindowHint, (int, int)) \
   X(GLFWwindow *, glfwCreateWindow, (int, int, const char *, GLFWmonitor *, GLFWwindow *)) \
   X(void, glfwDestroyWindow, (GLFWwindow *)) \
   X(void, glfwMakeContextCurrent, (GLFWwindow *)) \
   X(void, glfwSwapInterval, (int)) \
   X(void, glfwSwapBuffers, (GLFWwindow *)) \
   X(GLFWglproc, glfwGetProcAddress, (const char *)) \
   X(void, glfwPollEvents, (void)) \
   X(void, glfwWaitEventsTimeout, (double)) \
   X(int, glfwWindowShouldClose, (GLFWwindow *)) \
   X(void, glfwSetWindowShouldClose, (GLFWwindow *, int)) \
   X(void, glfwGetFramebufferSize, (GLFWwindow *, int *, int *)) \
   X(void, glfwGetWindowSize, (GLFWwindow *, int *, int *)) \
   X(void, glfwSetWindowSize, (GLFWwindow *, int, int)) \
   X(void, glfwGetWindowPos, (GLFWwindow *, int *, int *)) \
   X(void, glfwSetWindowPos, (GLFWwindow *, int, int)) \
   X(void, glfwSetWindowTitle, (GLFWwindow *, const char *)) \
   X(void, glfwShowWindow, (GLFWwindow *)) \
   X(void, glfwHideWindow, (GLFWwindow *)) \
   X(void, glfwIconifyWindow, (GLFWwindow *)) \
   X(GLFWmonitor *, glfwGetWindowMonitor, (GLFWwindow *)) \
   X(void, glfwSetWindowMonitor, (GLFWwindow *, GLFWmonitor *, int, int, int, int, int)) \
   X(GLFWmonitor *, glfwGetPrimaryMonitor, (void)) \
   X(const GLFWvidmode *, glfwGetVideoMode, (GLFWmonitor *)) \
   X(void, glfwGetCursorPos, (GLFWwindow *, double *, double *)) \
   X(void, glfwSetCursorPos, (GLFWwindow *, double, double)) \
   X(GLFWkeyfun, glfwSetKeyCallback, (GLFWwindow *, GLFWkeyfun)) \
   X(GLFWcharfun, glfwSetCharCallback, (GLFWwindow *, GLFWcharfun)) \
   X(GLFWmousebuttonfun, glfwSetMouseButtonCallback, (GLFWwindow *, GLFWmousebuttonfun)) \
   X(GLFWscrollfun, glfwSetScrollCallback, (GLFWwindow *, GLFWscrollfun)) \
   X(GLFWcursorposfun, glfwSetCursorPosCallback, (GLFWwindow *, GLFWcursorposfun)) \
   X(GLFWcursorenterfun, glfwSetCursorEnterCallback, (GLFWwindow *, GLFWcursorenterfun)) \
   X(GLFWwindowsizefun, glfwSetWindowSizeCallback, (GLFWwindow *, GLFWwindowsizefun)) \
   X(GLFWwindowrefreshfun, glfwSetWindowRefreshCallback, (GLFWwindow *, GLFWwindowrefreshfun)) \
   X(GLFWwindowiconifyfun, glfwSetWindowIconifyCallback, (GLFWwindow *, GLFWwindowiconifyfun)) \
   X(GLFWwindowposfun, glfwSetWindowPosCallback, (GLFWwindow *, GLFWwindowposfun)) \
   X(GLFWwindowclosefun, glfwSetWindowCloseCallback, (GLFWwindow *, GLFWwindowclosefun)) \
   X(void *, glfwGetX11Display, (void)) \
   X(unsigned long, glfwGetX11Window, (GLFWwindow *))

/* from libX11.so.6: Display * as void *, Window and plane masks as
 * unsigned long, XImage * as void * */
#define FV_X11_FUNCS(X) \
   X(int, XSync, (void *, int)) \
   X(void *, XGetImage, (void *, unsigned long, int, int, unsigned, unsigned, unsigned long, int))

#define FV_GLFW_FIELD(ret, name, params) ret (*name) params;
struct fv_glfw_table {
   FV_GLFW_FUNCS(FV_GLFW_FIELD)
   FV_X11_FUNCS(FV_GLFW_FIELD)
};
#undef FV_GLFW_FIELD

extern struct fv_glfw_table fv_glfw;

/* Loads libglfw.so.3 and libX11.so.6 once; returns 0, or -1 with the
 * reason on stderr. */
int fv_glfw_load(void);

/* fv_glfw.c, which fills the table, keeps the names */
#ifndef FV_GLFW_TABLE_ONLY
#include "fv_glfw_names.h"
#endif

#endif /* FV_GLFW_DLOPEN */
#endif
