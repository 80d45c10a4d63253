/*
 * ej3_no_typedef.c - exercise 3's functions (ej3_base.h) with one mistake:
 * vector_t is a struct without a typedef.
 */
#define MISTAKE_NO_TYPEDEF
#include "ej3_base.h"
