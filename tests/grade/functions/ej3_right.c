/*
 * ej3_right.c - exercise 3's functions (ej3_base.h) with no mistake: every
 * type and function right.
 */
#include "ej3_base.h"
