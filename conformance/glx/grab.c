/*
 * grab - the image of a program's window as the X server holds it, for
 * the programs that do not write their own (glxgears): the first viewable
 * top-level window (a child of the root) is read with XGetImage and
 * written as a PPM of its red, green and blue bits (glx_frames.h).
 * Exit 1 when there is no such window.
 *
 *   grab FILE.ppm
 */
#include "glx_frames.h"

int main(int argc, char **argv)
{
   if (argc != 2) {
      fprintf(stderr, "usage: grab FILE.ppm\n");
      return 2;
   }
   Display *dpy = XOpenDisplay(NULL);
   if (!dpy) {
      fprintf(stderr, "grab: cannot open the display\n");
      return 1;
   }
   Window root = DefaultRootWindow(dpy), parent, *children = NULL;
   unsigned n = 0;
   if (!XQueryTree(dpy, root, &root, &parent, &children, &n))
      return 1;
   for (unsigned i = 0; i < n; i++) {
      XWindowAttributes wa;
      if (XGetWindowAttributes(dpy, children[i], &wa) && wa.map_state == IsViewable &&
          wa.class == InputOutput) {
         write_drawable_ppm(dpy, children[i], wa.visual, argv[1], 0);
         XFree(children);
         XCloseDisplay(dpy);
         return 0;
      }
   }
   fprintf(stderr, "grab: no viewable window\n");
   return 1;
}
