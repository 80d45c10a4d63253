/*
 * functions.c - the second criterion: the functions the exercise's
 * statement asks for have its exact signatures and return the right
 * values on inputs chosen to reveal the usual mistakes.
 *
 * Each exercise has its own cases (functions_ej1.c, functions_ej2.c,
 * functions_ej3.c) on the shared machinery of harness.c: probe the
 * signatures, build a harness around the student's objects, run it
 * under the program's limits, read its log.  This file only chooses.
 */
#include "harness.h"

rayo_status grade_step_functions(grade_context *ctx, rayo_error *err)
{
    switch (ctx->options->exercise->course) {
    case RAYO_COURSE_EJ2:
        return grade_functions_ej2(ctx, err);
    case RAYO_COURSE_EJ3:
        return grade_functions_ej3(ctx, err);
    case RAYO_COURSE_EJ1:
    case RAYO_COURSE_EXERCISES:
    default:
        return grade_functions_ej1(ctx, err);
    }
}
