/*
 * grade_class.c - grading a class's submissions N at a time (see
 * grade_class.h).
 *
 * Workers take the next folder off a shared counter, grade it into its
 * slot and mark the slot done; the calling thread waits for slot 0, hands
 * it over, waits for slot 1, and so on, so the order of what is printed
 * never depends on which grading finished first.  The library's grader
 * is safe to run on several threads at once: it keeps no global state,
 * and its children are forked with only async-signal-safe calls before
 * exec (src/grade/run/process.c).
 */
#define _POSIX_C_SOURCE 200809L

#include "grade_class.h"

#include "cli.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAX_JOBS 256

typedef struct class_slot {
    cli_graded graded;
    rayo_grade_options options;
    char **sources;
    size_t source_count;
    int done;
} class_slot;

typedef struct class_run {
    pthread_mutex_t lock;
    pthread_cond_t finished;  /* a slot became done */
    char *const *folders;
    size_t count, next, done_count;
    const rayo_grade_options *template;
    class_slot *slots;
    atomic_int stop;          /* the caller asked to stop */
} class_run;

/* Each grading's cancel callback: the caller's, or the run stopping. */
static int run_cancelled(void *context)
{
    class_run *run = context;
    if (atomic_load(&run->stop))
        return 1;
    return run->template->cancelled != NULL &&
           run->template->cancelled(run->template->cancel_context);
}

static void grade_slot(class_run *run, size_t i)
{
    class_slot *slot = &run->slots[i];
    cli_graded *g = &slot->graded;
    g->index = i;
    g->folder = run->folders[i];
    g->options = &slot->options;
    rayo_error_init(&g->err, cli_lang());
    memset(&g->report, 0, sizeof g->report);
    slot->options = *run->template;
    slot->options.cancelled = run_cancelled;
    slot->options.cancel_context = run;
    g->status = rayo_grade_sources(run->folders[i], &slot->sources,
                                   &slot->source_count, &g->err);
    if (g->status == RAYO_OK) {
        slot->options.sources = (const char *const *)slot->sources;
        slot->options.source_count = slot->source_count;
        g->status = rayo_grade(&slot->options, &g->report, &g->err);
    }
}

static void *worker(void *context)
{
    class_run *run = context;
    for (;;) {
        size_t i;
        pthread_mutex_lock(&run->lock);
        if (run->next >= run->count || atomic_load(&run->stop)) {
            pthread_mutex_unlock(&run->lock);
            return NULL;
        }
        i = run->next++;
        pthread_mutex_unlock(&run->lock);

        grade_slot(run, i);

        pthread_mutex_lock(&run->lock);
        run->slots[i].done = 1;
        run->done_count++;
        pthread_cond_broadcast(&run->finished);
        pthread_mutex_unlock(&run->lock);
    }
}

static void release_slot(class_slot *slot)
{
    if (slot->graded.status == RAYO_OK)
        rayo_grade_report_free(&slot->graded.report);
    rayo_grade_paths_free(slot->sources, slot->source_count);
    slot->sources = NULL;
    slot->source_count = 0;
}

/* "rayo: graded K of N", drawn over itself on stderr; "" erases it. */
static void draw_progress(int *drawn, size_t done, size_t count, int erase)
{
    if (erase) {
        if (*drawn)
            fprintf(stderr, "\r%40s\r", "");
        *drawn = 0;
    } else {
        fputs("\rrayo: ", stderr);
        fprintf(stderr, _("graded %zu of %zu"), done, count);
        *drawn = 1;
    }
    fflush(stderr);
}

/* Grades slot i on the calling thread, as -j 1 does. */
static size_t grade_in_order(class_run *run, int progress, cli_graded_fn each,
                             void *context)
{
    size_t i, handed = 0;
    int drawn = 0;
    for (i = 0; i < run->count && !atomic_load(&run->stop); i++) {
        int stop;
        if (progress)
            draw_progress(&drawn, i, run->count, 0);
        grade_slot(run, i);
        if (progress)
            draw_progress(&drawn, 0, 0, 1);
        stop = each(&run->slots[i].graded, context);
        handed++;
        release_slot(&run->slots[i]);
        if (stop)
            atomic_store(&run->stop, 1);
    }
    return handed;
}

static size_t hand_over(class_run *run, int progress, cli_graded_fn each,
                        void *context)
{
    size_t i, handed = 0;
    int drawn = 0;
    for (i = 0; i < run->count; i++) {
        int stop;
        pthread_mutex_lock(&run->lock);
        while (!run->slots[i].done) {
            if (progress)
                draw_progress(&drawn, run->done_count, run->count, 0);
            pthread_cond_wait(&run->finished, &run->lock);
        }
        pthread_mutex_unlock(&run->lock);
        if (progress)
            draw_progress(&drawn, 0, 0, 1);
        stop = each(&run->slots[i].graded, context);
        handed++;
        release_slot(&run->slots[i]);
        if (stop) {
            atomic_store(&run->stop, 1);
            break;
        }
    }
    return handed;
}

size_t cli_grade_class(char *const *folders, size_t count, unsigned jobs,
                       const rayo_grade_options *template, int progress,
                       cli_graded_fn each, void *context)
{
    class_run run;
    pthread_t threads[MAX_JOBS];
    unsigned started = 0, t;
    size_t handed, i;

    memset(&run, 0, sizeof run);
    run.folders = folders;
    run.count = count;
    run.template = template;
    atomic_init(&run.stop, 0);
    run.slots = calloc(count > 0 ? count : 1, sizeof *run.slots);
    if (run.slots == NULL)
        return 0;
    progress = progress && isatty(STDERR_FILENO);
    if (jobs > MAX_JOBS)
        jobs = MAX_JOBS;
    if ((size_t)jobs > count)
        jobs = (unsigned)count;
    if (jobs <= 1) {
        handed = grade_in_order(&run, progress, each, context);
        free(run.slots);
        return handed;
    }

    pthread_mutex_init(&run.lock, NULL);
    pthread_cond_init(&run.finished, NULL);
    for (t = 0; t < jobs; t++) {
        if (pthread_create(&threads[t], NULL, worker, &run) != 0)
            break;
        started++;
    }
    if (started == 0) {
        /* No thread could start: grade here, one at a time. */
        handed = grade_in_order(&run, progress, each, context);
    } else {
        handed = hand_over(&run, progress, each, context);
    }
    atomic_store(&run.stop, 1);
    for (t = 0; t < started; t++)
        pthread_join(threads[t], NULL);
    /* Gradings that finished after the caller stopped. */
    for (i = handed; i < count; i++)
        if (run.slots[i].done)
            release_slot(&run.slots[i]);
    pthread_cond_destroy(&run.finished);
    pthread_mutex_destroy(&run.lock);
    free(run.slots);
    return handed;
}

unsigned cli_grade_default_jobs(void)
{
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    if (cpus < 1)
        return 1;
    return cpus > MAX_JOBS ? MAX_JOBS : (unsigned)cpus;
}
