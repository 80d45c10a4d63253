/*
 * band_fill.c - the machine's own scaling on the 16384x12288 P4 frame's
 * kind of work, with no rendering at all: the frame's bytes set to zero
 * in bands of 256 KiB, each thread filling slot buffers of its own, by
 * one thread or by the calling thread and helpers started for the fill,
 * as rayo_render starts them (on CPUs other than the caller's) and waits
 * for them (spinning while they end).  No ordering, no system calls: what is
 * left is starting threads and storing bytes, so a renderer whose frame
 * is mostly those two things cannot be expected to scale better than
 * this does on the same machine.
 */
#define _GNU_SOURCE /* CPU affinity and pthread_tryjoin_np, as render.c */

#include <pthread.h>
#include <sched.h>
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

/* Starts a helper away from the calling thread's CPU when there is
 * another (render.c's helper_create); 0 on success. */
static int start_helper(fill_thread *h, void *(*body)(void *))
{
#if defined(__GLIBC__) && defined(CPU_COUNT)
    cpu_set_t others;
    int here = sched_getcpu();
    if (here >= 0 && here < CPU_SETSIZE &&
        sched_getaffinity(0, sizeof others, &others) == 0) {
        pthread_attr_t attr;
        int created = 0;
        CPU_CLR(here, &others);
        if (CPU_COUNT(&others) > 0 && pthread_attr_init(&attr) == 0) {
            created = pthread_attr_setaffinity_np(&attr, sizeof others,
                                                  &others) == 0 &&
                      pthread_create(&h->thread, &attr, body, h) == 0;
            pthread_attr_destroy(&attr);
        }
        if (created)
            return 0;
    }
#endif
    return pthread_create(&h->thread, NULL, body, h) != 0 ? -1 : 0;
}

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

/*
 * The slots stay allocated from one call to the next, as a render's come
 * back from malloc where the last render's were, faulted in and cached
 * wherever they were last written.
 */
static unsigned char *fill_slots(unsigned threads)
{
    static unsigned char *slots;
    static unsigned capacity;
    if (threads > capacity) {
        unsigned char *grown =
            realloc(slots, (size_t)threads * FILL_SLOTS * FILL_BAND_BYTES);
        if (grown == NULL)
            return NULL;
        memset(grown, 1, (size_t)threads * FILL_SLOTS * FILL_BAND_BYTES);
        slots = grown;
        capacity = threads;
    }
    return slots;
}

double bench_band_fill_seconds(size_t bytes, unsigned threads)
{
    fill_job job;
    fill_thread *helpers = NULL;
    unsigned started = 0, i;
    double start, seconds;
    job.band_count = (bytes + FILL_BAND_BYTES - 1) / FILL_BAND_BYTES;
    job.slots = fill_slots(threads);
    if (threads > 1)
        helpers = malloc((threads - 1) * sizeof *helpers);
    if (job.slots == NULL || (threads > 1 && helpers == NULL)) {
        free(helpers);
        return -1;
    }
    atomic_init(&job.next_band, 0);
    start = bench_now();
    for (i = 0; i + 1 < threads; i++) {
        helpers[started].job = &job;
        helpers[started].index = started + 1;
        if (start_helper(&helpers[started], fill_helper) != 0)
            break;
        started++;
    }
    fill_bands(&job, 0);
    for (i = 0; i < started; i++) {
#if defined(__GLIBC__)
        /* As render.c's join_helper: spin, not sleep, while it ends. */
        double asked = bench_now();
        while (pthread_tryjoin_np(helpers[i].thread, NULL) != 0)
            if (bench_now() - asked > 50e-6) {
                pthread_join(helpers[i].thread, NULL);
                break;
            }
#else
        pthread_join(helpers[i].thread, NULL);
#endif
    }
    seconds = bench_now() - start;
    free(helpers);
    return seconds;
}
