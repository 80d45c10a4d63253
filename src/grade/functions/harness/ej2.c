/*
 * ej2.c - the harness of Ejercicio obligatorio 2's functions (gray,
 * float[3] vectors): the statement's eight functions declared weak with
 * its prototypes, each called on the numbers of a record.  A vector
 * case says its value and the vector it wrote ("result NAME K V X Y
 * Z"); computar_intensidad gets a scene (its spheres' centres and radii,
 * the light and the ray) and says the int it returns.  The cases and
 * their expected values are the grader's table (../ej2.c); the channel
 * and main are rayo_harness.h's.
 */
#define _POSIX_C_SOURCE 200809L
#include <stddef.h>

#include "rayo_harness.h"

#define RAYO_SPHERES 64

float producto_interno(const float a[3], const float b[3])
    __attribute__((weak));
float norma(const float a[3]) __attribute__((weak));
void normalizar(float a[3]) __attribute__((weak));
void resta(float r[3], const float a[3], const float b[3])
    __attribute__((weak));
void interpolar_recta(float p[3], const float o[3], const float d[3],
                      float t) __attribute__((weak));
float distancia_esfera(const float c[3], float r, const float o[3],
                       const float d[3]) __attribute__((weak));
void normal_esfera(float normal[3], const float c[3], float r,
                   const float p[3]) __attribute__((weak));
int computar_intensidad(const float cs[][3], const float rs[],
                        size_t n_esferas, const float luz[3],
                        const float o[3], const float d[3])
    __attribute__((weak));

static int rayo_present(const char *name)
{
    if (strcmp(name, "producto_interno") == 0)
        return producto_interno != 0;
    if (strcmp(name, "norma") == 0)
        return norma != 0;
    if (strcmp(name, "normalizar") == 0)
        return normalizar != 0;
    if (strcmp(name, "resta") == 0)
        return resta != 0;
    if (strcmp(name, "interpolar_recta") == 0)
        return interpolar_recta != 0;
    if (strcmp(name, "distancia_esfera") == 0)
        return distancia_esfera != 0;
    if (strcmp(name, "normal_esfera") == 0)
        return normal_esfera != 0;
    if (strcmp(name, "computar_intensidad") == 0)
        return computar_intensidad != 0;
    return 0;
}

static void rayo_vector(float *v)
{
    v[0] = rayo_float();
    v[1] = rayo_float();
    v[2] = rayo_float();
}

/* computar_intensidad's record: n, n centres, n radii, luz, o, d. */
static void rayo_call_scene(unsigned k)
{
    static float cs[RAYO_SPHERES][3], rs[RAYO_SPHERES];
    float luz[3], o[3], d[3];
    size_t n = (size_t)rayo_number(), i;
    int v;
    if (n > RAYO_SPHERES)
        n = RAYO_SPHERES;
    for (i = 0; i < n; i++)
        rayo_vector(cs[i]);
    for (i = 0; i < n; i++)
        rs[i] = rayo_float();
    rayo_vector(luz);
    rayo_vector(o);
    rayo_vector(d);
    v = computar_intensidad((const float(*)[3])cs, rs, n, luz, o, d);
    rayo_say("result computar_intensidad %u %d", k, v);
}

/* A vector case's record: a, b, c (vectors) and s (a scalar). */
static void rayo_call(const char *name, unsigned k)
{
    float a[3], b[3], c[3], s, r[3] = {0, 0, 0};
    double v = 0;
    if (strcmp(name, "computar_intensidad") == 0) {
        rayo_call_scene(k);
        return;
    }
    rayo_vector(a);
    rayo_vector(b);
    rayo_vector(c);
    s = rayo_float();
    if (strcmp(name, "producto_interno") == 0) {
        v = producto_interno(a, b);
    } else if (strcmp(name, "norma") == 0) {
        v = norma(a);
    } else if (strcmp(name, "normalizar") == 0) {
        normalizar(a);
        r[0] = a[0], r[1] = a[1], r[2] = a[2];
    } else if (strcmp(name, "resta") == 0) {
        resta(r, a, b);
    } else if (strcmp(name, "interpolar_recta") == 0) {
        interpolar_recta(r, a, b, s);
    } else if (strcmp(name, "distancia_esfera") == 0) {
        v = distancia_esfera(a, s, b, c);
    } else {
        normal_esfera(r, a, s, b);
    }
    rayo_say("result %s %u %.9g %.9g %.9g %.9g", name, k, v, r[0], r[1],
             r[2]);
}
