/*
 * ej3_write_past_end.c - exercise 3's functions (ej3_base.h) with one
 * mistake: arreglo_agregar grows a->v to n pointers, then writes v[n].
 */
#define MISTAKE_WRITE_PAST_END
#include "ej3_base.h"
