/*
 * ej2_near_root_always.c - exercise 2's functions (ej2_base.h) with one
 * mistake: distancia_esfera returns beta - sqrt(delta) even when it is
 * negative.
 */
#define MISTAKE_NEAR_ROOT_ALWAYS
#include "ej2_base.h"
