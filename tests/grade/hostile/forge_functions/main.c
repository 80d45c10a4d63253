/*
 * Hostile: forges the functions criterion of Ejercicio obligatorio 1.
 * Every function the statement asks for is wrong (producto_interno adds,
 * norma forgets the square root, intersecta_esfera always says 1), but
 * the first time one of them is called it prints the results the
 * grader expects for all its known inputs (public in rayo's source), as
 * the harness's own lines would read, bare and behind a guessed nonce.
 * main draws the right image with code of its own, so that only the
 * functions criterion is at stake.
 */
#include <math.h>
#include <stdio.h>

#define CX 0.5
#define CY 0.75
#define CZ 1.9
#define R 0.8

#define ANCHO 640
#define ALTO 480
#define FOV 90

#define PI 3.14159265358979323846

static int forged;

static void forge(void)
{
    if (forged)
        return;
    forged = 1;
    printf("\nresult producto_interno 0 32\n"
           "result producto_interno 1 -6.875\n"
           "result producto_interno 2 0.32\n"
           "result norma 0 13\n"
           "result norma 1 0.866025404\n"
           "result norma 2 1.73205081\n"
           "result norma 3 1\n"
           "0123456789abcdef0123456789abcdef result intersecta_esfera 0 1\n"
           "result intersecta_esfera 1 0\n"
           "result intersecta_esfera 2 0\n"
           "result intersecta_esfera 3 1\n"
           "result intersecta_esfera 4 0\n");
    fflush(stdout);
}

float producto_interno(float x1, float y1, float z1, float x2, float y2,
                       float z2)
{
    forge();
    return x1 + x2 + y1 + y2 + z1 + z2;
}

float norma(float x, float y, float z)
{
    forge();
    return x * x + y * y + z * z;
}

int intersecta_esfera(float dx, float dy, float dz)
{
    forge();
    return dx == dx && dy == dy && dz == dz;
}

int main(void)
{
    int x, y;
    double z = ANCHO / (2 * tan(FOV * PI / 180 / 2));

    printf("P1\n%d %d\n", ANCHO, ALTO);
    for (y = -ALTO / 2; y < ALTO / 2; y++) {
        for (x = -ANCHO / 2; x < ANCHO / 2; x++) {
            double n = sqrt(x * x + y * y + z * z);
            double dx = x / n, dy = -y / n, dz = z / n;
            double b = CX * dx + CY * dy + CZ * dz;
            double c = CX * CX + CY * CY + CZ * CZ;
            printf("%d\n", b * b - c + R * R >= 0);
        }
    }
    return 0;
}
