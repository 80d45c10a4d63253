/*
 * t_render_runs.c - plain PBM from rows as runs equals plain PBM from
 * bits, byte for byte.
 *
 * When rayo_render's sink is rayo_writer_row_sink and the writer is plain
 * PBM as wide as the frame, rows of the span renderer reach the writer
 * as runs of black pixels (src/formats/writer_runs.h) instead of bits.
 * Here the same frames are written both ways, through that sink and
 * through a sink of the test's own that forwards bits to
 * rayo_writer_write_rows: seeded random scenes of spheres (overlapping,
 * around and behind the camera), cameras turned or not, odd sizes, 1, 2
 * and 3 threads, and frames tall enough (65,536 rows) that render.c
 * brings in helper threads from the first band.  The writer counts the
 * rows that came as runs, and the white ones among them it handed to the
 * output by reference (pnm_write.c), so the test knows both paths were
 * taken; the tall frames refer to more rows than an output holds
 * references at once, so references are written out mid-frame too.  A
 * writer narrower than the frame gets bits (its rows are cut to its
 * width), never runs too long for its rows.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../src/formats/writer_impl.h"
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

typedef struct written {
    unsigned char *bytes; /* NULL on a failure */
    size_t size;
    uint32_t rows_as_runs;
    uint32_t rows_referred;
} written;

/* The frame as plain PBM width pixels wide (the camera's, or fewer),
 * through sink, into a temporary file read back. */
