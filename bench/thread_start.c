/*
 * thread_start.c - how long a new thread takes to start running on a CPU
 * that was idle, as a helper of rayo_render does.  It bounds what a
 * second thread can do for a frame that takes well under a millisecond:
 * the 16384x12288 P4 frame of large.c, whose scaling the table reports
 * next to the best speed-up a helper starting that late allows.
 */
#define _POSIX_C_SOURCE 200809L

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>

#include "bench.h"

#define SAMPLES 31

typedef struct start_probe {
    atomic_int running;
    double started;
} start_probe;

static void *note_start(void *argument)
{
    start_probe *probe = argument;
    probe->started = bench_now();
    atomic_store_explicit(&probe->running, 1, memory_order_release);
    return NULL;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double bench_thread_start_seconds(void)
{
    double samples[SAMPLES];
    int taken = 0, i;
    for (i = 0; i < SAMPLES; i++) {
        /* Long enough for the other CPU to go idle again. */
        struct timespec pause = {0, 500000};
        start_probe probe;
        pthread_t thread;
        double before;
        nanosleep(&pause, NULL);
        atomic_init(&probe.running, 0);
        before = bench_now();
        if (pthread_create(&thread, NULL, note_start, &probe) != 0)
            continue;
        /* The creator keeps its CPU busy, as a render's caller does. */
        while (!atomic_load_explicit(&probe.running, memory_order_acquire))
            ;
        samples[taken++] = probe.started - before;
        pthread_join(thread, NULL);
    }
    if (taken == 0)
        return -1;
    qsort(samples, (size_t)taken, sizeof *samples, by_value);
    return samples[taken / 2];
}
