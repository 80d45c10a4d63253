#ifndef PLANO_H
#define PLANO_H

#include "vector.h"

typedef struct plano plano_t;

plano_t *plano_crear(vector_t punto, vector_t normal);
void plano_destruir(plano_t *plano);
float plano_distancia(const plano_t *plano, vector_t o, vector_t d,
                      vector_t *punto, vector_t *normal);

#endif
