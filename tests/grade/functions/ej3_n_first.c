/*
 * ej3_n_first.c - exercise 3's functions (ej3_base.h) with one mistake:
 * arreglo_agregar increments a->n before realloc.
 */
#define MISTAKE_N_FIRST
#include "ej3_base.h"
