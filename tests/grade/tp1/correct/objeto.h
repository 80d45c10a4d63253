#ifndef OBJETO_H
#define OBJETO_H

#include "color.h"
#include "esfera.h"
#include "malla.h"
#include "plano.h"
#include "triangulo.h"
#include "vector.h"

typedef enum { ESFERA, PLANO, TRIANGULO, MALLA } geometria_t;

typedef struct objeto objeto_t;

/* El objeto se adueña de la geometria: destruirlo la destruye, y si no se
   puede crear, la destruye enseguida. */
objeto_t *objeto_crear(geometria_t geometria, void *g, color_t color,
                       float ka, float kd, float ks, float kr);
void objeto_destruir(objeto_t *objeto);
color_t objeto_color(const objeto_t *objeto);
float objeto_ka(const objeto_t *objeto);
float objeto_kd(const objeto_t *objeto);
float objeto_ks(const objeto_t *objeto);
float objeto_kr(const objeto_t *objeto);

float objeto_distancia(const objeto_t *objeto, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal);

#endif
