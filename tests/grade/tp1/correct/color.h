#ifndef COLOR_H
#define COLOR_H

#include <stdio.h>

/* Colores RGB con componentes reales (de EJ3). */
typedef struct {
    float r, g, b;
} color_t;

color_t color_crear(float r, float g, float b);
color_t color_sumar(color_t c, color_t m, float p);
color_t color_absorber(color_t b, color_t c);
/* Un canal por encima de 1 es 255; si no, la parte entera de 255 c. */
unsigned char color_byte(float c);
void color_imprimir(color_t c, FILE *f);

#endif
