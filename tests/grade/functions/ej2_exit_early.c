/*
 * ej2_exit_early.c - exercise 2's functions (ej2_base.h) with one
 * mistake: norma ends the program with exit(0) instead of returning.
 * The harness then never reaches its last line, and the call is named;
 * before the channel had a "done" line this passed unnoticed.
 */
#define MISTAKE_NORMA_EXITS
#include "ej2_base.h"
