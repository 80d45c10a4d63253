/*
 * grade_class.h - grading a class's submissions N at a time.
 *
 * `rayo grade --each DIR -j N` grades up to N submissions at once, on N
 * threads (each grading spends its time waiting for the compiler, the
 * program and valgrind, which are processes of their own), and hands the
 * reports back one by one in the folders' order, from the calling thread,
 * so the table, the JSON and the CSV come out exactly as with -j 1.
 */
#ifndef RAYO_CLI_GRADE_CLASS_H
#define RAYO_CLI_GRADE_CLASS_H

#include <stddef.h>

#include "rayo.h"

/* The outcome of one submission: status is rayo_grade's (or the
   sources' lookup's); report is filled when status is RAYO_OK. */
typedef struct cli_graded {
    size_t index;               /* in folders[] */
    const char *folder;
    const rayo_grade_options *options; /* with this submission's sources */
    rayo_status status;
    rayo_error err;
    rayo_grade_report report;
} cli_graded;

/* Called in order, for index 0, 1, ...; the report is freed after it
   returns.  Returns nonzero to stop (no later submission is handed
   over; those running are cancelled). */
typedef int (*cli_graded_fn)(const cli_graded *graded, void *context);

/*
 * Grades every folder with template's settings (its sources ignored),
 * jobs at a time (at least 1; threads beyond the count are not started).
 * When progress is nonzero, "rayo: graded K of N" is drawn on stderr
 * (a terminal) while it runs, and erased.  Returns the number of
 * submissions handed to each; fewer than count when it stopped or was
 * cancelled (template->cancelled).
 */
size_t cli_grade_class(char *const *folders, size_t count, unsigned jobs,
                       const rayo_grade_options *template, int progress,
                       cli_graded_fn each, void *context);

/* The default for -j: the CPUs online, at least 1. */
unsigned cli_grade_default_jobs(void);

#endif
