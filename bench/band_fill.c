/*
 * band_fill.c - the machine's own scaling on the 16384x12288 P4 frame's
 * kind of work, with no rendering at all: the frame's bytes set to zero
 * in bands of 256 KiB, each thread filling slot buffers of its own, by
 * one thread or by the calling thread and helpers started for the fill,
 * as rayo_render starts them.  No ordering, no system calls: what is
 * left is starting threads and storing bytes, so a renderer whose frame
 * is mostly those two things cannot be expected to scale better than
 * this does on the same machine.
 */
#define _POSIX_C_SOURCE 200809L

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define FILL_BAND_BYTES (256u * 1024u) /* render.c's BAND_TARGET_BYTES */
#define FILL_SLOTS 3u                  /* render.c's SLOTS_PER_THREAD */

typedef struct fill_job {
    atomic_size_t next_band;
    size_t band_count;
    unsigned char *slots; /* FILL_SLOTS bands per thread */
} fill_job;

typedef struct fill_thread {
    pthread_t thread;
    fill_job *job;
    unsigned index;
} fill_thread;

static void fill_bands(fill_job *job, unsigned index)
{
    unsigned char *own = job->slots + (size_t)index * FILL_SLOTS *
                                          FILL_BAND_BYTES;
    unsigned k = 0;
    while (atomic_fetch_add_explicit(&job->next_band, 1,
                                     memory_order_relaxed) <
           job->band_count) {
        unsigned char *slot = own + (size_t)(k++ % FILL_SLOTS) *
                                        FILL_BAND_BYTES;
        memset(slot, 0, FILL_BAND_BYTES);
        /* The bytes count as used, as a sink would use them. */
        __asm__ volatile("" : : "r"(slot) : "memory");
    }
}

static void *fill_helper(void *argument)
{
    fill_thread *self = argument;
    fill_bands(self->job, self->index);
    return NULL;
}

double bench_band_fill_seconds(size_t bytes, unsigned threads)
{
    fill_job job;
    fill_thread *helpers = NULL;
    unsigned started = 0, i;
    double start, seconds;
    job.band_count = (bytes + FILL_BAND_BYTES - 1) / FILL_BAND_BYTES;
    job.slots = malloc((size_t)threads * FILL_SLOTS * FILL_BAND_BYTES);
    if (threads > 1)
        helpers = malloc((threads - 1) * sizeof *helpers);
    if (job.slots == NULL || (threads > 1 && helpers == NULL)) {
        free(job.slots);
        free(helpers);
        return -1;
    }
    /* Every slot touched once, as a render's reused buffers are. */
    memset(job.slots, 1, (size_t)threads * FILL_SLOTS * FILL_BAND_BYTES);
    atomic_init(&job.next_band, 0);
    start = bench_now();
    for (i = 0; i + 1 < threads; i++) {
        helpers[started].job = &job;
        helpers[started].index = started + 1;
        if (pthread_create(&helpers[started].thread, NULL, fill_helper,
                           &helpers[started]) != 0)
            break;
        started++;
    }
    fill_bands(&job, 0);
    for (i = 0; i < started; i++)
        pthread_join(helpers[i].thread, NULL);
    seconds = bench_now() - start;
    free(job.slots);
    free(helpers);
    return seconds;
}
