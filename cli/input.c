/*
 * input.c - the one rule for inputs, shared by every subcommand: a file
 * the command reads that is missing, unreadable, a directory, malformed
 * or too large is bad input (exit 2, one line naming the file and the
 * reason), whatever the command; only outputs that cannot be created or
 * written are I/O failures (exit 1).  Most inputs are read by the library,
 * whose I/O errors the commands pass to cli_unreadable (text_io.c); grade
 * hands its inputs to a process that also does other I/O, so it checks
 * them here first.  And an output must never be one of the inputs:
 * cli_same_file says when two names are one file.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

/* The system's reason, in the command's language for the usual ones
   (the English is the C library's own text). */
static const char *reason(int error)
{
    switch (error) {
    case ENOENT:
        return _("No such file or directory");
    case EACCES:
        return _("Permission denied");
    case EISDIR:
        return _("Is a directory");
    case ENOTDIR:
        return _("Not a directory");
    }
    return strerror(error);
}

int cli_check_input(const char *path, cli_input_kind kind)
{
    struct stat st;
    int fd;
    if (strcmp(path, "-") == 0)
        return CLI_EXIT_OK;
    fd = open(path, O_RDONLY | O_NONBLOCK); /* a FIFO: no waiting */
    if (fd < 0)
        return cli_usage_error("%s: %s", path, reason(errno));
    if (fstat(fd, &st) != 0) {
        int saved = errno;
        close(fd);
        return cli_usage_error("%s: %s", path, reason(saved));
    }
    close(fd);
    if (S_ISDIR(st.st_mode) && kind == CLI_INPUT_FILE)
        return cli_usage_error("%s: %s", path, reason(EISDIR));
    if (!S_ISDIR(st.st_mode) && kind == CLI_INPUT_FOLDER)
        return cli_usage_error("%s: %s", path, reason(ENOTDIR));
    return CLI_EXIT_OK;
}

int cli_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    if (strcmp(a, "-") == 0 || strcmp(b, "-") == 0)
        return 0; /* a stream; "-" and "-" are refused elsewhere */
    if (strcmp(a, b) == 0)
        return 1;
    /* stat follows symbolic links: a link to the input is the input. */
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}
