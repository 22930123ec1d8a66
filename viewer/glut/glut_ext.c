/*
 * glutGetProcAddress (freeglut's fg_ext.c): a glut* name is one of
 * libfixglut's functions, looked up in the table below (every function
 * the library exports); any other name is asked of the GL library the
 * layer renders with, through OSMesaGetProcAddress (fixgl's, or Mesa's
 * for libfixglut-osmesa), as freeglut asks glXGetProcAddressARB.
 */
#include <GL/freeglut_ext.h>
#include <string.h>

#include "glut_internal.h"

/* void (*)(void) is the generic function pointer of GLUTproc; a
 * function's own type is restored by the caller's cast */
#define GLUT_PROC(name) { #name, (GLUTproc)name },

static const struct {
   const char *name;
   GLUTproc proc;
} glut_procs[] = {
   GLUT_PROC(glutAddMenuEntry)
   GLUT_PROC(glutAddSubMenu)
   GLUT_PROC(glutAttachMenu)
   GLUT_PROC(glutBitmapCharacter)
   GLUT_PROC(glutBitmapHeight)
   GLUT_PROC(glutBitmapLength)
   GLUT_PROC(glutBitmapString)
   GLUT_PROC(glutBitmapWidth)
   GLUT_PROC(glutChangeToMenuEntry)
   GLUT_PROC(glutChangeToSubMenu)
   GLUT_PROC(glutCloseFunc)
   GLUT_PROC(glutCreateMenu)
   GLUT_PROC(glutCreateWindow)
   GLUT_PROC(glutDestroyMenu)
   GLUT_PROC(glutDestroyWindow)
   GLUT_PROC(glutDetachMenu)
   GLUT_PROC(glutDeviceGet)
   GLUT_PROC(glutDisplayFunc)
   GLUT_PROC(glutEntryFunc)
   GLUT_PROC(glutExit)
   GLUT_PROC(glutExtensionSupported)
   GLUT_PROC(glutFullScreen)
   GLUT_PROC(glutFullScreenToggle)
   GLUT_PROC(glutGet)
   GLUT_PROC(glutGetMenu)
   GLUT_PROC(glutGetModifiers)
   GLUT_PROC(glutGetWindow)
   GLUT_PROC(glutGetWindowData)
   GLUT_PROC(glutHideWindow)
   GLUT_PROC(glutIconifyWindow)
   GLUT_PROC(glutIdleFunc)
   GLUT_PROC(glutInit)
   GLUT_PROC(glutInitContextFlags)
   GLUT_PROC(glutInitContextProfile)
   GLUT_PROC(glutInitContextVersion)
   GLUT_PROC(glutInitDisplayMode)
   GLUT_PROC(glutInitDisplayString)
   GLUT_PROC(glutInitErrorFunc)
   GLUT_PROC(glutInitWarningFunc)
   GLUT_PROC(glutInitWindowPosition)
   GLUT_PROC(glutInitWindowSize)
   GLUT_PROC(glutKeyboardFunc)
   GLUT_PROC(glutKeyboardUpFunc)
   GLUT_PROC(glutLeaveFullScreen)
   GLUT_PROC(glutLeaveMainLoop)
   GLUT_PROC(glutMainLoop)
   GLUT_PROC(glutMainLoopEvent)
   GLUT_PROC(glutMenuStateFunc)
   GLUT_PROC(glutMenuStatusFunc)
   GLUT_PROC(glutMotionFunc)
   GLUT_PROC(glutMouseFunc)
   GLUT_PROC(glutPassiveMotionFunc)
   GLUT_PROC(glutPositionWindow)
   GLUT_PROC(glutPostRedisplay)
   GLUT_PROC(glutRemoveMenuItem)
   GLUT_PROC(glutReshapeFunc)
   GLUT_PROC(glutReshapeWindow)
   GLUT_PROC(glutSetCursor)
   GLUT_PROC(glutSetIconTitle)
   GLUT_PROC(glutSetMenu)
   GLUT_PROC(glutSetOption)
   GLUT_PROC(glutSetWindow)
   GLUT_PROC(glutSetWindowData)
   GLUT_PROC(glutSetWindowTitle)
   GLUT_PROC(glutShowWindow)
   GLUT_PROC(glutSolidCone)
   GLUT_PROC(glutSolidCube)
   GLUT_PROC(glutSolidCylinder)
   GLUT_PROC(glutSolidDodecahedron)
   GLUT_PROC(glutSolidIcosahedron)
   GLUT_PROC(glutSolidOctahedron)
   GLUT_PROC(glutSolidSphere)
   GLUT_PROC(glutSolidTeapot)
   GLUT_PROC(glutSolidTetrahedron)
   GLUT_PROC(glutSolidTorus)
   GLUT_PROC(glutSpecialFunc)
   GLUT_PROC(glutSpecialUpFunc)
   GLUT_PROC(glutStrokeCharacter)
   GLUT_PROC(glutStrokeHeight)
   GLUT_PROC(glutStrokeLength)
   GLUT_PROC(glutStrokeString)
   GLUT_PROC(glutStrokeWidth)
   GLUT_PROC(glutSwapBuffers)
   GLUT_PROC(glutTimerFunc)
   GLUT_PROC(glutVisibilityFunc)
   GLUT_PROC(glutWMCloseFunc)
   GLUT_PROC(glutWarpPointer)
   GLUT_PROC(glutWireCone)
   GLUT_PROC(glutWireCube)
   GLUT_PROC(glutWireCylinder)
   GLUT_PROC(glutWireDodecahedron)
   GLUT_PROC(glutWireIcosahedron)
   GLUT_PROC(glutWireOctahedron)
   GLUT_PROC(glutWireSphere)
   GLUT_PROC(glutWireTeapot)
   GLUT_PROC(glutWireTetrahedron)
   GLUT_PROC(glutWireTorus)
};

GLUT_EXPORT GLUTproc glutGetProcAddress(const char *name)
{
   if (!name)
      return NULL;
   if (strncmp(name, "glut", 4) == 0) {
      for (size_t i = 0; i < sizeof glut_procs / sizeof glut_procs[0]; i++)
         if (strcmp(glut_procs[i].name, name) == 0)
            return glut_procs[i].proc;
      if (strcmp(name, "glutGetProcAddress") == 0)
         return (GLUTproc)glutGetProcAddress;
      return NULL;
   }
   return (GLUTproc)OSMesaGetProcAddress(name);
}
