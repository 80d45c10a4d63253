/*
 * ej1.c - the harness of Ejercicio obligatorio 1's functions:
 * producto_interno, norma and intersecta_esfera, declared weak with the
 * assignment's signatures (so that a missing one is said, not a link
 * error), each called on the numbers of a record and its value said.
 * Which calls, on what, and what they should return is the grader's
 * table (../ej1.c); the channel and main are rayo_harness.h's.
 */
#define _POSIX_C_SOURCE 200809L
#include "rayo_harness.h"

float producto_interno(float x1, float y1, float z1, float x2, float y2,
                       float z2) __attribute__((weak));
float norma(float x, float y, float z) __attribute__((weak));
int intersecta_esfera(float dx, float dy, float dz) __attribute__((weak));

static int rayo_present(const char *name)
{
    if (strcmp(name, "producto_interno") == 0)
        return producto_interno != 0;
    if (strcmp(name, "norma") == 0)
        return norma != 0;
    if (strcmp(name, "intersecta_esfera") == 0)
        return intersecta_esfera != 0;
    return 0;
}

static void rayo_call(const char *name, unsigned k)
{
    float a[6];
    double v;
    int i;
    for (i = 0; i < 6; i++)
        a[i] = rayo_float();
    if (strcmp(name, "producto_interno") == 0)
        v = (double)producto_interno(a[0], a[1], a[2], a[3], a[4], a[5]);
    else if (strcmp(name, "norma") == 0)
        v = (double)norma(a[0], a[1], a[2]);
    else
        v = (double)intersecta_esfera(a[0], a[1], a[2]);
    rayo_say("result %s %u %.9g", name, k, v);
}
