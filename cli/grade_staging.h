/*
 * grade_staging.h - the folder of rayo's where `rayo grade --each` puts
 * what it copies for a student (flat files under their own names, a
 * zip's sources): copying one file in, bounded, and removing the whole
 * folder at the end.
 *
 * The folder is flat by construction, a subfolder per student and files
 * in it, and is removed as such, following no link.
 */
#ifndef RAYO_CLI_GRADE_STAGING_H
#define RAYO_CLI_GRADE_STAGING_H

#define CLI_COPY_MAX (1u << 20) /* a file copied in */

/* Copies the file from to folder/own, a new file (no link followed), at
   most CLI_COPY_MAX bytes; 1, or 0 with errno (EFBIG: too large,
   EEXIST: own is there already). */
int cli_copy_source(const char *from, const char *folder, const char *own);

/* "dir/name", allocated; NULL when out of memory. */
char *cli_path_join(const char *dir, const char *name);

/* Removes staging: each subfolder's files, the subfolders, itself. */
void cli_remove_staging(const char *staging);

#endif
