/*
 * ej3_beyond_light.c - exercise 3's functions (ej3_base.h) with one mistake:
 * a sphere beyond a point light casts a shadow.
 */
#define MISTAKE_BEYOND_LIGHT
#include "ej3_base.h"
