/*
 * ej3_realloc_direct.c - exercise 3's functions (ej3_base.h) with one
 * mistake: arreglo_agregar assigns realloc's result to a->v directly.
 */
#define MISTAKE_REALLOC_DIRECT
#include "ej3_base.h"
