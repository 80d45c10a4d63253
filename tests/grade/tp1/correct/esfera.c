#include <math.h>
#include <stdlib.h>
#include "esfera.h"

struct esfera {
    vector_t centro;
    double radio;
};

esfera_t *esfera_crear(vector_t centro, double radio)
{
    esfera_t *e = malloc(sizeof(esfera_t));
    if (e == NULL)
        return NULL;
    e->centro = centro;
    e->radio = radio;
    return e;
}

void esfera_destruir(esfera_t *esfera)
{
    free(esfera);
}

float esfera_distancia(const esfera_t *esfera, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal)
{
    vector_t oc = vector_resta(o, esfera->centro);
    double b = vector_producto_interno(oc, d);
    double c = vector_producto_interno(oc, oc) - esfera->radio * esfera->radio;
    double delta = b * b - c;
    double t;
    if (delta < 0)
        return INFINITY;
    t = -b - sqrt(delta);
    if (t <= 0)
        t = -b + sqrt(delta);
    if (t <= 0)
        return INFINITY;
    *punto = vector_suma(o, vector_escalar(d, t));
    *normal = vector_normalizar(vector_resta(*punto, esfera->centro));
    return t;
}
