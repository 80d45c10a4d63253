/*
 * interior_pointer/main.c - a student-style submission for Ejercicio
 * obligatorio 1, written for rayo's grade tests.  Mistake: one row is
 * built in memory from malloc, reused for every row, never freed, and
 * the only pointer left to it at exit points into its middle (valgrind:
 * "possibly lost").
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define CX 0.5
#define CY 0.75
#define CZ 1.9
#define R 0.8

#define ANCHO 640
#define ALTO 480
#define FOV 90

#define PI 3.14159265358979323846

float producto_interno(float x1, float y1, float z1, float x2, float y2,
                       float z2)
{
    return x1 * x2 + y1 * y2 + z1 * z2;
}

float norma(float x, float y, float z)
{
    return sqrt(producto_interno(x, y, z, x, y, z));
}

int intersecta_esfera(float dx, float dy, float dz)
{
    float b = producto_interno(CX, CY, CZ, dx, dy, dz);
    float c = producto_interno(CX, CY, CZ, CX, CY, CZ);
    return b * b - c + R * R >= 0;
}

static int *centro; /* the row's middle pixel */

int main(void)
{
    int x, y;
    float z = ANCHO / (2 * tan(FOV * PI / 180 / 2));
    int *fila = malloc(ANCHO * sizeof *fila);

    if (fila == NULL)
        return 1;
    centro = fila + ANCHO / 2;
    fila = NULL;
    printf("P1\n%d %d\n", ANCHO, ALTO);
    for (y = -ALTO / 2; y < ALTO / 2; y++) {
        int *fila_y = centro - ANCHO / 2;
        for (x = -ANCHO / 2; x < ANCHO / 2; x++) {
            float n = norma(x, -y, z);
            fila_y[x + ANCHO / 2] = intersecta_esfera(x / n, -y / n, z / n);
        }
        for (x = 0; x < ANCHO; x++)
            printf("%d\n", fila_y[x]);
    }
    return 0;
}
