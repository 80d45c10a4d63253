/*
 * ej3_normal_unnormalised.c - exercise 3's functions (ej3_base.h) with one
 * mistake: esfera_distancia's normal is P - C.
 */
#define MISTAKE_NORMAL_UNNORMALISED
#include "ej3_base.h"
