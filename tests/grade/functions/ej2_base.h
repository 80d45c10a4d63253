/*
 * ej2_base.h - exercise 2's eight functions, right, for the fixtures of
 * tests/cli/grade_functions.t and tests/unit/t_grade_functions.c: each
 * fixture defines one MISTAKE_* and includes this file, so that it has
 * exactly one mistake.  main does nothing: only the functions criterion
 * is under test.
 */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#define INFINITO FLT_MAX
#define IA 5
#define II 255

float producto_interno(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

#ifdef MISTAKE_NORMA_DOUBLE
double norma(const float a[3])
#else
float norma(const float a[3])
#endif
{
#ifdef MISTAKE_NORMA_HANGS
    for (;;)
        ;
#endif
#ifdef MISTAKE_NORMA_EXITS
    exit(0);
#endif
    return sqrt(producto_interno(a, a));
}

void normalizar(float a[3])
{
#ifdef MISTAKE_NORMALIZAR_COPY
    float b[3] = {a[0], a[1], a[2]};
    float n = norma(b);
    b[0] /= n;
    b[1] /= n;
    b[2] /= n;
#else
    float n = norma(a);
    a[0] /= n;
    a[1] /= n;
    a[2] /= n;
#endif
}

void resta(float r[3], const float a[3], const float b[3])
{
#ifdef MISTAKE_RESTA_REVERSED
    r[0] = b[0] - a[0];
    r[1] = b[1] - a[1];
    r[2] = b[2] - a[2];
#else
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
#endif
}

void interpolar_recta(float p[3], const float o[3], const float d[3], float t)
{
    p[0] = o[0] + t * d[0];
    p[1] = o[1] + t * d[1];
    p[2] = o[2] + t * d[2];
}

float distancia_esfera(const float c[3], float r, const float o[3],
                       const float d[3])
{
    float oc[3];
    resta(oc, c, o);
    float beta = producto_interno(oc, d);
    float delta = beta * beta - producto_interno(oc, oc) + r * r;
    if (delta < 0)
#ifdef MISTAKE_MISS_ZERO
        return 0;
#else
        return INFINITO;
#endif
#ifdef MISTAKE_NEAR_ROOT_ALWAYS
    return beta - sqrt(delta);
#else
    if (beta - sqrt(delta) > 0)
        return beta - sqrt(delta);
    if (beta + sqrt(delta) > 0)
        return beta + sqrt(delta);
    return INFINITO;
#endif
}

void normal_esfera(float normal[3], const float c[3], float r,
                   const float p[3])
{
#ifdef MISTAKE_NORMAL_CRASH
    const float *nowhere = NULL;
    r = nowhere[(size_t)p[0] % 2];
#endif
    resta(normal, p, c);
    normal[0] /= r;
    normal[1] /= r;
    normal[2] /= r;
}

#ifndef MISTAKE_NO_INTENSIDAD
int computar_intensidad(const float cs[][3], const float rs[],
                        size_t n_esferas, const float luz[3],
                        const float o[3], const float d[3])
{
    float t_min = INFINITO;
    size_t i_min = 0;
    for (size_t i = 0; i < n_esferas; i++) {
        float t = distancia_esfera(cs[i], rs[i], o, d);
        if (t < t_min) {
            t_min = t;
            i_min = i;
        }
    }
    if (t_min == INFINITO)
        return 0;
    float p[3], normal[3];
    interpolar_recta(p, o, d, t_min);
    normal_esfera(normal, cs[i_min], rs[i_min], p);
    float ln = producto_interno(luz, normal);
    if (ln <= 0)
        return IA;
    for (size_t i = 0; i < n_esferas; i++) {
        if (i == i_min)
            continue;
#ifdef MISTAKE_SHADOW_BEHIND
        float oc[3];
        resta(oc, cs[i], p);
        float beta = producto_interno(oc, luz);
        if (beta * beta - producto_interno(oc, oc) + rs[i] * rs[i] >= 0)
            return IA;
#else
        if (distancia_esfera(cs[i], rs[i], p, luz) < INFINITO)
            return IA;
#endif
    }
    float intensidad = IA + II * ln;
    if (intensidad > 255)
        return 255;
    return intensidad;
}
#endif

int main(void)
{
    return 0;
}
