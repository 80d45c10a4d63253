/*
 * grade_request.h - what `rayo grade` was asked (its options, parsed by
 * cmd_grade.c), and the steps of the command that share it: grading a
 * class (grade_each.c) and writing the --csv and --gradescope files
 * (grade_files.c).  Private to the command.
 */
#ifndef RAYO_CLI_GRADE_REQUEST_H
#define RAYO_CLI_GRADE_REQUEST_H

#include <stdio.h>

#include "rayo.h"
#include "grade_export.h"

typedef struct grade_request {
    rayo_grade_options options;
    char course_reference[4096]; /* --reference course, resolved */
    int json, each, check;
    unsigned jobs;               /* -j: submissions graded at once */
    const char *csv;             /* --csv FILE or "-" */
    const char *gradescope;      /* --gradescope FILE */
    cli_grade_points points;     /* --points */
    int scored;                  /* --points was given: a score column */
    const char *feedback;        /* --feedback DIR */
} grade_request;

/* --each: every submission folder in dir graded, a row each, then the
   class's summary; an exit status. */
int cli_grade_each(const char *dir, grade_request *req);

/* Whether path is standard output. */
int cli_grade_is_stdout(const char *path);

/* A memory stream for what will go to path, or NULL (said) without
   memory; then its text written to path whole, freed; an exit status. */
FILE *cli_grade_export_start(char **text, size_t *size, const char *path);
int cli_grade_export_finish(FILE *stream, char **text, size_t *size,
                            const char *path);

/* The --csv and --gradescope files of one submission (report NULL: it
   could not be graded, err says why); an exit status. */
int cli_grade_export_one(const grade_request *req, const char *student,
                         const rayo_grade_report *report,
                         const rayo_error *err);

#endif
