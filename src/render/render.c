/*
 * render.c - scheduling rows: bands rendered by a pool of threads and
 * delivered to the sink in order.
 *
 * The frame is cut into bands of consecutive rows, each rendered into a
 * slot buffer and handed to the sink in order by the calling thread.  A
 * band's pixels depend only on its rows, never on which thread rendered
 * it, so the output is identical for any thread count.  A render stops
 * within a ray of being asked (render_stop.h).  Not the shading of a
 * pixel (row_*.c, shade_*.c), nor the writing of rows (the sink's).
 */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT, pthread_tryjoin_np */

#include "rayo/render.h"

#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "rayo/limits.h"

#include "../core/thread_start.h"
#include "../formats/writer_runs.h"
#include "row_plan.h"

/*
 * With one thread nothing is spawned.  With more, bands are first
 * rendered and delivered on the calling thread, and helpers start only
 * once the frame, at the pace of the bands done so far, would take
 * SERIAL_BELOW_SECONDS or more: a frame as small as the seed job's costs
 * less than waking a second CPU (docs/performance.md).
 *
 * In parallel, the calling thread is one of the renderers: whenever the
 * next band in order is not ready, it claims and renders the next free
 * band itself, so it never idles while a helper is still starting.  Each
 * thread renders into band buffers (slots) of its own, freed as their
 * bands are delivered, so no slot is ever written by two CPUs in turn.  A
 * thread with nothing to do spins briefly (a band is usually close to
 * done) before it sleeps on the condition variable, and a thread that
 * changes the state wakes sleepers only when there are some: futex
 * wake-ups are dear on a virtual machine.  For the same reason helpers
 * are started on another CPU than the caller's (thread_start.h), and the
 * caller spins while they end (join_helper).
 *
 * The rows poll the stop inside their bands, a band abandoned for it is
 * never delivered, and a render that ends early for any reason raises the
 * stop so its helpers drop their bands at once.
 *
 * Rows reach the sink as pixels, except for one shortcut of the
 * library's own: when the sink is rayo_writer_row_sink and its writer
 * takes runs (plain PBM, writer_runs.h), bands of the span path travel
 * as runs of black pixels, which that writer spells without scanning.
 */

/* Bands aim at this many bytes, so sinks get large writes. */
#define BAND_TARGET_BYTES (256u * 1024u)
/* and at least this many bands per thread, so threads share the work. */
#define BANDS_PER_THREAD 8u
/* Band buffers (slots) each thread owns, at most: a bit each in a mask. */
#define SLOTS_PER_THREAD 3u
_Static_assert(SLOTS_PER_THREAD < sizeof(unsigned) * 8,
               "a thread's free slots are bits of an unsigned");
/* Frames projected to take less than this stay on the calling thread. */
#define SERIAL_BELOW_SECONDS 0.0002
/* How long a thread with nothing to do spins before it sleeps. */
#define SPIN_SECONDS 0.00005

typedef struct band_job {
    const rayo_camera *camera;
    const rayo_scene *scene;
    const rayo_render_options *options;
    rayo_row_plan plan;
    size_t row_bytes;
    uint32_t rows_per_band, band_count;
    uint32_t slots_per_thread; /* SLOTS_PER_THREAD, or fewer for a
                                  frame of few bands */
    uint32_t slot_count;   /* slots_per_thread per thread: the bands in
                              flight, claimed but not delivered, at most */
    unsigned char *slots;  /* slot_count * rows_per_band * row_bytes;
                              thread t owns slots_per_thread from
                              t * slots_per_thread */
    uint32_t *ready;       /* [band % slot_count]: 1 + the slot that
                              holds the band once rendered, else 0 */
    unsigned *free_slots;  /* per thread: a bit for each free slot */
    rayo_writer *runs_writer; /* the sink's writer, when it takes rows as
                                 runs (writer_runs.h) and the plan makes
                                 them; else NULL */
    rayo_row_runs *runs;   /* with runs_writer: rows_per_band a slot */

    pthread_mutex_t lock;
    pthread_cond_t changed; /* a band was rendered or delivered, or stop */
    atomic_uint version;    /* counts those changes, for spinning */
    rayo_render_stop stopper; /* polled inside bands (render_stop.h) */
    unsigned sleepers;      /* threads waiting on changed */
    int spin;               /* spin before sleeping: a CPU per thread */
    uint32_t next_band;     /* next band to claim */
    uint32_t delivered;     /* bands handed to the sink */
    int stop;
} band_job;

