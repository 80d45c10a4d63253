/*
 * ejercicio1.h - the API of the assignment (Ejercicio obligatorio 1), with
 * its Spanish names and exact signatures, so a student's main.c compiles
 * against it unchanged with -std=c99 -Wall -Werror -pedantic and links
 * with -lrayo -lm.
 *
 * The functions are a thin layer over the general library (vec3.h,
 * sphere.h), which computes in double precision; the macros are the
 * assignment's, spelled exactly as it spells them, so a main.c that
 * defines them again the same way still compiles.
 */
#ifndef RAYO_EJERCICIO1_H
#define RAYO_EJERCICIO1_H

#include "rayo/export.h"

#define CX 0.5
#define CY 0.75
#define CZ 1.9
#define R 0.8

#define ANCHO 640
#define ALTO 480
#define FOV 90

#ifdef __cplusplus
extern "C" {
#endif

/* El producto interno (x1, y1, z1) . (x2, y2, z2). */
RAYO_API float producto_interno(float x1, float y1, float z1, float x2,
                                float y2, float z2);

/* La norma del vector (x, y, z). */
RAYO_API float norma(float x, float y, float z);

/*
 * 1 si el rayo desde el origen con dirección unitaria (dx, dy, dz)
 * intersecta la esfera de centro (CX, CY, CZ) y radio R, 0 si no.
 */
RAYO_API int intersecta_esfera(float dx, float dy, float dz);

#ifdef __cplusplus
}
#endif

#endif
