/*
 * fixgl's <GL/freeglut.h>: as freeglut's, the standard API (<GL/glut.h>,
 * freeglut's freeglut_std.h) and the extensions (<GL/freeglut_ext.h>)
 * that libfixglut provides.
 */
#ifndef FIXGL_FREEGLUT_H
#define FIXGL_FREEGLUT_H

#include <GL/glut.h>
#include <GL/freeglut_ext.h>

#endif /* FIXGL_FREEGLUT_H */
