/* fixgl native API */
#ifndef FIXGL_FIXGL_H
#define FIXGL_FIXGL_H
#endif
