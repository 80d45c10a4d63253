/*
 * grade_feedback.h - what `rayo grade --each` tells the teacher besides
 * the table: how it grouped the class (a line per student on stderr,
 * and a line per file it left out), and, with --feedback DIR, one report
 * per student written into DIR, ready to send back.
 *
 * Each report is the text `rayo grade` prints for one submission, in a
 * file named from the student's name (grade_roster.h's safe name, ".txt")
 * and written whole or not at all: a temporary file renamed into place.
 */
#ifndef RAYO_CLI_GRADE_FEEDBACK_H
#define RAYO_CLI_GRADE_FEEDBACK_H

#include <stddef.h>

#include "grade_roster.h"

/* The grouping, on stderr: "rayo: NAME (LAYOUT): FILES" a student,
   "rayo: left out: NAME (WHY)" a file; every name escaped. */
void cli_roster_say(const char *dir, const cli_roster *roster);

/* Makes dir when it is missing (its parent must exist); an exit status,
   the reason said when it fails. */
int cli_feedback_prepare(const char *dir);

/* text (size bytes) into dir/SAFE.txt, whole or not at all; an exit
   status, the reason said when it fails. */
int cli_feedback_write(const char *dir, const cli_student *student,
                       const char *text, size_t size);

#endif
