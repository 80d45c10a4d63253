/*
 * interrupt.c - recording the signals that end rayo, for operations that
 * stop at their next checkpoint (interrupt.h).
 *
 * The one piece of mutable global state in the command: a signal handler
 * has nowhere else to write.  It is a lock-free atomic, because the
 * render's threads read it while the handler, on any thread, writes it.
 */
#define _POSIX_C_SOURCE 200809L

#include "interrupt.h"

#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>

_Static_assert(ATOMIC_INT_LOCK_FREE == 2,
               "a signal handler may store only to a lock-free atomic");

const int cli_stop_signals[] = {SIGINT,  SIGTERM, SIGHUP, SIGALRM,
                                SIGUSR1, SIGUSR2, SIGXCPU};
const size_t cli_stop_signal_count =
    sizeof cli_stop_signals / sizeof cli_stop_signals[0];

static atomic_int interrupted_by;

static void on_interrupt(int signal_number)
{
    atomic_store_explicit(&interrupted_by, signal_number,
                          memory_order_relaxed);
}

void cli_interrupt_catch(void)
{
    struct sigaction action;
    size_t i;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    for (i = 0; i < cli_stop_signal_count; i++) {
        int number = cli_stop_signals[i];
        struct sigaction old;
        if (number != SIGINT && number != SIGTERM &&
            sigaction(number, NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;
        sigaction(number, &action, NULL);
    }
}

int cli_interrupted(void)
{
    return atomic_load_explicit(&interrupted_by, memory_order_relaxed);
}

int cli_interrupt_cancel(void *context)
{
    (void)context;
    return cli_interrupted() != 0;
}

void cli_die_of(int number)
{
    sigset_t just;
    if (number == SIGXCPU) { /* its default action dumps core */
        struct rlimit none;
        none.rlim_cur = 0;
        none.rlim_max = 0;
        setrlimit(RLIMIT_CORE, &none);
    }
    signal(number, SIG_DFL);
    raise(number);
    /* In a handler the signal is blocked until it returns: let it in. */
    sigemptyset(&just);
    sigaddset(&just, number);
    sigprocmask(SIG_UNBLOCK, &just, NULL);
}

int cli_interrupt_exit(void)
{
    int number = cli_interrupted();
    fflush(stdout);
    cli_die_of(number);
    return 128 + number;
}
