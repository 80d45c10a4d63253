/*
 * output_guard.c - removing an output's temporary file when SIGINT or
 * SIGTERM ends the command (output_guard.h).
 *
 * The handler does only what is safe in a signal handler: unlink(2) the
 * path saved when the guard was set, restore the default action and
 * raise the signal again, so the command dies of it (status 130 or 143
 * in a shell) as it would have.  Commit and abort run with both signals
 * blocked, so the handler never races the rename or the removal.
 */
#define _POSIX_C_SOURCE 200809L

#include "output_guard.h"

#include <signal.h>
#include <string.h>
#include <unistd.h>

/* The temporary file to remove; NULL when nothing is guarded. */
static const char *volatile guarded_path;

static void on_signal(int number)
{
    const char *path = guarded_path;
    if (path != NULL)
        unlink(path);
    signal(number, SIG_DFL);
    raise(number);
}

static void catch_unless_ignored(int number)
{
    struct sigaction action, old;
    if (sigaction(number, NULL, &old) == 0 && old.sa_handler == SIG_IGN)
        return;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(number, &action, NULL);
}

void cli_guard_output(const rayo_output *out)
{
    guarded_path = rayo_output_temp_path(out);
    if (guarded_path == NULL)
        return;
    catch_unless_ignored(SIGINT);
    catch_unless_ignored(SIGTERM);
}

/* Blocks SIGINT and SIGTERM into *old. */
static void hold_signals(sigset_t *old)
{
    sigset_t both;
    sigemptyset(&both);
    sigaddset(&both, SIGINT);
    sigaddset(&both, SIGTERM);
    sigprocmask(SIG_BLOCK, &both, old);
}

/* Forgets the path (freed by commit or abort); a held signal now finds
 * nothing to remove and kills the process. */
static void release_signals(const sigset_t *old)
{
    guarded_path = NULL;
    sigprocmask(SIG_SETMASK, old, NULL);
}

rayo_status cli_output_commit(rayo_output *out, rayo_error *err)
{
    sigset_t old;
    rayo_status status;
    hold_signals(&old);
    status = rayo_output_commit(out, err);
    release_signals(&old);
    return status;
}

void cli_output_abort(rayo_output *out)
{
    sigset_t old;
    hold_signals(&old);
    rayo_output_abort(out);
    release_signals(&old);
}
