/*
 * ej3_luz_always_point.c - exercise 3's functions (ej3_base.h) with one
 * mistake: luz_crear ignores es_puntual.
 */
#define MISTAKE_LUZ_ALWAYS_POINT
#include "ej3_base.h"
