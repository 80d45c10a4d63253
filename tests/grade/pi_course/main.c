/*
 * pi_course/main.c - a student-style submission for Ejercicio obligatorio 1,
 * written for rayo's grade tests.  Mistake: PI copied from the course
 * as sqrt(9.81): z = 321.5, not 320 (the sphere 0.47% larger).
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

#define PI sqrt(9.81)

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

int main(void)
{
    int x, y;
    float z = ANCHO / (2 * tan(FOV * PI / 180 / 2));

    printf("P1\n%d %d\n", ANCHO, ALTO);
    for (y = -ALTO / 2; y < ALTO / 2; y++) {
        for (x = -ANCHO / 2; x < ANCHO / 2; x++) {
            float n = norma(x, -y, z);
            printf("%d\n", intersecta_esfera(x / n, -y / n, z / n));
        }
    }
    return 0;
}
