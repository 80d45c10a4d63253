/*
 * ej2_normal_crash.c - exercise 2's functions (ej2_base.h) with one mistake:
 * normal_esfera reads through a null pointer.
 */
#define MISTAKE_NORMAL_CRASH
#include "ej2_base.h"
