/*
 * grade_print.h - one grading's report as `rayo grade` prints it: text
 * for a person, JSON for a program, and the escaped names of the class's
 * table (grade_print.c).  Private to the command.
 */
#ifndef RAYO_CLI_GRADE_PRINT_H
#define RAYO_CLI_GRADE_PRINT_H

#include <stddef.h>
#include <stdio.h>

#include "rayo.h"

/* Writes s escaped (names: a name, else a reason line). */
void cli_grade_print_escaped(FILE *out, const char *s, int names);

/* How many columns the name s takes escaped. */
size_t cli_grade_escaped_columns(const char *s);

/* Writes the name s escaped in exactly width columns on standard output:
   padded with spaces, or cut and ended with "..." when it is wider. */
void cli_grade_print_column(const char *s, size_t width);

/* The report's first line, in line: how the submission was isolated
   ("sandbox: bubblewrap (...)", or a warning that it was not); NULL for
   --sandbox=off.  Also the second line of Gradescope's output. */
const char *cli_grade_isolation_line(const char *isolation, char *line,
                                     size_t room);
void cli_grade_print_isolation(FILE *out, const char *isolation);

/* The report as text: a line or more a criterion, then PASS or FAIL. */
void cli_grade_print_text(FILE *out, const rayo_grade_report *r);

/* The report as one JSON object on standard output (student NULL: no
   "student" member), without a newline. */
void cli_grade_print_json(const char *student, const rayo_grade_options *o,
                          const rayo_grade_report *r);

#endif
