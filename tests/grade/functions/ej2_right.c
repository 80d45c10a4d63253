/*
 * ej2_right.c - exercise 2's functions (ej2_base.h) with no mistake: every
 * function right.
 */
#include "ej2_base.h"
