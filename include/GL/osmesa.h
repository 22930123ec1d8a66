#ifndef OSMESA_H
#define OSMESA_H
#endif