void rayo_render_options_init(rayo_render_options *options)
{
    options->shade = RAYO_SHADE_HIT;
    options->samples = 1;
    options->depth = 5;
    options->threads = 0;
    options->progress = NULL;
    options->progress_context = NULL;
    options->cancel = NULL;
    options->cancel_context = NULL;
    rayo_tp1_reading_init(&options->tp1);
}

static uint32_t band_rows(uint32_t rows, uint32_t first, uint32_t per_band)
{
    return rows - first < per_band ? rows - first : per_band;
}

static unsigned char *slot_memory(const band_job *job, uint32_t slot)
{
    return job->slots + (size_t)slot * job->rows_per_band * job->row_bytes;
}

/* The runs of a slot's rows, or NULL when the band goes as bits. */
static rayo_row_runs *slot_runs(const band_job *job, uint32_t slot)
{
    return job->runs != NULL ? job->runs + (size_t)slot * job->rows_per_band
                             : NULL;
}

static void render_band(const band_job *job, uint32_t band, uint32_t slot)
{
    uint32_t first = band * job->rows_per_band;
    uint32_t count = band_rows(job->camera->height, first, job->rows_per_band);
    rayo_row_plan_render_rows(&job->plan, first, count,
                              slot_memory(job, slot), job->row_bytes,
                              slot_runs(job, slot));
}

static rayo_status cancelled(rayo_error *err)
{
    return rayo_error_set(err, RAYO_ERR_CANCELLED, "render cancelled");
}

/* 1 when the render is to stop: a band rendered before this says no is
 * whole, and one abandoned for the stop is never delivered. */
static int stopping(band_job *job)
{
    return rayo_render_stopping(&job->stopper);
}

static rayo_status deliver(band_job *job, uint32_t band, uint32_t slot,
                           rayo_row_sink sink, void *context,
                           rayo_error *err)
{
    uint32_t first = band * job->rows_per_band;
    uint32_t count = band_rows(job->camera->height, first, job->rows_per_band);
    rayo_status status =
        job->runs != NULL
            ? rayo_writer_write_runs(job->runs_writer, slot_memory(job, slot),
                                     job->row_bytes, slot_runs(job, slot),
                                     count, err)
            : sink(context, slot_memory(job, slot), job->row_bytes, first,
                   count, err);
    if (status != RAYO_OK)
        return status;
    if (job->options->progress != NULL &&
        job->options->progress(job->options->progress_context, first + count,
                               job->camera->height))
        return cancelled(err);
    return RAYO_OK;
}

/* Renders and delivers the bands from `band` on, on this thread, in its
 * first slot. */
static rayo_status run_serial(band_job *job, uint32_t band,
                              rayo_row_sink sink, void *context,
                              rayo_error *err)
{
    for (; band < job->band_count; band++) {
        rayo_status status;
        render_band(job, band, 0);
        if (stopping(job))
            return cancelled(err);
        status = deliver(job, band, 0, sink, context, err);
        if (status != RAYO_OK)
            return status;
    }
    return RAYO_OK;
}

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* Records a change of state (lock held) and wakes whoever sleeps. */
static void announce(band_job *job)
{
    atomic_fetch_add_explicit(&job->version, 1, memory_order_release);
    if (job->sleepers > 0)
        pthread_cond_broadcast(&job->changed);
}

/* Waits (lock held) until the state changes from `seen`: a short spin
 * with the lock released, then sleep. */
