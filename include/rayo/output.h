/*
 * output.h - an output file that appears whole or not at all.
 *
 * A regular file is written to a temporary file beside it (same directory,
 * so the same file system) and renamed over the final name only on
 * rayo_output_commit, after everything was written and synced; a failure
 * or rayo_output_abort removes the temporary file and leaves any earlier
 * file of that name untouched.  The directory is held open meanwhile, so
 * a directory renamed mid-way gets the file, or loses the temporary
 * file, where it now is.
 *
 * Bytes only: images are formatted by the writers (writer.h).  Which
 * files it replaces, how, and its errors are said after the includes.
 */
#ifndef RAYO_OUTPUT_H
#define RAYO_OUTPUT_H

#include <stddef.h>

#include "rayo/export.h"
#include "rayo/status.h"

/*
 * An existing file is replaced only where a shell's `>` could write it:
 * one we may not write is refused (RAYO_ERR_IO, "Permission denied")
 * before anything is created, and a replaced file keeps its mode (for
 * root, its owner and group too).  A symbolic link is followed (the link
 * stays, its target is replaced) except where the kernel's
 * protected_symlinks rule forbids it: in a sticky world-writable
 * directory, a link owned by neither us nor the directory's owner.
 * Standard output ("-"), devices, pipes and sockets are written
 * directly: nothing is ever renamed over /dev/null.
 *
 * Writes are buffered; errors carry the file name and the system's reason.
 * A reader that went away (EPIPE) is reported as RAYO_ERR_PIPE so the
 * command can end quietly.  The caller should ignore SIGPIPE.
 */

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rayo_output rayo_output;

/* Opens path for writing; "-" is standard output.  A build of rayo
 * without files (RAYO_NO_FILE_OUTPUT, docs/architecture.md) refuses any
 * other path with RAYO_ERR_IO. */
RAYO_API rayo_status rayo_output_open(rayo_output **out, const char *path,
                                      rayo_error *err);

/* Wraps an open descriptor (not closed by rayo); name is for messages. */
RAYO_API rayo_status rayo_output_open_fd(rayo_output **out, int fd,
                                         const char *name, rayo_error *err);

/*
 * An output into memory, for a program without files (a web page, a
 * test): what is written collects in a buffer that grows as needed, and
 * a successful rayo_output_commit hands it over as *data (allocated with
 * malloc, the caller's to free; NULL when nothing was written) and
 * *size.  Until then, and when the commit fails or the output is
 * aborted, *data and *size are not touched.  name is for messages.
 */
RAYO_API rayo_status rayo_output_open_memory(rayo_output **out,
                                             const char *name,
                                             unsigned char **data,
                                             size_t *size, rayo_error *err);

RAYO_API rayo_status rayo_output_write(rayo_output *out, const void *data,
                                       size_t size, rayo_error *err);

/*
 * Flushes, syncs and (for a regular file) renames into place, then frees
 * out.  On failure the temporary file is removed and out is freed too.
 * Once a write has failed, bytes are missing, and the commit fails with
 * that write's error.
 */
RAYO_API rayo_status rayo_output_commit(rayo_output *out, rayo_error *err);

/* Discards what was written (removes the temporary file) and frees out. */
RAYO_API void rayo_output_abort(rayo_output *out);

/* The name used in messages: the path, or "standard output". */
RAYO_API const char *rayo_output_name(const rayo_output *out);

/* 1 when out writes straight to a terminal (standard output on one,
 * /dev/tty, a pseudo-terminal's device), where a progress bar on the
 * same terminal would land amid the image. */
RAYO_API int rayo_output_is_terminal(const rayo_output *out);

/*
 * The temporary file being written: its name in the directory open as
 * *dir_fd (kept open by out until commit or abort), or NULL (and *dir_fd
 * -1) when writing directly.  Lets a signal handler remove it before the
 * process dies, with unlinkat(*dir_fd, name, 0), which is async-signal-
 * safe and finds the file even after its directory was renamed.
 */
RAYO_API const char *rayo_output_temp_at(const rayo_output *out, int *dir_fd);

#ifdef __cplusplus
}
#endif

#endif
