/*
 * text_io.c - what compare and view share about their input and their
 * text output: an unreadable input is bad input (exit 2, whatever the
 * reason), and text on standard output is flushed and checked, a closed
 * pipe ending the command quietly as cat would.
 *
 * Not for binary output, which goes through rayo_output (output.h).
 */
#include <errno.h>
#include <string.h>

#include "cli.h"

int cli_unreadable(const rayo_error *err)
{
    if (err->status == RAYO_ERR_NOMEM)
        return cli_report(err);
    cli_say(err->message);
    return CLI_EXIT_USAGE;
}

int cli_flush_text(FILE *stream, const char *name)
{
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    int saved;
    errno = 0;
    if (fflush(stream) == 0 && !ferror(stream))
        return CLI_EXIT_OK;
    saved = errno;
    clearerr(stream);
    if (saved == EPIPE)
        rayo_error_set(&err, RAYO_ERR_PIPE, "%s: %s", name, strerror(saved));
    else
        rayo_error_set(&err, RAYO_ERR_IO, "%s: %s", name,
                       saved ? strerror(saved) : _("write failed"));
    return cli_report(&err);
}
