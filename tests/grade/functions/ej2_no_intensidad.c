/*
 * ej2_no_intensidad.c - exercise 2's functions (ej2_base.h) with one mistake:
 * computar_intensidad is not defined.
 */
#define MISTAKE_NO_INTENSIDAD
#include "ej2_base.h"
