/*
 * seed.h - the numbers of the assignment this project started from
 * (Ejercicio obligatorio 1): its sphere, image size and field of view.
 *
 * These are the command's defaults.  ejercicio1.h restates them under the
 * assignment's own names (CX, ANCHO, ...) for student code; a test checks
 * that the two agree.
 */
#ifndef RAYO_SEED_H
#define RAYO_SEED_H

#define RAYO_SEED_CENTER_X 0.5
#define RAYO_SEED_CENTER_Y 0.75
#define RAYO_SEED_CENTER_Z 1.9
#define RAYO_SEED_RADIUS 0.8
#define RAYO_SEED_WIDTH 640
#define RAYO_SEED_HEIGHT 480
#define RAYO_SEED_FOV 90

#endif
