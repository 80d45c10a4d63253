#ifndef TRIANGULO_H
#define TRIANGULO_H

#include "vector.h"

typedef struct triangulo triangulo_t;

/* La normal es normalizar((p1 - p0) x (p2 - p0)). */
triangulo_t *triangulo_crear(vector_t p0, vector_t p1, vector_t p2);
/* Con la normal dada (la del archivo STL). */
triangulo_t *triangulo_crear_con_normal(vector_t p0, vector_t p1, vector_t p2,
                                        vector_t normal);
void triangulo_destruir(triangulo_t *triangulo);
/* Moller-Trumbore. */
float triangulo_distancia(const triangulo_t *triangulo, vector_t o, vector_t d,
                          vector_t *punto, vector_t *normal);

#endif