static void await_change(band_job *job, unsigned seen)
{
    if (job->spin) {
        double start = seconds_now();
        pthread_mutex_unlock(&job->lock);
        while (atomic_load_explicit(&job->version, memory_order_acquire) ==
                   seen &&
               seconds_now() - start < SPIN_SECONDS)
            sched_yield();
        pthread_mutex_lock(&job->lock);
    }
    while (atomic_load_explicit(&job->version, memory_order_relaxed) ==
           seen) {
        job->sleepers++;
        pthread_cond_wait(&job->changed, &job->lock);
        job->sleepers--;
    }
}

/* The lowest set bit of a mask (of SLOTS_PER_THREAD bits; 0 for none,
 * which the callers rule out). */
static unsigned lowest_bit(unsigned mask)
{
    unsigned bit = 0;
    while (bit < SLOTS_PER_THREAD && !(mask & (1u << bit)))
        bit++;
    return bit < SLOTS_PER_THREAD ? bit : 0;
}

/* Claims the next band, when thread `thread` has a free slot, and renders
 * it there (lock held on entry and on return); 0 when there was none to
 * claim.  The next band to deliver is never left unclaimed for want of a
 * slot: the calling thread's slots hold only bands after it, and so are
 * all free when it is still unclaimed. */
static int claim_and_render(band_job *job, unsigned thread)
{
    uint32_t band = job->next_band, slot;
    unsigned free_slots = job->free_slots[thread];
    if (job->stop || band >= job->band_count || free_slots == 0 ||
        band >= job->delivered + job->slot_count)
        return 0;
    slot = thread * job->slots_per_thread + lowest_bit(free_slots);
    job->free_slots[thread] = free_slots & (free_slots - 1);
    job->next_band++;
    pthread_mutex_unlock(&job->lock);
    render_band(job, band, slot);
    pthread_mutex_lock(&job->lock);
    job->ready[band % job->slot_count] = slot + 1;
    announce(job);
    return 1;
}

typedef struct helper {
    thread_slot slot; /* started on another CPU (thread_start.h) */
    band_job *job;
    unsigned index; /* 1, 2, ...: the calling thread is 0 */
} helper;

static void *helper_main(void *argument)
{
    const helper *self = argument;
    band_job *job = self->job;
    pthread_mutex_lock(&job->lock);
    while (!job->stop && job->next_band < job->band_count)
        if (!claim_and_render(job, self->index))
            await_change(job, atomic_load_explicit(&job->version,
                                                   memory_order_relaxed));
    pthread_mutex_unlock(&job->lock);
    return NULL;
}

/*
 * Waits for a helper to end.  It usually ends a few microseconds after
 * the last band is delivered, and a joiner that sleeps meanwhile is woken
 * only when its CPU is, far later than a spinning one sees it
 * (docs/performance.md): so, with a CPU per thread, spin a while first,
 * where the C library can tell without waiting whether a thread has
 * ended.
 */
static void join_helper(pthread_t thread, int spin)
{
#if defined(__GLIBC__)
    if (spin) {
        double start = seconds_now();
        do {
            if (pthread_tryjoin_np(thread, NULL) == 0)
                return;
            sched_yield();
        } while (seconds_now() - start < SPIN_SECONDS);
    }
#else
    (void)spin;
#endif
    pthread_join(thread, NULL);
}

/* Bands from `first` on: this thread delivers them in order and renders
 * whatever it can claim while the next one is not ready; `threads` - 1
 * helpers render too. */
