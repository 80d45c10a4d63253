/*
 * interrupt.h - the signals that end rayo (SIGINT, SIGTERM, SIGHUP,
 * SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU) during a long operation (a render,
 * a grading): the handler only records the signal; the operation polls
 * it (a render from every rendering thread, before every ray, through
 * cli_interrupt_cancel), stops cleanly (temporary files and directories
 * removed), and the command then dies of the same signal, as it would
 * have without a handler (status 128 + the signal in a shell).
 *
 * For commands that only write an image already in memory, see
 * output_guard.h instead: there the handler removes the file itself.
 */
#ifndef RAYO_CLI_INTERRUPT_H
#define RAYO_CLI_INTERRUPT_H

#include <stddef.h>

/* The signals above, and how many. */
extern const int cli_stop_signals[];
extern const size_t cli_stop_signal_count;

/* From now on those signals are recorded instead of killing us.  SIGINT
 * and SIGTERM are caught whatever their disposition; the others stay
 * ignored when they were (nohup's SIGHUP). */
void cli_interrupt_catch(void);

/* The signal recorded since cli_interrupt_catch, or 0. */
int cli_interrupted(void);

/* cli_interrupted() != 0, as a rayo_cancel_fn (context unused): safe to
 * call from any thread at once, one relaxed atomic load. */
int cli_interrupt_cancel(void *context);

/* Dies of the recorded signal (stdout flushed first); returns 128 + it
 * only if that somehow fails. */
int cli_interrupt_exit(void);

/* Dies of signal `number` by its default action, without a core dump
 * (SIGXCPU's would leave one); async-signal-safe, for handlers too.
 * Returns only if the signal does not kill. */
void cli_die_of(int number);

#endif