static written write_frame(const rayo_camera *camera, const rayo_scene *scene,
                           unsigned threads, uint32_t width,
                           rayo_row_sink sink)
{
    char path[] = "/tmp/rayo-t-render-runs.XXXXXX";
    int fd = mkstemp(path), failed;
    rayo_image_info info;
    rayo_render_options options;
    rayo_write_options write_options = {RAYO_FORMAT_PBM, 1, 0};
    rayo_output *out;
    rayo_writer *writer;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    written result = {NULL, 0, 0, 0};
    off_t end;
    if (fd < 0)
        return result;
    unlink(path);
    rayo_render_options_init(&options);
    options.threads = threads;
    info = rayo_image_info_bit(width, camera->height);
    failed = rayo_output_open_fd(&out, fd, path, &err) != RAYO_OK;
    if (!failed &&
        rayo_writer_open(&writer, out, &info, &write_options, &err) !=
            RAYO_OK) {
        rayo_output_abort(out);
        failed = 1;
    }
    if (!failed) {
        failed = rayo_render(camera, scene, &options, sink, writer, &err) !=
                 RAYO_OK;
        result.rows_as_runs = writer->rows_as_runs;
        result.rows_referred = writer->rows_referred;
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
    if (!failed && end > 0 && (result.bytes = malloc((size_t)end)) != NULL &&
        pread(fd, result.bytes, (size_t)end, 0) != (ssize_t)end) {
        free(result.bytes);
        result.bytes = NULL;
    }
    close(fd);
    result.size = end > 0 ? (size_t)end : 0;
    return result;
}

typedef struct tally {
    int frames, differing;
    long rows_as_runs, bits_path_runs, rows_referred;
} tally;

/* Writes the frame both ways and compares. */
static void both_ways(const rayo_camera *camera, const rayo_scene *scene,
                      unsigned threads, uint32_t width, tally *t)
{
    written runs = write_frame(camera, scene, threads, width,
                               rayo_writer_row_sink);
    written bits = write_frame(camera, scene, threads, width, forward_bits);
    t->frames++;
    t->differing += runs.bytes == NULL || bits.bytes == NULL ||
                    runs.size != bits.size ||
                    memcmp(runs.bytes, bits.bytes, runs.size) != 0;
    t->rows_as_runs += runs.rows_as_runs;
    t->bits_path_runs += bits.rows_as_runs;
    t->rows_referred += runs.rows_referred;
    free(runs.bytes);
    free(bits.bytes);
}

/* Which writers take runs: plain PBM only, only through its own sink, and
 * only for rows as wide as its image. */
static void who_takes_runs(void)
{
    static const rayo_write_options kinds[] = {
        {RAYO_FORMAT_PBM, 1, 0}, {RAYO_FORMAT_PBM, 0, 0}, {RAYO_FORMAT_PNG, 0, 0}};
    static const char *const names[] = {"plain PBM", "raw PBM", "PNG"};
    rayo_image_info info = rayo_image_info_bit(17, 3);
    rayo_image_info wider = rayo_image_info_bit(18, 3);
    size_t k;
    for (k = 0; k < 3; k++) {
        rayo_output *out;
        rayo_writer *writer;
        rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
        int takes;
        if (rayo_output_open(&out, "/dev/null", &err) != RAYO_OK ||
            rayo_writer_open(&writer, out, &info, &kinds[k], &err) !=
                RAYO_OK) {
            ok(0, "a writer on /dev/null");
            continue;
        }
        takes = rayo_writer_taking_runs(rayo_writer_row_sink, writer,
                                        &info) != NULL;
        is_int(takes, k == 0, "%s %s runs", names[k],
               k == 0 ? "takes" : "refuses");
        if (k == 0) {
            ok(rayo_writer_taking_runs(forward_bits, writer, &info) == NULL,
               "not through another sink");
            ok(rayo_writer_taking_runs(rayo_writer_row_sink, writer,
                                       &wider) == NULL,
               "not for rows wider than its image");
        }
        rayo_writer_discard(writer);
        rayo_output_abort(out);
    }
}

static rayo_scene *random_scene(void)
{
    rayo_scene *scene;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    int spheres = 1 + (int)uniform(0, 6), s;
    if (rayo_scene_create(&scene, &err) != RAYO_OK)
        abort();
    for (s = 0; s < spheres; s++)
        if (rayo_scene_add_sphere(scene,
                                  rayo_vec3_make(uniform(-3, 3),
                                                 uniform(-3, 3),
                                                 uniform(-2, 6)),
                                  uniform(0.05, 1.5), &err) != RAYO_OK)
            abort();
    return scene;
}

static void random_camera(rayo_camera *camera, uint32_t width,
                          uint32_t height, int turned)
{
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (rayo_camera_init(camera, width, height, uniform(20, 150),
                         rayo_vec3_make(uniform(-1, 1), uniform(-1, 1),
                                        uniform(-1, 1)),
                         &err) != RAYO_OK ||
        (turned &&
         rayo_camera_look_at(camera,
                             rayo_vec3_make(uniform(-1, 1), uniform(-1, 1),
                                            4.0),
                             rayo_vec3_make(uniform(-0.3, 0.3), 1, 0),
                             &err) != RAYO_OK))
        abort();
}

int main(void)
{
    tally t = {0, 0, 0, 0, 0}, tall = {0, 0, 0, 0, 0},
          narrow = {0, 0, 0, 0, 0};
    int n;
    unsigned threads;
    who_takes_runs();
    for (n = 0; n < 60; n++) {
        rayo_camera camera;
        rayo_scene *scene = random_scene();
        random_camera(&camera, 1 + (uint32_t)uniform(0, 700),
                      1 + (uint32_t)uniform(0, 300), n % 2);
        for (threads = 1; threads <= 3; threads++)
            both_ways(&camera, scene, threads, camera.width, &t);
        rayo_scene_free(scene);
    }
    is_int(t.differing, 0, "runs and bits give the same plain PBM (%d frames)",
           t.frames);
    ok(t.rows_as_runs > 10000, "rows went as runs (%ld)", t.rows_as_runs);
    ok(t.rows_referred > 1000, "white rows went by reference (%ld)",
       t.rows_referred);
    is_int(t.bits_path_runs, 0, "no rows as runs through another sink");

    /* Tall frames: helpers from the first band, several at once. */
    for (n = 0; n < 2; n++) {
        rayo_camera camera;
        rayo_scene *scene = random_scene();
        random_camera(&camera, n == 0 ? 64 : 3, 65536, n);
        for (threads = 2; threads <= 7; threads += 5)
            both_ways(&camera, scene, threads, camera.width, &tall);
        rayo_scene_free(scene);
    }
    is_int(tall.differing, 0,
           "tall frames: runs and bits give the same plain PBM (%d frames, "
           "2 and 7 threads)",
           tall.frames);
    ok(tall.rows_as_runs > 100000, "tall frames: rows went as runs (%ld)",
       tall.rows_as_runs);
    ok(tall.rows_referred > 10000,
       "tall frames: white rows went by reference (%ld), more than an "
       "output holds at once",
       tall.rows_referred);

    /* A writer narrower than the frame: its rows cut to its width. */
    {
        rayo_camera camera;
        rayo_scene *scene = random_scene();
        random_camera(&camera, 700, 40, 0);
        both_ways(&camera, scene, 2, 17, &narrow);
        rayo_scene_free(scene);
    }
    is_int(narrow.differing, 0,
           "a writer narrower than the frame: the same bytes both ways");
    is_int(narrow.rows_as_runs, 0, "a writer narrower than the frame: bits");
    return tap_done();
}
