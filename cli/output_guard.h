/*
 * output_guard.h - a signal that ends rayo (interrupt.h's list: SIGINT,
 * SIGTERM, SIGHUP, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU) while a command
 * writes a file: the temporary file is removed and the command dies of
 * the signal, so an interrupted `rayo convert` or `rayo compare --diff`
 * leaves no ".NAME.XXXXXX" behind and the earlier file of that name
 * intact, even when the directory was renamed meanwhile.
 *
 * For commands that write an image already in memory (the write is
 * short).  Not for `rayo render`, which stops within a ray on its own
 * (cmd_render.c, interrupt.h).  Between cli_guard_output and
 * cli_output_commit or cli_output_abort, at most one output is guarded.
 */
#ifndef RAYO_CLI_OUTPUT_GUARD_H
#define RAYO_CLI_OUTPUT_GUARD_H

#include "rayo.h"

/* From now on those signals unlink out's temporary file (if it has one)
 * and kill the process with that signal.  Signals ignored when rayo
 * started stay ignored. */
void cli_guard_output(const rayo_output *out);

/* rayo_output_open and cli_guard_output with the signals held off in
 * between, so that no signal finds the temporary file made and not yet
 * guarded. */
rayo_status cli_output_open(rayo_output **out, const char *path,
                            rayo_error *err);

/* rayo_output_commit and rayo_output_abort with the signals held off
 * until the file is in place or gone, then the guard lifted; a signal
 * that came meanwhile takes effect then. */
rayo_status cli_output_commit(rayo_output *out, rayo_error *err);
void cli_output_abort(rayo_output *out);

#endif
