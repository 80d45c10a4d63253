/*
 * ej3_sumar_double.c - exercise 3's functions (ej3_base.h) with one mistake:
 * color_sumar takes a double p.
 */
#define MISTAKE_SUMAR_DOUBLE
#include "ej3_base.h"
