/*
 * ej2_shadow_behind.c - exercise 2's functions (ej2_base.h) with one mistake:
 * a sphere behind the point (delta >= 0, any t) casts a shadow.
 */
#define MISTAKE_SHADOW_BEHIND
#include "ej2_base.h"
