/*
 * setup_steps.c - times each step of a mesh's setup in one process:
 * reading the STL (rayo_mesh_read_file), placing it in a scene
 * (rayo_scene_add_mesh_threads) and building the hierarchy
 * (rayo_scene_prepare_threads), each in wall clock and processor time,
 * and the whole in the calling thread's own processor time: on a busy
 * machine, where wall clock says nothing, that is what is left on the
 * critical path when the other threads do their share
 * (docs/performance.md, "Setup on every thread").  Also the peak
 * resident size after placing and at the end.  Not part of rayo nor of
 * `make bench`'s rows; a measuring aid, built by `make setup-steps`.
 *
 *   setup-steps STL THREADS
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <time.h>

#include "rayo/mesh.h"
#include "rayo/scene.h"

static double ms(clockid_t clock)
{
    struct timespec t;
    clock_gettime(clock, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static long peak_mib(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024;
}

typedef struct mark {
    double wall, cpu, own;
} mark;

static mark now(void)
{
    mark m;
    m.wall = ms(CLOCK_MONOTONIC);
    m.cpu = ms(CLOCK_PROCESS_CPUTIME_ID);
    m.own = ms(CLOCK_THREAD_CPUTIME_ID);
    return m;
}

int main(int argc, char **argv)
{
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_mesh mesh;
    rayo_scene *scene;
    rayo_mesh_placement placement;
    size_t left_out;
    unsigned threads;
    mark m[4];
    long placed_peak;
    if (argc != 3) {
        fprintf(stderr, "usage: setup-steps STL THREADS\n");
        return 2;
    }
    threads = (unsigned)strtoul(argv[2], NULL, 10);
    m[0] = now();
    if (rayo_mesh_read_file(argv[1], &mesh, NULL, &err) != RAYO_OK) {
        fprintf(stderr, "setup-steps: %s\n", err.message);
        return 1;
    }
    m[1] = now();
    rayo_mesh_placement_init(&placement);
    if (rayo_scene_create(&scene, &err) != RAYO_OK ||
        rayo_scene_add_mesh_threads(scene, &mesh, &placement, 0, threads,
                                    &left_out, &err) != RAYO_OK) {
        fprintf(stderr, "setup-steps: %s\n", err.message);
        return 1;
    }
    rayo_mesh_free(&mesh);
    placed_peak = peak_mib();
    m[2] = now();
    if (rayo_scene_prepare_threads(scene, threads, &err) != RAYO_OK) {
        fprintf(stderr, "setup-steps: %s\n", err.message);
        return 1;
    }
    m[3] = now();
    printf("-j %u  read %.0f/%.0f  place %.0f/%.0f  prepare %.0f/%.0f  "
           "setup %.0f/%.0f ms (wall/processor)  calling thread %.0f ms  "
           "peak %ld MiB placed, %ld MiB at the end\n",
           threads, m[1].wall - m[0].wall, m[1].cpu - m[0].cpu,
           m[2].wall - m[1].wall, m[2].cpu - m[1].cpu,
           m[3].wall - m[2].wall, m[3].cpu - m[2].cpu,
           m[3].wall - m[0].wall, m[3].cpu - m[0].cpu,
           m[3].own - m[0].own, placed_peak, peak_mib());
    rayo_scene_free(scene);
    return 0;
}
