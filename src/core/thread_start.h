/*
 * thread_start.h - starting a helper thread where it runs at once: on
 * another CPU than the caller's.  Private to the library.
 *
 * Left to itself, Linux often puts a new thread on the CPU of the thread
 * that creates it, even with another CPU idle, and there it waits until
 * the creator (working, never sleeping) is preempted or done: a helper
 * meant to share a job of a few milliseconds then shares nothing
 * (docs/performance.md).  So a helper is created allowed only the CPUs
 * other than the caller's, and, once running there, is given back all
 * the CPUs the process may use.  Without glibc's affinity calls, or when
 * they fail, threads start wherever the system puts them.
 */
#ifndef RAYO_THREAD_START_H
#define RAYO_THREAD_START_H

#include <pthread.h>
#include <stddef.h>

/* Where helpers start: the CPUs the process may use, and those less the
 * caller's (as bits of a cpu_set_t). */
typedef struct thread_place {
    unsigned long allowed[16], start[16];
    int steer; /* 1 when start is set and not empty */
} thread_place;

/* A started helper: pthread_join(slot.thread) ends it.  It keeps its own
 * copy of the CPUs to widen to, so the place may go first. */
typedef struct thread_slot {
    pthread_t thread;
    void *(*body)(void *);
    void *argument;
    unsigned long allowed[16];
    int steer;
} thread_slot;

/* Where helpers of the calling thread should start. */
void thread_place_init(thread_place *place);

/* Starts body(argument) on a thread placed by place (NULL: anywhere);
 * 0 when started.  The slot must live until the thread is joined. */
int thread_start(thread_slot *slot, const thread_place *place,
                 void *(*body)(void *), void *argument);

/* The most threads thread_run_all runs. */
#define THREAD_RUN_MAX 64

/* Runs body(argument) on `threads` threads (at most THREAD_RUN_MAX), the
 * caller one of them, the helpers placed by thread_place_init; returns
 * when all are done.  Helpers that cannot be started are done without:
 * body must share the work out itself (a counter of jobs taken). */
void thread_run_all(unsigned threads, void *(*body)(void *), void *argument);

/* body(job) for each of `count` jobs of `size` bytes from `jobs`, on
 * `count` threads (at most THREAD_RUN_MAX) as thread_run_all: each thread
 * takes the next job not taken, so every job is done once even when
 * helpers cannot be started. */
void thread_run_each(unsigned count, void *(*body)(void *), void *jobs,
                     size_t size);

#endif
