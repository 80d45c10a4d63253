/*
 * ej3_imprimir_rounds.c - exercise 3's functions (ej3_base.h) with one
 * mistake: color_imprimir rounds 255 c.
 */
#define MISTAKE_IMPRIMIR_ROUNDS
#include "ej3_base.h"
