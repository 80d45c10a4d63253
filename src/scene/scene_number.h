/*
 * scene_number.h - reading one number of a scene file, exactly as strtod
 * reads it, without strtod's cost on the common case.
 *
 * Private to the library (scene_file.c).  See scene_number.c for why the
 * fast path gives the same double as strtod, bit for bit.
 */
#ifndef RAYO_SCENE_NUMBER_H
#define RAYO_SCENE_NUMBER_H

#include <stddef.h>

/*
 * 1 and *value when the length bytes at text (not NUL-terminated) are a
 * whole finite decimal number: an optional sign, digits with at most one
 * '.', an optional exponent (no hex, inf or nan spellings), shorter than
 * 64 bytes; the value is strtod's.  0 otherwise (*value then unspecified).
 */
int scene_number_read(const char *text, size_t length, double *value);

/* The same through strtod alone: the reference, for tests. */
int scene_number_read_strtod(const char *text, size_t length,
                             double *value);

#endif
