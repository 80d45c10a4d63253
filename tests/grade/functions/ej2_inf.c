/*
 * ej2_inf.c - ej2_nan.c with every function returning +infinity (1/0):
 * each comparison must say "(infinity)" with a likely cause.
 */
static volatile float one = 1;
#define BAD_VALUE (one / zero)
#include "ej2_nan.c"
