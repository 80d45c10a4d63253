/*
 * render.c - scheduling rows: bands rendered by a pool of threads and
 * delivered to the sink in order.
 *
 * The frame is cut into bands of consecutive rows.  Worker threads claim
 * bands in increasing order and render each into one of a ring of slot
 * buffers; the calling thread waits for the next band in order, hands it
 * to the sink, and frees its slot for a later band.  A band's pixels
 * depend only on its rows, never on which thread rendered it, so the
 * output is identical for any thread count.  With one thread nothing is
 * spawned.  With more, bands are first rendered and delivered on the
 * calling thread, and the workers start only once the frame, at the pace
 * of the bands done so far, would take SERIAL_BELOW_SECONDS or more: the
 * seed job takes tens of microseconds with the span fast path, and
 * starting threads would cost more than they save.
 */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */

#include "rayo/render.h"

#include <pthread.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "rayo/limits.h"

#include "row_plan.h"

/* Bands aim at this many bytes, so sinks get large writes. */
#define BAND_TARGET_BYTES (256u * 1024u)
/* and at least this many bands per thread, so threads share the work. */
#define BANDS_PER_THREAD 8u
/* Slots per thread in the ring of band buffers. */
#define SLOTS_PER_THREAD 3u
/* Frames projected to take less than this stay on the calling thread. */
#define SERIAL_BELOW_SECONDS 0.003

typedef struct band_job {
    const rayo_camera *camera;
    const rayo_scene *scene;
    const rayo_render_options *options;
    rayo_row_plan plan;
    size_t row_bytes;
    uint32_t rows_per_band, band_count, slot_count;
    unsigned char *slots;  /* slot_count * rows_per_band * row_bytes */
    uint32_t *slot_band;   /* band held ready in each slot, or UINT32_MAX */

    pthread_mutex_t lock;
    pthread_cond_t band_ready; /* a worker finished a band */
    pthread_cond_t slot_free;  /* the consumer released a slot */
    uint32_t next_band;        /* next band for a worker to claim */
    uint32_t delivered;        /* bands handed to the sink */
    int stop;
} band_job;

/*
 * The CPUs this process may run on (taskset, cpusets), else the online
 * ones.  One system call: sysconf reads a file under /sys, which cost
 * the seed job a tenth of its time.
 */
unsigned rayo_cpu_count(void)
{
    long n;
#ifdef CPU_COUNT
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        n = CPU_COUNT(&set);
    else
#endif
        n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        return 1;
    return n > (long)RAYO_MAX_THREADS ? RAYO_MAX_THREADS : (unsigned)n;
}

void rayo_render_options_init(rayo_render_options *options)
{
    options->shade = RAYO_SHADE_HIT;
    options->samples = 1;
    options->depth = 5;
    options->threads = 0;
    options->progress = NULL;
    options->progress_context = NULL;
}

static uint32_t band_rows(uint32_t rows, uint32_t first, uint32_t per_band)
{
    return rows - first < per_band ? rows - first : per_band;
}

static unsigned char *slot_memory(const band_job *job, uint32_t band)
{
    size_t slot = band % job->slot_count;
    return job->slots + slot * job->rows_per_band * job->row_bytes;
}

static void render_band(const band_job *job, uint32_t band)
{
    uint32_t first = band * job->rows_per_band;
    uint32_t count = band_rows(job->camera->height, first, job->rows_per_band);
    unsigned char *memory = slot_memory(job, band);
    uint32_t r;
    for (r = 0; r < count; r++)
        rayo_row_plan_render(&job->plan, first + r,
                             memory + (size_t)r * job->row_bytes);
}

static void *worker_main(void *argument)
{
    band_job *job = argument;
    for (;;) {
        uint32_t band;
        pthread_mutex_lock(&job->lock);
        while (!job->stop && job->next_band < job->band_count &&
               job->next_band >= job->delivered + job->slot_count)
            pthread_cond_wait(&job->slot_free, &job->lock);
        if (job->stop || job->next_band >= job->band_count) {
            pthread_mutex_unlock(&job->lock);
            return NULL;
        }
        band = job->next_band++;
        pthread_mutex_unlock(&job->lock);

        render_band(job, band);

        pthread_mutex_lock(&job->lock);
        job->slot_band[band % job->slot_count] = band;
        pthread_cond_broadcast(&job->band_ready);
        pthread_mutex_unlock(&job->lock);
    }
}

static rayo_status deliver(band_job *job, uint32_t band, rayo_row_sink sink,
                           void *context, rayo_error *err)
{
    uint32_t first = band * job->rows_per_band;
    uint32_t count = band_rows(job->camera->height, first, job->rows_per_band);
    rayo_status status = sink(context, slot_memory(job, band), job->row_bytes,
                              first, count, err);
    if (status != RAYO_OK)
        return status;
    if (job->options->progress != NULL &&
        job->options->progress(job->options->progress_context, first + count,
                               job->camera->height))
        return rayo_error_set(err, RAYO_ERR_CANCELLED, "render cancelled");
    return RAYO_OK;
}

