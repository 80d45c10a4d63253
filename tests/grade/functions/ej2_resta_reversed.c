/*
 * ej2_resta_reversed.c - exercise 2's functions (ej2_base.h) with one
 * mistake: resta computes b - a.
 */
#define MISTAKE_RESTA_REVERSED
#include "ej2_base.h"
