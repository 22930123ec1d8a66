/*
 * A legacy GLUT demo driven by menus and keys: a pop-up menu on the right
 * button chooses the shape (with submenus for the shading and the polygon
 * mode), keys switch wireframe, shade model and size, the arrow keys and
 * a left-button drag turn the shape, and its name is written with a stroke
 * font.  Single-buffered (glFlush).  Plain GLUT 3.7 code.
 *
 * Keys: w wireframe, s flat/smooth, + / - size, space next shape,
 * arrows turn, Esc quits.
 */
#include <GL/glut.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { TEAPOT, TORUS, CUBE, SPHERE, CONE, ICOSA, DODECA, OCTA, TETRA, NUM_SHAPES };
static const char *const names[NUM_SHAPES] = {
   "Teapot", "Torus", "Cube", "Sphere", "Cone", "Icosahedron", "Dodecahedron",
   "Octahedron", "Tetrahedron" };

static int shape = TEAPOT;
static int wire;
static int flat;
static float size = 1.0f;
static float rot_x = 20.0f, rot_y = 30.0f;
static int drag_x, drag_y, dragging;
static int win_w = 1, win_h = 1;

static void draw_shape(void)
{
   switch (shape) {
   case TEAPOT: wire ? glutWireTeapot(0.8) : glutSolidTeapot(0.8); break;
   case TORUS: wire ? glutWireTorus(0.25, 0.7, 12, 20) : glutSolidTorus(0.25, 0.7, 12, 20); break;
   case CUBE: wire ? glutWireCube(1.2) : glutSolidCube(1.2); break;
   case SPHERE: wire ? glutWireSphere(0.9, 16, 12) : glutSolidSphere(0.9, 16, 12); break;
   case CONE: wire ? glutWireCone(0.7, 1.4, 16, 4) : glutSolidCone(0.7, 1.4, 16, 4); break;
   case ICOSA: wire ? glutWireIcosahedron() : glutSolidIcosahedron(); break;
   case DODECA:
      glScalef(0.55f, 0.55f, 0.55f);
      wire ? glutWireDodecahedron() : glutSolidDodecahedron();
      break;
   case OCTA: wire ? glutWireOctahedron() : glutSolidOctahedron(); break;
   case TETRA: wire ? glutWireTetrahedron() : glutSolidTetrahedron(); break;
   }
}

static void stroke_text(float x, float y, float scale, const char *s)
{
   glPushMatrix();
   glTranslatef(x, y, 0.0f);
   glScalef(scale, scale, scale);
   for (; *s; s++)
      glutStrokeCharacter(GLUT_STROKE_ROMAN, *s);
   glPopMatrix();
}