/* Renders and delivers the bands from `band` on, on this thread. */
static rayo_status run_serial(band_job *job, uint32_t band,
                              rayo_row_sink sink, void *context,
                              rayo_error *err)
{
    for (; band < job->band_count; band++) {
        rayo_status status;
        render_band(job, band);
        status = deliver(job, band, sink, context, err);
        if (status != RAYO_OK)
            return status;
    }
    return RAYO_OK;
}

/* Workers render the bands from `first` on; this thread delivers them. */
static rayo_status run_parallel(band_job *job, unsigned threads,
                                uint32_t first, rayo_row_sink sink,
                                void *context, rayo_error *err)
{
    pthread_t *workers = malloc(threads * sizeof *workers);
    rayo_status status = RAYO_OK;
    unsigned started = 0, i;
    uint32_t band;
    if (workers == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    job->next_band = first;
    job->delivered = first;
    pthread_mutex_init(&job->lock, NULL);
    pthread_cond_init(&job->band_ready, NULL);
    pthread_cond_init(&job->slot_free, NULL);
    for (i = 0; i < threads; i++) {
        if (pthread_create(&workers[started], NULL, worker_main, job) != 0)
            break;
        started++;
    }
    if (started == 0) {
        status = run_serial(job, first, sink, context, err);
    } else {
        for (band = first; band < job->band_count && status == RAYO_OK;
             band++) {
            uint32_t slot = band % job->slot_count;
            pthread_mutex_lock(&job->lock);
            while (job->slot_band[slot] != band)
                pthread_cond_wait(&job->band_ready, &job->lock);
            pthread_mutex_unlock(&job->lock);

            status = deliver(job, band, sink, context, err);

            pthread_mutex_lock(&job->lock);
            job->slot_band[slot] = UINT32_MAX;
            job->delivered = band + 1;
            if (status != RAYO_OK)
                job->stop = 1;
            pthread_cond_broadcast(&job->slot_free);
            pthread_mutex_unlock(&job->lock);
        }
    }
    for (i = 0; i < started; i++)
        pthread_join(workers[i], NULL);
    pthread_cond_destroy(&job->slot_free);
    pthread_cond_destroy(&job->band_ready);
    pthread_mutex_destroy(&job->lock);
    free(workers);
    return status;
}

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/*
 * Renders and delivers bands on this thread while the frame, projected
 * from what is done so far, stays under SERIAL_BELOW_SECONDS; hands the
 * rest to the workers as soon as it does not.  The first projection comes
 * from one row, so an expensive frame loses one row, not one band, to the
 * serial start (the row is rendered again with its band).
 */
static rayo_status run_adaptive(band_job *job, unsigned threads,
                                rayo_row_sink sink, void *context,
                                rayo_error *err)
{
    double start = seconds_now();
    uint32_t band;
    rayo_row_plan_render(&job->plan, 0, slot_memory(job, 0));
    if ((seconds_now() - start) * job->camera->height >=
        SERIAL_BELOW_SECONDS)
        return run_parallel(job, threads, 0, sink, context, err);
    for (band = 0; band < job->band_count; band++) {
        rayo_status status;
        double spent = seconds_now() - start;
        if (band > 0 &&
            spent / band * job->band_count >= SERIAL_BELOW_SECONDS)
            return run_parallel(job, threads, band, sink, context, err);
        render_band(job, band);
        status = deliver(job, band, sink, context, err);
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
    uint32_t i, by_memory, by_sharing;
    rayo_status status;

    if (threads > RAYO_MAX_THREADS)
        threads = RAYO_MAX_THREADS;
    job.camera = camera;
    job.scene = scene;
    job.options = options;
    job.row_bytes = rayo_image_info_row_bytes(&info);
    by_memory = (uint32_t)(BAND_TARGET_BYTES / job.row_bytes);
    by_sharing = camera->height / (threads * BANDS_PER_THREAD);
    job.rows_per_band = by_memory < by_sharing ? by_memory : by_sharing;
    if (job.rows_per_band < 1)
        job.rows_per_band = 1;
    job.band_count = (camera->height + job.rows_per_band - 1) /
                     job.rows_per_band;
    if (threads > job.band_count)
        threads = job.band_count;
    job.slot_count = threads == 1 ? 1 : threads * SLOTS_PER_THREAD;
    if (job.slot_count > job.band_count)
        job.slot_count = job.band_count;
    job.next_band = 0;
    job.delivered = 0;
    job.stop = 0;
    job.slots = malloc((size_t)job.slot_count * job.rows_per_band *
                       job.row_bytes);
    job.slot_band = malloc(job.slot_count * sizeof *job.slot_band);
    if (job.slots == NULL || job.slot_band == NULL) {
        free(job.slots);
        free(job.slot_band);
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "out of memory for render buffers");
    }
    for (i = 0; i < job.slot_count; i++)
        job.slot_band[i] = UINT32_MAX;
    rayo_row_plan_init(&job.plan, camera, scene, options);
    status = threads == 1
                 ? run_serial(&job, 0, sink, sink_context, err)
                 : run_adaptive(&job, threads, sink, sink_context, err);
    rayo_row_plan_free(&job.plan);
    free(job.slots);
    free(job.slot_band);
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
