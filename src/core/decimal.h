/*
 * decimal.h - reading one decimal number of a text file (a scene, an
 * ASCII STL, an OBJ), exactly as strtod reads it in the C locale, without
 * strtod's cost on the common case.
 *
 * Private to the library.  See decimal.c for why the fast path gives the
 * same double as strtod, bit for bit.
 */
#ifndef RAYO_DECIMAL_H
#define RAYO_DECIMAL_H

#include <stddef.h>

/*
 * 1 and *value when the length bytes at text (not NUL-terminated) are a
 * whole finite decimal number: an optional sign, digits with at most one
 * '.', an optional exponent (no hex, inf or nan spellings), shorter than
 * 64 bytes; the value is strtod's.  0 otherwise (*value then unspecified).
 */
int decimal_read(const char *text, size_t length, double *value);

/* The same through strtod alone: the reference, for tests. */
int decimal_read_strtod(const char *text, size_t length,
                             double *value);

#endif