static void display(void)
{
   char label[64];
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   double aspect = (double)win_w / (double)win_h;
   glOrtho(-1.6 * aspect, 1.6 * aspect, -1.6, 1.6, -10.0, 10.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glEnable(GL_LIGHTING);
   glEnable(GL_DEPTH_TEST);
   glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
   glPushMatrix();
   glRotatef(rot_x, 1.0f, 0.0f, 0.0f);
   glRotatef(rot_y, 0.0f, 1.0f, 0.0f);
   glScalef(size, size, size);
   draw_shape();
   glPopMatrix();

   /* the label, unlit, in window coordinates */
   glDisable(GL_LIGHTING);
   glDisable(GL_DEPTH_TEST);
   glMatrixMode(GL_PROJECTION);
   glLoadIdentity();
   glOrtho(0.0, win_w, 0.0, win_h, -1.0, 1.0);
   glMatrixMode(GL_MODELVIEW);
   glLoadIdentity();
   glColor3f(1.0f, 1.0f, 0.4f);
   snprintf(label, sizeof label, "%s %s %s", names[shape], wire ? "wire" : "solid",
            flat ? "flat" : "smooth");
   stroke_text(8.0f, 8.0f, 0.12f, label);
   glColor3f(0.6f, 0.8f, 1.0f);
   int len = glutStrokeLength(GLUT_STROKE_MONO_ROMAN, (const unsigned char *)"fixgl");
   glPushMatrix();
   glTranslatef(win_w - 8.0f - len * 0.1f, win_h - 20.0f, 0.0f);
   glScalef(0.1f, 0.1f, 0.1f);
   for (const char *p = "fixgl"; *p; p++)
      glutStrokeCharacter(GLUT_STROKE_MONO_ROMAN, *p);
   glPopMatrix();
   glFlush();
}

static void reshape(int w, int h)
{
   win_w = w, win_h = h ? h : 1;
   glViewport(0, 0, w, h);
}

static void choose_shape(int value)
{
   shape = value;
   glutPostRedisplay();
}

static void choose_shading(int value)
{
   flat = value;
   glutPostRedisplay();
}

static void choose_mode(int value)
{
   wire = value;
   glutPostRedisplay();
}

static void main_menu(int value)
{
   if (value == 99)
      exit(0);
}

static void keyboard(unsigned char key, int x, int y)
{
   (void)x, (void)y;
   switch (key) {
   case 'w': wire = !wire; break;
   case 's': flat = !flat; break;
   case '+': size *= 1.2f; break;
   case '-': size /= 1.2f; break;
   case ' ': shape = (shape + 1) % NUM_SHAPES; break;
   case 27: exit(0);
   default: return;
   }
   glutPostRedisplay();
}

static void special(int key, int x, int y)
{
   (void)x, (void)y;
   switch (key) {
   case GLUT_KEY_LEFT: rot_y -= 15.0f; break;
   case GLUT_KEY_RIGHT: rot_y += 15.0f; break;
   case GLUT_KEY_UP: rot_x -= 15.0f; break;
   case GLUT_KEY_DOWN: rot_x += 15.0f; break;
   default: return;
   }
   glutPostRedisplay();
}

static void mouse(int button, int state, int x, int y)
{
   if (button == GLUT_LEFT_BUTTON) {
      dragging = state == GLUT_DOWN;
      drag_x = x, drag_y = y;
   }
}

static void motion(int x, int y)
{
   if (!dragging)
      return;
   rot_y += (float)(x - drag_x);
   rot_x += (float)(y - drag_y);
   drag_x = x, drag_y = y;
   glutPostRedisplay();
}

int main(int argc, char **argv)
{
   static const GLfloat light_pos[] = { 1.0f, 2.0f, 3.0f, 0.0f };
   static const GLfloat diffuse[] = { 0.3f, 0.6f, 0.9f, 1.0f };
   static const GLfloat back[] = { 0.9f, 0.3f, 0.2f, 1.0f };

   glutInit(&argc, argv);
   glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
   glutInitWindowSize(320, 240);
   glutCreateWindow("fixgl: GLUT menus demo");

   glClearColor(0.05f, 0.05f, 0.05f, 1.0f);
   glEnable(GL_LIGHT0);
   glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
   glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
   glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diffuse);
   glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, back);

   int shapes = glutCreateMenu(choose_shape);
   for (int i = 0; i < NUM_SHAPES; i++)
      glutAddMenuEntry(names[i], i);
   int shading = glutCreateMenu(choose_shading);
   glutAddMenuEntry("Smooth", 0);
   glutAddMenuEntry("Flat", 1);
   int mode = glutCreateMenu(choose_mode);
   glutAddMenuEntry("Solid", 0);
   glutAddMenuEntry("Wire", 1);
   glutAddMenuEntry("(removed)", 2);
   glutRemoveMenuItem(3);
   glutCreateMenu(main_menu);
   glutAddSubMenu("Shape", shapes);
   glutAddSubMenu("Shading", shading);
   glutAddSubMenu("Polygons", mode);
   glutAddMenuEntry("Quit", 98);
   glutChangeToMenuEntry(4, "Quit", 99);
   glutAttachMenu(GLUT_RIGHT_BUTTON);

   glutDisplayFunc(display);
   glutReshapeFunc(reshape);
   glutKeyboardFunc(keyboard);
   glutSpecialFunc(special);
   glutMouseFunc(mouse);
   glutMotionFunc(motion);
   glutMainLoop();
   return 0;
}
