/*
 * ej2_normalizar_copy.c - exercise 2's functions (ej2_base.h) with one
 * mistake: normalizar normalises a copy, not a.
 */
#define MISTAKE_NORMALIZAR_COPY
#include "ej2_base.h"
