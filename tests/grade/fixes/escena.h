/*
 * escena.h - the part of exercise 3's statement that the valgrind
 * fixtures beside it share: its types and constructors, as a student
 * writes them.  Each fixture makes one memory mistake with them, for
 * rayo's grade tests (tests/cli/grade_fixes.t).
 */
#ifndef ESCENA_H
#define ESCENA_H

#include <stdbool.h>
#include <stdlib.h>

typedef struct { float x, y, z; } vector_t;
typedef struct { float r, g, b; } color_t;
typedef struct { vector_t centro; float radio; color_t color; float ka, kd; } esfera_t;
typedef struct { vector_t posicion; color_t color; bool es_puntual; } luz_t;
typedef struct { void **v; size_t n; } arreglo_t;

esfera_t *esfera_crear(vector_t centro, float radio, color_t color, float ka,
                       float kd);
void esfera_destruir(esfera_t *esfera);
luz_t *luz_crear(vector_t posicion, color_t color, bool es_puntual);
void luz_destruir(luz_t *luz);
bool arreglo_agregar(arreglo_t *a, void *e);

#endif
