/*
 * Menus: creation and editing, attachment to mouse buttons, the pop-up
 * drawn by the layer over the presented frame (never into the program's
 * frame), and the scripted choice of an entry (FIXGLUT_EVENTS "menu:").
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glut_internal.h"

struct glut_menu glut_menus[GLUT_MAX_MENUS];
int glut_current_menu;          /* 1-based id, 0 = none */
int glut_attached[3];           /* menu id per button, 0 = none */
struct glut_popup glut_popup;

static struct glut_menu *menu_of(int id)
{
   if (id < 1 || id > GLUT_MAX_MENUS || !glut_menus[id - 1].used)
      return NULL;
   return &glut_menus[id - 1];
}

static struct glut_menu *current(const char *fn)
{
   struct glut_menu *m = menu_of(glut_current_menu);
   if (!m)
      glut_warn("%s: no current menu", fn);
   return m;
}

GLUT_EXPORT int glutCreateMenu(void (*func)(int value))
{
   for (int i = 0; i < GLUT_MAX_MENUS; i++) {
      if (!glut_menus[i].used) {
         glut_menus[i] = (struct glut_menu){ .used = true, .func = func };
         glut_current_menu = i + 1;
         return i + 1;
      }
   }
   glut_fatal("too many menus (%d)", GLUT_MAX_MENUS);
}

GLUT_EXPORT void glutDestroyMenu(int menu)
{
   struct glut_menu *m = menu_of(menu);
   if (!m)
      return;
   for (int i = 0; i < m->num_items; i++)
      free(m->items[i].label);
   free(m->items);
   *m = (struct glut_menu){ 0 };
   for (int b = 0; b < 3; b++)
      if (glut_attached[b] == menu)
         glut_attached[b] = 0;
   if (glut_current_menu == menu)
      glut_current_menu = 0;
}

GLUT_EXPORT int glutGetMenu(void)
{
   return glut_current_menu;
}

GLUT_EXPORT void glutSetMenu(int menu)
{
   if (menu_of(menu))
      glut_current_menu = menu;
   else
      glut_warn("glutSetMenu: no menu %d", menu);
}

static void add_item(const char *label, int value, bool sub)
{
   struct glut_menu *m = current(sub ? "glutAddSubMenu" : "glutAddMenuEntry");
   if (!m)
      return;
   struct glut_menu_item *items = realloc(m->items, (size_t)(m->num_items + 1) * sizeof *items);
   char *copy = strdup(label ? label : "");
   if (!items || !copy)
      glut_fatal("out of memory");
   m->items = items;
   m->items[m->num_items++] = (struct glut_menu_item){ copy, value, sub };
}

GLUT_EXPORT void glutAddMenuEntry(const char *label, int value)
{
   add_item(label, value, false);
}

GLUT_EXPORT void glutAddSubMenu(const char *label, int submenu)
{
   if (!menu_of(submenu)) {
      glut_warn("glutAddSubMenu: no menu %d", submenu);
      return;
   }
   add_item(label, submenu, true);
}

static void change_item(int item, const char *label, int value, bool sub, const char *fn)
{
   struct glut_menu *m = current(fn);
   if (!m)
      return;
   if (item < 1 || item > m->num_items) {
      glut_warn("%s: no item %d", fn, item);
      return;
   }
   char *copy = strdup(label ? label : "");
   if (!copy)
      glut_fatal("out of memory");
   free(m->items[item - 1].label);
   m->items[item - 1] = (struct glut_menu_item){ copy, value, sub };
}

GLUT_EXPORT void glutChangeToMenuEntry(int item, const char *label, int value)
{
   change_item(item, label, value, false, "glutChangeToMenuEntry");
}

GLUT_EXPORT void glutChangeToSubMenu(int item, const char *label, int submenu)
{
   change_item(item, label, submenu, true, "glutChangeToSubMenu");
}

