#include <math.h>
#include <stdlib.h>
#include "triangulo.h"

#define EPSILON_DET 1e-12

struct triangulo {
    vector_t p0, e1, e2;
    vector_t normal;
};

triangulo_t *triangulo_crear_con_normal(vector_t p0, vector_t p1, vector_t p2,
                                        vector_t normal)
{
    triangulo_t *t = malloc(sizeof(triangulo_t));
    if (t == NULL)
        return NULL;
    t->p0 = p0;
    t->e1 = vector_resta(p1, p0);
    t->e2 = vector_resta(p2, p0);
    t->normal = vector_normalizar(normal);
    return t;
}

triangulo_t *triangulo_crear(vector_t p0, vector_t p1, vector_t p2)
{
    vector_t n = vector_producto_vectorial(vector_resta(p1, p0),
                                           vector_resta(p2, p0));
    return triangulo_crear_con_normal(p0, p1, p2, n);
}

void triangulo_destruir(triangulo_t *triangulo)
{
    free(triangulo);
}

float triangulo_distancia(const triangulo_t *tr, vector_t o, vector_t d,
                          vector_t *punto, vector_t *normal)
{
    vector_t h = vector_producto_vectorial(d, tr->e2);
    double a = vector_producto_interno(tr->e1, h);
    vector_t s, q;
    double u, v, t;
    if (fabs(a) < EPSILON_DET)
        return INFINITY;
    s = vector_resta(o, tr->p0);
    u = vector_producto_interno(s, h) / a;
    if (u < 0 || u > 1)
        return INFINITY;
    q = vector_producto_vectorial(s, tr->e1);
    v = vector_producto_interno(d, q) / a;
    if (v < 0 || u + v > 1)
        return INFINITY;
    t = vector_producto_interno(tr->e2, q) / a;
    if (t <= 0)
        return INFINITY;
    *punto = vector_suma(o, vector_escalar(d, t));
    *normal = tr->normal;
    return t;
}
