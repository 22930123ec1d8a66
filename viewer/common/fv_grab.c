/* The window's pixels from the X server (fv_grab.h). */
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>

/* GLFW, and its native X11 access (declared there: <GLFW/glfw3native.h>
 * would need the XRandR headers for nothing else) */
#include "fv_glfw.h"

#include "fv_grab.h"

static int mask_shift(unsigned long mask)
{
   int s = 0;
   while (mask && !(mask & 1)) {
      mask >>= 1;
      s++;
   }
   return s;
}

int fv_grab_window(struct GLFWwindow *win, int w, int h, unsigned char *rgba)
{
   Display *dpy = glfwGetX11Display();
   Window xw = glfwGetX11Window(win);
   if (!dpy || !xw) {
      fprintf(stderr, "fv_grab: not an X11 window\n");
      return -1;
   }
   XSync(dpy, False);
   XImage *img = XGetImage(dpy, xw, 0, 0, (unsigned)w, (unsigned)h, AllPlanes, ZPixmap);
   if (!img) {
      fprintf(stderr, "fv_grab: XGetImage failed\n");
      return -1;
   }
   const int rs = mask_shift(img->red_mask), gs = mask_shift(img->green_mask),
             bs = mask_shift(img->blue_mask);
   const unsigned long rm = img->red_mask >> rs, gm = img->green_mask >> gs,
                       bm = img->blue_mask >> bs;
   if (rm != 255 || gm != 255 || bm != 255) {
      fprintf(stderr, "fv_grab: the window's visual is not 8 bits per channel\n");
      XDestroyImage(img);
      return -1;
   }
   for (int y = 0; y < h; y++) {
      unsigned char *row = rgba + (size_t)(h - 1 - y) * w * 4;   /* bottom-up */
      for (int x = 0; x < w; x++) {
         unsigned long p = XGetPixel(img, x, y);
         row[x * 4 + 0] = (unsigned char)((p >> rs) & 255);
         row[x * 4 + 1] = (unsigned char)((p >> gs) & 255);
         row[x * 4 + 2] = (unsigned char)((p >> bs) & 255);
         row[x * 4 + 3] = 255;
      }
   }
   XDestroyImage(img);
   return 0;
}
