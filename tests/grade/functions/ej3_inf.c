/*
 * ej3_inf.c - ej3_nan.c with every computing function returning
 * +infinity (1/0): each comparison must say it, with a likely cause.
 */
static volatile float one = 1;
#define BAD_VALUE (one / zero)
#include "ej3_nan.c"
