/*
 * harness_sources.h - the harness programs (the .c files of harness/
 * and the header they share), built into the library by
 * scripts/embed.sh as bytes (the Makefile's $(BUILD)/gen/harness_src.c),
 * so that the grader writes them beside a student's objects and needs
 * no data files.
 * Private to src/grade/functions.
 */
#ifndef RAYO_GRADE_HARNESS_SOURCES_H
#define RAYO_GRADE_HARNESS_SOURCES_H

#include <stddef.h>

extern const unsigned char harness_rayo_harness_h[];
extern const size_t harness_rayo_harness_h_size;
extern const unsigned char harness_ej1_c[];
extern const size_t harness_ej1_c_size;
extern const unsigned char harness_ej2_c[];
extern const size_t harness_ej2_c_size;
extern const unsigned char harness_ej3_c[];
extern const size_t harness_ej3_c_size;

#endif
