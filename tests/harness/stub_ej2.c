/*
 * stub_ej2.c - stand-ins for a student's Ejercicio 2 functions, so that
 * `make check` compiles and links the harness (src/grade/functions/
 * harness/ej2.c) with the course's flags: a typo there fails the build's
 * checks, not a student's grade.  Not a model solution: a few return 0.
 */
#include <math.h>
#include <stddef.h>

float producto_interno(const float a[3], const float b[3]);
float norma(const float a[3]);
void normalizar(float a[3]);
void resta(float r[3], const float a[3], const float b[3]);
void interpolar_recta(float p[3], const float o[3], const float d[3],
                      float t);
float distancia_esfera(const float c[3], float r, const float o[3],
                       const float d[3]);
void normal_esfera(float normal[3], const float c[3], float r,
                   const float p[3]);
int computar_intensidad(const float cs[][3], const float rs[],
                        size_t n_esferas, const float luz[3],
                        const float o[3], const float d[3]);
int rayo_student_main(void);

float producto_interno(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

float norma(const float a[3])
{
    return sqrtf(producto_interno(a, a));
}

void normalizar(float a[3])
{
    float n = norma(a);
    a[0] /= n;
    a[1] /= n;
    a[2] /= n;
}

void resta(float r[3], const float a[3], const float b[3])
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

void interpolar_recta(float p[3], const float o[3], const float d[3],
                      float t)
{
    p[0] = o[0] + t * d[0];
    p[1] = o[1] + t * d[1];
    p[2] = o[2] + t * d[2];
}

float distancia_esfera(const float c[3], float r, const float o[3],
                       const float d[3])
{
    (void)c, (void)r, (void)o, (void)d;
    return 0;
}

void normal_esfera(float normal[3], const float c[3], float r,
                   const float p[3])
{
    resta(normal, p, c);
    normal[0] /= r;
    normal[1] /= r;
    normal[2] /= r;
}

int computar_intensidad(const float cs[][3], const float rs[],
                        size_t n_esferas, const float luz[3],
                        const float o[3], const float d[3])
{
    (void)cs, (void)rs, (void)n_esferas, (void)luz, (void)o, (void)d;
    return 5;
}

int rayo_student_main(void)
{
    return 0;
}
