#ifndef IMAGEN_H
#define IMAGEN_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include "color.h"

/* El tipo imagen que dio la catedra en EJ4. */
typedef struct imagen imagen_t;

imagen_t *imagen_crear(size_t ancho, size_t alto);
void imagen_destruir(imagen_t *im);
void imagen_dimensiones(const imagen_t *im, size_t *ancho, size_t *alto);
bool imagen_set_pixel(imagen_t *im, size_t x, size_t y, color_t color);
color_t imagen_get_pixel(const imagen_t *im, size_t x, size_t y);

void escribir_int16_little_endian(FILE *f, int16_t v);
void escribir_int32_little_endian(FILE *f, int32_t v);
void escribir_PPM(const imagen_t *im, FILE *f);
void escribir_BMP(const imagen_t *im, FILE *f);

#endif
