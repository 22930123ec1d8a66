/*
 * glut-api: the layer's bookkeeping, headless (run with FIXGLUT_HEADLESS=1,
 * FIXGLUT_FRAMES=6, FIXGLUT_FRAME_MS=16 and the FIXGLUT_EVENTS of
 * tests/meson.build): argument parsing, display-mode buffers, glutGet,
 * the deterministic clock and timers, scripted events and modifiers,
 * reshape, menus, font metrics.  glutMainLoop exits the process; the
 * verdict is given by an atexit handler.
 */
#include <GL/glut.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int checks, failures;
static int frames_displayed, timer_frame = -1, reshapes, last_w, last_h;
static int key_seen, key_mods = -1, special_seen, mouse_seen, menu_value = -1, menu_current;
static int menu_id;

#define CHECK(cond)                                                              \
   do {                                                                          \
      checks++;                                                                  \
      if (!(cond)) {                                                             \
         failures++;                                                             \
         fprintf(stderr, "glut-api: %s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      }                                                                          \
   } while (0)

static void verdict(void)
{
   /* state reached through the scripted events and the loop */
   CHECK(frames_displayed == 2);           /* frame 0, and after the reshape of frame 5 */
   CHECK(timer_frame == 48);               /* 40 ms timer: first frame at >= 40 ms is 3 */
   CHECK(key_seen == 'x');
   CHECK(key_mods == GLUT_ACTIVE_SHIFT);
   CHECK(special_seen == GLUT_KEY_F5);
   CHECK(mouse_seen == 1);
   CHECK(menu_value == 42);
   CHECK(menu_current == menu_id);
   CHECK(reshapes == 2 && last_w == 64 && last_h == 48);
   printf("glut-api: %d checks, %d failed\n", checks, failures);
   fflush(stdout);
   if (failures)
      _exit(1);
}

static void display(void)
{
   frames_displayed++;
   glClear(GL_COLOR_BUFFER_BIT);
   glutSwapBuffers();
}

static void reshape(int w, int h)
{
   reshapes++;
   last_w = w, last_h = h;
   CHECK(glutGet(GLUT_WINDOW_WIDTH) == w && glutGet(GLUT_WINDOW_HEIGHT) == h);
   glViewport(0, 0, w, h);
}

static void timer(int value)
{
   CHECK(value == 7);
   timer_frame = glutGet(GLUT_ELAPSED_TIME);
}

static void keyboard(unsigned char key, int x, int y)
{
   key_seen = key;
   key_mods = glutGetModifiers();
   CHECK(x == 10 && y == 20);
}

static void special(int key, int x, int y)
{
   (void)x, (void)y;
   special_seen = key;
}

static void mouse(int button, int state, int x, int y)
{
   if (button == GLUT_LEFT_BUTTON && state == GLUT_DOWN && x == 3 && y == 4)
      mouse_seen = 1;
}

static void menu(int value)
{
   menu_value = value;
   menu_current = glutGetMenu();
}

static void submenu(int value)
{
   (void)value;
}

int main(void)
{
   char *argv[] = { "glut-api", "-geometry", "80x60+5+6", "-display", ":0", "-iconic", "kept",
                    NULL };
   int argc = 7;
   atexit(verdict);

   glutInit(&argc, argv);
   CHECK(argc == 2 && !strcmp(argv[1], "kept") && argv[2] == NULL);
   CHECK(glutGet(GLUT_INIT_WINDOW_WIDTH) == 80 && glutGet(GLUT_INIT_WINDOW_HEIGHT) == 60);
   CHECK(glutGet(GLUT_INIT_WINDOW_X) == 5 && glutGet(GLUT_INIT_WINDOW_Y) == 6);
   glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH | GLUT_STENCIL | GLUT_ACCUM);
   CHECK(glutGet(GLUT_INIT_DISPLAY_MODE) == (GLUT_DOUBLE | GLUT_DEPTH | GLUT_STENCIL | GLUT_ACCUM));
   CHECK(glutCreateWindow("api") == 1);
   CHECK(glutGetWindow() == 1);
   CHECK(glutGet(GLUT_WINDOW_WIDTH) == 80 && glutGet(GLUT_WINDOW_HEIGHT) == 60);
   CHECK(glutGet(GLUT_WINDOW_DEPTH_SIZE) == 24);
   CHECK(glutGet(GLUT_WINDOW_STENCIL_SIZE) == 8);
   CHECK(glutGet(GLUT_WINDOW_ACCUM_RED_SIZE) == 16);
   CHECK(glutGet(GLUT_WINDOW_RED_SIZE) == 8 && glutGet(GLUT_WINDOW_ALPHA_SIZE) == 8);
   CHECK(glutGet(GLUT_WINDOW_DOUBLEBUFFER) == 1 && glutGet(GLUT_WINDOW_RGBA) == 1);
   CHECK(glutGet(GLUT_SCREEN_WIDTH) == 1280 && glutGet(GLUT_SCREEN_HEIGHT) == 1024);
   CHECK(glutGet(GLUT_ELAPSED_TIME) == 0);
   CHECK(glutDeviceGet(GLUT_NUM_MOUSE_BUTTONS) == 3);
   CHECK(glutExtensionSupported("GL_EXT_blend_color") ==
         (strstr((const char *)glGetString(GL_EXTENSIONS), "GL_EXT_blend_color") != NULL));
   CHECK(!glutExtensionSupported("GL_EXT_blend"));   /* a prefix is not a name */

   /* fonts */
   CHECK(glutBitmapWidth(GLUT_BITMAP_8_BY_13, 'W') == 8);
   CHECK(glutBitmapWidth(GLUT_BITMAP_9_BY_15, 'i') == 9);
   CHECK(glutBitmapLength(GLUT_BITMAP_8_BY_13, (const unsigned char *)"abc") == 24);
   CHECK(glutBitmapHeight(GLUT_BITMAP_HELVETICA_18) == 23);
   CHECK(glutBitmapWidth(GLUT_BITMAP_HELVETICA_12, 'i') < glutBitmapWidth(GLUT_BITMAP_HELVETICA_12, 'W'));
   CHECK(glutStrokeWidth(GLUT_STROKE_MONO_ROMAN, 'i') == 105);
   CHECK(glutStrokeWidth(GLUT_STROKE_MONO_ROMAN, 'W') == 105);
   CHECK(glutStrokeLength(GLUT_STROKE_MONO_ROMAN, (const unsigned char *)"abcd") == 419);
   CHECK(glutStrokeWidth(GLUT_STROKE_ROMAN, 'i') < glutStrokeWidth(GLUT_STROKE_ROMAN, 'm'));
   CHECK(glutStrokeHeight(GLUT_STROKE_ROMAN) > 119.0f && glutStrokeHeight(GLUT_STROKE_ROMAN) < 119.1f);

   /* menus */
   int sub = glutCreateMenu(submenu);
   glutAddMenuEntry("s1", 1);
   menu_id = glutCreateMenu(menu);
   CHECK(glutGetMenu() == menu_id && sub != menu_id);
   glutAddMenuEntry("one", 1);
   glutAddSubMenu("sub", sub);
   glutAddMenuEntry("three", 3);
   CHECK(glutGet(GLUT_MENU_NUM_ITEMS) == 3);
   glutChangeToMenuEntry(3, "answer", 42);
   glutRemoveMenuItem(1);
   CHECK(glutGet(GLUT_MENU_NUM_ITEMS) == 2);
   glutAttachMenu(GLUT_RIGHT_BUTTON);
   glutSetMenu(sub);
   CHECK(glutGetMenu() == sub);

   glutDisplayFunc(display);
   glutReshapeFunc(reshape);
   glutKeyboardFunc(keyboard);
   glutSpecialFunc(special);
   glutMouseFunc(mouse);
   glutTimerFunc(40, timer, 7);
   glutMainLoop();
   return 1;   /* not reached */
}