static rayo_status run_parallel(band_job *job, unsigned threads,
                                uint32_t first, rayo_row_sink sink,
                                void *context, rayo_error *err)
{
    helper *helpers = malloc((threads - 1) * sizeof *helpers);
    thread_place place;
    rayo_status status = RAYO_OK;
    unsigned started = 0, i;
    uint32_t band = first;
    if (helpers == NULL)
        threads = 1; /* this thread renders every band itself */
    for (i = 0; i < threads; i++)
        job->free_slots[i] = (1u << job->slots_per_thread) - 1;
    for (i = 0; i < job->slot_count; i++)
        job->ready[i] = 0;
    job->next_band = first;
    job->delivered = first;
    job->sleepers = 0;
    /* With more threads than CPUs, a spinning thread would take the CPU
     * of one with work to do. */
    job->spin = threads <= rayo_cpu_count();
    atomic_init(&job->version, 0);
    pthread_mutex_init(&job->lock, NULL);
    pthread_cond_init(&job->changed, NULL);
    thread_place_init(&place);
    for (i = 0; i + 1 < threads; i++) {
        helpers[started].job = job;
        helpers[started].index = started + 1;
        if (thread_start(&helpers[started].slot, &place, helper_main,
                         &helpers[started]) != 0)
            break;
        started++;
    }
    pthread_mutex_lock(&job->lock);
    while (band < job->band_count && status == RAYO_OK) {
        uint32_t *ready = &job->ready[band % job->slot_count];
        unsigned seen;
        /* Before a band is taken as ready: one abandoned mid-way was
         * marked ready after its renderer saw the stop. */
        if (stopping(job)) {
            status = cancelled(err);
            break;
        }
        if (*ready != 0) {
            uint32_t slot = *ready - 1;
            pthread_mutex_unlock(&job->lock);
            status = deliver(job, band, slot, sink, context, err);
            pthread_mutex_lock(&job->lock);
            *ready = 0;
            job->free_slots[slot / job->slots_per_thread] |=
                1u << (slot % job->slots_per_thread);
            job->delivered = ++band;
            if (status != RAYO_OK)
                job->stop = 1;
            announce(job);
            continue;
        }
        seen = atomic_load_explicit(&job->version, memory_order_relaxed);
        if (!claim_and_render(job, 0))
            await_change(job, seen);
    }
    job->stop = 1;
    if (status != RAYO_OK) /* helpers abandon their bands at once */
        rayo_render_stop_now(&job->stopper);
    announce(job);
    pthread_mutex_unlock(&job->lock);
    for (i = 0; i < started; i++)
        join_helper(helpers[i].slot.thread, job->spin);
    pthread_cond_destroy(&job->changed);
    pthread_mutex_destroy(&job->lock);
    free(helpers);
    return status;
}

/*
 * Renders and delivers bands on this thread while the frame's rendering,
 * projected from the bands done so far, stays under SERIAL_BELOW_SECONDS;
 * brings in helpers as soon as it does not.  Only rendering counts:
 * helpers cannot make the sink faster.  The first projection comes from
 * one row, so an expensive frame loses one row, not one band, to the
 * serial start (the row is rendered again with its band).
 */
static rayo_status run_adaptive(band_job *job, unsigned threads,
                                rayo_row_sink sink, void *context,
                                rayo_error *err)
{
    double start = seconds_now(), rendering;
    uint32_t band;
    rayo_row_plan_render(&job->plan, 0, slot_memory(job, 0));
    rendering = seconds_now() - start;
    if (stopping(job))
        return cancelled(err);
    if (rendering * job->camera->height >= SERIAL_BELOW_SECONDS)
        return run_parallel(job, threads, 0, sink, context, err);
    rendering = 0.0;
    for (band = 0; band < job->band_count; band++) {
        rayo_status status;
        if (band > 0 &&
            rendering / band * job->band_count >= SERIAL_BELOW_SECONDS)
            return run_parallel(job, threads, band, sink, context, err);
        start = seconds_now();
        render_band(job, band, 0);
        rendering += seconds_now() - start;
        if (stopping(job))
            return cancelled(err);
        status = deliver(job, band, 0, sink, context, err);
        if (status != RAYO_OK)
            return status;
    }
    return RAYO_OK;
}

