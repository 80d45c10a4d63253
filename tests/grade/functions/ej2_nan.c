/*
 * ej2_nan.c - exercise 2's eight functions, each returning (or writing)
 * NaN, as 0/0 gives it: every comparison of the functions criterion must
 * say "nan (not a number)" with a likely cause, and computar_intensidad's
 * int must be recognised as what a NaN becomes through (int).  With
 * BAD_VALUE defined first (ej2_inf.c) they return that instead.
 */
#include <stddef.h>

static volatile float zero;

#ifndef BAD_VALUE
#define BAD_VALUE (zero / zero)
#endif

float producto_interno(const float a[3], const float b[3])
{
    (void)a;
    (void)b;
    return BAD_VALUE;
}

float norma(const float a[3])
{
    (void)a;
    return BAD_VALUE;
}

void normalizar(float a[3])
{
    a[0] = a[1] = a[2] = BAD_VALUE;
}

void resta(float r[3], const float a[3], const float b[3])
{
    (void)a;
    (void)b;
    r[0] = r[1] = r[2] = BAD_VALUE;
}

void interpolar_recta(float p[3], const float o[3], const float d[3],
                      float t)
{
    (void)o;
    (void)d;
    (void)t;
    p[0] = p[1] = p[2] = BAD_VALUE;
}

float distancia_esfera(const float c[3], float r, const float o[3],
                       const float d[3])
{
    (void)c;
    (void)r;
    (void)o;
    (void)d;
    return BAD_VALUE;
}

void normal_esfera(float normal[3], const float c[3], float r,
                   const float p[3])
{
    (void)c;
    (void)r;
    (void)p;
    normal[0] = normal[1] = normal[2] = BAD_VALUE;
}

int computar_intensidad(const float cs[][3], const float rs[],
                        size_t n_esferas, const float luz[3],
                        const float o[3], const float d[3])
{
    float i = BAD_VALUE;
    (void)cs;
    (void)rs;
    (void)n_esferas;
    (void)luz;
    (void)o;
    (void)d;
    return (int)i;
}

int main(void)
{
    return 0;
}
