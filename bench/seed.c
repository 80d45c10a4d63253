/*
 * seed.c - the seed job (640x480, the assignment's sphere, plain PBM)
 * against its two yardsticks:
 *   - the I/O floor: the same bytes, already in memory, in one write;
 *   - the baseline: the assignment's program (baseline.c).
 * The job is the library doing what `rayo > pipe` does: camera, scene,
 * render (threads as the renderer sees fit), P1 writer, output.  Two
 * destinations: a pipe that a thread empties (its reading is part of
 * every figure), and a regular file, truncated before each run (page
 * cache; no fsync, as with `rayo > file`).
 */
#define _POSIX_C_SOURCE 200809L

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench.h"

typedef struct memory_sink {
    unsigned char *bytes;
    size_t size;
} memory_sink;

typedef struct seed_setup {
    rayo_camera camera;
    rayo_scene *scene;
} seed_setup;

static int seed_init(seed_setup *setup)
{
    rayo_error err;
    if (rayo_camera_init(&setup->camera, RAYO_SEED_WIDTH, RAYO_SEED_HEIGHT,
                         RAYO_SEED_FOV, rayo_vec3_make(0, 0, 0),
                         &err) != RAYO_OK ||
        rayo_scene_create(&setup->scene, &err) != RAYO_OK)
        return -1;
    return rayo_scene_add_sphere(setup->scene,
                                 rayo_vec3_make(RAYO_SEED_CENTER_X,
                                                RAYO_SEED_CENTER_Y,
                                                RAYO_SEED_CENTER_Z),
                                 RAYO_SEED_RADIUS, &err) == RAYO_OK
               ? 0
               : -1;
}

/* The seed job into fd; 0 on success. */
static int seed_job(const seed_setup *setup, int fd)
{
    rayo_render_options options;
    rayo_output *out;
    rayo_error err;
    rayo_render_options_init(&options);
    if (rayo_output_open_fd(&out, fd, "pipe", &err) != RAYO_OK)
        return -1;
    return bench_render_into(out, &setup->camera, setup->scene, &options,
                             RAYO_FORMAT_PBM, 1);
}

static int write_all(int fd, const unsigned char *bytes, size_t size)
{
    while (size > 0) {
        ssize_t n = write(fd, bytes, size);
        if (n <= 0)
            return -1;
        bytes += n;
        size -= (size_t)n;
    }
    return 0;
}

/* What the seed job writes, in memory. */
static int seed_bytes(const seed_setup *setup, memory_sink *sink)
{
    char path[] = "/tmp/rayo-bench-seed.XXXXXX";
    int fd = mkstemp(path);
    off_t size;
    if (fd < 0)
        return -1;
    unlink(path);
    if (seed_job(setup, dup(fd)) != 0)
        return -1;
    size = lseek(fd, 0, SEEK_END);
    sink->bytes = malloc((size_t)size);
    sink->size = (size_t)size;
    if (sink->bytes == NULL ||
        pread(fd, sink->bytes, sink->size, 0) != (ssize_t)size) {
        close(fd);
        return -1;
    }
    close(fd);
    return 0;
}

typedef enum seed_kind { SEED_FLOOR, SEED_JOB, SEED_BASELINE } seed_kind;

/* One timed run into a fresh drained pipe, or into the file at path
 * when path is not NULL; seconds, or -1. */
static double seed_run(const seed_setup *setup, const memory_sink *bytes,
                       seed_kind kind, const char *path)
{
    bench_pipe *p = NULL;
    int fd, failed = 0;
    double start, seconds;
    if (path != NULL)
        fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    else if (bench_pipe_open(&p, &fd) != 0)
        return -1;
    if (fd < 0)
        return -1;
    start = bench_now();
    switch (kind) {
    case SEED_FLOOR:
        failed = write_all(fd, bytes->bytes, bytes->size) != 0;
        close(fd);
        break;
    case SEED_JOB:
        failed = seed_job(setup, fd) != 0;
        close(fd);
        break;
    case SEED_BASELINE:
        bench_baseline_seed(fd); /* closes fd */
        break;
    }
    if (p != NULL)
        bench_pipe_close(p, -1);
    seconds = bench_now() - start;
    return failed ? -1 : seconds;
}

/* Best of runs of each kind, interleaved so a busy moment hurts all
 * alike; the baseline, a hundred times slower, runs a twentieth as
 * often. */
static void seed_best(const seed_setup *setup, const memory_sink *bytes,
                      const char *path, int repeats, double best[3])
{
    int r, k;
    for (k = 0; k < 3; k++)
        best[k] = -1;
    for (r = 0; r < repeats; r++)
        for (k = 0; k < 3; k++)
            if (k != SEED_BASELINE || r % 20 == 0)
                best[k] = bench_best(best[k],
                                       seed_run(setup, bytes,
                                                (seed_kind)k, path));
}

void bench_seed(bench_table *table)
{
    seed_setup setup;
    memory_sink bytes = {NULL, 0};
    double pipe_best[3], file_best[3];
    char path[64];
    /* A run is a tenth of a millisecond: on a shared machine the best of
     * a hundred per --repeat is the one least disturbed. */
    int repeats = bench_repeats(table) * 100;
    const char *scratch = getenv("BENCH_TMP");
    if (seed_init(&setup) != 0 || seed_bytes(&setup, &bytes) != 0) {
        bench_add(table, "seed_error", "seed job could not run", -1, "");
        return;
    }
    snprintf(path, sizeof path, "%s/seed.pbm", scratch ? scratch : "/tmp");
    seed_best(&setup, &bytes, NULL, repeats, pipe_best);
    seed_best(&setup, &bytes, path, repeats, file_best);
    unlink(path);
    bench_add(table, "seed_bytes", "seed job output (640x480 P1)",
              (double)bytes.size, "bytes");
    bench_add(table, "seed_floor_ms", "pipe: I/O floor, same bytes from memory",
              pipe_best[SEED_FLOOR] * 1e3, "ms");
    bench_add(table, "seed_job_ms", "pipe: seed job, rayo",
              pipe_best[SEED_JOB] * 1e3, "ms");
    bench_add(table, "seed_baseline_ms", "pipe: baseline (printf per pixel)",
              pipe_best[SEED_BASELINE] * 1e3, "ms");
    bench_add(table, "seed_file_floor_ms",
              "file: I/O floor, same bytes from memory",
              file_best[SEED_FLOOR] * 1e3, "ms");
    bench_add(table, "seed_file_job_ms", "file: seed job, rayo",
              file_best[SEED_JOB] * 1e3, "ms");
    bench_add(table, "seed_file_baseline_ms",
              "file: baseline (printf per pixel)",
              file_best[SEED_BASELINE] * 1e3, "ms");
    bench_target(table, "pipe: seed job / I/O floor",
                 pipe_best[SEED_JOB] / pipe_best[SEED_FLOOR], 1.3, 1);
    bench_target(table, "file: seed job / I/O floor",
                 file_best[SEED_JOB] / file_best[SEED_FLOOR], 1.3, 1);
    bench_target(table, "pipe: baseline / seed job",
                 pipe_best[SEED_BASELINE] / pipe_best[SEED_JOB], 8.0, 0);
    free(bytes.bytes);
    rayo_scene_free(setup.scene);
}
