/*
 * Presentation of a CPU-rendered RGBA frame in a GLFW window through the
 * SYSTEM OpenGL, shared by libfixglut and the viewer.
 *
 * The process is linked with fixgl, which exports the gl* symbols; the
 * system GL is never linked.  Its functions are reached only through
 * glfwGetProcAddress (GLFW loads libGL.so.1 with dlopen, RTLD_LOCAL), so
 * the system's gl* never shadow fixgl's, and fixgl's never serve the window.
 *
 * The copy is exact: glDrawPixels of RGBA8 at window position (0,0), pixel
 * zoom 1, dithering, blending, depth, fog and texturing off, so the window
 * holds the same bytes as the frame (tested under Xvfb).
 */
#ifndef FV_PRESENT_H
#define FV_PRESENT_H

#ifdef __cplusplus
extern "C" {
#endif

struct fv_present;

/* Loads the system GL entry points; the GLFW window's context must be
 * current.  Returns NULL (with a message on stderr) when one is missing. */
struct fv_present *fv_present_create(void);
void fv_present_destroy(struct fv_present *p);

/* Draws a bottom-up RGBA8 frame of w x h into the current context's back
 * buffer, whose framebuffer is fb_w x fb_h (cleared to black outside the
 * frame).  The caller swaps the buffers. */
void fv_present_frame(struct fv_present *p, const unsigned char *rgba, int w, int h,
                      int fb_w, int fb_h);

/* Reads w x h RGBA8 pixels (bottom-up) from the front (front != 0) or back
 * buffer of the current context: the screenshot of the window. */
void fv_present_read(struct fv_present *p, int front, int w, int h, unsigned char *rgba);

/* glFinish of the system GL. */
void fv_present_finish(struct fv_present *p);

#ifdef __cplusplus
}
#endif

#endif
