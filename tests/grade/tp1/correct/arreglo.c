#include <stdlib.h>
#include "arreglo.h"

arreglo_t *arreglo_crear(void)
{
    arreglo_t *a = malloc(sizeof(arreglo_t));
    if (a == NULL)
        return NULL;
    a->v = NULL;
    a->n = 0;
    return a;
}

bool arreglo_agregar(arreglo_t *a, void *e)
{
    void **aux = realloc(a->v, (a->n + 1) * sizeof(void *));
    if (aux == NULL)
        return false;
    a->v = aux;
    a->v[a->n++] = e;
    return true;
}

void arreglo_destruir(arreglo_t *a, void (*destruir)(void *))
{
    size_t i;
    for (i = 0; i < a->n; i++)
        destruir(a->v[i]);
    free(a->v);
    free(a);
}
