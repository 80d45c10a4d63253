/*
 * ej3_crear_swaps.c - exercise 3's functions (ej3_base.h) with one mistake:
 * esfera_crear swaps ka and kd.
 */
#define MISTAKE_CREAR_SWAPS
#include "ej3_base.h"