GLUT_EXPORT void glutRemoveMenuItem(int item)
{
   struct glut_menu *m = current("glutRemoveMenuItem");
   if (!m)
      return;
   if (item < 1 || item > m->num_items) {
      glut_warn("glutRemoveMenuItem: no item %d", item);
      return;
   }
   free(m->items[item - 1].label);
   memmove(&m->items[item - 1], &m->items[item],
           (size_t)(m->num_items - item) * sizeof *m->items);
   m->num_items--;
}

GLUT_EXPORT void glutAttachMenu(int button)
{
   if (button >= 0 && button < 3 && menu_of(glut_current_menu))
      glut_attached[button] = glut_current_menu;
}

GLUT_EXPORT void glutDetachMenu(int button)
{
   if (button >= 0 && button < 3)
      glut_attached[button] = 0;
}

/* Calls the callback of `menu` for its leaf item (0-based), with that menu
 * current during the call (as GLUT does). */
void glut_menu_invoke(int menu, int item)
{
   struct glut_menu *m = menu_of(menu);
   if (!m || item < 0 || item >= m->num_items || m->items[item].is_submenu)
      return;
   int saved = glut_current_menu;
   glut_current_menu = menu;
   if (m->func)
      m->func(m->items[item].value);
   if (menu_of(saved))
      glut_current_menu = saved;
}

/* Scripted choice: PATH is 1-based item numbers separated by '.', through
 * submenus ("3.2": the 2nd item of the submenu at item 3). */
bool glut_menu_choose_path(int button, const char *path)
{
   if (button < 0 || button > 2)
      return false;
   int menu = glut_attached[button];
   const char *p = path;
   for (;;) {
      struct glut_menu *m = menu_of(menu);
      char *end;
      long item = strtol(p, &end, 10);
      if (!m || end == p || item < 1 || item > m->num_items)
         return false;
      if (*end == '.') {
         if (!m->items[item - 1].is_submenu)
            return false;
         menu = m->items[item - 1].value;
         p = end + 1;
         continue;
      }
      if (*end != '\0' || m->items[item - 1].is_submenu)
         return false;
      glut_menu_status(GLUT_MENU_IN_USE, 0, 0);
      glut_menu_invoke(menu, (int)item - 1);
      glut_menu_status(GLUT_MENU_NOT_IN_USE, 0, 0);
      return true;
   }
}

/* ---- the pop-up (window mode) ------------------------------------------- */

#define FONT GLUT_BITMAP_9_BY_15
#define PAD 6

int glut_menu_item_height(void)
{
   return 20;
}

static int text_width(const char *s)
{
   int w = 0;
   for (; *s; s++) {
      const struct glut_bitmap_glyph *g = glut_bitmap_glyph(FONT, (unsigned char)*s);
      if (g)
         w += (int)g->advance;
   }
   return w;
}

int glut_menu_width(int menu)
{
   struct glut_menu *m = menu_of(menu);
   int w = 60;
   for (int i = 0; m && i < m->num_items; i++) {
      int iw = text_width(m->items[i].label) + 2 * PAD + (m->items[i].is_submenu ? 14 : 0);
      if (iw > w)
         w = iw;
   }
   return w;
}

static int item_at(int level, int x, int y)
{
   struct glut_menu *m = menu_of(glut_popup.menu[level]);
   if (!m)
      return -1;
   int lx = x - glut_popup.x[level], ly = y - glut_popup.y[level];
   if (lx < 0 || lx >= glut_menu_width(glut_popup.menu[level]) || ly < 0)
      return -1;
   int i = ly / glut_menu_item_height();
   return i < m->num_items ? i : -1;
}

void glut_popup_open(int button, int x, int y)
{
   glut_popup = (struct glut_popup){ .depth = 1, .button = button };
   glut_popup.menu[0] = glut_attached[button];
   glut_popup.x[0] = x, glut_popup.y[0] = y;
   glut_popup.highlight[0] = -1;
   glut_menu_status(GLUT_MENU_IN_USE, x, y);
}

/* Highlights the item under the cursor, opening or closing cascades;
 * returns whether the pop-up changed. */
