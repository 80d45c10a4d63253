#ifndef MALLA_H
#define MALLA_H

#include "vector.h"

typedef struct malla malla_t;

/* Lee un STL binario y ubica cada triangulo: escala s, rotacion en grados
   alrededor de x, luego y, luego z, y traslacion t. NULL si falla. */
malla_t *malla_crear_desde_stl(const char *archivo, double s, vector_t grados,
                               vector_t t);
void malla_destruir(malla_t *malla);
/* La del triangulo mas cercano. */
float malla_distancia(const malla_t *malla, vector_t o, vector_t d,
                      vector_t *punto, vector_t *normal);

#endif
