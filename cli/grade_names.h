/*
 * grade_names.h - names in a class's folder: how a flat folder's files
 * named by student ("ana_main.c", "ana_perez-vector.h") split into the
 * student's name and the file's own name, and how a student's name
 * becomes a file name of rayo's (a report, a folder of copied files).
 *
 * Pure functions on strings: nothing here reads a folder or a file.
 */
#ifndef RAYO_CLI_GRADE_NAMES_H
#define RAYO_CLI_GRADE_NAMES_H

#include <stddef.h>

/* One flat file: entry is its name in the folder; prefix and own, once
   split, the student's name (entry's first prefix bytes) and the file's
   own name (a pointer into entry).  fixed: the split is known already
   (Moodle's names), cli_flat_split leaves it. */
typedef struct cli_flat_file {
    const char *entry;
    size_t prefix;
    const char *own;
    int fixed;
} cli_flat_file;

/* A C source or header's own name: "x.c" or "x.h", not hidden. */
int cli_is_source_name(const char *name);

/* Whether name splits at i (a '_' or '-', not the first byte) into a
   student's name and a source's own name. */
int cli_flat_splits_at(const char *name, size_t i);

/*
 * Splits each of the count files that is not fixed, by the class: the
 * split whose own name the most files share, then the one whose name
 * the most files could have, then the longer name; last, a file whose
 * own name and name no other file shares joins a name others took, if
 * one of its splits gives it.  Each file must split somewhere.
 */
void cli_flat_split(cli_flat_file *files, size_t count);

/* name as a file name: ASCII letters, digits, '-', '_' and '.', and
   accented Latin letters, kept; anything else '_' (one for a run);
   never beginning with '.', at most 80 bytes, "student" when nothing is
   left. */
void cli_safe_file_name(const char *name, char *out, size_t room);

#endif
