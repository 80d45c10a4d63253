#ifndef ESFERA_H
#define ESFERA_H

#include "vector.h"

typedef struct esfera esfera_t;

esfera_t *esfera_crear(vector_t centro, double radio);
void esfera_destruir(esfera_t *esfera);
/* La distancia t > 0 a lo largo de o + t d (d unitario), o INFINITY. */
float esfera_distancia(const esfera_t *esfera, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal);

#endif