bool glut_popup_motion(int x, int y)
{
   struct glut_popup before = glut_popup;
   for (int level = glut_popup.depth - 1; level >= 0; level--) {
      int i = item_at(level, x, y);
      if (i < 0)
         continue;
      glut_popup.depth = level + 1;
      glut_popup.highlight[level] = i;
      struct glut_menu *m = menu_of(glut_popup.menu[level]);
      if (m->items[i].is_submenu && level + 1 < GLUT_MAX_MENU_DEPTH) {
         glut_popup.depth = level + 2;
         glut_popup.menu[level + 1] = m->items[i].value;
         glut_popup.x[level + 1] = glut_popup.x[level] + glut_menu_width(glut_popup.menu[level]);
         glut_popup.y[level + 1] = glut_popup.y[level] + i * glut_menu_item_height();
         glut_popup.highlight[level + 1] = -1;
      }
      break;
   }
   return memcmp(&before, &glut_popup, sizeof before) != 0;
}

void glut_popup_release(int x, int y)
{
   int menu = 0, item = -1;
   for (int level = glut_popup.depth - 1; level >= 0 && item < 0; level--) {
      int i = item_at(level, x, y);
      if (i >= 0) {
         menu = glut_popup.menu[level];
         item = i;
      }
   }
   glut_popup.depth = 0;
   glut_menu_status(GLUT_MENU_NOT_IN_USE, x, y);
   if (item >= 0)
      glut_menu_invoke(menu, item);
}

/* ---- drawing the pop-up into the presented copy (bottom-up RGBA) -------- */

static void fill(unsigned char *rgba, int w, int h, int x0, int y0, int x1, int y1,
                 unsigned char r, unsigned char g, unsigned char b)
{
   /* window coordinates: y down from the top */
   for (int y = y0; y < y1; y++) {
      if (y < 0 || y >= h)
         continue;
      unsigned char *row = rgba + (size_t)(h - 1 - y) * w * 4;
      for (int x = x0; x < x1; x++) {
         if (x < 0 || x >= w)
            continue;
         row[x * 4] = r, row[x * 4 + 1] = g, row[x * 4 + 2] = b, row[x * 4 + 3] = 255;
      }
   }
}

static void text(unsigned char *rgba, int w, int h, int x, int baseline, const char *s,
                 unsigned char c)
{
   for (; *s; s++) {
      const struct glut_bitmap_glyph *g = glut_bitmap_glyph(FONT, (unsigned char)*s);
      if (!g)
         continue;
      int stride = (g->width + 7) / 8;
      for (int j = 0; j < g->height; j++) {
         /* row j is j pixels above the glyph's bottom */
         int wy = baseline + (int)g->yorig - j;
         for (int i = 0; i < g->width; i++) {
            if (!(g->bits[j * stride + i / 8] & (0x80 >> (i % 8))))
               continue;
            int wx = x - (int)g->xorig + i;
            fill(rgba, w, h, wx, wy, wx + 1, wy + 1, c, c, c);
         }
      }
      x += (int)g->advance;
   }
}

void glut_menu_overlay(unsigned char *rgba, int w, int h)
{
   const int ih = glut_menu_item_height();
   for (int level = 0; level < glut_popup.depth; level++) {
      struct glut_menu *m = menu_of(glut_popup.menu[level]);
      if (!m)
         continue;
      int x0 = glut_popup.x[level], y0 = glut_popup.y[level];
      int mw = glut_menu_width(glut_popup.menu[level]);
      fill(rgba, w, h, x0 - 1, y0 - 1, x0 + mw + 1, y0 + m->num_items * ih + 1, 40, 40, 40);
      for (int i = 0; i < m->num_items; i++) {
         bool hl = glut_popup.highlight[level] == i;
         unsigned char bg = hl ? 70 : 215, fg = hl ? 255 : 0;
         fill(rgba, w, h, x0, y0 + i * ih, x0 + mw, y0 + (i + 1) * ih, bg, bg, hl ? 160 : bg);
         text(rgba, w, h, x0 + PAD, y0 + i * ih + ih - 6, m->items[i].label, fg);
         if (m->items[i].is_submenu)
            text(rgba, w, h, x0 + mw - 12, y0 + i * ih + ih - 6, ">", fg);
      }
   }
}
