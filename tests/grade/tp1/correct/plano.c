#include <math.h>
#include <stdlib.h>
#include "plano.h"

struct plano {
    vector_t punto;
    vector_t normal;
};

plano_t *plano_crear(vector_t punto, vector_t normal)
{
    plano_t *p = malloc(sizeof(plano_t));
    if (p == NULL)
        return NULL;
    p->punto = punto;
    p->normal = vector_normalizar(normal);
    return p;
}

void plano_destruir(plano_t *plano)
{
    free(plano);
}

float plano_distancia(const plano_t *plano, vector_t o, vector_t d,
                      vector_t *punto, vector_t *normal)
{
    double dn = vector_producto_interno(d, plano->normal);
    double t;
    if (dn == 0)
        return INFINITY;
    t = vector_producto_interno(vector_resta(plano->punto, o), plano->normal) / dn;
    if (t <= 0)
        return INFINITY;
    *punto = vector_suma(o, vector_escalar(d, t));
    *normal = plano->normal;
    return t;
}
