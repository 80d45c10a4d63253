#ifndef ARREGLO_H
#define ARREGLO_H

#include <stdbool.h>
#include <stddef.h>

/* Arreglo generico de punteros (de EJ3). */
typedef struct {
    void **v;
    size_t n;
} arreglo_t;

arreglo_t *arreglo_crear(void);
bool arreglo_agregar(arreglo_t *a, void *e);
void arreglo_destruir(arreglo_t *a, void (*destruir)(void *));

#endif
