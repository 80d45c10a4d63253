/*
 * ej2_norma_hangs.c - exercise 2's functions (ej2_base.h) with one
 * mistake: norma never returns.
 */
#define MISTAKE_NORMA_HANGS
#include "ej2_base.h"
