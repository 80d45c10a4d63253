/*
 * baseline.c - the straightforward solution of the assignment, written
 * the way the assignment asks for it: producto_interno, norma and
 * intersecta_esfera on floats, and one printf per pixel.  It is what the
 * seed job is measured against (the issue asks for at least 8x), not
 * code rayo uses; its functions are static so they do not collide with
 * the library's seed API of the same names.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>

#include "bench.h"

#define CX 0.5
#define CY 0.75
#define CZ 1.9
#define R 0.8
#define ANCHO 640
#define ALTO 480
#define FOV 90
#define PI 3.14159265358979323846

static float producto_interno(float x1, float y1, float z1, float x2,
                              float y2, float z2)
{
    return x1 * x2 + y1 * y2 + z1 * z2;
}

static float norma(float x, float y, float z)
{
    return sqrtf(producto_interno(x, y, z, x, y, z));
}

static int intersecta_esfera(float dx, float dy, float dz)
{
    float cd = producto_interno((float)CX, (float)CY, (float)CZ, dx, dy, dz);
    float cc = producto_interno((float)CX, (float)CY, (float)CZ, (float)CX,
                                (float)CY, (float)CZ);
    return cd * cd - cc + (float)(R * R) >= 0;
}

void bench_baseline_seed(int fd)
{
    FILE *out = fdopen(fd, "w");
    float z = (float)(ANCHO / (2 * tan(FOV * PI / 360.0)));
    int x, y;
    if (out == NULL)
        return;
    fprintf(out, "P1\n%d %d\n", ANCHO, ALTO);
    for (y = -ALTO / 2; y < ALTO / 2; y++)
        for (x = -ANCHO / 2; x < ANCHO / 2; x++) {
            float n = norma((float)x, (float)-y, z);
            fprintf(out, "%d\n",
                    intersecta_esfera((float)x / n, (float)-y / n, z / n));
        }
    fclose(out);
}
