/*
 * output_guard.c - removing an output's temporary file when a signal
 * ends the command (output_guard.h).
 *
 * The handler does only what is safe in a signal handler: unlinkat(2)
 * the name saved when the guard was set, relative to the directory
 * descriptor the output holds (so a renamed directory still loses the
 * file), then die of the signal by its default action (cli_die_of:
 * status 128 + the signal in a shell) as the command would have.
 * Commit and abort run with every such signal blocked, so the handler
 * never races the rename or the removal.
 */
#define _POSIX_C_SOURCE 200809L
#define _ATFILE_SOURCE

#include "output_guard.h"

#include <fcntl.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>

#include "interrupt.h"

/* The temporary file to remove: its name, NULL when nothing is guarded,
 * in the directory open as guarded_dir. */
static const char *volatile guarded_name;
static volatile sig_atomic_t guarded_dir = -1;

static void on_signal(int number)
{
    const char *name = guarded_name;
    if (name != NULL)
        unlinkat(guarded_dir, name, 0);
    cli_die_of(number);
}

/* Every signal of the list, into *set. */
static void stop_set(sigset_t *set)
{
    size_t i;
    sigemptyset(set);
    for (i = 0; i < cli_stop_signal_count; i++)
        sigaddset(set, cli_stop_signals[i]);
}

static void catch_unless_ignored(int number)
{
    struct sigaction action, old;
    if (sigaction(number, NULL, &old) == 0 && old.sa_handler == SIG_IGN)
        return;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    stop_set(&action.sa_mask); /* one removal at a time */
    sigaction(number, &action, NULL);
}

void cli_guard_output(const rayo_output *out)
{
    int dir;
    const char *name = rayo_output_temp_at(out, &dir);
    size_t i;
    if (name == NULL)
        return;
    guarded_dir = dir;
    guarded_name = name;
    for (i = 0; i < cli_stop_signal_count; i++)
        catch_unless_ignored(cli_stop_signals[i]);
}

/* Blocks the signals into *old. */
static void hold_signals(sigset_t *old)
{
    sigset_t all;
    stop_set(&all);
    sigprocmask(SIG_BLOCK, &all, old);
}

/* Forgets the name (freed by commit or abort); a held signal now finds
 * nothing to remove and kills the process. */
static void release_signals(const sigset_t *old)
{
    guarded_name = NULL;
    sigprocmask(SIG_SETMASK, old, NULL);
}

rayo_status cli_output_open(rayo_output **out, const char *path,
                            rayo_error *err)
{
    sigset_t old;
    rayo_status status;
    hold_signals(&old);
    status = rayo_output_open(out, path, err);
    if (status == RAYO_OK)
        cli_guard_output(*out);
    sigprocmask(SIG_SETMASK, &old, NULL);
    return status;
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
