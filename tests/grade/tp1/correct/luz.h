#ifndef LUZ_H
#define LUZ_H

#include <stdbool.h>
#include "color.h"
#include "vector.h"

/* Una luz puntual (posicion) o no puntual (direccion hacia la luz). */
typedef struct {
    vector_t posicion;
    color_t color;
    bool es_puntual;
} luz_t;

luz_t *luz_crear(vector_t posicion, color_t color, bool es_puntual);
void luz_destruir(void *luz);
/* La direccion unitaria desde p hacia la luz. */
vector_t luz_direccion(const luz_t *luz, vector_t p);

#endif
