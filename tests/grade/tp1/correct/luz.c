#include <stdlib.h>
#include "luz.h"

luz_t *luz_crear(vector_t posicion, color_t color, bool es_puntual)
{
    luz_t *l = malloc(sizeof(luz_t));
    if (l == NULL)
        return NULL;
    l->posicion = es_puntual ? posicion : vector_normalizar(posicion);
    l->color = color;
    l->es_puntual = es_puntual;
    return l;
}

void luz_destruir(void *luz)
{
    free(luz);
}

vector_t luz_direccion(const luz_t *luz, vector_t p)
{
    if (luz->es_puntual)
        return vector_normalizar(vector_resta(luz->posicion, p));
    return luz->posicion;
}
