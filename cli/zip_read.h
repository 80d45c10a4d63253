/*
 * zip_read.h - a student's zip file, as a class archive holds them: its
 * C sources and headers copied out into a folder of rayo's own, so that
 * `rayo grade --each` can grade it like any other submission.
 *
 * It is a small bounded reader of the zip's central directory, for
 * stored and deflated entries (zlib inflates), not an unzip: it writes
 * only *.c and *.h files, flattened to their own names, and refuses the
 * whole archive (one line saying why) when an entry is absolute, climbs
 * out with "..", is a link, is encrypted, or when the archive has too
 * many entries or inflates past the bounds below.  Nothing is run and
 * nothing outside dest is touched.
 */
#ifndef RAYO_CLI_ZIP_READ_H
#define RAYO_CLI_ZIP_READ_H

#include <stddef.h>

#include "rayo.h"

#define CLI_ZIP_MAX_SIZE (64u << 20)   /* the zip file itself */
#define CLI_ZIP_MAX_ENTRIES 1000u      /* entries of any kind */
#define CLI_ZIP_MAX_FILE (1u << 20)    /* one source, inflated */
#define CLI_ZIP_MAX_TOTAL (8u << 20)   /* every source, inflated */

/*
 * Copies the *.c and *.h entries of the zip at path into the existing,
 * empty folder dest, each under its own name (the part after the last
 * '/'); entries in __MACOSX/ and names beginning with '.' are left out.
 * *names gets the names written (sorted; free with rayo_grade_paths_free)
 * and *others the count of entries left out.  On failure dest may hold
 * some files: the caller removes the folder.  Errors: RAYO_ERR_FORMAT
 * (a hostile or malformed archive: the message says which entry and
 * why), RAYO_ERR_LIMIT (past a bound), RAYO_ERR_IO, RAYO_ERR_NOMEM.
 */
rayo_status cli_zip_extract_sources(const char *path, const char *dest,
                                    char ***names, size_t *count,
                                    size_t *others, rayo_error *err);

#endif
