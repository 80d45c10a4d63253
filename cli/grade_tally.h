/*
 * grade_tally.h - the summary that ends `rayo grade --each`'s table: how
 * many submissions passed, failed or could not be graded, and for each
 * criterion how many failed it and with which mistakes.
 *
 * A mistake's kind is named as the report names it: the first line of
 * the failed criterion's reasons (quotes and warnings passed over), up
 * to its first ':', ';', " (" or ", at ", so that "crashed: segmentation
 * fault (SIGSEGV); ..." and "leak: 40 bytes in 1 blocks ..." count as
 * "crashed" and "leak" whatever the numbers.  It counts; it grades
 * nothing, and prints only the summary it is asked for.
 */
#ifndef RAYO_CLI_GRADE_TALLY_H
#define RAYO_CLI_GRADE_TALLY_H

#include <stddef.h>
#include <stdio.h>

#include "rayo.h"

#define CLI_TALLY_KIND_BYTES 60 /* the longest a kind is kept */

typedef struct cli_tally_kind {
    int criterion;
    char text[CLI_TALLY_KIND_BYTES + 1];
    size_t students;
} cli_tally_kind;

typedef struct cli_tally {
    size_t passed, failed, errors;
    size_t failed_in[RAYO_GRADE_CRITERIA];
    cli_tally_kind *kinds;
    size_t kind_count;
} cli_tally;

/* One submission: its report, or NULL when it could not be graded.
   Returns 0 when memory ran out (the kinds are then incomplete). */
int cli_tally_add(cli_tally *tally, const rayo_grade_report *report);

/* The kind of a failed criterion's reasons, into text. */
void cli_tally_kind_of(const rayo_grade_item *item,
                       char text[CLI_TALLY_KIND_BYTES + 1]);

/* The summary: a line of counts, then a row per criterion with how many
   failed it and its kinds, most frequent first (at most 8 a criterion),
   escaped as the table's names are. */
void cli_tally_print(FILE *stream, const cli_tally *tally);

void cli_tally_free(cli_tally *tally);

#endif
