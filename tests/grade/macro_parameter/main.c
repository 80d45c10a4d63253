/*
 * macro_parameter/main.c - a student-style submission for Ejercicio
 * obligatorio 1, written for rayo's grade tests.
 * Mistake: producto_interno's parameters are called CX, CY, CZ, the
 * names of the file's macros for the sphere's centre, so the
 * preprocessor turns them into numbers and it does not compile.
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

float producto_interno(float CX, float CY, float CZ, float x2, float y2,
                       float z2)
{
    return CX * x2 + CY * y2 + CZ * z2;
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
