/*
 * libfixglut internals: state shared by the core (glut_main.c), the menus
 * (glut_menu.c), the shapes, the teapot and the fonts.
 *
 * The same sources build two libraries: libfixglut (rendering by fixgl,
 * windows through GLFW) and libfixglut-osmesa (rendering by Mesa's OSMesa,
 * the oracle of the tests; headless only, built with FIXGLUT_ORACLE).
 */
#ifndef GLUT_INTERNAL_H
#define GLUT_INTERNAL_H

#include <GL/glut.h>
#include <GL/osmesa.h>
#include <stdbool.h>

#define GLUT_EXPORT __attribute__((visibility("default")))

#define GLUT_MAX_MENUS 64
#define GLUT_MAX_MENU_DEPTH 4

struct glut_menu_item {
   char *label;
   int value;        /* the callback's value, or the submenu's id */
   bool is_submenu;
};

struct glut_menu {
   bool used;
   void (*func)(int value);
   struct glut_menu_item *items;
   int num_items;
};

/* An open pop-up menu (window mode): a stack of cascaded menus. */
struct glut_popup {
   int depth;                          /* 0 = closed */
   int button;
   int menu[GLUT_MAX_MENU_DEPTH];
   int x[GLUT_MAX_MENU_DEPTH], y[GLUT_MAX_MENU_DEPTH];   /* top-left, window coords */
   int highlight[GLUT_MAX_MENU_DEPTH]; /* item index or -1 */
};

/* The CPU-side 8-bit glyph cells of a bitmap font (generated from the
 * stroke glyphs, glut_font.c). */
struct glut_bitmap_glyph {
   int width, height;     /* bitmap size in pixels */
   float xorig, yorig;    /* glBitmap's origin */
   float advance;
   const unsigned char *bits;   /* rows bottom to top, MSB first, byte-padded */
};

const struct glut_bitmap_glyph *glut_bitmap_glyph(void *font, int c);

/* Menus (glut_menu.c) */
extern struct glut_menu glut_menus[GLUT_MAX_MENUS];
extern int glut_current_menu;
extern int glut_attached[3];
extern struct glut_popup glut_popup;
void glut_menu_invoke(int menu, int item);
bool glut_menu_choose_path(int button, const char *path);
int glut_menu_item_height(void);
int glut_menu_width(int menu);
void glut_menu_overlay(unsigned char *rgba, int w, int h);
bool glut_popup_motion(int x, int y);
void glut_popup_release(int x, int y);
void glut_popup_open(int button, int x, int y);

/* Core (glut_main.c) */
void glut_fatal(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
void glut_warn(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void glut_represent(void);     /* presents the last frame again (menu changes) */
void glut_menu_status(int status, int x, int y);

/* PNG frames (glut_png.c): libpng is loaded at the first call.  Writes
 * w x h RGBA8 pixels, bottom_up: the buffer's first row is the image's
 * bottom (GL order).  Returns 0, or -1 after a warning. */
int glut_png_write(const char *path, int w, int h, const unsigned char *rgba, bool bottom_up);

#endif
