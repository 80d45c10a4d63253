/*
 * stub_ej1.c - stand-ins for a student's Ejercicio 1 functions, so that
 * `make check` compiles and links the harness (src/grade/functions/
 * harness/ej1.c) with the course's flags: a typo there fails the build's
 * checks, not a student's grade.  Right answers, not a model solution
 * to grade against.
 */
#include <math.h>

float producto_interno(float x1, float y1, float z1, float x2, float y2,
                       float z2);
float norma(float x, float y, float z);
int intersecta_esfera(float dx, float dy, float dz);

float producto_interno(float x1, float y1, float z1, float x2, float y2,
                       float z2)
{
    return x1 * x2 + y1 * y2 + z1 * z2;
}

float norma(float x, float y, float z)
{
    return sqrtf(producto_interno(x, y, z, x, y, z));
}

int intersecta_esfera(float dx, float dy, float dz)
{
    float b = 0.5f * dx + 0.75f * dy + 1.9f * dz;
    return b * b - (0.25f + 0.5625f + 3.61f) + 0.64f >= 0;
}

int rayo_student_main(void);

int rayo_student_main(void)
{
    return 0;
}
