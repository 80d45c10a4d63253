/*
 * interrupt.c - recording SIGINT and SIGTERM for operations that stop at
 * their next checkpoint (interrupt.h).
 *
 * The one piece of mutable global state in the command: a signal handler
 * has nowhere else to write.
 */
#define _POSIX_C_SOURCE 200809L

#include "interrupt.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>

static volatile sig_atomic_t interrupted_by;

static void on_interrupt(int signal_number)
{
    interrupted_by = signal_number;
}

void cli_interrupt_catch(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);
}

int cli_interrupted(void)
{
    return interrupted_by;
}

int cli_interrupt_exit(void)
{
    int number = interrupted_by;
    fflush(stdout);
    signal(number, SIG_DFL);
    raise(number);
    return 128 + number;
}
