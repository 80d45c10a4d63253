/*
 * grade_roster.h - who is in a class's folder, as teachers receive it:
 * `rayo grade --each DIR` finds the students in DIR whatever shape the
 * course's platform gave it (a folder per student, Moodle's folders and
 * flat downloads, GitHub Classroom's repositories, a zip per student, a
 * flat folder of files named by student: below, and docs/grading.md),
 * and says how it grouped them.  Files that fit none of these are listed
 * with the reason, never dropped silently.  This file only finds and
 * copies; it grades nothing and prints nothing.
 */
#ifndef RAYO_CLI_GRADE_ROSTER_H
#define RAYO_CLI_GRADE_ROSTER_H

#include <stddef.h>

#include "rayo.h"

/*
 * Shapes, each entry of DIR on its own:
 *   - a folder per student (the name is the folder's);
 *   - Moodle's "Ana Pérez_12345_assignsubmission_file_/" folders, and
 *     its flat download "Ana Pérez_12345_assignsubmission_file_main.c";
 *   - GitHub Classroom's "assignment-name-username/" repositories (a
 *     prefix that every folder shares, up to a '-', is not the name);
 *   - a zip file per student ("ana.zip"; also one zip alone in a
 *     student's folder), its sources copied out (zip_read.h);
 *   - a flat folder of files named by student ("ana_main.c",
 *     "ana_vector.h", "beto-main.c").
 */

typedef enum cli_layout {
    CLI_LAYOUT_FOLDER,    /* a folder named by the student */
    CLI_LAYOUT_MOODLE,    /* Moodle's folder or flat files */
    CLI_LAYOUT_CLASSROOM, /* a GitHub Classroom repository */
    CLI_LAYOUT_ZIP,       /* a zip file */
    CLI_LAYOUT_FILES      /* files named by student */
} cli_layout;

typedef struct cli_student {
    char *name;        /* as taken from DIR's names (untrusted text) */
    char *safe;        /* a file name made from it, unique in the class */
    char *folder;      /* what is graded: the student's folder, or one
                          rayo filled */
    cli_layout layout;
    char **files;      /* what went with it, as named in DIR (a zip: the
                          zip, then its sources) */
    size_t file_count;
    char *problem;     /* why it cannot be graded (a refused zip), or
                          NULL */
} cli_student;

typedef struct cli_unplaced {
    char *name;        /* the entry of DIR */
    const char *why;   /* a sentence */
} cli_unplaced;

typedef struct cli_roster {
    cli_student *students; /* sorted by name */
    size_t count;
    cli_unplaced *unplaced; /* sorted by name */
    size_t unplaced_count;
    char *staging;     /* rayo's folder for copied files, or NULL */
} cli_roster;

/* Finds the students in dir.  RAYO_ERR_INVALID when there is none;
   free with cli_roster_free in every case. */
rayo_status cli_roster_build(const char *dir, cli_roster *roster,
                             rayo_error *err);

/* Frees the roster and removes the files rayo copied. */
void cli_roster_free(cli_roster *roster);

/* How a layout is named in the grouping's lines ("a zip file", ...). */
const char *cli_layout_name(cli_layout layout);

#endif
