/*
 * interrupt.h - SIGINT and SIGTERM during a long operation (a render, a
 * grading): the handler only records the signal; the operation polls it
 * through its cancel callback, stops cleanly (temporary files and
 * directories removed), and the command then dies of the same signal, as
 * it would have without a handler (status 130 or 143 in a shell).
 *
 * For commands that only write an image already in memory, see
 * output_guard.h instead: there the handler removes the file itself.
 */
#ifndef RAYO_CLI_INTERRUPT_H
#define RAYO_CLI_INTERRUPT_H

/* From now on SIGINT and SIGTERM are recorded instead of killing us. */
void cli_interrupt_catch(void);

/* The signal recorded since cli_interrupt_catch, or 0. */
int cli_interrupted(void);

/* Dies of the recorded signal (stdout flushed first); returns 128 + it
 * only if that somehow fails. */
int cli_interrupt_exit(void);

#endif
