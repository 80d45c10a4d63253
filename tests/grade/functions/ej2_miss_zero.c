/*
 * ej2_miss_zero.c - exercise 2's functions (ej2_base.h) with one mistake:
 * distancia_esfera returns 0 on a miss.
 */
#define MISTAKE_MISS_ZERO
#include "ej2_base.h"
