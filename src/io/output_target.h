/*
 * output_target.h - what an output path names, and whether rayo may
 * replace it, decided as a shell's `>` and the kernel would decide it:
 * symbolic links followed only where the kernel's protected_symlinks
 * rule follows them, an existing file replaced only when we may write
 * it.  Private to output.c, which then creates, renames and removes
 * its temporary file relative to the directory found here.
 */
#ifndef RAYO_OUTPUT_TARGET_H
#define RAYO_OUTPUT_TARGET_H

#include <sys/stat.h>

typedef struct rayo_output_target {
    int dir_fd;       /* the directory that holds it (O_PATH), or -1 */
    char *name;       /* its name there (malloc'ed) */
    int exists;       /* 1: st describes it */
    struct stat st;
    int refused_link; /* the error is a link the rule does not follow */
} rayo_output_target;

/*
 * Finds what path names: dir_fd and name are then the directory and
 * the name of something that is not a symbolic link (or does not exist
 * yet: exists 0), or of a link to a device, pipe or socket, to be
 * opened through the link (/dev/stdout is /proc/self/fd/1, whose
 * "pipe:[N]" names nothing to walk to).  Returns 0 or an errno value;
 * a link that the protected_symlinks rule would not follow is EACCES,
 * with refused_link set.  target is to be released with
 * rayo_output_target_free whatever the result.
 */
int rayo_output_target_find(rayo_output_target *target, const char *path);

/*
 * 0 when the existing regular file may be replaced: we may write it
 * (our effective ids, as open(2) checks; root may write anything on a
 * writable file system), and, in a sticky directory, it is ours or the
 * directory is, as the rename requires (or we are root).  Otherwise
 * EACCES, EPERM or EROFS.
 */
int rayo_output_target_replaceable(const rayo_output_target *target);

/* Closes the directory, unless taken (dir_fd set to -1), and frees the
 * name, unless taken (NULL). */
void rayo_output_target_free(rayo_output_target *target);

#endif
