/*
 * grade_export.h - a grading's results for other tools: CSV for a
 * spreadsheet (--csv), and Gradescope's autograder results.json
 * (--gradescope), with points per criterion (--points).
 *
 * Both are built in memory and written whole by the command (output.h),
 * so a reader never sees half a file.
 */
#ifndef RAYO_CLI_GRADE_EXPORT_H
#define RAYO_CLI_GRADE_EXPORT_H

#include <stdio.h>

#include "rayo.h"

/* Points a passed criterion earns; a failed or skipped one earns 0. */
typedef struct cli_grade_points {
    double points[RAYO_GRADE_CRITERIA];
    unsigned given; /* bit c: --points named criterion c */
} cli_grade_points;

/* compile 10, functions 20, run 10, output 10, image 40, valgrind 10. */
void cli_grade_points_default(cli_grade_points *points);

/* "image=50,valgrind=0,...": the named criteria's points replaced (0 to
 * 1000 each).  Returns CLI_EXIT_OK, or prints the one-line error and
 * returns CLI_EXIT_USAGE. */
int cli_grade_points_parse(const char *text, cli_grade_points *points);

/* The points earned, and (in *max) the points there were. */
double cli_grade_score(const rayo_grade_report *report,
                       const cli_grade_points *points, double *max);

/* CSV (RFC 4180): the header, then one row per submission.  A grading
 * that could not be done (report NULL) has result "error" and the
 * message in the last column. */
void cli_grade_csv_header(FILE *stream);
void cli_grade_csv_row(FILE *stream, const char *student,
                       const rayo_grade_report *report,
                       const char *error_message,
                       const cli_grade_points *points);

/* Gradescope's results.json for one submission: "score", "output" (the
 * summary, and sandbox_note when not NULL), and one entry of "tests" per
 * criterion with points (criteria worth 0 are left out).  With report
 * NULL, a score of 0 and the error message as the output. */
void cli_grade_gradescope(FILE *stream, const rayo_grade_report *report,
                          const char *error_message,
                          const char *sandbox_note,
                          const cli_grade_points *points);

#endif
