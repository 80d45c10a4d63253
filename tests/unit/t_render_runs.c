/*
 * t_render_runs.c - plain PBM from rows as runs equals plain PBM from
 * bits, byte for byte.
 *
 * When rayo_render's sink is rayo_writer_row_sink and the writer is plain
 * PBM, rows of the span renderer reach the writer as runs of black pixels
 * (src/formats/writer_runs.h) instead of bits.  Here the same frames are
 * written both ways, through that sink and through a sink of the test's
 * own that forwards bits to rayo_writer_write_rows, on seeded random
 * scenes of spheres (overlapping, around and behind the camera), cameras
 * turned or not, odd sizes, and 1, 2 and 3 threads.  It also checks which writers take runs.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../src/formats/writer_runs.h"
#include "rayo.h"
#include "tap.h"

static uint64_t state = 0xD1B54A32D192ED03ull;

static double uniform(double lo, double hi)
{
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * (double)(state >> 11) / 9007199254740992.0;
}

/* A sink that is not rayo_writer_row_sink: rows reach the writer as bits. */
static rayo_status forward_bits(void *writer, const unsigned char *rows,
                                size_t stride, uint32_t first_row,
                                uint32_t count, rayo_error *err)
{
    (void)first_row;
    return rayo_writer_write_rows(writer, rows, stride, count, err);
}

/* The frame as plain PBM through sink (NULL: rayo_writer_row_sink), in
 * a new buffer of *size bytes; NULL on a failure. */
static unsigned char *written(const rayo_camera *camera,
                              const rayo_scene *scene, unsigned threads,
                              rayo_row_sink sink, size_t *size)
{
    char path[] = "/tmp/rayo-t-render-runs.XXXXXX";
    int fd = mkstemp(path), failed;
    rayo_image_info info;
    rayo_render_options options;
    rayo_write_options write_options = {RAYO_FORMAT_PBM, 1};
    rayo_output *out;
    rayo_writer *writer;
    rayo_error err;
    unsigned char *bytes = NULL;
    off_t end;
    if (fd < 0)
        return NULL;
    unlink(path);
    rayo_render_options_init(&options);
    options.threads = threads;
    info = rayo_render_image_info(camera, &options);
    failed = rayo_output_open_fd(&out, fd, path, &err) != RAYO_OK;
    if (!failed &&
        rayo_writer_open(&writer, out, &info, &write_options, &err) !=
            RAYO_OK) {
        rayo_output_abort(out);
        failed = 1;
    }
    if (!failed) {
        failed = (sink == NULL &&
                  rayo_writer_taking_runs(rayo_writer_row_sink, writer) ==
                      NULL) ||
                 rayo_render(camera, scene, &options,
                             sink ? sink : rayo_writer_row_sink, writer,
                             &err) != RAYO_OK;
        if (failed)
            rayo_writer_discard(writer);
        else
            failed = rayo_writer_finish(writer, &err) != RAYO_OK;
        if (failed)
            rayo_output_abort(out);
        else
            failed = rayo_output_commit(out, &err) != RAYO_OK;
    }
    end = lseek(fd, 0, SEEK_END);
    if (!failed && end > 0 && (bytes = malloc((size_t)end)) != NULL &&
        pread(fd, bytes, (size_t)end, 0) != (ssize_t)end) {
        free(bytes);
        bytes = NULL;
    }
    close(fd);
    *size = end > 0 ? (size_t)end : 0;
    return bytes;
}

/* 1 when both ways give the same bytes. */
static int same_both_ways(const rayo_camera *camera, const rayo_scene *scene,
                          unsigned threads)
{
    size_t runs_size, bits_size;
    unsigned char *runs = written(camera, scene, threads, NULL, &runs_size);
    unsigned char *bits =
        written(camera, scene, threads, forward_bits, &bits_size);
    int same = runs != NULL && bits != NULL && runs_size == bits_size &&
               memcmp(runs, bits, runs_size) == 0;
    free(runs);
    free(bits);
    return same;
}

/* Which writers take runs: plain PBM only, and only through its sink. */
static void who_takes_runs(void)
{
    static const rayo_write_options kinds[] = {
        {RAYO_FORMAT_PBM, 1}, {RAYO_FORMAT_PBM, 0}, {RAYO_FORMAT_PNG, 0}};
    rayo_image_info info = rayo_image_info_bit(17, 3);
    size_t k;
    for (k = 0; k < 3; k++) {
        rayo_output *out;
        rayo_writer *writer;
        rayo_error err;
        int takes;
        if (rayo_output_open(&out, "/dev/null", &err) != RAYO_OK ||
            rayo_writer_open(&writer, out, &info, &kinds[k], &err) !=
                RAYO_OK) {
            ok(0, "a writer on /dev/null");
            continue;
        }
        takes = rayo_writer_taking_runs(rayo_writer_row_sink, writer) != NULL;
        is_int(takes, k == 0, "%s %s runs",
               k == 0 ? "plain PBM" : k == 1 ? "raw PBM" : "PNG",
               k == 0 ? "takes" : "refuses");
        if (k == 0)
            ok(rayo_writer_taking_runs(forward_bits, writer) == NULL,
               "not through another sink");
        rayo_writer_discard(writer);
        rayo_output_abort(out);
    }
}

int main(void)
{
    int n, differing = 0, frames = 0;
    who_takes_runs();
    for (n = 0; n < 60; n++) {
        rayo_camera camera;
        rayo_scene *scene;
        rayo_error err;
        uint32_t width = 1 + (uint32_t)uniform(0, 700);
        uint32_t height = 1 + (uint32_t)uniform(0, 300);
        int spheres = 1 + (int)uniform(0, 6), s;
        unsigned threads;
        if (rayo_camera_init(&camera, width, height, uniform(20, 150),
                             rayo_vec3_make(uniform(-1, 1), uniform(-1, 1),
                                            uniform(-1, 1)),
                             &err) != RAYO_OK ||
            rayo_scene_create(&scene, &err) != RAYO_OK)
            return 1;
        if (n % 2 == 1 &&
            rayo_camera_look_at(&camera,
                                rayo_vec3_make(uniform(-1, 1), uniform(-1, 1),
                                               4.0),
                                rayo_vec3_make(uniform(-0.3, 0.3), 1, 0),
                                &err) != RAYO_OK)
            return 1;
        for (s = 0; s < spheres; s++)
            if (rayo_scene_add_sphere(
                    scene,
                    rayo_vec3_make(uniform(-3, 3), uniform(-3, 3),
                                   uniform(-2, 6)),
                    uniform(0.05, 1.5), &err) != RAYO_OK)
                return 1;
        for (threads = 1; threads <= 3; threads++, frames++)
            differing += !same_both_ways(&camera, scene, threads);
        rayo_scene_free(scene);
    }
    is_int(differing, 0, "runs and bits give the same plain PBM (%d frames)",
           frames);
    return tap_done();
}
