/*
 * ej2_norma_double.c - exercise 2's functions (ej2_base.h) with one mistake:
 * norma returns double.
 */
#define MISTAKE_NORMA_DOUBLE
#include "ej2_base.h"
