/*
 * tp1.h - what the files that grade a whole program (TP1) share: its
 * source checks, its runs, and the check of the BMP it writes.  Private
 * to src/grade; grade_impl.h declares the step grade.c calls.
 */
#ifndef RAYO_GRADE_TP1_H
#define RAYO_GRADE_TP1_H

#include <stddef.h>
#include <stdint.h>

#include "grade_impl.h"

/* tp1_source.c: the statement's two prototypes and the lookup-table
   rule, read from the sources (the functions criterion). */
rayo_status grade_tp1_sources(grade_context *ctx, rayo_error *err);

/* tp1_runs.c: the runs to .ppm and .bmp, their files, and the runs
   with wrong arguments (the run and output criteria). */
rayo_status grade_tp1_runs(grade_context *ctx, rayo_error *err);

/* checks/bmp_check.c: size bytes named name against the course's BMP
   layout for width x height; findings into item (pass or fail), and the
   pixels into image (RGB, 8 bits) when they can be read, else image
   zeroed.  RAYO_OK unless memory ran out. */
rayo_status grade_bmp_check(const void *data, size_t size, uint32_t width,
                            uint32_t height, const char *name,
                            rayo_grade_item *item, rayo_image *image,
                            rayo_error *err);

#endif
