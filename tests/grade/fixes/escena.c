/*
 * escena.c - exercise 3's constructors and destructors written right,
 * shared by the valgrind fixtures (leak_spheres.c, leak_lights.c,
 * leak_array.c); overrun.c has an arreglo_agregar of its own.
 */
#include "escena.h"

esfera_t *esfera_crear(vector_t centro, float radio, color_t color, float ka,
                       float kd)
{
    esfera_t *e = malloc(sizeof *e);
    if (e == NULL)
        return NULL;
    e->centro = centro;
    e->radio = radio;
    e->color = color;
    e->ka = ka;
    e->kd = kd;
    return e;
}

void esfera_destruir(esfera_t *esfera)
{
    free(esfera);
}

luz_t *luz_crear(vector_t posicion, color_t color, bool es_puntual)
{
    luz_t *l = malloc(sizeof *l);
    if (l == NULL)
        return NULL;
    l->posicion = posicion;
    l->color = color;
    l->es_puntual = es_puntual;
    return l;
}

void luz_destruir(luz_t *luz)
{
    free(luz);
}

#ifndef OWN_ARREGLO_AGREGAR
bool arreglo_agregar(arreglo_t *a, void *e)
{
    void **v = realloc(a->v, (a->n + 1) * sizeof *v);
    if (v == NULL)
        return false;
    v[a->n++] = e;
    a->v = v;
    return true;
}
#endif
