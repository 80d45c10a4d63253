/*
 * thread_start.c - helpers started on another CPU than the caller's
 * (thread_start.h).
 */
#define _GNU_SOURCE /* sched_getaffinity, sched_getcpu, CPU_COUNT, thread
                       affinity */

#include "thread_start.h"

#include <sched.h>
#include <stdatomic.h>
#include <string.h>

#if defined(__GLIBC__) && defined(CPU_COUNT)
#define STEER 1
_Static_assert(sizeof(cpu_set_t) == sizeof(((thread_place *)0)->allowed),
               "a thread_place holds a cpu_set_t");
#else
#define STEER 0
#endif

void thread_place_init(thread_place *place)
{
    memset(place, 0, sizeof *place);
#if STEER
    {
        cpu_set_t allowed, start;
        int here = sched_getcpu();
        if (here < 0 || here >= CPU_SETSIZE ||
            sched_getaffinity(0, sizeof allowed, &allowed) != 0)
            return;
        start = allowed;
        CPU_CLR(here, &start);
        memcpy(place->allowed, &allowed, sizeof allowed);
        memcpy(place->start, &start, sizeof start);
        place->steer = CPU_COUNT(&start) > 0;
    }
#endif
}

/* The helper, running where it was started: given back every CPU, then
 * its body. */
static void *trampoline(void *argument)
{
    thread_slot *slot = argument;
#if STEER
    if (slot->steer) {
        cpu_set_t allowed;
        memcpy(&allowed, slot->allowed, sizeof allowed);
        pthread_setaffinity_np(pthread_self(), sizeof allowed, &allowed);
    }
#endif
    return slot->body(slot->argument);
}

int thread_start(thread_slot *slot, const thread_place *place,
                 void *(*body)(void *), void *argument)
{
    slot->body = body;
    slot->argument = argument;
    slot->steer = place != NULL && place->steer;
    if (slot->steer)
        memcpy(slot->allowed, place->allowed, sizeof slot->allowed);
#if STEER
    if (slot->steer) {
        pthread_attr_t attr;
        int created = 0;
        if (pthread_attr_init(&attr) == 0) {
            cpu_set_t start;
            memcpy(&start, place->start, sizeof start);
            created = pthread_attr_setaffinity_np(&attr, sizeof start,
                                                  &start) == 0 &&
                      pthread_create(&slot->thread, &attr, trampoline,
                                     slot) == 0;
            pthread_attr_destroy(&attr);
        }
        if (created)
            return 0;
    }
#endif
    return pthread_create(&slot->thread, NULL, trampoline, slot) != 0 ? -1
                                                                       : 0;
}

void thread_run_all(unsigned threads, void *(*body)(void *), void *argument)
{
    thread_slot helpers[THREAD_RUN_MAX - 1];
    thread_place place;
    unsigned started = 0, i;
    if (threads > THREAD_RUN_MAX)
        threads = THREAD_RUN_MAX;
    if (threads > 1)
        thread_place_init(&place);
    for (i = 1; i < threads; i++) {
        if (thread_start(&helpers[started], &place, body, argument) != 0)
            break;
        started++;
    }
    (void)body(argument);
    for (i = 0; i < started; i++)
        pthread_join(helpers[i].thread, NULL);
}

/* thread_run_each's jobs, and how many are taken. */
typedef struct job_list {
    void *(*body)(void *);
    char *jobs;
    size_t size;
    unsigned count;
    atomic_uint taken;
} job_list;

static void *take_jobs(void *argument)
{
    job_list *list = argument;
    unsigned i;
    while ((i = atomic_fetch_add(&list->taken, 1)) < list->count)
        (void)list->body(list->jobs + (size_t)i * list->size);
    return NULL;
}

void thread_run_each(unsigned count, void *(*body)(void *), void *jobs,
                     size_t size)
{
    job_list list;
    list.body = body;
    list.jobs = jobs;
    list.size = size;
    list.count = count;
    atomic_init(&list.taken, 0);
    thread_run_all(count, take_jobs, &list);
}
