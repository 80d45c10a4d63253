/*
 * ej3_double_vector.c - exercise 3's functions (ej3_base.h) with one mistake:
 * vector_t has double members.
 */
#define MISTAKE_DOUBLE_VECTOR
#include "ej3_base.h"
