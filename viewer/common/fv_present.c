/*
 * Presentation through the system GL reached by glfwGetProcAddress only
 * (fv_present.h).
 */
#include "fv_glfw.h"
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>

#include "fv_present.h"

/* Pointer types of the system GL functions used; prefixed so that no name
 * can bind to fixgl's exports. */
typedef void (*pfn_enum)(GLenum);
typedef void (*pfn_viewport)(GLint, GLint, GLsizei, GLsizei);
typedef void (*pfn_clear_color)(GLfloat, GLfloat, GLfloat, GLfloat);
typedef void (*pfn_clear)(GLbitfield);
typedef void (*pfn_pixel_storei)(GLenum, GLint);
typedef void (*pfn_pixel_zoom)(GLfloat, GLfloat);
typedef void (*pfn_window_pos2i)(GLint, GLint);
typedef void (*pfn_draw_pixels)(GLsizei, GLsizei, GLenum, GLenum, const void *);
typedef void (*pfn_read_pixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *);
typedef void (*pfn_void)(void);

struct fv_present {
   pfn_enum Disable, DrawBuffer, ReadBuffer;
   pfn_viewport Viewport;
   pfn_clear_color ClearColor;
   pfn_clear Clear;
   pfn_pixel_storei PixelStorei;
   pfn_pixel_zoom PixelZoom;
   pfn_window_pos2i WindowPos2i;
   pfn_draw_pixels DrawPixels;
   pfn_read_pixels ReadPixels;
   pfn_void Finish;
};

static GLFWglproc load(const char *name, int *missing)
{
   GLFWglproc f = glfwGetProcAddress(name);
   if (!f) {
      fprintf(stderr, "fv_present: the system GL has no %s\n", name);
      *missing = 1;
   }
   return f;
}

struct fv_present *fv_present_create(void)
{
   struct fv_present *p = calloc(1, sizeof *p);
   int missing = 0;
   if (!p)
      return NULL;
   p->Disable = (pfn_enum)load("glDisable", &missing);
   p->DrawBuffer = (pfn_enum)load("glDrawBuffer", &missing);
   p->ReadBuffer = (pfn_enum)load("glReadBuffer", &missing);
   p->Viewport = (pfn_viewport)load("glViewport", &missing);
   p->ClearColor = (pfn_clear_color)load("glClearColor", &missing);
   p->Clear = (pfn_clear)load("glClear", &missing);
   p->PixelStorei = (pfn_pixel_storei)load("glPixelStorei", &missing);
   p->PixelZoom = (pfn_pixel_zoom)load("glPixelZoom", &missing);
   p->WindowPos2i = (pfn_window_pos2i)load("glWindowPos2i", &missing);
   p->DrawPixels = (pfn_draw_pixels)load("glDrawPixels", &missing);
   p->ReadPixels = (pfn_read_pixels)load("glReadPixels", &missing);
   p->Finish = (pfn_void)load("glFinish", &missing);
   if (missing) {
      free(p);
      return NULL;
   }
   /* State for an exact copy, set once: the context serves nothing else. */
   p->Disable(GL_DITHER);
   p->Disable(GL_BLEND);
   p->Disable(GL_DEPTH_TEST);
   p->Disable(GL_ALPHA_TEST);
   p->Disable(GL_FOG);
   p->Disable(GL_TEXTURE_2D);
   p->Disable(GL_LIGHTING);
   p->PixelZoom(1.0f, 1.0f);
   p->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
   p->PixelStorei(GL_PACK_ALIGNMENT, 1);
   return p;
}

void fv_present_destroy(struct fv_present *p)
{
   free(p);
}

void fv_present_frame(struct fv_present *p, const unsigned char *rgba, int w, int h,
                      int fb_w, int fb_h)
{
   p->DrawBuffer(GL_BACK);
   p->Viewport(0, 0, fb_w, fb_h);
   if (fb_w != w || fb_h != h) {
      p->ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
      p->Clear(GL_COLOR_BUFFER_BIT);
   }
   /* Window coordinates (0,0): the frame's bottom row at the bottom; the
    * window's top-left corner holds the frame's top-left pixel when the
    * sizes agree. */
   p->WindowPos2i(0, fb_h - h);
   p->DrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

void fv_present_read(struct fv_present *p, int front, int w, int h, unsigned char *rgba)
{
   p->Finish();
   p->ReadBuffer(front ? GL_FRONT : GL_BACK);
   p->ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

void fv_present_finish(struct fv_present *p)
{
   p->Finish();
}