rayo_status rayo_render(const rayo_camera *camera, const rayo_scene *scene,
                        const rayo_render_options *options,
                        rayo_row_sink sink, void *sink_context,
                        rayo_error *err)
{
    rayo_image_info info = rayo_render_image_info(camera, options);
    unsigned threads = options->threads ? options->threads : rayo_cpu_count();
    band_job job;
    uint32_t by_memory, by_sharing;
    size_t row_memory;
    rayo_status status;

    if (threads > RAYO_MAX_THREADS)
        threads = RAYO_MAX_THREADS;
    job.camera = camera;
    job.scene = scene;
    job.options = options;
    job.row_bytes = rayo_image_info_row_bytes(&info);
    rayo_row_plan_init(&job.plan, camera, scene, options);
    rayo_render_stop_init(&job.stopper, options);
    job.plan.stop = &job.stopper;
    job.runs_writer = rayo_row_plan_has_runs(&job.plan)
                          ? rayo_writer_taking_runs(sink, sink_context, &info)
                          : NULL;
    row_memory = job.row_bytes + (job.runs_writer ? sizeof *job.runs : 0);
    by_memory = (uint32_t)(BAND_TARGET_BYTES / row_memory);
    by_sharing = camera->height / (threads * BANDS_PER_THREAD);
    job.rows_per_band = by_memory < by_sharing ? by_memory : by_sharing;
    if (job.rows_per_band < 1)
        job.rows_per_band = 1;
    job.band_count = (camera->height + job.rows_per_band - 1) /
                     job.rows_per_band;
    if (threads > job.band_count)
        threads = job.band_count;
    /* No more slots than the frame has bands. */
    job.slots_per_thread = SLOTS_PER_THREAD;
    while (job.slots_per_thread > 1 &&
           threads * job.slots_per_thread > job.band_count)
        job.slots_per_thread--;
    job.slot_count = threads == 1 ? 1 : threads * job.slots_per_thread;
    job.next_band = 0;
    job.delivered = 0;
    job.stop = 0;
    job.slots = malloc((size_t)job.slot_count * job.rows_per_band *
                       job.row_bytes);
    job.ready = malloc(job.slot_count * sizeof *job.ready);
    job.free_slots = malloc(threads * sizeof *job.free_slots);
    /* Without memory for the runs, rows go as bits. */
    job.runs = job.runs_writer == NULL
                   ? NULL
                   : malloc((size_t)job.slot_count * job.rows_per_band *
                            sizeof *job.runs);
    if (job.slots == NULL || job.ready == NULL || job.free_slots == NULL) {
        status = rayo_error_set(err, RAYO_ERR_NOMEM,
                                "out of memory for render buffers");
    } else {
        status = threads == 1
                     ? run_serial(&job, 0, sink, sink_context, err)
                     : run_adaptive(&job, threads, sink, sink_context, err);
    }
    rayo_row_plan_free(&job.plan);
    free(job.slots);
    free(job.ready);
    free(job.free_slots);
    free(job.runs);
    return status;
}

typedef struct image_sink {
    rayo_image *image;
} image_sink;

static rayo_status copy_rows(void *context, const unsigned char *rows,
                             size_t stride, uint32_t first_row,
                             uint32_t count, rayo_error *err)
{
    image_sink *target = context;
    uint32_t r;
    (void)err;
    for (r = 0; r < count; r++) {
        unsigned char *dst = rayo_image_row(target->image, first_row + r);
        memcpy(dst, rows + (size_t)r * stride, target->image->stride);
    }
    return RAYO_OK;
}

rayo_status rayo_render_image(const rayo_camera *camera,
                              const rayo_scene *scene,
                              const rayo_render_options *options,
                              rayo_image *image, rayo_error *err)
{
    rayo_image_info info = rayo_render_image_info(camera, options);
    image_sink target;
    rayo_status status = rayo_image_create(image, &info, err);
    if (status != RAYO_OK)
        return status;
    target.image = image;
    status = rayo_render(camera, scene, options, copy_rows, &target, err);
    if (status != RAYO_OK)
        rayo_image_free(image);
    return status;
}
